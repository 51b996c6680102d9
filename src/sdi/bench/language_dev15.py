"""A fifteenth held-out set for the language front end (dev15): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev14` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a line worker dictating to a phone's voice assistant with gloves on — run-on sentences,
  "um", "okay so", and words the speech recogniser got wrong ("tour" for tower, "rope" for
  row, "peer amid", "stare case", "for" / "to" / "tree" / "sick" for numbers);
* a process engineer pasting a terse change request from an email — bullets, numbered steps,
  "Re:", quoted lines and a signature;
* an architecture student using building words loosely for cube structures — colonnade,
  portico, lintel, plinth, podium, stair, terrace, courtyard, pavilion;
* a parent building with a child ("let's make a …", "can the robot do a … for Emma");
* an operator whose first language is German or Spanish — odd prepositions ("in the height
  of", "left from it"), floors for levels, "make me", metric everything, decimal commas
  ("0,3 m").

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three structures, references ("it", "the first one", "the little
one"), distributive phrases ("each", "between each"), comparisons ("twice the height", "one
less"), corrections ("no wait, make it four high"), removals and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — one merged structure where a
tower could be set down touching another, both clear and centre-to-centre readings of an
unqualified spacing where both are buildable — and nothing else. Geometry comes only from
`sdi.bench.boxes`, through the shared checks in `language_checks` and the local checks below.

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
    return Case(id=f"dev15-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _gaps(*ns: int, side: str | None = None) -> k.Rel:
    """A and B are one of `ns` cubes apart (clear, ± 1.5 cm); A on `side` of B when given."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for n in ns:
            r = k.gap_of(n, side)(a, b)
            if r is None:
                return None
            first = first or r
        return first

    return rel


def _spaced(n: int, check: k.Check, gap: int) -> k.Pred:
    """n separate structures passing `check`, each `gap` cubes (clear, ± 1.5 cm) from its
    nearest neighbour — in a line or in a cluster."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.each(n, check)(result)
        if r:
            return r
        comps = bx.components(bx.boxes(result))
        for a in comps:
            d = min(bx.separation(a, b) for b in comps if b is not a)
            if abs(d - gap * bx.CUBE) > 0.015:
                return f"a structure {d:.3f} m from its nearest neighbour, want {gap} cube(s)"
        return None

    return f


def _pieces(lo: int, hi: int) -> k.Pred:
    """Some layout on the table in the workspace, of lo–hi separate structures."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.anything(result)
        if r:
            return r
        n = len(bx.components(bx.boxes(result)))
        return None if lo <= n <= hi else f"{n} separate structures, want {lo}–{hi}"

    return f


def _column_sizes(*ns: int) -> k.Check:
    """The parts, grouped by footprint centre, form stacks of exactly these sizes."""

    def f(bs: k.Boxes) -> k.Reason:
        got = sorted(len(c) for c in bx.columns(bs))
        return None if got == sorted(ns) else f"stacks of {got}, want {sorted(ns)}"

    return f


def _top_ring(bs: k.Boxes) -> k.Reason:
    """The topmost level is a ring round one empty cell (the centre cube left out)."""
    z = max(round(b.lo[2], 3) for b in bs)
    top = [b for b in bs if round(b.lo[2], 3) == z]
    return k.ring_of(inner=(1, 1))(top)


def _has_beam(bs: k.Boxes) -> k.Reason:
    """At least one part longer than a cube (a beam)."""
    return None if any(max(b.size) > 0.1 for b in bs) else "no beam"


def _symmetric(bs: k.Boxes) -> k.Reason:
    """The occupied cells are mirror-symmetric front to back or left to right."""
    vox = bx.voxels(bs)
    nx, ny = bx.footprint_cubes(bs)
    if {(nx - 1 - i, j, z) for i, j, z in vox} == vox:
        return None
    if {(i, ny - 1 - j, z) for i, j, z in vox} == vox:
        return None
    return "not mirror-symmetric either way"


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
GATE = k.bridge
RING5 = k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5))
RING4 = k.all_of(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4))


# an L with both arms 4 (sharing the corner) or 5 (4 beyond the corner), a 2-cube tower in
# the inside corner touching both arms
_L4_TOWER = k.plan_heights("1111", "12..", "1...", "1...")
_L5_TOWER = k.plan_heights("11111", "12...", "1....", "1....", "1....")


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "okay so um build a tower of four and then right next to it on the left another tower "
        "of two with like one cube of space",
        k.pair(T(2), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "rel-02",
        REL,
        "Re: trial build for line 4\n- wall, 5 long x 2 high\n- 1x tower (3 cubes) behind the "
        "wall, 1 cube clearance\nThanks, M. Keller",
        k.pair(T(3), k.wall(5, 2), k.gap_of(1, _B)),
    ),
    _c(
        "rel-03",
        REL,
        "A portico: two columns four cubes tall with a lintel across the top, the columns one "
        "cube apart.",
        one(GATE(4, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "rel-04",
        REL,
        "let's make a tower of five for Emma and a little one of two right in front of it so "
        "she can see both, leave a gap",
        k.pair(T(2), T(5), k.all_rels(k.on_side(_F), _near)),
    ),
    _c(
        "rel-05",
        REL,
        "Make me a wall with 4 cubes in the length and 3 in the height, and a tower with 2 "
        "floors on the right side of the wall, distance 5 cm.",
        k.pair(T(2), k.wall(4, 3), k.gap_of(1, _R)),
    ),
    _c(
        "rel-06",
        REL,
        "okay build a pyramid with three levels and put a single cube on top of uh no next to "
        "it on the right side not touching",
        k.pair(T(1), k.pyramid(3), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "rel-07",
        REL,
        "CR-112: place 2x2 block (2 high) at table centre; 4-cube tower directly on top of it, "
        "centred.",
        one(k.on_top(T(4), k.block(2, 2, 2)), k.centred(), reg("centre")),
    ),
    _c(
        "rel-08",
        REL,
        "A courtyard: a ring of cubes one high, five by five outside, with a single column of "
        "three standing in the middle of it as a monument.",
        k.pair(RING5, T(3), k.centred_in()),
    ),
    _c(
        "rel-09",
        REL,
        "can the robot build two towers of three for Emma with a bridge on top so her little "
        "car can go under",
        one(GATE(3, pillars=2)),
    ),
    _c(
        "rel-10",
        REL,
        "Please put a row of 6 cubes from left to right, and behind this row, in distance of "
        "one cube, a second row also of 6.",
        k.pair(
            k.all_of(k.row(6), k.runs("y")),
            k.all_of(k.row(6), k.runs("y")),
            k.parallel_gap(1),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "so um three towers in a line two then four then six going front to back okay and uh "
        "a cube gap between each one",
        k.in_order("x", T(2), T(4), T(6), gaps=(1,)),
    ),
    _c(
        "rel-12",
        REL,
        "Scope:\n1. Tower A - 5 cubes\n2. Tower B - 3 cubes, 2 cubes clear to the left of A\n"
        "3. Beam? NO - keep them separate\nRegards, Process Eng.",
        k.pair(T(3), T(5), k.gap_of(2, _L)),
    ),
    _c(
        "rel-13",
        REL,
        "Put a plinth down first, a 3 by 3 slab one cube thick, and stand four columns of two "
        "on its corners.",
        one(k.base(3, 3), k.corner_columns(2), k.levels(9, 4, 4)),
    ),
    _c(
        "rel-14",
        REL,
        "Build me a bridge: two towers with 3 floors, between them 5 cm, and on top a beam of "
        "15 cm.",
        one(GATE(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "rel-15",
        REL,
        "okay put a staircase with four steps and um a tower the same height as the top step "
        "next to it with a little gap",
        k.pair(T(4), k.staircase(4), _near),
    ),
    _c(
        "rel-16",
        REL,
        "Request: 1 x pyramid (3 levels) in centre; 1 x ring, 1 high, around it. Ring must not "
        "touch pyramid.",
        k.around(k.pyramid(3), k.ring_of(high=1)),
    ),
    _c(
        "rel-17",
        REL,
        "A small colonnade: three columns of four cubes standing in a row left to right, a "
        "cube's space between them, no lintel.",
        k.in_order("y", T(4), T(4), T(4), gaps=(1,)),
    ),
    _c(
        "rel-18",
        REL,
        "for Emma: a little 2 by 2 block, two cubes high, and a tower of five on each side of "
        "it with a bit of space",
        k.between_(k.block(2, 2, 2), T(5)),
    ),
    _c(
        "rel-19",
        REL,
        "Make a tower with 6 floors. Left from it, in distance of 2 cubes, a tower with the half "
        "height. Right from it the same.",
        k.in_order("y", T(3), T(6), T(3), gaps=(1, 2)),
    ),
    _c(
        "rel-20",
        REL,
        "okay so a fence around a tower uh the tower's three high and the fence is just one "
        "cube high all the way round",
        k.any_of(
            k.around(T(3), k.ring_of(high=1)),
            one(k.holding(T(3), k.ring_of(high=1))),
        ),
    ),
    _c(
        "rel-21",
        REL,
        "> can you do the L-shape again?\nYes. L-shape, both arms 4 cubes, 1 layer. Add a "
        "2-cube tower in the inside corner, touching both arms.",
        one(k.any_of(_L4_TOWER, _L5_TOWER)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "okay so stack four cubes and then um put two more on top of that one",
        one(T(6)),
    ),
    _c(
        "seq-02",
        SEQ,
        "Change request #88\n1) Build wall 6 long, 2 high.\n2) Remove the two end cubes of the "
        "top course.\nThat's it.",
        one(k.profile(1, 2, 2, 2, 2, 1), k.flat),
    ),
    _c(
        "seq-03",
        SEQ,
        "Lay a podium four by four, one cube high. Then a second tier two by two centred on it, "
        "then a column two cubes high on top of that.",
        one(k.base(4, 4), k.levels(16, 4, 1, 1), k.centred()),
    ),
    _c(
        "seq-04",
        SEQ,
        "let's build a tower of three for Emma. okay now she wants it taller, add three more",
        one(T(6)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Make me a row with 5 cubes. No, sorry, with 7 cubes, the 5 was wrong.",
        one(k.row(7)),
    ),
    _c(
        "seq-06",
        SEQ,
        "build a pyramid uh four levels and then um take off the top two levels",
        one(k.pyramid(2), k.long(lo=4)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Steps:\n- two towers, 4 cubes, 1 cube apart\n- beam across tops\n- one cube on the "
        "beam, centre\nDone = bridge w/ cube on top.",
        one(
            k.on_top(T(1), k.all_of(k.bare_bridge, GATE(4, pillars=2))),
            k.leg_gap(1),
            k.height(6),
            k.top_centred(),
        ),
    ),
    _c(
        "seq-08",
        SEQ,
        "Build a flight of five steps, then knock off the lowest step.",
        one(k.profile(2, 3, 4, 5)),
    ),
    _c(
        "seq-09",
        SEQ,
        "let's make two towers for Emma, one of four and one of two, apart. now put the little "
        "one on top of the big one",
        one(T(6)),
    ),
    _c(
        "seq-10",
        SEQ,
        "First you build a slab of 3 x 4 cubes. After, on this slab you put a second layer, but "
        "only 2 x 3, in the middle.",
        one(k.on_top(k.block(2, 3, 1), k.block(3, 4, 1)), k.centred()),
    ),
    _c(
        "seq-11",
        SEQ,
        "build a wall five long three high no wait make it four high sorry",
        one(k.wall(5, 4)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Per call today:\n1. 3 towers of 3, in a row L-R, 1 cube gaps\n2. remove the middle "
        "one\n3. put its cubes on the right-hand tower",
        k.pair(T(3), T(6), k.gap_of(3, _L)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Lay out the ground floor of a courtyard, a square ring four by four, then raise its "
        "walls to three cubes.",
        one(k.ring_of(high=3, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "can the robot put a row of four cubes down for Emma, then another row of four on top, "
        "and then one more",
        one(k.any_of(k.wall(4, 3), k.on_top(T(1), k.wall(4, 2)))),
    ),
    _c(
        "seq-15",
        SEQ,
        "Make two towers, the first with 2 floors, the second with 5 floors, 10 cm between "
        "them. Then make the first one the same height like the second.",
        k.pair(T(5), T(5), _gaps(1, 2)),
    ),
    _c(
        "seq-16",
        SEQ,
        "okay um lay down a three by three plate and then take the middle one out",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Action items\n- Build staircase, 3 steps, rising to the back\n- Then add a 4th step at "
        "the top end\n- Keep it climbing to the back",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Two columns of three, one cube apart; lay a lintel across; then a second storey: two "
        "more columns of two standing on the ends of the lintel.",
        one(GATE(3, pillars=2), k.leg_gap(1), k.levels(2, 2, 2, 1, 2, 2), _column_sizes(1, 5, 5)),
    ),
    _c(
        "seq-19",
        SEQ,
        "let's make a tower of four, then another tower of four next to it, and then put one "
        "more cube on top of the first one so it's the biggest",
        k.any_of(k.pair(T(5), T(4), _near), one(k.cell_heights(5, 4))),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "okay so a tower um seven high", one(T(7))),
    _c(
        "num-02",
        NUM,
        "Qty 3 towers, 2 cubes each, in a line, 1 cube spacing.",
        k.in_line(3, T(2), 1),
    ),
    _c(
        "num-03",
        NUM,
        "A colonnade of five slender columns, each three cubes high, spaced one cube apart.",
        k.in_line(5, T(3), 1),
    ),
    _c("num-04", NUM, "let's do a tower as tall as Emma is old, she's six", one(T(6))),
    _c("num-05", NUM, "Make me a tower with 8 floors, please.", one(T(8))),
    _c(
        "num-06",
        NUM,
        "okay two towers of five uh and a third one that's one less um all apart",
        k.structures(T(5), T(5), T(4)),
    ),
    _c("num-07", NUM, "Qty: 1 dozen cubes as a 3x4 pad, single layer.", one(k.block(3, 4, 1))),
    _c(
        "num-08",
        NUM,
        "A terrace in three tiers: the bottom tier a row of six, the next four, the top two - "
        "stepped like a ziggurat seen from the side.",
        one(k.pyramid_counts(6, 4, 2), k.flat),
    ),
    _c(
        "num-09",
        NUM,
        "can the robot make a tower with one cube for every finger on my hand",
        one(T(5)),
    ),
    _c("num-10", NUM, "Please a row of cubes with length 0,3 m.", one(k.row(6))),
    _c("num-11", NUM, "um a wall uh ten cubes long and two high", one(k.wall(10, 2))),
    _c("num-12", NUM, "Need: tower H=9 (cubes). Nothing else.", one(T(9))),
    _c(
        "num-13",
        NUM,
        "Two columns flanking an entrance, the left one twice the height of the right one, "
        "which is three cubes.",
        k.pair(T(6), T(3), k.all_rels(k.on_side(_L), _near)),
    ),
    _c(
        "num-14",
        NUM,
        "three towers for the three kids, Emma's is 2, Ben's is 4 and the baby's is just 1, "
        "not touching",
        k.structures(T(2), T(4), T(1)),
    ),
    _c("num-15", NUM, "Make me one tower, the height is the double of 4 cubes.", one(T(8))),
    _c(
        "num-16",
        NUM,
        "okay build three towers of three no actually make that four towers of three a cube apart",
        _spaced(4, T(3), 1),
    ),
    _c("num-17", NUM, "Spec: staircase, n=6 steps.", one(k.staircase(6))),
    _c("num-18", NUM, "A square pyramid, four courses.", one(k.pyramid(4), k.broad)),
    _c(
        "num-19",
        NUM,
        "Build two walls with 5 cubes in the length. The first wall has 2 cubes in the height, "
        "the second one more. Between them 1 cube.",
        k.pair(k.wall(5, 2), k.wall(5, 3), _gaps(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "okay I need a slab um four by five just one layer",
        one(k.block(4, 5, 1)),
    ),
    _c(
        "dim-02",
        DIM,
        "- Block: L 3 / W 2 / H 2 (cubes)\n- anywhere on table",
        one(k.block(3, 2, 2)),
    ),
    _c("dim-03", DIM, "A podium 20 cm by 15 cm and 10 cm high.", one(k.block(4, 3, 2))),
    _c(
        "dim-04",
        DIM,
        "let's make a big wall for Emma's dinosaurs, like 6 cubes long and as high as 4",
        one(k.wall(6, 4)),
    ),
    _c(
        "dim-05",
        DIM,
        "Make me a wall, 25 cm in the length and 15 cm in the height.",
        one(k.wall(5, 3)),
    ),
    _c("dim-06", DIM, "I need a plate of 0,2 x 0,15 m, one layer.", one(k.block(4, 3, 1))),
    _c(
        "dim-07",
        DIM,
        "a um tower thats two cubes wide and two cubes deep and five tall",
        one(k.block(2, 2, 5)),
    ),
    _c(
        "dim-08",
        DIM,
        "Enclosure: outer 5x4, wall height 2, open interior.",
        one(k.ring_of(high=2, inner=(3, 2)), k.dims(4, 5)),
    ),
    _c(
        "dim-09",
        DIM,
        "A portico whose columns are 15 cm tall, spanned by a single lintel.",
        one(GATE(3, pillars=2)),
    ),
    _c(
        "dim-10",
        DIM,
        "Emma wants a fence for her animals, a square one, 6 cubes on each side, just one high",
        one(k.ring_of(high=1, inner=(4, 4)), k.dims(6, 6)),
    ),
    _c(
        "dim-11",
        DIM,
        "Make a stair with 5 steps, the steps 2 cubes wide.",
        one(k.staircase(5), k.dims(2, 5)),
    ),
    _c(
        "dim-12",
        DIM,
        "Wall, 0.40 m long x 0.10 m high, thickness 1 cube, run front-to-back.",
        one(k.wall(8, 2), k.runs("x")),
    ),
    _c(
        "dim-13",
        DIM,
        "make a block thats um three wide four deep and two high wide meaning left to right",
        one(k.block_xy(4, 3, 2)),
    ),
    _c(
        "dim-14",
        DIM,
        "A plinth 4 by 4, one cube thick, with a column 4 cubes tall rising from its centre.",
        one(k.on_top(T(4), k.block(4, 4, 1)), k.centred(), k.levels(16, 1, 1, 1, 1)),
    ),
    _c(
        "dim-15",
        DIM,
        "A bridge where the pillars are in the height of 20 cm and the distance of the pillars "
        "is 5 cm.",
        one(GATE(4, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "dim-16",
        DIM,
        "a little table for Emma's doll, legs two cubes high",
        one(k.canopy(lo=2, hi=2)),
    ),
    _c(
        "dim-17",
        DIM,
        "Pls confirm & build:\n* grid 5 (x) by 2 (y), 1 layer\n* x = depth, y = width",
        one(k.block_xy(5, 2, 1)),
    ),
    _c(
        "dim-18",
        DIM,
        "A stepped terrace, three terraces deep front to back, each a cube higher than the one "
        "in front, five cubes wide.",
        one(k.staircase(3), k.rises(_B), k.dims(3, 5)),
    ),
    _c(
        "dim-19",
        DIM,
        "Make an L from cubes: one side 30 cm, the other side 20 cm, only one layer.",
        one(k.shape_letter("L"), k.dims(4, 6), k.height(1)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "okay a tower of five and um don't put it in the middle put it over on the right",
        one(T(5), reg("right"), k.not_(reg("centre"), "in the middle")),
    ),
    _c("neg-02", NEG, "Build 4x4 pad. NOT two layers - one layer only.", one(k.block(4, 4, 1))),
    _c(
        "neg-03",
        NEG,
        "A courtyard ring, 4 by 4, one course high, with nothing inside it.",
        one(RING4),
    ),
    _c(
        "neg-04",
        NEG,
        "let's do a pyramid for Emma but not a tall one, just two levels",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-05",
        NEG,
        "Make me a wall with 6 cubes in the length, but not higher than 2 cubes.",
        one(k.any_of(k.wall(6, 2), k.row(6))),
    ),
    _c(
        "neg-06",
        NEG,
        "build a staircase four steps but uh not going sideways I want it climbing up towards "
        "the back",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c("neg-07", NEG, "Row of 7, along Y. Do not stack anything.", one(k.row(7), k.runs("y"))),
    _c(
        "neg-08",
        NEG,
        "Two columns of four without any lintel, just standing a cube apart.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "neg-09",
        NEG,
        "a tower for Emma, not too tall or she'll knock it over, maybe four?",
        one(T(4)),
    ),
    _c(
        "neg-10",
        NEG,
        "Please two towers with 3 floors, but they must not touch themselves, 5 cm between.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "neg-11",
        NEG,
        "okay put a row of six um not left to right I mean front to back",
        one(k.row(6), k.runs("x")),
    ),
    _c(
        "neg-12",
        NEG,
        "Build a 3x3x3 cube block.\n- no beams\n- skip the centre cube of the top layer",
        one(k.dims(3, 3), k.levels(9, 9, 8), k.only_cubes, _top_ring),
    ),
    _c(
        "neg-13",
        NEG,
        "Raise a single column of five on the left side of the table - not on the right, and "
        "not touching anything.",
        one(T(5), reg("left")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typ-01", TYP, "okay build a tour of five cubes", one(T(5))),
    _c("typ-02", TYP, "um put down a rope of six cubes", one(k.row(6))),
    _c("typ-03", TYP, "build a peer amid with three levels", one(k.pyramid(3))),
    _c("typ-04", TYP, "okay make a stare case with for steps", one(k.staircase(4))),
    _c(
        "typ-05",
        TYP,
        "build to towers of tree cubes with a gap",
        k.pair(T(3), T(3), _near),
    ),
    _c(
        "typ-06",
        TYP,
        "Biuld 2x3 slab, singel layer, centre of tabel",
        one(k.block(2, 3, 1), reg("centre")),
    ),
    _c(
        "typ-07",
        TYP,
        "Make me a wal with 4 cubs in the lenght and 3 in the heigth",
        one(k.wall(4, 3)),
    ),
    _c(
        "typ-08",
        TYP,
        "A colonade of three colums, four cubes high, one cube apart",
        k.in_line(3, T(4), 1),
    ),
    _c(
        "typ-09",
        TYP,
        "can teh robot make a brigde for emma, two towers of 3 with a beam ontop",
        one(GATE(3, pillars=2)),
    ),
    _c("typ-10", TYP, "okay a wall sick cubes long and to high", one(k.wall(6, 2))),
    _c(
        "typ-11",
        TYP,
        "Tower 6 cubse, pos x=0.5 y=0.3 (pls confrim)",
        one(T(6), k.near(0.5, 0.3)),
    ),
    _c("typ-12", TYP, "Please build a pyramide with 3 stages.", one(k.pyramid(3))),
    _c("typ-13", TYP, "put down a slap three by three one layer", one(k.block(3, 3, 1))),
    _c("typ-14", TYP, "A courtyad ring 5x5, one cube hgih, empty insdie", one(RING5)),
    _c("typ-15", TYP, "lets make a castel for emma pleeease", one(k.castle)),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "okay five cubes high a tower um on the left put it",
        one(T(5), reg("left")),
    ),
    _c(
        "wo-02",
        WO,
        "On top of the 2x2 block (2 high): 1 cube. Block first.",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.levels(4, 4, 1)),
    ),
    _c(
        "wo-03",
        WO,
        "Three steps high, a stair, climbing to the left.",
        one(k.staircase(3), k.rises(_L)),
    ),
    _c("wo-04", WO, "nine cubes tall, that's the tower Emma wants", one(T(9))),
    _c(
        "wo-05",
        WO,
        "On the right side from the table make me a row of 5 cubes.",
        one(k.row(5), reg("right")),
    ),
    _c(
        "wo-06",
        WO,
        "In the height of 4 cubes and in the length of 5, a wall please.",
        one(k.wall(5, 4)),
    ),
    _c(
        "wo-07",
        WO,
        "behind the tower of three okay put a wall um four long two high behind it with a bit "
        "of space",
        k.pair(k.wall(4, 2), T(3), k.all_rels(k.on_side(_B), _near)),
    ),
    _c(
        "wo-08",
        WO,
        "3 high, 3 wide, 1 deep - wall. Left side of table.",
        one(k.wall(3, 3), k.runs("y"), reg("left")),
    ),
    _c(
        "wo-09",
        WO,
        "Across two columns of three, a lintel - that's the gate I want.",
        one(GATE(3, pillars=2)),
    ),
    _c(
        "wo-10",
        WO,
        "and then on top a little cube, but first a tower of four, for Emma",
        one(T(5)),
    ),
    _c(
        "wo-11",
        WO,
        "Two cubes between them, two towers with 6 floors make.",
        k.pair(T(6), T(6), k.gap_of(2)),
    ),
    _c(
        "wo-12",
        WO,
        "um the pyramid the three level one you know put it in the back",
        one(k.pyramid(3), reg("back")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "okay so um yeah hang on my gloves are on okay so build a tower of six thanks",
        one(T(6)),
    ),
    _c(
        "fil-02",
        FIL,
        "Hi all,\n\nFollowing up on yesterday's meeting (see below). For the cell trial please "
        "build a 2x4 pad, 1 layer.\n\nBest regards,\nDaniel Ruiz\nProcess Engineering | Plant "
        "2\n\n> On Tue, Anna wrote:\n> can we get a test build?",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "fil-03",
        FIL,
        "So for my studio crit I'm doing this thing about thresholds, right, and I'd love a "
        "simple gate: two columns of four and a lintel on top. That's all.",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "fil-04",
        FIL,
        "okay Emma sweetie watch this, robot, can you build a staircase with three steps, yes, "
        "that one, good",
        one(k.staircase(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Hello, good morning, I hope you are fine. I would like to have a wall of 4 cubes in "
        "length and 2 in height. Thank you very much and have a nice day.",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-06",
        FIL,
        "okay uh yeah so like a row of five cubes I guess um going left to right yeah that's it",
        one(k.row(5), k.runs("y")),
    ),
    _c(
        "fil-07",
        FIL,
        "Re: Re: FW: cell 3\n\nSee attached (no attachment, sorry). Short version: 3x3 slab, 2 "
        "layers.\n\n--\nSent from my phone",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-08",
        FIL,
        "Honestly this is just a massing model, nothing precious - a block 2 by 3, three high, "
        "like a little tower house.",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Emma's been asking all morning, she loves the robot, so let's do two towers of four "
        "next to each other with a space, she'll knock them over after anyway",
        k.pair(T(4), T(4), _near),
    ),
    _c(
        "fil-10",
        FIL,
        "Sorry for my English. I need please one pyramid with 3 levels, it is for a "
        "demonstration for the customer from Spain.",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-11",
        FIL,
        "hey assistant um tell the robot okay a ring of cubes four by four one high over",
        one(RING4),
    ),
    _c(
        "fil-12",
        FIL,
        "FYI - Quality asked for a reference build. Tower, 4 cubes. No rush. Cheers",
        one(T(4)),
    ),
    _c(
        "fil-13",
        FIL,
        "right, shoes off, Emma, sit - robot, a bridge please, towers of two and a beam, thank "
        "you robot!",
        one(GATE(2, pillars=2)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "okay um tower of three in the front right corner",
        one(T(3), reg("front right")),
    ),
    _c(
        "reg-02",
        REG,
        "Place 1x tower, 5 cubes, at X=0.60 / Y=0.40.",
        one(T(5), k.near(0.60, 0.40)),
    ),
    _c(
        "reg-03",
        REG,
        "Make me a tower with 3 floors at x = 0,35 m and y = 0,2 m.",
        one(T(3), k.near(0.35, 0.20)),
    ),
    _c(
        "reg-04",
        REG,
        "Set the pavilion - four legs of two and a roof - at the back of the site.",
        one(k.canopy(4, 2, 2), reg("back")),
    ),
    _c(
        "reg-05",
        REG,
        "let's put Emma's tower of four right in the middle so she can reach it",
        one(T(4), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "In the left back corner, please, a block 2 x 2 x 2.",
        one(k.block(2, 2, 2), reg("back left")),
    ),
    _c(
        "reg-07",
        REG,
        "put a wall uh four long two high along the back edge of the table",
        one(k.wall(4, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "reg-08",
        REG,
        "Layout:\n- Tower 1 (3 cubes): front left\n- Tower 2 (3 cubes): front right\n- Tower 3 "
        "(6 cubes): back centre",
        k.structures(
            k.all_of(T(3), reg("front left")),
            k.all_of(T(3), reg("front right")),
            k.all_of(T(6), reg("back"), k.near(y=0.30, tol=0.05)),
        ),
    ),
    _c(
        "reg-09",
        REG,
        "Place a staircase of three steps against the right-hand side of the table, climbing "
        "toward the middle.",
        one(k.staircase(3), reg("right"), k.rises(_L)),
    ),
    _c(
        "reg-10",
        REG,
        "can the robot make a row of three on Emma's side, she's sitting on the left",
        one(k.row(3), reg("left")),
    ),
    _c(
        "reg-11",
        REG,
        "Please a slab 3 x 3, placed 10 cm from the front border of the working area, in the "
        "middle of the width.",
        one(
            k.block(3, 3, 1),
            k.near(y=0.30),
            k.any_of(k.near(x=0.375, tol=0.02), k.near(x=0.30, tol=0.02)),
        ),
    ),
    _c(
        "reg-12",
        REG,
        "okay so two single cubes one way over on the left and one way over on the right",
        k.structures(k.all_of(T(1), reg("left")), k.all_of(T(1), reg("right"))),
    ),
    _c(
        "reg-13",
        REG,
        "Block 2x2x3 - position: x 0.45, y 0.15 (right side).",
        one(k.block(2, 2, 3), k.near(0.45, 0.15)),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "um just build whatever okay something quick", k.anything),
    _c(
        "open-02",
        OPEN,
        "Need any test structure using at least one beam. Design at your discretion.",
        k.all_of(k.anything, k.layout(_has_beam)),
    ),
    _c(
        "open-03",
        OPEN,
        "Surprise me with a small temple front - columns and something on top, your proportions.",
        k.all_of(k.anything, k.layout(k.arch)),
    ),
    _c("open-04", OPEN, "can the robot build something fun for Emma? she's four", k.anything),
    _c(
        "open-05",
        OPEN,
        "Make me something nice with the cubes, you can decide the form, but not higher than "
        "20 cm.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c("open-06", OPEN, "okay build a tower any height you want", one(T(lo=2, hi=10))),
    _c(
        "open-07",
        OPEN,
        "Pls build a 'typical' demo structure - 3 to 5 separate pieces, any shapes.",
        _pieces(3, 5),
    ),
    _c(
        "open-08",
        OPEN,
        "A little courtyard, whatever size works, just enclosed on all sides.",
        one(k.ring),
    ),
    _c(
        "open-09",
        OPEN,
        "let's do a big castle for Emma, as big as the robot can manage",
        one(k.castle),
    ),
    _c(
        "open-10",
        OPEN,
        "Please build a small house from cubes, how you want.",
        k.all_of(k.anything, one(k.height(lo=2))),
    ),
    _c(
        "open-11",
        OPEN,
        "uh make some kind of stairs I don't care how many steps",
        one(k.staircase()),
    ),
    _c(
        "open-12",
        OPEN,
        "Something with a clear axis of symmetry - a central element with matching pieces "
        "either side. Your call on sizes.",
        k.all_of(k.anything, k.layout(_symmetric)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "okay so um the uh [inaudible] on the thing yeah", k.honest()),
    _c(
        "bad-02",
        BAD,
        "Tower, 12 cubes. (Yes 12 - need to test max height.)",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-03",
        BAD,
        "A column five cubes tall that is also no taller than two cubes.",
        k.honest(one(k.any_of(T(5), T(2)))),
    ),
    _c(
        "bad-04",
        BAD,
        "Emma wants to say something - 'robot robot make a unicorn rainbow, a big big one!'",
        k.honest(k.all_of(k.anything, k.layout(k.arch))),
    ),
    _c("bad-05", BAD, "Bitte baue einen Turm aus fünf Würfeln.", k.honest(one(T(5)))),
    _c(
        "bad-06",
        BAD,
        "Hazme una pared de seis cubos de largo y dos de alto, por favor.",
        k.honest(one(k.wall(6, 2))),
    ),
    _c(
        "bad-07",
        BAD,
        "build a wall um twenty cubes long",
        k.honest(one(k.any_of(k.wall(lo=2, hi=12), k.row(lo=2, hi=12)))),
    ),
    _c("bad-08", BAD, "Re: (no subject)\n\n\n--\nSent from Outlook", k.honest()),
    _c(
        "bad-09",
        BAD,
        "A courtyard ring, 4 by 4 outside, with an open interior of 5 by 5.",
        k.honest(one(k.ring)),
    ),
    _c(
        "bad-10",
        BAD,
        "can the robot make a tower as high as the ceiling for Emma",
        k.honest(one(T(lo=2, hi=10))),
    ),
    _c("bad-11", BAD, "Make me a staircase with 0 steps.", k.honest()),
    _c("bad-12", BAD, "okay cancel that no wait um", k.honest()),
    _c("bad-13", BAD, "Tower 4 cubes @ x=0.95, y=0.30", k.honest(one(T(4)))),
    _c(
        "bad-14",
        BAD,
        "A row with length 1,5 m, please.",
        k.honest(one(k.row(lo=2, hi=12))),
    ),
    _c("bad-15", BAD, "Give me the feeling of Louis Kahn's light, in cubes.", k.honest()),
]
