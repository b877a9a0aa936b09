# Mistake: PushROSNamespace without a GroupAction stays in force: robot2 lands in /robot1/robot2.
# Verdict names: /robot2/sensor_publisher is not in the graph
# (It finds its own share folder with ThisLaunchFileDir: the test builds each wrong answer
#   under another package name, where FindPackageShare('my_ws_exercises') finds nothing.)
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    settings = PathJoinSubstitution(
        [ThisLaunchFileDir(), '..', 'config', 'ex65_robots.yaml'])
    actions = []
    for namespace in ('robot1', 'robot2'):
        actions += [
            PushROSNamespace(namespace),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
            Node(package='my_robot_pkg', executable='data_processor', output='screen'),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=[settings]),
        ]
    return LaunchDescription(actions)
