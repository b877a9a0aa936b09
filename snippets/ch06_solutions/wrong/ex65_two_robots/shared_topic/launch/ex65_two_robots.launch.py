# Mistake: the sensors' topic is remapped to the absolute /distance, which both robots share.
# Verdict names: /distance is shared by the robots
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
        return GroupAction([
            PushROSNamespace(namespace),
            Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
                 remappings=[('distance', '/distance')]),
            Node(package='my_robot_pkg', executable='data_processor', output='screen',
                 remappings=[('distance', '/distance')]),
            Node(package='my_robot_pkg', executable='robot_controller', output='screen',
                 parameters=[settings]),
        ])

    return LaunchDescription([robot('robot1'), robot('robot2')])
