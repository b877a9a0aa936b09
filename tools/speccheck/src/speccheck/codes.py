"""Stable finding codes, and the one-line fix hint that goes with each.

A code names what kind of requirement was not met, so that CI (JSON, JUnit,
SARIF reports) can match on it while the human text stays free to change.
The names follow the ros-tooling rosgraph proposal where it has one
(NodeMissing, UnexpectedNode, TopicMissing, TypeMismatch, QoSMismatch); the
others are speccheck's own, in the same style.  A code, once published, is
not renamed: add a new one instead.
"""
from __future__ import annotations

NODE_MISSING = 'NodeMissing'
UNEXPECTED_NODE = 'UnexpectedNode'
DUPLICATE_NODE = 'DuplicateNode'
NODE_MISMATCH = 'NodeMismatch'
EXECUTABLE_MISSING = 'ExecutableMissing'
TOPIC_MISSING = 'TopicMissing'
PUBLISHER_MISSING = 'PublisherMissing'
SUBSCRIBER_MISSING = 'SubscriberMissing'
TYPE_MISMATCH = 'TypeMismatch'
RATE_MISMATCH = 'RateMismatch'
QOS_MISMATCH = 'QoSMismatch'
PARAMETER_MISSING = 'ParameterMissing'
PARAMETER_MISMATCH = 'ParameterMismatch'
UNEXPECTED_PARAMETER = 'UnexpectedParameter'
PARAMETERS_UNREADABLE = 'ParametersUnreadable'
ARGUMENT_MISSING = 'ArgumentMissing'
ARGUMENT_MISMATCH = 'ArgumentMismatch'
UNEXPECTED_ARGUMENT = 'UnexpectedArgument'
LAUNCH_FAILED = 'LaunchFailed'
#: A requirement this check cannot decide (status `not checked`).
NOT_CHECKED = 'NotChecked'

#: code -> what to do about it, in one line
HINTS: dict[str, str] = {
    NODE_MISSING: 'start a Node with this name and namespace, or remove the node from the spec',
    UNEXPECTED_NODE: 'add the node to the spec, or stop starting it',
    DUPLICATE_NODE: 'give each Node action its own name or namespace',
    NODE_MISMATCH: 'start the package and executable the spec names, or correct the spec',
    EXECUTABLE_MISSING: 'build and source the workspace (colcon build), or fix the package or '
                        'executable name',
    TOPIC_MISSING: 'check the topic name and the remappings of the nodes that should use it',
    PUBLISHER_MISSING: "remap the node's topic to this name, or correct the spec's publishers",
    SUBSCRIBER_MISSING: "remap the node's topic to this name, or correct the spec's subscribers",
    TYPE_MISMATCH: 'use the message type the spec names on every endpoint, or correct the spec',
    RATE_MISMATCH: "change the publishing rate (its parameter or timer), or the spec's rate bounds",
    QOS_MISMATCH: 'make the publisher offer at least the reliability and durability the '
                  'subscriber requests',
    PARAMETER_MISSING: 'declare the parameter in the node, or fix its name in the spec',
    PARAMETER_MISMATCH: 'set the type and value the spec wants (launch file or parameter file)',
    UNEXPECTED_PARAMETER: "fix the parameter's spelling, or add it to the spec",
    PARAMETERS_UNREADABLE: 'make sure the node spins, so that its parameter services answer',
    ARGUMENT_MISSING: 'declare the argument with DeclareLaunchArgument',
    ARGUMENT_MISMATCH: 'make the default and choices of the DeclareLaunchArgument match the spec',
    UNEXPECTED_ARGUMENT: 'drop the argument, or declare it in the launch file',
    LAUNCH_FAILED: 'run the launch file with `ros2 launch` to see its error, and fix that first',
    NOT_CHECKED: 'check it with `speccheck live`, or in a launch test',
}
