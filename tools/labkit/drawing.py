"""Draw the ROS graph the way rqt_graph does (:func:`draw_graph`).

The picture is made by :mod:`labkit.graph_drawing` from a snapshot;
this module adds taking the snapshot when none is given, which needs
:mod:`labkit.graph` (that in turn draws through :mod:`labkit.graph_drawing`,
so neither imports the other in a cycle).
"""
from __future__ import annotations

from typing import Any

from labkit.graph import graph as take_snapshot
from labkit.graph_drawing import (
    DISPLAY_PX_PER_INCH,
    FONT_SIZES,
    MAX_WIDTH,
    PNG_DPI,
    GraphFigure,
    default_caption,
    describe,
    layers,
    layout,
    layout_plan,
    render,
    to_networkx,
)

__all__ = ['DISPLAY_PX_PER_INCH', 'FONT_SIZES', 'MAX_WIDTH', 'PNG_DPI', 'GraphFigure',
           'default_caption', 'describe', 'draw_graph', 'layers', 'layout', 'layout_plan',
           'to_networkx']


def draw_graph(snapshot: Any = None, *, show_types: bool = False, title: str | None = None,
               caption: str | None = None) -> GraphFigure:
    """Draw the ROS graph and return the matplotlib Figure (shown inline by Jupyter).

    With no snapshot, takes one now (`labkit.graph()`).  `show_types=True`
    writes each topic's message type under its name.  `caption` is the line
    under the picture on the page (default: what the graph holds, and how to
    read it); the alt text lists every node and connection.
    """
    if snapshot is None:
        snapshot = take_snapshot()
    return render(snapshot, show_types=show_types, title=title, caption=caption)
