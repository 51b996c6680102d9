"""ρ_motion: task steps → collision-free, time-parameterised joint trajectories (paper eq. 20).

For each pick-and-place step, on the robot's current configuration and the current scene:

- free moves (to the pick approach, from the pick retreat to the place approach) are planned
  with OMPL's RRTConnect in joint space, as MoveIt does, then shortcut with OMPL's path
  simplifier;
- approach → grasp → retreat are short straight joint moves on the IK branch of the task,
  checked with a tighter clearance and allowed to touch the part's own supports;
- every segment is time-parameterised with Ruckig, rest to rest with phase synchronisation, so
  each joint follows the same profile and the motion stays on the straight joint-space segment
  that was collision-checked, under each joint's velocity and acceleration limit;
- the trajectory is sampled at the robot's controller rate and every sample is checked again.

A failure is a `MotionPlanningError` carrying a `FailureEvent` (step, part, error type, pose).
"""

from __future__ import annotations

import dataclasses
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from ompl import base as ob
from ompl import geometric as og
from ompl import util as ou
from ruckig import InputParameter, Result, Ruckig, Synchronization, Trajectory

from sdi import deadline
from sdi.errors import MotionPlanningError
from sdi.motion.scene import Scene
from sdi.motion.trajectory import JointTrajectory
from sdi.robot import RobotModel, ik, ik_nearest
from sdi.robot.kinematics import frame_reach, link_frames_batch, sweep_bound
from sdi.tasks.events import FailureEvent
from sdi.tasks.generator import pose_tuple
from sdi.tasks.task import GRASP_SECONDS, PickPlace, TaskPlan, Waypoint

if TYPE_CHECKING:
    from sdi.execute.job import VerifiedJob

ou.setLogLevel(ou.LOG_ERROR)

CHECK_RESOLUTION = 0.01
"""OMPL motion-validation step as a fraction of the state space extent."""
CLOSE_WORK_SPEED = 0.25
"""Fraction of the speed/acceleration limits for approach, grasp and retreat moves."""
SWEEP_FRACTION = 0.5
"""The dense re-check: a controller sample is checked unless no point of the arm (or the part
it carries) has moved more than this fraction of the clearance since the last checked sample
(bounded by `sweep_bound`), so every sample keeps at least half the clearance; the last sample
of every segment is always checked. Fast motion checks every sample; slow close work skips the
samples that barely move."""


@dataclass(frozen=True)
class GripEvent:
    """The gripper closes (`grip`) or opens (`release`) at time t, holding `part_id`."""

    t: float
    robot: str
    kind: str  # "grip" | "release"
    part_id: str


@dataclass(frozen=True)
class StepMotion:
    step: int
    robot: str
    part_id: str
    start: float
    end: float
    planning_seconds: float


@dataclass
class MotionPlan:
    """Q_plan: one trajectory per robot, gripper events, and per-step timing."""

    trajectories: dict[str, JointTrajectory]
    events: list[GripEvent] = field(default_factory=list)
    steps: list[StepMotion] = field(default_factory=list)
    via: dict[int, tuple[list[np.ndarray], list[np.ndarray], list[np.ndarray]]] = field(
        default_factory=dict
    )
    revised: dict[int, PickPlace] = field(default_factory=dict)
    """Steps whose waypoints the planner moved to another IK branch (the originals collide)."""
    """Per step: the checked free-space joint via points to the pick approach, from the pick
    retreat to the place approach, and from the place retreat home (ends included), for the
    exporters to replay exactly."""

    @property
    def makespan(self) -> float:
        return max((s.end for s in self.steps), default=0.0)


def _ruckig_segment(
    robot: RobotModel, qa: np.ndarray, qb: np.ndarray, dt: float, scale: float = 1.0
) -> np.ndarray:
    """Samples (every dt) of a rest-to-rest, phase-synchronised move qa → qb, incl. qb."""
    if np.allclose(qa, qb, atol=1e-9):
        return qb[None, :].copy()
    dof = len(qa)
    otg = Ruckig(dof)
    inp = InputParameter(dof)
    inp.current_position = qa.tolist()
    inp.current_velocity = [0.0] * dof
    inp.current_acceleration = [0.0] * dof
    inp.target_position = qb.tolist()
    inp.target_velocity = [0.0] * dof
    inp.target_acceleration = [0.0] * dof
    inp.max_velocity = [j.max_velocity * scale for j in robot.joints]
    inp.max_acceleration = [j.max_acceleration * scale for j in robot.joints]
    inp.max_jerk = [j.max_acceleration * 10 * scale for j in robot.joints]
    inp.synchronization = Synchronization.Phase
    traj = Trajectory(dof)
    result = otg.calculate(inp, traj)
    if result not in (Result.Working, Result.Finished):
        raise ValueError(f"ruckig could not time this move: {result}")
    n = max(1, math.ceil(traj.duration / dt))
    out = np.empty((n, dof))
    for k in range(1, n + 1):
        pos, _, _ = traj.at_time(min(k * dt, traj.duration))
        out[k - 1] = pos
    out[-1] = qb
    return out


_SEEDED: list[int] = []


def _seed_once(seed: int) -> None:
    """OMPL's RNG can be seeded once per process, before any sampling (deterministic runs)."""
    if not _SEEDED:
        ou.RNG.setSeed(seed)
        _SEEDED.append(seed)


class MotionPlanner:
    """Plans every step of a `TaskPlan` against a live `Scene`."""

    def __init__(
        self,
        robots: dict[str, RobotModel],
        *,
        margin: float = 0.005,
        timeout: float = 5.0,
        speed_scale: float = 1.0,
        seed: int = 1,
    ) -> None:
        self.robots = robots
        self.margin = margin
        self.timeout = timeout
        self.speed_scale = speed_scale
        self.last_reasons: list[str] = []
        _seed_once(seed)

    # -- OMPL --------------------------------------------------------------------------------
    def _rrt(
        self,
        scene: Scene,
        robot: str,
        qa: np.ndarray,
        qb: np.ndarray,
        fail: Callable[[str, str], MotionPlanningError],
    ) -> list[np.ndarray]:
        model = self.robots[robot]
        if self._segment_clear(scene, robot, qa, qb, frozenset(), self.margin):
            return [qa, qb]
        space = ob.RealVectorStateSpace(len(qa))
        bounds = ob.RealVectorBounds(len(qa))
        for i, j in enumerate(model.joints):
            bounds.setLow(i, j.lower)
            bounds.setHigh(i, j.upper)
        space.setBounds(bounds)
        ss = og.SimpleSetup(space)
        n = len(qa)

        def valid(state: object) -> bool:
            q = np.array([state[i] for i in range(n)])  # type: ignore[index]
            return scene.collides(robot, q) is None

        ss.setStateValidityChecker(valid)
        ss.getSpaceInformation().setStateValidityCheckingResolution(CHECK_RESOLUTION)
        start, goal = space.allocState(), space.allocState()
        for i in range(n):
            start[i] = float(qa[i])
            goal[i] = float(qb[i])
        ss.setStartAndGoalStates(start, goal)
        ss.setPlanner(og.RRTConnect(ss.getSpaceInformation()))
        solved = ss.solve(self.timeout)
        if not solved or str(solved) != "Exact solution":
            raise fail("timeout", f"RRTConnect found no path in {self.timeout:g} s")
        ss.simplifySolution(min(1.0, self.timeout))
        states = ss.getSolutionPath().getStates()
        return [np.array([s[i] for i in range(n)]) for s in states]

    def _segment_clear(
        self,
        scene: Scene,
        robot: str,
        qa: np.ndarray,
        qb: np.ndarray,
        ignore: frozenset[str],
        margin: float,
    ) -> bool:
        steps = max(2, math.ceil(float(np.max(np.abs(qb - qa))) / 0.02) + 1)
        return all(
            scene.collides(robot, qa + (qb - qa) * s, ignore_parts=ignore, margin=margin) is None
            for s in np.linspace(0.0, 1.0, steps)
        )

    # -- IK branches ---------------------------------------------------------------------------
    def _free_branch(
        self,
        scene: Scene,
        robot: str,
        wps: tuple[Waypoint, Waypoint, Waypoint],
        q_from: np.ndarray,
        ignore: frozenset[str],
    ) -> tuple[Waypoint, Waypoint, Waypoint] | None:
        """Approach/grasp/retreat on a collision-free IK branch, nearest `q_from` first."""
        model = self.robots[robot]
        reasons: list[str] = []

        def ok(up: np.ndarray, at: np.ndarray) -> bool:
            hit = scene.collides(robot, up)
            where = "approach"
            if hit is None:
                hit = scene.collides(robot, at, ignore_parts=ignore, margin=0.001)
                where = "grasp"
            if hit is not None:
                reasons.append(f"{hit} at the {where}")
            return hit is None

        if ok(wps[0].q, wps[1].q):
            return wps
        for up in sorted(
            ik(model, wps[0].T_world_tcp), key=lambda q: float(np.sum(np.abs(q - q_from)))
        ):
            at = ik_nearest(model, wps[1].T_world_tcp, up)
            if at is None or float(np.max(np.abs(at - up))) > 1.5:
                reasons.append("no IK branch joins the approach and the grasp")
                continue
            if not ok(up, at):
                continue
            return (
                Waypoint(wps[0].name, wps[0].T_world_tcp, up),
                Waypoint(wps[1].name, wps[1].T_world_tcp, at),
                Waypoint(wps[2].name, wps[2].T_world_tcp, up),
            )
        self.last_reasons = sorted(set(reasons))
        return None

    # -- one step ----------------------------------------------------------------------------
    def plan_step(
        self, scene: Scene, step: PickPlace, q0: np.ndarray, t0: float, home: np.ndarray
    ) -> tuple[
        list[tuple[float, np.ndarray]],
        list[GripEvent],
        float,
        float,
        tuple[list[np.ndarray], list[np.ndarray], list[np.ndarray]],
    ]:
        """Sampled motion of `step` from q0 at time t0: (samples, grip events, end, seconds).

        The scene is updated as the step runs (part attached, then placed); each segment is
        sampled at the controller rate and every sample re-checked in the scene of its time.
        """
        started = time.perf_counter()
        robot = step.robot
        model = self.robots[robot]
        dt = 1.0 / model.controller_rate_hz

        def fail(kind: str, message: str, pose: np.ndarray | None = None) -> MotionPlanningError:
            T = step.T_world_part_target if pose is None else pose
            event = FailureEvent(
                step=step.step, part_id=step.part_id, error_type=kind,  # type: ignore[arg-type]
                target_pose=pose_tuple(T), robot=robot, message=message,
            )  # fmt: skip
            return MotionPlanningError(
                f"step {step.step + 1} ({step.part_id}, {robot}): {kind}: {message}", event=event
            )

        samples: list[tuple[float, np.ndarray]] = []
        events: list[GripEvent] = []
        clock = [t0]
        q_now = [q0]

        def move(path: list[np.ndarray], ignore: frozenset[str], margin: float, what: str) -> None:
            # close work (1 mm clearance, parts meeting) runs slowly, like MoveL v100
            scale = self.speed_scale * (CLOSE_WORK_SPEED if margin < self.margin else 1.0)
            held = scene.carried.get(robot)
            carried = 0.0
            if held is not None:
                T_flange_part = model.tool.T_flange_tcp @ held[1]
                half = 0.5 * float(np.linalg.norm(step.part_size))
                carried = float(np.linalg.norm(T_flange_part[:3, 3])) + half
            reach = frame_reach(model, carried)
            allowed = SWEEP_FRACTION * margin
            for target in path:
                seg = _ruckig_segment(model, q_now[0], target, dt, scale)
                frames = link_frames_batch(model, seg)
                checked = link_frames_batch(model, q_now[0])[0]
                k = 0
                while k < len(seg):  # the next sample that moved too far (or every 32nd)
                    window = frames[k : k + 32]
                    over = np.flatnonzero(sweep_bound(checked, window, reach) > allowed)
                    j = k + (int(over[0]) if len(over) else len(window) - 1)
                    hit = scene.collides(robot, seg[j], ignore_parts=ignore, margin=margin)
                    if hit is not None:
                        raise fail("collision", f"{what}: the trajectory touches {hit}")
                    checked, k = frames[j], j + 1
                for row in seg:
                    clock[0] += dt
                    samples.append((clock[0], row))
                q_now[0] = target

        def hold(kind: str) -> None:
            # the arm settles at the stop point for the dwell, then the gripper acts
            for _ in range(max(1, round(GRASP_SECONDS[step.tool] / dt))):
                clock[0] += dt
                samples.append((clock[0], q_now[0].copy()))
            events.append(GripEvent(clock[0], robot, kind, step.part_id))
            clock[0] += dt
            samples.append((clock[0], q_now[0].copy()))

        supports = self._touching(scene, step)
        pick = self._free_branch(scene, robot, step.pick, q0, frozenset({"table"}))
        if pick is None:
            raise fail(
                "collision", "every IK branch at the supply collides", step.T_world_part_supply
            )
        if pick is not step.pick:
            step = dataclasses.replace(step, pick=pick)
        T = step.T_world_part_target
        bottom = T[2, 3] - float((np.abs(T[:3, :3]) @ (0.5 * np.array(step.part_size)))[2])
        if bottom < 0.002:
            supports = supports | {"table"}
        close = 0.001
        supply = step.T_world_part_supply
        path = self._rrt(scene, robot, q0, step.pick[0].q, lambda k, m: fail(k, m, supply))
        to_pick = path[1:]
        move(path[1:], frozenset(), self.margin, "to the pick approach")
        move([step.pick[1].q], frozenset(), close, "down to the supply")
        hold("grip")
        scene.attach(robot, step.T_tcp_part, step.part_size)
        move([step.pick[2].q], frozenset({"table"}), close, "lifting from the supply")
        place = self._free_branch(scene, robot, step.place, step.pick[2].q, supports)
        if place is None:
            raise fail(
                "collision",
                f"every IK branch at the target collides ({'; '.join(self.last_reasons)})",
            )
        if place is not step.place:
            step = dataclasses.replace(step, place=place)
        path = self._rrt(scene, robot, step.pick[2].q, step.place[0].q, fail)
        to_place = path[1:]
        move(path[1:], frozenset(), self.margin, "carrying to the target")
        move([step.place[1].q], supports, close, "down to the target")
        hold("release")
        scene.detach(robot)
        scene.add_part(step.part_id, step.T_world_part_target, step.part_size)
        move([step.place[2].q], supports | {step.part_id}, close, "retreating from the target")
        # back to its home over its own supply, out of the other arm's way
        path = self._rrt(scene, robot, step.place[2].q, home, fail)
        to_home = path[1:]
        move(path[1:], frozenset(), self.margin, "returning home")
        seconds = time.perf_counter() - started
        self._last_step = step
        return samples, events, clock[0], seconds, (to_pick, to_place, to_home)

    def _touching(self, scene: Scene, step: PickPlace) -> frozenset[str]:
        """Placed parts within 2 mm of the target box: the part may touch them when set down."""
        import pybullet as pb

        probe = scene._box(step.part_size)
        T = step.T_world_part_target
        from sdi.motion.scene import _quat_xyzw

        pb.resetBasePositionAndOrientation(
            probe, T[:3, 3].tolist(), _quat_xyzw(T[:3, :3]), physicsClientId=scene.client
        )
        near = frozenset(scene.near_parts(probe, 0.002))
        pb.removeBody(probe, physicsClientId=scene.client)
        return near

    # -- the whole job -----------------------------------------------------------------------
    def plan(self, job: VerifiedJob, tasks: TaskPlan) -> MotionPlan:
        """Q_plan for every step of the verified job's task plan in σ* order, each arm one step
        after another (`retime` in `sdi.commission` moves the steps to a two-arm schedule).
        The job is trusted; `VerifiedJob.admit` only checks it is the one the Inspector passed
        and that `tasks` are its steps."""
        job.admit(tasks)
        with Scene(self.robots, margin=self.margin) as scene:
            q_now = {r: tasks.home[r].copy() for r in tasks.robots}
            for r, q in q_now.items():
                scene.set_q(r, q)
            samples: dict[str, list[tuple[float, np.ndarray]]] = {
                r: [(0.0, q_now[r].copy())] for r in tasks.robots
            }
            clock = dict.fromkeys(tasks.robots, 0.0)
            events: list[GripEvent] = []
            steps: list[StepMotion] = []
            via: dict[int, tuple[list[np.ndarray], list[np.ndarray], list[np.ndarray]]] = {}
            revised: dict[int, PickPlace] = {}
            for step in tasks.steps:
                deadline.check()
                robot = step.robot
                for r in tasks.robots:  # the other arms stand where they last stopped
                    if r != robot:
                        scene.set_q(r, q_now[r])
                t0 = clock[robot]
                rows, evs, end, seconds, via[step.step] = self.plan_step(
                    scene, step, q_now[robot], t0, tasks.home[robot]
                )
                samples[robot].extend(rows)
                events.extend(evs)
                q_now[robot] = rows[-1][1] if rows else q_now[robot]
                clock[robot] = end
                steps.append(StepMotion(step.step, robot, step.part_id, t0, end, seconds))
                if self._last_step is not step:
                    revised[step.step] = self._last_step
            trajectories = {}
            for r, rows in samples.items():
                rate = self.robots[r].controller_rate_hz
                ts = np.array([row[0] for row in rows])
                qs = np.array([row[1] for row in rows])
                keep = np.concatenate([[True], np.diff(ts) > 1e-9])
                trajectories[r] = JointTrajectory(r, ts[keep], qs[keep], rate)
        return MotionPlan(trajectories, events, steps, via, revised)
