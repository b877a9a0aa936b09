# Mistake: the detector is left out to save a process: the camera and the monitor run
#   within budget, and no result is ever made.
# Verdict names: /detector is not in the graph
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tuning_demo_pkg', executable='camera', name='camera', output='screen',
             parameters=[{'width': 640, 'height': 480, 'fps': 10.0}]),
        Node(package='tuning_demo_pkg', executable='monitor', name='monitor', output='screen'),
    ])
