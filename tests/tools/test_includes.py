"""Snippet includes: expansion, sections, marker stripping, and the errors
that must fail the build."""
from __future__ import annotations

import textwrap

import pytest
from textbook.includes import IncludeError, expand, language_of, load_snippet


@pytest.fixture
def snippets(tmp_path):
    root = tmp_path / 'snippets'
    pkg = root / 'pkg'
    (pkg / 'launch').mkdir(parents=True)
    (pkg / 'launch' / 'demo.launch.py').write_text(textwrap.dedent("""\
        from launch import LaunchDescription


        def generate_launch_description():
            # [START nodes]
            nodes = ['a', 'b']
            # [END nodes]
            return LaunchDescription([])
        """))
    (pkg / 'package.xml').write_text(textwrap.dedent("""\
        <package format="3">
          <!-- [START deps] -->
          <exec_depend>rclpy</exec_depend>
          <!-- [END deps] -->
        </package>
        """))
    (pkg / 'params.yaml').write_text('node:\n  ros__parameters:\n    x: 1  # ```\n')
    return root


def lesson(body: str) -> str:
    return '# Lesson\n\n' + textwrap.dedent(body)


def test_whole_file_becomes_a_titled_python_block_without_markers(snippets):
    text, used = expand(lesson("""\
        ```{snippet} pkg/launch/demo.launch.py
        ```
        """), 'lessons/x.md', snippets)
    assert '<div class="snippet-title">' in text
    assert 'pkg/launch/demo.launch.py</div>' in text
    assert '```python\nfrom launch import LaunchDescription\n' in text
    assert '[START' not in text and '[END' not in text
    assert "    nodes = ['a', 'b']" in text
    assert [s.path.name for s in used] == ['demo.launch.py']


def test_section_is_cut_out_and_dedented(snippets):
    text, used = expand(lesson("""\
        ```{snippet} pkg/launch/demo.launch.py#nodes
        ```
        """), 'lessons/x.md', snippets)
    assert "```python\nnodes = ['a', 'b']\n```" in text
    assert 'LaunchDescription' not in text
    assert used[0].section == 'nodes'


def test_xml_section_markers_and_language(snippets):
    snippet = load_snippet('pkg/package.xml#deps', root=snippets)
    assert snippet.language == 'xml'
    assert snippet.code == '<exec_depend>rclpy</exec_depend>'


def test_fence_is_longer_than_backticks_in_the_snippet(snippets):
    text, _ = expand(lesson('```{snippet} pkg/params.yaml\n```\n'), 'lessons/x.md', snippets)
    assert '````yaml\n' in text and text.rstrip().endswith('````')


def test_include_inside_a_list_item_keeps_its_indentation(snippets):
    text, _ = expand(lesson("""\
        - look:

          ```{snippet} pkg/package.xml#deps
          ```
        """), 'lessons/x.md', snippets)
    assert '\n  ```xml\n  <exec_depend>rclpy</exec_depend>\n  ```' in text


def test_code_cells_and_other_fences_are_left_alone(snippets):
    body = lesson("""\
        ```python
        print("{snippet} is just text here")
        ```

        ```{code-cell} ipython3
        print(1)
        ```
        """)
    assert expand(body, 'lessons/x.md', snippets) == (body, [])


@pytest.mark.parametrize('language,name', [
    ('python', 'a.launch.py'), ('yaml', 'p.yaml'), ('xml', 'package.xml'),
    ('xml', 'a.launch.xml'), ('ini', 'setup.cfg'), ('cmake', 'CMakeLists.txt'),
    ('text', 'resource_marker'),
])
def test_language_from_extension(tmp_path, language, name):
    assert language_of(tmp_path / name) == language


@pytest.mark.parametrize('target,message', [
    ('pkg/launch/missing.launch.py',
     'snippet file snippets/pkg/launch/missing.launch.py does not exist'),
    ('pkg/launch/demo.launch.py#nope',
     "snippet section 'nope' not found in snippets/pkg/launch/demo.launch.py"),
    ('../outside.py', 'is outside snippets/'),
    ('#nodes', 'needs a path'),
])
def test_bad_include_fails_naming_lesson_and_line(snippets, target, message):
    (snippets.parent / 'outside.py').write_text('x = 1\n')
    with pytest.raises(IncludeError) as error:
        expand(lesson(f'text\n\n```{{snippet}} {target}\n```\n'), 'lessons/ch06/L1/x.md', snippets)
    assert str(error.value).startswith('lessons/ch06/L1/x.md:5: ')
    assert message in str(error.value)


def test_include_with_content_fails(snippets):
    with pytest.raises(IncludeError, match=r'x.md:3: a snippet include takes no content'):
        expand(lesson('```{snippet} pkg/package.xml\nextra\n```\n'), 'x.md', snippets)


def test_unterminated_section_fails(snippets):
    (snippets / 'pkg' / 'half.py').write_text('# [START a]\nx = 1\n')
    with pytest.raises(IncludeError, match="section 'a' not found"):
        load_snippet('pkg/half.py#a', root=snippets)
