"""Joint trajectories: the planned Q_plan and executed Q_exec of one robot (paper eq. 4–7).

Times are seconds from the start of the job, joint values radians, sampled at the robot
controller's rate (IRB120 50 Hz, IRB1600 250 Hz). Immutable: arrays are read-only copies.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class JointTrajectory:
    """q[k] is the joint vector of `robot` at time t[k]; t strictly increasing."""

    robot: str
    t: np.ndarray  # (T,) s
    q: np.ndarray  # (T, dof) rad
    rate_hz: float
    joint_names: tuple[str, ...] = field(default=())

    def __post_init__(self) -> None:
        t = np.array(self.t, dtype=float).reshape(-1)
        q = np.array(self.q, dtype=float)
        if q.ndim != 2 or q.shape[0] != t.shape[0]:
            raise ValueError(f"q must be (T, dof) with T = len(t) = {t.shape[0]}, got {q.shape}")
        if t.size > 1 and np.any(np.diff(t) <= 0):
            raise ValueError("t must be strictly increasing")
        if not (np.all(np.isfinite(t)) and np.all(np.isfinite(q))):
            raise ValueError("t and q must be finite")
        t.setflags(write=False)
        q.setflags(write=False)
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "q", q)

    @property
    def dof(self) -> int:
        return int(self.q.shape[1])

    @property
    def duration(self) -> float:
        return float(self.t[-1] - self.t[0]) if self.t.size else 0.0

    def __len__(self) -> int:
        return int(self.t.shape[0])

    def at(self, times: np.ndarray) -> np.ndarray:
        """Nearest-timestamp samples (paper §III-E alignment), shape (len(times), dof)."""
        times = np.asarray(times, dtype=float)
        idx = np.searchsorted(self.t, times)
        idx = np.clip(idx, 1, len(self.t) - 1) if len(self.t) > 1 else np.zeros_like(idx)
        if len(self.t) > 1:
            left = self.t[idx - 1]
            right = self.t[idx]
            idx = np.where(np.abs(times - left) <= np.abs(right - times), idx - 1, idx)
        return self.q[idx]

    def concatenated(self, other: JointTrajectory) -> JointTrajectory:
        """This trajectory followed by `other` (same robot; other starts after this ends)."""
        if other.robot != self.robot:
            raise ValueError(f"cannot join {self.robot} and {other.robot} trajectories")
        if len(self) == 0:
            return other
        if len(other) == 0:
            return self
        keep = other.t > self.t[-1]
        return JointTrajectory(
            self.robot,
            np.concatenate([self.t, other.t[keep]]),
            np.concatenate([self.q, other.q[keep]]),
            self.rate_hz,
            self.joint_names,
        )
