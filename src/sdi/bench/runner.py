"""Run the evaluation suite through the rule-based pipeline and score it.

A command succeeds when `sdi.pipeline.plan` returns status ``success`` (the layout passed every
constraint) *and* the command's acceptance predicate holds for that layout.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from typing import Any

from sdi.bench.suite import GROUPS, SUITE, BenchCommand
from sdi.model.cell import CellConfig
from sdi.pipeline import PlanResult, plan


@dataclass(frozen=True)
class CommandRecord:
    """The outcome of one suite command. `seconds` is the planning time, s."""

    id: str
    group: str
    text: str
    status: str
    accepted: bool
    reason: str | None
    seconds: float
    parts: int
    spec: str | None = None
    error: str | None = None

    @property
    def success(self) -> bool:
        return self.status == "success" and self.accepted


@dataclass(frozen=True)
class GroupStats:
    """Success rate (0–1) and mean planning time (s per command) of a group of records."""

    name: str
    count: int
    successes: int
    mean_seconds: float

    @property
    def rate(self) -> float:
        return self.successes / self.count if self.count else 0.0


def _stats(name: str, records: Sequence[CommandRecord]) -> GroupStats:
    n = len(records)
    return GroupStats(
        name=name,
        count=n,
        successes=sum(r.success for r in records),
        mean_seconds=sum(r.seconds for r in records) / n if n else 0.0,
    )


@dataclass(frozen=True)
class SuiteResult:
    """Per-command records with per-group and overall statistics."""

    records: tuple[CommandRecord, ...]

    @property
    def groups(self) -> dict[str, GroupStats]:
        names = [g for g in GROUPS if any(r.group == g for r in self.records)]
        names += sorted({r.group for r in self.records} - set(names))
        return {g: _stats(g, [r for r in self.records if r.group == g]) for g in names}

    @property
    def overall(self) -> GroupStats:
        return _stats("Overall", self.records)

    @property
    def failures(self) -> tuple[CommandRecord, ...]:
        return tuple(r for r in self.records if not r.success)

    def to_json_dict(self) -> dict[str, Any]:
        def stats(s: GroupStats) -> dict[str, Any]:
            return {
                "count": s.count,
                "successes": s.successes,
                "success_rate": round(s.rate, 4),
                "mean_seconds": round(s.mean_seconds, 6),
            }

        return {
            "overall": stats(self.overall),
            "groups": {g: stats(s) for g, s in self.groups.items()},
            "commands": [
                {**asdict(r), "seconds": round(r.seconds, 6), "success": r.success}
                for r in self.records
            ],
        }

    def markdown_table(self) -> str:
        """Rows for each group and Overall: commands, success %, mean seconds per command."""
        lines = [
            "| Group | Commands | Success % | Mean s/command |",
            "|---|---:|---:|---:|",
        ]
        for s in [*self.groups.values(), self.overall]:
            lines.append(f"| {s.name} | {s.count} | {100 * s.rate:.1f} | {s.mean_seconds:.4f} |")
        return "\n".join(lines)


def run_command(command: BenchCommand, cell: CellConfig | None = None) -> CommandRecord:
    """Plan one command and judge its layout."""
    return judge(command, plan(command.text, cell))


def judge(command: BenchCommand, result: PlanResult) -> CommandRecord:
    """The record of a command planned as `result`: its status and the predicate's verdict."""
    reason: str | None
    if result.status != "success" or result.layout is None:
        reason = f"plan {result.status}: {result.error or 'no layout'}"
        accepted = False
    else:
        try:
            reason = command.accept(result.layout)
        except Exception as exc:  # a predicate crash is a failed check, not a crashed run
            reason = f"predicate raised {type(exc).__name__}: {exc}"
        accepted = reason is None
    return CommandRecord(
        id=command.id,
        group=command.group,
        text=command.text,
        status=result.status,
        accepted=accepted,
        reason=reason,
        seconds=result.seconds,
        parts=len(result.layout) if result.layout is not None else 0,
        spec=result.spec.describe() if result.spec is not None else None,
        error=result.error,
    )


def run_suite(
    cell: CellConfig | None = None,
    commands: Sequence[BenchCommand] = SUITE,
    progress: Callable[[CommandRecord], None] | None = None,
) -> SuiteResult:
    """Run every command through `sdi.pipeline.plan`; `progress` is called after each one."""
    cell = cell or CellConfig()
    records = []
    for command in commands:
        record = run_command(command, cell)
        records.append(record)
        if progress is not None:
            progress(record)
    return SuiteResult(records=tuple(records))
