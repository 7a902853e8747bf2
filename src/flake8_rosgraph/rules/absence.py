"""What ROS001, ROS003, ROS008 and ROS009 share: reporting an end whose other end is missing.

An absence is only as good as the analysis that failed to find the other end,
so these rules stay quiet whenever something could fill the gap (test
fixtures only fill gaps of the package they test: :mod:`.fixtures`):

* the name is exempt (infrastructure, rviz tools, per-node built-in services,
  or the user's external names — see :mod:`.exempt`);
* some entity of the peer kind has a name the analysis could not resolve and a
  type and known end (:attr:`~flake8_rosgraph.graph.model.Entity.name_suffix`) that do
  not rule the match out — unless the name is a slip of the pen for a name used in
  the other role with the same message type (``/odmo`` beside ``/odom``): one unknown
  elsewhere hardly happens to be exactly the misspelt name. An end whose type is
  unknown too (a test harness or recorder whose topics come from a plan at run
  time) could be any topic at all: it fills only gaps of its own package or launch
  file (:func:`.topics.near`), never the whole workspace's; so does an end whose
  name a launch file makes unknown (a launch argument, a parameter file the
  analysis cannot read): that is one configuration of one launch system;
* the end's name is known only partly (``param if launched else '/scan'``): its
  site's unknown alternative may be connected. A partly known end does count as
  the present other end of its name (``/scan`` above satisfies a subscriber of
  ``/scan``), but never makes another end reportable (:meth:`.EndpointIndex.wired_nodes`);
* another alternative of the same creation site (``'a' if sim else 'b'``) is
  connected or excused: the site works in at least one configuration;
* the node runs as written in code, and a launch file of its package runs an
  action the analysis cannot follow that may start nodes (an ``OpaqueFunction``
  building them from configuration), or starts an executable of its package
  that the analysis cannot tie to code with remaps or a namespace: that launch
  file may start it remapped (``("fix", "gps/fix")``) — unless the name is a
  slip of the pen, as above;
* the rule's own ``invalid`` entities: rclpy raises before they exist (ROS006).

**Interfaces.** Most dangling ends in real repositories are deliberate: the
other end is a C++ node, a robot, a simulator, rviz or a person at the command
line. A dangling end is taken for such an interface, and reported only when a
near name is used in the other role (a likely typo or namespace slip — the
strongest signal; every name of the other role counts, connected or not,
since a typo usually hits a name that other nodes still use: see
:mod:`.near_miss`; or a slip of an infrastructure topic with that topic's
type, ``/joint_state`` of ``sensor_msgs/msg/JointState``, whose other end is
outside the workspace by nature: see :mod:`.infrastructure`), when

* the node has no endpoint of the same kind that reaches another node of the
  workspace — none of its publishers (for ROS001) is subscribed here, so its
  outputs are meant for the outside; this covers stand-alone drivers and tools;
* or several nodes use the name in the same role (six example programs all
  publishing the robot's ``/cmd_vel``): they agree on it, so it is no slip;
* or the name lives in a namespace other than ``/`` where the workspace uses
  at least two names, all in this role and none in the other (``/fmu/out/...``
  only subscribed, ``/local_costmap/clear_...`` only called): another
  program's interface.

* or the name lies in the namespace in which a launch file of the workspace
  starts a node whose code the analysis does not see (an installed package's
  executable, a C++ executable it cannot tie to code): that program's own
  relative names land there.

A ros2_control controller a controller manager's parameters configure
(``arm_controller.type: joint_trajectory_controller/JointTrajectoryController``)
is such a program too: the names under ``/arm_controller/`` are its ends. And an
absolute name a launch file hands such a node as a parameter value
(robot_localization's ``imu1: /mag/heading_imu``) may be its end: that name
(only that one) is not dangling either.

A name a launch file remaps such a node of unseen code onto (``teleop_twist_joy``
started with ``('/cmd_vel', '/cmd_vel_intuitive')``) is not dangling at all: the
launch file says that program uses it, and it is the other end the analysis cannot see;
so is a transport plugin's topic one token under it (``/front_camera/image_raw/compressed``),
but not any other name under it (a remap onto ``/odom`` says nothing of ``/odom/wheels``).
Likewise a name a node hands, together with itself, to a library no stub models
(``hbba_lite.OnOffHbbaSubscriber(self, Image, 'image_raw', ...)``), and the names
under it: that library makes the end (:mod:`~flake8_rosgraph.graph.unseen_calls`).

A node no launch file starts runs as written, and meets the launched programs run as
written too (``ros2 run``): a name a launched node's code writes connects its end, and is
a near name for it (a recogniser run on its own misspelling the ``speaking`` that the speech
node's code writes, though the launch file starts that node in ``/robot``).

A name a launch file changed (namespace, remap) is an interface toward the
nodes that launch file does not start: it is compared only with the nodes
of its own launch system, and with the nodes another launch file starts in
the same namespace other than the root (one robot's bring-up and teleop
launch files, both in ``/alfie``: a teleop publishing ``/robotlowcmd`` where
the bring-up's ``robotlowcmd`` lands in ``/alfie`` is a namespace slip).

* or the end's message type is made for a tool outside the workspace
  (``visualization_msgs``: rviz draws the markers, and sends interactive markers'
  feedback; :data:`.exempt.TOOL_MESSAGE_PACKAGES`). Such ends still count as the
  node's outward ends below.

* or most of the node's ends of this kind have no partner in the workspace:
  a node that feeds the workspace through one publisher and the world outside
  through several (a robot driver's ``/odom``, ``/battery``, ``/imu_wrist``,
  ``/joint_limits`` beside the ``/joint_states`` a workspace node reads) is
  mostly an interface, and its unread outputs are meant for the outside.

What is left is the odd one out: a node that feeds (or is fed by) the
workspace through most of its publishers and not through this one — the
thesis's ``topic5`` and ``topic8``.

Measured on 17 further repositories (stretch_ros2, t-top, osr-rover-code,
pyrobosim, carla ros-bridge, orca4, ROS2swarm, sailbot_workspace, …): the
majority test removed 16 by-design ROS001 findings of three such nodes of
stretch_ros2 (its driver, ArUco and face detectors) and no true one.

Measured with the extractor on 15 public repositories with rclpy nodes
(ros2/examples, ros2/demos, navigation2, turtlebot3, geometry2,
gazebo_ros_pkgs, teleop_tools, teleop_twist_keyboard, nmea_navsat_driver,
diagnostics, audio_common, ros2_control_demos, Universal_Robots_ROS2_Driver,
px4-offboard, yolo_ros; 120 nodes): reporting every dangling end gives 135
findings, and reading them found no wiring bug among them (robot, controller,
Nav2 and camera interfaces, rviz outputs, command-line inputs). With the
policy above, 3 remain, also by design (PX4's ``/fmu/in/offboard_control_mode``
read by the flight controller, yolo_ros's depth inputs from a camera driver).
The knob ``report_interfaces=True`` (constructor argument) reports every
dangling end, and the message then says how to declare an interface.
"""
from __future__ import annotations

from collections import Counter
from typing import Callable, ClassVar, Iterator

from ..graph.model import PEER_KIND, Entity, RosGraph
from ..launch.instantiate import LaunchScopes
from .base import Finding, Rule, RuleConfig
from .exempt import ExemptNames, for_a_tool
from .infrastructure import infrastructure_slip
from .launch_context import (UnseenLaunches, controller_namespaces, transported, under_any, unseen_code_names,
                             unseen_parameter_names, unseen_remap_targets)
from .near_miss import NearMiss, NearMissFinder
from .shared import once
from .topics import Endpoint, EndpointIndex, namespace_of
from .vocabulary import NAME_NOUN, VERB, name_origin, origin_related, related
from .written import launched_names, written_graph


class AbsenceRule(Rule):
    """Base of the "X without Y" rules; subclasses set :attr:`kind`, :attr:`missing` and the Rule attributes."""

    #: The kind whose entities may dangle (``"publishers"`` for ROS001).
    kind: ClassVar[str]
    #: What is missing, for the message ("subscriber" in "has no subscriber").
    missing: ClassVar[str]

    def __init__(self, report_interfaces: bool = False) -> None:
        #: Knob: also report dangling ends that look like interfaces (see the module docstring).
        self.report_interfaces = report_interfaces

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        index = EndpointIndex.build(graph)
        exempt = ExemptNames.build(config.external_names)
        unseen = once("unseen names", graph, lambda: unseen_code_names(graph) | controller_namespaces(graph))
        remapped = once("unseen remap targets", graph, lambda: unseen_remap_targets(graph))
        configured = once("unseen parameter names", graph, lambda: unseen_parameter_names(graph))
        peer_kind = PEER_KIND[self.kind]
        scopes = once("launch scopes", graph, lambda: LaunchScopes(graph.systems))
        # a node no launch file starts still meets a launched executable run as written
        unconnected = [ep for ep in index.endpoints(self.kind) if self._dangles(ep, index, exempt)
                       and not under_any(ep.entity.name, unseen) and not transported(ep.entity, remapped)
                       and ep.entity.name not in configured
                       and not (ep.node.launch is None and scopes.written_name(peer_kind, ep.entity.name))]
        if not unconnected:
            return
        peers = {name: index.using(peer_kind, name) for name in index.names(peer_kind)}
        near_misses = _NearNames(NearMissFinder(peers), once("unseen launches", graph, lambda: UnseenLaunches.of(graph)),
                                 lambda: _with_launched_as_written(peers, graph, peer_kind))
        # An unknown name elsewhere may be this end's partner, and a launch file the analysis
        # cannot follow may remap the end itself; hardly so for a slip of the pen.
        def unknown_may_fill(ep: Endpoint) -> bool:
            return index.unresolved_peer_may_match(ep) or near_misses.remapped_unseen(ep)

        slips = {id(ep) for ep in unconnected if unknown_may_fill(ep)
                 and ((near := near_misses.find(ep)) is not None and near.is_slip_of(ep)
                      or infrastructure_slip(ep) is not None)}
        dangling = [ep for ep in unconnected if id(ep) in slips or not unknown_may_fill(ep)]
        dangling = self._whole_sites_only(dangling, index)
        wired = index.wired_nodes(self.kind, exempt)
        one_way = index.one_way_namespaces(self.kind)
        excused = {id(ep) for ep in dangling
                   if index.same_role_nodes(ep) > 1
                   or namespace_of(ep.entity.name) in one_way
                   or scopes.renamed(ep.node, ep.entity)
                   or scopes.in_foreign_namespace(ep.entity.name)}
        # Ends neither excused nor a likely slip: the node's unexplained ones.
        unexplained = [ep for ep in dangling if id(ep) not in excused and near_misses.find(ep) is None
                       and infrastructure_slip(ep) is None]
        mostly_outside = _mostly_dangling([ep for ep in index.endpoints(self.kind) if index.peers(ep)],
                                          unexplained)
        for endpoint in dangling:
            # A helper called once per name (a bridge forwarding a list of topics) is how
            # interfaces are built: such an end is reported only as a slip of a used name.
            interface = (id(endpoint.node) not in wired
                         or id(endpoint.node) in mostly_outside
                         or id(endpoint) in excused
                         or endpoint.entity.own_call
                         or for_a_tool(endpoint.entity.type))
            yield from self._report(endpoint, near_misses, interface, scopes, id(endpoint) in slips)

    def _dangles(self, endpoint: Endpoint, index: EndpointIndex, exempt: ExemptNames) -> bool:
        """No known other end (an unknown one may still exist: see :meth:`check`)."""
        return (endpoint.entity.invalid is None  # rclpy raises before it exists; ROS006 says so
                and not endpoint.entity.partial  # the site's unknown alternative may be connected
                and endpoint.entity.name not in exempt
                and not index.peers(endpoint))

    def _whole_sites_only(self, dangling: list[Endpoint], index: EndpointIndex) -> list[Endpoint]:
        """Keep the dangling endpoints whose creation site dangles in every alternative on its node.

        ``create_publisher(String, 'a' if sim else 'b', 10)`` yields two
        publishers at one location; if either is connected (or excused), the
        site works in some configuration and the other value is not reported.
        Each launched instance of a node is a configuration of its own: a
        parameter file that names the topic wrongly breaks the node it
        configures, however well the other launch files set it. So is each
        call of a shared helper that names its end alone
        (:attr:`~flake8_rosgraph.graph.model.Entity.own_call`): ``self._client(T, '/strat')``
        dangles however well ``self._client(T, '/stop')`` is served (and is reported as
        the slip of ``/start`` it is; a helper's end with no near name is an interface).
        """
        def site(ep: Endpoint) -> tuple:
            return ep.entity.location, id(ep.node), ep.entity.name if ep.entity.own_call else None

        alternatives = Counter(site(ep) for ep in index.endpoints(self.kind))
        dangling_at = Counter(site(ep) for ep in dangling)
        return [ep for ep in dangling if dangling_at[site(ep)] == alternatives[site(ep)]]

    def _report(self, endpoint: Endpoint, near_misses: _NearNames, interface: bool,
                scopes: LaunchScopes, slip_only: bool) -> Iterator[Finding]:
        """``slip_only``: an unknown name may be the partner, so only a slip is worth saying."""
        entity = endpoint.entity
        origin_words = name_origin(entity)
        named = f"'{entity.name}' ({origin_words})" if origin_words else f"'{entity.name}'"
        head = f"{NAME_NOUN[self.kind]} {named} has no {self.missing}"
        origin = origin_related(entity)
        near = near_misses.find(endpoint)
        def compared(peer: Endpoint) -> bool:
            return scopes.together(endpoint.node, peer.node) or scopes.one_robot(endpoint.node, peer.node)

        if near is not None and not compared(near.peer) and (
                scopes.renamed(endpoint.node, entity) or scopes.renamed(near.peer.node, near.peer.entity)):
            # a name launch changed is compared only with the nodes the same launch file starts,
            # or that a launch file starts in the same robot namespace
            near = near_misses.find(endpoint, accept=compared)
        infrastructure = infrastructure_slip(endpoint) if near is None else None
        if slip_only and (near is None or not near.is_slip_of(endpoint)) and infrastructure is None:
            return
        if infrastructure is not None:
            message = (f"{head}; did you mean '{infrastructure}' (an infrastructure topic of this "
                       f"type, {'published' if self.kind == 'subscriptions' else 'subscribed'} outside the workspace)?")
            yield Finding(entity.location, self.code, message, origin)
        elif near is not None:
            peer = near.peer.entity
            message = (f"{head}; did you mean '{near.name}' "
                       f"({VERB[peer.kind]} at {_where(peer)})?")
            yield Finding(entity.location, self.code, message, origin + (related(peer),) + origin_related(peer))
        elif not interface:
            yield Finding(entity.location, self.code, head, origin)
        elif self.report_interfaces:
            message = f"{head} in the workspace; if something outside uses it, add it to --rosgraph-external-topics"
            yield Finding(entity.location, self.code, message, origin)


class _NearNames:
    """:class:`NearMissFinder` for the absence rules: a partner that a launch file the analysis
    cannot follow may start remapped (:class:`.launch_context.UnseenLaunches`) is a near
    name only for a slip of the pen — its ``old/gripper/command`` may well be remapped onto
    the ``/gripper/command`` it is one namespace token away from."""

    def __init__(self, finder: NearMissFinder, unseen: UnseenLaunches,
                 as_written: Callable[[], dict[str, list[Endpoint]]]) -> None:
        self.finder = finder
        self.unseen = unseen
        self._as_written = as_written
        self._written_finder: NearMissFinder | None = None

    def remapped_unseen(self, endpoint: Endpoint) -> bool:
        return self.unseen.may_rename(endpoint.node)

    def _finder_for(self, endpoint: Endpoint) -> NearMissFinder:
        """A node no launch file starts runs as written, beside the launched executables run as
        written too (``ros2 run``): the names their code writes are near names for its ends."""
        if endpoint.node.launch is not None:
            return self.finder
        if self._written_finder is None:
            self._written_finder = NearMissFinder(self._as_written())
        return self._written_finder

    def find(self, endpoint: Endpoint, accept: Callable[[Endpoint], bool] | None = None) -> NearMiss | None:
        finder = self._finder_for(endpoint)
        near = finder.find(endpoint, accept)
        if near is None or near.is_slip_of(endpoint) or not self.remapped_unseen(near.peer):
            return near
        return finder.find(endpoint, lambda peer: (accept is None or accept(peer))
                           and not self.remapped_unseen(peer))


def _with_launched_as_written(peers: dict[str, list[Endpoint]], graph: RosGraph,
                              kind: str) -> dict[str, list[Endpoint]]:
    """``peers`` (the judged graph's ends of ``kind`` by name) with the ends of every launched
    node's code as written: what a node run as written meets when the launched programs run
    as written too."""
    written = written_graph(graph)
    if written is None:
        return peers
    launched = launched_names(graph)
    out = {name: list(ends) for name, ends in peers.items()}
    for endpoint in EndpointIndex.build(written).endpoints(kind):
        if id(endpoint.node) in launched:
            out.setdefault(endpoint.entity.name or "", []).append(endpoint)
    return out


def _mostly_dangling(connected: list[Endpoint], unexplained: list[Endpoint]) -> frozenset[int]:
    """``id()`` of the nodes with more ends of the kind that have no partner in the workspace
    and nothing else explains (``unexplained``: no other user, no slip) than ends that have
    one (``connected``): such a node mostly talks to the world outside (a robot driver's
    odometry, battery, IMU and joint limits beside the joint states a workspace node reads).
    Alternatives of one creation site count once."""
    def per_node(endpoints: list[Endpoint]) -> Counter:
        return Counter(node for node, _ in {(id(ep.node), ep.entity.location) for ep in endpoints})

    dangling, wired = per_node(unexplained), per_node(connected)
    return frozenset(node for node, count in dangling.items() if count > wired[node])


def _where(entity: Entity) -> str:
    """Where the other end stands, and where a launch named it if it did."""
    origin_words = name_origin(entity)
    return entity.location.short() + (f", {origin_words}" if origin_words else "")
