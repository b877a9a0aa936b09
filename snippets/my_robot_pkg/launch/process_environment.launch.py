"""Environment variables for every process a launch starts, and where they stop.

    ROBOT_NAME=alpha ros2 launch my_robot_pkg process_environment.launch.py
"""
from launch import LaunchDescription
from launch.actions import ExecuteProcess, GroupAction, SetEnvironmentVariable


def show_robot_name(name: str) -> ExecuteProcess:
    """A program that prints the ROBOT_NAME its environment gives it."""
    return ExecuteProcess(cmd=['echo "ROBOT_NAME=$ROBOT_NAME"'], shell=True,
                          name=name, output='screen')


def generate_launch_description():
    # [START environment]
    return LaunchDescription([
        show_robot_name('before'),  # started first: the terminal's ROBOT_NAME
        SetEnvironmentVariable('ROBOT_NAME', 'beta'),  # for every process started after it
        GroupAction([
            SetEnvironmentVariable('ROBOT_NAME', 'gamma'),  # only inside this group
            show_robot_name('in_group'),
        ]),
        show_robot_name('after_group'),  # the group's value ended with the group
    ])
    # [END environment]
