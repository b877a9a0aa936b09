# The solution's launch file; this wrong answer is in config/ex65_robots.yaml.
# (It finds its own share folder with ThisLaunchFileDir: the test builds each wrong answer
#   under another package name, where FindPackageShare('my_ws_exercises') finds nothing.)
from launch import LaunchDescription
from launch.actions import GroupAction
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    settings = PathJoinSubstitution(
        [ThisLaunchFileDir(), '..', 'config', 'ex65_robots.yaml'])

    def robot(namespace: str) -> GroupAction:
        # The group ends the namespace with the robot: robot2 is not inside robot1.
        return GroupAction([
            PushROSNamespace(namespace),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen'),
            Node(package='my_robot_pkg', executable='data_processor', output='screen'),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=[settings]),
        ])

    return LaunchDescription([robot('robot1'), robot('robot2')])
