"""How often messages arrive on topics, and how large they are, measured over
a bounded window.

speccheck's (`speccheck.rates`, one copy for both tools; its docstring says
how the subscriptions are made), under the name lessons and graders use, raising
LabkitError.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from speccheck import rates
from speccheck.rates import QUEUE_DEPTH, Rate, matching_qos, wait_for_publishers

from labkit.errors import as_labkit_error

__all__ = ['QUEUE_DEPTH', 'Rate', 'matching_qos', 'measure_rates', 'message_class',
           'wait_for_publishers']


def message_class(type_name: str) -> Any:
    """'std_msgs/msg/Float32' -> the std_msgs.msg.Float32 class."""
    with as_labkit_error():
        return rates.message_class(type_name)


def measure_rates(topics: Mapping[str, str], window: float = 3.0,
                  discovery: float = 5.0) -> dict[str, Rate]:
    """Rate and mean message size of each topic (name -> message type name),
    all measured in one window (see :func:`speccheck.rates.measure_rates`)."""
    with as_labkit_error():
        return rates.measure_rates(topics, window, discovery)
