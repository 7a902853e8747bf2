"""Lattice laws of the abstract values (``absint.values``), checked on random values.

The fixpoint engine is only guaranteed to terminate, and to give the same
result whatever order it visits things in, if join is a least upper bound
(commutative, associative, idempotent, consistent with ``leq``) and widening
turns every ascending chain into one that stabilises after a bounded number of
steps. These properties are tested here on values drawn from small domains, so
that random values often overlap, nest and hit the size and depth bounds.
"""
from __future__ import annotations

from functools import reduce

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from flake8_rosgraph.absint.values import (BOTTOM, MAX_ATOMS, MAX_DEPTH, MAX_OBJECTS, MAX_RECORD_NESTING,
                                           SATURATED, TOP,
                                           ClassAtom, Coll, Const, DictAtom, Extern, FuncAtom, Input,
                                           ModuleAtom, Obj, Record, Seq, Value, atoms, from_input, join_all,
                                           soften)

LAWS = settings(max_examples=300, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

constants = st.one_of(
    st.sampled_from(["", "a", "b", "/chatter", "~/x"]),
    st.text(alphabet="ab/_", max_size=3),
    st.integers(-2, 2),
    st.floats(allow_nan=True, allow_infinity=True, width=16),
    st.booleans(),
    st.none(),
    st.binary(max_size=2),
).map(Const.of)

classes = st.one_of(st.builds(ClassAtom, st.integers(0, 3)),
                    st.sampled_from(["rclpy.node.Node", "std_msgs.msg.String"]).map(Extern))

leaf_atoms = st.one_of(
    constants,
    st.sampled_from(["rclpy.node.Node", "rclpy.qos.QoSProfile", "std_msgs.msg.String", "os.path"]).map(Extern),
    st.builds(Obj, st.sampled_from(["a.py:1:0", "a.py:2:4", "b.py:9:8"]), classes),
    st.builds(FuncAtom, st.integers(0, 3)),
    st.builds(ClassAtom, st.integers(0, 3)),
    st.sampled_from(["pkg", "pkg.mod"]).map(ModuleAtom),
)


def _hinted(constants_: list[Const]) -> Value:
    """⊤ joined with some constants: an unknown that keeps them as hints."""
    return TOP.join(atoms(constants_))


#: Outside inputs a value may be (a parameter of one of two objects).
inputs = st.builds(Input, st.sampled_from(["a.py:1:0", "b.py:9:8"]), st.sampled_from(["param:t", "param:u"]))


def _value_of(atom_lists: st.SearchStrategy) -> st.SearchStrategy[Value]:
    plain = st.one_of(st.just(TOP), st.just(SATURATED), st.just(BOTTOM),
                      st.lists(constants, min_size=1, max_size=14).map(_hinted),
                      st.lists(constants, min_size=1, max_size=3).map(lambda c: soften(atoms(c))),
                      st.lists(atom_lists, max_size=6).map(atoms))
    # The same values as one outside input (a parameter's value, its default the atoms).
    return st.one_of(plain, st.tuples(plain, inputs).map(lambda p: from_input(*p)))


def _extend(inner: st.SearchStrategy) -> st.SearchStrategy:
    """Containers of values built from ``inner`` atoms: tuples/lists, collections, dicts."""
    values = _value_of(inner)
    return st.one_of(
        st.builds(Seq, st.sampled_from(["tuple", "list"]), st.lists(values, max_size=3).map(tuple)),
        st.builds(Coll, st.sampled_from(["list", "set"]), values),
        st.builds(DictAtom, st.lists(st.tuples(values, values), max_size=2).map(tuple)),
    )


any_atom = st.recursive(leaf_atoms, _extend, max_leaves=8)
any_value = _value_of(any_atom)


def _depth(atom) -> int:
    if isinstance(atom, Seq):
        return 1 + max((_value_depth(v) for v in atom.items), default=0)
    if isinstance(atom, Coll):
        return 1 + _value_depth(atom.elem)
    if isinstance(atom, DictAtom):
        return 1 + max((max(_value_depth(k), _value_depth(v)) for k, v in atom.items), default=0)
    if isinstance(atom, Record):  # no container level itself
        return max((_value_depth(v) for _, v in atom.fields), default=0)
    return 0


def _value_depth(value: Value) -> int:
    return max((_depth(a) for a in value), default=0)


# -- join --------------------------------------------------------------------------------------

@LAWS
@given(any_value, any_value)
def test_join_is_commutative(a: Value, b: Value) -> None:
    assert a.join(b) == b.join(a)


@LAWS
@given(any_value, any_value, any_value)
def test_join_is_associative(a: Value, b: Value, c: Value) -> None:
    assert a.join(b).join(c) == a.join(b.join(c))


@LAWS
@given(any_value)
def test_join_is_idempotent(a: Value) -> None:
    assert a.join(a) == a


@LAWS
@given(any_value, any_value)
def test_join_is_an_upper_bound(a: Value, b: Value) -> None:
    joined = a.join(b)
    assert a.leq(joined) and b.leq(joined)


@LAWS
@given(any_value, any_value, any_value)
def test_join_is_the_least_upper_bound(a: Value, b: Value, c: Value) -> None:
    if a.leq(c) and b.leq(c):
        assert a.join(b).leq(c)


@LAWS
@given(st.lists(any_value, max_size=6))
def test_join_all_is_the_fold_of_join(values: list[Value]) -> None:
    assert join_all(values) == reduce(Value.join, values, BOTTOM)


# -- order -------------------------------------------------------------------------------------

@LAWS
@given(any_value, any_value)
def test_leq_agrees_with_join(a: Value, b: Value) -> None:
    assert a.leq(b) == (a.join(b) == b)


@LAWS
@given(any_value)
def test_leq_is_reflexive(a: Value) -> None:
    assert a.leq(a)


@LAWS
@given(any_value, any_value)
def test_leq_is_antisymmetric(a: Value, b: Value) -> None:
    if a.leq(b) and b.leq(a):
        assert a == b


@LAWS
@given(any_value, any_value, any_value)
def test_leq_is_transitive(a: Value, b: Value, c: Value) -> None:
    if a.leq(b) and b.leq(c):
        assert a.leq(c)


# -- bottom and top ----------------------------------------------------------------------------

@LAWS
@given(any_value)
def test_bottom_is_the_identity_of_join(a: Value) -> None:
    assert BOTTOM.join(a) == a == a.join(BOTTOM)
    assert BOTTOM.leq(a)
    assert a.leq(BOTTOM) == a.is_bottom


@LAWS
@given(any_value)
def test_saturated_top_absorbs_join(a: Value) -> None:
    assert SATURATED.join(a) == SATURATED == a.join(SATURATED)
    assert a.leq(SATURATED)
    assert SATURATED.leq(a) == a.is_saturated


@LAWS
@given(st.lists(constants, min_size=1, max_size=MAX_ATOMS))
def test_top_keeps_the_constants_it_is_joined_with_as_hints(items: list[Const]) -> None:
    """``param if c else '/scan'``: still ⊤ to every consumer, with ``'/scan'`` kept as a hint."""
    known = atoms(items)
    hinted = TOP.join(known)
    assert hinted == known.join(TOP)
    assert hinted.is_top and not hinted.is_saturated
    assert hinted.consts() is None and hinted.strings() is None and list(hinted) == []
    assert sorted(map(repr, hinted.hinted())) == sorted(repr(a.value) for a in known)
    assert TOP.leq(hinted) and known.leq(hinted) and not hinted.leq(TOP)


@LAWS
@given(st.lists(constants, min_size=MAX_ATOMS + 1, max_size=MAX_ATOMS + 4, unique=True))
def test_hints_past_the_bound_saturate(items: list[Const]) -> None:
    hinted = TOP
    for item in items:
        hinted = hinted.join(atoms([item]))
    assert hinted == SATURATED


def test_top_joined_with_anything_but_constants_saturates() -> None:
    """Only constants are hints: an unknown that may also be an object keeps nothing."""
    node = atoms([Obj("a.py:1:0", Extern("rclpy.node.Node"))])
    assert TOP.join(node) == SATURATED
    assert TOP.join(atoms([Const.of("/scan"), Extern("std_msgs.msg.String")])) == SATURATED


def test_top_and_bottom_are_distinct_and_recognised() -> None:
    assert TOP != BOTTOM and TOP != SATURATED
    assert TOP.is_top and not TOP.is_bottom and not TOP.is_saturated
    assert SATURATED.is_top and SATURATED.is_saturated and not SATURATED.is_bottom
    assert BOTTOM.is_bottom and not BOTTOM.is_top
    assert atoms([]) == BOTTOM


# -- the bounds that make chains finite --------------------------------------------------------

@LAWS
@given(st.lists(any_atom, max_size=30))
def test_values_never_exceed_the_bounds(items: list) -> None:
    value = atoms(items)
    if not value.is_top:
        assert sum(type(a) is Const for a in value.atoms) <= MAX_ATOMS
        assert len(value.atoms) <= MAX_OBJECTS
        assert _value_depth(value) <= MAX_DEPTH
    hinted = TOP.join(value)
    assert hinted.is_saturated or len(hinted.hints) <= MAX_ATOMS


@pytest.mark.parametrize("rebuild, bound", [
    # ``d = os.path.join(root, d)``: a record holding a tuple holding the value it replaces
    (lambda value: Record("os.path.join", (("paths", atoms([Seq("tuple", (TOP, value))])),)), MAX_DEPTH),
    # ``p = Path(p)``: a record holding the value it replaces, directly
    (lambda value: Record("pathlib.Path", (("parts", value),)), MAX_RECORD_NESTING),
], ids=["through-a-container", "record-in-record"])
def test_a_cell_rebuilt_from_itself_as_a_record_settles(rebuild, bound: int) -> None:
    """A record built from the value it replaces (a callback re-run as its field grows) nests
    one level per step, and its text doubles: the chain settles within the bound."""
    value, steps = atoms([Const("str", "recordings")]), 0
    while True:
        grown = value.join(atoms([rebuild(value)]))
        if grown == value:
            break
        value, steps = grown, steps + 1
        assert steps <= bound + 1
    assert len(repr(value)) < 10_000 and _value_depth(value) <= MAX_DEPTH


@LAWS
@given(st.lists(any_atom, max_size=12))
def test_atoms_do_not_depend_on_order(items: list) -> None:
    forward, backward = atoms(items), atoms(list(reversed(items)))
    assert forward == backward
    assert hash(forward) == hash(backward)
    assert repr(forward) == repr(backward)


@LAWS
@given(any_value, any_value)
def test_equal_values_hash_alike(a: Value, b: Value) -> None:
    if a == b:
        assert hash(a) == hash(b)


# -- widening ----------------------------------------------------------------------------------

@LAWS
@given(any_value, any_value)
def test_widening_is_an_upper_bound_of_join(a: Value, b: Value) -> None:
    assert a.join(b).leq(a.widen(b))
    assert a.leq(a.widen(b))


@LAWS
@given(any_value, any_value)
def test_widening_keeps_a_stable_value(a: Value, b: Value) -> None:
    if b.leq(a):
        assert a.widen(b) == a


@LAWS
@given(st.lists(any_value, min_size=1, max_size=40))
def test_widened_chains_stabilise(sequence: list[Value]) -> None:
    """Widening any sequence of values into a running approximation changes it at most once."""
    current = sequence[0]
    changes = 0
    for value in sequence[1:]:
        widened = current.widen(value)
        assert current.leq(widened)
        if widened != current:
            changes += 1
        current = widened
    assert changes <= 1
    for value in sequence:
        assert current.widen(value) == current, "the limit is not a fixpoint"


@LAWS
@given(st.lists(any_value, min_size=1, max_size=40))
def test_joined_chains_are_finite(sequence: list[Value]) -> None:
    """Even without widening, an ascending chain built by join grows at most MAX_ATOMS + 2 times
    (constants one by one, then to ⊤ keeping them as hints, then to the saturated ⊤)."""
    current = BOTTOM
    increases = 0
    for value in sequence:
        joined = current.join(value)
        assert current.leq(joined)
        if joined != current:
            increases += 1
        current = joined
    assert increases <= MAX_ATOMS + 2
