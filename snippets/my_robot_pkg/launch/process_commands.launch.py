"""Non-ROS commands started by launch, and what launch tells us about them.

    ros2 launch my_robot_pkg process_commands.launch.py
"""
from launch import LaunchDescription
from launch.actions import ExecuteProcess, LogInfo, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO
from launch.substitutions import FindExecutable


def generate_launch_description():
    # [START commands]
    # A plain program: FindExecutable looks `uname` up on the PATH, like a shell would.
    system_info = ExecuteProcess(
        cmd=[FindExecutable(name='uname'), '-s', '-m'],
        name='system_info',
        output='screen',
    )
    # A shell command line: variables, $(...) and pipes need shell=True.
    greeter = ExecuteProcess(
        cmd=['echo "robot $ROBOT_NAME works in $(pwd)"'],
        shell=True,
        cwd='/tmp',                             # the folder the command runs in
        additional_env={'ROBOT_NAME': 'alpha'},  # added to the environment it inherits
        name='greeter',
        output='screen',
    )
    # [END commands]
    return LaunchDescription([
        system_info,
        greeter,
        # [START handlers]
        RegisterEventHandler(OnProcessIO(
            target_action=greeter,
            # called with each chunk the process writes to stdout (bytes)
            on_stdout=lambda event: LogInfo(
                msg=f'greeter said: {event.text.decode().strip()}'),
        )),
        RegisterEventHandler(OnProcessExit(
            # no target_action: called for every process that exits
            on_exit=lambda event, context: LogInfo(
                msg=f'{event.action.name} exited with code {event.returncode}'),
        )),
        # [END handlers]
    ])
