"""labkit: run ROS 2 launches from a notebook and look at what they start.

The lessons of this book use a handful of calls::

    import labkit

    with labkit.launch('my_robot_pkg', 'robot_system.launch.py', robot_name='my_bot') as run:
        print(run.command)  # ros2 launch my_robot_pkg robot_system.launch.py robot_name:=my_bot
        run.wait_for_nodes(['/sensor_publisher', '/data_processor'])
        snapshot = labkit.graph()     # nodes, topics, who publishes / subscribes
        print(snapshot)
        snapshot.parameters('/sensor_publisher')   # {'publish_rate': 2.0, ...}
        labkit.draw_graph(snapshot)   # the rqt_graph picture, as a matplotlib Figure
        print(run.output())           # what the launch printed so far
    # leaving the block stops the launch: Ctrl-C, as in a terminal

A notebook run outside the book's build starts with `labkit.require_workspace()`:
it says exactly what to install, build and source when something is missing.

Exercises grade the student's own package with `labkit.exercises`
(`setup`, `solution`, `check`; see EXERCISES.md).

`labkit.launch()` and `labkit.run()` (for `ros2 run`) also work without
`with`: keep the returned object and call `.stop()` when done.  Whatever
is still running when the kernel exits is stopped, and a small watchdog
process stops it even if the kernel crashes or is killed.

labkit uses only rclpy and the `ros2` command, so it works the same with a
real ROS 2 install and with this project's clean-room one.  It inherits the
ROS isolation (ROS_DOMAIN_ID, ROS_AUTOMATIC_DISCOVERY_RANGE) of the notebook,
which the book's build sets for every lesson.
"""
from labkit.errors import LabkitError, NodesNotFoundError, ProcessExitedError
from labkit.workspace import (
                              WorkspaceNotReadyError,
                              require_ros_python,
                              require_workspace,
                              sourced_environment,
)

# Without a sourced ROS 2, `import labkit` says what to do, not "No module named 'rclpy'".
require_ros_python()

from labkit import exercises  # noqa: E402
from labkit.background import Background  # noqa: E402
from labkit.commands import launch, run, start, start_launch  # noqa: E402
from labkit.drawing import draw_graph  # noqa: E402
from labkit.graph import GraphSnapshot, Topic, graph, read_parameters  # noqa: E402

__all__ = [
    'Background', 'GraphSnapshot', 'LabkitError', 'NodesNotFoundError', 'ProcessExitedError',
    'Topic', 'WorkspaceNotReadyError', 'draw_graph', 'exercises', 'graph', 'launch',
    'read_parameters', 'require_workspace', 'run', 'sourced_environment', 'start',
    'start_launch',
]
