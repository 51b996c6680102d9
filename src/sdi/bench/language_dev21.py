"""A twenty-first held-out set for the language front end (dev21): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev19` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a Spanish- or Portuguese-speaking operator writing English with Romance word order and false
  friends: "a tower of 4 cubes of height" (4 high), "realize a wall" (build one), "in the
  right part" (on the right side), "actually" (currently, never a correction), "large" (long,
  from largo), "per" (by, from por), "floors" (levels), "quit" (remove, from quitar), "pretend"
  (intend), "near to the robot" (at the front). Two commands are wholly in Spanish or
  Portuguese (bad input: a refusal or a noted reading);
* a German-speaking operator: compound-like phrasing ("a 3-high tower, left beside it a row"),
  the verb at the end ("a tower in the middle build"), "bitte", "also" (so), "so high" (as
  high: "half so high" is half as high), "become" (get), "lang" (long). Two commands are wholly
  in German (bad input);
* an architect using building vocabulary. A storey or a course is one cube level; a column or
  pier is a one-cube tower; a colonnade is separate columns of one height in one line (evenly
  spaced when a spacing is said); a plinth is a one-course slab with something standing on it;
  a lintel is a beam or a row of cubes across the tops of two columns (the shared `bridge`,
  or a bar of cubes bearing on both); a portico is columns under one connected roof (beams, or
  a slab of cubes bearing on every column); a terrace is a staircase (rising away from the
  street, i.e. the front, when said); a setback storey is a smaller full storey on the one
  below; a footprint is the plan size in cubes. A cantilever is built as a beam capping a
  column and overhanging it, or refused; a dome is bad input;
* a new user who has never used the tool and asks or hedges ("could it maybe do a small
  bridge? not too big I guess"). A question that names a structure is a request for it;
  "small" is at most 4 cubes high and 5 long overall; a stated size with "maybe" or "like" is
  still the size wanted;
* an operator who edits the request in the same message: replaced numbers ("four — make that
  five"), moved places ("front left — no, the back left"), removals ("forget the wall", "take
  away the one on the right"), "same again but smaller". Only the last version counts.

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the middle one"),
distributive phrases ("a column on each corner"), comparisons ("the double of cubes"),
corrections, removals and unusable input (gibberish, other languages, contradictions, sizes
past the cell, references to nothing built).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a lintel or bridge span as a
beam or a bar of cubes, "next to" as apart or touching where the operator did not say, a stem
of a T counted with or without the bar — and nothing else. Geometry comes only from
`sdi.bench.boxes`, through the shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 m; left = +y, back = +x (away from the
robot at x = 0, y = 0.30); the front is the robot's side (small x).
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
    return Case(id=f"dev21-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _post(h: int | None) -> k.Check:
    """A column or pier: a one-cube tower `h` high (any height when None)."""
    return k.tower(h) if h is not None else k.tower(lo=1, hi=10)


def _top_on_posts(posts: int | None = None, mouth: int | None = None, n: int = 2) -> k.Check:
    """`n` separate posts `posts` cubes high (any height when None), for two posts `mouth`
    cubes apart (± 1.5 cm) when given, and as the topmost level one connected piece resting on
    every post — a beam, a bar of cubes or a slab of cubes (the shared `legs_roof` wants every
    part of the top piece to bear on something, so it misses a bar of cubes across a gap)."""

    def f(bs: k.Boxes) -> k.Reason:
        z = max(round(b.lo[2], 3) for b in bs)
        top = [b for b in bs if round(b.lo[2], 3) == z]
        below = [b for b in bs if round(b.lo[2], 3) != z]
        legs = bx.components(below) if below else []
        if len(legs) != n or len(bx.components(top)) != 1:
            return f"not one top piece on {n} separate posts"
        for g in legs:
            r = _post(posts)(g)
            if r:
                return f"post: {r}"
            if not any(bx.rests_on(p, q) for p in top for q in g):
                return "the top piece does not rest on every post"
        if mouth is not None and n == 2:
            gap = bx.separation(legs[0], legs[1])
            if abs(gap - mouth * bx.CUBE) > 0.015:
                return f"posts {gap:.3f} m apart, want {mouth} cube(s)"
        return None

    return f


def _lintel(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """A bridge, lintel or gate: two posts `posts` high, `mouth` cubes apart when given, with
    a beam or a bar of cubes across the top."""
    shared = k.bridge(posts, pillars=2)
    if mouth is not None:
        shared = k.all_of(shared, k.leg_gap(mouth))
    return k.any_of(shared, _top_on_posts(posts, mouth))


def _portico(legs: int, h: int) -> k.Check:
    """`legs` columns `h` high under one connected roof (beams, or a slab of cubes)."""
    return k.any_of(k.legs_roof(legs=legs, leg_lo=h, leg_hi=h), _top_on_posts(h, n=legs))


def _tall_side(side: str) -> k.Check:
    """The tallest column(s) of one structure lie on `side` of the rest of it."""

    def f(bs: k.Boxes) -> k.Reason:
        cols = bx.columns(bs)
        top = max(bx.top(c) for c in cols)
        tall = [b for c in cols if bx.top(c) >= top - bx.TOL for b in c]
        rest = [b for c in cols if bx.top(c) < top - bx.TOL for b in c]
        if not rest:
            return "no lower part"
        got = bx.side_of(tall, rest)
        return None if got == side else f"the tall part is {got} of the rest, want {side}"

    return f


def _lies(check: k.Check, side: str) -> k.Pred:
    """Some structure passing `check` lies on `side` of every other structure."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        for g in comps:
            if check(g) is not None:
                continue
            if all(bx.side_of(g, h) == side for h in comps if h is not g):
                return None
        return f"no such structure {side} of all the others"

    return f


def _stairs_plus(steps: int, extra: int) -> k.Check:
    """A staircase of `steps` with a tower of `extra` cubes standing on one cell of its top
    step."""

    def f(bs: k.Boxes) -> k.Reason:
        cols = bx.columns(bs)
        tall = max(cols, key=bx.top)
        if len(tall) <= extra:
            return "no tower on the top step"
        added = tall[-extra:]
        rest = [b for b in bs if all(b is not a for a in added)]
        r = k.staircase(steps)(rest) or k.tower(extra)(added)
        if r:
            return r
        if abs(min(a.lo[2] for a in added) - bx.top(rest)) > bx.TOL:
            return "the tower does not stand on the top step"
        return None

    return f


def _min_side(n: int) -> k.Check:
    """The shorter footprint side is at least `n` cubes."""

    def f(bs: k.Boxes) -> k.Reason:
        a = bx.plan_dims(bs)[0]
        return None if a >= n else f"footprint {bx.plan_dims(bs)}, want ≥ {n} each way"

    return f


def _inset(m: float) -> k.Check:
    """Every part at least `m` metres inside the workspace's sides (away from the edges)."""

    def f(bs: k.Boxes) -> k.Reason:
        (x0, x1), (y0, y1), _ = bx.WORKSPACE
        lo, hi = bx.bounds(bs)
        if lo[0] < x0 + m - bx.TOL or hi[0] > x1 - m + bx.TOL:
            return f"within {m} m of the front or back edge"
        if lo[1] < y0 + m - bx.TOL or hi[1] > y1 - m + bx.TOL:
            return f"within {m} m of the left or right edge"
        return None

    return f


def _capped(h: int, over: int) -> k.Check:
    """A one-cube column `h` high capped by a single top piece, one level thick, resting on it
    and overhanging it by `over` cubes (± 1 cm) on both ends along one axis (a cantilever)."""

    def f(bs: k.Boxes) -> k.Reason:
        below, above = bx.split_at(bs, h * bx.CUBE)
        r = k.tower(h)(below) if below else "no column"
        if r:
            return f"column: {r}"
        if not above or bx.thickness_cubes(above) != 1 or len(bx.components(above)) != 1:
            return "not one cap, one level thick"
        if not bx.stands_on(above, below):
            return "the cap does not rest on the column"
        (alo, ahi), (blo, bhi) = bx.bounds(above), bx.bounds(below)
        for i in (0, 1):
            a, b = blo[i] - alo[i], ahi[i] - bhi[i]
            if abs(a - over * bx.CUBE) <= 0.01 and abs(b - over * bx.CUBE) <= 0.01:
                return None
        return f"the cap does not overhang {over} cube(s) on both ends"

    return f


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


def _colonnade(lo: int = 3) -> k.Pred:
    """At least `lo` separate columns, all one height of at least 2, in one line along x or y
    (any spacing)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < lo:
            return f"{len(comps)} separate structures, want ≥ {lo}"
        h = bx.thickness_cubes(comps[0])
        if h < 2:
            return "columns under 2 cubes high"
        return k.in_line(len(comps), k.tower(h))(result)

    return f


def _nothing_built(result: Mapping[str, Any]) -> k.Reason:
    """Nothing ends up on the table: an error or failure, or an empty layout."""
    if result.get("status") in ("error", "failure"):
        return None
    return None if not bx.objects(result) else "something was built"


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
_ARCH = k.any_of(k.arch, _top_on_posts())  # anything spanning a gap, bars of cubes too


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Realize a tower of 4 cubes of height and, at its left, a wall of 3 of length and 2 of "
        "height, separated by one cube.",
        k.pair(k.wall(3, 2), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "rel-02",
        REL,
        "A 3-high tower, left beside it a row of 4 cubes, one cube gap between, bitte.",
        k.pair(k.row(4), T(3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-03",
        REL,
        "Two columns, four storeys each, 10 cm clear between them, with a lintel across the top.",
        one(_lintel(4, 2)),
    ),
    _c(
        "rel-04",
        REL,
        "Could it put a little tower next to a bigger one? Like 2 cubes and 5 cubes, not "
        "touching I guess?",
        k.pair(T(2), T(5), _near),
    ),
    _c(
        "rel-05",
        REL,
        "Wall of 5 long and 2 high at the back, and a tower of 3 in front of it. Hmm, no, put "
        "the tower behind the wall instead.",
        k.pair(T(3), k.wall(5, 2), k.on_side(_B)),
    ),
    _c(
        "rel-06",
        REL,
        "A colonnade of five columns, three storeys each, running left to right, one cube of "
        "clear space between neighbouring columns.",
        k.in_order("y", *[T(3)] * 5, gaps=(1,)),
    ),
    _c(
        "rel-07",
        REL,
        "Put a pyramid of 2 floors in the right part, and at its side, more to the left, a "
        "tower of 5 cubes of height.",
        k.all_of(
            k.pair(T(5), k.pyramid(2), k.on_side(_L)),
            k.some(k.pyramid(2), reg("right")),
        ),
    ),
    _c(
        "rel-08",
        REL,
        "Two towers of 4 and between them please a tower of 2 build.",
        k.any_of(k.between_(T(2), T(4)), one(k.flat, k.profile(4, 2, 4))),
    ),
    _c(
        "rel-09",
        REL,
        "Is it ok to put a small pyramid on top of a block? Maybe a 3 by 3 block two high, with "
        "a pyramid of 2 levels sitting on it?",
        one(k.on_top(k.pyramid(2), k.block(3, 3, 2))),
    ),
    _c(
        "rel-10",
        REL,
        "Three towers of 3 in a line from left to right, a cube apart. Actually take away the "
        "one on the right, just leave two.",
        k.pair(T(3), T(3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-11",
        REL,
        "A 4 by 4 plinth, one course high, with a single column of three storeys standing on "
        "each of its corners.",
        one(k.plan_heights("4114", "1111", "1111", "4114")),
    ),
    _c(
        "rel-12",
        REL,
        "A wall, 6 long and 2 high, and in front of it, one cube away, a 2x2 block of one "
        "layer, please.",
        k.pair(k.block(2, 2, 1), k.wall(6, 2), k.gap_of(1, _F)),
    ),
    _c(
        "rel-13",
        REL,
        "Would it be able to make a bridge with a little tower next to it on each side? Towers "
        "2 high maybe, I'm not sure about the bridge.",
        k.between_(_ARCH, T(2)),
    ),
    _c(
        "rel-14",
        REL,
        "I need two towers of 3 cubes of height in the back part and, in front of the two, a "
        "row of 4 cubes.",
        k.all_of(
            k.structures(k.all_of(T(3), reg("back")), k.all_of(T(3), reg("back")), k.row(4)),
            _lies(k.row(4), _F),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "Please a staircase with 3 steps, and on the highest step a tower of 2 cubes more put.",
        one(_stairs_plus(3, 2)),
    ),
    _c(
        "rel-16",
        REL,
        "A portico: four columns of three storeys on the corners of a square, one cube clear "
        "between them each way, carrying a flat roof.",
        one(_portico(4, 3), k.dims(3, 3)),
    ),
    _c(
        "rel-17",
        REL,
        "A tower of 6 in the middle and a row of 3 on either side of it... wait, just one row, "
        "on its right.",
        k.any_of(
            k.all_of(k.pair(k.row(3), T(6), k.on_side(_R)), k.some(T(6), reg("centre"))),
            one(k.cell_heights(6, 1, 1, 1), _tall_side(_L)),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "Mount a tower of 5 cubes in the centre and four cubes alone around it, one at each "
        "side, separated from it by one cube.",
        k.all_of(k.on_every_side(T(5), T(1), 1), k.some(T(5), reg("centre"))),
    ),
    _c(
        "rel-19",
        REL,
        "Two walls, each 5 long and 3 high, parallel, with 2 cubes space between, like a "
        "corridor, bitte.",
        k.pair(k.wall(5, 3), k.wall(5, 3), k.parallel_gap(2)),
    ),
    _c(
        "rel-20",
        REL,
        "A 3 by 3 slab, one course, with a 2-storey column standing on its rear left corner.",
        one(k.plan_heights("311", "111", "111"), k.upper_side(_B, 1), k.upper_side(_L, 1)),
    ),
    _c(
        "rel-21",
        REL,
        "um, can the robot put a row of 4 behind a tower? the tower like 3 high? sorry if "
        "that's a dumb question",
        k.pair(k.row(4), T(3), k.on_side(_B)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Build a tower of 5, then another one of 5 to the right of it. Hmm, make the second "
        "one 3 instead.",
        k.pair(T(3), T(5), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "seq-02",
        SEQ,
        "First a 3x3 plate, one layer, then on it in the middle a tower of 3, bitte.",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "First realize a wall of 4 of length and 3 of height, and after, quit the row of above.",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Lay a 4 by 4 plinth first, then raise a single 2 by 2 storey on it, set back the same "
        "from every edge.",
        one(k.plan_heights("1111", "1221", "1221", "1111")),
    ),
    _c(
        "seq-05",
        SEQ,
        "Maybe start with a row of 5? And then, if it can, a second row of 5 on top of that one.",
        one(k.wall(5, 2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "Stack 4 cubes here in the middle, then the same again on its left but smaller, 2 cubes.",
        k.all_of(
            k.pair(T(2), T(4), k.all_rels(k.on_side(_L), _near)),
            k.some(T(4), reg("centre")),
        ),
    ),
    _c(
        "seq-07",
        SEQ,
        "Build a 5 tower. Then take from it 2 cubes away and make with them a second tower beside.",
        k.pair(T(3), T(2), _near),
    ),
    _c(
        "seq-08",
        SEQ,
        "Put a pyramid of 3 floors and after quit the cube of the top and the floor below it.",
        one(k.full, k.height(1), _min_side(3)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Set out two piers of four storeys, 5 cm clear of each other, then drop a lintel "
        "across them.",
        one(_lintel(4, 1)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Could it build a small staircase first, like 3 steps, and then maybe a tower of 3 next "
        "to the top step? Or is that too much.",
        k.any_of(
            k.pair(T(3), k.staircase(3), _near),
            one(k.cell_heights(1, 2, 3, 3)),
        ),
    ),
    _c(
        "seq-11",
        SEQ,
        "A row of 6 along the front. Oh and build it up: make it two layers. No, three.",
        one(k.wall(6, 3), reg("front")),
    ),
    _c(
        "seq-12",
        SEQ,
        "First a wall of 5, 2 high, running left to right, then on its left end a tower of 4 "
        "— on the wall, not beside it.",
        one(k.lr_profile(6, 2, 2, 2, 2)),
    ),
    _c(
        "seq-13",
        SEQ,
        "First a tower of 3 cubes. After, at 1 cube of distance to the back, other equal. And "
        "after, other more to the back, also at 1 cube.",
        k.in_order("x", T(3), T(3), T(3), gaps=(1,)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Start with a terrace of three steps climbing away from the street side, which is the "
        "front, then add a fourth step at the top.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "seq-15",
        SEQ,
        "I'd like to try a bridge? Pillars of 2 maybe. And after that, um, a second bridge just "
        "like it, behind the first one?",
        k.pair(_lintel(2), _lintel(2), k.on_side(_B)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Build three towers, of 2, 3 and 4, in a line. Then remove the middle one.",
        k.structures(T(2), T(4)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Make please a 2x2 tower, 3 high; then on it one cube on each corner... no, only on "
        "one corner.",
        one(k.plan_heights("43", "33")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Actually the table is empty. First put a wall of 4 of length and 2 of height in the "
        "left part, after a tower of 3 in the right part.",
        k.structures(k.all_of(k.wall(4, 2), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "seq-19",
        SEQ,
        "Build a solid 3 by 3 footprint three storeys high, then take away the top storey "
        "except its centre cell.",
        one(k.plan_heights("222", "232", "222")),
    ),
    _c(
        "seq-20",
        SEQ,
        "so first a tower of 4? then, hmm, could you take the top one off and put it next to "
        "the tower, on the table? like on its left",
        k.any_of(
            k.pair(T(1), T(3), k.all_rels(k.on_side(_L), _near)),
            one(k.cell_heights(3, 1), _tall_side(_R)),
        ),
    ),
    _c(
        "seq-21",
        SEQ,
        "Put a 2x2 block, 2 high, at the back right. Then move it to the front left, and add "
        "one more layer while you're at it.",
        one(k.block(2, 2, 3), reg("front left")),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "Realize a tower with half a dozen cubes plus one.", one(T(7))),
    _c(
        "num-02",
        NUM,
        "Please a row of ten cubes, all in one line from left to right.",
        one(k.row(10), k.runs("y")),
    ),
    _c(
        "num-03",
        NUM,
        "A colonnade of four columns, five storeys each.",
        k.in_line(4, T(5)),
    ),
    _c(
        "num-04",
        NUM,
        "I think I want... three? three towers, with 1, 2 and 3 cubes. if that's ok",
        k.structures(T(1), T(2), T(3)),
    ),
    _c(
        "num-05",
        NUM,
        "Four towers of 2, make that five, in a row, a cube apart.",
        k.in_line(5, T(2), 1),
    ),
    _c(
        "num-06",
        NUM,
        "Two towers: a small one of 3, and the other with the double of cubes.",
        k.structures(T(3), T(6)),
    ),
    _c(
        "num-07",
        NUM,
        "Three towers, the first 2 high and each next one 2 higher, bitte in one line.",
        k.line(T(2), T(4), T(6)),
    ),
    _c(
        "num-08",
        NUM,
        "A 3 by 4 ground-floor slab, one course: twelve modules in all.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-09",
        NUM,
        "not sure about the numbers, but maybe a pyramid with a 4 by 4 bottom? and it goes up "
        "till there's one on top?",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "num-10",
        NUM,
        "Make 3 stacks of 4. Actually two of them only. No, make it three again, but 3 high.",
        k.each(3, T(3)),
    ),
    _c(
        "num-11",
        NUM,
        "Put five cubes alone, separated, in a line of front to back, with one cube of space "
        "between each.",
        k.in_order("x", *[T(1)] * 5, gaps=(1,)),
    ),
    _c(
        "num-12",
        NUM,
        "Two pairs of towers: two of 2 on the left side and two of 5 on the right side.",
        k.structures(
            k.all_of(T(2), reg("left")),
            k.all_of(T(2), reg("left")),
            k.all_of(T(5), reg("right")),
            k.all_of(T(5), reg("right")),
        ),
    ),
    _c(
        "num-13",
        NUM,
        "A four-storey block on a 2 by 2 footprint, and next to it a two-storey one on the "
        "same footprint.",
        k.any_of(
            k.pair(k.block(2, 2, 2), k.block(2, 2, 4), _near),
            one(k.plan_heights("44", "44", "22", "22")),
        ),
    ),
    _c(
        "num-14",
        NUM,
        "how many cubes does a 3-step staircase take? 6 right? can it build that",
        one(k.staircase(3), k.parts(6)),
    ),
    _c(
        "num-15",
        NUM,
        "Two rows of 4 running left to right, one behind the other, a cube apart. Scrap that, "
        "three rows.",
        k.in_order("x", *[k.all_of(k.row(4), k.runs("y"))] * 3, gaps=(1,)),
    ),
    _c("num-16", NUM, "Construct a pyramid of three floors.", one(k.pyramid(3))),
    _c(
        "num-17",
        NUM,
        "A wall of eight long and half so high, please.",
        one(k.wall(8, 4)),
    ),
    _c(
        "num-18",
        NUM,
        "A colonnade of five columns across the width, alternating two and four storeys, "
        "starting and ending with two, one cube apart.",
        k.in_order("y", T(2), T(4), T(2), T(4), T(2), gaps=(1,)),
    ),
    _c(
        "num-19",
        NUM,
        "could I get like 10 single cubes? spread out however it likes",
        k.each(10, T(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Realize a wall of 30 centimetres of large and 15 of high.",
        one(k.wall(6, 3)),
    ),
    _c(
        "dim-02",
        DIM,
        "A block 10 by 15 by 20 centimetres, standing upright, bitte.",
        one(k.block(2, 3, 4)),
    ),
    _c("dim-03", DIM, "A column 35 centimetres tall on a single-cube footprint.", one(T(7))),
    _c(
        "dim-04",
        DIM,
        "A ground-floor slab with a 25 by 15 cm footprint, one course thick.",
        one(k.block(5, 3, 1)),
    ),
    _c(
        "dim-05",
        DIM,
        "could it do a wall maybe 20 cm long? and not too high, like 10 cm?",
        one(k.wall(4, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "A 4 by 4 platform, two high. Make it 3 by 5 instead, same height.",
        one(k.block(3, 5, 2)),
    ),
    _c(
        "dim-07",
        DIM,
        "A tower of 0.3 metres of height in the centre of the table.",
        one(T(6), reg("centre")),
    ),
    _c(
        "dim-08",
        DIM,
        "A staircase, 4 steps, every step 10 cm deep and one cube wide, each one cube higher.",
        one(k.profile(1, 1, 2, 2, 3, 3, 4, 4), k.flat),
    ),
    _c(
        "dim-09",
        DIM,
        "A terrace 3 cubes wide with three levels, each level one cube deep, rising towards "
        "the back.",
        one(k.staircase(3), k.rises(_B), k.dims(3, 3)),
    ),
    _c(
        "dim-10",
        DIM,
        "would a ring work? the outside about 25 cm square, one cube tall, hollow",
        one(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-11",
        DIM,
        "Wall 6 long, 3 high. No, keep it 6 long but 20 cm high.",
        one(k.wall(6, 4)),
    ),
    _c(
        "dim-12",
        DIM,
        "A platform of 20 per 20 centimetres and 5 of thickness.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "dim-13",
        DIM,
        "An L of 4 long and 3 wide, one layer, flat on the table, please.",
        one(k.shape_letter("L"), k.dims(3, 4), k.height(1)),
    ),
    _c(
        "dim-14",
        DIM,
        "A bridge with a 10 cm clear span on piers 15 cm high.",
        one(_lintel(3, 2)),
    ),
    _c(
        "dim-15",
        DIM,
        "i'm not sure what size, maybe a block around 10 cm each way? like a little cube made "
        "of cubes",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "dim-16",
        DIM,
        "A 2 by 6 slab. Sorry, I meant 6 long but only 1 wide, one high.",
        one(k.row(6)),
    ),
    _c(
        "dim-17",
        DIM,
        "Build a pyramid with the base of 5 per 5 and three floors.",
        one(k.pyramid(3), k.base(5, 5)),
    ),
    _c(
        "dim-18",
        DIM,
        "A hollow enclosure: outer footprint 6 by 4, walls one cube thick and two courses high.",
        one(k.ring_of(high=2, inner=(4, 2)), k.dims(4, 6)),
    ),
    _c(
        "dim-19",
        DIM,
        "A T out of cubes, the bar 5 long, the stem 3 more, flat on the table.",
        one(k.shape_letter("T"), k.height(1), k.any_of(k.dims(4, 5), k.dims(3, 5))),
    ),
    _c(
        "dim-20",
        DIM,
        "A three-storey column capped by a beam that cantilevers 5 cm out on both sides.",
        one(_capped(3, 1)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A tower of 5 cubes, but not in the centre: in the right part.",
        one(T(5), reg("right"), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-02",
        NEG,
        "A wall 5 long, 2 high, but without beams, only cubes, bitte.",
        one(k.wall(5, 2), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "A colonnade of four columns, three storeys, no lintel or roof on them, one cube between "
        "each.",
        k.in_line(4, T(3), 1),
    ),
    _c(
        "neg-04",
        NEG,
        "a tower of 4 maybe? but please not near the edge, I don't want it to fall off",
        one(T(4), _inset(0.05)),
    ),
    _c(
        "neg-05",
        NEG,
        "Three towers of 3 in a row. No, not three, just two, and don't let them touch.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-06",
        NEG,
        "A 3 by 3 platform of one cube of height, without the cube of the centre.",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "neg-07",
        NEG,
        "A pyramid of 3 levels, but the top cube please not.",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-08",
        NEG,
        "A two-storey enclosure, 4 by 4 outside, with no openings and no doorway.",
        one(k.ring_of(high=2, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "neg-09",
        NEG,
        "not a tower, more like a flat thing? 3 by 4 maybe, just one layer",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "neg-10",
        NEG,
        "Put a tower of 4 on the left and a wall of 4 by 2 on the right. Actually forget the wall.",
        one(T(4), reg("left")),
    ),
    _c(
        "neg-11",
        NEG,
        "Two towers of 3, not the one next to the other: one in the front part and the other "
        "in the back part.",
        k.structures(k.all_of(T(3), reg("front")), k.all_of(T(3), reg("back"))),
    ),
    _c(
        "neg-12",
        NEG,
        "Stairs of 4 steps, not upward to the back but to the left going.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "neg-13",
        NEG,
        "A solid 3 by 3 block of two storeys: no setback, no overhang, nothing hollow.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "neg-14",
        NEG,
        "can I have a bridge but without the beam thing on top? like just cubes?",
        one(_top_on_posts(), k.only_cubes),
    ),
    # ------------------------------------------------------------------ typo
    _c(
        "typo-01",
        TYP,
        "Realise a towre of 5 cubs in the rigth part.",
        one(T(5), reg("right")),
    ),
    _c("typo-02", TYP, "Bitte a wal of 4 lang and 3 hig.", one(k.wall(4, 3))),
    _c("typo-03", TYP, "a colonade of 3 colums, 4 storys each", k.in_line(3, T(4))),
    _c("typo-04", TYP, "can it maek a pyrmaid? 2 levles i think", one(k.pyramid(2))),
    _c("typo-05", TYP, "tower of 3 - no 6 - at the bakc", one(T(6), reg("back"))),
    _c("typo-06", TYP, "A brigde with pilars of 3 cubs", one(_lintel(3))),
    _c(
        "typo-07",
        TYP,
        "A staircaise with 5 stpes, going up to the rigth.",
        one(k.staircase(5), k.rises(_R)),
    ),
    _c(
        "typo-08",
        TYP,
        "a plinht 3x3, with a colum of 3 on it in the centre",
        one(k.plan_heights("111", "141", "111")),
    ),
    _c("typo-09", TYP, "sory i dont know how this works, a smal tower of 2 pls?", one(T(2))),
    _c(
        "typo-10",
        TYP,
        "two towrs of 4 nex to each other, actualy make them 5",
        k.pair(T(5), T(5), _near),
    ),
    _c("typo-11", TYP, "A slab of 4 per 2 and one cub of hight.", one(k.block(4, 2, 1))),
    _c(
        "typo-12",
        TYP,
        "pleas a ring of 5 x 5 cubse, 1 hihg",
        one(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c("typo-13", TYP, "a portcio of 4 colmns, 2 storyes, flat roof", one(_portico(4, 2))),
    _c(
        "typo-14",
        TYP,
        "is it posible to do a arch? nothig too big",
        k.all_of(k.small, one(_ARCH)),
    ),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "Please a tower of 4 cubes in the middle build.",
        one(T(4), reg("centre")),
    ),
    _c(
        "wo-02",
        WO,
        "On the left side a wall, 5 long and 2 high, you must build.",
        one(k.wall(5, 2), reg("left")),
    ),
    _c(
        "wo-03",
        WO,
        "Of 3 levels I want the pyramid, and in the back part.",
        one(k.pyramid(3), reg("back")),
    ),
    _c(
        "wo-04",
        WO,
        "To the right of the tower of 5 put a row of 3 cubes.",
        k.any_of(
            k.pair(k.row(3), T(5), k.on_side(_R)),
            one(k.cell_heights(5, 1, 1, 1), _tall_side(_L)),
        ),
    ),
    _c(
        "wo-05",
        WO,
        "Four storeys, on a single-cube footprint, in the back right corner: the column.",
        one(T(4), reg("back right")),
    ),
    _c(
        "wo-06",
        WO,
        "the staircase, 4 steps? is what I'd like, going up to the left",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "wo-07",
        WO,
        "Five high, no, four high, two of them, side by side with a cube between: towers.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "wo-08",
        WO,
        "Beside the bridge, on the right, a tower of 3 should stand. The bridge has pillars of 2.",
        k.pair(T(3), _lintel(2), k.on_side(_R)),
    ),
    _c(
        "wo-09",
        WO,
        "Of 4 cubes of height, two towers, one in the left part and one in the right part.",
        k.structures(k.all_of(T(4), reg("left")), k.all_of(T(4), reg("right"))),
    ),
    _c("wo-10", WO, "Across two 3-storey piers, 5 cm apart, a lintel.", one(_lintel(3, 1))),
    _c(
        "wo-11",
        WO,
        "In the front right corner, 2 by 2 and 3 high, a block, please.",
        one(k.block(2, 2, 3), reg("front right")),
    ),
    _c(
        "wo-12",
        WO,
        "on top of a 3 by 3 slab (is that a thing?) a tower of 2, in the middle",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "wo-13",
        WO,
        "At the front, a row of 5, make that 6, running left to right.",
        one(k.row(6), k.runs("y"), reg("front")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Good morning! Actually I am alone in the laboratory, so I have time. Please realize a "
        "tower of 6 cubes.",
        one(T(6)),
    ),
    _c(
        "fil-02",
        FIL,
        "So, ja, also, I am now back from the Mittagspause, and I would like a staircase with "
        "3 steps, bitte schön.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-03",
        FIL,
        "Client meeting got moved to Thursday so the massing study can wait; for now just give "
        "me a 2 by 4 slab, one course, as a plinth study.",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "fil-04",
        FIL,
        "Hi! First time using this, my colleague said it's easy. Sorry if I do this wrong. "
        "Could it make a wall? Like 4 long and 2 high?",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-05",
        FIL,
        "ok so I said a tower of 3 earlier but scratch that, different thing entirely today: a "
        "pyramid of 2 levels.",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-06",
        FIL,
        "Hello, how are you? I hope well. Look, I need for my experiment a row of 5 cubes, "
        "nothing more. Thank you very much, kisses.",
        one(k.row(5)),
    ),
    _c(
        "fil-07",
        FIL,
        "Guten Morgen! The coffee machine is broken again, typical. Anyway: two towers of 3, "
        "with one cube space between. Danke!",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-08",
        FIL,
        "We're doing a quick sketch model here, nothing precious, the sort of thing you'd knock "
        "up in foam: a bridge on two 3-storey piers.",
        one(_lintel(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Um. Okay. I've never done this. Is it listening? Okay. A block, 3 by 3, two high. I "
        "think that's how you say it.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-10",
        FIL,
        "Right, where were we, sorry, phone rang. Yes, the ring: 4 by 4, one high. Or no, let "
        "me think... yes, 4 by 4 is fine.",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "fil-11",
        FIL,
        "Sorry for my English, I am from Portugal. I want a staircase of 4 steps, if it is "
        "possible. Obrigado!",
        one(k.staircase(4)),
    ),
    _c(
        "fil-12",
        FIL,
        "Okay, we make it like this, so that it works: a 2 by 2 block, 4 high, in the middle, "
        "fertig.",
        one(k.block(2, 2, 4), reg("centre")),
    ),
    _c(
        "fil-13",
        FIL,
        "Forgive the jargon, I've been in planning meetings all week: a T-shaped footprint, one "
        "storey, bar of 3 and stem of 2.",
        one(k.shape_letter("T"), k.height(1), k.any_of(k.dims(3, 3), k.dims(2, 3))),
    ),
    _c(
        "fil-14",
        FIL,
        "Hallo, it is me again from the other lab, ja. Can I become a tower of 5, please?",
        one(T(5)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Put a tower of 3 cubes in the left part of the back.",
        one(T(3), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "Bitte a pyramid of 2 levels, right at the front, in the middle from left to right.",
        one(k.pyramid(2), reg("front"), k.near(y=0.30)),
    ),
    _c(
        "reg-03",
        REG,
        "Site the column, four storeys, at the rear of the plot, centred on the left-right axis.",
        one(T(4), reg("back"), k.near(y=0.30)),
    ),
    _c(
        "reg-04",
        REG,
        "could it put a small wall somewhere on the right? 3 long maybe, 2 high",
        one(k.wall(3, 2), reg("right")),
    ),
    _c(
        "reg-05",
        REG,
        "Tower of 5 in the front left... no, the back left corner.",
        one(T(5), reg("back left")),
    ),
    _c(
        "reg-06",
        REG,
        "A slab of 2 per 3 in the right part, near to the robot.",
        one(k.block(2, 3, 1), reg("front right")),
    ),
    _c(
        "reg-07",
        REG,
        "A row of 4 along the left edge, front to back, please.",
        one(k.row(4), k.runs("x"), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-08",
        REG,
        "Place a 3 by 3 plinth, with a single-storey column on its centre, in the middle of "
        "the site.",
        one(k.plan_heights("111", "121", "111"), reg("centre")),
    ),
    _c(
        "reg-09",
        REG,
        "um, the middle of the table? a tower of 3 there please, if it can reach",
        one(T(3), reg("centre")),
    ),
    _c(
        "reg-10",
        REG,
        "Put a staircase of 3 at the back right. Actually at the front right.",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "reg-11",
        REG,
        "Two towers of 2: one in the left part near to the robot, and the other in the right "
        "part far from the robot.",
        k.structures(k.all_of(T(2), reg("front left")), k.all_of(T(2), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "At x 0.6 and y 0.2 a tower of 3 cubes, please.",
        one(T(3), k.near(0.60, 0.20, 0.011)),
    ),
    _c(
        "reg-13",
        REG,
        "Set the enclosure, 4 by 4 outside, one course, in the front left quadrant.",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4), reg("front left")),
    ),
    _c(
        "reg-14",
        REG,
        "I'm not sure how the sides work, is left the robot's left? anyway a wall of 4 by 2 on "
        "the left please",
        one(k.wall(4, 2), reg("left")),
    ),
    _c(
        "reg-15",
        REG,
        "I pretend to make a row of 4 cubes near to the robot, in the middle of the width.",
        one(k.row(4), reg("front"), k.near(y=0.30)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Realize something pretty with 10 cubes, what you want.",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(10), k.only_cubes))),
    ),
    _c(
        "open-02",
        OPEN,
        "Build something tall, bitte, higher than 5 cubes.",
        k.all_of(k.anything, k.layout(k.height(lo=6))),
    ),
    _c(
        "open-03",
        OPEN,
        "Give me a massing study: any composition of at least two separate volumes.",
        k.all_of(k.anything, _count(2, 99)),
    ),
    _c(
        "open-04",
        OPEN,
        "so could it maybe do a small bridge? not too big I guess, whatever it thinks",
        k.all_of(k.small, one(_ARCH)),
    ),
    _c(
        "open-05",
        OPEN,
        "Something small, three cubes. No, make it five cubes in total, any shape.",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(5), k.only_cubes))),
    ),
    _c(
        "open-06",
        OPEN,
        "A little construction of your invention, not higher than 3 cubes.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-07",
        OPEN,
        "Any shape, but please only in the right half of the table.",
        k.all_of(k.anything, k.layout(reg("right"))),
    ),
    _c(
        "open-08",
        OPEN,
        "A folly for the garden. Your design, but it has to span something.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-09",
        OPEN,
        "I don't really know what to ask for. What can it build? Just do anything simple I guess.",
        k.anything,
    ),
    _c(
        "open-10",
        OPEN,
        "Build me two of anything. Or three. No, two's fine.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-11",
        OPEN,
        "Something with a colonnade feel: a few columns in a line, your call on height and number.",
        k.all_of(k.anything, _colonnade(3)),
    ),
    _c(
        "open-12",
        OPEN,
        "Surprise me with a staircase, the steps that you want.",
        k.all_of(k.anything, one(k.staircase())),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "Realize a tower of 15 cubes of height.",  # 15 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-02",
        BAD,
        "Bitte einen Turm aus vier Würfeln auf der linken Seite bauen.",
        k.honest(one(T(4), reg("left"))),
    ),
    _c(
        "bad-03",
        BAD,
        "Construa uma parede de cinco cubos de comprimento e dois de altura.",
        k.honest(one(k.wall(5, 2))),
    ),
    _c(
        "bad-04",
        BAD,
        "A cantilevered balcony projecting 20 cm from a single column, with nothing under it.",
        k.honest(k.anything),  # a 15 cm beam cannot reach out 20 cm
    ),
    _c("bad-05", BAD, "what is this thing? is it a robot? does it do coffee", k.honest()),
    _c(
        "bad-06",
        BAD,
        "A tower of 4. No, 6. No wait, scratch all of that, don't build anything.",
        k.any_of(k.honest(), _nothing_built),
    ),
    _c(
        "bad-07",
        BAD,
        "A wall of 3 metres of long.",  # 60 cubes: past the cell
        k.honest(one(k.wall())),
    ),
    _c(
        "bad-08",
        BAD,
        "A tower, 4 high and at the same time 7 high.",
        k.honest(one(k.any_of(T(4), T(7)))),
    ),
    _c(
        "bad-09",
        BAD,
        "A twelve-storey tower on a one-cube footprint.",  # 12 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-10",
        BAD,
        "A colonnade of fifteen columns, one cube apart, in a single line.",  # 29 cubes long
        k.honest(k.anything),
    ),
    _c("bad-11", BAD, "hello?? is this thing on?? ok never mind", k.honest()),
    _c(
        "bad-12",
        BAD,
        "Move the tower you built yesterday a bit to the left.",  # nothing was built
        k.honest(k.anything),
    ),
    _c(
        "bad-13",
        BAD,
        "Haz una torre de tres cubos en el centro, por favor.",
        k.honest(one(T(3), reg("centre"))),
    ),
    _c(
        "bad-14",
        BAD,
        "A staircase that goes up and down at the same time, with 0 steps.",
        k.honest(k.anything),
    ),
    _c("bad-15", BAD, "A geodesic dome 40 cm in diameter.", k.honest(k.anything)),
    _c("bad-16", BAD, "make it nice", k.honest(k.anything)),  # "it" names nothing
    _c(
        "bad-17",
        BAD,
        "Build a wall of 5 long, 2 high. Then remove the wall. Then remove the tower.",
        k.any_of(k.honest(), _nothing_built),  # there is no tower; nothing is left standing
    ),
    _c("bad-18", BAD, "A tower of minus three cubes.", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-19",
        BAD,
        "Ich möchte eine Brücke mit Pfeilern aus zwei Würfeln.",
        k.honest(one(_lintel(2))),
    ),
    _c(
        "bad-20",
        BAD,
        "A 30 by 30 cm plinth with a 50 cm column on it.",  # 1 + 10 levels: past the cell
        k.honest(one(k.on_top(T(lo=1, hi=9), k.block(6, 6, 1)))),
    ),
]
