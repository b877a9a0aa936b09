"""Topic wiring of a running system, as the snippet tests compare it."""
from __future__ import annotations

import labkit

from .._polling import poll

#: topic -> (publishers, subscribers)
Wiring = dict[str, tuple[tuple[str, ...], tuple[str, ...]]]


def wiring(snapshot: labkit.GraphSnapshot) -> Wiring:
    return {name: (tuple(sorted(topic.publishers)), tuple(sorted(topic.subscribers)))
            for name, topic in snapshot.topics.items()}


def settled_graph(expected: Wiring, guard: float, only_expected: bool = False,
                  namespace: str | None = None) -> labkit.GraphSnapshot:
    """The graph once it shows `expected` (endpoints are discovered after their nodes),
    or as it is when `guard` seconds run out, for the assertion to show.  With
    `only_expected`, topics `expected` does not name are left out of the comparison;
    with `namespace`, endpoints of nodes outside it (see :func:`in_namespace`)."""
    snapshots = []

    def shows_expected() -> bool:
        snapshots.append(labkit.graph())
        return wiring_of(snapshots[-1], expected, only_expected, namespace) == expected

    poll(shows_expected, guard)
    return snapshots[-1]


def wiring_of(snapshot: labkit.GraphSnapshot, expected: Wiring,
              only_expected: bool = False, namespace: str | None = None) -> Wiring:
    """The snapshot's wiring; with `only_expected`, only of the topics `expected` names;
    with `namespace`, only of the nodes in it."""
    found = wiring(snapshot) if namespace is None else in_namespace(wiring(snapshot), namespace)
    return {name: ends for name, ends in found.items() if name in expected} \
        if only_expected else found


def in_namespace(found: Wiring, namespace: str) -> Wiring:
    """Only the endpoints of nodes in `namespace`, for a test whose launch puts every
    node there.  A node SIGKILLed by an earlier test on the same worker (a Fast DDS
    shutdown hang) stays on the graph, endpoints and all, until its discovery lease
    ends, which can outlast the next test's whole run."""
    prefix = namespace.rstrip('/') + '/'
    kept: Wiring = {}
    for topic, (publishers, subscribers) in found.items():
        ours = (tuple(p for p in publishers if p.startswith(prefix)),
                tuple(s for s in subscribers if s.startswith(prefix)))
        if any(ours):
            kept[topic] = ours
    return kept


def nodes_in(snapshot: labkit.GraphSnapshot, namespace: str) -> list[str]:
    """The snapshot's node names in `namespace`, sorted (see :func:`in_namespace`)."""
    prefix = namespace.rstrip('/') + '/'
    return sorted(name for name in snapshot.nodes if name.startswith(prefix))
