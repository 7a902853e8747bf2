"""ROS105 lifecycle-order."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import RosGraph
from .base import Finding, Rule, RuleConfig

#: What rclpy does in each case.
CONSEQUENCE = {
    "before rclpy.init()": "the default context is not initialised yet: rclpy raises",
    "after rclpy.shutdown()": "the default context is shut down: rclpy raises",
    "after its destroy_node()": "its handle is destroyed: rclpy raises InvalidHandle",
}


class LifecycleOrder(Rule):
    """## What it does
    Checks the order of rclpy's life-cycle calls inside one function (or module
    body): a node created before an `rclpy.init()` that follows it on every
    path, a node created after an `rclpy.shutdown()` that precedes it on every
    path (with no `rclpy.init()` in between), and a publisher, subscription,
    timer, service, client, action or parameter created on a node after that
    node's `destroy_node()`. Creations through calls (a node class's
    constructor, a factory) count.

    ## Why is this bad?
    Nodes live in the default context that `rclpy.init()` creates and
    `rclpy.shutdown()` ends: creating one outside it raises at run time, and a
    destroyed node has no handle left to create entities with.

    ## Known problems
    Only calls that run on every path of the same body (outside `try`) order
    it (the plain statements of a script's `if __name__ == '__main__':` count
    as its module body's); calls spread over several functions, or code that uses its own
    `Context`, are not judged. Using a node after shutdown other than creating
    one (spinning, publishing) is not reported.

    ## Example
    ```python
    def main():
        node = Talker()
        rclpy.init()
        rclpy.spin(node)
    ```

    ## Use instead
    ```python
    def main():
        rclpy.init()
        node = Talker()
        rclpy.spin(node)
    ```

    ## Options
    None.
    """

    code = "ROS105"
    name = "lifecycle-order"
    level = "error"
    precision = "very-high"
    summary = "a node created outside rclpy.init()/shutdown(), or an entity created on a destroyed node"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        usage = graph.usage
        if usage is None:
            return
        for item in usage.out_of_order:
            yield Finding(item.location, self.code,
                          f"{item.what} {item.problem}: {CONSEQUENCE[item.problem]}",
                          ((item.other, f"{item.problem.split()[-1]} here"),))
