"""ROS namespace arithmetic shared by Node, PushRosNamespace and LifecycleNode.

Kept free of launch imports: the rules are pure string functions and are
tested on their own.
"""
from __future__ import annotations


def is_namespace_absolute(ns: str) -> bool:
    """A namespace starting with '/' ignores every pushed namespace."""
    return ns.startswith('/')


def is_root_namespace(ns: str) -> bool:
    return ns == '/'


def make_namespace_absolute(ns: str | None) -> str | None:
    """Give a relative namespace a leading '/' (ROS resolves them from the root); None stays
    None, as in Jazzy."""
    if ns is None or is_namespace_absolute(ns):
        return ns
    return '/' + ns


def prefix_namespace(base_ns: str | None, ns: str | None) -> str | None:
    """Compose a pushed namespace with a node's (or another push's) namespace.

    An absolute `ns` replaces the base, a relative one is appended to
    it, and a missing one leaves the base as it was.  Empty strings count as
    missing, the way `Node(namespace='')` means "no namespace".
    """
    if not ns:
        return base_ns or None
    if is_namespace_absolute(ns) or not base_ns:
        return ns
    return base_ns.rstrip('/') + '/' + ns


def full_node_namespace(pushed: str | None, namespace: str | None) -> str | None:
    """The absolute namespace a node ends up in, or None if it has none at all.

    A namespace given as '' outside any push is the root: Jazzy passes `-r __ns:=/`.
    """
    composed = prefix_namespace(pushed, namespace)
    if composed is None:
        return None if namespace is None else '/'
    return make_namespace_absolute(composed)


def fully_qualified_name(namespace: str | None, name: str) -> str:
    """'/ns/name' as ROS prints it ('/name' in the root namespace)."""
    if not namespace or is_root_namespace(namespace):
        return '/' + name
    return namespace.rstrip('/') + '/' + name
