"""mkdocs hook: lessons become executed notebook pages of the site.

- on_config: read and check every lesson and the glossary, build the
  navigation (chapter -> layer -> lesson) from metadata;
- on_files (before mkdocs-jupyter): build the snippets workspace, execute
  stale lessons (cached by content, two at a time) and add the executed
  notebooks to the site, each with its handout without solutions
  (handout.py), with a generated page per chapter and per layer;
  mkdocs-jupyter renders the notebooks;
- on_page_content: snippet title bars, folded solutions, header box (with what
  produced the outputs: parity_record.provenance), Key
  points box, glossary links and tabs (render.py), a TOC that keeps the code of
  headings (page_toc.py); an image without a description fails the build;
- on_page_context: "edit this page" of a lesson opens its .md source.

Any failing check or cell fails the build with a message naming the lesson.
``mkdocs serve`` watches lessons/ and snippets/, and the cache makes a
rebuild re-execute only lessons whose content or snippets changed.
"""
from __future__ import annotations

import logging
from pathlib import Path

import nbformat
from bs4 import BeautifulSoup
from mkdocs.exceptions import PluginError
from mkdocs.plugins import event_priority
from mkdocs.structure.files import File, Files
from mkdocs.structure.toc import get_toc
from mkdocs.utils import get_relative_url

from textbook import glossary, parity_record, paths
from textbook.execute import LessonExecutionError, publish_all
from textbook.handout import handout_name, without_solutions
from textbook.header import header_html
from textbook.lessons import Lesson, load_all
from textbook.nav import build_nav, part_pages
from textbook.page_toc import toc_tokens
from textbook.render import LessonPage, finish_lesson_html, images_without_description
from textbook.tabs import TabsError
from textbook.workspace import WorkspaceBuildError, ensure_built

log = logging.getLogger('mkdocs.hooks.textbook')
GLOSSARY_PAGE = 'glossary.md'
_lessons: list[Lesson] = []
_glossary: list[glossary.Entry] = []
_parity_record: dict[str, dict] = {}


def on_config(config):
    global _lessons, _glossary, _parity_record
    try:
        _lessons = load_all()
        _glossary = glossary.load()
        _parity_record = parity_record.load()
    except ValueError as error:
        raise PluginError(f'lesson check failed:\n{error}') from None
    config['nav'] = build_nav(_lessons, glossary=GLOSSARY_PAGE, reference=reference_pages())
    return config


def reference_pages(docs: Path = paths.DOCS) -> list[tuple[str, str]]:
    """(title, page) of every docs/reference/ page, titled by its first heading."""
    pages = []
    for path in sorted((docs / 'reference').glob('*.md')):
        heading = next((line[2:].strip() for line in path.read_text().splitlines()
                        if line.startswith('# ')), path.stem)
        pages.append((heading, path.relative_to(docs).as_posix()))
    return pages


@event_priority(100)  # before mkdocs-jupyter turns .ipynb files into pages
def on_files(files: Files, config) -> Files:
    try:
        ensure_built()
        published = publish_all(_lessons)
    except (LessonExecutionError, WorkspaceBuildError) as error:
        raise PluginError(f'lesson execution failed:\n{error}') from None
    for lesson in _lessons:
        log.info('lesson %s -> %s', lesson.source, paths.rel(published[lesson.source]))
        files.append(File(lesson.site_path, src_dir=str(paths.NOTEBOOKS),
                          dest_dir=config['site_dir'],
                          use_directory_urls=config['use_directory_urls']))
        files.append(_handout_file(lesson, published[lesson.source], config))
    for site_path, markdown in part_pages(_lessons).items():
        files.append(File.generated(config, site_path, content=markdown))
    return files


def _handout_file(lesson: Lesson, executed: Path, config) -> File:
    """The lesson's notebook without solutions, beside the executed notebook that
    mkdocs-jupyter puts in the page's folder (the theme links both)."""
    stem = Path(lesson.site_path).stem
    handout = without_solutions(nbformat.read(executed, as_version=4))
    site_path = f'{Path(lesson.site_path).with_suffix("").as_posix()}/{handout_name(stem)}'
    return File.generated(config, site_path, content=nbformat.writes(handout))


def _lesson_of(page) -> Lesson | None:
    return next((lesson for lesson in _lessons if lesson.site_path == page.file.src_uri), None)


def _url_from(page, files: Files, src_uri: str) -> str:
    return get_relative_url(files.get_file_from_path(src_uri).url, page.url)


def on_page_content(html: str, page, config, files) -> str:
    lesson = _lesson_of(page)
    if lesson is None:
        return html
    by_id = {other.id: other for other in _lessons}
    prerequisites = [(by_id[prereq].title, _url_from(page, files, by_id[prereq].site_path))
                     for prereq in lesson.meta['prerequisites']]
    try:
        executed = nbformat.read(paths.NOTEBOOKS / lesson.site_path, as_version=4)
        outputs = parity_record.provenance(lesson, executed, _parity_record)
        finished = finish_lesson_html(html, LessonPage(
            header=header_html(lesson.meta, prerequisites, outputs), glossary=_glossary,
            glossary_url=_url_from(page, files, GLOSSARY_PAGE)))
    except TabsError as error:
        raise PluginError(f'{lesson.source}: {error}') from None
    soup = BeautifulSoup(finished, 'html.parser')
    missing = images_without_description(soup)
    if missing:
        raise PluginError(f'{lesson.source}: {len(missing)} picture(s) without a description '
                          f'(alt text); draw graphs with labkit.draw_graph, which adds one')
    page.toc = get_toc(toc_tokens(soup))
    return finished


def on_page_context(context, page, config, nav):
    lesson = _lesson_of(page)
    if lesson is not None and config.get('repo_url') and config.get('edit_uri'):
        page.edit_url = source_edit_url(config['repo_url'], config['edit_uri'], lesson.source)
    return context


def source_edit_url(repo_url: str, edit_uri: str, source: str) -> str:
    """The edit link of a repository file: ``edit_uri`` names docs/, so the
    repository root is one folder up (``edit/main/docs/`` -> ``edit/main/``)."""
    root = edit_uri.strip('/').rsplit('/', 1)[0]
    return f"{repo_url.rstrip('/')}/{root}/{source}"
