# Mistake: use_sensor has no choices, so use_sensor:=yes is not refused: the controller starts
#   and then the condition of the sensor fails on 'yes'.
# Verdict names: use_sensor:=yes was not refused
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    robot_name = LaunchConfiguration('robot_name')
    max_speed = LaunchConfiguration('max_speed')
    use_sensor = LaunchConfiguration('use_sensor')
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='rover',
                              description='Name of the robot'),
        DeclareLaunchArgument('max_speed', default_value='0.3',
                              description='Top linear speed in m/s (a decimal number)'),
        DeclareLaunchArgument('use_sensor', default_value='true'),
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[{'robot_name': robot_name, 'max_linear_speed': max_speed}],
            output='screen',
        ),
        Node(
            package='my_robot_pkg',
            executable='sensor_publisher',
            output='screen',
            condition=IfCondition(use_sensor),
        ),
        LogInfo(
            msg=['Fast robot: max_speed ', max_speed, ' m/s is above 1.0 m/s'],
            condition=IfCondition(PythonExpression([max_speed, ' > 1.0'])),
        ),
    ])
