"""The minimal repair of an operator's edit that breaks a constraint: keep every part the
operator touched where they put it if possible, otherwise as close as possible.

It follows the Inspector's violations one at a time, each with the fix it suggests, smallest
first: a part outside the workspace goes back inside (to the nearest point the violation names)
and down onto what is under it; of two colliding parts, the untouched one makes room for the one
the operator placed (it moves aside by the overlap, or to a place the edit vacated, with what
rests on it), else the operator's part is lifted onto the other (their x and y kept); a floating
or unbalanced part the operator did not touch goes along with the operator's part it stood on,
else settles onto what is under it, else a support is re-added under it (a new part); an
order the Inspector refuses becomes the nearest valid order — the operator's order with only
the parts moved that must come later (`nearest_order`). Every step is verified again; a repair
that cannot converge (a fix that undoes another, or no fix suggested) is None, and the operator
keeps the other choices (undo the edit, replan).
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

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
    unkept: tuple[tuple[str, str], ...] = ()  # asked (earlier, later) pairs no valid order keeps

    def describe(self) -> str:
        text = describe_diff(list(self.changes))
        if self.order_changed:
            order = "the nearest valid order"
            if self.unkept:
                pairs = ", ".join(f"{a} before {b}" for a, b in self.unkept)
                order += f" (not kept: {pairs})"
            text = order if text == "unchanged" else f"{text}; {order}"
        return text


def nearest_order(
    layout: Layout,
    cell: CellConfig,
    wanted: Sequence[str],
    asked: Sequence[tuple[str, str]] = (),
) -> list[str] | None:
    """The valid order closest to `wanted`: the operator's order with each part placed as soon
    as its supports allow (Kahn's algorithm over the support graph, ties broken by the
    operator's rank); if the gripper cannot place that one, the same level by level (lower
    levels first, the operator's order within a level); else the Inspector's own order; None if
    the layout has none. Each is verified.

    The pairs the operator `asked` for with move-before edits ((earlier, later)) are kept as
    precedences wherever the supports allow them (`later` does not hold `earlier` up); the
    order that keeps most of them wins, the first among equals."""
    a = Analysis(layout, cell)
    ids = layout.ids
    rank = {pid: k for k, pid in enumerate(wanted)}
    level = {pid: round(layout.part(pid).bottom / cell.cube[2]) for pid in ids}
    extra = _allowed_pairs(a, asked)
    found: list[list[str]] = []
    for edges in (extra, ()) if extra else ((),):
        for key in (
            lambda i: (rank.get(ids[i], len(ids) + i),),
            lambda i: (level[ids[i]], rank.get(ids[i], len(ids) + i)),
        ):
            order = _kahn(a, key, edges)
            if order is not None and order not in found and \
                    verify(layout, cell, sequence=order).passed:  # fmt: skip
                found.append(order)
                break
    if not found:
        report = verify(layout, cell)
        return list(report.sequence) if report.passed and report.sequence else None

    def kept(order: list[str]) -> int:
        at = {pid: k for k, pid in enumerate(order)}
        return sum(1 for x, y in asked if x in at and y in at and at[x] < at[y])

    return max(found, key=kept)  # the first among equals


def _allowed_pairs(a: Analysis, asked: Sequence[tuple[str, str]]) -> tuple[tuple[int, int], ...]:
    """The asked (earlier, later) pairs, as part indices, that the support graph allows: added
    one by one as precedences as long as no cycle forms."""
    index = a.layout.index
    n = len(a.layout)
    after: list[set[int]] = [set() for _ in range(n)]  # i → what must come after i
    for lo, up in a.graph.support_edges.tolist():
        after[lo].add(up)

    def reaches(i: int, j: int) -> bool:
        seen, todo = {i}, [i]
        while todo:
            k = todo.pop()
            if k == j:
                return True
            for m in after[k] - seen:
                seen.add(m)
                todo.append(m)
        return False

    out: list[tuple[int, int]] = []
    for x, y in asked:
        if x not in index or y not in index:
            continue
        i, j = index[x], index[y]
        if i != j and not reaches(j, i):  # y need not come before x
            after[i].add(j)
            out.append((i, j))
    return tuple(out)


def _kahn(
    a: Analysis, key: Callable[[int], tuple[int, ...]], extra: Sequence[tuple[int, int]] = ()
) -> list[str] | None:
    """A topological order of the support graph (supports first) and the `extra` (before,
    after) precedences, smallest `key` first."""
    ids = a.layout.ids
    n = len(ids)
    below: list[set[int]] = [set() for _ in range(n)]
    for lo, up in [*a.graph.support_edges.tolist(), *extra]:
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


def _overlapping(layout: Layout, moved: set[int], tol: float) -> bool:
    """Does any part of `moved` overlap another part by more than `tol` (m) on every axis?"""
    c, h = layout.centres, layout.half_extents
    for i in moved:
        depth = (h[i] + h) - np.abs(c - c[i])
        depth[i] = -1.0
        if bool(np.any(np.all(depth > tol, axis=1))):
            return True
    return False


def _riders(layout: Layout, i: int, touched: set[str], tol: float) -> set[int]:
    """Part i and every untouched part resting on it, transitively (what moves with it)."""
    c, h = layout.centres, layout.half_extents
    out, todo = {i}, [i]
    while todo:
        j = todo.pop()
        for k in range(len(layout)):
            if k in out or layout.objects[k].id in touched:
                continue
            on = abs((c[k, 2] - h[k, 2]) - (c[j, 2] + h[j, 2])) < tol
            if on and all(abs(c[k, a] - c[j, a]) < h[k, a] + h[j, a] - tol for a in (0, 1)):
                out.add(k)
                todo.append(k)
    return out


def _make_room(
    layout: Layout,
    mine: int,
    other: int,
    touched: set[str],
    vacated: Sequence[Sequence[float]],
    cell: CellConfig,
) -> Layout | None:
    """Keep the operator's part `mine` where they put it: the untouched part `other` it collides
    with moves out of the way, with what rests on it — sideways by the overlap (away from
    `mine`, either way if they are level with each other), or to a place an operator's edit
    vacated at its height. The smallest move that overlaps nothing and stays inside the
    workspace wins (a vacated place first among equals); None if there is none."""
    tol = cell.tolerances.contact
    c, h = layout.centres, layout.half_extents
    deltas: list[tuple[float, int, tuple[float, float]]] = []
    for a in (0, 1):
        depth = float(h[mine, a] + h[other, a] - abs(c[other, a] - c[mine, a]))
        side = float(np.sign(c[other, a] - c[mine, a]))
        for sign in (side,) if side else (1.0, -1.0):
            d = [0.0, 0.0]
            d[a] = round(sign * depth, 6)
            deltas.append((abs(depth), 1, (d[0], d[1])))
    for spot in vacated:
        if abs(float(spot[2]) - float(c[other, 2])) < tol:
            d2 = (round(float(spot[0] - c[other, 0]), 6), round(float(spot[1] - c[other, 1]), 6))
            deltas.append((math.hypot(*d2), 0, d2))
    group = _riders(layout, other, touched, tol)
    ws = cell.workspace
    for _, _, (dx, dy) in sorted(deltas):
        if not dx and not dy:
            continue
        parts = list(layout.objects)
        for k in group:
            p = parts[k]
            x, y, z = p.position
            parts[k] = Part(id=p.id, position=(round(x + dx, 6), round(y + dy, 6), z),
                            orientation=p.orientation, size=p.size)  # fmt: skip
        out = layout.replaced(parts)
        lo = out.centres[list(group)] - out.half_extents[list(group)]
        hi = out.centres[list(group)] + out.half_extents[list(group)]
        if np.any(lo < np.array(ws.lower) - tol) or np.any(hi > np.array(ws.upper) + tol):
            continue
        if not _overlapping(out, group, tol):
            return out
    return None


def _follow_support(
    layout: Layout, i: int, moved_by: dict[str, tuple[float, float, float]], cell: CellConfig
) -> Layout | None:
    """An untouched part left hanging because a part under it was moved by the operator goes
    along with that part (the same sideways move), if it then overlaps nothing."""
    tol = cell.tolerances.contact
    c, h = layout.centres, layout.half_extents
    bottom = c[i, 2] - h[i, 2]
    for pid, (dx, dy, _) in sorted(moved_by.items()):
        j = layout.index.get(pid)
        if j is None or abs(c[j, 2] + h[j, 2] - bottom) > tol or not (dx or dy):
            continue
        if not all(abs(c[i, a] - c[j, a]) < h[i, a] + h[j, a] - tol for a in (0, 1)):
            continue  # not on the moved part
        p = layout.objects[i]
        x, y, z = p.position
        part = Part(id=p.id, position=(round(x + dx, 6), round(y + dy, 6), z),
                    orientation=p.orientation, size=p.size)  # fmt: skip
        out = layout.replaced(part if k == i else q for k, q in enumerate(layout.objects))
        if not _overlapping(out, {i}, tol):
            return out
    return None


def _fix(
    layout: Layout,
    v: Violation,
    touched: set[str],
    cell: CellConfig,
    original: Layout | None = None,
) -> Layout | None:
    """One step towards a valid layout for violation `v`, or None if there is none to take.
    `original` is the layout before the edit (where touched parts were)."""
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
        others = [pid for pid in ids if pid not in touched]
        if len(mine) == 1 and mine[0] in touched and others:
            vacated = [original.part(pid).position for pid in sorted(touched)
                       if original is not None and pid in original.index]  # fmt: skip
            room = _make_room(layout, layout.index[mine[0]], layout.index[others[0]],
                              touched, vacated, cell)  # fmt: skip
            if room is not None:
                return room
        i = layout.index[mine[0]]
        x, y = layout.centres[i, :2]
        return _placed(layout, i, float(x), float(y))
    if v.constraint in (Constraint.CONTACT, Constraint.SUPPORT, Constraint.STABILITY):
        i = layout.index[ids[0]]
        if original is not None and ids[0] not in touched:
            moved_by = {
                pid: tuple(float(b - a) for a, b in zip(original.part(pid).position,
                                                        layout.part(pid).position, strict=True))
                for pid in touched if pid in original.index and pid in layout.index
            }  # fmt: skip
            along = _follow_support(layout, i, moved_by, cell)  # type: ignore[arg-type]
            if along is not None:
                return along
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
    asked: Sequence[tuple[str, str]] = (),
) -> Repair | None:
    """The smallest verified repair of `edited` (the operator's layout, with their order
    `sequence` if they gave one), or None when it cannot be found. When following the
    violations' fixes does not converge and `original` (the layout before the edit) is given,
    the touched parts go back towards where they were, only as far as they must."""
    cell = cell or CellConfig()
    found = _follow(edited, cell, touched, sequence, max_steps, original=original, asked=asked)
    if found is None and original is not None:
        back = _back_towards(edited, original, touched, cell, sequence)
        if back is not None:
            found = _follow(back, cell, touched, sequence, 0, start=edited, asked=asked)
    return found


def _follow(
    edited: Layout,
    cell: CellConfig,
    touched: Sequence[str],
    sequence: Sequence[str] | None,
    max_steps: int | None,
    *,
    start: Layout | None = None,
    original: Layout | None = None,
    asked: Sequence[tuple[str, str]] = (),
) -> Repair | None:
    """Follow the violations' fixes from `edited`; the diff is taken from `start` (default:
    `edited`); `original` (the layout before the edit) says where touched parts came from."""
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
            at = {pid: k for k, pid in enumerate(final)}
            return Repair(
                layout, final, changes,
                order_changed=sequence is not None and tuple(sequence) != final,
                kept=tuple(pid for pid in touched if pid in layout.index and pid not in moved),
                unkept=tuple((x, y) for x, y in asked if x in at and y in at and at[x] > at[y]),
            )  # fmt: skip
        violations = sorted(report.violations, key=lambda v: GEOMETRY_FIRST.index(v.constraint))
        geometric = [v for v in violations if v.constraint in GEOMETRY_FIRST[:5]]
        if not geometric:
            if order is None:
                return None
            better = nearest_order(layout, cell, order, asked)
            if better is None or better == order:
                return None
            order = better
            continue
        step = None
        for v in geometric:
            step = _fix(layout, v, mine, cell, original)
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
