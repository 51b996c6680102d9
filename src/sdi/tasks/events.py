"""Failure events e_k = (step_k, part id, error type, target pose) (paper §III-B, Operator)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

ErrorType = Literal[
    "ik", "collision", "timeout", "unreachable", "grip", "deviation", "blocked", "placement"
]


@dataclass(frozen=True)
class FailureEvent:
    step: int
    part_id: str
    error_type: ErrorType
    target_pose: tuple[float, ...]  # x, y, z (m), qw, qx, qy, qz
    robot: str | None = None
    message: str = ""

    def to_json_dict(self) -> dict[str, Any]:
        return {
            "step": self.step,
            "part_id": self.part_id,
            "error_type": self.error_type,
            "target_pose": [round(v, 6) for v in self.target_pose],
            "robot": self.robot,
            "message": self.message,
        }
