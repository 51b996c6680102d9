"""A tenth development set for the language front end (dev10): six more new voices at the cell.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev9` (no command shared with
any set, see tests). The commands come from six kinds of people, none of them used before:

* a robotics PhD student writing terse technical specs (coordinates, mm, axis names, "n=4",
  "h=3", "z_top");
* a museum exhibit designer describing visual composition (plinth, slender column, flanking,
  centrepiece);
* a safety officer adding constraints (distance from the front edge, away from the robot,
  height limits);
* a parent dictating a child's idea ("she wants …", "he says …");
* a British / Australian operator with local idioms ("knock up", "pop", "chuck", "ta", "arvo");
* a game designer thinking in levels, tiles, maps, spawn points and rooms.

About 65 % ordinary and 35 % harder: relations between structures (on top of, beside with a side
and a gap, around, between/flanking, along an edge), sequences ("first … then …", "then pinch the
top one off"), numbers attached to the right thing, dimension words (wide/deep/tall, cm/mm/m/
inches), negation and hedges, typos, regions and coordinates, corrections, distributive phrases
("a pillar on each corner", "a tower at both ends", "a tile in each corner of the map"),
comparisons, references ("another just the same to its left"), open descriptions and unusable
input that must be refused or flagged.

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
    return Case(id=f"dev10-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _min_x(x: float) -> k.Check:
    """Nothing nearer the front (robot) edge than `x`: every part's back face of x ≥ `x`."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = bx.bounds(bs)[0][0]
        return None if lo >= x - bx.TOL else f"a part reaches x = {lo:.3f}, want ≥ {x}"

    return f


def _no_corners(n: int) -> k.Check:
    """One layer of cubes on an n×n footprint with exactly the four corner cells empty."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.dims(n, n)(bs) or k.height(1)(bs) or k.only_cubes(bs)
        if r:
            return r
        empty = {(i, j) for i in range(n) for j in range(n)} - bx.cells(bs)
        corners = {(i, j) for i in (0, n - 1) for j in (0, n - 1)}
        if empty != corners:
            return f"empty cells {sorted(empty)}, want the four corners"
        return None if len(bs) == n * n - 4 else "overlapping parts"

    return f


def _end_columns(extra: int) -> k.Check:
    """Everything above the bottom level is two columns of `extra` parts, one over each end
    slice of the base's long side."""

    def f(bs: k.Boxes) -> k.Reason:
        z0 = min(b.lo[2] for b in bs)
        upper = [b for b in bs if b.lo[2] > z0 + bx.TOL]
        cols = bx.columns(upper)
        if len(cols) != 2:
            return f"{len(cols)} columns on top, want 2 (one per end)"
        if any(len(c) != extra for c in cols):
            return f"columns of {sorted(len(c) for c in cols)}, want {extra} each"
        fx, fy = bx.footprint_cubes(bs)
        axis = 0 if fx >= fy else 1
        lo, hi = bx.bounds(bs)
        ends = set()
        for col in cols:
            c = col[0].centre[axis]
            if abs(c - (lo[axis] + bx.CUBE / 2)) <= 0.01:
                ends.add("lo")
            elif abs(c - (hi[axis] - bx.CUBE / 2)) <= 0.01:
                ends.add("hi")
            else:
                return "a column not on an end of the base"
        return None if ends == {"lo", "hi"} else "both columns on one end"

    return f


def _descending(result: Mapping[str, Any]) -> k.Reason:
    """Three columns of three different heights: separate towers, or touching as steps."""
    sep = k.each(3, k.tower(lo=1))(result)
    if sep is None:
        hs = {bx.thickness_cubes(c) for c in bx.components(bx.boxes(result))}
        return None if len(hs) == 3 else f"tower heights {sorted(hs)}, want three different"
    steps = k.one(k.staircase(3))(result)
    return None if steps is None else f"{sep}; {steps}"


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE = k.shape_letter("L")
U_SHAPE = k.shape_letter("U")
T_SHAPE = k.shape_letter("T")
_RING6_2 = k.all_of(k.ring_of(high=2), k.dims(6, 6))
_WALL6_Y = k.all_of(k.wall(6, 2), k.runs("y"))

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "a low plinth, three by three and a single cube deep, with a slender column four "
        "cubes tall rising from its centre",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.levels(9, 1, 1, 1, 1), k.centred()),
    ),
    _c(
        "rel-02",
        REL,
        "tower n=5 on the +y side of a 2x2x2 block, gap 50 mm",
        k.pair(T(5), k.block(2, 2, 2), k.gap_of(1, _L)),
    ),
    _c(
        "rel-03",
        REL,
        "spawn a 4x4 floor tile and stick a pillar two tiles high on each corner of it",
        one(k.base(4, 4), k.levels(16, 4, 4), k.corner_columns(2)),
    ),
    _c(
        "rel-04",
        REL,
        "my son says the tower of three has to live inside a fence so it can't run away",
        # a fence free round the tower, or laid tight against it
        k.any_of(
            k.around(T(3), k.all_of(k.ring, k.low(3))),
            one(k.holding(T(3), k.all_of(k.ring, k.low(3)))),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "knock up two towers of four with a beam across the top of them, cheers",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "rel-06",
        REL,
        "a row of five between two stacks of three, leaving a cube's width either side for the "
        "gripper",
        k.between_(k.row(5), T(3)),
    ),
    _c(
        "rel-07",
        REL,
        "a 2x2 pedestal one cube high, flanked by two slender columns five cubes tall",
        k.between_(k.block(2, 2, 1), T(5)),
    ),
    _c(
        "rel-08",
        REL,
        "wall L=6 H=2 along y; directly in front of it (-x) a 2x2 slab, clearance 1 cube",
        k.pair(k.block(2, 2, 1), _WALL6_Y, k.gap_of(1, _F)),
    ),
    _c(
        "rel-09",
        REL,
        "boss room: a 2x2 treasure tile, one high, sitting inside a 6x6 border two tiles high",
        k.any_of(
            k.around(k.block(2, 2, 1), _RING6_2),
            one(k.holding(k.block(2, 2, 1), _RING6_2)),  # the tile pushed against the border
        ),
    ),
    _c(
        "rel-10",
        REL,
        "chuck a three-level pyramid up the back and a tower of six out the front of it, "
        "roughly two cubes apart",
        k.any_of(*[k.pair(T(6), k.pyramid(3), k.gap_of(n, _F)) for n in (1, 2, 3)]),
    ),
    _c(
        "rel-11",
        REL,
        "two parallel walls, four long and three high, with a 15 cm corridor between them for "
        "the inspection camera",
        k.pair(k.wall(4, 3), k.wall(4, 3), k.parallel_gap(3)),
    ),
    _c(
        "rel-12",
        REL,
        "a 3 by 2 slab two layers thick, and another one just the same to its left with a "
        "one-cube gap",
        k.pair(k.block(3, 2, 2), k.block(3, 2, 2), k.gap_of(1, _L)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "step 1: 3x3 slab at z=0. step 2: 2x2 slab on it, centred. step 3: 1 cube on top.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "seq-02",
        SEQ,
        "first she wants a row of four, then another row of four on top of that, and then one "
        "more on top again",
        one(k.wall(4, 3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "build a 4x4 platform, then delete the four corner tiles",
        one(_no_corners(4)),
    ),
    _c("seq-04", SEQ, "stack up five, then pinch the top one off", one(T(4))),
    _c(
        "seq-05",
        SEQ,
        "begin with a long low base, six by two and one cube high; then set a column of three "
        "at each end of it",
        one(k.base(6, 2), k.levels(12, 2, 2, 2), _end_columns(3)),
    ),
    _c("seq-06", SEQ, "do a tower of seven — nah, make it five, mate", one(T(5))),
    _c(
        "seq-07",
        SEQ,
        "build a wall five long and two high, and once it's done take the top layer off again",
        one(k.row(5)),
    ),
    _c(
        "seq-08",
        SEQ,
        "init: tower h=3 at (0.40, 0.25). then: same at (0.40, 0.35). then: beam spanning both.",
        one(k.bridge(3, pillars=2), k.near(0.40, 0.30)),
    ),
    _c(
        "seq-09",
        SEQ,
        "first lay a 3x3 floor, then raise every tile by one level except the middle one",
        one(k.dims(3, 3), k.levels(9, 8), k.height(2), k.only_cubes),
    ),
    _c(
        "seq-10",
        SEQ,
        "he wants a tower of three, and then right next to it one that's a cube taller",
        k.any_of(k.pair(T(4), T(3), k.near_rel()), one(k.profile(3, 4))),
    ),
    _c(
        "seq-11",
        SEQ,
        "first a 4x4 plinth one cube high, then a 2x2 block two cubes tall set at its centre",
        one(k.levels(16, 4, 4), k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.centred(0.01)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "towers, n=4, h=3 each", k.each(4, T(3))),
    _c("num-02", NUM, "three 2x2 tiles, each stacked two high", k.each(3, k.block(2, 2, 2))),
    _c("num-03", NUM, "half a dozen cubes in a single line", one(k.row(6))),
    _c(
        "num-04",
        NUM,
        "two towers please, one with 3 cubes and the other with 5 cubes",
        k.structures(T(3), T(5)),
    ),
    _c("num-05", NUM, "a pair of columns, each seven cubes high", k.each(2, T(7))),
    _c("num-06", NUM, "three stacks of four, spread out a bit", k.each(3, T(4))),
    _c(
        "num-07",
        NUM,
        "no more than 20 cubes in total: a 4 by 5 slab, one layer",
        one(k.block(4, 5, 1)),
    ),
    _c(
        "num-08",
        NUM,
        "a 3-level pyramid with 9 tiles on the ground floor",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c("num-09", NUM, "wall, L=5, H=4, 20 cubes total", one(k.wall(5, 4))),
    _c("num-10", NUM, "eight cubes, all of them in one tower", one(T(8))),
    _c("num-11", NUM, "a couple of walls, each four long and two high", k.each(2, k.wall(4, 2))),
    _c(
        "num-12",
        NUM,
        "one column of two and a second column four times as tall",
        k.structures(T(2), T(8)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "block 150x100x100 mm (x, y, z)", one(k.block_xy(3, 2, 2))),
    _c(
        "dim-02",
        DIM,
        "a wall half a metre long and ten centimetres high",
        one(k.wall(10, 2)),
    ),
    _c("dim-03", DIM, "a slender column 35 cm tall", one(T(7))),
    _c(
        "dim-04",
        DIM,
        "a slab 20 cm wide and 30 cm deep, one cube thick",
        one(k.block_xy(6, 4, 1)),
    ),
    _c(
        "dim-05",
        DIM,
        "a platform 4 tiles long, 3 tiles deep and 2 tiles high",
        one(k.block(4, 3, 2)),
    ),
    _c("dim-06", DIM, "tower, z_top = 0.25 m", one(T(5))),
    _c(
        "dim-07",
        DIM,
        "a staircase, but it has to stay under 20 cm tall, so as many steps as that allows",
        one(k.staircase(3)),
    ),
    _c(
        "dim-08",
        DIM,
        "a slab six inches by six inches",
        one(k.solid(3, 3), k.low(2)),
    ),
    _c(
        "dim-09",
        DIM,
        "an arch with an opening 10 cm high and 5 cm wide",
        one(k.bridge(2, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "dim-10",
        DIM,
        "ring, outer 250 x 250 mm, h = 50 mm",
        one(k.ring_of(high=1), k.dims(5, 5)),
    ),
    _c(
        "dim-11",
        DIM,
        "a tower as tall as her teddy, and her teddy is 30 centimetres",
        one(T(6)),
    ),
    _c(
        "dim-12",
        DIM,
        "a thin wall, one tile thick, 40 cm across and 3 tiles tall",
        one(k.wall(8, 3)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of six, but not anywhere near the front edge",
        one(T(6), not_(reg(_F), "at the front")),
    ),
    _c("neg-02", NEG, "2x3 slab, no beams, single layer", one(k.block(2, 3, 1), k.only_cubes)),
    _c(
        "neg-03",
        NEG,
        "a pyramid but NOT a big one, she says only two floors",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-04",
        NEG,
        "a wall of four, not too tall mind, two high will do",
        one(k.wall(4, 2)),
    ),
    _c(
        "neg-05",
        NEG,
        "a colonnade of four columns of three, with no lintel across them",
        k.each(4, T(3)),
    ),
    _c(
        "neg-06",
        NEG,
        "a 4x4 floor, but don't fill in the inner 2x2",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "neg-07",
        NEG,
        "two stacks of four; nothing within 10 cm of the robot's side of the workspace",
        k.all_of(k.each(2, T(4)), k.layout(_min_x(0.30))),
    ),
    _c(
        "neg-08",
        NEG,
        "a staircase of three, not going up towards the left",
        one(k.staircase(3), not_(k.rises(_L), "climbs towards the left")),
    ),
    _c("neg-09", NEG, "tower h=4, NOT at the centre", one(T(4), not_(reg("centre"), "central"))),
    _c("neg-10", NEG, "a tower of five, no hang on, not five, four", one(T(4))),
    _c("neg-11", NEG, "a low 3x3 plinth with nothing standing on it", one(k.block(3, 3, 1))),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr h=5", one(T(5))),
    _c("typo-02", TYP, "a piramid of thre levels", one(k.pyramid(3))),
    _c("typo-03", TYP, "a wal six lomg and too high", one(k.wall(6, 2))),
    _c("typo-04", TYP, "5x5 platfrom, 1 tlie high", one(k.block(5, 5, 1))),
    _c("typo-05", TYP, "stiarcase of 4 stesp", one(k.staircase(4))),
    _c("typo-06", TYP, "a colum of sevn cubes", one(T(7))),
    _c(
        "typo-07",
        TYP,
        "to stakcs of three, kept away form the front",
        k.each(2, T(3), not_(reg(_F), "at the front")),
    ),
    _c("typo-08", TYP, "brdige, pilar h=3", one(k.bridge(3, pillars=2))),
    _c("typo-09", TYP, "a castel for her dollz", one(k.castle)),
    _c(
        "typo-10",
        TYP,
        "an L shpae, each arm 4 tiels",
        # the arms sharing the corner cube, or 4 beyond it
        one(L_SHAPE, k.any_of(k.dims(4, 4), k.dims(5, 5))),
    ),
    _c("typo-11", TYP, "a 2x2x3 blcok, ta", one(k.block(2, 2, 3))),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "rising from the centre of a 3x3 plinth, a column of five",
        one(k.on_top(T(5), k.block(3, 3, 1)), k.levels(9, 1, 1, 1, 1, 1), k.centred()),
    ),
    _c("wo-02", WO, "h=3, w=4, type=wall", one(k.wall(4, 3))),
    _c("wo-03", WO, "four high, that tower, up the back", one(T(4), reg(_B))),
    _c("wo-04", WO, "tiles 3 by 3 and layers 2 — a block", one(k.block(3, 3, 2))),
    _c(
        "wo-05",
        WO,
        "on the right a tower of three, and on the left a tower of five",
        k.pair(T(3), T(5), k.on_side(_R)),
    ),
    _c("wo-06", WO, "a ring, 5 by 5, two high it should be", one(k.ring_of(high=2), k.dims(5, 5))),
    _c(
        "wo-07",
        WO,
        "to the back left, keeping clear of the robot, a slab of 2 by 2",
        one(k.block(2, 2, 1), reg("back left")),
    ),
    _c(
        "wo-08",
        WO,
        "five steps, rising towards the back, a grand staircase",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c(
        "wo-09",
        WO,
        "2 cubes apart, two rows of 4 cubes, side by side",
        k.pair(k.row(4), k.row(4), k.parallel_gap(2)),
    ),
    _c(
        "wo-10",
        WO,
        "a pillar 3 tall, and behind it by one tile a 2-level pyramid",
        k.pair(k.pyramid(2), T(3), k.gap_of(1, _B)),
    ),
    _c(
        "wo-11",
        WO,
        "a T, the bar five long, stem of three, lay it flat",
        # the stem 3 below the bar, or 3 counting the bar's middle cube
        one(T_SHAPE, k.height(1), k.any_of(k.dims(4, 5), k.dims(3, 5))),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning! Hope you're well. When you get a sec, could you pop a tower of four on the "
        "table? Ta very much.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok so my 6 year old is sitting next to me and she has very firm opinions lol. she "
        "wants a wall three long and two high. thanks!!",
        one(k.wall(3, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "For the ablation run (seed 17, trial 3) I need a baseline structure: 3x3x1 slab. "
        "Logging starts now.",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "fil-04",
        FIL,
        "For the opening of the new gallery wing we're after something quiet and "
        "architectural; concretely, a pyramid of three tiers.",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Reminder: per site rule 4.2 safety glasses are mandatory inside the cell. Task for "
        "today: a row of five cubes.",
        one(k.row(5)),
    ),
    _c(
        "fil-06",
        FIL,
        "ok level design time 🎮 first room is a U shape, 3 tiles across and 3 deep, one high. gg",
        # the arms 3 deep with the base row, or 3 beyond it
        one(U_SHAPE, k.height(1), k.any_of(k.dims(3, 3), k.dims(3, 4))),
    ),
    _c(
        "fil-07",
        FIL,
        "G'day mate, hope the arvo's treating you well. Whack up a staircase of four for us "
        "would ya",
        one(k.staircase(4)),
    ),
    _c(
        "fil-08",
        FIL,
        "Sorry, he's typing over my shoulder. He says: a bridge with legs of two. That's it, "
        "thank you!",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-09",
        FIL,
        "quick sanity check before the paper deadline, no pressure: 2x2x2 block please, thx",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "fil-10",
        FIL,
        "The visitors' route curves past this spot and the afternoon light comes in from the "
        "left. Anyway: a single column, six cubes.",
        one(T(6)),
    ),
    _c(
        "fil-11",
        FIL,
        "Right, kettle's on, so while I'm waiting: a 4 by 4 ring, one high, if you'd be so kind.",
        one(k.ring_of(high=1), k.dims(4, 4)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower h=4 @ (x=0.30, y=0.45)", one(T(4), k.near(0.30, 0.45))),
    _c(
        "reg-02",
        REG,
        "a 3x3 slab, and keep everything at least 10 cm from the front edge of the workspace",
        k.all_of(one(k.block(3, 3, 1)), k.layout(_min_x(0.30))),
    ),
    _c(
        "reg-03",
        REG,
        "put a 2x2 tile in each corner of the map",
        k.structures(
            *[k.all_of(k.block(2, 2, 1), reg(c)) for c in ("back left", "back right")],
            *[k.all_of(k.block(2, 2, 1), reg(c)) for c in ("front left", "front right")],
        ),
    ),
    _c(
        "reg-04",
        REG,
        "a wall six long and two high down the right-hand side, running front to back",
        one(k.wall(6, 2), k.runs("x"), reg(_R)),
    ),
    _c(
        "reg-05",
        REG,
        "the centrepiece: a three-level pyramid right in the middle of the floor",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "a stack of five over on the left, towards the back",
        one(T(5), reg("back left")),
    ),
    _c(
        "reg-07",
        REG,
        "row n=5 along y, centred at x=0.60",
        one(k.row(5), k.runs("y"), k.near(x=0.60)),
    ),
    _c(
        "reg-08",
        REG,
        "a tower of three at the back, well away from the robot, at y = 0.30",
        one(T(3), reg(_B), k.near(y=0.30)),
    ),
    _c(
        "reg-09",
        REG,
        "a tower at both ends of the table, each four cubes tall",
        # the table's ends taken as left and right, or as front and back
        k.any_of(
            k.structures(k.all_of(T(4), reg(_L)), k.all_of(T(4), reg(_R))),
            k.structures(k.all_of(T(4), reg(_F)), k.all_of(T(4), reg(_B))),
        ),
    ),
    _c(
        "reg-10",
        REG,
        "spawn point at the front right: a single 1x1 pillar, 2 high",
        one(T(2), reg("front right")),
    ),
    _c(
        "reg-11",
        REG,
        "a low screen wall, six long and two high, along the back edge, with a small 2x2 plinth "
        "standing in front of it",
        k.pair(k.block(2, 2, 1), k.all_of(_WALL6_Y, reg(_B)), k.on_side(_F)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "a low plinth with a slender column rising from its centre",
        one(
            k.on_top(T(lo=2), k.all_of(k.broad, k.full, k.low(2))),
            k.centred(),
        ),
    ),
    _c("open-02", OPEN, "she wants something that looks a bit like a rocket", one(k.height(lo=3))),
    _c(
        "open-03",
        OPEN,
        "a small maze-like enclosure for level one",
        k.any_of(
            one(k.any_of(k.ring, U_SHAPE)),
            k.few(2, 4, k.any_of(k.wall(), k.row(lo=2), L_SHAPE, U_SHAPE)),
        ),
    ),
    _c(
        "open-04",
        OPEN,
        "something nice and chunky for the shop window",
        one(k.full, k.broad, k.height(lo=2)),
    ),
    _c(
        "open-05",
        OPEN,
        "a minimal load-bearing span structure",
        one(k.any_of(k.bridge(), k.arch)),
    ),
    _c(
        "open-06",
        OPEN,
        "a little shelter a toy koala could sit under",
        one(k.any_of(k.canopy(), k.bridge(), k.arch)),
    ),
    _c(
        "open-07",
        OPEN,
        "something low and stable, nothing higher than 10 cm",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c(
        "open-08",
        OPEN,
        "a composition of three columns of descending height",
        _descending,
    ),
    _c(
        "open-09",
        OPEN,
        "the final boss tower, as tall as the cell allows",
        one(k.any_of(T(lo=8, hi=10), k.all_of(k.broad, k.full, k.height(lo=8)))),
    ),
    _c("open-10", OPEN, "a tiny little house", one(k.any_of(k.broad, k.arch))),
    _c(
        "open-11",
        OPEN,
        "a modest wall, nothing fancy",
        one(k.any_of(k.wall(lo=3), k.row(lo=3)), k.long(hi=8)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "h=NaN", k.honest()),
    _c("bad-02", BAD, "a tower of 12 cubes", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-03",
        BAD,
        "she wants a rainbow unicorn castle that flies",
        k.honest(k.anything),
    ),
    _c("bad-04", BAD, "sorry, wrong window", k.honest()),
    _c("bad-05", BAD, "load level 3 from the save file", k.honest()),
    _c(
        "bad-06",
        BAD,
        "a column reaching right up to the ceiling, 3 metres",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-07", BAD, "a tower at x = 1.5", k.honest(one(T(lo=1)))),
    _c(
        "bad-08",
        BAD,
        "a 2x2 slab, but leave the workspace completely empty",
        k.honest(one(k.solid(2, 2))),
    ),
    _c("bad-09", BAD, "qwfp;; zxcv 0.0.0", k.honest()),
    _c("bad-10", BAD, "a tower of minus three", k.honest(one(T(3)))),
    _c("bad-11", BAD, "bin the lot and start again", k.honest()),
    _c("bad-12", BAD, "a 20x20 floor of tiles", k.honest(one(k.broad))),
)
