"""XML launch files (``*.launch.xml``) → :mod:`.actions`.

Read with :mod:`xml.parsers.expat` (no external entities, no DTD fetching)
into a small element tree that keeps each element's line and column, since
findings point at the ``<node>`` or ``<remap>`` a developer must edit.  Tags
and attributes follow launch_xml / launch_ros (``node``, ``lifecycle_node``,
``remap``, ``param`` (inline, nested, or ``from=`` a file), ``group``,
``push-ros-namespace``, ``set_remap``, ``set_parameter``, ``include`` with
``arg`` children, ``arg``, ``let``, ``if``/``unless``); both the ``_`` and
``-`` spellings of tag names are accepted, as launch does.
"""
from __future__ import annotations

import xml.parsers.expat
from dataclasses import dataclass, field

from ..graph.model import Location
from .actions import (Action, Condition, DeclareArgument, GroupAction, Include, NodeAction,
                      PushNamespace, SetConfiguration, SetParameter, SetRemap, Subst, Unsupported)
from .frontend_subst import parse_substitutions
from .yaml_reader import scalar


@dataclass
class Element:
    tag: str
    attrs: dict[str, str]
    line: int
    column: int
    children: list["Element"] = field(default_factory=list)
    #: The character data directly inside it (``<topic>chatter</topic>``).
    text: str = ""


#: Deepest element nesting read (real launch files nest a handful of groups).
MAX_XML_DEPTH = 100


class XmlRefused(ValueError):
    """A document this tool will not read (a DTD with declarations, nesting beyond the limit)."""


def safe_parser() -> "xml.parsers.expat.XMLParserType":
    """An expat parser that refuses a DTD internal subset and entity declarations before expanding any.

    Launch files and manifests never need them; refusing them is what keeps
    "billion laughs" and similar entity expansions from costing time or memory.
    """
    parser = xml.parsers.expat.ParserCreate()
    parser.SetParamEntityParsing(xml.parsers.expat.XML_PARAM_ENTITY_PARSING_NEVER)

    def doctype(name: str, system_id: str | None, public_id: str | None, internal: int) -> None:
        if internal:
            raise XmlRefused(f"line {parser.CurrentLineNumber}: a DOCTYPE with declarations is not read")

    def entity(*_: object) -> None:
        raise XmlRefused(f"line {parser.CurrentLineNumber}: entity declarations are not read")

    parser.StartDoctypeDeclHandler = doctype
    parser.EntityDeclHandler = entity
    return parser


def parse_xml(text: str) -> Element:
    """The document's root element; raises ``ExpatError`` or :class:`XmlRefused` with a line."""
    parser = safe_parser()
    stack: list[Element] = []
    roots: list[Element] = []

    def start(tag: str, attrs: dict[str, str]) -> None:
        if len(stack) >= MAX_XML_DEPTH:
            raise XmlRefused(f"line {parser.CurrentLineNumber}: elements nested deeper than {MAX_XML_DEPTH}")
        element = Element(tag, dict(attrs), parser.CurrentLineNumber, parser.CurrentColumnNumber + 1)
        (stack[-1].children if stack else roots).append(element)
        stack.append(element)

    def end(tag: str) -> None:
        stack.pop()

    def data(text: str) -> None:
        if stack:
            stack[-1].text += text

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = data
    parser.Parse(text, True)
    return roots[0]


def _tag(element: Element) -> str:
    return element.tag.replace("-", "_")


def _subst(value: str | None) -> Subst | None:
    return None if value is None else parse_substitutions(value)


def _condition(element: Element) -> Condition | None:
    if "if" in element.attrs:
        return Condition(parse_substitutions(element.attrs["if"]))
    if "unless" in element.attrs:
        return Condition(parse_substitutions(element.attrs["unless"]), negate=True)
    return None


def typed(value: str) -> object:
    """A ``value=`` attribute as launch types it (YAML rules: ``1`` int, ``true`` bool)."""
    if "$(" in value:
        return value
    return scalar(value.strip())


class XmlFront:
    def __init__(self, path: str) -> None:
        self.path = path

    def where(self, element: Element) -> Location:
        return Location(self.path, element.line, element.column)

    def actions(self, root: Element) -> list[Action]:
        return [a for child in root.children for a in self.action(child)]

    def action(self, el: Element) -> list[Action]:
        tag = _tag(el)
        at = self.where(el)
        if tag in ("node", "lifecycle_node"):
            return [self.node(el, lifecycle=tag == "lifecycle_node")]
        if tag == "group":
            scoped = el.attrs.get("scoped", "true").lower() != "false"
            inner: list[Action] = []
            if "ns" in el.attrs or "namespace" in el.attrs:
                inner.append(PushNamespace(at, parse_substitutions(
                    el.attrs.get("namespace", el.attrs.get("ns", "")))))
            inner.extend(a for child in el.children for a in self.action(child))
            return [GroupAction(at, inner, scoped, _condition(el))]
        if tag == "push_ros_namespace":
            return [PushNamespace(at, parse_substitutions(el.attrs.get("namespace", el.attrs.get("ns", ""))),
                                  _condition(el))]
        if tag == "set_remap":
            return [SetRemap(at, parse_substitutions(el.attrs.get("from", "")),
                             parse_substitutions(el.attrs.get("to", "")), _condition(el))]
        if tag == "set_parameter":
            return [SetParameter(at, el.attrs.get("name", ""), typed(el.attrs.get("value", "")), _condition(el))]
        if tag == "arg":
            return [DeclareArgument(at, el.attrs.get("name", ""), _subst(el.attrs.get("default")))]
        if tag == "let":
            return [SetConfiguration(at, el.attrs.get("name", ""),
                                     parse_substitutions(el.attrs.get("value", "")))]
        if tag == "include":
            args = [(c.attrs.get("name", ""), parse_substitutions(c.attrs.get("value", "")))
                    for c in el.children if _tag(c) == "arg"]
            return [Include(at, parse_substitutions(el.attrs.get("file", "")), args, _condition(el))]
        if tag == "timer":
            return [GroupAction(at, self.actions(el), scoped=False)]
        return [Unsupported(at, f"<{el.tag}>")]

    def node(self, el: Element, lifecycle: bool) -> NodeAction:
        attrs = el.attrs
        node = NodeAction(self.where(el), _subst(attrs.get("pkg")), _subst(attrs.get("exec")),
                          _subst(attrs.get("name")), _subst(attrs.get("namespace", attrs.get("ns"))),
                          condition=_condition(el), lifecycle=lifecycle)
        for child in el.children:
            tag = _tag(child)
            if tag == "remap":
                node.remaps.append((parse_substitutions(child.attrs.get("from", "")),
                                    parse_substitutions(child.attrs.get("to", "")),
                                    self.where(child)))
            elif tag == "param":
                self.param(child, "", node)
        return node

    def param(self, el: Element, prefix: str, node: NodeAction) -> None:
        if "from" in el.attrs:
            node.param_files.append((parse_substitutions(el.attrs["from"]), self.where(el)))
            return
        name = prefix + el.attrs.get("name", "")
        if "value" in el.attrs:
            node.params.append((name, typed(el.attrs["value"]), self.where(el)))
        for child in el.children:
            if _tag(child) == "param":
                self.param(child, name + ".", node)


def read_xml_launch(path: str, text: str) -> list[Action]:
    """The actions of an XML launch file (``path`` root-relative, for locations)."""
    return XmlFront(path).actions(parse_xml(text))
