"""Graph pictures group nodes by namespace: a shaded, labelled box per namespace.

Two identical robots, each in its namespace, must show as two boxes holding
exactly their own nodes and topics; root-namespace nodes stay outside every
box; a graph without namespaces gets no box; the alt text says how nodes are
grouped.  Rendered with Agg and measured in display pixels, like
test_labkit_drawing.py.
"""
from __future__ import annotations

import numpy as np
import pytest
from labkit.drawing import describe, draw_graph, layout_plan, to_networkx
from labkit.graph import GraphSnapshot
from labkit.graph_namespaces import groups, namespace
from matplotlib.patches import Patch

from tests.tools.test_labkit_drawing import (
    CASES,
    Rendered,
    arrow_line,
    fan_out_fan_in,
    polyline_points,
    render,
    snapshot,
    three_node_chain,
    topic,
)

FLOAT = 'std_msgs/msg/Float32'
TWIST = 'geometry_msgs/msg/Twist'


def two_robots() -> GraphSnapshot:
    """Lesson 6.1.5: the robot's three nodes twice, under /robot1 and /robot2."""
    topics = []
    for robot in ('/robot1', '/robot2'):
        topics += [topic(f'{robot}/distance', FLOAT, (f'{robot}/sensor_publisher',),
                         (f'{robot}/data_processor',)),
                   topic(f'{robot}/distance_filtered', FLOAT, (f'{robot}/data_processor',),
                         (f'{robot}/robot_controller',)),
                   topic(f'{robot}/cmd_vel', TWIST, (f'{robot}/robot_controller',))]
    return snapshot(*topics)


def capstone() -> GraphSnapshot:
    """The capstone's shape: /turtlesim in the root namespace and six nodes per turtle."""
    topics = []
    for t in ('/turtle1', '/turtle2'):
        topics += [
            topic(f'{t}/pose', 'turtlesim/msg/Pose', ('/turtlesim',),
                  (f'{t}/wall_sensor', f'{t}/pose_estimator')),
            topic(f'{t}/wall_reading', 'capstone_interfaces/msg/WallReading',
                  (f'{t}/wall_sensor',), (f'{t}/safety_monitor',)),
            topic(f'{t}/estimated_pose', 'geometry_msgs/msg/PoseStamped',
                  (f'{t}/pose_estimator',), (f'{t}/patrol_planner', f'{t}/controller')),
            topic(f'{t}/goal', 'geometry_msgs/msg/PoseStamped', (f'{t}/patrol_planner',),
                  (f'{t}/controller',)),
            topic(f'{t}/cmd_vel_nav', TWIST, (f'{t}/controller',), (f'{t}/safety_monitor',)),
            topic(f'{t}/cmd_vel', TWIST, (f'{t}/safety_monitor',), ('/turtlesim',)),
            topic(f'{t}/status', 'capstone_interfaces/msg/RobotStatus',
                  (f'{t}/patrol_planner',), (f'{t}/mission_recorder',)),
        ]
    return snapshot(*topics)


def nested() -> GraphSnapshot:
    """Nodes in /a, /a/b and /a/b/c, and one in the root namespace."""
    return snapshot(topic('/a/x', FLOAT, ('/a/n1',), ('/a/b/n2',)),
                    topic('/a/b/y', FLOAT, ('/a/b/n2',), ('/a/b/c/n3', '/top')))


NAMESPACED = {
    'two robots': (two_robots, False),
    'capstone': (capstone, False),
    'capstone with types (wrapped into bands)': (capstone, True),
    'nested namespaces': (nested, False),
    **{name: case for name, case in CASES.items()
       if groups(to_networkx(case[0]()))},
}


@pytest.fixture(scope='module', params=list(NAMESPACED), ids=list(NAMESPACED))
def drawn(request) -> tuple[GraphSnapshot, Rendered]:
    make, show_types = NAMESPACED[request.param]
    graph = make()
    return graph, render(draw_graph(graph, show_types=show_types))


def centre(patch: Patch) -> np.ndarray:
    extent = patch.get_window_extent()
    return np.array([(extent.x0 + extent.x1) / 2, (extent.y0 + extent.y1) / 2])


def inside(box: Patch, point: np.ndarray) -> bool:
    return box.get_window_extent().contains(*point)


def test_the_namespaced_cases_cover_boxes_cut_by_bands():
    figure = render(draw_graph(capstone(), show_types=True))
    assert max(len(boxes) for boxes in figure.boxes.values()) > 1


@pytest.mark.parametrize('make, spaces', [(two_robots, {'/robot1', '/robot2'}),
                                          (capstone, {'/turtle1', '/turtle2'})])
def test_one_box_per_namespace_around_exactly_its_nodes_and_topics(make, spaces):
    graph = make()
    rendered = render(draw_graph(graph))
    assert set(rendered.boxes) == spaces
    assert all(len(boxes) == 1 for boxes in rendered.boxes.values())
    for space, (box,) in rendered.boxes.items():
        held = {name for name, shape in rendered.shapes.items() if inside(box, centre(shape))}
        assert held == {name for name in rendered.shapes if namespace(name) == space}
    assert '/turtlesim' not in {name for name, shape in rendered.shapes.items()
                                for (box,) in rendered.boxes.values()
                                if inside(box, centre(shape))}


def test_two_identical_robots_get_two_identical_boxes_side_by_side():
    rendered = render(draw_graph(two_robots()))
    (first,), (second,) = (rendered.boxes[space] for space in ('/robot1', '/robot2'))
    a, b = first.get_window_extent(), second.get_window_extent()
    assert abs(a.width - b.width) < 1 and abs(a.height - b.height) < 1
    assert a.x1 < b.x0  # /robot1 on the left, as a reader expects


def test_every_box_holds_only_its_namespace_and_every_namespaced_node_a_box(drawn):
    graph, rendered = drawn
    assert set(rendered.boxes) == set(groups(to_networkx(graph)))
    for name, shape in rendered.shapes.items():
        point = centre(shape)
        around = [space for space, boxes in rendered.boxes.items()
                  if any(inside(box, point) for box in boxes)]
        if name in graph.nodes and namespace(name) != '/':
            assert around == [namespace(name)], name
        else:
            assert around in ([], [namespace(name)]), name


def test_boxes_lie_apart_under_the_shapes_and_arrows(drawn):
    _, rendered = drawn
    boxes = [box for boxes in rendered.boxes.values() for box in boxes]
    extents = [box.get_window_extent() for box in boxes]
    assert not any(a.overlaps(b) for i, a in enumerate(extents) for b in extents[i + 1:])
    top = min(artist.get_zorder() for artist in [*rendered.labels.values(), *rendered.arrows])
    assert all(box.get_zorder() < top for box in boxes)


def test_each_box_is_labelled_with_its_namespace_clear_of_shapes(drawn):
    _, rendered = drawn
    renderer = rendered.figure.canvas.get_renderer()
    for space, boxes in rendered.boxes.items():
        labels = rendered.box_labels[space]
        assert [label.get_text() for label in labels] == [space] * len(boxes)
        assert {label.get_fontsize() for label in labels} == {
            next(iter(rendered.labels.values())).get_fontsize()}
        for box, label in zip(boxes, labels, strict=True):
            extent = label.get_window_extent(renderer)
            assert box.get_window_extent().contains(extent.x0, extent.y0)
            assert box.get_window_extent().contains(extent.x1, extent.y1)
            for name, shape in rendered.shapes.items():
                assert not extent.overlaps(shape.get_window_extent()), (space, name)
            # an edge entering from the side may pass there: it runs under the label
            assert all(label.get_zorder() > arrow.get_zorder() for arrow in rendered.arrows)


@pytest.mark.parametrize('make', [two_robots, capstone, nested])
def test_no_arrow_crosses_a_namespace_label_in_the_lessons_graphs(make):
    rendered = render(draw_graph(make()))
    renderer = rendered.figure.canvas.get_renderer()
    for space, labels in rendered.box_labels.items():
        for label in labels:
            extent = label.get_window_extent(renderer)
            for arrow in rendered.arrows:
                assert extent.count_contains(polyline_points(arrow_line(arrow))) == 0, space


@pytest.mark.parametrize('make', [three_node_chain, fan_out_fan_in, CASES['long loop'][0]])
def test_a_graph_without_namespaces_has_no_box(make):
    graph = make()
    rendered = render(draw_graph(graph, show_types=True))
    assert rendered.boxes == {} and rendered.box_labels == {}
    assert layout_plan(to_networkx(graph)).boxes == []
    assert 'namespace' not in rendered.figure.description
    assert 'namespace' not in rendered.figure.caption


def test_root_namespace_nodes_alone_get_no_box():
    graph = to_networkx(snapshot(topic('/robot1/scan', FLOAT, ('/driver',), ('/viewer',))))
    assert groups(graph) == {}


def test_the_alt_text_and_caption_say_how_nodes_are_grouped():
    figure = draw_graph(two_robots())
    assert figure.description.endswith(
        'Nodes grouped by namespace: /robot1 (3 nodes), /robot2 (3 nodes).')
    assert 'each shaded box holds the nodes and topics of one namespace' in figure.caption
    assert describe(to_networkx(capstone())).endswith(
        'Nodes grouped by namespace: /turtle1 (6 nodes), /turtle2 (6 nodes).')


def test_a_node_belongs_to_its_full_namespace():
    assert namespace('/robot1/distance') == '/robot1'
    assert namespace('/a/b/c/n3') == '/a/b/c'
    assert namespace('/turtlesim') == '/'
    assert groups(to_networkx(nested())) == {
        '/a': ['/a/n1', '/a/x'], '/a/b': ['/a/b/n2', '/a/b/y'], '/a/b/c': ['/a/b/c/n3']}
