"""The safety gate between planning and robots: a `VerifiedJob` exists only if V(C, K) passed.

`VerifiedJob.inspect` is the only way to make one: it runs the Inspector on the layout and
sequence once and refuses anything that fails (`UnverifiedPlanError` carrying the Inspector's
`Violation` objects and report). The job is then the one value that flows downstream: task
generation, motion planning, the commissioning record, drivers and exporters take the job and
trust it — none of them runs the verifier again.

What they do instead is a cheap identity check (`check`, `admit`): the job's content hash
(cell, layout, sequence) must be one that `inspect` sealed in this process. A job assembled by
hand (`object.__new__`) with content the Inspector never passed, or a job whose layout, sequence
or cell was altered after inspection, hashes to something unsealed and is refused.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

from sdi.errors import UnverifiedPlanError
from sdi.execute.record import canonical, cell_hash, layout_hash, sha256
from sdi.inspector.verifier import Report, verify
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout

if TYPE_CHECKING:
    from sdi.tasks.task import TaskPlan

_TOKEN = object()
_SEALED: set[str] = set()
"""Content hashes of the jobs `inspect` passed in this process."""


def job_hash(cell_digest: str, layout_digest: str, sequence: Sequence[str]) -> str:
    """The identity of a verified job: the hashes of its cell and layout, and its sequence."""
    body = {"cell_hash": cell_digest, "layout_hash": layout_digest, "sequence": list(sequence)}
    return sha256(canonical(body))


@dataclass(frozen=True)
class VerifiedJob:
    layout: Layout
    sequence: tuple[str, ...]
    cell: CellConfig
    report: Report
    hash: str = ""
    _token: object = None

    def __post_init__(self) -> None:
        if self._token is not _TOKEN:
            raise UnverifiedPlanError("a VerifiedJob is made only by VerifiedJob.inspect(...)")

    @classmethod
    def inspect(
        cls, layout: Layout, cell: CellConfig | None = None, sequence: Sequence[str] | None = None
    ) -> VerifiedJob:
        """Run the Inspector (once); a job comes back only if every constraint passed."""
        cell = cell or CellConfig()
        report = verify(layout, cell, sequence=sequence)
        if not report.passed or report.sequence is None:
            raise UnverifiedPlanError(
                f"refused: the layout breaks {len(report.violations)} constraint(s); "
                "nothing moves until the Inspector passes it",
                violations=report.violations,
                report=report,
            )
        digest = job_hash(cell_hash(cell), layout_hash(layout), report.sequence)
        _SEALED.add(digest)
        return cls(layout, tuple(report.sequence), cell, report, digest, _TOKEN)

    def content_hash(self) -> str:
        """The hash of what the job holds now (equal to `hash` unless it was altered)."""
        return job_hash(cell_hash(self.cell), layout_hash(self.layout), self.sequence)

    def check(self) -> None:
        """The gate's identity check (no verifier run): this content passed `inspect`."""
        now = self.content_hash()
        if now != self.hash or now not in _SEALED:
            raise UnverifiedPlanError(
                f"refused: job {str(self.hash)[:12]} is not what the Inspector passed "
                f"(its content hashes to {now[:12]}); nothing moves — inspect it again"
            )

    def admit(self, tasks: TaskPlan) -> None:
        """`check`, and the task plan places exactly this job's parts in its order."""
        self.check()
        if [s.part_id for s in tasks.steps] != list(self.sequence):
            raise UnverifiedPlanError("refused: the task plan does not match the verified job")
