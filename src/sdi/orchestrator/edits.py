"""Human edits I_h applied to a layout: C' = C ⊕ I_h (paper eq. 3), then re-verified.

An edit is a JSON object: {"op": "move", "id", "position": [x, y, z]}, {"op": "translate",
"id", "by": [dx, dy, dz]}, {"op": "rotate", "id", "yaw_deg"}, {"op": "insert", "id",
"position", "size"?, "yaw_deg"?}, {"op": "remove", "id"}, and the order edit {"op":
"sequence", …} with one of "order": [ids] (the whole order), "reverse": true, or "move": id or
[ids] with "before": id (those parts placed just before that one). Edits are all-or-nothing: a
bad one refuses the whole batch with a message naming it, and the layout stays as it was.
`edit` also says which parts the operator touched and the order they asked for (None if they
gave no order edit); `apply_edits` is its layout.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from sdi.errors import InputError
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part, quat_from_yaw


def finite3(value: Any) -> tuple[float, float, float] | None:
    """`value` as three finite floats (a position, m), or None when it is not one — also for
    an integer past any float, which a JSON body may hold (`math.isfinite` would raise)."""
    if not (isinstance(value, list | tuple) and len(value) == 3):
        return None
    out = []
    for v in value:
        if isinstance(v, bool) or not isinstance(v, int | float):
            return None
        try:
            f = float(v)
        except OverflowError:
            return None
        if not math.isfinite(f):
            return None
        out.append(f)
    return (out[0], out[1], out[2])


def _vec(edit: dict[str, Any], key: str, k: int) -> tuple[float, float, float]:
    value = finite3(edit.get(key))
    if value is None:
        raise InputError(f"needs {key} as three finite numbers (metres)", field=f"edits[{k}].{key}")
    return value


@dataclass(frozen=True)
class Edited:
    """An edit batch's result: the operator's layout, their order (None: the Inspector's), the
    parts they moved, turned or inserted, and the parts they removed."""

    layout: Layout
    sequence: tuple[str, ...] | None
    touched: tuple[str, ...]
    removed: tuple[str, ...]
    asked: tuple[tuple[str, str], ...] = ()  # (earlier, later): the move-before edits' pairs


def _ids(edit: dict[str, Any], key: str, k: int, known: list[str]) -> list[str]:
    value = edit.get(key)
    names = [value] if isinstance(value, str) else value
    if not isinstance(names, list) or not names or not all(isinstance(n, str) for n in names):
        raise InputError(f"needs {key} as a part id or a list of part ids",
                         field=f"edits[{k}].{key}")  # fmt: skip
    unknown = [n for n in names if n not in known]
    if unknown:
        raise InputError(f"unknown part id(s) {unknown}; the order holds {known[:12]}",
                         field=f"edits[{k}].{key}")  # fmt: skip
    if len(set(names)) != len(names):
        raise InputError("names a part twice", field=f"edits[{k}].{key}")
    return list(names)


def _reordered(edit: dict[str, Any], k: int, order: list[str]) -> list[str]:
    """The order edit applied to `order`: a whole order, reverse, or move-before."""
    given = [key for key in ("order", "reverse", "move") if key in edit]
    if len(given) != 1:
        raise InputError(
            'give exactly one of "order": [ids], "reverse": true, or "move": ids with '
            f'"before": id (got {given or "none"})',
            field=f"edits[{k}]",
        )
    if given[0] == "order":
        new = _ids(edit, "order", k, order)
        if sorted(new) != sorted(order):
            missing = [pid for pid in order if pid not in new]
            raise InputError(f"must name every part once; missing {missing[:12]}",
                             field=f"edits[{k}].order")  # fmt: skip
        return new
    if given[0] == "reverse":
        if edit["reverse"] is not True:
            raise InputError("must be true (or leave it out)", field=f"edits[{k}].reverse")
        return order[::-1]
    moving = _ids(edit, "move", k, order)
    before = _ids(edit, "before", k, order)
    if len(before) != 1 or before[0] in moving:
        raise InputError("needs one part id that is not being moved", field=f"edits[{k}].before")
    rest = [pid for pid in order if pid not in moving]
    at = rest.index(before[0])
    return rest[:at] + moving + rest[at:]


def edit(
    layout: Layout,
    edits: list[dict[str, Any]],
    cell: CellConfig | None = None,
    *,
    sequence: Sequence[str] | None = None,
) -> Edited:
    """C ⊕ I_h with what the operator touched; `sequence` is the order an order edit starts
    from (default: the layout's part order)."""
    cell = cell or CellConfig()
    if not isinstance(edits, list):
        raise InputError("must be a list of edit objects", field="edits")
    parts = {p.id: p for p in layout.objects}
    order = list(layout.ids)
    placing = list(sequence) if sequence is not None and sorted(sequence) == sorted(order) \
        else list(order)  # fmt: skip
    ordered = False
    touched: list[str] = []
    removed: list[str] = []
    asked: list[tuple[str, str]] = []
    for k, item in enumerate(edits):
        if not isinstance(item, dict):
            raise InputError("must be an object with an 'op'", field=f"edits[{k}]")
        op = item.get("op")
        if op == "sequence":
            placing = _reordered(item, k, placing)
            ordered = True
            if "move" in item:
                moving = [item["move"]] if isinstance(item["move"], str) else item["move"]
                then = item["before"] if isinstance(item["before"], str) else item["before"][0]
                asked += [(str(m), str(then)) for m in moving if (str(m), str(then)) not in asked]
            continue
        raw = item.get("id")
        pid = raw if isinstance(raw, str) else ""
        if op != "insert" and pid not in parts:
            raise InputError(f"unknown part id {pid!r}", field=f"edits[{k}].id")
        try:
            if op == "move":
                p = parts[pid]
                parts[pid] = Part(
                    id=pid,
                    position=_vec(item, "position", k),
                    orientation=p.orientation,
                    size=p.size,
                )
            elif op == "translate":
                parts[pid] = parts[pid].moved(*_vec(item, "by", k))
            elif op == "rotate":
                p = parts[pid]
                parts[pid] = Part(
                    id=pid,
                    position=p.position,
                    orientation=quat_from_yaw(math.radians(_yaw(item, k))),
                    size=p.size,
                )
            elif op == "insert":
                if not pid or pid in parts:
                    raise InputError(
                        f"needs a new, unused id (got {pid!r})", field=f"edits[{k}].id"
                    )
                size = _vec(item, "size", k) if "size" in item else cell.cube
                yaw = _yaw(item, k) if "yaw_deg" in item else 0.0
                parts[pid] = Part(id=pid, position=_vec(item, "position", k), size=size,
                                  orientation=quat_from_yaw(math.radians(yaw)))  # fmt: skip
                order.append(pid)
                placing.append(pid)
            elif op == "remove":
                del parts[pid]
                order.remove(pid)
                placing.remove(pid)
                removed.append(pid)
            else:
                raise InputError(
                    f"unknown op {op!r}; use move, translate, rotate, insert, remove or sequence",
                    field=f"edits[{k}].op",
                )
        except ValueError as exc:  # pydantic validation of the new part
            raise InputError(str(exc).splitlines()[0], field=f"edits[{k}]") from None
        if op != "remove" and pid not in touched:
            touched.append(pid)
    if len(order) > cell.limits.max_parts:
        raise InputError(f"more than {cell.limits.max_parts} parts", field="edits")
    return Edited(
        layout=Layout(objects=tuple(parts[i] for i in order)),
        sequence=tuple(placing) if ordered else None,
        touched=tuple(pid for pid in touched if pid in parts),
        removed=tuple(removed),
        asked=tuple((a, b) for a, b in asked if a in parts and b in parts),
    )


def _yaw(item: dict[str, Any], k: int) -> float:
    yaw = item.get("yaw_deg")
    if isinstance(yaw, bool) or not isinstance(yaw, int | float) or not math.isfinite(yaw):
        raise InputError("needs yaw_deg as a number (degrees)", field=f"edits[{k}].yaw_deg")
    return float(yaw)


def apply_edits(
    layout: Layout, edits: list[dict[str, Any]], cell: CellConfig | None = None
) -> Layout:
    """The operator's layout C ⊕ I_h (`edit` without what was touched)."""
    return edit(layout, edits, cell).layout
