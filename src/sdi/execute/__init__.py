"""Execution: the safety-gated job, failure injection and the drivers (the Operator's side).

The simulation driver (PyBullet) is imported on first use, so planning alone never loads the
physics engine.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from sdi.execute.faults import SCENARIOS, FaultScenario
from sdi.execute.job import VerifiedJob

if TYPE_CHECKING:
    from sdi.execute.driver import Driver
    from sdi.execute.sim import ExecutionResult, SimDriver

__all__ = ["SCENARIOS", "Driver", "ExecutionResult", "FaultScenario", "SimDriver", "VerifiedJob"]


def __getattr__(name: str) -> Any:
    if name in ("SimDriver", "ExecutionResult"):
        from sdi.execute import sim

        return getattr(sim, name)
    if name == "Driver":
        from sdi.execute.driver import Driver

        return Driver
    raise AttributeError(name)
