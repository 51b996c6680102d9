"""The orchestrator: a LangGraph state machine over PLAN, DESIGN, INSPECT, HUMAN_REVIEW,
PRE_EXECUTE, EXECUTE and REPLAN (paper §III-B, Alg. 1).

Fixed edges where reliability matters: PLAN → DESIGN → INSPECT, and the Inspector gates every
path to the robots. Routing is decided only at failure branch points (REPLAN): by the model when
the method routes with LangGraph and a model is set, otherwise by deterministic rules. REPLAN
tries the recovery skills first (shift, flatten) and sends their output straight to the
Inspector, then the Designer's `modify`, then Specifier relaxation (the raw command), then the
human. At most `method.replans` replans. The three human touch points are LangGraph
`interrupt()`s: design review, pre-execution confirmation, failure report. State is
checkpointed (SQLite), so a killed process resumes where it stopped. Every working phase runs
under a wall-clock limit (`[limits] phase_seconds`, 300 s by default); a phase that runs past it
stops at its next clean point and goes to the failure report.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, TypedDict

from langgraph.graph import END, START, StateGraph
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
from sdi.execute.faults import SCENARIOS
from sdi.inspector.verifier import verify
from sdi.jsonable import plain
from sdi.llm.chat import ChatModel
from sdi.llm.openai_backend import LLMError, parse_json
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout, parse_layout
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.edits import apply_edits
from sdi.orchestrator.methods import SAMS_SKILLS, SASS_SKILLS, Method
from sdi.recovery import flatten, shift
from sdi.skills.builtin import default_registry
from sdi.spec.structure_spec import Spec

ACTIONS = ("shift", "flatten", "modify", "relax", "escalate")


class RunState(TypedDict, total=False):
    run_id: str
    command: str
    method: str
    backend: str
    spec: dict[str, Any] | None
    spec_source: str
    relaxed: bool
    layout: dict[str, Any] | None
    sequence: list[str] | None
    violations: list[dict[str, Any]]
    replans: int
    tried: list[str]
    failure: dict[str, Any] | None
    faults: list[str]
    execution: dict[str, Any] | None
    planning: dict[str, Any] | None
    status: str
    phase: str
    notes: list[str]
    approve: bool
    design_only: bool  # stop once the design is verified (benchmarks): status "verified"


@dataclass
class RunContext:
    """What the nodes need that is not state: the cell, the model, the method, the bus."""

    cell: CellConfig
    method: Method
    model: ChatModel | None
    bus: MessageBus
    arms: list[str] | None = None


def _crash_hook(node: str) -> None:
    """Fault injection for the crash/resume tests: SDI_CRASH_AT=<node> kills the process there."""
    if os.environ.get("SDI_CRASH_AT") == node:
        os._exit(137)


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
        scenario = SCENARIOS.get(failure.get("scenario", ""))
        height = scenario is not None and any(r.z_min is not None for r in scenario.regions)
        for action in ("flatten", "shift") if height else ("shift", "flatten"):
            if action not in tried:
                return action
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
    allowed = [a for a in ACTIONS if ctx.method.recovery or a not in ("shift", "flatten")]
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


def build_graph(ctx: RunContext) -> StateGraph:
    cell, method, bus = ctx.cell, ctx.method, ctx.bus

    def say(
        state: RunState, sender: str, receiver: str, type: str, payload: dict[str, Any]
    ) -> None:
        bus.send(state["run_id"], sender, receiver, type, payload, key=str(state.get("replans", 0)))

    # -- PLAN ---------------------------------------------------------------------------------
    def plan(state: RunState) -> dict[str, Any]:
        _crash_hook("plan")
        command = state["command"]
        raw = ctx.model is not None and (not method.specifier or state.get("relaxed"))
        if raw:  # raw command to the Designer (no Specifier, or Specifier relaxation)
            say(
                state,
                "orchestrator",
                "designer",
                "command",
                {"command": command, "relaxed": bool(state.get("relaxed"))},
            )
            return {"spec": None, "spec_source": "raw command", "phase": "design"}
        try:
            result = Specifier(ctx.model if method.specifier else None, cell).specify(command)
        except SpecError as exc:
            say(state, "orchestrator", "human", "error", {"error": str(exc)})
            return {"status": "failure", "phase": "end", "notes": [str(exc)], "spec": None}
        spec = result.spec.model_dump(mode="json", exclude_none=True)
        say(state, "specifier", "designer", "spec", {"spec": spec, "source": result.source})
        return {
            "spec": result.spec.model_dump(mode="json"),
            "spec_source": result.source,
            "phase": "design",
        }

    # -- DESIGN -------------------------------------------------------------------------------
    def design(state: RunState) -> dict[str, Any]:
        _crash_hook("design")
        spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
        outcome: DesignOutcome = _designer(ctx).design(spec, state["command"])
        parts = len(outcome.layout) if outcome.layout else 0
        message = {"status": outcome.status, "parts": parts, "notes": outcome.notes}
        say(state, "designer", "inspector", "layout", message)
        if outcome.layout is None:
            return {"layout": None, "violations": [], "notes": outcome.notes, "phase": "replan"}
        return {"layout": outcome.layout.to_json_dict(), "phase": "inspect", "notes": outcome.notes}

    # -- INSPECT (never an LLM, except the critic ablation) ------------------------------------
    def inspect(state: RunState) -> dict[str, Any]:
        _crash_hook("inspect")
        layout = _layout(state, cell)
        if layout is None:
            return {
                "violations": [{"constraint": "design", "message": "no layout"}],
                "phase": "replan",
            }
        if method.critic == "llm" and ctx.model is not None:
            verdict = llm_critic(ctx, layout)
            say(state, "critic", "orchestrator", "verdict", verdict)
            if verdict.get("passed"):
                return {"violations": [], "sequence": list(layout.ids), "phase": "review"}
            return {
                "violations": [{"constraint": "critic", "message": str(verdict.get("problems"))}],
                "phase": "replan",
            }
        report = verify(layout, cell, sequence=None)
        violations = [v.to_json_dict() for v in report.violations]
        say(
            state,
            "inspector",
            "orchestrator",
            "verification",
            {"passed": report.passed, "violations": violations[:20]},
        )
        return {
            "violations": violations,
            "sequence": list(report.sequence) if report.sequence else None,
            "phase": "review" if report.passed else "replan",
        }

    # -- HUMAN_REVIEW -------------------------------------------------------------------------
    def human_review(state: RunState) -> dict[str, Any]:
        if state.get("design_only"):
            return {"status": "verified", "phase": "end"}
        if state.get("approve"):
            decision: dict[str, Any] = {"action": "approve"}
        else:
            decision = interrupt(
                {
                    "kind": "design_review",
                    "layout": state.get("layout"),
                    "sequence": state.get("sequence"),
                }
            )
        say(state, "human", "orchestrator", "review", decision)
        action = decision.get("action") if isinstance(decision, dict) else None
        if action == "approve":
            return {"phase": "pre_execute"}
        if action == "edit":
            layout = _layout(state, cell)
            assert layout is not None
            try:
                edited = apply_edits(layout, decision.get("edits", []), cell)
            except InputError as exc:
                return {"notes": [f"edit refused: {exc}"], "phase": "review_again"}
            return {"layout": edited.to_json_dict(), "phase": "inspect"}
        return {"status": "rejected", "phase": "end"}

    # -- PRE_EXECUTE --------------------------------------------------------------------------
    def pre_execute(state: RunState) -> dict[str, Any]:
        from sdi.commission import commission

        _crash_hook("pre_execute")
        layout = _layout(state, cell)
        assert layout is not None
        try:
            planned = commission(layout, cell, sequence=state.get("sequence"), arms=ctx.arms)
        except UnverifiedPlanError as exc:  # the symbolic gate (matters in the critic ablation)
            say(state, "inspector", "orchestrator", "refused", {"error": str(exc)})
            return {
                "violations": [{"constraint": "gate", "message": m} for m in exc.violations],
                "phase": "replan",
            }
        except MotionPlanningError as exc:
            event = exc.event.to_json_dict()  # type: ignore[attr-defined]
            say(state, "operator", "orchestrator", "failure", event)
            return {"failure": event, "phase": "replan"}
        summary = planned.summary()
        say(
            state,
            "operator",
            "human",
            "preview",
            {k: v for k, v in summary.items() if k != "planning_s_per_step"},
        )
        if not state.get("approve"):
            decision = interrupt({"kind": "pre_execute", "planning": summary})
            say(state, "human", "orchestrator", "confirm", decision)
            if not (isinstance(decision, dict) and decision.get("action") == "approve"):
                return {"status": "aborted", "phase": "end", "planning": summary}
        return {"planning": summary, "phase": "execute"}

    # -- EXECUTE ------------------------------------------------------------------------------
    def execute(state: RunState) -> dict[str, Any]:
        from sdi.commission import commission
        from sdi.commission import execute as run

        _crash_hook("execute")
        layout = _layout(state, cell)
        assert layout is not None
        faults = tuple(SCENARIOS[f] for f in state.get("faults", []))
        try:
            planned = commission(layout, cell, sequence=state.get("sequence"), arms=ctx.arms)
            _, report = run(planned, faults=faults)
        except (MotionPlanningError, UnverifiedPlanError) as exc:
            event = getattr(exc, "event", None)
            report = {
                "status": "failure",
                "failure": event.to_json_dict() if event else {"message": str(exc)},
            }
        say(state, "operator", "orchestrator", "execution", report)
        if report["status"] == "success" and report.get("v_traj") == "pass":
            return {"execution": report, "status": "success", "phase": "end", "failure": None}
        failure: dict[str, Any] = dict(report.get("failure") or {})  # type: ignore[call-overload]
        for name in state.get("faults", []):
            event_scenario = failure.get("message", "").split(":")[0]
            if event_scenario == name:
                failure["scenario"] = name
        return {"execution": report, "failure": failure, "phase": "replan"}

    # -- REPLAN -------------------------------------------------------------------------------
    def replan(state: RunState) -> dict[str, Any]:
        _crash_hook("replan")
        replans = state.get("replans", 0) + 1
        if method.orchestration == "none" or replans > method.replans:
            action = "escalate" if method.orchestration in ("langgraph", "hybrid") else "fail"
        elif method.orchestration in ("langgraph", "hybrid"):
            action = llm_route(state, ctx)
        else:
            action = rule_route(state, method)
            if method.orchestration == "pge" and action in ("shift", "flatten", "relax"):
                action = "modify"
        say(state, "orchestrator", "orchestrator", "route", {"action": action, "replan": replans})
        tried = [*state.get("tried", []), action]
        update: dict[str, Any] = {"replans": replans, "tried": tried}
        layout = _layout(state, cell)
        failure = state.get("failure") or {}
        scenario = SCENARIOS.get(failure.get("scenario", ""))
        blocked = scenario.regions if scenario else ()
        if action in ("shift", "flatten") and layout is not None:
            try:
                if action == "shift":
                    repaired = shift(layout, cell, blocked=blocked)
                else:
                    limits = [r.z_min for r in blocked if r.z_min is not None]
                    repaired = flatten(
                        layout, cell, z_max=min(limits) if limits else None, blocked=blocked
                    )
            except InfeasibleError as exc:
                return {**update, "notes": [f"{action}: {exc}"], "phase": "replan"}
            # recovery output goes straight to the Inspector; the injected obstacle stays
            return {
                **update,
                "layout": repaired.to_json_dict(),
                "failure": None,
                "phase": "inspect",
            }
        if action == "modify":
            return {**update, "phase": "modify"}
        if action == "relax":
            return {**update, "relaxed": True, "phase": "plan"}
        if action == "escalate":
            return {**update, "phase": "failure_report"}
        return {**update, "status": "failure", "phase": "end"}

    def modify(state: RunState) -> dict[str, Any]:
        _crash_hook("modify")
        layout = _layout(state, cell)
        designer = _designer(ctx)
        spec = Spec.model_validate(state["spec"]) if state.get("spec") else None
        if isinstance(designer, RuleDesigner) or layout is None:
            outcome = designer.design(spec, state["command"])
        else:
            report = verify(layout, cell)
            outcome = designer.design(
                spec, state["command"], start=layout, violations=report.violations
            )
        say(state, "designer", "inspector", "layout", {"status": outcome.status, "modified": True})
        if outcome.layout is None:
            return {"phase": "replan", "notes": outcome.notes}
        return {"layout": outcome.layout.to_json_dict(), "phase": "inspect", "failure": None}

    def failure_report(state: RunState) -> dict[str, Any]:
        if state.get("approve") or state.get("design_only"):
            return {"status": "failure", "phase": "end"}
        decision = interrupt(
            {
                "kind": "failure_report",
                "failure": state.get("failure"),
                "violations": state.get("violations", [])[:10],
            }
        )
        say(state, "human", "orchestrator", "failure_decision", decision)
        action = decision.get("action") if isinstance(decision, dict) else None
        if action == "edit":
            layout = _layout(state, cell)
            if layout is not None:
                try:
                    edited = apply_edits(layout, decision.get("edits", []), cell)
                except InputError as exc:
                    return {"notes": [f"edit refused: {exc}"], "status": "failure", "phase": "end"}
                return {
                    "layout": edited.to_json_dict(),
                    "phase": "inspect",
                    "replans": 0,
                    "tried": [],
                    "failure": None,
                }
        if action == "retry":
            return {"phase": "plan", "replans": 0, "tried": [], "failure": None, "relaxed": False}
        return {"status": "failure", "phase": "end"}

    def limited(
        name: str, fn: Callable[[RunState], dict[str, Any]]
    ) -> Callable[[RunState], dict[str, Any]]:
        def node(state: RunState) -> dict[str, Any]:
            try:
                with phase_limit(name, phase_seconds(name, state, cell)):
                    return plain(fn(state))  # JSON-ready: checkpoints refuse numpy
            except PhaseTimeout as exc:
                failure = {"error_type": "timeout", "phase": name, "message": str(exc)}
                say(state, "orchestrator", "human", "failure", failure)
                return {"failure": failure, "notes": [str(exc)], "phase": "failure_report"}

        return node

    def route(state: RunState) -> str:
        phase = state.get("phase", "end")
        if state.get("status") in ("failure", "rejected", "aborted", "success", "verified"):
            return END
        return {
            "design": "design", "inspect": "inspect", "review": "human_review",
            "review_again": "human_review", "pre_execute": "pre_execute", "execute": "execute",
            "replan": "replan", "modify": "modify", "plan": "plan",
            "failure_report": "failure_report",
        }.get(phase, END)  # fmt: skip

    g = StateGraph(RunState)
    nodes: dict[str, Callable[[RunState], dict[str, Any]]] = {
        "plan": plan, "design": design, "inspect": inspect, "human_review": human_review,
        "pre_execute": pre_execute, "execute": execute, "replan": replan, "modify": modify,
        "failure_report": failure_report,
    }  # fmt: skip
    for name, fn in nodes.items():
        if name not in ("human_review", "failure_report"):  # a person is not timed
            fn = limited(name, fn)
        g.add_node(name, fn)  # type: ignore[call-overload]
    g.add_edge(START, "plan")
    for name in nodes:
        g.add_conditional_edges(name, route)
    return g


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
