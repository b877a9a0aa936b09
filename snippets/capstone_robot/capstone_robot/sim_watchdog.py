"""Simulator watchdog: ends, with exit code 1, when turtlesim is gone.

With ``sim:=false`` the simulator is not a process of the launch, so no
``OnProcessExit`` can see it end.  This node can: it looks for the node
``world_node`` (default ``/turtlesim``; on a real robot, the driver the
robots cannot do without) in the ROS graph every ``check_period`` seconds,
and exits when it has left the graph, or when it has not come within
``startup_timeout`` seconds.  The launch watches this node's exit instead
(R7: without the simulator the system shuts down).  It asks the graph
through its own node, as every node can, rather than by running
``ros2 node list``, which on a real install starts the ros2 daemon.
"""
import time

from rclpy.node import Node

from .running import Finished, run

class SimWatchdog(Node):

    def __init__(self):
        super().__init__('sim_watchdog')
        self.world = self.declare_parameter('world_node', '/turtlesim').value
        self.startup_timeout = self.declare_parameter('startup_timeout', 10.0).value
        check_period = self.declare_parameter('check_period', 0.5).value
        self.seen = False
        self.started = time.monotonic()
        self.create_timer(check_period, self.check)
        self.get_logger().info(f'Looking for {self.world} (up to {self.startup_timeout:.1f} s)')

    def simulator_running(self) -> bool:
        return self.world in {f"{namespace.rstrip('/')}/{name}"
                             for name, namespace in self.get_node_names_and_namespaces()}

    def check(self):
        if self.simulator_running():
            if not self.seen:
                self.seen = True
                self.get_logger().info(f'Found {self.world}: watching it')
        elif self.seen:
            self.give_up(f'{self.world} has left the ROS graph: no world left')
        elif time.monotonic() - self.started > self.startup_timeout:
            self.give_up(f'{self.world} not found within {self.startup_timeout:.1f} s: '
                         'start the simulator first, or use sim:=true')

    def give_up(self, reason: str):
        """Exit code 1, which capstone.launch.py's OnProcessExit turns into a shutdown."""
        self.get_logger().fatal(reason)
        raise Finished(1)


def main(args=None):
    return run(SimWatchdog, args)


if __name__ == '__main__':
    main()
