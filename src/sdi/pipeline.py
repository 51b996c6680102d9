"""End to end with no model: command → spec → layout → verified + sequenced plan.

`plan` never raises for a user's mistake: every outcome is a `PlanResult` whose `status` is
``success`` only when the layout passed every constraint **and** the reading used every
material word of the command; ``partial`` when the layout passed but part of the command was
not used (`notes` and `ignored` say what); ``failure`` when the command was understood but no
feasible layout came out; and ``error`` when the command itself is unusable (`understood`
says what was recognised).
"""

from __future__ import annotations

import time
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict

from sdi.design.composer import compose
from sdi.errors import InfeasibleError, InputError, SpecError
from sdi.inspector.verifier import cap_violations, verify
from sdi.inspector.violation import Violation
from sdi.language import Reading, read
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.spec.structure_spec import Spec

Status = Literal["success", "partial", "failure", "error"]
SpecSource = Literal["model", "grammar"]


class PlanResult(BaseModel):
    """The outcome of planning one command (the `sdi plan --json` contract)."""

    model_config = ConfigDict(frozen=True)

    status: Status
    command: str
    spec: Spec | None = None
    layout: Layout | None = None
    sequence: tuple[str, ...] | None = None
    violations: tuple[Violation, ...] = ()
    error: str | None = None
    understood: dict[str, Any] | None = None
    seconds: float = 0.0
    llm_calls: int = 0
    notes: tuple[str, ...] = ()
    ignored: tuple[str, ...] = ()
    reading: Reading | None = None
    llm_malformed: int = 0
    llm_failures: int = 0
    spec_source: SpecSource | None = None
    """Who wrote the spec: the model, or the grammar (no model, or its reply was not used)."""

    def to_json_dict(self) -> dict[str, Any]:
        listed, omitted = cap_violations(self.violations)  # at most 50 per constraint
        out: dict[str, Any] = {
            "status": self.status,
            "command": self.command,
            "notes": list(self.notes),
            "ignored": list(self.ignored),
            "reading": self.reading.to_json_dict() if self.reading is not None else None,
            "spec": self.spec.model_dump(mode="json", exclude_none=True) if self.spec else None,
            "layout": self.layout.to_json_dict() if self.layout is not None else None,
            "sequence": list(self.sequence) if self.sequence is not None else None,
            "violations": [v.to_json_dict() for v in listed],
            "metrics": {
                "seconds": round(self.seconds, 6),
                "llm_calls": self.llm_calls,
                "llm_malformed": self.llm_malformed,
                "llm_failures": self.llm_failures,
            },
        }
        if self.spec_source is not None:
            out["spec_source"] = self.spec_source
        if omitted:
            out["omitted"] = omitted
        if self.error:
            out["error"] = self.error
        if self.status == "error":
            out["understood"] = self.understood or {}
        return out


def plan(command: str, cell: CellConfig | None = None) -> PlanResult:
    """Plan `command` with the rule-based Specifier and the parametric Designer."""
    cell = cell or CellConfig()
    start = time.perf_counter()

    def done(**kw: Any) -> PlanResult:
        return PlanResult(command=command, seconds=time.perf_counter() - start, **kw)

    try:
        reading = read(command, cell)
    except SpecError as exc:
        return done(status="error", error=str(exc), understood=exc.understood or {})
    except InputError as exc:
        return done(status="error", error=str(exc), understood={})
    spec = reading.spec
    said = {"notes": reading.notes, "ignored": reading.ignored, "reading": reading}
    try:
        layout = compose(spec, cell)
    except (InfeasibleError, InputError) as exc:
        return done(status="failure", spec=spec, spec_source="grammar", error=str(exc), **said)
    report = verify(layout, cell, precedence=spec.precedence)
    status: Status = "failure"
    if report.passed:
        status = "success" if reading.complete else "partial"
    return done(
        status=status,
        **said,
        spec=spec,
        spec_source="grammar",
        layout=layout,
        sequence=report.sequence,
        violations=report.violations,
        error=_error(report.passed, len(report.violations), reading),
    )


def _error(passed: bool, violations: int, reading: Reading | None) -> str | None:
    if not passed:
        return f"{violations} constraint violation(s)"
    if reading is not None and not reading.complete:
        return "the layout verifies, but part of the command was not used: " + ", ".join(
            f"'{m}'" for m in reading.material
        )
    return None


def plan_with(command: str, method: str, model: Any, cell: CellConfig | None = None) -> PlanResult:
    """Plan `command` with a method's Specifier and Designer and a chat model (design only).

    The same JSON contract as `plan`; `llm_calls` counts the model's calls. The Inspector has
    the last word: status is ``success`` only if the final layout passed every check.
    """
    from sdi.agents.specifier import Specifier
    from sdi.orchestrator.graph import RunContext, _designer
    from sdi.orchestrator.methods import METHODS

    if method not in METHODS:
        raise InputError(
            f"unknown method {method!r}; choose from {sorted(METHODS)}", field="--method"
        )
    cell = cell or CellConfig()
    m = METHODS[method]
    start = time.perf_counter()
    usage = model.usage if model is not None else None
    before = (usage.calls, usage.malformed, usage.failures) if usage is not None else (0, 0, 0)
    notes: list[str] = []
    spec_source: SpecSource | None = None

    def done(**kw: Any) -> PlanResult:
        now = (usage.calls, usage.malformed, usage.failures) if usage is not None else (0, 0, 0)
        return PlanResult(
            command=command,
            seconds=time.perf_counter() - start,
            llm_calls=now[0] - before[0],
            llm_malformed=now[1] - before[1],
            llm_failures=now[2] - before[2],
            spec_source=spec_source,
            notes=tuple(notes),
            **kw,
        )

    spec: Spec | None = None
    reading: Reading | None = None
    if model is None or m.specifier:
        try:
            specified = Specifier(model if m.specifier else None, cell).specify(command)
        except SpecError as exc:
            return done(status="error", error=str(exc), understood=exc.understood or None)
        spec, notes = specified.spec, list(specified.notes)
        spec_source = "model" if specified.source == "llm" else "grammar"
        reading = specified.reading if spec_source == "grammar" else None
        if reading is not None:
            notes = [*reading.notes, *notes]
    ctx = RunContext(cell, m, model, None)  # type: ignore[arg-type]
    outcome = _designer(ctx).design(spec, command)
    if outcome.layout is None:
        return done(status="failure", spec=spec, error="; ".join(outcome.notes) or "no layout")
    report = outcome.report or verify(outcome.layout, cell)
    status: Status = "failure"
    if report.passed:
        status = "partial" if reading is not None and not reading.complete else "success"
    return done(
        status=status,
        spec=spec,
        layout=outcome.layout,
        sequence=report.sequence,
        violations=report.violations,
        error=_error(report.passed, len(report.violations), reading),
        ignored=reading.ignored if reading is not None else (),
        reading=reading,
    )
