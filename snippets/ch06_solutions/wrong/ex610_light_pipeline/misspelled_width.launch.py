# Mistake: 'widht' instead of 'width': the camera declares only width, ignores the unknown
#   name without a word and sends images of its default width.
# Verdict names: width is 1280, the camera's default
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tuning_demo_pkg', executable='pipeline', output='screen',
             parameters=[{'widht': 640, 'height': 480, 'fps': 10.0, 'detect_rate': 5.0}]),
        Node(package='tuning_demo_pkg', executable='monitor', name='monitor', output='screen'),
    ])
