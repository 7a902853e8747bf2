"""The fixture system in all three formats: instantiated nodes, includes, remaps, parameters, findings."""
from __future__ import annotations

import json

import pytest

from flake8_rosgraph.launch.api import (apply, graph_to_json_obj, judged_graph, system_for_file,
                                    system_to_json)
from flake8_rosgraph.rules import run_rules
from flake8_rosgraph.rules.base import RuleConfig
from flake8_rosgraph.rules.topics import EndpointIndex

FORMATS = ("py", "xml", "yaml")
BRINGUP = "src/demo_bringup/launch/"


def instances(system):
    """(fqn, package/executable, sorted entity names, settings) per instantiated node."""
    return sorted(
        (i.node.fqn, f"{i.launched.package}/{i.launched.executable}",
         tuple(sorted((e.kind, e.name) for e in i.node.entities)),
         tuple(sorted((name, origin) for name, _, _, origin in i.settings)))
        for i in system.instances)


EXPECTED_SYSTEM = [
    ("/default_ns/talker", "demo_py/talker", (("parameters", "rate"), ("publishers", "/default_ns/chatter")), ()),
]


@pytest.mark.parametrize("ext", FORMATS)
def test_sub_launch_alone_uses_the_argument_default(ws, ext):
    assert instances(ws.system(f"sub.launch.{ext}")) == EXPECTED_SYSTEM


@pytest.mark.parametrize("ext", FORMATS)
def test_system_is_instantiated_per_rcl(ws, ext):
    system = ws.system(f"system.launch.{ext}")
    assert instances(system) == [
        ("/plain/listener", "demo_py/listener", (("subscriptions", "/plain/heard"),), ()),
        # the include passes ns:=r2 over the sub-launch's default
        ("/r1/listener", "demo_py/listener", (("subscriptions", "/r1/chatter"),), ()),
        # launch name overrides the code's 'talker'; pushed namespace from the 'robot' argument
        ("/r1/speaker", "demo_py/talker", (("parameters", "rate"), ("publishers", "/r1/chatter")),
         (("rate", "inline"), ("rate", "shared file"), ("rte", "shared file"))),
        ("/r2/talker", "demo_py/talker", (("parameters", "rate"), ("publishers", "/r2/chatter")), ()),
    ]
    assert system.files == [BRINGUP + f"system.launch.{ext}", BRINGUP + f"sub.launch.{ext}"]
    assert system.arguments == {"robot": "r1", "with_relay": "true"}
    assert system.problems == []
    statuses = sorted((n.package, n.executable, n.target.status, n.conditional) for n in system.nodes)
    assert statuses == [
        ("demo_cpp", "relay", "no-python", True),
        ("demo_py", "listener", "found", False), ("demo_py", "listener", "found", False),
        ("demo_py", "talker", "found", False), ("demo_py", "talker", "found", False),
        ("demo_py", "talkr", "missing-executable", False),
    ]


def test_three_formats_agree(ws):
    def shape(system):
        return [{k: v for k, v in n.items() if k not in ("file", "line", "column", "remappings", "parameters")}
                | {"remappings": [(r["from"], r["to"]) for r in n["remappings"]],
                   "parameters": [(p["name"], p["value"]) for p in n["parameters"]]}
                for n in system_to_json(system)["nodes"]]
    py, xml, yaml = (shape(ws.system(f"system.launch.{ext}")) for ext in FORMATS)
    assert py == xml == yaml


def test_remap_that_fixes_a_connection(ws):
    judged = judged_graph(ws.graph, ws.systems)
    index = EndpointIndex.build(judged)
    subscription = next(ep for ep in index.endpoints("subscriptions") if ep.entity.name == "/r1/chatter")
    # one /r1/speaker per format: each system file starts it
    assert {peer.node.fqn for peer in index.peers(subscription)} == {"/r1/speaker"}


def test_unresolvable_parts_are_reported_not_guessed(ws):
    # Not named like a launch file, so only read when asked for (``graph --launch FILE``).
    assert not any(s.launch_file.endswith("partial.xml") for s in ws.systems)
    system = system_for_file(ws.root, ws.graph, ws.python.launches, ws.python.targets, ws.root / "src/demo_bringup/extra/partial.xml")
    assert [(d.line, d.message) for d in system.problems] == [
        (2, "include not resolved: package 'nav2_bringup' is not in the workspace"),
        (4, "<executable> is not followed: nodes it starts are not in the system"),
    ]
    node, = system.nodes
    assert node.namespace is None
    assert node.unresolved == ["namespace: launch argument 'robot_ns' has no default"]
    instance, = system.instances
    assert (instance.node.name, instance.node.namespace, instance.node.entities[1].name) == \
        ("talker", None, None)
    assert not system.complete


def test_findings_of_the_workspace(ws):
    judged = judged_graph(ws.graph, ws.systems)
    found = [(f.code, f.location.short(), f.message) for f in run_rules(judged, RuleConfig())]
    per_format = []
    for ext, (remap, hear, talkr, relay) in {"py": (17, 23, 25, 26), "xml": (6, 16, 18, 19),
                                             "yaml": (12, 34, 36, 39)}.items():
        launch = BRINGUP + f"system.launch.{ext}"
        per_format += [
            ("ROS202", f"{launch}:{remap}",
             "remap 'unused_topic' -> 'other' matches no name used by any of the 2 nodes it applies to"),
            ("ROS202", f"{launch}:{hear}",
             "remap 'hear' -> 'chatter' matches no name node '/plain/listener' uses (it uses /plain/heard); did you mean '/plain/heard'?"),
            ("ROS201", f"{launch}:{talkr}", "package 'demo_py' has no executable 'talkr'; did you mean 'talker'?"),
            ("ROS203", f"{launch}:{relay}",
             "rcl rejects node name 'relay-1': contains '-' (only alphanumerics and '_' are allowed)"),
        ]
    assert sorted(found) == sorted(per_format + [
        ("ROS204", "src/demo_bringup/config/talker.yaml:4",
         "parameter 'rte' is set for node '/r1/speaker', which never declares it; did you mean 'rate'?"),
        # broken.launch.xml remaps the talker away from the monitor it feeds in the code: both
        # ends of that system dangle, however well the other launch files wire the talker
        ("ROS003", "src/demo_py/demo_py/monitor.py:9",
         "topic '/chatter' has no publisher; did you mean '/chattr' (published at src/demo_py/demo_py/talker.py:10)?"),
        ("ROS001", "src/demo_py/demo_py/talker.py:10",
         "topic '/chattr' has no subscriber; did you mean '/chatter' (subscribed at src/demo_py/demo_py/monitor.py:9)?"),
    ])


def test_code_graph_alone_has_no_launch_findings(ws):
    assert run_rules(ws.graph, RuleConfig()) == []


def test_apply_gives_launch_info_and_is_deterministic(ws):
    system = ws.system("system.launch.xml")
    first = json.dumps(graph_to_json_obj(apply(ws.graph, system)), sort_keys=False)
    again = json.dumps(graph_to_json_obj(apply(ws.graph, ws.system("system.launch.xml"))), sort_keys=False)
    assert first == again
    nodes = {n["fqn"]: n for n in json.loads(first)["nodes"]}
    assert nodes["/r1/speaker"]["launch"] == {
        "file": BRINGUP + "system.launch.xml", "line": 7, "executable": "talker", "package": "demo_py"}
    assert nodes["/r2/talker"]["launch"]["file"] == BRINGUP + "sub.launch.xml"
    # not started by this system: judged as written
    assert "launch" not in nodes["/monitor"]
    # the C++ node has no code to analyse: a node without entities, at the launch file
    relay = [n for n in json.loads(first)["nodes"] if (n.get("launch") or {}).get("executable") == "relay"]
    assert [(r["name"], r["path"], r["publishers"]) for r in relay] == [("relay-1", BRINGUP + "system.launch.xml", [])]
