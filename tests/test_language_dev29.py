"""The dev29 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev29 import CASES as DEV29

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


def _towers(
    pairs: Sequence[tuple[float, int]], x: float | None = None, y: float | None = None
) -> list[Obj]:
    """Columns at the given (position, height) pairs along y (x fixed) or along x (y fixed)."""
    if x is not None:
        return [c for pos, h in pairs for c in column(x, pos, h)]
    assert y is not None
    return [c for pos, h in pairs for c in column(pos, y, h)]


def _dev29(case_id: str) -> Case:
    return next(c for c in DEV29 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV29) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV29) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV29} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV29)
    ids = [c.id for c in DEV29]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev29-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV29:
        assert c.id.startswith(f"dev29-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name (the frozen test set included: its
    commands are only compared here, never shown)."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_dev29"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_test" in others
    seen: dict[str, str] = {}
    for c in DEV29:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    clashes = [
        (seen[_norm(c.text)], name, c.id)
        for name, cases in others.items()
        for c in cases
        if _norm(c.text) in seen
    ]
    assert not clashes, clashes  # ids only, never another set's text
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV29}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
TWO_APART = res(*column(0.30, 0.15, 4), *grid(0.60, 0.40, 2, 3, layers=2))
OUTSIDE = res(*column(0.10, 0.30, 2))
NO_LAYOUT = {"status": "error", "layout": None}
EMPTY = {"status": "success", "layout": {"objects": []}}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, TWO_APART, OUTSIDE, NO_LAYOUT, EMPTY])
def test_every_predicate_answers_without_raising(result: dict[str, Any]) -> None:
    for case in DEV29:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev29.py").read_text(encoding="utf-8")
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

_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375
_SLAB4 = grid(0.40, 0.25, 4, 4)  # x 0.375–0.575, y 0.225–0.425
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_ROW6_BACK = _row_y(0.65, 0.20, 6)  # x 0.625–0.675, y 0.175–0.475
_PYR_16_9_4 = [
    *_SLAB4,
    *grid(0.425, 0.275, 3, 3, z0=C),
    *grid(0.45, 0.30, 2, 2, z0=2 * C),
]
_POSTS2 = [*column(0.45, 0.25, 2), *column(0.45, 0.35, 2)]  # a cube clear between them
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev29-rel-01",  # a 4-tower and a 2-tower beside it, both on the left, apart …
            res(*column(0.45, 0.45, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.45, 4), *column(0.45, 0.15, 2)),  # the 2 over on the right
        ),
        (
            "dev29-rel-01",  # … or touching
            res(*column(0.45, 0.45, 4), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.15, 2)),  # touching, on the right
        ),
        (
            "dev29-rel-05",  # a single cube dead in the middle of a 5 x 5 ring
            res(*_PEN5, cube(0.45, 0.30, C / 2)),
            res(*_PEN5, cube(0.40, 0.25, C / 2)),  # inside, but in a corner of the interior
        ),
        (
            "dev29-rel-08",  # a 2-tower on the centre cube of a 3 x 3 slab
            res(*_SLAB3, *column(0.45, 0.30, 2, C)),
            res(*_SLAB3, *column(0.40, 0.25, 2, C)),  # on a corner cube
        ),
        (
            "dev29-rel-09",  # two 4-towers a cube apart under a beam
            res(*column(0.45, 0.25, 4), *column(0.45, 0.35, 4), beam(0.45, 0.30, 0.225, YAW90)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3), beam(0.45, 0.30, 0.175, YAW90)),
        ),
        (
            "dev29-rel-12",  # a 6 x 3 wall with a cube on each end
            res(*_stairs_y(0.45, 0.15, (4, 3, 3, 3, 3, 4))),
            res(*_stairs_y(0.45, 0.10, (1, 3, 3, 3, 3, 3, 3, 1))),  # set beside the ends
        ),
        (
            "dev29-rel-13",  # a single cube on the top step of a 4-step staircase
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4)), cube(0.45, 0.35, 0.225)),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4)), cube(0.45, 0.30, 0.175)),  # a step lower
        ),
        (
            "dev29-rel-14",  # a 2-tower inside a 4 x 4 ring, against its wall …
            res(*ring(0.40, 0.25, 4), *column(0.45, 0.30, 2)),
            res(*ring(0.40, 0.25, 4), *column(0.70, 0.30, 2)),  # outside it
        ),
        (
            "dev29-rel-14",  # … or clear of it, in the middle
            res(*ring(0.40, 0.25, 4), *column(0.475, 0.325, 2)),
            res(*ring(0.40, 0.25, 5), *column(0.475, 0.325, 2)),  # a 5 x 5 ring
        ),
        (
            "dev29-rel-16",  # a back row of 6 with a 2-tower in front of each end, clear …
            res(*_ROW6_BACK, *column(0.55, 0.20, 2), *column(0.55, 0.45, 2)),
            res(*_ROW6_BACK, *column(0.55, 0.30, 2), *column(0.55, 0.35, 2)),  # the middle
        ),
        (
            "dev29-rel-16",  # … or set against the row
            res(*_ROW6_BACK, *column(0.60, 0.20, 2), *column(0.60, 0.45, 2)),
            res(*_ROW6_BACK, *column(0.70, 0.20, 2), *column(0.70, 0.45, 2)),  # behind it
        ),
        (
            "dev29-rel-19",  # a 6-tower set against a 3 x 3 x 2 block
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.55, 0.30, 6)),
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.75, 0.30, 6)),  # 20 cm away
        ),
        (
            "dev29-rel-20",  # a 5-tower, a 3-tower to its left, a row of 4 in front of the 5
            res(*column(0.65, 0.25, 5), *column(0.65, 0.40, 3), *_row_y(0.35, 0.175, 4)),
            res(*column(0.65, 0.25, 5), *column(0.65, 0.10, 3), *_row_y(0.35, 0.175, 4)),
        ),
        (
            "dev29-seq-03",  # a 3 x 3 slab, a 2 x 2 layer on it, one cube on top
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C), cube(0.45, 0.30, 0.125)),
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C)),  # the last step forgotten
        ),
        (
            "dev29-seq-04",  # a 7-tower less a couple off the top
            res(*column(0.45, 0.30, 5)),
            res(*column(0.45, 0.30, 7)),
        ),
        (
            "dev29-seq-08",  # a front row of 6 without its two middle cubes
            res(*_row_y(0.30, 0.15, 2), *_row_y(0.30, 0.35, 2)),
            res(*_row_y(0.30, 0.15, 6)),
        ),
        (
            "dev29-seq-15",  # a 16-9-4-1 pyramid less its top cube
            res(*_PYR_16_9_4),
            res(*_PYR_16_9_4, cube(0.475, 0.325, 0.175)),  # the top cube kept
        ),
        (
            "dev29-seq-18",  # three 3-towers a cube apart, the middle one raised to 5
            res(*_towers([(0.15, 3), (0.25, 5), (0.35, 3)], x=0.45)),
            res(*_towers([(0.15, 5), (0.25, 3), (0.35, 3)], x=0.45)),  # an end one raised
        ),
        (
            "dev29-seq-20",  # a 3 x 3 slab, corrected to the right
            res(*grid(0.40, 0.10, 3, 3)),
            res(*grid(0.40, 0.40, 3, 3)),  # left, as first said
        ),
        (
            "dev29-num-03",  # two rows of 5, one behind the other, a cube between
            res(*_row_y(0.40, 0.20, 5), *_row_y(0.50, 0.20, 5)),
            res(*_row_x(0.30, 0.20, 5), *_row_x(0.30, 0.30, 5)),  # side by side instead
        ),
        (
            "dev29-num-04",  # a few 2-towers
            res(*_towers([(0.15, 2), (0.30, 2), (0.45, 2)], x=0.45)),
            res(*_towers([(0.15, 2), (0.30, 2)], x=0.45)),  # only a couple
        ),
        (
            "dev29-num-10",  # a 2-tower and a 6-tower set against it
            res(*column(0.45, 0.30, 6), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.30, 3), *column(0.45, 0.35, 2)),  # not three times as tall
        ),
        (
            "dev29-num-12",  # 1, 2, 3, 4 from left (+y) to right
            res(*_towers([(0.45, 1), (0.35, 2), (0.25, 3), (0.15, 4)], x=0.45)),
            res(*_towers([(0.15, 1), (0.25, 2), (0.35, 3), (0.45, 4)], x=0.45)),
        ),
        (
            "dev29-num-15",  # 5, 4, 3, 2, 1 from the front (small x) back
            res(*_towers([(0.25, 5), (0.35, 4), (0.45, 3), (0.55, 2), (0.65, 1)], y=0.30)),
            res(*_towers([(0.25, 1), (0.35, 2), (0.45, 3), (0.55, 4), (0.65, 5)], y=0.30)),
        ),
        (
            "dev29-num-17",  # a cube on each corner of a 4 x 4 slab
            res(*_SLAB4, *[cube(x, y, 0.075) for x in (0.40, 0.55) for y in (0.25, 0.40)]),
            res(*_SLAB4, *[cube(x, y, 0.075) for x in (0.45, 0.50) for y in (0.30, 0.35)]),
        ),
        (
            "dev29-num-20",  # a 2-tower between two 4-towers
            res(*_towers([(0.15, 4), (0.25, 2), (0.35, 4)], x=0.45)),
            res(*_towers([(0.15, 2), (0.25, 4), (0.35, 4)], x=0.45)),  # at one end
        ),
        (
            "dev29-dim-13",  # two 3-towers 10 cm apart: clear …
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 3)),  # 15 cm clear
        ),
        (
            "dev29-dim-13",  # … or centre to centre
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 2)),  # one too short
        ),
        (
            "dev29-neg-05",  # posts of two under a bar of cubes, no beam
            res(*_POSTS2, *_row_y(0.45, 0.25, 3, z0=2 * C)),
            res(*_POSTS2, beam(0.45, 0.30, 0.125, YAW90)),
        ),
        (
            "dev29-neg-08",  # a 3 x 3 square with the middle missing
            res(*ring(0.40, 0.25, 3)),
            res(*_SLAB3),
        ),
        (
            "dev29-neg-09",  # four steps not climbing towards the robot
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4))),  # climbs to the back
            res(*_stairs_x(0.35, 0.30, (4, 3, 2, 1))),  # climbs to the front
        ),
        (
            "dev29-neg-10",  # a 5-tower not in the back half
            res(*column(0.35, 0.30, 5)),
            res(*column(0.65, 0.30, 5)),
        ),
        (
            "dev29-wo-14",  # two 3-towers touching
            res(*column(0.45, 0.30, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3)),  # apart
        ),
        (
            "dev29-reg-01",  # a 3-tower at x 0.6, y 0.2
            res(*column(0.60, 0.20, 3)),
            res(*column(0.40, 0.20, 3)),
        ),
        (
            "dev29-open-09",  # a bunch of towers in a row
            res(*_towers([(0.15, 1), (0.25, 3), (0.35, 2), (0.45, 4)], x=0.45)),
            res(*_towers([(0.15, 1), (0.35, 3)], x=0.45)),  # only two
        ),
        (
            "dev29-bad-02",  # not a build request: only a refusal
            _ERROR,
            res(*column(0.45, 0.30, 3), notes=["built an example tower"]),
        ),
        (
            "dev29-bad-03",  # past the cell: refuse, or build within it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes, the cell's height"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev29-bad-07",  # another language: refuse, or build the tower and say so
            res(*column(0.45, 0.30, 4), notes=["read as Spanish: a tower of four cubes"]),
            res(*column(0.45, 0.30, 4)),
        ),
    ],
)
def test_dev29_predicates_on_hand_built_layouts(
    case_id: str, right: dict[str, Any], wrong: dict[str, Any]
) -> None:
    case = _dev29(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
