"""ξ_generate / ξ_modify, the Designer: spec → layout, in three interchangeable strategies.

- `RuleDesigner`: the parametric generators (no model; the `rules` backend).
- `LoopDesigner`: one LLM call per attempt (paper Alg. 2). `feedback` selects the baseline:
  "none" (LLM-Direct, one pass), "full" (LLM-FixedLoop: every constraint and every violation
  each retry), "adaptive" (LLM-AdaptLoop: only φ(E), the violated constraints, and the previous
  layout); `full_prompt` puts all of K into the first prompt (LLM-FullPrompt).
- `AgenticDesigner`: a function-calling loop over the skill registry (paper Alg. 3) with a step
  budget and the "output final JSON" nudge.

Every strategy ends in the same safety gate (paper eq. 17): the layout is verified by the
Inspector and returned only if it passes. Malformed output — not JSON, wrong types, unknown
fields or tools, hallucinated ids, oversized replies — is counted and fed back, never raised.
"""

from __future__ import annotations

import contextlib
import json
from dataclasses import dataclass, field
from typing import Any, Literal

from pydantic import ValidationError

from sdi import deadline
from sdi.agents.prompts import (
    LAYOUT_OUTPUT_SCHEMA,
    all_constraints,
    few_shot_messages,
    phi,
    system_prompt,
)
from sdi.design.composer import compose
from sdi.errors import InfeasibleError, InputError, UnverifiedPlanError
from sdi.execute.job import VerifiedJob
from sdi.inspector.verifier import Report
from sdi.llm.chat import ChatModel, Message
from sdi.llm.openai_backend import LLMError, parse_json
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout, parse_layout
from sdi.skills.registry import SkillRegistry
from sdi.spec.structure_spec import Spec

MAX_TOOL_RESULT = 6000
"""Characters of a tool result sent back to the model (the rest is cut, with a note)."""


@dataclass
class DesignOutcome:
    status: Literal["success", "failure"]
    layout: Layout | None
    report: Report | None
    attempts: int = 0
    notes: list[str] = field(default_factory=list)
    job: VerifiedJob | None = None  # the Inspector's pass of `layout` (status "success")


def task_text(spec: Spec | None, command: str) -> str:
    """The user turn: the command, and the structured spec when there is one."""
    if spec is None:
        return command
    return f"{command}\nSpecification: {spec.model_dump_json(exclude_none=True)}"


def safety_gate(
    layout: Layout | None, cell: CellConfig, attempts: int, notes: list[str]
) -> DesignOutcome:
    """C_final = C if V(C, K) passes, else FAILURE (paper eq. 17)."""
    if layout is None:
        return DesignOutcome("failure", None, None, attempts, [*notes, "no layout produced"])
    try:
        job = VerifiedJob.inspect(layout, cell)
    except UnverifiedPlanError as exc:
        report = exc.report
        assert report is not None
    else:
        return DesignOutcome("success", layout, job.report, attempts, notes, job)
    return DesignOutcome(
        "failure",
        layout,
        report,
        attempts,
        [*notes, f"safety gate: {len(report.violations)} violation(s)"],
    )


def _layout_from(value: Any, cell: CellConfig) -> Layout:
    if isinstance(value, dict) and "layout" in value and "objects" not in value:
        value = value["layout"]
    layout, _ = parse_layout(value, max_parts=cell.limits.max_parts)
    return layout


class RuleDesigner:
    name = "parametric"

    def __init__(self, cell: CellConfig | None = None) -> None:
        self.cell = cell or CellConfig()

    def design(self, spec: Spec | None, command: str = "") -> DesignOutcome:
        if spec is None:
            return DesignOutcome("failure", None, None, 0, ["the parametric designer needs a spec"])
        try:
            layout = compose(spec, self.cell)
        except (InfeasibleError, InputError) as exc:
            return DesignOutcome("failure", None, None, 1, [str(exc)])
        return safety_gate(layout, self.cell, 1, [])


class GeneratorFirstDesigner:
    """The Hybrid's Designer: the parametric generator skills first, the model only if needed.

    When the spec names structures the generators can build and their layout passes the
    Inspector, no model call is spent. Otherwise the adaptive loop (Alg. 2) takes over: it
    repairs the generated layout from its violations φ(E), or designs from the command when
    nothing could be generated.
    """

    name = "generator-first"

    def __init__(self, model: ChatModel, cell: CellConfig | None = None, *, t_max: int = 3) -> None:
        self.cell = cell or CellConfig()
        self.rules = RuleDesigner(self.cell)
        self.loop = LoopDesigner(model, self.cell, t_max=t_max, feedback="adaptive")

    def design(
        self,
        spec: Spec | None,
        command: str = "",
        start: Layout | None = None,
        violations: tuple[Any, ...] = (),
    ) -> DesignOutcome:
        if start is not None:  # ξ_modify: a layout to repair is the model's job
            return self.loop.design(spec, command, start=start, violations=violations)
        generated = self.rules.design(spec, command)
        if generated.status == "success":
            return generated
        # repair what the generators built, or design from the command if they built nothing
        report = generated.report
        outcome = self.loop.design(
            spec, command, start=generated.layout, violations=report.violations if report else ()
        )
        outcome.notes[:0] = [f"generators: {'; '.join(generated.notes)}"]
        return outcome


class LoopDesigner:
    """Alg. 2 and its baselines: one structured-output LLM call per attempt."""

    def __init__(
        self,
        model: ChatModel,
        cell: CellConfig | None = None,
        *,
        t_max: int = 3,
        feedback: Literal["none", "full", "adaptive"] = "adaptive",
        full_prompt: bool = False,
        temperature: float = 0.3,
    ) -> None:
        self.model = model
        self.temperature = temperature
        self.cell = cell or CellConfig()
        self.t_max = 1 if feedback == "none" else t_max
        self.feedback = feedback
        self.full_prompt = full_prompt
        self.name = {"none": "direct", "full": "fixed-loop", "adaptive": "adaptive-loop"}[feedback]

    def _minimal(self, spec: Spec | None, command: str) -> list[Message]:
        system = system_prompt(self.cell)
        if self.full_prompt:
            system += "\nAll constraints:\n" + all_constraints()
        task = task_text(spec, command)
        return [
            {"role": "system", "content": system},
            *few_shot_messages(),
            {"role": "user", "content": task},
        ]

    def design(
        self,
        spec: Spec | None,
        command: str = "",
        start: Layout | None = None,
        violations: tuple[Any, ...] = (),
    ) -> DesignOutcome:
        prompt = self._minimal(spec, command)
        if start is not None:  # ξ_modify: repair a given layout
            prompt += self._retry(start, violations, None)
        notes: list[str] = []
        layout: Layout | None = None
        for attempt in range(1, self.t_max + 1):
            deadline.check()
            try:
                reply = self.model.chat(
                    prompt,
                    json_schema=LAYOUT_OUTPUT_SCHEMA,
                    max_tokens=2048,
                    temperature=self.temperature,
                    role="designer",
                )
            except LLMError as exc:
                notes.append(str(exc))
                break
            try:
                layout = _layout_from(parse_json(reply.content), self.cell)
            except (ValueError, ValidationError, InputError) as exc:
                self.model.usage.malformed += 1
                notes.append(f"attempt {attempt}: malformed layout ({exc})")
                retry = f"Your answer was not a valid layout: {exc}. Answer with JSON only."
                prompt = [
                    *self._minimal(spec, command),
                    {
                        "role": "user",
                        "content": retry,
                    },
                ]
                layout = None
                continue
            try:
                job = VerifiedJob.inspect(layout, self.cell)
            except UnverifiedPlanError as exc:
                assert exc.report is not None
                report = exc.report
            else:
                return DesignOutcome("success", layout, job.report, attempt, notes, job)
            notes.append(f"attempt {attempt}: {len(report.violations)} violation(s)")
            prompt = self._minimal(spec, command) + self._retry(layout, report.violations, report)
        return safety_gate(layout, self.cell, self.t_max, notes)

    def _retry(self, layout: Layout, violations: Any, report: Report | None) -> list[Message]:
        previous = json.dumps(layout.to_json_dict())
        if self.feedback == "full":
            found = "\n".join(f"- {v.message}" for v in violations)
            text = (
                "Your layout failed verification.\nAll constraints:\n"
                f"{all_constraints()}\nViolations:\n{found}"
            )
        else:
            text = "Your layout failed verification.\n" + phi(violations)
        return [
            {"role": "assistant", "content": previous},
            {"role": "user", "content": text + "\nReturn the corrected layout as JSON only."},
        ]


SKILL_INSTRUCTIONS = (
    "You have tools. Prefer a generate_* tool to build a structure, call verify to check a "
    "layout, and flatten/shift to repair one. When the layout passes, answer with the final "
    'layout as JSON only: {"objects": [...]}.'
)


class AgenticDesigner:
    """Alg. 3: the LLM picks skills through function calling until it outputs a layout."""

    name = "agentic"

    def __init__(
        self,
        model: ChatModel,
        registry: SkillRegistry,
        cell: CellConfig | None = None,
        *,
        t_max: int = 8,
    ) -> None:
        self.model = model
        self.registry = registry
        self.cell = cell or CellConfig()
        self.t_max = t_max
        self.transcript: list[Message] = []

    def design(
        self,
        spec: Spec | None,
        command: str = "",
        start: Layout | None = None,
        violations: tuple[Any, ...] = (),
    ) -> DesignOutcome:
        task = task_text(spec, command)
        if start is not None:
            task += (
                "\nRepair this layout: " + json.dumps(start.to_json_dict()) + "\n" + phi(violations)
            )
        messages: list[Message] = [
            {"role": "system", "content": system_prompt(self.cell) + "\n" + SKILL_INSTRUCTIONS},
            {"role": "user", "content": task},
        ]
        self.transcript = messages  # the conversation, for the audit trail and tests
        notes: list[str] = []
        layout: Layout | None = None
        candidate: Layout | None = None  # the last layout a tool produced
        tools = self.registry.tools()
        if spec is not None:  # offer only the generators the spec names (smaller prompts)
            wanted = {f"generate_{st.shape}" for st in spec.structures} | {"generate"}
            names = [t["function"]["name"] for t in tools]
            tools = [
                t for t, n in zip(tools, names, strict=True)
                if not n.startswith("generate_") or n in wanted
            ]  # fmt: skip
        steps = 0
        for steps in range(1, self.t_max + 1):
            deadline.check()
            choice = None
            if steps == 1 and spec is not None and len(spec.structures) == 1 and start is None:
                name = f"generate_{spec.structures[0].shape}"
                if name in self.registry:  # begin with the generator the spec names
                    choice = {"type": "function", "function": {"name": name}}
            try:
                reply = self.model.chat(
                    messages, tools=tools, max_tokens=1024, role="designer", tool_choice=choice
                )
            except LLMError as exc:
                notes.append(str(exc))
                break
            if reply.tool_calls:
                messages.append(reply.as_message())
                for call in reply.tool_calls:
                    result = self.registry.dispatch(call.name, call.arguments)
                    if result.status == "failure":
                        self.model.usage.malformed += int(call.name not in self.registry)
                    produced = result.data.get("layout")
                    if produced is not None:
                        with contextlib.suppress(InputError):
                            candidate = _layout_from(produced, self.cell)
                    text = result.to_json()
                    if len(text) > MAX_TOOL_RESULT:
                        text = text[:MAX_TOOL_RESULT] + f"... (cut; {len(text)} characters)"
                    messages.append({"role": "tool", "tool_call_id": call.id, "content": text})
                continue
            try:
                layout = _layout_from(parse_json(reply.content), self.cell)
                break
            except (ValueError, ValidationError, InputError) as exc:
                self.model.usage.malformed += 1
                notes.append(f"step {steps}: no layout in the reply ({exc})")
                messages.append(reply.as_message())
                messages.append({"role": "user", "content": "Output final JSON: the layout only."})
        if layout is None and candidate is not None:
            notes.append("used the last layout a tool produced")
            layout = candidate
        return safety_gate(layout, self.cell, steps, notes)
