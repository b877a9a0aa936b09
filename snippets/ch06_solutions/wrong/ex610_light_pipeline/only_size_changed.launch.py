# Mistake: only the image size is changed; the camera still sends 30 fps and four processes
#   still start.
# Verdict names: 4 processes start
# Verdict names: the camera sends 30.0 fps
from launch import LaunchDescription
from launch_ros.actions import Node

IMAGE_QOS = {'reliability': 'reliable', 'depth': 100}


def generate_launch_description():
    return LaunchDescription([
        Node(package='tuning_demo_pkg', executable='camera', name='camera', output='screen',
             parameters=[{'width': 640, 'height': 480, 'fps': 30.0, **IMAGE_QOS}]),
        Node(package='tuning_demo_pkg', executable='detector', name='detector',
             output='screen', parameters=[{'detect_rate': 5.0, **IMAGE_QOS}]),
        Node(package='tuning_demo_pkg', executable='image_stats', name='image_stats',
             output='screen', parameters=[IMAGE_QOS]),
        Node(package='tuning_demo_pkg', executable='monitor', name='monitor', output='screen'),
    ])
