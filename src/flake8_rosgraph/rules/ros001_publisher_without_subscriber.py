"""ROS001 publisher-without-subscriber."""
from __future__ import annotations

from .absence import AbsenceRule


class PublisherWithoutSubscriber(AbsenceRule):
    """## What it does
    Checks for topics that are published but that nothing in the analysed
    workspace subscribes to.

    ## Why is this bad?
    Messages nobody receives are wasted work, and far more often the symptom of
    a wiring mistake: a typo in the topic name (`/cmd_vel` vs `/cmdvel`), a
    relative name that resolves into another namespace, or a subscriber that
    was renamed. ROS 2 reports none of these at run time; the system just sits
    idle.

    ## Known problems
    The rule only sees the Python code of the workspace: topics consumed by C++
    nodes, robots, rviz, `ros2 topic echo` or bag recordings look
    unsubscribed. To stay useful on real repositories it reports only the
    *odd one out*: a topic of a node whose other publishers do feed the
    workspace. It stays quiet (unless a near-miss subscription exists) when
    none of the node's publishers has a subscriber here (a driver's or
    tool's outputs), when several nodes publish the topic, or when the
    workspace only publishes into the topic's namespace (`/camera/...`).
    On 15 public repositories this leaves 3 of 135 dangling ends reported.
    Infrastructure topics (`/rosout`, `/parameter_events`, `/tf`,
    `/tf_static`, `/clock`, `/diagnostics`, `/robot_description`,
    `/joint_states`, rviz tool topics) are exempt. It also stays quiet when
    some subscription's topic name could not be resolved and its type does
    not rule the match out, and when another alternative of the same
    creation site (`'a' if sim else 'b'`) is connected.

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
