"""Stub references the analyser evaluates generically: named constants, key filters, record
constructors that name their fields, and records updated through an attribute."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.absint.values import Record
from flake8_rosgraph.analysis import load_stubs
from flake8_rosgraph.workspace import load_workspace

STUB = '''
[meta]
library = "acme"

[aliases]
"acme.presets.Presets.FAST.value" = "acme.presets.fast"

[constants."acme.presets.fast"]
record = "acme.Config"
fields = { speed = 10, mode = "fast" }

[constants."acme.presets.slow"]
record = "acme.Config"
fields = { speed = 1, mode = "slow" }

[classes."acme.presets.Presets".methods.by_key]
params = "name"
returns = { constant = "acme.presets.Presets.{name|upper}.value" }

[functions."acme.presets.lookup"]
params = "name"
returns = { constant = "acme.presets.{name}" }

[functions."acme.paths.absolute"]
params = "path=None"
returns = { format = "{path|rooted}" }

[functions."acme.paths.shout"]
params = "word"
returns = { format = "{word|upper}!" }

[classes."acme.Config"]
record = true

[classes."acme.Config".methods.__init__]
params = "self, speed=0, mode='normal'"

[classes."acme.Span"]
record = true

[classes."acme.Span".methods.__init__]
params = "self, *, minutes=0, seconds=0"
returns = { record = "acme.Span", fields = { whole_minutes = "minutes", extra_seconds = "seconds" } }

[classes."acme.Options".methods.get]
params = "self, name"
returns = { overridable = "name" }
'''


@pytest.fixture
def acme(tmp_path: Path):
    def analyse(code: str) -> Analysis:
        (tmp_path / "ws").mkdir(exist_ok=True)
        (tmp_path / "ws" / "m.py").write_text(textwrap.dedent(code))
        (tmp_path / "acme.toml").write_text(STUB)
        library, diags = load_stubs([tmp_path / "acme.toml"])
        assert not diags
        analysis = Analysis(Program(load_workspace(tmp_path / "ws").modules), library,
                            every_module_is_entry=True)
        analysis.run()
        return analysis
    return analyse


def value(analysis: Analysis, name: str):
    return analysis.heap[("g", "m", name)]


def test_a_constant_reference_finds_the_constant_its_template_names(acme):
    a = acme("""
        from acme.presets import Presets, lookup
        fast = Presets.by_key('fast')
        slow = lookup('slow')
        missing = lookup('warp')
        speed = Presets.by_key('Fast').speed
    """)
    assert value(a, "speed").consts() == [10]
    [slow] = list(value(a, "slow"))
    assert isinstance(slow, Record) and slow.field("mode").strings() == ["slow"]
    assert value(a, "missing").is_top          # not modelled: unknown, never a guess


def test_a_lookup_by_an_overridable_name_is_only_a_default(acme):
    a = acme("""
        import acme
        from acme.presets import lookup
        from acme.paths import shout
        options = acme.Options()
        chosen = lookup(options.get('slow'))
        fixed = lookup('slow')
        loud = shout(options.get('go'))
    """)
    assert value(a, "chosen").soft and not value(a, "fixed").soft
    assert value(a, "loud").strings() == ["GO!"] and value(a, "loud").soft


def test_rooted_filter_makes_absolute_paths(acme):
    a = acme("""
        from acme.paths import absolute
        none = absolute()
        empty = absolute('')
        relative = absolute('robot1')
        already = absolute('/robot1')
    """)
    assert [value(a, n).strings() for n in ("none", "empty", "relative", "already")] == \
        [["/"], ["/"], ["/robot1"], ["/robot1"]]


def test_a_record_constructor_may_name_its_fields_apart_from_its_arguments(acme):
    a = acme("""
        import acme
        span = acme.Span(minutes=2, seconds=5)
        minutes = span.whole_minutes
        seconds = span.seconds
        config = acme.Config(3)
        speed = config.speed
    """)
    assert value(a, "minutes").consts() == [2]
    assert value(a, "seconds").is_top          # not a field: not the argument either
    assert value(a, "speed").consts() == [3]   # records without `returns` keep their arguments


def test_a_record_held_in_an_attribute_is_updated_through_it(acme):
    a = acme("""
        import acme
        class Holder:
            pass
        holder = Holder()
        holder.config = acme.Config(speed=1)
        holder.config.mode = 'eco'
        mode = holder.config.mode
    """)
    assert "eco" in value(a, "mode").strings()
