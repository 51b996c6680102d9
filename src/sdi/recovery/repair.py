"""The minimal repair of an operator's edit that breaks a constraint: keep every part the
operator touched where they put it if possible, otherwise as close as possible.

It follows the Inspector's violations one at a time, each with the fix it suggests, smallest
first: a part outside the workspace goes back inside (to the nearest point the violation names)
and down onto what is under it; of two colliding parts the one the operator placed is lifted
onto the other (the operator's x and y kept); a floating or unbalanced part the operator did not
touch settles onto what is under it, else a support is re-added under it (a new part); an
order the Inspector refuses becomes the nearest valid order — the operator's order with only
the parts moved that must come later (`nearest_order`). Every step is verified again; a repair
that cannot converge (a fix that undoes another, or no fix suggested) is None, and the operator
keeps the other choices (undo the edit, replan).
"""

from __future__ import annotations

import heapq
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from sdi.inspector.analysis import Analysis
from sdi.inspector.verifier import verify
from sdi.inspector.violation import Constraint, Violation
from sdi.model.cell import CellConfig
from sdi.model.diff import PartChange, describe_diff, layout_diff
from sdi.model.layout import Layout
from sdi.model.part import Part

GEOMETRY_FIRST = (
    Constraint.WORKSPACE, Constraint.COLLISION, Constraint.CONTACT, Constraint.SUPPORT,
    Constraint.STABILITY, Constraint.GRAVITY, Constraint.SEQUENCE, Constraint.GRIPPING,
)  # fmt: skip
"""The order violations are repaired in: where parts are before when they are placed."""


@dataclass(frozen=True)
class Repair:
    """A verified repair: its layout and order, and the diff from the operator's layout."""

    layout: Layout
    sequence: tuple[str, ...]
    changes: tuple[PartChange, ...]
    order_changed: bool
    kept: tuple[str, ...]  # touched parts left exactly where the operator put them

    def describe(self) -> str:
        text = describe_diff(list(self.changes))
        if self.order_changed:
            text = ("the nearest valid order" if text == "unchanged"
                    else f"{text}; the nearest valid order")  # fmt: skip
        return text


def nearest_order(layout: Layout, cell: CellConfig, wanted: Sequence[str]) -> list[str] | None:
    """The valid order closest to `wanted`: the operator's order with each part placed as soon
    as its supports allow (Kahn's algorithm over the support graph, ties broken by the
    operator's rank); if the gripper cannot place that one, the same level by level (lower
    levels first, the operator's order within a level); else the Inspector's own order; None if
    the layout has none. Each is verified."""
    a = Analysis(layout, cell)
    ids = layout.ids
    rank = {pid: k for k, pid in enumerate(wanted)}
    level = {pid: round(layout.part(pid).bottom / cell.cube[2]) for pid in ids}
    for key in (
        lambda i: (rank.get(ids[i], len(ids) + i),),
        lambda i: (level[ids[i]], rank.get(ids[i], len(ids) + i)),
    ):
        order = _kahn(a, key)
        if order is not None and verify(layout, cell, sequence=order).passed:
            return order
    report = verify(layout, cell)
    return list(report.sequence) if report.passed and report.sequence else None


def _kahn(a: Analysis, key: Callable[[int], tuple[int, ...]]) -> list[str] | None:
    """A topological order of the support graph (supports first), smallest `key` first."""
    ids = a.layout.ids
    n = len(ids)
    below: list[set[int]] = [set() for _ in range(n)]
    for lo, up in a.graph.support_edges.tolist():
        below[up].add(lo)
    above: list[list[int]] = [[] for _ in range(n)]
    for up in range(n):
        for lo in below[up]:
            above[lo].append(up)
    waiting = [len(below[i]) for i in range(n)]
    ready = [(key(i), i) for i in range(n) if waiting[i] == 0]
    heapq.heapify(ready)
    order: list[str] = []
    while ready:
        _, i = heapq.heappop(ready)
        order.append(ids[i])
        for up in above[i]:
            waiting[up] -= 1
            if waiting[up] == 0:
                heapq.heappush(ready, (key(up), up))
    return order if len(order) == n else None


def _free_bottom(layout: Layout, i: int, x: float, y: float) -> float:
    """The lowest z (m) where part i, moved to (x, y), fits without overlapping anything:
    the table, or the top of the highest part in the first gap tall enough for it."""
    c, h = layout.centres, layout.half_extents
    hx, hy, hz = h[i]
    others = [
        j for j in range(len(layout))
        if j != i and abs(c[j, 0] - x) < h[j, 0] + hx - 1e-6
        and abs(c[j, 1] - y) < h[j, 1] + hy - 1e-6
    ]  # fmt: skip
    bottom = 0.0
    for j in sorted(others, key=lambda j: c[j, 2] - h[j, 2]):
        lo, hi = c[j, 2] - h[j, 2], c[j, 2] + h[j, 2]
        if lo < bottom + 2 * hz - 1e-6 and hi > bottom + 1e-6:
            bottom = hi
    return float(bottom)


def _placed(layout: Layout, i: int, x: float, y: float) -> Layout:
    """Part i moved to (x, y) and set down at the lowest free height there."""
    p = layout.objects[i]
    z = _free_bottom(layout, i, x, y) + float(layout.half_extents[i, 2])
    moved = Part(id=p.id, position=(round(x, 6), round(y, 6), round(z, 6)),
                 orientation=p.orientation, size=p.size)  # fmt: skip
    return layout.replaced(moved if k == i else q for k, q in enumerate(layout.objects))


def _added(layout: Layout, cell: CellConfig, at: Sequence[float]) -> Layout:
    taken = set(layout.ids)
    k = 1
    while f"s{k}" in taken:
        k += 1
    part = Part(id=f"s{k}", position=(float(at[0]), float(at[1]), float(at[2])), size=cell.cube)
    return layout.replaced((*layout.objects, part))


def _support_column(layout: Layout, i: int, cell: CellConfig) -> Layout | None:
    """Re-add a missing support: a column of cubes from the table up under the end of part i
    that rests on nothing (the cube-sized cell of its footprint farthest from what holds it),
    or None if its bottom is not a whole number of cubes up or that column is not free."""
    s, h = cell.cube[0], cell.cube[2]
    c, half = layout.centres, layout.half_extents
    bottom = float(c[i, 2] - half[i, 2])
    levels = round(bottom / h)
    if levels < 1 or abs(levels * h - bottom) > cell.tolerances.contact:
        return None
    nx = max(1, round(2 * half[i, 0] / s))
    ny = max(1, round(2 * half[i, 1] / s))
    cells = [
        (float(c[i, 0] - half[i, 0] + s * (kx + 0.5)), float(c[i, 1] - half[i, 1] + s * (ky + 0.5)))
        for kx in range(nx) for ky in range(ny)
    ]  # fmt: skip

    def held(x: float, y: float) -> bool:
        return any(
            abs(c[j, 2] + half[j, 2] - bottom) < cell.tolerances.contact
            and abs(c[j, 0] - x) < half[j, 0] + s / 2 - 1e-6
            and abs(c[j, 1] - y) < half[j, 1] + s / 2 - 1e-6
            for j in range(len(layout)) if j != i
        )  # fmt: skip

    holders = [(x, y) for x, y in cells if held(x, y)]
    free = [(x, y) for x, y in cells if not held(x, y)]
    if not free:
        return None
    if holders:
        hx = sum(x for x, _ in holders) / len(holders)
        hy = sum(y for _, y in holders) / len(holders)
        free.sort(key=lambda p: -((p[0] - hx) ** 2 + (p[1] - hy) ** 2))
    x, y = free[0]
    out = layout
    for k in range(levels):
        out = _added(out, cell, (x, y, k * h + h / 2))
    graph = Analysis(out, cell).graph
    clashes = graph.pairs[graph.colliding]
    if any(max(a, b) >= len(layout) for a, b in clashes.tolist()):
        return None  # the column would run into another part
    return out


def _group_inside(layout: Layout, group: list[int], cell: CellConfig) -> Layout | None:
    """The parts of `group` moved rigidly by the least x/y that brings them all inside the
    workspace, then lowered together as far as nothing under any of them stops them."""
    ws = cell.workspace
    c, h = layout.centres, layout.half_extents
    lo = (c[group] - h[group]).min(axis=0)
    hi = (c[group] + h[group]).max(axis=0)
    delta = [0.0, 0.0]
    for d, (low, high) in enumerate(((ws.x_min, ws.x_max), (ws.y_min, ws.y_max))):
        if hi[d] - lo[d] > high - low:
            return None  # the group is wider than the workspace
        delta[d] = max(0.0, low - lo[d]) - max(0.0, hi[d] - high)
    inside = set(group)
    drop = float("inf")
    for i in group:
        x, y = c[i, 0] + delta[0], c[i, 1] + delta[1]
        bottom = float(c[i, 2] - h[i, 2])
        below = [
            float(c[j, 2] + h[j, 2]) for j in range(len(layout))
            if j not in inside and c[j, 2] + h[j, 2] <= bottom + 1e-6
            and abs(c[j, 0] - x) < h[j, 0] + h[i, 0] - 1e-6
            and abs(c[j, 1] - y) < h[j, 1] + h[i, 1] - 1e-6
        ]  # fmt: skip
        drop = min(drop, bottom - max(below, default=0.0))
    parts = list(layout.objects)
    for i in group:
        p = parts[i]
        x, y, z = p.position
        parts[i] = Part(id=p.id, position=(round(x + delta[0], 6), round(y + delta[1], 6),
                        round(z - drop, 6)), orientation=p.orientation, size=p.size)  # fmt: skip
    return layout.replaced(parts)


def _fix(layout: Layout, v: Violation, touched: set[str], cell: CellConfig) -> Layout | None:
    """One step towards a valid layout for violation `v`, or None if there is none to take."""
    ids = [i for i in v.objects if i in layout.index]
    if not ids:
        return None
    s = v.suggestion or {}
    if v.constraint == Constraint.WORKSPACE:
        if ids[0] in touched:  # what the operator moved together moves back together
            return _group_inside(layout, [layout.index[pid] for pid in sorted(touched)], cell)
        i = layout.index[ids[0]]
        pos = s.get("position")
        if not isinstance(pos, list):
            return None
        return _placed(layout, i, float(pos[0]), float(pos[1]))
    if v.constraint == Constraint.COLLISION:
        mine = [pid for pid in ids if pid in touched] or ids[-1:]
        i = layout.index[mine[0]]
        x, y = layout.centres[i, :2]
        return _placed(layout, i, float(x), float(y))
    if v.constraint in (Constraint.CONTACT, Constraint.SUPPORT, Constraint.STABILITY):
        i = layout.index[ids[0]]
        x, y = layout.centres[i, :2]
        settled = _placed(layout, i, float(x), float(y))
        if settled.centres[i, 2] < layout.centres[i, 2] - 1e-6:
            return settled
        if isinstance(s.get("add_part_at"), list):
            return _added(layout, cell, s["add_part_at"])  # type: ignore[arg-type]
        column = _support_column(layout, i, cell)
        if column is not None:
            return column
        pos = s.get("position")
        if isinstance(pos, list) and s.get("id") in layout.index:
            j = layout.index[str(s["id"])]
            moved = layout.objects[j]
            part = Part(id=moved.id, position=(float(pos[0]), float(pos[1]), float(pos[2])),
                        orientation=moved.orientation, size=moved.size)  # fmt: skip
            return layout.replaced(part if k == j else q for k, q in enumerate(layout.objects))
        return None
    return None


BACK_STEPS = 20
"""How finely `_back_towards` walks the touched parts back towards where they were."""


def _back_towards(
    edited: Layout,
    original: Layout,
    touched: Sequence[str],
    cell: CellConfig,
    sequence: Sequence[str] | None,
) -> Layout | None:
    """The touched parts moved together, in `BACK_STEPS` steps, from where the operator put
    them back towards where they were; the first layout that verifies (nearest the operator's)."""
    moving = [pid for pid in touched if pid in edited.index and pid in original.index]
    if not moving:
        return None
    for k in range(1, BACK_STEPS + 1):
        t = k / BACK_STEPS
        parts = []
        for p in edited.objects:
            if p.id in moving:
                q = original.part(p.id)
                x, y, z = (
                    round(a + t * (b - a), 6) for a, b in zip(p.position, q.position, strict=True)
                )
                p = Part(id=p.id, position=(x, y, z), orientation=p.orientation, size=p.size)
            parts.append(p)
        candidate = edited.replaced(parts)
        if verify(candidate, cell, sequence=sequence).passed:
            return candidate
    return None


def repair_edit(
    edited: Layout,
    cell: CellConfig | None = None,
    *,
    touched: Sequence[str] = (),
    sequence: Sequence[str] | None = None,
    original: Layout | None = None,
    max_steps: int | None = None,
) -> Repair | None:
    """The smallest verified repair of `edited` (the operator's layout, with their order
    `sequence` if they gave one), or None when it cannot be found. When following the
    violations' fixes does not converge and `original` (the layout before the edit) is given,
    the touched parts go back towards where they were, only as far as they must."""
    cell = cell or CellConfig()
    found = _follow(edited, cell, touched, sequence, max_steps)
    if found is None and original is not None:
        back = _back_towards(edited, original, touched, cell, sequence)
        if back is not None:
            found = _follow(back, cell, touched, sequence, 0, start=edited)
    return found


def _follow(
    edited: Layout,
    cell: CellConfig,
    touched: Sequence[str],
    sequence: Sequence[str] | None,
    max_steps: int | None,
    *,
    start: Layout | None = None,
) -> Repair | None:
    """Follow the violations' fixes from `edited`; the diff is taken from `start` (default:
    `edited`)."""
    start = start or edited
    mine = set(touched)
    layout, order = edited, list(sequence) if sequence is not None else None
    seen = {layout.model_dump_json()}
    limit = max_steps if max_steps is not None else 3 * len(edited) + 10
    for _ in range(limit + 1):
        if order is not None and sorted(order) != sorted(layout.ids):
            order = [pid for pid in order if pid in layout.index] + [
                pid for pid in layout.ids if pid not in order
            ]
        report = verify(layout, cell, sequence=order)
        if report.passed:
            final = tuple(report.sequence or ())
            changes = tuple(layout_diff(start, layout))
            moved = {c.id for c in changes}
            return Repair(
                layout, final, changes,
                order_changed=sequence is not None and tuple(sequence) != final,
                kept=tuple(pid for pid in touched if pid in layout.index and pid not in moved),
            )  # fmt: skip
        violations = sorted(report.violations, key=lambda v: GEOMETRY_FIRST.index(v.constraint))
        geometric = [v for v in violations if v.constraint in GEOMETRY_FIRST[:5]]
        if not geometric:
            if order is None:
                return None
            better = nearest_order(layout, cell, order)
            if better is None or better == order:
                return None
            order = better
            continue
        step = None
        for v in geometric:
            step = _fix(layout, v, mine, cell)
            if step is not None and step.model_dump_json() not in seen:
                break
            step = None
        if step is None:
            return None
        seen.add(step.model_dump_json())
        layout = step
    return None


def diff_summary(before: Layout, after: Layout) -> str:
    """The change from the operator's layout in one line (for notes)."""
    return describe_diff(layout_diff(before, after))
