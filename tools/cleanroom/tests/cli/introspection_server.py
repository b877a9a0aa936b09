"""A std_srvs/SetBool server `/set_flag` with service introspection on (contents), called by
a client every 0.3 s, and a server `/quiet_flag` with introspection off: for `ros2 service
echo`.  Prints `ready` once both serve; SIGINT stops it."""
import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState
from std_srvs.srv import SetBool


def handle(request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
    response.success = request.data
    response.message = f'set to {request.data}'
    return response


def main() -> None:
    rclpy.init()
    node = rclpy.create_node('introspection_server')
    server = node.create_service(SetBool, '/set_flag', handle)
    server.configure_introspection(node.get_clock(), qos_profile_system_default,
                                   ServiceIntrospectionState.CONTENTS)
    node.create_service(SetBool, '/quiet_flag', handle)
    client = node.create_client(SetBool, '/set_flag')
    node.create_timer(0.3, lambda: client.call_async(SetBool.Request(data=True)))
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    print('ready introspection_server', flush=True)
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


if __name__ == '__main__':
    main()
