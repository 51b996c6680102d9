"""A seventeenth held-out set for the language front end (dev17): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev16` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a US technician who thinks in inches and feet ("a 6 inch tower", "two inches apart",
  "about a foot long", "a yard tall"). A cube is 0.05 m ≈ 1.97 in; the predicates accept the
  nearest whole number of cubes: 2 in ≈ 1 cube, 4 in ≈ 2, 6 in ≈ 3, 8 in ≈ 4, 10 in ≈ 5,
  a foot ≈ 6, a foot and a half ≈ 9; an amount halfway between two (5 in ≈ 2.5 cubes)
  accepts both. "N inches apart" accepts the clear gap and, where that is buildable, the
  centre-to-centre reading; a distance from an edge is floor from the edge to the nearest
  part, rounded the same way; a position ("16 inches out") is the footprint centre, ± 3 cm;
* a video-game / puzzle player using game words loosely ("stack 'em", "spawn", "a Tetris
  L-piece", "a Jenga-style tower", "level 1 … level 2", "like in Minecraft", "the map"). A
  Tetris piece is four cubes in one plane, lying flat or standing up where it can stand;
* an operator whose first language is French, Italian, Japanese or Chinese — articles and
  plurals off, adjective after noun ("a wall long 5 and high 2", "tower high of 6", "3 cube",
  "pyramid of 2 floors"), verb last; and three commands wholly in Italian, Japanese or
  Chinese (bad input: a refusal or a noted reading);
* a chat pasted in one message with its revisions ("tower of 4. wait, make it 5. no, …"),
  "same again but …", "undo the last one", "another like that" and ordinals ("the second one
  from the left", "the leftmost", "the third one", "the last row") — the final state counts;
* a quality engineer writing acceptance criteria or the expected result ("Expected result:
  …", "The finished assembly shall consist of …", "Acceptance: …", "Nonconformance if …").

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references and ordinals, distributive
phrases ("on each corner", "one on each side"), comparisons ("twice that", "2 less"),
revisions, removals and unusable input (gibberish, contradictions, sizes past the cell, other
languages).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — both roundings of an inch
size halfway between two cube counts, one merged structure where a tower could be set down
touching another, a Tetris piece flat or upright — and nothing else. Geometry comes only from
`sdi.bench.boxes`, through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30).
"""

from __future__ import annotations

import itertools

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

INCH = 0.0254  # m


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev17-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _partly(side: str) -> k.Rel:
    """A's footprint centre lies to `side` of B's (by 2 cm or more), whatever else differs."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        got = bx.sides(a, b)
        return None if side in got else f"A is {sorted(got) or 'level with B'}, not {side}"

    return rel


def _either_way(*checks: k.Check) -> k.Pred:
    """The structures in a line along x or y, in this order or the reverse."""
    rev = checks[::-1]
    return k.any_of(
        k.in_order("x", *checks),
        k.in_order("x", *rev),
        k.in_order("y", *checks),
        k.in_order("y", *rev),
    )


def _beyond_top(n: int) -> k.Rel:
    """A stands beyond the end B (a staircase) climbs towards, `n` cubes clear (± 1.5 cm)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        up = bx.rises_towards(b)
        if up is None:
            return "B is not a staircase"
        if bx.side_of(a, b) != up:
            return f"A is {bx.side_of(a, b)} of the stairs, which climb towards {up}"
        return k.gap_of(n)(a, b)

    return rel


def _reaches_x(x: float) -> k.Check:
    """Some part reaches back to x ≥ `x` (m) — up against the back edge."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[0] for b in bs)
        return None if hi >= x - bx.TOL else f"back face at x {hi:.3f}, want ≥ {x:.3f}"

    return f


def _max_y(y: float) -> k.Check:
    """Every part lies at y ≤ `y` (m), i.e. that far right of the left edge or more."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[1] for b in bs)
        return None if hi <= y + bx.TOL else f"a part reaches y {hi:.3f}, want ≤ {y:.3f}"

    return f


def _has_beam(bs: k.Boxes) -> k.Reason:
    """At least one part is a beam (three cubes long)."""
    if any(bx.cubes(max(b.size)) == 3 for b in bs):
        return None
    return "no beam"


def _crosshatched(n: int) -> k.Check:
    """A Jenga-style tower: `n` layers on a 3×3 footprint, each layer three beams side by
    side, every layer's beams turned across the layer below."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.all_of(k.block(3, 3, n), k.levels(*[3] * n))(bs)
        if r:
            return r
        runs: list[set[int]] = []
        for z in sorted({round(b.lo[2], 3) for b in bs}):
            layer = [b for b in bs if round(b.lo[2], 3) == z]
            if any(bx.cubes(max(b.size)) != 3 for b in layer):
                return "a layer not made of beams"
            runs.append({0 if b.size[0] > b.size[1] else 1 for b in layer})
        if any(len(r) != 1 for r in runs):
            return "beams of one layer not parallel"
        if any(a == b for a, b in itertools.pairwise(runs)):
            return "a layer not turned across the one below"
        return None

    return f


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
GATE = k.bridge
RING5 = k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5))
RING4 = k.all_of(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4))

# Tetris pieces: four cubes in one plane, flat on the table or standing where they can stand.
I_PIECE = k.any_of(k.row(4), T(4))
O_PIECE = k.any_of(k.block(2, 2, 1), k.wall(2, 2))
L_PIECE = k.all_of(
    k.parts(4),
    k.only_cubes,
    k.any_of(
        k.all_of(k.shape_letter("L"), k.dims(2, 3), k.height(1)),  # flat (J, its mirror, too)
        k.all_of(k.flat, k.profile(3, 1)),  # upright: a column of 3 with a foot
        k.all_of(k.flat, k.profile(2, 1, 1)),  # upright: a row of 3 with one cube on an end
    ),
)
T_PIECE = k.all_of(
    k.parts(4),
    k.only_cubes,
    k.any_of(
        k.all_of(k.shape_letter("T"), k.dims(2, 3), k.height(1)),  # flat
        k.all_of(k.flat, k.profile(1, 2, 1)),  # upright: a row of 3, one on the middle
    ),
)
TETROMINO = k.all_of(k.parts(4), k.only_cubes, k.any_of(k.flat, k.height(1)))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Put a 6 inch stack and a 4 inch stack about two inches apart.",
        k.pair(T(3), T(2), k.gap_of(1)),  # 6 in ≈ 3, 4 in ≈ 2; 2 in clear ≈ 1 cube
    ),
    _c(
        "rel-02",
        REL,
        "spawn two towers of 4 and slap a beam across em like a gate",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "rel-03",
        REL,
        "Please a tower high of 5, and at the left of it a tower more small, of 2, with one "
        "cube of space.",
        k.pair(T(2), T(5), k.gap_of(1, _L)),
    ),
    _c(
        "rel-04",
        REL,
        "tower of 3 in the middle. now a tower of 5 behind it. no wait, in front of it. leave a "
        "cube gap.",
        k.all_of(k.pair(T(5), T(3), k.gap_of(1, _F)), k.some(T(3), reg("centre"))),
    ),
    _c(
        "rel-05",
        REL,
        "Acceptance criterion: two towers of 3 cubes each with 10 cm of clear space between them.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "rel-06",
        REL,
        "Set down a 3 by 3 pad 2 inches thick and stand an 8 inch tower in the middle of it.",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1, 1)),
    ),
    _c(
        "rel-07",
        REL,
        "build a 3x3 platform like in minecraft and put a 2 high pillar on every corner",
        one(k.base(3, 3), k.corner_columns(2), k.levels(9, 4, 4)),
    ),
    _c(
        "rel-08",
        REL,
        "Wall, long 6, high 2. In front of wall, one tower of 3 cube. Not touch.",
        k.pair(T(3), k.wall(6, 2), k.all_rels(k.on_side(_F), _near)),
    ),
    _c(
        "rel-09",
        REL,
        "Build two towers of 4 a cube apart. Now the second one from the left, make it 6.",
        k.pair(T(6), T(4), k.gap_of(1, _R)),  # of two, the second from the left is the right one
    ),
    _c(
        "rel-10",
        REL,
        "The finished assembly shall consist of a ring one cube high, 5 x 5 outside, with a "
        "single 3-high tower standing at its center, not touching the ring.",
        k.pair(RING5, T(3), k.centred_in()),
    ),
    _c(
        "rel-11",
        REL,
        "two walls a foot long and 4 inches high, running front to back, parallel, with a 4 "
        "inch aisle between them",
        k.pair(  # 12 in ≈ 6 cubes, 4 in ≈ 2; the aisle is clear floor
            k.all_of(k.wall(6, 2), k.runs("x")),
            k.all_of(k.wall(6, 2), k.runs("x")),
            k.parallel_gap(2),
        ),
    ),
    _c(
        "rel-12",
        REL,
        "drop an O-piece and an I-piece side by side with a little gap",
        k.pair(O_PIECE, I_PIECE, k.within(0.15)),
    ),
    _c(
        "rel-13",
        REL,
        "Make a bridge: two pillar high 3, over them one beam. At the right of the bridge, a "
        "pyramid of 2 floors.",
        k.pair(k.pyramid(2), GATE(3, pillars=2), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "rel-14",
        REL,
        "Put three towers of 2 in a row left to right, a cube between each. The leftmost one "
        "gets 3 more cubes.",
        k.in_order("y", T(5), T(2), T(2), gaps=(1,)),
    ),
    _c(
        "rel-15",
        REL,
        "Expected result: a staircase of 4 steps rising toward the back, with a 4-high tower "
        "standing 5 cm behind its top step.",
        k.pair(T(4), k.all_of(k.staircase(4), k.rises(_B)), _beyond_top(1)),
    ),
    _c(
        "rel-16",
        REL,
        "Build a castle and stick a 4 inch tower out front of it, about 2 inches off the wall.",
        k.pair(T(2), k.castle, k.gap_of(1, _F)),
    ),
    _c(
        "rel-17",
        REL,
        "build a lil house: four 3-high pillars at the corners and a roof on top",
        one(k.canopy(4, 3, 3)),
    ),
    _c(
        "rel-18",
        REL,
        "Two tower, each 4 cube. Between them put one small wall long 3 high 2. All touch "
        "together.",
        one(k.flat, k.profile(4, 2, 2, 2, 4)),
    ),
    _c(
        "rel-19",
        REL,
        "make a row of 5 along the front, left to right. then a tower of 3 on the middle cube. "
        "actually, on the last cube on the right.",
        one(k.plan_heights("11114"), k.runs("y"), k.upper_side(_R, 1), reg("front")),
    ),
    _c(
        "rel-20",
        REL,
        "Acceptance: three towers of heights 2, 4 and 6 in a straight line front to back, "
        "tallest at the back, 5 cm clear spacing.",
        k.in_order("x", T(2), T(4), T(6), gaps=(1,)),
    ),
    _c(
        "rel-21",
        REL,
        "A 10 inch square pen, one block high, with a 2-block stack in the dead center.",
        k.pair(RING5, T(2), k.centred_in()),  # 10 in ≈ 5 cubes outside
    ),
    _c(
        "rel-22",
        REL,
        "build a 5-stack in the middle and surround it with four 2-stacks, one on each side, a "
        "block of space each",
        k.on_every_side(k.all_of(T(5), reg("centre")), T(2), 1),
    ),
    _c(
        "rel-23",
        REL,
        "The assembly shall consist of two 3-high towers with a 2 x 2 block, 2 high, centred "
        "between them; all three items free-standing.",
        k.between_(k.block(2, 2, 2), T(3)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "build a tower of 4. hmm wait make it 5. and put it on the left side. no sorry, the "
        "right side.",
        one(T(5), reg("right")),
    ),
    _c(
        "seq-02",
        SEQ,
        "Row of 4 going left to right. Then a tower of 3 next to it. Undo the last one.",
        one(k.row(4), k.runs("y")),
    ),
    _c(
        "seq-03",
        SEQ,
        "Make a tower of 3 at the back. Same again but at the front.",
        k.structures(k.all_of(T(3), reg("back")), k.all_of(T(3), reg("front"))),
    ),
    _c(
        "seq-04",
        SEQ,
        "A wall 4 long, 2 high. And another like that, behind it, with a cube gap.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.gap_of(1, _B)),
    ),
    _c(
        "seq-05",
        SEQ,
        "level 1: 4x4 floor. level 2: 3x3 on top. level 3: 2x2. level 4: 1 block. gg",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "seq-06",
        SEQ,
        "Stack it up to 10 inches, then pull the top 2 inches off.",
        one(T(4)),  # 10 in ≈ 5 cubes, less 2 in ≈ 1
    ),
    _c(
        "seq-07",
        SEQ,
        "First you make one line of 5 cube on the table. After, on this line, one other line of "
        "3 cube, in the middle. At the end one cube on the top of all.",
        one(k.pyramid_counts(5, 3, 1), k.flat, k.centred()),
    ),
    _c(
        "seq-08",
        SEQ,
        "Step 1: place a 2 x 3 base, one layer. Step 2: add a second identical layer. Expected "
        "result: a 2 x 3 x 2 block.",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "tower of 6 please. hmm too tall, take off 2. actually take off one more.",
        one(T(3)),
    ),
    _c(
        "seq-10",
        SEQ,
        "three towers of 3 in a line left to right, some gap. remove the middle one. and the "
        "first one, make it 5.",
        k.pair(T(5), T(3), k.on_side(_L)),
    ),
    _c(
        "seq-11",
        SEQ,
        "spawn a 2x2 block 3 high. then break the top layer lol",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Start with a foot-long row running front to back. Then put a second row on top, same "
        "length.",
        one(k.wall(6, 2), k.runs("x")),
    ),
    _c(
        "seq-13",
        SEQ,
        "First, tower 4 cube. Next, right side of it, same tower, space one cube. Last, one "
        "beam on both.",
        one(GATE(4, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Procedure: (1) build a 3-step staircase rising to the left; (2) add a fourth step at "
        "the high end. Expected result: 4 steps rising to the left.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Put a 2x2 slab, one layer, front left. Same again but back right, and 2 layers.",
        k.structures(
            k.all_of(k.block(2, 2, 1), reg("front left")),
            k.all_of(k.block(2, 2, 2), reg("back right")),
        ),
    ),
    _c(
        "seq-16",
        SEQ,
        "Pyramid of 3 levels in the middle. Then a tower of 4 left of it. Then a wall behind "
        "them. Undo the last one.",
        k.any_of(
            k.all_of(
                k.pair(T(4), k.pyramid(3), k.all_rels(k.on_side(_L), _near)),
                k.some(k.pyramid(3), reg("centre")),
            ),
            one(k.with_column(4, k.pyramid(3))),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "build stairs like the end of a mario level, 5 steps, then put a flagpole (a 6-stack) "
        "1 block past the top",
        k.pair(T(6), k.staircase(5), _beyond_top(1)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Lay a 6 by 6 inch pad, then build it up to 4 inches tall.",
        one(k.block(3, 3, 2)),  # 6 in ≈ 3 cubes, 4 in ≈ 2 layers
    ),
    _c(
        "seq-19",
        SEQ,
        "Make a wall long 5 and high 3. Then take away the cube in the middle of the top.",
        one(k.flat, k.profile(3, 3, 2, 3, 3)),
    ),
    _c(
        "seq-20",
        SEQ,
        "tower of 2 on the right. another like that on the left. and another like that in the "
        "middle. now put the middle one on top of the right one.",
        k.pair(T(4), T(2), k.on_side(_R)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Test sequence: build two 3-high towers 5 cm apart, bridge them with one beam, then "
        "add one cube on top of the beam at mid-span. Expected: 8 parts total.",
        one(GATE(3, pillars=2), k.leg_gap(1), k.parts(8), k.height(5), k.top_centred()),
    ),
    _c(
        "seq-22",
        SEQ,
        "Make 4 towers of 2 in a line, front to back. The second one, make it 4. No, the third "
        "one. And remove the last one.",
        k.in_order("x", T(2), T(2), T(4)),
    ),
    _c(
        "seq-23",
        SEQ,
        "Grid of 4 rows, 3 cubes per row, one layer. Then remove the last row.",
        one(k.block(3, 3, 1)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "stack 'em 7 high", one(T(7))),
    _c("num-02", NUM, "I want 3 tower of 3 cube.", k.each(3, T(3))),
    _c(
        "num-03",
        NUM,
        "Two towers, one 3 high and the other one twice that.",
        k.structures(T(3), T(6)),
    ),
    _c(
        "num-04",
        NUM,
        "The assembly shall contain exactly twelve cubes arranged as a single 3 x 4 layer.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-05",
        NUM,
        "build 2 towers: player 1 tower is 5, player 2 tower is 2 less",
        k.structures(T(5), T(3)),
    ),
    _c("num-06", NUM, "tower of 8. too much, half of that.", one(T(4))),
    _c("num-07", NUM, "Make a staircase of five marches.", one(k.staircase(5))),
    _c(
        "num-08",
        NUM,
        "Acceptance: four towers of heights 1, 2, 3 and 4 (in cubes), free-standing, in any order.",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    _c("num-09", NUM, "make a tower x3, each one 4 blocks", k.each(3, T(4))),
    _c(
        "num-10",
        NUM,
        "Three stacks, each one 4 inches high.",
        k.each(3, T(2)),  # 4 in ≈ 2 cubes
    ),
    _c(
        "num-11",
        NUM,
        "row of 7. no make it 3 less. and another row like that next to it, touching.",
        one(k.block(2, 4, 1)),
    ),
    _c("num-12", NUM, "Please build tower, number of cube is ten.", one(T(10))),
    _c(
        "num-13",
        NUM,
        "Quantity check: the pyramid shall have 3 levels with 9, 4 and 1 cubes.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-14",
        NUM,
        "a 1-2-3 combo: three towers in a row going 1, 2, 3 high",
        k.any_of(_either_way(T(1), T(2), T(3)), one(k.flat, k.profile(1, 2, 3))),
    ),
    _c(
        "num-15",
        NUM,
        "put 5 towers of 1 in a row. actually just 4. a cube between each.",
        k.in_line(4, T(1), 1),
    ),
    _c(
        "num-16",
        NUM,
        "One tower of six cubes and one of four, the small one at right.",
        k.pair(T(4), T(6), k.on_side(_R)),
    ),
    _c(
        "num-17",
        NUM,
        "The deliverable is 2 walls of 5 x 2 cubes and 1 tower of 5; total part count 25.",
        k.structures(k.wall(5, 2), k.wall(5, 2), T(5)),
    ),
    _c("num-18", NUM, "stack half a dozen of the 2-inch blocks", one(T(6))),
    _c("num-19", NUM, "stand two I-pieces on end, one on top of the other", one(T(8))),
    _c(
        "num-20",
        NUM,
        "first tower 2, second tower 2 more than the first, third tower 2 more than the second. "
        "in a line.",
        _either_way(T(2), T(4), T(6)),
    ),
    _c(
        "num-21",
        NUM,
        "Tower, 5 cube. Also tower, 5 cube. Total 2 tower, same height.",
        k.each(2, T(5)),
    ),
    _c(
        "num-22",
        NUM,
        "a Jenga-style tower: 4 layers of 3 beams, each layer turned across the one below",
        one(_crosshatched(4)),
    ),
    _c(
        "num-23",
        NUM,
        "Build two towers of 3, a cube apart. Put two more cubes on the first tower.",
        k.pair(T(5), T(3), k.gap_of(1)),  # "first" left open: either may be the taller
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "A tower about a foot and a half tall.",
        one(T(9)),  # 18 in = 45.7 cm ≈ 9 cubes
    ),
    _c(
        "dim-02",
        DIM,
        "a wall about a foot long and 4 inches high",
        one(k.wall(6, 2)),  # 12 in ≈ 6.1 cubes, 4 in ≈ 2
    ),
    _c("dim-03", DIM, "a 4 by 8 inch pad, one block thick", one(k.block(2, 4, 1))),
    _c("dim-04", DIM, "Build me a 6 inch cube out of the blocks.", one(k.block(3, 3, 3))),
    _c(
        "dim-05",
        DIM,
        "a tower around 5 inches",
        one(T(lo=2, hi=3)),  # 5 in = 12.7 cm = 2.5 cubes: either rounding
    ),
    _c(
        "dim-06",
        DIM,
        "make a 4x4 platform like in minecraft, one block thick",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "dim-07",
        DIM,
        "gimme a chonky wall, 2 blocks thick, 5 long, 3 tall",
        one(k.block(2, 5, 3)),
    ),
    _c("dim-08", DIM, "Make one wall long 7 and high 2.", one(k.wall(7, 2))),
    _c("dim-09", DIM, "I need a tower high of 6 cubes, please.", one(T(6))),
    _c("dim-10", DIM, "A block large 3, long 4, high 2.", one(k.block(3, 4, 2))),
    _c(
        "dim-11",
        DIM,
        "The finished assembly shall measure 150 mm x 150 mm in plan and 100 mm in height, solid.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "dim-12",
        DIM,
        "Acceptance: wall length 250 mm, height 150 mm, thickness one cube, oriented left to "
        "right.",
        one(k.wall(5, 3), k.runs("y")),
    ),
    _c("dim-13", DIM, "build a tetris L-piece out of cubes", one(L_PIECE)),
    _c(
        "dim-14",
        DIM,
        "A staircase, 4 steps, each step 2 inches tall and 4 inches deep.",
        one(k.profile(1, 1, 2, 2, 3, 3, 4, 4)),  # rise ≈ 1 cube, tread ≈ 2 cubes
    ),
    _c(
        "dim-15",
        DIM,
        "Expected result: a ring of cubes 300 x 200 mm outside, 1 cube high.",
        one(k.ring_of(high=1, inner=(4, 2)), k.dims(4, 6)),
    ),
    _c(
        "dim-16",
        DIM,
        "make a row a foot and a half long running left to right",
        one(k.row(9), k.runs("y")),  # 18 in ≈ 9 cubes
    ),
    _c(
        "dim-17",
        DIM,
        "build a floor 5 wide and 2 deep, 1 block thick, like a minecraft bridge deck",
        one(k.block_xy(2, 5, 1)),
    ),
    _c(
        "dim-18",
        DIM,
        "A pyramid with base of 4 on 4.",
        one(k.pyramid(), k.base(4, 4)),
    ),
    _c(
        "dim-19",
        DIM,
        "Put up a gate with 6 inch legs and the beam across the top.",
        one(GATE(3, pillars=2)),
    ),
    _c(
        "dim-20",
        DIM,
        "The enclosure shall be 250 mm square outside and 100 mm high.",
        one(k.ring_of(high=2, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c("dim-21", DIM, "Table with 4 leg, leg high 2 cube.", one(k.canopy(4, 2, 2))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A tower no taller than 7 inches, but as tall as that allows.",
        one(T(3)),  # 7 in = 17.8 cm: 3 cubes (15 cm) fit, 4 (20 cm) do not
    ),
    _c(
        "neg-02",
        NEG,
        "make a 3x3 platform but leave out the middle block, no block there",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "neg-03",
        NEG,
        "Two tower of 4, they must not touch, the distance is not more of 10 cm.",
        k.pair(T(4), T(4), k.within(0.115)),
    ),
    _c(
        "neg-04",
        NEG,
        "tower of 3 on the left. no, not the left. the back.",
        one(T(3), reg("back"), k.not_(reg("left"), "still on the left")),
    ),
    _c(
        "neg-05",
        NEG,
        "Reject if any part is within 10 cm of the front edge. Required: a 2 x 2 block, 3 high.",
        one(k.block(2, 2, 3), k.min_x(0.30)),
    ),
    _c(
        "neg-06",
        NEG,
        "a row of blocks a foot long, not going front to back, side to side",
        one(k.row(6), k.runs("y")),
    ),
    _c(
        "neg-07",
        NEG,
        "build stairs, 4 steps, but dont make them go towards me, make them go up to the right",
        one(k.staircase(4), k.rises(_R)),
    ),
    _c(
        "neg-08",
        NEG,
        "Pyramid 3 level. Not on center, please on back side.",
        one(k.pyramid(3), reg("back"), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-09",
        NEG,
        "The assembly shall not exceed 2 layers: a 3 x 5 slab built to the maximum allowed height.",
        one(k.block(3, 5, 2)),
    ),
    _c(
        "neg-10",
        NEG,
        "put a beam across two 3-stacks. no wait, don't use a beam, just leave the two stacks a "
        "cube apart.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "neg-11",
        NEG,
        "Tower of 4, and keep it at least 6 inches away from the left edge.",
        one(T(4), _max_y(0.55 - 3 * bx.CUBE)),  # 6 in ≈ 3 cubes (15 cm) of floor or more
    ),
    _c(
        "neg-12",
        NEG,
        "make a 5 block tower but don't put it on the spawn point (the middle)",
        one(T(5), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-13",
        NEG,
        "Make a wall long 4 high 2, without the cubes of the corners at the top.",
        one(k.flat, k.profile(1, 2, 2, 1)),
    ),
    _c(
        "neg-14",
        NEG,
        "Nonconformance if the two towers touch. Build: towers of 5 and 2, spaced 50 mm clear.",
        k.pair(T(5), T(2), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "make a 6 inhc tower", one(T(3))),
    _c("typo-02", TYP, "stakc em 6 hihg", one(T(6))),
    _c("typo-03", TYP, "I want one pyramide of 3 levels.", one(k.pyramid(3))),
    _c("typo-04", TYP, "a wal long 5 and hihg 2", one(k.wall(5, 2))),
    _c(
        "typo-05",
        TYP,
        "Acceptence criteria: one towr, heigth 4 cubes, locatd in the back rigth quadrant.",
        one(T(4), reg("back right")),
    ),
    _c("typo-06", TYP, "tower of 4. wiat, make it 6. no sory, 5", one(T(5))),
    _c("typo-07", TYP, "a 10 inch by 10 inch sqaure pen, one blcok high", one(RING5)),
    _c("typo-08", TYP, "build a brigde with 2 piilars of 4 blocs", one(GATE(4, pillars=2))),
    _c("typo-09", TYP, "Please tower of cubes five, in the left sied.", one(T(5), reg("left"))),
    _c(
        "typo-10",
        TYP,
        "Expcted result: a 3-stpe staircase rising to the rigth.",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "typo-11",
        TYP,
        "row of 4 left to rigth. thn anothr one on top. undo that",
        one(k.row(4), k.runs("y")),
    ),
    _c(
        "typo-12",
        TYP,
        "put two 8 incg towers 4 inchs apart",
        k.pair(T(4), T(4), k.gaps(1, 2)),  # 4 in clear ≈ 2 cubes, or centre to centre ≈ 1 clear
    ),
    _c("typo-13", TYP, "make me a tetirs T-peice", one(T_PIECE)),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Cubes 4, tower, on the right side, please make.", one(T(4), reg("right"))),
    _c("wo-02", WO, "Make for me a wall long of 6 and high of 3.", one(k.wall(6, 3))),
    _c("wo-03", WO, "8 inches high, that tower, and near the back.", one(T(4), reg("back"))),
    _c(
        "wo-04",
        WO,
        "on top of a 2x2 floor: a 3 stack. floor goes down first obv",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    _c(
        "wo-05",
        WO,
        "Of the two towers, the one on the left shall be 6 cubes high and the one on the right "
        "2; spacing 10 cm clear.",
        k.pair(T(6), T(2), k.gap_of(2, _L)),
    ),
    _c(
        "wo-06",
        WO,
        "on the left, a tower. 3 high. no, 4 high. then on the right, same.",
        k.structures(k.all_of(T(4), reg("left")), k.all_of(T(4), reg("right"))),
    ),
    _c(
        "wo-07",
        WO,
        "Front of robot, one row, five cube, from left to right.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-08",
        WO,
        "Two inches between them, the two stacks, each 6 inches.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "wo-09",
        WO,
        "3 levels high, a pyramid, spawn it in the back left",
        one(k.pyramid(3), reg("back left")),
    ),
    _c(
        "wo-10",
        WO,
        "In the center of the work area, 5 cubes high: one tower. That is the expected result.",
        one(T(5), reg("centre")),
    ),
    _c(
        "wo-11",
        WO,
        "Of stairs, 4 steps, going up toward the left, make one.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "wo-12",
        WO,
        "the bigger one behind. two towers, 5 and 2. a cube gap.",
        k.pair(T(5), T(2), k.gap_of(1, _B)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Alrighty, so I'm more of a tape-measure guy than a metric guy, bear with me. I need a "
        "tower about 8 inches tall. That's all, thanks bud.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok so im speedrunning this tutorial lmao, just spawn a 3x3 platform, 1 block thick, go "
        "go go",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "fil-03",
        FIL,
        "Good morning, excuse me for my english, it is not very good. I would like, if "
        "possible, a pyramid of 3 levels. Thank you very much and good work.",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-04",
        FIL,
        "hey! so earlier Mike asked for something, never mind that. here's what I need: a wall "
        "5 long, 2 high. thanks!",
        one(k.wall(5, 2)),
    ),
    _c(
        "fil-05",
        FIL,
        "Document QP-17 rev B. Scope: robot cell build verification. Expected result: one "
        "6-high tower. Sign-off: QE.",
        one(T(6)),
    ),
    _c(
        "fil-06",
        FIL,
        "Okay, the boss wants this by lunch so no pressure, ha. Two stacks, 6 inches each, about "
        "4 inches apart, side by side. Appreciate ya.",
        k.pair(T(3), T(3), k.gaps(1, 2)),
    ),
    _c(
        "fil-07",
        FIL,
        "bro this is like the best sandbox ever. ok ok focus. build a staircase 5 steps. thx",
        one(k.staircase(5)),
    ),
    _c(
        "fil-08",
        FIL,
        "Hello, I am new in the laboratory, I come from Lyon. My chief tell me to ask you a "
        "bridge with two pillar of 2 cube. Thanks.",
        one(GATE(2, pillars=2)),
    ),
    _c(
        "fil-09",
        FIL,
        "[10:02] Ana: morning. [10:03] Ana: can you build a 2x4 slab, one layer? [10:03] Ana: "
        "cheers",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "fil-10",
        FIL,
        "Per the quality plan, and for traceability purposes, the expected result of this test "
        "is recorded as: a ring 4 x 4 outside, 1 cube high, no other parts.",
        one(RING4),
    ),
    _c(
        "fil-11",
        FIL,
        "Heads up, got grease on my hands so typing slow. tower 10 inches. done.",
        one(T(5)),
    ),
    _c(
        "fil-12",
        FIL,
        "Sorry for trouble. Thank you always. Please, tower of 7 cube. Thank you.",
        one(T(7)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Put a 4 inch tower about 16 inches out from the robot.",
        one(T(2), k.near(x=16 * INCH)),  # 16 in = 0.406 m
    ),
    _c(
        "reg-02",
        REG,
        "Tower of 6 inches, 8 inches left of the middle line.",
        one(T(3), k.near(y=0.30 + 8 * INCH)),  # y = 0.503
    ),
    _c(
        "reg-03",
        REG,
        "spawn a 4-stack in the top-right corner of the map (the back right)",
        one(T(4), reg("back right")),
    ),
    _c(
        "reg-04",
        REG,
        "Put a staircase of 3 in the corner at the back on the left.",
        one(k.staircase(3), reg("back left")),
    ),
    _c(
        "reg-05",
        REG,
        "Expected result: a 2 x 3 slab, one layer, located in the front-left quadrant of the "
        "workspace.",
        one(k.block(2, 3, 1), reg("front left")),
    ),
    _c(
        "reg-06",
        REG,
        "tower of 5 at the front. no. back. no, front was right. front it is.",
        one(T(5), reg("front")),
    ),
    _c(
        "reg-07",
        REG,
        "A row 8 inches long, sitting right up at the back edge, within an inch of it.",
        one(k.row(4), _reaches_x(0.80 - INCH)),
    ),
    _c(
        "reg-08",
        REG,
        "put a pyramid 2 levels in the middle of the map",
        one(k.pyramid(2), reg("centre")),
    ),
    _c("reg-09", REG, "Right side, near robot, put tower 3 cube.", one(T(3), reg("front right"))),
    _c(
        "reg-10",
        REG,
        "The tower (4 high) shall be located with its centre at x = 0.55 m, y = 0.20 m, "
        "tolerance ±10 mm.",
        one(T(4), k.near(0.55, 0.20, 0.011)),
    ),
    _c(
        "reg-11",
        REG,
        "Two towers of 3, one left and one right. Move the leftmost to the back.",
        k.all_of(
            k.structures(k.all_of(T(3), reg("back")), k.all_of(T(3), reg("right"))),
            k.pair(T(3), T(3), _partly(_B)),
        ),
    ),
    _c(
        "reg-12",
        REG,
        "Put a 3-high stack at x = 18 in, y = 12 in.",
        one(T(3), k.near(18 * INCH, 12 * INCH)),  # (0.457, 0.305) m
    ),
    _c(
        "reg-13",
        REG,
        "build a wall 5 long, 2 high, on the left edge of the map, running front to back",
        one(k.wall(5, 2), k.runs("x"), k.centre_y_min(0.45)),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "sandbox mode: build whatever u want", k.anything),
    _c(
        "open-02",
        OPEN,
        "Something no taller than 6 inches, your call on the rest.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-03",
        OPEN,
        "Make something beautiful, you choose, but with not more of 20 cubes.",
        k.all_of(k.anything, k.layout(k.parts(hi=20))),
    ),
    _c(
        "open-04",
        OPEN,
        "Expected result: any single free-standing structure containing at least one beam. No "
        "further requirements.",
        k.all_of(k.anything, one(_has_beam)),
    ),
    _c(
        "open-05",
        OPEN,
        "build something. hm, actually, something with a bridge in it. whatever size.",
        k.all_of(k.anything, k.layout(k.arch)),
    ),
    _c("open-06", OPEN, "make a tetris piece, any one", one(TETROMINO)),
    _c(
        "open-07",
        OPEN,
        "Build a few towers, any heights, but none over a foot.",
        k.few(2, 5, T(lo=1, hi=6)),
    ),
    _c("open-08", OPEN, "Make any tower you want, the height is free.", one(T(lo=2, hi=10))),
    _c(
        "open-09",
        OPEN,
        "Acceptance criteria TBD by operator; for now any structure 3 cubes high or less, "
        "located in the back half.",
        k.all_of(k.anything, k.layout(k.all_of(k.low(3), reg("back")))),
    ),
    _c(
        "open-10",
        OPEN,
        "make me a thing. no, two things. small ones.",
        k.all_of(k.anything, k.each(2, k.low(4), k.long(hi=5))),
    ),
    _c("open-11", OPEN, "build a boss arena, like a walled area, u pick the size", one(k.ring)),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "gg ez no re", k.honest()),
    _c("bad-02", BAD, "A tower a yard tall.", k.honest(one(T(lo=1, hi=10)))),  # 36 in ≈ 18
    _c(
        "bad-03",
        BAD,
        "a 2 foot by 2 foot slab, one layer",  # ≈ 12 × 12 cubes; the cell is 12 × 10
        k.honest(one(k.height(1))),
    ),
    _c("bad-04", BAD, "Costruisci una torre di cinque cubi, per favore.", k.honest(one(T(5)))),
    _c("bad-05", BAD, "立方体を三つ積んでタワーを作ってください。", k.honest(one(T(3)))),
    _c("bad-06", BAD, "请在左边搭一个四块高的塔。", k.honest(one(T(4), reg("left")))),
    _c("bad-07", BAD, "undo the last one", k.honest()),
    _c("bad-08", BAD, "and another like that, but bigger", k.honest(k.anything)),
    _c(
        "bad-09",
        BAD,
        "Expected result: a single tower that is both 3 and 5 cubes high.",
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c(
        "bad-10",
        BAD,
        "a 6 inch tower, 5 blocks tall",  # 6 in ≈ 3 cubes, not 5
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c("bad-11", BAD, "spawn a creeper", k.honest(k.anything)),
    _c(
        "bad-12",
        BAD,
        "The assembly shall be a tower of 600 mm height.",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-13",
        BAD,
        "tower of 3 on the left. and on the right. no, only on the left. but not on the left.",
        k.honest(one(T(3))),
    ),
    _c(
        "bad-14",
        BAD,
        "stack a dozen of the 2 inch blocks straight up",  # 12 high, past the 10-level limit
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-15", BAD, "ctrl+z ctrl+z ctrl+z", k.honest()),
    _c("bad-16", BAD, "Fai un muro lungo sei e alto due.", k.honest(one(k.wall(6, 2)))),
    _c(
        "bad-17",
        BAD,
        "Expected result: a ring whose inside is larger than its outside.",
        k.honest(one(k.ring)),
    ),
]
