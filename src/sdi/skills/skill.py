"""A skill ξ = (name, description, JSON Schema Θ, function) returning (status, data, errors).

Paper §III-B, eq. 8. Inputs are a pydantic model, so the JSON Schema the LLM sees and the
validation the registry runs come from one definition.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Generic, Literal, TypeVar

from pydantic import BaseModel, ConfigDict, Field

SkillStatus = Literal["success", "failure", "partial"]
P = TypeVar("P", bound=BaseModel)


class SkillResult(BaseModel):
    """r ∈ R = {success, failure, partial} × D × 2^Σ*, serialised as JSON for a `tool` message."""

    model_config = ConfigDict(frozen=True)

    status: SkillStatus
    data: dict[str, Any] = Field(default_factory=dict)
    errors: tuple[str, ...] = ()

    @classmethod
    def ok(cls, **data: Any) -> SkillResult:
        return cls(status="success", data=data)

    @classmethod
    def fail(cls, *errors: str, **data: Any) -> SkillResult:
        return cls(status="failure", data=data, errors=errors)

    def to_json(self) -> str:
        return json.dumps(self.model_dump(mode="json"), separators=(",", ":"))


@dataclass(frozen=True)
class Skill(Generic[P]):
    name: str
    description: str
    params: type[P]
    run: Callable[[P], SkillResult]

    def schema(self) -> dict[str, Any]:
        """The input JSON Schema Θ (pydantic's, with the title noise removed)."""
        schema = self.params.model_json_schema()
        schema.pop("title", None)
        return schema

    def tool(self) -> dict[str, Any]:
        """OpenAI function-calling tool definition."""
        return {
            "type": "function",
            "function": {
                "name": self.name,
                "description": self.description,
                "parameters": self.schema(),
            },
        }
