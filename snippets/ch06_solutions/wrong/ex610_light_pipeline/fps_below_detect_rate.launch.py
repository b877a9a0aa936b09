# Mistake: the camera is slowed below the detector's rate (2 fps for 5 results a second), so
#   most detection ticks find no new frame and the results drop with the frames.
# Verdict names: results a second the detector must publish
# Verdict names: less than twice the detector's detect_rate
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='tuning_demo_pkg', executable='pipeline', output='screen',
             parameters=[{'width': 640, 'height': 480, 'fps': 2.0, 'detect_rate': 5.0}]),
        Node(package='tuning_demo_pkg', executable='monitor', name='monitor', output='screen'),
    ])
