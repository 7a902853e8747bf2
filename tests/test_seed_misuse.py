"""scripts/seed_misuse.py on a hand-written workspace: a battery monitor and its docking client.
Every misuse bug it seeds (a synchronous call in a callback, a misspelt parameter read, a
callback taking an argument rclpy never passes, rclpy.init() after the node, a misspelt or
int-valued message field) is reported by the tool at the edited line, and its neutral edit (an
optional ``event=None`` on a timer callback) changes nothing."""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

SCRIPT = Path(__file__).resolve().parents[1] / "scripts" / "seed_misuse.py"
TOOL = Path(sys.executable).parent / "flake8-rosgraph"

MONITOR = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import BatteryState
    from std_msgs.msg import Float32
    from std_srvs.srv import Trigger


    class BatteryMonitor(Node):
        '''Publishes the charge, asks the dock to charge when it is low.'''

        def __init__(self):
            super().__init__('battery_monitor')
            self.declare_parameter('low_charge', 0.2)
            self.declare_parameter('period', 1.0)
            self.low = self.get_parameter('low_charge').value
            self.charge_pub = self.create_publisher(Float32, 'charge', 10)
            self.dock = self.create_client(Trigger, 'dock')
            self.create_subscription(BatteryState, 'battery_state', self.on_battery, 10)
            self.create_service(Trigger, 'report', self.on_report)
            self.create_timer(self.get_parameter('period').value, self.on_tick)
            self.charge = 1.0

        def on_battery(self, state):
            self.charge = state.percentage
            if self.charge < self.low:
                self.dock.call_async(Trigger.Request())

        def on_tick(self):
            reading = Float32()
            reading.data = 1.0
            self.charge_pub.publish(reading)

        def on_report(self, request, response):
            response.success = self.charge > self.low
            return response


    def main():
        rclpy.init()
        node = BatteryMonitor()
        rclpy.spin(node)
"""


@pytest.fixture(scope="module")
def script():
    spec = importlib.util.spec_from_file_location("seed_misuse", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return module


@pytest.mark.skipif(not TOOL.exists(), reason=f"flake8-rosgraph is not installed beside {sys.executable}")
def test_every_seeded_misuse_bug_is_reported_and_the_neutral_edit_is_quiet(script, tmp_path: Path) -> None:
    corpus = tmp_path / "corpus"
    write(corpus / "power", package("power", "'monitor = power.monitor:main'", {"monitor": MONITOR}))
    monitor = corpus / "power/power/power/monitor.py"
    before = monitor.read_bytes()
    mutants = script.make(corpus, tmp_path / "mutants.jsonl", cap=5, seed=1)
    assert sorted(m.kind for m in mutants) == [
        "cb_arity", "cb_arity", "cb_arity", "field_int", "field_typo", "init_order",
        "neg_cb_default", "param_typo", "sync_call"]
    results = script.run(corpus, mutants, tmp_path / "results.jsonl", str(TOOL))
    missed = [(r["kind"], r["line"], r["new"]) for r in results if r["expect"] and not r["detected"]]
    assert missed == []
    assert [r["new"] for r in results if not r["expect"]] == [[]]
    assert monitor.read_bytes() == before  # every edit undone
