"""Design review in the twin (touch point 1): the operator's edits I_h, undo/redo, instant check.

A `ReviewSession` holds the layout the orchestrator proposed (C) and the operator's finished
edits, one undo step each. Every step is a list of edits in the orchestrator's own edit format
(`sdi.orchestrator.edits`), so what the operator accepts is sent to the run as it is and
applied there by the same code: C' = C ⊕ I_h. After each step the Inspector runs on C' at once;
its violations colour the parts and list their hints.

Page operations (`apply`): ``move`` (a finished drag; snapped to the part grid unless
``free``), ``rotate`` (±90° about z), ``insert`` (a cube or beam of the cell, optionally
turned), ``remove``, ``reorder`` (move one part before another in the assembly order) and
``hint`` (apply a violation's suggestion). Each raises `InputError` naming the field.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from sdi.errors import InputError
from sdi.execute.record import layout_hash
from sdi.inspector.verifier import Report, verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.orchestrator.edits import apply_edits, finite3

Edit = dict[str, Any]


def yaw_deg(orientation: tuple[float, float, float, float]) -> float:
    """Rotation about z (degrees) of a part's quaternion [w, x, y, z] that turns about z only."""
    w, z = orientation[0], orientation[3]
    return math.degrees(2.0 * math.atan2(z, w))


def page_parts(layout: dict[str, Any] | None) -> list[dict[str, Any]] | None:
    """A layout (its JSON form) as the page draws it: id, centre (m), size (m), yaw (°)."""
    if not layout:
        return None
    return [
        {"id": p["id"], "position": p["position"], "size": p["size"],
         "yaw_deg": round(yaw_deg(tuple(p.get("orientation", (1, 0, 0, 0)))), 3)}
        for p in layout["objects"]
    ]  # fmt: skip


def snap(position: list[float], size: tuple[float, float, float], cell: CellConfig) -> list[float]:
    """The nearest grid position: x, y on half a cube; z on a resting level of the part."""
    grid = cell.cube[0] / 2
    level = cell.cube[2]
    x, y, z = position
    k = max(0, round((z - size[2] / 2) / level))
    return [round(round(x / grid) * grid, 6), round(round(y / grid) * grid, 6),
            round(size[2] / 2 + k * level, 6)]  # fmt: skip


def _vec3(value: Any, name: str) -> list[float]:
    xyz = finite3(value)
    if xyz is None or not isinstance(value, list):
        raise InputError("needs three finite numbers (metres)", field=name)
    return list(xyz)


@dataclass
class ReviewSession:
    """The operator's edits of one proposed design."""

    cell: CellConfig
    base: Layout
    steps: list[list[Edit]] = field(default_factory=list)
    undone: list[list[Edit]] = field(default_factory=list)
    version: int = 0
    _layout: Layout | None = None
    _report: Report | None = None

    @property
    def base_hash(self) -> str:
        return layout_hash(self.base)

    @property
    def edits(self) -> list[Edit]:
        return [e for step in self.steps for e in step]

    @property
    def order(self) -> list[str] | None:
        """The operator's assembly order, if a step set one (the last one wins)."""
        orders = [e["order"] for e in self.edits if e.get("op") == "sequence"]
        return list(orders[-1]) if orders else None

    def layout(self) -> Layout:
        if self._layout is None:
            self._layout = self._built(self.steps)
        return self._layout

    def _built(self, steps: list[list[Edit]]) -> Layout:
        """C ⊕ I_h for these steps (the order edits set no geometry)."""
        geometric = [e for step in steps for e in step if e.get("op") != "sequence"]
        return apply_edits(self.base, geometric, self.cell)

    def report(self) -> Report:
        """The Inspector on C ⊕ I_h (with the operator's order, if they set one)."""
        if self._report is None:
            layout = self.layout()
            order = self.order
            if order is not None:  # parts inserted or removed since the reorder
                have = set(layout.ids)
                order = [i for i in order if i in have]
                order += [i for i in layout.ids if i not in order]
            self._report = verify(layout, self.cell, sequence=order)
        return self._report

    # -- operations -------------------------------------------------------------------------------
    def _changed(self) -> None:
        self._layout = None
        self._report = None
        self.version += 1

    def apply(self, op: dict[str, Any]) -> None:
        """One finished page operation → one undo step (the whole step or nothing)."""
        steps = [*self.steps, self._edits_for(op)]
        layout = self._built(steps)  # a refused edit raises here: nothing has changed
        self.steps = steps
        self.undone.clear()
        self._changed()
        self._layout = layout

    def undo(self) -> bool:
        if not self.steps:
            return False
        self.undone.append(self.steps.pop())
        self._changed()
        return True

    def redo(self) -> bool:
        if not self.undone:
            return False
        self.steps.append(self.undone.pop())
        self._changed()
        return True

    def _part(self, op: dict[str, Any]) -> Any:
        pid = op.get("id")
        part = next((p for p in self.layout().objects if p.id == pid), None)
        if part is None:
            raise InputError(f"no part {pid!r} in the layout under review", field="id")
        return part

    def _new_id(self) -> str:
        used = set(self.layout().ids) | {e.get("id") for e in self.edits}
        k = 1
        while f"h{k}" in used:
            k += 1
        return f"h{k}"

    def _edits_for(self, op: dict[str, Any]) -> list[Edit]:
        kind = op.get("op")
        if kind == "move":
            part = self._part(op)
            position = _vec3(op.get("position"), "position")
            if not op.get("free"):
                position = snap(position, part.size, self.cell)
            return [{"op": "move", "id": part.id, "position": position}]
        if kind == "rotate":
            part = self._part(op)
            by = op.get("by_deg", 90)
            if by not in (90, -90, 180):
                raise InputError("turns in 90° steps: by_deg is 90, -90 or 180", field="by_deg")
            yaw = (yaw_deg(part.orientation) + by + 180.0) % 360.0 - 180.0
            return [{"op": "rotate", "id": part.id, "yaw_deg": round(yaw, 6)}]
        if kind == "insert":
            name = op.get("part", "cube")
            if name not in self.cell.part_types:
                raise InputError(
                    f"unknown part type {name!r}; the cell has {sorted(self.cell.part_types)}",
                    field="part",
                )
            size = tuple(self.cell.part_types[name])
            position = _vec3(op.get("position"), "position")
            position = snap(position, (size[0], size[1], size[2]), self.cell)
            pid = self._new_id()
            out: list[Edit] = [
                {"op": "insert", "id": pid, "position": position, "size": list(size)}
            ]
            yaw = op.get("yaw_deg", 0)
            if yaw not in (0, 90, -90, 180):
                raise InputError(
                    "turns in 90° steps: yaw_deg is 0, 90, -90 or 180", field="yaw_deg"
                )
            if yaw:
                out.append({"op": "rotate", "id": pid, "yaw_deg": float(yaw)})
            return out
        if kind == "remove":
            return [{"op": "remove", "id": self._part(op).id}]
        if kind == "reorder":
            part = self._part(op)
            order = self.report().sequence or tuple(self.layout().ids)
            rest = [i for i in order if i != part.id]
            before = op.get("before")
            if before is None:
                rest.append(part.id)
            elif before in rest:
                rest.insert(rest.index(before), part.id)
            else:
                raise InputError(f"no part {before!r} to put {part.id} before", field="before")
            return [{"op": "sequence", "order": rest}]
        if kind == "hint":
            k = op.get("index")
            violations = self.report().violations
            if not isinstance(k, int) or not 0 <= k < len(violations):
                raise InputError(f"no violation {k!r} in the list", field="index")
            suggestion = violations[k].suggestion or {}
            add = suggestion.get("add_part_at")
            if isinstance(add, list | tuple) and len(add) == 3:  # the missing support
                at = [float(v) for v in add]
                return [{"op": "insert", "id": self._new_id(), "position": at,
                         "size": list(self.cell.cube)}]  # fmt: skip
            target: Any = suggestion.get("id")
            to: Any = suggestion.get("position")
            if target not in self.layout().index or not isinstance(to, list | tuple):
                raise InputError("this violation has no suggestion to apply", field="index")
            return [{"op": "move", "id": target, "position": [float(v) for v in to]}]
        raise InputError(
            f"unknown operation {kind!r}; use move, rotate, insert, remove, reorder or hint",
            field="op",
        )

    # -- the page's view --------------------------------------------------------------------------
    def to_json_dict(self) -> dict[str, Any]:
        layout, report = self.layout(), self.report()
        violating = {i for v in report.violations for i in v.objects}
        return {
            "version": self.version,
            "base_hash": self.base_hash,
            "layout_hash": layout_hash(layout),
            "parts": [
                {
                    "id": p.id,
                    "position": list(p.position),
                    "size": list(p.size),
                    "yaw_deg": round(yaw_deg(p.orientation), 3),
                    "state": "violating"
                    if p.id in violating
                    else ("verified" if report.passed else "proposed"),
                }
                for p in layout.objects
            ],
            "sequence": list(report.sequence) if report.sequence else None,
            "violations": [v.to_json_dict() for v in report.violations],
            "passed": report.passed,
            "edits": self.edits,
            "can_undo": bool(self.steps),
            "can_redo": bool(self.undone),
        }
