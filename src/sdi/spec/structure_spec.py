"""The structured specification l̂ that the Specifier produces and the Designer consumes.

One spec type per structure family, told apart by `shape` (a discriminated union,
`StructureSpec`): each family declares only the slots its generator reads, so a value a
family cannot use is refused when the spec is validated, with a message naming the field and
the family's slots. The language front end fills a flat `StructureDraft` first (the phrase
grammar cannot know the family's slots before it has read the whole phrase); the family
registry (`sdi.language.families.check_family`) turns a draft into its family's spec, moving
or reporting every value the family cannot hold.

JSON-Schema friendly so that an LLM can fill it under structured output. Counts are in
parts; the ``*_m`` fields give the same sizes in metres and win when both are set. Positions
are metres in the world frame; `region` names one of the cell's regions (left = +y, back =
+x).
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, TypeAlias

from pydantic import BaseModel, ConfigDict, Field, TypeAdapter, model_validator

Shape = Literal[
    "tower", "row", "grid", "wall", "block", "pyramid", "staircase", "bridge", "arch",
    "canopy", "enclosure", "l_shape", "u_shape", "t_shape", "castle", "pack", "cross",
]  # fmt: skip

SHAPES: tuple[str, ...] = Shape.__args__  # type: ignore[attr-defined]

Count = int | None
Side = Literal["left", "right", "front", "back"]

# The slots, one type each: a family declares the ones it uses (with its own description
# where the meaning is its own).
Parts = Annotated[Count, Field(ge=1, description="total parts")]
Length = Annotated[Count, Field(ge=1, description="parts along the main axis")]
Width = Annotated[Count, Field(ge=1, description="parts across the main axis")]
Height = Annotated[Count, Field(ge=1, description="levels (parts stacked)")]
Steps = Annotated[Count, Field(ge=1, description="staircase steps")]
Span = Annotated[Count, Field(ge=1, description="gap between supports, in parts")]
Spans = Annotated[Count, Field(ge=1, description="number of spans (bridge)")]
Dims = Annotated[Literal[2, 3] | None, Field(description="pyramid: 2-D (a face) or 3-D")]
LengthM = Annotated[float | None, Field(gt=0, description="size along the main axis, m")]
WidthM = Annotated[float | None, Field(gt=0, description="size across the main axis, m")]
HeightM = Annotated[float | None, Field(gt=0, description="height, m")]
GapM = Annotated[float | None, Field(ge=0, le=0.5, description="gap between neighbouring parts, m")]

# Every field, in the order `describe` lists them.
FIELDS: tuple[str, ...] = (
    "shape", "count", "length", "width", "height", "steps", "span", "spans", "dims",
    "length_m", "width_m", "height_m", "axis", "yaw_deg", "at_x", "at_y", "region", "edge",
    "at_face", "part", "gap_m",
)  # fmt: skip


class _Structure(BaseModel):
    """What every family has: where the structure stands and what it is built of."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    axis: Literal["x", "y"] | None = Field(None, description="main axis in the world frame")
    yaw_deg: float = Field(0.0, ge=-360, le=360, description="rotation about z, degrees")
    at_x: float | None = Field(None, description="footprint centre x, m")
    at_y: float | None = Field(None, description="footprint centre y, m")
    region: str | None = Field(None, description="named region of the cell (left, back right…)")
    edge: tuple[Side, ...] = Field(
        (), description="sides of the workspace it stands against (as far that way as it fits)"
    )
    at_face: tuple[Side, ...] = Field(
        (),
        description="faces of its footprint that at_x / at_y place, instead of its centre "
        "('front edge at x = 0.30 m': front on x, back on x, left and right on y)",
    )
    part: str = Field("cube", description="part type name from the cell configuration")

    @model_validator(mode="before")
    @classmethod
    def _only_its_slots(cls, data: Any) -> Any:
        if isinstance(data, dict):
            unknown = sorted(k for k in data if k not in cls.model_fields)
            if unknown:
                shape = data.get("shape", cls.__name__)
                raise ValueError(
                    f"a {shape} has no slot {', '.join(unknown)}; its slots are "
                    f"{', '.join(family_slots(cls))} (and the placement fields "
                    f"{', '.join(_Structure.model_fields)})"
                )
        return data

    def describe(self) -> str:
        """Short human summary, e.g. ``tower height=3 at (0.4, ·)``."""
        values = self.model_dump(exclude_none=True, exclude={"part", "yaw_deg", "edge", "at_face"})
        parts = [f"{k}={values[k]}" for k in FIELDS if k in values and k != "shape"]
        if self.yaw_deg:
            parts.append(f"yaw={self.yaw_deg:g}°")
        if self.edge:
            parts.append(f"edge={'+'.join(self.edge)}")
        if self.at_face:
            parts.append(f"at_face={'+'.join(self.at_face)}")
        if self.part != "cube":
            parts.append(f"part={self.part}")
        return " ".join([values["shape"], *parts])


class TowerSpec(_Structure):
    """One column of parts."""

    shape: Literal["tower"]
    count: Annotated[Count, Field(ge=1, description="parts in the column (as height)")] = None
    height: Height = None
    height_m: HeightM = None


class RowSpec(_Structure):
    """Parts in a line on the table."""

    shape: Literal["row"]
    count: Annotated[Count, Field(ge=1, description="parts in the line (as length)")] = None
    length: Length = None
    length_m: LengthM = None
    gap_m: GapM = None


class GridSpec(_Structure):
    """One layer of rows."""

    shape: Literal["grid"]
    count: Annotated[
        Count, Field(ge=1, description="parts, laid as a square when no side is given")
    ] = None
    length: Length = None
    width: Width = None
    length_m: LengthM = None
    width_m: WidthM = None
    gap_m: GapM = None


class WallSpec(_Structure):
    """A row stacked in levels."""

    shape: Literal["wall"]
    count: Annotated[Count, Field(ge=1, description="total parts when no length is given")] = None
    length: Length = None
    height: Height = None
    length_m: LengthM = None
    height_m: HeightM = None


class BlockSpec(_Structure):
    """A solid box of parts."""

    shape: Literal["block"]
    length: Length = None
    width: Width = None
    height: Height = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class PackSpec(_Structure):
    """A compact cluster of a given number of parts."""

    shape: Literal["pack"]
    count: Parts = None
    height: Height = None
    height_m: HeightM = None


class PyramidSpec(_Structure):
    """Levels shrinking upwards."""

    shape: Literal["pyramid"]
    length: Annotated[Count, Field(ge=1, description="parts along the bottom level")] = None
    width: Annotated[Count, Field(ge=1, description="bottom level across, when not square")] = None
    height: Height = None
    dims: Dims = None
    length_m: LengthM = None
    height_m: HeightM = None


class StaircaseSpec(_Structure):
    """Rising steps."""

    shape: Literal["staircase"]
    length: Annotated[Count, Field(ge=1, description="parts along each step")] = None
    width: Width = None
    height: Annotated[Count, Field(ge=1, description="levels each step rises")] = None
    steps: Steps = None
    width_m: WidthM = None
    height_m: HeightM = None


class BridgeSpec(_Structure):
    """Pillars carrying beams."""

    shape: Literal["bridge"]
    width: Width = None
    height: Annotated[Count, Field(ge=1, description="pillar levels")] = None
    span: Span = None
    spans: Spans = None
    width_m: WidthM = None
    height_m: HeightM = None


class ArchSpec(_Structure):
    """A corbelled arch."""

    shape: Literal["arch"]
    height: Annotated[Count, Field(ge=1, description="pillar levels")] = None
    span: Span = None
    width_m: WidthM = None
    height_m: HeightM = None


class CanopySpec(_Structure):
    """Four pillars with a roof."""

    shape: Literal["canopy"]
    height: Annotated[Count, Field(ge=1, description="pillar levels")] = None
    span: Span = None
    height_m: HeightM = None


class EnclosureSpec(_Structure):
    """A ring of walls."""

    shape: Literal["enclosure"]
    length: Length = None
    width: Width = None
    height: Height = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class CastleSpec(_Structure):
    """A ring of walls with a tower at each corner."""

    shape: Literal["castle"]
    count: Annotated[
        Count, Field(ge=1, description="levels the corner towers rise above the walls")
    ] = None
    length: Length = None
    width: Width = None
    height: Annotated[Count, Field(ge=1, description="levels of the walls")] = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class LShapeSpec(_Structure):
    """An L: a bar along the main axis and an arm across it."""

    shape: Literal["l_shape"]
    length: Length = None
    width: Width = None
    height: Height = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class UShapeSpec(_Structure):
    """A U: a base along the main axis and two arms across it."""

    shape: Literal["u_shape"]
    length: Length = None
    width: Width = None
    height: Height = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class TShapeSpec(_Structure):
    """A T: a bar along the main axis and a stem across it."""

    shape: Literal["t_shape"]
    length: Length = None
    width: Width = None
    height: Height = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None


class CrossSpec(_Structure):
    """A plus sign."""

    shape: Literal["cross"]
    length: Annotated[Count, Field(ge=1, description="parts along each bar")] = None
    height: Height = None
    length_m: LengthM = None
    height_m: HeightM = None


AnyStructure: TypeAlias = (
    TowerSpec | RowSpec | GridSpec | WallSpec | BlockSpec | PyramidSpec | StaircaseSpec
    | BridgeSpec | ArchSpec | CanopySpec | EnclosureSpec | LShapeSpec | UShapeSpec
    | TShapeSpec | CastleSpec | PackSpec | CrossSpec
)  # fmt: skip

# Any structure: one of the family types, chosen by `shape`.
StructureSpec: TypeAlias = Annotated[AnyStructure, Field(discriminator="shape")]

STRUCTURE_TYPES: dict[str, type[AnyStructure]] = {
    t.model_fields["shape"].annotation.__args__[0]: t for t in AnyStructure.__args__
}

_ADAPTER: TypeAdapter[StructureSpec] = TypeAdapter(StructureSpec)


def family_slots(family: type[BaseModel]) -> tuple[str, ...]:
    """The slots a family type declares (its fields besides `shape` and the placement)."""
    return tuple(k for k in FIELDS if k in family.model_fields and k not in _PLACEMENT)


def structure(shape: str, **values: Any) -> StructureSpec:
    """The spec of family `shape` with `values`; `ValueError` (pydantic's `ValidationError`)
    naming the field when the family has no such slot or a value is out of bounds."""
    return _ADAPTER.validate_python({"shape": shape, **values})


class StructureDraft(BaseModel):
    """A structure as the phrase grammar fills it, before the family check: every slot of
    every family, with the same bounds. `sdi.language.families.check_family` turns it into
    its family's `StructureSpec`."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    shape: Shape
    count: Parts = None
    length: Length = None
    width: Width = None
    height: Height = None
    steps: Steps = None
    span: Span = None
    spans: Spans = None
    dims: Dims = None
    length_m: LengthM = None
    width_m: WidthM = None
    height_m: HeightM = None
    axis: Literal["x", "y"] | None = Field(None, description="main axis in the world frame")
    yaw_deg: float = Field(0.0, ge=-360, le=360, description="rotation about z, degrees")
    at_x: float | None = Field(None, description="footprint centre x, m")
    at_y: float | None = Field(None, description="footprint centre y, m")
    region: str | None = Field(None, description="named region of the cell (left, back right…)")
    edge: tuple[Side, ...] = Field(
        (), description="sides of the workspace it stands against (as far that way as it fits)"
    )
    at_face: tuple[Side, ...] = Field(
        (),
        description="faces of its footprint that at_x / at_y place, instead of its centre "
        "('front edge at x = 0.30 m': front on x, back on x, left and right on y)",
    )
    part: str = Field("cube", description="part type name from the cell configuration")
    gap_m: GapM = None


_PLACEMENT = frozenset({"shape", *_Structure.model_fields})


class SpecDraft(BaseModel):
    """What one phrase of a command names, before the family check: drafts and notes."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    structures: tuple[StructureDraft, ...] = Field(min_length=1, max_length=50)
    notes: tuple[str, ...] = ()


RelationKind = Literal["on_top_of", "around", "next_to"]
Anchor = Literal[
    "corners", "ends", "corner", "end", "sides",
    "back left corner", "back right corner", "front left corner", "front right corner",
    "left end", "right end", "front end", "back end", "bend",
]  # fmt: skip
"""Where copies stand: every corner or end of the object's top (or beside its ends or sides);
one named corner or end; "bend": the corner of an L where its two arms meet."""


class Relation(BaseModel):
    """How one structure stands to another; indices into `Spec.structures`.

    ``on_top_of``: `subject` stands on the top face of `object`, centred on it, or with
    `side` flush with that edge of the top face ("a wall on the slab along its back edge"),
    centred along it. ``around``:
    `subject` (a ring) encloses `object`, sized to leave one part of room on every side.
    ``next_to``: `subject` stands beside `object` on `side` (left = +y, back = +x), one
    structure gap away. A structure is the subject of at most one relation.

    ``at`` makes the relation distributive — one copy of `subject` at each anchor: on the
    object's top face at its four ``corners`` or two ``ends`` (``on_top_of``), or against its
    two ``ends`` or all four ``sides`` on the ground (``next_to``: "a tower at both ends of the
    wall", "a tower on each of its four sides").
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    kind: RelationKind
    subject: int = Field(ge=0, description="index of the structure that is placed")
    object: int = Field(ge=0, description="index of the structure it is placed against")
    side: Side | None = Field(
        None,
        description="next_to: which side of the object; on_top_of: which edge of its top face "
        "the subject stands flush with (default: centred)",
    )
    at: Anchor | None = Field(
        None, description="one copy of the subject at each corner or end of the object"
    )
    gap_m: float | None = Field(
        None, ge=0, le=0.5, description="next_to: clear space between the two, m (0: touching)"
    )
    whole: bool | None = Field(
        None,
        description="next_to: one group with the object ('in front of them both', 'three towers "
        "together in front of the wall'): a structure beside the group is centred on all of it, "
        "else lined up with the structure it is beside",
    )

    @model_validator(mode="after")
    def _anchor(self) -> Relation:
        if self.at is not None and self.kind == "around":
            raise ValueError("at: a ring around a structure has no corners or ends to stand at")
        if self.at == "sides" and self.kind != "next_to":
            raise ValueError("at: copies on all four sides stand beside the structure")
        if self.at == "bend" and self.kind != "on_top_of":
            raise ValueError("at: 'bend' is the corner of an L's top where its arms meet")
        if self.at is not None and " " in self.at and self.kind != "on_top_of":
            raise ValueError(f"at: '{self.at}' names a corner of the structure's top face")
        if self.at is not None and self.side is not None:
            raise ValueError("at: copies at the corners or ends have no single side")
        if self.gap_m is not None and self.kind != "next_to":
            raise ValueError("gap_m: only a structure beside another has a gap to it")
        if self.whole is not None and self.kind != "next_to":
            raise ValueError("whole: only structures side by side make one group")
        return self

    def describe(self, names: list[str] | None = None) -> str:
        a = names[self.subject] if names else f"#{self.subject + 1}"
        b = names[self.object] if names else f"#{self.object + 1}"
        kind = self.kind.replace("_", " ")
        if self.at:
            return f"{a} {kind} {b} (one at each of its {self.at})"
        if self.kind == "next_to" and self.side:
            return f"{a} {kind} {b} ({self.side})"
        if self.kind == "on_top_of" and self.side:
            return f"{a} {kind} {b} (along its {self.side} edge)"
        return f"{a} {kind} {b}"


class Spec(BaseModel):
    """The whole command: one or more structures, placed side by side unless positioned or
    related to each other (`relations`)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    structures: tuple[StructureSpec, ...] = Field(min_length=1, max_length=50)
    relations: tuple[Relation, ...] = ()
    gap_m: float | None = Field(
        None, gt=0, le=0.5, description="clear space between separate structures, m"
    )
    line: Literal["x", "y"] | None = Field(
        None,
        description="separate structures stand one after another along this axis, in the "
        "order listed (x: front to back, y: right to left); default: side by side along y",
    )
    grid: tuple[int, int] | None = Field(
        None,
        description="separate structures stand in this many rows (front to back) by columns "
        "(right to left), in the order listed, the front row first; default: one line",
    )
    precedence: tuple[tuple[str, str], ...] = ()
    notes: tuple[str, ...] = Field((), description="assumptions the front end made")

    @model_validator(mode="after")
    def _relations_valid(self) -> Spec:
        n = len(self.structures)
        subjects: set[int] = set()
        for r in self.relations:
            if r.subject >= n or r.object >= n or r.subject == r.object:
                raise ValueError(
                    f"relation {r.kind}: structures {r.subject} and {r.object} must be two "
                    f"different indices below {n}"
                )
            if r.subject in subjects:
                raise ValueError(f"structure {r.subject} is the subject of two relations")
            subjects.add(r.subject)
        if self.grid is not None:
            rows, cols = self.grid
            free = n - len(subjects)
            if rows < 1 or cols < 1 or rows * cols != free:
                raise ValueError(
                    f"grid: {rows} x {cols} places for {free} separate structure(s); "
                    "give as many places as structures"
                )
        # no cycles: following subject → object must end
        target = {r.subject: r.object for r in self.relations}
        for start in target:
            seen, k = {start}, start
            while k in target:
                k = target[k]
                if k in seen:
                    raise ValueError("the relations between structures form a cycle")
                seen.add(k)
        return self

    def describe(self) -> str:
        text = "; ".join(s.describe() for s in self.structures)
        if self.relations:
            names = [f"{s.shape}#{k + 1}" for k, s in enumerate(self.structures)]
            text += " | " + "; ".join(r.describe(names) for r in self.relations)
        return text
