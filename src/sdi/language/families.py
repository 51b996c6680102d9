"""The family registry: which slots each structure family uses, and what a value it cannot use
becomes.

Each family's spec type (`sdi.spec.structure_spec`, e.g. `GridSpec`) declares the slots its
generator in `sdi.design.shapes` reads; the registry takes them from there. The phrase
grammar fills a flat `StructureDraft`, which may hold a value its family has no slot for;
`check_family` turns such a value into the family that can hold it (a grid two high is a
block), derives a slot from the others where the words imply it (eighteen cubes in a block
three by three are two layers), or reports it in the notes — never drops it silently — and
returns the family's spec.
"""

from __future__ import annotations

from dataclasses import dataclass

from pydantic import ValidationError

from sdi.errors import SpecError
from sdi.spec.structure_spec import (
    STRUCTURE_TYPES,
    AnyStructure,
    StructureDraft,
    StructureSpec,
    family_slots,
)

COMMON = frozenset({"shape", "axis", "yaw_deg", "at_x", "at_y", "region", "edge", "part"})


@dataclass(frozen=True)
class Family:
    """One structure family: its spec type and its slots (the fields of that type its
    generator reads, besides the placement common to all)."""

    name: str
    spec_type: type[AnyStructure]
    slots: frozenset[str]
    summary: str


FAMILIES: dict[str, Family] = {
    name: Family(name, t, frozenset(family_slots(t)), (t.__doc__ or name).strip().rstrip("."))
    for name, t in STRUCTURE_TYPES.items()
}


# Values a family has without a slot for them ("a row one high", "a grid one layer thick").
IMPLIED = {"height": 1, "width": 1, "count": 1}


def unused_slots(spec: StructureDraft) -> dict[str, object]:
    """Fields set on `spec` that its family's generator does not read (and that differ
    from what the family is anyway: a row is one part high)."""
    family = FAMILIES[spec.shape]
    values = spec.model_dump(exclude_none=True, exclude_defaults=True)
    return {
        k: v
        for k, v in values.items()
        if k not in family.slots and k not in COMMON and IMPLIED.get(k) != v
    }


def check_family(
    spec: StructureDraft, notes: list[str], material: list[str], *, part_m: float = 0.05
) -> StructureSpec:
    """The family spec of draft `spec`, with every value placed where its family uses it, or
    reported in `notes` (and, when it changes what is built, in `material`). `part_m` is the
    edge of the cell's cube, m: sizes in metres are compared with it."""
    flat = spec.shape in ("grid",)
    one_layer = spec.height_m is not None and round(spec.height_m / part_m) <= 1
    if flat and one_layer:  # "a slab 5 cm thick": one layer, which a grid is
        notes.append(f"a grid {spec.height_m:g} m thick is one layer of parts")
        spec = spec.model_copy(update={"height_m": None})
    elif flat and ((spec.height or 1) > 1 or spec.height_m is not None):
        high = spec.height or (f"{spec.height_m:g} m" if spec.height_m else "")
        notes.append(f"a grid {high} high is a solid block: built a block".replace("  ", " "))
        spec = spec.model_copy(update={"shape": "block", "gap_m": None})
        if spec.count is not None and spec.length is None:
            spec = spec.model_copy(update={"count": None})
    if spec.shape == "block" and spec.count is not None:
        spec = _block_from_count(spec, notes, material)
    one_deep = spec.shape in ("row", "wall") and spec.length is None and spec.length_m is None
    if one_deep and spec.width_m is not None and round(spec.width_m / part_m) > 1:
        # "a wall 40 cm wide, 2 high": a wall one part deep is as wide as it is long
        notes.append(f"read the {spec.shape}'s width {spec.width_m:g} m as its length")
        spec = spec.model_copy(update={"length_m": spec.width_m, "width_m": None})
    if (
        spec.shape in ("row", "wall")
        and spec.width is not None
        and spec.width > 1
        and (spec.length == 1)
    ):
        # "3 wide, 1 deep - wall": one part deep, so as long as it is wide, across the robot
        notes.append(f"read the {spec.shape} {spec.width} wide and 1 deep as {spec.width} long")
        spec = spec.model_copy(update={"length": spec.width, "width": None, "axis": "y"})
    if spec.shape in ("row", "wall") and spec.width is not None and spec.width > 1:
        wide = "grid" if spec.shape == "row" and (spec.height or 1) == 1 else "block"
        notes.append(f"a {spec.shape} {spec.width} wide is a {wide}: built a {wide}")
        spec = spec.model_copy(update={"shape": wide, "gap_m": None, "count": None})
        if wide == "grid":
            spec = spec.model_copy(update={"height": None})
    thin = (spec.width == 1) or (spec.width_m is not None and round(spec.width_m / part_m) == 1)
    if spec.shape in ("row", "wall") and thin and (spec.length or spec.length_m):
        # "a wall 350 mm long, 50 mm thick": one part thick, as a row or wall is
        notes.append(f"'{spec.width_m:g} m thick': one part, as a {spec.shape} is" if spec.width_m
                     else f"'1 wide': one part, as a {spec.shape} is")  # fmt: skip
        spec = spec.model_copy(update={"width": None, "width_m": None})
    if spec.shape == "row" and spec.height is not None and spec.height > 1:
        notes.append(f"a row {spec.height} high is a wall: built a wall")
        spec = spec.model_copy(update={"shape": "wall", "gap_m": None})
    if (
        spec.shape in ("cross", "pyramid")
        and spec.width is not None
        and spec.width == (spec.length or spec.width)
    ):
        spec = spec.model_copy(update={"width": None, "length": spec.length or spec.width})
    spec = _derive(spec, notes, material, part_m)
    spec = _metres_and_parts(spec, notes, material, part_m)
    implied = {
        k: None
        for k, v in spec.model_dump(exclude_none=True).items()
        if k not in FAMILIES[spec.shape].slots and k not in COMMON and IMPLIED.get(k) == v
    }
    if implied:
        spec = spec.model_copy(update=implied)
    left = unused_slots(spec)
    apart = any(n.endswith("as a part's width apart") for n in notes)
    if "gap_m" in left and (spec.shape == "tower" or apart):
        # "two towers that do not touch": separate structures stand apart anyway
        notes.append(f"separate structures stand apart: no gap to set inside a {spec.shape}")
        spec = spec.model_copy(update={"gap_m": None})
        left.pop("gap_m")
    if left:
        values = ", ".join(f"{k}={v}" for k, v in left.items())
        notes.append(f"ignored {values}: a {spec.shape} has no such parameter")
        material.extend(f"{k}={v}" for k, v in left.items())
        spec = spec.model_copy(update=dict.fromkeys(left))
    try:
        return FAMILIES[spec.shape].spec_type.model_validate(
            spec.model_dump(exclude_none=True, exclude_defaults=True) | {"shape": spec.shape}
        )
    except ValidationError as exc:  # "a 0.4 grid": a size no structure can have
        first = exc.errors()[0]
        where = ".".join(str(x) for x in first["loc"])
        raise SpecError(
            f"{spec.shape}: {where} {first['msg'].lower()} (got {first.get('input')!r}); "
            "give a whole number of parts, e.g. 'a 3 by 3 grid'",
            understood={"structures": [spec.shape]},
        ) from None


def _derive(
    spec: StructureDraft, notes: list[str], material: list[str], part_m: float
) -> StructureDraft:
    """Slots the words imply for a family: one side of a square family, a pyramid's base
    given as its width, a grid's missing side from its count, a table top's size, a bridge's
    length as the gap between its pillars."""
    square = ("grid", "block", "enclosure", "castle")
    one_side = spec.shape in square and spec.length is None and spec.width is None
    if one_side and spec.width_m is not None and spec.length_m is None:
        spec = spec.model_copy(update={"length_m": spec.width_m})
    if one_side and spec.length_m is not None and spec.width_m is None:
        spec = spec.model_copy(update={"width_m": spec.length_m})
    if spec.shape in ("bridge", "arch", "canopy") and spec.gap_m is not None:
        # "a bridge over a gap of one cube": the gap between pillars is the span
        span = max(1, round(spec.gap_m / part_m))
        spec = spec.model_copy(update={"span": spec.span or span, "gap_m": None})
    long = spec.length or (round(spec.length_m / part_m) if spec.length_m else None)
    if spec.shape == "bridge" and long and spec.span is None:
        # "a bridge 4 cubes long": over its pillars' outer faces, `spans` gaps of one size
        spans = spec.spans or 1
        span = max(1, (long - 1) // spans - 1)
        built = spans * (span + 1) + 1
        if built != long:
            material.append(f"{long} long")
            notes.append(f"a bridge {long} parts long cannot have {spans} equal gap(s) between "
                         f"one-part pillars: gaps of {span}, {built} long")  # fmt: skip
        else:
            notes.append(f"a bridge {long} parts long: pillars {span} apart")
        spec = spec.model_copy(update={"span": span, "length": None, "length_m": None})
    if spec.shape == "pyramid" and spec.width is not None and spec.length is None:
        spec = spec.model_copy(update={"length": spec.width, "width": None})
    if spec.shape == "grid" and spec.count is not None:
        sides = [s for s in (spec.length, spec.width) if s]
        if len(sides) == 1 and spec.count % sides[0] == 0:
            other = spec.count // sides[0]
            key = "width" if spec.width is None else "length"
            notes.append(f"{spec.count} parts in rows of {sides[0]}: {key} {other}")
            spec = spec.model_copy(update={key: other, "count": None})
    # unsaid, a wall is 2 high (`sdi.design.shapes.wall`)
    levels, count = spec.height or (2 if spec.height_m is None else 0), spec.count or 0
    if spec.shape == "wall" and count and levels > 1 and not (spec.length or spec.length_m):
        high = f"{levels} high" if spec.height else f"{levels} high (SDI's height for a wall)"
        if count % levels:  # "a wall of 5 cubes, 2 high": 5 cannot fill 2 levels
            notes.append(f"read {count} cubes as the wall's length ({count} cannot "
                         f"fill {levels} levels): {count} long, {high}")  # fmt: skip
            spec = spec.model_copy(update={"length": count, "count": None})
        elif count // levels <= levels:  # "a wall of four cubes, two high": no 2 by 2 block
            notes.append(f"read {count} cubes as the wall's length (all in {levels} levels "
                         f"it would be no longer than high): {count} long, {high}")  # fmt: skip
            spec = spec.model_copy(update={"length": count, "count": None})
        else:  # "a wall of 6 cubes, 3 high": one reading of two, said
            notes.append(f"read {count} cubes as all the wall's parts: "
                         f"{count // levels} long, {high} (say "
                         f"'{count} long' for a wall that long)")  # fmt: skip
    if spec.shape == "canopy" and spec.span is None and (spec.length or spec.width):
        side = max(spec.length or 0, spec.width or 0)
        if side >= 3:
            notes.append(f"a table top {side} parts across: legs {side - 2} apart")
            spec = spec.model_copy(update={"span": side - 2, "length": None, "width": None})
        if side >= 4:  # the top is its beams, which span the legs' centres, not their faces
            notes.append(f"the table's top is its beams, {side - 1} parts across over the legs' "
                         f"centres; the legs stand {side} parts across outside")  # fmt: skip
    return spec


def _metres_and_parts(
    spec: StructureDraft, notes: list[str], material: list[str], part_m: float
) -> StructureDraft:
    """A size given both in parts and in metres must agree; metres that are no whole number
    of parts are rounded, and said so."""
    for key in ("length", "width", "height"):
        parts, metres = getattr(spec, key), getattr(spec, f"{key}_m")
        if metres is None:
            continue
        whole = round(metres / part_m)
        if parts is not None and parts != whole:
            notes.append(
                f"ignored {key} {parts}: the command also says {metres:g} m ({whole} parts)"
            )
            material.append(f"{key}={parts}")
            spec = spec.model_copy(update={key: None})
        elif abs(metres / part_m - whole) > 0.05 and whole >= 1:
            notes.append(
                f"{metres:g} m is {metres / part_m:.1f} parts of {part_m:g} m: built {whole} "
                f"({whole * part_m:g} m)"
            )
    return spec


def _block_from_count(
    spec: StructureDraft, notes: list[str], material: list[str]
) -> StructureDraft:
    count = spec.count or 0
    length, w, h = spec.length, spec.width, spec.height
    known = [v for v in (length, w, h) if v]
    if len(known) == 3 and length and w and count % (length * w) == 0 and h == 1:
        spec = spec.model_copy(update={"height": count // (length * w)})
        notes.append(f"{count} parts in a {length} by {w} block: height {count // (length * w)}")
        return spec.model_copy(update={"count": None})
    if len(known) == 3 and (length or 1) * (w or 1) * (h or 1) == count:
        return spec.model_copy(update={"count": None})
    if len(known) == 2:
        area = known[0] * known[1]
        if count % area == 0:
            third = count // area
            key = "height" if h is None else ("width" if w is None else "length")
            notes.append(f"{count} parts in a block: {key} {third}")
            return spec.model_copy(update={key: third, "count": None})
    if count == 1 and len(known) == 3 and length == w == h:
        # "a cube 10 cm on every side": the name of an equal-sided block, not a count
        notes.append("read 'a cube' with its three sides as a block of that size")
        return spec.model_copy(update={"count": None})
    notes.append(f"ignored count={count}: a block's part count follows from its sides")
    material.append(f"count={count}")
    return spec.model_copy(update={"count": None})
