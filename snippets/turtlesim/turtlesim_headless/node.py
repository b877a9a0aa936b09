"""The ``turtlesim`` node: turtlesim's topics, services, parameters and action, headless.

Every 16 ms it moves each turtle by its velocity command, keeps it inside
the square, draws its pen trail, and publishes its pose and the colour under
it.  Instead of a window it keeps a PNG up to date (see ``canvas_file``).
"""
from __future__ import annotations

import math
import os
import time

import rclpy
from geometry_msgs.msg import Twist
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.task import Future
from std_srvs.srv import Empty
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from .canvas import Canvas
from .canvas_file import canvas_path
from .world import CENTRE, UPDATE_PERIOD, Turtle, World, normalize_angle

BACKGROUND = {'background_r': 69, 'background_g': 86, 'background_b': 255}
# What the C++ turtlesim lists for its /parameter_events publisher (read-only; shown
# by `ros2 param list`).
PARAMETER_EVENTS_QOS = {'depth': 1000, 'durability': 'volatile', 'history': 'keep_last',
                        'reliability': 'reliable'}
PICTURE_MIN_PERIOD = 0.2  # s between two PNGs while turtles move
PICTURE_MAX_PERIOD = 1.0  # s: the PNG is rewritten at least this often
ROTATION_SPEED = 1.0  # rad/s of rotate_absolute
ROTATION_TOLERANCE = 0.02  # rad


class TurtleInterfaces:
    """The ROS side of one turtle: ``<name>/cmd_vel``, ``pose``, ``color_sensor``, ..."""

    def __init__(self, sim: Turtlesim, turtle: Turtle) -> None:
        name = turtle.name
        self.turtle = turtle
        self.rotation: tuple | None = None  # (goal handle, target, start, done future)
        self._sim = sim
        self.cmd_vel = sim.create_subscription(Twist, f'{name}/cmd_vel', self._on_cmd_vel, 1)
        self.pose = sim.create_publisher(Pose, f'{name}/pose', 1)
        self.color = sim.create_publisher(Color, f'{name}/color_sensor', 1)
        self.services = [
            sim.create_service(SetPen, f'{name}/set_pen', self._on_set_pen),
            sim.create_service(TeleportAbsolute, f'{name}/teleport_absolute',
                               self._on_teleport_absolute),
            sim.create_service(TeleportRelative, f'{name}/teleport_relative',
                               self._on_teleport_relative),
        ]
        self.rotate = ActionServer(
            sim, RotateAbsolute, f'{name}/rotate_absolute', self._rotate,
            goal_callback=lambda goal: GoalResponse.ACCEPT,
            cancel_callback=lambda goal_handle: CancelResponse.ACCEPT)

    def destroy(self) -> None:
        self._finish_rotation(aborted=True)
        self.rotate.destroy()
        for service in self.services:
            self._sim.destroy_service(service)
        self._sim.destroy_subscription(self.cmd_vel)
        self._sim.destroy_publisher(self.pose)
        self._sim.destroy_publisher(self.color)

    def _on_cmd_vel(self, msg: Twist) -> None:
        self.turtle.command(msg.linear.x, msg.linear.y, msg.angular.z, time.monotonic())

    def _on_set_pen(self, request, response):
        pen = self.turtle.pen
        pen.r, pen.g, pen.b = request.r, request.g, request.b
        pen.width, pen.off = request.width, bool(request.off)
        return response

    def _on_teleport_absolute(self, request, response):
        self._sim.move_by_teleport(self.turtle, lambda t: t.teleport_absolute(
            request.x, request.y, request.theta))
        return response

    def _on_teleport_relative(self, request, response):
        self._sim.move_by_teleport(self.turtle, lambda t: t.teleport_relative(
            request.linear, request.angular))
        return response

    async def _rotate(self, goal_handle):
        """Turn on the spot to ``theta``, reporting the rotation still to go."""
        self._finish_rotation(aborted=True)  # a new goal replaces the old one
        done = Future()
        self.rotation = (goal_handle, normalize_angle(goal_handle.request.theta),
                         self.turtle.theta, done)
        await done
        return done.result()

    def step_rotation(self, dt: float) -> float | None:
        """Advance rotate_absolute by one update of ``dt`` seconds; the angular velocity
        it commands (never past the target)."""
        if self.rotation is None:
            return None
        goal_handle, target, _, _ = self.rotation
        remaining = normalize_angle(target - self.turtle.theta)
        if goal_handle.is_cancel_requested:
            self._finish_rotation(canceled=True)
            return None
        if abs(remaining) < ROTATION_TOLERANCE:
            self._finish_rotation()
            return None
        feedback = RotateAbsolute.Feedback()
        feedback.remaining = remaining
        goal_handle.publish_feedback(feedback)
        return math.copysign(min(ROTATION_SPEED, abs(remaining) / max(dt, 1e-3)), remaining)

    def _finish_rotation(self, canceled: bool = False, aborted: bool = False) -> None:
        if self.rotation is None:
            return
        goal_handle, _, start, done = self.rotation
        self.rotation = None
        self.turtle.command(0.0, 0.0, 0.0, time.monotonic())  # stop turning now
        result = RotateAbsolute.Result()
        result.delta = normalize_angle(self.turtle.theta - start)
        if goal_handle.is_active:
            if canceled:
                goal_handle.canceled()
            elif aborted:
                goal_handle.abort()
            else:
                goal_handle.succeed()
        done.set_result(result)


class Turtlesim(Node):
    """The simulator: the world, its canvas and every turtle's interfaces."""

    def __init__(self) -> None:
        super().__init__('turtlesim')
        for name, default in BACKGROUND.items():
            self.declare_parameter(name, default, ParameterDescriptor(
                description=f"{name.split('_')[1].upper()} channel of the background color",
                integer_range=[IntegerRange(from_value=0, to_value=255, step=1)]))
        self.declare_parameter('holonomic', False, ParameterDescriptor(
            description='If true, then turtles will be holonomic'))
        for policy, value in PARAMETER_EVENTS_QOS.items():
            self.declare_parameter(f'qos_overrides./parameter_events.publisher.{policy}', value,
                                   ParameterDescriptor(read_only=True))
        self.world = World()
        self.canvas = Canvas(self._background())
        self.interfaces: dict[str, TurtleInterfaces] = {}
        self.picture_path = canvas_path(self.get_fully_qualified_name())
        self._picture_dirty = True
        self._picture_time = -math.inf
        self._last_update = time.monotonic()
        self.create_service(Spawn, 'spawn', self._on_spawn)
        self.create_service(Kill, 'kill', self._on_kill)
        self.create_service(Empty, 'clear', self._on_clear)
        self.create_service(Empty, 'reset', self._on_reset)
        self.get_logger().info(
            f'Starting turtlesim with node name {self.get_fully_qualified_name()}')
        self._spawn(CENTRE, CENTRE, 0.0, '')
        self.create_timer(UPDATE_PERIOD, self._update)

    def _background(self) -> tuple[int, int, int]:
        return tuple(self.get_parameter(name).value for name in BACKGROUND)

    def _spawn(self, x: float, y: float, theta: float, name: str) -> Turtle:
        turtle = self.world.spawn(x, y, theta, name)
        self.interfaces[turtle.name] = TurtleInterfaces(self, turtle)
        self.get_logger().info(
            f'Spawning turtle [{turtle.name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]')
        self._picture_dirty = True
        return turtle

    def _on_spawn(self, request, response):
        try:
            response.name = self._spawn(request.x, request.y, request.theta, request.name).name
        except KeyError:
            self.get_logger().error(
                f'Tried to spawn turtle [{request.name}], which already exists')
        return response

    def _on_kill(self, request, response):
        if request.name not in self.interfaces:
            self.get_logger().error(
                f'Tried to kill turtle [{request.name}], which does not exist')
            return response
        self.interfaces.pop(request.name).destroy()
        self.world.kill(request.name)
        self._picture_dirty = True
        return response

    def _on_clear(self, request, response):
        self.get_logger().info('Clearing turtlesim.')
        self.canvas.clear(self._background())
        self._picture_dirty = True
        return response

    def _on_reset(self, request, response):
        self.get_logger().info('Resetting turtlesim.')
        for interfaces in self.interfaces.values():
            interfaces.destroy()
        self.interfaces.clear()
        self.canvas.clear(self._background())
        self.world = World()
        self._spawn(CENTRE, CENTRE, 0.0, '')
        return response

    def move_by_teleport(self, turtle: Turtle, teleport) -> None:
        """Teleport ``turtle``; its pen draws the jump, the walls still hold."""
        start = (turtle.x, turtle.y)
        teleport(turtle)
        self._after_move(turtle, start)

    def _after_move(self, turtle: Turtle, start: tuple[float, float]) -> None:
        hit = turtle.clamp()
        if hit is not None:
            self.get_logger().warning(
                f'Oh no! I hit the wall! (Clamping from [x={hit[0]:f}, y={hit[1]:f}])')
        if (turtle.x, turtle.y) != start:
            if not turtle.pen.off:
                self.canvas.line(start, (turtle.x, turtle.y), turtle.pen.rgb, turtle.pen.width)
            self._picture_dirty = True

    def _update(self) -> None:
        now = time.monotonic()
        previous, self._last_update = self._last_update, now
        if self._background() != self.canvas.background:
            self.canvas.clear(self._background())
            self._picture_dirty = True
        holonomic = self.get_parameter('holonomic').value
        for interfaces in list(self.interfaces.values()):
            turtle = interfaces.turtle
            rotation = interfaces.step_rotation(now - previous)
            if rotation is not None:  # it turns the turtle over the interval that just ended
                turtle.command(0.0, 0.0, rotation, previous)
            start, heading = (turtle.x, turtle.y), turtle.theta
            turtle.step(previous, now, holonomic)
            self._after_move(turtle, start)
            self._picture_dirty |= turtle.theta != heading
            self._publish(interfaces, now)
        self._write_picture(now)

    def _publish(self, interfaces: TurtleInterfaces, now: float) -> None:
        turtle = interfaces.turtle
        linear, _, angular = turtle.velocities(now)
        interfaces.pose.publish(Pose(x=turtle.x, y=turtle.y, theta=turtle.theta,
                                     linear_velocity=linear, angular_velocity=angular))
        r, g, b = self.canvas.color_at(turtle.x, turtle.y)
        interfaces.color.publish(Color(r=r, g=g, b=b))

    def _write_picture(self, now: float) -> None:
        """Keep the PNG current; an unchanged one is only touched (readers wait for a date)."""
        since = now - self._picture_time
        if self._picture_dirty and since >= PICTURE_MIN_PERIOD:
            self.canvas.save_png(list(self.world.turtles.values()), self.picture_path)
        elif since >= PICTURE_MAX_PERIOD:
            try:
                os.utime(self.picture_path)
            except FileNotFoundError:
                self.canvas.save_png(list(self.world.turtles.values()), self.picture_path)
        else:
            return
        self._picture_time = now
        self._picture_dirty = False


def main(args=None) -> int:
    rclpy.init(args=args)
    node = None
    try:
        node = Turtlesim()  # Ctrl+C while it starts (it is on the graph already) is fine too
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    except Exception:
        if rclpy.ok():
            raise  # a real error
        # Ctrl+C came while a timer callback was publishing: rclpy had already shut
        # its context down, so the publish failed (RCLError). Jazzy's turtlesim stops
        # cleanly on Ctrl+C, at any moment; so does this one.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0
