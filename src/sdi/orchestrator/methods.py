"""The compared methods of the paper (Table II) as named configurations of the same parts.

A method fixes which Specifier runs (model or grammar), which Designer strategy, the
orchestration (none, rule-based, PGE, LangGraph routing, hybrid), whether the recovery skills
are used, and the critic (the symbolic Inspector, or an LLM in the ablation). With the `rules`
backend every neural part is replaced by its rule-based counterpart, so every method runs
offline, and the deterministic parts stay as they are.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Designer = Literal[
    "direct",
    "full-prompt",
    "fixed-loop",
    "adaptive-loop",
    "agentic-1",
    "agentic-8",
    "generator-first",
    "parametric",
]
Orchestration = Literal["none", "rule", "pge", "langgraph", "hybrid"]


@dataclass(frozen=True)
class Method:
    name: str
    specifier: bool  # use the (LLM) Specifier to expand the command
    designer: Designer
    orchestration: Orchestration
    recovery: bool  # flatten / shift before asking the Designer
    critic: Literal["symbolic", "llm"] = "symbolic"
    replans: int = 3
    description: str = ""


METHODS: dict[str, Method] = {
    m.name: m
    for m in (
        Method("LLM-Direct", False, "direct", "none", False, description="one pass"),
        Method(
            "LLM-FullPrompt",
            False,
            "full-prompt",
            "none",
            False,
            description="all of K in the prompt",
        ),
        Method(
            "LLM-FixedLoop",
            False,
            "fixed-loop",
            "none",
            False,
            description="retry with full feedback",
        ),
        Method(
            "LLM-AdaptLoop",
            False,
            "adaptive-loop",
            "none",
            False,
            description="retry with φ(E) (Alg. 2)",
        ),
        Method(
            "SASS", False, "agentic-1", "none", False, description="one agent, one composite skill"
        ),
        Method("SAMS", False, "agentic-8", "none", False, description="one agent, granular skills"),
        Method(
            "MultiAgent-RuleOrch",
            False,
            "adaptive-loop",
            "rule",
            False,
            description="if-else orchestration",
        ),
        Method(
            "PGEOrch",
            True,
            "adaptive-loop",
            "pge",
            False,
            description="Specifier-Designer-Inspector loop",
        ),
        Method(
            "LGOrch",
            False,
            "adaptive-loop",
            "langgraph",
            False,
            description="LangGraph routing, raw command",
        ),
        Method(
            "Hybrid",
            True,
            "generator-first",
            "hybrid",
            True,
            description="SDI + LangGraph + recovery skills; generator skills before the model",
        ),
        Method(
            "Hybrid-LLMCritic",
            True,
            "generator-first",
            "hybrid",
            True,
            "llm",
            description="ablation: LLM critic",
        ),
    )
}

SASS_SKILLS = ["verify"]
SAMS_SKILLS = [
    "verify", "check_workspace", "check_collision", "check_gravity", "check_gripping",
    "sequence", "generate", "shift",
]  # fmt: skip
