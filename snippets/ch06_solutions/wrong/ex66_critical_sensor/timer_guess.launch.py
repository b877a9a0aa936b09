# Mistake: a TimerAction guesses how long the sensor needs; a slower calibration beats the guess.
# Verdict names: data_processor started before the sensor was ready
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessExit
from launch.events import Shutdown
from launch_ros.actions import Node


def generate_launch_description():
    sensor = Node(package='my_robot_pkg', executable='sensor_publisher', output='screen')
    processor = Node(package='my_robot_pkg', executable='data_processor', output='screen')
    return LaunchDescription([
        sensor,
        TimerAction(period=2.0, actions=[processor]),
        RegisterEventHandler(OnProcessExit(
            target_action=sensor,
            on_exit=[EmitEvent(event=Shutdown(reason='the sensor died'))],
        )),
    ])
