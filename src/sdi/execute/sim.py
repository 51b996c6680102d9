"""The `sim` driver: PyBullet physics executes Q_plan on simulated robots and real parts.

- The robots (the project's URDFs) follow Q_plan with joint position control, stepped at
  `physics_hz`; Q_exec is read from the simulated encoders at each robot's controller rate.
- Parts are dynamic boxes (mass from their volume and `density`, friction) that appear on the
  robot's supply slot when its step begins, are carried, released and settle under gravity.
- Gripping follows the tool: the vacuum holds a part only if its top face is under the cups;
  the parallel gripper only if the part sits between the pads. A held part is fixed to the TCP
  by a constraint at its actual relative pose, so tracking errors carry through to placement.
- Every Q_exec sample goes to the streaming monitor; execution pauses at the first breach.
- Failure injection: a step whose target lies in a blocked region fails before it moves; a
  drift fault drives joint 1 of every arm off Q_plan (the monitor then stops the execution).
- Progress: `progress` is told when motion starts (``kind: motion_started``), of every part
  set down (``kind: step_done``: step, part, robot, its pose then) and, once a simulated
  second, of Q_exec and δ so far (``kind: samples``), so
  an interrupted execution leaves a record of what is built; `placed` starts an execution
  from such a record: those parts stand where they were set down, their steps are skipped,
  and the robots start where the first step still to do begins.

Only a `VerifiedJob` is accepted, and it is checked (`VerifiedJob.admit`: the job the Inspector
passed, unaltered, and the task plan is its steps) before anything moves.
"""

from __future__ import annotations

import math
import tempfile
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pybullet as pb

from sdi import deadline
from sdi.execute.faults import FaultScenario
from sdi.execute.job import VerifiedJob
from sdi.motion.planner import MotionPlan
from sdi.motion.scene import TABLE_CENTRE, TABLE_HALF, _quat_xyzw
from sdi.motion.trajectory import JointTrajectory
from sdi.robot import RobotModel, write_urdf
from sdi.tasks.events import FailureEvent
from sdi.tasks.generator import pose_tuple
from sdi.tasks.task import TaskPlan

DISTURBANCE = 0.003
"""A placed part that moves more than this (m) after settling was disturbed: execution stops."""

SAMPLE_BATCH_S = 1.0
"""Q_exec goes to `progress` in batches of this much simulated time, s ..."""
SAMPLE_BATCH_HZ = 10.0
"""... thinned to this rate, Hz (a live view; the full Q_exec is in the result)."""


@dataclass
class ExecutionResult:
    """What happened: Q_exec, the as-built part poses and errors, and any failure event."""

    status: str  # "success" | "failure" | "paused"
    executed: dict[str, JointTrajectory]
    as_built: dict[str, tuple[float, ...]] = field(default_factory=dict)
    placement_error: dict[str, float] = field(default_factory=dict)  # m, centre distance
    failure: FailureEvent | None = None
    completed_steps: int = 0
    simulated_seconds: float = 0.0
    scenario: str | None = None  # the injected fault scenario that stopped execution

    @property
    def max_placement_error(self) -> float:
        return max(self.placement_error.values(), default=0.0)


def _pose_matrix(pos: tuple[float, ...], quat_xyzw: tuple[float, ...]) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = np.array(pb.getMatrixFromQuaternion(quat_xyzw)).reshape(3, 3)
    T[:3, 3] = pos
    return T


class SimDriver:
    """Executes verified jobs in PyBullet (DIRECT, headless)."""

    name = "sim"

    def __init__(
        self,
        robots: dict[str, RobotModel],
        *,
        physics_hz: float = 1000.0,
        density: float = 700.0,
        friction: float = 0.9,
        faults: tuple[FaultScenario, ...] = (),
        settle_seconds: float = 0.5,
        placement_tolerance: float = 0.005,
        solver_iterations: int = 150,
        position_gain: float = 0.8,
    ) -> None:
        self.robots = robots
        self.physics_hz = physics_hz
        self.density = density
        self.friction = friction
        self.faults = faults
        self.settle_seconds = settle_seconds
        self.placement_tolerance = placement_tolerance
        self.solver_iterations = solver_iterations
        self.position_gain = position_gain

    def execute(
        self,
        job: VerifiedJob,
        tasks: TaskPlan,
        motion: MotionPlan,
        *,
        monitor: object | None = None,
        placed: Mapping[str, Sequence[float]] | None = None,
        progress: Callable[[dict[str, Any]], None] | None = None,
    ) -> ExecutionResult:
        """Run the job; `monitor` is a streaming monitor with `update(robot, t, q)`.

        `placed` maps parts already built to their poses (x, y, z m, qw, qx, qy, qz): the run
        continues from there. `progress` receives one dict per part set down."""
        job.admit(tasks)  # the safety gate: the job the Inspector passed, and its steps
        c = pb.connect(pb.DIRECT)
        tmp = tempfile.TemporaryDirectory(prefix="sdi-sim-")
        try:
            return self._run(
                c, Path(tmp.name), job, tasks, motion, monitor, dict(placed or {}), progress
            )
        finally:
            pb.disconnect(c)
            tmp.cleanup()

    def _run(
        self,
        c: int,
        tmp: Path,
        job: VerifiedJob,
        tasks: TaskPlan,
        motion: MotionPlan,
        monitor: object | None,
        placed: dict[str, Sequence[float]],
        progress: Callable[[dict[str, Any]], None] | None,
    ) -> ExecutionResult:
        dt = 1.0 / self.physics_hz
        unknown = set(placed) - {s.part_id for s in tasks.steps}
        if unknown:
            from sdi.errors import UnverifiedPlanError

            raise UnverifiedPlanError(f"refused: parts {sorted(unknown)} are not in this job")
        todo = [m for m in motion.steps if m.part_id not in placed]
        t0 = min((m.start for m in todo), default=0.0)
        pb.setGravity(0, 0, -9.81, physicsClientId=c)
        pb.setTimeStep(dt, physicsClientId=c)
        pb.setPhysicsEngineParameter(numSolverIterations=self.solver_iterations, physicsClientId=c)
        table_shape = pb.createCollisionShape(
            pb.GEOM_BOX, halfExtents=TABLE_HALF, physicsClientId=c
        )
        table = pb.createMultiBody(0, table_shape, basePosition=TABLE_CENTRE, physicsClientId=c)
        pb.changeDynamics(table, -1, lateralFriction=self.friction, physicsClientId=c)
        bodies: dict[str, tuple[int, list[int], int]] = {}
        for name in tasks.robots:
            model = self.robots[name]
            path = write_urdf(model, tmp / name)
            T = model.T_world_base
            body = pb.loadURDF(
                str(path), T[:3, 3].tolist(), _quat_xyzw(T[:3, :3]), useFixedBase=True,
                physicsClientId=c,
            )  # fmt: skip
            joints, tcp = [], -1
            for j in range(pb.getNumJoints(body, physicsClientId=c)):
                info = pb.getJointInfo(body, j, physicsClientId=c)
                if info[2] == pb.JOINT_REVOLUTE:
                    joints.append(j)
                if info[12].decode() == "tcp":
                    tcp = j
            q0 = motion.trajectories[name].at(np.array([t0]))[0]
            for j, v in zip(joints, q0, strict=True):
                pb.resetJointState(body, j, float(v), physicsClientId=c)
            bodies[name] = (body, joints, tcp)

        steps = {s.step: s for s in tasks.steps}
        starts = {m.step: m.start for m in motion.steps}
        events = sorted(motion.events, key=lambda e: e.t)
        parts: dict[str, int] = {}
        held: dict[str, tuple[int, str]] = {}  # robot → (constraint, part id)
        spawned: set[int] = set()
        released: dict[str, float] = {}
        settled: dict[str, np.ndarray] = {}
        failure: FailureEvent | None = None
        scenario_name: str | None = None
        status = "success"
        for built in tasks.steps:  # what an earlier, interrupted execution built stays built
            if built.part_id in placed:
                pose = [float(v) for v in placed[built.part_id]]
                T = _pose_matrix(tuple(pose[:3]), (pose[4], pose[5], pose[6], pose[3]))
                parts[built.part_id] = self._spawn(c, T, built.part_size)
                spawned.add(built.step)
                released[built.part_id] = t0 - 1.0
        end = max(tr.t[-1] for tr in motion.trajectories.values())
        recorded: dict[str, list[tuple[float, np.ndarray]]] = {r: [] for r in tasks.robots}
        next_sample = dict.fromkeys(tasks.robots, 0.0)
        events = [e for e in events if e.part_id not in placed]
        ev = 0
        n_steps = math.ceil(end / dt) + 1
        done_steps = len(placed)
        check_every = max(1, round(1.0 / dt))  # the phase's wall-clock limit, once a sim second
        first = math.ceil(t0 / dt - 1e-9) if todo else n_steps
        batch_every = max(1, round(SAMPLE_BATCH_S * self.physics_hz))
        sent = dict.fromkeys(tasks.robots, 0)  # Q_exec samples already in a batch, per robot
        for k in range(first, n_steps):
            if k % check_every == 0:
                deadline.check()
            t = k * dt
            if k == first and progress is not None:
                progress({"kind": "motion_started", "t": round(t, 4)})
            # parts appear on the supply when their step begins; injected faults fire there
            for s, t_start in starts.items():
                if s in spawned or t + 1e-12 < t_start:
                    continue
                spawned.add(s)
                step = steps[s]
                for scenario in self.faults:
                    event = scenario.check(step)
                    if event is not None:
                        failure, status = event, "failure"
                        scenario_name = scenario.name
                        break
                if failure is not None:
                    break
                parts[step.part_id] = self._spawn(c, step.T_world_part_supply, step.part_size)
            if failure is not None:
                break
            while ev < len(events) and events[ev].t <= t + 1e-12:
                e = events[ev]
                ev += 1
                body, _, tcp = bodies[e.robot]
                step = next(s for s in tasks.steps if s.part_id == e.part_id)
                part = parts[e.part_id]
                if e.kind == "grip":
                    problem = self._grippable(c, body, tcp, part, step.tool, step.part_size)
                    if problem:
                        failure = FailureEvent(
                            step=step.step, part_id=step.part_id, error_type="grip",
                            target_pose=pose_tuple(step.T_world_part_supply), robot=e.robot,
                            message=problem,
                        )  # fmt: skip
                        status = "failure"
                        break
                    held[e.robot] = (self._attach(c, body, tcp, part), e.part_id)
                else:
                    constraint, _ = held.pop(e.robot)
                    pb.removeConstraint(constraint, physicsClientId=c)
                    pb.changeDynamics(
                        parts[e.part_id], -1, physicsClientId=c,
                        activationState=pb.ACTIVATION_STATE_ENABLE_SLEEPING,
                    )  # fmt: skip
                    done_steps += 1
                    released[e.part_id] = t
                    if progress is not None:
                        pos, orn = pb.getBasePositionAndOrientation(
                            parts[e.part_id], physicsClientId=c
                        )
                        progress({
                            "kind": "step_done", "step": step.step, "part_id": e.part_id,
                            "robot": e.robot, "t": round(t, 4), "completed": done_steps,
                            "pose": list(pose_tuple(_pose_matrix(pos, orn))),
                        })  # fmt: skip
            if failure is not None:
                break
            drift = sum(f.drift_rad for f in self.faults if t - t0 >= f.drift_after_s)
            for name, (body, joints, _) in bodies.items():
                self._control(c, body, joints, motion.trajectories[name], t, drift)
            pb.stepSimulation(physicsClientId=c)
            breach = None
            for name, (body, joints, _) in bodies.items():
                if t + 1e-12 >= next_sample[name]:
                    q = np.array([s[0] for s in pb.getJointStates(body, joints, physicsClientId=c)])
                    recorded[name].append((t, q))
                    next_sample[name] += 1.0 / self.robots[name].controller_rate_hz
                    if monitor is not None:
                        breach = monitor.update(name, t, q) or breach  # type: ignore[attr-defined]
            if progress is not None and k > first and k % batch_every == 0:
                self._batch(progress, recorded, sent, monitor)
            # placed parts must stay where they were set down (checked every 50 ms, after
            # they had 0.2 s to settle)
            if k % max(1, int(0.05 * self.physics_hz)) == 0:
                for pid, t_rel in released.items():
                    if t - t_rel < 0.2:
                        continue
                    pos, _ = pb.getBasePositionAndOrientation(parts[pid], physicsClientId=c)
                    if pid not in settled:
                        settled[pid] = np.array(pos)
                        continue
                    moved = float(np.linalg.norm(np.array(pos) - settled[pid]))
                    if moved > DISTURBANCE:
                        touching = sorted(
                            {name for name, (body, _, _) in bodies.items()
                             if pb.getContactPoints(body, parts[pid], physicsClientId=c)}
                        )  # fmt: skip
                        step = next(s for s in tasks.steps if s.part_id == pid)
                        status = "failure"
                        who = ", ".join(touching) or "another part"
                        failure = FailureEvent(
                            step=step.step, part_id=pid, error_type="collision",
                            target_pose=pose_tuple(step.T_world_part_target), robot=step.robot,
                            message=f"placed part {pid} was disturbed by {moved * 1000:.1f} mm at "
                            f"t = {t:.2f} s (touching: {who})",
                        )  # fmt: skip
                        break
                if failure is not None:
                    break
            if breach is not None:
                status = "paused"
                if drift:
                    scenario_name = next(f.name for f in self.faults if f.drift_rad)
                step_now = max(
                    (m for m in motion.steps if m.start <= t), key=lambda m: m.start, default=None
                )
                current = steps[step_now.step] if step_now else tasks.steps[0]
                failure = FailureEvent(
                    step=current.step, part_id=current.part_id, error_type="deviation",
                    target_pose=pose_tuple(current.T_world_part_target), robot=breach.robot,
                    message=f"δ = {breach.deviation:.4f} rad exceeded ε at t = {breach.t:.3f} s",
                )  # fmt: skip
                break
        if progress is not None:
            self._batch(progress, recorded, sent, monitor)
        for _ in range(int(self.settle_seconds * self.physics_hz)):
            pb.stepSimulation(physicsClientId=c)
        as_built: dict[str, tuple[float, ...]] = {}
        errors: dict[str, float] = {}
        for finished in tasks.steps:
            if finished.part_id not in released:
                continue  # never set down (execution stopped before its step)
            pos, orn = pb.getBasePositionAndOrientation(parts[finished.part_id], physicsClientId=c)
            T = _pose_matrix(pos, orn)
            as_built[finished.part_id] = pose_tuple(T)
            errors[finished.part_id] = float(
                np.linalg.norm(T[:3, 3] - finished.T_world_part_target[:3, 3])
            )
        if failure is None and errors:
            # the as-built check: every part must end where the design put it
            worst = max(errors, key=lambda pid: errors[pid])
            if errors[worst] > self.placement_tolerance:
                step = next(s for s in tasks.steps if s.part_id == worst)
                status = "failure"
                failure = FailureEvent(
                    step=step.step, part_id=worst, error_type="placement",
                    target_pose=pose_tuple(step.T_world_part_target), robot=step.robot,
                    message=f"as built {errors[worst] * 1000:.1f} mm from its design pose "
                    f"(tolerance {self.placement_tolerance * 1000:.1f} mm)",
                )  # fmt: skip
        executed = {}
        for name, rows in recorded.items():
            if rows:
                executed[name] = JointTrajectory(
                    name, np.array([r[0] for r in rows]), np.array([r[1] for r in rows]),
                    self.robots[name].controller_rate_hz,
                )  # fmt: skip
        return ExecutionResult(
            status=status,
            executed=executed,
            as_built=as_built,
            placement_error=errors,
            failure=failure,
            completed_steps=done_steps,
            simulated_seconds=min(end, n_steps * dt),
            scenario=scenario_name,
        )

    def _batch(
        self,
        progress: Callable[[dict[str, Any]], None],
        recorded: dict[str, list[tuple[float, np.ndarray]]],
        sent: dict[str, int],
        monitor: object | None,
    ) -> None:
        """One `samples` event: each robot's Q_exec since the last batch (t s, q rad) at
        `SAMPLE_BATCH_HZ`, and the largest δ so far (rad)."""
        q: dict[str, list[list[float]]] = {}
        for name, rows in recorded.items():
            every = max(1, round(self.robots[name].controller_rate_hz / SAMPLE_BATCH_HZ))
            new = rows[sent[name] :]
            kept = new[::every]
            if new and (len(new) - 1) % every:  # the batch ends on its last sample (a breach
                kept.append(new[-1])  # stops execution there: the page must see it)
            q[name] = [[round(t, 4), *(round(float(v), 6) for v in qq)] for t, qq in kept]
            sent[name] = len(rows)
        if not any(q.values()):
            return
        delta = getattr(monitor, "max_deviation", None)
        progress({"kind": "samples", "q": q,
                  "delta_max_rad": None if delta is None else round(float(delta), 6)})  # fmt: skip

    def _control(
        self, c: int, body: int, joints: list[int], tr: JointTrajectory, t: float, drift: float
    ) -> None:
        """Joint position control with velocity feed-forward from Q_plan; `drift` (rad, an
        injected fault) is added to joint 1's target."""
        target = tr.at(np.array([t]))[0].copy()
        ahead = tr.at(np.array([t + 1.0 / tr.rate_hz]))[0]
        velocity = (ahead - target) * tr.rate_hz  # feed-forward, rad/s
        target[0] += drift
        n = len(joints)
        pb.setJointMotorControlArray(
            body, joints, pb.POSITION_CONTROL, targetPositions=target.tolist(),
            targetVelocities=velocity.tolist(), forces=[5000.0] * n,
            positionGains=[self.position_gain] * n, velocityGains=[1.0] * n, physicsClientId=c,
        )  # fmt: skip

    def _spawn(self, c: int, T: np.ndarray, size: tuple[float, float, float]) -> int:
        half = [s / 2 for s in size]
        shape = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=c)
        mass = self.density * size[0] * size[1] * size[2]
        body = pb.createMultiBody(
            mass, shape, basePosition=T[:3, 3].tolist(), baseOrientation=_quat_xyzw(T[:3, :3]),
            physicsClientId=c,
        )  # fmt: skip
        # A resting box creeps ~0.3 mm per 30 s under PyBullet's contact solver (the bottom row
        # of a wall drifted 3 mm over a 25-part job); sleeping stops that, and a contact with
        # anything moving wakes the part again.
        pb.changeDynamics(
            body, -1, lateralFriction=self.friction,
            activationState=pb.ACTIVATION_STATE_ENABLE_SLEEPING, physicsClientId=c,
        )  # fmt: skip
        return body

    def _grippable(
        self, c: int, robot: int, tcp: int, part: int, tool: str, size: tuple[float, float, float]
    ) -> str | None:
        """Why the tool cannot hold the part here, or None (vacuum: top face; fingers: sides)."""
        state = pb.getLinkState(robot, tcp, computeForwardKinematics=True, physicsClientId=c)
        T_tcp = _pose_matrix(state[4], state[5])
        pos, orn = pb.getBasePositionAndOrientation(part, physicsClientId=c)
        T_part = _pose_matrix(pos, orn)
        p = np.linalg.inv(T_part) @ T_tcp[:, 3]  # TCP in the part frame
        half = 0.5 * np.array(size)
        if tool == "vacuum":
            if abs(p[2] - half[2]) > 0.004:
                return f"suction cups {abs(p[2] - half[2]) * 1000:.1f} mm off the top face"
            if abs(p[0]) > half[0] - 0.01 or abs(p[1]) > half[1] - 0.01:
                return "suction cups not over the top face"
            return None
        if abs(p[0]) > half[0] or abs(p[1]) > half[1] or not -half[2] <= p[2] <= half[2]:
            return "the part is not between the finger pads"
        return None

    def _attach(self, c: int, robot: int, tcp: int, part: int) -> int:
        # held parts never fall asleep (a sleeping part would stop following the gripper)
        for state in (pb.ACTIVATION_STATE_WAKE_UP, pb.ACTIVATION_STATE_DISABLE_SLEEPING):
            pb.changeDynamics(part, -1, activationState=state, physicsClientId=c)
        state = pb.getLinkState(robot, tcp, computeForwardKinematics=True, physicsClientId=c)
        pos, orn = pb.getBasePositionAndOrientation(part, physicsClientId=c)
        inv_pos, inv_orn = pb.invertTransform(state[4], state[5])
        rel_pos, rel_orn = pb.multiplyTransforms(inv_pos, inv_orn, pos, orn)
        for link in range(-1, pb.getNumJoints(robot, physicsClientId=c)):
            pb.setCollisionFilterPair(robot, part, link, -1, 0, physicsClientId=c)
        constraint = pb.createConstraint(
            robot, tcp, part, -1, pb.JOINT_FIXED, [0, 0, 0], rel_pos, [0, 0, 0],
            parentFrameOrientation=rel_orn, physicsClientId=c,
        )  # fmt: skip
        pb.changeConstraint(constraint, maxForce=1e4, physicsClientId=c)
        return constraint
