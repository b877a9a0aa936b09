"""Create a future on the launch's loop, or a detached one before the loop exists."""
import asyncio


def create_future(loop: asyncio.AbstractEventLoop | None) -> asyncio.Future:
    """Return a new future bound to `loop` when given."""
    if loop is not None:
        return loop.create_future()
    return asyncio.Future()
