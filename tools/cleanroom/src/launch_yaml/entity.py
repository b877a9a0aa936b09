"""A YAML mapping seen as a launch front-end Entity."""
from __future__ import annotations

from typing import Any

from launch.frontend.entity import (
    Entity as BaseEntity,
)
from launch.frontend.entity import (
    attribute_not_found,
    is_entity_list_type,
    unexpected_attributes,
)
from launch.frontend.type_utils import get_typed_value


def entities_of(items: Any, type_name: str | None, parent: BaseEntity | None
                ) -> list[Entity]:
    """Entities of a YAML list: `[{tag: {...}}, ...]`, or `[{...}]` all of `type_name`."""
    if not isinstance(items, list):
        raise TypeError(f'Expected a list of entities, got {type(items)}')
    result = []
    for item in items:
        if type_name is None:
            if not isinstance(item, dict) or len(item) != 1:
                raise RuntimeError('Expected a dictionary with one key (the entity type)')
            (tag, body), = item.items()
            result.append(Entity(body if body is not None else {}, tag, parent=parent))
        else:
            result.append(Entity(item, type_name, parent=parent))
    return result


class Entity(BaseEntity):
    """Attributes are the keys of the mapping (already typed by YAML); children in `children`."""

    def __init__(self, element: Any, type_name: str, *,
                 parent: BaseEntity | None = None) -> None:
        if not isinstance(element, dict):
            raise TypeError(f"Entity '{type_name}' expected a mapping, got {type(element)}")
        self.__element = element
        self.__type_name = type_name
        self.__parent = parent
        self.__read_keys: set = set()

    @property
    def type_name(self) -> str:
        """The key this mapping was under."""
        return self.__type_name

    @property
    def parent(self) -> BaseEntity | None:
        """The enclosing entity."""
        return self.__parent

    @property
    def children(self) -> list[BaseEntity]:
        """The entities listed under `children:`."""
        self.__read_keys.add('children')
        return entities_of(self.__element.get('children', []), None, self)

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """Return key `name` (or the list of mappings under it for List[Entity])."""
        if name not in self.__element:
            if optional:
                return None
            raise attribute_not_found(name, data_type, self.type_name)
        self.__read_keys.add(name)
        value = self.__element[name]
        if is_entity_list_type(data_type):
            return entities_of(value, name, self)
        if data_type is None:
            return value  # typed by YAML already: "42" stays text
        if data_type is str and isinstance(value, (bool, int, float)):
            return str(value)
        return get_typed_value(value, data_type, can_be_str)

    def assert_entity_completely_parsed(self) -> None:
        """ValueError naming the keys nobody read."""
        unread = set(self.__element) - self.__read_keys
        if unread:
            raise unexpected_attributes(self.type_name, unread)
