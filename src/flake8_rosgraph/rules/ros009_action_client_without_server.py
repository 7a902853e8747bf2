"""ROS009 action-client-without-server."""
from __future__ import annotations

from .absence import AbsenceRule


class ActionClientWithoutServer(AbsenceRule):
    """## What it does
    Checks for action clients whose action no node of the analysed workspace
    serves.

    The end is compared with every action name served in the workspace,
    connected or not, with a compatible type. A *near name* — a typo (swapped,
    missing, doubled or changed characters, case, singular/plural of the last
    word), the written name resolved as private (`~/x`), relative or absolute
    in its node, one namespace token more or less, or one `_`-word more or
    less at an end of a namespace token (`/qr_detection` for `/qr_detection_pkg`)
    — is named in the message ("did you mean ...?") with its location as
    related location.

    ## Why is this bad?
    `wait_for_server()` blocks forever and goals are never accepted. The cause
    is usually a misspelt action name or a server in another namespace.

    ## Known problems
    Actions served by C++ nodes outside the workspace, or created through
    templates whose names the analysis cannot resolve (Nav2's
    `navigate_to_pose`, MoveIt's `move_action`, controllers'
    `follow_joint_trajectory`), look unserved;
    declare them as external names. The rule reports only an action client of
    a node whose other action clients reach servers of the workspace; it
    stays quiet (unless a near name is served) when none of them does,
    when several nodes use the action, or when the workspace only uses
    actions of the action's namespace in this role. It also stays quiet when
    some action server's name could not be resolved and its type and known
    end do not rule the match out (a slip of the pen of a fully known served
    name of the same type is reported all the same). A client whose name is known only partly
    (`param if remote else 'fibonacci'`) is never reported.
    Which names count as near, how test fixtures are kept apart from
    production nodes, and how a changed-files run shows a near-name finding
    are as for ROS001 (see its Known problems).

    ## Example
    ```python
    ActionServer(self, Fibonacci, 'fibonacci', self.execute)   # server node
    ActionClient(self, Fibonacci, 'fibonaci')                   # client node
    ```

    ## Use instead
    ```python
    ActionClient(self, Fibonacci, 'fibonacci')
    ```

    ## Options
    - `--rosgraph-external-topics` (`ROSGRAPH_EXTERNAL_TOPICS`): also takes
      action names served outside the workspace.
    """

    code = "ROS009"
    name = "action-client-without-server"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "an action client's action has no server"
    kind = "action_clients"
    missing = "server"
