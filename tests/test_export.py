"""Robot programs: RAPID modules and the abb-motion-program-exec Python program, offline."""

from __future__ import annotations

import math
import random
import re

import numpy as np
import pytest

from rapid_replay import check_order, rapidchecker_errors, simulate
from sdi.commission import commission
from sdi.design import compose
from sdi.export import confdata, interlock_plan, python_program, rapid_module
from sdi.export.rapid import SIGNALS
from sdi.robot import fk
from sdi.spec import Spec, structure
from sdi.tasks.generator import steps_conflict

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def plan():
    layout = compose(
        Spec(
            structures=(
                structure("tower", height=2, at_x=0.3),
                structure("tower", height=2, at_x=0.7),
            )
        )
    )
    return commission(layout)


ROBTARGET = re.compile(
    r"CONST robtarget (\w+) := \[\[([-\d.,]+)\],\[([-\d.,]+)\],\[(-?\d+),(-?\d+),(-?\d+),(-?\d+)\],"
)


def test_rapid_module_structure_and_targets(plan):
    for name, robot in plan.robots.items():
        steps = plan.tasks.for_robot(name)
        assert steps, name
        text = rapid_module(plan.job, plan.tasks, plan.motion, robot)
        assert text.startswith(f"MODULE SDI_{name.upper()}") and text.rstrip().endswith("ENDMODULE")
        assert "PROC main()" in text and "ENDPROC" in text
        assert re.search(r"PERS tooldata t\w+ := \[TRUE,\[\[", text)
        targets = {m.group(1): m for m in ROBTARGET.finditer(text)}
        assert len(targets) == 6 * len(steps)
        gripper = SIGNALS[robot.tool.kind]
        assert text.count(f"SetDO {gripper},") == 2 * len(steps)
        assert text.count("WaitTime") == 2 * len(steps)
        assert text.count("MoveL") == 4 * len(steps)
        for step in steps:
            p = f"p{step.step + 1}"
            for where, wps in (("pick", step.pick), ("place", step.place)):
                for w in wps:
                    m = targets[f"{p}_{where}_{w.name}"]
                    mm = np.array([float(v) for v in m.group(2).split(",")])
                    T = np.linalg.inv(robot.T_world_base) @ fk(robot, w.q)
                    assert np.allclose(mm, T[:3, 3] * 1000, atol=0.01)  # base frame, mm
                    quat = np.array([float(v) for v in m.group(3).split(",")])
                    assert math.isclose(float(np.linalg.norm(quat)), 1.0, abs_tol=1e-3)
                    assert tuple(int(m.group(k)) for k in range(4, 8)) == confdata(w.q)
            # the place grasp puts the part at its design pose
            T_part = fk(robot, step.place[1].q) @ step.T_tcp_part
            assert np.allclose(T_part[:3, 3], step.T_world_part_target[:3, 3], atol=1e-6)


def test_python_program_builds_offline(plan, tmp_path):
    source = python_program(plan.job, plan.tasks, plan.motion, plan.robots, command="two towers")
    path = tmp_path / "program.py"
    path.write_text(source)
    namespace: dict[str, object] = {"__name__": "sdi_program"}
    exec(compile(source, str(path), "exec"), namespace)  # builds with the real library, no robot
    build = namespace["build_programs"]
    for name in plan.robots:
        programs = build(name)  # type: ignore[operator]
        n = len(plan.tasks.for_robot(name))
        assert len(programs) == 3 * n + 1  # home, then per step: to grasp, to place, home
        signal = SIGNALS[plan.robots[name].tool.kind]
        assert [io for _, io in programs] == [None] + [(signal, 1), (signal, 0), None] * n
        rapid = "\n".join(mp.get_program_rapid() for mp, _ in programs)
        assert rapid.count("MoveL") == 4 * n
        assert "MoveAbsJ" in rapid


class _Replayed:
    def __init__(self, plan):
        self.tasks, self.plan = plan.tasks, plan

    def exclusive(self, later: int, earlier: int) -> bool:
        a, b = self.tasks.steps[later], self.tasks.steps[earlier]
        if a.robot == b.robot:
            return False
        return not self.plan.parallel or steps_conflict(a, b, self.plan.robots)


def test_commissioned_modules_replay_in_order_and_pass_rapidchecker(plan):
    interlocks = interlock_plan(
        plan.tasks, plan.robots, parallel=plan.parallel, signals=plan.job.cell.interlocks
    )
    modules = {
        name: rapid_module(plan.job, plan.tasks, plan.motion, robot, interlocks=interlocks)
        for name, robot in plan.robots.items()
    }
    for name, text in modules.items():
        assert rapidchecker_errors(text) == [], name
        # the conservative default (no schedule given): one arm at a time, still valid RAPID
        assert (
            rapidchecker_errors(rapid_module(plan.job, plan.tasks, plan.motion, plan.robots[name]))
            == []
        )
    for seed in range(5):
        run = simulate(
            modules, plan.job.cell.interlocks, len(plan.tasks.steps), random.Random(seed)
        )
        check_order(_Replayed(plan), run)


def test_confdata_quadrants():
    q = np.array([0.1, 0.0, 0.0, -0.1, 0.5, 3.5])
    assert confdata(q)[:3] == (0, -1, 2)
    assert confdata(np.array([0, 0, 0, 0, -0.2, 0]))[3] == 1
