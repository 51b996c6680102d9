"""τ_task: a verified, sequenced layout → pick-and-place steps with robots and waypoints.

For each part in σ*, in order:

1. the grip options still open when it is placed (the Inspector's gripping model) give the
   tool kinds that can take it; the vacuum grips the top face, the fingers close along a free
   world axis β with the pads a little below the top;
2. each robot with such a tool is tried: the part comes from that robot's supply area (known
   poses; a slot is refilled after each pick), and IK must exist for approach, grasp and
   retreat at the supply and at the target, on one branch, near the robot's last pose;
3. among the robots that can do it, the one that would finish it earliest (estimated from
   joint distances under velocity and acceleration limits) gets it.

The safety gate: steps are made only for a `VerifiedJob` (the Inspector passed its layout and
sequence once, in `VerifiedJob.inspect`); the generator trusts the job and does not re-verify.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from sdi.errors import InputError, MotionPlanningError, UnverifiedPlanError
from sdi.inspector.analysis import Analysis
from sdi.model.cell import CellConfig, ParallelGripper, SupplyArea
from sdi.model.layout import Layout
from sdi.model.part import quat_from_matrix, rotation_matrix
from sdi.robot import RobotModel, ik, ik_nearest, robots_for
from sdi.tasks.events import FailureEvent
from sdi.tasks.schedule import Schedule, list_schedule
from sdi.tasks.task import GRASP_SECONDS, PickPlace, TaskPlan, Waypoint

if TYPE_CHECKING:
    from sdi.execute.job import VerifiedJob

APPROACH_HEIGHT = 0.10
"""Approach and retreat waypoints sit this far above the grasp, m."""
PLACEMENT_CLEARANCE = 0.0008
"""Gap (m) left beside already-placed side neighbours when setting a part down."""
CONFLICT_DISTANCE = 0.25
"""Steps of different arms whose targets are closer than this (xy, m) never overlap in time."""


def pose_tuple(T: np.ndarray) -> tuple[float, ...]:
    """(x, y, z, qw, qx, qy, qz) of a 4×4 pose, metres."""
    return (*(float(v) for v in T[:3, 3]), *(float(q) for q in quat_from_matrix(T[:3, :3])))


def _frame(R: np.ndarray, p: np.ndarray) -> np.ndarray:
    T = np.eye(4)
    T[:3, :3] = R
    T[:3, 3] = p
    return T


def _rot_z(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def grasps_in_part(
    kind: str, axis_in_part: int | None, half: np.ndarray, depth: float
) -> list[np.ndarray]:
    """Candidate T_part_tcp for a tool: TCP z down the part's −z; fingers close along tool x."""
    down = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])  # x↔y, z flipped
    out = []
    if kind == "vacuum":
        for k in range(4):
            out.append(_frame(_rot_z(k * math.pi / 2) @ down, np.array([0.0, 0.0, half[2]])))
        return out
    assert axis_in_part is not None
    # tool x (the 2FG7's closing axis) along the part's axis: `down` has tool x = part y
    base = down if axis_in_part == 1 else _rot_z(math.pi / 2) @ down
    z_tcp = half[2] - depth / 2
    for k in range(2):
        out.append(_frame(_rot_z(k * math.pi) @ base, np.array([0.0, 0.0, z_tcp])))
    return out


@dataclass(frozen=True)
class _Option:
    kind: str
    world_axis: int | None


def supply_slots(area: SupplyArea, size: tuple[float, float, float]) -> list[np.ndarray]:
    """Known part poses in a supply area: a grid at `pitch`, parts axis-aligned on the table."""
    xs = np.arange(area.x_range[0], area.x_range[1] + 1e-9, max(area.pitch, size[0] + 0.03))
    ys = np.arange(area.y_range[0], area.y_range[1] + 1e-9, max(area.pitch, size[1] + 0.03))
    return [_frame(np.eye(3), np.array([x, y, size[2] / 2])) for x in xs for y in ys]


def joint_move_seconds(robot: RobotModel, qa: np.ndarray, qb: np.ndarray) -> float:
    """Time of a synchronised joint move under each joint's velocity/acceleration limit, s."""
    worst = 0.0
    for j, spec in enumerate(robot.joints):
        d = abs(float(qb[j] - qa[j]))
        v, a = spec.max_velocity, spec.max_acceleration
        t = 2 * math.sqrt(d / a) if d < v * v / a else d / v + v / a
        worst = max(worst, t)
    return worst


def steps_conflict(a: PickPlace, b: PickPlace, robots: Mapping[str, RobotModel]) -> bool:
    """Whether steps of two different arms share space and so must never overlap in time.

    Their targets are closer than CONFLICT_DISTANCE, or one arm would reach past the other
    (a's target is not clearly on a's side of b's, along the line between the bases). The
    scheduler keeps such steps apart in σ* order; the exported programs interlock them.
    """
    pa, pb = a.T_world_part_target[:2, 3], b.T_world_part_target[:2, 3]
    if float(np.linalg.norm(pa - pb)) < CONFLICT_DISTANCE:
        return True
    ra, rb = robots[a.robot], robots[b.robot]
    axis = rb.T_world_base[:2, 3] - ra.T_world_base[:2, 3]
    norm = float(np.linalg.norm(axis))
    if norm < 1e-9:
        return True
    axis /= norm
    return float((pa - pb) @ axis) > -0.10


class TaskGenerator:
    """Builds `TaskPlan`s for a cell; one instance per job."""

    def __init__(
        self,
        cell: CellConfig | None = None,
        robots: dict[str, RobotModel] | None = None,
        *,
        arms: Sequence[str] | None = None,
    ) -> None:
        self.cell = cell or CellConfig()
        all_robots = robots or robots_for(self.cell)
        names = list(arms) if arms else list(all_robots)
        unknown = [n for n in names if n not in all_robots]
        if unknown:
            raise UnverifiedPlanError(
                f"unknown robots {unknown}; the cell has {sorted(all_robots)}"
            )
        self.robots = {n: all_robots[n] for n in names}
        self.areas = {a.robot: a for a in self.cell.supply_areas}
        for robot in self.robots.values():
            self._check_supply(robot)
        self.home = {n: self._home(r) for n, r in self.robots.items()}

    def _check_supply(self, robot: RobotModel) -> None:
        """Every pick slot of the robot's supply area must be reachable with the tool down."""
        area = self.areas.get(robot.name)
        if area is None:
            raise InputError(
                f"{robot.name} has no supply area; add one for it", field="supply_areas"
            )
        down = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
        for T in supply_slots(area, self.cell.cube):
            grasp = T.copy()
            grasp[2, 3] = self.cell.cube[2]
            if not ik(robot, _frame(down, grasp[:3, 3])):
                raise InputError(
                    f"the pick slot at ({T[0, 3]:.3f}, {T[1, 3]:.3f}) m is out of "
                    f"{robot.name}'s reach; move the area closer to the robot",
                    field=f"supply_areas.{area.name}",
                )

    def _home(self, robot: RobotModel) -> np.ndarray:
        """Tool down, 0.30 m above the centre of the robot's supply area, in a front,
        elbow-up configuration: each arm waits over its own feeder, away from the other."""
        area = next((a for a in self.cell.supply_areas if a.robot == robot.name), None)
        base = robot.T_world_base[:3, 3]
        if area is not None:
            xy = np.array([sum(area.x_range) / 2, sum(area.y_range) / 2])
        else:
            xy = base[:2] + 0.5 * robot.T_world_base[:2, 0]
        down = np.array([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]])
        T = _frame(down, np.array([xy[0], xy[1], 0.30]))
        front = [q for q in ik(robot, T) if abs(q[0]) < 2.0 and q[2] > -math.pi / 2]
        if front:
            return min(front, key=lambda q: float(np.sum(np.abs(q))))
        q = ik_nearest(robot, T, np.zeros(6))
        return q if q is not None else np.zeros(6)

    # -- per step ---------------------------------------------------------------------------
    def _options(self, a: Analysis, i: int, rank: np.ndarray) -> list[_Option]:
        grip = a.grip
        blocked = set()
        rows = grip.blocks[grip.blocks[:, 0] == i]
        for _, o, j in rows.tolist():
            if rank[j] < rank[i]:
                blocked.add(o)
        out = []
        for o, opt in enumerate(grip.options):
            if grip.fits[i, o] and o not in blocked:
                out.append(_Option(opt.kind, None if opt.axis is None else "xy".index(opt.axis)))
        return out

    def _chain(
        self, robot: RobotModel, T_world_tcp: np.ndarray, seed: np.ndarray
    ) -> list[np.ndarray] | None:
        """IK for approach, grasp, retreat above/at T (one branch, seeded from `seed`)."""
        up = T_world_tcp.copy()
        up[2, 3] += APPROACH_HEIGHT
        q_up = ik_nearest(robot, up, seed)
        if q_up is None:
            return None
        q_at = ik_nearest(robot, T_world_tcp, q_up)
        if q_at is None or np.max(np.abs(q_at - q_up)) > 1.5:
            return None
        return [q_up, q_at, q_up]

    def _try(
        self,
        robot: RobotModel,
        option: _Option,
        T_part: np.ndarray,
        T_supply: np.ndarray,
        half: np.ndarray,
        seed: np.ndarray,
    ) -> tuple[np.ndarray, list[np.ndarray], list[np.ndarray]] | None:
        depth = 0.0
        axis_in_part = None
        if option.kind == "parallel":
            gripper = next(g for g in self.cell.grippers if isinstance(g, ParallelGripper))
            depth = min(gripper.grip_depth, 2 * half[2])
            assert option.world_axis is not None
            beta = np.zeros(3)
            beta[option.world_axis] = 1.0
            axis_in_part = int(np.argmax(np.abs(T_part[:3, :3].T @ beta)[:2]))
        best = None
        for T_part_tcp in grasps_in_part(option.kind, axis_in_part, half, depth):
            place = self._chain(robot, T_part @ T_part_tcp, seed)
            if place is None:
                continue
            pick = self._chain(robot, T_supply @ T_part_tcp, seed)
            if pick is None:
                continue
            cost = float(np.sum(np.abs(pick[0] - seed)) + np.sum(np.abs(place[0] - pick[0])))
            if best is None or cost < best[0]:
                best = (cost, T_part_tcp, pick, place)
        return None if best is None else (best[1], best[2], best[3])

    def generate(self, job: VerifiedJob) -> tuple[TaskPlan, Schedule]:
        """Steps for every part of a verified job in its order σ*, with robots, waypoints and a
        schedule. The job is trusted (no second Inspector run); it must be a job `inspect`
        passed (`VerifiedJob.check`) for this generator's cell."""
        from sdi.execute.record import cell_hash

        job.check()
        if job.cell != self.cell and cell_hash(job.cell) != cell_hash(self.cell):
            raise UnverifiedPlanError(
                "refused: the job was verified for another cell configuration than this "
                "generator's; inspect it for this cell"
            )
        layout = job.layout
        order = list(job.sequence)
        a = Analysis(layout, self.cell)
        index = layout.index
        rank = np.empty(len(layout), dtype=np.intp)
        for k, pid in enumerate(order):
            rank[index[pid]] = k
        interacts = self._interactions(a)
        slots = {
            n: supply_slots(self.areas[n], self.cell.cube) if n in self.areas else []
            for n in self.robots
        }
        used = dict.fromkeys(self.robots, 0)
        last_q = dict(self.home)
        steps: list[PickPlace] = []
        free_at = dict.fromkeys(self.robots, 0.0)
        ends: dict[int, float] = {}
        # Look-ahead: work only one robot can do is reserved for it, so flexible steps go to
        # the other arm (time each robot still owes to exclusive steps, s).
        exclusive = self._exclusive_load(layout, order, a, rank, slots)
        for k, pid in enumerate(order):
            i = index[pid]
            part = layout.objects[i]
            T_part = _frame(rotation_matrix(part.orientation), np.array(part.position))
            T_part[:3, 3] += self._clearance(a, i, rank)
            half = 0.5 * np.array(part.size)
            options = self._options(a, i, rank)
            depends = tuple(sorted(int(rank[j]) for j in interacts.get(i, ()) if rank[j] < k))
            best: tuple[float, PickPlace, float] | None = None
            for name, robot in self.robots.items():
                if name not in self.areas:
                    continue
                slot_list = slots[name] or [np.eye(4)]
                T_supply = slot_list[used[name] % len(slot_list)].copy()
                T_supply[2, 3] = part.size[2] / 2
                for option in options:
                    if option.kind != robot.tool.kind:
                        continue
                    found = self._try(robot, option, T_part, T_supply, half, last_q[name])
                    if found is None:
                        continue
                    T_part_tcp, pick_q, place_q = found
                    duration = self._estimate(robot, last_q[name], pick_q, place_q)
                    start = max([free_at[name], *(ends[d] for d in depends)])
                    end = start + duration
                    owed = sum(t for j, t in exclusive.get(name, {}).items() if j > k)
                    score = end + owed
                    if best is None or score < best[0] - 1e-9:
                        step = self._step(
                            k, pid, name, option, T_part, T_supply, T_part_tcp, pick_q, place_q,
                            part.size, depends,
                        )  # fmt: skip
                        best = (score, step, end)
            if best is None:
                tools = sorted({o.kind for o in options}) or ["none"]
                raise MotionPlanningError(
                    f"step {k + 1}: no robot can pick and place {pid} (open grip options: "
                    f"{', '.join(tools)}; IK failed for every robot with such a tool)",
                    event=FailureEvent(
                        step=k,
                        part_id=pid,
                        error_type="ik",
                        target_pose=pose_tuple(T_part),
                        message="no inverse kinematics solution for the supply or target pose",
                    ),
                )
            _, step, end = best
            steps.append(step)
            used[step.robot] += 1
            last_q[step.robot] = step.place[2].q
            free_at[step.robot] = end
            ends[k] = end
        plan = TaskPlan(tuple(steps), tuple(self.robots), dict(self.home))
        return plan, self.schedule(plan)

    def _clearance(self, a: Analysis, i: int, rank: np.ndarray) -> np.ndarray:
        """Offset (m) that sets part i down a little away from side neighbours already placed.

        A stiff gripper pressing a part against one that is already there shoves it; real cells
        leave a small gap. Per lateral axis with placed neighbours on one side only, the part
        moves PLACEMENT_CLEARANCE away from them (inside the contact tolerance, relative to the
        design pose, so offsets never accumulate). The Inspector's contact relations still hold.
        """
        c = a.layout.centres
        h = a.layout.half_extents
        graph = a.graph
        pairs = graph.pairs[graph.in_contact]
        mine = pairs[(pairs == i).any(axis=1)]
        offset = np.zeros(3)
        clearance = min(PLACEMENT_CLEARANCE, 0.8 * self.cell.tolerances.contact)
        for axis in (0, 1):
            sides = set()
            for p, q in mine.tolist():
                j = q if p == i else p
                if rank[j] > rank[i]:
                    continue
                # a side neighbour: overlapping in z, touching across this axis
                overlap_z = min(c[i, 2] + h[i, 2], c[j, 2] + h[j, 2]) - max(
                    c[i, 2] - h[i, 2], c[j, 2] - h[j, 2]
                )
                gap = abs(c[i, axis] - c[j, axis]) - (h[i, axis] + h[j, axis])
                if overlap_z > 0.5 * h[i, 2] and abs(gap) <= self.cell.tolerances.contact:
                    sides.add(1.0 if c[j, axis] > c[i, axis] else -1.0)
            if len(sides) == 1:
                offset[axis] = -sides.pop() * clearance
        return offset

    def _exclusive_load(
        self,
        layout: Layout,
        order: list[str],
        a: Analysis,
        rank: np.ndarray,
        slots: dict[str, list[np.ndarray]],
    ) -> dict[str, dict[int, float]]:
        """Per robot: estimated seconds of the steps that only it can do, by step index."""
        out: dict[str, dict[int, float]] = {}
        if len(self.robots) < 2:
            return out
        index = layout.index
        for k, pid in enumerate(order):
            part = layout.objects[index[pid]]
            T_part = _frame(rotation_matrix(part.orientation), np.array(part.position))
            half = 0.5 * np.array(part.size)
            options = self._options(a, index[pid], rank)
            able: dict[str, float] = {}
            for name, robot in self.robots.items():
                if name not in self.areas or not slots[name]:
                    continue
                T_supply = slots[name][0].copy()
                T_supply[2, 3] = part.size[2] / 2
                for option in options:
                    if option.kind != robot.tool.kind:
                        continue
                    found = self._try(robot, option, T_part, T_supply, half, self.home[name])
                    if found is not None:
                        home = self.home[name]
                        able[name] = self._estimate(robot, home, found[1], found[2])
                        break
            if len(able) == 1:
                ((name, seconds),) = able.items()
                out.setdefault(name, {})[k] = seconds
        return out

    def _estimate(
        self, robot: RobotModel, q0: np.ndarray, pick: list[np.ndarray], place: list[np.ndarray]
    ) -> float:
        path = [q0, *pick, *place]
        moves = sum(joint_move_seconds(robot, a, b) for a, b in itertools.pairwise(path))
        return moves + 2 * GRASP_SECONDS[robot.tool.kind]

    def _step(
        self,
        k: int,
        pid: str,
        robot: str,
        option: _Option,
        T_part: np.ndarray,
        T_supply: np.ndarray,
        T_part_tcp: np.ndarray,
        pick_q: list[np.ndarray],
        place_q: list[np.ndarray],
        size: tuple[float, float, float],
        depends: tuple[int, ...],
    ) -> PickPlace:
        names = ("approach", "grasp", "retreat")

        def waypoints(
            T_part_world: np.ndarray, qs: list[np.ndarray]
        ) -> tuple[Waypoint, Waypoint, Waypoint]:
            T = T_part_world @ T_part_tcp
            up = T.copy()
            up[2, 3] += APPROACH_HEIGHT
            poses = (up, T, up)
            return tuple(Waypoint(n, p, q) for n, p, q in zip(names, poses, qs, strict=True))  # type: ignore[return-value]

        return PickPlace(
            step=k,
            part_id=pid,
            robot=robot,
            tool=option.kind,
            grip_axis=None if option.world_axis is None else "xy"[option.world_axis],
            pick=waypoints(T_supply, pick_q),
            place=waypoints(T_part, place_q),
            T_world_part_supply=T_supply,
            T_world_part_target=T_part,
            part_size=size,
            T_tcp_part=np.linalg.inv(T_part_tcp),
            depends_on=depends,
        )

    @staticmethod
    def _interactions(a: Analysis) -> dict[int, set[int]]:
        """Parts whose placement order matters to each other: contact or grip keep-out."""
        out: dict[int, set[int]] = {}
        pairs = a.graph.pairs[a.graph.in_contact]
        rows = [pairs, a.grip.blocks[:, [0, 2]]]
        for i, j in np.concatenate(rows).tolist():
            out.setdefault(i, set()).add(j)
            out.setdefault(j, set()).add(i)
        return out

    def schedule(self, plan: TaskPlan, durations: dict[int, float] | None = None) -> Schedule:
        """Schedule `plan` on its robots; `durations` (s) default to the estimates."""
        by_step = {s.step: s for s in plan.steps}

        def duration(k: int) -> float:
            if durations is not None and k in durations:
                return durations[k]
            s = by_step[k]
            robot = self.robots[s.robot]
            prev = [p for p in plan.for_robot(s.robot) if p.step < k]
            q0 = prev[-1].place[2].q if prev else self.home[s.robot]
            return self._estimate(robot, q0, [w.q for w in s.pick], [w.q for w in s.place])

        def conflict(k: int, other: int) -> bool:
            return steps_conflict(by_step[k], by_step[other], self.robots)

        return list_schedule(
            [s.step for s in plan.steps],
            lambda k: by_step[k].robot,
            duration,
            lambda k: by_step[k].depends_on,
            conflict,
        )
