"""Header box, Key points (check and box), glossary links and the TOC of a lesson page."""
from __future__ import annotations

import pytest
from bs4 import BeautifulSoup
from textbook import glossary, keypoints
from textbook.header import header_html
from textbook.page_toc import toc_tokens
from textbook.render import LessonPage, finish_lesson_html, images_without_description

META = {'duration_minutes': 45, 'proficiency': 'B1', 'hardware_tier': 1,
        'tier_1_path': 'Runs on a laptop.', 'learning_objectives': ['Write a <launch> file']}


def cell(inner: str) -> str:
    return (f'<div class="jp-Cell jp-MarkdownCell"><div class="jp-InputArea">'
            f'<div class="jp-RenderedMarkdown">{inner}</div></div></div>')


def test_header_shows_metadata_and_links_prerequisites():
    box = BeautifulSoup(header_html(META, [('Anatomy', '../01_anatomy/')]), 'html.parser')
    text = box.get_text(' ')
    for fact in ('45 min', 'B1', 'tier 1 (laptop only)', 'Runs on a laptop.',
                 'Write a <launch> file'):
        assert fact in text
    assert [(a.text, a['href']) for a in box.select('a')] == [('Anatomy', '../01_anatomy/')]


def test_header_without_prerequisites_says_start_here():
    assert 'start here' in BeautifulSoup(header_html(META, []), 'html.parser').get_text()


LESSON = '---\ntextbook: {}\n---\n# T\n\n## One\n\n```python\n## not a heading\n```\n'


def test_a_lesson_ending_in_key_points_passes():
    keypoints.check(LESSON + '## Key points\n\n- a\n', 'l.md')


def test_a_lesson_without_key_points_names_its_last_section_and_line():
    with pytest.raises(keypoints.KeyPointsError, match=r"^l\.md:6: the last section is '## One'"):
        keypoints.check(LESSON, 'l.md')


def test_a_lesson_with_no_sections_names_its_last_line():
    with pytest.raises(keypoints.KeyPointsError, match=r'^l\.md:2: the lesson has no'):
        keypoints.check('# T\ntext', 'l.md')


GLOSSARY = """# Glossary

## Launch argument {#launch-argument data-terms="launch argument|launch arguments"}

A named input of a `launch` file.

## Argument {#argument}

Anything.
"""


@pytest.fixture
def entries(tmp_path):
    path = tmp_path / 'glossary.md'
    path.write_text(GLOSSARY)
    return glossary.load(path)


def test_glossary_entries_have_terms_and_plain_definitions(entries):
    assert [(e.anchor, e.terms) for e in entries] == [
        ('launch-argument', ('launch argument', 'launch arguments')), ('argument', ('argument',))]
    assert entries[0].definition == 'A named input of a launch file.'


def test_a_malformed_glossary_entry_names_its_line(tmp_path):
    path = tmp_path / 'glossary.md'
    path.write_text('# G\n\n## Launch argument\n')
    with pytest.raises(glossary.GlossaryError, match=r'glossary\.md:3: a glossary entry is'):
        glossary.load(path)


def test_only_the_first_prose_use_is_linked_never_code_headings_or_links(entries):
    html = cell('<h2>Launch arguments</h2><p><code>launch argument</code> and '
                '<a href="x">an argument</a>; Launch arguments, then an argument, '
                'a launch argument, arguments.</p>')
    soup = BeautifulSoup(html, 'html.parser')
    assert glossary.link_first_uses(soup, entries, '../glossary/') == ['argument',
                                                                       'launch-argument']
    links = [(a.text, a['href']) for a in soup.select('a.glossary-term')]
    assert links == [('Launch arguments', '../glossary/#launch-argument'),
                     ('argument', '../glossary/#argument')]
    assert soup.h2.a is None and soup.code.a is None
    assert soup.p.get_text() == ('launch argument and an argument; Launch arguments, then an '
                                 'argument, a launch argument, arguments.')


def test_lesson_page_gets_header_under_title_and_key_points_box(entries):
    html = ('<div class="jp-Notebook">' + cell('<h1>Title</h1><p>intro</p>') +
            cell('<h2>Key points</h2><ul><li>one</li></ul>') + cell('<p>next lesson</p>') +
            '</div>')
    soup = BeautifulSoup(finish_lesson_html(html, LessonPage(
        header=header_html(META, []), glossary=entries, glossary_url='g/')), 'html.parser')
    assert soup.h1.find_next_sibling().get('class')[-1] == 'textbook-header'
    box = soup.select_one('div.textbook-key-points')
    assert box.h2.text == 'Key points' and 'next lesson' in box.get_text()
    assert soup.select('div.textbook-header a.glossary-term') == []


def test_toc_keeps_inline_code_and_the_real_ids():
    soup = BeautifulSoup(
        '<h1 id="t">T<a class="anchor-link" href="#t">¶</a></h1>'
        '<h2 id="start-it-with-ros2-launch">Start it with <code>ros2 launch</code>'
        '<a class="anchor-link" href="#x">¶</a></h2><h3 id="sub">Sub</h3><h2 id="b">B</h2>',
        'html.parser')
    (root,) = toc_tokens(soup)
    assert [(c['id'], c['name']) for c in root['children']] == [
        ('start-it-with-ros2-launch', 'Start it with <code>ros2 launch</code>'), ('b', 'B')]
    assert root['children'][0]['children'][0]['id'] == 'sub'


def test_images_without_a_real_description_are_found():
    soup = BeautifulSoup('<img alt="A graph"><img><img alt="No description has been '
                         'provided for this image">', 'html.parser')
    assert len(images_without_description(soup)) == 2
