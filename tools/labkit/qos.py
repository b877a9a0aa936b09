"""QoS of every publisher and subscriber of a topic, and which pairs cannot talk.

speccheck's (`speccheck.qos`, one copy for both tools), under the name lessons
and graders use.
"""
from __future__ import annotations

from speccheck.qos import Endpoint, Mismatch, endpoints, mismatches

__all__ = ['Endpoint', 'Mismatch', 'endpoints', 'mismatches']
