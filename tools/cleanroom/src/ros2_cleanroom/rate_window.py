"""Message arrival statistics for `ros2 topic hz`, kept apart from ROS for testing."""
from __future__ import annotations

import math
from collections import deque


class RateWindow:
    """Arrival times of the last `size` messages and the rate report they give."""

    def __init__(self, size: int = 10000) -> None:
        self.times: deque[float] = deque(maxlen=size)
        self.received = 0
        self._reported = 0

    def add(self, stamp: float) -> None:
        self.times.append(stamp)
        self.received += 1

    def report(self) -> str | None:
        """The block `ros2 topic hz` prints each second, or None if nothing to say.

        'no new messages' when nothing arrived since the last report; nothing
        at all until two messages give a first interval.
        """
        if self.received == self._reported:
            return 'no new messages' if self._reported else None
        if len(self.times) < 2:
            return None
        self._reported = self.received
        stamps = list(self.times)
        intervals = [b - a for a, b in zip(stamps, stamps[1:], strict=False)]
        mean = sum(intervals) / len(intervals)
        if mean <= 0:
            return None
        std_dev = math.sqrt(sum((d - mean) ** 2 for d in intervals) / len(intervals))
        return (f'average rate: {1.0 / mean:.3f}\n'
                f'\tmin: {min(intervals):.3f}s max: {max(intervals):.3f}s '
                f'std dev: {std_dev:.5f}s window: {len(stamps)}')
