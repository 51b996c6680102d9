"""ξ_reshape: when a structure cannot stay as commanded under a height limit, rebuild it as the
shape that keeps most of the command — the same family split into lower structures beside each
other, the same family lower, a wall instead of a tower — ranked by how much of the command
survives, and only then the geometric `flatten`.

A candidate's *survival* is a number in [0, 1]: half of it for the parts kept (the count in a
command is explicit), three tenths for keeping the shape family, two tenths for the height kept.
Each candidate is composed by the generators, shifted clear of the blocked regions if it must be
(`shift_search`), and verified; the best one that passes wins. A reshaped structure is a changed
*shape*: the orchestrator shows it to the operator for approval instead of executing it unattended.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from sdi.design.composer import compose
from sdi.errors import InfeasibleError, SDIError
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.region import Region
from sdi.recovery.flatten import flatten
from sdi.recovery.shift import default_margin, shift_search
from sdi.spec.structure_spec import Spec, StructureSpec, structure

PARTS, FAMILY, HEIGHT = 0.5, 0.3, 0.2
"""Weights of the survival score: parts kept, shape family kept, height kept."""


@dataclass(frozen=True)
class Reshaped:
    """A reshape's outcome: the layout, what it was and what it is now, and the survival score."""

    layout: Layout
    before: str  # e.g. "tower of 4 parts, 4 levels"
    after: str  # e.g. "2 towers of 2 levels beside each other (4 parts)"
    survival: float
    parts_before: int
    parts_after: int
    moved: str | None = None  # how it was then moved clear of the blocked regions, if it was

    def describe(self) -> str:
        text = (
            f"flattened from {self.before} → {self.after} "
            f"({round(100 * self.survival)} % of the command kept)"
        )
        return f"{text}, then {self.moved}" if self.moved else text


def _levels_of(s: StructureSpec) -> int | None:
    height: int | None = getattr(s, "height", None)
    if s.shape == "tower":
        return height or getattr(s, "count", None)
    if s.shape == "staircase":
        return getattr(s, "steps", None)
    return height


def _with(s: StructureSpec, **update: Any) -> StructureSpec:
    """`s` with slots changed (None: unset), validated as the family it then is."""
    data = {**s.model_dump(exclude_none=True), **update}
    shape = data.pop("shape")
    return structure(shape, **{k: v for k, v in data.items() if v is not None})


def _name(s: StructureSpec) -> str:
    dims = [f"{k} {v}" for k in ("count", "length", "width", "height", "steps") if
            (v := getattr(s, k, None)) is not None]  # fmt: skip
    return f"{s.shape} ({', '.join(dims)})" if dims else s.shape


def _candidates(s: StructureSpec, levels: int) -> list[tuple[list[StructureSpec], str, bool]]:
    """(structures, description, same family) that replace `s` with at most `levels` levels."""
    n = _levels_of(s)
    if n is None or n <= levels:
        return []
    base = _with(s, count=None, height_m=None)
    out: list[tuple[list[StructureSpec], str, bool]] = []
    if s.shape == "tower":
        k = math.ceil(n / levels)
        heights = [n // k + (1 if i < n % k else 0) for i in range(k)]
        towers = [_with(base, height=h) for h in heights]
        for i, t in enumerate(towers[1:], start=1):  # beside the first, one structure gap apart
            towers[i] = _with(t, at_x=None, at_y=None, region=None)
        out.append((towers, f"{k} towers of {'+'.join(map(str, heights))} levels beside each "
                            f"other ({n} parts)", True))  # fmt: skip
        out.append(([_with(base, height=levels)], f"a tower of {levels} levels "
                    f"({levels} parts)", True))  # fmt: skip
        if n % k == 0:
            wall = _with(base, shape="wall", length=k, height=n // k)
            out.append(([wall], f"a wall {k} long and {n // k} high ({n} parts)", False))
    elif s.shape == "wall" and s.length:
        length = math.ceil(s.length * n / levels)
        out.append(([_with(base, length=length, height=levels)],
                    f"a wall {length} long and {levels} high", True))  # fmt: skip
        out.append(([_with(base, height=levels)],
                    f"a wall {s.length} long and {levels} high", True))  # fmt: skip
    elif s.shape == "staircase":
        out.append(([_with(base, steps=levels)],
                    f"a staircase of {levels} steps", True))  # fmt: skip
    elif "height" in type(s).model_fields:
        out.append(([_with(base, height=levels)],
                    f"a {s.shape} {levels} levels high", True))  # fmt: skip
    return out


def reshape(
    spec: Spec | None,
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    z_max: float,
    blocked: tuple[Region, ...] = (),
) -> Reshaped:
    """The best-surviving verified shape under `z_max` m, else the geometric `flatten`.

    Raises `InfeasibleError` if nothing fits, or if the layout is under the limit already (a
    flattening that changes nothing would run the failed layout again)."""
    cell = cell or CellConfig()
    h, eps = cell.cube[2], cell.tolerances.contact
    tops = layout.centres[:, 2] + layout.half_extents[:, 2] if len(layout) else None
    if tops is None or float(tops.max()) <= z_max + eps:
        raise InfeasibleError(
            f"z_max: the structure is {0 if tops is None else float(tops.max()):.3f} m high, "
            f"already under {z_max:g} m; flattening it would run the same layout again",
            parameter="z_max",
        )
    levels = int((z_max + eps) // h)
    if levels < 1:
        raise InfeasibleError(
            f"z_max: {z_max:g} m is lower than one part ({h:g} m)", parameter="z_max"
        )
    n_before = len(layout)
    options: list[tuple[float, Layout, str, str]] = []
    if spec is not None and len(spec.structures) == 1:  # one structure: its family is known
        s = spec.structures[0]
        height_before = _levels_of(s) or 1
        for structures, text, same in _candidates(s, levels):
            try:
                candidate = compose(Spec(structures=tuple(structures)), cell)
            except SDIError:
                continue
            kept = min(len(candidate), n_before) / max(len(candidate), n_before)
            tall = max(round(float(p.top) / h) for p in candidate) / height_before
            score = PARTS * kept + FAMILY * same + HEIGHT * min(1.0, tall)
            options.append((score, candidate, _name(s), text))
    try:  # the geometric flatten: every part kept, the shape is no longer a family's
        flat = flatten(layout, cell, z_max=z_max, blocked=blocked)
        tall = max(round(float(p.top) / h) for p in flat) / max(1, round(float(tops.max()) / h))
        options.append((PARTS + HEIGHT * min(1.0, tall), flat, f"{n_before} parts up to "
                        f"{float(tops.max()):.3f} m", f"the same {n_before} parts re-stacked "
                        f"beside, under {z_max:g} m"))  # fmt: skip
    except InfeasibleError:
        pass
    options.sort(key=lambda o: -o[0])
    margin = default_margin(cell)
    for score, candidate, before, after in options:
        cleared = _clear(candidate, cell, blocked, margin)
        if cleared is None:
            continue
        placed, moved = cleared
        if max(p.top for p in placed) > z_max + eps or not verify(placed, cell).passed:
            continue
        return Reshaped(placed, before, after, round(score, 3), n_before, len(placed), moved)
    raise InfeasibleError(
        f"z_max: no shape of the command fits under {z_max:g} m clear of the blocked regions; "
        "allow a higher limit or a smaller structure",
        parameter="z_max",
    )


def _clear(
    layout: Layout, cell: CellConfig, blocked: tuple[Region, ...], margin: float
) -> tuple[Layout, str | None] | None:
    """The layout itself if it keeps `margin` clear of `blocked`, else shifted clear (with how
    it was moved), else None."""
    try:
        shifted = shift_search(layout, cell, blocked=blocked, margin=margin)
    except InfeasibleError as exc:
        return (layout, None) if exc.parameter == "layout" else None
    return shifted.layout, shifted.describe()
