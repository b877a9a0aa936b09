"""`speccheck snapshot`: a spec written from the running graph, which speccheck's own
loader reads and which `speccheck live` finds met on the same system."""
from __future__ import annotations

import subprocess
import sys
from array import array

import jsonschema
import labkit
import pytest
import yaml
from speccheck import Status, check_live, load_spec
from speccheck.__main__ import main
from speccheck.graph import GraphSnapshot, Topic
from speccheck.schema import SPEC_SCHEMA
from speccheck.snapshot import build_spec, to_yaml

GRAPH = GraphSnapshot(('/robot1/lidar', '/robot1/filter', '/mute'), {
    '/robot1/scan': Topic('/robot1/scan', ('sensor_msgs/msg/LaserScan',), ('/robot1/lidar',),
                          ('/robot1/filter',)),
    '/robot1/move/feedback': Topic('/robot1/move/feedback',
                                   ('nav_pkg/action/Move_FeedbackMessage',), (),
                                   ('/robot1/filter',)),
    '/mixed': Topic('/mixed', ('std_msgs/msg/Int32', 'std_msgs/msg/Float32'), ('/mute',), ()),
})
PARAMETERS = {
    '/robot1/lidar': {'frame_id': 'laser', 'rate': 10.0, 'use_sim_time': False,
                      'ranges': array('d', [0.5, 4.0]), 'ids': [1, 2], 'none_yet': [],
                      'unset': None, 'qos_overrides./scan.depth': 5},
    '/robot1/filter': {'window_size': 5},
    '/mute': 'did not answer on /mute/list_parameters',
}


def test_the_snapshot_of_a_graph_is_a_spec_speccheck_loads(write_spec):
    data, notes = build_spec(GRAPH, PARAMETERS, 'test')
    assert list(jsonschema.Draft202012Validator(SPEC_SCHEMA).iter_errors(data)) == []
    lidar = data['nodes']['/robot1/lidar']['parameters']
    assert lidar == {'frame_id': {'type': 'string', 'value': 'laser'},
                     'rate': {'type': 'double', 'value': 10.0},
                     'use_sim_time': {'type': 'bool', 'value': False},
                     'ranges': {'type': 'double_array', 'value': [0.5, 4.0]},
                     'ids': {'type': 'integer_array', 'value': [1, 2]},
                     'none_yet': {'type': 'string_array', 'value': []}}
    assert data['nodes']['/mute'] is None
    assert data['topics']['/robot1/scan'] == {'type': 'sensor_msgs/msg/LaserScan',
                                              'publishers': ['/robot1/lidar'],
                                              'subscribers': ['/robot1/filter']}
    assert data['topics']['/mixed'] == {'publishers': ['/mute']}
    assert data['topics']['/robot1/move/feedback'] == {'subscribers': ['/robot1/filter']}
    assert sorted(notes) == sorted([
        'node /robot1/lidar: parameter unset: unset or of no single type',
        'node /robot1/lidar: parameter qos_overrides./scan.depth: a name a spec cannot hold',
        'node /mute: parameters not read: did not answer on /mute/list_parameters',
        "topic /robot1/move/feedback: type 'nav_pkg/action/Move_FeedbackMessage' not recorded",
        "topic /mixed: type 'std_msgs/msg/Int32, std_msgs/msg/Float32' not recorded",
    ])
    spec = load_spec(write_spec(to_yaml(data, notes)))
    assert [node.name for node in spec.nodes] == ['/robot1/lidar', '/robot1/filter', '/mute']
    rate = next(p for p in spec.node('/robot1/lidar').parameters if p.name == 'rate')
    assert (rate.type, rate.value, rate.has_value) == ('double', 10.0, True)


def test_the_yaml_says_where_it_came_from_and_what_was_left_out():
    text = to_yaml(*build_spec(GRAPH, PARAMETERS, 'test'))
    assert text.startswith('# Written by `speccheck snapshot` from the running graph')
    assert '# left out: node /mute: parameters not read: did not answer' in text
    assert yaml.safe_load(text)['description'] == 'test'



@pytest.fixture(scope='module')
def robot_system(ros_env):
    with labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env) as run:
        run.wait_for_nodes(['/sensor_publisher', '/data_processor'])
        yield run


@pytest.mark.ros
def test_a_snapshot_of_the_running_system_is_met_by_it(robot_system, tmp_path, capsys):
    out = tmp_path / 'snapshot.spec.yaml'
    assert main(['snapshot', str(out)]) == 0
    assert capsys.readouterr().err == f'speccheck snapshot: wrote {out}\n'
    spec = load_spec(out)
    assert {'/sensor_publisher', '/data_processor'} <= {node.name for node in spec.nodes}
    rate = next(p for p in spec.node('/sensor_publisher').parameters
                if p.name == 'publish_rate')
    assert (rate.type, rate.value) == ('double', 2.0)
    distance = next(topic for topic in spec.topics if topic.name == '/distance')
    assert (distance.type, distance.publishers, distance.subscribers) == (
        'std_msgs/msg/Float32', ('/sensor_publisher',), ('/data_processor',))
    report = check_live(spec, window=0.5)
    report.assert_ok()
    assert not report.find('other nodes')  # the snapshot has every node
    assert sum(f.status is Status.MET for f in report.findings) >= 8


@pytest.mark.ros
def test_cli_snapshot_of_a_launch_then_live_against_it(sourced, tmp_path):
    launch = ['--launch', 'my_robot_pkg', 'robot_args.launch.py', 'robot_name:=snap_bot']
    snap = subprocess.run([sys.executable, '-m', 'speccheck', 'snapshot', '-', *launch],
                          env=sourced, capture_output=True, text=True, timeout=120)
    assert snap.returncode == 0, snap.stderr
    data = yaml.safe_load(snap.stdout)
    assert data['description'] == 'Snapshot of robot_args.launch.py robot_name:=snap_bot'
    assert data['nodes']['/robot_controller']['parameters']['robot_name'] == {
        'type': 'string', 'value': 'snap_bot'}
    spec = tmp_path / 'snap.spec.yaml'
    spec.write_text(snap.stdout, encoding='utf-8')
    live = subprocess.run([sys.executable, '-m', 'speccheck', 'live', str(spec), *launch,
                           '--window', '0.5'], env=sourced, capture_output=True, text=True,
                          timeout=120)
    assert live.returncode == 0, live.stdout + live.stderr
    assert "met         node /robot_controller: parameter robot_name: 'snap_bot'" in live.stdout
    other = subprocess.run([sys.executable, '-m', 'speccheck', 'live', str(spec), '--launch',
                            'my_robot_pkg', 'robot_args.launch.py', '--window', '0.5'],
                           env=sourced, capture_output=True, text=True, timeout=120)
    assert other.returncode == 1  # another robot_name: the snapshot is not met
