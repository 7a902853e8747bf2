"""``if __name__ == '__main__':``, the guard of a script's own run."""
from __future__ import annotations

import ast


def is_main_guard(test: ast.expr) -> bool:
    """``__name__ == '__main__'`` (either way round)."""
    if not isinstance(test, ast.Compare) or len(test.ops) != 1 or not isinstance(test.ops[0], ast.Eq):
        return False
    sides = [test.left, test.comparators[0]]
    return any(isinstance(x, ast.Name) and x.id == "__name__" for x in sides) and \
        any(isinstance(x, ast.Constant) and x.value == "__main__" for x in sides)


#: Statements that run as a whole, one after the other, when they stand in a straight body.
SIMPLE_STATEMENTS = (ast.Expr, ast.Assign, ast.AnnAssign, ast.AugAssign)


def script_steps(tree: ast.Module) -> tuple[tuple[int, int], ...]:
    """``(first, last)`` lines of each simple statement directly in a top-level ``__main__``
    guard, with no choice inside it (no ``x if c else y``, ``a or b``). The module's run as a
    program runs them one after the other whenever it runs, so they order each other as a
    body's straight code does, though the analysis (which cannot know how the module is run)
    takes the guard as a branch."""
    return tuple((stmt.lineno, stmt.end_lineno or stmt.lineno)
                 for guard in tree.body if isinstance(guard, ast.If) and is_main_guard(guard.test)
                 for stmt in guard.body if isinstance(stmt, SIMPLE_STATEMENTS)
                 and not any(isinstance(n, (ast.IfExp, ast.BoolOp)) for n in ast.walk(stmt)))
