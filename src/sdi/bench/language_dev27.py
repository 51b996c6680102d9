"""A twenty-seventh held-out set for the language front end (dev27): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev26` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is meant to measure an ordinary
working day at the cell, so about 80 % of the commands are ordinary — one or two structures
with a size, a place, one relation or a two-step sequence, in plain but varied English — and
they come from five kinds of people, none of them used by an earlier set:

* a cell operator typing on the tablet mounted at the station between cycles: short entries
  with the first letter capitalised by the keyboard, "pls", "thx", "u", "w/", "@", sizes as
  "2x3", and the slips a touch keyboard's autocorrect makes — real words in place of the
  meant ones ("towel" for tower, "bean" for beam, "if" for of, "slav" for slab). A slip is
  read as the word the operator meant; a half-sent entry ("Tower of"), a pocket-tap string of
  letters and "same as job 4471" (nothing to go on) are bad input;
* a veteran fitter who has worked with millimetres for thirty years and says so: "mil" is a
  millimetre ("150 mil" is three cubes, "a 150 beam" is the beam), a "course" is one layer,
  "daylight" between two things is the clear gap, "centre to centre" is measured between
  footprint centres (100 centre to centre is one cube clear), "square to the front edge"
  runs parallel to it, "flush" is in contact. "X 400, Y 200" is the footprint centre in the
  cell frame (x away from the robot, y to its left), held to 2 cm; "N in from" an edge or
  "N out from the robot" accepts either the footprint centre or the nearest face at that
  distance (the edges are the workspace's). A wall longer than the cell, cubes of a size
  the cell does not stock, a negative gap and welding are bad input;
* a team lead handing a job over by word of mouth on the way past the cell, the words typed
  in as said: "Right, when you get a sec", "can you stick", "knock up", "the lads", "Cheers".
  Chatter about the day is filler, and a number in it is not a size ("at two", "five
  minutes", "the group of twelve", "at eleven"); "actually, make it three high" replaces the
  figure; "the same as we did for the Thursday visit", a tower on "the other one" when
  nothing stands on the table, a tower past the cell's height and a request to look at the
  conveyor are bad input (the last admits only a refusal);
* an engineering intern in their first weeks who writes neat, complete, polite sentences:
  "Please build …", "I would like …", "Firstly … Secondly …", "respectively", "Thank you."
  The courtesy is filler. A negative size, two heights for one tower, half a step and a
  sphere are bad input;
* a Scottish shop-floor operator writing as they speak: "gie us" / "give us" (give me),
  "stick" / "bung" (put), "wee" (small: with a number the number stands, without one
  nothing is checked beyond the rest of the command), "o'" (of), "wi'" (with), "tae" (to),
  "doon" (down), "aff" (off), "twa" (two), "yin" (one: "the middle yin"), "aboot" (about),
  "aye", "naw" / "nae" / "no" (no, not: "no at the back" is not at the back), "och" /
  "ach" (interjections), "so it is" (emphasis), "bonny" (nice), "the thingmy" (a thing with
  no name). "Och, never mind, forget it" cancels the whole request (refusal only); a tower
  "right up tae the ceiling" is past the cell.

About 80 % ordinary and 20 % harder: three or more structures, references ("on it", "the
middle yin", "the tower on the left", "the other one"), distributive phrases ("a tower of two
on each corner", "a single cube sat on each end", "one in each corner of the table", "50 of
daylight between each"), comparisons ("twice as tall as a tower of three"), removals ("take
the two end cubes off", "take the middle yin away", "lose the top step") and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording, and nothing else:

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by its
  column heights); "right next to it" is at most 10 cm clear, or touching; "not touching",
  "no touching", "a gap", "apart" and "a bit of a gap" mean separate structures;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none is
  said; "behind the middle of it" also lines the centres up (± 3 cm); "directly in front"
  puts the first's centre within the second's width; a tower "in front of" a wall may stand
  against it as one structure; "just in front" is no more than 25 cm clear;
* a bridge's or gate's top is a beam (the shared `bridge`, overall height one more than the
  posts) where the command names a beam, and a beam or a bar of cubes where it does not;
  "just cubes across the top" is a bar of cubes only; a table is four separate legs under one
  connected top of beams or of cubes (the shared `canopy`, a cube top, or the beam roof);
* a ring's stated size is its outside; "in the middle of" / "dead centre inside" a ring is
  inside its empty interior, clear of the ring, with the centres within 3 cm;
* a staircase's width is free unless given, and so is the way it climbs unless said; "a
  single cube on the top step" stands on the top step only; "lose the top step" accepts the
  top cube off (heights 1, 2, 3, 3) or the whole last step off;
* a pyramid's step is free unless given: "a base of four by four" accepts 16-9-4-1 and
  16-4-1, so with "the top cube removed" 16-9-4 or 16-4; "base 5x5, 3 levels" is any
  three-level pyramid on a full 5 × 5 base; "a flat pyramid, like a triangle standing
  upright, bottom row of four" is 4-3-2-1, one cube thick;
* "a tower of two on each corner" of a 3 × 3 slab makes its corner columns three high; "a
  3-high tower on its back left corner — sitting on the corner cube" stands on that corner
  cell; "a single cube sat on each end" of a wall stands on its two end columns;
* "opposite ends of the table" is left and right regions or front and back regions;
  "tall-ish" is at least four cubes high; "something wi' steps in it" is a staircase or a
  pyramid; "some sort of enclosure" is a ring;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the back edge" is every part at x ≥ 0.60, "the back half" every part at x ≥ 0.50,
  "up against the left-hand edge" a footprint centre at y ≥ 0.45, "the centre line" y = 0.30
  ± 3 cm; a stated coordinate is the footprint centre ± 2 cm.

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

_TALLISH = 4  # cubes: "tall-ish"


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev27-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _opposite_ends(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B stand at opposite ends of the table: one in the left region and the other in
    the right, or one in the front region and the other in the back."""
    for ra, rb in ((_L, _R), (_R, _L), (_F, _B), (_B, _F)):
        if bx.region_problem(a, ra) is None and bx.region_problem(b, rb) is None:
            return None
    return "not at opposite ends of the table"


def _near_any(xs: tuple[float, ...], ys: tuple[float, ...], tol: float = 0.02) -> k.Check:
    """The footprint centre within `tol` of one of the x values and one of the y values (an
    empty tuple leaves that axis free): a distance "in from" an edge read to the centre or
    to the nearest face."""

    def f(bs: k.Boxes) -> k.Reason:
        cx, cy = bx.centre(bs)
        if xs and all(abs(cx - x) > tol for x in xs):
            return f"centre x {cx:.3f}, want one of {xs} ± {tol}"
        if ys and all(abs(cy - y) > tol for y in ys):
            return f"centre y {cy:.3f}, want one of {ys} ± {tol}"
        return None

    return f


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_CORNERS = ("back left", "back right", "front left", "front right")


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Tower of 4 front left, and a tower of 2 right next to it pls",
        k.any_of(
            k.pair(k.all_of(T(4), reg("front left")), T(2), k.within(0.10)),
            one(k.cell_heights(4, 2), reg("front left")),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "Wall, 250 long, 100 high, running left to right. Then a tower of 150 behind it with "
        "100 mil of daylight between them.",
        k.pair(T(3), k.all_of(k.wall(5, 2), k.runs("y")), k.gap_of(2, _B)),
    ),
    _c(
        "rel-03",
        REL,
        "Right, when you get a sec, can you stick a single cube on top of a three-by-three "
        "slab, dead in the middle? Cheers.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "Please build a pyramid with three levels, and place a tower of two cubes to its left, "
        "not touching it.",
        k.pair(T(2), k.pyramid(3), k.on_side(_L)),
    ),
    _c(
        "rel-05",
        REL,
        "Gie us a wee ring, five by five, one high, wi' a tower o' two stood in the middle of it.",
        k.pair(_PEN5, T(2), k.centred_in(0.03)),
    ),
    _c(
        "rel-06",
        REL,
        "Row of 5 along the front, then a 2x2 block 3 high behind the middle of it",
        k.any_of(
            k.pair(
                k.block(2, 2, 3),
                k.all_of(k.row(5), k.runs("y"), reg("front")),
                k.all_rels(k.on_side(_B), _facing_mid()),
            ),
            one(k.plan_heights("11111", ".33..", ".33.."), reg("front")),
        ),
    ),
    _c(
        "rel-07",
        REL,
        "Two towers, 200 mil high, 50 mil of daylight between them, and a 150 beam across the top.",
        one(_beam_bridge(4, 1)),
    ),
    _c(
        "rel-08",
        REL,
        "Can you put a wall up along the back, six long, two high, and then a tower of four in "
        "front of it? Anywhere in front is fine.",
        k.any_of(
            k.pair(T(4), k.all_of(k.wall(6, 2), k.runs("y"), reg("back")), k.on_side(_F)),
            one(_col_beside(4, k.all_of(k.wall(6, 2), k.runs("y")), _F), reg("back")),
        ),
    ),
    _c(
        "rel-09",
        REL,
        "I would like a staircase of four steps, with a single cube placed on the top step.",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "rel-10",
        REL,
        "Stick a tower o' five at the back right, and another o' three just in front of it, "
        "no touching.",
        k.pair(
            T(3),
            k.all_of(T(5), reg("back right")),
            k.all_rels(k.on_side(_F), k.within(0.25)),
        ),
    ),
    _c("rel-11", REL, "Gate: 2 posts 3 high w/ a beam on top", one(_beam_bridge(3))),
    _c(
        "rel-12",
        REL,
        "Ring of cubes, 300 by 300 outside, one course, and a 100-high tower dead centre "
        "inside it, not touching the ring.",
        k.pair(k.all_of(k.ring_of(1, (4, 4)), k.dims(6, 6)), T(2), k.centred_in(0.03)),
    ),
    _c(
        "rel-13",
        REL,
        "Need a tower of six in between two towers of two, all in a line, a cube's gap either "
        "side.",
        k.line(T(2), T(6), T(2), gaps=(1,)),
    ),
    _c(
        "rel-14",
        REL,
        "Please place a row of four cubes directly in front of a wall that is four cubes long "
        "and three cubes high, leaving a gap of one cube between them.",
        k.pair(
            k.row(4),
            k.wall(4, 3),
            k.all_rels(k.parallel_gap(1), k.on_side(_F), _square_to),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "A wall five long, three high, and a wee single cube sat on each end of it.",
        one(k.profile(4, 3, 3, 3, 4)),
    ),
    _c(
        "rel-16",
        REL,
        "Pyramid 3 levels in the middle, towers of 4 on both sides of it w/ a bit of a gap",
        k.any_of(
            *[
                k.in_order(
                    axis,
                    T(4),
                    k.all_of(k.pyramid(3), reg("centre")),
                    T(4),
                    max_gap=0.25,
                )
                for axis in ("x", "y")
            ]
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Slab 200 by 200, one course, and a 3-high tower flush on its back left corner — "
        "sitting on the corner cube, I mean.",
        one(
            k.plan_heights("4111", "1111", "1111", "1111"),
            k.upper_side(_B, 1),
            k.upper_side(_L, 1),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "Could you please build two walls, each five cubes long and two cubes high, running "
        "from front to back and parallel to each other with a gap of two cubes?",
        k.pair(
            k.all_of(k.wall(5, 2), k.runs("x")),
            k.all_of(k.wall(5, 2), k.runs("x")),
            k.parallel_gap(2),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "For the two o'clock demo, can you knock up a table — four legs, two high — and a "
        "tower of three to the right of it?",
        k.pair(T(3), _roofed(4, 2), k.on_side(_R)),
    ),
    _c(
        "rel-20",
        REL,
        "Put a tower o' four in between two rows o' three, aye, the rows running front tae back.",
        k.any_of(
            k.between_(T(4), k.all_of(k.row(3), k.runs("x"))),
            one(k.any_of(k.plan_heights("111", ".4.", "111"), k.plan_heights("111", "4..", "111"))),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Tower of 6 back left. Actually make it 4",
        one(T(4), reg("back left")),
    ),
    _c(
        "seq-02",
        SEQ,
        "Lay a 150 by 100 slab, one course. Then put a second course on it, same size.",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "First thing, put a row of six across the front. Then take the two end cubes off, one "
        "each end.",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-04",
        SEQ,
        "Please build a tower of five cubes. Afterwards, please add a second tower of five "
        "cubes to its right, leaving a gap of one cube.",
        k.pair(T(5), T(5), k.gap_of(1, _R)),
    ),
    _c("seq-05", SEQ, "Build a tower o' seven, then take the top three aff it.", one(T(4))),
    _c(
        "seq-06",
        SEQ,
        "3x3 slab center. Then 2x2 on top. Then 1 on top of that",
        one(k.pyramid_counts(9, 4, 1), reg("centre")),
    ),
    _c(
        "seq-07",
        SEQ,
        "Two towers, 150 high, 50 of daylight between. Then run a 150 beam across the tops.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Can you set up a wall on the right-hand side, five long, two high? Actually, make it "
        "three high, the lads need it taller.",
        one(k.wall(5, 3), reg("right")),
    ),
    _c(
        "seq-09",
        SEQ,
        "Firstly, please build a pyramid with a base of four by four cubes. Secondly, please "
        "remove the top cube from it.",
        one(k.pyramid(), k.base(4, 4), _flat_topped_pyramid),
    ),
    _c(
        "seq-10",
        SEQ,
        "Gie us three towers o' two in a row, a cube apart. Then take the middle yin away.",
        k.pair(T(2), T(2), k.gap_of(3)),
    ),
    _c(
        "seq-11",
        SEQ,
        "L shape 4x4 flat, 1 high. Then add a tower of 3 on the corner",
        one(k.plan_heights("4111", "1...", "1...", "1...")),
    ),
    _c(
        "seq-12",
        SEQ,
        "Wall 300 long, 150 high. Then knock 50 off the top, so it ends up at 100.",
        one(k.wall(6, 2)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Put a tower of four front right, then the same again front left.",
        k.structures(k.all_of(T(4), reg("front right")), k.all_of(T(4), reg("front left"))),
    ),
    _c(
        "seq-14",
        SEQ,
        "Please construct a row of three cubes. Then please extend the row by two cubes at the "
        "same end, so that it becomes five cubes long.",
        one(k.row(5)),
    ),
    _c(
        "seq-15",
        SEQ,
        "A tower o' six in the centre. Naw, wait, make that five.",
        one(T(5), reg("centre")),
    ),
    _c(
        "seq-16",
        SEQ,
        "Block 2x2x2 front left, then another one same size back right",
        k.structures(
            k.all_of(k.block(2, 2, 2), reg("front left")),
            k.all_of(k.block(2, 2, 2), reg("back right")),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "Staircase, four steps, 50 mil rise each. Then lose the top step.",
        one(k.any_of(k.staircase(3), k.profile(1, 2, 3, 3))),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build a 3 by 3 slab on the left. Once that's done, a tower of two on each corner of it.",
        one(k.plan_heights("313", "111", "313"), reg("left")),
    ),
    _c(
        "seq-19",
        SEQ,
        "Please build two towers, each four cubes high, with a gap of one cube between them. "
        "Then please remove one cube from the top of the tower on the left.",
        k.pair(T(3), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Build a wall, six long, two high. Och, scrap that — a row o' six instead.",
        one(k.row(6)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "3 towers of 2 in a line, 1 cube gap",
        k.in_line(3, T(2), 1),
    ),
    _c(
        "num-02",
        NUM,
        "Four towers: 50, 100, 150 and 200 high, left to right, 50 of daylight between each.",
        k.in_order("y", T(1), T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-03",
        NUM,
        "Should only take you five minutes — a pyramid, four levels, for the two o'clock group "
        "of twelve.",
        one(k.pyramid(4)),
    ),
    _c("num-04", NUM, "Please build a tower consisting of eight cubes.", one(T(8))),
    _c(
        "num-05",
        NUM,
        "A couple o' towers o' four, a wee bit apart.",
        k.pair(T(4), T(4), k.within(0.25)),
    ),
    _c("num-06", NUM, "Slab, 12 cubes, 3 rows of 4", one(k.block(3, 4, 1))),
    _c("num-07", NUM, "Build a block, 2 by 2, four courses.", one(k.block(2, 2, 4))),
    _c(
        "num-08",
        NUM,
        "I need half a dozen single cubes down the left-hand side, front to back, one cube apart.",
        k.all_of(
            k.in_order("x", *[T(1)] * 6, gaps=(1,)),
            k.layout(reg("left")),
        ),
    ),
    _c(
        "num-09",
        NUM,
        "I would like three towers with heights of two, three and four cubes respectively, "
        "placed from front to back with gaps of one cube.",
        k.in_order("x", T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-10",
        NUM,
        "Gie us a tower o' three and one twice as tall, side by side.",
        k.any_of(k.pair(T(6), T(3), k.within(0.25)), one(k.cell_heights(6, 3))),
    ),
    _c("num-11", NUM, "Pyramid, base 5x5, 3 levels", one(k.pyramid(3), k.base(5, 5))),
    _c(
        "num-12",
        NUM,
        "Two bridges: each one two 100-high posts, 50 apart, with a 150 beam across. Keep 100 "
        "of daylight between the bridges.",
        k.pair(_beam_bridge(2, 1), _beam_bridge(2, 1), k.gap_of(2)),
    ),
    _c(
        "num-13",
        NUM,
        "Two rows of five, one behind the other, a cube apart, both running left to right.",
        k.pair(
            k.all_of(k.row(5), k.runs("y")),
            k.all_of(k.row(5), k.runs("y")),
            k.parallel_gap(1),
        ),
    ),
    _c("num-14", NUM, "Please construct a staircase with six steps.", one(k.staircase(6))),
    _c(
        "num-15",
        NUM,
        "Three wee towers, heights one, twa and three, any order, nae touching.",
        k.structures(T(1), T(2), T(3)),
    ),
    _c(
        "num-16",
        NUM,
        "Need 4 stacks of 3, one in each corner of the table",
        k.structures(*[k.all_of(T(3), reg(r)) for r in _CORNERS]),
    ),
    _c(
        "num-17",
        NUM,
        "Ring, 250 square outside, 100 high.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "num-18",
        NUM,
        "Could you do a wall that's eight long and three high for the camera lot? They'll be "
        "here at ten.",
        one(k.wall(8, 3)),
    ),
    _c(
        "num-19",
        NUM,
        "I would like a flat pyramid, like a triangle of cubes standing upright, with a bottom "
        "row of four cubes.",
        one(k.pyramid_counts(4, 3, 2, 1), k.flat),
    ),
    _c(
        "num-20",
        NUM,
        "Stick five towers o' two in a line, left tae right, a cube between each.",
        k.in_order("y", *[T(2)] * 5, gaps=(1,)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Tower 30cm tall, back right", one(T(6), reg("back right"))),
    _c("dim-02", DIM, "Wall, 350 long by 150 high.", one(k.wall(7, 3))),
    _c(
        "dim-03",
        DIM,
        "Can you do me a slab about 20 centimetres square, just the one layer?",
        one(k.block(4, 4, 1)),
    ),
    _c("dim-04", DIM, "Please build a tower with a height of 0.4 metres.", one(T(8))),
    _c(
        "dim-05",
        DIM,
        "A wee wall, aboot 15 centimetres high and 25 long.",
        one(k.wall(5, 3)),
    ),
    _c("dim-06", DIM, "Row 250mm long, left side", one(k.row(5), reg("left"))),
    _c("dim-07", DIM, "Block, 100 by 100, 150 high.", one(k.block(2, 2, 3))),
    _c(
        "dim-08",
        DIM,
        "I want a staircase about 15 cm high — three steps, obviously.",
        one(k.staircase(3)),
    ),
    _c(
        "dim-09",
        DIM,
        "Please construct a bridge whose two pillars are each ten centimetres tall, with a beam "
        "across the top.",
        one(_beam_bridge(2)),
    ),
    _c(
        "dim-10",
        DIM,
        "Gie us a block half a metre long and 10 centimetres wide, one layer.",
        one(k.block(2, 10, 1)),
    ),
    _c("dim-11", DIM, "Pyramid w/ a 15cm base", one(k.pyramid(), k.base(3, 3))),
    _c(
        "dim-12",
        DIM,
        "Two towers, 200 high, 100 centre to centre.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "dim-13",
        DIM,
        "Put up an L, arms about 20 cm each, one layer high.",
        one(k.shape_letter("L"), k.dims(4, 4), k.height(1)),
    ),
    _c(
        "dim-14",
        DIM,
        "Please build a ring that is 20 centimetres on each side and 10 centimetres tall.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "dim-15",
        DIM,
        "Stick a tower up on the left, 25 centimetre tall.",
        one(T(5), reg("left")),
    ),
    _c("dim-16", DIM, "Wall 0.3m long x 0.1m high", one(k.wall(6, 2))),
    _c(
        "dim-17",
        DIM,
        "Gate: two 150-high posts, 50 daylight, beam on top. Top of the beam should come out at "
        "200.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "dim-18",
        DIM,
        "Knock up a table, would you — legs ten centimetres, top about fifteen by fifteen.",
        one(_roofed(4, 2), k.dims(3, 3)),
    ),
    _c(
        "dim-19",
        DIM,
        "Please build a slab measuring 25 centimetres by 15 centimetres, two layers thick.",
        one(k.block(5, 3, 2)),
    ),
    _c(
        "dim-20",
        DIM,
        "A staircase up tae 20 centimetres, five centimetre steps, climbing tae the right.",
        one(k.staircase(4), k.rises(_R)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Tower of 5 NOT in the centre",
        one(T(5), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-02",
        NEG,
        "3 by 3 square, one course, no cube in the middle.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-03",
        NEG,
        "Bridge with legs of three, but don't bother with a beam, just cubes across the top.",
        one(_bar_on_posts(3, 3), k.only_cubes),
    ),
    _c(
        "neg-04",
        NEG,
        "Please build a tower of six cubes, but please do not place it on the left side of the "
        "table.",
        one(T(6), k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-05",
        NEG,
        "A pyramid o' three levels, nae beams.",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c("neg-06", NEG, "Row of 7, not left to right", one(k.row(7), k.runs("x"))),
    _c("neg-07", NEG, "Two towers of 150, and don't let them touch.", k.each(2, T(3))),
    _c(
        "neg-08",
        NEG,
        "Don't put anything near the robot — a wall, four long by two high, in the back half of "
        "the table.",
        one(k.wall(4, 2), k.min_x(0.50)),
    ),
    _c(
        "neg-09",
        NEG,
        "Please build a table with four legs, two cubes high, without using any beams.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-10",
        NEG,
        "Build a ring, four by four, one high, but leave a gap in the side nearest the robot, "
        "like a door.",
        one(
            k.dims(4, 4),
            k.height(1),
            k.parts(lo=10, hi=11),
            k.not_(k.ring, "closed"),
            _missing_on(_F),
        ),
    ),
    _c(
        "neg-11",
        NEG,
        "Staircase 4 steps, NOT going up to the left",
        one(k.staircase(4), k.not_(k.rises(_L), "climbs to the left")),
    ),
    _c(
        "neg-12",
        NEG,
        "Block 150 by 150, 100 high, no beams, and keep it off the front edge.",
        one(k.block(3, 3, 2), k.only_cubes, k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-13",
        NEG,
        "Give me a tower of three and a tower of five, but not next to each other — opposite "
        "ends of the table.",
        k.pair(T(3), T(5), _opposite_ends),
    ),
    _c(
        "neg-14",
        NEG,
        "Please build a wall five cubes in length and two in height that does not run from left "
        "to right.",
        one(k.wall(5, 2), k.runs("x")),
    ),
    _c(
        "neg-15",
        NEG,
        "A 2 by 3 block, two high — no at the back, mind, keep it tae the front.",
        one(k.block(2, 3, 2), reg("front")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "Towel of 5 cubes front right", one(T(5), reg("front right"))),
    _c("typo-02", TYP, "Bridge w/ legs of 2 and a bean across", one(_beam_bridge(2))),
    _c("typo-03", TYP, "Wall 200 lnog, 100 hihg.", one(k.wall(4, 2))),
    _c(
        "typo-04",
        TYP,
        "Can you put up a pyramd, three levles, on the rihgt?",
        one(k.pyramid(3), reg("right")),
    ),
    _c("typo-05", TYP, "Please bulid a staircase of five stpes.", one(k.staircase(5))),
    _c("typo-06", TYP, "Gie us a towr o' sixx, ta.", one(T(6))),
    _c("typo-07", TYP, "2x3 slav 2 layers", one(k.block(2, 3, 2))),
    _c(
        "typo-08",
        TYP,
        "Rign, 200 square outside, 50 hgih.",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "typo-09",
        TYP,
        "Two towres of four, a cueb apart, back left.",
        k.all_of(k.pair(T(4), T(4), k.gap_of(1)), k.layout(reg("back left"))),
    ),
    _c(
        "typo-10",
        TYP,
        "Please constuct a row of six cubes alnog the back of the tabel.",
        one(k.row(6), k.runs("y"), reg("back")),
    ),
    _c("typo-11", TYP, "A wee tabel wi' fuor legs, twa high.", one(_roofed(4, 2))),
    _c(
        "typo-12",
        TYP,
        "Tower if 3 on top of a 3x3 slab, centered",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
    ),
    _c(
        "typo-13",
        TYP,
        "Two tweors 100 high with 50 daylihgt and a 150 baem on top.",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "typo-14",
        TYP,
        "Stick a 2x2 blokc, thre high, in the midle.",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Front left: tower, 4.", one(T(4), reg("front left"))),
    _c("wo-02", WO, "150 high, 300 long — that's the wall I'm after.", one(k.wall(6, 3))),
    _c(
        "wo-03",
        WO,
        "On the right-hand side, by the end of the day if you can, a pyramid of three.",
        one(k.pyramid(3), reg("right")),
    ),
    _c(
        "wo-04",
        WO,
        "At the centre of the table, please place a block of two by two cubes, three cubes high.",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    _c("wo-05", WO, "Five high, the tower, and at the back.", one(T(5), reg("back"))),
    _c(
        "wo-06",
        WO,
        "On top of a 2x2 block 2 high: one more cube, centred",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.top_centred(), k.levels(4, 4, 1)),
    ),
    _c(
        "wo-07",
        WO,
        "Right-hand side, 100 in from the back edge: tower, 200 high.",
        one(T(4), reg("right"), _near_any((0.70, 0.675), ())),
    ),
    _c(
        "wo-08",
        WO,
        "The wall — five long, two high — put it across the back, would you.",
        one(k.wall(5, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "wo-09",
        WO,
        "Two cubes high, three cubes wide and four cubes long: that is the block I would like "
        "you to build.",
        one(k.block(3, 4, 2)),
    ),
    _c(
        "wo-10",
        WO,
        "Behind the tower o' three, put a tower o' six, wi' a cube's space between.",
        k.pair(T(6), T(3), k.gap_of(1, _B)),
    ),
    _c(
        "wo-11",
        WO,
        "4 steps, climbing away from the robot, staircase pls",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "wo-12",
        WO,
        "A hundred mil apart, centre to centre, two 150 towers.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "wo-13",
        WO,
        "Over by the left, that's where I want the ring — four by four, one high.",
        one(_PEN4, reg("left")),
    ),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "Hi, job 2207 on the screen says: tower of 3. Thx", one(T(3))),
    _c(
        "fil-02",
        FIL,
        "Been doing this thirty years and I still like a tidy cell. Right — wall, 250 long, "
        "100 high, square to the front edge.",
        one(k.wall(5, 2), k.runs("y")),
    ),
    _c(
        "fil-03",
        FIL,
        "Morning all. Bit of a mad one today, we've got the auditors in at eleven and half the "
        "team's off sick. Anyway — a pyramid, three levels, in the middle please. Cheers.",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-04",
        FIL,
        "Good morning. My name is Priya and I am the new engineering intern on this line. For "
        "my first task, I would like to build a staircase of three steps. Thank you very much.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Aye, how's it going? Grand day for it. Right, gie us a row o' five, would ye.",
        one(k.row(5)),
    ),
    _c("fil-06", FIL, "Shift B, station 4, cycle 118. Block 2x2, 2 high", one(k.block(2, 2, 2))),
    _c(
        "fil-07",
        FIL,
        "Now listen, none of your fancy stuff. Two towers of 100, 50 mil of daylight, and "
        "that's your lot.",
        k.pair(T(2), T(2), k.gap_of(1)),
    ),
    _c(
        "fil-08",
        FIL,
        "I know you're busy and I hate to pile more on, but when you get a minute — and honestly "
        "it's not urgent — a bridge, legs of two, please.",
        one(_span(2)),
    ),
    _c(
        "fil-09",
        FIL,
        "I hope this message finds you well. As discussed in yesterday's meeting, I would be "
        "grateful if you could build a tower of seven cubes on the right side of the table. "
        "Kind regards.",
        one(T(7), reg("right")),
    ),
    _c(
        "fil-10",
        FIL,
        "Ach, the kettle's broke again, so it is. Anyway, stick a tower o' four in the back "
        "left for us.",
        one(T(4), reg("back left")),
    ),
    _c("fil-11", FIL, "Quick one before break. Ring 5x5, 1 high. Ta", one(_PEN5)),
    _c(
        "fil-12",
        FIL,
        "Back in my day we'd have done this by hand with a set square. Block, 150 by 100, one "
        "course high, on the left.",
        one(k.block(3, 2, 1), reg("left")),
    ),
    _c(
        "fil-13",
        FIL,
        "So — the big boss is coming round at three and she loves a good staircase. Four "
        "steps, climbing towards the back, if you can.",
        one(k.staircase(4), k.rises(_B)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "Tower 4 @ back right corner", one(T(4), reg("back right"))),
    _c(
        "reg-02",
        REG,
        "Tower of 150, centre at X 400, Y 200.",
        one(T(3), k.near(0.40, 0.20, 0.02)),
    ),
    _c(
        "reg-03",
        REG,
        "Can you put a row of four across the front edge, near the robot?",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "reg-04",
        REG,
        "Please place a pyramid of two levels in the front left corner of the table.",
        one(k.pyramid(2), reg("front left")),
    ),
    _c(
        "reg-05",
        REG,
        "Stick a wee block, two by two, one high, right in the middle.",
        one(k.block(2, 2, 1), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "Wall 6x2 along back edge",
        one(k.wall(6, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-07",
        REG,
        "Slab 200 square, one course, centred at X 500, Y 300.",
        one(k.block(4, 4, 1), k.near(0.50, 0.30, 0.02)),
    ),
    _c(
        "reg-08",
        REG,
        "Put a tower of five right over on the left-hand side, up against the edge.",
        one(T(5), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-09",
        REG,
        "Please place a tower of three cubes at the back of the table, on the centre line.",
        one(T(3), reg("back"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-10",
        REG,
        "A row o' four, front tae back, doon the right-hand side.",
        one(k.row(4), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-11",
        REG,
        "2 towers of 3: one front left, one front right",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("front right"))),
    ),
    _c(
        "reg-12",
        REG,
        "Tower, 250 high, 150 in from the left-hand edge and 300 out from the robot.",
        one(T(5), _near_any((0.30, 0.325), (0.40, 0.375))),
    ),
    _c(
        "reg-13",
        REG,
        "The back half of the table's free today, so put the 3 by 3 block there — two high.",
        one(k.block(3, 3, 2), k.min_x(0.50)),
    ),
    _c(
        "reg-14",
        REG,
        "Please build an L shape with both arms three cubes long, one cube high, in the back "
        "right corner of the table.",
        one(k.shape_letter("L"), k.dims(3, 3), k.height(1), reg("back right")),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Anything u like, max 6 cubes",
        k.all_of(k.anything, k.layout(_cubes(hi=6))),
    ),
    _c(
        "open-02",
        OPEN,
        "Build whatever you fancy, but nothing over 150 high.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-03",
        OPEN,
        "Just put something up so the visitors have something to look at — your call.",
        k.anything,
    ),
    _c(
        "open-04",
        OPEN,
        "Please build any structure you consider suitable for demonstrating the robot, using no "
        "more than twelve cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=12))),
    ),
    _c(
        "open-05",
        OPEN,
        "Build us something bonny, whatever ye like, on the left.",
        k.all_of(k.anything, k.layout(reg("left"))),
    ),
    _c(
        "open-06",
        OPEN,
        "Something tall-ish, your choice, back right",
        k.all_of(k.anything, k.layout(k.all_of(reg("back right"), k.height(lo=_TALLISH)))),
    ),
    _c(
        "open-07",
        OPEN,
        "Any shape you like, but keep the whole thing inside a 200 by 200 footprint.",
        k.all_of(k.anything, k.layout(_fits(4, 4))),
    ),
    _c(
        "open-08",
        OPEN,
        "Two structures, whatever you like, just keep them apart.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-09",
        OPEN,
        "Please build something that has a gap underneath it, such as a bridge or an arch.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-10",
        OPEN,
        "Make us a wee something wi' steps in it.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-11",
        OPEN,
        "Surprise me. Cubes only, no beams",
        k.all_of(k.anything, k.layout(k.only_cubes)),
    ),
    _c(
        "open-12",
        OPEN,
        "Some sort of enclosure, any size you like, one course high.",
        k.all_of(k.anything, one(k.ring, k.height(1))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Tower of", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-02", BAD, "Same as job 4471", k.honest(k.anything)),
    _c(
        "bad-03",
        BAD,
        "Wall, 900 long, 100 high.",  # 18 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-04",
        BAD,
        "Tower of three, but use the 30 mil cubes this time.",  # the cell has 50 mm cubes only
        k.honest(one(T(lo=2, hi=3))),
    ),
    _c(
        "bad-05",
        BAD,
        "Weld a 150 beam across two 100-high towers.",  # the cell cannot weld
        k.honest(one(_beam_bridge(2))),
    ),
    _c("bad-06", BAD, "Do the same as we did for the Thursday visit.", k.honest(k.anything)),
    _c(
        "bad-07",
        BAD,
        "Can you have a look at the conveyor when you get a sec? It's making that noise again.",
        k.honest(),
    ),
    _c(
        "bad-08",
        BAD,
        "A tower of twelve, right up high for the photo.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-09", BAD, "Please build a tower of minus three cubes.", k.honest(k.anything)),
    _c(
        "bad-10",
        BAD,
        "Please build one tower that is two cubes high and five cubes high.",
        k.honest(one(k.any_of(T(2), T(5)))),
    ),
    _c(
        "bad-11",
        BAD,
        "Please build a perfect sphere with a diameter of ten centimetres.",
        k.honest(k.anything),
    ),
    _c("bad-12", BAD, "Gie us a tower o' four. Och, never mind, forget it.", k.honest()),
    _c(
        "bad-13",
        BAD,
        "Build us a tower right up tae the ceiling.",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-14", BAD, "Stick the thingmy on the wotsit.", k.honest()),
    _c("bad-15", BAD, "Ffgghhjjjjjj", k.honest()),
    _c(
        "bad-16",
        BAD,
        "Ring 15x15 1 high",  # 15 cubes across: past the cell
        k.honest(k.anything),
    ),
    _c(
        "bad-17",
        BAD,
        "Two towers of 150, with minus 50 of daylight between them.",
        k.honest(k.anything),
    ),
    _c(
        "bad-18",
        BAD,
        "Put a tower of three on top of the other one.",  # nothing stands on the table
        k.honest(k.anything),
    ),
    _c(
        "bad-19",
        BAD,
        "Please build a staircase with two and a half steps.",
        k.honest(one(k.any_of(k.staircase(2), k.staircase(3)))),
    ),
]
