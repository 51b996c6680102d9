"""Execution: the safety-gated job, failure injection and the drivers (the Operator's side)."""

from sdi.execute.driver import Driver
from sdi.execute.faults import SCENARIOS, FaultScenario
from sdi.execute.job import VerifiedJob
from sdi.execute.sim import ExecutionResult, SimDriver

__all__ = ["SCENARIOS", "Driver", "ExecutionResult", "FaultScenario", "SimDriver", "VerifiedJob"]
