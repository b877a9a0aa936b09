"""Capstone project (chapter 7): the night shift.

    ros2 launch my_ws_exercises night_shift.launch.py               # the day shift
    ros2 launch my_ws_exercises night_shift.launch.py shift:=night

The brief (lesson "The capstone project brief") lists the requirements N1-N6.
Reuse capstone_bringup's launch files; do not copy or change them:
sim.launch.py (argument robot_count) and robot.launch.py (arguments robot and
robot_params, the one parameter file it loads over the capstone's
defaults.yaml).

TODO N1: turtlesim and three robots, turtle1, turtle2 and turtle3
TODO N2: turtle3 is the inspector: its route, speed and stop distance come
         from your site layer, config/night_shift_inspector.yaml
TODO N4: a launch argument shift, day (default) or night; night loads your
         layer config/night_shift_night.yaml (every robot at half its day speed)
TODO N5: any other shift is refused before anything starts, with a message
         that names the allowed values
"""
from launch import LaunchDescription


def generate_launch_description():
    return LaunchDescription([
    ])
