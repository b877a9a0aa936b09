"""ReadyAggregator: call a ready function once several parts are ready."""
from __future__ import annotations

import threading
from collections.abc import Callable


class ReadyAggregator:
    """Calls `ready_fn` on the `num_calls`-th call of `ready_fn()` on this object."""

    def __init__(self, ready_fn: Callable[[], None], num_calls: int) -> None:
        self._ready_fn = ready_fn
        self._count_to_ready = num_calls
        self._lock = threading.Lock()

    def ready_fn(self) -> None:
        """Count one part as ready; the last one calls the parent ready function."""
        with self._lock:
            self._count_to_ready -= 1
            fire = self._count_to_ready == 0
        if fire:
            self._ready_fn()
