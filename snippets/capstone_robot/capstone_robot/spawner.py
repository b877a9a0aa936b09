"""Spawner: asks turtlesim for one more turtle, then ends.

turtlesim starts with ``turtle1`` only; every further robot needs its own
turtle, made by turtlesim's ``/spawn`` service (the real turtlesim's and
the headless one's).  The turtle gets the name ``turtle_name`` (default:
the last part of the spawner's namespace) at ``x``, ``y``, ``theta``.
"""
from rclpy.node import Node
from turtlesim.srv import Spawn

from .running import ConfigurationError, Finished, run


class Spawner(Node):
    """Calls ``/spawn`` once turtlesim offers it, and ends (exit code 0) with its answer."""

    def __init__(self):
        super().__init__('spawner')
        self.turtle = self.declare_parameter('turtle_name', '').value \
            or self.get_namespace().rstrip('/').rpartition('/')[2]
        if not self.turtle:
            raise ConfigurationError('No turtle name: set turtle_name or start me in a namespace')
        self.request = Spawn.Request(name=self.turtle,
                                     x=self.declare_parameter('x', 1.0).value,
                                     y=self.declare_parameter('y', 1.0).value,
                                     theta=self.declare_parameter('theta', 0.0).value)
        self.client = self.create_client(Spawn, '/spawn')
        self.future = None
        self.create_timer(0.1, self.step)

    def step(self):
        """Ask as soon as turtlesim is there; finish when it has answered."""
        if self.future is None:
            if self.client.service_is_ready():
                self.future = self.client.call_async(self.request)
            else:
                self.get_logger().info('Waiting for turtlesim (/spawn)', once=True)
        elif self.future.done():
            self.report(self.future.result())
            raise Finished(0)

    def report(self, response: Spawn.Response):
        r = self.request
        if response.name:
            self.get_logger().info(
                f'Spawned {r.name} at ({r.x:.2f}, {r.y:.2f}), heading {r.theta:.2f}')
        else:  # turtlesim refuses a name that exists
            self.get_logger().warning(f'{r.name} exists already: using that turtle')


def main(args=None):
    return run(Spawner, args)


if __name__ == '__main__':
    main()
