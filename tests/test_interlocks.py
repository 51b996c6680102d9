"""Exported programs keep the schedule's order across the two controllers.

The RAPID modules of both robots are run by a small interpreter of what they emit (`MoveAbsJ`,
`MoveJ`, `MoveL`, `WaitTime`, `SetDO`, `WaitDI`, procedure calls) as two concurrent processes in
a discrete-event simulation, with the controllers' done/ready outputs wired to the other's
inputs as the cell's `[interlocks]` names them, random motion durations and start offsets, from
clear I/O and from the I/O a finished run leaves. Every run must finish (no deadlock), no step
may start before the steps it depends on (its supports) are placed, and no two steps that share
space (the scheduler's own conflict test, or every pair once the job fell back to one arm at a
time) may overlap. The Python program's coordinator runs against two fake controllers with the
same checks. `rapidchecker` (a RAPID grammar checker by others) accepts every module.
"""

from __future__ import annotations

import random
import re
import threading
import time
from dataclasses import dataclass

import pytest

from rapid_replay import Run, check_order, rapidchecker_errors, simulate, supports
from sdi.errors import InputError
from sdi.execute.job import VerifiedJob
from sdi.export import interlock_plan, python_program, rapid_module
from sdi.model.cell import CellConfig, Interlocks
from sdi.motion.planner import MotionPlan
from sdi.pipeline import plan as plan_command
from sdi.robot import robots_for
from sdi.tasks.generator import TaskGenerator, steps_conflict
from sdi.tasks.task import TaskPlan

COMMANDS = [
    "a bridge at x = 0.35",
    "a tower of 3 at x = 0.3 and a tower of 3 at x = 0.7",  # Table VI, dual-arm
    "a row of 3 at x = 0.3 and a row of 3 at x = 0.7",  # Table VI, dual-arm
    "a 2 by 2 grid at x = 0.3 and a tower of 2 at x = 0.7",  # Table VI, dual-arm: grid + tower
]


@dataclass
class Job:
    cell: CellConfig
    job: VerifiedJob
    tasks: TaskPlan
    parallel: bool

    def modules(self, signals: Interlocks | None = None) -> dict[str, str]:
        robots = robots_for(self.cell)
        interlocks = interlock_plan(
            self.tasks,
            robots,
            parallel=self.parallel,
            signals=signals or self.cell.interlocks,
        )
        motion = MotionPlan({})  # no via points: the interlocks do not depend on them
        return {
            name: rapid_module(self.job, self.tasks, motion, robots[name], interlocks=interlocks)
            for name in self.tasks.robots
            if self.tasks.for_robot(name)
        }

    def exclusive(self, later: int, earlier: int) -> bool:
        a, b = self.tasks.steps[later], self.tasks.steps[earlier]
        if a.robot == b.robot:
            return False
        return not self.parallel or steps_conflict(a, b, robots_for(self.cell))


def make_job(command: str, cell: CellConfig | None = None, *, parallel: bool = True) -> Job:
    cell = cell or CellConfig()
    result = plan_command(command, cell)
    assert result.layout is not None and result.sequence is not None, result.error
    job = VerifiedJob.inspect(result.layout, cell, result.sequence)
    tasks, _ = TaskGenerator(cell).generate(job)
    return Job(cell, job, tasks, parallel)


@pytest.fixture(scope="module")
def jobs() -> dict[str, Job]:
    return {c: make_job(c) for c in COMMANDS}


def replay(job: Job, seeds: range = range(12)) -> None:
    modules = job.modules()
    n = len(job.tasks.steps)
    for seed in seeds:
        rng = random.Random(seed)
        first = simulate(modules, job.cell.interlocks, n, rng)
        check_order(job, first)
        # again, from the I/O the finished run left on the controllers
        check_order(job, simulate(modules, job.cell.interlocks, n, rng, first.io))


# -- tests --------------------------------------------------------------------------------------


@pytest.mark.parametrize("command", COMMANDS)
def test_rapid_modules_keep_the_schedule_order(jobs, command):
    job = jobs[command]
    assert len({s.robot for s in job.tasks.steps}) == 2, "a dual-arm job"
    replay(job)


def test_the_bridge_waits_for_the_second_pillar(jobs):
    job = jobs["a bridge at x = 0.35"]
    beam = next(s for s in job.tasks.steps if s.part_id.startswith("b"))
    assert len(supports(job.tasks)[beam.step]) == 2, "the beam rests on two pillars"
    pillars = [d for d in supports(job.tasks)[beam.step] if job.tasks.steps[d].robot != beam.robot]
    assert pillars, "the other arm places a pillar under the beam"
    modules = job.modules()
    text = modules[beam.robot]
    before_beam = text[text.index(f"! step {beam.step + 1}:") :].splitlines()[1]
    assert before_beam.strip().startswith("WaitDI diSDI_")
    # without interlocks the replay finds the fault the issue describes
    off = job.cell.interlocks.model_copy(update={"enabled": False})
    early = 0
    for seed in range(30):
        run = simulate(job.modules(off), job.cell.interlocks, 5, random.Random(seed))
        early += any(run.start[beam.step] < run.released[d] for d in pillars)
        with pytest.raises(AssertionError):
            check_order(job, run)
    assert early, "the beam goes down before the other arm's pillar in some run"


def test_one_arm_at_a_time_serialises_every_step(jobs):
    job = jobs["a tower of 3 at x = 0.3 and a tower of 3 at x = 0.7"]
    serial = Job(job.cell, job.job, job.tasks, parallel=False)
    replay(serial, range(6))
    # the towers are far apart: in parallel, the arms do not wait for each other at all
    assert "WaitDI" not in "".join(job.modules().values())


def test_signal_names_come_from_the_cell(jobs):
    base = jobs["a bridge at x = 0.35"]
    signals = Interlocks(
        done_output="DO_{robot}_S{step}",
        done_input="DI_{robot}_S{step}",
        ready_output="DO_{robot}_Rdy",
        ready_input="DI_{robot}_Rdy",
    )
    cell = base.cell.model_copy(update={"interlocks": signals})
    job = Job(cell, VerifiedJob.inspect(base.job.layout, cell, base.job.sequence), base.tasks, True)
    modules = job.modules()
    assert "SetDO DO_irb1600_S2, 1;" in modules["irb1600"]
    assert "WaitDI DI_irb1600_S2, 1;" in modules["irb120"]
    assert "WaitDI DI_irb120_Rdy, 1;" in modules["irb1600"]
    rng = random.Random(1)
    check_order(job, simulate(modules, signals, len(job.tasks.steps), rng))


@pytest.mark.parametrize(
    ("toml", "message"),
    [
        ('[interlocks]\ndone_output = "doDone{step}"\n', "placeholders {robot}, {step}"),
        ('[interlocks]\nready_input = "di{robot}{step}"\n', "placeholders {robot}"),
        ('[interlocks]\ndone_input = "1di{robot}{step}"\n', "not a RAPID signal name"),
        ('[interlocks]\ndone_input = "doSDI_{robot}_Done{step}"\n', "four different"),
        ('[interlocks]\nwait_input = "x"\n', "interlocks.wait_input"),
        (
            '[[robots]]\nname = "irb-120"\nmodel = "irb120"\nbase_xy = [0.0, 0.3]\n'
            '[[robots]]\nname = "b"\nmodel = "irb1600"\nbase_xy = [1.3, 0.3]\n',
            "'doSDI_irb-120_Done99999' is not a RAPID signal name",
        ),
        (
            '[interlocks]\ndone_output = "doSDI_{robot}_Done_of_pick_and_place_{step}"\n',
            "at most 32 characters",
        ),
    ],
)
def test_interlock_names_are_validated(tmp_path, toml, message):
    path = tmp_path / "cell.toml"
    path.write_text(toml)
    with pytest.raises(InputError, match=re.escape(message)):
        CellConfig.load(path)


def test_interlocks_section_loads(tmp_path):
    path = tmp_path / "cell.toml"
    path.write_text('[interlocks]\ndone_output = "do{robot}Step{step}"\nenabled = true\n')
    cell = CellConfig.load(path)
    assert cell.interlocks.signal("done_output", "irb120", 3) == "doirb120Step3"
    assert cell.interlocks.signal("done_input", "irb120", 3) == "diSDI_irb120_Done3"


@pytest.mark.parametrize("command", COMMANDS)
def test_rapidchecker_accepts_every_module(jobs, command):
    job = jobs[command]
    for parallel in (True, False):
        for name, text in Job(job.cell, job.job, job.tasks, parallel).modules().items():
            assert rapidchecker_errors(text) == [], (command, name)


def test_rapidchecker_is_a_real_check():
    text = "MODULE M\n    PROC main()\n      SetDO doX, 1;\n    ENDPROC\nENDMODULE\n"
    assert rapidchecker_errors(text)  # 6 spaces: bad indentation
    assert rapidchecker_errors("MODULE M\n    PROC main()\n        WaitDI x 1;\n    ENDPROC\n")


# -- the Python program's coordinator ----------------------------------------------------------


class FakeController:
    """A MotionProgramExecClient stand-in: each motion program takes a little while."""

    def __init__(self, name: str, rng: random.Random, calls: list, fail_at: int | None = None):
        self.name, self.rng, self.calls, self.fail_at = name, rng, calls, fail_at
        self.abb_client = self
        self.count = 0
        self.lock = threading.Lock()
        self.io: list[tuple[str, int]] = []
        self.io_at: list[float] = []

    def execute_motion_program(self, mp):
        self.count += 1
        if self.count == self.fail_at:
            raise ConnectionError("controller unreachable")
        t0 = time.perf_counter()
        time.sleep(self.rng.uniform(0.0, 0.004))
        self.calls.append((self.name, self.count - 1, t0, time.perf_counter()))

    def set_digital_io(self, signal, value):
        self.io.append((signal, value))
        self.io_at.append(time.perf_counter())


def program(job: Job) -> dict:
    robots = robots_for(job.cell)
    interlocks = interlock_plan(
        job.tasks, robots, parallel=job.parallel, signals=job.cell.interlocks
    )
    source = python_program(
        job.job, job.tasks, MotionPlan({}), robots, command="test", interlocks=interlocks
    )
    namespace: dict = {"__name__": "sdi_program"}
    exec(compile(source, "sdi_program.py", "exec"), namespace)
    return namespace


@pytest.mark.parametrize("command", COMMANDS)
def test_python_coordinator_keeps_the_order(jobs, command):
    pytest.importorskip("abb_motion_program_exec")
    job = jobs[command]
    ns = program(job)
    for seed in range(3):
        rng = random.Random(seed)
        calls: list = []
        clients = {n: FakeController(n, random.Random(rng.random()), calls) for n in ns["ROBOTS"]}
        ns["run"](clients, log=lambda _: None)
        run = Run()
        for name in clients:
            # segment index → step: one home move, then three segments per step
            numbers = [number for number, _, segs in ns["build_steps"](name) for _ in segs]
            for robot, index, t0, t1 in calls:
                if robot == name and numbers[index] is not None:
                    k = numbers[index] - 1
                    run.start.setdefault(k, t0)
                    run.end[k] = t1
            signal = ns["ROBOTS"][name]["signal"]
            mine = [s["number"] - 1 for s in ns["ROBOTS"][name]["steps"]]
            assert clients[name].io == [(signal, 1), (signal, 0)] * len(mine)
            for k, t in zip(mine, clients[name].io_at[1::2], strict=True):
                run.released[k] = t  # the gripper lets go
        check_order(job, run)


def test_python_coordinator_stops_both_robots_on_a_failure(jobs):
    pytest.importorskip("abb_motion_program_exec")
    job = jobs["a bridge at x = 0.35"]
    ns = program(job)
    calls: list = []
    clients = {
        "irb120": FakeController("irb120", random.Random(0), calls),
        "irb1600": FakeController("irb1600", random.Random(1), calls, fail_at=3),
    }
    with pytest.raises(RuntimeError, match="irb1600 stopped: controller unreachable"):
        ns["run"](clients, log=lambda _: None)
    # the IRB120 waits for the IRB1600's step 2 before its step 3: it never gets there
    assert clients["irb120"].count <= 4
    with pytest.raises(SystemExit, match="run them together"):
        ns["run"]({"irb120": clients["irb120"]}, log=lambda _: None)
