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
import re
import string
import tomllib
from functools import cached_property
from pathlib import Path
from typing import Annotated, Any, Literal

from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from sdi.errors import InputError

Vec2 = tuple[float, float]
Vec3 = tuple[float, float, float]
REACH = 1000.0
"""Largest |coordinate| and length in a cell, m (parts obey the same bound, `MAX_COORDINATE`)."""
Coord = Annotated[float, Field(ge=-REACH, le=REACH)]
"""A world coordinate, metres."""
Length = Annotated[float, Field(gt=0, le=REACH)]
"""A length that must be > 0, metres."""
Gap = Annotated[float, Field(ge=0, le=REACH)]
"""A gap or tolerance that must be ≥ 0, metres."""
Coords2 = tuple[Coord, Coord]
Lengths2 = tuple[Length, Length]
PartEdge = Annotated[float, Field(gt=0, le=10.0)]
"""An edge of a part type, metres (parts are at most 10 m, like `Part.size`)."""
Lengths3 = tuple[PartEdge, PartEdge, PartEdge]


class _Frozen(BaseModel):
    """Frozen, no unknown keys, every number finite (no NaN or infinity)."""

    model_config = ConfigDict(frozen=True, extra="forbid", allow_inf_nan=False)


def _ordered_range(name: str, lo: float, hi: float) -> None:
    if not lo < hi:
        raise ValueError(f"{name}: the first value must be below the second, got [{lo}, {hi}]")


class Workspace(_Frozen):
    """The assembly workspace cuboid W (paper eq. 6). Every part's box must lie inside it."""

    x_min: Coord = 0.20
    x_max: Coord = 0.80
    y_min: Coord = 0.05
    y_max: Coord = 0.55
    z_min: Coord = 0.0
    z_max: Coord = 0.50

    @model_validator(mode="after")
    def _ordered(self) -> Workspace:
        for axis in "xyz":
            lo, hi = getattr(self, f"{axis}_min"), getattr(self, f"{axis}_max")
            if not lo < hi:
                raise ValueError(f"{axis}_min: must be below {axis}_max ({hi}), got {lo}")
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
    min_face: Length = Field(0.04, description="smallest top-face edge the cup pattern seals on, m")
    body_half_extents: Lengths2 = Field(
        (0.05, 0.05), description="body footprint half sizes x, y, m"
    )
    body_clearance: Gap = Field(
        0.02, description="height of the body's underside above the gripped part's top face, m"
    )


class ParallelGripper(_Frozen):
    """Two fingers closing along a lateral axis β ∈ {x, y} (OnRobot 2FG7)."""

    kind: Literal["parallel"] = "parallel"
    name: str = "2FG7"
    max_opening: Length = Field(0.073, description="widest finger opening, m")
    finger_thickness: Length = Field(0.010, description="finger thickness along β, m")
    finger_width: Length = Field(0.020, description="finger width across β, m")
    clearance: Gap = Field(0.004, description="free space each side beyond the part face, m")
    grip_depth: Length = Field(0.0175, description="deepest pad reach below the part top, m")
    finger_length: Length = Field(0.0445, description="fingertip to gripper body, m")
    body_half_extents: Lengths2 = Field(
        (0.045, 0.0355), description="body footprint half sizes along β and across β, m"
    )


class SupplyArea(_Frozen):
    """A rectangle on the table where one robot picks parts from known poses."""

    name: str
    robot: str
    x_range: Coords2
    y_range: Coords2
    pitch: Length = Field(0.08, description="spacing of the part grid in the area, m")

    @model_validator(mode="after")
    def _ordered(self) -> SupplyArea:
        _ordered_range("x_range", *self.x_range)
        _ordered_range("y_range", *self.y_range)
        return self


class RobotPlacement(_Frozen):
    """Where a robot of the cell stands: its base on the table plane, turned about z."""

    name: str
    model: Literal["irb120", "irb1600"]
    base_xy: Coords2 = Field(description="world position of the base, m")
    base_yaw_deg: float = Field(
        0.0, ge=-360.0, le=360.0, description="rotation of the base about z, degrees"
    )


class Tolerances(_Frozen):
    contact: Gap = Field(0.001, description="ε of the paper's contact predicate, m")
    support_overlap: Gap = Field(
        0.005, description="least footprint overlap on each axis for support from below, m"
    )
    stability_margin: Gap = Field(
        0.002, description="least distance of a centre of mass inside its support polygon, m"
    )


class Limits(_Frozen):
    max_parts: int = Field(10_000, ge=1, description="largest layout accepted")
    max_command_chars: int = Field(2_000, ge=1, description="longest command accepted")
    phase_seconds: float = Field(
        300.0,
        gt=0,
        le=1e6,
        description="wall-clock limit of one orchestrator phase (design, plan, …), s",
    )


_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}")
"""A RAPID identifier (signal names too): a letter, then letters, digits or _; 32 at most."""


class Interlocks(_Frozen):
    """Digital I/O that keeps two controllers in the schedule's order (exported programs).

    The arms sit on separate controllers (RobotWare 5 and 6), so MultiMove's `WaitSyncTask`
    does not apply. After a step another robot waits for, its robot sets
    `done_output` (placeholders {robot}: the robot that set it, {step}: the step number, from
    1); the other controller reads the same wire as `done_input`. `ready_output`/`ready_input`
    are the start handshake. Wire every robot's outputs to the other controllers' inputs of
    the same {robot} and {step} (EIO configuration, cross-connections or a PLC).
    """

    enabled: bool = Field(True, description="emit interlocks (off: each robot runs alone)")
    done_output: str = Field("doSDI_{robot}_Done{step}", description="set after a step, DO")
    done_input: str = Field("diSDI_{robot}_Done{step}", description="read before a step, DI")
    ready_output: str = Field("doSDI_{robot}_Ready", description="start handshake, DO")
    ready_input: str = Field("diSDI_{robot}_Ready", description="start handshake, DI")

    def signal(self, which: str, robot: str, step: int | None = None) -> str:
        """The signal `which` ("done_output", …) of `robot` (and 1-based `step`)."""
        template: str = getattr(self, which)
        return template.format(robot=robot, step=step)

    @model_validator(mode="after")
    def _names(self) -> Interlocks:
        fields = ("done_output", "done_input", "ready_output", "ready_input")
        for name in fields:
            template = getattr(self, name)
            wanted = {"robot", "step"} if name.startswith("done") else {"robot"}
            try:
                found = {f for _, f, _, _ in string.Formatter().parse(template) if f is not None}
            except ValueError as exc:
                raise ValueError(f"{name}: {exc} in {template!r}") from None
            if found != wanted:
                raise ValueError(
                    f"{name}: {template!r} must use exactly the placeholders "
                    f"{', '.join('{' + w + '}' for w in sorted(wanted))}"
                )
            self._check(name, self.signal(name, "r", 99999))
        names = [self.signal(n, "r", 1) for n in fields]
        if len(set(names)) < len(names):
            raise ValueError(
                "done_output, done_input, ready_output and ready_input must give four "
                "different signal names"
            )
        return self

    @staticmethod
    def _check(field: str, name: str, robot: str = "") -> None:
        if not _IDENTIFIER.fullmatch(name):
            raise ValueError(
                f"{field}: {name!r} is not a RAPID signal name (a letter, then letters, digits "
                f"or _, at most 32 characters){f'; rename robot {robot!r}' if robot else ''}"
            )


class DesignDefaults(_Frozen):
    """Where and how generators place structures when the command does not say."""

    anchor: Coords2 = Field((0.45, 0.30), description="default footprint centre x, y, m")
    structure_gap: Gap = Field(0.10, description="gap between separate structures, m")
    regions: dict[str, Coords2] = Field(
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


def _unique(table: str, names: list[str]) -> None:
    seen: set[str] = set()
    for i, name in enumerate(names):
        if name in seen:
            raise ValueError(
                f"{table}[{i}].name: duplicate name {name!r}; every name must be unique"
            )
        seen.add(name)


class CellConfig(_Frozen):
    """Everything the symbolic core needs to know about the cell."""

    workspace: Workspace = Workspace()
    part_types: dict[str, Lengths3] = Field(
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
    interlocks: Interlocks = Interlocks()

    @cached_property
    def cube(self) -> Vec3:
        return self.part_types["cube"]

    @model_validator(mode="after")
    def _consistent(self) -> CellConfig:
        if "cube" not in self.part_types:
            raise ValueError("part_types must define 'cube', the default part")
        _unique("robots", [r.name for r in self.robots])
        _unique("supply_areas", [a.name for a in self.supply_areas])
        robots = {r.name for r in self.robots}
        given = "supply_areas" in self.model_fields_set  # the defaults name the default robots
        for i, area in enumerate(self.supply_areas if given else ()):
            if area.robot not in robots:
                raise ValueError(
                    f"supply_areas[{i}].robot: no robot named {area.robot!r}; "
                    f"the cell has {sorted(robots)}"
                )
        if self.interlocks.enabled and len(self.robots) > 1:
            for r in self.robots:
                for name in ("done_output", "done_input", "ready_output", "ready_input"):
                    signal = self.interlocks.signal(name, r.name, 99999)
                    Interlocks._check(f"interlocks.{name}", signal, r.name)
        return self

    @classmethod
    def load(cls, path: str | Path | None = None) -> CellConfig:
        """Defaults, overridden by the TOML file at `path` (or ``$SDI_CELL``) when given."""
        path = path or os.environ.get("SDI_CELL")
        if not path:
            return cls()
        path = Path(path)
        fix = "give --cell a TOML file (or unset $SDI_CELL)"
        try:
            data: dict[str, Any] = tomllib.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            raise InputError(f"no such cell configuration file: {path}; {fix}") from None
        except IsADirectoryError:
            raise InputError(f"{path} is a folder, not a cell configuration; {fix}") from None
        except UnicodeDecodeError:
            raise InputError(f"{path} is not UTF-8 text; {fix}") from None
        except OSError as exc:
            raise InputError(f"cannot read {path}: {exc.strerror or exc}; {fix}") from None
        except tomllib.TOMLDecodeError as exc:
            raise InputError(f"{path} is not valid TOML: {exc}") from None
        except RecursionError:
            raise InputError(f"{path} is nested too deeply to be a cell configuration") from None
        return cls.from_dict(data)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> CellConfig:
        """Validate a parsed TOML document; errors name the TOML key (``workspace.x_max``)."""
        try:
            return cls.model_validate(data)
        except ValidationError as exc:
            raise _describe(exc.errors()[0]) from None


def _key(loc: tuple[int | str, ...]) -> str:
    key = ""
    for item in loc:
        key += f"[{item}]" if isinstance(item, int) else (f".{item}" if key else str(item))
    return key


def _describe(error: Any) -> InputError:
    """One `ValidationError` entry as an `InputError` naming the TOML key and the fix."""
    loc = tuple(x for x in error["loc"] if not (isinstance(x, str) and x.startswith("function-")))
    kind, got, ctx = error["type"], error.get("input"), error.get("ctx") or {}
    if kind == "finite_number":
        message = f"must be a finite number, got {got}"
    elif kind in ("greater_than", "greater_than_equal", "less_than_equal", "less_than"):
        bound = {"greater_than": "> ", "greater_than_equal": "≥ ", "less_than": "< ",
                 "less_than_equal": "≤ "}[kind]  # fmt: skip
        message = f"must be {bound}{next(iter(ctx.values()))}, got {got}"
    elif kind == "extra_forbidden":
        section = _key(loc[:-1])
        model = _SECTIONS.get(str(loc[0]) if len(loc) > 1 else "")
        known = f"; the keys are {', '.join(model.model_fields)}" if model else ""
        where = f" in [{section}]" if section else ""
        message = f"unknown key{where}; check its spelling{known}"
    elif kind in ("float_parsing", "float_type", "int_parsing", "int_type", "int_from_float"):
        message = f"must be a number, got {got!r}"
    elif kind in ("tuple_type", "list_type", "too_short", "too_long"):
        message = f"must be a list of numbers of the right length, got {got!r}"
    elif kind == "missing" and loc and isinstance(loc[-1], int):
        loc, message = loc[:-1], "too few numbers in the list"
    elif kind == "missing":
        message = "is required; add it"
    elif kind in ("dict_type", "model_type", "model_attributes_type"):
        message = f"must be a TOML table of keys and values, got {got!r}"
    else:
        message = error["msg"].removeprefix("Value error, ")
    # Our own validators start their message with the key inside the section.
    named = _OWN_KEY.match(message)
    if named:
        key = ".".join(k for k in (_key(loc), named[1]) if k)
        return InputError(named[2], field=key)
    return InputError(message, field=_key(loc) or None)


_OWN_KEY = re.compile(r"^([A-Za-z_][\w\[\].]*): (.*)$", re.DOTALL)


_SECTIONS: dict[str, type[BaseModel]] = {
    "": CellConfig,
    "workspace": Workspace,
    "tolerances": Tolerances,
    "limits": Limits,
    "design": DesignDefaults,
    "interlocks": Interlocks,
    "robots": RobotPlacement,
    "supply_areas": SupplyArea,
}
"""TOML sections → the model that reads them (to list the valid keys of a misspelt one)."""
