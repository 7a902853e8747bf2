"""The codes the rules report, for the front ends that need them before the rules are loaded.

flake8 asks the plugin in ``parse_options``, on every run, which of its codes the user's
``--select``/``--ignore`` leave on. A warm run then only reads the kept report, so importing
every rule module (about a tenth of a second) just to learn their codes would be most of
what the plugin costs it. ``tests/test_codes.py`` keeps this table equal to
:data:`flake8_rosgraph.rules.RULES`.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class RuleCode:
    """A rule's code and whether it runs without being asked for (see :class:`.options.CodeFilter`)."""

    code: str
    default_enabled: bool = True


#: Every rule's code, in code order.
RULE_CODES: tuple[RuleCode, ...] = (
    *(RuleCode(f"ROS{n:03d}") for n in range(1, 10)),
    RuleCode("ROS010", default_enabled=False),
    *(RuleCode(f"ROS{n:03d}") for n in range(101, 108)),
    *(RuleCode(f"ROS{n:03d}") for n in range(201, 207)),
)
