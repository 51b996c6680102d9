"""The dev23 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev23 import CASES as DEV23

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


def _stairs_y(x, y0, hs):
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _stairs_x(x0, y, hs):
    """Columns of the given heights in a line along x from x0 (front to back)."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _bridge_y(x, y, legs):
    """Two posts `legs` high at y ± one cube (one cube clear), a beam across them along y."""
    return [*column(x, y - C, legs), *column(x, y + C, legs), beam(x, y, C * legs + C / 2, YAW90)]


def _without(objs, *xy):
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o):
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _dev23(case_id: str) -> Case:
    return next(c for c in DEV23 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV23) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV23) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV23} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV23)
    ids = [c.id for c in DEV23]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev23-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV23:
        assert c.id.startswith(f"dev23-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev23"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    others = _other_sets()
    assert "language_dev19" in others and "language_dev22" in others
    seen: dict[str, str] = {}
    for c in DEV23:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV23}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV23:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev23.py").read_text(encoding="utf-8")
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

_WALL6X2_AT_BACK = [*_row_y(0.50, 0.175, 6), *_row_y(0.50, 0.175, 6, z0=C)]  # y 0.15–0.45
_PYR2 = [*grid(0.40, 0.25, 3, 3), cube(0.45, 0.30, 0.075)]  # x 0.375–0.525, y 0.225–0.375
_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375
_CORNERS3 = ((0.40, 0.25), (0.40, 0.35), (0.50, 0.25), (0.50, 0.35))
_EDGES3 = ((0.40, 0.30), (0.50, 0.30), (0.45, 0.25), (0.45, 0.35))
_BENCH = [*column(0.45, 0.25, 1), *column(0.45, 0.35, 1), beam(0.45, 0.30, 0.075, YAW90)]
_TABLE2 = [  # four legs 2 high on the corners of a 3 by 3 cube top, x 0.375–0.525
    *[c for x, y in _CORNERS3 for c in column(x, y, 2)],
    *grid(0.40, 0.25, 3, 3, z0=2 * C),
]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev23-rel-03",  # a 3-tower 2 clear in front of the middle of a 6 x 2 wall
            res(*_WALL6X2_AT_BACK, *column(0.35, 0.30, 3)),
            res(*_WALL6X2_AT_BACK, *column(0.35, 0.175, 3)),  # in front of one end
        ),
        (
            "dev23-rel-04",  # a 2-column against the right (-y) of a 4-tower
            res(*column(0.45, 0.30, 4), *column(0.45, 0.25, 2)),
            res(*column(0.45, 0.30, 4), *column(0.45, 0.35, 2)),  # on its left
        ),
        (
            "dev23-rel-07",  # a 3-tower inside a 5 x 5 pen
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 3)),  # outside it
        ),
        (
            "dev23-rel-08",  # towers of 5 with a 5-cube gap, a 2-level pyramid in the gap
            res(*column(0.45, 0.15, 5), *column(0.45, 0.45, 5), *_PYR2),
            res(
                *column(0.45, 0.15, 5),
                *column(0.45, 0.45, 5),
                *grid(0.60, 0.25, 3, 3),
                cube(0.65, 0.30, 0.075),
            ),  # the pyramid behind the gap, not in it
        ),
        (
            "dev23-rel-09",  # a bridge with legs of 3 and one cube on the middle of the deck
            res(*_bridge_y(0.45, 0.30, 3), cube(0.45, 0.30, 0.225)),
            res(*_bridge_y(0.45, 0.30, 3), cube(0.45, 0.25, 0.225)),  # over one leg
        ),
        (
            "dev23-rel-10",  # a 5-lamp post clear of the bench's left (+y) end …
            res(*_BENCH, *column(0.45, 0.45, 5)),
            res(*_BENCH, *column(0.45, 0.15, 5)),  # at its right end
        ),
        (
            "dev23-rel-10",  # … or set against it
            res(*_BENCH, *column(0.45, 0.40, 5)),
            res(*_BENCH, *column(0.45, 0.40, 4)),
        ),
        (
            "dev23-rel-14",  # a 3 x 3 slab with a cube on every corner
            res(*_SLAB3, *[cube(x, y, 0.075) for x, y in _CORNERS3]),
            res(*_SLAB3, *[cube(x, y, 0.075) for x, y in _EDGES3]),  # on the edge middles
        ),
        (
            "dev23-rel-15",  # a table on legs of 2 and a 2-column stool one cube clear of it
            res(*_TABLE2, *column(0.30, 0.30, 2)),
            res(*_TABLE2, *column(0.25, 0.30, 2)),  # two cubes clear
        ),
        (
            "dev23-rel-18",  # stairs climbing back, a 4-tower against the top step
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4, 4))),
            res(*_stairs_x(0.30, 0.30, (4, 1, 2, 3, 4))),  # against the bottom step
        ),
        (
            "dev23-rel-19",  # a 3 x 3 x 2 house with a 2-cube chimney on one corner
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.40, 0.25, 2, z0=2 * C)),
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.45, 0.30, 2, z0=2 * C)),
        ),
        (
            "dev23-rel-20",  # a 5 x 2 wall with a 3-tower touching each end, in line
            res(*_stairs_y(0.45, 0.125, (3, 2, 2, 2, 2, 2, 3))),
            res(*_stairs_y(0.45, 0.20, (3, 2, 2, 2, 3))),  # the wall's own end columns raised
        ),
        (
            "dev23-seq-03",  # 4 x 4 slab, a 2 x 2 on its centre, a cube on top of that
            res(*grid(0.40, 0.25, 4, 4), *grid(0.45, 0.30, 2, 2, z0=C), cube(0.475, 0.325, 0.125)),
            res(*grid(0.40, 0.25, 4, 4), *grid(0.40, 0.25, 2, 2, z0=C), cube(0.425, 0.275, 0.125)),
        ),
        (
            "dev23-seq-10",  # a 5 chimney with a 2 x 2 wall touching on either side
            res(*_stairs_y(0.45, 0.20, (2, 2, 5, 2, 2))),
            res(*_stairs_y(0.45, 0.20, (2, 5, 2))),
        ),
        (
            "dev23-seq-14",  # a 3-level pyramid less its top, a 2-tower in its place
            res(
                *grid(0.40, 0.25, 3, 3),
                *grid(0.40, 0.25, 2, 2, z0=C),
                *column(0.425, 0.275, 2, 2 * C),
            ),
            res(*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C), cube(0.425, 0.275, 0.125)),
        ),
        (
            "dev23-seq-20",  # podium 2, 3, 2 after raising the lowest place: one block …
            res(*_stairs_y(0.45, 0.25, (2, 3, 2))),
            res(*_stairs_y(0.45, 0.25, (2, 3, 1))),
        ),
        (
            "dev23-seq-20",  # … or separate places in a line
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 3), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.10, 2), *column(0.45, 0.30, 3), *column(0.45, 0.50, 2)),
        ),
        (
            "dev23-num-05",  # winner 4 in the middle, 3 and 2 on either side
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 4), *column(0.45, 0.40, 3)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev23-num-08",  # 8 single cubes, two rows of four, a cube between every cube
            res(*[cube(x, 0.15 + 0.10 * j, C / 2) for x in (0.40, 0.50) for j in range(4)]),
            res(*[cube(x, 0.15 + 0.10 * j, C / 2) for x in (0.40, 0.55) for j in range(4)]),
        ),
        (
            "dev23-num-10",  # a bench: a seat of four cubes on two legs of one
            res(*column(0.45, 0.20, 1), *column(0.45, 0.35, 1), *_row_y(0.45, 0.20, 4, z0=C)),
            res(*_BENCH),  # a beam seat, three long
        ),
        (
            "dev23-num-16",  # a 2-tower on each corner of a one-layer 3 x 3 slab
            res(*_SLAB3, *[c for x, y in _CORNERS3 for c in column(x, y, 2, z0=C)]),
            res(*_SLAB3, *[c for x, y in _CORNERS3 for c in column(x, y, 1, z0=C)]),
        ),
        (
            "dev23-neg-05",  # four bare legs of 2, two cubes apart in a square
            res(*[c for x in (0.40, 0.55) for y in (0.25, 0.40) for c in column(x, y, 2)]),
            res(
                *[c for x in (0.40, 0.55) for y in (0.25, 0.40) for c in column(x, y, 2)],
                *grid(0.40, 0.25, 4, 4, z0=2 * C),
            ),  # the top left on
        ),
        (
            "dev23-neg-13",  # a 4 x 4 ring with one cube out of its front side
            res(*_without(ring(0.40, 0.25, 4), (0.40, 0.30))),
            res(*_without(ring(0.40, 0.25, 4), (0.55, 0.30))),  # out of the back side
        ),
        (
            "dev23-neg-14",  # a 3-level pyramid with its top cube left off
            res(*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), cube(0.45, 0.30, 0.075)),  # a 2-level, cube on top
        ),
        (
            "dev23-dim-15",  # coffee table 15 cm square, 10 cm high: legs of 1 under the top …
            res(*[c for x, y in _CORNERS3 for c in column(x, y, 1)], *grid(0.40, 0.25, 3, 3, z0=C)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),  # a solid block
        ),
        (
            "dev23-dim-15",  # … or legs of 2
            res(*_TABLE2),
            res(
                *[c for x, y in _CORNERS3 for c in column(x, y, 3)],
                *grid(0.40, 0.25, 3, 3, z0=3 * C),
            ),
        ),
        (
            "dev23-fil-05",  # posts of 3 with a bar of cubes across (taller posts rejected)
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3), *_row_y(0.45, 0.25, 3, z0=3 * C)),
            res(*column(0.45, 0.25, 4), *column(0.45, 0.35, 4), *_row_y(0.45, 0.25, 3, z0=4 * C)),
        ),
        (
            "dev23-rel-05",  # a doorway with sides of 4 and a 3-cube doormat one cube in front
            res(*_bridge_y(0.50, 0.30, 4), *_row_y(0.40, 0.25, 3)),
            res(*_bridge_y(0.50, 0.30, 4), *_row_y(0.60, 0.25, 3)),  # the mat behind it
        ),
        (
            "dev23-seq-18",  # the 4-tower moved to the bridge's right, two cubes clear
            res(*_bridge_y(0.45, 0.30, 2), *column(0.45, 0.10, 4)),
            res(*_bridge_y(0.45, 0.30, 2), *column(0.45, 0.50, 4)),  # left where it was
        ),
        (
            "dev23-wo-06",  # a tall bridge in the middle
            res(*_bridge_y(0.45, 0.30, 4)),
            res(*_bridge_y(0.45, 0.30, 2)),  # the default height
        ),
        (
            "dev23-typo-06",  # "stiars 5 up lft": climbing left …
            res(*_stairs_y(0.45, 0.15, (1, 2, 3, 4, 5))),
            res(*_stairs_y(0.45, 0.15, (5, 4, 3, 2, 1))),
        ),
        (
            "dev23-typo-06",  # … or standing on the left
            res(*_stairs_x(0.35, 0.45, (1, 2, 3, 4, 5))),
            res(*_stairs_x(0.35, 0.15, (1, 2, 3, 4, 5))),
        ),
        (
            "dev23-open-06",  # three different things
            res(*column(0.30, 0.45, 3), *_row_y(0.45, 0.15, 4), *grid(0.65, 0.35, 2, 2)),
            res(*column(0.30, 0.45, 3), *column(0.45, 0.15, 3), *column(0.65, 0.35, 3)),
        ),
        (
            "dev23-bad-02",  # wholly in Spanish: a noted reading is honest, a silent one is not
            res(*column(0.45, 0.30, 5), notes=["read as Spanish: a tower of five cubes"]),
            res(*column(0.45, 0.30, 5)),
        ),
        (
            "dev23-bad-04",  # a tower of 12: past the cell; refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev23-bad-01",  # a maintenance ticket, not a build: only a refusal is honest
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 3), notes=["read as: a tower"]),
        ),
    ],
)
def test_dev23_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev23(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
