"""ξ_spread: open gaps between the parts of a structure so that a parallel gripper reaches each
one, when no arm can take a part the way the packed structure leaves it.

A cube with neighbours already placed on two adjacent sides cannot be gripped from the side: only
the vacuum tool can take it, from the top. Where the arm that carries the vacuum tool does not
reach (Table V's corner pocket lies beyond the IRB120's reach), moving or turning the structure
does not help. Spreading does: every column of parts moves away from the structure's footprint
centre by `gap` per part it is away from it (the columns stay a lattice, the parts keep their
heights and turns), so the fingers fit between neighbours. The smallest gap that works wins:
each candidate is moved clear of the blocked regions with the recovery's margin
(`shift_search`), verified by the Inspector, and commissioned (task generation and motion
planning, as PRE_EXECUTE will) for the cell's arms. Gaps change the shape — a spread grid is no
longer a filled one — so the orchestrator shows the result to the operator for approval.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from sdi.errors import InfeasibleError, SDIError
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part
from sdi.model.region import Region
from sdi.recovery.shift import Shifted, default_margin, shift_search

GAPS: tuple[float, ...] = (0.01, 0.015, 0.02, 0.025, 0.03, 0.035, 0.04, 0.045, 0.05)
"""The gaps tried between neighbouring parts, m, smallest first."""


@dataclass(frozen=True)
class Spread:
    """A spread's outcome: the layout, the gap opened (m) and how it was then moved, if it was."""

    layout: Layout
    gap: float
    shifted: Shifted | None = None

    def describe(self) -> str:
        text = (
            f"opened gaps of {self.gap * 1000:.0f} mm between neighbouring parts so that the "
            "parallel gripper reaches each one"
        )
        return f"{text}, then {self.shifted.describe()}" if self.shifted else text


def spread_apart(layout: Layout, gap: float, cell: CellConfig | None = None) -> Layout:
    """`layout` with every part's x and y moved away from the footprint centre by `gap` m per
    part width it is away from it (a part's column moves with it; heights and turns kept)."""
    cell = cell or CellConfig()
    if len(layout) == 0 or gap <= 0:
        return layout
    lo = (layout.centres - layout.half_extents).min(axis=0)
    hi = (layout.centres + layout.half_extents).max(axis=0)
    centre = (lo[:2] + hi[:2]) / 2
    scale = (cell.cube[0] + gap) / cell.cube[0]
    parts = []
    for p in layout.objects:
        xy = centre + (np.array(p.position[:2]) - centre) * scale
        position = (round(float(xy[0]), 6), round(float(xy[1]), 6), p.position[2])
        parts.append(Part(id=p.id, position=position, orientation=p.orientation, size=p.size))
    return layout.replaced(parts)


def spread(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    blocked: tuple[Region, ...] = (),
    gaps: Sequence[float] = GAPS,
    arms: Sequence[str] | None = None,
) -> Spread:
    """The smallest gap of `gaps` with which the spread layout clears `blocked` (by the margin),
    verifies and can be commissioned by `arms` (default: every arm of the cell).

    Raises `InfeasibleError` naming `layout` if no gap works."""
    from sdi.commission import commission

    cell = cell or CellConfig()
    margin = default_margin(cell)
    last = "no gap was tried"
    for gap in gaps:
        candidate = spread_apart(layout, gap, cell)
        moved: Shifted | None = None
        try:
            moved = shift_search(candidate, cell, blocked=blocked, margin=margin)
            candidate = moved.layout
        except InfeasibleError as exc:
            if exc.parameter != "layout":  # "already clear" is fine; "cannot clear" is not
                last = f"{gap * 1000:.0f} mm: {exc}"
                continue
            if "outside the workspace" in str(exc):
                last = f"{gap * 1000:.0f} mm: {exc}"
                continue
        report = verify(candidate, cell)
        if not report.passed:
            last = f"{gap * 1000:.0f} mm: {report.violations[0].message}"
            continue
        try:
            commission(candidate, cell, arms=arms)
        except SDIError as exc:
            last = f"{gap * 1000:.0f} mm: {exc}"
            continue
        return Spread(candidate, gap, moved)
    raise InfeasibleError(
        f"layout: no gap up to {max(gaps) * 1000:.0f} mm lets the arms build the structure "
        f"clear of the blocked regions (last: {last}); redesign it or ask the operator",
        parameter="layout",
    )
