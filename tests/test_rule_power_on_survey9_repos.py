"""Findings and misses of the rules on a ninth round of public repositories (a grasping GUI,
a debugging course's relay system, rover stacks), each fixed by a general mechanism: a
realistic multi-file workspace holding the pattern, and its near-identical twin, one of which
must be reported and the other stay quiet."""
from __future__ import annotations

from pathlib import Path

from test_precision_on_survey6_repos import ament_python, sites
from test_recall_mechanisms import findings
from test_workspace_discovery import write

# -- a node class keeping its own `namespace` attribute ---------------------------------------------
GRASP_SERVER = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class GraspServer(Node):
        def __init__(self):
            super().__init__('visual_grasp')
            self.create_service(Trigger, '/visual_grasp/set_target', self.on_target)
            self.create_service(Trigger, '/visual_grasp/calibrate', self.on_target)

        def on_target(self, request, response):
            response.success = True
            return response


    def main():
        rclpy.init()
        rclpy.spin(GraspServer())
"""

GRASP_GUI = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class CalibrationClient:
        \"\"\"Calls the grasp server's calibration service under the prefix it is given.\"\"\"

        def __init__(self, node: Node, prefix: str) -> None:
            root = '/' + prefix.strip('/')
            self._client = node.create_client(Trigger, root + '/calibrate')


    class GraspGui(Node):
        def __init__(self):
            super().__init__('visual_grasp_gui')
            self.namespace = {namespace}
            self.node_name = 'grasp_panel'
            self._create_clients()

        def _create_clients(self):
            root = self.namespace.rstrip('/')
            self.set_target = self.create_client(Trigger, root + '/set_target')
            self.calibration = CalibrationClient(self, root)


    def main():
        rclpy.init()
        rclpy.spin(GraspGui())
"""


def grasp_workspace(root: Path, namespace: str) -> Path:
    return write(root, {
        **ament_python("grasp_server", "'server = grasp_server.server:main'"),
        "grasp_server/grasp_server/server.py": GRASP_SERVER,
        **ament_python("grasp_gui", "'gui = grasp_gui.gui:main'"),
        "grasp_gui/grasp_gui/gui.py": GRASP_GUI.format(namespace=namespace),
    })


def test_a_node_class_attribute_called_namespace_is_the_class_own(tmp_path: Path) -> None:
    """Project_LINK's grasp GUI stores ``self.namespace = '/visual_grasp'`` on its Node subclass
    and builds its clients from it in a helper method. rclpy keeps the node's namespace in rcl
    (``get_namespace()``), not in an attribute, so the class's own value is the only one:
    no '//calibrate' (a false ROS006) and no '/set_target' beside '/visual_grasp/set_target'."""
    root = grasp_workspace(tmp_path, "'/visual_grasp'")
    assert findings(root, ["ROS006", "ROS008"]) == []


def test_a_misspelt_namespace_attribute_is_reported(tmp_path: Path) -> None:
    root = grasp_workspace(tmp_path, "'/visual_grap'")
    reported = findings(root, ["ROS006", "ROS008"])
    assert sites(reported) == [("ROS008", "grasp_gui/grasp_gui/gui.py", 11),
                               ("ROS008", "grasp_gui/grasp_gui/gui.py", 23)]
