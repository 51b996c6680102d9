"""A thirteenth development set for the language front end (dev13): five voices at the cell.

Written without looking at the Specifier's grammar, its tests, the front end's code, the frozen
test set or any benchmark result, and worded apart from `language_dev` … `language_dev12` (no
command shared with any set, see tests). Nothing here was run through the system while it was
written. The commands come from five kinds of people who give orders to a robot cell:

* a production engineer writing a work order or ticket — terse, metric, key=value
  ("JOB 118: tower h=5 …", "qty 3 pillars, h=4 cubes each", "2x wall L=5 H=3");
* speech-to-text transcripts from an operator with a headset — no punctuation, fillers ("uh",
  "um", "like") and a few homophones a recogniser plausibly makes ("for" for four, "to" for
  two, "tree" for three, "won" for one);
* a non-native English speaker — dropped articles, unusual prepositions and word order
  ("please to build", "tower with height of eight", "of four cubes a row make");
* a teacher with schoolchildren describing a build step by step ("First we …, now we …");
* a CAD user giving dimensions in mm or cm ("footprint 150 x 100 mm, 3 layers", "c/c 100 mm").

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three structures, references ("it", "them", "him"), distributive
phrases ("on each corner"), comparisons ("double of the height", "half as tall", "1.5x the
wall height"), corrections ("EDIT: h=6", "no sorry, of five"), removals and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — including one merged structure
where "next to" or "behind it" could be built touching, and both clear and centre-to-centre
readings of an unqualified spacing — and nothing else. Geometry comes only from
`sdi.bench.boxes` through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30).
"""

from __future__ import annotations

import itertools
from collections.abc import Mapping
from typing import Any

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev13-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _gap_either(*ns: int, side: str | None = None) -> k.Rel:
    """A and B are one of `ns` cubes apart (± 1.5 cm), A on `side` of B — for a spacing that
    may be meant clear or centre to centre."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        reasons = [k.gap_of(n, side)(a, b) for n in ns]
        return None if None in reasons else reasons[0]

    return rel


def _parallel(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B run along the same axis (their longer plan sides both along x, or both y)."""
    (ax, ay), (bx0, by) = bx.footprint_cubes(a), bx.footprint_cubes(b)
    return None if (ax > ay) == (bx0 > by) and ax != ay and bx0 != by else "not parallel"


def _peak_on(side: str) -> k.Check:
    """The single tallest column of the structure stands on `side` of the rest of it."""

    def f(bs: k.Boxes) -> k.Reason:
        top = max(b.hi[2] for b in bs)
        tallest = [b for b in bs if b.hi[2] >= top - bx.TOL]
        if len(tallest) != 1:
            return "no single tallest column"
        x, y, _ = tallest[0].centre
        peak = [b for b in bs if abs(b.centre[0] - x) <= 0.01 and abs(b.centre[1] - y) <= 0.01]
        rest = [b for b in bs if all(b is not q for q in peak)]
        if not rest:
            return "nothing beside the tallest column"
        got = bx.side_of(peak, rest)
        return None if got == side else f"tallest column on the {got}, want {side}"

    return f


def _in_order(axis: str, *checks: k.Check, gap: int | None = None) -> k.Pred:
    """Exactly len(checks) separate structures in the workspace; ordered front to back
    (axis "x") or left to right (axis "y"), the i-th passes checks[i]; neighbours `gap` cubes
    apart (± 1.5 cm) when given."""

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
        if gap is not None:
            for a, b in itertools.pairwise(comps):
                r = k.gap_of(gap)(a, b)
                if r:
                    return r
        return None

    return f


def _near_top_step(max_gap: float = 0.10) -> k.Rel:
    """A stands within `max_gap` of the highest step of the staircase B."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        top = max(q.hi[2] for q in b)
        xy = {(round(q.centre[0], 3), round(q.centre[1], 3)) for q in b if q.hi[2] >= top - bx.TOL}
        step = [q for q in b if (round(q.centre[0], 3), round(q.centre[1], 3)) in xy]
        gap = bx.separation(a, step)
        return None if gap <= max_gap else f"{gap:.2f} m from the top step"

    return rel


def _all_left_of_centre(bs: k.Boxes) -> k.Reason:
    """Nothing in the right half of the table (every part at y ≥ 0.30)."""
    (_, y0, _), _ = bx.bounds(bs)
    return None if y0 >= 0.30 - bx.TOL else f"a part reaches y {y0:.3f}, in the right half"


def _min_side(n: int) -> k.Check:
    """At least `n` cubes each way in plan."""

    def f(bs: k.Boxes) -> k.Reason:
        a = bx.plan_dims(bs)[0]
        return None if a >= n else f"footprint {bx.plan_dims(bs)}, want at least {n}×{n}"

    return f


def _low_demo(result: Mapping[str, Any]) -> k.Reason:
    """Some layout, at most 3 cubes high."""
    return k.anything(result) or k.layout(k.low(3))(result)


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
_near = k.near_rel()
L_SHAPE = k.shape_letter("L")
ROW5Y = k.all_of(k.row(5), k.runs("y"))
ROW5X = k.all_of(k.row(5), k.runs("x"))

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "JOB 118: tower h=5 + tower h=2; the h=2 one 50 mm clear to the right of the h=5",
        k.pair(T(2), T(5), k.gap_of(1, _R)),
    ),
    _c(
        "rel-02",
        REL,
        "please to build one wall long five cubes, high two, and on top in the middle put one cube",
        one(k.on_top(T(1), k.wall(5, 2)), k.height(3), k.top_centred()),
    ),
    _c(
        "rel-03",
        REL,
        "Okay class, first a big flat square, three by three. And now a little tower of two "
        "right in the middle of it!",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.levels(9, 1, 1), k.top_centred()),
    ),
    _c(
        "rel-04",
        REL,
        "bridge: two pillars 150 mm tall, clear span between pillars 50 mm, beam on top",
        one(k.bridge(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "rel-05",
        REL,
        "um put a tower of three and then uh behind it like a wall five long two high",
        k.any_of(
            k.pair(k.wall(5, 2), T(3), k.all_rels(k.on_side(_B), _near)),
            one(k.cell_heights(3, 2, 2, 2, 2, 2), _peak_on(_F)),  # the tower against the wall
        ),
    ),
    _c(
        "rel-06",
        REL,
        "WO-7: ring 5x5 h=1 cube; 1x tower h=3 centred inside the ring",
        k.pair(k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)), T(3), k.centred_in()),
    ),
    _c(
        "rel-07",
        REL,
        "make pyramid of three floors and left from it one tower of four, distance one cube",
        k.pair(T(4), k.pyramid(3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-08",
        REL,
        "Now children, two towers of five first, and then we lay a long beam from one tower "
        "across to the other one, just like a bridge",
        one(k.bridge(5, pillars=2)),
    ),
    _c(
        "rel-09",
        REL,
        "slab 200 x 200 mm, 50 mm thick; on it a block 100 x 100 x 100 mm, centred",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.levels(16, 4, 4), k.centred()),
    ),
    _c(
        "rel-10",
        REL,
        "a tower of six and a tower of to in front of it",
        k.any_of(
            k.pair(T(2), T(6), k.all_rels(k.on_side(_F), _near)),
            one(k.xprofile(2, 6)),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "qty 3 towers h=2/h=4/h=6 in one line, ascending from right to left, 50 mm clear between",
        _in_order("y", T(6), T(4), T(2), gap=1),
    ),
    _c(
        "rel-12",
        REL,
        "between two towers of three please to put one block two on two, not touching them",
        k.between_(k.solid(2, 2), T(3)),
    ),
    _c(
        "rel-13",
        REL,
        "we take a flat square, four by four, and on each corner we put one more cube",
        one(k.base(4, 4), k.levels(16, 4), k.corner_columns(1)),
    ),
    _c(
        "rel-14",
        REL,
        "wall L 250 mm, H 100 mm; adjacent column at 1.5x the wall height",
        k.any_of(
            k.pair(T(3), k.wall(5, 2), _near),
            one(k.cell_heights(3, 2, 2, 2, 2, 2)),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "build a bridge with pillars of tree and then put a tower of two on top of it",
        one(k.on_top(T(2), k.all_of(k.bare_bridge, k.bridge(3, pillars=2))), k.height(6)),
    ),
    _c(
        "rel-16",
        REL,
        "the small tower, two cubes, it must stand behind the big tower of five, touching him",
        one(k.xprofile(5, 2)),
    ),
    _c(
        "rel-17",
        REL,
        "The red team builds a tower of four on the left, the blue team a tower of four on the "
        "right, and in the middle, between them, we put a little pyramid of two levels",
        k.between_(k.pyramid(2), T(4)),
    ),
    _c(
        "rel-18",
        REL,
        "row 5 cubes along Y; second row 5 cubes parallel to it, 50 mm clearance between rows",
        k.pair(ROW5Y, ROW5Y, k.parallel_gap(1)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "First we lay five cubes in a line. Then we put four on top of them. And then three "
        "more on top of those!",
        one(k.pyramid_counts(5, 4, 3), k.flat),
    ),
    _c(
        "seq-02",
        SEQ,
        "Step 1: slab 3x2, 1 layer. Step 2: second layer, same size. Step 3: tower h=2 on top, "
        "any position",
        one(k.on_top(T(2), k.block(3, 2, 2)), k.levels(6, 6, 1, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "ok first a wall um six long two high then uh take off the top row",
        one(k.row(6)),
    ),
    _c(
        "seq-04",
        SEQ,
        "build tower of seven... no, sorry, not of seven, of five",
        one(T(5)),
    ),
    _c(
        "seq-05",
        SEQ,
        "create 2 columns H=150 mm, 100 mm centre-to-centre; then place the 150 mm beam across "
        "the tops",
        one(k.bridge(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "seq-06",
        SEQ,
        "We build three towers of four in a row, with space between. Now we take away the "
        "tower at the left end.",
        k.each(2, T(4)),
    ),
    _c(
        "seq-07",
        SEQ,
        "1) row x5 along X (front to back). 2) duplicate it 1 cube to the left, parallel",
        k.pair(ROW5X, ROW5X, k.all_rels(k.parallel_gap(1), k.on_side(_L))),
    ),
    _c(
        "seq-08",
        SEQ,
        "put down a 2 by 2 um then a nother 2 by 2 on top and then a single cube on top of that",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.levels(4, 4, 1)),
    ),
    _c(
        "seq-09",
        SEQ,
        "first you make ring four on four, height one. after, you fill inside of it",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Let's make a tower of three. Good! Now make it two cubes taller.",
        one(T(5)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Block 100 x 150 x 50 mm. Revision: height 100 mm",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Seq: (a) tower h=3 at x=0.40 y=0.30, (b) tower h=3 at x=0.50 same y, (c) beam across both",
        one(k.bridge(3, pillars=2), k.leg_gap(1), k.near(0.45, 0.30)),
    ),
    _c(
        "seq-13",
        SEQ,
        "make to towers of four with a gap then put a beam on them then put won cube on top of "
        "the beam",
        one(k.on_top(T(1), k.all_of(k.bare_bridge, k.bridge(4, pillars=2))), k.height(6)),
    ),
    _c(
        "seq-14",
        SEQ,
        "at first the staircase of three steps, after that near to the highest step one tower "
        "of five",
        k.any_of(
            one(k.profile(1, 2, 3, 5)),
            k.pair(T(5), k.staircase(3), _near_top_step()),
        ),
    ),
    _c(
        "seq-15",
        SEQ,
        "Step one: a wall of four cubes, two high. Step two: a second wall just the same, "
        "behind the first one, with a gap of two cubes. Step three: count the cubes with me!",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.all_rels(k.parallel_gap(2), k.on_side(_B))),
    ),
    _c("seq-16", SEQ, "Tower h=8. EDIT: h=6, not 8", one(T(6))),
    _c(
        "seq-17",
        SEQ,
        "extrude a 3 x 3 cube footprint to 100 mm, then remove the centre column",
        one(k.ring_of(high=2, inner=(1, 1)), k.dims(3, 3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "qty 3 pillars, h=4 cubes each, spaced apart", k.each(3, T(4))),
    _c("num-02", NUM, "give me for towers of two", k.each(4, T(2))),
    _c("num-03", NUM, "make one tower with height of eight", one(T(8))),
    _c(
        "num-04",
        NUM,
        "How many cubes are in a tower of six? Six, well done! Let's build it.",
        one(T(6)),
    ),
    _c(
        "num-05",
        NUM,
        "array 2 x 3 of single cubes, pitch 100 mm",
        k.all_of(k.each(6, T(1)), k.layout(k.dims(3, 5))),
    ),
    _c(
        "num-06",
        NUM,
        "2x wall L=5 H=3, parallel, not touching",
        k.pair(k.wall(5, 3), k.wall(5, 3), _parallel),
    ),
    _c("num-07", NUM, "a pyramid tree levels high please", one(k.pyramid(3))),
    _c(
        "num-08",
        NUM,
        "I need the tower of three and the other tower, it has double of the height",
        k.any_of(k.structures(T(3), T(6)), one(k.cell_heights(3, 6))),
    ),
    _c(
        "num-09",
        NUM,
        "Twelve cubes, children: we make a floor with three rows of four",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-10",
        NUM,
        "items: 1x tower h=1, 1x tower h=3, 1x tower h=5, all separate",
        k.structures(T(1), T(3), T(5)),
    ),
    _c(
        "num-11",
        NUM,
        "4 cubes stacked = one 200 mm column; make two of those, 150 mm apart",
        k.pair(T(4), T(4), _gap_either(3, 2)),
    ),
    _c("num-12", NUM, "just won cube at the front please", one(T(1), reg(_F))),
    _c(
        "num-13",
        NUM,
        "make the wall from ten cubes, in two lines, each line five",
        one(k.wall(5, 2)),
    ),
    _c(
        "num-14",
        NUM,
        "a tower of eight, and next to it a little one that is only half as tall",
        k.any_of(k.pair(T(4), T(8), _near), one(k.cell_heights(8, 4))),
    ),
    _c(
        "num-15",
        NUM,
        "4x tower h=2 on the corners of a 4x4-cube square, nothing in between",
        k.all_of(k.each(4, T(2)), k.layout(k.dims(4, 4))),
    ),
    _c(
        "num-16",
        NUM,
        "three-tier stepped pyramid, tiers 3x3, 2x2, 1x1 cubes",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-17",
        NUM,
        "um make a staircase with uh five steps no six steps",
        one(k.staircase(6)),
    ),
    _c(
        "num-18",
        NUM,
        "two times the tower of three, and between them distance of two cubes",
        k.pair(T(3), T(3), _gap_either(2, 1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "column, H=350 mm", one(T(7))),
    _c("dim-02", DIM, "footprint 150 x 100 mm, 3 layers", one(k.block(3, 2, 3))),
    _c("dim-03", DIM, "plate 250 x 150 x 50 mm", one(k.block(5, 3, 1))),
    _c("dim-04", DIM, "a tower about twenty centimetres tall", one(T(4))),
    _c(
        "dim-05",
        DIM,
        "wall with length of 0.3 meter and height of 0.1 meter",
        one(k.wall(6, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "ring, outer 200 x 200 mm, wall height 50 mm",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c("dim-07", DIM, "row, L=400 mm, along Y", one(k.row(8), k.runs("y"))),
    _c(
        "dim-08",
        DIM,
        "Who has a ruler? Fifteen centimetres. The robot makes a tower exactly that tall.",
        one(T(3)),
    ),
    _c(
        "dim-09",
        DIM,
        "staircase, total rise 200 mm, 50 mm per step",
        one(k.staircase(4)),
    ),
    _c(
        "dim-10",
        DIM,
        "2 columns H=100 mm, clear gap 250 mm",
        k.pair(T(2), T(2), k.gap_of(5)),
    ),
    _c("dim-11", DIM, "block 10x10x15 cm", one(k.block(2, 2, 3))),
    _c(
        "dim-12",
        DIM,
        "bridge: pillar height 250 mm, inner clearance 50 mm",
        one(k.bridge(5, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "dim-13",
        DIM,
        "make a square platform, side 20 centimetre, thick 10 centimetre",
        one(k.block(4, 4, 2)),
    ),
    _c("dim-14", DIM, "uh a row of cubes like thirty five centimetres long", one(k.row(7))),
    _c(
        "dim-15",
        DIM,
        "pyramid, base 150 x 150 mm, total height 150 mm",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c("dim-16", DIM, "tower h=0.45 m at x=0.5 y=0.3", one(T(9), k.near(0.5, 0.3))),
    _c(
        "dim-17",
        DIM,
        "A wall as long as your hand, about twenty centimetres, and two cubes high.",
        one(k.wall(4, 2)),
    ),
    _c("dim-18", DIM, "wall 1 cube thick, 150 mm long, 200 mm high", one(k.wall(3, 4))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "tower h=5, NOT in the centre zone",
        one(T(5), not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-02",
        NEG,
        "a wall four long three high no beams",
        one(k.wall(4, 3), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "the pyramid please not more than two floors, base three on three",
        one(k.base(3, 3), k.pyramid(2)),
    ),
    _c(
        "neg-04",
        NEG,
        "Towers of four, three of them, and none of them may touch another one.",
        k.each(3, T(4)),
    ),
    _c(
        "neg-05",
        NEG,
        "ring 5x5, h=2, no infill",
        one(k.ring_of(high=2, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c(
        "neg-06",
        NEG,
        "staircase 4 steps, must not rise to the left",
        one(k.staircase(4), not_(k.rises(_L), "rises to the left")),
    ),
    _c("neg-07", NEG, "not a pyramid um a block two by two by three", one(k.block(2, 2, 3))),
    _c(
        "neg-08",
        NEG,
        "row of six cubes but no in the direction front-back",
        one(k.row(6), k.runs("y")),
    ),
    _c(
        "neg-09",
        NEG,
        "A bridge, but without the beam on top this time: just the two pillars of three, with a "
        "gap between them",
        k.each(2, T(3)),
    ),
    _c(
        "neg-10",
        NEG,
        "slab 4x3 cubes, single layer; do not place anything in the right half of the table",
        one(k.block(4, 3, 1), _all_left_of_centre),
    ),
    _c("neg-11", NEG, "tower h=3, not at the back", one(T(3), not_(reg(_B), "at the back"))),
    _c("neg-12", NEG, "a tower of five uh no not five six", one(T(6))),
    _c(
        "neg-13",
        NEG,
        "one tower of four, nothing else, no other things on the table",
        one(T(4)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towre h=4 at fornt-left", one(T(4), reg("front left"))),
    _c("typo-02", TYP, "plese to bild a wal of lenght 5 hight 2", one(k.wall(5, 2))),
    _c("typo-03", TYP, "pyramd 3 lvls", one(k.pyramid(3))),
    _c(
        "typo-04",
        TYP,
        "stiarcase 5 stpes going up to the rigth",
        one(k.staircase(5), k.rises(_R)),
    ),
    _c("typo-05", TYP, "slab 200 x 100 mm, 2 laeyrs", one(k.block(4, 2, 2))),
    _c("typo-06", TYP, "rign 4x4 h=1", one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4))),
    _c("typo-07", TYP, "brigde, pilars h=2", one(k.bridge(2, pillars=2))),
    _c("typo-08", TYP, "now we bulid a towr of thre cubes", one(T(3))),
    _c("typo-09", TYP, "2 towres h=3, 2 cubs apart", k.pair(T(3), T(3), _gap_either(2, 1))),
    _c("typo-10", TYP, "qty 1 cueb at x=0.7 y=0.45", one(T(1), k.near(0.7, 0.45))),
    _c(
        "typo-11",
        TYP,
        "a plattform 3x3 with tower of 2 on teh middle",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred()),
    ),
    _c("typo-12", TYP, "L-shaep 3 by 3 one layer", one(L_SHAPE, k.dims(3, 3), k.height(1))),
    _c("typo-13", TYP, "a wall for long to high", one(k.wall(4, 2))),
    _c("typo-14", TYP, "tabel with 4 legz h=3", one(k.canopy(4, 3, 3))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "A tower of five build you at left side", one(T(5), reg(_L))),
    _c(
        "wo-02",
        WO,
        "Of four cubes a row make, from left to right going",
        one(k.row(4), k.runs("y")),
    ),
    _c("wo-03", WO, "High three, long five, the wall", one(k.wall(5, 3))),
    _c(
        "wo-04",
        WO,
        "On the block two by two a tower of two put",
        one(k.on_top(T(2), k.solid(2, 2))),
    ),
    _c("wo-05", WO, "at x=0.35 y=0.20: tower, h=3", one(T(3), k.near(0.35, 0.20))),
    _c(
        "wo-06",
        WO,
        "Behind the pyramid of two levels, a tower of four, two cubes far",
        k.pair(T(4), k.pyramid(2), k.gap_of(2, _B)),
    ),
    _c(
        "wo-07",
        WO,
        "Steps, four of them, up to the back climbing",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "wo-08",
        WO,
        "The pillars three high make, and over them a beam lay",
        one(k.bridge(3, pillars=2)),
    ),
    _c("wo-09", WO, "3 layers, 100 x 100 mm, block", one(k.block(2, 2, 3))),
    _c(
        "wo-10",
        WO,
        "Inside a ring of six by six, a block two by two",
        k.any_of(
            k.around(k.solid(2, 2), k.all_of(k.ring, k.dims(6, 6))),
            one(k.holding(k.solid(2, 2), k.all_of(k.ring, k.dims(6, 6)))),
        ),
    ),
    _c(
        "wo-11",
        WO,
        "Right of the wall four long two high, a tower of three, touching it",
        one(k.cell_heights(3, 2, 2, 2, 2), _peak_on(_R)),
    ),
    _c("wo-12", WO, "cubes eight in one column stacked", one(T(8))),
    _c(
        "wo-13",
        WO,
        "in the back right corner, a slab three by two, one layer",
        one(k.block(3, 2, 1), reg("back right")),
    ),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "uh yeah so um can you like build a tower of five", one(T(5))),
    _c(
        "fil-02",
        FIL,
        "Okay everybody, quiet please, thank you. Now the robot is going to build a wall six "
        "cubes long and two cubes high. Watch carefully!",
        one(k.wall(6, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Ticket #5521 / requester: line 3 / priority: low / desc: 2x2 block h=4 cubes / "
        "notes: none",
        one(k.block(2, 2, 4)),
    ),
    _c(
        "fil-04",
        FIL,
        "hello, good morning, sorry for my english, please can you make for me one pyramid with "
        "three levels, thank you very much",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "um so like a staircase uh four steps yeah that's it over",
        one(k.staircase(4)),
    ),
    _c(
        "fil-06",
        FIL,
        "per drawing rev B, sheet 2 of 3, see detail A: ring 4 x 4 cubes, H 100 mm, tolerance n/a",
        one(k.ring_of(high=2, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "fil-07",
        FIL,
        "Who remembers what a bridge is? Yes, Tom! Two pillars and something on top. So let's "
        "ask the robot for a bridge with pillars of two.",
        one(k.bridge(2, pillars=2)),
    ),
    _c(
        "fil-08",
        FIL,
        "okay robot uh hmm let me think um a row of five cubes I guess",
        one(k.row(5)),
    ),
    _c(
        "fil-09",
        FIL,
        "URGENT (again) - customer visit 14:00 - need: tower h=7, anywhere - thx",
        one(T(7)),
    ),
    _c(
        "fil-10",
        FIL,
        "so, I try to explain: I want one wall, the length is three, the height is four, okay? "
        "that's all",
        one(k.wall(3, 4)),
    ),
    _c(
        "fil-11",
        FIL,
        "Remember to keep your hands away from the robot. Good. Now: a flat square of four by "
        "four cubes, just one layer.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "fil-12",
        FIL,
        "like seriously just a cube um one cube in the middle of the table you know",
        one(T(1), reg("centre")),
    ),
    _c(
        "fil-13",
        FIL,
        "note: all dims in mm unless stated otherwise. item 1: tower, H 200",
        one(T(4)),
    ),
    _c(
        "fil-14",
        FIL,
        "FYI cell 2 is down for maintenance till Friday; meanwhile on this cell: 2 towers h=3, "
        "1 cube gap",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower h=4 @ x=0.60 y=0.40", one(T(4), k.near(0.60, 0.40))),
    _c("reg-02", REG, "a tower of three over on the left side", one(T(3), reg(_L))),
    _c(
        "reg-03",
        REG,
        "please one pyramid of two levels in the corner front right",
        one(k.pyramid(2), reg("front right")),
    ),
    _c(
        "reg-04",
        REG,
        "The robot puts one cube far away at the back, the furthest it can.",
        one(T(1), k.near(x=0.75, tol=0.05)),
    ),
    _c(
        "reg-05",
        REG,
        "block 2x2x2 cubes, centre at (0.45, 0.30)",
        one(k.block(2, 2, 2), k.near(0.45, 0.30)),
    ),
    _c(
        "reg-06",
        REG,
        "wall L=6 H=2 along the back edge",
        one(k.wall(6, 2), k.runs("y"), reg(_B)),
    ),
    _c(
        "reg-07",
        REG,
        "put a row of four along the right side front to back",
        one(k.row(4), k.runs("x"), reg(_R)),
    ),
    _c(
        "reg-08",
        REG,
        "tower of six, put him close at the robot, in front",
        one(T(6), reg(_F)),
    ),
    _c(
        "reg-09",
        REG,
        "One tower on the left side of the table and one on the right side, both three cubes.",
        k.structures(k.all_of(T(3), reg(_L)), k.all_of(T(3), reg(_R))),
    ),
    _c(
        "reg-10",
        REG,
        "ring 3x3, h=1, centred on x=0.60 y=0.20",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3), k.near(0.60, 0.20)),
    ),
    _c("reg-11", REG, "slab 4x4 1L, centre of table", one(k.block(4, 4, 1), reg("centre"))),
    _c(
        "reg-12",
        REG,
        "a staircase of three in the back left",
        one(k.staircase(3), reg("back left")),
    ),
    _c(
        "reg-13",
        REG,
        "two towers of two, one in the front, one in the back",
        k.structures(k.all_of(T(2), reg(_F)), k.all_of(T(2), reg(_B))),
    ),
    _c(
        "reg-14",
        REG,
        "tower H 150, offset 100 mm to the right of the table centre",
        one(T(3), k.near(y=0.20), k.near(x=0.45, tol=0.05)),
    ),
    _c(
        "reg-15",
        REG,
        "Let's put a little wall of three, two high, right in front of the robot, close to it.",
        one(k.wall(3, 2), reg(_F), k.near(y=0.30, tol=0.06)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Let's build something the children can push a toy car under.",
        one(k.any_of(k.bridge(), k.arch, k.canopy())),
    ),
    _c("open-02", OPEN, "demo piece, any shape, max h=3 cubes", _low_demo),
    _c("open-03", OPEN, "um just build like a tall thing", one(k.height(lo=4))),
    _c("open-04", OPEN, "make something nice, small, for the photo", k.small),
    _c(
        "open-05",
        OPEN,
        "test part: any solid block, footprint at least 3 x 3 cubes",
        one(k.full, _min_side(3)),
    ),
    _c(
        "open-06",
        OPEN,
        "A wall for our castle. You decide how long.",
        one(k.wall(lo=2)),
    ),
    _c(
        "open-07",
        OPEN,
        "a few towers, heights at operator's discretion",
        k.few(2, 6, T(lo=1)),
    ),
    _c("open-08", OPEN, "build uh some kind of stairs", one(k.staircase(lo=2))),
    _c(
        "open-09",
        OPEN,
        "one enclosure for the animals, the size is your choice",
        one(k.ring),
    ),
    _c(
        "open-10",
        OPEN,
        "A short tower, not taller than my hand.",
        one(T(lo=2, hi=4)),  # a hand is 18–20 cm
    ),
    _c("open-11", OPEN, "pyramid, any number of tiers", one(k.pyramid(lo=2))),
    _c(
        "open-12",
        OPEN,
        "platform for a sensor: flat, single layer, min 2x2",
        one(k.full, k.height(1), k.broad),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "tower h=15 cubes", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-02", BAD, "row L=1200 mm", k.honest(one(k.row(lo=2, hi=12)))),
    _c("bad-03", BAD, "uh um hmm okay so yeah", k.honest()),
    _c(
        "bad-04",
        BAD,
        "make tower of three what is five high",
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c("bad-05", BAD, "tower h=3 at x=0.95 y=0.30", k.honest(one(T(3)))),
    _c(
        "bad-06",
        BAD,
        "block 100 x 100 x -50 mm",
        k.honest(one(k.full, k.dims(2, 2))),
    ),
    _c("bad-07", BAD, "Build the same thing as the other class did.", k.honest()),
    _c("bad-08", BAD, "zzzt krrk inaudible kkhh", k.honest()),
    _c(
        "bad-09",
        BAD,
        "2x tower h=4, clear gap 300 mm, beam on top",
        k.honest(k.any_of(k.each(2, T(4)), one(k.bridge(4, pillars=2)))),
    ),
    _c("bad-10", BAD, "slab 600 x 600 mm, 1 layer", k.honest(one(k.full, k.height(1)))),
    _c("bad-11", BAD, "please make it more big", k.honest()),
    _c(
        "bad-12",
        BAD,
        "build a tower of uh [inaudible] cubes",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-13",
        BAD,
        "A ring that is only one cube wide and one cube long.",
        k.honest(one(k.any_of(T(lo=1), k.ring))),
    ),
    _c("bad-14", BAD, "staircase, 0 steps", k.honest()),
    _c("bad-15", BAD, "pyramid base 100 x 100 mm, 5 tiers", k.honest(one(k.pyramid()))),
)
