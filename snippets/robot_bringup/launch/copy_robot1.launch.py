"""Robot 1, all in one file: the alternative to subsystem files and includes.

copy_robot2.launch.py began as a copy of this file.  Since then robot 1's
perception and control were retuned here (window 5, 0.5 m/s) and nobody
changed the copy.  Lesson 6.12 runs both and compares the robots.

    ros2 launch robot_bringup copy_robot1.launch.py
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    # [START robot]
    return LaunchDescription([GroupAction([
        PushROSNamespace('robot1'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': 2.0}]),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=[{'window_size': 5}]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=[{'robot_name': 'robot1', 'update_rate': 20.0,
                          'max_linear_speed': 0.5, 'max_angular_speed': 1.0}]),
    ])])
    # [END robot]
