"""Parametric structure families in a local frame.

Each family turns its spec type (`TowerSpec`, `GridSpec`, …) into boxes in the structure's own
frame: u is the main axis, v across it, z up from the table; the footprint is centred later.
Sizes come from the cell's part types, so the same code builds with other cube sizes. A family
raises `InfeasibleError` naming the parameter it cannot satisfy.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from sdi.errors import InfeasibleError
from sdi.spec.structure_spec import (
    ArchSpec,
    BlockSpec,
    BridgeSpec,
    CanopySpec,
    CastleSpec,
    CrossSpec,
    EnclosureSpec,
    GridSpec,
    LShapeSpec,
    PackSpec,
    PyramidSpec,
    RowSpec,
    StaircaseSpec,
    StructureSpec,
    TowerSpec,
    TShapeSpec,
    UShapeSpec,
    WallSpec,
)

MAX_PARTS_PER_STRUCTURE = 2_000


@dataclass(frozen=True)
class Box:
    """A part in the local frame: centre (u, v, z) in metres, its type, and its long axis."""

    u: float
    v: float
    z: float
    kind: str = "cube"
    along_v: bool = False


@dataclass(frozen=True)
class Sizes:
    cube: tuple[float, float, float]
    beam: tuple[float, float, float] | None
    min_bearing: float

    @property
    def s(self) -> float:
        return self.cube[0]

    @property
    def h(self) -> float:
        return self.cube[2]


def _resolve(count: int | None, metres: float | None, unit: float, default: int, name: str) -> int:
    if metres is not None:
        n = round(metres / unit)
        if n < 1:
            raise InfeasibleError(
                f"{name}: {metres:g} m is less than one part ({unit:g} m)", parameter=name
            )
        return n
    return default if count is None else count


def _levels(z0: float, n: int, sz: float) -> list[float]:
    return [z0 + sz / 2 + k * sz for k in range(n)]


def _check_at_least(value: int, low: int, name: str, why: str) -> None:
    if value < low:
        raise InfeasibleError(f"{name}: {value} is too small; {why}", parameter=name)


def tower(sp: TowerSpec, z: Sizes) -> list[Box]:
    n = _resolve(sp.height or sp.count, sp.height_m, z.h, 3, "height")
    return [Box(0.0, 0.0, zc) for zc in _levels(0.0, n, z.h)]


def row(sp: RowSpec, z: Sizes) -> list[Box]:
    n = _resolve(sp.length or sp.count, sp.length_m, z.s, 5, "length")
    pitch = z.s + (sp.gap_m or 0.0)
    return [Box(i * pitch, 0.0, z.h / 2) for i in range(n)]


def grid(sp: GridSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 3, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    if sp.count and not (sp.length or sp.width or sp.length_m or sp.width_m):
        nu = math.ceil(math.sqrt(sp.count))
        nv = math.ceil(sp.count / nu)
        cells = [(i, j) for j in range(nv) for i in range(nu)][: sp.count]
    else:
        cells = [(i, j) for j in range(nv) for i in range(nu)]
    pitch = z.s + (sp.gap_m or 0.0)
    return [Box(i * pitch, j * pitch, z.h / 2) for i, j in cells]


def wall(sp: WallSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 4, "length")
    nh = _resolve(sp.height, sp.height_m, z.h, 2, "height")
    if sp.count and not (sp.length or sp.length_m):
        nu = max(1, math.ceil(sp.count / nh))
    return [Box(i * z.s, 0.0, zc) for zc in _levels(0.0, nh, z.h) for i in range(nu)]


def block(sp: BlockSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 2, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    nh = _resolve(sp.height, sp.height_m, z.h, nu, "height")
    return [
        Box(i * z.s, j * z.s, zc)
        for zc in _levels(0.0, nh, z.h)
        for j in range(nv)
        for i in range(nu)
    ]


def pack(sp: PackSpec, z: Sizes) -> list[Box]:
    """`count` parts as compact as possible, filled bottom-up.

    Among bounding boxes at least 75 % full, take the one with the least surface (the most
    cube-like), then the squarest, then the fewest levels; `height` fixes the number of levels.
    """
    n = sp.count or 8
    fixed = _resolve(sp.height, sp.height_m, z.h, 0, "height") or None
    best: tuple[float, int, int, int, int, int] | None = None
    for levels in [fixed] if fixed else range(1, n + 1):
        per_level = math.ceil(n / levels)
        for nu in range(1, per_level + 1):
            nv = math.ceil(per_level / nu)
            if nu > nv or (nu - 1) * nv >= per_level:
                continue  # keep nu ≤ nv and no empty row
            fill = n / (nu * nv * levels)
            surface = 2 * (nu * nv + nv * levels + nu * levels)
            key = (0 if fill >= 0.75 else 1, surface, max(nu, nv, levels), levels, nu, nv)
            if best is None or key < best:
                best = key
    assert best is not None
    _, _, _, levels, nu, nv = best
    cells = [(i, j, k) for k in range(levels) for j in range(nv) for i in range(nu)][:n]
    return [Box(i * z.s, j * z.s, z.h / 2 + k * z.h) for i, j, k in cells]


def pyramid(sp: PyramidSpec, z: Sizes) -> list[Box]:
    base = _resolve(sp.length or sp.width, sp.length_m, z.s, 0, "length")
    levels = _resolve(sp.height, sp.height_m, z.h, 0, "height")
    if not base:
        base = levels or 3
    if not levels:
        levels = base
    if levels > base:
        raise InfeasibleError(
            f"height: {levels} levels need a base of at least {levels} parts, not {base}",
            parameter="height",
        )
    three_d = sp.dims == 3
    out: list[Box] = []
    for k in range(levels):
        n = base - k
        off = k * z.s / 2
        zc = z.h / 2 + k * z.h
        for i in range(n):
            if three_d:
                out.extend(Box(off + i * z.s, off + j * z.s, zc) for j in range(n))
            else:
                out.append(Box(off + i * z.s, 0.0, zc))
    return out


def staircase(sp: StaircaseSpec, z: Sizes) -> list[Box]:
    steps = _resolve(sp.steps or sp.height or sp.length, sp.height_m, z.h, 3, "steps")
    width = _resolve(sp.width, sp.width_m, z.s, 1, "width")
    return [
        Box(i * z.s, j * z.s, zc)
        for i in range(steps)
        for j in range(width)
        for zc in _levels(0.0, i + 1, z.h)
    ]


def _beam(z: Sizes, name: str) -> tuple[float, float, float]:
    if z.beam is None:
        raise InfeasibleError(f"{name}: needs a 'beam' part type in the cell", parameter=name)
    return z.beam


def bridge(sp: BridgeSpec, z: Sizes) -> list[Box]:
    """Pillars joined by beams; `spans` beams end to end over `spans + 1` pillars."""
    beam = _beam(z, "span")
    height = _resolve(sp.height, sp.height_m, z.h, 2, "height")
    spans = sp.spans or 1
    width = _resolve(sp.width, sp.width_m, z.s, 1, "width")
    max_span = int((beam[0] - 2 * z.min_bearing) // z.s)
    span = sp.span or (1 if spans == 1 else 2)
    if span > max_span:
        raise InfeasibleError(
            f"span: {span} parts ({span * z.s:g} m) is wider than a {beam[0]:g} m beam can "
            f"bridge with {z.min_bearing:g} m bearing each side; at most {max_span}, "
            "or ask for more spans",
            parameter="span",
        )
    if spans > 1 and (span + 1) * z.s < beam[0] - 1e-9:
        raise InfeasibleError(
            f"span: with {spans} spans each gap must be at least "
            f"{math.ceil(beam[0] / z.s - 1)} parts so the {beam[0]:g} m beams do not overlap",
            parameter="span",
        )
    pitch = (span + 1) * z.s
    top = height * z.h
    out: list[Box] = []
    for j in range(width):
        v = j * z.s
        for p in range(spans + 1):
            out.extend(Box(p * pitch, v, zc) for zc in _levels(0.0, height, z.h))
        out.extend(Box((p + 0.5) * pitch, v, top + beam[2] / 2, "beam") for p in range(spans))
    return out


def arch(sp: ArchSpec, z: Sizes) -> list[Box]:
    """Two pillars, corbels stepping in by a quarter part per level, and a beam on top."""
    beam = _beam(z, "span")
    height = _resolve(sp.height, sp.height_m, z.h, 2, "height")
    opening = _resolve(sp.span, sp.width_m, z.s, 2, "span")
    corbels = min(2, opening)
    step = z.s / 4
    gap = opening * z.s - 2 * corbels * step
    if gap + 2 * z.min_bearing > beam[0] + 1e-9:
        widest = int((beam[0] - 2 * z.min_bearing + 4 * step) // z.s)
        raise InfeasibleError(
            f"span: an opening of {opening} parts leaves {gap:g} m between the corbels, more "
            f"than a {beam[0]:g} m beam covers with {z.min_bearing:g} m bearing; at most {widest}",
            parameter="span",
        )
    left, right = 0.0, (opening + 1) * z.s
    out = [Box(u, 0.0, zc) for u in (left, right) for zc in _levels(0.0, height, z.h)]
    for k in range(1, corbels + 1):
        zc = (height + k - 0.5) * z.h
        out += [Box(left + k * step, 0.0, zc), Box(right - k * step, 0.0, zc)]
    out.append(Box((left + right) / 2, 0.0, (height + corbels) * z.h + beam[2] / 2, "beam"))
    return out


def canopy(sp: CanopySpec, z: Sizes) -> list[Box]:
    """Four pillars and a two-layer roof of beams: two along u on the pillars, then a closed
    top of beams side by side across them along v."""
    beam = _beam(z, "span")
    height = _resolve(sp.height, sp.height_m, z.h, 3, "height")
    span = _resolve(sp.span, None, z.s, 1, "span")
    widest = int((beam[0] - 2 * z.min_bearing) // z.s)
    if span > widest:
        raise InfeasibleError(
            f"span: {span} parts between pillars is more than a {beam[0]:g} m roof beam covers "
            f"with {z.min_bearing:g} m bearing; at most {widest}",
            parameter="span",
        )
    pitch = (span + 1) * z.s
    top = height * z.h
    across = round(beam[0] / beam[1])  # cross beams side by side close the roof
    out = [
        Box(u, v, zc)
        for v in (0.0, pitch)
        for u in (0.0, pitch)
        for zc in _levels(0.0, height, z.h)
    ]
    out += [Box(pitch / 2, v, top + beam[2] / 2, "beam") for v in (0.0, pitch)]
    out += [
        Box(pitch / 2 + (k - (across - 1) / 2) * beam[1], pitch / 2, top + 1.5 * beam[2], "beam",
            along_v=True)
        for k in range(across)
    ]  # fmt: skip
    return out


def _footprint(cells: list[tuple[int, int]], height: int, z: Sizes) -> list[Box]:
    return [Box(i * z.s, j * z.s, zc) for zc in _levels(0.0, height, z.h) for i, j in cells]


def _ring(nu: int, nv: int) -> list[tuple[int, int]]:
    return [(i, j) for j in range(nv) for i in range(nu) if i in (0, nu - 1) or j in (0, nv - 1)]


def enclosure(sp: EnclosureSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 4, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    _check_at_least(nu, 3, "length", "an enclosure needs 3 parts per side to have an inside")
    _check_at_least(nv, 3, "width", "an enclosure needs 3 parts per side to have an inside")
    return _footprint(_ring(nu, nv), height, z)


def castle(sp: CastleSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 4, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    _check_at_least(nu, 3, "length", "a castle's wall ring needs 3 parts per side")
    _check_at_least(nv, 3, "width", "a castle's wall ring needs 3 parts per side")
    out = _footprint(_ring(nu, nv), height, z)
    extra = sp.count or 1  # corner towers rise this many levels above the walls
    for i, j in ((0, 0), (nu - 1, 0), (0, nv - 1), (nu - 1, nv - 1)):
        out += [Box(i * z.s, j * z.s, zc) for zc in _levels(height * z.h, extra, z.h)]
    return out


def l_shape(sp: LShapeSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 3, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    cells = [(i, 0) for i in range(nu)] + [(0, j) for j in range(1, nv)]
    return _footprint(cells, height, z)


def u_shape(sp: UShapeSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 3, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    _check_at_least(nu, 3, "length", "a U needs 3 parts along its base to have an opening")
    _check_at_least(nv, 2, "width", "a U needs arms at least 2 parts long")
    cells = [(i, 0) for i in range(nu)] + [(u, j) for u in (0, nu - 1) for j in range(1, nv)]
    return _footprint(cells, height, z)


def t_shape(sp: TShapeSpec, z: Sizes) -> list[Box]:
    nu = _resolve(sp.length, sp.length_m, z.s, 3, "length")
    nv = _resolve(sp.width, sp.width_m, z.s, nu, "width")
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    _check_at_least(nu, 3, "length", "a T's bar needs 3 parts")
    _check_at_least(nv, 2, "width", "a T needs a stem at least 1 part below its bar")
    if nu % 2 == 0:
        nu += 1  # the stem sits in the middle of the bar
    mid = nu // 2
    cells = [(i, nv - 1) for i in range(nu)] + [(mid, j) for j in range(nv - 1)]
    return _footprint(cells, height, z)


def cross(sp: CrossSpec, z: Sizes) -> list[Box]:
    n = _resolve(sp.length, sp.length_m, z.s, 3, "length")
    if n % 2 == 0:
        n += 1
    height = _resolve(sp.height, sp.height_m, z.h, 1, "height")
    mid = n // 2
    cells = [(i, mid) for i in range(n)] + [(mid, j) for j in range(n) if j != mid]
    return _footprint(cells, height, z)


# Keyed by `shape`: the generator of a family takes that family's spec type.
FAMILIES: dict[str, Callable[[Any, Sizes], list[Box]]] = {
    "tower": tower,
    "row": row,
    "grid": grid,
    "wall": wall,
    "block": block,
    "pack": pack,
    "pyramid": pyramid,
    "staircase": staircase,
    "bridge": bridge,
    "arch": arch,
    "canopy": canopy,
    "enclosure": enclosure,
    "castle": castle,
    "l_shape": l_shape,
    "u_shape": u_shape,
    "t_shape": t_shape,
    "cross": cross,
}


def generate(sp: StructureSpec, z: Sizes) -> list[Box]:
    """The boxes of any structure, by its family's generator."""
    return FAMILIES[sp.shape](sp, z)
