"""Checks of lesson 6.5 (Namespaces and remapping).

They start the student's launch file the way a terminal would and judge the
running graph: which nodes run in which namespace, and which topics each node
really publishes and reads after its namespace and remappings were applied.
Never the text of the file, so any valid way of writing it passes.
"""
from __future__ import annotations

from labkit.checks.ch06_03 import parameter_is, parameters_of
from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

TWO_SENSORS_FILE = 'ex65_two_sensors.launch.py'
SENSORS = {'front': '/front/sensor_publisher', 'rear': '/rear/sensor_publisher'}
PROCESSOR = '/data_processor'
MERGED = '/ranges'
TWO_ROBOTS_FILE = 'ex65_two_robots.launch.py'
ROBOTS_CONFIG = 'ex65_robots.yaml'
ROBOT_NAMES = {'robot1': 'alpha', 'robot2': 'bravo'}
ROBOT_SPEED = 0.8
PIPELINE = ('sensor_publisher', 'data_processor', 'robot_controller')


def published_by(run: LaunchProbe, node: str) -> list[str]:
    """Topics `node` publishes (the graph's view, after namespace and remappings)."""
    topics = run.snapshot.topics.values() if run.snapshot else ()
    return sorted(topic.name for topic in topics if node in topic.publishers)


def read_by(run: LaunchProbe, node: str) -> list[str]:
    """Topics `node` subscribes to."""
    topics = run.snapshot.topics.values() if run.snapshot else ()
    return sorted(topic.name for topic in topics if node in topic.subscribers)


def _sensor_hint(namespace: str, topics: list[str]) -> str:
    """What to do, judged from where the sensor's readings went instead."""
    fix = f"remappings=[('distance', '{MERGED}')]"
    if f'/{namespace}/distance' in topics:
        return (f"its remapping matched nothing, and launch and ROS ignore such a rule without "
                f"a word. The first name of a remapping is the name in the node's code, "
                f"'distance', resolved in the node's namespace (/{namespace}/distance); "
                f"'/distance' names another topic. Write {fix}")
    if f'/{namespace}/ranges' in topics:
        return ("'ranges' is a relative name, so the namespace is put in front of it; "
                f"only an absolute name (with a leading /) leaves the namespace: {fix}")
    return f'give the sensor {fix}'


def _sensor_publishes_merged(verdict: Verdict, run: LaunchProbe, namespace: str) -> None:
    sensor = SENSORS[namespace]
    topics = published_by(run, sensor)
    verdict.expect(topics == [MERGED], f'{sensor} publishes {MERGED}',
                   f'{sensor} publishes {", ".join(topics) or "nothing"} instead of {MERGED}: '
                   + _sensor_hint(namespace, topics))


def _processor_reads_merged(verdict: Verdict, run: LaunchProbe) -> None:
    topics = read_by(run, PROCESSOR)
    hint = f"give it remappings=[('distance', '{MERGED}')] as well"
    if '/distance' in topics:
        hint = ('remapping the sensors does not change the processor: it still reads the name '
                'in its code, distance, which is /distance in no namespace; ' + hint)
    verdict.expect(topics == [MERGED], f'{PROCESSOR} reads {MERGED}',
                   f'{PROCESSOR} reads {", ".join(topics) or "nothing"} instead of {MERGED}: '
                   + hint)


def check_two_sensors(package: StudentPackage, verdict: Verdict) -> Verdict:
    """/front and /rear sensors both publish /ranges, which /data_processor reads."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, TWO_SENSORS_FILE, (*SENSORS.values(), PROCESSOR))
    if not requirements.launch_ran(verdict, run):
        return verdict
    for namespace, sensor in SENSORS.items():
        if requirements.node_running(
                verdict, run, sensor,
                f"start Node(package='my_robot_pkg', executable='sensor_publisher', "
                f"namespace='{namespace}', ...): namespace= puts the node into /{namespace}, "
                f"name= would rename it"):
            _sensor_publishes_merged(verdict, run, namespace)
    if requirements.node_running(verdict, run, PROCESSOR,
                                 "start Node(package='my_robot_pkg', executable='data_processor', "
                                 '...) with no namespace'):
        _processor_reads_merged(verdict, run)
    requirements.names_unique(verdict, run)
    return verdict


def _robot_nodes(namespace: str) -> tuple[str, ...]:
    return tuple(f'/{namespace}/{node}' for node in PIPELINE)


def _namespace_of(name: str) -> str:
    """'/robot1/distance' -> 'robot1'; '/distance' -> ''."""
    parts = name.strip('/').split('/')
    return parts[0] if len(parts) > 1 else ''


def _robots_running(verdict: Verdict, run: LaunchProbe) -> bool:
    nested = [node for node in run.nodes if node.startswith('/robot1/robot2/')]
    hint = ('each robot is a GroupAction([PushROSNamespace(...), Node(...), ...]), so that '
            'the namespace ends with its group')
    if nested:
        hint = (f'robot2 landed inside robot1 ({nested[0]}): a PushROSNamespace outside a '
                'GroupAction stays in force for everything after it; ' + hint)
    ok = True
    for namespace in ROBOT_NAMES:
        for node in _robot_nodes(namespace):
            ok = requirements.node_running(verdict, run, node, hint) and ok
    return ok


def _robots_apart(verdict: Verdict, run: LaunchProbe) -> None:
    """Each robot's chain inside its namespace, and no topic shared between robots."""
    for namespace in ROBOT_NAMES:
        sensor, processor, controller = _robot_nodes(namespace)
        requirements.topic_link(verdict, run, f'/{namespace}/distance', sensor, processor)
        requirements.topic_link(verdict, run, f'/{namespace}/distance_filtered', processor,
                                controller)
    topics = run.snapshot.topics.values() if run.snapshot else ()
    for topic in topics:
        robots = sorted({_namespace_of(node) for node in (*topic.publishers,
                                                             *topic.subscribers)})
        if len(robots) > 1:
            verdict.fail(f'{topic.name} is shared by the robots (published by '
                         f'{", ".join(topic.publishers) or "nobody"}, read by '
                         f'{", ".join(topic.subscribers) or "nobody"}): a name with a leading '
                         '/ is absolute and leaves the namespace; keep every topic name '
                         'relative, so each robot gets its own')


def _settings(verdict: Verdict, run: LaunchProbe) -> None:
    source = f'from config/{ROBOTS_CONFIG}'
    for namespace, robot_name in ROBOT_NAMES.items():
        controller = f'/{namespace}/robot_controller'
        got = (run.inspected or {}).get(controller) or {}
        if got.get('robot_name') == 'my_robot':
            fix = (f'no section of the file reached {controller}: pass the installed '
                   f"config/{ROBOTS_CONFIG} in its parameters=[...], and key its section "
                   f"'{controller}:' (a bare 'robot_controller:' means /robot_controller, a "
                   'node in no namespace)')
        else:
            fix = (f"a section that also matches the other robot's controller (such as "
                   f"'/**/robot_controller:') gives both the same values; key one section "
                   f"'{controller}:' per robot")
        parameter_is(verdict, run, controller, 'robot_name', robot_name, source, fix)
        parameter_is(verdict, run, controller, 'max_linear_speed', ROBOT_SPEED, source,
                     f'set max_linear_speed: {ROBOT_SPEED} in its section')


def check_two_robots(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Two robots in /robot1 and /robot2, kept apart, configured by one parameter file."""
    if not requirements.files_installed(verdict, package):
        return verdict
    controllers = tuple(f'/{namespace}/robot_controller' for namespace in ROBOT_NAMES)
    expected = tuple(node for namespace in ROBOT_NAMES for node in _robot_nodes(namespace))
    run = probe(package, TWO_ROBOTS_FILE, expected, inspect=parameters_of(controllers))
    if not requirements.launch_ran(verdict, run):
        return verdict
    if _robots_running(verdict, run):
        _robots_apart(verdict, run)
        _settings(verdict, run)
    requirements.names_unique(verdict, run)
    return verdict


EXERCISES = (
    Exercise('ex65_two_sensors', 'Exercise 6.5.1 (two namespaced sensors, one processor)',
             ('launch/' + TWO_SENSORS_FILE,), check_two_sensors),
    Exercise('ex65_two_robots', 'Exercise 6.5.2 (two robots, one parameter file)',
             ('launch/' + TWO_ROBOTS_FILE, 'config/' + ROBOTS_CONFIG), check_two_robots),
)
