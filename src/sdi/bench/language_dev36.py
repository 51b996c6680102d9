"""A thirty-sixth held-out set for the language front end (dev36): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set (but dev27, the format example) or any benchmark
result, and worded apart from `language_dev` … `language_dev35` (no command shared with any
set, see tests). Nothing here was run through the system while it was written. The set is
deliberately mainstream: about 85 % of the commands are what an ordinary person at a robot
cell would really type — one or two structures with a size, a place, one relation or a
two-step sequence ("then …"), in plain, varied English (build / make / put / place / stack /
set up / lay / give me / I need / could you; the place before or after the structure; sizes
as words or digits, "2 by 4", "3x3", cm, mm and metres; articles dropped now and then).

The brief suggested a tired night-shift operator, a new intern, a customer at a trade-show
demo, a maintenance planner and a teacher's assistant. Every one of those had been used (the
night shift by dev26; the intern by dev27; the trade-fair booth by dev26, and visitors or
customers trying the cell by dev12, dev24 and dev30; maintenance technicians and their work
orders by dev3, dev6, dev8, dev14 and dev23; teaching assistants by dev7, and teachers by
dev5, dev9, dev13 and dev23), so five other ordinary people were chosen. None of them is
among the voices of an earlier set, and the words they bring (a video call, a plank for the
beam, the foreground and background, "less two", "in ascending order") are new to the sets:

* a colleague working from home who types into the cell over a video call: chatter about the
  connection ("can you hear me?", "you froze for a second", "I'm on the train", "you've gone
  all pixelated") is filler, and so is what they say they can see on the camera feed. A
  request for "what I said before the call dropped" has nothing to go on (bad input); "my
  screen's frozen, don't start anything" and "cancel that, build nothing" ask for no build
  (refusal only); a command cut off in mid-word and a string of keys from a laggy keyboard
  are bad input;
* a joiner from the site workshop covering the cell for the day: a "plank" is the cell's
  beam (15 cm); an "upright" is a tower; "a shelf" is two uprights with a plank across the
  tops (the shared `bridge`, overall one cube higher than the uprights); "cubes across the
  top instead" is a bar of cubes; a "frame" is a ring (its size the outside); a "course" is
  one layer; "butt up against" means set touching, as one structure; uprights "N cm apart"
  accept the clear gap and the centre-to-centre reading (joiners set out on centres); trade
  sayings ("measure twice, cut once") are filler. A plank longer than the cell stocks,
  sawing a cube in half and a tower of two heights at once are bad input;
* a photographer shooting the company brochure, whose camera stands behind the robot looking
  out over the table: the "foreground" is the front region, the "background" or "the back of
  the shot" the back region, "left / right of frame" the robot's left / right; "centre of
  frame" alone is the centre region, and with the foreground or background it is the middle
  from left to right (a footprint centre within 8 cm of y = 0.30); "in shot", shot and
  setup numbers and lenses ("the 50 mm lens") are filler, never a size; "breathing room"
  between two things is a clear gap of no more than 25 cm; "nothing else in shot" is exactly
  the structure named; "something tall" is at least four cubes high. Painting the cubes asks
  for no build (refusal only); a tower past the cell's height, "like the Eiffel Tower" and a
  tower on a camera case that is not on the table are bad input;
* an accounts clerk from the office, who writes like a ledger: "in total" counts the cubes
  of the whole layout, "split evenly" makes the parts equal, "less N" is N fewer, "a further
  N" is N more, "Correction:" replaces what it corrects, and purchase-order, reference and
  cost-centre numbers are filler, never a size. A total that comes out below zero, "same as
  last quarter's order" and a wall longer than the cell are bad input;
* a librarian running the public library's maker club with the cell: polite, complete
  sentences ("Please could you …", "for our Saturday group"); "in ascending / descending
  order" is heights rising / falling along one line, in the direction given, either way
  when none is given; shelf marks ("629.8"), group sizes and times are filler. A request for
  a book ("recommend a good book") asks for no build (refusal only); half a cube and a
  perfect cylinder are bad input.

About 85 % ordinary and 15 % harder: three or four structures, references ("the one on the
right", "the one in the middle"), distributive phrases ("a tower of four on each side", "in
each of the four corners", "a gap of one cube between each"), a removal ("remove the one in
the middle"), corrections in the same message ("Correction: make that …", "on second
thoughts, move it") and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by the
  column and the rest); "not touching", "kept apart", "a gap" mean separate structures; "no
  gap between them" and "they should touch" make them one;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none
  is said; where nothing rules touching out, a tower so placed may also be set against the
  other as one structure, the column on that side of the rest; "directly behind" puts the
  centre within the other's width, "lined up one behind the other" and "behind the middle of
  it" line the centres up (± 3 cm);
* "on top of" stands on it, anywhere on it unless "in the middle" / "in the centre" is said
  (then centred over it, ± 3 cm); a cube "on the top step" stands on the top step only;
  "three more cubes on the back end" of a row stands them on its back cube; a tower "butted
  up against the end" of a row stands on the table beyond its end cube or beside it;
* "between" two towers "in a straight line" is the three in a line, apart or touching;
* a ring's or frame's stated size is its outside, of any height unless one is said; "in the
  middle of" a ring is inside its empty interior, clear of it, the centres within 3 cm;
* a table "topped with beams" is the cell's beam roof (the shared `beam_roof`); "no beams
  for the top" is one connected top of cubes resting on every leg;
* a staircase's width is free, and so is the way it climbs unless said; "N cm in total
  height" with 5 cm steps is N / 5 steps; a pyramid's step and base are free unless given; a
  slab is one layer unless a thickness is given; "wide" runs left to right (y) and "deep"
  front to back (x);
* "N apart" between two rows is the clear gap (5 cm centre to centre would make them touch);
  "a few" towers are three or four; "something small" is the shared `small` (at most four
  cubes high and five long overall);
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the right-hand edge" is running front to back with every part within 15 cm of that
  edge (y ≤ 0.20); "hard up against the left edge" puts the nearest face within 2 cm of it
  (y ≥ 0.53); "the left half" is every part at y ≥ 0.30; "well back from the robot" is the
  back region; a stated coordinate ("x = 0.5, y = 0.4") is the footprint centre ± 2 cm; the
  edges are the workspace's.

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

_TALL = 4  # cubes: "something tall"
_EDGE_BAND = 0.15  # m: "along an edge" keeps every part this close to it
_HARD_UP = 0.02  # m: "hard up against an edge" puts the nearest face this close to it
_XS = (0.20, 0.80)  # workspace front and back edges, m
_YS = (0.05, 0.55)  # workspace right and left edges, m


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev36-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _ok(bs: k.Boxes) -> k.Reason:
    """Always holds (no further condition)."""
    return None


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


def _bar_on_posts(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Two separate posts lo–hi cubes high (any height when None) and, as the topmost level,
    one connected bar resting on both — a beam or a row of cubes (with a row of cubes the
    shared `bridge` finds no top piece, since the bar's middle cubes rest on nothing)."""

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
        return None

    return f


def _beam_bridge(posts: int, mouth: int | None = None) -> k.Check:
    """Two posts `posts` high under a beam (the shared `bridge`), the overall height one more
    than the posts; the posts `mouth` cubes apart clear when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _span(posts: int) -> k.Check:
    """Two posts `posts` high with a beam (one layer above the posts) or a bar of cubes
    across the tops."""
    return k.any_of(_beam_bridge(posts), _bar_on_posts(posts, posts))


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


def _col_side(h: int, rest: k.Check, side: str | None = None, col: k.Check = _ok) -> k.Check:
    """One structure: a full column of exactly `h` cubes standing on the table (and passing
    `col`), set against the rest, which passes `rest`; the column lies to `side` of the rest
    when given."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for c in bx.columns(bs):
            if len(c) != h or k.tower(h)(c) is not None or c[0].lo[2] > bx.TOL:
                continue
            others = [b for b in bs if all(b is not q for q in c)]
            if not others:
                continue
            r = col(c) or rest(others)
            if r is None and side is not None and bx.side_of(c, others) != side:
                r = f"the {h}-column is {bx.side_of(c, others)} of the rest, want {side}"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the rest"

    return f


def _by(
    h: int,
    other: k.Check,
    side: str | None = None,
    max_gap: float | None = None,
    col: k.Check = _ok,
    rel: k.Rel | None = None,
) -> k.Pred:
    """A tower of `h` (also passing `col`) to `side` of a structure passing `other`: two
    separate structures (no more than `max_gap` m clear when given, `rel` holding between
    tower and other when given), or one structure with the tower set against the other."""
    rels: list[k.Rel] = []
    if side is not None:
        rels.append(k.on_side(side))
    if max_gap is not None:
        rels.append(k.within(max_gap))
    if rel is not None:
        rels.append(rel)
    apart = k.pair(k.all_of(k.tower(h), col), other, k.all_rels(*rels))
    return k.any_of(apart, k.one(_col_side(h, other, side, col)))


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


def _cubes(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Between `lo` and `hi` cubes among the parts (beams not counted)."""

    def f(bs: k.Boxes) -> k.Reason:
        n = sum(k.only_cubes([b]) is None for b in bs)
        if (lo is not None and n < lo) or (hi is not None and n > hi):
            return f"{n} cubes, want {lo if lo is not None else ''}–{hi if hi is not None else ''}"
        return None

    return f


def _has_beam(bs: k.Boxes) -> k.Reason:
    """At least one part at least two cubes long (a beam)."""
    long_parts = [b for b in bs if max(b.size) >= 2 * bx.CUBE]
    return None if long_parts else "no beam"


def _min_y(y: float) -> k.Check:
    """Every part lies at y ≥ `y` (m): on that side, to the left."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _edge(side: str, band: float = _EDGE_BAND) -> k.Check:
    """Every part within `band` m of the workspace's `side` edge."""

    def f(bs: k.Boxes) -> k.Reason:
        if side == _R:
            far = max(b.hi[1] for b in bs) - _YS[0]
        elif side == _L:
            far = _YS[1] - min(b.lo[1] for b in bs)
        elif side == _F:
            far = max(b.hi[0] for b in bs) - _XS[0]
        else:
            far = _XS[1] - min(b.lo[0] for b in bs)
        ok = far <= band + bx.TOL
        return None if ok else f"a part {far:.3f} m from the {side} edge, want ≤ {band}"

    return f


def _hard_up(side: str, tol: float = _HARD_UP) -> k.Check:
    """The nearest face within `tol` m of the workspace's `side` edge."""

    def f(bs: k.Boxes) -> k.Reason:
        if side == _R:
            gap = min(b.lo[1] for b in bs) - _YS[0]
        elif side == _L:
            gap = _YS[1] - max(b.hi[1] for b in bs)
        elif side == _F:
            gap = min(b.lo[0] for b in bs) - _XS[0]
        else:
            gap = _XS[1] - max(b.hi[0] for b in bs)
        return None if gap <= tol + bx.TOL else f"{gap:.3f} m off the {side} edge, want ≤ {tol}"

    return f


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_MID_Y = k.near(y=0.30, tol=0.03)  # lined up on the centre line
_FRAME_MID = k.near(y=0.30, tol=0.08)  # "centre of frame" with a foreground / background
_CORNERS = ("back left", "back right", "front left", "front right")


def _ring(n: int, high: int | None = None) -> k.Check:
    """A square ring `n` cubes across outside (one cube thick), `high` high (any when None)."""
    return k.all_of(k.ring_of(high, (n - 2, n - 2)), k.dims(n, n))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Sorry, you froze for a second there. Put a tower of three on the left side, please, "
        "and a row of four in front of it.",
        _by(3, k.row(4), _B, col=reg("left")),
    ),
    _c(
        "rel-02",
        REL,
        "Two uprights, four cubes high, with a plank across the top.",
        one(_beam_bridge(4)),
    ),
    _c(
        "rel-03",
        REL,
        "For the brochure shot I need a 3x3 slab, one layer, with a single cube sitting right "
        "in the middle of it.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "A tower of five, and to its right a tower of two, with a gap of one cube between them.",
        k.pair(T(2), T(5), k.gap_of(1, _R)),
    ),
    _c(
        "rel-05",
        REL,
        "For our Saturday maker club, could you please build a ring of cubes five by five with "
        "one cube standing in the middle of it?",
        k.pair(_ring(5), T(1), k.centred_in(0.03)),
    ),
    _c(
        "rel-06",
        REL,
        "Right, I can see the table on my screen now. Build a wall five long and two high across "
        "the back, then a tower of four in front of it.",
        _by(4, k.all_of(k.wall(5, 2), k.runs("y"), reg("back")), _F),
    ),
    _c(
        "rel-07",
        REL,
        "Butt a tower of two up against the end of a row of five — they should touch.",
        one(k.any_of(k.plan_heights("211111"), k.plan_heights("11111", "2...."))),
    ),
    _c(
        "rel-08",
        REL,
        "Pyramid of three levels in the centre of frame, with a tower of four on each side of "
        "it and a little breathing room between.",
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
        "rel-09",
        REL,
        "One beam and two towers of three cubes each, please — the beam laid across the tops of "
        "the towers.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-10",
        REL,
        "Could the robot please place a staircase of three steps next to a tower of five?",
        _by(5, k.staircase(3), max_gap=0.25),
    ),
    _c(
        "rel-11",
        REL,
        "On the feed it looks like the table's clear. Build a 2 by 2 block, three high, and put "
        "a single cube on top of it.",
        one(k.on_top(T(1), k.block(2, 2, 3)), k.levels(4, 4, 4, 1)),
    ),
    _c(
        "rel-12",
        REL,
        "Lay a frame of cubes, five by five on the outside, one course, and stand a tower of "
        "three in the middle of it.",
        k.pair(_ring(5, 1), T(3), k.centred_in(0.03)),
    ),
    _c(
        "rel-13",
        REL,
        "Put a tower of six in the background and a tower of two in the foreground, lined up "
        "one behind the other.",
        k.pair(
            k.all_of(T(6), reg("back")),
            k.all_of(T(2), reg("front")),
            k.all_rels(k.on_side(_B), _facing_mid()),
        ),
    ),
    _c(
        "rel-14",
        REL,
        "Build a row of six cubes and, behind it, a second row of six, one cube apart.",
        k.pair(k.row(6), k.row(6), k.all_rels(k.parallel_gap(1), k.on_side(_B))),
    ),
    _c(
        "rel-15",
        REL,
        "Please set a tower of four between two towers of two, all in a straight line.",
        k.any_of(k.line(T(2), T(4), T(2)), one(k.profile(2, 4, 2))),
    ),
    _c(
        "rel-16",
        REL,
        "Sorry about the echo. Could you put a tower of five at the front right, and a tower "
        "of three directly behind it?",
        _by(3, k.all_of(T(5), reg("front right")), _B, rel=_square_to),
    ),
    _c(
        "rel-17",
        REL,
        "Put up two walls, four long and two high, parallel, with a gap of one cube between "
        "them — like the sides of a trough.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(1)),
    ),
    _c(
        "rel-18",
        REL,
        "I want the tall one behind the short one: a tower of seven behind a tower of three, "
        "both on the centre line of the table.",
        _by(7, k.all_of(T(3), _MID_Y), _B, col=_MID_Y),
    ),
    _c(
        "rel-19",
        REL,
        "Order line 3: a table, four legs of two cubes each, topped with beams.",
        one(k.beam_roof(4, 2)),
    ),
    _c(
        "rel-20",
        REL,
        "Please put a row of five cubes along the front, and behind the middle of it a tower "
        "of four, with a one-cube gap.",
        k.pair(
            T(4),
            k.all_of(k.row(5), k.runs("y"), reg("front")),
            k.all_rels(k.gap_of(1, _B), _facing_mid()),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Build a tower of four at the back left. Then, once that's done, another tower of four "
        "at the back right.",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    _c(
        "seq-02",
        SEQ,
        "First lay a 3x3 slab, one course. Then put a second course on top, same size.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Start with a wall six long and two high along the back. Then put a row of four in the "
        "foreground.",
        k.structures(
            k.all_of(k.wall(6, 2), k.runs("y"), reg("back")),
            k.all_of(k.row(4), reg("front")),
        ),
    ),
    _c(
        "seq-04",
        SEQ,
        "Build a tower of seven cubes, then remove two from the top.",
        one(T(5)),
    ),
    _c(
        "seq-05",
        SEQ,
        "First, please build a staircase of four steps. Then add a single cube on the top step.",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "seq-06",
        SEQ,
        "Make a row of five, left to right. Then put a second row on top of it so it becomes a "
        "wall.",
        one(k.wall(5, 2), k.runs("y")),
    ),
    _c(
        "seq-07",
        SEQ,
        "Two uprights of three, one cube apart. Then lay a plank across the tops.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Pyramid, three levels, centre of frame. Then a tower of two on its left, not touching.",
        k.pair(T(2), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_L)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Build two towers of three. Then add a further two cubes to the one on the right.",
        k.pair(T(5), T(3), k.on_side(_R)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Please build a row of four cubes running left to right. Next, please build an "
        "identical row directly behind it, touching.",
        one(k.block_xy(2, 4, 1)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build a wall four long and three high. Then take the top layer off.",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Set up a tower of two on the left, then one of five on the right.",
        k.structures(k.all_of(T(2), reg("left")), k.all_of(T(5), reg("right"))),
    ),
    _c(
        "seq-13",
        SEQ,
        "Build a block 2x2, two high, in the foreground. After that, one more just like it in "
        "the background.",
        k.structures(
            k.all_of(k.block(2, 2, 2), reg("front")),
            k.all_of(k.block(2, 2, 2), reg("back")),
        ),
    ),
    _c(
        "seq-14",
        SEQ,
        "A tower of six cubes. Correction: make that a tower of four.",
        one(T(4)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Please start by building a 4 by 4 ring of cubes, one high. When that is done, please "
        "add a second layer on top of it.",
        one(_ring(4, 2)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Okay so step one, a row of three cubes front to back. Step two, stack three more cubes "
        "on the back end of it.",
        one(k.xprofile(1, 1, 4)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Lay a 2x4 slab, one course. Then put a 2x2, one course, on top, in the middle.",
        one(k.on_top(k.block(2, 2, 1), k.block(2, 4, 1)), k.centred(), k.levels(8, 4)),
    ),
    _c(
        "seq-18",
        SEQ,
        "First a tower of five on the left of frame. Then, on second thoughts, move it to the "
        "right.",
        one(T(5), reg("right")),
    ),
    _c(
        "seq-19",
        SEQ,
        "Build a 2 by 3 slab, one layer. Then put a tower of three on top of it, anywhere.",
        one(k.on_top(T(3), k.block(2, 3, 1)), k.levels(6, 1, 1, 1)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Please build three towers of four cubes in a row, with a gap of two cubes between "
        "each. Then please remove the one in the middle.",
        k.pair(T(4), T(4), k.gap_of(5)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Twelve cubes in total, split evenly into three towers.",
        k.each(3, T(4)),
    ),
    _c(
        "num-02",
        NUM,
        "Please build four towers in descending order of height, five cubes down to two, from "
        "left to right, with a one-cube gap between each.",
        k.in_order("y", T(5), T(4), T(3), T(2), gaps=(1,)),
    ),
    _c(
        "num-03",
        NUM,
        "Build a tower of eight cubes. Sorry, the dog's barking — eight, yes.",
        one(T(8)),
    ),
    _c("num-04", NUM, "Stack nine cubes into one tower.", one(T(9))),
    _c(
        "num-05",
        NUM,
        "Two towers of six, side by side, for the hero shot.",
        _by(6, T(6), max_gap=0.25),
    ),
    _c("num-06", NUM, "A slab of 15 cubes: 3 rows of 5, one layer.", one(k.block(3, 5, 1))),
    _c(
        "num-07",
        NUM,
        "Our group of eleven would love to see a pyramid with four levels, please.",
        one(k.pyramid(4)),
    ),
    _c(
        "num-08",
        NUM,
        "Three towers, heights two, four and six, left to right, a cube apart.",
        k.in_order("y", T(2), T(4), T(6), gaps=(1,)),
    ),
    _c("num-09", NUM, "Give me a wall nine cubes long and two high.", one(k.wall(9, 2))),
    _c(
        "num-10",
        NUM,
        "A staircase with five steps in the background.",
        one(k.staircase(5), reg("back")),
    ),
    _c("num-11", NUM, "A tower of ten, less three.", one(T(7))),
    _c(
        "num-12",
        NUM,
        "Please make two rows of seven cubes each, parallel, two cubes apart.",
        k.pair(k.row(7), k.row(7), k.parallel_gap(2)),
    ),
    _c("num-13", NUM, "A block three by three and three high, please.", one(k.block(3, 3, 3))),
    _c("num-14", NUM, "Half a dozen cubes in a single row.", one(k.row(6))),
    _c(
        "num-15",
        NUM,
        "Build a pair of towers, four and two, with a gap of two cubes.",
        k.pair(T(4), T(2), k.gap_of(2)),
    ),
    _c(
        "num-16",
        NUM,
        "Three towers of three and one tower of six, all kept apart from each other.",
        k.structures(T(3), T(3), T(3), T(6)),
    ),
    _c(
        "num-17",
        NUM,
        "Please line up three towers in ascending order — one, two and three cubes — with a "
        "one-cube gap between each.",
        k.line(T(1), T(2), T(3), gaps=(1,)),
    ),
    _c("num-18", NUM, "I need a row of eight cubes, front to back.", one(k.row(8), k.runs("x"))),
    _c("num-19", NUM, "A 2x2 column, six high.", one(k.block(2, 2, 6))),
    _c(
        "num-20",
        NUM,
        "A total of eight cubes: a tower of five and a tower of three, a cube apart.",
        k.pair(T(5), T(3), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Tower 20 cm tall on the left, please.", one(T(4), reg("left"))),
    _c("dim-02", DIM, "A wall 300 mm long and 100 mm high.", one(k.wall(6, 2))),
    _c(
        "dim-03",
        DIM,
        "A slab 15 cm by 20 cm, one layer thick, in the foreground.",
        one(k.block(3, 4, 1), reg("front")),
    ),
    _c("dim-04", DIM, "Could you lay a row 0.35 m long?", one(k.row(7))),
    _c(
        "dim-05",
        DIM,
        "Please build a tower that is 45 centimetres high.",
        one(T(9)),
    ),
    _c("dim-06", DIM, "Block 10 by 15 cm and 10 cm high.", one(k.block(2, 3, 2))),
    _c(
        "dim-07",
        DIM,
        "Two uprights 15 cm high, a plank across the top.",
        one(_beam_bridge(3)),
    ),
    _c(
        "dim-08",
        DIM,
        "A staircase 20 cm high, climbing towards the back.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "dim-09",
        DIM,
        "A ring 25 cm square on the outside, 5 cm high.",
        one(_ring(5, 1)),
    ),
    _c(
        "dim-10",
        DIM,
        "Please build a wall that is 40 centimetres long and 15 centimetres high.",
        one(k.wall(8, 3)),
    ),
    _c("dim-11", DIM, "Could you do a 3x3 block, 150 mm tall?", one(k.block(3, 3, 3))),
    _c(
        "dim-12",
        DIM,
        "Two towers 20 cm high, 10 cm apart.",
        k.pair(T(4), T(4), k.gaps(2, 1)),
    ),
    _c("dim-13", DIM, "Pyramid with a 25 cm base.", one(k.pyramid(), k.base(5, 5))),
    _c("dim-14", DIM, "A slab 0.2 m by 0.1 m, one layer.", one(k.block(4, 2, 1))),
    _c(
        "dim-15",
        DIM,
        "Please make a row of cubes 30 centimetres long along the left side.",
        one(k.row(6), k.runs("x"), reg("left")),
    ),
    _c("dim-16", DIM, "Tower half a metre high.", one(T(10))),
    _c("dim-17", DIM, "Give me a 2 by 4 block, 5 cm thick.", one(k.block(2, 4, 1))),
    _c(
        "dim-18",
        DIM,
        "A wall 25 cm long by 20 cm high, background left.",
        one(k.wall(5, 4), reg("back left")),
    ),
    _c(
        "dim-19",
        DIM,
        "Two rows of cubes, each 20 cm long, 5 cm apart.",
        k.pair(k.row(4), k.row(4), k.gap_of(1)),
    ),
    _c(
        "dim-20",
        DIM,
        "Please build a staircase with steps 5 centimetres high, 20 centimetres in total height.",
        one(k.staircase(4)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Tower of six, but not at the front — I can't see the front on the camera.",
        one(T(6), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-02",
        NEG,
        "A shelf, but no plank this time: two uprights of three with cubes across the top instead.",
        one(_bar_on_posts(3, 3), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "Two towers of four, not touching, and neither of them in the foreground.",
        k.each(2, T(4), k.not_(reg("front"), "in the foreground")),
    ),
    _c(
        "neg-04",
        NEG,
        "A pyramid of three levels, no beams at all.",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-05",
        NEG,
        "Please build a row of five cubes that does not run from front to back.",
        one(k.row(5), k.runs("y")),
    ),
    _c(
        "neg-06",
        NEG,
        "Don't build anything on the right — just a 2x2 block, two high, on the left.",
        one(k.block(2, 2, 2), reg("left")),
    ),
    _c(
        "neg-07",
        NEG,
        "A frame of cubes, four by four, one course, but leave one cube out of the back side.",
        one(
            k.dims(4, 4),
            k.height(1),
            k.parts(11),
            k.not_(k.ring, "closed"),
            _missing_on(_B),
        ),
    ),
    _c(
        "neg-08",
        NEG,
        "A tower of five that isn't in the centre of frame.",
        one(T(5), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-09",
        NEG,
        "A 3x4 slab, one layer, less the two middle cubes.",
        one(k.ring_of(1, (1, 2)), k.dims(3, 4), k.parts(10)),
    ),
    _c(
        "neg-10",
        NEG,
        "Please build a table with four legs three cubes high, but please don't use any beams "
        "for the top.",
        one(_roof_on(4, 3), k.only_cubes),
    ),
    _c(
        "neg-11",
        NEG,
        "Staircase of three steps, not climbing towards the robot.",
        one(k.staircase(3), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-12",
        NEG,
        "Two uprights of four, no plank — leave them free-standing, a cube apart.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "neg-13",
        NEG,
        "A wall five long and three high, and nothing else in shot.",
        one(k.wall(5, 3)),
    ),
    _c(
        "neg-14",
        NEG,
        "Two towers of five, no gap between them.",
        one(k.cell_heights(5, 5)),
    ),
    _c(
        "neg-15",
        NEG,
        "Please build a tower of four cubes, but not on the left-hand side of the table and not "
        "at the back.",
        one(T(4), k.not_(reg("left"), "on the left"), k.not_(reg("back"), "at the back")),
    ),
    # ------------------------------------------------------------------ typo
    _c(
        "typo-01",
        TYP,
        "Sorry, laggy keyboard: towerr of fivve at the back.",
        one(T(5), reg("back")),
    ),
    _c("typo-02", TYP, "Two uprigths of three with a plnak across.", one(_beam_bridge(3))),
    _c(
        "typo-03",
        TYP,
        "Pyramdi of two levles in the forground.",
        one(k.pyramid(2), reg("front")),
    ),
    _c("typo-04", TYP, "A slba of 2 by 5, one layre.", one(k.block(2, 5, 1))),
    _c("typo-05", TYP, "Please biuld a staircsae of three steps.", one(k.staircase(3))),
    _c(
        "typo-06",
        TYP,
        "Wall fuor long, two hihg, on the rigth.",
        one(k.wall(4, 2), reg("right")),
    ),
    _c("typo-07", TYP, "A fraem of cubes 5x5, one cuorse.", one(_ring(5, 1))),
    _c(
        "typo-08",
        TYP,
        "Towr of 6 in the backgruond, left of fraem.",
        one(T(6), reg("back left")),
    ),
    _c(
        "typo-09",
        TYP,
        "Tow towers of three, one cueb apart.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "typo-10",
        TYP,
        "Plaese place a row of six cubse across the front of the tabel.",
        one(k.row(6), k.runs("y"), reg("front")),
    ),
    _c(
        "typo-11",
        TYP,
        "3x3 blcok, 2 hgih, in the midle.",
        one(k.block(3, 3, 2), reg("centre")),
    ),
    _c(
        "typo-12",
        TYP,
        "Lay a 4x4 slab one course thcik, then a towr of 2 on top in the centr.",
        one(k.on_top(T(2), k.block(4, 4, 1)), k.centred(), k.levels(16, 1, 1)),
    ),
    _c(
        "typo-13",
        TYP,
        "Two towres, four and seven, side by sdie.",
        _by(4, T(7), max_gap=0.25),
    ),
    _c("typo-14", TYP, "A tower of eihgt, less too.", one(T(6))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "At the back right — a tower of three, please.", one(T(3), reg("back right"))),
    _c("wo-02", WO, "Three courses high and four long, that wall.", one(k.wall(4, 3))),
    _c(
        "wo-03",
        WO,
        "In the foreground on the left, a 2 by 2 block one high.",
        one(k.block(2, 2, 1), reg("front left")),
    ),
    _c(
        "wo-04",
        WO,
        "Five cubes high, one tower, centre of the table.",
        one(T(5), reg("centre")),
    ),
    _c(
        "wo-05",
        WO,
        "Of three levels, a pyramid, please, at the back of the table.",
        one(k.pyramid(3), reg("back")),
    ),
    _c(
        "wo-06",
        WO,
        "On top of a 3x3 slab one layer thick, a tower of three.",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.levels(9, 1, 1, 1)),
    ),
    _c("wo-07", WO, "Across two uprights of two, a plank.", one(_beam_bridge(2))),
    _c(
        "wo-08",
        WO,
        "Behind the tower of two, a tower of five, a cube's gap between them.",
        k.pair(T(5), T(2), k.gap_of(1, _B)),
    ),
    _c(
        "wo-09",
        WO,
        "Four steps — staircase — climbing to the left.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "wo-10",
        WO,
        "Running from front to back along the right-hand side, please build a row of five cubes.",
        one(k.row(5), k.runs("x"), reg("right")),
    ),
    _c(
        "wo-11",
        WO,
        "Two high and six long: a wall, along the front.",
        one(k.wall(6, 2), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-12",
        WO,
        "To the left of a 2x2 block two courses high, put a tower of four.",
        _by(4, k.block(2, 2, 2), _L),
    ),
    _c(
        "wo-13",
        WO,
        "Dead centre of frame is where the ring goes: four by four, one high.",
        one(_ring(4, 1), reg("centre")),
    ),
    _c(
        "wo-14",
        WO,
        "Three cubes wide, two cubes deep, two high — one block.",
        one(k.block_xy(2, 3, 2)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi, can you hear me? I'm on the train so the signal might drop. Anyway: a tower of four "
        "at the front left. Speak soon.",
        one(T(4), reg("front left")),
    ),
    _c(
        "fil-02",
        FIL,
        "Measure twice, cut once, as my old gaffer used to say. A wall, five long, two high, "
        "please.",
        one(k.wall(5, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Lovely light in here this morning. For shot 14 of 30, could I have a pyramid of three "
        "levels in the centre?",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-04",
        FIL,
        "Ref PO-20931, cost centre 4410. One tower of six cubes. Thanks.",
        one(T(6)),
    ),
    _c(
        "fil-05",
        FIL,
        "Good afternoon! We have twelve children coming at four o'clock for the maker club. "
        "Could you please build a staircase of four steps for them?",
        one(k.staircase(4)),
    ),
    _c(
        "fil-06",
        FIL,
        "You've gone all pixelated on my end, but I think you can still read this: a row of six "
        "along the back, please.",
        one(k.row(6), k.runs("y"), reg("back")),
    ),
    _c(
        "fil-07",
        FIL,
        "Been at the bench since seven and my coffee's gone cold. Two uprights of two with a "
        "plank on top, when you're ready.",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-08",
        FIL,
        "We're on a tight schedule, three setups before lunch. First setup: a 2 by 3 block, two "
        "high, at the back.",
        one(k.block(2, 3, 2), reg("back")),
    ),
    _c(
        "fil-09",
        FIL,
        "Month-end close, so I'll be quick: two towers of three, a cube apart. Ta.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-10",
        FIL,
        "The robotics books are at shelf mark 629.8, by the way. Anyway, please could you build "
        "a tower of five cubes?",
        one(T(5)),
    ),
    _c(
        "fil-11",
        FIL,
        "Can you see my screen? No? Never mind. A ring, five by five, one high.",
        one(_ring(5, 1)),
    ),
    _c(
        "fil-12",
        FIL,
        "Twenty-odd years of joinery and I've never had a robot do the donkey work. A 3 by 3 "
        "slab, one course.",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "fil-13",
        FIL,
        "I've got the 50 mm lens on, so keep it compact: a tower of three on the right.",
        one(T(3), reg("right")),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Tower of four in the back left corner, where the camera can see it.",
        one(T(4), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "Put a 2x2 block, two courses, in the front right corner.",
        one(k.block(2, 2, 2), reg("front right")),
    ),
    _c(
        "reg-03",
        REG,
        "A row of five right across the background.",
        one(k.row(5), k.runs("y"), reg("back")),
    ),
    _c(
        "reg-04",
        REG,
        "A tower of five at x = 0.5, y = 0.4.",
        one(T(5), k.near(0.50, 0.40, 0.02)),
    ),
    _c(
        "reg-05",
        REG,
        "Please place a pyramid of two levels in the centre of the table.",
        one(k.pyramid(2), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "Wall four long, two high, along the right-hand edge.",
        one(k.wall(4, 2), k.runs("x"), _edge(_R)),
    ),
    _c("reg-07", REG, "Stand a tower of six in the middle of the table.", one(T(6), reg("centre"))),
    _c(
        "reg-08",
        REG,
        "Foreground, centre of frame: a 3 by 3 slab, one layer.",
        one(k.block(3, 3, 1), reg("front"), _FRAME_MID),
    ),
    _c(
        "reg-09",
        REG,
        "A row of four cubes, centred at x = 0.3, y = 0.3.",
        one(k.row(4), k.near(0.30, 0.30, 0.02)),
    ),
    _c(
        "reg-10",
        REG,
        "Please build a wall six cubes long and two high at the back of the table, running left "
        "to right.",
        one(k.wall(6, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "reg-11",
        REG,
        "Two towers of three: one at the front left, one at the back right.",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "Put a staircase of three steps over on the left, well back from the robot.",
        one(k.staircase(3), reg("back left")),
    ),
    _c(
        "reg-13",
        REG,
        "Tower of four, hard up against the left edge of the table.",
        one(T(4), _hard_up(_L)),
    ),
    _c(
        "reg-14",
        REG,
        "A 2 by 2 block, one layer, in each of the four corners of the table.",
        k.structures(*[k.all_of(k.block(2, 2, 1), reg(r)) for r in _CORNERS]),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Build whatever you like, I just want to check the camera feed works.",
        k.anything,
    ),
    _c(
        "open-02",
        OPEN,
        "Something with a plank in it, your choice.",
        k.all_of(k.anything, k.layout(_has_beam)),
    ),
    _c(
        "open-03",
        OPEN,
        "Give me something tall for the back of the shot — you choose what.",
        k.all_of(k.anything, k.layout(reg("back")), k.some(k.height(lo=_TALL))),
    ),
    _c(
        "open-04",
        OPEN,
        "Any structure you like, using no more than ten cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-05",
        OPEN,
        "Please surprise the children with something of your choosing — nothing taller than "
        "four cubes.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-06",
        OPEN,
        "Any two structures you like, but keep them apart.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-07",
        OPEN,
        "Knock something together with a gap underneath it — a shelf, a bridge, whatever.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-08",
        OPEN,
        "Something small and tidy in the centre of frame, your choice.",
        k.all_of(k.small, k.layout(reg("centre"))),
    ),
    _c(
        "open-09",
        OPEN,
        "Use exactly eight cubes, any shape, no beams.",
        k.all_of(k.anything, k.layout(k.all_of(_cubes(8, 8), k.only_cubes))),
    ),
    _c(
        "open-10",
        OPEN,
        "Please build anything you like, as long as it has steps in it.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-11",
        OPEN,
        "Put up whatever you fancy on the left half of the table.",
        k.all_of(k.anything, k.layout(_min_y(0.30))),
    ),
    _c(
        "open-12",
        OPEN,
        "A few towers, any heights, lined up left to right.",
        k.any_of(*[k.in_order("y", *[T(lo=1, hi=10)] * n) for n in (3, 4)]),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "You cut out there — just build what I said before the call dropped.",
        k.honest(k.anything),
    ),
    _c(
        "bad-02",
        BAD,
        "My screen's frozen, don't start anything until I call you back.",
        k.honest(),
    ),
    _c(
        "bad-03",
        BAD,
        "Two uprights of three and a plank 40 cm long across them.",  # planks are 15 cm
        k.honest(one(_span(3))),
    ),
    _c(
        "bad-04",
        BAD,
        "Saw a cube in half and put both halves on top of a tower of three.",
        k.honest(one(T(lo=3, hi=4))),
    ),
    _c(
        "bad-05",
        BAD,
        "A tower of twelve cubes for a dramatic low-angle shot.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-06", BAD, "Can you paint the cubes red for the photo?", k.honest()),
    _c("bad-07", BAD, "A tower of three cubes, less five.", k.honest(k.anything)),
    _c(
        "bad-08",
        BAD,
        "A wall 1.2 metres long, two high.",  # 24 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-09",
        BAD,
        "Please build a tower of three and a half cubes.",
        k.honest(one(T(lo=3, hi=4))),
    ),
    _c(
        "bad-10",
        BAD,
        "Could you please recommend a good book on robotics for our readers?",
        k.honest(),
    ),
    _c("bad-11", BAD, "Can you build a tower of fi", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-12",
        BAD,
        "A tower of four that's also six high.",
        k.honest(one(k.any_of(T(4), T(6)))),
    ),
    _c("bad-13", BAD, "Make it look like the Eiffel Tower.", k.honest(k.anything)),
    _c("bad-14", BAD, "Same as last quarter's order, please.", k.honest(k.anything)),
    _c(
        "bad-15",
        BAD,
        "Please build a round tower, a perfect cylinder.",
        k.honest(k.anything),
    ),
    _c("bad-16", BAD, "Tower of three. Actually, cancel that, build nothing.", k.honest()),
    _c("bad-17", BAD, "jjjkkk;;;lll", k.honest()),
    _c(
        "bad-18",
        BAD,
        "Stand a tower of four on top of the camera case I left on the table.",
        k.honest(k.anything),
    ),
]
