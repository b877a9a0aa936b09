"""An XML element seen as a launch front-end Entity."""
from __future__ import annotations

import xml.etree.ElementTree as ET
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


class Entity(BaseEntity):
    """Attributes are XML attributes (text, coerced on read); children are child elements.

    `name-sep="S"` next to an attribute turns its text into a list split on S.
    Reading is tracked so that attributes nobody read (typos) are reported.
    """

    def __init__(self, xml_element: ET.Element, *, parent: BaseEntity | None = None) -> None:
        self.__element = xml_element
        self.__parent = parent
        self.__read_attributes: set = set()

    @property
    def type_name(self) -> str:
        """The tag."""
        return self.__element.tag

    @property
    def parent(self) -> BaseEntity | None:
        """The enclosing entity."""
        return self.__parent

    @property
    def children(self) -> list[BaseEntity]:
        """Every child element."""
        return [Entity(child, parent=self) for child in self.__element]

    def get_attr(self, name: str, *, data_type: Any = str, optional: bool = False,
                 can_be_str: bool = True) -> Any:
        """Return attribute `name` (or the child elements `name` for List[Entity])."""
        if is_entity_list_type(data_type):
            children = [Entity(child, parent=self) for child in self.__element
                        if child.tag == name]
            if not children and not optional:
                raise attribute_not_found(name, data_type, self.type_name)
            return children or None
        attributes = self.__element.attrib
        if name not in attributes:
            if optional:
                return None
            raise attribute_not_found(name, data_type, self.type_name)
        self.__read_attributes.add(name)
        value: Any = attributes[name]
        separator = attributes.get(f'{name}-sep')
        if separator is not None:
            self.__read_attributes.add(f'{name}-sep')
            value = value.split(separator)
        return get_typed_value(value, data_type, can_be_str)

    def assert_entity_completely_parsed(self) -> None:
        """ValueError naming the attributes nobody read."""
        unread = set(self.__element.attrib) - self.__read_attributes
        if unread:
            raise unexpected_attributes(self.type_name, unread)
