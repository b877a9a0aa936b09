"""OnExecutionComplete: react when an action's work is done, and where its
handler must stand (lesson 6.6).

    ros2 launch my_robot_pkg events_execution_complete.launch.py
"""
from launch import LaunchDescription
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler, TimerAction
from launch.event_handlers import OnExecutionComplete


def generate_launch_description():
    # [START handlers]
    calibrate = ExecuteProcess(cmd=['sleep', '0.2'], name='calibrate')
    announce = TimerAction(period=1.0, actions=[LogInfo(msg='timer: one second')])
    return LaunchDescription([
        # registered before its action: fires once the process has ended
        RegisterEventHandler(OnExecutionComplete(
            target_action=calibrate,
            on_completion=[LogInfo(msg='calibrate complete')])),
        calibrate,
        announce,
        # registered after its action: never fires
        RegisterEventHandler(OnExecutionComplete(
            target_action=announce,
            on_completion=[LogInfo(msg='announce complete')])),
    ])
    # [END handlers]
