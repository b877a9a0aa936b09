# Mistake: ros2 param set run by the launch file: stored, but the loop was timed at start-up
# Verdict names: started its control loop at 20.0 Hz
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    scout_params = PathJoinSubstitution(
        [FindPackageShare('my_robot_pkg'), 'config', 'robot_params.yaml'])
    return LaunchDescription([
        Node(package='my_robot_pkg', executable='robot_controller', name='robot_controller',
             output='screen', parameters=[scout_params]),
        ExecuteProcess(cmd=['ros2', 'param', 'set', '/robot_controller', 'update_rate', '5.0'],
                       output='screen'),
    ])
