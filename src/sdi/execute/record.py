"""The commissioning record: the planned job as one plain-JSON value with a content hash.

When motion is planned, everything a driver or an exporter needs — per robot the timed joint
trajectory Q_plan at controller rate, the tasks with robot assignment, waypoints and the
schedule, the grip events, the cell configuration and its hash, the layout and the sequence —
becomes one canonical JSON text. Its SHA-256 is the record's hash: what the operator approves,
and what EXECUTE checks before anything moves. Floats are written with Python's shortest
round-trip repr, so `commissioning()` rebuilds exactly the arrays that were planned.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from sdi.errors import SDIError
from sdi.jsonable import plain
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout, parse_layout

if TYPE_CHECKING:
    from sdi.commission import Commissioning
    from sdi.execute.job import VerifiedJob


class RecordError(SDIError):
    """A stored record does not match its hash, the approval, the layout or the cell."""


def canonical(value: Any) -> str:
    """The canonical JSON text of a plain value (sorted keys, no spaces)."""
    return json.dumps(plain(value), sort_keys=True, separators=(",", ":"), allow_nan=False)


def sha256(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


def cell_hash(cell: CellConfig) -> str:
    """The content hash of a cell configuration (every field, defaults included)."""
    return sha256(canonical(cell.model_dump(mode="json")))


def layout_hash(layout: Layout) -> str:
    return sha256(canonical(layout.to_json_dict()))


def _arr(a: Any) -> np.ndarray:
    return np.asarray(a, dtype=float)


def _waypoint(w: Any) -> dict[str, Any]:
    return {"name": w.name, "T_world_tcp": w.T_world_tcp, "q": w.q}


def _step(s: Any) -> dict[str, Any]:
    return {
        "step": s.step, "part_id": s.part_id, "robot": s.robot, "tool": s.tool,
        "grip_axis": s.grip_axis, "pick": [_waypoint(w) for w in s.pick],
        "place": [_waypoint(w) for w in s.place], "T_world_part_supply": s.T_world_part_supply,
        "T_world_part_target": s.T_world_part_target, "part_size": s.part_size,
        "T_tcp_part": s.T_tcp_part, "depends_on": s.depends_on,
    }  # fmt: skip


@dataclass(frozen=True)
class CommissioningRecord:
    """One planned job: `text` is its canonical JSON, `hash` the SHA-256 of `text`."""

    hash: str
    text: str

    @classmethod
    def of(cls, plan: Commissioning) -> CommissioningRecord:
        job, motion = plan.job, plan.motion
        body = {
            "format": 1,
            "cell": job.cell.model_dump(mode="json"),
            "cell_hash": cell_hash(job.cell),
            "layout": job.layout.to_json_dict(),
            "layout_hash": layout_hash(job.layout),
            "sequence": list(job.sequence),
            "tasks": {
                "robots": list(plan.tasks.robots),
                "home": plan.tasks.home,
                "steps": [_step(s) for s in plan.tasks.steps],
            },
            "motion": {
                "trajectories": {
                    r: {
                        "t": tr.t,
                        "q": tr.q,
                        "rate_hz": tr.rate_hz,
                        "joint_names": list(tr.joint_names),
                    }
                    for r, tr in motion.trajectories.items()
                },
                "events": [e.__dict__ for e in motion.events],
                "steps": [m.__dict__ for m in motion.steps],
                "via": {str(k): v for k, v in motion.via.items()},
            },
            "schedule": [s.__dict__ for s in plan.schedule.slots],
            "parallel": plan.parallel,
            "notes": list(plan.notes),
        }
        text = canonical(body)
        return cls(sha256(text), text)

    @classmethod
    def load(cls, text: str, expected_hash: str) -> CommissioningRecord:
        """A stored record; refuses one whose text no longer has the hash it was stored under."""
        actual = sha256(text)
        if actual != expected_hash:
            raise RecordError(
                f"the stored commissioning record {expected_hash[:12]} was changed after it was "
                f"planned (its content now hashes to {actual[:12]}); nothing moves — plan again"
            )
        return cls(actual, text)

    @property
    def body(self) -> dict[str, Any]:
        value: dict[str, Any] = json.loads(self.text)
        return value

    def summary(self) -> dict[str, Any]:
        """What the operator approves: the hash, makespan and each robot's steps."""
        body = self.body
        steps: dict[str, list[str]] = {r: [] for r in body["tasks"]["robots"]}
        for s in body["tasks"]["steps"]:
            steps[s["robot"]].append(s["part_id"])
        makespan = max(
            (tr["t"][-1] for tr in body["motion"]["trajectories"].values() if tr["t"]), default=0.0
        )
        return {
            "record_hash": self.hash,
            "cell_hash": body["cell_hash"],
            "makespan_s": round(float(makespan), 3),
            "steps": len(body["tasks"]["steps"]),
            "steps_per_robot": {r: len(v) for r, v in steps.items()},
            "parts_per_robot": steps,
            "parallel": body["parallel"],
            "notes": body["notes"],
        }

    def cell(self) -> CellConfig:
        return CellConfig.model_validate(self.body["cell"])

    @property
    def job_hash(self) -> str:
        """The identity of the verified job this record was planned from (`VerifiedJob.hash`)."""
        from sdi.execute.job import job_hash

        body = self.body
        return job_hash(body["cell_hash"], body["layout_hash"], body["sequence"])

    def commissioning(self, cell: CellConfig, job: VerifiedJob | None = None) -> Commissioning:
        """Rebuild the planned job for a driver or exporter; refuses another cell.

        `job` is the verified job the record was planned from, when the caller still holds it
        (the orchestrator within one process): it must be that job (same hash, and it passes
        `VerifiedJob.check`), and the Inspector does not run again. Without it (a record read
        in another process, `sdi export` from a stored run) the layout and sequence pass
        `VerifiedJob.inspect` once: a record is never a way around the safety gate.
        """
        from sdi.commission import Commissioning
        from sdi.errors import UnverifiedPlanError
        from sdi.execute.job import VerifiedJob
        from sdi.motion.planner import GripEvent, MotionPlan, StepMotion
        from sdi.motion.trajectory import JointTrajectory
        from sdi.robot import robots_for
        from sdi.tasks.schedule import Schedule, Slot
        from sdi.tasks.task import PickPlace, TaskPlan, Waypoint

        body = self.body
        now = cell_hash(cell)
        if now != body["cell_hash"]:
            raise RecordError(
                f"the cell configuration changed since record {self.hash[:12]} was planned "
                f"(cell {body['cell_hash'][:12]} then, {now[:12]} now); nothing moves"
            )
        if job is None:
            layout, _ = parse_layout(body["layout"], max_parts=cell.limits.max_parts)
            job = VerifiedJob.inspect(layout, cell, body["sequence"])
        else:
            job.check()
            if job.hash != self.job_hash:
                raise UnverifiedPlanError(
                    f"refused: record {self.hash[:12]} was planned from job {self.job_hash[:12]}, "
                    f"not from job {job.hash[:12]}; nothing moves"
                )

        def waypoint(w: dict[str, Any]) -> Any:
            return Waypoint(w["name"], _arr(w["T_world_tcp"]), _arr(w["q"]))

        steps = tuple(
            PickPlace(
                step=s["step"], part_id=s["part_id"], robot=s["robot"], tool=s["tool"],
                grip_axis=s["grip_axis"], pick=tuple(waypoint(w) for w in s["pick"]),
                place=tuple(waypoint(w) for w in s["place"]),
                T_world_part_supply=_arr(s["T_world_part_supply"]),
                T_world_part_target=_arr(s["T_world_part_target"]),
                part_size=tuple(s["part_size"]), T_tcp_part=_arr(s["T_tcp_part"]),
                depends_on=tuple(s["depends_on"]),
            )
            for s in body["tasks"]["steps"]
        )  # fmt: skip
        tasks = TaskPlan(
            steps,
            tuple(body["tasks"]["robots"]),
            {r: _arr(q) for r, q in body["tasks"]["home"].items()},
        )
        m = body["motion"]
        motion = MotionPlan(
            {
                r: JointTrajectory(
                    r, _arr(tr["t"]), _arr(tr["q"]), float(tr["rate_hz"]), tuple(tr["joint_names"])
                )
                for r, tr in m["trajectories"].items()
            },
            [GripEvent(**e) for e in m["events"]],
            [StepMotion(**s) for s in m["steps"]],
            {int(k): tuple([_arr(q) for q in part] for part in v) for k, v in m["via"].items()},  # type: ignore[misc]
        )
        schedule = Schedule(tuple(Slot(**s) for s in body["schedule"]))
        robots = robots_for(cell)
        return Commissioning(
            job, tasks, motion, schedule, robots, bool(body["parallel"]), list(body["notes"])
        )
