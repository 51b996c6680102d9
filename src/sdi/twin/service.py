"""What the twin does with runs: start, review, approve, execute, watch — on the run database.

The twin is one more client of the orchestrator, beside the CLI, on the same run database: a
run started in either can be reviewed, approved or resumed in the other. Each action that may
take seconds (a command through the Specifier and Designer, motion planning, execution) runs in
a worker thread with its own `Orchestrator`; the page follows it through the run's event
stream. One tab at a time holds a run's edit lock; every tab sees the same state.

The design review's edits live in a `ReviewSession` per run, stored in the run database after
each step (table ``twin_reviews``), so a reload or a restart of the server shows them again.
"""

from __future__ import annotations

import json
import logging
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sdi.errors import InputError, SDIError
from sdi.execute.record import layout_hash
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.rundb import connect, prepare
from sdi.orchestrator.runner import Orchestrator, RunStatus
from sdi.twin.replay import replay
from sdi.twin.review import ReviewSession, page_parts

log = logging.getLogger(__name__)

LOCK_SECONDS = 20.0
"""A tab that has not been heard from for this long loses the edit lock, s."""

SCHEMA = """
CREATE TABLE IF NOT EXISTS twin_reviews (
    run_id TEXT PRIMARY KEY, base_hash TEXT NOT NULL, steps TEXT NOT NULL, undone TEXT NOT NULL
);
"""


REVIEWED = ("design_review", "recovery_review")
"""Pauses that show a layout the operator may edit and accept (a recovery that changed the
shape comes back as `recovery_review`, with what it changed)."""

EDITABLE = (*REVIEWED, "failure_report")
"""Pauses whose layout the page's editor opens: at a failure report, the failed layout (what
the operator sends is an edit; the run inspects it and comes back to design review)."""


class LockedError(InputError):
    """Another tab holds the run's edit lock."""


@dataclass
class Lock:
    tab: str
    seen: float


class Twin:
    """The twin's model of every run in one run database."""

    def __init__(self, db: Path, cell: CellConfig | None = None) -> None:
        self.db = prepare(db)
        self.cell = cell
        self._orch = Orchestrator(db=self.db, cell=cell)
        self._conn = connect(self.db)
        self._conn.isolation_level = None
        self._conn.executescript(SCHEMA)
        self._lock = threading.RLock()
        self.bus = MessageBus(self.db)
        self.sessions: dict[str, ReviewSession] = {}
        self.locks: dict[str, Lock] = {}
        self.busy: dict[str, str] = {}
        self.errors: dict[str, str] = {}
        self.threads: list[threading.Thread] = []

    def close(self) -> None:
        for t in self.threads:
            t.join(timeout=60)
        self.bus.close()
        self._orch.close()
        self._conn.close()

    # -- workers ----------------------------------------------------------------------------------
    def _work(self, run_id: str, action: str, fn: Callable[[Orchestrator], Any]) -> None:
        """Run `fn` with a fresh orchestrator in a worker thread; one action per run at a time."""
        with self._lock:
            if run_id in self.busy:
                raise InputError(f"run {run_id} is busy ({self.busy[run_id]}); wait", field="run")
            self.busy[run_id] = action
            self.errors.pop(run_id, None)

        def target() -> None:
            orch = Orchestrator(db=self.db, cell=self.cell)
            try:
                fn(orch)
            except SDIError as exc:
                self._fail(run_id, str(exc))
            except Exception as exc:  # a bug, not the operator's mistake: said on the page too
                log.exception("the twin's %s of run %s failed", action, run_id)
                self._fail(run_id, f"the {action} stopped on an internal error "
                                   f"({type(exc).__name__}: {exc}); the run is as its last "
                                   "checkpoint left it; see the server log")  # fmt: skip
            finally:
                orch.close()
                with self._lock:
                    self.busy.pop(run_id, None)
                self.bus.send(run_id, "twin", "human", "twin_idle", {"action": action})

        thread = threading.Thread(target=target, name=f"sdi-{action}-{run_id}", daemon=True)
        self.threads = [t for t in self.threads if t.is_alive()]
        self.threads.append(thread)
        thread.start()

    def _fail(self, run_id: str, error: str) -> None:
        self.errors[run_id] = error
        self.bus.send(run_id, "twin", "human", "twin_error", {"error": error})

    def wait(self, timeout: float = 600.0) -> None:
        """Block until every worker finished (tests, shutdown)."""
        end = time.monotonic() + timeout
        for t in list(self.threads):
            t.join(timeout=max(0.0, end - time.monotonic()))

    # -- runs -------------------------------------------------------------------------------------
    def start(self, command: str, faults: list[str] | None = None) -> str:
        """Start a run of `command` (with injected `faults`, for demonstrations and tests)."""
        from sdi.execute.faults import FAULTS

        command = command.strip()
        if not command:
            raise InputError("type a command first", field="command")
        unknown = [f for f in faults or [] if f not in FAULTS]
        if unknown:
            raise InputError(f"unknown fault scenarios {unknown}; choose from {sorted(FAULTS)}",
                             field="faults")  # fmt: skip
        run_id = Orchestrator.new_run_id()
        self.bus.send(run_id, "twin", "orchestrator", "twin_command", {"command": command})
        self._work(run_id, "plan", lambda o: o.start(command, run_id=run_id, faults=faults))
        return run_id

    def runs(self, limit: int = 50) -> list[dict[str, Any]]:
        out: list[dict[str, Any]] = []
        for run_id in reversed(self.bus.runs()[-limit:]):
            try:
                status = self._status(run_id)
            except InputError:  # events only (a run that never reached its first checkpoint)
                out.append({"run_id": run_id, "status": "busy" if run_id in self.busy else "?"})
                continue
            waiting = (status.waiting_for or {}).get("kind")
            out.append({"run_id": run_id, "status": status.status, "waiting_for": waiting,
                        "command": status.state.get("command"),
                        "busy": self.busy.get(run_id)})  # fmt: skip
        return out

    def _status(self, run_id: str) -> RunStatus:
        with self._lock:
            return self._orch.status(run_id)

    # -- review sessions --------------------------------------------------------------------------
    def _cell(self, status: RunStatus) -> CellConfig:
        raw = status.state.get("cell")
        return CellConfig.model_validate(raw) if raw else CellConfig()

    def session(self, run_id: str, status: RunStatus | None = None) -> ReviewSession | None:
        """The review session of a run waiting at design review or a failure report (made or
        reloaded on demand)."""
        status = status or self._status(run_id)
        waiting = status.waiting_for or {}
        if waiting.get("kind") not in EDITABLE or not waiting.get("layout"):
            return None
        base = Layout.model_validate(waiting["layout"])
        base_hash = layout_hash(base)
        with self._lock:
            s = self.sessions.get(run_id)
            if s is not None and s.base_hash == base_hash:
                return s
            s = ReviewSession(self._cell(status), base)
            row = self._conn.execute(
                "SELECT base_hash, steps, undone FROM twin_reviews WHERE run_id = ?", (run_id,)
            ).fetchone()
            if row is not None and row[0] == base_hash:
                s.steps, s.undone = json.loads(row[1]), json.loads(row[2])
            self.sessions[run_id] = s
            return s

    def _store(self, run_id: str, s: ReviewSession) -> None:
        self._conn.execute(
            "INSERT OR REPLACE INTO twin_reviews VALUES (?, ?, ?, ?)",
            (run_id, s.base_hash, json.dumps(s.steps), json.dumps(s.undone)),
        )

    def _forget(self, run_id: str) -> None:
        """Drop the run's review session: its edits belong to a design the operator turned
        down (a replan that brings the same layout back starts without them)."""
        with self._lock:
            self.sessions.pop(run_id, None)
            self._conn.execute("DELETE FROM twin_reviews WHERE run_id = ?", (run_id,))

    # -- the edit lock ----------------------------------------------------------------------------
    def lock(self, run_id: str, tab: str) -> Lock:
        """Take (or keep) the run's edit lock for `tab`; `LockedError` if another tab has it."""
        if not tab:
            raise InputError("the page did not say which tab it is", field="tab")
        now = time.monotonic()
        with self._lock:
            held = self.locks.get(run_id)
            if held is not None and held.tab != tab and now - held.seen < LOCK_SECONDS:
                raise LockedError(
                    "another tab is editing this run; wait for it or close it", field="lock"
                )
            self.locks[run_id] = Lock(tab, now)
            return self.locks[run_id]

    def release(self, run_id: str, tab: str) -> None:
        with self._lock:
            held = self.locks.get(run_id)
            if held is not None and held.tab == tab:
                del self.locks[run_id]

    def seen(self, run_id: str, tab: str) -> None:
        """A heartbeat of a tab: keeps its lock alive."""
        with self._lock:
            held = self.locks.get(run_id)
            if held is not None and held.tab == tab:
                held.seen = time.monotonic()

    def holder(self, run_id: str) -> str | None:
        held = self.locks.get(run_id)
        if held is None or time.monotonic() - held.seen >= LOCK_SECONDS:
            return None
        return held.tab

    # -- touch point 1: design review -------------------------------------------------------------
    def _review(self, run_id: str, tab: str) -> ReviewSession:
        self.lock(run_id, tab)
        if run_id in self.busy:
            raise InputError(f"run {run_id} is busy ({self.busy[run_id]}); wait", field="run")
        s = self.session(run_id)
        if s is None:
            raise InputError(f"run {run_id} is not waiting at design review", field="run")
        return s

    def _kind(self, run_id: str) -> str | None:
        return (self._status(run_id).waiting_for or {}).get("kind")

    def resolve_edit(self, run_id: str, tab: str, action: str) -> None:
        """Answer an edit the run's Inspector refused (made outside the twin, e.g. by
        `sdi resume --edit`): take the minimal repair, undo it, replan, or reject."""
        from sdi.orchestrator.graph import EDIT_CHOICES

        self.lock(run_id, tab)
        status = self._status(run_id)
        if (status.waiting_for or {}).get("kind") != "edit_review":
            raise InputError(f"run {run_id} has no refused edit to answer", field="run")
        if action not in EDIT_CHOICES or action == "edit":
            raise InputError("use repair, undo, replan or reject", field="action")
        decision = {"action": action, "by": "twin"}
        self._work(run_id, f"edit-{action}", lambda o: o.resume(run_id, decision))

    def edit(self, run_id: str, tab: str, op: dict[str, Any]) -> dict[str, Any]:
        s = self._review(run_id, tab)
        with self._lock:
            if op.get("op") == "undo":
                s.undo()
            elif op.get("op") == "redo":
                s.redo()
            else:
                s.apply(op)
            self._store(run_id, s)
            view = s.to_json_dict()
        self.bus.send(run_id, "twin", "human", "twin_edit", {"version": s.version})
        return view

    def accept(self, run_id: str, tab: str, layout_hash_seen: str) -> None:
        """Accept the layout under review as the page showed it (its hash). With edits, the run
        applies them itself (C ⊕ I_h), re-inspects, and is approved only if the layout it then
        waits on is the one the operator saw."""
        s = self._review(run_id, tab)
        if not s.report().passed:
            raise InputError(
                "the layout has violations; fix them (or undo) before accepting", field="accept"
            )
        current = layout_hash(s.layout())
        if layout_hash_seen != current:
            raise InputError("the layout changed since the page showed it; look again",
                             field="layout_hash")  # fmt: skip
        edits = s.edits
        if self._kind(run_id) == "failure_report":  # the failed layout, edited: the run
            if not edits:  # inspects it and comes back to design review
                raise InputError("edit the failed layout first (or retry, or abort)", field="edits")
            decision = {"action": "edit", "edits": edits, "by": "twin"}
            self._work(run_id, "edit-failed", lambda o: o.resume(run_id, decision))
            return

        def run(o: Orchestrator) -> None:
            status = o.status(run_id)
            if edits:
                status = o.resume(run_id, {"action": "edit", "edits": edits, "by": "twin"})
            waiting = status.waiting_for or {}
            layout = waiting.get("layout")
            if (
                waiting.get("kind") in REVIEWED
                and layout is not None
                and layout_hash(Layout.model_validate(layout)) == current
            ):
                o.resume(run_id, {"action": "approve", "by": "twin", "layout_hash": current})

        self._work(run_id, "accept", run)

    def reject(self, run_id: str, tab: str, reason: str) -> None:
        """Reject the design with a reason: the orchestrator replans with it (the next design
        review says what changed, or that nothing did)."""
        self._review(run_id, tab)
        if self._kind(run_id) not in REVIEWED:
            raise InputError(f"run {run_id} is not waiting at design review", field="run")
        reason = " ".join(reason.split())[:500]
        if not reason:
            raise InputError("say why, so the orchestrator can replan (or abort the run)",
                             field="reason")  # fmt: skip
        decision = {"action": "reject", "reason": reason, "by": "twin"}
        self._forget(run_id)
        self._work(run_id, "reject", lambda o: o.resume(run_id, decision))

    def abort(self, run_id: str, tab: str) -> None:
        """End the run at design review (nothing moves)."""
        self._review(run_id, tab)
        if self._kind(run_id) not in REVIEWED:
            raise InputError(f"run {run_id} is not waiting at design review", field="run")
        decision = {"action": "abort", "by": "twin"}
        self._work(run_id, "abort", lambda o: o.resume(run_id, decision))

    # -- touch point 2: the commissioning record ---------------------------------------------------
    def confirm(self, run_id: str, tab: str, action: str, record_hash: str | None) -> None:
        self.lock(run_id, tab)
        status = self._status(run_id)
        waiting = status.waiting_for or {}
        if waiting.get("kind") not in ("pre_execute", "resume_execution"):
            raise InputError(f"run {run_id} is not waiting for approval to execute", field="run")
        if action == "approve":
            if record_hash != waiting.get("record_hash"):
                raise InputError("the approval must name the record on screen; reload",
                                 field="record_hash")  # fmt: skip
            decision = {"action": "approve", "record_hash": record_hash, "by": "twin"}
        elif action in ("revise", "abort"):
            decision = {"action": action, "by": "twin"}
        else:
            raise InputError("use approve, revise or abort", field="action")
        self._work(run_id, f"confirm-{action}", lambda o: o.resume(run_id, decision))

    # -- touch point 3: failure report ------------------------------------------------------------
    def failure_decision(
        self, run_id: str, tab: str, action: str, skill: str | None = None
    ) -> None:
        """Answer a failure report: a recovery skill the report offers, retry (plan again) or
        abort; the human edit goes through the editor (`edit`, then `accept`)."""
        self.lock(run_id, tab)
        status = self._status(run_id)
        waiting = status.waiting_for or {}
        if waiting.get("kind") != "failure_report":
            raise InputError(f"run {run_id} has no failure report open", field="run")
        decision: dict[str, Any] = {"action": action, "by": "twin"}
        if action == "recover":
            offered = [k["name"] for k in waiting.get("skills") or []]
            if skill not in offered:
                raise InputError(f"choose one of the skills offered: {', '.join(offered)}",
                                 field="skill")  # fmt: skip
            decision["skill"] = skill
        elif action not in ("retry", "abort"):
            raise InputError("use recover, retry or abort (or edit the layout)", field="action")
        self._forget(run_id)
        self._work(run_id, f"failure-{action}", lambda o: o.resume(run_id, decision))

    # -- views ------------------------------------------------------------------------------------
    def view(self, run_id: str) -> dict[str, Any]:
        """Everything the page shows of a run, in one value."""
        try:
            status = self._status(run_id)
        except InputError:
            history = self.bus.history(run_id)
            if not history:
                raise
            # started, before its first checkpoint: only the command is known so far
            command = next((m.payload.get("command") for m in history
                            if m.type in ("twin_command", "command")), None)  # fmt: skip
            status = RunStatus(run_id, "running", None, {"command": command})
        state = status.state
        waiting = dict(status.waiting_for or {})
        session = self.session(run_id, status)
        layout = None
        if state.get("layout") and (session is None or waiting.get("kind") not in REVIEWED):
            layout = page_parts(state["layout"])
        if waiting.get("kind") == "edit_review" and session is None:
            layout = page_parts(waiting.get("layout"))
        waiting.pop("layout", None)
        return {
            "run_id": run_id,
            "command": state.get("command"),
            "status": status.status,
            "waiting_for": waiting or None,
            "busy": self.busy.get(run_id),
            "error": self.errors.get(run_id),
            "lock": self.holder(run_id),
            "reading": reading(state),
            "review": session.to_json_dict() if session is not None else None,
            "layout": layout,
            "sequence": state.get("sequence"),
            "violations": state.get("violations") or [],
            "planning": state.get("planning"),
            "record_hash": state.get("record_hash"),
            "approved_hash": state.get("approved_hash"),
            "execution": _execution_summary(state.get("execution")),
            "failure": state.get("failure"),
            "notes": state.get("notes") or [],
        }

    def timeline(
        self, run_id: str, record_hash: str | None = None, rate_hz: float = 20.0
    ) -> dict[str, Any]:
        """The commissioning record as the page plays it: each arm's Q_plan thinned to
        `rate_hz`, when each part is gripped and released, the schedule and the makespan. The
        record is `record_hash`, else the run's current one (`Orchestrator.record`: the one
        awaiting approval, else the one approved)."""
        from sdi.execute.record import RecordError

        try:
            with self._lock:
                if record_hash is None:
                    record = self._orch.record(run_id)
                else:  # a record an event names (a replay)
                    record = self._orch.records.get(run_id, record_hash)
        except RecordError as exc:
            raise InputError(str(exc), field="record") from None
        body = record.body
        robots: dict[str, Any] = {}
        for name, tr in body["motion"]["trajectories"].items():
            every = max(1, round(float(tr["rate_hz"]) / rate_hz))
            t, q = tr["t"][::every], tr["q"][::every]
            if tr["t"] and t[-1] != tr["t"][-1]:
                t, q = [*t, tr["t"][-1]], [*q, tr["q"][-1]]
            robots[name] = {"t": [round(v, 4) for v in t],
                            "q": [[round(v, 5) for v in row] for row in q]}  # fmt: skip
        when = {(e["kind"], e["part_id"]): e["t"] for e in body["motion"]["events"]}
        motions = {m["step"]: m for m in body["motion"]["steps"]}
        steps = []
        for s in body["tasks"]["steps"]:
            grip, release = when.get(("grip", s["part_id"])), when.get(("release", s["part_id"]))
            motion: dict[str, Any] = motions.get(s["step"], {})
            steps.append({"step": s["step"], "part_id": s["part_id"], "robot": s["robot"],
                          "start": motion.get("start"), "end": motion.get("end"),
                          "grip": grip, "release": release,
                          "target": s["T_world_part_target"], "size": s["part_size"]})  # fmt: skip
        makespan = max((r["t"][-1] for r in robots.values() if r["t"]), default=0.0)
        return {"record_hash": record.hash, "robots": robots, "steps": steps,
                "makespan_s": makespan, "parallel": body["parallel"]}  # fmt: skip

    def events(self, run_id: str, after: int = 0) -> list[dict[str, Any]]:
        return [m.to_json_dict() for m in self.bus.history(run_id, after=after)]

    def replay(self, run_id: str) -> dict[str, Any]:
        """The run told again from its event stream alone (`sdi.twin.replay`)."""
        history = self.events(run_id)
        if not history:
            raise InputError(f"no run {run_id!r} in {self.db}", field="RUN_ID")
        return replay(history)


def reading(state: dict[str, Any]) -> dict[str, Any] | None:
    """The Specifier's reading as the page lists it: structures, relations, assumptions."""
    spec = state.get("spec")
    if not spec:
        return None
    from sdi.spec.structure_spec import Spec

    parsed = Spec.model_validate(spec)
    names = [f"{s.shape}#{k + 1}" for k, s in enumerate(parsed.structures)]
    return {
        "source": state.get("spec_source"),
        "structures": [f"{names[k]}: {s.describe()}" for k, s in enumerate(parsed.structures)],
        "relations": [r.describe(names) for r in parsed.relations],
        "notes": list(parsed.notes),
        "ignored": list(state.get("ignored") or []),
    }


def _execution_summary(report: dict[str, Any] | None) -> dict[str, Any] | None:
    if not report:
        return None
    keep = ("status", "v_traj", "delta_rad", "epsilon_rad", "max_placement_error_m",
            "completed_steps", "record_hash", "failure", "scenario")  # fmt: skip
    return {k: report[k] for k in keep if k in report}
