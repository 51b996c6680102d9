"""The language evaluation sets: the raw-JSON geometry, the acceptance checks on hand-built
layouts (each must pass the right layout and fail a wrong one), scoring, and the sets
themselves — sizes, unique ids, no shared commands, and the frozen test set's hash. The
second to nineteenth dev sets (dev2 … dev19) are held to the same checks and share no
command with any other set."""

from __future__ import annotations

import hashlib
import math
from pathlib import Path

import pytest

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import PHENOMENA, Case, score
from sdi.bench.language_dev import CASES as DEV
from sdi.bench.language_dev2 import CASES as DEV2
from sdi.bench.language_dev3 import CASES as DEV3
from sdi.bench.language_dev4 import CASES as DEV4
from sdi.bench.language_dev5 import CASES as DEV5
from sdi.bench.language_dev6 import CASES as DEV6
from sdi.bench.language_dev7 import CASES as DEV7
from sdi.bench.language_dev8 import CASES as DEV8
from sdi.bench.language_dev9 import CASES as DEV9
from sdi.bench.language_dev10 import CASES as DEV10
from sdi.bench.language_dev11 import CASES as DEV11
from sdi.bench.language_dev12 import CASES as DEV12
from sdi.bench.language_dev13 import CASES as DEV13
from sdi.bench.language_dev14 import CASES as DEV14
from sdi.bench.language_dev15 import CASES as DEV15
from sdi.bench.language_dev16 import CASES as DEV16
from sdi.bench.language_dev17 import CASES as DEV17
from sdi.bench.language_dev18 import CASES as DEV18
from sdi.bench.language_dev19 import CASES as DEV19
from sdi.bench.language_dev20 import CASES as DEV20
from sdi.bench.language_dev21 import CASES as DEV21
from sdi.bench.language_dev22 import CASES as DEV22
from sdi.bench.language_dev23 import CASES as DEV23
from sdi.bench.language_dev24 import CASES as DEV24
from sdi.bench.language_dev25 import CASES as DEV25
from sdi.bench.language_dev26 import CASES as DEV26
from sdi.bench.language_dev27 import CASES as DEV27
from sdi.bench.language_dev28 import CASES as DEV28
from sdi.bench.language_dev29 import CASES as DEV29
from sdi.bench.language_dev30 import CASES as DEV30
from sdi.bench.language_dev31 import CASES as DEV31
from sdi.bench.language_dev32 import CASES as DEV32
from sdi.bench.language_dev33 import CASES as DEV33
from sdi.bench.language_dev34 import CASES as DEV34
from sdi.bench.language_dev35 import CASES as DEV35
from sdi.bench.language_dev36 import CASES as DEV36
from sdi.bench.language_dev37 import CASES as DEV37
from sdi.bench.language_dev38 import CASES as DEV38
from sdi.bench.language_dev39 import CASES as DEV39
from sdi.bench.language_test import CASES as TEST

# sha256 of src/sdi/bench/language_test.py. The test set is frozen: changing this constant
# must be a deliberate, reviewed decision.
FROZEN_TEST_SHA256 = "7d1dd3c73b2b10f6f30c812bf0d0d6b9a140b1b80858ddbdf669aad08563a6fa"

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


TOWER3 = res(*column(0.45, 0.30, 3))
TOWER4 = res(*column(0.45, 0.30, 4))
# two 2-cube towers 0.10 m apart along y, a beam turned 90° about z resting on both
BRIDGE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.30, 0.125, YAW90))
BEAM_ON_ONE = res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2), beam(0.45, 0.20, 0.125, YAW90))
# a 5 × 5 ring (3 × 3 empty inside) with a 2-cube tower in the middle
PEN = res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 2))
_R5 = ring(0.35, 0.20, 5)
PEN_OPEN = res(*_R5[:2], *_R5[3:], *column(0.45, 0.30, 2))  # a side cube missing
TOWER_OUTSIDE = res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 2))
STAIRS3 = res(*column(0.40, 0.30, 1), *column(0.45, 0.30, 2), *column(0.50, 0.30, 3))


def test_box_of_rotated_beam():
    b = bx.box_of(beam(0.45, 0.30, 0.125, YAW90))
    assert b.size == pytest.approx((0.05, 0.15, 0.05))
    assert b.lo == pytest.approx((0.425, 0.225, 0.10))
    q45 = [math.cos(math.pi / 8), 0.0, 0.0, math.sin(math.pi / 8)]
    b45 = bx.box_of(beam(0.45, 0.30, 0.125, q45))
    side = (0.15 + 0.05) / 2 * math.sqrt(2)  # |R| rotates the half-extents
    assert b45.size == pytest.approx((side, side, 0.05))
    # a beam stood upright (90° about y) is 0.15 m tall
    qy = [math.cos(math.pi / 4), 0.0, math.sin(math.pi / 4), 0.0]
    assert bx.box_of(beam(0.45, 0.30, 0.075, qy)).size == pytest.approx((0.05, 0.05, 0.15))


def test_measures_on_a_tower_and_a_block():
    bs = bx.boxes(TOWER3)
    assert bx.count(bs) == 3 and bx.height_cubes(bs) == 3 and bx.tallest(bs) == 3
    assert bx.levels(bs) == {0.0: 1, 0.05: 1, 0.1: 1}
    assert bx.footprint_cubes(bs) == (1, 1)
    blk = bx.boxes(res(*grid(0.40, 0.25, 3, 2, layers=2)))
    assert bx.footprint_cubes(blk) == (3, 2) and bx.plan_dims(blk) == (2, 3)
    assert bx.level_counts(blk) == [6, 6] and bx.is_full(blk)
    assert bx.boxes({"status": "error", "layout": None}) == []


def test_contact_face_and_edge_but_not_corner():
    a = bx.box_of(cube(0.40, 0.30, 0.025))
    assert bx.touching(a, bx.box_of(cube(0.45, 0.30, 0.025)))  # face
    assert bx.touching(a, bx.box_of(cube(0.45, 0.35, 0.025)))  # vertical edge
    assert not bx.touching(a, bx.box_of(cube(0.45, 0.35, 0.075)))  # corner only
    assert not bx.touching(a, bx.box_of(cube(0.46, 0.30, 0.025)))  # 1 cm gap
    assert len(bx.components(bx.boxes(PEN))) == 2


def test_tower_checks():
    assert k.one(k.tower(3))(TOWER3) is None
    assert k.one(k.tower(3))(TOWER4) is not None
    assert k.one(k.tower(lo=2, hi=4))(TOWER4) is None
    assert k.one(k.tower(3))(res(*column(0.40, 0.30, 3), *column(0.60, 0.30, 3))) is not None
    assert k.each(2, k.tower(3))(res(*column(0.40, 0.30, 3), *column(0.60, 0.30, 3))) is None
    assert k.one(k.tower(3))({"status": "error", "layout": None}) == "no layout"


def test_bridge_on_two_towers():
    bs = bx.boxes(BRIDGE)
    spans = bx.spans(bs)
    assert len(spans) == 1 and len(spans[0].supports) == 2
    assert k.one(k.bridge(2, pillars=2))(BRIDGE) is None
    assert k.one(k.bridge(3))(BRIDGE) is not None  # pillars are 2 high
    assert k.one(k.bridge())(BEAM_ON_ONE) is not None  # the beam rests on one tower only
    assert k.one(k.bridge())(res(*column(0.45, 0.25, 2), *column(0.45, 0.35, 2))) is not None
    assert k.one(k.arch)(BRIDGE) is None and k.one(k.arch)(TOWER3) is not None


def test_ring_around_a_tower():
    assert k.around(k.tower(2))(PEN) is None
    assert k.around(k.tower(3))(PEN) is not None  # wrong tower height
    assert k.around(k.tower(2))(PEN_OPEN) is not None  # a gap in the ring
    assert k.around(k.tower(2))(TOWER_OUTSIDE) is not None
    ring_only = res(*ring(0.35, 0.20, 4))
    assert k.one(k.ring_of(high=1, inner=(2, 2)))(ring_only) is None
    assert k.one(k.ring_of(high=2))(ring_only) is not None
    assert k.one(k.ring)(TOWER3) is not None


def test_staircase_and_profile():
    assert bx.staircase_steps(bx.boxes(STAIRS3)) == 3
    assert bx.rises_towards(bx.boxes(STAIRS3)) == "back"
    assert k.one(k.staircase(3), k.rises("back"))(STAIRS3) is None
    assert k.one(k.staircase(4))(STAIRS3) is not None
    assert k.one(k.staircase())(TOWER3) is not None
    gappy = res(*column(0.40, 0.30, 1), *column(0.50, 0.30, 3), cube(0.45, 0.30, 0.075))
    assert k.one(k.staircase())(gappy) is not None  # a hole under the middle step
    ends = res(*column(0.40, 0.30, 2), cube(0.45, 0.30, 0.025), *column(0.50, 0.30, 2))
    assert k.one(k.profile(2, 1, 2))(ends) is None
    assert k.one(k.profile(1, 2, 3))(ends) is not None


def test_pyramid_and_on_top():
    pyr = res(*grid(0.40, 0.25, 3, 3), *grid(0.425, 0.275, 2, 2, z0=C), cube(0.45, 0.30, 0.125))
    assert bx.pyramid_levels(bx.boxes(pyr)) == [9, 4, 1]
    assert k.one(k.pyramid_counts(9, 4, 1), k.broad)(pyr) is None
    assert k.one(k.pyramid(2))(pyr) is not None
    assert k.one(k.pyramid())(res(*grid(0.40, 0.25, 3, 3, layers=2))) is not None
    slab_tower = res(*grid(0.40, 0.25, 2, 2), *column(0.40, 0.25, 2, z0=C))
    assert k.one(k.on_top(k.tower(2), k.block(2, 2, 1)))(slab_tower) is None
    assert k.one(k.on_top(k.tower(3), k.block(2, 2, 1)))(slab_tower) is not None
    assert bx.stands_on(
        bx.boxes(res(*column(0.40, 0.25, 2, z0=C))), bx.boxes(res(*grid(0.40, 0.25, 2, 2)))
    )


def test_canopy_on_four_legs():
    legs = [c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2)]
    roof = [beam(0.40, 0.30, 0.125, YAW90), beam(0.50, 0.30, 0.125, YAW90)]
    roof2 = [beam(0.45, 0.25, 0.175), beam(0.45, 0.35, 0.175)]
    table = res(*legs, *roof, *roof2)
    assert k.one(k.canopy(4, 2, 2))(table) is None
    assert k.one(k.canopy(4, 3, 3))(table) is not None
    assert k.one(k.canopy())(BRIDGE) is not None  # two legs only


def test_relative_placement_and_regions():
    tower_left = column(0.45, 0.45, 3)
    wall = [c for y in (0.15, 0.20, 0.25) for c in column(0.45, y, 2)]
    r = res(*tower_left, *wall)
    assert k.beside(k.tower(3), k.wall(3, 2), "left")(r) is None
    assert k.beside(k.tower(3), k.wall(3, 2), "right")(r) is not None
    assert k.beside(k.tower(3), k.wall(3, 2), "left", max_gap=0.05)(r) is not None
    assert bx.sides(bx.boxes(res(*tower_left)), bx.boxes(res(*wall))) == {"left"}
    assert k.one(k.tower(3), k.region("left"))(res(*tower_left)) is None
    assert k.one(k.tower(3), k.region("back left"))(res(*tower_left)) is not None
    assert k.one(k.tower(3), k.region("back left"))(res(*column(0.65, 0.45, 3))) is None
    assert k.one(k.tower(3), k.near(0.45, 0.45))(res(*tower_left)) is None
    three = res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 5), *column(0.45, 0.45, 2))
    assert k.between_(k.tower(5), k.tower(2))(three) is None
    off = res(*column(0.45, 0.15, 2), *column(0.45, 0.45, 5), *column(0.45, 0.30, 2))
    assert k.between_(k.tower(5), k.tower(2))(off) is not None
    outside = res(*column(0.85, 0.30, 3))
    assert k.one(k.tower(3))(outside) == "a part outside the workspace"


def test_letters():
    el = res(
        *[cube(0.40 + C * i, 0.25, 0.025) for i in range(3)],
        *[cube(0.40, 0.25 + C * j, 0.025) for j in range(1, 3)],
    )
    assert bx.letter(bx.boxes(el)) == "L"
    tee = res(
        *[cube(0.40 + C * i, 0.35, 0.025) for i in range(3)],
        *[cube(0.45, 0.25 + C * j, 0.025) for j in range(2)],
    )
    assert bx.letter(bx.boxes(tee)) == "T"
    plus = res(
        *[cube(0.40 + C * i, 0.30, 0.025) for i in range(3)],
        cube(0.45, 0.25, 0.025),
        cube(0.45, 0.35, 0.025),
    )
    assert bx.letter(bx.boxes(plus)) == "cross"
    assert bx.letter(bx.boxes(TOWER3)) is None


def test_scoring_outcomes():
    case = Case("x", "relation", "a 3-cube tower", k.one(k.tower(3)))
    assert score(case, TOWER3) == ("correct", None)
    assert score(case, TOWER4)[0] == "silent_misreading"
    assert score(case, {**TOWER3, "status": "partial"})[0] == "honest_miss"
    assert score(case, {"status": "error", "layout": None})[0] == "honest_miss"
    bad = Case("y", "bad_input", "a 3-cube tower 4 high", k.honest(k.one(k.tower(3))))
    assert score(bad, {"status": "error", "layout": None})[0] == "correct"
    assert score(bad, TOWER3)[0] == "silent_misreading"  # silent: no note of the assumption
    assert score(bad, {**TOWER3, "notes": ["assumed 3 cubes"]})[0] == "correct"
    assert score(bad, {**TOWER4, "notes": ["assumed 4 cubes"]})[0] == "silent_misreading"
    gib = Case("z", "bad_input", "blah", k.refused)
    assert score(gib, {"status": "failure", "layout": None})[0] == "honest_miss"
    crash = Case("w", "relation", "t", lambda r: r["nope"])  # a crashing predicate
    assert score(crash, TOWER3)[0] == "silent_misreading"


def _norm(text: str) -> str:
    return " ".join(text.lower().split())


# name → (cases, at least, at least per phenomenon, at least on the hard phenomena)
SETS = {
    "dev": (DEV, 150, 10, 0), "dev2": (DEV2, 160, 14, 0), "dev3": (DEV3, 180, 12, 18),
    "dev4": (DEV4, 150, 12, 0), "dev5": (DEV5, 150, 12, 0), "dev6": (DEV6, 120, 10, 0),
    "dev7": (DEV7, 120, 10, 0), "dev8": (DEV8, 120, 10, 0), "dev9": (DEV9, 120, 10, 0),
    "dev10": (DEV10, 120, 10, 0), "dev11": (DEV11, 150, 8, 15), "dev12": (DEV12, 150, 8, 15),
    "dev13": (DEV13, 160, 8, 15), "dev14": (DEV14, 160, 8, 15),
    "dev15": (DEV15, 160, 8, 15),
    "dev16": (DEV16, 160, 8, 15),
    "dev17": (DEV17, 170, 8, 15),
    "dev18": (DEV18, 170, 8, 15),
    "dev19": (DEV19, 170, 8, 15),
    "dev20": (DEV20, 170, 8, 15),
    "dev21": (DEV21, 170, 8, 15),
    "dev22": (DEV22, 170, 8, 15),
    "dev23": (DEV23, 170, 8, 15),
    "dev24": (DEV24, 170, 8, 15),
    "dev25": (DEV25, 170, 8, 15),
    "dev26": (DEV26, 170, 8, 15),
    "dev27": (DEV27, 170, 8, 15),
    "dev28": (DEV28, 180, 8, 15),
    "dev29": (DEV29, 180, 8, 15),
    "dev30": (DEV30, 180, 8, 15),
    "dev31": (DEV31, 180, 8, 15),
    "dev32": (DEV32, 180, 8, 15),
    "dev33": (DEV33, 180, 8, 15),
    "dev34": (DEV34, 180, 8, 15),
    "dev35": (DEV35, 180, 8, 15),
    "dev36": (DEV36, 180, 8, 15),
    "dev37": (DEV37, 180, 8, 15),
    "dev38": (DEV38, 180, 8, 15),
    "dev39": (DEV39, 180, 8, 15),
    "test": (TEST, 60, 5, 0),
}  # fmt: skip
HARD = {
    "dev3": ("relation", "sequence", "numbers", "dimensions", "negation", "word_order"),
    "dev11": ("relation", "numbers", "dimensions", "sequence"),
    "dev12": ("relation", "numbers", "dimensions", "sequence"),
    "dev13": ("relation", "numbers", "dimensions", "sequence"),
    "dev14": ("relation", "numbers", "dimensions", "sequence"),
    "dev15": ("relation", "numbers", "dimensions", "sequence"),
    "dev16": ("relation", "numbers", "dimensions", "sequence"),
    "dev17": ("relation", "numbers", "dimensions", "sequence"),
    "dev18": ("relation", "numbers", "dimensions", "sequence"),
    "dev19": ("relation", "numbers", "dimensions", "sequence"),
    "dev20": ("relation", "numbers", "dimensions", "sequence"),
    "dev21": ("relation", "numbers", "dimensions", "sequence"),
    "dev22": ("relation", "numbers", "dimensions", "sequence"),
    "dev23": ("relation", "numbers", "dimensions", "sequence"),
    "dev24": ("relation", "numbers", "dimensions", "sequence"),
    "dev25": ("relation", "numbers", "dimensions", "sequence"),
    "dev26": ("relation", "numbers", "dimensions", "sequence"),
    "dev27": ("relation", "numbers", "dimensions", "sequence"),
    "dev28": ("relation", "numbers", "dimensions", "sequence"),
    "dev29": ("relation", "numbers", "dimensions", "sequence"),
    "dev30": ("relation", "numbers", "dimensions", "sequence"),
    "dev31": ("relation", "numbers", "dimensions", "sequence"),
    "dev32": ("relation", "numbers", "dimensions", "sequence"),
    "dev33": ("relation", "numbers", "dimensions", "sequence"),
    "dev34": ("relation", "numbers", "dimensions", "sequence"),
    "dev35": ("relation", "numbers", "dimensions", "sequence"),
    "dev36": ("relation", "numbers", "dimensions", "sequence"),
    "dev37": ("relation", "numbers", "dimensions", "sequence"),
    "dev38": ("relation", "numbers", "dimensions", "sequence"),
    "dev39": ("relation", "numbers", "dimensions", "sequence"),
}


@pytest.mark.parametrize("name", list(SETS))
def test_set_sizes_ids_and_phenomena(name):
    cases, least, per_phenomenon, hard = SETS[name]
    assert len(cases) >= least
    if name not in ("dev", "test"):
        assert all(c.id.startswith(f"{name}-") for c in cases)
    per = {p: sum(c.phenomenon == p for c in cases) for p in PHENOMENA}
    assert set(per) == set(PHENOMENA) and min(per.values()) >= per_phenomenon, per
    assert min((per[p] for p in HARD.get(name, ())), default=hard) >= hard, per
    assert {c.phenomenon for c in cases} <= set(PHENOMENA)
    assert all(callable(c.accept) for c in cases)


def test_the_benchmarks_list_of_sets_is_every_set_here():
    assert list(k.SETS) == list(SETS)  # the benchmarks read k.SETS; a set left out goes unmeasured


def test_ids_are_unique_across_every_set():
    ids = [c.id for cases, *_ in SETS.values() for c in cases]
    assert len(ids) == len(set(ids))


def test_no_command_is_shared_within_or_between_sets():
    seen: dict[str, str] = {}
    for cases, *_ in SETS.values():
        for c in cases:
            if not _norm(c.text):
                continue  # blank commands (bad input) are alike by nature
            assert _norm(c.text) not in seen, (c.id, seen.get(_norm(c.text)))
            seen[_norm(c.text)] = c.id


def test_test_set_is_frozen():
    path = Path(k.__file__).with_name("language_test.py")
    assert hashlib.sha256(path.read_bytes()).hexdigest() == FROZEN_TEST_SHA256


NO_LAYOUT = {"status": "error", "layout": None}


@pytest.mark.parametrize("result", [TOWER3, BRIDGE, PEN, STAIRS3, NO_LAYOUT])
def test_every_predicate_answers_without_raising(result):
    for case in (
        *DEV,
        *DEV2,
        *DEV3,
        *DEV4,
        *DEV5,
        *DEV6,
        *DEV7,
        *DEV8,
        *DEV9,
        *DEV10,
        *DEV11,
        *DEV12,
        *DEV13,
        *DEV14,
        *DEV15,
        *DEV16,
        *DEV17,
        *DEV18,
        *DEV19,
        *DEV20,
        *DEV21,
        *DEV22,
        *TEST,
    ):
        out = case.accept(result)
        assert out is None or isinstance(out, str), case.id


def test_the_judges_import_nothing_from_the_system_they_judge():
    forbidden = (
        "sdi.model",
        "sdi.design",
        "sdi.inspector",
        "sdi.spec",
        "sdi.bench.signatures",
        "sdi.bench.suite",
        "sdi.pipeline",
    )
    here = Path(k.__file__).parent
    for name in (
        "boxes.py",
        "language_checks.py",
        "language_dev.py",
        "language_dev2.py",
        "language_dev3.py",
        "language_dev4.py",
        "language_dev5.py",
        "language_dev6.py",
        "language_dev7.py",
        "language_dev8.py",
        "language_dev9.py",
        "language_dev10.py",
        "language_dev11.py",
        "language_dev12.py",
        "language_dev13.py",
        "language_dev14.py",
        "language_dev15.py",
        "language_dev16.py",
        "language_dev17.py",
        "language_dev18.py",
        "language_dev19.py",
        "language_dev20.py",
        "language_dev21.py",
        "language_dev22.py",
        "language_dev23.py",
        "language_dev24.py",
        "language_dev25.py",
        "language_dev26.py",
        "language_dev27.py",
        "language_dev28.py",
        "language_dev29.py",
        "language_dev30.py",
        "language_dev31.py",
        "language_dev32.py",
        "language_dev33.py",
        "language_dev34.py",
        "language_dev35.py",
        "language_dev36.py",
        "language_dev37.py",
        "language_dev38.py",
        "language_dev39.py",
        "language_test.py",
    ):
        src = (here / name).read_text(encoding="utf-8")
        imports = [ln for ln in src.splitlines() if ln.lstrip().startswith(("import ", "from "))]
        assert not [ln for ln in imports if any(f in ln for f in forbidden)], name


def test_many_structures_match_quickly_and_one_to_one():
    singles = res(
        *[cube(0.25 + 0.1 * i, 0.10 + 0.1 * j, 0.025) for i in range(5) for j in range(3)]
    )
    assert k.each(15, k.tower(1))(singles) is None
    checks = [k.tower(1)] * 14 + [k.tower(2)]
    assert k.structures(*checks)(singles) is not None
    two = res(*column(0.40, 0.30, 2), *column(0.60, 0.30, 2))
    assert k.structures(k.tower(2), k.tower(3))(two) is not None  # no double use of a tower
    dup = res(*column(0.45, 0.30, 3), cube(0.45, 0.30, 0.075))
    assert k.one(k.tower(3))(dup) == "overlapping parts"


def _dev2(case_id: str) -> Case:
    return next(c for c in DEV2 if c.id == case_id)


_CASTLE = ring(0.35, 0.20, 5) + [
    c
    for x, y in ((0.35, 0.20), (0.55, 0.20), (0.35, 0.40), (0.55, 0.40))
    for c in column(x, y, 2, C)
]
_ROW4 = [cube(0.45, 0.225 + C * j, 0.025) for j in range(4)]
_STAIRS3 = column(0.30, 0.30, 1) + column(0.35, 0.30, 2) + column(0.40, 0.30, 3)
_CROSS = [cube(0.40 + C * i, 0.30, 0.025) for i in range(3)] + [
    cube(0.45, 0.25, 0.025),
    cube(0.45, 0.35, 0.025),
]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev2-rel-11",  # a castle with a single cube in its courtyard
            res(*_CASTLE, cube(0.45, 0.30, 0.025)),
            res(*ring(0.35, 0.20, 5), cube(0.45, 0.30, 0.025)),
        ),
        (
            "dev2-rel-17",  # a 4-cube row with a cube on each end
            res(*_ROW4, cube(0.45, 0.225, 0.075), cube(0.45, 0.375, 0.075)),
            res(*_ROW4, cube(0.45, 0.225, 0.075)),
        ),
        (
            "dev2-rel-07",  # a 4-cube tower with a 3-step staircase in front of it
            res(*_STAIRS3, *column(0.45, 0.30, 4)),  # built against it: one 4-step flight
            res(
                *column(0.45, 0.30, 1),
                *column(0.40, 0.30, 2),
                *column(0.35, 0.30, 3),
                *column(0.30, 0.30, 4),
            ),  # climbing towards the robot
        ),
        (
            "dev2-seq-05",  # a row of 5, then take away the middle cube
            res(*[cube(0.45, 0.20 + C * j, 0.025) for j in (0, 1, 3, 4)]),
            res(*[cube(0.45, 0.20 + C * j, 0.025) for j in range(4)]),
        ),
        (
            "dev2-seq-15",  # a 3x3 ring built up to 3 layers
            res(*ring(0.40, 0.25, 3, high=3)),
            res(*ring(0.40, 0.25, 3, high=1)),
        ),
        ("dev2-neg-08", res(*_CROSS), res(*grid(0.40, 0.25, 3, 3))),  # 3x3 without corners
        (
            "dev2-dim-16",  # 2 deep (along x, away from the robot) and 5 wide
            res(*grid(0.45, 0.20, 2, 5)),
            res(*grid(0.40, 0.25, 5, 2)),
        ),
        (
            "dev2-reg-15",  # 40 cm out from the robot, 10 cm left of centre
            res(*column(0.40, 0.40, 2)),
            res(*column(0.45, 0.45, 2)),
        ),
        (
            "dev2-neg-05",  # a staircase, not going up towards the robot
            res(*column(0.40, 0.30, 1), *column(0.40, 0.35, 2), *column(0.40, 0.40, 3)),
            res(*column(0.50, 0.30, 1), *column(0.45, 0.30, 2), *column(0.40, 0.30, 3)),
        ),
        (
            "dev2-open-19",  # twelve cubes packed as tightly as possible
            res(*grid(0.40, 0.25, 2, 2, layers=3)),
            res(*grid(0.40, 0.25, 2, 6)),
        ),
        ("dev2-open-06", res(*ring(0.40, 0.25, 4)), res(*ring(0.35, 0.20, 5))),  # small
        (
            "dev2-open-13",  # a sturdy base with a tall tower on it
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 3, z0=C)),
            res(*column(0.45, 0.30, 4)),
        ),
    ],
)
def test_dev2_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev2(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev3


def _dev3(case_id: str) -> Case:
    return next(c for c in DEV3 if c.id == case_id)


def _row_y(x, y0, n, z0=0.0):
    return [cube(x, y0 + C * j, z0 + C / 2) for j in range(n)]


def _row_x(x0, y, n, z0=0.0):
    return [cube(x0 + C * i, y, z0 + C / 2) for i in range(n)]


_BRIDGE3 = [*column(0.45, 0.25, 3), *column(0.45, 0.35, 3), beam(0.45, 0.30, 0.175, YAW90)]
_PLUS3 = [*_row_x(0.40, 0.30, 3), cube(0.45, 0.25, 0.025), cube(0.45, 0.35, 0.025)]
_PYR2 = [*grid(0.40, 0.25, 3, 3), *grid(0.425, 0.275, 2, 2, z0=C)]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev3-rel-21",  # a cube sitting on the middle of the beam of a 3-high bridge
            res(*_BRIDGE3, cube(0.45, 0.30, 0.225)),
            res(*_BRIDGE3, cube(0.45, 0.25, 0.225)),  # over a pillar, not the middle
        ),
        (
            "dev3-seq-10",  # a plus sign 3 across with one cube on its centre
            res(*_PLUS3, cube(0.45, 0.30, 0.075)),
            res(*_PLUS3, cube(0.40, 0.30, 0.075)),  # on an arm
        ),
        (
            "dev3-neg-11",  # two towers of 3, far apart
            res(*column(0.45, 0.10, 3), *column(0.45, 0.50, 3)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3)),  # one cube apart
        ),
        (
            "dev3-neg-18",  # three cubes in a line, not touching
            res(cube(0.45, 0.20, 0.025), cube(0.45, 0.30, 0.025), cube(0.45, 0.40, 0.025)),
            res(cube(0.45, 0.20, 0.025), cube(0.55, 0.30, 0.025), cube(0.45, 0.40, 0.025)),
        ),
        (
            "dev3-reg-03",  # row 4 right up against the back edge
            res(*_row_y(0.775, 0.25, 4)),
            res(*_row_y(0.60, 0.25, 4)),  # at the back, but not against the edge
        ),
        (
            "dev3-reg-05",  # a 4-long wall hugging the right boundary
            res(*_row_x(0.40, 0.075, 4), *_row_x(0.40, 0.075, 4, z0=C)),
            res(*_row_x(0.40, 0.20, 4), *_row_x(0.40, 0.20, 4, z0=C)),
        ),
        (
            "dev3-dim-20",  # a row across the whole width, left to right
            res(*_row_y(0.45, 0.075, 10)),
            res(*_row_x(0.25, 0.30, 10)),  # ten long, but front to back
        ),
        (
            "dev3-reg-12",  # a row of 3 across the front, 5 cm in from the front edge
            res(*_row_y(0.275, 0.25, 3)),
            res(*_row_y(0.35, 0.25, 3)),
        ),
        (
            "dev3-neg-16",  # a 3-level pyramid without its top cube
            res(*_PYR2),
            res(*_PYR2, cube(0.45, 0.30, 0.125)),  # the whole pyramid
        ),
        (
            "dev3-neg-05",  # a 4x4 patch without the middle four
            res(*ring(0.40, 0.25, 4)),
            res(*grid(0.40, 0.25, 4, 4)),
        ),
        (
            "dev3-seq-18",  # a 3x3 pad at the back, a tower of 4 in front of it
            res(*grid(0.60, 0.25, 3, 3), *column(0.40, 0.30, 4)),
            res(*grid(0.30, 0.25, 3, 3), *column(0.60, 0.30, 4)),
        ),
        (
            "dev3-seq-06",  # a 5 x 2 wall with the middle top cube pulled out
            res(*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 2, z0=C), *_row_y(0.45, 0.35, 2, z0=C)),
            res(*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 4, z0=C)),
        ),
        ("dev3-open-03", res(*grid(0.40, 0.25, 3, 3, layers=2)), res(*grid(0.40, 0.25, 2, 2, 2))),
        ("dev3-open-07", res(*ring(0.40, 0.25, 4)), res(*ring(0.40, 0.25, 3))),  # roomy pen
        ("dev3-open-08", res(*_row_y(0.45, 0.20, 5)), res(*grid(0.40, 0.25, 4, 4))),
        ("dev3-open-15", res(*grid(0.40, 0.25, 2, 3)), res(*_row_y(0.45, 0.20, 6))),  # pile
    ],
)
def test_dev3_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev3(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev4


def _dev4(case_id: str) -> Case:
    return next(c for c in DEV4 if c.id == case_id)


def _slab_without_corners(x0, y0, n):
    return [
        cube(x0 + C * i, y0 + C * j, C / 2)
        for i in range(n)
        for j in range(n)
        if not (i in (0, n - 1) and j in (0, n - 1))
    ]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        ("dev4-rel-01", res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 3, z0=C)), TOWER3),
        (
            "dev4-rel-14",  # a row of 4 with a cube stacked on each end
            res(*grid(0.40, 0.25, 4, 1), cube(0.40, 0.25, 0.075), cube(0.55, 0.25, 0.075)),
            res(*grid(0.40, 0.25, 4, 1), cube(0.45, 0.25, 0.075), cube(0.50, 0.25, 0.075)),
        ),
        (
            "dev4-seq-04",  # a 3x3 grid with one cube on its centre
            res(*grid(0.40, 0.25, 3, 3), cube(0.45, 0.30, 0.075)),
            res(*grid(0.40, 0.25, 3, 3), cube(0.40, 0.25, 0.075)),
        ),
        (
            "dev4-seq-13",
            res(*grid(0.40, 0.25, 2, 1), *grid(0.55, 0.25, 2, 1)),
            res(*grid(0.40, 0.25, 4, 1)),
        ),
        (
            "dev4-neg-15",  # a 4x4 slab without its corners
            res(*_slab_without_corners(0.40, 0.25, 4)),
            res(*grid(0.40, 0.25, 4, 4)),
        ),
        (
            "dev4-reg-11",  # a row of 5 left to right across the back
            res(*grid(0.65, 0.20, 1, 5)),
            res(*grid(0.50, 0.30, 5, 1)),
        ),
        (
            "dev4-reg-13",  # a row of 4 going away from the robot, on the left
            res(*grid(0.40, 0.45, 4, 1)),
            res(*grid(0.40, 0.40, 1, 4)),
        ),
        (
            "dev4-wo-14",  # a U 4 wide: a 4 × 4 ring with two middle cubes of one side gone
            res(
                *[
                    c
                    for c in ring(0.40, 0.25, 4)
                    if c["position"][0] < 0.5 or c["position"][1] in (0.25, 0.40)
                ]
            ),
            res(*grid(0.40, 0.25, 3, 1)),
        ),
    ],
)
def test_dev4_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev4(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev5


def _dev5(case_id: str) -> Case:
    return next(c for c in DEV5 if c.id == case_id)


_WALL5X3 = [cube(0.45, 0.20 + C * j, C / 2 + C * h) for h in range(3) for j in range(5)]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev5-rel-06",  # a 4 x 2 wall with a cube on top of one end
            res(*_row_y(0.45, 0.20, 4), *_row_y(0.45, 0.20, 4, z0=C), cube(0.45, 0.20, 0.125)),
            res(*_row_y(0.45, 0.20, 4), *_row_y(0.45, 0.20, 4, z0=C), cube(0.45, 0.25, 0.125)),
        ),
        (
            "dev5-rel-03",  # a cube inside a 4x4 enclosure
            res(*ring(0.30, 0.20, 6), cube(0.425, 0.325, 0.025)),
            res(*ring(0.30, 0.20, 6), cube(0.70, 0.30, 0.025)),  # outside the ring
        ),
        (
            "dev5-seq-07",  # a 3x3 slab without its corners: a plus
            res(*_PLUS3),
            res(*grid(0.40, 0.25, 3, 3)),
        ),
        (
            "dev5-seq-13",  # a row of 3 with a row of 2 on top
            res(*_row_y(0.45, 0.20, 3), *_row_y(0.45, 0.20, 2, z0=C)),
            res(*_row_y(0.45, 0.20, 3), *_row_y(0.45, 0.20, 3, z0=C)),
        ),
        (
            "dev5-neg-08",  # a row of 5 without its second cube
            res(cube(0.45, 0.20, 0.025), *_row_y(0.45, 0.30, 3)),
            res(*_row_y(0.45, 0.20, 5)),
        ),
        (
            "dev5-neg-10",  # a 5 x 3 wall with a doorway in the middle of the bottom course
            res(
                *[
                    c
                    for c in _WALL5X3
                    if (round(c["position"][1], 3), c["position"][2]) != (0.30, C / 2)
                ]
            ),
            res(*_WALL5X3),
        ),
        (
            "dev5-reg-04",  # a 4-long wall along the right edge
            res(*_row_x(0.40, 0.075, 4), *_row_x(0.40, 0.075, 4, z0=C)),
            res(*_row_y(0.45, 0.075, 4), *_row_y(0.45, 0.075, 4, z0=C)),  # across, not along
        ),
        (
            "dev5-reg-10",  # a 2x2x2 block 0.3 m straight out from the robot
            res(*grid(0.275, 0.275, 2, 2, layers=2)),
            res(*grid(0.475, 0.275, 2, 2, layers=2)),
        ),
        (
            "dev5-dim-13",  # tabletop 20 x 15 cm on 10 cm legs
            res(
                *column(0.40, 0.25, 2),
                *column(0.55, 0.25, 2),
                *column(0.40, 0.35, 2),
                *column(0.55, 0.35, 2),
                *grid(0.40, 0.25, 4, 3, z0=2 * C),
            ),
            res(*grid(0.40, 0.25, 4, 3)),
        ),
        ("dev5-open-15", res(*ring(0.40, 0.25, 4)), res(*ring(0.40, 0.25, 3))),
    ],
)
def test_dev5_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev5(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev6


def _dev6(case_id: str) -> Case:
    return next(c for c in DEV6 if c.id == case_id)


def _slab_with_corner_columns(x0, y0, n, high):
    corners = [(x0 + C * i, y0 + C * j) for i in (0, n - 1) for j in (0, n - 1)]
    return [*grid(x0, y0, n, n), *[c for x, y in corners for c in column(x, y, high, z0=C)]]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev6-rel-07",  # a row of 5 with one more cube on each end
            res(*_row_y(0.45, 0.20, 5), cube(0.45, 0.20, 0.075), cube(0.45, 0.40, 0.075)),
            res(*_row_y(0.45, 0.20, 5), cube(0.45, 0.25, 0.075), cube(0.45, 0.35, 0.075)),
        ),
        (
            "dev6-rel-08",  # two towers, the left one taller
            res(*column(0.45, 0.40, 4), *column(0.45, 0.20, 2)),
            res(*column(0.45, 0.40, 2), *column(0.45, 0.20, 4)),
        ),
        (
            "dev6-rel-12",  # a 3 tower at the front, a 6 tower right behind it (touching)
            res(*column(0.40, 0.30, 3), *column(0.45, 0.30, 6)),
            res(*column(0.40, 0.30, 6), *column(0.45, 0.30, 3)),
        ),
        (
            "dev6-rel-13",  # a 4x4 slab with a 3-high tower on each corner
            res(*_slab_with_corner_columns(0.40, 0.25, 4, 3)),
            res(
                *grid(0.40, 0.25, 4, 4),
                *[c for x in (0.45, 0.50) for y in (0.30, 0.35) for c in column(x, y, 3, z0=C)],
            ),
        ),
        (
            "dev6-rel-04",  # a 2-cube tower dead centre on a 3x3 slab
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 2, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 2, z0=C)),
        ),
        (
            "dev6-seq-08",  # a 4x4 ring with a cube on each corner on top
            res(
                *ring(0.40, 0.25, 4),
                *[cube(x, y, 0.075) for x in (0.40, 0.55) for y in (0.25, 0.40)],
            ),
            res(
                *ring(0.40, 0.25, 4),
                *[cube(x, y, 0.075) for x in (0.40, 0.55) for y in (0.30, 0.35)],
            ),
        ),
        (
            "dev6-neg-10",  # a 6 x 2 wall without the two top end cubes
            res(*_row_y(0.45, 0.20, 6), *_row_y(0.45, 0.25, 4, z0=C)),
            res(*_row_y(0.45, 0.20, 6), *_row_y(0.45, 0.20, 6, z0=C)),
        ),
        (
            "dev6-dim-09",  # 15 cm wide (y) and 25 cm deep (x)
            res(*grid(0.40, 0.25, 5, 3)),
            res(*grid(0.40, 0.25, 3, 5)),
        ),
        (
            "dev6-reg-06",  # a 2-level pyramid 150 mm left of the centre
            res(*grid(0.45, 0.425, 2, 2), cube(0.475, 0.45, 0.075)),
            res(*grid(0.45, 0.275, 2, 2), cube(0.475, 0.30, 0.075)),
        ),
        (
            "dev6-open-10",  # a podium: three columns of different heights
            res(*column(0.45, 0.25, 2), *column(0.45, 0.30, 3), *column(0.45, 0.35, 1)),
            res(*_row_y(0.45, 0.25, 3), *_row_y(0.45, 0.25, 3, z0=C)),
        ),
    ],
)
def test_dev6_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev6(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev7


def _dev7(case_id: str) -> Case:
    return next(c for c in DEV7 if c.id == case_id)


_RING4 = ring(0.40, 0.25, 4)


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev7-rel-01",  # a 5 x 2 wall with a 4-tall tower at both ends
            res(
                *column(0.45, 0.20, 4),
                *[c for y in (0.25, 0.30, 0.35) for c in column(0.45, y, 2)],
                *column(0.45, 0.40, 4),
            ),
            res(*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)),
        ),
        (
            "dev7-rel-02",  # left tower 3, right tower twice as tall
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 6)),
            res(*column(0.45, 0.40, 6), *column(0.45, 0.20, 3)),
        ),
        (
            "dev7-rel-03",  # a cube on every corner of a 4x4 slab
            res(*_slab_with_corner_columns(0.40, 0.25, 4, 1)),
            res(*grid(0.40, 0.25, 4, 4), *[cube(0.45, y, 0.075) for y in (0.25, 0.30, 0.35, 0.40)]),
        ),
        (
            "dev7-rel-08",  # two left-to-right rows of 5, a one-cube gap between them
            res(*_row_y(0.40, 0.20, 5), *_row_y(0.50, 0.20, 5)),
            res(*_row_y(0.40, 0.20, 5), *_row_y(0.60, 0.20, 5)),
        ),
        (
            "dev7-rel-10",  # a 3x3 pad with a 3 x 2 wall on its back edge
            res(
                *grid(0.40, 0.25, 3, 3), *_row_y(0.50, 0.25, 3, z0=C), *_row_y(0.50, 0.25, 3, 2 * C)
            ),
            res(
                *grid(0.40, 0.25, 3, 3), *_row_y(0.40, 0.25, 3, z0=C), *_row_y(0.40, 0.25, 3, 2 * C)
            ),
        ),
        (
            "dev7-seq-08",  # an L with 3-cube arms, its corner at the back left
            res(*_row_x(0.40, 0.40, 3), cube(0.50, 0.35, 0.025), cube(0.50, 0.30, 0.025)),
            res(*_row_x(0.40, 0.30, 3), cube(0.40, 0.35, 0.025), cube(0.40, 0.40, 0.025)),
        ),
        (
            "dev7-seq-13",  # two 2x2 pads, the second one cube to the right, not touching
            res(*grid(0.45, 0.35, 2, 2), *grid(0.45, 0.20, 2, 2)),
            res(*grid(0.45, 0.35, 2, 2), *grid(0.45, 0.10, 2, 2)),  # two cubes apart
        ),
        (
            "dev7-neg-02",  # a 4x4 ring left open on the side facing the robot
            res(
                *[
                    c
                    for c in _RING4
                    if not (c["position"][0] == 0.40 and 0.27 < c["position"][1] < 0.38)
                ]
            ),
            res(
                *[
                    c
                    for c in _RING4
                    if not (c["position"][0] == 0.55 and 0.27 < c["position"][1] < 0.38)
                ]
            ),
        ),
        (
            "dev7-wo-05",  # a cube inside a 4 by 4 ring, free in its 2x2 floor
            res(*_RING4, cube(0.475, 0.325, 0.025)),
            res(*_RING4, cube(0.70, 0.30, 0.025)),
        ),
        (
            "dev7-open-12",  # a few towers of different heights
            res(*column(0.40, 0.20, 2), *column(0.40, 0.30, 3), *column(0.40, 0.40, 4)),
            res(*column(0.40, 0.20, 2), *column(0.40, 0.30, 2), *column(0.40, 0.40, 4)),
        ),
    ],
)
def test_dev7_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev7(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev8


def _dev8(case_id: str) -> Case:
    return next(c for c in DEV8 if c.id == case_id)


def _bridge(x, y, n):
    """Two n-cube pillars at y ± 0.05 joined by a beam turned along y."""
    return [*column(x, y - 0.05, n), *column(x, y + 0.05, n), beam(x, y, n * C + C / 2, YAW90)]


def _grid_corners(x0, y0):
    """A 3 (x) by 5 (y) grid with a 2-cube tower on each corner cell."""
    corners = [(x0 + C * i, y0 + C * j) for i in (0, 2) for j in (0, 4)]
    return [*grid(x0, y0, 3, 5), *[c for x, y in corners for c in column(x, y, 2, z0=C)]]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev8-rel-02",  # a 4-high tower left of a 3x3 pad, one cube gap
            res(*grid(0.40, 0.20, 3, 3), *column(0.45, 0.40, 4)),
            res(*grid(0.40, 0.20, 3, 3), *column(0.45, 0.10, 4)),
        ),
        (
            "dev8-rel-03",  # two bridges, the right one's pillars one taller (left: 2)
            res(*_bridge(0.45, 0.40, 2), *_bridge(0.45, 0.20, 3)),
            res(*_bridge(0.45, 0.40, 3), *_bridge(0.45, 0.20, 2)),
        ),
        (
            "dev8-rel-04",  # a 6x6 ring with a 2x2 block, 2 high, in the middle
            res(*ring(0.40, 0.175, 6), *grid(0.50, 0.275, 2, 2, layers=2)),
            res(*ring(0.40, 0.175, 6), *grid(0.50, 0.275, 2, 2, layers=1)),
        ),
        (
            "dev8-rel-07",  # a 3x3 slab with one cube on each corner
            res(*_slab_with_corner_columns(0.40, 0.25, 3, 1)),
            res(
                *grid(0.40, 0.25, 3, 3),
                *[cube(x, y, 0.075) for x, y in ((0.40, 0.30), (0.50, 0.30), (0.45, 0.25))],
                cube(0.45, 0.35, 0.075),
            ),
        ),
        (
            "dev8-rel-12",  # a left-right row of 5 with a 3-high tower on its middle cube
            res(*_row_y(0.45, 0.20, 5), *column(0.45, 0.30, 3, z0=C)),
            res(*_row_y(0.45, 0.20, 5), *column(0.45, 0.20, 3, z0=C)),
        ),
        (
            "dev8-seq-09",  # a tower of 4, then one twice as tall on its right
            res(*column(0.45, 0.40, 4), *column(0.45, 0.20, 8)),
            res(*column(0.45, 0.40, 8), *column(0.45, 0.20, 4)),
        ),
        (
            "dev8-seq-10",  # a 3x5 grid at the front with a 2-high tower on each corner
            res(*_grid_corners(0.25, 0.20)),
            res(*_grid_corners(0.60, 0.20)),
        ),
        (
            "dev8-dim-05",  # 15 cm wide (y), 20 cm deep (x), 10 cm high
            res(*grid(0.40, 0.25, 4, 3, layers=2)),
            res(*grid(0.40, 0.25, 3, 4, layers=2)),
        ),
        (
            "dev8-dim-10",  # two 3-high towers 0.1 m apart (clear gap or centre to centre)
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.45, 3)),
        ),
        (
            "dev8-dim-11",  # a bridge on 2-high pillars with a 50 mm gap between them
            res(*_bridge(0.45, 0.30, 2)),
            res(*column(0.45, 0.235, 2), *column(0.45, 0.365, 2), beam(0.45, 0.30, 0.125, YAW90)),
        ),
        (
            "dev8-neg-11",  # a 3x3 block 2 high without the middle cubes
            res(*ring(0.40, 0.25, 3, high=2)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev8-num-09",  # three towers of different heights adding up to nine
            res(*column(0.40, 0.20, 2), *column(0.40, 0.30, 3), *column(0.40, 0.40, 4)),
            res(*column(0.40, 0.20, 3), *column(0.40, 0.30, 3), *column(0.40, 0.40, 3)),
        ),
        (
            "dev8-open-11",  # a few separate stacks of the same height
            res(*column(0.40, 0.20, 3), *column(0.40, 0.30, 3), *column(0.40, 0.40, 3)),
            res(*column(0.40, 0.20, 3), *column(0.40, 0.30, 3), *column(0.40, 0.40, 4)),
        ),
        (
            "dev8-typo-09",  # an L with arms of 4 and 3
            res(*_row_x(0.40, 0.30, 4), cube(0.40, 0.35, 0.025), cube(0.40, 0.40, 0.025)),
            res(*_row_x(0.40, 0.30, 4), *[cube(0.40, 0.30 + C * j, 0.025) for j in (1, 2, 3)]),
        ),
        (
            "dev8-wo-05",  # a tower of 2 standing on a bridge
            res(*_bridge(0.45, 0.30, 2), *column(0.45, 0.30, 2, z0=3 * C)),
            res(*_bridge(0.45, 0.30, 2), *column(0.45, 0.30, 3, z0=3 * C)),
        ),
        (
            "dev8-typo-10",  # a ring round a 2-tower: free inside it, or a 3x3 fence laid tight
            res(*ring(0.40, 0.25, 3), *column(0.45, 0.30, 2)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev8-rel-10",  # a one-high fence around a 4-tower
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 4)),
            res(*ring(0.35, 0.20, 5, high=2), *column(0.45, 0.30, 4)),
        ),
        (
            "dev8-reg-11",  # a cube in each corner of the table and one in the middle
            res(
                *[cube(x, y, 0.025) for x in (0.25, 0.75) for y in (0.10, 0.50)],
                cube(0.45, 0.30, 0.025),
            ),
            res(
                *[cube(x, y, 0.025) for x in (0.25, 0.75) for y in (0.10, 0.50)],
                cube(0.65, 0.30, 0.025),
            ),
        ),
    ],
)
def test_dev8_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev8(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev9


def _dev9(case_id: str) -> Case:
    return next(c for c in DEV9 if c.id == case_id)


def _stairs_x(x0, y, hs):
    """Columns of the given heights in a line along x from x0 (front to back)."""
    return [c for i, h in enumerate(hs) for c in column(x0 + C * i, y, h)]


def _stairs_y(x, y0, hs):
    """Columns of the given heights in a line along y from y0 (right to left)."""
    return [c for j, h in enumerate(hs) for c in column(x, y0 + C * j, h)]


def _pyr(x0, y0, levels):
    """A pyramid of 1–3 levels (3x3, 2x2, one cube), its base corner cube at (x0, y0)."""
    out = grid(x0, y0, 3, 3)
    if levels >= 2:
        out += grid(x0 + C / 2, y0 + C / 2, 2, 2, z0=C)
    if levels >= 3:
        out.append(cube(x0 + C, y0 + C, 2 * C + C / 2))
    return out


_WIDE_BRIDGE4 = [
    *column(0.45, 0.225, 4),
    *column(0.45, 0.375, 4),
    beam(0.45, 0.30, 4 * C + C / 2, YAW90),
]
_SLAB34 = grid(0.40, 0.25, 3, 4)


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev9-rel-01",  # a 4x4 plinth with a centred column of three on it
            res(*grid(0.375, 0.225, 4, 4), *column(0.45, 0.30, 3, z0=C)),
            res(*grid(0.375, 0.225, 4, 4), *column(0.375, 0.225, 3, z0=C)),
        ),
        (
            "dev9-rel-03",  # a 4-tower right of a 5x2 wall, two cubes of space
            res(*grid(0.35, 0.35, 5, 1, layers=2), *column(0.45, 0.20, 4)),
            res(*grid(0.35, 0.35, 5, 1, layers=2), *column(0.45, 0.50, 4)),
        ),
        (
            "dev9-rel-04",  # a fence around one cube
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 1)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 1)),
        ),
        (
            "dev9-rel-04",  # … a fence laid tight round it is a 3x3 patch
            res(*grid(0.40, 0.25, 3, 3)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev9-wo-06",  # a cube in a 4x4 ring, touching the ring's walls (one structure)
            res(*ring(0.40, 0.25, 4), *column(0.45, 0.30, 1)),
            res(*ring(0.40, 0.25, 4), *column(0.45, 0.30, 2)),
        ),
        (
            "dev9-wo-06",  # … or free in the middle of the inside
            res(*ring(0.40, 0.25, 4), *column(0.475, 0.325, 1)),
            res(*ring(0.40, 0.25, 5), *column(0.50, 0.35, 1)),
        ),
        (
            "dev9-rel-08",  # … the pallet pushed against the ring
            res(*ring(0.325, 0.175, 6), *grid(0.375, 0.225, 2, 2, layers=2)),
            res(*ring(0.325, 0.175, 6), *grid(0.375, 0.225, 2, 2, layers=3)),
        ),
        (
            "dev9-rel-07",  # a bridge on 3-high pillars with a 2-tower standing on the beam
            res(*_bridge(0.45, 0.30, 3), *column(0.45, 0.30, 2, z0=4 * C)),
            res(*_bridge(0.45, 0.30, 3), *column(0.45, 0.30, 3, z0=4 * C)),
        ),
        (
            "dev9-rel-08",  # a 2x2x2 pallet inside a one-high 6x6 ring
            res(*ring(0.325, 0.175, 6), *grid(0.425, 0.275, 2, 2, layers=2)),
            res(*ring(0.325, 0.175, 6, high=2), *grid(0.425, 0.275, 2, 2, layers=2)),
        ),
        (
            "dev9-rel-09",  # a 3-step staircase with a 5-tower against its tall end
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 5))),
            res(*_stairs_y(0.45, 0.20, (5, 1, 2, 3))),
        ),
        (
            "dev9-rel-10",  # a row of three between two 2x2 pads, a gap each side
            res(
                *grid(0.425, 0.10, 2, 2),
                *_row_y(0.45, 0.25, 3),
                *grid(0.425, 0.45, 2, 2),
            ),
            res(
                *grid(0.425, 0.10, 2, 2),
                *grid(0.425, 0.25, 2, 2),
                *_row_y(0.45, 0.40, 3),
            ),
        ),
        (
            "dev9-rel-12",  # two parallel 4x2 walls facing each other 3 cubes apart
            res(*grid(0.35, 0.20, 4, 1, layers=2), *grid(0.35, 0.40, 4, 1, layers=2)),
            res(*grid(0.25, 0.30, 4, 1, layers=2), *grid(0.60, 0.30, 4, 1, layers=2)),
        ),
        (
            "dev9-rel-13",  # a 4x4 podium with a column of three on each corner
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 3)),
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 2)),
        ),
        (
            "dev9-rel-14",  # a row of 6 with a tower of 3 at both ends
            res(
                *_row_y(0.45, 0.175, 6),
                *column(0.45, 0.175, 3, z0=C),
                *column(0.45, 0.425, 3, z0=C),
            ),
            res(
                *_row_y(0.45, 0.175, 6),
                *column(0.45, 0.175, 3, z0=C),
                *column(0.45, 0.225, 3, z0=C),
            ),
        ),
        (
            "dev9-rel-16",  # a 6-tower and next to it a wall half as high
            res(*column(0.45, 0.20, 6), *grid(0.45, 0.30, 1, 4, layers=3)),
            res(*column(0.45, 0.20, 6), *grid(0.45, 0.30, 1, 4, layers=2)),
        ),
        (
            "dev9-rel-16",  # … or the wall built against the tower
            res(*column(0.45, 0.25, 6), *grid(0.45, 0.30, 1, 4, layers=3)),
            res(*column(0.45, 0.25, 5), *grid(0.45, 0.30, 1, 4, layers=3)),
        ),
        (
            "dev9-seq-03",  # a 3-tower, then one twice as tall next to it
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 6)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 5)),
        ),
        (
            "dev9-seq-04",  # a 3x4 slab with one corner cube taken away
            res(*_SLAB34[1:]),
            res(*_SLAB34[:5], *_SLAB34[6:]),
        ),
        (
            "dev9-seq-08",  # two 4-towers two cubes apart with a beam across
            res(*_WIDE_BRIDGE4),
            res(*column(0.45, 0.225, 3), *column(0.45, 0.375, 3), beam(0.45, 0.30, 0.175, YAW90)),
        ),
        (
            "dev9-seq-12",  # a 4x4 podium with a 2x2 tier in its centre
            res(*grid(0.375, 0.225, 4, 4), *grid(0.425, 0.275, 2, 2, z0=C)),
            res(*grid(0.375, 0.225, 4, 4), *grid(0.375, 0.225, 2, 2, z0=C)),
        ),
        (
            "dev9-dim-06",  # width (y) 10 cm, depth (x) 15 cm, one layer
            res(*grid(0.40, 0.25, 3, 2)),
            res(*grid(0.40, 0.25, 2, 3)),
        ),
        (
            "dev9-dim-07",  # 0.2 m pillars with 10 cm clear between them
            res(*_WIDE_BRIDGE4),
            res(*_bridge(0.45, 0.30, 4)),
        ),
        (
            "dev9-neg-09",  # a 4-step staircase not climbing toward the robot
            res(*_stairs_x(0.40, 0.30, (1, 2, 3, 4))),
            res(*_stairs_x(0.40, 0.30, (4, 3, 2, 1))),
        ),
        (
            "dev9-neg-10",  # two 3-stacks, neither in the middle
            res(*column(0.30, 0.15, 3), *column(0.70, 0.45, 3)),
            res(*column(0.30, 0.15, 3), *column(0.45, 0.30, 3)),
        ),
        (
            "dev9-reg-07",  # a 2-tower at (0.30, 0.45) and a 4-tower at (0.65, 0.15)
            res(*column(0.30, 0.45, 2), *column(0.65, 0.15, 4)),
            res(*column(0.30, 0.45, 4), *column(0.65, 0.15, 2)),
        ),
        (
            "dev9-reg-10",  # five 2-columns along the left edge, front to back
            res(*[c for i in range(5) for c in column(0.25 + 0.1 * i, 0.45, 2)]),
            res(*[c for j in range(5) for c in column(0.45, 0.10 + 0.1 * j, 2)]),
        ),
        (
            "dev9-reg-10",  # … or touching into one wall
            res(*grid(0.30, 0.45, 5, 1, layers=2)),
            res(*grid(0.30, 0.20, 5, 1, layers=2)),
        ),
        (
            "dev9-reg-11",  # a 2x2x2 block 10 cm left of the centre
            res(*grid(0.425, 0.375, 2, 2, layers=2)),
            res(*grid(0.425, 0.175, 2, 2, layers=2)),
        ),
        (
            "dev9-typo-12",  # a 4x4 slab with a cube in each corner
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 1)),
            res(*grid(0.35, 0.20, 4, 4), *grid(0.40, 0.25, 2, 2, z0=C)),
        ),
        (
            "dev9-wo-10",  # a 2-level pyramid on the left, a 3-level one on the right
            res(*_pyr(0.40, 0.40, 2), *_pyr(0.40, 0.10, 3)),
            res(*_pyr(0.40, 0.40, 3), *_pyr(0.40, 0.10, 2)),
        ),
        (
            "dev9-open-08",  # a few short stacks along the back
            res(*[c for y in (0.15, 0.30, 0.45) for c in column(0.65, y, 3)]),
            res(*[c for y in (0.15, 0.30, 0.45) for c in column(0.30, y, 3)]),
        ),
        (
            "dev9-bad-11",  # a floating slab: refuse, or build it on the table and say so
            {"status": "error", "layout": None},
            res(*grid(0.425, 0.275, 2, 2, z0=0.10), notes=["floating as asked"]),
        ),
    ],
)
def test_dev9_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev9(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev10


def _dev10(case_id: str) -> Case:
    return next(c for c in DEV10 if c.id == case_id)


_SLAB44 = grid(0.35, 0.20, 4, 4)
_CORNERS44 = (0, 3, 12, 15)  # grid index i * 4 + j of the four corner cells


def _raised_border(x0, y0):
    """A 3x3 floor with a second layer on every cell but the middle one."""
    top = [
        cube(x0 + C * i, y0 + C * j, C + C / 2)
        for i in range(3)
        for j in range(3)
        if (i, j) != (1, 1)
    ]
    return [*grid(x0, y0, 3, 3), *top]


_MAP_CORNERS = [
    *grid(0.70, 0.45, 2, 2),
    *grid(0.70, 0.10, 2, 2),
    *grid(0.25, 0.45, 2, 2),
    *grid(0.25, 0.10, 2, 2),
]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev10-rel-01",  # a 3x3 plinth with a centred 4-column on it
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 4, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 4, z0=C)),
        ),
        (
            "dev10-rel-02",  # a 5-tower on the +y side of a 2x2x2 block, 50 mm gap
            res(*grid(0.425, 0.225, 2, 2, layers=2), *column(0.45, 0.375, 5)),
            res(*grid(0.425, 0.225, 2, 2, layers=2), *column(0.45, 0.125, 5)),
        ),
        (
            "dev10-rel-03",  # a 4x4 floor with a 2-high pillar on each corner
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 2)),
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 3)),
        ),
        (
            "dev10-rel-04",  # a fence around a 3-tower
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 3)),
        ),
        (
            "dev10-rel-04",  # … or laid tight round it
            res(*ring(0.40, 0.25, 3), *column(0.45, 0.30, 3)),
            res(*ring(0.40, 0.25, 3, high=4), *column(0.45, 0.30, 3)),
        ),
        (
            "dev10-rel-05",  # two 4-towers with a beam across
            res(*_bridge(0.45, 0.30, 4)),
            res(*_bridge(0.45, 0.30, 3)),
        ),
        (
            "dev10-rel-06",  # a row of five between two 3-stacks
            res(*column(0.45, 0.10, 3), *_row_y(0.45, 0.20, 5), *column(0.45, 0.50, 3)),
            res(*column(0.45, 0.10, 3), *_row_y(0.75, 0.20, 5), *column(0.45, 0.50, 3)),
        ),
        (
            "dev10-rel-08",  # a 2x2 slab in front (-x) of a 6x2 wall along y, 1 cube clear
            res(*grid(0.50, 0.15, 1, 6, layers=2), *grid(0.35, 0.25, 2, 2)),
            res(*grid(0.50, 0.15, 1, 6, layers=2), *grid(0.60, 0.25, 2, 2)),
        ),
        (
            "dev10-rel-09",  # a 2x2 tile inside a 6x6 border two high
            res(*ring(0.325, 0.175, 6, high=2), *grid(0.425, 0.275, 2, 2)),
            res(*ring(0.325, 0.175, 6), *grid(0.425, 0.275, 2, 2)),
        ),
        (
            "dev10-rel-10",  # a 3-level pyramid behind, a 6-tower in front, ~2 cubes apart
            res(*_pyr(0.55, 0.25, 3), *column(0.40, 0.30, 6)),
            res(*_pyr(0.55, 0.25, 3), *column(0.75, 0.30, 6)),
        ),
        (
            "dev10-rel-11",  # two parallel 4x3 walls with a 15 cm corridor
            res(*grid(0.35, 0.20, 4, 1, layers=3), *grid(0.35, 0.40, 4, 1, layers=3)),
            res(*grid(0.35, 0.20, 4, 1, layers=3), *grid(0.35, 0.35, 4, 1, layers=3)),
        ),
        (
            "dev10-rel-12",  # two 3x2x2 slabs side by side, one cube apart
            res(*grid(0.40, 0.15, 3, 2, layers=2), *grid(0.40, 0.30, 3, 2, layers=2)),
            res(*grid(0.40, 0.15, 3, 2, layers=2), *grid(0.60, 0.15, 3, 2, layers=2)),
        ),
        (
            "dev10-seq-03",  # a 4x4 platform without its four corners
            res(*[c for i, c in enumerate(_SLAB44) if i not in _CORNERS44]),
            res(*[c for i, c in enumerate(_SLAB44) if i not in _CORNERS44[:3]]),
        ),
        (
            "dev10-seq-05",  # a 6x2 base with a 3-column at each end
            res(
                *grid(0.30, 0.25, 6, 2),
                *column(0.30, 0.25, 3, z0=C),
                *column(0.55, 0.30, 3, z0=C),
            ),
            res(
                *grid(0.30, 0.25, 6, 2),
                *column(0.30, 0.25, 3, z0=C),
                *column(0.35, 0.25, 3, z0=C),
            ),
        ),
        (
            "dev10-seq-08",  # a 3-bridge centred at (0.40, 0.30)
            res(*_bridge(0.40, 0.30, 3)),
            res(*_bridge(0.60, 0.30, 3)),
        ),
        (
            "dev10-seq-09",  # a 3x3 floor with every tile but the middle raised
            res(*_raised_border(0.40, 0.25)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev10-seq-10",  # a 3-tower and next to it one a cube taller
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 4)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 5)),
        ),
        (
            "dev10-seq-11",  # a 4x4 plinth with a 2x2x2 block at its centre
            res(*grid(0.375, 0.225, 4, 4), *grid(0.425, 0.275, 2, 2, layers=2, z0=C)),
            res(*grid(0.375, 0.225, 4, 4), *grid(0.375, 0.225, 2, 2, layers=2, z0=C)),
        ),
        (
            "dev10-num-12",  # a 2-column and one four times as tall
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 8)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 4)),
        ),
        (
            "dev10-dim-01",  # 150 (x) by 100 (y) by 100 (z) mm
            res(*grid(0.40, 0.25, 3, 2, layers=2)),
            res(*grid(0.40, 0.25, 2, 3, layers=2)),
        ),
        (
            "dev10-dim-04",  # 20 cm wide (y), 30 cm deep (x)
            res(*grid(0.30, 0.20, 6, 4)),
            res(*grid(0.30, 0.20, 4, 6)),
        ),
        (
            "dev10-dim-09",  # an arch with a 10 cm high, 5 cm wide opening
            res(*_bridge(0.45, 0.30, 2)),
            res(*_bridge(0.45, 0.30, 3)),
        ),
        (
            "dev10-neg-07",  # two 4-stacks, nothing within 10 cm of the front edge
            res(*column(0.35, 0.20, 4), *column(0.35, 0.40, 4)),
            res(*column(0.25, 0.20, 4), *column(0.35, 0.40, 4)),
        ),
        (
            "dev10-reg-02",  # a 3x3 slab at least 10 cm from the front edge
            res(*grid(0.35, 0.25, 3, 3)),
            res(*grid(0.225, 0.25, 3, 3)),
        ),
        (
            "dev10-reg-03",  # a 2x2 tile in each corner of the map
            res(*_MAP_CORNERS),
            res(*_MAP_CORNERS[:8], *grid(0.45, 0.45, 2, 2), *_MAP_CORNERS[12:]),
        ),
        (
            "dev10-reg-09",  # a 4-tower at both ends of the table
            res(*column(0.45, 0.10, 4), *column(0.45, 0.50, 4)),
            res(*column(0.45, 0.40, 4), *column(0.45, 0.50, 4)),
        ),
        (
            "dev10-reg-11",  # a 6x2 screen wall along the back, a 2x2 plinth in front of it
            res(*grid(0.65, 0.15, 1, 6, layers=2), *grid(0.45, 0.25, 2, 2)),
            res(*grid(0.30, 0.15, 1, 6, layers=2), *grid(0.45, 0.25, 2, 2)),
        ),
        (
            "dev10-wo-05",  # a 3-tower on the right, a 5-tower on the left
            res(*column(0.45, 0.15, 3), *column(0.45, 0.45, 5)),
            res(*column(0.45, 0.15, 5), *column(0.45, 0.45, 3)),
        ),
        (
            "dev10-wo-10",  # a 2-level pyramid one tile behind a 3-pillar
            res(*column(0.40, 0.30, 3), *_pyr(0.50, 0.25, 2)),
            res(*column(0.70, 0.30, 3), *_pyr(0.50, 0.25, 2)),
        ),
        (
            "dev10-open-01",  # a low plinth with a slender column from its centre
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 3, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 3, z0=C)),
        ),
        (
            "dev10-open-08",  # three columns of descending height
            res(*column(0.45, 0.15, 4), *column(0.45, 0.30, 3), *column(0.45, 0.45, 2)),
            res(*column(0.45, 0.15, 3), *column(0.45, 0.30, 3), *column(0.45, 0.45, 3)),
        ),
        (
            "dev10-wo-09",  # two 4-rows side by side, 2 cubes apart
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.55, 0.20, 4)),
            res(*_row_y(0.40, 0.075, 4), *_row_y(0.40, 0.375, 4)),
        ),
        (
            "dev10-wo-11",  # a flat T, bar 5, stem 3
            res(*_row_y(0.55, 0.20, 5), *_row_x(0.40, 0.30, 3)),
            res(*_row_y(0.55, 0.20, 5), *_row_x(0.45, 0.30, 2), cube(0.55, 0.30, 0.075)),
        ),
        (
            "dev10-neg-06",  # a 4x4 floor with the inner 2x2 left empty
            res(*ring(0.40, 0.25, 4)),
            res(*grid(0.40, 0.25, 4, 4)),
        ),
        (
            "dev10-dim-07",  # a staircase under 20 cm tall: 3 steps
            res(*_stairs_y(0.45, 0.20, (1, 2, 3))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
        ),
        (
            "dev10-open-07",  # something low: nothing above 10 cm
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
            res(*grid(0.40, 0.25, 3, 3, layers=3)),
        ),
        (
            "dev10-bad-02",  # a 12-cube tower: refuse, or cap it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev10-bad-12",  # a 20x20 floor: refuse, or build a smaller one and say so
            res(*grid(0.40, 0.25, 3, 3), notes=["20x20 does not fit; built 3x3"]),
            res(*grid(0.40, 0.25, 3, 3)),
        ),
    ],
)
def test_dev10_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev10(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev11


def _dev11(case_id: str) -> Case:
    return next(c for c in DEV11 if c.id == case_id)


def _l_shape(x0, y0, arm):
    """A flat L: `arm` cubes along y from (x0, y0) and `arm` along x, sharing the corner."""
    return [*_row_y(x0, y0, arm), *_row_x(x0 + C, y0, arm - 1)]


_TABLE_CORNERS = [(0.25, 0.10), (0.25, 0.50), (0.75, 0.10), (0.75, 0.50)]


def _table(high):
    """Four `high`-cube legs under two beams along y and two beams across them."""
    legs = [c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, high)]
    z = high * C + C / 2
    return [
        *legs,
        beam(0.40, 0.30, z, YAW90),
        beam(0.50, 0.30, z, YAW90),
        beam(0.45, 0.25, z + C),
        beam(0.45, 0.35, z + C),
    ]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev11-rel-01",  # a 4-tower on a 3x3 slab
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 4, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 3, z0=C)),
        ),
        (
            "dev11-rel-02",  # a 2x2x2 block and a 5-tower next to it
            res(*grid(0.425, 0.225, 2, 2, layers=2), *column(0.45, 0.40, 5)),
            res(*grid(0.425, 0.225, 2, 2, layers=2), *column(0.45, 0.40, 4)),
        ),
        (
            "dev11-rel-02",  # … or the tower built against the block
            res(*grid(0.425, 0.275, 2, 2, layers=2), *column(0.45, 0.375, 5)),
            res(*grid(0.425, 0.275, 2, 2, layers=2), *column(0.45, 0.375, 4)),
        ),
        (
            "dev11-rel-03",  # a 3-tower on the left (+y), a 6-tower on the right
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 6)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 6)),
        ),
        (
            "dev11-rel-04",  # a 2-tower inside a 5x5 ring
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 2)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 2)),
        ),
        (
            "dev11-rel-09",  # a 4x4 slab with a cube on each corner
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 1)),
            res(*_slab_with_corner_columns(0.35, 0.20, 4, 2)),
        ),
        (
            "dev11-rel-11",  # a 3-tower and next to it one twice as tall
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 6)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 5)),
        ),
        (
            "dev11-rel-15",  # a 6x3 wall with a 5-tower at each end (as its end columns)
            res(*_stairs_y(0.45, 0.15, (5, 3, 3, 3, 3, 5))),
            res(*_stairs_y(0.45, 0.15, (5, 3, 3, 3, 3, 3))),
        ),
        (
            "dev11-rel-16",  # a 2-level pyramid right (-y) of a 2x4 slab, 2 cubes apart
            res(*grid(0.425, 0.375, 2, 4), *_pyr(0.40, 0.125, 2)),
            res(*grid(0.425, 0.375, 2, 4), *_pyr(0.40, 0.175, 2)),
        ),
        (
            "dev11-rel-17",  # towers of 2, 6 and 4, the tallest in the middle
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 6), *column(0.45, 0.45, 4)),
            res(*column(0.45, 0.15, 6), *column(0.45, 0.30, 2), *column(0.45, 0.45, 4)),
        ),
        (
            "dev11-rel-18",  # a table: four 2-high legs under a beam top
            res(*_table(2)),
            res(*_table(3)),
        ),
        (
            "dev11-rel-20",  # a 2-level pyramid in the middle of a 6x6 fence
            res(*ring(0.325, 0.175, 6), *_pyr(0.40, 0.25, 2)),
            res(*ring(0.325, 0.175, 6), *_pyr(0.65, 0.25, 2)),
        ),
        (
            "dev11-rel-21",  # corrected: the 3-stack to the right (-y) of the 5-stack
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 5)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 5)),
        ),
        (
            "dev11-seq-01",  # a 3x3 slab with a centred 3-tower
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 3, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 3, z0=C)),
        ),
        (
            "dev11-seq-05",  # a 4x4 floor without its middle four
            res(*ring(0.35, 0.20, 4)),
            res(*grid(0.35, 0.20, 4, 4)),
        ),
        (
            "dev11-seq-06",  # a 4x2 wall and a 3-tower on its right (-y)
            res(*grid(0.45, 0.30, 1, 4, layers=2), *column(0.45, 0.20, 3)),
            res(*grid(0.45, 0.20, 1, 4, layers=2), *column(0.45, 0.45, 3)),
        ),
        (
            "dev11-seq-06",  # … or the tower against the wall's right end
            res(*_stairs_y(0.45, 0.20, (3, 2, 2, 2, 2))),
            res(*_stairs_y(0.45, 0.20, (2, 2, 2, 2, 3))),
        ),
        (
            "dev11-seq-08",  # two 4-towers two cubes apart with a beam across
            res(*_WIDE_BRIDGE4),
            res(*column(0.45, 0.225, 3), *column(0.45, 0.375, 3), beam(0.45, 0.30, 0.175, YAW90)),
        ),
        (
            "dev11-seq-13",  # a 5-step staircase without its highest step
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4))),
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4, 5))),
        ),
        (
            "dev11-seq-16",  # a cube at the front, a 4-tower behind it
            res(*column(0.30, 0.30, 1), *column(0.45, 0.30, 4)),
            res(*column(0.30, 0.30, 4), *column(0.45, 0.30, 1)),
        ),
        (
            "dev11-seq-16",  # … or the tower set against the back of the cube
            res(*_stairs_x(0.35, 0.30, (1, 4))),
            res(*_stairs_x(0.35, 0.30, (4, 1))),
        ),
        (
            "dev11-seq-17",  # a 3-tower, then one twice as big on its left (+y)
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 6)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 6)),
        ),
        (
            "dev11-seq-18",  # five 2-towers in a line without the middle one
            res(*[c for y in (0.10, 0.20, 0.40, 0.50) for c in column(0.45, y, 2)]),
            res(*[c for y in (0.10, 0.20, 0.30, 0.40, 0.50) for c in column(0.45, y, 2)]),
        ),
        (
            "dev11-seq-18",  # … or, built touching, two 2x2 walls left
            res(*grid(0.45, 0.20, 1, 2, layers=2), *grid(0.45, 0.35, 1, 2, layers=2)),
            res(*_stairs_y(0.45, 0.20, (2, 2, 2, 2, 2))),
        ),
        (
            "dev11-num-05",  # two rows of 4, apart
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.55, 0.20, 4)),
            res(*_row_y(0.40, 0.20, 4), *_row_y(0.55, 0.20, 3)),
        ),
        (
            "dev11-num-05",  # … or side by side as a 2x4 patch
            res(*grid(0.40, 0.20, 2, 4)),
            res(*grid(0.40, 0.20, 2, 4, layers=2)),
        ),
        (
            "dev11-num-08",  # stacks of 1, 2, 3 and 4 set in order: a staircase
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 4, 3))),
        ),
        (
            "dev11-num-18",  # a 3-step staircase and a tower as tall as its top step
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 3))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
        ),
        (
            "dev11-dim-06",  # 10 x 10 x 15 cm
            res(*grid(0.425, 0.275, 2, 2, layers=3)),
            res(*grid(0.425, 0.275, 2, 2, layers=2)),
        ),
        (
            "dev11-dim-13",  # a 15 cm bridge: 2-cube pillars under the beam, or 3-cube pillars
            res(*_bridge(0.45, 0.30, 2)),
            res(*_bridge(0.45, 0.30, 4)),
        ),
        (
            "dev11-dim-15",  # 35 cm long and a foot (6 cubes) high
            res(*grid(0.45, 0.15, 1, 7, layers=6)),
            res(*grid(0.45, 0.15, 1, 7, layers=5)),
        ),
        (
            "dev11-neg-01",  # a 5-tower not in the middle
            res(*column(0.30, 0.15, 5)),
            res(*column(0.45, 0.30, 5)),
        ),
        (
            "dev11-neg-03",  # a row of 6 not running left to right
            res(*_row_x(0.30, 0.30, 6)),
            res(*_row_y(0.45, 0.15, 6)),
        ),
        (
            "dev11-neg-07",  # a 5x5 ring with nothing inside
            res(*ring(0.35, 0.20, 5)),
            res(*ring(0.35, 0.20, 5), cube(0.40, 0.25, C / 2)),
        ),
        (
            "dev11-neg-08",  # a 4-step staircase not climbing to the left (+y)
            res(*_stairs_y(0.45, 0.20, (4, 3, 2, 1))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
        ),
        (
            "dev11-typo-13",  # an L with arms of 4
            res(*_l_shape(0.40, 0.20, 4)),
            res(*_l_shape(0.40, 0.20, 3)),
        ),
        (
            "dev11-wo-06",  # a 4-tower on the right (-y) of a 3x3 slab
            res(*grid(0.40, 0.30, 3, 3), *column(0.45, 0.20, 4)),
            res(*grid(0.40, 0.20, 3, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev11-wo-06",  # … or built against the slab's right side
            res(*grid(0.40, 0.30, 3, 3), *column(0.45, 0.25, 4)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.40, 4)),
        ),
        (
            "dev11-wo-08",  # a 6-tower behind (+x) a 4x2 wall
            res(*grid(0.40, 0.225, 1, 4, layers=2), *column(0.55, 0.30, 6)),
            res(*grid(0.40, 0.225, 1, 4, layers=2), *column(0.25, 0.30, 6)),
        ),
        (
            "dev11-reg-06",  # a 2-tower in each corner of the table
            res(*[c for x, y in _TABLE_CORNERS for c in column(x, y, 2)]),
            res(
                *[c for x, y in _TABLE_CORNERS[:3] for c in column(x, y, 2)], *column(0.45, 0.30, 2)
            ),
        ),
        (
            "dev11-reg-08",  # a cube back left, a cube front right
            res(cube(0.65, 0.45, C / 2), cube(0.30, 0.15, C / 2)),
            res(cube(0.65, 0.15, C / 2), cube(0.30, 0.45, C / 2)),
        ),
        (
            "dev11-reg-11",  # a 4-tower 10 cm right (-y) of the centre
            res(*column(0.45, 0.20, 4)),
            res(*column(0.45, 0.40, 4)),
        ),
        (
            "dev11-reg-12",  # a 4x4 ring as far back as it goes
            res(*ring(0.625, 0.225, 4)),
            res(*ring(0.35, 0.225, 4)),
        ),
        (
            "dev11-fil-09",  # a 5x5 ring in the middle
            res(*ring(0.35, 0.20, 5)),
            res(*ring(0.55, 0.30, 5)),
        ),
        (
            "dev11-open-09",  # a low wide platform
            res(*grid(0.40, 0.25, 3, 3)),
            res(*grid(0.40, 0.25, 3, 3, layers=3)),
        ),
        (
            "dev11-bad-02",  # a 25-cube tower: refuse, or cap it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev11-bad-08",  # 4 cubes yet 50 cm tall: refuse, or pick one and say so
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 4)),
        ),
    ],
)
def test_dev11_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev11(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev12


def _dev12(case_id: str) -> Case:
    return next(c for c in DEV12 if c.id == case_id)


def _rows_pyramid(x, y0):
    """A flat pyramid one cube thick along y: rows of 4, 3, 2 and 1, each centred."""
    return [
        *_row_y(x, y0, 4),
        *_row_y(x, y0 + C / 2, 3, z0=C),
        *_row_y(x, y0 + C, 2, z0=2 * C),
        cube(x, y0 + 1.5 * C, 3 * C + C / 2),
    ]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev12-rel-01",  # a 2x2x2 block two cubes right (-y) of a 4-tower
            res(*column(0.45, 0.40, 4), *grid(0.425, 0.20, 2, 2, layers=2)),
            res(*column(0.45, 0.20, 4), *grid(0.425, 0.35, 2, 2, layers=2)),
        ),
        (
            "dev12-rel-02",  # a cube on the middle of a 4x2 wall
            res(*grid(0.45, 0.225, 1, 4, layers=2), cube(0.45, 0.30, 2 * C + C / 2)),
            res(*grid(0.45, 0.225, 1, 4, layers=2), cube(0.45, 0.225, 2 * C + C / 2)),
        ),
        (
            "dev12-rel-04",  # a bridge on 3-pillars with a cube on the beam
            res(*_bridge(0.45, 0.30, 3), cube(0.45, 0.30, 4 * C + C / 2)),
            res(*_bridge(0.45, 0.30, 3)),
        ),
        (
            "dev12-rel-05",  # a 5-tower between two rows of 3, apart
            res(*_row_x(0.40, 0.15, 3), *_row_x(0.40, 0.45, 3), *column(0.45, 0.30, 5)),
            res(*_row_x(0.40, 0.20, 3), *_row_x(0.40, 0.35, 3), *column(0.45, 0.50, 5)),
        ),
        (
            "dev12-rel-06",  # a 3x3 floor with a 2-tower on every corner
            res(*_slab_with_corner_columns(0.40, 0.25, 3, 2)),
            res(*_slab_with_corner_columns(0.40, 0.25, 3, 1)),
        ),
        (
            "dev12-rel-08",  # the 7-tower left (+y), the 3-tower right, two cubes between
            res(*column(0.45, 0.40, 7), *column(0.45, 0.25, 3)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.25, 7)),
        ),
        (
            "dev12-rel-09",  # a 3-level pyramid inside a 2-high ring, free of it
            res(*ring(0.30, 0.15, 7, high=2), *_pyr(0.40, 0.25, 3)),
            res(*ring(0.30, 0.15, 7, high=2), *_pyr(0.40, 0.25, 2)),
        ),
        (
            "dev12-rel-09",  # … or the ring laid tight round the pyramid
            res(*ring(0.35, 0.20, 5, high=2), *_pyr(0.40, 0.25, 3)),
            res(*ring(0.35, 0.20, 5, high=1), *_pyr(0.40, 0.25, 3)),
        ),
        (
            "dev12-rel-10",  # a 4x4 slab, a 2x2 block on it, a cube on the block
            res(
                *grid(0.35, 0.20, 4, 4),
                *grid(0.40, 0.25, 2, 2, z0=C),
                cube(0.425, 0.275, 2 * C + C / 2),
            ),
            res(*grid(0.35, 0.20, 4, 4), *grid(0.40, 0.25, 2, 2, z0=C), cube(0.35, 0.20, 1.5 * C)),
        ),
        (
            "dev12-rel-11",  # a 3-tower behind (+x) a 4x4 ring, outside it
            res(*ring(0.40, 0.225, 4), *column(0.70, 0.30, 3)),
            res(*ring(0.40, 0.225, 4), *column(0.25, 0.30, 3)),
        ),
        (
            "dev12-rel-11",  # … or set against the ring's back
            res(*ring(0.40, 0.225, 4), *column(0.60, 0.30, 3)),
            res(*ring(0.40, 0.225, 4), *column(0.35, 0.30, 3)),
        ),
        (
            "dev12-rel-13",  # a row of 6 built up to 3 at both ends
            res(*_stairs_y(0.45, 0.15, (3, 1, 1, 1, 1, 3))),
            res(*_stairs_y(0.45, 0.15, (4, 1, 1, 1, 1, 4))),
        ),
        (
            "dev12-rel-14",  # a 4x2 wall and a tower twice as tall beside it
            res(*grid(0.45, 0.20, 1, 4, layers=2), *column(0.45, 0.45, 4)),
            res(*grid(0.45, 0.20, 1, 4, layers=2), *column(0.45, 0.45, 3)),
        ),
        (
            "dev12-rel-14",  # … or the tower built against the wall's end
            res(*_stairs_y(0.45, 0.20, (2, 2, 2, 2, 4))),
            res(*_stairs_y(0.45, 0.20, (2, 2, 2, 4))),
        ),
        (
            "dev12-rel-15",  # stacks of 2, 4, 6 from front to back
            res(*column(0.30, 0.30, 2), *column(0.45, 0.30, 4), *column(0.60, 0.30, 6)),
            res(*column(0.30, 0.30, 6), *column(0.45, 0.30, 4), *column(0.60, 0.30, 2)),
        ),
        (
            "dev12-rel-16",  # a 2x2 pad in one corner of a 3x3 pad
            res(*grid(0.40, 0.25, 3, 3), *grid(0.40, 0.25, 2, 2, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *grid(0.425, 0.275, 2, 2, z0=C)),
        ),
        (
            "dev12-rel-17",  # a 3-tower, a 2x2 block, a 2-level pyramid, left to right
            res(*column(0.45, 0.47, 3), *grid(0.425, 0.30, 2, 2), *_pyr(0.40, 0.10, 2)),
            res(*column(0.45, 0.10, 3), *grid(0.425, 0.30, 2, 2), *_pyr(0.40, 0.40, 2)),
        ),
        (
            "dev12-seq-05",  # corrected: a 5x5 pen
            res(*ring(0.35, 0.20, 5)),
            res(*ring(0.40, 0.25, 3)),
        ),
        (
            "dev12-seq-06",  # a 3x3 floor without its centre cube
            res(*ring(0.40, 0.25, 3)),
            res(*grid(0.40, 0.25, 3, 3)),
        ),
        (
            "dev12-seq-07",  # a 4-step staircase up to the back, a 4-tower behind the top
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4, 4))),
            res(*_stairs_x(0.30, 0.30, (4, 1, 2, 3, 4))),
        ),
        (
            "dev12-seq-08",  # two 5-towers one cube apart, a beam across
            res(*_bridge(0.45, 0.30, 5)),
            res(*_WIDE_BRIDGE4),
        ),
        (
            "dev12-seq-09",  # a 6x2 wall with a 4-tower against its left (+y) end
            res(*_stairs_y(0.45, 0.15, (2, 2, 2, 2, 2, 2, 4))),
            res(*_stairs_y(0.45, 0.15, (4, 2, 2, 2, 2, 2, 2))),
        ),
        (
            "dev12-seq-12",  # rows of 4, 3, 2, 1 stacked
            res(*_rows_pyramid(0.45, 0.20)),
            res(*_rows_pyramid(0.45, 0.20)[:-1]),
        ),
        (
            "dev12-seq-13",  # three 3-towers without the middle one
            res(*column(0.45, 0.15, 3), *column(0.45, 0.45, 3)),
            res(*column(0.45, 0.15, 3), *column(0.45, 0.30, 3), *column(0.45, 0.45, 3)),
        ),
        (
            "dev12-seq-14",  # a 4x4 fence filled in and a layer more
            res(*grid(0.35, 0.20, 4, 4, layers=2)),
            res(*ring(0.35, 0.20, 4, high=2)),
        ),
        (
            "dev12-seq-15",  # towers of 2, 3, 4 from front to back
            res(*column(0.30, 0.30, 2), *column(0.45, 0.30, 3), *column(0.60, 0.30, 4)),
            res(*column(0.30, 0.30, 4), *column(0.45, 0.30, 3), *column(0.60, 0.30, 2)),
        ),
        (
            "dev12-num-01",  # towers of 2, 4 and 6
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 4), *column(0.45, 0.45, 6)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 4), *column(0.45, 0.45, 5)),
        ),
        (
            "dev12-num-01",  # … or built touching
            res(*_stairs_y(0.45, 0.25, (2, 4, 6))),
            res(*_stairs_y(0.45, 0.25, (2, 4, 4))),
        ),
        (
            "dev12-num-06",  # a 3-tower and one a cube shorter, built touching
            res(*column(0.45, 0.25, 3), *column(0.45, 0.30, 2)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.30, 3)),
        ),
        (
            "dev12-num-10",  # three 3x3 rings
            res(*ring(0.25, 0.10, 3), *ring(0.45, 0.10, 3), *ring(0.65, 0.10, 3)),
            res(*ring(0.25, 0.10, 3), *ring(0.45, 0.10, 3)),
        ),
        (
            "dev12-num-12",  # a 4-stack and beside it one of half its height
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 3)),
        ),
        (
            "dev12-dim-05",  # 25 cm square outside, 10 cm tall
            res(*ring(0.35, 0.20, 5, high=2)),
            res(*ring(0.35, 0.20, 5, high=1)),
        ),
        (
            "dev12-dim-13",  # two 20 cm towers 10 cm apart
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 4)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.40, 4)),
        ),
        (
            "dev12-dim-16",  # a fence round a 2x2 cube space
            res(*ring(0.40, 0.25, 4)),
            res(*ring(0.40, 0.25, 3)),
        ),
        (
            "dev12-neg-01",  # a 4-tower not in the middle
            res(*column(0.30, 0.15, 4)),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev12-neg-12",  # a 4-step staircase not climbing to the back
            res(*_stairs_x(0.35, 0.30, (4, 3, 2, 1))),
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev12-typo-12",  # an L with arms of 4
            res(*_l_shape(0.40, 0.20, 4)),
            res(*_l_shape(0.40, 0.20, 3)),
        ),
        (
            "dev12-wo-08",  # a 2-stack one cube left (+y) of a 3-level pyramid
            res(*_pyr(0.40, 0.15, 3), *column(0.45, 0.35, 2)),
            res(*_pyr(0.40, 0.30, 3), *column(0.45, 0.20, 2)),
        ),
        (
            "dev12-wo-11",  # a 3-tower inside a 5x5 fence
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 3)),
        ),
        (
            "dev12-reg-04",  # a cube as far left (+y) as it goes
            res(cube(0.45, 0.525, C / 2)),
            res(cube(0.45, 0.30, C / 2)),
        ),
        (
            "dev12-reg-05",  # a 2-tower on the left (+y), a 5-tower on the right
            res(*column(0.45, 0.40, 2), *column(0.45, 0.20, 5)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.40, 5)),
        ),
        (
            "dev12-reg-09",  # cubes in the back left and back right corners
            res(cube(0.65, 0.45, C / 2), cube(0.65, 0.15, C / 2)),
            res(cube(0.65, 0.45, C / 2), cube(0.30, 0.15, C / 2)),
        ),
        (
            "dev12-open-06",  # towers of different heights
            res(*column(0.45, 0.15, 2), *column(0.45, 0.30, 3), *column(0.45, 0.45, 4)),
            res(*column(0.45, 0.15, 3), *column(0.45, 0.30, 3)),
        ),
        (
            "dev12-open-12",  # taller than wide
            res(*column(0.45, 0.30, 4)),
            res(*grid(0.40, 0.25, 3, 3)),
        ),
        (
            "dev12-bad-01",  # a 14-cube tower: refuse, or cap it and say so
            res(*column(0.45, 0.30, 10), notes=["capped at 10 cubes"]),
            res(*column(0.45, 0.30, 10)),
        ),
        (
            "dev12-bad-08",  # a beam cannot span three cubes: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.20, 5), *column(0.45, 0.40, 5)),
        ),
    ],
)
def test_dev12_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev12(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev13


def _dev13(case_id: str) -> Case:
    return next(c for c in DEV13 if c.id == case_id)


def _corner_cubes(x0, y0, far, high, z0=0.0):
    """Columns of `high` cubes on the four corners of a square `far` cubes across."""
    d = C * (far - 1)
    return [c for x in (x0, x0 + d) for y in (y0, y0 + d) for c in column(x, y, high, z0=z0)]


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev13-rel-01",  # the 2-tower 50 mm clear to the right (-y) of the 5-tower
            res(*column(0.45, 0.35, 5), *column(0.45, 0.25, 2)),
            res(*column(0.45, 0.25, 5), *column(0.45, 0.35, 2)),
        ),
        (
            "dev13-rel-04",  # 3-cube pillars, 50 mm clear between them, a beam on top
            res(*_bridge(0.45, 0.30, 3)),
            res(*_bridge(0.45, 0.30, 2)),
        ),
        (
            "dev13-rel-05",  # a 5x2 wall behind a 3-tower, built against it
            res(*grid(0.50, 0.20, 1, 5, layers=2), *column(0.45, 0.30, 3)),
            res(*grid(0.50, 0.20, 1, 5, layers=2), *column(0.55, 0.30, 3)),
        ),
        (
            "dev13-rel-06",  # a 3-tower in the very middle of a 5x5 ring
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.40, 0.25, 3)),
        ),
        (
            "dev13-rel-07",  # a 4-tower one cube left (+y) of a 3-level pyramid
            res(*_pyr(0.40, 0.15, 3), *column(0.45, 0.35, 4)),
            res(*_pyr(0.40, 0.15, 3), *column(0.45, 0.35, 3)),
        ),
        (
            "dev13-rel-09",  # a 2x2x2 block centred on a 4x4 slab
            res(*grid(0.35, 0.20, 4, 4), *grid(0.40, 0.25, 2, 2, layers=2, z0=C)),
            res(*grid(0.35, 0.20, 4, 4), *grid(0.35, 0.20, 2, 2, layers=2, z0=C)),
        ),
        (
            "dev13-rel-11",  # towers of 6, 4, 2 from left (+y) to right, one cube apart
            res(*column(0.45, 0.40, 6), *column(0.45, 0.30, 4), *column(0.45, 0.20, 2)),
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 4), *column(0.45, 0.20, 6)),
        ),
        (
            "dev13-rel-13",  # a 4x4 slab with one cube on each corner
            res(*grid(0.35, 0.20, 4, 4), *_corner_cubes(0.35, 0.20, 4, 1, z0=C)),
            res(*grid(0.35, 0.20, 4, 4), *_corner_cubes(0.35, 0.20, 4, 2, z0=C)),
        ),
        (
            "dev13-rel-14",  # a 5x2 wall and a 3-tower beside it
            res(*grid(0.45, 0.15, 1, 5, layers=2), *column(0.45, 0.45, 3)),
            res(*grid(0.45, 0.15, 1, 5, layers=2), *column(0.45, 0.45, 4)),
        ),
        (
            "dev13-rel-16",  # a 2-tower touching the back (+x) of a 5-tower
            res(*_stairs_x(0.40, 0.30, (5, 2))),
            res(*_stairs_x(0.40, 0.30, (2, 5))),
        ),
        (
            "dev13-rel-18",  # two rows of 5 along y, 50 mm apart
            res(*_row_y(0.40, 0.20, 5), *_row_y(0.50, 0.20, 5)),
            res(*_row_y(0.40, 0.20, 5), *_row_y(0.55, 0.20, 5)),
        ),
        (
            "dev13-num-05",  # a 2 x 3 array of cubes at a 100 mm pitch
            res(*[cube(x, y, C / 2) for x in (0.40, 0.50) for y in (0.20, 0.30, 0.40)]),
            res(*[cube(x, y, C / 2) for x in (0.40, 0.50) for y in (0.20, 0.35, 0.50)]),
        ),
        (
            "dev13-num-08",  # a 3-tower and one of double its height
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 6)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.40, 5)),
        ),
        (
            "dev13-num-11",  # two 4-towers 150 mm apart (clear)
            res(*column(0.45, 0.20, 4), *column(0.45, 0.40, 4)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 4)),
        ),
        (
            "dev13-num-14",  # an 8-tower with a half-height one built against it
            res(*_stairs_y(0.45, 0.25, (8, 4))),
            res(*_stairs_y(0.45, 0.25, (8, 3))),
        ),
        (
            "dev13-num-15",  # 2-towers on the corners of a 4x4 square
            res(*_corner_cubes(0.40, 0.25, 4, 2)),
            res(*_corner_cubes(0.40, 0.25, 3, 2)),
        ),
        (
            "dev13-num-06",  # two parallel 5x3 walls, apart
            res(*grid(0.35, 0.20, 1, 5, layers=3), *grid(0.50, 0.20, 1, 5, layers=3)),
            res(*grid(0.35, 0.20, 1, 5, layers=3), *grid(0.50, 0.45, 5, 1, layers=3)),
        ),
        (
            "dev13-num-18",  # two 3-towers two cubes apart (clear)
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.50, 3)),
        ),
        (
            "dev13-dim-02",  # 150 x 100 mm, 3 layers
            res(*grid(0.40, 0.25, 3, 2, layers=3)),
            res(*grid(0.40, 0.25, 3, 2, layers=2)),
        ),
        (
            "dev13-dim-06",  # a 4x4 ring one cube high
            res(*ring(0.40, 0.25, 4)),
            res(*ring(0.40, 0.25, 4, high=2)),
        ),
        (
            "dev13-dim-10",  # two 2-towers 250 mm clear
            res(*column(0.45, 0.15, 2), *column(0.45, 0.45, 2)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.40, 2)),
        ),
        (
            "dev13-dim-12",  # 5-cube pillars 50 mm clear
            res(*_bridge(0.45, 0.30, 5)),
            res(
                *column(0.45, 0.225, 5),
                *column(0.45, 0.375, 5),
                beam(0.45, 0.30, 5 * C + C / 2, YAW90),
            ),
        ),
        (
            "dev13-seq-07",  # two rows of 5 front to back, one cube apart
            res(*_row_x(0.35, 0.30, 5), *_row_x(0.35, 0.40, 5)),
            res(*_row_x(0.35, 0.30, 5), *_row_x(0.35, 0.45, 5)),
        ),
        (
            "dev13-seq-13",  # a bridge on 4-pillars with a cube on the beam
            res(*_bridge(0.45, 0.30, 4), cube(0.45, 0.30, 5 * C + C / 2)),
            res(*_bridge(0.45, 0.30, 4)),
        ),
        (
            "dev13-seq-14",  # a 3-step staircase with a 5-tower against its top step
            res(*_stairs_x(0.35, 0.30, (1, 2, 3, 5))),
            res(*_stairs_x(0.35, 0.30, (5, 1, 2, 3))),
        ),
        (
            "dev13-seq-15",  # a second 4x2 wall behind the first, two cubes between
            res(*grid(0.35, 0.20, 1, 4, layers=2), *grid(0.50, 0.20, 1, 4, layers=2)),
            res(*grid(0.35, 0.20, 4, 1, layers=2), *grid(0.35, 0.35, 4, 1, layers=2)),
        ),
        (
            "dev13-neg-10",  # a 4x3 slab kept out of the right (-y) half
            res(*grid(0.40, 0.35, 4, 3)),
            res(*grid(0.40, 0.25, 4, 3)),
        ),
        (
            "dev13-wo-11",  # a 3-tower against the right (-y) end of a 4x2 wall
            res(*_stairs_y(0.45, 0.20, (3, 2, 2, 2, 2))),
            res(*_stairs_y(0.45, 0.20, (2, 2, 2, 2, 3))),
        ),
        (
            "dev13-bad-09",  # a beam cannot span 300 mm: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.15, 4), *column(0.45, 0.45, 4)),
        ),
    ],
)
def test_dev13_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev13(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev14


def _dev14(case_id: str) -> Case:
    return next(c for c in DEV14 if c.id == case_id)


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev14-rel-01",  # a 2-tower one cube clear to the left (+y) of a 4-tower
            res(*column(0.45, 0.25, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.35, 4), *column(0.45, 0.25, 2)),
        ),
        (
            "dev14-rel-03",  # a 3-tower one cube in front (-x) of a 4x2 wall
            res(*grid(0.50, 0.20, 1, 4, layers=2), *column(0.40, 0.25, 3)),
            res(*grid(0.50, 0.20, 1, 4, layers=2), *column(0.60, 0.25, 3)),
        ),
        (
            "dev14-rel-07",  # the 5-tower two cubes behind (+x) the 3-tower
            res(*column(0.35, 0.30, 3), *column(0.50, 0.30, 5)),
            res(*column(0.50, 0.30, 3), *column(0.35, 0.30, 5)),
        ),
        (
            "dev14-rel-08",  # a 2-tower in the very middle of a 5x5 ring
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 2)),
            res(*ring(0.35, 0.20, 5), *column(0.40, 0.30, 2)),
        ),
        (
            "dev14-rel-10",  # towers of 2, 4, 6 from left (+y) to right, one cube apart
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 4), *column(0.45, 0.20, 6)),
            res(*column(0.45, 0.40, 6), *column(0.45, 0.30, 4), *column(0.45, 0.20, 2)),
        ),
        (
            "dev14-rel-11",  # a 2x2x2 block between two 4-towers, one cube clear each side
            res(
                *column(0.45, 0.175, 4),
                *grid(0.425, 0.275, 2, 2, layers=2),
                *column(0.45, 0.425, 4),
            ),
            res(
                *column(0.45, 0.125, 4),
                *grid(0.425, 0.275, 2, 2, layers=2),
                *column(0.45, 0.425, 4),
            ),
        ),
        (
            "dev14-rel-13",  # two rows of 6 along y, one cube apart
            res(*_row_y(0.40, 0.20, 6), *_row_y(0.50, 0.20, 6)),
            res(*_row_y(0.40, 0.20, 6), *_row_y(0.55, 0.20, 6)),
        ),
        (
            "dev14-rel-16",  # two 4-stacks touching front to back: a 2 (x) by 1 block, 4 high
            res(*grid(0.40, 0.30, 2, 1, layers=4)),
            res(*grid(0.40, 0.30, 1, 2, layers=4)),
        ),
        (
            "dev14-rel-17",  # three 3-towers front to back, two cubes clear between
            res(*column(0.30, 0.30, 3), *column(0.45, 0.30, 3), *column(0.60, 0.30, 3)),
            res(*column(0.30, 0.30, 3), *column(0.40, 0.30, 3), *column(0.50, 0.30, 3)),
        ),
        (
            "dev14-rel-18",  # two gates of 4-pillars, the second two cubes to the left
            res(*_bridge(0.45, 0.20, 4), *_bridge(0.45, 0.45, 4)),
            res(*_bridge(0.45, 0.20, 4), *_bridge(0.45, 0.40, 4)),
        ),
        (
            "dev14-num-02",  # two 6-towers, two cubes clear
            res(*column(0.45, 0.20, 6), *column(0.45, 0.35, 6)),
            res(*column(0.45, 0.20, 6), *column(0.45, 0.30, 6)),
        ),
        (
            "dev14-num-06",  # three 2-towers in a line, one cube between each
            res(*column(0.40, 0.20, 2), *column(0.40, 0.30, 2), *column(0.40, 0.40, 2)),
            res(*column(0.40, 0.20, 2), *column(0.40, 0.30, 2), *column(0.40, 0.45, 2)),
        ),
        (
            "dev14-num-07",  # a 4-tower and one double its height
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 8)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 6)),
        ),
        (
            "dev14-num-14",  # a 6-tower between two 3-towers
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 6), *column(0.45, 0.40, 3)),
            res(*column(0.45, 0.20, 6), *column(0.45, 0.30, 3), *column(0.45, 0.40, 3)),
        ),
        (
            "dev14-dim-03",  # 2 deep (x), 3 wide (y), 2 tall
            res(*grid(0.40, 0.25, 2, 3, layers=2)),
            res(*grid(0.40, 0.25, 3, 2, layers=2)),
        ),
        (
            "dev14-dim-07",  # a ring 4 by 5 outside, 2 high
            res(
                *[
                    c
                    for i in range(4)
                    for j in range(5)
                    if i in (0, 3) or j in (0, 4)
                    for c in column(0.40 + C * i, 0.20 + C * j, 2)
                ]
            ),
            res(*ring(0.40, 0.20, 5, high=2)),
        ),
        (
            "dev14-dim-14",  # 5-brick posts, one brick clear between
            res(*_bridge(0.45, 0.30, 5)),
            res(*_bridge(0.45, 0.30, 4)),
        ),
        (
            "dev14-dim-16",  # a 2x2 column 5 high
            res(*grid(0.40, 0.25, 2, 2, layers=5)),
            res(*grid(0.40, 0.25, 2, 2, layers=4)),
        ),
        (
            "dev14-seq-11",  # a 7-tower split into 4 and 3, apart or touching
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 3)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 4)),
        ),
        (
            "dev14-seq-11",  # the touching reading
            res(*_stairs_y(0.45, 0.25, (4, 3))),
            res(*_stairs_y(0.45, 0.25, (7, 3))),
        ),
        (
            "dev14-seq-17",  # after removing the 4, a 3-tower one cube behind a 2-tower
            res(*column(0.40, 0.30, 2), *column(0.50, 0.30, 3)),
            res(*column(0.40, 0.30, 3), *column(0.50, 0.30, 2)),
        ),
        (
            "dev14-neg-06",  # a 3-level pyramid kept out of the left (+y) half
            res(*_pyr(0.40, 0.10, 3)),
            res(*_pyr(0.40, 0.25, 3)),
        ),
        (
            "dev14-reg-05",  # 2-towers front left and back right
            res(*column(0.30, 0.45, 2), *column(0.70, 0.15, 2)),
            res(*column(0.30, 0.15, 2), *column(0.70, 0.45, 2)),
        ),
        (
            "dev14-seq-09",  # rows of 6, 4, 2; the 4 in the middle of the 6, the 2 anywhere on it
            res(
                *_row_y(0.45, 0.20, 6),
                *_row_y(0.45, 0.25, 4, z0=C),
                *_row_y(0.45, 0.25, 2, z0=2 * C),
            ),
            res(
                *_row_y(0.45, 0.20, 6),
                *_row_y(0.45, 0.20, 4, z0=C),
                *_row_y(0.45, 0.25, 2, z0=2 * C),
            ),
        ),
        (
            "dev14-rel-19",  # a row of 5 in front (-x) of both 3-towers
            res(*column(0.50, 0.25, 3), *column(0.50, 0.35, 3), *_row_y(0.40, 0.20, 5)),
            res(*column(0.50, 0.25, 3), *column(0.40, 0.45, 3), *_row_y(0.40, 0.20, 5)),
        ),
        (
            "dev14-num-19",  # a 6-stack and a 2-stack, one cube clear
            res(*column(0.45, 0.25, 6), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.25, 6), *column(0.45, 0.35, 3)),
        ),
        (
            "dev14-bad-11",  # x = 1.2 is outside the cell: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 3)),
        ),
    ],
)
def test_dev14_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev14(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev15


def _dev15(case_id: str) -> Case:
    return next(c for c in DEV15 if c.id == case_id)


_L4_ARMS = [*_row_y(0.40, 0.20, 4), *_row_x(0.45, 0.20, 3)]  # arms of 4 sharing the corner


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev15-rel-01",  # a 2-tower one cube clear to the left (+y) of a 4-tower
            res(*column(0.45, 0.30, 4), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.30, 4), *column(0.45, 0.20, 2)),
        ),
        (
            "dev15-rel-13",  # a 3x3 plinth with a 2-cube column on each corner
            res(
                *grid(0.40, 0.25, 3, 3),
                *[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 2, z0=C)],
            ),
            res(
                *grid(0.40, 0.25, 3, 3),
                *[c for x in (0.40, 0.45) for y in (0.25, 0.35) for c in column(x, y, 2, z0=C)],
            ),
        ),
        (
            "dev15-rel-19",  # 3-towers left and right of a 6-tower, 2 cubes clear
            res(*column(0.45, 0.15, 3), *column(0.45, 0.30, 6), *column(0.45, 0.45, 3)),
            res(*column(0.45, 0.15, 6), *column(0.45, 0.30, 3), *column(0.45, 0.45, 3)),
        ),
        (
            "dev15-rel-19",  # the centre-to-centre reading of "in distance of 2 cubes"
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 6), *column(0.45, 0.40, 3)),
            res(*column(0.45, 0.20, 3), *column(0.45, 0.30, 6), *column(0.45, 0.45, 3)),
        ),
        (
            "dev15-rel-20",  # a one-high fence round a 3-tower, apart from it
            res(*ring(0.35, 0.20, 5), *column(0.45, 0.30, 3)),
            res(*ring(0.35, 0.20, 5), *column(0.70, 0.30, 3)),
        ),
        (
            "dev15-rel-20",  # or hugging it (one structure)
            res(*ring(0.40, 0.25, 3), *column(0.45, 0.30, 3)),
            res(*ring(0.40, 0.25, 3, high=3), *column(0.45, 0.30, 3)),
        ),
        (
            "dev15-rel-21",  # an L of 4-arms, a 2-tower in the inside corner touching both
            res(*_L4_ARMS, *column(0.45, 0.25, 2)),
            res(*_L4_ARMS, *column(0.45, 0.15, 2)),
        ),
        (
            "dev15-seq-02",  # a 6x2 wall with both end cubes of the top course taken off
            res(*_row_y(0.45, 0.20, 6), *_row_y(0.45, 0.25, 4, z0=C)),
            res(*_row_y(0.45, 0.20, 6), *_row_y(0.45, 0.20, 4, z0=C)),
        ),
        (
            "dev15-seq-12",  # 3, (removed), 3+3: a 3-tower three cubes left of a 6-tower
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 6)),
            res(*column(0.45, 0.40, 6), *column(0.45, 0.20, 3)),
        ),
        (
            "dev15-seq-18",  # a 3-pillar gate with a 2-cube column over each pillar
            res(
                *_bridge(0.45, 0.30, 3),
                *column(0.45, 0.25, 2, z0=4 * C),
                *column(0.45, 0.35, 2, z0=4 * C),
            ),
            res(*_bridge(0.45, 0.30, 3), *column(0.45, 0.30, 2, z0=4 * C)),
        ),
        (
            "dev15-num-16",  # four 3-towers a cube apart: a line or a square cluster
            res(*[c for x in (0.40, 0.50) for y in (0.25, 0.35) for c in column(x, y, 3)]),
            res(*[c for y in (0.15, 0.25, 0.35, 0.50) for c in column(0.45, y, 3)]),
        ),
        (
            "dev15-neg-12",  # a 3x3x3 block without the centre cube of the top layer
            res(
                *grid(0.40, 0.25, 3, 3, layers=2),
                *[
                    c
                    for c in grid(0.40, 0.25, 3, 3, z0=2 * C)
                    if not (
                        math.isclose(c["position"][0], 0.45)
                        and math.isclose(c["position"][1], 0.30)
                    )
                ],
            ),
            res(*grid(0.40, 0.25, 3, 3, layers=3)),
        ),
        (
            "dev15-dim-13",  # 4 deep (x), 3 wide (y), 2 high
            res(*grid(0.40, 0.25, 4, 3, layers=2)),
            res(*grid(0.40, 0.25, 3, 4, layers=2)),
        ),
        (
            "dev15-dim-18",  # three 5-wide terraces climbing to the back
            res(*[c for j in range(5) for c in _stairs_x(0.40, 0.20 + C * j, (1, 2, 3))]),
            res(*[c for j in range(5) for c in _stairs_x(0.40, 0.20 + C * j, (3, 2, 1))]),
        ),
        (
            "dev15-reg-11",  # a 3x3 slab 10 cm from the front border (x 0.20), edge or centre
            res(*grid(0.325, 0.25, 3, 3)),
            res(*grid(0.45, 0.25, 3, 3)),
        ),
        (
            "dev15-open-12",  # mirror-symmetric: a 2x2 block between two equal towers
            res(
                *column(0.45, 0.20, 3), *grid(0.425, 0.275, 2, 2, layers=2), *column(0.45, 0.40, 3)
            ),
            res(
                *column(0.45, 0.20, 3), *grid(0.425, 0.275, 2, 2, layers=2), *column(0.45, 0.40, 2)
            ),
        ),
        (
            "dev15-bad-13",  # x = 0.95 is outside the cell: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 4)),
        ),
    ],
)
def test_dev15_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev15(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev16


def _dev16(case_id: str) -> Case:
    return next(c for c in DEV16 if c.id == case_id)


def _without(objs, *cells):
    """`objs` less the cubes whose (x, y) centre is one of `cells`."""
    return [
        c
        for c in objs
        if not any(
            math.isclose(c["position"][0], x) and math.isclose(c["position"][1], y)
            for x, y in cells
        )
    ]


# a 3-level pyramid centred at (0.50, 0.30): 3x3, 2x2, one cube
_PYR3_AT_50 = [
    *grid(0.45, 0.25, 3, 3),
    *grid(0.475, 0.275, 2, 2, z0=C),
    cube(0.50, 0.30, 2 * C + C / 2),
]
_WALL3X2 = [*_row_y(0.45, 0.25, 3), *_row_y(0.45, 0.25, 3, z0=C)]
_WALL5X2 = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]
_BLOCK222 = grid(0.425, 0.275, 2, 2, layers=2)  # centred on (0.45, 0.30)


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev16-rel-04",  # a 2-tower 0.10 m (centre to centre) left of a 5-tower at (0.45, 0.30)
            res(*column(0.45, 0.30, 5), *column(0.45, 0.40, 2)),
            res(*column(0.45, 0.30, 5), *column(0.45, 0.45, 2)),  # 0.10 m clear instead
        ),
        (
            "dev16-rel-05",  # a 3-tower a cube clear beyond the top end of 3 steps
            res(*_stairs_x(0.35, 0.30, (1, 2, 3)), *column(0.55, 0.30, 3)),
            res(*_stairs_x(0.35, 0.30, (1, 2, 3)), *column(0.25, 0.30, 3)),  # at the low end
        ),
        (
            "dev16-rel-08",  # a one-high ring round a 3-level pyramid, one cube of floor between
            res(*_PYR3_AT_50, *ring(0.35, 0.15, 7)),
            res(*_PYR3_AT_50, *ring(0.30, 0.10, 9)),  # two cubes of floor
        ),
        (
            "dev16-rel-11",  # a 3x2 wall with a 4-tower touching the middle of its back face
            res(*_WALL3X2, *column(0.50, 0.30, 4)),
            res(*_WALL3X2, *column(0.40, 0.30, 4)),  # in front of it
        ),
        (
            "dev16-rel-13",  # a 5x2 wall along y with a 4-tower flush at both ends
            res(*_WALL5X2, *column(0.45, 0.15, 4), *column(0.45, 0.45, 4)),
            res(*_WALL5X2, *column(0.45, 0.45, 4)),  # one end only
        ),
        (
            "dev16-rel-18",  # a central 2x2x2 block, a 3-tower a cube clear on each side
            res(
                *_BLOCK222,
                *column(0.325, 0.30, 3),
                *column(0.575, 0.30, 3),
                *column(0.45, 0.425, 3),
                *column(0.45, 0.175, 3),
            ),
            res(
                *_BLOCK222,
                *column(0.325, 0.30, 3),
                *column(0.575, 0.30, 3),
                *column(0.45, 0.425, 3),
                *column(0.575, 0.20, 3),  # a second one behind, none on the right
            ),
        ),
        (
            "dev16-seq-08",  # the left-hand (+y) column raised to 5, a cube clear of the 3
            res(*column(0.45, 0.35, 5), *column(0.45, 0.25, 3)),
            res(*column(0.45, 0.35, 3), *column(0.45, 0.25, 5)),
        ),
        (
            "dev16-seq-09",  # a 3x5 grid less its four corner cubes
            res(
                *_without(
                    grid(0.40, 0.20, 3, 5), (0.40, 0.20), (0.40, 0.40), (0.50, 0.20), (0.50, 0.40)
                )
            ),
            res(*grid(0.40, 0.20, 3, 5)),
        ),
        (
            "dev16-num-08",  # columns of 2, 4, 6, 8 from left (+y) to right, apart
            res(
                *column(0.45, 0.45, 2),
                *column(0.45, 0.35, 4),
                *column(0.45, 0.25, 6),
                *column(0.45, 0.15, 8),
            ),
            res(
                *column(0.45, 0.45, 8),
                *column(0.45, 0.35, 6),
                *column(0.45, 0.25, 4),
                *column(0.45, 0.15, 2),
            ),
        ),
        (
            "dev16-num-08",  # or touching, still rising to the right
            res(
                *column(0.45, 0.40, 2),
                *column(0.45, 0.35, 4),
                *column(0.45, 0.30, 6),
                *column(0.45, 0.25, 8),
            ),
            res(
                *column(0.45, 0.40, 2),
                *column(0.45, 0.35, 6),
                *column(0.45, 0.30, 4),
                *column(0.45, 0.25, 8),
            ),
        ),
        (
            "dev16-num-16",  # six 2-stacks in two lanes of three
            res(*[c for x in (0.40, 0.55) for y in (0.20, 0.30, 0.40) for c in column(x, y, 2)]),
            res(*[c for y in (0.10, 0.18, 0.26, 0.34, 0.42, 0.50) for c in column(0.45, y, 2)]),
        ),
        (
            "dev16-neg-13",  # a 5x2 wall without the middle cube of its top course
            res(*_without(_WALL5X2[5:], (0.45, 0.30)), *_WALL5X2[:5]),
            res(*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 4, z0=C)),  # an end cube left out
        ),
        (
            "dev16-reg-08",  # both towers wholly in the left half (y ≥ 0.30)
            res(*column(0.45, 0.45, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.45, 4), *column(0.45, 0.25, 2)),
        ),
        (
            "dev16-wo-12",  # a 5-tower set down against a 3-level pyramid (one structure)
            res(*_pyr(0.40, 0.25, 3), *column(0.55, 0.30, 5)),
            res(*_pyr(0.40, 0.25, 3), *column(0.55, 0.30, 4)),
        ),
        (
            "dev16-bad-02",  # 14 high is past the cell: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 10)),
        ),
    ],
)
def test_dev16_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev16(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev17


def _dev17(case_id: str) -> Case:
    return next(c for c in DEV17 if c.id == case_id)


def _jenga(layers, turn=True):
    """Layers of three beams on a 3x3 footprint centred on (0.45, 0.30), the first along x,
    each next one turned 90° about z when `turn`."""
    out = []
    for i in range(layers):
        z = C / 2 + C * i
        if turn and i % 2:
            out += [beam(x, 0.30, z, YAW90) for x in (0.40, 0.45, 0.50)]
        else:
            out += [beam(0.45, y, z) for y in (0.25, 0.30, 0.35)]
    return out


_STAIRS5_X = _stairs_x(0.35, 0.30, (1, 2, 3, 4, 5))  # climbing back, top step at x 0.55


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev17-rel-01",  # 6 in ≈ 3 and 4 in ≈ 2 cubes, two inches ≈ one cube clear
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.40, 2)),  # two cubes clear
        ),
        (
            "dev17-rel-09",  # of two towers, the second from the left (the -y one) raised to 6
            res(*column(0.45, 0.35, 4), *column(0.45, 0.25, 6)),
            res(*column(0.45, 0.35, 6), *column(0.45, 0.25, 4)),
        ),
        (
            "dev17-rel-14",  # the leftmost of three 2-stacks raised to 5, a cube between each
            res(*column(0.45, 0.40, 5), *column(0.45, 0.30, 2), *column(0.45, 0.20, 2)),
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 2), *column(0.45, 0.20, 5)),
        ),
        (
            "dev17-rel-15",  # a 4-tower a cube behind the top of 4 steps climbing back
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4)), *column(0.55, 0.30, 4)),
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4)), *column(0.45, 0.40, 4)),  # to one side
        ),
        (
            "dev17-rel-19",  # revised: the 3-tower on the right-hand end cube of a front row of 5
            res(*_row_y(0.35, 0.20, 5), *column(0.35, 0.20, 3, z0=C)),
            res(*_row_y(0.35, 0.20, 5), *column(0.35, 0.30, 3, z0=C)),  # the first version
        ),
        (
            "dev17-rel-19",  # the mirror image: on the left-hand end
            res(*_row_y(0.35, 0.20, 5), *column(0.35, 0.20, 3, z0=C)),
            res(*_row_y(0.35, 0.20, 5), *column(0.35, 0.40, 3, z0=C)),
        ),
        (
            "dev17-rel-22",  # a central 5-stack, a 2-stack a cube clear on each of its sides
            res(
                *column(0.45, 0.30, 5),
                *column(0.35, 0.30, 2),
                *column(0.55, 0.30, 2),
                *column(0.45, 0.40, 2),
                *column(0.45, 0.20, 2),
            ),
            res(
                *column(0.45, 0.30, 5),
                *column(0.35, 0.30, 2),
                *column(0.55, 0.30, 2),
                *column(0.45, 0.40, 2),
                *column(0.65, 0.30, 2),  # a second one behind, none on the right
            ),
        ),
        (
            "dev17-seq-01",  # 4 → 5, left → right: the last word wins
            res(*column(0.45, 0.15, 5)),
            res(*column(0.45, 0.45, 5)),
        ),
        (
            "dev17-seq-17",  # a 6-stack flagpole a block past the top of 5 steps
            res(*_STAIRS5_X, *column(0.65, 0.30, 6)),
            res(*_STAIRS5_X, *column(0.25, 0.30, 6)),  # at the bottom end
        ),
        (
            "dev17-seq-20",  # the middle 2-stack moved onto the right one: 4 right, 2 left
            res(*column(0.45, 0.15, 4), *column(0.45, 0.45, 2)),
            res(*column(0.45, 0.15, 2), *column(0.45, 0.45, 4)),
        ),
        (
            "dev17-seq-21",  # two 3-towers, a beam across, one cube at mid-span: 8 parts
            res(
                *column(0.45, 0.25, 3),
                *column(0.45, 0.35, 3),
                beam(0.45, 0.30, 0.175, YAW90),
                cube(0.45, 0.30, 0.225),
            ),
            res(
                *column(0.45, 0.25, 3),
                *column(0.45, 0.35, 3),
                beam(0.45, 0.30, 0.175, YAW90),
                cube(0.45, 0.25, 0.225),  # over one pillar, not mid-span
            ),
        ),
        (
            "dev17-seq-22",  # 4 towers front to back, the third raised to 4, the last removed
            res(*column(0.30, 0.30, 2), *column(0.40, 0.30, 2), *column(0.50, 0.30, 4)),
            res(*column(0.30, 0.30, 2), *column(0.40, 0.30, 4), *column(0.50, 0.30, 2)),
        ),
        (
            "dev17-num-22",  # a Jenga-style tower: 4 layers of 3 beams, each turned across
            res(*_jenga(4)),
            res(*_jenga(4, turn=False)),
        ),
        (
            "dev17-dim-05",  # "around 5 inches" = 2.5 cubes: 2 or 3
            res(*column(0.45, 0.30, 3)),
            res(*column(0.45, 0.30, 5)),
        ),
        (
            "dev17-dim-05",
            res(*column(0.45, 0.30, 2)),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev17-dim-13",  # a Tetris L lying flat
            res(*_row_x(0.40, 0.30, 3), cube(0.40, 0.35, 0.025)),
            res(*_row_x(0.40, 0.30, 4)),  # an I-piece
        ),
        (
            "dev17-dim-13",  # or standing: a column of 3 with a foot
            res(*column(0.45, 0.30, 3), cube(0.50, 0.30, 0.025)),
            res(*column(0.45, 0.30, 3), cube(0.50, 0.30, 0.025), cube(0.40, 0.30, 0.025)),
        ),
        (
            "dev17-dim-14",  # 4 steps, each 2 in (1 cube) high and 4 in (2 cubes) deep
            res(*_stairs_x(0.30, 0.30, (1, 1, 2, 2, 3, 3, 4, 4))),
            res(*_stairs_x(0.30, 0.30, (1, 2, 3, 4))),
        ),
        (
            "dev17-typo-13",  # a Tetris T standing: a row of 3, one on the middle
            res(*_row_y(0.45, 0.25, 3), cube(0.45, 0.30, 0.075)),
            res(*_row_y(0.45, 0.25, 3), cube(0.45, 0.25, 0.075)),  # that is an L
        ),
        (
            "dev17-neg-11",  # 6 in ≈ 3 cubes or more of floor to the left edge (y 0.55)
            res(*column(0.45, 0.375, 4)),
            res(*column(0.45, 0.45, 4)),
        ),
        (
            "dev17-reg-02",  # 8 in left of the middle line: y ≈ 0.503
            res(*column(0.45, 0.50, 3)),
            res(*column(0.45, 0.40, 3)),
        ),
        (
            "dev17-reg-07",  # an 8-inch row within an inch of the back edge (x 0.80)
            res(*_row_y(0.775, 0.20, 4)),
            res(*_row_y(0.70, 0.20, 4)),
        ),
        (
            "dev17-reg-11",  # the left tower moved to the back, the right one left alone
            res(*column(0.65, 0.40, 3), *column(0.45, 0.15, 3)),
            res(*column(0.45, 0.45, 3), *column(0.45, 0.15, 3)),  # nothing moved
        ),
        (
            "dev17-bad-02",  # a yard (≈ 18 cubes) is past the cell: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 10)),
        ),
    ],
)
def test_dev17_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev17(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev18


def _dev18(case_id: str) -> Case:
    return next(c for c in DEV18 if c.id == case_id)


def _spaced(x0, y0, nx, ny, pitch, high=1):
    """An nx × ny array of columns `high` cubes tall, `pitch` m apart centre to centre."""
    return [
        c
        for i in range(nx)
        for j in range(ny)
        for c in column(x0 + pitch * i, y0 + pitch * j, high)
    ]


_FLAT4X2 = [*_row_y(0.45, 0.20, 4), *_row_y(0.45, 0.20, 4, z0=C)]  # y 0.20–0.35, x 0.45
_CHECKER = [
    cube(0.40 + C * i, 0.25 + C * j, 0.025) for i in range(4) for j in range(4) if (i + j) % 2 == 0
]
_L_ARMS4 = [*_row_y(0.40, 0.20, 4), *_row_x(0.45, 0.20, 3)]  # arms of 4 sharing the corner


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev18-rel-21",  # a bare "stage left" of the flat: the robot's left (+y) …
            res(*_FLAT4X2, *column(0.45, 0.45, 3)),
            res(*_FLAT4X2, *column(0.60, 0.275, 3)),  # upstage of it, not to a side
        ),
        (
            "dev18-rel-21",  # … or the performer's left, the robot's right (-y)
            res(*_FLAT4X2, *column(0.45, 0.10, 3)),
            res(*_FLAT4X2, *column(0.30, 0.275, 3)),  # downstage of it
        ),
        (
            "dev18-fil-12",  # glossed: the actor's left facing the house = the robot's right
            res(*column(0.30, 0.15, 5)),
            res(*column(0.30, 0.45, 5)),
        ),
        (
            "dev18-reg-04",  # glossed: the performer's right facing the audience = +y
            res(*column(0.45, 0.50, 4)),
            res(*column(0.45, 0.10, 4)),
        ),
        (
            "dev18-reg-02",  # a bare "downstage left": either side, but not the middle
            res(*grid(0.30, 0.10, 2, 2)),
            res(*grid(0.275, 0.275, 2, 2)),
        ),
        (
            "dev18-rel-19",  # A1 and C3 of a touching 3 x 3 grid: opposite corners
            res(*column(0.40, 0.25, 2), *column(0.50, 0.35, 2)),
            res(*column(0.40, 0.25, 2), *column(0.50, 0.25, 2)),  # A1 and C1
        ),
        (
            "dev18-rel-24",  # rows A–C front to back, columns 1–4 left to right: A1 and C4
            res(*column(0.40, 0.40, 3), *column(0.50, 0.25, 3)),
            res(*column(0.40, 0.25, 3), *column(0.50, 0.40, 3)),  # A4 and C1
        ),
        (
            "dev18-num-01",  # a 3 x 4 array: touching (a plate) …
            res(*grid(0.40, 0.25, 3, 4)),
            res(*grid(0.40, 0.25, 3, 4)[:-1]),  # a position left empty
        ),
        (
            "dev18-num-01",  # … or evenly spaced
            res(*_spaced(0.35, 0.15, 3, 4, 0.10)),
            res(*_spaced(0.35, 0.15, 3, 4, 0.10)[:-1], cube(0.60, 0.48, 0.025)),  # off the grid
        ),
        (
            "dev18-num-02",  # 2 x 6 positions one cube clear of each other
            res(*_spaced(0.25, 0.25, 6, 2, 0.10)),
            res(*grid(0.40, 0.25, 6, 2)),  # touching
        ),
        (
            "dev18-num-03",  # a checkerboard on the table …
            res(*_CHECKER),
            res(*grid(0.40, 0.25, 4, 4)),
        ),
        (
            "dev18-num-03",  # … or on top of a 4 x 4 plate
            res(
                *grid(0.40, 0.25, 4, 4),
                *[{**c, "position": [*c["position"][:2], 0.075]} for c in _CHECKER],
            ),
            res(*grid(0.40, 0.25, 4, 4), *grid(0.40, 0.25, 4, 2, z0=C)),  # half covered
        ),
        (
            "dev18-rel-14",  # a spaced 2 x 3 array with a 4-high marker on its right
            res(*_spaced(0.40, 0.20, 2, 3, 0.10), *column(0.45, 0.08, 4)),
            res(*_spaced(0.40, 0.20, 2, 3, 0.10), *column(0.45, 0.52, 4)),  # on its left
        ),
        (
            "dev18-neg-11",  # a 2 x 3 array of 2-high stacks, none touching
            res(*_spaced(0.40, 0.20, 2, 3, 0.10, high=2)),
            res(*grid(0.40, 0.25, 2, 3, layers=2)),
        ),
        (
            "dev18-rel-08",  # OCR "l0 crn apart": 10 cm clear (2 cubes) …
            res(*column(0.45, 0.20, 4), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.40, 2)),  # 15 cm clear
        ),
        (
            "dev18-rel-08",  # … or 10 cm centre to centre (1 cube clear)
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 2)),
            res(*column(0.45, 0.20, 4), *column(0.45, 0.30, 4)),
        ),
        (
            "dev18-dim-13",  # OCR "2O cm 1ong and l5 cm high": 4 long, 3 high
            res(*[c for h in range(3) for c in _row_y(0.45, 0.20, 4, z0=C * h)]),
            res(*_row_y(0.45, 0.20, 4)),  # "l5" misread as 5 cm
        ),
        (
            "dev18-dim-01",  # a 2 by 3 by 4 cuboid standing on its 2 × 3 face …
            res(*grid(0.40, 0.25, 2, 3, layers=4)),
            res(*grid(0.40, 0.25, 2, 3, layers=3)),
        ),
        (
            "dev18-dim-01",  # … or lying on its 3 × 4 face
            res(*grid(0.40, 0.25, 3, 4, layers=2)),
            res(*grid(0.40, 0.25, 3, 3, layers=2)),
        ),
        (
            "dev18-rel-11",  # two walls of 4, 2 high, perpendicular, sharing a vertex
            res(*_L_ARMS4, *[{**c, "position": [*c["position"][:2], 0.075]} for c in _L_ARMS4]),
            res(
                *_row_y(0.40, 0.20, 4),
                *_row_y(0.40, 0.20, 4, z0=C),
                *_row_y(0.50, 0.20, 4),
                *_row_y(0.50, 0.20, 4, z0=C),
            ),  # parallel, not perpendicular
        ),
        (
            "dev18-dim-04",  # a triangular prism: 3 × 4 base, a ridge of 4 along the middle
            res(*grid(0.40, 0.25, 3, 4), *_row_y(0.45, 0.25, 4, z0=C)),
            res(*grid(0.40, 0.25, 3, 4), *_row_y(0.40, 0.25, 4, z0=C)),  # ridge on an edge
        ),
        (
            "dev18-seq-11",  # reflected in the front-back middle line: moved …
            res(*column(0.45, 0.20, 3)),
            res(*column(0.45, 0.40, 3)),  # left where it was
        ),
        (
            "dev18-seq-11",  # … or copied
            res(*column(0.45, 0.40, 3), *column(0.45, 0.20, 3)),
            res(*column(0.45, 0.40, 3), *column(0.45, 0.10, 3)),
        ),
        (
            "dev18-open-10",  # symmetric about the middle line y = 0.30
            res(*column(0.60, 0.20, 2), *column(0.60, 0.40, 2)),
            res(*column(0.60, 0.20, 2), *column(0.60, 0.40, 3)),
        ),
        (
            "dev18-rel-04",  # a 2-stack in the plate's centre well: standing on it …
            res(*grid(0.40, 0.25, 3, 3), *column(0.45, 0.30, 2, z0=C)),
            res(*grid(0.40, 0.25, 3, 3), *column(0.40, 0.25, 2, z0=C)),  # on a corner
        ),
        (
            "dev18-rel-04",  # … or down in the well
            res(*_without(grid(0.40, 0.25, 3, 3), (0.45, 0.30)), *column(0.45, 0.30, 2)),
            res(*_without(grid(0.40, 0.25, 3, 3), (0.45, 0.30)), *column(0.45, 0.30, 4)),
        ),
        (
            "dev18-seq-17",  # OCR: 4 steps rising left, the top step taken off
            res(*_stairs_y(0.45, 0.20, (1, 2, 3))),
            res(*_stairs_y(0.45, 0.20, (1, 2, 3, 4))),
        ),
        (
            "dev18-neg-07",  # three towers, all different, none over 4
            res(*column(0.30, 0.30, 1), *column(0.45, 0.30, 3), *column(0.60, 0.30, 4)),
            res(*column(0.30, 0.30, 2), *column(0.45, 0.30, 2), *column(0.60, 0.30, 3)),
        ),
        (
            "dev18-open-09",  # any prism: a staircase extruded 3 wide
            res(*[c for y in (0.25, 0.30, 0.35) for c in _stairs_x(0.40, y, (1, 2, 3))]),
            res(*_pyr(0.40, 0.25, 3)),
        ),
        (
            "dev18-bad-13",  # OCR "l5" = 15 levels, past the cell: refuse, or say what changed
            {"status": "error", "layout": None},
            res(*column(0.45, 0.30, 5)),
        ),
    ],
)
def test_dev18_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev18(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


# ---------------------------------------------------------------- dev19


def _dev19(case_id: str) -> Case:
    return next(c for c in DEV19 if c.id == case_id)


def _hurdle_y(x, y, legs):
    """Two posts `legs` high at y ± one cube, a beam across them along y."""
    return [*column(x, y - C, legs), *column(x, y + C, legs), beam(x, y, C * legs + C / 2, YAW90)]


def _lifted(objs, dz):
    return [{**c, "position": [*c["position"][:2], c["position"][2] + dz]} for c in objs]


_TIERS_432 = [  # three tiers, two layers each: 4 by 4, 3 by 3, 2 by 2, centred on (0.475, 0.275)
    *grid(0.40, 0.20, 4, 4, layers=2),
    *grid(0.425, 0.225, 3, 3, layers=2, z0=2 * C),
    *grid(0.45, 0.25, 2, 2, layers=2, z0=4 * C),
]
_WALL5X2_Y = [*_row_y(0.45, 0.20, 5), *_row_y(0.45, 0.20, 5, z0=C)]  # y 0.20–0.40


@pytest.mark.parametrize(
    ("case_id", "right", "wrong"),
    [
        (
            "dev19-rel-04",  # podium in separate blocks: second on the left (+y), third right
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 3), *column(0.45, 0.20, 1)),
            res(*column(0.45, 0.40, 1), *column(0.45, 0.30, 3), *column(0.45, 0.20, 2)),
        ),
        (
            "dev19-rel-04",  # … or one stepped block, heights 2, 3, 1 from left to right
            res(*_stairs_y(0.45, 0.25, (1, 3, 2))),
            res(*_stairs_y(0.45, 0.25, (2, 3, 1))),  # mirrored: second place on the right
        ),
        (
            "dev19-seq-05",  # "touching it on the left": one block only
            res(*_stairs_y(0.45, 0.25, (1, 3, 2))),
            res(*column(0.45, 0.40, 2), *column(0.45, 0.30, 3), *column(0.45, 0.20, 1)),
        ),
        (
            "dev19-num-04",  # gold 4 in the middle, silver 3 on its left, bronze 2 on its right
            res(*_stairs_y(0.45, 0.25, (2, 4, 3))),
            res(*_stairs_y(0.45, 0.25, (3, 4, 2))),
        ),
        (
            "dev19-dim-01",  # tiers 4 by 4, 3 by 3, 2 by 2, two layers each
            res(*_TIERS_432),
            res(*_TIERS_432[:41], *_lifted(_TIERS_432[50:], -C)),  # middle tier one layer
        ),
        (
            "dev19-seq-01",  # a 1 by 1 tier two layers high on the middle of a 3 by 3 by 2
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.45, 0.30, 2, z0=2 * C)),
            res(*grid(0.40, 0.25, 3, 3, layers=2), *column(0.40, 0.25, 2, z0=2 * C)),
        ),
        (
            "dev19-typo-09",  # "a weding cake with 3 teirs, each one smaler"
            res(*_pyr(0.40, 0.25, 3)),
            res(*_PYR2),
        ),
        (
            "dev19-seq-03",  # three tiers less the top one: two tiers, here two layers each
            res(*grid(0.40, 0.25, 3, 3, layers=2), *grid(0.425, 0.275, 2, 2, layers=2, z0=2 * C)),
            res(*_pyr(0.40, 0.25, 3)),  # the top tier left on
        ),
        (
            "dev19-num-06",  # '{"towers": [3, 5, 2]}': three towers, any arrangement
            res(*column(0.30, 0.20, 3), *column(0.60, 0.45, 5), *column(0.45, 0.30, 2)),
            res(*column(0.30, 0.20, 3), *column(0.60, 0.45, 5), *column(0.45, 0.30, 5)),
        ),
        (
            "dev19-num-17",  # gap_cm=10: 10 cm clear (2 cubes) …
            res(*[c for j in range(3) for c in column(0.45, 0.15 + 0.15 * j, 4)]),
            res(*[c for j in range(3) for c in column(0.45, 0.10 + 0.20 * j, 4)]),  # 3 clear
        ),
        (
            "dev19-num-17",  # … or 10 cm centre to centre (1 cube clear)
            res(*[c for j in range(3) for c in column(0.45, 0.20 + 0.10 * j, 4)]),
            res(*[c for j in range(3) for c in column(0.45, 0.20 + 0.10 * j, 3)]),
        ),
        (
            "dev19-typo-03",  # "to towrs of for": two towers of four
            res(*column(0.45, 0.20, 4), *column(0.45, 0.40, 4)),
            res(*column(0.45, 0.30, 4)),
        ),
        (
            "dev19-num-10",  # "ate blox in a rowe": a row of eight
            res(*_row_y(0.45, 0.10, 8)),
            res(*_row_y(0.45, 0.10, 5)),
        ),
        (
            "dev19-rel-10",  # "rite next to it tuching": one structure, columns of 6 and 2
            res(*column(0.45, 0.30, 6), *column(0.45, 0.35, 2)),
            res(*column(0.45, 0.30, 6), *column(0.45, 0.40, 2)),
        ),
        (
            "dev19-dim-06",  # a goal 2 wide, posts 3: a beam bearing on both posts …
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3), beam(0.45, 0.275, 0.175, YAW90)),
            res(*column(0.45, 0.25, 3), *column(0.45, 0.35, 3), beam(0.45, 0.30, 0.175, YAW90)),
        ),
        (
            "dev19-dim-06",  # … or a crossbar of four cubes
            res(*column(0.45, 0.20, 3), *column(0.45, 0.35, 3), *_row_y(0.45, 0.20, 4, z0=3 * C)),
            res(*column(0.45, 0.20, 2), *column(0.45, 0.35, 2), *_row_y(0.45, 0.20, 4, z0=2 * C)),
        ),
        (
            "dev19-rel-06",  # two hurdles "two cubes high", 3 clear along x: legs of 2 …
            res(*_hurdle_y(0.30, 0.30, 2), *_hurdle_y(0.50, 0.30, 2)),
            res(*_hurdle_y(0.30, 0.30, 2), *_hurdle_y(0.45, 0.30, 2)),  # 2 clear
        ),
        (
            "dev19-rel-06",  # … or legs of 1 under a bar whose top is 2 cubes up
            res(*_hurdle_y(0.30, 0.30, 1), *_hurdle_y(0.50, 0.30, 1)),
            res(*_hurdle_y(0.30, 0.30, 3), *_hurdle_y(0.50, 0.30, 3)),
        ),
        (
            "dev19-neg-11",  # three hurdles, the middle one two bare posts
            res(
                *_hurdle_y(0.30, 0.30, 2),
                *column(0.45, 0.25, 2),
                *column(0.45, 0.35, 2),
                *_hurdle_y(0.60, 0.30, 2),
            ),
            res(*_hurdle_y(0.30, 0.30, 2), *_hurdle_y(0.45, 0.30, 2), *_hurdle_y(0.60, 0.30, 2)),
        ),
        (
            "dev19-rel-13",  # a 3-tower touching the wall on its right (-y)
            res(*_WALL5X2_Y, *column(0.45, 0.15, 3)),
            res(*_WALL5X2_Y, *column(0.45, 0.45, 3)),
        ),
        (
            "dev19-bad-09",  # 12 tiers: past the cell; refuse, or say what changed
            {"status": "error", "layout": None},
            res(*_pyr(0.40, 0.25, 3)),
        ),
        (
            "dev19-bad-13",  # wholly in Hindi: a noted reading is honest, a silent one is not
            res(*column(0.45, 0.30, 5), notes=["read as Hindi: a tower of five cubes"]),
            res(*column(0.45, 0.30, 5)),
        ),
    ],
)
def test_dev19_predicates_on_hand_built_layouts(case_id, right, wrong):
    case = _dev19(case_id)
    assert case.accept(right) is None
    assert case.accept(wrong) is not None


def test_a_canopys_beam_roof_is_told_from_legs_of_another_height():
    from sdi.pipeline import plan

    canopy = k._boxes_or_reason(plan("a canopy with legs 2 high").to_json_dict())
    bridge = k._boxes_or_reason(plan("a bridge with pillars 2 high").to_json_dict())
    assert k.beam_roof(4, 2)(canopy) is None
    assert k.beam_roof(4, 3)(canopy) is not None and k.beam_roof(4, 2)(bridge) is not None
