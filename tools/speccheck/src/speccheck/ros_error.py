"""The error the graph-reading helpers raise when the ROS graph does not give what
was asked: a node that does not answer its parameter services, a message type
that does not import.  Its message is written for the person at the terminal;
the running check turns it into a finding, labkit into a LabkitError."""
from __future__ import annotations


class RosError(RuntimeError):
    """The ROS graph did not answer as needed; the message says what and why."""
