"""The turtles and their motion, without ROS: what turtlesim computes each update.

The window is 500 x 500 pixels at 45 pixels per metre, so the world is a
square of (500 - 1) / 45 = 11.0888... metres; the first turtle starts at its
centre.  A velocity command holds for one second, then the turtle stops.
A turtle that would leave the square is put back on its edge.
"""
from __future__ import annotations

import math
import struct
from dataclasses import dataclass, field

PIXELS = 500
PIXELS_PER_METER = 45.0


def float32(value: float) -> float:
    """``value`` rounded to single precision, as turtlesim's ``float`` arithmetic."""
    return struct.unpack('f', struct.pack('f', value))[0]


WORLD_SIZE = float32((PIXELS - 1) / PIXELS_PER_METER)  # 11.088889 m
CENTRE = float32(WORLD_SIZE / 2)  # 5.544445 m
UPDATE_PERIOD = 0.016  # seconds, as turtlesim
COMMAND_TIMEOUT = 1.0  # seconds a cmd_vel holds
DEFAULT_PEN = (179, 184, 255, 3, False)  # r, g, b, width, off


def normalize_angle(theta: float) -> float:
    """The same heading in [-pi, pi)."""
    return theta - 2 * math.pi * math.floor((theta + math.pi) / (2 * math.pi))


@dataclass
class Pen:
    r: int = DEFAULT_PEN[0]
    g: int = DEFAULT_PEN[1]
    b: int = DEFAULT_PEN[2]
    width: int = DEFAULT_PEN[3]
    off: bool = DEFAULT_PEN[4]

    @property
    def rgb(self) -> tuple[int, int, int]:
        return (self.r, self.g, self.b)


@dataclass
class Turtle:
    """One turtle: its pose, the last command and when it came, its pen."""

    name: str
    x: float
    y: float
    theta: float
    linear_x: float = 0.0
    linear_y: float = 0.0
    angular: float = 0.0
    command_time: float = -math.inf
    pen: Pen = field(default_factory=Pen)

    def command(self, linear_x: float, linear_y: float, angular: float, now: float) -> None:
        """A cmd_vel arrived at ``now`` (seconds)."""
        self.linear_x, self.linear_y, self.angular = linear_x, linear_y, angular
        self.command_time = now

    def velocities(self, now: float) -> tuple[float, float, float]:
        """The command in force at ``now``: zero once it is a second old."""
        if now - self.command_time > COMMAND_TIMEOUT:
            return 0.0, 0.0, 0.0
        return self.linear_x, self.linear_y, self.angular

    def step(self, previous: float, now: float, holonomic: bool = False) -> None:
        """Move as the command in force between two updates (``clamp`` then keeps it inside).

        Only the part of ``previous``..``now`` the command covers counts, so a
        command moves the turtle for exactly one second of wall time however
        late an update comes.
        """
        linear_x, linear_y, angular = self.linear_x, self.linear_y, self.angular
        dt = min(now, self.command_time + COMMAND_TIMEOUT) - max(previous, self.command_time)
        if dt <= 0.0:
            return
        if not holonomic:
            linear_y = 0.0
        self.theta = normalize_angle(self.theta + angular * dt)
        cos, sin = math.cos(self.theta), math.sin(self.theta)
        self.x += (cos * linear_x - sin * linear_y) * dt
        self.y += (sin * linear_x + cos * linear_y) * dt

    def clamp(self) -> tuple[float, float] | None:
        """Put the turtle back inside the square; the old position if it was outside."""
        if 0.0 <= self.x <= WORLD_SIZE and 0.0 <= self.y <= WORLD_SIZE:
            return None
        before = (self.x, self.y)
        self.x = min(max(self.x, 0.0), WORLD_SIZE)
        self.y = min(max(self.y, 0.0), WORLD_SIZE)
        return before

    def teleport_absolute(self, x: float, y: float, theta: float) -> None:
        self.x, self.y, self.theta = x, y, normalize_angle(theta)

    def teleport_relative(self, linear: float, angular: float) -> None:
        """Turn by ``angular`` first, then move ``linear`` along the new heading."""
        self.theta = normalize_angle(self.theta + angular)
        self.x += math.cos(self.theta) * linear
        self.y += math.sin(self.theta) * linear


class World:
    """All turtles by name, and the numbering of turtles spawned without a name."""

    def __init__(self) -> None:
        self.turtles: dict[str, Turtle] = {}
        self._next_id = 1

    def spawn(self, x: float, y: float, theta: float, name: str = '') -> Turtle:
        """Add a turtle; an empty name becomes ``turtleN``, N counting up (never reused).

        Raises KeyError if a turtle of that name exists.
        """
        if not name:
            name = f'turtle{self._next_id}'
            while name in self.turtles:
                self._next_id += 1
                name = f'turtle{self._next_id}'
            self._next_id += 1
        if name in self.turtles:
            raise KeyError(name)
        turtle = Turtle(name, x, y, normalize_angle(theta))
        self.turtles[name] = turtle
        return turtle

    def kill(self, name: str) -> Turtle:
        """Remove a turtle; KeyError if there is none of that name."""
        return self.turtles.pop(name)

    def reset(self) -> Turtle:
        """Only a fresh ``turtle1`` at the centre remains."""
        self.turtles.clear()
        self._next_id = 1
        return self.spawn(CENTRE, CENTRE, 0.0)
