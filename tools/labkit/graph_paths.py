"""Arrow paths for the graph drawing.

:class:`Pen` builds them from straight runs, S-curves and rounded corners,
reversibly (a back edge is laid out along the data flow and drawn the other
way); :class:`FollowPath` makes a matplotlib arrow follow one and end at the
outlines of the shapes it joins.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

from matplotlib.bezier import inside_circle, split_path_inout
from matplotlib.patches import Patch
from matplotlib.path import Path
from matplotlib.transforms import Transform

Point = tuple[float, float]


class Pen:
    """Builds a path from lines and Bézier curves, starting at `start`."""

    def __init__(self, start: Point):
        self.start = start
        self.segments: list[tuple[list[Point], Point]] = []  # (control points, end)

    @property
    def here(self) -> Point:
        return self.segments[-1][1] if self.segments else self.start

    def line(self, end: Point) -> None:
        self.segments.append(([], end))

    def s_curve(self, end: Point, leave: float = 0.0, arrive: float = 0.0) -> None:
        """A smooth S across a column gap, leaving and arriving with the given
        slopes (dy/dx), so it continues the straight runs on either side."""
        (x0, y0), (x1, y1) = self.here, end
        half = (x1 - x0) / 2
        self.segments.append(([(x0 + half, y0 + leave * half), (x1 - half, y1 - arrive * half)],
                              end))

    def rounded(self, corners: list[Point], end: Point, radius: float) -> None:
        """Straight runs through `corners` to `end`, rounding each corner."""
        points = [self.here, *corners, end]
        for previous, corner, following in zip(points, points[1:], points[2:], strict=False):
            r = min(radius, distance(previous, corner) / 2, distance(corner, following) / 2)
            self.line(towards(corner, previous, r))
            self.segments.append(([corner], towards(corner, following, r)))
        self.line(end)

    def path(self, reverse: bool = False) -> Path:
        """The path drawn so far (end to start if `reverse`)."""
        segments = self.segments
        start = self.start
        if reverse and segments:
            starts = [start] + [end for _, end in segments[:-1]]
            start = segments[-1][1]
            segments = [(controls[::-1], begin) for (controls, _), begin
                        in zip(segments[::-1], starts[::-1], strict=True)]
        vertices, codes = [start], [Path.MOVETO]
        kinds = {0: Path.LINETO, 1: Path.CURVE3, 2: Path.CURVE4}
        for controls, end in segments:
            vertices += [*controls, end]
            codes += [kinds[len(controls)]] * (len(controls) + 1)
        return Path(vertices, codes)


def distance(a: Point, b: Point) -> float:
    return ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5


def towards(start: Point, goal: Point, length: float) -> Point:
    """The point `length` from `start` on the way to `goal`."""
    gap = distance(start, goal)
    if gap == 0:
        return start
    return (start[0] + (goal[0] - start[0]) * length / gap,
            start[1] + (goal[1] - start[1]) * length / gap)


class FollowPath:
    """Connection style for FancyArrowPatch: follow a path laid out beforehand.

    Like matplotlib's own styles it then cuts the path where it leaves the
    start shape (`patchA`) and enters the end shape (`patchB`), and shrinks it
    by `shrinkA`/`shrinkB`, so arrows touch the shapes' outlines.
    """

    def __init__(self, path: Path, transform: Transform):
        self.path, self.transform = path, transform

    def __call__(self, posA: Any, posB: Any, shrinkA: float = 2.0, shrinkB: float = 2.0,
                 patchA: Patch | None = None, patchB: Patch | None = None) -> Path:
        path = self.transform.transform_path(self.path)
        if patchA is not None:
            path = _cut(path, patchA.contains_point, keep='after')
        if patchB is not None:
            path = _cut(path, patchB.contains_point, keep='before')
        if shrinkA:
            path = _cut(path, inside_circle(*path.vertices[0], shrinkA), keep='after')
        if shrinkB:
            path = _cut(path, inside_circle(*path.vertices[-1], shrinkB), keep='before')
        return path


def _cut(path: Path, inside: Callable[[Any], bool], keep: str) -> Path:
    try:
        before, after = split_path_inout(path, inside)
    except ValueError:  # never crosses the outline: leave it whole
        return path
    return after if keep == 'after' else before
