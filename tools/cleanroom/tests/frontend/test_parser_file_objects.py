"""Parser.load of file objects and paths, and the Parser's file-name helpers.

Every expectation was recorded from Jazzy (launch 3.4.3): a file object
without a name fits no front end by its name, so all are tried in turn (XML,
then YAML), the stream rewound to its start after each failure; the
name helpers take file *names* only (a StringIO or Path is an AttributeError);
`.launch` files are read as XML and as YAML.
"""
from __future__ import annotations

import io
import subprocess
import sys
import warnings
from pathlib import Path

import launch_xml
import launch_yaml
import pytest
from launch.frontend import InvalidFrontendLaunchFileError, Parser
from launch.launch_description_sources import get_launch_description_from_any_launch_file

UNKNOWN = 'The launch file may have a syntax error, or its format is unknown'
XML_SYNTAX = "ParseError('syntax error: line 1, column 0')"
ONE_ROOT = "RuntimeError('Expected only one root')"


def loaded(file) -> tuple[str, str, str]:
    entity, parser = Parser.load(file)
    return type(entity).__module__, entity.type_name, type(parser).__module__


def load_failure(file) -> InvalidFrontendLaunchFileError:
    with pytest.raises(InvalidFrontendLaunchFileError) as error:
        Parser.load(file)
    return error.value


@pytest.mark.parametrize(('text', 'expected'), [
    ('<launch/>', ('launch_xml.entity', 'launch', 'launch_xml.parser')),
    ('launch: []\n', ('launch_yaml.entity', 'launch', 'launch_yaml.parser')),
    ('<foo/>', ('launch_xml.entity', 'foo', 'launch_xml.parser')),
    ('launch: 3\n', ('launch_yaml.entity', 'launch', 'launch_yaml.parser')),
])
def test_unnamed_file_object_tries_every_front_end(text, expected):
    assert loaded(io.StringIO(text)) == expected


@pytest.mark.parametrize(('text', 'errors'), [
    ('garbage <<', [XML_SYNTAX, ONE_ROOT]),
    ('', ["ParseError('no element found: line 1, column 0')",
          "TypeError(\"object of type 'NoneType' has no len()\")"]),
])
def test_unnamed_file_object_nobody_reads(text, errors):
    stream = io.StringIO(text)
    error = load_failure(stream)
    assert str(error) == UNKNOWN
    assert repr(error) == "InvalidFrontendLaunchFileError('')"
    assert [repr(e) for e in error._likely_errors] == errors
    assert error.__cause__ is None and error.__context__ is None
    assert stream.tell() == 0 and not stream.closed


def test_stream_is_rewound_to_its_very_start_between_front_ends():
    xml_tail = io.StringIO('xx<launch/>')
    xml_tail.read(2)
    assert loaded(xml_tail)[1] == 'launch'  # XML reads from where the stream was
    assert xml_tail.tell() == 11
    yaml = io.StringIO('launch: []\n')
    yaml.read(2)
    assert loaded(yaml)[:2] == ('launch_yaml.entity', 'launch')  # YAML after seek(0)
    xml = io.StringIO('<launch/>')
    xml.read(3)
    error = load_failure(xml)
    assert [repr(e) for e in error._likely_errors] == [
        "ParseError('not well-formed (invalid token): line 1, column 4')", ONE_ROOT]


class Unseekable(io.TextIOBase):
    """A stream that is read once and cannot seek."""

    def __init__(self, text: str) -> None:
        self._text: str | None = text

    def read(self, size: int | None = -1) -> str:
        text, self._text = self._text or '', None
        return text

    def readable(self) -> bool:
        return True


def test_unseekable_stream_fails_on_the_rewind():
    assert loaded(Unseekable('<launch/>'))[1] == 'launch'
    with pytest.raises(io.UnsupportedOperation) as error:
        Parser.load(Unseekable('launch: []\n'))
    assert str(error.value) == 'seek'
    assert repr(error.value.__context__) == XML_SYNTAX


def test_named_file_object_goes_by_its_name():
    stream = io.StringIO('launch: []\n')
    stream.name = 'x.xml'
    assert loaded(stream)[0] == 'launch_yaml.entity'
    bad = io.StringIO('garbage <<')
    bad.name = 'x.xml'
    error = load_failure(bad)
    assert str(error) == '\n'.join([
        'Caught multiple exceptions when trying to load file of format [xml]:',
        ' - ParseError: syntax error: line 1, column 0',
        ' - RuntimeError: Expected only one root'])
    assert repr(error.__cause__) == XML_SYNTAX


@pytest.mark.parametrize(('name', 'extension', 'errors'), [
    ('bad.launch', 'launch', [XML_SYNTAX, ONE_ROOT]),
    ('bad.launch.yaml', 'yaml', [ONE_ROOT, XML_SYNTAX]),
    ('bad.yml', 'yml', [ONE_ROOT, XML_SYNTAX]),
    ('bad.txt', '', [XML_SYNTAX, ONE_ROOT]),
    ('.xml', '', [XML_SYNTAX, ONE_ROOT]),
])
@pytest.mark.parametrize('as_path', [False, True])
def test_paths(tmp_path, monkeypatch, name, extension, errors, as_path):
    path = tmp_path / name
    path.write_text('garbage <<')
    monkeypatch.chdir(tmp_path)
    error = load_failure(Path(name) if as_path else name)
    assert repr(error) == f'InvalidFrontendLaunchFileError({extension!r})'
    assert [repr(e) for e in error._likely_errors] == errors
    if extension:
        assert repr(error.__cause__) == errors[0]
    else:
        assert str(error) == UNKNOWN and error.__cause__ is None


def test_path_objects_and_any_name_load(tmp_path):
    (tmp_path / 'y.xml').write_text('launch: []\n')
    (tmp_path / 'noext').write_text('<launch/>')
    assert loaded(tmp_path / 'y.xml')[0] == 'launch_yaml.entity'
    assert loaded(tmp_path / 'noext')[0] == 'launch_xml.entity'
    assert loaded(str(tmp_path / 'noext'))[0] == 'launch_xml.entity'
    assert launch_xml.Parser.load(tmp_path / 'noext')[0].type_name == 'launch'
    assert launch_yaml.Parser.load(tmp_path / 'y.xml')[0].type_name == 'launch'
    with pytest.raises(FileNotFoundError):
        Parser.load(tmp_path / 'missing')


@pytest.mark.parametrize(('text', 'error'), [
    ('', "TypeError(\"object of type 'NoneType' has no len()\")"),
    ('5', "TypeError(\"object of type 'int' has no len()\")"),
    ('abc', ONE_ROOT),
    ('- a', "AttributeError(\"'list' object has no attribute 'keys'\")"),
    ('a: 1\nb: 2', ONE_ROOT),
    ('{}', ONE_ROOT),
])
def test_yaml_root_errors(text, error):
    with pytest.raises(Exception) as raised:
        launch_yaml.Parser.load(io.StringIO(text))
    assert repr(raised.value) == error


def test_extensions():
    assert launch_xml.Parser.get_file_extensions() == {'launch', 'launch.xml', 'xml'}
    assert launch_yaml.Parser.get_file_extensions() == {
        'yml', 'launch.yaml', 'launch.yml', 'launch', 'yaml'}
    assert Parser.get_file_extensions() == set()
    assert Parser.get_file_extensions_from_parsers() == {
        'xml', 'launch.yml', 'launch.xml', 'launch', 'launch.yaml', 'yaml', 'yml'}
    available = Parser.get_available_extensions()
    assert type(available).__name__ == 'dict_keys' and list(available) == ['xml', 'yaml']
    assert Parser.frontend_parsers == {'xml': launch_xml.Parser, 'yaml': launch_yaml.Parser}


@pytest.mark.parametrize(('name', 'parsers'), [
    ('a.launch.xml', [launch_xml.Parser]),
    ('a.launch', [launch_xml.Parser, launch_yaml.Parser]),
    ('a.launch.yml', [launch_yaml.Parser]),
    ('.xml', [launch_xml.Parser]),
    ('a.xml.txt', []), ('xml', []), ('A.XML', []), ('a.launch.py', []), ('a', []),
])
def test_parsers_from_filename(name, parsers):
    assert Parser.get_parsers_from_filename(name) == parsers
    assert Parser.is_filename_valid(name) is bool(parsers)
    assert Parser.may_parse(name) is False  # the base class reads no extension


@pytest.mark.parametrize('not_a_name', [io.StringIO('<launch/>'), Path('a.launch.xml')])
def test_name_helpers_take_names_only(not_a_name):
    message = f"'{type(not_a_name).__name__}' object has no attribute 'endswith'"
    if isinstance(not_a_name, io.StringIO):
        message = "'_io.StringIO' object has no attribute 'endswith'"
    for helper in (Parser.is_filename_valid, Parser.get_parsers_from_filename,
                   launch_xml.Parser.may_parse, launch_yaml.Parser.may_parse):
        with pytest.raises(AttributeError) as error:
            helper(not_a_name)
        assert str(error.value) == message
    assert Parser.may_parse(not_a_name) is False


def test_methods_take_no_file():
    for method in ('get_file_extensions_from_parsers', 'get_available_extensions',
                   'get_file_extensions'):
        with pytest.raises(TypeError) as error:
            getattr(Parser, method)(io.StringIO('<launch/>'))
        assert str(error.value) == (
            f'Parser.{method}() takes 1 positional argument but 2 were given')
    with pytest.raises(TypeError) as error:
        Parser.get_parsers_from_filename()
    assert str(error.value) == (
        "Parser.get_parsers_from_filename() missing 1 required positional argument: 'filename'")


def test_deprecated_extension_helpers():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter('always')
        assert Parser.is_extension_valid('xml') is True
        assert Parser.is_extension_valid('yml') is False
        assert Parser.get_parser_from_extension('yaml') is launch_yaml.Parser
        with pytest.raises(RuntimeError) as error:
            Parser.get_parser_from_extension('launch.xml')
    assert str(error.value) == 'Not recognized frontend implementation'
    assert repr(error.value.__context__) == "KeyError('launch.xml')"
    valid = 'Parser.is_extension_valid is deprecated, use Parser.is_filename_valid instead'
    parser = ('Parser.get_parser_from_extension is deprecated, '
              'use Parser.get_parsers_from_filename instead')
    assert [(w.category, str(w.message)) for w in caught] == [
        (UserWarning, valid), (UserWarning, valid), (UserWarning, parser), (UserWarning, parser)]


@pytest.mark.parametrize(('name', 'expected'), [
    ('bad.txt', "InvalidLaunchFileError('')"),
    ('.xml', "InvalidLaunchFileError('')"),
    ('bad.launch', "InvalidLaunchFileError('launch')"),
])
def test_any_launch_file_keeps_the_failures(tmp_path, name, expected):
    path = tmp_path / name
    path.write_text('garbage <<')
    with pytest.raises(Exception) as raised:
        get_launch_description_from_any_launch_file(str(path))
    error = raised.value
    assert repr(error) == expected
    assert [type(e).__name__ for e in error._likely_errors] == [
        'InvalidFrontendLaunchFileError', 'SyntaxError']
    if expected.endswith("('')"):
        assert str(error) == UNKNOWN and error.__cause__ is None
    else:
        assert str(error).splitlines()[:4] == [
            'Caught multiple exceptions when trying to load file of format [launch]:',
            ' - InvalidFrontendLaunchFileError: Caught multiple exceptions when trying to '
            'load file of format [launch]:',
            ' - ParseError: syntax error: line 1, column 0',
            ' - RuntimeError: Expected only one root']


def test_launch_extensions_load_on_the_first_parse_action():
    """Run in a fresh interpreter: the flag is per class, and set by parse_action."""
    code = (
        'import io, sys\n'
        'from launch.frontend import Parser\n'
        'p = Parser()\n'
        'print(Parser.extensions_loaded, "launch_ros" in sys.modules)\n'
        'entity, parser = Parser.load(\n'
        '    io.StringIO(\'<launch><let name="a" value="b"/></launch>\'))\n'
        'parser.parse_action(entity.children[0])\n'
        'print(Parser.extensions_loaded, type(parser).extensions_loaded, '
        '"launch_ros" in sys.modules)\n')
    result = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                            check=True, timeout=60)
    assert result.stdout.split('\n') == ['False False', 'False True True', '']
