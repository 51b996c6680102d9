"""Reports of a monitored run: a deviation plot (PNG) and a JSON-ready summary.

Both accept a batch `DeviationResult` or a live `StreamingMonitor`. Deviations and ε are in
rad, times in s. matplotlib is imported only when plotting, and drawn on an Agg canvas of its
own — no pyplot, no global backend switch, no display needed.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from sdi.monitor.deviation import (
    Breach,
    DeviationResult,
    MonitorError,
    StreamingMonitor,
    _check_epsilon,
)


def _unpack(source: DeviationResult | StreamingMonitor) -> tuple[DeviationResult, Breach | None]:
    if isinstance(source, StreamingMonitor):
        return source.result(), source.breach
    if isinstance(source, DeviationResult):
        return source, None
    raise MonitorError(
        f"expected a DeviationResult or a StreamingMonitor, got {type(source).__name__}"
    )


def report_dict(source: DeviationResult | StreamingMonitor, epsilon: float) -> dict[str, Any]:
    """A JSON-serialisable summary: δ and ε (rad), pass/fail, the worst robot and time (s),
    samples per robot, per-robot maxima (rad) and, for a monitor, its first breach."""
    eps = _check_epsilon(epsilon)
    result, breach = _unpack(source)
    passed = result.delta <= eps
    return {
        "delta_rad": result.delta,
        "epsilon_rad": eps,
        "passed": passed,
        "verdict": "pass" if passed else "fail",
        "worst": {"robot": result.robot, "t_s": result.t},
        "samples": result.samples,
        "max_delta_rad": {robot: s.max for robot, s in result.series.items()},
        "breach": None
        if breach is None
        else {
            "robot": breach.robot,
            "t_s": breach.t,
            "t_plan_s": breach.t_plan,
            "deviation_rad": breach.deviation,
            "q_plan_rad": [float(x) for x in breach.q_plan],
            "q_exec_rad": [float(x) for x in breach.q_exec],
        },
    }


def plot_deviation(
    source: DeviationResult | StreamingMonitor, epsilon: float, path: Path | str
) -> Path:
    """Write `deviation_png` to `path` (whole or not at all) and return the path.

    Creates the parent folder if needed.
    """
    from sdi.outputs import write_atomic

    out = Path(path)
    data = deviation_png(source, epsilon)
    out.parent.mkdir(parents=True, exist_ok=True)
    write_atomic(out, data)
    return out


def deviation_png(source: DeviationResult | StreamingMonitor, epsilon: float) -> bytes:
    """A PNG of δ_r(t) (rad) over time t (s) for each robot, with the ε line and the worst
    sample marked (and a monitor's first breach, if any).

    Needs matplotlib (not a core dependency).
    """
    import io

    eps = _check_epsilon(epsilon)
    result, breach = _unpack(source)
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError as exc:  # pragma: no cover - depends on the environment
        raise MonitorError(
            "plotting the deviation needs matplotlib; install it with `pip install matplotlib`"
        ) from exc

    fig = Figure(figsize=(8.0, 4.5), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    for robot, s in result.series.items():
        ax.plot(s.t, s.delta, linewidth=1.2, label=f"{robot} (max {s.max:.3g} rad)")
    ax.axhline(eps, color="tab:red", linestyle="--", linewidth=1.0, label=f"ε = {eps:.3g} rad")
    if result.robot is not None and result.t is not None:
        ax.plot(
            [result.t],
            [result.delta],
            marker="o",
            markersize=8,
            markerfacecolor="none",
            markeredgecolor="black",
            linestyle="none",
            label=f"worst: {result.robot} at t = {result.t:.3f} s",
        )
    if breach is not None:
        ax.plot(
            [breach.t],
            [breach.deviation],
            marker="x",
            markersize=8,
            color="tab:red",
            linestyle="none",
            label=f"first breach: {breach.robot} at t = {breach.t:.3f} s",
        )
    verdict = "PASS" if result.delta <= eps else "FAIL"
    ax.set_title(f"Trajectory deviation: δ = {result.delta:.4g} rad, ε = {eps:.4g} rad — {verdict}")
    ax.set_xlabel("time t [s]")
    ax.set_ylabel("deviation ‖q_plan − q_exec‖₂ [rad]")
    ax.set_ylim(bottom=0.0, top=max(result.delta, eps) * 1.15)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", fontsize="small")
    fig.tight_layout()
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png")
    return buffer.getvalue()
