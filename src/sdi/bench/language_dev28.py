"""A twenty-eighth held-out set for the language front end (dev28): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev27` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is deliberately mainstream: about
80 % of the commands are what an operator at a robot cell really types — one or two
structures with a size, a place, one relation or a two-step sequence, in plain, varied
English (build / make / put / place / stack / set up / lay out / give me / I need / can you /
let's; the place first or the size last; sizes as words, digits, "3x2", cm, mm and metres;
articles sometimes dropped) — and they come from five kinds of people, none of them used by
an earlier set:

* a day-shift operator entering the next job at the cell's HMI between batches: "Next job:",
  "Batch 31 done", "Reset done", "Cycle count 2150". Batch, cycle and bin numbers are filler,
  never a size; "Cancel last. Don't build anything." admits only a refusal; a bare "Next
  job:" is bad input;
* a production planner whose job lines come from a spreadsheet or an MES export and are
  pasted as text: "Job 3 – Tower – Qty 2 – H 4", "Item | Qty | H | Loc", "Op 10 / Op 20",
  "rev B". "Qty N" is N separate structures of that kind; "H", "L" and "W" are height,
  length and width in cubes unless a unit (mm, m) is given in the field or its header; "X"
  and "Y" (mm) are the footprint centre in the cell frame, held to 2 cm; "Loc" is a named
  region; a later revision or operation replaces the one it amends; order numbers, dates,
  priorities and cost centres are filler. A field holding "#N/A", a negative quantity, a
  length past the cell or a position off the table is bad input;
* an experienced colleague telling a trainee over the shoulder what to type and why, the
  words as the trainee typed them ("ok so Mike says …", "he says", "she says count the
  outside"). Only what is to be built is checked; the reasons ("so the gripper fits", "the
  camera is there", "so it's balanced") are filler unless they name a place or a gap. A
  sentence in Spanish or German is bad input (a refusal, or the reading with a note);
* a customer-service person relaying what a customer asked for: "The customer would like…",
  "they want", "client says", "called back and changed it". The relaying and the small talk
  are filler; the last change the customer made wins. A question that is not a build (when
  an order ships), a sphere, and colours the cell does not stock are bad input;
* an operator who thinks aloud and hedges: "hmm", "maybe", "I guess", "roughly", "not sure
  but", "I think". The hedge does not make the size vague: "roughly 25 cm" is still five
  cubes, "maybe 4… yeah, 4" is four, and "six, hmm no, make it 4" is four (the last figure
  wins). A cylinder, a staircase of zero steps and legs of one and a half cubes are bad input.

About 80 % ordinary and 20 % harder: three or four structures, references ("on it", "the right
one", "the left one", "there"), distributive phrases ("a tower of two on each corner",
"each a cube away"), comparisons ("three times that height", "exactly as tall as the
staircase"), removals ("take one cube off each end of the top row", "take the top cube off",
"remove the right one"), corrections in the same message and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) through the shared checks and accepts every reasonable reading of vague
wording, and nothing else. Conventions (mostly dev27's):

* "next to", "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by column heights),
  and so may a tower "placed to the right of" another; "right next to it" is at most 10 cm
  clear, or touching; "a bit of space", "not touching", "with some space", "a gap" and "Qty
  N" mean separate structures ("a bit of space" also no more than 25 cm clear); "a gap of N
  cubes" / "N cm gap" is the clear gap ± 1.5 cm; "2x2x4" with no header naming the columns
  is either 2 × 2 four high or 2 × 4 two high;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none is
  said; "lined up with the middle of it" also lines the centres up (± 3 cm); a tower "in
  front of" a wall may stand against it as one structure where the command allows touching;
* "between" is the shared `between_` on three separate structures, or the three set
  against one another in one line as one structure;
* a bridge's top is a beam (the shared `bridge`, overall height one more than the posts)
  where the command names a beam, and a beam or a bar of cubes where it does not; "cubes
  only (no beam)" is a bar of cubes; a table is four separate legs under one connected top
  of beams or of cubes, and "top of beams" is the cell's beam roof (the shared `beam_roof`);
* a ring's stated size is its outside ("she says count the outside"); "in the middle of" or
  "centred inside" a ring is inside its empty interior with the centres within 2 cm; "on
  top … in the middle" / "centred" on a slab or block is centred within 2 cm (so a part set
  on a corner cell of an even-sided base does not pass);
* a staircase's width is free unless given, and so is the way it climbs unless said ("going
  up to the right" climbs towards -y); a pyramid's step and base are free unless given; "a
  pyramid of 4 levels with the top cube taken off" is any three-level pyramid with more than
  one part on top;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "not too close to the robot" is outside the front region; "along the <side> edge" is
  every part within 20 cm of that edge of the workspace (front edge x = 0.20, back 0.80,
  left y = 0.55, right 0.05) and running along it; "the left half" is every part at y ≥
  0.30, "the back half" every part at x ≥ 0.50; "the centre line" / "in the middle
  left-right" is y = 0.30 ± 4 cm (± 3 cm with "exactly"); "roughly the middle of the right
  side" is the right region with x within 8 cm of 0.45; a stated X / Y is the footprint
  centre ± 2 cm;
* "tall" with no figure is at least five cubes high; "low, no higher than 2 cubes" is at
  most two; "max N cubes" counts cubes (beams not counted).

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

_TALL = 5  # cubes: "tall" with no figure
_EDGE = 0.20  # m: "along the <side> edge" is every part within this of that edge
_X0, _X1 = bx.WORKSPACE[0]
_Y0, _Y1 = bx.WORKSPACE[1]


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev28-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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
    or a row of cubes (with a row of cubes the shared `bridge` finds no top piece, since the
    bar's middle cubes rest on nothing)."""

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
    than the posts (so taller posts under a bar of cubes do not pass); the posts `mouth` cubes
    apart clear when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _span(posts: int) -> k.Check:
    """A bridge with no beam named: two posts `posts` high with a beam (the shared `bridge`,
    one layer above the posts) or a bar of cubes across the tops."""
    beam = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return k.any_of(beam, _bar_on_posts(posts, posts))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected top that is the topmost level and rests on every leg (a top of beams or of
    cubes, whose middle cubes rest on nothing)."""

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


def _col_beside(h: int, rest: k.Check, side: str) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table, set against the rest,
    which passes `rest`; the column lies to `side` of the rest."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col in bx.columns(bs):
            if len(col) != h or k.tower(h)(col) is not None or col[0].lo[2] > bx.TOL:
                continue
            others = [b for b in bs if all(b is not c for c in col)]
            if not others:
                continue
            r = rest(others)
            if r is None and bx.side_of(col, others) != side:
                r = f"the {h}-column is {bx.side_of(col, others)} of the rest, want {side}"
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


def _facing_mid(tol: float = 0.03) -> k.Rel:
    """A stands square in front of (or behind, or beside) the middle of B: their centres line
    up across the direction from B to A, ± tol."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (ax, ay), (bx0, by0) = bx.centre(a), bx.centre(b)
        off = abs(ay - by0) if bx.side_of(a, b) in (_F, _B) else abs(ax - bx0)
        return None if off <= tol else f"{off:.3f} m off the middle"

    return rel


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
    """A pyramid whose top level is more than one part (its top cube left off)."""
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


def _along_edge(side: str, depth: float = _EDGE) -> k.Check:
    """Every part within `depth` (m) of the workspace's `side` edge, and the structure running
    along that edge (its longer side parallel to it)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        (x0, y0, _), (x1, y1, _) = bx.bounds(bs)
        far = {
            _F: x1 - _X0,
            _B: _X1 - x0,
            _L: _Y1 - y0,
            _R: y1 - _Y0,
        }[side]
        if far > depth + bx.TOL:
            return f"reaches {far:.3f} m from the {side} edge, want ≤ {depth}"
        return k.runs("y" if side in (_F, _B) else "x")(bs)

    return f


def _border_only(bs: k.Boxes) -> k.Reason:
    """Every part stands on a border cell of the footprint (a ring, open or closed)."""
    if not bs:
        return "no parts"
    fx, fy = bx.footprint_cubes(bs)
    inner = [(i, j) for i, j in bx.cells(bs) if 0 < i < fx - 1 and 0 < j < fy - 1]
    return None if not inner else f"{len(inner)} cell(s) inside the border filled"


def _min_y(y: float) -> k.Check:
    """Every part lies at y ≥ `y` (m): in the left part of the table."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _next_to(a: k.Check, b: k.Check, a_h: int, b_h: int, max_gap: float = 0.25) -> k.Pred:
    """Two towers "next to" each other: A (passing `a`) clear of B (passing `b`) and no more
    than `max_gap` away, or the two set against each other as one structure of columns
    `a_h` and `b_h` high."""
    return k.any_of(
        k.pair(a, b, k.within(max_gap)),
        k.one(k.cell_heights(a_h, b_h)),
    )


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_PYR2 = k.pyramid(2)
_PYR3 = k.pyramid(3)


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Next job: 4-high tower, and a 2-high one right next to it on its left.",
        k.any_of(
            k.pair(T(2), T(4), k.all_rels(k.within(0.10), k.on_side(_L))),
            one(_col_beside(2, T(4), _L)),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "Job 7 – Pyramid – 3 levels – plus a 2-cube tower behind it, not touching",
        k.pair(T(2), _PYR3, k.on_side(_B)),
    ),
    _c(
        "rel-03",
        REL,
        "ok Sam says: put a single cube on top of a 2x2 block that's two high, cube goes in the "
        "middle so it's balanced",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.top_centred(0.02), k.levels(4, 4, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "The customer would like a bridge made of two towers of three cubes with a beam across "
        "the top.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-05",
        REL,
        "hmm, a ring, maybe 5 by 5, one high, and I guess a tower of 3 standing in the middle "
        "of it",
        k.pair(_PEN5, T(3), k.centred_in(0.02)),
    ),
    _c(
        "rel-06",
        REL,
        "Set up a wall 6 long and 2 high along the back, then a row of 4 in front of it with a "
        "gap.",
        k.pair(k.row(4), k.all_of(k.wall(6, 2), k.runs("y"), reg("back")), k.on_side(_F)),
    ),
    _c(
        "rel-07",
        REL,
        "Line 2: Tower, H=5 | Line 3: Tower, H=2, placed to the right of line 2",
        k.any_of(k.pair(T(2), T(5), k.on_side(_R)), one(_col_beside(2, T(5), _R))),
    ),
    _c(
        "rel-08",
        REL,
        "build a tower of four, then a staircase of three steps to its left, leave one cube gap "
        "so the gripper fits between",
        k.pair(k.staircase(3), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "rel-09",
        REL,
        "They want a tall tower of six in between two little towers of two.",
        k.any_of(
            k.between_(T(6), T(2)),
            one(k.plan_heights("262")),
        ),
    ),
    _c(
        "rel-10",
        REL,
        "I think a staircase, 4 steps, and then, not sure, maybe a cube on the top step? yeah, "
        "let's do that",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "rel-11",
        REL,
        "Lay out a 3x3 slab, one layer, with a tower of two on each corner of it.",
        one(k.plan_heights("313", "111", "313")),
    ),
    _c(
        "rel-12",
        REL,
        "Job 12 – Table – Legs: 4 – Leg H: 3 – Top: beams",
        one(k.beam_roof(4, 3)),
    ),
    _c(
        "rel-13",
        REL,
        "two walls, 4 long and 2 high, parallel to each other with a gap of 2 cubes — he says "
        "that's the corridor for the AGV test",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-14",
        REL,
        "Customer wants a small pyramid, two levels, sitting on top of a 4x4 slab one cube thick.",
        one(k.on_top(_PYR2, k.block(4, 4, 1))),
    ),
    _c(
        "rel-15",
        REL,
        "maybe two towers, both 4 high, roughly a cube apart, and a beam across them I guess",
        one(_beam_bridge(4, 1)),
    ),
    _c(
        "rel-16",
        REL,
        "Row of 5 at the front, then tower of 3 behind it, lined up with the middle of the row",
        k.any_of(
            k.pair(
                T(3),
                k.all_of(k.row(5), reg("front")),
                k.all_rels(k.on_side(_B), _facing_mid()),
            ),
            one(k.plan_heights("11111", "..3.."), reg("front")),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Item: ring | Size: 4x4 | H: 2 | Contents: 1 cube, centred inside",
        k.pair(k.all_of(k.ring_of(2, (2, 2)), k.dims(4, 4)), T(1), k.centred_in(0.02)),
    ),
    _c(
        "rel-18",
        REL,
        "put the 2-high tower in front of the wall, wall is 5 long 3 high, tower can touch the "
        "wall that's fine",
        k.any_of(
            k.pair(T(2), k.wall(5, 3), k.on_side(_F)),
            one(_col_beside(2, k.wall(5, 3), _F)),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "The client is after two pyramids of two levels side by side, one cube between them.",
        k.pair(_PYR2, _PYR2, k.gap_of(1)),
    ),
    _c(
        "rel-20",
        REL,
        "a tower of 5 at the back left and, hmm, a row of 3 to the right of it with a bit of "
        "space between, I suppose",
        k.pair(
            k.row(3),
            k.all_of(T(5), reg("back left")),
            k.all_rels(k.on_side(_R), k.within(0.25)),
        ),
    ),
    _c(
        "rel-21",
        REL,
        "Tower of 4 in the centre with a tower of 2 on its left and another tower of 2 on its "
        "right, each a cube away.",
        k.in_order("y", T(2), k.all_of(T(4), reg("centre")), T(2), gaps=(1,)),
    ),
    _c(
        "rel-22",
        REL,
        "Client says: towers of 3 and 6, 2 cubes apart, and the shorter one has to be in front.",
        k.pair(T(3), T(6), k.gap_of(2, _F)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Tower of 5 back right. Then the same again back left.",
        k.structures(k.all_of(T(5), reg("back right")), k.all_of(T(5), reg("back left"))),
    ),
    _c(
        "seq-02",
        SEQ,
        "Step 1: slab 3x3, 1 layer. Step 2: 2x2 on top of it. Step 3: single cube on top of that.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "build the wall first, 6 long 2 high, then take one cube off each end of the top row, "
        "she says that makes it look stepped",
        one(k.profile(1, 2, 2, 2, 2, 1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "The customer ordered a tower of 7, then called back and changed it to 5.",
        one(T(5)),
    ),
    _c(
        "seq-05",
        SEQ,
        "ok so first a row of 4... then I guess another row of 4 right on top of it? yeah",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "Make a staircase of 3 steps, then extend it to 5 steps.",
        one(k.staircase(5)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Op 10: block 2x2, 2 high, centre. Op 20: scrap op 10, build a row of 6 there instead.",
        one(k.row(6), reg("centre")),
    ),
    _c(
        "seq-08",
        SEQ,
        "stack a tower of 3, now add 2 more cubes on it — Jo says so it matches the other cell",
        one(T(5)),
    ),
    _c(
        "seq-09",
        SEQ,
        "They'd like a pyramid of four levels, but they also said to take the top cube off it "
        "afterwards.",
        one(_PYR3, _flat_topped_pyramid),
    ),
    _c(
        "seq-10",
        SEQ,
        "tower of 6, hmm no, too tall, let's make it 4",
        one(T(4)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Put two towers of 3 a cube apart. After that, beam on top across both.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Row 1: Wall, L=5, H=2, Loc front. Row 2: same wall, Loc back.",
        k.structures(
            k.all_of(k.wall(5, 2), reg("front")),
            k.all_of(k.wall(5, 2), reg("back")),
        ),
    ),
    _c(
        "seq-13",
        SEQ,
        "build a 4x4 ring one high. then he says add a second layer on the ring",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "The client wants a 2x3 slab, one layer, on the left first, and then a tower of 4 over "
        "on the right side of the table.",
        k.structures(
            k.all_of(k.block(2, 3, 1), reg("left")),
            k.all_of(T(4), reg("right")),
        ),
    ),
    _c(
        "seq-15",
        SEQ,
        "row of 5? no wait, 4 I think. yes 4. along the front",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-16",
        SEQ,
        "Three towers of 2 in a line, one cube apart. Then remove the right one.",
        k.pair(T(2), T(2), k.gap_of(1)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Job 4 rev A: Tower H 3. Job 4 rev B: Tower H 6 (supersedes rev A)",
        one(T(6)),
    ),
    _c(
        "seq-18",
        SEQ,
        "first a pyramid of 3 levels, then a tower of 3 to its right with a one-cube gap",
        k.pair(T(3), _PYR3, k.gap_of(1, _R)),
    ),
    _c(
        "seq-19",
        SEQ,
        "They asked for a 3x3 block two high, and then on reflection they'd like one more layer "
        "on it.",
        one(k.block(3, 3, 3)),
    ),
    _c(
        "seq-20",
        SEQ,
        "tower of 4 on the left, tower of 4 on the right, then, hmm, I guess take 2 off the left "
        "one",
        k.structures(k.all_of(T(2), reg("left")), k.all_of(T(4), reg("right"))),
    ),
    _c(
        "seq-21",
        SEQ,
        "Lay out a row of 8, then remove 3 cubes from one end.",
        one(k.row(5)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Next: 4 towers of 2 in a row, 1 cube gap between them",
        k.in_line(4, T(2), 1),
    ),
    _c("num-02", NUM, "Item: Tower | Qty: 3 | H: 3", k.each(3, T(3))),
    _c(
        "num-03",
        NUM,
        "three towers, heights 1 2 3, from left to right, a gap of one cube each",
        k.in_order("y", T(1), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "num-04",
        NUM,
        "The customer would like ten cubes laid out as a single row.",
        one(k.row(10)),
    ),
    _c(
        "num-05",
        NUM,
        "hmm, maybe three... no, four steps on the staircase. four.",
        one(k.staircase(4)),
    ),
    _c("num-06", NUM, "Slab 2x5, 1 layer", one(k.block(2, 5, 1))),
    _c(
        "num-07",
        NUM,
        "Pyramid | Levels: 4 | Base: 4x4",
        one(k.pyramid(4), k.base(4, 4)),
    ),
    _c(
        "num-08",
        NUM,
        "make two rows of six, parallel, with one cube between them",
        k.pair(k.row(6), k.row(6), k.parallel_gap(1)),
    ),
    _c(
        "num-09",
        NUM,
        "They want five single cubes spread out in a line, a cube apart.",
        k.in_line(5, T(1), 1),
    ),
    _c("num-10", NUM, "a tower of... I guess 7? seven's fine", one(T(7))),
    _c("num-11", NUM, "Give me a wall 7 long, 4 high", one(k.wall(7, 4))),
    _c(
        "num-12",
        NUM,
        "Qty 2 | Bridge | Post H: 2 | Beam: 1 each",
        k.each(2, _beam_bridge(2)),
    ),
    _c(
        "num-13",
        NUM,
        "put a tower of 2, and another one three times that height beside it",
        _next_to(T(6), T(2), 6, 2),
    ),
    _c(
        "num-14",
        NUM,
        "The client would like a staircase with seven steps.",
        one(k.staircase(7)),
    ),
    _c(
        "num-15",
        NUM,
        "roughly a 3 by 3 by 3 block, I mean made out of cubes",
        one(k.block(3, 3, 3)),
    ),
    _c(
        "num-16",
        NUM,
        "Towers of 1, 2, 3, 4 and 5, front to back, one cube gap between each.",
        k.in_order("x", T(1), T(2), T(3), T(4), T(5), gaps=(1,)),
    ),
    _c(
        "num-17",
        NUM,
        "Job 9: 2 x Pyramid (2 levels), 2 x Tower (H 3), all separate",
        k.structures(_PYR2, _PYR2, T(3), T(3)),
    ),
    _c(
        "num-18",
        NUM,
        "a ring 6 by 6, 1 high — she says count the outside",
        one(k.ring_of(1, (4, 4)), k.dims(6, 6)),
    ),
    _c(
        "num-19",
        NUM,
        "The client is asking for a staircase of three steps and, not touching it, a tower "
        "exactly as tall as the staircase.",
        k.structures(T(3), k.staircase(3)),
    ),
    _c(
        "num-20",
        NUM,
        "I'd go with two... no, three towers of five, with some space between them",
        k.each(3, T(5)),
    ),
    _c("num-21", NUM, "I need a block 4 x 2, 3 high please", one(k.block(4, 2, 3))),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Tower 20 cm, front right", one(T(4), reg("front right"))),
    _c("dim-02", DIM, "Wall | L (mm): 400 | H (mm): 100", one(k.wall(8, 2))),
    _c(
        "dim-03",
        DIM,
        "slab 15 by 20 centimetres, one layer — Kev says always give it in cm",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "dim-04",
        DIM,
        "They'd like a tower about 35 centimetres tall.",
        one(T(7)),
    ),
    _c(
        "dim-05",
        DIM,
        "a tower, roughly 0.25 m tall I think, yeah",
        one(T(5)),
    ),
    _c("dim-06", DIM, "Row 300mm, back", one(k.row(6), reg("back"))),
    _c("dim-07", DIM, "Block | 100 x 150 x 100 mm (L x W x H)", one(k.block(2, 3, 2))),
    _c(
        "dim-08",
        DIM,
        "make the staircase 20 cm tall, 5 cm per step",
        one(k.staircase(4)),
    ),
    _c(
        "dim-09",
        DIM,
        "The client wants a bridge with 15 cm pillars and a beam laid across them.",
        one(_beam_bridge(3)),
    ),
    _c(
        "dim-10",
        DIM,
        "a ring roughly 25 cm across on the outside, 5 cm high I guess",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5)),
    ),
    _c("dim-11", DIM, "Wall 0.5 m long, 0.15 m high", one(k.wall(10, 3))),
    _c("dim-12", DIM, "Slab | 200 x 200 mm | Layers: 2", one(k.block(4, 4, 2))),
    _c(
        "dim-13",
        DIM,
        "two towers 10 cm tall with a 10 cm gap between them",
        k.pair(T(2), T(2), k.gap_of(2)),
    ),
    _c(
        "dim-14",
        DIM,
        "The customer wants a pyramid on a base 20 cm square.",
        one(k.pyramid(), k.base(4, 4)),
    ),
    _c(
        "dim-15",
        DIM,
        "an L shape, hmm, both arms about 15 cm long, one cube high",
        one(k.shape_letter("L"), k.dims(3, 3), k.height(1)),
    ),
    _c("dim-16", DIM, "Stack a tower 45cm high", one(T(9))),
    _c("dim-17", DIM, "Row | Length: 0.35 m", one(k.row(7))),
    _c(
        "dim-18",
        DIM,
        "a table, legs 5 cm high, top 15 by 15 cm, write it like that he says",
        one(_roofed(4, 1), k.dims(3, 3)),
    ),
    _c(
        "dim-19",
        DIM,
        "They want a block 10 by 10 by 30 cm, standing upright.",
        one(k.block(2, 2, 6)),
    ),
    _c(
        "dim-20",
        DIM,
        "slab, maybe 25 by 10 cm? one layer, yeah",
        one(k.block(5, 2, 1)),
    ),
    _c("dim-21", DIM, "Can you build a wall 20cm long and 20cm high", one(k.wall(4, 4))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Tower of 6, not at the front",
        one(T(6), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-02",
        NEG,
        "Pyramid, 3 levels | Beams: NO",
        one(_PYR3, k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "wall 5 by 2 but not along the back, the camera is mounted there",
        one(k.wall(5, 2), k.not_(reg("back"), "at the back")),
    ),
    _c(
        "neg-04",
        NEG,
        "The customer doesn't want the two towers touching: two towers of 4.",
        k.each(2, T(4)),
    ),
    _c(
        "neg-05",
        NEG,
        "a row of six, not left-right I think, more front to back",
        one(k.row(6), k.runs("x")),
    ),
    _c(
        "neg-06",
        NEG,
        "Block 3x3x1 w/o the middle cube",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-07",
        NEG,
        "Bridge | Post H: 2 | Top: cubes only (no beam)",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-08",
        NEG,
        "two towers of 3, don't put them in the middle — one on the left, one on the right",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "neg-09",
        NEG,
        "Client says no beams at all: a table with 4 legs, 2 high.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-10",
        NEG,
        "staircase, 3 steps, hmm, just not going up towards the robot",
        one(k.staircase(3), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-11",
        NEG,
        "Ring 4x4, 1 high, leave out one cube on the left side",
        one(
            k.dims(4, 4),
            k.height(1),
            k.parts(11),
            _border_only,
            _missing_on(_L),
        ),
    ),
    _c(
        "neg-12",
        NEG,
        "Tower | H: 5 | Loc: anywhere except back right",
        one(T(5), k.not_(reg("back right"), "at the back right")),
    ),
    _c(
        "neg-13",
        NEG,
        "just a 2x2 block, 2 high, nothing else on the table this time",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "neg-14",
        NEG,
        "They'd like a pyramid of 3 levels, and they specifically don't want it on the left.",
        one(_PYR3, k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-15",
        NEG,
        "a tower of 4, I guess not too close to the robot",
        one(T(4), k.not_(reg("front"), "close to the robot")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "Towr of 4 bakc left", one(T(4), reg("back left"))),
    _c("typo-02", TYP, "Qyt 2 | Towre | H 3", k.each(2, T(3))),
    _c("typo-03", TYP, "pyarmid 3 lvls in the centre", one(_PYR3, reg("centre"))),
    _c(
        "typo-04",
        TYP,
        "The cusotmer would like a staricase of 5 setps.",
        one(k.staircase(5)),
    ),
    _c("typo-05", TYP, "hmm mabye a wal 6 long, 2 hihg?", one(k.wall(6, 2))),
    _c("typo-06", TYP, "Sabl 3x4 1 layr", one(k.block(3, 4, 1))),
    _c(
        "typo-07",
        TYP,
        "Job 5 – Brdige – legs 3 – beam acros top",
        one(_beam_bridge(3)),
    ),
    _c(
        "typo-08",
        TYP,
        "two towrs of 5 wiht a gap of one cueb",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c("typo-09", TYP, "they wnat a rign 5x5 one hihg", one(_PEN5)),
    _c(
        "typo-10",
        TYP,
        "I thnik a row of 7, alng the front",
        one(k.row(7), k.runs("y"), reg("front")),
    ),
    _c(
        "typo-11",
        TYP,
        "Towre 3 ontop of 2x2 slab, centred",
        one(k.on_top(T(3), k.block(2, 2, 1)), k.centred(0.02), k.levels(4, 1, 1, 1)),
    ),
    _c(
        "typo-12",
        TYP,
        "Itme: block | 2x2x4 | Qty 1",
        one(k.any_of(k.block(2, 2, 4), k.block(2, 4, 2))),
    ),
    _c(
        "typo-13",
        TYP,
        "put a tower of 2 inf ront of the wall (wall's 4 long 2 hgih), touching is ok",
        k.any_of(
            k.pair(T(2), k.wall(4, 2), k.on_side(_F)),
            one(_col_beside(2, k.wall(4, 2), _F)),
        ),
    ),
    _c(
        "typo-14",
        TYP,
        "client wnats 3 towers of 3 in a line, cube gap",
        k.in_line(3, T(3), 1),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Back right, tower, 6 high.", one(T(6), reg("back right"))),
    _c("wo-02", WO, "H 3 | L 5 | Item: Wall", one(k.wall(5, 3))),
    _c(
        "wo-03",
        WO,
        "on the left side of the table — that's where the 3x3 slab goes, one layer",
        one(k.block(3, 3, 1), reg("left")),
    ),
    _c(
        "wo-04",
        WO,
        "Four levels high is the pyramid the customer wants, in the centre.",
        one(k.pyramid(4), reg("centre")),
    ),
    _c("wo-05", WO, "two high, five long, hmm, a wall I guess", one(k.wall(5, 2))),
    _c(
        "wo-06",
        WO,
        "To the right of a 3-tower: 5-tower, 1 cube gap",
        k.pair(T(5), T(3), k.gap_of(1, _R)),
    ),
    _c("wo-07", WO, "Loc: front left / Item: row / Qty cubes: 5", one(k.row(5), reg("front left"))),
    _c(
        "wo-08",
        WO,
        "3 steps, going up to the right, staircase — right is minus y he says",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "wo-09",
        WO,
        "Behind the pyramid of three levels, the customer would like a tower of four.",
        k.pair(T(4), _PYR3, k.on_side(_B)),
    ),
    _c(
        "wo-10",
        WO,
        "on top, a single cube, of a 3x3 slab I guess, in the middle",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(0.02), k.levels(9, 1)),
    ),
    _c(
        "wo-11",
        WO,
        "Across the back: wall, 8 long, 2 high",
        one(k.wall(8, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "wo-12",
        WO,
        "4 high, 2x2 — Block — Loc back left",
        one(k.block(2, 2, 4), reg("back left")),
    ),
    _c(
        "wo-13",
        WO,
        "with a beam on top, two towers of 2, one cube apart",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "wo-14",
        WO,
        "In the front right corner, they'd like a tower of three.",
        one(T(3), reg("front right")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Batch 31 finished, bin emptied, guards closed. Next job: tower of 4, centre.",
        one(T(4), reg("centre")),
    ),
    _c(
        "fil-02",
        FIL,
        "Shift plan wk 14, line 2, cost centre 4410. Job 1 – Row – Qty 1 – L 6",
        one(k.row(6)),
    ),
    _c(
        "fil-03",
        FIL,
        "ok Mike says always check the gripper first, fine, done. now: staircase of 4 climbing "
        "to the back",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "fil-04",
        FIL,
        "Hi team, I've had Mrs Okafor from Brightline on the phone for twenty minutes, lovely "
        "lady. The customer would like a pyramid of two levels. Thanks!",
        one(_PYR2),
    ),
    _c(
        "fil-05",
        FIL,
        "so, um, I was thinking about it over lunch and, well, I guess a wall 4 long and 3 high "
        "would do",
        one(k.wall(4, 3)),
    ),
    _c(
        "fil-06",
        FIL,
        "OK. Reset done. Cycle count 2150. Slab 4x4, one layer, back.",
        one(k.block(4, 4, 1), reg("back")),
    ),
    _c(
        "fil-07",
        FIL,
        "MES export 14/03 08:00 – Order 77812 – Priority 2 – Item: Tower – Qty: 1 – Height: 6 "
        "cubes",
        one(T(6)),
    ),
    _c(
        "fil-08",
        FIL,
        "right, Ana says rule one is never trust the default height, so: tower, 3 cubes, front "
        "left",
        one(T(3), reg("front left")),
    ),
    _c(
        "fil-09",
        FIL,
        "Client's very particular, they've been with us for 12 years. They want a 2x2 block, 3 "
        "high.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-10",
        FIL,
        "hmm hmm. let me think. ok. yes. a ring, 4 by 4, one high",
        one(_PEN4),
    ),
    _c(
        "fil-11",
        FIL,
        "Between batches, quick one: bridge, posts of 2, beam on top",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-12",
        FIL,
        "Note: material already staged at cell 3. Job 2 – Staircase – Steps: 5 – Loc: right",
        one(k.staircase(5), reg("right")),
    ),
    _c(
        "fil-13",
        FIL,
        "he's explaining the why so I learn it, the beam is heavy so it goes on last: two "
        "towers of 3 with a beam across",
        one(_beam_bridge(3)),
    ),
    _c(
        "fil-14",
        FIL,
        "Apologies for the delay on this one, our system was down all morning. The customer has "
        "asked for two towers of 5, a cube apart.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "fil-15",
        FIL,
        "not sure this is the best use of the afternoon but whatever, let's do a row of three on "
        "the left",
        one(k.row(3), reg("left")),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "Place tower 3, front right corner", one(T(3), reg("front right"))),
    _c(
        "reg-02",
        REG,
        "Tower | H: 4 | X (mm): 500 | Y (mm): 400",
        one(T(4), k.near(0.50, 0.40, 0.02)),
    ),
    _c(
        "reg-03",
        REG,
        "put the 2x2 slab in the middle of the table, calibration jobs always go in the middle",
        one(k.block(2, 2, 1), reg("centre")),
    ),
    _c(
        "reg-04",
        REG,
        "The customer wants their pyramid, 3 levels, at the back of the table.",
        one(_PYR3, reg("back")),
    ),
    _c(
        "reg-05",
        REG,
        "a wall, 5 long 2 high, I guess along the left edge?",
        one(k.wall(5, 2), _along_edge(_L)),
    ),
    _c(
        "reg-06",
        REG,
        "Row of 4 along the front edge",
        one(k.row(4), _along_edge(_F)),
    ),
    _c(
        "reg-07",
        REG,
        "Block 3x3x2 | Loc: back left corner",
        one(k.block(3, 3, 2), reg("back left")),
    ),
    _c(
        "reg-08",
        REG,
        "tower of 5 in the centre of the table, exactly on the centre line",
        one(T(5), reg("centre"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-09",
        REG,
        "They'd like a staircase of 3 in the front left corner.",
        one(k.staircase(3), reg("front left")),
    ),
    _c(
        "reg-10",
        REG,
        "hmm, tower of 2 somewhere on the right, roughly the middle of the right side",
        one(T(2), reg("right"), k.near(x=0.45, tol=0.08)),
    ),
    _c(
        "reg-11",
        REG,
        "2 towers of 4: back left + back right",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "Slab 2x4, 1 layer, centre at X 300 Y 300",
        one(k.block(2, 4, 1), k.near(0.30, 0.30, 0.02)),
    ),
    _c(
        "reg-13",
        REG,
        "ring 5 by 5, one high, back right — keep the front clear for the operator",
        one(_PEN5, reg("back right")),
    ),
    _c(
        "reg-14",
        REG,
        "They want a wall of 6 by 2 right across the middle of the table, left to right.",
        one(k.wall(6, 2), k.runs("y"), reg("centre")),
    ),
    _c(
        "reg-15",
        REG,
        "I guess two towers of three, one at the front and one at the back, both in the middle "
        "left-right",
        k.structures(
            k.all_of(T(3), reg("front"), k.near(y=0.30, tol=0.04)),
            k.all_of(T(3), reg("back"), k.near(y=0.30, tol=0.04)),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Next job: operator's choice, max 8 cubes",
        k.all_of(k.anything, k.layout(_cubes(hi=8))),
    ),
    _c(
        "open-02",
        OPEN,
        "Job 6 – Item: any – Qty: 1 – Note: demo piece, cell's discretion",
        k.all_of(k.anything, _count(1)),
    ),
    _c(
        "open-03",
        OPEN,
        "now he says type anything you want so you can see how it plans it",
        k.anything,
    ),
    _c(
        "open-04",
        OPEN,
        "The customer isn't fussy, they'd just like something with an arch or a bridge in it.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-05",
        OPEN,
        "hmm, I don't know, something low I guess, no higher than 2 cubes",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c(
        "open-06",
        OPEN,
        "Free build, left half of the table only",
        k.all_of(k.anything, k.layout(_min_y(0.30))),
    ),
    _c(
        "open-07",
        OPEN,
        "Job 11 – Item: TBD by cell – Max H 100 mm – Max footprint 150 x 150 mm",
        k.all_of(k.anything, k.layout(k.all_of(k.low(2), _fits(3, 3)))),
    ),
    _c(
        "open-08",
        OPEN,
        "build any three separate things, your pick, she wants me to see how it spaces them",
        k.all_of(k.anything, _count(3)),
    ),
    _c(
        "open-09",
        OPEN,
        "They'd like something tall, that's all they said.",
        k.all_of(k.anything, k.some(k.height(lo=_TALL))),
    ),
    _c(
        "open-10",
        OPEN,
        "something with steps maybe? any size I guess",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-11",
        OPEN,
        "Any structure you like, cubes only",
        k.all_of(k.anything, k.layout(k.only_cubes)),
    ),
    _c(
        "open-12",
        OPEN,
        "Customer says surprise us, but keep it on the back half of the table.",
        k.all_of(k.anything, k.layout(k.min_x(0.50))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Next job:", k.honest(k.anything)),
    _c(
        "bad-02",
        BAD,
        "Job 8 – Tower – Qty 1 – Height: #N/A",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-03", BAD, "asdf jkl; test test", k.honest()),
    _c(
        "bad-04",
        BAD,
        "The customer would like a sphere, about 15 cm across.",
        k.honest(k.anything),
    ),
    _c(
        "bad-05",
        BAD,
        "hmm, a wall 3 long that's longer than the 5-long row beside it, I guess",
        k.honest(k.anything),
    ),
    _c(
        "bad-06",
        BAD,
        "Next job: tower, 14 high, for the display shelf",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-07",
        BAD,
        "Job 10 – Row – Qty 1 – Length: 1500 mm",  # 30 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-08",
        BAD,
        "construye una torre de cuatro cubos, por favor",
        k.honest(one(T(4))),
    ),
    _c(
        "bad-09",
        BAD,
        "The customer is asking when their last order will ship, can you check?",
        k.honest(),
    ),
    _c(
        "bad-10",
        BAD,
        "hmm, maybe a cylinder? like a round tower, 10 cm across",
        k.honest(k.anything),
    ),
    _c(
        "bad-11",
        BAD,
        "Ring 2x2, 1 high",  # no room for an interior
        k.honest(k.anything),
    ),
    _c("bad-12", BAD, "Job 13 – Tower – Qty: -2 – H: 3", k.honest(k.anything)),
    _c(
        "bad-13",
        BAD,
        "baue bitte eine Mauer, fünf lang und zwei hoch",
        k.honest(one(k.wall(5, 2))),
    ),
    _c(
        "bad-14",
        BAD,
        "The customer wants a tower of 4 built in gold-coloured cubes.",  # no colours stocked
        k.honest(one(T(4))),
    ),
    _c(
        "bad-15",
        BAD,
        "a staircase, I guess, with zero steps?",
        k.honest(k.anything),
    ),
    _c("bad-16", BAD, "Cancel last. Don't build anything.", k.honest()),
    _c(
        "bad-17",
        BAD,
        "Job 14 – Slab – 3x3 – Layers: 2 – X: 1200 mm",  # off the table (x ≤ 0.80)
        k.honest(one(k.block(3, 3, 2))),
    ),
    _c(
        "bad-18",
        BAD,
        "Client wants a tower 3 cubes high that is also taller than half a metre.",
        k.honest(k.anything),
    ),
    _c(
        "bad-19",
        BAD,
        "put a tower of three on top of the old one, the one from this morning",
        k.honest(k.anything),
    ),
    _c(
        "bad-20",
        BAD,
        "hmm, a bridge maybe, with legs of 1.5 cubes?",
        k.honest(one(k.any_of(_span(1), _span(2)))),
    ),
]
