"""A left-to-right graph picture that fits a page width: ranks wrap into bands.

:mod:`labkit.graph_dot` lays a graph out in one row of ranks.  When that is
wider than the page, consecutive ranks are split into as few, as even bands
as fit, stacked top to bottom, and dot lays each band out on its own.  An
edge from one band to another leaves its band on the right (dot routes it to
there around the shapes), runs down a lane on the right margin, left along
the corridor above the band it enters and down the left margin, and enters
that band from the left: it never runs through a band.  A group's box (a
namespace) is drawn in each band that holds some of its members, around
those: simpler than keeping a group in one band, and the wrapping edges
still only run in the margins and corridors.
"""
from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import networkx as nx
from matplotlib.path import Path
from matplotlib.transforms import Affine2D

from labkit.graph_dot import Box, Edge, Gaps, Group, Layout, Point, Size, lay_out
from labkit.graph_paths import joined, rounded

STUB_SIZE = (0.01, 0.01)  # inches: the point where a wrapping edge leaves or enters a band


@dataclass(frozen=True)
class Spacing:
    """Distances of the picture, in inches."""

    gaps: Gaps = Gaps()
    margin: float = 0.12       # around everything
    lane_margin: float = 0.14  # from a band to the first wrapping edge beside it
    lane_gap: float = 0.07     # between wrapping edges running side by side
    band_gap: float = 0.3      # between two bands, plus the lanes running there
    corner: float = 0.08       # radius of the wrapping edges' rounded corners


@dataclass
class Placement:
    """Where everything goes: shape centres and arrow paths, in inches, y up.

    `routes[(source, target)]` runs from the source's outline to the tip of
    the arrow at the target's outline.  `bands` counts the rows of ranks;
    `direction` is 'TB' where the ranks run top to bottom instead.  `boxes`
    are the groups' boxes, one per group and band.
    """

    width: float
    height: float
    centres: dict[str, Point]
    routes: dict[Edge, Path]
    bands: int = 1
    direction: str = 'LR'
    wrapping: int = 0  # edges running from one band to another
    boxes: list[Box] = field(default_factory=list)


def place(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
          max_width: float | None = None, spacing: Spacing = Spacing(),
          groups: Sequence[Group] = ()) -> Placement:
    """Lay `graph` out left to right for shapes ('ellipse', 'box') of the given
    (width, height) in inches, to fit `max_width` (unless a single rank is
    wider): wrapped into bands, or top to bottom when that fits and wrapping
    would send more than two edges per band around the margins or cut a
    group's box in two.  Each of `groups` is kept together in a box (one in
    each band that holds its members)."""
    whole = _stack(graph, sizes, shapes, [list(graph)], spacing, groups)
    if max_width is None or whole.width <= max_width:
        return whole
    wrapped = _wrap(graph, sizes, shapes, max_width, spacing, whole, groups)
    downwards = _top_to_bottom(graph, sizes, shapes, spacing, groups)
    if downwards.width <= max_width and (
            wrapped.width > max_width or wrapped.wrapping > 2 * (wrapped.bands - 1)
            or len(wrapped.boxes) > len(downwards.boxes)):
        return downwards
    return wrapped


def _top_to_bottom(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
                   spacing: Spacing, groups: Sequence[Group]) -> Placement:
    layout = lay_out(graph, sizes, shapes, spacing.gaps, direction='TB', groups=groups)
    shift = Affine2D().translate(spacing.margin, spacing.margin)
    return Placement(layout.width + 2 * spacing.margin, layout.height + 2 * spacing.margin,
                     {vertex: tuple(shift.transform(centre))
                      for vertex, centre in layout.centres.items()},
                     {edge: path.transformed(shift) for edge, path in layout.routes.items()},
                     direction='TB', boxes=[box.moved(shift) for box in layout.boxes])


def _wrap(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
          max_width: float, spacing: Spacing, whole: Placement, groups: Sequence[Group],
          ) -> Placement:
    """The narrowest of a few splits into bands; the first that fits."""
    ranks = _ranks(whole.centres, sizes)
    best, limit = whole, max_width - 2 * spacing.margin
    for _ in range(len(ranks)):
        bands = _split(ranks, limit, spacing.gaps.rank)
        if len(bands) == 1:
            break
        wrapped = _stack(graph, sizes, shapes, bands, spacing, groups)
        if wrapped.width < best.width:
            best = wrapped
        if wrapped.width <= max_width:
            break
        # lanes and dot's own ranking of each band add width: ask for narrower bands
        limit -= wrapped.width - max_width + 0.01
    return best


def _ranks(centres: Mapping[str, Point], sizes: Mapping[str, Size],
           ) -> list[tuple[list[str], float]]:
    """Vertices by rank (dot centres a rank on one x), left to right, with
    each rank's width."""
    by_x: dict[float, list[str]] = {}
    for vertex, (x, _) in centres.items():
        by_x.setdefault(round(x, 2), []).append(vertex)
    return [(sorted(by_x[x]), max(sizes[v][0] for v in by_x[x])) for x in sorted(by_x)]


def _split(ranks: list[tuple[list[str], float]], limit: float, gap: float,
           ) -> list[list[str]]:
    """Consecutive ranks in as few bands as fit `limit` inches each, as even
    as possible (the widest band as narrow as it can be)."""
    widths = [width for _, width in ranks]
    count = len(ranks)

    def span(first: int, last: int) -> float:
        return sum(widths[first:last]) + gap * (last - first - 1)

    inf = float('inf')
    # widest[b][j]: the widest band when ranks 0..j-1 go into b bands
    widest = [[inf] * (count + 1) for _ in range(count + 1)]
    cut = [[0] * (count + 1) for _ in range(count + 1)]
    widest[0][0] = 0.0
    bands_needed = count
    for b in range(1, count + 1):
        for j in range(1, count + 1):
            for i in range(b - 1, j):
                band = span(i, j)
                if band > limit and j - i > 1:
                    continue  # a single rank that is too wide must do
                candidate = max(widest[b - 1][i], band)
                if candidate < widest[b][j]:
                    widest[b][j], cut[b][j] = candidate, i
        if widest[b][count] < inf:
            bands_needed = b
            break
    bands, j = [], count
    for b in range(bands_needed, 0, -1):
        i = cut[b][j]
        bands.append([v for vertices, _ in ranks[i:j] for v in vertices])
        j = i
    return bands[::-1]


def _stub(kind: str, edge: Edge) -> str:
    """The name of the point where `edge` leaves ('out') or enters ('in') a
    band; a space is never part of a ROS name."""
    return f' {kind} {edge[0]} {edge[1]}'


def _band_layouts(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
                  bands: list[list[str]], wrapping: list[Edge], gaps: Gaps,
                  groups: Sequence[Group]) -> list[Layout]:
    """Each band laid out by dot, with a stub for every wrapping edge: the
    rightmost rank for those leaving, the leftmost for those entering."""
    band_of = {vertex: b for b, members in enumerate(bands) for vertex in members}
    layouts = []
    for b, members in enumerate(bands):
        band = nx.DiGraph(graph.subgraph(members))
        exits = [edge for edge in wrapping if band_of[edge[0]] == b]
        entries = [edge for edge in wrapping if band_of[edge[1]] == b]
        band.add_edges_from(((source, _stub('out', (source, target))) for source, target in exits),
                            arrow=False)
        band.add_edges_from((_stub('in', (source, target)), target) for source, target in entries)
        stubs = {vertex for vertex in band if vertex not in graph}
        layouts.append(lay_out(band, {**sizes, **dict.fromkeys(stubs, STUB_SIZE)},
                               {**shapes, **dict.fromkeys(stubs, 'point')}, gaps,
                               first=[_stub('in', edge) for edge in entries],
                               last=[_stub('out', edge) for edge in exits], groups=groups))
    return layouts


def _stack(graph: nx.DiGraph, sizes: Mapping[str, Size], shapes: Mapping[str, str],
           bands: list[list[str]], spacing: Spacing, groups: Sequence[Group] = (),
           ) -> Placement:
    """The bands laid out and stacked top to bottom, wrapping edges in lanes."""
    band_of = {vertex: b for b, members in enumerate(bands) for vertex in members}
    wrapping = sorted(edge for edge in graph.edges if band_of[edge[0]] != band_of[edge[1]])
    layouts = _band_layouts(graph, sizes, shapes, bands, wrapping, spacing.gaps, groups)
    entering = [sum(1 for edge in wrapping if band_of[edge[1]] == b) for b in range(len(bands))]
    left = spacing.margin + (spacing.lane_margin + max(entering) * spacing.lane_gap
                             if wrapping else 0.0)
    corridors = [spacing.band_gap + n * spacing.lane_gap if b or n else 0.0
                 for b, n in enumerate(entering)]
    height = (2 * spacing.margin + sum(layout.height for layout in layouts)
              + sum(corridors))
    shifts, top = [], height - spacing.margin
    for layout, corridor in zip(layouts, corridors, strict=True):
        top -= corridor
        shifts.append(Affine2D().translate(left, top - layout.height))
        top -= layout.height
    centres: dict[str, Point] = {}
    routes: dict[Edge, Path] = {}
    for layout, shift in zip(layouts, shifts, strict=True):
        for vertex, centre in layout.centres.items():
            centres[vertex] = tuple(shift.transform(centre))
        for edge, path in layout.routes.items():
            routes[edge] = path.transformed(shift)
    right = left + max(layout.width for layout in layouts)
    lanes = _lanes(wrapping, centres, band_of, right, shifts, layouts, left, spacing)
    for edge in wrapping:
        out, into = _stub('out', edge), _stub('in', edge)
        routes[edge] = joined([routes.pop((edge[0], out)), lanes[edge],
                               routes.pop((into, edge[1]))])
    width = right + spacing.margin + (spacing.lane_margin + len(wrapping) * spacing.lane_gap
                                      if wrapping else 0.0)
    real = {vertex: centre for vertex, centre in centres.items() if vertex in graph}
    boxes = [box.moved(shift) for layout, shift in zip(layouts, shifts, strict=True)
             for box in layout.boxes]
    return Placement(width, height, real, routes, len(bands), wrapping=len(wrapping),
                     boxes=boxes)


def _lanes(wrapping: list[Edge], centres: Mapping[str, Point], band_of: Mapping[str, int],
           right: float, shifts: list[Affine2D], layouts: list[Layout], left: float,
           spacing: Spacing) -> dict[Edge, Path]:
    """The way of each wrapping edge from its exit to its entry point: right to
    its lane on the right margin, along it to the corridor above the band it
    enters, left to its lane on the left margin, to its entry point.

    The lowest exits take the innermost lanes on the right, so no edge runs
    across another's way down, and edges back up to an earlier band (a loop's
    way back) the outermost; in a corridor, an inner lane turns higher and
    then runs down further out, so lanes do not cross there either.
    """
    def exit_y(edge: Edge) -> float:
        return centres[_stub('out', edge)][1]

    def lane_key(edge: Edge) -> tuple:
        band = band_of[edge[0]]
        if band_of[edge[1]] < band:  # back up: outside every edge going down
            return (1, band, exit_y(edge), edge)
        return (0, -band, exit_y(edge), edge)

    order = sorted(wrapping, key=lane_key)
    lane_x = {edge: right + spacing.lane_margin + k * spacing.lane_gap
              for k, edge in enumerate(order)}
    lanes = {}
    for b, (shift, layout) in enumerate(zip(shifts, layouts, strict=True)):
        entering = [edge for edge in order if band_of[edge[1]] == b]
        band_top = shift.transform((0.0, layout.height))[1]
        corridor_top = band_top + spacing.band_gap / 2 + len(entering) * spacing.lane_gap
        for j, edge in enumerate(entering):
            start, end = centres[_stub('out', edge)], centres[_stub('in', edge)]
            y = corridor_top - j * spacing.lane_gap
            x = left - spacing.lane_margin - (len(entering) - 1 - j) * spacing.lane_gap
            lanes[edge] = rounded([start, (lane_x[edge], start[1]), (lane_x[edge], y), (x, y),
                                   (x, end[1]), end], spacing.corner)
    return lanes
