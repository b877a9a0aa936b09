"""What `ros2 topic bw` and `ros2 topic delay` report each second, kept apart from ROS."""
from __future__ import annotations

import math
from collections import deque


def _size(count: float) -> str:
    """Bytes as `ros2 topic bw` prints them: `20 B`, `1.51 KB`, `2.50 MB`."""
    if count < 1000:
        return f'{count:.0f} B'
    if count < 1000 * 1000:
        return f'{count / 1000:.2f} KB'
    return f'{count / (1000 * 1000):.2f} MB'


class BandwidthWindow:
    """Arrival times and serialized sizes of the last `size` messages."""

    def __init__(self, size: int = 100) -> None:
        self.samples: deque[tuple[float, int]] = deque(maxlen=size)

    def add(self, stamp: float, size: int) -> None:
        self.samples.append((stamp, size))

    def report(self, now: float) -> str | None:
        """Bytes per second since the oldest message of the window, and the sizes."""
        if not self.samples or now <= self.samples[0][0]:
            return None
        sizes = [size for _, size in self.samples]
        rate = sum(sizes) / (now - self.samples[0][0])
        mean = sum(sizes) / len(sizes)
        return (f'{_size(rate)}/s from {len(sizes)} messages\n'
                f'\tMessage size mean: {_size(mean)} min: {_size(min(sizes))} '
                f'max: {_size(max(sizes))}')


class DelayWindow:
    """The delays (receive time minus header stamp, seconds) of the last `size` messages."""

    def __init__(self, size: int = 10000) -> None:
        self.delays: deque[float] = deque(maxlen=size)
        self.received = 0
        self._reported = 0

    def add(self, delay: float) -> None:
        self.delays.append(delay)
        self.received += 1

    def report(self) -> str | None:
        """The block printed each second once messages came in since the last one."""
        if self.received == self._reported or not self.delays:
            return None
        self._reported = self.received
        delays = list(self.delays)
        mean = sum(delays) / len(delays)
        std_dev = math.sqrt(sum((d - mean) ** 2 for d in delays) / len(delays))
        return (f'average delay: {mean:.3f}\n'
                f'\tmin: {min(delays):.3f}s max: {max(delays):.3f}s '
                f'std dev: {std_dev:.5f}s window: {len(delays)}')
