"""`--format text|json|junit|sarif` of a static check of scoped.launch.py against
scoped.yaml (2 requirements failed, 4 not checked, 14 met).

The SARIF report is validated against the SARIF 2.1.0 JSON schema kept beside this
file: sarif-schema-2.1.0.json is `lib/schemas/sarif-2.1.0-rtm.5.json` of the npm
package @microsoft/jest-sarif 1.0.0-beta.0 (MIT), the schema of the SARIF 2.1.0
standard (its `version` is the enum ['2.1.0']), sha256 2d99159a...4de4f8.
"""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import jsonschema
import pytest
from speccheck import check_static, load_spec
from speccheck.__main__ import main

from tests.speccheck.conftest import HERE, LAUNCH_FILES

ROOT = HERE.parents[1]
SPEC = LAUNCH_FILES / 'scoped.yaml'
LAUNCH = LAUNCH_FILES / 'scoped.launch.py'
SARIF_SCHEMA = HERE / 'sarif-schema-2.1.0.json'
#: (code, spec line) of the two failures, in report order
FAILURES = [('UnexpectedParameter', 10), ('PublisherMissing', 20)]


@pytest.fixture
def run(sourced, capsys, monkeypatch):
    """`speccheck static scoped.yaml scoped.launch.py --format FORMAT` from the repository
    root (as CI runs it in a checkout): its exit code and stdout."""
    monkeypatch.chdir(ROOT)

    def run(format: str | None) -> tuple[int, str]:
        words = ['static', str(SPEC.relative_to(ROOT)), str(LAUNCH)]
        code = main(words + (['--format', format] if format else []))
        captured = capsys.readouterr()
        assert captured.err == ''
        return code, captured.out
    return run


def test_text_is_the_default_and_unchanged(run):
    code, default = run(None)
    assert code == 1
    assert run('text') == (1, default)
    report = check_static(load_spec(SPEC.relative_to(ROOT)), LAUNCH)
    assert default == str(report) + '\n'
    assert default.rstrip().endswith('FAILED: 14 met, 2 failed, 4 not checked')


def test_json_has_every_finding_with_code_line_and_hint(run):
    code, out = run('json')
    data = json.loads(out)
    assert (code, data['exit_code'], data['ok'], data['kind']) == (1, 1, False, 'static')
    assert data['summary'] == {'met': 14, 'failed': 2, 'not_checked': 4}
    assert len(data['findings']) == 20
    failed = [f for f in data['findings'] if f['status'] == 'failed']
    assert [(f['code'], f['line']) for f in failed] == FAILURES
    assert failed[1]['requirement'] == 'topic /scan: publisher /robot1/lidar'
    assert failed[1]['hint'].startswith('remap ')
    met = next(f for f in data['findings'] if f['status'] == 'met')
    assert (met['code'], met['hint']) == (None, '')


def test_junit_has_a_testcase_per_requirement(run):
    code, out = run('junit')
    assert code == 1
    suite = ET.fromstring(out).find('testsuite')
    assert {k: suite.get(k) for k in ('tests', 'failures', 'errors', 'skipped')} == {
        'tests': '20', 'failures': '2', 'errors': '0', 'skipped': '4'}
    cases = suite.findall('testcase')
    assert len(cases) == 20 and len({case.get('name') for case in cases}) == 20
    failed = [case for case in cases if case.find('failure') is not None]
    assert [(case.find('failure').get('type'), int(case.get('line'))) for case in failed] \
        == FAILURES
    assert failed[1].get('name') == 'topic /scan: publisher /robot1/lidar'
    assert 'gives /robot1/scan, not /scan' in failed[1].find('failure').get('message')
    assert len([case for case in cases if case.find('skipped') is not None]) == 4


def test_sarif_is_valid_and_puts_results_on_spec_lines(run):
    code, out = run('sarif')
    assert code == 1
    log = json.loads(out)
    schema = json.loads(SARIF_SCHEMA.read_text(encoding='utf-8'))
    jsonschema.Draft4Validator.check_schema(schema)
    errors = [error.message for error in jsonschema.Draft4Validator(schema).iter_errors(log)]
    assert errors == []
    (sarif_run,) = log['runs']
    results = sarif_run['results']
    assert [r['level'] for r in results].count('note') == 4
    errors = [r for r in results if r['level'] == 'error']
    assert [(r['ruleId'], r['locations'][0]['physicalLocation']['region']['startLine'])
            for r in errors] == FAILURES
    rules = sarif_run['tool']['driver']['rules']
    assert all(rules[r['ruleIndex']]['id'] == r['ruleId'] for r in results)
    artifact = errors[0]['locations'][0]['physicalLocation']['artifactLocation']
    assert artifact == {'uri': 'tests/speccheck/launch_files/scoped.yaml',
                        'uriBaseId': 'SRCROOT'}
    assert sarif_run['originalUriBaseIds']['SRCROOT']['uri'] == ROOT.as_uri() + '/'


def test_the_sarif_schema_rejects_a_broken_log():
    """The validation above can fail: a result without its message is refused."""
    schema = json.loads(SARIF_SCHEMA.read_text(encoding='utf-8'))
    broken = {'version': '2.1.0', 'runs': [{'tool': {'driver': {'name': 'speccheck'}},
                                             'results': [{'ruleId': 'NodeMissing'}]}]}
    assert not jsonschema.Draft4Validator(schema).is_valid(broken)
    assert Path(SARIF_SCHEMA).stat().st_size > 100_000
