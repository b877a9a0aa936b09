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

#: code -> which requirement was not met (SARIF rule descriptions; the reference page's table)
SUMMARIES: dict[str, str] = {
    NODE_MISSING: 'A node of the spec is not started (static) or not running (live)',
    UNEXPECTED_NODE: 'The launch file starts a named node the spec does not list',
    DUPLICATE_NODE: 'Two Node actions start nodes of one name',
    NODE_MISMATCH: 'The node is started from another package or executable',
    EXECUTABLE_MISSING: 'The package or executable is not in the sourced workspace',
    TOPIC_MISSING: 'No node publishes or subscribes to a topic of the spec',
    PUBLISHER_MISSING: 'A node that must publish to a topic does not',
    SUBSCRIBER_MISSING: 'A node that must subscribe to a topic does not',
    TYPE_MISMATCH: "A topic has another message type than the spec's",
    RATE_MISMATCH: "The measured rate is outside the spec's bounds, or no message came",
    QOS_MISMATCH: 'A publisher and a subscriber of a topic have incompatible QoS',
    PARAMETER_MISSING: 'The running node has no parameter of that name',
    PARAMETER_MISMATCH: "A parameter's type or value differs from the spec's",
    UNEXPECTED_PARAMETER: 'The launch file sets a parameter the spec does not list',
    PARAMETERS_UNREADABLE: "The node's parameters could not be read",
    ARGUMENT_MISSING: 'The launch file does not declare an argument of the spec',
    ARGUMENT_MISMATCH: "A launch argument's default, required-ness or choices differ",
    UNEXPECTED_ARGUMENT: 'An argument given on the command line is declared nowhere',
    LAUNCH_FAILED: 'The launch file fails, or its nodes did not appear in time',
    NOT_CHECKED: 'A requirement this check cannot decide',
}
