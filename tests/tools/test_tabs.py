"""Marked groups of files become mkdocs-material tabs on the site: rendered
through nbconvert as mkdocs-jupyter renders a lesson, then finished as the
site build finishes a lesson page."""
from __future__ import annotations

import nbformat
import pytest
from bs4 import BeautifulSoup, Comment
from nbconvert import HTMLExporter
from textbook.lessons import load
from textbook.render import finish_lesson_html
from textbook.tabs import TabsError

from ._lesson_files import write_lesson

THREE_FILES = """Before.

<!-- tabs -->
Python:

```python
x = 1
```

XML:

```xml
<launch/>
```

YAML:

```yaml
launch: []
```

A sentence about the YAML file.
<!-- /tabs -->

After.
"""


def _page(*markdown: str) -> BeautifulSoup:
    notebook = nbformat.v4.new_notebook()
    notebook.cells = [nbformat.v4.new_markdown_cell(text) for text in markdown]
    html, _ = HTMLExporter(template_name='lab').from_notebook_node(notebook)
    return BeautifulSoup(finish_lesson_html(html), 'html.parser')


def test_a_marked_group_becomes_one_tab_per_label_with_the_first_selected():
    page = _page(THREE_FILES)
    (tab_set,) = page.select('div.tabbed-set.tabbed-alternate')
    assert [label.get_text() for label in tab_set.select('.tabbed-labels label')] == \
        ['Python', 'XML', 'YAML']
    blocks = tab_set.select('.tabbed-content > .tabbed-block')
    assert [block.get_text().strip() for block in blocks] == \
        ['x = 1', '<launch/>', 'launch: []\n\nA sentence about the YAML file.']
    radios = tab_set.find_all('input', recursive=False)
    assert [radio.has_attr('checked') for radio in radios] == [True, False, False]
    assert [label['for'] for label in tab_set.select('label')] == [r['id'] for r in radios]
    text = page.get_text()
    assert 'Python:' not in text and 'Before.' in text and 'After.' in text
    assert not page.find_all(string=lambda s: isinstance(s, Comment) and 'tabs' in s)


def test_two_groups_on_a_page_get_their_own_radio_names():
    page = _page(THREE_FILES, THREE_FILES)
    names = [{radio['name'] for radio in tab_set.find_all('input', recursive=False)}
             for tab_set in page.select('div.tabbed-set')]
    assert len(names) == 2 and names[0] != names[1] and all(len(n) == 1 for n in names)


def test_a_page_without_markers_is_unchanged_by_tabs():
    page = _page('Python:\n\n```python\nx = 1\n```\n')
    assert not page.select('.tabbed-set') and 'Python:' in page.get_text()


@pytest.mark.parametrize('markdown, message', [
    (THREE_FILES.replace('<!-- /tabs -->', ''), '1 <!-- tabs --> but 0 <!-- /tabs -->'),
    ('<!-- tabs -->\nPython:\n\n```python\nx = 1\n```\n\n<!-- /tabs -->\n',
     'needs two labels or more'),
    ('<!-- tabs -->\nSome prose first.\n\nPython:\n\n```python\nx\n```\n\nXML:\n\n```xml\n'
     '<launch/>\n```\n\n<!-- /tabs -->\n', 'content before the first tab label'),
    ('<!-- tabs -->\nPython:\n\nXML:\n\n```xml\n<launch/>\n```\n\n<!-- /tabs -->\n',
     'a tab label with nothing under it'),
])
def test_a_malformed_group_is_an_error_that_says_what_is_wrong(markdown, message):
    with pytest.raises(TabsError, match=message):
        _page(markdown)


def test_markers_in_different_cells_are_an_error():
    with pytest.raises(TabsError, match='no <!-- /tabs --> after it in the same cell'):
        _page('<!-- tabs -->\nPython:\n\n```python\nx\n```\n',
              'XML:\n\n```xml\ny\n```\n\n<!-- /tabs -->')



def test_loading_a_lesson_names_the_file_and_cell_of_a_malformed_group(tmp_path):
    path = write_lesson(tmp_path, '## A heading\n\n<!-- tabs -->\nPython:\n\n```python\nx\n```\n')
    with pytest.raises(TabsError, match=r"demo.md: the markdown cell that begins '## A "
                                        r"heading': 1 <!-- tabs --> but 0 <!-- /tabs -->"):
        load(path)
