"""Remapping rules: `(from, to)` pairs of strings or substitutions.

As in Jazzy, a rule must be a tuple of two, each side becoming a tuple of
substitutions; `normalize_remap_rules` is a generator (nothing is checked
before it is iterated).
"""
from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import Any

from launch import Substitution
from launch.utilities import ensure_argument_type, normalize_to_list_of_substitutions

NormalizedRemapRule = tuple[tuple[Substitution, ...], tuple[Substitution, ...]]


def normalize_remap_rule(remap_rule: Any) -> NormalizedRemapRule:
    ensure_argument_type(remap_rule, (tuple,), 'remap_rule')
    if len(remap_rule) != 2:
        raise TypeError(f'remap_rule must be a tuple of length 2, got length {len(remap_rule)}')
    return (tuple(normalize_to_list_of_substitutions(remap_rule[0])),
            tuple(normalize_to_list_of_substitutions(remap_rule[1])))


def normalize_remap_rules(remap_rules: Iterable[Any]) -> Iterator[NormalizedRemapRule]:
    for remap_rule in remap_rules:
        yield normalize_remap_rule(remap_rule)
