"""pytest's fixtures: the values pytest passes to the functions it calls itself.

pytest calls the ``test*`` functions of a test module (``test_*.py``, ``*_test.py``) and
the fixtures they need: for each parameter it passes the value of the fixture of that
name, the function decorated with ``@pytest.fixture`` (or ``fixture`` imported from
pytest; ``name=`` renames it) — what it returns or, for a generator fixture, what it
yields. A fixture is looked up in the test's own module first, then in the ``conftest.py``
of its folder and of each folder above. A parameter that ``@pytest.mark.parametrize``
names gets the listed values instead (known when literals are listed for it alone), and a
name no fixture of the workspace defines (a plugin's, pytest's own ``request``) stays unknown.

This module only finds, syntactically, which fixture function each parameter names; the
interpreter reads the fixture's value from the heap, and runs the test only once every
fixture it takes has a value (see ``Interpreter.run_task``, ``Interpreter.fixture_value``).
"""
from __future__ import annotations

import ast
import posixpath
from typing import Callable

from .program import Class, Function, Module, Program
from .values import TOP, FuncAtom, Record, Value, atoms, const

#: Files pytest collects tests from, and the files that share fixtures with a folder.
CONFTEST = "conftest.py"


def is_test_file(path: str) -> bool:
    name = posixpath.basename(path)
    return name == CONFTEST or (name.endswith(".py") and (
        name.startswith("test_") or name[:-3].endswith("_test")))


#: What pytest calls on an instance of a test class besides its ``test*`` methods.
CLASS_HOOKS = ("setup_class", "setup_method", "setup", "teardown_method", "teardown", "teardown_class")


def is_test_class(klass: Class) -> bool:
    """Whether pytest collects ``klass``: a top-level ``Test…`` class of a test module
    without an ``__init__`` of its own (pytest skips those); it instantiates it and runs its
    ``test*`` methods (static or not) between the :data:`CLASS_HOOKS`."""
    return klass.parent is None and klass.node.name.startswith("Test") \
        and "__init__" not in klass.methods and is_test_file(klass.module.path) \
        and posixpath.basename(klass.module.path) != CONFTEST


def test_class_calls(klass: Class, names: set[str]) -> list[str]:
    """The methods (of ``names``, the class's and its bases') pytest calls on a test class."""
    return sorted(n for n in names if n.startswith("test") or n in CLASS_HOOKS)


class Fixtures:
    """Which workspace fixture function each parameter of a pytest-called function names."""

    def __init__(self, program: Program) -> None:
        self.program = program
        self._by_path: dict[str, str] | None = None       # module path -> module name
        self._defined: dict[str, dict[str, int]] = {}     # module name -> fixture name -> fid
        self._visible: dict[str, dict[str, int]] = {}     # module name -> fixtures it sees

    def arguments(self, func: Function) -> dict[str, int]:
        """Parameter name -> fid of the fixture pytest passes for it, for a function pytest
        calls (a module-level ``test*`` function or fixture of a test file, or a ``test*``
        function a factory defines: see :meth:`_made_test`); empty otherwise."""
        if not self._called_by_pytest(func):
            return {}
        visible = self._visible_in(func.module)
        a = func.node.args
        params = [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]
        given = _parametrized(func.node)
        return {name: visible[name] for name in params if name in visible and name not in given}

    def listed_values(self, func: Function) -> dict[str, list[Value]]:
        """Parameter name -> the values ``@pytest.mark.parametrize('name', [...])`` lists for
        it, for a function pytest calls: it runs the function once with each (once with each
        combination, for several such decorators). Only a decorator naming one parameter and
        listing literals counts; values listed in rows for several parameters stay unknown."""
        if not self._called_by_pytest(func):
            return {}
        out: dict[str, list[Value]] = {}
        for decorator in func.node.decorator_list:
            found = _listed(decorator)
            if found is not None:
                out[found[0]] = [const(v) for v in found[1]]
        return out

    def _called_by_pytest(self, func: Function) -> bool:
        if isinstance(func.node, ast.Lambda) or func.cls is not None:
            return False
        if func.parent is not None:
            if not self._made_test(func):
                return False
        elif not is_test_file(func.module.path):
            return False
        return func.node.name.startswith("test") or func.fid in self._visible_in(func.module).values()

    def _made_test(self, func: Function) -> bool:
        """A ``test*`` function defined inside a function (a factory that hands its tests to
        the test classes of several modules, ``type(name, bases, tests)``), of a module that
        shares fixtures with test files (a ``conftest.py`` above it): pytest runs it as a
        test method, with the fixtures of that folder. Its parameters are looked up only when
        the task left them unknown (a caller of its own passes its values)."""
        return func.node.name.startswith("test") and any(
            posixpath.basename(self.program.modules[c].path) == CONFTEST
            for c in conftests_seen_from(func.module.path, self._module_at))

    def request(self, func: Function) -> Value | None:
        """What pytest passes a test function's ``request`` parameter when no workspace fixture
        of that name exists: its built-in request, whose ``node.originalname`` is the test's
        name (so is ``node.name``, unless ``parametrize`` adds the parameters' ids), and whose
        ``function`` is the test. ``None`` for anything else (a fixture's request depends on
        which test asks for it)."""
        if func.parent is not None or func.cls is not None or isinstance(func.node, ast.Lambda) \
                or not func.node.name.startswith("test") or not is_test_file(func.module.path):
            return None
        a = func.node.args
        if "request" not in {p.arg for p in a.posonlyargs + a.args + a.kwonlyargs} \
                or "request" in self._visible_in(func.module):
            return None
        name = const(func.node.name)
        item = Record("_pytest.python.Function", (
            ("name", TOP if _parametrized(func.node) else name), ("originalname", name)))
        return atoms([Record("_pytest.fixtures.FixtureRequest", (
            ("function", atoms([FuncAtom(func.fid)])), ("node", atoms([item]))))])

    def _visible_in(self, module: Module) -> dict[str, int]:
        known = self._visible.get(module.name)
        if known is None:
            known = {}
            chain = [module.name, *(c for c in conftests_seen_from(module.path, self._module_at)
                                    if c != module.name)]
            for name in reversed(chain):  # the nearest definition wins
                known.update(self._defined_in(name))
            self._visible[module.name] = known
        return known

    def _module_at(self, path: str) -> str | None:
        if self._by_path is None:
            self._by_path = {m.path: m.name for m in self.program.modules.values()}
        return self._by_path.get(path)

    def _defined_in(self, name: str) -> dict[str, int]:
        known = self._defined.get(name)
        if known is None:
            known = {}
            module = self.program.ensure(name)
            for node in module.tree.body if module is not None else ():
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                    fixture = _fixture_name(node, module)
                    fid = self.program.fid_of.get(id(node))
                    if fixture is not None and fid is not None:
                        known[fixture] = fid
            self._defined[name] = known
        return known


def conftests_seen_from(path: str, module_at: Callable[[str], str | None]) -> list[str]:
    """The ``conftest.py`` modules whose fixtures a test file at ``path`` sees, nearest first:
    its folder's, then each folder's above (``module_at``: the module of a path, if any)."""
    found: list[str] = []
    folder = posixpath.dirname(path)
    while True:
        conftest = module_at(posixpath.join(folder, CONFTEST) if folder else CONFTEST)
        if conftest is not None and conftest not in found:
            found.append(conftest)
        if not folder:
            return found
        folder = posixpath.dirname(folder)


def _fixture_name(node: ast.FunctionDef | ast.AsyncFunctionDef, module: Module) -> str | None:
    """The name a ``@pytest.fixture`` decorator gives the function, else ``None``."""
    for decorator in node.decorator_list:
        call = decorator if isinstance(decorator, ast.Call) else None
        target = call.func if call is not None else decorator
        if _names_pytest_fixture(target, module):
            for kw in call.keywords if call is not None else ():
                if kw.arg == "name" and isinstance(kw.value, ast.Constant) \
                        and isinstance(kw.value.value, str):
                    return kw.value.value
            return node.name
    return None


def _names_pytest_fixture(expr: ast.expr, module: Module) -> bool:
    if isinstance(expr, ast.Attribute):
        return expr.attr == "fixture" and isinstance(expr.value, ast.Name) \
            and expr.value.id == "pytest"
    if isinstance(expr, ast.Name):
        return any(isinstance(stmt, ast.ImportFrom) and stmt.module == "pytest" and any(
            alias.name == "fixture" and (alias.asname or alias.name) == expr.id
            for alias in stmt.names) for stmt in module.tree.body)
    return False


def _listed(decorator: ast.expr) -> tuple[str, list] | None:
    """``(parameter, values)`` of ``@pytest.mark.parametrize('name', [literal, …])``."""
    if not (isinstance(decorator, ast.Call) and isinstance(decorator.func, ast.Attribute)
            and decorator.func.attr == "parametrize" and len(decorator.args) == 2
            and not any(k.arg == "indirect" for k in decorator.keywords)):
        return None
    first, rows = decorator.args
    if not (isinstance(first, ast.Constant) and isinstance(first.value, str)
            and first.value.strip().isidentifier()) or not isinstance(rows, (ast.List, ast.Tuple)):
        return None
    values = []
    for row in rows.elts:
        if not isinstance(row, ast.Constant) or not isinstance(row.value, (str, int, float, bool, type(None))):
            return None
        values.append(row.value)
    return (first.value.strip(), values) if values else None


def _parametrized(node: ast.FunctionDef | ast.AsyncFunctionDef) -> frozenset[str]:
    """Parameters ``@pytest.mark.parametrize("a, b", …)`` gives values to."""
    names: set[str] = set()
    for decorator in node.decorator_list:
        if isinstance(decorator, ast.Call) and isinstance(decorator.func, ast.Attribute) \
                and decorator.func.attr == "parametrize" and decorator.args:
            first = decorator.args[0]
            if isinstance(first, ast.Constant) and isinstance(first.value, str):
                names.update(n.strip() for n in first.value.split(","))
            elif isinstance(first, (ast.List, ast.Tuple)):
                names.update(e.value for e in first.elts
                             if isinstance(e, ast.Constant) and isinstance(e.value, str))
    return frozenset(names)
