"""The format-independent view of one element of a front-end launch file."""
from __future__ import annotations

from typing import Any


class Entity:
    """One tag (XML) or mapping (YAML) of a launch file, read attribute by attribute.

    Format packages (launch_xml, launch_yaml) subclass it; the parse methods of
    actions only use this interface, so one parse method serves every format.
    """

    @property
    def type_name(self) -> str:
        """The tag name, e.g. 'node'."""
        raise NotImplementedError

    @property
    def parent(self) -> Entity | None:
        """The enclosing entity, None for the root."""
        raise NotImplementedError

    @property
    def children(self) -> list[Entity]:
        """The nested entities (XML child elements, YAML `children:`)."""
        raise NotImplementedError

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """Return attribute `name` coerced to `data_type`.

        `data_type=List[Entity]` returns the nested entities called `name`;
        `data_type=None` infers the type of the text as YAML does.  A missing
        attribute is None when `optional`, else an AttributeError.
        """
        raise NotImplementedError

    def assert_entity_completely_parsed(self) -> None:
        """Raise ValueError naming the attributes no parse method read (typos)."""
        raise NotImplementedError


def is_entity_list_type(data_type: Any) -> bool:
    """True for `List[Entity]` (and `list` of a subclass), the nested-entities request."""
    args = getattr(data_type, '__args__', None)
    origin = getattr(data_type, '__origin__', None)
    return (origin is list and bool(args) and isinstance(args[0], type)
            and issubclass(args[0], Entity))


def attribute_not_found(name: str, data_type: Any, type_name: str) -> AttributeError:
    """The error Jazzy raises for a missing mandatory attribute."""
    return AttributeError(
        f"Attribute '{name}' of type '{data_type}' not found in Entity '{type_name}'")


def unexpected_attributes(type_name: str, names: set) -> ValueError:
    """The error Jazzy raises for attributes nobody read."""
    return ValueError(f'Unexpected attribute(s) found in `{type_name}`: {names}')


EntityListType: type = list[Entity]
