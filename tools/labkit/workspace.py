"""What a lesson needs around it, with a message that says how to get it.

A notebook downloaded from the site runs on the student's own ROS 2 Jazzy:
its first cell calls :func:`require_workspace`, which fails with the exact
steps when ROS 2 or the book's workspace is not sourced in the shell that
started Jupyter.  :func:`book_snippets` finds the book's ``snippets/`` folder
(starter and solution files of the exercises) where a pip-installed labkit
has no repository next to it.
"""
from __future__ import annotations

import importlib.util
import os
import shutil
import subprocess
from pathlib import Path

from labkit.errors import LabkitError

#: The book's robot package: a sourced book workspace has it.
BOOK_PACKAGE = 'my_robot_pkg'
REPOSITORY = 'https://github.com/ros2-launch-textbook/ros2-launch-textbook'
#: Set it to the `snippets/` folder of a clone when labkit cannot find one.
SNIPPETS_VAR = 'LABKIT_SNIPPETS'
_STARTERS = Path('starters') / 'my_ws_exercises'

SETUP_STEPS = f"""\
Do this once, in a terminal:

    source /opt/ros/jazzy/setup.bash          # ROS 2 Jazzy (or activate your RoboStack env)
    git clone {REPOSITORY}
    python3 -m venv --system-site-packages ~/textbook-venv
    source ~/textbook-venv/bin/activate
    pip install ./ros2-launch-textbook/tools/rclhelpers ./ros2-launch-textbook jupyterlab
    mkdir -p ~/ros2_ws/src
    cp -r ros2-launch-textbook/snippets/* ~/ros2_ws/src/
    cd ~/ros2_ws && colcon build              # --packages-skip turtlesim if ROS has turtlesim

and then, every time, start Jupyter from a shell with the workspace sourced,
with this notebook in ~/ros2_ws:

    source /opt/ros/jazzy/setup.bash
    source ~/textbook-venv/bin/activate
    cd ~/ros2_ws && source install/setup.bash
    jupyter lab
"""


class WorkspaceNotReadyError(LabkitError):
    """ROS 2 or the book's workspace is missing from the notebook's environment."""


def book_package_prefix(env: dict[str, str] | None = None) -> str | None:
    """The install prefix of the book's package on ``AMENT_PREFIX_PATH``, if any."""
    env = os.environ if env is None else env
    for prefix in filter(None, env.get('AMENT_PREFIX_PATH', '').split(os.pathsep)):
        marker = Path(prefix) / 'share' / 'ament_index' / 'resource_index' / 'packages'
        if (marker / BOOK_PACKAGE).is_file():
            return prefix
    return None


def missing_requirements(env: dict[str, str] | None = None) -> list[str]:
    """What the notebook's environment lacks, one sentence each (empty: ready)."""
    env = os.environ if env is None else env
    missing = []
    if shutil.which('ros2', path=env.get('PATH', '')) is None:
        missing.append('the `ros2` command is not on PATH (ROS 2 is not sourced)')
    for module in ('rclpy', 'launch', 'launch_ros'):
        if importlib.util.find_spec(module) is None:
            missing.append(f'Python cannot import `{module}` (ROS 2 is not sourced '
                           f'in the shell that started Jupyter)')
    if book_package_prefix(env) is None:
        missing.append(f"the book's package `{BOOK_PACKAGE}` is not on AMENT_PREFIX_PATH "
                       f'(the workspace is not built, or its install/setup.bash not sourced)')
    return missing


def require_workspace() -> None:
    """Check that ROS 2 and the book's workspace are sourced; call it in a lesson's first cell.

    Returns nothing, so the cell shows nothing when all is there; raises
    WorkspaceNotReadyError listing what is missing and what to do.
    """
    missing = missing_requirements()
    if missing:
        raise WorkspaceNotReadyError(
            "This notebook needs ROS 2 Jazzy and the book's workspace, sourced in the "
            'shell that started Jupyter. Missing:\n'
            + ''.join(f'  - {item}\n' for item in missing) + '\n' + SETUP_STEPS)


def require_ros_python() -> None:
    """Raise the message of :func:`require_workspace` when rclpy cannot be imported
    (labkit is built on it), so `import labkit` explains instead of failing on rclpy."""
    if importlib.util.find_spec('rclpy') is None:
        require_workspace()


def _candidates() -> list[Path]:
    """Where the book's snippets/ may be, in order of preference."""
    found = []
    if os.environ.get(SNIPPETS_VAR):
        found.append(Path(os.environ[SNIPPETS_VAR]))
    found.append(Path(__file__).resolve().parents[2] / 'snippets')  # labkit in the repository
    found.append(Path.cwd() / 'src')  # a workspace whose src/ is a copy of snippets/
    return found


def book_snippets() -> Path:
    """The book's ``snippets/`` folder: $LABKIT_SNIPPETS, the repository labkit
    runs from, or the current workspace's ``src/`` when it holds a copy of it.

    Returns the repository's path when none holds the starters (then
    :func:`require_snippets` explains).
    """
    candidates = _candidates()
    return next((c for c in candidates if (c / _STARTERS).is_dir()),
                Path(__file__).resolve().parents[2] / 'snippets')


def require_snippets(snippets: Path) -> Path:
    """``snippets``, or an error saying how to give labkit the book's exercise files."""
    if not (snippets / _STARTERS).is_dir():
        raise WorkspaceNotReadyError(
            f"labkit's exercises need the book's starter and solution files "
            f'(snippets/{_STARTERS.as_posix()} of the repository), and labkit found none: '
            f'not in ${SNIPPETS_VAR}, not next to labkit, not in src/ of this workspace '
            f'({Path.cwd()}). Copy the snippets into the workspace '
            f'(cp -r ros2-launch-textbook/snippets/* src/) or set '
            f'{SNIPPETS_VAR}=/path/to/ros2-launch-textbook/snippets before starting Jupyter.\n\n'
            + SETUP_STEPS)
    return snippets


def sourced_environment(workspace: str | os.PathLike = '.',
                        base: dict[str, str] | None = None) -> dict[str, str]:
    """``base`` (default: this process's environment) after
    ``source <workspace>/install/setup.bash``, done by bash itself as in a
    student's terminal: pass it as ``env=`` to run what that workspace built."""
    setup = Path(workspace) / 'install' / 'setup.bash'
    env = dict(os.environ if base is None else base)
    if not setup.is_file():
        return env
    out = subprocess.run(['bash', '-c', f'source "{setup}" >/dev/null && env -0'],
                         env=env, check=True, capture_output=True, timeout=60).stdout
    pairs = (entry.split(b'=', 1) for entry in out.split(b'\0') if b'=' in entry)
    sourced = {key.decode(): value.decode() for key, value in pairs}
    for noise in ('_', 'SHLVL', 'PWD', 'OLDPWD'):
        sourced.pop(noise, None)
    return sourced
