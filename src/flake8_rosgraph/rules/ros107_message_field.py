"""ROS107 message-field."""
from __future__ import annotations

from dataclasses import replace
from typing import Iterator

from ..graph.messages import FieldRead, FieldStore
from ..graph.model import RosGraph
from ..interfaces.catalogue import Catalogue, display_name, message_key
from ..interfaces.definitions import Field, MessageDef
from ..interfaces.field_values import rejection, without_none_alternative
from ..interfaces.ros1_names import ros2_name
from .base import Finding, Rule, RuleConfig


def resolve(catalogue: Catalogue, root: MessageDef, path: tuple[str, ...]
            ) -> tuple[MessageDef, Field | None, str] | None:
    """Walk ``path`` down nested message fields: the definition holding the last step, its
    field (``None`` when that definition has no such field) and the step's name. ``None``
    when the walk leaves what the catalogue knows (an unknown nested type, an array)."""
    current = root
    for depth, name in enumerate(path):
        found = current.field(name)
        if found is None or depth == len(path) - 1:
            return current, found, name
        if found.type.array is not None or not found.type.is_message:
            return None
        nested = catalogue.get(found.type.base)
        if nested is None:
            return None
        current = nested
    return None


#: What a generated message class has besides its fields and constants (rosidl_generator_py).
_CLASS_ATTRIBUTES = frozenset({"get_fields_and_field_types", "SLOT_TYPES"})


def _class_attribute(owner: MessageDef, name: str) -> bool:
    """A name a message instance has that is not a field: constants, ``<FIELD>__DEFAULT``,
    the class's own API and private or special names."""
    return (name in owner.constants or name in _CLASS_ATTRIBUTES or name.startswith("_")
            or (name.endswith("__DEFAULT") and owner.field(name[:-len("__DEFAULT")].lower()) is not None))


def merge_contexts(stores: list[FieldStore]) -> list[FieldStore]:
    """One store per place, field and way, its value joined over every context the code ran in.

    Code in a function is analysed once per calling context, including contexts met on the
    way to the fixpoint (a caller's value before it grew to its final one): a value is judged
    only as the join of them all, and unknown if any of them is."""
    merged: dict[tuple, FieldStore] = {}
    for store in stores:
        key = (store.location, store.message, store.path, store.keyword)
        known = merged.get(key)
        if known is None:
            merged[key] = store
        elif known.value is not None:
            value = None if store.value is None else tuple(sorted(set(known.value + store.value), key=repr))
            merged[key] = replace(known, value=value)
    return [merged[key] for key in sorted(merged, key=repr)]


class MessageField(Rule):
    """## What it does
    Checks what code stores in ROS message fields, by attribute or constructor
    keyword: the field must exist, and the value must be one rclpy accepts for
    the field's type. Fields read (`msg.dat`) must exist too.

    ## Why is this bad?
    Generated message classes check every assignment: `String(data=5)`,
    `twist.linear.x = 1` (an `int` in a `float64` field), `status.level = 300`
    (out of a `uint8`'s range), `msg.ranges = 0.0` (a scalar for an array) and
    `header.stamp = self.get_clock().now()` (an `rclpy.time.Time`, not a
    `builtin_interfaces/Time`) all raise `AssertionError`; a misspelt field
    raises `AttributeError`. Releases that skip these checks for speed pass the
    value to C at `publish`, which then fails or silently truncates. Message
    classes take keyword arguments only: `String('hi')` is a `TypeError`.

    ## Known problems
    Field definitions come from the interface packages shipped with the tool
    (the core ones, and nav2_msgs, vision_msgs, control_msgs, moveit_msgs,
    geographic_msgs, ackermann_msgs, turtlesim, controller_manager_msgs,
    irobot_create_msgs and map_msgs, except the messages whose fields differ
    between ROS distributions), the workspace's own `.msg`/`.srv`/`.action`
    files and the folders given with `--rosgraph-interfaces`; a message of any
    other package is not checked. Only values the analysis knows are judged (constants, message
    instances, lists of known elements); `msg.x = float(v)` or a value from a
    parameter of unknown type is accepted. A value that may be objects of
    different kinds (a message on one path, a tuple on another the analysis
    could not tell apart; messages of two types) is reported only when every
    one is rejected; an object that may be one of several message types, only
    when none of them has the field. A field read in a function that tests
    that attribute (`hasattr(msg, 'header')`, `getattr(msg, 'header', None)`)
    is not judged. A keyword the class does not have
    is ignored silently when field checks are off, and is still reported.
    A field ROS 2 renamed (`info.K` of `CameraInfo`, now `k`) is reported
    with its ROS 2 name, except in a file that also uses the ROS 2 name on
    that message: code for both versions (`if ROS_VERSION == 1:`) whose ROS 1
    branch never runs under ROS 2.
    Test code (fixtures, pytest and unittest test classes) is judged like the
    product: a missing field or a rejected value raises in a test just the same,
    and the test then fails for a reason it does not test.

    ## Example
    ```python
    cmd = Twist()
    cmd.linear.x = 1
    header = Header(stamp=self.get_clock().now())
    ```

    ## Use instead
    ```python
    cmd = Twist()
    cmd.linear.x = 1.0
    header = Header(stamp=self.get_clock().now().to_msg())
    ```

    ## Options
    None.
    """

    code = "ROS107"
    name = "message-field"
    level = "error"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a message field the type does not have, or a value the field's type rejects"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        facts, catalogue = graph.messages, graph.interfaces
        if facts is None or catalogue is None:
            return
        for built in facts.constructions:
            key = message_key(built.message)
            if built.positional and catalogue.get(key) is not None:
                yield Finding(built.location, self.code,
                              f"{display_name(key)} takes keyword arguments only, not "
                              f"{built.positional} positional")
        # Every field path each file writes or reads, by message (see :func:`_both_versions`).
        used = frozenset((f.location.path, f.message, f.path) for f in (*facts.stores, *facts.reads))
        stores: dict[tuple, list[FieldStore]] = {}
        for store in merge_contexts(facts.stores):
            stores.setdefault((store.location, store.path, store.keyword), []).append(store)
        for group in stores.values():
            yield from _unanimous([self._store_problem(catalogue, store, used) for store in group])
        reads: dict[tuple, list[FieldRead]] = {}
        for read in facts.reads:
            reads.setdefault((read.location, read.path), []).append(read)
        for group in reads.values():
            yield from _unanimous([self._read_problem(catalogue, read, used) for read in group])

    def _read_problem(self, catalogue: Catalogue, read: FieldRead, used: frozenset) -> Finding | None:
        root = catalogue.get(message_key(read.message))
        resolved = resolve(catalogue, root, read.path) if root is not None else None
        if resolved is None or resolved[1] is not None or _class_attribute(resolved[0], resolved[2]):
            return None
        owner, _, name = resolved
        if _both_versions(owner, name, read, used):
            return None
        return Finding(read.location, self.code,
                       f"{display_name(owner.key)} has no field '{name}'{_ros2_hint(owner, name)}")

    def _store_problem(self, catalogue: Catalogue, store: FieldStore, used: frozenset) -> Finding | None:
        root = catalogue.get(message_key(store.message))
        if root is None or any(step.startswith("_") for step in store.path):
            return None
        resolved = resolve(catalogue, root, store.path)
        if resolved is None:
            return None
        owner, found, name = resolved
        where = display_name(owner.key)
        if found is None:
            if _both_versions(owner, name, store, used):
                return None
            what = " (it is a constant)" if name in owner.constants else \
                " (constructor keyword)" if store.keyword else _ros2_hint(owner, name)
            return Finding(store.location, self.code, f"{where} has no field '{name}'{what}")
        shapes = without_none_alternative(list(store.value or ()))
        verdicts = [(shape, rejection(found.type, shape)) for shape in shapes]
        rejected = [(shape, why) for shape, why in verdicts if why is not None]
        if not rejected or (len(rejected) < len(verdicts) and not _one_kind(shapes)):
            return None
        shape, why = rejected[0]
        return Finding(store.location, self.code,
                       f"{where} field '{name}' ({found.type.spelled()}) rejects {why}"
                       f"{_hint(found.type.base, shape)}")


def _both_versions(owner: MessageDef, name: str, fact: FieldStore | FieldRead, used: frozenset) -> bool:
    """Whether ``name`` is a ROS 1 field of ``owner`` (``CameraInfo.K``) whose ROS 2 name (``k``)
    the fact's file also uses on that message: code written for both versions (``if ROS_VERSION
    == 1: info.K = … else: info.k = …``), whose ROS 1 branch never runs under ROS 2."""
    spelling = ros2_name(owner.key, name)
    return spelling is not None and (fact.location.path, fact.message, fact.path[:-1] + (spelling,)) in used


def _ros2_hint(owner: MessageDef, name: str) -> str:
    spelling = ros2_name(owner.key, name)
    return "" if spelling is None else f" (its ROS 1 name: the ROS 2 field is '{spelling}')"


def _unanimous(problems: list[Finding | None]) -> list[Finding]:
    """The first problem of one place, when every message type the object may be has one.

    ``msg = Twist() if humble else TwistStamped()`` followed, on the path that knows
    which, by ``msg.linear.x = …``: the analysis sees both types at the store and
    must not report the field the other one lacks.
    """
    return [problems[0]] if problems and all(problems) else []


def _one_kind(shapes: list) -> bool:
    """Whether the possible values are all of one kind (numbers count as one).

    ``1`` or ``2.5`` at a float field is the classic bug on one of two paths. A
    message *or* a tuple is something else: values of two classes whose paths
    the analysis could not keep apart (``if calibrator.is_mono:``), so only a
    value every alternative of which is rejected is reported then.
    """
    return len({"number" if s.kind in ("bool", "int", "float") else (s.kind, s.cls) for s in shapes}) == 1


#: rclpy's time classes and the message each one's ``to_msg()`` makes.
_TO_MSG = {"rclpy.time.Time": "builtin_interfaces/msg/Time",
           "rclpy.duration.Duration": "builtin_interfaces/msg/Duration"}


def _hint(base: str, shape) -> str:
    """How to write the value the field takes, for the two mistakes everyone makes."""
    if base in ("float32", "float64") and shape.kind == "int":
        return f": write {float(shape.value)!r}"
    if shape.kind == "instance" and _TO_MSG.get(shape.cls) == base:
        return ": call .to_msg() on it"
    return ""
