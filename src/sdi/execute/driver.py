"""The protocol every execution driver implements (simulation now; real controllers later).

A driver takes a `VerifiedJob` (the Inspector passed it), its task plan and Q_plan, executes,
streams Q_exec samples to an optional monitor (`update(robot, t, q) -> breach | None`, and
stops at the first breach), and reports an `ExecutionResult`: Q_exec, as-built poses and any
failure event. Drivers must call `job.admit(tasks)` before anything moves (an identity check
against what `VerifiedJob.inspect` passed; the verifier does not run again). `placed` (part id →
pose) continues an interrupted execution from what is already built; `progress` is told of
every part set down, so the run's event stream records what is built as it is built.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any, Protocol, runtime_checkable

from sdi.execute.job import VerifiedJob
from sdi.execute.sim import ExecutionResult
from sdi.motion.planner import MotionPlan
from sdi.tasks.task import TaskPlan


@runtime_checkable
class Driver(Protocol):
    name: str

    def execute(
        self,
        job: VerifiedJob,
        tasks: TaskPlan,
        motion: MotionPlan,
        *,
        monitor: object | None = None,
        placed: Mapping[str, Sequence[float]] | None = None,
        progress: Callable[[dict[str, Any]], None] | None = None,
    ) -> ExecutionResult: ...
