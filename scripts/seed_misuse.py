#!/usr/bin/env python3
"""Seed rclpy misuse bugs into copies of real repositories and count what the tool reports.

Usage::

    scripts/seed_misuse.py make CORPUS MUTANTS.jsonl [--cap N] [--seed S]
    scripts/seed_misuse.py run CORPUS MUTANTS.jsonl RESULTS.jsonl [--tool flake8-rosgraph]

``CORPUS`` holds one folder per repository (each its own workspace root). ``make`` reads the
Python files with ``ast`` (it never imports them) and writes one-line edits, each a bug the
misuse rules exist for, or a neutral edit that must change nothing:

========================  =====================================================  ========
kind                      edit                                                   expected
========================  =====================================================  ========
``sync_call``             ``client.call_async(req)`` -> ``client.call(req)``     ROS101
                          inside a method registered as a callback
``param_typo``            ``get_parameter('max_speed')`` -> ``'max_sped'``,      ROS102
                          where the class declares ``max_speed``
``cb_arity``              a timer callback taking an ``event`` (a ROS 1 habit),  ROS103
                          a subscription callback without its message, a
                          service callback without the response
``init_order``            ``rclpy.init()`` moved after the line that makes the   ROS105
                          node (``node = Talker()``) in ``main``
``field_typo``            ``msg.data = …`` -> ``msg.dat = …`` on a message the   ROS107
                          same function constructs
``field_int``             ``msg.x = 1.0`` -> ``msg.x = 1`` (rclpy rejects an     ROS107
                          int for a float field)
``neg_cb_default``        a timer callback gains ``event=None``                  nothing
========================  =====================================================  ========

Only sites the rules can be expected to judge are seeded: callbacks without decorators, and
messages of packages whose definitions the tool has (the shipped table or the repository's
own ``.msg`` files). ``run`` edits each repository in place, runs ``flake8-rosgraph check``,
restores the file, and writes one JSON line per mutant: ``detected`` when a new finding with
the expected code is at one of the mutant's lines, ``masked`` when the clean repository
already has one there, ``new`` the new findings (for a neutral edit: false alarms). Run it on
a copy of the corpus, never on a checkout you work in.
"""
from __future__ import annotations

import argparse
import ast
import hashlib
import json
import random
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Iterator

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from flake8_rosgraph.interfaces.catalogue import standard_catalogue  # noqa: E402

#: Creation methods -> the position and keyword of their callback argument.
CALLBACK_ARGUMENT = {"create_subscription": (2, "callback"), "create_timer": (1, "callback"),
                     "create_service": (2, "callback")}
SKIPPED_DIRS = {"build", "install", "log", "node_modules"}


@dataclass
class Mutant:
    id: str
    repo: str
    kind: str
    file: str
    line: int
    old: str
    new: str
    expect: str                                     # a code, or "" for a neutral edit
    lines: list[int] = field(default_factory=list)  # where a finding counts
    description: str = ""


def split_lines(text: str) -> list[str]:
    """The lines as Python's tokenizer numbers them (``\\r\\n``, ``\\r`` or ``\\n``), with their ends."""
    return re.findall(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+$", text)


def _python_files(root: Path) -> Iterator[Path]:
    for path in sorted(root.rglob("*.py")):
        parts = path.relative_to(root).parts
        if not any(p.startswith(".") or p in SKIPPED_DIRS for p in parts):
            yield path


def _call_name(node: ast.AST) -> str | None:
    if isinstance(node, ast.Call):
        if isinstance(node.func, ast.Attribute):
            return node.func.attr
        if isinstance(node.func, ast.Name):
            return node.func.id
    return None


def _argument(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
    for kw in call.keywords:
        if kw.arg == keyword:
            return kw.value
    if index < len(call.args) and not any(isinstance(a, ast.Starred) for a in call.args[:index + 1]):
        return call.args[index]
    return None


def _self_attribute(node: ast.expr | None) -> str | None:
    if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name) and node.value.id == "self":
        return node.attr
    return None


def _text(node: ast.expr | None) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


class Seeder:
    """The mutants of one file."""

    def __init__(self, repo: str, rel: str, text: str, known_packages: set[str]) -> None:
        self.repo, self.rel = repo, rel
        self.lines = [line.rstrip("\r\n") for line in split_lines(text)]
        self.tree = ast.parse(text)
        self.known_packages = known_packages
        self.found: list[Mutant] = []

    def edit(self, kind: str, line: int, old: str, new: str, expect: str, lines: list[int],
             description: str) -> None:
        source = self.lines[line - 1]
        if source.count(old) != 1:
            return
        edited = list(self.lines)
        edited[line - 1] = source.replace(old, new)
        try:
            ast.parse("\n".join(edited))
        except SyntaxError:
            return
        digest = hashlib.sha1(f"{self.repo}:{self.rel}:{line}:{old}:{new}".encode()).hexdigest()[:8]
        self.found.append(Mutant(f"{kind}-{digest}", self.repo, kind, self.rel, line, old, new,
                                 expect, sorted(set(lines)), description))

    def seed(self) -> list[Mutant]:
        for cls in (n for n in ast.walk(self.tree) if isinstance(n, ast.ClassDef)):
            methods = {f.name: f for f in cls.body if isinstance(f, (ast.FunctionDef, ast.AsyncFunctionDef))}
            registered: dict[str, tuple[str, int]] = {}
            for node in ast.walk(cls):
                name = _call_name(node)
                if name in CALLBACK_ARGUMENT:
                    method = _self_attribute(_argument(node, *CALLBACK_ARGUMENT[name]))
                    if method in methods and not methods[method].decorator_list:
                        registered.setdefault(method, (name, node.lineno))
            for method, (creation, line) in registered.items():
                self._callback(methods[method], creation, line)
            self._parameters(cls)
        self._fields()
        self._init_order()
        return self.found

    def _callback(self, func: ast.FunctionDef | ast.AsyncFunctionDef, creation: str, registered: int) -> None:
        for node in ast.walk(func):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) and node.func.attr == "call_async":
                line = node.func.end_lineno or node.lineno
                self.edit("sync_call", line, ".call_async(", ".call(", "ROS101", [line],
                          f"call_async -> call in callback {func.name}")
                break
        args = func.args
        if args.vararg or args.kwonlyargs or args.defaults or args.kwarg or args.posonlyargs:
            return
        params, line = [a.arg for a in args.args], func.lineno
        if creation == "create_timer" and params == ["self"]:
            old = f"def {func.name}(self)"
            self.edit("cb_arity", line, old, f"def {func.name}(self, event)", "ROS103", [line, registered],
                      f"timer callback {func.name} takes an event")
            self.edit("neg_cb_default", line, old, f"def {func.name}(self, event=None)", "", [],
                      f"timer callback {func.name} takes an optional event")
        elif creation == "create_subscription" and len(params) == 2:
            self.edit("cb_arity", line, f"def {func.name}(self, {params[1]})", f"def {func.name}(self)",
                      "ROS103", [line, registered], f"subscription callback {func.name} takes no message")
        elif creation == "create_service" and len(params) == 3:
            self.edit("cb_arity", line, f"def {func.name}(self, {params[1]}, {params[2]})",
                      f"def {func.name}(self, {params[1]})", "ROS103", [line, registered],
                      f"service callback {func.name} takes no response")

    def _parameters(self, cls: ast.ClassDef) -> None:
        declared, reads = set(), []
        for node in ast.walk(cls):
            name = _call_name(node)
            first = _text(node.args[0]) if name and node.args else None
            if name == "declare_parameter" and first:
                declared.add(first)
            elif name == "get_parameter" and first:
                reads.append(node)
            elif name in ("__init__", "Node") and any(
                    kw.arg in ("allow_undeclared_parameters", "automatically_declare_parameters_from_overrides")
                    for kw in node.keywords):
                return
        for read in reads:
            name = read.args[0].value
            typo = name[:-2] + name[-1]
            if name in declared and len(name) >= 4 and typo not in declared:
                quote = self.lines[read.args[0].lineno - 1][read.args[0].col_offset]
                self.edit("param_typo", read.args[0].lineno, f"{quote}{name}{quote}", f"{quote}{typo}{quote}",
                          "ROS102", [read.args[0].lineno], f"get_parameter({name!r}) misspelt {typo!r}")
                return

    def _fields(self) -> None:
        classes = {alias.asname or alias.name: node.module.split(".")[0]
                   for node in ast.walk(self.tree)
                   if isinstance(node, ast.ImportFrom) and node.module and node.module.endswith(".msg")
                   for alias in node.names}
        classes = {name: package for name, package in classes.items() if package in self.known_packages}
        for func in (n for n in ast.walk(self.tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))):
            made = {st.targets[0].id: st.value.func.id for st in ast.walk(func)
                    if isinstance(st, ast.Assign) and len(st.targets) == 1 and isinstance(st.targets[0], ast.Name)
                    and isinstance(st.value, ast.Call) and isinstance(st.value.func, ast.Name)
                    and st.value.func.id in classes}
            seeded = set()
            for st in ast.walk(func):
                target = st.targets[0] if isinstance(st, ast.Assign) and len(st.targets) == 1 else None
                if not (isinstance(target, ast.Attribute) and isinstance(target.value, ast.Name)
                        and target.value.id in made and target.value.id not in seeded and len(target.attr) > 3):
                    continue
                seeded.add(target.value.id)
                line, old = target.end_lineno or target.lineno, f"{target.value.id}.{target.attr} ="
                typo = target.attr[:-2] + target.attr[-1]
                self.edit("field_typo", line, old, f"{target.value.id}.{typo} =", "ROS107", [line],
                          f"{made[target.value.id]} field {target.attr} misspelt {typo}")
                value = st.value
                if isinstance(value, ast.Constant) and type(value.value) is float and value.value.is_integer() \
                        and value.lineno == value.end_lineno:
                    written = self.lines[value.lineno - 1][value.col_offset:value.end_col_offset]
                    if written.endswith(".0"):
                        self.edit("field_int", value.lineno, f"{old} {written}", f"{old} {written[:-2]}",
                                  "ROS107", [value.lineno], f"an int written to float field {target.attr}")

    def _init_order(self) -> None:
        for func in (n for n in self.tree.body if isinstance(n, ast.FunctionDef) and n.name == "main"):
            for first, second in zip(func.body, func.body[1:]):
                init = isinstance(first, ast.Expr) and isinstance(first.value, ast.Call) \
                    and isinstance(first.value.func, ast.Attribute) and first.value.func.attr == "init" \
                    and isinstance(first.value.func.value, ast.Name) and first.value.func.value.id == "rclpy"
                maker = _call_name(second.value) if isinstance(second, ast.Assign) else None
                if init and maker and (maker[0].isupper() or maker == "create_node") \
                        and first.lineno == first.end_lineno and second.lineno == second.end_lineno:
                    a, b = self.lines[first.lineno - 1].strip(), self.lines[second.lineno - 1].strip()
                    digest = hashlib.sha1(f"{self.repo}:{self.rel}:{first.lineno}".encode()).hexdigest()[:8]
                    self.found.append(Mutant(f"init_order-{digest}", self.repo, "init_order", self.rel,
                                             first.lineno, a, b, "ROS105", [first.lineno, second.lineno],
                                             "rclpy.init() after the node is made"))
                    return


def _known_packages(root: Path) -> set[str]:
    """The message packages whose definitions the tool has: the shipped ones and the repository's."""
    known = {key.split("/", 1)[0] for key in standard_catalogue().messages}
    known |= {p.parent.parent.name for p in root.rglob("*.msg") if p.parent.name == "msg"}
    return known


def make(corpus: Path, out: Path, cap: int, seed: int) -> list[Mutant]:
    """Up to ``cap`` mutants of each kind, taken round-robin over the repositories."""
    found: dict[str, dict[str, list[Mutant]]] = {}
    for root in sorted(p for p in corpus.iterdir() if p.is_dir()):
        known = _known_packages(root)
        for path in _python_files(root):
            try:
                text = path.read_text(encoding="utf-8")
                if "flake8: noqa" in text:
                    continue  # the file opts out of flake8: nothing it says is reported
                mutants = Seeder(root.name, path.relative_to(root).as_posix(), text, known).seed()
            except (SyntaxError, UnicodeDecodeError, ValueError, OSError):
                continue
            for mutant in mutants:
                found.setdefault(mutant.kind, {}).setdefault(mutant.repo, []).append(mutant)
    rng = random.Random(seed)
    kept: list[Mutant] = []
    for kind in sorted(found):
        repos = found[kind]
        for mutants in repos.values():
            rng.shuffle(mutants)
        depth, picked = 0, []
        while len(picked) < cap and any(len(m) > depth for m in repos.values()):
            picked += [repos[r][depth] for r in sorted(repos) if len(repos[r]) > depth][:cap - len(picked)]
            depth += 1
        kept += picked
    kept.sort(key=lambda m: m.id)
    out.write_text("".join(json.dumps(asdict(m)) + "\n" for m in kept), encoding="utf-8")
    return kept


def findings(tool: str, root: Path, cache: Path) -> set[tuple[str, int, str, str]]:
    done = subprocess.run([tool, "check", ".", "--format", "json", "--root", ".", "--cache-dir", str(cache)],
                          cwd=root, capture_output=True, text=True, timeout=900)
    try:
        items = json.loads(done.stdout)["findings"]
    except (ValueError, KeyError, TypeError):
        print(f"{root}: no findings read: {done.stderr[-300:]}", file=sys.stderr)
        return set()
    return {(f["path"], f["line"], f["code"], f["message"]) for f in items}


def apply(root: Path, mutant: Mutant) -> None:
    path = root / mutant.file
    with path.open(encoding="utf-8", newline="") as file:
        lines = split_lines(file.read())
    if mutant.kind == "init_order":
        a, b = mutant.lines
        first, second = lines[a - 1], lines[b - 1]
        indent = first[:len(first) - len(first.lstrip())]
        end_a, end_b = first[len(first.rstrip("\r\n")):], second[len(second.rstrip("\r\n")):]
        lines[a - 1], lines[b - 1] = indent + second.strip() + end_a, indent + first.strip() + end_b
    elif lines[mutant.line - 1].count(mutant.old) == 1:
        lines[mutant.line - 1] = lines[mutant.line - 1].replace(mutant.old, mutant.new)
    else:
        raise ValueError(f"{mutant.id}: the file changed since the mutant was made")
    path.write_text("".join(lines), encoding="utf-8", newline="")


def run(corpus: Path, mutants: list[Mutant], out: Path, tool: str) -> list[dict]:
    results, clean, caches = [], {}, {}
    work = Path(tempfile.mkdtemp(prefix="seed-misuse-"))
    try:
        for mutant in mutants:
            root = corpus / mutant.repo
            if mutant.repo not in clean:
                clean[mutant.repo] = findings(tool, root, work / f"{mutant.repo}-clean")
                caches[mutant.repo] = work / mutant.repo
            path = root / mutant.file
            original = path.read_bytes()
            try:
                apply(root, mutant)
                new = findings(tool, root, caches[mutant.repo]) - clean[mutant.repo]
            finally:
                path.write_bytes(original)
            if mutant.kind == "init_order":  # the two lines swapped: so did their clean findings
                a, b = mutant.lines
                moved = {(p, {a: b, b: a}.get(n, n) if p == mutant.file else n, c, m)
                         for p, n, c, m in clean[mutant.repo]}
                new -= moved
            at = [f for f in new if f[2] == mutant.expect and f[0] == mutant.file and f[1] in mutant.lines]
            masked = any(f[2] == mutant.expect and f[0] == mutant.file and f[1] in mutant.lines
                         for f in clean[mutant.repo]) if mutant.expect else False
            results.append({**asdict(mutant), "detected": bool(at), "masked": masked,
                            "new": [list(f) for f in sorted(new)]})
    finally:
        shutil.rmtree(work, ignore_errors=True)
    out.write_text("".join(json.dumps(r) + "\n" for r in results), encoding="utf-8")
    return results


def summary(results: list[dict]) -> str:
    rows = {}
    for r in results:
        row = rows.setdefault(r["kind"], [0, 0, 0, 0])
        row[0] += 1
        row[1] += r["detected"]
        row[2] += r["masked"]
        row[3] += bool(r["new"]) and not r["expect"]
    return "\n".join(f"{kind:16s} {n:4d} mutants  {d:4d} detected  {m:3d} masked  {f:3d} false alarms"
                     for kind, (n, d, m, f) in sorted(rows.items()))


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="command", required=True)
    made = sub.add_parser("make")
    made.add_argument("corpus", type=Path)
    made.add_argument("mutants", type=Path)
    made.add_argument("--cap", type=int, default=30, help="mutants of each kind at most")
    made.add_argument("--seed", type=int, default=7)
    ran = sub.add_parser("run")
    ran.add_argument("corpus", type=Path)
    ran.add_argument("mutants", type=Path)
    ran.add_argument("results", type=Path)
    ran.add_argument("--tool", default="flake8-rosgraph")
    args = parser.parse_args(argv)
    if args.command == "make":
        print(f"{len(make(args.corpus, args.mutants, args.cap, args.seed))} mutants -> {args.mutants}")
        return 0
    mutants = [Mutant(**json.loads(line)) for line in args.mutants.read_text(encoding="utf-8").splitlines()]
    print(summary(run(args.corpus, mutants, args.results, args.tool)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
