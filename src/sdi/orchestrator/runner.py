"""Runs of the orchestrator: start, resume after an interrupt or a crash, status, audit log.

One SQLite file (default: the user's data directory, or $SDI_DB) holds the LangGraph
checkpoints and the message bus. The graph is compiled with the checkpointer; a run's thread id
is its run id, so any process can resume it.
"""

from __future__ import annotations

import os
import sqlite3
import uuid
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from langgraph.checkpoint.sqlite import SqliteSaver
from langgraph.types import Command

from sdi.errors import InputError
from sdi.llm.chat import ChatModel, Usage
from sdi.model.cell import CellConfig
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.graph import RunContext, RunState, build_graph
from sdi.orchestrator.methods import METHODS


def default_db() -> Path:
    env = os.environ.get("SDI_DB")
    if env:
        return Path(env)
    from platformdirs import user_data_dir

    return Path(user_data_dir("sdi")) / "runs.sqlite"


@dataclass
class RunStatus:
    run_id: str
    status: str  # paused | success | verified | failure | rejected | aborted | running
    waiting_for: dict[str, Any] | None = None
    state: dict[str, Any] = field(default_factory=dict)
    usage: dict[str, Any] = field(default_factory=dict)

    def to_json_dict(self) -> dict[str, Any]:
        keep = ("command", "method", "backend", "spec_source", "sequence", "replans", "tried",
                "failure", "execution", "planning", "notes", "relaxed")  # fmt: skip
        return {
            "run_id": self.run_id,
            "status": self.status,
            "waiting_for": self.waiting_for,
            "layout_parts": len((self.state.get("layout") or {}).get("objects", [])),
            **{k: self.state.get(k) for k in keep if k in self.state},
            "usage": self.usage,
        }


class Orchestrator:
    def __init__(
        self,
        *,
        db: Path | None = None,
        cell: CellConfig | None = None,
        model: ChatModel | None = None,
        arms: list[str] | None = None,
    ) -> None:
        self.db = db or default_db()
        self.db.parent.mkdir(parents=True, exist_ok=True)
        self.cell = cell or CellConfig()
        self.model = model
        self.arms = arms
        self._conn = sqlite3.connect(self.db, check_same_thread=False)
        self.saver = SqliteSaver(self._conn)
        self.bus = MessageBus(self.db)

    def close(self) -> None:
        self.bus.close()
        self._conn.close()

    def _graph(self, method: str) -> Any:
        if method not in METHODS:
            raise InputError(
                f"unknown method {method!r}; choose from {sorted(METHODS)}", field="--method"
            )
        ctx = RunContext(self.cell, METHODS[method], self.model, self.bus, self.arms)
        return build_graph(ctx).compile(checkpointer=self.saver)

    def _status(self, graph: Any, run_id: str) -> RunStatus:
        snapshot = graph.get_state({"configurable": {"thread_id": run_id}})
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
    ) -> RunStatus:
        """Run `command` until it ends or pauses for a person. `design_only` stops once the
        design passed the Inspector (status ``verified``; nothing is planned or executed)."""
        graph = self._graph(method)
        run_id = run_id or uuid.uuid4().hex[:12]
        state: RunState = {
            "run_id": run_id, "command": command, "method": method, "backend": backend,
            "replans": 0, "tried": [], "faults": list(faults or []), "notes": [],
            "approve": approve, "relaxed": False, "design_only": design_only,
        }  # fmt: skip
        self.bus.send(
            run_id,
            "human",
            "orchestrator",
            "command",
            {"command": command, "method": method, "backend": backend},
        )
        graph.invoke(state, {"configurable": {"thread_id": run_id}})
        return self._status(graph, run_id)

    def method_of(self, run_id: str) -> str:
        for m in self.bus.history(run_id):
            if m.type == "command":
                return str(m.payload.get("method", "Hybrid"))
        raise InputError(f"no run {run_id!r} in {self.db}", field="RUN_ID")

    def resume(self, run_id: str, decision: dict[str, Any] | None = None) -> RunStatus:
        """Continue a paused or crashed run; `decision` answers the interrupt it waits on."""
        graph = self._graph(self.method_of(run_id))
        config = {"configurable": {"thread_id": run_id}}
        before = self._status(graph, run_id)
        if before.status == "paused":
            if decision is None:
                return before
            graph.invoke(Command(resume=decision), config)
        elif before.status == "running":  # crashed mid-graph: continue from the last checkpoint
            graph.invoke(None, config)
        return self._status(graph, run_id)

    def status(self, run_id: str) -> RunStatus:
        return self._status(self._graph(self.method_of(run_id)), run_id)
