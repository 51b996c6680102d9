"""The dev36 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder predicates on hand-built layouts (each
must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev36 import CASES as DEV36

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05
Obj = dict[str, Any]


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(
    x: float, y: float, z: float, q: tuple[float, ...] | list[float] = (1.0, 0.0, 0.0, 0.0)
) -> Obj:
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


def _stairs_y(x: float, y0: float, hs: tuple[int, ...]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _towers_y(x: float, placed: list[tuple[float, int]]) -> list[Obj]:
    """Separate columns at (x, y) for each (y, height) in `placed`."""
    return [c for y, h in placed for c in column(x, y, h)]


def _without(objs: list[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _dev36(case_id: str) -> Case:
    return next(c for c in DEV36 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV36) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV36) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV36} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV36)
    ids = [c.id for c in DEV36]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev36-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV36:
        assert c.id.startswith(f"dev36-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev36"):
            continue
        mod = importlib.import_module(f"sdi.bench.{name}")
        cases = getattr(mod, "CASES", None)
        if cases is not None:
            out[name] = list(cases)
    return out


def test_no_command_is_shared_within_the_set_or_with_another() -> None:
    others = _other_sets()
    assert "language_dev34" in others and "language_dev35" in others
    seen: dict[str, str] = {}
    for c in DEV36:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV36}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT: Obj = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result: Mapping[str, Any]) -> None:
    for case in DEV36:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev36.py").read_text(encoding="utf-8")
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
_ROW5 = _row_y(0.45, 0.20, 5)  # x 0.425–0.475, y 0.175–0.425
_ROW5_FRONT = _row_y(0.30, 0.20, 5)  # x 0.275–0.325, y 0.175–0.425
# a 9-4-1 pyramid centred at (0.45, 0.30), y 0.225–0.375
_PYR = [
    *grid(0.40, 0.25, 3, 3),
    *grid(0.425, 0.275, 2, 2, z0=C),
    cube(0.45, 0.30, 0.125),
]
_SLAB2X4 = grid(0.40, 0.20, 2, 4)  # x 0.375–0.475, y 0.175–0.375
_ERROR: Obj = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev36-rel-01",  # a 3-tower on the left with a row of four in front of it …
            res(*column(0.45, 0.45, 3), *_row_y(0.30, 0.30, 4)),
            res(*column(0.45, 0.45, 3), *_row_y(0.60, 0.30, 4)),  # the row behind it
        ),
        (
            "dev36-rel-01",  # … or the tower set against the back of the row
            res(*column(0.40, 0.45, 3), *_row_y(0.35, 0.35, 4)),
            res(*column(0.40, 0.15, 3), *_row_y(0.35, 0.10, 4)),  # the tower on the right
        ),
        (
            "dev36-rel-05",  # one cube in the middle of a 5 x 5 ring
            res(*_PEN5, cube(0.45, 0.30, C / 2)),
            res(*_PEN5, cube(0.70, 0.30, C / 2)),  # outside it
        ),
        (
            "dev36-rel-07",  # a 2-tower butted against the end of a row of five
            res(*_ROW5, *column(0.45, 0.45, 2)),
            res(*_ROW5, *column(0.50, 0.30, 2)),  # against the middle of its side
        ),
        (
            "dev36-rel-08",  # a centre pyramid with a 4-tower on each side, a cube clear
            res(*_PYR, *column(0.45, 0.45, 4), *column(0.45, 0.15, 4)),
            res(*_PYR, *column(0.45, 0.45, 4), *column(0.30, 0.30, 4)),  # left and front
        ),
        (
            "dev36-rel-13",  # a 6-tower at the back lined up behind a 2-tower at the front
            res(*column(0.65, 0.30, 6), *column(0.30, 0.30, 2)),
            res(*column(0.65, 0.30, 6), *column(0.30, 0.20, 2)),  # not lined up
        ),
        (
            "dev36-rel-15",  # 2, 4, 2 in a straight line, apart …
            res(*_towers_y(0.45, [(0.20, 2), (0.30, 4), (0.40, 2)])),
            res(*_towers_y(0.45, [(0.20, 2), (0.30, 2), (0.40, 4)])),  # the 4 at an end
        ),
        (
            "dev36-rel-15",  # … or touching
            res(*_stairs_y(0.45, 0.25, (2, 4, 2))),
            res(*_stairs_y(0.45, 0.25, (2, 2, 4))),
        ),
        (
            "dev36-rel-16",  # a 3-tower directly behind a front-right 5-tower …
            res(*column(0.30, 0.15, 5), *column(0.45, 0.15, 3)),
            res(*column(0.30, 0.15, 5), *column(0.45, 0.25, 3)),  # behind, off to one side
        ),
        (
            "dev36-rel-16",  # … or set against its back
            res(*column(0.30, 0.15, 5), *column(0.35, 0.15, 3)),
            res(*column(0.30, 0.15, 5), *column(0.25, 0.15, 3)),  # against its front
        ),
        (
            "dev36-rel-18",  # the 7-tower behind the 3-tower, both on the centre line
            res(*column(0.60, 0.30, 7), *column(0.40, 0.30, 3)),
            res(*column(0.40, 0.30, 7), *column(0.60, 0.30, 3)),  # the other way round
        ),
        (
            "dev36-rel-20",  # a 4-tower behind the middle of a front row of five, a cube clear
            res(*_ROW5_FRONT, *column(0.40, 0.30, 4)),
            res(*_ROW5_FRONT, *column(0.40, 0.20, 4)),  # behind its end
        ),
        (
            "dev36-seq-16",  # a front-to-back row of three, three more cubes on its back end
            res(*_row_x(0.40, 0.30, 3), *column(0.50, 0.30, 3, C)),
            res(*_row_x(0.40, 0.30, 3), *column(0.40, 0.30, 3, C)),  # on the front end
        ),
        (
            "dev36-seq-17",  # a 2 x 2 in the middle of a 2 x 4 slab
            res(*_SLAB2X4, *grid(0.40, 0.25, 2, 2, z0=C)),
            res(*_SLAB2X4, *grid(0.40, 0.20, 2, 2, z0=C)),  # at one end
        ),
        (
            "dev36-seq-20",  # three 4-towers two cubes apart, the middle one removed
            res(*_towers_y(0.45, [(0.15, 4), (0.45, 4)])),
            res(*_towers_y(0.45, [(0.15, 4), (0.30, 4), (0.45, 4)])),
        ),
        (
            "dev36-num-02",  # 5, 4, 3, 2 from left (+y) to right, a cube apart
            res(*_towers_y(0.45, [(0.45, 5), (0.35, 4), (0.25, 3), (0.15, 2)])),
            res(*_towers_y(0.45, [(0.15, 5), (0.25, 4), (0.35, 3), (0.45, 2)])),
        ),
        (
            "dev36-num-17",  # 1, 2, 3 in ascending order, either way along the line
            res(*_towers_y(0.45, [(0.20, 3), (0.30, 2), (0.40, 1)])),
            res(*_towers_y(0.45, [(0.20, 1), (0.30, 3), (0.40, 2)])),
        ),
        (
            "dev36-neg-07",  # a 4 x 4 frame, one course, a cube left out of its back side
            res(*_without(ring(0.40, 0.25, 4), (0.55, 0.30))),
            res(*_without(ring(0.40, 0.25, 4), (0.40, 0.30))),  # out of its front side
        ),
        (
            "dev36-neg-09",  # a 3 x 4 slab less its two middle cubes
            res(*_without(grid(0.40, 0.25, 3, 4), (0.45, 0.30), (0.45, 0.35))),
            res(*grid(0.40, 0.25, 3, 4)),
        ),
        (
            "dev36-neg-14",  # two 5-towers with no gap between them
            res(*column(0.45, 0.30, 5), *column(0.45, 0.35, 5)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.40, 5)),
        ),
        (
            "dev36-reg-06",  # a 4 x 2 wall running front to back along the right-hand edge
            res(*_row_x(0.40, 0.10, 4), *_row_x(0.40, 0.10, 4, z0=C)),
            res(*_row_x(0.40, 0.25, 4), *_row_x(0.40, 0.25, 4, z0=C)),  # off the edge
        ),
        (
            "dev36-reg-13",  # a 4-tower hard up against the left edge (y 0.55)
            res(*column(0.45, 0.525, 4)),
            res(*column(0.45, 0.45, 4)),
        ),
        (
            "dev36-wo-14",  # three wide (y), two deep (x), two high
            res(*grid(0.40, 0.25, 2, 3, layers=2)),
            res(*grid(0.40, 0.25, 3, 2, layers=2)),  # three deep, two wide
        ),
        (
            "dev36-dim-12",  # two 4-towers 10 cm apart, clear …
            res(*_towers_y(0.45, [(0.20, 4), (0.35, 4)])),
            res(*_towers_y(0.45, [(0.20, 4), (0.40, 4)])),  # 15 cm clear
        ),
        (
            "dev36-dim-12",  # … or centre to centre
            res(*_towers_y(0.45, [(0.20, 4), (0.30, 4)])),
            res(*_towers_y(0.45, [(0.20, 4), (0.25, 4)])),  # touching
        ),
        (
            "dev36-open-11",  # anything on the left half: every part at y ≥ 0.30
            res(*column(0.45, 0.45, 2)),
            res(*column(0.45, 0.30, 2)),  # straddling the middle
        ),
        (
            "dev36-bad-09",  # half a cube: refuse, or build a whole number and say so
            res(*column(0.45, 0.30, 4), notes=["no half cubes; rounded up to four"]),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev36-bad-02",  # asked to wait: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 3), notes=["built a tower while waiting"]),
        ),
    ],
)
def test_dev36_predicates_on_hand_built_layouts(
    case_id: str, right: Mapping[str, Any], wrong: Mapping[str, Any]
) -> None:
    case = _dev36(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
