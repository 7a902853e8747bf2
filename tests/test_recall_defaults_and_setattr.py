"""Extraction mechanisms found on a seventh round of real repositories outside every test set:
a value chosen by a command-line option's default (``None if args.trace is None else
args.trace.resolve()``) is itself only a default, so a later ``if`` on it explores both
ways. Each on a realistic multi-file workspace, with a twin where following the code must
not invent an entity."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

TOPICS = ("publishers", "subscriptions")


# -- a choice made by an option's default is only a default -----------------------------------
SIMULATION = """
    import rclpy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from rclpy.node import Node

    from sim_runner.trace import OdomTrace


    def run(world, trace_path=None):
        rclpy.init(args=[])
        node = Node('sim_bridge')
        node.create_subscription(Odometry, '/odom', print, 10)
        if trace_path is not None:
            trace = OdomTrace(trace_path)
            node.create_publisher(Twist, '/cmd_vel', 1)
            node.create_subscription(Odometry, '/odom/ground_truth', trace.record, 10)
        rclpy.spin(node)
"""
TRACE = """
    class OdomTrace:
        '''Writes every odometry message to a file, for the offline phase check.'''

        def __init__(self, path):
            self.path = path

        def record(self, msg):
            with open(self.path, 'a') as out:
                out.write(f'{msg.header.stamp.sec}\\n')
"""
MAIN = """
    import argparse
    from pathlib import Path

    from sim_runner.simulation import run


    def _parser():
        parser = argparse.ArgumentParser(description='Run the simulation bridge')
        parser.add_argument('--world', default='warehouse')
        parser.add_argument('--odom-trace', type=Path, default=None)
        return parser


    def main(argv=None):
        args = _parser().parse_args(argv)
        run(args.world, {trace})
        return 0
"""


def _simulation(tmp_path: Path, trace: str) -> Path:
    return write(tmp_path, package("sim_runner", "'sim = sim_runner.main:main'", {
        "simulation": SIMULATION, "trace": TRACE, "main": MAIN.replace("{trace}", trace)}))


def test_an_option_default_chosen_by_a_conditional_decides_no_later_branch(tmp_path: Path) -> None:
    """``None if args.odom_trace is None else …`` is None only by default: ``--odom-trace``
    given, ``run`` takes the traced branch, so its publisher and subscription are in the
    graph (Isaac Sim navigation bridge: nine sites reported never reached)."""
    root = _simulation(tmp_path, "None if args.odom_trace is None else args.odom_trace.expanduser()")
    assert entities(root, TOPICS) == {"/sim_bridge": [
        ("publishers", "/cmd_vel"), ("subscriptions", "/odom"),
        ("subscriptions", "/odom/ground_truth")]}


def test_an_attribute_of_an_option_default_of_none_is_the_given_value(tmp_path: Path) -> None:
    """``args.odom_trace.expanduser()`` fails on the default ``None`` but not on a path given
    on the command line: the call goes on, with a value the analysis does not know."""
    root = _simulation(tmp_path, "args.odom_trace.expanduser()")
    assert entities(root, TOPICS)["/sim_bridge"] == [
        ("publishers", "/cmd_vel"), ("subscriptions", "/odom"),
        ("subscriptions", "/odom/ground_truth")]


def test_a_conditional_on_a_plain_none_still_decides_the_branch(tmp_path: Path) -> None:
    """The twin: a local that is ``None`` in every run (no option can change it) still rules
    the traced branch out; no publisher is invented and the line is explained."""
    files = package("sim_runner", "'sim = sim_runner.main:main'", {
        "simulation": SIMULATION, "trace": TRACE,
        "main": MAIN.replace("{trace}", "None if trace is None else trace.expanduser()").replace(
            "args = _parser().parse_args(argv)", "args = _parser().parse_args(argv)\n        trace = None")})
    root = write(tmp_path, files)
    assert entities(root, TOPICS) == {"/sim_bridge": [("subscriptions", "/odom")]}
    assert reasons(root)[("sim_runner/sim_runner/simulation.py", 15)][0] == "missing"
