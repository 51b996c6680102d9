"""The orchestrator: a LangGraph state machine over PLAN, DESIGN, INSPECT, HUMAN_REVIEW,
PRE_EXECUTE, EXECUTE and REPLAN (paper §III-B, Alg. 1).

The graph comes from `build_graph()` and is drawn by LangGraph itself (`sdi graph`). Every node is a
module-level function `node(state, runtime)` over the run's typed state and an explicit
`RunContext` (the cell, the method, the model, the event stream, the record store). Edges:

- fixed (`add_edge`) where the flow is fixed: START → PLAN, DESIGN → INSPECT (whatever the
  Designer makes goes to the Inspector);
- conditional, each with its `path_map`, only at branch points: the Inspector's verdict, the
  review outcomes, REPLAN's choice, the failure report. A node that asks for a route its map
  does not have raises `RoutingError` — a run never ends quietly on a typo.

The gate is a type: a layout is verified once, by `VerifiedJob.inspect` (in the Designer's own
gate or in INSPECT), and the `VerifiedJob` is what PRE_EXECUTE plans and EXECUTE runs — held in
`RunContext.jobs` by cell and layout hash, since the checkpointed state is plain JSON; a miss
(another process, the critic ablation) inspects again. Every path to EXECUTE passes INSPECT,
the design review, PRE_EXECUTE (which plans motion once and stores the commissioning record)
and CONFIRM (the pre-execution approval, naming the record's hash); EXECUTE runs exactly that
record (`tests/test_graph.py` checks the edges).
Routing is decided only at failure branch points (REPLAN): by the model when the method routes
with LangGraph and a model is set, otherwise by deterministic rules. REPLAN tries the recovery
skills first (shift, flatten) and sends their output straight to the Inspector, then the
Designer's `modify`, then Specifier relaxation (the raw command), then the human; at most
`method.replans` replans. The human touch points are LangGraph `interrupt()`s, each first in its
node (so nothing is sent twice when the node re-runs on resume): design review, pre-execution
confirmation (and its repeat after an interrupted execution), failure report; and two that
only a person answers, never `--approve-all`: an edit the Inspector refused (`edit_review`:
repair, undo, replan — edits never spend the replan budget) and a recovery that changed the
shape (`recovery_review`). Every recovery states what it changed (`recoveries`). Every working
phase runs under a wall-clock limit (`[limits] phase_seconds`); a phase past it goes to the
failure report.
"""

from __future__ import annotations

import os
from collections import OrderedDict
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any, TypedDict

from langgraph.graph import END, START, StateGraph
from langgraph.runtime import Runtime
from langgraph.types import interrupt

from sdi.agents.designer import (
    AgenticDesigner,
    DesignOutcome,
    GeneratorFirstDesigner,
    LoopDesigner,
    RuleDesigner,
)
from sdi.agents.specifier import Specifier
from sdi.deadline import PhaseTimeout, phase_limit
from sdi.errors import (
    InfeasibleError,
    InputError,
    MotionPlanningError,
    SDIError,
    SpecError,
    UnverifiedPlanError,
)
from sdi.execute.faults import FAULTS, SCENARIOS
from sdi.execute.job import VerifiedJob
from sdi.execute.record import CommissioningRecord, RecordError, cell_hash, layout_hash
from sdi.inspector.verifier import verify
from sdi.inspector.violation import Violation
from sdi.jsonable import plain
from sdi.llm.chat import ChatModel
from sdi.llm.openai_backend import LLMError, parse_json
from sdi.model.cell import CellConfig
from sdi.model.diff import layout_diff
from sdi.model.layout import Layout, parse_layout
from sdi.model.region import Region
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.edits import edit
from sdi.orchestrator.methods import SAMS_SKILLS, SASS_SKILLS, Method
from sdi.orchestrator.records import RecordStore
from sdi.recovery.outcome import RecoveryOutcome, recover, rule_replan
from sdi.recovery.repair import repair_edit
from sdi.skills.builtin import default_registry
from sdi.spec.structure_spec import Spec

ACTIONS = ("shift", "flatten", "spread", "modify", "relax", "escalate")
SKILLS = ("shift", "flatten", "spread")
"""The geometric recovery skills (`sdi.recovery`); methods without recovery never use them."""


class RoutingError(SDIError):
    """A node asked for a route its edges do not have (a bug, never an operator's mistake)."""


class Failure(TypedDict, total=False):
    """A failure event: what failed, where, and which injected scenario (if any) caused it."""

    error_type: str  # ik | collision | timeout | grip | deviation | placement | gate | …
    scenario: str | None  # the fault scenario whose region blocked the step
    phase: str  # the phase that failed
    step: int | None
    part_id: str | None
    robot: str | None
    target_pose: list[float] | None  # x, y, z (m), qw, qx, qy, qz
    message: str


class RunState(TypedDict, total=False):
    run_id: str
    command: str
    method: str
    backend: str
    cell: dict[str, Any]  # the cell configuration the run was started with
    cell_hash: str  # its sha256 (`sdi.execute.record.cell_hash`)
    arms: list[str] | None
    faults: list[str]  # injected fault scenarios (names in `SCENARIOS`)
    spec: dict[str, Any] | None
    spec_source: str
    ignored: list[str]  # words of the command the Specifier's reading left unused
    unread: list[str]  # the material ones among them: the run ends `partial`, not `success`
    relaxed: bool
    layout: dict[str, Any] | None
    sequence: list[str] | None
    violations: list[dict[str, Any]]
    replans: int
    tried: list[str]
    failure: Failure | None
    execution: dict[str, Any] | None
    planning: dict[str, Any] | None  # the record's summary (hash, makespan, steps per robot)
    record_hash: str | None  # the planned commissioning record
    approved_hash: str | None  # the record the operator approved
    resume_from: dict[str, Any] | None  # as-built state of an interrupted execution
    review_note: str | None  # why the last edit was refused
    status: str
    phase: str  # the route out of the node that ran last
    notes: list[str]
    approve: bool  # unattended: every review approved (`--approve-all`), but never the
    # confirmation after an interrupted execution nor a failure report
    design_only: bool  # stop once the design is verified (benchmarks): status "verified"
    recoveries: list[dict[str, Any]]  # each recovery's outcome (`RecoveryOutcome`), in order
    pending_approval: dict[str, Any] | None  # a recovery that changed the shape: a person
    # approves the next design review, whatever `--approve-all` says
    avoid: list[dict[str, Any]]  # places learned to avoid (`Region`s), e.g. unreachable targets
    operator_sequence: list[str] | None  # the order the operator gave (an order edit)
    edit: dict[str, Any] | None  # the operator's edit being checked, or refused by the
    # Inspector with its repair (`status` checking | invalid); see `EDIT_CHOICES`
    edit_outcome: dict[str, Any] | None  # what became of the last edit, and the diff from it
    revisions: list[str]  # the operator's reasons for rejecting designs, oldest first: read
    # after the command as clauses that change it (and, with a model, the Designer's feedback)
    rejected: dict[str, Any] | None  # the design last rejected ("layout", "reason"), until the
    # next design review says what the replan changed
    given_layout: dict[str, Any] | None  # a layout the operator gave as a file (`sdi run
    # --layout`): the run's design; no Specifier and no Designer read a command for it


class Jobs:
    """The verified jobs of this process's runs, by cell and layout hash, newest last.

    The run state is plain JSON (it is checkpointed), so it cannot hold a `VerifiedJob`; this is
    where the one INSPECT made (or the Designer's own gate made, for the very layout INSPECT
    receives) waits for PRE_EXECUTE and EXECUTE. A miss (another process resumed the run, or
    the critic ablation skipped the Inspector) means `VerifiedJob.inspect` runs again.
    """

    def __init__(self, size: int = 32) -> None:
        self.size = size
        self._jobs: OrderedDict[tuple[str, str], VerifiedJob] = OrderedDict()

    def put(self, job: VerifiedJob) -> VerifiedJob:
        key = (cell_hash(job.cell), layout_hash(job.layout))
        self._jobs[key] = job
        self._jobs.move_to_end(key)
        while len(self._jobs) > self.size:
            self._jobs.popitem(last=False)
        return job

    def get(
        self, cell: CellConfig, layout: Layout, sequence: Sequence[str] | None = None
    ) -> VerifiedJob | None:
        """The job for exactly this cell and layout (and sequence, when given), if held."""
        job = self._jobs.get((cell_hash(cell), layout_hash(layout)))
        if job is None or (sequence is not None and tuple(sequence) != job.sequence):
            return None
        return job

    def job(
        self, cell: CellConfig, layout: Layout, sequence: Sequence[str] | None = None
    ) -> VerifiedJob:
        """The held job, else `VerifiedJob.inspect` (raises `UnverifiedPlanError`)."""
        return self.get(cell, layout, sequence) or self.put(
            VerifiedJob.inspect(layout, cell, sequence)
        )


@dataclass
class RunContext:
    """What the nodes need that is not state: the cell, the model, the method, the stores."""

    cell: CellConfig
    method: Method
    model: ChatModel | None
    bus: MessageBus
    records: RecordStore | None = None  # where PRE_EXECUTE stores the commissioning record
    arms: list[str] | None = None
    jobs: Jobs = field(default_factory=Jobs)  # the verified jobs INSPECT hands on

    @property
    def store(self) -> RecordStore:
        if self.records is None:
            raise RoutingError("this context has no record store; it cannot plan motion")
        return self.records


Rt = Runtime[RunContext]


def _crash_hook(node: str) -> None:
    """Fault injection for the crash/resume tests: SDI_CRASH_AT=<node> kills the process there."""
    if os.environ.get("SDI_CRASH_AT") == node:
        os._exit(137)


def _hold_hook(node: str) -> None:
    """For the concurrency tests: SDI_HOLD_AT=<node> with SDI_HOLD_FILE=<path> makes the process
    write <path>.ready on entering the node and wait there until <path> exists."""
    if os.environ.get("SDI_HOLD_AT") != node or not os.environ.get("SDI_HOLD_FILE"):
        return
    import time
    from pathlib import Path

    gate = Path(os.environ["SDI_HOLD_FILE"])
    Path(f"{gate}.ready").write_text(str(os.getpid()))
    while not gate.exists():
        time.sleep(0.05)


def say(
    state: RunState, ctx: RunContext, sender: str, receiver: str, type: str, payload: dict[str, Any]
) -> None:
    ctx.bus.send(state["run_id"], sender, receiver, type, payload)


def _layout(state: RunState, cell: CellConfig) -> Layout | None:
    data = state.get("layout")
    if not data:
        return None
    layout, _ = parse_layout(data, max_parts=cell.limits.max_parts)
    return layout


def _designer(ctx: RunContext) -> Any:
    m, model = ctx.method, ctx.model
    if model is None or m.designer == "parametric":
        return RuleDesigner(ctx.cell)
    if m.designer in ("agentic-1", "agentic-8"):
        registry = default_registry(ctx.cell)
        registry = registry.subset(SASS_SKILLS if m.designer == "agentic-1" else SAMS_SKILLS)
        return AgenticDesigner(model, registry, ctx.cell)
    if m.designer == "generator-first":
        return GeneratorFirstDesigner(model, ctx.cell)
    feedback = {
        "direct": "none",
        "full-prompt": "none",
        "fixed-loop": "full",
        "adaptive-loop": "adaptive",
    }[m.designer]
    return LoopDesigner(model, ctx.cell, feedback=feedback, full_prompt=m.designer == "full-prompt")  # type: ignore[arg-type]


def rule_route(state: RunState, method: Method) -> str:
    """Deterministic failure routing: recovery skills, then the Designer, relaxation, a human."""
    tried = state.get("tried", [])
    failure = state.get("failure") or {}
    if failure and method.recovery:
        scenario = SCENARIOS.get(failure.get("scenario") or "")
        height = scenario is not None and any(r.z_min is not None for r in scenario.regions)
        for action in ("flatten", "shift") if height else ("shift", "flatten"):
            # a second shift only after a new failure taught it a place to avoid
            if action not in tried or (action == "shift" and tried.count(action) < 2
                                       and failure.get("error_type") == "ik"
                                       and not failure.get("scenario")):  # fmt: skip
                return action
        # no arm could take a part where it stands, and moving did not help: open gaps
        if failure.get("error_type") == "ik" and not failure.get("scenario") \
                and "spread" not in tried:  # fmt: skip
            return "spread"
    if "modify" not in tried or tried.count("modify") < 2:
        return "modify"
    if method.specifier and not state.get("relaxed"):
        return "relax"
    return "escalate"


def llm_route(state: RunState, ctx: RunContext) -> str:
    """The model picks the recovery at a failure branch point; rules decide if it cannot."""
    fallback = rule_route(state, ctx.method)
    if ctx.model is None:
        return fallback
    allowed = [a for a in ACTIONS if ctx.method.recovery or a not in SKILLS]
    prompt = (
        "A robot assembly plan failed. Choose the next action from "
        f'{allowed} and answer JSON {{"action": ...}}.\n'
        f"Failure: {state.get('failure')}\nViolations: {(state.get('violations') or [])[:5]}\n"
        f"Already tried: {state.get('tried', [])}"
    )
    try:
        reply = ctx.model.chat([{"role": "user", "content": prompt}], json_schema={
            "type": "object", "properties": {"action": {"type": "string", "enum": allowed}},
            "required": ["action"]}, max_tokens=50, role="router")  # fmt: skip
        action = str(parse_json(reply.content).get("action"))
    except (ValueError, AttributeError, LLMError):
        ctx.model.usage.malformed += 1
        return fallback
    return action if action in allowed else fallback


def phase_seconds(name: str, state: RunState, cell: CellConfig) -> float:
    """The wall-clock limit of phase `name`: `[limits] phase_seconds`, and for EXECUTE that plus
    twice the planned makespan — a robot cannot finish faster than its plan, and a long job
    must not be cut off by a limit meant for thinking."""
    limit = cell.limits.phase_seconds
    if name == "execute":
        makespan = float((state.get("planning") or {}).get("makespan_s") or 0.0)
        limit += 2.0 * makespan
    return limit


def failure_of(event: dict[str, Any] | None, phase: str, **extra: Any) -> Failure:
    """A typed failure from a driver's or planner's event dict."""
    e = event or {}
    return Failure(
        error_type=str(extra.get("error_type") or e.get("error_type") or "unknown"),
        scenario=extra.get("scenario"),
        phase=phase,
        step=e.get("step"),
        part_id=e.get("part_id"),
        robot=e.get("robot"),
        target_pose=e.get("target_pose"),
        message=str(extra.get("message") or e.get("message") or ""),
    )


# -- PLAN -------------------------------------------------------------------------------------
def plan_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    _crash_hook("plan")
    command = state["command"]
    if state.get("given_layout") is not None:  # the operator's own layout: nothing to read
        return _given_plan(state)
    raw = ctx.model is not None and (not ctx.method.specifier or state.get("relaxed"))
    if raw:  # raw command to the Designer (no Specifier, or Specifier relaxation)
        told = {"command": designer_command(state), "relaxed": bool(state.get("relaxed"))}
        say(state, ctx, "orchestrator", "designer", "command", told)
        return {"spec": None, "spec_source": "raw command", "phase": "design"}
    specifier = Specifier(ctx.model if ctx.method.specifier else None, ctx.cell)
    revisions = list(state.get("revisions") or [])
    notes: list[str] = []
    try:
        try:
            result = specifier.specify(revised_command(command, revisions))
        except SpecError as exc:
            if not revisions:
                raise
            # the operator's latest reason is not a change the reader can make: say so, and
            # plan without it (the design review then shows what came back)
            notes.append(f"your reason {revisions[-1]!r} could not be read as a change to the "
                         f"command ({exc}); planned without it")  # fmt: skip
            revisions.pop()
            result = specifier.specify(revised_command(command, revisions))
    except SpecError as exc:
        say(state, ctx, "orchestrator", "human", "error", {"error": str(exc)})
        return {"status": "failure", "phase": "end", "notes": [str(exc)], "spec": None}
    spec = result.spec.model_dump(mode="json", exclude_none=True)
    say(state, ctx, "specifier", "designer", "spec", {"spec": spec, "source": result.source})
    reading = result.reading
    update: dict[str, Any] = {
        "spec": result.spec.model_dump(mode="json"),
        "spec_source": result.source,
        "ignored": list(reading.ignored) if reading is not None else [],
        # words of the command the reading could not use: the run ends `partial`, not success
        "unread": list(reading.material) if reading is not None else [],
        "phase": "design",
    }
    said = [*(reading.notes if reading is not None else ()), *result.notes]
    if said:  # the reading's assumptions and what it left out, shown at every review
        notes = [*notes, *(n for n in said if n not in notes)]
    if notes:
        if revisions != list(state.get("revisions") or []):
            say(state, ctx, "orchestrator", "human", "revision_unread", {"note": notes[0]})
            update["revisions"] = revisions
        update["notes"] = list(dict.fromkeys([*state.get("notes", []), *notes]))
    return update


def _given_plan(state: RunState) -> dict[str, Any]:
    """PLAN for a run of a layout given as a file: the layout is the design. A reason the
    operator gave when rejecting it cannot change a file's layout: say so (edits can)."""
    update: dict[str, Any] = {"spec": None, "spec_source": "layout file", "phase": "design"}
    revisions = list(state.get("revisions") or [])
    if revisions:
        note = (
            f"your reason {revisions[-1]!r} was not applied: a layout given as a file is "
            "changed by editing it (sdi resume --edit, or the twin), not by a reason"
        )
        update["notes"] = list(dict.fromkeys([*state.get("notes", []), note]))
        update["revisions"] = revisions[:-1]
    return update


def revised_command(command: str, revisions: Sequence[str]) -> str:
    """The command with the operator's rejection reasons after it, each a clause of its own
    ("a row of 3 cubes" + "make it 4 high" → "a row of 3 cubes. make it 4 high"): the language
    front end reads a clause that changes an earlier structure as that change."""
    text = command.strip()
    for reason in revisions:
        text = f"{text.rstrip(' .')}. {reason.strip()}"
    return text


def designer_command(state: RunState) -> str:
    """What the Designer is told: the command, and each design the operator rejected with
    their reason (feedback for a model; the parametric designer works from the spec)."""
    feedback = [f"\nThe operator rejected a design: {r}" for r in state.get("revisions") or []]
    return state["command"] + "".join(feedback)


# -- DESIGN -----------------------------------------------------------------------------------
def design_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    _crash_hook("design")
    given = state.get("given_layout")
    if given is not None:  # the operator's layout file: INSPECT judges it as an edit of theirs
        say(state, ctx, "human", "inspector", "layout", {"parts": len(given.get("objects", []))})
        sequence = state.get("operator_sequence")
        ids = [str(o.get("id")) for o in given.get("objects", [])]
        check = {"status": "checking", "given": True, "before": given, "operator": given,
                 "touched": ids, "removed": [], "asked": [], "sequence": sequence}  # fmt: skip
        return {"layout": given, "edit": check, "edit_outcome": None, "phase": "inspect"}
    spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
    outcome: DesignOutcome = _designer(ctx).design(spec, designer_command(state))
    parts = len(outcome.layout) if outcome.layout else 0
    message = {"status": outcome.status, "parts": parts, "notes": outcome.notes}
    say(state, ctx, "designer", "inspector", "layout", message)
    # the reading's notes (what was assumed, what was not used) stay; the Designer's follow
    notes = list(dict.fromkeys([*state.get("notes", []), *outcome.notes]))
    if outcome.layout is None:
        return {"layout": None, "violations": [], "notes": notes, "phase": "inspect"}
    if outcome.job is not None:  # the Designer's own gate passed it: INSPECT need not run again
        ctx.jobs.put(outcome.job)
    return {"layout": outcome.layout.to_json_dict(), "phase": "inspect", "notes": notes}


# -- INSPECT (never an LLM, except the critic ablation) -------------------------------------
def inspect_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    _crash_hook("inspect")
    if state.get("phase") == "failure_report":  # DESIGN or MODIFY ran out of time
        return {"phase": "failure_report"}
    layout = _layout(state, ctx.cell)
    if layout is None:
        return {"violations": [{"constraint": "design", "message": "no layout"}], "phase": "replan"}
    checking = (state.get("edit") or {}).get("status") == "checking"
    if ctx.method.critic == "llm" and ctx.model is not None and not checking:  # an operator's
        # edit is always judged by the Inspector: its violations and repair go back to them
        verdict = llm_critic(ctx, layout)
        say(state, ctx, "critic", "orchestrator", "verdict", verdict)
        if verdict.get("passed"):
            return {"violations": [], "sequence": list(layout.ids), "phase": "review"}
        return {
            "violations": [{"constraint": "critic", "message": str(verdict.get("problems"))}],
            "phase": "replan",
        }
    wanted = state.get("operator_sequence")
    if wanted is not None and sorted(wanted) != sorted(layout.ids):
        wanted = None  # a recovery changed the parts: the Inspector orders them
    try:  # the one verification of this layout; PRE_EXECUTE and EXECUTE take the job
        job = ctx.jobs.job(ctx.cell, layout, wanted)
        report = job.report
    except UnverifiedPlanError as exc:
        job = None
        assert exc.report is not None
        report = exc.report
    violations = [v.to_json_dict() for v in report.violations]
    say(state, ctx, "inspector", "orchestrator", "verification",
        {"passed": job is not None, "violations": violations[:20],
         "layout_hash": layout_hash(layout)})  # fmt: skip
    update: dict[str, Any] = {
        "violations": violations,
        "sequence": list(job.sequence) if job is not None else None,
        "phase": "review" if job is not None else "replan",
    }
    pending = state.get("edit")
    if pending and pending.get("status") == "checking":  # the operator's edit: theirs to judge
        update["phase"] = "review"
        if job is not None:
            update["edit"] = None
            update["edit_outcome"] = {"choice": "kept", "changes": []}
        else:
            update["edit"] = _refused_edit(pending, layout, report.violations, ctx.cell)
            shown = {k: v for k, v in update["edit"].items() if k not in ("before", "operator")}
            say(state, ctx, "orchestrator", "human", "edit_check", shown)
    return update


# -- HUMAN_REVIEW -----------------------------------------------------------------------------
EDIT_CHOICES = ("repair", "undo", "replan", "edit", "reject")
"""The answers to an edit the Inspector refused: take the minimal repair, undo the edit,
replan from the edited layout, edit again, or reject the design."""
GIVEN_CHOICES = ("repair", "edit", "reject")
"""The answers when the refused layout is the one the operator gave as a file."""


def _start_edit(
    state: RunState, ctx: RunContext, layout: Layout, edits: Any, base: dict[str, Any] | None
) -> dict[str, Any]:
    """Apply the operator's edits; their layout goes to INSPECT and comes back to them.

    `base` is the edit being answered (its layout before the first edit stays the one an undo
    returns to). A malformed batch is refused with a note, and nothing changes."""
    try:
        edited = edit(layout, edits, ctx.cell, sequence=state.get("sequence"))
    except InputError as exc:
        say(state, ctx, "orchestrator", "human", "edit_refused", {"error": str(exc)})
        return {"notes": [f"edit refused: {exc}"], "review_note": str(exc)}
    before = (base or {}).get("before") or layout.to_json_dict()
    touched = sorted({*((base or {}).get("touched") or []), *edited.touched})
    asked = [*((base or {}).get("asked") or []), *(list(p) for p in edited.asked)]
    operator = edited.layout.to_json_dict()
    return {
        "layout": operator,
        "operator_sequence": list(edited.sequence) if edited.sequence is not None else None,
        "edit": {"status": "checking", "before": before, "operator": operator,
                 "touched": touched, "removed": list(edited.removed), "asked": asked,
                 "sequence": list(edited.sequence) if edited.sequence is not None else None},
        "edit_outcome": None, "review_note": None, "phase": "inspect",
    }  # fmt: skip


def _refused_edit(
    pending: dict[str, Any], layout: Layout, violations: Sequence[Violation], cell: CellConfig
) -> dict[str, Any]:
    """The refused edit as the operator sees it: its violations, and the minimal repair (or
    None), with the diff from their layout; for an order edit, the nearest valid order."""
    wanted = pending.get("sequence")
    before, _ = parse_layout(pending["before"], max_parts=cell.limits.max_parts)
    touched = pending.get("touched") or ()
    asked = [(str(a), str(b)) for a, b in pending.get("asked") or ()]
    fix = repair_edit(layout, cell, touched=touched, sequence=wanted, original=before, asked=asked)
    repair: dict[str, Any] | None = None
    if fix is not None:
        repair = {"layout": fix.layout.to_json_dict(), "sequence": list(fix.sequence),
                  "changes": [c.model_dump(mode="json") for c in fix.changes],
                  "kept": list(fix.kept), "summary": fix.describe()}  # fmt: skip
    shown = [v.to_json_dict() for v in violations][:20]
    out = {**pending, "status": "invalid", "violations": shown, "repair": repair}
    if wanted is not None:
        out["nearest_order"] = fix and list(fix.sequence)
    return out


def _outcome_notes(choice: str, changes: list[dict[str, Any]], summary: str | None = None) -> str:
    from sdi.model.diff import PartChange, describe_diff

    text = summary or describe_diff([PartChange.model_validate(c) for c in changes])
    return f"your edit → {choice}: {'your layout kept' if text == 'unchanged' else text}"


def _edit_review(state: RunState, ctx: RunContext, pending: dict[str, Any]) -> dict[str, Any]:
    """An edit the Inspector refused: the operator chooses; nothing is approved unseen."""
    # a layout given as a file has nothing to undo to and no command to replan from
    choices = GIVEN_CHOICES if pending.get("given") else EDIT_CHOICES
    request = {
        "kind": "edit_review",
        "layout": pending.get("operator"),
        "violations": pending.get("violations"),
        "repair": pending.get("repair"),
        "nearest_order": pending.get("nearest_order"),
        "choices": list(choices),
        "refused": state.get("review_note"),
    }
    decision = interrupt(request)
    say(state, ctx, "human", "orchestrator", "review", decision)
    action = decision.get("action") if isinstance(decision, dict) else None
    if action not in choices:
        action = None  # asked again below
    operator, _ = parse_layout(pending["operator"], max_parts=ctx.cell.limits.max_parts)
    if action == "repair":
        repair = pending.get("repair")
        if not repair:
            note = "no repair keeps this edit valid; answer undo, replan, edit or reject"
            return {"review_note": note, "phase": "review"}
        outcome = {"choice": "repair", "changes": repair["changes"], "summary": repair["summary"]}
        update = {"layout": repair["layout"], "operator_sequence": repair["sequence"]}
    elif action == "undo":
        before, _ = parse_layout(pending["before"], max_parts=ctx.cell.limits.max_parts)
        changes = [c.model_dump(mode="json") for c in layout_diff(operator, before)]
        outcome = {"choice": "undo", "changes": changes}
        update = {"layout": pending["before"], "operator_sequence": None}
    elif action == "replan":
        outcome = {"choice": "replan", "operator": pending["operator"]}  # diff once designed
        update = {"operator_sequence": None}
    elif action == "edit":
        started = _start_edit(state, ctx, operator, decision.get("edits", []), pending)
        return {**started, "phase": started.get("phase", "review")}
    elif action == "reject":
        return {"status": "rejected", "phase": "end", "edit": None}
    else:
        note = (f"the edited layout breaks {len(pending.get('violations') or [])} constraint(s); "
                f"answer one of {', '.join(choices)}")  # fmt: skip
        return {"review_note": note, "phase": "review"}
    notes = list(state.get("notes", []))
    if "changes" in outcome:
        notes.append(_outcome_notes(action, outcome["changes"], outcome.get("summary")))
    say(state, ctx, "orchestrator", "human", "edit_resolved", outcome)
    return {**update, "edit": None, "edit_outcome": outcome, "notes": notes, "review_note": None,
            "phase": "modify" if action == "replan" else "inspect"}  # fmt: skip


REVIEW_CHOICES = ("approve", "edit", "reject", "abort")
"""The answers at a design review: approve; edit (C ⊕ I_h, re-inspected); reject with a reason
(the orchestrator replans: the reason is read after the command as a clause that changes it,
and a model Designer is told it); abort (the run ends, status ``rejected``). A reject without a
reason has nothing to replan from: it ends the run, as abort does (the CLI's ``--reject``)."""


def _replanned_note(state: RunState, cell: CellConfig) -> str | None:
    """What the replan after a rejection changed, for the next design review to say: never the
    same layout shown again as if it were new."""
    rejected = state.get("rejected")
    current = _layout(state, cell)
    if not rejected or current is None or not rejected.get("layout"):
        return None
    before, _ = parse_layout(rejected["layout"], max_parts=cell.limits.max_parts)
    reason = rejected.get("reason", "")
    if layout_hash(before) == layout_hash(current):
        unused = state.get("ignored") or []
        why = f" (words not used: {', '.join(unused)})" if unused else ""
        return (f"replanned after your rejection ({reason!r}): the same layout came back — "
                f"the reason was not read as a change{why}")  # fmt: skip
    from sdi.model.diff import describe_diff

    changes = describe_diff(layout_diff(before, current))
    return f"replanned after your rejection ({reason!r}): {changes}"


def review_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    pending_edit = state.get("edit")
    if pending_edit and pending_edit.get("status") == "invalid":
        return _edit_review(state, ctx, pending_edit)
    if state.get("design_only"):
        return {"status": "verified", "phase": "end"}
    update: dict[str, Any] = {}
    outcome = state.get("edit_outcome")
    if outcome and "changes" not in outcome and outcome.get("operator"):  # a replanned edit
        operator, _ = parse_layout(outcome["operator"], max_parts=ctx.cell.limits.max_parts)
        current = _layout(state, ctx.cell)
        changes = [c.model_dump(mode="json") for c in layout_diff(operator, current or operator)]
        outcome = {"choice": outcome.get("choice"), "changes": changes}
        update["edit_outcome"] = outcome
        update["notes"] = [*state.get("notes", []), _outcome_notes("replan", changes)]
    replanned = _replanned_note(state, ctx.cell)
    if replanned is not None:
        update["notes"] = [*update.get("notes", state.get("notes", [])), replanned]
        update["rejected"] = None
    pending = state.get("pending_approval")
    if state.get("approve") and not pending:
        decision: Any = {"action": "approve", "by": "--approve-all"}
    else:
        request = {
            "kind": "recovery_review" if pending else "design_review",
            "layout": state.get("layout"),
            "sequence": state.get("sequence"),
            "refused": state.get("review_note"),
            "choices": list(REVIEW_CHOICES),
        }
        if pending:
            request["recovery"] = pending
        if outcome:
            request["edit_outcome"] = outcome
        if replanned is not None:
            request["replanned"] = replanned
        decision = interrupt(request)
    say(state, ctx, "human", "orchestrator", "review", decision)
    action = decision.get("action") if isinstance(decision, dict) else None
    if action == "approve":
        return {**update, "phase": "pre_execute", "review_note": None, "pending_approval": None}
    if action == "edit":
        layout = _layout(state, ctx.cell)
        assert layout is not None
        started = _start_edit(state, ctx, layout, decision.get("edits", []), None)
        return {**update, "pending_approval": None, **started,
                "phase": started.get("phase", "review")}  # fmt: skip
    reason = decision.get("reason") if isinstance(decision, dict) else None
    if action == "reject" and isinstance(reason, str) and reason.strip():
        reason = " ".join(reason.split())[:500]
        say(state, ctx, "orchestrator", "specifier", "revision", {"reason": reason})
        return {**update, "revisions": [*(state.get("revisions") or []), reason],
                "rejected": {"reason": reason, "layout": state.get("layout")},
                "pending_approval": None, "review_note": None, "operator_sequence": None,
                "edit_outcome": None, "phase": "plan"}  # fmt: skip
    return {**update, "status": "rejected", "phase": "end"}


# -- PRE_EXECUTE: plan motion once, store the record -----------------------------------------
def pre_execute_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    from sdi.commission import commission

    ctx = runtime.context
    _crash_hook("pre_execute")
    layout = _layout(state, ctx.cell)
    assert layout is not None
    try:  # the job INSPECT verified; the gate runs here only if it did not (critic ablation)
        job = ctx.jobs.job(ctx.cell, layout, state.get("sequence"))
        planned = commission(job, arms=ctx.arms)
    except UnverifiedPlanError as exc:
        say(state, ctx, "inspector", "orchestrator", "refused",
            {"error": str(exc), "violations": exc.violations_json()[:20]})  # fmt: skip
        violations = exc.violations_json() or [{"constraint": "gate", "message": str(exc)}]
        return {"violations": violations, "phase": "replan"}
    except MotionPlanningError as exc:
        event = exc.event.to_json_dict()  # type: ignore[attr-defined]
        say(state, ctx, "operator", "orchestrator", "failure", event)
        return {"failure": failure_of(event, "pre_execute"), "phase": "replan"}
    record = CommissioningRecord.of(planned)
    ctx.store.put(state["run_id"], record)
    summary = record.summary()
    say(state, ctx, "operator", "human", "record", summary)
    return {"planning": summary, "record_hash": record.hash, "phase": "confirm"}


# -- CONFIRM: the pre-execution approval names the record's hash -----------------------------
def confirm_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    record_hash = state.get("record_hash")
    interrupted = state.get("resume_from")
    if state.get("approve") and not interrupted:
        decision: Any = {"action": "approve", "record_hash": record_hash, "by": "--approve-all"}
    else:
        request: dict[str, Any] = {
            "kind": "resume_execution" if interrupted else "pre_execute",
            "record_hash": record_hash,
            "planning": state.get("planning"),
        }
        if interrupted:
            request["as_built"] = interrupted
        decision = interrupt(request)
    say(state, ctx, "human", "orchestrator", "confirm", decision)
    if isinstance(decision, dict) and decision.get("action") == "revise" and not interrupted:
        return {"phase": "review", "record_hash": None, "planning": None}  # back to the design
    if not (isinstance(decision, dict) and decision.get("action") == "approve"):
        return {"status": "aborted", "phase": "end"}
    named = decision.get("record_hash")
    if named is not None and named != record_hash:
        note = f"the approval names record {str(named)[:12]}, but the planned record is " \
               f"{str(record_hash)[:12]}; nothing moves"  # fmt: skip
        say(state, ctx, "orchestrator", "human", "refused", {"error": note})
        return {"status": "aborted", "phase": "end", "notes": [note]}
    return {"approved_hash": record_hash, "phase": "execute"}


# -- EXECUTE: exactly the approved record ------------------------------------------------------
def execute_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    from sdi.commission import execute as run

    ctx = runtime.context
    _crash_hook("execute")
    _hold_hook("execute")
    run_id, approved = state["run_id"], state.get("approved_hash")
    try:
        if not approved or approved != state.get("record_hash"):
            raise RecordError("no approved commissioning record; nothing moves")
        record = ctx.store.get(run_id, approved)
        layout = _layout(state, ctx.cell)
        if layout is None or layout_hash(layout) != record.body["layout_hash"]:
            raise RecordError(
                f"the run's layout changed since record {approved[:12]} was approved; nothing moves"
            )
        held = ctx.jobs.get(ctx.cell, layout, record.body["sequence"])
        planned = record.commissioning(ctx.cell, held)  # no second verification if held
    except (RecordError, UnverifiedPlanError) as exc:
        say(state, ctx, "operator", "human", "refused", {"error": str(exc)})
        failure = failure_of(None, "execute", error_type="record", message=str(exc))
        return {"failure": failure, "status": "failure", "phase": "end", "notes": [str(exc)]}
    resume_from = state.get("resume_from") or {}
    already = list(resume_from.get("placed", []))
    placed = {p["part_id"]: p["pose"] for p in already}
    say(state, ctx, "operator", "orchestrator", "execution_started",
        {"record_hash": approved, "already_placed": already})  # fmt: skip
    crash_after = int(os.environ.get("SDI_CRASH_AFTER_STEPS", "0") or 0)

    def progress(event: dict[str, Any]) -> None:
        kind = str(event.pop("kind", "step_done"))
        say(state, ctx, "operator", "orchestrator", kind, event)
        if crash_after and event.get("completed") == crash_after:
            os._exit(137)  # fault injection for the kill-during-execution test

    faults = tuple(FAULTS[f] for f in state.get("faults", []))
    try:
        result, report = run(planned, faults=faults, placed=placed, progress=progress)
    except UnverifiedPlanError as exc:
        report = {"status": "failure", "failure": {"message": str(exc), "error_type": "gate"}}
        result = None
    report["record_hash"] = approved
    say(state, ctx, "operator", "orchestrator", "execution", report)
    update: dict[str, Any] = {"execution": report, "resume_from": None}
    if report["status"] == "success" and report.get("v_traj") == "pass":
        # built as planned; `partial` when the command had words the reading could not use
        done = "partial" if state.get("unread") else "success"
        return {**update, "status": done, "phase": "end", "failure": None}
    raw = report.get("failure")
    event = raw if isinstance(raw, dict) else None
    scenario = getattr(result, "scenario", None)
    failure = failure_of(event, "execute", scenario=scenario)
    if report["status"] == "paused":  # δ breached ε: the robots stopped; a person decides
        return {**update, "failure": failure, "phase": "failure_report"}
    return {**update, "failure": failure, "phase": "replan"}


# -- REPLAN -----------------------------------------------------------------------------------
def replan_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    method = ctx.method
    _crash_hook("replan")
    replans = state.get("replans", 0) + 1
    if method.orchestration == "none" or replans > method.replans:
        action = "escalate" if method.orchestration in ("langgraph", "hybrid") else "fail"
    elif method.orchestration in ("langgraph", "hybrid"):
        action = llm_route(state, ctx)
    else:
        action = rule_route(state, method)
        if method.orchestration == "pge" and action in (*SKILLS, "relax"):
            action = "modify"
    by_rules = ctx.model is None or method.orchestration not in ("langgraph", "hybrid")
    say(state, ctx, "orchestrator", "orchestrator", "route", {"action": action, "replan": replans})
    tried = [*state.get("tried", []), action]
    update: dict[str, Any] = {"replans": replans, "tried": tried}
    layout = _layout(state, ctx.cell)
    avoid = _avoid(state, ctx.cell)
    update["avoid"] = avoid
    blocked = _blocked(state, avoid)
    if action in SKILLS and layout is not None:
        spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
        # spread commissions its result, the real test of reach: the places learned from IK
        # failures (which may have been a grip no arm could take, not a place) do not bind it
        regions = _blocked(state, []) if action == "spread" else blocked
        try:
            repaired, recovery = recover(action, layout, ctx.cell, regions, spec, arms=ctx.arms)
        except InfeasibleError as exc:
            update["notes"] = [*state.get("notes", []), f"{action}: {exc}"]
            if by_rules:  # not tried, so not counted: the rules never choose it twice
                update["replans"] = state.get("replans", 0)
            return {**update, "phase": "replan"}
        return {**update, **_recovered(state, ctx, layout, repaired, recovery), "phase": "inspect"}
    if action in SKILLS:
        return {**update, "phase": "replan"}
    if action == "modify":
        return {**update, "phase": "modify"}
    if action == "relax":
        return {**update, "relaxed": True, "phase": "plan"}
    if action == "escalate":
        return {**update, "phase": "failure_report"}
    return {**update, "status": "failure", "phase": "end"}


def _avoid(state: RunState, cell: CellConfig) -> list[dict[str, Any]]:
    """The places learned to avoid: the run's earlier ones, and the target of an IK failure no
    injected region explains (one part's footprint there, for every height)."""
    avoid = list(state.get("avoid") or [])
    failure = state.get("failure") or {}
    pose = failure.get("target_pose")
    if failure.get("error_type") == "ik" and not failure.get("scenario") and pose:
        x, y, half = float(pose[0]), float(pose[1]), cell.cube[0] / 2
        region = Region(name=f"unreachable near ({x:.3f}, {y:.3f})", x_min=x - half,
                        x_max=x + half, y_min=y - half, y_max=y + half)  # fmt: skip
        data = region.model_dump(mode="json", exclude_none=True)
        if data not in avoid:
            avoid.append(data)
    return avoid


def _blocked(state: RunState, avoid: list[dict[str, Any]]) -> tuple[Region, ...]:
    """Every region the run must keep out of: each injected fault's (they stay while the run
    recovers, whichever one failed last) and the places learned to avoid."""
    regions = [r for name in state.get("faults", []) for r in FAULTS[name].regions]
    return (*regions, *(Region.model_validate(r) for r in avoid))


def _recovered(
    state: RunState, ctx: RunContext, before: Layout, after: Layout, outcome: RecoveryOutcome
) -> dict[str, Any]:
    """The state update of a recovery: the new layout, what changed (notes, `recoveries`, a
    `recovery` event), and — when the shape changed — a review no `--approve-all` answers."""
    data = outcome.model_dump(mode="json")
    say(state, ctx, "orchestrator", "human", "recovery", data)
    update: dict[str, Any] = {
        "layout": after.to_json_dict(),
        "failure": None,
        "recoveries": [*(state.get("recoveries") or []), data],
        "notes": [*state.get("notes", []), f"recovery: {outcome.summary}"],
    }
    if outcome.shape_changed:
        update["pending_approval"] = data
    return update


def _inspected(state: RunState) -> tuple[Violation, ...] | None:
    """The Inspector's violations of the run's layout, as INSPECT stored them (all of them), or
    None if what is stored is not the Inspector's (the critic, a missing layout)."""
    try:
        return tuple(Violation.model_validate(v) for v in state.get("violations") or [])
    except ValueError:
        return None


def modify_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    _crash_hook("modify")
    layout = _layout(state, ctx.cell)
    designer = _designer(ctx)
    spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
    failure = state.get("failure") or {}
    if isinstance(designer, RuleDesigner) and layout is not None and failure:
        # the rule-based replan (MultiAgent-RuleOrch): away from the regions that failed
        avoid = _avoid(state, ctx.cell)
        try:
            repaired, recovery = rule_replan(layout, ctx.cell, _blocked(state, avoid))
        except InfeasibleError as exc:
            note = f"rule-based replan: {exc}"
            return {"phase": "replan", "notes": [*state.get("notes", []), note], "avoid": avoid}
        return {**_recovered(state, ctx, layout, repaired, recovery), "avoid": avoid,
                "phase": "inspect"}  # fmt: skip
    if state.get("given_layout") is not None:  # no command to design from: REPLAN goes on
        note = "the Designer cannot redesign a layout given as a file (it has no command)"
        return {"phase": "replan", "notes": list(dict.fromkeys([*state.get("notes", []), note]))}
    if isinstance(designer, RuleDesigner) or layout is None:
        outcome = designer.design(spec, state["command"])
    else:
        violations = _inspected(state)  # what INSPECT found in this very layout
        if violations is None:  # not the Inspector's own findings (critic ablation, gate)
            violations = verify(layout, ctx.cell).violations
        outcome = designer.design(spec, state["command"], start=layout, violations=violations)
    say(state, ctx, "designer", "inspector", "layout",
        {"status": outcome.status, "modified": True})  # fmt: skip
    if outcome.layout is None:
        return {"phase": "replan", "notes": outcome.notes}
    if outcome.job is not None:  # the Designer's gate passed it: INSPECT need not run again
        ctx.jobs.put(outcome.job)
    return {"layout": outcome.layout.to_json_dict(), "phase": "inspect", "failure": None}


FAILURE_CHOICES = ("recover", "retry", "edit", "abort")
"""The answers to a failure report: run one of the recovery skills the orchestrator would try
(``{"action": "recover", "skill": …}``), plan the command again (retry), edit the failed layout
(``{"action": "edit", "edits": […]}``), or abort."""

SKILL_DOES = {
    "shift": "move the layout clear of the blocked regions (same shape)",
    "flatten": "lower the structure under the height limit (changes the shape)",
    "spread": "open gaps between the parts so the grippers reach them (changes the spacing)",
    "modify": "the Designer redesigns from the failed layout",
}
"""The recovery skills an operator may pick at a failure report, as REPLAN names them."""


def recovery_skills(state: RunState, method: Method) -> list[str]:
    """The recovery skills the orchestrator would try for this failure, in its order: shift and
    flatten (with the method's recovery skills and a layout to recover), then the Designer."""
    skills: list[str] = []
    if method.recovery and state.get("layout"):
        scenario = SCENARIOS.get((state.get("failure") or {}).get("scenario") or "")
        height = scenario is not None and any(r.z_min is not None for r in scenario.regions)
        skills += ["flatten", "shift"] if height else ["shift", "flatten"]
        skills.append("spread")
    return [*skills, "modify"]


def _recover_chosen(state: RunState, ctx: RunContext, skill: Any) -> dict[str, Any]:
    """The operator's pick of a recovery skill: run shift or flatten here (to INSPECT), or hand
    the failed layout to the Designer (MODIFY). The replan budget starts again, as on retry."""
    offered = recovery_skills(state, ctx.method)
    if skill not in offered:
        note = f"no recovery skill {skill!r} here; choose one of {', '.join(offered)}"
        return {"review_note": note, "phase": "failure_report"}
    budget = {"replans": 0, "tried": [skill], "review_note": None}
    if skill == "modify":
        return {**budget, "phase": "modify"}
    layout = _layout(state, ctx.cell)
    assert layout is not None  # `recovery_skills` offers shift and flatten only with a layout
    spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
    avoid = _avoid(state, ctx.cell)
    try:
        repaired, recovery = recover(skill, layout, ctx.cell, _blocked(state, avoid), spec)
    except InfeasibleError as exc:
        return {"review_note": f"{skill}: {exc}", "phase": "failure_report", "avoid": avoid}
    return {**budget, **_recovered(state, ctx, layout, repaired, recovery), "avoid": avoid,
            "phase": "inspect"}  # fmt: skip


def failure_report_node(state: RunState, runtime: Rt) -> dict[str, Any]:
    ctx = runtime.context
    if state.get("approve") or state.get("design_only"):
        return {"status": "failure", "phase": "end"}
    skills = recovery_skills(state, ctx.method)
    decision = interrupt(
        {
            "kind": "failure_report",
            "failure": state.get("failure"),
            "violations": state.get("violations", [])[:10],
            "refused": state.get("review_note"),
            "layout": state.get("layout"),
            "choices": list(FAILURE_CHOICES),
            "skills": [{"name": k, "does": SKILL_DOES[k]} for k in skills],
        }
    )
    say(state, ctx, "human", "orchestrator", "failure_decision", decision)
    action = decision.get("action") if isinstance(decision, dict) else None
    if action == "recover":
        return _recover_chosen(state, ctx, decision.get("skill"))
    if action == "edit":
        layout = _layout(state, ctx.cell)
        if layout is not None:
            started = _start_edit(state, ctx, layout, decision.get("edits", []), None)
            if "edit" not in started:  # refused as malformed: the report waits again
                return {**started, "phase": "failure_report"}
            return {**started, "replans": 0, "tried": [], "failure": None}
    if action == "retry":
        return {"phase": "plan", "replans": 0, "tried": [], "failure": None, "relaxed": False,
                "review_note": None}  # fmt: skip
    return {"status": "failure", "phase": "end"}


Node = Callable[[RunState, Rt], dict[str, Any]]

NODES: dict[str, Node] = {
    "plan": plan_node,
    "design": design_node,
    "inspect": inspect_node,
    "review": review_node,
    "pre_execute": pre_execute_node,
    "confirm": confirm_node,
    "execute": execute_node,
    "replan": replan_node,
    "modify": modify_node,
    "failure_report": failure_report_node,
}
"""The phases. HUMAN_REVIEW is `review`; CONFIRM is PRE_EXECUTE's human approval."""

UNTIMED = ("review", "confirm", "failure_report")
"""Nodes that wait for a person: not under a wall-clock limit."""

FIXED: dict[str, str] = {"design": "inspect"}
"""Fixed edges: whatever the Designer makes (or fails to make) goes to the Inspector, which
passes an empty design on to REPLAN and a timed-out one to the failure report."""

ROUTES: dict[str, tuple[str, ...]] = {
    "plan": ("design", "end"),
    "inspect": ("review", "replan"),
    "review": ("pre_execute", "inspect", "modify", "review", "plan", "end"),
    "pre_execute": ("confirm", "replan"),
    "confirm": ("execute", "review", "end"),
    "execute": ("replan", "end"),
    "replan": ("inspect", "modify", "plan", "replan", "failure_report", "end"),
    "modify": ("inspect", "replan"),
    "failure_report": ("inspect", "modify", "plan", "failure_report", "end"),
}
"""Each node's possible next phases; a timed node may also go to the failure report."""


def _timed(name: str, fn: Node) -> Node:
    def node(state: RunState, runtime: Rt) -> dict[str, Any]:
        ctx = runtime.context
        try:
            with phase_limit(name, phase_seconds(name, state, ctx.cell)):
                return plain(fn(state, runtime))
        except PhaseTimeout as exc:
            failure = Failure(error_type="timeout", scenario=None, phase=name, message=str(exc))
            say(state, ctx, "orchestrator", "human", "failure", dict(failure))
            return {"failure": failure, "notes": [str(exc)], "phase": "failure_report"}

    node.__name__ = name
    return node


def _router(name: str, targets: tuple[str, ...]) -> Callable[[RunState], str]:
    def route(state: RunState) -> str:
        phase = state.get("phase", "")
        if phase not in targets:
            raise RoutingError(f"node {name!r} asked for route {phase!r}; it has {list(targets)}")
        return phase

    route.__name__ = f"route_{name}"
    return route


def build_graph() -> StateGraph[RunState, RunContext, RunState, RunState]:
    """The orchestrator's graph (not compiled): nodes, fixed edges, mapped branch points."""
    g = StateGraph(RunState, context_schema=RunContext)
    for name, fn in NODES.items():
        g.add_node(name, fn if name in UNTIMED else _timed(name, fn))  # type: ignore[call-overload]
    g.add_edge(START, "plan")
    for name, target in FIXED.items():
        g.add_edge(name, target)
    for name, targets in ROUTES.items():
        if name not in UNTIMED:
            targets = (*targets, "failure_report") if "failure_report" not in targets else targets
        path_map = {t: (END if t == "end" else t) for t in targets}
        g.add_conditional_edges(name, _router(name, targets), path_map)  # type: ignore[arg-type]
    return g


def mermaid() -> str:
    """The graph as LangGraph draws it (Mermaid)."""
    return str(build_graph().compile().get_graph().draw_mermaid())


def llm_critic(ctx: RunContext, layout: Layout) -> dict[str, Any]:
    """The ablation: an LLM judges feasibility instead of the Inspector (never the last gate)."""
    assert ctx.model is not None
    import json

    from sdi.agents.prompts import all_constraints

    prompt = (
        "Check this layout against the constraints and answer JSON "
        '{"passed": true|false, "problems": [...]}.\nConstraints:\n'
        f"{all_constraints()}\nLayout: {json.dumps(layout.to_json_dict())}"
    )
    try:
        reply = ctx.model.chat([{"role": "user", "content": prompt}], max_tokens=300, role="critic")
        value = parse_json(reply.content)
        return {"passed": bool(value.get("passed")), "problems": value.get("problems", [])}
    except (ValueError, AttributeError, LLMError, SDIError):
        ctx.model.usage.malformed += 1
        return {"passed": False, "problems": ["critic answer unusable"]}
