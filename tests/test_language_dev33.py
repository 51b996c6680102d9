"""The dev33 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev33 import CASES as DEV33

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


Obj = dict[str, Any]
Res = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Any = (1.0, 0.0, 0.0, 0.0)) -> Obj:
    return {"id": "b", "position": [x, y, z], "orientation": list(q), "size": [0.15, C, C]}


def res(*objs: Obj, status: str = "success", **extra: Any) -> Res:
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


def _cols_y(x: float, y0: float, hs: tuple[int, ...]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left), touching."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _cols_x(x0: float, y: float, hs: tuple[int, ...]) -> list[Obj]:
    """Columns of the given heights in a line along x from x0 (front to back), touching."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _towers(*xyh: tuple[float, float, int]) -> list[Obj]:
    """Separate columns, one per (x, y, height)."""
    return [c for x, y, h in xyh for c in column(x, y, h)]


def _dev33(case_id: str) -> Case:
    return next(c for c in DEV33 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV33) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV33) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV33} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV33)
    ids = [c.id for c in DEV33]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev33-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV33:
        assert c.id.startswith(f"dev33-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name (modules that fail to import — a set
    still being written — are skipped). Only compared, never shown."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_dev33"):
            continue
        try:
            mod = importlib.import_module(f"sdi.bench.{name}")
        except Exception:  # a set another writer is still editing
            continue
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_dev31" in others
    seen: dict[str, str] = {}
    inside: list[tuple[str, str]] = []
    for c in DEV33:
        assert _norm(c.text), c.id
        if _norm(c.text) in seen:
            inside.append((seen[_norm(c.text)], c.id))
        seen[_norm(c.text)] = c.id
    assert inside == []
    # only ids are reported, never another set's text
    shared = [
        (seen[_norm(c.text)], name, c.id)
        for name, cases in others.items()
        for c in cases
        if _norm(c.text) in seen
    ]
    assert shared == []
    other_ids = {c.id for cases in others.values() for c in cases}
    assert sorted(other_ids & {c.id for c in DEV33}) == []


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
TWO = res(*column(0.30, 0.15, 2), *column(0.65, 0.45, 5), notes=["two towers"])
NO_LAYOUT: Res = {"status": "error", "layout": None}
EMPTY: Res = {"status": "success", "layout": {"objects": []}}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, TWO, NO_LAYOUT, EMPTY])
def test_every_predicate_answers_without_raising(result: Res) -> None:
    for case in DEV33:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev33.py").read_text(encoding="utf-8")
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


def test_bad_input_cases_are_judged_for_honesty() -> None:
    """A silent success never passes a bad-input case, whatever it built."""
    for case in DEV33:
        if case.phenomenon == k.BAD:
            assert case.accept(TOWER3) is not None, case.id
            assert case.accept(NO_LAYOUT) is None, case.id


# ---------------------------------------------------------------- hand-built layouts

_SLAB3_BR = grid(0.55, 0.15, 3, 3)  # x 0.525–0.675, y 0.125–0.275: the back right
_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375
_ROW5_BACK = _row_y(0.65, 0.20, 5)  # y 0.175–0.425, centre y 0.30
_WALL4X3_FRONT = _cols_y(0.30, 0.225, (3, 3, 3, 3))  # x 0.275–0.325, y 0.20–0.40
_WALL6X3_BACK = _cols_y(0.65, 0.175, (3,) * 6)
_BRIDGE3 = [
    *column(0.45, 0.25, 3),
    *column(0.45, 0.35, 3),
    beam(0.45, 0.30, 0.175, YAW90),
]
_ERROR: Res = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev33-rel-01",  # a 2-tower directly in front of a 4-tower at the back
            res(*_towers((0.65, 0.30, 4), (0.50, 0.30, 2))),
            res(*_towers((0.65, 0.30, 4), (0.45, 0.40, 2))),  # in front, but off to one side
        ),
        (
            "dev33-rel-04",  # a tall tower and a short one beside it, clear …
            res(*_towers((0.45, 0.25, 5), (0.45, 0.35, 2))),
            res(*_towers((0.45, 0.25, 3), (0.45, 0.35, 3))),  # the same height
        ),
        (
            "dev33-rel-04",  # … or set against it
            res(*_cols_y(0.45, 0.30, (5, 2))),
            res(*_cols_y(0.45, 0.30, (3, 3))),
        ),
        (
            "dev33-rel-05",  # a 4-stack in front of the middle of a back row of 5
            res(*_ROW5_BACK, *column(0.50, 0.30, 4)),
            res(*_ROW5_BACK, *column(0.50, 0.40, 4)),  # in front of its end
        ),
        (
            "dev33-rel-10",  # a 2-stack against the back of a front wall 4 x 3
            res(*_WALL4X3_FRONT, *column(0.35, 0.275, 2)),
            res(*_WALL4X3_FRONT, *column(0.25, 0.275, 2)),  # against its front
        ),
        (
            "dev33-rel-12",  # the left (+y) one twice the right one's 3
            res(*_towers((0.45, 0.35, 6), (0.45, 0.25, 3))),
            res(*_towers((0.45, 0.35, 3), (0.45, 0.25, 6))),  # the sides swapped
        ),
        (
            "dev33-rel-15",  # a row of 4 behind a 3-tower, touching
            res(*column(0.40, 0.30, 3), *_row_y(0.45, 0.225, 4)),
            res(*column(0.50, 0.30, 3), *_row_y(0.45, 0.225, 4)),  # the row in front
        ),
        (
            "dev33-rel-16",  # a back-right 3 x 3 slab with a 3-stack on its middle cube
            res(*_SLAB3_BR, *column(0.60, 0.20, 3, C)),
            res(*_SLAB3_BR, *column(0.55, 0.15, 3, C)),  # on a corner cube
        ),
        (
            "dev33-rel-17",  # a long front row and a shorter one behind it
            res(*_row_y(0.30, 0.20, 5), *_row_y(0.45, 0.25, 3)),
            res(*_row_y(0.30, 0.20, 5), *_row_y(0.45, 0.20, 5)),  # as long
        ),
        (
            "dev33-rel-19",  # a 2-stack between two 4-stacks, all touching
            res(*_cols_y(0.45, 0.25, (4, 2, 4))),
            res(*_cols_y(0.45, 0.25, (4, 4, 2))),  # the 2 at the end
        ),
        (
            "dev33-rel-21",  # a lower wall of the same length in front of a 6 x 3 back wall
            res(*_WALL6X3_BACK, *_row_y(0.45, 0.175, 6)),
            res(*_WALL6X3_BACK, *_cols_y(0.45, 0.175, (3,) * 6)),  # as high
        ),
        (
            "dev33-rel-22",  # 2, 6, 2 left to right, a cube's gap each side
            res(*_towers((0.45, 0.40, 2), (0.45, 0.30, 6), (0.45, 0.20, 2))),
            res(*_towers((0.45, 0.45, 2), (0.45, 0.30, 6), (0.45, 0.15, 2))),  # two cubes
        ),
        (
            "dev33-seq-05",  # two 4-towers a cube apart, the right (-y) one made taller
            res(*_towers((0.45, 0.35, 4), (0.45, 0.25, 6))),
            res(*_towers((0.45, 0.35, 6), (0.45, 0.25, 4))),  # the left one
        ),
        (
            "dev33-seq-10",  # three 2-stacks a cube apart, the middle one removed
            res(*_towers((0.45, 0.35, 2), (0.45, 0.15, 2))),
            res(*_towers((0.45, 0.35, 2), (0.45, 0.25, 2), (0.45, 0.15, 2))),
        ),
        (
            "dev33-seq-15",  # a bridge on 3-stacks with a cube on the middle of the beam
            res(*_BRIDGE3, cube(0.45, 0.30, 0.225)),
            res(*_BRIDGE3, cube(0.45, 0.25, 0.225)),  # on the end of the beam
        ),
        (
            "dev33-seq-17",  # a 3 x 3-based pyramid less its apex: 9-4 …
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C)),
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C), cube(0.45, 0.30, 0.125)),
        ),
        (
            "dev33-seq-17",  # … or the bare 3 x 3 layer of a 9-1 pyramid
            res(*_SLAB3),
            res(*_SLAB3, cube(0.45, 0.30, 0.075)),
        ),
        (
            "dev33-seq-19",  # a front-to-back row of 5 with one more on each end
            res(*_cols_x(0.40, 0.30, (2, 1, 1, 1, 2))),
            res(*_cols_y(0.45, 0.20, (2, 1, 1, 1, 2))),  # running left to right
        ),
        (
            "dev33-seq-20",  # the first (front-right) tower of 2 raised to 4
            res(*_towers((0.30, 0.15, 4), (0.45, 0.15, 4))),
            res(*_towers((0.30, 0.15, 2), (0.45, 0.15, 6))),  # the second one raised
        ),
        (
            "dev33-seq-21",  # three 3-towers a cube apart, the middle one the tallest
            res(*_towers((0.45, 0.20, 3), (0.45, 0.30, 5), (0.45, 0.40, 3))),
            res(*_towers((0.45, 0.20, 5), (0.45, 0.30, 3), (0.45, 0.40, 3))),
        ),
        (
            "dev33-seq-22",  # 3 and 6, then two off the bigger one: 3 and 4
            res(*_towers((0.45, 0.25, 3), (0.45, 0.35, 4))),
            res(*_towers((0.45, 0.25, 1), (0.45, 0.35, 6))),  # off the smaller one
        ),
        (
            "dev33-num-10",  # 1, 2, 3, 4 from front to back
            res(*_towers((0.30, 0.30, 1), (0.40, 0.30, 2), (0.50, 0.30, 3), (0.60, 0.30, 4))),
            res(*_towers((0.30, 0.30, 4), (0.40, 0.30, 3), (0.50, 0.30, 2), (0.60, 0.30, 1))),
        ),
        (
            "dev33-num-15",  # a 4-tower and a half-as-tall one set against it
            res(*_cols_y(0.45, 0.30, (4, 2))),
            res(*_cols_y(0.45, 0.30, (4, 3))),
        ),
        (
            "dev33-num-20",  # left to right: 2, then each taller than the one before
            res(*_towers((0.45, 0.40, 2), (0.45, 0.30, 3), (0.45, 0.20, 5))),
            res(*_towers((0.45, 0.40, 2), (0.45, 0.30, 4), (0.45, 0.20, 3))),
        ),
        (
            "dev33-dim-10",  # an 8-long wall and a shorter one parallel to it, 2 high
            res(*_cols_x(0.25, 0.30, (2,) * 8), *_cols_x(0.30, 0.40, (2,) * 5)),
            res(*_cols_x(0.25, 0.30, (2,) * 8), *_cols_x(0.70, 0.30, (2, 2))),  # end to end
        ),
        (
            "dev33-dim-12",  # two 3-towers 10 cm apart (clear, or centre to centre)
            res(*_towers((0.45, 0.20, 3), (0.45, 0.35, 3))),
            res(*_towers((0.45, 0.15, 3), (0.45, 0.40, 3))),  # 20 cm
        ),
        (
            "dev33-neg-05",  # two towers no taller than 3, the left one shorter
            res(*_towers((0.45, 0.40, 2), (0.45, 0.20, 3))),
            res(*_towers((0.45, 0.40, 3), (0.45, 0.20, 2))),
        ),
        (
            "dev33-neg-10",  # a 5-tower and a shorter one on opposite sides of the table
            res(*_towers((0.45, 0.45, 5), (0.45, 0.15, 3))),
            res(*_towers((0.45, 0.45, 5), (0.65, 0.45, 3))),  # both on the left
        ),
        (
            "dev33-reg-05",  # the 5 far left (+y), the 3 far right
            res(*_towers((0.45, 0.50, 5), (0.45, 0.10, 3))),
            res(*_towers((0.45, 0.50, 3), (0.45, 0.10, 5))),
        ),
        (
            "dev33-reg-10",  # a 4 in the left half, a taller one in the right half
            res(*_towers((0.45, 0.40, 4), (0.45, 0.20, 6))),
            res(*_towers((0.45, 0.40, 4), (0.65, 0.30, 6))),  # on the centre line
        ),
        (
            "dev33-typo-05",  # a short tower in front of a tall one
            res(*_towers((0.35, 0.30, 2), (0.55, 0.30, 5))),
            res(*_towers((0.35, 0.30, 5), (0.55, 0.30, 2))),  # the tall one in front
        ),
        (
            "dev33-fil-05",  # a 4-tower and a taller one set against it
            res(*_cols_y(0.45, 0.30, (4, 6))),
            res(*_cols_y(0.45, 0.30, (4, 4))),
        ),
        (
            "dev33-open-10",  # something wider than it is tall
            res(*_row_y(0.45, 0.20, 5)),
            res(*column(0.45, 0.30, 5)),
        ),
        (
            "dev33-seq-12",  # a 3-tower at the centre of a 5 x 5 ring
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.40, 0.25, 3)),  # against its inside corner
        ),
        (
            "dev33-bad-03",  # a metre is past the cell: build within it and say so
            res(*column(0.45, 0.30, 10), notes=["a metre is past the cell; built 10 high"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev33-bad-08",  # not a build at all: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 2), notes=["built something instead"]),
        ),
    ],
)
def test_dev33_predicates_on_hand_built_layouts(case_id: str, right: Res, wrong: Res) -> None:
    case = _dev33(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
