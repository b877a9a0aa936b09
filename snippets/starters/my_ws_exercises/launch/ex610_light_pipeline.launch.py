"""Exercise 6.10.1: a pipeline within a budget.

This is tuning_demo_pkg's pipeline as first written (pipeline_baseline.launch.py).
Change it so that it stays within this budget:

- the detector still publishes 5 results a second, and the monitor reports them;
- the camera sends at most 10 fps, and at least twice the detector's detect_rate;
- images of at most 640x480 pixels;
- at most 3 processes for the nodes.

    colcon build --packages-select my_ws_exercises
    ros2 launch my_ws_exercises ex610_light_pipeline.launch.py
"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # TODO: meet the budget above with parameters, executables and nodes left out.
    return LaunchDescription([
        Node(
            package='tuning_demo_pkg',
            executable='camera',
            name='camera',
            parameters=[{
                'width': 1280,
                'height': 720,
                'fps': 30.0,
                'reliability': 'reliable',
                'depth': 100,
            }],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='detector',
            name='detector',
            parameters=[{
                'detect_rate': 5.0,
                'reliability': 'reliable',
                'depth': 100,
            }],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='image_stats',
            name='image_stats',
            parameters=[{'reliability': 'reliable', 'depth': 100}],
            output='screen',
        ),
        Node(
            package='tuning_demo_pkg',
            executable='monitor',
            name='monitor',
            output='screen',
        ),
    ])
