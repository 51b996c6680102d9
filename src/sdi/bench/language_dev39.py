"""A thirty-ninth held-out set for the language front end (dev39): plain commands, second writer.

Written blind: without looking at the front end's code (`sdi.language`, `sdi.spec`) or its
tests, the frozen test set's cases, the cases of any other set but dev27 and dev38 (the format
examples), or any benchmark result — only the README, the shared checks
(`language_checks`), the geometry (`boxes`), dev27 and dev38 whole, and the first lines (the
docstrings) of the other sets were read — and worded apart from `language_dev` …
`language_dev38` and the test set (no command shared with any set, compared by a script that
printed only this set's own duplicates). Nothing here was run through the system while it was
written; the module was only imported, and every predicate called on an empty result.

Like dev38 the set has NO voices: its 180 commands are what ordinary people at a robot cell —
operators, engineers, students, visitors — type into a text box, worded afresh by a second
writer: many verbs (build, make, put, place, stack, stand, lay, set, pop, give me, I need,
could you, can we, I'd like, let's have), the place before or after the structure, sizes as
words, digits, cm, mm and m, "3x4" and "2 by 6", articles dropped, casual punctuation, an
ordinary typo now and then, follow-up sentences, small corrections ("oh wait, make that 2
high", "no wait, 8"), polite requests and questions ("could we get …?").

Roughly: 35 % one structure with a size and perhaps a place; 30 % two structures with one
relation (on top of, behind, in front of, to the left / right of, next to, between, joined by
a beam, around / inside) or a gap; 15 % a two- or three-step sequence in one message ("then
take … off", "then bridge them", "oh wait, make that …", "now move it to …"); 10 % three or
more structures with references ("the tall one", "each one", "the middle one", "the first two",
"the one on the right"); 10 % bad input. The families are the cell's: tower / column / stack,
wall, row, slab and grid, block, pyramid, staircase, bridge, arch, table, ring / enclosure,
castle, and the L, T and U shapes.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else.
Conventions (dev38's, which are the shared ones of dev27 and the sets after it, as used here):

* "next to", "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by the column and the
  rest); "right next to it" is at most 10 cm clear, or touching; "not touching", "a gap",
  "apart", "spaced out", "with gaps" mean separate structures;
* "in front of", "behind", "to the left / right of", "on its left" is the dominant direction
  between footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when
  none is said; where nothing rules touching out, a tower so placed may also be set against
  the other as one structure, its column then lying on that side of the rest;
* "N cubes apart", "a gap of N", "a cube of space", "5 cm between them" are the clear gap
  (± 1.5 cm); a bare "10 cm apart" also accepts the centre-to-centre reading (for single
  columns and one-cube-thick walls, one cube less clear); a gap said with no unit is in cubes;
  "facing each other", "parallel" share their long axis and face each other across the gap;
  two walls "one behind the other" may also run front to back, end to end; "in a row / in a
  line" is one line along x or y (the shared `in_line`, `in_order`, `line`); "left to right" is
  the order along -y, "right to left" along +y; "in a square" / "in two rows of three" is an
  evenly gapped array of rows and columns, either way round;
* "between" two structures with the gaps given is the three in one line (`line`); "on each
  side of" a bridge is a line of three either way, the gap said between neighbours;
* "on top of", "on it", "sitting on it" stands on it (the shared `on_top`), anywhere on it
  unless "in the middle", "on the middle" or "centred" is said (then centred over it, ± 3
  cm); "a single cube on top of each end" of a wall stands on its two end columns; "a tower of
  3 on its left end" of a row stands on the left end cube or makes that end three high;
* a bridge's top is a beam (the shared `bridge`, the overall height one more than the posts)
  where the command names a beam, and a beam or a bar of cubes where it does not; "no beam"
  is a bar of cubes only; "15 cm tall overall with a beam on top" is posts of two; an arch is
  anything spanning a gap between two supports; a table is four separate legs under one
  connected top of beams or of cubes (the shared `canopy`, a top of cubes, or the cell's beam
  roof);
* a ring's or enclosure's stated size is its outside, of any height unless one is said; "in
  the middle of", "in the very middle", "in the centre" of a ring is inside its empty interior,
  clear of it, the centres within 3 cm; a ring "around" or "surrounding" a structure is round
  it, clear of it (two structures) or holding it against its walls (one); "a ring out of 12
  cubes, one high" is any closed ring of 12 cubes;
* a castle is the shared `castle`; an L, T or U is its footprint letter (the shared
  `shape_letter`); an arm's stated length is read either with the shared corner cell or beyond
  it; "flat" / "one layer" is one high, "make it 2 high" makes every column two high;
* a staircase's width is free, and so is the way it climbs unless said; a pyramid's step and
  base are free unless given; "N levels" is N levels; "15 cm tall" is three;
* a grid of cubes is a full one-layer slab or single cubes standing apart in even rows and
  columns; a slab is one layer unless a thickness is given; "15 x 15 x 10 cm", "3 by 3 and 2
  high" give a block's footprint and then its height;
* a cube is 5 cm: "30cm", "100mm", "0.25 m", "45 cm" are 6, 2, 5 and 9 cubes; a hedged figure
  ("with 4 steps I guess") is the figure;
* in a sequence the finished state counts: "oh wait, make that N" replaces the figure, "now
  move it to …" moves it, "scrap the castle and make … instead" leaves only the new one, "the
  first two" of three towers in a line are two neighbours at either end, "the tall one" is the
  tallest, "the middle one" the one between the other two;
* "something nice", "you pick", "your pick", "doesn't matter what" leave everything free but
  what is said; "low and wide" is at most two cubes high and at least two cubes each way in
  plan; "with steps in it" is a staircase or a pyramid; "something you could look through" is
  anything spanning a gap or a ring; "a tall thing and a short thing" only compares the two;
  "three different things" differ pairwise in footprint, height or part count; numbers in
  chatter ("it's 2pm", "a group of 15 students") are never sizes;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "close to the robot" is the front; "against the back edge" is every part at x ≥ 0.60; "as
  far back as it'll go" reaches the back edge of the workspace (within 2 cm); "along the left
  edge" is a footprint centre at y ≥ 0.45; "in each of the four corners" are the corner
  regions; "not at the front", "anywhere but the right side", "none of them at the front" are
  outside that region.

Bad input (contradictions, sizes past the cell or below one cube, a place off the table,
shapes or finishes the cell does not have, things that are not on the table, a half-typed
command, nothing to go on, gibberish) is honest only as an error (or a failure) or as a layout
WITH notes naming the assumption (`k.honest`); a request that is not a build at all, or that
was cancelled, admits only the refusal. Geometry comes only from `sdi.bench.boxes`, through
the shared checks in `language_checks` and the local checks below (several copied from dev38).

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

_LOW = 2  # cubes: "low" is at most this high


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev39-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _any(bs: k.Boxes) -> k.Reason:
    """Any structure at all."""
    return None if bs else "no parts"


def _free(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """No relation asked for between A and B."""
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


def _bar_on_posts(
    lo: int | None = None, hi: int | None = None, mouth: int | None = None
) -> k.Check:
    """Two separate posts lo–hi cubes high (any height when None), `mouth` cubes apart clear
    (± 1.5 cm) when given, and as the topmost level one connected bar resting on both — a beam
    or a row of cubes (from dev38)."""

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


def _col_beside(h: int, rest: k.Check, side: str) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table, set against the rest,
    which passes `rest`; the column lies to `side` of the rest (from dev38)."""

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


def _differ(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B are different structures: footprint, height or part count differ."""
    same = (
        bx.plan_dims(a) == bx.plan_dims(b)
        and bx.thickness_cubes(a) == bx.thickness_cubes(b)
        and len(a) == len(b)
    )
    return "the two structures are alike" if same else None


def _all_differ(result: Mapping[str, Any]) -> k.Reason:
    """Every two separate structures of the layout differ (`_differ`)."""
    comps = k.separate_structures(result)
    if isinstance(comps, str):
        return comps
    for a, b in itertools.combinations(comps, 2):
        r = _differ(a, b)
        if r:
            return r
    return None


def _taller(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A is taller than B."""
    ha, hb = bx.thickness_cubes(a), bx.thickness_cubes(b)
    return None if ha > hb else f"{ha} high is not taller than {hb}"


def _two_heights(bs: k.Boxes) -> k.Reason:
    """One structure on the table whose columns are not all the same height (a tall part and
    a short part set together)."""
    r = k.on_table(bs)
    if r:
        return r
    tops: dict[tuple[int, int], int] = {}
    for i, j, z in bx.voxels(bs):
        tops[(i, j)] = max(tops.get((i, j), 0), z + 1)
    return None if len(set(tops.values())) >= 2 else "every column the same height"


def _extruded(h: int) -> k.Check:
    """Every footprint cell carries a full column exactly `h` cubes high."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        vox = bx.voxels(bs)
        cells = {(i, j) for i, j, _ in vox}
        if bx.thickness_cubes(bs) != h or len(vox) != len(cells) * h:
            return f"not every column {h} high"
        return None

    return f


def _against_back(bs: k.Boxes) -> k.Reason:
    """The structure reaches the back edge of the workspace (within 2 cm)."""
    if not bs:
        return "no parts"
    hi = max(b.hi[0] for b in bs)
    edge = bx.WORKSPACE[0][1]
    return None if hi >= edge - 0.02 else f"back face at x {hi:.3f}, want ≥ {edge - 0.02:.2f}"


def _clusters(values: list[float], tol: float = 0.01) -> list[float]:
    """The distinct values (within `tol`), lowest first."""
    out: list[float] = []
    for v in sorted(values):
        if not out or v - out[-1] > tol:
            out.append(v)
    return out


def _array(rows: int, cols: int, check: k.Check, gap: int) -> k.Pred:
    """rows × cols separate structures, each passing `check`, standing in a full array of
    rows and columns (either way round), every two neighbours in a row or a column `gap`
    cubes apart, clear (± 1.5 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != rows * cols:
            return f"{len(comps)} separate structures, want {rows * cols}"
        for g in comps:
            r = check(g)
            if r:
                return r
        xs = _clusters([bx.centre(g)[0] for g in comps])
        ys = _clusters([bx.centre(g)[1] for g in comps])
        if sorted((len(xs), len(ys))) != sorted((rows, cols)):
            return f"in {len(xs)} × {len(ys)} lines, want {rows} × {cols}"

        def index(g: k.Boxes) -> tuple[int, int]:
            cx, cy = bx.centre(g)
            ix = min(range(len(xs)), key=lambda i: abs(xs[i] - cx))
            iy = min(range(len(ys)), key=lambda j: abs(ys[j] - cy))
            return ix, iy

        where = [index(g) for g in comps]
        if len(set(where)) != len(comps):
            return "two structures in one cell of the array"
        for (a, ia), (b, ib) in itertools.combinations(zip(comps, where, strict=True), 2):
            if abs(ia[0] - ib[0]) + abs(ia[1] - ib[1]) == 1:
                r = k.gap_of(gap)(a, b)
                if r:
                    return f"neighbours: {r}"
        return None

    return f


def _grid(a: int, b: int) -> k.Pred:
    """An a × b grid of cubes: one full one-layer a × b slab, or a × b single cubes standing
    apart in evenly spaced rows and columns (either way round; from dev38)."""
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


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected top that is the topmost level and rests on every leg (a top of beams or of
    cubes, whose middle cubes rest on nothing; from dev38)."""

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


def _one_behind(check: k.Check, gap: int) -> k.Pred:
    """Two structures passing `check`, the second behind the first, `gap` cubes apart: both
    running left to right and facing across the gap, or both running front to back, end to
    end."""
    across = k.all_of(check, k.runs("y"))
    along = k.all_of(check, k.runs("x"))
    return k.any_of(
        k.pair(across, across, k.all_rels(k.parallel_gap(gap), k.on_side(_B))),
        k.pair(along, along, k.all_rels(k.gap_of(gap), k.on_side(_B))),
    )


def _letter(kind: str, *sizes: tuple[int, int]) -> k.Check:
    """The footprint letter `kind` with one of the footprints `sizes` (either way round)."""
    return k.all_of(k.shape_letter(kind), k.any_of(*[k.dims(a, b) for a, b in sizes]))


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_RING4 = k.all_of(k.ring_of(None, (2, 2)), k.dims(4, 4))  # 4 × 4 outside, any height
_RING5 = k.all_of(k.ring_of(None, (3, 3)), k.dims(5, 5))  # 5 × 5 outside, any height
_RING6 = k.all_of(k.ring_of(None, (4, 4)), k.dims(6, 6))  # 6 × 6 outside, any height
_CORNERS = ("back left", "back right", "front left", "front right")
_NOT_FRONT = k.not_(reg("front"), "at the front")


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "could you put a tower of 6 to the right of a 3 step staircase",
        _placed(T(6), k.staircase(3), _R, 6),
    ),
    _c(
        "rel-02",
        REL,
        "pyramid with 3 levels, and a row of four cubes in front of it",
        k.pair(k.row(4), k.pyramid(3), k.on_side(_F)),
    ),
    _c(
        "rel-03",
        REL,
        "2 walls, both 6 long and 2 tall, parallel, 3 cubes apart",
        k.pair(k.wall(6, 2), k.wall(6, 2), k.parallel_gap(3)),
    ),
    _c(
        "rel-04",
        REL,
        "Build a bridge: two 3-high towers and a beam across.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-05",
        REL,
        "a 2 by 6 slab with a tower of 3 stood on top of it",
        one(k.on_top(T(3), k.block(2, 6, 1)), k.levels(12, 1, 1, 1)),
    ),
    _c(
        "rel-06",
        REL,
        "a 4x4 ring with a single cube in the very middle",
        k.pair(_RING4, T(1), k.centred_in(0.03)),
    ),
    _c(
        "rel-07",
        REL,
        "ring of cubes 6 by 6 around a tower of 4",
        k.any_of(k.around(T(4), _RING6), one(k.holding(T(4), _RING6))),
    ),
    _c(
        "rel-08",
        REL,
        "I need a tower of 5 between two 2x2 blocks, gap of one cube each side",
        k.line(k.solid(2, 2), T(5), k.solid(2, 2), gaps=(1,)),
    ),
    _c(
        "rel-09",
        REL,
        "Set a 2 cube tower right next to the wall, the wall being 5 long, 3 high",
        _next(T(2), k.wall(5, 3), k.with_column(2, k.wall(5, 3)), gap=0.10),
    ),
    _c(
        "rel-10",
        REL,
        "two towers of 5 cubes joined at the top by a beam, 1 cube gap between them",
        one(_beam_bridge(5, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "an arch, and next to it a tower 3 cubes tall",
        _next(T(3), _ARCH, k.with_column(3, _ARCH)),
    ),
    _c(
        "rel-12",
        REL,
        "staircase of 4 with a 2x2 block on its left, leave a gap",
        k.pair(k.solid(2, 2), k.staircase(4), k.on_side(_L)),
    ),
    _c(
        "rel-13",
        REL,
        "a tower of 3 in front of a tower of 6, not touching",
        k.pair(T(3), T(6), k.on_side(_F)),
    ),
    _c(
        "rel-14",
        REL,
        "put an L shape with 4 cube arms behind a row of 5, a bit of space between",
        k.pair(_letter("L", (4, 4), (5, 5)), k.row(5), k.on_side(_B)),
    ),
    _c(
        "rel-15",
        REL,
        "put a single cube on top of each end of a wall 5 long and 2 high",
        one(k.plan_heights("32223")),
    ),
    _c(
        "rel-16",
        REL,
        "a 5 by 5 slab with a 3 level pyramid sitting on it",
        one(k.on_top(k.pyramid(3), k.block(5, 5, 1))),
    ),
    _c(
        "rel-17",
        REL,
        "a wall 4 long, 2 high, and a second one just like it behind it with a cube of space "
        "between",
        _one_behind(k.wall(4, 2), 1),
    ),
    _c(
        "rel-18",
        REL,
        "stack a tower of 4 on the middle of a 3x3 block that's 2 high",
        one(
            k.on_top(T(4), k.block(3, 3, 2)),
            k.top_centred(),
            k.levels(9, 9, 1, 1, 1, 1),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "tower of 2 to the left of a 5-cube tower, with a 2 cube gap",
        k.pair(T(2), T(5), k.gap_of(2, _L)),
    ),
    _c(
        "rel-20",
        REL,
        "could you surround a 3-high tower with a 5x5 enclosure?",
        k.any_of(k.around(T(3), _RING5), one(k.holding(T(3), _RING5))),
    ),
    _c(
        "rel-21",
        REL,
        "towers of 2, 4 and 6 in a line, spaced out, and put one more cube on the tall one",
        k.line(T(2), T(4), T(7)),
    ),
    _c(
        "rel-22",
        REL,
        "a row of 4 along the front, a pyramid of 2 levels behind it and a tower of 5 behind "
        "the pyramid, with gaps between them",
        k.in_order("x", k.all_of(k.row(4), k.runs("y"), reg("front")), k.pyramid(2), T(5)),
    ),
    _c(
        "rel-23",
        REL,
        "Two towers of 3 with a 2x2 block between them, everything a cube apart",
        k.line(T(3), k.solid(2, 2), T(3), gaps=(1,)),
    ),
    _c(
        "rel-24",
        REL,
        "a bridge with 2-high pillars, and a tower of 4 on each side of it, a cube away",
        k.line(T(4), _span(2), T(4), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "build a 6 high tower and then take the top 3 cubes off", one(T(3))),
    _c(
        "seq-02",
        SEQ,
        "lay a row of 5 cubes, then put a second row on top of it",
        one(k.wall(5, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Make a 3x3 slab. Then put a 2x2 layer on it.",
        one(k.on_top(k.block(2, 2, 1), k.block(3, 3, 1)), k.levels(9, 4)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Build a staircase with 3 steps then keep going until it has 6",
        one(k.staircase(6)),
    ),
    _c(
        "seq-05",
        SEQ,
        "tower of 3 at the front left. after that another one at the back right, 5 high",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(5), reg("back right"))),
    ),
    _c(
        "seq-06",
        SEQ,
        "put down a row of 4 going left to right, then build a tower of 3 on its left end",
        one(k.any_of(k.lr_profile(4, 1, 1, 1), k.lr_profile(3, 1, 1, 1))),
    ),
    _c(
        "seq-07",
        SEQ,
        "Build two 4-cube towers a cube apart. Then bridge them with a beam.",
        one(_beam_bridge(4, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "make a 2 by 2 block 4 high, then knock the top two layers off",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "A wall 7 long, 3 high please. Oh wait, make that 2 high.",
        one(k.wall(7, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "build an enclosure 5x5, one cube high, then put a tower of 3 in the middle of it",
        k.pair(k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5)), T(3), k.centred_in(0.03)),
    ),
    _c(
        "seq-11",
        SEQ,
        "make a tower of 2, then put three more cubes on it, then one more",
        one(T(6)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Place a 3 step staircase, then a tower of 4 to its right",
        _placed(T(4), k.staircase(3), _R, 4),
    ),
    _c(
        "seq-13",
        SEQ,
        "lay a 2x4 slab, then put another 2x4 slab on top of that",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "seq-14",
        SEQ,
        "first a row of 3 going front to back, then turn it so it runs left to right",
        one(k.row(3), k.runs("y")),
    ),
    _c(
        "seq-15",
        SEQ,
        "build a castle. actually no, scrap the castle and make a 3 level pyramid instead",
        one(k.pyramid(3)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Build a U shape 4 wide with 3-cube arms. Then make it 2 high.",
        one(_letter("U", (4, 3), (4, 4)), _extruded(2)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Stack 4 cubes into a tower. Now move it to the back left corner.",
        one(T(4), reg("back left")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build three towers of 3 in a row with a cube gap. Then put a beam over the first two.",
        k.pair(_beam_bridge(3, 1), T(3), k.gap_of(1)),
    ),
    _c(
        "seq-19",
        SEQ,
        "three towers, 2, 4 and 6 high, left to right, a cube apart. then make the middle one "
        "as tall as the one on the right",
        k.in_order("y", T(2), T(6), T(6), gaps=(1,)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Build 4 separate towers of 2 in a line, then add 2 cubes to each one",
        k.in_line(4, T(4)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Make three 2x2 blocks in a line, 2 cubes apart, one high. Then stack a tower of 3 on "
        "the middle block.",
        k.line(
            k.block(2, 2, 1),
            k.all_of(k.on_top(T(3), k.block(2, 2, 1)), k.levels(4, 1, 1, 1)),
            k.block(2, 2, 1),
            gaps=(2,),
        ),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "tower, eight cubes", one(T(8))),
    _c("num-02", NUM, "Give me a wall eleven long and three high", one(k.wall(11, 3))),
    _c("num-03", NUM, "a slab of 4 by 6 cubes", one(k.block(4, 6, 1))),
    _c("num-04", NUM, "a table with 4 legs, each leg two cubes", one(_roofed(4, 2))),
    _c("num-05", NUM, "can we get a staircase with eight steps", one(k.staircase(8))),
    _c(
        "num-06",
        NUM,
        "make a ring out of 12 cubes, one high",
        one(k.ring_of(1), k.parts(12)),
    ),
    _c("num-07", NUM, "Build me a column of 6.", one(T(6))),
    _c("num-08", NUM, "a 5x2 block, three layers", one(k.block(5, 2, 3))),
    _c(
        "num-09",
        NUM,
        "a T shape, bar of 5, stem of 3, one layer",
        one(_letter("T", (5, 3), (5, 4)), k.height(1)),
    ),
    _c(
        "num-10",
        NUM,
        "an L with one arm 5 long and the other 3, flat",
        one(_letter("L", (5, 3), (6, 4), (5, 4), (6, 3)), k.height(1)),
    ),
    _c(
        "num-11",
        NUM,
        "a tower of nine and a tower of one, 4 cubes between them",
        k.pair(T(9), T(1), k.gap_of(4)),
    ),
    _c(
        "num-12",
        NUM,
        "two rows of 6, two cubes apart, parallel",
        k.pair(k.row(6), k.row(6), k.parallel_gap(2)),
    ),
    _c(
        "num-13",
        NUM,
        "a 3 by 3 slab and a 2 by 2 slab, with a gap of three cubes",
        k.pair(k.block(3, 3, 1), k.block(2, 2, 1), k.gap_of(3)),
    ),
    _c(
        "num-14",
        NUM,
        "a pair of 7-high towers, 2 apart",
        k.pair(T(7), T(7), k.gap_of(2)),
    ),
    _c("num-15", NUM, "build a 9 cube tower, then remove four", one(T(5))),
    _c("num-16", NUM, "a row of 6, no wait, 8", one(k.row(8))),
    _c(
        "num-17",
        NUM,
        "make a staircase of 6 steps. then remove 2 steps",
        one(k.staircase(4)),
    ),
    _c(
        "num-18",
        NUM,
        "three towers, 1, 2 and 3 cubes tall, right to left, with 2 cube gaps",
        k.in_order("y", T(3), T(2), T(1), gaps=(2,)),
    ),
    _c(
        "num-19",
        NUM,
        "five towers of 2 in a line, one cube apart, and make the middle one 6 high",
        k.line(T(2), T(2), T(6), T(2), T(2), gaps=(1,)),
    ),
    _c(
        "num-20",
        NUM,
        "4 single cubes in a square, 2 cubes apart",
        _array(2, 2, T(1), 2),
    ),
    _c(
        "num-21",
        NUM,
        "six towers of 3, in two rows of three, a cube apart",
        _array(2, 3, T(3), 1),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a tower 30cm high", one(T(6))),
    _c("dim-02", DIM, "wall, 40 cm long, 15 cm tall", one(k.wall(8, 3))),
    _c("dim-03", DIM, "slab 20cm x 30cm", one(k.block(4, 6, 1))),
    _c("dim-04", DIM, "make a row of cubes 0.25 m long", one(k.row(5))),
    _c("dim-05", DIM, "stack cubes up to 45 cm", one(T(9))),
    _c("dim-06", DIM, "Could the robot build a pyramid 15 cm tall?", one(k.pyramid(3))),
    _c("dim-07", DIM, "a 2 by 2 block 100mm tall", one(k.block(2, 2, 2))),
    _c("dim-08", DIM, "staircase 250 mm high please", one(k.staircase(5))),
    _c(
        "dim-09",
        DIM,
        "an enclosure 30 cm by 20 cm, 5 cm high",
        one(k.ring_of(1, (4, 2)), k.dims(6, 4)),
    ),
    _c(
        "dim-10",
        DIM,
        "a bridge 15cm tall overall with a beam on top",
        one(_beam_bridge(2)),
    ),
    _c("dim-11", DIM, "a block measuring 15 x 15 x 10 cm", one(k.block(3, 3, 2))),
    _c("dim-12", DIM, "lay a row 60cm long", one(k.row(12))),
    _c("dim-13", DIM, "square slab, 25 cm on each side", one(k.block(5, 5, 1))),
    _c(
        "dim-14",
        DIM,
        "two towers, 10 cm and 20 cm tall, 10 cm apart",
        k.pair(T(2), T(4), k.gaps(2, 1)),
    ),
    _c(
        "dim-15",
        DIM,
        "a 35 cm tower behind a wall 25 cm long and 10 cm high",
        _placed(T(7), k.wall(5, 2), _B, 7),
    ),
    _c(
        "dim-16",
        DIM,
        "two rows 30 cm long with 5 cm between them",
        k.pair(k.row(6), k.row(6), k.gap_of(1)),
    ),
    _c(
        "dim-17",
        DIM,
        "a 20 cm tower and a 5 cm one, 15 cm apart",
        k.pair(T(4), T(1), k.gaps(3, 2)),
    ),
    _c(
        "dim-18",
        DIM,
        "a slab 10 by 20 cm and a tower 25 cm tall on it",
        one(k.on_top(T(5), k.block(2, 4, 1)), k.levels(8, 1, 1, 1, 1, 1)),
    ),
    _c(
        "dim-19",
        DIM,
        "two walls 20 cm long and 15 cm high, facing each other 10 cm apart",
        k.pair(k.wall(4, 3), k.wall(4, 3), k.either(k.parallel_gap(2), k.parallel_gap(1))),
    ),
    _c("dim-20", DIM, "a tower 25 cm high. then add 10 cm to it", one(T(7))),
    _c("dim-21", DIM, "Lay a row 35 cm long, then cut it down to 20 cm", one(k.row(4))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 5, not at the front",
        one(T(5), _NOT_FRONT),
    ),
    _c(
        "neg-02",
        NEG,
        "a wall 6 long and 2 high that doesn't run left to right",
        one(k.wall(6, 2), k.runs("x")),
    ),
    _c(
        "neg-03",
        NEG,
        "4x4 square of cubes with the middle four left out",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4), k.parts(12)),
    ),
    _c(
        "neg-04",
        NEG,
        "a pyramid of 3 levels, no beams in it",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-05",
        NEG,
        "a staircase of 4 that doesn't climb to the left",
        one(k.staircase(4), k.not_(k.rises(_L), "climbs to the left")),
    ),
    _c(
        "neg-06",
        NEG,
        "tower of 4 anywhere but the right side",
        one(T(4), k.not_(reg("right"), "on the right")),
    ),
    _c(
        "neg-07",
        NEG,
        "two 5-high towers, not stacked, not touching",
        k.each(2, T(5)),
    ),
    _c(
        "neg-08",
        NEG,
        "a 3x3 slab and a tower of 4, but don't put the tower on the slab",
        k.any_of(
            k.structures(k.block(3, 3, 1), T(4)),
            one(k.with_column(4, k.block(3, 3, 1))),
        ),
    ),
    _c(
        "neg-09",
        NEG,
        "two rows of 4 cubes, not parallel to each other, and not touching",
        k.pair(k.all_of(k.row(4), k.runs("x")), k.all_of(k.row(4), k.runs("y")), _free),
    ),
    _c(
        "neg-10",
        NEG,
        "put a tower of 6 in front of a wall 4 long 2 high, without it touching the wall",
        k.pair(T(6), k.wall(4, 2), k.on_side(_F)),
    ),
    _c(
        "neg-11",
        NEG,
        "a bridge with pillars 3 high, no beam, and a tower of 2 to its left",
        _placed(T(2), k.all_of(_bar_on_posts(3, 3), k.only_cubes), _L, 2),
    ),
    _c(
        "neg-12",
        NEG,
        "build a tower of 4 at the back, then move it so it isn't at the back any more",
        one(T(4), k.not_(reg("back"), "at the back")),
    ),
    _c(
        "neg-13",
        NEG,
        "four towers of 2 in a row, a cube apart, none of them at the front",
        k.in_line(4, k.all_of(T(2), _NOT_FRONT), 1),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "buld a tower of 6 cubes", one(T(6))),
    _c("typo-02", TYP, "a stiarcase of 3 stpes", one(k.staircase(3))),
    _c("typo-03", TYP, "mak a wall 5 lnog, 2 high", one(k.wall(5, 2))),
    _c("typo-04", TYP, "pyrmaid 4 levels pls", one(k.pyramid(4))),
    _c("typo-05", TYP, "a 3x4 gird of cubes please", _grid(3, 4)),
    _c("typo-06", TYP, "a rign 5 by 5", one(_RING5)),
    _c("typo-07", TYP, "castel with towers at the corners", one(k.castle)),
    _c(
        "typo-08",
        TYP,
        "tower of 3 in frnot of a tower of 5",
        _placed(T(3), T(5), _F, 3),
    ),
    _c(
        "typo-09",
        TYP,
        "two towres of 4 with a beam acros the top",
        one(_beam_bridge(4)),
    ),
    _c(
        "typo-10",
        TYP,
        "a 2x2 blokc next to a 3 high towr",
        _next(T(3), k.solid(2, 2), k.with_column(3, k.solid(2, 2))),
    ),
    _c(
        "typo-11",
        TYP,
        "row of 5 and a pyarmid of 2 levles behind it",
        k.pair(k.pyramid(2), k.row(5), k.on_side(_B)),
    ),
    _c("typo-12", TYP, "make a towre of 3, then ad 2 more cubes", one(T(5))),
    _c(
        "typo-13",
        TYP,
        "lay a 3x3 slab thne put a tower of 2 in teh middle",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "Against the back edge, a row of 8",
        one(k.row(8), k.runs("y"), k.min_x(0.60)),
    ),
    _c("wo-02", WO, "5 high, a tower, in the front left", one(T(5), reg("front left"))),
    _c("wo-03", WO, "Two cubes high and six long: wall", one(k.wall(6, 2))),
    _c("wo-04", WO, "Of 4 levels, a pyramid is what I'd like", one(k.pyramid(4))),
    _c(
        "wo-05",
        WO,
        "Steps, five of them, going up to the back",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c("wo-06", WO, "3 by 3 and 2 high is the block I need", one(k.block(3, 3, 2))),
    _c(
        "wo-07",
        WO,
        "Behind the wall put a tower of 3; the wall is 4 long and 2 high",
        _placed(T(3), k.wall(4, 2), _B, 3),
    ),
    _c(
        "wo-08",
        WO,
        "On a 4 by 4 slab, centred, a 2x2 block two high",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.centred(), k.levels(16, 4, 4)),
    ),
    _c(
        "wo-09",
        WO,
        "To the right of a 5-tower, a 2-tower",
        _placed(T(2), T(5), _R, 2),
    ),
    _c(
        "wo-10",
        WO,
        "One cube apart, a row of 3 and a row of 3, parallel",
        k.pair(k.row(3), k.row(3), k.parallel_gap(1)),
    ),
    _c(
        "wo-11",
        WO,
        "Inside a 6x6 ring, in the centre, a 2x2 block",
        k.pair(_RING6, k.solid(2, 2), k.centred_in(0.03)),
    ),
    _c("wo-12", WO, "Take one cube off after you've stacked a tower of 5", one(T(4))),
    _c(
        "wo-13",
        WO,
        "From left to right: a 3-step staircase, a tower of 4, and a 2x2 block of 2, all with "
        "a cube of space between them",
        k.in_order("y", k.staircase(3), T(4), k.block(2, 2, 2), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "hey there, just wondering if the robot could make a tower of 5 for me, cheers",
        one(T(5)),
    ),
    _c(
        "fil-02",
        FIL,
        "ok I'm back from the meeting. wall, 4 long and 3 high please",
        one(k.wall(4, 3)),
    ),
    _c(
        "fil-03",
        FIL,
        "For my thesis photos I need a 4-level pyramid, if that's alright",
        one(k.pyramid(4)),
    ),
    _c(
        "fil-04",
        FIL,
        "um, so, like, a staircase? with 4 steps I guess",
        one(k.staircase(4)),
    ),
    _c(
        "fil-05",
        FIL,
        "Hi team, it's 2pm and the line is quiet, so let's have a 2 by 5 slab",
        one(k.block(2, 5, 1)),
    ),
    _c(
        "fil-06",
        FIL,
        "I've been told the robot's good at rings, so a 4 by 4 ring would be lovely, thanks so "
        "much",
        one(_RING4),
    ),
    _c(
        "fil-07",
        FIL,
        "Sorry to bother you again! Could we get two towers of 4, one cube apart?",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "fil-08",
        FIL,
        "ok the camera is rolling now, so: a bridge with 3-high legs and a beam, and a 2-cube "
        "tower in front of it",
        _placed(T(2), _beam_bridge(3), _F, 2),
    ),
    _c(
        "fil-09",
        FIL,
        "My boss wants a row of 6 with a tower of 3 behind it, don't ask me why",
        _placed(T(3), k.row(6), _B, 3),
    ),
    _c(
        "fil-10",
        FIL,
        "Hello! We're a group of 15 students. Could we see a castle and a tower of 5 next to it?",
        _next(T(5), k.castle, k.with_column(5, k.castle)),
    ),
    _c(
        "fil-11",
        FIL,
        "right, first things first, stack a tower of 4. then, if you don't mind, pop two more "
        "on it. ta",
        one(T(6)),
    ),
    _c(
        "fil-12",
        FIL,
        "Honestly no rush at all, but three pyramids of 2 levels in a line with 1 cube gaps "
        "would be great",
        k.in_line(3, k.pyramid(2), 1),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "a tower of 4 in the back right corner", one(T(4), reg("back right"))),
    _c(
        "reg-02",
        REG,
        "put a pyramid with 3 levels over on the left",
        one(k.pyramid(3), reg("left")),
    ),
    _c(
        "reg-03",
        REG,
        "a 3x2 slab right in the middle of the table",
        one(k.block(3, 2, 1), reg("centre")),
    ),
    _c(
        "reg-04",
        REG,
        "a wall 5 long 2 high at the front, close to the robot",
        one(k.wall(5, 2), reg("front")),
    ),
    _c("reg-05", REG, "staircase of 4 at the back", one(k.staircase(4), reg("back"))),
    _c("reg-06", REG, "a ring 5x5 in the front right", one(_RING5, reg("front right"))),
    _c(
        "reg-07",
        REG,
        "a 2x2 block 4 high on the right-hand side",
        one(k.block(2, 2, 4), reg("right")),
    ),
    _c(
        "reg-08",
        REG,
        "a row of 7 running front to back along the left edge",
        one(k.row(7), k.runs("x"), k.centre_y_min(0.45)),
    ),
    _c("reg-09", REG, "a castle as far back as it'll go", one(k.castle, _against_back)),
    _c(
        "reg-10",
        REG,
        "a tower of 3 at the front left and a row of 4 at the back right",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(k.row(4), reg("back right"))),
    ),
    _c(
        "reg-11",
        REG,
        "one 2x2 block in the left back corner and another in the right front corner, both 3 high",
        k.structures(
            k.all_of(k.block(2, 2, 3), reg("back left")),
            k.all_of(k.block(2, 2, 3), reg("front right")),
        ),
    ),
    _c(
        "reg-12",
        REG,
        "a wall along the front, 6 long and 2 high, and a pyramid of 2 levels at the back",
        k.structures(
            k.all_of(k.wall(6, 2), k.runs("y"), reg("front")),
            k.all_of(k.pyramid(2), reg("back")),
        ),
    ),
    _c(
        "reg-13",
        REG,
        "a bridge on the right side with 2-high pillars, and a tower of 5 in the middle of the "
        "table",
        k.structures(k.all_of(_span(2), reg("right")), k.all_of(T(5), reg("centre"))),
    ),
    _c(
        "reg-14",
        REG,
        "a tower of 2 in each of the four corners of the table",
        k.structures(*[k.all_of(T(2), reg(r)) for r in _CORNERS]),
    ),
    _c(
        "reg-15",
        REG,
        "three 3-high towers along the back: one on the left, one in the middle, one on the right",
        k.in_order(
            "y",
            k.all_of(T(3), reg("back left")),
            k.all_of(T(3), reg("back")),
            k.all_of(T(3), reg("back right")),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "build me something nice", k.anything),
    _c(
        "open-02",
        OPEN,
        "something low and wide, maybe for a base",
        k.all_of(k.anything, k.layout(k.all_of(k.low(_LOW), k.broad))),
    ),
    _c("open-03", OPEN, "a tower, you pick the height", one(T(lo=2, hi=10))),
    _c(
        "open-04",
        OPEN,
        "a structure with steps in it, any size",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-05",
        OPEN,
        "put something at the front right, doesn't matter what",
        k.all_of(k.anything, k.layout(reg("front right"))),
    ),
    _c(
        "open-06",
        OPEN,
        "something you could look through, an arch or a ring maybe",
        k.all_of(k.anything, k.some(k.any_of(_ARCH, k.ring))),
    ),
    _c(
        "open-07",
        OPEN,
        "two things of your choice, one stacked on top of the other",
        k.all_of(k.anything, one(k.on_top(_any, _any))),
    ),
    _c(
        "open-08",
        OPEN,
        "build a tall thing and a short thing next to each other",
        k.all_of(
            k.anything,
            k.any_of(k.pair(_any, _any, k.all_rels(_taller, k.within(0.25))), one(_two_heights)),
        ),
    ),
    _c(
        "open-09",
        OPEN,
        "three different things in a row, your pick, with some space between them",
        k.all_of(k.anything, _count(3), k.in_line(3, _any), _all_differ),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "a tower 4 high and also 2 high",
        k.honest(one(k.any_of(T(4), T(2)))),
    ),
    _c("bad-02", BAD, "build a wall 20 cubes long", k.honest(k.anything)),  # past the cell's 12
    _c(
        "bad-03",
        BAD,
        "stack 25 cubes in a single tower",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-04", BAD, "make a cylinder 10 cm across", k.honest(k.anything)),
    _c(
        "bad-05",
        BAD,
        "put a tower of 3 on the floor next to the table",  # off the table
        k.honest(one(T(3))),
    ),
    _c("bad-06", BAD, "how's the weather looking for the weekend", k.honest()),
    _c("bad-07", BAD, "lkjh poiuy zxcv", k.honest()),
    _c("bad-08", BAD, "put a pyramid of", k.honest(k.anything)),
    _c("bad-09", BAD, "a row of minus two cubes", k.honest(k.anything)),
    _c("bad-10", BAD, "a staircase with 0 steps", k.honest(k.anything)),
    _c("bad-11", BAD, "stack a tower of 4. no, forget it, nothing today", k.honest()),
    _c(
        "bad-12",
        BAD,
        "add another cube to the tower that's already there",  # nothing is on the table
        k.honest(k.anything),
    ),
    _c("bad-13", BAD, "build it again like last time", k.honest(k.anything)),
    _c("bad-14", BAD, "a slab 30 by 30 cubes", k.honest(k.anything)),  # past 12 by 10
    _c(
        "bad-15",
        BAD,
        "stack two and a half cubes into a tower",
        k.honest(one(k.any_of(T(2), T(3)))),
    ),
    _c(
        "bad-16",
        BAD,
        "a wall 3 long and 2 high, painted blue",  # the cell does not paint
        k.honest(one(k.wall(3, 2))),
    ),
    _c("bad-17", BAD, "can you email me the report from this morning", k.honest()),
    _c(
        "bad-18",
        BAD,
        "a tower 6 high that is shorter than 3 cubes",
        k.honest(one(k.any_of(T(6), T(lo=1, hi=2)))),
    ),
]
