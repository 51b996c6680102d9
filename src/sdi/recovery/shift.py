"""ξ_shift: translate a whole structure, by a given amount or out of blocked regions.

Without an explicit (dx, dy) it searches translations on a `step` grid, smallest first, for one
that keeps every part inside the workspace and out of every blocked region.
"""

from __future__ import annotations

import numpy as np

from sdi.errors import InfeasibleError
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part
from sdi.model.region import Region


def translated(layout: Layout, dx: float, dy: float) -> Layout:
    return Layout(
        objects=tuple(
            Part(
                id=p.id,
                position=(
                    round(p.position[0] + dx, 6),
                    round(p.position[1] + dy, 6),
                    p.position[2],
                ),
                orientation=p.orientation,
                size=p.size,
            )
            for p in layout.objects
        )
    )


def shift(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    blocked: tuple[Region, ...] = (),
    dx: float | None = None,
    dy: float | None = None,
    step: float = 0.01,
) -> Layout:
    """The layout moved by (dx, dy) m, or by the smallest move that clears `blocked`."""
    cell = cell or CellConfig()
    if dx is not None or dy is not None:
        return translated(layout, dx or 0.0, dy or 0.0)
    if len(layout) == 0:
        return layout
    ws = cell.workspace
    lo = layout.centres - layout.half_extents
    hi = layout.centres + layout.half_extents
    if lo[:, 2].min() < ws.z_min - 1e-9 or hi[:, 2].max() > ws.z_max + 1e-9:
        raise InfeasibleError(
            "layout: the structure is outside the workspace in z; shifting in x and y cannot "
            "fix that; use flatten",
            parameter="layout",
        )
    # All translations that keep the structure's box inside the workspace, nearest first.
    xs = (
        np.arange(
            np.ceil((ws.x_min - lo[:, 0].min()) / step),
            np.floor((ws.x_max - hi[:, 0].max()) / step) + 1,
        )
        * step
    )
    ys = (
        np.arange(
            np.ceil((ws.y_min - lo[:, 1].min()) / step),
            np.floor((ws.y_max - hi[:, 1].max()) / step) + 1,
        )
        * step
    )
    if xs.size == 0 or ys.size == 0:
        raise InfeasibleError(
            "layout: the structure is larger than the workspace", parameter="layout"
        )
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    moves = np.stack([gx.ravel(), gy.ravel()], axis=1)
    moves = moves[np.lexsort((moves[:, 1], moves[:, 0], np.hypot(moves[:, 0], moves[:, 1])))]
    for mx, my in moves:
        offset = np.array([mx, my, 0.0])
        if not any(r.blocks(lo + offset, hi + offset).any() for r in blocked):
            return translated(layout, float(mx), float(my))
    names = ", ".join(r.describe() for r in blocked)
    raise InfeasibleError(
        f"blocked: no translation keeps the structure inside the workspace and out of {names}; "
        "try flatten or a smaller structure",
        parameter="blocked",
    )
