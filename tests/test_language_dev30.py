"""The dev30 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Iterable, Sequence
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev30 import CASES as DEV30

Obj = dict[str, Any]
YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Sequence[float] = (1.0, 0.0, 0.0, 0.0)) -> Obj:
    return {"id": "b", "position": [x, y, z], "orientation": list(q), "size": [0.15, C, C]}


def res(*objs: Obj, status: str = "success", **extra: Any) -> Obj:
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


def _wall_y(x: float, y0: float, n: int, high: int) -> list[Obj]:
    return [c for h in range(high) for c in _row_y(x, y0, n, z0=C * h)]


def _stairs_y(x: float, y0: float, hs: Iterable[int]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _without(objs: list[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _dev30(case_id: str) -> Case:
    return next(c for c in DEV30 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV30) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV30) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV30} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV30)
    ids = [c.id for c in DEV30]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev30-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV30:
        assert c.id.startswith(f"dev30-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name (modules that do not import, such as
    a set still being written, are skipped). Only compared, never printed."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_dev30"):
            continue
        try:
            mod = importlib.import_module(f"sdi.bench.{name}")
        except Exception:  # another set being written at the same time
            continue
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_dev29" in others
    seen: dict[str, str] = {}
    for c in DEV30:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            if not isinstance(getattr(c, "text", None), str):
                continue
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {getattr(c, "id", None) for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV30}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
TWO = res(*column(0.30, 0.20, 2), *grid(0.60, 0.35, 2, 2, layers=2))
OUTSIDE = res(*column(0.95, 0.30, 2))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, TWO, OUTSIDE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result: Obj) -> None:
    for case in DEV30:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev30.py").read_text(encoding="utf-8")
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


def test_bad_input_admits_no_silent_layout() -> None:
    for case in DEV30:
        if case.phenomenon != k.BAD:
            continue
        assert case.accept(TOWER3) is not None, case.id
        assert case.accept(NO_LAYOUT) is None, case.id


# ---------------------------------------------------------------- hand-built layouts

_ROW5 = _row_y(0.30, 0.20, 5)  # x 0.275–0.325, y 0.175–0.425, centre y 0.30
_PEN5 = ring(0.35, 0.20, 5)  # x 0.325–0.575, y 0.175–0.425; the middle cell at (0.45, 0.30)
_SLAB3_BACK = grid(0.60, 0.25, 3, 3)  # x 0.575–0.725, y 0.225–0.375
_WALL6X3_BACK = _wall_y(0.70, 0.175, 6, 3)  # x 0.675–0.725, y 0.15–0.45
_CORNERS = [(0.30, 0.45), (0.30, 0.15), (0.65, 0.45), (0.65, 0.15)]
_ERROR = {"status": "error", "layout": None}


def _bridge4(cube_y: float) -> Obj:
    """Two 4-towers a cube apart along y, a beam across, a cube on the beam at `cube_y`."""
    return res(
        *column(0.45, 0.25, 4),
        *column(0.45, 0.35, 4),
        beam(0.45, 0.30, 0.225, YAW90),
        cube(0.45, cube_y, 0.275),
    )


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev30-rel-02",  # a 3-tower behind the middle of a row of five, a square between
            res(*_ROW5, *column(0.40, 0.30, 3)),
            res(*_ROW5, *column(0.40, 0.40, 3)),  # behind its end
        ),
        (
            "dev30-rel-07",  # a 2-tower in the middle of a 5 x 5 ring
            res(*_PEN5, *column(0.45, 0.30, 2)),
            res(*_PEN5, *column(0.40, 0.25, 2)),  # inside, but in a corner of the hole
        ),
        (
            "dev30-rel-08",  # a 5-tower set against the front of a back wall
            res(*_WALL6X3_BACK, *column(0.65, 0.30, 5)),
            res(*_WALL6X3_BACK, *column(0.75, 0.30, 5)),  # against its back
        ),
        (
            "dev30-rel-12",  # a row of three between a left and a right 3-tower
            res(*column(0.45, 0.45, 3), *_row_x(0.40, 0.30, 3), *column(0.45, 0.15, 3)),
            res(*column(0.45, 0.45, 3), *_row_y(0.70, 0.25, 3), *column(0.45, 0.15, 3)),
        ),
        (
            "dev30-rel-13",  # a cube 10 cm clear to the right (-y) of a 4-tower
            res(*column(0.45, 0.35, 4), *column(0.45, 0.20, 1)),
            res(*column(0.45, 0.35, 4), *column(0.45, 0.50, 1)),  # to its left
        ),
        (
            "dev30-rel-14",  # a 2-tower inside a 5 x 5 ring, against its wall …
            res(*_PEN5, *column(0.40, 0.25, 2)),
            res(*_PEN5, *column(0.70, 0.30, 2)),  # outside it
        ),
        (
            "dev30-rel-15",  # a 3-tower on each end cube of a row of five
            res(*_stairs_y(0.45, 0.20, (4, 1, 1, 1, 4))),
            res(*_stairs_y(0.45, 0.15, (3, 1, 1, 1, 1, 1, 3))),  # beside the ends
        ),
        (
            "dev30-rel-21",  # 1, 3, 5 from left (+y) to right, a cube between
            res(*column(0.45, 0.40, 1), *column(0.45, 0.30, 3), *column(0.45, 0.20, 5)),
            res(*column(0.45, 0.40, 5), *column(0.45, 0.30, 3), *column(0.45, 0.20, 1)),
        ),
        (
            "dev30-rel-22",  # 4 front right; 2 directly behind it; 3 directly left of it
            res(*column(0.30, 0.15, 4), *column(0.40, 0.15, 2), *column(0.30, 0.25, 3)),
            res(*column(0.30, 0.15, 4), *column(0.40, 0.25, 2), *column(0.30, 0.25, 3)),
        ),
        (
            "dev30-rel-24",  # a single cube in front of a three-step staircase
            res(*_stairs_y(0.50, 0.25, (1, 2, 3)), *column(0.35, 0.30, 1)),
            res(*_stairs_y(0.50, 0.25, (1, 2, 3)), *column(0.65, 0.30, 1)),  # behind it
        ),
        (
            "dev30-seq-02",  # a front row of six less two end cubes: four left
            res(*_row_y(0.30, 0.15, 4)),
            res(*_row_y(0.30, 0.15, 6)),
        ),
        (
            "dev30-seq-09",  # an 8 x 2 wall less its middle two columns: two 3 x 2 walls in line
            res(*_wall_y(0.45, 0.15, 3, 2), *_wall_y(0.45, 0.40, 3, 2)),
            res(*_wall_y(0.40, 0.20, 3, 2), *_wall_y(0.55, 0.20, 3, 2)),  # side by side
        ),
        (
            "dev30-seq-13",  # a cube on the middle of a beam across two 4-towers
            _bridge4(0.30),
            _bridge4(0.35),  # over a post
        ),
        (
            "dev30-seq-17",  # a four-step staircase less its lowest step: 2, 3, 4
            res(*_stairs_y(0.45, 0.20, (2, 3, 4))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
        ),
        (
            "dev30-seq-19",  # a 3 x 3 slab at the back with a 2-tower on each corner
            res(
                *_SLAB3_BACK,
                *[c for x in (0.60, 0.70) for y in (0.25, 0.35) for c in column(x, y, 2, C)],
            ),
            res(
                *_SLAB3_BACK,
                *[c for x in (0.60, 0.70) for y in (0.25, 0.35) for c in column(x, y, 3, C)],
            ),
        ),
        (
            "dev30-seq-20",  # three 3-towers a cube apart, the right one taken away
            res(*column(0.45, 0.40, 3), *column(0.45, 0.30, 3)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.30, 3), *column(0.45, 0.20, 3)),
        ),
        (
            "dev30-num-02",  # heights 1, 2, 3, 4 from left (+y) to right, touching
            res(*_stairs_y(0.45, 0.30, (4, 3, 2, 1))),
            res(*_stairs_y(0.45, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev30-num-03",  # a 3-tower between two 6-towers, apart …
            res(*column(0.45, 0.15, 6), *column(0.45, 0.30, 3), *column(0.45, 0.45, 6)),
            res(*column(0.45, 0.15, 6), *column(0.45, 0.30, 6), *column(0.45, 0.45, 3)),
        ),
        (
            "dev30-num-03",  # … or all three touching in a line
            res(*_stairs_y(0.45, 0.25, (6, 3, 6))),
            res(*_stairs_y(0.45, 0.25, (6, 6, 3))),
        ),
        (
            "dev30-num-12",  # a 3-tower and, beside it, one twice as tall
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 6)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 5)),
        ),
        (
            "dev30-num-13",  # a row of seven whose end squares are marked 5
            res(*_stairs_y(0.45, 0.15, (5, 1, 1, 1, 1, 1, 5))),
            res(*_stairs_y(0.45, 0.20, (5, 1, 1, 1, 5))),  # only five squares in all
        ),
        (
            "dev30-num-14",  # a 2 x 2 block four high and one half its height
            res(*grid(0.40, 0.20, 2, 2, layers=2), *grid(0.40, 0.35, 2, 2, layers=4)),
            res(*grid(0.40, 0.20, 2, 2, layers=3), *grid(0.40, 0.35, 2, 2, layers=4)),
        ),
        (
            "dev30-num-18",  # a 3-tower in each corner, a single cube in the centre
            res(*[c for x, y in _CORNERS for c in column(x, y, 3)], cube(0.45, 0.30, C / 2)),
            res(*[c for x, y in _CORNERS for c in column(x, y, 3)], cube(0.25, 0.30, C / 2)),
        ),
        (
            "dev30-neg-04",  # a 3 x 3 square less its bottom (front) middle square
            res(*_without(grid(0.40, 0.25, 3, 3), (0.40, 0.30))),
            res(*_without(grid(0.40, 0.25, 3, 3), (0.50, 0.30))),  # the top (back) one
        ),
        (
            "dev30-neg-11",  # a 2 x 2 square outside the back half
            res(*grid(0.30, 0.25, 2, 2)),
            res(*grid(0.50, 0.25, 2, 2)),
        ),
        (
            "dev30-reg-03",  # centre 10 cm from the front edge, 15 cm from the left edge
            res(*column(0.30, 0.40, 3)),
            res(*column(0.325, 0.375, 3)),  # the faces at those distances, not the centre
        ),
        (
            "dev30-reg-06",  # a 4 x 2 wall within 5 cm of the back edge
            res(*_wall_y(0.775, 0.20, 4, 2)),
            res(*_wall_y(0.65, 0.20, 4, 2)),
        ),
        (
            "dev30-reg-09",  # faces 10 cm in from the right edge and 20 cm in from the front
            res(*column(0.425, 0.175, 4)),
            res(*column(0.30, 0.25, 4)),  # the two figures swapped
        ),
        (
            "dev30-reg-19",  # a 2 x 2 x 2 block touching the right edge, 15 cm from the front
            res(*grid(0.375, 0.075, 2, 2, layers=2)),
            res(*grid(0.375, 0.125, 2, 2, layers=2)),  # 5 cm off the right edge
        ),
        (
            "dev30-wo-07",  # a 2-tower 10 cm from the left and back edges
            res(*column(0.70, 0.45, 2)),
            res(*column(0.70, 0.15, 2)),  # 10 cm from the right edge instead
        ),
        (
            "dev30-bad-10",  # French: refuse, or build the tower of three and say so
            res(*column(0.45, 0.30, 3), notes=["request was in French; read as a 3-tower"]),
            res(*column(0.45, 0.30, 3)),
        ),
        (
            "dev30-bad-05",  # not a build request: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 1), notes=["built a cube"]),
        ),
    ],
)
def test_dev30_predicates_on_hand_built_layouts(case_id: str, right: Obj, wrong: Obj) -> None:
    case = _dev30(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
