"""ROS substitutions and the errors launch reports with Jazzy's text (goldens 22, 23, 27, 28)."""
import re

import pytest
from ament_index_python.packages import PackageNotFoundError
from launch import LaunchContext
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import (
    ExecutableInPackage,
    FindPackage,
    FindPackagePrefix,
    FindPackageShare,
)

PKG = 'lr_test_pkg'
ERROR_PREFIX = '[ERROR] [launch]: Caught exception in launch (see debug for traceback): '


def test_find_package_substitutions(test_package):
    context = LaunchContext()
    assert FindPackagePrefix(PKG).perform(context) == str(test_package)
    assert FindPackageShare(PKG).perform(context) == str(test_package / 'share' / PKG)
    assert isinstance(FindPackageShare(PKG), FindPackage)
    assert ExecutableInPackage('noop', PKG).perform(context) == str(
        test_package / 'lib' / PKG / 'noop')


def test_package_name_from_a_substitution(test_package):
    context = LaunchContext()
    context.launch_configurations['pkg'] = PKG
    share = FindPackageShare(LaunchConfiguration('pkg')).perform(context)
    assert share == str(test_package / 'share' / PKG)


def test_unknown_executable_text_has_the_trailing_space(test_package):
    with pytest.raises(Exception) as info:
        ExecutableInPackage('talker_node', PKG).perform(LaunchContext())
    libexec = test_package / 'lib' / PKG
    assert str(info.value) == (
        f"executable 'talker_node' not found on the libexec directory '{libexec}' ")


def test_unknown_package_raises_ament_error(test_package):
    with pytest.raises(PackageNotFoundError) as info:
        FindPackageShare('my_robot_pkgg').perform(LaunchContext())
    assert str(info.value).startswith("\"package 'my_robot_pkgg' not found, searching: [")


@pytest.mark.parametrize('node, message', [
    (lambda prefix: Node(package=PKG, executable='talker_node', name='typo'),
     lambda prefix: "executable 'talker_node' not found on the libexec directory "
                    f"'{prefix}/lib/{PKG}' "),
    (lambda prefix: Node(package='my_robot_pkgg', executable='talker', name='typo'),
     lambda prefix: "\"package 'my_robot_pkgg' not found, searching: ["),
    (lambda prefix: Node(package=PKG, executable='noop', name=LaunchConfiguration('robot')),
     lambda prefix: "launch configuration 'robot' does not exist"),
    (lambda prefix: Node(package=PKG, executable='noop', name='t', parameters=[
        {'r': ParameterValue(LaunchConfiguration('x', default='abc'), value_type=float)}]),
     lambda prefix: "value='abc' is not an instance of <class 'float'>"),
])
def test_errors_end_the_launch_with_jazzys_text(test_package, run_launch, capfd, node, message):
    record = run_launch([node(test_package)])
    out = capfd.readouterr()
    assert record.returncode == 1
    assert record.processes == []
    assert ERROR_PREFIX + message(test_package) in out.out + out.err


def test_node_name_that_fails_to_expand_is_named_first(test_package, run_launch, capfd):
    """Jazzy logs which Node failed before the launch error (errors/ golden 27)."""
    record = run_launch([Node(package=PKG, executable='noop', name=LaunchConfiguration('robot'),
                              namespace='fleet')])
    out = capfd.readouterr().out
    errors = [line for line in out.splitlines() if line.startswith('[ERROR]')]
    assert record.returncode == 1
    assert len(errors) == 2, out
    assert re.fullmatch(
        r"\[ERROR\] \[launch_ros\.actions\.node\]: Error while expanding or validating "
        rf"node name or namespace for 'package={PKG}, executable=noop, "
        r"name=<[\w.]+\.LaunchConfiguration object at 0x[0-9a-f]+>, namespace=fleet':",
        errors[0])
    assert errors[1] == ERROR_PREFIX + "launch configuration 'robot' does not exist"


def test_node_that_expands_logs_no_error(test_package, run_launch, capfd):
    record = run_launch([Node(package=PKG, executable='noop', name='fine')])
    assert record.returncode == 0
    assert '[ERROR]' not in capfd.readouterr().out
