"""Reports battery health through diagnostic_updater."""
import diagnostic_updater
import rclpy
from diagnostic_msgs.msg import DiagnosticStatus
from rclpy.node import Node
from std_msgs.msg import Bool


class VoltageTask(diagnostic_updater.DiagnosticTask):
    def __init__(self, node):
        super().__init__('voltage')
        self.node = node

    def run(self, stat):
        self.node.alarm_pub = self.node.create_publisher(Bool, 'battery_alarm', 1)
        stat.summary(DiagnosticStatus.OK, 'ok')
        return stat


class BatteryMonitor(Node):
    def __init__(self):
        super().__init__('battery_monitor')
        self.updater = diagnostic_updater.Updater(self, period=2.0)
        self.updater.setHardwareID('bms')
        self.updater.add('temperature', self.check_temperature)
        self.updater.add(VoltageTask(self))

    def check_temperature(self, stat):
        self.temp_pub = self.create_publisher(Bool, 'overheated', 1)
        return stat


def main():
    rclpy.init()
    rclpy.spin(BatteryMonitor())
