"""A thirty-second set for the language front end (dev32): five more everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev31` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is deliberately mainstream: about
80 % of the commands are what an operator at the cell really types — one or two structures
with a size, a place, one relation or a two-step sequence, in plain but varied English (many
verbs and sentence orders; sizes as words, digits, "3x2", cm, mm and m; articles sometimes
dropped; casual punctuation) — and they come from five kinds of people, none used before:

* an operator dictating to the cell's voice input: numbers spoken as words ("four cubes",
  "twenty centimetres"), no punctuation but the capital and the full stop the dictation puts
  in, run-on sentences ("… the wall is five long and two high"), spoken corrections ("no
  wait make that six", "sorry to the left") where the last word wins, and now and then a
  word the recogniser heard wrong ("power" for tower, "rose" for row, "ate" for eight), read
  as the operator meant it. A phrase cut off before the size, a negative size, a
  contradiction and a command in Spanish are bad input;
* a fitter running test builds after a tool changeover: "Test piece:", "Check build:", "One
  more for the record:", "Test piece #3" and notes on the tool ("gripper swapped", "3 bolts
  re-torqued", "offsets re-taught at 14:20"). Test-piece numbers, times, bolt counts and
  step numbers ("Step 2: …") are never sizes; "X 600 Y 150" is the footprint centre in mm in
  the cell frame, held to 2 cm; "150 x 100 x 100" for a block is length × width × height but
  also accepted as a 2 × 2 footprint 3 high. A tower past the cell's height, a sphere, a
  position off the table and a cancelled check build are bad input (the last admits only a
  refusal);
* a trainer writing short exercises for new operators: "Exercise 7: …", "Task: …", "Goal:
  …", "Difficulty: easy. Time: 2 minutes." The exercise number, the time and the
  difficulty are never a size. An exercise that asks for two heights at once, a wall
  longer than the cell and a task that is not a build at all ("explain to your partner …",
  refusal only) are bad input;
* an operator who describes the build by its use or look and gives sizes for it. A bench
  is two legs under a seat (a beam, or a bar of cubes across the legs' tops); a doorway, a
  gateway, a goal or gateposts "with a crossbar" is two posts under a beam or a bar of cubes
  (a beam when the command names one); a pillar or post is a tower; a platform, plinth or
  step-stool is a full block; a set of steps is a staircase (climbing the way said); a low
  fence is a row, one cube high unless a height is given, running along the edge it is put
  along; a pen is a ring; a hedge is a row. "A doorway about 20 cm tall" accepts posts of
  three under a beam (20 cm overall) and posts of four (a 20 cm opening). A ball, a
  cylinder, a glass box and legs half a cube high are bad input;
* a colleague leaving a sticky note for the next shift: "pls", "thx", "ta", "before 6",
  "tmrw", "→" (then, or: goes to), "&" (and), "w/" (with), "x2" (two of them, separate),
  "lvls" (levels), brackets for a size, capitals for emphasis ("NOT touching", "EXCEPT"),
  the odd slip of the pen ("towr", "rihgt"). The time and the greeting are filler. A note
  that asks for "the usual", a block that cannot fit inside the ring it is put in, a scrawl
  and a note in German are bad input.

About 80 % ordinary and 20 % harder: three structures, references ("on it", "the one on the
right", "the foot of the stairs"), distributive phrases ("a cube on each end", "one cube on
each corner"), comparisons ("twice as tall as four cubes", "taller by 2"), removals ("take 2
off the top", "pull the 2 cubes off the left end"), corrections in the same message and
unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "two towers" (any count of structures) with nothing said about where they stand is that
  many separate structures, anywhere in the cell; "x2" likewise;
* "next to" with nothing said about touching is clear of it and no more than 25 cm away, or
  set against it so the two are one structure (checked by the column); "right next to it"
  is at most 10 cm clear, or touching; "not touching", "leave a gap" and "apart" are
  separate structures; "N cm apart" (a length) accepts the clear gap and, where buildable,
  the centre-to-centre reading; "N cube(s) apart", "a gap of N" and "gap N" are clear;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance; a tower
  in front of a wall or beside a block may also stand against it as one structure; "at the
  foot of" a staircase is on the side it climbs away from; "between" two towers with
  nothing said about touching accepts separate structures in a line and the merged profile;
* "on top of" a slab or block with nothing said about where stands anywhere on it, "in the
  middle" / "dead centre" of it centred over it (± 3 cm); "a cube on each end" of a row
  stands on its end cubes; "on one of its corners" stands on a corner cell; "inside" a ring
  whose interior the thing fills is one structure, the ring round it;
* a bridge's or gate's top is a beam (overall height one more than the posts) where the
  command names a beam, and a beam or a bar of cubes where it does not; "just cubes across
  the top" is a bar of cubes only; a table is four separate legs under one connected top of
  beams or of cubes;
* a ring's stated size is its outside; "in the middle of" a ring is inside its empty
  interior, clear of the ring, centres within 3 cm;
* a staircase's width is free unless given (a "10 cm wide" staircase is two cubes wide), and
  so is the way it climbs unless said; a pyramid's step is free unless given ("a bottom
  layer of three by three" is any pyramid on a full 3 × 3 base); "a flat top" is a top level
  of more than one part;
* a slab is a full block of the stated footprint, one layer unless a thickness is given;
  "tall" is at least five cubes high; "small" is at most 4 cubes high and 5 long overall;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "back, middle" is the back region with the centre within 8 cm of y = 0.30; "along the
  left edge" a footprint centre at y ≥ 0.45, "along the right-hand edge" one at y ≤ 0.15;
  "the back half" every part at x ≥ 0.50, "the front half" every part at x ≤ 0.50; "the
  centre line" is y = 0.30 ± 3 cm; "not near the robot" is outside the front region; a
  stated coordinate is the footprint centre ± 2 cm.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`); a request that is not a build at all, or that was cancelled, admits
only the refusal. Geometry comes only from `sdi.bench.boxes`, through the shared checks in
`language_checks` and the local checks below.

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

_TALL = 5  # cubes: "tall"
_OPPOSITE = {_L: _R, _R: _L, _F: _B, _B: _F}


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev32-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _span(posts: int, mouth: int | None = None) -> k.Check:
    """A bridge with no beam named: two posts `posts` high with a beam or a bar of cubes
    across the tops."""
    return k.any_of(_beam_bridge(posts, mouth), _bar_on_posts(posts, posts, mouth))


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


def _col_beside(h: int, rest: k.Check, side: str, col: k.Check | None = None) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table, set against the rest,
    which passes `rest`; the column lies on `side` of the rest and passes `col` when given."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for c in bx.columns(bs):
            if len(c) != h or k.tower(h)(c) is not None or c[0].lo[2] > bx.TOL:
                continue
            others = [b for b in bs if all(b is not q for q in c)]
            if not others:
                continue
            r = rest(others) or (col(c) if col is not None else None)
            if r is None and bx.side_of(c, others) != side:
                r = f"the {h}-column is {bx.side_of(c, others)} of the rest, want {side}"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the rest"

    return f


def _topped(base: k.Check, n_top: int = 1) -> k.Check:
    """The topmost level is `n_top` parts standing on the rest, and the rest passes `base`."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        z = max(round(b.lo[2], 3) for b in bs)
        top = [b for b in bs if round(b.lo[2], 3) == z]
        rest = [b for b in bs if round(b.lo[2], 3) != z]
        if len(top) != n_top:
            return f"{len(top)} parts on top, want {n_top}"
        if not rest or not bx.stands_on(top, rest):
            return "nothing on top of the rest"
        return base(rest)

    return f


def _missing_on(side: str) -> k.Check:
    """The footprint's border has at least one empty cell, and every empty border cell lies on
    its `side` edge (front = smallest x, left = largest y)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        cs = bx.cells(bs)
        fx, fy = bx.footprint_cubes(bs)
        border = {
            (i, j) for i in range(fx) for j in range(fy) if i in (0, fx - 1) or j in (0, fy - 1)
        }
        missing = border - cs
        if not missing:
            return "no gap in the border"
        on_edge = {
            _F: lambda i, j: i == 0,
            _B: lambda i, j: i == fx - 1,
            _R: lambda i, j: j == 0,
            _L: lambda i, j: j == fy - 1,
        }[side]
        wrong = [c for c in missing if not on_edge(*c)]
        return None if not wrong else f"a gap in the border off the {side} side"

    return f


def _flat_topped_pyramid(bs: k.Boxes) -> k.Reason:
    """A pyramid whose top level is more than one part."""
    p = bx.pyramid_levels(bs)
    if p is None:
        return "not a pyramid"
    return None if p[-1] > 1 else "a single cube on top"


def _fits(a: int, b: int) -> k.Check:
    """A footprint no bigger than a × b cubes (either way round)."""

    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        want = (min(a, b), max(a, b))
        ok = got[0] <= want[0] and got[1] <= want[1]
        return None if ok else f"footprint {got}, want within {want}"

    return f


def _cubes(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Between `lo` and `hi` cubes among the parts (beams not counted)."""

    def f(bs: k.Boxes) -> k.Reason:
        n = sum(k.only_cubes([b]) is None for b in bs)
        if (lo is not None and n < lo) or (hi is not None and n > hi):
            return f"{n} cubes, want {lo if lo is not None else ''}–{hi if hi is not None else ''}"
        return None

    return f


def _has_beam(bs: k.Boxes) -> k.Reason:
    """At least one part is a beam (a horizontal extent of two cubes or more)."""
    if any(max(b.hi[i] - b.lo[i] for i in (0, 1)) >= 2 * bx.CUBE for b in bs):
        return None
    return "no beam in it"


def _centre_y_max(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m): over against the right-hand edge."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


def _max_x(x: float) -> k.Check:
    """Every part lies at x ≤ `x` (m): in the front part of the table."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[0] for b in bs)
        return None if hi <= x + bx.TOL else f"a part reaches x {hi:.3f}, want ≤ {x}"

    return f


def _at_foot(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A stands at the foot of staircase B: on the side B climbs away from."""
    up = bx.rises_towards(b)
    if up is None:
        return "B is not a staircase"
    got = bx.side_of(a, b)
    return None if got == _OPPOSITE[up] else f"A is {got} of the stairs, which climb {up}"


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))


def _next_to(small: k.Check, h: int, big: k.Check, side: str | None, max_gap: float) -> k.Pred:
    """A structure passing `small` (a column of `h` when set against) next to one passing
    `big`: clear of it by at most `max_gap`, or against it as one structure; on `side` of it
    when given."""
    rel = k.within(max_gap) if side is None else k.all_rels(k.on_side(side), k.within(max_gap))
    touching = [_col_beside(h, big, s) for s in ((side,) if side else k.SIDES)]
    return k.any_of(k.pair(small, big, rel), one(k.any_of(*touching)))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Build a tower of four cubes and put a tower of two cubes right next to it on the left.",
        _next_to(T(2), 2, T(4), _L, 0.10),
    ),
    _c(
        "rel-02",
        REL,
        "Test piece: 3x3 slab, one layer, single cube on top dead centre.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "rel-03",
        REL,
        "Exercise 4: Build a wall five cubes long and two high along the back of the table. "
        "Place a tower of three in front of it.",
        k.any_of(
            k.pair(T(3), k.all_of(k.wall(5, 2), k.runs("y"), reg("back")), k.on_side(_F)),
            one(_col_beside(3, k.all_of(k.wall(5, 2), k.runs("y"), reg("back")), _F)),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "I need a doorway: two posts four cubes high with a beam across the top.",
        one(_beam_bridge(4)),
    ),
    _c(
        "rel-05",
        REL,
        "pls build tower of 5 back left & a 2x2 block (2 high) in front of it",
        k.any_of(
            k.pair(k.block(2, 2, 2), k.all_of(T(5), reg("back left")), k.on_side(_F)),
            one(_col_beside(5, k.block(2, 2, 2), _B, reg("back left"))),
        ),
    ),
    _c(
        "rel-06",
        REL,
        "Build a pyramid three levels high then put a row of four cubes behind it with a gap "
        "of one cube.",
        k.pair(k.row(4), k.pyramid(3), k.gap_of(1, _B)),
    ),
    _c(
        "rel-07",
        REL,
        "Check build: two towers of 3, one cube gap, 150 beam across the tops.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "rel-08",
        REL,
        "Task: Place a tower of six in the middle of a ring of cubes five by five, one cube "
        "high. The tower must not touch the ring.",
        k.pair(_PEN5, T(6), k.centred_in(0.03)),
    ),
    _c(
        "rel-09",
        REL,
        "A little bench with a seat three cubes long, legs one cube high at each end.",
        one(_span(1), k.long(3), k.height(2)),
    ),
    _c(
        "rel-10",
        REL,
        "tower of 3 → on top of the 2x2 block pls (block is 1 high)",
        one(k.on_top(T(3), k.block(2, 2, 1)), k.levels(4, 1, 1, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "Put two towers of three cubes side by side with a gap of two cubes between them.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "rel-12",
        REL,
        "Test piece: wall 4 long 3 high, tower of 2 to its right, not touching.",
        k.pair(T(2), k.wall(4, 3), k.on_side(_R)),
    ),
    _c(
        "rel-13",
        REL,
        "Goal: a staircase of four steps, and a tower of four at the foot of the stairs, one "
        "cube away from the lowest step.",
        k.pair(T(4), k.staircase(4), k.all_rels(k.gap_of(1), _at_foot)),
    ),
    _c(
        "rel-14",
        REL,
        "A plinth three by three, one cube thick, with a pillar of four standing in the middle "
        "of it.",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1, 1)),
    ),
    _c(
        "rel-15",
        REL,
        "pyramid (3 lvls) centre & tower of 6 behind it, leave a gap",
        k.pair(T(6), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_B)),
    ),
    _c(
        "rel-16",
        REL,
        "Build three towers in a row the middle one five cubes tall and the outside ones three "
        "cubes tall leave a one cube gap between them.",
        k.line(T(3), T(5), T(3), gaps=(1,)),
    ),
    _c(
        "rel-17",
        REL,
        "One more for the record: bridge, pillars 2 high, a 2-cube gap between them, a row of "
        "cubes across the top.",
        one(_bar_on_posts(2, 2, mouth=2), k.only_cubes),
    ),
    _c(
        "rel-18",
        REL,
        "Exercise 7: Two walls, each four long and two high, parallel to each other and two "
        "cubes apart.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-19",
        REL,
        "A goal for a table-football match: two posts three high with a crossbar on top, and a "
        "single cube for the ball somewhere in front of it.",
        k.pair(T(1), _span(3), k.on_side(_F)),
    ),
    _c(
        "rel-20",
        REL,
        "ring 4x4 (1 high) w/ a 2x2 block, 2 high, INSIDE it filling the middle",
        one(k.holding(k.block(2, 2, 2), _PEN4)),
    ),
    _c(
        "rel-21",
        REL,
        "Build a wall six cubes long and two high across the front then put a staircase of "
        "three steps behind it climbing towards the back with a gap of one cube.",
        k.pair(
            k.all_of(k.staircase(3), k.rises(_B)),
            k.all_of(k.wall(6, 2), k.runs("y"), reg("front")),
            k.gap_of(1, _B),
        ),
    ),
    _c(
        "rel-22",
        REL,
        "Check build: 2x2 block, 3 high. Tower of 5 touching its left side.",
        one(_col_beside(5, k.block(2, 2, 3), _L)),
    ),
    _c(
        "rel-23",
        REL,
        "Task: Lay a row of five cubes, then put a single cube on top of each end of it.",
        one(k.profile(2, 1, 1, 1, 2)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Build a tower of five cubes in the centre then add two more cubes on top.",
        one(T(7), reg("centre")),
    ),
    _c("seq-02", SEQ, "Test piece: tower of 6. Take 2 off the top.", one(T(4))),
    _c(
        "seq-03",
        SEQ,
        "Exercise 2: Lay a row of four cubes. Then lay a second row of four on top of it.",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-04",
        SEQ,
        "First a low platform two by three, one cube thick, then a pillar of three on one of "
        "its corners.",
        one(k.plan_heights("411", "111")),
    ),
    _c(
        "seq-05",
        SEQ,
        "tower of 3 front left → then same again front right",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("front right"))),
    ),
    _c(
        "seq-06",
        SEQ,
        "Make a wall five cubes long and three high actually make it two high.",
        one(k.wall(5, 2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Check build. Step 1: 4x4 slab. Step 2: 3x3 layer on it. Step 3: 2x2 on that. Step 4: "
        "single cube on top.",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Task: Build two towers of four, one cube apart. Then remove the top cube from the one "
        "on the right.",
        k.pair(T(3), T(4), k.gap_of(1, _R)),
    ),
    _c(
        "seq-09",
        SEQ,
        "A set of steps, four of them, going up to the left; then cap the top step with one "
        "more cube.",
        one(_topped(k.all_of(k.staircase(4), k.rises(_L)))),
    ),
    _c(
        "seq-10",
        SEQ,
        "row of 6 along the front → then pull the 2 cubes off the left end",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-11",
        SEQ,
        "Put a pyramid with three levels on the right then put a tower of four to the left of "
        "it with a gap of two cubes.",
        k.pair(T(4), k.all_of(k.pyramid(3), reg("right")), k.gap_of(2, _L)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Gripper changed. Test piece: block 2x2x2. Then build it up to 2x2x4.",
        one(k.block(2, 2, 4)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Exercise 5: First build a staircase of three steps. Next, add a fourth step at the "
        "top end.",
        one(k.staircase(4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "A little wall to sit on, four long and two high. Then knock it down to one high.",
        one(k.row(4)),
    ),
    _c(
        "seq-15",
        SEQ,
        "2 towers of 5 (gap 1) & a beam across the top → then 1 cube on the beam, in the middle",
        one(_topped(_beam_bridge(5, 1)), k.top_centred()),
    ),
    _c("seq-16", SEQ, "Build a tower of eight cubes no wait make that six.", one(T(6))),
    _c(
        "seq-17",
        SEQ,
        "One more for the record: row of 5 on the left. Now a second row of 5 alongside it, "
        "touching.",
        one(k.block(2, 5, 1), reg("left")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Task: Build a ring four by four, one high. Then add a second layer to the ring.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-19",
        SEQ,
        "A low fence along the back, one cube high and six long, then make it a cube taller.",
        one(k.wall(6, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "seq-20",
        SEQ,
        "4x2 slab back right → then 1 cube on each corner of it",
        one(k.plan_heights("2112", "2112"), reg("back right")),
    ),
    _c(
        "seq-21",
        SEQ,
        "Make a staircase of five steps going up to the right sorry to the left.",
        one(k.staircase(5), k.rises(_L)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Build three towers of four cubes each in a line with one cube between them.",
        k.in_line(3, T(4), 1),
    ),
    _c("num-02", NUM, "Test piece #3: tower of 7.", one(T(7))),
    _c("num-03", NUM, "Exercise 12: Build a tower nine cubes high.", one(T(9))),
    _c(
        "num-04",
        NUM,
        "A pair of gateposts, each three cubes tall, a cube apart.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c("num-05", NUM, "tower of 4 x2 pls, before 6", k.each(2, T(4))),
    _c(
        "num-06",
        NUM,
        "Make a pyramid with a bottom layer of three by three cubes.",
        one(k.pyramid(), k.base(3, 3)),
    ),
    _c(
        "num-07",
        NUM,
        "Check build: 12 cubes as a 3 by 4 slab, single layer.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-08",
        NUM,
        "Task 1: Place four single cubes in a line from front to back, each one cube apart.",
        k.in_order("x", *[T(1)] * 4, gaps=(1,)),
    ),
    _c(
        "num-09",
        NUM,
        "A pair of bookends: two towers of three with a gap of four cubes between them.",
        k.pair(T(3), T(3), k.gap_of(4)),
    ),
    _c(
        "num-10",
        NUM,
        "towers 1, 2, 3 & 4 high, left → right, 1 cube gaps",
        k.in_order("y", T(1), T(2), T(3), T(4), gaps=(1,)),
    ),
    _c("num-11", NUM, "I need a tower twice as tall as four cubes.", one(T(8))),
    _c(
        "num-12",
        NUM,
        "Check build: two towers, one of 3 and the other taller by 2, gap 1.",
        k.pair(T(3), T(5), k.gap_of(1)),
    ),
    _c(
        "num-13",
        NUM,
        "Exercise 9: Build a staircase of three steps using exactly a dozen cubes.",
        one(k.staircase(3), k.dims(2, 3), k.parts(12), k.only_cubes),
    ),
    _c(
        "num-14",
        NUM,
        "A little hedge of five cubes in a row with a single cube on the middle one.",
        one(k.profile(1, 1, 2, 1, 1)),
    ),
    _c(
        "num-15",
        NUM,
        "3 single cubes down the left side, front to back, gap of 2 between each",
        k.all_of(k.in_order("x", *[T(1)] * 3, gaps=(2,)), k.layout(reg("left"))),
    ),
    _c(
        "num-16",
        NUM,
        "Build two rows of three cubes one behind the other with a gap of one cube.",
        k.any_of(
            k.pair(
                k.all_of(k.row(3), k.runs("y")),
                k.all_of(k.row(3), k.runs("y")),
                k.parallel_gap(1),
            ),
            k.in_order(
                "x", k.all_of(k.row(3), k.runs("x")), k.all_of(k.row(3), k.runs("x")), gaps=(1,)
            ),
        ),
    ),
    _c("num-17", NUM, "Test piece: five-step staircase.", one(k.staircase(5))),
    _c(
        "num-18",
        NUM,
        "Goal: a wall of eighteen cubes, six long and three high.",
        one(k.wall(6, 3)),
    ),
    _c(
        "num-19",
        NUM,
        "A pen for the cubes: a ring seven by seven, one high.",
        one(k.ring_of(1, (5, 5)), k.dims(7, 7)),
    ),
    _c(
        "num-20",
        NUM,
        "half a dozen cubes as a 2x3 slab, back left, thx",
        one(k.block(2, 3, 1), reg("back left")),
    ),
    _c(
        "num-21",
        NUM,
        "Build four towers one two three and four cubes tall in any order not touching.",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Build a tower thirty centimetres tall.", one(T(6))),
    _c("dim-02", DIM, "Test piece: wall 200 mm long, 150 mm high.", one(k.wall(4, 3))),
    _c(
        "dim-03",
        DIM,
        "Exercise 6: Build a slab 25 cm by 20 cm, one layer thick.",
        one(k.block(5, 4, 1)),
    ),
    _c(
        "dim-04",
        DIM,
        "A little bench 15 cm long with legs 5 cm high.",
        one(_span(1), k.long(3), k.height(2)),
    ),
    _c("dim-05", DIM, "row 30cm, front", one(k.row(6), reg("front"))),
    _c(
        "dim-06",
        DIM,
        "Make a block ten centimetres by ten centimetres and twenty centimetres high.",
        one(k.block(2, 2, 4)),
    ),
    _c("dim-07", DIM, "Check build: tower, 0.25 m.", one(T(5))),
    _c(
        "dim-08",
        DIM,
        "Task: a staircase 20 cm tall, each step 5 cm high.",
        one(k.staircase(4)),
    ),
    _c(
        "dim-09",
        DIM,
        "A doorway about 20 cm tall: two posts and a beam across the top.",
        one(k.any_of(_beam_bridge(3), _beam_bridge(4))),
    ),
    _c(
        "dim-10",
        DIM,
        "wall 40cm long x 10cm high along the back pls",
        one(k.wall(8, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "dim-11",
        DIM,
        "Put down a ring twenty five centimetres on a side one cube high.",
        one(_PEN5),
    ),
    _c(
        "dim-12",
        DIM,
        "Test piece: block 150 x 100 x 100.",
        one(k.any_of(k.block(3, 2, 2), k.block(2, 2, 3))),
    ),
    _c("dim-13", DIM, "Exercise 8: Build a tower 35 cm high.", one(T(7))),
    _c(
        "dim-14",
        DIM,
        "A low fence down the left side, 30 cm long and 5 cm high.",
        one(k.row(6), k.runs("x"), reg("left")),
    ),
    _c("dim-15", DIM, "2 towers 15cm high, 10cm apart", k.pair(T(3), T(3), k.gaps(1, 2))),
    _c(
        "dim-16",
        DIM,
        "Build a pyramid with a base thirty centimetres square.",
        one(k.pyramid(), k.base(6, 6)),
    ),
    _c(
        "dim-17",
        DIM,
        "Check build: beam on two posts, posts 100 mm, top of the beam at 150 mm.",
        one(_beam_bridge(2)),
    ),
    _c(
        "dim-18",
        DIM,
        "Goal: a table. Legs 10 cm high, top 20 cm by 20 cm.",
        one(_roofed(4, 2), k.dims(4, 4)),
    ),
    _c(
        "dim-19",
        DIM,
        "A little platform to stand things on, 20 by 15 centimetres and 10 centimetres thick.",
        one(k.block(4, 3, 2)),
    ),
    _c(
        "dim-20",
        DIM,
        "staircase, 4 steps, 10cm wide",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c(
        "dim-21",
        DIM,
        "Make a wall half a metre long and fifteen centimetres high.",
        one(k.wall(10, 3)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Build a tower of five cubes but not in the middle.",
        one(T(5), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "Test piece: pyramid, 3 levels, no beams.",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "Task: Lay a row of five cubes. It must not be at the front of the table.",
        one(k.row(5), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-04",
        NEG,
        "A doorway with no beam: two posts of three and just cubes across the top.",
        one(_bar_on_posts(3, 3), k.only_cubes),
    ),
    _c("neg-05", NEG, "2 towers of 3 — NOT touching", k.each(2, T(3))),
    _c(
        "neg-06",
        NEG,
        "Build a staircase of four steps that does not go up towards the back.",
        one(k.staircase(4), k.not_(k.rises(_B), "climbs to the back")),
    ),
    _c(
        "neg-07",
        NEG,
        "Check build: 3x3 slab, one layer, without the centre cube.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-08",
        NEG,
        "Goal: two towers of four with nothing between them, a gap of three cubes.",
        k.pair(T(4), T(4), k.gap_of(3)),
    ),
    _c(
        "neg-09",
        NEG,
        "A little table, four legs two high, no beams on top, just cubes.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-10",
        NEG,
        "tower of 6 anywhere EXCEPT back left",
        one(T(6), k.not_(reg("back left"), "at the back left")),
    ),
    _c(
        "neg-11",
        NEG,
        "Put a row of seven cubes and don't make it go front to back.",
        one(k.row(7), k.runs("y")),
    ),
    _c(
        "neg-12",
        NEG,
        "Test piece: block 2x2, 3 high, not near the robot.",
        one(k.block(2, 2, 3), k.not_(reg("front"), "near the robot")),
    ),
    _c(
        "neg-13",
        NEG,
        "Exercise 11: Build a ring five by five, one cube high, but leave out the middle cube "
        "of its left side to make an opening.",
        one(
            k.dims(5, 5),
            k.height(1),
            k.parts(15),
            k.not_(k.ring, "closed"),
            _missing_on(_L),
        ),
    ),
    _c(
        "neg-14",
        NEG,
        "A pyramid with a flat top: three levels, but no single cube at the top.",
        one(k.pyramid(3), _flat_topped_pyramid),
    ),
    _c(
        "neg-15",
        NEG,
        "wall 5 long x 2 high, not along the front",
        one(k.wall(5, 2), k.not_(reg("front"), "at the front")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr of 5 back rihgt", one(T(5), reg("back right"))),
    _c("typo-02", TYP, "Build a power of six cubes on the left.", one(T(6), reg("left"))),
    _c("typo-03", TYP, "Test peice: stair case, 3 steps.", one(k.staircase(3))),
    _c(
        "typo-04",
        TYP,
        "Exercise 3: Bulid a wall fuor cubes long and three high.",
        one(k.wall(4, 3)),
    ),
    _c(
        "typo-05",
        TYP,
        "A litle bench: two legs of one cube and a baem for the seat.",
        one(_beam_bridge(1)),
    ),
    _c("typo-06", TYP, "pyrmaid 4 levles, centre pls", one(k.pyramid(4), reg("centre"))),
    _c(
        "typo-07",
        TYP,
        "Build a rose of five cubes along the front.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c("typo-08", TYP, "Chekc build: 2x2 blcok, 2 high.", one(k.block(2, 2, 2))),
    _c(
        "typo-09",
        TYP,
        "Task: Place two towres of three cubes, one cube aprat.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "typo-10",
        TYP,
        "A dorway: two posts 3 hihg with a beam on top.",
        one(_beam_bridge(3)),
    ),
    _c("typo-11", TYP, "ring 4x4 1 hgih, fornt left", one(_PEN4, reg("front left"))),
    _c("typo-12", TYP, "Build a tower of ate cubes.", one(T(8))),
    _c(
        "typo-13",
        TYP,
        "Test piece: slab 3x3, one layer, w/ a towre of 2 on the middel.",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "typo-14",
        TYP,
        "Goal: a staricase of five steps going up to the rigth.",
        one(k.staircase(5), k.rises(_R)),
    ),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "On the left side of the table a tower of four cubes please.",
        one(T(4), reg("left")),
    ),
    _c("wo-02", WO, "Three high, four long: wall. Test piece.", one(k.wall(4, 3))),
    _c(
        "wo-03",
        WO,
        "Exercise 1: Five cubes high, at the back — that is the tower you must build.",
        one(T(5), reg("back")),
    ),
    _c(
        "wo-04",
        WO,
        "Up to the left, four steps — a set of steps, that's what I need.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c("wo-05", WO, "back right → 2x3 block, 1 high", one(k.block(2, 3, 1), reg("back right"))),
    _c(
        "wo-06",
        WO,
        "In front of the wall put a tower of three the wall is five long and two high.",
        k.any_of(
            k.pair(T(3), k.wall(5, 2), k.on_side(_F)),
            one(_col_beside(3, k.wall(5, 2), _F)),
        ),
    ),
    _c(
        "wo-07",
        WO,
        "With a one-cube gap between them, two towers of six. Check build.",
        k.pair(T(6), T(6), k.gap_of(1)),
    ),
    _c(
        "wo-08",
        WO,
        "Task: On top of a 2 by 2 block one cube high, place a single cube.",
        one(k.on_top(T(1), k.block(2, 2, 1)), k.levels(4, 1)),
    ),
    _c(
        "wo-09",
        WO,
        "Across the back, one cube high, seven long: a low fence.",
        one(k.row(7), k.runs("y"), reg("back")),
    ),
    _c("wo-10", WO, "@ centre: pyramid, 3 lvls", one(k.pyramid(3), reg("centre"))),
    _c(
        "wo-11",
        WO,
        "Three levels that's the pyramid I want on the right.",
        one(k.pyramid(3), reg("right")),
    ),
    _c(
        "wo-12",
        WO,
        "Left of the tower of 5, a tower of 2. Gap 1. One more for the record.",
        k.pair(T(2), T(5), k.gap_of(1, _L)),
    ),
    _c(
        "wo-13",
        WO,
        "Goal: ten centimetres apart and parallel, two rows of four cubes.",
        k.pair(k.row(4), k.row(4), k.either(k.parallel_gap(2), k.parallel_gap(1))),
    ),
    _c(
        "wo-14",
        WO,
        "Two cubes high and three long, that's the little wall I want between the two towers "
        "of four.",
        k.any_of(
            k.between_(k.wall(3, 2), T(4)),
            one(k.profile(4, 2, 2, 2, 4)),
        ),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Okay so this is for the morning batch build a tower of three cubes thank you.",
        one(T(3)),
    ),
    _c(
        "fil-02",
        FIL,
        "Gripper swapped to the new fingers, torque checked, all good. Test piece: row of 4.",
        one(k.row(4)),
    ),
    _c(
        "fil-03",
        FIL,
        "Exercise 2 (about five minutes; read the whole task first): build a tower of six cubes.",
        one(T(6)),
    ),
    _c(
        "fil-04",
        FIL,
        "My daughter wants something her doll can sit on, so a little bench: two legs one "
        "cube high and a beam across.",
        one(_beam_bridge(1)),
    ),
    _c(
        "fil-05",
        FIL,
        "Hi Jo! hope the night went ok :) pls build 3x3 slab, 2 high, before 7 → thx, Sam",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-06",
        FIL,
        "Hello robot good morning it's raining again anyway build a staircase of three steps.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-07",
        FIL,
        "New tool fitted at 14:20, offsets re-taught, calibration ok. One more for the "
        "record: tower of 8.",
        one(T(8)),
    ),
    _c(
        "fil-08",
        FIL,
        "Exercise 4. Difficulty: easy. Time: 2 minutes. Task: build a wall three long and two "
        "high.",
        one(k.wall(3, 2)),
    ),
    _c(
        "fil-09",
        FIL,
        "We've got the school visit on Friday and the kids love anything that looks like a "
        "castle gate, so two posts four high with a beam over the top, please.",
        one(_beam_bridge(4)),
    ),
    _c(
        "fil-10",
        FIL,
        "shift 2 → shift 3: coffee machine fixed!! also pls build a pyramid, 3 levels, on the "
        "left. ta",
        one(k.pyramid(3), reg("left")),
    ),
    _c(
        "fil-11",
        FIL,
        "Um right let me think ok a block two by two and two high in the centre.",
        one(k.block(2, 2, 2), reg("centre")),
    ),
    _c(
        "fil-12",
        FIL,
        "Changeover from gripper A to gripper B complete, 3 bolts re-torqued. Check build: 2 "
        "towers of 4, 2 cubes apart.",
        k.pair(T(4), T(4), k.gap_of(2)),
    ),
    _c(
        "fil-13",
        FIL,
        "Exercise 15 — check the table is clear before you start, and wear your glasses. Goal: "
        "a ring four by four, one high.",
        one(_PEN4),
    ),
    _c(
        "fil-14",
        FIL,
        "Honestly it just needs to look tidy for the photo. A low fence along the front, one "
        "cube high and eight long.",
        one(k.row(8), k.runs("y"), reg("front")),
    ),
    _c(
        "fil-15",
        FIL,
        "sorry for the mess on the bench, will sort tmrw. tower of 5 front right pls",
        one(T(5), reg("front right")),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Build a tower of four cubes in the back left corner.",
        one(T(4), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "Test piece: 2x2 block, 2 high, centred at X 450 Y 300.",
        one(k.block(2, 2, 2), k.near(0.45, 0.30, 0.02)),
    ),
    _c(
        "reg-03",
        REG,
        "Exercise 7: Place a row of five cubes along the right-hand edge of the table, running "
        "front to back.",
        one(k.row(5), k.runs("x"), _centre_y_max(0.15)),
    ),
    _c(
        "reg-04",
        REG,
        "A low fence along the back, one cube high, five long.",
        one(k.row(5), k.runs("y"), reg("back")),
    ),
    _c(
        "reg-05",
        REG,
        "pyramid 2 lvls → front right corner",
        one(k.pyramid(2), reg("front right")),
    ),
    _c(
        "reg-06",
        REG,
        "Put a staircase of three steps in the middle of the table.",
        one(k.staircase(3), reg("centre")),
    ),
    _c(
        "reg-07",
        REG,
        "Check build: tower of 6 at X 600 Y 150.",
        one(T(6), k.near(0.60, 0.15, 0.02)),
    ),
    _c(
        "reg-08",
        REG,
        "Task: Build a 3 by 3 slab, one layer, in the front half of the table.",
        one(k.block(3, 3, 1), _max_x(0.50)),
    ),
    _c(
        "reg-09",
        REG,
        "A set of steps in the front left corner, three steps, going up towards the back.",
        one(k.staircase(3), k.rises(_B), reg("front left")),
    ),
    _c(
        "reg-10",
        REG,
        "wall 6x2 → along left edge, front to back",
        one(k.wall(6, 2), k.runs("x"), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-11",
        REG,
        "Build two towers of three one in the front left corner and one in the back right corner.",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "Test piece: ring 5x5, 1 high, in the back half of the table.",
        one(_PEN5, k.min_x(0.50)),
    ),
    _c(
        "reg-13",
        REG,
        "Goal: a tower of five on the centre line of the table, near the front.",
        one(T(5), k.near(y=0.30, tol=0.03), reg("front")),
    ),
    _c(
        "reg-14",
        REG,
        "A little doorway over on the right: posts two high and a beam across.",
        one(_beam_bridge(2), reg("right")),
    ),
    _c(
        "reg-15",
        REG,
        "block 2x2 (3 high) back, middle — not in a corner",
        one(k.block(2, 2, 3), reg("back"), k.near(y=0.30, tol=0.08)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Build anything you like with up to ten cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-02",
        OPEN,
        "Test piece: your choice, any small shape, just to see the new gripper working.",
        k.small,
    ),
    _c(
        "open-03",
        OPEN,
        "Exercise 13 (free choice): Build any structure that uses at least one beam.",
        k.all_of(k.anything, k.layout(_has_beam)),
    ),
    _c(
        "open-04",
        OPEN,
        "Something that looks a bit like a little house, your design.",
        k.anything,
    ),
    _c(
        "open-05",
        OPEN,
        "build whatever on the right, nothing taller than 3 pls",
        k.all_of(k.anything, k.layout(k.all_of(reg("right"), k.low(3)))),
    ),
    _c(
        "open-06",
        OPEN,
        "Surprise me with something on the left side of the table.",
        k.all_of(k.anything, k.layout(reg("left"))),
    ),
    _c(
        "open-07",
        OPEN,
        "Check build: any two structures, keep them apart.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-08",
        OPEN,
        "Task: Build something with steps in it, your design, no more than four cubes high.",
        k.all_of(
            k.anything,
            k.some(k.any_of(k.staircase(), k.pyramid())),
            k.layout(k.low(4)),
        ),
    ),
    _c(
        "open-09",
        OPEN,
        "Something you could walk under if you were tiny, an arch or a gateway, any size.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-10",
        OPEN,
        "free slot tmrw — build any demo piece, max 8 cubes, no beams",
        k.all_of(k.anything, k.layout(k.all_of(_cubes(hi=8), k.only_cubes))),
    ),
    _c(
        "open-11",
        OPEN,
        "Build something tall in the back right your choice.",
        k.all_of(k.anything, k.layout(k.all_of(reg("back right"), k.height(lo=_TALL)))),
    ),
    _c(
        "open-12",
        OPEN,
        "Goal: free build. Cubes only, and keep it inside a 3 by 3 footprint.",
        k.all_of(k.anything, k.layout(k.all_of(k.only_cubes, _fits(3, 3)))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Build a tower of", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-02",
        BAD,
        "Construye una torre de cuatro cubos en el centro.",
        k.honest(one(T(4))),
    ),
    _c(
        "bad-03",
        BAD,
        "Test piece: tower of 14.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-04", BAD, "Test piece: sphere, 10 cm across.", k.honest(k.anything)),
    _c(
        "bad-05",
        BAD,
        "Exercise 3: Build one tower that is both three cubes and six cubes high.",
        k.honest(one(k.any_of(T(3), T(6)))),
    ),
    _c(
        "bad-06",
        BAD,
        "Task: Build a wall twenty cubes long and two high.",  # past the cell's 12
        k.honest(k.anything),
    ),
    _c("bad-07", BAD, "A nice round ball to sit on the shelf.", k.honest(k.anything)),
    _c(
        "bad-08",
        BAD,
        "A round column like a drainpipe, a cylinder 20 cm high.",
        k.honest(k.anything),
    ),
    _c("bad-09", BAD, "pls build the usual before 6 → thx", k.honest(k.anything)),
    _c("bad-10", BAD, "asdf jkl qwe ;;", k.honest()),
    _c("bad-11", BAD, "Build a tower of minus two cubes.", k.honest(k.anything)),
    _c(
        "bad-12",
        BAD,
        "Check build: block 2x2, 3 high. Scrap that, no check builds today, leave the table empty.",
        k.honest(),
    ),
    _c(
        "bad-13",
        BAD,
        "Exercise 14: Explain to your partner why the robot stops when the door is opened.",
        k.honest(),
    ),
    _c(
        "bad-14",
        BAD,
        "A see-through glass box for the display cabinet.",
        k.honest(k.anything),
    ),
    _c(
        "bad-15",
        BAD,
        "ring 3x3 w/ a 2x2 block inside it",  # a 3 x 3 ring has one free cell inside
        k.honest(k.anything),
    ),
    _c(
        "bad-16",
        BAD,
        "Build a staircase of three steps going up to the left and going up to the right.",
        k.honest(one(k.staircase(3))),
    ),
    _c(
        "bad-17",
        BAD,
        "Bitte einen Turm aus drei Würfeln bauen, danke!",
        k.honest(one(T(3))),
    ),
    _c(
        "bad-18",
        BAD,
        "Test piece: tower of 3 at X 1200 Y 300.",  # x 1.2 m is off the table
        k.honest(one(T(3))),
    ),
    _c(
        "bad-19",
        BAD,
        "A little bench with legs half a cube high.",
        k.honest(k.anything),
    ),
]
