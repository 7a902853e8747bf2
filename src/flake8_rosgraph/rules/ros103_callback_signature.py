"""ROS103 callback-signature."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import RosGraph
from ..graph.usage import Callback, Signature
from .base import Finding, Rule, RuleConfig


def _fits(cb: Callback) -> bool:
    """Whether ``cb`` may take what rclpy passes it (an unknown signature may)."""
    sig = cb.signature
    return sig is None or cb.passes is None or (cb.by_annotation and sig.annotated) \
        or any(sig.accepts(n) for n in cb.passes)


def _accepted(sig: Signature) -> str:
    """``sig`` in words: "takes 2 arguments", "takes 1 to 3 arguments", "takes at least 1 argument"."""
    if sig.required_keywords:
        return "requires the keyword argument" + ("s " if len(sig.required_keywords) > 1 else " ") + \
            ", ".join(f"'{k}'" for k in sig.required_keywords)
    if sig.maximum is None:
        low = f"at least {sig.required}"
    elif sig.maximum == sig.required:
        low = str(sig.required)
    else:
        low = f"{sig.required} to {sig.maximum}"
    plural = "" if low.endswith(" 1") or low == "1" else "s"
    return f"takes {low} argument{plural}"


class CallbackSignature(Rule):
    """## What it does
    Checks each function registered as a callback against the arguments the
    library passes it: a subscription callback gets the message, a timer or
    guard-condition callback nothing, a service callback the request and the
    response, action goal / cancel / accepted / execute callbacks the goal
    request or goal handle, a future's done callback the future, a
    set-parameters callback the parameter list. Bound methods do not count
    `self`; parameters with defaults and `*args` make a signature acceptable.
    A subscription callback may also take the message info (rclpy ≥ Iron), a
    timer callback a parameter annotated `TimerInfo` (rclpy ≥ Jazzy).
    Also checks that callbacks whose result rclpy uses (service callbacks: the
    response; set-parameters callbacks: a `SetParametersResult`) return a value
    on every path.

    ## Why is this bad?
    The executor calls the callback only when the first message, request or
    timer tick arrives: a wrong signature is a `TypeError` at run time, often
    long after start-up, and the callback never runs. A service callback that
    returns `None` makes rclpy fail to send the response, so the client waits
    forever.

    ## Known problems
    Functions wrapped by a decorator or `functools.partial` anywhere, and
    generators, are not judged (their signature may not be what is called);
    neither is a timer callback with annotated parameters (rclpy passes
    `TimerInfo` by annotation). A subscription callback taking two arguments is
    accepted although rclpy before Iron passes only the message.
    Callable objects (instances with `__call__`) are not checked.

    ## Example
    ```python
    self.create_timer(0.5, self.on_tick)
    self.create_service(Trigger, 'reset', self.on_reset)

    def on_tick(self, msg):
        ...

    def on_reset(self, request, response):
        self.counter = 0
    ```

    ## Use instead
    ```python
    def on_tick(self):
        ...

    def on_reset(self, request, response):
        self.counter = 0
        response.success = True
        return response
    ```

    ## Options
    None.
    """

    code = "ROS103"
    name = "callback-signature"
    level = "error"
    precision = "very-high"
    summary = "a callback cannot take the arguments rclpy passes, or a service callback returns nothing"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        usage = graph.usage
        if usage is None:
            return
        missing_return: dict[tuple, Callback] = {}
        # A name defined twice under a condition (``if ROS_VERSION == 1: def on_params(self,
        # config, level)`` / ``else: def on_params(self, params)``) is one function or the
        # other: its registration is wrong only if every definition is, and it is one finding.
        fitting = {(cb.registration, cb.role, cb.function) for cb in usage.callbacks if _fits(cb)}
        unfit: dict[tuple, list[Callback]] = {}
        for cb in usage.callbacks:
            sig = cb.signature
            if sig is None or cb.passes is None or (cb.by_annotation and sig.annotated):
                continue
            if not any(sig.accepts(n) for n in cb.passes):
                if (cb.registration, cb.role, cb.function) not in fitting:
                    unfit.setdefault((cb.registration, cb.role, cb.function), []).append(cb)
            elif cb.must_return and cb.may_return_none:
                missing_return.setdefault((cb.definition, cb.must_return), cb)
        for key in sorted(unfit):
            definitions = sorted(unfit[key], key=lambda cb: cb.definition)
            cb = definitions[0]
            given = " or ".join(map(str, cb.passes or ())) + " argument" + ("" if cb.passes == (1,) else "s")
            yield Finding(cb.registration, self.code,
                          f"{cb.role} `{cb.function}` {_accepted(cb.signature)}, but rclpy passes "
                          f"{given}: TypeError when it is called",
                          tuple((d.definition, f"`{d.function}` defined here") for d in definitions))
        for (definition, what), cb in sorted(missing_return.items()):
            yield Finding(definition, self.code,
                          f"{cb.role} `{cb.function}` must return {what}, but returns None on "
                          "some path", ((cb.registration, f"registered as {cb.role} here"),))
