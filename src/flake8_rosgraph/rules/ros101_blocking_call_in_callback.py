"""ROS101 blocking-call-in-callback."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import RosGraph
from ..graph.usage import BlockingCall
from .base import Finding, Rule, RuleConfig

#: A sleep this long (seconds) or longer inside a callback is reported; shorter ones are not.
LONG_SLEEP_S = 1.0


def deadlocks(call: BlockingCall) -> str | None:
    """What goes wrong when ``call`` runs inside its callback, or ``None`` when it may be legal."""
    if call.kind == "wait":
        if call.same_node is not True:
            return None  # an entity of another node: another executor may serve it
        if call.concurrent is False:
            return "the executor cannot deliver it while this callback holds the callback group (deadlock)"
        if call.executor == "single":
            return "the single-threaded executor is busy running this callback (deadlock)"
        return None
    if call.kind == "spin":
        if call.same_node is True:
            return ("that executor is already running this callback: the spin re-enters it, and "
                    "nothing of this callback's group runs until it returns (deadlock when it "
                    "waits for one of them)")
        return None
    if call.kind == "sleep":
        if call.seconds and max(call.seconds) >= LONG_SLEEP_S and call.executor == "single":
            return (f"for {max(call.seconds):g} s the single-threaded executor runs no other "
                    "callback, timer or service of the node")
        return None
    if call.executor == "single":
        return "the single-threaded executor runs nothing else meanwhile"
    return None


class BlockingCallInCallback(Rule):
    """## What it does
    Follows every call chain, across functions and modules, from each function
    an rclpy executor calls back — subscription, timer, service, guard condition,
    action (goal, cancel, accepted, execute, feedback) and future done callbacks —
    to the blocking calls the stubs mark (`blocking = "…"`): `Client.call()`,
    `ActionClient.send_goal()`, `Rate.sleep()`, `rclpy.spin*()`,
    `Executor.spin*()` and long `time.sleep()`. It reports at the call in the
    callback that starts the chain and lists the chain down to the blocking call.

    It stays quiet where the call is legal:

    - a synchronous call waits for a client whose responses run in another
      callback group than the calling callback (or in a reentrant group) — unless
      the node is known to be spun by a single-threaded executor;
    - the client (or rate) belongs to another node, which another executor may
      spin;
    - a spin of another node or executor than the one running the callback;
    - `time.sleep()` shorter than one second, of unknown length, or on a node not
      known to be spun by a single-threaded executor (`rclpy.spin(node)`,
      `SingleThreadedExecutor`): a long sleep only stalls that executor, it does
      not deadlock it.

    ## Why is this bad?
    An executor runs the callbacks of a callback group one at a time (all of a
    node's callbacks share its default, mutually exclusive group), and a
    single-threaded executor runs one callback at a time in all. A service
    response, an action result or a rate's timer is delivered by the executor
    too: waiting for it inside a callback waits for something the executor
    cannot do until the callback returns — the node hangs for good (or until the
    timeout). Spinning the executor that is running the callback re-enters it.

    ## Known problems
    Which executor spins a node is read from `rclpy.spin(node)`,
    `executor.add_node(node)` and the like in the workspace; a node spun
    elsewhere counts as unknown, and then only calls that deadlock under any
    executor (a client in the caller's own exclusive group) are reported.
    `Future.result()` is not reported: in rclpy it never blocks (it returns
    `None` before the future is done). A chain is followed through the calls
    the analysis resolves; calls through unknown objects are not followed.

    ## Example
    ```python
    def on_update(self, msg):
        response = self.map_client.call(GetMap.Request())  # hangs forever
        self.map_pub.publish(response.map)
    ```

    ## Use instead
    ```python
    def on_update(self, msg):
        future = self.map_client.call_async(GetMap.Request())
        future.add_done_callback(lambda f: self.map_pub.publish(f.result().map))
    ```
    or give the client its own callback group and spin the node with a
    `MultiThreadedExecutor`.

    ## Options
    None.
    """

    code = "ROS101"
    name = "blocking-call-in-callback"
    level = "error"
    precision = "high"
    summary = "a callback reaches a call that blocks the executor running it (deadlock or stall)"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        usage = graph.usage
        if usage is None:
            return
        for call in usage.blocking:
            consequence = deadlocks(call)
            if consequence is None:
                continue
            first, last = call.steps[0], call.steps[-1]
            via = ""
            if len(call.steps) > 1:
                via = " via " + " → ".join(f"`{s.text}`" for s in call.steps[:-1])
            cb = call.callback
            message = (f"`{last.text}` reached from {cb.role} `{cb.function}`{via} "
                       f"{call.why}; {consequence}")
            related = [(cb.registration, f"`{cb.function}` registered as {cb.role} here")]
            related += [(s.location, f"calls `{s.text}`") for s in call.steps[1:-1]]
            if len(call.steps) > 1:
                related.append((last.location, f"`{last.text}` {call.why}"))
            yield Finding(first.location, self.code, message, tuple(related))
