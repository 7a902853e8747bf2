"""Library models (``stubs/*.toml``, schema in ``docs/stubs.md``).

Three promises are checked here:

* every shipped model loads with zero errors and means what it says: effect kinds and
  arguments the graph builder reads, references to parameters the signature has, bases
  and ``via`` classes that exist;
* a broken stub file never raises: each broken entry becomes one message naming the file
  and the key, and the rest of the file still loads;
* on small workspaces written for these tests (``tests/stubs_fixtures/<case>/``), the models
  yield the entities the real libraries create — names, types, QoS, ``via`` — and a user's
  own stub file models a wrapper library the analyser cannot see.
"""
from __future__ import annotations

import string
from functools import lru_cache
from pathlib import Path
from typing import Iterator

import pytest

from flake8_rosgraph.absint.library import FunctionModel, LibraryModel, Ref, load_library
from flake8_rosgraph.analysis import build_graph, builtin_stub_texts
from flake8_rosgraph.graph.builder import ENTITY_KINDS
from flake8_rosgraph.graph.json_out import to_json
from flake8_rosgraph.graph.model import RosGraph

FIXTURES = Path(__file__).parent / "stubs_fixtures"
SHIPPED = builtin_stub_texts()
SHIPPED_NAMES = [name for name, _ in SHIPPED]

#: The arguments the graph builder reads, per effect kind (docs/stubs.md, "Effects").
EFFECT_ARGS: dict[str, frozenset[str]] = {
    "node": frozenset({"target", "name", "namespace", "allow_undeclared", "auto_declare",
                        "cli_args", "context", "use_global_arguments"}),
    "publisher": frozenset({"node", "topic", "type", "qos", "qos_for_depth", "via"}),
    "subscription": frozenset({"node", "topic", "type", "qos", "qos_for_depth", "callback", "via",
                               "when_true", "in_parameters"}),
    "service": frozenset({"node", "name", "type", "callback", "via"}),
    "client": frozenset({"node", "name", "type", "via", "object", "group"}),
    "action_server": frozenset({"node", "name", "type", "callback", "via"}),
    "action_client": frozenset({"node", "name", "type", "via", "object", "group"}),
    "timer": frozenset({"node", "period", "callback", "object"}),
    "parameter": frozenset({"node", "name", "default"}),
    "parameters": frozenset({"node", "namespace", "parameters"}),
    "parameter_use": frozenset({"node", "name", "names", "parameters", "how"}),
    "publish": frozenset({"publisher", "msg", "type"}),
    # read by the misuse facts (flake8_rosgraph.graph.facts) for ROS101-ROS106
    "callback": frozenset({"function", "role", "passes", "annotated", "returns", "node", "group",
                          "executor", "entity", "future"}),
    "future": frozenset({"future", "entity"}),
    "spin": frozenset({"node", "executor"}),
    "executor_node": frozenset({"executor", "node"}),
    "waits_for": frozenset({"entity"}),
    "rate": frozenset({"node", "frequency", "object"}),
    "context_init": frozenset({"context", "args"}),
    "context_shutdown": frozenset({"context"}),
    "node_destroy": frozenset({"node"}),
    "timer_stop": frozenset({"timer"}),
    # launch files: read back by flake8_rosgraph.launch, not by the graph builder
    "launch_node": frozenset({"package", "executable"}),
    "launch_description": frozenset({"description"}),
}
#: Arguments without which an effect of that kind cannot become an entity.
EFFECT_REQUIRED: dict[str, frozenset[str]] = {
    # (a node whose name the library makes at run time, like rqt's pid-suffixed one, has none)
    "node": frozenset({"target"}),
    **{kind: frozenset({"node", name_arg, "type"}) for kind, (_, name_arg) in ENTITY_KINDS.items()},
    "timer": frozenset({"node", "period"}),
    "parameter": frozenset({"node", "name"}),
    "parameters": frozenset({"node", "namespace", "parameters"}),
    "parameter_use": frozenset({"node"}),
    "callback": frozenset({"function", "role", "passes"}),
    "publish": frozenset({"publisher", "msg"}),
    "future": frozenset({"future", "entity"}),
    "spin": frozenset(),
    "executor_node": frozenset({"executor", "node"}),
    "waits_for": frozenset({"entity"}),
    "rate": frozenset({"node", "frequency"}),
    "context_init": frozenset(),
    "context_shutdown": frozenset(),
    "node_destroy": frozenset({"node"}),
    "timer_stop": frozenset({"timer"}),
    "launch_node": frozenset(),
    "launch_description": frozenset(),
}

#: rmw_qos_profile_default without its depth: what rclpy makes of a plain depth.
DEPTH_PROFILE = {"history": "keep_last", "reliability": "reliable", "durability": "volatile",
                 "liveliness": "system_default", "deadline": 0, "lifespan": 0,
                 "liveliness_lease_duration": 0}


# =========================================================================================
# shipped models
# =========================================================================================
def _models(library: LibraryModel) -> Iterator[FunctionModel]:
    yield from library.functions.values()
    for cls in library.classes.values():
        yield from cls.methods.values()


def _template_params(template: str) -> set[str]:
    return {field.partition("|")[0] for _, field, _, _ in string.Formatter().parse(template)
            if field}


def _ref_problems(ref: Ref, params: set[str], where: str, allow_return: bool) -> list[str]:
    names = params | ({"@return"} if allow_return else set())
    if ref.input is not None:
        on, key = ref.input
        missing = sorted((_template_params(key) | {on}) - names)
        return [f"{where}.input: no parameter {p!r}" for p in missing] + _ref_problems(
            Ref(ref.how, ref.data, ref.on), params, where, allow_return)
    if ref.how == "arg" and ref.data not in names:
        return [f"{where}: no parameter {ref.data!r}"]
    if ref.how in ("format", "constant", "object"):
        template = ref.data[0] if ref.how == "object" else ref.data
        return [f"{where}: no parameter {p!r}" for p in sorted(_template_params(template) - params)]
    if ref.how == "load":
        missing = sorted((_template_params(ref.data) | {ref.on}) - names)
        return [f"{where}: no parameter {p!r}" for p in missing]
    return []


def _model_problems(model: FunctionModel) -> list[str]:
    """Everything in one function model that the loader accepts but that cannot work."""
    params = {p.name for p in model.signature.params}
    where = model.qualname
    problems: list[str] = []
    for i, effect in enumerate(model.effects):
        at = f"{where}.effects[{i}]"
        args = {name for name, _ in effect.args}
        if effect.kind not in EFFECT_ARGS:
            problems.append(f"{at}: unknown kind {effect.kind!r}")
            continue
        problems += [f"{at}: {effect.kind} takes no {a!r}"
                     for a in sorted(args - EFFECT_ARGS[effect.kind])]
        problems += [f"{at}: {effect.kind} needs {a!r}"
                     for a in sorted(EFFECT_REQUIRED[effect.kind] - args)]
        for name, ref in effect.args:
            problems += _ref_problems(ref, params, f"{at}.{name}", allow_return=True)
    for i, store in enumerate(model.stores):
        at = f"{where}.stores[{i}]"
        # A store made per entry of ``each`` also names the entry's ``@key`` and ``@value``.
        entry = params | {"@key", "@value"} if store.each is not None else params
        if store.each is not None:
            problems += _ref_problems(Ref("arg", store.each), params, f"{at}.each", allow_return=False)
        problems += _ref_problems(Ref("arg", store.on), params, f"{at}.on", allow_return=True)
        problems += _ref_problems(Ref("format", store.key), entry, f"{at}.key", allow_return=False)
        problems += _ref_problems(store.value, entry, f"{at}.value", allow_return=True)
    if model.returns.how == "ref":
        problems += _ref_problems(model.returns.data, params, f"{where}.returns",
                                  allow_return=False)
    if model.returns.how == "partial":
        problems += _ref_problems(Ref("arg", model.returns.data), params, f"{where}.returns",
                                  allow_return=False)
    for name, ref in model.returns.fields:
        problems += _ref_problems(ref, params, f"{where}.returns.{name}", allow_return=False)
    problems += [f"{where}.callbacks: no parameter {c!r}"
                 for c in model.callbacks if c not in params]
    return problems


@pytest.mark.parametrize("name", SHIPPED_NAMES)
def test_shipped_stub_loads_without_errors(name):
    library = load_library([(name, dict(SHIPPED)[name])])
    assert library.errors == []
    assert library.functions or library.classes


def test_all_shipped_stubs_load_together_without_errors():
    assert load_library(SHIPPED).errors == []


def test_the_library_models_this_task_adds_are_shipped():
    assert {"tf2_ros.toml", "message_filters.toml", "interactive_markers.toml",
            "diagnostic_updater.toml", "nav2_simple_commander.toml"} <= set(SHIPPED_NAMES)


def test_no_shipped_stub_silently_replaces_another_ones_entry():
    owners: dict[tuple[str, str], list[str]] = {}
    for name, text in SHIPPED:
        library = load_library([(name, text)])
        for section in ("functions", "classes", "constants"):
            for qualname in getattr(library, section):
                owners.setdefault((section, qualname), []).append(name)
    assert {key: files for key, files in owners.items() if len(files) > 1} == {}


@pytest.mark.parametrize("name", SHIPPED_NAMES)
def test_shipped_stub_effects_and_references_are_consistent(name):
    library = load_library([(name, dict(SHIPPED)[name])])
    problems = [p for model in _models(library) for p in _model_problems(model)]
    assert problems == []


def _constant_refs(model: FunctionModel) -> Iterator[str]:
    refs = [ref for effect in model.effects for _, ref in effect.args]
    refs += [store.value for store in model.stores] + [ref for _, ref in model.returns.fields]
    if model.returns.how == "ref":
        refs.append(model.returns.data)
    yield from (ref.data for ref in refs if ref.how == "constant")


def test_every_shipped_constant_reference_names_a_modelled_constant():
    library = load_library(SHIPPED)
    missing = [name for model in _models(library) for name in _constant_refs(model)
               if not _template_params(name) and library.canonical(name) not in library.constants]
    assert missing == []
    presets = [name for name in library.aliases if name.startswith("rclpy.qos.QoSPresetProfiles.")]
    assert presets and all(library.canonical(p) in library.constants for p in presets)


def test_effect_vocabulary_covers_every_entity_kind_the_builder_knows():
    assert set(ENTITY_KINDS) <= set(EFFECT_ARGS)


def test_shipped_bases_and_via_classes_are_modelled():
    library = load_library(SHIPPED)
    problems = [f"{cls.qualname}: base {base!r} is not modelled"
                for cls in library.classes.values() for base in cls.bases
                if library.canonical(base) not in library.classes]
    for model in _models(library):
        for effect in model.effects:
            for name, ref in effect.args:
                if name != "via":
                    continue
                vias = ref.data.strings() if ref.how == "const" else None
                if not vias:
                    problems.append(f"{model.qualname}: via must be a const string")
                    continue
                problems += [f"{model.qualname}: via {v!r} is not a modelled class or function"
                             for v in vias if library.canonical(v) not in library.classes
                             and library.canonical(v) not in library.functions]
    assert problems == []


def test_blocking_calls_are_modelled_with_why_and_duration():
    library = load_library(SHIPPED)
    assert library.method("rclpy.client.Client", "call").blocking
    assert library.method("rclpy.executors.MultiThreadedExecutor", "spin").blocking
    assert library.functions["rclpy.spin_until_future_complete"].blocking
    assert library.functions["time.sleep"].blocks_for == "secs"
    assert library.method("rclpy.client.Client", "call_async").blocking is None
    # rclpy's Future.result() returns None before the future is done: it never blocks.
    assert library.method("rclpy.task.Future", "result").blocking is None


def test_consistency_check_catches_a_misspelt_model():
    # The consistency test above is only worth something if it can fail.
    library = load_library([("typo.toml", """
[functions."acme.make_pub"]
params = "node, name"
effects = [{ kind = "publisher", node = "node", topc = "name", type = { const = "a/msg/B" } }]
callbacks = ["cb"]
stores = [{ on = "nod", key = "{nme}", value = "name" }]
""")])
    assert library.errors == []
    assert _model_problems(library.functions["acme.make_pub"]) == [
        "acme.make_pub.effects[0]: publisher takes no 'topc'",
        "acme.make_pub.effects[0]: publisher needs 'topic'",
        "acme.make_pub.stores[0].on: no parameter 'nod'",
        "acme.make_pub.stores[0].key: no parameter 'nme'",
        "acme.make_pub.callbacks: no parameter 'cb'",
    ]


# =========================================================================================
# broken stub files: one message naming file and key, never an exception
# =========================================================================================
#: A valid entry appended to each broken file: it must still load.
GOOD = '\n[constants."ok.FINE"]\nvalue = 1\n'

BROKEN: dict[str, tuple[str, str]] = {
    # case: (stub text, text the single error message must contain after "broken.toml: ")
    "unknown top-level key": ("function = 1\n", "unknown top-level key 'function'"),
    "true_instances not a list of names": ("true_instances = 'acme'\n",
                                           "true_instances: expected a list of module names"),
    "unknown function key": ('[functions."acme.make_pub"]\nparam = "node"\n',
                             "functions.'acme.make_pub': unknown key 'param'"),
    "unknown class key": ('[classes."acme.Base"]\ncolour = "blue"\n',
                          "classes.'acme.Base': unknown key 'colour'"),
    "params not a string": ('[functions."acme.f"]\nparams = ["node"]\n',
                            "functions.'acme.f'.params: expected a string"),
    "bad params syntax": ('[functions."acme.f"]\nparams = "node name"\n',
                          "functions.'acme.f'.params: bad parameter list 'node name'"),
    "non-literal default": ('[functions."acme.f"]\nparams = "node, depth=len(\'x\')"\n',
                            "functions.'acme.f'.params: default \"len('x')\" is not a literal"),
    "unsupported literal default": ('[functions."acme.f"]\nparams = "node, tags={1, 2}"\n',
                                    "functions.'acme.f'.params: unsupported value {1, 2}"),
    "reference of the wrong type": (
        '[functions."acme.f"]\nparams = "node"\neffects = [{ kind = "publisher", node = 3 }]\n',
        "functions.'acme.f'.effects[0].node: expected a parameter name"),
    "effect without kind": ('[functions."acme.f"]\nparams = "node"\n'
                            'effects = [{ node = "node" }]\n',
                            "functions.'acme.f'.effects[0]: needs kind"),
    "effect not a table": ('[functions."acme.f"]\neffects = ["publisher"]\n',
                           "functions.'acme.f'.effects[0]: expected a table, got str"),
    "callbacks not a list": ('[functions."acme.f"]\nparams = "cb"\ncallbacks = "cb"\n',
                             "functions.'acme.f'.callbacks: expected a list of strings"),
    "store missing a key": ('[functions."acme.f"]\nparams = "self, v"\n'
                            'stores = [{ on = "self", key = "k" }]\n',
                            "functions.'acme.f'.stores[0]: needs on, key, value (and may have each)"),
    "returned record with unknown key": ('[functions."acme.f"]\n'
                                         'returns = { record = "acme.R", field = {} }\n',
                                         "functions.'acme.f'.returns: unknown key 'field'"),
    "bases not a list": ('[classes."acme.Base"]\nbases = "rclpy.node.Node"\n',
                         "classes.'acme.Base'.bases: expected a list of strings"),
    "entry not a boolean": ('[classes."acme.Base"]\nentry = "yes"\n',
                            "classes.'acme.Base'.entry: expected true or false"),
    "methods not a table": ('[classes."acme.Base"]\nmethods = 3\n',
                            "classes.'acme.Base'.methods: expected a table, got int"),
    "broken method": ('[classes."acme.Base".methods.__init__]\nparams = "self, x=y"\n',
                      "classes.'acme.Base'.methods.__init__.params: default 'y' is not a literal"),
    "constant without value": ('[constants."acme.X"]\nnumber = 3\n',
                               "constants.'acme.X': expected { value = … }"),
    "alias to a non-string": ('[aliases]\n"acme.A" = 3\n', "aliases.'acme.A': expected a string"),
    "section not a table": ("functions = 3\n", "[functions] must be a table"),
    "blocking not a string": ('[functions."acme.wait"]\nblocking = true\n',
                              "functions.'acme.wait'.blocking: expected a non-empty string"),
    "blocking empty": ('[functions."acme.wait"]\nblocking = " "\n',
                       "functions.'acme.wait'.blocking: expected a non-empty string"),
    "blocks_for without blocking": ('[functions."acme.wait"]\nparams = "secs"\nblocks_for = "secs"\n',
                                    "functions.'acme.wait'.blocks_for: only meaningful with blocking"),
    "callback_args for no callback": ('[functions."acme.run"]\nparams = "target, args=()"\n'
                                      'callback_args = { target = { args = "args" } }\n',
                                      "functions.'acme.run'.callback_args.target: not one of callbacks"),
    "callback_args naming no parameter": ('[functions."acme.run"]\nparams = "target, args=()"\n'
                                          'callbacks = ["target"]\n'
                                          'callback_args = { target = { args = "argv" } }\n',
                                          "functions.'acme.run'.callback_args.target.args: 'argv' "
                                          "is not a parameter"),
    "callback_args with an unknown key": ('[functions."acme.run"]\nparams = "target, args=()"\n'
                                          'callbacks = ["target"]\n'
                                          'callback_args = { target = { positional = "args" } }\n',
                                          "functions.'acme.run'.callback_args.target: expected args"),
    "blocks_for not a parameter": ('[functions."acme.wait"]\nparams = "secs"\nblocking = "sleeps"\n'
                                   'blocks_for = "seconds"\n',
                                   "functions.'acme.wait'.blocks_for: 'seconds' is not a parameter"),
}

#: Broken files that once escaped the loader's reporting (kept as regressions).
KNOWN_GAPS: dict[str, tuple[str, str, str]] = {
    "stores not a list": ('[functions."acme.f"]\nparams = "self"\nstores = 3\n',
                          "functions.'acme.f'.stores", "raises TypeError iterating an int"),
    "effects not a list": ('[functions."acme.f"]\neffects = 3\n',
                           "functions.'acme.f'.effects", "raises TypeError iterating an int"),
    "date constant": ('[constants."acme.RELEASED"]\nvalue = 2024-05-01\n',
                      "constants.'acme.RELEASED'", "message names neither file nor key"),
    "params with a second statement": ('[functions."acme.f"]\nparams = "x): pass\\ndef g(y"\n',
                                       "functions.'acme.f'.params", "accepted silently"),
}


def _single_error(text: str) -> tuple[LibraryModel, str]:
    library = load_library([("broken.toml", text)])
    assert len(library.errors) == 1, library.errors
    return library, library.errors[0]


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_broken_entry_is_reported_with_file_and_key_and_the_rest_loads(case):
    text, expected = BROKEN[case]
    library, error = _single_error(text + GOOD)
    assert error.startswith("broken.toml: ")
    assert expected in error
    assert "ok.FINE" in library.constants


@pytest.mark.parametrize("case", [
    pytest.param(case)
    for case, (_, _, why) in sorted(KNOWN_GAPS.items())])
def test_known_loader_gaps(case):
    text, expected, _ = KNOWN_GAPS[case]
    library, error = _single_error(text + GOOD)
    assert error.startswith(f"broken.toml: {expected}")
    assert "ok.FINE" in library.constants


def test_invalid_toml_is_one_message_naming_the_file():
    _, error = _single_error('[functions."acme.f"]\nparams 3\n')
    assert error.startswith("broken.toml: not valid TOML: ")
    assert "line 2" in error


def test_deeply_nested_toml_is_reported_not_raised():
    _, error = _single_error("[constants.deep]\nvalue = " + "[" * 5000 + "]" * 5000 + "\n")
    assert error.startswith("broken.toml: ")


def test_huge_stub_file_loads_every_entry():
    count = 5000
    text = "".join(f'[functions."acme.gen.make_pub_{i}"]\nparams = "node, topic, qos=10"\n'
                   'effects = [{ kind = "publisher", node = "node", topic = "topic", '
                   'qos = "qos" }]\n'
                   for i in range(count))
    library = load_library([("huge.toml", text)])
    assert library.errors == []
    assert len(library.functions) == count


def test_huge_value_under_an_unknown_key_is_one_message():
    _, error = _single_error('blob = "' + "x" * 5_000_000 + '"\n' + GOOD)
    assert error == "broken.toml: unknown top-level key 'blob'"


def test_later_file_replaces_an_entry_and_reports_nothing():
    library = load_library([("a.toml", '[functions."acme.f"]\nparams = "x"\n'),
                            ("b.toml", '[functions."acme.f"]\nparams = "x, y"\n')])
    assert library.errors == []
    assert [p.name for p in library.functions["acme.f"].signature.params] == ["x", "y"]


# -- through build_graph: diagnostics, and the graph is still built -------------------------
def _tf_topics(graph: RosGraph) -> list[str]:
    return sorted(e.name for _, e in graph.entities() if e.via and e.via.startswith("tf2_ros."))


@pytest.mark.parametrize("text", [
    '[functions."acme.f"]\nparams = "node, depth=len(\'x\')"\n',
    '[functions."acme.f"]\nparams 3\n',
    '[functions."acme.f"]\nparams = "x"\nreturns = { object = "{x}", separator = "/", shape = "(" }\n',
    '[functions."acme.f"]\nparams = "x"\nreturns = { object = "{x}", separator = "", shape = ".*" }\n',
])
def test_broken_user_stub_becomes_an_error_diagnostic_and_the_graph_is_still_built(tmp_path, text):
    stub = tmp_path / "broken.toml"
    stub.write_text(text, encoding="utf-8")
    graph = build_graph(FIXTURES / "tf2", [stub])
    errors = [d for d in graph.diagnostics if d.severity == "error"]
    assert len(errors) == 1
    assert errors[0].path == str(stub)
    assert errors[0].message.startswith(f"stub: {stub}: ")
    assert _tf_topics(graph) == ["/tf", "/tf", "/tf2_buffer_server", "/tf2_frames", "/tf_static",
                                 "/tf_static"]


def test_unreadable_stub_file_becomes_an_error_diagnostic(tmp_path):
    missing = tmp_path / "nowhere.toml"
    graph = build_graph(FIXTURES / "tf2", [missing])
    assert [(d.path, d.severity) for d in graph.diagnostics] == [(str(missing), "error")]
    assert "cannot read stub file" in graph.diagnostics[0].message
    assert "/tf_static" in _tf_topics(graph)


def test_deeply_nested_user_stub_does_not_lose_the_graph(tmp_path):
    stub = tmp_path / "deep.toml"
    stub.write_text("[constants.deep]\nvalue = " + "[" * 5000 + "]" * 5000 + "\n", encoding="utf-8")
    graph = build_graph(FIXTURES / "tf2", [stub])
    assert "/tf_static" in _tf_topics(graph)


# =========================================================================================
# end to end: fixture workspaces
# =========================================================================================
@lru_cache(maxsize=None)
def graph_of(case: str, *stubs: str) -> RosGraph:
    return build_graph(FIXTURES / case, [FIXTURES / s for s in stubs])


def named(graph: RosGraph, kind: str) -> list[tuple]:
    """``(node fqn, entity name, type, via)`` of every entity of ``kind``, sorted."""
    return sorted((n.fqn, e.name, e.type, e.via) for n, e in graph.entities(kind))


def entity(graph: RosGraph, kind: str, fqn: str, name: str):
    found = [e for n, e in graph.entities(kind) if n.fqn == fqn and e.name == name]
    assert len(found) == 1, (kind, fqn, name, found)
    return found[0]


CASES = ["tf2", "message_filters_sync", "interactive_markers", "diagnostics", "nav2_commander"]


@pytest.mark.parametrize("case", CASES)
def test_fixture_analyses_without_diagnostics(case):
    assert graph_of(case).diagnostics == []


@pytest.mark.parametrize("case", CASES)
def test_fixture_graph_is_the_same_byte_for_byte_on_every_run(case):
    first = to_json(build_graph(FIXTURES / case))
    assert to_json(build_graph(FIXTURES / case)) == first


# -- tf2_ros ---------------------------------------------------------------------------------
TF = "tf2_msgs/msg/TFMessage"


def test_tf2_broadcasters_publish_absolute_tf_topics_from_a_namespaced_node():
    assert named(graph_of("tf2"), "publishers") == [
        ("/robot1/frame_publisher", "/tf", TF, "tf2_ros.TransformBroadcaster"),
        ("/robot1/frame_publisher", "/tf_static", TF, "tf2_ros.StaticTransformBroadcaster"),
    ]


def test_tf2_listener_subscribes_both_topics_on_its_node_without_a_user_callback():
    graph = graph_of("tf2")
    assert named(graph, "subscriptions") == [
        ("/frame_listener", "/tf", TF, "tf2_ros.TransformListener"),
        ("/frame_listener", "/tf_static", TF, "tf2_ros.TransformListener"),
    ]
    assert [e.callback for _, e in graph.entities("subscriptions")] == [None, None]


def test_tf2_static_topic_is_transient_local_at_both_ends():
    graph = graph_of("tf2")
    pub = entity(graph, "publishers", "/robot1/frame_publisher", "/tf_static")
    sub = entity(graph, "subscriptions", "/frame_listener", "/tf_static")
    assert (pub.qos["durability"], pub.qos["depth"]) == ("transient_local", 1)
    assert (sub.qos["durability"], sub.qos["depth"]) == ("transient_local", 100)


def test_tf2_default_qos_is_rclpys_depth_profile_and_a_passed_qos_overrides_it():
    graph = graph_of("tf2")
    pub = entity(graph, "publishers", "/robot1/frame_publisher", "/tf")
    assert {k: pub.qos[k] for k in ("history", "depth", "reliability", "durability")} == \
        {"history": "keep_last", "depth": 100, "reliability": "reliable", "durability": "volatile"}
    assert entity(graph, "subscriptions", "/frame_listener", "/tf").qos["depth"] == 5


def test_tf2_buffer_with_a_node_serves_frames_and_buffer_client_is_an_action_client():
    graph = graph_of("tf2")
    assert named(graph, "services") == [
        ("/frame_listener", "/tf2_frames", "tf2_msgs/srv/FrameGraph", "tf2_ros.Buffer")]
    assert named(graph, "action_clients") == [
        ("/frame_listener", "/tf2_buffer_server", "tf2_msgs/action/LookupTransform",
         "tf2_ros.BufferClient")]


# -- message_filters -------------------------------------------------------------------------
MFS = "message_filters.Subscriber"


def test_message_filters_subscribers_are_subscriptions_with_no_callback():
    graph = graph_of("message_filters_sync")
    assert named(graph, "subscriptions") == [
        ("/stereo_sync", "/camera/camera_info", "sensor_msgs/msg/CameraInfo", MFS),
        ("/stereo_sync", "/camera/image_raw", "sensor_msgs/msg/Image", MFS),
    ]
    assert [e.callback for _, e in graph.entities("subscriptions")] == [None, None]
    # A depth is rclpy's QoSProfile(depth=N): the default profile with that depth.
    assert entity(graph, "subscriptions", "/stereo_sync", "/camera/image_raw").qos == dict(DEPTH_PROFILE, depth=10)
    assert entity(graph, "subscriptions", "/stereo_sync", "/camera/camera_info").qos == dict(DEPTH_PROFILE, depth=5)


def test_message_filters_registered_callbacks_are_analysed_and_get_topic_is_followed():
    # on_pair / on_exact_pair create publishers: they are found only if registerCallback
    # schedules them; '/camera/image_raw/exact' needs getTopic() to return the topic.
    assert named(graph_of("message_filters_sync"), "publishers") == [
        ("/stereo_sync", "/camera/image_raw/exact", "std_msgs/msg/Header", None),
        ("/stereo_sync", "/paired_stamp", "std_msgs/msg/Header", None),
    ]


# -- interactive_markers ---------------------------------------------------------------------
IMS = "interactive_markers.InteractiveMarkerServer"
VIS = "visualization_msgs"


def test_interactive_marker_server_topics_and_service_follow_its_namespace():
    graph = graph_of("interactive_markers")
    update, feedback = f"{VIS}/msg/InteractiveMarkerUpdate", f"{VIS}/msg/InteractiveMarkerFeedback"
    assert [t for t in named(graph, "publishers") if t[3]] == [
        ("/arm/planner_markers", "/planner/markers/update", update, IMS),
        ("/ui/marker_server", "/ui/simple_marker/update", update, IMS),
    ]
    assert named(graph, "subscriptions") == [
        ("/arm/planner_markers", "/planner/markers/feedback", feedback, IMS),
        ("/ui/marker_server", "/ui/simple_marker/feedback", feedback, IMS),
    ]
    assert named(graph, "services") == [
        ("/arm/planner_markers", "/planner/markers/get_interactive_markers",
         f"{VIS}/srv/GetInteractiveMarkers", IMS),
        ("/ui/marker_server", "/ui/simple_marker/get_interactive_markers",
         f"{VIS}/srv/GetInteractiveMarkers", IMS),
    ]


def test_interactive_marker_feedback_and_menu_callbacks_are_analysed():
    assert [t for t in named(graph_of("interactive_markers"), "publishers") if not t[3]] == [
        ("/ui/marker_server", "/ui/marker_goal", "std_msgs/msg/String", None),
        ("/ui/marker_server", "/ui/marker_reset", "std_msgs/msg/String", None),
    ]


# -- diagnostic_updater ----------------------------------------------------------------------
def test_diagnostic_updater_publishes_diagnostics_and_declares_its_parameters():
    graph = graph_of("diagnostics")
    assert ("/battery_monitor", "/diagnostics", "diagnostic_msgs/msg/DiagnosticArray",
            "diagnostic_updater.Updater") in named(graph, "publishers")
    assert sorted((e.name, e.default) for _, e in graph.entities("parameters")) == [
        ("diagnostic_updater.period", 2.0), ("diagnostic_updater.use_fqn", False)]
    assert [(e.period, e.callback) for _, e in graph.entities("timers")] == [(2.0, None)]


def test_diagnostic_task_functions_and_run_methods_are_analysed():
    assert [t[1] for t in named(graph_of("diagnostics"), "publishers") if not t[3]] == [
        "/battery_alarm", "/overheated"]


# -- nav2_simple_commander -------------------------------------------------------------------
NAV2_ACTIONS = {
    "assisted_teleop": "AssistedTeleop", "backup": "BackUp",
    "compute_path_through_poses": "ComputePathThroughPoses",
    "compute_path_to_pose": "ComputePathToPose",
    "follow_path": "FollowPath", "follow_waypoints": "FollowWaypoints",
    "navigate_through_poses": "NavigateThroughPoses", "navigate_to_pose": "NavigateToPose",
    "smooth_path": "SmoothPath", "spin": "Spin",
}
NAV2_SERVICES = {
    "global_costmap/clear_entirely_global_costmap": "ClearEntireCostmap",
    "global_costmap/get_costmap": "GetCostmap",
    "local_costmap/clear_entirely_local_costmap": "ClearEntireCostmap",
    "local_costmap/get_costmap": "GetCostmap",
    "map_server/load_map": "LoadMap",
}
NAV = "nav2_simple_commander.robot_navigator.BasicNavigator"


def test_basic_navigator_is_a_node_with_the_nav2_clients_in_its_namespace():
    graph = graph_of("nav2_commander")
    fqn = "/robot1/basic_navigator"
    assert [(n.fqn, n.cls) for n in graph.nodes if n.fqn == fqn] == [(fqn, None)]
    assert [t for t in named(graph, "action_clients") if t[0] == fqn] == sorted(
        (fqn, f"/robot1/{name}", f"nav2_msgs/action/{typ}", NAV)
        for name, typ in NAV2_ACTIONS.items())
    assert [t for t in named(graph, "clients") if t[0] == fqn] == sorted(
        (fqn, f"/robot1/{name}", f"nav2_msgs/srv/{typ}", NAV)
        for name, typ in NAV2_SERVICES.items())
    amcl = entity(graph, "subscriptions", fqn, "/robot1/amcl_pose")
    assert (amcl.type, amcl.via, amcl.qos["durability"]) == (
        "geometry_msgs/msg/PoseWithCovarianceStamped", NAV, "transient_local")
    assert entity(graph, "publishers", fqn, "/robot1/initialpose").qos == dict(DEPTH_PROFILE, depth=10)


def test_basic_navigator_subclass_keeps_the_navigator_entities_and_adds_its_own():
    graph = graph_of("nav2_commander")
    fqn = "/docking_navigator"
    assert [(n.fqn, n.cls) for n in graph.nodes if n.fqn == fqn] == [(fqn, "DockingNavigator")]
    assert len([t for t in named(graph, "action_clients") if t[0] == fqn]) == len(NAV2_ACTIONS)
    assert [t for t in named(graph, "publishers") if t[0] == fqn] == [
        (fqn, "/dock_status", "std_msgs/msg/String", None),
        (fqn, "/initialpose", "geometry_msgs/msg/PoseWithCovarianceStamped", NAV),
    ]


def test_basic_navigator_subclass_nothing_instantiates_is_still_a_node():
    graph = graph_of("nav2_entry")
    fqn = "/inspector/inspection_navigator"
    assert [(n.fqn, n.cls) for n in graph.nodes] == [(fqn, "InspectionNavigator")]
    assert (fqn, "/inspector/navigate_to_pose", "nav2_msgs/action/NavigateToPose", NAV) in \
        named(graph, "action_clients")
    assert (fqn, "/inspector/inspection_report", "std_msgs/msg/String", None) in \
        named(graph, "publishers")


# -- a user's own stub file ------------------------------------------------------------------
USER_STUB = "user_wrapper/stubs/acme_robot.toml"


def test_user_stub_models_a_wrapper_library_the_analyser_cannot_see():
    graph = graph_of("user_wrapper/ws", USER_STUB)
    assert graph.diagnostics == []
    assert [(n.fqn, n.cls) for n in graph.nodes] == [("/arm/arm_driver", "ArmDriver")]
    assert named(graph, "publishers") == [
        ("/arm/arm_driver", "/arm/heartbeat", "std_msgs/msg/Header", "acme_robot.RobotBase"),
        ("/arm/arm_driver", "/arm/joint_states", "sensor_msgs/msg/JointState", None),
    ]
    command = entity(graph, "subscriptions", "/arm/arm_driver", "/arm/gripper/command")
    assert (command.type, command.callback) == ("std_msgs/msg/String", "ArmDriver.on_gripper")


def test_without_the_user_stub_the_wrapper_library_is_invisible():
    assert graph_of("user_wrapper/ws").nodes == []


def test_every_shipped_stub_is_in_the_table_of_shipped_models():
    table = (Path(__file__).parent.parent / "docs" / "stubs.md").read_text(encoding="utf-8")
    assert [name for name in SHIPPED_NAMES if f"`{name}`" not in table] == []


def test_instances_of_a_library_that_says_so_are_true():
    model = load_library([("acme.toml", 'true_instances = ["acme_robot"]\n')])
    assert model.errors == []
    assert model.instance_is_true("acme_robot.base.RobotBase")
    assert not model.instance_is_true("acme_robotics.Arm")  # another library sharing the prefix
    assert load_library(builtin_stub_texts()).instance_is_true("rclpy.node.Node")
