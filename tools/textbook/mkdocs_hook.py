"""mkdocs hook: lessons become executed notebook pages of the site.

- on_config: read and check every lesson, build the navigation from metadata;
- on_files (before mkdocs-jupyter): build the snippets workspace, execute
  stale lessons (cached by content, two at a time) and add the executed
  notebooks to the site; mkdocs-jupyter renders them;
- on_page_content: snippet title bars and folded solutions (render.py).

Any failing check or cell fails the build with a message naming the lesson.
``mkdocs serve`` watches lessons/ and snippets/, and the cache makes a
rebuild re-execute only lessons whose content or snippets changed.
"""
from __future__ import annotations

import logging

from mkdocs.exceptions import PluginError
from mkdocs.plugins import event_priority
from mkdocs.structure.files import File, Files

from textbook import paths
from textbook.execute import LessonExecutionError, publish_all
from textbook.lessons import Lesson, load_all
from textbook.nav import build_nav
from textbook.render import finish_lesson_html
from textbook.workspace import WorkspaceBuildError, ensure_built

log = logging.getLogger("mkdocs.hooks.textbook")
_lessons: list[Lesson] = []


def on_config(config):
    global _lessons
    try:
        _lessons = load_all()
    except ValueError as error:
        raise PluginError(f"lesson check failed:\n{error}") from None
    config["nav"] = build_nav(_lessons)
    return config


@event_priority(100)  # before mkdocs-jupyter turns .ipynb files into pages
def on_files(files: Files, config) -> Files:
    try:
        ensure_built()
        published = publish_all(_lessons)
    except (LessonExecutionError, WorkspaceBuildError) as error:
        raise PluginError(f"lesson execution failed:\n{error}") from None
    for lesson in _lessons:
        log.info("lesson %s -> %s", lesson.source, paths.rel(published[lesson.source]))
        files.append(File(lesson.site_path, src_dir=str(paths.NOTEBOOKS),
                          dest_dir=config["site_dir"],
                          use_directory_urls=config["use_directory_urls"]))
    return files


def on_page_content(html: str, page, config, files) -> str:
    if page.file.src_uri.endswith(".ipynb"):
        return finish_lesson_html(html)
    return html
