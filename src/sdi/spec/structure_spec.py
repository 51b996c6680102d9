"""The structured specification l̂ that the Specifier produces and the Designer consumes.

Flat and JSON-Schema friendly so that an LLM can fill it under structured output. Counts are in
parts; the ``*_m`` fields give the same sizes in metres and win when both are set. Positions are
metres in the world frame; `region` names one of the cell's regions (left = +y, back = +x).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

Shape = Literal[
    "tower", "row", "grid", "wall", "block", "pyramid", "staircase", "bridge", "arch",
    "canopy", "enclosure", "l_shape", "u_shape", "t_shape", "castle", "pack", "cross",
]  # fmt: skip

SHAPES: tuple[str, ...] = Shape.__args__  # type: ignore[attr-defined]

Count = int | None


class StructureSpec(BaseModel):
    """One structure to build."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    shape: Shape
    count: Count = Field(None, ge=1, description="total parts (tower, row, pack)")
    length: Count = Field(None, ge=1, description="parts along the main axis")
    width: Count = Field(None, ge=1, description="parts across the main axis")
    height: Count = Field(None, ge=1, description="levels (parts stacked)")
    steps: Count = Field(None, ge=1, description="staircase steps")
    span: Count = Field(None, ge=1, description="gap between supports, in parts")
    spans: Count = Field(None, ge=1, description="number of spans (bridge)")
    dims: Literal[2, 3] | None = Field(None, description="pyramid: 2-D (a face) or 3-D")
    length_m: float | None = Field(None, gt=0, description="size along the main axis, m")
    width_m: float | None = Field(None, gt=0, description="size across the main axis, m")
    height_m: float | None = Field(None, gt=0, description="height, m")
    axis: Literal["x", "y"] | None = Field(None, description="main axis in the world frame")
    yaw_deg: float = Field(0.0, ge=-360, le=360, description="rotation about z, degrees")
    at_x: float | None = Field(None, description="footprint centre x, m")
    at_y: float | None = Field(None, description="footprint centre y, m")
    region: str | None = Field(None, description="named region of the cell (left, back right…)")
    part: str = Field("cube", description="part type name from the cell configuration")
    gap_m: float | None = Field(None, ge=0, le=0.5, description="gap between neighbouring parts, m")

    def describe(self) -> str:
        """Short human summary, e.g. ``tower height=3 at (0.4, ·)``."""
        fields = self.model_dump(exclude_none=True, exclude={"shape", "part", "yaw_deg"})
        parts = [f"{k}={v}" for k, v in fields.items()]
        if self.yaw_deg:
            parts.append(f"yaw={self.yaw_deg:g}°")
        if self.part != "cube":
            parts.append(f"part={self.part}")
        return " ".join([self.shape, *parts])


RelationKind = Literal["on_top_of", "around", "next_to"]
Side = Literal["left", "right", "front", "back"]


class Relation(BaseModel):
    """How one structure stands to another; indices into `Spec.structures`.

    ``on_top_of``: `subject` stands on the top face of `object`, centred on it. ``around``:
    `subject` (a ring) encloses `object`, sized to leave one part of room on every side.
    ``next_to``: `subject` stands beside `object` on `side` (left = +y, back = +x), one
    structure gap away. A structure is the subject of at most one relation.
    """

    model_config = ConfigDict(frozen=True, extra="forbid")

    kind: RelationKind
    subject: int = Field(ge=0, description="index of the structure that is placed")
    object: int = Field(ge=0, description="index of the structure it is placed against")
    side: Side | None = Field(None, description="next_to: which side of the object")

    def describe(self, names: list[str] | None = None) -> str:
        a = names[self.subject] if names else f"#{self.subject + 1}"
        b = names[self.object] if names else f"#{self.object + 1}"
        kind = self.kind.replace("_", " ")
        if self.kind == "next_to" and self.side:
            return f"{a} {kind} {b} ({self.side})"
        return f"{a} {kind} {b}"


class Spec(BaseModel):
    """The whole command: one or more structures, placed side by side unless positioned or
    related to each other (`relations`)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    structures: tuple[StructureSpec, ...] = Field(min_length=1, max_length=50)
    relations: tuple[Relation, ...] = ()
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
