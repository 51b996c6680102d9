"""The compared methods on the evaluation suite: success, LLM calls, tokens and seconds.

Every method runs the whole orchestrator (Specifier, Designer, Inspector, replans with its
routing and recovery) up to the verified design — nothing is motion-planned or executed — on
the same commands and the same backend. A command succeeds when the run ends ``verified`` and
the command's acceptance predicate holds for the layout. Calls and tokens are the model's own
accounting, per command.
"""

from __future__ import annotations

import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from sdi.bench.suite import GROUPS, BenchCommand
from sdi.llm.chat import ChatModel
from sdi.model.cell import CellConfig
from sdi.model.layout import parse_layout
from sdi.orchestrator.methods import METHODS
from sdi.orchestrator.runner import Orchestrator, RunStatus


@dataclass(frozen=True)
class MethodRecord:
    """One command under one method. `seconds` is wall-clock time of the run."""

    method: str
    id: str
    group: str
    status: str
    accepted: bool
    llm_calls: int
    prompt_tokens: int
    completion_tokens: int
    malformed: int
    replans: int
    seconds: float
    reason: str | None = None
    spec_source: str | None = None  # llm | rules (llm malformed) | rules (llm disagreed) | …

    @property
    def success(self) -> bool:
        return self.status == "verified" and self.accepted


def run_method(
    method: str,
    commands: Sequence[BenchCommand],
    model: ChatModel | None,
    cell: CellConfig | None = None,
    db: Path | None = None,
    progress: Callable[[MethodRecord], None] | None = None,
) -> list[MethodRecord]:
    """Run every command through the orchestrator configured as `method`."""
    cell = cell or CellConfig()
    with tempfile.TemporaryDirectory() as tmp:
        orch = Orchestrator(db=db or Path(tmp) / "bench.sqlite", cell=cell, model=model)
        records = []
        try:
            for command in commands:
                records.append(_one(orch, method, command, model, cell))
                if progress is not None:
                    progress(records[-1])
        finally:
            orch.close()
    return records


def _one(
    orch: Orchestrator,
    method: str,
    command: BenchCommand,
    model: ChatModel | None,
    cell: CellConfig,
) -> MethodRecord:
    return run_one(orch, method, command, model, cell)[0]


def run_one(
    orch: Orchestrator,
    method: str,
    command: BenchCommand,
    model: ChatModel | None,
    cell: CellConfig,
) -> tuple[MethodRecord, RunStatus]:
    """Run one command through `orch` as `method` up to the verified design; the record and
    the run's final status (its state holds the layout and sequence)."""
    before = model.usage.to_json_dict() if model is not None else {}
    start = time.perf_counter()
    status = orch.start(command.text, method=method, design_only=True)
    seconds = time.perf_counter() - start
    after = model.usage.to_json_dict() if model is not None else {}

    def spent(key: str) -> int:
        return int(after.get(key, 0)) - int(before.get(key, 0))

    reason: str | None = None
    accepted = False
    data = status.state.get("layout")
    if status.status != "verified" or not data:
        notes = status.state.get("notes") or []
        reason = f"run {status.status}" + (f": {notes[-1]}" if notes else "")
    else:
        layout, _ = parse_layout(data, max_parts=cell.limits.max_parts)
        try:
            reason = command.accept(layout)
        except Exception as exc:  # a predicate crash is a failed check, not a crashed run
            reason = f"predicate raised {type(exc).__name__}: {exc}"
        accepted = reason is None
    record = MethodRecord(
        method=method,
        id=command.id,
        group=command.group,
        status=status.status,
        accepted=accepted,
        llm_calls=spent("llm_calls"),
        prompt_tokens=spent("prompt_tokens"),
        completion_tokens=spent("completion_tokens"),
        malformed=spent("malformed"),
        replans=int(status.state.get("replans") or 0),
        seconds=seconds,
        reason=reason,
        spec_source=status.state.get("spec_source"),
    )
    return record, status


def summarise(records: Sequence[MethodRecord]) -> dict[str, Any]:
    """Per method: success rate per group and overall, mean calls, tokens and seconds."""

    def stats(rs: Sequence[MethodRecord]) -> dict[str, Any]:
        n = len(rs)
        if not n:
            return {"count": 0}
        return {
            "count": n,
            "success_rate": round(sum(r.success for r in rs) / n, 4),
            "llm_calls_per_command": round(sum(r.llm_calls for r in rs) / n, 3),
            "tokens_per_command": round(
                sum(r.prompt_tokens + r.completion_tokens for r in rs) / n, 1
            ),
            "malformed_per_command": round(sum(r.malformed for r in rs) / n, 3),
            "seconds_per_command": round(sum(r.seconds for r in rs) / n, 4),
        }

    methods = [m for m in METHODS if any(r.method == m for r in records)]
    out: dict[str, Any] = {}
    for m in methods:
        rs = [r for r in records if r.method == m]
        groups = [g for g in GROUPS if any(r.group == g for r in rs)]
        out[m] = {
            "overall": stats(rs),
            "groups": {g: stats([r for r in rs if r.group == g]) for g in groups},
        }
    return out


def markdown_table(summary: dict[str, Any]) -> str:
    """One row per method: success % per group and overall, calls, tokens, seconds."""
    groups = sorted({g for s in summary.values() for g in s["groups"]}, key=GROUPS.index)
    head = "| Method | " + " | ".join(groups) + " | Overall % | calls/cmd | tokens/cmd | s/cmd |"
    lines = [head, "|---|" + "---:|" * (len(groups) + 4)]
    for method, s in summary.items():
        cells = [
            f"{100 * s['groups'][g]['success_rate']:.0f}" if g in s["groups"] else "–"
            for g in groups
        ]
        o = s["overall"]
        lines.append(
            f"| {method} | " + " | ".join(cells) + f" | {100 * o['success_rate']:.1f} | "
            f"{o['llm_calls_per_command']:.2f} | {o['tokens_per_command']:.0f} | "
            f"{o['seconds_per_command']:.3f} |"
        )
    return "\n".join(lines)


def records_json(records: Sequence[MethodRecord]) -> list[dict[str, Any]]:
    return [{**asdict(r), "seconds": round(r.seconds, 4), "success": r.success} for r in records]
