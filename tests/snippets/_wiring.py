"""Topic wiring of a running system, as the snippet tests compare it."""
from __future__ import annotations

import time

import labkit

#: topic -> (publishers, subscribers)
Wiring = dict[str, tuple[tuple[str, ...], tuple[str, ...]]]


def wiring(snapshot: labkit.GraphSnapshot) -> Wiring:
    return {name: (tuple(sorted(topic.publishers)), tuple(sorted(topic.subscribers)))
            for name, topic in snapshot.topics.items()}


def settled_graph(expected: Wiring, guard: float) -> labkit.GraphSnapshot:
    """The graph once it shows `expected` (endpoints are discovered after their nodes),
    or as it is when `guard` seconds run out, for the assertion to show."""
    deadline = time.monotonic() + guard
    while True:
        snapshot = labkit.graph()
        if wiring(snapshot) == expected or time.monotonic() > deadline:
            return snapshot
        time.sleep(0.2)
