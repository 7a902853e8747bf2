"""ROS008 service-client-without-server."""
from __future__ import annotations

from .absence import AbsenceRule


class ServiceClientWithoutServer(AbsenceRule):
    """## What it does
    Checks for service clients whose service no node of the analysed workspace
    serves.

    The end is compared with every service name served in the workspace,
    connected or not, with a compatible type. A *near name* — a typo (swapped,
    missing, doubled or changed characters, case, singular/plural of the last
    word), the written name resolved as private (`~/x`), relative or absolute
    in its node, one namespace token more or less, or one `_`-word more or
    less at an end of a namespace token (`/qr_detection` for `/qr_detection_pkg`)
    — is named in the message ("did you mean ...?") with its location as
    related location.

    ## Why is this bad?
    `wait_for_service()` never returns (or times out on every call) and
    `call_async()` futures never complete. The cause is usually a misspelt
    service name or a server that lives in another namespace.

    ## Known problems
    Services served by C++ nodes outside the workspace, or inside it under
    names the analysis cannot resolve (Nav2, ros2_control, drivers), look
    unserved.
    The rule reports only a client of a node whose other clients reach
    servers of the workspace; it stays quiet (unless a near name
    is served) when none of the node's clients is served here, when several
    nodes call the service, or when the workspace only calls into the
    service's namespace (`/local_costmap/clear_...`: another node's
    services). The services every node serves itself (parameter services
    such as `<node>/get_parameters`, `<node>/get_type_description`, logger
    services, and the lifecycle services of lifecycle nodes) are exempt. It
    also stays quiet when some server's name could not be resolved and its
    type and known end do not rule the match out (a slip of the pen of a
    fully known served name of the same type is reported all the same). A client whose name is known only
    partly (`param if remote else 'add'`) is never reported.
    Which names count as near, how test fixtures are kept apart from
    production nodes, and how a changed-files run shows a near-name finding
    are as for ROS001 (see its Known problems).

    ## Example
    ```python
    self.create_service(AddTwoInts, 'add_two_ints', self.add)      # server node
    self.create_client(AddTwoInts, 'add_two_int')                  # client node
    ```

    ## Use instead
    ```python
    self.create_client(AddTwoInts, 'add_two_ints')
    ```

    ## Options
    - `--rosgraph-external-topics` (`ROSGRAPH_EXTERNAL_TOPICS`): also takes
      service names served outside the workspace.
    """

    code = "ROS008"
    name = "service-client-without-server"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a service client's service has no server"
    kind = "clients"
    missing = "server"
