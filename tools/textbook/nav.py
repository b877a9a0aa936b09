"""Site navigation from lesson metadata: Chapter -> teaching layer -> lesson.

Every chapter and every layer of the plan (:mod:`textbook.plan`) gets a page
of its own (``ch06/index.md``, ``ch06/L1/index.md``) that says what the part
is and lists its lessons, written or not yet; mkdocs-material shows it as
the section's index page.
"""
from __future__ import annotations

from itertools import groupby
from typing import Any

from .lessons import Lesson
from .metadata import CHAPTERS, LAYERS
from .plan import CHAPTER_PURPOSE, LAYER_PURPOSE, PLANNED, lesson_number, planned_numbers


def chapter_label(chapter: int) -> str:
    return f'Chapter {chapter} · {CHAPTERS[chapter]}'


def layer_label(layer: str) -> str:
    return f'{layer} · {LAYERS[layer]}'


def chapter_page(chapter: int) -> str:
    return f'ch{chapter:02d}/index.md'


def layer_page(chapter: int, layer: str) -> str:
    return f'ch{chapter:02d}/{layer}/index.md'


def _layers_of(chapter: int) -> list[str]:
    return [layer for (ch, layer) in PLANNED if ch == chapter and layer is not None]


def _ordered(lessons: list[Lesson]) -> list[Lesson]:
    return sorted(lessons, key=lambda lesson: (lesson.meta['chapter'], lesson.meta['layer'],
                                               lesson.path.name))


def build_nav(lessons: list[Lesson], home: str = 'index.md',
              glossary: str | None = None,
              reference: list[tuple[str, str]] | None = None) -> list[Any]:
    """The mkdocs ``nav`` value; lessons keep their file order inside a layer.

    ``reference``: (title, page) of the reference pages, listed after the glossary.
    """
    by_part = {key: list(group) for key, group in groupby(
        _ordered(lessons), key=lambda lesson: (lesson.meta['chapter'], lesson.meta['layer']))}
    chapters = sorted({chapter for chapter, _ in PLANNED} | {c for c, _ in by_part})
    nav: list[Any] = [{'Home': home}]
    for chapter in chapters:
        layers = sorted(set(_layers_of(chapter)) | {lay for c, lay in by_part if c == chapter})
        entries: list[Any] = [chapter_page(chapter)]
        for layer in layers:
            entries.append({layer_label(layer): [layer_page(chapter, layer)] + [
                {lesson.title: lesson.site_path} for lesson in by_part.get((chapter, layer), [])]})
        nav.append({chapter_label(chapter): entries})
    if glossary:
        nav.append({'Glossary': glossary})
    if reference:
        nav.append({'Reference': [{title: page} for title, page in reference]})
    return nav


def _lesson_list(lessons: list[Lesson], numbers: list[str], from_page: str) -> list[str]:
    """Markdown list items: written lessons linked, planned ones marked as such."""
    depth = from_page.count('/')
    written = {lesson_number(lesson.meta['chapter'], lesson.path.name): lesson
               for lesson in lessons}
    items = []
    for number in sorted(set(numbers) | set(written), key=lambda n: int(n.split('.')[1])):
        lesson = written.get(number)
        if lesson is None:
            items.append(f'- {number} *(not written yet)*')
        else:
            link = '../' * depth + lesson.site_path
            items.append(f"- {number} [{lesson.title}]({link}) "
                         f"({lesson.meta['duration_minutes']} min, "
                         f"level {lesson.meta['proficiency']})")
    return items


def layer_markdown(chapter: int, layer: str, lessons: list[Lesson]) -> str:
    """The page of one layer of a chapter."""
    page = layer_page(chapter, layer)
    mine = [lesson for lesson in _ordered(lessons)
            if (lesson.meta['chapter'], lesson.meta['layer']) == (chapter, layer)]
    numbers = planned_numbers(chapter, layer) if (chapter, layer) in PLANNED else []
    return '\n'.join([f'# {chapter_label(chapter)}: {layer_label(layer)}', '',
                      LAYER_PURPOSE[layer], '', '## Lessons', '',
                      *_lesson_list(mine, numbers, page), ''])


def chapter_markdown(chapter: int, lessons: list[Lesson]) -> str:
    """The page of a chapter: what it covers, then each layer and its lessons."""
    page = chapter_page(chapter)
    mine = [lesson for lesson in _ordered(lessons) if lesson.meta['chapter'] == chapter]
    lines = [f'# {chapter_label(chapter)}', '', CHAPTER_PURPOSE[chapter], '']
    if (chapter, None) in PLANNED:
        lines += ['## Lessons', '', *_lesson_list(mine, planned_numbers(chapter, None), page)]
    for layer in sorted(set(_layers_of(chapter)) | {lesson.meta['layer'] for lesson in mine}):
        in_layer = [lesson for lesson in mine if lesson.meta['layer'] == layer]
        numbers = planned_numbers(chapter, layer) if (chapter, layer) in PLANNED else []
        lines += [f'## [{layer_label(layer)}]({layer}/index.md)', '', LAYER_PURPOSE[layer], '',
                  *_lesson_list(in_layer, numbers, page), '']
    return '\n'.join(lines) + '\n'


def part_pages(lessons: list[Lesson]) -> dict[str, str]:
    """Every chapter and layer page: site path -> markdown."""
    pages = {}
    chapters = {chapter for chapter, _ in PLANNED} | {les.meta['chapter'] for les in lessons}
    for chapter in sorted(chapters):
        pages[chapter_page(chapter)] = chapter_markdown(chapter, lessons)
        layers = set(_layers_of(chapter)) | {les.meta['layer'] for les in lessons
                                             if les.meta['chapter'] == chapter}
        for layer in sorted(layers):
            pages[layer_page(chapter, layer)] = layer_markdown(chapter, layer, lessons)
    return pages
