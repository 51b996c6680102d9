"""The dev28 language set: its size, ids and phenomena, no command shared with another set,
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
from sdi.bench.language_dev28 import CASES as DEV28

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


Obj = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Sequence[float] = (1.0, 0.0, 0.0, 0.0)) -> Obj:
    """A 0.15 m beam along x (or, turned by `q`, along y)."""
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
    """a cubes along x by b along y, `layers` high, lowest cube centre at (x0, y0)."""
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


def _cols_y(x: float, y0: float, hs: Sequence[int]) -> list[Obj]:
    """Touching columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _towers_y(x: float, ys_hs: Sequence[tuple[float, int]]) -> list[Obj]:
    """Separate columns at (x, y) of the given heights, for (y, h) pairs."""
    return [c for y, h in ys_hs for c in column(x, y, h)]


def _without(objs: Sequence[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _pyr2(x0: float, y0: float) -> list[Obj]:
    """A 2 × 2 base with one cube centred on it (levels 4, 1)."""
    return [*grid(x0, y0, 2, 2), cube(x0 + C / 2, y0 + C / 2, 1.5 * C)]


def _dev28(case_id: str) -> Case:
    return next(c for c in DEV28 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV28) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV28) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV28} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV28)
    ids = [c.id for c in DEV28]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev28-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV28:
        assert c.id.startswith(f"dev28-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but this one (compared only by
    normalised text, never printed)."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_dev28"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev26" in others and "language_dev27" in others
    seen: dict[str, str] = {}
    for c in DEV28:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    shared = [
        (seen[_norm(c.text)], name, c.id)
        for name, cases in others.items()
        for c in cases
        if _norm(c.text) in seen
    ]
    assert not shared, [(mine, name) for mine, name, _ in shared]
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV28}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
OUTSIDE = res(*column(0.90, 0.30, 2), *column(0.45, 0.30, 1))
EMPTY = res()
NO_LAYOUT = {"status": "error", "layout": None}
SPREAD = res(*column(0.30, 0.45, 2), *grid(0.60, 0.10, 2, 3), *ring(0.40, 0.25, 4))


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, OUTSIDE, EMPTY, NO_LAYOUT, SPREAD])
def test_every_predicate_answers_without_raising(result: dict[str, Any]) -> None:
    for case in DEV28:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev28.py").read_text(encoding="utf-8")
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


def test_bad_input_never_accepts_a_silent_success() -> None:
    for case in DEV28:
        if case.phenomenon == k.BAD:
            assert case.accept(TOWER3) is not None, case.id


# ---------------------------------------------------------------- hand-built layouts

_SLAB2 = grid(0.40, 0.25, 2, 2)  # x 0.375–0.475, y 0.225–0.325, centre (0.425, 0.275)
_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375, centre (0.45, 0.30)
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; middle cell at (0.45, 0.30)
_RING4X2 = ring(0.40, 0.25, 4, high=2)  # x 0.375–0.575, y 0.225–0.425, centre (0.475, 0.325)
_ROW5_FRONT = _row_y(0.30, 0.20, 5)  # x 0.275–0.325, y 0.175–0.425, middle cube y 0.30
_WALL5X3 = [c for z in range(3) for c in _row_y(0.55, 0.20, 5, z0=C * z)]  # x 0.525–0.575
_LEGS3 = [c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 3)]
_BEAM_TOP = [
    beam(0.45, 0.25, 0.175),
    beam(0.45, 0.35, 0.175),
    beam(0.45, 0.30, 0.225, YAW90),
]
_PYR_16_9_4 = [
    *grid(0.40, 0.25, 4, 4),
    *grid(0.40, 0.25, 3, 3, z0=C),
    *grid(0.40, 0.25, 2, 2, z0=2 * C),
]
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev28-rel-01",  # a 2-tower a cube clear on the left (+y) of a 4-tower …
            res(*column(0.45, 0.30, 4), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.30, 4), *column(0.45, 0.20, 2)),  # on its right
        ),
        (
            "dev28-rel-01",  # … or set against its left side
            res(*column(0.45, 0.30, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.30, 4), *column(0.45, 0.25, 2)),  # against its right
        ),
        (
            "dev28-rel-03",  # one cube centred on a 2 x 2 block two high
            res(*grid(0.40, 0.25, 2, 2, layers=2), cube(0.425, 0.275, 0.125)),
            res(*grid(0.40, 0.25, 2, 2, layers=2), cube(0.40, 0.25, 0.125)),  # on a corner
        ),
        (
            "dev28-rel-05",  # a 3-tower in the middle of a 5 x 5 ring
            res(*_PEN5, *column(0.45, 0.30, 3)),
            res(*_PEN5, *column(0.40, 0.25, 3)),  # inside, but in a corner of the floor
        ),
        (
            "dev28-rel-09",  # a 6-tower between two 2-towers …
            res(*_towers_y(0.45, [(0.15, 2), (0.30, 6), (0.45, 2)])),
            res(*_towers_y(0.45, [(0.15, 2), (0.30, 2), (0.45, 6)])),  # the tall one at an end
        ),
        (
            "dev28-rel-09",  # … or the three set against one another
            res(*_cols_y(0.45, 0.25, (2, 6, 2))),
            res(*_cols_y(0.45, 0.25, (2, 2, 6))),
        ),
        (
            "dev28-rel-11",  # a 3 x 3 slab with a tower of two on each corner
            res(
                *_SLAB3,
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2, C)],
            ),
            res(
                *_SLAB3,
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 1, C)],
            ),
        ),
        (
            "dev28-rel-12",  # a table on four 3-high legs with a roof of beams
            res(*_LEGS3, *_BEAM_TOP),
            res(*_LEGS3, *grid(0.40, 0.25, 3, 3, z0=3 * C)),  # a top of cubes
        ),
        (
            "dev28-rel-13",  # two 4 x 2 walls side by side, two cubes clear
            res(
                *[c for z in (0, C) for c in _row_x(0.35, 0.20, 4, z0=z)],
                *[c for z in (0, C) for c in _row_x(0.35, 0.35, 4, z0=z)],
            ),
            res(  # end to end, two cubes apart
                *[c for z in (0, C) for c in _row_x(0.25, 0.30, 4, z0=z)],
                *[c for z in (0, C) for c in _row_x(0.55, 0.30, 4, z0=z)],
            ),
        ),
        (
            "dev28-rel-16",  # a 3-tower behind the middle of a front row of five …
            res(*_ROW5_FRONT, *column(0.45, 0.30, 3)),
            res(*_ROW5_FRONT, *column(0.45, 0.40, 3)),  # behind its end
        ),
        (
            "dev28-rel-16",  # … or set against its middle
            res(*_ROW5_FRONT, *column(0.35, 0.30, 3)),
            res(*_ROW5_FRONT, *column(0.35, 0.20, 3)),
        ),
        (
            "dev28-rel-17",  # a 4 x 4 ring two high with one cube centred inside
            res(*_RING4X2, cube(0.475, 0.325, 0.025)),
            res(*_RING4X2, cube(0.45, 0.30, 0.025)),  # in one cell of the floor
        ),
        (
            "dev28-rel-18",  # a 2-tower against the front of a 5 x 3 wall
            res(*_WALL5X3, *column(0.50, 0.30, 2)),
            res(*_WALL5X3, *column(0.60, 0.30, 2)),  # against its back
        ),
        (
            "dev28-rel-21",  # 2, 4, 2 from left to right, the 4 in the centre, a cube apart
            res(*_towers_y(0.45, [(0.40, 2), (0.30, 4), (0.20, 2)])),
            res(*_towers_y(0.45, [(0.40, 2), (0.30, 2), (0.20, 4)])),
        ),
        (
            "dev28-rel-22",  # the 3-tower in front of the 6-tower, two cubes clear
            res(*column(0.35, 0.30, 3), *column(0.50, 0.30, 6)),
            res(*column(0.35, 0.30, 6), *column(0.50, 0.30, 3)),  # the tall one in front
        ),
        (
            "dev28-seq-03",  # a 6 x 2 wall less the two end cubes of its top row
            res(*_cols_y(0.45, 0.15, (1, 2, 2, 2, 2, 1))),
            res(*_cols_y(0.45, 0.15, (2, 2, 2, 2, 2, 2))),
        ),
        (
            "dev28-seq-09",  # a 4-level pyramid less its top cube
            res(*_PYR_16_9_4),
            res(*_PYR_16_9_4, cube(0.425, 0.275, 0.175)),  # the top cube kept
        ),
        (
            "dev28-seq-16",  # three 2-towers a cube apart, the right one removed
            res(*_towers_y(0.45, [(0.35, 2), (0.25, 2)])),
            res(*_towers_y(0.45, [(0.35, 2), (0.25, 2), (0.15, 2)])),
        ),
        (
            "dev28-seq-20",  # two 4-towers, two cubes taken off the left one
            res(*column(0.45, 0.45, 2), *column(0.45, 0.15, 4)),
            res(*column(0.45, 0.45, 4), *column(0.45, 0.15, 2)),  # off the right one
        ),
        (
            "dev28-num-03",  # heights 1, 2, 3 from left (+y) to right, a cube apart
            res(*_towers_y(0.45, [(0.40, 1), (0.30, 2), (0.20, 3)])),
            res(*_towers_y(0.45, [(0.40, 3), (0.30, 2), (0.20, 1)])),
        ),
        (
            "dev28-num-13",  # a 2-tower and one three times as tall beside it
            res(*column(0.45, 0.30, 2), *column(0.45, 0.40, 6)),
            res(*column(0.45, 0.30, 2), *column(0.45, 0.40, 5)),  # three more, not three times
        ),
        (
            "dev28-num-16",  # heights 1 … 5 from front to back, a cube apart
            res(*[c for i in range(5) for c in column(0.25 + 0.10 * i, 0.30, i + 1)]),
            res(*[c for i in range(5) for c in column(0.25 + 0.10 * i, 0.30, 5 - i)]),
        ),
        (
            "dev28-num-17",  # two 2-level pyramids and two 3-towers, all separate
            res(
                *_pyr2(0.30, 0.15),
                *_pyr2(0.30, 0.40),
                *column(0.60, 0.20, 3),
                *column(0.60, 0.40, 3),
            ),
            res(
                *_pyr2(0.30, 0.15),
                *column(0.30, 0.45, 3),
                *column(0.60, 0.20, 3),
                *column(0.60, 0.40, 3),
            ),
        ),
        (
            "dev28-dim-18",  # a table on four 1-high legs under a 3 x 3 top
            res(
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 1)],
                *grid(0.40, 0.25, 3, 3, z0=C),
            ),
            res(
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2)],
                *grid(0.40, 0.25, 3, 3, z0=2 * C),
            ),
        ),
        (
            "dev28-neg-11",  # a 4 x 4 ring, one cube left out of its left (+y) side …
            res(*_without(ring(0.40, 0.25, 4), (0.45, 0.40))),
            res(*_without(ring(0.40, 0.25, 4), (0.45, 0.25))),  # out of the right side
        ),
        (
            "dev28-neg-11",  # … a left corner cube will do, a closed ring will not
            res(*_without(ring(0.40, 0.25, 4), (0.40, 0.40))),
            res(*ring(0.40, 0.25, 4)),
        ),
        (
            "dev28-typo-11",  # a 3-tower centred on a 2 x 2 slab
            res(*_SLAB2, *column(0.425, 0.275, 3, C)),
            res(*_SLAB2, *column(0.40, 0.25, 3, C)),  # on a corner cell
        ),
        (
            "dev28-wo-10",  # one cube on the middle of a 3 x 3 slab
            res(*_SLAB3, cube(0.45, 0.30, 0.075)),
            res(*_SLAB3, cube(0.40, 0.25, 0.075)),
        ),
        (
            "dev28-reg-02",  # a 4-tower at X 500, Y 400
            res(*column(0.50, 0.40, 4)),
            res(*column(0.40, 0.50, 4)),  # the figures swapped
        ),
        (
            "dev28-reg-05",  # a 5 x 2 wall along the left edge, running front to back
            res(*[c for z in (0, C) for c in _row_x(0.35, 0.50, 5, z0=z)]),
            res(*[c for z in (0, C) for c in _row_y(0.45, 0.30, 5, z0=z)]),  # across it
        ),
        (
            "dev28-open-06",  # anything, all of it in the left half
            res(*_row_y(0.45, 0.35, 4)),
            res(*_row_y(0.45, 0.25, 4)),  # centre on the left, but reaching over the line
        ),
        (
            "dev28-bad-02",  # the height field is #N/A: refuse, or build and say so
            res(*column(0.45, 0.30, 3), notes=["height missing (#N/A); assumed 3"]),
            res(*column(0.45, 0.30, 3)),
        ),
        (
            "dev28-bad-09",  # not a build at all: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 2), notes=["built a tower"]),
        ),
        (
            "dev28-bad-16",  # the operator cancelled: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 2), notes=["nothing was asked for"]),
        ),
    ],
)
def test_dev28_predicates_on_hand_built_layouts(
    case_id: str, right: dict[str, Any], wrong: dict[str, Any]
) -> None:
    case = _dev28(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
