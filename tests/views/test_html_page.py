"""The interactive graph page in a real headless browser: drawn, searchable, filterable, explained on click.

Each page is the one ``flake8-rosgraph graph --format html`` writes for a
workspace: the shipped example, and a generated 150-node workspace
(:mod:`fleet`) for readability and speed at scale.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from .browser import console_errors, open_page
from .fleet import NODES_PER_PACKAGE, PACKAGES, write_fleet

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"


def save_screenshot(driver, tmp_path: Path, name: str) -> None:
    """Save a screenshot beside the test's files, and into ``$ROSGRAPH_SCREENSHOTS`` when set (README image)."""
    driver.save_screenshot(str(tmp_path / name))
    if os.environ.get("ROSGRAPH_SCREENSHOTS"):
        shutil.copy(tmp_path / name, Path(os.environ["ROSGRAPH_SCREENSHOTS"]) / name)


def graph_cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", *args],
                          capture_output=True, text=True, timeout=300, check=True)


def page_of(workspace: Path, out: Path, *extra: str) -> tuple[Path, dict]:
    """Write the page of ``workspace`` and return it with the graph JSON of the same workspace."""
    page = out / "graph.html"
    graph_cli(str(workspace), "--format", "html", "-o", str(page), *extra)
    graph = json.loads(graph_cli(str(workspace), "--format", "json").stdout)
    return page, graph


def visible(driver, selector: str) -> int:
    return driver.execute_script(f"return document.querySelectorAll({selector!r} + ':not(.hidden)').length")


def texts(driver, selector: str) -> list[str]:
    return driver.execute_script(
        f"return Array.from(document.querySelectorAll({selector!r})).map(e => e.textContent)")


def choose(driver, select_id: str, value: str) -> None:
    driver.execute_script(
        "const s = document.getElementById(arguments[0]); s.value = arguments[1];"
        "s.dispatchEvent(new Event('change'));", select_id, value)


def search(driver, text: str) -> None:
    box = driver.find_element("id", "search")
    box.clear()
    box.send_keys(text)


@pytest.fixture(scope="module")
def fleet(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("fleet")
    assert write_fleet(root) == len(PACKAGES) * NODES_PER_PACKAGE
    return root


def test_example_page_draws_every_node_and_explains_a_click(browser, tmp_path):
    page, graph = page_of(EXAMPLES, tmp_path)
    started = time.perf_counter()
    open_page(browser, page)
    assert browser.execute_script("return document.body.getAttribute('data-ready')") == "1"
    assert time.perf_counter() - started < 1.0, "the example's page must open in under a second"
    assert page.stat().st_size < 1_000_000
    fqns = sorted(n["fqn"] for n in graph["nodes"])
    drawn = sorted(t.split("\n")[0] for t in texts(browser, "g.vertex.kind-node text:first-of-type"))
    assert drawn == fqns
    # the thesis node with a self-loop carries its finding, drawn and listed
    assert "ROS002" in " ".join(texts(browser, "#panel .finding"))
    node = browser.find_element("css selector", "g.vertex.kind-node[data-id^='node:/node_2@']")
    node.click()
    assert browser.find_element("id", "panel-title").text == "/node_2"
    rows = texts(browser, "#entities tr")
    assert any("/topic5" in row and "producers.py:" in row for row in rows), rows
    assert any("ROS001" in t for t in texts(browser, "#panel .finding"))
    save_screenshot(browser, tmp_path, "example.png")
    assert console_errors(browser) == []


def test_example_page_filters_by_package_and_finding(browser, tmp_path):
    page, graph = page_of(EXAMPLES, tmp_path)
    open_page(browser, page)
    thesis_nodes = [n for n in graph["nodes"] if n["path"].startswith("src/thesis_graph/")]
    choose(browser, "filter-package", "thesis_graph")
    assert visible(browser, "g.vertex.kind-node") == len(thesis_nodes) == 4
    choose(browser, "filter-package", "")
    choose(browser, "filter-finding", "ROS003")
    shown = texts(browser, "g.vertex.kind-node:not(.hidden) text:first-of-type")
    assert shown == ["/node_3"]
    assert "/topic8" in texts(browser, "g.vertex.kind-topic:not(.hidden) text")
    assert console_errors(browser) == []


def write_package(root: Path, name: str, module: str, source: str) -> None:
    pkg = root / "src" / name
    (pkg / name).mkdir(parents=True)
    (pkg / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    (pkg / name / "__init__.py").write_text("")
    (pkg / name / f"{module}.py").write_text(source)


BROADCASTER = """\
import rclpy
from rclpy.node import Node
from rcl_interfaces.srv import GetParameters
from std_msgs.msg import String
from tf2_msgs.msg import TFMessage


class Odometry(Node):
    def __init__(self):
        super().__init__('odometry')
        self.tf_pub = self.create_publisher(TFMessage, '/tf', 10)
        self.odom_pub = self.create_publisher(String, 'odom_text', 10)
        self.params = self.create_client(GetParameters, '/controller/get_parameters')


class Logger(Node):
    def __init__(self):
        super().__init__('logger')
        self.create_subscription(String, 'odom_text', self.on_odom, 10)

    def on_odom(self, msg):
        self.get_logger().info(msg.data)
"""


def test_infrastructure_is_hidden_until_asked_for(browser, tmp_path):
    write_package(tmp_path, "odometry", "nodes", BROADCASTER)
    page, _ = page_of(tmp_path, tmp_path)
    open_page(browser, page)
    exempt = texts(browser, "g.vertex.exempt text")
    assert sorted(exempt) == ["/controller/get_parameters", "/tf"]
    assert visible(browser, "g.vertex.exempt") == 0
    assert visible(browser, "path.edge.exempt") == 0
    assert texts(browser, "g.vertex.kind-topic:not(.hidden) text") == ["/odom_text"]
    browser.find_element("id", "show-infra").click()
    assert visible(browser, "g.vertex.exempt") == 2
    assert console_errors(browser) == []


def test_fleet_page_at_150_nodes(browser, fleet, tmp_path):
    page, graph = page_of(fleet, tmp_path)
    open_page(browser, page)
    assert len(graph["nodes"]) == 150
    assert visible(browser, "g.vertex.kind-node") == 150
    # search highlights without hiding: every stage of one branch of the planning pipeline
    search(browser, "/planning/s2_")
    assert browser.execute_script("return document.querySelectorAll('g.vertex.match').length") == 3 + 3 + 3
    search(browser, "")
    choose(browser, "filter-package", "planning")
    assert visible(browser, "g.vertex.kind-node") == NODES_PER_PACKAGE
    # a launch view shows what that launch file starts, in its namespace
    views = texts(browser, "#view option")
    launch_view = next(i for i, title in enumerate(views) if title.endswith("planning.launch.py"))
    choose(browser, "view", str(launch_view))
    drawn = texts(browser, "g.vertex.kind-node text:first-of-type")
    assert drawn and all(t.startswith("/planning_ns/") for t in drawn)
    # layout: no two vertices of the code-level view overlap
    choose(browser, "view", "0")
    overlaps = browser.execute_script("""
        const boxes = Array.from(document.querySelectorAll('g.vertex')).map(g => g.getBBox());
        let n = 0;
        for (let i = 0; i < boxes.length; i++) for (let j = i + 1; j < boxes.length; j++) {
          const a = boxes[i], b = boxes[j];
          if (a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height) n++;
        }
        return n;""")
    assert overlaps == 0
    save_screenshot(browser, tmp_path, "fleet.png")
    assert console_errors(browser) == []


def test_page_is_self_contained(tmp_path):
    page, _ = page_of(EXAMPLES, tmp_path)
    text = page.read_text(encoding="utf-8")
    assert "http://" not in text.replace("http://www.w3.org/2000/svg", "")
    assert "https://" not in text and "<script src" not in text and "<link" not in text
    assert "default-src 'none'" in text  # nothing may be fetched at view time


def test_names_cannot_break_out_of_the_page(tmp_path):
    write_package(tmp_path, "evil", "node",
        "import rclpy\nfrom rclpy.node import Node\nfrom std_msgs.msg import String\n\n\n"
        "class Evil(Node):\n    def __init__(self):\n        super().__init__('evil')\n"
        "        self.create_publisher(String, '</script><script>alert(1)</script>', 10)\n")
    page, _ = page_of(tmp_path, tmp_path)
    text = page.read_text(encoding="utf-8")
    assert text.count("</script>") == 2  # the data block and the page's own script, nothing injected


def test_same_workspace_same_page(tmp_path):
    first, _ = page_of(EXAMPLES, tmp_path)
    again = tmp_path / "again.html"
    graph_cli(str(EXAMPLES), "--format", "html", "-o", str(again))
    assert first.read_bytes() == again.read_bytes()
