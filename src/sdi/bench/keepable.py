"""Can the commanded shape be kept at all under a failure scenario? Computed, not declared.

Table V scores *shape kept*: the layout built after recovery still has the command's structure
signature. That is only a fair demand where some placement of the commanded structure avoids the
scenario's blocked regions. `keepable` searches for one: the layout the command plans — packed as
planned, or with gaps opened between its parts as the recovery's `spread` makes them — turned by
every quarter turn the cell allows (about its footprint centre) and moved on a `STEP` grid over
the whole workspace, is a candidate if it

1. still satisfies the case's signature (`sdi.bench.shape_checks`; a turn can break an axis),
2. lies inside the workspace, and
3. keeps the recovery's clearance margin (`sdi.recovery.shift.default_margin`) from every
   blocked region — a height limit included: a 4-cube tower reaches 0.20 m wherever it stands.

Geometry is not the whole answer: the arms must also reach. The geometric candidates are tried
packed first, then by gap, each nearest first, with the real commissioning
(`sdi.commission.commission`: task generation and motion planning) until one plans, at most
`MAX_COMMISSIONED` per gap. The answer says which test decided it, in words for the table's
footnotes.
"""

from __future__ import annotations

import json
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from sdi.bench import shape_checks
from sdi.errors import SDIError
from sdi.execute.faults import SCENARIOS
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.region import Region
from sdi.recovery.shift import default_margin, translated, turned
from sdi.recovery.spread import GAPS, spread_apart

STEP = 0.005
"""The placement grid, m: half the shift search's step, so the answer is at least as fine."""

YAWS: tuple[float, ...] = (0.0, 90.0, 180.0, 270.0)
"""The turns of the whole structure the cell allows (quarter turns about z), degrees."""

MAX_COMMISSIONED = 2000
"""How many geometrically clear placements of the packed structure (nearest first) are
commissioned before giving up: one that cannot be gripped fails in task generation, in about
10 ms, so for the suite's cases this is every one of them."""

MAX_COMMISSIONED_SPREAD = 20
"""The same per gap of a spread structure: these reach motion planning (about 1 s each), so a
"no" after them is not exhaustive (the answer says how many were tried)."""


@dataclass(frozen=True)
class Keepable:
    """The answer. `possible`: a placement keeps the shape and plans; `geometric`: one at least
    clears the regions inside the workspace. Moves in metres, yaw in degrees."""

    possible: bool
    geometric: bool
    reason: str
    moved_by_m: tuple[float, float] | None = None
    yaw_deg: float | None = None
    gap_m: float | None = None  # the gap opened between neighbouring parts (0: packed)
    candidates: int = 0  # geometrically clear placements found
    commissioned: int = 0  # of those, how many were motion-planned

    def to_json_dict(self) -> dict[str, Any]:
        return {
            "possible": self.possible,
            "geometric": self.geometric,
            "reason": self.reason,
            "moved_by_m": self.moved_by_m,
            "yaw_deg": self.yaw_deg,
            "gap_m": self.gap_m,
            "candidates": self.candidates,
            "commissioned": self.commissioned,
        }


def _clear_moves(
    layout: Layout, cell: CellConfig, blocked: Sequence[Region], margin: float, step: float
) -> np.ndarray:
    """Every (dx, dy) on the `step` grid that keeps `layout` inside the workspace and `margin`
    clear of `blocked`, as an (n, 2) array, nearest the original position first."""
    ws = cell.workspace
    lo = layout.centres - layout.half_extents
    hi = layout.centres + layout.half_extents
    if lo[:, 2].min() < ws.z_min - 1e-9 or hi[:, 2].max() > ws.z_max + 1e-9:
        return np.zeros((0, 2))
    xs = np.arange(np.ceil((ws.x_min - lo[:, 0].min()) / step - 1e-9),
                   np.floor((ws.x_max - hi[:, 0].max()) / step + 1e-9) + 1) * step  # fmt: skip
    ys = np.arange(np.ceil((ws.y_min - lo[:, 1].min()) / step - 1e-9),
                   np.floor((ws.y_max - hi[:, 1].max()) / step + 1e-9) + 1) * step  # fmt: skip
    if xs.size == 0 or ys.size == 0:
        return np.zeros((0, 2))
    gx, gy = np.meshgrid(xs, ys, indexing="ij")
    moves = np.stack([gx.ravel(), gy.ravel()], axis=1)
    pad = np.array([margin, margin, 0.0])  # a placement gap is sideways, never upwards
    ok = np.ones(len(moves), dtype=bool)
    for k in range(len(layout)):  # part by part, every move at once
        offset = np.column_stack([moves, np.zeros(len(moves))])
        plo, phi = lo[k] + offset - pad, hi[k] + offset + pad
        for region in blocked:
            ok &= ~region.blocks(plo, phi)
    moves = moves[ok]
    order = np.lexsort((moves[:, 1], moves[:, 0], np.hypot(moves[:, 0], moves[:, 1])))
    return moves[order]


def keepable(
    layout: Layout,
    shape: Sequence[Sequence[Any]],
    blocked: Sequence[Region],
    cell: CellConfig | None = None,
    *,
    step: float = STEP,
    reach: bool = True,
    gaps: Sequence[float] = GAPS,
) -> Keepable:
    """Can `layout`'s structure, keeping signature `shape`, stand clear of `blocked`?

    Candidates are `layout` packed and spread by each of `gaps` (m). With `reach`, the clear
    placements are also commissioned — packed first (at most `MAX_COMMISSIONED`), then the
    spread ones, widest gap first (at most `MAX_COMMISSIONED_SPREAD` per gap), each nearest
    first: the answer is possible only if one plans."""
    from sdi.commission import commission

    cell = cell or CellConfig()
    signature = shape_checks.signature(shape)
    margin = default_margin(cell)
    found: list[tuple[float, float, float, float, float, Layout]] = []  # gap, distance, yaw, …
    broke: list[str] = []
    for gap in (0.0, *gaps):
        variant = spread_apart(layout, gap, cell) if gap else layout
        for yaw in YAWS:
            candidate = turned(variant, yaw)
            why = signature(candidate)
            if why is not None:
                if not gap:
                    broke.append(f"{yaw:g}°: {why}")
                continue
            for dx, dy in _clear_moves(candidate, cell, blocked, margin, step).tolist():
                found.append((gap, round(float(np.hypot(dx, dy)), 9), yaw, dx, dy, candidate))
    found.sort(key=lambda c: (c[0] > 0, -c[0], *c[1:5]))  # packed, then the widest gap
    names = ", ".join(r.describe() for r in blocked)
    if not found:
        turns = f" (turning breaks it: {'; '.join(broke)})" if broke else ""
        return Keepable(
            False, False,
            f"no placement or quarter turn of the commanded structure, packed or with gaps, lies "
            f"inside the workspace {margin * 1000:.1f} mm clear of {names}{turns}",
        )  # fmt: skip
    if not reach:
        gap, _, yaw, dx, dy, _ = found[0]
        return Keepable(True, True, "a clear placement exists (reach not checked)",
                        (round(dx, 6), round(dy, 6)), yaw, gap, len(found))  # fmt: skip
    tried: dict[float, int] = {}
    last: dict[float, str] = {}
    for gap, _, yaw, dx, dy, candidate in found:
        if tried.get(gap, 0) >= (MAX_COMMISSIONED_SPREAD if gap else MAX_COMMISSIONED):
            continue
        tried[gap] = tried.get(gap, 0) + 1
        placed = translated(candidate, dx, dy)
        if signature(placed) is not None:  # the signature's lattice may depend on the place
            continue
        try:
            commission(placed, cell)
        except SDIError as exc:
            last[gap] = str(exc)
            continue
        spread = f"with gaps of {gap * 1000:.0f} mm, " if gap else ""
        return Keepable(True, True, f"{spread}moved by ({dx:.3f}, {dy:.3f}) m, turned by "
                        f"{yaw:g}°, it clears every region and plans", (round(dx, 6),
                        round(dy, 6)), yaw, gap, len(found), sum(tried.values()))  # fmt: skip
    n = sum(tried.values())
    packed = f" (packed: {last[0.0]})" if 0.0 in last else ""
    return Keepable(
        False, True,
        f"{len(found)} placement(s), packed or with gaps, clear {names} geometrically, but none "
        f"of the {n} tried nearest first can be built by the arms{packed}",
        candidates=len(found), commissioned=n,
    )  # fmt: skip


_ANSWERS: dict[str, Keepable] = {}
"""`case_keepable`'s answers in this process (the same case is asked once per method)."""


def case_keepable(command: str, shape: Sequence[Sequence[Any]], scenario: str,
                  cell: CellConfig | None = None) -> Keepable:  # fmt: skip
    """`keepable` for a Table V case: the layout the command plans, the scenario's regions."""
    from sdi.pipeline import plan

    cell = cell or CellConfig()
    key = json.dumps([command, shape, scenario, cell.model_dump(mode="json")], sort_keys=True)
    if key not in _ANSWERS:
        result = plan(command, cell)
        _ANSWERS[key] = (
            Keepable(False, False, f"the command does not plan: {result.error}")
            if result.layout is None
            else keepable(result.layout, shape, SCENARIOS[scenario].regions, cell)
        )
    return _ANSWERS[key]
