"""The cell configuration: workspace, part types, grippers, supply areas, tolerances, limits.

Defaults model the paper's station (IRB120 + OnRobot VGC10 vacuum, IRB1600 + OnRobot 2FG7
parallel gripper; numbers from ``robots.md``). A TOML file overrides any subset::

    [workspace]
    x_max = 0.70

    [limits]
    max_parts = 2000

All lengths are metres, all angles radians unless a name says otherwise.
"""

from __future__ import annotations

import os
import tomllib
from functools import cached_property
from pathlib import Path
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from sdi.errors import InputError

Vec2 = tuple[float, float]
Vec3 = tuple[float, float, float]


class _Frozen(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")


class Workspace(_Frozen):
    """The assembly workspace cuboid W (paper eq. 6). Every part's box must lie inside it."""

    x_min: float = 0.20
    x_max: float = 0.80
    y_min: float = 0.05
    y_max: float = 0.55
    z_min: float = 0.0
    z_max: float = 0.50

    @model_validator(mode="after")
    def _ordered(self) -> Workspace:
        for axis in "xyz":
            lo, hi = getattr(self, f"{axis}_min"), getattr(self, f"{axis}_max")
            if not lo < hi:
                raise ValueError(f"workspace.{axis}_min ({lo}) must be below {axis}_max ({hi})")
        return self

    @property
    def lower(self) -> Vec3:
        return (self.x_min, self.y_min, self.z_min)

    @property
    def upper(self) -> Vec3:
        return (self.x_max, self.y_max, self.z_max)

    @property
    def centre(self) -> Vec2:
        return (0.5 * (self.x_min + self.x_max), 0.5 * (self.y_min + self.y_max))


class VacuumGripper(_Frozen):
    """Suction from the top (OnRobot VGC10). Needs the top face free and the body's column clear."""

    kind: Literal["vacuum"] = "vacuum"
    name: str = "VGC10"
    min_face: float = Field(0.04, description="smallest top-face edge the cup pattern seals on, m")
    body_half_extents: Vec2 = Field((0.05, 0.05), description="body footprint half sizes x, y, m")
    body_clearance: float = Field(
        0.02, description="height of the body's underside above the gripped part's top face, m"
    )


class ParallelGripper(_Frozen):
    """Two fingers closing along a lateral axis β ∈ {x, y} (OnRobot 2FG7)."""

    kind: Literal["parallel"] = "parallel"
    name: str = "2FG7"
    max_opening: float = Field(0.073, description="widest finger opening, m")
    finger_thickness: float = Field(0.010, description="finger thickness along β, m")
    finger_width: float = Field(0.020, description="finger width across β, m")
    clearance: float = Field(0.004, description="free space each side beyond the part face, m")
    grip_depth: float = Field(0.0175, description="deepest pad reach below the part top, m")
    finger_length: float = Field(0.0445, description="fingertip to gripper body, m")
    body_half_extents: Vec2 = Field(
        (0.045, 0.0355), description="body footprint half sizes along β and across β, m"
    )


class SupplyArea(_Frozen):
    """A rectangle on the table where one robot picks parts from known poses."""

    name: str
    robot: str
    x_range: Vec2
    y_range: Vec2
    pitch: float = Field(0.08, description="spacing of the part grid in the area, m")


class RobotPlacement(_Frozen):
    """Where a robot of the cell stands: its base on the table plane, turned about z."""

    name: str
    model: Literal["irb120", "irb1600"]
    base_xy: Vec2 = Field(description="world position of the base, m")
    base_yaw_deg: float = Field(0.0, description="rotation of the base about z, degrees")


class Tolerances(_Frozen):
    contact: float = Field(0.001, description="ε of the paper's contact predicate, m")
    support_overlap: float = Field(
        0.005, description="least footprint overlap on each axis for support from below, m"
    )
    stability_margin: float = Field(
        0.002, description="least distance of a centre of mass inside its support polygon, m"
    )


class Limits(_Frozen):
    max_parts: int = Field(10_000, ge=1, description="largest layout accepted")
    max_command_chars: int = Field(2_000, ge=1, description="longest command accepted")
    phase_seconds: float = Field(
        300.0, gt=0, description="wall-clock limit of one orchestrator phase (design, plan, …), s"
    )


class DesignDefaults(_Frozen):
    """Where and how generators place structures when the command does not say."""

    anchor: Vec2 = Field((0.45, 0.30), description="default footprint centre x, y, m")
    structure_gap: float = Field(0.10, description="gap between separate structures, m")
    regions: dict[str, Vec2] = Field(
        default_factory=lambda: {
            "centre": (0.45, 0.30),
            "left": (0.45, 0.45),
            "right": (0.45, 0.15),
            "front": (0.30, 0.30),
            "back": (0.65, 0.30),
            "front left": (0.30, 0.45),
            "front right": (0.30, 0.15),
            "back left": (0.65, 0.45),
            "back right": (0.65, 0.15),
        },
        description="named regions → footprint centre x, y, m (left = +y, back = +x)",
    )


class CellConfig(_Frozen):
    """Everything the symbolic core needs to know about the cell."""

    workspace: Workspace = Workspace()
    part_types: dict[str, Vec3] = Field(
        default_factory=lambda: {"cube": (0.05, 0.05, 0.05), "beam": (0.15, 0.05, 0.05)},
        description="named part sizes (x, y, z), m",
    )
    grippers: tuple[VacuumGripper | ParallelGripper, ...] = (VacuumGripper(), ParallelGripper())
    supply_areas: tuple[SupplyArea, ...] = (
        SupplyArea(
            name="irb120_supply", robot="irb120", x_range=(0.12, 0.30), y_range=(-0.10, 0.00)
        ),
        SupplyArea(
            name="irb1600_supply", robot="irb1600", x_range=(0.95, 1.10), y_range=(0.72, 0.87)
        ),
    )
    robots: tuple[RobotPlacement, ...] = (
        RobotPlacement(name="irb120", model="irb120", base_xy=(0.0, 0.30), base_yaw_deg=0.0),
        RobotPlacement(name="irb1600", model="irb1600", base_xy=(1.30, 0.30), base_yaw_deg=180.0),
    )
    tolerances: Tolerances = Tolerances()
    limits: Limits = Limits()
    design: DesignDefaults = DesignDefaults()

    @cached_property
    def cube(self) -> Vec3:
        return self.part_types["cube"]

    @model_validator(mode="after")
    def _needs_cube(self) -> CellConfig:
        for name, size in self.part_types.items():
            if min(size) <= 0:
                raise ValueError(f"part_types.{name}: every edge must be > 0 m, got {list(size)}")
        if "cube" not in self.part_types:
            raise ValueError("part_types must define 'cube', the default part")
        return self

    @classmethod
    def load(cls, path: str | Path | None = None) -> CellConfig:
        """Defaults, overridden by the TOML file at `path` (or ``$SDI_CELL``) when given."""
        path = path or os.environ.get("SDI_CELL")
        if not path:
            return cls()
        path = Path(path)
        try:
            data: dict[str, Any] = tomllib.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise InputError(f"no such cell configuration file: {path}") from None
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"{path} is not valid TOML: {exc}") from None
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            first = exc.errors()[0]
            field = ".".join(str(x) for x in first["loc"])
            raise InputError(first["msg"].removeprefix("Value error, "), field=field) from None
