"""Forward kinematics from the URDF joint chain, analytic inverse kinematics by the OPW method.

OPW: M. Brandstötter, A. Angerer, M. Hofbaur, "An analytical solution of the inverse kinematics
problem of industrial serial manipulators with an ortho-parallel basis and a spherical wrist",
Austrian Robotics Workshop 2014. An arm whose joints 2 and 3 are parallel and orthogonal to
joint 1, with a spherical wrist (axes 4, 5, 6 meet in one point), has at most 8 solutions in
closed form: 2 for the shoulder (front/back) × 2 for the elbow (up/down) × 2 for the wrist
(flip). Joints whose range exceeds 2π (the IRB120's and IRB1600's joint 6, the IRB1600's joint 4)
add the ±2π variants of each.

Poses are 4×4 transforms ``T_a_b`` (pose of b in a, metres); joint vectors are (6,) radians.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from weakref import WeakKeyDictionary

import numpy as np

from sdi.robot.exceptions import RobotModelError
from sdi.robot.model import T_LINK6_FLANGE, CollisionShape, OPWParameters, RobotModel

_TWO_PI = 2.0 * math.pi
_ACOS_SLACK = 1e-12
"""How far (relative) a cosine may overshoot ±1 from round-off and still count as reachable."""
_WRIST_SINGULAR = 1e-7
"""|sin q5| below which the wrist is treated as singular (axes 4 and 6 aligned)."""
_LIMIT_SLACK = 1e-9
"""Round-off allowed beyond a joint limit, rad; such values are clipped onto the limit."""
_DUPLICATE_DIGITS = 9
"""Decimal places (rad) to which two IK solutions must agree to count as the same."""


def _as_q(model: RobotModel, q: Sequence[float] | np.ndarray) -> np.ndarray:
    arr = np.asarray(q, dtype=float).reshape(-1)
    if arr.shape != (6,):
        raise RobotModelError(
            f"q must hold 6 joint values (rad) for {list(model.joint_names)}, got {arr.shape[0]}",
            field=f"{model.name}.q",
        )
    return arr


def _as_pose(T: np.ndarray, what: str) -> np.ndarray:
    arr = np.asarray(T, dtype=float)
    if arr.shape != (4, 4):
        raise RobotModelError(f"must be a 4×4 transform, got shape {arr.shape}", field=what)
    return arr


def _joint_transform(axis: str, origin: tuple[float, float, float], angle: float) -> np.ndarray:
    """Pose of a child link in its parent: translate by `origin`, then turn about `axis`."""
    c, s = math.cos(angle), math.sin(angle)
    x, y, z = origin
    if axis == "z":
        rows = [[c, -s, 0.0, x], [s, c, 0.0, y], [0.0, 0.0, 1.0, z]]
    elif axis == "y":
        rows = [[c, 0.0, s, x], [0.0, 1.0, 0.0, y], [-s, 0.0, c, z]]
    else:
        rows = [[1.0, 0.0, 0.0, x], [0.0, c, -s, y], [0.0, s, c, z]]
    rows.append([0.0, 0.0, 0.0, 1.0])
    return np.array(rows)


def link_frames(model: RobotModel, q: Sequence[float] | np.ndarray) -> list[np.ndarray]:
    """World poses of every frame of the arm at joint values `q` (6,) rad.

    Returns nine (4, 4) transforms: ``T_world_base``, ``T_world_link_1`` … ``T_world_link_6``,
    ``T_world_flange``, ``T_world_tcp``; the collision shapes of ``LINK_NAMES[i]`` hang off
    entry i and the tool's boxes off the flange (entry 7).
    """
    qv = _as_q(model, q)
    T = model.T_world_base
    frames = [T.copy()]
    for joint, angle in zip(model.joints, qv.tolist(), strict=True):
        T = T @ _joint_transform(joint.axis, joint.origin_xyz, angle)
        frames.append(T)
    T_world_flange = T @ T_LINK6_FLANGE
    frames.append(T_world_flange)
    frames.append(T_world_flange @ model.tool.T_flange_tcp)
    return frames


def link_frames_batch(model: RobotModel, Q: np.ndarray) -> np.ndarray:
    """`link_frames` for many configurations at once: Q (n, 6) rad → (n, 9, 4, 4)."""
    Q = np.asarray(Q, dtype=float).reshape(-1, 6)
    n = len(Q)
    out = np.empty((n, 9, 4, 4))
    T = np.broadcast_to(model.T_world_base, (n, 4, 4)).copy()
    out[:, 0] = T
    for i, joint in enumerate(model.joints):
        c, s = np.cos(Q[:, i]), np.sin(Q[:, i])
        J = np.zeros((n, 4, 4))
        J[:, 3, 3] = 1.0
        J[:, :3, 3] = joint.origin_xyz
        a, b = {"x": (1, 2), "y": (2, 0), "z": (0, 1)}[joint.axis]
        k = 3 - a - b
        J[:, k, k] = 1.0
        J[:, a, a], J[:, a, b], J[:, b, a], J[:, b, b] = c, -s, s, c
        T = T @ J
        out[:, i + 1] = T
    out[:, 7] = T @ T_LINK6_FLANGE
    out[:, 8] = out[:, 7] @ model.tool.T_flange_tcp
    return out


def fk_flange(model: RobotModel, q: Sequence[float] | np.ndarray) -> np.ndarray:
    """(4, 4) pose of the flange (ROS-Industrial tool0) in the world at joint values `q` rad."""
    return link_frames(model, q)[7]


def fk(model: RobotModel, q: Sequence[float] | np.ndarray) -> np.ndarray:
    """(4, 4) pose of the tool centre point in the world, ``T_world_tcp``, at `q` (6,) rad."""
    return link_frames(model, q)[8]


def fk_opw(opw: OPWParameters, q: Sequence[float] | np.ndarray) -> np.ndarray:
    """(4, 4) pose of the flange in the base frame, ``T_base_flange``, by the OPW model.

    `q` are the robot's joint values (rad); they are mapped to the OPW model's angles with the
    parameters' offsets and sign corrections. Must equal the URDF chain (`fk_flange` with the
    base at the world origin); the tests check it.
    """
    t = [
        float(qi) * sgn - off
        for qi, sgn, off in zip(q, opw.sign_corrections, opw.offsets, strict=True)
    ]
    psi3 = math.atan2(opw.a2, opw.c3)
    k = math.hypot(opw.a2, opw.c3)
    cx1 = opw.c2 * math.sin(t[1]) + k * math.sin(t[1] + t[2] + psi3) + opw.a1
    cz1 = opw.c2 * math.cos(t[1]) + k * math.cos(t[1] + t[2] + psi3)
    c1, s1 = math.cos(t[0]), math.sin(t[0])
    centre = np.array([cx1 * c1 - opw.b * s1, cx1 * s1 + opw.b * c1, cz1 + opw.c1])
    R = _rot_z(t[0]) @ _rot_y(t[1] + t[2]) @ _rot_z(t[3]) @ _rot_y(t[4]) @ _rot_z(t[5])
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = centre + opw.c4 * R[:, 2]
    return T


def _rot_y(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _clamped_acos(x: float) -> float | None:
    """acos(x), or None when x is beyond ±1 by more than round-off (the pose is out of reach)."""
    if x > 1.0:
        return 0.0 if x <= 1.0 + _ACOS_SLACK else None
    if x < -1.0:
        return math.pi if x >= -1.0 - _ACOS_SLACK else None
    return math.acos(x)


def _opw_thetas(p: OPWParameters, m: list[list[float]], theta4_hint: float) -> list[list[float]]:
    """Up to 8 OPW-model angle sets that put the flange at ``m`` (T_base_flange, nested lists).

    At a wrist singularity (q5 = 0, axes 4 and 6 aligned) only θ4 + θ6 is defined; θ4 is then
    set to `theta4_hint` (OPW angle, rad) and one solution replaces the wrist pair.
    """
    r00, r01, r02 = m[0][0], m[0][1], m[0][2]
    r10, r11, r12 = m[1][0], m[1][1], m[1][2]
    r20, r21, r22 = m[2][0], m[2][1], m[2][2]
    # wrist centre: back from the flange along its z by c4
    cx = m[0][3] - p.c4 * r02
    cy = m[1][3] - p.c4 * r12
    cz = m[2][3] - p.c4 * r22
    rho2 = cx * cx + cy * cy - p.b * p.b
    if rho2 < 0.0:
        return []
    nx1 = math.sqrt(rho2) - p.a1
    tmp1 = math.atan2(cy, cx)
    tmp2 = math.atan2(p.b, nx1 + p.a1)
    dz = cz - p.c1
    kappa2 = p.a2 * p.a2 + p.c3 * p.c3
    kappa = math.sqrt(kappa2)
    c2_2 = p.c2 * p.c2
    psi3 = math.atan2(p.a2, p.c3)

    out: list[list[float]] = []
    # shoulder front (θ1 towards the wrist centre) and back (θ1 + π, reaching over)
    for theta1, horiz in ((tmp1 - tmp2, nx1), (tmp1 + tmp2 - math.pi, -(nx1 + 2.0 * p.a1))):
        s_2 = horiz * horiz + dz * dz
        s = math.sqrt(s_2)
        if s < 1e-12:
            continue
        alpha = _clamped_acos((s_2 + c2_2 - kappa2) / (2.0 * s * p.c2))
        gamma = _clamped_acos((s_2 - c2_2 - kappa2) / (2.0 * p.c2 * kappa))
        if alpha is None or gamma is None:
            continue
        direction = math.atan2(horiz, dz)
        s1, c1 = math.sin(theta1), math.cos(theta1)
        for theta2, theta3 in (
            (direction - alpha, gamma - psi3),
            (direction + alpha, -gamma - psi3),
        ):
            s23, c23 = math.sin(theta2 + theta3), math.cos(theta2 + theta3)
            # wrist: R_arm_flange = Rz(θ4) Ry(θ5) Rz(θ6) with R_base_arm = Rz(θ1) Ry(θ2 + θ3)
            cos5 = r02 * s23 * c1 + r12 * s23 * s1 + r22 * c23
            sin5 = math.sqrt(max(0.0, 1.0 - cos5 * cos5))
            if sin5 < _WRIST_SINGULAR:
                xx = c1 * c23 * r00 + s1 * c23 * r10 - s23 * r20
                yx = -s1 * r00 + c1 * r10
                if cos5 > 0.0:  # R_arm_flange = Rz(θ4 + θ6)
                    phi = math.atan2(yx, xx)
                    out.append([theta1, theta2, theta3, theta4_hint, 0.0, phi - theta4_hint])
                else:  # R_arm_flange = Rz(θ4 − θ6) Ry(π)
                    phi = math.atan2(-yx, -xx)
                    out.append([theta1, theta2, theta3, theta4_hint, math.pi, theta4_hint - phi])
                continue
            theta4 = math.atan2(r12 * c1 - r02 * s1, r02 * c23 * c1 + r12 * c23 * s1 - r22 * s23)
            theta5 = math.atan2(sin5, cos5)
            theta6 = math.atan2(
                r01 * s23 * c1 + r11 * s23 * s1 + r21 * c23,
                -r00 * s23 * c1 - r10 * s23 * s1 - r20 * c23,
            )
            out.append([theta1, theta2, theta3, theta4, theta5, theta6])
            out.append([theta1, theta2, theta3, theta4 + math.pi, -theta5, theta6 - math.pi])
    return out


@dataclass(frozen=True)
class _Tables:
    """Per-model constants of the IK's limit handling, (6,) arrays unless noted."""

    offsets: np.ndarray  # OPW offsets, rad
    signs: np.ndarray  # OPW sign corrections
    lower: np.ndarray  # rad
    upper: np.ndarray  # rad
    wrap_base: np.ndarray  # start of the 2π window each joint value is wrapped into, rad
    turns: tuple[tuple[int, np.ndarray], ...]  # multi-turn joint, its 2πk shifts (k, 1, 6)


_TABLES: WeakKeyDictionary[RobotModel, _Tables] = WeakKeyDictionary()


def _tables(model: RobotModel) -> _Tables:
    tables = _TABLES.get(model)
    if tables is None:
        lower, upper = model.lower, model.upper
        multi = (upper - lower) >= _TWO_PI
        # several turns fit: the window centred on mid-range; else the one from the lower limit
        wrap_base = np.where(multi, 0.5 * (lower + upper) - math.pi, lower - _LIMIT_SLACK)
        turns = []
        for i in np.flatnonzero(multi).tolist():
            k = int((upper[i] - lower[i]) // _TWO_PI)
            shifts = np.zeros((2 * k, 1, 6))
            shifts[:, 0, i] = [_TWO_PI * n for n in range(-k, k + 1) if n != 0]
            turns.append((i, shifts))
        tables = _Tables(
            offsets=np.array(model.opw.offsets, dtype=float),
            signs=np.array(model.opw.sign_corrections, dtype=float),
            lower=lower,
            upper=upper,
            wrap_base=wrap_base,
            turns=tuple(turns),
        )
        _TABLES[model] = tables
    return tables


def _solutions(
    model: RobotModel, T_world_tcp: np.ndarray, *, all_turns: bool, q4_hint: float
) -> np.ndarray:
    """IK solutions as rows of an (n, 6) array, rad: per OPW branch the turn nearest mid-range
    of the joints whose range exceeds 2π, or with `all_turns` every turn of those joints."""
    T = _as_pose(T_world_tcp, "T_world_tcp")
    m = (model.T_base_world @ T @ model.T_tcp_flange).tolist()
    tb = _tables(model)
    opw = model.opw
    thetas = _opw_thetas(opw, m, q4_hint * opw.sign_corrections[3] - opw.offsets[3])
    if not thetas:
        return np.empty((0, 6))
    Q = (np.array(thetas) + tb.offsets) * tb.signs
    Q = tb.wrap_base + np.mod(Q - tb.wrap_base, _TWO_PI)
    Q = Q[np.all(Q - tb.upper <= _LIMIT_SLACK, axis=1)]
    Q = np.maximum(np.minimum(Q, tb.upper), tb.lower)
    if len(Q) > 1:
        # coinciding branches (stretched or folded elbow) give equal angles up to round-off
        keys = np.round(Q, _DUPLICATE_DIGITS).tolist()
        keep = [i for i, key in enumerate(keys) if key not in keys[:i]]
        if len(keep) < len(Q):
            Q = Q[keep]
    if all_turns:
        for i, shifts in tb.turns:
            extra = (Q[None] + shifts).reshape(-1, 6)
            column = extra[:, i]
            inside = (column >= tb.lower[i] - _LIMIT_SLACK) & (column <= tb.upper[i] + _LIMIT_SLACK)
            Q = np.concatenate([Q, extra[inside]])
            Q[:, i] = np.maximum(np.minimum(Q[:, i], tb.upper[i]), tb.lower[i])
    return Q


def ik(model: RobotModel, T_world_tcp: np.ndarray, *, all_turns: bool = False) -> list[np.ndarray]:
    """Joint solutions (each (6,) rad, inside the limits) that put the TCP at `T_world_tcp`.

    Up to 8 solutions, one per shoulder/elbow/wrist branch; for joints whose range exceeds 2π
    the turn nearest the middle of the range is chosen, or, with ``all_turns=True``, every
    turn is returned too (up to 8 × 2 × 3 for the IRB1600). An unreachable pose gives ``[]``.
    """
    return list(_solutions(model, T_world_tcp, all_turns=all_turns, q4_hint=0.0))


def ik_nearest(
    model: RobotModel,
    T_world_tcp: np.ndarray,
    seed: Sequence[float] | np.ndarray,
    *,
    weights: Sequence[float] | np.ndarray | None = None,
) -> np.ndarray | None:
    """The IK solution (6,) rad nearest `seed` (6,) rad, or None if the pose is unreachable.

    Distance is ``Σ (w_i (q_i − seed_i))²`` over every branch and turn; the default weights
    ``w_i = 1 / max_velocity_i`` (s/rad) measure it in seconds of full-speed travel, so a
    slow shoulder counts more than a fast wrist. At a wrist singularity joint 4 keeps the
    seed's value.
    """
    s = _as_q(model, seed)
    w = 1.0 / model.max_velocity if weights is None else np.asarray(weights, dtype=float)
    Q = _solutions(model, T_world_tcp, all_turns=True, q4_hint=float(s[3]))
    if not len(Q):
        return None
    d = np.sum(((Q - s) * w) ** 2, axis=1)
    return Q[int(np.argmin(d))].copy()


def _shape_reach(shape: CollisionShape) -> float:
    """Largest distance (m) from the carrying frame's origin to a point of `shape`."""
    dims = np.asarray(shape.dimensions)
    extent = float(dims[0]) if shape.kind == "sphere" else float(np.linalg.norm(dims))
    return float(np.linalg.norm(shape.T_link_shape[:3, 3])) + extent


def frame_reach(model: RobotModel, carried: float = 0.0) -> np.ndarray:
    """Per frame of `link_frames`, how far (m) its geometry reaches from the frame origin.

    The flange frame carries the tool and, when given, a part whose farthest point is
    `carried` m from the flange origin.
    """
    reach = [max((_shape_reach(s) for s in shapes), default=0.0) for shapes in model.link_shapes]
    tool = max(_shape_reach(b) for b in model.tool.collision_boxes)
    reach += [0.0] * (9 - len(reach))
    reach[7] = max(reach[7], tool, carried)
    return np.array(reach)


def sweep_bound(frames_a: np.ndarray, frames_b: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """Upper bound (m) on how far any point of the arm moves between configurations.

    `frames_a` (9, 4, 4) are the `link_frames` of one configuration, `frames_b` (..., 9, 4, 4)
    those of one or many others; returns one bound per configuration of `frames_b`. A point at
    distance ≤ r from a frame's origin moves at most |Δp| + θ·r when the frame moves by Δp and
    turns by θ (the chord of a turn is shorter than its arc).
    """
    dp = np.linalg.norm(frames_b[..., :3, 3] - frames_a[:, :3, 3], axis=-1)
    trace = np.einsum("kij,...kij->...k", frames_a[:, :3, :3], frames_b[..., :3, :3])
    theta = np.arccos(np.clip((trace - 1.0) / 2.0, -1.0, 1.0))
    return np.max(dp + theta * reach, axis=-1)


__all__ = [
    "fk", "fk_flange", "fk_opw", "frame_reach", "ik", "ik_nearest", "link_frames",
    "link_frames_batch", "sweep_bound",
]  # fmt: skip
