"""As many sensors as the argument sensor_count asks for: a loop over a
launch argument's value, which only Python can write (lesson 6.11).

    ros2 launch my_robot_pkg sensor_array.launch.py sensor_count:=5
"""
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


# [START opaque]
def sensors(context: LaunchContext) -> list[Node]:
    """Runs while the launch runs, when the argument has its value: a plain int."""
    count = int(LaunchConfiguration('sensor_count').perform(context))
    return [Node(package='my_robot_pkg', executable='sensor_publisher',
                 name=f'sensor_{number}', output='screen')
            for number in range(1, count + 1)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('sensor_count', default_value='3',
                              description='How many sensors to start'),
        OpaqueFunction(function=sensors),
    ])
# [END opaque]
