"""The picture turtlesim's window would show, drawn with Pillow.

Pen trails go on a persistent layer (cleared by /clear and /reset); the
turtles are drawn on top only when a picture is taken, so they leave no
marks of their own.
"""
from __future__ import annotations

import math
import os
import tempfile
from pathlib import Path

from PIL import Image, ImageDraw

from .world import PIXELS, PIXELS_PER_METER, Turtle

TURTLE_LENGTH = 24  # pixels, about turtlesim's turtle icon
SHELL = (46, 139, 87)
SKIN = (144, 238, 144)


def to_pixel(x: float, y: float) -> tuple[float, float]:
    """World metres to image pixels (y grows upwards in the world, downwards in images)."""
    return x * PIXELS_PER_METER, (PIXELS - 1) - y * PIXELS_PER_METER


def to_grid(x: float, y: float) -> tuple[int, int]:
    """The image pixel a world position falls on (pen strokes end on it, the sensor reads it)."""
    px, py = to_pixel(x, y)
    return (min(max(round(px), 0), PIXELS - 1), min(max(round(py), 0), PIXELS - 1))


class Canvas:
    """Background and pen trails; a PNG of them with the turtles on top."""

    def __init__(self, background: tuple[int, int, int]) -> None:
        self.background = background
        self.trails = Image.new('RGB', (PIXELS, PIXELS), background)
        self._draw = ImageDraw.Draw(self.trails)

    def clear(self, background: tuple[int, int, int] | None = None) -> None:
        """Erase every trail; optionally with a new background colour."""
        if background is not None:
            self.background = background
        self._draw.rectangle((0, 0, PIXELS, PIXELS), fill=self.background)

    def line(self, start: tuple[float, float], end: tuple[float, float],
             rgb: tuple[int, int, int], width: int) -> None:
        """A pen stroke between two world positions."""
        self._draw.line((to_grid(*start), to_grid(*end)), fill=rgb, width=max(width, 1))

    def color_at(self, x: float, y: float) -> tuple[int, int, int]:
        """The colour under a turtle (its color_sensor reading)."""
        return self.trails.getpixel(to_grid(x, y))

    def picture(self, turtles: list[Turtle]) -> Image.Image:
        """The window's content now: trails with every turtle drawn on top."""
        image = self.trails.copy()
        draw = ImageDraw.Draw(image)
        for turtle in turtles:
            _draw_turtle(draw, turtle)
        return image

    def save_png(self, turtles: list[Turtle], path: Path) -> None:
        """Write the picture to ``path`` atomically (a reader never sees half a file)."""
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=f'.{path.name}.', dir=path.parent)
        try:
            with os.fdopen(handle, 'wb') as out:
                self.picture(turtles).save(out, format='PNG')
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise


def _draw_turtle(draw: ImageDraw.ImageDraw, turtle: Turtle) -> None:
    """A shell with a head that points along the turtle's heading."""
    cx, cy = to_pixel(turtle.x, turtle.y)
    # Image y points down, so the heading's y component flips.
    hx, hy = math.cos(turtle.theta), -math.sin(turtle.theta)
    half = TURTLE_LENGTH / 2
    for side in (-1, 1):  # four legs
        for along in (-0.45, 0.45):
            lx = cx + hx * along * half - hy * side * half * 0.75
            ly = cy + hy * along * half + hx * side * half * 0.75
            draw.ellipse((lx - 3, ly - 3, lx + 3, ly + 3), fill=SKIN)
    head_x, head_y = cx + hx * half * 0.95, cy + hy * half * 0.95
    draw.ellipse((head_x - 4, head_y - 4, head_x + 4, head_y + 4), fill=SKIN)
    r = half * 0.7
    draw.ellipse((cx - r, cy - r, cx + r, cy + r), fill=SHELL, outline=(0, 80, 0))
