"""What the workspace's metadata says: its packages, the classes they register, its launch files.

The packages and their executables (:mod:`.launch.packages`), the classes packages register
with frameworks (:mod:`.registrations`), the XML/YAML launch files (:mod:`.launch.discover`),
which files are Python (:mod:`.workspace`) and the packages' own interface (message)
files (:mod:`.interfaces.catalogue`) are read from manifests, build files, plugin
and robot descriptions, shebangs and C++ sources — never from the Python modules an edit
usually touches. Read together, they are kept together
between runs (:func:`.cache.metadata_key`), so an edit to Python code does not read them again.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from .graph.model import Diagnostic, internal_error
from .interfaces.catalogue import InterfaceFile, interface_files
from .launch.discover import frontend_launch_files
from .launch.packages import PackageIndex, find_packages
from .registrations import registered_classes
from .security.policy import PolicyProfile, policy_files, read_policies
from . import workspace


@dataclass
class WorkspaceMetadata:
    packages: PackageIndex = field(default_factory=PackageIndex)
    #: ``module.Class`` a framework instantiates -> the base class type its registration writes.
    registered: dict[str, str] = field(default_factory=dict)
    #: Root-relative paths of the XML and YAML launch files.
    launch_files: list[str] = field(default_factory=list)
    #: Root-relative paths of the Python files (see :func:`.workspace.python_files`: which files
    #: without a suffix are programs is read from shebangs and build files, not from modules).
    python_files: list[str] = field(default_factory=list)
    #: The workspace packages' ``msg``/``srv``/``action`` files, in path order.
    interface_files: list[InterfaceFile] = field(default_factory=list)
    #: The SROS2 policy files' profiles (:mod:`.security.policy`).
    policy_profiles: list[PolicyProfile] = field(default_factory=list)
    #: What could not be read, each naming the file or package.
    diagnostics: list[Diagnostic] = field(default_factory=list)


def read_metadata(root: Path) -> WorkspaceMetadata:
    """The metadata under ``root`` (nothing around a single file); a failure in one part costs that
    part only, with an error diagnostic."""
    meta = WorkspaceMetadata()
    if not root.is_dir():
        return meta
    try:
        meta.packages = find_packages(root)
        meta.diagnostics.extend(meta.packages.diagnostics)
    except Exception as exc:
        meta.diagnostics.append(internal_error("packages not read", exc))
    try:
        meta.registered, problems = registered_classes(root)
        meta.diagnostics.extend(problems)
    except Exception as exc:
        meta.diagnostics.append(internal_error("classes registered with frameworks not read", exc))
    try:
        meta.launch_files = frontend_launch_files(root, meta.diagnostics)
    except Exception as exc:
        meta.diagnostics.append(internal_error("launch files not found", exc))
    meta.python_files = [path.relative_to(root).as_posix()
                         for path in workspace.python_files(root, meta.diagnostics)]
    try:
        meta.interface_files = interface_files(root, root)
    except Exception as exc:
        meta.diagnostics.append(internal_error("interface definitions not read", exc))
    try:
        meta.policy_profiles = read_policies(root, policy_files(root), meta.diagnostics)
    except Exception as exc:
        meta.diagnostics.append(internal_error("SROS2 policy files not read", exc))
    return meta
