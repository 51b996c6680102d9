"""ξ_flatten: lower a structure below a height limit by moving its top parts beside it.

Parts whose top is above `z_max` are taken off, lowest first, and re-stacked on the cube
lattice of the structure: each goes to the free cell that keeps it closest to the structure's
footprint centre while staying low (score = distance in parts + half its level), inside the
workspace, under the limit and out of any blocked region. Cells count as stackable only where a
kept part covers the whole cell, so nothing is placed on an edge or a gap.
"""

from __future__ import annotations

import math

import numpy as np

from sdi.errors import InfeasibleError
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part
from sdi.model.region import Region

Cell = tuple[int, int]


def flatten(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    z_max: float | None = None,
    blocked: tuple[Region, ...] = (),
) -> Layout:
    """A layout with every part's top at or below `z_max` metres (default: half the height)."""
    cell = cell or CellConfig()
    if len(layout) == 0:
        return layout
    s, h = cell.cube[0], cell.cube[2]
    eps = cell.tolerances.contact
    tops = layout.centres[:, 2] + layout.half_extents[:, 2]
    if z_max is None:
        levels = max(1, math.ceil(round(float(tops.max()) / h) / 2))
        z_max = levels * h
    if z_max < h - eps:
        raise InfeasibleError(
            f"z_max: {z_max:g} m is lower than one part ({h:g} m)", parameter="z_max"
        )
    z_max = min(z_max, cell.workspace.z_max)
    move = [
        i for i in np.argsort(layout.centres[:, 2], kind="stable").tolist() if tops[i] > z_max + eps
    ]
    if not move:
        return layout
    keep = [i for i in range(len(layout)) if tops[i] <= z_max + eps]
    origin = layout.centres[0, :2] - s * np.round(layout.centres[0, :2] / s)

    def cell_of(x: float, y: float) -> Cell:
        return (round((x - origin[0]) / s), round((y - origin[1]) / s))

    def centre_of(c: Cell) -> tuple[float, float]:
        return (origin[0] + c[0] * s, origin[1] + c[1] * s)

    height: dict[Cell, float] = {}
    for i in keep:
        lo = layout.centres[i] - layout.half_extents[i]
        hi = layout.centres[i] + layout.half_extents[i]
        for cx in range(cell_of(lo[0], 0)[0] - 1, cell_of(hi[0], 0)[0] + 2):
            for cy in range(cell_of(0, lo[1])[1] - 1, cell_of(0, hi[1])[1] + 2):
                x, y = centre_of((cx, cy))
                overlap_x = min(hi[0], x + s / 2) - max(lo[0], x - s / 2)
                overlap_y = min(hi[1], y + s / 2) - max(lo[1], y - s / 2)
                if overlap_x <= eps or overlap_y <= eps:
                    continue
                full = overlap_x >= s - eps and overlap_y >= s - eps
                prev = height.get((cx, cy), 0.0)
                height[(cx, cy)] = (
                    max(prev, float(hi[2])) if full and prev != math.inf else math.inf
                )

    ws = cell.workspace
    centre = layout.centres[:, :2].mean(axis=0)
    home = cell_of(float(centre[0]), float(centre[1]))
    radius = int(max(ws.x_max - ws.x_min, ws.y_max - ws.y_min) / s) + 2
    candidates = sorted(
        ((cx, cy) for cx in range(home[0] - radius, home[0] + radius + 1)
         for cy in range(home[1] - radius, home[1] + radius + 1)),
        key=lambda c: (math.hypot(c[0] - home[0], c[1] - home[1]), c),
    )  # fmt: skip
    moved: dict[int, tuple[float, float, float]] = {}
    for i in move:
        part = layout.objects[i]
        if not np.allclose(layout.half_extents[i], [s / 2, s / 2, h / 2], atol=eps):
            raise InfeasibleError(
                f"flatten moves only cube parts; {part.id} is {list(part.size)} m. "
                "Lower the structure with 'shift' or redesign it",
                parameter="layout",
            )
        best: tuple[float, Cell, float] | None = None
        for c in candidates:
            base = height.get(c, 0.0)
            if base == math.inf or base + h > z_max + eps:
                continue
            x, y = centre_of(c)
            lo = np.array([x - s / 2, y - s / 2, base])
            hi = np.array([x + s / 2, y + s / 2, base + h])
            if np.any(lo < np.array(ws.lower) - eps) or np.any(hi > np.array(ws.upper) + eps):
                continue
            if any(r.blocks(lo, hi)[0] for r in blocked):
                continue
            score = math.hypot(c[0] - home[0], c[1] - home[1]) + 0.5 * round(base / h)
            if best is None or score < best[0] - 1e-9:
                best = (score, c, base)
        if best is None:
            raise InfeasibleError(
                f"z_max: no free place under {z_max:g} m for {part.id}; allow a higher limit",
                parameter="z_max",
            )
        _, c, base = best
        x, y = centre_of(c)
        moved[i] = (round(x, 6), round(y, 6), round(base + h / 2, 6))
        height[c] = base + h
    parts = [
        Part(id=p.id, position=moved[i], orientation=p.orientation, size=p.size)
        if i in moved
        else p
        for i, p in enumerate(layout.objects)
    ]
    return Layout(objects=tuple(parts))
