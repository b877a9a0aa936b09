"""Substitutions performed against a bare LaunchContext."""
from __future__ import annotations

import os
import re
import shutil
import sys

import launch.logging
import pytest
from launch import LaunchContext
from launch.conditions import InvalidConditionExpressionError
from launch.substitutions import (
    AllSubstitution,
    AndSubstitution,
    AnonName,
    AnySubstitution,
    Command,
    EnvironmentVariable,
    EqualsSubstitution,
    FileContent,
    FindExecutable,
    IfElseSubstitution,
    LaunchConfiguration,
    LaunchLogDir,
    LocalSubstitution,
    NotEqualsSubstitution,
    NotSubstitution,
    OrSubstitution,
    PathJoinSubstitution,
    PythonExpression,
    SubstitutionFailure,
    TextSubstitution,
    ThisLaunchFile,
    ThisLaunchFileDir,
)
from launch.utilities import (
    ensure_argument_type,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)


@pytest.fixture
def context() -> LaunchContext:
    ctx = LaunchContext()
    ctx.launch_configurations.update({'robot': 'bot', 'sim': 'True', 'radius': '0.1'})
    return ctx


def test_text_and_normalize(context):
    subs = normalize_to_list_of_substitutions(['a', TextSubstitution(text='b'),
                                               LaunchConfiguration('robot')])
    assert [type(s).__name__ for s in subs] == ['TextSubstitution', 'TextSubstitution',
                                                'LaunchConfiguration']
    assert perform_substitutions(context, subs) == 'abbot'
    assert TextSubstitution(text='x').describe() == "'x'"
    with pytest.raises(TypeError):
        normalize_to_list_of_substitutions(5)


def test_launch_configuration_default_and_missing(context):
    assert LaunchConfiguration('robot').perform(context) == 'bot'
    assert LaunchConfiguration('nope', default='fallback').perform(context) == 'fallback'
    assert LaunchConfiguration('nope', default=5).perform(context) == '5'
    with pytest.raises(SubstitutionFailure, match="launch configuration 'nope' does not exist"):
        LaunchConfiguration('nope').perform(context)
    assert LaunchConfiguration('robot').describe() == "LaunchConfig('robot')"


def test_path_join(context):
    path = PathJoinSubstitution(['/opt', LaunchConfiguration('robot'), 'cfg.yaml'])
    assert path.perform(context) == '/opt/bot/cfg.yaml'
    # `/` arrived after Jazzy: a file using it here would fail on Jazzy
    with pytest.raises(TypeError, match='unsupported operand'):
        PathJoinSubstitution(['/a']) / 'b'


def test_path_join_takes_one_substitution_per_component(context):
    """Observed on Jazzy: the components are normalised as SomeSubstitutionsType, so
    a list inside (text joined within one component) is refused when the launch
    file is loaded, and describe() joins the components with ' + '."""
    with pytest.raises(TypeError) as refused:
        PathJoinSubstitution(['/opt', [LaunchConfiguration('robot'), '.yaml']])
    assert str(refused.value) == ("Failed to normalize given item of type '<class 'list'>', "
                                  "when only 'str' or 'launch.Substitution' were expected.")
    path = PathJoinSubstitution(['a', LaunchConfiguration('robot'), 't'])
    assert [type(s).__name__ for s in path.substitutions] == [
        'TextSubstitution', 'LaunchConfiguration', 'TextSubstitution']
    assert path.describe() == "PathJoin(''a' + LaunchConfig('robot') + 't'')"
    assert PathJoinSubstitution('abc').perform(context) == 'abc'


def test_python_expression(context):
    assert PythonExpression(['2 * ', LaunchConfiguration('radius')]).perform(context) == '0.2'
    assert PythonExpression('pi > 3 and math.e > 2').perform(context) == 'True'
    assert PythonExpression('os.sep', python_modules=['os']).perform(context) == os.sep
    with pytest.raises(SubstitutionFailure):
        PythonExpression('1 +').perform(context)


def test_environment_variable_uses_context_environment(context):
    context.environment['CR_ONLY_IN_CONTEXT'] = 'ctx'
    assert 'CR_ONLY_IN_CONTEXT' not in os.environ
    assert EnvironmentVariable('CR_ONLY_IN_CONTEXT').perform(context) == 'ctx'
    assert EnvironmentVariable('CR_MISSING', default_value='dflt').perform(context) == 'dflt'
    with pytest.raises(SubstitutionFailure, match="environment variable 'CR_MISSING'"):
        EnvironmentVariable('CR_MISSING').perform(context)


def test_find_executable(context):
    assert FindExecutable(name='sh').perform(context) == shutil.which('sh')
    # Jazzy's message names the list of substitutions, not the name it looked for
    missing = r"^executable '\[<launch\.substitutions\.text_substitution\.TextSubstitution " \
              r"object at 0x[0-9a-f]+>\]' not found on the PATH$"
    with pytest.raises(SubstitutionFailure, match=missing):
        FindExecutable(name='no-such-exe-cr').perform(context)


def test_command(context):
    assert Command(['echo ', LaunchConfiguration('robot')]).perform(context) == 'bot\n'
    with pytest.raises(SubstitutionFailure, match='executed command failed'):
        Command('false').perform(context)
    noisy = f'{sys.executable} -c "import sys; print(1); sys.stderr.write(\'warn\')"'
    with pytest.raises(SubstitutionFailure, match='stderr output'):
        Command(noisy).perform(context)
    assert Command(noisy, on_stderr='ignore').perform(context) == '1\n'
    assert Command(noisy, on_stderr='capture').perform(context) == '1\nwarn'


def test_anon_name_is_stable_per_name(context):
    first = AnonName('viewer').perform(context)
    assert first.startswith('viewer_')
    assert AnonName('viewer').perform(context) == first
    assert AnonName('other').perform(context) != first


def test_local_substitution(context):
    context.extend_locals({'answer': {'x': 42}})
    assert LocalSubstitution("answer['x']").perform(context) == '42'
    with pytest.raises(SubstitutionFailure):
        LocalSubstitution('missing').perform(context)


def test_boolean_substitutions(context):
    sim = LaunchConfiguration('sim')
    assert NotSubstitution(sim).perform(context) == 'false'
    assert AndSubstitution(sim, 'false').perform(context) == 'false'
    assert OrSubstitution(sim, 'false').perform(context) == 'true'
    assert AnySubstitution('0', 'false', '1').perform(context) == 'true'
    assert AllSubstitution('1', 'true', sim).perform(context) == 'true'
    with pytest.raises(InvalidConditionExpressionError):
        NotSubstitution('maybe').perform(context)


def test_equals_and_if_else(context):
    assert EqualsSubstitution(LaunchConfiguration('radius'), '0.10').perform(context) == 'true'
    assert EqualsSubstitution(LaunchConfiguration('sim'), True).perform(context) == 'true'
    assert EqualsSubstitution('abc', 'abd').perform(context) == 'false'
    assert NotEqualsSubstitution('abc', 'abd').perform(context) == 'true'
    choice = IfElseSubstitution(LaunchConfiguration('sim'), 'simulation', 'hardware')
    assert choice.perform(context) == 'simulation'
    context.launch_configurations['sim'] = '0'
    assert choice.perform(context) == 'hardware'


def test_file_content(context, tmp_path):
    path = tmp_path / 'f.txt'
    path.write_text('content\n')
    assert FileContent(str(path)).perform(context) == 'content\n'
    with pytest.raises(SubstitutionFailure, match='missing.txt'):
        FileContent(str(tmp_path / 'missing.txt')).perform(context)


def test_this_launch_file_outside_a_file(context):
    with pytest.raises(SubstitutionFailure, match='outside of a launch file'):
        ThisLaunchFile().perform(context)
    context.extend_locals({'current_launch_file_path': '/x/y.launch.py',
                           'current_launch_file_directory': '/x'})
    assert ThisLaunchFile().perform(context) == '/x/y.launch.py'
    assert ThisLaunchFileDir().perform(context) == '/x'


def test_launch_log_dir_is_below_ros_log_dir(context):
    launch.logging.reset()  # another test on this worker may have made its folder already
    log_dir = LaunchLogDir().perform(context)
    assert log_dir.startswith(os.environ['ROS_LOG_DIR'])
    assert os.path.isdir(log_dir)


def test_ensure_argument_type():
    ensure_argument_type('x', [str], 'name')
    # Jazzy's words (observed): the caller quoted in front, the classes as Python prints them.
    with pytest.raises(TypeError, match=re.escape(
            "'MyAction' expected 'name' to be one of [<class 'str'>, <class 'bytes'>], "
            "but got '1' of type '<class 'int'>'")):
        ensure_argument_type(1, (str, bytes), 'name', 'MyAction')
    with pytest.raises(TypeError, match=re.escape(
            "Expected 'name' to be one of [<class 'tuple'>], but got 'x' of type '<class 'str'>'")):
        ensure_argument_type('x', tuple, 'name')


def test_normalize_to_list_of_substitutions_iterates_what_is_not_text():
    with pytest.raises(TypeError, match="^'int' object is not iterable$"):
        normalize_to_list_of_substitutions(1)
    with pytest.raises(TypeError, match="^'NoneType' object is not iterable$"):
        normalize_to_list_of_substitutions(None)
