"""spec.schema.json, the spec format's JSON Schema: the one speccheck validates with,
a valid draft 2020-12 schema, met by every spec of the book's snippets, and refusing
an unknown key."""
from __future__ import annotations

import json
from pathlib import Path

import jsonschema
import pytest
import speccheck.schema
import yaml
from speccheck import SpecError, load_spec

ROOT = Path(__file__).parents[2]
SCHEMA_FILE = ROOT / 'tools' / 'speccheck' / 'src' / 'speccheck' / 'spec.schema.json'
#: Every spec file of snippets/ but the exercises' wrong answers, which may be specs
#: that speccheck refuses on purpose.
SPECS = sorted(path for path in (ROOT / 'snippets').rglob('*.spec.yaml')
               if 'wrong' not in path.relative_to(ROOT).parts)


def schema() -> dict:
    return json.loads(SCHEMA_FILE.read_text(encoding='utf-8'))


def test_the_schema_file_is_what_speccheck_validates_with():
    assert speccheck.schema.SPEC_SCHEMA == schema()
    jsonschema.Draft202012Validator.check_schema(schema())
    assert schema()['$schema'] == 'https://json-schema.org/draft/2020-12/schema'


def test_the_reference_page_names_the_schema_file():
    page = (ROOT / 'docs' / 'reference' / 'spec-files.md').read_text(encoding='utf-8')
    assert str(SCHEMA_FILE.relative_to(ROOT)) in page


def test_the_book_has_spec_files():
    assert len(SPECS) >= 10, SPECS  # the glob found the book's specs


@pytest.mark.parametrize('path', SPECS, ids=lambda path: str(path.relative_to(ROOT)))
def test_every_spec_of_the_book_meets_the_schema(path):
    data = yaml.safe_load(path.read_text(encoding='utf-8')) or {}
    errors = [f'{list(error.absolute_path)}: {error.message}' for error in
              jsonschema.Draft202012Validator(schema()).iter_errors(data)]
    assert errors == []
    load_spec(path)  # and speccheck loads it


@pytest.mark.parametrize('text, where', [
    ('colour: red\n', []),
    ('nodes:\n  /a:\n    pakage: x\n', ['nodes', '/a']),
    ('topics:\n  /t:\n    publisher: [/a]\n', ['topics', '/t']),
    ('nodes:\n  /a:\n    parameters:\n      p: {type: double, vale: 1.0}\n',
     ['nodes', '/a', 'parameters', 'p']),
    ('arguments:\n  a: {defualt: x}\n', ['arguments', 'a']),
])
def test_an_unknown_key_fails(text, where, write_spec):
    errors = list(jsonschema.Draft202012Validator(schema()).iter_errors(yaml.safe_load(text)))
    assert [(error.validator, list(error.absolute_path)) for error in errors] == [
        ('additionalProperties', where)]
    with pytest.raises(SpecError, match='unknown key'):
        load_spec(write_spec(text))
