"""Plain JSON values for everything that is stored: checkpoints, the message bus, reports."""

from __future__ import annotations

from typing import Any


def plain(value: Any) -> Any:
    """A JSON-ready copy: numpy scalars and arrays become numbers and lists, tuples lists."""
    if isinstance(value, dict):
        return {str(k): plain(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [plain(v) for v in value]
    if hasattr(value, "tolist"):  # numpy scalar or array
        return plain(value.tolist())
    return value
