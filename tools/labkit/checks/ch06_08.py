"""Checks of lesson 6.8 (From requirements to a launch file with an assistant).

Exercise 6.8.1 grades a spec file, and a spec is judged by what it does: the
student's spec is run through `speccheck`, as their terminal would
run it, against the book's launch file that meets the requirements (the spec
must pass it, statically and running) and against two launch files with one
wrong value each (the static check must fail them).  Never the spec's text,
so any correct way of writing it passes.
"""
from __future__ import annotations

from labkit.grading import spec_run
from labkit.grading.exercise import Exercise
from labkit.grading.spec_run import SpecRun
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict

SPEC = 'specs/ex68_front_spec.spec.yaml'
BOOK_PACKAGE = 'my_robot_pkg'
SYSTEM = 'front_sensor_system.launch.py'
#: planted defect: (launch file, what is wrong in it, what the spec needs to catch it)
DEFECTS = (
    ('front_sensor_system_bad_rate.launch.py',
     'the argument rate defaults to 1.0, so the sensor publishes at 1 Hz',
     "give the argument rate its default '10.0', or publish_rate its value 10.0"),
    ('front_sensor_system_bad_window.launch.py',
     'data_processor averages 5 readings (window_size 5)',
     'give window_size its value 4, not only its type'),
)


def run_speccheck(package: StudentPackage, mode: str, launch_file: str) -> SpecRun:
    """`speccheck MODE SPEC --launch my_robot_pkg FILE` in the student's workspace."""
    spec = package.source / SPEC
    shown = (f'speccheck {mode} {package.shown(spec)} '
             f'--launch {BOOK_PACKAGE} {launch_file}')
    return spec_run.run_speccheck(package, mode, spec, ['--launch', BOOK_PACKAGE, launch_file],
                                  shown)


def _passes_the_system(verdict: Verdict, package: StudentPackage, mode: str) -> bool:
    """The spec passes the launch file that meets the requirements."""
    run = run_speccheck(package, mode, SYSTEM)
    check = 'static check' if mode == 'static' else 'running check'
    if run.returncode == 2:
        return verdict.fail(f'`{run.command}` could not read the spec: {run.error}').passed
    findings = run.shown_findings(6)
    extra = any('not in the spec' in line for line in run.failed)
    if extra and any('no Node action starts it' in line for line in run.failed):
        why = ('your spec names nodes the system does not have and leaves out those it has: '
               'write each name fully qualified, with its namespace (/front/...)')
    elif extra:
        why = ('the system has something your spec does not list, and a spec must name '
               'every node and parameter the requirements give')
    else:
        why = 'the spec asks for something the requirements do not say'
    return verdict.expect(
        run.returncode == 0,
        f'the {check} of {SYSTEM}, which meets the requirements, passes with your spec',
        f'the {check} of {SYSTEM}, which meets the requirements, fails with your spec: '
        f'{why}. `{run.command}` reported:\n      {findings}')


def _catches(verdict: Verdict, package: StudentPackage, launch_file: str, defect: str,
             need: str) -> None:
    run = run_speccheck(package, 'static', launch_file)
    first = run.failed[0] if run.failed else run.error
    verdict.expect(
        run.returncode == 1,
        f'the static check catches {launch_file} ({defect}): {first}',
        f'your spec passes {launch_file}, where {defect}; {need}')


def check_front_spec(package: StudentPackage, verdict: Verdict) -> Verdict:
    """The student's spec passes the right system and fails both planted defects."""
    spec = package.source / SPEC
    if not spec.is_file():
        return verdict.fail(f'{package.shown(spec)} does not exist: run '
                            "labkit.exercises.setup('ex68_front_spec') to create the starter")
    if not _passes_the_system(verdict, package, 'static'):
        return verdict
    if not _passes_the_system(verdict, package, 'live'):
        return verdict
    for launch_file, defect, need in DEFECTS:
        _catches(verdict, package, launch_file, defect, need)
    return verdict


EXERCISES = (
    Exercise('ex68_front_spec', 'Exercise 6.8.1 (a spec that catches a planted defect)',
             (SPEC,), check_front_spec),
)
