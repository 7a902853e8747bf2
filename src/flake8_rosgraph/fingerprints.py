"""Stable identities of findings, shared by SARIF (``partialFingerprints``) and baselines.

A finding must keep its identity when unrelated lines are added above it, so
no identity holds a line number: it is the code, the file, the message with
its ``file:line`` references stripped, the text of the source line, and the
finding's rank among identical ones (two equal lines with the same problem
stay two findings). ``primaryLocationLineHash`` is GitHub's name for the
line-text part with that rank, ``hash:rank``.
"""
from __future__ import annotations

import hashlib
import re
from collections import Counter
from pathlib import Path
from typing import Hashable

from .safe_io import MAX_SOURCE_BYTES, read_bytes

_LINE_REF = re.compile(r"(\.[A-Za-z]+):\d+\b")


class SourceLines:
    """The stripped text of source lines, each file read once (unreadable files give empty text)."""

    def __init__(self) -> None:
        self._lines: dict[Path, list[str]] = {}

    def raw(self, path: Path, line: int) -> str:
        """The line as written (no line break); empty when the file or line does not exist."""
        if path not in self._lines:
            try:  # the workspace's one safe opener: no FIFO, device or huge file
                self._lines[path] = read_bytes(path, None, MAX_SOURCE_BYTES).decode("utf-8", "replace").splitlines()
            except OSError:
                self._lines[path] = []
        lines = self._lines[path]
        return lines[line - 1] if 0 < line <= len(lines) else ""

    def text(self, path: Path, line: int) -> str:
        """The line without its indentation and trailing blanks."""
        return self.raw(path, line).strip()


class Ranks:
    """Counts identical identities in the order they are seen: 1 for the first, 2 for the next …"""

    def __init__(self) -> None:
        self._seen: Counter[Hashable] = Counter()

    def next(self, identity: Hashable) -> int:
        self._seen[identity] += 1
        return self._seen[identity]


def without_line_numbers(message: str) -> str:
    """``… at pkg/a.py:41`` → ``… at pkg/a.py``: the message as it reads after lines move."""
    return _LINE_REF.sub(r"\1", message)


def finding_fingerprint(code: str, path: str, message: str, line_text: str, rank: int,
                        related: list[tuple[str, str]]) -> str:
    """The identity of one finding; ``path`` and the related paths relative to a fixed root."""
    parts = [code, path, without_line_numbers(message), line_text, str(rank)]
    parts += sorted(f"{other}\0{label}" for other, label in related)
    return hashlib.sha256("\0".join(parts).encode()).hexdigest()[:32]


def line_hash(line_text: str, rank: int) -> str:
    """GitHub's ``primaryLocationLineHash``: the whitespace-normalised line's hash and the rank."""
    normalised = " ".join(line_text.split())
    return f"{hashlib.sha256(normalised.encode()).hexdigest()[:16]}:{rank}"
