"""Where things live in the repository, computed once so no module guesses."""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SNIPPETS = ROOT / "snippets"
LESSONS = ROOT / "lessons"
DOCS = ROOT / "docs"
BUILD = ROOT / "build"
WORKSPACE = BUILD / "ws"
NOTEBOOKS = BUILD / "notebooks"
CACHE = BUILD / "cache"
RUNS = BUILD / "run"
TOOLS = ROOT / "tools"
MKDOCS_YML = ROOT / "mkdocs.yml"

# The interpreter of the project environment; its bin/ holds colcon, ros2,
# mkdocs and pytest, so it goes first on PATH for everything we start.
VENV_BIN = Path(sys.executable).parent


def rel(path: Path) -> str:
    """Repository-relative path for messages (absolute if outside the repo)."""
    try:
        return str(Path(path).resolve().relative_to(ROOT))
    except ValueError:
        return str(path)
