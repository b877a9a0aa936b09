"""Launch arguments decide which nodes start.

    ros2 launch my_robot_pkg conditional_sensors.launch.py sim_mode:=false controller:=manual
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import EqualsSubstitution, LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    sim_mode = LaunchConfiguration('sim_mode')
    use_filter = LaunchConfiguration('use_filter')
    controller = LaunchConfiguration('controller')
    sensor_rate = LaunchConfiguration('sensor_rate')

    # [START arguments]
    arguments = [
        DeclareLaunchArgument('sim_mode', default_value='true', choices=['true', 'false']),
        DeclareLaunchArgument('use_filter', default_value='true',
                              description='Start data_processor to smooth the readings'),
        DeclareLaunchArgument('controller', default_value='auto', choices=['auto', 'manual']),
        DeclareLaunchArgument('sensor_rate', default_value='2.0',
                              description='Readings per second of the simulated sensor'),
    ]
    # [END arguments]

    # [START if_unless]
    simulated_sensor = Node(
        package='my_robot_pkg',
        executable='sensor_publisher',
        parameters=[{'publish_rate': sensor_rate}],
        output='screen',
        condition=IfCondition(sim_mode),
    )
    no_simulation_note = LogInfo(
        msg='sim_mode is false: no simulated sensor, start the driver of the real one',
        condition=UnlessCondition(sim_mode),
    )
    # [END if_unless]

    # [START python_expression]
    # Average over about one second of readings: as many as the sensor sends per second.
    window_size = PythonExpression(['max(1, int(', sensor_rate, '))'])
    processor = Node(
        package='my_robot_pkg',
        executable='data_processor',
        parameters=[{'window_size': window_size}],
        output='screen',
        condition=IfCondition(use_filter),
    )
    # [END python_expression]

    # [START equals]
    autonomous_controller = Node(
        package='my_robot_pkg',
        executable='robot_controller',
        output='screen',
        condition=IfCondition(EqualsSubstitution(controller, 'auto')),
    )
    manual_note = LogInfo(
        msg='controller is manual: no robot_controller, drive the robot yourself',
        condition=IfCondition(EqualsSubstitution(controller, 'manual')),
    )
    # [END equals]

    return LaunchDescription(arguments + [
        simulated_sensor,
        no_simulation_note,
        processor,
        autonomous_controller,
        manual_note,
    ])
