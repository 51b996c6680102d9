"""Task plans τ_task(C*) (paper eq. 19): one pick-and-place step per part, in assembly order.

Frames: every pose is a 4×4 homogeneous transform in the world frame, named T_world_x (x in
world), metres and radians. A waypoint carries the robot's joint solution for it, so motion
planning starts from configurations already known to be reachable.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

GRASP_SECONDS = {"vacuum": 0.5, "parallel": 0.5}
"""Time to grip or release: the grippers' Modbus I/O runs at 2 Hz (paper Table I)."""


@dataclass(frozen=True)
class Waypoint:
    """A TCP pose the robot passes through, with its joint solution (rad)."""

    name: str  # "approach" | "grasp" | "retreat"
    T_world_tcp: np.ndarray
    q: np.ndarray


@dataclass(frozen=True)
class PickPlace:
    """Step k: `robot` picks `part_id` from its supply slot and places it at its design pose."""

    step: int
    part_id: str
    robot: str
    tool: str  # "vacuum" | "parallel"
    grip_axis: str | None  # world axis the fingers close along; None for vacuum
    pick: tuple[Waypoint, Waypoint, Waypoint]  # approach, grasp, retreat
    place: tuple[Waypoint, Waypoint, Waypoint]
    T_world_part_supply: np.ndarray
    T_world_part_target: np.ndarray
    part_size: tuple[float, float, float]
    T_tcp_part: np.ndarray  # where the part sits in the gripper while carried
    depends_on: tuple[int, ...] = ()
    """Steps whose placement must be finished before this one places (support, contact,
    grip keep-out): running steps in parallel never reorders these."""


@dataclass(frozen=True)
class TaskPlan:
    """All steps of a job, in the Inspector's assembly order σ*."""

    steps: tuple[PickPlace, ...]
    robots: tuple[str, ...]
    home: dict[str, np.ndarray] = field(default_factory=dict)

    def for_robot(self, robot: str) -> list[PickPlace]:
        return [s for s in self.steps if s.robot == robot]
