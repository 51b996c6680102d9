"""The dev31 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev31 import CASES as DEV31

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


Obj = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Sequence[float] = (1.0, 0.0, 0.0, 0.0)) -> Obj:
    return {"id": "b", "position": [x, y, z], "orientation": list(q), "size": [0.15, C, C]}


def res(*objs: Obj, status: str = "success", **extra: Any) -> dict[str, Any]:
    return {"status": status, "layout": {"objects": list(objs)}, **extra}


def column(x: float, y: float, n: int, z0: float = 0.0) -> list[Obj]:
    return [cube(x, y, z0 + C / 2 + C * j) for j in range(n)]


def ring(x0: float, y0: float, n: int, high: int = 1) -> list[Obj]:
    """An n × n square ring of cubes, lower-left cube centre at (x0, y0)."""
    out: list[Obj] = []
    for i in range(n):
        for j in range(n):
            if i in (0, n - 1) or j in (0, n - 1):
                out += column(x0 + C * i, y0 + C * j, high)
    return out


def grid(x0: float, y0: float, a: int, b: int, layers: int = 1, z0: float = 0.0) -> list[Obj]:
    """a cubes along x by b along y, `layers` high, the first cube's centre at (x0, y0)."""
    return [
        cube(x0 + C * i, y0 + C * j, z0 + C / 2 + C * h)
        for h in range(layers)
        for i in range(a)
        for j in range(b)
    ]


def _row_y(x: float, y0: float, n: int, z0: float = 0.0) -> list[Obj]:
    return [cube(x, y0 + C * j, z0 + C / 2) for j in range(n)]


def _row_x(x0: float, y: float, n: int, z0: float = 0.0) -> list[Obj]:
    return [cube(x0 + C * i, y, z0 + C / 2) for i in range(n)]


def _stairs_y(x: float, y0: float, hs: Sequence[int]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _stairs_x(x0: float, y: float, hs: Sequence[int]) -> list[Obj]:
    """Columns of the given heights in a line along x from x0 (front to back)."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _dev31(case_id: str) -> Case:
    return next(c for c in DEV31 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV31) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV31) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV31} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV31)
    ids = [c.id for c in DEV31]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev31-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV31:
        assert c.id.startswith(f"dev31-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one; a module that does not import (a set still being written) is
    skipped."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev31"):
            continue
        try:
            mod = importlib.import_module(f"sdi.bench.{name}")
        except Exception:  # a half-written sibling set
            continue
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_dev29" in others
    seen: dict[str, str] = {}
    for c in DEV31:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV31}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
RING_NOTED = res(*ring(0.35, 0.20, 5), status="partial", notes=["assumed one high"])
NO_LAYOUT: dict[str, Any] = {"status": "error", "layout": None}
EMPTY: dict[str, Any] = {"status": "success", "layout": {"objects": []}}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, RING_NOTED, NO_LAYOUT, EMPTY])
def test_every_predicate_answers_without_raising(result: Mapping[str, Any]) -> None:
    for case in DEV31:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev31.py").read_text(encoding="utf-8")
    imports = [
        ln.strip() for ln in src.splitlines() if ln.lstrip().startswith(("import ", "from "))
    ]
    from_sdi = [ln for ln in imports if "sdi" in ln]
    allowed = (
        "from sdi.bench import boxes as bx",
        "from sdi.bench import language_checks as k",
        "from sdi.bench.language_checks import Case",
    )
    assert all(ln in allowed for ln in from_sdi), from_sdi


# ---------------------------------------------------------------- hand-built layouts

_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375, centre (0.45, 0.30)
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_WALL5_Y = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]  # x 0.425–0.475
_WALL6_Y = [*_row_y(0.45, 0.175, 6), *_row_y(0.45, 0.175, 6, z0=C)]  # y 0.15–0.45
_WALL4_FRONT = [*_row_y(0.35, 0.225, 4), *_row_y(0.35, 0.225, 4, z0=C)]  # x 0.325–0.375
_BLOCK_RIGHT = grid(0.45, 0.20, 2, 2, layers=2)  # x 0.425–0.525, y 0.175–0.275
_ERROR: dict[str, Any] = {"status": "error", "layout": None}
_BRIDGE3 = [*column(0.45, 0.25, 3), *column(0.45, 0.35, 3), beam(0.45, 0.30, 0.175, YAW90)]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev31-rel-01",  # the speaker's left is the robot's right: the 4-tower at -y
            res(*column(0.45, 0.20, 4), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.40, 4), *column(0.45, 0.20, 2)),  # read in the robot's frame
        ),
        (
            "dev31-rel-04",  # a cube on the middle of a beam bridge on posts of three
            res(*_BRIDGE3, cube(0.45, 0.30, 0.225)),
            res(*_BRIDGE3, cube(0.45, 0.25, 0.225)),  # on the end of the beam
        ),
        (
            "dev31-rel-06",  # a 3-tower on the speaker's side (+x) of a left-right wall …
            res(*_WALL5_Y, *column(0.60, 0.30, 3)),
            res(*_WALL5_Y, *column(0.30, 0.30, 3)),  # on the robot's side
        ),
        (
            "dev31-rel-06",  # … or set against its +x face
            res(*_WALL5_Y, *column(0.50, 0.30, 3)),
            res(*_WALL5_Y, *column(0.40, 0.30, 3)),  # against its -x face
        ),
        (
            "dev31-rel-09",  # two touching rows of six along the front: a 2 x 6 slab
            res(*_row_y(0.30, 0.175, 6), *_row_y(0.35, 0.175, 6)),
            res(*_row_y(0.30, 0.175, 6), *_row_y(0.40, 0.175, 6)),  # a gap between the rows
        ),
        (
            "dev31-rel-11",  # the block on the speaker's left (robot's right) of the tower …
            res(*column(0.45, 0.35, 5), *_BLOCK_RIGHT),
            res(*column(0.45, 0.25, 5), *grid(0.45, 0.35, 2, 2, layers=2)),
        ),
        (
            "dev31-rel-11",  # … or the tower set against the block's +y face
            res(*_BLOCK_RIGHT, *column(0.45, 0.30, 5)),
            res(*_BLOCK_RIGHT, *column(0.45, 0.15, 5)),  # against its -y face
        ),
        (
            "dev31-rel-12",  # all 13 cubes: a 4-tower on the middle of a 3 x 3 slab
            res(*_SLAB3, *column(0.45, 0.30, 4, C)),
            res(*_SLAB3, *column(0.40, 0.25, 4, C)),  # on a corner
        ),
        (
            "dev31-rel-13",  # a 6-tower inside a 5 x 5 ring, clear of it …
            res(*_PEN5, *column(0.45, 0.30, 6)),
            res(*_PEN5, *column(0.70, 0.30, 6)),  # to one side of it
        ),
        (
            "dev31-rel-13",  # … or against its inner wall
            res(*_PEN5, *column(0.40, 0.30, 6)),
            res(*_PEN5, *column(0.30, 0.30, 6)),  # against its outer wall
        ),
        (
            "dev31-rel-16",  # directly in front as the speaker sees it: +x, square to the wall
            res(*_WALL6_Y, *column(0.60, 0.30, 3)),
            res(*_WALL6_Y, *column(0.75, 0.48, 3)),  # behind but off the wall's end
        ),
        (
            "dev31-rel-16",  # the robot's-frame reading
            res(*_WALL6_Y, *column(0.55, 0.30, 3)),
            res(*_WALL6_Y, *column(0.30, 0.30, 3)),
        ),
        (
            "dev31-rel-17",  # a 3 x 3 slab with a cube on each of its two back corners
            res(*_SLAB3, cube(0.50, 0.25, 0.075), cube(0.50, 0.35, 0.075)),
            res(*_SLAB3, cube(0.40, 0.25, 0.075), cube(0.40, 0.35, 0.075)),  # front corners
        ),
        (
            "dev31-rel-19",  # 6, 3, 6 in a line, a cube between neighbours
            res(*column(0.45, 0.20, 6), *column(0.45, 0.30, 3), *column(0.45, 0.40, 6)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 6), *column(0.45, 0.40, 6)),
        ),
        (
            "dev31-rel-20",  # a front wall, the 4-tower beyond it from the speaker (-x)
            res(*_WALL4_FRONT, *column(0.25, 0.30, 4)),
            res(*_WALL4_FRONT, *column(0.50, 0.30, 4)),  # on the speaker's side
        ),
        (
            "dev31-rel-22",  # a 3-tower against the right (-y) of a front-to-back row of four
            res(*_row_x(0.40, 0.30, 4), *column(0.45, 0.25, 3)),
            res(*_row_x(0.40, 0.30, 4), *column(0.45, 0.35, 3)),  # on its left
        ),
        (
            "dev31-seq-06",  # a 4-tower on the speaker's left: the robot's right
            res(*column(0.45, 0.15, 4)),
            res(*column(0.45, 0.45, 4)),
        ),
        (
            "dev31-seq-08",  # a front row of six with a 2-tower on each end
            res(*_stairs_y(0.30, 0.175, (3, 1, 1, 1, 1, 3))),
            res(*_stairs_y(0.30, 0.175, (3, 1, 1, 1, 1, 1, 3))),  # the row of seven kept
        ),
        (
            "dev31-seq-16",  # the one on the speaker's right (robot's left) is left standing
            res(*column(0.45, 0.45, 3)),
            res(*column(0.45, 0.15, 3)),
        ),
        (
            "dev31-seq-17",  # 6 and 4, the top cube moved across: 5 and 5
            res(*column(0.45, 0.20, 5), *column(0.45, 0.40, 5)),
            res(*column(0.45, 0.20, 6), *column(0.45, 0.40, 4)),
        ),
        (
            "dev31-seq-20",  # a 3 x 3-based pyramid less its top cube: 9-4
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C)),
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C), cube(0.45, 0.30, 0.125)),
        ),
        (
            "dev31-seq-22",  # a cube on top of the bigger (four-high) of two 2 x 2 blocks
            res(
                *grid(0.45, 0.20, 2, 2, layers=4),
                *grid(0.45, 0.35, 2, 2, layers=2),
                cube(0.475, 0.225, 0.225),
            ),
            res(
                *grid(0.45, 0.20, 2, 2, layers=4),
                *grid(0.45, 0.35, 2, 2, layers=2),
                cube(0.475, 0.375, 0.125),  # on the smaller one
            ),
        ),
        (
            "dev31-num-03",  # 2, 4, 6 from the speaker's left: 6, 4, 2 from the robot's left
            res(*column(0.45, 0.40, 6), *column(0.45, 0.30, 4), *column(0.45, 0.20, 2)),
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 4), *column(0.45, 0.20, 6)),
        ),
        (
            "dev31-num-07",  # 16 cubes as a square ring one high: 5 x 5
            res(*ring(0.35, 0.20, 5)),
            res(*ring(0.40, 0.25, 3, high=2)),  # also 16 cubes, but two high
        ),
        (
            "dev31-num-14",  # three parallel rows of four, a cube apart
            res(*_row_y(0.35, 0.20, 4), *_row_y(0.45, 0.20, 4), *_row_y(0.55, 0.20, 4)),
            res(*_row_y(0.35, 0.20, 4), *_row_y(0.45, 0.20, 4)),  # the first figure
        ),
        (
            "dev31-num-15",  # 4, 3, 2 from the speaker towards the robot: 2, 3, 4 along +x
            res(*column(0.35, 0.30, 2), *column(0.45, 0.30, 3), *column(0.55, 0.30, 4)),
            res(*column(0.35, 0.30, 4), *column(0.45, 0.30, 3), *column(0.55, 0.30, 2)),
        ),
        (
            "dev31-dim-11",  # a 4 x 4 ring nearest the speaker on their left: back right
            res(*ring(0.55, 0.15, 4)),
            res(*ring(0.25, 0.35, 4)),  # front left, the robot's-frame reading
        ),
        (
            "dev31-dim-14",  # two 2-towers "10 cm apart": two cubes clear …
            res(*column(0.45, 0.20, 2), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 2)),  # three cubes clear
        ),
        (
            "dev31-dim-14",  # … or centre to centre (one cube clear)
            res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.25, 2), *column(0.45, 0.30, 2)),  # touching
        ),
        (
            "dev31-dim-16",  # four steps climbing away from the speaker: towards the robot
            res(*_stairs_x(0.30, 0.30, (4, 3, 2, 1))),
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev31-neg-11",  # a 4-step staircase not climbing towards the speaker (+x)
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev31-reg-01",  # the corner on the speaker's right, nearest them: back left
            res(*column(0.65, 0.45, 4)),
            res(*column(0.30, 0.15, 4)),
        ),
        (
            "dev31-reg-07",  # the far corner on the speaker's left: front right
            res(*grid(0.25, 0.10, 3, 3)),
            res(*grid(0.60, 0.40, 3, 3)),
        ),
        (
            "dev31-reg-17",  # the 2-tower back left, the 4-tower front right
            res(*column(0.65, 0.45, 2), *column(0.30, 0.15, 4)),
            res(*column(0.30, 0.15, 2), *column(0.65, 0.45, 4)),
        ),
        (
            "dev31-wo-07",  # twelve cubes: a 3 x 3 slab with a 3-tower on its middle
            res(*_SLAB3, *column(0.45, 0.30, 3, C)),
            res(*_SLAB3, *column(0.50, 0.35, 3, C)),
        ),
        (
            "dev31-typo-01",  # the speaker's right: the robot's left
            res(*column(0.45, 0.45, 4)),
            res(*column(0.45, 0.15, 4)),
        ),
        (
            "dev31-open-09",  # nothing on the speaker's left (the robot's right)
            res(*column(0.45, 0.45, 3)),
            res(*column(0.45, 0.45, 3), *column(0.45, 0.15, 3)),
        ),
        (
            "dev31-bad-09",  # the request was called off: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 4), notes=["the request was cancelled"]),
        ),
        (
            "dev31-bad-17",  # no glass cubes: refuse, or build with the stocked ones and say so
            res(*column(0.45, 0.30, 4), notes=["glass cubes are not stocked; used the usual"]),
            res(*column(0.45, 0.30, 4)),
        ),
    ],
)
def test_dev31_predicates_on_hand_built_layouts(
    case_id: str, right: Mapping[str, Any], wrong: Mapping[str, Any]
) -> None:
    case = _dev31(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
