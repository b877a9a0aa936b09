"""The capstone as the chapter 7 checks know it: capstone_bringup's robot.launch.py
starts these nodes in each turtle's namespace, next to turtlesim, from these configs."""
from __future__ import annotations

from labkit.grading.exercise import SNIPPETS

SIMULATOR = '/turtlesim'
ROBOT_NODES = ('wall_sensor', 'pose_estimator', 'patrol_planner', 'controller',
               'safety_monitor', 'mission_recorder')
CONFIG = SNIPPETS / 'capstone_bringup' / 'config'


def robot_nodes(*robots: str) -> tuple[str, ...]:
    """The full names of the nodes of `robots` (e.g. 'turtle1'), robot by robot."""
    return tuple(f'/{robot}/{node}' for robot in robots for node in ROBOT_NODES)
