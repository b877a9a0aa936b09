"""Site navigation from lesson metadata: Chapter -> teaching layer -> lesson."""
from __future__ import annotations

from itertools import groupby
from typing import Any

from .lessons import Lesson
from .metadata import CHAPTERS, LAYERS


def chapter_label(chapter: int) -> str:
    return f"Chapter {chapter} · {CHAPTERS[chapter]}"


def layer_label(layer: str) -> str:
    return f"{layer} · {LAYERS[layer]}"


def build_nav(lessons: list[Lesson], home: str = "index.md") -> list[Any]:
    """The mkdocs ``nav`` value; lessons keep their file order inside a layer."""
    ordered = sorted(lessons, key=lambda lesson: (lesson.meta["chapter"], lesson.meta["layer"],
                                                  lesson.path.name))
    nav: list[Any] = [{"Home": home}]
    for chapter, in_chapter in groupby(ordered, key=lambda lesson: lesson.meta["chapter"]):
        layers = []
        for layer, in_layer in groupby(in_chapter, key=lambda lesson: lesson.meta["layer"]):
            layers.append({layer_label(layer): [{lesson.title: lesson.site_path}
                                                for lesson in in_layer]})
        nav.append({chapter_label(chapter): layers})
    return nav
