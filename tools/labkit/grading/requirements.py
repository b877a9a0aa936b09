"""Requirements many checks share, each recorded in a Verdict with a message
that says what is wrong and what to do about it."""
from __future__ import annotations

from labkit.grading.exercise import ExerciseVerdict
from labkit.grading.launch_probe import LaunchProbe
from labkit.grading.student_package import StudentPackage
from labkit.grading.verdict import Verdict


def files_installed(verdict: Verdict, package: StudentPackage,
                    files: tuple[str, ...] | None = None) -> bool:
    """Every file exists in src/ and its installed copy is current.

    Without `files`, the files of the exercise being graded (Exercise.files,
    carried by its ExerciseVerdict); give them only for a check that also
    needs another exercise's file.
    """
    if files is None:
        if not isinstance(verdict, ExerciseVerdict):
            raise TypeError('files_installed() needs `files` outside Exercise.grade()')
        files = verdict.files
    ok = True
    for relative in files:
        problem = package.installed_problem(relative)
        ok = verdict.expect(problem is None, f'{package.shown(package.source / relative)} '
                            'is built and installed', problem or '') and ok
    return ok


def launch_ran(verdict: Verdict, run: LaunchProbe) -> bool:
    """The launch started processes and kept running until the check stopped it."""
    if run.exited_by_itself:
        errors = run.launch_errors()
        if errors:
            return verdict.fail(f'`{run.command}` stopped with an error (exit code '
                                f'{run.returncode}):\n      ' + '\n      '.join(errors)).passed
        if not run.processes:
            return verdict.fail(f'`{run.command}` starts no process and ends at once: '
                                'add the Node actions the TODO comments ask for').passed
        return verdict.fail(f'`{run.command}` ended by itself (exit code {run.returncode}); '
                            'its last lines:\n      ' + '\n      '.join(run.lines[-5:])).passed
    return verdict.expect(True, f'`{run.command}` starts and runs', '')


def node_running(verdict: Verdict, run: LaunchProbe, node: str, how: str) -> bool:
    """`node` is in the graph; `how` tells the student how to start it."""
    others = ', '.join(run.nodes) or 'none'
    return verdict.expect(node in run.nodes, f'{node} is running',
                          f'{node} is not in the graph (nodes: {others}): {how}')


def names_unique(verdict: Verdict, run: LaunchProbe) -> bool:
    """No two processes run as the same node (the launch log tells them apart)."""
    shared = {node: owners for node, owners in run.node_processes.items() if len(owners) > 1}
    for node, owners in sorted(shared.items()):
        verdict.fail(f'{len(owners)} processes run as the node {node} '
                     f'({", ".join(owners)} in the launch log): every node needs its own '
                     f'name; remove the extra Node action or give it another name=')
    return not shared


def topic_link(verdict: Verdict, run: LaunchProbe, topic: str, publisher: str,
               subscriber: str) -> bool:
    """`publisher` -> `topic` -> `subscriber` in the graph."""
    publishers, subscribers = run.publishers(topic), run.subscribers(topic)
    met = publisher in publishers and subscriber in subscribers
    return verdict.expect(
        met, f'{publisher} -> {topic} -> {subscriber}',
        f'{topic} should go from {publisher} to {subscriber}; it is published by '
        f'{", ".join(publishers) or "nobody"} and read by {", ".join(subscribers) or "nobody"}')
