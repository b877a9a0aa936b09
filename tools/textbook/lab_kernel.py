"""The book's Jupyter kernel: a lesson in JupyterLab runs as in the book's build.

Jupyter starts ``python -m textbook.lab_kernel -f {connection_file}`` (the
kernel spec ``ros2-launch-textbook``, installed into .venv by
``tools/setup_env.sh``).  This launcher leases a private ROS domain, builds
and sources the snippets workspace, creates a student workspace (``src/``
with a copy of every book package, see execute.student_workspace) as the
working folder, and runs ipykernel there.  When the kernel ends, whatever it
left running is stopped, the folder removed and the domain released.

``python -m textbook.lab_kernel --install`` writes the kernel spec.
"""
from __future__ import annotations

import argparse
import json
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

from jupyter_client.kernelspec import KernelSpecManager

from . import paths, reaper
from .execute import student_env, student_workspace
from .isolation import acquire_domain

KERNEL_NAME = 'ros2-launch-textbook'
DISPLAY_NAME = 'ROS 2 launch textbook (Jazzy)'


def kernel_spec() -> dict:
    """The kernel.json of the book's kernel, for this interpreter."""
    return {
        'argv': [sys.executable, '-m', 'textbook.lab_kernel', '-f', '{connection_file}'],
        'display_name': DISPLAY_NAME,
        'language': 'python',
        # An interrupt travels as a message to ipykernel: a signal to the
        # launcher's process group would reach the launcher too.
        'interrupt_mode': 'message',
        'metadata': {'debugger': True},
    }


def install_kernel_spec(prefix: str = sys.prefix) -> Path:
    """Install the kernel spec under ``prefix`` (default: this environment); returns its folder."""
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / 'kernel.json').write_text(json.dumps(kernel_spec(), indent=1) + '\n')
        target = KernelSpecManager().install_kernel_spec(
            folder, kernel_name=KERNEL_NAME, prefix=prefix)
    return Path(target)


def run_kernel(connection_file: str) -> int:
    """Run ipykernel for ``connection_file`` in the book's environment; its exit code."""
    with acquire_domain() as lease:
        workdir = student_workspace(paths.RUNS / f'lab-{lease.token}')
        env = student_env(lease, workdir)
        kernel = subprocess.Popen(
            [sys.executable, '-m', 'ipykernel_launcher', '-f', connection_file],
            env=env, cwd=workdir)
        # Jupyter stops a kernel with SIGTERM (after a shutdown request);
        # pass it on.  SIGINT reaches ipykernel itself (message interrupts,
        # or the signal to the whole process group): the launcher stays.
        signal.signal(signal.SIGTERM, lambda *_: kernel.terminate())
        signal.signal(signal.SIGINT, lambda *_: None)
        try:
            return kernel.wait()
        finally:
            if kernel.poll() is None:
                kernel.kill()
                kernel.wait()
            leftovers = reaper.reap([lease.token])
            if leftovers:
                print('lab kernel: stopped processes still running at the end:\n  '
                      + '\n  '.join(leftovers), file=sys.stderr)
            shutil.rmtree(workdir, ignore_errors=True)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='python -m textbook.lab_kernel', description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('-f', dest='connection_file', help="the kernel's connection file")
    parser.add_argument('--install', action='store_true',
                        help=f'install the kernel spec {KERNEL_NAME!r} into {sys.prefix}')
    options = parser.parse_args(argv)
    if options.install:
        print(install_kernel_spec())
        return 0
    if not options.connection_file:
        parser.error('-f CONNECTION_FILE is required (Jupyter passes it)')
    return run_kernel(options.connection_file)


if __name__ == '__main__':
    sys.exit(main())
