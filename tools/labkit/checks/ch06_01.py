"""Checks of lesson 6.1 (Anatomy of a launch file): Node(package, executable,
name, output).  They judge the running graph and the launch log, never the
text of the file, so any valid way of writing it passes."""
from __future__ import annotations

from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

PIPELINE_FILE = 'ex61_full_pipeline.launch.py'
FRONT_SENSOR_FILE = 'ex61_front_sensor.launch.py'
PIPELINE = ('/sensor_publisher', '/data_processor', '/robot_controller')


def _start_it(node: str, executable: str) -> str:
    return (f"start it with Node(package='my_robot_pkg', executable='{executable}', "
            f"name='{node.lstrip('/')}', output='screen')")


def check_full_pipeline(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Three nodes, and the data flows sensor -> processor -> controller -> /cmd_vel."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, PIPELINE_FILE, PIPELINE)
    if not requirements.launch_ran(verdict, run):
        return verdict
    for node in PIPELINE:
        requirements.node_running(verdict, run, node, _start_it(node, node.lstrip('/')))
    requirements.names_unique(verdict, run)
    requirements.topic_link(verdict, run, '/distance', '/sensor_publisher', '/data_processor')
    requirements.topic_link(verdict, run, '/distance_filtered', '/data_processor',
                            '/robot_controller')
    publishers = run.publishers('/cmd_vel')
    verdict.expect(publishers == ('/robot_controller',), '/robot_controller publishes /cmd_vel',
                   f'/cmd_vel should be published by /robot_controller alone; it is published '
                   f'by {", ".join(publishers) or "nobody"}')
    return verdict


def check_front_sensor(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The program sensor_publisher runs once, as the node /front_sensor, feeding the processor."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, FRONT_SENSOR_FILE, ('/front_sensor', '/data_processor'))
    if not requirements.launch_ran(verdict, run):
        return verdict
    if requirements.node_running(verdict, run, '/front_sensor',
                                 "give the sensor's Node action name='front_sensor'"):
        programs = run.node_processes.get('/front_sensor', [])
        verdict.expect(
            programs and all(p.startswith('sensor_publisher-') for p in programs),
            f'the launch log shows /front_sensor as the program sensor_publisher '
            f'({", ".join(programs)})',
            f'/front_sensor is run by {", ".join(programs) or "a process that logs nothing"}: '
            "executable= stays 'sensor_publisher', only name= changes")
    verdict.expect('/sensor_publisher' not in run.nodes, '/sensor_publisher is gone from the graph',
                   '/sensor_publisher is still in the graph: the sensor must run under the name '
                   'front_sensor only')
    requirements.names_unique(verdict, run)
    requirements.node_running(verdict, run, '/data_processor',
                              _start_it('/data_processor', 'data_processor'))
    requirements.topic_link(verdict, run, '/distance', '/front_sensor', '/data_processor')
    return verdict


EXERCISES = (
    Exercise('ex61_full_pipeline', 'Exercise 6.1.1 (the whole robot)',
             ('launch/' + PIPELINE_FILE,), check_full_pipeline),
    Exercise('ex61_front_sensor', 'Exercise 6.1.2 (same program, another name)',
             ('launch/' + FRONT_SENSOR_FILE,), check_front_sensor),
)
