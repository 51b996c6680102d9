"""Run one case of a suite under one method, backend and seed, and score it.

Every suite's case runs what the system does, unchanged, and judges the outcome from outside:

- ``commands``: plan the command (no method: the pipeline, `sdi.pipeline.plan`; a method: the
  orchestrator up to the verified design) and judge it by its acceptance predicate.
- ``human-mods``: plan the command with the orchestrator, enter the operator's edits at the
  first design review, and follow the run to its next review. *entered* = the edit was
  accepted; *detected* = the Inspector's first verdict after it is a failure (or the review
  lists violations); *corrected* = the run came back to a review with a layout that passes
  `verify` (checked again here); *edit kept* = every part the operator touched is where they
  put it (removed parts stay removed; an order edit survives in the sequence); *as close* =
  kept, or, where the edit cannot be kept, no feasible pose is nearer the operator's target than
  the repaired one by more than a grid step (`_as_close`); *shape kept* =
  the final layout still has the command's structure signature.
- ``failures``: run the command unattended with the scenario's blocked regions. *hit* = an
  execution failed at least once; *recovered* = the run ended ``success``; *shape kept* = the
  layout built still has the command's signature; *stated* = a changed layout comes with notes;
  *keepable* = some placement of the commanded structure keeps its signature, clears the
  scenario's regions and plans (`sdi.bench.keepable`, computed, not declared).
- ``motion``: plan, commission on one arm (and on both for dual-arm cases), execute in
  PyBullet with monitoring (paper Table VI).

With ``physics``, every successful layout is also assembled in PyBullet in its sequence
(`sdi.execute.physics_check.assemble`, 1 mm jitter from the case's seed) and *stands* = every
part within 5 mm and 3° of its pose.

Methods whose point is the model (no orchestration of their own, LangGraph routing, the LLM
critic) have no honest row on the ``rules`` backend: `needs_model` says so, and their cases are
``n/a`` rather than the rule-based counterparts under their name.
"""

from __future__ import annotations

import math
import tempfile
import time
from contextlib import ExitStack
from pathlib import Path
from typing import Any, Literal

import numpy as np
from pydantic import BaseModel, ConfigDict

from sdi.bench import shape_checks
from sdi.bench.scenarios import Case, CommandCase, FailureCase, HumanMod, MotionCase
from sdi.llm.chat import ChatModel
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout, parse_layout
from sdi.orchestrator.methods import METHODS

Outcome = Literal["done", "n/a", "timeout", "error"]

PAPER_METHODS: tuple[str, ...] = ("MultiAgent-RuleOrch", "PGEOrch", "LGOrch", "Hybrid")
"""The columns of the paper's Tables IV and V: Rule, PGE, LG, Hyb."""

EDIT_TOLERANCE = 1e-3
"""How close (m) a touched part must stay to where the operator put it to count as kept."""


def needs_model(method: str) -> bool:
    """True if `method` is nothing without a model: no orchestration of its own (the LLM
    designs alone), LangGraph routing by the model, or the LLM critic."""
    m = METHODS[method]
    return m.critic == "llm" or m.orchestration in ("none", "langgraph")


class RunConfig(BaseModel):
    """What every case of a sweep shares (part of each result's cache key)."""

    model_config = ConfigDict(frozen=True)

    backend: str = "rules"
    physics: bool = False
    phase_seconds: float | None = None
    cell: CellConfig = CellConfig()

    def effective_cell(self) -> CellConfig:
        if self.phase_seconds is None:
            return self.cell
        limits = self.cell.limits.model_copy(update={"phase_seconds": self.phase_seconds})
        return self.cell.model_copy(update={"limits": limits})


class CaseResult(BaseModel):
    """One case under one method and seed. `fields` are the suite's own scores."""

    suite: str
    case: str
    method: str | None
    backend: str
    seed: int
    outcome: Outcome
    seconds: float = 0.0
    llm_calls: int = 0
    fields: dict[str, Any] = {}
    physics: dict[str, Any] | None = None
    error: str | None = None
    key: str = ""


class CaseTimeout(BaseException):
    """The case ran past its wall-clock limit (raised by the sweep's alarm; a BaseException so
    that no `except Exception` in the code under test takes it for an ordinary failure)."""


_MODELS: dict[str, ChatModel | None] = {}
_STACK = ExitStack()


def _model(backend: str) -> ChatModel | None:
    """The process's model for `backend`, opened once (a local server lives as long as the
    process)."""
    if backend not in _MODELS:
        from sdi.llm import open_backend

        _MODELS[backend] = open_backend(backend, _STACK)
    return _MODELS[backend]


def run_case(
    suite: str, case: Case, method: str | None, seed: int, config: RunConfig
) -> CaseResult:
    """Run and score one case (exceptions other than a timeout become ``error`` results)."""
    base = {
        "suite": suite,
        "case": case.id,
        "method": method,
        "backend": config.backend,
        "seed": seed,
    }
    if method is not None and config.backend == "rules" and needs_model(method):
        return CaseResult(**base, outcome="n/a")
    model = _model(config.backend) if method is not None else None
    calls0 = model.usage.calls if model is not None else 0
    start = time.perf_counter()
    try:
        fields, built = _RUNNERS[suite](case, method, model, config)
    except CaseTimeout:
        return CaseResult(**base, outcome="timeout", seconds=time.perf_counter() - start)
    except Exception as exc:  # a crash is a scored error, not a crashed sweep
        return CaseResult(
            **base,
            outcome="error",
            seconds=time.perf_counter() - start,
            error=f"{type(exc).__name__}: {exc}",
        )
    seconds = time.perf_counter() - start
    calls = (model.usage.calls if model is not None else 0) - calls0
    physics = None
    if config.physics and built is not None:
        physics = stands(*built, seed=seed)
    return CaseResult(
        **base, outcome="done", seconds=seconds, llm_calls=calls, fields=fields, physics=physics
    )


def stands(layout: Layout, sequence: list[str] | None, *, seed: int) -> dict[str, Any]:
    """Assemble `layout` in PyBullet in `sequence`: does every part stay put?"""
    from sdi.execute.physics_check import assemble

    s = assemble(layout, sequence, seed=seed)
    return {
        "stands": s.stands,
        "worst_part": s.worst_part,
        "worst_offset_mm": round(1000 * s.worst_offset_m, 2),
        "worst_tilt_deg": round(s.worst_tilt_deg, 2),
        "fell_at_step": s.fell_at_step,
    }


Built = tuple[Layout, list[str] | None] | None
"""The successful layout and its sequence (for the physics column), or None."""


def _layout(data: Any, cell: CellConfig) -> Layout | None:
    if not data:
        return None
    layout, _ = parse_layout(data, max_parts=cell.limits.max_parts)
    return layout


def _commands(
    case: Case, method: str | None, model: ChatModel | None, config: RunConfig
) -> tuple[dict[str, Any], Built]:
    from dataclasses import asdict

    from sdi.bench.suite import by_id

    assert isinstance(case, CommandCase)
    command, cell = by_id(case.id), config.effective_cell()
    if method is None:
        from sdi.bench.runner import judge
        from sdi.pipeline import plan

        result = plan(command.text, cell)
        record = judge(command, result)
        built = (result.layout, list(result.sequence or [])) if record.success else None
        assert built is None or built[0] is not None
        return {**asdict(record), "success": record.success}, built  # type: ignore[return-value]
    from sdi.bench.methods import run_one
    from sdi.orchestrator.runner import Orchestrator

    with tempfile.TemporaryDirectory() as tmp:
        orch = Orchestrator(db=Path(tmp) / "bench.sqlite", cell=cell, model=model)
        try:
            mrecord, status = run_one(orch, method, command, model, cell)
        finally:
            orch.close()
    layout = _layout(status.state.get("layout"), cell) if mrecord.success else None
    fields = {**asdict(mrecord), "text": command.text, "success": mrecord.success}
    return fields, ((layout, status.state.get("sequence")) if layout is not None else None)


def _kept(before: Layout, after: Layout, seq0: list[str], seq1: list[str], edits: Any) -> bool:
    """Is every part the operator touched where they put it, and every order edit in force?"""
    from sdi.errors import InputError
    from sdi.orchestrator.edits import apply_edits

    geometric = [e for e in edits if e.get("op") != "sequence"]
    ordering = [e for e in edits if e.get("op") == "sequence"]
    now = {p.id: p for p in after.objects}
    if geometric:
        try:
            wanted = {p.id: p for p in apply_edits(before, list(geometric)).objects}
        except InputError:
            return False
        for e in geometric:
            pid = str(e.get("id"))
            if e.get("op") == "remove":
                if pid in now:
                    return False
                continue
            if pid not in now:
                return False
            a, b = now[pid], wanted[pid]
            if math.dist(a.position, b.position) > EDIT_TOLERANCE:
                return False
            if (
                e.get("op") == "rotate"
                and max(abs(x - y) for x, y in zip(a.orientation, b.orientation, strict=True))
                > 1e-3
                and max(abs(x + y) for x, y in zip(a.orientation, b.orientation, strict=True))
                > 1e-3
            ):
                return False
    for e in ordering:
        if e.get("reverse"):
            if seq1 == seq0:
                return False
        elif "move" in e and "before" in e:
            first, then = str(e["move"]), str(e["before"])
            if first not in seq1 or then not in seq1 or seq1.index(first) > seq1.index(then):
                return False
    return True


CLOSE_STEP = 0.005
"""The grid (m) on which `_as_close` looks for a feasible pose nearer the operator's target."""

CLOSE_MAX_VERIFIED = 400
"""How many nearer candidates `_as_close` verifies before it gives up (and says no)."""


def _as_close(before: Layout, after: Layout, seq1: list[str], edits: Any, cell: CellConfig) -> bool:
    """Is every part the operator touched as close to where they put it as any feasible pose?

    The second, weaker measure beside `_kept`, for edits whose target cannot be kept (a part
    put outside the workspace). Parts one batch moved by the same displacement move as one
    group (the operator moved a row). A group is as close as possible if no rigid move of it
    from the operator's target, shorter than the repair's (its farthest part) by more than
    `CLOSE_STEP`, gives a layout — the rest as repaired — that the Inspector passes; candidate
    moves lie on a `CLOSE_STEP` grid sideways and rest the group on the table or on a part's
    top. Removed parts stay removed; of the move-before pairs an order edit asked for, every
    one the supports allow is kept (a later part that holds the earlier one up cannot)."""
    from sdi.errors import InputError
    from sdi.inspector.analysis import Analysis
    from sdi.inspector.verifier import verify
    from sdi.model.part import Part
    from sdi.orchestrator.edits import apply_edits

    geometric = [e for e in edits if e.get("op") != "sequence"]
    now = {p.id: p for p in after.objects}
    if geometric:
        try:
            wanted = {p.id: p for p in apply_edits(before, list(geometric)).objects}
        except InputError:
            return False
        old = {p.id: p for p in before.objects}
        groups: dict[tuple[Any, ...], list[str]] = {}
        for e in geometric:
            pid = str(e.get("id"))
            if e.get("op") == "remove":
                if pid in now:
                    return False
                continue
            if pid not in now:
                return False
            key = (tuple(np.round(np.subtract(wanted[pid].position, old[pid].position), 6))
                   if pid in old else ("inserted", pid))  # fmt: skip
            group = groups.setdefault(key, [])
            if pid not in group:
                group.append(pid)
        for ids in groups.values():
            if not _group_as_close(after, wanted, ids, cell, verify, Part):
                return False
    for e in edits:
        if e.get("op") != "sequence" or "move" not in e:
            continue
        moving = [e["move"]] if isinstance(e["move"], str) else list(e["move"])
        then = e["before"] if isinstance(e["before"], str) else e["before"][0]
        at = {pid: k for k, pid in enumerate(seq1)}
        held = _holds_up(Analysis(after, cell))
        for m in moving:
            if m in at and then in at and at[m] > at[then] and then not in held.get(m, set()):
                return False
    return True


def _holds_up(a: Any) -> dict[str, set[str]]:
    """Part id → every part under it, transitively (what must be placed before it)."""
    ids = a.layout.ids
    below: dict[str, set[str]] = {}
    for lo, up in a.graph.support_edges.tolist():
        below.setdefault(ids[up], set()).add(ids[lo])
    out: dict[str, set[str]] = {}

    def visit(pid: str) -> set[str]:
        if pid not in out:
            out[pid] = set()
            for q in below.get(pid, ()):
                out[pid] |= {q, *visit(q)}
        return out[pid]

    for pid in ids:
        visit(pid)
    return out


def _group_as_close(
    after: Layout, wanted: dict[str, Any], ids: list[str], cell: CellConfig, verify: Any,
    part: Any,
) -> bool:  # fmt: skip
    """`_as_close` for one group of touched parts (see there)."""
    reached = max(math.dist(after.part(pid).position, wanted[pid].position) for pid in ids)
    if reached <= EDIT_TOLERANCE:
        return True
    limit = reached - CLOSE_STEP
    if limit <= 0:
        return True
    rest = [p for p in after.objects if p.id not in ids]
    T = np.array([wanted[pid].position for pid in ids])
    half = np.array([np.asarray(wanted[pid].size) / 2 for pid in ids])  # upright parts
    bottom0 = float((T[:, 2] - half[:, 2]).min())
    ws = cell.workspace
    lo_ws, hi_ws = np.array(ws.lower), np.array(ws.upper)
    k = int(limit / CLOSE_STEP) + 1
    steps = np.arange(-k, k + 1) * CLOSE_STEP
    candidates: list[tuple[float, float, float, float]] = []
    rc = np.array([p.position for p in rest]) if rest else np.zeros((0, 3))
    rh = np.array([np.asarray(p.size) / 2 for p in rest]) if rest else np.zeros((0, 3))
    for dx in steps:
        for dy in steps:
            if math.hypot(dx, dy) >= limit:
                continue
            c = T + np.array([dx, dy, 0.0])
            if np.any(c[:, :2] - half[:, :2] < lo_ws[:2] - 1e-9) or np.any(
                c[:, :2] + half[:, :2] > hi_ws[:2] + 1e-9
            ):
                continue
            bottoms = {0.0}
            for j in range(len(rest)):
                if np.any(np.all(np.abs(c[:, :2] - rc[j, :2]) < half[:, :2] + rh[j, :2] - 1e-6,
                                 axis=1)):  # fmt: skip
                    bottoms.add(float(rc[j, 2] + rh[j, 2]))
            for b in bottoms:
                dz = b - bottom0
                d = math.sqrt(dx * dx + dy * dy + dz * dz)
                if d < limit:
                    candidates.append((d, float(dx), float(dy), dz))
    candidates.sort()
    for n, (_, dx, dy, dz) in enumerate(candidates):
        if n >= CLOSE_MAX_VERIFIED:
            return False  # not shown to be the nearest
        moved = [
            part(id=pid, position=tuple(float(v) for v in T[i] + (dx, dy, dz)),
                 orientation=wanted[pid].orientation, size=wanted[pid].size)
            for i, pid in enumerate(ids)
        ]  # fmt: skip
        if verify(Layout(objects=(*rest, *moved)), cell).passed:
            return False  # a feasible pose nearer the operator's target
    return True


OPERATOR_CHOICES = ("repair", "keep", "minimal_repair")
"""If a review offers choices after an edit, the benchmark's operator takes the first of these
on offer (the repair that keeps the edit), else the first offered."""


def _choose(waiting: dict[str, Any]) -> dict[str, Any] | None:
    options = waiting.get("choices") or waiting.get("options")
    if not isinstance(options, list) or not options:
        return None
    names = [o.get("action") if isinstance(o, dict) else o for o in options]
    for want in OPERATOR_CHOICES:
        if want in names:
            chosen = options[names.index(want)]
            return chosen if isinstance(chosen, dict) else {"action": chosen}
    first = options[0]
    return first if isinstance(first, dict) else {"action": first}


def _human_mods(
    case: Case, method: str | None, model: ChatModel | None, config: RunConfig
) -> tuple[dict[str, Any], Built]:
    from sdi.inspector.verifier import verify
    from sdi.orchestrator.runner import Orchestrator

    assert isinstance(case, HumanMod) and method is not None
    cell = config.effective_cell()
    signature = shape_checks.signature(case.shape)
    edits = [dict(e) for e in case.edits]
    fields: dict[str, Any] = {"type": case.type, "paper_steps": case.paper_steps}
    with tempfile.TemporaryDirectory() as tmp:
        orch = Orchestrator(db=Path(tmp) / "bench.sqlite", cell=cell, model=model)
        try:
            s = orch.start(case.command, method=method)
            waiting = s.waiting_for or {}
            if s.status != "paused" or waiting.get("kind") != "design_review":
                return {**fields, "planned": False, "status": s.status}, None
            before = _layout(waiting.get("layout"), cell)
            assert before is not None
            seq0 = list(waiting.get("sequence") or [])
            fields |= {"planned": True, "steps": len(before)}
            seen = len(orch.bus.history(s.run_id))
            notes0 = len(s.state.get("notes") or [])
            s = orch.resume(s.run_id, {"action": "edit", "edits": edits})
            events = orch.bus.history(s.run_id, after=seen)
            refused = [e.payload.get("error") for e in events if e.type == "edit_refused"]
            verdicts = [e.payload.get("passed") for e in events if e.type == "verification"]
            shown = (s.waiting_for or {}).get("violations")
            detected = not refused and ((bool(verdicts) and not verdicts[0]) or bool(shown))
            for _ in range(3):  # answer the choices a review offers after the edit, if any
                waiting = s.waiting_for or {}
                choice = _choose(waiting) if s.status == "paused" else None
                if waiting.get("kind") != "edit_review" or choice is None:
                    break
                s = orch.resume(s.run_id, choice)
            waiting = s.waiting_for or {}
            final = _layout(waiting.get("layout") or s.state.get("layout"), cell)
            seq1 = list(waiting.get("sequence") or s.state.get("sequence") or [])
            at_review = s.status == "paused" and waiting.get("kind") == "design_review"
            passes = final is not None and verify(final, cell).passed
            corrected = bool(detected and at_review and passes)
            kept = bool(corrected and final is not None and _kept(before, final, seq0, seq1, edits))
            close = kept or bool(
                corrected and final is not None and _as_close(before, final, seq1, edits, cell)
            )
            notes = list(s.state.get("notes") or [])[notes0:]
            fields |= {
                "entered": not refused,
                "refused": refused[0] if refused else None,
                "detected": detected,
                "corrected": corrected,
                "edit_kept": kept,
                "edit_as_close": close,
                "shape_kept": bool(passes and final is not None and signature(final) is None),
                "reverted": bool(final is not None and final == before and seq1 == seq0),
                "status": s.status,
                "waiting_for": waiting.get("kind"),
                "notes": notes,
                "final_parts": len(final) if final is not None else 0,
            }
            built = (final, seq1 or None) if corrected and final is not None else None
            return fields, built
        finally:
            orch.close()


def _failures(
    case: Case, method: str | None, model: ChatModel | None, config: RunConfig
) -> tuple[dict[str, Any], Built]:
    from sdi.bench.keepable import case_keepable
    from sdi.execute.record import layout_hash
    from sdi.orchestrator.runner import Orchestrator

    assert isinstance(case, FailureCase) and method is not None
    cell = config.effective_cell()
    signature = shape_checks.signature(case.shape)
    with tempfile.TemporaryDirectory() as tmp:
        orch = Orchestrator(db=Path(tmp) / "bench.sqlite", cell=cell, model=model)
        try:
            s = orch.start(case.command, method=method, faults=[case.scenario], approve=True)
            asked = 0  # a recovery that changed the shape waits for the operator: approve it
            while s.status == "paused" and (s.waiting_for or {}).get("kind") == "recovery_review":
                asked += 1
                s = orch.resume(s.run_id, {"action": "approve", "by": "bench"}, approve_all=True)
            events = orch.bus.history(s.run_id)
        finally:
            orch.close()
    executions = [e.payload for e in events if e.type == "execution"]
    first_design = next(
        (
            e.payload.get("layout_hash")
            for e in events
            if e.type == "verification" and e.payload.get("passed")
        ),
        None,
    )
    hit = any(x.get("status") != "success" for x in executions) or any(
        e.type == "failure" for e in events
    )
    recovered = s.status == "success"
    final = _layout(s.state.get("layout"), cell)
    changed = bool(final is not None and first_design and layout_hash(final) != first_design)
    notes = list(s.state.get("notes") or [])
    can = case_keepable(case.command, case.shape, case.scenario, cell)
    fields = {
        "scenario": case.scenario,
        "keepable": can.possible,
        "keepable_reason": can.reason,
        "hit": hit,
        "recovered": recovered,
        "shape_kept": bool(recovered and final is not None and signature(final) is None),
        "changed": changed,
        "stated": bool(not changed or notes),
        "asked_operator": asked,
        "tried": list(s.state.get("tried") or []),
        "notes": notes,
        "status": s.status,
        "executions": len(executions),
        "parts": len(final) if final is not None else 0,
    }
    built = (final, s.state.get("sequence")) if recovered and final is not None else None
    return fields, built


def _motion(
    case: Case, method: str | None, model: ChatModel | None, config: RunConfig
) -> tuple[dict[str, Any], Built]:
    import statistics

    from sdi.commission import commission, execute
    from sdi.errors import SDIError
    from sdi.pipeline import plan

    assert isinstance(case, MotionCase)
    cell = config.effective_cell()
    result = plan(case.command, cell)
    base = {"category": case.category, "command": case.command, "extra": case.extra}
    if result.status != "success" or result.layout is None:
        return {**base, "error": result.error, "passed": False}, None
    layout = result.layout
    one, arm = None, None
    started = time.perf_counter()
    for name in ("irb120", "irb1600"):  # the IRB120 where it reaches everything
        try:
            one, arm = commission(layout, cell, arms=[name]), name
            break
        except SDIError:
            continue
    row: dict[str, Any] = {
        **base,
        "parts": len(layout),
        "single_arm": arm,
        "makespan_one_arm_s": round(one.makespan, 2) if one else None,
        "planning_s_one_arm": round(time.perf_counter() - started, 2),
    }
    chosen = one
    if case.mode == "dual":
        started = time.perf_counter()
        two = commission(layout, cell)
        row["planning_s_two_arms"] = round(time.perf_counter() - started, 2)
        row["makespan_two_arms_s"] = round(two.makespan, 2)
        row["speedup"] = round(one.makespan / two.makespan, 2) if one else None
        chosen = two
    if chosen is None:
        return {**row, "error": "no single arm can build it", "passed": False}, None
    row["planning_s_per_step"] = round(
        statistics.mean(float(m.planning_seconds) for m in chosen.motion.steps), 3
    )
    _, report = execute(chosen)
    row |= {
        "executed": report["status"],
        "v_traj": report["v_traj"],
        "delta_rad": report["delta_rad"],
        "max_placement_error_mm": round(1000 * float(str(report["max_placement_error_m"])), 2),
    }
    row["passed"] = row["executed"] == "success" and row["v_traj"] == "pass"
    return row, ((layout, list(result.sequence or [])) if row["passed"] else None)


_RUNNERS = {
    "commands": _commands,
    "human-mods": _human_mods,
    "failures": _failures,
    "motion": _motion,
}
