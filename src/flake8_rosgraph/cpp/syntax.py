"""tree-sitter's C++ grammar: the parser, the walk, and what a damaged file costs.

tree-sitter never fails on bad input: it recovers, marking what it could not
parse with ``ERROR`` and ``MISSING`` nodes. Real ROS code trips it often on
macros (``MY_PKG_PUBLIC explicit Node(...)``, ``"%" PRId64``); recovery is
local, so the rest of the file is still read. One diagnostic per damaged file
names the first damaged line: a warning when a damaged region holds an rclcpp
call (a call may be missed there), else an informational one.

The readers walk trees iteratively with a budget of syntax nodes per file
(:data:`MAX_SYNTAX_NODES`), so neither deep nesting nor a huge file can exhaust
the stack or the time.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

from ..graph.model import Diagnostic, Location

#: Syntax nodes read per file at most; beyond, the rest of the file is not read.
MAX_SYNTAX_NODES = 400_000
#: Text that marks a damaged region as one that may hide an rclcpp call.
_ROS_CALL_TEXT = (b"create_", b"declare_parameter", b"make_shared", b"Node(")


class BudgetExceeded(Exception):
    """The file has more syntax nodes than :data:`MAX_SYNTAX_NODES`."""


def load_parser() -> tuple[Any, str | None]:
    """A tree-sitter C++ parser, or ``(None, why not)`` when tree-sitter is missing or incompatible."""
    try:
        import tree_sitter
        import tree_sitter_cpp
    except ImportError as exc:
        return None, f"C++ sources not read: {exc.name or 'tree-sitter'} is not installed"
    try:
        return tree_sitter.Parser(tree_sitter.Language(tree_sitter_cpp.language())), None
    except (TypeError, ValueError) as exc:
        return None, f"C++ sources not read: this tree-sitter cannot load the C++ grammar ({exc})"


@dataclass(frozen=True)
class SourceText:
    """A parsed file's path and bytes, to turn tree-sitter points into locations and nodes into text."""

    path: str
    data: bytes

    def location(self, node: Any) -> Location:
        row, byte_col = node.start_point
        line_start = node.start_byte - byte_col
        column = len(self.data[line_start:node.start_byte].decode("utf-8", "replace")) + 1
        return Location(self.path, row + 1, column)


def nodes_of_types(language: Any, root: Any, types: tuple[str, ...]) -> list[Any]:
    """Every node of ``types`` under ``root`` (itself included), parents before their children
    and otherwise in source order. tree-sitter's query engine finds them without handing each
    node of the tree to Python; it returns them grouped by type, hence the sort."""
    import tree_sitter

    query = _query(language, types)
    cursor_type = getattr(tree_sitter, "QueryCursor", None)  # tree-sitter >= 0.25
    found = (cursor_type(query) if cursor_type is not None else query).captures(root)
    return sorted(found.get("node", ()), key=lambda node: (node.start_byte, -node.end_byte))


@lru_cache(maxsize=8)
def _query(language: Any, types: tuple[str, ...]) -> Any:
    import tree_sitter

    return tree_sitter.Query(language, "[" + " ".join(f"({kind})" for kind in types) + "] @node")


def text(node: Any) -> str:
    return node.text.decode("utf-8", "replace")


def damage_diagnostic(source: SourceText, root: Any) -> Diagnostic | None:
    """One diagnostic for the damaged regions of a parsed file, if there are any."""
    if not root.has_error:
        return None
    regions: list[Any] = []
    stack = [root]
    while stack:
        node = stack.pop()
        if node.type == "ERROR" or node.is_missing:
            regions.append(node)
        elif node.has_error:
            stack.extend(reversed(node.children))
    if not regions:
        return None
    regions.sort(key=lambda n: n.start_byte)
    risky = [n for n in regions if any(marker in n.text for marker in _ROS_CALL_TEXT)]
    first = (risky or regions)[0]
    line = first.start_point[0] + 1
    count = f" ({len(regions)} damaged regions)" if len(regions) > 1 else ""
    if risky:
        return Diagnostic(source.path, line, f"C++ syntax error at line {line}{count}: rclcpp calls "
                                             "there may be missed (tree-sitter)", "warning")
    return Diagnostic(source.path, line, f"C++ syntax not understood at line {line}{count}, often a "
                                         "macro; the rest of the file is read (tree-sitter)", "info")
