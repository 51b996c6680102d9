"""What changed between two layouts, part by part: moved, turned, added, removed (metres,
degrees). Recovery outcomes and edit repairs report their result as this diff, so the operator
sees, in the notes, the JSON and the audit trail, how far the result is from what they had.
"""

from __future__ import annotations

import math
from typing import Literal

import numpy as np
from pydantic import BaseModel, ConfigDict

from sdi.model.layout import Layout
from sdi.model.part import Part, rotation_matrix

MOVE_TOLERANCE = 1e-6
"""Moves shorter than this (m) and turns smaller than this (rad) are no change."""


class PartChange(BaseModel):
    """One part's change: `by` is the translation (m), `turned_deg` the yaw difference."""

    model_config = ConfigDict(frozen=True)

    id: str
    kind: Literal["moved", "turned", "moved+turned", "added", "removed"]
    by: tuple[float, float, float] | None = None
    turned_deg: float | None = None
    position: tuple[float, float, float] | None = None  # where it is now (or was, if removed)

    def describe(self) -> str:
        if self.kind == "added":
            return f"{self.id} added at {_point(self.position)}"
        if self.kind == "removed":
            return f"{self.id} removed (was at {_point(self.position)})"
        words = []
        if self.by is not None:
            words.append(f"moved by {_point(self.by)} m to {_point(self.position)}")
        if self.turned_deg is not None:
            words.append(f"turned by {self.turned_deg:g}°")
        return f"{self.id} " + " and ".join(words)


def _point(v: tuple[float, ...] | None) -> str:
    if v is None:
        return "?"
    return "(" + ", ".join(_mm(x) for x in v) + ")"


def _mm(x: float) -> str:
    """Metres to millimetre precision, without trailing zeros or a negative zero."""
    text = f"{x:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _yaw(part: Part) -> float:
    R = rotation_matrix(part.orientation)
    return math.atan2(float(R[1, 0]), float(R[0, 0]))


def layout_diff(before: Layout, after: Layout) -> list[PartChange]:
    """Every part that differs between `before` and `after`, in `after`'s order then removals."""
    out: list[PartChange] = []
    old = {p.id: p for p in before}
    for p in after:
        q = old.get(p.id)
        if q is None:
            out.append(PartChange(id=p.id, kind="added", position=_r(p.position)))
            continue
        d = np.subtract(p.position, q.position)
        moved = float(np.linalg.norm(d)) > MOVE_TOLERANCE
        turn = math.degrees(_yaw(p) - _yaw(q))
        turn = (turn + 180.0) % 360.0 - 180.0
        turned = abs(math.radians(turn)) > MOVE_TOLERANCE
        if moved or turned:
            kind = "moved+turned" if moved and turned else ("moved" if moved else "turned")
            out.append(
                PartChange(
                    id=p.id,
                    kind=kind,
                    by=_r(tuple(float(v) for v in d)) if moved else None,
                    turned_deg=round(turn, 3) if turned else None,
                    position=_r(p.position),
                )
            )
    ids = {p.id for p in after}
    out += [
        PartChange(id=q.id, kind="removed", position=_r(q.position))
        for q in before
        if q.id not in ids
    ]
    return out


def _r(v: tuple[float, ...]) -> tuple[float, float, float]:
    return (round(float(v[0]), 6), round(float(v[1]), 6), round(float(v[2]), 6))


def describe_diff(changes: list[PartChange], limit: int = 8) -> str:
    """The changes in one line: 'unchanged', or each change, the rest counted."""
    if not changes:
        return "unchanged"
    text = "; ".join(c.describe() for c in changes[:limit])
    if len(changes) > limit:
        text += f"; and {len(changes) - limit} more change(s)"
    return text
