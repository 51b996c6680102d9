"""The scenario suites as data: Table IV's human modifications, Table V's injected failures
and Table VI's motion commands, read from the TOML files in `sdi/bench/suites/` into typed
models (a mistake in a file fails on load, naming the case).

The 70-command evaluation suite (Tables II/III) stays in `sdi.bench.suite`: its acceptance
predicates combine alternatives and compound structures that are code; `COMMANDS` wraps it
in the same `Case` interface as the data suites.
"""

from __future__ import annotations

import tomllib
from functools import cache
from importlib import resources
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field, field_validator

from sdi.bench import shape_checks
from sdi.bench.suite import SUITE
from sdi.execute.faults import SCENARIOS

SUITES: tuple[str, ...] = ("commands", "human-mods", "failures", "motion")
"""Suite names, in the order `--suite all` runs them."""


class _Case(BaseModel):
    model_config = ConfigDict(frozen=True, extra="forbid")

    id: str
    command: str

    @property
    def label(self) -> str:
        return self.command


class _Shaped(_Case):
    shape: tuple[tuple[Any, ...], ...]
    """The command's structure signature (`sdi.bench.shape_checks`)."""

    @field_validator("shape")
    @classmethod
    def _valid(cls, v: tuple[tuple[Any, ...], ...]) -> tuple[tuple[Any, ...], ...]:
        shape_checks.signature(v)  # fails on an unknown check or bad arguments
        return v


class CommandCase(_Case):
    """One of the 70 evaluation commands (predicate in `sdi.bench.suite`)."""

    group: str


class HumanMod(_Shaped):
    """An invalid edit the operator makes at the design review (Table IV)."""

    name: str
    type: Literal["WS", "Col", "Grav", "Seq"]
    paper_steps: int = Field(gt=0)
    steps_note: str | None = None
    edits: tuple[dict[str, Any], ...] = Field(min_length=1)

    @property
    def label(self) -> str:
        return self.name


class FailureCase(_Shaped):
    """A command run with an injected failure scenario (Table V)."""

    scenario: str
    name: str
    error: str

    @field_validator("scenario")
    @classmethod
    def _known(cls, v: str) -> str:
        if v not in SCENARIOS:
            raise ValueError(f"unknown scenario {v!r}; choose from {sorted(SCENARIOS)}")
        return v

    @property
    def label(self) -> str:
        return self.name


class MotionCase(_Case):
    """A command planned, motion-planned and executed on the cell (Table VI)."""

    category: str
    mode: Literal["single", "dual"]
    extra: bool = False


Case = CommandCase | HumanMod | FailureCase | MotionCase


def _load(name: str, model: type[_Case]) -> tuple[Any, ...]:
    text = resources.files("sdi.bench").joinpath("suites", name).read_text(encoding="utf-8")
    rows = tomllib.loads(text).get("case", [])
    out = []
    for k, row in enumerate(rows):
        try:
            out.append(model.model_validate(row))
        except ValueError as exc:
            raise ValueError(f"suites/{name}: case {k + 1} ({row.get('id')}): {exc}") from None
    ids = [c.id for c in out]
    if len(set(ids)) != len(ids):
        raise ValueError(f"suites/{name}: duplicate case ids")
    return tuple(out)


@cache
def load(suite: str) -> tuple[Case, ...]:
    """The cases of `suite` (one of `SUITES`)."""
    if suite == "commands":
        return tuple(CommandCase(id=c.id, command=c.text, group=c.group) for c in SUITE)
    if suite == "human-mods":
        return _load("human_mods.toml", HumanMod)
    if suite == "failures":
        return _load("failures.toml", FailureCase)
    if suite == "motion":
        return _load("motion.toml", MotionCase)
    raise ValueError(f"unknown suite {suite!r}; choose from {[*SUITES, 'all']}")
