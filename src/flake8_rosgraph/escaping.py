"""Names and messages made safe to print: no control characters reach a terminal, a log or a CI parser.

Topic names, node names and file names come from the analysed repository. A
topic literal holding ``"\\nsrc/x.py:1:1: F401 …"`` or ``"\\x1b[2K"`` printed raw
forges a finding line that CI problem matchers pick up, or rewrites the
terminal. So every message is escaped where it is made (the rules' findings,
the analysis's diagnostics) and again, idempotently, where text is printed:
control characters (C0, DEL, C1), bidirectional overrides ("Trojan Source")
and lone surrogates (file names that are not UTF-8) become visible
``\\xNN``/``\\uNNNN`` escapes. Backslashes are left alone, which keeps the
escaping idempotent; the output stays unambiguous about what is *not* a
control character, which is what matters for safety.
"""
from __future__ import annotations

import re

#: What is never printed raw: C0 controls, DEL, C1 controls, bidi embeddings/overrides/isolates,
#: line/paragraph separators, lone surrogates.
_UNSAFE = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]")


def _escape_char(match: re.Match) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code <= 0xFF else f"\\u{code:04x}"


def escape_text(text: str) -> str:
    """``text`` with every unsafe character written as a visible escape (idempotent)."""
    return _UNSAFE.sub(_escape_char, text)


#: After ``json.dumps``: what it leaves raw (with ``ensure_ascii=False``) and a terminal would act on.
_JSON_UNSAFE = re.compile("[\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069\ud800-\udfff]")


def json_safe(dumped: str) -> str:
    """JSON text with the characters ``json.dumps`` leaves raw written as ``\\uNNNN`` escapes.

    ``json.dumps`` already escapes C0 controls; the rest can only occur inside
    strings, where a ``\\u`` escape means the same character, so the document
    decodes to the same data and prints (and encodes) safely.
    """
    return _JSON_UNSAFE.sub(lambda m: f"\\u{ord(m.group()):04x}", dumped)
