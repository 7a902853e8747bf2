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
