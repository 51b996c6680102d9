"""A twelfth development set for the language front end (dev12): four people at the cell.

Written without looking at the Specifier's grammar, its tests, the frozen test set or any
benchmark result, and worded apart from `language_dev` … `language_dev11` (no command shared with
any set, see tests). The commands come from four kinds of people who operate or visit a robot
cell:

* an experienced cell operator who is busy and terse ("tower 4, x 0.55 y 0.15", "ok. tower. six.
  go");
* a new apprentice who is unsure and asks as much as orders ("so first I do the wall … is that
  right?", "sorry I'm new here");
* a visitor or customer describing what they would like to see built, chatty and polite;
* someone reading a sketch or a whiteboard aloud ("on the left there's …, and behind it …").

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence, a negation, a typo, a unit) and 30 % harder: three structures, references ("it",
"them", "the first one", "the big one"), distributive phrases ("a tower of two on each corner",
"at both ends"), comparisons ("one shorter", "half its height", "twice as tall"), corrections
("no wait"), removals ("then take away the middle one"), vague sizes and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — including one merged structure
where "next to" or "behind it" could be built touching — and nothing else. Geometry comes only
from `sdi.bench.boxes` through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30).
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


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev12-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _in_order(axis: str, *checks: k.Check) -> k.Pred:
    """Exactly len(checks) separate structures in the workspace; ordered front to back
    (axis "x") or left to right (axis "y"), the i-th passes checks[i]."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        bs = bx.boxes(result)
        if not bs:
            return "no layout"
        if not bx.in_workspace(bs):
            return "a part outside the workspace"
        comps = bx.components(bs)
        if len(comps) != len(checks):
            return f"{len(comps)} separate structures, want {len(checks)}"
        if axis == "x":
            comps = sorted(comps, key=lambda g: bx.centre(g)[0])
        else:
            comps = sorted(comps, key=lambda g: -bx.centre(g)[1])
        for i, (g, c) in enumerate(zip(comps, checks, strict=True)):
            r = c(g)
            if r:
                return f"structure {i + 1} in order: {r}"
        return None

    return f


def _upper_in_corner(bs: k.Boxes) -> k.Reason:
    """Everything above the bottom level sits flush in one corner of the bottom level."""
    z0 = min(b.lo[2] for b in bs)
    bottom = [b for b in bs if b.lo[2] <= z0 + bx.TOL]
    upper = [b for b in bs if b.lo[2] > z0 + bx.TOL]
    if not upper:
        return "nothing on top"
    (ulo, uhi), (blo, bhi) = bx.bounds(upper), bx.bounds(bottom)
    for i in (0, 1):
        if abs(ulo[i] - blo[i]) > bx.TOL and abs(uhi[i] - bhi[i]) > bx.TOL:
            return "the upper part is not in a corner"
    return None


def _ring_and_column(high: int, side: str) -> k.Check:
    """One structure: a ring with a single `high`-cube column, taller than every other part of
    it, built against its outside on `side` (a tower set touching a ring)."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.ring(bs)
        if r:
            return r
        cols = sorted(bx.columns(bs), key=lambda c: -bx.top(c))
        if len(cols) < 2 or bx.top(cols[1]) >= bx.top(cols[0]) - bx.TOL:
            return "no single column taller than the ring"
        if bx.thickness_cubes(cols[0]) != high:
            return f"column {bx.thickness_cubes(cols[0])} high, want {high}"
        got = bx.side_of(cols[0], bs)
        return None if got == side else f"column on the {got}, want {side}"

    return f


def _distinct_towers(result: Mapping[str, Any]) -> k.Reason:
    """2–6 separate single-cube-footprint towers, no two of the same height."""
    r = k.few(2, 6, k.tower(lo=1))(result)
    if r:
        return r
    hs = [bx.thickness_cubes(g) for g in bx.components(bx.boxes(result))]
    return None if len(set(hs)) == len(hs) else f"heights {sorted(hs)} repeat"


def _big_flat(bs: k.Boxes) -> k.Reason:
    """A solid one-layer platform at least 4 cubes each way."""
    r = k.full(bs) or k.height(1)(bs)
    if r:
        return r
    return None if bx.plan_dims(bs)[0] >= 4 else f"footprint {bx.plan_dims(bs)}, not big"


def _taller_than_wide(bs: k.Boxes) -> k.Reason:
    """A solid stack whose height exceeds its longer footprint side."""
    r = k.full(bs)
    if r:
        return r
    h, n = bx.thickness_cubes(bs), bx.plan_dims(bs)[1]
    return None if h > n else f"{h} high on a footprint {n} long"


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
_near = k.near_rel()
L_SHAPE = k.shape_letter("L")

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "on the left there's a tower of four, and to the right of it, a couple of cubes away, "
        "a 2x2 block two high",
        k.pair(k.block(2, 2, 2), T(4), k.gap_of(2, _R)),
    ),
    _c(
        "rel-02",
        REL,
        "stick one cube on top of a wall 4 long and 2 high, dead in the middle of it",
        one(k.on_top(T(1), k.wall(4, 2)), k.height(3), k.top_centred()),
    ),
    _c(
        "rel-03",
        REL,
        "a 2x2 block with a fence all round it, fence one cube high, and leave some space "
        "between the block and the fence",
        k.around(k.solid(2, 2), k.ring_of(high=1)),
    ),
    _c(
        "rel-04",
        REL,
        "Could it make a little bridge, pillars three cubes tall, and then sit one cube on the "
        "middle of the beam? My son would love that.",
        one(k.on_top(T(1), k.bare_bridge), k.height(5)),
    ),
    _c(
        "rel-05",
        REL,
        "a tower of 5 standing between two rows of three, not touching either row",
        k.between_(T(5), k.row(3)),
    ),
    _c(
        "rel-06",
        REL,
        "3x3 floor, and on every corner of it a little tower of two",
        one(k.base(3, 3), k.levels(9, 4, 4), k.corner_columns(2)),
    ),
    _c(
        "rel-07",
        REL,
        "a wall five long three high, and in front of it a row of five with a one cube gap",
        k.pair(k.row(5), k.wall(5, 3), k.gap_of(1, _F)),
    ),
    _c(
        "rel-08",
        REL,
        "the big one goes on the left, a tower of seven, and the small one, three high, on its "
        "right with two cubes of space in between",
        k.pair(T(3), T(7), k.gap_of(2, _R)),
    ),
    _c(
        "rel-09",
        REL,
        "a three level pyramid and round it a ring two cubes high",
        k.any_of(
            k.around(k.pyramid(3), k.ring_of(high=2)),
            one(k.holding(k.pyramid(3), k.ring_of(high=2))),
        ),
    ),
    _c(
        "rel-10",
        REL,
        "put a 2x2 block on top of a 4x4 slab and then a single cube on top of the block",
        one(k.on_top(T(1), k.on_top(k.solid(2, 2), k.block(4, 4, 1)))),
    ),
    _c(
        "rel-11",
        REL,
        "from the drawing: a ring four by four, and behind it, outside the ring, a tower of three",
        k.any_of(
            k.pair(T(3), k.all_of(k.ring, k.dims(4, 4)), k.on_side(_B)),
            one(k.dims(4, 5), _ring_and_column(3, _B)),  # the tower against the ring's back
        ),
    ),
    _c(
        "rel-12",
        REL,
        "two towers of four, one either side of a 2x2 block, each with a small gap to the block",
        k.between_(k.solid(2, 2), T(4)),
    ),
    _c(
        "rel-13",
        REL,
        "line of six cubes, and at both ends stack it up to three",
        one(k.profile(3, 1, 1, 1, 1, 3)),
    ),
    _c(
        "rel-14",
        REL,
        "a wall 4 long 2 high, and beside it a tower twice as tall as the wall",
        k.any_of(
            k.pair(T(4), k.wall(4, 2), _near),
            one(k.cell_heights(4, 2, 2, 2, 2)),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "reading the sketch: a stack of two at the front, behind it a stack of four, and behind "
        "that one a stack of six",
        k.any_of(_in_order("x", T(2), T(4), T(6)), one(k.xprofile(2, 4, 6))),
    ),
    _c(
        "rel-16",
        REL,
        "a 3x3 pad, one layer, and a 2x2 pad sitting on it pushed into one corner",
        one(k.on_top(k.block(2, 2, 1), k.block(3, 3, 1)), _upper_in_corner),
    ),
    _c(
        "rel-17",
        REL,
        "three things, left to right: a tower of 3, then a 2x2 block, then a two-level pyramid, "
        "with space between each",
        _in_order("y", T(3), k.solid(2, 2), k.pyramid(2)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "first lay a row of five going left to right, then a second row of five on top of it",
        one(k.wall(5, 2), k.runs("y")),
    ),
    _c(
        "seq-02",
        SEQ,
        "start with a tower of six. ok now lift the top three off again",
        one(T(3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "build a 4x4 slab. after that a 3x3 on top, then a 2x2, then one cube on the very top",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "make a tower of three, then another one just like it two cubes over to the left",
        # two cubes of clear space, or two cubes centre to centre
        k.any_of(k.pair(T(3), T(3), k.gap_of(2, _L)), k.pair(T(3), T(3), k.gap_of(1, _L))),
    ),
    _c(
        "seq-05",
        SEQ,
        "a 3 by 3 pen, one high - no wait, make the pen 5 by 5",
        one(k.ring_of(high=1), k.dims(5, 5)),
    ),
    _c(
        "seq-06",
        SEQ,
        "lay a 3x3 floor and then take the centre cube back out",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "seq-07",
        SEQ,
        "a staircase of four going up towards the back, and then right behind the top step a "
        "tower of four",
        k.any_of(
            one(k.xprofile(1, 2, 3, 4, 4)),
            k.pair(T(4), k.all_of(k.staircase(4), k.rises(_B)), k.all_rels(k.on_side(_B), _near)),
        ),
    ),
    _c(
        "seq-08",
        SEQ,
        "two towers of five with one cube of space between them, then a beam across the top",
        one(k.bridge(5, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "seq-09",
        SEQ,
        "so first I do the wall, 6 long 2 high, and then after that a tower of 4 at its left "
        "end? is that right?",
        k.any_of(
            one(k.lr_profile(4, 2, 2, 2, 2, 2, 2)),
            one(k.lr_profile(4, 2, 2, 2, 2, 2)),
            k.pair(T(4), k.wall(6, 2), k.all_rels(k.on_side(_L), _near)),
        ),
    ),
    _c(
        "seq-10",
        SEQ,
        "stack of 4, then another stack of 4 touching it on the right, then one more on the "
        "right of that",
        one(k.wall(3, 4), k.runs("y")),
    ),
    _c(
        "seq-11",
        SEQ,
        "make a bridge with pillars of 2. actually make the pillars 4 instead",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "seq-12",
        SEQ,
        "put down a row of 4, then on top of that a row of 3, then 2, then 1",
        one(k.pyramid_counts(4, 3, 2, 1), k.flat),
    ),
    _c(
        "seq-13",
        SEQ,
        "build three towers of 3 in a row with gaps, then take away the middle one",
        k.each(2, T(3)),
    ),
    _c(
        "seq-14",
        SEQ,
        "a 4x4 fence first, then fill it in, then another layer on top of everything",
        # the fence one high (or two, filled up to two) and a layer more
        one(k.any_of(k.block(4, 4, 2), k.block(4, 4, 3))),
    ),
    _c(
        "seq-15",
        SEQ,
        "first a tower of 2 at the front. then behind it a tower one taller. then behind that "
        "one taller again",
        k.any_of(_in_order("x", T(2), T(3), T(4)), one(k.xprofile(2, 3, 4))),
    ),
    _c(
        "seq-16",
        SEQ,
        "wall of four, three high - sorry, I meant four high and three long",
        one(k.wall(3, 4)),
    ),
    _c(
        "seq-17",
        SEQ,
        "put a cube down at x 0.3 y 0.3, then stack two more on it",
        one(T(3), k.near(0.3, 0.3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "three towers please: two, four and six high",
        k.any_of(k.structures(T(2), T(4), T(6)), one(k.cell_heights(2, 4, 6))),
    ),
    _c("num-02", NUM, "half a dozen cubes laid out in a line", one(k.row(6))),
    _c("num-03", NUM, "a couple of towers, five cubes in each", k.each(2, T(5))),
    _c(
        "num-04",
        NUM,
        "2 walls, each 3 long and 2 tall, apart from each other",
        k.each(2, k.wall(3, 2)),
    ),
    _c(
        "num-05",
        NUM,
        "four stacks of 2 arranged in a square",
        k.any_of(k.each(4, T(2)), one(k.block(2, 2, 2))),
    ),
    _c(
        "num-06",
        NUM,
        "a tower of three and next to it a tower one shorter",
        k.any_of(k.structures(T(3), T(2)), one(k.cell_heights(3, 2))),
    ),
    _c(
        "num-07",
        NUM,
        "a pyramid: 16 cubes on the bottom layer, then 9, then 4, then 1",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c("num-08", NUM, "ten cubes, all of them stacked in one column", one(T(10))),
    _c("num-09", NUM, "use fifteen cubes to make a 3 by 5 floor", one(k.block(3, 5, 1))),
    _c(
        "num-10",
        NUM,
        "build 3 little rings, each 3x3 and one cube high",
        k.each(3, k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c("num-11", NUM, "a wall made of 8 cubes, two rows of four", one(k.wall(4, 2))),
    _c(
        "num-12",
        NUM,
        "a stack of four and beside it one half its height",
        k.any_of(k.pair(T(2), T(4), _near), one(k.cell_heights(4, 2))),
    ),
    _c(
        "num-13",
        NUM,
        "twenty cubes on a 2x2 footprint, as high as that gets you",
        one(k.block(2, 2, 5)),
    ),
    _c(
        "num-14",
        NUM,
        "a staircase with steps of 1, 2, 3, 4 and 5 cubes",
        one(k.staircase(5)),
    ),
    _c(
        "num-15",
        NUM,
        "first a lone cube, then a tower of 2, then one of 3, all in a row with gaps",
        k.structures(T(1), T(2), T(3)),
    ),
    _c("num-16", NUM, "a 6 by 2 slab, double thickness", one(k.block(6, 2, 2))),
    _c("num-17", NUM, "just the one pillar, nine cubes", one(T(9))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "tower, 25 cm tall, middle of the table", one(T(5), reg("centre"))),
    _c(
        "dim-02",
        DIM,
        "a wall forty centimetres long and 15 high, centimetres I mean",
        one(k.wall(8, 3)),
    ),
    _c("dim-03", DIM, "a square slab 15 cm on a side, one cube thick", one(k.block(3, 3, 1))),
    _c("dim-04", DIM, "a single-layer pad 0.1 by 0.2 metres", one(k.block(2, 4, 1))),
    _c(
        "dim-05",
        DIM,
        "a ring 25 cm square on the outside and 10 cm tall",
        one(k.ring_of(high=2), k.dims(5, 5)),
    ),
    _c("dim-06", DIM, "a staircase that reaches 20 cm at the top step", one(k.staircase(4))),
    _c(
        "dim-07",
        DIM,
        "a bridge whose pillars are 10 cm tall and stand 5 cm apart",
        one(k.bridge(2, pillars=2), k.leg_gap(1)),
    ),
    _c("dim-08", DIM, "could it do a tower half a metre tall?", one(T(10))),
    _c("dim-09", DIM, "a straight row of cubes 30 cm long", one(k.row(6))),
    _c(
        "dim-10",
        DIM,
        "a block 10 cm wide, 10 cm deep and 10 cm tall",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "dim-11",
        DIM,
        "a line of cubes one foot long, on the table, just one layer",
        one(k.row(6)),
    ),
    _c("dim-12", DIM, "a pyramid that comes out 15 cm tall", one(k.pyramid(3))),
    _c(
        "dim-13",
        DIM,
        "two towers each 20 cm high standing 10 cm apart",
        # 10 cm of clear space, or 10 cm centre to centre
        k.any_of(k.pair(T(4), T(4), k.gap_of(2)), k.pair(T(4), T(4), k.gap_of(1))),
    ),
    _c(
        "dim-14",
        DIM,
        "a platform 20x20 cm and 5 cm thick",
        one(k.block(4, 4, 1)),
    ),
    _c("dim-15", DIM, "tower 150 mm high pls", one(T(3))),
    _c(
        "dim-16",
        DIM,
        "a one-cube-high fence enclosing a space 10 by 10 cm inside",
        one(k.ring_of(high=1, inner=(2, 2))),
    ),
    _c(
        "dim-17",
        DIM,
        "a 35 cm line of cubes running from front to back",
        one(k.row(7), k.runs("x")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 4 but not in the middle, put it somewhere off to the side",
        one(T(4), not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "a 3x3 pad with no tower on it, nothing on top at all",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "neg-03",
        NEG,
        "a ring 4 by 4 without anything inside it",
        one(k.ring_of(inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "neg-04",
        NEG,
        "a staircase of 3 steps and don't use any beams for it",
        one(k.staircase(3), k.only_cubes),
    ),
    _c(
        "neg-05",
        NEG,
        "a wall, 5 long, no taller than 2",
        one(k.any_of(k.wall(5, 2), k.row(5))),
    ),
    _c(
        "neg-06",
        NEG,
        "bridge with pillars 3 high, not 2, three",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "neg-07",
        NEG,
        "two towers of 3 and they mustn't touch",
        k.each(2, T(3)),
    ),
    _c(
        "neg-08",
        NEG,
        "a pyramid but not a big one, two levels is plenty",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-09",
        NEG,
        "a row of 5 that does not run front to back",
        one(k.row(5), k.runs("y")),
    ),
    _c(
        "neg-10",
        NEG,
        "a 2x2x2 block anywhere except the back of the table",
        one(k.block(2, 2, 2), not_(reg(_B), "at the back")),
    ),
    _c(
        "neg-11",
        NEG,
        "hmm not a tower, more of a wall really, four long and three high",
        one(k.wall(4, 3)),
    ),
    _c(
        "neg-12",
        NEG,
        "staircase of 4, but it shouldn't climb towards the back",
        one(k.staircase(4), not_(k.rises(_B), "climbs towards the back")),
    ),
    _c(
        "neg-13",
        NEG,
        "a tower of 6, I don't mind where, only not on the right side",
        one(T(6), not_(reg(_R), "on the right")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr of 5 at the fornt", one(T(5), reg(_F))),
    _c("typo-02", TYP, "a wal 6 lnog 2 hgh", one(k.wall(6, 2))),
    _c("typo-03", TYP, "staircse with 4 setps please", one(k.staircase(4))),
    _c("typo-04", TYP, "piramid three levles high", one(k.pyramid(3))),
    _c("typo-05", TYP, "a brdige with pilars of 3 cubse", one(k.bridge(3, pillars=2))),
    _c(
        "typo-06",
        TYP,
        "2 towrs of 4, one to the lfet of the other, 1 cube gap",
        k.pair(T(4), T(4), k.gap_of(1, _L)),
    ),
    _c("typo-07", TYP, "a rnig 5x5, 2 hihg", one(k.ring_of(high=2), k.dims(5, 5))),
    _c(
        "typo-08",
        TYP,
        "3x3 slba with a tower of 3 on tpo",
        one(k.on_top(T(3), k.block(3, 3, 1))),
    ),
    _c("typo-09", TYP, "a row of sevn cubse", one(k.row(7))),
    _c("typo-10", TYP, "cnaopy on fuor legs 2 high", one(k.canopy(4, 2, 2))),
    _c("typo-11", TYP, "bulid a 4x2 pad, too layers", one(k.block(4, 2, 2))),
    _c(
        "typo-12",
        TYP,
        "an L shpae, each arm 4 cubes",
        # the arms 4 counting the shared corner cube, or 4 beyond it
        one(L_SHAPE, k.any_of(k.dims(4, 4), k.dims(5, 5))),
    ),
    _c("typo-13", TYP, "put a cueb at x 0.6 y 0.2", one(T(1), k.near(0.6, 0.2))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "five high, that tower, on the left please", one(T(5), reg(_L))),
    _c(
        "wo-02",
        WO,
        "of the wall, the length is 6 and the height 3",
        one(k.wall(6, 3)),
    ),
    _c(
        "wo-03",
        WO,
        "at the back right, a ring of 4 by 4 I want",
        one(k.ring, k.dims(4, 4), reg("back right")),
    ),
    _c(
        "wo-04",
        WO,
        "three steps, a staircase, going up to the right",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "wo-05",
        WO,
        "on top of the 2x2 block a tower of 3 goes",
        one(k.on_top(T(3), k.solid(2, 2))),
    ),
    _c(
        "wo-06",
        WO,
        "in front of the wall (4 long, 2 high) a tower of 2, gap of two cubes",
        k.pair(T(2), k.wall(4, 2), k.gap_of(2, _F)),
    ),
    _c(
        "wo-07",
        WO,
        "the pillars 4 high, a beam across them, a bridge make",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "wo-08",
        WO,
        "to the left of a three-level pyramid, one cube away from it, a stack of 2",
        k.pair(T(2), k.pyramid(3), k.gap_of(1, _L)),
    ),
    _c("wo-09", WO, "3 by 4 the slab, 2 layers thick", one(k.block(3, 4, 2))),
    _c(
        "wo-10",
        WO,
        "cubes, eight of them, in a line front to back",
        one(k.row(8), k.runs("x")),
    ),
    _c(
        "wo-11",
        WO,
        "around the tower of 3, a 5x5 fence",
        k.any_of(
            k.around(T(3), k.all_of(k.ring, k.dims(5, 5))),
            one(k.holding(T(3), k.all_of(k.ring, k.dims(5, 5)))),
        ),
    ),
    _c("wo-12", WO, "x 0.5 y 0.4 - tower of 4 there", one(T(4), k.near(0.5, 0.4))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "morning! busy day. first thing, can you get the robot to do a 4x4 floor, one layer, "
        "thanks",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "fil-02",
        FIL,
        "so my daughter is mad about bridges, she'd be thrilled - could you do one with pillars "
        "about three cubes tall? that would be lovely",
        one(k.bridge(lo=2, hi=4, pillars=2)),
    ),
    _c("fil-03", FIL, "ok ok ok. tower. six. go", one(T(6))),
    _c(
        "fil-04",
        FIL,
        "sorry I'm new here and not sure how this works, but could I ask for a staircase, like, "
        "five steps?",
        one(k.staircase(5)),
    ),
    _c(
        "fil-05",
        FIL,
        "right, while the coffee's brewing, knock me up a ring 6 by 6, one high, cheers",
        one(k.ring_of(high=1), k.dims(6, 6)),
    ),
    _c(
        "fil-06",
        FIL,
        "we're showing the customer the arm today and they liked the pyramid last time, so do a "
        "three-level one again",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-07",
        FIL,
        "um hi, is it okay if I... I'd like a wall of five, two high? if that's not too much "
        "trouble",
        one(k.wall(5, 2)),
    ),
    _c(
        "fil-08",
        FIL,
        "let's see what it does with this - a 2x3 block, three tall - and then we go to lunch",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "fil-09",
        FIL,
        "the boss wants a demo, nothing fancy, just two towers of four side by side with a gap",
        k.each(2, T(4)),
    ),
    _c(
        "fil-10",
        FIL,
        "honestly my favourite is the table one, can we have a table with legs three high please",
        one(k.canopy(lo=3, hi=3)),
    ),
    _c(
        "fil-11",
        FIL,
        "I'm reading off the whiteboard here, it says: row of 4, front to back, that's all it says",
        one(k.row(4), k.runs("x")),
    ),
    _c(
        "fil-12",
        FIL,
        "ugh the last job got cancelled. fine. a 3x3 pad two layers thick in the middle",
        one(k.block(3, 3, 2), reg("centre")),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower of 3 at x=0.4 please", one(T(3), k.near(x=0.4))),
    _c(
        "reg-02",
        REG,
        "a 2x2 block over in the front left corner",
        one(k.solid(2, 2), reg("front left")),
    ),
    _c(
        "reg-03",
        REG,
        "a wall along the right-hand side, 5 long 2 high, running front to back",
        one(k.wall(5, 2), k.runs("x"), reg(_R)),
    ),
    _c(
        "reg-04",
        REG,
        "a single cube as far to the left as it'll go",
        one(T(1), k.near(y=0.51, tol=0.04)),
    ),
    _c(
        "reg-05",
        REG,
        "on the left there's a tower of two, and on the right a tower of five",
        k.any_of(k.pair(T(2), T(5), k.on_side(_L)), one(k.lr_profile(2, 5))),
    ),
    _c(
        "reg-06",
        REG,
        "a two level pyramid at the back, in the middle left to right",
        one(k.pyramid(2), reg(_B), k.near(y=0.30, tol=0.05)),
    ),
    _c(
        "reg-07",
        REG,
        "put a 3x3 ring close to the robot",
        one(k.ring_of(inner=(1, 1)), k.dims(3, 3), reg(_F)),
    ),
    _c("reg-08", REG, "tower of 4 at x 0.55, y 0.15", one(T(4), k.near(0.55, 0.15))),
    _c(
        "reg-09",
        REG,
        "two cubes, one in the back left corner and one in the back right corner",
        k.structures(
            k.all_of(T(1), reg("back left")),
            k.all_of(T(1), reg("back right")),
        ),
    ),
    _c(
        "reg-10",
        REG,
        "a row of 6 along the front edge of the table",
        one(k.row(6), k.runs("y"), reg(_F)),
    ),
    _c(
        "reg-11",
        REG,
        "a staircase of 3 right in the middle of the table",
        one(k.staircase(3), reg("centre")),
    ),
    _c(
        "reg-12",
        REG,
        "a tower of 5, 15 cm to the left of the centre",
        one(T(5), k.near(y=0.45), k.near(x=0.475, tol=0.05)),
    ),
    _c(
        "reg-13",
        REG,
        "far right, near the back: a 2x3 slab, single layer",
        one(k.block(2, 3, 1), reg("back right")),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "something tall, whatever you like", one(k.height(lo=4))),
    _c("open-02", OPEN, "a small tower for the display", one(T(lo=2, hi=4))),
    _c(
        "open-03",
        OPEN,
        "a little house a toy could live in",
        one(k.any_of(k.canopy(), k.ring, k.bridge(), k.castle)),
    ),
    _c(
        "open-04",
        OPEN,
        "something long and low, like a garden wall",
        one(k.any_of(k.row(lo=5), k.all_of(k.wall(lo=5), k.low(2)))),
    ),
    _c(
        "open-05",
        OPEN,
        "just some steps for the figurines to climb, any number",
        one(k.staircase(lo=2)),
    ),
    _c("open-06", OPEN, "a handful of towers, none of them the same height", _distinct_towers),
    _c("open-07", OPEN, "a big flat platform", one(_big_flat)),
    _c("open-08", OPEN, "a gate of some sort", one(k.any_of(k.bridge(), k.arch))),
    _c("open-09", OPEN, "something like a little fort", one(k.any_of(k.castle, k.ring))),
    _c("open-10", OPEN, "a pen, whatever size you think", one(k.ring)),
    _c("open-11", OPEN, "surprise me, but keep it small", k.small),
    _c("open-12", OPEN, "a stack that's taller than it is wide", one(_taller_than_wide)),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "tower of 14 cubes", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-02",
        BAD,
        "a row of 30 cubes from left to right",
        k.honest(one(k.row(lo=2, hi=12))),
    ),
    _c(
        "bad-03",
        BAD,
        "a tower of three that's also five high",
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c("bad-04", BAD, "put a cube at x 1.5", k.honest(one(T(1)))),
    _c("bad-05", BAD, "blah blah robot blah", k.honest()),
    _c("bad-06", BAD, "build the thing from yesterday again", k.honest()),
    _c(
        "bad-07",
        BAD,
        "a hollow ring that's 2x2",
        k.honest(one(k.any_of(k.ring, k.solid(2, 2)))),
    ),
    _c(
        "bad-08",
        BAD,
        "two towers of five three cubes apart and a beam laid across them",
        k.honest(k.any_of(k.each(2, T(5)), one(k.bridge(5, pillars=2)))),
    ),
    _c(
        "bad-09",
        BAD,
        "a staircase of 12 steps",
        k.honest(one(k.staircase(lo=2, hi=10))),
    ),
    _c(
        "bad-10",
        BAD,
        "a pyramid with a base fifteen cubes by fifteen",
        k.honest(one(k.pyramid())),
    ),
    _c("bad-11", BAD, "can you make it smaller", k.honest()),
    _c("bad-12", BAD, "stack minus three cubes on top of each other", k.honest(one(T(3)))),
    _c("bad-13", BAD, "build a block zero centimetres tall", k.honest(one(k.full, k.height(1)))),
)
