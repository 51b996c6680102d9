"""A sixth development set for the language front end (dev6): the production floor.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev5` (no command shared with
any set, see tests). The commands come from people on a production floor — shift workers leaving
handover notes, line leads on the radio, QA inspectors, maintenance engineers writing in mm and
inches — and are weighted about 65 % ordinary (one or two structures, a size, a place, one
relation or a two-step sequence, a negation, a typo, a unit) to 35 % harder (corrections,
references to the structure just described, distributive phrases such as "a cube on each end",
comparisons, corner towers, three-part layouts, vague size words, unusable input).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks` and the few local checks below.

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
    return Case(id=f"dev6-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _taller_on(side: str) -> Rel:
    """A stands on `side` of B and is taller than B."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        if bx.side_of(a, b) != side:
            return f"the taller one is {bx.side_of(a, b)} of the other, want {side}"
        ha, hb = bx.thickness_cubes(a), bx.thickness_cubes(b)
        return None if ha > hb else f"heights {ha} and {hb}: the {side} one is not taller"

    return rel


def _centred_on(upper: k.Check, lower: k.Check) -> k.Check:
    """`lower` is the bottom level; `upper` (everything above) stands on it, footprint centres
    within 1 cm."""

    def f(bs: k.Boxes) -> k.Reason:
        z0 = min(b.lo[2] for b in bs)
        below = [b for b in bs if b.lo[2] <= z0 + bx.TOL]
        above = [b for b in bs if b.lo[2] > z0 + bx.TOL]
        if not above:
            return "nothing on top"
        r = lower(below) or upper(above)
        if r:
            return r
        if not bx.stands_on(above, below):
            return "the upper part does not rest on the lower"
        (ux, uy), (lx, ly) = bx.centre(above), bx.centre(below)
        if abs(ux - lx) > 0.01 or abs(uy - ly) > 0.01:
            return "the upper part is off centre"
        return None

    return f


def _tight_ring(inner: k.Check) -> k.Check:
    """A one-high ring built tight against what it surrounds (so the two touch): the border
    cells of the bottom level form a closed ring, and everything else passes `inner`."""

    def f(bs: k.Boxes) -> k.Reason:
        lo, hi = bx.bounds(bs)
        edge = [
            b
            for b in bs
            if b.lo[2] <= lo[2] + bx.TOL
            and b.hi[2] <= lo[2] + bx.CUBE + bx.TOL
            and (
                b.lo[0] <= lo[0] + bx.TOL
                or b.hi[0] >= hi[0] - bx.TOL
                or b.lo[1] <= lo[1] + bx.TOL
                or b.hi[1] >= hi[1] - bx.TOL
            )
        ]
        rest = [b for b in bs if b not in edge]
        if not rest:
            return "nothing inside the ring"
        return k.ring(edge) or inner(rest)

    return f


def _podium(bs: k.Boxes) -> k.Reason:
    """Three full columns in a line, three different heights (a winners' podium)."""
    fx, fy = bx.footprint_cubes(bs)
    if min(fx, fy) != 1 or max(fx, fy) != 3:
        return f"footprint {fx}×{fy}, want 1×3"
    prof = bx.step_profile(bs, 0 if fx > fy else 1)
    if len(set(prof)) != 3:
        return f"heights {prof}, want three different"
    return None if len(bx.voxels(bs)) == sum(prof) else "columns not full"


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
        "tower of four behind the 3x3 pad, leave about a hand's width between them",
        k.beside(T(4), k.block(3, 3, 1), _B),
    ),
    _c(
        "rel-02",
        REL,
        "two 2-high towers with a three-cube row running between them",
        k.any_of(k.between_(k.row(3), T(2)), one(k.profile(2, 1, 1, 1, 2))),
    ),
    _c(
        "rel-03",
        REL,
        "U shape goes on the left, and the L on the right of it",
        k.beside(L_SHAPE, U_SHAPE, _R),
    ),
    _c(
        "rel-04",
        REL,
        "on a 3x3 slab, dead centre, stand a 2-cube tower",
        one(_centred_on(T(2), k.block(3, 3, 1))),
    ),
    _c(
        "rel-05",
        REL,
        "gate with two posts 4 high and a beam over them; a 2-cube tower behind the gate",
        k.beside(T(2), k.bridge(4, pillars=2), _B),
    ),
    _c(
        "rel-06",
        REL,
        "3-level pyramid with a ring of cubes all the way round it",
        # a free ring, or one laid tight against the pyramid's base (the two then touch)
        k.any_of(k.around(k.pyramid(3)), one(_tight_ring(k.pyramid(3)))),
    ),
    _c(
        "rel-07",
        REL,
        "lay a row of 5 cubes and sit one more cube on each end of it",
        one(k.profile(2, 1, 1, 1, 2)),
    ),
    _c(
        "rel-08",
        REL,
        "two towers, the left one taller than the right one",
        k.pair(T(), T(), _taller_on(_L)),
    ),
    _c(
        "rel-09",
        REL,
        "a tower of 5 standing inside a pen that has a 3 by 3 floor",
        k.around(T(5), k.ring_of(inner=(3, 3))),
    ),
    _c(
        "rel-10",
        REL,
        "2-step staircase in front of a wall that's 4 long and 3 high",
        k.beside(k.staircase(2), k.wall(4, 3), _F),
    ),
    _c(
        "rel-11",
        REL,
        "3-level pyramid, and on its right a row of 4 running front to back",
        k.beside(k.all_of(k.row(4), k.runs("x")), k.pyramid(3), _R),
    ),
    _c(
        "rel-12",
        REL,
        "a 3 tower at the front and a 6 tower directly behind it",
        k.any_of(
            k.beside(T(6), T(3), _B),
            one(k.xprofile(3, 6)),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "4x4 slab with a 3-high tower on each of its corners",
        one(k.base(4, 4), k.parts(16 + 12), k.corner_columns(3)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "row of 6, left to right. then take the two end cubes off",
        one(k.row(4), k.runs("y")),
    ),
    _c(
        "seq-02",
        SEQ,
        "lay a 2x3 pad... on second thought make it 3x3",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "tower of 4 at the back left. after that, the same again at the back right",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    _c(
        "seq-04",
        SEQ,
        "lay a 4x4 base, then a 2x2 layer centred on it, then one cube on the very top",
        one(k.pyramid_counts(16, 4, 1)),
    ),
    _c(
        "seq-05",
        SEQ,
        "two towers of 3 with a one-cube gap, then bridge them with a beam",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "put up a 5-long wall two courses tall, then bump it up another course",
        one(k.wall(5, 3)),
    ),
    _c("seq-07", SEQ, "stack 6 cubes. remove the top half.", one(T(3))),
    _c(
        "seq-08",
        SEQ,
        "ring of cubes, one high, 4 by 4 on the outside. then a cube on each corner on top",
        one(k.ring, k.dims(4, 4), k.levels(12, 4), k.corner_columns(1)),
    ),
    _c(
        "seq-09",
        SEQ,
        "A 3 cube tower. Now another one the same height directly to its left, touching it",
        one(k.wall(2, 3), k.runs("y")),
    ),
    _c("seq-10", SEQ, "put a T shape down, then slide it to the front", one(T_SHAPE, reg(_F))),
    _c(
        "seq-11",
        SEQ,
        "start with a 3 by 3 grid. take out the middle cube. then add a second layer the same",
        one(k.ring_of(high=2, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "seq-12",
        SEQ,
        "build a pyramid of 3 levels, then knock the top cube off",
        one(k.pyramid(2)),
    ),
    _c(
        "seq-13",
        SEQ,
        "2-cube tower at the front. put another one like it behind it",
        k.any_of(k.beside(T(2), T(2), _B), one(k.wall(2, 2), k.runs("x"))),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "a tower of a half dozen cubes", one(T(6))),
    _c("num-02", NUM, "rows: 3 of them, 5 cubes each, spaced out", k.each(3, k.row(5))),
    _c(
        "num-03",
        NUM,
        "a couple of small towers, two cubes apiece",
        k.any_of(k.each(2, T(2)), one(k.wall(2, 2))),
    ),
    _c("num-04", NUM, "wall: eighteen cubes, 6 per course", one(k.wall(6, 3))),
    _c("num-05", NUM, "a staircase going up to a height of four", one(k.staircase(4))),
    _c("num-06", NUM, "a 3x3 block, three layers (27 cubes)", one(k.block(3, 3, 3))),
    _c(
        "num-07",
        NUM,
        "4 separate single cubes in a line",
        k.each(4, T(1)),
    ),
    _c("num-08", NUM, "a stack double the height of a 3-cube one", one(T(6))),
    _c(
        "num-09",
        NUM,
        "one 2x2 pad and one 3x3 pad, not touching",
        k.structures(k.block(2, 2, 1), k.block(3, 3, 1)),
    ),
    _c("num-10", NUM, "a bridge on pillars of nine cubes each", one(k.bridge(9, pillars=2))),
    _c("num-11", NUM, "10 cubes in a line, flat on the table, all touching", one(k.row(10))),
    _c(
        "num-12",
        NUM,
        "two towers: one of 2, the other 3 more than that",
        k.any_of(k.structures(T(2), T(5)), one(k.profile(2, 5))),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "tower, 6 in tall", one(T(3))),
    _c("dim-02", DIM, "lay out a 10-inch row of cubes", one(k.row(5))),
    _c("dim-03", DIM, "pad 0.1 x 0.2 m", one(k.block(2, 4, 1))),
    _c("dim-04", DIM, "wall, length 20cm, height 15cm", one(k.wall(4, 3))),
    _c("dim-05", DIM, "a solid block 100 mm on every side", one(k.block(2, 2, 2))),
    _c("dim-06", DIM, "staircase, total height 200 mm", one(k.staircase(4))),
    _c(
        "dim-07",
        DIM,
        "a tower of cubes roughly a third of a metre tall",
        one(T(lo=6, hi=7)),
    ),
    _c(
        "dim-08",
        DIM,
        "enclosure 30 by 30 cm outside dimensions, one cube high",
        one(k.ring_of(high=1), k.dims(6, 6)),
    ),
    _c(
        "dim-09",
        DIM,
        "slab 15 cm wide (left to right) and 25 cm deep",
        one(k.block_xy(5, 3, 1)),
    ),
    _c("dim-10", DIM, "a pyramid 15 cm tall", one(k.pyramid(3))),
    _c("dim-11", DIM, "bridge, the pillars should come up to 20cm", one(k.bridge(4, pillars=2))),
    _c(
        "dim-12",
        DIM,
        "a 2x2 column 3/10 of a metre high",
        one(k.block(2, 2, 6)),
    ),
    # ------------------------------------------------------------------ negation
    _c("neg-01", NEG, "4-high tower, not on the right side", one(T(4), not_(reg(_R), "right"))),
    _c("neg-02", NEG, "a 3x4 pad - don't use beams", one(k.block(3, 4, 1), k.only_cubes)),
    _c("neg-03", NEG, "tower of 5. not 4, FIVE", one(T(5))),
    _c(
        "neg-04",
        NEG,
        "a row of 4 that does NOT run left to right",
        one(k.row(4), k.runs("x")),
    ),
    _c("neg-05", NEG, "two towers of 2 that aren't touching each other", k.each(2, T(2))),
    _c("neg-06", NEG, "a 5x5 ring with no gaps in it", one(k.ring, k.dims(5, 5))),
    _c(
        "neg-07",
        NEG,
        "staircase of 4 that doesn't go up towards the back",
        one(k.staircase(4), not_(k.rises(_B), "climbs to the back")),
    ),
    _c(
        "neg-08",
        NEG,
        "a 3x3 slab minus its middle cube",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "neg-09",
        NEG,
        "nothing taller than 2 cubes: a 2 x 4 block",
        one(k.any_of(k.block(2, 4, 1), k.block(2, 4, 2))),
    ),
    _c(
        "neg-10",
        NEG,
        "wall 6 long and 2 high, but leave out the two cubes at the top ends",
        one(k.profile(1, 2, 2, 2, 2, 1)),
    ),
    _c(
        "neg-11",
        NEG,
        "anywhere but the front: a 2-level pyramid",
        one(k.pyramid(2), not_(reg(_F), "at the front")),
    ),
    _c(
        "neg-12",
        NEG,
        "a tower of 3 — and don't put it in the middle",
        one(T(3), not_(reg("centre"), "in the middle")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "stak 4 cubse into a towr", one(T(4))),
    _c("typo-02", TYP, "a rwo of cubse, 6 lnog", one(k.row(6))),
    _c("typo-03", TYP, "a 3x3 pda in teh back", one(k.block(3, 3, 1), reg(_B))),
    _c("typo-04", TYP, "brige, pillers 3 high", one(k.bridge(3, pillars=2))),
    _c("typo-05", TYP, "pyramind, jsut 2 levles", one(k.pyramid(2))),
    _c("typo-06", TYP, "stiarcase pls, 5 stesp", one(k.staircase(5))),
    _c("typo-07", TYP, "wll 4 lon 3 hgh", one(k.wall(4, 3))),
    _c(
        "typo-08",
        TYP,
        "a rign around a singel cube",
        # a free cube inside, or a 3x3 outline whose middle cell the cube fills
        k.any_of(k.around(T(1)), one(k.dims(3, 3), k.parts(9), k.low(1), k.only_cubes)),
    ),
    _c("typo-09", TYP, "a crosss shaep in the midle plz", one(CROSS, reg("centre"))),
    _c("typo-10", TYP, "an L shpe, both arms 4 cubes", one(L_SHAPE, k.dims(4, 4))),
    _c(
        "typo-11",
        TYP,
        "two towres of 3, one behnid the other",
        k.any_of(k.beside(T(3), T(3), _B), one(k.wall(2, 3), k.runs("x"))),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "of five cubes, a tower, at the back", one(T(5), reg(_B))),
    _c(
        "wo-02",
        WO,
        "left side of the table the staircase goes, 3 steps",
        one(k.staircase(3), reg(_L)),
    ),
    _c(
        "wo-03", WO, "3 deep by 3 wide, single layer, that's the grid i want", one(k.block(3, 3, 1))
    ),
    _c("wo-04", WO, "pillars of 2, beam on top, bridge", one(k.bridge(2, pillars=2))),
    _c(
        "wo-05",
        WO,
        "behind, a tower of 4 - in front of it, a 2x2 pad",
        k.beside(T(4), k.block(2, 2, 1), _B),
    ),
    _c("wo-06", WO, "6 by 6 and one course high: a ring", one(k.ring_of(high=1), k.dims(6, 6))),
    _c("wo-07", WO, "on the right put the wall, 5 long 2 high", one(k.wall(5, 2), reg(_R))),
    _c(
        "wo-08",
        WO,
        "top level one cube, bottom level 3x3, pyramid",
        one(k.any_of(k.pyramid_counts(9, 4, 1), k.pyramid_counts(9, 1))),
    ),
    _c("wo-09", WO, "tall, 7 cubes, the tower", one(T(7))),
    _c("wo-10", WO, "in front a T, please", one(T_SHAPE, reg(_F))),
    _c("wo-11", WO, "long side left to right, 2 by 5, a slab", one(k.block_xy(2, 5, 1))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Shift handover: line 3 down for maintenance (unrelated). Robot cell needs a 4-cube "
        "tower for the camera calibration. Cheers, Dave",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok so basically what I need, and sorry if this is obvious, is a row of five cubes",
        one(k.row(5)),
    ),
    _c(
        "fil-03",
        FIL,
        "QA here - audit tomorrow. Please build a 3-level pyramid so we can check placement "
        "accuracy, thanks in advance!!",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-04",
        FIL,
        "radio check... over. build a bridge, pillars 2 high. over and out",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-05",
        FIL,
        "I know it's late and everyone's tired but could you pop a 2 by 2 pad down? Appreciate it.",
        one(k.block(2, 2, 1)),
    ),
    _c(
        "fil-06",
        FIL,
        "just so you know the coffee machine's broken again lol. anyway: staircase, 4 steps",
        one(k.staircase(4)),
    ),
    _c(
        "fil-07",
        FIL,
        "As discussed in this morning's stand-up, and per ticket #4411, we need a ring of cubes "
        "2 high.",
        one(k.ring_of(high=2)),
    ),
    _c("fil-08", FIL, "yo. cross. thx", one(CROSS)),
    _c(
        "fil-09",
        FIL,
        "Dear SDI, kindly construct a wall of length 4 and height 4. Best regards, Maintenance",
        one(k.wall(4, 4)),
    ),
    _c(
        "fil-10",
        FIL,
        "for the trade show demo (booth 12, hall B) an L shape, nothing else needed right now",
        one(L_SHAPE),
    ),
    _c(
        "fil-11",
        FIL,
        "please please please a tower of eight, the guy on B shift bet me it can't be done",
        one(T(8)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "put a 3-cube tower over in the corner front-left",
        one(T(3), reg("front left")),
    ),
    _c("reg-02", REG, "2x2 pad at x=0.5 y=0.4", one(k.block(2, 2, 1), k.near(0.5, 0.4))),
    _c(
        "reg-03",
        REG,
        "staircase of 3 along the left edge, climbing away from the robot",
        one(k.staircase(3), reg(_L), k.rises(_B)),
    ),
    _c(
        "reg-04",
        REG,
        "a row of 4 cubes parallel to the back edge, close to it",
        one(k.row(4), k.runs("y"), reg(_B)),
    ),
    _c("reg-05", REG, "tower of 6, dead centre", one(T(6), reg("centre"))),
    _c(
        "reg-06",
        REG,
        "a 2-level pyramid 150 mm left of the centre",
        one(k.pyramid(2), k.near(y=0.45)),
    ),
    _c(
        "reg-07",
        REG,
        "a wall 3 long near the robot, on the right",
        one(k.wall(3), reg("front right")),
    ),
    _c("reg-08", REG, "U shape, back right", one(U_SHAPE, reg("back right"))),
    _c(
        "reg-09",
        REG,
        "a pen that takes up most of the left half of the table",
        one(k.ring, reg(_L), k.long(lo=4)),
    ),
    _c("reg-10", REG, "single cube at 0.25, 0.10", one(T(1), k.near(0.25, 0.10))),
    _c(
        "reg-11",
        REG,
        "two towers of 3, one at the far left, one at the far right",
        k.structures(k.all_of(T(3), reg(_L)), k.all_of(T(3), reg(_R))),
    ),
    _c(
        "reg-12",
        REG,
        "a 2x2 block 3 high about 40 cm from the robot, straight ahead",
        one(k.block(2, 2, 3), k.near(0.40, 0.30, tol=0.04)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "a skyscraper",
        one(k.any_of(T(lo=6), k.all_of(k.solid(2, 2), k.height(lo=6)))),
    ),
    _c(
        "open-02",
        OPEN,
        "a little wall",
        one(k.any_of(k.all_of(k.wall(lo=2, hi=5), k.low(3)), k.row(lo=2, hi=5))),
    ),
    _c(
        "open-03",
        OPEN,
        "something like a park bench",
        one(k.any_of(k.bridge(lo=1, hi=3), k.canopy(lo=1, hi=3))),
    ),
    _c("open-04", OPEN, "a towering flight of stairs", one(k.staircase(lo=5))),
    _c("open-05", OPEN, "some sort of low, flat stage", one(k.broad, k.full, k.height(1))),
    _c(
        "open-06",
        OPEN,
        "a watchtower with a wall around it",
        k.any_of(k.around(T(lo=3)), one(_tight_ring(T(lo=3)))),
    ),
    _c("open-07", OPEN, "a pyramid, the bigger the better", one(k.pyramid(lo=3))),
    _c(
        "open-08",
        OPEN,
        "a tunnel a toy train could go through",
        one(k.any_of(k.bridge(), k.arch, k.canopy())),
    ),
    _c("open-09", OPEN, "some kind of small fortification", one(k.any_of(k.castle, k.ring))),
    _c("open-10", OPEN, "a podium for 3 winners", one(_podium)),
    _c(
        "open-11",
        OPEN,
        "a squat little tower",
        one(k.any_of(T(lo=1, hi=3), k.all_of(k.solid(2, 2), k.height(lo=1, hi=3)))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "asdf jkl;", k.refused),
    _c("bad-02", BAD, "Bitte einen Turm mit vier Würfeln bauen, danke", k.honest(one(T(4)))),
    _c("bad-03", BAD, "tower, height 2 metres", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-04", BAD, "3-cube row at x 1500 mm", k.honest(one(k.row(3)))),
    _c("bad-05", BAD, "build -2 towers", k.honest(k.each(2, T()))),
    _c(
        "bad-06",
        BAD,
        "a 3-level pyramid that is only 2 levels high",
        k.honest(k.any_of(one(k.pyramid(3)), one(k.pyramid(2)))),
    ),
    _c("bad-07", BAD, "is it going to rain on Friday?", k.honest()),
    _c("bad-08", BAD, "shut the robot down", k.honest()),
    _c(
        "bad-09",
        BAD,
        "tower with three and a half cubes",
        k.honest(k.any_of(one(T(3)), one(T(4)))),
    ),
    _c("bad-10", BAD, "a cylinder 10 cm in diameter", k.honest(k.layout(k.parts(lo=1)))),
    _c("bad-11", BAD, "-- -- --", k.refused),
    _c("bad-12", BAD, "a slab of 50 by 50 cubes", k.honest(one(k.broad, k.full))),
)
