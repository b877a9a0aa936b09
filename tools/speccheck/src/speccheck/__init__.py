"""speccheck: check a ROS 2 system against a written spec, statically and running.

A spec (YAML; see :mod:`speccheck.spec` and docs/reference/spec-files.md)
says which nodes, topics, parameters and launch arguments a system must
have.  Two checks compare it with reality:

    import speccheck

    spec = speccheck.load_spec('system.yaml')
    report = speccheck.check_static(spec, 'robot_system.launch.py', {'sim_mode': 'true'})
    report                     # a table in a notebook; str(report) for text
    report.assert_ok()         # in a test (or: assert report.ok, report)

    with labkit.launch('my_robot_pkg', 'robot_system.launch.py') as run:
        run.wait_for_nodes(['/sensor_publisher'])
        speccheck.check_live(spec, window=3.0)

From a shell: ``speccheck static|live SPEC [--launch PKG FILE | PATH]
[name:=value ...] [--format text|json|junit|sarif]`` (or ``python -m
speccheck``); exit code 0 met, 1 a requirement not met, 2 could not judge
(spec file, launch file, arguments, or a crash).
"""
from speccheck.live_check import check_live
from speccheck.report import Finding, Report, Status
from speccheck.spec import Spec, SpecError, load_spec
from speccheck.static_check import check_static

__all__ = ['Finding', 'Report', 'Spec', 'SpecError', 'Status', 'check_live', 'check_static',
           'load_spec']
