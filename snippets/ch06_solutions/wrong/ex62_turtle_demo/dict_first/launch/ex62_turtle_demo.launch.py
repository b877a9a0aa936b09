# Mistake: the dictionary comes before the file in parameters=[...], so the file's 0.2 wins
# Verdict names: got max_linear_speed 0.2 (a float), expected 0.35
# (ThisLaunchFileDir finds this package's config/ without naming the package, so that
# the test can build this file under another package name; a student writes FindPackageShare.)
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    turtle_params = PathJoinSubstitution([ThisLaunchFileDir(), '..', 'config', 'ex62_turtle.yaml'])
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[{'max_linear_speed': 0.35}, turtle_params]),
    ])
