"""labkit's graph observer is speccheck's (`speccheck.observer`): one hidden node
per kernel, shared by labkit and a `speccheck.check_live` in the same kernel, so
the second tool does not wait for discovery again.

`labkit.observer` is that very module (so what a test patches here is what
labkit and speccheck use); its node is named `_labkit_<pid>` in a kernel.
"""
from __future__ import annotations

import sys

from speccheck import observer

observer.NODE_PREFIX = '_labkit'
sys.modules[__name__] = observer
