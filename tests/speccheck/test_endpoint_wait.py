"""The running check waits for what the spec names: discovery reports a node seconds
after it starts on a busy machine, and its subscriptions after the node; a check that
looked at once reported a subscription that was merely late as missing (seen in CI),
and `speccheck live` without --launch a running node as 'not running'."""
from __future__ import annotations

from speccheck import live_check, load_spec
from speccheck.graph import GraphSnapshot, Topic

SPEC = """\
nodes:
  /sensor: {}
  /monitor: {}
topics:
  /reading:
    publishers: [/sensor]
    subscribers: [/monitor]
"""


def snapshot(nodes: tuple[str, ...], subscribers: tuple[str, ...] = ()) -> GraphSnapshot:
    topic = Topic('/reading', ('std_msgs/msg/Float32',), ('/sensor',), subscribers)
    return GraphSnapshot(nodes, {'/reading': topic} if '/sensor' in nodes else {})


def looks(monkeypatch, *snapshots: GraphSnapshot) -> list[GraphSnapshot]:
    """The graph gives `snapshots` in turn; returns the list of those it gave."""
    given: list[GraphSnapshot] = []
    queue = iter(snapshots)

    def graph() -> GraphSnapshot:
        given.append(next(queue))
        return given[-1]

    monkeypatch.setattr(live_check, 'graph', graph)
    monkeypatch.setattr(live_check.time, 'sleep', lambda seconds: None)
    return given


def test_waits_for_a_late_node_and_a_late_subscription(monkeypatch, write_spec):
    complete = snapshot(('/monitor', '/sensor'), ('/monitor',))
    given = looks(monkeypatch, snapshot(('/sensor',)), snapshot(('/monitor', '/sensor')),
                  complete)
    assert live_check._wait_for_spec(load_spec(write_spec(SPEC)), grace=30.0) is complete
    assert len(given) == 3


def test_gives_up_after_the_grace_so_the_check_can_report_what_is_missing(monkeypatch,
                                                                          write_spec):
    clock = {'now': 0.0, 'looks': 0}

    def graph() -> GraphSnapshot:
        clock['looks'] += 1
        assert clock['looks'] < 20, 'still waiting long after the grace'
        clock['now'] += 1.0
        return snapshot(('/monitor', '/sensor'))

    monkeypatch.setattr(live_check, 'graph', graph)
    monkeypatch.setattr(live_check.time, 'monotonic', lambda: clock['now'])
    monkeypatch.setattr(live_check.time, 'sleep', lambda seconds: None)
    found = live_check._wait_for_spec(load_spec(write_spec(SPEC)), grace=3.0)
    assert found.topics['/reading'].subscribers == ()
    assert clock['looks'] == 3
