"""Robot 2, all in one file: a copy of copy_robot1.launch.py made before robot 1
was retuned, and never updated (lesson 6.12 shows what that costs).

    ros2 launch robot_bringup copy_robot2.launch.py
"""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    # [START robot]
    return LaunchDescription([GroupAction([
        PushROSNamespace('robot2'),
        Node(package='my_robot_pkg', executable='sensor_publisher', output='screen',
             parameters=[{'publish_rate': 2.0}]),
        Node(package='my_robot_pkg', executable='data_processor', output='screen',
             parameters=[{'window_size': 3}]),
        Node(package='my_robot_pkg', executable='robot_controller', output='screen',
             parameters=[{'robot_name': 'robot2', 'update_rate': 20.0,
                          'max_linear_speed': 0.8, 'max_angular_speed': 1.0}]),
    ])])
    # [END robot]
