"""The dev25 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev25 import CASES as DEV25

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


def _dev25(case_id: str) -> Case:
    return next(c for c in DEV25 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV25) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV25) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV25} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV25)
    ids = [c.id for c in DEV25]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev25-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV25:
        assert c.id.startswith(f"dev25-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev25"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    others = _other_sets()
    assert "language_dev23" in others and "language_dev24" in others
    seen: dict[str, str] = {}
    for c in DEV25:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV25}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV25:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev25.py").read_text(encoding="utf-8")
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

_WALL6X2 = [*_row_y(0.45, 0.175, 6), *_row_y(0.45, 0.175, 6, z0=C)]  # along y, y 0.15–0.45
_WALL5X3_BACK = [c for h in range(3) for c in _row_y(0.55, 0.20, 5, z0=C * h)]  # x 0.525–0.575
_ROW5_FRONT = _row_y(0.35, 0.20, 5)  # x 0.325–0.375, y 0.175–0.425
_PYR2 = [*grid(0.40, 0.25, 3, 3), cube(0.45, 0.30, 0.075)]  # x 0.375–0.525, y 0.225–0.375
_PYR3 = [*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C), cube(0.425, 0.275, 0.125)]
_PYR4 = [
    *grid(0.40, 0.25, 4, 4),
    *grid(0.40, 0.25, 3, 3, z0=C),
    *grid(0.40, 0.25, 2, 2, z0=2 * C),
    cube(0.425, 0.275, 0.175),
]
_SLAB4 = grid(0.40, 0.25, 4, 4)  # x 0.375–0.575, y 0.225–0.425
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev25-rel-03",  # a 4-tower set against the back of a 6 x 2 wall
            res(*_WALL6X2, *column(0.50, 0.325, 4)),
            res(*_WALL6X2, *column(0.40, 0.325, 4)),  # against its front
        ),
        (
            "dev25-rel-06",  # a beam bridge on pillars of 3, one cube centred on the beam
            res(*_bridge_y(0.45, 0.30, 3), cube(0.45, 0.30, 0.225)),
            res(*_bridge_y(0.45, 0.30, 3), cube(0.45, 0.25, 0.225)),  # over one pillar
        ),
        (
            "dev25-rel-10",  # a 2-column against the left (+y) of a 5-tower
            res(*column(0.45, 0.30, 5), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.25, 2)),  # on its right
        ),
        (
            "dev25-rel-11",  # a 6-tower 2 clear in front of the middle of a 5 x 3 wall
            res(*_WALL5X3_BACK, *column(0.40, 0.30, 6)),
            res(*_WALL5X3_BACK, *column(0.40, 0.20, 6)),  # in front of one end
        ),
        (
            "dev25-rel-13",  # "I say again": ONE 4-tower dead centre in a 5 x 5 ring
            res(*_PEN5, *column(0.45, 0.30, 4)),
            res(*_PEN5, *column(0.45, 0.30, 4), *column(0.70, 0.30, 4)),  # the repeat built
        ),
        (
            "dev25-rel-16",  # 3 stairs climbing back, a 4-tower against the top step
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4))),
            res(*_stairs_x(0.30, 0.30, (4, 1, 2, 3))),  # against the bottom step
        ),
        (
            "dev25-rel-17",  # 3-towers on the left and right of a centre pyramid, clear of it
            res(*_PYR2, *column(0.45, 0.15, 3), *column(0.45, 0.45, 3)),
            res(*_PYR2, *column(0.30, 0.30, 3), *column(0.60, 0.30, 3)),  # in front and behind
        ),
        (
            "dev25-rel-18",  # a 6-tower directly behind a front row of 5, two cubes clear
            res(*_ROW5_FRONT, *column(0.50, 0.30, 6)),
            res(*_ROW5_FRONT, *column(0.50, 0.44, 6)),  # behind, but off the row's end
        ),
        (
            "dev25-rel-19",  # a lighthouse of 6 clear on the gangplank's starboard (-y) side
            res(*_bridge_y(0.45, 0.35, 3), *column(0.45, 0.15, 6)),
            res(*_bridge_y(0.45, 0.35, 3), *column(0.45, 0.50, 6)),  # to port
        ),
        (
            "dev25-rel-20",  # a 4 x 4 slab with a cube on each of its four corners
            res(*_SLAB4, *[cube(x, y, 0.075) for x in (0.40, 0.55) for y in (0.25, 0.40)]),
            res(*_SLAB4, *[cube(x, y, 0.075) for x in (0.45, 0.50) for y in (0.30, 0.35)]),
        ),
        (
            "dev25-seq-11",  # a 6 x 2 wall with a 3-tower on top of its left (+y) end
            res(*_stairs_y(0.45, 0.175, (2, 2, 2, 2, 2, 5))),
            res(*_stairs_y(0.45, 0.175, (2, 2, 2, 2, 2, 2, 3))),  # touching the end instead
        ),
        (
            "dev25-seq-12",  # a gate on pillars of 4 with a cube on the beam over the middle
            res(*_bridge_y(0.45, 0.30, 4), cube(0.45, 0.30, 0.275)),
            res(*_bridge_y(0.45, 0.30, 4), cube(0.45, 0.35, 0.275)),  # over one pillar
        ),
        (
            "dev25-seq-18",  # four steps said twice, then the top step off: ONE 3-step stair
            res(*_stairs_x(0.35, 0.30, (1, 2, 3))),
            res(*_stairs_x(0.35, 0.20, (1, 2, 3)), *_stairs_x(0.35, 0.40, (1, 2, 3))),
        ),
        (
            "dev25-seq-19",  # 4 steps climbing forward (away from the robot), a 2-mast on top
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 6))),
            res(*_stairs_x(0.35, 0.30, (6, 3, 2, 1))),  # climbing towards the robot
        ),
        (
            "dev25-seq-20",  # a 3-level pyramid less its top cube, a 3-tower in its place
            res(
                *grid(0.40, 0.25, 3, 3),
                *grid(0.40, 0.25, 2, 2, z0=C),
                *column(0.425, 0.275, 3, 2 * C),
            ),
            res(*_PYR3, *column(0.425, 0.275, 3, 3 * C)),  # the top cube kept under the tower
        ),
        (
            "dev25-num-11",  # six single cubes in a 2 x 3 grid, a cube between neighbours
            res(*[cube(x, y, C / 2) for x in (0.40, 0.50) for y in (0.20, 0.30, 0.40)]),
            res(*[cube(x, y, C / 2) for x in (0.40, 0.55) for y in (0.20, 0.30, 0.40)]),
        ),
        (
            "dev25-num-19",  # masts 2, 4, 2 athwartships (along y), two cubes of water between
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 4), *column(0.45, 0.45, 2)),
            res(*column(0.30, 0.30, 2), *column(0.45, 0.30, 4), *column(0.60, 0.30, 2)),
        ),
        (
            "dev25-neg-05",  # nothing above 3 cubes: the tallest pyramid allowed has 3 levels
            res(*_PYR3),
            res(*_PYR4),
        ),
        (
            "dev25-neg-09",  # a 5 x 5 deck with the middle left open: the 3 x 3 middle …
            res(*_PEN5),
            res(*grid(0.35, 0.20, 5, 5)),  # a full deck
        ),
        (
            "dev25-neg-09",  # … or the one middle cell
            res(*_without(grid(0.35, 0.20, 5, 5), (0.45, 0.30))),
            res(*_without(grid(0.35, 0.20, 5, 5), (0.35, 0.20))),  # a corner left out
        ),
        (
            "dev25-neg-14",  # a 4 x 4 x 2 ring with a doorway in its aft (front, robot) side
            res(*_without(ring(0.40, 0.25, 4, high=2), (0.40, 0.30))),
            res(*_without(ring(0.40, 0.25, 4, high=2), (0.55, 0.30))),  # in the forward side
        ),
        (
            "dev25-fil-01",  # few-shot prompt: only the last input is built
            res(*_PYR3),
            res(*_PYR3, *column(0.30, 0.45, 2), *_row_y(0.65, 0.15, 3)),  # the examples too
        ),
        (
            "dev25-reg-14",  # the port quarter: aft (front) and to port (left)
            res(*column(0.30, 0.45, 6)),
            res(*column(0.65, 0.45, 6)),  # the port bow
        ),
        (
            "dev25-bad-01",  # 40 high past the limits: refuse, or cap it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes, the cell's height limit"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev25-bad-15",  # "five (4)": word and figure disagree
            _ERROR,
            res(*column(0.45, 0.30, 4)),  # silently took the figure
        ),
    ],
)
def test_dev25_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev25(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
