"""Tabs on the site for files shown side by side (Python, XML, YAML).

Lesson markdown reaches the page through mkdocs-jupyter (nbconvert), which
ignores mkdocs' markdown extensions such as ``pymdownx.tabbed``.  So a lesson
marks the group in plain markdown, which Jupyter shows as it is (one file
after another), and the site build turns it into mkdocs-material's tabs::

    <!-- tabs -->
    Python:
    (a snippet or any blocks)
    XML:
    (...)
    <!-- /tabs -->

Each paragraph that is only a short label ending in ``:`` starts a tab.
"""
from __future__ import annotations

from bs4 import BeautifulSoup, Comment, Tag
from nbconvert.filters.markdown_mistune import markdown2html_mistune

START, END = 'tabs', '/tabs'
_LONGEST_LABEL = 40


class TabsError(ValueError):
    """A tab group the build cannot turn into tabs."""


def _marker(node: object, text: str) -> bool:
    return isinstance(node, Comment) and node.strip() == text


def _label(node: object) -> str | None:
    """'Python' for a paragraph 'Python:', else None."""
    if not isinstance(node, Tag) or node.name != 'p':
        return None
    text = node.get_text().strip()
    if text.endswith(':') and 0 < len(text) <= _LONGEST_LABEL and '\n' not in text:
        return text[:-1].strip()
    return None


def _members(start: Comment) -> tuple[list[object], Comment]:
    members, node = [], start.next_sibling
    while node is not None and not _marker(node, END):
        if _marker(node, START):
            raise TabsError('<!-- tabs --> inside another tab group')
        members.append(node)
        node = node.next_sibling
    if node is None:
        raise TabsError('<!-- tabs --> has no <!-- /tabs --> after it in the same cell')
    return members, node


def _split(members: list[object]) -> list[tuple[str, list[object]]]:
    tabs: list[tuple[str, list[object]]] = []
    for node in members:
        label = _label(node)
        if label is not None:
            tabs.append((label, []))
        elif tabs:
            tabs[-1][1].append(node)
        elif str(node).strip():
            raise TabsError(f'content before the first tab label: {str(node).strip()[:60]!r}')
    if len(tabs) < 2:
        raise TabsError(f'a tab group needs two labels or more ("Python:"), found {len(tabs)}')
    if any(not any(str(n).strip() for n in nodes) for _, nodes in tabs):
        raise TabsError('a tab label with nothing under it')
    return tabs


def _tab_set(soup: BeautifulSoup, group: int, tabs: list[tuple[str, list[object]]]) -> Tag:
    """mkdocs-material's markup for pymdownx.tabbed (alternate style)."""
    tab_set = soup.new_tag('div', attrs={'class': 'tabbed-set tabbed-alternate',
                                         'data-tabs': f'{group}:{len(tabs)}'})
    labels = soup.new_tag('div', attrs={'class': 'tabbed-labels'})
    content = soup.new_tag('div', attrs={'class': 'tabbed-content'})
    for number, (label, nodes) in enumerate(tabs, 1):
        radio = soup.new_tag('input', attrs={'id': f'__tabbed_{group}_{number}',
                                             'name': f'__tabbed_{group}', 'type': 'radio'})
        if number == 1:
            radio['checked'] = 'checked'
        tab_set.append(radio)
        tag = soup.new_tag('label', attrs={'for': f'__tabbed_{group}_{number}'})
        tag.string = label
        labels.append(tag)
        block = soup.new_tag('div', attrs={'class': 'tabbed-block'})
        for node in nodes:
            block.append(node.extract())
        content.append(block)
    tab_set.append(labels)
    tab_set.append(content)
    return tab_set


def group_tabs(soup: BeautifulSoup) -> int:
    """Turn every marked group into tabs; returns how many groups there were."""
    starts = [node for node in soup.find_all(string=lambda s: _marker(s, START))]
    stray = [node for node in soup.find_all(string=lambda s: _marker(s, END))]
    if len(stray) != len(starts):
        raise TabsError(f'{len(starts)} <!-- tabs --> but {len(stray)} <!-- /tabs -->')
    for group, start in enumerate(starts, 1):
        members, end = _members(start)
        tabs = _split(members)
        for node in members:
            if _label(node) is not None or not str(node).strip():
                node.extract()
        start.replace_with(_tab_set(soup, group, tabs))
        end.extract()
    return len(starts)


def check_markdown(markdown: str, where: str) -> None:
    """Raise TabsError naming ``where`` if the cell's tab groups cannot become tabs:
    the cell is rendered by nbconvert's markdown renderer, as the site renders it."""
    if f'<!-- {START} -->' not in markdown and f'<!-- {END} -->' not in markdown:
        return
    try:
        group_tabs(BeautifulSoup(markdown2html_mistune(markdown), 'html.parser'))
    except TabsError as error:
        raise TabsError(f'{where}: {error}') from None
