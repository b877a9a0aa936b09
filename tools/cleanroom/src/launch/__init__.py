"""Clean-room implementation of the ROS 2 Jazzy `launch` Python API (work in progress)."""
