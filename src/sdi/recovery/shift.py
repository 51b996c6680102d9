"""ξ_shift: translate (and, if that is what it takes, turn) a whole structure out of blocked
regions, by the smallest change.

Without an explicit (dx, dy) it searches translations on a `step` grid, in every direction, for
every quarter-turn yaw of the structure about its footprint centre (0° first), and keeps the
cheapest one that keeps every part inside the workspace and at least `margin` away from every
blocked region. A turn is tried only when no plain move clears the regions: it changes how the
structure faces — for a row or wall the command named along an axis, the command itself — so any
move inside the workspace is the smaller change (`turn_cost`). The margin (default: the
placement clearance the robot leaves beside neighbours plus the contact tolerance) keeps a
structure set down with its small placement gap from re-entering the region it was moved out of.
A layout that already clears every region is not "shifted" by (0, 0): that would run the failed
layout again.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sdi.errors import InfeasibleError
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part, quat_from_yaw
from sdi.model.region import Region


def turn_cost(cell: CellConfig) -> float:
    """What a quarter turn of the whole structure costs in the search, as metres of translation:
    more than the workspace's diagonal, so every plain move is preferred to a turn."""
    ws = cell.workspace
    return math.hypot(ws.x_max - ws.x_min, ws.y_max - ws.y_min) + 0.01


@dataclass(frozen=True)
class Shifted:
    """A shift's outcome: the layout and the change, in metres and degrees about z."""

    layout: Layout
    dx: float
    dy: float
    yaw_deg: float = 0.0
    margin: float = 0.0

    def describe(self) -> str:
        words = []
        if self.dx or self.dy:
            words.append(f"moved by ({self.dx:.3f}, {self.dy:.3f}) m")
        if self.yaw_deg:
            words.append(f"turned by {self.yaw_deg:g}° about its centre")
        clear = f"{self.margin * 1000:.1f} mm clear of the blocked region"
        return f"{', '.join(words)}, {clear}"


def default_margin(cell: CellConfig) -> float:
    """The least clearance from a blocked region, m: placement gap + contact tolerance."""
    from sdi.tasks.generator import PLACEMENT_CLEARANCE

    return PLACEMENT_CLEARANCE + cell.tolerances.contact


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


def _quat_mul(a: tuple[float, ...], b: tuple[float, ...]) -> tuple[float, float, float, float]:
    w1, x1, y1, z1 = a
    w2, x2, y2, z2 = b
    q = (
        w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
        w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
        w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
        w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    )
    return tuple(0.0 if abs(v) < 1e-12 else round(v, 12) for v in q)  # type: ignore[return-value]


def turned(layout: Layout, yaw_deg: float) -> Layout:
    """The layout turned by `yaw_deg` about the vertical axis through its footprint centre."""
    if not yaw_deg % 360 or len(layout) == 0:
        return layout
    lo = (layout.centres - layout.half_extents).min(axis=0)
    hi = (layout.centres + layout.half_extents).max(axis=0)
    cx, cy = (lo[:2] + hi[:2]) / 2
    a = math.radians(yaw_deg)
    c, s = round(math.cos(a), 12), round(math.sin(a), 12)
    q = quat_from_yaw(a)
    parts = []
    for p in layout.objects:
        x, y = p.position[0] - cx, p.position[1] - cy
        parts.append(
            Part(
                id=p.id,
                position=(
                    round(cx + c * x - s * y, 6),
                    round(cy + s * x + c * y, 6),
                    p.position[2],
                ),
                orientation=_quat_mul(q, p.orientation),
                size=p.size,
            )
        )
    return Layout(objects=tuple(parts))


def _blocked(regions: tuple[Region, ...], lo: np.ndarray, hi: np.ndarray) -> bool:
    return any(bool(r.blocks(lo, hi).any()) for r in regions)


def shift_search(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    blocked: tuple[Region, ...] = (),
    step: float = 0.01,
    margin: float | None = None,
    yaws: tuple[float, ...] = (0.0, 90.0, 180.0, 270.0),
) -> Shifted:
    """The cheapest move (and quarter turn) that keeps `margin` m clear of `blocked`.

    Raises `InfeasibleError` naming `blocked` when none exists, and naming `layout` when the
    layout is clear already (a shift by (0, 0) would reproduce it).
    """
    cell = cell or CellConfig()
    margin = default_margin(cell) if margin is None else margin
    if len(layout) == 0:
        raise InfeasibleError("layout: nothing to shift", parameter="layout")
    ws = cell.workspace
    pad = np.array([margin, margin, 0.0])  # a placement gap is sideways, never upwards
    lo0 = layout.centres - layout.half_extents
    hi0 = layout.centres + layout.half_extents
    if lo0[:, 2].min() < ws.z_min - 1e-9 or hi0[:, 2].max() > ws.z_max + 1e-9:
        raise InfeasibleError(
            "layout: the structure is outside the workspace in z; shifting in x and y cannot "
            "fix that; use flatten",
            parameter="layout",
        )
    if not blocked or not _blocked(blocked, lo0 - pad, hi0 + pad):
        raise InfeasibleError(
            "layout: the structure is already clear of every blocked region; shifting it would "
            "run the same layout again",
            parameter="layout",
        )
    best: tuple[float, float, float, float, Layout] | None = None
    for yaw in yaws:
        candidate = turned(layout, yaw)
        quarters = round((yaw % 360) / 90 if yaw % 360 <= 180 else (360 - yaw % 360) / 90)
        cost0 = turn_cost(cell) * quarters
        if best is not None and cost0 >= best[0]:
            continue
        lo = candidate.centres - candidate.half_extents
        hi = candidate.centres + candidate.half_extents
        if yaw % 360 and not _blocked(blocked, lo - pad, hi + pad):
            best = (cost0, 0.0, 0.0, yaw, candidate)
            continue
        xs = (
            np.arange(
                np.ceil((ws.x_min - lo[:, 0].min()) / step - 1e-9),
                np.floor((ws.x_max - hi[:, 0].max()) / step + 1e-9) + 1,
            )
            * step
        )
        ys = (
            np.arange(
                np.ceil((ws.y_min - lo[:, 1].min()) / step - 1e-9),
                np.floor((ws.y_max - hi[:, 1].max()) / step + 1e-9) + 1,
            )
            * step
        )
        if xs.size == 0 or ys.size == 0:
            continue
        gx, gy = np.meshgrid(xs, ys, indexing="ij")
        moves = np.stack([gx.ravel(), gy.ravel()], axis=1)
        cost = np.hypot(moves[:, 0], moves[:, 1]) + cost0
        order = np.lexsort((moves[:, 1], moves[:, 0], cost))
        for k in order.tolist():
            if best is not None and cost[k] >= best[0] - 1e-12:
                break
            offset = np.array([moves[k, 0], moves[k, 1], 0.0])
            if not _blocked(blocked, lo + offset - pad, hi + offset + pad):
                best = (float(cost[k]), float(moves[k, 0]), float(moves[k, 1]), yaw, candidate)
                break
    if best is None:
        names = ", ".join(r.describe() for r in blocked)
        raise InfeasibleError(
            f"blocked: no move{' or quarter turn' if len(yaws) > 1 else ''} keeps the "
            "structure inside the workspace and "
            f"{margin * 1000:.1f} mm clear of {names}; try flatten or a smaller structure",
            parameter="blocked",
        )
    _, dx, dy, yaw, candidate = best
    return Shifted(translated(candidate, dx, dy), round(dx, 6), round(dy, 6), yaw % 360, margin)


def shift(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    blocked: tuple[Region, ...] = (),
    dx: float | None = None,
    dy: float | None = None,
    step: float = 0.01,
) -> Layout:
    """The layout moved by (dx, dy) m, or by the smallest change that clears `blocked`
    (`shift_search`)."""
    cell = cell or CellConfig()
    if dx is not None or dy is not None:
        return translated(layout, dx or 0.0, dy or 0.0)
    if len(layout) == 0:
        return layout
    return shift_search(layout, cell, blocked=blocked, step=step).layout
