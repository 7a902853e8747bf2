"""YAML launch files (``*.launch.yaml``) → :mod:`.actions`.

The launch_yaml layout: a top-level ``launch:`` list whose items are
one-key mappings ``{tag: {attributes…}}``; children of ``group`` are under
``children``, a node's remappings under ``remap`` and parameters under
``param`` (``name``/``value``, nested ``param`` lists, or ``from`` a file),
an include's arguments under ``arg``.  Tag spellings with ``_`` and ``-``
are both accepted.  Values are strings with ``$(…)`` substitutions, or YAML
scalars for parameter values.
"""
from __future__ import annotations

from typing import Any

from ..graph.model import Location
from .actions import (Action, Condition, DeclareArgument, GroupAction, Include, NodeAction,
                      PushNamespace, SetConfiguration, SetParameter, SetRemap, Subst, Unsupported)
from .frontend_subst import parse_substitutions
from .yaml_reader import YamlError, YNode, read_yaml


def _text(value: YNode | None) -> Subst | None:
    if value is None or value.value is None:
        return None
    raw = value.value
    if isinstance(raw, bool):
        return parse_substitutions("true" if raw else "false")
    return parse_substitutions(str(raw))


def _items(value: YNode | None) -> list[YNode]:
    if value is None:
        return []
    if isinstance(value.value, list):
        return value.value
    return [value]


def _attrs(node: YNode) -> dict[str, YNode]:
    return node.value if isinstance(node.value, dict) else {}


def _condition(attrs: dict[str, YNode]) -> Condition | None:
    if "if" in attrs:
        return Condition(_text(attrs["if"]) or parse_substitutions(""))
    if "unless" in attrs:
        return Condition(_text(attrs["unless"]) or parse_substitutions(""), negate=True)
    return None


def _param_value(value: YNode) -> Any:
    if isinstance(value.value, str) and "$(" in value.value:
        return value.value
    return value.plain()


class YamlFront:
    def __init__(self, path: str) -> None:
        self.path = path

    def where(self, node: YNode) -> Location:
        return Location(self.path, node.line, node.column)

    def actions(self, entries: list[YNode]) -> list[Action]:
        out: list[Action] = []
        for entry in entries:
            if not isinstance(entry.value, dict) or len(entry.value) != 1:
                out.append(Unsupported(self.where(entry), "a launch entry that is not a one-key mapping"))
                continue
            (tag, body), = entry.value.items()
            out.extend(self.action(tag.replace("-", "_"), body, Location(self.path, entry.line, entry.column)))
        return out

    def action(self, tag: str, body: YNode, at: Location) -> list[Action]:
        attrs = _attrs(body)
        text = {k: _text(v) for k, v in attrs.items() if not isinstance(v.value, (list, dict))}
        if tag in ("node", "lifecycle_node"):
            return [self.node(attrs, text, at, tag == "lifecycle_node")]
        if tag == "group":
            scoped = str(attrs["scoped"].value).lower() != "false" if "scoped" in attrs else True
            inner: list[Action] = []
            ns = text.get("namespace") or text.get("ns")
            if ns is not None:
                inner.append(PushNamespace(at, ns))
            inner.extend(self.actions(_items(attrs.get("children"))))
            return [GroupAction(at, inner, scoped, _condition(attrs))]
        if tag == "push_ros_namespace":
            return [PushNamespace(at, text.get("namespace") or text.get("ns") or parse_substitutions(""),
                                  _condition(attrs))]
        if tag == "set_remap":
            return [SetRemap(at, text.get("from") or parse_substitutions(""),
                             text.get("to") or parse_substitutions(""), _condition(attrs))]
        if tag == "set_parameter":
            value = attrs.get("value")
            return [SetParameter(at, str(attrs["name"].value) if "name" in attrs else "",
                                 None if value is None else _param_value(value), _condition(attrs))]
        if tag == "arg":
            return [DeclareArgument(at, str(attrs["name"].value) if "name" in attrs else "",
                                    text.get("default"))]
        if tag == "let":
            return [SetConfiguration(at, str(attrs["name"].value) if "name" in attrs else "",
                                     text.get("value") or parse_substitutions(""))]
        if tag == "include":
            args = [(str(_attrs(a).get("name", YNode("", 0)).value), _text(_attrs(a).get("value"))
                     or parse_substitutions(""))
                    for a in _items(attrs.get("arg"))]
            return [Include(at, text.get("file") or parse_substitutions(""), args, _condition(attrs))]
        if tag == "timer":
            return [GroupAction(at, self.actions(_items(attrs.get("children"))), scoped=False)]
        return [Unsupported(at, f"'{tag}'")]

    def node(self, attrs: dict[str, YNode], text: dict[str, Subst | None], at: Location,
             lifecycle: bool) -> NodeAction:
        node = NodeAction(at, text.get("pkg"), text.get("exec"), text.get("name"),
                          text.get("namespace") or text.get("ns"), condition=_condition(attrs),
                          lifecycle=lifecycle)
        for remap in _items(attrs.get("remap")):
            fields = _attrs(remap)
            node.remaps.append((_text(fields.get("from")) or parse_substitutions(""),
                                _text(fields.get("to")) or parse_substitutions(""),
                                self.where(remap)))
        for param in _items(attrs.get("param")):
            self.param(param, "", node)
        return node

    def param(self, param: YNode, prefix: str, node: NodeAction) -> None:
        fields = _attrs(param)
        if "from" in fields:
            node.param_files.append((_text(fields["from"]) or parse_substitutions(""), self.where(param)))
            return
        name = prefix + str(fields["name"].value) if "name" in fields else prefix
        if "value" in fields:
            node.params.append((name, _param_value(fields["value"]), self.where(param)))
        for child in _items(fields.get("param")):
            self.param(child, name + ".", node)


def read_yaml_launch(path: str, text: str) -> list[Action]:
    """The actions of a YAML launch file; raises :class:`YamlError` on what it cannot read."""
    document = read_yaml(text)
    if not isinstance(document.value, dict) or "launch" not in document.value:
        raise YamlError(document.line, "no top-level 'launch:' list")
    return YamlFront(path).actions(_items(document.value["launch"]))
