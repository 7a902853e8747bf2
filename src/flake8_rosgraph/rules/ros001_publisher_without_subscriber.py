"""ROS001 publisher-without-subscriber."""
from __future__ import annotations

from .absence import AbsenceRule


class PublisherWithoutSubscriber(AbsenceRule):
    """## What it does
    Checks for topics that are published but that nothing in the analysed
    workspace subscribes to.

    The end is compared with every topic name subscribed in the workspace,
    connected or not, with a compatible type. A *near name* — a typo (swapped,
    missing, doubled or changed characters, case, singular/plural of the last
    word), the written name resolved as private (`~/x`), relative or absolute
    in its node, one namespace token more or less, or one `_`-word more or
    less at an end of a namespace token (`/qr_detection` for `/qr_detection_pkg`)
    — is named in the message ("did you mean ...?") with its location as
    related location.

    ## Why is this bad?
    Messages nobody receives are wasted work, and far more often the symptom of
    a wiring mistake: a typo in the topic name (`/cmd_vel` vs `/cmdvel`), a
    relative name that resolves into another namespace, or a subscriber that
    was renamed. ROS 2 reports none of these at run time; the system just sits
    idle.

    ## Known problems
    The rule sees the workspace's Python code and, as partner ends, the rclcpp
    calls of its C++ packages whose names are literal or simple constants
    (read with tree-sitter); topics consumed by C++ code it cannot resolve,
    robots, rviz, `ros2 topic echo` or bag recordings look unsubscribed. To stay useful on real repositories it reports only the
    *odd one out*: a topic of a node whose other publishers do feed the
    workspace. It stays quiet (unless a near name is subscribed) when
    none of the node's publishers has a subscriber here (a driver's or
    tool's outputs; a subscriber on a node of the same name, as when
    several executables run one driver class, is no other node), when several nodes publish the topic, when the
    workspace only publishes into the topic's namespace (`/camera/...`), or
    when its type is made for a tool (`visualization_msgs`: rviz draws the
    markers and interactive markers).
    On 15 public repositories this leaves 3 of 135 dangling ends reported.
    Infrastructure topics (`/rosout`, `/parameter_events`, `/tf`,
    `/tf_static`, `/clock`, `/diagnostics`, `/robot_description`,
    `/joint_states`, rviz tool topics) are exempt; a publisher of one's type
    under a slip of its name (`/tf_statics` of `tf2_msgs/msg/TFMessage`) is
    reported with it as near name (a namespace more or less is no slip). It also stays quiet when
    some subscription's topic name could not be resolved and its type and
    known end (a relative name on a node of unknown namespace ends in
    `/<name>`) do not rule the match out (a name a launch file makes unknown,
    such as a launch argument, only in its own package or launch file) — but not for a slip of the pen
    (spelling, case, plural, resolution) of a fully known subscribed name
    of the same type — and when another alternative of the same
    creation site (`'a' if sim else 'b'`) on the same node is connected
    (each launched instance is a configuration of its own). A topic name known
    only partly (`param if launched else '/scan'`) is never reported, since
    its unknown alternative may be subscribed; its known alternative counts
    as a publisher of that topic for ROS003.

    Numbered families (`/robot1/odom` vs `/robot2/odom`, `/cmd` vs `/cmd2`)
    are never near names, nor is one last name in two namespaces
    (`/left/image`, `/right/image`). A token of at most five characters
    matches only a swap of neighbours or one character more or less (`/left`
    and `/lift` are two words), longer ones one edit, from ten characters
    two. Test fixtures (nodes in `test/` or `tests/` folders, `test_*.py`
    modules, nodes started by launch files there) form their own system:
    they connect with the fixtures and the production nodes of the package
    they test only, so a test's end never makes a production end look
    connected; the nodes of two test modules in a test folder never run
    together (a misspelling is still named from the other module, which spells
    the name meant). Ends created by a shared helper function sit at the helper's
    creation call; the names one call of the helper may give (`a if sim else b`)
    count as alternatives of one site, the names separate calls give as separate
    ends (`self._client(T, '/start')`, `self._client(T, '/stop')`). When
    flake8 checks only some files (pre-commit), a near-name finding whose
    end is not checked is shown at the checked near end.

    ## Example
    ```python
    # teleop/teleop/keyboard.py
    self.create_publisher(Twist, 'cmd_vel', 10)
    # base/base/driver.py
    self.create_subscription(Twist, 'cmdvel', self.on_twist, 10)
    ```

    ## Use instead
    ```python
    # base/base/driver.py
    self.create_subscription(Twist, 'cmd_vel', self.on_twist, 10)
    ```

    ## Options
    - `--rosgraph-external-topics` (`ROSGRAPH_EXTERNAL_TOPICS`): topics consumed
      outside the workspace; `*`, `?` and `**` wildcards allowed.
    """

    code = "ROS001"
    name = "publisher-without-subscriber"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a topic is published but nothing in the analysed workspace subscribes to it"
    kind = "publishers"
    missing = "subscriber"
