"""labkit waits until the ros2 daemon lists what the graph has (Jazzy's `ros2`
answers "Node not found" until its daemon has seen a node), and only where
there is a daemon (Jazzy's and the clean room's `ros2` have one)."""
from __future__ import annotations

import stat
from pathlib import Path

from labkit.ros2_command import _has_daemon, find_ros2, missing_from_daemon

# A `ros2` with a daemon that learns about the graph on its third look, as a
# daemon started moments ago does; every call is logged.
FAKE_ROS2 = """#!/bin/bash
here="$(dirname "$0")"
echo "$*" >> "$here/calls"
case "$*" in
  "daemon status") echo "The daemon is not running" ;;
  "daemon start") echo "The daemon has been started"; touch "$here/started" ;;
  "node list --all"|"topic list")
    looks=$(grep -c "node list" "$here/calls")
    if [ -f "$here/started" ] && [ "$looks" -ge 3 ] && [ ! -f "$here/blind" ]; then
      if [ "$*" = "topic list" ]; then printf '/chatter\\n/rosout\\n'; else echo /talker; fi
    fi ;;
  *) exit 2 ;;
esac
"""


def _fake_ros2(folder: Path, blind: bool = False) -> str:
    ros2 = folder / 'ros2'
    ros2.write_text(FAKE_ROS2)
    ros2.chmod(ros2.stat().st_mode | stat.S_IEXEC)
    if blind:
        (folder / 'blind').touch()
    return str(ros2)


def test_it_starts_the_daemon_and_waits_until_it_lists_nodes_and_topics(tmp_path):
    ros2 = _fake_ros2(tmp_path)
    assert missing_from_daemon(ros2, ['/talker'], ['/chatter'], timeout=30) == []
    calls = (tmp_path / 'calls').read_text().splitlines()
    assert calls[:2] == ['daemon status', 'daemon start']
    assert calls.count('node list --all') == 3


def test_what_the_daemon_never_lists_is_returned(tmp_path):
    ros2 = _fake_ros2(tmp_path, blind=True)
    assert missing_from_daemon(ros2, ['/talker'], ['/chatter'], timeout=0.5) == [
        '/talker', '/chatter']


def test_without_a_daemon_verb_there_is_nothing_to_wait_for(tmp_path):
    """A `ros2` whose `daemon status` fails (no such verb): no wait, no other call."""
    ros2 = tmp_path / 'ros2'
    ros2.write_text('#!/bin/bash\necho "$*" >> "$(dirname "$0")/calls"\nexit 2\n')
    ros2.chmod(ros2.stat().st_mode | stat.S_IEXEC)
    assert missing_from_daemon(str(ros2), ['/nobody'], ['/nothing'], timeout=30) == []
    assert (tmp_path / 'calls').read_text().splitlines() == ['daemon status']


def test_the_book_s_ros2_has_a_daemon_to_wait_for():
    """The clean room's `ros2` (this environment's) has the daemon verb, as Jazzy's."""
    assert _has_daemon(find_ros2())
