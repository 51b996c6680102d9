"""The one exception tree of SDI.

Every error names what is wrong (the field, the part id or the word), the bound it broke and
what to do about it. User mistakes are `InputError`s: the CLI prints their message and exits
with code 2, never a stack trace.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from sdi.inspector.verifier import Report
    from sdi.inspector.violation import Violation


class SDIError(Exception):
    """Root of every error SDI raises on purpose."""


class InputError(SDIError):
    """Bad input from a person or a program: malformed JSON, a bad value, an unknown field.

    `field` is the dotted path of the offending value (``objects[3].size``) when known.
    """

    def __init__(self, message: str, *, field: str | None = None) -> None:
        self.field = field
        super().__init__(f"{field}: {message}" if field else message)


class LimitError(InputError):
    """Input beyond an explicit, configurable limit (part count, text length, …)."""


class SpecError(SDIError):
    """The language front end could not turn a command into a structure specification.

    `understood` says what it did recognise so the operator can rephrase.
    """

    def __init__(self, message: str, *, understood: dict[str, object] | None = None) -> None:
        self.understood = understood or {}
        super().__init__(message)


class InfeasibleError(SDIError):
    """A generator or recovery skill cannot satisfy a parameter; `parameter` names it."""

    def __init__(self, message: str, *, parameter: str | None = None) -> None:
        self.parameter = parameter
        super().__init__(message)


class SequencingError(SDIError):
    """No assembly order exists; `blocked` lists the parts that could not be placed."""

    def __init__(self, message: str, *, blocked: list[str]) -> None:
        self.blocked = blocked
        super().__init__(message)


class UnverifiedPlanError(SDIError):
    """A layout or sequence that did not pass the Inspector was offered to the robot side.

    The safety gate: nothing reaches task generation, motion planning, a driver or an exporter
    unless `VerifiedJob.inspect` passed it. `violations` are the Inspector's `Violation`
    objects (constraint, parts, message, hint, suggestion); `report` is its whole answer
    when the Inspector ran (None for a refusal that is not the Inspector's, e.g. a forged job).
    """

    def __init__(
        self,
        message: str,
        *,
        violations: Sequence[Violation] = (),
        report: Report | None = None,
    ) -> None:
        self.violations: tuple[Violation, ...] = tuple(violations)
        self.report = report
        super().__init__(message)

    def violations_json(self) -> list[dict[str, object]]:
        """The violations as plain JSON objects (`Violation.to_json_dict`)."""
        return [v.to_json_dict() for v in self.violations]


class MotionPlanningError(SDIError):
    """No motion for a step. `event` is the failure event (step, part id, error type, pose)."""

    def __init__(self, message: str, *, event: object) -> None:
        self.event = event
        super().__init__(message)
