"""One robot, composed of its subsystems: each included in a scope of its own,
with every argument it needs passed down, all in the robot's namespace.

    ros2 launch robot_bringup robot.launch.py robot_name:=robot1
    ros2 launch robot_bringup robot.launch.py robot_name:=robot2 sensor_rate:=5.0
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import PushROSNamespace
from launch_ros.substitutions import FindPackageShare


# [START subsystem]
def subsystem(name: str, arguments: dict) -> GroupAction:
    """Include launch/<name>.launch.py in a scope of its own: its arguments end with it."""
    path = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                 f'{name}.launch.py'])
    return GroupAction([IncludeLaunchDescription(PythonLaunchDescriptionSource(path),
                                                 launch_arguments=arguments.items())])
# [END subsystem]


def generate_launch_description():
    # [START arguments]
    arguments = [
        DeclareLaunchArgument('robot_name',
                              description='Namespace of the robot (required: no two robots '
                                          'may share one)'),
        DeclareLaunchArgument('sensor_rate', default_value='2.0',
                              description='Sensor readings per second'),
        DeclareLaunchArgument('control_rate', default_value='20.0',
                              description='Control loop updates per second'),
    ]
    # [END arguments]
    robot_name = LaunchConfiguration('robot_name')
    # [START robot]
    robot = GroupAction([
        PushROSNamespace(robot_name),
        subsystem('sensors', {'rate': LaunchConfiguration('sensor_rate')}),
        subsystem('perception', {}),
        subsystem('control', {'robot_name': robot_name,
                              'rate': LaunchConfiguration('control_rate')}),
    ])
    # [END robot]
    return LaunchDescription([*arguments, robot])
