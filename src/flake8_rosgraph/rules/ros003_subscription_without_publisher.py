"""ROS003 subscription-without-publisher."""
from __future__ import annotations

from .absence import AbsenceRule


class SubscriptionWithoutPublisher(AbsenceRule):
    """## What it does
    Checks for topics that are subscribed but that nothing in the analysed
    workspace publishes.

    The end is compared with every topic name published in the workspace,
    connected or not, with a compatible type. A *near name* — a typo (swapped,
    missing, doubled or changed characters, case, singular/plural of the last
    word), the written name resolved as private (`~/x`), relative or absolute
    in its node, one namespace token more or less, or one `_`-word more or
    less at an end of a namespace token (`/qr_detection` for `/qr_detection_pkg`)
    — is named in the message ("did you mean ...?") with its location as
    related location.

    ## Why is this bad?
    The callback never runs. The node waits forever for data that does not
    come, usually because of a typo in the topic name, a namespace slip
    (`scan` inside namespace `robot1` is `/robot1/scan`, not `/scan`) or a
    publisher that was renamed. ROS 2 raises no error for it.

    ## Known problems
    Topics published by C++ nodes whose names the analysis cannot resolve
    (the workspace's rclcpp calls with literal names are partner ends),
    drivers outside the workspace, simulators, rviz, the command line or bag
    playback look unpublished. The rule reports only the *odd one
    out*: a topic of a node whose other subscriptions are fed by the
    workspace. It stays quiet (unless a near name is published) when none
    of the node's subscriptions has a publisher here (a tool fed from
    outside), when several nodes subscribe to the topic, when the
    workspace only subscribes within the topic's namespace (`/fmu/out/...`),
    or when its type is made for a tool (`visualization_msgs`: rviz sends
    interactive markers' feedback).
    Infrastructure topics (`/rosout`, `/parameter_events`, `/tf`,
    `/tf_static`, `/clock`, `/diagnostics`, `/robot_description`,
    `/joint_states`, rviz tool topics such as `/initialpose` and
    `/goal_pose`) are exempt; a subscription of one's type under a slip of
    its name (`/joint_state` of `sensor_msgs/msg/JointState`) is reported
    with it as near name, its publisher being outside by nature (a namespace
    more or less, `/robot1/joint_states`, is no slip). It also stays quiet when some publisher's topic
    name could not be resolved and its type and known end do not rule the
    match out (a slip of the pen of a fully known published name of the same
    type is reported all the same), and when another alternative of the same creation site on the same
    node is connected (each launched instance is a configuration of its own). A
    topic name known only partly (`param if launched else '/scan'`) is never
    reported; its known alternative counts as a subscription for ROS001.
    Which names count as near, how test fixtures are kept apart from
    production nodes, and how a changed-files run shows a near-name finding
    are as for ROS001 (see its Known problems).

    ## Example
    ```python
    class Mapper(Node):
        def __init__(self):
            super().__init__('mapper', namespace='robot1')
            self.create_subscription(LaserScan, '/scan', self.on_scan, 10)
            self.create_publisher(OccupancyGrid, 'map', 10)
    # elsewhere, a node in namespace robot1:
    #     self.create_publisher(LaserScan, 'scan', 10)  -> /robot1/scan
    ```

    ## Use instead
    ```python
    self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
    ```

    ## Options
    - `--rosgraph-external-topics` (`ROSGRAPH_EXTERNAL_TOPICS`): topics
      published outside the workspace; `*`, `?` and `**` wildcards allowed.
    """

    code = "ROS003"
    name = "subscription-without-publisher"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a topic is subscribed but nothing publishes it"
    kind = "subscriptions"
    missing = "publisher"
