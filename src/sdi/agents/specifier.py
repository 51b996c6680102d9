"""ξ_spec, the Specifier: command → structured spec l̂ under a JSON Schema (paper §III-B).

With a model: one structured-output call (system prompt + schema), validated with pydantic.
The offline reader (`sdi.language`) reads the same command as a cross-check, slot by slot:
every value the reader took from the command's words (a count, a size, a coordinate, a
region) and every relation it found must be the same in the model's spec, matched structure
by structure; otherwise the reader's spec wins and the disagreement is reported — explicit
numbers in the command always beat a model's reading. The model's spec is used when it agrees
on all of those (it may add what the words left open). Where the model's output is
malformed, the reader is the fallback. Without a model (`rules` backend) the reader alone is
the Specifier.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from pydantic import ValidationError

from sdi.agents.prompts import SPEC_PROMPT
from sdi.errors import SpecError
from sdi.language import Reading, read
from sdi.llm.chat import ChatModel
from sdi.llm.openai_backend import LLMError, parse_json
from sdi.model.cell import CellConfig
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import Spec


@dataclass
class SpecResult:
    spec: Spec
    source: str  # "rules" | "llm" | "rules (llm malformed)" | "rules (llm disagreed)"
    notes: list[str] = field(default_factory=list)
    reading: Reading | None = None  # the grammar's reading of the command, when it had one


class Specifier:
    def __init__(self, model: ChatModel | None, cell: CellConfig | None = None) -> None:
        self.model = model
        self.cell = cell or CellConfig()

    def specify(self, command: str) -> SpecResult:
        rules: Spec | None = None
        reading: Reading | None = None
        rules_error: SpecError | None = None
        try:
            reading = read(command, self.cell)
            rules = reading.spec
        except SpecError as exc:
            rules_error = exc
        if self.model is None:
            if rules is None:
                assert rules_error is not None
                raise rules_error
            return SpecResult(rules, "rules", reading=reading)
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
                reading,
            )
        if rules is not None:
            conflict = disagreement(rules, llm_spec, stated_numbers(command))
            if conflict:
                return SpecResult(
                    rules,
                    "rules (llm disagreed)",
                    [
                        f"the model's reading disagrees with the command's words ({conflict}); "
                        f"used the grammar's: model read {llm_spec.describe()!r}, grammar read "
                        f"{rules.describe()!r}"
                    ],
                    reading,
                )
        return SpecResult(llm_spec, "llm")


def stated_numbers(command: str) -> set[float]:
    """The numbers written in `command`, in digits or words ("three" → 3)."""
    tokens = re.findall(r"\d+(?:\.\d+)?|[a-z]+", command.lower())
    out: set[float] = set()
    for t in words_to_numbers(tokens):
        try:
            out.add(float(t))
        except ValueError:
            continue
    return out


_PLACE = ("at_x", "at_y", "region", "edge", "axis", "dims", "part", "shape")


def disagreement(rules: Spec, model: Spec, stated: set[float] | None = None) -> str | None:
    """Where `model` contradicts what the grammar read from the words, or None.

    Structures are matched in order within each family; every field the grammar took from
    the words — a position, region, axis or part, or a count or size whose number is written
    in the command (`stated`; all numbers when None) — must have the same value in the
    model's structure, and the relations must be the same. Values the grammar chose for a
    vague word ("a very tall tower") are the model's to choose.
    """
    shapes = sorted(s.shape for s in rules.structures)
    if shapes != sorted(s.shape for s in model.structures):
        return f"structures {shapes} vs {sorted(s.shape for s in model.structures)}"
    theirs: dict[str, list[int]] = {}
    for k, s in enumerate(model.structures):
        theirs.setdefault(s.shape, []).append(k)
    mapping: dict[int, int] = {}
    for k, s in enumerate(rules.structures):
        j = theirs[s.shape].pop(0)
        mapping[k] = j
        said = s.model_dump(exclude_defaults=True)
        got = model.structures[j].model_dump()
        for key, value in said.items():
            explicit = (
                key in _PLACE
                or stated is None
                or (isinstance(value, int | float) and float(value) in stated)
            )
            if not explicit:
                continue
            if got.get(key) != value:
                return f"{s.shape} {key}: command says {value}, model says {got.get(key)}"
    mine = sorted((r.kind, mapping[r.subject], mapping[r.object], r.side) for r in rules.relations)
    other = sorted((r.kind, r.subject, r.object, r.side) for r in model.relations)
    if mine != other:
        return "relations between the structures differ"
    return None


def _why(exc: Exception) -> str:
    """A short reason for a fallback note: what was wrong with the model's reply."""
    if isinstance(exc, LLMError):
        return exc.reason
    if isinstance(exc, ValidationError):
        first = exc.errors()[0]
        where = ".".join(str(x) for x in first["loc"])
        return (
            f"not a valid spec: {exc.error_count()} validation error(s), first at {where}: "
            f"{first['msg']}"[:240]
        )
    return f"not a JSON spec: {str(exc)[:80]}"


__all__ = ["SpecResult", "Specifier", "disagreement"]
