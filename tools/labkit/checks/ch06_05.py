"""Checks of lesson 6.5 (Namespaces and remapping).

They start the student's launch file the way a terminal would and judge the
running graph: which nodes run in which namespace, and which topics each node
really publishes and reads after its namespace and remappings were applied.
Never the text of the file, so any valid way of writing it passes.
"""
from __future__ import annotations

from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

TWO_SENSORS_FILE = 'ex65_two_sensors.launch.py'
SENSORS = {'front': '/front/sensor_publisher', 'rear': '/rear/sensor_publisher'}
PROCESSOR = '/data_processor'
MERGED = '/ranges'


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
        hint = ("remapping the sensors does not change the processor: it still reads the name "
                "in its code, distance, which is /distance in no namespace; " + hint)
    verdict.expect(topics == [MERGED], f'{PROCESSOR} reads {MERGED}',
                   f'{PROCESSOR} reads {", ".join(topics) or "nothing"} instead of {MERGED}: '
                   + hint)


def check_two_sensors(package: StudentPackage) -> Verdict:
    """/front and /rear sensors both publish /ranges, which /data_processor reads."""
    verdict = Verdict('Exercise 6.5.1 (two namespaced sensors, one processor)')
    if not requirements.files_installed(verdict, package, ('launch/' + TWO_SENSORS_FILE,)):
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


EXERCISES = (
    Exercise('ex65_two_sensors', 'Exercise 6.5.1 (two namespaced sensors, one processor)',
             ('launch/' + TWO_SENSORS_FILE,), check_two_sensors),
)
