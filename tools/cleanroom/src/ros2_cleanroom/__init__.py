"""The clean-room `ros2` command: verbs launch, run, node, topic and param."""
