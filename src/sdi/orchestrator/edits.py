"""Human edits I_h applied to a layout: C' = C ⊕ I_h (paper eq. 3), then re-verified.

An edit is a JSON object: {"op": "move", "id", "position": [x, y, z]}, {"op": "translate",
"id", "by": [dx, dy, dz]}, {"op": "rotate", "id", "yaw_deg"}, {"op": "insert", "id",
"position", "size"?}, {"op": "remove", "id"}. Edits are all-or-nothing: a bad one refuses the
whole batch with a message naming it, and the layout stays as it was.
"""

from __future__ import annotations

import math
from typing import Any

from sdi.errors import InputError
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part, quat_from_yaw


def _vec(edit: dict[str, Any], key: str, k: int) -> tuple[float, float, float]:
    value = edit.get(key)
    if not (
        isinstance(value, list | tuple)
        and len(value) == 3
        and all(
            isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)
            for v in value
        )
    ):
        raise InputError(f"needs {key} as three finite numbers (metres)", field=f"edits[{k}].{key}")
    return (float(value[0]), float(value[1]), float(value[2]))


def apply_edits(
    layout: Layout, edits: list[dict[str, Any]], cell: CellConfig | None = None
) -> Layout:
    cell = cell or CellConfig()
    if not isinstance(edits, list):
        raise InputError("must be a list of edit objects", field="edits")
    parts = {p.id: p for p in layout.objects}
    order = list(layout.ids)
    for k, edit in enumerate(edits):
        if not isinstance(edit, dict):
            raise InputError("must be an object with an 'op'", field=f"edits[{k}]")
        op = edit.get("op")
        raw = edit.get("id")
        pid = raw if isinstance(raw, str) else ""
        if op != "insert" and pid not in parts:
            raise InputError(f"unknown part id {pid!r}", field=f"edits[{k}].id")
        try:
            if op == "move":
                p = parts[pid]
                parts[pid] = Part(
                    id=pid,
                    position=_vec(edit, "position", k),
                    orientation=p.orientation,
                    size=p.size,
                )
            elif op == "translate":
                parts[pid] = parts[pid].moved(*_vec(edit, "by", k))
            elif op == "rotate":
                yaw = edit.get("yaw_deg")
                if not isinstance(yaw, int | float) or not math.isfinite(yaw):
                    raise InputError("needs yaw_deg as a number", field=f"edits[{k}].yaw_deg")
                p = parts[pid]
                parts[pid] = Part(
                    id=pid,
                    position=p.position,
                    orientation=quat_from_yaw(math.radians(yaw)),
                    size=p.size,
                )
            elif op == "insert":
                if not pid or pid in parts:
                    raise InputError(
                        f"needs a new, unused id (got {pid!r})", field=f"edits[{k}].id"
                    )
                size = _vec(edit, "size", k) if "size" in edit else cell.cube
                parts[pid] = Part(id=pid, position=_vec(edit, "position", k), size=size)
                order.append(pid)
            elif op == "remove":
                del parts[pid]
                order.remove(pid)
            else:
                raise InputError(
                    f"unknown op {op!r}; use move, translate, rotate, insert or remove",
                    field=f"edits[{k}].op",
                )
        except ValueError as exc:  # pydantic validation of the new part
            raise InputError(str(exc).splitlines()[0], field=f"edits[{k}]") from None
    if len(order) > cell.limits.max_parts:
        raise InputError(f"more than {cell.limits.max_parts} parts", field="edits")
    return Layout(objects=tuple(parts[i] for i in order))
