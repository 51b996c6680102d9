"""Homogeneous transforms (4×4, metres and radians) used by the robot models.

Naming: ``T_a_b`` is the pose of frame b expressed in frame a, so ``T_a_c = T_a_b @ T_b_c`` and
a point p_b in b is ``T_a_b @ [p_b, 1]`` in a. Roll-pitch-yaw follows URDF: fixed axes x, y, z,
``R = Rz(yaw) @ Ry(pitch) @ Rx(roll)``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

Vec3 = tuple[float, float, float]


def rotation(axis: str, angle: float) -> np.ndarray:
    """(3, 3) rotation by `angle` (rad) about the unit axis ``'x'``, ``'y'`` or ``'z'``."""
    c, s = math.cos(angle), math.sin(angle)
    if axis == "x":
        return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    if axis == "y":
        return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])
    if axis == "z":
        return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    raise ValueError(f"axis must be 'x', 'y' or 'z', got {axis!r}")


def rotation_rpy(rpy: Sequence[float]) -> np.ndarray:
    """(3, 3) rotation of URDF roll, pitch, yaw (rad): ``Rz(yaw) @ Ry(pitch) @ Rx(roll)``."""
    roll, pitch, yaw = (float(v) for v in rpy)
    return rotation("z", yaw) @ rotation("y", pitch) @ rotation("x", roll)


def make_transform(
    xyz: Sequence[float] = (0.0, 0.0, 0.0), rpy: Sequence[float] = (0.0, 0.0, 0.0)
) -> np.ndarray:
    """(4, 4) transform with translation `xyz` (m) and URDF roll-pitch-yaw `rpy` (rad)."""
    T = np.eye(4)
    T[:3, :3] = rotation_rpy(rpy)
    T[:3, 3] = np.asarray(xyz, dtype=float)
    return T


def invert_transform(T: np.ndarray) -> np.ndarray:
    """Inverse of a rigid (4, 4) transform: ``T_b_a`` from ``T_a_b``."""
    R = T[:3, :3]
    out = np.eye(4)
    out[:3, :3] = R.T
    out[:3, 3] = -R.T @ T[:3, 3]
    return out


def rpy_from_matrix(R: np.ndarray) -> Vec3:
    """URDF roll, pitch, yaw (rad) of a (3, 3) rotation; at pitch = ±π/2 yaw is set to 0."""
    cos_pitch = math.hypot(float(R[0, 0]), float(R[1, 0]))
    pitch = math.atan2(-float(R[2, 0]), cos_pitch)
    if cos_pitch > 1e-9:
        roll = math.atan2(float(R[2, 1]), float(R[2, 2]))
        yaw = math.atan2(float(R[1, 0]), float(R[0, 0]))
    else:  # gimbal lock: only roll ∓ yaw is defined; put it all in roll
        roll = math.atan2(-float(R[1, 2]), float(R[1, 1]))
        yaw = 0.0
    return (roll, pitch, yaw)


def is_rigid(T: np.ndarray, tol: float = 1e-9) -> bool:
    """True if `T` is a (4, 4) proper rigid transform within `tol`."""
    if T.shape != (4, 4) or not np.all(np.isfinite(T)):
        return False
    R = T[:3, :3]
    return bool(
        np.allclose(R.T @ R, np.eye(3), atol=tol)
        and abs(np.linalg.det(R) - 1.0) < tol
        and np.allclose(T[3], (0.0, 0.0, 0.0, 1.0), atol=tol)
    )


def pose_error(T_a: np.ndarray, T_b: np.ndarray) -> tuple[float, float]:
    """Distance between two poses: (translation error m, rotation angle error rad)."""
    dp = float(np.linalg.norm(T_a[:3, 3] - T_b[:3, 3]))
    R = T_a[:3, :3].T @ T_b[:3, :3]
    # the axis-angle magnitude from the skew part is accurate for small angles, trace for large
    s = 0.5 * math.sqrt(
        (R[2, 1] - R[1, 2]) ** 2 + (R[0, 2] - R[2, 0]) ** 2 + (R[1, 0] - R[0, 1]) ** 2
    )
    c = 0.5 * (float(np.trace(R)) - 1.0)
    return dp, math.atan2(s, c)


def tool_down_pose(position: Sequence[float], yaw: float = 0.0) -> np.ndarray:
    """``T_world_tcp`` for a top grasp: the TCP at `position` (m) with its z (the approach
    direction) pointing straight down (world −z) and its x at `yaw` (rad) about world z."""
    return make_transform(position, (math.pi, 0.0, yaw))
