"""Start the controller with a robot name and a speed limit chosen at launch time.

    ros2 launch my_robot_pkg robot_args.launch.py --show-args
    ros2 launch my_robot_pkg robot_args.launch.py robot_name:=my_bot sim_mode:=false
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # [START declare]
    robot_name_arg = DeclareLaunchArgument(
        'robot_name',
        default_value='scout',
        description='Name of the robot, used in the log of the controller',
    )
    max_speed_arg = DeclareLaunchArgument(
        'max_speed',
        default_value='0.5',
        description='Top linear speed in m/s (a decimal number, e.g. 1.0)',
    )
    sim_mode_arg = DeclareLaunchArgument(
        'sim_mode',
        default_value='true',
        choices=['true', 'false'],
    )
    # [END declare]

    # [START use]
    robot_name = LaunchConfiguration('robot_name')
    max_speed = LaunchConfiguration('max_speed')
    sim_mode = LaunchConfiguration('sim_mode')

    controller = Node(
        package='my_robot_pkg',
        executable='robot_controller',
        parameters=[{
            'robot_name': robot_name,
            'max_linear_speed': max_speed,
        }],
        output='screen',
    )
    # [END use]

    # [START description]
    return LaunchDescription([
        robot_name_arg,
        max_speed_arg,
        sim_mode_arg,
        LogInfo(msg=['Robot ', robot_name, ', sim_mode ', sim_mode,
                     ', max_speed ', max_speed]),
        controller,
    ])
    # [END description]
