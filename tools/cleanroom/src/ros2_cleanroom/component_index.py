"""The components packages register in the ament index (resource type `rclcpp_components`).

Each line of a package's resource is `plugin;library`; Jazzy lists the part
before the first `;` of every line as it is (blank lines included), packages
in the index's directory order.
"""
from __future__ import annotations

from ament_index_python import get_resource, get_resources, has_resource

RESOURCE_TYPE = 'rclcpp_components'


class PackageNotFound(LookupError):
    """The package is not in the ament index."""


def _types_in(content: str) -> list[str]:
    return [line.split(';')[0] for line in content.splitlines()]


def package_component_types(package: str) -> list[str]:
    """The component types of one package ([] if it registers none)."""
    if not has_resource('packages', package):
        raise PackageNotFound(package)
    if not has_resource(RESOURCE_TYPE, package):
        return []
    content, _ = get_resource(RESOURCE_TYPE, package)
    return _types_in(content)


def registered_component_types() -> list[tuple[str, list[str]]]:
    """(package, types) of every package that registers components."""
    return [(package, _types_in(get_resource(RESOURCE_TYPE, package)[0]))
            for package in get_resources(RESOURCE_TYPE)]
