"""Development set for the language front end: commands as robot-cell operators type them.

Written independently of the Specifier's grammar. The engineer may tune on these; the frozen
`language_test` set is for the final verdict. Each case's predicate checks parameters (counts,
footprints in cubes, heights, number of structures, relations, regions), accepting every
reasonable reading of a vague command and nothing else.
"""

from __future__ import annotations

from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = "left", "right", "front", "back"


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev-{id_}", phenomenon=phenomenon, text=text, accept=accept)


def _tall_wide_base(bs: k.Boxes) -> k.Reason:
    from sdi.bench import boxes as bx

    counts = bx.level_counts(bs)
    if bx.thickness_cubes(bs) < 3:
        return "under 3 cubes tall"
    if bx.plan_dims(bs)[1] < 2 or counts[0] <= counts[-1]:
        return f"base not wider than the top (levels {counts})"
    return None


def _compact(bs: k.Boxes) -> k.Reason:
    from sdi.bench import boxes as bx

    a, b = bx.plan_dims(bs)
    return None if b <= 3 and bx.thickness_cubes(bs) <= 3 and a >= 2 else "not compact"


def _low_wide(bs: k.Boxes) -> k.Reason:
    from sdi.bench import boxes as bx

    a, b = bx.plan_dims(bs)
    if bx.thickness_cubes(bs) != 1 or a < 2 or b < 3:
        return f"not low and wide: {a}×{b}×{bx.thickness_cubes(bs)}"
    return k.full(bs)


def _big_block(bs: k.Boxes) -> k.Reason:
    from sdi.bench import boxes as bx

    if len(bs) < 8 or bx.plan_dims(bs)[0] < 2:
        return f"not big: {len(bs)} parts, footprint {bx.plan_dims(bs)}"
    return k.full(bs)


REL = "relation"
SEQ = "sequence"
NUM = "numbers"
DIM = "dimensions"
NEG = "negation"
TYP = "typo"
WO = "word_order"
FIL = "filler"
REG = "region"
OPEN = "open"
BAD = "bad_input"

T = k.tower
one = k.one

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "put a 2-cube tower on top of a 3 by 3 slab",
        one(k.on_top(T(2), k.block(3, 3, 1))),
    ),
    _c(
        "rel-02",
        REL,
        "a tower of 3 cubes on the left and a row of 4 cubes on the right",
        k.beside(T(3), k.row(4), _L, max_gap=0.5),
    ),
    _c(
        "rel-03",
        REL,
        "two pillars, four cubes each, with a beam across the top",
        one(k.bridge(4, pillars=2)),
    ),
    _c("rel-04", REL, "make a pen of cubes around a 3-high stack", k.around(T(3))),
    _c(
        "rel-05", REL, "place a column of 5 cubes between two 2-cube stacks", k.between_(T(5), T(2))
    ),
    _c(
        "rel-06",
        REL,
        "build a wall, and right next to it on its left side a tower of 4",
        k.beside(T(4), k.wall(), _L),
    ),
    _c(
        "rel-07",
        REL,
        "a gate: two 3-cube posts joined at the top by a beam",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "rel-08",
        REL,
        "a 2x2 block two layers high with a single cube sitting on top",
        one(k.on_top(T(1), k.block(2, 2, 2))),
    ),
    _c("rel-09", REL, "a ring of cubes with a small tower inside it", k.around(T(lo=2, hi=4))),
    _c(
        "rel-10",
        REL,
        "a staircase of 3 steps in front of a tower of 5",
        k.beside(k.staircase(3), T(5), _F),
    ),
    _c("rel-11", REL, "connect two 3-cube towers with a beam", one(k.bridge(3, pillars=2))),
    _c("rel-12", REL, "a row of five cubes behind a 3-cube tower", k.beside(k.row(5), T(3), _B)),
    _c(
        "rel-13",
        REL,
        "put a 3 by 2 grid to the right of a pyramid",
        k.beside(k.block(3, 2), k.pyramid(), _R),
    ),
    _c("rel-14", REL, "an enclosure with a pyramid inside", k.around(k.pyramid())),
    _c(
        "rel-15",
        REL,
        "a tower of 2 on top of a 4-long wall that is 2 high",
        one(k.on_top(T(2), k.wall(4, 2))),
    ),
    _c(
        "rel-16",
        REL,
        "a cross of cubes with a 2-cube tower next to it on the right",
        k.beside(T(2), k.shape_letter("cross"), _R),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "lay a row of 4, then add a second row on top of it", one(k.block(1, 4, 2))),
    _c(
        "seq-02",
        SEQ,
        "first build a 3x3 square, then put a 2x2 square on it, then a single cube on the very top",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c("seq-03", SEQ, "start with a tower of 2. Then add two more cubes to it.", one(T(4))),
    _c(
        "seq-04",
        SEQ,
        "make a row of 3 cubes; after that, stack another cube on each end",
        one(k.profile(2, 1, 2)),
    ),
    _c(
        "seq-05",
        SEQ,
        "build a tower of 3, then a second identical tower beside it",
        k.any_of(k.each(2, T(3)), one(k.block(1, 2, 3))),
    ),
    _c(
        "seq-06",
        SEQ,
        "put down a 2 by 2 pad, then build each level like the one below until it is 3 high",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "seq-07",
        SEQ,
        "a staircase: start with 3 cubes in a row, then 2 on top from one end, then 1 on top",
        one(k.staircase(3)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Lay out a row of six cubes. Next, stack a row of four on top, centred. "
        "Finally one row of two on top of that.",
        one(k.flat, k.pyramid_counts(6, 4, 2)),
    ),
    _c("seq-09", SEQ, "build a tower of 5, then take the top two off again", one(T(3))),
    _c(
        "seq-10",
        SEQ,
        "place two cubes a little apart, then bridge them with a beam",
        one(k.bridge(1, pillars=2)),
    ),
    _c("seq-11", SEQ, "make a 3 cube column and then make it two cubes taller", one(T(5))),
    _c(
        "seq-12",
        SEQ,
        "first the left tower of 4, then the right tower of 2",
        k.beside(T(4), T(2), _L, max_gap=0.5),
    ),
    _c(
        "seq-13",
        SEQ,
        "Step 1: a 4x1 row. Step 2: on top of it, another 4x1 row. Step 3: a third one.",
        one(k.block(1, 4, 3)),
    ),
    _c(
        "seq-14",
        SEQ,
        "build a square ring of cubes one layer high, and then raise it by another layer",
        one(k.ring_of(high=2)),
    ),
    _c(
        "seq-15",
        SEQ,
        "begin with a 2-step staircase and keep adding steps until it has 4",
        one(k.staircase(4)),
    ),
    _c(
        "seq-16",
        SEQ,
        "first a ring of cubes, then a tower of 3 in the middle of it",
        k.around(T(3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "two eight-cube stacks", k.each(2, T(8))),
    _c("num-02", NUM, "6 cubes into a single column", one(T(6))),
    _c("num-03", NUM, "four legs, each three cubes tall, with a flat top", one(k.canopy(4, 3, 3))),
    _c(
        "num-04",
        NUM,
        "eighteen cubes into a block three long and three wide",
        one(k.block(3, 3, 2)),
    ),
    _c("num-05", NUM, "three towers of two cubes", k.each(3, T(2))),
    _c("num-06", NUM, "a row of seven", one(k.row(7))),
    _c("num-07", NUM, "a pair of 5-high towers", k.each(2, T(5))),
    _c("num-08", NUM, "a dozen cubes in one straight line", one(k.row(12))),
    _c(
        "num-09",
        NUM,
        "build 3 stacks: one of 1, one of 2 and one of 3 cubes",
        k.any_of(k.structures(T(1), T(2), T(3)), one(k.staircase(3))),
    ),
    _c(
        "num-10",
        NUM,
        "a tower twice as tall as the 3-cube tower next to it",
        k.any_of(k.beside(T(6), T(3)), one(k.profile(6, 3))),
    ),
    _c("num-11", NUM, "half a dozen cubes stacked up", one(T(6))),
    _c("num-12", NUM, "a wall of ten cubes, five long", one(k.wall(5, 2))),
    _c("num-13", NUM, "a pyramid with a 4 by 4 base", one(k.pyramid(lo=2), k.base(4, 4))),
    _c("num-14", NUM, "two bridges, each on pillars three cubes high", k.each(2, k.bridge(3))),
    _c(
        "num-15",
        NUM,
        "a 2-step staircase and a 4-step staircase",
        k.structures(k.staircase(2), k.staircase(4)),
    ),
    _c("num-16", NUM, "a bridge with three spans", one(k.bridge(pillars=4))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a block 3 wide, 2 deep and 2 high", one(k.block(3, 2, 2))),
    _c("dim-02", DIM, "a slab five across and three deep, one cube thick", one(k.block(5, 3, 1))),
    _c("dim-03", DIM, "a 2 by 3 grid, 2 high", one(k.block(2, 3, 2))),
    _c("dim-04", DIM, "a 10 cm by 10 cm square three layers high", one(k.block(2, 2, 3))),
    _c("dim-05", DIM, "a pad 0.15 m by 0.10 m, two layers deep", one(k.block(3, 2, 2))),
    _c("dim-06", DIM, "a wall 6 cubes long and 3 cubes high", one(k.wall(6, 3))),
    _c("dim-07", DIM, "a tower 20 cm tall", one(T(4))),
    _c("dim-08", DIM, "a 4x4 patch", one(k.block(4, 4, 1))),
    _c("dim-09", DIM, "a 3x3x3 cube made of cubes", one(k.block(3, 3, 3))),
    _c("dim-10", DIM, "a row 25 cm long", one(k.row(5))),
    _c("dim-11", DIM, "a wall 30 cm long and 10 cm high", one(k.wall(6, 2))),
    _c("dim-12", DIM, "a platform 4 by 2, single layer", one(k.block(4, 2, 1))),
    _c(
        "dim-13",
        DIM,
        "a staircase 4 steps high and 2 cubes wide",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c("dim-14", DIM, "a 1x5 line of cubes", one(k.row(5))),
    _c("dim-15", DIM, "an enclosure measuring 4 by 4 on the outside", one(k.ring, k.dims(4, 4))),
    _c("dim-16", DIM, "a U shape, 4 wide and 3 deep", one(k.shape_letter("U"), k.dims(3, 4))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "put three cubes side by side, don't stack them",
        k.any_of(one(k.row(3)), k.each(3, T(1))),
    ),
    _c("neg-02", NEG, "a tower but not too tall", one(T(lo=2, hi=5))),
    _c(
        "neg-03",
        NEG,
        "a tower that is not on the left",
        one(T(lo=2), k.not_(k.region(_L), "on the left")),
    ),
    _c(
        "neg-04",
        NEG,
        "a 3x3 grid without the middle cube",
        one(k.ring_of(high=1, inner=(1, 1)), k.parts(8)),
    ),
    _c(
        "neg-05",
        NEG,
        "a wall 5 long, no taller than 2 cubes",
        k.any_of(one(k.wall(5, 2)), one(k.row(5))),
    ),
    _c("neg-06", NEG, "a staircase with no more than 3 steps", one(k.staircase(lo=2, hi=3))),
    _c("neg-07", NEG, "a pyramid, but not a 3-D one, just flat", one(k.pyramid(lo=2), k.flat)),
    _c("neg-08", NEG, "build a tower of 4, not 5", one(T(4))),
    _c(
        "neg-09",
        NEG,
        "put a tower of 3 anywhere except the back",
        one(T(3), k.not_(k.region(_B), "at the back")),
    ),
    _c("neg-10", NEG, "two towers of 3 — they must not touch", k.each(2, T(3))),
    _c("neg-11", NEG, "an enclosure with no roof and nothing inside", one(k.ring)),
    _c("neg-12", NEG, "a 2x2x2 block, no beams, only cubes", one(k.block(2, 2, 2), k.only_cubes)),
    _c(
        "neg-13",
        NEG,
        "a tower that isn't in the middle",
        one(T(lo=2), k.not_(k.region("centre"), "in the middle")),
    ),
    _c("neg-14", NEG, "not a tower: a flat 2 by 2 patch", one(k.block(2, 2, 1))),
    _c("neg-15", NEG, "no bridge, just two separate 3-cube pillars", k.each(2, T(3))),
    _c(
        "neg-16",
        NEG,
        "a castle without the corner towers, just the wall around",
        one(k.ring, k.not_(k.castle, "has corner towers")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a tiny brige", one(k.bridge(lo=1, hi=2))),
    _c("typo-02", TYP, "a towr of 4", one(T(4))),
    _c("typo-03", TYP, "a stiarcase with 3 stpes", one(k.staircase(3))),
    _c("typo-04", TYP, "buidl a piramid", one(k.pyramid(lo=2))),
    _c("typo-05", TYP, "a 3 by 3 gird", one(k.block(3, 3, 1))),
    _c("typo-06", TYP, "a wal 5 long 2 high", one(k.wall(5, 2))),
    _c("typo-07", TYP, "an enclousre around a tower", k.around(T(lo=1))),
    _c("typo-08", TYP, "two towres of 3", k.each(2, T(3))),
    _c("typo-09", TYP, "a row of fvie cubes", one(k.row(5))),
    _c("typo-10", TYP, "put a toewr on the lfet", one(T(lo=2), k.region(_L))),
    _c("typo-11", TYP, "a brdige between two towers of three", one(k.bridge(3, pillars=2))),
    _c("typo-12", TYP, "a caslte", one(k.castle)),
    _c("typo-13", TYP, "tower of 3 at teh back", one(T(3), k.region(_B))),
    _c("typo-14", TYP, "a 2x2x2 blcok", one(k.block(2, 2, 2))),
    _c("typo-15", TYP, "an L shpae", one(k.shape_letter("L"))),
    _c("typo-16", TYP, "a cros shape", one(k.shape_letter("cross"))),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "Back right corner: a 2x2 patch. Front left: a tower three high.",
        k.structures(
            k.all_of(k.block(2, 2), k.region("back right")), k.all_of(T(3), k.region("front left"))
        ),
    ),
    _c("wo-02", WO, "On the left, a row of 4.", one(k.row(4), k.region(_L))),
    _c("wo-03", WO, "Three cubes high, that's the tower I want.", one(T(3))),
    _c("wo-04", WO, "Out of cubes, a wall 4 long and 3 high.", one(k.wall(4, 3))),
    _c("wo-05", WO, "At the back, stairs with 3 steps.", one(k.staircase(3), k.region(_B))),
    _c("wo-06", WO, "Four cubes tall and on the right: a tower.", one(T(4), k.region(_R))),
    _c("wo-07", WO, "In the middle goes a pyramid.", one(k.pyramid(lo=2), k.region("centre"))),
    _c("wo-08", WO, "5 long, 1 high, 1 deep: a row.", one(k.row(5))),
    _c("wo-09", WO, "On top of two 2-cube towers, a beam.", one(k.bridge(2, pillars=2))),
    _c("wo-10", WO, "Around a single cube, a ring.", k.around(T(1))),
    _c(
        "wo-11",
        WO,
        "Left side a tower of 5, right side a tower of 2.",
        k.beside(T(5), T(2), _L, max_gap=0.5),
    ),
    _c("wo-12", WO, "x = 0.6, y = 0.2: a 3-cube tower.", one(T(3), k.near(0.6, 0.2))),
    _c(
        "wo-13",
        WO,
        "A 3 by 3 grid is what I need, on the front side.",
        one(k.block(3, 3), k.region(_F)),
    ),
    _c(
        "wo-14",
        WO,
        "Stairs, four steps, climbing towards the back.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c("wo-15", WO, "Two of them, each 4 cubes high: towers.", k.each(2, T(4))),
    _c("wo-16", WO, "A castle, on the right.", one(k.castle, k.region(_R))),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "Could you please build a tower of 3 cubes for me? Thanks!", one(T(3))),
    _c(
        "fil-02",
        FIL,
        "hey robot, for the demo today we need a 3x2 grid, cheers",
        one(k.block(3, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "I'd like, if it's not too much trouble, a staircase with four steps.",
        one(k.staircase(4)),
    ),
    _c("fil-04", FIL, "ok so basically just a row of 5 cubes, nothing fancy", one(k.row(5))),
    _c(
        "fil-05",
        FIL,
        "Good morning! Please stack four cubes into a tower on the left. "
        "The visitors arrive at 10.",
        one(T(4), k.region(_L)),
    ),
    _c(
        "fil-06",
        FIL,
        "umm, can we get like two towers of 2 joined by a bridge? that'd be great",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-07",
        FIL,
        "For the open day: a pyramid, please, the 3-D kind.",
        one(k.pyramid(lo=2), k.broad),
    ),
    _c(
        "fil-08", FIL, "Right, the customer wants a ring of cubes, as soon as you can.", one(k.ring)
    ),
    _c("fil-09", FIL, "please please please a tower of 6", one(T(6))),
    _c(
        "fil-10",
        FIL,
        "I know it's late but could you put a 2x2 block, 2 high, at the back before you go",
        one(k.block(2, 2, 2), k.region(_B)),
    ),
    _c(
        "fil-11",
        FIL,
        "Testing the new cell - build a wall 4 long and 2 high, then we'll see.",
        one(k.wall(4, 2)),
    ),
    _c("fil-12", FIL, "So my boss says: make an arch. Any size is fine.", one(k.arch)),
    _c("fil-13", FIL, "Kindly construct a 4-cube tower. Regards, the lab team", one(T(4))),
    _c("fil-14", FIL, "Just a quick one: three cubes in a row, thanks a lot!", one(k.row(3))),
    _c(
        "fil-15",
        FIL,
        "as discussed in the meeting, a 3x3 pad, nothing else, ok?",
        one(k.block(3, 3, 1)),
    ),
    _c("fil-16", FIL, "pls just a T shape, whatever size, ty", one(k.shape_letter("T"))),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "a tower of 3 on the left", one(T(3), k.region(_L))),
    _c(
        "reg-02",
        REG,
        "a 2x2 grid in the back left corner",
        one(k.block(2, 2), k.region("back left")),
    ),
    _c("reg-03", REG, "a row of 4 along the front", one(k.row(4), k.region(_F))),
    _c("reg-04", REG, "a pyramid in the centre", one(k.pyramid(lo=2), k.region("centre"))),
    _c(
        "reg-05",
        REG,
        "a 3-step staircase on the right-hand side",
        one(k.staircase(3), k.region(_R)),
    ),
    _c("reg-06", REG, "a tower of 4 at x 0.6 m, y 0.4 m", one(T(4), k.near(0.6, 0.4))),
    _c("reg-07", REG, "a wall at the back, 5 long", one(k.wall(5), k.region(_B))),
    _c(
        "reg-08",
        REG,
        "put a tower of 2 in the front right corner",
        one(T(2), k.region("front right")),
    ),
    _c(
        "reg-09",
        REG,
        "a tower of 3 on the left and another one on the right",
        k.any_of(
            k.structures(k.all_of(T(3), k.region(_L)), k.all_of(T(3), k.region(_R))),
            k.beside(T(3), T(3), _L),
        ),
    ),
    _c(
        "reg-10",
        REG,
        "a 3x3 slab as close to the IRB120 as it can go",
        one(k.block(3, 3), k.region(_F)),
    ),
    _c("reg-11", REG, "a tower as far back as possible", one(T(lo=2), k.region(_B))),
    _c("reg-12", REG, "a bridge in the back right", one(k.bridge(), k.region("back right"))),
    _c("reg-13", REG, "a ring near the left edge of the table", one(k.ring, k.region(_L))),
    _c("reg-14", REG, "a tower of 5 at x = 45 cm", one(T(5), k.near(x=0.45))),
    _c("reg-15", REG, "a row of 3 in the middle of the table", one(k.row(3), k.region("centre"))),
    _c("reg-16", REG, "an arch at the front", one(k.arch, k.region(_F))),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a tall structure with a wide base", one(_tall_wide_base)),
    _c("open-02", OPEN, "something small", k.layout(k.parts(lo=1, hi=6))),
    _c("open-03", OPEN, "a tall tower", one(T(lo=5, hi=10))),
    _c("open-04", OPEN, "a small tower", one(T(lo=2, hi=4))),
    _c("open-05", OPEN, "a big block", one(_big_block)),
    _c("open-06", OPEN, "a long wall", one(k.wall(lo=5))),
    _c("open-07", OPEN, "a low, wide platform", one(_low_wide)),
    _c("open-08", OPEN, "a few cubes in a row", one(k.row(lo=3, hi=5))),
    _c("open-09", OPEN, "a short staircase", one(k.staircase(lo=2, hi=3))),
    _c(
        "open-10",
        OPEN,
        "a little shelter a toy could stand under",
        one(k.any_of(k.canopy(), k.bridge())),
    ),
    _c("open-11", OPEN, "some stairs", one(k.staircase())),
    _c("open-12", OPEN, "a gateway a cube could pass under", one(k.bridge(lo=1))),
    _c("open-13", OPEN, "a tower as tall as the cell allows", one(T(lo=7, hi=10))),
    _c("open-14", OPEN, "a compact pile of 8 cubes", one(k.parts(8), _compact)),
    _c("open-15", OPEN, "a wide, flat pyramid", one(k.pyramid(lo=2), k.long(lo=3))),
    _c("open-16", OPEN, "a little table for a teddy bear", one(k.canopy())),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "asdf qwerty zxcv", k.refused),
    _c("bad-02", BAD, "Baue einen Turm aus drei Würfeln", k.honest(one(T(3)))),
    _c("bad-03", BAD, "a 3-cube tower 5 cubes tall", k.honest(k.any_of(one(T(3)), one(T(5))))),
    _c("bad-04", BAD, "a 500-cube tower", k.honest(one(T(lo=2, hi=10)))),
    _c("bad-05", BAD, "build a tower " + "la " * 700, k.honest(one(T(lo=2)))),
    _c("bad-06", BAD, "", k.refused),
    _c("bad-07", BAD, "    ", k.refused),
    _c("bad-08", BAD, "a tower of -3 cubes", k.honest(one(T(lo=1)))),
    _c("bad-09", BAD, "a tower of 0 cubes", k.honest()),
    _c("bad-10", BAD, "a tower of 2.5 cubes", k.honest(one(T(lo=2, hi=3)))),
    _c("bad-11", BAD, "a tower at x = 5 m", k.honest(one(T(lo=1)))),
    _c("bad-12", BAD, "a 20 by 20 grid", k.honest(one(k.full))),
    _c("bad-13", BAD, "a bridge with no pillars", k.honest(one(k.bridge()))),
    _c("bad-14", BAD, "\U0001f642\U0001f642\U0001f642", k.refused),
    _c("bad-15", BAD, "SELECT * FROM cubes WHERE colour = 'red';", k.refused),
    _c(
        "bad-16",
        BAD,
        "a row of 3 that is also a tower of 3",
        k.honest(k.any_of(one(k.row(3)), one(T(3)))),
    ),
)
