"""What the lessons' launch logs say, as patterns the snippet tests share."""
from __future__ import annotations

import re

import pytest

#: `[INFO] [talker-1]: process started with pid [..]` -> the process name
STARTED = re.compile(r'^\[INFO\] \[([\w.]+)-\d+\]: process started with pid')
#: `[INFO] [talker-1]: process has finished cleanly [..]` -> the process name
ENDED = re.compile(r'^\[INFO\] \[([\w.]+)-\d+\]: process has finished cleanly')

#: A node that ignores Ctrl+C's SIGINT and SIGTERM while Fast DDS deletes its
#: participant (a deadlock between discovery listener threads and the deletion;
#: gdb shows them in onReaderDiscovery / assert_remote_participant_liveliness,
#: the class of eProsima/Fast-DDS#6193 and ros2/rcl#886) is escalated by launch,
#: exactly as Jazzy escalates it, and the test's "every process finished cleanly"
#: fails.  Such a test runs once more, and only for that failure: any other
#: failure, or the same one twice, fails the test.
DDS_SHUTDOWN_HANG = pytest.mark.flaky(reruns=1, only_rerun=[r'failed to terminate'])
