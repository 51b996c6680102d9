"""A ninth development set for the language front end (dev9): six new voices at the cell.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev8` (no command shared with
any set, see tests). The commands come from six kinds of people, none of them used before:

* a quality inspector describing a reference part to reproduce ("replicate: …", part numbers,
  "L x W x H", datums);
* a school teacher preparing a classroom demo (talks to the children while giving the order);
* a voice-assistant transcript — no punctuation, spoken numbers, "uh", "um", self-corrections
  ("six long no sorry five");
* an architecture-minded hobbyist using building words (colonnade, plinth, lintel, terrace,
  parapet, tier, podium, posts);
* a logistics worker thinking in pallets, stacks, layers, aisles and loading/unloading;
* someone pasting from a spreadsheet or a chat (key: value lines, table rows, bullets, emoji).

About 65 % ordinary (one or two structures, a size, a place, a unit, one negation or typo) and
35 % harder: relations between structures (on top of, beside with a side and a gap, around,
inside, between, parallel, against an end), sequences ("first … then …", "then take the top two
off", "then fill in the middle"), numbers attached to the right thing ("two stacks of five",
"4 pallets, each 2x2, 3 high"), comparisons ("twice as tall", "half as high as the tower"),
references ("an identical one to its right"), distributive phrases ("a column on each corner",
"a tower at both ends"), corrections, open descriptions and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the IRB120 at x = 0, y = 0.30).
"""

from __future__ import annotations

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

Rel = k.Rel


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev9-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _missing_corner(a: int, b: int) -> k.Check:
    """One layer of cubes on an a×b footprint with exactly one corner cell left empty."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.dims(a, b)(bs) or k.height(1)(bs) or k.only_cubes(bs)
        if r:
            return r
        fx, fy = bx.footprint_cubes(bs)
        empty = {(i, j) for i in range(fx) for j in range(fy)} - bx.cells(bs)
        corners = {(i, j) for i in (0, fx - 1) for j in (0, fy - 1)}
        if len(empty) != 1 or not empty <= corners:
            return f"empty cells {sorted(empty)}, want one corner"
        return None if len(bs) == fx * fy - 1 else "overlapping parts"

    return f


def _square(bs: k.Boxes) -> k.Reason:
    a, b = bx.plan_dims(bs)
    return None if a == b else f"footprint {a}×{b}, not square"


def _tower_ending_wall(tower: int, high: int) -> k.Check:
    """One cube thick: a wall `high` cubes high (≥ 2 long) with a `tower`-high column
    against one end, every column full."""

    def f(bs: k.Boxes) -> k.Reason:
        fx, fy = bx.footprint_cubes(bs)
        if min(fx, fy) != 1:
            return "not one cube thick"
        prof = bx.step_profile(bs, 0 if fx >= fy else 1)
        if prof and prof[-1] == tower:
            prof = prof[::-1]
        if len(prof) < 3 or prof[0] != tower or set(prof[1:]) != {high}:
            return f"height profile {prof}, want [{tower}, {high}, {high}, …]"
        return None if len(bx.voxels(bs)) == sum(prof) else "columns not full"

    return f


def _pyramid_pair_sides(small: int, big: int, side: str) -> k.Pred:
    """Two pyramids, the `small`-level one on `side` of the `big`-level one."""
    return k.pair(k.pyramid(small), k.pyramid(big), k.on_side(side))


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE = k.shape_letter("L")
U_SHAPE = k.shape_letter("U")
T_SHAPE = k.shape_letter("T")
# a terrace / tiered thing: steps one way, or steps all round
_RING6 = k.all_of(k.ring_of(high=1), k.dims(6, 6))
_TERRACE3 = k.any_of(k.staircase(3), k.pyramid(3))

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "a 4x4 plinth, one cube thick, with a column of three standing on it, centred",
        one(k.on_top(T(3), k.block(4, 4, 1)), k.levels(16, 1, 1, 1), k.centred()),
    ),
    _c(
        "rel-02",
        REL,
        "two pallets of 3x3, single layer, side by side with a one-cube aisle between them",
        k.pair(k.block(3, 3, 1), k.block(3, 3, 1), k.gap_of(1)),
    ),
    _c(
        "rel-03",
        REL,
        "put a tower of four uh to the right of a wall five long two high leave two cubes of space",
        k.pair(T(4), k.wall(5, 2), k.gap_of(2, _R)),
    ),
    _c(
        "rel-04",
        REL,
        "Class, watch closely: the robot will put a fence all the way around one single cube "
        "so it can't escape.",
        # a fence free round it, or touching it (laid tight round it, a 3x3 outline)
        k.any_of(
            k.around(T(1), k.all_of(k.ring, k.low(3))),
            one(k.holding(T(1), k.all_of(k.ring, k.low(3)))),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "a lintel resting across two posts, the posts four cubes tall",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "rel-06",
        REL,
        "replicate ref part B-12: 3x3 pad, and directly behind it a 2x2 pad, 1 cube gap",
        k.pair(k.block(2, 2, 1), k.block(3, 3, 1), k.gap_of(1, _B)),
    ),
    _c(
        "rel-07",
        REL,
        "structure: bridge\npillar height: 3\nextra: tower of 2 standing on the beam",
        one(k.on_top(T(2), k.bare_bridge), k.height(6)),
    ),
    _c(
        "rel-08",
        REL,
        "a 2x2 pallet stacked two high, enclosed by a one-high ring 6 cubes across",
        k.any_of(
            k.around(k.block(2, 2, 2), _RING6),
            one(k.holding(k.block(2, 2, 2), _RING6)),  # the pallet against the ring
        ),
    ),
    _c(
        "rel-09",
        REL,
        "Now a staircase of three, and right up against its tall end a tower of five.",
        one(k.profile(1, 2, 3, 5)),
    ),
    _c(
        "rel-10",
        REL,
        "between two uh two by two pads put a little row of three leave a gap each side",
        k.between_(k.row(3), k.block(2, 2, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "a three-tier terrace, and on its left a tower six cubes high",
        k.beside(T(6), _TERRACE3, _L),
    ),
    _c(
        "rel-12",
        REL,
        "replicate fixture F3: two parallel walls, 4 long x 2 high, facing each other 3 cubes "
        "apart",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(3)),
    ),
    _c(
        "rel-13",
        REL,
        "a podium 4 by 4, one layer, with a column of three on each of its corners",
        one(k.base(4, 4), k.levels(16, 4, 4, 4), k.corner_columns(3)),
    ),
    _c(
        "rel-14",
        REL,
        "row of 6 cubes, a tower of 3 at both ends",
        # the towers on the end cubes (end cube under them or counted), or against the ends
        one(
            k.any_of(
                k.profile(4, 1, 1, 1, 1, 4),
                k.profile(3, 1, 1, 1, 1, 3),
                k.profile(3, 1, 1, 1, 1, 1, 1, 3),
            )
        ),
    ),
    _c(
        "rel-15",
        REL,
        "replicate: 2x3 pad, 2 layers, and an identical one to its right, 2 cube gap",
        k.pair(k.block(2, 3, 2), k.block(2, 3, 2), k.gap_of(2, _R)),
    ),
    _c(
        "rel-16",
        REL,
        "a tower of 6 and next to it a wall half as high",
        # separate, or the wall built against the tower
        k.any_of(k.pair(k.wall(high=3), T(6), k.near_rel()), one(_tower_ending_wall(6, 3))),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "first a two by two slab then on top of it uh a single cube then another cube on that",
        one(k.levels(4, 1, 1), k.on_top(T(2), k.block(2, 2, 1))),
    ),
    _c(
        "seq-02",
        SEQ,
        "replicate in this order: (1) row of 4, front to back (2) a second row of 4 on top "
        "(3) a third row on top of that",
        one(k.wall(4, 3), k.runs("x")),
    ),
    _c(
        "seq-03",
        SEQ,
        "First we'll make a tower of three. Then, children, we'll make another one twice as "
        "tall right next to it.",
        k.any_of(k.pair(T(6), T(3), k.near_rel()), one(k.profile(3, 6))),
    ),
    _c(
        "seq-04",
        SEQ,
        "step | action\n1 | lay a 3x4 slab\n2 | take one corner cube away",
        one(_missing_corner(3, 4)),
    ),
    _c("seq-05", SEQ, "build a stack of 5, then take the top two off", one(T(3))),
    _c("seq-06", SEQ, "make a wall six long no sorry five long three high", one(k.wall(5, 3))),
    _c(
        "seq-07",
        SEQ,
        "Start with a 5x5 ring, one high. Then fill in the middle.",
        one(k.block(5, 5, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "• 1st: tower 4\n• 2nd: same again, 2 cubes to the left of the first\n"
        "• 3rd: beam across both",
        # two cubes of clear space, or two cubes centre to centre
        one(k.bridge(4, pillars=2), k.leg_gap(1, 2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "We start with a pyramid of three levels. Now the robot takes the top cube off.",
        one(k.any_of(k.pyramid_counts(9, 4), k.pyramid_counts(25, 9))),
    ),
    _c(
        "seq-10",
        SEQ,
        "load 3 layers of 2x3 onto the pallet spot, then unload the top layer",
        one(k.block(2, 3, 2)),
    ),
    _c("seq-11", SEQ, "tower of three um actually make that eight", one(T(8))),
    _c(
        "seq-12",
        SEQ,
        "first the podium, 4 by 4 and one cube thick; then a second tier, 2 by 2, set right "
        "in the centre of it",
        one(k.pyramid_counts(16, 4), k.centred(0.01)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "two stacks of five", k.each(2, T(5))),
    _c("num-02", NUM, "three towers of um two each", k.each(3, T(2))),
    _c("num-03", NUM, "4 pallets, each 2x2, 3 high", k.each(4, k.block(2, 2, 3))),
    _c(
        "num-04",
        NUM,
        "Let's count together: one, two, three, four — four cubes in a line.",
        one(k.row(4)),
    ),
    _c("num-05", NUM, "qty: 3\nitem: tower\nheight_cubes: 4", k.each(3, T(4))),
    _c("num-06", NUM, "a colonnade of five columns, each four cubes tall", k.each(5, T(4))),
    _c(
        "num-07",
        NUM,
        "replicate: pyramid, 3 tiers, 14 cubes in total",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-08",
        NUM,
        "a wall twelve cubes long uh no wait ten cubes long one high",
        one(k.row(10)),
    ),
    _c("num-09", NUM, "12 cubes as one block, 2 wide and 2 deep", one(k.block(2, 2, 3))),
    _c(
        "num-10",
        NUM,
        "need 2x pyramids (2 levels) + 1x ring 4x4 👍",
        k.structures(k.pyramid(2), k.pyramid(2), k.all_of(k.ring, k.dims(4, 4))),
    ),
    _c("num-11", NUM, "six cubes shared equally between two towers", k.each(2, T(3))),
    _c(
        "num-12",
        NUM,
        "one tower of 2 and a second one three times as tall",
        k.structures(T(2), T(6)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a parapet wall 30 cm long and 10 cm high", one(k.wall(6, 2))),
    _c(
        "dim-02",
        DIM,
        "replicate: block, 100 x 100 x 150 mm (L x W x H)",
        one(k.block(2, 2, 3)),
    ),
    _c("dim-03", DIM, "a tower about twenty centimetres high", one(T(4))),
    _c(
        "dim-04",
        DIM,
        "a pallet footprint of 25 cm by 20 cm, one layer",
        one(k.block(5, 4, 1)),
    ),
    _c(
        "dim-05",
        DIM,
        "A staircase whose top step is 15 cm above the table, please.",
        one(k.staircase(3)),
    ),
    _c(
        "dim-06",
        DIM,
        "type: slab\nwidth: 10cm\ndepth: 15cm\nheight: 5cm",
        one(k.block_xy(3, 2, 1)),
    ),
    _c(
        "dim-07",
        DIM,
        "replicate gate G-2: two pillars 0.2 m tall, 10 cm clear between them, beam on top",
        one(k.bridge(4, pillars=2), k.leg_gap(2)),
    ),
    _c(
        "dim-08",
        DIM,
        "a slab 2 inches thick and 10 inches square",
        one(k.block(5, 5, 1)),
    ),
    _c(
        "dim-09",
        DIM,
        "a ring uh thirty five centimetres across on the outside",
        one(k.ring, k.dims(7, 7)),
    ),
    _c(
        "dim-10",
        DIM,
        "a stack going up to 0.4 m",
        one(k.any_of(T(8), k.all_of(k.solid(2, 2), k.height(8)))),
    ),
    _c(
        "dim-11",
        DIM,
        "a wall 0.25 m long, 5 cm thick and 0.15 m high",
        one(k.wall(5, 3)),
    ),
    _c(
        "dim-12",
        DIM,
        "Let's make a tower exactly as tall as our 30 cm ruler.",
        one(T(6)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of five not on the left",
        one(T(5), not_(reg(_L), "on the left")),
    ),
    _c("neg-02", NEG, "replicate: 3x3 slab, NO cube on top", one(k.block(3, 3, 1))),
    _c(
        "neg-03",
        NEG,
        "a 2x2 stack, not more than 3 layers",
        one(k.solid(2, 2), k.height(lo=2, hi=3)),
    ),
    _c(
        "neg-04",
        NEG,
        "A bridge, but without the beam this time — just its two pillars of three.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-05",
        NEG,
        "an enclosure 5x5 with no gap left for a door",
        one(k.ring, k.dims(5, 5)),
    ),
    _c(
        "neg-06",
        NEG,
        "row of 5 ❌ not left-right ✅ front-back",
        one(k.row(5), k.runs("x")),
    ),
    _c("neg-07", NEG, "a wall no not a wall a row of six", one(k.row(6))),
    _c(
        "neg-08",
        NEG,
        "beams: none\ncubes: 8\nshape: 2x2x2",
        one(k.block(2, 2, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "replicate staircase, 4 steps, not climbing toward the robot",
        one(k.staircase(4), not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-10",
        NEG,
        "two stacks of 3, don't put them in the middle of the table",
        k.each(2, T(3), not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-11",
        NEG,
        "a pyramid of three tiers and not hollow",
        one(k.any_of(k.pyramid_counts(9, 4, 1), k.pyramid_counts(25, 9, 1))),
    ),
    _c("neg-12", NEG, "A tower of 4 — not 40, children, four!", one(T(4))),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a tour of three cubes", one(T(3))),
    _c("typo-02", TYP, "palet 3x3 2 layres", one(k.block(3, 3, 2))),
    _c("typo-03", TYP, "colonade of 3 colums 5 high", k.each(3, T(5))),
    _c("typo-04", TYP, "brigde pls, piller ht 2 🙏", one(k.bridge(2, pillars=2))),
    _c("typo-05", TYP, "replciate: staricase 5 stpes", one(k.staircase(5))),
    _c("typo-06", TYP, "pyrmaid with four levles", one(k.pyramid(4))),
    _c("typo-07", TYP, "wlal 7 long 3 hihg", one(k.wall(7, 3))),
    _c("typo-08", TYP, "rnig 6x6 one hgih", one(k.ring_of(high=1), k.dims(6, 6))),
    _c("typo-09", TYP, "tow towers of fuor", k.each(2, T(4))),
    _c(
        "typo-10",
        TYP,
        "a U shaep, 4 acros and 3 deeep",
        # the arms 3 deep with the base row, or 3 beyond it
        one(U_SHAPE, k.any_of(k.dims(3, 4), k.dims(4, 4))),
    ),
    _c(
        "typo-11",
        TYP,
        "T shpe, bar 5 wide, stme 3",
        # the stem 3 below the bar, or 3 counting the bar's middle cube
        one(T_SHAPE, k.any_of(k.dims(4, 5), k.dims(3, 5))),
    ),
    _c(
        "typo-12",
        TYP,
        "a cube in ecah corenr of a 4x4 slba",
        one(k.base(4, 4), k.levels(16, 4), k.corner_columns(1)),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "three high and five long, that parapet", one(k.wall(5, 3))),
    _c(
        "wo-02",
        WO,
        "on the plinth of 3x3, the column of 4 stands",
        one(k.on_top(T(4), k.block(3, 3, 1))),
    ),
    _c(
        "wo-03",
        WO,
        "to the back, a pallet of 2 by 3 goes",
        one(k.solid(2, 3), k.low(3), reg(_B)),
    ),
    _c(
        "wo-04",
        WO,
        "steps four of them going up to the left",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "wo-05",
        WO,
        "height 6, tower, position right side",
        one(T(6), reg(_R)),
    ),
    _c(
        "wo-06",
        WO,
        "a ring of cubes, 4 by 4, and in it a single cube, put",
        # the cube free inside, or in one of the four inside cells, touching the ring
        k.any_of(
            k.around(T(1), k.all_of(k.ring, k.dims(4, 4))),
            one(k.holding(T(1), k.all_of(k.ring, k.dims(4, 4)))),
        ),
    ),
    _c("wo-07", WO, "two levels, the pyramid, a small one please", one(k.pyramid(2))),
    _c("wo-08", WO, "of cubes 8 a block make, 2 by 2", one(k.block(2, 2, 2))),
    _c(
        "wo-09",
        WO,
        "behind the tower of 3, the wall of 4 long 2 high, with a gap of one",
        k.pair(k.wall(4, 2), T(3), k.gap_of(1, _B)),
    ),
    _c(
        "wo-10",
        WO,
        "left a pyramid of 2 levels, right one of 3",
        _pyramid_pair_sides(2, 3, _L),
    ),
    _c(
        "wo-11",
        WO,
        "a bridge, the pillars of which are 3 high, beam across",
        one(k.bridge(3, pillars=2)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Good morning class! Phones away, please. For our first demo, the robot is going to "
        "build a tower of five cubes. Ready?",
        one(T(5)),
    ),
    _c(
        "fil-02",
        FIL,
        "hey robot uh can you like build me a um row of four thanks",
        one(k.row(4)),
    ),
    _c(
        "fil-03",
        FIL,
        "QA ticket 2231 — reference part P/N 88-104 rev B measured OK. Replicate: 2x4 slab, "
        "2 layers. Sign-off: J. Ortiz",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "fil-04",
        FIL,
        "hey 👋 quick one, can we get a staircase of 3 steps? 🙏🙏 thx!!",
        one(k.staircase(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "end of shift, dock 4 is clear, last job of the day: one stack of 6 and then we're done",
        one(T(6)),
    ),
    _c(
        "fil-06",
        FIL,
        "I've always loved Roman temples, the way the columns carry the roof — anyway, for now "
        "just a simple arch: two pillars of 2 with a beam over them.",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-07",
        FIL,
        "| job | 0042 |\n| operator | KM |\n| build | ring 5x5, 2 high |\n| notes | n/a |",
        one(k.ring_of(high=2), k.dims(5, 5)),
    ),
    _c(
        "fil-08",
        FIL,
        "okay so um what I want is uh a pyramid um three levels yeah that's it",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Remember what we learned about walls last week? Let's build one: six long, two high. "
        "Afterwards we'll talk about why bricks overlap.",
        one(k.wall(6, 2)),
    ),
    _c(
        "fil-10",
        FIL,
        "as per the manifest: block 3x3x2, handle with care, fragile",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-11",
        FIL,
        ">> forwarded from Sam: 'can the robot do an L, arms 3 each?' << yes please do that one",
        one(L_SHAPE, k.any_of(k.dims(3, 3), k.dims(4, 4))),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "replicate at datum x=0.35 y=0.40: tower, 3 units",
        one(T(3), k.near(0.35, 0.40)),
    ),
    _c(
        "reg-02",
        REG,
        "a two by two slab in the back right corner",
        one(k.block(2, 2, 1), reg("back right")),
    ),
    _c(
        "reg-03",
        REG,
        "a parapet along the back edge, six long and two high, running left to right",
        one(k.wall(6, 2), k.runs("y"), reg(_B)),
    ),
    _c(
        "reg-04",
        REG,
        "stage a 3x2 pallet, one layer, at the front left",
        one(k.block(3, 2, 1), reg("front left")),
    ),
    _c(
        "reg-05",
        REG,
        "📍 x: 0.6, y: 0.15 → pyramid 2 lvls",
        one(k.pyramid(2), k.near(0.6, 0.15)),
    ),
    _c(
        "reg-06",
        REG,
        "Let's put a 4 by 4 ring right in the middle so everyone can see it.",
        one(k.ring, k.dims(4, 4), reg("centre")),
    ),
    _c(
        "reg-07",
        REG,
        "x,y,structure\n0.30,0.45,tower 2\n0.65,0.15,tower 4",
        k.structures(
            k.all_of(T(2), k.near(0.30, 0.45)),
            k.all_of(T(4), k.near(0.65, 0.15)),
        ),
    ),
    _c(
        "reg-08",
        REG,
        "a staircase of three over on the right side near the back",
        one(k.staircase(3), reg("back right")),
    ),
    _c(
        "reg-09",
        REG,
        "a stack of 4 at the left end of the table and another stack of 4 at the right end",
        k.structures(k.all_of(T(4), reg(_L)), k.all_of(T(4), reg(_R))),
    ),
    _c(
        "reg-10",
        REG,
        "five columns along the left edge, each two high, in a line running front to back",
        # separate columns, or columns touching into one wall
        k.any_of(
            k.all_of(k.each(5, T(2), reg(_L)), k.layout(k.runs("x"))),
            one(k.wall(5, 2), k.runs("x"), reg(_L)),
        ),
    ),
    _c(
        "reg-11",
        REG,
        "replicate, positioned 10 cm left of centre: 2x2x2 block",
        # the centre taken as the usual (0.45, 0.30) or as the workspace middle (0.50, 0.30)
        one(k.block(2, 2, 2), k.near(y=0.40), k.near(x=0.475, tol=0.05)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "a little Greek-temple-like thing",
        one(k.any_of(k.canopy(), k.bridge())),
    ),
    _c(
        "open-02",
        OPEN,
        "something tall and thin for the children to measure",
        one(T(lo=4)),
    ),
    _c(
        "open-03",
        OPEN,
        "a sturdy low stack that won't tip over",
        one(k.full, k.broad, k.height(lo=1, hi=4)),
    ),
    _c("open-04", OPEN, "make something cool 😎 for the open day", k.anything),
    _c(
        "open-05",
        OPEN,
        "uh just a small wall something low",
        one(k.any_of(k.row(lo=3), k.wall(lo=3)), k.low(3), k.long(hi=8)),
    ),
    _c(
        "open-06",
        OPEN,
        "a stepped terrace",
        one(k.any_of(k.staircase(lo=2), k.pyramid(lo=2))),
    ),
    _c(
        "open-07",
        OPEN,
        "replicate: a small enclosure, roughly square",
        one(k.ring, _square, k.long(hi=7)),
    ),
    _c(
        "open-08",
        OPEN,
        "a few short stacks along the back",
        k.few(2, 6, k.all_of(T(lo=2, hi=4), reg(_B))),
    ),
    _c("open-09", OPEN, "a castle for the story corner", one(k.castle)),
    _c(
        "open-10",
        OPEN,
        "something a toy figure could walk under",
        one(k.any_of(k.bridge(), k.arch, k.canopy())),
    ),
    _c(
        "open-11",
        OPEN,
        "a big um pyramid as big as it can go",
        one(k.pyramid(lo=4)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "um uh hmm", k.refused),
    _c(
        "bad-02",
        BAD,
        "🤖🧱🧱🧱❓",
        k.honest(k.any_of(one(T(3)), one(k.row(3)))),
    ),
    _c("bad-03", BAD, "stack of 15 on the pallet", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-04", BAD, "replicate the part as per the drawing attached", k.honest()),
    _c("bad-05", BAD, "a colonnade 2 metres long", k.honest(k.anything)),
    _c("bad-06", BAD, "Build us a tower that has zero cubes in it.", k.honest()),
    _c(
        "bad-07",
        BAD,
        "type: wall\nheight: -2",
        k.honest(one(k.any_of(k.wall(lo=2), k.row(lo=2)))),
    ),
    _c("bad-08", BAD, "stop stop stop", k.honest()),
    _c("bad-09", BAD, "what's the weather like in the cell today lol", k.honest()),
    _c("bad-10", BAD, "a ring of cubes at y = 0.9", k.honest(one(k.ring))),
    _c(
        "bad-11",
        BAD,
        "a 2x2 slab floating 10 cm above the table",
        k.honest(one(k.block(2, 2, 1), k.on_table)),
    ),
    _c("bad-12", BAD, "put a tower of 5 on top of the robot", k.honest(one(T(5)))),
)
