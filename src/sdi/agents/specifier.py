"""ξ_spec, the Specifier: command → structured spec l̂ under a JSON Schema (paper §III-B).

With a model: one structured-output call (system prompt + schema), validated with pydantic.
The rule-based grammar parses the same command as a cross-check: where it understands the
command and the model's spec names different structures, the grammar's reading wins (small
models drift); where the model's output is malformed, the grammar is the fallback. Without a
model (`rules` backend) the grammar alone is the Specifier.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from pydantic import ValidationError

from sdi.agents.prompts import SPEC_PROMPT
from sdi.errors import SpecError
from sdi.llm.chat import ChatModel
from sdi.llm.openai_backend import LLMError, parse_json
from sdi.model.cell import CellConfig
from sdi.spec.grammar import parse_command
from sdi.spec.structure_spec import Spec


@dataclass
class SpecResult:
    spec: Spec
    source: str  # "rules" | "llm" | "rules (llm malformed)" | "rules (llm disagreed)"
    notes: list[str] = field(default_factory=list)


class Specifier:
    def __init__(self, model: ChatModel | None, cell: CellConfig | None = None) -> None:
        self.model = model
        self.cell = cell or CellConfig()

    def specify(self, command: str) -> SpecResult:
        rules: Spec | None = None
        rules_error: SpecError | None = None
        try:
            rules = parse_command(command, self.cell)
        except SpecError as exc:
            rules_error = exc
        if self.model is None:
            if rules is None:
                assert rules_error is not None
                raise rules_error
            return SpecResult(rules, "rules")
        try:
            reply = self.model.chat(
                [{"role": "system", "content": SPEC_PROMPT}, {"role": "user", "content": command}],
                json_schema=Spec.model_json_schema(),
                max_tokens=600,
                role="specifier",
            )
            llm_spec = Spec.model_validate(parse_json(reply.content))
        except (ValueError, ValidationError, LLMError) as exc:
            if not isinstance(exc, LLMError):
                self.model.usage.malformed += 1
            if rules is None:
                raise SpecError(
                    f"neither the model nor the grammar understood the command ({exc})",
                    understood=rules_error.understood if rules_error else {},
                ) from None
            return SpecResult(
                rules,
                "rules (llm malformed)",
                [f"the model's reply was unusable ({_why(exc)}); used the grammar"],
            )
        if rules is not None and sorted(s.shape for s in rules.structures) != sorted(
            s.shape for s in llm_spec.structures
        ):
            return SpecResult(
                rules,
                "rules (llm disagreed)",
                [
                    f"model read {llm_spec.describe()!r}, grammar read {rules.describe()!r}; "
                    "used the grammar"
                ],
            )
        return SpecResult(llm_spec, "llm")


def _why(exc: Exception) -> str:
    """A short reason for a fallback note: what was wrong with the model's reply."""
    if isinstance(exc, LLMError):
        return exc.reason
    if isinstance(exc, ValidationError):
        return f"not a valid spec: {exc.error_count()} validation error(s)"
    return f"not a JSON spec: {str(exc)[:80]}"


__all__ = ["SpecResult", "Specifier"]
