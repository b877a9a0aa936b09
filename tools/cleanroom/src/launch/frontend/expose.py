"""Registries of the tags and substitutions a front end understands.

`expose_action('tag')` / `expose_substitution('name')` register a class whose
`parse` classmethod turns an Entity (or substitution arguments) into the
keyword arguments of its constructor; packages (launch_ros) register theirs
when the parser loads its launch extensions.
"""
from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ..substitution import Substitution
    from .entity import Entity

ActionParseMethod = Callable[['Entity', Any], tuple[type, dict[str, Any]]]
SubstitutionParseMethod = Callable[[list[list['Substitution']]], tuple[type, dict[str, Any]]]

action_parse_methods: dict[str, ActionParseMethod] = {}
substitution_parse_methods: dict[str, SubstitutionParseMethod] = {}


def register_action_parse_method(name: str, method: ActionParseMethod) -> None:
    """Make tag `name` parse with `method(entity, parser) -> (cls, kwargs)`."""
    action_parse_methods[name] = method


def register_substitution_parse_method(name: str, method: SubstitutionParseMethod) -> None:
    """Make `$(name ...)` parse with `method(args) -> (cls, kwargs)`."""
    substitution_parse_methods[name] = method


def expose_action(name: str) -> Callable[[type], type]:
    """Class decorator: tag `name` is parsed by the class's `parse(entity, parser)`."""
    def decorator(cls: type) -> type:
        register_action_parse_method(name, cls.parse)
        return cls
    return decorator


def expose_substitution(name: str) -> Callable[[type], type]:
    """Class decorator: `$(name ...)` is parsed by the class's `parse(args)`."""
    def decorator(cls: type) -> type:
        register_substitution_parse_method(name, cls.parse)
        return cls
    return decorator


def instantiate_action(entity: Entity, parser: Any) -> Any:
    """Build the action of `entity` with its registered parse method."""
    action_type, kwargs = action_parse_methods[entity.type_name](entity, parser)
    return action_type(**kwargs)


def instantiate_substitution(name: str, args: list[list[Substitution]]) -> Substitution:
    """Build the substitution `$(name args...)`; RuntimeError for an unknown name."""
    if name not in substitution_parse_methods:
        raise RuntimeError(f'Unknown substitution: {name}')
    substitution_type, kwargs = substitution_parse_methods[name](args)
    return substitution_type(**kwargs)
