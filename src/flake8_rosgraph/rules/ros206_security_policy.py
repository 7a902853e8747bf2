"""ROS206 security-policy."""
from __future__ import annotations

from fnmatch import fnmatchcase
from typing import Iterator

from ..graph.model import RosGraph
from ..security.policy import PolicyProfile
from .base import Finding, Rule, RuleConfig
from .vocabulary import ENTITY_NOUN

#: Graph entity kind -> the policy list and permission that grant it.
PERMISSION = {"publishers": ("topics", "publish"), "subscriptions": ("topics", "subscribe"),
              "services": ("services", "reply"), "clients": ("services", "request"),
              "action_servers": ("actions", "execute"), "action_clients": ("actions", "call")}


def _granted(profile: PolicyProfile, kind: str, mode: str, name: str) -> bool:
    """DDS takes a DENY rule over an ALLOW rule, and denies what no rule grants."""
    matching = [rule.allow for rule in profile.rules if rule.kind == kind and rule.mode == mode
                and any(fnmatchcase(name, pattern) for pattern in rule.patterns)]
    return bool(matching) and all(matching)


class SecurityPolicy(Rule):
    """## What it does
    Checks each node's publishers, subscriptions, services, clients and
    actions against the SROS2 access-control policy files in the workspace
    (`<policy><enclaves><enclave><profiles><profile ns=… node=…>`): an
    endpoint that no profile of that node grants — its name in no ALLOW list
    of the right permission (`publish`, `subscribe`, `reply`, `request`,
    `execute`, `call`), or in a DENY list — is reported.

    ## Why is this bad?
    `ros2 security create_permission` turns the policy into the DDS
    permissions a secured system enforces (`ROS_SECURITY_ENABLE=true`,
    `ROS_SECURITY_STRATEGY=Enforce`): creating an endpoint the permissions do
    not grant fails, so the node that runs fine in development dies, or loses
    that connection, on the secured robot. A topic renamed in code but not in
    the policy is the usual cause.

    ## Known problems
    Nodes are matched to profiles by the fully qualified name they run
    under (a launch file's name and namespace applied); a node whose name is
    unknown, or that no profile names, is not judged. The enclave a node runs in is chosen at launch, so an
    endpoint is reported only when none of the node's profiles, in any
    enclave, grants it. Profiles include rules with `xi:include`: files in the
    workspace are read; sros2's shipped `common/` files grant only what every
    node has (`/rosout`, `/parameter_events`, its parameter services), which
    is never judged; a profile with any other include that cannot be read may
    grant anything and is not judged. Endpoints whose names the analysis does
    not know are not judged.

    ## Example
    ```xml
    <profile ns="/" node="base_driver">
      <topics subscribe="ALLOW"><topic>cmd_vel</topic></topics>
      <topics publish="ALLOW"><topic>odom</topic></topics>
    </profile>
    ```
    ```python
    self.create_publisher(Odometry, 'odometry', 10)
    ```

    ## Use instead
    ```python
    self.create_publisher(Odometry, 'odom', 10)
    ```
    or grant `odometry` in the profile.

    ## Options
    None.
    """

    code = "ROS206"
    name = "security-policy"
    level = "error"
    precision = "high"
    summary = "an endpoint that the node's SROS2 access-control policy does not grant"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        profiles: dict[str, list[PolicyProfile]] = {}
        for profile in graph.policies:
            profiles.setdefault(profile.node, []).append(profile)
        for node in graph.nodes:
            mine = profiles.get(node.fqn or "")
            if not mine or any(p.open for p in mine):
                continue
            for entity in node.entities:
                permission = PERMISSION.get(entity.kind)
                if permission is None or entity.name is None or entity.partial or entity.invalid is not None:
                    continue
                if not any(_granted(p, *permission, entity.name) for p in mine):
                    where = ", ".join(f"enclave '{p.enclave}'" for p in mine)
                    yield Finding(entity.location, self.code,
                                  f"{ENTITY_NOUN[entity.kind]} '{entity.name}' of node '{node.fqn}' is not "
                                  f"granted '{permission[1]}' by its SROS2 policy ({where}): a secured "
                                  "system refuses it",
                                  tuple((p.location, f"policy profile of '{p.node}'") for p in mine))
