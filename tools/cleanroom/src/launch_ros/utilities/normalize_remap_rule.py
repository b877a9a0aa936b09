"""Remapping rules: `(from, to)` pairs of strings or substitutions."""
from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launch import LaunchContext
from launch.utilities import normalize_to_list_of_substitutions

from .substitution_values import perform_text

NormalizedRemapRule = tuple[list[Any], list[Any]]


def normalize_remap_rule(rule: Any) -> NormalizedRemapRule:
    if not isinstance(rule, (tuple, list)) or len(rule) != 2:
        raise TypeError(f'a remapping rule must be a (from, to) pair, got {rule!r}')
    return (normalize_to_list_of_substitutions(rule[0]),
            normalize_to_list_of_substitutions(rule[1]))


def normalize_remap_rules(rules: Iterable[Any]) -> list[NormalizedRemapRule]:
    if isinstance(rules, (str, dict)):
        raise TypeError(f"'remappings' must be a list of (from, to) pairs, got {rules!r}")
    return [normalize_remap_rule(rule) for rule in rules]


def evaluate_remap_rules(context: LaunchContext,
                         rules: Iterable[NormalizedRemapRule]) -> list[tuple[str, str]]:
    return [(perform_text(context, src), perform_text(context, dst)) for src, dst in rules]
