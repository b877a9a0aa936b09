"""Arrow paths for the graph drawing.

:func:`rounded` and :func:`joined` build the way of an edge that wraps from
one band of a picture to another; :class:`FollowPath` makes a matplotlib
arrow follow a path and end at the outlines of the shapes it joins.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import Any

from matplotlib.bezier import inside_circle, split_path_inout
from matplotlib.patches import Patch
from matplotlib.path import Path
from matplotlib.transforms import Transform

Point = tuple[float, float]


def rounded(points: list[Point], radius: float) -> Path:
    """Straight runs through `points`, each corner rounded with `radius` (at
    most half of the shorter run beside it)."""
    vertices, codes = [points[0]], [Path.MOVETO]
    for previous, corner, following in zip(points, points[1:], points[2:], strict=False):
        r = min(radius, _distance(previous, corner) / 2, _distance(corner, following) / 2)
        vertices += [_towards(corner, previous, r), corner, _towards(corner, following, r)]
        codes += [Path.LINETO, Path.CURVE3, Path.CURVE3]
    vertices.append(points[-1])
    codes.append(Path.LINETO)
    return Path(vertices, codes)


def joined(paths: list[Path]) -> Path:
    """One continuous path through `paths` in turn (each starting where the
    one before ends), as an arrow needs."""
    vertices = [vertex for path in paths for vertex in path.vertices]
    codes = [code for path in paths for code in path.codes]
    codes = [Path.MOVETO] + [Path.LINETO if code == Path.MOVETO else code for code in codes[1:]]
    return Path(vertices, codes)


def _distance(a: Point, b: Point) -> float:
    return ((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5


def _towards(start: Point, goal: Point, length: float) -> Point:
    """The point `length` from `start` on the way to `goal`."""
    gap = _distance(start, goal)
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
