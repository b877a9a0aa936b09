"""Launch, parameter-file, setup.py and package.xml code typed into a lesson
fails the build; prose, includes and other code pass."""
from __future__ import annotations

import textwrap

import pytest
from textbook.inline_check import InlineCodeError, check, find_violations

HEADER = '---\ntitle: x\n---\n\n# Lesson\n\n'  # 6 lines before the body


def lesson(body: str) -> str:
    return HEADER + textwrap.dedent(body)


@pytest.mark.parametrize('code,kind,bad_line', [
    ('from launch import LaunchDescription\nld = LaunchDescription([])', 'launch code', 1),
    ('def generate_launch_description():\n    pass', 'launch code', 0),
    ("<launch>\n  <node pkg='a' exec='b'/>\n</launch>", 'an XML launch file', 0),
    ('launch:\n- node:\n    pkg: a', 'a YAML launch file', 0),
    ('talker:\n  ros__parameters:\n    rate: 2.0', 'a YAML parameter file', 1),
    ('setup(\n    data_files=[],\n)', 'setup.py code', 1),
    ("entry_points={\n    'console_scripts': ['a = b:c'],\n}", 'setup.py code', 0),
    ('<package format="3">\n  <name>x</name>', 'package.xml code', 0),
    ('<exec_depend>rclpy</exec_depend>', 'package.xml code', 0),
])
@pytest.mark.parametrize('fence', ['```python', '```{code-cell} ipython3'])
def test_typed_in_code_fails(code, kind, bad_line, fence):
    # Lines 7-10 of the file: prose, blank, fence, "x = 1"; `code` starts at line 11.
    text = lesson(f'Some prose.\n\n{fence}\nx = 1\n{code}\n```\n')
    violations = find_violations(text, 'lessons/ch06/L1/x.md')
    assert violations, f'{kind} was not caught'
    first = violations[0]
    assert (first.kind, first.line) == (kind, 11 + bad_line)
    with pytest.raises(InlineCodeError, match=rf'^lessons/ch06/L1/x.md:{11 + bad_line}: '):
        check(text, 'lessons/ch06/L1/x.md')


def test_writefile_heredoc_in_a_bash_cell_fails():
    text = lesson("""\
        ```{code-cell} ipython3
        %%bash
        cat > params.yaml <<EOF
        node:
          ros__parameters:
            a: 1
        EOF
        ```
        """)
    assert [v.kind for v in find_violations(text, 'x.md')] == ['a YAML parameter file']


def test_every_violation_is_reported():
    text = lesson("""\
        ```yaml
        a:
          ros__parameters: {}
        ```

        ```xml
        <depend>rclpy</depend>
        ```
        """)
    assert [v.line for v in find_violations(text, 'x.md')] == [9, 13]


def test_prose_includes_and_ordinary_code_pass():
    text = lesson("""\
        A `LaunchDescription(...)` holds actions; `ros__parameters:` starts
        the parameters of a node in a YAML file.

        ```{snippet} my_robot_pkg/launch/sensors.launch.py
        ```

        ```{code-cell} ipython3
        %%bash
        ros2 launch my_robot_pkg sensors.launch.py
        ```

        ```bash
        colcon build
        ```
        """)
    assert find_violations(text, 'x.md') == []
    check(text, 'x.md')
