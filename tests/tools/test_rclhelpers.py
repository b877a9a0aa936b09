"""rclhelpers: the one copy of the rclpy helpers labkit and the clean room's `ros2` share.

Issue 13: labkit and ros2_cleanroom each kept the same name helpers and the
same "call a service once" lines; both now import them from rclhelpers, and
the last test keeps a second copy from coming back.
"""
from __future__ import annotations

import re
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import psutil
import pytest
import rclpy
from rcl_interfaces.srv import GetParameters, ListParameters
from rclhelpers import services
from rclhelpers.names import full_name, is_hidden, split_full_name
from rclhelpers.services import call_service
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions
from textbook import paths

from .._polling import poll, still_running

pytestmark = pytest.mark.ros  # creates rclpy nodes and services

RCLHELPERS = paths.TOOLS / 'rclhelpers'


@pytest.mark.parametrize(('name', 'namespace', 'full'), [
    ('talker', '/', '/talker'),
    ('talker', '/robot1', '/robot1/talker'),
    ('controller', '/fleet/robot1', '/fleet/robot1/controller'),
])
def test_full_name_and_split_full_name_are_inverse(name, namespace, full):
    assert full_name(name, namespace) == full
    assert split_full_name(full) == (name, namespace)


def test_split_full_name_puts_a_relative_name_in_the_root_namespace():
    assert split_full_name('talker') == ('talker', '/')
    assert split_full_name('robot1/talker') == ('talker', '/robot1')


@pytest.mark.parametrize(('name', 'hidden'), [
    ('/_labkit_1234', True),
    ('/_ros2cli_99', True),
    ('/robot1/_internal/state', True),
    ('_private', True),
    ('/robot1/talker', False),
    ('/sensor_publisher', False),  # an underscore inside a token hides nothing
    ('/', False),
])
def test_is_hidden_looks_at_the_first_character_of_every_token(name, hidden):
    assert is_hidden(name) is hidden


@pytest.fixture
def context() -> Iterator[Context]:
    """A private rclpy context, so the test touches no global rclpy state."""
    context = Context()
    rclpy.init(args=[], context=context, signal_handler_options=SignalHandlerOptions.NO)
    try:
        yield context
    finally:
        context.try_shutdown()


@pytest.fixture
def parameter_server(context: Context) -> Iterator[str]:
    """A node offering its parameter services, spun in a background thread; its full name."""
    server = rclpy.create_node('rclhelpers_test_server', context=context)
    server.declare_parameter('answer', 42)
    executor = SingleThreadedExecutor(context=context)
    executor.add_node(server)
    thread = threading.Thread(target=executor.spin, daemon=True)
    thread.start()
    try:
        yield full_name(server.get_name(), server.get_namespace())
    finally:
        executor.shutdown()
        thread.join()
        server.destroy_node()


@pytest.fixture
def client_node(context: Context) -> Iterator[Node]:
    """A node nothing spins, like labkit's observer and the `ros2` command's node."""
    node = rclpy.create_node('_rclhelpers_test_client', context=context,
                             start_parameter_services=False, enable_rosout=False)
    try:
        yield node
    finally:
        node.destroy_node()


def test_call_service_returns_the_answer_of_a_running_service(parameter_server, client_node):
    listing = call_service(client_node, ListParameters, f'{parameter_server}/list_parameters',
                           ListParameters.Request(depth=0))
    assert listing is not None, f'{parameter_server}/list_parameters did not answer'
    assert 'answer' in listing.result.names

    values = call_service(client_node, GetParameters, f'{parameter_server}/get_parameters',
                          GetParameters.Request(names=['answer']))
    assert values is not None, f'{parameter_server}/get_parameters did not answer'
    assert [value.integer_value for value in values.values] == [42]
    assert list(client_node.clients) == [], 'the temporary client was left on the node'


def test_call_service_gives_none_when_nobody_offers_the_service(client_node):
    response = call_service(client_node, ListParameters, '/nobody_here/list_parameters',
                            ListParameters.Request(), timeout=0.2)
    assert response is None
    assert list(client_node.clients) == [], 'the temporary client was left on the node'


# A module-level definition of one of the helpers, or rclpy's spin-a-future
# call, anywhere in tools/ but rclhelpers is a second copy.
# So is a lease taken from domain_coordinator (rclhelpers.domains) or a parent-death
# signal set up (rclhelpers.processes).
COPY = re.compile(r'^def (full_name|split_full_name|is_hidden|call_service)\(|'
                  r'spin_until_future_complete|domain_coordinator\.domain_id\(|PR_SET_PDEATHSIG = ',
                  re.MULTILINE)


def second_copies(tools: Path) -> list[str]:
    """`path:line: text` of every line in tools/ (but rclhelpers and tests) that repeats a
    helper."""
    found = []
    for path in sorted(tools.rglob('*.py')):
        if RCLHELPERS in path.parents or 'tests' in path.relative_to(tools).parts:
            continue  # tests may imitate another holder or client on purpose
        text = path.read_text(encoding='utf-8')
        for match in COPY.finditer(text):
            line = text.count('\n', 0, match.start()) + 1
            found.append(f'{path.relative_to(tools)}:{line}: {match.group(0)}')
    return found


def test_the_helpers_have_one_copy_in_tools():
    assert list(RCLHELPERS.rglob('*.py')), f'no rclhelpers sources in {RCLHELPERS}'
    copies = second_copies(paths.TOOLS)
    assert not copies, ('a second copy of an rclhelpers helper; import it from rclhelpers '
                        '(issue 13):\n' + '\n'.join(copies))


def test_a_second_copy_is_found(tmp_path):
    (tmp_path / 'labkit').mkdir()
    (tmp_path / 'labkit' / 'observer.py').write_text(
        'import rclpy\n\n\ndef is_hidden(name):\n    return False\n\n'
        'rclpy.spin_until_future_complete(node, future)\n'
        'with domain_coordinator.domain_id(selector=pick):\n    pass\n'
        '_PR_SET_PDEATHSIG = 1\n')
    assert second_copies(tmp_path) == ['labkit/observer.py:4: def is_hidden(',
                                       'labkit/observer.py:7: spin_until_future_complete',
                                       'labkit/observer.py:8: domain_coordinator.domain_id(',
                                       'labkit/observer.py:10: PR_SET_PDEATHSIG = ']


# A parent that starts a child with die_with_parent, says the child's pid and waits.
PARENT = """
import os, signal, subprocess, sys
from rclhelpers.processes import die_with_parent
me = os.getpid()
child = subprocess.Popen([sys.executable, '-c', 'import time; time.sleep(600)'],
                         preexec_fn=lambda: die_with_parent(me, signal.SIGTERM))
print(child.pid, flush=True)
child.wait()
"""


def test_die_with_parent_ends_the_child_when_its_parent_is_killed():
    parent = subprocess.Popen([sys.executable, '-c', PARENT], stdout=subprocess.PIPE, text=True)
    child = psutil.Process(int(parent.stdout.readline()))
    try:
        parent.kill()  # SIGKILL: the parent can clean up nothing itself
        parent.wait()
        gone = poll(lambda: not still_running([child.pid]), 30)  # 30: a hang guard
    finally:
        if child.is_running():
            child.send_signal(signal.SIGKILL)
    assert gone, 'the child outlived its killed parent'


def test_read_service_asks_again_until_answered(monkeypatch):
    """A first request that reached only a stale server (None) is sent again."""
    answers = [None, None, 'response']
    timeouts = []

    def call(node, srv_type, name, request, timeout):
        timeouts.append(timeout)
        return answers.pop(0)

    monkeypatch.setattr(services, 'call_service', call)
    assert services.read_service(None, None, '/x', None, timeout=30) == 'response'
    assert timeouts == [services.RESEND_AFTER] * 3


def test_read_service_gives_up_after_its_timeout(monkeypatch):
    monkeypatch.setattr(services, 'call_service', lambda *args: None)
    assert services.read_service(None, None, '/x', None, timeout=0) is None
