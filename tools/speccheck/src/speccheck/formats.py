"""A report as CI reads it: JSON, JUnit XML (one testcase per finding) and SARIF 2.1.0
(results on the spec file's lines, which GitHub code scanning shows on the file).

The text format is `str(report)`, unchanged, because lessons print it; codes,
spec lines and hints appear only here.
"""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections import Counter
from importlib import metadata
from pathlib import Path

from speccheck import codes
from speccheck.report import Finding, Report, Status

FORMATS = ('text', 'json', 'junit', 'sarif')

SARIF_SCHEMA_URI = 'https://json.schemastore.org/sarif-2.1.0.json'
#: SARIF result level of a finding: a failure is an error; an undecided requirement a
#: note, or a warning when it has its own code (a QoS pair that may not talk).
_ERROR, _WARNING, _NOTE = 'error', 'warning', 'note'


def render(report: Report, format: str) -> str:
    """`report` in `format` (one of FORMATS)."""
    if format == 'text':
        return str(report)
    return {'json': as_json, 'junit': as_junit, 'sarif': as_sarif}[format](report)


def _version() -> str:
    try:
        return metadata.version('speccheck')
    except metadata.PackageNotFoundError:  # run from a source tree
        return '0'


def _counts(report: Report) -> Counter:
    return Counter(finding.status for finding in report.findings)


def as_json(report: Report) -> str:
    counts = _counts(report)
    return json.dumps({
        'tool': 'speccheck', 'version': _version(), 'kind': report.kind,
        'spec': report.spec, 'target': report.target, 'ok': report.ok,
        'exit_code': report.exit_code,
        'summary': {'met': counts[Status.MET], 'failed': counts[Status.FAILED],
                    'not_checked': counts[Status.NOT_CHECKED]},
        'findings': [{'requirement': f.requirement, 'status': f.status.name.lower(),
                      'evidence': f.evidence, 'code': f.rule, 'line': f.line, 'hint': f.hint}
                     for f in report.findings],
    }, indent=2, ensure_ascii=False)


def as_junit(report: Report) -> str:
    """One testsuite, one testcase per finding: failed ones fail, undecided ones are skipped."""
    counts = _counts(report)
    suites = ET.Element('testsuites', name='speccheck')
    suite = ET.SubElement(suites, 'testsuite', name=report.title(),
                          tests=str(len(report.findings)), failures=str(counts[Status.FAILED]),
                          errors='0', skipped=str(counts[Status.NOT_CHECKED]))
    seen: Counter = Counter()
    for finding in report.findings:
        seen[finding.requirement] += 1
        name = finding.requirement + (f' #{seen[finding.requirement]}'
                                      if seen[finding.requirement] > 1 else '')
        case = ET.SubElement(suite, 'testcase', name=name,
                             classname=f'speccheck.{report.kind}.{Path(report.spec).stem}',
                             file=report.spec, line=str(finding.line or 1))
        if finding.status is Status.FAILED:
            failure = ET.SubElement(case, 'failure', type=finding.rule or 'Failed',
                                    message=finding.evidence)
            failure.text = (f'{finding.evidence}\nhint: {finding.hint}\n'
                            f'spec: {report.spec}:{finding.line or 1}')
        elif finding.status is Status.NOT_CHECKED:
            ET.SubElement(case, 'skipped', message=f'not checked: {finding.evidence}')
        else:
            ET.SubElement(case, 'system-out').text = finding.evidence
    ET.indent(suites)
    return ET.tostring(suites, encoding='unicode', xml_declaration=True)


def as_sarif(report: Report) -> str:
    """SARIF 2.1.0: every finding that is not met is a result on its spec line."""
    shown = [f for f in report.findings if f.status is not Status.MET]
    rule_ids = sorted({f.rule or 'Failed' for f in shown})
    location, base = _artifact(report.spec)
    results = [{
        'ruleId': finding.rule or 'Failed',
        'ruleIndex': rule_ids.index(finding.rule or 'Failed'),
        'level': _level(finding),
        'message': {'text': f'{finding.requirement}: {finding.evidence}'
                            + (f' (fix: {finding.hint})' if finding.hint else '')},
        'locations': [{'physicalLocation': {'artifactLocation': location,
                                            'region': {'startLine': finding.line or 1}}}],
    } for finding in shown]
    run = {
        'tool': {'driver': {
            'name': 'speccheck', 'version': _version(),
            'rules': [_rule(rule_id) for rule_id in rule_ids]}},
        'automationDetails': {'id': f'speccheck/{report.kind}/'},
        'invocations': [{'executionSuccessful': True}],
        'results': results,
    }
    if base:
        run['originalUriBaseIds'] = {'SRCROOT': {'uri': base}}
    return json.dumps({'$schema': SARIF_SCHEMA_URI, 'version': '2.1.0', 'runs': [run]},
                      indent=2, ensure_ascii=False)


def _level(finding: Finding) -> str:
    if finding.status is Status.FAILED:
        return _ERROR
    return _NOTE if finding.rule == codes.NOT_CHECKED else _WARNING


def _rule(rule_id: str) -> dict:
    summary = codes.SUMMARIES.get(rule_id, 'A requirement of the spec is not met')
    return {'id': rule_id, 'name': rule_id, 'shortDescription': {'text': summary},
            'help': {'text': codes.HINTS.get(rule_id, summary)}}


def _artifact(spec: str) -> tuple[dict, str | None]:
    """The spec file as a SARIF artifact location: relative to the working folder (the
    repository checkout in CI, which code scanning resolves it against) when inside it."""
    path = Path(spec).resolve()
    try:
        relative = path.relative_to(Path.cwd())
    except ValueError:
        return {'uri': path.as_uri()}, None
    return {'uri': relative.as_posix(), 'uriBaseId': 'SRCROOT'}, Path.cwd().as_uri() + '/'
