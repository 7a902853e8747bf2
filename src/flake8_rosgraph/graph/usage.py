"""How the code uses rclpy, beyond the graph: facts for the misuse rules ROS101–ROS106.

Plain data, read off the analysis by :mod:`.usage_builder`: rules decide what is a problem,
these only say what the code does — which functions are callbacks and what they accept,
which blocking calls each callback reaches and through which calls, which executors spin
which nodes, which parameters each node declares and uses, what periods timers get. The
rules import these, not the analysis.

An unknown stays unknown here (``None``): a rule that needs it stays quiet.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .model import Location


@dataclass(frozen=True)
class Group:
    """A callback group as far as known: ``key`` identifies it (a node's default group is
    ``default@<node>``), ``reentrant`` is ``None`` for a group of an unknown class."""

    key: str
    reentrant: bool | None


@dataclass(frozen=True)
class Signature:
    """How many positional arguments a callable accepts (after a bound ``self``)."""

    required: int
    maximum: int | None            # None: ``*args``
    required_keywords: tuple[str, ...]
    annotated: bool = False        # some parameter has a type annotation

    def accepts(self, count: int) -> bool:
        return not self.required_keywords and self.required <= count and \
            (self.maximum is None or count <= self.maximum)


@dataclass(frozen=True)
class Callback:
    """A function some library call will call back (registration × function)."""

    role: str                      # "timer callback", "service callback", …
    passes: tuple[int, ...] | None  # how many positional arguments the library may pass
    #: The library fills an annotated parameter by its type (rclpy's ``TimerInfo``).
    by_annotation: bool
    must_return: str | None        # what it must return ("the response"), if anything
    on_executor: bool              # run by an executor (not synchronously by the library)
    registration: Location
    function: str                  # qualname
    definition: Location
    nodes: frozenset[str]          # node object sites; empty when unknown
    group: Group | None
    #: What the function accepts; ``None`` when a decorator or ``functools.partial``
    #: may change it.
    signature: Signature | None
    #: Some run ends without returning a value (``return``/``return None``/the end of the body).
    may_return_none: bool
    #: The analysis's handles on the function and its receiver, for building the other facts;
    #: not facts themselves (not compared, not kept by the cache: -1 and ``None`` there).
    fid: int = field(compare=False, default=-1)
    receiver: object = field(compare=False, default=None)


@dataclass(frozen=True)
class Step:
    """One call on the way from a callback to a blocking call."""

    location: Location
    text: str                      # the callee as written: "helpers.fetch()"


@dataclass(frozen=True)
class BlockingCall:
    """A blocking library call a callback reaches through ``steps`` (first in the callback,
    last the blocking call itself)."""

    callback: Callback
    steps: tuple[Step, ...]
    why: str
    kind: str                      # "wait" (for an entity), "spin", "sleep" or "other"
    #: sleep: how long, when every possible duration is known.
    seconds: tuple[float, ...] | None
    #: wait: can the awaited entity's callbacks run while this callback runs (another
    #: group, or a reentrant one)? ``None``: unknown.
    concurrent: bool | None
    #: wait: the awaited entity is on the callback's node; spin: it spins the callback's
    #: node or its executor. ``None``: unknown.
    same_node: bool | None
    #: The executor kind spinning the callback's node: "single", "multi" or "unknown".
    executor: str


@dataclass(frozen=True)
class NodeParameters:
    """What one node object declares."""

    site: str
    label: str
    location: Location
    open: bool                     # allows undeclared / declares from overrides / unknown names
    declared: frozenset[str]
    #: It allows undeclared parameters or declares those the overrides hold: any name may be
    #: read (``open`` alone may mean only that some declared name is unknown).
    allows_undeclared: bool = False


@dataclass(frozen=True)
class ParameterUse:
    location: Location
    how: str                       # "get_parameter", "get_parameters", "set_parameters", …
    names: tuple[str, ...] | None
    nodes: tuple[str, ...] | None  # node object sites; None when unknown
    #: Every run of the call sits in a ``try`` whose ``except`` may catch
    #: ``ParameterNotDeclaredException`` (it, a base class, a bare ``except:``, or a class the
    #: analysis cannot name): the code handles an undeclared parameter.
    handled: bool = False


@dataclass(frozen=True)
class Redeclaration:
    location: Location
    name: str
    node: str
    first: Location


@dataclass(frozen=True)
class PeriodArgument:
    location: Location
    what: str                      # "timer period" or "rate frequency"
    values: tuple | None           # every possible value, None when unknown
    conditional: bool              # created on some paths only (a test may exclude values)
    #: The code cancels or destroys this timer somewhere: with period 0 it runs once (the
    #: "start when spinning" idiom), not in a busy loop.
    stopped: bool = False


@dataclass(frozen=True)
class OutOfOrder:
    """A call that runs, in one body, after (or before) the call it depends on."""

    location: Location
    what: str                      # "node created", "node spun", "entity created on node 'x'"
    problem: str                   # "before rclpy.init()", "after rclpy.shutdown()", …
    other: Location                # the init / shutdown / destroy_node call


@dataclass
class UsageFacts:
    callbacks: list[Callback] = field(default_factory=list)
    blocking: list[BlockingCall] = field(default_factory=list)
    nodes: dict[str, NodeParameters] = field(default_factory=dict)
    parameter_uses: list[ParameterUse] = field(default_factory=list)
    redeclarations: list[Redeclaration] = field(default_factory=list)
    periods: list[PeriodArgument] = field(default_factory=list)
    out_of_order: list[OutOfOrder] = field(default_factory=list)
    #: Parameter names written at declaration calls the analysis did not attribute to a known
    #: node (:mod:`.declaration_sites`): some node may declare them unseen.
    unattributed_parameters: frozenset[str] = frozenset()


def callback_order(cb: Callback) -> tuple:
    return (cb.registration, cb.function, cb.role)
