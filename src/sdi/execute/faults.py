"""Failure injection: blocked regions that make steps fail as in the paper's Table V, and a
drift that makes the executed joints leave the plan.

A scenario is a set of regions of the cell and the error a step reports when its target part
(or the path to it) lies in one: the Operator then emits a failure event for the orchestrator
to recover from (shift, flatten, redesign or a human). `SCENARIOS` are Table V's. An execution
fault (`EXECUTION_FAULTS`) blocks nothing: from `drift_after_s` into the motion the sim driver
drives the first joint of every arm `drift_rad` off Q_plan, so Q_exec deviates and the
streaming monitor's δ breaches ε. `FAULTS` is every named fault a run may be started with.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from sdi.model.region import Region
from sdi.tasks.events import ErrorType, FailureEvent
from sdi.tasks.generator import pose_tuple
from sdi.tasks.task import PickPlace


@dataclass(frozen=True)
class FaultScenario:
    name: str
    regions: tuple[Region, ...]
    error_type: ErrorType
    description: str
    drift_rad: float = 0.0  # joint 1 of every arm driven this far off Q_plan, rad ...
    drift_after_s: float = 0.0  # ... from this long after the motion starts, s

    def check(self, step: PickPlace) -> FailureEvent | None:
        T = step.T_world_part_target
        half = np.abs(T[:3, :3]) @ (0.5 * np.array(step.part_size))
        lo, hi = T[:3, 3] - half, T[:3, 3] + half
        for region in self.regions:
            if region.blocks(lo, hi)[0]:
                return FailureEvent(
                    step=step.step,
                    part_id=step.part_id,
                    error_type=self.error_type,
                    target_pose=pose_tuple(T),
                    robot=step.robot,
                    message=f"{self.name}: target in blocked region {region.describe()}",
                )
        return None


def _r(**kw: float) -> Region:
    return Region.model_validate(kw)


SCENARIOS: dict[str, FaultScenario] = {
    s.name: s
    for s in (
        FaultScenario("workspace_boundary", (_r(x_min=0.6),), "ik", "x > 0.6 m: IK failure"),
        FaultScenario("height_limit", (_r(z_min=0.15),), "collision", "z > 0.15 m: self-collision"),
        FaultScenario(
            "singular_centre",
            (_r(x_min=0.42, x_max=0.48, y_min=0.27, y_max=0.33),),
            "ik",
            "IK singularity in the centre of the workspace",
        ),
        FaultScenario("env_collision", (_r(y_min=0.4),), "collision", "y > 0.4 m: obstacle"),
        FaultScenario(
            "combined", (_r(x_min=0.6), _r(z_min=0.15)), "ik", "x > 0.6 m and z > 0.15 m"
        ),
        FaultScenario(
            "narrow_corridor",
            (_r(x_max=0.3), _r(x_min=0.4)),
            "collision",
            "only 0.3 ≤ x ≤ 0.4 m is free",
        ),
        FaultScenario("low_ceiling", (_r(z_min=0.08),), "collision", "z > 0.08 m: low ceiling"),
        FaultScenario(
            "y_band", (_r(y_max=0.23), _r(y_min=0.37)), "collision", "only 0.23 ≤ y ≤ 0.37 m"
        ),
        FaultScenario(
            "diagonal_obstacle",
            (Region(normal=(1.0, 1.0, 0.0), offset=0.7),),
            "collision",
            "x + y > 0.7 m: diagonal obstacle",
        ),
        FaultScenario(
            "corner_pocket",
            (_r(x_max=0.55), _r(x_min=0.75), _r(y_max=0.35), _r(y_min=0.55)),
            "collision",
            "only a small pocket 0.55–0.75 × 0.35–0.55 m is free",
        ),
    )
}


EXECUTION_FAULTS: dict[str, FaultScenario] = {
    "joint_drift": FaultScenario(
        "joint_drift", (), "deviation",
        "joint 1 of every arm drifts 0.2 rad off the plan 3 s into the motion: δ breaches ε",
        drift_rad=0.2, drift_after_s=3.0,
    ),
}  # fmt: skip

FAULTS: dict[str, FaultScenario] = {**SCENARIOS, **EXECUTION_FAULTS}
"""Every named fault: Table V's blocked regions and the execution faults."""
