"""One rigid box-shaped part `c_i = (id, p, q, s)` (paper eq. 2).

Frames and units: `position` is the centre of the box in metres in the world frame (z up, the
table top is z = 0); `orientation` is a unit quaternion ``[w, x, y, z]`` rotating the part frame
into the world frame; `size` is the box's edge lengths (sx, sy, sz) in metres in the part frame.
"""

from __future__ import annotations

import math
from functools import cached_property
from typing import Annotated

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, Strict, field_validator

MAX_COORDINATE = 1000.0
"""Largest |x|, |y|, |z| of a part centre, m: far beyond any cell, small enough that no
computation on it overflows (a part at x = 1e308 is refused as input, not reported as 309
digits)."""
QUAT_TOLERANCE = 1e-3
"""How far from 1 a quaternion's norm may be before it is refused (no silent renormalising)."""

PartId = Annotated[str, Field(min_length=1, max_length=64, pattern=r"^[A-Za-z0-9_.:\-]+$")]
Number = Annotated[float, Strict()]
"""A JSON number: integers and floats; no booleans or numeric strings."""
Vec3 = tuple[Number, Number, Number]
Quat = tuple[Number, Number, Number, Number]


def quat_from_yaw(yaw_rad: float) -> Quat:
    """Unit quaternion ``[w, x, y, z]`` of a rotation by `yaw_rad` about world z."""
    half = 0.5 * yaw_rad
    w, z = math.cos(half), math.sin(half)
    # Snap float noise so that multiples of 90° give exact axis-aligned boxes.
    w = 0.0 if abs(w) < 1e-12 else w
    z = 0.0 if abs(z) < 1e-12 else z
    return (w, 0.0, 0.0, z)


def rotation_matrix(q: Quat) -> np.ndarray:
    """3×3 rotation matrix (world from part) of a unit quaternion ``[w, x, y, z]``."""
    w, x, y, z = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def quat_from_matrix(R: np.ndarray) -> Quat:
    """Unit quaternion ``[w, x, y, z]`` of a 3×3 rotation matrix (inverse of `rotation_matrix`)."""
    w = math.sqrt(max(0.0, 1.0 + R[0, 0] + R[1, 1] + R[2, 2])) / 2
    if w > 1e-6:
        return (
            w,
            (R[2, 1] - R[1, 2]) / (4 * w),
            (R[0, 2] - R[2, 0]) / (4 * w),
            (R[1, 0] - R[0, 1]) / (4 * w),
        )
    i = int(np.argmax(np.diag(R)))  # a turn near 180°: start from the largest diagonal
    v = [0.0, 0.0, 0.0]
    v[i] = math.sqrt(max(0.0, 1 + 2 * R[i, i] - np.trace(R))) / 2
    for j in range(3):
        if j != i:
            v[j] = (R[j, i] + R[i, j]) / (4 * v[i])
    w = (R[(i + 2) % 3, (i + 1) % 3] - R[(i + 1) % 3, (i + 2) % 3]) / (4 * v[i])
    return (w, v[0], v[1], v[2])


class Part(BaseModel):
    """A box part. Immutable: edits make new parts (`moved`, `model_copy`)."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    id: PartId
    position: Vec3 = Field(description="centre of the box, metres, world frame, z up")
    orientation: Quat = Field(
        default=(1.0, 0.0, 0.0, 0.0), description="unit quaternion [w, x, y, z], world from part"
    )
    size: Vec3 = Field(default=(0.05, 0.05, 0.05), description="edge lengths, metres, > 0")

    @field_validator("position", "size", "orientation")
    @classmethod
    def _finite(cls, value: tuple[float, ...]) -> tuple[float, ...]:
        if not all(math.isfinite(v) for v in value):
            raise ValueError("every number must be finite (no NaN or infinity)")
        return value

    @field_validator("position")
    @classmethod
    def _bounded(cls, value: Vec3) -> Vec3:
        if max(abs(v) for v in value) > MAX_COORDINATE:
            raise ValueError(
                f"coordinates are metres and at most {MAX_COORDINATE:g} m from the origin, "
                f"got [{', '.join(f'{v:.6g}' for v in value)}]"
            )
        return value

    @field_validator("size")
    @classmethod
    def _positive(cls, value: Vec3) -> Vec3:
        if min(value) <= 0.0:
            raise ValueError(f"every edge length must be > 0 m, got {list(value)}")
        if max(value) > 10.0:
            raise ValueError(f"edge lengths are metres and at most 10 m, got {list(value)}")
        return value

    @field_validator("orientation")
    @classmethod
    def _unit(cls, value: Quat) -> Quat:
        norm = math.sqrt(sum(v * v for v in value))
        if abs(norm - 1.0) > QUAT_TOLERANCE:
            raise ValueError(
                f"quaternion [w, x, y, z] must have norm 1 (±{QUAT_TOLERANCE}), got {norm:.6g}; "
                "divide each component by the norm"
            )
        return value

    @cached_property
    def half_extents(self) -> np.ndarray:
        """Half edge lengths of the world-frame axis-aligned bounding box, metres, shape (3,)."""
        half = 0.5 * np.asarray(self.size)
        if self.orientation == (1.0, 0.0, 0.0, 0.0):
            return half
        return np.abs(rotation_matrix(self.orientation)) @ half

    @property
    def bottom(self) -> float:
        """z of the AABB's lowest face, metres."""
        return self.position[2] - float(self.half_extents[2])

    @property
    def top(self) -> float:
        """z of the AABB's highest face, metres."""
        return self.position[2] + float(self.half_extents[2])

    def moved(self, dx: float = 0.0, dy: float = 0.0, dz: float = 0.0) -> Part:
        """A copy translated by (dx, dy, dz) metres."""
        x, y, z = self.position
        return Part(
            id=self.id,
            position=(x + dx, y + dy, z + dz),
            orientation=self.orientation,
            size=self.size,
        )
