"""The launch check waits for the endpoints a spec names: discovery reports a
node before its publishers and subscribers, and a check that looked at once
reported a subscription that was merely late as missing (seen in CI under load)."""
from __future__ import annotations

import labkit
from labkit.graph import GraphSnapshot, Topic
from speccheck import live_run, load_spec

SPEC = """\
nodes:
  /sensor: {}
  /monitor: {}
topics:
  /reading:
    publishers: [/sensor]
    subscribers: [/monitor]
"""


def snapshot(subscribers: tuple[str, ...]) -> GraphSnapshot:
    topic = Topic('/reading', ('std_msgs/msg/Float32',), ('/sensor',), subscribers)
    return GraphSnapshot(('/monitor', '/sensor'), {'/reading': topic})


def test_waits_until_a_late_subscription_is_discovered(monkeypatch, write_spec):
    looks = iter([GraphSnapshot(('/monitor', '/sensor'), {}), snapshot(()), snapshot(()),
                  snapshot(('/monitor',))])
    seen = []

    def graph() -> GraphSnapshot:
        seen.append(next(looks))
        return seen[-1]

    monkeypatch.setattr(labkit, 'graph', graph)
    monkeypatch.setattr(live_run.time, 'sleep', lambda seconds: None)
    live_run._wait_for_endpoints(load_spec(write_spec(SPEC)), grace=30.0)
    assert len(seen) == 4


def test_gives_up_after_the_grace_so_the_check_can_report_what_is_missing(monkeypatch,
                                                                          write_spec):
    clock = {'now': 0.0, 'looks': 0}

    def graph() -> GraphSnapshot:
        clock['looks'] += 1
        assert clock['looks'] < 20, 'still waiting long after the grace'
        clock['now'] += 1.0
        return snapshot(())

    monkeypatch.setattr(labkit, 'graph', graph)
    monkeypatch.setattr(live_run.time, 'monotonic', lambda: clock['now'])
    monkeypatch.setattr(live_run.time, 'sleep', lambda seconds: None)
    live_run._wait_for_endpoints(load_spec(write_spec(SPEC)), grace=3.0)
    assert clock['looks'] == 3
