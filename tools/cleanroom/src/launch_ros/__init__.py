"""Clean-room implementation of the ROS 2 Jazzy `launch_ros` Python API (work in progress)."""
