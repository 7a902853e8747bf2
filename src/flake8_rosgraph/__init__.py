"""flake8-rosgraph: the ROS 2 computation graph of rclpy code, found statically."""

__version__ = "0.2.0"
