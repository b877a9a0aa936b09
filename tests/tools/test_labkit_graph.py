"""labkit.graph / draw_graph: what a running launch looks like, read with rclpy."""
from __future__ import annotations

import labkit
import pytest
from labkit import observer
from labkit.drawing import layers, layout, to_networkx
from labkit.graph import GraphSnapshot, Topic
from matplotlib.figure import Figure
from std_msgs.msg import Float32

from tests._polling import wait_for

SYSTEM_NODES = ['/sensor_publisher', '/data_processor']


@pytest.fixture(scope='module')
def system(ros_env):
    with labkit.launch('my_robot_pkg', 'robot_system.launch.py', env=ros_env) as run:
        run.wait_for_nodes(SYSTEM_NODES)
        yield labkit.graph()


def test_topics_have_types_publishers_and_subscribers(system):
    assert set(SYSTEM_NODES) <= set(system.nodes)
    distance = system.topics['/distance']
    assert distance == Topic('/distance', ('std_msgs/msg/Float32',), ('/sensor_publisher',),
                             ('/data_processor',))
    assert system.publishers('/distance_filtered') == ('/data_processor',)
    assert system.subscribers('/distance_filtered') == ()
    assert ('/sensor_publisher', '/distance') in system.edges()
    assert ('/distance', '/data_processor') in system.edges()


def test_hidden_nodes_and_default_topics_are_left_out(system):
    assert not any(name.startswith('/_') for name in system.nodes)
    assert '/rosout' not in system.topics and '/parameter_events' not in system.topics
    everything = labkit.graph(include_hidden=True, include_default_topics=True)
    assert any(name.startswith('/_labkit_') for name in everything.nodes)
    assert '/sensor_publisher' in everything.topics['/rosout'].publishers


def test_snapshot_text_lists_topics(system):
    text = str(system)
    assert '/distance [std_msgs/msg/Float32]\n    published by: /sensor_publisher\n' \
           '    subscribed by: /data_processor' in text


def test_parameters_of_a_running_node(system):
    assert system.parameters('/sensor_publisher') == {
        'publish_rate': 2.0, 'start_type_description_service': True, 'use_sim_time': False}


def test_parameters_of_an_absent_node_fail_clearly():
    with pytest.raises(labkit.LabkitError, match='/nope did not answer'):
        labkit.read_parameters('/nope', timeout=0.5)


def test_drawing_labels_shapes_and_left_to_right_flow(system):
    figure = system.draw()
    assert isinstance(figure, Figure)
    texts = {t.get_text(): t for t in figure.axes[0].texts if t.get_text()}
    assert set(texts) >= {'/sensor_publisher', '/distance', '/data_processor',
                          '/distance_filtered'}
    assert type(texts['/sensor_publisher'].get_bbox_patch().get_boxstyle()).__name__ == \
        'Ellipse'
    assert type(texts['/distance'].get_bbox_patch().get_boxstyle()).__name__ == 'Square'
    xs = [texts[name].get_position()[0]
          for name in ('/sensor_publisher', '/distance', '/data_processor', '/distance_filtered')]
    assert xs == sorted(xs) and len(set(xs)) == 4


def _chain_snapshot() -> GraphSnapshot:
    """Ten nodes: two sensors -> fusion -> planner <-> controller, plus loggers."""
    topics = {
        '/scan': Topic('/scan', ('sensor_msgs/msg/LaserScan',), ('/lidar',), ('/fusion',)),
        '/image': Topic('/image', ('sensor_msgs/msg/Image',), ('/camera',), ('/fusion', '/rec')),
        '/map': Topic('/map', ('nav_msgs/msg/OccupancyGrid',), ('/fusion',), ('/planner',)),
        '/plan': Topic('/plan', ('nav_msgs/msg/Path',), ('/planner',), ('/controller',)),
        '/odom': Topic('/odom', ('nav_msgs/msg/Odometry',), ('/controller',), ('/planner',)),
        '/cmd_vel': Topic('/cmd_vel', ('geometry_msgs/msg/Twist',), ('/controller',),
                          ('/base', '/logger')),
    }
    nodes = ('/base', '/camera', '/controller', '/fusion', '/idle', '/lidar', '/logger',
             '/planner', '/rec', '/watch')
    return GraphSnapshot(nodes, topics)


def test_layout_is_layered_and_deterministic():
    snapshot = _chain_snapshot()
    graph = to_networkx(snapshot)
    first, second = layout(graph), layout(to_networkx(_chain_snapshot()))
    assert first == second
    column = {vertex: index for index, col in enumerate(layers(graph)) for vertex in col}
    assert column['/lidar'] == column['/camera'] == 0
    assert column['/lidar'] < column['/scan'] < column['/fusion'] < column['/map']
    # the planner/controller loop runs left to right; only /odom -> /planner points back
    assert column['/map'] < column['/planner'] < column['/plan'] < column['/controller'] \
        < column['/odom']
    assert column['/controller'] < column['/cmd_vel'] < column['/base']


def test_drawing_ten_nodes_labels_every_vertex():
    snapshot = _chain_snapshot()
    figure = labkit.draw_graph(snapshot, show_types=True, title='ten nodes')
    labels = {t.get_text() for t in figure.axes[0].texts if t.get_text()}
    assert set(snapshot.nodes) <= labels
    assert '/cmd_vel\n[geometry_msgs/msg/Twist]' in labels
    assert figure.axes[0].get_title() == 'ten nodes'
    assert len([t for t in figure.axes[0].texts if not t.get_text()]) == \
        len(snapshot.edges())  # one arrow per edge


def test_drawing_an_empty_graph():
    figure = labkit.draw_graph(GraphSnapshot((), {}))
    assert [t.get_text() for t in figure.axes[0].texts] == ['no nodes in the graph']



class _GraphWithLeftovers:
    """What a long-lived observer can see after missed departures: exited
    /gone and an exited twin of /talker are still listed, own nothing, and
    the twin shadows the live /talker in the by-node queries."""

    class Endpoint:
        def __init__(self, node_name: str) -> None:
            self.node_name, self.node_namespace = node_name, '/'

    def get_node_names_and_namespaces(self):
        return [('talker', '/'), ('talker', '/'), ('listener', '/'), ('gone', '/'),
                ('server', '/')]

    def get_topic_names_and_types(self):
        return [('/chatter', ['std_msgs/msg/String']), ('/rosout', ['rcl_interfaces/msg/Log'])]

    def get_publishers_info_by_topic(self, topic):
        names = {'/chatter': ['talker', '_NODE_NAME_UNKNOWN_'], '/rosout': ['talker', 'listener']}
        return [self.Endpoint(name) for name in names[topic]]

    def get_subscriptions_info_by_topic(self, topic):
        return [self.Endpoint('listener')] if topic == '/chatter' else []

    def get_publisher_names_and_types_by_node(self, name, namespace):
        return []  # the leftover twin answers for /talker

    get_subscriber_names_and_types_by_node = get_publisher_names_and_types_by_node
    get_client_names_and_types_by_node = get_publisher_names_and_types_by_node

    def get_service_names_and_types_by_node(self, name, namespace):
        return [('/server/reset', ['std_srvs/srv/Empty'])] if name == 'server' else []

    def get_service_names_and_types(self):
        return [('/server/reset', ['std_srvs/srv/Empty'])]


def test_left_over_nodes_of_exited_processes_are_left_out(monkeypatch):
    from types import SimpleNamespace

    from labkit import observer
    monkeypatch.setattr(observer, 'settle', lambda: None)
    monkeypatch.setattr(observer, 'observer',
                        lambda: SimpleNamespace(node=_GraphWithLeftovers()))
    assert observer.node_names() == ['/listener', '/server', '/talker']
    snapshot = labkit.graph()
    assert snapshot.nodes == ('/listener', '/server', '/talker')
    assert snapshot.topics == {'/chatter': Topic('/chatter', ('std_msgs/msg/String',),
                                                 ('/talker',), ('/listener',))}


def test_settle_notices_a_second_publisher_on_a_known_topic(ros_env):
    # settle() waits until the graph stops changing; a new publisher on a
    # topic that already exists changes no name or type, only the counts
    watcher = observer.observer()
    first = watcher.node.create_publisher(Float32, '/settle_probe', 1)
    wait_for(lambda: watcher.node.count_publishers('/settle_probe') == 1, 10, 'first publisher')
    before = observer._fingerprint(watcher.node)
    second = watcher.node.create_publisher(Float32, '/settle_probe', 1)
    try:
        wait_for(lambda: observer._fingerprint(watcher.node) != before, 10,
                 'the fingerprint to change with the second publisher')
    finally:
        watcher.node.destroy_publisher(second)
        watcher.node.destroy_publisher(first)
