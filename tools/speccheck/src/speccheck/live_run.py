"""The running check of a launch file: start it, check, stop it."""
from __future__ import annotations

from pathlib import Path

from speccheck import codes
from speccheck.launcher import Launch, LaunchError
from speccheck.live_check import DEFAULT_WINDOW, check_live
from speccheck.report import Finding, Report, Status, located
from speccheck.spec import Spec


def check_launch_live(spec: Spec, launch_file: str | Path | tuple[str, str] | None,
                      arguments: dict[str, str] | None = None, *,
                      window: float = DEFAULT_WINDOW, timeout: float = 20.0) -> Report:
    """Start `launch_file` (if given), wait for the spec's nodes, check, and stop it.

    `launch_file` is a path or a (package, file name) pair, as `ros2 launch`
    takes them.  Without a launch file the system that is running now is checked.
    """
    if launch_file is None:
        return check_live(spec, window)
    words = launch_file if isinstance(launch_file, tuple) else (str(launch_file),)
    target = Path(words[-1]).name + ''.join(f' {k}:={v}' for k, v in (arguments or {}).items())
    with Launch(*words, arguments=arguments) as run:
        try:
            run.wait_for_nodes([node.name for node in spec.nodes], timeout=timeout)
        except LaunchError as error:
            return Report('live', spec.source, target, located(
                [Finding('launch', Status.FAILED, str(error), codes.LAUNCH_FAILED)], spec.lines))
        report = check_live(spec, window, target)
        return Report('live', spec.source, target,
                      (*located([Finding('launch', Status.MET, f'`{run.command}` running')],
                                spec.lines), *report.findings))

