"""Full ROS names: built, split and checked for hiddenness, as rclpy gives them apart."""
from __future__ import annotations


def full_name(name: str, namespace: str) -> str:
    """`/ns` + `name` -> `/ns/name` (the root namespace gives `/name`).

    rclpy's graph queries give a node's name and namespace apart; listings
    and lookups use the one full name.
    """
    return namespace.rstrip('/') + '/' + name


def split_full_name(full: str) -> tuple[str, str]:
    """`/ns/name` -> (`name`, `/ns`); a name without a slash is in `/`.

    The reverse of :func:`full_name`, for rclpy's by-node queries.
    """
    full = full if full.startswith('/') else '/' + full
    namespace, _, name = full.rpartition('/')
    return name, namespace or '/'


def is_hidden(name: str) -> bool:
    """ROS hides any node, topic or service with a name token starting with `_`.

    That is how labkit's observer and the `ros2` command's own node stay out
    of the listings they make.
    """
    return any(token.startswith('_') for token in name.split('/') if token)
