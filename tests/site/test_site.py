"""`mkdocs build --strict` succeeds and the pages show executed output."""
from __future__ import annotations

import html
from pathlib import Path

import nbformat
import pytest
from bs4 import BeautifulSoup
from textbook.handout import handout_name
from textbook.lessons import load_all

# One worker builds the site once for all site tests; lessons the lesson tests
# executed come from the cache, the others the build executes itself.
pytestmark = pytest.mark.xdist_group('site')


def page_text(site, page: str) -> str:
    return html.unescape(BeautifulSoup((site / page).read_text(), 'html.parser').get_text())


@pytest.mark.timeout(1800)
def test_pilot_page_shows_its_executed_output(site):
    text = page_text(site, 'ch06/L1/00_setup_check/index.html')
    assert '[sensor_publisher]: Reading #' in text
    assert '[data_processor]: Received ' in text
    assert 'sensor_publisher exited with code 0' in text
    assert 'Summary: 1 package finished' in text or 'Summary: ' in text


@pytest.mark.timeout(1800)
def test_pilot_page_has_titled_snippets_and_a_download(site):
    page = BeautifulSoup((site / 'ch06/L1/00_setup_check/index.html').read_text(),
                         'html.parser')
    titles = [span.text for span in page.select('div.highlight > span.filename')]
    assert 'snippets/my_robot_pkg/setup.py' in titles
    assert page.select_one('a[title="Download the executed notebook"]') is not None
    notebook = nbformat.read(site / 'ch06/L1/00_setup_check/00_setup_check.ipynb', as_version=4)
    outputs = ''.join(out.get('text', '') for cell in notebook.cells
                      for out in cell.get('outputs', []))
    assert '[data_processor]: Received ' in outputs


@pytest.mark.timeout(1800)
def test_navigation_is_chapter_layer_lesson(site):
    text = page_text(site, 'index.html')
    for label in ('Chapter 6 · Building Robot Systems', 'L1 · Manual Foundation',
                  'Set up and check your environment', 'Glossary',
                  'Spec files: the system you meant to build'):
        assert label in text


@pytest.mark.timeout(1800)
def test_every_lesson_page_offers_a_handout_without_solutions(site):
    """Beside the executed notebook, the same without its solution cells (to hand out),
    and the page says what produced its outputs."""
    for lesson in load_all():
        folder = site / lesson.site_path.removesuffix('.ipynb')
        page = BeautifulSoup((folder / 'index.html').read_text(), 'html.parser')
        name = handout_name(Path(lesson.site_path).name)
        link = page.select_one('a[title="Download the notebook without solutions (to hand out)"]')
        assert link is not None and link['href'].endswith(name), lesson.source
        executed = nbformat.read(folder / Path(lesson.site_path).name, as_version=4)
        handout = nbformat.read(folder / name, as_version=4)
        tagged = [cell for cell in executed.cells if 'solution' in cell.metadata.get('tags', [])]
        assert len(handout.cells) == len(executed.cells) - len(tagged), lesson.source
        assert not any('solution' in cell.metadata.get('tags', []) for cell in handout.cells)
        outputs = page.select_one('.textbook-outputs')
        assert outputs is not None and 'executed on' in outputs.get_text(), lesson.source
