"""The rules on the ground-truth graphs of two real repositories (ros2/examples, ros2/demos).

These graphs are what a perfect extractor would produce; the findings below are
every finding the default rules raise on them, each read and judged:
the ROS005 is the demo of incompatible QoS in quality_of_service_demo (a true
positive by construction). The stand-alone nodes' dangling ends (``/estop``,
``/test_cloud``, ``/lifecycle_chatter``, ``/message_lost_chatter``) and the
node names repeated across alternative tutorial files are by design and must
stay quiet (see rules/absence.py and ROS007's docstring for the numbers).
"""
import pytest
from truth_graphs import TRUTH_DIR, load_graph

from flake8_rosgraph.rules import RuleConfig, run_rules

QOS_DEMO = "quality_of_service_demo/rclpy/quality_of_service_demo_py/common_nodes.py"
EXPECTED = {
    "ros2-examples.json": [],
    "ros2-demos.json": [f"ROS005 {QOS_DEMO}:118"],
}


@pytest.mark.parametrize("truth", sorted(EXPECTED))
def test_findings_on_real_repositories(truth):
    path = TRUTH_DIR / truth
    if not path.exists():
        pytest.skip(f"the dev evaluation kit is not next to the repository ({path})")
    findings = run_rules(load_graph(path), RuleConfig())
    assert [f"{f.code} {f.location.short()}" for f in findings] == EXPECTED[truth]
