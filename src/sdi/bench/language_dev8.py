"""An eighth development set for the language front end (dev8): the robot cell at work.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev7` (no command shared with
any set, see tests). The commands come from five kinds of people who type into a working robot
cell:

* a production-line setter doing changeovers ("changeover to job 7741", "same as last shift");
* a maintenance technician on a phone keyboard — no capitals, typos, abbreviations ("2x",
  "pcs", "ht", "cnr", "w/", "@");
* a non-native English speaker — articles dropped, verb last, odd word order;
* a manager writing long, polite, email-like requests;
* a trainer giving numbered, step-by-step instructions to trainees.

About 65 % ordinary (one or two structures, a size, a place, one relation or a two-step
sequence, a negation, a typo, a unit) and 35 % harder: relations between structures (on top of,
beside with a side and a gap, around, between, joined by a beam), sequences ("first … then …",
"no wait, 7", "then remove the top layer"), numbers attached to the right thing ("3 stacks of 4
pcs", "a pyramid from thirty cubes"), comparisons ("pillars one cube taller than the left
one's"), references ("an identical block next to it"), distributive phrases ("a tower of two on
each of its four corners"), open descriptions and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the IRB120 at x = 0, y = 0.30).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

Rel = k.Rel


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev8-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _leg_gap(n: int) -> k.Check:
    """Exactly two supports under the top piece, `n` cubes (± 1.5 cm) apart."""

    def f(bs: k.Boxes) -> k.Reason:
        legs = bx.roof_legs(bs)
        if legs is None or len(legs) != 2:
            return "not two supports under a top piece"
        gap = bx.separation(legs[0], legs[1])
        if abs(gap - n * bx.CUBE) > 0.015:
            return f"supports {gap:.3f} m apart, want {n} cube(s)"
        return None

    return f


def _tight_fence(h: int) -> k.Check:
    """A one-high 3x3 outline of cubes laid tight round an `h`-cube tower in its middle cell
    (one structure: the tower touches the fence)."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.dims(3, 3)(bs) or k.only_cubes(bs) or k.levels(9, *[1] * (h - 1))(bs)
        if r:
            return r
        (x0, y0, _), _ = bx.bounds(bs)
        mid = [c for c in bx.columns(bs) if _at(c, x0 + 0.075, y0 + 0.075)]
        return None if mid and len(mid[0]) == h else f"the middle column is not {h} high"

    return f


def _at(col: k.Boxes, x: float, y: float) -> bool:
    cx, cy, _ = col[0].centre
    return abs(cx - x) <= 0.01 and abs(cy - y) <= 0.01


def _min_side(n: int) -> k.Check:
    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        return None if got[0] >= n else f"footprint {got}, want ≥ {n} each way"

    return f


def _tower_set(lo: int, hi: int, rule: Callable[[list[int]], k.Reason]) -> k.Pred:
    """lo–hi separate single-column towers whose heights (in cubes) satisfy `rule`."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        bs = bx.boxes(result)
        if not bs:
            return "no layout"
        if not bx.in_workspace(bs):
            return "a part outside the workspace"
        comps = bx.components(bs)
        if not lo <= len(comps) <= hi:
            return f"{len(comps)} structures, want {lo}–{hi}"
        for g in comps:
            r = k.tower()(g)
            if r:
                return r
        return rule(sorted(bx.thickness_cubes(g) for g in comps))

    return f


def _sum_distinct(total: int) -> Callable[[list[int]], k.Reason]:
    def rule(hs: list[int]) -> k.Reason:
        if len(set(hs)) != len(hs):
            return f"heights {hs} repeat"
        return None if sum(hs) == total else f"heights {hs} add up to {sum(hs)}, want {total}"

    return rule


def _same_height(least: int) -> Callable[[list[int]], k.Reason]:
    def rule(hs: list[int]) -> k.Reason:
        if len(set(hs)) != 1:
            return f"heights {hs} differ"
        return None if hs[0] >= least else f"stacks {hs[0]} high, want ≥ {least}"

    return rule


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE = k.shape_letter("L")

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "tower 3 cube put on top of slab 2 by 2",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    _c(
        "rel-02",
        REL,
        "changeover: 4 high tower to the left of a 3x3 pad, one cube gap",
        k.pair(T(4), k.block(3, 3, 1), k.gap_of(1, _L)),
    ),
    _c(
        "rel-03",
        REL,
        "Could we have two bridges side by side, the one on the right with pillars one cube "
        "taller than the left one's? Left pillars 2.",
        k.pair(k.bridge(3, pillars=2), k.bridge(2, pillars=2), k.on_side(_R)),
    ),
    _c(
        "rel-04",
        REL,
        "ring 6x6 w/ a 2x2 block 2 ht in the middle of it",
        # "6x6" as the outside (4x4 floor) or as the floor (8x8 outside)
        k.around(k.block(2, 2, 2), k.all_of(k.ring, k.any_of(k.dims(6, 6), k.dims(8, 8)))),
    ),
    _c(
        "rel-05",
        REL,
        "two tower of 5, and beam lying across top of them",
        one(k.bridge(5, pillars=2)),
    ),
    _c(
        "rel-06",
        REL,
        "2x2 column 4 high between two 3-high towers",
        k.between_(k.block(2, 2, 4), T(3)),
    ),
    _c(
        "rel-07",
        REL,
        "Exercise three: lay a 3x3 slab and set one cube on each of its four corners.",
        one(k.base(3, 3), k.levels(9, 4), k.corner_columns(1)),
    ),
    _c(
        "rel-08",
        REL,
        "2 towers 3ht, 2 cubes apart, one in front of the other",
        k.pair(T(3), T(3), k.gap_of(2, _B)),
    ),
    _c(
        "rel-09",
        REL,
        "We would like the staircase (four steps) placed to the right of the bridge, with the "
        "bridge pillars three cubes high.",
        k.beside(k.staircase(4), k.bridge(3, pillars=2), _R),
    ),
    _c(
        "rel-10",
        REL,
        "around tower of 4, make fence, fence one high",
        # a free tower, or a 3x3 fence laid tight round it
        k.any_of(k.around(T(4), k.ring_of(high=1)), one(_tight_fence(4))),
    ),
    _c(
        "rel-11",
        REL,
        "same as last shift: 3x3x3 block, plus an identical block on its left with 1 cube gap",
        k.pair(k.block(3, 3, 3), k.block(3, 3, 3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-12",
        REL,
        "row of 5 left-right, and a 3ht tower on the middle cube",
        # three cubes on top of the middle cube, or the middle cube counted in the tower
        one(k.any_of(k.lr_profile(1, 1, 4, 1, 1), k.lr_profile(1, 1, 3, 1, 1))),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Step 1: a 4x4 slab. Step 2: a 2x2 slab centred on it. Step 3: one cube on the very top.",
        one(k.pyramid_counts(16, 4, 1)),
    ),
    _c("seq-02", SEQ, "tower 5ht... no wait 7", one(T(7))),
    _c(
        "seq-03",
        SEQ,
        "changeover job 2: first a wall 4 long 2 high, then a second identical wall 2 cubes in "
        "front of it",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.gap_of(2, _F)),
    ),
    _c(
        "seq-04",
        SEQ,
        "first make row of 3 cube, after put same row on it, and again one more",
        one(k.wall(3, 3)),
    ),
    _c(
        "seq-05",
        SEQ,
        "To start, a bridge on 2-high pillars. Once that is done, please add a tower of three "
        "to its left.",
        k.beside(T(3), k.bridge(2, pillars=2), _L),
    ),
    _c(
        "seq-06",
        SEQ,
        "Build a 3-step staircase. Next, build a second staircase exactly like it, one cube to "
        "its right.",
        k.pair(k.staircase(3), k.staircase(3), k.gap_of(1, _R)),
    ),
    _c(
        "seq-07",
        SEQ,
        "4x4 ring 1ht then add 1 more layer on it",
        one(k.ring_of(high=2), k.dims(4, 4)),
    ),
    _c("seq-08", SEQ, "block 2x2x3, then remove top layer", one(k.block(2, 2, 2))),
    _c(
        "seq-09",
        SEQ,
        "tower of 4 make. then on the right of it, a tower double so high",
        k.any_of(k.pair(T(8), T(4), k.on_side(_R)), one(k.lr_profile(4, 8))),
    ),
    _c(
        "seq-10",
        SEQ,
        "First, lay out a 3x5 grid at the front of the table; afterwards, place a tower of two "
        "cubes on each of its four corners.",
        one(k.base(3, 5), k.levels(15, 4, 4), k.corner_columns(2), reg(_F)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Place a row of five cubes. Now take the two end cubes away.",
        one(k.row(3)),
    ),
    _c("seq-12", SEQ, "pyramid 3 lvls, then move it to the left side", one(k.pyramid(3), reg(_L))),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "3 stacks of 4 pcs", k.each(3, T(4))),
    _c(
        "num-02",
        NUM,
        "five tower, each one have two cube",
        k.any_of(k.each(5, T(2)), one(k.wall(5, 2))),
    ),
    _c(
        "num-03",
        NUM,
        "two rows of six, side by side",
        k.any_of(k.each(2, k.row(6)), one(k.block(2, 6, 1))),
    ),
    _c(
        "num-04",
        NUM,
        "I'd like a pyramid built from thirty cubes",
        # 16 + 9 + 4 + 1, or 25 + 4 + 1
        one(k.pyramid(), k.parts(30)),
    ),
    _c("num-05", NUM, "Build half a dozen cubes into one single tower.", one(T(6))),
    _c("num-06", NUM, "2x tower 3ht + 1x tower 5ht", k.structures(T(3), T(3), T(5))),
    _c("num-07", NUM, "a wall of 12 cubes, 3 per course", one(k.wall(3, 4))),
    _c("num-08", NUM, "4 slabs 2x2, single layer", k.each(4, k.block(2, 2, 1))),
    _c(
        "num-09",
        NUM,
        "three towers whose heights add up to nine, no two the same",
        _tower_set(3, 3, _sum_distinct(9)),
    ),
    _c(
        "num-10",
        NUM,
        "A staircase of five steps, and a second one with two fewer steps.",
        k.structures(k.staircase(5), k.staircase(3)),
    ),
    _c(
        "num-11",
        NUM,
        "ring 4x4 3 ht, 2 of them",
        k.each(2, k.all_of(k.ring_of(high=3), k.dims(4, 4))),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "tower, h = 350 mm", one(T(7))),
    _c("dim-02", DIM, "slab 20x20cm", one(k.block(4, 4, 1))),
    _c("dim-03", DIM, "wall long 40 centimetre, high 15 centimetre", one(k.wall(8, 3))),
    _c("dim-04", DIM, "a tower 8 inches tall", one(T(4))),
    _c(
        "dim-05",
        DIM,
        "Build a platform 15 cm wide, 20 cm deep and 10 cm high.",
        one(k.block_xy(4, 3, 2)),
    ),
    _c("dim-06", DIM, "stairs 4 steps, total ht 20cm", one(k.staircase(4))),
    _c("dim-07", DIM, "ring, outside 0.3 m x 0.3 m", one(k.ring, k.dims(6, 6))),
    _c(
        "dim-08",
        DIM,
        "pyramid, the base is 25 cm each side",
        one(k.pyramid(lo=2), k.base(5, 5)),
    ),
    _c(
        "dim-09",
        DIM,
        "a wall that is half a metre long and ten centimetres thick, two cubes tall",
        one(k.block(2, 10, 2)),
    ),
    _c(
        "dim-10",
        DIM,
        "Two towers, each 0.15 m tall, 0.1 m apart.",
        # 10 cm of clear space, or 10 cm between the centres
        k.any_of(k.pair(T(3), T(3), k.gap_of(2)), k.pair(T(3), T(3), k.gap_of(1))),
    ),
    _c(
        "dim-11",
        DIM,
        "bridge pillars 100mm ht gap 50mm",
        one(k.bridge(2, pillars=2), _leg_gap(1)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "tower 5 ht, not at the front",
        one(T(5), not_(reg(_F), "at the front")),
    ),
    _c("neg-02", NEG, "slab 3 by 3, no second layer", one(k.block(3, 3, 1))),
    _c(
        "neg-03",
        NEG,
        "a staircase, not too tall — no more than four steps",
        one(k.staircase(lo=2, hi=4)),
    ),
    _c("neg-04", NEG, "4 towers of 2 but don't let them touch each other", k.each(4, T(2))),
    _c(
        "neg-05",
        NEG,
        "Lay out a row of 6 cubes, but don't stack anything on it.",
        one(k.row(6)),
    ),
    _c(
        "neg-06",
        NEG,
        "ring 5x5 1ht dont put anything inside",
        one(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c(
        "neg-07",
        NEG,
        "pyramid 3 level but not on the right side",
        one(k.pyramid(3), not_(reg(_R), "on the right")),
    ),
    _c(
        "neg-08",
        NEG,
        "no beams please - a 3x3 patch of cubes only",
        one(k.block(3, 3, 1), k.only_cubes),
    ),
    _c("neg-09", NEG, "not 4, not 6 — tower of 5", one(T(5))),
    _c(
        "neg-10",
        NEG,
        "Make a row of 4 that does not run left to right; it should run away from the robot.",
        one(k.row(4), k.runs("x")),
    ),
    _c(
        "neg-11",
        NEG,
        "3x3 block 2ht, leave out the middle ones",
        one(k.dims(3, 3), k.ring_of(high=2, inner=(1, 1)), k.parts(16)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr 4 hgh on teh left", one(T(4), reg(_L))),
    _c("typo-02", TYP, "sqaure rign 5x5", one(k.ring, k.dims(5, 5))),
    _c("typo-03", TYP, "stiarcase 3 setps", one(k.staircase(3))),
    _c("typo-04", TYP, "2 towres 3ht, 1 cbue gap", k.pair(T(3), T(3), k.gap_of(1))),
    _c("typo-05", TYP, "brdige w/ pillers 4 hgih", one(k.bridge(4, pillars=2))),
    _c("typo-06", TYP, "slba 2x4 two layrs", one(k.block(2, 4, 2))),
    _c("typo-07", TYP, "pyramdi 2 lvl in teh middel", one(k.pyramid(2), reg("centre"))),
    _c("typo-08", TYP, "wal 6 lng 2 hi", one(k.wall(6, 2))),
    _c(
        "typo-09",
        TYP,
        "L shpae arms 4 n 3",
        # arms counted with the shared corner cube, or without it
        one(L_SHAPE, k.any_of(k.dims(3, 4), k.dims(4, 5))),
    ),
    _c(
        "typo-10",
        TYP,
        "cirlce of cubse arond a towr of 2",
        k.any_of(k.around(T(2)), one(_tight_fence(2))),
    ),
    _c("typo-11", TYP, "towr 3 ontop of 3x3 plate", one(k.on_top(T(3), k.block(3, 3, 1)))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "cubes six, in one column, please stack", one(T(6))),
    _c(
        "wo-02",
        WO,
        "on the back side, the wall of four long make",
        one(k.any_of(k.wall(4), k.row(4)), reg(_B)),
    ),
    _c("wo-03", WO, "big pyramid I want, level four", one(k.pyramid(4))),
    _c("wo-04", WO, "of 3 by 3, block, height 3", one(k.block(3, 3, 3))),
    _c(
        "wo-05",
        WO,
        "bridge below, tower of 2 cube above on it",
        one(k.on_top(T(2), k.bare_bridge)),
    ),
    _c(
        "wo-06",
        WO,
        "left from tower of 3, pyramid of 2 level",
        k.beside(k.pyramid(2), T(3), _L),
    ),
    _c(
        "wo-07",
        WO,
        "stairs 5 step going up to back",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c(
        "wo-08",
        WO,
        "in front right corner a 2x2 slab put",
        one(k.block(2, 2, 1), reg("front right")),
    ),
    _c(
        "wo-09",
        WO,
        "a ring 4x4, inside it nothing, height of two",
        one(k.ring_of(high=2, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c("wo-10", WO, "rows 2, each of cubes 5, with gap 1", k.pair(k.row(5), k.row(5), k.gap_of(1))),
    _c("wo-11", WO, "high 4, wide 3: the wall", one(k.wall(3, 4))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi team, following up on yesterday's meeting — could the cell please build a tower of "
        "four cubes for the customer demo? Thanks in advance, Karen",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "changeover to job 7741. old layout cleared. new: row of 5 cubes",
        one(k.row(5)),
    ),
    _c(
        "fil-03",
        FIL,
        "Alright everyone, eyes on the screen. We'll begin with something easy: a 2 by 2 slab.",
        one(k.block(2, 2, 1)),
    ),
    _c(
        "fil-04",
        FIL,
        "ok robot back online after e-stop reset, pls do bridge pillars 2ht thx",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-05",
        FIL,
        "Dear all, as discussed in the Q3 planning session, we want to show the visitors from "
        "the board what the cell can do. Nothing fancy: a pyramid, three levels, somewhere in "
        "the middle of the table. Let me know if there are any issues. Best regards, Martin",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-06",
        FIL,
        "hello, excuse me, i am new here, i like to have a staircase with 4 step please, thank you",
        one(k.staircase(4)),
    ),
    _c(
        "fil-07",
        FIL,
        "shift B handover: cell idle, gripper checked OK. next job is a 3 high wall, 5 long",
        one(k.wall(5, 3)),
    ),
    _c(
        "fil-08",
        FIL,
        "Good. Now for the second exercise of today's training - and remember, safety glasses "
        "on - build a ring of cubes, 4 by 4, one high.",
        one(k.ring_of(high=1), k.dims(4, 4)),
    ),
    _c(
        "fil-09",
        FIL,
        "Per the customer's spec sheet (rev C, attached), the deliverable is a 2x3 block, 2 "
        "layers tall. Please confirm once built.",
        one(k.block(2, 3, 2)),
    ),
    _c("fil-10", FIL, "fyi conveyor 2 still down. anyway 3 towers 2ht", k.each(3, T(2))),
    _c(
        "fil-11",
        FIL,
        "ok lads, quick one before break: L shape, arms of 4",
        one(L_SHAPE, k.any_of(k.dims(4, 4), k.dims(5, 5))),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower 3 at x=0.5 y=0.2", one(T(3), k.near(0.5, 0.2))),
    _c("reg-02", REG, "slab 2x2 back left cnr", one(k.block(2, 2, 1), reg("back left"))),
    _c(
        "reg-03",
        REG,
        "pyramid 2 level in the corner front left",
        one(k.pyramid(2), reg("front left")),
    ),
    _c(
        "reg-04",
        REG,
        "Could the wall (six long, two high) go along the right-hand edge of the table, "
        "running front to back?",
        one(k.wall(6, 2), k.runs("x"), reg(_R)),
    ),
    _c(
        "reg-05",
        REG,
        "Place a 3-step staircase in the exact centre of the work area.",
        one(k.staircase(3), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "ring 4x4 @ x 0.6 y 0.4",
        one(k.ring, k.dims(4, 4), k.near(0.6, 0.4)),
    ),
    _c(
        "reg-07",
        REG,
        "two towers of 4: one back right, one front left",
        k.structures(
            k.all_of(T(4), reg("back right")),
            k.all_of(T(4), reg("front left")),
        ),
    ),
    _c(
        "reg-08",
        REG,
        "at middle of table block 2x2x2, and at left edge tower 3",
        k.structures(
            k.all_of(k.block(2, 2, 2), reg("centre")),
            k.all_of(T(3), reg(_L)),
        ),
    ),
    _c(
        "reg-09",
        REG,
        "Please position a bridge with 3-high pillars towards the back of the cell.",
        one(k.bridge(3, pillars=2), reg(_B)),
    ),
    _c(
        "reg-10",
        REG,
        "Put a row of 4 cubes 10 cm in front of the centre, running left to right.",
        one(k.row(4), k.runs("y"), reg(_F), k.near(y=0.30, tol=0.05)),
    ),
    _c(
        "reg-11",
        REG,
        "cube in each cnr of the table + 1 in the middle",
        k.structures(
            k.all_of(T(1), reg("front left")),
            k.all_of(T(1), reg("front right")),
            k.all_of(T(1), reg("back left")),
            k.all_of(T(1), reg("back right")),
            k.all_of(T(1), reg("centre")),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "something that looks like a gateway for the lobby model",
        one(k.any_of(k.bridge(), k.arch, k.canopy())),
    ),
    _c(
        "open-02",
        OPEN,
        "a short, stubby tower",
        one(k.any_of(T(lo=2, hi=3), k.all_of(k.solid(2, 2), k.height(lo=2, hi=3)))),
    ),
    _c("open-03", OPEN, "big slab", one(k.full, k.height(hi=2), _min_side(4))),
    _c("open-04", OPEN, "something like small table", one(k.canopy(), k.long(hi=6))),
    _c(
        "open-05",
        OPEN,
        "a chunky cube built out of the small cubes",
        one(k.any_of(k.block(2, 2, 2), k.block(3, 3, 3), k.block(4, 4, 4))),
    ),
    _c(
        "open-06",
        OPEN,
        "a modest perimeter fence for a future exhibit",
        one(k.ring, k.low(3)),
    ),
    _c(
        "open-07",
        OPEN,
        "a long low wall",
        one(k.any_of(k.row(lo=5), k.wall(lo=5, high=2))),
    ),
    _c("open-08", OPEN, "tallest tower u can do", one(T(lo=8))),
    _c("open-09", OPEN, "castle, not big", one(k.castle, k.long(hi=7))),
    _c(
        "open-10",
        OPEN,
        "a couple of pillars with something across them",
        one(k.any_of(k.bridge(), k.arch)),
    ),
    _c(
        "open-11",
        OPEN,
        "a few separate stacks, all the same height",
        _tower_set(2, 6, _same_height(2)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "jjjjjjj kkk", k.refused),
    _c("bad-02", BAD, "bitte drei Würfel zu einem Turm stapeln, danke", k.honest(one(T(3)))),
    _c("bad-03", BAD, "tower 14 high", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-04", BAD, "Could you please make the robot faster next time?", k.honest()),
    _c("bad-05", BAD, "Build a row of minus three cubes.", k.honest(one(k.row(3)))),
    _c(
        "bad-06",
        BAD,
        "slab 20x20 cubes",
        k.honest(one(k.full, k.height(1))),
    ),
    _c(
        "bad-07",
        BAD,
        "the tower must be 3 high and also 5 high",
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c("bad-08", BAD, "ctrl+z the last job pls", k.honest()),
    _c("bad-09", BAD, "a ring at x = 1.2 m", k.honest(one(k.ring))),
    _c("bad-10", BAD, "?? .. ,, ??", k.refused),
    _c("bad-11", BAD, "Now put a cube underneath the table.", k.honest(one(T(1)))),
)
