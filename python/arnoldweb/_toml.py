"""Python values as TOML text, for Scene.set() and Scene.from_dict().

The library reads the text (the same reader as the CLI), so every check and
message is the library's; this module only spells values.
"""
from __future__ import annotations

import functools
import json
import math
import numbers
from typing import Any, Collection, Mapping

__all__ = ["literal", "document", "integer_keys"]


@functools.lru_cache(maxsize=None)
def integer_keys() -> frozenset:
    """The dotted keys whose values are (or hold) integers, from the library's key table."""
    from . import _arnoldweb as _core
    return frozenset(k["key"] for k in _core.scene_keys() if "integer" in k["type"])


def _whole(value: Any) -> Any:
    """value with every float that has a whole value (1e6, np.float64(64.0)) as an int: the
    spelling of a number where an integer is asked (a float key takes an integer as well)."""
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return value
    if isinstance(value, numbers.Real) and not isinstance(value, numbers.Integral):
        v = float(value)
        return int(v) if v.is_integer() and abs(v) < 2.0 ** 63 else value
    if isinstance(value, (list, tuple)) or (hasattr(value, "tolist") and not isinstance(value, numbers.Number)):
        return [_whole(v) for v in (value.tolist() if hasattr(value, "tolist") else value)]
    return value


def literal(value: Any, integers: Collection[str] = (), key: str = "") -> str:
    """The TOML spelling of a value: bool, int, float, str, list/tuple, dict (inline table).
    Where ``key`` (or, in a table, ``key.sub``) is one of ``integers``, floats with a whole value
    are written as integers."""
    if key in integers:
        value = _whole(value)
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        v = float(value)
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)  # a TOML basic string
    if isinstance(value, Mapping):
        return "{ " + ", ".join(f"{_key(k)} = {literal(v, integers, f'{key}.{k}')}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)) or hasattr(value, "tolist"):
        items = value.tolist() if hasattr(value, "tolist") else value
        return "[" + ", ".join(literal(v, integers) for v in items) + "]"
    raise TypeError(f"a scene value must be a bool, number, string, list or dict, not {type(value).__name__}")


def _key(k: Any) -> str:
    k = str(k)
    if k and all(c.isalnum() or c in "_-" for c in k):
        return k
    return json.dumps(k, ensure_ascii=False)


def _nested(d: Mapping) -> dict:
    """{"model.energy": 30} -> {"model": {"energy": 30}} (dotted keys spread out)."""
    out: dict = {}
    for k, v in d.items():
        if not isinstance(k, str):
            raise TypeError(f"scene keys are strings, not {type(k).__name__} ({k!r})")
        parts = k.split(".")
        node = out
        for p in parts[:-1]:
            node = node.setdefault(p, {})
            if not isinstance(node, dict):
                raise ValueError(f"scene key {k!r}: {p!r} is both a value and a table")
        last = parts[-1]
        if isinstance(v, Mapping):
            v = _nested(v)
            if isinstance(node.get(last), dict):
                node[last].update(v)
                continue
        node[last] = v
    return out


def document(d: Mapping, integers: Collection[str] = ()) -> str:
    """A scene dict ({"model": {"energy": 30}, "panel": [{...}], ...}) as a TOML document (floats
    with a whole value as integers for the keys in ``integers``)."""
    d = _nested(d)
    lines = []
    tables = []
    for k, v in d.items():
        if isinstance(v, dict):
            tables.append((k, v))
        elif isinstance(v, (list, tuple)) and v and all(isinstance(x, Mapping) for x in v):
            tables.append((k, list(v)))
        else:
            lines.append(f"{_key(k)} = {literal(v, integers, k)}")
    for k, v in tables:
        for table in (v if isinstance(v, list) else [v]):
            lines.append("")
            lines.append(f"[[{_key(k)}]]" if isinstance(v, list) else f"[{_key(k)}]")
            for kk, vv in table.items():
                lines.append(f"{_key(kk)} = {literal(vv, integers, f'{k}.{kk}')}")
    return "\n".join(lines) + "\n"
