"""Mission recorder: a lifecycle-managed node that keeps the robot's log book.

A lifecycle node does nothing useful until it is told to: ``configure``
reads its parameters and opens its file, ``activate`` starts recording,
``deactivate`` pauses, ``cleanup`` closes the file.  The launch file walks
it through configure and activate once the rest of the robot is starting.
It logs every waypoint reached and every safety stop, and with
``record_file`` set also appends them to that file as CSV lines.
"""
import time

from capstone_interfaces.msg import RobotStatus
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from std_msgs.msg import Bool

from .running import run


class MissionRecorder(LifecycleNode):

    def __init__(self):
        super().__init__('mission_recorder')
        self.declare_parameter('record_file', '')  # '' records to the log only
        self.file = None
        self.recording = []
        self.reached = 0
        self.stopped = False
        self.stops = 0

    def on_configure(self, state) -> TransitionCallbackReturn:
        path = self.get_parameter('record_file').value
        if path:
            try:
                self.file = open(path, 'a', encoding='utf-8')  # open until cleanup
            except OSError as error:
                self.get_logger().error(f'Cannot record to {path}: {error}')
                return TransitionCallbackReturn.FAILURE
        self.get_logger().info(f'Configured: recording to {path or "the log only"}')
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state) -> TransitionCallbackReturn:
        self.recording = [
            self.create_subscription(RobotStatus, 'status', self.on_status, 10),
            self.create_subscription(Bool, 'safety_stop', self.on_safety_stop, 10),
        ]
        self.get_logger().info('Active: recording the mission')
        return super().on_activate(state)

    def on_deactivate(self, state) -> TransitionCallbackReturn:
        for subscription in self.recording:
            self.destroy_subscription(subscription)
        self.recording = []
        self.get_logger().info(f'Paused after {self.reached} waypoints, {self.stops} stops')
        return super().on_deactivate(state)

    def on_cleanup(self, state) -> TransitionCallbackReturn:
        self.close()
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state) -> TransitionCallbackReturn:
        self.close()
        return TransitionCallbackReturn.SUCCESS

    def close(self):
        if self.file is not None:
            self.file.close()
            self.file = None

    def record(self, event: str, detail: str):
        self.get_logger().info(f'{event}: {detail}')
        if self.file is not None:
            self.file.write(f'{time.time():.3f},{event},{detail}\n')
            self.file.flush()

    def on_status(self, status: RobotStatus):
        if status.waypoints_reached > self.reached:
            self.reached = status.waypoints_reached
            self.record('waypoint', f'{self.reached} reached, next #{status.waypoint_index}')

    def on_safety_stop(self, stop: Bool):
        if stop.data and not self.stopped:
            self.stops += 1
            self.record('safety_stop', f'stop {self.stops}')
        self.stopped = stop.data


def main(args=None):
    return run(MissionRecorder, args)


if __name__ == '__main__':
    main()
