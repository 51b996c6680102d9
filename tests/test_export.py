"""Robot programs: RAPID modules and the abb-motion-program-exec Python program, offline."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from sdi.commission import commission
from sdi.design import compose
from sdi.export import confdata, python_program, rapid_module
from sdi.robot import fk
from sdi.spec import Spec, StructureSpec

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def plan():
    layout = compose(
        Spec(
            structures=(
                StructureSpec(shape="tower", height=2, at_x=0.3),
                StructureSpec(shape="tower", height=2, at_x=0.7),
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
        assert text.count("SetDO") == 2 * len(steps) and text.count("WaitTime") == 2 * len(steps)
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
        assert len(programs) == 2 * n + 1
        assert [io for _, io in programs[:-1]] == [("doVacuumOn", 1), ("doVacuumOn", 0)] * n or [
            io for _, io in programs[:-1]
        ] == [("doGripClose", 1), ("doGripClose", 0)] * n
        rapid = "\n".join(mp.get_program_rapid() for mp, _ in programs)
        assert rapid.count("MoveL") == 4 * n
        assert "MoveAbsJ" in rapid


def test_confdata_quadrants():
    q = np.array([0.1, 0.0, 0.0, -0.1, 0.5, 3.5])
    assert confdata(q)[:3] == (0, -1, 2)
    assert confdata(np.array([0, 0, 0, 0, -0.2, 0]))[3] == 1
