"""Synthetic ROS 2 workspaces of any size, for the growth benchmark.

Why synthetic: measuring how the analysis *scales* needs the same kind of code
at 1×, 2×, 4×, … sizes, and real repositories only come in one size. Copying a
real package N times would not do either: identical module, node and topic
names would collapse into one graph (and raise duplicate-name findings), so the
graph would not grow with the code. Here each copy ("fleet") gets its own
package names, namespace, node names and topic names, while the code inside
keeps the shapes real rclpy code has: a shared ``common`` package imported by
the others (name constants, QoS presets, a base node class, plain helper
maths), sensor drivers on timers, filters that subscribe and republish, a
controller with a service, an action server and client, and a bring-up module
running several nodes in one executor. About two thirds of each file is
ordinary non-ROS logic, as in real nodes.

All templates are written for this benchmark. The output depends only on the
scale, so two runs produce identical files.

Usage: ``python benchmarks/synth.py OUT_DIR [--scale N]`` (OUT_DIR/src/... is written).
"""
from __future__ import annotations

import argparse
import string
from dataclasses import dataclass
from pathlib import Path

#: Sensor channels per fleet; chosen so that one fleet is about 6,250 lines,
#: which makes scale 16 about 100,000 lines.
CHANNELS_PER_FLEET = 31


@dataclass(frozen=True)
class Channel:
    """One sensor chain of a fleet: a driver publishing ``raw``, a filter republishing ``filtered``."""

    index: int
    kind: str  # "range" or "imu"

    @property
    def name(self) -> str:
        return f"{self.kind}{self.index}"

    @property
    def const(self) -> str:
        return self.name.upper()


def fleet_channels() -> list[Channel]:
    return [Channel(i, "range" if i % 2 == 0 else "imu") for i in range(CHANNELS_PER_FLEET)]


# -- package boilerplate --------------------------------------------------------------------

PACKAGE_XML = string.Template('''\
<?xml version="1.0"?>
<?xml-model href="http://download.ros.org/schema/package_format3.xsd" schematypens="http://www.w3.org/2001/XMLSchema"?>
<package format="3">
  <name>$pkg</name>
  <version>0.3.1</version>
  <description>$description</description>
  <maintainer email="bench@flake8-rosgraph.invalid">benchmark generator</maintainer>
  <license>Apache-2.0</license>

  <exec_depend>rclpy</exec_depend>
$depends
  <test_depend>ament_flake8</test_depend>
  <test_depend>python3-pytest</test_depend>

  <export>
    <build_type>ament_python</build_type>
  </export>
</package>
''')

SETUP_PY = string.Template('''\
from setuptools import find_packages, setup

package_name = '$pkg'

setup(
    name=package_name,
    version='0.3.1',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='benchmark generator',
    maintainer_email='bench@flake8-rosgraph.invalid',
    description='$description',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
$scripts
        ],
    },
)
''')

SETUP_CFG = string.Template('''\
[develop]
script_dir=$$base/lib/$pkg
[install]
install_scripts=$$base/lib/$pkg
''')


# -- the common package ---------------------------------------------------------------------

QOS_PY = '''\
"""QoS presets shared by both ends of every topic of the fleet.

Sensor streams are best effort (a late sample is worthless), commands and
modes are reliable, and the latched status is transient-local so that a
dashboard started late still sees the last state.
"""
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data

SENSOR_QOS = qos_profile_sensor_data
FILTERED_QOS = QoSProfile(depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
COMMAND_QOS = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
STATUS_QOS = QoSProfile(
    depth=1,
    reliability=ReliabilityPolicy.RELIABLE,
    durability=DurabilityPolicy.TRANSIENT_LOCAL,
)
HEARTBEAT_QOS = QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)
'''

GEOMETRY_PY = '''\
"""Small geometry helpers used by the drivers, filters and controller.

Kept free of ROS types so they can be unit-tested without a ROS installation.
"""
import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Vector3:
    """A plain 3-vector; the message types are converted at the edges."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0

    def __add__(self, other: 'Vector3') -> 'Vector3':
        return Vector3(self.x + other.x, self.y + other.y, self.z + other.z)

    def __sub__(self, other: 'Vector3') -> 'Vector3':
        return Vector3(self.x - other.x, self.y - other.y, self.z - other.z)

    def scaled(self, factor: float) -> 'Vector3':
        return Vector3(self.x * factor, self.y * factor, self.z * factor)

    def dot(self, other: 'Vector3') -> float:
        return self.x * other.x + self.y * other.y + self.z * other.z

    def norm(self) -> float:
        return math.sqrt(self.dot(self))

    def normalized(self) -> 'Vector3':
        length = self.norm()
        if length < 1e-12:
            return Vector3()
        return self.scaled(1.0 / length)


@dataclass(frozen=True)
class Quaternion:
    """Unit quaternion (x, y, z, w), the convention of geometry_msgs."""

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    w: float = 1.0

    @staticmethod
    def from_yaw(yaw: float) -> 'Quaternion':
        half = yaw / 2.0
        return Quaternion(0.0, 0.0, math.sin(half), math.cos(half))

    def yaw(self) -> float:
        siny_cosp = 2.0 * (self.w * self.z + self.x * self.y)
        cosy_cosp = 1.0 - 2.0 * (self.y * self.y + self.z * self.z)
        return math.atan2(siny_cosp, cosy_cosp)

    def multiply(self, other: 'Quaternion') -> 'Quaternion':
        return Quaternion(
            self.w * other.x + self.x * other.w + self.y * other.z - self.z * other.y,
            self.w * other.y - self.x * other.z + self.y * other.w + self.z * other.x,
            self.w * other.z + self.x * other.y - self.y * other.x + self.z * other.w,
            self.w * other.w - self.x * other.x - self.y * other.y - self.z * other.z,
        )


def normalize_angle(angle: float) -> float:
    """Wrap an angle to [-pi, pi)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def clamp(value: float, low: float, high: float) -> float:
    return max(low, min(high, value))


def lerp(a: float, b: float, t: float) -> float:
    return a + (b - a) * clamp(t, 0.0, 1.0)


def distance_2d(x0: float, y0: float, x1: float, y1: float) -> float:
    return math.hypot(x1 - x0, y1 - y0)
'''

NODE_BASE_PY = string.Template('''\
"""The base class of every node in the fleet: namespace, heartbeat, parameter helpers.

Every node publishes a heartbeat so the supervisor can tell a hung node from a
quiet one; putting it here means no node can forget it.
"""
from rclpy.node import Node
from std_msgs.msg import Header

from $common.names import FLEET_NAMESPACE, HEARTBEAT_TOPIC
from $common.qos import HEARTBEAT_QOS


class FleetNode(Node):
    """A node in the fleet namespace that beats once per second."""

    HEARTBEAT_PERIOD_S = 1.0

    def __init__(self, node_name: str) -> None:
        super().__init__(node_name, namespace=FLEET_NAMESPACE)
        self._beats = 0
        self._heartbeat_pub = self.create_publisher(Header, HEARTBEAT_TOPIC, HEARTBEAT_QOS)
        self._heartbeat_timer = self.create_timer(self.HEARTBEAT_PERIOD_S, self._beat)

    def _beat(self) -> None:
        self._beats += 1
        header = Header()
        header.stamp = self.get_clock().now().to_msg()
        header.frame_id = self.get_name()
        self._heartbeat_pub.publish(header)

    def float_parameter(self, name: str, default: float) -> float:
        """Declare ``name`` and return its value, falling back to ``default`` when unset."""
        self.declare_parameter(name, default)
        value = self.get_parameter(name).value
        return float(value) if value is not None else default

    def int_parameter(self, name: str, default: int) -> int:
        self.declare_parameter(name, default)
        value = self.get_parameter(name).value
        return int(value) if value is not None else default
''')


def names_py(fleet: str, channels: list[Channel]) -> str:
    """The name constants module: one raw and one filtered topic per channel."""
    lines = [
        '"""Topic, service and action names of the fleet, shared by all its packages.',
        "",
        "Relative names resolve in the fleet namespace, so the same code runs once per",
        "robot; importing the constants keeps both ends of a topic in step.",
        '"""',
        "",
        f"FLEET_NAMESPACE = '/{fleet}'",
        "",
        "HEARTBEAT_TOPIC = 'heartbeat'",
        "CMD_VEL_TOPIC = 'cmd_vel'",
        "STATUS_TOPIC = 'status'",
        "MODE_SERVICE = 'set_mode'",
        "CALIBRATE_SERVICE = 'calibrate'",
        "NAVIGATE_ACTION = 'navigate'",
        "",
    ]
    for ch in channels:
        lines.append(f"{ch.const}_RAW = 'sensors/{ch.name}/raw'")
        lines.append(f"{ch.const}_FILTERED = 'sensors/{ch.name}/filtered'")
    lines += ["", "FILTERED_TOPICS = ("]
    lines += [f"    {ch.const}_FILTERED," for ch in channels]
    lines += [")", ""]
    return "\n".join(lines)


# -- sensor drivers -------------------------------------------------------------------------

RANGE_DRIVER_PY = string.Template('''\
"""Driver of range sensor $index: polls the device and publishes ``sensor_msgs/Range``.

The device is simulated by a deterministic sweep so the node runs without hardware;
the reading path (validation, median of three, out-of-range handling) is the real one.
"""
import math

import rclpy
from sensor_msgs.msg import Range
from std_srvs.srv import Trigger

from $common.names import CALIBRATE_SERVICE, ${CONST}_RAW
from $common.node_base import FleetNode
from $common.qos import SENSOR_QOS


class RangeDevice:
    """The device side: raw readings in millimetres, with the usual glitches."""

    MAX_MM = 4000
    MIN_MM = 20

    def __init__(self, phase: float) -> None:
        self._phase = phase
        self._tick = 0
        self.offset_mm = 0

    def read_mm(self) -> int:
        self._tick += 1
        value = 1500.0 + 1200.0 * math.sin(self._phase + self._tick * 0.05)
        if self._tick % 97 == 0:
            return 0  # a dropped echo reads as zero
        return int(value) + self.offset_mm

    def read_filtered_mm(self) -> int:
        samples = sorted(self.read_mm() for _ in range(3))
        return samples[1]


class ${Kind}Driver(FleetNode):
    """Publishes ``${name}/raw`` at ``rate_hz``; ``calibrate`` zeroes the offset."""

    FIELD_OF_VIEW = 0.26

    def __init__(self) -> None:
        super().__init__('${name}_driver')
        self._rate_hz = self.float_parameter('rate_hz', 20.0)
        self._frame_id = 'range_${index}_link'
        self._device = RangeDevice(phase=${index}.0)
        self._publisher = self.create_publisher(Range, ${CONST}_RAW, SENSOR_QOS)
        self._calibrate_srv = self.create_service(Trigger, '${name}/' + CALIBRATE_SERVICE,
                                                  self.on_calibrate)
        self._timer = self.create_timer(1.0 / self._rate_hz, self.poll)
        self._published = 0

    def poll(self) -> None:
        millimetres = self._device.read_filtered_mm()
        msg = Range()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.header.frame_id = self._frame_id
        msg.radiation_type = Range.ULTRASOUND
        msg.field_of_view = self.FIELD_OF_VIEW
        msg.min_range = RangeDevice.MIN_MM / 1000.0
        msg.max_range = RangeDevice.MAX_MM / 1000.0
        if millimetres <= 0:
            msg.range = float('inf')
        elif millimetres < RangeDevice.MIN_MM:
            msg.range = float('-inf')
        else:
            msg.range = min(millimetres, RangeDevice.MAX_MM) / 1000.0
        self._publisher.publish(msg)
        self._published += 1

    def on_calibrate(self, request, response):
        readings = [self._device.read_mm() for _ in range(10)]
        valid = [r for r in readings if r > 0]
        if not valid:
            response.success = False
            response.message = 'no valid reading'
            return response
        self._device.offset_mm = 1000 - sum(valid) // len(valid)
        response.success = True
        response.message = f'offset {self._device.offset_mm} mm'
        return response


def main(args=None):
    rclpy.init(args=args)
    node = ${Kind}Driver()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

IMU_DRIVER_PY = string.Template('''\
"""Driver of IMU $index: integrates the gyro into an orientation and publishes ``sensor_msgs/Imu``.

The orientation is integrated here rather than in the filter because the device
delivers rates at a higher frequency than the topic carries.
"""
import math

import rclpy
from sensor_msgs.msg import Imu

from $common.geometry import Quaternion, Vector3, normalize_angle
from $common.names import ${CONST}_RAW
from $common.node_base import FleetNode
from $common.qos import SENSOR_QOS


class GyroIntegrator:
    """Yaw from the z rate, with a bias estimated while the robot stands still."""

    STILL_THRESHOLD = 0.002

    def __init__(self) -> None:
        self.yaw = 0.0
        self.bias = 0.0
        self._still_samples = 0

    def update(self, rate_z: float, dt: float) -> float:
        if abs(rate_z - self.bias) < self.STILL_THRESHOLD:
            self._still_samples += 1
            self.bias += (rate_z - self.bias) / min(self._still_samples, 500)
        else:
            self._still_samples = 0
        self.yaw = normalize_angle(self.yaw + (rate_z - self.bias) * dt)
        return self.yaw


class ${Kind}Driver(FleetNode):
    """Publishes ``${name}/raw``; the covariances come from parameters."""

    def __init__(self) -> None:
        super().__init__('${name}_driver')
        self._rate_hz = self.float_parameter('rate_hz', 100.0)
        self._gyro_noise = self.float_parameter('gyro_noise', 0.01)
        self._accel_noise = self.float_parameter('accel_noise', 0.05)
        self._integrator = GyroIntegrator()
        self._tick = 0
        self._publisher = self.create_publisher(Imu, ${CONST}_RAW, SENSOR_QOS)
        self._timer = self.create_timer(1.0 / self._rate_hz, self.sample)

    def _simulated_rates(self) -> tuple[Vector3, Vector3]:
        t = self._tick / self._rate_hz
        gyro = Vector3(0.0, 0.0, 0.3 * math.sin(0.5 * t + ${index}))
        accel = Vector3(0.1 * math.cos(t), 0.0, 9.81)
        return gyro, accel

    def sample(self) -> None:
        self._tick += 1
        gyro, accel = self._simulated_rates()
        yaw = self._integrator.update(gyro.z, 1.0 / self._rate_hz)
        orientation = Quaternion.from_yaw(yaw)
        msg = Imu()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.header.frame_id = 'imu_${index}_link'
        msg.orientation.x = orientation.x
        msg.orientation.y = orientation.y
        msg.orientation.z = orientation.z
        msg.orientation.w = orientation.w
        msg.angular_velocity.x = gyro.x
        msg.angular_velocity.y = gyro.y
        msg.angular_velocity.z = gyro.z
        msg.linear_acceleration.x = accel.x
        msg.linear_acceleration.y = accel.y
        msg.linear_acceleration.z = accel.z
        gyro_var = self._gyro_noise ** 2
        accel_var = self._accel_noise ** 2
        msg.angular_velocity_covariance = [gyro_var, 0.0, 0.0, 0.0, gyro_var, 0.0, 0.0, 0.0, gyro_var]
        msg.linear_acceleration_covariance = [accel_var, 0.0, 0.0, 0.0, accel_var, 0.0,
                                              0.0, 0.0, accel_var]
        self._publisher.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = ${Kind}Driver()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

# -- filters ----------------------------------------------------------------------------------

RANGE_FILTER_PY = string.Template('''\
"""Filter for range sensor $index: a sliding median with outlier rejection.

Subscribes to the raw stream and republishes ``${name}/filtered`` at the same
rate; infinite readings (no echo) pass through untouched, as REP 117 asks.
"""
from collections import deque

import rclpy
from sensor_msgs.msg import Range

from $common.names import ${CONST}_FILTERED, ${CONST}_RAW
from $common.node_base import FleetNode
from $common.qos import FILTERED_QOS, SENSOR_QOS


class SlidingMedian:
    """Median of the last ``window`` finite samples, rejecting jumps above ``max_jump``."""

    def __init__(self, window: int, max_jump: float) -> None:
        self._samples: deque = deque(maxlen=window)
        self._max_jump = max_jump
        self.rejected = 0

    def push(self, value: float) -> float | None:
        if self._samples and abs(value - self.median()) > self._max_jump:
            self.rejected += 1
            return None
        self._samples.append(value)
        return self.median()

    def median(self) -> float:
        ordered = sorted(self._samples)
        middle = len(ordered) // 2
        if len(ordered) % 2:
            return ordered[middle]
        return 0.5 * (ordered[middle - 1] + ordered[middle])


class ${Kind}Filter(FleetNode):
    """``${name}/raw`` in, ``${name}/filtered`` out."""

    def __init__(self) -> None:
        super().__init__('${name}_filter')
        window = self.int_parameter('window', 5)
        max_jump = self.float_parameter('max_jump', 0.5)
        self._median = SlidingMedian(window, max_jump)
        self._publisher = self.create_publisher(Range, ${CONST}_FILTERED, FILTERED_QOS)
        self._subscription = self.create_subscription(Range, ${CONST}_RAW, self.on_range,
                                                      SENSOR_QOS)

    def on_range(self, msg: Range) -> None:
        if msg.range in (float('inf'), float('-inf')):
            self._publisher.publish(msg)
            return
        value = self._median.push(msg.range)
        if value is None:
            self.get_logger().debug(f'rejected {msg.range:.3f} m ({self._median.rejected} so far)')
            return
        out = Range()
        out.header = msg.header
        out.radiation_type = msg.radiation_type
        out.field_of_view = msg.field_of_view
        out.min_range = msg.min_range
        out.max_range = msg.max_range
        out.range = value
        self._publisher.publish(out)


def main(args=None):
    rclpy.init(args=args)
    node = ${Kind}Filter()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

IMU_FILTER_PY = string.Template('''\
"""Filter for IMU $index: a complementary filter fusing gyro yaw with accelerometer tilt.

The gyro is trusted at high frequency and the accelerometer at low frequency;
``alpha`` sets the crossover.
"""
import math

import rclpy
from sensor_msgs.msg import Imu

from $common.geometry import Quaternion, clamp
from $common.names import ${CONST}_FILTERED, ${CONST}_RAW
from $common.node_base import FleetNode
from $common.qos import FILTERED_QOS, SENSOR_QOS


class ComplementaryFilter:
    """Roll and pitch from the accelerometer, blended with integrated rates."""

    def __init__(self, alpha: float) -> None:
        self.alpha = clamp(alpha, 0.0, 1.0)
        self.roll = 0.0
        self.pitch = 0.0
        self._last_stamp = None

    def update(self, stamp: float, gyro_x: float, gyro_y: float,
               ax: float, ay: float, az: float) -> tuple[float, float]:
        dt = 0.0 if self._last_stamp is None else max(0.0, stamp - self._last_stamp)
        self._last_stamp = stamp
        accel_roll = math.atan2(ay, az)
        accel_pitch = math.atan2(-ax, math.hypot(ay, az))
        self.roll = self.alpha * (self.roll + gyro_x * dt) + (1.0 - self.alpha) * accel_roll
        self.pitch = self.alpha * (self.pitch + gyro_y * dt) + (1.0 - self.alpha) * accel_pitch
        return self.roll, self.pitch


class ${Kind}Filter(FleetNode):
    """``${name}/raw`` in, ``${name}/filtered`` out, orientation corrected."""

    def __init__(self) -> None:
        super().__init__('${name}_filter')
        self._filter = ComplementaryFilter(self.float_parameter('alpha', 0.98))
        self._publisher = self.create_publisher(Imu, ${CONST}_FILTERED, FILTERED_QOS)
        self._subscription = self.create_subscription(Imu, ${CONST}_RAW, self.on_imu, SENSOR_QOS)

    def on_imu(self, msg: Imu) -> None:
        stamp = msg.header.stamp.sec + msg.header.stamp.nanosec * 1e-9
        roll, pitch = self._filter.update(
            stamp, msg.angular_velocity.x, msg.angular_velocity.y,
            msg.linear_acceleration.x, msg.linear_acceleration.y, msg.linear_acceleration.z)
        yaw = Quaternion(msg.orientation.x, msg.orientation.y,
                         msg.orientation.z, msg.orientation.w).yaw()
        cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
        cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
        cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
        msg.orientation.w = cr * cp * cy + sr * sp * sy
        msg.orientation.x = sr * cp * cy - cr * sp * sy
        msg.orientation.y = cr * sp * cy + sr * cp * sy
        msg.orientation.z = cr * cp * sy - sr * sp * cy
        self._publisher.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = ${Kind}Filter()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

# -- control: controller (service + many subscriptions) and mission (action server + client) ---

CONTROLLER_PY = string.Template('''\
"""The velocity controller: fuses every filtered sensor and publishes ``cmd_vel``.

It slows down in proportion to the nearest obstacle any range sensor sees and
steers towards the heading the mission asks for. ``set_mode`` switches between
idle, manual and auto.
"""
import math

import rclpy
from geometry_msgs.msg import Twist
from sensor_msgs.msg import Imu, Range
from std_msgs.msg import String
from std_srvs.srv import SetBool

from $common.geometry import clamp, normalize_angle
from $common.names import CMD_VEL_TOPIC, MODE_SERVICE, STATUS_TOPIC
$range_imports
$imu_imports
from $common.node_base import FleetNode
from $common.qos import COMMAND_QOS, FILTERED_QOS, STATUS_QOS

RANGE_TOPICS = (
$range_topics
)
IMU_TOPICS = (
$imu_topics
)


class SpeedGovernor:
    """Scales the commanded speed by the clearance ahead."""

    def __init__(self, stop_distance: float, slow_distance: float) -> None:
        self.stop_distance = stop_distance
        self.slow_distance = max(slow_distance, stop_distance + 1e-3)
        self.nearest = {}

    def observe(self, sensor: str, distance: float) -> None:
        self.nearest[sensor] = distance

    def factor(self) -> float:
        if not self.nearest:
            return 0.0
        closest = min(self.nearest.values())
        span = self.slow_distance - self.stop_distance
        return clamp((closest - self.stop_distance) / span, 0.0, 1.0)


class Controller(FleetNode):
    """Publishes ``cmd_vel`` at 20 Hz from the latest sensor data and target heading."""

    MODES = ('idle', 'manual', 'auto')

    def __init__(self) -> None:
        super().__init__('controller')
        self._max_speed = self.float_parameter('max_speed', 0.8)
        self._gain = self.float_parameter('heading_gain', 1.5)
        self._governor = SpeedGovernor(self.float_parameter('stop_distance', 0.3),
                                       self.float_parameter('slow_distance', 1.2))
        self._mode = 'idle'
        self._heading = 0.0
        self._target_heading = 0.0
        self._cmd_pub = self.create_publisher(Twist, CMD_VEL_TOPIC, COMMAND_QOS)
        self._status_pub = self.create_publisher(String, STATUS_TOPIC, STATUS_QOS)
        self._mode_srv = self.create_service(SetBool, MODE_SERVICE, self.on_set_mode)
        self._range_subs = [
            self.create_subscription(Range, topic, self.on_range, FILTERED_QOS)
            for topic in RANGE_TOPICS
        ]
        self._imu_subs = [
            self.create_subscription(Imu, topic, self.on_imu, FILTERED_QOS)
            for topic in IMU_TOPICS
        ]
        self._timer = self.create_timer(0.05, self.control_step)

    def on_range(self, msg: Range) -> None:
        self._governor.observe(msg.header.frame_id, msg.range)

    def on_imu(self, msg: Imu) -> None:
        siny = 2.0 * (msg.orientation.w * msg.orientation.z)
        cosy = 1.0 - 2.0 * (msg.orientation.z * msg.orientation.z)
        if cosy != 0.0 or siny != 0.0:
            self._heading = math.atan2(siny, cosy)

    def on_set_mode(self, request, response):
        self._mode = 'auto' if request.data else 'manual'
        response.success = True
        response.message = self._mode
        status = String()
        status.data = self._mode
        self._status_pub.publish(status)
        return response

    def set_target_heading(self, heading: float) -> None:
        self._target_heading = normalize_angle(heading)

    def control_step(self) -> None:
        cmd = Twist()
        if self._mode == 'auto':
            error = normalize_angle(self._target_heading - self._heading)
            cmd.angular.z = clamp(self._gain * error, -1.0, 1.0)
            cmd.linear.x = self._max_speed * self._governor.factor() * (1.0 - min(abs(error), 1.0))
        self._cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = Controller()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

MISSION_PY = string.Template('''\
"""The mission executive: serves ``navigate`` and switches the controller to auto.

A goal is a list of waypoints; the executive reports progress as feedback and
succeeds when the last one is reached or the time budget runs out.
"""
import math
import time

import rclpy
from nav2_msgs.action import NavigateToPose
from rclpy.action import ActionServer
from std_srvs.srv import SetBool

from $common.geometry import distance_2d
from $common.names import MODE_SERVICE, NAVIGATE_ACTION
from $common.node_base import FleetNode


class Waypoints:
    """The remaining waypoints of the active goal."""

    def __init__(self, points: list[tuple[float, float]], tolerance: float) -> None:
        self.points = list(points)
        self.tolerance = tolerance

    def advance(self, x: float, y: float) -> bool:
        while self.points and distance_2d(x, y, *self.points[0]) < self.tolerance:
            self.points.pop(0)
        return not self.points


class Mission(FleetNode):
    """Action server ``navigate``; client of the controller's ``set_mode``."""

    def __init__(self) -> None:
        super().__init__('mission')
        self._tolerance = self.float_parameter('goal_tolerance', 0.25)
        self._budget_s = self.float_parameter('time_budget', 120.0)
        self._mode_client = self.create_client(SetBool, MODE_SERVICE)
        self._server = ActionServer(self, NavigateToPose, NAVIGATE_ACTION,
                                    execute_callback=self.execute)

    def _set_auto(self, enabled: bool) -> None:
        if not self._mode_client.wait_for_service(timeout_sec=1.0):
            self.get_logger().warning('controller has no set_mode service')
            return
        request = SetBool.Request()
        request.data = enabled
        self._mode_client.call_async(request)

    def execute(self, goal_handle):
        pose = goal_handle.request.pose.pose.position
        route = Waypoints([(pose.x / 2.0, pose.y / 2.0), (pose.x, pose.y)], self._tolerance)
        self._set_auto(True)
        started = time.monotonic()
        feedback = NavigateToPose.Feedback()
        x = y = 0.0
        while not route.advance(x, y):
            if time.monotonic() - started > self._budget_s:
                self._set_auto(False)
                goal_handle.abort()
                return NavigateToPose.Result()
            tx, ty = route.points[0]
            heading = math.atan2(ty - y, tx - x)
            x += 0.1 * math.cos(heading)
            y += 0.1 * math.sin(heading)
            feedback.distance_remaining = distance_2d(x, y, pose.x, pose.y)
            goal_handle.publish_feedback(feedback)
        self._set_auto(False)
        goal_handle.succeed()
        return NavigateToPose.Result()


def main(args=None):
    rclpy.init(args=args)
    node = Mission()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

# -- apps: operator console (action client, status) and bring-up (several nodes, one process) --

CONSOLE_PY = string.Template('''\
"""The operator console: sends navigation goals and shows the fleet status.

Goals come from the ``goals`` parameter as ``x,y`` pairs; the console sends
the next one when the previous one finishes.
"""
import rclpy
from geometry_msgs.msg import Twist
from nav2_msgs.action import NavigateToPose
from rclpy.action import ActionClient
from std_msgs.msg import Header, String

from $common.names import CMD_VEL_TOPIC, HEARTBEAT_TOPIC, NAVIGATE_ACTION, STATUS_TOPIC
from $common.node_base import FleetNode
from $common.qos import COMMAND_QOS, HEARTBEAT_QOS, STATUS_QOS


def parse_goals(text: str) -> list[tuple[float, float]]:
    """``'1,2;3,4'`` -> ``[(1.0, 2.0), (3.0, 4.0)]``; malformed pairs are skipped."""
    goals = []
    for pair in text.split(';'):
        parts = pair.split(',')
        if len(parts) != 2:
            continue
        try:
            goals.append((float(parts[0]), float(parts[1])))
        except ValueError:
            continue
    return goals


class Console(FleetNode):
    """Action client of ``navigate``; watches status, heartbeats and the commanded velocity."""

    def __init__(self) -> None:
        super().__init__('console')
        self.declare_parameter('goals', '2.0,0.0;2.0,2.0;0.0,0.0')
        self._goals = parse_goals(self.get_parameter('goals').value)
        self._client = ActionClient(self, NavigateToPose, NAVIGATE_ACTION)
        self._status_sub = self.create_subscription(String, STATUS_TOPIC, self.on_status,
                                                    STATUS_QOS)
        self._heartbeat_sub = self.create_subscription(Header, HEARTBEAT_TOPIC, self.on_heartbeat,
                                                       HEARTBEAT_QOS)
        self._cmd_sub = self.create_subscription(Twist, CMD_VEL_TOPIC, self.on_cmd, COMMAND_QOS)
        self._alive = {}
        self._busy = False
        self._timer = self.create_timer(0.5, self.next_goal)

    def on_status(self, msg: String) -> None:
        self.get_logger().info(f'mode: {msg.data}')

    def on_heartbeat(self, msg: Header) -> None:
        self._alive[msg.frame_id] = msg.stamp.sec

    def on_cmd(self, msg: Twist) -> None:
        if abs(msg.linear.x) > 1.0:
            self.get_logger().warning(f'fast command: {msg.linear.x:.2f} m/s')

    def next_goal(self) -> None:
        if self._busy or not self._goals or not self._client.server_is_ready():
            return
        x, y = self._goals.pop(0)
        goal = NavigateToPose.Goal()
        goal.pose.pose.position.x = x
        goal.pose.pose.position.y = y
        self._busy = True
        future = self._client.send_goal_async(goal, feedback_callback=self.on_feedback)
        future.add_done_callback(self.on_accepted)

    def on_feedback(self, feedback) -> None:
        self.get_logger().info(f'{feedback.feedback.distance_remaining:.1f} m to go')

    def on_accepted(self, future) -> None:
        handle = future.result()
        if not handle.accepted:
            self._busy = False
            return
        handle.get_result_async().add_done_callback(self.on_result)

    def on_result(self, future) -> None:
        self._busy = False


def main(args=None):
    rclpy.init(args=args)
    node = Console()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')

BRINGUP_PY = string.Template('''\
"""Runs the whole sensor pipeline of the fleet in one process (one executor, many nodes).

Composing the drivers and filters in one process avoids a copy per message on
the robot's small computer; the controller and mission stay separate processes.
"""
import rclpy
from rclpy.executors import MultiThreadedExecutor

$imports


def build_nodes() -> list:
    return [
$constructors
    ]


def main(args=None):
    rclpy.init(args=args)
    executor = MultiThreadedExecutor()
    nodes = build_nodes()
    for node in nodes:
        executor.add_node(node)
    try:
        executor.spin()
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
''')


# -- assembling a fleet -----------------------------------------------------------------------

def _package(out: Path, pkg: str, description: str, depends: list[str],
             modules: dict[str, str], scripts: dict[str, str]) -> None:
    """Write one ament_python package: manifest, setup files, marker and modules."""
    base = out / "src" / pkg
    (base / pkg).mkdir(parents=True, exist_ok=True)
    (base / "resource").mkdir(exist_ok=True)
    (base / "resource" / pkg).write_text("", encoding="utf-8")
    (base / "package.xml").write_text(PACKAGE_XML.substitute(
        pkg=pkg, description=description,
        depends="\n".join(f"  <exec_depend>{d}</exec_depend>" for d in depends)), encoding="utf-8")
    (base / "setup.cfg").write_text(SETUP_CFG.substitute(pkg=pkg), encoding="utf-8")
    (base / "setup.py").write_text(SETUP_PY.substitute(
        pkg=pkg, description=description,
        scripts="\n".join(f"            '{name} = {pkg}.{target}'," for name, target in scripts.items())),
        encoding="utf-8")
    for name, text in {"__init__": "", **modules}.items():
        (base / pkg / f"{name}.py").write_text(text, encoding="utf-8")


def write_fleet(out: Path, number: int) -> None:
    """Write the five packages of fleet ``number`` under ``out/src``."""
    fleet = f"fleet{number:02d}"
    common = f"{fleet}_common"
    channels = fleet_channels()

    def fields(ch: Channel) -> dict[str, object]:
        return {"common": common, "index": ch.index, "name": ch.name, "CONST": ch.const,
                "Kind": ch.name.capitalize()}

    _package(out, common, "Names, QoS presets, the base node and geometry helpers.",
             ["std_msgs"],
             {"names": names_py(fleet, channels), "qos": QOS_PY, "geometry": GEOMETRY_PY,
              "node_base": NODE_BASE_PY.substitute(common=common)}, {})
    drivers = {f"{ch.name}_driver": (RANGE_DRIVER_PY if ch.kind == "range" else IMU_DRIVER_PY)
               .substitute(fields(ch)) for ch in channels}
    _package(out, f"{fleet}_drivers", "Sensor drivers.", [common, "sensor_msgs", "std_srvs"],
             drivers, {name: f"{name}:main" for name in drivers})
    filters = {f"{ch.name}_filter": (RANGE_FILTER_PY if ch.kind == "range" else IMU_FILTER_PY)
               .substitute(fields(ch)) for ch in channels}
    _package(out, f"{fleet}_perception", "Filters for every sensor stream.", [common, "sensor_msgs"],
             filters, {name: f"{name}:main" for name in filters})
    ranges = [ch for ch in channels if ch.kind == "range"]
    imus = [ch for ch in channels if ch.kind == "imu"]
    control = {
        "controller": CONTROLLER_PY.substitute(
            common=common,
            range_imports="\n".join(f"from {common}.names import {ch.const}_FILTERED" for ch in ranges),
            imu_imports="\n".join(f"from {common}.names import {ch.const}_FILTERED" for ch in imus),
            range_topics="\n".join(f"    {ch.const}_FILTERED," for ch in ranges),
            imu_topics="\n".join(f"    {ch.const}_FILTERED," for ch in imus)),
        "mission": MISSION_PY.substitute(common=common),
    }
    _package(out, f"{fleet}_control", "Velocity controller and mission executive.",
             [common, "geometry_msgs", "nav2_msgs", "std_srvs"],
             control, {name: f"{name}:main" for name in control})
    pipeline = [(f"{fleet}_drivers", f"{ch.name}_driver", f"{ch.name.capitalize()}Driver")
                for ch in channels]
    pipeline += [(f"{fleet}_perception", f"{ch.name}_filter", f"{ch.name.capitalize()}Filter")
                 for ch in channels]
    apps = {
        "console": CONSOLE_PY.substitute(common=common),
        "bringup": BRINGUP_PY.substitute(
            imports="\n".join(f"from {pkg}.{mod} import {cls}" for pkg, mod, cls in pipeline),
            constructors="\n".join(f"        {cls}()," for _, _, cls in pipeline)),
    }
    _package(out, f"{fleet}_apps", "Operator console and sensor bring-up.",
             [f"{fleet}_drivers", f"{fleet}_perception", "nav2_msgs"],
             apps, {name: f"{name}:main" for name in apps})


def write_workspace(out: Path, scale: int) -> Path:
    """Write a colcon workspace of ``scale`` fleets to ``out`` (created); returns ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    for number in range(1, scale + 1):
        write_fleet(out, number)
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", type=Path, help="directory to write the workspace to")
    parser.add_argument("--scale", type=int, default=1, help="number of fleets (default 1)")
    args = parser.parse_args(argv)
    write_workspace(args.out, args.scale)
    lines = sum(len(p.read_text(encoding="utf-8").splitlines()) for p in args.out.rglob("*.py"))
    print(f"{args.out}: {args.scale} fleet(s), {lines} lines of Python")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
