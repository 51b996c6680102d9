"""The dev27 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev27 import CASES as DEV27

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


def _stairs_y(x, y0, hs):
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _without(objs, *xy):
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o):
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _triangle(x, y0, n):
    """An upright triangle of cubes one cube thick along y: n cubes at the bottom, each level
    one fewer, set half a cube in, from y0 (the bottom-right cube's centre)."""
    return [
        cube(x, y0 + C * (level / 2 + j), C / 2 + C * level)
        for level in range(n)
        for j in range(n - level)
    ]


def _dev27(case_id: str) -> Case:
    return next(c for c in DEV27 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV27) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV27) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV27} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV27)
    ids = [c.id for c in DEV27]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev27-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV27:
        assert c.id.startswith(f"dev27-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev27"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    others = _other_sets()
    assert "language_dev25" in others and "language_dev26" in others
    seen: dict[str, str] = {}
    for c in DEV27:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV27}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV27:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev27.py").read_text(encoding="utf-8")
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
_ROW5_FRONT = _row_y(0.30, 0.20, 5)  # x 0.275–0.325, y 0.175–0.425
_WALL6X2_BACK = [*_row_y(0.65, 0.175, 6), *_row_y(0.65, 0.175, 6, z0=C)]  # x 0.625–0.675
_PYR_16_9_4 = [
    *_SLAB4,
    *grid(0.40, 0.25, 3, 3, z0=C),
    *grid(0.40, 0.25, 2, 2, z0=2 * C),
]
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_CORNERS = [(0.30, 0.45), (0.30, 0.15), (0.65, 0.45), (0.65, 0.15)]
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev27-rel-01",  # a 2-tower right next to a front-left 4-tower, a cube clear …
            res(*column(0.30, 0.45, 4), *column(0.30, 0.35, 2)),
            res(*column(0.30, 0.45, 4), *column(0.30, 0.15, 2)),  # across the table
        ),
        (
            "dev27-rel-01",  # … or set against it
            res(*column(0.30, 0.45, 4), *column(0.30, 0.40, 2)),
            res(*column(0.65, 0.45, 4), *column(0.65, 0.40, 2)),  # at the back left
        ),
        (
            "dev27-rel-03",  # one cube on the middle of a 3 x 3 slab
            res(*_SLAB3, cube(0.45, 0.30, 0.075)),
            res(*_SLAB3, cube(0.40, 0.25, 0.075)),  # on a corner
        ),
        (
            "dev27-rel-05",  # a 2-tower in the middle of a 5 x 5 ring
            res(*_PEN5, *column(0.45, 0.30, 2)),
            res(*_PEN5, *column(0.70, 0.30, 2)),  # outside it
        ),
        (
            "dev27-rel-06",  # a 2 x 2 x 3 block behind the middle of a front row of 5 …
            res(*_ROW5_FRONT, *grid(0.45, 0.275, 2, 2, layers=3)),
            res(*_ROW5_FRONT, *grid(0.45, 0.375, 2, 2, layers=3)),  # behind its end
        ),
        (
            "dev27-rel-06",  # … or set against its middle
            res(*_ROW5_FRONT, *grid(0.35, 0.25, 2, 2, layers=3)),
            res(*_ROW5_FRONT, *grid(0.35, 0.20, 2, 2, layers=3)),  # against its end
        ),
        (
            "dev27-rel-08",  # a 4-tower set against the front of a back wall
            res(*_WALL6X2_BACK, *column(0.60, 0.30, 4)),
            res(*_WALL6X2_BACK, *column(0.70, 0.30, 4)),  # against its back
        ),
        (
            "dev27-rel-13",  # 2, 6, 2 in a line, a cube between neighbours
            res(*column(0.45, 0.15, 2), *column(0.45, 0.25, 6), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.25, 2), *column(0.45, 0.35, 6)),
        ),
        (
            "dev27-rel-15",  # a 5 x 3 wall with a cube on top of each end
            res(*_stairs_y(0.45, 0.20, (4, 3, 3, 3, 4))),
            res(*_stairs_y(0.45, 0.15, (1, 3, 3, 3, 3, 3, 1))),  # beside the ends
        ),
        (
            "dev27-rel-17",  # a 3-tower on the back-left corner cube of a 4 x 4 slab
            res(*_SLAB4, *column(0.55, 0.40, 3, C)),
            res(*_SLAB4, *column(0.40, 0.40, 3, C)),  # on the front-left corner
        ),
        (
            "dev27-rel-20",  # a 4-tower between two front-to-back rows of three
            res(*_row_x(0.40, 0.20, 3), *column(0.45, 0.30, 4), *_row_x(0.40, 0.40, 3)),
            res(*_row_x(0.40, 0.20, 3), *_row_x(0.40, 0.30, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev27-seq-09",  # a 4 x 4-based pyramid less its top cube: 16-9-4 …
            res(*_PYR_16_9_4),
            res(*_PYR_16_9_4, cube(0.425, 0.275, 0.175)),  # the top cube kept
        ),
        (
            "dev27-seq-09",  # … or 16-4
            res(*_SLAB4, *grid(0.45, 0.30, 2, 2, z0=C)),
            res(*_SLAB4, *grid(0.45, 0.30, 2, 2, z0=C), cube(0.475, 0.325, 0.125)),
        ),
        (
            "dev27-seq-10",  # three 2-towers a cube apart, the middle one taken away
            res(*column(0.45, 0.15, 2), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.25, 2), *column(0.45, 0.35, 2)),
        ),
        (
            "dev27-seq-11",  # a flat 4 x 4 L with a 3-tower on its corner
            res(*_row_y(0.40, 0.25, 4), *_row_x(0.45, 0.25, 3), *column(0.40, 0.25, 3, C)),
            res(*_row_y(0.40, 0.25, 4), *_row_x(0.45, 0.25, 3), *column(0.55, 0.25, 3, C)),
        ),
        (
            "dev27-seq-18",  # a 3 x 3 slab on the left with a 2-tower on each corner
            res(
                *grid(0.40, 0.35, 3, 3),
                *[c for x in (0.40, 0.50) for y in (0.35, 0.45) for c in column(x, y, 2, C)],
            ),
            res(
                *grid(0.40, 0.35, 3, 3),
                *[c for x in (0.40, 0.50) for y in (0.35, 0.45) for c in column(x, y, 3, C)],
            ),
        ),
        (
            "dev27-seq-19",  # the left (+y) of two 4-towers one cube shorter
            res(*column(0.45, 0.35, 3), *column(0.45, 0.25, 4)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 4)),  # the right one shortened
        ),
        (
            "dev27-num-02",  # heights 1, 2, 3, 4 from left (+y) to right, a cube apart
            res(
                *[c for i, y in enumerate((0.45, 0.35, 0.25, 0.15)) for c in column(0.45, y, i + 1)]
            ),
            res(
                *[c for i, y in enumerate((0.15, 0.25, 0.35, 0.45)) for c in column(0.45, y, i + 1)]
            ),
        ),
        (
            "dev27-num-10",  # a 3-tower and a 6-tower side by side, touching …
            res(*column(0.45, 0.30, 3), *column(0.45, 0.35, 6)),
            res(*column(0.45, 0.30, 3), *column(0.45, 0.35, 5)),  # not twice as tall
        ),
        (
            "dev27-num-10",  # … or clear and close
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 6)),
            res(*column(0.25, 0.30, 3), *column(0.70, 0.30, 6)),  # 40 cm apart
        ),
        (
            "dev27-num-16",  # a 3-stack in each corner of the table
            res(*[c for x, y in _CORNERS for c in column(x, y, 3)]),
            res(*[c for x, y in [*_CORNERS[:3], (0.45, 0.30)] for c in column(x, y, 3)]),
        ),
        (
            "dev27-num-19",  # an upright triangle 4-3-2-1, one cube thick
            res(*_triangle(0.45, 0.225, 4)),
            res(*_triangle(0.45, 0.225, 3)),  # a bottom row of three
        ),
        (
            "dev27-neg-10",  # a 4 x 4 ring, one high, a doorway in its front (robot) side
            res(*_without(ring(0.40, 0.25, 4), (0.40, 0.30))),
            res(*_without(ring(0.40, 0.25, 4), (0.55, 0.30))),  # in the back side
        ),
        (
            "dev27-neg-13",  # a 3-tower and a 5-tower at opposite ends of the table
            res(*column(0.45, 0.45, 3), *column(0.45, 0.15, 5)),
            res(*column(0.45, 0.30, 3), *column(0.45, 0.45, 5)),  # the centre and the left
        ),
        (
            "dev27-wo-07",  # a 4-tower on the right, 100 mm in from the back edge (x 0.80)
            res(*column(0.70, 0.15, 4)),
            res(*column(0.55, 0.15, 4)),
        ),
        (
            "dev27-reg-12",  # 150 in from the left edge (y 0.55), 300 out from the robot
            res(*column(0.30, 0.40, 5)),
            res(*column(0.40, 0.30, 5)),  # the two figures swapped
        ),
        (
            "dev27-bad-04",  # no 30 mm cubes: refuse, or build with 50 mm ones and say so
            res(*column(0.45, 0.30, 3), notes=["only 50 mm cubes are stocked; used those"]),
            res(*column(0.45, 0.30, 3)),
        ),
        (
            "dev27-bad-12",  # the request was cancelled: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 4), notes=["the request was cancelled"]),
        ),
    ],
)
def test_dev27_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev27(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
