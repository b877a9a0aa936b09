"""Where things live in the repository, computed once so no module guesses."""
from __future__ import annotations

import os
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SNIPPETS = ROOT / 'snippets'
LESSONS = ROOT / 'lessons'
DOCS = ROOT / 'docs'
# TEXTBOOK_BUILD moves every build product (workspace, caches, executed
# notebooks): the parity command runs a second stack beside the first in
# build/jazzy without touching build/.
BUILD = Path(os.environ.get('TEXTBOOK_BUILD') or ROOT / 'build').resolve()
WORKSPACE = BUILD / 'ws'
NOTEBOOKS = BUILD / 'notebooks'
CACHE = BUILD / 'cache'
# Lessons and lab kernels run in folders shaped like ~/ros2_ws, outside the
# repository: inside it, a student's `colcon test` would find this repository's
# pytest configuration above the workspace (pytest looks upwards for one) and
# report test names a student's machine never shows.
RUNS = Path(os.environ.get('TMPDIR') or tempfile.gettempdir()) / 'ros2-launch-textbook-runs'
TOOLS = ROOT / 'tools'
MKDOCS_YML = ROOT / 'mkdocs.yml'

# The interpreter of the project environment; its bin/ holds colcon, ros2,
# mkdocs and pytest, so it goes first on PATH for everything we start.
VENV_BIN = Path(sys.executable).parent


def tool_path(path: str | None = None) -> str:
    """``PATH`` with the project environment's bin/ first (``path``: the PATH to extend)."""
    rest = os.environ.get('PATH', '') if path is None else path
    return f'{VENV_BIN}{os.pathsep}{rest}'


def executable(name: str) -> str:
    """The command ``name`` as the project environment finds it: .venv/bin, then
    PATH (with ROS 2 sourced, ``colcon`` or ``ros2`` may come from there only)."""
    found = shutil.which(name, path=tool_path())
    if found is None:
        raise FileNotFoundError(f'{name}: not found in {VENV_BIN} or on PATH; '
                                f'run `make setup` (or source your ROS 2 installation)')
    return found


def rel(path: Path) -> str:
    """Repository-relative path for messages (absolute if outside the repo)."""
    try:
        return str(Path(path).resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


#: How the pages show the folder a lesson ran in: the student's workspace.
STUDENT_WORKSPACE = '~/ros2_ws'
#: How the pages show this checkout (its .venv, its build/): where the README's
#: `git clone` puts it in a student's home.
STUDENT_CHECKOUT = '~/ros2-launch-textbook'


def shown(text: str, workdir: Path | None = None) -> str:
    """``text`` with the build machine's folders written as a student's terminal
    shows them: ``workdir`` (a lesson's scratch folder) as ``~/ros2_ws``, this
    checkout as ``~/ros2-launch-textbook``."""
    if workdir is not None:
        text = text.replace(str(workdir), STUDENT_WORKSPACE)
    return text.replace(str(ROOT), STUDENT_CHECKOUT)
