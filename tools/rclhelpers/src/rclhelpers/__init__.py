"""Helpers shared by the book's tools (labkit, textbook) and the clean room.

labkit must run on a real ROS 2, where the clean room is not installed, and
the clean room (our stand-in for ROS 2's launch and ros2cli) may not import
labkit: this distribution is the bottom layer both can use (issue 13).  Each
module imports only what its own job needs, so that a light caller (`ros2
run`, the test plugin) does not pay for rclpy:

- `names`: full node names and hidden names (no imports);
- `services`: one service call on a node nothing spins (rclpy);
- `domains`: the ROS domain lease (domain_coordinator);
- `processes`: a child that dies with its parent (Linux prctl), a process group
  stopped with escalating signals (psutil).
"""
