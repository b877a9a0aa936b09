"""The turtle's world without ROS: a square with four walls, and headings.

turtlesim's window is 500 pixels at 45 pixels per metre, so its world is
(500 - 1) / 45 = 11.088889 m on each side, from (0, 0) at the bottom left.
"""
from __future__ import annotations

import math

WORLD_SIZE = 11.088889  # metres


def normalize_angle(theta: float) -> float:
    """The same heading in [-pi, pi), so that differences of headings stay small."""
    return theta - 2 * math.pi * math.floor((theta + math.pi) / (2 * math.pi))


def wall_distances(x: float, y: float, size: float = WORLD_SIZE) -> dict[str, float]:
    """Distance from (x, y) to each wall, by the wall's name."""
    return {'left': x, 'right': size - x, 'bottom': y, 'top': size - y}


def distance_ahead(x: float, y: float, theta: float, size: float = WORLD_SIZE) -> float:
    """How far the turtle can drive along its heading before it meets a wall."""
    cos, sin = math.cos(theta), math.sin(theta)
    limits = []
    if cos > 1e-9:
        limits.append((size - x) / cos)
    elif cos < -1e-9:
        limits.append(-x / cos)
    if sin > 1e-9:
        limits.append((size - y) / sin)
    elif sin < -1e-9:
        limits.append(-y / sin)
    return max(0.0, min(limits))
