"""A second, independent development set for the language front end.

Written without looking at the Specifier's grammar or the frozen test set, and worded apart
from the first dev set (no command shared with either, see tests): new vocabulary (pad, pen,
lintel, posts, courtyard, storey, rear, mat, fort, pack), new sentence shapes (terse
shop-floor notes, passive voice, fronted relations and Yoda order, ordinal steps, references
to "it" / "them" / "the first one" / "the base"), units in mm, cm and m, British and American
spelling, typos of every kind, hedges and chit-chat.

Same `Case` type and phenomena as `language_dev`; each predicate checks parameters (counts per
level, footprints in cubes, heights, number of separate structures, relations, regions),
accepting every reasonable reading of vague wording and nothing else.

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
    return Case(id=f"dev2-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks (open wording)


def _chunky(bs: k.Boxes) -> k.Reason:
    """A solid block at least 2 × 2 in plan and at least 2 layers high."""
    a, b = bx.plan_dims(bs)
    if a < 2 or bx.thickness_cubes(bs) < 2:
        return f"not chunky: {a}×{b}×{bx.thickness_cubes(bs)}"
    return k.full(bs)


def _small_ring(bs: k.Boxes) -> k.Reason:
    """An enclosure no bigger than 4 × 4 cubes outside and at most 2 high."""
    r = k.ring(bs)
    if r:
        return r
    a, b = bx.plan_dims(bs)
    if b > 4 or bx.thickness_cubes(bs) > 2:
        return f"not small: {a}×{b}×{bx.thickness_cubes(bs)}"
    return None


def _big_square_grid(bs: k.Boxes) -> k.Reason:
    """One full layer, square, at least 4 × 4."""
    a, b = bx.plan_dims(bs)
    if a != b or a < 4 or bx.thickness_cubes(bs) != 1:
        return f"not a big square grid: {a}×{b}×{bx.thickness_cubes(bs)}"
    return k.full(bs)


def _large_mat(bs: k.Boxes) -> k.Reason:
    """One full layer at least 3 × 3 and at least 12 cubes of area."""
    a, b = bx.plan_dims(bs)
    if bx.thickness_cubes(bs) != 1 or a < 3 or a * b < 12:
        return f"not a large mat: {a}×{b}×{bx.thickness_cubes(bs)}"
    return k.full(bs)


def _sturdy_base(bs: k.Boxes) -> k.Reason:
    """A solid base at least 2 × 2 in plan."""
    return k.broad(bs) or k.full(bs)


def _pack(n: int, tight: bool = False) -> k.Check:
    """A solid box of exactly n cubes, at least 2 × 2 in plan and no side over 4 cubes; when
    `tight`, as near a cube as it goes (no side more than one cube longer than another)."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.parts(n)(bs) or k.full(bs)
        if r:
            return r
        sides = (*bx.footprint_cubes(bs), bx.thickness_cubes(bs))
        if min(sides[:2]) < 2 or max(sides) > 4:
            return f"not a pack: {sides[0]}×{sides[1]}×{sides[2]}"
        if tight and max(sides) > min(sides) + 1:
            return f"not tight: {sides[0]}×{sides[1]}×{sides[2]}"
        return None

    return f


T = k.tower
one = k.one

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "stack a 3-cube tower on the middle of a 3x3 pad",
        one(k.on_top(T(3), k.block(3, 3, 1))),
    ),
    _c(
        "rel-02",
        REL,
        "a tower of four standing to the left of a five-cube row",
        k.beside(T(4), k.row(5), _L),
    ),
    _c("rel-03", REL, "span a beam across two 3-high columns", one(k.bridge(3, pillars=2))),
    _c("rel-04", REL, "fence in a 2-cube tower with a ring of cubes", k.around(T(2))),
    _c("rel-05", REL, "put a 2x2 block inside an enclosure", k.around(k.solid(2, 2))),
    _c(
        "rel-06",
        REL,
        "a pyramid sitting beside a wall, on the wall's right",
        k.beside(k.pyramid(lo=2), k.wall(), _R),
    ),
    _c(
        "rel-07",
        REL,
        "a 4-cube tower with a 3-step staircase in front of it",
        k.any_of(
            k.beside(k.staircase(3), T(4), _F),
            # the stairs built against the tower's front, leading up to it
            one(k.staircase(4), k.rises(_B)),
        ),
    ),
    _c("rel-08", REL, "lay a beam over a pair of two-cube stacks", one(k.bridge(2, pillars=2))),
    _c("rel-09", REL, "put one cube on top of a tower of three", one(T(4))),
    _c("rel-10", REL, "set a 3-cube row on top of another 3-cube row", one(k.block(1, 3, 2))),
    _c(
        "rel-11",
        REL,
        "a castle with a single cube in its courtyard",
        k.around(T(1), k.castle),
    ),
    _c(
        "rel-12",
        REL,
        "a T shape and, left of it, an L shape",
        k.beside(k.shape_letter("L"), k.shape_letter("T"), _L),
    ),
    _c(
        "rel-13",
        REL,
        "a gate made of two 4-cube posts and a lintel",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "rel-14",
        REL,
        "a two-layer ring around a two-level pyramid",
        k.around(k.pyramid(2), k.ring_of(high=2)),
    ),
    _c(
        "rel-15",
        REL,
        "a 2-cube tower beside a pyramid with a 3x3 base, on the pyramid's left",
        k.beside(T(2), k.all_of(k.pyramid(lo=2), k.base(3, 3)), _L),
    ),
    _c(
        "rel-16",
        REL,
        "a wall 5 long and 2 high with a tower of 3 in front of it",
        k.beside(T(3), k.wall(5, 2), _F),
    ),
    _c(
        "rel-17",
        REL,
        "a 4-cube row with a cube on each end",
        # a cube stood on each end, or one added at each end (a row of 6)
        one(k.any_of(k.profile(2, 1, 1, 2), k.row(6))),
    ),
    _c(
        "rel-18",
        REL,
        "a canopy held up by four 3-cube posts",
        one(k.canopy(4, 3, 3)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "First lay a 4x4 base. Second, a 3x3 on it. Third, 2x2. Fourth, one cube.",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c("seq-02", SEQ, "build a tower of 2, then make it three times as tall", one(T(6))),
    _c(
        "seq-03",
        SEQ,
        "put down two single cubes 10 cm apart, then stack two more cubes on each of them",
        k.each(2, T(3)),
    ),
    _c(
        "seq-04",
        SEQ,
        "build three towers of 2. Then add a cube to the first one.",
        k.structures(T(3), T(2), T(2)),
    ),
    _c(
        "seq-05",
        SEQ,
        "make a row of 5. Then take away the middle cube.",
        k.each(2, k.row(2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "start with a wall 4 long and 2 high, then add a third layer on it",
        one(k.wall(4, 3)),
    ),
    _c("seq-07", SEQ, "a 2x3 grid; after that, double its height", one(k.block(2, 3, 2))),
    _c("seq-08", SEQ, "build a tower of 6, then knock off the top cube", one(T(5))),
    _c(
        "seq-09",
        SEQ,
        "Make two 3-cube towers. After that put a beam across them.",
        one(k.bridge(3, pillars=2)),
    ),
    _c("seq-10", SEQ, "lay down a ring of cubes, then put a tower of 2 in it", k.around(T(2))),
    _c(
        "seq-11",
        SEQ,
        "first a row of 4 on the right, second a row of 4 on the left",
        k.any_of(
            k.structures(k.all_of(k.row(4), k.region(_R)), k.all_of(k.row(4), k.region(_L))),
            k.beside(k.row(4), k.row(4), _L, max_gap=0.5),
        ),
    ),
    _c(
        "seq-12",
        SEQ,
        "begin with the base: a 3x3 square. On the base, put a tower of 3.",
        one(k.on_top(T(3), k.block(3, 3, 1))),
    ),
    _c(
        "seq-13",
        SEQ,
        "build a staircase of 2 steps, then extend it by two more steps",
        one(k.staircase(4)),
    ),
    _c("seq-14", SEQ, "place one cube; then stack 4 more on it; then another 2", one(T(7))),
    _c(
        "seq-15",
        SEQ,
        "build a 3x3 ring, then build it up to 3 layers",
        one(k.ring_of(high=3, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "seq-16",
        SEQ,
        "two rows of three, one on top of the other, and then a third row of three on the very top",
        one(k.block(1, 3, 3)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Build a tower of 3 on the left and a tower of 5 on the right. "
        "Then make the first one as tall as the second.",
        k.any_of(
            k.structures(k.all_of(T(5), k.region(_L)), k.all_of(T(5), k.region(_R))),
            k.beside(T(5), T(5), _L, max_gap=0.5),
        ),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "nine cubes in a single stack", one(T(9))),
    _c("num-02", NUM, "a column of ten", one(T(10))),
    _c(
        "num-03",
        NUM,
        "three rows of four",
        k.any_of(k.each(3, k.row(4)), one(k.block(3, 4, 1)), one(k.wall(4, 3))),
    ),
    _c("num-04", NUM, "four towers, every one of them three high", k.each(4, T(3))),
    _c("num-05", NUM, "a couple of 3-cube towers", k.each(2, T(3))),
    _c("num-06", NUM, "a tower of seven", one(T(7))),
    _c("num-07", NUM, "two dozen cubes as a 4 by 6 slab", one(k.block(4, 6, 1))),
    _c("num-08", NUM, "a pyramid of three levels", one(k.pyramid(3))),
    _c("num-09", NUM, "5 towers, each of them 2 cubes", k.each(5, T(2))),
    _c("num-10", NUM, "a single cube", one(T(1))),
    _c("num-11", NUM, "a wall built from 12 cubes, 3 high", one(k.wall(4, 3))),
    _c(
        "num-12",
        NUM,
        "two towers, one of 2 cubes and one of 6",
        k.structures(T(2), T(6)),
    ),
    _c("num-13", NUM, "a staircase of five", one(k.staircase(5))),
    _c("num-14", NUM, "1 tower, 8 cubes", one(T(8))),
    _c("num-15", NUM, "two walls, each 3 long and 2 high", k.each(2, k.wall(3, 2))),
    _c("num-16", NUM, "a 3-storey tower", one(T(3))),
    _c("num-17", NUM, "a row of 3 and a row of 6", k.structures(k.row(3), k.row(6))),
    _c("num-18", NUM, "a pack of 18 cubes", one(_pack(18))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a tower 250 mm high", one(T(5))),
    _c("dim-02", DIM, "a slab 200 mm x 150 mm", one(k.block(4, 3, 1))),
    _c("dim-03", DIM, "a wall 0.35 m long and 0.15 m tall", one(k.wall(7, 3))),
    _c("dim-04", DIM, "a block 10 cm on each side", one(k.block(2, 2, 2))),
    _c("dim-05", DIM, "a 15cm cube built from cubes", one(k.block(3, 3, 3))),
    _c("dim-06", DIM, "a row 40cm long", one(k.row(8))),
    _c("dim-07", DIM, "a 5 x 2 x 3 block", one(k.block(5, 2, 3))),
    _c("dim-08", DIM, "a grid of 3 columns by 4 rows", one(k.block(3, 4, 1))),
    _c("dim-09", DIM, "a staircase rising 20 cm in 4 steps", one(k.staircase(4))),
    _c(
        "dim-10",
        DIM,
        "an enclosure 5 cubes on a side, 2 high",
        one(k.ring_of(high=2, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c("dim-11", DIM, "a bridge 3 cubes tall at the pillars", one(k.bridge(3))),
    _c("dim-12", DIM, "an L, each arm 4 cubes long", one(k.shape_letter("L"), k.dims(4, 4))),
    _c(
        "dim-13",
        DIM,
        "a T that is 5 across the top and 3 down the stem",
        one(k.shape_letter("T"), k.any_of(k.dims(5, 3), k.dims(5, 4))),
    ),
    _c(
        "dim-14",
        DIM,
        "a cross 5 cubes wide and 5 long",
        one(k.shape_letter("cross"), k.dims(5, 5)),
    ),
    _c("dim-15", DIM, "a row half a metre long", one(k.row(10))),
    _c(
        "dim-16",
        DIM,
        "a grid 2 cubes deep (away from the robot) and 5 cubes wide",
        one(k.block_xy(2, 5, 1)),
    ),
    _c("dim-17", DIM, "a 3-level pyramid on a 4x4 base", one(k.pyramid(3), k.base(4, 4))),
    _c("dim-18", DIM, "a tower 0.3 meters tall", one(T(6))),
    # ------------------------------------------------------------------ negation (and hedges)
    _c(
        "neg-01",
        NEG,
        "a row of 4, but don't put it on the right",
        one(k.row(4), k.not_(k.region(_R), "on the right")),
    ),
    _c("neg-02", NEG, "a tower, never taller than three cubes", one(T(lo=2, hi=3))),
    _c("neg-03", NEG, "a pyramid that is not flat", one(k.pyramid(lo=2), k.broad)),
    _c("neg-04", NEG, "two towers of 4, without a beam between them", k.each(2, T(4))),
    _c(
        "neg-05",
        NEG,
        "a staircase, not going up towards the robot",
        one(k.staircase(), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c("neg-06", NEG, "build a wall of 6 but no higher than one cube", one(k.row(6))),
    _c("neg-07", NEG, "I don't want a tower; I want a row of 5", one(k.row(5))),
    _c(
        "neg-08",
        NEG,
        "a 3x3 grid, but leave out the corners",
        one(k.shape_letter("cross"), k.parts(5), k.dims(3, 3)),
    ),
    _c(
        "neg-09",
        NEG,
        "a 3 by 3 block, not more than 2 layers",
        one(k.any_of(k.block(3, 3, 1), k.block(3, 3, 2))),
    ),
    _c("neg-10", NEG, "two 3-cube towers with no gap between them", one(k.block(1, 2, 3))),
    _c("neg-11", NEG, "a pyramid using at most 5 cubes", one(k.pyramid(lo=2), k.parts(hi=5))),
    _c(
        "neg-12",
        NEG,
        "a tower of 5, and keep it away from the front",
        one(T(5), k.not_(k.region(_F), "at the front")),
    ),
    _c("neg-13", NEG, "an enclosure that's only one cube high, not two", one(k.ring_of(high=1))),
    _c("neg-14", NEG, "a wall 5 long and 3 high, no windows or gaps", one(k.wall(5, 3))),
    _c("neg-15", NEG, "a tower that's not 3, not 5, but 4 cubes", one(T(4))),
    _c(
        "neg-16",
        NEG,
        "a row of cubes, no more than six and no fewer than four",
        one(k.row(lo=4, hi=6)),
    ),
    _c("neg-17", NEG, "a tower, probably 4 cubes, maybe 5", one(T(lo=4, hi=5))),
    _c(
        "neg-18",
        NEG,
        "put a 2x2 patch neither on the left nor on the right",
        one(
            k.block(2, 2, 1),
            k.not_(k.region(_L), "on the left"),
            k.not_(k.region(_R), "on the right"),
        ),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a towwer of 5", one(T(5))),
    _c("typo-02", TYP, "a pyramd with 3 levles", one(k.pyramid(3))),
    _c("typo-03", TYP, "a staircsae of four stepps", one(k.staircase(4))),
    _c("typo-04", TYP, "brigde on two 3-cube pilars", one(k.bridge(3, pillars=2))),
    _c("typo-05", TYP, "a wll 6 lnog and 2 hihg", one(k.wall(6, 2))),
    _c("typo-06", TYP, "a rwo of thre cubes", one(k.row(3))),
    _c("typo-07", TYP, "an encolsure arround a 2 cube towre", k.around(T(2))),
    _c("typo-08", TYP, "a 4x4 grdi", one(k.block(4, 4, 1))),
    _c("typo-09", TYP, "a castel on teh left", one(k.castle, k.region(_L))),
    _c("typo-10", TYP, "put a tower on the rihgt", one(T(lo=2), k.region(_R))),
    _c("typo-11", TYP, "a tabel with fuor legs", one(k.canopy(4))),
    _c("typo-12", TYP, "an arhc", one(k.arch)),
    _c("typo-13", TYP, "a U shaep", one(k.shape_letter("U"))),
    _c("typo-14", TYP, "a blokc 3x2x2", one(k.block(3, 2, 2))),
    _c("typo-15", TYP, "a pyremid in the centar", one(k.pyramid(lo=2), k.region("centre"))),
    _c("typo-16", TYP, "a towre of sevn", one(T(7))),
    _c("typo-17", TYP, "two stakcs of thrre", k.each(2, T(3))),
    _c("typo-18", TYP, "a crosss shape", one(k.shape_letter("cross"))),
    _c("typo-19", TYP, "a pakc of 8 cubes", one(_pack(8))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Behind the wall, a tower of 3.", k.beside(T(3), k.wall(), _B)),
    _c(
        "wo-02",
        WO,
        "To the right of a 2-cube tower goes a row of 3.",
        k.beside(k.row(3), T(2), _R),
    ),
    _c("wo-03", WO, "A tower of 5 is to be built at the back.", one(T(5), k.region(_B))),
    _c("wo-04", WO, "Stacked 6 high, one tower.", one(T(6))),
    _c("wo-05", WO, "Inside a ring of cubes, a 3-cube tower should stand.", k.around(T(3))),
    _c("wo-06", WO, "Four steps high the staircase should be.", one(k.staircase(4))),
    _c("wo-07", WO, "Joined by a beam on top, two towers of 3.", one(k.bridge(3, pillars=2))),
    _c("wo-08", WO, "Wide 4, deep 3, high 1: a grid.", one(k.block(4, 3, 1))),
    _c("wo-09", WO, "Cubes, 8 of them, in a row.", one(k.row(8))),
    _c(
        "wo-10",
        WO,
        "On the right an L, on the left a T.",
        k.any_of(
            k.structures(
                k.all_of(k.shape_letter("L"), k.region(_R)),
                k.all_of(k.shape_letter("T"), k.region(_L)),
            ),
            k.beside(k.shape_letter("T"), k.shape_letter("L"), _L, max_gap=0.5),
        ),
    ),
    _c(
        "wo-11",
        WO,
        "Next to the staircase, on its right, a tower of 2; the staircase has 3 steps.",
        k.beside(T(2), k.staircase(3), _R),
    ),
    _c("wo-12", WO, "High: 3. Long: 5. Wall.", one(k.wall(5, 3))),
    _c("wo-13", WO, "A bridge is wanted, with pillars of 4.", one(k.bridge(4))),
    _c(
        "wo-14",
        WO,
        "In the front-left corner a 2x2x2 block should be placed.",
        one(k.block(2, 2, 2), k.region("front left")),
    ),
    _c(
        "wo-15",
        WO,
        "Onto a 2x2 block of two layers goes a tower of 2.",
        one(k.on_top(T(2), k.block(2, 2, 2))),
    ),
    _c("wo-16", WO, "The tower of 4 — put it on the left.", one(T(4), k.region(_L))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "hi! hope your day's going well. could you make a wall 5 long and 2 high? cheers",
        one(k.wall(5, 2)),
    ),
    _c("fil-02", FIL, "Right then, a tower of seven please, ta", one(T(7))),
    _c(
        "fil-03",
        FIL,
        "So, erm, what I'm after is basically a pyramid, three levels, nothing more",
        one(k.pyramid(3)),
    ),
    _c("fil-04", FIL, "quick one before lunch - 2x4 grid", one(k.block(2, 4, 1))),
    _c(
        "fil-05",
        FIL,
        "Dear robot, I would be most grateful if you could assemble a bridge on two pillars "
        "of 3 cubes. Kind regards, Sam",
        one(k.bridge(3, pillars=2)),
    ),
    _c("fil-06", FIL, "lol ok so my kid wants a castle. make it happen :)", one(k.castle)),
    _c(
        "fil-07",
        FIL,
        "For the trade fair video we need something photogenic, so: a staircase of five "
        "steps, climbing to the left.",
        one(k.staircase(5), k.rises(_L)),
    ),
    _c(
        "fil-08",
        FIL,
        "note to self / robot: row of 6 cubes, front of table",
        one(k.row(6), k.region(_F)),
    ),
    _c(
        "fil-09",
        FIL,
        "If you have a minute, and only if it's no bother, put an enclosure around a single cube.",
        k.around(T(1)),
    ),
    _c(
        "fil-10",
        FIL,
        "Honestly I don't mind how, just need a 3 by 3 by 2 block, thank you so much!!!",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-11",
        FIL,
        "yeah so like, a U shape i guess, you know the kind",
        one(k.shape_letter("U")),
    ),
    _c(
        "fil-12",
        FIL,
        "Morning team. Agenda item 3: the robot builds a cross shape. Agenda item 4: coffee.",
        one(k.shape_letter("cross")),
    ),
    _c(
        "fil-13",
        FIL,
        "We've had a long week, so let's keep it simple: two 2-cube towers, that's all.",
        k.each(2, T(2)),
    ),
    _c(
        "fil-14",
        FIL,
        "btw the camera's been recalibrated. anyway, a table with four legs 2 high, thx",
        one(k.canopy(4, 2, 2)),
    ),
    _c("fil-15", FIL, "Per work order #4471, an arch, please.", one(k.arch)),
    _c(
        "fil-16",
        FIL,
        "OK robot, listen carefully: I need a tower of 3 cubes. Got it? Good.",
        one(T(3)),
    ),
    _c(
        "fil-17",
        FIL,
        "Following up on my email from Tuesday (sorry for the delay!) - could the cell put "
        "together an L-shape, 3 by 3? Many thanks, and have a lovely weekend.",
        one(k.shape_letter("L"), k.dims(3, 3)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower 4 @ x .5", one(T(4), k.near(x=0.5))),
    _c("reg-02", REG, "back-left: tower of 2", one(T(2), k.region("back left"))),
    _c("reg-03", REG, "a 3x2 grid towards the rear", one(k.block(3, 2, 1), k.region(_B))),
    _c("reg-04", REG, "a row of 5 close to the robot", one(k.row(5), k.region(_F))),
    _c(
        "reg-05",
        REG,
        "a pyramid at the rear right",
        one(k.pyramid(lo=2), k.region("back right")),
    ),
    _c("reg-06", REG, "put a wall along the left edge", one(k.wall(), k.region(_L))),
    _c("reg-07", REG, "tower of 3 at (0.3, 0.4)", one(T(3), k.near(0.3, 0.4))),
    _c("reg-08", REG, "stairs at the front right", one(k.staircase(), k.region("front right"))),
    _c("reg-09", REG, "a ring dead centre", one(k.ring, k.region("centre"))),
    _c(
        "reg-10",
        REG,
        "near the robot on the left side, a tower of 5",
        one(T(5), k.region("front left")),
    ),
    _c("reg-11", REG, "a 2x2x2 block at y = 0.45", one(k.block(2, 2, 2), k.near(y=0.45))),
    _c("reg-12", REG, "a bridge placed centrally", one(k.bridge(), k.region("centre"))),
    _c(
        "reg-13",
        REG,
        "a tower of 6 in the center of the table and a row of 3 at the back",
        k.structures(k.all_of(T(6), k.region("centre")), k.all_of(k.row(3), k.region(_B))),
    ),
    _c(
        "reg-14",
        REG,
        "an L shape over on the right hand side",
        one(k.shape_letter("L"), k.region(_R)),
    ),
    _c(
        "reg-15",
        REG,
        "put a 2 cube tower 40 cm out from the robot, 10 cm left of centre",
        one(T(2), k.near(0.40, 0.40)),
    ),
    _c("reg-16", REG, "tower at x 600 mm y 150 mm", one(T(lo=2), k.near(0.6, 0.15))),
    _c(
        "reg-17",
        REG,
        "on the left-hand side at the very back, a castle",
        one(k.castle, k.region("back left")),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a skinny tower", one(T(lo=2))),
    _c("open-02", OPEN, "a chunky block", one(_chunky)),
    _c(
        "open-03",
        OPEN,
        "a low wall",
        one(k.any_of(k.all_of(k.wall(lo=3), k.height(lo=2, hi=3)), k.row(lo=3))),
    ),
    _c("open-04", OPEN, "a tiny pyramid", one(k.pyramid(2), k.parts(hi=5))),
    _c("open-05", OPEN, "a really big flight of stairs", one(k.staircase(lo=4))),
    _c("open-06", OPEN, "a small enclosure", one(_small_ring)),
    _c("open-07", OPEN, "a tall, thin wall", one(k.wall(), k.height(lo=4))),
    _c("open-08", OPEN, "a long row", one(k.row(lo=6))),
    _c("open-09", OPEN, "a little tunnel", one(k.arch)),
    _c("open-10", OPEN, "a few towers", k.few(2, 5, T(lo=2))),
    _c("open-11", OPEN, "a big square grid", one(_big_square_grid)),
    _c("open-12", OPEN, "a little fort", one(k.ring)),
    _c(
        "open-13",
        OPEN,
        "a sturdy base with a tall tower on it",
        one(k.on_top(T(lo=3), _sturdy_base)),
    ),
    _c("open-14", OPEN, "a large mat of cubes, one layer", one(_large_mat)),
    _c("open-15", OPEN, "a handful of cubes in a line", one(k.row(lo=3, hi=6))),
    _c("open-16", OPEN, "stairs, not too many steps", one(k.staircase(lo=2, hi=4))),
    _c("open-17", OPEN, "something tall", one(k.height(lo=4))),
    _c("open-18", OPEN, "a doorway", one(k.arch)),
    _c(
        "open-19",
        OPEN,
        "pack twelve cubes together as tightly as you can",
        one(_pack(12, tight=True)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "jfkdls;a fjdksla", k.refused),
    _c("bad-02", BAD, "Costruisci una torre di quattro cubi", k.honest(one(T(4)))),
    _c(
        "bad-03",
        BAD,
        "Fais un mur de cinq cubes",
        k.honest(one(k.any_of(k.row(5), k.wall()))),
    ),
    _c("bad-04", BAD, "a tower 15 cubes tall", k.honest(one(T(lo=2, hi=10)))),
    _c("bad-05", BAD, "a row of 20 cubes", k.honest(one(k.row(lo=2, hi=12)))),
    _c(
        "bad-06",
        BAD,
        "a single tower that is both 3 and 6 cubes tall",
        k.honest(one(k.any_of(T(3), T(6)))),
    ),
    _c("bad-07", BAD, "put a tower at y = 0.9", k.honest(one(T(lo=1)))),
    _c("bad-08", BAD, "???", k.refused),
    _c("bad-09", BAD, "1234567890", k.refused),
    _c("bad-10", BAD, "a pyramid with a 12 by 12 base", k.honest(one(k.pyramid(lo=2)))),
    _c("bad-11", BAD, "a staircase of 15 steps", k.honest(one(k.staircase(lo=2, hi=10)))),
    _c("bad-12", BAD, "build a tower on the ceiling", k.honest(one(T(lo=1)))),
    _c("bad-13", BAD, "make me a sandwich", k.honest()),
    _c("bad-14", BAD, "<script>alert(1)</script>", k.refused),
    _c("bad-15", BAD, "搭一个三层的塔", k.honest(one(T(3)))),
    _c("bad-16", BAD, "a tower of 1e9 cubes", k.honest(one(T(lo=2, hi=10)))),
    _c(
        "bad-17",
        BAD,
        "a ring with nothing inside it and a tower inside it",
        k.honest(k.any_of(one(k.ring), k.around(T(lo=1)))),
    ),
    _c("bad-18", BAD, "a tower 3 cubes tall at x = 0.1 m", k.honest(one(T(3)))),
    _c(
        "bad-19",
        BAD,
        "a wall 4 long, 2 high and 7 long",
        k.honest(one(k.any_of(k.wall(4, 2), k.wall(7, 2)))),
    ),
)
