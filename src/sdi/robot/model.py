"""Robot, joint and tool models of the paper's two-arm cell (numbers from ``robots.md``).

Frames (all right-handed, metres, radians):

- ``world``: the cell frame; the table top is z = 0, the workspace W is x 0.20–0.80,
  y 0.05–0.55 (``sdi.model.cell.Workspace``).
- ``base``: the robot base frame (ABB base frame, z up through joint 1), ``T_world_base``.
- ``link_i``: the URDF link frames, placed at joint i's origin and rotated by q_i about its axis;
  at q = 0 every link frame is parallel to ``base``.
- ``flange``: the mounting face of the last link, = ROS-Industrial ``tool0`` = ``link_6`` rotated
  by rpy (0, π/2, 0), so the flange's z (the tool axis) points along link 6's x.
- ``tcp``: the tool centre point of the gripper, ``tool.T_flange_tcp``; its z is the approach
  direction (suction cups' or pads' normal, pointing out of the tool).

Arrays stored in these values are read-only copies; the classes compare by identity.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Literal

import numpy as np

from sdi.model.cell import CellConfig
from sdi.robot.exceptions import JointLimitError, RobotModelError
from sdi.robot.transforms import invert_transform, is_rigid, make_transform

Axis = Literal["x", "y", "z"]
ToolKind = Literal["vacuum", "parallel"]
ShapeKind = Literal["box", "cylinder", "sphere"]
Vec3 = tuple[float, float, float]

LINK_NAMES: tuple[str, ...] = (
    "base_link",
    "link_1",
    "link_2",
    "link_3",
    "link_4",
    "link_5",
    "link_6",
)
"""URDF names of the seven moving-chain links, in `link_frames` order (then flange, tcp)."""

T_LINK6_FLANGE: np.ndarray = make_transform(rpy=(0.0, math.pi / 2, 0.0))
"""Pose of the flange (tool0) in link 6: rpy (0, π/2, 0), no offset (robots.md)."""
T_LINK6_FLANGE.setflags(write=False)


def _frozen_array(value: object, shape: tuple[int, ...], what: str) -> np.ndarray:
    arr = np.array(value, dtype=float)
    if arr.shape != shape:
        raise RobotModelError(f"must have shape {shape}, got {arr.shape}", field=what)
    arr.setflags(write=False)
    return arr


def _rigid(value: object, what: str) -> np.ndarray:
    T = _frozen_array(value, (4, 4), what)
    if not is_rigid(T, tol=1e-6):
        raise RobotModelError(
            "must be a rigid transform (orthonormal rotation, det +1, last row 0 0 0 1)",
            field=what,
        )
    return T


@dataclass(frozen=True)
class JointSpec:
    """One revolute joint of the URDF chain.

    The joint frame sits at `origin_xyz` (m) in the parent link's frame with rpy = 0 and turns
    the child link by q about its own `axis`. Limits are rad, rad/s and rad/s²; `max_effort`
    (N·m) is a nominal value used only in the URDF.
    """

    name: str
    origin_xyz: Vec3
    axis: Axis
    lower: float
    upper: float
    max_velocity: float
    max_acceleration: float
    max_effort: float = 100.0

    def __post_init__(self) -> None:
        if self.axis not in ("x", "y", "z"):
            raise RobotModelError(
                f"axis must be 'x', 'y' or 'z', got {self.axis!r}", field=f"{self.name}.axis"
            )
        if not self.lower < self.upper:
            raise RobotModelError(
                f"lower limit {self.lower} rad must be below upper limit {self.upper} rad",
                field=f"{self.name}.lower",
            )
        for attr in ("max_velocity", "max_acceleration", "max_effort"):
            value = getattr(self, attr)
            if not (value > 0 and math.isfinite(value)):
                raise RobotModelError(
                    f"must be > 0 and finite, got {value}", field=f"{self.name}.{attr}"
                )

    @property
    def span(self) -> float:
        """Width of the joint range, rad."""
        return self.upper - self.lower

    def contains(self, q: float, tol: float = 0.0) -> bool:
        """True if `q` (rad) lies within the limits widened by `tol` (rad)."""
        return self.lower - tol <= q <= self.upper + tol


@dataclass(frozen=True, eq=False)
class CollisionShape:
    """A primitive solid fixed to a link, used for collision and visual geometry.

    `dimensions` (m) depend on `kind`: a box has its half extents (hx, hy, hz) along the shape
    frame's axes; a cylinder has (radius, half_length) with its axis along the shape frame's z;
    a sphere has (radius,). `T_link_shape` is the pose of the shape's centre frame in the
    frame of the link (or, for tools, of the flange) that carries it.
    """

    kind: ShapeKind
    dimensions: tuple[float, ...]
    T_link_shape: np.ndarray

    def __post_init__(self) -> None:
        expected = {"box": 3, "cylinder": 2, "sphere": 1}.get(self.kind)
        if expected is None:
            raise RobotModelError(f"kind must be box, cylinder or sphere, got {self.kind!r}")
        dims = tuple(float(d) for d in self.dimensions)
        if len(dims) != expected or min(dims) <= 0:
            raise RobotModelError(
                f"a {self.kind} needs {expected} dimensions > 0 m, got {list(dims)}",
                field="dimensions",
            )
        object.__setattr__(self, "dimensions", dims)
        object.__setattr__(self, "T_link_shape", _rigid(self.T_link_shape, "T_link_shape"))

    @classmethod
    def box(cls, lower: Vec3, upper: Vec3) -> CollisionShape:
        """An axis-aligned box spanning `lower` … `upper` (m) in the carrying frame."""
        lo, hi = np.asarray(lower, dtype=float), np.asarray(upper, dtype=float)
        if np.any(hi <= lo):
            raise RobotModelError(
                f"box upper {list(hi)} must exceed lower {list(lo)} on every axis"
            )
        half = 0.5 * (hi - lo)
        return cls(
            "box", (float(half[0]), float(half[1]), float(half[2])), make_transform(0.5 * (lo + hi))
        )

    @classmethod
    def cylinder(
        cls,
        axis: Axis,
        radius: float,
        lower: float,
        upper: float,
        centre: tuple[float, float] = (0.0, 0.0),
    ) -> CollisionShape:
        """A cylinder of `radius` (m) along the carrying frame's `axis`, from `lower` to `upper`
        (m) on that axis, its axis passing through `centre` (m) on the other two axes (in
        x, y, z order without the cylinder axis)."""
        if upper <= lower:
            raise RobotModelError(f"cylinder upper {upper} m must exceed lower {lower} m")
        mid = 0.5 * (lower + upper)
        u, v = centre
        if axis == "x":
            T = make_transform((mid, u, v), (0.0, math.pi / 2, 0.0))
        elif axis == "y":
            T = make_transform((u, mid, v), (-math.pi / 2, 0.0, 0.0))
        else:
            T = make_transform((u, v, mid))
        return cls("cylinder", (radius, 0.5 * (upper - lower)), T)

    @classmethod
    def sphere(cls, radius: float, centre: Vec3 = (0.0, 0.0, 0.0)) -> CollisionShape:
        """A sphere of `radius` (m) centred at `centre` (m) in the carrying frame."""
        return cls("sphere", (radius,), make_transform(centre))

    @property
    def half_extents(self) -> Vec3:
        """Half extents (m) of the shape's bounding box in its own frame."""
        d = self.dimensions
        if self.kind == "box":
            return (d[0], d[1], d[2])
        if self.kind == "cylinder":
            return (d[0], d[0], d[1])
        return (d[0], d[0], d[0])

    @property
    def bounding_radius(self) -> float:
        """Radius (m) of the smallest sphere about the shape centre that holds the shape."""
        return (
            float(np.linalg.norm(self.half_extents))
            if self.kind != "sphere"
            else self.dimensions[0]
        )

    def inertia_diagonal(self, mass_kg: float) -> Vec3:
        """Principal moments (kg·m²) of a solid of this shape and `mass_kg` about its centre."""
        d = self.dimensions
        if self.kind == "box":
            hx, hy, hz = d
            return (
                mass_kg * (hy * hy + hz * hz) / 3.0,
                mass_kg * (hx * hx + hz * hz) / 3.0,
                mass_kg * (hx * hx + hy * hy) / 3.0,
            )
        if self.kind == "cylinder":
            r, h = d
            side = mass_kg * (3.0 * r * r + 4.0 * h * h) / 12.0
            return (side, side, 0.5 * mass_kg * r * r)
        moment = 0.4 * mass_kg * d[0] * d[0]
        return (moment, moment, moment)


@dataclass(frozen=True, eq=False)
class ToolModel:
    """A gripper mounted on the flange.

    `T_flange_tcp` is the pose of the tool centre point in the flange frame (its z the approach
    direction); `collision_boxes` are boxes in the flange frame (each one's `half_extents` and
    `T_link_shape` = T_flange_box); `mass_kg` is the tool's mass.
    """

    name: str
    kind: ToolKind
    T_flange_tcp: np.ndarray
    mass_kg: float
    collision_boxes: tuple[CollisionShape, ...]

    def __post_init__(self) -> None:
        if self.kind not in ("vacuum", "parallel"):
            raise RobotModelError(
                f"kind must be vacuum or parallel, got {self.kind!r}", field=self.name
            )
        object.__setattr__(
            self, "T_flange_tcp", _rigid(self.T_flange_tcp, f"{self.name}.T_flange_tcp")
        )
        if not self.mass_kg > 0:
            raise RobotModelError(
                f"must be > 0 kg, got {self.mass_kg}", field=f"{self.name}.mass_kg"
            )
        boxes = tuple(self.collision_boxes)
        if not boxes or any(b.kind != "box" for b in boxes):
            raise RobotModelError(
                "needs at least one shape, all boxes", field=f"{self.name}.collision_boxes"
            )
        object.__setattr__(self, "collision_boxes", boxes)

    @property
    def tcp_offset(self) -> float:
        """Distance (m) from the flange origin to the TCP."""
        return float(np.linalg.norm(self.T_flange_tcp[:3, 3]))


@dataclass(frozen=True)
class OPWParameters:
    """Geometry of an ortho-parallel arm with a spherical wrist (Brandstötter et al. 2014), m.

    Convention of the reference implementation ``opw_kinematics``: the OPW model's angle of
    joint i is ``theta_i = q_i * sign_corrections[i] - offsets[i]``, so
    ``q_i = (theta_i + offsets[i]) * sign_corrections[i]``. In the OPW zero pose the arm
    stands straight up and the flange's z points up.
    """

    a1: float
    a2: float
    b: float
    c1: float
    c2: float
    c3: float
    c4: float
    offsets: tuple[float, float, float, float, float, float] = (0.0,) * 6
    sign_corrections: tuple[int, int, int, int, int, int] = (1,) * 6

    def __post_init__(self) -> None:
        if len(self.offsets) != 6 or len(self.sign_corrections) != 6:
            raise RobotModelError("offsets and sign_corrections need 6 entries each", field="opw")
        if any(s not in (1, -1) for s in self.sign_corrections):
            raise RobotModelError(
                f"sign corrections must be ±1, got {list(self.sign_corrections)}", field="opw"
            )
        if self.c2 <= 0 or math.hypot(self.a2, self.c3) <= 0:
            raise RobotModelError(
                "c2 and the forearm length √(a2² + c3²) must be > 0 m", field="opw"
            )


@dataclass(frozen=True, eq=False)
class RobotModel:
    """A six-axis arm with its tool and its placement in the cell.

    `joints` are the six revolute joints of the URDF chain base → link_1 … link_6;
    `opw` the same geometry for the analytic IK; `T_world_base` the base's pose in the world;
    `controller_rate_hz` the rate at which the controller takes/gives joint samples;
    `link_shapes[i]` the collision shapes of ``LINK_NAMES[i]`` in that link's frame;
    `link_masses_kg[i]` that link's (estimated) mass.
    """

    name: str
    joints: tuple[JointSpec, ...]
    opw: OPWParameters
    T_world_base: np.ndarray
    tool: ToolModel
    controller_rate_hz: float
    link_shapes: tuple[tuple[CollisionShape, ...], ...]
    link_masses_kg: tuple[float, ...]
    lower: np.ndarray = field(init=False, repr=False)
    upper: np.ndarray = field(init=False, repr=False)
    max_velocity: np.ndarray = field(init=False, repr=False)
    max_acceleration: np.ndarray = field(init=False, repr=False)
    T_base_world: np.ndarray = field(init=False, repr=False)
    T_tcp_flange: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        joints = tuple(self.joints)
        if len(joints) != 6:
            raise RobotModelError(f"needs 6 joints, got {len(joints)}", field=f"{self.name}.joints")
        names = [j.name for j in joints]
        if len(set(names)) != 6:
            raise RobotModelError(
                f"joint names must be unique, got {names}", field=f"{self.name}.joints"
            )
        object.__setattr__(self, "joints", joints)
        T = _rigid(self.T_world_base, f"{self.name}.T_world_base")
        object.__setattr__(self, "T_world_base", T)
        if not self.controller_rate_hz > 0:
            raise RobotModelError(
                f"must be > 0 Hz, got {self.controller_rate_hz}",
                field=f"{self.name}.controller_rate_hz",
            )
        shapes = tuple(tuple(s) for s in self.link_shapes)
        if len(shapes) != len(LINK_NAMES) or len(self.link_masses_kg) != len(LINK_NAMES):
            raise RobotModelError(
                f"link_shapes and link_masses_kg need one entry per link {list(LINK_NAMES)}",
                field=f"{self.name}.link_shapes",
            )
        if min(self.link_masses_kg) <= 0:
            raise RobotModelError(
                f"every link mass must be > 0 kg, got {list(self.link_masses_kg)}",
                field=f"{self.name}.link_masses_kg",
            )
        object.__setattr__(self, "link_shapes", shapes)
        object.__setattr__(self, "link_masses_kg", tuple(float(m) for m in self.link_masses_kg))
        for attr in ("lower", "upper", "max_velocity", "max_acceleration"):
            arr = np.array([getattr(j, attr) for j in joints], dtype=float)
            arr.setflags(write=False)
            object.__setattr__(self, attr, arr)
        T_base_world = invert_transform(T)
        T_base_world.setflags(write=False)
        object.__setattr__(self, "T_base_world", T_base_world)
        T_tcp_flange = invert_transform(self.tool.T_flange_tcp)
        T_tcp_flange.setflags(write=False)
        object.__setattr__(self, "T_tcp_flange", T_tcp_flange)

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(j.name for j in self.joints)

    @property
    def dof(self) -> int:
        return len(self.joints)

    def placed(self, T_world_base: np.ndarray) -> RobotModel:
        """This robot with its base at `T_world_base` (4×4, base pose in the world)."""
        return replace(self, T_world_base=T_world_base)

    def with_tool(self, tool: ToolModel) -> RobotModel:
        """This robot carrying `tool`."""
        return replace(self, tool=tool)

    def within_limits(self, q: np.ndarray, tol: float = 1e-9) -> bool:
        """True if every joint value of `q` (6,) rad is inside its limits widened by `tol`."""
        q = np.asarray(q, dtype=float)
        return bool(np.all(q >= self.lower - tol) and np.all(q <= self.upper + tol))

    def check_limits(self, q: np.ndarray, tol: float = 1e-9) -> None:
        """Raise `JointLimitError` naming the first joint of `q` (6,) outside its limits."""
        q = np.asarray(q, dtype=float).reshape(-1)
        if q.shape != (6,):
            raise RobotModelError(f"q must have 6 joint values, got {q.shape[0]}", field=self.name)
        for j, value in zip(self.joints, q, strict=True):
            if not j.contains(float(value), tol):
                raise JointLimitError(self.name, j.name, float(value), j.lower, j.upper)

    def clip(self, q: np.ndarray) -> np.ndarray:
        """`q` (6,) rad clipped into the joint limits."""
        return np.clip(np.asarray(q, dtype=float), self.lower, self.upper)


# ---------------------------------------------------------------------------------------------
# Tools (OnRobot, robots.md "Grippers")

VGC10_TIP = 0.1115
"""Suction-cup tips of the VGC10 (four-cup variant) from the flange along the tool axis, m."""
TWO_FG7_TCP = 0.140
"""Pad centre of the 2FG7 from the flange along the tool axis, m."""
TWO_FG7_MAX_OPENING = 0.073
"""Widest opening of the 2FG7 fingers, m."""


def vgc10() -> ToolModel:
    """OnRobot VGC10 vacuum gripper, four Ø0.016 m cups at (±0.0175, ±0.0175) m.

    Body 0.100 × 0.100 × 0.090 m from the flange face; the cups fill the rest of the
    0.1115 m to their tips, where the TCP sits (z along the tool axis, out of the cups).
    Mass 0.814 kg is OnRobot's data-sheet value (robots.md gives none).
    """
    body_h = 0.090
    cups_half = 0.0175 + 0.008
    return ToolModel(
        name="VGC10",
        kind="vacuum",
        T_flange_tcp=make_transform((0.0, 0.0, VGC10_TIP)),
        mass_kg=0.814,
        collision_boxes=(
            CollisionShape.box((-0.05, -0.05, 0.0), (0.05, 0.05, body_h)),
            CollisionShape.box((-cups_half, -cups_half, body_h), (cups_half, cups_half, VGC10_TIP)),
        ),
    )


def two_fg7(opening: float = TWO_FG7_MAX_OPENING) -> ToolModel:
    """OnRobot 2FG7 parallel gripper with its fingers `opening` (m) apart.

    Body 0.090 (x, the finger travel β) × 0.071 (y) × 0.1145 (z) m centred 0.056 m from the
    flange; fingers 0.010 m thick, 0.020 m wide, from the body to 0.159 m; TCP at the pad
    centre 0.140 m out along z. The default, fully open, is the envelope for collision checks.
    """
    if not 0.0 <= opening <= TWO_FG7_MAX_OPENING:
        raise RobotModelError(
            f"{opening} m is outside 0 … {TWO_FG7_MAX_OPENING} m", field="2FG7.opening"
        )
    body_lo, body_hi = 0.056 - 0.1145 / 2, 0.056 + 0.1145 / 2
    tip, thick, half_w = 0.159, 0.010, 0.010
    inner = opening / 2
    return ToolModel(
        name="2FG7",
        kind="parallel",
        T_flange_tcp=make_transform((0.0, 0.0, TWO_FG7_TCP)),
        mass_kg=1.0,
        collision_boxes=(
            CollisionShape.box((-0.045, -0.0355, body_lo), (0.045, 0.0355, body_hi)),
            CollisionShape.box((inner, -half_w, body_hi), (inner + thick, half_w, tip)),
            CollisionShape.box((-inner - thick, -half_w, body_hi), (-inner, half_w, tip)),
        ),
    )


# ---------------------------------------------------------------------------------------------
# Robots (ABB, robots.md)

DEG = math.pi / 180.0


def _joints(
    origins: list[Vec3],
    limits: list[tuple[float, float]],
    speeds: list[float],
    accelerations: list[float],
    efforts: list[float],
) -> tuple[JointSpec, ...]:
    axes: tuple[Axis, ...] = ("z", "y", "y", "x", "y", "x")
    return tuple(
        JointSpec(
            f"joint_{i + 1}",
            origins[i],
            axes[i],
            *limits[i],
            speeds[i],
            accelerations[i],
            efforts[i],
        )
        for i in range(6)
    )


def irb120(T_world_base: np.ndarray | None = None, *, tool: ToolModel | None = None) -> RobotModel:
    """ABB IRB120-3/0.58 with an OnRobot VGC10 (default), PC SDK feedback at 50 Hz.

    Limits and speeds from data sheet ROB0149EN_D, accelerations MoveIt's (each is 0.2 s⁻¹
    × the joint's speed). Joint 5 uses ±115° (product specification) rather than the URDF's
    ±120°: a plan inside the narrower range is valid under both readings.
    """
    speeds = [4.36332, 4.36332, 4.36332, 5.58505, 5.58505, 7.33038]
    joints = _joints(
        origins=[
            (0, 0, 0),
            (0, 0, 0.290),
            (0, 0, 0.270),
            (0, 0, 0.070),
            (0.302, 0, 0),
            (0.072, 0, 0),
        ],
        limits=[
            (-2.87979, 2.87979),
            (-1.91986, 1.91986),
            (-1.91986, 1.22173),
            (-2.79253, 2.79253),
            (-115 * DEG, 115 * DEG),
            (-6.98132, 6.98132),
        ],
        speeds=speeds,
        accelerations=[0.87266, 0.87266, 0.87266, 1.11701, 1.11701, 1.46608],
        efforts=[40.0, 40.0, 20.0, 8.0, 8.0, 4.0],
    )
    shapes: tuple[tuple[CollisionShape, ...], ...] = (
        (CollisionShape.box((-0.218, -0.093, 0.0), (0.093, 0.093, 0.166)),),
        (CollisionShape.cylinder("z", 0.115, 0.149, 0.357),),
        (CollisionShape.box((-0.077, -0.12, -0.085), (0.077, 0.12, 0.333)),),
        (CollisionShape.box((-0.096, -0.06, -0.054), (0.161, 0.06, 0.145)),),
        (CollisionShape.cylinder("x", 0.066, 0.144, 0.347),),
        (CollisionShape.sphere(0.07),),
        (CollisionShape.cylinder("x", 0.021, -0.010, 0.0),),
    )
    return RobotModel(
        name="irb120",
        joints=joints,
        opw=OPWParameters(
            a1=0.0,
            a2=-0.070,
            b=0.0,
            c1=0.290,
            c2=0.270,
            c3=0.302,
            c4=0.072,
            offsets=(0.0, 0.0, -math.pi / 2, 0.0, 0.0, 0.0),
        ),
        T_world_base=np.eye(4) if T_world_base is None else T_world_base,
        tool=vgc10() if tool is None else tool,
        controller_rate_hz=50.0,
        link_shapes=shapes,
        # 25 kg in total (data sheet), split by link volume; estimates
        link_masses_kg=(7.0, 4.5, 5.5, 3.5, 2.5, 1.5, 0.5),
    )


IRB1600_ACCELERATION_PER_SPEED = 0.2
"""Acceleration limit per unit joint speed for the IRB1600, s⁻¹ (MoveIt's IRB120 ratio)."""


def irb1600(T_world_base: np.ndarray | None = None, *, tool: ToolModel | None = None) -> RobotModel:
    """ABB IRB1600 with the 1.45 m geometry and an OnRobot 2FG7 (default), EGM at 250 Hz.

    Limits and speeds are robots.md's 8/1.45 column. ABB publishes no acceleration limits;
    we use 0.2 s⁻¹ × each joint's speed, the ratio of MoveIt's IRB120 limits, so both arms of
    the cell are time-parameterised alike (full speed after 5 s, well inside the hardware).
    """
    speeds = [math.pi, math.pi, 3.4906, 6.9813, 6.9813, 8.0285]
    joints = _joints(
        origins=[
            (0, 0, 0),
            (0.150, 0, 0.4865),
            (0, 0, 0.700),
            (0.300, 0, 0),
            (0.300, 0, 0),
            (0.065, 0, 0),
        ],
        limits=[
            (-math.pi, math.pi),
            (-math.pi / 2, 2.0944),
            (-4.27601, 1.1344),
            (-3.4906, 3.4906),
            (-2.0071, 2.0071),
            (-6.9813, 6.9813),
        ],
        speeds=speeds,
        accelerations=[IRB1600_ACCELERATION_PER_SPEED * v for v in speeds],
        efforts=[600.0, 800.0, 300.0, 80.0, 80.0, 40.0],
    )
    shapes: tuple[tuple[CollisionShape, ...], ...] = (
        (CollisionShape.box((-0.382, -0.242, 0.0), (0.278, 0.242, 0.171)),),
        (CollisionShape.box((-0.264, -0.163, 0.125), (0.315, 0.193, 0.651)),),
        (CollisionShape.box((-0.087, -0.252, -0.088), (0.087, -0.106, 0.770)),),
        (CollisionShape.box((-0.175, -0.12, -0.136), (0.314, 0.161, 0.108)),),
        (CollisionShape.cylinder("x", 0.063, 0.014, 0.355),),
        (CollisionShape.box((-0.042, -0.024, -0.042), (0.042, 0.024, 0.042)),),
        (CollisionShape.cylinder("x", 0.025, -0.010, 0.0),),
    )
    return RobotModel(
        name="irb1600",
        joints=joints,
        opw=OPWParameters(
            a1=0.150,
            a2=0.0,
            b=0.0,
            c1=0.4865,
            c2=0.700,
            c3=0.600,
            c4=0.065,
            offsets=(0.0, 0.0, -math.pi / 2, 0.0, 0.0, 0.0),
        ),
        T_world_base=np.eye(4) if T_world_base is None else T_world_base,
        tool=two_fg7() if tool is None else tool,
        controller_rate_hz=250.0,
        link_shapes=shapes,
        # about 250 kg in total (data sheet), split by link volume; estimates
        link_masses_kg=(80.0, 70.0, 40.0, 35.0, 15.0, 8.0, 2.0),
    )


IRB120_BASE_XY: tuple[float, float] = (0.0, 0.30)
"""World position of the IRB120's base, m (yaw 0: it faces +x, the workspace)."""
IRB1600_BASE_XY: tuple[float, float] = (1.30, 0.30)
"""World position of the IRB1600's base, m (yaw π: it faces −x, the workspace). Far enough
back that every workspace point has a front, elbow-up solution: nearer, targets by its own
edge need over-the-head configurations that sweep towards the IRB120."""


def default_robots() -> dict[str, RobotModel]:
    """The paper's cell: both arms on the table plane (base z = 0), across the workspace.

    The IRB120 stands at world (0.00, 0.30) facing +x. Its wrist reaches at most
    c2 + √(a2² + c3²) ≈ 0.58 m from the shoulder, so with the VGC10 pointing down at a 0.05 m
    cube on the table it reaches about x ≤ 0.57 on the line y = 0.30 and less off it: targets
    with x > ~0.6 are outside its reach and IK fails there (the paper's "workspace boundary
    x > 0.6 → IK failure"). The IRB1600 stands at world (1.30, 0.30) facing −x and reaches
    the whole workspace W (x 0.20–0.80, y 0.05–0.55) in front, elbow-up configurations.
    """
    return {
        "irb120": irb120(make_transform((*IRB120_BASE_XY, 0.0))),
        "irb1600": irb1600(make_transform((*IRB1600_BASE_XY, 0.0), (0.0, 0.0, math.pi))),
    }


def robots_for(cell: CellConfig) -> dict[str, RobotModel]:
    """The robots of a cell configuration (`[[robots]]`), placed where it says."""
    factories = {"irb120": irb120, "irb1600": irb1600}
    out: dict[str, RobotModel] = {}
    for p in cell.robots:
        T = make_transform((*p.base_xy, 0.0), (0.0, 0.0, math.radians(p.base_yaw_deg)))
        out[p.name] = replace(factories[p.model](T), name=p.name)
    return out


__all__ = [
    "IRB120_BASE_XY",
    "IRB1600_BASE_XY",
    "LINK_NAMES",
    "T_LINK6_FLANGE",
    "CollisionShape",
    "JointSpec",
    "OPWParameters",
    "RobotModel",
    "ToolModel",
    "default_robots",
    "irb120",
    "irb1600",
    "two_fg7",
    "vgc10",
]
