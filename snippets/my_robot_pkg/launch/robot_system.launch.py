"""Start the robot's sensor and its data processor with one command.

    ros2 launch my_robot_pkg robot_system.launch.py

Lesson 6.1 takes this file apart line by line.
"""
# [START imports]
from launch import LaunchDescription
from launch_ros.actions import Node
# [END imports]


# [START function]
def generate_launch_description():
    # `ros2 launch` calls this function and carries out what it returns:
    # a LaunchDescription, the list of things to start.
    return LaunchDescription([
        # [START sensor_node]
        Node(
            package='my_robot_pkg',         # the package that holds it
            executable='sensor_publisher',  # an entry point of setup.py
            name='sensor_publisher',        # the node's name in the ROS graph
            output='screen',                # its output is shown in this terminal
        ),
        # [END sensor_node]
        Node(
            package='my_robot_pkg',
            executable='data_processor',
            name='data_processor',
            output='screen',
        ),
    ])
# [END function]
