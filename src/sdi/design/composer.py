"""The parametric Designer: a `Spec` becomes a verified `Layout`.

Each structure is generated in its local frame, turned to its axis and yaw, and placed at its
stated position, its named region, or — for structures the command does not place — side by
side around the cell's anchor point, keeping `structure_gap` between footprints. Parameters the
workspace cannot hold are refused up front with the largest value that fits; the finished
layout must pass the verifier, or the Designer says which constraint it breaks.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from sdi.design.shapes import MAX_PARTS_PER_STRUCTURE, Box, Sizes, generate
from sdi.errors import InfeasibleError, InputError, LimitError
from sdi.inspector.contacts import ContactGraph
from sdi.inspector.verifier import Report, verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part, quat_from_yaw
from sdi.spec.structure_spec import Spec, StructureSpec


@dataclass(frozen=True)
class _Placed:
    """A structure's boxes in world orientation, centred on its footprint, and where it goes."""

    spec: StructureSpec
    xy: np.ndarray  # (n, 2) offsets from the footprint centre, m
    z: np.ndarray  # (n,) centre heights, m
    sizes: list[tuple[float, float, float]]
    yaws: np.ndarray  # (n,) rad
    half: np.ndarray  # (2,) footprint half extents x, y, m
    kinds: list[str]
    # where the structure's own footprint centre is in the unit (a unit of related
    # structures is centred on all of them; stated coordinates are the structure's own)
    origin: np.ndarray = field(default_factory=lambda: np.zeros(2))


def part_sizes(cell: CellConfig, part: str) -> Sizes:
    """The generators' part sizes for structures built of `part` in `cell`."""
    if part not in cell.part_types:
        raise InputError(
            f"unknown part type {part!r}; the cell has {sorted(cell.part_types)}", field="part"
        )
    return Sizes(
        cell.part_types[part], cell.part_types.get("beam"), cell.tolerances.support_overlap
    )


def _footprint_half(
    yaws: list[float] | np.ndarray, dims: list[tuple[float, float, float]]
) -> np.ndarray:
    """Footprint of boxes turned by `yaws` (rad) about z: AABB half extents (n, 2), m."""
    return np.array(
        [
            [abs(math.cos(a)) * d[0] / 2 + abs(math.sin(a)) * d[1] / 2,
             abs(math.sin(a)) * d[0] / 2 + abs(math.cos(a)) * d[1] / 2]
            for a, d in zip(yaws, dims, strict=True)
        ]
    ).reshape(-1, 2)  # fmt: skip


def _orient(spec: StructureSpec, boxes: list[Box], sizes: Sizes) -> _Placed:
    yaw0 = math.pi / 2 if (spec.axis or "y") == "y" else 0.0
    yaw = yaw0 + math.radians(spec.yaw_deg)
    cos, sin = math.cos(yaw), math.sin(yaw)
    kinds, dims, yaws, uv = [], [], [], []
    for b in boxes:
        size = sizes.cube if b.kind == "cube" else sizes.beam
        assert size is not None
        kinds.append(b.kind)
        dims.append(size)
        yaws.append(yaw + (math.pi / 2 if b.along_v else 0.0))
        uv.append((b.u, b.v))
    local = np.array(uv, dtype=float).reshape(-1, 2)
    xy = local @ np.array([[cos, sin], [-sin, cos]])
    xy[np.abs(xy) < 1e-12] = 0.0
    half = _footprint_half(yaws, dims)
    lo, hi = (xy - half).min(axis=0), (xy + half).max(axis=0)
    centre = (lo + hi) / 2
    return _Placed(
        spec=spec,
        xy=xy - centre,
        z=np.array([b.z for b in boxes]),
        sizes=dims,
        yaws=np.array(yaws),
        half=(hi - lo) / 2,
        kinds=kinds,
    )


def _axis_parameter(spec: StructureSpec, world_axis: int) -> str:
    main = 0 if (spec.axis or "y") == "x" else 1
    if spec.yaw_deg % 180 and spec.yaw_deg % 90 == 0:
        main = 1 - main
    return "length" if world_axis == main else "width"


def _check_fits(p: _Placed, cell: CellConfig) -> None:
    ws = cell.workspace
    top = float((p.z + np.array([d[2] for d in p.sizes]) / 2).max())
    if top > ws.z_max - ws.z_min + 1e-9:
        name = "steps" if p.spec.shape == "staircase" else "height"
        levels = int((ws.z_max - ws.z_min) / cell.cube[2] + 1e-9)
        raise InfeasibleError(
            f"{name}: the {p.spec.shape} is {top:.3f} m tall but the workspace is "
            f"{ws.z_max - ws.z_min:g} m tall (at most {levels} levels of {cell.cube[2]:g} m)",
            parameter=name,
        )
    extent = (ws.x_max - ws.x_min, ws.y_max - ws.y_min)
    for d in (0, 1):
        if 2 * p.half[d] > extent[d] + 1e-9:
            name = _axis_parameter(p.spec, d)
            fits = int(extent[d] / cell.cube[0] + 1e-9)
            raise InfeasibleError(
                f"{name}: the {p.spec.shape} is {2 * p.half[d]:.3f} m long along {'xy'[d]} but the "
                f"workspace is {extent[d]:g} m (about {fits} parts); "
                f"make it smaller or turn it with 'along {'yx'[d]}'",
                parameter=name,
            )


_FACES = {"front": (0, 1.0), "back": (0, -1.0), "right": (1, 1.0), "left": (1, -1.0)}
"""A footprint face: the axis it faces along and which way its centre lies from it."""


def _target(spec: StructureSpec, cell: CellConfig) -> tuple[float | None, float | None]:
    x, y = spec.at_x, spec.at_y
    if spec.region is not None:
        regions = cell.design.regions
        if spec.region not in regions:
            raise InputError(
                f"unknown region {spec.region!r}; the cell has {sorted(regions)}", field="region"
            )
        rx, ry = regions[spec.region]
        x = rx if x is None else x
        y = ry if y is None else y
    if spec.edge:
        # against a side of the workspace: the boundary itself, which `_clamp` turns into as
        # far that way as the footprint fits
        ws = cell.workspace
        bounds = {"back": (ws.x_max, None), "front": (ws.x_min, None),
                  "left": (None, ws.y_max), "right": (None, ws.y_min)}  # fmt: skip
        cx, cy = cell.design.regions.get("centre", cell.design.anchor)
        for side in spec.edge:
            bx, by = bounds[side]
            x = bx if bx is not None and spec.at_x is None else x
            y = by if by is not None and spec.at_y is None else y
        x = cx if x is None else x
        y = cy if y is None else y
    return x, y


def _inside(centre: np.ndarray, half: np.ndarray, cell: CellConfig) -> bool:
    ws = cell.workspace
    return bool(
        ws.x_min - 1e-9 <= centre[0] - half[0]
        and centre[0] + half[0] <= ws.x_max + 1e-9
        and ws.y_min - 1e-9 <= centre[1] - half[1]
        and centre[1] + half[1] <= ws.y_max + 1e-9
    )


def _clear(
    centre: np.ndarray, half: np.ndarray, taken: list[tuple[np.ndarray, np.ndarray]], gap: float
) -> bool:
    return all(np.any(np.abs(centre - c) >= half + h + gap - 1e-9) for c, h in taken)


def _search(
    want: np.ndarray,
    half: np.ndarray,
    taken: list[tuple[np.ndarray, np.ndarray]],
    gap: float,
    cell: CellConfig,
    axes: tuple[int, ...],
) -> np.ndarray | None:
    """The free spot nearest `want`, moving only along `axes` (half-part steps)."""
    if _inside(want, half, cell) and _clear(want, half, taken, gap):
        return want
    if not axes:
        return None
    step = cell.cube[0] / 2
    reach = int(max(cell.workspace.x_max - cell.workspace.x_min,
                    cell.workspace.y_max - cell.workspace.y_min) / step) + 1  # fmt: skip
    for r in range(1, reach + 1):
        ring = []
        for i in range(-r, r + 1) if 0 in axes else (0,):
            for j in range(-r, r + 1) if 1 in axes else (0,):
                if max(abs(i), abs(j)) == r:
                    ring.append(want + step * np.array([i, j]))
        ring.sort(key=lambda c: (float(np.linalg.norm(c - want)), c[0], c[1]))
        for c in ring:
            if _inside(c, half, cell) and _clear(c, half, taken, gap):
                return c
    return None


def _clamp(c: np.ndarray, half: np.ndarray, cell: CellConfig, axes: tuple[int, ...]) -> np.ndarray:
    ws = cell.workspace
    c = c.copy()
    for d in axes:
        lo = (ws.x_min, ws.y_min)[d] + half[d]
        hi = (ws.x_max, ws.y_max)[d] - half[d]
        if lo <= hi:
            c[d] = min(max(c[d], lo), hi)
    return c


def _place_all(
    placed: list[_Placed],
    cell: CellConfig,
    gap: float | None = None,
    line: str | None = None,
    grid: tuple[int, int] | None = None,
) -> list[np.ndarray]:
    """Footprint centres: stated coordinates exactly, regions and the rest nearest free spot.

    Stated coordinates are kept (an unstated axis may slide to avoid another structure); a
    named region, or an edge of the workspace, is a preference the structure is pulled into
    and moved from to stay clear;
    structures with neither go side by side along y around the anchor (along x, front to
    back, when `line` is "x"; in rows by columns around it when `grid` is given).
    """
    anchor = np.array(cell.design.anchor)
    stated = gap is not None
    gap = cell.design.structure_gap if gap is None else gap
    ws = cell.workspace
    centres: list[np.ndarray | None] = [None] * len(placed)
    taken: list[tuple[np.ndarray, np.ndarray]] = []
    owners: list[int] = []

    def put(k: int, c: np.ndarray) -> None:
        centres[k] = c
        taken.append((c, placed[k].half))
        owners.append(k)

    # 1. stated coordinates
    for k, p in enumerate(placed):
        if p.spec.at_x is None and p.spec.at_y is None:
            continue
        x, y = _target(p.spec, cell)
        c = np.array([anchor[0] if x is None else x, anchor[1] if y is None else y])
        c = c - np.array(
            [p.origin[0] if x is not None else 0.0, p.origin[1] if y is not None else 0.0]
        )
        for face in p.spec.at_face:  # "its front edge at x = 0.30": the centre behind it
            d, sign = _FACES[face]
            if (x, y)[d] is not None:
                c[d] += sign * p.half[d]
        free_axes = tuple(d for d, v in enumerate((p.spec.at_x, p.spec.at_y)) if v is None)
        c = _clamp(c, p.half, cell, free_axes)
        if not _inside(c, p.half, cell):
            d = 0 if not (ws.x_min <= c[0] - p.half[0] and c[0] + p.half[0] <= ws.x_max) else 1
            field = ("at_x", "at_y")[d]
            lo = (ws.x_min, ws.y_min)[d] + p.half[d]
            hi = (ws.x_max, ws.y_max)[d] - p.half[d]
            raise InfeasibleError(
                f"{field}: {c[d]:g} m puts the {p.spec.shape} outside the workspace; "
                f"its centre {'xy'[d]} must lie in [{lo:.3f}, {hi:.3f}] m",
                parameter=field,
            )
        # "two towers, both at x = 0.5": moved along the free axis, they keep the gap apart
        # (SDI's own gap only where there is room for it)
        spot = _search(c, p.half, taken, gap, cell, free_axes) if free_axes else None
        if spot is None and not (stated and free_axes):
            spot = _search(c, p.half, taken, 0.0, cell, free_axes)
        if spot is None:
            other = next(
                placed[o]
                for o, (tc, th) in zip(owners, taken, strict=True)
                if not _clear(c, p.half, [(tc, th)], 0.0)
            )
            field = "at_x" if p.spec.at_x is not None else "at_y"
            raise InfeasibleError(
                f"{field}: the {p.spec.shape} at ({c[0]:g}, {c[1]:g}) m overlaps the "
                f"{other.spec.shape} placed before it; give them positions at least "
                f"{2 * float(max(p.half)):.3f} m apart",
                parameter=field,
            )
        put(k, spot)
    # 2. named regions, 3. the rest side by side along y around the anchor
    regional = [
        k for k, p in enumerate(placed) if centres[k] is None and (p.spec.region or p.spec.edge)
    ]
    free = [k for k in range(len(placed)) if centres[k] is None and k not in regional]
    wants: list[tuple[int, np.ndarray, str, float]] = []
    groups: dict[tuple[str | None, tuple[str, ...]], list[int]] = {}
    for k in regional:  # several in one region ("three towers at the back") stand in a line
        groups.setdefault((placed[k].spec.region, tuple(placed[k].spec.edge)), []).append(k)
    extent = (ws.x_max - ws.x_min, ws.y_max - ws.y_min)
    for members in groups.values():
        region = placed[members[0]].spec.region or ""
        along = 0 if line == "x" or (region in ("left", "right")) else 1
        widths = [2 * placed[k].half[along] for k in members]
        # "five towers along the back": the line stays in its region (the fifth stood out)
        between = gap if stated else _closed_up(widths, gap, extent[along])
        start = -(sum(widths) + between * max(0, len(members) - 1)) / 2
        for k, w in zip(members, widths, strict=True):
            x, y = _target(placed[k].spec, cell)
            assert x is not None and y is not None
            want = np.array([x, y])
            if len(members) == 1:  # "a tower in the centre, another 10 cm to its left": the
                want -= placed[k].origin  # structure said there stands there, not its unit
            want[along] += start + w / 2
            start += w + between
            wants.append((k, _clamp(want, placed[k].half, cell, (0, 1)), "region", between))
    if grid is not None and len(free) == grid[0] * grid[1]:
        wants.extend((*w, gap) for w in _grid_wants(placed, free, grid, anchor, gap))
    else:
        d = 0 if line == "x" else 1
        step: float = gap

        def length(axis: int, between: float = step) -> float:
            return sum(2 * placed[k].half[axis] for k in free) + between * max(0, len(free) - 1)

        if line is None and length(1) > extent[1] and length(0) <= extent[0]:
            d = 0  # a line too long for across the table runs front to back (it broke in two)
        elif line == "y" and length(1, 0.01) > extent[1] and length(0) <= extent[0]:
            d = 0  # said across, but too long for it even closed up
        widths = [2 * placed[k].half[d] for k in free]
        if not stated:  # the line stays one line (it broke in two)
            gap = _closed_up(widths, gap, extent[d])
        s0 = anchor[d] - (sum(widths) + gap * max(0, len(free) - 1)) / 2
        for k, w in zip(free, widths, strict=True):
            want = anchor.copy()
            want[d] = s0 + w / 2
            wants.append((k, want, "structures", gap))
            s0 += w + gap
    for k, want, field, clear in wants:
        spot = _search(want, placed[k].half, taken, clear, cell, (0, 1))
        if spot is None:
            raise InfeasibleError(
                f"{field}: no free place in the workspace for the {placed[k].spec.shape} "
                f"beside the {len(taken)} structure(s) already placed; make them smaller or fewer",
                parameter=field,
            )
        put(k, spot)
    return [c for c in centres if c is not None]


def _closed_up(widths: list[float], gap: float, room: float) -> float:
    """SDI's own `gap` between structures of `widths` in a line, closed up (to 1 cm at least)
    so that the line fits in `room`."""
    if len(widths) < 2 or sum(widths) + gap * (len(widths) - 1) <= room:
        return gap
    return max(min(gap, (room - sum(widths) - 1e-6) / (len(widths) - 1)), min(gap, 0.01))


def _grid_wants(
    placed: list[_Placed],
    free: list[int],
    grid: tuple[int, int],
    anchor: np.ndarray,
    gap: float,
) -> list[tuple[int, np.ndarray, str]]:
    """Wanted centres of `free` in `grid` rows (front to back) by columns (right to left),
    the front row first, each row as deep and each column as wide as its largest member,
    `gap` between them, the whole centred on `anchor`."""
    rows, cols = grid
    cells = [(k, divmod(i, cols)) for i, k in enumerate(free)]
    depth = [max(2 * placed[k].half[0] for k, (r, _) in cells if r == row) for row in range(rows)]
    width = [max(2 * placed[k].half[1] for k, (_, c) in cells if c == col) for col in range(cols)]
    x0 = anchor[0] - (sum(depth) + gap * (rows - 1)) / 2
    y0 = anchor[1] - (sum(width) + gap * (cols - 1)) / 2
    out = []
    for k, (r, c) in cells:
        x = x0 + sum(depth[:r]) + gap * r + depth[r] / 2
        y = y0 + sum(width[:c]) + gap * c + width[c] / 2
        out.append((k, np.array([x, y]), "grid"))
    return out


def _merge(base: _Placed, other: _Placed, dxy: np.ndarray, dz: float) -> _Placed:
    """One unit of `base` and `other` moved by (dxy, dz), re-centred on its footprint."""
    xy = np.vstack([base.xy, other.xy + dxy])
    z = np.concatenate([base.z, other.z + dz])
    sizes = [*base.sizes, *other.sizes]
    yaws = np.concatenate([base.yaws, other.yaws])
    lo = np.minimum(-base.half, dxy - other.half)
    hi = np.maximum(base.half, dxy + other.half)
    centre = (lo + hi) / 2
    return _Placed(
        spec=base.spec,
        xy=xy - centre,
        z=z,
        sizes=sizes,
        yaws=yaws,
        half=(hi - lo) / 2,
        kinds=[*base.kinds, *other.kinds],
        origin=base.origin - centre,
    )


def _top(p: _Placed) -> tuple[float, np.ndarray, np.ndarray]:
    """Height of the unit's top face, m, and the footprint centre and half extents of the
    parts that reach it."""
    tops = p.z + np.array([d[2] for d in p.sizes]) / 2
    top = float(tops.max())
    high = tops > top - 1e-6
    half = _footprint_half(p.yaws, p.sizes)[high]
    lo, hi = (p.xy[high] - half).min(axis=0), (p.xy[high] + half).max(axis=0)
    return top, (lo + hi) / 2, (hi - lo) / 2


def _along_top(
    sub: _Placed, top_half: np.ndarray, cell: CellConfig, edge: str | None = None
) -> _Placed:
    """A structure whose axis was not said, set on a top it overhangs but would fit on if
    turned ("a wall along x, with a row of 3 on top"), or set along the top's left or right
    edge: turned to run along that top or edge."""
    s = sub.spec
    fits = bool(np.all(sub.half <= top_half + 1e-6))
    along = edge in ("left", "right") and sub.half[1] > sub.half[0] + 1e-6
    if s.axis is not None or s.yaw_deg or (fits and not along):
        return sub
    if np.any(sub.half[::-1] > top_half + 1e-6):
        return sub
    turned = s.model_copy(update={"axis": "x"})  # its axis was not said: y, turned to x
    sizes = part_sizes(cell, turned.part)
    return _orient(turned, generate(turned, sizes), sizes)


_SIDES = {"left": (1, 1.0), "right": (1, -1.0), "back": (0, 1.0), "front": (0, -1.0)}
_SIDE_OF = {v: k for k, v in _SIDES.items()}
_CLIMBING_BACK = {"left": ("y", 180.0), "right": ("y", 0.0), "back": ("x", 180.0),
                  "front": ("x", 0.0)}  # fmt: skip
"""A staircase on that side of another climbs back towards it: its axis and yaw (it climbs
+y along y, +x along x, the other way turned half round)."""


def _facing(stairs: StructureSpec, cell: CellConfig) -> Callable[[str], _Placed] | None:
    """A staircase whose way up was not said, put beside another structure, climbs towards it
    ("a staircase leading up to a tower", "a staircase against each end of a wall"): the
    staircase as placed on each side; None for any other structure."""
    if stairs.shape != "staircase" or stairs.axis is not None or stairs.yaw_deg:
        return None
    sizes = part_sizes(cell, stairs.part)
    boxes = generate(stairs, sizes)

    def on(side: str) -> _Placed:
        axis, yaw = _CLIMBING_BACK[side]
        return _orient(stairs.model_copy(update={"axis": axis, "yaw_deg": yaw}), boxes, sizes)

    return on


def _ring_for(ring: StructureSpec, inner: _Placed, cell: CellConfig) -> StructureSpec:
    """The ring's size: as stated, else one part of room around `inner` on every side."""
    unit = cell.cube[0]
    need = [round(2 * float(h) / unit + 0.499) + 2 for h in inner.half]  # inside, in parts
    if getattr(ring, "length", None) is not None or getattr(ring, "length_m", None) is not None:
        return ring
    side = max(need) + 2
    # the sides its family has (an enclosure or a castle has both; a model may name another)
    sides: dict[str, int] = {k: side for k in ("length", "width") if k in type(ring).model_fields}
    return ring.model_copy(update={**sides, "axis": None})


def _beside(
    base: _Placed,
    sub: _Placed,
    side: str | None,
    cell: CellConfig,
    gap: float | None = None,
    groups: tuple[bool, bool] = (False, False),
    facing: Callable[[str], _Placed] | None = None,
) -> _Placed:
    """`sub` `gap` (else one structure gap) from `base` on `side`; with no side, to the left
    if the pair fits across the workspace that way, else behind — but two long structures
    running left to right (rows, walls) stand alongside, one behind the other. Across, the two
    structures themselves line up — or the whole of a unit that is one group (`groups`: base,
    sub; `Relation.whole`). `facing` gives `sub` as turned on a side (see `_facing`)."""
    ws = cell.workspace
    extent = np.array([ws.x_max - ws.x_min, ws.y_max - ws.y_min])
    gap = cell.design.structure_gap if gap is None else gap
    along_y = all(p.half[1] >= 2 * p.half[0] for p in (base, sub))
    for name in [side] if side else (["back", "left"] if along_y else ["left", "back"]):
        sub = facing(name) if facing else sub
        d, sign = _SIDES[name]
        dxy = np.zeros(2)
        dxy[d] = sign * (base.half[d] + sub.half[d] + gap)
        # "a tower in front of the pyramid, a row to the left of the tower": the tower stands
        # before the pyramid, not the middle of the tower and row; "a row in front of them both":
        # before the middle of the two
        base_at, sub_at = (
            np.zeros(2) if grouped else p.origin
            for p, grouped in zip((base, sub), groups, strict=True)
        )
        dxy[1 - d] = base_at[1 - d] - sub_at[1 - d]
        unit = _merge(base, sub, dxy, 0.0)
        if side or bool(np.all(2 * unit.half <= extent + 1e-9)):
            return unit
    return unit


def _at_anchors(
    base: _Placed,
    sub: _Placed,
    kind: str,
    at: str,
    cell: CellConfig,
    gap: float | None = None,
    facing: Callable[[str], _Placed] | None = None,
) -> _Placed:
    """One copy of `sub` at each corner or end of `base`: on its top face (``on_top_of``)
    or against its two ends (or all four sides) on the ground, `gap` away (``next_to``;
    touching by default; `facing` turns the copy on each side to face `base`). A square
    base's ends are its left and right sides."""
    sub_bottom = float((sub.z - np.array([d[2] for d in sub.sizes]) / 2).min())
    if kind == "on_top_of":
        top, _, _ = _top(base)
        high = base.z + np.array([d[2] for d in base.sizes]) / 2 > top - 1e-6
        half = _footprint_half(base.yaws, base.sizes)[high]
        lo, hi = (base.xy[high] - half).min(axis=0), (base.xy[high] + half).max(axis=0)
        centre, room = (lo + hi) / 2, (hi - lo) / 2 - sub.half  # where a copy's centre may go
        long = int(np.argmax(hi - lo))
        if at == "bend":  # the corner of an L where its two arms meet
            offsets = [_bend(base.xy[high], cell.cube[0], base.spec.shape) - centre]
        elif at.startswith("corner") or at.endswith(" corner"):
            if np.any(room < sub.half - 1e-9):  # two copies side by side would touch
                raise InfeasibleError(
                    f"on each corner: the {base.spec.shape}'s top face is too small for four "
                    f"{sub.spec.shape}s apart; make it larger",
                    parameter="length",
                )
            offsets = [np.array([sx * room[0], sy * room[1]]) for sx in (-1, 1) for sy in (-1, 1)]
            if " " in at:  # "back left corner": that one (back = +x, left = +y)
                fb, lr = at.split()[:2]
                offsets = [np.array([(1 if fb == "back" else -1) * room[0],
                                     (1 if lr == "left" else -1) * room[1]])]  # fmt: skip
        else:
            if room[long] < sub.half[long] - 1e-9:
                raise InfeasibleError(
                    f"on each end: the {base.spec.shape} is too short for two "
                    f"{sub.spec.shape}s apart; make it longer",
                    parameter="length",
                )
            offsets = [s * room[long] * np.eye(2)[long] for s in (-1.0, 1.0)]
            if " " in at:  # "left end": that end of the long side (left = +y, back = +x)
                offsets = offsets[1:] if at.split()[0] in ("left", "back") else offsets[:1]
        anchors, dz = [centre + off for off in offsets], top - sub_bottom
        copies = [sub] * len(anchors)  # on a top, every copy as said
    else:
        long = 1 if base.half[1] >= base.half[0] - 1e-9 else 0
        axes = (0, 1) if at == "sides" else (long,)
        base_bottom = float((base.z - np.array([d[2] for d in base.sizes]) / 2).min())
        sides = [(d, s) for d in axes for s in (-1.0, 1.0)]
        copies = [(facing or (lambda _: sub))(_SIDE_OF[side]) for side in sides]
        anchors = [
            s * (base.half[d] + copy.half[d] + (gap or 0.0)) * np.eye(2)[d]
            for (d, s), copy in zip(sides, copies, strict=True)
        ]
        dz = base_bottom - sub_bottom
    if not at.endswith("s"):  # "on one corner", "at one end": the first of them
        anchors = anchors[:1]
    shift = np.zeros(2)  # `_merge` re-centres the unit: anchors move with it
    for n, anchor in enumerate(anchors):
        merged = _merge(base, copies[n], anchor - shift, dz)
        shift = shift + (base.xy[0] - merged.xy[0])
        base = merged
    return base


def _bend(xy: np.ndarray, step: float, shape: str) -> np.ndarray:
    """The one part of a top face (part centres `xy`) with a neighbour along x and along y
    and no more: where an L's two arms meet."""
    near = np.abs(xy[:, None, :] - xy[None, :, :])
    along = [
        (np.abs(near[..., axis] - step) < 1e-6) & (near[..., 1 - axis] < 1e-6) for axis in (0, 1)
    ]
    bends = [k for k in range(len(xy)) if along[0][k].sum() == 1 and along[1][k].sum() == 1]
    if len(bends) != 1:
        raise InfeasibleError(
            f"at its corner: the {shape}'s top has {len(bends)} corners where two arms meet, "
            "not one; say which corner",
            parameter="relations",
        )
    return np.asarray(xy[bends[0]], dtype=float)


def _related(spec: Spec, placed: list[_Placed], cell: CellConfig) -> list[_Placed]:
    """The units `_relate` makes, each checked to fit the workspace."""
    units = _relate(spec, list(placed), cell)
    for p in units:
        try:
            _check_fits(p, cell)
        except InfeasibleError as exc:
            raise InfeasibleError(
                f"{exc} — counting the structures related to it", parameter=exc.parameter
            ) from None
    return units


def _relate(spec: Spec, placed: list[_Placed | None], cell: CellConfig) -> list[_Placed]:
    """Fold related structures into units: a subject joins its object's unit.

    Returns the units to place, one per structure that is no relation's subject, in order.
    """
    subject_of = {r.subject: r for r in spec.relations}
    children: dict[int, list[int]] = {}
    for r in spec.relations:
        children.setdefault(r.object, []).append(r.subject)
    units: dict[int, _Placed] = {}

    grouped = {r.object for r in spec.relations if r.whole}  # units that are one group

    def ordered(k: int) -> list[int]:
        # on the object's own top first: "a tower in front of a wall, a row on top of the
        # wall" stands on the wall, not on the taller tower merged beside it
        return sorted(children.get(k, []), key=lambda c: subject_of[c].kind != "on_top_of")

    def attach(base: _Placed, c: int) -> _Placed:
        rel = subject_of[c]
        if rel.kind == "around":
            sub_spec = _ring_for(spec.structures[c], base, cell)
            sizes = part_sizes(cell, sub_spec.part)
            sub = _orient(sub_spec, generate(sub_spec, sizes), sizes)
            inside = sub.half - cell.cube[0]  # the ring's walls are one part thick
            if np.any(inside < base.half + 1e-9):  # no room between them: no inside
                raise InfeasibleError(
                    f"around: the {sub_spec.shape}'s inside is smaller than the "
                    f"{base.spec.shape} it should enclose; make the ring at least "
                    f"{round(2 * float(base.half.max()) / cell.cube[0]) + 3} parts on a side",
                    parameter="length",
                )
            base = _merge(base, sub, np.zeros(2), 0.0)
            for cc in ordered(c):  # "a ring around a tower, and a row in front of the ring"
                if subject_of[cc].kind == "on_top_of":
                    raise InfeasibleError(
                        "on top of a ring around another structure: SDI cannot stand a "
                        "structure on a ring that encloses another; place it beside",
                        parameter="relations",
                    )
                base = attach(base, cc)  # the ring is the unit's outside: beside it is beside that
            return base
        # a staircase beside another stands parallel to it ("a second staircase next to it")
        alike = spec.structures[rel.object].shape == spec.structures[c].shape
        facing = _facing(spec.structures[c], cell) if c not in children and not alike else None
        if rel.at is not None:
            return _at_anchors(base, unit(c), rel.kind, rel.at, cell, rel.gap_m, facing)
        sub = unit(c)
        if rel.kind == "on_top_of":
            top, centre, top_half = _top(base)
            if c not in children:
                sub = units[c] = _along_top(sub, top_half, cell, rel.side)
            if rel.side is not None:  # "a wall on the slab, along its back edge": flush with it
                axis, sign = _SIDES[rel.side]
                centre = centre.copy()
                centre[axis] += sign * (top_half[axis] - sub.half[axis])
            bottom = float((sub.z - np.array([d[2] for d in sub.sizes]) / 2).min())
            return _merge(base, sub, centre, top - bottom)
        return _beside(
            base, sub, rel.side, cell, rel.gap_m, (rel.object in grouped, c in grouped), facing
        )

    def unit(k: int) -> _Placed:
        if k in units:
            return units[k]
        base = placed[k]
        assert base is not None
        for c in ordered(k):
            base = attach(base, c)
        units[k] = base
        return base

    return [unit(k) for k in range(len(placed)) if k not in subject_of]


def compose(spec: Spec, cell: CellConfig | None = None) -> Layout:
    """Generate and place every structure of `spec`; no verification (see `design`).

    Related structures (`spec.relations`) are built as one unit first: a structure on top of
    another stands centred on its highest parts, a ring around another is sized to enclose
    it, a structure next to another stands one structure gap away on the stated side.
    """
    cell = cell or CellConfig()
    placed: list[_Placed] = []
    generated: list[tuple[list[Box], Sizes]] = []
    total = 0
    for s in spec.structures:
        sizes = part_sizes(cell, s.part)
        boxes = generate(s, sizes)
        if len(boxes) > MAX_PARTS_PER_STRUCTURE:
            raise LimitError(
                f"a {s.shape} of {len(boxes)} parts exceeds "
                f"{MAX_PARTS_PER_STRUCTURE} per structure",
                field="structures",
            )
        total += len(boxes)
        if total > cell.limits.max_parts:
            raise LimitError(
                f"{total} parts exceed limits.max_parts = {cell.limits.max_parts}",
                field="structures",
            )
        p = _orient(s, boxes, sizes)
        try:
            _check_fits(p, cell)
        except InfeasibleError as exc:
            # An unstated axis is ours to choose: turn the structure if that makes it fit.
            if s.axis is not None or exc.parameter not in ("length", "width"):
                raise
            turned = s.model_copy(update={"axis": "x"})
            p = _orient(turned, boxes, sizes)
            try:
                _check_fits(p, cell)
            except InfeasibleError:
                raise exc from None
        placed.append(p)
        generated.append((boxes, sizes))
    if spec.relations:
        try:
            placed = _related(spec, placed, cell)
        except InfeasibleError as exc:
            # "a row of 5 with a tower on each side": too long across the table with the ones
            # beside it; turned along x if no structure's axis was said
            if any(s.axis is not None for s in spec.structures) or exc.parameter not in (
                "length",
                "width",
            ):
                raise
            along_x = [
                _orient(s.model_copy(update={"axis": "x"}), boxes, sizes)
                for s, (boxes, sizes) in zip(spec.structures, generated, strict=True)
            ]
            try:
                placed = _related(spec, along_x, cell)
            except InfeasibleError:
                raise exc from None
    centres = _place_all(placed, cell, spec.gap_m, spec.line, spec.grid)
    parts: list[Part] = []
    counters: dict[str, int] = {}
    for p, centre in zip(placed, centres, strict=True):
        mine: list[Part] = []
        for (dx, dy), z, size, yaw, kind in zip(p.xy, p.z, p.sizes, p.yaws, p.kinds, strict=True):
            counters[kind] = counters.get(kind, 0) + 1
            prefix = "c" if kind == "cube" else kind[0]
            mine.append(
                Part(
                    id=f"{prefix}{counters[kind]}",
                    position=(round(centre[0] + dx, 6), round(centre[1] + dy, 6), round(z, 6)),
                    # a cube turned by a multiple of 90° is the same box: keep it axis-aligned
                    orientation=quat_from_yaw(0.0 if kind == "cube" and _square(yaw) else yaw),
                    size=size,
                )
            )
        if not _square(math.radians(p.spec.yaw_deg)) and len(mine) > 1:
            graph = ContactGraph(Layout(objects=tuple(mine)), cell.tolerances.contact, 0.0)
            if graph.colliding.any():
                raise InfeasibleError(
                    f"yaw_deg: turned by {p.spec.yaw_deg:g}°, the bounding boxes of neighbouring "
                    f"parts of the {p.spec.shape} overlap (the verifier uses axis-aligned boxes); "
                    "use a multiple of 90°",
                    parameter="yaw_deg",
                )
        parts.extend(mine)
    return Layout(objects=tuple(parts))


def _square(yaw_rad: float) -> bool:
    """`yaw_rad` is a multiple of 90°."""
    quarter = yaw_rad / (math.pi / 2)
    return abs(quarter - round(quarter)) < 1e-9


def design(spec: Spec, cell: CellConfig | None = None) -> tuple[Layout, Report]:
    """`compose`, then verify: the layout and its passing report, or `InfeasibleError`."""
    cell = cell or CellConfig()
    layout = compose(spec, cell)
    report = verify(layout, cell, precedence=spec.precedence)
    if not report.passed:
        first = report.violations[0]
        raise InfeasibleError(
            f"the generated layout breaks {len(report.violations)} constraint(s), first "
            f"{first.constraint.value}: {first.message}",
            parameter=None,
        )
    return layout, report
