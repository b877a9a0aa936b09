"""Checks of lesson 6.7 (Debugging a multi-node system): a broken launch file,
fixed so that the data flows.  Judged on the running graph, the launch log
and the messages that arrive, never on the text of the file."""
from __future__ import annotations

from labkit.grading import requirements
from labkit.grading.exercise import Exercise
from labkit.grading.launch_probe import LaunchProbe, probe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict
from labkit.graph import GraphSnapshot
from labkit.rates import measure_rates

PIPELINE_FILE = 'ex67_fix_pipeline.launch.py'
NODES = ('/sensor_publisher', '/data_processor')
#: A node in another ROS_DOMAIN_ID never shows up, so the probe cannot tell
#: "up" from "still starting" and waits this long at most.
PROBE_TIMEOUT = 15.0
#: How long to count the filtered readings (the sensor publishes at 2 Hz).
FLOW_WINDOW = 3.0


def _filtered_readings(_snapshot: GraphSnapshot) -> int:
    """How many messages arrive on /distance_filtered while the launch runs."""
    return measure_rates({'/distance_filtered': 'std_msgs/msg/Float32'},
                         window=FLOW_WINDOW)['/distance_filtered'].count


def _in_graph_or_elsewhere(verdict: Verdict, run: LaunchProbe, node: str) -> None:
    """`node` is in the graph; if its process logs but it is not, say where it went."""
    if node in run.nodes:
        verdict.expect(True, f'{node} is in the graph', '')
    elif node in run.node_processes:
        verdict.fail(f'{node} runs (the launch log shows its lines from '
                     f'{", ".join(run.node_processes[node])}) but is not in this graph: it is '
                     'in another ROS_DOMAIN_ID. Remove the additional_env that sets '
                     'ROS_DOMAIN_ID, so it joins the domain of the launch')
    else:
        requirements.node_running(verdict, run, node,
                                  f"start it with Node(package='my_robot_pkg', "
                                  f"executable='{node.lstrip('/')}')")


def check_fix_pipeline(package: StudentPackage, verdict: Verdict) -> Verdict:
    """Both nodes in the launch's domain, /distance linking them, readings filtered."""
    if not requirements.files_installed(verdict, package):
        return verdict
    run = probe(package, PIPELINE_FILE, NODES, timeout=PROBE_TIMEOUT,
                inspect=_filtered_readings)
    if not requirements.launch_ran(verdict, run):
        return verdict
    for node in NODES:
        _in_graph_or_elsewhere(verdict, run, node)
    requirements.topic_link(verdict, run, '/distance', '/sensor_publisher', '/data_processor')
    readings = run.inspected or 0
    verdict.expect(readings > 0,
                   f'filtered readings arrive on /distance_filtered ({readings} in '
                   f'{FLOW_WINDOW:g} s)',
                   f'no message arrived on /distance_filtered in {FLOW_WINDOW:g} s: the filter '
                   'receives no readings; `ros2 topic info -v /distance` and `ros2 node list` '
                   'show why')
    return verdict


EXERCISES = (
    Exercise('ex67_fix_pipeline', 'Exercise 6.7.1 (make the data flow)',
             ('launch/' + PIPELINE_FILE,), check_fix_pipeline),
)
