"""A seventh development set for the language front end (dev7): the university lab.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev6` (no command shared with
any set, see tests). The commands come from people in a teaching and research lab — students
typing quickly, teaching assistants writing numbered lists, a researcher who thinks aloud in
run-on sentences, a visiting engineer with inches and metres — and are weighted about 65 %
ordinary to 35 % harder: corrections ("no wait, make it 4"), changes to the structure just
described ("then make the pillars one taller", "halve it"), references ("an identical one to its
right"), distributive phrases ("a tower at each end", "a cube on every corner"), comparisons
("the right one twice as tall as the left"), lists and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the IRB120 at x = 0, y = 0.30).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

Rel = k.Rel


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev7-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _on_side(side: str) -> Rel:
    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        got = bx.side_of(a, b)
        return None if got == side else f"A is {got} of B, want {side}"

    return rel


def _elbow(side_x: str, side_y: str) -> k.Check:
    """An L whose corner (elbow) cell is the footprint corner at `side_x` (front/back) and
    `side_y` (left/right)."""

    def f(bs: k.Boxes) -> k.Reason:
        if bx.letter(bs) != "L":
            return f"footprint letter {bx.letter(bs)}, want L"
        fx, fy = bx.footprint_cubes(bs)
        i = fx - 1 if side_x == _B else 0
        j = fy - 1 if side_y == _L else 0
        cs = bx.cells(bs)
        if (i, j) in cs and (fx - 1 - i, fy - 1 - j) not in cs:
            return None
        return f"the L's corner is not at the {side_x} {side_y}"

    return f


def _open_front(bs: k.Boxes) -> k.Reason:
    """A square outline with its back row complete and at least one cell missing from the
    front row (a ring left open on the side facing the robot)."""
    fx, fy = bx.footprint_cubes(bs)
    cs = bx.cells(bs)
    if k.ring(bs) is None:
        return "closed all round"
    if any((fx - 1, j) not in cs for j in range(fy)):
        return "back side not complete"
    if any((i, 0) not in cs or (i, fy - 1) not in cs for i in range(fx)):
        return "left or right side not complete"
    if all((0, j) in cs for j in range(fy)):
        return "front side not open"
    return None


def _has_side(n: int) -> k.Check:
    def f(bs: k.Boxes) -> k.Reason:
        got = bx.footprint_cubes(bs)
        return None if n in got else f"footprint {got}, no side of {n}"

    return f


def _towers_differ(lo: int, hi: int) -> k.Pred:
    """lo–hi separate towers, no two of the same height."""

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
        hs = [bx.thickness_cubes(g) for g in comps]
        return None if len(set(hs)) == len(hs) else f"heights {hs} repeat"

    return f


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE, U_SHAPE, T_SHAPE, CROSS = (k.shape_letter(s) for s in ("L", "U", "T", "cross"))

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "wall 5 long, 2 high, and stand a 4-tall tower at both ends of it",
        k.any_of(
            one(k.profile(4, 2, 2, 2, 4)),
            one(k.profile(4, 2, 2, 2, 2, 2, 4)),
            k.between_(k.wall(5, 2), T(4)),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "two towers side by side, the left one is 3 high and the right one twice as tall",
        k.any_of(
            k.pair(T(3), T(6), _on_side(_L)),
            one(k.lr_profile(3, 6)),
        ),
    ),
    _c(
        "rel-03",
        REL,
        "a cube on every corner of a 4x4 slab",
        one(k.base(4, 4), k.levels(16, 4), k.corner_columns(1)),
    ),
    _c("rel-04", REL, "a 5-cube tower between two L shapes", k.between_(T(5), L_SHAPE)),
    _c(
        "rel-05",
        REL,
        "the pyramid should sit in front of the castle",
        k.beside(k.pyramid(), k.castle, _F),
    ),
    _c(
        "rel-06",
        REL,
        "a 2x2x2 block with a ring of cubes going round it, not touching it",
        k.around(k.block(2, 2, 2)),
    ),
    _c("rel-07", REL, "a tower of 3 on top of another tower of 3", one(T(6))),
    _c(
        "rel-08",
        REL,
        "two rows of 5 left to right, one behind the other, a one-cube gap between them",
        k.pair(
            k.all_of(k.row(5), k.runs("y")),
            k.all_of(k.row(5), k.runs("y")),
            k.gap_of(1, _B),
        ),
    ),
    _c(
        "rel-09",
        REL,
        "a T and a cross next to each other, the T on the left",
        k.beside(T_SHAPE, CROSS, _L),
    ),
    _c(
        "rel-10",
        REL,
        "a 3x3 pad and along its back edge a wall 3 long, 2 high, standing on the pad",
        one(k.xprofile(1, 1, 3)),
    ),
    _c(
        "rel-11",
        REL,
        "a ring, and just outside it on the left a tower of 3",
        k.beside(T(3), k.ring, _L),
    ),
    _c(
        "rel-12",
        REL,
        "the taller of the two towers goes at the back - make them 2 and 5",
        k.any_of(k.beside(T(5), T(2), _B), one(k.xprofile(2, 5))),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "row of 3. no wait, make it 4", one(k.row(4))),
    _c(
        "seq-02",
        SEQ,
        "build a tower of 5, then put an identical one to its right",
        k.any_of(k.beside(T(5), T(5), _R), one(k.wall(2, 5), k.runs("y"))),
    ),
    _c(
        "seq-03",
        SEQ,
        "make a 4x2 slab; now stack a second one exactly on top of it",
        one(k.block(4, 2, 2)),
    ),
    _c(
        "seq-04",
        SEQ,
        "put down a staircase of 3. then give it a fourth step",
        one(k.staircase(4)),
    ),
    _c(
        "seq-05",
        SEQ,
        "first a 5x5 ring, one high, then a 3-cube tower in the middle of it",
        k.around(T(3), k.all_of(k.ring_of(high=1), k.dims(5, 5))),
    ),
    _c(
        "seq-06",
        SEQ,
        "build a 3x3x3 cube out of cubes, then take off the top layer",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "a tower of 2 at the front; after that a tower of 2 at the back; then one more of 2 "
        "halfway between them",
        k.between_(T(2), T(2)),
    ),
    _c(
        "seq-08",
        SEQ,
        "make an L with 3-cube arms, then turn it so its corner is at the back left",
        one(_elbow(_B, _L), k.dims(3, 3)),
    ),
    _c(
        "seq-09",
        SEQ,
        "put a 3-level pyramid in the centre. actually, move it further back",
        one(k.pyramid(3), reg(_B)),
    ),
    _c(
        "seq-10",
        SEQ,
        "row of 5 going left to right, then a second row of 5 on top, then a third",
        one(k.wall(5, 3), k.runs("y")),
    ),
    _c(
        "seq-11",
        SEQ,
        "build a bridge with 2-high pillars. then make the pillars one cube taller",
        one(k.bridge(3, pillars=2)),
    ),
    _c("seq-12", SEQ, "tower of 6... actually, halve it", one(T(3))),
    _c(
        "seq-13",
        SEQ,
        "a 2x2 pad, then the same pad again one cube to the right of it, not touching",
        k.pair(k.block(2, 2, 1), k.block(2, 2, 1), k.gap_of(1, _R)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "a wall, four courses of five", one(k.wall(5, 4))),
    _c("num-02", NUM, "a grid of three by four", one(k.block(3, 4, 1))),
    _c(
        "num-03",
        NUM,
        "a 2-level pyramid on a base of sixteen",
        one(k.pyramid(2), k.base(4, 4)),
    ),
    _c("num-04", NUM, "a pair of bridges, pillars 3 high", k.each(2, k.bridge(3, pillars=2))),
    _c(
        "num-05",
        NUM,
        "two rows, one of 7 and one of 2 fewer",
        k.any_of(
            k.structures(k.row(7), k.row(5)),
            one(k.dims(2, 7), k.parts(12), k.height(1)),
        ),
    ),
    _c(
        "num-06",
        NUM,
        "three towers - heights one, two, three",
        k.any_of(k.structures(T(1), T(2), T(3)), one(k.staircase(3))),
    ),
    _c("num-07", NUM, "8 steps in a staircase please", one(k.staircase(8))),
    _c("num-08", NUM, "3 slabs of 3 by 3, one layer each, separate", k.each(3, k.block(3, 3, 1))),
    _c("num-09", NUM, "a tower of nine minus four", one(T(5))),
    _c("num-10", NUM, "four towers, four cubes tall each", k.each(4, T(4))),
    _c("num-11", NUM, "a 5-by-5 ring, three high", one(k.ring_of(high=3), k.dims(5, 5))),
    _c("num-12", NUM, "a bridge on a pair of eight-high towers", one(k.bridge(8, pillars=2))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a tower 0.4 metres high", one(T(8))),
    _c("dim-02", DIM, "row of cubes, length approx 12 inches", one(k.row(6))),
    _c("dim-03", DIM, "a slab 30 cm by 10 cm by 5 cm", one(k.block(6, 2, 1))),
    _c("dim-04", DIM, "wall 250mm x 100mm (L x H)", one(k.wall(5, 2))),
    _c(
        "dim-05",
        DIM,
        "3-step staircase, each tread 50 mm deep and 100 mm wide",
        one(k.staircase(3), k.dims(2, 3)),
    ),
    _c(
        "dim-06",
        DIM,
        "a pyramid with a 35 cm base side",
        one(k.pyramid(lo=2), k.base(7, 7)),
    ),
    _c(
        "dim-07",
        DIM,
        "an enclosure with a clear space of 10 cm x 10 cm inside",
        one(k.ring_of(inner=(2, 2))),
    ),
    _c(
        "dim-08",
        DIM,
        "bridge: pillars 150 mm high, 100 mm apart",
        one(k.bridge(3, pillars=2)),
    ),
    _c("dim-09", DIM, "a 4 inch high tower", one(T(2))),
    _c(
        "dim-10",
        DIM,
        "a 30 cm tower on a 15 cm x 15 cm slab",
        one(k.any_of(k.on_top(T(6), k.block(3, 3, 1)), k.on_top(T(5), k.block(3, 3, 1)))),
    ),
    _c(
        "dim-11",
        DIM,
        "a row from left to right, 0.5 m long",
        one(k.row(10), k.runs("y")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower, 4 high, which shouldn't be at the back or the front",
        one(T(4), not_(reg(_B), "at the back"), not_(reg(_F), "at the front")),
    ),
    _c(
        "neg-02",
        NEG,
        "a 4x4 ring but not closed on the side facing the robot",
        one(k.dims(4, 4), _open_front),
    ),
    _c("neg-03", NEG, "no tower please, just a flat 2x6 slab", one(k.block(2, 6, 1))),
    _c(
        "neg-04",
        NEG,
        "5 steps, and they mustn't climb to the right",
        one(k.staircase(5), not_(k.rises(_R), "climbs to the right")),
    ),
    _c(
        "neg-05",
        NEG,
        "three 2-high towers with space between every one of them",
        k.each(3, T(2)),
    ),
    _c("neg-06", NEG, "make a 3x5 pad, no wait, not 3x5, 3x4", one(k.block(3, 4, 1))),
    _c("neg-07", NEG, "a wall of 4 x 3 with no cube missing", one(k.wall(4, 3))),
    _c(
        "neg-08",
        NEG,
        "a pyramid on a 4x4 base, but stop before the single top cube",
        one(k.any_of(k.pyramid_counts(16, 9, 4), k.pyramid_counts(16, 4))),
    ),
    _c("neg-09", NEG, "anything but a tower: let's have a 2x2x2 block", one(k.block(2, 2, 2))),
    _c(
        "neg-10",
        NEG,
        "not left, not right - in the middle: tower of 5",
        one(T(5), not_(reg(_L), "on the left"), not_(reg(_R), "on the right")),
    ),
    _c(
        "neg-11",
        NEG,
        "a bridge, don't make the pillars taller than 2",
        one(k.bridge(lo=1, hi=2)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "stak thre cubse on top of eachother", one(T(3))),
    _c("typo-02", TYP, "pyrmid on a 3x3 bsae plase", one(k.pyramid(lo=2), k.base(3, 3))),
    _c("typo-03", TYP, "a wall 5 lnog and 2 tal", one(k.wall(5, 2))),
    _c("typo-04", TYP, "an encloser 5 by 5", one(k.ring, k.dims(5, 5))),
    _c("typo-05", TYP, "tow towers, fuor high each", k.any_of(k.each(2, T(4)), one(k.wall(2, 4)))),
    _c("typo-06", TYP, "staircse w/ 4 steps on the rihgt", one(k.staircase(4), reg(_R))),
    _c("typo-07", TYP, "briddge, both pilars 3 hihg", one(k.bridge(3, pillars=2))),
    _c("typo-08", TYP, "make a U shpae with the cubse", one(U_SHAPE)),
    _c("typo-09", TYP, "a slab 2x3, 2 layres", one(k.block(2, 3, 2))),
    _c("typo-10", TYP, "towr of 5 up at teh frnot", one(T(5), reg(_F))),
    _c("typo-11", TYP, "a T-shpe, 3 acorss", one(T_SHAPE, _has_side(3))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "5 the tower should be, in height", one(T(5))),
    _c("wo-02", WO, "front right, tower of 2 please", one(T(2), reg("front right"))),
    _c("wo-03", WO, "bridge, 4-high pillars, two of them", one(k.bridge(4, pillars=2))),
    _c("wo-04", WO, "2 by 2 and 4 high, block", one(k.block(2, 2, 4))),
    _c(
        "wo-05",
        WO,
        "a cube, inside of a ring of 4 by 4",
        # a 4x4 outline leaves a 2x2 floor: the cube is free in it or touches the wall
        k.any_of(
            k.around(T(1), k.all_of(k.ring, k.any_of(k.dims(4, 4), k.dims(6, 6)))),
            one(k.dims(4, 4), k.parts(13), k.low(1), k.only_cubes),
        ),
    ),
    _c("wo-06", WO, "stairs - 6 of them", one(k.staircase(6))),
    _c(
        "wo-07",
        WO,
        "to the right of the tower of 3 — a wall 3 long, 3 high",
        k.beside(k.wall(3, 3), T(3), _R),
    ),
    _c("wo-08", WO, "of 4 levels, a pyramid, on the left", one(k.pyramid(4), reg(_L))),
    _c("wo-09", WO, "3 across, 5 back, flat: a pad", one(k.block_xy(5, 3, 1))),
    _c(
        "wo-10",
        WO,
        "the ring around, the 2x2 pad in the middle",
        # a free pad, or a one-high 4x4 outline laid tight round it (a full 4x4 patch)
        k.any_of(k.around(k.block(2, 2, 1)), one(k.block(4, 4, 1))),
    ),
    _c("wo-11", WO, "a row of cubes - 7 - running away from me", one(k.row(7), k.runs("x"))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "hey so for my thesis I need a reference build, could you do a 3-step staircase? no rush",
        one(k.staircase(3)),
    ),
    _c("fil-02", FIL, "Prof said we should try something simple first. Tower of 3.", one(T(3))),
    _c(
        "fil-03",
        FIL,
        "ok ok ok. here goes. a bridge. two pillars of 3. go!",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "fil-04",
        FIL,
        "Lab notebook entry 14: build request - pyramid, 2 levels. Observations to follow.",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-05",
        FIL,
        "sorry my english not so good, i want wall, 4 long, 2 high, thank you very much",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-06",
        FIL,
        "Good afternoon! Hope the robot is having a good day :) Could I please get a 3x3 grid "
        "of cubes?",
        one(k.block(3, 3, 1)),
    ),
    _c("fil-07", FIL, "test test 1 2 3 ... ok it's on. row of 4 cubes", one(k.row(4))),
    _c(
        "fil-08",
        FIL,
        "My supervisor would like, if at all possible and assuming it's no trouble, a ring 1 "
        "cube high.",
        one(k.ring_of(high=1)),
    ),
    _c("fil-09", FIL, "it's 2am and I've had way too much coffee, give me a castle", one(k.castle)),
    _c(
        "fil-10",
        FIL,
        "Reminder that the group meeting moved to 3pm. Also, could someone build an L shape "
        "with arms of 3",
        one(L_SHAPE, k.dims(3, 3)),
    ),
    _c(
        "fil-11",
        FIL,
        "For the calibration run (see the attached spreadsheet, sheet 2) I need towers of 2, 4 "
        "and 6 standing in a line",
        k.any_of(k.structures(T(2), T(4), T(6)), one(k.profile(2, 4, 6))),
    ),
    _c(
        "fil-12",
        FIL,
        "so I was thinking, and tell me if this is dumb, but what if we did a wall that's like "
        "6 long and 3 high and just see how the robot handles it, yeah?",
        one(k.wall(6, 3)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "a tower of 4 at the back, centred left-right",
        one(T(4), reg(_B), k.near(y=0.30)),
    ),
    _c("reg-02", REG, "2x3 pad in the right back corner", one(k.block(2, 3, 1), reg("back right"))),
    _c("reg-03", REG, "a 3-level pyramid at (0.55, 0.25)", one(k.pyramid(3), k.near(0.55, 0.25))),
    _c("reg-04", REG, "a ring on the left side of the cell", one(k.ring, reg(_L))),
    _c(
        "reg-05",
        REG,
        "put the 4-step staircase nearest the robot, in the middle",
        one(k.staircase(4), reg(_F), k.near(y=0.30, tol=0.05)),
    ),
    _c("reg-06", REG, "a cross at x 400 mm y 350 mm", one(CROSS, k.near(0.40, 0.35))),
    _c(
        "reg-07",
        REG,
        "a 6-cube-long wall pushed right up to the back edge",
        one(k.wall(6), k.runs("y"), reg(_B)),
    ),
    _c(
        "reg-08",
        REG,
        "one tower of 3 in the front left and one in the back right",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "reg-09",
        REG,
        "a bridge, pillars 2 high, over on the right-hand side",
        one(k.bridge(2, pillars=2), reg(_R)),
    ),
    _c(
        "reg-10",
        REG,
        "a 2x2x2 block 10 cm to the left of the centre",
        one(k.block(2, 2, 2), k.near(0.45, 0.40)),
    ),
    _c(
        "reg-11",
        REG,
        "a single cube in each of the four corners of the table",
        k.structures(
            k.all_of(T(1), reg("front left")),
            k.all_of(T(1), reg("front right")),
            k.all_of(T(1), reg("back left")),
            k.all_of(T(1), reg("back right")),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a really tall tower", one(T(lo=6))),
    _c(
        "open-02",
        OPEN,
        "a little house",
        one(k.any_of(k.ring, k.canopy(), k.bridge(), k.castle)),
    ),
    _c(
        "open-03",
        OPEN,
        "a long wall, as long as you can reasonably make it",
        one(k.any_of(k.wall(lo=6), k.row(lo=6))),
    ),
    _c("open-04", OPEN, "a compact block", one(k.full, k.broad, k.height(lo=2))),
    _c(
        "open-05",
        OPEN,
        "an impressive, sweeping staircase",
        one(k.any_of(k.staircase(lo=4), k.all_of(k.staircase(lo=3), k.broad))),
    ),
    _c("open-06", OPEN, "a smallish pen", one(k.ring, k.long(hi=5))),
    _c(
        "open-07",
        OPEN,
        "a pillar",
        one(k.any_of(T(lo=2), k.all_of(k.solid(2, 2), k.height(lo=3)))),
    ),
    _c(
        "open-08",
        OPEN,
        "a low fence around a cube",
        # a free cube inside, or a 3x3 outline whose middle cell the cube fills
        k.any_of(
            k.around(T(1), k.all_of(k.ring, k.low(2))),
            one(k.dims(3, 3), k.parts(9), k.low(1), k.only_cubes),
        ),
    ),
    _c("open-09", OPEN, "a pyramid, just a teeny one", one(k.pyramid(2))),
    _c("open-10", OPEN, "an overpass", one(k.any_of(k.bridge(), k.arch, k.canopy()))),
    _c(
        "open-11",
        OPEN,
        "a square platform",
        one(k.full, k.broad, k.height(lo=1, hi=2), k.any_of(*[k.dims(n, n) for n in range(2, 11)])),
    ),
    _c("open-12", OPEN, "a few towers of different heights", _towers_differ(2, 5)),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "qwertyuiop", k.refused),
    _c(
        "bad-02",
        BAD,
        "haz una torre de cinco cubos por favor",
        k.honest(one(T(5))),
    ),
    _c("bad-03", BAD, "stack 12 cubes one on another in one column", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-04", BAD, "a 4-cube row, y = 900 mm", k.honest(one(k.row(4)))),
    _c("bad-05", BAD, "build me a pyramid that has no levels at all", k.honest()),
    _c(
        "bad-06",
        BAD,
        "a wall that is 3 long and 6 long at the same time",
        k.honest(one(k.any_of(k.wall(3), k.wall(6), k.row(3), k.row(6)))),
    ),
    _c("bad-07", BAD, "calibrate the gripper", k.honest()),
    _c("bad-08", BAD, "¯\\_(ツ)_/¯", k.refused),
    _c("bad-09", BAD, "a ring with a 1 metre wide inside", k.honest(one(k.ring))),
    _c("bad-10", BAD, "a tower of 4 floating 10 cm above the table", k.honest(one(T(4)))),
    _c("bad-11", BAD, "make it bigger", k.honest()),
    _c(
        "bad-12",
        BAD,
        "a staircase going down into the table",
        k.honest(one(k.staircase())),
    ),
)
