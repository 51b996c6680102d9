"""The safety gate between planning and robots: a `VerifiedJob` exists only if V(C, K) passed.

`VerifiedJob.inspect` is the only way to make one: it runs the Inspector on the layout and
sequence and refuses anything that fails. Drivers and exporters accept nothing else, and
check the job again before moving (a cheap re-verification guards against a job assembled by
hand with `object.__new__` or altered after inspection).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from sdi.errors import UnverifiedPlanError
from sdi.inspector.verifier import Report, verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout

_TOKEN = object()


@dataclass(frozen=True)
class VerifiedJob:
    layout: Layout
    sequence: tuple[str, ...]
    cell: CellConfig
    report: Report
    _token: object = None

    def __post_init__(self) -> None:
        if self._token is not _TOKEN:
            raise UnverifiedPlanError("a VerifiedJob is made only by VerifiedJob.inspect(...)")

    @classmethod
    def inspect(
        cls, layout: Layout, cell: CellConfig | None = None, sequence: Sequence[str] | None = None
    ) -> VerifiedJob:
        """Run the Inspector; a job comes back only if every constraint passed."""
        cell = cell or CellConfig()
        report = verify(layout, cell, sequence=sequence)
        if not report.passed or report.sequence is None:
            raise UnverifiedPlanError(
                f"refused: the layout breaks {len(report.violations)} constraint(s); "
                "nothing moves until the Inspector passes it",
                violations=[f"{v.constraint.value}: {v.message}" for v in report.violations[:10]],
            )
        return cls(layout, tuple(report.sequence), cell, report, _TOKEN)

    def recheck(self) -> None:
        """Verify again (drivers call this before any motion)."""
        report = verify(self.layout, self.cell, sequence=self.sequence)
        if not report.passed:
            raise UnverifiedPlanError(
                "refused: the job no longer passes the Inspector",
                violations=[f"{v.constraint.value}: {v.message}" for v in report.violations[:10]],
            )
