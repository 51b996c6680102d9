"""A fourth development set for the language front end (dev4): a new user's first hour.

Written without looking at the Specifier's grammar, its tests or the frozen test set, and worded
apart from `language_dev`, `language_dev2` and `language_dev3` (no command shared with any set,
see tests). Where dev3 leans on hard phenomena, dev4 is weighted to the ordinary requests an
operator types on day one — about 60 % plain commands (one or two structures with a size, a
place, a simple relation such as on top of / next to / around / joined by a beam, a two-step
sequence, a negation, a typo, a unit) and about 40 % harder ones (corrections, references,
three-part layouts, unusual units, vague size words, unusable input).

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
    return Case(id=f"dev4-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks (on boxes)


def _top_centred(bs: k.Boxes) -> k.Reason:
    """The highest level sits over the middle of the footprint (within a quarter cube)."""
    if not bs:
        return "no parts"
    z = max(round(b.lo[2], 3) for b in bs)
    top = [b for b in bs if round(b.lo[2], 3) == z]
    (tx, ty), (cx, cy) = bx.centre(top), bx.centre(bs)
    if abs(tx - cx) > 0.013 or abs(ty - cy) > 0.013:
        return f"top level centred at ({tx:.3f}, {ty:.3f}), footprint centre ({cx:.3f}, {cy:.3f})"
    return None


def _side(n: int) -> k.Check:
    """One plan side is n cubes."""

    def f(bs: k.Boxes) -> k.Reason:
        d = bx.plan_dims(bs)
        return None if n in d else f"footprint {d[0]}×{d[1]}, want a side of {n}"

    return f


def _corners_empty(bs: k.Boxes) -> k.Reason:
    """The four corner cells of the footprint are empty."""
    cs = bx.cells(bs)
    if not cs:
        return "no parts"
    xs, ys = [c[0] for c in cs], [c[1] for c in cs]
    corners = {(x, y) for x in (min(xs), max(xs)) for y in (min(ys), max(ys))}
    full_corners = corners & cs
    return None if not full_corners else f"{len(full_corners)} corner cells filled"


def _wide(n: int) -> k.Check:
    """The longer plan side is at least n cubes."""
    return k.long(lo=n)


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE, U_SHAPE, T_SHAPE, CROSS = (k.shape_letter(s) for s in ("L", "U", "T", "cross"))
PYR3D = k.all_of(k.pyramid(lo=2), k.broad)

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "put a tower of 3 cubes on top of a 3x3 slab",
        one(k.on_top(T(3), k.block(3, 3, 1))),
    ),
    _c("rel-02", REL, "a 2-cube tower next to a row of 4 cubes", k.beside(T(2), k.row(4))),
    _c("rel-03", REL, "a square fence of cubes around a 2-high tower", k.around(T(2))),
    _c(
        "rel-04",
        REL,
        "two 2-cube stacks joined at the top by a beam",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "rel-05",
        REL,
        "one cube sitting on top of a 2x2 block",
        one(k.on_top(T(1), k.solid(2, 2))),
    ),
    _c("rel-06", REL, "a 3-level pyramid beside a 4-long wall", k.beside(k.pyramid(3), k.wall(4))),
    _c(
        "rel-07",
        REL,
        "a wall 5 long and 2 high, with a tower of 4 behind it",
        k.beside(T(4), k.wall(5, 2), _B),
    ),
    _c(
        "rel-08",
        REL,
        "a 2 by 2 pad in front of a 3-step staircase",
        k.beside(k.block(2, 2, 1), k.staircase(3), _F),
    ),
    _c("rel-09", REL, "a ring around a 2x2 block", k.around(k.solid(2, 2))),
    _c(
        "rel-10",
        REL,
        "a single cube placed between two 4-cube towers",
        k.between_(T(1), T(4)),
    ),
    _c(
        "rel-11",
        REL,
        "a tower of 3 on the left of a cross",
        k.beside(T(3), CROSS, _L),
    ),
    _c(
        "rel-12",
        REL,
        "a tower of 5 to the right of an L shape",
        k.beside(T(5), L_SHAPE, _R),
    ),
    _c(
        "rel-13",
        REL,
        "a 2-level pyramid standing on a 4x4 slab",
        one(k.on_top(k.pyramid(2), k.block(4, 4, 1))),
    ),
    _c(
        "rel-14",
        REL,
        "a row of 4 with one extra cube stacked on each end",
        one(k.profile(2, 1, 1, 2)),
    ),
    _c("rel-15", REL, "a T and an L side by side", k.beside(T_SHAPE, L_SHAPE)),
    _c(
        "rel-16",
        REL,
        "a two-high ring with a small pyramid inside",
        k.around(k.pyramid(lo=2), k.ring_of(high=2)),
    ),
    _c(
        "rel-17",
        REL,
        "a 3 by 3 grid and, right behind it, a wall of the same width 3 high",
        k.any_of(
            k.beside(k.wall(3, 3), k.block(3, 3, 1), _B),
            one(k.levels(12, 3, 3), k.dims(3, 4)),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "a beam laid across two towers of 4 with a cube on the middle of the beam",
        one(k.bridge(4, pillars=2), k.parts(10), _top_centred),
    ),
    _c(
        "rel-19",
        REL,
        "Make a 2x2 pad and a tower of 5. Set the pad to the left of the tower.",
        k.beside(k.block(2, 2, 1), T(5), _L),
    ),
    _c(
        "rel-20",
        REL,
        "a flat roof held up by four 3-cube legs",
        one(k.canopy(4, 3, 3)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "build a tower of 3, then a row of 3 next to it",
        k.beside(T(3), k.row(3)),
    ),
    _c(
        "seq-02",
        SEQ,
        "first lay a 2x3 pad, then add a second layer on it",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "stack four cubes and then put two more on top",
        one(T(6)),
    ),
    _c(
        "seq-04",
        SEQ,
        "lay out a 3x3 grid; next, place one cube on its centre",
        one(k.on_top(T(1), k.block(3, 3, 1)), _top_centred),
    ),
    _c(
        "seq-05",
        SEQ,
        "make two towers of 3 and then lay a beam over them",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "build a ring of cubes, after that put a 3-cube tower inside it",
        k.around(T(3)),
    ),
    _c(
        "seq-07",
        SEQ,
        "a wall 4 long and 2 high; then raise it by one more layer",
        one(k.wall(4, 3)),
    ),
    _c(
        "seq-08",
        SEQ,
        "put up a tower of 5, then take the top two cubes off",
        one(T(3)),
    ),
    _c(
        "seq-09",
        SEQ,
        "lay a row of 6 and then make it two layers tall",
        one(k.wall(6, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "build a 3-level pyramid, then a second identical one to its right",
        k.beside(k.pyramid(3), k.pyramid(3), _R),
    ),
    _c(
        "seq-11",
        SEQ,
        "make an L shape and after that a T shape beside it",
        k.beside(L_SHAPE, T_SHAPE),
    ),
    _c(
        "seq-12",
        SEQ,
        "first a bridge on 2-cube pillars, then stand a 2-cube tower on the beam",
        one(k.bridge(2, pillars=2), k.parts(7)),
    ),
    _c(
        "seq-13",
        SEQ,
        "a row of 5 cubes; now remove the middle one",
        k.each(2, k.row(2)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Put down three separate cubes in a line. Then stack another cube on the first one.",
        k.structures(T(2), T(1), T(1)),
    ),
    _c(
        "seq-15",
        SEQ,
        "start with a 4x4 slab, then put a 2x2 slab on it, then a single cube on top of that",
        one(k.pyramid_counts(16, 4, 1)),
    ),
    _c(
        "seq-16",
        SEQ,
        "build a tower of 6, and afterwards move it to the back of the table",
        one(T(6), reg(_B)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "half a dozen cubes in a row", one(k.row(6))),
    _c("num-02", NUM, "a pair of 3-cube towers", k.each(2, T(3))),
    _c("num-03", NUM, "nine cubes laid out as a square", one(k.block(3, 3, 1))),
    _c("num-04", NUM, "a tower twice as tall as 3 cubes", one(T(6))),
    _c("num-05", NUM, "a wall of 3 courses, 4 cubes per course", one(k.wall(4, 3))),
    _c(
        "num-06",
        NUM,
        "three towers, of 1, 2 and 3 cubes",
        k.structures(T(1), T(2), T(3)),
    ),
    _c("num-07", NUM, "a pyramid four levels tall", one(k.pyramid(4))),
    _c("num-08", NUM, "a 3x4 grid of cubes", one(k.block(3, 4, 1))),
    _c("num-09", NUM, "a couple of towers, 2 cubes each", k.each(2, T(2))),
    _c("num-10", NUM, "tower, n = 7", one(T(7))),
    _c(
        "num-11",
        NUM,
        "two rows of five cubes",
        k.any_of(k.each(2, k.row(5)), one(k.block(2, 5, 1))),
    ),
    _c("num-12", NUM, "a tower of one cube less than eight", one(T(7))),
    _c("num-13", NUM, "five towers of a single cube each", k.each(5, T(1))),
    _c("num-14", NUM, "a staircase of 5 steps", one(k.staircase(5))),
    _c(
        "num-15",
        NUM,
        "use exactly 8 cubes to make a 2x2 block",
        one(k.block(2, 2, 2)),
    ),
    _c("num-16", NUM, "a quadruple stack of cubes", one(T(4))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "make me a tower that is 20 cm tall", one(T(4))),
    _c("dim-02", DIM, "a row of cubes 30 cm long", one(k.row(6))),
    _c("dim-03", DIM, "a 10 x 10 cm pad", one(k.block(2, 2, 1))),
    _c("dim-04", DIM, "a wall 25 cm long and 10 cm tall", one(k.wall(5, 2))),
    _c("dim-05", DIM, "a tower 150 mm high", one(T(3))),
    _c("dim-06", DIM, "a square slab 0.15 m on each side", one(k.block(3, 3, 1))),
    _c("dim-07", DIM, "a bridge with pillars 10 cm high", one(k.bridge(2, pillars=2))),
    _c("dim-08", DIM, "a grid 20 cm by 15 cm", one(k.block(4, 3, 1))),
    _c("dim-09", DIM, "a cube of cubes 10 cm on every side", one(k.block(2, 2, 2))),
    _c("dim-10", DIM, "a staircase that ends 20 cm above the table", one(k.staircase(4))),
    _c("dim-11", DIM, "a column of cubes 3 dm tall", one(T(6))),
    _c("dim-12", DIM, "a row 0.4 m long", one(k.row(8))),
    _c(
        "dim-13",
        DIM,
        "a ring 20 cm across, one cube high",
        one(
            k.ring_of(high=1),
            k.any_of(
                k.all_of(k.dims(4, 4), k.ring_of(inner=(2, 2))),
                k.all_of(k.dims(6, 6), k.ring_of(inner=(4, 4))),
            ),
        ),
    ),
    _c("dim-14", DIM, "a tower about four inches tall", one(T(2))),
    _c(
        "dim-15",
        DIM,
        "a staircase of 4 steps, 10 cm wide",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c(
        "dim-16",
        DIM,
        "a table 15 cm square with legs 5 cm high",
        one(k.canopy(lo=1, hi=1), k.dims(3, 3)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 4, but not on the left side",
        one(T(4), not_(reg(_L), "on the left")),
    ),
    _c("neg-02", NEG, "a row of 5 cubes, no beams please", one(k.row(5), k.only_cubes)),
    _c(
        "neg-03",
        NEG,
        "a 3x3 grid without the centre cube",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c("neg-04", NEG, "not a tower, a row of 4 cubes", one(k.row(4))),
    _c(
        "neg-05",
        NEG,
        "two 3-cube towers that do not touch",
        k.each(2, T(3)),
    ),
    _c("neg-06", NEG, "a staircase with 3 steps, not 4", one(k.staircase(3))),
    _c("neg-07", NEG, "a cross, not an L", one(CROSS)),
    _c("neg-08", NEG, "a pyramid that isn't flat", one(PYR3D)),
    _c(
        "neg-09",
        NEG,
        "a wall 5 long that is no taller than 2 cubes",
        one(k.any_of(k.wall(5, 2), k.row(5))),
    ),
    _c(
        "neg-10",
        NEG,
        "a 2x2x2 block and nothing else on the table",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "neg-11",
        NEG,
        "a tower of 5. Actually no, make it 6.",
        one(T(6)),
    ),
    _c(
        "neg-12",
        NEG,
        "a bridge, but don't put it near the robot",
        one(k.bridge(), not_(reg(_F), "near the robot")),
    ),
    _c(
        "neg-13",
        NEG,
        "a ring of cubes with nothing in the middle",
        one(k.ring),
    ),
    _c(
        "neg-14",
        NEG,
        "an arch with no beam, only cubes",
        one(k.arch, k.only_cubes),
    ),
    _c(
        "neg-15",
        NEG,
        "a 4x4 slab but leave out its four corner cubes",
        one(k.dims(4, 4), k.parts(12), k.only_cubes, k.low(1), _corners_empty),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "biuld a towr of 4 cubez", one(T(4))),
    _c("typo-02", TYP, "a rwo of 6", one(k.row(6))),
    _c("typo-03", TYP, "a pyarmid of three levles", one(k.pyramid(3))),
    _c("typo-04", TYP, "a wal 4 lnog 3 high", one(k.wall(4, 3))),
    _c("typo-05", TYP, "a brige with two pilars of 3", one(k.bridge(3, pillars=2))),
    _c("typo-06", TYP, "a 3x3 gird", one(k.block(3, 3, 1))),
    _c("typo-07", TYP, "a stiarcase with 4 setps", one(k.staircase(4))),
    _c("typo-08", TYP, "a ring arund a tower of 2", k.around(T(2))),
    _c("typo-09", TYP, "a tower of 3 on top off a 2x2 pad", one(k.on_top(T(3), k.block(2, 2, 1)))),
    _c("typo-10", TYP, "a crosss shpae please", one(CROSS)),
    _c("typo-11", TYP, "two towres of fvie", k.each(2, T(5))),
    _c("typo-12", TYP, "an enclousre 2 high", one(k.ring_of(high=2))),
    _c("typo-13", TYP, "a tower of 3 nxet to a tower of 2", k.beside(T(3), T(2))),
    _c("typo-14", TYP, "a 2x4 blcok 2 layres high", one(k.block(2, 4, 2))),
    _c("typo-15", TYP, "a castel", one(k.castle)),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "of five cubes, a tower", one(T(5))),
    _c("wo-02", WO, "3 high, 4 long: a wall", one(k.wall(4, 3))),
    _c("wo-03", WO, "on the right, a pyramid with 3 levels", one(k.pyramid(3), reg(_R))),
    _c("wo-04", WO, "cubes, 7 of them, in a row", one(k.row(7))),
    _c("wo-05", WO, "2 by 3, a pad", one(k.block(2, 3, 1))),
    _c(
        "wo-06",
        WO,
        "on top of a 3x3 pad, a tower of 2",
        one(k.on_top(T(2), k.block(3, 3, 1))),
    ),
    _c("wo-07", WO, "around a tower of 3, a ring", k.around(T(3))),
    _c("wo-08", WO, "steps: 5. shape: staircase.", one(k.staircase(5))),
    _c(
        "wo-09",
        WO,
        "with a beam across the top, two towers of 2",
        one(k.bridge(2, pillars=2)),
    ),
    _c("wo-10", WO, "at the back, a tower of 4 I want", one(T(4), reg(_B))),
    _c(
        "wo-11",
        WO,
        "next to the L, a tower of 3; the L first",
        k.beside(T(3), L_SHAPE),
    ),
    _c("wo-12", WO, "three layers high the block should be, 2 by 2", one(k.block(2, 2, 3))),
    _c(
        "wo-13",
        WO,
        "behind a row of 3, a wall of 3 that is 2 high",
        k.beside(k.wall(3, 2), k.row(3), _B),
    ),
    _c("wo-14", WO, "a U, 4 wide, please", one(U_SHAPE, _side(4))),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "hey, could you make a tower of 4 for me? thanks!", one(T(4))),
    _c(
        "fil-02",
        FIL,
        "Good morning! I'd like to see the robot build a small bridge, two pillars of two "
        "cubes and a beam on top. Cheers",
        one(k.bridge(2, pillars=2)),
    ),
    _c("fil-03", FIL, "ok so basically just a row of 5 cubes, that's all", one(k.row(5))),
    _c(
        "fil-04",
        FIL,
        "I'm just testing this out - let's try a 3x3 pad, nothing special",
        one(k.block(3, 3, 1)),
    ),
    _c("fil-05", FIL, "please please build a pyramid with 3 levels :)", one(k.pyramid(3))),
    _c(
        "fil-06",
        FIL,
        "first time using this, sorry if it's wrong... a wall, 4 long, 2 high?",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-07",
        FIL,
        "My manager asked me to get the robot to make a cross shape for the demo tomorrow. "
        "Can it do that?",
        one(CROSS),
    ),
    _c(
        "fil-08",
        FIL,
        "Task for today: staircase, four steps. Thank you in advance.",
        one(k.staircase(4)),
    ),
    _c("fil-09", FIL, "alright robot, show me a 2x2 block 2 high", one(k.block(2, 2, 2))),
    _c(
        "fil-10",
        FIL,
        "if it's not too much trouble, I would like two towers of 3 next to each other",
        k.any_of(k.beside(T(3), T(3)), one(k.wall(2, 3))),
    ),
    _c("fil-11", FIL, "let's see... maybe a ring, 2 cubes high, yeah", one(k.ring_of(high=2))),
    _c(
        "fil-12",
        FIL,
        "Note to operator: the gripper was recalibrated this morning. Build an L shape, "
        "3 by 3, and check the corners.",
        one(L_SHAPE, k.dims(3, 3)),
    ),
    _c(
        "fil-13",
        FIL,
        "so the thing is I need a table - four legs of 2 cubes and a flat top - for a photo",
        one(k.canopy(4, 2, 2)),
    ),
    _c("fil-14", FIL, "quick one: tower of 8, go", one(T(8))),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "a tower of 3 on the left side of the table", one(T(3), reg(_L))),
    _c("reg-02", REG, "a row of 4 at the front", one(k.row(4), reg(_F))),
    _c(
        "reg-03",
        REG,
        "a 2x2 pad in the middle of the workspace",
        one(k.block(2, 2, 1), reg("centre")),
    ),
    _c("reg-04", REG, "a pyramid of 3 levels at the back", one(k.pyramid(3), reg(_B))),
    _c("reg-05", REG, "a wall 5 long on the right", one(k.wall(5), reg(_R))),
    _c(
        "reg-06", REG, "a staircase in the back right corner", one(k.staircase(), reg("back right"))
    ),
    _c("reg-07", REG, "a cube in the front left corner", one(T(1), reg("front left"))),
    _c(
        "reg-08",
        REG,
        "a tower of 4 at x = 0.5 m, y = 0.3 m",
        one(T(4), k.near(0.5, 0.3)),
    ),
    _c(
        "reg-09",
        REG,
        "a 3x3 grid centred at 400 mm, 200 mm",
        one(k.block(3, 3, 1), k.near(0.4, 0.2)),
    ),
    _c(
        "reg-10",
        REG,
        "one tower of 2 at the front and one tower of 2 at the back",
        k.structures(k.all_of(T(2), reg(_F)), k.all_of(T(2), reg(_B))),
    ),
    _c(
        "reg-11",
        REG,
        "a row of 5 running left to right across the back",
        one(k.row(5), k.runs("y"), reg(_B)),
    ),
    _c(
        "reg-12",
        REG,
        "a bridge far from the robot",
        one(k.bridge(), reg(_B)),
    ),
    _c(
        "reg-13",
        REG,
        "a row of 4 going away from the robot, on the left",
        one(k.row(4), k.runs("x"), reg(_L)),
    ),
    _c(
        "reg-14",
        REG,
        "a castle right in the centre",
        one(k.castle, reg("centre")),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a smallish tower, nothing big", one(T(lo=2, hi=4))),
    _c("open-02", OPEN, "a really tall stack of cubes", one(T(lo=5, hi=10))),
    _c("open-03", OPEN, "a low little wall, just knee height for a mouse", one(k.wall(), k.low(2))),
    _c("open-04", OPEN, "a nice long line of cubes", one(k.row(lo=6))),
    _c("open-05", OPEN, "a little bridge", one(k.bridge(lo=1, hi=3))),
    _c("open-06", OPEN, "a simple arch", one(k.arch)),
    _c("open-07", OPEN, "a table", one(k.canopy())),
    _c("open-08", OPEN, "a big grid", one(k.full, k.broad, k.low(1), _wide(4))),
    _c("open-09", OPEN, "some steps going up", one(k.staircase())),
    _c("open-10", OPEN, "a pyramid", one(k.pyramid(lo=2))),
    _c(
        "open-11",
        OPEN,
        "a box shape to keep something in",
        # an enclosure, or one standing on a solid floor (a tray)
        one(k.any_of(k.ring, k.on_top(k.ring, k.full))),
    ),
    _c("open-12", OPEN, "a gate", one(k.any_of(k.bridge(), k.arch))),
    _c("open-13", OPEN, "a pyramid that is wide and not very high", one(k.pyramid(lo=2), _wide(4))),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "asdf qwer zxcv", k.refused),
    _c("bad-02", BAD, "ok thanks bye", k.refused),
    _c("bad-03", BAD, "Construis une tour de quatre cubes", k.honest(one(T(4)))),
    _c("bad-04", BAD, "Bau einen Turm aus drei Würfeln", k.honest(one(T(3)))),
    _c("bad-05", BAD, "a tower of 15 cubes", k.honest(one(T(lo=2, hi=10)))),
    _c("bad-06", BAD, "stack minus three cubes", k.honest(one(T(3)))),
    _c("bad-07", BAD, "a row 2 metres long", k.honest(one(k.row(lo=2, hi=12)))),
    _c("bad-08", BAD, "build it again", k.honest()),
    _c(
        "bad-09",
        BAD,
        "a tower of 3.5 cubes",
        k.honest(k.any_of(one(T(3)), one(T(4)))),
    ),
    _c("bad-10", BAD, "a tower of 3 at x = 1.5 m", k.honest(one(T(3)))),
    _c("bad-11", BAD, "what's the weather like?", k.refused),
    _c(
        "bad-12",
        BAD,
        "a wall 3 long and 6 long",
        k.honest(k.any_of(one(k.wall(3)), one(k.wall(6)))),
    ),
    _c("bad-13", BAD, "a tower made of spheres", k.honest(one(T(lo=2)))),
)
