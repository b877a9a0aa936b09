"""Draw a :class:`GraphSnapshot` the way rqt_graph does: nodes as ellipses,
topics as boxes, arrows from publisher to topic to subscriber.

Every label is measured with the figure's own renderer first, and Graphviz's
dot (:mod:`labkit.graph_dot`) lays the shapes out at those sizes, so shapes
never overlap and arrows never cross a label.  The figure stays within
notebook width (:data:`MAX_WIDTH`): a wide graph first gets a smaller font,
then wraps into bands and grows downwards (:mod:`labkit.graph_bands`; top to
bottom instead when wrapping would send many edges around the margins).
Each namespace that holds nodes is a labelled, shaded box around its nodes
and topics (:mod:`labkit.graph_namespaces`), laid out by dot as a cluster,
so two robots, each in its namespace, show as two boxes.
The layout is deterministic, so an executed lesson shows the same picture on
every build.

In a notebook the figure shows itself as a captioned picture
(:class:`GraphFigure`): an HTML ``<figure>`` whose ``<img>`` has an alt text
listing every node and connection and is displayed at one scale for every
graph (:data:`DISPLAY_PX_PER_INCH`), so two graphs on a page compare at a
glance and labels stay readable at the column width.

This module renders a snapshot it is given and imports nothing of
:mod:`labkit.graph`, so a snapshot can draw itself (``GraphSnapshot.draw``)
while :func:`labkit.drawing.draw_graph` takes a snapshot when given none.
"""
from __future__ import annotations

import base64
import html
import io
from typing import Any

import matplotlib.pyplot as plt
import networkx as nx
from matplotlib.figure import Figure
from matplotlib.font_manager import FontProperties
from matplotlib.patches import BoxStyle, FancyBboxPatch
from matplotlib.path import Path
from matplotlib.text import Text
from matplotlib.transforms import Affine2D

from labkit.graph_bands import Placement, Spacing, place
from labkit.graph_dot import Box, Gaps, Group, Size
from labkit.graph_namespaces import describe_groups, groups
from labkit.graph_paths import FollowPath

__all__ = ['DISPLAY_PX_PER_INCH', 'MAX_WIDTH', 'GraphFigure', 'describe', 'layers', 'layout',
           'render', 'to_networkx']

#: Widest figure, in inches: what a notebook shows without scaling it down.
MAX_WIDTH = 9.5
#: Label sizes in points, tried in turn before wrapping into bands (at the first).
FONT_SIZES = (9.0, 8.0)
TITLE_SIZE = 11.0
TITLE_SPACE = 0.4  # inches above the graph for the title
#: Screen pixels per figure inch for every graph on a page: MAX_WIDTH fits the
#: book's content column (874 px), where a 9 pt label is 11.5 px high.
DISPLAY_PX_PER_INCH = 92
PNG_DPI = 2 * DISPLAY_PX_PER_INCH  # sharp on high-density screens too


class GraphFigure(Figure):
    """A graph picture that carries its caption and description to the page.

    Jupyter renders the ``text/html`` part of :meth:`_repr_mimebundle_`: a
    ``<figure>`` with the alt text and a ``<figcaption>``, the width fixed at
    the book's scale.  ``image/png`` (with ``alt`` metadata) is there for
    front ends that show no HTML.
    """

    caption: str = ''
    description: str = ''

    def png(self) -> bytes:
        """The picture at exactly the figure's size (no tight bounding box, so
        every graph keeps the same scale)."""
        buffer = io.BytesIO()
        self.savefig(buffer, format='png', dpi=PNG_DPI, facecolor='white')
        return buffer.getvalue()

    def display_width(self) -> int:
        """Width in screen pixels at the book's scale."""
        return round(self.get_figwidth() * DISPLAY_PX_PER_INCH)

    def to_html(self, encoded: str | None = None) -> str:
        """The captioned ``<figure>``; `encoded` is the base64 PNG if already made."""
        encoded = encoded or base64.b64encode(self.png()).decode('ascii')
        return (f'<figure class="ros-graph">'
                f'<img src="data:image/png;base64,{encoded}" width="{self.display_width()}" '
                f'alt="{html.escape(self.description)}">'
                f'<figcaption>{html.escape(self.caption)}</figcaption></figure>')

    def _repr_mimebundle_(self, include: Any = None, exclude: Any = None,
                          ) -> tuple[dict[str, str], dict[str, Any]]:
        encoded = base64.b64encode(self.png()).decode('ascii')
        data = {'text/html': self.to_html(encoded), 'image/png': encoded,
                'text/plain': f'<ROS graph: {self.caption}>'}
        metadata = {'image/png': {'alt': self.description, 'width': self.display_width()}}
        return data, metadata


class Ellipse(BoxStyle.Ellipse):
    """An ellipse around a label that is taller and so narrower than matplotlib's.

    matplotlib's ellipse circumscribes the padded label with both axes
    stretched by √2, which makes long node names very wide.  Stretching the
    height by 2 instead needs only 2/√3 ≈ 1.15 of the width, still with the
    whole label inside.
    """

    HEIGHT_STRETCH = 2.0

    def __call__(self, x0: float, y0: float, width: float, height: float,
                 mutation_size: float) -> Path:
        pad = mutation_size * self.pad
        width, height = width + 2 * pad, height + 2 * pad
        b = height / 2 * self.HEIGHT_STRETCH
        a = width / 2 / (1 - 1 / self.HEIGHT_STRETCH ** 2) ** 0.5
        centre_x, centre_y = x0 + width / 2 - pad, y0 + height / 2 - pad
        return Path.unit_circle().transformed(
            Affine2D().scale(a, b).translate(centre_x, centre_y))


NODE_STYLE = dict(boxstyle=Ellipse(pad=0.3), facecolor='#dbe9f6', edgecolor='#2b6cb0',
                  linewidth=1.2)
TOPIC_STYLE = dict(boxstyle='square,pad=0.5', facecolor='#fdf1dc', edgecolor='#b7791f',
                   linewidth=1.2)
ARROW_COLOR = '#4a5568'
ARROW_SCALE = 11.0  # points; the head of '-|>' is 0.4 of it long and 0.2 of it wide
SPACING = Spacing(gaps=Gaps(arrow_head=0.4 * ARROW_SCALE / 72))
TEXT_COLOR = '#1a202c'
#: A namespace's box: under everything else, lighter than the shapes in it.
BOX_STYLE = dict(boxstyle='round,pad=0,rounding_size=0.08', facecolor='#f1f3f6',
                 edgecolor='#a0aec0', linewidth=1.0, zorder=1)
BOX_LABEL_COLOR = '#4a5568'
BOX_LABEL_BACKGROUND = dict(boxstyle='square,pad=0.1', facecolor=BOX_STYLE['facecolor'],
                            edgecolor='none')
BOX_LABEL_INSET = 0.05  # inches from the box's top left corner to its label (< dot's margin)


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
    """Vertices in columns, each right of everything that feeds it, top to bottom.

    A feedback loop is laid out along the data flow and only its way back
    points left.
    """
    columns: dict[float, list[tuple[float, str]]] = {}
    for vertex, (x, y) in layout(graph).items():
        columns.setdefault(round(x, 3), []).append((-y, vertex))
    return [[vertex for _, vertex in sorted(columns[x])] for x in sorted(columns)]


def layout(graph: nx.DiGraph, sizes: dict[str, tuple[float, float]] | None = None,
           ) -> dict[str, tuple[float, float]]:
    """x, y centre (inches, y up) of every vertex for shapes of the given sizes
    (default: 1.2 x 0.35 inches each)."""
    return layout_plan(graph, sizes).centres


def layout_plan(graph: nx.DiGraph, sizes: dict[str, tuple[float, float]] | None = None,
                max_width: float | None = None, label_sizes: dict[str, Size] | None = None,
                ) -> Placement:
    """The full :class:`~labkit.graph_bands.Placement` (centres, arrow paths and
    namespace boxes), wrapped into bands to fit `max_width`.  `label_sizes`
    gives the room, in inches, of each namespace box's label (default: an
    estimate from its length)."""
    if sizes is None:
        sizes = {vertex: (1.2, 0.35) for vertex in graph}
    shapes = {vertex: 'ellipse' if graph.nodes[vertex].get('kind') == 'node' else 'box'
              for vertex in graph}
    label_sizes = label_sizes or {}
    namespaces = [Group(space, frozenset(members),
                        label_sizes.get(space, (0.08 * len(space) + 0.1, 0.17)))
                  for space, members in groups(graph).items()]
    return place(graph, sizes, shapes, max_width, SPACING, namespaces)


def _label(vertex: str, graph: nx.DiGraph, show_types: bool) -> str:
    if graph.nodes[vertex]['kind'] == 'topic' and show_types:
        return f"{vertex}\n[{graph.nodes[vertex]['type']}]"
    return vertex


def _measure(labels: dict[str, Text], figure: Figure, fontsize: float,
             ) -> dict[str, tuple[float, float]]:
    """Width and height, in inches, of each label's shape at `fontsize`."""
    renderer = figure.canvas.get_renderer()
    sizes = {}
    for vertex, label in labels.items():
        label.set_fontsize(fontsize)
        label.update_bbox_position_size(renderer)
        extent = label.get_bbox_patch().get_window_extent(renderer)
        sizes[vertex] = (extent.width / figure.dpi, extent.height / figure.dpi)
    return sizes


def _measure_box_labels(graph: nx.DiGraph, figure: Figure, fontsize: float,
                        ) -> dict[str, Size]:
    """The room, in inches, each namespace's label needs at the top left of its box."""
    renderer = figure.canvas.get_renderer()
    font = FontProperties(size=fontsize)
    sizes = {}
    for space in groups(graph):
        width, height, _ = renderer.get_text_width_height_descent(space, font, ismath=False)
        # dot keeps its margin above and below the label's room, which is
        # where the inset goes
        sizes[space] = (width / figure.dpi + 2 * BOX_LABEL_INSET, height / figure.dpi)
    return sizes


def _fit(graph: nx.DiGraph, labels: dict[str, Text], figure: Figure,
         ) -> tuple[Placement, float]:
    """The layout at the font size that fits with the fewest bands, left to
    right if it can (the larger size on a tie), and that size; leaves the
    labels at it."""
    plans = [(layout_plan(graph, _measure(labels, figure, size), MAX_WIDTH,
                          _measure_box_labels(graph, figure, size)), size)
             for size in FONT_SIZES]
    plan, fontsize = min(plans, key=lambda entry: (
        entry[0].width > MAX_WIDTH, entry[0].bands, entry[0].direction != 'LR', -entry[1]))
    _measure(labels, figure, fontsize)
    return plan, fontsize


def describe(graph: nx.DiGraph) -> str:
    """What the picture shows, in words: the alt text a screen reader reads."""
    nodes = sorted(v for v in graph if graph.nodes[v]['kind'] == 'node')
    if not nodes:
        return 'ROS graph with no nodes.'
    parts = [f"ROS graph of {len(nodes)} node{'s' * (len(nodes) != 1)}: {', '.join(nodes)}."]
    for topic in sorted(v for v in graph if graph.nodes[v]['kind'] == 'topic'):
        publishers = ', '.join(sorted(graph.predecessors(topic))) or 'nobody'
        subscribers = ', '.join(sorted(graph.successors(topic))) or 'nobody'
        parts.append(f'Topic {topic} is published by {publishers} and read by {subscribers}.')
    return ' '.join(parts + [describe_groups(graph)]).rstrip()


def default_caption(graph: nx.DiGraph, title: str | None) -> str:
    """A caption that says what the picture shows and how to read it."""
    kinds = [graph.nodes[v]['kind'] for v in graph]
    nodes, topics = kinds.count('node'), kinds.count('topic')
    shown = (f"{nodes} node{'s' * (nodes != 1)} (ellipses) and "
             f"{topics} topic{'s' * (topics != 1)} (boxes); each arrow runs from a "
             f"publisher to its topic or from a topic to a subscriber")
    if groups(graph):
        shown += '; each shaded box holds the nodes and topics of one namespace'
    return f'The ROS graph, {title}: {shown}.' if title else f'The ROS graph: {shown}.'


def render(snapshot: Any, *, show_types: bool = False, title: str | None = None,
           caption: str | None = None) -> GraphFigure:
    """Draw `snapshot` and return the matplotlib Figure (shown inline by Jupyter).

    `show_types=True` writes each topic's message type under its name.
    `caption` is the line under the picture on the page (default: what the
    graph holds, and how to read it); the alt text lists every node and
    connection.  (:func:`labkit.draw_graph` also takes a snapshot when given none.)
    """
    graph = to_networkx(snapshot)
    figure = plt.figure(figsize=(4.0, 1.0), FigureClass=GraphFigure)
    figure.caption = caption or default_caption(graph, title)
    figure.description = describe(graph)
    try:  # measuring needs the open figure's canvas
        _draw(figure, graph, show_types, title)
    finally:
        plt.close(figure)  # returned, not also auto-shown: Jupyter displays it once
    return figure


def _draw(figure: Figure, graph: nx.DiGraph, show_types: bool, title: str | None) -> None:
    axes = figure.add_axes((0.0, 0.0, 1.0, 1.0))
    axes.set_axis_off()
    if title:
        axes.set_title(title, fontsize=TITLE_SIZE, color=TEXT_COLOR, pad=8)
    if not graph:
        axes.text(0.5, 0.5, 'no nodes in the graph', ha='center', va='center',
                  fontsize=FONT_SIZES[0] + 1, color='#718096', transform=axes.transAxes)
        _reserve_title_space(figure, axes, 4.0, 1.0, bool(title))
        return
    labels = {
        vertex: axes.text(0, 0, _label(vertex, graph, show_types), ha='center', va='center',
                          color=TEXT_COLOR, zorder=3, multialignment='center',
                          bbox=NODE_STYLE if graph.nodes[vertex]['kind'] == 'node'
                          else TOPIC_STYLE)
        for vertex in sorted(graph)}
    plan, fontsize = _fit(graph, labels, figure)
    width, height = plan.width, plan.height
    if title:  # never cut the title off
        extent = axes.title.get_window_extent(figure.canvas.get_renderer())
        width = max(width, extent.width / figure.dpi + 0.4)
    _reserve_title_space(figure, axes, width, height, bool(title))
    spare = (width - plan.width) / 2  # under a wide title, the graph sits centred
    axes.set_xlim(-spare, plan.width + spare)
    axes.set_ylim(0, height)
    for vertex, label in labels.items():
        label.set_position(plan.centres[vertex])
    for box in plan.boxes:
        _draw_box(axes, box, fontsize)
    for source, target in sorted(graph.edges):
        # Arrows are drawn after the labels (higher zorder): each label has
        # placed its shape by then, and the arrow is cut at that shape.
        axes.annotate('', xy=plan.centres[target], xytext=plan.centres[source], zorder=4,
                      arrowprops=dict(
                          arrowstyle='-|>', color=ARROW_COLOR, linewidth=1.1,
                          mutation_scale=ARROW_SCALE, shrinkA=1.0, shrinkB=0.5,
                          connectionstyle=FollowPath(plan.routes[(source, target)],
                                                     axes.transData),
                          patchA=labels[source].get_bbox_patch(),
                          patchB=labels[target].get_bbox_patch()))


def _draw_box(axes: Any, box: Box, fontsize: float) -> None:
    """A namespace's shaded box, under the shapes and arrows, with its label
    at the top left where dot left room for it.  An edge entering the box
    from the side may still pass there (dot keeps only the box's own edges
    off its label), so the label is drawn over the arrows, on the box's shade."""
    left, bottom, right, top = box.bounds
    axes.add_patch(FancyBboxPatch((left, bottom), right - left, top - bottom,
                                  gid=f'namespace {box.name}', **BOX_STYLE))
    axes.text(left + BOX_LABEL_INSET, top - BOX_LABEL_INSET, box.name, ha='left', va='top',
              fontsize=fontsize, color=BOX_LABEL_COLOR, zorder=5, gid=f'namespace {box.name}',
              bbox=BOX_LABEL_BACKGROUND)


def _reserve_title_space(figure: Figure, axes: Any, width: float, height: float,
                         titled: bool) -> None:
    """Size the figure to `width` x `height` inches of axes, plus room for a title."""
    total = height + (TITLE_SPACE if titled else 0.0)
    figure.set_size_inches(width, total)
    axes.set_position((0.0, 0.0, 1.0, height / total))
