"""A thirty-eighth held-out set for the language front end (dev38): plain commands, no voices.

Written blind: without looking at the front end's code or tests, the frozen test set, the
cases of any other set (but dev27, the format example) or any benchmark result — only the
README, the shared checks, the geometry and the other sets' docstrings were read — and worded
apart from `language_dev` … `language_dev37` (no command shared with any set, see tests).
Nothing here was run through the system while it was written.

The set is different in kind from the ones before it. Each earlier set spoke in five colourful
voices with their own jargon — dialects, trades, shorthand, chat and ticket conventions — and
what those sets measure is dominated by the conventions. This one has NO voices. Its 180
commands are what ordinary people at a robot cell — operators, engineers, students, visitors
— really type into a text box, with no jargon and nothing that needs explaining: many verbs
(build, make, put, place, stack, set up, lay, add, give me, I need, could you, let's have,
I'd like), the place before or after the structure, sizes as words, digits, cm, mm, m, "3x3"
and "2 by 4", articles sometimes dropped, casual punctuation and now and then an ordinary typo.
A miss here is a miss on plain English.

Roughly: 35 % one structure with a size and perhaps a place; 30 % two structures with one
relation (on top of, behind, in front of, to the left / right of, next to, between, joined by a
beam, around / inside) or a gap; 15 % a two- or three-step sequence in one message ("then put
… on it", "then take … off", "then make it taller", "actually make it 5"); 10 % three or more
structures with references ("the first and the last ones", "the tall one", "each of them", "the
one on the left", "the middle one"); 10 % bad input. The families are the cell's: tower, wall,
row, slab and grid, block, pyramid, staircase, bridge, arch, table and canopy, ring or
enclosure, castle, and the L, T and U shapes.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else.
Conventions (the shared ones of dev27 and the sets after it):

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by the
  column heights, or by the column and the rest); "right next to it" is at most 10 cm clear,
  or touching; "not touching", "a gap", "apart", "near each other but not touching" mean
  separate structures; "so they're touching" makes them one;
* "in front of", "behind", "to the left / right of", "on its right" is the dominant direction
  between footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when
  none is said; where nothing rules touching out, a tower so placed may also be set against
  the other as one structure, its column then lying on that side of the rest; "with a gap",
  "not touching", "a little in front", "a bit in front" keep them separate, the last two no
  more than 25 cm clear; "directly behind … so they're touching" is one structure, the column
  behind;
* "N cubes apart", "a gap of N cubes", "one cube between each", "a 5 cm gap", "one cube of
  space" are the clear gap (± 1.5 cm); a bare "10 cm apart" also accepts the centre-to-centre
  reading (for single columns and one-cube-thick walls, one cube less clear); "facing each
  other", "parallel" and rows "one behind the other" share their long axis and face each other
  across the gap (two rows one behind the other may also run front to back, end to end);
  "in a row / in a line" is one line along x or y (the shared `in_line`, `in_order`, `line`);
  "left to right" is the order along -y;
* "between" two towers with the gaps given is the three in one line (`line`); an arch "with a
  tower on either side of it" is the shared `between_`;
* "on top of" stands on it (the shared `on_top`), anywhere on it unless "in the middle",
  "right in the middle" or "centred" is said (then centred over it, ± 3 cm); "a tower of 3 on
  each end" of a wall stands on its end columns, makes them three high, or stands against or
  just past each end, in line with it; "a 2-cube tower on each corner" of a one-high ring
  stands on the corner cubes or makes the corners two high;
* a bridge's top is a beam (the shared `bridge`, the overall height one more than the posts)
  where the command names a beam, and a beam or a bar of cubes where it does not; "no beams",
  "no beam please, just cubes" is a bar of cubes only; "a small bridge" is any bridge; an arch
  is anything spanning a gap between two supports (a beam, a bar of cubes or corbelled), and
  "about 20 cm high" is four cubes to the top or a four-cube opening (five overall); a table or
  canopy is four separate legs under one connected top of beams or of cubes (the shared
  `canopy`, a top of cubes, or the cell's beam roof), "without any beams" a top of cubes only,
  and "about 15 cm square" a 3 × 3 footprint;
* a ring's or enclosure's stated size is its outside, of any height unless one is said; "in
  the middle of" a ring is inside its empty interior, clear of the ring, the centres within
  3 cm; "surround a block with a ring" is the ring round it, clear of it (two structures) or
  holding it against its walls (one); "an enclosure of 16 cubes, square, one high" is the
  5 × 5 ring;
* a castle is the shared `castle` (a ring with at least four corner columns above the wall);
  "walls 2 high and corner towers 4 high" makes the lowest column two and the highest four,
  on at least four columns;
* an L, T or U is its footprint letter (the shared `shape_letter`); an arm's stated length is
  read either with the shared corner cell or beyond it; "flat" / "one cube high" is one high,
  and an L's height is otherwise free;
* a staircase's width is free, and so is the way it climbs unless said ("towards the robot"
  climbs to the front); "take away the top step" accepts the top cube off (heights 1, 2, 3, 4,
  4) or the whole last step off; a pyramid's step is free unless given, so "a 3x3 base" is any
  pyramid on a full 3 × 3 base and "then take off the top cube" leaves 9-4 or the bare 3 × 3
  layer; "N levels" is N levels;
* a grid of cubes is a full one-layer slab or the single cubes standing apart in evenly spaced
  rows and columns; a slab is one layer unless a thickness is given; "3 wide, 3 deep and 2
  high", "10cm x 10cm, 25cm high" give a block's footprint and height;
* a cube is 5 cm: "20 cm", "350 mm", "0.4 m", "half a metre" are 4, 7, 8 and 10 cubes; "twice
  as tall" and "half as tall" are exact; a hedged figure ("maybe 3 levels?") is the figure;
* in a sequence the finished state counts: "actually make it N" replaces the figure, "the same
  at the front right" is another copy there, "the first and the last ones" are the two ends of
  the line (either end may be first), "the tall one" is the tallest, "the one on the left" /
  "on the right" is the +y / -y one, "the middle one" the one between the other two;
* "whatever you like", "your choice", "surprise me" leave everything free but what is said;
  "something tall" is at least four cubes high; "something small" is the shared `small`;
  "10 cubes or fewer" counts cubes (beams not counted); "something with a gap underneath" is
  anything spanning a gap; "two different structures" differ in footprint, height or part
  count; numbers in chatter ("a demo at 3", "20 minutes") are never sizes;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "near the robot" is the front; "along the back edge" and "as far from the robot as it can
  go" are every part at x ≥ 0.60; "in every corner" and "one in each back corner" are the
  corner regions; "not at the back", "anywhere except the left side", "not in the middle" are
  outside that region.

Bad input (contradictions, sizes past the cell or below one cube, a place off the table,
shapes or materials the cell does not have, things that are not on the table, a half-typed
command, nothing to go on, gibberish) is honest only as an error (or a failure) or as a layout
WITH notes naming the assumption (`k.honest`); a request that is not a build at all, or that
was cancelled, admits only the refusal. Geometry comes only from `sdi.bench.boxes`, through
the shared checks in `language_checks` and the local checks below.

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

_TALL = 4  # cubes: "something tall"


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev38-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _any(bs: k.Boxes) -> k.Reason:
    """Any structure at all."""
    return None if bs else "no parts"


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
    than the posts; the posts `mouth` cubes apart clear when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _span(posts: int) -> k.Check:
    """A bridge with no beam named: two posts `posts` high with a beam (one layer above the
    posts) or a bar of cubes across the tops."""
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


def _next(a: k.Check, b: k.Check, merged: k.Check | None = None, gap: float = 0.25) -> k.Pred:
    """A next to B: two separate structures no more than `gap` clear, or (when `merged` is
    given) the two set against each other as one structure passing `merged`."""
    apart = k.pair(a, b, k.within(gap))
    return apart if merged is None else k.any_of(apart, k.one(merged))


def _placed(a: k.Check, b: k.Check, side: str, h: int | None = None) -> k.Pred:
    """A on `side` of B: two separate structures, or, when A is a tower of `h`, its column
    set against B on that side as one structure."""
    apart = k.pair(a, b, k.on_side(side))
    return apart if h is None else k.any_of(apart, k.one(_col_beside(h, b, side)))


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


def _differ(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B are different structures: footprint, height or part count differ."""
    same = (
        bx.plan_dims(a) == bx.plan_dims(b)
        and bx.thickness_cubes(a) == bx.thickness_cubes(b)
        and len(a) == len(b)
    )
    return "the two structures are alike" if same else None


def _clusters(values: list[float], tol: float = 0.01) -> list[float]:
    """The distinct values (within `tol`), lowest first."""
    out: list[float] = []
    for v in sorted(values):
        if not out or v - out[-1] > tol:
            out.append(v)
    return out


def _grid(a: int, b: int) -> k.Pred:
    """An a × b grid of cubes: one full one-layer a × b slab, or a × b single cubes standing
    apart in evenly spaced rows and columns (either way round)."""
    slab = k.one(k.block(a, b, 1))

    def spaced(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != a * b:
            return f"{len(comps)} separate structures, want {a * b}"
        for g in comps:
            r = k.tower(1)(g) or k.on_table(g)
            if r:
                return f"not single cubes: {r}"
        xs = _clusters([bx.centre(g)[0] for g in comps])
        ys = _clusters([bx.centre(g)[1] for g in comps])
        if sorted((len(xs), len(ys))) != sorted((a, b)):
            return f"cubes in {len(xs)} × {len(ys)} lines, want {a} × {b}"
        for line in (xs, ys):
            steps = [q - p for p, q in itertools.pairwise(line)]
            if steps and max(steps) - min(steps) > 0.01:
                return "rows or columns not evenly spaced"
        return None

    return k.any_of(slab, spaced)


def _castle(wall_h: int, tower_h: int) -> k.Check:
    """A castle (the shared `castle`) whose lowest column is `wall_h` cubes and whose highest
    columns, at least four of them, are `tower_h`."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.castle(bs)
        if r:
            return r
        tops: dict[tuple[int, int], int] = {}
        for i, j, z in bx.voxels(bs):
            tops[(i, j)] = max(tops.get((i, j), 0), z + 1)
        hs = sorted(tops.values())
        if hs[0] != wall_h:
            return f"walls {hs[0]} high, want {wall_h}"
        if hs[-1] != tower_h or hs.count(tower_h) < 4:
            return f"towers {hs[-1]} high ({hs.count(hs[-1])} columns), want {tower_h}"
        return None

    return f


def _rows_behind(n: int, gap: int) -> k.Pred:
    """Two rows of `n`, one behind the other, `gap` cubes apart: parallel rows running left to
    right facing across the gap, or two rows running front to back, end to end."""
    across = k.all_of(k.row(n), k.runs("y"))
    along = k.all_of(k.row(n), k.runs("x"))
    return k.any_of(
        k.pair(across, across, k.all_rels(k.parallel_gap(gap), k.on_side(_B))),
        k.pair(along, along, k.all_rels(k.gap_of(gap), k.on_side(_B))),
    )


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_BRIDGE = k.any_of(k.bridge(), _bar_on_posts())  # any bridge, beam or bar of cubes
_RING5 = k.all_of(k.ring_of(None, (3, 3)), k.dims(5, 5))  # 5 × 5 outside, any height
_CORNERS = ("back left", "back right", "front left", "front right")


def _letter(kind: str, *sizes: tuple[int, int]) -> k.Check:
    """The footprint letter `kind` with one of the footprints `sizes` (either way round)."""
    return k.all_of(k.shape_letter(kind), k.any_of(*[k.dims(a, b) for a, b in sizes]))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "put a tower of 3 cubes next to a tower of 5",
        _next(T(3), T(5), k.cell_heights(3, 5)),
    ),
    _c(
        "rel-02",
        REL,
        "Can you build a wall 5 cubes long and 2 high, with a 4-cube tower behind it?",
        _placed(T(4), k.wall(5, 2), _B, 4),
    ),
    _c(
        "rel-03",
        REL,
        "I'd like a 3x3 slab with a single cube on top, right in the middle.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "two towers of four with a beam laid across the top of them",
        one(_beam_bridge(4)),
    ),
    _c(
        "rel-05",
        REL,
        "Build a square ring of cubes, 5 by 5, and stand a 3 high tower in the middle of it",
        k.pair(_RING5, T(3), k.centred_in(0.03)),
    ),
    _c(
        "rel-06",
        REL,
        "row of 6 cubes along the front, and a pyramid somewhere behind it",
        k.pair(k.pyramid(), k.all_of(k.row(6), k.runs("y"), reg("front")), k.on_side(_B)),
    ),
    _c(
        "rel-07",
        REL,
        "Make a staircase with 4 steps and put a 2-cube tower on its right, not touching it",
        k.pair(T(2), k.staircase(4), k.on_side(_R)),
    ),
    _c(
        "rel-08",
        REL,
        "Two walls, each 4 long and 3 high, facing each other with a 2 cube gap between them.",
        k.pair(k.wall(4, 3), k.wall(4, 3), k.parallel_gap(2)),
    ),
    _c(
        "rel-09",
        REL,
        "place a 2x2 block two cubes high in front of a 5-cube tower, with a gap between them",
        k.pair(k.block(2, 2, 2), T(5), k.on_side(_F)),
    ),
    _c(
        "rel-10",
        REL,
        "build a small bridge and a tower of 6 to the left of it",
        _placed(T(6), _BRIDGE, _L, 6),
    ),
    _c(
        "rel-11",
        REL,
        "set up a table with four legs 2 cubes tall, and a tower of 3 beside it",
        _next(T(3), _roofed(4, 2), k.with_column(3, _roofed(4, 2))),
    ),
    _c(
        "rel-12",
        REL,
        "Could you make a castle and put a little 2-cube tower in front of it?",
        _placed(T(2), k.castle, _F, 2),
    ),
    _c(
        "rel-13",
        REL,
        "tower of 5 between two towers of 2, one cube gap on each side",
        k.line(T(2), T(5), T(2), gaps=(1,)),
    ),
    _c(
        "rel-14",
        REL,
        "Surround a 2x2 block with a ring of cubes.",
        k.any_of(k.around(k.solid(2, 2)), one(k.holding(k.solid(2, 2), k.ring))),
    ),
    _c(
        "rel-15",
        REL,
        "Two 3-cube towers with cubes going across the top to join them, no beams.",
        one(_bar_on_posts(3, 3), k.only_cubes),
    ),
    _c(
        "rel-16",
        REL,
        "put a row of 5 in front of a wall that's 5 long and 3 high, leaving one cube of space",
        k.pair(k.row(5), k.wall(5, 3), k.all_rels(k.parallel_gap(1), k.on_side(_F))),
    ),
    _c(
        "rel-17",
        REL,
        "build an L shape with arms of 3 and put a 4 high tower right next to it",
        _next(
            T(4),
            _letter("L", (3, 3), (4, 4)),
            k.with_column(4, _letter("L", (3, 3), (4, 4))),
            gap=0.10,
        ),
    ),
    _c(
        "rel-18",
        REL,
        "I want a staircase of 3 steps to the right of a 3-level pyramid",
        k.pair(k.staircase(3), k.pyramid(3), k.on_side(_R)),
    ),
    _c(
        "rel-19",
        REL,
        "Stack a 2x2 block, 2 high, on top of a 4x4 slab, centred.",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.centred(), k.levels(16, 4, 4)),
    ),
    _c(
        "rel-20",
        REL,
        "Make an arch with a tower of 2 a little way off on either side of it, then add a cube "
        "to each of the towers.",
        k.between_(_ARCH, T(3)),
    ),
    _c(
        "rel-21",
        REL,
        "Can you put a tower of 4 directly behind a tower of 2 so they're touching?",
        one(_col_beside(4, T(2), _B)),
    ),
    _c(
        "rel-22",
        REL,
        "Make two rows of 4, one behind the other, 2 cubes apart",
        _rows_behind(4, 2),
    ),
    _c(
        "rel-23",
        REL,
        "Set up a canopy with legs 3 cubes high and, a bit in front of it, a row of 4.",
        k.pair(k.row(4), _roofed(4, 3), k.all_rels(k.on_side(_F), k.within(0.25))),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "Build a tower of 5, then take 2 cubes off the top.", one(T(3))),
    _c(
        "seq-02",
        SEQ,
        "make a wall 4 long and 2 high. after that make it one cube taller",
        one(k.wall(4, 3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Stack 3 cubes in the back right corner. Actually make it 5.",
        one(T(5), reg("back right")),
    ),
    _c(
        "seq-04",
        SEQ,
        "Put down a 4 by 4 slab, then a tower of 3 in the middle of it.",
        one(k.on_top(T(3), k.block(4, 4, 1)), k.centred(), k.levels(16, 1, 1, 1)),
    ),
    _c(
        "seq-05",
        SEQ,
        "first a row of 4 going left to right, then another row of 4 right behind it",
        k.any_of(
            one(k.block(2, 4, 1), k.runs("y")),
            k.pair(
                k.all_of(k.row(4), k.runs("y")),
                k.all_of(k.row(4), k.runs("y")),
                k.all_rels(k.on_side(_B), k.within(0.10)),
            ),
        ),
    ),
    _c(
        "seq-06",
        SEQ,
        "Build a staircase of 3 steps. Then add one more step to it.",
        one(k.staircase(4)),
    ),
    _c(
        "seq-07",
        SEQ,
        "make two towers of 3 with a gap of one cube, then lay a beam across them",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Lay out a row of 6 cubes from left to right. Then remove the two on the left end.",
        one(k.row(4), k.runs("y")),
    ),
    _c(
        "seq-09",
        SEQ,
        "build a pyramid with a 3x3 base, then take off the top cube",
        one(k.any_of(k.pyramid_counts(9, 4), k.block(3, 3, 1))),
    ),
    _c(
        "seq-10",
        SEQ,
        "Stack a tower of 2 at the front left, then do the same at the front right.",
        k.structures(k.all_of(T(2), reg("front left")), k.all_of(T(2), reg("front right"))),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build a 2x2 block 3 high and then put another layer on top of it",
        one(k.block(2, 2, 4)),
    ),
    _c(
        "seq-12",
        SEQ,
        "I want a ring, 4 by 4, one cube high. Then make it two high.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Build a tower of 4 in the centre. Then build one twice as tall right next to it.",
        k.any_of(
            k.pair(T(8), k.all_of(T(4), reg("centre")), k.within(0.10)),
            one(k.cell_heights(8, 4), reg("centre")),
        ),
    ),
    _c(
        "seq-14",
        SEQ,
        "Build a wall 8 long and 2 high, then take out the two middle columns so there's a gap "
        "in it.",
        k.line(k.wall(3, 2), k.wall(3, 2), gaps=(2,)),
    ),
    _c(
        "seq-15",
        SEQ,
        "build a table with legs 2 high. then put one cube on top of it",
        one(_topped(_roofed(4, 2), 1)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Make a staircase of 5 steps going up towards the back, then take away the top step.",
        one(k.any_of(k.all_of(k.staircase(4), k.rises(_B)), k.xprofile(1, 2, 3, 4, 4))),
    ),
    _c(
        "seq-17",
        SEQ,
        "Two towers of 4, side by side, a cube apart. Now take one cube off the left one.",
        k.pair(T(3), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Start with a ring of cubes 4 by 4, one high, then put a 2-cube tower on each corner.",
        one(
            k.any_of(
                k.plan_heights("3113", "1..1", "1..1", "3113"),
                k.plan_heights("2112", "1..1", "1..1", "2112"),
            )
        ),
    ),
    _c(
        "seq-19",
        SEQ,
        "build a bridge with pillars 3 high. actually, make the pillars 2 high",
        one(_span(2)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Lay a 2 by 3 block two high, then add one more layer to it.",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Three towers in a row, heights 2, 3 and 4, one cube between each. Then take away the "
        "middle one.",
        k.pair(T(2), T(4), k.gap_of(3)),
    ),
    _c(
        "seq-22",
        SEQ,
        "Make 4 towers of 2 in a line, a cube apart. Then make the first and the last ones 4 high.",
        k.line(T(4), T(2), T(2), T(4), gaps=(1,)),
    ),
    _c(
        "seq-23",
        SEQ,
        "Build a wall 6 long and 2 high, running left to right, with a tower of 3 on each end. "
        "Then take the one on the right away.",
        k.any_of(
            one(
                k.any_of(
                    k.lr_profile(5, 2, 2, 2, 2, 2),
                    k.lr_profile(3, 2, 2, 2, 2, 2),
                    k.lr_profile(3, 2, 2, 2, 2, 2, 2),
                )
            ),
            k.pair(
                T(3),
                k.all_of(k.wall(6, 2), k.runs("y")),
                k.all_rels(k.on_side(_L), k.within(0.25)),
            ),
        ),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "build a tower with seven cubes in it", one(T(7))),
    _c("num-02", NUM, "make a row of twelve cubes", one(k.row(12))),
    _c("num-03", NUM, "I need a slab 3 cubes by 5 cubes", one(k.block(3, 5, 1))),
    _c("num-04", NUM, "Could you stack nine cubes into one tall tower?", one(T(9))),
    _c("num-05", NUM, "let's have a pyramid with 4 levels", one(k.pyramid(4))),
    _c("num-06", NUM, "staircase, six steps, please", one(k.staircase(6))),
    _c(
        "num-07",
        NUM,
        "two towers, one 2 high and one 6 high, with a 3 cube gap",
        k.pair(T(2), T(6), k.gap_of(3)),
    ),
    _c(
        "num-08",
        NUM,
        "Build four towers of 3 in a row with 2-cube gaps, then add a cube to each of them.",
        k.in_line(4, T(4), 2),
    ),
    _c(
        "num-09",
        NUM,
        "five single cubes in a line across the back, each one cube apart",
        k.all_of(k.in_order("y", *[T(1)] * 5, gaps=(1,)), k.layout(reg("back"))),
    ),
    _c("num-10", NUM, "a block that's 3 wide, 3 deep and 2 high", one(k.block(3, 3, 2))),
    _c(
        "num-11",
        NUM,
        "A tower of 7, and a tower of 2 next to it.",
        _next(T(2), T(7), k.cell_heights(7, 2)),
    ),
    _c("num-12", NUM, "wall: ten cubes long, two cubes high", one(k.wall(10, 2))),
    _c(
        "num-13",
        NUM,
        "an enclosure made of 16 cubes, square, one high",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5), k.parts(16)),
    ),
    _c(
        "num-14",
        NUM,
        "Make 3 towers, 1, 2 and 3 cubes tall, left to right. Then make the tall one 5 high.",
        k.in_order("y", T(1), T(2), T(5)),
    ),
    _c(
        "num-15",
        NUM,
        "Build a tower of 3 and, beside it, one twice as tall",
        _next(T(6), T(3), k.cell_heights(6, 3)),
    ),
    _c(
        "num-16",
        NUM,
        "a castle with walls 2 high and corner towers 4 high",
        one(_castle(2, 4)),
    ),
    _c("num-17", NUM, "Give me a 4x4 grid of cubes", _grid(4, 4)),
    _c(
        "num-18",
        NUM,
        "two bridges side by side, each with pillars 2 cubes high, and leave a 2 cube gap "
        "between the bridges",
        k.pair(_span(2), _span(2), k.gap_of(2)),
    ),
    _c("num-19", NUM, "a row of 3 cubes, then add 4 more to the end of it", one(k.row(7))),
    _c("num-20", NUM, "make a tower of 10, then remove 6 from the top", one(T(4))),
    _c(
        "num-21",
        NUM,
        "a U shape 5 cubes wide with arms 3 long, one cube high",
        one(_letter("U", (5, 3), (5, 4)), k.height(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "I need a tower that's 20 cm tall", one(T(4))),
    _c("dim-02", DIM, "put up a wall 30cm long and 15cm high", one(k.wall(6, 3))),
    _c("dim-03", DIM, "give me a slab 15 cm by 20 cm", one(k.block(3, 4, 1))),
    _c("dim-04", DIM, "I'd like a block 10cm x 10cm, 25cm high", one(k.block(2, 2, 5))),
    _c("dim-05", DIM, "make a row 0.4 m long", one(k.row(8))),
    _c("dim-06", DIM, "can you build a tower 350 mm high", one(T(7))),
    _c("dim-07", DIM, "a staircase 20cm tall", one(k.staircase(4))),
    _c("dim-08", DIM, "pyramid with a base 25 cm square", one(k.pyramid(), k.base(5, 5))),
    _c(
        "dim-09",
        DIM,
        "a ring 25cm across on the outside and 10 cm high",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-10",
        DIM,
        "a table about 15 cm square with legs 10 cm tall",
        one(_roofed(4, 2), k.dims(3, 3)),
    ),
    _c(
        "dim-11",
        DIM,
        "two towers 15 cm high, 10 cm apart",
        k.pair(T(3), T(3), k.gaps(2, 1)),
    ),
    _c("dim-12", DIM, "a bridge with 150mm pillars and a beam on top", one(_beam_bridge(3))),
    _c(
        "dim-13",
        DIM,
        "an L shape, each arm 20 cm long, 5 cm high",
        one(_letter("L", (4, 4), (5, 5)), k.height(1)),
    ),
    _c("dim-14", DIM, "build a wall half a metre long and 10 cm tall", one(k.wall(10, 2))),
    _c(
        "dim-15",
        DIM,
        "a 30 cm tower and a 10 cm tower with a 5 cm gap between them",
        k.pair(T(6), T(2), k.gap_of(1)),
    ),
    _c("dim-16", DIM, "an arch about 20 cm high", one(_ARCH, k.height(lo=4, hi=5))),
    _c(
        "dim-17",
        DIM,
        "a flat T shape, the top bar 25 cm and the stem 15 cm",
        one(_letter("T", (5, 3), (5, 4)), k.height(1)),
    ),
    _c(
        "dim-18",
        DIM,
        "a 15 by 15 cm slab, 5 cm thick, with a 20 cm tower standing on it",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.levels(9, 1, 1, 1, 1)),
    ),
    _c("dim-19", DIM, "build a tower 25cm tall then take 10 cm off it", one(T(3))),
    _c("dim-20", DIM, "make a row 20 cm long. then make it 35 cm long", one(k.row(7))),
    _c(
        "dim-21",
        DIM,
        "Put two walls 25 cm long and 10 cm high parallel to each other, 15 cm apart.",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.either(k.parallel_gap(3), k.parallel_gap(2))),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 6, but not in the middle of the table",
        one(T(6), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "Build a 3x3 square of cubes without the one in the centre",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-03",
        NEG,
        "staircase of 4 steps that doesn't go up towards the robot",
        one(k.staircase(4), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-04",
        NEG,
        "make a pyramid 3 levels high, don't use any beams",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-05",
        NEG,
        "a row of 5 that doesn't run left to right",
        one(k.row(5), k.runs("x")),
    ),
    _c("neg-06", NEG, "two towers of 4, not touching each other", k.each(2, T(4))),
    _c(
        "neg-07",
        NEG,
        "wall 5 long 3 high, not at the back",
        one(k.wall(5, 3), k.not_(reg("back"), "at the back")),
    ),
    _c(
        "neg-08",
        NEG,
        "a bridge with legs of 2, no beam please, just cubes",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "a tower of 3 and a tower of 5 near each other but not touching",
        k.pair(T(3), T(5), k.within(0.25)),
    ),
    _c(
        "neg-10",
        NEG,
        "Build a table with four legs 3 high, but without any beams",
        one(_roof_on(4, 3), k.only_cubes),
    ),
    _c(
        "neg-11",
        NEG,
        "a 2x2 block 2 high at the front and a tower of 6 that isn't at the front",
        k.structures(
            k.all_of(k.block(2, 2, 2), reg("front")),
            k.all_of(T(6), k.not_(reg("front"), "at the front")),
        ),
    ),
    _c(
        "neg-12",
        NEG,
        "three towers of 2 in a row, none of them touching, and make the one on the left 4 high",
        k.in_order("y", T(4), T(2), T(2)),
    ),
    _c(
        "neg-13",
        NEG,
        "a tower of 5 anywhere except the left side",
        one(T(5), k.not_(reg("left"), "on the left")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "biuld a towr of 4 cubes", one(T(4))),
    _c("typo-02", TYP, "make a pyramyd with 3 levles", one(k.pyramid(3))),
    _c("typo-03", TYP, "staircse with 5 setps", one(k.staircase(5))),
    _c(
        "typo-04",
        TYP,
        "a wal 6 long and 2 hihg at the back",
        one(k.wall(6, 2), reg("back")),
    ),
    _c("typo-05", TYP, "two towers of 3 joined by a beem on top", one(_beam_bridge(3))),
    _c("typo-06", TYP, "a 2x3 blcok, 2 high", one(k.block(2, 3, 2))),
    _c(
        "typo-07",
        TYP,
        "put a ring of cubes 5x5 in the midle",
        one(_RING5, reg("centre")),
    ),
    _c(
        "typo-08",
        TYP,
        "a tower of 5 behnid a tower of 2",
        _placed(T(5), T(2), _B, 5),
    ),
    _c("typo-09", TYP, "cna you make a slab 4 by 4 pleas", one(k.block(4, 4, 1))),
    _c("typo-10", TYP, "Build a tower of 3 than put 2 more on top", one(T(5))),
    _c(
        "typo-11",
        TYP,
        "three rows of 4, paralel, one cube apart, then remvoe the middle one",
        k.pair(k.row(4), k.row(4), k.parallel_gap(3)),
    ),
    _c("typo-12", TYP, "build an arhc in the middle of the table", one(_ARCH, reg("centre"))),
    _c(
        "typo-13",
        TYP,
        "pyrmid of 2 levels to the rigth of a 4 tower",
        k.any_of(
            k.pair(k.pyramid(2), T(4), k.on_side(_R)),
            one(_col_beside(4, k.pyramid(2), _L)),
        ),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "At the back left, a tower of 3.", one(T(3), reg("back left"))),
    _c("wo-02", WO, "20 cm long and 10 cm high, that's the wall I want", one(k.wall(4, 2))),
    _c(
        "wo-03",
        WO,
        "In the centre of the table put a pyramid, 3 levels",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "wo-04",
        WO,
        "In front of the staircase, a tower of 2 - and the staircase has 4 steps.",
        _placed(T(2), k.staircase(4), _F, 2),
    ),
    _c(
        "wo-05",
        WO,
        "Four steps up to the left - a staircase",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "wo-06",
        WO,
        "On top of a 2 by 2 slab, a tower of 3",
        one(k.on_top(T(3), k.block(2, 2, 1)), k.levels(4, 1, 1, 1)),
    ),
    _c(
        "wo-07",
        WO,
        "Three high and five long, a wall on the right side",
        one(k.wall(5, 3), reg("right")),
    ),
    _c(
        "wo-08",
        WO,
        "To the left of the pyramid put a 4 tower. The pyramid should have 3 levels.",
        _placed(T(4), k.pyramid(3), _L, 4),
    ),
    _c("wo-09", WO, "With legs 3 high, a table", one(_roofed(4, 3))),
    _c(
        "wo-10",
        WO,
        "A gap of 2 cubes between them, two towers of 5",
        k.pair(T(5), T(5), k.gap_of(2)),
    ),
    _c(
        "wo-11",
        WO,
        "Add two cubes on top once you've built a tower of 4",
        one(T(6)),
    ),
    _c(
        "wo-12",
        WO,
        "Left to right: a tower of 4, a tower of 2, a tower of 4, each a cube apart.",
        k.in_order("y", T(4), T(2), T(4), gaps=(1,)),
    ),
    _c(
        "wo-13",
        WO,
        "Five cubes in a row, and a little in front of them a 2x2 block 2 high",
        k.pair(k.block(2, 2, 2), k.row(5), k.all_rels(k.on_side(_F), k.within(0.25))),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi! First time using this. Could you build a tower of 4 for me? Thanks",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok so my group is doing a demo at 3 and we need a staircase with 5 steps",
        one(k.staircase(5)),
    ),
    _c(
        "fil-03",
        FIL,
        "Hello, I'm here with the school trip. Can the robot make a pyramid? Maybe 3 levels?",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-04",
        FIL,
        "Morning! Coffee machine's broken again. Anyway, two towers of 3 with a one cube gap "
        "please",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-05",
        FIL,
        "I'm writing up my lab report and need a photo of a wall, 6 cubes long and 3 high, so "
        "could you build one?",
        one(k.wall(6, 3)),
    ),
    _c(
        "fil-06",
        FIL,
        "we've got 20 minutes before the visitors arrive so let's just do a 3x3 slab with a "
        "tower of 2 on it",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.levels(9, 1, 1)),
    ),
    _c(
        "fil-07",
        FIL,
        "Testing the new gripper today. Let's start simple: a row of 4 cubes.",
        one(k.row(4)),
    ),
    _c(
        "fil-08",
        FIL,
        "right, let's see if this works. build a tower of 3, then put another tower of 3 next "
        "to it",
        _next(T(3), T(3), k.cell_heights(3, 3)),
    ),
    _c(
        "fil-09",
        FIL,
        "My daughter wants to see a castle! Can you build a small one?",
        one(k.castle),
    ),
    _c(
        "fil-10",
        FIL,
        "Good afternoon. For the test run I'd like a bridge with 2-high pillars and a tower of "
        "4 behind it. That's all, thank you.",
        _placed(T(4), _span(2), _B, 4),
    ),
    _c(
        "fil-11",
        FIL,
        "Sorry if this is confusing, I'm new here. I'd like three towers of 2 in a line, a cube "
        "apart, and then a cube on top of the middle one",
        k.line(T(2), T(3), T(2), gaps=(1,)),
    ),
    _c(
        "fil-12",
        FIL,
        "Quick one before lunch: pyramid of 2 levels on the left, staircase of 3 steps on the "
        "right",
        k.structures(k.all_of(k.pyramid(2), reg("left")), k.all_of(k.staircase(3), reg("right"))),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower of 5 in the front right corner", one(T(5), reg("front right"))),
    _c(
        "reg-02",
        REG,
        "build a wall 6 long and 2 high along the back edge of the table",
        one(k.wall(6, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-03",
        REG,
        "put a 2x2 block, 3 high, in the middle of the table",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    _c(
        "reg-04",
        REG,
        "a staircase of 3 steps near the robot",
        one(k.staircase(3), reg("front")),
    ),
    _c(
        "reg-05",
        REG,
        "an enclosure 4 by 4, 1 high, over on the left side",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4), reg("left")),
    ),
    _c(
        "reg-06",
        REG,
        "put a pyramid with a 3x3 base as far from the robot as it can go",
        one(k.pyramid(), k.base(3, 3), k.min_x(0.60)),
    ),
    _c(
        "reg-07",
        REG,
        "a row of 6 cubes going front to back down the right side",
        one(k.row(6), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-08",
        REG,
        "a tower of 4 at the back left and a tower of 2 at the front right",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(2), reg("front right"))),
    ),
    _c(
        "reg-09",
        REG,
        "two 2x2 blocks, one in each back corner",
        k.structures(
            k.all_of(k.solid(2, 2), reg("back left")),
            k.all_of(k.solid(2, 2), reg("back right")),
        ),
    ),
    _c(
        "reg-10",
        REG,
        "Build an L shape with arms 4 long in the back right corner, one cube high",
        one(_letter("L", (4, 4), (5, 5)), k.height(1), reg("back right")),
    ),
    _c(
        "reg-11",
        REG,
        "Put a tower of 3 in every corner of the table, then make the one at the back left 6 high",
        k.structures(
            k.all_of(T(6), reg("back left")),
            *[k.all_of(T(3), reg(r)) for r in _CORNERS[1:]],
        ),
    ),
    _c(
        "reg-12",
        REG,
        "a bridge in the centre of the table, pillars 3 high",
        one(_span(3), reg("centre")),
    ),
    _c(
        "reg-13",
        REG,
        "a wall 5 long and 2 high across the front, and a castle at the back",
        k.structures(
            k.all_of(k.wall(5, 2), k.runs("y"), reg("front")),
            k.all_of(k.castle, reg("back")),
        ),
    ),
    _c(
        "reg-14",
        REG,
        "a tower of 6 in the centre with 4 single cubes around it, one on each side, a cube away",
        k.on_every_side(k.all_of(T(6), reg("centre")), T(1), 1),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "build whatever you like", k.anything),
    _c(
        "open-02",
        OPEN,
        "make something tall, your choice",
        k.all_of(k.anything, k.layout(k.height(lo=_TALL))),
    ),
    _c(
        "open-03",
        OPEN,
        "any shape you want as long as it uses 10 cubes or fewer",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-04",
        OPEN,
        "Something with a gap underneath, like a bridge or an arch",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-05",
        OPEN,
        "two different structures, you choose, on opposite sides of the table",
        k.all_of(k.anything, k.pair(_any, _any, k.all_rels(_opposite_ends, _differ))),
    ),
    _c(
        "open-06",
        OPEN,
        "surprise me, but keep it at the back of the table",
        k.all_of(k.anything, k.layout(reg("back"))),
    ),
    _c(
        "open-07",
        OPEN,
        "build something small in the front left",
        k.all_of(k.small, k.layout(reg("front left"))),
    ),
    _c("open-08", OPEN, "a tower, any height you like", one(T(lo=2, hi=10))),
    _c(
        "open-09",
        OPEN,
        "three structures of your choice in a row, not touching",
        k.all_of(k.anything, _count(3), k.in_line(3, _any)),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "build a tower 3 cubes high and 7 cubes high",
        k.honest(one(k.any_of(T(3), T(7)))),
    ),
    _c(
        "bad-02",
        BAD,
        "could you stack up a tower of 15 cubes",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-03",
        BAD,
        "make a wall 2 metres long",  # 40 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-04",
        BAD,
        "put a tower of 3 one metre to the left of the table",  # off the table
        k.honest(one(T(3))),
    ),
    _c("bad-05", BAD, "what time does the lab close today?", k.honest()),
    _c("bad-06", BAD, "asdfgh jkl qwerty", k.honest()),
    _c("bad-07", BAD, "build a", k.honest(k.anything)),
    _c("bad-08", BAD, "a sphere made of cubes, 20 cm across", k.honest(k.anything)),
    _c("bad-09", BAD, "stack a tower of minus 4 cubes", k.honest(k.anything)),
    _c(
        "bad-10",
        BAD,
        "Build a tower of 4. Actually no, cancel that, don't build anything.",
        k.honest(),
    ),
    _c(
        "bad-11",
        BAD,
        "put a cube on top of the red box",  # nothing is on the table
        k.honest(k.anything),
    ),
    _c("bad-12", BAD, "build the same thing as yesterday", k.honest(k.anything)),
    _c("bad-13", BAD, "make me a pyramid with zero levels in it", k.honest(k.anything)),
    _c(
        "bad-14",
        BAD,
        "a row of 3 and a half cubes",
        k.honest(one(k.any_of(k.row(3), k.row(4)))),
    ),
    _c("bad-15", BAD, "could you turn the robot off when you're done", k.honest()),
    _c(
        "bad-16",
        BAD,
        "a wall 4 long and 2 high that is also 6 long",
        k.honest(one(k.any_of(k.wall(4, 2), k.wall(6, 2)))),
    ),
    _c(
        "bad-17",
        BAD,
        "a ring 20 by 20 cubes",  # past the cell's 12 by 10
        k.honest(k.anything),
    ),
    _c(
        "bad-18",
        BAD,
        "build a tower of 3 out of glass cubes",  # the cell has no glass cubes
        k.honest(one(T(3))),
    ),
]
