"""Run a command and substitute its standard output."""
from __future__ import annotations

import shlex
import subprocess
from typing import TYPE_CHECKING

from ..logging import get_logger
from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType

_ON_STDERR = ('fail', 'ignore', 'warn', 'capture')


class Command(Substitution):
    """The stdout of a command (split like a shell would, run without a shell).

    `on_stderr` says what output on stderr means: 'fail' (default) raises,
    'warn' logs a warning, 'ignore' drops it, 'capture' appends it.
    """

    def __init__(self, command: SomeSubstitutionsType, *,
                 on_stderr: SomeSubstitutionsType = 'fail') -> None:
        super().__init__()
        self.__command = normalize_to_list_of_substitutions(command)
        self.__on_stderr = normalize_to_list_of_substitutions(on_stderr)

    @property
    def command(self) -> list[Substitution]:
        """The command, as substitutions."""
        return self.__command

    @property
    def on_stderr(self) -> list[Substitution]:
        """What to do with stderr output, as substitutions."""
        return self.__on_stderr

    def describe(self) -> str:
        """Return e.g. Command('xacro robot.urdf.xacro')."""
        return f"Command({' + '.join(s.describe() for s in self.__command)})"

    def perform(self, context: LaunchContext) -> str:
        """Run the command in the launch environment and return its stdout."""
        command = perform_substitutions(context, self.__command)
        on_stderr = perform_substitutions(context, self.__on_stderr)
        if on_stderr not in _ON_STDERR:
            raise SubstitutionFailure(
                f"invalid on_stderr value '{on_stderr}', expected one of {list(_ON_STDERR)}")
        try:
            result = subprocess.run(shlex.split(command), capture_output=True,
                                    env=dict(context.environment), check=False)
        except OSError as exc:
            raise SubstitutionFailure(f'executed command failed. Command: {command}\n'
                                      f'Captured stderr output: {exc}') from exc
        stdout = result.stdout.decode(errors='replace')
        stderr = result.stderr.decode(errors='replace')
        if result.returncode != 0:
            raise SubstitutionFailure(f'executed command failed. Command: {command}\n'
                                      f'Captured stderr output: {stderr}')
        if stderr:
            if on_stderr == 'fail':
                raise SubstitutionFailure(f'executed command showed stderr output. '
                                          f'Command: {command}\nCaptured stderr output: {stderr}')
            if on_stderr == 'warn':
                get_logger('launch').warning(f'executed command showed stderr output. '
                                             f'Command: {command}\n'
                                             f'Captured stderr output: {stderr}')
            elif on_stderr == 'capture':
                stdout += stderr
        return stdout
