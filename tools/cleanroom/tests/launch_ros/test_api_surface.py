"""Import paths and small behaviours launch files rely on."""
import launch_ros
import lifecycle_msgs.msg
from launch import LaunchContext
from launch.substitutions import LaunchConfiguration
from launch_ros.events.lifecycle import StateTransition
from launch_ros.parameter_descriptions import ParameterFile


def test_subpackages_load_on_attribute_access():
    assert launch_ros.actions.Node.__name__ == 'Node'
    assert launch_ros.actions.PushROSNamespace is launch_ros.actions.PushRosNamespace
    assert launch_ros.substitutions.FindPackageShare.__name__ == 'FindPackageShare'
    descriptions = launch_ros.parameter_descriptions
    assert launch_ros.descriptions.ParameterValue is descriptions.ParameterValue
    assert callable(launch_ros.utilities.make_namespace_absolute)
    assert callable(launch_ros.utilities.evaluate_parameters)


def test_state_transition_exposes_labels():
    msg = lifecycle_msgs.msg.TransitionEvent()
    msg.timestamp = 42
    msg.transition.label = 'configure'
    msg.start_state.label = 'configuring'
    msg.goal_state.label = 'inactive'
    event = StateTransition(action='node', msg=msg)
    assert (event.action, event.timestamp, event.transition, event.start_state,
            event.goal_state) == ('node', 42, 'configure', 'configuring', 'inactive')
    assert event.name == 'launch_ros.events.lifecycle.StateTransition'


def test_parameter_file_allow_substs_from_a_launch_argument(tmp_path):
    source = tmp_path / 'p.yaml'
    source.write_text('/**:\n  ros__parameters:\n    who: $(var who)\n')
    context = LaunchContext()
    context.launch_configurations.update({'who': 'me', 'subst': 'true'})
    param_file = ParameterFile(str(source), allow_substs=LaunchConfiguration('subst'))
    path = param_file.evaluate(context)
    assert path.name.startswith('launch_params_')
    assert path.read_text() == '/**:\n  ros__parameters:\n    who: me\n'
    param_file.cleanup()
    assert not path.exists()
    context.launch_configurations['subst'] = 'false'
    assert ParameterFile(str(source), allow_substs=LaunchConfiguration('subst')).evaluate(
        context) == source


def test_parameter_file_unknown_substitution_names_the_file(tmp_path):
    import pytest

    source = tmp_path / 'bad.yaml'
    source.write_text('a: $(nope x)\n')
    with pytest.raises(ValueError, match=r"unknown substitution '\$\(nope \.\.\.\)' in "
                                         r"parameter file '.*bad.yaml'"):
        ParameterFile(str(source), allow_substs=True).evaluate(LaunchContext())
