"""The skill registry Ξ: Tools(Ξ) for the LLM and Dispatch(Ξ, name, args) for its calls.

Dispatch never raises for the caller's mistakes: an unknown tool, arguments that are not JSON
or do not match the schema, or a skill that fails all come back as a `failure` result with a
message the model can act on.
"""

from __future__ import annotations

import json
import logging
from typing import Any

from pydantic import BaseModel, ValidationError

from sdi.errors import SDIError
from sdi.skills.skill import Skill, SkillResult

log = logging.getLogger(__name__)

MAX_ARGUMENT_CHARS = 1_000_000


class SkillRegistry:
    def __init__(self, skills: list[Skill[Any]] | None = None) -> None:
        self._skills: dict[str, Skill[Any]] = {}
        for skill in skills or []:
            self.register(skill)

    def register(self, skill: Skill[Any]) -> None:
        if skill.name in self._skills:
            raise ValueError(f"a skill named {skill.name!r} is already registered")
        self._skills[skill.name] = skill

    def __contains__(self, name: object) -> bool:
        return name in self._skills

    def __getitem__(self, name: str) -> Skill[Any]:
        return self._skills[name]

    @property
    def names(self) -> list[str]:
        return list(self._skills)

    def subset(self, names: list[str]) -> SkillRegistry:
        """A registry with only `names` (e.g. the one composite verifier of SASS)."""
        missing = [n for n in names if n not in self._skills]
        if missing:
            raise KeyError(f"unknown skills {missing}; known: {self.names}")
        return SkillRegistry([self._skills[n] for n in names])

    def tools(self) -> list[dict[str, Any]]:
        """Tools(Ξ): every skill as an OpenAI function-calling tool."""
        return [skill.tool() for skill in self._skills.values()]

    def dispatch(self, name: str, arguments: str | dict[str, Any] | None) -> SkillResult:
        """Dispatch(Ξ, n, a) = f_ξ(a), validating `a` against ξ's schema first."""
        skill = self._skills.get(name)
        if skill is None:
            return SkillResult.fail(
                f"unknown tool {name!r}; available tools: {', '.join(self.names)}"
            )
        if arguments is None or arguments == "":
            arguments = {}
        if isinstance(arguments, str):
            if len(arguments) > MAX_ARGUMENT_CHARS:
                return SkillResult.fail(
                    f"arguments of {len(arguments)} characters exceed {MAX_ARGUMENT_CHARS}"
                )
            try:
                arguments = json.loads(arguments)
            except json.JSONDecodeError as exc:
                return SkillResult.fail(f"arguments are not valid JSON: {exc.msg} at {exc.pos}")
        if not isinstance(arguments, dict):
            return SkillResult.fail("arguments must be a JSON object")
        try:
            params: BaseModel = skill.params.model_validate(arguments)
        except ValidationError as exc:
            problems = [
                f"{'.'.join(str(x) for x in e['loc']) or '(arguments)'}: {e['msg']}"
                for e in exc.errors()[:5]
            ]
            return SkillResult.fail(*problems)
        try:
            return skill.run(params)
        except SDIError as exc:
            return SkillResult.fail(str(exc))
        except Exception as exc:  # a skill bug must not kill the agent loop
            log.exception("skill %s crashed", name)
            return SkillResult.fail(f"internal error in {name}: {type(exc).__name__}: {exc}")
