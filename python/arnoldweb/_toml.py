"""Python values as TOML text, for Scene.set() and Scene.from_dict().

The library reads the text (the same reader as the CLI), so every check and
message is the library's; this module only spells values.
"""
from __future__ import annotations

import json
import math
import numbers
from typing import Any, Mapping

__all__ = ["literal", "document"]


def literal(value: Any) -> str:
    """The TOML spelling of a value: bool, int, float, str, list/tuple, dict (inline table)."""
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
        return "{ " + ", ".join(f"{_key(k)} = {literal(v)}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)) or hasattr(value, "tolist"):
        items = value.tolist() if hasattr(value, "tolist") else value
        return "[" + ", ".join(literal(v) for v in items) + "]"
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


def document(d: Mapping) -> str:
    """A scene dict ({"model": {"energy": 30}, "panel": [{...}], ...}) as a TOML document."""
    d = _nested(d)
    lines = []
    tables = []
    for k, v in d.items():
        if isinstance(v, dict):
            tables.append((k, v))
        elif isinstance(v, (list, tuple)) and v and all(isinstance(x, Mapping) for x in v):
            tables.append((k, list(v)))
        else:
            lines.append(f"{_key(k)} = {literal(v)}")
    for k, v in tables:
        for table in (v if isinstance(v, list) else [v]):
            lines.append("")
            lines.append(f"[[{_key(k)}]]" if isinstance(v, list) else f"[{_key(k)}]")
            for kk, vv in table.items():
                lines.append(f"{_key(kk)} = {literal(vv)}")
    return "\n".join(lines) + "\n"
