"""The structured specification l̂ that the Specifier produces and the Designer consumes.

Flat and JSON-Schema friendly so that an LLM can fill it under structured output. Counts are in
parts; the ``*_m`` fields give the same sizes in metres and win when both are set. Positions are
metres in the world frame; `region` names one of the cell's regions (left = +y, back = +x).
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

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


class Spec(BaseModel):
    """The whole command: one or more structures, placed side by side unless positioned."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    structures: tuple[StructureSpec, ...] = Field(min_length=1, max_length=50)
    precedence: tuple[tuple[str, str], ...] = ()
    notes: tuple[str, ...] = Field((), description="assumptions the front end made")

    def describe(self) -> str:
        return "; ".join(s.describe() for s in self.structures)
