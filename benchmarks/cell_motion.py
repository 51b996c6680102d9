"""Motion planning and execution on the cell (paper Table VI) and the 25-step dual-arm job.

For each command: plan with the offline front end, commission on one arm (the single robot
that can do every step; the IRB120 where it reaches, else the IRB1600) and on both arms,
execute the chosen plan in PyBullet with monitoring, and record planning seconds per
pick-and-place step, the makespans and the speed-up, δ and the worst placement error.

Run: `python benchmarks/cell_motion.py [--quick]` (part of `make bench`).
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

from sdi.bench.scenarios import load
from sdi.commission import commission, execute
from sdi.errors import SDIError
from sdi.pipeline import plan

OUT = Path(__file__).parent / "results" / "cell_motion.json"

TABLE_VI = [(c.category, c.mode, c.command) for c in load("motion") if not c.extra]
"""The paper's 12 commands (`sdi/bench/suites/motion.toml`, also run by `sdi bench --suite
motion`)."""
LARGE = next((c.category, c.mode, c.command) for c in load("motion") if c.extra)


def single_arm(layout):  # the IRB120 where it reaches everything, else the IRB1600
    for arm in ("irb120", "irb1600"):
        try:
            return arm, commission(layout, arms=[arm])
        except SDIError:
            continue
    return None, None  # e.g. a grid whose last cube only the IRB120's vacuum can place


def run(category: str, mode: str, command: str) -> dict:
    result = plan(command)
    if result.status != "success" or result.layout is None:
        return {"category": category, "command": command, "error": result.error}
    layout = result.layout
    started = time.perf_counter()
    arm, one = single_arm(layout)
    one_s = time.perf_counter() - started
    row = {
        "category": category,
        "command": command,
        "parts": len(layout),
        "single_arm": arm,
        "makespan_one_arm_s": round(one.makespan, 2) if one else None,
        "planning_s_one_arm": round(one_s, 2),
    }
    chosen = one
    if mode == "dual":
        started = time.perf_counter()
        two = commission(layout)
        row["planning_s_two_arms"] = round(time.perf_counter() - started, 2)
        row["makespan_two_arms_s"] = round(two.makespan, 2)
        row["speedup"] = round(one.makespan / two.makespan, 2) if one else None
        row["parallel"] = two.parallel
        row["steps_per_robot"] = two.summary()["steps_per_robot"]
        chosen = two
    per_step = [m.planning_seconds for m in chosen.motion.steps]
    row["planning_s_per_step"] = round(statistics.mean(per_step), 3)
    _, report = execute(chosen)
    row.update(
        executed=report["status"],
        v_traj=report["v_traj"],
        delta_rad=report["delta_rad"],
        max_placement_error_mm=round(1000 * float(report["max_placement_error_m"]), 2),
    )
    return row


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--quick", action="store_true", help="first command of each category")
    args = parser.parse_args()
    commands = TABLE_VI if not args.quick else [TABLE_VI[0], TABLE_VI[6], TABLE_VI[9]]
    rows = []
    for category, mode, command in [*commands, LARGE]:
        row = run(category, mode, command)
        rows.append(row)
        print(json.dumps(row), flush=True)
    ok = [r for r in rows if r.get("executed") == "success" and r.get("v_traj") == "pass"]
    large = rows[-1]
    summary = {
        "passed": f"{len(ok)}/{len(rows)}",
        "mean_planning_s_per_step": round(
            statistics.mean(r["planning_s_per_step"] for r in rows if "planning_s_per_step" in r), 3
        ),
        "best_speedup": max((r.get("speedup") or 0.0 for r in rows), default=0.0),
        "large_job_planning_s": large.get("planning_s_two_arms"),
        "targets": {"large_job_planning_s": 20.0, "speedup": 1.8},
    }
    print(json.dumps(summary))
    OUT.parent.mkdir(parents=True, exist_ok=True)
    result = {"benchmark": "cell_motion", "python": sys.version.split()[0]}
    result |= {"summary": summary, "rows": rows}
    OUT.write_text(json.dumps(result, indent=2) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
