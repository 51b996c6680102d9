"""The evaluation suite: 70 plain-language commands in groups A–E, each with an acceptance
predicate built from geometry-only shape signatures, and a runner that scores the pipeline."""

from sdi.bench.runner import CommandRecord, GroupStats, SuiteResult, run_suite
from sdi.bench.suite import GROUPS, SUITE, BenchCommand, by_id

__all__ = [
    "GROUPS",
    "SUITE",
    "BenchCommand",
    "CommandRecord",
    "GroupStats",
    "SuiteResult",
    "by_id",
    "run_suite",
]
