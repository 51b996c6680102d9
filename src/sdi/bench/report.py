"""An evaluation run as one call: which jobs the suites, methods and seeds make, and what each
suite's report holds (JSON, Markdown table, PNG chart) once the sweep is done.

Default methods: the plain pipeline on ``commands`` (today's `sdi bench`), the paper's four
columns (Rule, PGE, LG, Hyb) on ``human-mods`` and ``failures``; ``motion`` is the pipeline and
the cell, so methods do not apply to it.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from sdi.bench.cases import PAPER_METHODS, CaseResult, RunConfig
from sdi.bench.runner import CommandRecord, SuiteResult
from sdi.bench.scenarios import SUITES, load
from sdi.bench.sweep import Job, code_key
from sdi.bench.tables import markdown, summarise
from sdi.orchestrator.methods import METHODS


def resolve_suites(name: str) -> list[str]:
    """``all`` or one suite name → the suites to run; ValueError naming the choices."""
    if name == "all":
        return list(SUITES)
    if name not in SUITES:
        raise ValueError(f"unknown suite {name!r}; choose from {[*SUITES, 'all']}")
    return [name]


PIPELINE = "pipeline"
"""The method name of the plain pipeline (`sdi.pipeline.plan`, no orchestrator)."""


def resolve_methods(names: Sequence[str] | None) -> list[str | None] | None:
    """``all`` → every method, ``paper`` → the four of Tables IV/V, ``pipeline`` → None (the
    plain pipeline); unknown names refused."""
    if not names:
        return None
    out: list[str | None] = []
    for name in names:
        expanded: list[str | None]
        if name == PIPELINE:
            expanded = [None]
        elif name in ("all", "paper"):
            expanded = list(METHODS) if name == "all" else list(PAPER_METHODS)
        elif name in METHODS:
            expanded = [name]
        else:
            choices = [PIPELINE, *METHODS, "paper", "all"]
            raise ValueError(f"unknown method {name!r}; choose from {choices}")
        out += [m for m in expanded if m not in out]
    return out


def plan_jobs(
    suites: Sequence[str],
    methods: Sequence[str | None] | None,
    seeds: int,
    only: Sequence[str] | None = None,
) -> list[Job]:
    """Every (case, method, seed) of the suites; `only` keeps the named case ids. The plain
    pipeline has no review or recovery, so it is not run on human-mods and failures."""
    jobs = []
    for suite in suites:
        ms: list[str | None]
        if suite == "motion":
            ms = [None]
        elif suite == "commands":
            ms = list(methods) if methods else [None]
        else:
            ms = [m for m in methods or PAPER_METHODS if m is not None] or list(PAPER_METHODS)
        for case in load(suite):
            if only and case.id not in only:
                continue
            for m in ms:
                for seed in range(seeds):
                    jobs.append(Job(suite, case, m, seed))
    return jobs


def suite_json(
    suite: str, results: Sequence[CaseResult], config: RunConfig, seeds: int
) -> dict[str, Any]:
    """The suite's report: settings, its table's summary, every result. For the commands run
    through the plain pipeline it also carries `SuiteResult`'s keys (overall, groups,
    commands), as `sdi bench` always wrote them."""
    data: dict[str, Any] = {
        "suite": suite,
        "backend": config.backend,
        "seeds": seeds,
        "physics": config.physics,
        "phase_seconds": config.phase_seconds,
        "code": code_key(),
        "summary": summarise(suite, results),
        "results": [r.model_dump(mode="json") for r in results],
    }
    if suite == "commands":
        plain = [r for r in results if r.method is None and r.outcome == "done" and r.seed == 0]
        if plain:
            names = CommandRecord.__dataclass_fields__
            records = tuple(
                CommandRecord(**{k: v for k, v in r.fields.items() if k in names}) for r in plain
            )
            data |= SuiteResult(records=records).to_json_dict()
    return data


def suite_markdown(suite: str, data: dict[str, Any]) -> str:
    return markdown(suite, data["summary"])
