"""ROS106 invalid-timer-period."""
from __future__ import annotations

import math
from typing import Iterator

from ..graph.model import RosGraph
from .base import Finding, Rule, RuleConfig


def _zero(value) -> bool:
    return type(value) in (int, float) and value == 0


def _problem(what: str, value) -> str | None:
    """Why rclpy rejects (or busy-loops on) ``value`` as a timer period / rate frequency."""
    if isinstance(value, bool):
        return None  # float(True) is 1.0: odd, but it works
    if isinstance(value, (int, float)):
        if math.isnan(value):
            return "is NaN"
        if value < 0:
            return f"is negative ({value!r}): rclpy raises"
        if value == 0:
            return ("is 0: rclpy raises ValueError" if what == "rate frequency" else
                    "is 0: the timer fires on every executor wake-up, a busy loop that starves "
                    "every other callback")
        return None
    if isinstance(value, str):
        if what == "timer period":
            try:
                number = float(value)
            except ValueError:
                return f"is the string {value!r}, which float() cannot convert: rclpy raises"
            return _problem(what, number)
        return f"is the string {value!r}, not a number: rclpy raises TypeError"
    if value is None:
        return "is None: rclpy raises TypeError"
    return None


class InvalidTimerPeriod(Rule):
    """## What it does
    Checks the period given to `create_timer()` and the frequency given to
    `create_rate()`: every value the analysis finds for it must be a positive
    number.

    ## Why is this bad?
    A negative period, a zero or negative rate frequency, `None` or a string
    that is not a number make rclpy raise when the timer or rate is created; a
    period of 0 creates a timer that is always ready, so the executor runs its
    callback in a busy loop and starves everything else.

    ## Known problems
    Only values the analysis knows are checked; a value that is only a
    default the environment can override (a ROS parameter, a command-line
    option) is not judged. Every possible value is checked, so a value that is
    invalid on one branch only is reported too — unless the timer is created on
    some paths only and some of its values are valid. A test that compares a
    local with a constant (`if period > 0:`, `if period:`) rules the failing
    values out of the branch; other guards (`if self.ready():`) do not.
    A timer of period 0 that the code cancels or destroys somewhere
    (`self.timer.cancel()` in its callback, `destroy_timer(self.timer)`) is a
    one-shot that runs once when the executor starts, and is not reported.

    ## Example
    ```python
    period = 0.1 if self.fast else 0  # "0: as fast as possible"
    self.create_timer(period, self.publish)
    ```

    ## Use instead
    ```python
    period = 0.1 if self.fast else 0.02
    self.create_timer(period, self.publish)
    ```

    ## Options
    None.
    """

    code = "ROS106"
    name = "invalid-timer-period"
    level = "error"
    precision = "very-high"
    summary = "a timer period or rate frequency that is not a positive number"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        usage = graph.usage
        if usage is None:
            return
        for arg in usage.periods:
            # A timer the code stops runs its callback once at period 0, then no more.
            values = sorted((v for v in arg.values or () if not (arg.stopped and _zero(v))), key=repr)
            problems = [p for p in (_problem(arg.what, v) for v in values) if p is not None]
            if arg.conditional and len(problems) < len(values):
                continue  # the test that guards the creation may be what excludes the bad value
            for problem in problems:
                yield Finding(arg.location, self.code, f"{arg.what} {problem}")
