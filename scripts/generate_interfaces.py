#!/usr/bin/env python3
"""Regenerate ``src/flake8_rosgraph/interfaces/standard.json`` from real interface files.

Usage::

    scripts/generate_interfaces.py CHECKOUTS_DIR [-o OUTPUT]

``CHECKOUTS_DIR`` holds a folder per source repository of :data:`PACKAGES`, named after it
(``common_interfaces``), or one per ROS distribution's branch of it (``control_msgs@humble``,
``control_msgs@jazzy``, ``control_msgs@master``); a file ``<folder>.commit`` (or the
checkout's ``.git``) names the commit, which is recorded in the output. Only the packages
listed in :data:`PACKAGES` are kept. A message that reads differently on two branches is left
out (listed under ``differs``): the table must hold for whichever distribution the user runs,
and a field one distribution lacks would be reported as missing there. The output holds facts
only — each message's fields with fully qualified types and its constant names — never the
files' text or comments.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "src"))

from flake8_rosgraph.interfaces.catalogue import Catalogue  # noqa: E402

#: Source repository (on GitHub) → the standard packages taken from it.
PACKAGES: dict[str, tuple[str, ...]] = {
    "ros2/common_interfaces": (
        "std_msgs", "geometry_msgs", "sensor_msgs", "nav_msgs", "std_srvs", "diagnostic_msgs",
        "visualization_msgs", "trajectory_msgs", "shape_msgs", "actionlib_msgs", "stereo_msgs"),
    "ros2/rcl_interfaces": (
        "builtin_interfaces", "action_msgs", "rcl_interfaces", "lifecycle_msgs", "rosgraph_msgs",
        "statistics_msgs", "composition_interfaces", "service_msgs", "type_description_interfaces"),
    "ros2/example_interfaces": ("example_interfaces",),
    "ros2/geometry2": ("tf2_msgs",),
    "ros2/unique_identifier_msgs": ("unique_identifier_msgs",),
    "ros2/demos": ("action_tutorials_interfaces",),
    # Beyond the core: the message packages Python nodes import most (counted over 55 public
    # repositories), each read from its humble, jazzy and rolling branches where it has them.
    "ros-navigation/navigation2": ("nav2_msgs",),
    "ros-perception/vision_msgs": ("vision_msgs",),
    "ros-controls/control_msgs": ("control_msgs",),
    "moveit/moveit_msgs": ("moveit_msgs",),
    "ros-geographic-info/geographic_info": ("geographic_msgs",),
    "ros-drivers/ackermann_msgs": ("ackermann_msgs",),
    "ros/ros_tutorials": ("turtlesim",),
    "ros-controls/ros2_control": ("controller_manager_msgs",),
    "iRobotEducation/irobot_create_msgs": ("irobot_create_msgs",),
    "ros-planning/navigation_msgs": ("map_msgs",),
}
DEFAULT_OUTPUT = Path(__file__).resolve().parents[1] / "src/flake8_rosgraph/interfaces/standard.json"


def commit_of(checkout: Path) -> str:
    recorded = checkout.with_name(checkout.name + ".commit")
    if recorded.is_file():
        return recorded.read_text(encoding="utf-8").strip()
    try:
        return subprocess.run(["git", "-C", str(checkout), "rev-parse", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def checkouts_of(checkouts: Path, repo: str) -> list[tuple[str | None, Path]]:
    """The checkouts of ``repo``: its one folder (ref ``None``), or one per branch, by branch."""
    name = repo.split("/", 1)[1]
    single = checkouts / name
    if single.is_dir():
        return [(None, single)]
    return [(folder.name.split("@", 1)[1], folder)
            for folder in sorted(checkouts.glob(f"{name}@*")) if folder.is_dir()]


def _definitions(checkout: Path, repo: str, wanted: tuple[str, ...]) -> dict[str, list[str]]:
    catalogue = Catalogue()
    catalogue.add_tree(checkout)
    if catalogue.problems:
        raise SystemExit("\n".join(f"{path}: {why}" for path, why in catalogue.problems))
    found = {key.split("/", 1)[0] for key in catalogue.messages}
    missing = sorted(set(wanted) - found)
    if missing:
        raise SystemExit(f"{repo} ({checkout.name}): packages not found: {', '.join(missing)}")
    return {key: definition.lines() for key, definition in catalogue.messages.items()
            if key.split("/", 1)[0] in wanted}


def generate(checkouts: Path, packages: dict[str, tuple[str, ...]] = PACKAGES) -> dict:
    """The JSON document for the checkouts under ``checkouts``; missing packages are an error."""
    messages: dict[str, list[str]] = {}
    differs: set[str] = set()
    sources = []
    for repo, wanted in sorted(packages.items()):
        found = checkouts_of(checkouts, repo)
        if not found:
            raise SystemExit(f"missing checkout {checkouts / repo.split('/', 1)[1]} (for {repo})")
        read: dict[str, list[str]] = {}
        for _, checkout in found:
            for key, lines in _definitions(checkout, repo, wanted).items():
                if read.setdefault(key, lines) != lines:
                    differs.add(key)
        messages.update((key, lines) for key, lines in read.items() if key not in differs)
        source: dict = {"repository": f"github:{repo}"}
        if found[0][0] is None:
            source["commit"] = commit_of(found[0][1])
        else:
            source["commits"] = {ref: commit_of(checkout) for ref, checkout in found}
        source["packages"] = sorted(wanted)
        sources.append(source)
    document = {"generated_by": "scripts/generate_interfaces.py", "sources": sources,
                "messages": dict(sorted(messages.items()))}
    if differs:
        document["differs"] = sorted(differs)
    return document


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("checkouts", type=Path)
    parser.add_argument("-o", "--output", type=Path, default=DEFAULT_OUTPUT)
    args = parser.parse_args(argv)
    document = generate(args.checkouts, PACKAGES)
    text = json.dumps(document, indent=0, sort_keys=False, separators=(",", ":")) + "\n"
    args.output.write_text(text, encoding="utf-8")
    print(f"{len(document['messages'])} message definitions → {args.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
