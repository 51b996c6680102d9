"""An eleventh development set for the language front end (dev11): the mainstream voice.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev10` (no command shared
with any set, see tests). Where the earlier sets each brought new personas, dev11 is
deliberately mainstream: commands phrased the way ordinary new operators of a robot cell type
them on their first day — plain, natural English, sometimes sloppy ("bulid a towr"), sometimes
chatty ("hi! first time using this"), in varied sentence shapes (imperatives, "I want …",
"can you …", fronted places, trailing afterthoughts, bare noun phrases) — with the usual
structure words and their common synonyms (tower / stack / pillar, row / line, wall, slab /
pad / floor / block, ring / fence, staircase / steps, pyramid, bridge, canopy, castle, L).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence, a negation, a typo, a unit in cm / mm / m / inches / feet) and 30 % harder: three
structures, references ("it", "the same tower again", "that"), distributive phrases ("a cube
on each corner", "a tower of 5 at each end", "one in each corner of the table"), comparisons
("twice as tall", "one less"), corrections ("no, on the right"), removals ("then take away the
middle one"), vague sizes ("a tall tower", "a few towers") and unusable, contradictory or
out-of-limit input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations such
as on top of / beside with a side / around / between, regions) and accepts every reasonable
reading of vague wording — including, where a relation such as "next to" or "at each end" may
be built touching, the single merged structure. Geometry comes only from `sdi.bench.boxes`
through the shared checks in `language_checks` and the few local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, right = −y, back = +x, front = −x (the robot stands at x = 0,
y = 0.30).
"""

from __future__ import annotations

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev11-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _taller_on(side: str) -> k.Check:
    """One structure of cube columns: the tallest columns stand on `side` of all the rest
    (a tower built against another structure, read as one merged structure)."""

    def f(bs: k.Boxes) -> k.Reason:
        cols = bx.columns(bs)
        top = max(len(c) for c in cols)
        tall = [b for c in cols if len(c) == top for b in c]
        rest = [b for c in cols if len(c) != top for b in c]
        if not rest:
            return "all columns equally tall"
        got = bx.side_of(tall, rest)
        return None if got == side else f"the tall part is {got} of the rest, want {side}"

    return f


def _corners_of_table(check: k.Check) -> k.Pred:
    """Four structures passing `check`, one in each corner region of the table."""
    return k.structures(
        *[k.all_of(check, k.region(f"{a} {b}")) for a in (_F, _B) for b in (_L, _R)]
    )


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
        "put a tower of 4 on top of a 3x3 slab",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.levels(9, 1, 1, 1, 1)),
    ),
    _c(
        "rel-02",
        REL,
        "make a 2x2 block, 2 high, and a 5 cube tower next to it",
        # separate, or the tower built against the block (one structure)
        k.any_of(
            k.pair(T(5), k.block(2, 2, 2), k.near_rel()),
            one(k.levels(5, 5, 1, 1, 1), k.dims(2, 3)),
        ),
    ),
    _c(
        "rel-03",
        REL,
        "I'd like a tower of 3 on the left and a tower of 6 on the right",
        k.pair(T(3), T(6), k.on_side(_L)),
    ),
    _c(
        "rel-04",
        REL,
        "build a ring of cubes 5 by 5 and put a 2 high tower inside it",
        k.any_of(
            k.around(T(2), k.all_of(k.ring, k.dims(5, 5))),
            one(k.holding(T(2), k.all_of(k.ring, k.dims(5, 5)))),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "two pillars of three cubes with a beam laid across the top of them",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "rel-06",
        REL,
        "a pyramid with 3 levels and a tower of 4 behind it",
        k.beside(T(4), k.pyramid(3), _B),
    ),
    _c(
        "rel-07",
        REL,
        "i want a wall 5 long 2 high and in front of it a row of 5, leave one cube of space",
        k.pair(k.row(5), k.wall(5, 2), k.gap_of(1, _F)),
    ),
    _c(
        "rel-08",
        REL,
        "Place a row of 4 cubes between two towers of 3.",
        k.any_of(k.between_(k.row(4), T(3)), one(k.profile(3, 1, 1, 1, 1, 3))),
    ),
    _c(
        "rel-09",
        REL,
        "lay a 4x4 slab and put a cube on each corner of it",
        one(k.base(4, 4), k.levels(16, 4), k.corner_columns(1)),
    ),
    _c(
        "rel-10",
        REL,
        "a 3x3 pad with a 2x2 pad on top of it and a single cube on top of that",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "build a tower of 3, and next to it a tower twice as tall",
        k.any_of(k.pair(T(6), T(3), k.near_rel()), one(k.profile(3, 6))),
    ),
    _c(
        "rel-12",
        REL,
        "a low fence around a 2x2 block",
        k.any_of(
            k.around(k.solid(2, 2), k.all_of(k.ring, k.low(2))),
            one(k.holding(k.solid(2, 2), k.all_of(k.ring, k.low(2)))),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "build a bridge, then stand one single cube on the middle of the beam",
        one(k.on_top(T(1), k.bare_bridge)),
    ),
    _c(
        "rel-14",
        REL,
        "two 3x3 slabs, one right on top of the other, and a tower of 2 on top of both",
        one(k.on_top(T(2), k.block(3, 3, 2)), k.levels(9, 9, 1, 1)),
    ),
    _c(
        "rel-15",
        REL,
        "a wall 6 long and 3 high with a tower of 5 at each end",
        # the towers as the wall's end columns, against its ends, or free at each end
        k.any_of(
            one(k.profile(5, 3, 3, 3, 3, 5)),
            one(k.profile(5, 3, 3, 3, 3, 3, 3, 5)),
            k.between_(k.wall(6, 3), T(5)),
        ),
    ),
    _c(
        "rel-16",
        REL,
        "a 2 by 4 slab and a pyramid of 2 levels to the right of it, 2 cubes apart",
        k.pair(k.pyramid(2), k.block(2, 4, 1), k.gap_of(2, _R)),
    ),
    _c(
        "rel-17",
        REL,
        "three towers of 2, 4 and 6 cubes, with the tallest one in the middle",
        k.any_of(k.between_(T(6), T(2), T(4)), one(k.profile(2, 6, 4))),
    ),
    _c(
        "rel-18",
        REL,
        "a little table: four legs, each 2 cubes high, and a flat top resting on them",
        one(k.canopy(4, 2, 2)),
    ),
    _c(
        "rel-19",
        REL,
        "a tower of 5, and an identical one 3 cubes to the left of it",
        k.pair(T(5), T(5), k.gap_of(3, _L)),
    ),
    _c(
        "rel-20",
        REL,
        "a 6 by 6 fence with a small 2-level pyramid in the middle",
        k.any_of(
            k.around(k.pyramid(2), k.all_of(k.ring, k.dims(6, 6))),
            one(k.holding(k.pyramid(2), k.all_of(k.ring, k.dims(6, 6)))),
        ),
    ),
    _c(
        "rel-21",
        REL,
        "a stack of 3 to the left of a stack of 5 - no, to the right of it",
        k.any_of(
            k.pair(T(3), T(5), k.on_side(_R)),
            one(k.lr_profile(5, 3)),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "first build a 3x3 slab, then put a tower of 3 in the middle of it",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.levels(9, 1, 1, 1), k.centred(0.01)),
    ),
    _c("seq-02", SEQ, "build a tower of 6, then take off the top cube", one(T(5))),
    _c(
        "seq-03",
        SEQ,
        "make a row of 5 and then add a second row on top of it",
        one(k.wall(5, 2)),
    ),
    _c(
        "seq-04",
        SEQ,
        "start with a tower of 2. now make it 3 cubes taller",
        one(T(5)),
    ),
    _c(
        "seq-05",
        SEQ,
        "make a 4x4 floor. then remove the middle 4 cubes",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-06",
        SEQ,
        "first a wall 4 long 2 high, after that a tower of 3 to the right of the wall",
        k.any_of(
            k.pair(T(3), k.wall(4, 2), k.on_side(_R)),
            one(k.lr_profile(2, 2, 2, 2, 3)),
        ),
    ),
    _c(
        "seq-07",
        SEQ,
        "build a pyramid of 3 levels and when it's done remove the cube at the very top",
        one(k.any_of(k.pyramid_counts(9, 4), k.pyramid_counts(25, 9))),
    ),
    _c(
        "seq-08",
        SEQ,
        "tower of 4. then another tower of 4 two cubes to its right. then a beam on top "
        "across the two",
        # two cubes of clear space, or two cubes centre to centre
        one(k.bridge(4, pillars=2), k.leg_gap(1, 2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "make a stack of 3 cubes. put another stack of 3 next to it. and one more next to that",
        k.any_of(k.each(3, T(3)), one(k.wall(3, 3))),
    ),
    _c("seq-10", SEQ, "build a 5 high tower... actually no, make it 7", one(T(7))),
    _c(
        "seq-11",
        SEQ,
        "first lay a row of 6 going front to back, then lay the same row again on its left "
        "side, touching it",
        one(k.block_xy(6, 2, 1)),
    ),
    _c(
        "seq-12",
        SEQ,
        "put down a 2x3 slab, then stack 2 more layers on it",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "seq-13",
        SEQ,
        "a staircase of 5 steps, then take away the highest step",
        one(k.staircase(4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "make a wall 6 long and 3 high, then knock off the top row",
        one(k.wall(6, 2)),
    ),
    _c(
        "seq-15",
        SEQ,
        "build a bridge on 2-cube pillars. then make both pillars one cube taller",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "seq-16",
        SEQ,
        "first place a single cube at the front. then put a tower of 4 behind it",
        # separate, or the tower set right against the back of the cube
        k.any_of(
            k.pair(T(4), k.all_of(T(1), reg(_F)), k.on_side(_B)),
            one(k.xprofile(1, 4)),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "build a 3 cube tower, then build another one twice as big to the left of it",
        k.any_of(k.pair(T(6), T(3), k.on_side(_L)), one(k.lr_profile(6, 3))),
    ),
    _c(
        "seq-18",
        SEQ,
        "build 5 towers of 2 in a line, then take away the middle one",
        # four towers left; or, built touching into a wall, two short walls left
        k.any_of(k.each(4, T(2)), k.each(2, k.wall(2, 2))),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "build three towers of 4 cubes", k.each(3, T(4))),
    _c("num-02", NUM, "5 towers, 2 cubes each", k.each(5, T(2))),
    _c("num-03", NUM, "a tower ten cubes tall", one(T(10))),
    _c("num-04", NUM, "stack seven cubes on top of each other", one(T(7))),
    _c(
        "num-05",
        NUM,
        "can you do two rows of 4",
        k.any_of(k.each(2, k.row(4)), one(k.block(2, 4, 1))),
    ),
    _c("num-06", NUM, "use 12 cubes to make a wall 4 long", one(k.wall(4, 3))),
    _c(
        "num-07",
        NUM,
        "a pyramid of 3 levels with 9 cubes on the bottom",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-08",
        NUM,
        "four stacks: 1, 2, 3 and 4 cubes high",
        # four separate stacks, or set side by side in order (a staircase)
        k.any_of(k.structures(T(1), T(2), T(3), T(4)), one(k.staircase(4))),
    ),
    _c("num-09", NUM, "a line made of eight cubes", one(k.row(8))),
    _c("num-10", NUM, "3 walls, each 3 long and 2 high", k.each(3, k.wall(3, 2))),
    _c(
        "num-11",
        NUM,
        "two towers, one of 3 and one of 5",
        k.structures(T(3), T(5)),
    ),
    _c("num-12", NUM, "a 3 by 3 by 3 cube made of cubes", one(k.block(3, 3, 3))),
    _c("num-13", NUM, "build 2 bridges, pillars 2 high", k.each(2, k.bridge(2, pillars=2))),
    _c(
        "num-14",
        NUM,
        "a tower with 4 cubes and another one with one less",
        k.structures(T(4), T(3)),
    ),
    _c("num-15", NUM, "a wall of 15 cubes, 5 long", one(k.wall(5, 3))),
    _c("num-16", NUM, "twenty cubes in a 4x5 slab", one(k.block(4, 5, 1))),
    _c("num-17", NUM, "six single cubes spread out on the table", k.each(6, T(1))),
    _c(
        "num-18",
        NUM,
        "a staircase with three steps and a tower as tall as the top step",
        k.any_of(
            k.structures(k.staircase(3), T(3)),
            one(k.profile(1, 2, 3, 3)),  # the tower against the top step
        ),
    ),
    _c("num-19", NUM, "half a dozen towers of two", k.each(6, T(2))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "can I get a tower that's 20 cm tall", one(T(4))),
    _c("dim-02", DIM, "a wall 30cm long and 15cm high", one(k.wall(6, 3))),
    _c("dim-03", DIM, "a flat slab 10 cm by 15 cm", one(k.block(2, 3, 1))),
    _c("dim-04", DIM, "a row 25 centimeters long", one(k.row(5))),
    _c("dim-05", DIM, "a tower half a meter high", one(T(10))),
    _c(
        "dim-06",
        DIM,
        "a block 10 cm wide, 10 cm deep and 15 cm tall",
        one(k.block(2, 2, 3)),
    ),
    _c("dim-07", DIM, "a stack 0.3 m high", one(T(6))),
    _c("dim-08", DIM, "build a wall 40 cm wide, 2 cubes high", one(k.wall(8, 2))),
    _c("dim-09", DIM, "make a tower that's 100 mm tall", one(T(2))),
    _c("dim-10", DIM, "a square pad 20 cm on each side", one(k.block(4, 4, 1))),
    _c("dim-11", DIM, "a 15 cm tall staircase", one(k.staircase(3))),
    _c(
        "dim-12",
        DIM,
        "a ring 25cm x 25cm, 5cm high",
        one(k.ring_of(high=1), k.dims(5, 5)),
    ),
    _c(
        "dim-13",
        DIM,
        "a bridge 15 cm high",
        # 15 cm overall (2-cube pillars under the beam) or 15 cm pillars
        one(k.any_of(k.bridge(2, pillars=2), k.bridge(3, pillars=2))),
    ),
    _c("dim-14", DIM, "a 6 inch tower", one(T(3))),
    _c(
        "dim-15",
        DIM,
        "a wall that is 35 cm long and a foot high",
        one(k.wall(7, 6)),
    ),
    _c(
        "dim-16",
        DIM,
        "put a 10 cm tall tower next to a 25 cm tall tower",
        k.any_of(k.pair(T(2), T(5), k.near_rel()), one(k.profile(2, 5))),
    ),
    _c("dim-17", DIM, "a floor 30 cm by 20 cm", one(k.block(6, 4, 1))),
    _c("dim-18", DIM, "a pyramid about 15 cm tall", one(k.pyramid(3))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 5, not in the middle",
        one(T(5), not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "a wall 4 long, 2 high, without any beams",
        one(k.wall(4, 2), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "a row of 6 but not going left to right",
        one(k.row(6), k.runs("x")),
    ),
    _c(
        "neg-04",
        NEG,
        "a 3x3 slab and don't put anything on top of it",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "neg-05",
        NEG,
        "two towers of 3, they shouldn't touch each other",
        k.each(2, T(3)),
    ),
    _c(
        "neg-06",
        NEG,
        "a pyramid, no more than 3 levels",
        one(k.pyramid(lo=2, hi=3)),
    ),
    _c(
        "neg-07",
        NEG,
        "a ring 5x5 with nothing inside it",
        one(k.ring_of(inner=(3, 3)), k.dims(5, 5)),
    ),
    _c(
        "neg-08",
        NEG,
        "a staircase of 4 steps that does not go up towards the left",
        one(k.staircase(4), not_(k.rises(_L), "climbs to the left")),
    ),
    _c(
        "neg-09",
        NEG,
        "a tower, not too tall, maybe 3 or 4 cubes",
        one(T(lo=3, hi=4)),
    ),
    _c(
        "neg-10",
        NEG,
        "make two pillars of 4 cubes but don't put anything across them",
        k.each(2, T(4)),
    ),
    _c(
        "neg-11",
        NEG,
        "a 2x2 block, not taller than 10 cm",
        one(k.solid(2, 2), k.height(lo=1, hi=2)),
    ),
    _c("neg-12", NEG, "don't build a tower, build a row of 3 instead", one(k.row(3))),
    _c(
        "neg-13",
        NEG,
        "a tower of 4 that isn't on the right side",
        one(T(4), not_(reg(_R), "on the right")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "bulid a towr of 5 cubse", one(T(5))),
    _c("typo-02", TYP, "a wal 6 lnog and 2 hgih", one(k.wall(6, 2))),
    _c("typo-03", TYP, "a 3x3 slba pls", one(k.block(3, 3, 1))),
    _c("typo-04", TYP, "make a stiarcase, 4 setps", one(k.staircase(4))),
    _c("typo-05", TYP, "two towres of three", k.each(2, T(3))),
    _c("typo-06", TYP, "a pyramd 3 levles", one(k.pyramid(3))),
    _c("typo-07", TYP, "a bridg with pilars of 2", one(k.bridge(2, pillars=2))),
    _c("typo-08", TYP, "a rign 4 by 4", one(k.ring, k.dims(4, 4))),
    _c("typo-09", TYP, "put a cueb on top of a tower of 3", one(T(4))),
    _c("typo-10", TYP, "row of 7 cubes on the lfet side", one(k.row(7), reg(_L))),
    _c(
        "typo-11",
        TYP,
        "a towr of 4 nxt to a towr of 2",
        k.any_of(k.pair(T(4), T(2), k.near_rel()), one(k.profile(2, 4))),
    ),
    _c("typo-12", TYP, "a 2x2 blcok 3 hihg", one(k.block(2, 2, 3))),
    _c(
        "typo-13",
        TYP,
        "an L shpae with arms of 4",
        # arms of 4 counting the corner cube, or 4 beyond it
        one(L_SHAPE, k.any_of(k.dims(4, 4), k.dims(5, 5))),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "5 cubes high, a tower", one(T(5))),
    _c("wo-02", WO, "on the left put a row of 4", one(k.row(4), reg(_L))),
    _c("wo-03", WO, "a wall build me, 5 long and 3 high", one(k.wall(5, 3))),
    _c(
        "wo-04",
        WO,
        "in the back right corner a tower of 3",
        one(T(3), reg("back right")),
    ),
    _c("wo-05", WO, "3 levels high, that's the pyramid I want", one(k.pyramid(3))),
    _c(
        "wo-06",
        WO,
        "next to the 3x3 slab, on its right, a tower of 4 please",
        k.any_of(
            k.beside(T(4), k.block(3, 3, 1), _R),
            one(k.levels(10, 1, 1, 1), k.dims(3, 4), _taller_on(_R)),
        ),
    ),
    _c(
        "wo-07",
        WO,
        "steps, 4 of them, going up towards the back",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "wo-08",
        WO,
        "the tower of 6 goes behind the wall, the wall 4 long and 2 high",
        k.any_of(
            k.pair(T(6), k.wall(4, 2), k.on_side(_B)),
            one(k.levels(5, 5, 1, 1, 1, 1), _taller_on(_B)),
        ),
    ),
    _c("wo-09", WO, "a bridge I need, pillars 3 cubes tall", one(k.bridge(3, pillars=2))),
    _c(
        "wo-10",
        WO,
        "of 4 by 4 a ring, make it 2 high",
        one(k.ring_of(high=2), k.dims(4, 4)),
    ),
    _c(
        "wo-11",
        WO,
        "at x 0.6 y 0.2 a tower of 2 you should build",
        one(T(2), k.near(0.6, 0.2)),
    ),
    _c("wo-12", WO, "long, 6 cubes; high, 2 cubes; a wall", one(k.wall(6, 2))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "hi! first time using this. could you build a tower of 4 cubes please?",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok so my boss wants to see what this thing can do, let's try a pyramid with 3 levels",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-03",
        FIL,
        "hello robot :) please make a row of 5 cubes, thank you so much",
        one(k.row(5)),
    ),
    _c(
        "fil-04",
        FIL,
        "hmm let me think... ok, a 2x2 block, 3 high. that should do",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-05",
        FIL,
        "not sure how this works but i'd like a small wall, 4 long 2 high, if that's possible",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-06",
        FIL,
        "Good afternoon. For the demo today we need a bridge with pillars of 3. Thanks in advance!",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "fil-07",
        FIL,
        "this is a test. please build two towers of 2. end of test.",
        k.each(2, T(2)),
    ),
    _c(
        "fil-08",
        FIL,
        "wow that last one looked great! now do a staircase with 5 steps",
        one(k.staircase(5)),
    ),
    _c(
        "fil-09",
        FIL,
        "could you please, if it's not too much trouble, put a ring 5 by 5 in the middle of "
        "the table",
        one(k.ring, k.dims(5, 5), reg("centre")),
    ),
    _c(
        "fil-10",
        FIL,
        "just checking the robot works - a single cube at the centre is fine",
        one(T(1), reg("centre")),
    ),
    _c(
        "fil-11",
        FIL,
        "my kid is watching so let's make it fun: build a castle!",
        one(k.castle),
    ),
    _c(
        "fil-12",
        FIL,
        "right, coffee's done, let's go. a 3x4 slab, one layer, on the right side",
        one(k.block(3, 4, 1), reg(_R)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "a tower of 3 at the front of the table", one(T(3), reg(_F))),
    _c(
        "reg-02",
        REG,
        "a row of 4 along the back, left to right",
        one(k.row(4), k.runs("y"), reg(_B)),
    ),
    _c(
        "reg-03",
        REG,
        "put a 2x2 block in the front left corner",
        one(k.solid(2, 2), reg("front left")),
    ),
    _c("reg-04", REG, "a tower of 5 at x=0.3, y=0.4", one(T(5), k.near(0.3, 0.4))),
    _c("reg-05", REG, "a pyramid of 2 levels on the right", one(k.pyramid(2), reg(_R))),
    _c(
        "reg-06",
        REG,
        "one tower of 2 in each of the four corners of the table",
        _corners_of_table(T(2)),
    ),
    _c(
        "reg-07",
        REG,
        "a wall 5 long 2 high along the left edge, running front to back",
        one(k.wall(5, 2), k.runs("x"), reg(_L)),
    ),
    _c(
        "reg-08",
        REG,
        "a cube at the back left and a cube at the front right",
        k.structures(
            k.all_of(T(1), reg("back left")),
            k.all_of(T(1), reg("front right")),
        ),
    ),
    _c(
        "reg-09",
        REG,
        "a staircase of 3 in the centre of the table",
        one(k.staircase(3), reg("centre")),
    ),
    _c("reg-10", REG, "a 3x3 slab close to the robot", one(k.block(3, 3, 1), reg(_F))),
    _c(
        "reg-11",
        REG,
        "a tower of 4, 10 cm to the right of the centre",
        # the centre taken as the usual (0.45, 0.30) or as the workspace middle (0.50, 0.30)
        one(T(4), k.near(y=0.20), k.near(x=0.475, tol=0.05)),
    ),
    _c(
        "reg-12",
        REG,
        "a ring 4x4 as far back as it can go",
        one(k.ring, k.dims(4, 4), k.near(x=0.70, tol=0.04)),
    ),
    _c(
        "reg-13",
        REG,
        "a bridge with 2-high pillars on the left side of the table",
        one(k.bridge(2, pillars=2), reg(_L)),
    ),
    _c(
        "reg-14",
        REG,
        "a tower of 6 at y = 0.15, halfway between front and back",
        one(T(6), k.near(y=0.15), k.near(x=0.475, tol=0.05)),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "build me a really tall tower", one(T(lo=5))),
    _c("open-02", OPEN, "a small pyramid", one(k.pyramid(lo=2, hi=3))),
    _c("open-03", OPEN, "build something nice", k.anything),
    _c(
        "open-04",
        OPEN,
        "a short wall",
        # short: low, or not long
        one(k.any_of(k.row(lo=2), k.wall(lo=2)), k.any_of(k.low(3), k.long(hi=4))),
    ),
    _c(
        "open-05",
        OPEN,
        "make a big solid block",
        one(k.full, k.broad, k.any_of(k.long(lo=3), k.height(lo=4))),
    ),
    _c("open-06", OPEN, "put a few towers on the table", k.few(2, 5, T(lo=1))),
    _c("open-07", OPEN, "some kind of gate", one(k.any_of(k.bridge(), k.arch))),
    _c(
        "open-08",
        OPEN,
        "a little house for a toy",
        one(k.any_of(k.ring, k.canopy(), k.arch)),
    ),
    _c("open-09", OPEN, "a low wide platform", one(k.full, k.broad, k.low(2))),
    _c(
        "open-10",
        OPEN,
        "something quick, just a few cubes",
        k.all_of(k.anything, k.layout(k.parts(lo=2, hi=6))),
    ),
    _c("open-11", OPEN, "a tower about as tall as it can be", one(T(lo=8, hi=10))),
    _c("open-12", OPEN, "a medium-sized staircase", one(k.staircase(lo=3, hi=6))),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "asdfgh", k.refused),
    _c("bad-02", BAD, "a tower of 25 cubes", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-03", BAD, "build a tower with minus 3 cubes", k.honest()),
    _c("bad-04", BAD, "a wall 2 metres long", k.honest(k.anything)),
    _c("bad-05", BAD, "put a cube at x = 1.5", k.honest(one(T(1)))),
    _c("bad-06", BAD, "a ring that is 1 by 1", k.honest(k.anything)),
    _c("bad-07", BAD, "make it", k.honest()),
    _c(
        "bad-08",
        BAD,
        "a tower of 4 cubes that is 50 cm tall",
        k.honest(one(k.any_of(T(4), T(10)))),
    ),
    _c("bad-09", BAD, "build the same thing as yesterday please", k.honest()),
    _c("bad-10", BAD, "a pyramid that has 0 levels", k.honest()),
    _c(
        "bad-11",
        BAD,
        "a row of 5 that is also a tower of 5",
        k.honest(one(k.any_of(k.row(5), T(5)))),
    ),
    _c("bad-12", BAD, "can you make me a cup of tea", k.honest()),
)
