"""Python values as the TOML text of a ``--set key=value`` override."""
import json
import math
from typing import Any


def toml_value(value: Any) -> str:
    """``value`` written as TOML: booleans, numbers (every digit of a float), strings, lists and dicts
    (inline tables). A value of another type raises TypeError."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string: the same escapes
    if hasattr(value, "tolist") and not isinstance(value, (list, tuple)):  # numpy scalars and arrays
        return toml_value(value.tolist())
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + "}"
    raise TypeError(f"a case value must be a bool, number, string, list or dict, not {type(value).__name__}")


def override(key: str, value: Any) -> str:
    """The ``--set`` text of ``key`` = ``value``."""
    if not isinstance(key, str) or not key:
        raise TypeError("a case key is a dotted name such as 'jet.velocity'")
    return f"{key}={toml_value(value)}"
