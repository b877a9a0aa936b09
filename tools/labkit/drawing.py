"""Draw a :class:`GraphSnapshot` the way rqt_graph does: nodes as ellipses,
topics as boxes, arrows from publisher to topic to subscriber.

The layout is layered left to right by data flow (sources on the left) and
fully deterministic, so an executed lesson shows the same picture on every
build.
"""
from __future__ import annotations

from typing import Any

import matplotlib.pyplot as plt
import networkx as nx
from matplotlib.figure import Figure

NODE_STYLE = dict(boxstyle='ellipse,pad=0.35', facecolor='#dbe9f6', edgecolor='#2b6cb0',
                  linewidth=1.2)
TOPIC_STYLE = dict(boxstyle='square,pad=0.45', facecolor='#fdf1dc', edgecolor='#b7791f',
                   linewidth=1.2)
X_GAP = 2.6  # layout units between layers
Y_GAP = 1.0  # layout units between rows


def to_networkx(snapshot: Any) -> nx.DiGraph:
    """The snapshot as a directed graph; each vertex has `kind` 'node' or 'topic'."""
    graph = nx.DiGraph()
    for name in snapshot.nodes:
        graph.add_node(name, kind='node')
    for topic in snapshot.topics.values():
        graph.add_node(topic.name, kind='topic', type=topic.type)
    graph.add_edges_from(snapshot.edges())
    return graph


def layers(graph: nx.DiGraph) -> list[list[str]]:
    """Vertices in columns: each one right of everything that feeds it (cycles share a column).

    Within a column, vertices sit near the average row of their inputs (one
    barycentre sweep, ties by name), which keeps arrows short and uncrossed.
    """
    condensed = nx.condensation(graph)
    column_of = {}
    for index, generation in enumerate(nx.topological_generations(condensed)):
        for component in generation:
            for vertex in condensed.nodes[component]['members']:
                column_of[vertex] = index
    columns: list[list[str]] = [[] for _ in range(max(column_of.values(), default=-1) + 1)]
    for vertex in sorted(graph.nodes):
        columns[column_of[vertex]].append(vertex)
    row_of: dict[str, float] = {}
    for column in columns:
        def barycentre(vertex: str) -> tuple[float, str]:
            rows = [row_of[p] for p in graph.predecessors(vertex) if p in row_of]
            return (sum(rows) / len(rows) if rows else float('inf'), vertex)
        column.sort(key=barycentre)
        for row, vertex in enumerate(column):
            row_of[vertex] = row - (len(column) - 1) / 2
    return columns


def layout(graph: nx.DiGraph) -> dict[str, tuple[float, float]]:
    """x, y position of every vertex (x grows with the data flow, first row on top)."""
    positions = {}
    for x, column in enumerate(layers(graph)):
        for row, vertex in enumerate(column):
            positions[vertex] = (x * X_GAP, ((len(column) - 1) / 2 - row) * Y_GAP)
    return positions


def draw_graph(snapshot: Any = None, *, show_types: bool = False, title: str | None = None,
               ) -> Figure:
    """Draw the ROS graph and return the matplotlib Figure (shown inline by Jupyter).

    With no snapshot, takes one now (`labkit.graph()`).  `show_types=True`
    writes each topic's message type under its name.
    """
    if snapshot is None:
        from labkit.graph import graph as take_snapshot
        snapshot = take_snapshot()
    graph = to_networkx(snapshot)
    positions = layout(graph)
    columns = max((len(column) for column in layers(graph)), default=1)
    width = max(6.0, 2.3 * (max((x for x, _ in positions.values()), default=0) / X_GAP + 1))
    figure = plt.figure(figsize=(width, max(2.5, 0.85 * columns + 1.0)))
    plt.close(figure)  # returned, not also auto-shown: Jupyter displays it once
    axes = figure.add_subplot()
    axes.set_axis_off()
    if title:
        axes.set_title(title)
    if not positions:
        axes.text(0.5, 0.5, 'no nodes in the graph', ha='center', va='center')
        return figure
    labels = {}
    for vertex, (x, y) in positions.items():
        kind = graph.nodes[vertex]['kind']
        text = vertex
        if kind == 'topic' and show_types:
            text = f"{vertex}\n[{graph.nodes[vertex]['type']}]"
        labels[vertex] = axes.text(x, y, text, ha='center', va='center', fontsize=9,
                                   bbox=NODE_STYLE if kind == 'node' else TOPIC_STYLE,
                                   zorder=3)
    for source, target in sorted(graph.edges):
        axes.annotate('', xy=positions[target], xytext=positions[source], zorder=2,
                      arrowprops=dict(arrowstyle='-|>', color='#4a5568', linewidth=1.1,
                                      shrinkA=2, shrinkB=2,
                                      patchA=labels[source].get_bbox_patch(),
                                      patchB=labels[target].get_bbox_patch()))
    xs = [x for x, _ in positions.values()]
    ys = [y for _, y in positions.values()]
    axes.set_xlim(min(xs) - X_GAP / 2, max(xs) + X_GAP / 2)
    axes.set_ylim(min(ys) - Y_GAP / 1.5, max(ys) + Y_GAP / 1.5)
    return figure
