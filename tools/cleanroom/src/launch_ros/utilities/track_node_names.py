"""Count node names started within one launch (Jazzy's add_node_name API)."""
from __future__ import annotations

import weakref
from collections import Counter

from launch import LaunchContext

_counts: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def add_node_name(context: LaunchContext, node_name: str) -> None:
    """Record one more node called `node_name` (fully qualified) in this launch."""
    _counts.setdefault(context, Counter())[node_name] += 1


def get_node_name_count(context: LaunchContext, node_name: str) -> int:
    return _counts.get(context, Counter())[node_name]
