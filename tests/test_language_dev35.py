"""The dev35 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the local checks on hand-built layouts (each case
must pass the right reading and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev35 import CASES as DEV35

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05
Obj = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - running id
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
    out = []
    for i in range(n):
        for j in range(n):
            if i in (0, n - 1) or j in (0, n - 1):
                out += column(x0 + C * i, y0 + C * j, high)
    return out


def grid(
    x0: float,
    y0: float,
    a: int,
    b: int,
    layers: int = 1,
    z0: float = 0.0,
    step: float = C,
) -> list[Obj]:
    """a × b cubes (or single-cube towers `layers` high) from (x0, y0), centres `step` apart."""
    return [
        cube(x0 + step * i, y0 + step * j, z0 + C / 2 + C * h)
        for h in range(layers)
        for i in range(a)
        for j in range(b)
    ]


def _row_y(x: float, y0: float, n: int, z0: float = 0.0) -> list[Obj]:
    return [cube(x, y0 + C * j, z0 + C / 2) for j in range(n)]


def _row_x(x0: float, y: float, n: int, z0: float = 0.0) -> list[Obj]:
    return [cube(x0 + C * i, y, z0 + C / 2) for i in range(n)]


def _wall_x(x0: float, y: float, n: int, high: int) -> list[Obj]:
    return [c for h in range(high) for c in _row_x(x0, y, n, z0=C * h)]


def _wall_y(x: float, y0: float, n: int, high: int) -> list[Obj]:
    return [c for h in range(high) for c in _row_y(x, y0, n, z0=C * h)]


def _stairs_y(x: float, y0: float, hs: tuple[int, ...]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _without(objs: list[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _plus5(mid: int) -> list[Obj]:
    """A flat plus sign five across each way centred on (0.45, 0.30), its middle column `mid`
    cubes high."""
    arms = [cube(x, 0.30, C / 2) for x in (0.35, 0.40, 0.50, 0.55)]
    arms += [cube(0.45, y, C / 2) for y in (0.20, 0.25, 0.35, 0.40)]
    return [*arms, *column(0.45, 0.30, mid)]


def _dev35(case_id: str) -> Case:
    return next(c for c in DEV35 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV35) == 180
    per = {p: sum(c.phenomenon == p for c in DEV35) for p in PHENOMENA}
    assert per == {
        "relation": 20,
        "sequence": 20,
        "numbers": 20,
        "dimensions": 20,
        "negation": 15,
        "typo": 14,
        "word_order": 13,
        "filler": 13,
        "region": 14,
        "open": 12,
        "bad_input": 19,
    }, per
    assert all(callable(c.accept) for c in DEV35)
    ids = [c.id for c in DEV35]
    assert len(ids) == len(set(ids))
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV35:
        assert c.id.startswith(f"dev35-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev35"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_dev33" in others
    seen: dict[str, str] = {}
    for c in DEV35:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV35}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result: dict[str, Any]) -> None:
    for case in DEV35:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev35.py").read_text(encoding="utf-8")
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

_WALL6X2_BACK = _wall_y(0.65, 0.175, 6, 2)  # x 0.625–0.675, y 0.15–0.45, centre y 0.30
_ROW5_FRONT = _row_y(0.30, 0.20, 5)  # x 0.275–0.325, y 0.175–0.425
_ROW6_FRONT = _row_y(0.40, 0.175, 6)  # x 0.375–0.425, y 0.15–0.45, centre y 0.30
_L4 = [*_row_y(0.40, 0.25, 4), *_row_x(0.45, 0.25, 3)]  # a flat L, its corner at (0.40, 0.25)
_FRAME4 = ring(0.40, 0.25, 4)  # x 0.375–0.575, y 0.225–0.425; the left side at y 0.40
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev35-rel-01",  # a 2-tower right next to a 5-tower, on its left, a cube clear …
            res(*column(0.45, 0.30, 5), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.20, 2)),  # on its right
        ),
        (
            "dev35-rel-01",  # … or set against its left side
            res(*column(0.45, 0.30, 5), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.25, 2)),
        ),
        (
            "dev35-rel-03",  # a 3-tower against the front of a back wall, at its middle
            res(*_WALL6X2_BACK, *column(0.60, 0.325, 3)),
            res(*_WALL6X2_BACK, *column(0.60, 0.175, 3)),  # against its end
        ),
        (
            "dev35-rel-04",  # two towers side by side, the left (+y) one taller, apart …
            res(*column(0.45, 0.40, 5), *column(0.45, 0.25, 3)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.25, 5)),  # the right one taller
        ),
        (
            "dev35-rel-04",  # … or touching
            res(*column(0.45, 0.35, 4), *column(0.45, 0.30, 2)),
            res(*column(0.45, 0.35, 3), *column(0.45, 0.30, 3)),  # the same height
        ),
        (
            "dev35-rel-07",  # a flat plus sign with a tower of four on its middle cube
            res(*_plus5(5)),
            res(*_without(_plus5(1), (0.45, 0.40)), *column(0.45, 0.40, 5)),  # on an arm's tip
        ),
        (
            "dev35-rel-11",  # a front edging row of five, a 2-post standing on each end …
            res(*_ROW5_FRONT, *column(0.30, 0.20, 2, C), *column(0.30, 0.40, 2, C)),
            res(
                *_row_y(0.65, 0.20, 5), *column(0.65, 0.20, 2, C), *column(0.65, 0.40, 2, C)
            ),  # at the back
        ),
        (
            "dev35-rel-11",  # … or separate posts just past the ends, in line with the row
            res(*_ROW5_FRONT, *column(0.30, 0.10, 2), *column(0.30, 0.50, 2)),
            res(*_ROW5_FRONT, *column(0.40, 0.20, 2), *column(0.40, 0.40, 2)),  # behind the ends
        ),
        (
            "dev35-rel-17",  # two 4-towers 10 cm apart, mirrored about y = 0.30
            res(*column(0.45, 0.225, 4), *column(0.45, 0.375, 4)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 4)),  # off the centre line
        ),
        (
            "dev35-rel-18",  # a 5-tower a cube behind the middle of a left-right row of six
            res(*_ROW6_FRONT, *column(0.50, 0.325, 5)),
            res(*_ROW6_FRONT, *column(0.50, 0.225, 5)),  # behind, 7.5 cm off its middle
        ),
        (
            "dev35-rel-20",  # a row of four behind a row of six, the right (-y) ends in line
            res(*_ROW6_FRONT, *_row_y(0.50, 0.175, 4)),
            res(*_ROW6_FRONT, *_row_y(0.50, 0.275, 4)),  # left-aligned
        ),
        (
            "dev35-seq-05",  # a flat L, arms of four, with a 3-tower on its corner cube
            res(*_L4, *column(0.40, 0.25, 3, C)),
            res(*_L4, *column(0.55, 0.25, 3, C)),  # on the end of an arm
        ),
        (
            "dev35-seq-06",  # a T: a left-right row of five, its stem going back (+x)
            res(*_row_y(0.40, 0.20, 5), cube(0.45, 0.30, C / 2), cube(0.50, 0.30, C / 2)),
            res(*_row_y(0.40, 0.20, 5), cube(0.35, 0.30, C / 2), cube(0.30, 0.30, C / 2)),
        ),
        (
            "dev35-seq-07",  # five stadium steps, the top step taken away
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4, 5))),
        ),
        (
            "dev35-seq-18",  # a 3-tower at the back left and its mirror image at the back right
            res(*column(0.65, 0.45, 3), *column(0.65, 0.15, 3)),
            res(*column(0.65, 0.45, 3), *column(0.72, 0.15, 3)),  # not at the mirror position
        ),
        (
            "dev35-num-08",  # a flat H: two rows of three joined at their middles
            res(*_row_y(0.40, 0.25, 3), *_row_y(0.50, 0.25, 3), cube(0.45, 0.30, C / 2)),
            res(*_row_y(0.40, 0.25, 3), *_row_y(0.50, 0.25, 3), cube(0.45, 0.25, C / 2)),
        ),
        (
            "dev35-num-17",  # a 3 x 3 grid of single cubes, a cube clear between neighbours
            res(*grid(0.35, 0.20, 3, 3, step=2 * C)),
            res(*grid(0.30, 0.15, 3, 3, step=3 * C)),  # two cubes clear
        ),
        (
            "dev35-dim-17",  # a 5-tower whose back face is 5 cm in from the back edge (x 0.80)
            res(*column(0.725, 0.30, 5)),
            res(*column(0.775, 0.30, 5)),  # flush with the edge
        ),
        (
            "dev35-neg-04",  # a 4 x 4 frame, one cube left out of its left (+y) side
            res(*_without(_FRAME4, (0.45, 0.40))),
            res(*_without(_FRAME4, (0.45, 0.25))),  # out of its right side
        ),
        (
            "dev35-neg-11",  # two 4 x 2 walls, apart, one running each way
            res(*_wall_x(0.30, 0.15, 4, 2), *_wall_y(0.65, 0.25, 4, 2)),
            res(*_wall_y(0.30, 0.25, 4, 2), *_wall_y(0.65, 0.25, 4, 2)),  # the same way
        ),
        (
            "dev35-reg-08",  # a 5 x 2 wall against the right-hand edge, running front to back
            res(*_wall_x(0.35, 0.075, 5, 2)),
            res(*_wall_y(0.45, 0.075, 5, 2)),  # running along the edge's end, left to right
        ),
        (
            "dev35-reg-12",  # 10 cm clear of the left edge (y 0.55) and of the back (x 0.80)
            res(*column(0.675, 0.425, 4)),
            res(*column(0.675, 0.175, 4)),  # 10 cm from the right edge instead
        ),
        (
            "dev35-reg-13",  # a 3 x 3 slab on the table's centre point (here 0.50, 0.30)
            res(*grid(0.45, 0.25, 3, 3)),
            res(*grid(0.35, 0.25, 3, 3)),  # centred at x 0.40
        ),
        (
            "dev35-open-04",  # an L standing up: a 4-column at one end of a row of three
            res(*column(0.45, 0.30, 4), cube(0.45, 0.35, C / 2), cube(0.45, 0.40, C / 2)),
            res(*_row_y(0.45, 0.30, 3)),  # a straight row
        ),
        (
            "dev35-open-11",  # a layout that is its own mirror image across y = 0.30
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 2), *column(0.45, 0.40, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 2), *column(0.45, 0.40, 2)),
        ),
        (
            "dev35-open-12",  # two things 10 cm apart left to right, their front faces in line
            res(*column(0.40, 0.20, 2), *grid(0.40, 0.35, 2, 2)),
            res(*column(0.40, 0.20, 2), *grid(0.45, 0.35, 2, 2)),  # the block set back
        ),
        (
            "dev35-bad-04",  # the request was cancelled: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 3), notes=["the request was cancelled; built it anyway"]),
        ),
        (
            "dev35-bad-14",  # half a cube: refuse, or build a whole number and say so
            res(*column(0.45, 0.30, 3), notes=["half cubes are not possible; built three"]),
            res(*column(0.45, 0.30, 3)),
        ),
    ],
)
def test_dev35_predicates_on_hand_built_layouts(
    case_id: str, right: dict[str, Any], wrong: dict[str, Any]
) -> None:
    case = _dev35(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
