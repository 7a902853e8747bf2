"""CFG construction: edges, short-circuit lowering, and which blocks always run."""
import ast

from flake8_rosgraph.absint.cfg import Bind, Eval, Return, build_cfg


def cfg_of(code: str):
    return build_cfg(ast.parse(code).body)


def edges(cfg):
    return sorted((b.id, e.target, e.polarity if e.test is not None else None)
                  for b in cfg.blocks.values() for e in b.succs)


def reachable(cfg):
    seen, todo = set(), [cfg.entry]
    while todo:
        b = todo.pop()
        if b in seen:
            continue
        seen.add(b)
        todo.extend(e.target for e in cfg.blocks[b].succs)
        todo.extend(cfg.blocks[b].exc_succs)
    return seen


def block_with(cfg, predicate):
    return [b.id for b in cfg.blocks.values() if any(predicate(op) for op in b.ops)]


def calls_to(name):
    def pred(op):
        return any(isinstance(n, ast.Call) and getattr(n.func, "id", None) == name
                   for n in ast.walk(op if isinstance(op, ast.AST) else getattr(op, "expr", op)
                                     if isinstance(op, Eval) else ast.Pass()))
    return pred


def test_if_else_has_true_and_false_edges():
    cfg = cfg_of("if c:\n    a()\nelse:\n    b()\nd()\n")
    polarities = [p for _, _, p in edges(cfg) if p is not None]
    assert sorted(polarities) == [False, True]


def test_statement_after_if_dominates_exit_but_branches_do_not():
    cfg = cfg_of("if c:\n    a()\nelse:\n    b()\nd()\n")
    dom = cfg.exit_dominators()
    assert block_with(cfg, calls_to("d"))[0] in dom
    assert block_with(cfg, calls_to("a"))[0] not in dom
    assert block_with(cfg, calls_to("b"))[0] not in dom


def test_and_is_lowered_to_two_tests():
    cfg = cfg_of("if a and b:\n    x()\n")
    tests = [op for b in cfg.blocks.values() for op in b.ops if isinstance(op, Eval)]
    assert [ast.unparse(t.expr) for t in tests] == ["a", "b"]


def test_not_swaps_branch_polarity():
    plain = cfg_of("if a:\n    x()\n")
    negated = cfg_of("if not a:\n    x()\n")
    x_plain = block_with(plain, calls_to("x"))[0]
    x_neg = block_with(negated, calls_to("x"))[0]
    into = lambda cfg, t: [e.polarity for b in cfg.blocks.values() for e in b.succs if e.target == t]
    assert into(plain, x_plain) == [True]
    assert into(negated, x_neg) == [False]


def test_while_loop_has_back_edge_and_loop_head():
    cfg = cfg_of("while c:\n    a()\nb()\n")
    assert len(cfg.loop_heads) == 1
    head = next(iter(cfg.loop_heads))
    assert any(e.target == head for b in cfg.blocks.values() if b.id != head and b.id != cfg.entry
               for e in b.succs)


def test_break_skips_loop_else():
    cfg = cfg_of("for x in y:\n    break\nelse:\n    e()\nz()\n")
    # the else block is reachable (loop may not run) and the break goes to after the loop
    assert block_with(cfg, calls_to("e"))
    assert block_with(cfg, calls_to("z"))[0] in reachable(cfg)


def test_for_binds_target_from_iterator():
    cfg = cfg_of("for a, b in pairs:\n    use(a)\n")
    binds = [op for blk in cfg.blocks.values() for op in blk.ops if isinstance(op, Bind)]
    assert len(binds) == 1 and binds[0].how == "iter"


def test_code_after_return_is_unreachable():
    fn = cfg_of("return 1\nafter()\n")
    assert not block_with(fn, calls_to("after"))
    assert any(isinstance(op, Return) for b in fn.blocks.values() for op in b.ops)
    assert fn.exit in reachable(fn)


def test_raise_outside_try_ends_the_path():
    cfg = cfg_of("if c:\n    raise ValueError()\nafter()\n")
    raising = [b for b in cfg.blocks.values() if any(isinstance(op, Eval) and isinstance(op.expr, ast.Call)
                                                     for op in b.ops)]
    assert any(not b.succs for b in raising)


def test_try_statements_have_exception_edges_to_handlers():
    cfg = cfg_of("try:\n    a()\n    b()\nexcept E as err:\n    h()\nfinally:\n    f()\n")
    handler = [b for b in cfg.blocks.values()
               if any(isinstance(op, Bind) and op.how == "except" for op in b.ops)]
    assert len(handler) == 1
    sources = [b for b in cfg.blocks.values() if handler[0].id in b.exc_succs]
    assert len(sources) >= 2  # a() and b() each may raise
    assert block_with(cfg, calls_to("f"))[0] in cfg.exit_dominators()


def test_match_cases_fall_through_and_bind_captures():
    cfg = cfg_of("match cmd:\n    case ['go', where]:\n        go(where)\n    case _:\n        stop()\n")
    binds = [op for b in cfg.blocks.values() for op in b.ops if isinstance(op, Bind)]
    assert [b.how for b in binds] == ["match", "match"]
    assert block_with(cfg, calls_to("go")) and block_with(cfg, calls_to("stop"))


def test_with_binds_context_value():
    cfg = cfg_of("with open(p) as f:\n    use(f)\n")
    binds = [op for b in cfg.blocks.values() for op in b.ops if isinstance(op, Bind)]
    assert binds[0].how == "enter"


def test_statements_in_a_try_body_still_dominate_the_exit():
    cfg = cfg_of("try:\n    a()\n    b()\nexcept KeyboardInterrupt:\n    pass\nc()\n")
    dom = cfg.exit_dominators()
    assert block_with(cfg, calls_to("a"))[0] in dom
    assert block_with(cfg, calls_to("b"))[0] in dom
