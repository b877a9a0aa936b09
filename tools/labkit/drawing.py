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


def without_cycles(graph: nx.DiGraph) -> nx.DiGraph:
    """The graph minus the edges that close a cycle (a feedback loop's way back).

    Found by depth-first search from the sources, in name order, so the same
    graph always loses the same edges.
    """
    dag = nx.DiGraph()
    dag.add_nodes_from(graph.nodes)
    state: dict[str, str] = {}

    def visit(vertex: str) -> None:
        state[vertex] = 'open'
        for successor in sorted(graph.successors(vertex)):
            if state.get(successor) == 'open':
                continue  # leads back to a vertex on the current path
            dag.add_edge(vertex, successor)
            if successor not in state:
                visit(successor)
        state[vertex] = 'done'

    for vertex in sorted(graph.nodes, key=lambda v: (graph.in_degree(v) > 0, v)):
        if vertex not in state:
            visit(vertex)
    return dag


def layers(graph: nx.DiGraph) -> list[list[str]]:
    """Vertices in columns, each right of everything that feeds it.

    A feedback loop is laid out along the data flow and only its way back
    points left.  Within a column, vertices sit near the average row of
    their inputs (one barycentre sweep, ties by name), which keeps arrows
    short and uncrossed.
    """
    dag = without_cycles(graph)
    column_of: dict[str, int] = {}
    for vertex in nx.lexicographical_topological_sort(dag):
        column_of[vertex] = max((column_of[p] + 1 for p in dag.predecessors(vertex)), default=0)
    columns: list[list[str]] = [[] for _ in range(max(column_of.values(), default=-1) + 1)]
    for vertex in sorted(graph.nodes):
        columns[column_of[vertex]].append(vertex)
    row_of: dict[str, float] = {}
    for column in columns:
        def barycentre(vertex: str) -> tuple[float, str]:
            rows = [row_of[p] for p in dag.predecessors(vertex) if p in row_of]
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
    columns = layers(graph)
    rows = max((len(column) for column in columns), default=1)
    # About 1.6 inches per column keeps 9 pt labels apart and a 9-column
    # system readable at notebook width.
    width = min(15.0, max(6.0, 1.6 * len(columns)))
    figure = plt.figure(figsize=(width, max(2.5, 0.8 * rows + 1.0)))
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
        backwards = positions[target][0] <= positions[source][0]
        # Drawn after the labels (higher zorder), so that their boxes are in
        # place when each arrow is clipped to them and its head stays visible.
        axes.annotate('', xy=positions[target], xytext=positions[source], zorder=4,
                      arrowprops=dict(arrowstyle='-|>', color='#4a5568', linewidth=1.1,
                                      shrinkA=2, shrinkB=2,
                                      connectionstyle=f'arc3,rad={0.4 if backwards else 0}',
                                      patchA=labels[source].get_bbox_patch(),
                                      patchB=labels[target].get_bbox_patch()))
    xs = [x for x, _ in positions.values()]
    ys = [y for _, y in positions.values()]
    axes.set_xlim(min(xs) - X_GAP / 2, max(xs) + X_GAP / 2)
    axes.set_ylim(min(ys) - Y_GAP / 1.5, max(ys) + Y_GAP / 1.5)
    return figure
