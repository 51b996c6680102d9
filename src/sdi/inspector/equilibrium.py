"""Static equilibrium by linear programming: can contact forces hold every part still?

The centre-of-mass test (`stability`) treats everything above a cut as one rigid body, but
contacts only push: a part on top cannot hold up the part it rests on. Here every part is its
own rigid body, as in assembly-stability work (rigid blocks, unilateral contacts, Coulomb
friction approximated by a pyramid):

- Contacts are the support edges (a bottom face on a top face, footprint overlap ≥ the support
  overlap) and the table under parts that rest on it. Each contact patch — a rectangle — is
  shrunk by the stability margin on every side and carries an unknown normal force
  f ≥ 0 (pointing up into the upper part) at each of its 4 corners.
- With friction μ > 0 each corner also carries tangential forces along ±x and ±y,
  λ ≥ 0 with Σλ ≤ μ f (the friction pyramid), and all six rows of force and torque balance are
  written; with μ = 0 (the default) only vertical force and the two tipping torques remain.
  Side contacts are left out on purpose: a rigid-body LP lets two side faces squeeze a part
  with any force and friction then holds it up, which no simulator (and no real stack)
  reproduces.
- Every balance row of part i gets a pair of non-negative slacks; the LP minimises their sum.
  Zero total slack ⇔ the forces exist ⇔ the layout can stand; the parts whose rows need slack
  are the ones that cannot be held.

Sparse and solved with HiGHS; O(N) rows and variables for N parts.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import linprog
from scipy.sparse import coo_matrix
from scipy.spatial import ConvexHull, QhullError

from sdi.inspector.contacts import ContactGraph

SLACK_TOLERANCE = 1e-7
"""Slack (in units of the mean part weight) above which a part counts as unbalanced."""


@dataclass(frozen=True)
class Equilibrium:
    """The LP's answer for one (sub-)layout."""

    stands: bool
    unbalanced: list[int]
    """Parts (layout indices) that no set of contact forces holds still."""
    deficit: dict[int, float]
    """Per unbalanced part, the total slack its balance rows needed (mean part weights)."""


def _contacts(
    graph: ContactGraph, slots: np.ndarray, block: np.ndarray, margin: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lower, upper, patch) of the contacts of the slots, as slot indices; lower −1 is fixed
    ground (the table, or a supporting part outside the slot's block).

    Slot t is part `slots[t]` in block `block[t]`; blocks are solved independently."""
    layout, eps = graph.layout, graph.eps
    n = len(layout)
    c, h = layout.centres, layout.half_extents
    edges, patches = graph.support_edges, graph.support_patches
    order = np.argsort(edges[:, 1], kind="stable")
    e_sorted, p_sorted = edges[order], patches[order]
    ptr = np.searchsorted(e_sorted[:, 1], np.arange(n + 1))
    count = ptr[slots + 1] - ptr[slots]
    upper = np.repeat(np.arange(slots.size), count)
    first = np.repeat(ptr[slots], count)
    offset = np.arange(upper.size) - np.repeat(np.cumsum(count) - count, count)
    edge = first + offset
    lower_part = e_sorted[edge, 0]
    keys = block.astype(np.int64) * n + slots
    key_order = np.argsort(keys, kind="stable")
    sorted_keys = keys[key_order]
    want = block[upper].astype(np.int64) * n + lower_part
    at = np.minimum(np.searchsorted(sorted_keys, want), sorted_keys.size - 1)
    lower = np.where(sorted_keys[at] == want, key_order[at], -1)
    on_table = np.nonzero(np.abs(c[slots, 2] - h[slots, 2]) <= eps)[0]
    tp = slots[on_table]
    table = np.stack(
        [c[tp, 0] - h[tp, 0], c[tp, 0] + h[tp, 0], c[tp, 1] - h[tp, 1], c[tp, 1] + h[tp, 1]],
        axis=1,
    ).reshape(-1, 4)
    lower = np.concatenate([lower, np.full(on_table.size, -1)])
    upper = np.concatenate([upper, on_table])
    patch = np.concatenate([p_sorted[edge].reshape(-1, 4), table]).reshape(-1, 4)
    # Shrink by the margin; a patch narrower than twice the margin becomes its middle line.
    mid_x, mid_y = (patch[:, 0] + patch[:, 1]) / 2, (patch[:, 2] + patch[:, 3]) / 2
    half_x = np.maximum((patch[:, 1] - patch[:, 0]) / 2 - margin, 0.0)
    half_y = np.maximum((patch[:, 3] - patch[:, 2]) / 2 - margin, 0.0)
    shrunk = np.stack([mid_x - half_x, mid_x + half_x, mid_y - half_y, mid_y + half_y], axis=1)
    return lower.astype(np.intp), upper.astype(np.intp), shrunk


def solve(
    graph: ContactGraph,
    margin: float,
    *,
    members: np.ndarray | None = None,
    friction: float = 0.0,
) -> Equilibrium:
    """Static equilibrium of the parts `members` (all parts when None) under gravity.

    Parts outside `members` that support a member are fixed ground (they are placed and
    carry any load: `robust`, or not yet at issue)."""
    if members is None:
        members = np.arange(len(graph.layout))
    return solve_many(graph, margin, [members], friction=friction)[0]


def solve_many(
    graph: ContactGraph,
    margin: float,
    groups: Sequence[np.ndarray],
    *,
    friction: float = 0.0,
) -> list[Equilibrium]:
    """`solve` for several groups of parts at once: one block-diagonal LP (each group on its
    own), built vectorised, one solver call instead of one per group."""
    sizes = [len(g) for g in groups]
    if not sum(sizes):
        return [Equilibrium(True, [], {}) for _ in groups]
    slots = np.concatenate([np.asarray(g, dtype=np.intp) for g in groups])
    block = np.repeat(np.arange(len(groups)), sizes)
    a_eq, b_eq, a_ub, cost, n_x, rows_per = _system(graph, margin, slots, block, friction)
    kwargs: dict[str, object] = {}
    if a_ub is not None:
        kwargs["A_ub"] = a_ub
        kwargs["b_ub"] = np.zeros(a_ub.shape[0])
    res = linprog(cost, A_eq=a_eq, b_eq=b_eq, bounds=(0, None), method="highs", **kwargs)
    if res.status != 0 or res.x is None:  # cannot happen with slacks: all unbalanced
        per_slot = np.full(slots.size, math.inf)
    else:
        n_rows = rows_per * slots.size
        sl = res.x[n_x:]
        per_slot = (sl[:n_rows] + sl[n_rows:]).reshape(-1, rows_per).sum(axis=1)
    out = []
    start = 0
    for size in sizes:
        mine, parts = per_slot[start : start + size], slots[start : start + size]
        start += size
        bad = np.nonzero(mine > SLACK_TOLERANCE)[0]
        out.append(
            Equilibrium(
                stands=bad.size == 0,
                unbalanced=parts[bad].tolist(),
                deficit={int(parts[b]): float(mine[b]) for b in bad},
            )
        )
    return out


def _system(
    graph: ContactGraph, margin: float, slots: np.ndarray, block: np.ndarray, friction: float
) -> tuple[Any, np.ndarray, Any, np.ndarray, int, int]:
    """The LP over the slots: equality rows (force and torque balance, each with two
    slacks), friction rows, cost; and the number of force variables and rows per slot."""
    layout = graph.layout
    n = slots.size
    c, h = layout.centres, layout.half_extents
    vol = layout.volumes
    weight = vol[slots] / float(np.mean(vol))  # in mean part weights
    scale = float(np.mean(h)) * 2  # moments in weight × part length
    lower, upper, patch = _contacts(graph, slots, block, margin)
    n_c = lower.size
    # Corner k of contact e: index 4e + k.
    vx = np.stack([patch[:, 0], patch[:, 1], patch[:, 0], patch[:, 1]], axis=1).ravel()
    vy = np.stack([patch[:, 2], patch[:, 2], patch[:, 3], patch[:, 3]], axis=1).ravel()
    up4 = np.repeat(upper, 4)
    lo4 = np.repeat(lower, 4)
    zc = np.repeat(c[slots[upper], 2] - h[slots[upper], 2], 4)  # contact plane height
    n_v = 4 * n_c
    rows_per = 6 if friction > 0 else 3
    # Row layout per slot: friction: Fx Fy Fz Mx My Mz; no friction: Fz Mx My.
    if friction > 0:
        RFX, RFY, RFZ, RMX, RMY, RMZ = 0, 1, 2, 3, 4, 5
    else:
        RFZ, RMX, RMY = 0, 1, 2
        RFX = RFY = RMZ = -1
    r_idx: list[np.ndarray] = []
    c_idx: list[np.ndarray] = []
    vals: list[np.ndarray] = []

    def add(slot: np.ndarray, row: int, col: np.ndarray, val: np.ndarray, sign: float) -> None:
        ok = slot >= 0
        r_idx.append(slot[ok] * rows_per + row)
        c_idx.append(col[ok])
        vals.append(sign * val[ok])

    def centre(slot: np.ndarray, axis: int) -> np.ndarray:
        return np.where(slot >= 0, c[slots[np.maximum(slot, 0)], axis], 0.0)

    cols = np.arange(n_v)
    for slot, sign in ((up4, 1.0), (lo4, -1.0)):
        dx, dy = (vx - centre(slot, 0)) / scale, (vy - centre(slot, 1)) / scale
        add(slot, RFZ, cols, np.ones(n_v), sign)  # normal force up on the upper part
        add(slot, RMX, cols, dy, sign)  # τx = dy·fz
        add(slot, RMY, cols, -dx, sign)  # τy = −dx·fz
    n_f = 0
    ub: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
    if friction > 0:
        n_f = 4 * n_v  # per corner: +x, −x, +y, −y
        fcols = n_v + np.arange(n_f).reshape(n_v, 4)
        for slot, sign in ((up4, 1.0), (lo4, -1.0)):
            dx, dy = (vx - centre(slot, 0)) / scale, (vy - centre(slot, 1)) / scale
            dz = (zc - centre(slot, 2)) / scale
            for k, (ax, s) in enumerate(((0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0))):
                col = fcols[:, k]
                if ax == 0:  # force (s, 0, 0): τ = (0, dz·s, −dy·s)
                    add(slot, RFX, col, np.full(n_v, s), sign)
                    add(slot, RMY, col, dz * s, sign)
                    add(slot, RMZ, col, -dy * s, sign)
                else:  # force (0, s, 0): τ = (−dz·s, 0, dx·s)
                    add(slot, RFY, col, np.full(n_v, s), sign)
                    add(slot, RMX, col, -dz * s, sign)
                    add(slot, RMZ, col, dx * s, sign)
        # Σλ − μ f ≤ 0 per corner.
        ub_r = np.concatenate([np.repeat(np.arange(n_v), 4), np.arange(n_v)])
        ub_c = np.concatenate([fcols.ravel(), np.arange(n_v)])
        ub_v = np.concatenate([np.ones(n_f), np.full(n_v, -friction)])
        ub = (ub_r, ub_c, ub_v)
    n_rows = rows_per * n
    n_x = n_v + n_f
    slack = np.arange(n_rows)
    r_all = np.concatenate([*r_idx, slack, slack])
    c_all = np.concatenate([*c_idx, n_x + slack, n_x + n_rows + slack])
    v_all = np.concatenate([*vals, np.ones(n_rows), -np.ones(n_rows)])
    a_eq = coo_matrix((v_all, (r_all, c_all)), shape=(n_rows, n_x + 2 * n_rows)).tocsr()
    b_eq = np.zeros(n_rows)
    b_eq[np.arange(n) * rows_per + RFZ] = weight  # supports carry the weight
    cost = np.concatenate([np.zeros(n_x), np.ones(2 * n_rows)])
    a_ub = None
    if ub is not None:
        a_ub = coo_matrix((ub[2], (ub[0], ub[1])), shape=(n_v, n_x + 2 * n_rows)).tocsr()
    return a_eq, b_eq, a_ub, cost, n_x, rows_per


def alone(graph: ContactGraph, margin: float) -> np.ndarray:
    """Parts whose own centre of mass is not over their own supports (by `margin`).

    When a part is placed nothing rests on it yet (whatever does comes later in any valid
    order), so this is its exact balance at that moment, whatever the order. Vectorised
    over parts with one support; parts on several supports are checked by the hull."""
    from sdi.inspector.stability import _hull_check

    layout, eps = graph.layout, graph.eps
    c, h = layout.centres, layout.half_extents
    edges, patches = graph.support_edges, graph.support_patches
    n = len(layout)
    bad: list[int] = []
    on_table = np.abs(c[:, 2] - h[:, 2]) <= eps
    order = np.argsort(edges[:, 1], kind="stable")
    e_sorted, p_sorted = edges[order], patches[order]
    ptr = np.searchsorted(e_sorted[:, 1], np.arange(n + 1))
    up = e_sorted[:, 1]
    over_one = (
        (p_sorted[:, 0] + margin <= c[up, 0])
        & (c[up, 0] <= p_sorted[:, 1] - margin)
        & (p_sorted[:, 2] + margin <= c[up, 1])
        & (c[up, 1] <= p_sorted[:, 3] - margin)
    )
    fine = on_table.copy()
    fine[up[over_one]] = True  # fast path: the centre of mass is over one of its patches
    has = np.nonzero(ptr[1:] > ptr[:-1])[0]
    if has.size:  # fast path: patches spanning the part across y (or x), the hull a rectangle
        starts = ptr[has]
        for a, b in ((0, 1), (1, 0)):  # a: the axis they span, b: the axis they spread along
            span = (p_sorted[:, 2 * a] <= c[up, a] - h[up, a] + eps) & (
                p_sorted[:, 2 * a + 1] >= c[up, a] + h[up, a] - eps
            )
            lo = np.minimum.reduceat(p_sorted[:, 2 * b], starts)
            hi = np.maximum.reduceat(p_sorted[:, 2 * b + 1], starts)
            ok = np.logical_and.reduceat(span, starts) & (h[has, a] >= margin)
            ok &= (lo + margin <= c[has, b]) & (c[has, b] <= hi - margin)
            fine[has[ok]] = True
    for i in np.nonzero(~fine & (ptr[1:] > ptr[:-1]))[0].tolist():
        mine = p_sorted[ptr[i] : ptr[i + 1]]
        x, y = c[i, 0], c[i, 1]
        outside, _ = _hull_check(np.array([x, y]), mine, margin)
        if outside > -margin + 1e-12:
            bad.append(i)
    return np.array(bad, dtype=np.intp)


def robust(graph: ContactGraph) -> np.ndarray:
    """Parts that any set of loads on their top face leaves balanced, shape (N,) bool.

    A part on the table, or one whose support patches' convex hull covers its whole footprint:
    every load on its top lands over that hull. Only parts that are not robust can be tipped
    by what is put on them (and held by a counterweight put on later)."""
    layout, eps = graph.layout, graph.eps
    c, h = layout.centres, layout.half_extents
    n = len(layout)
    out = np.abs(c[:, 2] - h[:, 2]) <= eps
    edges, patches = graph.support_edges, graph.support_patches
    order = np.argsort(edges[:, 1], kind="stable")
    e_sorted, p_sorted = edges[order], patches[order]
    ptr = np.searchsorted(e_sorted[:, 1], np.arange(n + 1))
    up = e_sorted[:, 1]
    full = (p_sorted[:, 0] <= c[up, 0] - h[up, 0] + eps) & (
        p_sorted[:, 1] >= c[up, 0] + h[up, 0] - eps
    )
    full &= (p_sorted[:, 2] <= c[up, 1] - h[up, 1] + eps) & (
        p_sorted[:, 3] >= c[up, 1] + h[up, 1] - eps
    )
    out[up[full]] = True  # fast path: one patch covers the whole footprint
    # Second fast path: patches that each span the footprint across one axis and together
    # reach both of its ends along the other (a beam on two pillars).
    has = np.nonzero(ptr[1:] > ptr[:-1])[0]
    if has.size:
        starts = ptr[has]
        lo_x, hi_x = c[has, 0] - h[has, 0], c[has, 0] + h[has, 0]
        lo_y, hi_y = c[has, 1] - h[has, 1], c[has, 1] + h[has, 1]
        span_y = (p_sorted[:, 2] <= c[up, 1] - h[up, 1] + eps) & (
            p_sorted[:, 3] >= c[up, 1] + h[up, 1] - eps
        )
        span_x = (p_sorted[:, 0] <= c[up, 0] - h[up, 0] + eps) & (
            p_sorted[:, 1] >= c[up, 0] + h[up, 0] - eps
        )
        all_y = np.logical_and.reduceat(span_y, starts)
        all_x = np.logical_and.reduceat(span_x, starts)
        reach_x = (np.minimum.reduceat(p_sorted[:, 0], starts) <= lo_x + eps) & (
            np.maximum.reduceat(p_sorted[:, 1], starts) >= hi_x - eps
        )
        reach_y = (np.minimum.reduceat(p_sorted[:, 2], starts) <= lo_y + eps) & (
            np.maximum.reduceat(p_sorted[:, 3], starts) >= hi_y - eps
        )
        out[has[(all_y & reach_x) | (all_x & reach_y)]] = True
    for i in np.nonzero(~out & (ptr[1:] > ptr[:-1]))[0].tolist():
        mine = p_sorted[ptr[i] : ptr[i + 1]]
        lo_x, hi_x = c[i, 0] - h[i, 0], c[i, 0] + h[i, 0]
        lo_y, hi_y = c[i, 1] - h[i, 1], c[i, 1] + h[i, 1]
        corners = np.concatenate(
            [mine[:, [0, 2]], mine[:, [1, 2]], mine[:, [0, 3]], mine[:, [1, 3]]]
        )
        try:
            eq = ConvexHull(corners).equations
        except QhullError:
            continue
        foot = np.array([[lo_x, lo_y], [hi_x, lo_y], [lo_x, hi_y], [hi_x, hi_y]])
        out[i] = bool(np.all(foot @ eq[:, :2].T + eq[:, 2] <= eps))
    return out


def upward_closure(graph: ContactGraph, seeds: np.ndarray) -> np.ndarray:
    """`seeds` and every part resting on them, at any depth (sorted indices)."""
    edges = graph.support_edges
    mask = np.zeros(len(graph.layout), dtype=bool)
    mask[seeds] = True
    while True:
        grow = edges[mask[edges[:, 0]] & ~mask[edges[:, 1]], 1]
        if grow.size == 0:
            return np.nonzero(mask)[0]
        mask[grow] = True
