"""The dev24 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev24 import CASES as DEV24

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


def _bridge_y(x, y, legs):
    """Two piers `legs` high at y ± one cube (one cube clear), a beam across them along y."""
    return [*column(x, y - C, legs), *column(x, y + C, legs), beam(x, y, C * legs + C / 2, YAW90)]


def _dev24(case_id: str) -> Case:
    return next(c for c in DEV24 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV24) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV24) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV24} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV24)
    ids = [c.id for c in DEV24]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev24-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV24:
        assert c.id.startswith(f"dev24-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev24"):
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
    for c in DEV24:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV24}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV24:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev24.py").read_text(encoding="utf-8")
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

_WALL5X2_Y = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]  # y 0.175–0.425
_L_AT = [  # an L of 2-high columns: arm of 4 along x from (0.40, 0.20), arm of 3 along y
    *[c for i in range(4) for c in column(0.40 + C * i, 0.20, 2)],
    *[c for j in (1, 2) for c in column(0.40, 0.20 + C * j, 2)],
]
_SLAB4X2 = grid(0.40, 0.25, 4, 2)  # x 0.375–0.575, y 0.225–0.325


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev24-rel-04",  # a 3-tower against the front face of the wall, at its middle
            res(*_WALL5X2_Y, *column(0.40, 0.30, 3)),
            res(*_WALL5X2_Y, *column(0.40, 0.20, 3)),  # in front of one end
        ),
        (
            "dev24-rel-06",  # a 3-tower free in the exact centre of a 5 x 5 ring
            res(*ring(0.40, 0.20, 5), *column(0.50, 0.30, 3)),
            res(*ring(0.40, 0.20, 5), *column(0.45, 0.25, 3)),  # against the ring's corner
        ),
        (
            "dev24-rel-07",  # stairs of 3 leading up to a 4-tower, set against it …
            res(*_stairs_y(0.45, 0.15, (1, 2, 3, 4))),
            res(*_stairs_y(0.45, 0.15, (4, 1, 2, 3))),  # the tower at the low end
        ),
        (
            "dev24-rel-07",  # … or standing clear off the high end
            res(*_stairs_y(0.45, 0.15, (1, 2, 3)), *column(0.45, 0.35, 4)),
            res(*_stairs_y(0.45, 0.25, (1, 2, 3)), *column(0.45, 0.15, 4)),  # off the low end
        ),
        (
            "dev24-rel-09",  # a 2-tower on each side of a bridge with legs of 3
            res(*_bridge_y(0.45, 0.30, 3), *column(0.45, 0.15, 2), *column(0.45, 0.45, 2)),
            res(*_bridge_y(0.45, 0.30, 3), *column(0.60, 0.25, 2), *column(0.60, 0.35, 2)),
        ),
        (
            "dev24-rel-13",  # a crate tucked into the L's inside corner, touching both arms …
            res(*_L_AT, cube(0.45, 0.25, C / 2)),
            res(*_L_AT, cube(0.35, 0.15, C / 2)),  # at the outside corner
        ),
        (
            "dev24-rel-13",  # … or standing clear in the corner
            res(*_L_AT, cube(0.50, 0.30, C / 2)),
            res(*_L_AT, cube(0.50, 0.30, C / 2), cube(0.55, 0.35, C / 2)),  # two crates
        ),
        (
            "dev24-rel-16",  # one cube against each of the tower's four sides
            res(
                *column(0.45, 0.30, 3),
                *[cube(x, y, C / 2) for x, y in ((0.40, 0.30), (0.50, 0.30), (0.45, 0.25))],
                cube(0.45, 0.35, C / 2),
            ),
            res(
                *column(0.45, 0.30, 3),
                *[cube(x, y, C / 2) for x, y in ((0.40, 0.30), (0.50, 0.30), (0.45, 0.25))],
            ),
        ),
        (
            "dev24-rel-21",  # a 2-tower on each corner of a 4 x 2 slab
            res(
                *_SLAB4X2,
                *[c for x in (0.40, 0.55) for y in (0.25, 0.30) for c in column(x, y, 2, z0=C)],
            ),
            res(
                *_SLAB4X2,
                *[c for x in (0.45, 0.50) for y in (0.25, 0.30) for c in column(x, y, 2, z0=C)],
            ),  # on the middle cells
        ),
        (
            "dev24-rel-22",  # three 2-pillars 2 apart along the front, the middle one crated
            res(*column(0.30, 0.15, 2), *column(0.30, 0.30, 3), *column(0.30, 0.45, 2)),
            res(*column(0.30, 0.15, 3), *column(0.30, 0.30, 2), *column(0.30, 0.45, 2)),
        ),
        (
            "dev24-seq-04",  # the end tiles of a row of 4 raised to level 3 …
            res(*_stairs_y(0.45, 0.20, (3, 1, 1, 3))),
            res(*_stairs_y(0.45, 0.20, (3, 3, 1, 1))),  # the first two raised
        ),
        (
            "dev24-seq-04",  # … or, counting the ground as level 0, to four high
            res(*_stairs_y(0.45, 0.20, (4, 1, 1, 4))),
            res(*_stairs_y(0.45, 0.20, (4, 1, 1, 3))),
        ),
        (
            "dev24-seq-05",  # half of a 6 x 2 wall: the top course off …
            res(*_row_y(0.45, 0.15, 6)),
            res(*_row_y(0.45, 0.15, 6), *_row_y(0.45, 0.15, 6, z0=C)),  # nothing removed
        ),
        (
            "dev24-seq-05",  # … or one end half off
            res(*_row_y(0.45, 0.15, 3), *_row_y(0.45, 0.15, 3, z0=C)),
            res(*_stairs_y(0.45, 0.15, (2, 2, 2, 1, 1, 1))),  # half of the top course only
        ),
        (
            "dev24-seq-08",  # a bridge with one block on the middle of its top
            res(*BRIDGE["layout"]["objects"], cube(0.45, 0.30, 0.175)),
            res(*BRIDGE["layout"]["objects"], cube(0.45, 0.35, 0.175)),  # over one leg
        ),
        (
            "dev24-seq-13",  # a row of 5 along the front, a 3-tower on its right (-y) end
            res(*_stairs_y(0.30, 0.20, (4, 1, 1, 1, 1))),
            res(*_stairs_y(0.30, 0.20, (1, 1, 1, 1, 4))),  # on the left end
        ),
        (
            "dev24-seq-14",  # three 2-pillars 1 apart along the back, the middle one deleted
            res(*column(0.65, 0.20, 2), *column(0.65, 0.40, 2)),
            res(*column(0.65, 0.20, 2), *column(0.65, 0.30, 2)),  # an end one deleted
        ),
        (
            "dev24-seq-16",  # the top 3 of an 8-tower moved one cube off to its right
            res(*column(0.45, 0.35, 5), *column(0.45, 0.25, 3)),
            res(*column(0.45, 0.25, 5), *column(0.45, 0.35, 3)),  # to its left
        ),
        (
            "dev24-seq-20",  # 2, 3, 4 one cube apart, the middle one taken away
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 4)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 4)),  # closed up
        ),
        (
            "dev24-num-04",  # a 2 x 2 x 2 block centred on a 4 x 4 floor
            res(*grid(0.40, 0.20, 4, 4), *grid(0.45, 0.25, 2, 2, layers=2, z0=C)),
            res(*grid(0.40, 0.20, 4, 4), *grid(0.40, 0.20, 2, 2, layers=2, z0=C)),  # a corner
        ),
        (
            "dev24-num-09",  # 6 crates, 2 by 3, one tile apart each way
            res(
                *[cube(0.40 + 0.10 * i, 0.20 + 0.10 * j, C / 2) for i in range(2) for j in range(3)]
            ),
            res(
                *[cube(0.40 + 0.15 * i, 0.20 + 0.10 * j, C / 2) for i in range(2) for j in range(3)]
            ),  # two tiles apart one way
        ),
        (
            "dev24-num-14",  # 4, 3, 2, 1 from left (+y) to right, one tile apart
            res(*[c for j, h in enumerate((4, 3, 2, 1)) for c in column(0.45, 0.45 - 0.10 * j, h)]),
            res(*[c for j, h in enumerate((1, 2, 3, 4)) for c in column(0.45, 0.45 - 0.10 * j, h)]),
        ),
        (
            "dev24-num-17",  # walls 5 x 2 and 5 x 3, parallel, two cubes apart
            res(
                *_stairs_y(0.40, 0.20, (2,) * 5),
                *_stairs_y(0.55, 0.20, (3,) * 5),
            ),
            res(
                *_stairs_y(0.40, 0.20, (2,) * 5),
                *_stairs_y(0.55, 0.20, (2,) * 5),  # the same height
            ),
        ),
        (
            "dev24-neg-12",  # three 2-towers, not all in a straight line
            res(*column(0.40, 0.20, 2), *column(0.40, 0.40, 2), *column(0.60, 0.30, 2)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 2), *column(0.45, 0.45, 2)),
        ),
        (
            "dev24-neg-15",  # posts of 2 with a top of cubes, no beam
            res(*column(0.45, 0.20, 2), *column(0.45, 0.35, 2), *_row_y(0.45, 0.20, 4, z0=2 * C)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.35, 2), beam(0.45, 0.275, 0.125, YAW90)),
        ),
        (
            "dev24-dim-12",  # a little table: four legs of 2 under a 3 x 3 cube top
            res(
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2)],
                *grid(0.40, 0.25, 3, 3, z0=2 * C),
            ),
            res(
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 3)],
                *grid(0.40, 0.25, 3, 3, z0=3 * C),  # legs of 15 cm
            ),
        ),
        (
            "dev24-wo-13",  # stairs on the pillar's left, climbing right (-y) up to it
            res(*_stairs_y(0.45, 0.20, (4, 3, 2, 1))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),  # on its right
        ),
        (
            "dev24-num-08",  # two and three, next to each other: touching …
            res(*column(0.45, 0.30, 2), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.30, 2), *column(0.45, 0.35, 2)),
        ),
        (
            "dev24-num-08",  # … or clear
            res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 3)),
            res(*column(0.25, 0.10, 2), *column(0.75, 0.50, 3)),  # across the table
        ),
        (
            "dev24-bad-02",  # wholly in French: a noted reading is honest, a silent one is not
            res(*column(0.45, 0.45, 4), notes=["read as French: a tower of four on the left"]),
            res(*column(0.45, 0.45, 4)),
        ),
        (
            "dev24-bad-04",  # 60 cm: past the cell; refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 10)),
        ),
    ],
)
def test_dev24_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev24(case_id)
    assert case.accept(right) is None, case.accept(right)
    assert case.accept(wrong) is not None
