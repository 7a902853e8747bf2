"""CMakeLists.txt read as a list of commands, in linear time.

A hand-written scanner rather than regular expressions over the whole file: a
pattern spanning arguments backtracks on inputs like ``install(PROGRAMS``
followed by thousands of spaces. The package reader (executables) and the
workspace walk (installed scripts to analyse) both read CMake through it.
"""
from __future__ import annotations

import re
_BRACKET_OPEN = re.compile(r"\[(=*)\[")


def _bracket_end(text: str, pos: int) -> tuple[int, str] | None:
    """For a bracket argument/comment opening at ``pos`` (``[==[``): its end and its content."""
    match = _BRACKET_OPEN.match(text, pos)
    if match is None:
        return None
    close = "]" + match.group(1) + "]"
    end = text.find(close, match.end())
    end = len(text) if end < 0 else end
    return end + len(close), text[match.end():end]


def _skip_comment(text: str, pos: int) -> int:
    """The position after the comment starting with ``#`` at ``pos``."""
    bracket = _bracket_end(text, pos + 1)
    if bracket is not None:
        return bracket[0]
    end = text.find("\n", pos)
    return len(text) if end < 0 else end


def _quoted_end(text: str, pos: int) -> int:
    """The position after the quoted argument opening at ``pos``."""
    i = pos + 1
    while i < len(text):
        char = text[i]
        if char == "\\":
            i += 2
        elif char == '"':
            return i + 1
        else:
            i += 1
    return len(text)


#: The rest of an unquoted argument (``\s`` is ``str.isspace``): at least its first character.
_UNQUOTED_REST = re.compile(r".[^\s()]*", re.DOTALL)


def _arguments(text: str, pos: int) -> tuple[list[str], int]:
    """The arguments of a command whose ``(`` is at ``pos``, and the position after its ``)``."""
    args: list[str] = []
    depth, i, start = 1, pos + 1, -1
    while i < len(text) and depth:
        char = text[i]
        if start < 0 and char == '"':
            end = _quoted_end(text, i)
            args.append(text[i + 1:end - 1])
            i = end
            continue
        if start < 0 and char == "[" and _bracket_end(text, i) is not None:
            end, content = _bracket_end(text, i)  # type: ignore[misc]
            args.append(content)
            i = end
            continue
        if char == "#" and start < 0:
            i = _skip_comment(text, i)
            continue
        if char.isspace() or char in "()":
            if start >= 0:
                args.append(text[start:i])
                start = -1
            depth += char == "("
            depth -= char == ")"
        elif start < 0:
            # An unquoted argument runs to the next space or parenthesis (quotes, brackets and
            # ``#`` inside it are plain characters): one match, not a step per character.
            start = i
            i = _UNQUOTED_REST.match(text, i).end()
            continue
        i += 1
    if start >= 0:
        args.append(text[start:i])
    return args, i


_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


def cmake_commands(text: str) -> list[tuple[str, list[str]]]:
    """``(lower-case command name, arguments)`` of each command invocation, in one linear pass.

    A hand-written scanner rather than regular expressions over the whole file:
    a pattern spanning arguments backtracks on inputs like ``install(PROGRAMS``
    followed by thousands of spaces.
    """
    commands: list[tuple[str, list[str]]] = []
    i = 0
    while i < len(text):
        char = text[i]
        if char == "#":
            i = _skip_comment(text, i)
        elif char == '"':
            i = _quoted_end(text, i)
        elif char == "_" or char.isalpha():
            match = _IDENTIFIER.match(text, i)
            end = match.end() if match else i + 1
            j = end
            while j < len(text) and text[j] in " \t":
                j += 1
            if j < len(text) and text[j] == "(":
                name = text[i:end].lower()
                args, i = _arguments(text, j)
                commands.append((name, args))
            else:
                i = end
        else:
            i += 1
    return commands


_VARIABLE_NAME = re.compile(r"[A-Za-z0-9_.+-]+")
_REFERENCE = re.compile(r"\$\{([A-Za-z0-9_.+-]+)\}")


def literal_variables(commands: list[tuple[str, list[str]]]) -> dict[str, str]:
    """The variables a file sets to one literal word, and only to that one.

    ``set(EXEC_NAME "turtlebot3_fake_node")`` names the executable of a later
    ``add_executable(${EXEC_NAME} ...)``. A variable set to a list, to another
    variable, to different words (on branches the scanner does not follow), with
    ``CACHE``/``PARENT_SCOPE``, or unset, is not literal: it stays unknown.
    """
    values: dict[str, set[str]] = {}
    for name, args in commands:
        if name in ("set", "unset") and args and _VARIABLE_NAME.fullmatch(args[0]):
            literal = name == "set" and len(args) == 2 and "$" not in args[1] and ";" not in args[1]
            values.setdefault(args[0], set()).add(args[1] if literal else "$")
    return {var: found.pop() for var, found in sorted(values.items()) if len(found) == 1 and "$" not in found}


def expand(arg: str, variables: dict[str, str]) -> str:
    """``arg`` with its ``${VAR}`` references to known variables replaced (others left as written)."""
    return _REFERENCE.sub(lambda m: variables.get(m.group(1), m.group(0)), arg)
