"""Patrol planner: which point the robot should drive to now.

It walks a list of waypoints (parameter ``waypoints``: x1, y1, x2, y2, ...,
a flat list because a parameter cannot be a list of pairs) and moves on to
the next once the estimated pose is within ``tolerance`` of the current one,
round and round.  The service ``set_mode`` switches between ``patrol`` and
``hold`` (stay where you are); ``status`` reports the patrol twice a second.
"""
import math

from capstone_interfaces.msg import RobotStatus
from capstone_interfaces.srv import SetMode
from geometry_msgs.msg import Point
from rclpy.node import Node
from turtlesim.msg import Pose

from .running import ConfigurationError, run

MODES = (RobotStatus.MODE_PATROL, RobotStatus.MODE_HOLD)


class PatrolPlanner(Node):

    def __init__(self):
        super().__init__('patrol_planner')
        flat = self.declare_parameter('waypoints', [2.0, 2.0, 9.0, 2.0, 9.0, 9.0, 2.0, 9.0]).value
        self.tolerance = self.declare_parameter('tolerance', 0.3).value
        self.mode = self.declare_parameter('mode', RobotStatus.MODE_PATROL).value
        status_rate = self.declare_parameter('status_rate', 2.0).value
        if len(flat) < 2 or len(flat) % 2:
            raise ConfigurationError(
                f'waypoints must be pairs x1, y1, x2, y2, ...; got {len(flat)} numbers')
        if self.mode not in MODES:
            raise ConfigurationError(f'mode must be one of {MODES}, got {self.mode!r}')
        self.waypoints = list(zip(flat[0::2], flat[1::2], strict=True))
        self.index = 0
        self.reached = 0
        self.pose = None
        self.hold_at = None  # where the robot stays in hold mode
        self.robot = self.get_namespace().strip('/')
        self.create_subscription(Pose, 'estimated_pose', self.on_pose, 10)
        self.goal_publisher = self.create_publisher(Point, 'goal', 10)
        self.status_publisher = self.create_publisher(RobotStatus, 'status', 10)
        self.create_service(SetMode, 'set_mode', self.on_set_mode)
        self.create_timer(1.0 / status_rate, self.publish_status)
        self.get_logger().info(f'Patrolling {len(self.waypoints)} waypoints, mode {self.mode}')

    def goal(self) -> tuple[float, float]:
        if self.mode == RobotStatus.MODE_HOLD and self.hold_at is not None:
            return self.hold_at
        return self.waypoints[self.index]

    def distance_to_goal(self) -> float:
        x, y = self.goal()
        return math.dist((x, y), (self.pose.x, self.pose.y))

    def on_pose(self, pose: Pose):
        self.pose = pose
        if self.mode == RobotStatus.MODE_HOLD and self.hold_at is None:
            self.hold_at = (pose.x, pose.y)
        if self.mode == RobotStatus.MODE_PATROL and self.distance_to_goal() < self.tolerance:
            self.reached += 1
            self.index = (self.index + 1) % len(self.waypoints)
            x, y = self.waypoints[self.index]
            self.get_logger().info(f'Waypoint reached ({self.reached} so far); next: '
                                   f'#{self.index} at ({x:.2f}, {y:.2f})')
        x, y = self.goal()
        self.goal_publisher.publish(Point(x=float(x), y=float(y)))

    def on_set_mode(self, request: SetMode.Request, response: SetMode.Response):
        if request.mode not in MODES:
            response.accepted = False
            response.message = f'unknown mode {request.mode!r}; use one of {", ".join(MODES)}'
            return response
        self.mode = request.mode
        self.hold_at = (self.pose.x, self.pose.y) if self.pose is not None else None
        response.accepted = True
        response.message = f'mode is now {self.mode}'
        self.get_logger().info(f'Mode: {self.mode}')
        return response

    def publish_status(self):
        if self.pose is None:
            return
        x, y = self.goal()
        self.status_publisher.publish(RobotStatus(
            robot=self.robot, mode=self.mode, waypoint_index=self.index,
            waypoint_count=len(self.waypoints), waypoints_reached=self.reached,
            goal_x=float(x), goal_y=float(y), distance_to_goal=self.distance_to_goal()))


def main(args=None):
    return run(PatrolPlanner, args)


if __name__ == '__main__':
    main()
