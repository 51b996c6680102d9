"""Geometry on the raw plan JSON, independent of the rest of SDI.

Everything here reads only ``result["layout"]["objects"]`` — each object a dict with ``position``
(box centre, m, world frame, z up, table top at z = 0), ``orientation`` (unit quaternion
``[w, x, y, z]``) and ``size`` (``[sx, sy, sz]``, m) — and computes world axis-aligned boxes
itself. It deliberately imports nothing from `sdi.model`, `sdi.design`, `sdi.inspector` or
`sdi.bench.signatures`, so the language evaluation sets judge layouts with their own geometry.

Conventions (default cell): the robot stands at x = 0, so "front" = small x, "back" = large x,
"left" = +y, "right" = -y. A cube is 0.05 m; sizes "in cubes" are extents / 0.05, rounded.
"""

from __future__ import annotations

import itertools
import math
from collections import Counter
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy import ndimage

CUBE = 0.05
TOL = 0.002  # contact tolerance, m
WORKSPACE = ((0.20, 0.80), (0.05, 0.55), (0.0, 0.50))


@dataclass(frozen=True)
class Box:
    """A world axis-aligned box: `lo` and `hi` corners, m."""

    id: str
    lo: tuple[float, float, float]
    hi: tuple[float, float, float]

    @property
    def centre(self) -> tuple[float, float, float]:
        return (
            (self.lo[0] + self.hi[0]) / 2,
            (self.lo[1] + self.hi[1]) / 2,
            (self.lo[2] + self.hi[2]) / 2,
        )

    @property
    def size(self) -> tuple[float, float, float]:
        return (self.hi[0] - self.lo[0], self.hi[1] - self.lo[1], self.hi[2] - self.lo[2])


Boxes = Sequence[Box]


# ---------------------------------------------------------------- reading the plan


def rotation(q: Sequence[float]) -> list[list[float]]:
    """The rotation matrix of a quaternion ``[w, x, y, z]`` (normalised here)."""
    w, x, y, z = (float(v) for v in q)
    n = math.sqrt(w * w + x * x + y * y + z * z) or 1.0
    w, x, y, z = w / n, x / n, y / n, z / n
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def box_of(obj: Mapping[str, Any]) -> Box:
    """The world axis-aligned box of one raw layout object."""
    p = [float(v) for v in obj["position"]]
    half = [float(v) / 2 for v in obj["size"]]
    r = rotation(obj.get("orientation") or (1.0, 0.0, 0.0, 0.0))
    ext = [sum(abs(r[i][j]) * half[j] for j in range(3)) for i in range(3)]
    return Box(
        id=str(obj.get("id", "")),
        lo=(p[0] - ext[0], p[1] - ext[1], p[2] - ext[2]),
        hi=(p[0] + ext[0], p[1] + ext[1], p[2] + ext[2]),
    )


def objects(result: Mapping[str, Any]) -> list[dict[str, Any]] | None:
    """The raw objects of a plan result (or of a bare layout dict); None when there is no
    layout."""
    layout = result.get("layout", result) if "objects" not in result else result
    if not isinstance(layout, Mapping):
        return None
    objs = layout.get("objects")
    return list(objs) if isinstance(objs, list) else None


def boxes(result: Mapping[str, Any]) -> list[Box]:
    """World boxes of a plan result; empty when it has no layout."""
    return [box_of(o) for o in objects(result) or []]


# ---------------------------------------------------------------- whole-set measures


def count(bs: Boxes) -> int:
    return len(bs)


def bounds(bs: Boxes) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    lo = tuple(min(b.lo[i] for b in bs) for i in range(3))
    hi = tuple(max(b.hi[i] for b in bs) for i in range(3))
    return lo, hi  # type: ignore[return-value]


def centre(bs: Boxes) -> tuple[float, float]:
    """The footprint (x, y) centre of the boxes' bounding box."""
    lo, hi = bounds(bs)
    return ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)


def top(bs: Boxes) -> float:
    return max(b.hi[2] for b in bs) if bs else 0.0


def cubes(length: float) -> int:
    """A length in cube units (0.05 m), rounded."""
    return round(length / CUBE)


def footprint(bs: Boxes) -> tuple[float, float]:
    """x and y extent of the boxes, m."""
    lo, hi = bounds(bs)
    return (hi[0] - lo[0], hi[1] - lo[1])


def footprint_cubes(bs: Boxes) -> tuple[int, int]:
    """x and y extent in cubes."""
    fx, fy = footprint(bs)
    return (cubes(fx), cubes(fy))


def plan_dims(bs: Boxes) -> tuple[int, int]:
    """Footprint in cubes, smaller first (orientation-free)."""
    a, b = footprint_cubes(bs)
    return (min(a, b), max(a, b))


def height_cubes(bs: Boxes) -> int:
    """Height of the top above the table, in cubes."""
    return cubes(top(bs))


def thickness_cubes(bs: Boxes) -> int:
    """Own height (top minus bottom), in cubes — for structures standing on others."""
    return cubes(top(bs) - min(b.lo[2] for b in bs)) if bs else 0


def levels(bs: Boxes) -> dict[float, int]:
    """Parts per distinct bottom height (m, rounded to 1 mm), lowest first."""
    c = Counter(round(b.lo[2], 3) for b in bs)
    return dict(sorted(c.items()))


def level_counts(bs: Boxes) -> list[int]:
    return list(levels(bs).values())


def in_workspace(bs: Boxes, tol: float = 0.001) -> bool:
    return all(
        WORKSPACE[i][0] - tol <= b.lo[i] and b.hi[i] <= WORKSPACE[i][1] + tol
        for b in bs
        for i in range(3)
    )


def voxels(bs: Boxes) -> set[tuple[int, int, int]]:
    """Occupied cube cells (i, j, k) counted from the boxes' own min corner."""
    if not bs:
        return set()
    lo, _ = bounds(bs)
    out: set[tuple[int, int, int]] = set()
    for b in bs:
        r = [
            range(cubes(b.lo[i] - lo[i]), max(cubes(b.hi[i] - lo[i]), cubes(b.lo[i] - lo[i]) + 1))
            for i in range(3)
        ]
        out.update((i, j, k) for i in r[0] for j in r[1] for k in r[2])
    return out


def cells(bs: Boxes) -> set[tuple[int, int]]:
    """Occupied footprint cells (i, j) in cube units from the boxes' min corner."""
    return {(i, j) for i, j, _ in voxels(bs)}


def is_full(bs: Boxes) -> bool:
    """Every cube cell of the bounding box is occupied (a solid block, row, wall, grid)."""
    fx, fy = footprint_cubes(bs)
    lo, hi = bounds(bs)
    return len(voxels(bs)) == fx * fy * cubes(hi[2] - lo[2])


# ---------------------------------------------------------------- contact and structures


def _overlaps(a: Box, b: Box) -> list[float]:
    return [min(a.hi[i], b.hi[i]) - max(a.lo[i], b.lo[i]) for i in range(3)]


def touching(a: Box, b: Box, tol: float = TOL) -> bool:
    """Face or edge contact (or overlap) within `tol`; a corner-only contact does not count."""
    ov = _overlaps(a, b)
    if min(ov) < -tol:
        return False
    return sum(o <= tol for o in ov) <= 2


def components(bs: Boxes, tol: float = TOL) -> list[list[Box]]:
    """Connected groups of touching boxes, largest first (ties: smaller x, then y)."""
    n = len(bs)
    parent = list(range(n))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for i in range(n):
        for j in range(i + 1, n):
            if touching(bs[i], bs[j], tol):
                parent[find(i)] = find(j)
    groups: dict[int, list[Box]] = {}
    for i in range(n):
        groups.setdefault(find(i), []).append(bs[i])
    out = list(groups.values())
    out.sort(key=lambda g: (-len(g), *centre(g)))
    return out


def rests_on(upper: Box, lower: Box, tol: float = TOL) -> bool:
    """`upper`'s bottom face lies on `lower`'s top face with a real xy overlap."""
    ov = _overlaps(upper, lower)
    return abs(upper.lo[2] - lower.hi[2]) <= tol and ov[0] > tol and ov[1] > tol


def stands_on(upper: Boxes, lower: Boxes, tol: float = TOL) -> bool:
    """Every lowest part of `upper` is off the table and rests on a top face of `lower`."""
    if not upper or not lower:
        return False
    z0 = min(b.lo[2] for b in upper)
    base = [b for b in upper if b.lo[2] <= z0 + tol]
    return z0 > tol and all(any(rests_on(b, q, tol) for q in lower) for b in base)


def split_at(bs: Boxes, z: float, tol: float = TOL) -> tuple[list[Box], list[Box]]:
    """(parts whose bottom is below z, parts from z up)."""
    return [b for b in bs if b.lo[2] < z - tol], [b for b in bs if b.lo[2] >= z - tol]


def columns(bs: Boxes, tol: float = 0.01) -> list[list[Box]]:
    """Parts grouped by xy centre (within `tol`), each list lowest first."""
    cols: list[list[Box]] = []
    for b in sorted(bs, key=lambda b: b.lo[2]):
        cx, cy, _ = b.centre
        for col in cols:
            x, y, _ = col[0].centre
            if abs(x - cx) <= tol and abs(y - cy) <= tol:
                col.append(b)
                break
        else:
            cols.append([b])
    return cols


def tallest(bs: Boxes, tol: float = TOL) -> int:
    """The tallest chain of parts, each resting on the one below, from the table (in parts)."""
    chain: dict[int, int] = {}
    order = sorted(range(len(bs)), key=lambda i: bs[i].lo[2])
    for i in order:
        below = [chain[j] for j in chain if rests_on(bs[i], bs[j], tol)]
        chain[i] = 1 + max(below) if below else (1 if bs[i].lo[2] <= tol else 0)
    return max(chain.values(), default=0)


@dataclass(frozen=True)
class Span:
    """A part resting on two or more separate supports (with a gap between them under it)."""

    part: Box
    supports: tuple[tuple[Box, ...], ...]


def spans(bs: Boxes, tol: float = TOL) -> list[Span]:
    """Every part whose supporters belong to ≥ 2 separate structures of what lies below it."""
    out: list[Span] = []
    for p in bs:
        if p.lo[2] <= tol:
            continue
        below = [q for q in bs if q is not p and q.hi[2] <= p.lo[2] + tol]
        groups = components(below, tol)
        hit = [g for g in groups if any(rests_on(p, q, tol) for q in g)]
        if len(hit) >= 2:
            out.append(Span(p, tuple(tuple(g) for g in hit)))
    return out


def span_supports(bs: Boxes, tol: float = TOL) -> list[list[Box]]:
    """The distinct supports (pillars) of all spans of `bs`, by footprint, in x-then-y order."""
    seen: dict[frozenset[str], list[Box]] = {}
    for s in spans(bs, tol):
        for g in s.supports:
            seen.setdefault(frozenset(b.id + repr(b.lo) for b in g), list(g))
    return sorted(seen.values(), key=lambda g: centre(g))


def roof_legs(bs: Boxes, tol: float = TOL) -> list[list[Box]] | None:
    """The legs under a roof. Some level splits the boxes into a connected top piece (roof,
    deck, beam, lintel) standing on what lies below, and every separate structure below
    carries it; the legs are those structures. Of all such splits, the one with the most legs
    (on ties the highest, so the legs are as tall as they go); None when there is none."""
    best: list[list[Box]] | None = None
    for z in sorted({round(b.lo[2], 3) for b in bs if b.lo[2] > tol}):
        below, roof = split_at(bs, z, tol)
        if len(components(roof, tol)) != 1 or not stands_on(roof, below, tol):
            continue
        legs = components(below, tol)
        if not all(any(rests_on(r, q, tol) for r in roof for q in g) for g in legs):
            continue
        if best is None or len(legs) >= len(best):  # most legs; on ties the highest split
            best = sorted(legs, key=lambda g: centre(g))
    return best


# ---------------------------------------------------------------- enclosure

_RES = 0.01


def _interior(bs: Boxes) -> tuple[np.ndarray, float, float]:
    """A mask (1 cm cells over the padded footprint) of free cells not reachable from
    outside."""
    lo, hi = bounds(bs)
    x0, y0 = lo[0] - 2 * _RES, lo[1] - 2 * _RES
    nx = math.ceil((hi[0] - x0) / _RES) + 2
    ny = math.ceil((hi[1] - y0) / _RES) + 2
    occ = np.zeros((nx, ny), dtype=bool)
    xs = x0 + (np.arange(nx) + 0.5) * _RES
    ys = y0 + (np.arange(ny) + 0.5) * _RES
    for b in bs:
        mx = (xs > b.lo[0] - TOL) & (xs < b.hi[0] + TOL)
        my = (ys > b.lo[1] - TOL) & (ys < b.hi[1] + TOL)
        occ |= np.outer(mx, my)
    labels, _ = ndimage.label(~occ)
    border = set(np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]])))
    inside = ~occ & ~np.isin(labels, list(border))
    return inside, x0, y0


def interior_area(bs: Boxes) -> float:
    """Footprint area (m²) fully surrounded by `bs` (0 for anything not ring-like)."""
    if not bs:
        return 0.0
    inside, _, _ = _interior(bs)
    return float(inside.sum()) * _RES * _RES


def encloses(ring: Boxes, inner: Boxes) -> bool:
    """`ring` surrounds an empty interior that contains the whole footprint (centre and
    corners) of every part of `inner`."""
    if not ring or not inner:
        return False
    inside, x0, y0 = _interior(ring)
    m = 0.003  # footprint corners, pulled in by 3 mm
    for b in inner:
        cx, cy, _ = b.centre
        xs = (cx, b.lo[0] + m, b.hi[0] - m)
        ys = (cy, b.lo[1] + m, b.hi[1] - m)
        for x in xs:
            for y in ys:
                i, j = int((x - x0) / _RES), int((y - y0) / _RES)
                if not (0 <= i < inside.shape[0] and 0 <= j < inside.shape[1] and inside[i, j]):
                    return False
    return True


# ---------------------------------------------------------------- relative placement


def separation(a: Boxes, b: Boxes) -> float:
    """Smallest xy gap between the two bounding boxes, m (0 when they touch or overlap)."""
    (alo, ahi), (blo, bhi) = bounds(a), bounds(b)
    gx = max(0.0, blo[0] - ahi[0], alo[0] - bhi[0])
    gy = max(0.0, blo[1] - ahi[1], alo[1] - bhi[1])
    return math.hypot(gx, gy)


def sides(a: Boxes, b: Boxes, margin: float = 0.02) -> set[str]:
    """Where `a` is relative to `b`: any of left (+y), right (-y), back (+x), front (-x)."""
    (ax, ay), (bx, by) = centre(a), centre(b)
    out = set()
    if ay - by > margin:
        out.add("left")
    if by - ay > margin:
        out.add("right")
    if ax - bx > margin:
        out.add("back")
    if bx - ax > margin:
        out.add("front")
    return out


def side_of(a: Boxes, b: Boxes) -> str:
    """The dominant direction of `a` from `b`: left, right, back or front."""
    (ax, ay), (bx, by) = centre(a), centre(b)
    dx, dy = ax - bx, ay - by
    if abs(dy) >= abs(dx):
        return "left" if dy > 0 else "right"
    return "back" if dx > 0 else "front"


def between(mid: Boxes, a: Boxes, b: Boxes) -> bool:
    """`mid`'s footprint centre projects strictly inside the segment from `a`'s centre to
    `b`'s, and lies closer to that segment than half its length."""
    (mx, my), (ax, ay), (bx, by) = centre(mid), centre(a), centre(b)
    dx, dy = bx - ax, by - ay
    n2 = dx * dx + dy * dy
    if n2 == 0:
        return False
    t = ((mx - ax) * dx + (my - ay) * dy) / n2
    off = abs((mx - ax) * dy - (my - ay) * dx) / math.sqrt(n2)
    return 0.0 < t < 1.0 and off < 0.5 * math.sqrt(n2)


REGIONS: dict[str, tuple[float, float]] = {
    "left": (0.45, 0.45),
    "right": (0.45, 0.15),
    "front": (0.30, 0.30),
    "back": (0.65, 0.30),
    "centre": (0.45, 0.30),
}


def region_problem(bs: Boxes, name: str) -> str | None:
    """Loose named-region check on the footprint centre; `name` like "back left" or
    "centre"."""
    if not bs:
        return "no parts"
    x, y = centre(bs)
    words = set(name.lower().replace("-", " ").replace("center", "centre").split())
    words.discard("corner")
    tests = {
        "left": (y > 0.33, "y > 0.33"),
        "right": (y < 0.27, "y < 0.27"),
        "front": (x < 0.42, "x < 0.42"),
        "back": (x > 0.48, "x > 0.48"),
        "centre": (abs(x - 0.45) <= 0.08 and abs(y - 0.30) <= 0.08, "within 8 cm of centre"),
        "middle": (abs(x - 0.45) <= 0.08 and abs(y - 0.30) <= 0.08, "within 8 cm of centre"),
    }
    for w in words:
        if w not in tests:
            raise ValueError(f"unknown region word {w!r}")
        ok, need = tests[w]
        if not ok:
            return f"{name}: centre ({x:.3f}, {y:.3f}) fails {need}"
    return None


# ---------------------------------------------------------------- shape profiles


def step_profile(bs: Boxes, axis: int) -> list[int]:
    """Height in cubes (from the boxes' own bottom) of each cube-wide slice along `axis`
    (0 = x, 1 = y), low to high coordinate."""
    if not bs:
        return []
    n = footprint_cubes(bs)[axis]
    prof = [0] * n
    for i, _, k in ((v[axis], v[1 - axis], v[2]) for v in voxels(bs)):
        prof[i] = max(prof[i], k + 1)
    return prof


def staircase_steps(bs: Boxes) -> int:
    """Number of steps if `bs` is a staircase (slice heights rising by one cube per slice
    along x or y, every step filled down to the table), else 0."""
    if not bs:
        return 0
    vox = voxels(bs)
    best = 0
    for axis in (0, 1):
        prof = step_profile(bs, axis)
        if len(prof) < 2:
            continue
        rising = prof == list(range(1, len(prof) + 1))
        falling = prof == list(range(len(prof), 0, -1))
        if not (rising or falling):
            continue
        width = footprint_cubes(bs)[1 - axis]
        want = sum(prof) * width
        if len(vox) == want:
            best = max(best, len(prof))
    return best


def rises_towards(bs: Boxes) -> str | None:
    """The direction a staircase climbs: back (+x), front (-x), left (+y), right (-y)."""
    if staircase_steps(bs) < 2:
        return None
    for axis, up, down in ((0, "back", "front"), (1, "left", "right")):
        prof = step_profile(bs, axis)
        if len(prof) >= 2 and prof == list(range(1, len(prof) + 1)):
            return up
        if len(prof) >= 2 and prof == list(range(len(prof), 0, -1)):
            return down
    return None


def pyramid_levels(bs: Boxes) -> list[int] | None:
    """Parts per level if `bs` is a pyramid (≥ 2 levels, each level strictly fewer parts
    than the one below and inside its footprint, one part on top or a ridge), else None."""
    if not bs:
        return None
    by_level: dict[float, list[Box]] = {}
    for b in bs:
        by_level.setdefault(round(b.lo[2], 3), []).append(b)
    zs = sorted(by_level)
    if len(zs) < 2:
        return None
    counts = [len(by_level[z]) for z in zs]
    for lower, upper in itertools.pairwise(zs):
        if len(by_level[upper]) >= len(by_level[lower]):
            return None
        (llo, lhi), (ulo, uhi) = bounds(by_level[lower]), bounds(by_level[upper])
        if any(ulo[i] < llo[i] - TOL or uhi[i] > lhi[i] + TOL for i in (0, 1)):
            return None
        if not stands_on(by_level[upper], by_level[lower]):
            return None
    return counts


SYMMETRIES = [
    lambda i, j: (i, j),
    lambda i, j: (-i, j),
    lambda i, j: (i, -j),
    lambda i, j: (-i, -j),
    lambda i, j: (j, i),
    lambda i, j: (-j, i),
    lambda i, j: (j, -i),
    lambda i, j: (-j, -i),
]
"""The eight turns and mirror images of a plan cell (i, j) about the origin."""


def _normal_forms(cs: Iterable[tuple[int, int]]) -> list[frozenset[tuple[int, int]]]:
    out = []
    for f in SYMMETRIES:
        pts = [f(i, j) for i, j in cs]
        mi, mj = min(p[0] for p in pts), min(p[1] for p in pts)
        out.append(frozenset((i - mi, j - mj) for i, j in pts))
    return out


def letter(bs: Boxes) -> str | None:
    """The footprint letter of one-cube-thick arms: "L", "U", "T", "cross", or None."""
    cs = cells(bs)
    if not cs:
        return None
    for f in _normal_forms(cs):
        w = max(i for i, _ in f) + 1
        h = max(j for _, j in f) + 1
        if w >= 2 and h >= 2 and f == {(i, 0) for i in range(w)} | {(0, j) for j in range(h)}:
            return "L"
        if (
            w >= 3
            and h >= 2
            and f
            == (
                {(i, 0) for i in range(w)}
                | {(0, j) for j in range(h)}
                | {(w - 1, j) for j in range(h)}
            )
        ):
            return "U"
        if w >= 3 and h >= 2 and w % 2 == 1:
            c = w // 2
            if f == {(i, h - 1) for i in range(w)} | {(c, j) for j in range(h)}:
                return "T"
        for c in range(1, w - 1):
            for r in range(1, h - 1):
                if f == {(i, r) for i in range(w)} | {(c, j) for j in range(h)}:
                    return "cross"
    return None
