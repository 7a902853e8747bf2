"""Engine behaviour: which modules are entry points, budgets, determinism of effects."""
import textwrap

from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.analysis import load_stubs
from flake8_rosgraph.workspace import load_workspace


def run(tmp_path, files, **kw):
    for rel, text in files.items():
        path = tmp_path / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
    library, _ = load_stubs()
    analysis = Analysis(Program(load_workspace(tmp_path).modules), library, **kw)
    analysis.run()
    return analysis


FILES = {
    "pkg/__init__.py": "",
    "pkg/names.py": "TOPIC = 'scan'\n",
    "pkg/node.py": """
        import rclpy
        from sensor_msgs.msg import LaserScan
        from pkg.names import TOPIC
        def main():
            node = rclpy.create_node('n')
            node.create_publisher(LaserScan, TOPIC, 10)
    """,
    "pkg/main.py": "from pkg.node import main\nmain()\n",
    "tools/report.py": "def report(rows):\n    return [r for r in rows]\n",
}


def test_only_modules_reaching_an_active_library_are_entries(tmp_path):
    analysis = run(tmp_path, FILES)
    assert analysis.relevant == {"pkg.node", "pkg.main"}
    analysed = {task[1] for task in analysis.effects if task[0] == "mod"}
    assert "pkg.names" in analysed          # read on demand for TOPIC
    assert "tools.report" not in analysed   # never needed
    [publisher] = [e for e in analysis.all_effects() if e.kind == "publisher"]
    assert publisher.arg("topic").strings() == ["scan"]


def test_budget_exhaustion_is_reported_not_raised(tmp_path):
    analysis = run(tmp_path, FILES, max_task_runs=1)
    assert any("budget" in d.message for d in analysis.diagnostics)


def test_every_object_gets_its_own_constructor_analysis(tmp_path):
    names = [f"n{i}" for i in range(20)]
    analysis = run(tmp_path, {"fleet.py": "import rclpy\nfrom rclpy.node import Node\n"
                              "class Member(Node):\n"
                              "    def __init__(self, name):\n"
                              "        super().__init__(name)\n"
                              + "".join(f"m{i} = Member('{n}')\n" for i, n in enumerate(names))})
    created = sorted(e.arg("name").strings()[0] for e in analysis.all_effects() if e.kind == "node")
    assert created == sorted(names)


def test_a_base_class_helper_keeps_every_nodes_parameters(tmp_path):
    """A fleet of nodes, each declaring its own parameters through one helper of their base
    class: more calls of the helper than the context bound in all, few per node."""
    kinds = [f"sensor{i}" for i in range(12)]
    analysis = run(tmp_path, {
        "fleet/__init__.py": "",
        "fleet/base.py": """
            from rclpy.node import Node
            class FleetNode(Node):
                def __init__(self, name):
                    super().__init__(name)
                def float_parameter(self, name, default):
                    self.declare_parameter(name, default)
                    return self.get_parameter(name).value
        """,
        "fleet/members.py": "import rclpy\nfrom fleet.base import FleetNode\n"
                            "class Member(FleetNode):\n"
                            "    def __init__(self, kind):\n"
                            "        super().__init__(kind)\n"
                            "        self.rate = self.float_parameter(kind + '_rate', 10.0)\n"
                            "        self.gain = self.float_parameter(kind + '_gain', 0.5)\n"
                            + "".join(f"m{i} = Member('{k}')\n" for i, k in enumerate(kinds)),
    })
    declared = sorted(s for e in analysis.all_effects() if e.kind == "parameter"
                      for s in e.arg("name").strings() or [None])
    assert declared == sorted(f"{k}_{p}" for k in kinds for p in ("rate", "gain"))
    assert not any("more than 8 different ways" in d.message for d in analysis.diagnostics)


def test_too_many_contexts_widen_arguments_and_say_so(tmp_path):
    """A helper that creates entities itself keeps 24 contexts, any other function 8."""
    calls = "".join(f"make('t{i}')\nprefix('p{i}')\n" for i in range(30))
    analysis = run(tmp_path, {"m.py": "import rclpy\nnode = rclpy.create_node('n')\n"
                              "def prefix(topic):\n"
                              "    return topic\n"
                              "def make(topic):\n"
                              "    node.create_publisher(int, topic, 10)\n" + calls})
    topics = [e.arg("topic") for e in analysis.all_effects() if e.kind == "publisher"]
    assert any(t.is_top for t in topics)
    messages = [d.message for d in analysis.diagnostics]
    assert any("make is called in more than 24 different ways" in m for m in messages)
    assert any("prefix is called in more than 8 different ways" in m for m in messages)


def test_counters_in_callbacks_are_widened_not_counted_up(tmp_path):
    analysis = run(tmp_path, {"n.py": """
        import rclpy
        from rclpy.node import Node
        class Ticker(Node):
            def __init__(self):
                super().__init__('ticker')
                self.count = 0
                self.create_timer(0.1, self.tick)
            def tick(self):
                self.count += 1
        Ticker()
    """})
    counts = [v for k, v in analysis.heap.items() if k[0] == "a" and k[2] == "count"]
    assert counts and counts[0].is_top
    assert analysis.task_runs < 15  # not one run per value of the counter


def test_the_analysis_leaves_no_garbage_cycle_and_restores_the_collector(tmp_path):
    """The analysis runs with the cyclic collector paused and must be freed by reference
    counting: a cycle through it would keep every heap value, AST and CFG alive until a
    full collection later in flake8's own checks."""
    import gc
    import weakref
    from flake8_rosgraph.analysis import _build_graph, collector_paused

    for rel, text in FILES.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(textwrap.dedent(text))
    created = []
    original = Analysis.__init__

    def remember(self, *args, **kwargs):
        original(self, *args, **kwargs)
        created.append(weakref.ref(self))

    gc.collect()
    Analysis.__init__ = remember
    try:
        with collector_paused():
            assert not gc.isenabled()
            graph = _build_graph(tmp_path, (), (), ())
            assert created and all(ref() is None for ref in created), "an analysis outlived build_graph"
    finally:
        Analysis.__init__ = original
    assert gc.isenabled()
    assert graph.nodes
