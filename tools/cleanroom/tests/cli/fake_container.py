"""A fake component container for the `ros2 component` tests: an rclpy node that
offers the three composition_interfaces services and keeps a list of "loaded"
components (nothing is loaded: the headless stack has no C++ container).

`python fake_container.py NAME [--ros-args ...]`; prints `ready` once it serves,
and one line per load request (what it was asked for).  Loading from package
`bad` fails with the words rclcpp_components uses for an unknown package.
"""
from __future__ import annotations

import sys

import rclpy
from composition_interfaces.srv import ListNodes, LoadNode, UnloadNode
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.utilities import remove_ros_args

NOT_FOUND = 'Could not find requested resource in ament index'


class FakeContainer(Node):
    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.components: dict[int, str] = {}
        self.next_id = 1
        self.create_service(ListNodes, '~/_container/list_nodes', self.list_nodes)
        self.create_service(LoadNode, '~/_container/load_node', self.load_node)
        self.create_service(UnloadNode, '~/_container/unload_node', self.unload_node)

    def list_nodes(self, request: ListNodes.Request,
                   response: ListNodes.Response) -> ListNodes.Response:
        response.unique_ids = list(self.components)
        response.full_node_names = list(self.components.values())
        return response

    def load_node(self, request: LoadNode.Request,
                  response: LoadNode.Response) -> LoadNode.Response:
        print('load', request.package_name, request.plugin_name, list(request.remap_rules),
              [(p.name, p.value.type) for p in request.parameters], flush=True)
        if request.package_name == 'bad':
            response.error_message = NOT_FOUND
            return response
        name = request.node_name or request.plugin_name.split('::')[-1].lower()
        namespace = request.node_namespace or '/'
        response.full_node_name = namespace.rstrip('/') + '/' + name
        response.unique_id = self.next_id
        response.success = True
        self.components[self.next_id] = response.full_node_name
        self.next_id += 1
        return response

    def unload_node(self, request: UnloadNode.Request,
                    response: UnloadNode.Response) -> UnloadNode.Response:
        if self.components.pop(request.unique_id, None) is None:
            response.error_message = f'No node found with unique_id: {request.unique_id}'
        else:
            response.success = True
        return response


def main() -> None:
    rclpy.init(args=sys.argv)
    plain = remove_ros_args(sys.argv)
    node = FakeContainer(plain[1] if len(plain) > 1 else 'ComponentManager')
    print('ready', flush=True)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
