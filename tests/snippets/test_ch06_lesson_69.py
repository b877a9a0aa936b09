"""Lesson 6.9 (debugging multi-node communication with an assistant): the
stored prompts and replies are unchanged, the shortest question comes first,
the second prompt still pastes the package's code as it is, and every
experiment the lesson shows gives the result the lesson states (above all
the measurements that reject the shortest reply's bet, and the one-sided
fixes).

The lesson's experiments are repeated here as a student's terminal would
run them: `ros2 run` with a durability parameter, the launch files, late
`ros2 topic echo`, `ros2 topic info -v`, `ros2 doctor --report`.  Each test
waits for log lines or graph states, never for a time, and stops what it
started before the next test (they share a ROS domain, and a transient_local
publisher of one would feed a subscriber of the next).
"""
from __future__ import annotations

import hashlib
import re
import subprocess

import labkit
from textbook import paths

from .._polling import wait_for

LESSON = paths.LESSONS / 'ch06/L2/09_debugging_with_an_assistant.md'
DRAFTS = paths.SNIPPETS / 'ai_drafts' / 'ch06_09_speed_limit'
PACKAGE = paths.SNIPPETS / 'comms_demo_pkg'
#: sha256 of each stored prompt and reply, as the assistant got and gave them.
STORED = {
    'zero_prompt.md': 'bc3c8316be570f8bd480e00054f08ce796bc4bcbaff6d4f454bb2c6fbf0e143e',
    'zero_response.md': '7795a2c95c9393baf71258dd4576dd1dbf8651bfed51d2ef7e1af5dc178fd5b0',
    'first_prompt.md': '7109a2a6245b0324d60ca0e95ad164d0a1f589149bb85e0d6f9fa69ca1205802',
    'first_response.md': '8229cddb4efd7cb355ed4a65677cc7fd33169eb41df28a2f3163fda3508c0be8',
    'prompt.md': '84810855ff69a398f9227168eb2e614a8dd603cf4cfe05ec851753e06f32148b',
    'response.md': 'fa94a0862c8bc40089a30f55af554235ac0fe0b170ee1e69cc38922699352a14',
}
HANG_GUARD = 30.0  # seconds; only stops a broken test from hanging, never a speed limit
#: How long a late `ros2 topic echo --once` listens where nothing may arrive.
ECHO_WAIT = '3'
NODES = ['/limit_server', '/speed_governor']
PUBLISHED = r'\[limit_server\]: Published speed limit'
RECEIVED = r'\[speed_governor\]: Speed limit (\d+\.\d\d) m/s received'
WARNING = r'\[speed_governor\]: No speed limit received yet'
DATA = re.compile(r'^data: (\S+)$', re.MULTILINE)
MARKER = re.compile(r'^[ \t]*# \[(?:START|END) \w+\]\n', re.MULTILINE)


def _ros2(env: dict[str, str], *words: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['ros2', *words], env=env, cwd=paths.WORKSPACE,
                          capture_output=True, text=True, timeout=HANG_GUARD)


def _late_echo(env: dict[str, str], *options: str) -> subprocess.CompletedProcess[str]:
    return _ros2(env, 'topic', 'echo', '/speed_limit', *options, '--once', '--timeout', ECHO_WAIT)


def _topic_info(env: dict[str, str]) -> str:
    """`ros2 topic info -v /speed_limit`, once both endpoints are discovered."""
    def read() -> str:
        info = _ros2(env, 'topic', 'info', '-v', '/speed_limit').stdout
        return info if info.count('Endpoint type:') == 2 else ''
    return wait_for(read, HANG_GUARD, 'both /speed_limit endpoints in topic info -v')


def _durabilities(env: dict[str, str]) -> dict[str, str]:
    """PUBLISHER / SUBSCRIPTION -> durability of that /speed_limit endpoint (the lesson
    greps these lines)."""
    return dict(re.findall(r'Endpoint type: (\S+)\n(?:.*\n)*?\s+Durability: (\S+)',
                           _topic_info(env)))


def _publishers(env: dict[str, str]) -> tuple[str, list[str]]:
    """The publisher count `topic info -v` states, and the node of each publisher
    endpoint it lists (the lesson rejects "another topic name" with these lines)."""
    info = _topic_info(env)
    count = re.search(r'^Publisher count: (\d+)$', info, re.MULTILINE).group(1)
    nodes = [re.search(r'^Node name: (\S+)$', block, re.MULTILINE).group(1)
             for block in info.split('\n\n') if 'Endpoint type: PUBLISHER' in block]
    return count, nodes


def _qos_status(env: dict[str, str]) -> str:
    report = _ros2(env, 'doctor', '--report').stdout
    return re.search(r'compatibility status\s*: (.*)', report).group(1)


def _run(env: dict[str, str], executable: str, durability: str | None) -> labkit.Background:
    parameters = {'durability': durability} if durability else None
    return labkit.run('comms_demo_pkg', executable, parameters=parameters, env=env,
                      cwd=paths.WORKSPACE)


def _sha256(name: str) -> str:
    return hashlib.sha256((DRAFTS / name).read_bytes()).hexdigest()


def test_stored_prompts_and_replies_are_unchanged():
    assert {name: _sha256(name) for name in STORED} == STORED


def test_the_lesson_shows_every_stored_prompt_and_reply():
    lesson = LESSON.read_text()
    for name in STORED:
        assert f'```{{snippet}} ai_drafts/ch06_09_speed_limit/{name}\n' in lesson, name


def test_the_lesson_asks_the_shortest_question_first():
    """The symptom-only question is what a student sends before collecting anything."""
    lesson = LESSON.read_text()
    order = [lesson.index(f'ai_drafts/ch06_09_speed_limit/{name}')
             for name in ('zero_prompt.md', 'first_prompt.md', 'prompt.md')]
    assert order == sorted(order)


def test_the_second_prompt_pastes_the_package_as_it_is():
    """If the launch file or a node changes, the stored prompt no longer describes it."""
    blocks = re.findall(r'```python\n(.*?)```', (DRAFTS / 'prompt.md').read_text(), re.DOTALL)
    files = [PACKAGE / 'launch' / 'limits_broken.launch.py',
             PACKAGE / 'comms_demo_pkg' / 'limit_server.py',
             PACKAGE / 'comms_demo_pkg' / 'speed_governor.py']
    assert blocks == [MARKER.sub('', path.read_text()) for path in files]


def test_broken_system_late_echoes_get_nothing_and_a_new_publish_arrives(ros_env):
    with labkit.launch('comms_demo_pkg', 'limits_broken.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as broken:
        broken.wait_for_nodes(NODES, timeout=HANG_GUARD)
        broken.wait_for_output(WARNING, timeout=HANG_GUARD)
        # The shortest reply's bet (another topic name) and its "never publishes": rejected.
        assert _publishers(ros_env) == ('1', ['limit_server'])
        assert re.search(PUBLISHED, broken.output()), broken.output()
        assert _durabilities(ros_env) == {'PUBLISHER': 'VOLATILE', 'SUBSCRIPTION': 'VOLATILE'}
        assert _qos_status(ros_env) == 'OK'

        plain = _late_echo(ros_env)
        assert not DATA.search(plain.stdout) and plain.returncode == 0, plain
        asking = _late_echo(ros_env, '--qos-durability', 'transient_local',
                            '--qos-reliability', 'reliable')
        assert not DATA.search(asking.stdout), asking
        assert re.search(r"New publisher discovered on topic '/speed_limit', offering "
                         r'incompatible QoS\. .*Last incompatible policy: DURABILITY',
                         asking.stderr), asking

        # Experiment A: an echo that has subscribed, and the governor, get a new publish.
        with labkit.start('ros2 topic echo /speed_limit', env=ros_env,
                          cwd=paths.WORKSPACE) as listener:
            wait_for(lambda: len(labkit.graph(include_hidden=True)
                                 .subscribers('/speed_limit')) >= 2,
                     HANG_GUARD, "the echo's subscription in the graph")
            assert _ros2(ros_env, 'param', 'set', '/limit_server', 'max_speed',
                         '0.5').returncode == 0
            received = broken.wait_for_output(RECEIVED, timeout=HANG_GUARD)
            assert re.search(RECEIVED, received).group(1) == '0.50'
            assert listener.wait_for_output(r'^data:', timeout=HANG_GUARD) == 'data: 0.5'
        assert broken.stop() == 0, broken.output()


def test_publisher_only_transient_local_keeps_the_limit_but_the_governor_gets_nothing(ros_env):
    with _run(ros_env, 'limit_server', 'transient_local') as server:
        server.wait_for_output(PUBLISHED, timeout=HANG_GUARD)
        with _run(ros_env, 'speed_governor', None) as governor:
            governor.wait_for_output(WARNING, timeout=HANG_GUARD)
            assert _durabilities(ros_env) == {'PUBLISHER': 'TRANSIENT_LOCAL',
                                              'SUBSCRIPTION': 'VOLATILE'}
            assert _qos_status(ros_env) == 'OK'
            # echo picks the durability the publisher offers: no --qos option needed.
            echo = _late_echo(ros_env)
            assert DATA.findall(echo.stdout) == ['0.30000001192092896'], echo
            governor.stop()
        assert not re.search(RECEIVED, governor.output()), governor.output()
        server.stop()
    # The kept limit lived in the server's publisher: gone with it.
    after = _late_echo(ros_env, 'std_msgs/msg/Float32', '--qos-durability', 'transient_local',
                       '--qos-reliability', 'reliable')
    assert not DATA.search(after.stdout) and after.returncode == 0, after


def test_subscriber_only_transient_local_is_incompatible(ros_env):
    with _run(ros_env, 'limit_server', None) as server:
        server.wait_for_output(PUBLISHED, timeout=HANG_GUARD)
        with _run(ros_env, 'speed_governor', 'transient_local') as governor:
            governor.wait_for_output(r"\[speed_governor\]: New publisher discovered on topic "
                                     r"'speed_limit', offering incompatible QoS\. No messages "
                                     r'will be received from it\. Last incompatible policy: '
                                     r'DURABILITY', timeout=HANG_GUARD)
            server.wait_for_output(r"\[limit_server\]: New subscription discovered on topic "
                                   r"'speed_limit', requesting incompatible QoS\. No messages "
                                   r'will be sent to it\. Last incompatible policy: DURABILITY',
                                   timeout=HANG_GUARD)
            assert _durabilities(ros_env) == {'PUBLISHER': 'VOLATILE',
                                              'SUBSCRIPTION': 'TRANSIENT_LOCAL'}
            assert _qos_status(ros_env) == \
                'ERROR: Volatile publisher and transient local subscription;'
            governor.stop()
        assert not re.search(RECEIVED, governor.output()), governor.output()
        server.stop()


def test_fixed_system_a_plain_late_echo_gets_the_limit(ros_env):
    with labkit.launch('comms_demo_pkg', 'limits_fixed.launch.py', env=ros_env,
                       cwd=paths.WORKSPACE) as fixed:
        received = fixed.wait_for_output(RECEIVED, timeout=HANG_GUARD)
        assert re.search(RECEIVED, received).group(1) == '0.30'
        assert _durabilities(ros_env) == {'PUBLISHER': 'TRANSIENT_LOCAL',
                                          'SUBSCRIPTION': 'TRANSIENT_LOCAL'}
        assert _qos_status(ros_env) == 'OK'
        echo = _late_echo(ros_env)
        assert DATA.findall(echo.stdout) == ['0.30000001192092896'], echo
        assert fixed.stop() == 0, fixed.output()
