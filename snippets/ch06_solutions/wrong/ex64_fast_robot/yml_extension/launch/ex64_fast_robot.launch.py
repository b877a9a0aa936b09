# Mistake: the parameter file is saved as config/ex64_fast_robot.yml. setup.py's data_files
#   install config/*.yaml only, so colcon build leaves it out of install/.
# Verdict names: config/ex64_fast_robot.yml is in src/ but not installed
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params_file = PathJoinSubstitution(
        [FindPackageShare('my_ws_exercises'), 'config', 'ex64_fast_robot.yml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
