"""ExecutableInPackage: `<prefix>/lib/<package>/<executable>`, as `ros2 run` finds it."""
from __future__ import annotations

import os
from typing import Any

from launch import LaunchContext, Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions

from ._failure import SubstitutionFailure
from .find_package import FindPackagePrefix


class ExecutableInPackage(FindPackagePrefix):
    """Locate an executable in a package's libexec directory.

    Errors carry Jazzy's wording (golden 23, trailing space included).
    """

    def __init__(self, executable: Any, package: Any) -> None:
        super().__init__(package)
        self.__executable = normalize_to_list_of_substitutions(executable)

    @property
    def executable(self) -> list[Substitution]:
        return self.__executable

    def describe(self) -> str:
        return 'ExecInPkg(pkg={}, exec={})'.format(
            ' + '.join(s.describe() for s in self.package),
            ' + '.join(s.describe() for s in self.__executable))

    def perform(self, context: LaunchContext) -> str:
        executable = perform_substitutions(context, self.__executable)
        package = perform_substitutions(context, self.package)
        prefix = self.find(package)
        libexec = os.path.join(prefix, 'lib', package)
        if not os.path.isdir(libexec):
            raise SubstitutionFailure(
                f"package '{package}' found at '{prefix}', but libexec directory "
                f"'{libexec}' does not exist")
        path = os.path.join(libexec, executable)
        if not os.path.isfile(path):
            raise SubstitutionFailure(
                f"executable '{executable}' not found on the libexec directory '{libexec}' ")
        return path
