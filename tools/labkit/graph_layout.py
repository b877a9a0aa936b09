"""Layered left-to-right layout of a directed graph, measured in inches.

Sugiyama's recipe, kept small: break cycles, give every vertex a column
(sources left), thread long edges through placeholder slots ("dummies") so
they never run through a shape, order each column to avoid crossings, then
place rows so arrows stay as straight as the columns allow.  Columns are as
wide as their widest shape, so nothing overlaps whatever the labels say.
When the columns do not fit the page width, they wrap into bands stacked
top to bottom, and edges crossing from one band to the next run around the
bands instead of through them.

Everything here is plain geometry (no renderer) and deterministic: the same
graph and sizes always give the same picture.
"""
from __future__ import annotations

from collections.abc import Callable, Hashable, Mapping, Sequence
from dataclasses import dataclass
from itertools import pairwise

import networkx as nx
from matplotlib.path import Path

from labkit.graph_paths import Pen

Point = tuple[float, float]
Size = tuple[float, float]
Edge = tuple[str, str]
Hop = tuple[Hashable, Hashable, bool]  # left item, right item, part of a back edge


@dataclass(frozen=True)
class Spacing:
    """Distances of the layout, in inches."""

    column_gap: float = 0.38    # between two columns: room for the arrows' curves
    row_gap: float = 0.2        # between two shapes stacked in a column
    lead: float = 0.03          # straight run of an arrow beside a shape in a wide column
    passage: float = 0.08       # height of the slot a long edge takes in a column
    passage_gap: float = 0.08   # between such a slot and its neighbours
    port_gap: float = 0.07      # between the ends of arrows sharing a side of a shape
    margin: float = 0.12        # around everything
    lane_margin: float = 0.14   # from a band to the first wrapped edge beside it
    lane_gap: float = 0.07      # between wrapped edges running side by side
    band_gap: float = 0.3       # between two bands, plus the lanes running there
    corner: float = 0.08        # radius of the rounded corners of wrapped edges


@dataclass
class Placement:
    """Where everything goes: shape centres and arrow paths, in inches, y up.

    `routes[(source, target)]` runs from the source's centre to the target's
    centre (a drawing clips it at both shapes).
    """

    width: float
    height: float
    centres: dict[str, Point]
    routes: dict[Edge, Path]
    columns: list[list[str]]
    bands: int = 1


@dataclass(frozen=True)
class _Dummy:
    """A slot in one column that a long edge passes through.

    Forward edges from one source share their slots (`edge` is then
    (source, '') and `index` the column) until they branch off to their
    targets: one line that forks, not a bundle of parallel ones.
    """

    edge: Edge
    index: int


def _key(item: Hashable) -> tuple:
    """Sort key mixing real vertices (names) and dummies, real ones first."""
    if isinstance(item, _Dummy):
        return (1, *item.edge, item.index)
    return (0, str(item))


def flow_order(graph: nx.DiGraph) -> list[str]:
    """All vertices in data-flow order, so that few edges point backwards.

    Eades, Lin and Smyth's greedy heuristic for a small feedback arc set:
    sources go to the front, sinks to the back; when only cycles remain, the
    vertex most fed by what is already placed goes next (where data enters a
    loop), then the one with most outputs over inputs, then by name.
    """
    remaining = graph.copy()
    front: list[str] = []
    back: list[str] = []
    while remaining:
        changed = True
        while changed:
            sinks = sorted(v for v in remaining if remaining.out_degree(v) == 0)
            back[:0] = sinks
            remaining.remove_nodes_from(sinks)
            sources = sorted(v for v in remaining if remaining.in_degree(v) == 0)
            front += sources
            remaining.remove_nodes_from(sources)
            changed = bool(sinks or sources)
        if remaining:
            placed = set(front)
            chosen = min(remaining, key=lambda v, placed=placed: (
                -sum(1 for p in graph.predecessors(v) if p in placed),
                remaining.in_degree(v) - remaining.out_degree(v), v))
            front.append(chosen)
            remaining.remove_node(chosen)
    return front + back


def without_cycles(graph: nx.DiGraph) -> nx.DiGraph:
    """The graph minus the edges that close a cycle (a feedback loop's way back):
    those pointing backwards in :func:`flow_order`.  Deterministic."""
    position = {v: i for i, v in enumerate(flow_order(graph))}
    dag = nx.DiGraph()
    dag.add_nodes_from(graph.nodes)
    dag.add_edges_from((u, v) for u, v in graph.edges if position[u] < position[v])
    return dag


@dataclass
class _Layering:
    """Columns (top to bottom, dummies included) and each edge's chain through them."""

    columns: list[list[Hashable]]
    chains: dict[Edge, list[Hashable]]   # left to right; reversed for back edges
    back: set[Edge]

    def column_of(self) -> dict[Hashable, int]:
        return {item: c for c, column in enumerate(self.columns) for item in column}

    def chain_hops(self, edge: Edge) -> list[Hop]:
        chain = self.chains[edge]
        return [(left, right, edge in self.back) for left, right in pairwise(chain)]

    def hops(self) -> list[Hop]:
        """Every hop between neighbouring columns, once (shared slots share hops)."""
        return list(dict.fromkeys(hop for edge in self.chains for hop in self.chain_hops(edge)))


def _columns(graph: nx.DiGraph) -> tuple[nx.DiGraph, dict[str, int], set[Edge]]:
    """The graph without self-loops, each vertex's column, and the back edges."""
    graph = graph.copy()
    graph.remove_edges_from(list(nx.selfloop_edges(graph)))
    dag = without_cycles(graph)
    back = {edge for edge in graph.edges if not dag.has_edge(*edge)}
    flow = dag.copy()
    flow.add_edges_from((target, source) for source, target in back)
    column: dict[str, int] = {}
    for vertex in nx.lexicographical_topological_sort(flow):
        column[vertex] = max((column[p] + 1 for p in flow.predecessors(vertex)), default=0)
    _shorten(flow, column)
    return graph, column, back


def _thread(graph: nx.DiGraph, column: Mapping[str, int], back: set[Edge],
            band_of: Sequence[int] | None = None) -> _Layering:
    """Put the vertices in their columns and thread every edge through slots
    in the columns it passes.  With bands, an edge takes slots only in its
    first and last band: between them it runs along the margin."""
    columns: list[list[Hashable]] = [[] for _ in range(max(column.values(), default=-1) + 1)]
    isolated = {v for v in graph if graph.degree(v) == 0}
    for vertex in sorted(graph, key=lambda v: (v in isolated, v)):
        columns[column[vertex]].append(vertex)
    chains: dict[Edge, list[Hashable]] = {}
    for edge in sorted(graph.edges):
        left, right = (edge[1], edge[0]) if edge in back else edge
        between = range(column[left] + 1, column[right])
        if band_of is not None:
            ends = (band_of[column[left]], band_of[column[right]])
            between = [c for c in between if band_of[c] in ends]
        owner = edge if edge in back else (left, '')
        dummies = [_Dummy(owner, c) for c in between]
        for dummy in dummies:
            if dummy not in columns[dummy.index]:
                columns[dummy.index].append(dummy)
        chains[edge] = [left, *dummies, right]
    return _Layering(columns, chains, back)


def _shorten(flow: nx.DiGraph, column: dict[str, int]) -> None:
    """Move vertices with more outputs than inputs right, up to their first
    reader: it shortens more edges than it stretches (a source then sits
    next to its reader, not far away in column 0)."""
    for _ in range(len(flow)):
        moved = False
        for vertex in sorted(flow, key=lambda v: (-column[v], v)):
            if flow.out_degree(vertex) > flow.in_degree(vertex):
                latest = min(column[s] for s in flow.successors(vertex)) - 1
                if latest > column[vertex]:
                    column[vertex], moved = latest, True
        if not moved:
            return


def _crossings(layering: _Layering) -> int:
    position = {item: i for column in layering.columns for i, item in enumerate(column)}
    column = layering.column_of()
    by_gap: dict[int, list[tuple[int, int]]] = {}
    for left, right, _ in layering.hops():
        by_gap.setdefault(column[left], []).append((position[left], position[right]))
    total = 0
    for hops in by_gap.values():
        for i, (a1, b1) in enumerate(hops):
            total += sum(1 for a2, b2 in hops[i + 1:] if (a1 - a2) * (b1 - b2) < 0)
    return total


def _order(layering: _Layering, sweeps: int = 12) -> None:
    """Reorder each column by the mean position of its neighbours (barycentre
    heuristic), sweeping right then left, and keep the order with fewest crossings."""
    before: dict[Hashable, list[Hashable]] = {}
    after: dict[Hashable, list[Hashable]] = {}
    for left, right, _ in layering.hops():
        after.setdefault(left, []).append(right)
        before.setdefault(right, []).append(left)

    columns = layering.columns
    for column in columns[1:]:
        column.sort(key=_key)
    position = {item: i for column in columns for i, item in enumerate(column)}

    def sort_column(column: list[Hashable], neighbours: dict) -> None:
        def barycentre(item: Hashable) -> tuple:
            near = neighbours.get(item, [])
            mean = sum(position[n] for n in near) / len(near) if near else position[item]
            return (mean, position[item])
        column.sort(key=barycentre)
        position.update({item: i for i, item in enumerate(column)})

    for column in columns[1:]:
        sort_column(column, before)
    best, fewest = [list(c) for c in columns], _crossings(layering)
    for sweep in range(sweeps):
        rightwards = sweep % 2 == 1
        indices = range(1, len(columns)) if rightwards else range(len(columns) - 2, -1, -1)
        for c in indices:
            sort_column(columns[c], before if rightwards else after)
        crossings = _crossings(layering)
        if crossings < fewest:
            best, fewest = [list(c) for c in columns], crossings
    layering.columns[:] = best


def _isotonic(targets: list[float], weights: list[float]) -> list[float]:
    """The non-decreasing sequence closest to `targets` (weighted least squares),
    by pooling adjacent violators."""
    blocks: list[list[float]] = []   # [value, weight, count]
    for target, weight in zip(targets, weights, strict=True):
        blocks.append([target, weight, 1])
        while len(blocks) > 1 and blocks[-2][0] > blocks[-1][0]:
            value, weight, count = blocks.pop()
            previous = blocks[-1]
            total = previous[1] + weight
            blocks[-1] = [(previous[0] * previous[1] + value * weight) / total, total,
                          previous[2] + count]
    return [value for value, _, count in blocks for _ in range(int(count))]


def _rows(layering: _Layering, heights: Mapping[Hashable, float], spacing: Spacing,
          links: list[Hop], sweeps: int = 16) -> dict[Hashable, float]:
    """Depth (downwards, inches) of each item's centre.

    Each column is pulled towards the depths of its neighbours on both sides
    along `links` while keeping its order and the gaps between shapes: an
    isotonic regression per column, sweeping right and left.  A link pulls
    with 1 / (the neighbour's links on that side)², so a private link wins
    over one to a hub and a chain stays straight while a fan bends.
    Passages of back edges pull weakly, so a feedback loop bends around the
    main flow instead of bending it; items with no links pack under the one
    above.
    """
    before: dict[Hashable, list[Hashable]] = {}
    after: dict[Hashable, list[Hashable]] = {}
    for left, right, _ in links:
        after.setdefault(left, []).append(right)
        before.setdefault(right, []).append(left)

    def gap(upper: Hashable, lower: Hashable) -> float:
        real = not isinstance(upper, _Dummy) and not isinstance(lower, _Dummy)
        return (heights[upper] + heights[lower]) / 2 + (
            spacing.row_gap if real else spacing.passage_gap)

    def weight(item: Hashable) -> float:
        if isinstance(item, _Dummy) and item.edge in layering.back:
            return 0.1
        return 1.0

    depth: dict[Hashable, float] = {}
    for column in layering.columns:
        offsets = [0.0]
        for upper, lower in pairwise(column):
            offsets.append(offsets[-1] + gap(upper, lower))
        for item, offset in zip(column, offsets, strict=True):
            depth[item] = offset - offsets[-1] / 2
    columns = layering.columns
    for sweep in range(sweeps):
        for column in columns if sweep % 2 == 0 else columns[::-1]:
            offsets = [0.0]
            for upper, lower in pairwise(column):
                offsets.append(offsets[-1] + gap(upper, lower))
            targets: list[float | None] = []
            weights = []
            for item, offset in zip(column, offsets, strict=True):
                pulls = [(depth[n], len(after[n]) ** -2) for n in before.get(item, [])]
                pulls += [(depth[n], len(before[n]) ** -2) for n in after.get(item, [])]
                if pulls:
                    total = sum(w for _, w in pulls)
                    targets.append(sum(d * w for d, w in pulls) / total - offset)
                    weights.append(weight(item) * total)
                else:  # linked to nothing: pack against the item above
                    targets.append(None)
                    weights.append(0.05)
            known = [t for t in targets if t is not None] or [0.0]
            previous = known[0]
            for i, target in enumerate(targets):
                if target is None:
                    targets[i] = previous
                else:
                    previous = target
            for item, value, offset in zip(column, _isotonic(targets, weights), offsets,
                                           strict=True):
                depth[item] = value + offset
    return depth


def _room(layering: _Layering, depth: Mapping[Hashable, float],
          heights: Mapping[Hashable, float], spacing: Spacing) -> dict[Hashable, float]:
    """Free height next to each item that arrows may use: half the gap to its
    neighbour in the column, on the tighter side."""
    room = {}
    for column in layering.columns:
        gaps = [(depth[lower] - heights[lower] / 2) - (depth[upper] + heights[upper] / 2)
                for upper, lower in pairwise(column)]
        gaps = [spacing.row_gap, *gaps, spacing.row_gap]
        for i, item in enumerate(column):
            room[item] = min(gaps[i], gaps[i + 1]) / 2
    return room


def _bands(widths: list[float], crossing: list[int], limit: float | None,
           spacing: Spacing) -> tuple[list[tuple[int, int]], float]:
    """Split columns into bands (first, last) that fit `limit` inches, as few
    as possible, cutting as few edges as possible, as even as possible; one
    band when there is no limit.  Also returns the estimated widest band."""
    count = len(widths)
    if limit is None or count <= 1:
        return [(0, count - 1)], 0.0

    def width(first: int, last: int) -> float:
        inner = sum(widths[first:last + 1]) + spacing.column_gap * (last - first)
        if first > 0:
            inner += _lanes(crossing[first - 1], spacing)
        if last < count - 1:
            inner += _lanes(crossing[last], spacing)
        return inner + 2 * spacing.margin

    # best[b][j]: for columns 0..j-1 in b bands, (edges cut, widest band), the
    # fewest cuts first: every edge running from one band to the next is a detour
    inf = (float('inf'), float('inf'))
    best = [[inf] * (count + 1) for _ in range(count + 1)]
    split = [[0] * (count + 1) for _ in range(count + 1)]
    best[0][0] = (0, 0.0)
    for b in range(1, count + 1):
        for j in range(1, count + 1):
            for i in range(b - 1, j):
                cuts, widest = best[b - 1][i]
                band = width(i, j - 1)
                if band > limit and j - i > 1:
                    continue  # too wide (a single column that is too wide must do)
                candidate = (cuts + (crossing[i - 1] if i > 0 else 0), max(widest, band))
                if candidate < best[b][j]:
                    best[b][j], split[b][j] = candidate, i
    chosen = next(b for b in range(1, count + 1) if best[b][count] < inf)
    bands, j = [], count
    for b in range(chosen, 0, -1):
        i = split[b][j]
        bands.append((i, j - 1))
        j = i
    return bands[::-1], best[chosen][count][1]


def place(graph: nx.DiGraph, sizes: Mapping[str, Size], spacing: Spacing = Spacing(),
          max_width: float | None = None, reach: Mapping[str, float] | None = None,
          ) -> Placement:
    """Lay `graph` out for shapes of the given (width, height) in inches.

    With `max_width`, columns wrap into as many bands as needed to keep the
    picture that narrow (unless a single column is wider).  `reach` limits how
    far above or below its centre arrows may end at a shape (a box wants them
    on its sides; by default they may spread into half the free space around).
    """
    graph, column, back = _columns(graph)
    if not graph:
        return Placement(2 * spacing.margin, 2 * spacing.margin, {}, {}, [])
    count = max(column.values()) + 1
    widths = [spacing.passage + 2 * spacing.lead] * count
    for vertex, c in column.items():
        widths[c] = max(widths[c], sizes[vertex][0] + 2 * spacing.lead)
    crossing = [0] * count
    unwrapped = _thread(graph, column, back)
    at = unwrapped.column_of()
    for left, _, _ in unwrapped.hops():
        crossing[at[left]] += 1
    limit = max_width
    for _ in range(count):
        bands, estimate = _bands(widths, crossing, limit, spacing)
        plan = _arrange(graph, column, back, bands, sizes, widths, spacing, reach or {})
        if max_width is None or plan.width <= max_width or len(bands) == count:
            break
        # the lanes along the margins are only known once arranged: ask for
        # bands narrower by the overflow, which rules this split out
        limit = estimate - (plan.width - max_width) - 0.01
    return plan


def _lanes(count: int, spacing: Spacing) -> float:
    """Width taken by `count` wrapped edges running side by side along a margin."""
    return spacing.lane_margin + count * spacing.lane_gap if count else 0.0


@dataclass
class _Frame:
    """Where columns and bands sit, and so every item's centre (inches, y up)."""

    column_of: dict[Hashable, int]
    band_of: list[int]
    left_edge: list[float]     # of each column
    widths: list[float]        # of each column
    band_top: list[float]      # y of each band's top
    band_depth: list[float]    # depth of each band's top
    depth: Mapping[Hashable, float]
    width: float               # of the bands, without lanes on the right
    height: float

    def centre(self, item: Hashable) -> Point:
        c = self.column_of[item]
        b = self.band_of[c]
        return (self.left_edge[c] + self.widths[c] / 2,
                self.band_top[b] - (self.depth[item] - self.band_depth[b]))

    def slope(self, item: Hashable, x: float, y: float) -> float:
        """Of the straight run between `item`'s centre and (x, y); 0 for a passage."""
        if isinstance(item, _Dummy):
            return 0.0
        cx, cy = self.centre(item)
        return max(-1.0, min(1.0, (y - cy) / (x - cx)))


def _frame(layering: _Layering, bands: list[tuple[int, int]], widths: list[float],
           depth: Mapping[Hashable, float], heights: Mapping[Hashable, float],
           entering: list[int], spacing: Spacing) -> _Frame:
    """Bands top to bottom, each starting at the left margin plus the lanes of
    the edges entering it, which also run in a corridor above it."""
    band_of = [b for b, (first, last) in enumerate(bands) for _ in range(first, last + 1)]
    left_edge: list[float] = []
    right = 0.0
    for b, (first, last) in enumerate(bands):
        x = spacing.margin + _lanes(entering[b], spacing)
        for c in range(first, last + 1):
            left_edge.append(x)
            x += widths[c] + spacing.column_gap
        right = max(right, x - spacing.column_gap)
    extent = []
    for first, last in bands:
        items = [item for c in range(first, last + 1) for item in layering.columns[c]]
        extent.append((min(depth[i] - heights[i] / 2 for i in items),
                       max(depth[i] + heights[i] / 2 for i in items)))
    corridor = [spacing.band_gap + n * spacing.lane_gap if b else 0.0
                for b, n in enumerate(entering)]
    height = 2 * spacing.margin + sum(bottom - top for top, bottom in extent) + sum(corridor)
    band_top, y = [], height - spacing.margin
    for b, (top, bottom) in enumerate(extent):
        y -= corridor[b]
        band_top.append(y)
        y -= bottom - top
    return _Frame(layering.column_of(), band_of, left_edge, widths, band_top,
                  [top for top, _ in extent], depth, right, height)


@dataclass
class _Lane:
    """The way of an edge wrapping to a later band: right along its row to `x`,
    down to the corridor at `y` above the band it enters, left to `left`, down
    to its row there."""

    x: float
    y: float
    left: float


def _wrap_lanes(wraps: list[Hop], frame: _Frame, port: Mapping, bands: list[tuple[int, int]],
                spacing: Spacing) -> dict[Hop, _Lane]:
    """A lane for every wrapping hop, such that no two run on top of each other.

    Down the right margin, hops get the innermost lane free over their whole
    run (shorter runs first, lower rows first, so they nest); in a corridor
    the outermost of them runs lowest and turns down innermost, so hops in
    the same order neither cross nor overlap.
    """
    right_base = frame.width + spacing.lane_margin
    lane_x: dict[Hop, float] = {}
    taken: list[list[tuple[float, float]]] = []
    runs = []
    for hop in wraps:
        left, right, _ = hop
        b = frame.band_of[frame.column_of[left]]
        to = frame.band_of[frame.column_of[right]]
        y_out = frame.centre(left)[1] + port[(left, 'out', hop)]
        runs.append(((to - b, b, y_out), hop, (frame.band_top[to], y_out + spacing.lane_gap)))
    for _, hop, (low, high) in sorted(runs, key=lambda run: run[0]):
        slot = next((i for i, spans in enumerate(taken)
                     if all(high < s_low or s_high < low for s_low, s_high in spans)), None)
        if slot is None:
            slot = len(taken)
            taken.append([])
        taken[slot].append((low, high))
        lane_x[hop] = right_base + slot * spacing.lane_gap
    lanes = {}
    for b, (first, _) in enumerate(bands):
        arriving = sorted((hop for hop in wraps
                           if frame.band_of[frame.column_of[hop[1]]] == b),
                          key=lambda hop: -lane_x[hop])
        for k, hop in enumerate(arriving):
            lanes[hop] = _Lane(lane_x[hop],
                               frame.band_top[b] + spacing.band_gap / 2 + k * spacing.lane_gap,
                               frame.left_edge[first] - spacing.lane_margin
                               - k * spacing.lane_gap)
    return lanes


def _route(edge: Edge, layering: _Layering, frame: _Frame, port: Mapping,
           lanes: Mapping[Hop, _Lane], spacing: Spacing) -> Path:
    """The arrow of `edge`, from centre to centre: straight beside a shape or
    through a passage, an S-curve across each column gap, around the margins
    from band to band."""
    chain = layering.chains[edge]
    pen = Pen(frame.centre(chain[0]))
    for hop in layering.chain_hops(edge):
        left, right, _ = hop
        cl, cr = frame.column_of[left], frame.column_of[right]
        y_out = frame.centre(left)[1] + port[(left, 'out', hop)]
        y_in = frame.centre(right)[1] + port[(right, 'in', hop)]
        exit_x, entry_x = frame.left_edge[cl] + frame.widths[cl], frame.left_edge[cr]
        pen.line((exit_x, y_out))
        if hop in lanes:
            lane = lanes[hop]
            pen.rounded([(lane.x, y_out), (lane.x, lane.y), (lane.left, lane.y),
                         (lane.left, y_in)], (entry_x, y_in), spacing.corner)
        else:
            pen.s_curve((entry_x, y_in), frame.slope(left, exit_x, y_out),
                        frame.slope(right, entry_x, y_in))
        if isinstance(right, _Dummy):
            pen.line((entry_x + frame.widths[cr], y_in))
    pen.line(frame.centre(chain[-1]))
    return pen.path(reverse=edge in layering.back)


def _arrange(graph: nx.DiGraph, column: Mapping[str, int], back: set[Edge],
             bands: list[tuple[int, int]], sizes: Mapping[str, Size], widths: list[float],
             spacing: Spacing, reach: Mapping[str, float]) -> Placement:
    """Positions and arrow paths for the given bands of columns."""
    band_of = [b for b, (first, last) in enumerate(bands) for _ in range(first, last + 1)]
    layering = _thread(graph, column, back, band_of if len(bands) > 1 else None)
    _order(layering)
    heights = {item: spacing.passage if isinstance(item, _Dummy) else sizes[item][1]
               for items in layering.columns for item in items}
    column_of = layering.column_of()
    hops = layering.hops()
    wraps = [hop for hop in hops if band_of[column_of[hop[0]]] != band_of[column_of[hop[1]]]]
    depth = _rows(layering, heights, spacing, [hop for hop in hops if hop not in wraps])
    entering = [0] * len(bands)
    for _, right, _ in wraps:
        entering[band_of[column_of[right]]] += 1
    frame = _frame(layering, bands, widths, depth, heights, entering, spacing)
    port = _ports(layering, hops, frame.centre, depth, heights, spacing, reach)
    lanes = _wrap_lanes(wraps, frame, port, bands, spacing)
    width = max([frame.width, *(lane.x for lane in lanes.values())]) + spacing.margin
    real_columns = [[v for v in items if not isinstance(v, _Dummy)]
                    for items in layering.columns]
    return Placement(
        width=width, height=frame.height,
        centres={v: frame.centre(v) for items in real_columns for v in items},
        routes={edge: _route(edge, layering, frame, port, lanes, spacing)
                for edge in layering.chains},
        columns=real_columns, bands=len(bands))


def _ports(layering: _Layering, hops: list[Hop], centre: Callable[[Hashable], Point],
           depth: Mapping[Hashable, float], heights: Mapping[Hashable, float],
           spacing: Spacing, reach: Mapping[str, float],
           ) -> dict[tuple[Hashable, str, Hop], float]:
    """Height offset where each hop leaves ('out') or enters ('in') an item.

    Arrows sharing a side of a shape end at different heights, in the order
    of where they come from, so they neither overlap nor cross there; a
    loop's way back takes the upper of two otherwise equal places.
    """
    sides: dict[tuple[Hashable, str], list[tuple[tuple, Hop]]] = {}
    for hop in hops:
        left, right, back = hop
        sides.setdefault((left, 'out'), []).append(((-centre(right)[1], not back), hop))
        sides.setdefault((right, 'in'), []).append(((-centre(left)[1], not back), hop))
    room = _room(layering, depth, heights, spacing)
    port = {}
    for (item, side), entries in sides.items():
        entries.sort(key=lambda entry: entry[0])
        step = 0.0
        if len(entries) > 1 and not isinstance(item, _Dummy):
            half = min(reach.get(item, float('inf')), (heights[item] + room[item]) / 2)
            step = min(spacing.port_gap, 2 * max(half, 0.0) / (len(entries) - 1))
        for i, (_, hop) in enumerate(entries):
            port[(item, side, hop)] = ((len(entries) - 1) / 2 - i) * step
    return port
