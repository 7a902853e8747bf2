"""The value lattice on concrete cases (the laws are property-tested elsewhere)."""
from flake8_rosgraph.absint.values import (BOTTOM, MAX_ATOMS, TOP, Const, Seq, atoms, const,
                                           soften)


def test_join_is_set_union_until_the_bound():
    a, b = const("a"), const("b")
    assert a.join(b).strings() == ["a", "b"]
    many = BOTTOM
    for i in range(MAX_ATOMS + 1):
        many = many.join(const(i))
    assert many.is_top


def test_constants_of_different_types_stay_apart():
    assert len(list(atoms([Const.of(1), Const.of(True), Const.of(1.0)]))) == 3


def test_widening_jumps_to_top_on_growth_only():
    a = const("a")
    assert a.widen(a) == a
    assert a.widen(const("b")).is_top


def test_nesting_beyond_the_depth_bound_is_top():
    value = const(0)
    for _ in range(10):
        value = atoms([Seq("tuple", (value,))])
    assert value.is_top


def test_softness_survives_join_and_orders_values():
    hard, soft = const("x"), soften(const("x"))
    assert hard.join(soft).soft
    assert hard.leq(soft) and not soft.leq(hard)
    assert not soften(TOP).soft


def test_signed_zero_and_nan_do_not_make_sets_order_dependent():
    zero, minus_zero, nan = Const.of(0.0), Const.of(-0.0), Const.of(float("nan"))
    assert atoms([zero, minus_zero]) == atoms([minus_zero, zero])
    assert atoms([nan, Const.of(float("nan"))]) == atoms([nan])


def test_top_keeps_constants_as_hints_and_saturates_past_the_bound():
    from flake8_rosgraph.absint.values import SATURATED, Extern
    hinted = TOP.join(const("/scan")).join(soften(const("/map")))
    assert hinted.is_top and not hinted.soft and hinted.hinted() == ["/map", "/scan"]
    assert hinted.strings() is None and list(hinted) == []
    assert repr(hinted) == "⊤∪{Const(kind='str', value='/map'), Const(kind='str', value='/scan')}"
    assert TOP.join(atoms([Extern("std_msgs.msg.String")])) == SATURATED
    assert hinted.widen(TOP.join(const("/odom"))) == SATURATED
    many = TOP
    for i in range(MAX_ATOMS + 1):
        many = many.join(const(i))
    assert many == SATURATED and many.join(const("a")) == SATURATED


def test_atoms_are_visited_in_the_same_order_whatever_the_hash_seed():
    """The analysis calls, schedules and builds for each atom of a value in turn: in set order,
    which contexts a function got first (and so which ones its bound kept) followed the hash
    seed, and with them the diagnostics of a whole workspace (yasmin's editor)."""
    import subprocess
    import sys
    probe = ("from flake8_rosgraph.absint.values import atoms, const, Extern\n"
             "value = atoms([const('/scan'), const('/odom'), const(3), Extern('a.B'), Extern('c.D')])\n"
             "print([repr(a) for a in value])\n")
    seen = {subprocess.run([sys.executable, "-c", probe], env={"PYTHONHASHSEED": seed}, capture_output=True,
                           text=True, check=True).stdout for seed in ("1", "2", "3", "4", "5")}
    assert len(seen) == 1
