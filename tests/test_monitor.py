"""The monitor: δ(Q_plan, Q_exec), V_traj and the streaming monitor (paper Sub-problem 5, §III-E).

Plans are smooth joint motions sampled at the controller rates of the two arms (IRB120 50 Hz,
IRB1600 250 Hz); executions are copies with known, hand-made errors, so the expected δ is
known in closed form. Times in s, joints and δ in rad.
"""

from __future__ import annotations

import heapq
import json
from collections.abc import Iterator

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import sdi.monitor as monitor_pkg
from sdi.errors import InputError
from sdi.monitor import (
    Breach,
    DeviationResult,
    MonitorError,
    StreamingMonitor,
    deviation,
    plot_deviation,
    report_dict,
    verify_trajectory,
)
from sdi.motion import JointTrajectory

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def smooth(robot: str, rate_hz: float, duration: float = 3.0, dof: int = 6) -> JointTrajectory:
    """A smooth plan: joint j follows 0.3·sin(0.7·(j+1)·t + j), sampled at `rate_hz`."""
    t = np.arange(round(duration * rate_hz) + 1) / rate_hz
    j = np.arange(dof)
    q = 0.3 * np.sin(0.7 * (j + 1) * t[:, None] + j)
    return JointTrajectory(robot, t, q, rate_hz)


def with_offset(
    traj: JointTrajectory, joint: int, offset: float, t0: float, t1: float
) -> JointTrajectory:
    """`traj` with `offset` rad added to `joint` for t0 ≤ t ≤ t1 s."""
    q = traj.q.copy()
    q[(traj.t >= t0) & (traj.t <= t1), joint] += offset
    return JointTrajectory(traj.robot, traj.t, q, traj.rate_hz)


def samples(executed: dict[str, JointTrajectory]) -> Iterator[tuple[float, str, np.ndarray]]:
    """The executed samples of all robots merged in time order, as a driver would stream them."""

    def stream(robot: str, e: JointTrajectory) -> Iterator[tuple[float, str, np.ndarray]]:
        for t, q in zip(e.t, e.q, strict=True):
            yield float(t), robot, q

    return heapq.merge(*(stream(r, e) for r, e in executed.items()), key=lambda s: s[0])


@pytest.fixture
def plan() -> dict[str, JointTrajectory]:
    return {"irb120": smooth("irb120", 50.0), "irb1600": smooth("irb1600", 250.0)}


@pytest.fixture
def offset_exec(plan: dict[str, JointTrajectory]) -> dict[str, JointTrajectory]:
    """The plan executed exactly, except joint 3 of the IRB1600 is 0.01 rad off for 1 ≤ t ≤ 2 s."""
    return {"irb120": plan["irb120"], "irb1600": with_offset(plan["irb1600"], 2, 0.01, 1.0, 2.0)}


# --------------------------------------------------------------------------------------------
# batch δ and V_traj


def test_identical_execution_has_zero_deviation_and_passes(plan):
    result = deviation(plan, dict(plan))
    assert result.delta == 0.0
    assert result.samples == {"irb120": 151, "irb1600": 751}
    assert all(np.all(s.delta == 0.0) for s in result.series.values())
    check = verify_trajectory(plan, dict(plan), epsilon=1e-9)
    assert check.passed and check.verdict == "pass"
    assert check.delta == 0.0 and check.epsilon == 1e-9


def test_known_offset_gives_that_deviation_at_that_robot_and_window(plan, offset_exec):
    result = deviation(plan, offset_exec)
    assert result.delta == pytest.approx(0.01, abs=1e-12)
    assert result.robot == "irb1600"
    assert result.t is not None and 1.0 <= result.t <= 2.0

    s = result.series["irb1600"]
    inside = (s.t >= 1.0) & (s.t <= 2.0)
    np.testing.assert_allclose(s.delta[inside], 0.01, rtol=0, atol=1e-12)
    assert np.all(s.delta[~inside] == 0.0)
    assert np.all(result.series["irb120"].delta == 0.0)

    fail = verify_trajectory(plan, offset_exec, epsilon=0.005)
    assert not fail.passed and fail.verdict == "fail"
    assert fail.robot == "irb1600" and fail.t is not None and 1.0 <= fail.t <= 2.0
    assert verify_trajectory(plan, offset_exec, epsilon=0.02).passed


def test_threshold_is_inclusive(plan, offset_exec):
    """Paper eq. 7: pass iff δ ≤ ε, so δ = ε passes."""
    delta = deviation(plan, offset_exec).delta
    assert verify_trajectory(plan, offset_exec, epsilon=delta).passed
    assert not verify_trajectory(plan, offset_exec, epsilon=np.nextafter(delta, 0.0)).passed


def test_different_rates_align_by_nearest_timestamp_not_interpolation():
    """A 50 Hz plan of q₀(t) = t, executed exactly but recorded at 250 Hz.

    Linear interpolation of the plan reproduces q₀(t) = t exactly, so it would give δ = 0.
    Nearest-timestamp alignment compares the executed sample at t = 0.012 s with the planned
    one at 0.020 s (0.008 s away, the one at 0.000 s is 0.012 s away): δ = 0.008 rad.
    """
    t_plan = np.arange(51) / 50.0
    t_exec = np.arange(251) / 250.0
    q_plan = np.zeros((51, 6))
    q_plan[:, 0] = t_plan
    q_exec = np.zeros((251, 6))
    q_exec[:, 0] = t_exec
    plan = {"irb120": JointTrajectory("irb120", t_plan, q_plan, 50.0)}
    executed = {"irb120": JointTrajectory("irb120", t_exec, q_exec, 250.0)}

    s = deviation(plan, executed).series["irb120"]
    k = 3  # t = 0.012 s
    assert s.t[k] == pytest.approx(0.012)
    interpolated = np.interp(s.t[k], t_plan, q_plan[:, 0])
    assert abs(interpolated - q_exec[k, 0]) == pytest.approx(0.0, abs=1e-15)
    assert s.delta[k] == pytest.approx(0.020 - 0.012, abs=1e-15)
    assert s.delta[2] == pytest.approx(0.008, abs=1e-15)  # t = 0.008 s → plan sample at 0.0 s
    assert s.delta[5] == 0.0  # t = 0.020 s coincides with a plan sample
    assert deviation(plan, executed).delta == pytest.approx(0.008, abs=1e-15)

    # The alignment is JointTrajectory.at's (paper §III-E), sample for sample.
    expected = np.linalg.norm(plan["irb120"].at(t_exec) - q_exec, axis=1)
    np.testing.assert_allclose(s.delta, expected, rtol=0, atol=1e-15)


def test_samples_outside_the_plan_span_use_the_nearest_end_sample():
    plan = {"r": JointTrajectory("r", [1.0, 2.0], [[0.0, 0.0], [1.0, 0.0]], 1.0)}
    executed = {"r": JointTrajectory("r", [0.0, 2.5, 9.0], [[0.1, 0.0], [1.0, 0.0], [1.3, 0.0]], 1)}
    s = deviation(plan, executed).series["r"]
    np.testing.assert_allclose(s.delta, [0.1, 0.0, 0.3], rtol=0, atol=1e-15)


def test_midway_samples_go_to_the_earlier_plan_sample():
    plan = {"r": JointTrajectory("r", [0.0, 0.5, 1.0], [[0.0], [1.0], [2.0]], 2.0)}
    executed = {"r": JointTrajectory("r", [0.25, 0.75], [[0.0], [1.0]], 2.0)}
    assert deviation(plan, executed).delta == 0.0
    mon = StreamingMonitor(plan, epsilon=0.5)
    assert mon.update("r", 0.25, [0.0]) is None
    assert mon.update("r", 0.75, [1.0]) is None
    assert mon.max_deviation == 0.0


# --------------------------------------------------------------------------------------------
# streaming


def test_streaming_breaches_at_the_first_sample_above_epsilon(plan, offset_exec):
    eps = 0.005
    batch = deviation(plan, offset_exec)
    mon = StreamingMonitor(plan, eps)
    breaches: list[tuple[int, Breach]] = []
    order = list(samples(offset_exec))
    for n, (t, robot, q) in enumerate(order):
        b = mon.update(robot, t, q)
        if b is not None:
            breaches.append((n, b))

    first = next(n for n, (t, r, _) in enumerate(order) if r == "irb1600" and t >= 1.0)
    assert len(breaches) == 1  # reported once, at the first exceeding sample
    n, b = breaches[0]
    assert n == first
    assert b.robot == "irb1600" and b.t == 1.0 and b.t_plan == 1.0
    assert b.deviation == pytest.approx(0.01, abs=1e-12) and b.epsilon == eps
    np.testing.assert_array_equal(b.q_plan, plan["irb1600"].q[250])
    np.testing.assert_array_equal(b.q_exec, offset_exec["irb1600"].q[250])
    assert "irb1600" in str(b) and "ε" in str(b)
    assert mon.breached and mon.breach is b

    # Same samples, same answer as the batch δ — bit for bit.
    assert mon.max_deviation == batch.delta
    assert mon.result().robot == batch.robot and mon.result().t == batch.t
    for robot, s in mon.series().items():
        np.testing.assert_array_equal(s.t, batch.series[robot].t)
        np.testing.assert_array_equal(s.delta, batch.series[robot].delta)
    assert not mon.check().passed and mon.check().delta == batch.delta


def test_streaming_drift_breaches_when_it_first_crosses_not_later(plan):
    """A drift growing 0.04 rad/s from t = 1 s on joint 1 crosses ε = 0.03 rad after 0.75 s."""
    p = plan["irb1600"]
    q = p.q.copy()
    q[:, 0] += 0.04 * np.clip(p.t - 1.0, 0.0, None)
    executed = JointTrajectory("irb1600", p.t, q, p.rate_hz)
    plan_one = {"irb1600": p}
    expected = deviation(plan_one, {"irb1600": executed}).series["irb1600"]
    k_first = int(np.argmax(expected.delta > 0.03))

    mon = StreamingMonitor(plan_one, epsilon=0.03)
    hits = [k for k in range(len(p)) if mon.update("irb1600", p.t[k], q[k]) is not None]
    assert hits == [k_first]
    assert expected.delta[k_first - 1] <= 0.03 < expected.delta[k_first]
    assert mon.breach is not None and mon.breach.t == pytest.approx(1.75, abs=1 / 250)


def test_streaming_deviation_equal_to_epsilon_is_not_a_breach():
    plan = {"r": JointTrajectory("r", [0.0, 1.0], [[0.0], [0.0]], 1.0)}
    mon = StreamingMonitor(plan, epsilon=0.25)
    assert mon.update("r", 0.0, [0.25]) is None
    assert not mon.breached and mon.max_deviation == 0.25 and mon.check().passed
    assert mon.update("r", 1.0, [0.5]) is not None


def test_streaming_monitor_before_any_sample():
    mon = StreamingMonitor({"r": JointTrajectory("r", [0.0], [[0.0]], 1.0)}, epsilon=0.1)
    result = mon.result()
    assert result.delta == 0.0 and result.robot is None and result.t is None
    assert result.samples == {"r": 0}
    assert mon.robots == ("r",) and mon.epsilon == 0.1


def test_streaming_pointer_is_amortised_constant_per_sample(plan):
    """Count reads of the planned time axis: linear in plan + execution length, not quadratic.

    Deliberately no wall-clock assertion: a from-scratch search per sample would read
    O(plan length) entries per sample, the index pointer O(1) amortised.
    """

    class CountingTimes:
        def __init__(self, t: np.ndarray) -> None:
            self.t, self.reads = t, 0

        def __len__(self) -> int:
            return len(self.t)

        def __getitem__(self, i: int) -> float:
            self.reads += 1
            return float(self.t[i])

    for n_exec in (2_000, 20_000):
        p = smooth("irb1600", 250.0, duration=8.0)
        mon = StreamingMonitor({"irb1600": p}, epsilon=1.0)
        counter = CountingTimes(p.t)
        mon._tracks["irb1600"].t = counter  # white-box probe
        t_exec = np.linspace(0.0, 8.0, n_exec)
        for t in t_exec:
            mon.update("irb1600", t, p.q[0])
        assert counter.reads <= 2 * (len(p) + n_exec) + 2


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    n_plan=st.integers(1, 30),
    n_exec=st.integers(1, 60),
    dof=st.integers(1, 8),
    seed=st.integers(0, 2**32 - 1),
    grid=st.booleans(),
)
def test_batch_and_streaming_match_a_brute_force_reference(n_plan, n_exec, dof, seed, grid):
    """δ equals a direct nearest-neighbour scan, and the streaming δ equals the batch δ."""
    rng = np.random.default_rng(seed)
    if grid:  # shared quarter-second grid: many exact hits and midway ties
        t_plan = np.sort(rng.choice(np.arange(200) / 4.0, n_plan, replace=False))
        t_exec = np.sort(rng.choice(np.arange(400) / 8.0, n_exec, replace=False))
    else:
        t_plan = np.sort(rng.choice(np.arange(10_000), n_plan, replace=False)) / 97.0
        t_exec = np.sort(rng.choice(np.arange(12_000), n_exec, replace=False)) / 89.0
    q_plan = rng.normal(size=(n_plan, dof))
    q_exec = rng.normal(size=(n_exec, dof))
    plan = {"a": JointTrajectory("a", t_plan, q_plan, 50.0)}
    executed = {"a": JointTrajectory("a", t_exec, q_exec, 250.0)}

    ref = [
        np.linalg.norm(q_plan[int(np.argmin(np.abs(t_plan - t)))] - q)
        for t, q in zip(t_exec, q_exec, strict=True)
    ]  # argmin returns the first minimum: ties to the earlier plan sample
    result = deviation(plan, executed)
    np.testing.assert_allclose(result.series["a"].delta, ref, rtol=1e-12, atol=1e-15)
    assert result.delta == pytest.approx(max(ref), rel=1e-12)

    eps = max(result.delta / 2, 1e-9)
    mon = StreamingMonitor(plan, eps)
    first = None
    for k, (t, q) in enumerate(zip(t_exec, q_exec, strict=True)):
        if mon.update("a", t, q) is not None:
            first = k if first is None else pytest.fail("breach reported twice")
    assert mon.max_deviation == result.delta
    np.testing.assert_array_equal(mon.series()["a"].delta, result.series["a"].delta)
    above = np.flatnonzero(result.series["a"].delta > eps)
    assert first == (int(above[0]) if above.size else None)


# --------------------------------------------------------------------------------------------
# errors


def test_dof_mismatch_names_the_robot_and_both_dofs(plan):
    bad = dict(plan)
    bad["irb120"] = JointTrajectory("irb120", plan["irb120"].t, plan["irb120"].q[:, :5], 50.0)
    with pytest.raises(MonitorError, match=r"irb120.*executed dof 5 ≠ planned dof 6") as exc:
        deviation(plan, bad)
    assert exc.value.robot == "irb120"
    assert isinstance(exc.value, InputError)

    mon = StreamingMonitor(plan, epsilon=0.01)
    with pytest.raises(MonitorError, match=r"irb1600.*executed dof 7 ≠ planned dof 6"):
        mon.update("irb1600", 0.0, np.zeros(7))


def test_unknown_and_missing_robots_are_named(plan):
    extra = {**plan, "kuka": smooth("kuka", 100.0)}
    with pytest.raises(MonitorError, match=r"'kuka' is not in the plan") as exc:
        deviation(plan, extra)
    assert exc.value.robot == "kuka"
    with pytest.raises(MonitorError, match=r"'irb1600' has a plan but no executed trajectory"):
        deviation(plan, {"irb120": plan["irb120"]})
    with pytest.raises(MonitorError, match=r"'kuka' is not in the plan.*irb120"):
        StreamingMonitor(plan, epsilon=0.01).update("kuka", 0.0, np.zeros(6))
    with pytest.raises(MonitorError, match=r"belongs to robot 'irb120'"):
        deviation(plan, {"irb120": plan["irb120"], "irb1600": plan["irb120"]})


def test_bad_thresholds_and_inputs_are_rejected(plan):
    for eps in (0.0, -0.01, float("nan"), float("inf")):
        with pytest.raises(MonitorError, match="ε must be"):
            verify_trajectory(plan, plan, eps)
        with pytest.raises(MonitorError, match="ε must be"):
            StreamingMonitor(plan, eps)
    with pytest.raises(MonitorError, match="no robots"):
        deviation({}, {})
    empty = JointTrajectory("irb120", np.zeros(0), np.zeros((0, 6)), 50.0)
    with pytest.raises(MonitorError, match="no samples"):
        deviation(plan, {**plan, "irb120": empty})
    with pytest.raises(MonitorError, match="no samples"):
        StreamingMonitor({"irb120": empty}, 0.1)

    mon = StreamingMonitor(plan, epsilon=0.01)
    mon.update("irb120", 1.0, plan["irb120"].q[50])
    with pytest.raises(MonitorError, match="increasing time"):
        mon.update("irb120", 0.5, plan["irb120"].q[25])
    with pytest.raises(MonitorError, match="finite"):
        mon.update("irb120", 2.0, np.full(6, np.nan))


# --------------------------------------------------------------------------------------------
# reports


def _check_png(path, min_bytes: int = 10_000) -> np.ndarray:
    from matplotlib import image

    data = path.read_bytes()
    assert data[:8] == PNG_SIGNATURE
    assert len(data) > min_bytes
    img = image.imread(path)
    assert img.ndim == 3 and img.shape[0] > 100 and img.shape[1] > 100
    assert float(np.ptp(img)) > 0.0  # something was drawn
    return img


def test_plot_from_a_batch_result_writes_a_readable_png(plan, offset_exec, tmp_path):
    result = deviation(plan, offset_exec)
    out = plot_deviation(result, 0.005, tmp_path / "plots" / "deviation.png")
    assert out == tmp_path / "plots" / "deviation.png" and out.is_file()
    assert _check_png(out).shape[:2] == (450, 800)


def test_plot_from_a_monitor_writes_a_readable_png(plan, offset_exec, tmp_path):
    mon = StreamingMonitor(plan, 0.005)
    for t, robot, q in samples(offset_exec):
        mon.update(robot, t, q)
    _check_png(plot_deviation(mon, mon.epsilon, tmp_path / "live.png"))
    with pytest.raises(MonitorError, match="ε must be"):
        plot_deviation(mon, 0.0, tmp_path / "x.png")


def test_report_dict_is_json_ready(plan, offset_exec):
    result = deviation(plan, offset_exec)
    summary = json.loads(json.dumps(report_dict(result, 0.005)))
    assert summary["verdict"] == "fail" and summary["passed"] is False
    assert summary["delta_rad"] == pytest.approx(0.01, abs=1e-12)
    assert summary["epsilon_rad"] == 0.005
    assert summary["worst"]["robot"] == "irb1600" and 1.0 <= summary["worst"]["t_s"] <= 2.0
    assert summary["samples"] == {"irb120": 151, "irb1600": 751}
    assert summary["breach"] is None
    assert report_dict(result, 0.02)["verdict"] == "pass"

    mon = StreamingMonitor(plan, 0.005)
    for t, robot, q in samples(offset_exec):
        mon.update(robot, t, q)
    live = json.loads(json.dumps(report_dict(mon, mon.epsilon)))
    assert live["breach"]["robot"] == "irb1600" and live["breach"]["t_s"] == 1.0
    assert len(live["breach"]["q_exec_rad"]) == 6
    assert live["delta_rad"] == summary["delta_rad"]
    with pytest.raises(MonitorError, match="DeviationResult or a StreamingMonitor"):
        report_dict(plan, 0.1)


def test_public_surface_is_complete():
    public = {n for n in dir(monitor_pkg) if not n.startswith("_")} - {"deviation", "report"}
    assert set(monitor_pkg.__all__) >= public | {"deviation"}
    assert all(hasattr(monitor_pkg, n) for n in monitor_pkg.__all__)
    assert isinstance(
        deviation({"r": smooth("r", 10.0)}, {"r": smooth("r", 10.0)}), DeviationResult
    )
