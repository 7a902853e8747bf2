"""A class's own name as a value: ``__class__`` (the class whose body defines the method),
``type(self)`` and ``self.__class__`` (the object's class), and their ``__name__``,
``__qualname__``, ``__module__`` — node names written from them (ros/diagnostics'
``NTPMonitor``: ``super().__init__(__class__.__name__)``)."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph

from test_workspace_discovery import PACKAGE_XML, write

MONITORS = {
    "host_monitors/package.xml": PACKAGE_XML.format(name="host_monitors", build="ament_python"),
    "host_monitors/setup.py": """
        from setuptools import setup
        setup(name='host_monitors', packages=['host_monitors'],
              entry_points={'console_scripts': ['monitors = host_monitors.run:main']})
    """,
    "host_monitors/host_monitors/__init__.py": "",
    "host_monitors/host_monitors/base.py": """
        from diagnostic_msgs.msg import DiagnosticArray
        from rclpy.node import Node


        class Monitor(Node):
            '''Each monitor is a node named after its class, reporting under the base's name.'''

            def __init__(self):
                super().__init__(type(self).__name__.lower())
                self.pub = self.create_publisher(
                    DiagnosticArray, __class__.__name__.lower() + '/' + self.__class__.__name__, 10)
    """,
    "host_monitors/host_monitors/monitors.py": """
        from .base import Monitor


        class CpuMonitor(Monitor):
            pass


        class NtpMonitor(Monitor):
            pass
    """,
    "host_monitors/host_monitors/run.py": """
        import rclpy
        from rclpy.executors import MultiThreadedExecutor

        from .monitors import CpuMonitor, NtpMonitor


        def main():
            rclpy.init()
            executor = MultiThreadedExecutor()
            for node in (CpuMonitor(), NtpMonitor()):
                executor.add_node(node)
            executor.spin()
    """,
}


def test_class_names_name_the_nodes(tmp_path: Path) -> None:
    """``type(self)`` is the object's class, ``__class__`` the class that defines the method:
    each monitor is named after its own class, its topic after the base's and its own."""
    root = write(tmp_path, MONITORS)
    assert {node.fqn: sorted(e.name for e in node.entities if e.kind == "publishers")
            for node in build_graph(root).nodes} == {
        "/cpumonitor": ["/monitor/CpuMonitor"],
        "/ntpmonitor": ["/monitor/NtpMonitor"],
    }
