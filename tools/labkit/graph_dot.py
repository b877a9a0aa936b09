"""Lay a directed graph out left to right with Graphviz's ``dot``, in inches.

``dot`` (bundled in the pygraphviz wheel, so no system Graphviz is needed)
does what a layered picture of data flow needs: ranks from left to right,
feedback loops broken so only their way back points left, few crossings,
and splines routed around every shape.  Shapes are given at their measured
size, so nothing overlaps whatever the labels say.  Groups of vertices (the
nodes of one namespace) become dot clusters: dot keeps each group together
inside a box with room for its label and reports where the box is.  The
same graph and sizes always give the same picture.
"""
from __future__ import annotations

import math
from collections.abc import Callable, Collection, Mapping, Sequence
from dataclasses import dataclass, field

import networkx as nx
import pygraphviz
from matplotlib.path import Path
from matplotlib.transforms import Affine2D

Point = tuple[float, float]
Size = tuple[float, float]
Edge = tuple[str, str]

POINTS_PER_INCH = 72.0
DOT_ARROW_LENGTH = 10.0  # points, at arrowsize 1
CLUSTER_MARGIN = 6.0  # points between a group's box and the shapes in it


@dataclass(frozen=True)
class Gaps:
    """Distances dot keeps, in inches."""

    rank: float = 0.38      # between two ranks: room for the arrows' curves
    node: float = 0.2       # between two shapes in one rank
    clearance: float = 0.03  # around each shape, kept free of other edges
    #: of the arrowhead a drawing puts at an edge's end: dot ends the spline
    #: that far before the shape and gives the tip
    arrow_head: float = 0.06


@dataclass(frozen=True)
class Group:
    """Vertices dot keeps together in one box, with room at the box's top
    left for a label of `label` (width, height) inches."""

    name: str
    members: frozenset[str]
    label: Size


@dataclass(frozen=True)
class Box:
    """Where a :class:`Group` (or the part of it in one band) was put:
    left, bottom, right, top in inches, y up; its label's room is at the top left."""

    name: str
    bounds: tuple[float, float, float, float]

    def moved(self, shift: Affine2D) -> Box:
        left, bottom, right, top = self.bounds
        (left, bottom), (right, top) = shift.transform([(left, bottom), (right, top)])
        return Box(self.name, (float(left), float(bottom), float(right), float(top)))


@dataclass
class Layout:
    """Shape centres and edge paths in inches, y up, inside `width` x `height`.

    `routes[(tail, head)]` runs from the tail's outline to the tip of the
    arrow at the head's outline (to the head's centre for an edge whose
    data says ``arrow=False``).  `boxes` are the groups' boxes.
    """

    width: float
    height: float
    centres: dict[str, Point]
    routes: dict[Edge, Path]
    boxes: list[Box] = field(default_factory=list)


def lay_out(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
            gaps: Gaps = Gaps(), first: Collection[str] = (), last: Collection[str] = (),
            direction: str = 'LR', groups: Sequence[Group] = ()) -> Layout:
    """Lay `graph` out for shapes (dot's 'ellipse', 'box', 'point') of the given
    (width, height) in inches; `first` / `last` vertices get the first / last
    rank to themselves.  `direction` is dot's rankdir: 'LR' or 'TB'.  Each of
    `groups` (disjoint) is kept together in a box.

    Each connected part (a group counting as connected) is laid out on its
    own and the parts are stacked in the order of their names (top to
    bottom, or left to right for 'TB'), so two robots' chains show in the
    order a reader expects.
    """
    parts = sorted((sorted(part) for part in _parts(graph, groups)), key=lambda part: part[0])
    layouts = [_lay_out_part(nx.DiGraph(graph.subgraph(part)), sizes, shapes, gaps,
                             set(first) & set(part), set(last) & set(part), direction,
                             _within(groups, part))
               for part in parts]
    if not layouts:
        return Layout(0.0, 0.0, {}, {})
    downwards = direction == 'LR'
    if downwards:
        width = max(layout.width for layout in layouts)
        height = sum(layout.height for layout in layouts) + gaps.node * (len(layouts) - 1)
    else:
        width = sum(layout.width for layout in layouts) + gaps.node * (len(layouts) - 1)
        height = max(layout.height for layout in layouts)
    stacked = Layout(width, height, {}, {})
    offset = height if downwards else 0.0
    for layout in layouts:
        if downwards:
            offset -= layout.height
            shift = Affine2D().translate(0.0, offset)
            offset -= gaps.node
        else:
            shift = Affine2D().translate(offset, 0.0)
            offset += layout.width + gaps.node
        stacked.centres.update({vertex: tuple(shift.transform(centre))
                                for vertex, centre in layout.centres.items()})
        stacked.routes.update({edge: path.transformed(shift)
                               for edge, path in layout.routes.items()})
        stacked.boxes.extend(box.moved(shift) for box in layout.boxes)
    return stacked


def _parts(graph: nx.DiGraph, groups: Sequence[Group]) -> list[set[str]]:
    """The weakly connected parts of `graph`, where a group's members count as
    joined: a group is never split over two parts (and so two boxes)."""
    joined = nx.Graph(graph.to_undirected(as_view=True))
    for group in groups:
        members = sorted(group.members & set(graph))
        joined.add_edges_from(zip(members, members[1:], strict=False))
    return list(nx.connected_components(joined))


def _within(groups: Sequence[Group], vertices: Collection[str]) -> list[Group]:
    """The groups with only their members among `vertices`, empty ones left out."""
    kept = [Group(group.name, group.members & set(vertices), group.label) for group in groups]
    return [group for group in kept if group.members]


def _lay_out_part(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
                  gaps: Gaps, first: Collection[str], last: Collection[str], direction: str,
                  groups: Sequence[Group]) -> Layout:
    drawing = _to_dot(graph, sizes, shapes, gaps, first, last, direction)
    for index, group in enumerate(groups):
        _add_cluster(drawing, index, group)
    drawing.layout(prog='dot')
    _, _, right, top = (float(value) for value in drawing.graph_attr['bb'].split(','))

    def inches(x: float, y: float) -> Point:
        return x / POINTS_PER_INCH, y / POINTS_PER_INCH

    return Layout(right / POINTS_PER_INCH, top / POINTS_PER_INCH,
                  {str(node): inches(*_point(node.attr['pos'])) for node in drawing.nodes()},
                  {(str(edge[0]), str(edge[1])): _spline(edge.attr['pos'], inches,
                                                         gaps.clearance)
                   for edge in drawing.edges()},
                  [Box(group.name, _bounds(drawing.get_subgraph(_cluster(index)), inches))
                   for index, group in enumerate(groups)])


def _cluster(index: int) -> str:
    """dot lays out a subgraph as a box when its name starts with 'cluster'."""
    return f'cluster_{index}'


def _add_cluster(drawing: pygraphviz.AGraph, index: int, group: Group) -> None:
    """`group` as a dot cluster whose label is an empty cell of the label's
    size: dot reserves the room at the top left and the drawing writes the
    label there with its own font."""
    width, height = (max(1, math.ceil(side * POINTS_PER_INCH)) for side in group.label)
    room = (f'<<table border="0" cellborder="0" cellpadding="0" cellspacing="0"><tr>'
            f'<td fixedsize="true" width="{width}" height="{height}"></td></tr></table>>')
    drawing.add_subgraph(sorted(group.members), name=_cluster(index), label=room,
                         labeljust='l', labelloc='t', margin=CLUSTER_MARGIN)


def _bounds(cluster: pygraphviz.AGraph, inches: Callable[[float, float], Point],
            ) -> tuple[float, float, float, float]:
    left, bottom, right, top = (float(value) for value in cluster.graph_attr['bb'].split(','))
    return (*inches(left, bottom), *inches(right, top))


def _to_dot(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
            gaps: Gaps, first: Collection[str], last: Collection[str], direction: str,
            ) -> pygraphviz.AGraph:
    """The graph in dot's terms, each shape with room around it.

    Sources go in first: dot breaks a cycle at the first edge its depth-first
    search finds closing it, so a loop entered from outside starts where data
    enters it.
    """
    drawing = pygraphviz.AGraph(directed=True, strict=False)
    room = 2 * gaps.clearance  # part of the gaps between the shapes
    drawing.graph_attr.update(rankdir=direction, ranksep=gaps.rank - room,
                              nodesep=gaps.node - room, pad=0, splines='spline')
    drawing.node_attr.update(fixedsize='true', label='', margin=0, penwidth=0)
    drawing.edge_attr.update(arrowsize=gaps.arrow_head * POINTS_PER_INCH / DOT_ARROW_LENGTH)
    order = sorted(graph, key=lambda vertex: (graph.in_degree(vertex) > 0, vertex))
    for vertex in order:
        width, height = sizes[vertex]
        drawing.add_node(vertex, shape=shapes[vertex], width=width + 2 * gaps.clearance,
                         height=height + 2 * gaps.clearance)
    for vertex in order:
        for target in sorted(graph.successors(vertex)):
            arrow = graph.edges[vertex, target].get('arrow', True)
            drawing.add_edge(vertex, target, **({} if arrow else {'dir': 'none'}))
    for name, members in (('source', first), ('sink', last)):
        if members:
            drawing.add_subgraph(sorted(members), rank=name)
    return drawing


def _point(text: str) -> Point:
    x, y = text.split(',')
    return float(x), float(y)


def _spline(text: str, inches: Callable[[float, float], Point], clearance: float) -> Path:
    """dot's edge position ('e,x,y' tip, then start point and Bézier control
    triples) as a path from the start to the arrow's tip, both ends carried on
    by `clearance` (into the room dot kept around the shapes, where a drawing
    cuts them at the shapes' outlines)."""
    tip = None
    points = []
    for item in text.split(';')[0].split():
        if item.startswith('e,'):
            tip = inches(*_point(item[2:]))
        elif not item.startswith('s,'):
            points.append(inches(*_point(item)))
    codes = [Path.MOVETO] + [Path.CURVE4] * (len(points) - 1)
    if tip is not None:
        points.append(tip)
        codes.append(Path.LINETO)
    points = [_beyond(points[0], points[1], clearance), *points[1:-1],
              _beyond(points[-1], points[-2], clearance)]
    return Path(points, codes)


def _beyond(end: Point, before: Point, length: float) -> Point:
    """`end` moved `length` further along the way from `before`."""
    dx, dy = end[0] - before[0], end[1] - before[1]
    run = (dx * dx + dy * dy) ** 0.5
    if run == 0:
        return end
    return end[0] + dx * length / run, end[1] + dy * length / run
