"""SetUseSimTime: shorthand for SetParameter('use_sim_time', <bool>)."""
from __future__ import annotations

from typing import Any

from ..parameter_descriptions import ParameterValue
from .set_parameter import SetParameter


class SetUseSimTime(SetParameter):
    """Make every node in scope use (or not use) simulated time; the value must be a bool."""

    def __init__(self, value: Any, **kwargs: Any) -> None:
        super().__init__('use_sim_time', ParameterValue(value, value_type=bool), **kwargs)
