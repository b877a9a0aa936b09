"""labkit.draw_graph: the geometry of the rendered picture.

Snapshots are built directly (no ROS running); each figure is rendered with
Agg and measured in display pixels: shapes must not overlap, labels must sit
inside their shapes, arrows must run from shape to shape without crossing
any label, and the figure must fit a notebook's width.  Namespace boxes
(and their labels) are kept apart from the shapes here and checked in
test_graph_namespaces.py.
"""
from __future__ import annotations

import random
from dataclasses import dataclass, field

import numpy as np
import pytest
from labkit.drawing import FONT_SIZES, MAX_WIDTH, draw_graph
from labkit.graph import GraphSnapshot, Topic
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from matplotlib.path import Path
from matplotlib.text import Annotation, Text

NOTEBOOK_WIDTH = 10.0  # inches; a lesson's figure must not be scaled down below this
REACH = 5.0  # pixels between an arrow's end and its shape's outline, at most (stroke, gap)


def topic(name: str, type_: str, publishers: tuple[str, ...] = (),
          subscribers: tuple[str, ...] = ()) -> Topic:
    return Topic(name, (type_,), publishers, subscribers)


def snapshot(*topics: Topic, extra_nodes: tuple[str, ...] = ()) -> GraphSnapshot:
    nodes = set(extra_nodes)
    for t in topics:
        nodes |= set(t.publishers) | set(t.subscribers)
    return GraphSnapshot(tuple(sorted(nodes)), {t.name: t for t in sorted(
        topics, key=lambda t: t.name)})


def three_node_chain() -> GraphSnapshot:
    """The book's robot: sensor -> processor -> controller."""
    return snapshot(
        topic('/distance', 'std_msgs/msg/Float32', ('/sensor_publisher',), ('/data_processor',)),
        topic('/distance_filtered', 'std_msgs/msg/Float32', ('/data_processor',),
              ('/robot_controller',)),
        topic('/cmd_vel', 'geometry_msgs/msg/Twist', ('/robot_controller',)))


def fan_out_fan_in() -> GraphSnapshot:
    """Ten nodes: one camera, eight workers reading it, one aggregator reading them all."""
    workers = tuple(f'/detector_{i}' for i in range(1, 9))
    return snapshot(
        topic('/image_raw', 'sensor_msgs/msg/Image', ('/camera_driver',), workers),
        *(topic(f'/detections_{i}', 'vision_msgs/msg/Detection2DArray', (worker,),
                ('/aggregator',)) for i, worker in enumerate(workers, start=1)))


def feedback_loop() -> GraphSnapshot:
    """planner -> /plan -> controller -> /odom -> planner: a cycle."""
    return snapshot(
        topic('/scan', 'sensor_msgs/msg/LaserScan', ('/sensor',), ('/planner',)),
        topic('/plan', 'nav_msgs/msg/Path', ('/planner',), ('/controller',)),
        topic('/odom', 'nav_msgs/msg/Odometry', ('/controller',), ('/planner',)),
        topic('/cmd_vel', 'geometry_msgs/msg/Twist', ('/controller',)))


def long_pipeline() -> GraphSnapshot:
    """Twelve filters in a row: far too many columns for one line."""
    stages = [f'/stage_{i:02d}_filter' for i in range(12)]
    return snapshot(*(topic(f'/signal_{i:02d}', 'std_msgs/msg/Float64', (stage,),
                            tuple(stages[i + 1:i + 2])) for i, stage in enumerate(stages)))


def pure_cycle() -> GraphSnapshot:
    """Three nodes in a ring and nothing else: no source where the flow starts."""
    ring = ('/ping', '/pong', '/relay')
    return snapshot(*(topic(f'{a}_out', 'std_msgs/msg/Int32', (a,), (b,))
                      for a, b in zip(ring, ring[1:] + ring[:1], strict=True)))


def reads_its_own_topic() -> GraphSnapshot:
    """A node that subscribes to what it publishes (a loop through one topic),
    next to a sensor feeding it."""
    return snapshot(
        topic('/heartbeat', 'std_msgs/msg/Header', ('/supervisor',), ('/supervisor',)),
        topic('/range', 'sensor_msgs/msg/Range', ('/sensor',), ('/supervisor',)),
        topic('/status', 'std_msgs/msg/String', ('/supervisor',), ('/supervisor', '/logger')))


def long_loop() -> GraphSnapshot:
    """The long pipeline with its last stage feeding the first: wrapped into
    bands, the way back runs from the last band up to the first."""
    pipeline = long_pipeline()
    back = topic('/feedback', 'std_msgs/msg/Float64', ('/stage_11_filter',),
                 ('/stage_00_filter',))
    return snapshot(*pipeline.topics.values(), back)


def robot_stack() -> GraphSnapshot:
    """Twelve nodes, fifteen topics: loops (one through a single topic), a topic
    nobody publishes, namespaces and a node with no topics at all."""
    return snapshot(
        topic('/robot/scan', 'sensor_msgs/msg/LaserScan', ('/robot/lidar_driver',),
              ('/robot/localization', '/robot/obstacle_detector')),
        topic('/robot/imu', 'sensor_msgs/msg/Imu', ('/robot/imu_driver',),
              ('/robot/localization',)),
        topic('/robot/wheel_odom', 'nav_msgs/msg/Odometry', ('/robot/base_driver',),
              ('/robot/localization',)),
        topic('/robot/pose', 'geometry_msgs/msg/PoseStamped', ('/robot/localization',),
              ('/robot/planner', '/robot/controller', '/ui/dashboard')),
        topic('/robot/obstacles', 'std_msgs/msg/Float32MultiArray',
              ('/robot/obstacle_detector',), ('/robot/planner',)),
        topic('/robot/goal', 'geometry_msgs/msg/PoseStamped', ('/ui/dashboard',),
              ('/robot/planner',)),
        topic('/robot/path', 'nav_msgs/msg/Path', ('/robot/planner',),
              ('/robot/controller', '/ui/dashboard')),
        topic('/robot/cmd_vel', 'geometry_msgs/msg/Twist', ('/robot/controller',),
              ('/robot/base_driver', '/robot/safety')),
        topic('/robot/estop', 'std_msgs/msg/Bool', ('/robot/safety',),
              ('/robot/base_driver', '/robot/controller')),
        topic('/robot/status', 'std_msgs/msg/String', ('/robot/controller',),
              ('/ui/dashboard', '/robot/controller')),
        topic('/robot/battery', 'sensor_msgs/msg/BatteryState', ('/robot/base_driver',),
              ('/ui/dashboard',)),
        topic('/robot/map', 'nav_msgs/msg/OccupancyGrid', (), ('/robot/planner',)),
        topic('/diagnostics', 'diagnostic_msgs/msg/DiagnosticArray',
              ('/robot/lidar_driver', '/robot/base_driver'), ('/ui/dashboard',)),
        topic('/robot/heartbeat', 'std_msgs/msg/Header', ('/robot/safety',), ('/watchdog',)),
        topic('/ui/markers', 'visualization_msgs/msg/MarkerArray', ('/robot/planner',), ()),
        extra_nodes=('/robot/parameter_server',))


def random_system(seed: int) -> GraphSnapshot:
    """Up to 12 nodes and 15 topics wired at random (loops, fans, strays), the
    same for the same seed."""
    rng = random.Random(seed)
    nodes = [f'/{rng.choice(["", "robot/", "ns/"])}node_{i}' + 'x' * rng.randint(0, 12)
             for i in range(rng.randint(1, 12))]
    topics = []
    for j in range(rng.randint(0, 15)):
        publishers = rng.sample(nodes, rng.randint(0, min(2, len(nodes))))
        subscribers = rng.sample(nodes, rng.randint(0 if publishers else 1, min(4, len(nodes))))
        topics.append(topic(f'/topic_{j}' + 'y' * rng.randint(0, 10),
                            rng.choice(['std_msgs/msg/Float32', 'sensor_msgs/msg/PointCloud2']),
                            tuple(sorted(publishers)), tuple(sorted(subscribers))))
    return snapshot(*topics, extra_nodes=tuple(nodes))


CASES = {
    'chain': (three_node_chain, False),
    'chain with types': (three_node_chain, True),
    'fan-out/fan-in': (fan_out_fan_in, False),
    'fan-out/fan-in with types': (fan_out_fan_in, True),
    'feedback loop': (feedback_loop, True),
    'long pipeline': (long_pipeline, True),
    'pure cycle': (pure_cycle, False),
    'node reading its own topic': (reads_its_own_topic, True),
    'long loop': (long_loop, True),
    'robot stack': (robot_stack, True),
    'one node': (lambda: GraphSnapshot(('/lonely_node',), {}), False),
    **{f'random system {seed}': (lambda seed=seed: random_system(seed), seed % 2 == 0)
       for seed in range(6)},
}


@dataclass
class Rendered:
    figure: Figure
    shapes: dict[str, Patch]      # vertex name -> its ellipse or box
    labels: dict[str, Text]
    arrows: list[Annotation]
    #: namespace -> its shaded boxes (one per band it is drawn in) and their labels
    boxes: dict[str, list[Patch]] = field(default_factory=dict)
    box_labels: dict[str, list[Text]] = field(default_factory=dict)

    def outline(self, name: str) -> Path:
        """The shape's outline in display pixels."""
        shape = self.shapes[name]
        return shape.get_transform().transform_path(shape.get_path())


def render(figure: Figure) -> Rendered:
    FigureCanvasAgg(figure)
    figure.canvas.draw()
    axes = figure.axes[0]
    texts = axes.texts
    labels = {t.get_text().split('\n')[0]: t for t in texts
              if t.get_text() and not _namespace_gid(t)}
    boxes: dict[str, list[Patch]] = {}
    box_labels: dict[str, list[Text]] = {}
    for patch in axes.patches:
        boxes.setdefault(_namespace_gid(patch), []).append(patch)
    for text in texts:
        if _namespace_gid(text):
            box_labels.setdefault(_namespace_gid(text), []).append(text)
    return Rendered(figure, {name: t.get_bbox_patch() for name, t in labels.items()}, labels,
                    [t for t in texts if isinstance(t, Annotation)], boxes, box_labels)


def _namespace_gid(artist) -> str:
    """The namespace a box or box label is drawn for ('' for anything else)."""
    gid = artist.get_gid() or ''
    return gid.removeprefix('namespace ') if gid.startswith('namespace ') else ''


@pytest.fixture(scope='module', params=list(CASES), ids=list(CASES))
def drawn(request) -> tuple[GraphSnapshot, Rendered]:
    make, show_types = CASES[request.param]
    graph = make()
    return graph, render(draw_graph(graph, show_types=show_types))


def polyline_points(path: Path, step: float = 1.0) -> np.ndarray:
    """Points along `path` (display pixels) no more than `step` apart."""
    points = []
    for polygon in path.to_polygons(closed_only=False):
        for a, b in zip(polygon[:-1], polygon[1:], strict=True):
            count = max(2, int(np.ceil(np.hypot(*(b - a)) / step)) + 1)
            points.append(np.linspace(a, b, count))
    return np.concatenate(points)


def arrow_line(arrow: Annotation) -> Path:
    """The drawn arrow (line and head) in display pixels."""
    patch = arrow.arrow_patch
    return patch.get_transform().transform_path(patch.get_path())


def arrow_parts(arrow: Annotation) -> tuple[Path, Path]:
    """The arrow's line and its head, in display pixels."""
    path = arrow_line(arrow)
    head = np.flatnonzero(path.codes == Path.MOVETO)[1]  # the head follows the line
    return (Path(path.vertices[:head], path.codes[:head]),
            Path(path.vertices[head:], path.codes[head:]))


def arrow_ends(arrow: Annotation) -> tuple[np.ndarray, np.ndarray]:
    """Where the arrow's line starts and where it ends (at the head's tip)."""
    line, _ = arrow_parts(arrow)
    return line.vertices[0], line.vertices[-1]


def depth_inside(outline: Path, points: np.ndarray) -> np.ndarray:
    """How far (pixels) each point lies inside `outline`; 0 for points outside."""
    corners = np.concatenate(outline.to_polygons(closed_only=False))
    a, b = corners[:-1], corners[1:]
    ab = b - a
    t = np.clip(((points[:, None, :] - a) * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-9),
                0, 1)
    nearest = a + t[..., None] * ab
    distance = np.hypot(*(points[:, None, :] - nearest).transpose(2, 0, 1)).min(axis=1)
    return np.where(outline.contains_points(points), distance, 0.0)


def touches(outline: Path, point: np.ndarray, radius: float) -> bool:
    """Whether some point within `radius` pixels of `point` is inside `outline`."""
    angles = np.linspace(0, 2 * np.pi, 72, endpoint=False)
    around = point + radius * np.column_stack([np.cos(angles), np.sin(angles)])
    return bool(outline.contains_points(around).any())


def test_every_vertex_has_one_shape_and_every_edge_one_arrow(drawn):
    graph, rendered = drawn
    assert set(rendered.shapes) == set(graph.nodes) | set(graph.topics)
    assert len(rendered.arrows) == len(graph.edges())


def test_no_two_shapes_overlap(drawn):
    _, rendered = drawn
    extents = {name: shape.get_window_extent() for name, shape in rendered.shapes.items()}
    names = sorted(extents)
    overlapping = [(a, b) for i, a in enumerate(names) for b in names[i + 1:]
                   if extents[a].overlaps(extents[b])]
    assert overlapping == []


def test_every_label_lies_inside_its_shape(drawn):
    _, rendered = drawn
    renderer = rendered.figure.canvas.get_renderer()
    for name, label in rendered.labels.items():
        box = label.get_window_extent(renderer)
        corners = np.array([[box.x0, box.y0], [box.x0, box.y1], [box.x1, box.y0],
                            [box.x1, box.y1]])
        assert rendered.outline(name).contains_points(corners).all(), name


def test_figure_fits_a_notebook_and_holds_everything(drawn):
    _, rendered = drawn
    width, _ = rendered.figure.get_size_inches()
    assert MAX_WIDTH <= NOTEBOOK_WIDTH
    assert width <= MAX_WIDTH
    page = rendered.figure.bbox
    for name, shape in rendered.shapes.items():
        extent = shape.get_window_extent()
        assert page.x0 <= extent.x0 and extent.x1 <= page.x1, name
        assert page.y0 <= extent.y0 and extent.y1 <= page.y1, name


def test_labels_share_one_readable_size(drawn):
    _, rendered = drawn
    sizes = {label.get_fontsize() for label in rendered.labels.values()}
    assert len(sizes) == 1 and sizes.pop() >= 8


def test_arrows_run_from_shape_to_shape_through_no_label(drawn):
    graph, rendered = drawn
    outlines = {name: rendered.outline(name) for name in rendered.shapes}
    pixels_per_point = rendered.figure.dpi / 72
    drawn_edges = set()
    for arrow in rendered.arrows:
        start, tip = arrow_ends(arrow)
        source = [name for name, outline in outlines.items() if touches(outline, start, REACH)]
        target = [name for name, outline in outlines.items() if touches(outline, tip, REACH)]
        assert len(source) == 1 and len(target) == 1, (source, target)
        drawn_edges.add((source[0], target[0]))
        line, head = (polyline_points(part) for part in arrow_parts(arrow))
        for name, outline in outlines.items():
            assert not outline.contains_points(line).any(), \
                f'arrow {source[0]} -> {target[0]} runs through {name}'
            # the head may overlap its target's outline stroke, never the inside
            allowed = rendered.shapes[name].get_linewidth() * pixels_per_point / 2 \
                if name == target[0] else 0.0
            assert depth_inside(outline, head).max() <= allowed, \
                f'the head of {source[0]} -> {target[0]} cuts into {name}'
    assert drawn_edges == set(graph.edges())


def test_a_loop_is_drawn_with_its_way_back():
    rendered = render(draw_graph(feedback_loop(), show_types=True))
    centre = {name: shape.get_window_extent() for name, shape in rendered.shapes.items()}
    # the flow runs left to right, so the way back from /odom to /planner points left
    assert centre['/planner'].x1 < centre['/plan'].x0 < centre['/controller'].x0 \
        < centre['/odom'].x0
    back = [arrow for arrow in rendered.arrows
            if touches(rendered.outline('/odom'), arrow_ends(arrow)[0], REACH)]
    assert len(back) == 1
    points = polyline_points(arrow_line(back[0]))
    assert np.ptp(points[:, 0]) > centre['/plan'].width  # runs back past /plan
    assert np.ptp(points[:, 1]) > 5  # and curves around it rather than straight through


def test_too_many_columns_wrap_downwards_instead_of_widening():
    rendered = render(draw_graph(long_pipeline(), show_types=True))
    width, height = rendered.figure.get_size_inches()
    assert width <= MAX_WIDTH
    rows = {round(shape.get_window_extent().y0) for shape in rendered.shapes.values()}
    assert len(rows) >= 3 and height > 2
    first, last = rendered.shapes['/stage_00_filter'], rendered.shapes['/stage_11_filter']
    assert first.get_window_extent().y0 > last.get_window_extent().y1  # flow continues below


def test_a_small_graph_keeps_the_larger_font_and_one_row():
    rendered = render(draw_graph(three_node_chain()))
    assert {label.get_fontsize() for label in rendered.labels.values()} == {max(FONT_SIZES)}
    ys = {round(shape.get_window_extent().y0) for shape in rendered.shapes.values()
          if shape.get_boxstyle().__class__.__name__ == 'Ellipse'}
    assert len(ys) == 1


def test_drawing_is_deterministic():
    def geometry() -> list:
        rendered = render(draw_graph(robot_stack(), show_types=True))
        shapes = [(name, tuple(np.round(shape.get_window_extent().bounds, 3)))
                  for name, shape in sorted(rendered.shapes.items())]
        arrows = [np.round(arrow_line(arrow).vertices, 3).tolist()
                  for arrow in rendered.arrows]
        return [tuple(rendered.figure.get_size_inches()), shapes, arrows]

    assert geometry() == geometry()


def test_an_empty_graph_says_so():
    figure = draw_graph(GraphSnapshot((), {}), title='nothing running')
    assert [t.get_text() for t in figure.axes[0].texts] == ['no nodes in the graph']
    assert figure.axes[0].get_title() == 'nothing running'
