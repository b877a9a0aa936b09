"""Helpers below `parameter_descriptions` and `ros_adapters` in the import order.

`launch_ros.utilities` holds `evaluate_parameters` / `normalize_parameters`,
which build on the parameter descriptions, while the descriptions (and the
ROS adapter) need these helpers: keeping them here, below both, is what keeps
the package free of import cycles (see the import contract in .importlinter).
Their public homes stay `launch_ros.utilities.<module>`.
"""
