"""The dev21 language set: its size and phenomena, unique ids, no command shared with another
set, predicates that answer on any result, and — on hand-built layouts from raw cube poses —
each hard case's predicate passing a right layout and failing the one a careless reader would
build."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev21 import CASES

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


def cube(x, y, z, i=[0]):  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x, y, z, q=(1.0, 0.0, 0.0, 0.0)):
    return {"id": "b", "position": [x, y, z], "orientation": list(q), "size": [0.15, C, C]}


def res(*objs, status="success", **extra):
    return {"status": status, "layout": {"objects": list(objs)}, **extra}


def column(x, y, n, z0=0.0):
    return [cube(x, y, z0 + C / 2 + C * j) for j in range(n)]


def ring(x0, y0, n, high=1):
    """An n × n square ring of cubes, lower-left cube centre at (x0, y0)."""
    out = []
    for i in range(n):
        for j in range(n):
            if i in (0, n - 1) or j in (0, n - 1):
                out += column(x0 + C * i, y0 + C * j, high)
    return out


def grid(x0, y0, a, b, layers=1, z0=0.0):
    return [
        cube(x0 + C * i, y0 + C * j, z0 + C / 2 + C * h)
        for h in range(layers)
        for i in range(a)
        for j in range(b)
    ]


def _row_y(x, y0, n, z0=0.0):
    return [cube(x, y0 + C * j, z0 + C / 2) for j in range(n)]


def _row_x(x0, y, n, z0=0.0):
    return [cube(x0 + C * i, y, z0 + C / 2) for i in range(n)]


def _stairs_x(x0, y, hs):
    """Columns of the given heights in a line along x from x0 (front to back)."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _stairs_y(x, y0, hs):
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


def _case(case_id: str) -> Case:
    return next(c for c in CASES if c.id == case_id)


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(CASES) >= 170
    assert all(c.id.startswith("dev21-") for c in CASES)
    ids = [c.id for c in CASES]
    assert len(ids) == len(set(ids))
    per = {p: sum(c.phenomenon == p for c in CASES) for p in PHENOMENA}
    assert {c.phenomenon for c in CASES} <= set(PHENOMENA)
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert all(callable(c.accept) for c in CASES)
    for c in CASES:  # the id names the phenomenon: dev21-<phen>-NN
        assert c.id.rsplit("-", 1)[1].isdigit(), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES (never the frozen test set, which is not opened)."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_test", "language_dev21"):
            continue
        out[name] = importlib.import_module(f"sdi.bench.{name}").CASES
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    mine = [_norm(c.text) for c in CASES]
    assert len(mine) == len(set(mine))
    others = _other_sets()
    assert "language_dev19" in others and "language_dev" in others
    seen = {_norm(c.text): (name, c.id) for name, cases in others.items() for c in cases}
    shared = [(c.id, seen[_norm(c.text)]) for c in CASES if _norm(c.text) in seen]
    assert not shared, shared


def test_no_id_is_shared_with_another_set():
    theirs = {c.id for cases in _other_sets().values() for c in cases}
    assert not theirs & {c.id for c in CASES}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in CASES:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_judge_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev21.py").read_text(encoding="utf-8")
    imports = [
        ln.strip() for ln in src.splitlines() if ln.lstrip().startswith(("import ", "from "))
    ]
    sdi = [ln for ln in imports if "sdi" in ln]
    assert sdi and all(
        ln
        in (
            "from sdi.bench import boxes as bx",
            "from sdi.bench import language_checks as k",
            "from sdi.bench.language_checks import Case",
        )
        for ln in sdi
    ), sdi


# ---------------------------------------------------------------- hand-built layouts

_PORTICO_LEGS3 = [c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 3)]
_PORTICO_BEAMS3 = [  # two beams along y on the legs, two across them along x
    beam(0.40, 0.30, 3 * C + C / 2, YAW90),
    beam(0.50, 0.30, 3 * C + C / 2, YAW90),
    beam(0.45, 0.25, 4 * C + C / 2),
    beam(0.45, 0.35, 4 * C + C / 2),
]
_WALL5_Y = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]  # y 0.175–0.425


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev21-rel-03",  # two 4-storey columns 10 cm clear, a beam across the top …
            res(*column(0.45, 0.225, 4), *column(0.45, 0.375, 4), beam(0.45, 0.30, 0.225, YAW90)),
            res(*column(0.45, 0.25, 4), *column(0.45, 0.35, 4), beam(0.45, 0.30, 0.225, YAW90)),
        ),
        (
            "dev21-rel-03",  # … or a bar of four cubes; 3-storey columns are not it
            res(*column(0.45, 0.225, 4), *column(0.45, 0.375, 4), *_row_y(0.45, 0.225, 4, 4 * C)),
            res(*column(0.45, 0.225, 3), *column(0.45, 0.375, 3), *_row_y(0.45, 0.225, 4, 3 * C)),
        ),
        (
            "dev21-rel-06",  # five 3-storey columns left to right, one cube clear
            res(*[c for j in range(5) for c in column(0.45, 0.10 + 0.10 * j, 3)]),
            res(*[c for j in range(5) for c in column(0.45, 0.10 + 0.10 * j, 4)]),
        ),
        (
            "dev21-rel-11",  # a 4 by 4 plinth with a 3-storey column on each corner
            res(
                *grid(0.40, 0.20, 4, 4),
                *[c for x in (0.40, 0.55) for y in (0.20, 0.35) for c in column(x, y, 3, C)],
            ),
            res(  # the columns set in from the corners
                *grid(0.40, 0.20, 4, 4),
                *[c for x in (0.45, 0.50) for y in (0.25, 0.30) for c in column(x, y, 3, C)],
            ),
        ),
        (
            "dev21-rel-14",  # two towers of 3 at the back, a row of 4 in front of both
            res(*column(0.65, 0.20, 3), *column(0.65, 0.40, 3), *_row_y(0.40, 0.225, 4)),
            res(*column(0.55, 0.20, 3), *column(0.55, 0.40, 3), *_row_y(0.70, 0.225, 4)),
        ),
        (
            "dev21-rel-15",  # stairs 1, 2, 3 with a 2-cube tower on the top step
            res(*_stairs_x(0.40, 0.30, (1, 2, 5))),
            res(*_stairs_x(0.40, 0.30, (1, 4, 3))),  # the tower on the middle step
        ),
        (
            "dev21-rel-16",  # a portico: four 3-storey columns under a slab of cubes …
            res(*_PORTICO_LEGS3, *grid(0.40, 0.25, 3, 3, z0=3 * C)),
            res(
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2)],
                *grid(0.40, 0.25, 3, 3, z0=2 * C),
            ),
        ),
        (
            "dev21-rel-16",  # … or under beams; three columns are not four
            res(*_PORTICO_LEGS3, *_PORTICO_BEAMS3),
            res(*_PORTICO_LEGS3[3:], *grid(0.40, 0.25, 3, 3, z0=3 * C)),
        ),
        (
            "dev21-rel-17",  # a 6-tower in the middle, one row of 3 on its right (-y)
            res(*column(0.45, 0.30, 6), *_row_x(0.40, 0.15, 3)),
            res(*column(0.45, 0.30, 6), *_row_x(0.40, 0.45, 3)),
        ),
        (
            "dev21-rel-17",  # built against its right side is fine too
            res(*column(0.45, 0.30, 6), *_row_y(0.45, 0.15, 3)),
            res(*column(0.45, 0.30, 6), *_row_y(0.45, 0.15, 3), *_row_y(0.45, 0.35, 3)),
        ),
        (
            "dev21-rel-18",  # a 5-tower in the centre, a single cube one clear on each side
            res(
                *column(0.45, 0.30, 5),
                *[cube(x, y, C / 2) for x, y in ((0.35, 0.30), (0.55, 0.30))],
                *[cube(x, y, C / 2) for x, y in ((0.45, 0.20), (0.45, 0.40))],
            ),
            res(  # two cubes clear
                *column(0.45, 0.30, 5),
                *[cube(x, y, C / 2) for x, y in ((0.30, 0.30), (0.60, 0.30))],
                *[cube(x, y, C / 2) for x, y in ((0.45, 0.15), (0.45, 0.45))],
            ),
        ),
        (
            "dev21-rel-20",  # a 2-storey column on the slab's rear (+x) left (+y) corner
            res(*grid(0.40, 0.25, 3, 3), *column(0.50, 0.35, 2, C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 2, C)),
        ),
        (
            "dev21-seq-08",  # a 3-level pyramid less its top two levels: the base slab
            res(*grid(0.40, 0.25, 3, 3)),
            res(*grid(0.40, 0.25, 3, 3), *grid(0.425, 0.275, 2, 2, z0=C)),
        ),
        (
            "dev21-seq-12",  # a wall of 5 × 2 along y, a 4-tower on its left (+y) end
            res(*_WALL5_Y, *column(0.45, 0.40, 4, 2 * C)),
            res(*_WALL5_Y, *column(0.45, 0.20, 4, 2 * C)),
        ),
        (
            "dev21-seq-17",  # a 2×2×3 tower with one cube on one corner only
            res(*grid(0.45, 0.30, 2, 2, layers=3), cube(0.45, 0.30, 3 * C + C / 2)),
            res(*grid(0.45, 0.30, 2, 2, layers=4)),
        ),
        (
            "dev21-seq-20",  # the top cube moved onto the table at the tower's left …
            res(*column(0.45, 0.30, 3), cube(0.45, 0.40, C / 2)),
            res(*column(0.45, 0.30, 3), cube(0.45, 0.20, C / 2)),
        ),
        (
            "dev21-seq-20",  # … set down against it is fine; left on top is not
            res(*column(0.45, 0.30, 3), cube(0.45, 0.35, C / 2)),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev21-num-15",  # three rows of 4 along y, one behind the other, a cube apart
            res(*_row_y(0.40, 0.225, 4), *_row_y(0.50, 0.225, 4), *_row_y(0.60, 0.225, 4)),
            res(*_row_y(0.40, 0.225, 4), *_row_y(0.50, 0.225, 4)),
        ),
        (
            "dev21-num-18",  # five columns across: 2, 4, 2, 4, 2 high, one cube apart
            res(
                *[c for j, h in enumerate((2, 4, 2, 4, 2)) for c in column(0.45, 0.10 + 0.1 * j, h)]
            ),
            res(
                *[c for j, h in enumerate((4, 2, 4, 2, 4)) for c in column(0.45, 0.10 + 0.1 * j, h)]
            ),
        ),
        (
            "dev21-dim-08",  # four steps, each two cubes deep
            res(*_stairs_x(0.30, 0.30, (1, 1, 2, 2, 3, 3, 4, 4))),
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev21-dim-19",  # a flat T: bar of 5 along y, stem of 3 more along x
            res(*_row_y(0.40, 0.20, 5), *_row_x(0.45, 0.30, 3)),
            res(*_row_y(0.40, 0.20, 5), *_row_x(0.45, 0.20, 3)),  # stem at the end: an L
        ),
        (
            "dev21-dim-20",  # a beam centred across a 3-storey column, 5 cm out each side
            res(*column(0.45, 0.30, 3), beam(0.45, 0.30, 3 * C + C / 2, YAW90)),
            res(*column(0.45, 0.30, 3), beam(0.45, 0.35, 3 * C + C / 2, YAW90)),
        ),
        (
            "dev21-neg-14",  # a bridge with a bar of cubes, not a beam
            res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), *_row_y(0.45, 0.25, 3, 2 * C)),
            BRIDGE,
        ),
        (
            "dev21-reg-11",  # a 2-tower front left, another back right
            res(*column(0.30, 0.45, 2), *column(0.65, 0.15, 2)),
            res(*column(0.30, 0.15, 2), *column(0.65, 0.45, 2)),
        ),
        (
            "dev21-open-11",  # any few columns of one height in a line
            res(*[c for i in range(4) for c in column(0.30 + 0.10 * i, 0.30, 3)]),
            res(*[c for i in range(4) for c in column(0.30 + 0.10 * i, 0.30, i + 2)]),
        ),
        (
            "dev21-bad-06",  # "don't build anything": nothing on the table …
            res(),
            res(*column(0.45, 0.30, 6)),
        ),
        (
            "dev21-bad-06",  # … or an honest refusal
            NO_LAYOUT,
            res(*column(0.45, 0.30, 4), notes=["built the first tower"]),
        ),
        (
            "dev21-bad-20",  # 1 + 10 levels: refuse, or shorten the column and say so
            res(*grid(0.35, 0.15, 6, 6), *column(0.45, 0.30, 9, C), notes=["column cut to 9"]),
            res(*grid(0.35, 0.15, 6, 6), *column(0.45, 0.30, 9, C)),
        ),
        (
            "dev21-bad-02",  # wholly in German: a noted reading is honest, a silent one is not
            res(*column(0.45, 0.45, 4), notes=["read as German: a tower of four on the left"]),
            res(*column(0.45, 0.45, 4)),
        ),
    ],
)
def test_dev21_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _case(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
