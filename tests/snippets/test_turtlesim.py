"""The headless turtlesim against turtlesim's documented behaviour: its topics,
services, parameters and action, its motion (a command holds one second),
its walls, spawn/kill errors, pens, teleports, and the picture it draws."""
from __future__ import annotations

import math
import re

import pytest
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import GetParameters, ListParameters, SetParameters
from rclpy.action import ActionClient
from std_srvs.srv import Empty
from textbook import workspace

from ._turtlesim_client import SimClient, load_turtlesim_interfaces
from .test_nodes import NodeProcess

INSTALL = workspace.ensure_built()
if not (INSTALL / 'turtlesim/share/turtlesim/HEADLESS').is_file():
    pytest.skip('a real turtlesim is installed; the headless one is not built',
                allow_module_level=True)
load_turtlesim_interfaces(INSTALL)

from turtlesim.action import RotateAbsolute  # noqa: E402
from turtlesim.msg import Color, Pose  # noqa: E402
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative  # noqa: E402
from turtlesim_headless.canvas import to_pixel  # noqa: E402
from turtlesim_headless.canvas_file import wait_for_canvas  # noqa: E402

WORLD = 11.088889  # metres: (500 - 1) px / 45 px per metre, in float32
CENTRE = 5.544445
BACKGROUND = (69, 86, 255)
PEN = (179, 184, 255)


@pytest.fixture
def sim(ros_env, tmp_path):
    """A turtlesim_node of the workspace, drawing into tmp_path/canvas.png."""
    env = dict(ros_env, TURTLESIM_CANVAS_PNG=str(tmp_path / 'canvas.png'))
    node = NodeProcess(env, 'turtlesim', 'turtlesim_node')
    node.canvas = tmp_path / 'canvas.png'
    started = node.wait_until(lambda lines: any('Spawning turtle [turtle1]' in x for x in lines))
    assert started, node.output
    yield node
    assert node.stop() == 0, node.output
    assert 'Traceback' not in node.output, node.output


@pytest.fixture
def client():
    ros = SimClient()
    ros.watch(Pose, '/turtle1/pose')
    ros.watch(Color, '/turtle1/color_sensor')
    yield ros
    ros.close()


def log_lines(node: NodeProcess, level: str, text: str) -> list[str]:
    """Lines ``[LEVEL] [<stamp>] [turtlesim]: <text>`` of the node's output."""
    pattern = re.compile(rf'^\[{level}\] \[\d+\.\d+\] \[turtlesim\]: {re.escape(text)}$')
    return [line for line in node.lines if pattern.match(line)]


def wait_for_log(node: NodeProcess, level: str, text: str) -> None:
    assert node.wait_until(lambda _: log_lines(node, level, text)), node.output


def pixel(image, x: float, y: float) -> tuple[int, int, int]:
    px, py = to_pixel(x, y)
    return image.getpixel((round(px), round(py)))


def stopped_after_moving(start: Pose):
    """A pose that has moved away from ``start`` and whose command has run out."""
    def check(pose: Pose) -> bool:
        moved = math.dist((pose.x, pose.y), (start.x, start.y)) > 0.05 \
            or abs(pose.theta - start.theta) > 0.05
        return moved and pose.linear_velocity == 0.0 and pose.angular_velocity == 0.0
    return check


def test_starts_like_turtlesim(sim):
    assert log_lines(sim, 'INFO', 'Starting turtlesim with node name /turtlesim')
    assert log_lines(
        sim, 'INFO', 'Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], theta=[0.000000]')


def test_topics_services_and_action_of_turtle1(sim, client):
    expected = {
        '/turtle1/cmd_vel': 'geometry_msgs/msg/Twist',
        '/turtle1/pose': 'turtlesim/msg/Pose',
        '/turtle1/color_sensor': 'turtlesim/msg/Color',
    }
    topics = client.spin_until(
        lambda: (t := client.topics()) and all(name in t for name in expected) and t,
        "turtle1's topics")
    assert {name: topics[name][0] for name in expected} == expected
    expected = {
        '/spawn': 'turtlesim/srv/Spawn', '/kill': 'turtlesim/srv/Kill',
        '/clear': 'std_srvs/srv/Empty', '/reset': 'std_srvs/srv/Empty',
        '/turtle1/set_pen': 'turtlesim/srv/SetPen',
        '/turtle1/teleport_absolute': 'turtlesim/srv/TeleportAbsolute',
        '/turtle1/teleport_relative': 'turtlesim/srv/TeleportRelative',
        '/turtle1/rotate_absolute/_action/send_goal':
            'turtlesim/action/RotateAbsolute_SendGoal',
    }
    services = client.spin_until(
        lambda: (s := client.services()) and all(name in s for name in expected) and s,
        "turtlesim's services")
    assert {name: services[name][0] for name in expected} == expected


def test_first_pose_is_the_centre_and_the_background_is_a_parameter(sim, client):
    pose = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    assert (pose.x, pose.y, pose.theta) == pytest.approx((CENTRE, CENTRE, 0.0), abs=1e-5)
    names = ['background_r', 'background_g', 'background_b', 'holonomic']
    values = client.call(GetParameters, '/turtlesim/get_parameters', names=names).values
    assert [v.integer_value for v in values[:3]] == list(BACKGROUND)
    assert values[3].type == ParameterType.PARAMETER_BOOL and values[3].bool_value is False
    color = client.wait_for('/turtle1/color_sensor', lambda c: True, 'a colour')
    assert (color.r, color.g, color.b) == BACKGROUND


def test_parameters_are_those_ros2_param_list_shows_for_turtlesim(sim, client):
    names = client.call(ListParameters, '/turtlesim/list_parameters').result.names
    assert sorted(names) == [
        'background_b', 'background_g', 'background_r', 'holonomic',
        'qos_overrides./parameter_events.publisher.depth',
        'qos_overrides./parameter_events.publisher.durability',
        'qos_overrides./parameter_events.publisher.history',
        'qos_overrides./parameter_events.publisher.reliability',
        'start_type_description_service', 'use_sim_time']


def test_a_command_drives_straight_for_one_second(sim, client):
    start = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    client.drive('turtle1', linear=1.0)
    moving = client.wait_for('/turtle1/pose', lambda p: p.linear_velocity == 1.0, 'motion')
    assert moving.angular_velocity == 0.0
    end = client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    assert end.x - start.x == pytest.approx(1.0, abs=0.1)  # 1 m/s held for 1 s
    assert (end.y, end.theta) == pytest.approx((start.y, start.theta), abs=1e-4)
    # The turtle stands on its own trail.
    client.wait_for('/turtle1/color_sensor', lambda c: (c.r, c.g, c.b) == PEN, 'the pen colour')


def test_a_command_turns_on_the_spot(sim, client):
    start = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    client.drive('turtle1', angular=1.0)
    end = client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    assert end.theta == pytest.approx(1.0, abs=0.1)
    assert (end.x, end.y) == pytest.approx((start.x, start.y), abs=1e-4)


def test_a_holonomic_turtle_moves_sideways(sim, client):
    start = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    client.drive('turtle1', linear=1.0, lateral=1.0)  # not holonomic: sideways is ignored
    middle = client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    assert (middle.x - start.x, middle.y - start.y) == pytest.approx((1.0, 0.0), abs=0.1)
    value = ParameterValue(type=ParameterType.PARAMETER_BOOL, bool_value=True)
    result = client.call(SetParameters, '/turtlesim/set_parameters',
                         parameters=[Parameter(name='holonomic', value=value)])
    assert result.results[0].successful
    client.drive('turtle1', linear=1.0, lateral=1.0)
    end = client.wait_for('/turtle1/pose', stopped_after_moving(middle), 'the stop')
    assert (end.x - middle.x, end.y - middle.y) == pytest.approx((1.0, 1.0), abs=0.1)
    assert end.theta == pytest.approx(start.theta, abs=1e-4)


def test_the_wall_stops_the_turtle_with_a_warning(sim, client):
    client.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=10.5, y=3.0, theta=0.0)
    start = client.wait_for('/turtle1/pose', lambda p: p.x == pytest.approx(10.5), 'teleport')
    client.drive('turtle1', linear=2.0)
    end = client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    assert (end.x, end.y) == pytest.approx((WORLD, 3.0), abs=1e-4)
    warning = re.compile(r'^\[WARN\] \[\d+\.\d+\] \[turtlesim\]: Oh no! I hit the wall! '
                         r'\(Clamping from \[x=11\.\d{6}, y=3\.000000\]\)$')
    assert sim.wait_until(lambda lines: any(warning.match(line) for line in lines)), sim.output


def test_spawn_names_turtles_and_refuses_a_taken_name(sim, client):
    named = client.call(Spawn, '/spawn', x=2.0, y=2.0, theta=0.2, name='')
    assert named.name == 'turtle2'
    wait_for_log(sim, 'INFO', 'Spawning turtle [turtle2] at x=[2.000000], y=[2.000000], '
                 'theta=[0.200000]')
    client.watch(Pose, '/turtle2/pose')
    pose = client.wait_for('/turtle2/pose', lambda p: True, "turtle2's pose")
    assert (pose.x, pose.y, pose.theta) == pytest.approx((2.0, 2.0, 0.2), abs=1e-5)
    assert client.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='leo').name == 'leo'

    client.call(Kill, '/kill', name='turtle2')
    assert client.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='').name == 'turtle3'

    taken = client.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='turtle1')
    assert taken.name == ''
    wait_for_log(sim, 'ERROR', 'Tried to spawn turtle [turtle1], which already exists')


def test_a_turtle_spawned_outside_is_put_on_the_wall(sim, client):
    assert client.call(Spawn, '/spawn', x=20.0, y=4.0, theta=0.0, name='far').name == 'far'
    client.watch(Pose, '/far/pose')
    pose = client.wait_for('/far/pose', lambda p: True, "far's pose")
    assert (pose.x, pose.y) == pytest.approx((WORLD, 4.0), abs=1e-4)
    wait_for_log(sim, 'WARN', 'Oh no! I hit the wall! (Clamping from [x=20.000000, y=4.000000])')


def test_kill_removes_a_turtle_and_names_a_missing_one(sim, client):
    client.call(Spawn, '/spawn', x=2.0, y=2.0, theta=0.0, name='turtle2')
    client.spin_until(lambda: '/turtle2/pose' in client.topics(), "turtle2's topics")
    client.call(Kill, '/kill', name='turtle2')
    client.spin_until(lambda: '/turtle2/set_pen' not in client.services(),
                      "turtle2's services to go")
    client.call(Kill, '/kill', name='nobody')
    wait_for_log(sim, 'ERROR', 'Tried to kill turtle [nobody], which does not exist')


def test_teleports_draw_with_the_pen_unless_it_is_off(sim, client):
    client.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=2.0, y=CENTRE, theta=0.0)
    client.call(SetPen, '/turtle1/set_pen', r=255, g=0, b=0, width=5, off=1)
    client.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=2.0, y=9.0, theta=math.pi / 2)
    client.call(SetPen, '/turtle1/set_pen', r=255, g=0, b=0, width=5, off=0)
    # Turn first (to heading 0), then move along the new heading.
    client.call(TeleportRelative, '/turtle1/teleport_relative', linear=3.0, angular=-math.pi / 2)
    pose = client.wait_for('/turtle1/pose', lambda p: p.y > 8.0 and p.x > 4.0,
                           'the relative teleport')
    assert (pose.x, pose.y, pose.theta) == pytest.approx((5.0, 9.0, 0.0), abs=1e-4)

    picture = wait_for_canvas(path=sim.canvas)
    assert pixel(picture, 4.0, CENTRE) == PEN  # default pen, centre -> (2, 5.54)
    assert pixel(picture, 2.0, 7.5) == BACKGROUND  # pen off on the way up
    assert pixel(picture, 3.5, 9.0) == (255, 0, 0)  # red pen to the right


def test_the_picture_shows_the_turtle_where_it_moved(sim, client):
    before = wait_for_canvas(path=sim.canvas)
    start = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    assert pixel(before, CENTRE, CENTRE) != BACKGROUND  # the turtle
    assert pixel(before, CENTRE + 1.5, CENTRE) == BACKGROUND

    client.drive('turtle1', linear=2.0)
    end = client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    after = wait_for_canvas(path=sim.canvas)
    assert after.tobytes() != before.tobytes()
    assert pixel(after, end.x, end.y) != PEN  # the turtle on top of its trail
    assert pixel(after, (start.x + end.x) / 2, CENTRE) == PEN
    assert pixel(after, CENTRE, CENTRE + 1.0) == BACKGROUND


def test_clear_reset_and_the_background_parameter(sim, client):
    start = client.wait_for('/turtle1/pose', lambda p: True, 'a pose')
    client.call(Spawn, '/spawn', x=2.0, y=2.0, theta=0.0, name='turtle2')
    client.drive('turtle1', linear=2.0)
    client.wait_for('/turtle1/pose', stopped_after_moving(start), 'the stop')
    assert pixel(wait_for_canvas(path=sim.canvas), CENTRE + 1.0, CENTRE) == PEN

    client.call(Empty, '/clear')
    wait_for_log(sim, 'INFO', 'Clearing turtlesim.')
    assert pixel(wait_for_canvas(path=sim.canvas), CENTRE + 1.0, CENTRE) == BACKGROUND

    value = ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=150)
    result = client.call(SetParameters, '/turtlesim/set_parameters',
                         parameters=[Parameter(name='background_r', value=value)])
    assert result.results[0].successful
    assert pixel(wait_for_canvas(path=sim.canvas), 0.5, 0.5) == (150, 86, 255)

    client.call(Empty, '/reset')
    wait_for_log(sim, 'INFO', 'Resetting turtlesim.')
    client.spin_until(lambda: '/turtle2/pose' not in client.topics(), 'turtle2 to go')
    pose = client.wait_for('/turtle1/pose', lambda p: abs(p.x - CENTRE) < 1e-4, 'turtle1 back')
    assert (pose.y, pose.theta) == pytest.approx((CENTRE, 0.0), abs=1e-5)


def test_rotate_absolute_turns_to_a_heading(sim, client):
    action = ActionClient(client.node, RotateAbsolute, '/turtle1/rotate_absolute')
    client.spin_until(action.server_is_ready, 'the rotate_absolute action')
    feedback = []
    sent = action.send_goal_async(RotateAbsolute.Goal(theta=1.5),
                                  feedback_callback=lambda f: feedback.append(f.feedback))
    goal = client.spin_until(lambda: sent.done() and sent.result(), 'goal acceptance')
    assert goal.accepted
    finished = goal.get_result_async()
    result = client.spin_until(lambda: finished.done() and finished.result(), 'the result')
    assert result.result.delta == pytest.approx(1.5, abs=0.05)
    assert feedback and feedback[0].remaining > feedback[-1].remaining
    pose = client.wait_for('/turtle1/pose', lambda p: p.angular_velocity == 0.0, 'the stop')
    assert pose.theta == pytest.approx(1.5, abs=0.05)
    action.destroy()
