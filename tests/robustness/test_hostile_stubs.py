"""Broken, hostile and enormous stub files given with ``--stubs``.

A stub file is data: whatever it holds, the run ends normally, the built-in
models still apply (the good nodes are all extracted), each broken entry is
named by a diagnostic on the stub file, and nothing in it is ever executed.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from .harness import assert_clean_exit, diagnostics_on, entity_keys, graph_cli, parse_graph
from .hostile_inputs import GOOD_ENTITIES, GOOD_FILES, write_files

#: Written by a stub default if anything ever evaluated it.
MARKER = "STUB_CODE_RAN"


def _enormous(entries: int) -> str:
    return "[functions]\n" + "".join(
        f'"generated.f{i}" = {{ params = "a, b={i}", returns = "generated.C{i}", '
        f'effects = [{{ kind = "k{i}", x = "a" }}] }}\n' for i in range(entries))


def _enormous_broken(entries: int) -> str:
    return "[functions]\n" + "".join(f'"broken.f{i}" = {{ params = {i}, bogus_{i} = true }}\n'
                                     for i in range(entries))


#: name → (file content, regular expression one diagnostic on the file must match; None: no diagnostic).
STUB_CASES: dict[str, tuple[bytes, str | None]] = {
    "not_toml": (b"not = valid = toml [[[\n", r"not valid TOML"),
    "invalid_utf8": (b"[functions]\n\xff\xfe = 1\n", r"cannot read stub file"),
    "binary_garbage": (bytes(range(256)) * 64, r"cannot read stub file|not valid TOML"),
    "sections_of_wrong_type": (b'functions = 3\nclasses = "x"\nconstants = [1]\naliases = 1\n', r"must be a table"),
    "unknown_top_level_key": (b"[surprise]\nx = 1\n", r"unknown top-level key 'surprise'"),
    "unknown_entry_key": (b'[functions."pkg.f"]\nparams = "a"\nbogus = 1\n', r"unknown key 'bogus'"),
    "params_not_a_string": (b'[functions."pkg.f"]\nparams = 5\n', r"params"),
    "effects_not_a_list": (b'[functions."pkg.f"]\neffects = "publish everything"\n', r"effects"),
    "effect_without_kind": (b'[functions."pkg.f"]\neffects = [{ topic = "a" }]\n', r"kind"),
    "bases_not_a_list": (b'[classes."pkg.C"]\nbases = "rclpy.node.Node"\n', r"bases"),
    "entry_flag_not_bool": (b'[classes."pkg.C"]\nentry = "yes"\n', r"entry"),
    "store_missing_keys": (b'[functions."pkg.f"]\nstores = [{ on = "self" }]\n', r"stores"),
    "alias_not_a_string": (b'[aliases]\n"pkg.a" = 3\n', r"aliases"),
    "constant_of_unsupported_type": (b'[constants]\n"pkg.WHEN" = { value = 1979-05-27T07:32:00Z }\n',
                                     r"constants|unsupported"),
    "code_in_a_default": ((f'[functions."pkg.f"]\nparams = "x=__import__(\'pathlib\').Path(\'{MARKER}\')'
                           f'.write_text(\'ran\')"\n').encode(), r"not a literal"),
    "code_after_the_parameter_list": (b'[functions."pkg.f"]\nparams = "x): pass\\nimport os\\ndef g(y"\n',
                                      r"parameter list"),
    "power_tower_default": (b'[functions."pkg.f"]\nparams = "x=10 ** 10 ** 10"\n', r"not a literal"),
    "deeply_nested_default": (('[functions."pkg.f"]\nparams = "x=' + "(" * 3000 + "1" + ")" * 3000 + '"\n').encode(),
                              r"parameter list|nested|too complex|recursion|not a literal"),
    "deeply_nested_arrays": (("deep = " + "[" * 5000 + "]" * 5000 + "\n").encode(),
                             r"nested too deeply|not valid TOML|recursion"),
    "alias_cycles": (b'[aliases]\n"pkg.a" = "pkg.b"\n"pkg.b" = "pkg.a"\n"pkg.self" = "pkg.self"\n', None),
    "class_base_cycle": (b'[classes."pkg.A"]\nbases = ["pkg.B"]\n[classes."pkg.B"]\nbases = ["pkg.A"]\n'
                         b'[classes."pkg.S"]\nbases = ["pkg.S"]\nentry = true\n', None),
    "enormous_valid": (_enormous(50_000).encode(), None),
    "enormous_broken": (_enormous_broken(2_000).encode(), r"functions\.'broken\.f1999'"),
}


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    write_files(root, {k: v.encode() for k, v in GOOD_FILES.items()})
    return root


def run_with_stub(tmp_path: Path, workspace: Path, stub: str) -> dict:
    """Run the graph CLI from ``tmp_path`` with ``--stubs STUB`` (a path relative to ``tmp_path``)."""
    done = graph_cli(workspace, "--format", "json", "--stubs", stub, cwd=tmp_path)
    assert_clean_exit(done)
    graph = parse_graph(done)
    found = entity_keys(graph)
    assert GOOD_ENTITIES <= found, f"good entities lost: {sorted(GOOD_ENTITIES - found, key=str)}"
    return graph


@pytest.mark.parametrize("name", sorted(STUB_CASES))
def test_hostile_stub_file(name: str, tmp_path: Path, workspace: Path) -> None:
    content, expected = STUB_CASES[name]
    (tmp_path / "stubs").mkdir()
    (tmp_path / "stubs" / f"{name}.toml").write_bytes(content)
    graph = run_with_stub(tmp_path, workspace, f"stubs/{name}.toml")
    on_stub = diagnostics_on(graph, f"stubs/{name}.toml")
    if expected is not None:
        assert any(re.search(expected, d["message"]) for d in on_stub), \
            f"no diagnostic matching {expected!r} on the stub; diagnostics: {graph['diagnostics'][:20]}"
    assert not (tmp_path / MARKER).exists() and not (workspace / MARKER).exists(), "stub content was executed"


def test_every_broken_entry_is_named(tmp_path: Path, workspace: Path) -> None:
    (tmp_path / "many.toml").write_text(_enormous_broken(300), encoding="utf-8")
    graph = run_with_stub(tmp_path, workspace, "many.toml")
    named = {m.group(1) for d in diagnostics_on(graph, "many.toml")
             for m in [re.search(r"functions\.'broken\.f(\d+)'", d["message"])] if m}
    assert named == {str(i) for i in range(300)}


@pytest.mark.parametrize("kind", ["missing", "directory"])
def test_stub_path_that_is_not_a_file(kind: str, tmp_path: Path, workspace: Path) -> None:
    if kind == "directory":
        (tmp_path / "nothing.toml").mkdir()
    graph = run_with_stub(tmp_path, workspace, "nothing.toml")
    assert any("cannot read stub file" in d["message"] for d in diagnostics_on(graph, "nothing.toml")), \
        graph["diagnostics"]
