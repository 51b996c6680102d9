"""A fifth development set for the language front end (dev5): new users in their first hour.

Written without looking at the Specifier's grammar, its tests or the frozen test set, and worded
apart from `language_dev` … `language_dev4` (no command shared with any set, see tests). The
commands come from four kinds of first-hour user — a lab technician, a teacher preparing a demo
for children, an automation engineer who writes tersely with units (``h=250mm``, ``L=0.35 m``)
and a manager — and are weighted about 70 % ordinary (one or two structures, a size, a place, one
relation or a two-step sequence, a negation, a typo, a unit) to 30 % harder (corrections,
removals, three-part layouts, feet, vague size words, unusable input).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks`.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the IRB120 at x = 0).
"""

from __future__ import annotations

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev5-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks (on boxes)


def _room(cells: int) -> k.Check:
    """An enclosure whose empty interior holds at least `cells` cube cells."""

    def f(bs: k.Boxes) -> k.Reason:
        got = round(bx.interior_area(bs) / (bx.CUBE * bx.CUBE))
        return None if got >= cells else f"interior {got} cells, want ≥ {cells}"

    return f


def _table(leg_high: int, a: int, b: int) -> k.Check:
    """A one-piece top with an a×b footprint (either orientation) carried by ≥ 3 separate legs
    `leg_high` cubes high, each touching the top. Unlike `k.canopy` the top may be a slab of
    cubes, most of whose parts rest on each other rather than on a leg."""

    def f(bs: k.Boxes) -> k.Reason:
        below, above = bx.split_at(bs, leg_high * bx.CUBE)
        if not below or not above:
            return f"no top resting on {leg_high}-high legs"
        legs = bx.components(below)
        if len(legs) < 3:
            return f"{len(legs)} legs, want ≥ 3"
        if any(bx.thickness_cubes(g) != leg_high or k.on_table(g) for g in legs):
            return f"legs not all {leg_high} high on the table"
        if len(bx.components(above)) != 1:
            return "top not one piece"
        if not all(any(bx.rests_on(r, q) for r in above for q in g) for g in legs):
            return "a leg carries nothing"
        got = bx.plan_dims(above)
        return None if got == tuple(sorted((a, b))) else f"top {got}, want {a}×{b}"

    return f


def _square_ring(*outer: int) -> k.Check:
    """A ring whose outer footprint is n×n for one of `outer`."""
    return k.all_of(k.ring, k.any_of(*[k.dims(n, n) for n in outer]))


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
        "park a 3-cube tower just left of a 2x2x2 block",
        k.beside(T(3), k.block(2, 2, 2), _L),
    ),
    _c(
        "rel-02",
        REL,
        "put a 3-step staircase behind a U shape",
        k.beside(k.staircase(3), U_SHAPE, _B),
    ),
    _c(
        "rel-03",
        REL,
        "one lonely cube inside a 4x4 enclosure",
        # a 4x4 floor inside (6x6 outside) with the cube free; or 4x4 outside, where a cube
        # inside always touches the wall: one 13-cube, one-high piece
        k.any_of(
            k.around(T(1), _square_ring(6)),
            one(k.dims(4, 4), k.parts(13), k.low(1), k.only_cubes),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "a gate made of two 3-high posts and a beam, with a single cube in front of the gate",
        k.beside(T(1), k.bridge(3, pillars=2), _F),
    ),
    _c(
        "rel-05",
        REL,
        "a row of 3 with a 2-cube tower at each side of it",
        k.any_of(k.between_(k.row(3), T(2)), one(k.profile(2, 1, 1, 1, 2))),
    ),
    _c(
        "rel-06",
        REL,
        "a wall 4 long and 2 high, with a cube resting on top of one end",
        one(k.profile(3, 2, 2, 2)),
    ),
    _c(
        "rel-07",
        REL,
        "a tower of 4 to the right of a bridge whose pillars are 2 cubes high",
        k.beside(T(4), k.bridge(2, pillars=2), _R),
    ),
    _c(
        "rel-08",
        REL,
        "a 7 by 7 fence with a small plus sign inside it",
        k.around(CROSS, _square_ring(7)),
    ),
    _c(
        "rel-09",
        REL,
        "a staircase of 4 steps leading up to a tower of 5",
        k.any_of(one(k.staircase(5)), k.beside(k.staircase(4), T(5))),
    ),
    _c(
        "rel-10",
        REL,
        "a 3-cube tower in between two 2-level pyramids",
        k.between_(T(3), k.pyramid(2)),
    ),
    _c(
        "rel-11",
        REL,
        "a row of 6 in front of a wall that is 6 long and 3 high",
        k.beside(k.row(6), k.wall(6, 3), _F),
    ),
    _c(
        "rel-12",
        REL,
        "a 3-level pyramid standing behind a staircase of 3",
        k.beside(k.pyramid(3), k.staircase(3), _B),
    ),
    _c("rel-13", REL, "the cross goes to the right of the castle", k.beside(CROSS, k.castle, _R)),
    _c(
        "rel-14",
        REL,
        "a tower of 6 surrounded by a ring of cubes 2 high",
        k.around(T(6), k.ring_of(high=2)),
    ),
    _c(
        "rel-15",
        REL,
        "a 2x2 slab with a 3-cube tower standing on one corner of it",
        one(k.on_top(T(3), k.block(2, 2, 1)), k.parts(7)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "put down eight cubes in a 2 by 4 patch, and then double it in height",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "seq-02",
        SEQ,
        "first a row of 4 going away from the robot, then a second row of 4 alongside it",
        k.any_of(
            one(k.block(2, 4, 1), k.runs("x")),
            k.each(2, k.row(4), k.runs("x")),
        ),
    ),
    _c(
        "seq-03",
        SEQ,
        "stack 3 cubes. next to that, stack 5.",
        k.any_of(k.beside(T(3), T(5)), one(k.profile(3, 5))),
    ),
    _c(
        "seq-04",
        SEQ,
        "build a 4-step staircase and then a 4-cube tower at its top end",
        k.any_of(one(k.profile(1, 2, 3, 4, 4)), k.beside(T(4), k.staircase(4))),
    ),
    _c(
        "seq-05",
        SEQ,
        "make a ring 1 high, then add a second course on top of the ring",
        one(k.ring_of(high=2)),
    ),
    _c("seq-06", SEQ, "build a tower of 7. take away 3 cubes from it.", one(T(4))),
    _c(
        "seq-07",
        SEQ,
        "make a 3x3 slab, then remove the four corner cubes",
        one(CROSS, k.dims(3, 3), k.low(1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "place a tower of 2 on the left; then a tower of 2 on the right; finally span them "
        "with a beam",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "first a wall 3 long and 3 high, then knock off its top row",
        one(k.wall(3, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "place one cube in the middle of the table. then build a ring around it",
        k.around(T(1)),
    ),
    _c("seq-11", SEQ, "build a T shape, then shift it to the right side", one(T_SHAPE, reg(_R))),
    _c(
        "seq-12",
        SEQ,
        "make a pyramid 2 levels high, and then make it one level taller",
        one(k.pyramid(3)),
    ),
    _c(
        "seq-13",
        SEQ,
        "a row of 3 from left to right; then put a row of 2 on top of it",
        one(k.pyramid_counts(3, 2)),
    ),
    _c(
        "seq-14",
        SEQ,
        "build a tower of 5 in the back left corner, then another one in the front right corner",
        k.structures(
            k.all_of(T(5), reg("back left")),
            k.all_of(T(5), reg("front right")),
        ),
    ),
    _c(
        "seq-15",
        SEQ,
        "make a 4-cube row. Now turn it so it points away from the robot",
        one(k.row(4), k.runs("x")),
    ),
    _c(
        "seq-16",
        SEQ,
        "build a 3-cube tower. Then build 2 more just like it, all in a line",
        k.any_of(k.each(3, T(3)), one(k.wall(3, 3))),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "a 2x2 tower using a dozen cubes", one(k.block(2, 2, 3))),
    _c("num-02", NUM, "row, seven cubes long", one(k.row(7))),
    _c(
        "num-03",
        NUM,
        "a trio of towers, each two cubes tall",
        k.any_of(k.each(3, T(2)), one(k.wall(3, 2))),
    ),
    _c("num-04", NUM, "one tower, 9 cubes tall", one(T(9))),
    _c(
        "num-05",
        NUM,
        "a pyramid whose bottom layer is 4 by 4",
        one(k.pyramid(lo=2), k.base(4, 4)),
    ),
    _c("num-06", NUM, "twenty cubes in a 4 by 5 slab", one(k.block(4, 5, 1))),
    _c(
        "num-07",
        NUM,
        "three 4-cube rows",
        k.any_of(k.each(3, k.row(4)), one(k.block(3, 4, 1))),
    ),
    _c("num-08", NUM, "a staircase: 1, 2, 3, 4, 5, 6 cubes high", one(k.staircase(6))),
    _c("num-09", NUM, "a wall of 2 rows with 7 in each", one(k.wall(7, 2))),
    _c(
        "num-10",
        NUM,
        "a 4-cube tower and, next to it, one double that height",
        k.any_of(k.beside(T(8), T(4)), one(k.profile(4, 8))),
    ),
    _c("num-11", NUM, "a tower of ten", one(T(10))),
    _c(
        "num-12",
        NUM,
        "4 rows of 4 cubes, all touching, flat on the table",
        one(k.block(4, 4, 1)),
    ),
    _c("num-13", NUM, "a bridge with a pair of 4-cube pillars", one(k.bridge(4, pillars=2))),
    _c(
        "num-14",
        NUM,
        "a single 3-level pyramid, the first level 5x5",
        one(k.pyramid(3), k.base(5, 5)),
    ),
    _c("num-15", NUM, "a tower with one more cube than 5", one(T(6))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "tower h=250mm", one(T(5))),
    _c("dim-02", DIM, "row L=0.35 m", one(k.row(7))),
    _c("dim-03", DIM, "pad 150x100 mm", one(k.block(3, 2, 1))),
    _c("dim-04", DIM, "wall 300 mm long x 150 mm high", one(k.wall(6, 3))),
    _c("dim-05", DIM, "a block 3 wide, 2 deep and 4 high", one(k.block(2, 3, 4))),
    _c("dim-06", DIM, "cube stack, 0.45 m tall", one(T(9))),
    _c("dim-07", DIM, "staircase, 5 steps, rise 50 mm each", one(k.staircase(5))),
    _c(
        "dim-08",
        DIM,
        "a 20 cm by 20 cm square ring, single course",
        one(k.ring_of(high=1), k.any_of(k.dims(4, 4), k.dims(6, 6))),
    ),
    _c(
        "dim-09",
        DIM,
        "a bridge spanning a 5 cm gap with pillars 15 cm tall",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "dim-10",
        DIM,
        "a pyramid with a base 25 cm square",
        one(k.pyramid(lo=2), k.base(5, 5)),
    ),
    _c("dim-11", DIM, "a wall 1 foot long, 2 cubes high", one(k.wall(6, 2))),
    _c("dim-12", DIM, "a slab of 10 cm x 30 cm", one(k.block(2, 6, 1))),
    _c(
        "dim-13",
        DIM,
        "tabletop 20 x 15 cm, legs 10 cm",
        one(k.any_of(_table(2, 4, 3), k.all_of(k.canopy(lo=2, hi=2), k.dims(4, 3)))),
    ),
    _c("dim-14", DIM, "a 3-course wall, 0.2 m run", one(k.wall(4, 3))),
    _c(
        "dim-15",
        DIM,
        "a row of cubes 40 cm from its left end to its right end",
        one(k.row(8), k.runs("y")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 3 that isn't at the back",
        one(T(3), not_(reg(_B), "at the back")),
    ),
    _c("neg-02", NEG, "a 2x5 slab, without using any beam", one(k.block(2, 5, 1), k.only_cubes)),
    _c("neg-03", NEG, "make the pyramid 3 levels, not 2", one(k.pyramid(3))),
    _c("neg-04", NEG, "two rows of 3 with no gap between them", one(k.block(2, 3, 1))),
    _c(
        "neg-05",
        NEG,
        "a U, not a closed ring - leave one side open",
        one(U_SHAPE, not_(k.ring, "closed")),
    ),
    _c(
        "neg-06",
        NEG,
        "don't build anything at the front; a 3x3 grid at the back",
        one(k.block(3, 3, 1), reg(_B)),
    ),
    _c(
        "neg-07",
        NEG,
        "a tower that is not taller than 3 cubes and not shorter than 3 cubes",
        one(T(3)),
    ),
    _c(
        "neg-08",
        NEG,
        "a row of 5, except skip the second cube",
        k.structures(T(1), k.row(3)),
    ),
    _c("neg-09", NEG, "an enclosure with no tower in it", one(k.ring)),
    _c(
        "neg-10",
        NEG,
        "a wall 5 long and 3 high with no cube in the middle of the bottom course, like a doorway",
        one(k.dims(1, 5), k.height(3), k.parts(14), k.only_cubes),
    ),
    _c(
        "neg-11",
        NEG,
        "a staircase that doesn't climb towards the left",
        one(k.staircase(), not_(k.rises(_L), "climbs to the left")),
    ),
    _c(
        "neg-12",
        NEG,
        "put a tower of 4 anywhere except the centre",
        one(T(4), not_(reg("centre"), "in the centre")),
    ),
    _c("neg-13", NEG, "i said 5 steps not 3 - staircase", one(k.staircase(5))),
    _c(
        "neg-14",
        NEG,
        "two pyramids, each 2 levels, neither touching the other",
        k.each(2, k.pyramid(2)),
    ),
    _c("neg-15", NEG, "a square of cubes, hollow, not filled in", one(k.ring, k.low(1))),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towre with 5 cubse", one(T(5))),
    _c("typo-02", TYP, "a pyrmaid 4 levls", one(k.pyramid(4))),
    _c("typo-03", TYP, "a 2x2 blok, 3 hihg", one(k.block(2, 2, 3))),
    _c("typo-04", TYP, "an arhc made of cubse", one(k.arch)),
    _c("typo-05", TYP, "row of 8 cubes on teh left", one(k.row(8), reg(_L))),
    _c("typo-06", TYP, "staricase 3 stpes", one(k.staircase(3))),
    _c("typo-07", TYP, "an L shaep 4 by 2", one(L_SHAPE, k.dims(4, 2))),
    _c("typo-08", TYP, "a enclsure arond a 2 cube towr", k.around(T(2))),
    _c("typo-09", TYP, "bild a tabel with 4 legs", one(k.canopy(4))),
    _c("typo-10", TYP, "a wal 6 logn, 2 hihg", one(k.wall(6, 2))),
    _c("typo-11", TYP, "3 towers of 3 in a line, sepparate", k.each(3, T(3))),
    _c("typo-12", TYP, "a T shaep at teh back", one(T_SHAPE, reg(_B))),
    _c(
        "typo-13",
        TYP,
        "a brdige over a gap of one cube, pilars 2 high",
        one(k.bridge(2, pillars=2)),
    ),
    _c("typo-14", TYP, "a grdi 4x3", one(k.block(4, 3, 1))),
    _c(
        "typo-15",
        TYP,
        "a 3 cube towr ontop of a 3x3 slba",
        one(k.on_top(T(3), k.block(3, 3, 1))),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "six cubes high, one tower", one(T(6))),
    _c(
        "wo-02",
        WO,
        "to the left of the pyramid (3 levels) a tower of 2",
        k.beside(T(2), k.pyramid(3), _L),
    ),
    _c("wo-03", WO, "4 steps, the staircase", one(k.staircase(4))),
    _c("wo-04", WO, "in the back right: a 2x2 pad", one(k.block(2, 2, 1), reg("back right"))),
    _c("wo-05", WO, "high 2 cubes, long 5 cubes, a wall", one(k.wall(5, 2))),
    _c("wo-06", WO, "a ring - inside it a cube", k.around(T(1))),
    _c(
        "wo-07",
        WO,
        "beam on top, legs 3 cubes each, two of them: a gate",
        one(k.bridge(3, pillars=2)),
    ),
    _c("wo-08", WO, "3 levels, pyramid, at the front", one(k.pyramid(3), reg(_F))),
    _c("wo-09", WO, "an L, arms of 3 cubes each", one(L_SHAPE, k.dims(3, 3))),
    _c(
        "wo-10",
        WO,
        "towers: three. height: 2 each.",
        k.any_of(k.each(3, T(2)), one(k.wall(3, 2))),
    ),
    _c(
        "wo-11",
        WO,
        "left side, row of 4 front to back",
        one(k.row(4), k.runs("x"), reg(_L)),
    ),
    _c(
        "wo-12",
        WO,
        "a slab underneath, 4x4; on it a tower of 3",
        one(k.on_top(T(3), k.block(4, 4, 1))),
    ),
    _c(
        "wo-13",
        WO,
        "behind the wall (3 long, 2 high) a 3-cube tower",
        k.beside(T(3), k.wall(3, 2), _B),
    ),
    _c(
        "wo-14",
        WO,
        "2 high the ring should be, with a 3 by 3 space inside",
        one(k.ring_of(high=2, inner=(3, 3))),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi! I'm showing this to a class of 8-year-olds this afternoon, could the robot build a "
        "little staircase with 3 steps for them? They'll love it",
        one(k.staircase(3)),
    ),
    _c(
        "fil-02",
        FIL,
        "Morning. Sample rack mock-up needed: a 2 x 4 pad of cubes on the table please, ta.",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "fil-03",
        FIL,
        "For the investor visit on Thursday I want something impressive - a castle, in the "
        "middle of the cell.",
        one(k.castle, reg("centre")),
    ),
    _c("fil-04", FIL, "umm ok can you, like, make a tower? 4 cubes? idk", one(T(4))),
    _c("fil-05", FIL, "FYI gripper tested OK. Req: wall L=5 cubes, H=3. Thx.", one(k.wall(5, 3))),
    _c(
        "fil-06",
        FIL,
        "The kids want to see a bridge a toy car could drive under! Two towers of 3 and a beam "
        "across, please :)",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "fil-07",
        FIL,
        "Sorry to bother you again. Could we have one pyramid, three layers, whenever the robot "
        "is free?",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-08",
        FIL,
        "Just need a quick visual for the slide deck: two towers of 5 side by side, nothing fancy",
        k.any_of(k.beside(T(5), T(5)), one(k.wall(2, 5))),
    ),
    _c(
        "fil-09",
        FIL,
        "as per the SOP (rev B), please build: one ring, 1 cube high, around a single cube",
        k.around(T(1), k.ring_of(high=1)),
    ),
    _c("fil-10", FIL, "hello robot friend :-) a cross please", one(CROSS)),
    _c(
        "fil-11",
        FIL,
        "btw the table was wiped down so it's clean - go ahead and build a 3 by 3 grid",
        one(k.block(3, 3, 1)),
    ),
    _c("fil-12", FIL, "right, let's get going: row of 6 cubes, ta very much", one(k.row(6))),
    _c(
        "fil-13",
        FIL,
        "for the Year 2 counting lesson: a tower of 1, a tower of 2 and a tower of 3, in a line "
        "so the children can compare them",
        k.any_of(k.structures(T(1), T(2), T(3)), one(k.staircase(3))),
    ),
    _c(
        "fil-14",
        FIL,
        "whatever you think is best really, but personally I'd go for a U shape",
        one(U_SHAPE),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "a tower of 5 near the back edge, on the left",
        one(T(5), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "a pyramid of 2 levels at x 0.6, y 0.2",
        one(k.pyramid(2), k.near(0.6, 0.2)),
    ),
    _c("reg-03", REG, "a 3-step staircase close to the robot", one(k.staircase(3), reg(_F))),
    _c(
        "reg-04",
        REG,
        "a wall 4 long along the right edge",
        one(k.wall(4), reg(_R), k.runs("x")),
    ),
    _c("reg-05", REG, "an L in the back left corner", one(L_SHAPE, reg("back left"))),
    _c(
        "reg-06",
        REG,
        "a ring in the centre of the cell, 1 high",
        one(k.ring_of(high=1), reg("centre")),
    ),
    _c("reg-07", REG, "a tower of 2 at (0.35, 0.45)", one(T(2), k.near(0.35, 0.45))),
    _c("reg-08", REG, "cross, far right", one(CROSS, reg(_R))),
    _c(
        "reg-09",
        REG,
        "a row of 3 cubes at the front, left to right",
        one(k.row(3), k.runs("y"), reg(_F)),
    ),
    _c(
        "reg-10",
        REG,
        "a 2x2x2 block 0.3 m straight out from the robot base",
        one(k.block(2, 2, 2), k.near(0.3, 0.3, tol=0.04)),
    ),
    _c("reg-11", REG, "a table at the front right", one(k.canopy(), reg("front right"))),
    _c(
        "reg-12",
        REG,
        "put a tower of 3 on the left and a 2x2 pad on the right",
        k.structures(k.all_of(T(3), reg(_L)), k.all_of(k.block(2, 2, 1), reg(_R))),
    ),
    _c("reg-13", REG, "bridge in the far back, near the edge", one(k.bridge(), reg(_B))),
    _c(
        "reg-14",
        REG,
        "a T shape with its centre at 450 mm, 300 mm",
        one(T_SHAPE, k.near(0.45, 0.30)),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a tiny tower", one(T(lo=1, hi=3))),
    _c("open-02", OPEN, "a big castle", one(k.castle)),
    _c(
        "open-03",
        OPEN,
        "a wide, low wall",
        one(k.any_of(k.all_of(k.wall(lo=5), k.low(3)), k.row(lo=5))),
    ),
    _c(
        "open-04",
        OPEN,
        "something for the kids to look at, maybe a pyramid",
        one(k.pyramid(lo=2)),
    ),
    _c("open-05", OPEN, "a small staircase", one(k.staircase(lo=2, hi=4))),
    _c(
        "open-06",
        OPEN,
        "a sturdy tower",
        one(k.any_of(T(lo=2), k.all_of(k.solid(2, 2), k.height(lo=2)))),
    ),
    _c("open-07", OPEN, "a fence", one(k.any_of(k.ring, k.wall(), k.row(lo=3)))),
    _c("open-08", OPEN, "a wide staircase", one(k.staircase(), k.broad)),
    _c("open-09", OPEN, "a medium-sized pyramid", one(k.pyramid(lo=2, hi=4))),
    _c("open-10", OPEN, "some sort of doorway for a toy", one(k.any_of(k.bridge(), k.arch))),
    _c("open-11", OPEN, "a plus sign", one(CROSS)),
    _c(
        "open-12",
        OPEN,
        "some kind of shelter with a roof",
        one(k.any_of(k.canopy(), k.bridge())),
    ),
    _c("open-13", OPEN, "a chunky, solid lump of cubes", one(k.full, k.broad, k.height(lo=2))),
    _c("open-14", OPEN, "a short row", one(k.row(lo=2, hi=4))),
    _c("open-15", OPEN, "a pen big enough for a 2x2 pad", one(k.ring, _room(4))),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "lorem ipsum dolor", k.refused),
    _c("bad-02", BAD, "hmm", k.refused),
    _c("bad-03", BAD, "Costruisci una torre di cinque cubi", k.honest(one(T(5)))),
    _c("bad-04", BAD, "a tower of 40 cubes", k.honest(one(T(lo=2, hi=10)))),
    _c("bad-05", BAD, "a tower of 3 at y = -0.2 m", k.honest(one(T(3)))),
    _c("bad-06", BAD, "a row of zero cubes", k.honest()),
    _c(
        "bad-07",
        BAD,
        "a pyramid with 3 levels and 5 levels",
        k.honest(k.any_of(one(k.pyramid(3)), one(k.pyramid(5)))),
    ),
    _c("bad-08", BAD, "undo", k.honest()),
    _c("bad-09", BAD, "a sphere of cubes, 20 cm across", k.honest(k.layout(k.parts(lo=1)))),
    _c("bad-10", BAD, "a wall 3 m long", k.honest(one(k.any_of(k.wall(), k.row(lo=2))))),
    _c("bad-11", BAD, "print the layout as a PDF", k.honest()),
    _c(
        "bad-12",
        BAD,
        "a tower 7 cubes tall and 3 cubes tall",
        k.honest(k.any_of(one(T(7)), one(T(3)))),
    ),
    _c("bad-13", BAD, "rm -rf /", k.refused),
    _c("bad-14", BAD, "a staircase of -4 steps", k.honest(one(k.staircase(4)))),
    _c("bad-15", BAD, "a ring with an inside of 20 x 20 cubes", k.honest(one(k.ring))),
)
