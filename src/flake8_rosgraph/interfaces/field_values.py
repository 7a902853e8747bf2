"""Which Python values rclpy's generated message classes accept in a field.

The rules are rosidl_generator_py's property setters (``_msg.py.em``): a ``float32``/
``float64`` field takes only ``float`` (``1`` is rejected, ``True`` too); an integer field
takes ``int`` (and so ``bool``) within the range of its width; ``bool`` takes only ``bool``;
``string`` only ``str`` (no longer than its bound); ``byte`` a ``bytes`` of length one; a
nested message exactly an instance of its class; an array field a sequence (never a
``str``) of the right length whose elements each pass the element rule. Where releases skip
the setter checks (``ROS_PYTHON_CHECK_FIELDS`` unset, Jazzy on), the C conversion at
publish asserts the same types or silently truncates, so the same values are wrong there.

Values are :class:`~flake8_rosgraph.graph.messages.ValueShape`; an ``other`` shape, or an
instance of a class that is neither a message nor modelled, is never judged.
"""
from __future__ import annotations

from typing import Any

from .catalogue import display_name, message_key
from .definitions import FieldType

#: Inclusive ranges of the integer types (``char`` is an unsigned 8-bit integer in ROS 2).
INT_RANGES: dict[str, tuple[int, int]] = {
    **{f"int{n}": (-2 ** (n - 1), 2 ** (n - 1) - 1) for n in (8, 16, 32, 64)},
    **{f"uint{n}": (0, 2 ** n - 1) for n in (8, 16, 32, 64)},
    "char": (0, 255),
}
FLOAT_TYPES = frozenset({"float32", "float64"})
FLOAT32_MAX = 3.402823466e+38
STRING_TYPES = frozenset({"string", "wstring"})
_SCALAR_KINDS = frozenset({"bool", "int", "float", "str", "bytes", "none"})


def describe(shape: Any) -> str:
    """A value as a message names it: ``the int 5``, ``a geometry_msgs/msg/Vector3 message``."""
    if shape.kind == "none":
        return "None"
    if shape.kind in _SCALAR_KINDS:
        text = repr(shape.value)
        return f"the {shape.kind} {text if len(text) <= 40 else text[:37] + '...'}"
    if shape.kind == "instance":
        key = message_key(shape.cls)
        return f"a {display_name(key)} message" if key else f"a {shape.cls}"
    if shape.kind == "sequence":
        noun = shape.value or "sequence"
        return f"a {noun} of {shape.length}" if shape.length is not None else f"a {noun}"
    return "this value"


def without_none_alternative(shapes: list[Any]) -> list[Any]:
    """The possibilities worth judging: ``None`` beside other values is nearly always the
    failure return of a helper (``path = get_path() or None``) that the caller checks on a path
    the analysis does not separate; ``None`` alone is judged."""
    rest = [s for s in shapes if s.kind != "none"]
    return rest if rest else list(shapes)


def rejection(ftype: FieldType, shape: Any) -> str | None:
    """Why the field rejects the value (a phrase naming the value), or ``None`` when it is
    accepted or cannot be judged."""
    if ftype.array is not None:
        return _array_rejection(ftype, shape)
    return _scalar_rejection(ftype, shape)


def _instance_is_known(shape: Any) -> bool:
    """An instance whose class the analysis can name for sure: a message, or a modelled class."""
    return message_key(shape.cls) is not None or shape.modelled


def _may_be_reexport(key: str | None, base: str) -> bool:
    """Whether a message class of another package but the same name may be the field's own
    class, re-exported: a package's ``msg`` module can import another's classes
    (bosdyn_msgs.msg does ``from bosdyn_api_msgs.msg import *``), and the class keeps its name."""
    return key is not None and key.rsplit("/", 1)[-1] == base.rsplit("/", 1)[-1] \
        and key.split("/", 1)[0] != base.split("/", 1)[0]


def _scalar_rejection(ftype: FieldType, shape: Any) -> str | None:
    kind, base = shape.kind, ftype.base
    if kind == "instance":
        if ftype.is_message:
            key = message_key(shape.cls)
            if key == base or not _instance_is_known(shape) or _may_be_reexport(key, base):
                return None
            return describe(shape)
        return describe(shape) if _instance_is_known(shape) else None
    if kind not in _SCALAR_KINDS and kind != "sequence":
        return None
    if ftype.is_message:
        return describe(shape)
    if kind == "sequence":
        return describe(shape)
    if base == "bool":
        return None if kind == "bool" else describe(shape)
    if base in INT_RANGES:
        if kind == "bool":
            return None  # bool is an int subclass: accepted
        if kind != "int":
            return describe(shape)
        low, high = INT_RANGES[base]
        return None if low <= shape.value <= high else f"{describe(shape)} (out of [{low}, {high}])"
    if base in FLOAT_TYPES:
        if kind != "float":
            return describe(shape)
        value = shape.value
        if base == "float32" and abs(value) > FLOAT32_MAX and value not in (float("inf"), float("-inf")):
            return f"{describe(shape)} (out of the float32 range)"
        return None
    if base in STRING_TYPES:
        if kind != "str":
            return describe(shape)
        if ftype.string_bound is not None and len(shape.value) > ftype.string_bound:
            return f"{describe(shape)} (longer than {ftype.string_bound})"
        return None
    if base == "byte":
        return None if kind == "bytes" and len(shape.value) == 1 else describe(shape)
    return None


def _array_rejection(ftype: FieldType, shape: Any) -> str | None:
    kind = shape.kind
    if kind == "bytes":
        return None  # bytes is a sequence (of ints)
    if kind in _SCALAR_KINDS:
        return describe(shape)
    if kind == "instance":
        return describe(shape) if _instance_is_known(shape) else None
    if kind != "sequence":
        return None
    if shape.length is not None:
        if ftype.array == "fixed" and shape.length != ftype.size:
            return f"{describe(shape)} (the array has exactly {ftype.size})"
        if ftype.array == "bounded" and shape.length > ftype.size:
            return f"{describe(shape)} (the array holds at most {ftype.size})"
    for item in shape.items or ():
        why = _scalar_rejection(ftype.element(), item)
        if why is not None:
            return f"a sequence holding {why}"
    return None
