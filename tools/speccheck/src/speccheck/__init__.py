"""speccheck: check a ROS 2 system against a written spec, statically and running.

A spec (YAML; see :mod:`speccheck.spec` and docs/reference/spec-files.md)
says which nodes, topics, parameters and launch arguments a system must
have.  Two checks compare it with reality:

    import speccheck

    spec = speccheck.load_spec('system.yaml')
    report = speccheck.check_static(spec, 'robot_system.launch.py', {'sim_mode': 'true'})
    report                     # a table in a notebook; str(report) for text
    report.assert_ok()         # in a test (or: assert report.ok, report)

    # with the system running (`ros2 launch ...`), in this ROS_DOMAIN_ID:
    speccheck.check_live(spec, window=3.0)

From a shell: ``speccheck static|live SPEC [--launch PKG FILE | PATH]
[name:=value ...] [--format text|json|junit|sarif]`` (or ``python -m
speccheck``); exit code 0 met, 1 a requirement not met, 2 could not judge
(spec file, launch file, arguments, or a crash).

Tools built on speccheck (the book's labkit) may also use its graph modules,
which are public as modules: `speccheck.graph` (a snapshot of the graph, a
node's parameters), `speccheck.qos`, `speccheck.rates`, `speccheck.observer`
(the one hidden node of a process), `speccheck.launcher` and
`speccheck.launch_command` (a launch as a child process), `speccheck.ros_error`.
speccheck itself imports nothing of the book (.importlinter says so).
"""
from speccheck.live_check import check_live
from speccheck.report import Finding, Report, Status
from speccheck.spec import Spec, SpecError, load_spec
from speccheck.static_check import check_static

__all__ = ['Finding', 'Report', 'Spec', 'SpecError', 'Status', 'check_live', 'check_static',
           'load_spec']
