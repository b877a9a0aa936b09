# Mistake: the parameter file is saved as config/ex64_fast_robot.yml. setup.py's data_files
#   install config/*.yaml only, so colcon build leaves it out of install/.
# Verdict names: config/ex64_fast_robot.yml is in src/ but not installed
# (It finds its own share folder with ThisLaunchFileDir: the test builds each wrong answer
#   under another package name, where FindPackageShare('my_ws_exercises') finds nothing.)
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    params_file = PathJoinSubstitution(
        [ThisLaunchFileDir(), '..', 'config', 'ex64_fast_robot.yml'])
    return LaunchDescription([
        Node(
            package='my_robot_pkg',
            executable='robot_controller',
            parameters=[params_file],
            output='screen',
        ),
    ])
