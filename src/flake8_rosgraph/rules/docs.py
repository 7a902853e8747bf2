"""The rule documentation, taken from the rule docstrings: parsed sections and the generated ``docs/rules.md``.

The docstrings are the single source (ruff style: What it does / Why is this
bad? / Known problems / Example / Use instead / Options); the SARIF writer
reads the same :class:`RuleDoc`. Regenerate the page after editing a rule::

    python -m flake8_rosgraph.rules.docs docs/rules.md           # write
    python -m flake8_rosgraph.rules.docs --check docs/rules.md   # exit 1 if stale
"""
from __future__ import annotations

import argparse
import inspect
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

from . import RULES
from .base import Rule
from .exempt import BUILTIN_EXEMPT

#: The ruff section titles, in the order every rule docstring must use.
SECTIONS: tuple[str, ...] = ("What it does", "Why is this bad?", "Known problems", "Example", "Use instead", "Options")

_HEADING = re.compile(r"^## (.+)$", re.MULTILINE)


@dataclass(frozen=True)
class RuleDoc:
    """One rule's documentation: identity plus the docstring's sections (title, markdown body) in order."""

    code: str
    name: str
    level: str
    summary: str
    default_enabled: bool
    precision: str
    sections: tuple[tuple[str, str], ...]

    def section(self, title: str) -> str:
        return dict(self.sections)[title]

    @property
    def markdown(self) -> str:
        """The sections as markdown (``##`` headings demoted to ``###``)."""
        return "\n\n".join(f"### {title}\n{body}" for title, body in self.sections)


def rule_doc(rule: Rule) -> RuleDoc:
    """Parse a rule's docstring; ``ValueError`` if its sections are missing or out of order."""
    text = inspect.cleandoc(type(rule).__doc__ or "")
    headings = list(_HEADING.finditer(text))
    titles = tuple(m.group(1).strip() for m in headings)
    if titles != SECTIONS:
        raise ValueError(f"{rule.code}: docstring sections {titles} differ from {SECTIONS}")
    bodies = [text[m.end():nxt.start() if nxt else len(text)].strip()
              for m, nxt in zip(headings, [*headings[1:], None])]
    return RuleDoc(rule.code, rule.name, rule.level, rule.summary, rule.default_enabled,
                   rule.precision, tuple(zip(titles, bodies)))  # type: ignore[attr-defined]


def render(rules: Sequence[Rule]) -> str:
    """The whole ``docs/rules.md`` page: an index table, then one section per rule."""
    docs = [rule_doc(rule) for rule in rules]
    lines = [
        "# Rules",
        "",
        "<!-- Generated from the rule docstrings by `python -m flake8_rosgraph.rules.docs docs/rules.md`;"
        " do not edit. -->",
        "",
        "| code | name | level | precision | default | fires when |",
        "|---|---|---|---|---|---|",
    ]
    for doc in docs:
        default = "on" if doc.default_enabled else "off"
        lines.append(f"| [{doc.code}](#{doc.code.lower()}-{doc.name}) | {doc.name} | {doc.level} | {doc.precision} "
                     f"| {default} | {doc.summary} |")
    lines += ["", "## Built-in exempt names", "",
              "ROS001, ROS002, ROS003, ROS008 and ROS009 skip these names; `--rosgraph-external-topics` adds more "
              "(same syntax: `*` within a name component, `**` across components).", "",
              "| name | why |", "|---|---|"]
    lines += [f"| `{pattern}` | {why} |" for pattern, why in BUILTIN_EXEMPT]
    for doc in docs:
        lines += ["", f"## {doc.code} {doc.name}", "", f"Level: {doc.level}. "
                  f"{'Enabled' if doc.default_enabled else 'Disabled'} by default.", "", doc.markdown]
    return "\n".join(lines) + "\n"


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m flake8_rosgraph.rules.docs", description=__doc__.splitlines()[0])
    parser.add_argument("output", type=Path, help="the markdown file to write (docs/rules.md)")
    parser.add_argument("--check", action="store_true", help="do not write; exit 1 if the file is out of date")
    args = parser.parse_args(argv)
    text = render(RULES)
    if args.check:
        current = args.output.read_text(encoding="utf-8") if args.output.exists() else ""
        if current != text:
            print(f"{args.output} is out of date; run python -m flake8_rosgraph.rules.docs {args.output}",
                  file=sys.stderr)
            return 1
        return 0
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(text, encoding="utf-8", newline="\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
