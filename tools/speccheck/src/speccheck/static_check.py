"""The static check: a spec against what a launch file would start.

Nothing is started: see launch_walk for how the launch file is read.  The
topic wiring can only be judged from remappings here (which names a
program uses is known when it runs), so a topic endpoint without a remap
rule that decides it is reported as not checked statically.  Likewise a
spec node that no visible Node action starts is not checked (never failed)
when the launch file has parts that may start nodes unseen (an
OpaqueFunction, an event handler, a TimerAction, a plain process).
"""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path

from rclhelpers.names import split_full_name

from speccheck import codes, values
from speccheck.launch_walk import PlannedNode, StaticSystem, walk_launch_file
from speccheck.report import Finding, Report, Status, located
from speccheck.spec import NodeSpec, Spec, TopicSpec
from speccheck.workspace import find_executable

MET, FAILED, NOT_CHECKED = Status.MET, Status.FAILED, Status.NOT_CHECKED


def check_static(spec: Spec, launch_file: str | Path,
                 arguments: dict[str, str] | None = None) -> Report:
    """Check `launch_file` (started with `arguments`) against `spec` without starting it."""
    system = walk_launch_file(launch_file, arguments)
    findings = located(_findings(spec, system), spec.lines)
    target = Path(launch_file).name + ''.join(f' {k}:={v}' for k, v in system.given.items())
    return Report('static', spec.source, target, tuple(findings))


def _findings(spec: Spec, system: StaticSystem) -> list[Finding]:
    if system.error is not None:
        return [Finding('launch file', FAILED,
                        f'{Path(system.launch_file).name} fails before starting anything: '
                        f'{system.error}', codes.LAUNCH_FAILED)]
    findings = [_started(spec, system)]
    findings += [Finding('launch file', FAILED, problem, codes.LAUNCH_FAILED)
                 for problem in system.problems]
    findings += _given_arguments(system)
    findings += _arguments(spec, system)
    matched = _match_nodes(spec, system, findings)
    findings += _executables(system)
    for node_spec in spec.nodes:
        if node_spec.name in matched:
            findings += _parameters(node_spec, matched[node_spec.name])
    for topic in spec.topics:
        findings += _wiring(topic, system, matched)
    findings += [Finding(f'node {node.label}', NOT_CHECKED, note, at=_node_at(node))
                 for node in system.nodes for note in node.notes]
    findings += [Finding('launch file', NOT_CHECKED, item) for item in system.not_checked]
    return findings


def _started(spec: Spec, system: StaticSystem) -> Finding:
    """What the launch file would start: met when it starts nodes (or the spec wants
    none); when it starts none that the walk can see, not checked if parts are hidden."""
    if system.nodes or not spec.nodes:
        return Finding('launch file', MET, _summary(system))
    if system.hidden:
        return Finding('launch file', NOT_CHECKED,
                       f'{_summary(system)} that the static check can see; '
                       + ', '.join(dict.fromkeys(f'{kind} in {where}'
                                                 for kind, where in system.hidden))
                       + ' may start them (not checked statically)')
    return Finding('launch file', FAILED, _summary(system), codes.NODE_MISSING)


def _summary(system: StaticSystem) -> str:
    started = ', '.join(node.label for node in system.nodes) or 'no nodes'
    text = f'would start {started}'
    if system.skipped:
        text += f'; not started because of a false condition: {", ".join(system.skipped)}'
    return text


def _unseen(system: StaticSystem) -> str:
    """Why a node no visible Node action starts is not judged, or '' if it can be."""
    kinds = list(dict.fromkeys(kind for kind, _ in system.hidden))
    if not kinds:
        return ''
    return ('no Node action the static check can see starts it; an '
            f'{" or ".join(kinds)} of the launch files may (not checked statically)')


def _given_arguments(system: StaticSystem) -> list[Finding]:
    declared = {argument.name for argument in system.all_arguments}
    return [Finding(f'argument {name}', FAILED,
                    f'given as {name}:={value} but no launch file declares {name!r}, so it '
                    'changes nothing; declared: ' + (', '.join(sorted(declared)) or 'none'),
                    codes.UNEXPECTED_ARGUMENT)
            for name, value in system.given.items() if name not in declared]


def _arguments(spec: Spec, system: StaticSystem) -> list[Finding]:
    declared = {argument.name: argument for argument in system.top_arguments}
    findings = []
    for wanted in spec.arguments:
        requirement = f'argument {wanted.name}'
        at = ('arguments', wanted.name)
        found = declared.get(wanted.name)
        if found is None:
            findings.append(Finding(requirement, FAILED, 'not declared; the launch file '
                                    f'declares: {", ".join(declared) or "no arguments"}',
                                    codes.ARGUMENT_MISSING, at))
            continue
        problems = []
        if wanted.required and found.default is not None:
            problems.append(f'has the default {found.default!r}, the spec wants it required '
                            '(no default)')
        if wanted.default is not None and found.default != wanted.default:
            problems.append(f'default {found.default!r}, the spec says {wanted.default!r}'
                            if found.default is not None else
                            f'has no default, the spec says {wanted.default!r}')
        if wanted.choices is not None and sorted(found.choices or ()) != sorted(wanted.choices):
            problems.append(f'choices {list(found.choices) if found.choices else "not set"}, '
                            f'the spec says {list(wanted.choices)}')
        if problems:
            findings.append(Finding(requirement, FAILED, '; '.join(problems),
                                    codes.ARGUMENT_MISMATCH, at))
        else:
            default = 'no default' if found.default is None else f'default {found.default!r}'
            choices = f', choices {list(found.choices)}' if found.choices else ''
            findings.append(Finding(requirement, MET, f'declared, {default}{choices}', at=at))
    return findings


def _match_nodes(spec: Spec, system: StaticSystem,
                 findings: list[Finding]) -> dict[str, PlannedNode]:
    """Pair each spec node with the Node action that starts it (by name, or by
    package, executable and namespace when the launch file gives no name)."""
    matched: dict[str, PlannedNode] = {}
    unnamed_used: set[int] = set()
    unseen = _unseen(system)
    for node_spec in spec.nodes:
        requirement = f'node {node_spec.name}'
        at = ('nodes', node_spec.name)
        named = [node for node in system.nodes if node.full_name == node_spec.name]
        if len(named) > 1:
            findings.append(Finding(requirement, FAILED, f'started {len(named)} times: two '
                                    'nodes with one name confuse parameters and services',
                                    codes.DUPLICATE_NODE, at))
        if named:
            matched[node_spec.name] = named[0]
            findings.append(_identity(node_spec, named[0]))
            continue
        candidate = _unnamed_candidate(node_spec, system, unnamed_used)
        if candidate is not None:
            unnamed_used.add(id(candidate))
            matched[node_spec.name] = candidate
            findings.append(Finding(requirement, NOT_CHECKED,
                                    f'{candidate.package}/{candidate.executable} is started in '
                                    f'{candidate.namespace} without a name, so the program picks '
                                    'the node name; taken as this node, name not checked '
                                    'statically', at=at))
            continue
        if unseen:
            findings.append(Finding(requirement, NOT_CHECKED, unseen, at=at))
            continue
        findings.append(Finding(requirement, FAILED, _missing_node_evidence(node_spec, system),
                                codes.NODE_MISSING, at))
    if spec.nodes:
        wanted = {node.name for node in spec.nodes}
        for node in system.nodes:
            if node.full_name is not None and node.full_name not in wanted:
                findings.append(Finding(f'node {node.full_name}', FAILED,
                                        f'started by {Path(node.launch_file).name} '
                                        f'({node.package}/{node.executable}) but not in the spec',
                                        codes.UNEXPECTED_NODE, ('nodes',)))
    return matched


def _identity(node_spec: NodeSpec, node: PlannedNode) -> Finding:
    problems = []
    if node_spec.package and node.package != node_spec.package:
        problems.append(f'package {node.package!r}, the spec says {node_spec.package!r}')
    if node_spec.executable and node.executable != node_spec.executable:
        problems.append(f'executable {node.executable!r}, the spec says '
                        f'{node_spec.executable!r}')
    evidence = (f'started by {Path(node.launch_file).name} as {node.package}/'
                f'{node.executable}')
    if node.remaps:
        evidence += ', remaps ' + ', '.join(f'{s}:={d}' for s, d in node.remaps)
    at = ('nodes', node_spec.name)
    if problems:
        return Finding(f'node {node_spec.name}', FAILED, f'{evidence}; ' + '; '.join(problems),
                       codes.NODE_MISMATCH, at)
    return Finding(f'node {node_spec.name}', MET, evidence, at=at)


def _unnamed_candidate(node_spec: NodeSpec, system: StaticSystem,
                       used: set[int]) -> PlannedNode | None:
    _, namespace = split_full_name(node_spec.name)
    for node in system.nodes:
        if node.name is not None or id(node) in used or node.namespace != namespace:
            continue
        if node_spec.executable and node.executable != node_spec.executable:
            continue
        if node_spec.package and node.package != node_spec.package:
            continue
        if node_spec.executable or split_full_name(node_spec.name)[0] == node.executable:
            return node
    return None


def _missing_node_evidence(node_spec: NodeSpec, system: StaticSystem) -> str:
    text = 'no Node action starts it'
    started = [node.label for node in system.nodes]
    text += f'; the launch file would start: {", ".join(started) or "nothing"}'
    skipped = [label for label in system.skipped if split_full_name(node_spec.name)[0] in label]
    if skipped:
        text += f'; not started because its condition is false: {", ".join(skipped)}'
    return text


def _executables(system: StaticSystem) -> list[Finding]:
    findings = []
    for node in system.nodes:
        found, evidence = find_executable(node.package, node.executable)
        findings.append(Finding(f'executable of {node.label}', MET if found else FAILED,
                                evidence, None if found else codes.EXECUTABLE_MISSING,
                                _node_at(node)))
    return findings


def _parameters(node_spec: NodeSpec, node: PlannedNode) -> list[Finding]:
    if node_spec.parameters is None:
        return []
    given = node.parameters()
    findings = []
    for wanted in node_spec.parameters:
        requirement = f'node {node_spec.name}: parameter {wanted.name}'
        at = ('nodes', node_spec.name, 'parameters', wanted.name)
        setting = given.get(wanted.name)
        if setting is None:
            findings.append(Finding(requirement, NOT_CHECKED,
                                    "not set by the launch file, so the node's own default "
                                    f'applies (the running check reads it); spec: '
                                    f'{values.expectation(wanted)}', at=at))
            continue
        problem = values.judge(wanted, setting.value)
        findings.append(Finding(
            requirement, FAILED if problem else MET,
            f'{problem or "set to " + values.show(setting.value)} (from {setting.origin})',
            codes.PARAMETER_MISMATCH if problem else None, at))
    known = {wanted.name for wanted in node_spec.parameters}
    for name, setting in given.items():
        if setting.targeted and name not in known:
            findings.append(Finding(
                f'node {node_spec.name}: parameter {name}', FAILED,
                f'set to {values.show(setting.value)} by {setting.origin} but not in the spec: '
                'a misspelt name, or one the node does not declare (it would be ignored)',
                codes.UNEXPECTED_PARAMETER, ('nodes', node_spec.name, 'parameters')))
    return findings


def _node_at(node: PlannedNode) -> tuple:
    """The spec path of a node the launch file starts (('nodes', name), or () unnamed)."""
    return ('nodes', node.full_name) if node.full_name else ()


def resolve(name: str, node: PlannedNode) -> str:
    """A topic name as a node would resolve it: absolute, private (~) or relative."""
    if name.startswith('/'):
        return name
    if name.startswith('~'):
        base = node.full_name or (node.namespace.rstrip('/') + '/<name>')
        return base + name[1:] if name[1:].startswith('/') else base + '/' + name[1:]
    return node.namespace.rstrip('/') + '/' + name


def _wiring(topic: TopicSpec, system: StaticSystem,
            matched: dict[str, PlannedNode]) -> list[Finding]:
    """Each expected endpoint, judged on the Node action that starts it: the one
    `_match_nodes` paired with the spec node (also an unnamed one), else by name."""
    findings = []
    unseen = _unseen(system)
    for role, names in (('publisher', topic.publishers), ('subscriber', topic.subscribers)):
        code = codes.PUBLISHER_MISSING if role == 'publisher' else codes.SUBSCRIBER_MISSING
        for index, name in enumerate(names):
            requirement = f'topic {topic.name}: {role} {name}'
            at = ('topics', topic.name, f'{role}s', index)
            nodes = [matched[name]] if name in matched else [
                node for node in system.nodes if node.full_name == name]
            if not nodes and unseen:
                findings.append(Finding(requirement, NOT_CHECKED, unseen, at=at))
                continue
            if not nodes:
                findings.append(Finding(requirement, FAILED,
                                        f'expected {role} {name}, but the launch file starts '
                                        'no node of that name', code, at))
                continue
            finding = _endpoint(requirement, topic.name, nodes[0])
            findings.append(replace(finding, code=code if finding.status is FAILED else None,
                                    at=at))
    return findings


def effective_remaps(node: PlannedNode) -> dict[str, str]:
    """Resolved source name -> resolved target name; the first rule for a name wins."""
    rules: dict[str, str] = {}
    for source, target in node.remaps:
        rules.setdefault(resolve(source, node), resolve(target, node))
    return rules


def _endpoint(requirement: str, topic: str, node: PlannedNode) -> Finding:
    rules = effective_remaps(node)
    written = {resolve(source, node): f'{source}:={target}' for source, target in
               reversed(node.remaps)}
    for source, target in rules.items():
        if target == topic:
            return Finding(requirement, MET, f'remap {written[source]} gives {topic}')
    if topic in rules:
        return Finding(requirement, FAILED,
                       f'remap {written[topic]} moves {topic} to {rules[topic]}')
    last = topic.rsplit('/', 1)[1]
    for source, target in rules.items():
        if target.rsplit('/', 1)[1] == last:
            return Finding(requirement, FAILED,
                           f'remap {written[source]} gives {target}, not {topic}')
    namespace = node.namespace.rstrip('/')
    if topic.startswith(namespace + '/'):
        relative = topic[len(namespace) + 1:]  # may have several segments: turtle1/pose
        return Finding(requirement, NOT_CHECKED,
                       f'no remap decides it; the program gives {topic} if it uses the relative '
                       f'name {relative!r} (not checked statically)')
    return Finding(requirement, NOT_CHECKED,
                   f"no remap decides it; outside the node's namespace {node.namespace}, only "
                   f'an absolute name in the program gives {topic} (not checked statically)')
