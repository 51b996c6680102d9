"""Robot programs: an ABB RAPID module per robot, and a Python program per command.

Both replay the verified plan: free-space moves go through the planner's collision-checked
joint via points (`MoveAbsJ`, joint-interpolated like the planned segments), approaches are
`MoveJ` to a robtarget, descents, grasps and retreats are `MoveL` stop points, and the gripper
is switched with `SetDO` and given `WaitTime` for its 2 Hz Modbus I/O. Targets are in the
robot's base frame (wobj0), millimetres, quaternions w first, with the configuration data of
the planned joint solution. Only a `VerifiedJob` is exported. With two robots the modules
keep the schedule's order with digital I/O between the controllers (`WaitDI`/`SetDO`, signal
names from the cell's `[interlocks]`; see `sdi.export.interlocks`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from sdi.execute.job import VerifiedJob
from sdi.export.interlocks import InterlockPlan, interlock_plan
from sdi.motion.planner import MotionPlan
from sdi.robot import RobotModel
from sdi.tasks.generator import pose_tuple
from sdi.tasks.task import GRASP_SECONDS, PickPlace, TaskPlan

SIGNALS = {"vacuum": "doVacuumOn", "parallel": "doGripClose"}
"""Digital outputs that switch each gripper (configure them on the controller)."""
FREE_SPEED = "v500"
LINEAR_SPEED = "v100"


def _num(v: float) -> str:
    text = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def confdata(q: np.ndarray) -> tuple[int, int, int, int]:
    """ABB confdata [cf1, cf4, cf6, cfx] of a joint solution (rad).

    cf1, cf4, cf6 are the quadrants of axes 1, 4, 6; cfx encodes the arm configuration
    (0–7): +4 when the wrist centre is behind axis 1, +2 when it is below the lower arm
    (elbow down: axis 3 past its straight-arm position), +1 when axis 5 is negative.
    """
    quad = [math.floor(float(q[i]) / (math.pi / 2)) for i in (0, 3, 5)]
    behind = 0  # solutions from the nearest-branch IK keep the wrist in front of axis 1
    below = 1 if float(q[2]) < -math.pi / 2 else 0
    negative5 = 1 if float(q[4]) < 0 else 0
    return quad[0], quad[1], quad[2], 4 * behind + 2 * below + negative5


@dataclass(frozen=True)
class RapidTarget:
    name: str
    T_base_tcp: np.ndarray
    q: np.ndarray

    def robtarget(self) -> str:
        x, y, z, qw, qx, qy, qz = pose_tuple(self.T_base_tcp)
        cf = confdata(self.q)
        trans = ",".join(_num(v * 1000) for v in (x, y, z))
        rot = ",".join(_num(v) for v in (qw, qx, qy, qz))
        return (
            f"CONST robtarget {self.name} := [[{trans}],[{rot}],"
            f"[{cf[0]},{cf[1]},{cf[2]},{cf[3]}],[9E9,9E9,9E9,9E9,9E9,9E9]];"
        )


def jointtarget(q: np.ndarray) -> str:
    degrees = ",".join(_num(math.degrees(float(v))) for v in q)
    return f"[[{degrees}],[9E9,9E9,9E9,9E9,9E9,9E9]]"


def tooldata(robot: RobotModel) -> str:
    T = robot.tool.T_flange_tcp
    x, y, z, qw, qx, qy, qz = pose_tuple(T)
    cog = ",".join(_num(v * 1000 / 2) for v in (x, y, z))
    return (
        f"PERS tooldata t{robot.tool.name} := [TRUE,[[{_num(x * 1000)},{_num(y * 1000)},"
        f"{_num(z * 1000)}],[{_num(qw)},{_num(qx)},{_num(qy)},{_num(qz)}]],"
        f"[{_num(robot.tool.mass_kg)},[{cog}],[1,0,0,0],0,0,0]];"
    )


def _targets(robot: RobotModel, step: PickPlace) -> list[RapidTarget]:
    T_base_world = np.linalg.inv(robot.T_world_base)
    out = []
    for where, wps in (("pick", step.pick), ("place", step.place)):
        for w in wps:
            out.append(
                RapidTarget(f"p{step.step + 1}_{where}_{w.name}", T_base_world @ w.T_world_tcp, w.q)
            )
    return out


def rapid_module(
    job: VerifiedJob,
    tasks: TaskPlan,
    motion: MotionPlan,
    robot: RobotModel,
    *,
    interlocks: InterlockPlan | None = None,
) -> str:
    """The RAPID module that runs `robot`'s share of the verified job.

    With steps on more than one robot, the module keeps the schedule's order with I/O
    interlocks (`interlocks`; default: the cell's signals, every step of the other robots
    exclusive, i.e. one arm at a time): `WaitDI` before a step for the other robots' steps it
    needs, `SetDO` after a step another robot waits for, and a start handshake: clear this
    robot's outputs (`sdi_reset`), wait until the done inputs it reads are clear (the other
    robot has started too, so nothing left from the last run is taken for new), set ready,
    wait for the others' ready. Ready goes off at the end; done outputs stay on (the other
    robot may not have read them yet) until the next start. After an aborted run, run
    `sdi_reset` on every controller before starting again.
    """
    job.admit(tasks)
    if interlocks is None:
        interlocks = interlock_plan(tasks, {}, parallel=False, signals=job.cell.interlocks)
    io = interlocks if interlocks.active else None
    tool = f"t{robot.tool.name}"
    signal = SIGNALS[robot.tool.kind]
    wait = _num(GRASP_SECONDS[robot.tool.kind])
    steps = tasks.for_robot(robot.name)
    lines = [
        f"MODULE SDI_{robot.name.upper()}",
        f"    ! Generated by SDI from a verified plan: {len(steps)} pick-and-place step(s).",
        "    ! Targets in the robot base frame (wobj0), mm; quaternions [qw,qx,qy,qz].",
        f"    ! Gripper: {robot.tool.name} ({robot.tool.kind}) on digital output {signal}.",
        f"    {tooldata(robot)}",
        f"    CONST jointtarget jHome := {jointtarget(tasks.home[robot.name])};",
    ]
    for step in steps:
        lines += [f"    {t.robtarget()}" for t in _targets(robot, step)]
    signalled = set(io.signalled(robot.name)) if io else set()
    outputs = [io.done_output(k) for k in sorted(signalled)] if io else []
    if io:
        ready = io.signals.signal("ready_output", robot.name)
        outputs.append(ready)
        lines += [
            f"    ! Interlocks with {', '.join(io.peers(robot.name))} on other controllers: "
            "WaitDI before a step waits",
            "    ! for their steps it needs; SetDO after a step they wait for "
            "(cell configuration [interlocks]).",
        ]
    lines += ["", "    PROC main()"]
    if io:
        lines.append("        ! start: own interlock outputs off, wait until the others are off")
        lines.append("        sdi_reset;")
        lines += [f"        WaitDI {name}, 0;" for name in io.inputs_of(robot.name)]
        lines.append(f"        SetDO {ready}, 1;")
        lines += [
            f"        WaitDI {io.signals.signal('ready_input', peer)}, 1;"
            for peer in io.peers(robot.name)
        ]
    lines.append(f"        MoveAbsJ jHome, {FREE_SPEED}, fine, {tool};")
    for n, step in enumerate(steps):
        to_pick, to_place, to_home = motion.via.get(step.step, ([], [], []))
        p = f"p{step.step + 1}"
        lines.append(f"        ! step {step.step + 1}: {step.part_id}")
        if io:
            for d in io.waits.get(step.step, ()):
                lines.append(f"        WaitDI {io.done_input(d)}, 1;")
        for q in to_pick[:-1]:
            lines.append(f"        MoveAbsJ {jointtarget(q)}, {FREE_SPEED}, z10, {tool};")
        lines += [
            f"        MoveJ {p}_pick_approach, {FREE_SPEED}, z10, {tool} \\WObj:=wobj0;",
            f"        MoveL {p}_pick_grasp, {LINEAR_SPEED}, fine, {tool} \\WObj:=wobj0;",
            f"        SetDO {signal}, 1;",
            f"        WaitTime {wait};",
            f"        MoveL {p}_pick_retreat, {LINEAR_SPEED}, fine, {tool} \\WObj:=wobj0;",
        ]
        for q in to_place[:-1]:
            lines.append(f"        MoveAbsJ {jointtarget(q)}, {FREE_SPEED}, z10, {tool};")
        lines += [
            f"        MoveJ {p}_place_approach, {FREE_SPEED}, z10, {tool} \\WObj:=wobj0;",
            f"        MoveL {p}_place_grasp, {LINEAR_SPEED}, fine, {tool} \\WObj:=wobj0;",
            f"        SetDO {signal}, 0;",
            f"        WaitTime {wait};",
            f"        MoveL {p}_place_retreat, {LINEAR_SPEED}, fine, {tool} \\WObj:=wobj0;",
        ]
        # back home over the supply through the checked via points
        for q in to_home[:-1]:
            lines.append(f"        MoveAbsJ {jointtarget(q)}, {FREE_SPEED}, z10, {tool};")
        # a stop point before setting a done output or waiting for the other robot
        waits_next = bool(io and n + 1 < len(steps) and io.waits.get(steps[n + 1].step))
        stop = step.step in signalled or waits_next
        lines.append(f"        MoveAbsJ jHome, {FREE_SPEED}, {'fine' if stop else 'z10'}, {tool};")
        if step.step in signalled:
            assert io is not None
            lines.append(f"        SetDO {io.done_output(step.step)}, 1;")
    lines += ["        ! all steps done", f"        MoveAbsJ jHome, {FREE_SPEED}, fine, {tool};"]
    if io:
        lines.append(f"        SetDO {ready}, 0;")
    lines.append("    ENDPROC")
    if io:
        lines += ["", "    PROC sdi_reset()", "        ! this robot's interlock outputs off"]
        lines += [f"        SetDO {name}, 0;" for name in outputs]
        lines.append("    ENDPROC")
    lines += ["ENDMODULE", ""]
    return "\n".join(lines)
