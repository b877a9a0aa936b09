"""Navigation from metadata, snippet title bars and folded solutions."""
from __future__ import annotations

from types import SimpleNamespace

from bs4 import BeautifulSoup
from textbook.mkdocs_hook import source_edit_url
from textbook.nav import build_nav, part_pages
from textbook.render import finish_lesson_html


def fake_lesson(chapter, layer, name, title):
    return SimpleNamespace(meta={'chapter': chapter, 'layer': layer, 'duration_minutes': 30,
                                 'proficiency': 'B1'}, title=title,
                           path=SimpleNamespace(name=name),
                           site_path=f'ch{chapter:02d}/{layer}/{name[:-3]}.ipynb')


def test_nav_is_chapter_then_layer_then_lesson_with_a_page_for_each_part():
    nav = build_nav([
        fake_lesson(7, 'L1', '00_a.md', 'Capstone A'),
        fake_lesson(6, 'L2', '08_b.md', 'AI B'),
        fake_lesson(6, 'L1', '01_c.md', 'Second'),
        fake_lesson(6, 'L1', '00_d.md', 'First'),
    ], glossary='glossary.md', reference=[('Spec files', 'reference/spec-files.md')])
    assert nav == [
        {'Home': 'index.md'},
        {'Chapter 6 · Building Robot Systems': [
            'ch06/index.md',
            {'L1 · Manual Foundation': ['ch06/L1/index.md', {'First': 'ch06/L1/00_d.ipynb'},
                                        {'Second': 'ch06/L1/01_c.ipynb'}]},
            {'L2 · AI Collaboration': ['ch06/L2/index.md', {'AI B': 'ch06/L2/08_b.ipynb'}]},
            {'L3 · Intelligence Design': ['ch06/L3/index.md']},
            {'L4 · Spec-Driven': ['ch06/L4/index.md']},
        ]},
        {'Chapter 7 · Capstone': [
            'ch07/index.md',
            {'L1 · Manual Foundation': ['ch07/L1/index.md', {'Capstone A': 'ch07/L1/00_a.ipynb'}]},
        ]},
        {'Glossary': 'glossary.md'},
        {'Reference': [{'Spec files': 'reference/spec-files.md'}]},
    ]


def test_layer_page_links_written_lessons_and_names_the_missing_ones():
    lessons = [fake_lesson(6, 'L1', '00_d.md', 'First'), fake_lesson(6, 'L1', '01_c.md', 'Second')]
    pages = part_pages(lessons)
    layer = pages['ch06/L1/index.md']
    assert '- 6.0 [First](../../ch06/L1/00_d.ipynb) (30 min, level B1)' in layer
    assert '- 6.7 *(not written yet)*' in layer
    assert 'by hand' in layer
    assert '- 6.8 *(not written yet)*' in pages['ch06/L2/index.md']
    assert '- 7.3 *(not written yet)*' in pages['ch07/index.md']
    assert '[L1 · Manual Foundation](L1/index.md)' in pages['ch06/index.md']


def test_snippet_title_moves_into_the_code_block():
    html = ('<div class="snippet-title">snippets/p/setup.py</div>\n'
            '<div class="highlight"><pre>x = 1</pre></div>')
    soup = BeautifulSoup(finish_lesson_html(html), 'html.parser')
    block = soup.select_one('div.highlight')
    assert block.select_one('span.filename').text == 'snippets/p/setup.py'
    assert soup.select('div.snippet-title') == []


def code_cell(text, tag=''):
    """A code cell as mkdocs-jupyter renders it: a tagged wrapper around a tagged cell."""
    tag = f' celltag_{tag}' if tag else ''
    return (f'<div class="jp-Cell jp-CodeCell{tag}"><div class="jp-Cell jp-CodeCell{tag}">'
            f'<pre>{text}</pre></div></div>')


def markdown_cell(text, tag=''):
    """A markdown cell: the tag sits on the rendered markdown inside the cell."""
    tag = f' celltag_{tag}' if tag else ''
    return (f'<div class="jp-Cell jp-MarkdownCell"><div class="jp-InputArea">'
            f'<div class="jp-RenderedMarkdown{tag}"><p>{text}</p></div></div></div>')


def test_consecutive_solution_cells_fold_into_one_closed_details():
    html = ('<div class="jp-Notebook">' + markdown_cell('task') +
            markdown_cell('explained', 'solution') + code_cell('answer', 'solution') +
            code_cell('next') + code_cell('a hint', 'hint') + '</div>')
    soup = BeautifulSoup(finish_lesson_html(html), 'html.parser')
    folded = soup.select('details')
    assert [d.summary.text for d in folded] == ['Solution', 'Hint']
    assert not any(d.has_attr('open') for d in folded)
    assert [c.get_text() for c in folded[0].find_all('div', class_='jp-Cell', recursive=False)] \
        == ['explained', 'answer']
    notebook = soup.select_one('div.jp-Notebook')
    assert [c.name for c in notebook.find_all(recursive=False)] == \
        ['div', 'details', 'div', 'details']
    assert not soup.select('details details'), 'folds must not nest'


def test_edit_link_of_a_lesson_opens_its_markdown_source():
    assert source_edit_url('https://github.com/o/r/', 'edit/main/docs/',
                           'lessons/ch06/L1/00_a.md') == \
        'https://github.com/o/r/edit/main/lessons/ch06/L1/00_a.md'
