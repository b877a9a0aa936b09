"""The running check of a launch file: start it with labkit, check, stop it."""
from __future__ import annotations

import time
from pathlib import Path

import labkit

from speccheck.live_check import DEFAULT_WINDOW, check_live
from speccheck.report import Finding, Report, Status
from speccheck.spec import Spec

#: Seconds to wait, once the nodes are up, for the endpoints the spec names.
ENDPOINT_GRACE = 10.0


def check_launch_live(spec: Spec, launch_file: str | Path | tuple[str, str] | None,
                      arguments: dict[str, str] | None = None, *,
                      window: float = DEFAULT_WINDOW, timeout: float = 20.0,
                      endpoint_grace: float = ENDPOINT_GRACE) -> Report:
    """Start `launch_file` (if given), wait for the spec's nodes, check, and stop it.

    `launch_file` is a path or a (package, file name) pair, as `ros2 launch`
    takes them.  Without a launch file the system that is running now is checked.
    Once the nodes are up, the check waits up to `endpoint_grace` seconds for
    the publishers and subscribers the spec names, because discovery reports a
    node before its endpoints (on a busy machine, seconds before).
    """
    if launch_file is None:
        return check_live(spec, window)
    words = launch_file if isinstance(launch_file, tuple) else (str(launch_file),)
    target = Path(words[-1]).name + ''.join(f' {k}:={v}' for k, v in (arguments or {}).items())
    with labkit.launch(*words, launch_arguments=arguments or {}) as run:
        try:
            run.wait_for_nodes([node.name for node in spec.nodes], timeout=timeout)
        except labkit.LabkitError as error:
            return Report('live', spec.source, target,
                          (Finding('launch', Status.FAILED, str(error)),))
        _wait_for_endpoints(spec, endpoint_grace)
        report = check_live(spec, window, target)
        return Report('live', spec.source, target,
                      (Finding('launch', Status.MET, f'`{run.command}` running'),
                       *report.findings))


def _wait_for_endpoints(spec: Spec, grace: float) -> None:
    """Return once every publisher and subscriber the spec names is in the graph,
    or after `grace` seconds (the check then reports what is missing)."""
    deadline = time.monotonic() + grace
    wanted = [(topic.name, role, name) for topic in spec.topics
              for role, names in (('publishers', topic.publishers),
                                  ('subscribers', topic.subscribers))
              for name in names]
    while wanted and time.monotonic() < deadline:
        snapshot = labkit.graph()
        wanted = [(topic, role, name) for topic, role, name in wanted
                  if topic not in snapshot.topics
                  or name not in getattr(snapshot.topics[topic], role)]
        if wanted:
            time.sleep(0.1)
