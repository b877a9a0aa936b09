"""FindPackage, FindPackagePrefix, FindPackageShare: install paths from the ament index."""
from __future__ import annotations

from typing import Any

from ament_index_python.packages import get_package_prefix, get_package_share_directory
from launch import LaunchContext, Substitution
from launch.utilities import normalize_to_list_of_substitutions, perform_substitutions


class FindPackage(Substitution):
    """Base for substitutions that locate a directory of a ROS package.

    An unknown package raises ament_index_python's PackageNotFoundError
    unchanged (golden 22 shows its text passed through).
    """

    def __init__(self, package: Any) -> None:
        super().__init__()
        self.__package = normalize_to_list_of_substitutions(package)

    @property
    def package(self) -> list[Substitution]:
        return self.__package

    def find(self, package_name: str) -> str:
        raise NotImplementedError

    def perform(self, context: LaunchContext) -> str:
        return self.find(perform_substitutions(context, self.__package))

    def describe(self) -> str:
        """Return e.g. FindPackageShare(pkg='demo'), as Jazzy's `ros2 launch -p` shows it."""
        return f"{type(self).__name__}(pkg={' + '.join(s.describe() for s in self.__package)})"


class FindPackagePrefix(FindPackage):
    """The install prefix of a package (`<prefix>`, which holds lib/ and share/)."""

    def find(self, package_name: str) -> str:
        return get_package_prefix(package_name)


class FindPackageShare(FindPackage):
    """The share directory of a package (`<prefix>/share/<package>`)."""

    def find(self, package_name: str) -> str:
        return get_package_share_directory(package_name)
