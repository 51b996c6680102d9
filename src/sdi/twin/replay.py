"""A finished run told again from its event stream alone: design, approval, execution.

`replay` reads nothing but the run's stored events and returns the steps the page walks
through, oldest first:

- ``design``: a layout the operator was shown (the `stopped` event of a design review, a
  recovery review, a refused edit or a failure report carries it), with what that review said
  (a replan's outcome, a recovery, a refusal);
- ``decision``: the operator's answer there (approve, edit with its edits, reject with its
  reason, abort, a recovery skill, retry), and who gave it;
- ``record``: a commissioning record planned (its hash, makespan and steps);
- ``approval``: the approval of a record, naming its hash, and who gave it;
- ``execution``: one execution of the approved record: the Q_exec samples and the parts set
  down (as the events stored them), and how it ended (V_traj, δ against ε, any failure).

The execution step names its record's hash; the page plots δ against that record's Q_plan,
which the run database holds under the hash (`Twin.timeline`).
"""

from __future__ import annotations

from typing import Any

from sdi.twin.review import page_parts

ANSWERS = ("review", "failure_decision", "confirm")
"""Events that are a person's answer at a touch point."""


def _decision(event: dict[str, Any]) -> dict[str, Any]:
    p = event["payload"] if isinstance(event["payload"], dict) else {}
    step: dict[str, Any] = {"kind": "decision", "seq": event["seq"], "at": event["type"],
                            "action": p.get("action"), "by": p.get("by")}  # fmt: skip
    if isinstance(p.get("edits"), list):
        step["edits"] = p["edits"]
    for key in ("reason", "skill", "record_hash"):
        if p.get(key):
            step[key] = p[key]
    return step


def replay(events: list[dict[str, Any]]) -> dict[str, Any]:
    """The replay of one run from its events (each ``{"seq", "type", "payload", …}``)."""
    steps: list[dict[str, Any]] = []
    command: str | None = None
    execution: dict[str, Any] | None = None
    version = 0
    for e in events:
        kind, p = e["type"], e["payload"] if isinstance(e["payload"], dict) else {}
        if kind in ("command", "twin_command") and command is None:
            command = p.get("command")
        elif kind == "stopped" and p.get("layout"):
            version += 1
            step = {"kind": "design", "seq": e["seq"], "version": version,
                    "waiting_for": p.get("waiting_for"), "parts": page_parts(p["layout"]),
                    "sequence": p.get("sequence")}  # fmt: skip
            for key in ("replanned", "recovery", "refused", "violations"):
                if p.get(key):
                    step[key] = p[key]
            steps.append(step)
        elif kind == "record":
            steps.append({"kind": "record", "seq": e["seq"], "record_hash": p.get("record_hash"),
                          "makespan_s": p.get("makespan_s"), "steps": p.get("steps")})  # fmt: skip
        elif kind == "confirm" and p.get("action") == "approve":
            steps.append({"kind": "approval", "seq": e["seq"], "record_hash": p.get("record_hash"),
                          "by": p.get("by")})  # fmt: skip
        elif kind in ANSWERS:
            steps.append(_decision(e))
        elif kind == "execution_started":
            execution = {"kind": "execution", "seq": e["seq"], "record_hash": p.get("record_hash"),
                         "already_placed": p.get("already_placed") or [], "events": [],
                         "report": None}  # fmt: skip
            steps.append(execution)
        elif kind in ("samples", "step_done") and execution is not None:
            execution["events"].append({"seq": e["seq"], "type": kind, "payload": p})
        elif kind == "execution" and execution is not None:
            keep = ("status", "v_traj", "delta_rad", "epsilon_rad", "completed_steps",
                    "failure", "scenario")  # fmt: skip
            execution["report"] = {k: p.get(k) for k in keep}
            execution = None
    return {"command": command, "steps": steps}
