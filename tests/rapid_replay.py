"""Replaying exported RAPID modules: a small interpreter of what SDI emits, run as concurrent
controllers in a discrete-event simulation, and the rapidchecker grammar check (4-space
indentation). Used by tests/test_interlocks.py and tests/test_export.py."""

from __future__ import annotations

import random
import re
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import pytest

from sdi.export.rapid import SIGNALS
from sdi.model.cell import Interlocks


def parse(text: str) -> list[tuple[str, list[str]]]:
    """`main`'s instructions with procedure calls inlined; `("#step", [k])` marks step k."""
    procs: dict[str, list[tuple[str, list[str]]]] = {}
    current = None
    for line in text.splitlines():
        s = line.strip()
        if m := re.fullmatch(r"PROC (\w+)\(\)", s):
            current = m.group(1)
            procs[current] = []
        elif s == "ENDPROC":
            current = None
        elif current is None or not s:
            continue
        elif m := re.match(r"! step (\d+):", s):
            procs[current].append(("#step", [str(int(m.group(1)) - 1)]))
        elif s == "! all steps done":
            procs[current].append(("#step", []))
        elif not s.startswith("!"):
            assert s.endswith(";"), s
            word, _, rest = s[:-1].partition(" ")
            procs[current].append((word, [a.strip() for a in rest.split(",")] if rest else []))

    def expand(name: str) -> list[tuple[str, list[str]]]:
        out = []
        for word, args in procs[name]:
            out += expand(word) if word in procs and not args else [(word, args)]
        return out

    return expand("main")


class Deadlock(AssertionError):
    pass


@dataclass
class Run:
    start: dict[int, float] = field(default_factory=dict)
    end: dict[int, float] = field(default_factory=dict)
    released: dict[int, float] = field(default_factory=dict)
    io: dict[object, int] = field(default_factory=dict)


def simulate(
    modules: dict[str, str],
    signals: Interlocks,
    steps: int,
    rng: random.Random,
    io: dict[object, int] | None = None,
) -> Run:
    """Run the modules as concurrent controllers (discrete events); raise Deadlock if stuck."""
    outputs: dict[tuple[str, str], object] = {}
    inputs: dict[tuple[str, str], object] = {}
    for robot in modules:
        for other in modules:
            if other == robot:
                continue
            inputs[(robot, signals.signal("ready_input", other))] = ("ready", other)
            for n in range(1, steps + 1):
                inputs[(robot, signals.signal("done_input", other, n))] = ("done", other, n)
        outputs[(robot, signals.signal("ready_output", robot))] = ("ready", robot)
        for n in range(1, steps + 1):
            outputs[(robot, signals.signal("done_output", robot, n))] = ("done", robot, n)

    values = dict(io or {})
    set_at: dict[object, float] = {}
    run = Run()
    programs = {r: parse(text) for r, text in modules.items()}
    pc = dict.fromkeys(modules, 0)
    clock = {r: rng.uniform(0.0, 20.0) for r in modules}  # controllers start when they start
    step: dict[str, int | None] = dict.fromkeys(modules)
    while True:
        ready = []
        for r, program in programs.items():
            if pc[r] == len(program):
                continue
            word, args = program[pc[r]]
            t = clock[r]
            if word == "WaitDI":
                wire = inputs.get((r, args[0]), (r, args[0]))
                if values.get(wire, 0) != int(args[1]):
                    continue
                t = max(t, set_at.get(wire, 0.0))
            ready.append((t, r))
        if not ready:
            stuck = {r: programs[r][pc[r]] for r in programs if pc[r] < len(programs[r])}
            if stuck:
                raise Deadlock(f"the controllers wait for each other: {stuck}")
            run.io = values
            return run
        t, r = min(ready)
        clock[r] = t
        word, args = programs[r][pc[r]]
        pc[r] += 1
        k = step[r]
        if word == "#step":
            step[r] = int(args[0]) if args else None
        elif word in ("MoveAbsJ", "MoveJ", "MoveL"):
            if k is not None:
                run.start.setdefault(k, clock[r])
            clock[r] += rng.uniform(0.05, 3.0)
            if k is not None:
                run.end[k] = clock[r]
        elif word == "WaitTime":
            clock[r] += float(args[0])
        elif word == "SetDO":
            wire = outputs.get((r, args[0]), (r, args[0]))
            values[wire] = int(args[1])
            set_at[wire] = clock[r]
            if args[0] in SIGNALS.values() and int(args[1]) == 0 and k is not None:
                run.released[k] = clock[r]
        elif word != "WaitDI":
            raise AssertionError(f"unknown instruction {word} {args}")


def supports(tasks: Any) -> dict[int, list[int]]:
    """Steps whose part a step's part rests on, from the target poses alone (not depends_on)."""
    boxes = {}
    for s in tasks.steps:
        T = s.T_world_part_target
        half = 0.5 * np.abs(T[:3, :3]) @ np.array(s.part_size)
        boxes[s.step] = (T[:3, 3] - half, T[:3, 3] + half)
    out: dict[int, list[int]] = {}
    for k, (lo, _) in boxes.items():
        out[k] = []
        for j, (lo2, hi2) in boxes.items():
            overlap = np.minimum(boxes[k][1][:2], hi2[:2]) - np.maximum(lo[:2], lo2[:2])
            if j != k and abs(hi2[2] - lo[2]) < 2e-3 and bool(np.all(overlap > 1e-3)):
                out[k].append(j)
    return out


def check_order(job: Any, run: Run) -> None:
    """Supports placed before a step starts; steps sharing space never overlap in time.

    `job` has `tasks` (a TaskPlan) and `exclusive(later, earlier)` (steps sharing space)."""
    steps = job.tasks.steps
    assert set(run.start) == set(run.end) == set(run.released) == {s.step for s in steps}
    below = supports(job.tasks)
    for s in steps:
        for d in sorted({*s.depends_on, *below[s.step]}):
            assert run.released[d] <= run.start[s.step], (
                f"step {s.step + 1} ({s.part_id}) starts before step {d + 1} "
                f"({steps[d].part_id}) has placed its part"
            )
        for o in steps[: s.step]:
            if job.exclusive(s.step, o.step):
                apart = run.end[o.step] <= run.start[s.step] or run.end[s.step] <= run.start[o.step]
                assert apart, f"steps {o.step + 1} and {s.step + 1} are in a shared zone at once"


def rapidchecker_errors(text: str) -> list[str]:
    with warnings.catch_warnings():  # rapidchecker 0.1.5 uses pyparsing's pre-3.0 names
        warnings.simplefilter("ignore", DeprecationWarning)
        pytest.importorskip("rapidchecker")
        from rapidchecker import config
        from rapidchecker.cli import check_file

        before = config.CONFIG.indentation_size
        config.CONFIG.indentation_size = 4  # SDI's modules indent by 4 spaces
        try:
            return [str(e) for e in check_file(text)]
        finally:
            config.CONFIG.indentation_size = before
