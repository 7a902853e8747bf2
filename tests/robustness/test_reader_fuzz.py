"""Fuzzing the launch, YAML, XML, CMake and substitution readers: only their own errors, in bounded time.

Hypothesis builds documents from the characters and fragments these formats
are made of (and mutates realistic launch and parameter files). Every reader
must either return or raise its documented error — never an ``IndexError``,
a ``RecursionError`` or a hang — and a launch file that reads must also
execute statically. Deterministic (``derandomize``, no example database) and
bounded (a fixed number of examples per reader, about 20 s in all).
"""
from __future__ import annotations

import xml.parsers.expat
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from flake8_rosgraph.launch.execute import Executor
from flake8_rosgraph.launch.frontend_subst import parse_substitutions
from flake8_rosgraph.launch.model import ExecutableRef
from flake8_rosgraph.launch.packages import PackageIndex, cmake_commands
from flake8_rosgraph.launch.param_files import _sections
from flake8_rosgraph.launch.xml_front import XmlRefused, read_xml_launch
from flake8_rosgraph.launch.yaml_front import read_yaml_launch
from flake8_rosgraph.launch.yaml_reader import YamlError, read_yaml

from .metadata_workspace import BRINGUP, CMAKE, PARAMS

FUZZ = settings(max_examples=500, derandomize=True, database=None, deadline=None,
                suppress_health_check=list(HealthCheck))

YAML_LAUNCH = """\
launch:
  - arg: {name: robot, default: r1}
  - group:
      namespace: $(var robot)
      children:
        - node:
            pkg: chat_pkg
            exec: listener
            remap: [{from: chatter, to: /shared}]
            param:
              - {name: rate, value: 2.0}
              - from: $(find-pkg-share chat_pkg)/config/listener.yaml
  - include: {file: "$(dirname)/other.launch.yaml", arg: [{name: x, value: "1"}]}
base: &base {a: 1, b: [1, 2]}
merged:
  <<: *base
  c: |
    text
"""

YAML_PIECES = ["\n", "  ", "- ", ": ", "[", "]", "{", "}", ",", "&a ", "*a", "<<: ", "'", '"', "#", "|",
               ">", "!", "launch:", "node:", "group:", "children:", "pkg: p", "exec: e", "x", "1", "\t",
               "---", "$(var x)", "ros__parameters:", "\\", "%YAML"]
XML_PIECES = ["<launch>", "</launch>", "<group>", "</group>", '<node pkg="p" exec="e"/>', "<node ", "/>",
              ">", "<", '<remap from="a" to="b"/>', '<param name="n" value="1"/>', '<include file="f.xml"/>',
              '<!DOCTYPE l [<!ENTITY e "x">]>', "&e;", "&amp;", "<![CDATA[", "]]>", '"', "'", "$(var x)",
              " ", "\n", "<?xml version='1.0'?>", "<arg name='x' default='1'/>", "<let name='y' value='$(var x)'/>"]
SUBST_PIECES = ["$(", ")", "var ", "find-pkg-share ", "dirname", "env ", "'", '"', " ", "x", "/", "$(var x)"]
CMAKE_PIECES = ["add_executable(", "install(", "PROGRAMS ", "DESTINATION ", "lib/${PROJECT_NAME}", ")", "(",
                "#", "#[[", "]]", "[=[", "]=]", '"', "\\", " ", "\n", "x.py", "${VAR}", "\t"]


def _documents(pieces: list[str], seeds: list[str]) -> st.SearchStrategy[str]:
    built = st.lists(st.sampled_from(pieces), max_size=80).map("".join)

    def mutate(seed: str, cut: int, insert: str) -> str:
        at = cut % (len(seed) + 1)
        return seed[:at] + insert + seed[at:]

    mutated = st.builds(mutate, st.sampled_from(seeds), st.integers(0, 10_000),
                        st.lists(st.sampled_from(pieces), max_size=6).map("".join))
    return st.one_of(built, mutated, st.text(max_size=200))


def _execute(actions: list) -> None:
    """Run the actions as a one-file system: what a read launch file goes through next."""
    executor = Executor(Path("."), PackageIndex(), lambda path: (actions, None),
                        lambda package, executable: ExecutableRef("unknown"))
    executor.system("fuzz.launch")


@FUZZ
@given(_documents(YAML_PIECES, [YAML_LAUNCH, PARAMS]))
def test_yaml_readers(text: str) -> None:
    try:
        document = read_yaml(text)
    except YamlError:
        return
    document.plain()
    _sections(document, [], "fuzz.yaml", [])
    try:
        actions = read_yaml_launch("fuzz.launch.yaml", text)
    except YamlError:
        return
    _execute(actions)


@FUZZ
@given(_documents(XML_PIECES, [BRINGUP]))
def test_xml_launch_reader(text: str) -> None:
    try:
        actions = read_xml_launch("fuzz.launch.xml", text)
    except (xml.parsers.expat.ExpatError, XmlRefused, IndexError):  # IndexError: no root element
        return
    _execute(actions)


@FUZZ
@given(_documents(SUBST_PIECES, ["$(find-pkg-share $(var pkg))/launch/$(var name).launch.py"]))
def test_substitutions(text: str) -> None:
    parse_substitutions(text)


@FUZZ
@given(_documents(CMAKE_PIECES, [CMAKE]))
def test_cmake_reader(text: str) -> None:
    for name, args in cmake_commands(text):
        assert name == name.lower() and all(isinstance(a, str) for a in args)
