"""Executable: the command of a process as given, and as expanded when it starts.

ExecuteProcess keeps its command here so that the expanded values have one
home that users can reach: `output_format` strings name them as
`{this.process_description.final_name}` (Jazzy's default prefix).
"""
from __future__ import annotations

import os
import re
import shlex
from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType

SubstitutionsList = list[Substitution]
EnvPairs = list[tuple[SubstitutionsList, SubstitutionsList]]


def _pairs(env: Mapping | Iterable[tuple]) -> EnvPairs:
    items = env.items() if isinstance(env, Mapping) else env
    return [(normalize_to_list_of_substitutions(k), normalize_to_list_of_substitutions(v))
            for k, v in items]


class Executable:
    """Describes one process: command, prefix, name, folder and environment.

    The given parts are substitutions until the process starts; then they are
    expanded once (`final_*`), and the name gets the launch-wide process
    number (`talker-1`).  `cmd` stays a mutable list so that launch_ros' Node
    can append its ROS arguments before the expansion.
    """

    def __init__(
        self, *,
        cmd: Iterable[SomeSubstitutionsType],
        prefix: SomeSubstitutionsType | None = None,
        name: SomeSubstitutionsType | None = None,
        cwd: SomeSubstitutionsType | None = None,
        env: Mapping | Iterable[tuple] | None = None,
        additional_env: Mapping | Iterable[tuple] | None = None,
        arguments: Iterable[SomeSubstitutionsType] | None = None,
    ) -> None:
        if isinstance(cmd, (str, Substitution)):
            cmd = [cmd]
        self.__cmd: list[SubstitutionsList] = [
            normalize_to_list_of_substitutions(token) for token in [*cmd, *(arguments or [])]]
        self.__prefix = None if prefix is None else normalize_to_list_of_substitutions(prefix)
        self.__name = None if name is None else normalize_to_list_of_substitutions(name)
        self.__cwd = None if cwd is None else normalize_to_list_of_substitutions(cwd)
        self.__env = None if env is None else _pairs(env)
        self.__additional_env = None if additional_env is None else _pairs(additional_env)
        self.__final_name: str | None = None
        self.__final_cmd: list[str] | None = None
        self.__final_cwd: str | None = None
        self.__final_env: dict[str, str] | None = None

    @property
    def cmd(self) -> list[SubstitutionsList]:
        """The command; a mutable list of argument substitution lists."""
        return self.__cmd

    @property
    def prefix(self) -> SubstitutionsList | None:
        """The prefix command, as substitutions."""
        return self.__prefix

    @property
    def name(self) -> SubstitutionsList | None:
        """The given name, as substitutions (None: the executable's basename)."""
        return self.__name

    @property
    def cwd(self) -> SubstitutionsList | None:
        """The working directory, as substitutions."""
        return self.__cwd

    @property
    def env(self) -> EnvPairs | None:
        """The replacement environment, as substitution pairs."""
        return self.__env

    @property
    def additional_env(self) -> EnvPairs | None:
        """Variables added to the environment, as substitution pairs."""
        return self.__additional_env

    @property
    def final_name(self) -> str | None:
        """`<name or basename of the executable>-N` once started, else None."""
        return self.__final_name

    @property
    def final_cmd(self) -> list[str] | None:
        """The expanded command line, prefix included, once started."""
        return self.__final_cmd

    @property
    def final_cwd(self) -> str | None:
        """The expanded working directory (None: the launch's own)."""
        return self.__final_cwd

    @property
    def final_env(self) -> dict[str, str] | None:
        """The complete environment the process gets, once started."""
        return self.__final_env

    def _expand(self, context: LaunchContext) -> None:
        """Perform the substitutions and number the process (ExecuteProcess.execute)."""
        cmd = [perform_substitutions(context, token) for token in self.__cmd]
        if not cmd or not cmd[0]:
            raise RuntimeError('ExecuteProcess: empty command')
        executable = cmd[0]
        base = perform_substitutions(context, self.__name) if self.__name is not None \
            else os.path.basename(executable)
        self.__final_name = f'{base}-{context._allocate_process_number()}'
        self.__final_cmd = self.__prefix_words(context, executable) + cmd
        self.__final_cwd = None if self.__cwd is None \
            else perform_substitutions(context, self.__cwd)
        if self.__env is None:
            env = dict(context.environment)
        else:
            env = {perform_substitutions(context, k): perform_substitutions(context, v)
                   for k, v in self.__env}
        for k, v in self.__additional_env or []:
            env[perform_substitutions(context, k)] = perform_substitutions(context, v)
        self.__final_env = env

    def __prefix_words(self, context: LaunchContext, executable: str) -> list[str]:
        """The given prefix, else the `launch-prefix` configuration (if its filter matches)."""
        if self.__prefix is not None:
            return shlex.split(perform_substitutions(context, self.__prefix))
        prefix = context.launch_configurations.get('launch-prefix', '')
        if not prefix:
            return []
        pattern = context.launch_configurations.get('launch-prefix-filter')
        if pattern and not re.search(pattern, os.path.basename(executable)):
            return []
        return shlex.split(str(prefix))
