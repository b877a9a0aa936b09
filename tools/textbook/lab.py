"""``make lab``: JupyterLab on lessons/, where every lesson runs in the book's kernel.

The lessons' front matter names the ``python3`` kernel (the book's build
picks its own kernel, see execute.py), and we do not rewrite it.  The lab
server offers only the book's kernel (lab_kernel.py) and makes it the
default, so a lesson that asks for a Python kernel gets it: JupyterLab takes
the one kernel of the notebook's language when the named one is not offered.
Lessons are MyST markdown: jupytext (installed with its lab extension) opens
them as notebooks, and a settings override makes that the default viewer of
``.md`` files, so a double click opens a lesson as a notebook.
"""
from __future__ import annotations

import json
import os
from pathlib import Path

from . import paths
from .lab_kernel import KERNEL_NAME

LAB = paths.BUILD / "lab"
#: JupyterLab's application settings (overrides.json) for the book's lab only.
SETTINGS = LAB / "settings"
OVERRIDES = {
    "@jupyterlab/docmanager-extension:plugin": {
        "defaultViewers": {"markdown": "Jupytext Notebook", "myst": "Jupytext Notebook"},
    },
}


def write_settings(folder: Path = SETTINGS) -> Path:
    """Write the lab's settings overrides into ``folder``; returns the folder."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "overrides.json").write_text(json.dumps(OVERRIDES, indent=2) + "\n")
    return folder


def lab_arguments(address: str = "127.0.0.1:8888", browser: bool = True,
                  settings: Path = SETTINGS) -> list[str]:
    """Arguments of ``python -m jupyterlab`` for the book's lab."""
    host, _, port = address.rpartition(":")
    arguments = [
        f"--ServerApp.root_dir={paths.LESSONS}",
        f"--ServerApp.ip={host or '127.0.0.1'}",
        f"--ServerApp.port={port or '8888'}",
        f"--LabApp.app_settings_dir={settings}",
        f"--KernelSpecManager.allowed_kernelspecs={KERNEL_NAME}",
        f"--MappingKernelManager.default_kernel_name={KERNEL_NAME}",
    ]
    if not browser:
        arguments.append("--no-browser")
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        arguments.append("--allow-root")  # containers often run as root
    return arguments
