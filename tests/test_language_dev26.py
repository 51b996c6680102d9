"""The dev26 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev26 import CASES as DEV26

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


def _dev26(case_id: str) -> Case:
    return next(c for c in DEV26 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena():
    assert len(DEV26) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV26) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV26} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV26)
    ids = [c.id for c in DEV26]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev26-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV26:
        assert c.id.startswith(f"dev26-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev26"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another():
    others = _other_sets()
    assert "language_dev24" in others and "language_dev25" in others
    seen: dict[str, str] = {}
    for c in DEV26:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV26}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in DEV26:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges():
    src = (Path(k.__file__).parent / "language_dev26.py").read_text(encoding="utf-8")
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

_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_PYR3 = [*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C), cube(0.425, 0.275, 0.125)]
_BLOCK332 = grid(0.40, 0.25, 3, 3, layers=2)  # x 0.375–0.525, y 0.225–0.375
_SLAB23 = grid(0.40, 0.25, 2, 3)  # x 0.375–0.475, y 0.225–0.375
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev26-rel-07",  # a 3-tower inside a 5 x 5 ring, clear of the wall …
            res(*_PEN5, *column(0.45, 0.30, 3)),
            res(*_PEN5, *column(0.70, 0.30, 3)),  # outside the ring
        ),
        (
            "dev26-rel-07",  # … or set against the inside of the wall
            res(*_PEN5, *column(0.40, 0.30, 3)),
            res(*_PEN5, *column(0.30, 0.30, 3)),  # against its outside
        ),
        (
            "dev26-rel-09",  # a 3-tower right behind a 5-tower, touching it
            res(*column(0.45, 0.30, 5), *column(0.50, 0.30, 3)),
            res(*column(0.45, 0.30, 5), *column(0.40, 0.30, 3)),  # in front of it
        ),
        (
            "dev26-rel-14",  # 3 steps leading up to a 5-tower, the top step touching it
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 5))),
            res(*_stairs_x(0.30, 0.30, (5, 1, 2, 3))),  # against the bottom step
        ),
        (
            "dev26-rel-16",  # a single cube on each side (left and right) of a centre 5-tower
            res(*_stairs_y(0.45, 0.25, (1, 5, 1))),
            res(*_stairs_y(0.45, 0.25, (5, 1, 1))),  # both on one side
        ),
        (
            "dev26-rel-17",  # a beam on two 4-towers, one cube on the beam over the middle
            res(*_bridge_y(0.45, 0.30, 4), cube(0.45, 0.30, 0.275)),
            res(*_bridge_y(0.45, 0.30, 4), cube(0.45, 0.35, 0.275)),  # over one pillar
        ),
        (
            "dev26-rel-18",  # towers 2, 4, 2 left to right, one cube apart
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 4), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 2), *column(0.45, 0.40, 2)),
        ),
        (
            "dev26-rel-19",  # a 3 x 3 x 2 block with a cube on each corner of its top
            res(*_BLOCK332, *[cube(x, y, 0.125) for x in (0.40, 0.50) for y in (0.25, 0.35)]),
            res(
                *_BLOCK332,
                *[
                    cube(x, y, 0.125)
                    for x, y in ((0.40, 0.30), (0.50, 0.30), (0.45, 0.25), (0.45, 0.35))
                ],
            ),
        ),
        (
            "dev26-rel-21",  # a tower as tall as the 3-level pyramid, two cubes to its right
            res(*_PYR3, *column(0.45, 0.10, 3)),
            res(*_PYR3, *column(0.45, 0.50, 3)),  # two cubes to its left
        ),
        (
            "dev26-seq-08",  # a 2 x 3 slab with a 3-tower on one corner
            res(*_SLAB23, *column(0.40, 0.25, 3, C)),
            res(*_SLAB23, *column(0.40, 0.30, 3, C)),  # on the middle of a long side
        ),
        (
            "dev26-seq-12",  # 3 steps with a cube on the top step
            res(*_stairs_x(0.35, 0.30, (1, 2, 4))),
            res(*_stairs_x(0.35, 0.30, (2, 2, 3))),  # on the bottom step
        ),
        (
            "dev26-seq-16",  # three 2-towers a cube apart, the middle one taken away
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 2), *column(0.45, 0.40, 2)),
        ),
        (
            "dev26-seq-18",  # a 5 x 2 wall left to right, a 3-tower on its right (-y) end
            res(*_stairs_y(0.45, 0.175, (5, 2, 2, 2, 2))),
            res(*_stairs_y(0.45, 0.175, (2, 2, 2, 2, 5))),  # on its left end
        ),
        (
            "dev26-seq-20",  # a 3 x 3 slab (the top layer removed) with a cube on the middle
            res(*grid(0.40, 0.25, 3, 3), cube(0.45, 0.30, 0.075)),
            res(*_BLOCK332, cube(0.45, 0.30, 0.125)),  # the top layer kept
        ),
        (
            "dev26-num-09",  # a 6-tower and a 3-tower beside it (here set against it)
            res(*column(0.45, 0.30, 6), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.30, 6), *column(0.45, 0.35, 2)),  # not half as tall
        ),
        (
            "dev26-num-18",  # towers 3, 4, 5 from front to back, one cube apart
            res(*column(0.35, 0.30, 3), *column(0.45, 0.30, 4), *column(0.55, 0.30, 5)),
            res(*column(0.35, 0.30, 5), *column(0.45, 0.30, 4), *column(0.55, 0.30, 3)),
        ),
        (
            "dev26-num-20",  # four single cubes in a square, two cubes of space between
            res(*[cube(x, y, C / 2) for x in (0.40, 0.55) for y in (0.25, 0.40)]),
            res(*[cube(x, y, C / 2) for x in (0.40, 0.50) for y in (0.25, 0.35)]),  # one apart
        ),
        (
            "dev26-neg-12",  # a 4 x 4 ring less one cube of its front (robot) side
            res(*_without(ring(0.40, 0.25, 4), (0.40, 0.30))),
            res(*_without(ring(0.40, 0.25, 4), (0.55, 0.30))),  # a door in the back side
        ),
        (
            "dev26-neg-13",  # a 3-level pyramid without its top cube
            res(*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C)),
            res(*_PYR3),
        ),
        (
            "dev26-wo-08",  # a 2-tower between two 4-towers, one cube apart
            res(*column(0.35, 0.30, 4), *column(0.45, 0.30, 2), *column(0.55, 0.30, 4)),
            res(*column(0.35, 0.30, 2), *column(0.45, 0.30, 4), *column(0.55, 0.30, 4)),
        ),
        (
            "dev26-reg-12",  # a row of 5 left to right as close to the robot as it goes
            res(*_row_y(0.25, 0.20, 5)),
            res(*_row_y(0.40, 0.20, 5)),  # in the front region but well out from the robot
        ),
        (
            "dev26-open-09",  # towers of different heights
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 3), *column(0.45, 0.40, 4)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev26-bad-01",  # 15 high past the limits: refuse, or cap it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes, the cell's height limit"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev26-bad-13",  # "five" said, four fingers shown: the figures disagree
            _ERROR,
            res(*column(0.45, 0.30, 4)),  # silently took one of them
        ),
    ],
)
def test_dev26_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev26(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
