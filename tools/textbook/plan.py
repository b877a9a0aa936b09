"""The book's plan: which lessons each chapter and layer will have.

The chapter and layer pages list the written lessons (from their metadata)
and say which planned ones are not written yet.
"""
from __future__ import annotations

#: (chapter, layer or None) -> (first, last) lesson number of that part.
PLANNED: dict[tuple[int, str | None], tuple[int, int]] = {
    (6, 'L1'): (0, 7),
    (6, 'L2'): (8, 10),
    (6, 'L3'): (11, 13),
    (6, 'L4'): (14, 15),
    (7, None): (1, 3),
}

LAYER_PURPOSE = {
    'L1': 'You write and run every file by hand, and understand every line of it.',
    'L2': 'You work with an AI assistant, and check what it gives you against the '
          'running system.',
    'L3': 'You design reusable pieces (launch files, configurations, packages) and the '
          'reasoning behind them.',
    'L4': 'You start from a written specification and build a system that provably '
          'meets it.',
}

CHAPTER_PURPOSE = {
    6: 'From two nodes in two terminals to launch files that start a whole robot with '
       'namespaces, parameters, arguments and conditions, packaged like any ROS 2 package.',
    7: 'A system of your own, built with everything Chapter 6 taught.',
}


def lesson_number(chapter: int, file_name: str) -> str:
    """``6.3`` for ``03_launch_arguments.md`` in chapter 6."""
    return f"{chapter}.{int(file_name.split('_', 1)[0])}"


def planned_numbers(chapter: int, layer: str | None) -> list[str]:
    first, last = PLANNED[(chapter, layer)]
    return [f'{chapter}.{n}' for n in range(first, last + 1)]
