"""Runs of the orchestrator: start, resume after an interrupt or a crash, status, audit log.

One SQLite file (default: the user's data directory, or $SDI_DB; created 0600) holds the
LangGraph checkpoints (read back as plain data only: `PlainSerializer`), the event stream, the
run leases and the commissioning records. A run's thread id is its run id, so any process can
resume it — one at a time: every start or resume holds the run's lease.

A run is bound to what it was started with: its method, backend, arms, fault scenarios and cell
(stored in the state with its hash). `resume` continues with those; another cell is refused,
naming both hashes, unless the caller asks to replan with it.
"""

from __future__ import annotations

import sqlite3
import uuid
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from langgraph.checkpoint.sqlite import SqliteSaver
from langgraph.types import Command

from sdi.errors import InputError
from sdi.execute.record import CommissioningRecord, cell_hash
from sdi.llm.chat import ChatModel, Usage
from sdi.model.cell import CellConfig
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.graph import Jobs, RunContext, RunState, build_graph
from sdi.orchestrator.lease import RunLease
from sdi.orchestrator.methods import METHODS
from sdi.orchestrator.records import RecordStore
from sdi.orchestrator.rundb import connect, default_db, prepare
from sdi.orchestrator.serde import PlainSerializer, UnsafeCheckpointError

if TYPE_CHECKING:
    from langchain_core.runnables import RunnableConfig

    from sdi.model.layout import Layout

__all__ = ["Orchestrator", "RunInfo", "RunStatus", "default_db"]

REVIEWS = ("design_review", "pre_execute", "resume_execution")
"""Interrupts that `--approve-all` answers; a failure report always needs a person."""

SHOWN = ("design_review", "recovery_review", "edit_review", "failure_report")
"""Interrupts that show a layout: the `stopped` event carries it (replays read it there)."""


@dataclass
class RunStatus:
    run_id: str
    status: str  # paused | success | verified | failure | rejected | aborted | running
    waiting_for: dict[str, Any] | None = None
    state: dict[str, Any] = field(default_factory=dict)
    usage: dict[str, Any] = field(default_factory=dict)

    def to_json_dict(self) -> dict[str, Any]:
        keep = ("command", "method", "backend", "cell_hash", "spec_source", "sequence",
                "replans", "tried", "failure", "execution", "planning", "record_hash",
                "approved_hash", "notes", "ignored", "unread", "relaxed", "recoveries",
                "edit", "edit_outcome")  # fmt: skip
        return {
            "run_id": self.run_id,
            "status": self.status,
            "waiting_for": self.waiting_for,
            "layout_parts": len((self.state.get("layout") or {}).get("objects", [])),
            **{k: self.state.get(k) for k in keep if k in self.state},
            "usage": self.usage,
        }


@dataclass(frozen=True)
class RunInfo:
    """What a run was started with."""

    run_id: str
    method: str
    backend: str
    cell_hash: str
    arms: list[str] | None


class Orchestrator:
    """Starts and resumes runs in one run database.

    `cell` is the cell for new runs (default: the built-in cell). On resume the run's own cell
    is used; a `cell` given here must have the same hash unless `replan_with_cell`.
    """

    def __init__(
        self,
        *,
        db: Path | None = None,
        cell: CellConfig | None = None,
        model: ChatModel | None = None,
        arms: list[str] | None = None,
        create: bool = True,
    ) -> None:
        self.db = prepare(db or default_db(), create=create)
        self.cell = cell
        self.model = model
        self.arms = arms
        self._conn = connect(self.db)
        try:
            self.saver = SqliteSaver(self._conn, serde=PlainSerializer())
            self.saver.setup()
        except sqlite3.DatabaseError as exc:
            message = f"{self.db} is not a usable run database ({exc})"
            raise InputError(message, field="--db") from None
        self.bus = MessageBus(self.db)
        self.records = RecordStore(self.db)
        self.graph = build_graph().compile(checkpointer=self.saver)
        self._owned: set[str] = set()
        self.jobs = Jobs()  # verified jobs, handed from INSPECT to PRE_EXECUTE and EXECUTE

    @contextmanager
    def owning(self, run_id: str) -> Iterator[None]:
        """Hold the run's lease for the block (re-entrant: a `start` or `resume` inside it does
        not take it again). `RunBusyError` if another live process holds it."""
        if run_id in self._owned:
            yield
            return
        with RunLease(self.db, run_id):
            self._owned.add(run_id)
            try:
                yield
            finally:
                self._owned.discard(run_id)

    @staticmethod
    def new_run_id() -> str:
        return uuid.uuid4().hex[:12]

    def close(self) -> None:
        self.bus.close()
        self.records.close()
        self._conn.close()

    # -- state ----------------------------------------------------------------------------------
    def _config(self, run_id: str) -> RunnableConfig:
        return {"configurable": {"thread_id": run_id}}

    def _snapshot(self, run_id: str) -> Any:
        try:
            return self.graph.get_state(self._config(run_id))
        except UnsafeCheckpointError as exc:
            raise InputError(
                f"{self.db}: run {run_id} holds data that is not plain ({exc}); refusing to "
                "load it — nothing was run. Use a run database SDI wrote.",
                field="--db",
            ) from None

    def _values(self, run_id: str) -> dict[str, Any]:
        values = dict(self._snapshot(run_id).values or {})
        if not values:
            raise InputError(f"no run {run_id!r} in {self.db}", field="RUN_ID")
        return values

    def info(self, run_id: str) -> RunInfo:
        v = self._values(run_id)
        return RunInfo(run_id, str(v.get("method", "Hybrid")), str(v.get("backend", "rules")),
                       str(v.get("cell_hash", "")), v.get("arms"))  # fmt: skip

    def _context(self, values: dict[str, Any]) -> RunContext:
        """The run's context from what it was started with; a stored value that is not what SDI
        writes (a crafted or damaged database) is refused naming the file."""
        from pydantic import ValidationError

        from sdi.execute.faults import FAULTS

        def bad(what: str) -> InputError:
            return InputError(f"{self.db}: run {values.get('run_id')} holds {what}", field="--db")

        method = values.get("method", "Hybrid")
        if method not in METHODS:
            raise bad(f"an unknown method {method!r}")
        faults = values.get("faults") or []
        if not isinstance(faults, list) or not all(f in FAULTS for f in faults):
            raise bad(f"unknown fault scenarios {faults!r}")
        arms = values.get("arms")
        if arms is not None and not (
            isinstance(arms, list) and all(isinstance(a, str) for a in arms)
        ):
            raise bad(f"malformed arms {arms!r}")
        try:
            cell = CellConfig.model_validate(values["cell"]) if values.get("cell") else CellConfig()
        except (ValidationError, TypeError, ValueError) as exc:
            raise bad(f"an invalid cell configuration ({str(exc).splitlines()[0]})") from None
        if values.get("cell") and cell_hash(cell) != values.get("cell_hash"):
            raise bad("a cell configuration that does not match its recorded hash")
        return RunContext(
            cell, METHODS[method], self.model, self.bus, self.records, arms, self.jobs
        )

    def _status(self, run_id: str) -> RunStatus:
        snapshot = self._snapshot(run_id)
        values = dict(snapshot.values or {})
        waiting = None
        for task in snapshot.tasks or ():
            for intr in getattr(task, "interrupts", ()) or ():
                waiting = intr.value
        status = (
            "paused"
            if waiting is not None
            else values.get("status") or ("running" if snapshot.next else "failure")
        )
        usage = (self.model.usage if self.model else Usage()).to_json_dict()
        return RunStatus(run_id, status, waiting, values, usage)

    def _invoke(self, run_id: str, values: dict[str, Any], payload: Any) -> RunStatus:
        try:
            self.graph.invoke(
                payload, self._config(run_id), context=self._context(values), durability="sync"
            )
        except UnsafeCheckpointError as exc:
            raise InputError(f"{self.db}: run {run_id}: {exc}", field="--db") from None
        status = self._status(run_id)
        waiting = status.waiting_for or {}
        stopped = {"status": status.status, "waiting_for": waiting.get("kind")}
        if waiting.get("record_hash"):
            stopped["record_hash"] = waiting["record_hash"]
        if waiting.get("kind") in SHOWN and waiting.get("layout"):
            # the layout the person is shown, so a replay of the events alone steps through
            # the design versions (and what each review said of it)
            stopped["layout"] = waiting["layout"]
            stopped["sequence"] = waiting.get("sequence")
            for key in ("replanned", "recovery", "refused", "violations"):
                if waiting.get(key):
                    stopped[key] = waiting[key]
        self.bus.send(run_id, "orchestrator", "human", "stopped", stopped)
        return status

    # -- runs -------------------------------------------------------------------------------------
    def start(
        self,
        command: str,
        *,
        method: str = "Hybrid",
        backend: str = "rules",
        faults: list[str] | None = None,
        approve: bool = False,
        run_id: str | None = None,
        design_only: bool = False,
        layout: Layout | None = None,
        sequence: list[str] | None = None,
    ) -> RunStatus:
        """Run `command` until it ends or pauses for a person. `approve` answers every review
        (unattended, `--approve-all`); `design_only` stops once the design passed the Inspector
        (status ``verified``; nothing is planned or executed). With `layout` (a layout file, and
        its `sequence` if it has one) that layout is the design: no Specifier, no Designer; the
        Inspector, the reviews and the record's approval are the same as for a command."""
        if method not in METHODS:
            raise InputError(
                f"unknown method {method!r}; choose from {sorted(METHODS)}", field="--method"
            )
        if layout is not None and not len(layout):
            raise InputError("the layout has no parts: nothing to build", field="--layout")
        cell = self.cell or CellConfig()
        run_id = run_id or self.new_run_id()
        state: RunState = {
            "run_id": run_id, "command": command, "method": method, "backend": backend,
            "cell": cell.model_dump(mode="json"), "cell_hash": cell_hash(cell),
            "arms": list(self.arms) if self.arms else None, "replans": 0, "tried": [],
            "faults": list(faults or []), "notes": [], "approve": approve, "relaxed": False,
            "design_only": design_only,
        }  # fmt: skip
        if layout is not None:
            state["given_layout"] = layout.to_json_dict()
            state["operator_sequence"] = list(sequence) if sequence is not None else None
        with self.owning(run_id):
            if self._snapshot(run_id).values:
                raise InputError(f"run {run_id} exists already in {self.db}", field="RUN_ID")
            self.bus.send(run_id, "human", "orchestrator", "command",
                          {"command": command, "method": method, "backend": backend,
                           "cell_hash": state["cell_hash"], "faults": state["faults"],
                           "arms": state["arms"], "approve_all": approve,
                           "given_parts": None if layout is None else len(layout)})  # fmt: skip
            return self._invoke(run_id, dict(state), state)

    def _bind_cell(self, run_id: str, values: dict[str, Any], replan_with_cell: bool) -> bool:
        """Check the caller's cell against the run's; True if the run must replan with it."""
        if self.cell is None:
            return False
        now, then = cell_hash(self.cell), str(values.get("cell_hash", ""))
        if now == then:
            return False
        if not replan_with_cell:
            raise InputError(
                f"run {run_id} was started with cell {then[:12]}, the cell given now is "
                f"{now[:12]}; resume without --cell to continue with the run's cell, or add "
                "--replan-with-cell to inspect and plan the design again with the new one",
                field="--cell",
            )
        return True

    def resume(
        self,
        run_id: str,
        decision: dict[str, Any] | None = None,
        *,
        approve_all: bool = False,
        replan_with_cell: bool = False,
    ) -> RunStatus:
        """Continue a paused or crashed run; `decision` answers the review it waits on;
        `approve_all` then answers every later review too (never a failure report)."""
        values = self._values(run_id)
        config = self._config(run_id)
        with self.owning(run_id):
            if self._bind_cell(run_id, values, replan_with_cell):
                assert self.cell is not None
                new = cell_hash(self.cell)
                change = {"from": values.get("cell_hash"), "to": new}
                self.bus.send(run_id, "human", "orchestrator", "cell_changed", change)
                update = {
                    "cell": self.cell.model_dump(mode="json"), "cell_hash": new,
                    "phase": "inspect", "record_hash": None, "approved_hash": None,
                    "resume_from": None,
                }  # fmt: skip
                self.graph.update_state(config, update, as_node="modify")
                values = self._values(run_id)
                status = self._invoke(run_id, values, None)
            else:
                status = self._status(run_id)
                if status.status == "running":
                    status = self._continue_crashed(run_id, values)
                elif status.status == "paused" and decision is not None:
                    status = self._invoke(run_id, values, Command(resume=decision))
            while approve_all and status.status == "paused":
                waiting = status.waiting_for or {}
                if waiting.get("kind") not in REVIEWS:
                    break
                answer = {"action": "approve", "by": "--approve-all"}
                if waiting.get("record_hash"):
                    answer["record_hash"] = waiting["record_hash"]
                status = self._invoke(run_id, values, Command(resume=answer))
        return status

    def _continue_crashed(self, run_id: str, values: dict[str, Any]) -> RunStatus:
        """A process died inside a node. If it died while executing, what is built stays built:
        record the interrupted attempt, and ask again before anything moves."""
        snapshot = self._snapshot(run_id)
        interrupted = interrupted_attempt(self.bus, run_id)
        if tuple(snapshot.next) == ("execute",) and interrupted is not None:
            self.bus.send(run_id, "orchestrator", "human", "execution_interrupted", interrupted)
            self.graph.update_state(
                self._config(run_id),
                {"resume_from": interrupted, "phase": "confirm"},
                as_node="pre_execute",
            )
        return self._invoke(run_id, values, None)

    def record(self, run_id: str) -> CommissioningRecord:
        """The run's current commissioning record, checked against its hash (for exporters, the
        twin, audits): the one awaiting approval when the run waits on one (after a recovery,
        that is newer than the one approved before), else the one approved, else the last
        one planned."""
        values = self._values(run_id)
        waiting = self._status(run_id).waiting_for or {}
        pending = waiting.get("record_hash") if waiting.get("kind") in (
            "pre_execute", "resume_execution") else None  # fmt: skip
        record_hash = pending or values.get("approved_hash") or values.get("record_hash")
        if not record_hash:
            raise InputError(f"run {run_id} has no commissioning record yet", field="RUN_ID")
        return self.records.get(run_id, str(record_hash))

    def approved_record(self, run_id: str) -> CommissioningRecord:
        """The record the operator approved (by its hash) — the only one an exporter may use;
        `InputError` naming the run when none is approved yet."""
        approved = self._values(run_id).get("approved_hash")
        if not approved:
            raise InputError(
                f"run {run_id} has no approved commissioning record; approve the record it "
                f"shows first (sdi resume {run_id} --approve) and export again",
                field="--run",
            )
        return self.records.get(run_id, str(approved))

    def status(self, run_id: str) -> RunStatus:
        self._values(run_id)
        return self._status(run_id)


def interrupted_attempt(bus: MessageBus, run_id: str) -> dict[str, Any] | None:
    """The as-built state of an execution that started and never reported, from the events:
    the steps completed and the parts placed (with their poses), or None."""
    history = bus.history(run_id)
    starts = [k for k, m in enumerate(history) if m.type == "execution_started"]
    if not starts:
        return None
    k0 = starts[-1]
    after = history[k0 + 1 :]
    if any(m.type == "execution" for m in after):
        return None
    started = history[k0].payload
    placed = list(started.get("already_placed", []))
    placed += [
        {k: m.payload[k] for k in ("part_id", "step", "robot", "pose")}
        for m in after
        if m.type == "step_done"
    ]
    return {
        "record_hash": started.get("record_hash"),
        "started_seq": history[k0].seq,
        "steps_completed": len(placed),
        "placed": placed,
    }
