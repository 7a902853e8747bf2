"""QoS profiles the camera stack shares (built in helpers, as real drivers do)."""
from rclpy.duration import Duration
from rclpy.qos import DurabilityPolicy, LivelinessPolicy, QoSProfile


def latched(depth=1):
    """Late joiners still get the last calibration."""
    return QoSProfile(depth=depth, durability=DurabilityPolicy.TRANSIENT_LOCAL)


def heartbeat_qos():
    """One heartbeat a second, asserted by the middleware."""
    return QoSProfile(depth=1, deadline=Duration(seconds=1),
                      liveliness=LivelinessPolicy.AUTOMATIC,
                      liveliness_lease_duration=Duration(seconds=2))
