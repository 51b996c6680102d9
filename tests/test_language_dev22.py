"""The dev22 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev22 import CASES as DEV22

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


def _plate(x0, y0, n, skip=()):
    """An n × n one-layer plate of cubes without the cells (i, j) in `skip`."""
    return [
        cube(x0 + C * i, y0 + C * j, C / 2)
        for i in range(n)
        for j in range(n)
        if (i, j) not in skip
    ]


def _dev22(case_id: str) -> Case:
    return next(c for c in DEV22 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV22) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV22) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV22} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV22)
    ids = [c.id for c in DEV22]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev22-") for i in ids)
    for c in DEV22:
        short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
        short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
        short |= {k.BAD: "bad"}
        assert c.id.startswith(f"dev22-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev22"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    others = _other_sets()
    assert "language_dev19" in others and "language_dev21" in others
    seen: dict[str, str] = {}
    for c in DEV22:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV22}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV22:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev22.py").read_text(encoding="utf-8")
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

_ROW6_Y = _row_y(0.45, 0.15, 6)  # x 0.45, y 0.125–0.425
_WALL5X2 = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]  # y 0.175–0.425
_SHED = [  # four legs 2 high on the corners of a 3 by 3 cube roof, x 0.475–0.625, y 0.225–0.375
    *column(0.50, 0.25, 2),
    *column(0.50, 0.35, 2),
    *column(0.60, 0.25, 2),
    *column(0.60, 0.35, 2),
    *grid(0.50, 0.25, 3, 3, z0=2 * C),
]
_SLAB_TRIMMED = [  # seq-18: a 4 x 4 slab without its corners, a 2 x 2 x 2 block on its middle
    *_plate(0.40, 0.25, 4, skip=((0, 0), (0, 3), (3, 0), (3, 3))),
    *grid(0.45, 0.30, 2, 2, layers=2, z0=C),
]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev22-rel-04",  # the post just past the platform's end, in line with it
            res(*_ROW6_Y, *column(0.45, 0.50, 4)),
            res(*_ROW6_Y, *column(0.35, 0.40, 4)),  # beside the platform, in front of its end
        ),
        (
            "dev22-rel-14",  # a 3-tower off each end of the wall
            res(*_WALL5X2, *column(0.45, 0.10, 3), *column(0.45, 0.50, 3)),
            res(*_WALL5X2, *column(0.35, 0.30, 3), *column(0.55, 0.30, 3)),  # front and back
        ),
        (
            "dev22-rel-10",  # stairs on the tower's right, climbing towards it (set against it)
            res(*_stairs_y(0.45, 0.15, (1, 2, 3, 5))),
            res(*_stairs_y(0.45, 0.15, (3, 2, 1, 5))),  # climbing away from the tower
        ),
        (
            "dev22-rel-10",  # … or clear of it
            res(*_stairs_y(0.45, 0.10, (1, 2, 3)), *column(0.45, 0.30, 5)),
            res(*_stairs_y(0.45, 0.35, (3, 2, 1)), *column(0.45, 0.20, 5)),  # on its left
        ),
        (
            "dev22-rel-11",  # a bridge with legs of 2 and one cube on the middle of the deck
            res(*BRIDGE["layout"]["objects"], cube(0.45, 0.30, 0.175)),
            res(*BRIDGE["layout"]["objects"], cube(0.45, 0.25, 0.175)),  # over one leg
        ),
        (
            "dev22-rel-17",  # a 3-tower inside a 4 x 4 ring, against its wall …
            res(*ring(0.40, 0.25, 4), *column(0.45, 0.30, 3)),
            res(*ring(0.40, 0.25, 4), *column(0.70, 0.30, 3)),  # outside the ring
        ),
        (
            "dev22-rel-17",  # … or standing free in the middle of it
            res(*ring(0.40, 0.25, 4), *column(0.475, 0.325, 3)),
            res(*ring(0.40, 0.25, 4), *column(0.475, 0.325, 2)),
        ),
        (
            "dev22-rel-08",  # a 150 mm column against the block's +Y (left) face
            res(*grid(0.45, 0.30, 2, 2), *column(0.45, 0.40, 3)),
            res(*grid(0.45, 0.30, 2, 2), *column(0.45, 0.25, 3)),  # against the -Y face
        ),
        (
            "dev22-rel-21",  # stairs climbing left, a 2-tower against the low (right) end
            res(*_stairs_y(0.45, 0.15, (2, 1, 2, 3))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 2))),  # against the high end
        ),
        (
            "dev22-rel-09",  # shed on four legs behind a platform of 5, one cube clear
            res(*_SHED, *_row_y(0.40, 0.20, 5)),
            res(*_SHED, *_row_y(0.70, 0.20, 5)),  # the platform behind the shed
        ),
        (
            "dev22-seq-14",  # the deck taken off the front bridge; the back one whole, 2 behind
            res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), *_bridge_y(0.60, 0.30, 2)),
            res(*_bridge_y(0.45, 0.30, 2), *column(0.60, 0.25, 2), *column(0.60, 0.35, 2)),
        ),
        (
            "dev22-seq-18",  # slab less its corners, a 2 x 2 x 2 block on the middle
            res(*_SLAB_TRIMMED),
            res(*grid(0.40, 0.25, 4, 4), *grid(0.45, 0.30, 2, 2, layers=2, z0=C)),  # corners on
        ),
        (
            "dev22-seq-15",  # a 4 x 3 wall less the top cube at both ends
            res(*_stairs_y(0.45, 0.20, (2, 3, 3, 2))),
            res(*_stairs_y(0.45, 0.20, (2, 3, 3, 3))),  # one end only
        ),
        (
            "dev22-num-03",  # four 2-columns on the corners of a 250 mm square (outside) …
            res(*[c for x in (0.40, 0.60) for y in (0.20, 0.40) for c in column(x, y, 2)]),
            res(*[c for j in range(4) for c in column(0.45, 0.15 + 0.10 * j, 2)]),  # a line
        ),
        (
            "dev22-num-03",  # … or 250 between the column centres
            res(*[c for x in (0.40, 0.65) for y in (0.20, 0.45) for c in column(x, y, 2)]),
            res(*[c for x in (0.40, 0.70) for y in (0.20, 0.50) for c in column(x, y, 2)]),
        ),
        (
            "dev22-num-15",  # a single cube against the left (+y) of each of three 2-towers
            res(
                *[
                    c
                    for x in (0.30, 0.45, 0.60)
                    for c in (*column(x, 0.30, 2), cube(x, 0.35, C / 2))
                ]
            ),
            res(
                *[
                    c
                    for x in (0.30, 0.45, 0.60)
                    for c in (*column(x, 0.30, 2), cube(x, 0.25, C / 2))
                ]
            ),
        ),
        (
            "dev22-num-17",  # 3 x 3 single cubes, one cube clear between neighbours
            res(
                *[cube(0.35 + 0.10 * i, 0.20 + 0.10 * j, C / 2) for i in range(3) for j in range(3)]
            ),
            res(
                *[cube(0.35 + 0.15 * i, 0.15 + 0.15 * j, C / 2) for i in range(3) for j in range(3)]
            ),
        ),
        (
            "dev22-num-04",  # three platforms of 4 side by side, one cube between
            res(*_row_y(0.30, 0.20, 4), *_row_y(0.40, 0.20, 4), *_row_y(0.50, 0.20, 4)),
            res(*_row_y(0.30, 0.20, 4), *_row_y(0.45, 0.20, 4), *_row_y(0.60, 0.20, 4)),
        ),
        (
            "dev22-neg-09",  # a platform of 6 with a one-cube footpath in the middle
            res(*_row_y(0.45, 0.15, 3), *_row_y(0.45, 0.35, 3)),
            res(*_row_y(0.45, 0.15, 6)),
        ),
        (
            "dev22-neg-13",  # a 4 x 4 plate without its two -Y (right) corners
            res(*_plate(0.40, 0.25, 4, skip=((0, 0), (3, 0)))),
            res(*_plate(0.40, 0.25, 4, skip=((0, 3), (3, 3)))),  # the +Y corners left out
        ),
        (
            "dev22-dim-17",  # gantry: posts of 4, 6 cubes apart, a bar of cubes across
            res(*column(0.45, 0.15, 4), *column(0.45, 0.50, 4), *_row_y(0.45, 0.15, 8, z0=4 * C)),
            res(*column(0.45, 0.15, 4), *column(0.45, 0.40, 4), *_row_y(0.45, 0.15, 6, z0=4 * C)),
        ),
        (
            "dev22-open-12",  # anything mirror-symmetric
            res(*_stairs_y(0.45, 0.25, (1, 2, 1))),
            res(*column(0.45, 0.30, 3), cube(0.50, 0.30, C / 2), *column(0.45, 0.35, 2)),
        ),
        (
            "dev22-bad-03",  # wholly in Swedish: a noted reading is honest, a silent one is not
            res(*column(0.45, 0.30, 4), notes=["read as Swedish: a tower of four cubes"]),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev22-bad-06",  # 750 mm: past the cell; refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 10)),
        ),
    ],
)
def test_dev22_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev22(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
