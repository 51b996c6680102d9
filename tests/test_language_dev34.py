"""The dev34 language set: its size, ids and phenomena, no command shared with another set,
predicates that answer on any result, and the harder and local predicates on hand-built
layouts (each must pass the right layout and fail the one a careless reader would build)."""

from __future__ import annotations

import importlib
import math
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import pytest

from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case
from sdi.bench.language_dev34 import CASES as DEV34

Obj = dict[str, Any]

YAW90 = [math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4)]
C = 0.05


def cube(x: float, y: float, z: float, i: list[int] = [0]) -> Obj:  # noqa: B006 - a running id
    i[0] += 1
    return {"id": f"c{i[0]}", "position": [x, y, z], "orientation": [1, 0, 0, 0], "size": [C, C, C]}


def beam(x: float, y: float, z: float, q: Iterable[float] = (1.0, 0.0, 0.0, 0.0)) -> Obj:
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


def _stairs_y(x: float, y0: float, hs: Iterable[int]) -> list[Obj]:
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _singles(x: float, ys: Iterable[float]) -> list[Obj]:
    """Single cubes at x, one at each y."""
    return [cube(x, y, C / 2) for y in ys]


def _without(objs: list[Obj], *xy: tuple[float, float]) -> list[Obj]:
    """The objects less those whose centre is at one of the (x, y) points."""

    def hit(o: Obj) -> bool:
        return any(
            abs(o["position"][0] - x) < 1e-6 and abs(o["position"][1] - y) < 1e-6 for x, y in xy
        )

    return [o for o in objs if not hit(o)]


def _posts_bar(legs: int) -> list[Obj]:
    """Two posts `legs` high at y 0.25 and 0.35 (a cube clear) under a bar of three cubes."""
    return [
        *column(0.45, 0.25, legs),
        *column(0.45, 0.35, legs),
        *_row_y(0.45, 0.25, 3, z0=C * legs),
    ]


def _posts_beam(legs: int) -> list[Obj]:
    """Two posts `legs` high at y 0.25 and 0.35 under a beam turned to run along y."""
    return [
        *column(0.45, 0.25, legs),
        *column(0.45, 0.35, legs),
        beam(0.45, 0.30, C * legs + C / 2, YAW90),
    ]


def _dev34(case_id: str) -> Case:
    return next(c for c in DEV34 if c.id == case_id)


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# ---------------------------------------------------------------- the set itself


def test_size_ids_and_phenomena() -> None:
    assert len(DEV34) >= 170
    per = {p: sum(c.phenomenon == p for c in DEV34) for p in PHENOMENA}
    assert min(per.values()) >= 8, per
    assert min(per[p] for p in ("relation", "numbers", "dimensions", "sequence")) >= 15, per
    assert {c.phenomenon for c in DEV34} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in DEV34)
    ids = [c.id for c in DEV34]
    assert len(ids) == len(set(ids))
    assert all(i.startswith("dev34-") for i in ids)
    short = {k.REL: "rel", k.SEQ: "seq", k.NUM: "num", k.DIM: "dim", k.NEG: "neg"}
    short |= {k.TYP: "typo", k.WO: "wo", k.FIL: "fil", k.REG: "reg", k.OPEN: "open"}
    short |= {k.BAD: "bad"}
    for c in DEV34:
        assert c.id.startswith(f"dev34-{short[c.phenomenon]}-"), c.id


def _other_sets() -> dict[str, list[Case]]:
    """Every other language set's CASES, by module name — all but the frozen test set (never
    opened here) and this one."""
    here = Path(k.__file__).parent
    out: dict[str, list[Case]] = {}
    for path in sorted(here.glob("language_*.py")):
        name = path.stem
        if name in ("language_test", "language_checks", "language_dev34"):
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
    for c in DEV34:
        assert _norm(c.text), c.id
        assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
        seen[_norm(c.text)] = c.id
    for name, cases in others.items():
        for c in cases:
            assert _norm(c.text) not in seen, (seen.get(_norm(c.text)), name, c.id)
    other_ids = {c.id for cases in others.values() for c in cases}
    assert not other_ids & {c.id for c in DEV34}


TOWER3 = res(*column(0.45, 0.30, 3))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
NO_LAYOUT: Obj = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result: Mapping[str, Any]) -> None:
    for case in DEV34:
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_module_imports_nothing_from_the_system_it_judges() -> None:
    src = (Path(k.__file__).parent / "language_dev34.py").read_text(encoding="utf-8")
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

_SLAB3 = grid(0.40, 0.25, 3, 3)  # x 0.375–0.525, y 0.225–0.375
_SLAB4 = grid(0.40, 0.25, 4, 4)  # x 0.375–0.575, y 0.225–0.425, centre (0.475, 0.325)
_SLAB3_FRONT = grid(0.25, 0.25, 3, 3)  # x 0.225–0.375, y 0.225–0.375: the front region
_FIRE5_2HIGH = ring(0.35, 0.20, 5, high=2)  # x 0.325–0.575, y 0.175–0.425; middle (0.45, 0.30)
_ERROR: Obj = {"status": "error", "layout": None}


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev34-rel-02",  # a gateway with no beam named: a bar of cubes on posts of three
            res(*_posts_bar(3)),
            res(*_posts_beam(2)),  # posts of two
        ),
        (
            "dev34-rel-03",  # a 3-tower on the middle cube of a row of five
            res(*_stairs_y(0.45, 0.20, (1, 1, 4, 1, 1))),
            res(*_stairs_y(0.45, 0.20, (4, 1, 1, 1, 1))),  # on the end cube
        ),
        (
            "dev34-rel-06",  # a fire ring of any height, a 2-flagpole in its middle
            res(*_FIRE5_2HIGH, *column(0.45, 0.30, 2)),
            res(*_FIRE5_2HIGH, *column(0.70, 0.30, 2)),  # outside it
        ),
        (
            "dev34-rel-09",  # a front slab and a 5-tower behind it, clear …
            res(*_SLAB3_FRONT, *column(0.45, 0.30, 5)),
            res(*_SLAB3_FRONT, *column(0.30, 0.45, 5)),  # to its left
        ),
        (
            "dev34-rel-09",  # … or set against its back face
            res(*_SLAB3_FRONT, *column(0.40, 0.30, 5)),
            res(*_SLAB3_FRONT, *column(0.30, 0.40, 5)),  # against its left face
        ),
        (
            "dev34-rel-15",  # a 2 x 2 column 4 high centred on a 4 x 4 slab
            res(*_SLAB4, *grid(0.45, 0.30, 2, 2, layers=4, z0=C)),
            res(*_SLAB4, *grid(0.40, 0.25, 2, 2, layers=4, z0=C)),  # in a corner
        ),
        (
            "dev34-rel-17",  # a 5 x 2 wall with a cube on each end
            res(*_stairs_y(0.45, 0.20, (3, 2, 2, 2, 3))),
            res(*_stairs_y(0.45, 0.20, (3, 2, 2, 2, 2))),  # one end only
        ),
        (
            "dev34-rel-18",  # a cube on the middle of the beam of a 3-post bridge
            res(*_posts_beam(3), cube(0.45, 0.30, 0.225)),
            res(*_posts_beam(3), cube(0.45, 0.25, 0.225)),  # over one post
        ),
        (
            "dev34-rel-20",  # a 2-tower halfway between two 4-towers 300 mm centre to centre
            res(*column(0.45, 0.15, 4), *column(0.45, 0.30, 2), *column(0.45, 0.45, 4)),
            res(*column(0.45, 0.15, 4), *column(0.45, 0.25, 2), *column(0.45, 0.45, 4)),
        ),
        (
            "dev34-seq-05",  # a 2 x 2 second layer on one corner of a 3 x 3 slab
            res(*_SLAB3, *grid(0.40, 0.25, 2, 2, z0=C)),
            res(*_SLAB3, *grid(0.40, 0.25, 3, 3, z0=C)),  # a full second layer
        ),
        (
            "dev34-seq-13",  # a 3-tower on the left (+y) end of a row of four
            res(*_stairs_y(0.45, 0.15, (1, 1, 1, 4))),
            res(*_stairs_y(0.45, 0.15, (4, 1, 1, 1))),  # on the right end
        ),
        (
            "dev34-seq-14",  # a three-level pyramid less its top cube: 9-4
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C)),
            res(*_SLAB3, *grid(0.425, 0.275, 2, 2, z0=C), cube(0.45, 0.30, 0.125)),
        ),
        (
            "dev34-seq-17",  # five front stepping stones a cube apart, the middle one gone
            res(*_singles(0.30, (0.10, 0.20, 0.40, 0.50))),
            res(*_singles(0.30, (0.10, 0.20, 0.30, 0.40))),  # an end one gone
        ),
        (
            "dev34-seq-20",  # a 3-column standing on each end cube of a row of five
            res(*_stairs_y(0.45, 0.20, (4, 1, 1, 1, 4))),
            res(*_stairs_y(0.45, 0.20, (3, 1, 1, 1, 3))),  # 15 cm counted from the table
        ),
        (
            "dev34-num-11",  # four single cubes on the corners of a square, one cube clear
            res(*_singles(0.40, (0.25, 0.35)), *_singles(0.50, (0.25, 0.35))),
            res(*_singles(0.40, (0.15, 0.25, 0.35, 0.45))),  # in a line
        ),
        (
            "dev34-num-19",  # 2, 3, 4 in a line, the 2 raised to 4
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 3), *column(0.45, 0.40, 4)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.30, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev34-neg-08",  # a bar of cubes on posts of two
            res(*_posts_bar(2)),
            res(*_posts_bar(3)),  # posts of three
        ),
        (
            "dev34-neg-14",  # a 5 x 5 ring, one high, a one-cube gap in its robot-facing side
            res(*_without(ring(0.40, 0.20, 5), (0.40, 0.30))),
            res(*_without(ring(0.40, 0.20, 5), (0.60, 0.30))),  # in the back side
        ),
        (
            "dev34-neg-15",  # a row of six, every part 40 cm or more from the robot
            res(*_row_y(0.45, 0.15, 6)),
            res(*_row_y(0.25, 0.15, 6)),
        ),
        (
            "dev34-reg-08",  # a front-to-back row of four along the right-hand edge
            res(*_row_x(0.35, 0.10, 4)),
            res(*_row_x(0.35, 0.20, 4)),  # on the right, but not along the edge
        ),
        (
            "dev34-wo-09",  # a 2-tower set against the right (-y) of a 5-tower
            res(*column(0.45, 0.30, 5), *column(0.45, 0.25, 2)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.35, 2)),  # against its left
        ),
        (
            "dev34-typo-14",  # four single stepping stones in a line, gaps between
            res(*_singles(0.45, (0.15, 0.25, 0.35, 0.45))),
            res(*_row_y(0.45, 0.15, 4)),  # touching: one row
        ),
        (
            "dev34-open-05",  # anything within 150 by 150 mm
            res(*_SLAB3),
            res(*grid(0.40, 0.25, 4, 2)),  # 200 mm long
        ),
        (
            "dev34-open-06",  # two separate structures
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 3)),
            res(*column(0.45, 0.25, 2), *column(0.45, 0.30, 3)),  # touching: one
        ),
        (
            "dev34-open-11",  # cubes only, no more than eight
            res(*grid(0.40, 0.25, 2, 4)),
            res(*_SLAB3),  # nine cubes
        ),
        (
            "dev34-bad-13",  # two heights for one tower: refuse, or build and say so
            res(*column(0.45, 0.30, 3), notes=["two heights given for one tower; built 3"]),
            res(*column(0.45, 0.30, 3)),
        ),
        (
            "dev34-bad-18",  # asked to build nothing: only a refusal will do
            _ERROR,
            res(*column(0.45, 0.30, 2), notes=["built a small tower"]),
        ),
    ],
)
def test_dev34_predicates_on_hand_built_layouts(
    case_id: str, right: Mapping[str, Any], wrong: Mapping[str, Any]
) -> None:
    case = _dev34(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None
