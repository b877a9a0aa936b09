"""Evaluate a Python expression built from substitutions."""
from __future__ import annotations

import importlib
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from ..substitution import Substitution
from ..utilities import normalize_to_list_of_substitutions, perform_substitutions
from .substitution_failure import SubstitutionFailure

if TYPE_CHECKING:
    from ..launch_context import LaunchContext
    from ..some_substitutions_type import SomeSubstitutionsType


class PythonExpression(Substitution):
    """str(eval(expression)) with the given modules available.

    `math` is imported by default and its names are also available without
    the `math.` prefix, so `pi * 2` works as in older launch files.
    """

    def __init__(self, expression: SomeSubstitutionsType,
                 python_modules: Iterable[SomeSubstitutionsType] = ('math',)) -> None:
        super().__init__()
        self.__expression = normalize_to_list_of_substitutions(expression)
        if isinstance(python_modules, (str, Substitution)):  # one module, not its letters
            python_modules = [python_modules]
        self.__python_modules = [normalize_to_list_of_substitutions(m) for m in python_modules]

    @property
    def expression(self) -> list[Substitution]:
        """The expression, as substitutions."""
        return self.__expression

    @property
    def python_modules(self) -> list[list[Substitution]]:
        """The modules made available, as substitutions."""
        return self.__python_modules

    def describe(self) -> str:
        """Return the expression and the modules, as Jazzy's `ros2 launch -p` shows them."""
        def join(subs: list[Substitution]) -> str:
            return ' + '.join(s.describe() for s in subs)
        modules = ', '.join(join(m) for m in self.__python_modules)
        return f'PythonExpr({join(self.__expression)}, [{modules}])'

    def perform(self, context: LaunchContext) -> str:
        """Evaluate the expression and return str() of the result."""
        namespace: dict[str, Any] = {}
        for module_subs in self.__python_modules:
            name = perform_substitutions(context, module_subs)
            module = importlib.import_module(name)
            if name == 'math':
                namespace.update({k: v for k, v in vars(module).items()
                                  if not k.startswith('_')})
            namespace[name.split('.')[0]] = importlib.import_module(name.split('.')[0])
        expression = perform_substitutions(context, self.__expression)
        try:
            return str(eval(expression, namespace))
        except Exception as exc:
            raise SubstitutionFailure(
                f"PythonExpression failed to evaluate '{expression}': {exc}") from exc
