"""robot.launch.py without its scopes: the subsystems included one after the
other, and control given only the arguments whose defaults we did not like.

    ros2 launch robot_bringup mistake_robot_unscoped.launch.py robot_name:=robot1

The controller's rate is not passed, so you would expect control.launch.py's
default, 20.0.  Lesson 6.12 shows what the controller really gets.
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import PushROSNamespace
from launch_ros.substitutions import FindPackageShare


def include(name: str, arguments: dict) -> IncludeLaunchDescription:
    path = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'launch',
                                 f'{name}.launch.py'])
    return IncludeLaunchDescription(PythonLaunchDescriptionSource(path),
                                    launch_arguments=arguments.items())


def generate_launch_description():
    robot_name = LaunchConfiguration('robot_name')
    # [START robot]
    robot = GroupAction([
        PushROSNamespace(robot_name),
        include('sensors', {'rate': LaunchConfiguration('sensor_rate')}),
        include('perception', {}),
        include('control', {'robot_name': robot_name}),  # rate: control's default 20.0?
    ])
    # [END robot]
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', description='Namespace of the robot'),
        DeclareLaunchArgument('sensor_rate', default_value='2.0',
                              description='Sensor readings per second'),
        robot,
    ])
