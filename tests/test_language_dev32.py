"""The dev32 language set: its size, ids and phenomena, no command shared with another set,
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
from sdi.bench.language_dev32 import CASES as DEV32

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


Obj = dict[str, Any]
Result = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Sequence[float] = (1.0, 0.0, 0.0, 0.0)) -> Obj:
    return {"id": "b", "position": [x, y, z], "orientation": list(q), "size": [0.15, C, C]}


def res(*objs: Obj, status: str = "success", **extra: Any) -> Result:
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


def grid(x0: float, y0: float, a: int, b: int, layers: int = 1, z0: float = 0.0) -> list[Obj]:
    """a cubes along x by b along y, `layers` high, first cube centre at (x0, y0)."""
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


def _stairs_y(x: float, y0: float, hs: Sequence[int]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _stairs_x(x0: float, y: float, hs: Sequence[int]) -> list[Obj]:
    """Columns of the given heights in a line along x from x0 (front to back)."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _without(objs: list[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _dev32(case_id: str) -> Case:
    return next(c for c in DEV32 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV32) >= 180
    per = {p: sum(c.phenomenon == p for c in DEV32) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV32} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV32)
    ids = [c.id for c in DEV32]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev32-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV32:
        assert c.id.startswith(f"dev32-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name (this one and the shared checks
    left out; a set that does not import yet, e.g. one still being written, is skipped)."""
    here = Path(k.__file__).parent
    out = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_checks", "language_dev32"):
            continue
        try:
            mod = importlib.import_module(f"sdi.bench.{name}")
        except Exception:  # a set mid-edit by someone else
            continue
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev27" in others and "language_dev31" in others
    seen: dict[str, str] = {}
    for c in DEV32:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    clashes = [
        (seen[_norm(c.text)], name, c.id)
        for name, cases in others.items()
        for c in cases
        if _norm(c.text) in seen
    ]
    assert not clashes, clashes  # ids only, never another set's text
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV32}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT = {"status": "error", "layout": None}
EMPTY = res()
OUTSIDE = res(*column(0.95, 0.30, 2), notes=["moved"])


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT, EMPTY, OUTSIDE])
def test_every_predicate_answers_without_raising(result: Result) -> None:
    for case in DEV32:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev32.py").read_text(encoding="utf-8")
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
_STAIRS4_W2 = [c for x in (0.45, 0.50) for c in _stairs_y(x, 0.20, (1, 2, 3, 4))]
_STAIRS3_W2 = [c for x in (0.45, 0.50) for c in _stairs_y(x, 0.25, (1, 2, 3))]
_GOAL = [*column(0.50, 0.25, 3), *column(0.50, 0.35, 3), beam(0.50, 0.30, 0.175, YAW90)]
_BRIDGE5 = [*column(0.45, 0.25, 5), *column(0.45, 0.35, 5), beam(0.45, 0.30, 0.275, YAW90)]
_SLAB_BR = grid(0.65, 0.10, 2, 4)  # x 0.625–0.725, y 0.075–0.275: the back right
_PYR_16_9_4 = [
    *grid(0.40, 0.25, 4, 4),
    *grid(0.425, 0.275, 3, 3, z0=C),
    *grid(0.45, 0.30, 2, 2, z0=2 * C),
]
_ERROR = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev32-rel-01",  # a 2-tower right next to a 4-tower on its left, a cube clear …
            res(*column(0.45, 0.25, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.25, 4), *column(0.45, 0.15, 2)),  # on its right
        ),
        (
            "dev32-rel-01",  # … or set against its left side
            res(*column(0.45, 0.25, 4), *column(0.45, 0.30, 2)),
            res(*column(0.45, 0.25, 4), *column(0.45, 0.20, 2)),  # against its right side
        ),
        (
            "dev32-rel-05",  # a back-left 5-tower with a 2 x 2 x 2 block in front of it
            res(*column(0.65, 0.45, 5), *grid(0.45, 0.40, 2, 2, layers=2)),
            res(*column(0.65, 0.45, 5), *grid(0.625, 0.30, 2, 2, layers=2)),  # to its right
        ),
        (
            "dev32-rel-08",  # a 6-tower in the middle of a 5 x 5 ring, not touching it
            res(*_PEN5, *column(0.45, 0.30, 6)),
            res(*_PEN5, *column(0.70, 0.30, 6)),  # outside the ring
        ),
        (
            "dev32-rel-10",  # a 3-tower standing on a 2 x 2 block one high
            res(*grid(0.45, 0.30, 2, 2), *column(0.45, 0.30, 3, C)),
            res(*grid(0.45, 0.30, 2, 2), *column(0.45, 0.40, 3)),  # beside it on the table
        ),
        (
            "dev32-rel-13",  # a 4-tower a cube from the foot of stairs climbing to the left
            res(*_stairs_y(0.45, 0.25, (1, 2, 3, 4)), *column(0.45, 0.15, 4)),
            res(*_stairs_y(0.45, 0.25, (1, 2, 3, 4)), *column(0.45, 0.50, 4)),  # at the top
        ),
        (
            "dev32-rel-17",  # 2-high pillars two cubes apart under a bar of four cubes
            res(*column(0.45, 0.20, 2), *column(0.45, 0.35, 2), *_row_y(0.45, 0.20, 4, 2 * C)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 2), *_row_y(0.45, 0.20, 3, 2 * C)),
        ),
        (
            "dev32-rel-19",  # a goal with a single-cube ball in front of it
            res(*_GOAL, cube(0.35, 0.30, C / 2)),
            res(*_GOAL, cube(0.65, 0.30, C / 2)),  # behind it
        ),
        (
            "dev32-rel-20",  # a 4 x 4 ring with a 2 x 2 x 2 block filling its middle
            res(*ring(0.40, 0.25, 4), *grid(0.45, 0.30, 2, 2, layers=2)),
            res(*ring(0.40, 0.25, 4), *grid(0.65, 0.30, 2, 2, layers=2)),  # outside it
        ),
        (
            "dev32-rel-22",  # a 5-tower against the left side of a 2 x 2 x 3 block
            res(*grid(0.45, 0.25, 2, 2, layers=3), *column(0.45, 0.35, 5)),
            res(*grid(0.45, 0.25, 2, 2, layers=3), *column(0.45, 0.20, 5)),  # its right side
        ),
        (
            "dev32-rel-23",  # a row of five with a cube on top of each end
            res(*_stairs_y(0.45, 0.20, (2, 1, 1, 1, 2))),
            res(*_row_y(0.45, 0.15, 7)),  # a cube added at each end on the table
        ),
        (
            "dev32-seq-04",  # a 2 x 3 platform with a 3-pillar on a corner cell
            res(*grid(0.45, 0.25, 2, 3), *column(0.45, 0.25, 3, C)),
            res(*grid(0.45, 0.25, 2, 3), *column(0.45, 0.30, 3, C)),  # mid-edge cell
        ),
        (
            "dev32-seq-07",  # step by step: 16-9-4-1
            res(*_PYR_16_9_4, cube(0.475, 0.325, 0.175)),
            res(*_PYR_16_9_4),  # step 4 left off
        ),
        (
            "dev32-seq-08",  # two 4-towers, the right one (-y) shortened to 3
            res(*column(0.45, 0.35, 4), *column(0.45, 0.25, 3)),
            res(*column(0.45, 0.35, 3), *column(0.45, 0.25, 4)),  # the left one shortened
        ),
        (
            "dev32-seq-09",  # four steps up to the left, one more cube on the top step
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 5))),
            res(*_stairs_y(0.45, 0.20, (5, 3, 2, 1))),  # climbing to the right
        ),
        (
            "dev32-seq-15",  # 5-post bridge with one cube on the middle of the beam
            res(*_BRIDGE5, cube(0.45, 0.30, 0.325)),
            res(*_BRIDGE5, cube(0.45, 0.25, 0.325)),  # over one post
        ),
        (
            "dev32-seq-20",  # a 4 x 2 slab at the back right with a cube on each corner
            res(*_SLAB_BR, *[cube(x, y, 0.075) for x in (0.65, 0.70) for y in (0.10, 0.25)]),
            res(*_SLAB_BR, *[cube(x, y, 0.075) for x in (0.65, 0.70) for y in (0.15, 0.20)]),
        ),
        (
            "dev32-num-10",  # heights 1, 2, 3, 4 from left (+y) to right, a cube apart
            res(
                *[c for i, y in enumerate((0.45, 0.35, 0.25, 0.15)) for c in column(0.45, y, i + 1)]
            ),
            res(
                *[c for i, y in enumerate((0.15, 0.25, 0.35, 0.45)) for c in column(0.45, y, i + 1)]
            ),
        ),
        (
            "dev32-num-13",  # three steps from a dozen cubes: two cubes wide
            res(*_STAIRS3_W2),
            res(*_stairs_y(0.45, 0.25, (1, 2, 3))),  # six cubes
        ),
        (
            "dev32-num-14",  # a hedge of five with a cube on the middle one
            res(*_stairs_y(0.45, 0.20, (1, 1, 2, 1, 1))),
            res(*_stairs_y(0.45, 0.20, (2, 1, 1, 1, 1))),  # on the end one
        ),
        (
            "dev32-num-16",  # two rows of three, one behind the other, a cube apart …
            res(*_row_y(0.40, 0.25, 3), *_row_y(0.50, 0.25, 3)),
            res(*_row_y(0.45, 0.10, 3), *_row_y(0.45, 0.30, 3)),  # end to end, left–right
        ),
        (
            "dev32-num-16",  # … or end to end front to back
            res(*_row_x(0.25, 0.30, 3), *_row_x(0.45, 0.30, 3)),
            res(*_row_x(0.25, 0.30, 3), *_row_x(0.50, 0.30, 3)),  # two cubes apart
        ),
        (
            "dev32-dim-12",  # 150 x 100 x 100: 3 x 2 two high …
            res(*grid(0.45, 0.25, 3, 2, layers=2)),
            res(*grid(0.45, 0.25, 3, 2, layers=1)),
        ),
        (
            "dev32-dim-12",  # … or 2 x 2 three high
            res(*grid(0.45, 0.25, 2, 2, layers=3)),
            res(*grid(0.45, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev32-dim-15",  # 10 cm apart: two cubes clear (or one, centre to centre)
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 3)),  # three cubes clear
        ),
        (
            "dev32-dim-20",  # four steps, 10 cm (two cubes) wide
            res(*_STAIRS4_W2),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),  # one cube wide
        ),
        (
            "dev32-wo-13",  # two parallel rows of four, one cube clear …
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.50, 0.20, 4)),
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.60, 0.20, 4)),  # three cubes clear
        ),
        (
            "dev32-wo-13",  # … or two cubes clear
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.55, 0.20, 4)),
            res(*_row_y(0.40, 0.10, 4), *_row_y(0.40, 0.35, 4)),  # end to end
        ),
        (
            "dev32-wo-14",  # a 3 x 2 wall between two 4-towers, clear of both …
            res(
                *column(0.45, 0.15, 4),
                *_row_y(0.45, 0.25, 3),
                *_row_y(0.45, 0.25, 3, C),
                *column(0.45, 0.45, 4),
            ),
            res(
                *column(0.45, 0.15, 4),
                *column(0.45, 0.25, 4),
                *_row_y(0.45, 0.35, 3),
                *_row_y(0.45, 0.35, 3, C),
            ),
        ),
        (
            "dev32-wo-14",  # … or set against both
            res(*_stairs_y(0.45, 0.15, (4, 2, 2, 2, 4))),
            res(*_stairs_y(0.45, 0.15, (4, 4, 2, 2, 2))),
        ),
        (
            "dev32-neg-06",  # four steps, not climbing to the back
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev32-neg-13",  # a 5 x 5 ring with an opening in the middle of its left side
            res(*_without(_PEN5, (0.45, 0.40))),
            res(*_without(_PEN5, (0.45, 0.20))),  # in its right side
        ),
        (
            "dev32-reg-03",  # a front-to-back row of five along the right-hand edge
            res(*_row_x(0.35, 0.10, 5)),
            res(*_row_x(0.35, 0.20, 5)),  # on the right, but off the edge
        ),
        (
            "dev32-reg-15",  # a 2 x 2 x 3 block at the back, in the middle left to right
            res(*grid(0.65, 0.275, 2, 2, layers=3)),
            res(*grid(0.65, 0.45, 2, 2, layers=3)),  # the back-left corner
        ),
        (
            "dev32-open-03",  # anything with a beam in it
            BRIDGE,
            TOWER3,
        ),
        (
            "dev32-bad-12",  # the check build was cancelled: only a refusal will do
            _ERROR,
            res(*grid(0.45, 0.30, 2, 2, layers=3), notes=["built as asked first"]),
        ),
        (
            "dev32-bad-18",  # a position off the table: refuse, or build and say so
            res(*column(0.70, 0.30, 3), notes=["x 1200 is off the table; placed at x 700"]),
            res(*column(0.70, 0.30, 3)),
        ),
    ],
)
def test_dev32_predicates_on_hand_built_layouts(case_id: str, right: Result, wrong: Result) -> None:
    case = _dev32(case_id)
    assert case.accept(right) is None, case.accept(right)
    assert case.accept(wrong) is not None
