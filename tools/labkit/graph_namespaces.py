"""Which namespace box of a graph picture each vertex belongs to.

Two identical robots, each in its namespace, should look like two copies
side by side, so a picture draws every namespace that holds nodes as a box
around its members.  A vertex belongs to its full namespace only
(``/robot1/sensor`` to ``/robot1``, ``/a/b/node`` to ``/a/b``): nested
namespaces become separate boxes next to each other, never boxes inside
boxes, which keeps each label on a box of its own.  A topic joins the box of
its namespace when that namespace holds nodes (``/robot1/distance`` beside
``/robot1``'s nodes); nodes and topics in the root namespace stay outside
every box, and a graph without namespaced nodes has no boxes at all.
"""
from __future__ import annotations

import networkx as nx

ROOT = '/'


def namespace(name: str) -> str:
    """The namespace a node or topic name lies in: '/robot1/distance' -> '/robot1'."""
    return name.rsplit('/', 1)[0] or ROOT


def groups(graph: nx.DiGraph) -> dict[str, list[str]]:
    """Namespace -> its vertices (nodes, then topics, each sorted by name), for
    every namespace other than the root that holds a node (vertex `kind` 'node')."""
    nodes = sorted(v for v in graph if graph.nodes[v]['kind'] == 'node')
    held = {namespace(node) for node in nodes} - {ROOT}
    topics = sorted(v for v in graph if graph.nodes[v]['kind'] != 'node')
    return {space: [v for v in nodes + topics if namespace(v) == space] for space in sorted(held)}


def describe_groups(graph: nx.DiGraph) -> str:
    """The grouping in words, for the alt text ('' when there are no boxes)."""
    counts = [(space, sum(graph.nodes[v]['kind'] == 'node' for v in members))
              for space, members in groups(graph).items()]
    if not counts:
        return ''
    return 'Nodes grouped by namespace: ' + ', '.join(
        f"{space} ({count} node{'s' * (count != 1)})" for space, count in counts) + '.'
