"""_wiring.in_namespace: a lingering node of an earlier test is not this launch's."""
from __future__ import annotations

from ._wiring import Wiring, in_namespace

FOUND: Wiring = {
    '/scout/distance': (('/scout/sensor_publisher',), ('/scout/data_processor',)),
    '/robot1/distance': (('/robot1/sensor_publisher',), ()),  # killed earlier, still discovered
    '/clock': ((), ('/robot1/robot_controller', '/scout/robot_controller')),
}


def test_keeps_only_the_endpoints_of_nodes_in_the_namespace():
    assert in_namespace(FOUND, '/scout') == {
        '/scout/distance': (('/scout/sensor_publisher',), ('/scout/data_processor',)),
        '/clock': ((), ('/scout/robot_controller',)),
    }


def test_a_namespace_is_not_a_name_prefix():
    assert in_namespace({'/scout2/x': (('/scout2/a',), ())}, '/scout') == {}
