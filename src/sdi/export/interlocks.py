"""Cross-robot interlocks: the schedule's order between two controllers, as waits on steps.

The two arms run on separate controllers, so each exported program must wait, before a step,
for every step of another robot that the schedule puts first and that this step needs:

- a *precedence*: a step it depends on (support, contact, grip keep-out: `PickPlace.depends_on`);
- a *shared-space exclusion*: a step of the other arm working in the same space
  (`steps_conflict`, the scheduler's own test). The list scheduler places conflicting steps in
  σ* order, one after the other, so the earlier step in σ* goes first.

When commissioning fell back to one arm at a time (`parallel` false: the arms could meet
anywhere), every pair of steps of different arms is exclusive. A step waits for the other
robot's step to be *done*: placed and back at home over its own supply, so the arm has left
the shared space. Waits are reduced per robot to the latest step it needs (each robot runs its
steps in order) and to what the robot has not already waited for.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from sdi.model.cell import Interlocks
from sdi.robot import RobotModel
from sdi.tasks.generator import steps_conflict
from sdi.tasks.task import PickPlace, TaskPlan


@dataclass(frozen=True)
class InterlockPlan:
    """Which steps wait for which (step indices from 0, as in the `TaskPlan`)."""

    robot_of: dict[int, str]
    waits: dict[int, tuple[int, ...]] = field(default_factory=dict)
    """Step → the other robots' steps that must be done before it starts (reduced)."""
    needs: dict[int, tuple[int, ...]] = field(default_factory=dict)
    """Step → every other robot's step it must not start before (unreduced, for checks)."""
    signals: Interlocks = field(default_factory=Interlocks)

    @property
    def active(self) -> bool:
        return self.signals.enabled and len(set(self.robot_of.values())) > 1 and bool(self.waits)

    def signalled(self, robot: str) -> list[int]:
        """Steps of `robot` after which it sets its done output (someone waits for them)."""
        waited = {d for ds in self.waits.values() for d in ds}
        return sorted(k for k in waited if self.robot_of[k] == robot)

    def peers(self, robot: str) -> list[str]:
        return sorted({r for r in self.robot_of.values() if r != robot})

    def done_output(self, step: int) -> str:
        return self.signals.signal("done_output", self.robot_of[step], step + 1)

    def done_input(self, step: int) -> str:
        return self.signals.signal("done_input", self.robot_of[step], step + 1)

    def inputs_of(self, robot: str) -> list[str]:
        """Every done input `robot` reads (its start check waits for them all to be 0)."""
        steps = sorted({d for k, ds in self.waits.items() if self.robot_of[k] == robot for d in ds})
        return [self.done_input(d) for d in steps]


def interlock_plan(
    tasks: TaskPlan,
    robots: Mapping[str, RobotModel],
    *,
    parallel: bool = True,
    signals: Interlocks | None = None,
) -> InterlockPlan:
    """The waits that keep `tasks`' schedule order across robots.

    `parallel` false (commissioning ran the arms one at a time) makes every pair of steps of
    different robots exclusive.
    """
    steps = sorted(tasks.steps, key=lambda s: s.step)
    robot_of = {s.step: s.robot for s in steps}
    by_step = {s.step: s for s in steps}

    def exclusive(later: PickPlace, earlier: PickPlace) -> bool:
        return not parallel or steps_conflict(later, earlier, robots)  # as the scheduler asks

    needs: dict[int, tuple[int, ...]] = {}
    waits: dict[int, tuple[int, ...]] = {}
    covered: dict[tuple[str, str], int] = {}  # (waiting robot, other robot) → latest step
    for s in steps:
        before = {int(d) for d in s.depends_on if robot_of[int(d)] != s.robot}
        before |= {
            o.step
            for o in steps
            if o.step < s.step and o.robot != s.robot and exclusive(s, by_step[o.step])
        }
        needs[s.step] = tuple(sorted(before))
        mine = []
        for other in sorted({robot_of[d] for d in before}):
            latest = max(d for d in before if robot_of[d] == other)
            if covered.get((s.robot, other), -1) < latest:
                covered[(s.robot, other)] = latest
                mine.append(latest)
        if mine:
            waits[s.step] = tuple(sorted(mine))
    return InterlockPlan(robot_of, waits, needs, signals or Interlocks())
