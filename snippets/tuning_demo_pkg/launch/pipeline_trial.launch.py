"""The baseline pipeline with every knob a launch argument, for trying one
change at a time.

With no argument it starts exactly what pipeline_baseline.launch.py starts;
each argument given on the command line is one change to measure:

    ros2 launch tuning_demo_pkg pipeline_trial.launch.py fps:=5.0
    ros2 launch tuning_demo_pkg pipeline_trial.launch.py image_stats:=false
"""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

# [START arguments]
#: name -> (the baseline's value, what it sets)
ARGUMENTS = {
    'width': ('1280', 'image width in pixels (camera)'),
    'height': ('720', 'image height in pixels (camera)'),
    'fps': ('30.0', 'frames per second (camera)'),
    'reliability': ('reliable', 'QoS reliability of /image: reliable or best_effort'),
    'depth': ('100', 'QoS history depth of /image'),
    'image_stats': ('true', 'start the image_stats node'),
    'one_process': ('false', 'run camera and detector in one process (executable pipeline)'),
}
# [END arguments]


def generate_launch_description():
    arguments = [DeclareLaunchArgument(name, default_value=default, description=text)
                 for name, (default, text) in ARGUMENTS.items()]
    # [START parameters]
    image_qos = {
        'reliability': LaunchConfiguration('reliability'),
        'depth': ParameterValue(LaunchConfiguration('depth'), value_type=int),
    }
    camera = {
        'width': ParameterValue(LaunchConfiguration('width'), value_type=int),
        'height': ParameterValue(LaunchConfiguration('height'), value_type=int),
        'fps': ParameterValue(LaunchConfiguration('fps'), value_type=float),
        **image_qos,
    }
    detector = {'detect_rate': 5.0, **image_qos}
    # [END parameters]
    one_process = LaunchConfiguration('one_process')
    # [START nodes]
    nodes = [
        Node(package='tuning_demo_pkg', executable='camera', name='camera',
             parameters=[camera], output='screen', condition=UnlessCondition(one_process)),
        Node(package='tuning_demo_pkg', executable='detector', name='detector',
             parameters=[detector], output='screen', condition=UnlessCondition(one_process)),
        # One process, two nodes (camera and detector): no name=, which would
        # give both nodes the same name; each node reads its own parameters.
        Node(package='tuning_demo_pkg', executable='pipeline',
             parameters=[camera, detector], output='screen',
             condition=IfCondition(one_process)),
        Node(package='tuning_demo_pkg', executable='image_stats', name='image_stats',
             parameters=[image_qos], output='screen',
             condition=IfCondition(LaunchConfiguration('image_stats'))),
        Node(package='tuning_demo_pkg', executable='monitor', name='monitor', output='screen'),
    ]
    # [END nodes]
    return LaunchDescription([*arguments, *nodes])
