"""Commissioning a verified layout on the cell: tasks → motion → schedule → execute → monitor.

Paper eq. 18 (π from C* to Q_plan) and eq. 21 (π_exec): every stage is deterministic.

1. The safety gate: `VerifiedJob.inspect` (the Inspector must pass the layout and sequence) —
   once; every later stage takes the job and trusts it.
2. τ_task assigns robots and waypoints (`TaskGenerator`).
3. ρ_motion plans every step in σ* order (`MotionPlanner`), one arm after the other.
4. The steps are scheduled with their real durations (two arms work in parallel where the
   assembly order and their working regions allow), the trajectories re-timed to the
   schedule, and the two arms checked against each other over the whole timeline; if they
   could meet, the job falls back to one arm at a time.
5. A driver executes Q_plan, the streaming monitor compares Q_exec, and V_traj decides.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from sdi import deadline
from sdi.errors import InputError
from sdi.execute.driver import Driver
from sdi.execute.faults import FaultScenario
from sdi.execute.job import VerifiedJob
from sdi.execute.sim import ExecutionResult, SimDriver
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.monitor import StreamingMonitor, verify_trajectory
from sdi.motion.planner import MotionPlan, MotionPlanner
from sdi.motion.scene import Scene
from sdi.motion.trajectory import JointTrajectory
from sdi.robot import RobotModel, robots_for
from sdi.tasks.generator import TaskGenerator
from sdi.tasks.schedule import Schedule
from sdi.tasks.task import TaskPlan

EPSILON = 0.05
"""Default V_traj threshold δ ≤ ε, rad (joint-space distance)."""


@dataclass
class Commissioning:
    """Everything planned for a job, ready for preview, export or execution."""

    job: VerifiedJob
    tasks: TaskPlan
    motion: MotionPlan
    schedule: Schedule
    robots: dict[str, RobotModel]
    parallel: bool
    notes: list[str] = field(default_factory=list)

    @property
    def makespan(self) -> float:
        return self.motion.makespan

    def summary(self) -> dict[str, object]:
        per_robot = {r: len(self.tasks.for_robot(r)) for r in self.tasks.robots}
        return {
            "steps": len(self.tasks.steps),
            "steps_per_robot": per_robot,
            "makespan_s": round(self.makespan, 3),
            "parallel": self.parallel,
            "planning_s_per_step": round(
                float(np.mean([s.planning_seconds for s in self.motion.steps])), 4
            )
            if self.motion.steps
            else 0.0,
            "notes": self.notes,
        }


def retime(motion: MotionPlan, schedule: Schedule, robots: Sequence[str]) -> MotionPlan:
    """Shift each step's samples to its scheduled start; robots hold still in between."""
    starts = {s.step: s.start for s in schedule.slots}
    by_robot: dict[str, list[tuple[float, np.ndarray]]] = {}
    steps = []
    events = []
    for r in robots:
        tr = motion.trajectories[r]
        rows: list[tuple[float, np.ndarray]] = [(0.0, tr.q[0])]
        clock = 0.0
        for m in sorted((m for m in motion.steps if m.robot == r), key=lambda m: m.start):
            shift = max(starts.get(m.step, m.start), clock) - m.start
            mask = (tr.t > m.start + 1e-12) & (tr.t <= m.end + 1e-12)
            if shift > 1e-9:
                rows.append((m.start + shift, rows[-1][1]))
            rows += [(float(t) + shift, q) for t, q in zip(tr.t[mask], tr.q[mask], strict=True)]
            clock = m.end + shift
            steps.append(
                type(m)(m.step, m.robot, m.part_id, m.start + shift, clock, m.planning_seconds)
            )
            events += [
                type(e)(e.t + shift, e.robot, e.kind, e.part_id)
                for e in motion.events
                if e.robot == r and m.start - 1e-12 <= e.t <= m.end + 1e-12
            ]
        ts = np.array([row[0] for row in rows])
        qs = np.array([row[1] for row in rows])
        keep = np.concatenate([[True], np.diff(ts) > 1e-9])
        by_robot[r] = list(zip(ts[keep], qs[keep], strict=True))
    trajectories = {
        r: JointTrajectory(
            r,
            np.array([t for t, _ in rows]),
            np.array([q for _, q in rows]),
            motion.trajectories[r].rate_hz,
        )
        for r, rows in by_robot.items()
    }
    return MotionPlan(
        trajectories,
        sorted(events, key=lambda e: e.t),
        sorted(steps, key=lambda s: s.step),
        motion.via,
        motion.revised,
    )


def arms_clear(
    motion: MotionPlan, robots: dict[str, RobotModel], tasks: TaskPlan, rate_hz: float = 50.0
) -> float | None:
    """First time (s) two arms come within the scene margin of each other, or None."""
    names = [r for r in tasks.robots if r in motion.trajectories]
    if len(names) < 2:
        return None
    times = np.arange(0.0, motion.makespan + 1e-9, 1.0 / rate_hz)
    with Scene({n: robots[n] for n in names}) as scene:
        import pybullet as pb

        a, b = (scene.robots[n] for n in names[:2])
        qa = motion.trajectories[names[0]].at(times)
        qb = motion.trajectories[names[1]].at(times)
        for t, q1, q2 in zip(times, qa, qb, strict=True):
            scene.set_q(names[0], q1)
            scene.set_q(names[1], q2)
            if pb.getClosestPoints(a.body, b.body, scene.margin, physicsClientId=scene.client):
                return float(t)
    return None


def order_clear(
    motion: MotionPlan, robots: dict[str, RobotModel], tasks: TaskPlan, rate_hz: float = 50.0
) -> str | None:
    """Check the re-timed plan against parts placed ahead of the assembly order.

    Each step was planned against the parts placed before it in σ*. Run in parallel, the other
    arm may already have placed parts that come later in σ*: those are obstacles the step never
    saw. For every sample of every step, the robot (and what it carries) is checked against
    exactly those parts. Returns a description of the first contact, or None.
    """
    released = {e.part_id: e.t for e in motion.events if e.kind == "release"}
    gripped = {e.part_id: e.t for e in motion.events if e.kind == "grip"}
    by_part = {s.part_id: s for s in tasks.steps}
    rank = {s.part_id: s.step for s in tasks.steps}
    with Scene({n: robots[n] for n in tasks.robots}) as scene:
        placed: list[str] = []
        for m in sorted(motion.steps, key=lambda m: m.start):
            deadline.check()
            step = by_part[m.part_id]
            ahead = sorted(
                (pid for pid, t in released.items() if rank[pid] > step.step and t < m.end),
                key=released.__getitem__,
            )
            if not ahead:
                continue
            tr = motion.trajectories[m.robot]
            for t in np.arange(m.start, m.end, 1.0 / rate_hz):
                present = [pid for pid in ahead if released[pid] <= t]
                for pid in present:
                    if pid not in placed:
                        s = by_part[pid]
                        scene.add_part(pid, s.T_world_part_target, s.part_size)
                        placed.append(pid)
                carrying = gripped[m.part_id] <= t < released[m.part_id]
                if carrying and m.robot not in scene.carried:
                    scene.attach(m.robot, step.T_tcp_part, step.part_size)
                if not carrying and m.robot in scene.carried:
                    scene.detach(m.robot)
                q = tr.at(np.array([t]))[0]
                ignore = frozenset(set(scene.parts) - set(present)) | {"table"}
                hit = scene.collides(m.robot, q, ignore_parts=ignore, margin=0.001)
                if hit is not None and ("part" in hit):
                    return f"step {step.step + 1} ({m.robot}) at t = {t:.1f} s would touch {hit}"
            scene.detach(m.robot)
    return None


def commission(
    job: VerifiedJob | Layout,
    cell: CellConfig | None = None,
    *,
    sequence: Sequence[str] | None = None,
    arms: Sequence[str] | None = None,
    robots: dict[str, RobotModel] | None = None,
    planner: MotionPlanner | None = None,
) -> Commissioning:
    """Plan a verified job for its cell (one or two arms).

    `job` is the `VerifiedJob` from the Inspector, trusted as it is (no second verification).
    A bare `Layout` (with `cell` and `sequence`) is shorthand for `VerifiedJob.inspect(layout,
    cell, sequence)` first — the one verification — and is refused if it does not pass.
    """
    if isinstance(job, Layout):
        job = VerifiedJob.inspect(job, cell, sequence)
    elif (cell is not None and cell is not job.cell) or sequence is not None:
        raise InputError("commission(job) takes the job's own cell and sequence; pass no others")
    cell = job.cell
    robots = robots or robots_for(cell)
    generator = TaskGenerator(cell, robots, arms=arms)
    tasks, _ = generator.generate(job)
    planner = planner or MotionPlanner({n: robots[n] for n in tasks.robots})
    sequential = planner.plan(job, tasks)
    if sequential.revised:
        steps = tuple(sequential.revised.get(st.step, st) for st in tasks.steps)
        tasks = TaskPlan(steps, tasks.robots, tasks.home)
    notes: list[str] = []
    durations = {m.step: m.end - m.start for m in sequential.steps}
    schedule = generator.schedule(tasks, durations)
    motion = retime(sequential, schedule, tasks.robots)
    parallel = len({s.robot for s in tasks.steps}) > 1
    if parallel:
        clash = arms_clear(motion, robots, tasks)
        reason = None if clash is None else f"the arms would meet at t = {clash:.2f} s"
        reason = reason or order_clear(motion, robots, tasks)
        if reason is not None:
            notes.append(f"in parallel, {reason}: one arm at a time")
            motion, parallel = sequential, False
            schedule = Schedule(
                tuple(
                    type(schedule.slots[0])(m.step, m.robot, m.start, m.end)
                    for m in sequential.steps
                )
            )
    return Commissioning(job, tasks, motion, schedule, robots, parallel, notes)


def execute(
    plan: Commissioning,
    *,
    epsilon: float = EPSILON,
    faults: tuple[FaultScenario, ...] = (),
    driver: Driver | None = None,
    placed: Mapping[str, Sequence[float]] | None = None,
    progress: Callable[[dict[str, Any]], None] | None = None,
) -> tuple[ExecutionResult, dict[str, object]]:
    """Run a commissioned plan on a driver (default: PyBullet) with streaming monitoring.

    `placed` (part id → pose) continues an interrupted execution from what is already built;
    `progress` is told of every part set down."""
    driver = driver or SimDriver(plan.robots, faults=faults)
    monitor = StreamingMonitor(plan.motion.trajectories, epsilon)
    result = driver.execute(
        plan.job, plan.tasks, plan.motion, monitor=monitor, placed=placed, progress=progress
    )
    check = None
    if result.executed and set(result.executed) == set(plan.motion.trajectories):
        check = verify_trajectory(plan.motion.trajectories, result.executed, epsilon)
    report: dict[str, object] = {
        "status": result.status,
        "completed_steps": result.completed_steps,
        "max_placement_error_m": round(result.max_placement_error, 5),
        "delta_rad": round(check.delta, 5) if check else None,
        "epsilon_rad": epsilon,
        "v_traj": check.verdict if check else None,
        "failure": result.failure.to_json_dict() if result.failure else None,
        "scenario": result.scenario,
    }
    return result, report
