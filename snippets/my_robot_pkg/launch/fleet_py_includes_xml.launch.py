"""Two robots from Python: each is the XML bringup_formats.launch.xml,
included with its own arguments.

    ros2 launch my_robot_pkg fleet_py_includes_xml.launch.py
"""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


# [START robot]
def robot(arguments: dict[str, str]) -> GroupAction:
    """One robot: the XML bringup with these arguments, in a group of its own."""
    bringup = os.path.join(get_package_share_directory('my_robot_pkg'),
                           'launch', 'bringup_formats.launch.xml')
    return GroupAction([IncludeLaunchDescription(XMLLaunchDescriptionSource(bringup),
                                                 launch_arguments=arguments.items())])
# [END robot]


def generate_launch_description():
    # [START fleet]
    return LaunchDescription([
        robot({'robot_name': 'robot1'}),
        robot({'robot_name': 'robot2', 'sensor_rate': '5.0', 'use_controller': 'false'}),
    ])
    # [END fleet]
