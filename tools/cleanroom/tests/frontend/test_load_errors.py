"""Bad front-end files fail the launch with Jazzy's messages (frontends goldens 38_/39_)."""
from __future__ import annotations

import io

import pytest
from launch import InvalidLaunchFileError
from launch.frontend import InvalidFrontendLaunchFileError, Parser
from launch.launch_description_sources import (
    get_launch_description_from_any_launch_file,
    get_launch_description_from_frontend_launch_file,
)

HEAD = 'Caught multiple exceptions when trying to load file of format [{}]:'
CAUGHT = 'Caught exception in launch (see debug for traceback): '


def python_error(name: str) -> str:
    return f' - SyntaxError: invalid syntax ({name}, line 1)'


def load_error(path) -> str:
    with pytest.raises(InvalidLaunchFileError) as error:
        get_launch_description_from_any_launch_file(str(path))
    return str(error.value)


def test_unknown_tag(write):
    path = write('bad.launch.xml', '<launch>\n  <log message="x"/>\n  <nodee pkg="p"/>\n</launch>')
    assert load_error(path) == '\n'.join([
        HEAD.format('xml'), ' - RuntimeError: Unrecognized entity of the type: nodee',
        python_error('bad.launch.xml')])


def test_unknown_yaml_tag(write):
    path = write('bad.launch.yaml', 'launch:\n- nodee: {pkg: p, exec: t}\n')
    assert load_error(path) == '\n'.join([
        HEAD.format('yaml'), ' - RuntimeError: Unrecognized entity of the type: nodee',
        python_error('bad.launch.yaml')])


def test_missing_attribute(write):
    path = write('bad.launch.xml', '<launch>\n  <node pkg="p" name="n"/>\n</launch>')
    assert load_error(path).splitlines()[1] == (
        " - AttributeError: Attribute 'exec' of type '<class 'str'>' not found in Entity 'node'")


def test_unknown_attribute(write):
    path = write('bad.launch.xml', '<launch>\n  <node pkg="p" exec="t" colour="red"/>\n</launch>')
    assert load_error(path).splitlines()[1] == (
        " - ValueError: Unexpected attribute(s) found in `node`: {'colour'}")


def test_bad_attribute_value(write):
    path = write('bad.launch.xml', '<launch>\n  <timer period="soon"><log message="m"/></timer>\n'
                                   '</launch>')
    assert load_error(path).splitlines()[1] == (
        " - ValueError: could not convert string to float: 'soon'")


def test_unknown_substitution(write):
    path = write('bad.launch.xml', '<launch>\n  <log message="$(no_such_subst x)"/>\n</launch>')
    assert load_error(path) == '\n'.join([
        HEAD.format('xml'), ' - VisitError: Error trying to process rule "substitution":', '',
        'Unknown substitution: no_such_subst', python_error('bad.launch.xml')])


def test_malformed_xml_tries_every_front_end(write):
    path = write('bad.launch.xml', '<launch>\n  <node pkg="p" exec="t">\n</launch>\n')
    assert load_error(path) == '\n'.join([
        HEAD.format('xml'), ' - InvalidFrontendLaunchFileError: ' + HEAD.format('xml'),
        ' - ParseError: mismatched tag: line 3, column 2',
        ' - RuntimeError: Expected only one root', python_error('bad.launch.xml')])


def test_malformed_yaml_tries_every_front_end(write):
    path = write('bad.launch.yaml', 'launch:\n- node: {pkg: p, exec: t\n- log: {message: a}\n')
    lines = load_error(path).splitlines()
    assert lines[:2] == [HEAD.format('yaml'),
                         ' - InvalidFrontendLaunchFileError: ' + HEAD.format('yaml')]
    assert lines[2] == ' - ParserError: while parsing a flow mapping'
    assert lines[3] == f'  in "{path}", line 2, column 9'
    assert lines[-2:] == [' - ParseError: syntax error: line 1, column 0',
                          python_error('bad.launch.yaml')]


def test_a_python_file_is_no_front_end_file(write):
    path = write('broken.launch.py', 'def nothing():\n    pass\n')
    assert load_error(path) == '\n'.join([
        HEAD.format('py'),
        f" - InvalidPythonLaunchFileError: launch file at '{path}' does not contain the "
        "required function 'generate_launch_description()'",
        " - RuntimeError: Expected 'launch' as root tag"])  # read as YAML: a string, no launch


def test_frontend_loader_alone(write):
    with pytest.raises(InvalidFrontendLaunchFileError,
                       match='The launch file may have a syntax error, or its format is unknown'):
        get_launch_description_from_frontend_launch_file(str(write('x.launch.txt', 'x')))
    assert Parser.is_filename_valid('a.launch.xml') and Parser.is_filename_valid('a.launch.yaml')
    assert not Parser.is_filename_valid('a.launch.py')
    assert {'xml', 'yaml'} <= set(Parser.get_available_extensions())


def test_root_must_be_launch(write):
    path = write('bad.launch.xml', '<group/>')
    assert load_error(path).splitlines()[:2] == [
        HEAD.format('xml'), " - RuntimeError: Expected 'launch' as root tag"]


def test_a_file_named_for_no_format_is_read_by_any_front_end(write):
    """Jazzy tries every front end on a file whose name says no format (a path, or a
    file object, with or without a name), from where the file object started; when
    all fail, the format is unknown; a missing file is the FileNotFoundError."""
    assert get_launch_description_from_any_launch_file(
        str(write('robot', '<launch><log message="m"/></launch>'))).entities
    assert get_launch_description_from_any_launch_file(
        str(write('robot.txt', 'launch:\n- log: {message: m}\n'))).entities
    named = io.StringIO('<launch/>')
    named.name = 'robot.launch.yaml'  # not YAML after all: XML reads it
    assert Parser.load(named)[0].type_name == 'launch'
    assert Parser.load(io.StringIO('launch: []\n'))[0].type_name == 'launch'
    with pytest.raises(InvalidFrontendLaunchFileError) as unknown:
        Parser.load(io.StringIO('garbage: [\n'))
    assert unknown.value.args == ('',) and unknown.value.__cause__ is None
    assert str(unknown.value) == 'The launch file may have a syntax error, or its format is unknown'
    with pytest.raises(InvalidLaunchFileError) as unknown:
        get_launch_description_from_any_launch_file(str(write('robot.txt', 'garbage(')))
    assert str(unknown.value) == 'The launch file may have a syntax error, or its format is unknown'
    with pytest.raises(FileNotFoundError):
        Parser.load(str(write('x', '')) + '.missing.xml')
    assert type(InvalidFrontendLaunchFileError('')).__module__ == 'launch.frontend.parser'


def test_the_load_error_composes_its_message_as_jazzy_does():
    one = InvalidLaunchFileError('xml', likely_errors=[ValueError('a')])
    two = InvalidLaunchFileError('py', likely_errors=[ValueError('a'), KeyError('k')])
    assert str(one) == ('Caught exception when trying to load file of format [xml]:\n'
                        ' - ValueError: a')
    assert str(two) == ('Caught multiple exceptions when trying to load file of format [py]:\n'
                        " - ValueError: a\n - KeyError: 'k'")
    unknown = 'The launch file may have a syntax error, or its format is unknown'
    assert str(InvalidLaunchFileError()) == str(InvalidLaunchFileError('xml')) == unknown
    assert str(InvalidLaunchFileError('', likely_errors=[ValueError('a')])) == unknown
    assert InvalidLaunchFileError().args == () and one.args == ('xml',)


def test_if_and_unless_together(write):
    path = write('bad.launch.xml', '<launch><log message="m" if="true" unless="true"/></launch>')
    assert "if and unless conditions can't be used simultaneously" in load_error(path)


def test_undeclared_var_fails_when_run(write, run_file):
    result = run_file(write('v.launch.xml', '<launch><log message="is $(var nowhere)"/></launch>'))
    assert result.returncode == 1
    assert result.error_text() == CAUGHT + "launch configuration 'nowhere' does not exist"


def test_invalid_choice_fails_when_run(write, run_file):
    path = write('c.launch.xml', """
        <launch>
          <arg name="mode" default="sim"><choice value="sim"/><choice value="real"/></arg>
        </launch>""")
    result = run_file(path, 'mode:=fly')
    assert result.returncode == 1
    assert ('[ERROR] [launch.actions.declare_launch_argument]: Argument "mode" provided value '
            '"fly" is not valid. Valid options are: [\'sim\', \'real\']') in result.output


def test_load_error_ends_the_launch_with_all_lines(write, run_file):
    result = run_file(write('bad.launch.xml', '<launch><nodee/></launch>'))
    assert result.returncode == 1
    assert result.error_text() == '\n'.join([
        CAUGHT + HEAD.format('xml'), ' - RuntimeError: Unrecognized entity of the type: nodee',
        python_error('bad.launch.xml')])
