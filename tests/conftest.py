"""Shared helpers for the test suite: hand-made parts and layouts, and cell fixtures.

Units are metres; a part's position is its box centre; the table top is z = 0. The default
part is a 0.05 m cube, so a cube resting on the table has its centre at z = 0.025.
"""

from __future__ import annotations

import pytest

from sdi.inspector.violation import Constraint
from sdi.model import CellConfig, Layout, ParallelGripper, Part, VacuumGripper

S = 0.05
"""Edge of the default cube, m."""


def cube(pid: str, x: float, y: float, z: float, size: float = S) -> Part:
    """A cube with its centre at (x, y, z)."""
    return Part(id=pid, position=(x, y, z), size=(size, size, size))


def box(pid: str, x: float, y: float, z: float, sx: float, sy: float, sz: float) -> Part:
    """An axis-aligned box with its centre at (x, y, z) and edge lengths (sx, sy, sz)."""
    return Part(id=pid, position=(x, y, z), size=(sx, sy, sz))


def tower(n: int, x: float = 0.45, y: float = 0.30, prefix: str = "t") -> list[Part]:
    """`n` default cubes stacked on the table at (x, y), ids ``t1`` (bottom) … ``tn``."""
    return [cube(f"{prefix}{k + 1}", x, y, S / 2 + k * S) for k in range(n)]


def layout(*parts: Part | list[Part]) -> Layout:
    """A layout from parts and lists of parts, in the order given."""
    flat: list[Part] = []
    for p in parts:
        flat.extend(p if isinstance(p, list) else [p])
    return Layout(objects=tuple(flat))


def codes(violations: object) -> set[str]:
    """The constraint codes of a report's (or a list's) violations."""
    items = getattr(violations, "violations", violations)
    return {v.constraint.value for v in items}  # type: ignore[attr-defined]


def of(violations: object, constraint: Constraint) -> list:
    """The violations of one constraint."""
    items = getattr(violations, "violations", violations)
    return [v for v in items if v.constraint == constraint]  # type: ignore[attr-defined]


@pytest.fixture
def cell() -> CellConfig:
    """The default cell: vacuum and parallel grippers, workspace x .20–.80, y .05–.55, z 0–.50."""
    return CellConfig()


@pytest.fixture
def parallel_cell() -> CellConfig:
    """A cell whose only tool is the two-finger parallel gripper."""
    return CellConfig(grippers=(ParallelGripper(),))


@pytest.fixture
def vacuum_cell() -> CellConfig:
    """A cell whose only tool is the vacuum gripper."""
    return CellConfig(grippers=(VacuumGripper(),))
