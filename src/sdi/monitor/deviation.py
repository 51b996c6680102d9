"""Trajectory deviation δ(Q_plan, Q_exec) and the pass/fail rule V_traj (paper eq. 5–7).

    δ(Q_plan, Q_exec) = max over robots r and executed times t of ‖q_plan_r(t) − q_exec_r(t)‖₂

Joint values are radians, times seconds from the start of the job, so δ and the threshold ε
are radians (a Euclidean norm over the joints of one robot). Alignment follows paper §III-E:
for each executed sample of robot r, the planned sample of r nearest in time is compared —
no interpolation. Ties (an executed sample exactly midway between two planned ones) go to the
earlier planned sample, as in `JointTrajectory.at`. Executed samples before the first or after
the last planned sample are compared with that end sample: the plan holds its end pose, so
an arm still settling after its planned motion ends is judged against where it should rest.

Two ways in: `deviation` / `verify_trajectory` judge a whole recorded Q_exec at once, and
`StreamingMonitor` judges samples as a driver produces them, so execution can pause at the
first breach (paper §III-E: pause, inspect in the twin, or replan).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

import numpy as np

from sdi.errors import InputError
from sdi.motion.trajectory import JointTrajectory


class MonitorError(InputError):
    """Plan and execution cannot be compared; `robot` names the offending robot when known."""

    def __init__(self, message: str, *, robot: str | None = None) -> None:
        self.robot = robot
        super().__init__(message, field=f"robot {robot!r}" if robot is not None else None)


@dataclass(frozen=True)
class DeviationSeries:
    """Per-sample deviation of one robot: delta[k] = ‖q_plan(t[k]) − q_exec(t[k])‖₂.

    `t` (s) are the executed timestamps, `delta` (rad) the deviations; both read-only, shape (K,).
    """

    robot: str
    t: np.ndarray  # (K,) s
    delta: np.ndarray  # (K,) rad

    def __post_init__(self) -> None:
        t = np.array(self.t, dtype=float).reshape(-1)
        delta = np.array(self.delta, dtype=float).reshape(-1)
        if t.shape != delta.shape:
            raise ValueError(f"t {t.shape} and delta {delta.shape} must have the same shape")
        t.setflags(write=False)
        delta.setflags(write=False)
        object.__setattr__(self, "t", t)
        object.__setattr__(self, "delta", delta)

    def __len__(self) -> int:
        return int(self.t.shape[0])

    @property
    def max(self) -> float:
        """Largest deviation of this robot, rad (0.0 with no samples)."""
        return float(self.delta.max()) if self.delta.size else 0.0


@dataclass(frozen=True)
class DeviationResult:
    """δ over all robots and executed samples, where it occurs, and the per-robot series.

    `delta` (rad) is the maximum; `robot` and `t` (s) locate it — the earliest such sample, and
    between robots reaching it at the same time the first in plan order. Both are None only when
    no sample has been seen (a streaming monitor before its first update). `series` maps each
    robot to its per-sample deviations, for plotting and the twin.
    """

    delta: float
    robot: str | None
    t: float | None
    series: Mapping[str, DeviationSeries]

    def __post_init__(self) -> None:
        object.__setattr__(self, "series", MappingProxyType(dict(self.series)))

    @property
    def samples(self) -> dict[str, int]:
        """Number of executed samples compared, per robot."""
        return {robot: len(s) for robot, s in self.series.items()}


@dataclass(frozen=True)
class TrajectoryCheck:
    """V_traj(Q_plan, Q_exec): pass iff δ ≤ ε (paper eq. 7). δ and ε in rad, `t` in s."""

    passed: bool
    delta: float
    epsilon: float
    robot: str | None
    t: float | None

    @property
    def verdict(self) -> str:
        """``"pass"`` or ``"fail"``, as in the paper."""
        return "pass" if self.passed else "fail"


@dataclass(frozen=True)
class Breach:
    """The first executed sample whose deviation exceeds ε.

    `t` (s) is the executed timestamp and `t_plan` (s) that of the planned sample it was aligned
    with; `deviation` and `epsilon` are rad; `q_plan` and `q_exec` (rad, shape (dof,)) are the
    two joint vectors compared.
    """

    robot: str
    t: float
    deviation: float
    q_plan: np.ndarray  # (dof,) rad
    q_exec: np.ndarray  # (dof,) rad
    t_plan: float
    epsilon: float

    def __str__(self) -> str:
        return (
            f"robot {self.robot!r} deviates {self.deviation:.6g} rad from its plan at "
            f"t = {self.t:.6g} s (plan sample t = {self.t_plan:.6g} s), above ε = "
            f"{self.epsilon:.6g} rad"
        )


def _check_epsilon(epsilon: float) -> float:
    eps = float(epsilon)
    if not (math.isfinite(eps) and eps > 0.0):
        raise MonitorError(
            f"ε must be a finite threshold > 0 rad, got {epsilon!r}; the paper's rule is δ ≤ ε"
        )
    return eps


def _check_trajectory(kind: str, robot: str, traj: object, empty: str = "") -> JointTrajectory:
    """`traj` must be a non-empty JointTrajectory of `robot`; `kind` is planned/executed."""
    if not isinstance(traj, JointTrajectory):
        raise MonitorError(
            f"{kind} trajectory must be a JointTrajectory, got {type(traj).__name__}",
            robot=robot,
        )
    if traj.robot != robot:
        raise MonitorError(
            f"{kind} trajectory is keyed {robot!r} but belongs to robot {traj.robot!r}",
            robot=robot,
        )
    if len(traj) == 0:
        raise MonitorError(f"{kind} trajectory has no samples{empty}", robot=robot)
    return traj


def _check_plan(plan: Mapping[str, JointTrajectory]) -> dict[str, JointTrajectory]:
    if not plan:
        raise MonitorError("the plan has no robots; nothing to monitor")
    return {robot: _check_trajectory("planned", robot, traj) for robot, traj in plan.items()}


def _dof_mismatch(robot: str, dof_plan: int, dof_exec: int) -> MonitorError:
    return MonitorError(
        f"executed dof {dof_exec} ≠ planned dof {dof_plan}; compare the same joints of the "
        "same robot (check the joint order and any gripper/extra axes)",
        robot=robot,
    )


def _unknown_robot(robot: str, known: Mapping[str, object], side: str) -> MonitorError:
    return MonitorError(
        f"robot {robot!r} is not in the {side}; known robots: {sorted(known)}", robot=robot
    )


def _worst(series: Mapping[str, DeviationSeries]) -> tuple[float, str | None, float | None]:
    """Max over robots: the earliest sample reaching it, then the first robot in plan order."""
    delta, robot, t = 0.0, None, None
    for r, s in series.items():
        if len(s) == 0:
            continue
        k = int(np.argmax(s.delta))  # first occurrence = earliest time
        d, tk = float(s.delta[k]), float(s.t[k])
        if robot is None or t is None or d > delta or (d == delta and tk < t):
            delta, robot, t = d, r, tk
    return delta, robot, t


def _norms(diff: np.ndarray) -> np.ndarray:
    """Row-wise ‖·‖₂ of (K, dof) joint differences, rad, summed joint by joint in order.

    Not np.linalg.norm: this fixed order of operations is the one `_norm` repeats per sample,
    so batch and streaming δ agree bit for bit, and a difference in a single joint gives
    exactly its magnitude (sqrt(d²) = |d| in IEEE arithmetic).
    """
    acc = np.zeros(diff.shape[0])
    for j in range(diff.shape[1]):
        acc = acc + diff[:, j] * diff[:, j]
    return np.sqrt(acc)


def _norm(diff: list[float]) -> float:
    """‖·‖₂ of one joint difference, rad, with the arithmetic of `_norms`."""
    acc = 0.0
    for x in diff:
        acc = acc + x * x
    return math.sqrt(acc)


def deviation(
    plan: Mapping[str, JointTrajectory], executed: Mapping[str, JointTrajectory]
) -> DeviationResult:
    """δ(Q_plan, Q_exec) in rad after nearest-timestamp alignment (paper eq. 6, §III-E).

    `plan` and `executed` map robot name → trajectory; both must hold the same robots, each with
    the same dof on both sides and at least one sample. Every executed sample is compared with
    the planned sample nearest in time; executed samples outside the planned time span are
    compared with the nearest end sample (the plan holds its end pose).
    """
    plans = _check_plan(plan)
    for robot in executed:
        if robot not in plans:
            raise _unknown_robot(robot, plans, "plan")
    series: dict[str, DeviationSeries] = {}
    for robot, p in plans.items():
        if robot not in executed:
            raise MonitorError(
                f"robot {robot!r} has a plan but no executed trajectory; record every planned "
                f"robot (executed has {sorted(executed)})",
                robot=robot,
            )
        e = _check_trajectory(
            "executed", robot, executed[robot], "; an empty recording cannot pass"
        )
        if e.dof != p.dof:
            raise _dof_mismatch(robot, p.dof, e.dof)
        series[robot] = DeviationSeries(robot, e.t, _norms(p.at(e.t) - e.q))
    delta, worst_robot, worst_t = _worst(series)
    return DeviationResult(delta, worst_robot, worst_t, series)


def verify_trajectory(
    plan: Mapping[str, JointTrajectory],
    executed: Mapping[str, JointTrajectory],
    epsilon: float,
) -> TrajectoryCheck:
    """V_traj (paper eq. 7): pass iff δ(Q_plan, Q_exec) ≤ `epsilon` (rad, > 0)."""
    eps = _check_epsilon(epsilon)
    result = deviation(plan, executed)
    return TrajectoryCheck(result.delta <= eps, result.delta, eps, result.robot, result.t)


class _RobotTrack:
    """One robot's plan, its alignment pointer, and the deviations seen so far."""

    __slots__ = ("delta_list", "dof", "i", "last_t", "plan", "q", "t", "t_list")

    def __init__(self, plan: JointTrajectory) -> None:
        self.plan = plan
        self.t: np.ndarray = plan.t
        self.q: np.ndarray = plan.q
        self.dof = plan.dof
        self.i = 0
        self.last_t = -math.inf
        self.t_list: list[float] = []
        self.delta_list: list[float] = []

    def nearest(self, t: float) -> int:
        """Index of the planned sample nearest `t`, ties to the earlier one.

        Executed times only increase, so the nearest index never decreases: the pointer moves
        forward while the next planned sample is strictly nearer — O(1) amortised per call.
        """
        ts, i, n = self.t, self.i, len(self.t)
        while i + 1 < n and abs(float(ts[i + 1]) - t) < abs(t - float(ts[i])):
            i += 1
        self.i = i
        return i


class StreamingMonitor:
    """Judge executed samples one at a time as a driver produces them (paper §III-E).

    Construct with the plans (robot name → `JointTrajectory`) and ε (rad, > 0); call `update`
    for each executed sample of each robot, in increasing time per robot (robots may
    interleave). `update` returns a `Breach` on the first sample whose deviation exceeds ε —
    the moment to pause — and None otherwise, including on later exceedances; `breach` keeps
    the first one. Alignment and arithmetic are those of `deviation`, so over the same samples
    `max_deviation` equals the batch δ. Each update costs O(dof) amortised.
    """

    def __init__(self, plan: Mapping[str, JointTrajectory], epsilon: float) -> None:
        self._epsilon = _check_epsilon(epsilon)
        self._tracks = {robot: _RobotTrack(p) for robot, p in _check_plan(plan).items()}
        self._max = 0.0
        self._worst_robot: str | None = None
        self._worst_t: float | None = None
        self._breach: Breach | None = None

    @property
    def epsilon(self) -> float:
        """The threshold ε, rad."""
        return self._epsilon

    @property
    def robots(self) -> tuple[str, ...]:
        """The monitored robots, in plan order."""
        return tuple(self._tracks)

    @property
    def max_deviation(self) -> float:
        """Running δ: the largest deviation seen so far, rad (0.0 before any sample)."""
        return self._max

    @property
    def breached(self) -> bool:
        """True once some sample has exceeded ε."""
        return self._breach is not None

    @property
    def breach(self) -> Breach | None:
        """The first breach, or None."""
        return self._breach

    def update(self, robot: str, t: float, q: np.ndarray | list[float]) -> Breach | None:
        """Record the executed joint vector `q` (rad, shape (dof,)) of `robot` at time `t` (s).

        Returns the `Breach` if this is the first sample to exceed ε, else None.
        """
        track = self._tracks.get(robot)
        if track is None:
            raise _unknown_robot(robot, self._tracks, "plan")
        t = float(t)
        if not math.isfinite(t):
            raise MonitorError(f"executed time must be finite, got {t!r} s", robot=robot)
        if t <= track.last_t:
            raise MonitorError(
                f"executed samples must arrive in increasing time; got t = {t!r} s after "
                f"t = {track.last_t!r} s",
                robot=robot,
            )
        q_exec = np.array(q, dtype=float).reshape(-1)
        if q_exec.shape[0] != track.dof:
            raise _dof_mismatch(robot, track.dof, q_exec.shape[0])
        if not np.all(np.isfinite(q_exec)):
            raise MonitorError(
                f"executed joints must be finite, got {q_exec} at t = {t} s", robot=robot
            )
        i = track.nearest(t)
        dev = _norm((track.q[i] - q_exec).tolist())
        track.last_t = t
        track.t_list.append(t)
        track.delta_list.append(dev)
        if dev > self._max or self._worst_robot is None:
            self._max, self._worst_robot, self._worst_t = dev, robot, t
        if self._breach is None and dev > self._epsilon:
            q_plan = track.q[i].copy()
            q_plan.setflags(write=False)
            q_exec.setflags(write=False)
            self._breach = Breach(robot, t, dev, q_plan, q_exec, float(track.t[i]), self._epsilon)
            return self._breach
        return None

    def series(self) -> dict[str, DeviationSeries]:
        """Per-robot deviations seen so far (every monitored robot, possibly empty)."""
        return {
            robot: DeviationSeries(robot, np.array(tr.t_list), np.array(tr.delta_list))
            for robot, tr in self._tracks.items()
        }

    def result(self) -> DeviationResult:
        """The samples seen so far as a `DeviationResult` (the worst is the first to reach δ)."""
        return DeviationResult(self._max, self._worst_robot, self._worst_t, self.series())

    def check(self) -> TrajectoryCheck:
        """V_traj over the samples seen so far: pass iff no sample exceeded ε."""
        return TrajectoryCheck(
            not self.breached, self._max, self._epsilon, self._worst_robot, self._worst_t
        )
