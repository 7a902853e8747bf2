"""ROS 2 interface definitions (``.msg``, ``.srv``, ``.action``) as data, and the rules rclpy's
generated classes apply to the values stored in their fields.

Nothing here imports a message package: the standard packages ship as facts generated from
their interface files (``standard.json``, see ``scripts/generate_interfaces.py``), and the
workspace's own interface files are parsed when it is analysed.
"""
