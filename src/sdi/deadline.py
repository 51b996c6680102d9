"""Wall-clock limits for the orchestrator's phases.

A phase (DESIGN, PRE_EXECUTE, …) runs under `phase_limit(name, seconds)`. Long work checks the
limit where it can stop cleanly — before every LLM call (whose own timeout is clipped to what
is left), every Designer iteration, every motion-planning step and every simulated second — and
raises `PhaseTimeout`, which the orchestrator turns into a failure report for the operator.
Outside a phase nothing is limited. A context variable, so nested calls need no extra argument.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar
from dataclasses import dataclass

from sdi.errors import SDIError


class PhaseTimeout(SDIError):
    """A phase ran past its wall-clock limit; `phase` and `limit_s` say which and how long."""

    def __init__(self, phase: str, limit_s: float) -> None:
        self.phase = phase
        self.limit_s = limit_s
        super().__init__(
            f"phase {phase} exceeded its wall-clock limit of {limit_s:g} s "
            "(raise [limits] phase_seconds in the cell config, or simplify the command)"
        )


@dataclass(frozen=True)
class _Limit:
    phase: str
    limit_s: float
    deadline: float


_CURRENT: ContextVar[_Limit | None] = ContextVar("sdi_phase_limit", default=None)


@contextmanager
def phase_limit(phase: str, seconds: float | None) -> Iterator[None]:
    """Run the body under a wall-clock limit (`None`: no limit)."""
    if seconds is None:
        yield
        return
    token = _CURRENT.set(_Limit(phase, seconds, time.monotonic() + seconds))
    try:
        yield
    finally:
        _CURRENT.reset(token)


def remaining() -> float | None:
    """Seconds left in the current phase, or None outside a limited phase."""
    limit = _CURRENT.get()
    return None if limit is None else limit.deadline - time.monotonic()


def check() -> None:
    """Raise `PhaseTimeout` if the current phase is over its limit."""
    limit = _CURRENT.get()
    if limit is not None and time.monotonic() > limit.deadline:
        raise PhaseTimeout(limit.phase, limit.limit_s)
