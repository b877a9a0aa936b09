# Mistake: the inspector's site layer is never loaded: turtle3 runs as the capstone's
# Verdict names: /turtle3/controller got max_linear 1.0, expected 0.6
"""The night shift (capstone project, chapter 7): three robots of the capstone,
turtle3 the inspector, and a shift that selects a parameter layer.

    ros2 launch my_ws_exercises night_shift.launch.py               # the day shift
    ros2 launch my_ws_exercises night_shift.launch.py shift:=night  # all at half speed

The simulator and each robot come from capstone_bringup (sim.launch.py,
robot.launch.py), unchanged.  robot.launch.py loads the capstone's
defaults.yaml, then one file of the robot's own (robot_params).  This file
makes that one file from the layers, last wins: the capstone's
config/<robot>.yaml, the inspector's site layer (turtle3 only), and the
shift's layer.  A layer names a node for every robot (/**/controller) or for
one robot (/turtle2/controller).
"""
import shutil
import tempfile

import yaml
from launch import LaunchContext, LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, \
    OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare

ROBOTS = ('turtle1', 'turtle2', 'turtle3')
INSPECTOR = 'turtle3'
SHIFTS = ('day', 'night')


def share(package: str, *path: str) -> PathJoinSubstitution:
    return PathJoinSubstitution([FindPackageShare(package), *path])


def layered(folder: str, robot: str, layers: list[str]) -> str:
    """One parameter file for `robot` in `folder` from `layers` (later layers win),
    keyed /**/<node>."""
    merged: dict[str, dict] = {}
    for layer in layers:
        with open(layer) as stream:
            entries = yaml.safe_load(stream) or {}
        for key, entry in entries.items():
            scope, _, node = key.rpartition('/')
            if scope in ('/**', f'/{robot}'):
                merged.setdefault(f'/**/{node}', {}).update(entry['ros__parameters'])
    path = f'{folder}/{robot}.yaml'
    with open(path, 'w') as out:
        yaml.safe_dump({key: {'ros__parameters': values} for key, values in merged.items()},
                       out)
    return path


def night_shift(context: LaunchContext) -> list:
    """The simulator and the three robots, each with its layers, for the shift asked for."""
    shift = LaunchConfiguration('shift').perform(context)  # checked: choices=SHIFTS
    mine = share('my_ws_exercises', 'config').perform(context)
    capstone = share('capstone_bringup', 'config').perform(context)
    folder = tempfile.mkdtemp(prefix='night_shift_')  # the merged files, removed at the end
    actions = [
        RegisterEventHandler(OnShutdown(
            on_shutdown=lambda event, context: shutil.rmtree(folder, ignore_errors=True))),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(share('capstone_bringup', 'launch', 'sim.launch.py')),
            launch_arguments={'robot_count': str(len(ROBOTS))}.items()),
    ]
    for robot in ROBOTS:
        layers = [f'{capstone}/{robot}.yaml']
        layers.append(f'{mine}/night_shift_{shift}.yaml')
        actions.append(GroupAction(scoped=True, actions=[IncludeLaunchDescription(
            PythonLaunchDescriptionSource(share('capstone_bringup', 'launch', 'robot.launch.py')),
            launch_arguments={'robot': robot,
                              'robot_params': layered(folder, robot, layers)}.items())]))
    return actions


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('shift', default_value='day', choices=list(SHIFTS),
                              description='day, or night: every robot at half its day speed'),
        OpaqueFunction(function=night_shift),
    ])
