"""Constant folding: Python's own operators and pure builtins applied to constant sets.

Each operation runs on the cartesian product of the operands' constants (bounded by
the value lattice) with the real Python semantics, and with guards so that folding
can neither hang nor blow up memory (no huge powers, no giant strings).  Anything
that raises, or is not on the allow-lists, folds to ⊤.
"""
from __future__ import annotations

import ast
import itertools
import operator
import posixpath
import re
import string
from typing import Any, Callable

from .values import MAX_ATOMS, TOP, Value, atoms, Const, from_input

#: Longest string/bytes a folded operation may produce.
MAX_STR = 4096

BINOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow, ast.BitAnd: operator.and_, ast.BitOr: operator.or_,
    ast.BitXor: operator.xor, ast.LShift: operator.lshift, ast.RShift: operator.rshift,
}
UNARYOPS: dict[type, Callable[[Any], Any]] = {
    ast.USub: operator.neg, ast.UAdd: operator.pos, ast.Not: operator.not_,
    ast.Invert: operator.invert,
}
CMPOPS: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.Is: operator.is_, ast.IsNot: operator.is_not,
    ast.In: lambda a, b: operator.contains(b, a),
    ast.NotIn: lambda a, b: not operator.contains(b, a),
}

#: Pure builtins that fold on constants.
PURE_BUILTINS: dict[str, Callable[..., Any]] = {
    "str": str, "int": int, "float": float, "bool": bool, "abs": abs, "round": round,
    "min": min, "max": max, "len": len, "repr": repr, "hex": hex, "oct": oct, "bin": bin,
    "chr": chr, "ord": ord,
}
#: Library functions that compute a string from strings only, and fold on constants
#: (``os.path.join(ns, 'cmd_vel')``): Python's own, for POSIX paths, as ROS names are.
PURE_LIBRARY: dict[str, Callable[..., Any]] = {
    "os.path.join": posixpath.join, "posixpath.join": posixpath.join,
    "os.path.basename": posixpath.basename, "posixpath.basename": posixpath.basename,
    "os.path.dirname": posixpath.dirname, "posixpath.dirname": posixpath.dirname,
    "os.path.normpath": posixpath.normpath, "posixpath.normpath": posixpath.normpath,
}
#: str methods that fold on constants (no side effects, bounded output).
STR_METHODS = frozenset({
    "format", "join", "upper", "lower", "strip", "lstrip", "rstrip", "replace", "capitalize",
    "title", "startswith", "endswith", "removeprefix", "removesuffix", "zfill", "casefold",
    "isdigit", "isalpha", "isalnum", "isidentifier", "find", "count", "split", "rsplit",
    "swapcase", "center", "ljust", "rjust", "encode",
})

#: str methods whose result, called without arguments on a setting's text, is taken to be the
#: setting itself: they only drop the whitespace around it, which is the layout of the file
#: or command line that supplies it (``str(param.value).strip()``), not part of a name.
SAME_TEXT = frozenset({"strip", "lstrip", "rstrip"})


def _safe(result: Any) -> bool:
    if isinstance(result, (str, bytes)):
        return len(result) <= MAX_STR
    if isinstance(result, int) and not isinstance(result, bool):
        return result.bit_length() <= 256
    if isinstance(result, (list, tuple)):
        return len(result) <= MAX_ATOMS and all(_safe(x) for x in result)
    return isinstance(result, (float, bool, complex)) or result is None


#: A width or precision in a format template big enough to build a huge string.
_WIDE = re.compile(r"\d{5,}")
#: str methods whose integer argument is the length of the result.
_WIDTH_METHODS = frozenset({"center", "ljust", "rjust", "zfill"})


def wide_template(text: object) -> bool:
    """Whether a format template/spec asks for a field wider than :data:`MAX_STR`."""
    return isinstance(text, str) and any(int(m) > MAX_STR for m in _WIDE.findall(text))


def safe_template(text: object) -> bool:
    """Whether a ``str.format`` template only substitutes its arguments whole.

    A field like ``{0.__class__}`` or ``{0[x]}`` reads attributes or items of
    the argument: folded on the analyser's own objects it would print their
    internals (and memory addresses, so output stops being deterministic).
    """
    if not isinstance(text, str):
        return True
    try:
        for _, name, spec, _ in string.Formatter().parse(text):
            if name is not None and ("." in name or "[" in name):
                return False
            if spec and "{" in spec and not safe_template(spec):
                return False
    except (ValueError, RecursionError):
        return False
    return True


def _guard_args(fn: Callable, args: tuple) -> bool:
    """Refuse operations that could take unbounded time or memory before running them."""
    if fn is operator.mod and args and wide_template(args[0]):
        return False
    if fn is format and len(args) == 2 and wide_template(args[1]):
        return False
    if fn is operator.pow and len(args) == 2:
        base, exp = args
        return isinstance(exp, (int, float)) and abs(exp) <= 64
    if fn in (operator.mul, operator.lshift) and len(args) == 2:
        a, b = args
        for x, y in ((a, b), (b, a)):
            if isinstance(x, (str, bytes)) and isinstance(y, int) and y * len(x) > MAX_STR:
                return False
        if fn is operator.lshift and isinstance(b, int) and b > 256:
            return False
    return True


def fold(fn: Callable[..., Any], operands: list[Value], wrap=None) -> Value:
    """Apply ``fn`` to every combination of the operands' constants."""
    pools = []
    size = 1
    soft = any(v.soft for v in operands)
    for value in operands:
        consts = value.consts()
        if consts is None:
            return TOP if not value.is_bottom else value
        if not consts:
            return value  # ⊥ in, ⊥ out
        pools.append(consts)
        size *= len(consts)
        if size > MAX_ATOMS * MAX_ATOMS:
            return TOP
    out = []
    for combo in itertools.product(*pools):
        if not _guard_args(fn, combo):
            return TOP
        try:
            result = fn(*combo)
        except Exception:  # the folded operation raises at run time: no value flows on
            continue
        if not _safe(result):
            return TOP
        if wrap is not None:
            atom = wrap(result)
            if atom is None:
                return TOP
            out.append(atom)
        elif isinstance(result, (list, tuple)):
            return TOP
        else:
            out.append(Const.of(result))
    return atoms(out, soft)


def fold_text(fn: Callable[..., Any], operands: list[Value]) -> Value:
    """:func:`fold` for building text (``+``, f-strings): where a piece is unknown but for a few
    strings it may be (``sys.argv[1] if ... else 'robot'``), the text those strings give is kept
    as what the unknown result may be, so ``f'/{ns}/pose'`` still names ``/robot/pose`` as only
    partly known. Only string results are kept; a fully unknown piece leaves nothing known.
    An overridable default of ``None`` (an option not given) is never text: code that formats
    it runs with the value given instead, so it is unknown there, never ``'None'``."""
    operands = [_given(v) for v in operands]
    result = fold(fn, operands)
    if not result.is_top or result.is_saturated or any(v.is_top and not v.hints for v in operands) \
            or not any(v.is_top for v in operands):
        return result
    known = fold(fn, [atoms(v.hints) if v.is_top else v for v in operands])
    strings = known.strings()
    if not strings:
        return result
    return from_input(result.join(known), result.origin) if result.origin is not None \
        else result.join(known)


def _given(value: Value) -> Value:
    """``value`` without an overridable ``None`` default: the other constants, as hints of ⊤."""
    consts = value.consts() if value.soft else None
    if not consts or None not in consts:
        return value
    return TOP.join(atoms(Const.of(c) for c in consts if c is not None))


def call_str_method(name: str, receiver: Value, args: list[Value]) -> Value:
    if name not in STR_METHODS:
        return TOP
    if name in _WIDTH_METHODS and any(
            isinstance(c, int) and c > MAX_STR for a in args for c in (a.consts() or ())):
        return TOP
    if name == "format" and not all(safe_template(c) for c in (receiver.consts() or ())):
        return TOP
    return fold(lambda s, *a: getattr(s, name)(*a) if isinstance(s, str) else _fail(),
                [receiver, *args], wrap=_wrap_seq)


def _fail():
    raise TypeError


def _wrap_seq(result: Any):
    from .values import Seq, const
    if isinstance(result, list):
        return Seq("list", tuple(const(x) for x in result))
    return Const.of(result)
