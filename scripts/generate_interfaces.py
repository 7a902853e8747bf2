#!/usr/bin/env python3
"""Regenerate ``src/flake8_rosgraph/interfaces/standard.json`` from real interface files.

Usage::

    scripts/generate_interfaces.py CHECKOUTS_DIR [-o OUTPUT]

``CHECKOUTS_DIR`` holds one folder per source repository (``common_interfaces``,
``rcl_interfaces``, ``example_interfaces``, ``geometry2``, ``unique_identifier_msgs``,
``demos``), each a checkout; a file ``CHECKOUTS_DIR/<repo>.commit`` (or the checkout's
``.git``) names the commit, which is recorded in the output. Only the packages listed in
:data:`PACKAGES` are kept. The output holds facts only — each message's fields with fully
qualified types and its constant names — never the files' text or comments.
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


def generate(checkouts: Path, packages: dict[str, tuple[str, ...]] = PACKAGES) -> dict:
    """The JSON document for the checkouts under ``checkouts``; missing packages are an error."""
    messages: dict[str, list[str]] = {}
    sources = []
    for repo, wanted in sorted(packages.items()):
        checkout = checkouts / repo.split("/", 1)[1]
        if not checkout.is_dir():
            raise SystemExit(f"missing checkout {checkout} (for {repo})")
        catalogue = Catalogue()
        catalogue.add_tree(checkout)
        if catalogue.problems:
            raise SystemExit("\n".join(f"{path}: {why}" for path, why in catalogue.problems))
        found = {key.split("/", 1)[0] for key in catalogue.messages}
        missing = sorted(set(wanted) - found)
        if missing:
            raise SystemExit(f"{repo}: packages not found: {', '.join(missing)}")
        for key, definition in catalogue.messages.items():
            if key.split("/", 1)[0] in wanted:
                messages[key] = definition.lines()
        sources.append({"repository": f"github:{repo}", "commit": commit_of(checkout),
                        "packages": sorted(wanted)})
    return {"generated_by": "scripts/generate_interfaces.py", "sources": sources,
            "messages": dict(sorted(messages.items()))}


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
