"""FROZEN test set for the language front end — do not edit, do not tune on it.

Written before any results were seen, independently of the Specifier's grammar. Its sha256 is
recorded in `tests/test_language_sets.py`, so any change shows up in review. Tune on
`language_dev`; report this set once.
"""

from __future__ import annotations

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.boxes import Boxes
from sdi.bench.language_checks import Case, Reason

T = k.tower
one = k.one
REL, SEQ, NUM, DIM, NEG, TYP = "relation", "sequence", "numbers", "dimensions", "negation", "typo"
WO, FIL, REG, OPEN, BAD = "word_order", "filler", "region", "open", "bad_input"


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"test-{id_}", phenomenon=phenomenon, text=text, accept=accept)


def _sturdy(bs: Boxes) -> Reason:
    """At least 2 x 2 at the base, no narrower at the bottom than at the top, 3+ cubes high."""
    counts = bx.level_counts(bs)
    if bx.thickness_cubes(bs) < 3 or bx.plan_dims(bs)[0] < 2 or counts[0] < counts[-1]:
        return f"not sturdy-looking: levels {counts}, footprint {bx.plan_dims(bs)}"
    return None


def _stair_then_tower(bs: Boxes) -> Reason:
    """Steps 1, 2, …, n then a 4-cube tower: beside the top step (profile 1..n, 4 with
    n ≥ 2) or standing on step n + 1 (profile 1..n, n + 5 with n ≥ 1); every column full."""
    fx, fy = bx.footprint_cubes(bs)
    axis = 0 if fx >= fy else 1
    prof = bx.step_profile(bs, axis)
    if prof and prof[0] > prof[-1]:
        prof = prof[::-1]
    n = len(prof) - 1
    ok = n >= 1 and prof[:-1] == list(range(1, n + 1))
    ok = ok and ((prof[-1] == 4 and n >= 2) or prof[-1] == n + 5)
    if not ok:
        return f"height profile {prof}, want steps then a 4-cube tower"
    if len(bx.voxels(bs)) != sum(prof) * (fy, fx)[axis]:
        return "columns not full"
    return None


def _modest(bs: Boxes) -> Reason:
    return None if 2 <= len(bs) <= 12 else f"{len(bs)} parts for a modest structure"


CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "stand a pillar of three cubes on top of a 2 by 2 base",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    _c("rel-02", REL, "a fence of cubes surrounding a 2-cube pillar", k.around(T(2))),
    _c(
        "rel-03",
        REL,
        "two 4-cube columns with a lintel beam resting across them",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "rel-04",
        REL,
        "a wall with a 3-cube stack beside it, on the right",
        k.beside(T(3), k.wall(), "right"),
    ),
    _c(
        "rel-05",
        REL,
        "set a short row of 3 between two towers of 4",
        k.any_of(k.between_(k.row(3), T(4)), one(k.profile(4, 1, 1, 1, 4))),
    ),
    _c(
        "rel-06", REL, "a staircase going up to a tower of 4 at its top end", one(_stair_then_tower)
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "put down five cubes in a line, then another line of five on them",
        one(k.block(1, 5, 2)),
    ),
    _c(
        "seq-02",
        SEQ,
        "first make a 4 by 4 layer, then a 3 by 3 layer on it, then 2 by 2, and finish "
        "with one cube",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "build a 2x3 slab and repeat that layer twice more on top",
        one(k.block(2, 3, 3)),
    ),
    _c("seq-04", SEQ, "make a pillar of 2 cubes. after that add 3 more cubes on it", one(T(5))),
    _c(
        "seq-05",
        SEQ,
        "one tower of 3 first, then another of 3 a bit to its left",
        k.beside(T(3), T(3), "left"),
    ),
    _c(
        "seq-06",
        SEQ,
        "start a ring of cubes, and once the first layer is done, put a second layer "
        "exactly like it on top",
        one(k.ring_of(high=2)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "three seven-cube pillars", k.each(3, T(7))),
    _c("num-02", NUM, "nine cubes in one stack", one(T(9))),
    _c(
        "num-03",
        NUM,
        "a table: four legs two cubes high and a top over them",
        one(k.canopy(4, 2, 2)),
    ),
    _c("num-04", NUM, "twelve cubes as a block two wide and three long", one(k.block(2, 3, 2))),
    _c("num-05", NUM, "a couple of towers, 4 cubes each", k.each(2, T(4))),
    _c("num-06", NUM, "two rows of three cubes, not touching", k.each(2, k.row(3))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a block four wide, two deep and three high", one(k.block(4, 2, 3))),
    _c("dim-02", DIM, "a slab 3 across and 4 deep, a single cube thick", one(k.block(3, 4, 1))),
    _c("dim-03", DIM, "a 3 by 2 grid, three layers", one(k.block(3, 2, 3))),
    _c("dim-04", DIM, "a wall 0.25 m long and 0.15 m tall", one(k.wall(5, 3))),
    _c("dim-05", DIM, "a square pad of 15 cm by 15 cm, two layers", one(k.block(3, 3, 2))),
    _c("dim-06", DIM, "a pillar 35 cm high", one(T(7))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "lay four cubes flat next to each other, do not pile them up",
        k.any_of(one(k.row(4)), one(k.block(2, 2, 1)), k.each(4, T(1))),
    ),
    _c("neg-02", NEG, "a stack, not too high please", one(T(lo=2, hi=5))),
    _c(
        "neg-03",
        NEG,
        "a tower of 3 that is not on the right side",
        one(T(3), k.not_(k.region("right"), "on the right")),
    ),
    _c(
        "neg-04",
        NEG,
        "a 4 by 4 square of cubes with the inside left empty",
        one(k.ring_of(high=1, inner=(2, 2)), k.parts(12)),
    ),
    _c("neg-05", NEG, "a pyramid that isn't flat, a proper 3-D one", one(k.pyramid(lo=2), k.broad)),
    _c("neg-06", NEG, "a row of 6 cubes, no gaps and no second layer", one(k.row(6))),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a smal brigde", one(k.bridge(lo=1, hi=2))),
    _c("typo-02", TYP, "a tower of 5 cubse", one(T(5))),
    _c("typo-03", TYP, "a stairacse of four steps", one(k.staircase(4))),
    _c("typo-04", TYP, "a 2 by 4 grdi", one(k.block(2, 4, 1))),
    _c("typo-05", TYP, "a pyarmid on the rihgt", one(k.pyramid(lo=2), k.region("right"))),
    _c("typo-06", TYP, "an enclosuer with a towre of 2 inside", k.around(T(2))),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "Front right: a row of 3. Back left: a 2-step staircase.",
        k.structures(
            k.all_of(k.row(3), k.region("front right")),
            k.all_of(k.staircase(2), k.region("back left")),
        ),
    ),
    _c(
        "wo-02",
        WO,
        "On the right side of the table, a 3 by 3 grid.",
        one(k.block(3, 3, 1), k.region("right")),
    ),
    _c("wo-03", WO, "Six cubes high is the column I need.", one(T(6))),
    _c("wo-04", WO, "With two 3-high pillars underneath it, a beam.", one(k.bridge(3, pillars=2))),
    _c(
        "wo-05",
        WO,
        "At the back of the cell, a wall of length 4.",
        one(k.wall(4), k.region("back")),
    ),
    _c("wo-06", WO, "Inside a ring of cubes: one tower of 2.", k.around(T(2))),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "Hi there, would you mind stacking 5 cubes into a tower? Cheers.", one(T(5))),
    _c(
        "fil-02",
        FIL,
        "ok team, for the customer visit we want a 4-step staircase, nothing else, thanks",
        one(k.staircase(4)),
    ),
    _c(
        "fil-03",
        FIL,
        "If possible, and only if it's safe, put a 2 by 2 patch on the left. Much appreciated.",
        one(k.block(2, 2, 1), k.region("left")),
    ),
    _c(
        "fil-04",
        FIL,
        "sooo... a bridge over two towers of 3? pretty please",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "fil-05",
        FIL,
        "We're filming later, so: a castle. Make it look nice. Thank you in advance!",
        one(k.castle),
    ),
    _c(
        "fil-06",
        FIL,
        "note for the night shift: build a row of 6 cubes and then stop",
        one(k.row(6)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "a tower of 4 on the right", one(T(4), k.region("right"))),
    _c(
        "reg-02",
        REG,
        "a 3 by 2 grid in the front left corner",
        one(k.block(3, 2, 1), k.region("front left")),
    ),
    _c(
        "reg-03",
        REG,
        "a staircase of 3 steps near the back edge",
        one(k.staircase(3), k.region("back")),
    ),
    _c("reg-04", REG, "a 3-cube column at x = 0.35, y = 0.45", one(T(3), k.near(0.35, 0.45))),
    _c(
        "reg-05",
        REG,
        "a ring right in the middle of the workspace",
        one(k.ring, k.region("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "a tower of 2 at the back and a tower of 5 at the front",
        k.any_of(
            k.structures(k.all_of(T(2), k.region("back")), k.all_of(T(5), k.region("front"))),
            k.beside(T(2), T(5), "back", max_gap=0.5),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "something sturdy-looking and tallish", one(_sturdy)),
    _c("open-02", OPEN, "a modest little structure", k.layout(_modest)),
    _c("open-03", OPEN, "a really tall column", one(T(lo=6, hi=10))),
    _c("open-04", OPEN, "a short little stack", one(T(lo=2, hi=3))),
    _c("open-05", OPEN, "a big staircase", one(k.staircase(lo=4))),
    _c("open-06", OPEN, "a long, low row", one(k.row(lo=5))),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "xkcd blorp flim flam", k.refused),
    _c("bad-02", BAD, "construye una torre de cuatro cubos", k.honest(one(T(4)))),
    _c(
        "bad-03",
        BAD,
        "a 2-cube stack that is 6 cubes tall",
        k.honest(k.any_of(one(T(2)), one(T(6)))),
    ),
    _c("bad-04", BAD, "a wall 1000 cubes long", k.honest(one(k.wall()))),
    _c("bad-05", BAD, "make a tower of 3 " + "and also " * 240 + "thanks", k.honest(one(T(3)))),
    _c("bad-06", BAD, "?!?! ... ;;;", k.refused),
)
