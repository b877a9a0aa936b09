# Mistake: the demo loads the turtle file, edited to 0.35, so normal days drive at 0.35 too
# Verdict names: ex62_turtle.launch.py now also gives max_linear_speed 0.35
# (ThisLaunchFileDir finds this package's config/ without naming the package, so that
# the test can build this file under another package name; a student writes FindPackageShare.)
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    turtle_params = PathJoinSubstitution([ThisLaunchFileDir(), '..', 'config', 'ex62_turtle.yaml'])
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[turtle_params]),
    ])
