"""Static stability: every sub-structure's centre of mass lies over its support polygon.

The paper has no such check (DESIGN.md §3). We cut the layout with a horizontal plane at every
height where some part's bottom face sits. Above each cut, parts joined by support edges form
sub-structures; each one rests on the contact patches of the support edges that cross the cut
(or on the table, at z = 0). Treating a sub-structure as one rigid body, it can only stand if its
centre of mass (uniform density) lies inside the convex hull of those patches, by a margin. A
part on its own is checked at the cut through its own bottom face, together with everything it
carries. Cost: O(H·N) for H distinct bottom heights, vectorised per cut.

Treating the sub-structure as rigid is optimistic — contacts only push, so a part on top cannot
hold up the part it rests on (a canopy with a pillar removed passes here). The verifier
therefore also runs `sdi.inspector.equilibrium` (each part its own body, forces by LP); this
module stays for the fixes it computes (which parts to move, by how much).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import ConvexHull, QhullError

from sdi.inspector.contacts import ContactGraph


@dataclass(frozen=True)
class Toppling:
    """A sub-structure whose centre of mass is outside its support polygon."""

    parts: list[int]
    plane_z: float
    com: tuple[float, float]
    outside_by: float
    movers: list[int]
    """The parts to move: the sub-structure, less the parts that rest on the table."""
    towards: tuple[float, float]
    """Translation (dx, dy) of `movers`, metres, that brings the centre of mass over the
    support (zero when none was found)."""


def _hull_check(com: np.ndarray, patches: np.ndarray, margin: float) -> tuple[float, np.ndarray]:
    """Signed distance of `com` outside the hull of the patches (≤ -margin is inside) + a fix."""
    corners = np.concatenate(
        [patches[:, [0, 2]], patches[:, [1, 2]], patches[:, [0, 3]], patches[:, [1, 3]]]
    )
    try:
        hull = ConvexHull(corners)
        eq = hull.equations  # rows (nx, ny, d): nx*x + ny*y + d <= 0 inside
        dist = eq[:, :2] @ com + eq[:, 2]
        worst = int(np.argmax(dist))
        outside = float(dist[worst])
    except QhullError:  # degenerate (collinear) support: treat as a line, use its box
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        outside = float(np.max(np.concatenate([lo - com, com - hi])))
    centroid = corners.mean(axis=0)
    direction = centroid - com
    norm = float(np.linalg.norm(direction))
    fix = direction / norm * (max(outside, 0.0) + margin) if norm > 0 else np.zeros(2)
    return outside, fix


def _fix(
    graph: ContactGraph, members: np.ndarray, plane: int, margin: float
) -> tuple[list[int], np.ndarray]:
    """Parts to move and a translation that makes the sub-structure stand, if one exists.

    First the whole sub-structure slides on its fixed supporters (their patches change as it
    moves, so the move is refined a few times); failing that, the parts resting on the cut
    stay and everything above them moves. Returns a zero move when neither works.
    """
    layout, eps = graph.layout, graph.eps
    c, h, mass = layout.centres, layout.half_extents, layout.volumes
    bottoms = c[:, 2] - h[:, 2]
    cut = plane * eps
    member_list = members.tolist()
    resting = [m for m in member_list if abs(bottoms[m] - cut) <= eps]
    above = [m for m in member_list if abs(bottoms[m] - cut) > eps]
    edges = graph.support_edges
    if plane <= 0:
        r = np.array(resting, dtype=np.intp)
        base = np.stack(
            [c[r, 0] - h[r, 0], c[r, 0] + h[r, 0], c[r, 1] - h[r, 1], c[r, 1] + h[r, 1]], 1
        )
    else:
        crossing = edges[~np.isin(edges[:, 0], member_list) & np.isin(edges[:, 1], member_list)]
        base = graph.support_patches[
            ~np.isin(edges[:, 0], member_list) & np.isin(edges[:, 1], member_list)
        ]
    strategies: list[tuple[list[int], np.ndarray | None]] = []
    if plane > 0:
        strategies.append((member_list, crossing))  # slide the whole sub-structure
    strategies.append((above, None))  # keep what rests on the cut, move the rest
    total = float(np.sum(mass[members]))
    for movers, sliding in strategies:
        if not movers:
            continue
        moved_mass = float(np.sum(mass[movers]))
        shift = np.zeros(2)
        for _ in range(12):
            com = (
                np.sum(mass[members, None] * c[members, :2], axis=0) + shift * moved_mass
            ) / total
            if sliding is None:
                patches = base
            else:
                lo, up = sliding[:, 0], sliding[:, 1]
                x_lo = np.maximum(c[lo, 0] - h[lo, 0], c[up, 0] - h[up, 0] + shift[0])
                x_hi = np.minimum(c[lo, 0] + h[lo, 0], c[up, 0] + h[up, 0] + shift[0])
                y_lo = np.maximum(c[lo, 1] - h[lo, 1], c[up, 1] - h[up, 1] + shift[1])
                y_hi = np.minimum(c[lo, 1] + h[lo, 1], c[up, 1] + h[up, 1] + shift[1])
                ok = (x_hi - x_lo > eps) & (y_hi - y_lo > eps)
                patches = np.stack([x_lo, x_hi, y_lo, y_hi], 1)[ok]
            if len(patches) == 0:
                break
            outside, step = _hull_check(com, patches, margin)
            if outside <= -margin + 1e-12:
                return movers, np.round(shift, 4)
            shift = shift + step * 1.05
    return member_list, np.zeros(2)


def find_toppling(graph: ContactGraph, margin: float) -> list[Toppling]:
    """All sub-structures that cannot stand, highest cut first, each reported once."""
    layout = graph.layout
    n = len(layout)
    if n == 0:
        return []
    c, h, mass = layout.centres, layout.half_extents, layout.volumes
    eps = graph.eps
    bottoms = c[:, 2] - h[:, 2]
    level = np.round(bottoms / eps).astype(np.int64)  # bottoms quantised to ε
    edges, patches = graph.support_edges, graph.support_patches
    table_patches = np.stack(
        [c[:, 0] - h[:, 0], c[:, 0] + h[:, 0], c[:, 1] - h[:, 1], c[:, 1] + h[:, 1]], 1
    )
    found: list[Toppling] = []
    reported: set[frozenset[int]] = set()
    for plane in sorted(set(level.tolist()), reverse=True):
        above = level >= plane
        idx = np.nonzero(above)[0]
        local = np.full(n, -1)
        local[idx] = np.arange(idx.size)
        inside = above[edges[:, 0]] & above[edges[:, 1]]
        e = edges[inside]
        graph_a = coo_matrix(
            (np.ones(len(e)), (local[e[:, 0]], local[e[:, 1]])), shape=(idx.size, idx.size)
        )
        _, label_local = connected_components(graph_a, directed=False)
        label = np.full(n, -1)
        label[idx] = label_local
        # Components that start at this cut (hold a part whose bottom is on it).
        fresh = np.unique(label[idx[level[idx] == plane]])
        if plane <= 0:  # the table carries parts resting on it
            carriers = idx[np.abs(bottoms[idx]) <= eps]
            cross_label, cross_patch = label[carriers], table_patches[carriers]
        else:
            crossing = ~above[edges[:, 0]] & above[edges[:, 1]]
            cross_label, cross_patch = label[edges[crossing, 1]], patches[crossing]
        weight = np.bincount(label[idx], weights=mass[idx])
        com_x = np.bincount(label[idx], weights=mass[idx] * c[idx, 0]) / weight
        com_y = np.bincount(label[idx], weights=mass[idx] * c[idx, 1]) / weight
        # Fast path, vectorised: the centre of mass lies well inside one of its patches.
        cx, cy = com_x[cross_label], com_y[cross_label]
        inside_one = (
            (cross_patch[:, 0] + margin <= cx)
            & (cx <= cross_patch[:, 1] - margin)
            & (cross_patch[:, 2] + margin <= cy)
            & (cy <= cross_patch[:, 3] - margin)
        )
        settled = np.zeros(weight.size, dtype=bool)
        settled[cross_label[inside_one]] = True
        held = np.zeros(weight.size, dtype=bool)
        held[cross_label] = True  # components with nothing under them go to the support check
        fresh = fresh[held[fresh] & ~settled[fresh]]
        if fresh.size == 0:
            continue
        order = np.argsort(cross_label, kind="stable")
        cross_label, cross_patch = cross_label[order], cross_patch[order]
        starts = np.searchsorted(cross_label, fresh, side="left")
        ends = np.searchsorted(cross_label, fresh, side="right")
        for comp, s, t in zip(fresh.tolist(), starts.tolist(), ends.tolist(), strict=True):
            com = np.array([com_x[comp], com_y[comp]])
            outside, _ = _hull_check(com, cross_patch[s:t], margin)
            if outside <= -margin + 1e-12:
                continue
            members = np.nonzero(label == comp)[0]
            key = frozenset(members.tolist())
            if key in reported:
                continue
            reported.add(key)
            movers, shift = _fix(graph, members, plane, margin)
            found.append(
                Toppling(
                    parts=members.tolist(),
                    plane_z=float(plane * eps),
                    com=(float(com[0]), float(com[1])),
                    outside_by=max(outside, 0.0),
                    movers=movers,
                    towards=(float(shift[0]), float(shift[1])),
                )
            )
    return found
