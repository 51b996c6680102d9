"""Seconds from the operator's approval to the first robot motion (the 25-part dual-arm job).

The whole orchestrator runs on a real run database: design review approved, PRE_EXECUTE plans
motion once and stores the commissioning record, then the record is approved and EXECUTE runs
it. Measured (wall clock, this machine): the planning time in PRE_EXECUTE, and the time from
the approval call to the driver's first simulated control step (the `motion_started` event),
which before the commissioning record included a second, full re-plan. The execution runs to
the end, so the result also says whether the approved record was built.

Run: `python benchmarks/approval_to_motion.py [--command TEXT]` (part of `make bench`).
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

from sdi.orchestrator import Orchestrator

OUT = Path(__file__).parent / "results" / "approval_to_motion.json"
LARGE = "a wall 5 long and 3 high at x = 0.3 and a wall 5 long and 2 high at x = 0.7"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--command", default=LARGE)
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        orch = Orchestrator(db=Path(tmp) / "runs.sqlite")
        try:
            s = orch.start(args.command)
            assert s.status == "paused" and s.waiting_for["kind"] == "design_review", s.status
            t = time.perf_counter()
            s = orch.resume(s.run_id, {"action": "approve"})
            planning_s = time.perf_counter() - t
            assert s.waiting_for["kind"] == "pre_execute", s.status
            record = s.waiting_for["record_hash"]
            approved_at = time.time()
            s = orch.resume(s.run_id, {"action": "approve", "record_hash": record})
            events = orch.bus.history(s.run_id)
        finally:
            orch.close()
    first_motion = next(m for m in events if m.type == "motion_started")
    started = next(m for m in events if m.type == "execution_started")
    execution = s.state.get("execution") or {}
    row = {
        "command": args.command,
        "parts": len(s.state["layout"]["objects"]),
        "record_hash": record,
        "makespan_s": s.state["planning"]["makespan_s"],
        "steps_per_robot": s.state["planning"]["steps_per_robot"],
        "planning_s_in_pre_execute": round(planning_s, 3),
        "approval_to_execution_started_s": round(started.ts - approved_at, 3),
        "approval_to_first_motion_s": round(first_motion.ts - approved_at, 3),
        "executed_record_hash": execution.get("record_hash"),
        "status": s.status,
        "v_traj": execution.get("v_traj"),
        "max_placement_error_mm": round(
            1000 * float(execution.get("max_placement_error_m") or 0), 2
        ),
        "records_planned": sum(m.type == "record" for m in events),
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(row, indent=2) + "\n", encoding="utf-8")
    print(json.dumps(row, indent=2))
    return 0 if row["executed_record_hash"] == record and s.status == "success" else 1


if __name__ == "__main__":
    sys.exit(main())
