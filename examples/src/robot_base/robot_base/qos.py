"""QoS presets, defined once so that both ends of a topic agree.

A best-effort publisher paired with a reliable subscription never connects;
sharing the profile object between publisher and subscriber prevents that.
"""
from rclpy.qos import QoSProfile, ReliabilityPolicy, qos_profile_sensor_data

#: Laser scans: a late scan is useless, so drop it instead of queueing it.
SCAN_QOS = qos_profile_sensor_data

#: Heartbeats repeat every second; losing one is harmless.
HEARTBEAT_QOS = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
