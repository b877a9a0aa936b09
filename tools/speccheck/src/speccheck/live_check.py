"""The running check: a spec against the ROS graph as it is now.

Reads the graph, parameters and QoS with rclpy only (`graph`, `qos`), so it
works with a real ROS 2 and with the clean room alike, and measures topic
rates over a bounded window (`rates`).
"""
from __future__ import annotations

import time

from speccheck import codes, qos, rates, values
from speccheck.graph import GraphSnapshot, graph, read_parameters
from speccheck.report import Finding, Report, Status, located
from speccheck.ros_error import RosError
from speccheck.spec import NodeSpec, Spec, TopicSpec

MET, FAILED, NOT_CHECKED = Status.MET, Status.FAILED, Status.NOT_CHECKED

#: Seconds of listening for rate measurements.
DEFAULT_WINDOW = 3.0
#: Seconds to wait for the nodes and endpoints the spec names before judging.
DISCOVERY_GRACE = 10.0


def check_live(spec: Spec, window: float = DEFAULT_WINDOW, target: str = 'running system',
               grace: float = DISCOVERY_GRACE) -> Report:
    """Check the running system against `spec` (rates are measured for `window` seconds).

    Discovery reports a node seconds after it starts on a busy machine, and its
    publishers and subscriptions after the node, so what the spec names is
    waited for, up to `grace` seconds; what is still missing then is reported.
    """
    snapshot = _wait_for_spec(spec, grace)
    findings: list[Finding] = []
    for node_spec in spec.nodes:
        findings += _node(node_spec, snapshot)
    if spec.nodes:
        others = sorted(set(snapshot.nodes) - {node.name for node in spec.nodes})
        if others:
            findings.append(Finding('other nodes', NOT_CHECKED,
                                    f'running but not in the spec: {", ".join(others)}',
                                    at=('nodes',)))
    measured = _measure(spec, snapshot, window)
    for topic in spec.topics:
        findings += _topic(topic, snapshot, measured)
    return Report('live', spec.source, target, located(findings, spec.lines))


def _wait_for_spec(spec: Spec, grace: float) -> GraphSnapshot:
    """The graph once every node, publisher and subscriber the spec names is in it,
    or as it is after `grace` seconds."""
    deadline = time.monotonic() + grace
    while True:
        snapshot = graph()
        if _all_present(spec, snapshot) or time.monotonic() >= deadline:
            return snapshot
        time.sleep(0.1)


def _all_present(spec: Spec, snapshot: GraphSnapshot) -> bool:
    if any(node.name not in snapshot.nodes for node in spec.nodes):
        return False
    for topic in spec.topics:
        found = snapshot.topics.get(topic.name)
        wanted = (*topic.publishers, *topic.subscribers)
        if wanted and found is None:
            return False
        if found is not None and not (set(topic.publishers) <= set(found.publishers)
                                      and set(topic.subscribers) <= set(found.subscribers)):
            return False
    return True


def _node(node_spec: NodeSpec, snapshot: GraphSnapshot) -> list[Finding]:
    requirement = f'node {node_spec.name}'
    at = ('nodes', node_spec.name)
    if node_spec.name not in snapshot.nodes:
        return [Finding(requirement, FAILED,
                        f'not running; running: {", ".join(snapshot.nodes) or "no nodes"}',
                        codes.NODE_MISSING, at)]
    findings = [Finding(requirement, MET, 'running', at=at)]
    if node_spec.parameters is None:
        return findings
    try:
        actual = read_parameters(node_spec.name)
    except RosError as error:
        return [*findings, Finding(f'{requirement}: parameters', FAILED, str(error),
                                   codes.PARAMETERS_UNREADABLE, (*at, 'parameters'))]
    for wanted in node_spec.parameters:
        name = f'{requirement}: parameter {wanted.name}'
        where = (*at, 'parameters', wanted.name)
        if wanted.name not in actual:
            findings.append(Finding(name, FAILED, 'the node has no such parameter; it has: '
                                    + ', '.join(sorted(actual)), codes.PARAMETER_MISSING, where))
            continue
        problem = values.judge(wanted, actual[wanted.name])
        findings.append(Finding(name, FAILED if problem else MET,
                                problem or f'{values.show(actual[wanted.name])}',
                                codes.PARAMETER_MISMATCH if problem else None, where))
    return findings


def _measure(spec: Spec, snapshot: GraphSnapshot, window: float) -> dict[str, rates.Rate]:
    wanted = {topic.name: snapshot.topics[topic.name].types[0] for topic in spec.topics
              if topic.has_rate and topic.name in snapshot.topics}
    return rates.measure_rates(wanted, window) if wanted else {}


def _topic(topic: TopicSpec, snapshot: GraphSnapshot,
           measured: dict[str, rates.Rate]) -> list[Finding]:
    requirement = f'topic {topic.name}'
    at = ('topics', topic.name)
    found = snapshot.topics.get(topic.name)
    if found is None:
        return [Finding(requirement, FAILED,
                        f'no node publishes or subscribes to {topic.name}' + _similar(
                            topic.name, snapshot), codes.TOPIC_MISSING, at)]
    findings = []
    if topic.type is not None:
        ok = found.types == (topic.type,)
        findings.append(Finding(f'{requirement}: type', MET if ok else FAILED,
                                found.type if ok else
                                f'{found.type}, the spec says {topic.type}',
                                None if ok else codes.TYPE_MISMATCH, (*at, 'type')))
    for role, names, actual in (('publisher', topic.publishers, found.publishers),
                                ('subscriber', topic.subscribers, found.subscribers)):
        code = codes.PUBLISHER_MISSING if role == 'publisher' else codes.SUBSCRIBER_MISSING
        for index, name in enumerate(names):
            line = f'{requirement}: {role} {name}'
            where = (*at, f'{role}s', index)
            if name in actual:
                findings.append(Finding(line, MET, f'{name} {role_verb(role)} {topic.name}',
                                        at=where))
            else:
                findings.append(Finding(line, FAILED, _missing_endpoint(
                    topic.name, role, name, actual, snapshot), code, where))
    if topic.has_rate:
        findings.append(_rate(topic, measured.get(topic.name)))
    findings += _qos(topic.name)
    return findings


def role_verb(role: str) -> str:
    return 'publishes' if role == 'publisher' else 'subscribes to'


def _missing_endpoint(topic: str, role: str, name: str, actual: tuple[str, ...],
                      snapshot: GraphSnapshot) -> str:
    text = f'{topic}: expected {role} {name}, found {", ".join(actual) or "none"}'
    if name not in snapshot.nodes:
        return f'{text}; {name} is not running'
    attr = 'publishers' if role == 'publisher' else 'subscribers'
    elsewhere = [t.name for t in snapshot.topics.values() if name in getattr(t, attr)]
    return f'{text}; {name} {role_verb(role)} {", ".join(elsewhere) or "nothing"}'


def _similar(topic: str, snapshot: GraphSnapshot) -> str:
    base = topic.rsplit('/', 1)[1]
    similar = [name for name in snapshot.topics if name.rsplit('/', 1)[1] == base]
    return f'; topics with that base name: {", ".join(similar)}' if similar else ''


def _rate(topic: TopicSpec, rate: rates.Rate | None) -> Finding:
    low = '0' if topic.rate_min is None else f'{topic.rate_min:g}'
    high = 'inf' if topic.rate_max is None else f'{topic.rate_max:g}'
    requirement = f'topic {topic.name}: rate {low}..{high} Hz'
    at = ('topics', topic.name, 'rate')
    if rate is None or rate.hz is None:
        count = 0 if rate is None else rate.count
        window = '' if rate is None else f' in {rate.window:g} s'
        return Finding(requirement, FAILED, f'{count} message(s){window}: no rate to measure',
                       codes.RATE_MISMATCH, at)
    ok = ((topic.rate_min is None or rate.hz >= topic.rate_min)
          and (topic.rate_max is None or rate.hz <= topic.rate_max))
    return Finding(requirement, MET if ok else FAILED,
                   f'measured {rate.hz:.2f} Hz ({rate.count} messages in {rate.window:g} s)',
                   None if ok else codes.RATE_MISMATCH, at)


def _qos(topic: str) -> list[Finding]:
    publishers, subscribers = qos.endpoints(topic)
    if not publishers or not subscribers:
        return []
    requirement = f'topic {topic}: QoS'
    at = ('topics', topic)
    problems = qos.mismatches(topic)
    if not problems:
        pairs = '; '.join(endpoint.describe() for endpoint in publishers + subscribers)
        return [Finding(requirement, MET, f'every publisher/subscriber pair compatible: {pairs}',
                        at=at)]
    return [Finding(requirement, FAILED if problem.error else NOT_CHECKED,
                    f'publisher {problem.publisher.describe()} and subscriber '
                    f'{problem.subscriber.describe()}: {problem.reason}', codes.QOS_MISMATCH, at)
            for problem in problems]
