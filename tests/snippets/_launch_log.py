"""What the lessons' launch logs say, as patterns the snippet tests share."""
from __future__ import annotations

import re

#: `[INFO] [talker-1]: process started with pid [..]` -> the process name
STARTED = re.compile(r'^\[INFO\] \[([\w.]+)-\d+\]: process started with pid')
#: `[INFO] [talker-1]: process has finished cleanly [..]` -> the process name
ENDED = re.compile(r'^\[INFO\] \[([\w.]+)-\d+\]: process has finished cleanly')
