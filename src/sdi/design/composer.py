"""The parametric Designer: a `Spec` becomes a verified `Layout`.

Each structure is generated in its local frame, turned to its axis and yaw, and placed at its
stated position, its named region, or — for structures the command does not place — side by
side around the cell's anchor point, keeping `structure_gap` between footprints. Parameters the
workspace cannot hold are refused up front with the largest value that fits; the finished
layout must pass the verifier, or the Designer says which constraint it breaks.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sdi.design.shapes import FAMILIES, MAX_PARTS_PER_STRUCTURE, Box, Sizes
from sdi.errors import InfeasibleError, InputError, LimitError
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


def _sizes(cell: CellConfig, part: str) -> Sizes:
    if part not in cell.part_types:
        raise InputError(
            f"unknown part type {part!r}; the cell has {sorted(cell.part_types)}", field="part"
        )
    return Sizes(
        cell.part_types[part], cell.part_types.get("beam"), cell.tolerances.support_overlap
    )


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
    # Footprint of the rotated boxes: AABB half extents per box.
    half = np.array(
        [
            [abs(math.cos(a)) * d[0] / 2 + abs(math.sin(a)) * d[1] / 2,
             abs(math.sin(a)) * d[0] / 2 + abs(math.cos(a)) * d[1] / 2]
            for a, d in zip(yaws, dims, strict=True)
        ]
    ).reshape(-1, 2)  # fmt: skip
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


def _place_all(placed: list[_Placed], cell: CellConfig) -> list[np.ndarray]:
    anchor = np.array(cell.design.anchor)
    gap = cell.design.structure_gap
    ws = cell.workspace
    centres: list[np.ndarray | None] = [None] * len(placed)
    taken: list[tuple[np.ndarray, np.ndarray]] = []
    # Stated positions first, exactly where asked.
    for k, p in enumerate(placed):
        x, y = _target(p.spec, cell)
        if x is None and y is None:
            continue
        c = np.array([anchor[0] if x is None else x, anchor[1] if y is None else y])
        if not _inside(c, p.half, cell):
            field = (
                "at_x"
                if not (ws.x_min <= c[0] - p.half[0] and c[0] + p.half[0] <= ws.x_max)
                else "at_y"
            )
            d = 0 if field == "at_x" else 1
            lo = (ws.x_min, ws.y_min)[d] + p.half[d]
            hi = (ws.x_max, ws.y_max)[d] - p.half[d]
            raise InfeasibleError(
                f"{field}: {c[d]:g} m puts the {p.spec.shape} outside the workspace; "
                f"its centre {'xy'[d]} must lie in [{lo:.3f}, {hi:.3f}] m",
                parameter=field,
            )
        centres[k] = c
        taken.append((c, p.half))
    # The rest side by side along y around the anchor, then the nearest free spot.
    free = [k for k, c in enumerate(centres) if c is None]
    widths = [2 * placed[k].half[1] for k in free]
    total = sum(widths) + gap * max(0, len(free) - 1)
    y = anchor[1] - total / 2
    preferred = []
    for w in widths:
        preferred.append(np.array([anchor[0], y + w / 2]))
        y += w + gap
    step = cell.cube[0] / 2
    for k, want in zip(free, preferred, strict=True):
        p = placed[k]
        spot = None
        for r in range(0, 40):
            ring = [
                want + step * np.array([i, j])
                for i in range(-r, r + 1)
                for j in range(-r, r + 1)
                if max(abs(i), abs(j)) == r
            ]
            ring.sort(key=lambda c: (float(np.linalg.norm(c - want)), c[0], c[1]))
            for c in ring:
                if _inside(c, p.half, cell) and _clear(c, p.half, taken, gap):
                    spot = c
                    break
            if spot is not None:
                break
        if spot is None:
            raise InfeasibleError(
                f"structures: the {len(placed)} structures do not fit side by side in the "
                "workspace; make them smaller or fewer",
                parameter="structures",
            )
        centres[k] = spot
        taken.append((spot, p.half))
    return [c for c in centres if c is not None]


def compose(spec: Spec, cell: CellConfig | None = None) -> Layout:
    """Generate and place every structure of `spec`; no verification (see `design`)."""
    cell = cell or CellConfig()
    placed: list[_Placed] = []
    total = 0
    for s in spec.structures:
        sizes = _sizes(cell, s.part)
        boxes = FAMILIES[s.shape](s, sizes)
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
        _check_fits(p, cell)
        placed.append(p)
    centres = _place_all(placed, cell)
    parts: list[Part] = []
    counters: dict[str, int] = {}
    for p, centre in zip(placed, centres, strict=True):
        for (dx, dy), z, size, yaw, kind in zip(p.xy, p.z, p.sizes, p.yaws, p.kinds, strict=True):
            counters[kind] = counters.get(kind, 0) + 1
            prefix = "c" if kind == "cube" else kind[0]
            parts.append(
                Part(
                    id=f"{prefix}{counters[kind]}",
                    position=(round(centre[0] + dx, 6), round(centre[1] + dy, 6), round(z, 6)),
                    orientation=quat_from_yaw(0.0 if kind == "cube" else yaw),
                    size=size,
                )
            )
    return Layout(objects=tuple(parts))


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
