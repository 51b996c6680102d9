"""A thirty-first held-out set for the language front end (dev31): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev29` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is deliberately mainstream: about
80 % of the commands are what a person at a robot cell would really type — one or two
structures with a size, a place, one relation or a two-step sequence, in plain, varied
English (build / make / put / place / stack / set up / lay / give me / I need / could you /
we'd like; the place first or the size last; sizes as words, digits, "2 by 4", "3x3", cm,
mm and metres; articles dropped now and then; casual punctuation) — and they come from five
kinds of people, none of them used by an earlier set:

* an operator who stands ACROSS THE TABLE from the robot, facing it, and describes places
  from where they stand. Their left is the robot's right (-y), their right the robot's left
  (+y); "nearest me", "my side", "my end", "in front of it as I see it" (between me and it)
  are the robot's back (+x); "the far side from me", "beyond it from me", "the robot's side"
  are the robot's front (-x); "climbing towards me" climbs to +x, "away from me" to -x. The
  speaker says where they stand in every such command ("from where I'm standing, across the
  table", "I'm opposite the robot", "the visitor side"), and a viewpoint said once holds for
  the whole message. When no viewpoint is said, or the command says "the robot's left", the
  words are read in the robot's frame, as in every other set;
* someone who counts their cubes and wants them used: "I've got 9 cubes, make a …", "use all
  12 cubes to …". "Use them all" / "use every one" / "don't leave any over" fixes the number
  of cubes in the layout exactly (cubes only, no beams); "I've got N" alone with a shape that
  fixes the rest ("a square slab", "a staircase") fixes the size through the count; a count
  the shape cannot use (7 cubes for a 2 × 2 block) or more cubes than the cell holds is bad
  input;
* a person who corrects themselves in mid-sentence: "a tower of five — sorry, four —", "on
  the left, no, right", "I mean", "wait", "um". The last word wins; "no, forget it, don't
  build anything" cancels the request (refusal only), and a correction broken off before the
  new figure ("sorry, I mean —") is bad input;
* a short, plain e-mail from a customer to the cell's inbox: greeting, one request, sign-off
  ("Hi team, … Thanks, Greta"; "Dear …, … Kind regards"). Greetings, names, order numbers,
  phone extensions and head-counts are filler, never a size; a message that asks for no build
  (buying cubes) admits only the refusal;
* a student describing a build for a lab report, in the future or the past tense ("The
  structure will consist of …", "We will need …", "A cube was placed …", "The procedure was:
  …"). What is described is what is to be built; lab numbers, dates, section numbers and
  group sizes are filler.

About 80 % ordinary and 20 % harder: three structures, references ("the one on my left", "the
bigger one", "the first tower", "it"), distributive phrases ("a cube on each of the two back
corners", "a tower of two on each end", "each a cube apart"), comparisons ("twice its
height", "half as tall"), removals ("take away the one on my left", "take the top cube off"),
corrections in the same message and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) through the shared checks and accepts every reasonable reading of vague
wording, and nothing else. Conventions (mostly dev27's):

* "next to", "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by column heights);
  "right next to it" is at most 10 cm clear, or touching; "touching" is one structure; "not
  touching", "a gap", "apart", "spaced" mean separate structures;
* "in front of", "behind", "to the left / right of" (in whichever frame applies) is the
  dominant direction between footprint centres (back = +x, front = -x, left = +y, right =
  -y), any distance when none is said; a tower "to the left of", "in front of" or "behind" a
  wall, row or block may also stand against it as one structure, the tower's column then lying
  beyond the rest's face on that side; "directly" in front / behind also puts the tower's
  centre within the other's width;
* "N cubes apart" / "a gap of N cubes" / "a cube's gap" / "N cm apart" is the clear gap
  (± 1.5 cm); a bare "10 cm apart" also accepts the centre-to-centre reading (one cube clear);
* "between" is three separate structures in one line (the shared `line`) when gaps are
  given; "in a row / in a line, a cube apart" is the shared `in_line`;
* a bridge's top is a beam (the shared `bridge`, overall height one more than the posts)
  where the command names a beam, and a beam or a bar of cubes where it does not; "just cubes
  across the top" is a bar of cubes only; a table is four separate legs under one connected
  top of beams or of cubes; "no beams" is cubes only;
* a ring's stated size is its outside; "in the middle of" a ring is inside its empty interior
  with the centres within 3 cm; a tower "inside" a ring is anywhere in the interior, clear of
  the ring or set against its inner wall;
* a tower "on top of" / "in the middle of" a slab stands on it, centred within 3 cm when the
  middle is named; "a tower of two on each end" of a row stands on the end cubes (the end
  columns three high), or makes the end columns two high;
* a staircase's width is free unless given (or fixed by a cube count), and so is the way it
  climbs unless said; a pyramid's step is free unless the levels or the height fix it; "a
  pyramid with a 3x3 base, then take the top cube off" accepts 9-4 and, from a 9-1 pyramid,
  the bare 3 × 3 slab; "the top step removed" accepts the last step gone or its top cube off;
* "something tall" is at least four cubes high; "no taller than 20 cm" is at most four; "no
  more than eight cubes" counts cubes (beams not counted); "something with steps" is a
  staircase or a pyramid; "any kind of enclosure" is a ring;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "exactly in the middle" / "on the centre line" also holds y = 0.30 ± 3 cm; "along the back
  edge" (or "the edge nearest me" for the speaker across the table) is every part at x ≥
  0.60; "along the left edge" a footprint centre at y ≥ 0.45 and running front to back; "the
  back half" every part at x ≥ 0.50; a stated x, y is the footprint centre ± 2 cm.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`): gibberish, another language, contradictions, sizes past the cell,
more cubes than the cell can use, shapes the cell cannot make (a sphere, a cone), materials
it does not stock, a place off the table, a reference to nothing. A message that asks for no
build, or that calls the build off, admits only the refusal (or a failure). Geometry comes
only from `sdi.bench.boxes`, through the shared checks in `language_checks` and the local
checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 × 0.05 × 0.05 m; left = +y, back = +x
(away from the robot at x = 0, y = 0.30); the front is the robot's side (small x).
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

_TALL = 4  # cubes: "something tall"


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev31-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _count(lo: int, hi: int | None = None) -> k.Pred:
    """Between `lo` and `hi` (or exactly `lo`) separate structures, inside the workspace."""
    top = lo if hi is None else hi

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        n = len(comps)
        return None if lo <= n <= top else f"{n} separate structures, want {lo}–{top}"

    return f


def _cubes(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Between `lo` and `hi` cubes among the parts (beams not counted)."""

    def f(bs: k.Boxes) -> k.Reason:
        n = sum(k.only_cubes([b]) is None for b in bs)
        if (lo is not None and n < lo) or (hi is not None and n > hi):
            return f"{n} cubes, want {lo if lo is not None else ''}–{hi if hi is not None else ''}"
        return None

    return f


def _all(n: int) -> k.Pred:
    """The whole layout is exactly `n` cubes and nothing else ("use them all")."""
    return k.layout(k.all_of(k.only_cubes, k.parts(n)))


def _every(check: k.Check) -> k.Pred:
    """Some layout, and every separate structure of it passes `check`."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        for g in comps:
            r = check(g)
            if r:
                return r
        return None

    return f


def _bar_on_posts(
    lo: int | None = None, hi: int | None = None, mouth: int | None = None
) -> k.Check:
    """Two separate posts lo–hi cubes high (any height when None), `mouth` cubes apart clear
    (± 1.5 cm) when given, and as the topmost level one connected bar resting on both — a beam
    or a row of cubes."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        z = max(round(b.lo[2], 3) for b in bs)
        bar = [b for b in bs if round(b.lo[2], 3) == z]
        below = [b for b in bs if round(b.lo[2], 3) != z]
        legs = bx.components(below) if below else []
        if len(legs) != 2 or len(bx.components(bar)) != 1:
            return "not one bar on two separate posts"
        for g in legs:
            r = k.on_table(g) or k.tower(lo=lo, hi=hi)(g)
            if r:
                return f"post: {r}"
            if not any(bx.rests_on(p, q) for p in bar for q in g):
                return "the bar does not rest on both posts"
        gap = bx.separation(legs[0], legs[1])
        if mouth is not None and abs(gap - mouth * bx.CUBE) > 0.015:
            return f"posts {gap:.3f} m apart, want {mouth} cube(s)"
        return None

    return f


def _beam_bridge(posts: int, mouth: int | None = None) -> k.Check:
    """Two posts `posts` high under a beam (the shared `bridge`), the overall height one more
    than the posts; the posts `mouth` cubes apart clear when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected top that is the topmost level and rests on every leg."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        z = max(round(b.lo[2], 3) for b in bs)
        roof = [b for b in bs if round(b.lo[2], 3) == z]
        below = [b for b in bs if round(b.lo[2], 3) != z]
        found = bx.components(below) if below else []
        if len(found) != legs or len(bx.components(roof)) != 1:
            return f"{len(found)} legs under the top level, want {legs} under one top"
        for g in found:
            r = k.on_table(g) or k.full(g) or k.height(leg_h)(g)
            if r:
                return f"leg: {r}"
            if not any(bx.rests_on(p, q) for p in roof for q in g):
                return "the top does not rest on every leg"
        return None

    return f


def _roofed(legs: int, leg_h: int) -> k.Check:
    """A table on `legs` legs `leg_h` high: the shared `canopy` one layer above the legs, a
    top of cubes, or the cell's beam roof."""
    return k.any_of(
        k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1)),
        _roof_on(legs, leg_h),
        k.beam_roof(legs, leg_h),
    )


def _col_against(h: int, rest: k.Check, side: str, square: bool = False) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table set against the rest,
    which passes `rest`; the column lies beyond the rest's face on `side` (and, with `square`,
    its centre within the rest's extent across that direction)."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col in bx.columns(bs):
            if len(col) != h or k.tower(h)(col) is not None or col[0].lo[2] > bx.TOL:
                continue
            others = [b for b in bs if all(b is not c for c in col)]
            if not others:
                continue
            r = rest(others)
            if r is None:
                (c0, c1), (o0, o1) = bx.bounds(col), bx.bounds(others)
                beyond = {
                    _B: c0[0] >= o1[0] - bx.TOL,
                    _F: c1[0] <= o0[0] + bx.TOL,
                    _L: c0[1] >= o1[1] - bx.TOL,
                    _R: c1[1] <= o0[1] + bx.TOL,
                }[side]
                if not beyond:
                    r = f"the {h}-column is not on the {side} of the rest"
                elif square:
                    cx, cy = bx.centre(col)
                    axis, v = (1, cy) if side in (_F, _B) else (0, cx)
                    if not o0[axis] - bx.TOL <= v <= o1[axis] + bx.TOL:
                        r = "the column is off the end of the rest"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the rest"

    return f


def _square_to(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A is "directly" in front of / behind / beside B: A's footprint centre lies within B's
    extent across the direction from B to A."""
    ax, ay = bx.centre(a)
    (x0, y0, _), (x1, y1, _) = bx.bounds(b)
    if bx.side_of(a, b) in (_F, _B):
        ok = y0 - bx.TOL <= ay <= y1 + bx.TOL
    else:
        ok = x0 - bx.TOL <= ax <= x1 + bx.TOL
    return None if ok else "not square to the other, off its end"


def _opposite_ends(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B stand at opposite ends of the table: one in the left region and the other in
    the right, or one in the front region and the other in the back."""
    for ra, rb in ((_L, _R), (_R, _L), (_F, _B), (_B, _F)):
        if bx.region_problem(a, ra) is None and bx.region_problem(b, rb) is None:
            return None
    return "not at opposite ends of the table"


def _pointed(bs: k.Boxes) -> k.Reason:
    """A pyramid with a single part on top."""
    p = bx.pyramid_levels(bs)
    if p is None:
        return "not a pyramid"
    return None if p[-1] == 1 else f"{p[-1]} parts on top, want 1"


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))


def _rows3(n: int, gap: int) -> k.Pred:
    """Three parallel rows of `n`, side by side, `gap` cubes apart (either way round)."""
    along_y = k.all_of(k.row(n), k.runs("y"))
    along_x = k.all_of(k.row(n), k.runs("x"))
    return k.any_of(
        k.in_order("x", along_y, along_y, along_y, gaps=(gap,)),
        k.in_order("y", along_x, along_x, along_x, gaps=(gap,)),
    )


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "From where I'm standing, across the table from the robot, put a tower of four on my "
        "left and a tower of two on my right.",
        k.pair(T(4), T(2), k.on_side(_R)),
    ),
    _c(
        "rel-02",
        REL,
        "I've got 7 cubes. Make a tower of four with a tower of three beside it, use them all.",
        k.all_of(
            k.any_of(k.pair(T(4), T(3), k.within(0.25)), one(k.cell_heights(4, 3))),
            _all(7),
        ),
    ),
    _c(
        "rel-03",
        REL,
        "Put a pyramid of three levels in the middle and a tower of five behind it — sorry, in "
        "front of it.",
        k.pair(T(5), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_F)),
    ),
    _c(
        "rel-04",
        REL,
        "Hello, could you build us a bridge: two posts of three cubes with a beam across the "
        "top, and a single cube sitting on the middle of the beam? Many thanks, Tom",
        one(k.on_top(T(1), _beam_bridge(3)), k.top_centred(0.03)),
    ),
    _c(
        "rel-05",
        REL,
        "The structure will consist of a ring of cubes, five by five on the outside and one "
        "cube high, with a single cube placed at the centre of the enclosed space.",
        k.pair(_PEN5, T(1), k.centred_in(0.03)),
    ),
    _c(
        "rel-06",
        REL,
        "I'm on the opposite side of the table to the robot. Build a wall of five, two high, "
        "running left to right, and a tower of three on my side of it.",
        k.any_of(
            k.pair(T(3), k.all_of(k.wall(5, 2), k.runs("y")), k.on_side(_B)),
            one(_col_against(3, k.all_of(k.wall(5, 2), k.runs("y")), _B)),
        ),
    ),
    _c(
        "rel-07",
        REL,
        "I've got 10 cubes: a 2 by 2 slab with a tower on top of it that uses up the rest.",
        k.all_of(one(k.on_top(T(6), k.block(2, 2, 1)), k.levels(4, 1, 1, 1, 1, 1, 1)), _all(10)),
    ),
    _c(
        "rel-08",
        REL,
        "two towers of three, a gap of two cubes between them, no, one cube, and a beam across "
        "the top",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "rel-09",
        REL,
        "Dear team, please make a row of six cubes along the front and a second row of six "
        "directly behind it with no gap, so it is two cubes deep. Regards, Anna",
        one(k.block_xy(2, 6, 1), reg("front")),
    ),
    _c(
        "rel-10",
        REL,
        "We need two walls, each four cubes long and three high, standing parallel with a gap "
        "of three cubes between them.",
        k.pair(k.wall(4, 3), k.wall(4, 3), k.parallel_gap(3)),
    ),
    _c(
        "rel-11",
        REL,
        "I'm facing the robot across the table. Tower of five, and a 2x2 block two high to the "
        "left of it — my left.",
        k.any_of(
            k.pair(k.block(2, 2, 2), T(5), k.on_side(_R)),
            one(_col_against(5, k.block(2, 2, 2), _L)),
        ),
    ),
    _c(
        "rel-12",
        REL,
        "Use all 13 cubes: a 3 by 3 slab and a tower of four standing in the middle of it.",
        k.all_of(
            one(k.on_top(T(4), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1, 1)),
            _all(13),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Put a tower of six to the right of the ring — wait, inside the ring. The ring's five by "
        "five, one high.",
        k.any_of(k.around(T(6), _PEN5), one(k.holding(T(6), _PEN5))),
    ),
    _c(
        "rel-14",
        REL,
        "Hi there, we'd like two towers of four cubes joined by a beam on top, placed at the "
        "back of the table. Thanks! Sam",
        one(_beam_bridge(4), reg("back")),
    ),
    _c(
        "rel-15",
        REL,
        "A cube was placed on each end of a row of five cubes, so that the row had a cube "
        "standing at both ends.",
        one(k.profile(2, 1, 1, 1, 2)),
    ),
    _c(
        "rel-16",
        REL,
        "Put a tower of three directly in front of the wall as I see it — I'm standing opposite "
        "the robot — the wall being six long, two high, running left to right.",
        k.any_of(
            k.pair(
                T(3),
                k.all_of(k.wall(6, 2), k.runs("y")),
                k.all_rels(k.on_side(_B), _square_to),
            ),
            one(_col_against(3, k.all_of(k.wall(6, 2), k.runs("y")), _B, square=True)),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Build a 3 by 3 slab, and put a cube on each corner — sorry, just on the two back corners.",
        one(k.plan_heights("212", "111", "111"), k.upper_side(_B, 1)),
    ),
    _c(
        "rel-18",
        REL,
        "Good afternoon, could you please place a 2x2 block, three high, with a tower of five "
        "right next to it on its left side? Best wishes, Jo",
        k.any_of(
            k.pair(T(5), k.block(2, 2, 3), k.all_rels(k.within(0.10), k.on_side(_L))),
            one(_col_against(5, k.block(2, 2, 3), _L)),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "For the experiment, a tower of three cubes will be positioned between two towers of "
        "six, all three in a single line with a spacing of one cube.",
        k.line(T(6), T(3), T(6), gaps=(1,)),
    ),
    _c(
        "rel-20",
        REL,
        "Facing the robot from the other side of the table: a wall four long and two high "
        "running left to right on the robot's side of the table, and a tower of four on the far "
        "side of the wall from me.",
        k.any_of(
            k.pair(
                T(4),
                k.all_of(k.wall(4, 2), k.runs("y"), reg("front")),
                k.on_side(_F),
            ),
            one(_col_against(4, k.all_of(k.wall(4, 2), k.runs("y")), _F), reg("front")),
        ),
    ),
    _c(
        "rel-21",
        REL,
        "Use all 8 cubes — two towers of four, touching each other.",
        k.all_of(one(k.cell_heights(4, 4)), _all(8)),
    ),
    _c(
        "rel-22",
        REL,
        "Place a row of four, and a tower of three on the left of it, I mean the right.",
        k.any_of(
            k.pair(T(3), k.row(4), k.on_side(_R)),
            one(_col_against(3, k.row(4), _R)),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "Tower of five — sorry, four — at the back.", one(T(4), reg("back"))),
    _c(
        "seq-02",
        SEQ,
        "make a wall on the left, no, right, six long and two high",
        one(k.wall(6, 2), reg("right")),
    ),
    _c(
        "seq-03",
        SEQ,
        "I have 18 cubes. Lay a 2 by 3 slab, then keep adding layers the same size until "
        "they're all used.",
        k.all_of(one(k.block(2, 3, 3)), _all(18)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Hi, please build a staircase of five steps and then remove the top step. Thanks, Priya",
        one(k.any_of(k.staircase(4), k.profile(1, 2, 3, 4, 4))),
    ),
    _c(
        "seq-05",
        SEQ,
        "First, a 3x3 slab was laid on the table; then a 2x2 slab was placed on it; finally a "
        "single cube was put on top.",
        one(k.pyramid_counts(9, 4, 1), k.base(3, 3)),
    ),
    _c(
        "seq-06",
        SEQ,
        "I'm on the far side of the table from the robot. Build a tower of six on my left, then "
        "take two cubes off it.",
        one(T(4), reg("right")),
    ),
    _c(
        "seq-07",
        SEQ,
        "With 9 cubes: build a tower of five first, then a tower next to it from the cubes that "
        "are left.",
        k.all_of(
            k.any_of(k.pair(T(5), T(4), k.within(0.25)), one(k.cell_heights(5, 4))),
            _all(9),
        ),
    ),
    _c(
        "seq-08",
        SEQ,
        "Row of seven across the front, actually make it six, then a tower of two on each end.",
        one(
            k.any_of(k.profile(3, 1, 1, 1, 1, 3), k.profile(2, 1, 1, 1, 1, 2)),
            k.runs("y"),
            reg("front"),
        ),
    ),
    _c(
        "seq-09",
        SEQ,
        "Hello, first make a 2 by 4 slab, then put another 2 by 4 layer on top of it. Kind "
        "regards, Omar",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "We will stack seven cubes into a tower and then take away the top three.",
        one(T(4)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Put a 2x2 block three high on my right — I'm across from the robot — and then a single "
        "cube on top of it.",
        one(k.on_top(T(1), k.block(2, 2, 3)), k.levels(4, 4, 4, 1), reg("left")),
    ),
    _c(
        "seq-12",
        SEQ,
        "I've got 15 cubes. Build a staircase of five steps with them, all of them, and "
        "nothing else.",
        k.all_of(one(k.staircase(5)), _all(15)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Build two towers of four, then join them with a beam — no, leave the beam off, just a "
        "cube's gap between them.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Dear cell team, please lay out a row of five cubes and afterwards extend it to eight. "
        "Thank you, Lena",
        one(k.row(8)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Initially a wall four cubes long and three high was built; its top layer was then "
        "removed.",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Standing opposite the robot here. Two towers of three, one on my left and one on my "
        "right, then take away the one on my left.",
        one(T(3), reg("left")),
    ),
    _c(
        "seq-17",
        SEQ,
        "I've got 10 cubes. Make a tower of six and a tower of four, then move the top cube of "
        "the tall one onto the short one.",
        k.all_of(k.any_of(k.each(2, T(5)), one(k.cell_heights(5, 5))), _all(10)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build a ring five by five, one high — sorry, two high — then put a tower of three in "
        "the middle of it.",
        k.pair(k.all_of(k.ring_of(2, (3, 3)), k.dims(5, 5)), T(3), k.centred_in(0.03)),
    ),
    _c(
        "seq-19",
        SEQ,
        "The procedure was: lay a row of four cubes from front to back, then stack a second "
        "row directly on top of it.",
        one(k.wall(4, 2), k.runs("x")),
    ),
    _c(
        "seq-20",
        SEQ,
        "Hi! Could you make a pyramid with a 3x3 base and then take the top cube off? Cheers, Dev",
        k.any_of(one(k.pyramid_counts(9, 4), k.base(3, 3)), one(k.block(3, 3, 1))),
    ),
    _c(
        "seq-21",
        SEQ,
        "Tower of 3 at the front, wait, make that the back right.",
        one(T(3), reg("back right")),
    ),
    _c(
        "seq-22",
        SEQ,
        "Hello, we'd like two 2x2 blocks a cube apart, one two high and one four high, and then "
        "a single cube on top of the bigger one. Thanks, Elif",
        k.pair(
            k.all_of(k.on_top(T(1), k.block(2, 2, 4)), k.levels(4, 4, 4, 4, 1)),
            k.block(2, 2, 2),
            k.gap_of(1),
        ),
    ),
    _c(
        "seq-23",
        SEQ,
        "We will build a tower of three and then a tower of five to its left; afterwards two "
        "more cubes will be added to the first tower.",
        k.any_of(k.pair(T(5), T(5), k.on_side(_L)), one(k.cell_heights(5, 5), k.runs("y"))),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Use all 12 cubes to make a slab three cubes wide.",
        k.all_of(one(k.block(3, 4, 1)), _all(12)),
    ),
    _c(
        "num-02",
        NUM,
        "I've got 9 cubes, make a square slab with them.",
        k.all_of(one(k.block(3, 3, 1)), _all(9)),
    ),
    _c(
        "num-03",
        NUM,
        "From where I'm standing, opposite the robot: three towers in a row from my left to my "
        "right, two, four and six high, a cube apart.",
        k.in_order("y", T(6), T(4), T(2), gaps=(1,)),
    ),
    _c(
        "num-04",
        NUM,
        "Three towers of four — sorry, of five — in a line, a cube apart.",
        k.in_line(3, T(5), 1),
    ),
    _c("num-05", NUM, "Hi, can we get a tower of nine cubes please? Thanks, Kim", one(T(9))),
    _c(
        "num-06",
        NUM,
        "The model consisted of four towers, each two cubes high, arranged in a row with a gap "
        "of one cube between neighbours.",
        k.in_line(4, T(2), 1),
    ),
    _c(
        "num-07",
        NUM,
        "I have 16 cubes. Build a square ring one cube high and use them all.",
        k.all_of(one(_PEN5), _all(16)),
    ),
    _c(
        "num-08",
        NUM,
        "Eight cubes: make two towers the same height.",
        k.any_of(k.each(2, T(4)), one(k.cell_heights(4, 4))),
    ),
    _c(
        "num-09",
        NUM,
        "A staircase of six steps, no, five, going up to the left.",
        one(k.staircase(5), k.rises(_L)),
    ),
    _c(
        "num-10",
        NUM,
        "I'm across the table from the robot. Put a dozen cubes down as a slab, three by four, "
        "on my right.",
        one(k.block(3, 4, 1), reg("left")),
    ),
    _c(
        "num-11",
        NUM,
        "Good morning. We would like five single cubes in a row, spaced one cube apart, at the "
        "back. Regards, Helen",
        k.all_of(k.in_line(5, T(1), 1), k.layout(reg("back"))),
    ),
    _c(
        "num-12",
        NUM,
        "The second structure will be a pyramid of four levels with a single cube at the top.",
        one(k.pyramid(4), _pointed),
    ),
    _c(
        "num-13",
        NUM,
        "I've got 12 cubes. Make three towers of equal height in a line, a cube apart, and use "
        "every cube.",
        k.all_of(k.in_line(3, T(4), 1), _all(12)),
    ),
    _c(
        "num-14",
        NUM,
        "Give me two — no, three — rows of four, side by side, with a cube between them.",
        _rows3(4, 1),
    ),
    _c(
        "num-15",
        NUM,
        "Starting nearest me (I'm on the side opposite the robot) and going towards the robot: "
        "towers of four, three and two, each a cube apart.",
        k.in_order("x", T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-16",
        NUM,
        "Hello, please build a wall ten cubes long and two high. Thank you, Ravi",
        one(k.wall(10, 2)),
    ),
    _c(
        "num-17",
        NUM,
        "We will need a pyramid with a base of four by four cubes and four levels.",
        one(k.pyramid_counts(16, 9, 4, 1), k.base(4, 4)),
    ),
    _c(
        "num-18",
        NUM,
        "I've got 20 cubes. Build a wall four cubes high that uses all of them.",
        k.all_of(one(k.wall(5, 4)), _all(20)),
    ),
    _c(
        "num-19",
        NUM,
        "Five towers of two, or, hmm, make it four towers of three, in a row with a cube's gap.",
        k.in_line(4, T(3), 1),
    ),
    _c(
        "num-20",
        NUM,
        "Hi, we need a tower of three and another twice its height, with a gap of one cube. "
        "Thanks, Ed",
        k.pair(T(6), T(3), k.gap_of(1)),
    ),
    _c(
        "num-21",
        NUM,
        "I've got 12 cubes: a tower of eight and one half as tall beside it.",
        k.all_of(
            k.any_of(k.pair(T(8), T(4), k.within(0.25)), one(k.cell_heights(8, 4))),
            _all(12),
        ),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Tower 25 cm tall on my left, please — I'm standing opposite the robot.",
        one(T(5), reg("right")),
    ),
    _c(
        "dim-02",
        DIM,
        "I've got 12 cubes; make a wall 20 cm long and use them all.",
        k.all_of(one(k.wall(4, 3)), _all(12)),
    ),
    _c(
        "dim-03",
        DIM,
        "A slab 15 cm by 20 cm — sorry, 15 by 25 — one layer.",
        one(k.block(3, 5, 1)),
    ),
    _c(
        "dim-04",
        DIM,
        "Hi, could you please build a tower 300 mm high? Thanks, Nadia",
        one(T(6)),
    ),
    _c(
        "dim-05",
        DIM,
        "The wall will measure 30 cm in length and 10 cm in height.",
        one(k.wall(6, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "Across the table from the robot here. Put a row 35 cm long running left to right along "
        "the edge nearest me.",
        one(k.row(7), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "dim-07",
        DIM,
        "With 8 cubes, build a block 10 cm by 10 cm, as tall as they allow.",
        k.all_of(one(k.block(2, 2, 2)), _all(8)),
    ),
    _c(
        "dim-08",
        DIM,
        "Make a staircase 20 cm high, um, 15 cm high, with 5 cm steps.",
        one(k.staircase(3)),
    ),
    _c(
        "dim-09",
        DIM,
        "Dear all, we need a 2 by 4 slab, 10 cm thick, in the centre of the table. Best, Karl",
        one(k.block(2, 4, 2), reg("centre")),
    ),
    _c(
        "dim-10",
        DIM,
        "The bridge consisted of two pillars 15 cm tall with a 15 cm beam laid across them.",
        one(_beam_bridge(3)),
    ),
    _c(
        "dim-11",
        DIM,
        "Square ring 20 cm across, 5 cm high, in the corner nearest me on my left — I'm on the "
        "opposite side to the robot.",
        one(_PEN4, reg("back right")),
    ),
    _c(
        "dim-12",
        DIM,
        "I've got 6 cubes. Make a tower 15 cm tall and another one with what's left, not touching.",
        k.all_of(k.each(2, T(3)), _all(6)),
    ),
    _c(
        "dim-13",
        DIM,
        "A tower of 200 mm — I mean 250 mm — in the back left.",
        one(T(5), reg("back left")),
    ),
    _c(
        "dim-14",
        DIM,
        "Hello, please place two towers 10 cm tall, 10 cm apart. Thanks, Mo",
        k.pair(T(2), T(2), k.gaps(1, 2)),
    ),
    _c(
        "dim-15",
        DIM,
        "We will need a slab 0.25 m by 0.1 m, one cube thick.",
        one(k.block(5, 2, 1)),
    ),
    _c(
        "dim-16",
        DIM,
        "I'm at the end of the table opposite the robot. A staircase 20 cm high that climbs "
        "away from me.",
        one(k.staircase(4), k.rises(_F)),
    ),
    _c(
        "dim-17",
        DIM,
        "I've got 18 cubes. Make a block 15 cm by 10 cm and stack it up until all are used.",
        k.all_of(one(k.block(3, 2, 3)), _all(18)),
    ),
    _c(
        "dim-18",
        DIM,
        "Bridge with pillars 10 cm tall, no, 15 cm, and a beam on top.",
        one(_beam_bridge(3)),
    ),
    _c(
        "dim-19",
        DIM,
        "Hi, we'd like a wall half a metre long and 5 cm high along the back. Cheers, Pat",
        one(k.row(10), k.runs("y"), reg("back")),
    ),
    _c(
        "dim-20",
        DIM,
        "The pyramid will have a base 20 cm square and stand 20 cm tall.",
        one(k.pyramid_counts(16, 9, 4, 1), k.base(4, 4)),
    ),
    _c(
        "dim-21",
        DIM,
        "Slab, 10 cm by 20 cm, on the left.",
        one(k.block(2, 4, 1), reg("left")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A tower of five, but not on my left — I'm facing the robot from across the table.",
        one(T(5), k.not_(reg("right"), "on the speaker's left (the robot's right)")),
    ),
    _c(
        "neg-02",
        NEG,
        "I've got 9 cubes. Make a 3 by 3 square, one layer, but leave the middle spot empty.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-03",
        NEG,
        "Bridge with legs of two and a beam — no, no beam, just cubes across the top.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-04",
        NEG,
        "Hello, please build a pyramid of three levels, and please don't use beams. Thanks, Sue",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-05",
        NEG,
        "The wall must not run left to right; it will be five cubes long and two high.",
        one(k.wall(5, 2), k.runs("x")),
    ),
    _c(
        "neg-06",
        NEG,
        "Keep it off my side of the table, I'm opposite the robot: a 2 by 2 block, two high.",
        one(k.block(2, 2, 2), k.not_(reg("back"), "on the speaker's side (the back)")),
    ),
    _c(
        "neg-07",
        NEG,
        "I've got 10 cubes but don't use them all — just a tower of six.",
        one(T(6)),
    ),
    _c(
        "neg-08",
        NEG,
        "Two towers of three, touching — no, not touching.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-09",
        NEG,
        "Hi, we need a row of five, but not along the front please. Best, Ali",
        one(k.row(5), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-10",
        NEG,
        "No beams were used; the structure was a table with four legs two cubes high.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-11",
        NEG,
        "From where I'm standing across the table, a staircase of four that does not climb "
        "towards me.",
        one(k.staircase(4), k.not_(k.rises(_B), "climbs towards the speaker (the back)")),
    ),
    _c(
        "neg-12",
        NEG,
        "Put a tower of four in the centre — not the centre, sorry, anywhere but the centre.",
        one(T(4), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-13",
        NEG,
        "Six cubes, none of them stacked, all touching in one straight line.",
        one(k.row(6)),
    ),
    _c(
        "neg-14",
        NEG,
        "Hello, please build two towers of four, but not next to each other: one at each end of "
        "the table. Thanks, Ben",
        k.pair(T(4), T(4), _opposite_ends),
    ),
    _c(
        "neg-15",
        NEG,
        "The slab will be three by three with no second layer.",
        one(k.block(3, 3, 1)),
    ),
    # ------------------------------------------------------------------ typo
    _c(
        "typo-01",
        TYP,
        "Tower of fuor on my rigth, Im oposite the robot",
        one(T(4), reg("left")),
    ),
    _c(
        "typo-02",
        TYP,
        "Ive got 8 cubse, make a 2x2 blcok with all of them",
        k.all_of(one(k.block(2, 2, 2)), _all(8)),
    ),
    _c("typo-03", TYP, "Wall of five, sory, six, two hihg", one(k.wall(6, 2))),
    _c(
        "typo-04",
        TYP,
        "Hi, could you plese build a pyarmid of three levles? Thnaks, Jen",
        one(k.pyramid(3)),
    ),
    _c(
        "typo-05",
        TYP,
        "The strucutre will consits of a staircase of four setps.",
        one(k.staircase(4)),
    ),
    _c(
        "typo-06",
        TYP,
        "Bridge, legs of three, beam acorss, at teh far side from me (Im across from the robot)",
        one(_beam_bridge(3), reg("front")),
    ),
    _c(
        "typo-07",
        TYP,
        "Use all 12 cubes to mkae a 2 by 6 slab",
        k.all_of(one(k.block(2, 6, 1)), _all(12)),
    ),
    _c("typo-08", TYP, "Towre of 3 at the frnot, no, the bakc", one(T(3), reg("back"))),
    _c(
        "typo-09",
        TYP,
        "Helo, two towers of five wiht a gap of one cube betwen them. Thx, Raj",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "typo-10",
        TYP,
        "We plaecd a singel cube on top of a 2x2 block two cubse high.",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.levels(4, 4, 1)),
    ),
    _c(
        "typo-11",
        TYP,
        "Rign 5x5 one hihg, on my lfet please, I'm standnig opposite the robot",
        one(_PEN5, reg("right")),
    ),
    _c("typo-12", TYP, "9 cubse, a tower, use evrey one", k.all_of(one(T(9)), _all(9))),
    _c(
        "typo-13",
        TYP,
        "Slab 3 by 4 — no 4 by 4 — one layre, in the midlde",
        one(k.block(4, 4, 1), reg("centre")),
    ),
    _c(
        "typo-14",
        TYP,
        "A tabel with four lges, each threee cubes high, will be bulit.",
        one(_roofed(4, 3)),
    ),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "On my left, from where I stand across the table, a tower of three.",
        one(T(3), reg("right")),
    ),
    _c("wo-02", WO, "All eight of my cubes, one tower — that's the job.", one(T(8))),
    _c(
        "wo-03",
        WO,
        "Four steps, no, five, that's the staircase I want.",
        one(k.staircase(5)),
    ),
    _c(
        "wo-04",
        WO,
        "Hi team. At the back left, if possible, a 2 by 3 slab. Thanks, Nina",
        one(k.block(2, 3, 1), reg("back left")),
    ),
    _c(
        "wo-05",
        WO,
        "Two cubes high and six long: that is the wall we will build.",
        one(k.wall(6, 2)),
    ),
    _c(
        "wo-06",
        WO,
        "Far side from me — I'm opposite the robot — running left to right, a row of six.",
        one(k.row(6), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-07",
        WO,
        "Into a 3 by 3 slab go nine of my twelve cubes, and the other three onto its middle as "
        "a tower.",
        k.all_of(
            one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
            _all(12),
        ),
    ),
    _c(
        "wo-08",
        WO,
        "Behind the tower of five — sorry, of four — put a tower of two.",
        k.pair(T(2), T(4), k.on_side(_B)),
    ),
    _c(
        "wo-09",
        WO,
        "Hello. A pyramid, three levels, in the middle of the table is what we'd like. Best "
        "regards, Claire",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "wo-10",
        WO,
        "Between two towers of five, a beam was laid, the towers a cube apart.",
        one(_beam_bridge(5, 1)),
    ),
    _c(
        "wo-11",
        WO,
        "Nearest to me, and I'm on the far side from the robot, a 2x2 block, three high.",
        one(k.block(2, 2, 3), reg("back")),
    ),
    _c(
        "wo-12",
        WO,
        "Twelve cubes, three high, a wall, all of them used.",
        k.all_of(one(k.wall(4, 3)), _all(12)),
    ),
    _c(
        "wo-13",
        WO,
        "At the front — I mean the right — put a ring four by four, one high.",
        one(_PEN4, reg("right")),
    ),
    _c(
        "wo-14",
        WO,
        "Three levels high, with a base of three by three, the pyramid was built at the front.",
        one(k.pyramid_counts(9, 4, 1), k.base(3, 3), reg("front")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi there,\n\nHope you're well. Could you build a tower of six cubes for our display?"
        "\n\nThanks in advance,\nGreta",
        one(T(6)),
    ),
    _c(
        "fil-02",
        FIL,
        "Good morning, I'm writing on behalf of Acme Fixtures (order 5521). Please make a wall "
        "seven long and two high. Kind regards, Bill Turner, Purchasing",
        one(k.wall(7, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Lab 4, Group B, 12 March. Aim: to test the robot's stacking accuracy. Method: a tower "
        "of five cubes will be built in the centre of the workspace.",
        one(T(5), reg("centre")),
    ),
    _c(
        "fil-04",
        FIL,
        "Okay, so I'm on the other side of the table from the robot, by the window, and my "
        "coffee's going cold. Put a staircase of three steps on my right.",
        one(k.staircase(3), reg("left")),
    ),
    _c(
        "fil-05",
        FIL,
        "Right, I counted them twice and there are 6 cubes in the tray, plus two beams I won't "
        "need. Make a row with all six.",
        k.all_of(one(k.row(6)), _all(6)),
    ),
    _c(
        "fil-06",
        FIL,
        "Um, okay, so, a, a block, two by two, sorry, I'm all over the place today, three high.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-07",
        FIL,
        "Dear SDI cell, we are a small school group visiting on Friday with 25 pupils. Could you "
        "build a bridge with two towers of two and a beam on top for them to see? Warm regards, "
        "Mrs Patel",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-08",
        FIL,
        "As outlined in section 2.3 of the report, and in line with our hypothesis, the "
        "specimen will be a slab of 4 by 3 cubes, one layer thick.",
        one(k.block(4, 3, 1)),
    ),
    _c(
        "fil-09",
        FIL,
        "I can't reach that far across, so — I'm opposite the robot — put a tower of three "
        "right in front of me, on my side of the table.",
        one(T(3), reg("back")),
    ),
    _c(
        "fil-10",
        FIL,
        "Got a fresh box of cubes today, 40 in it, but for now just build a tower of five.",
        one(T(5)),
    ),
    _c(
        "fil-11",
        FIL,
        "Can you, hmm, build a pyramid of, let me check my notes, three levels. Yes. Three.",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-12",
        FIL,
        "Hello,\nFollowing up on my call this morning. We'd like a ring five by five, one cube "
        "high.\nThanks again,\nMarta (Quality team, ext. 4410)",
        one(_PEN5),
    ),
    _c(
        "fil-13",
        FIL,
        "Week 6 practical. Our team of three students planned a staircase with four steps as the "
        "demonstration piece.",
        one(k.staircase(4)),
    ),
    _c(
        "fil-14",
        FIL,
        "Sorry, I'm over on the visitor side, the opposite end from the robot. Could you do a "
        "2x3 slab? Anywhere's fine.",
        one(k.block(2, 3, 1)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "I'm across the table from the robot. Tower of four in the corner to my right and "
        "nearest me.",
        one(T(4), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "From my side, opposite the robot: a row of five running away from me, down my "
        "left-hand side.",
        one(k.row(5), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-03",
        REG,
        "I've got 4 cubes. Stack them all in the front right corner.",
        k.all_of(one(T(4), reg("front right")), _all(4)),
    ),
    _c(
        "reg-04",
        REG,
        "Block 2 by 2, two high, at the back right, sorry, back left.",
        one(k.block(2, 2, 2), reg("back left")),
    ),
    _c(
        "reg-05",
        REG,
        "Hi, please put a tower of three exactly in the middle of the table. Thanks, Ines",
        one(T(3), reg("centre"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-06",
        REG,
        "A tower of three cubes will be positioned at x = 0.4 m, y = 0.2 m.",
        one(T(3), k.near(0.40, 0.20, 0.02)),
    ),
    _c(
        "reg-07",
        REG,
        "Standing opposite the robot: put a 3x3 slab in the far corner on my left — far from me, "
        "that is.",
        one(k.block(3, 3, 1), reg("front right")),
    ),
    _c(
        "reg-08",
        REG,
        "Use all 5 cubes for a row along the left edge.",
        k.all_of(one(k.row(5), k.runs("x"), k.centre_y_min(0.45)), _all(5)),
    ),
    _c(
        "reg-09",
        REG,
        "Staircase of three in the front left, no, front right.",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "reg-10",
        REG,
        "Dear team, could you place a wall of six by two along the back edge of the table? "
        "Regards, Hugo",
        one(k.wall(6, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-11",
        REG,
        "The pyramid (two levels) was built in the front left corner of the workspace.",
        one(k.pyramid(2), reg("front left")),
    ),
    _c(
        "reg-12",
        REG,
        "I'm at the far end from the robot. Tower of six halfway between me and the robot, on "
        "the centre line.",
        one(T(6), reg("centre"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-13",
        REG,
        "I've got 12 cubes, lay them all as a 3 by 4 slab in the back half of the table.",
        k.all_of(one(k.block(3, 4, 1), k.min_x(0.50)), _all(12)),
    ),
    _c(
        "reg-14",
        REG,
        "A row of four in the back, sorry, at the front, running left to right.",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "reg-15",
        REG,
        "Hi, could you build a tower of five at the front right of the table? Thanks, Leo",
        one(T(5), reg("front right")),
    ),
    _c(
        "reg-16",
        REG,
        "Two towers of three will be built, one in the back left corner and one in the back "
        "right corner.",
        k.structures(k.all_of(T(3), reg("back left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "reg-17",
        REG,
        "From where I'm standing, across from the robot: a tower of two in the corner nearest "
        "me on my right, and a tower of four in the far corner on my left.",
        k.structures(k.all_of(T(2), reg("back left")), k.all_of(T(4), reg("front right"))),
    ),
    _c(
        "reg-18",
        REG,
        "Tower of three on the robot's right-hand side, please — its right, not mine.",
        one(T(3), reg("right")),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "I've got 10 cubes. Build whatever you like, but use them all.",
        k.all_of(k.anything, _all(10)),
    ),
    _c(
        "open-02",
        OPEN,
        "Hi, anything you think looks good is fine with us, as long as it's no taller than 20 "
        "cm. Thanks, Ann",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-03",
        OPEN,
        "For the demonstration, the structure can be any shape the robot chooses, provided it "
        "uses no more than eight cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=8))),
    ),
    _c(
        "open-04",
        OPEN,
        "Something on my side of the table, whatever you like — I'm the one opposite the robot.",
        k.all_of(k.anything, k.layout(reg("back"))),
    ),
    _c(
        "open-05",
        OPEN,
        "Build me a tower — no, actually, anything you like, surprise me.",
        k.anything,
    ),
    _c(
        "open-06",
        OPEN,
        "I've got 6 cubes and two beams; build something with a gap under it, your choice.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-07",
        OPEN,
        "Hello, could you build something tall at the back for a photo? Anything works. "
        "Regards, Finn",
        k.all_of(k.anything, k.layout(k.all_of(reg("back"), k.height(lo=_TALL)))),
    ),
    _c(
        "open-08",
        OPEN,
        "The design is left to the robot, except that it should contain two separate structures.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-09",
        OPEN,
        "Anything at all, but nothing on my left, please — I'm across the table from the robot.",
        k.all_of(k.anything, _every(k.not_(reg("right"), "on the speaker's left"))),
    ),
    _c(
        "open-10",
        OPEN,
        "Make something with steps, a staircase or, no, a pyramid, whichever, you choose.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-11",
        OPEN,
        "I've got 4 cubes, build what you like, as long as none of them are stacked.",
        k.all_of(k.anything, k.layout(k.all_of(k.low(1), _cubes(hi=4)))),
    ),
    _c(
        "open-12",
        OPEN,
        "Hi team — any kind of enclosure will do, one cube high. Thanks! Zoe",
        k.all_of(k.anything, one(k.ring, k.height(1))),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "Use all 300 cubes to make one big tower.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-02",
        BAD,
        "I've got 7 cubes; make a 2 by 2 block and use every one of them.",  # 7 is not 4n
        k.honest(k.anything),
    ),
    _c(
        "bad-03",
        BAD,
        "A tower of five — sorry, I mean —",  # the correction never arrives
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-04",
        BAD,
        "Hi, do you also sell the cubes separately? We'd like to order some. Thanks, Jack",
        k.honest(),
    ),
    _c(
        "bad-05",
        BAD,
        "The structure will be a sphere of radius 10 cm.",
        k.honest(k.anything),
    ),
    _c(
        "bad-06",
        BAD,
        "Build a tower of four on the floor by my feet, I'm across from the robot.",
        k.honest(k.anything),  # off the table
    ),
    _c("bad-07", BAD, "mmmbbbvv cxz 0 0 0 ;;", k.honest()),
    _c(
        "bad-08",
        BAD,
        "Bonjour, pourriez-vous construire une tour de quatre cubes ? Merci, Sophie",
        k.honest(one(T(4))),
    ),
    _c(
        "bad-09",
        BAD,
        "A tower of four, no, forget it, don't build anything.",
        k.honest(),
    ),
    _c(
        "bad-10",
        BAD,
        "The wall will be 1.2 metres long and two cubes high.",  # 24 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-11",
        BAD,
        "I've got 12 cubes; make a tower of 15 with them.",  # more than the count and the cell
        k.honest(k.anything),
    ),
    _c(
        "bad-12",
        BAD,
        "Hello, please build a cone 20 cm high. Regards, Ivan",
        k.honest(k.anything),
    ),
    _c("bad-13", BAD, "Put it where I'm pointing.", k.honest()),
    _c(
        "bad-14",
        BAD,
        "The pyramid will have minus two levels.",
        k.honest(k.anything),
    ),
    _c(
        "bad-15",
        BAD,
        "Two towers of three, sorry, of eleven, a cube apart.",  # past the cell's 10 levels
        k.honest(k.anything),
    ),
    _c(
        "bad-16",
        BAD,
        "I've got 5 cubes. Build a 3 by 3 slab with them.",
        k.honest(k.anything),
    ),
    _c(
        "bad-17",
        BAD,
        "Hi, can you build a tower of four cubes out of glass? Thanks, Ola",  # not stocked
        k.honest(one(T(4))),
    ),
    _c(
        "bad-18",
        BAD,
        "The structure will be a tower that is both three and six cubes tall.",
        k.honest(one(k.any_of(T(3), T(6)))),
    ),
    _c(
        "bad-19",
        BAD,
        "From my side, opposite the robot: a wall twenty cubes long from my left to my right.",
        k.honest(k.anything),  # 20 cubes across: past the cell's 10
    ),
]
