"""A thirty-third held-out set for the language front end (dev33): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set (but dev27, the format example) or any benchmark
result, and worded apart from `language_dev` … `language_dev32` (no command shared with any
set, see tests). Nothing here was run through the system while it was written. The set is
deliberately mainstream: about 80 % of the commands are ordinary — one or two structures with
a size, a place, one relation or a two-step sequence, in plain but varied English — and they
come from five kinds of people, none of them used by an earlier set:

* a formal writer who puts everything in the passive voice: "A tower of four cubes is to be
  built at the back", "Two walls shall be placed …", "is required", "is to be laid". Preambles
  ("With reference to …", "In accordance with …", "Further to the minutes …") are filler;
* an operator who types the job as a short numbered list, one step per line ("1. Tower of 4
  front left\\n2. Take the top two off"). Every line adds to the one build, in order; a later
  line that changes or removes something replaces what it changes; "the first one" is the
  structure the first line built. A list with nothing on its lines is bad input;
* a British office worker with polite understatement: "if you wouldn't mind", "would you be
  so kind", "a smallish tower, nothing too ambitious", "perhaps three high", "about nine
  cubes". The courtesy is filler; a hedged figure ("perhaps three", "about eight", "say, two
  high") is still the figure; "little" / "smallish" with a figure adds nothing to it; "nothing
  too big" with no figure is the shared `small` (at most 4 cubes high and 5 long overall); a
  question that names a structure is a request for it; "on reflection" / "oh, sorry, I meant"
  replaces what it corrects; a request for tea is not a build (refusal only);
* an operator who compares sizes rather than counting: "a tall tower and a short one beside
  it", "a long row and a shorter one behind it", "a lower one", sometimes with one number for
  reference ("a tower of 3 and a taller one to its left"). A comparison is strict ("taller" is
  at least one cube taller, "shorter" at least one cube shorter in length, "lower" at least one
  cube lower) and nothing else about the compared size is checked; "tall" and "short" said of
  a pair only compare the two; "twice as tall", "half as tall", "a third of its height", "two
  cubes taller" are exact; "bigger" said after a height is the taller one;
* a warehouse picker turned cell operator, in plain words: a "stack" (or "pile", "one on top
  of the other") of N is a single column of N cubes, a "layer" is one level of cubes (a "layer
  3 by 2" a full one-level 3 × 2 slab), a "block A by B" (by C) a full A × B footprint (C high,
  the last figure the height), a "row" one cube thick and one high.

About 80 % ordinary and 20 % harder: three or more structures, references ("the first one",
"the bigger one", "the middle one", "that"), distributive phrases ("on each side of it", "in
all four corners", "one more on each end"), comparisons, removals ("take the top two off",
"remove the middle one", "the apex is to be removed"), corrections in the same message and
unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by its
  column heights); "right next to it" is at most 10 cm clear, or touching; "not touching", "a
  gap", "apart" mean separate structures; "touching" makes them one structure;
* "in front of", "behind", "to the left / right of" is the dominant direction between footprint
  centres (back = +x, front = -x, left = +y, right = -y), any distance when none is said, the
  two kept separate; a tower "behind" a wall, or "directly in front of" a tower, may also be
  set against it as one structure; "directly in front" puts the first's centre within the
  second's width; "in front of the middle of" a row also lines the centres up (± 3 cm);
* "N cubes apart" / "a cube's gap" / "one cube between" is the clear gap (± 1.5 cm); "10 cm
  apart" with no more said accepts the clear gap and the centre-to-centre reading (two cubes
  or one cube clear for single columns); "parallel" is the same long axis, side by side;
* a bridge's top is a beam (the shared `bridge`, overall height one more than the posts) where
  the command names a beam, and a beam or a bar of cubes where it does not; "just cubes along
  the top" is a bar of cubes only; a table is four separate legs under one connected top of
  beams or of cubes;
* a ring's stated size is its outside; "at its centre" / "sat in the middle" of a ring is
  inside its empty interior, clear of the ring, with the centres within 3 cm;
* a staircase's width is free unless given, and so is the way it climbs unless said; "remove
  the top step" accepts the top cube off (heights 1, 2, 3, 4, 4) or the whole last step off;
  a pyramid's step is free unless given, so a 3 × 3 base is 9-4-1 or 9-1, and with its apex
  removed 9-4 or the bare 3 × 3 layer;
* "A by B by C high" is a footprint A × B and C high; "2 wide, 4 long, 2 high" likewise;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the back edge" is every part at x ≥ 0.60, "the back half" every part at x ≥ 0.50,
  "the left half" every part at y ≥ 0.30 (the right half y ≤ 0.30), "far left" a footprint
  centre at y ≥ 0.45 and "far right" one at y ≤ 0.15, "the middle of the back edge" the back
  region on the centre line (y = 0.30 ± 3 cm), "not too close to the robot" outside the front
  region, "opposite sides of the table" the left and right regions or the front and back
  regions; a stated coordinate is the footprint centre ± 2 cm.

Bad input (a half-typed or empty command, gibberish, another language, contradictions, sizes
past the cell, shapes the cell cannot make such as a sphere, a cylinder or an upside-down
pyramid, a comparison with nothing on the table) is honest only as an error (or a failure) or
as a layout WITH notes naming the assumption (`k.honest`); a request that is not a build at all
admits only the refusal. Geometry comes only from `sdi.bench.boxes`, through the shared checks
in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 × 0.05 × 0.05 m; left = +y, back = +x
(away from the robot at x = 0, y = 0.30); the front is the robot's side (small x).
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

_MAX_H = 10  # cube levels the cell can hold


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev33-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _bar_on_posts(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Two separate posts lo–hi cubes high (any height when None) and, as the topmost level,
    one connected bar resting on both — a beam or a row of cubes."""

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
    """A bridge with no beam named: two posts `posts` high with a beam or a bar of cubes."""
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
    """A and B stand on opposite sides of the table: one in the left region and the other in
    the right, or one in the front region and the other in the back."""
    for ra, rb in ((_L, _R), (_R, _L), (_F, _B), (_B, _F)):
        if bx.region_problem(a, ra) is None and bx.region_problem(b, rb) is None:
            return None
    return "not on opposite sides of the table"


def _taller(by: int | None = None) -> k.Rel:
    """A is strictly taller than B (own height, in cubes); exactly `by` cubes taller when
    given."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        ha, hb = bx.thickness_cubes(a), bx.thickness_cubes(b)
        if by is not None:
            return None if ha - hb == by else f"{ha} vs {hb} high, want {by} taller"
        return None if ha > hb else f"{ha} high, not taller than {hb}"

    return rel


def _lower(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A is strictly lower than B (own height, in cubes)."""
    ha, hb = bx.thickness_cubes(a), bx.thickness_cubes(b)
    return None if ha < hb else f"{ha} high, not lower than {hb}"


def _shorter(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A's longer plan side is strictly shorter than B's."""
    la, lb = bx.plan_dims(a)[1], bx.plan_dims(b)[1]
    return None if la < lb else f"{la} long, not shorter than {lb}"


def _parallel(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B run along the same axis and stand side by side across it (not end to end)."""
    ax, ay = bx.footprint_cubes(a)
    bx_, by = bx.footprint_cubes(b)
    if ax == ay or bx_ == by:
        return "no long axis"
    if (ax > ay) != (bx_ > by):
        return "not parallel"
    side = bx.side_of(a, b)
    if ay > ax and side not in (_F, _B):
        return "end to end, not side by side"
    if ax > ay and side not in (_L, _R):
        return "end to end, not side by side"
    return None


def _two_columns(cmp: str, h: int | None = None) -> k.Check:
    """One structure of exactly two full columns on the table, set against each other: with
    `cmp` "unequal" any two different heights; with "taller" / "shorter" and `h`, one `h` high
    and the other strictly taller / shorter."""
    if cmp == "unequal":
        pairs = [(a, b) for a in range(1, _MAX_H + 1) for b in range(a + 1, _MAX_H + 1)]
    elif cmp == "taller" and h is not None:
        pairs = [(h, b) for b in range(h + 1, _MAX_H + 1)]
    elif cmp == "shorter" and h is not None:
        pairs = [(b, h) for b in range(1, h)]
    else:
        raise ValueError(cmp)
    return k.any_of(*[k.cell_heights(a, b) for a, b in pairs])


def _rising(axis: str, n: int, first: int, gaps: tuple[int, ...] = ()) -> k.Pred:
    """`n` separate towers in one line (front to back for "x", left to right for "y"), the
    first `first` high and each strictly taller than the one before it."""
    line = k.in_order(axis, *[k.tower(lo=1)] * n, gaps=gaps)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = line(result)
        if r:
            return r
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if axis == "x":
            comps = sorted(comps, key=lambda g: bx.centre(g)[0])
        else:
            comps = sorted(comps, key=lambda g: -bx.centre(g)[1])
        hs = [bx.thickness_cubes(g) for g in comps]
        if hs[0] != first:
            return f"the first tower {hs[0]} high, want {first}"
        if any(b <= a for a, b in itertools.pairwise(hs)):
            return f"heights {hs} do not rise"
        return None

    return f


def _min_y(y: float) -> k.Check:
    """Every part at y ≥ `y` (the left half for 0.30)."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _max_y(y: float) -> k.Check:
    """Every part at y ≤ `y` (the right half for 0.30)."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[1] for b in bs)
        return None if hi <= y + bx.TOL else f"a part reaches y {hi:.3f}, want ≤ {y}"

    return f


def _centre_y_max(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m): over to the right."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


def _wider_than_tall(bs: k.Boxes) -> k.Reason:
    """The longer plan side (in cubes) is more than the height."""
    w, h = bx.plan_dims(bs)[1], bx.thickness_cubes(bs)
    return None if w > h else f"{w} wide, {h} tall"


T = k.tower
one = k.one
reg = k.region
_ANY_T = T(lo=1, hi=_MAX_H)
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_CORNERS = ("back left", "back right", "front left", "front right")


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "A tower of four cubes is to be built at the back, and a tower of two cubes is to be "
        "placed directly in front of it.",
        k.any_of(
            k.pair(T(2), k.all_of(T(4), reg("back")), k.all_rels(k.on_side(_F), _square_to)),
            one(_col_beside(2, T(4), _F), reg("back")),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "1. Stack of 3 on the left\n2. Stack of 5 to its right, one cube gap",
        k.pair(T(5), k.all_of(T(3), reg("left")), k.gap_of(1, _R)),
    ),
    _c(
        "rel-03",
        REL,
        "Would you mind awfully putting a single cube on top of a two by two block, right in "
        "the middle? One layer for the block is plenty.",
        one(k.on_top(T(1), k.block(2, 2, 1)), k.centred(), k.levels(4, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "A tall tower and a short one beside it.",
        k.any_of(
            k.pair(_ANY_T, _ANY_T, k.all_rels(_taller(), k.within(0.25))),
            one(_two_columns("unequal")),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "Row of 5 along the back, then a stack of 4 in front of the middle of it",
        k.any_of(
            k.pair(
                T(4),
                k.all_of(k.row(5), k.runs("y"), reg("back")),
                k.all_rels(k.on_side(_F), _facing_mid()),
            ),
            one(k.plan_heights("11111", "..4.."), reg("back")),
        ),
    ),
    _c(
        "rel-06",
        REL,
        "Two walls, each five cubes long and two cubes high, shall be placed parallel to one "
        "another, running left to right, with a gap of one cube between them.",
        k.pair(
            k.all_of(k.wall(5, 2), k.runs("y")),
            k.all_of(k.wall(5, 2), k.runs("y")),
            k.parallel_gap(1),
        ),
    ),
    _c(
        "rel-07",
        REL,
        "If it's no trouble, a bridge with legs of three and a beam across the top, please.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-08",
        REL,
        "Put a tower of 3 in the middle, and a taller one to its left.",
        k.pair(_ANY_T, k.all_of(T(3), reg("centre")), k.all_rels(k.on_side(_L), _taller())),
    ),
    _c(
        "rel-09",
        REL,
        "Block 2 by 2, 2 high, and a single cube on top of it, dead centre",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.top_centred(), k.levels(4, 4, 1)),
    ),
    _c(
        "rel-10",
        REL,
        "1. Wall, 4 long, 3 high, across the front\n2. Stack of 2 behind it, touching",
        one(_col_beside(2, k.all_of(k.wall(4, 3), k.runs("y")), _B), reg("front")),
    ),
    _c(
        "rel-11",
        REL,
        "A pyramid of three levels is to be built in the centre, with a tower of five cubes "
        "placed on either side of it.",
        k.any_of(
            *[
                k.in_order(axis, T(5), k.all_of(k.pyramid(3), reg("centre")), T(5))
                for axis in ("x", "y")
            ]
        ),
    ),
    _c(
        "rel-12",
        REL,
        "Two towers next to each other, the left one twice the height of the right one, the "
        "right one three high.",
        k.any_of(
            k.pair(T(6), T(3), k.all_rels(k.on_side(_L), k.within(0.25))),
            one(_col_beside(6, T(3), _L)),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Could you pop a ring, five by five and one high, with a little tower of two sat in "
        "the middle of it? Lovely.",
        k.pair(_PEN5, T(2), k.centred_in(0.03)),
    ),
    _c(
        "rel-14",
        REL,
        "Two stacks of 5, a cube apart, and lay a beam across the tops",
        one(_beam_bridge(5, 1)),
    ),
    _c(
        "rel-15",
        REL,
        "A row of four cubes is to be laid immediately behind a tower of three, the two touching.",
        one(_col_beside(3, k.row(4), _F)),
    ),
    _c(
        "rel-16",
        REL,
        "1. Slab 3x3, one layer, back right\n2. Stack of 3 on its middle cube",
        one(k.plan_heights("111", "141", "111"), reg("back right")),
    ),
    _c(
        "rel-17",
        REL,
        "A long row across the front and a shorter one behind it.",
        k.pair(
            k.row(lo=2),
            k.all_of(k.row(lo=3), k.runs("y"), reg("front")),
            k.all_rels(k.on_side(_B), _shorter),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "Perhaps a staircase of four steps, and a single cube on the top step, if that's not "
        "too much bother.",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "rel-19",
        REL,
        "Stack of 2 squeezed in between two stacks of 4, all three touching",
        one(k.plan_heights("424")),
    ),
    _c(
        "rel-20",
        REL,
        "A table with four legs, each two cubes high, is required; a tower of three cubes is "
        "to stand to its right.",
        k.pair(T(3), _roofed(4, 2), k.on_side(_R)),
    ),
    _c(
        "rel-21",
        REL,
        "A wall 6 long and 3 high across the back, and a lower one of the same length in "
        "front of it.",
        k.pair(
            k.any_of(k.wall(6, 1), k.wall(6, 2)),
            k.all_of(k.wall(6, 3), k.runs("y"), reg("back")),
            k.on_side(_F),
        ),
    ),
    _c(
        "rel-22",
        REL,
        "1. Tower of 6 in the centre\n2. Tower of 2 on each side of it, left and right\n"
        "3. One cube gap each side",
        k.in_order("y", T(2), k.all_of(T(6), reg("centre")), T(2), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "1. Tower of 5 front left\n2. Take the top two off",
        one(T(3), reg("front left")),
    ),
    _c(
        "seq-02",
        SEQ,
        "A wall five cubes long and two cubes high is first to be built; a third course is "
        "then to be added along its full length.",
        one(k.wall(5, 3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Could you build a row of four running left to right, and then, if you don't mind, "
        "another row of four right behind it, touching?",
        one(k.block_xy(2, 4, 1)),
    ),
    _c("seq-04", SEQ, "Stack 6 in the middle. Actually, make that 4", one(T(4), reg("centre"))),
    _c(
        "seq-05",
        SEQ,
        "Build two towers of 4 side by side, a cube apart. Then make the right one taller.",
        k.pair(T(lo=5, hi=_MAX_H), T(4), k.gap_of(1, _R)),
    ),
    _c(
        "seq-06",
        SEQ,
        "1. Slab 4x4, 1 high, centre\n2. Slab 2x2 on top of it, in the middle\n"
        "3. Single cube on top of that",
        one(k.pyramid_counts(16, 4, 1), k.base(4, 4), k.centred(), reg("centre")),
    ),
    _c(
        "seq-07",
        SEQ,
        "A staircase of five steps is to be built, after which the top step is to be removed.",
        one(k.any_of(k.staircase(4), k.profile(1, 2, 3, 4, 4))),
    ),
    _c(
        "seq-08",
        SEQ,
        "A tower of three at the back, please. Oh, and while you're at it, another of three at "
        "the front, if that's all right.",
        k.structures(k.all_of(T(3), reg("back")), k.all_of(T(3), reg("front"))),
    ),
    _c(
        "seq-09",
        SEQ,
        "Lay a layer 3 by 2, then put a second layer on top, same size",
        one(k.block(3, 2, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "1. Three stacks of 2 in a row, left to right, one cube gap\n2. Remove the middle one",
        k.pair(T(2), T(2), k.gap_of(3, _L)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build a tower of 6. Then build a second one half as tall right next to it.",
        k.any_of(k.pair(T(3), T(6), k.within(0.10)), one(k.cell_heights(6, 3))),
    ),
    _c(
        "seq-12",
        SEQ,
        "A ring five cubes square and one cube high is to be built first; a tower of three "
        "cubes shall then be placed at its centre.",
        k.pair(_PEN5, T(3), k.centred_in(0.03)),
    ),
    _c(
        "seq-13",
        SEQ,
        "I'd quite like a wall, six long and three high. Actually, on reflection, two high "
        "would be better.",
        one(k.wall(6, 2)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Put a block 2 by 2 by 2 front right, then the same again back left",
        k.structures(
            k.all_of(k.block(2, 2, 2), reg("front right")),
            k.all_of(k.block(2, 2, 2), reg("back left")),
        ),
    ),
    _c(
        "seq-15",
        SEQ,
        "1. Two stacks of 3, one cube apart\n2. Beam across the top\n"
        "3. Single cube on the middle of the beam",
        one(_topped(_beam_bridge(3, 1)), k.top_centred()),
    ),
    _c(
        "seq-16",
        SEQ,
        "A wall 4 long and 2 high. Then a second wall twice as long, same height, behind it.",
        k.pair(k.wall(8, 2), k.wall(4, 2), k.on_side(_B)),
    ),
    _c(
        "seq-17",
        SEQ,
        "A pyramid with a base of three by three cubes is to be constructed; the single cube "
        "at its apex is subsequently to be removed.",
        one(k.any_of(k.all_of(k.pyramid_counts(9, 4), k.base(3, 3)), k.block(3, 3, 1))),
    ),
    _c(
        "seq-18",
        SEQ,
        "Would you be so kind as to build a tower of five on the right — oh, sorry, I meant "
        "the left.",
        one(T(5), reg("left")),
    ),
    _c(
        "seq-19",
        SEQ,
        "Row of 5 cubes, front to back. Then stack one more on each end",
        one(k.profile(2, 1, 1, 1, 2), k.runs("x")),
    ),
    _c(
        "seq-20",
        SEQ,
        "1. Tower of 2 front right\n2. Tower of 4 behind it\n3. Put two more on the first one",
        k.pair(T(4), k.all_of(T(4), reg("front right")), k.on_side(_B)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Build three towers of 3 in a row, a cube apart. Then make the middle one the tallest.",
        k.any_of(*[k.in_order(ax, T(3), T(lo=4, hi=_MAX_H), T(3), gaps=(1,)) for ax in ("x", "y")]),
    ),
    _c(
        "seq-22",
        SEQ,
        "Build a tower of 3 and a tower of 6, a cube apart. Then take two off the bigger one.",
        k.pair(T(4), T(3), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "3 stacks of 4, in a line, 1 cube between each", k.in_line(3, T(4), 1)),
    _c(
        "num-02",
        NUM,
        "Five towers of a single cube each are to be placed in a row from left to right, one "
        "cube apart.",
        k.in_order("y", *[T(1)] * 5, gaps=(1,)),
    ),
    _c("num-03", NUM, "Perhaps a tower of seven? If that's not pushing it.", one(T(7))),
    _c(
        "num-04",
        NUM,
        "1. Tower of 1\n2. Tower of 2 to its right\n3. Tower of 3 to the right of that\n"
        "All one cube apart",
        k.in_order("y", T(1), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "num-05",
        NUM,
        "Two towers, one of 2 and one three times as tall, a cube apart.",
        k.pair(T(6), T(2), k.gap_of(1)),
    ),
    _c("num-06", NUM, "Layer of 12 cubes, 3 rows of 4", one(k.block(3, 4, 1))),
    _c(
        "num-07",
        NUM,
        "A block measuring two cubes by three cubes in plan and four cubes in height is to be "
        "erected.",
        one(k.block(2, 3, 4)),
    ),
    _c(
        "num-08",
        NUM,
        "A couple of smallish towers, three high each, nothing too ambitious, with a bit of a "
        "gap between them.",
        k.pair(T(3), T(3), k.within(0.25)),
    ),
    _c("num-09", NUM, "1. Pyramid, 4 levels\n2. Nothing else", one(k.pyramid(4))),
    _c(
        "num-10",
        NUM,
        "Four towers in a line from front to back, each one cube taller than the one before, "
        "the first one a single cube.",
        k.in_order("x", T(1), T(2), T(3), T(4)),
    ),
    _c("num-11", NUM, "Pile of 8, one on top of the other", one(T(8))),
    _c("num-12", NUM, "A staircase of seven steps is to be provided.", one(k.staircase(7))),
    _c("num-13", NUM, "Just the one tower, if you would, about nine cubes high.", one(T(9))),
    _c(
        "num-14",
        NUM,
        "1. Two rows of 6\n2. Both left to right\n3. One behind the other, 2 cubes apart",
        k.pair(
            k.all_of(k.row(6), k.runs("y")),
            k.all_of(k.row(6), k.runs("y")),
            k.parallel_gap(2),
        ),
    ),
    _c(
        "num-15",
        NUM,
        "A tower of four and, next to it, one that's half as tall.",
        k.any_of(k.pair(T(2), T(4), k.within(0.25)), one(k.cell_heights(4, 2))),
    ),
    _c(
        "num-16",
        NUM,
        "Stacks of 2 in all four corners of the table",
        k.structures(*[k.all_of(T(2), reg(r)) for r in _CORNERS]),
    ),
    _c(
        "num-17",
        NUM,
        "A ring three cubes high, its outside measuring four cubes by four, is to be constructed.",
        one(k.ring_of(3, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "num-18",
        NUM,
        "I wonder if you might do a wall about eight long and, say, two high.",
        one(k.wall(8, 2)),
    ),
    _c(
        "num-19",
        NUM,
        "1. Row of 3 across the front\n2. Row of 3 across the back\n"
        "3. Row of 3 in between, same way round",
        k.in_order(
            "x",
            k.all_of(k.row(3), k.runs("y"), reg("front")),
            k.all_of(k.row(3), k.runs("y")),
            k.all_of(k.row(3), k.runs("y"), reg("back")),
        ),
    ),
    _c(
        "num-20",
        NUM,
        "Three towers in a line left to right, a cube apart, the first 2 high and each of the "
        "others taller than the one before it.",
        _rising("y", 3, 2, gaps=(1,)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Stack 25 cm high, back left", one(T(5), reg("back left"))),
    _c(
        "dim-02",
        DIM,
        "A wall 30 cm in length and 15 cm in height is to be built along the front.",
        one(k.wall(6, 3), k.runs("y"), reg("front")),
    ),
    _c(
        "dim-03",
        DIM,
        "A slab roughly 15 centimetres by 20, one layer, would be lovely.",
        one(k.block(3, 4, 1)),
    ),
    _c("dim-04", DIM, "1. Tower, 350 mm tall\n2. Put it on the right", one(T(7), reg("right"))),
    _c(
        "dim-05",
        DIM,
        "A tower 20 cm tall and a shorter one, 10 cm, in front of it.",
        k.pair(T(2), T(4), k.on_side(_F)),
    ),
    _c("dim-06", DIM, "Block 10 by 10 cm, 15 high", one(k.block(2, 2, 3))),
    _c(
        "dim-07",
        DIM,
        "A staircase rising to a height of 20 centimetres, in steps of 5 centimetres, is to be "
        "built.",
        one(k.staircase(4)),
    ),
    _c(
        "dim-08",
        DIM,
        "Could I trouble you for a row about 40 centimetres long? Nothing taller than one cube.",
        one(k.row(8)),
    ),
    _c(
        "dim-09",
        DIM,
        "1. Two posts, 15 cm each\n2. 5 cm gap between them\n3. Beam on top",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "dim-10",
        DIM,
        "A wall 40 cm long, and a second, shorter wall parallel to it, both 10 cm high.",
        k.pair(k.wall(high=2, lo=2, hi=7), k.wall(8, 2), _parallel),
    ),
    _c("dim-11", DIM, "Layer 20 by 25 cm", one(k.block(4, 5, 1))),
    _c(
        "dim-12",
        DIM,
        "Two towers, each 0.15 m in height, are to be placed 10 cm apart.",
        k.pair(T(3), T(3), k.gaps(1, 2)),
    ),
    _c(
        "dim-13",
        DIM,
        "Would a ring about 25 centimetres across and 5 centimetres high be possible?",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-14",
        DIM,
        "1. Pyramid\n2. Base 20 cm square\n3. Centre of the table",
        one(k.pyramid(), k.base(4, 4), reg("centre")),
    ),
    _c(
        "dim-15",
        DIM,
        "A 30 cm tower, and a second one a third of its height on its left.",
        k.pair(T(2), T(6), k.on_side(_L)),
    ),
    _c(
        "dim-16",
        DIM,
        "Row 0.3 m, front to back, right side",
        one(k.row(6), k.runs("x"), reg("right")),
    ),
    _c(
        "dim-17",
        DIM,
        "A block of 100 mm by 150 mm, 100 mm high, is to be placed at the back left.",
        one(k.block(2, 3, 2), reg("back left")),
    ),
    _c(
        "dim-18",
        DIM,
        "A little table would be rather nice — legs about 10 cm, top about 15 cm square.",
        one(_roofed(4, 2), k.dims(3, 3)),
    ),
    _c(
        "dim-19",
        DIM,
        "1. Wall 400 mm long\n2. 100 mm high\n3. Left to right",
        one(k.wall(8, 2), k.runs("y")),
    ),
    _c(
        "dim-20",
        DIM,
        "Two towers, 10 cm and 25 cm, the taller one behind.",
        k.pair(T(5), T(2), k.on_side(_B)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Stack of 5, not in the middle",
        one(T(5), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "A tower of four cubes is to be built; it shall not be placed at the front.",
        one(T(4), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-03",
        NEG,
        "A little bridge, legs of two, but no beam, if you don't mind — just cubes along the top.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-04",
        NEG,
        "1. Row of 5\n2. Not left to right\n3. Back half",
        one(k.row(5), k.runs("x"), k.min_x(0.50)),
    ),
    _c(
        "neg-05",
        NEG,
        "Two towers, neither taller than 3, not touching, with the left one shorter.",
        k.pair(
            T(lo=1, hi=3),
            T(lo=1, hi=3),
            k.all_rels(k.on_side(_L), _lower),
        ),
    ),
    _c(
        "neg-06",
        NEG,
        "3 by 3 layer, no cube in the middle",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-07",
        NEG,
        "A pyramid of three levels is to be constructed without the use of beams.",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-08",
        NEG,
        "Two towers of three, please, but do try not to let them touch.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-09",
        NEG,
        "1. Staircase, 3 steps\n2. Don't make it climb towards the robot",
        one(k.staircase(3), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-10",
        NEG,
        "A tower of 5 and another, not as tall, nowhere near it — opposite sides of the table.",
        k.pair(T(lo=1, hi=4), T(5), _opposite_ends),
    ),
    _c(
        "neg-11",
        NEG,
        "Block 2 by 3, 2 high, cubes only, no beams, keep it off the left",
        one(k.block(2, 3, 2), k.only_cubes, k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-12",
        NEG,
        "A wall four cubes long and three cubes high is required; it is not to run from front "
        "to back.",
        one(k.wall(4, 3), k.runs("y")),
    ),
    _c(
        "neg-13",
        NEG,
        "A ring, five by five, one high — nothing inside it, thank you, and not too close to "
        "the robot.",
        one(_PEN5, k.not_(reg("front"), "close to the robot")),
    ),
    _c(
        "neg-14",
        NEG,
        "1. Tower of 6\n2. Not on the right\n3. Not at the back",
        one(T(6), k.not_(reg("right"), "on the right"), k.not_(reg("back"), "at the back")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "Stakc of 4 back rihgt", one(T(4), reg("back right"))),
    _c(
        "typo-02",
        TYP,
        "A towr of three cubes is to be bulit in the centre.",
        one(T(3), reg("centre")),
    ),
    _c(
        "typo-03",
        TYP,
        "Could you possibly do a smal pyramid, three levles? Many thanks.",
        one(k.pyramid(3)),
    ),
    _c(
        "typo-04",
        TYP,
        "1. Wal 5 long\n2. 2 hihg\n3. Along the back",
        one(k.wall(5, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "typo-05",
        TYP,
        "A tall towre and a shoter one in front of it.",
        k.pair(_ANY_T, _ANY_T, k.all_rels(k.on_side(_F), _lower)),
    ),
    _c("typo-06", TYP, "Row of 7 cubse, front to bakc", one(k.row(7), k.runs("x"))),
    _c(
        "typo-07",
        TYP,
        "A staricase of four stpes shall be built on the lfet.",
        one(k.staircase(4), reg("left")),
    ),
    _c(
        "typo-08",
        TYP,
        "A litle brdige with legs of three and a beam acros, if it's no bother.",
        one(_beam_bridge(3)),
    ),
    _c(
        "typo-09",
        TYP,
        "1. Blcok 2x2\n2. 3 hgih\n3. Fornt left",
        one(k.block(2, 2, 3), reg("front left")),
    ),
    _c(
        "typo-10",
        TYP,
        "Two tower, the secnd twice as tall as the first, first one is 2, side by sdie, gap of "
        "one cube",
        k.pair(T(4), T(2), k.gap_of(1)),
    ),
    _c("typo-11", TYP, "Layre 4 by 4, 1 high, in the midle", one(k.block(4, 4, 1), reg("centre"))),
    _c(
        "typo-12",
        TYP,
        "A rign of four cubes by four, one cube in hieght, is to be placed at the back.",
        one(_PEN4, reg("back")),
    ),
    _c(
        "typo-13",
        TYP,
        "Perhpas two towers of fuor, a cube apart, if you'd be so kind.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c("typo-14", TYP, "1. Tabel, 4 legs\n2. Legs 3 hihg", one(_roofed(4, 3))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Back left, stack of 6.", one(T(6), reg("back left"))),
    _c(
        "wo-02",
        WO,
        "At the front of the table a row of five cubes, running left to right, is to be laid.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-03",
        WO,
        "Three high, if you wouldn't mind, and in the centre — a tower, that is.",
        one(T(3), reg("centre")),
    ),
    _c("wo-04", WO, "1. On the right\n2. Pyramid\n3. 3 levels", one(k.pyramid(3), reg("right"))),
    _c(
        "wo-05",
        WO,
        "In front, a tower of 3; behind it, one two cubes taller, with a cube's gap.",
        k.pair(T(5), T(3), k.gap_of(1, _B)),
    ),
    _c("wo-06", WO, "2 high, 3 wide, 4 long — that's the block I need", one(k.block(3, 4, 2))),
    _c(
        "wo-07",
        WO,
        "Behind the wall, which is to be five cubes long and two high, a tower of four cubes "
        "shall stand.",
        k.any_of(
            k.pair(T(4), k.wall(5, 2), k.on_side(_B)),
            one(_col_beside(4, k.wall(5, 2), _B)),
        ),
    ),
    _c(
        "wo-08",
        WO,
        "On the left, perhaps, a staircase — four steps would do nicely.",
        one(k.staircase(4), reg("left")),
    ),
    _c(
        "wo-09",
        WO,
        "1. Beam on top\n2. Of two stacks of 2\n3. Stacks one cube apart",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "wo-10",
        WO,
        "The taller of the two on the right, please: towers of 3 and 5, a cube apart.",
        k.pair(T(5), T(3), k.gap_of(1, _R)),
    ),
    _c(
        "wo-11",
        WO,
        "Front right corner, layer 2 by 2, then a stack of 3 on top of it in the middle",
        one(
            k.on_top(T(3), k.block(2, 2, 1)),
            k.centred(),
            k.levels(4, 1, 1, 1),
            reg("front right"),
        ),
    ),
    _c(
        "wo-12",
        WO,
        "Five steps high and climbing towards the back, a staircase is to be built.",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c(
        "wo-13",
        WO,
        "In the back right, if there's room, a block two by two by two.",
        one(k.block(2, 2, 2), reg("back right")),
    ),
    _c(
        "wo-14",
        WO,
        "1. Apart by one cube\n2. Two towers\n3. Five high each",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning! Terribly sorry to bother you, I know it's been a long week. A tower of four, "
        "whenever you get a moment. Cheers.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "Shift's nearly done, pallets are all wrapped. Last one: stack of 3 front left.",
        one(T(3), reg("front left")),
    ),
    _c(
        "fil-03",
        FIL,
        "With reference to the request raised at the weekly review, a wall six cubes long and "
        "two cubes high is to be built. No further action is required.",
        one(k.wall(6, 2)),
    ),
    _c(
        "fil-04",
        FIL,
        "Job list for the afternoon:\n1. Pyramid, 3 levels, centre\nThat's all for now, thanks",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-05",
        FIL,
        "Right, the visitors last week loved the big one, so this time: a tower of four and a "
        "taller one next to it.",
        k.any_of(
            k.pair(T(lo=5, hi=_MAX_H), T(4), k.within(0.25)),
            one(_two_columns("taller", 4)),
        ),
    ),
    _c(
        "fil-06",
        FIL,
        "Forklift's blocking bay 3 again, don't mind me. Row of 6, left to right, back of the "
        "table",
        one(k.row(6), k.runs("y"), reg("back")),
    ),
    _c(
        "fil-07",
        FIL,
        "I do hope the weather holds for the garden party on Saturday. Anyway — a ring, four "
        "by four, one high, if it's not too much trouble.",
        one(_PEN4),
    ),
    _c(
        "fil-08",
        FIL,
        "Further to the minutes of the meeting held on the 12th, it has been agreed that a "
        "staircase of three steps is to be built. Thank you for your cooperation.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Quick list before lunch (canteen shuts at 1):\n1. Block 2x2, 2 high\n2. Right side",
        one(k.block(2, 2, 2), reg("right")),
    ),
    _c(
        "fil-10",
        FIL,
        "Don't worry about matching the one from yesterday, it was far too tall anyway. Just a "
        "tower of five in the back right.",
        one(T(5), reg("back right")),
    ),
    _c(
        "fil-11",
        FIL,
        "Ok, picked 40 orders this morning, back's killing me. Give me two stacks of 3, a cube "
        "apart",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-12",
        FIL,
        "Sorry, me again — the tea trolley's just been round. Would you be able to manage a "
        "bridge with legs of two? No rush at all.",
        one(_span(2)),
    ),
    _c(
        "fil-13",
        FIL,
        "In accordance with the procedure for demonstration builds (revision 4), a block three "
        "cubes by three, two cubes high, is to be assembled.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-14",
        FIL,
        "Note from Dave, shift 2:\n1. Wall 4 long 3 high\n2. Front of the table\nCheers",
        one(k.wall(4, 3), reg("front")),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "Stack of 4, front right corner", one(T(4), reg("front right"))),
    _c(
        "reg-02",
        REG,
        "A pyramid of two levels is to be placed in the back left corner of the table.",
        one(k.pyramid(2), reg("back left")),
    ),
    _c(
        "reg-03",
        REG,
        "Could you put a tower of three somewhere near the middle, roughly?",
        one(T(3), reg("centre")),
    ),
    _c(
        "reg-04",
        REG,
        "1. Row of 4\n2. Right along the back edge\n3. Left to right",
        one(k.row(4), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-05",
        REG,
        "Two towers, 3 and 5, the taller on the far left and the shorter on the far right.",
        k.structures(
            k.all_of(T(5), k.centre_y_min(0.45)),
            k.all_of(T(3), _centre_y_max(0.15)),
        ),
    ),
    _c(
        "reg-06",
        REG,
        "Layer 3 by 3 in the back half of the table",
        one(k.block(3, 3, 1), k.min_x(0.50)),
    ),
    _c(
        "reg-07",
        REG,
        "A tower of five cubes is to be placed with its centre at x = 0.5 m, y = 0.4 m.",
        one(T(5), k.near(0.50, 0.40, 0.02)),
    ),
    _c(
        "reg-08",
        REG,
        "Perhaps a little wall at the front, just by the robot — four long, two high?",
        one(k.wall(4, 2), reg("front")),
    ),
    _c(
        "reg-09",
        REG,
        "1. Tower of 2 front left\n2. Tower of 2 front right\n3. Tower of 2 back left\n"
        "4. Tower of 2 back right",
        k.structures(*[k.all_of(T(2), reg(r)) for r in _CORNERS]),
    ),
    _c(
        "reg-10",
        REG,
        "A tower of 4 in the left half and a taller one in the right half.",
        k.structures(
            k.all_of(T(4), _min_y(0.30)),
            k.all_of(T(lo=5, hi=_MAX_H), _max_y(0.30)),
        ),
    ),
    _c(
        "reg-11",
        REG,
        "Row of 5 front to back down the left side",
        one(k.row(5), k.runs("x"), reg("left")),
    ),
    _c(
        "reg-12",
        REG,
        "A block two cubes by two, three cubes high, is to be located at the centre of the table.",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    _c(
        "reg-13",
        REG,
        "A staircase of three steps over on the right, I think, if that suits.",
        one(k.staircase(3), reg("right")),
    ),
    _c(
        "reg-14",
        REG,
        "1. Slab 2x4, one layer\n2. Centre it at x 0.6, y 0.3",
        one(k.block(2, 4, 1), k.near(0.60, 0.30, 0.02)),
    ),
    _c(
        "reg-15",
        REG,
        "Stack of 6 in the middle of the back edge",
        one(T(6), reg("back"), k.near(y=0.30, tol=0.03)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Whatever you want, 8 cubes max",
        k.all_of(k.anything, k.layout(_cubes(hi=8))),
    ),
    _c(
        "open-02",
        OPEN,
        "A structure of the system's own choosing is to be built, not exceeding 15 cm in height.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-03",
        OPEN,
        "Oh, anything you like really — surprise me, but nothing too big.",
        k.small,
    ),
    _c(
        "open-04",
        OPEN,
        "1. Build something\n2. Left side\n3. Cubes only",
        k.all_of(k.anything, k.layout(k.all_of(reg("left"), k.only_cubes))),
    ),
    _c(
        "open-05",
        OPEN,
        "Something taller than a tower of four, your choice what.",
        k.all_of(k.anything, k.layout(k.height(lo=5))),
    ),
    _c(
        "open-06",
        OPEN,
        "Build something with a gap under it, bridge, arch, whatever",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-07",
        OPEN,
        "Any two structures may be built, provided that they do not touch.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-08",
        OPEN,
        "Something with steps in it, perhaps? Whatever you think best.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-09",
        OPEN,
        "1. Your choice of shape\n2. No more than 10 cubes\n3. Keep it at the back",
        k.all_of(k.anything, k.layout(k.all_of(_cubes(hi=10), reg("back")))),
    ),
    _c(
        "open-10",
        OPEN,
        "Build something wider than it is tall.",
        k.all_of(k.anything, k.layout(_wider_than_tall)),
    ),
    _c(
        "open-11",
        OPEN,
        "Any shape, fits in a 3 by 3 footprint",
        k.all_of(k.anything, k.layout(_fits(3, 3))),
    ),
    _c(
        "open-12",
        OPEN,
        "Some form of enclosure, of any dimensions, is to be built.",
        k.all_of(k.anything, one(k.ring)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Stack of", k.honest(one(_ANY_T))),
    _c(
        "bad-02",
        BAD,
        "A sphere of fifteen centimetres diameter is to be produced.",
        k.honest(k.anything),
    ),
    _c(
        "bad-03",
        BAD,
        "Would you mind terribly building a tower about a metre tall?",  # 20 cubes: past 10
        k.honest(one(_ANY_T)),
    ),
    _c(
        "bad-04",
        BAD,
        "1. Tower of 4\n2. Now make it 2 high and 6 high",
        k.honest(one(k.any_of(T(2), T(4), T(6)))),
    ),
    _c("bad-05", BAD, "A tower that is taller than itself.", k.honest(k.anything)),
    _c("bad-06", BAD, "asdkjh qwe stack zzz", k.honest(k.anything)),
    _c(
        "bad-07",
        BAD,
        "A wall of twenty cubes in length is to be built.",  # past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-08",
        BAD,
        "Could you possibly fetch me a cup of tea while you're at it?",
        k.honest(),
    ),
    _c("bad-09", BAD, "1. Cylinder, 10 cm across\n2. 20 cm tall", k.honest(k.anything)),
    _c(
        "bad-10",
        BAD,
        "A tower of three that is taller than the tower of five next to it.",
        k.honest(k.anything),
    ),
    _c("bad-11", BAD, "Stack of -2", k.honest(k.anything)),
    _c(
        "bad-12",
        BAD,
        "Bouw een toren van vier blokken in het midden.",
        k.honest(one(T(4), reg("centre"))),
    ),
    _c(
        "bad-13",
        BAD,
        "Perhaps a tower of three — or perhaps not. I'll let you know.",
        k.honest(one(T(3))),
    ),
    _c("bad-14", BAD, "1.\n2.\n3.", k.honest()),
    _c(
        "bad-15",
        BAD,
        "Make it bigger than the other one.",  # nothing stands on the table
        k.honest(k.anything),
    ),
    _c("bad-16", BAD, "Layer 15 by 15", k.honest(k.anything)),  # past the cell
    _c(
        "bad-17",
        BAD,
        "A tower of two and a half cubes is to be built.",
        k.honest(one(k.any_of(T(2), T(3)))),
    ),
    _c(
        "bad-18",
        BAD,
        "A pyramid, if you could, ever so slightly upside down.",
        k.honest(k.anything),
    ),
    _c(
        "bad-19",
        BAD,
        "Glue the stack down so it doesn't fall over",  # the cell cannot glue
        k.honest(k.anything),
    ),
    _c("bad-20", BAD, "Zbuduj wieżę z trzech kostek.", k.honest(one(T(3)))),
]
