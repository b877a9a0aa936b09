"""``make lab``: JupyterLab on lessons/, where every lesson runs in the book's kernel.

The lessons' front matter names the ``python3`` kernel (the book's build
picks its own kernel, see execute.py), and we do not rewrite it.  The lab
server offers only the book's kernel (lab_kernel.py) and makes it the
default, so a lesson that asks for a Python kernel gets it: JupyterLab takes
the one kernel of the notebook's language when the named one is not offered.
JupyterLab then records that kernel in the notebook, and jupytext would
write only the front matter it knows: a pre-save hook
(:func:`keep_lesson_front_matter`) keeps each lesson's front matter as it is,
so saving a lesson from the lab changes only its cells.
Lessons are MyST markdown: jupytext (installed with its lab extension) opens
them as notebooks, and a settings override makes that the default viewer of
``.md`` files, so a double click opens a lesson as a notebook.
"""
from __future__ import annotations

import json
import os
import re
from pathlib import Path

from . import paths
from .lab_kernel import KERNEL_NAME

#: The book lab's own configuration: settings/overrides.json and a server config.
LAB = paths.BUILD / 'lab'
OVERRIDES = {
    '@jupyterlab/docmanager-extension:plugin': {
        'defaultViewers': {'markdown': 'Jupytext Notebook', 'myst': 'Jupytext Notebook'},
    },
}


#: The kernelspec every lesson's front matter names (the build ignores it).
LESSON_KERNELSPEC = {'display_name': 'Python 3', 'language': 'python', 'name': 'python3'}
_KERNELSPEC_BLOCK = re.compile(r'^kernelspec:\n(?:[ \t]+.*\n)+', re.MULTILINE)


def _split_front_matter(text: str) -> tuple[str, str] | None:
    """(front matter with its ``---`` lines, the rest), or None without one."""
    end = text.find('\n---\n', 3) if text.startswith('---\n') else -1
    return (text[:end + 5], text[end + 5:]) if end >= 0 else None


def keep_lesson_front_matter(model: dict, path: str, contents_manager: object = None,
                           **_: object) -> None:
    """Pre-save hook: a lesson saved from the lab keeps its front matter as it is.

    jupytext writes only the metadata it knows (it would drop ``textbook:``),
    adds its version, and JupyterLab records the book's kernel: so the file's
    own front matter is kept and only the cells are saved.  A new text
    notebook, or an .ipynb, gets the lessons' kernelspec instead of the book's.
    """
    if model.get('type') == 'notebook':  # an .ipynb
        spec = model['content'].get('metadata', {}).get('kernelspec', {})
        if spec.get('name') == KERNEL_NAME:
            model['content']['metadata']['kernelspec'] = dict(LESSON_KERNELSPEC)
        return
    text = model.get('content')
    parts = _split_front_matter(text) if isinstance(text, str) else None
    if model.get('type') != 'file' or parts is None:
        return
    header, body = parts
    on_disk = Path(getattr(contents_manager, 'root_dir', '')) / path
    old = _split_front_matter(on_disk.read_text()) if on_disk.is_file() else None
    if old is not None:
        model['content'] = old[0] + body
        return
    block = _KERNELSPEC_BLOCK.search(header)
    if block and f'name: {KERNEL_NAME}' in block.group(0):
        lesson_block = 'kernelspec:\n' + ''.join(
            f'  {key}: {value}\n' for key, value in LESSON_KERNELSPEC.items())
        model['content'] = header[:block.start()] + lesson_block + header[block.end():] + body


# A callable, not its import string: jupyter_server's validator of the string
# form imports the old value (None) instead of the new one.
SERVER_CONFIG = f"""\
# Written by {__name__}.write_settings for `make lab`.
from {__name__} import keep_lesson_front_matter

c.ContentsManager.pre_save_hook = keep_lesson_front_matter
"""


def write_settings(folder: Path = LAB) -> Path:
    """Write the lab's settings overrides and server config into ``folder``; returns it."""
    (folder / 'settings').mkdir(parents=True, exist_ok=True)
    (folder / 'settings' / 'overrides.json').write_text(json.dumps(OVERRIDES, indent=2) + '\n')
    (folder / 'jupyter_lab_config.py').write_text(SERVER_CONFIG)
    return folder


def lab_arguments(address: str = '127.0.0.1:8888', browser: bool = True,
                  folder: Path = LAB, root: Path = paths.LESSONS) -> list[str]:
    """Arguments of ``python -m jupyterlab`` for the book's lab on ``root``, with the
    configuration :func:`write_settings` wrote into ``folder``."""
    host, _, port = address.rpartition(':')
    arguments = [
        f"--config={folder / 'jupyter_lab_config.py'}",
        f'--ServerApp.root_dir={root}',
        f"--ServerApp.ip={host or '127.0.0.1'}",
        f"--ServerApp.port={port or '8888'}",
        f"--LabApp.app_settings_dir={folder / 'settings'}",
        f'--KernelSpecManager.allowed_kernelspecs={KERNEL_NAME}',
        f'--MappingKernelManager.default_kernel_name={KERNEL_NAME}',
    ]
    if not browser:
        arguments.append('--no-browser')
    if hasattr(os, 'geteuid') and os.geteuid() == 0:
        arguments.append('--allow-root')  # containers often run as root
    return arguments
