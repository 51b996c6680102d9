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

from dataclasses import dataclass

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
    graph: ContactGraph, members: np.ndarray, margin: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(lower, upper, patch) of the contacts among `members`; lower −1 is the table."""
    layout, eps = graph.layout, graph.eps
    c, h = layout.centres, layout.half_extents
    keep = np.zeros(len(layout), dtype=bool)
    keep[members] = True
    edges, patches = graph.support_edges, graph.support_patches
    inside = keep[edges[:, 0]] & keep[edges[:, 1]]
    on_table = members[np.abs(c[members, 2] - h[members, 2]) <= eps]
    table = np.stack(
        [
            c[on_table, 0] - h[on_table, 0],
            c[on_table, 0] + h[on_table, 0],
            c[on_table, 1] - h[on_table, 1],
            c[on_table, 1] + h[on_table, 1],
        ],
        axis=1,
    ).reshape(-1, 4)
    lower = np.concatenate([edges[inside, 0], np.full(on_table.size, -1)])
    upper = np.concatenate([edges[inside, 1], on_table])
    patch = np.concatenate([patches[inside], table]).reshape(-1, 4)
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
    """Static equilibrium of the parts `members` (all parts when None) under gravity."""
    layout = graph.layout
    n_all = len(layout)
    members = np.arange(n_all) if members is None else np.asarray(members, dtype=np.intp)
    if members.size == 0:
        return Equilibrium(True, [], {})
    local = np.full(n_all, -1, dtype=np.intp)
    local[members] = np.arange(members.size)
    n = members.size
    c, h = layout.centres, layout.half_extents
    vol = layout.volumes
    weight = vol[members] / float(np.mean(vol[members]))  # in mean part weights
    scale = float(np.mean(h[members])) * 2  # moments in weight × part length
    lower, upper, patch = _contacts(graph, members, margin)
    n_c = lower.size
    # Corner k of contact e: index 4e + k.
    vx = np.stack([patch[:, 0], patch[:, 1], patch[:, 0], patch[:, 1]], axis=1).ravel()
    vy = np.stack([patch[:, 2], patch[:, 2], patch[:, 3], patch[:, 3]], axis=1).ravel()
    up4 = np.repeat(upper, 4)
    lo4 = np.repeat(lower, 4)
    zc = np.repeat(c[upper, 2] - h[upper, 2], 4)  # contact plane height
    n_v = 4 * n_c
    rows_per = 6 if friction > 0 else 3
    # Row layout per part: friction: Fx Fy Fz Mx My Mz; no friction: Fz Mx My.
    if friction > 0:
        RFX, RFY, RFZ, RMX, RMY, RMZ = 0, 1, 2, 3, 4, 5
    else:
        RFZ, RMX, RMY = 0, 1, 2
        RFX = RFY = RMZ = -1
    r_idx: list[np.ndarray] = []
    c_idx: list[np.ndarray] = []
    vals: list[np.ndarray] = []

    def add(part: np.ndarray, row: int, col: np.ndarray, val: np.ndarray, sign: float) -> None:
        ok = part >= 0
        p = local[part[ok]]
        r_idx.append(p * rows_per + row)
        c_idx.append(col[ok])
        vals.append(sign * val[ok])

    cols = np.arange(n_v)
    for part, sign in ((up4, 1.0), (lo4, -1.0)):
        cx = np.where(part >= 0, c[np.maximum(part, 0), 0], 0.0)
        cy = np.where(part >= 0, c[np.maximum(part, 0), 1], 0.0)
        dx, dy = (vx - cx) / scale, (vy - cy) / scale
        add(part, RFZ, cols, np.ones(n_v), sign)  # normal force up on the upper part
        add(part, RMX, cols, dy, sign)  # τx = dy·fz
        add(part, RMY, cols, -dx, sign)  # τy = −dx·fz
    n_f = 0
    ub_rows: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None
    if friction > 0:
        n_f = 4 * n_v  # per corner: +x, −x, +y, −y
        fcols = n_v + np.arange(n_f).reshape(n_v, 4)
        for part, sign in ((up4, 1.0), (lo4, -1.0)):
            cx = np.where(part >= 0, c[np.maximum(part, 0), 0], 0.0)
            cy = np.where(part >= 0, c[np.maximum(part, 0), 1], 0.0)
            cz = np.where(part >= 0, c[np.maximum(part, 0), 2], 0.0)
            dx, dy, dz = (vx - cx) / scale, (vy - cy) / scale, (zc - cz) / scale
            for k, (ax, s) in enumerate(((0, 1.0), (0, -1.0), (1, 1.0), (1, -1.0))):
                col = fcols[:, k]
                if ax == 0:  # force (s, 0, 0): τ = (0, dz·s, −dy·s)
                    add(part, RFX, col, np.full(n_v, s), sign)
                    add(part, RMY, col, dz * s, sign)
                    add(part, RMZ, col, -dy * s, sign)
                else:  # force (0, s, 0): τ = (−dz·s, 0, dx·s)
                    add(part, RFY, col, np.full(n_v, s), sign)
                    add(part, RMX, col, -dz * s, sign)
                    add(part, RMZ, col, dx * s, sign)
        # Σλ − μ f ≤ 0 per corner.
        ub_r = np.concatenate([np.repeat(np.arange(n_v), 4), np.arange(n_v)])
        ub_c = np.concatenate([fcols.ravel(), np.arange(n_v)])
        ub_v = np.concatenate([np.ones(n_f), np.full(n_v, -friction)])
        ub_rows = (ub_r, ub_c, ub_v)
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
    kwargs: dict[str, object] = {}
    if ub_rows is not None:
        ub_r, ub_c, ub_v = ub_rows
        kwargs["A_ub"] = coo_matrix((ub_v, (ub_r, ub_c)), shape=(n_v, n_x + 2 * n_rows)).tocsr()
        kwargs["b_ub"] = np.zeros(n_v)
    res = linprog(cost, A_eq=a_eq, b_eq=b_eq, bounds=(0, None), method="highs", **kwargs)
    if res.status != 0 or res.x is None:  # cannot happen with slacks; be safe: all unbalanced
        return Equilibrium(False, members.tolist(), {int(m): float("inf") for m in members})
    s = res.x[n_x:]
    per_part = (s[:n_rows] + s[n_rows:]).reshape(n, rows_per).sum(axis=1)
    bad = np.nonzero(per_part > SLACK_TOLERANCE)[0]
    return Equilibrium(
        stands=bad.size == 0,
        unbalanced=members[bad].tolist(),
        deficit={int(members[b]): float(per_part[b]) for b in bad},
    )


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
    for i in np.nonzero(~on_table & (ptr[1:] > ptr[:-1]))[0].tolist():
        mine = p_sorted[ptr[i] : ptr[i + 1]]
        x, y = c[i, 0], c[i, 1]
        if np.any(
            (mine[:, 0] + margin <= x)
            & (x <= mine[:, 1] - margin)
            & (mine[:, 2] + margin <= y)
            & (y <= mine[:, 3] - margin)
        ):
            continue
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
    for i in np.nonzero(~out & (ptr[1:] > ptr[:-1]))[0].tolist():
        mine = p_sorted[ptr[i] : ptr[i + 1]]
        lo_x, hi_x = c[i, 0] - h[i, 0], c[i, 0] + h[i, 0]
        lo_y, hi_y = c[i, 1] - h[i, 1], c[i, 1] + h[i, 1]
        full = (mine[:, 0] <= lo_x + eps) & (mine[:, 1] >= hi_x - eps)
        full &= (mine[:, 2] <= lo_y + eps) & (mine[:, 3] >= hi_y - eps)
        if full.any():
            out[i] = True
            continue
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
