"""Patrol launch file for my_robot_pkg (ROS 2 Jazzy).

Usage:
    ros2 launch my_robot_pkg patrol.launch.py
    ros2 launch my_robot_pkg patrol.launch.py robot_name:=rover sensor_rate:=10
"""

import os
import re
import tempfile

import yaml

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue

PACKAGE = 'my_robot_pkg'
CONTROLLER_NAME = 'robot_controller'


def _param_sections(tree, prefix=''):
    """Yield (node_key, ros__parameters) for every section of a ROS 2 params file.

    Handles both flat keys ('/ns/node:') and nested keys ('ns:' -> 'node:').
    """
    if not isinstance(tree, dict):
        return
    for key, value in tree.items():
        if key == 'ros__parameters':
            if isinstance(value, dict):
                yield prefix or '/', value
        elif isinstance(value, dict):
            yield from _param_sections(value, prefix + '/' + str(key).strip('/'))


def _key_matches(key, fqn):
    """Match a params-file node key against a node FQN the way rclcpp does.

    '/*' matches one name token, '/**' any number of tokens.
    """
    pattern = key if key.startswith('/') else '/' + key
    return re.fullmatch(pattern.replace('/*', r'(/\w+)'), fqn) is not None


def _deep_merge(base, update):
    for key, value in update.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            _deep_merge(base[key], value)
        else:
            base[key] = value
    return base


def _controller_params_file(yaml_path, namespace):
    """Return a params file the namespaced controller will actually pick up.

    Parameter files are matched against the node's fully qualified name, so a
    section keyed 'robot_controller:' (-> '/robot_controller') is silently
    ignored once the node runs as '/<robot_name>/robot_controller'. Collect
    every section meant for the controller (with or without namespace, or
    wildcards) and re-emit it under '/**' so it applies whatever robot_name is.
    """
    ns_fqn = '/' + '/'.join(filter(None, [namespace, CONTROLLER_NAME]))
    bare_fqn = '/' + CONTROLLER_NAME

    try:
        with open(yaml_path, 'r') as f:
            content = yaml.safe_load(f) or {}
    except (OSError, yaml.YAMLError) as err:
        # Let the node report the problem with the original file.
        return yaml_path, [LogInfo(msg=f'[patrol] could not read {yaml_path}: {err}')]

    merged = {}
    for key, params in _param_sections(content):
        if _key_matches(key, ns_fqn) or _key_matches(key, bare_fqn):
            _deep_merge(merged, params)

    if not merged:
        return yaml_path, [LogInfo(
            msg=f'[patrol] no section for {CONTROLLER_NAME} found in {yaml_path}')]

    with tempfile.NamedTemporaryFile(
            mode='w', prefix=f'{CONTROLLER_NAME}_params_', suffix='.yaml',
            delete=False) as tmp:
        yaml.safe_dump({'/**': {'ros__parameters': merged}}, tmp, default_flow_style=False)
    return tmp.name, []


def _launch_setup(context, *args, **kwargs):
    robot_name = LaunchConfiguration('robot_name').perform(context)
    namespace = robot_name.strip('/')

    sensor_rate_str = LaunchConfiguration('sensor_rate').perform(context)
    try:
        # float() so that e.g. sensor_rate:=10 is still passed as a double.
        sensor_rate = float(sensor_rate_str)
    except ValueError:
        raise RuntimeError(
            f"Launch argument 'sensor_rate' must be a number (Hz), got '{sensor_rate_str}'")

    params_yaml = os.path.join(
        get_package_share_directory(PACKAGE), 'config', 'robot_params.yaml')
    controller_params, actions = _controller_params_file(params_yaml, namespace)

    cmd_vel_topic = f'/{namespace}/cmd_vel' if namespace else '/cmd_vel'

    sensor_publisher = Node(
        package=PACKAGE,
        executable='sensor_publisher',
        name='sensor_publisher',
        namespace=namespace,
        output='screen',
        # Publishes 'distance' -> /<robot_name>/distance
        parameters=[{'publish_rate': sensor_rate}],
    )

    data_processor = Node(
        package=PACKAGE,
        executable='data_processor',
        name='data_processor',
        namespace=namespace,
        output='screen',
        # Subscribes /<robot_name>/distance, publishes /<robot_name>/distance_filtered
        parameters=[{'window_size': 5}],
    )

    robot_controller = Node(
        package=PACKAGE,
        executable='robot_controller',
        name=CONTROLLER_NAME,
        namespace=namespace,
        output='screen',
        parameters=[
            controller_params,
            # Listed after the file so it overrides any robot_name in the YAML;
            # forced to str so e.g. robot_name:=123 isn't turned into an int.
            {'robot_name': ParameterValue(robot_name, value_type=str)},
        ],
        # A relative 'cmd_vel' already resolves to /<robot_name>/cmd_vel via the
        # namespace; these also catch an absolute '/cmd_vel' or private '~/cmd_vel'.
        remappings=[
            ('/cmd_vel', cmd_vel_topic),
            ('~/cmd_vel', cmd_vel_topic),
        ],
    )

    return actions + [sensor_publisher, data_processor, robot_controller]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(
            'robot_name',
            default_value='scout',
            description='Robot name; used as the namespace of every node',
        ),
        DeclareLaunchArgument(
            'sensor_rate',
            default_value='5.0',
            description='Sensor publish rate in Hz',
        ),
        OpaqueFunction(function=_launch_setup),
    ])
