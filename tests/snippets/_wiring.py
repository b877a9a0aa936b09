"""Topic wiring of a running system, as the snippet tests compare it."""
from __future__ import annotations

import time

import labkit

#: topic -> (publishers, subscribers)
Wiring = dict[str, tuple[tuple[str, ...], tuple[str, ...]]]


def wiring(snapshot: labkit.GraphSnapshot) -> Wiring:
    return {name: (tuple(sorted(topic.publishers)), tuple(sorted(topic.subscribers)))
            for name, topic in snapshot.topics.items()}


def settled_graph(expected: Wiring, guard: float, only_expected: bool = False
                  ) -> labkit.GraphSnapshot:
    """The graph once it shows `expected` (endpoints are discovered after their nodes),
    or as it is when `guard` seconds run out, for the assertion to show.  With
    `only_expected`, topics `expected` does not name are left out of the comparison."""
    deadline = time.monotonic() + guard
    while True:
        snapshot = labkit.graph()
        if wiring_of(snapshot, expected, only_expected) == expected \
                or time.monotonic() > deadline:
            return snapshot
        time.sleep(0.2)


def wiring_of(snapshot: labkit.GraphSnapshot, expected: Wiring,
              only_expected: bool = False) -> Wiring:
    """The snapshot's wiring; with `only_expected`, only of the topics `expected` names."""
    found = wiring(snapshot)
    return {name: ends for name, ends in found.items() if name in expected} \
        if only_expected else found
