"""A name made unique per launch, stable for the same base name."""
from __future__ import annotations

import os
import random
import re
import socket
from typing import TYPE_CHECKING

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class AnonName(Substitution):
    """`<name>_<host>_<pid>_<random>`; the same name gives the same result in a scope.

    The generated value is stored as launch configuration 'anon<name>' so
    every AnonName('x') in the launch agrees.
    """

    def __init__(self, name: SomeSubstitutionsType) -> None:
        super().__init__()
        self.__name = normalize_to_list_of_substitutions(name)

    @property
    def name(self) -> list:
        """The base name, as substitutions."""
        return self.__name

    def describe(self) -> str:
        """Return e.g. AnonName('rviz')."""
        return f"AnonName({' + '.join(s.describe() for s in self.__name)})"

    @staticmethod
    def compute_name(name: str) -> str:
        """Return a fresh anonymous name usable as a ROS node name."""
        raw = f'{name}_{socket.gethostname()}_{os.getpid()}_{random.getrandbits(63)}'
        return re.sub(r'[^A-Za-z0-9_]', '_', raw)

    def perform(self, context: LaunchContext) -> str:
        """Return the anonymous name for this base name."""
        name = perform_substitutions(context, self.__name)
        key = 'anon' + name
        if key not in context.launch_configurations:
            context.launch_configurations[key] = self.compute_name(name)
        return context.launch_configurations[key]
