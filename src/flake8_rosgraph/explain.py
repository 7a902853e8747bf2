"""What the graph is missing, and why: the report behind ``flake8-rosgraph graph --explain``.

A *creation site* is a call in the workspace to a callable the stubs declare as creating
something of the graph (a node, publisher, subscription, service, client, timer, action
server or client): its method or function name, or its class name for constructors, is
read from the loaded :class:`LibraryModel`, never from a list here.  Each site is compared,
by location, with the effects the analysis produced and the graph built from them.  A site
that is absent, or present with an unknown name, type or node, gets the reasons the
analysis recorded, in words: whether its module was analysed at all, whether its function
was ever called (or its class instantiated), whether the call was reached, whether a
budget stopped the analysis there, which workspace imports of its module did not resolve,
and where the unknown name comes from in the code.

Sites are found syntactically, so a call the stubs cannot see (through ``getattr`` or an
alias of the method) is not listed; a method name is matched on any receiver, so an
unrelated class with a method of the same name is listed as "not reached".
"""
from __future__ import annotations

import ast
import re
from dataclasses import dataclass
from typing import Iterable, Sequence

from .absint.engine import Analysis, Effect
from .absint.fixtures import Fixtures
from .absint.values import BOTTOM, Obj
from .absint.library import FunctionModel, LibraryModel
from .absint.objects import analysed_unresolved_base, analysed_user_bases
from .absint.passed_in import passed_in_parameter
from .absint.program import Function, Module, Program
from .graph.builder import ENTITY_KINDS, unpaired_types
from .graph.model import NAMED_KINDS, Entity, RosGraph
from .graph.parameter_switches import switched_off

#: Effect kinds that put something in the graph a user looks for (parameters are listed
#: by their own declarations and are not creation sites).
CREATION_KINDS = frozenset(ENTITY_KINDS) | {"node", "timer"}


@dataclass(frozen=True, order=True)
class Site:
    """One creation call in the workspace source."""

    path: str
    line: int
    column: int          # 1-based character column, as graph locations
    call: str            # the callable as written (``self.create_publisher``, ``Node``)


@dataclass(frozen=True, order=True)
class Explanation:
    site: Site
    status: str                  # "missing" | "unknown" | "complete"
    reasons: tuple[str, ...]

    def line(self) -> str:
        what = "not in the graph" if self.status == "missing" else "in the graph with " + \
            "; ".join(r for r in self.reasons if r.startswith("unknown "))
        why = [r for r in self.reasons if not r.startswith("unknown ")]
        text = f"{self.site.path}:{self.site.line}:{self.site.column}: {self.site.call}: {what}"
        return text + (": " + "; ".join(why) if why else "")


@dataclass(frozen=True)
class Report:
    explanations: tuple[Explanation, ...]

    @property
    def sites(self) -> int:
        return len(self.explanations)

    @property
    def complete(self) -> int:
        return sum(e.status == "complete" for e in self.explanations)

    def gaps(self) -> list[Explanation]:
        return [e for e in self.explanations if e.status != "complete"]

    def summary(self) -> str:
        missing = sum(e.status == "missing" for e in self.explanations)
        unknown = sum(e.status == "unknown" for e in self.explanations)
        share = f" ({100 * self.complete / self.sites:.0f}%)" if self.sites else ""
        return (f"creation sites: {self.sites}, in the graph and fully known: "
                f"{self.complete}{share}, with unknowns: {unknown}, not in the graph: {missing}")


@dataclass(frozen=True)
class _Callables:
    """Names of creation callables, read from the library model."""

    methods: frozenset[str]            # method names on library classes (not constructors)
    qualnames: frozenset[str]          # functions and classes whose call creates something
    constructors: frozenset[str]       # classes whose ``__init__`` creates something


def creation_callables(library: LibraryModel) -> _Callables:
    def creates(effects) -> bool:
        return any(e.kind in CREATION_KINDS for e in effects)

    methods, qualnames, ctors = set(), set(), set()
    for name, fn in library.functions.items():
        if creates(fn.effects):
            qualnames.add(name)
    for cls_name, cls in library.classes.items():
        for meth_name, meth in cls.methods.items():
            if creates(meth.effects):
                if meth_name == "__init__":
                    ctors.add(cls_name)
                else:
                    methods.add(meth_name)
    return _Callables(frozenset(methods), frozenset(qualnames | ctors), frozenset(ctors))


def explain(analyses: Sequence[Analysis], graph: RosGraph) -> Report:
    """Every creation site of the analysed workspace with its status and reasons: each group of
    modules (see :meth:`.Program.components`) explained from its own analysis."""
    return Report(tuple(sorted({item for analysis in analyses
                                for item in _Explainer(analysis, graph).run().explanations})))


class _Explainer:
    def __init__(self, analysis: Analysis, graph: RosGraph) -> None:
        self.an = analysis
        self.program: Program = analysis.program
        self.library = analysis.library
        self.callables = creation_callables(self.library)
        self._subclasses: dict[int, list[int]] | None = None
        self._class_ids: dict[int, int] | None = None  # id(ClassDef) -> cid, built when needed
        self._fixtures: Fixtures | None = None
        self.effects: dict[tuple[str, int, int], list[Effect]] = {}
        for eff in analysis.all_effects():
            if eff.kind in CREATION_KINDS and not switched_off(eff):
                self.effects.setdefault((eff.path, eff.line, eff.column), []).append(eff)
        self.wrappers = _workspace_only_calls(analysis)
        self.reached = frozenset().union(*analysis.reached_calls.values())
        #: Sites whose effects come from a task the budget abandoned (their names are made
        #: unknown), with the functions (or module top levels) those tasks ran.
        self.abandoned: dict[tuple[str, int, int], set[str]] = {}
        self.abandoned_functions = {task[1] for task in analysis.abandoned if task[0] == "fn"}
        for task in analysis.abandoned:
            for eff in analysis.effects.get(task, {}).values():
                self.abandoned.setdefault((eff.path, eff.line, eff.column), set()).add(
                    self.program.functions[task[1]].qualname if task[0] == "fn"
                    else f"module {task[1]}")
        self.graph_nodes: dict[tuple, list] = {}
        self.graph_entities: dict[tuple, list] = {}
        for node in graph.nodes:
            loc = node.location
            self.graph_nodes.setdefault((loc.path, loc.line, loc.column), []).append(node)
            for ent in node.entities:
                loc = ent.location
                self.graph_entities.setdefault((loc.path, loc.line, loc.column), []).append(
                    (node, ent))

    def run(self) -> Report:
        out: list[Explanation] = []
        for name in sorted(self.program.modules):
            module = self.program.modules[name]
            out.extend(self._module(module))
        return Report(tuple(sorted(set(out))))

    # -- finding sites ------------------------------------------------------------------
    def _module(self, module: Module) -> Iterable[Explanation]:
        imports = _import_bindings(self.program, module)
        unresolved = _unresolved_workspace_imports(self.program, module)
        for call, scope, klass in _calls_with_scope(module.tree):
            found = self._creation_call(call, klass, imports)
            if found is None:
                continue
            site = Site(module.path, call.lineno, module.column(call), found[0])
            key = (site.path, site.line, site.column)
            if key in self.wrappers and key not in self.effects:
                continue  # the workspace's own ``create_*``: the library call inside it is the site
            yield self._explain(site, found[1], module, call, scope, unresolved)

    def _creation_call(self, call: ast.Call, klass: ast.ClassDef | None,
                       imports: dict[str, str]) -> tuple[str, FunctionModel | None] | None:
        """``(label, model)`` when ``call`` creates something: a modelled function or class
        named through the module's imports, a creation method on any receiver, or the
        ``__init__`` of a modelled base class called from a subclass."""
        func = call.func
        dotted = _dotted(func)
        if self._in_workspace(dotted, imports):
            return None  # the workspace's own code: its creation calls are sites themselves
        qual = self._resolve(dotted, imports)
        if qual in self.callables.qualnames:
            model = self.library.functions.get(qual) or self.library.method(qual, "__init__")
            if model is not None and not _may_create(call, model):
                return None
            return dotted, model
        if isinstance(func, ast.Attribute):
            if func.attr in self.callables.methods:
                if self._own_method(func, klass):
                    return None  # a wrapper of the workspace's own: the call inside it is the site
                return _label(func), self._method_model(func.attr)
            if func.attr == "__init__" and klass is not None and _is_super_call(func.value, klass):
                for base in klass.bases:
                    qual = self._resolve(_dotted(base), imports)
                    if qual and any(c in self.callables.constructors for c in self.library.mro(qual)):
                        return _label(func), self.library.method(qual, "__init__")
        return None

    def _own_method(self, func: ast.Attribute, klass: ast.ClassDef | None) -> bool:
        """Whether ``self.<name>`` in ``klass`` calls a method the workspace defines on the class
        or a workspace base class (a plugin's ``create_client`` forwarding to its node's)."""
        if klass is None or not isinstance(func.value, ast.Name) or func.value.id not in ("self", "cls"):
            return False
        if self._class_ids is None:
            self._class_ids = {id(c.node): c.cid for c in self.program.classes}
        todo, seen = [self._class_ids.get(id(klass))], set()
        while todo:
            cid = todo.pop()
            if cid is None or cid in seen:
                continue
            seen.add(cid)
            if func.attr in self.program.classes[cid].methods:
                return True
            todo.extend(analysed_user_bases(self.an.heap, cid))
        return False

    def _in_workspace(self, dotted: str | None, imports: dict[str, str]) -> bool:
        head, _, _ = (dotted or "").partition(".")
        parts = imports.get(head, "").split(".")
        return any(".".join(parts[:i]) in self.program.modules for i in range(1, len(parts) + 1))

    def _resolve(self, dotted: str | None, imports: dict[str, str]) -> str | None:
        head, _, rest = (dotted or "").partition(".")
        if head not in imports:
            return None
        return self.library.canonical(imports[head] + ("." + rest if rest else ""))

    def _method_model(self, name: str) -> FunctionModel | None:
        for cls_name in sorted(self.library.classes):
            meth = self.library.classes[cls_name].methods.get(name)
            if meth is not None and meth.effects:
                return meth
        return None

    # -- explaining one site --------------------------------------------------------------
    def _explain(self, site: Site, model: FunctionModel | None, module: Module, call: ast.Call,
                 scope: ast.AST | None, unresolved: list[str]) -> Explanation:
        key = (site.path, site.line, site.column)
        effects = self.effects.get(key)
        if not effects:
            reasons = self._why_not_created(module, call, scope)
            if unresolved:
                reasons.append("imports not resolved in the workspace: " + ", ".join(unresolved))
            return Explanation(site, "missing", tuple(reasons))
        unknowns = self._unknowns(key, effects)
        if unknowns is None:
            return Explanation(site, "missing", (
                *(self._passed_in_reasons(effects)
                  or ["the object it is created on is not known to be a node here"]),
                *self._origin_reasons(call, scope, _node_argument(call), module),))
        func = self._function_of(scope)
        if not unknowns:
            if func is not None and self._overflowed(func):
                # The calls past the bound ran with unknown arguments: what they create on
                # another node or under another name is not in the graph, whatever this shows.
                return Explanation(site, "unknown", (
                    "unknown entities of some calls", f"{func.qualname} is called in more than "
                    f"{self.an.context_bound(func.fid)} different ways; the further calls were analysed "
                    "with unknown arguments and what they create is not in the graph"))
            return Explanation(site, "complete", ())
        reasons = list(unknowns)
        stopped = self._stopped_reason(key)
        if stopped:  # every constant of the effect was made unknown: no other reason holds
            return Explanation(site, "unknown", (*unknowns, stopped))
        for unknown in unknowns:
            field = unknown.removeprefix("unknown ").split(" ")[0]
            if field == "node":
                reasons.extend(self._presumed_reasons(key))
                continue
            found = self._owner_reasons(key) + self._parameter_reasons(key) if field == "name" \
                else _unpaired_reasons(effects) if field == "type" else []
            if not found:  # the written value itself is unknown
                param, argument = self._field_argument(call, model, effects, field)
                found = self._origin_reasons(call, scope, argument, module)
                if param is not None and argument is None:
                    found = [f"`{param}` is not passed: {model.qualname} chooses the {field} "
                             "when it runs"]
            reasons.extend(found)
        if func is not None and self._overflowed(func):
            reasons.append(f"{func.qualname} is called in more than "
                           f"{self.an.context_bound(func.fid)} different ways and was "
                           "also analysed with unknown arguments")
        if unresolved:
            reasons.append("imports not resolved in the workspace: " + ", ".join(unresolved))
        return Explanation(site, "unknown", tuple(dict.fromkeys(reasons)))

    def _unknowns(self, key: tuple, effects: list[Effect]) -> list[str] | None:
        """What the graph leaves unknown at the site; ``None`` if nothing reached the graph."""
        kinds = {e.kind for e in effects}
        out: list[str] = []
        if "node" in kinds:
            nodes = self.graph_nodes.get(key, [])
            if not nodes:
                return None
            if any(n.name is None for n in nodes):
                out.append("unknown name")
            if any(n.namespace is None for n in nodes):
                out.append("unknown namespace")
        if kinds - {"node"}:
            found = self.graph_entities.get(key, [])
            if not found:
                return None
            if any(e.kind != "timers" and e.name is None for _, e in found):
                out.append("unknown name" + _partly_known(e for _, e in found))
            if any(e.kind in NAMED_KINDS and e.type is None for _, e in found):  # typed kinds only
                out.append("unknown type")
            if any(n.unresolved_base or n.passed_in for n, _ in found):
                out.append("unknown node")
        return out

    def _parameter_reasons(self, key: tuple) -> list[str]:
        """Unknown names that are a parameter of their node with no default in code that reaches
        the call (none declared, or one a branch rules out: ``if prefix:`` past a default of ``''``)."""
        found = self.graph_entities.get(key, [])
        parameters = sorted({e.name_parameters for _, e in found
                             if e.name is None and e.name_parameters})
        # Known on some paths (declared with a default inside ``try``): not on all of them.
        where = " on some paths" if any(e.partial for _, e in found) else ""
        return [f"it is built from ROS {_plural(len(p), 'parameter')} {', '.join(repr(n) for n in p)} "
                f"of its node, with no default in code that reaches this call{where}; "
                "where a launch file sets them, `graph --launch FILE` shows the name"
                for p in parameters]

    def _why_not_created(self, module: Module, call: ast.Call, scope: ast.AST | None) -> list[str]:
        if ("mod", module.name, ()) not in self.an.effects:
            if module.name not in self.an.relevant:
                roots = ", ".join(sorted(self.library.active_roots()))
                return [f"module {module.name} is not analysed: it imports no modelled library "
                        f"({roots}) directly or through the workspace"]
            return [f"module {module.name} is not analysed (the analysis budget ran out first)"]
        func = self._function_of(scope)
        if func is not None and func.fid not in self.an.called:
            return [self._never_called(func)]
        where = (module.path, call.lineno, call.col_offset)
        budget = self._budget_hit(module, scope)
        if budget:
            return [budget]
        if func is not None and func.fid in self.abandoned_functions:
            return [self._stopped(func.qualname, "before it reached this call with a node")]
        if where not in self.reached:
            unset = self._unset_fixtures(func) if func is not None else []
            if unset:
                return [f"pytest runs {func.qualname} with {_plural(len(unset), 'fixture')} "
                        f"{', '.join(f'`{n}`' for n in unset)}, which the analysis never sees "
                        "return or yield a value"]
            return ["the analysis never reaches this line (every path to it goes through a "
                    "branch, exception or call the analysis decided cannot get here)"]
        receiver = call.func.value if isinstance(call.func, ast.Attribute) else call.func
        on_self = func is not None and func.cls is not None and isinstance(receiver, ast.Name) \
            and receiver.id == "self"
        reasons = [f"`{_short(receiver)}` is not known to be a modelled library object here"]
        stand_in = self.library.stand_in(call.func.attr) if on_self else None
        model = self.library.method(stand_in.owner, call.func.attr) if stand_in else None
        base = analysed_unresolved_base(self.an.heap, self.library, func.cls) if model else None
        if base is not None:
            reasons.append(f"the base class {base} is not resolved (imported from a library no stub "
                           f"models), and this call does not have the shape of {model.qualname} "
                           "(its arguments' number, names and kinds)")
        return reasons + self._origin_reasons(call, scope, receiver, module)

    def _unset_fixtures(self, func: Function) -> list[str]:
        """The pytest fixtures ``func`` takes whose function never produced a value."""
        if self._fixtures is None:
            self._fixtures = Fixtures(self.program)
        out = []
        for name, fid in sorted(self._fixtures.arguments(func).items()):
            if self.program.functions[fid].is_generator:
                produced = not self.an.heap.get(("yield", fid), BOTTOM).is_bottom
            else:
                produced = any(task[0] == "fn" and task[1] == fid and not self.an.returns(task).is_bottom
                               for task in self.an.effects)
            if not produced:
                out.append(name)
        return out

    def _never_called(self, func: Function) -> str:
        if isinstance(func.node, ast.Lambda):
            return f"the lambda in {func.qualname.rpartition('.')[0] or 'module'} is never called"
        if func.cls is not None:
            klass = self.program.classes[func.cls]
            if not self._instantiated(klass.cid):
                if any((_dotted(b) or "").endswith("TestCase") for b in klass.node.bases):
                    return (f"class {klass.qualname} is a test case: the test runner "
                            "instantiates it, analysed code never does")
                return (f"class {klass.qualname} is never instantiated by analysed code (nor "
                        "registered as a node entry point)")
            return f"method {func.qualname} is never called from any entry point"
        if func.parent is not None:
            return f"nested function {func.qualname} is never called"
        return f"function {func.qualname} is never called from any entry point"

    def _instantiated(self, cid: int) -> bool:
        """Whether analysed code instantiates the class or a subclass of it."""
        if self._subclasses is None:
            self._subclasses = {}
            for klass in self.program.classes:
                for base in analysed_user_bases(self.an.heap, klass.cid):
                    self._subclasses.setdefault(base, []).append(klass.cid)
        todo, seen = [cid], set()
        while todo:
            cur = todo.pop()
            if cur in seen:
                continue
            seen.add(cur)
            if cur in self.an.allocated:
                return True
            todo.extend(self._subclasses.get(cur, ()))
        return False

    def _overflowed(self, func: Function) -> bool:
        line = getattr(func.node, "lineno", 1)
        return any(d.path == func.module.path and d.line == line and "different ways" in d.message
                   for d in self.an.diagnostics)

    def _budget_hit(self, module: Module, scope: ast.AST | None) -> str | None:
        first = getattr(scope, "lineno", 1)
        last = getattr(scope, "end_lineno", None) or 10 ** 9
        for diag in self.an.diagnostics:
            if diag.path == module.path and first <= diag.line <= last \
                    and ("stopped" in diag.message or "too deeply" in diag.message):
                return "budget hit: " + diag.message
            if diag.path == "" and "budget" in diag.message:
                return "budget hit: " + diag.message
        return None

    def _stopped_reason(self, key: tuple) -> str | None:
        """The budget stopped the analysis of the code that made the site's entity before its
        values were final: the graph keeps the entity with its names unknown."""
        ran = self.abandoned.get(key)
        if not ran:
            return None
        return self._stopped(_some_code(ran), "before its values were final, so the names it "
                                              "creates are unknown")

    def _stopped(self, code: str, what: str) -> str:
        where = sorted({f"{d.path}:{d.line}" for d in self.an.diagnostics if " stopped: " in d.message})
        return (f"the analysis of {code} was stopped by its budget {what}"
                + (f" (see the warning at {', '.join(where)})" if where else ""))

    def _function_of(self, scope: ast.AST | None) -> Function | None:
        if scope is None:
            return None
        fid = self.program.fid_of.get(id(scope))
        return None if fid is None else self.program.functions[fid]

    def _passed_in_reasons(self, effects: list[Effect]) -> list[str]:
        """Why the node a parameter annotated as a node stands for is not in the graph: analysed
        code calls the function too, with a node it does not know (see :mod:`.absint.passed_in`)."""
        out = []
        for eff in effects:
            for obj in eff.arg("node"):
                found = passed_in_parameter(obj.site) if isinstance(obj, Obj) else None
                if found is not None:
                    out.append(f"it is created on parameter `{found[1]}` of "
                               f"{self.program.functions[found[0]].qualname}, a node, which analysed "
                               "code passes without the analysis knowing which node it is")
        return list(dict.fromkeys(out))

    def _presumed_reasons(self, key: tuple) -> list[str]:
        """Why the node of an entity is unknown: its class's base class is not resolved, or it
        is the node a function is handed by callers the analysis does not see."""
        out = []
        for node, _ in self.graph_entities.get(key, []):
            if node.unresolved_base:
                out.append(f"class {node.cls} is presumed to be a node: its base class "
                           f"{node.unresolved_base} is not resolved (imported from a library no "
                           "stub models), so its name and namespace are unknown; a stub for the "
                           "base class gives them")
            elif node.passed_in:
                out.append(f"its node is the {node.passed_in}, annotated as a node, which no "
                           "analysed code calls with a node: its name and namespace are the "
                           "caller's, unknown here")
        return out

    def _owner_reasons(self, key: tuple) -> list[str]:
        """Why a name written in full came out unknown: the node it is relative to."""
        relative, private = set(), set()
        for node, ent in self.graph_entities.get(key, []):
            if node.unresolved_base:
                continue  # said by the "unknown node" reason
            if ent.name is None and ent.raw_name is not None:
                if node.namespace is None:
                    relative.add(ent.raw_name)
                elif node.name is None:
                    private.add(ent.raw_name)
        out = []
        if relative:
            out.append(f"{_some(relative)} relative to the namespace of its node, which is unknown")
        if private:
            out.append(f"{_some(private)} built from the name of its node, which is unknown")
        return out

    @staticmethod
    def _field_argument(call: ast.Call, model: FunctionModel | None, effects: list[Effect],
                        field: str) -> tuple[str | None, ast.expr | None]:
        """The parameter that gives the created thing's ``field`` ("name", "namespace" or
        "type"), as the stub declares it, and the call's argument for it (``None`` when the
        call leaves it to its default)."""
        if model is None:
            return None, None
        for eff in effects:
            arg = ENTITY_KINDS.get(eff.kind, (None, "name"))[1] if field == "name" else field
            for spec in model.effects:
                ref = dict(spec.args).get(arg)
                if spec.kind == eff.kind and ref is not None and ref.how in ("arg", "overridable"):
                    return ref.data, _argument(call, model.signature, ref.data)
                if spec.kind == eff.kind and ref is not None and ref.how == "format":
                    # A name the library builds from parameters (``{node_name}/set_parameters``):
                    # the first of them the call passes is where an unknown part comes from.
                    for param in re.findall(r"\{(\w+)", ref.data):
                        argument = _argument(call, model.signature, param)
                        if argument is not None:
                            return param, argument
        return None, None

    def _star_binding(self, name: str, module: Module) -> str | None:
        """A name the module never binds itself, which only its ``from … import *`` of
        modules outside the workspace can bind: what those give is not known."""
        if name in module.globals or name in self.program.star_names(module):
            return None
        sources = sorted({stmt.module or "" for stmt in module.tree.body
                          if isinstance(stmt, ast.ImportFrom) and stmt.level == 0
                          and any(a.name == "*" for a in stmt.names)
                          and self.program.resolve_import(module, stmt.module, 0) not in self.program.modules})
        if not sources:
            return None
        return (f"`{name}` can only come from `from … import *` of {', '.join(f'`{s}`' for s in sources)}, "
                "outside the workspace: the names it binds are not known")

    def _library_import(self, name: str, module: Module) -> str | None:
        """A name the module imports from outside the workspace (``from tf2_geometry_msgs
        import PointStamped``) that no stub models and that is not an interface module's."""
        for stmt in module.tree.body:
            if not isinstance(stmt, ast.ImportFrom) or stmt.level or not stmt.module:
                continue
            for alias in stmt.names:
                qual = f"{stmt.module}.{alias.name}"
                if (alias.asname or alias.name) != name \
                        or self.program.resolve_import(module, stmt.module, 0) in self.program.modules \
                        or self.library.knows(qual) or stmt.module.split(".")[-1] in ("msg", "srv", "action"):
                    continue
                return (f"`{name}` is imported from `{stmt.module}`, outside the workspace, which no "
                        "stub models: what it is is not known")
        return None

    def _origin_reasons(self, call: ast.Call, scope: ast.AST | None, expr: ast.expr | None,
                        module: Module) -> list[str]:
        """Where the value of ``expr`` comes from, in words (what made it unknown)."""
        if expr is None:
            return []
        out: list[str] = []
        for name in sorted({n.id for n in ast.walk(expr) if isinstance(n, ast.Name)}
                           - {"self", "cls"}):
            binding = _binding_of(name, scope, call) or _module_binding(name, module) \
                or self._star_binding(name, module) or self._library_import(name, module)
            if binding:
                out.append(binding)
        calls = [sub for sub in ast.walk(expr) if isinstance(sub, ast.Call)]
        inner = {id(n) for c in calls for n in ast.walk(c) if n is not c}
        for sub in calls:
            if id(sub) in inner:
                continue  # named by the call around it
            callee = _dotted(sub.func) or ""
            if callee.endswith(("get_parameter", "get_parameter_or", "declare_parameter")):
                out.append("it comes from a ROS parameter (known only at run time)")
            else:
                out.append(f"it is built from `{_short(sub)}`, whose result is not known "
                           "statically")
        if not out:  # attributes only (``f"/{self.namespace}/{self.name}/get_state"``)
            out.extend(f"`{_short(attr)}` holds a value the analysis does not know here"
                       for attr in _outer_attributes(expr))
        return list(dict.fromkeys(out))


# -- syntax helpers ------------------------------------------------------------------------
def _workspace_only_calls(analysis: Analysis) -> frozenset[tuple[str, int, int]]:
    """Places of calls the analysis resolved, on every run that reached them, to workspace
    code only (``api.create_service(...)`` of a wrapper class the workspace defines, held in a
    variable): not creation sites, whatever their method's name."""
    callees: dict[tuple[str, int, int], set[str]] = {}
    graph = analysis.call_graph()
    for task in graph.tasks():
        for call in graph.sites(task):
            callees.setdefault((call.path, call.line, call.column), set()).add(call.callee[0])
    return frozenset(key for key, kinds in callees.items() if kinds == {"task"})


def _calls_with_scope(tree: ast.Module):
    """Every call with its innermost enclosing function (or lambda) and class definition."""
    stack: list[tuple[ast.AST, ast.AST | None, ast.ClassDef | None]] = [(tree, None, None)]
    while stack:
        node, scope, klass = stack.pop()
        if isinstance(node, ast.Call):
            yield node, scope, klass
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                # ``super().__init__`` belongs to the class the method is defined in.
                stack.append((child, child, node if isinstance(node, ast.ClassDef) else None))
            elif isinstance(child, ast.ClassDef):
                stack.append((child, scope, child))
            else:
                stack.append((child, scope, klass))


def _unpaired_reasons(effects: list[Effect]) -> list[str]:
    """A type left unknown because the call has several names and several types, which the
    analysis cannot pair (:func:`~.graph.builder.unpaired_types`)."""
    for eff in effects:
        types = unpaired_types(eff) if eff.kind in ENTITY_KINDS else []
        if types:
            return [f"it is one of {len(types)} types ({', '.join(types)}) and which of its "
                    "names goes with which type is not known"]
    return []


def _some(names: set[str]) -> str:
    """A few names of a set, in order, with the verb: "`a` is", "`a`, `b` (+3 more) are"."""
    first = sorted(names)[:2]
    text = ", ".join(f"`{n}`" for n in first)
    more = len(names) - len(first)
    text += f" (+{more} more)" if more else ""
    return text + (" is" if len(names) == 1 else " are")


def _outer_attributes(expr: ast.expr) -> list[ast.Attribute]:
    """The attribute reads that make up ``expr`` (``self.a`` and ``self.b.c`` in an f-string or
    a sum), outermost first, not those inside another attribute read or a call."""
    out: list[ast.Attribute] = []
    todo: list[ast.AST] = [expr]
    while todo:
        node = todo.pop(0)
        if isinstance(node, ast.Attribute):
            out.append(node)
        elif not isinstance(node, (ast.Call, ast.Lambda)):
            todo.extend(ast.iter_child_nodes(node))
    return out


def _some_code(names: set[str]) -> str:
    """``f`` or ``f``, ``g`` (+N more): the functions or module top levels named."""
    shown = sorted(names)
    text = ", ".join(shown[:2])
    return text + (f" (+{len(shown) - 2} more)" if len(shown) > 2 else "")


def _dotted(expr: ast.AST) -> str | None:
    parts = []
    while isinstance(expr, ast.Attribute):
        parts.append(expr.attr)
        expr = expr.value
    if isinstance(expr, ast.Name):
        return ".".join([expr.id] + parts[::-1])
    return None


def _partly_known(entities: Iterable[Entity]) -> str:
    """`` (known only partly: '/scan' on some paths, unknown on others)`` for a name that is
    an unknown joined with known constants (``param if launched else '/scan'``); empty otherwise."""
    known = sorted({e.name for e in entities if e.partial and e.name is not None})
    if not known:
        return ""
    return " (known only partly: " + " or ".join(f"'{n}'" for n in known) + " on some paths, unknown on others)"


def _label(func: ast.Attribute) -> str:
    return _dotted(func) or _short(func)


def _short(expr: ast.AST) -> str:
    text = ast.unparse(expr)
    return text if len(text) <= 60 else text[:57] + "..."


def _is_super_call(expr: ast.expr, klass: ast.ClassDef) -> bool:
    """``super()``, ``super(Klass, self)`` or a direct base (``Node.__init__(self, …)``)."""
    if isinstance(expr, ast.Call) and isinstance(expr.func, ast.Name) and expr.func.id == "super":
        return True
    dotted = _dotted(expr)
    return dotted is not None and any(_dotted(b) == dotted for b in klass.bases)


def _import_bindings(program: Program, module: Module) -> dict[str, str]:
    """Local name → absolute dotted name, for every import statement in the module."""
    out: dict[str, str] = {}
    for node in ast.walk(module.tree):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    out[alias.asname] = program.absolute_import(module, alias.name)
                else:
                    top = alias.name.split(".")[0]
                    out[top] = program.absolute_import(module, top)
        elif isinstance(node, ast.ImportFrom):
            base = program.resolve_import(module, node.module, node.level)
            for alias in node.names:
                if alias.name != "*":
                    out[alias.asname or alias.name] = f"{base}.{alias.name}" if base else alias.name
    return out


def _unresolved_workspace_imports(program: Program, module: Module) -> list[str]:
    """Imports that look like workspace imports (relative, or under a top-level package the
    workspace defines) but name no workspace module or module member."""
    tops = {name.split(".")[0] for name, mod in program.modules.items() if mod.is_package}
    out: set[str] = set()
    for node in ast.walk(module.tree):
        if isinstance(node, ast.ImportFrom):
            base = program.resolve_import(module, node.module, node.level)
            if node.level == 0 and base.split(".")[0] not in tops:
                continue
            if base not in program.modules and not any(
                    f"{base}.{a.name}" in program.modules for a in node.names):
                out.add(("." * node.level) + (node.module or ""))
        elif isinstance(node, ast.Import):
            for alias in node.names:
                if alias.name.split(".")[0] in tops and alias.name not in program.modules:
                    out.add(alias.name)
    return sorted(out)


def _may_create(call: ast.Call, model: FunctionModel) -> bool:
    """False when every creation effect needs an argument the call leaves at its ``None``
    default (``Buffer()`` without a node creates nothing)."""
    params = {p.name: p for p in model.signature.params}
    for spec in model.effects:
        if spec.kind not in CREATION_KINDS:
            continue
        ref = dict(spec.args).get("node") or dict(spec.args).get("target")
        param = params.get(ref.data) if ref is not None and ref.how == "arg" else None
        if param is None or param.name == "self" or param.default is None \
                or param.default.consts() != [None] or _argument(call, model.signature, param.name) \
                is not None or any(k.arg is None for k in call.keywords) \
                or any(isinstance(a, ast.Starred) for a in call.args):
            return True
    return False


def _node_argument(call: ast.Call) -> ast.expr | None:
    return call.func.value if isinstance(call.func, ast.Attribute) else None


def _argument(call: ast.Call, signature, param: str) -> ast.expr | None:
    for kw in call.keywords:
        if kw.arg == param:
            return kw.value
    names = [p.name for p in signature.params if p.kind == "pos"]
    explicit_self = isinstance(call.func, ast.Attribute) and call.func.attr == "__init__" \
        and not isinstance(call.func.value, ast.Call)  # ``Base.__init__(self, …)``
    if names and names[0] == "self" and not explicit_self:
        names = names[1:]
    if param in names:
        index = names.index(param)
        if index < len(call.args) and not any(isinstance(a, ast.Starred) for a in call.args[:index + 1]):
            return call.args[index]
    return None


def _module_binding(name: str, module: Module) -> str | None:
    """How a module-level name is bound, in words: more than once at module level (imports
    chosen by a condition), also by a function that declares it ``global``, or once to a
    value that is not a literal (``ns = sys.argv[1] if len(sys.argv) > 1 else 'robot'``)."""
    top: list[ast.AST] = []
    setters: list[str] = []
    _module_bindings(name, module.tree.body, top, setters)
    if setters:
        return (f"`{name}` is also set by function {_some_code(set(setters))} (`global {name}`), "
                "whose value there is not known statically")
    if len(top) > 1:
        how = "a loop among them" if any(isinstance(n, ast.For) for n in top) else "one per condition"
        return f"`{name}` is bound {len(top)} times at module level ({how})"
    if len(top) == 1 and isinstance(top[0], ast.Assign) and not isinstance(top[0].value, ast.Constant):
        return (f"it depends on module-level `{name} = {_short(top[0].value)}`, whose value is "
                "not known statically")
    return None


def _module_bindings(name: str, body: list, top: list[ast.AST], setters: list[str]) -> None:
    """Collect the statements binding ``name`` at module level into ``top``, and the functions
    that assign it through ``global`` into ``setters`` (class bodies bind their own names)."""
    for node in body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            declared = any(isinstance(n, ast.Global) and name in n.names for n in ast.walk(node))
            if declared and any(_binds(n, name) for n in ast.walk(node)):
                setters.append(node.name)
            continue
        if isinstance(node, ast.ClassDef):
            continue
        if _binds(node, name):
            top.append(node)
        for field in ("body", "orelse", "finalbody", "handlers"):
            inner = getattr(node, field, None)
            if inner:
                _module_bindings(name, inner, top, setters)


def _binds(node: ast.AST, name: str) -> bool:
    """Whether the statement ``node`` itself binds ``name`` (an import or an assignment)."""
    if isinstance(node, (ast.Import, ast.ImportFrom)):
        return any((a.asname or a.name.split(".")[0]) == name for a in node.names)
    if isinstance(node, ast.Assign):
        return any(isinstance(t, ast.Name) and t.id == name for tgt in node.targets for t in ast.walk(tgt))
    if isinstance(node, (ast.AnnAssign, ast.AugAssign)):
        return isinstance(node.target, ast.Name) and node.target.id == name
    if isinstance(node, ast.For):
        return any(isinstance(t, ast.Name) and t.id == name for t in ast.walk(node.target))
    return False


def _binding_of(name: str, scope: ast.AST | None, call: ast.Call) -> str | None:
    """How ``name`` is bound in the function around the call, in words."""
    if scope is None or isinstance(scope, ast.Lambda):
        return None
    args = scope.args
    params = [a.arg for a in args.posonlyargs + args.args + args.kwonlyargs]
    if name in params:
        return (f"it depends on parameter `{name}` of {scope.name}, unknown in at least one "
                "of its calls")
    if name in {a.arg for a in (args.vararg, args.kwarg) if a}:
        return f"it depends on `{name}`, the variable arguments of {scope.name}"
    for node in ast.walk(scope):
        if isinstance(node, (ast.For, ast.AsyncFor, ast.comprehension)) and \
                any(isinstance(t, ast.Name) and t.id == name for t in ast.walk(node.target)):
            return (f"it depends on loop variable `{name}` over `{_short(node.iter)}`, "
                    "whose elements are unknown")
        if isinstance(node, ast.Assign) and node.lineno <= call.lineno and any(
                isinstance(t, ast.Name) and t.id == name for tgt in node.targets for t in ast.walk(tgt)) \
                and not isinstance(node.value, ast.Constant):  # a literal is known: not the cause
            return f"it depends on `{name} = {_short(node.value)}`, whose value is unknown"
        if isinstance(node, ast.withitem) and node.optional_vars is not None and any(
                isinstance(t, ast.Name) and t.id == name for t in ast.walk(node.optional_vars)):
            return f"it depends on `{name}` bound by `with {_short(node.context_expr)}`"
    return None


def _plural(count: int, noun: str) -> str:
    return noun if count == 1 else noun + "s"
