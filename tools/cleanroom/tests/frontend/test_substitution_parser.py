"""`$(...)` text -> substitutions: every substitution name, quoting, nesting, errors."""
from __future__ import annotations

import os

import pytest
from lark.exceptions import VisitError
from launch import LaunchContext
from launch.frontend import Parser, parse_substitution
from launch.substitutions import (
    EnvironmentVariable,
    FindExecutable,
    LaunchConfiguration,
    PythonExpression,
    TextSubstitution,
    ThisLaunchFile,
    ThisLaunchFileDir,
)
from launch.utilities import perform_substitutions
from launch_ros.substitutions import ExecutableInPackage, FindPackagePrefix, FindPackageShare

Parser.load_launch_extensions()  # launch_ros' substitutions


def perform(text: str, context: LaunchContext) -> str:
    return perform_substitutions(context, parse_substitution(text))


@pytest.fixture
def context() -> LaunchContext:
    context = LaunchContext()
    context.launch_configurations.update({'mode': 'real', 'speed': '1.5', 'flag': 'true'})
    context.extend_locals({'current_launch_file_path': '/a/b/x.launch.xml',
                           'current_launch_file_directory': '/a/b'})
    return context


def test_plain_text_is_one_text_substitution():
    parsed = parse_substitution('just text with $ signs $x')
    assert len(parsed) == 1 and isinstance(parsed[0], TextSubstitution)
    assert parsed[0].text == 'just text with $ signs $x'


def test_empty_text():
    parsed = parse_substitution('')
    assert [type(s) for s in parsed] == [TextSubstitution] and parsed[0].text == ''


def test_text_around_substitutions_is_kept(context):
    parsed = parse_substitution('a $(var mode) b')
    assert [type(s) for s in parsed] == [TextSubstitution, LaunchConfiguration,
                                         TextSubstitution]
    assert perform('a $(var mode) b', context) == 'a real b'


@pytest.mark.parametrize(('text', 'expected'), [
    ('$(var mode)', 'real'),
    ('$(var missing fallback)', 'fallback'),
    ('$(env FE_TEST_SET)', 'yes'),
    ('$(env FE_TEST_UNSET dflt)', 'dflt'),
    ('$(optenv FE_TEST_UNSET)', ''),
    ('$(optenv FE_TEST_UNSET other)', 'other'),
    ("$(eval '$(var speed) > 1.0')", 'True'),
    ('$(eval \'"$(var mode)" == "real"\')', 'True'),
    ('$(dirname)', '/a/b'),
    ('$(filename)', '/a/b/x.launch.xml'),
    ('$(not $(var flag))', 'false'),
    ('$(and $(var flag) false)', 'false'),
    ('$(or $(var flag) false)', 'true'),
    ('$(any false $(var flag))', 'true'),
    ('$(all true $(var flag) false)', 'false'),
    ('$(equals $(var mode) real)', 'true'),
    ('$(not-equals $(var mode) real)', 'false'),
    ('$(if-else $(var flag) on off)', 'on'),
    ("$(command 'echo hi')", 'hi\n'),
])
def test_each_substitution(text, expected, context):
    context.environment['FE_TEST_SET'] = 'yes'
    context.environment.pop('FE_TEST_UNSET', None)
    assert perform(text, context) == expected


def test_find_exec_and_anon(context):
    assert perform('$(find-exec sh)', context) == FindExecutable(name='sh').perform(context)
    anon = perform('$(anon talker)', context)
    assert anon.startswith('talker_') and anon == perform('$(anon talker)', context)


def test_file_content(context, tmp_path):
    path = tmp_path / 'content.txt'
    path.write_text('inside')
    assert perform(f'$(file-content {path})', context) == 'inside'


def test_launch_ros_substitutions_build_their_classes():
    assert isinstance(parse_substitution('$(find-pkg-share p)')[0], FindPackageShare)
    assert isinstance(parse_substitution('$(find-pkg-prefix p)')[0], FindPackagePrefix)
    sub = parse_substitution('$(exec-in-pkg talker p)')[0]
    assert isinstance(sub, ExecutableInPackage)
    assert [s.text for s in sub.executable] == ['talker']


def test_quoted_arguments_keep_spaces_and_expand_substitutions(context):
    parsed = parse_substitution("$(eval '\"$(var mode)\" + \" x\"')")
    assert isinstance(parsed[0], PythonExpression)
    assert perform("$(eval '\"$(var mode)\" + \" x\"')", context) == 'real x'
    assert perform('$(var "mode")', context) == 'real'


def test_nested_substitution_as_argument(context):
    parsed = parse_substitution('$(env $(var mode) none)')
    assert isinstance(parsed[0], EnvironmentVariable)
    assert perform('$(env $(var mode) none)', context) == os.environ.get('real', 'none')


def test_unknown_substitution_is_a_visit_error():
    with pytest.raises(VisitError) as error:
        parse_substitution('$(no_such_subst x)')
    assert type(error.value).__name__ == 'VisitError'
    assert str(error.value) == ('Error trying to process rule "substitution":\n\n'
                                'Unknown substitution: no_such_subst')


def test_wrong_number_of_arguments_names_the_substitution():
    with pytest.raises(VisitError, match="'var' substitution expects 1 to 2 argument"):
        parse_substitution('$(var)')
    with pytest.raises(VisitError, match="'dirname' substitution expects 0 argument"):
        parse_substitution('$(dirname x)')


def test_this_launch_file_classes():
    assert isinstance(parse_substitution('$(dirname)')[0], ThisLaunchFileDir)
    assert isinstance(parse_substitution('$(filename)')[0], ThisLaunchFile)


def test_unclosed_substitution_is_an_error():
    with pytest.raises(Exception, match='Unexpected'):
        parse_substitution('$(var mode')
