"""ROS 2 name expansion and validation with the exact rules rcl and rmw apply at run time.

rclpy hands every node name, namespace, topic, service and action name to rcl,
which raises (``InvalidNodeNameException``, ``InvalidTopicNameException``, ...)
when the name breaks a rule. The checks here mirror the C sources check by
check, in the same order, so that the problem reported (and its index) is the
one rclpy would report:

* ``rmw/src/validate_node_name.c``       -> :func:`validate_node_name`
* ``rmw/src/validate_namespace.c``       -> :func:`validate_namespace`
* ``rmw/src/validate_full_topic_name.c`` -> :func:`validate_full_topic_name`
* ``rcl/src/rcl/validate_topic_name.c``  -> :func:`validate_topic_name`
* ``rcl/src/rcl/expand_topic_name.c``    -> :func:`expand_topic_name`
* ``rcl/src/rcl/remap.c`` (``rcl_remap_first_match``, topic/service rules) -> :func:`first_remap_match`
* ``rcl/src/rcl/node.c`` and rclpy ``Node.__init__`` namespace handling -> :func:`normalize_namespace`, :func:`fqn`
* ``rclpy/validate_parameter_name.py``   -> :func:`validate_parameter_name`

Service and action names go through the very same functions as topic names:
rcl resolves them with ``rcl_node_resolve_name(..., is_service=true)``, which
only changes the error code, so there is no separate service/action API.

Character classes are ASCII-only, like ``rcutils_isalnum_no_locale`` and
``isdigit`` in the C locale (Python's ``str.isalnum`` would accept ``'é'``).
Indices are character indices into the Python string; they equal rcl's byte
indices for ASCII names.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Mapping, Sequence

#: ``RMW_TOPIC_MAX_NAME_LENGTH``: 255 minus 8 characters that rmw reserves for DDS prefixes.
TOPIC_MAX_NAME_LENGTH = 255 - 8
#: ``RMW_NAMESPACE_MAX_LENGTH``: leaves room for ``/`` plus a one-character name.
NAMESPACE_MAX_LENGTH = TOPIC_MAX_NAME_LENGTH - 2
#: ``RMW_NODE_NAME_MAX_NAME_LENGTH``.
NODE_NAME_MAX_LENGTH = 255
#: A node name or name token starting with this is hidden by the ROS 2 CLI tools (rclpy ``HIDDEN_NODE_PREFIX``).
HIDDEN_PREFIX = "_"
#: Names whose checks are remembered: the rules check each name of the graph many times (once
#: per endpoint, launch instance and candidate); the results are immutable.
_REMEMBERED_CHECKS = 8192

_DIGITS = frozenset("0123456789")
_ALNUM = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz") | _DIGITS
_TOKEN_CHARS = _ALNUM | {"_"}
_FULL_NAME_CHARS = _TOKEN_CHARS | {"/"}

_NODE_SUBSTITUTION = "{node}"
_NAMESPACE_SUBSTITUTIONS = ("{ns}", "{namespace}")


@dataclass(frozen=True)
class NameCheck:
    """The verdict of one validation: ``reason`` and ``index`` say what rcl would complain about, and where."""

    ok: bool
    reason: str | None = None
    index: int | None = None


VALID = NameCheck(True)


def _fail(reason: str, index: int | None) -> NameCheck:
    return NameCheck(False, reason, index)


def _unallowed(char: str, allowed: str, index: int) -> NameCheck:
    # repr() keeps spaces, newlines and quotes visible in a one-line message.
    return _fail(f"contains {char!r} (only {allowed} are allowed)", index)


@lru_cache(maxsize=_REMEMBERED_CHECKS)
def validate_node_name(name: str) -> NameCheck:
    """Check a node name as ``rmw_validate_node_name`` does: ``[A-Za-z_][A-Za-z0-9_]*``, at most 255 characters."""
    if not name:
        return _fail("is empty", 0)
    for i, char in enumerate(name):
        if char not in _TOKEN_CHARS:
            return _unallowed(char, "alphanumerics and '_'", i)
    if name[0] in _DIGITS:
        return _fail("starts with a digit", 0)
    if len(name) > NODE_NAME_MAX_LENGTH:
        return _fail(f"is longer than {NODE_NAME_MAX_LENGTH} characters", NODE_NAME_MAX_LENGTH - 1)
    return VALID


@lru_cache(maxsize=_REMEMBERED_CHECKS)
def _validate_absolute(name: str, max_length: int) -> NameCheck:
    """The shared body of the full-topic-name and namespace checks; only the length limit differs."""
    if not name:
        return _fail("is empty", 0)
    if name[0] != "/":
        return _fail("is not absolute (must start with '/')", 0)
    if name[-1] == "/":
        return _fail("ends with '/'", len(name) - 1)
    for i, char in enumerate(name):
        if char not in _FULL_NAME_CHARS:
            return _unallowed(char, "alphanumerics, '_' and '/'", i)
    for i in range(len(name) - 1):
        if name[i] == "/":
            if name[i + 1] == "/":
                return _fail("contains '//'", i + 1)
            if name[i + 1] in _DIGITS:
                return _fail("has a token that starts with a digit", i + 1)
    if len(name) > max_length:
        return _fail(f"is longer than {max_length} characters", max_length - 1)
    return VALID


def validate_full_topic_name(name: str) -> NameCheck:
    """Check an expanded, absolute topic/service/action name as ``rmw_validate_full_topic_name`` does.

    rcl applies this after expansion and remapping, and treats the length limit
    (247 characters) as a hard error, so it is one here too.
    """
    return _validate_absolute(name, TOPIC_MAX_NAME_LENGTH)


def validate_namespace(ns: str) -> NameCheck:
    """Check an absolute namespace as ``rmw_validate_namespace`` does.

    The root ``"/"`` is valid; anything else must be a valid full name of at
    most 245 characters.

    Pass the namespace through :func:`normalize_namespace` first: the argument
    of ``Node(namespace=...)`` may legally be empty or relative.
    """
    if ns == "/":
        return VALID
    return _validate_absolute(ns, NAMESPACE_MAX_LENGTH)


@lru_cache(maxsize=_REMEMBERED_CHECKS)
def validate_topic_name(name: str) -> NameCheck:
    """Check a topic/service/action name as written in code, before expansion (``rcl_validate_topic_name``).

    The name may be relative, start with ``~`` and hold ``{substitutions}``.
    Like rcl, this does not look for ``//`` or the length limit: those are
    checked on the expanded name (:func:`expand_topic_name`).
    """
    if not name:
        return _fail("is empty", 0)
    if name[0] in _DIGITS:
        return _fail("starts with a digit", 0)
    if name[-1] == "/":
        return _fail("ends with '/'", len(name) - 1)
    in_braces = False
    brace_index = 0
    for i, char in enumerate(name):
        if char in _TOKEN_CHARS:
            if char in _DIGITS and in_braces and i - 1 == brace_index:
                return _fail("has a substitution that starts with a digit", i)
        elif char == "/":
            if in_braces:
                return _fail("has a substitution that contains '/'", i)
        elif char == "~":
            if i != 0:
                return _fail("has '~' that is not the first character", i)
        elif char == "{":
            brace_index = i
            if in_braces:
                return _fail("has a nested '{'", i)
            in_braces = True
        elif char == "}":
            if not in_braces:
                return _fail("has an unmatched '}'", i)
            in_braces = False
        elif in_braces:
            return _fail(f"has a substitution that contains {char!r}", i)
        else:
            return _unallowed(char, "alphanumerics, '_', '/', '~', '{' and '}'", i)
    if in_braces:
        return _fail("has an unmatched '{'", brace_index)
    # rcl inspects pairs (i, i + 1) and skips the last character, which is why
    # "~x" (two characters) passes while "~xy" fails; kept for fidelity.
    for i in range(len(name) - 1):
        if name[i] == "/":
            if name[i + 1] in _DIGITS:
                return _fail("has a token that starts with a digit", i + 1)
        elif i == 1 and name[0] == "~":
            return _fail("has '~' that is not followed by '/'", 1)
    return VALID


def validate_parameter_name(name: str) -> NameCheck:
    """Check a parameter name as rclpy's ``declare_parameter`` does.

    rclpy only rejects the empty name (``InvalidParameterException``); dots,
    slashes and the like are accepted, since parameter names are not graph names.
    """
    if not name:
        return _fail("is empty", 0)
    return VALID


def normalize_namespace(ns: str | None) -> str:
    """Turn the ``namespace`` argument of ``Node(...)`` into the namespace rcl uses.

    rclpy maps ``None`` to ``""``; rcl ``rcl_node_init`` maps ``""`` to ``"/"``
    and prefixes a relative namespace with ``"/"``. A trailing ``"/"`` is *not*
    stripped: rcl keeps it and then rejects the namespace, so stripping it
    would hide a real start-up failure from :func:`validate_namespace`.
    """
    if not ns:
        return "/"
    return ns if ns.startswith("/") else "/" + ns


def built_at_root(raw: str | None, namespace: str | None) -> bool:
    """Whether a name as written looks built from the node's namespace in the root namespace.

    ``self.get_namespace() + '/cmd'`` is ``"//cmd"`` when the node runs in ``"/"``
    (the default), which rcl rejects, and ``"/robot1/cmd"`` in ``"/robot1"``. The
    code only says the name starts with the namespace's ``"/"`` and then its own.
    """
    return namespace == "/" and raw is not None and raw.startswith("//")


def rebuild_in_namespace(raw: str | None, code_namespace: str | None,
                         namespace: str | None) -> str | None:
    """A name the code built from its root namespace (:func:`built_at_root`), as the same code
    builds it when the node is started in ``namespace`` instead (a launch file's): the root's
    ``"/"`` is replaced by that namespace; ``None`` when that namespace is unknown. Other names
    are returned as they are.
    """
    if not built_at_root(raw, code_namespace) or namespace == code_namespace:
        return raw
    return None if namespace is None else namespace + raw[1:]


def fqn(node_name: str, namespace: str) -> str:
    """The fully qualified node name, formatted as ``rcl_node_init`` does (no doubled ``/`` under the root)."""
    return namespace + node_name if namespace.endswith("/") else namespace + "/" + node_name


def _join(namespace: str, name: str) -> str:
    """``namespace`` + ``/`` + ``name``, without the extra ``/`` when the namespace is the root."""
    return namespace + name if len(namespace) == 1 else namespace + "/" + name


def expand_topic_name(
    name: str,
    node_name: str,
    namespace: str,
    substitutions: Mapping[str, str] | None = None,
) -> tuple[str | None, NameCheck]:
    """Expand a topic/service/action name the way ``rcl_expand_topic_name`` does, then validate the result.

    Relative names get the namespace prefixed, ``~`` becomes the node's fully
    qualified name, ``{node}``, ``{ns}`` and ``{namespace}`` are replaced (then
    any key of ``substitutions``, written without braces), absolute names are
    kept. ``namespace`` must already be normalised (:func:`normalize_namespace`).

    Returns ``(None, check)`` when rcl refuses to expand (invalid input name,
    node name or namespace, unknown substitution) and ``(expanded, check)``
    otherwise, where ``check`` is :func:`validate_full_topic_name` of the
    expanded name — rcl runs that check right after expansion, so e.g.
    ``"/foo/{ns}"`` expands to ``"/foo//my_ns"`` and then fails on ``//``.
    """
    check = validate_topic_name(name)
    if not check.ok:
        return None, check
    node_check = validate_node_name(node_name)
    if not node_check.ok:
        return None, _fail(f"node name {node_check.reason}", None)
    ns_check = validate_namespace(namespace)
    if not ns_check.ok:
        return None, _fail(f"namespace {ns_check.reason}", None)

    output = name
    if output.startswith("~"):
        output = _join(namespace, node_name) + output[1:]
    while "{" in output:
        start = output.index("{")
        end = output.find("}", start)
        key = output[start:end + 1]
        if key == _NODE_SUBSTITUTION:
            replacement = node_name
        elif key in _NAMESPACE_SUBSTITUTIONS:
            replacement = namespace
        elif substitutions is not None and key[1:-1] in substitutions:
            replacement = substitutions[key[1:-1]]
            if "{" in replacement or "}" in replacement:
                # rcl would re-scan the braces (and may loop forever); refuse instead.
                return None, _fail(f"substitution {key} has a value with braces", name.find(key))
        else:
            index = name.find(key)
            return None, _fail(f"has an unknown substitution {key}", index if index >= 0 else None)
        output = output.replace(key, replacement)
    if not output.startswith("/"):
        output = _join(namespace, output)
    return output, validate_full_topic_name(output)


@dataclass(frozen=True)
class RemapRule:
    """One topic/service remapping rule ``match:=replacement``; with ``node``, only for that node."""

    match: str
    replacement: str
    node: str | None = None


def first_remap_match(
    expanded_name: str,
    rules: Sequence[RemapRule],
    node_name: str,
    namespace: str,
) -> RemapRule | None:
    """The rule rcl applies to an expanded name (``rcl_remap_first_match``), or ``None``.

    Rules are tried in order (pass a node's local rules before the global
    ones); a rule's ``match`` side is expanded in the node's context and
    compared with the expanded name, and a match side that does not expand is
    skipped. The caller expands the winning rule's ``replacement`` with
    :func:`expand_topic_name`, as rcl does.
    """
    for rule in rules:
        if rule.node is not None and rule.node != node_name:
            continue
        expanded_match, _ = expand_topic_name(rule.match, node_name, namespace)
        if expanded_match is not None and expanded_match == expanded_name:
            return rule
    return None


def is_hidden(name: str) -> bool:
    """Whether the ROS 2 CLI hides this node, topic or service name: any ``/``-token starts with ``_``."""
    return any(token.startswith(HIDDEN_PREFIX) for token in name.split("/"))


def edit_distance(a: str, b: str, limit: int) -> int:
    """Levenshtein distance between ``a`` and ``b``, or ``limit + 1`` as soon as it must exceed ``limit``.

    Near-miss hints only care about small distances: a common prefix and suffix
    (which do not change the distance) are dropped, only the band of cells
    within ``limit`` of the diagonal is computed, and the computation stops once
    a whole band row is above ``limit`` — linear in the names' length, not
    quadratic (hundreds of long names sharing a prefix took minutes).
    """
    if limit < 0:
        raise ValueError("limit must not be negative")
    if a == b:
        return 0
    if abs(len(a) - len(b)) > limit:
        return limit + 1
    start = 0
    while start < min(len(a), len(b)) and a[start] == b[start]:
        start += 1
    end = 0
    while end < min(len(a), len(b)) - start and a[-1 - end] == b[-1 - end]:
        end += 1
    a, b = a[start:len(a) - end], b[start:len(b) - end]
    over = limit + 1
    previous = [j if j <= limit else over for j in range(len(b) + 1)]
    for i, char_a in enumerate(a, 1):
        low, high = max(1, i - limit), min(len(b), i + limit)
        current = [over] * (len(b) + 1)
        current[0] = i if i <= limit else over
        for j in range(low, high + 1):
            current[j] = min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (char_a != b[j - 1]))
        if min(current[low - 1:high + 1]) > limit:
            return over
        previous = current
    return min(previous[-1], over)


def known_suffix(raw: str | None) -> str | None:
    """How every expansion of ``raw`` ends, whatever the namespace and node name rcl puts in
    front of it: ``'scan'`` and ``'~/scan'`` end in ``'/scan'``; ``None`` for an absolute or
    unknown name, a bare ``'~'``, and names with substitutions."""
    if raw is None or raw.startswith("/") or "{" in raw:
        return None
    rest = raw[2:] if raw.startswith("~/") else raw
    if not rest or rest.startswith("~"):
        return None
    return "/" + rest.rstrip("/")

