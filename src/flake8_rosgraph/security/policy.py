"""SROS2 access-control policies: which node may publish, subscribe, serve and call what.

An SROS2 policy file (``<policy version="0.2.0"><enclaves><enclave path=…><profiles><profile
ns="/" node="talker">…``) lists, per node, the topics it may publish and subscribe, the
services it may serve (``reply``) and call (``request``), the actions it may serve
(``execute``) and call. ``ros2 security create_permission`` turns it into the DDS permissions
a secured system enforces: an endpoint the profile does not grant is refused when the node
creates it. Profiles name topics relative to their ``ns`` (``~/x`` to the node) and may use
``*``, ``?`` and ``[…]`` patterns; a DENY rule wins over an ALLOW rule, and what no rule
grants is denied.

Profiles pull rules in with ``xi:include`` (sros2's ``common/node.xml`` grants what every
node uses: ``/rosout``, ``/parameter_events``, its parameter services). An include read from
the workspace adds its rules; sros2's common files, when they are not in the workspace, grant
only those built-in endpoints, which the graph does not hold; any other include that cannot be
read leaves the profile *open*: it may grant anything, so nothing is judged against it.
"""
from __future__ import annotations

import posixpath
import xml.parsers.expat
from dataclasses import dataclass
from pathlib import Path

from .. import inventory
from ..graph.model import Diagnostic, Location
from ..launch.xml_front import Element, XmlRefused, parse_xml
from ..safe_io import UnsafeFile, read_text

#: Policy element -> the permission attributes it may carry.
RULE_MODES = {"topics": ("publish", "subscribe"), "services": ("reply", "request"),
              "actions": ("execute", "call")}
#: The element naming one name in a rule list.
NAME_ELEMENT = {"topics": "topic", "services": "service", "actions": "action"}
#: sros2's shipped includes: they grant the endpoints every node has (logging, time,
#: parameters, lifecycle), none of which the graph holds.
BUILT_IN_INCLUDES = frozenset({"node.xml", "logging.xml", "time.xml", "parameters.xml",
                               "lifecycle_node.xml"})
#: Nested includes followed at most (a file including itself stops here).
MAX_INCLUDE_DEPTH = 8
SKIP_DIRS = frozenset({"build", "install", "log"})


@dataclass(frozen=True)
class PolicyRule:
    """One permission list: ``kind`` (topics, services, actions), ``mode`` (publish, reply, …),
    whether it allows, and its name patterns made absolute."""

    kind: str
    mode: str
    allow: bool
    patterns: tuple[str, ...]


@dataclass(frozen=True)
class PolicyProfile:
    """What one profile of a policy file grants one node."""

    location: Location                 # the profile element
    enclave: str
    node: str                          # fully qualified: /ns/node
    rules: tuple[PolicyRule, ...]
    #: An include it could not read may grant more: nothing is judged against it.
    open: bool


def policy_files(root: Path) -> list[str]:
    """Root-relative paths of the XML files whose root element is an SROS2 ``policy``."""
    found = []
    for dirpath, dirnames, filenames in inventory.walk(root, None):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(filenames):
            if name.endswith(".xml") and name != "package.xml":
                path = Path(dirpath) / name
                try:
                    head = read_text(path, root)[:4096]
                except (OSError, UnsafeFile, UnicodeDecodeError, ValueError):
                    continue  # too large or not text: no policy file
                if "<policy" in head and "<enclaves" in head:
                    found.append(path.relative_to(root).as_posix())
    return sorted(found)


def read_policies(root: Path, files: list[str], diagnostics: list[Diagnostic]) -> list[PolicyProfile]:
    """The profiles of the policy ``files``; a file that cannot be read is a diagnostic."""
    profiles: list[PolicyProfile] = []
    for rel in files:
        try:
            element = _parse(root, rel)
        except _Unread as why:
            diagnostics.append(Diagnostic(rel, why.line, f"SROS2 policy not read: {why}"))
            continue
        reader = _Reader(root, diagnostics)
        for enclaves in _children(element, "enclaves"):
            for enclave, where in reader.expanded(enclaves.children, rel)[0]:
                if enclave.tag == "enclave":
                    profiles += reader.profiles(enclave, where)
    return profiles


class _Unread(Exception):
    def __init__(self, message: str, line: int = 1) -> None:
        super().__init__(message)
        self.line = line


def _parse(root: Path, rel: str) -> Element:
    try:
        return parse_xml(read_text(root / rel, root))
    except xml.parsers.expat.ExpatError as exc:
        raise _Unread(f"not well-formed XML: {xml.parsers.expat.ErrorString(exc.code)}", exc.lineno) from None
    except XmlRefused as exc:
        raise _Unread(str(exc)) from None
    except (OSError, UnsafeFile, UnicodeDecodeError, ValueError) as exc:
        raise _Unread(f"cannot read file: {exc}") from None


def _children(element: Element, tag: str) -> list[Element]:
    return [child for child in element.children if child.tag == tag]


def _absolute(name: str, namespace: str, node: str) -> str:
    """A profile's name made absolute, as rcl expands it for that node."""
    if name.startswith("/"):
        return name
    if name.startswith("~"):
        return posixpath.join(namespace, node) + name[1:]
    return posixpath.join(namespace, name)


class _Reader:
    """Reads the enclaves and profiles of policy files, following their includes."""

    def __init__(self, root: Path, diagnostics: list[Diagnostic]) -> None:
        self.root, self.diagnostics = root, diagnostics

    def expanded(self, elements: list[Element], where: str, depth: int = 0
                 ) -> tuple[list[tuple[Element, str]], bool]:
        """``elements`` (of file ``where``) with each ``xi:include`` replaced by the included
        root's children, each with the file it stands in; and whether an include could not be
        read (what it grants is unknown)."""
        out: list[tuple[Element, str]] = []
        unread = False
        for element in elements:
            if element.tag.rsplit(":", 1)[-1] != "include" or "href" not in element.attrs:
                out.append((element, where))
                continue
            href = element.attrs["href"]
            target = posixpath.normpath(posixpath.join(posixpath.dirname(where), href))
            included = None
            if depth < MAX_INCLUDE_DEPTH and not href.startswith("/") and not target.startswith(".."):
                try:
                    included = _parse(self.root, target)
                except _Unread:
                    included = None
            if included is not None:
                inner, inner_unread = self.expanded(included.children, target, depth + 1)
                out += inner
                unread |= inner_unread
            elif posixpath.basename(href) not in BUILT_IN_INCLUDES:
                unread = True
                self.diagnostics.append(Diagnostic(
                    where, element.line, f"SROS2 policy include '{href}' not read: what it grants is "
                                         "unknown, so the profiles it holds or adds to are not judged (ROS206)",
                    "info"))
        return out, unread

    def profiles(self, enclave: Element, where: str) -> list[PolicyProfile]:
        out = []
        for profiles in _children(enclave, "profiles"):
            for profile, source in self.expanded(profiles.children, where)[0]:
                if profile.tag != "profile" or "node" not in profile.attrs:
                    continue
                namespace = "/" + profile.attrs.get("ns", "/").strip("/")
                node = profile.attrs["node"]
                elements, unread = self.expanded(profile.children, source)
                rules = tuple(self._rules([e for e, _ in elements], namespace, node))
                out.append(PolicyProfile(Location(source, profile.line, profile.column),
                                         enclave.attrs.get("path", "/"), posixpath.join(namespace, node),
                                         rules, unread))
        return out

    @staticmethod
    def _rules(elements: list[Element], namespace: str, node: str) -> list[PolicyRule]:
        rules = []
        for element in elements:
            modes = RULE_MODES.get(element.tag)
            if modes is None:
                continue
            names = tuple(_absolute(child.text.strip(), namespace, node)
                          for child in _children(element, NAME_ELEMENT[element.tag]) if child.text.strip())
            for mode in modes:
                verdict = element.attrs.get(mode)
                if verdict in ("ALLOW", "DENY"):
                    rules.append(PolicyRule(element.tag, mode, verdict == "ALLOW", names))
        return rules
