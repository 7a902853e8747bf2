"""A ROS package's manifest (``package.xml``): the few fields the analysis needs.

Read with the safe expat parser (no DTD, no entities, bounded depth), so a hostile
manifest costs only its own package. Kept apart from the launch model because the
workspace walk needs it too: a ROS 1 (catkin) package is not ROS 2 code, and its
messages, launch files and APIs follow other rules.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

from .launch.xml_front import MAX_XML_DEPTH, XmlRefused, safe_parser

#: What REP 149 ``condition`` attributes may test, as a ROS 2 build sees it; other
#: variables (``$ROS_DISTRO``) are unknown, and a condition on them is undecided.
_ROS2_ENVIRONMENT = {"ROS_VERSION": "2"}
_COMPARISON = re.compile(r"^\s*(\S+)\s*(==|!=)\s*(\S+)\s*$")

#: Top-level elements whose text the analysis reads (first occurrence of ``name`` and
#: ``build_type``; every ``buildtool_depend``).
_FIELDS = ("name", "build_type", "buildtool_depend")


@dataclass(frozen=True)
class Manifest:
    name: str
    build_type: str            # from <export><build_type>, "" when not given
    buildtool_depends: tuple[str, ...]

    @property
    def is_ros1(self) -> bool:
        """A catkin package: built for ROS 1 (rospy, genpy messages, roslaunch XML). A
        manifest for both (``condition="$ROS_VERSION == 1"`` on catkin) is a ROS 2 package."""
        return "catkin" in self.buildtool_depends or self.build_type == "catkin"


def parse_manifest(text: str) -> Manifest:
    """The manifest in ``text``; raises ``ExpatError`` or ``XmlRefused`` on what it will not read."""
    texts: dict[str, list[str]] = {key: [] for key in _FIELDS}
    stack: list[str] = []
    chunks: list[str] = []
    parser = safe_parser()

    applies: list[bool] = []  # per open element: whether a ROS 2 build surely sees it

    def start(tag: str, attrs: dict) -> None:
        if len(stack) >= MAX_XML_DEPTH:
            raise XmlRefused(f"line {parser.CurrentLineNumber}: elements nested deeper than {MAX_XML_DEPTH}")
        stack.append(tag)
        applies.append(condition_holds(attrs.get("condition")) is True)
        chunks.clear()

    def end(tag: str) -> None:
        # <name> and <buildtool_depend> sit under <package>; <build_type> under <export>.
        if tag in _FIELDS and all(applies) and (
                len(stack) == 2 or (tag == "build_type" and len(stack) == 3)):
            texts[tag].append("".join(chunks).strip())
        chunks.clear()
        stack.pop()
        applies.pop()

    def data(chunk: str) -> None:
        if stack and stack[-1] in _FIELDS:
            chunks.append(chunk)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = data
    parser.Parse(text, True)
    return Manifest(name=next(iter(texts["name"]), ""),
                    build_type=next(iter(texts["build_type"]), ""),
                    buildtool_depends=tuple(texts["buildtool_depend"]))


def condition_holds(condition: str | None) -> bool | None:
    """Whether a REP 149 ``condition`` holds in a ROS 2 build (``None``: no condition → True;
    undecided → ``None``). Comparisons of ``$VAR`` with a literal, joined by ``and``/``or``
    without parentheses; anything else is undecided."""
    if condition is None or not condition.strip():
        return True
    if "(" in condition or ")" in condition:
        return None
    alternatives = []
    for alternative in re.split(r"\s+or\s+", condition.strip()):
        terms = []
        for term in re.split(r"\s+and\s+", alternative):
            match = _COMPARISON.match(term)
            if match is None:
                return None
            left, operator, right = (_operand(match.group(1)), match.group(2), _operand(match.group(3)))
            if left is None or right is None:
                terms.append(None)
            else:
                terms.append((left == right) == (operator == "=="))
        alternatives.append(False if False in terms else None if None in terms else True)
    return True if True in alternatives else None if None in alternatives else False


def _operand(word: str) -> str | None:
    """A literal, or the ROS 2 value of ``$VAR`` (``None`` when unknown)."""
    if word.startswith("$"):
        return _ROS2_ENVIRONMENT.get(word[1:])
    return word.strip("'\"")
