"""A twenty-third held-out set for the language front end (dev23): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev22` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a maintenance technician filing a work order in a CMMS ticket: terse fields ("WO#", "REQ:",
  "LOC:", "QTY", "NOTE:", "PRI:"), pipes and slashes between fields, abbreviations ("twr"
  tower, "blk" cube or cubes, "H" high, "L" long, "ea" each, "approx", "ctr" centre, "clr"
  clear, "lyr" layer). "4L x 2H" is 4 long and 2 high; "1 blk clearance" is one cube clear;
  "approx 25cm" is still 5 cubes; an amendment or "UPDATE" line replaces what it amends. A
  ticket that is not a build at all (a bearing to replace) is bad input and must be refused;
* a school teacher demonstrating the cell to a class, narrating as they go ("now watch,
  we'll ask it for…", "let's see if it can…", "who remembers…"). Only what the teacher asks
  the robot for is checked, not the chatter to the pupils; a trick question to the class
  ("a tower of minus two") is bad input;
* a logistics planner writing bullet lists and numbered steps over several lines. Each line
  adds to the one build unless a later step says to move, undo or skip something; "left to
  right" is along y from +y to -y; "length (left to right)" and "depth" are y and x;
* an impatient operator typing verbless fragments ("tower 4. another, 2. its right.
  touching."). A bare number after a structure is its size (a tower's height, a row's
  length, a pyramid's levels); "tall" is five cubes or more for a tower and legs of three or
  more for a bridge; "far right" is a footprint centre at y ≤ 0.20; "no, 8" is a correction;
* a person describing what they want by analogy with everyday things. A goalpost, doorway,
  arch or gate is two posts with a beam or a bar of cubes across the tops; a park or garden
  bench is the same with legs one cube high (a seat "a row of four cubes" or "20 cm long" is
  a bar four cubes long); a table or a canopy is four separate legs under one connected top
  of beams or of cubes (a table "10 cm high" may be legs of one under a one-cube top, or legs
  of two); a chimney is a full column one or two cubes across, or a hollow ring, of the given
  height; a fence is a row (or, when made "out of posts", separate posts in a line); a pen is
  a ring; a podium for three is three places, the winner's in the middle and highest, as one
  stepped block (each place one or two cubes wide, steps along either axis) or as separate
  blocks in a line no more than two cubes apart — which side the second place takes is only
  checked when the command says; a doormat or step in front is a row; a stool is a column; a
  house is a solid block and its chimney a column standing on its top.

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the middle one",
"that gap"), distributive phrases ("a cube on every corner", "one per corner", "on each
side"), comparisons ("twice as tall", "one cube taller than the one before", "matches the
second"), corrections ("no, 8", "UPDATE … reduce to 3H", "actually, take the top off"),
removals and unusable input (gibberish, emoji, other languages, contradictions, circular
steps, sizes and coordinates past the cell, non-build tickets, references to nothing built).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a crossbar or seat as a beam
or a bar of cubes, a tower set against another structure or clear of it when "next to" or
"beside" does not say, a podium in one block or in separate places, a table's height as legs
or overall — and nothing else. Geometry comes only from `sdi.bench.boxes`, through the shared
checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30); the front is the
robot's side (small x). Regions are `sdi.bench.boxes.region_problem`'s; "along the back edge"
is every part at x ≥ 0.60, "the back half" every part at x ≥ 0.50, "along the left-hand
edge" a footprint centre at y ≥ 0.40.
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

_TALL_TOWER = 5  # cubes: "tall" for a tower
_TALL_LEGS = 3  # cubes: "tall" for a bridge's legs


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev23-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _apart(n: int) -> k.Rel:
    """A and B are at least `n` cubes apart, clear (− 1.5 cm)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        gap = bx.separation(a, b)
        return None if gap >= n * bx.CUBE - 0.015 else f"{gap:.3f} m apart, want ≥ {n} cube(s)"

    return rel


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


def _span(posts: int | None = None, mouth: int | None = None, lo: int | None = None) -> k.Check:
    """A goalpost, doorway, gate, arch, bridge or bench: two posts `posts` high (or at least
    `lo`; any height when both are None) with a beam (the shared `bridge`) or a bar of cubes
    across the tops; posts `mouth` cubes apart clear when given."""
    plo, phi = (posts, posts) if posts is not None else (lo, None)
    # the overall height too: the shared `bridge` can read the top cubes of taller posts,
    # with a cube bar across them, as part of the top piece
    beam = k.all_of(
        k.bridge(lo=plo, hi=phi, pillars=2),
        k.height(lo=None if plo is None else plo + 1, hi=None if phi is None else phi + 1),
    )
    if mouth is not None:
        beam = k.all_of(beam, k.leg_gap(mouth))
    return k.any_of(beam, _bar_on_posts(plo, phi, mouth))


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
    """A table or canopy on `legs` legs `leg_h` high: the shared `canopy` one layer above the
    legs (it can read the top cubes of taller legs, with a cube top, as part of the top), or a
    cube top."""
    return k.any_of(
        k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1)),
        _roof_on(legs, leg_h),
        k.beam_roof(legs, leg_h),  # added after the first measurement: the cell's beam roof
    )


def _chimney(h: int) -> k.Check:
    """A chimney `h` cubes high: a full column one or two cubes across, or a hollow ring."""
    return k.any_of(k.tower(h), k.tower(h, base=2), k.ring_of(high=h))


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


def _between_gap(mid: k.Check, end: k.Check, n: int) -> k.Pred:
    """Three structures: `mid` between two passing `end`, which are `n` cubes apart clear
    (± 1.5 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != 3:
            return f"{len(comps)} separate structures, want 3"
        first: k.Reason = None
        for i, j, m in itertools.permutations(range(3)):
            a, b, c = comps[i], comps[j], comps[m]
            r = mid(a) or end(b) or end(c)
            if r is None and not bx.between(a, b, c):
                r = "not between"
            if r is None:
                r = k.gap_of(n)(b, c)
            if r is None:
                return None
            first = first or r
        return first

    return f


def _place(h: int) -> k.Check:
    """A solid block `h` cubes high on the table, any footprint (one place of a podium)."""
    return k.all_of(k.full, k.height(h), k.on_table)


def _stepped(*hs: int, left_to_right: bool = False) -> k.Check:
    """One stepped block on the table whose slice heights along one axis are `hs` (each place
    one or two cubes wide, any depth, every column full) — left (+y) to right (-y) in that
    order when `left_to_right`, else along either axis in either direction."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.on_table(bs)
        if r:
            return r
        n = len(bx.voxels(bs))
        fx, fy = bx.footprint_cubes(bs)
        for axis in (1,) if left_to_right else (0, 1):
            got = bx.step_profile(bs, axis)
            depth = (fy, fx)[axis]
            for w in (1, 2):
                want = [h for h in hs for _ in range(w)]
                ok = got[::-1] == want if left_to_right else got in (want, want[::-1])
                if ok and n == sum(want) * depth:
                    return None
        return f"step heights {bx.step_profile(bs, 1)}, want {list(hs)}"

    return f


def _podium(*hs: int, left_to_right: bool = False) -> k.Pred:
    """A podium whose places are `hs` high: one stepped block, or separate blocks in a line no
    more than two cubes apart (left to right in that order when `left_to_right`)."""
    gap = 2 * bx.CUBE + 0.015
    places = [_place(h) for h in hs]
    if left_to_right:
        apart = k.in_order("y", *places, max_gap=gap)
    else:
        apart = k.any_of(
            *[
                k.in_order(axis, *ps, max_gap=gap)
                for axis in ("x", "y")
                for ps in (places, places[::-1])
            ]
        )
    return k.any_of(k.one(_stepped(*hs, left_to_right=left_to_right)), apart)


def _nn_gap(n: int) -> k.Pred:
    """Every separate structure's nearest neighbour is `n` cubes away, clear (± 1.5 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < 2:
            return "fewer than two structures"
        for i, g in enumerate(comps):
            gap = min(bx.separation(g, h) for j, h in enumerate(comps) if j != i)
            if abs(gap - n * bx.CUBE) > 0.015:
                return f"a structure {gap:.3f} m from its nearest neighbour, want {n} cube(s)"
        return None

    return f


def _corners(*sides: int) -> k.Pred:
    """The separate structures stand one on each corner of the whole layout, whose footprint is
    s × s cubes for one of `sides`."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        everything = [b for g in comps for b in g]
        dims = bx.plan_dims(everything)
        if not any(dims == (s, s) for s in sides):
            return f"layout footprint {dims}, want one of {[(s, s) for s in sides]}"
        (x0, y0, _), (x1, y1, _) = bx.bounds(everything)
        seen = set()
        for g in comps:
            (gx0, gy0, _), (gx1, gy1, _) = bx.bounds(g)
            ex = "lo" if abs(gx0 - x0) <= bx.TOL else "hi" if abs(gx1 - x1) <= bx.TOL else None
            ey = "lo" if abs(gy0 - y0) <= bx.TOL else "hi" if abs(gy1 - y1) <= bx.TOL else None
            if ex is None or ey is None:
                return "a structure not on a corner"
            seen.add((ex, ey))
        return None if len(seen) == len(comps) == 4 else "not one structure on each corner"

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
    """A pyramid whose top level is more than one part (its top cube left off)."""
    p = bx.pyramid_levels(bs)
    if p is None:
        return "not a pyramid"
    return None if p[-1] > 1 else "a single cube on top"


def _centre_y_max(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m): far over to the right."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


def _fits(a: int, b: int) -> k.Check:
    """A footprint no bigger than a × b cubes (either way round)."""

    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        want = (min(a, b), max(a, b))
        ok = got[0] <= want[0] and got[1] <= want[1]
        return None if ok else f"footprint {got}, want within {want}"

    return f


def _symmetric(bs: k.Boxes) -> k.Reason:
    """The occupied cells are a mirror image of themselves in some upright plane: left to
    right, front to back, or (on a square footprint) along a diagonal."""
    vox = bx.voxels(bs)
    if not vox:
        return "no parts"
    mi = max(i for i, _, _ in vox)
    mj = max(j for _, j, _ in vox)
    mirrors = [{(mi - i, j, z) for i, j, z in vox}, {(i, mj - j, z) for i, j, z in vox}]
    if mi == mj:
        mirrors += [{(j, i, z) for i, j, z in vox}, {(mj - j, mi - i, z) for i, j, z in vox}]
    return None if vox in mirrors else "not mirror-symmetric"


def _all_differ(result: Mapping[str, Any]) -> k.Reason:
    """No two separate structures alike (same footprint, height and number of parts)."""
    comps = k.separate_structures(result)
    if isinstance(comps, str):
        return comps
    sigs = [(bx.plan_dims(g), bx.thickness_cubes(g), len(g)) for g in comps]
    return None if len(set(sigs)) == len(sigs) else "two of the structures are the same"


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "WO-2291 | REQ: twr x1, 5 blk H + wall 4L x 2H | LOC: twr directly behind wall, 1 blk "
        "clearance",
        k.pair(T(5), k.wall(4, 2), k.gap_of(1, _B)),
    ),
    _c(
        "rel-02",
        REL,
        "Now watch, everyone: we'll ask it for a little two-level pyramid, and then a tower of "
        "four just to the left of it. Close, but not touching.",
        k.pair(T(4), k.pyramid(2), k.all_rels(k.on_side(_L), k.within(0.15))),
    ),
    _c(
        "rel-03",
        REL,
        "Bay 2 layout:\n- wall: 6 long, 2 high\n- tower: 3 high, in front of the middle of the "
        "wall\n- clearance between them: 2 cubes",
        k.pair(T(3), k.wall(6, 2), k.all_rels(k.gap_of(2, _F), _facing_mid())),
    ),
    _c(
        "rel-04",
        REL,
        "tower 4. another, 2. its right. touching.",
        one(_col_beside(2, T(4), _R)),
    ),
    _c(
        "rel-05",
        REL,
        "I'd like a doorway, sides four cubes tall with a lintel across, and a doormat in front "
        "of it: a flat strip of three cubes, one cube out from the door.",
        k.pair(k.row(3), _span(4), k.gap_of(1, _F)),
    ),
    _c(
        "rel-06",
        REL,
        "REQ: blk 2x2x2, LOC: ctr. Twr 3H on top of blk, centred.",
        one(k.on_top(T(3), k.block(2, 2, 2)), k.centred(), k.levels(4, 4, 1, 1, 1), reg("centre")),
    ),
    _c(
        "rel-07",
        REL,
        "Let's see if it can put a tower of three inside a pen: a square ring, five cubes on "
        "each side, one cube high.",
        k.any_of(k.around(T(3), _PEN5), one(k.holding(T(3), _PEN5))),
    ),
    _c(
        "rel-08",
        REL,
        "Display, in order:\n1) two towers of 5, with a 5-cube gap between them\n2) a 2-level "
        "pyramid in that gap",
        _between_gap(k.pyramid(2), T(5), 5),
    ),
    _c(
        "rel-09",
        REL,
        "bridge. legs 3. one cube on top. middle.",
        one(_topped(_span(3)), k.top_centred()),
    ),
    _c(
        "rel-10",
        REL,
        "Make me a park bench with short legs, one cube each, and a lamp post five cubes tall "
        "standing at the left end of the bench.",
        k.any_of(
            k.pair(T(5), _span(1), k.all_rels(k.on_side(_L), k.within(0.15))),
            one(_col_beside(5, _span(1), _L)),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "TICKET 4410 / REQ: bridge, legs 2H / + twr 3H ea side of bridge / spacing 1 blk clr",
        k.line(T(3), _span(2), T(3), gaps=(1,)),
    ),
    _c(
        "rel-12",
        REL,
        "Next we'll ask for a wall five cubes long and three high, and on the far side of it, "
        "behind it, away from the robot, a single cube touching the wall.",
        one(_col_beside(1, k.wall(5, 3), _B)),
    ),
    _c(
        "rel-13",
        REL,
        "Arrangement:\n• tower A: 6 high\n• tower B: 3 high, on A's right\n• tower C: 3 high, "
        "on A's left\n• one cube between neighbours",
        k.in_order("y", T(3), T(6), T(3), gaps=(1,)),
    ),
    _c(
        "rel-14",
        REL,
        "slab 3x3. cube on every corner.",
        one(k.plan_heights("212", "111", "212")),
    ),
    _c(
        "rel-15",
        REL,
        "Something like a kitchen table, four legs two cubes tall with a top on them, and a "
        "stool next to it: a single column two cubes high, a cube away from the table.",
        k.pair(T(2), _roofed(4, 2), k.gap_of(1)),
    ),
    _c(
        "rel-16",
        REL,
        "REQ: ring 4x4 (hollow), 2H. LOC: back. + twr 4H in front of ring, 1 blk gap.",
        k.pair(
            T(4),
            k.all_of(k.ring_of(2, (2, 2)), k.dims(4, 4), reg("back")),
            k.gap_of(1, _F),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Let's see if it can do two towers, one twice as tall as the other, the short one "
        "three cubes, side by side with one cube of space.",
        k.pair(T(3), T(6), k.gap_of(1)),
    ),
    _c(
        "rel-18",
        REL,
        "Please build:\n- a staircase of 4 steps climbing towards the back\n- a tower of 4 at "
        "the top of the stairs, touching the top step",
        one(_col_beside(4, k.all_of(k.staircase(4), k.rises(_B)), _B)),
    ),
    _c(
        "rel-19",
        REL,
        "Picture a little house: a solid 3 by 3 block two cubes high, with a chimney two cubes "
        "tall standing on top of it at one corner.",
        one(k.plan_heights("422", "222", "222")),
    ),
    _c(
        "rel-20",
        REL,
        "wall 5 long 2 high. tower 3 each end. touching.",
        k.any_of(
            one(k.flat, k.profile(3, 2, 2, 2, 2, 2, 3)),
            one(k.plan_heights("3...3", "22222")),
            one(k.plan_heights("3....", "22222", "....3")),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "First we'll ask it for a tower of six. Now watch, let's see if it can take two cubes "
        "off the top again.",
        one(T(4)),
    ),
    _c(
        "seq-02",
        SEQ,
        "REQ: twr 5H. UPDATE 14:20: reduce to 3H per supervisor.",
        one(T(3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Sequence:\n1. Lay a 4 x 4 slab, one layer.\n2. Put a 2 x 2 block, one layer, on the "
        "centre of it.\n3. Put a single cube on top of that.",
        one(k.pyramid_counts(16, 4, 1), k.centred(), k.top_centred()),
    ),
    _c("seq-04", SEQ, "row of 6. no, 8.", one(k.row(8))),
    _c(
        "seq-05",
        SEQ,
        "Build a goalpost with posts 3 high. Then knock the crossbar off, I just want the two "
        "posts left standing.",
        k.pair(T(3), T(3), k.within(0.25)),
    ),
    _c(
        "seq-06",
        SEQ,
        "WO 8812 / step 1: wall 4L 3H / step 2: remove top row / step 3: QA",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Okay class, first a pyramid with three levels. Then we'll ask it to put a tower of two "
        "next to it, one cube away, on the right.",
        k.pair(T(2), k.pyramid(3), k.gap_of(1, _R)),
    ),
    _c(
        "seq-08",
        SEQ,
        "1. Tower of 3.\n2. Another tower of 3, one cube to its left.\n3. A beam across the two "
        "tops.",
        one(_span(3, 1)),
    ),
    _c(
        "seq-09",
        SEQ,
        "tower 5. take 1 off. add a 2 next to it. touching.",
        one(k.cell_heights(4, 2)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Start with something like a chimney, five cubes tall. Then put a little wall on either "
        "side of it, two cubes long and two high, touching it, like the gable end of a house.",
        one(k.cell_heights(2, 2, 5, 2, 2)),
    ),
    _c(
        "seq-11",
        SEQ,
        "REQ: 3x twr, 2H ea, in a row, 1 blk apart. THEN: +1 blk on middle twr only.",
        k.line(T(2), T(3), T(2), gaps=(1,)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Let's build a staircase of five steps... and now, to show you it can undo things, "
        "we'll ask it to take away the top step.",
        one(k.any_of(k.staircase(4), k.profile(1, 2, 3, 4, 4))),
    ),
    _c(
        "seq-13",
        SEQ,
        "To do:\n- row of 5 along the front\n- second row of 5 directly behind it, touching\n- "
        "third row on top? no, skip the third row",
        one(k.block(2, 5, 1), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-14",
        SEQ,
        "pyramid 3. remove top. put tower 2 there.",
        one(k.on_top(T(2), k.pyramid(2))),
    ),
    _c(
        "seq-15",
        SEQ,
        "Make a table, four legs of three and a top. Actually, take the top off again, I just "
        "need the four legs standing.",
        k.each(4, T(3)),
    ),
    _c(
        "seq-16",
        SEQ,
        "REQ: slab 3x3x1. REQ (amend): make it 2 lyr.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "seq-17",
        SEQ,
        "First we'll get a wall, four long and two high. Then a second wall just like it, "
        "parallel, two cubes behind the first.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.all_rels(k.parallel_gap(2), k.on_side(_B))),
    ),
    _c(
        "seq-18",
        SEQ,
        "Order of work:\n1) Bridge, legs 2.\n2) Tower of 4 two cubes to the left of the "
        "bridge.\n3) Move the tower to the right side instead, same distance.",
        k.pair(T(4), _span(2), k.gap_of(2, _R)),
    ),
    _c(
        "seq-19",
        SEQ,
        "3 towers. 2, 2, 2. then middle one up to 5.",
        k.line(T(2), T(5), T(2)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Start with a podium for three: middle place three high, the sides two and one. Then "
        "raise the lowest place so it matches the second.",
        _podium(2, 3, 2),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "REQ: twr x3, 4 blk ea. spacing 2 blk. LOC: along back edge.",
        k.all_of(k.in_order("y", T(4), T(4), T(4), gaps=(2,)), k.layout(k.min_x(0.60))),
    ),
    _c(
        "num-02",
        NUM,
        "Now, class, how many is a dozen? Twelve! Let's ask it for twelve cubes laid flat in a "
        "3 by 4 rectangle.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-03",
        NUM,
        "Quantities for the demo:\n- towers: 2 (height 3)\n- towers: 1 (height 6)\n- nothing else",
        k.structures(T(3), T(3), T(6)),
    ),
    _c("num-04", NUM, "pyramid. 4 levels. base 16.", one(k.pyramid_counts(16, 9, 4, 1))),
    _c(
        "num-05",
        NUM,
        "Build a podium with three places: the winner's place four cubes high, the runner-up "
        "three, and third place two.",
        _podium(3, 4, 2),
    ),
    _c(
        "num-06",
        NUM,
        "REQ: 2x walls 3L x 2H + 1x twr 5H. LOC: any. NOTE: all separate.",
        k.structures(k.wall(3, 2), k.wall(3, 2), T(5)),
    ),
    _c(
        "num-07",
        NUM,
        "Let's see if it can count backwards: a tower of five, then four, then three, then two, "
        "all in a row with a cube between.",
        k.line(T(5), T(4), T(3), T(2), gaps=(1,)),
    ),
    _c(
        "num-08",
        NUM,
        "Need:\n• 8 single cubes\n• in two rows of four\n• one cube of space between every cube",
        k.all_of(k.each(8, T(1)), k.layout(k.dims(3, 7)), _nn_gap(1)),
    ),
    _c("num-09", NUM, "towers. 3 of them. 1, 3, 5.", k.structures(T(1), T(3), T(5))),
    _c(
        "num-10",
        NUM,
        "A bench for two people: the seat a row of four cubes, on legs one cube tall.",
        one(_bar_on_posts(1, 1), k.long(4), k.only_cubes),
    ),
    _c(
        "num-11",
        NUM,
        "REQ: twr x1. H: double the std 3-blk twr.",
        one(T(6)),
    ),
    _c(
        "num-12",
        NUM,
        "Here's a tricky one: a row of cubes as long as the number of legs on a spider. Eight, "
        "that's right. Let's see.",
        one(k.row(8)),
    ),
    _c(
        "num-13",
        NUM,
        "Blocks needed:\n1. 2 x 2 x 1\n2. 2 x 2 x 2\n3. 2 x 2 x 3\nLine them up left to right "
        "in that order, one cube apart.",
        k.in_order("y", k.block(2, 2, 1), k.block(2, 2, 2), k.block(2, 2, 3), gaps=(1,)),
    ),
    _c(
        "num-14",
        NUM,
        "two. walls. 5 long. 3 high. parallel. gap 2.",
        k.pair(k.wall(5, 3), k.wall(5, 3), k.parallel_gap(2)),
    ),
    _c(
        "num-15",
        NUM,
        "Make a fence out of posts: five separate posts, each two cubes tall, in a line with a "
        "cube gap between them.",
        k.in_line(5, T(2), 1),
    ),
    _c(
        "num-16",
        NUM,
        "REQ: twr x4 @ 2H, one per corner of a 3x3 slab (slab 1 lyr). All one piece.",
        one(k.plan_heights("313", "111", "313")),
    ),
    _c(
        "num-17",
        NUM,
        "Watch this: we'll ask for three towers where each one is a cube taller than the one "
        "before, starting at three.",
        k.structures(T(3), T(4), T(5)),
    ),
    _c(
        "num-18",
        NUM,
        "Staircase spec:\n- steps: 6\n- width: 2 cubes\n- direction: up towards the left",
        one(k.staircase(6), k.dims(2, 6), k.rises(_L)),
    ),
    _c("num-19", NUM, "cubes. 10. one tower. no, 2 towers of 5.", k.each(2, T(5))),
    _c(
        "num-20",
        NUM,
        "Think of a hopscotch board laid out on the table: nine single cubes in a 3 by 3 "
        "square, each a cube apart.",
        k.all_of(k.each(9, T(1)), k.layout(k.dims(5, 5)), _nn_gap(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "REQ: wall, approx 25cm L x 10cm H. LOC: front.",
        one(k.wall(5, 2), reg("front")),
    ),
    _c(
        "dim-02",
        DIM,
        "Let's see if it knows its centimetres: a tower thirty centimetres tall, please.",
        one(T(6)),
    ),
    _c(
        "dim-03",
        DIM,
        "Slab requirements:\n- length: 30 cm (left to right)\n- depth: 15 cm\n- thickness: one "
        "cube",
        one(k.block_xy(3, 6, 1)),
    ),
    _c("dim-04", DIM, "tower. 20cm.", one(T(4))),
    _c(
        "dim-05",
        DIM,
        "Something about the size of a shoebox: 30 cm long, 15 cm wide and 10 cm tall, solid.",
        one(k.block(3, 6, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "REQ: ring/enclosure, ext 5 x 5 blk, 1 blk wall, H 100mm.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-07",
        DIM,
        "Now a doorway a doll could walk through: the sides 25 centimetres tall and 10 "
        "centimetres apart.",
        one(_span(5, 2)),
    ),
    _c(
        "dim-08",
        DIM,
        "Bridge spec:\n- pillar height: 150 mm\n- clear span between pillars: 1 cube\n- deck: "
        "one beam",
        one(k.bridge(3, pillars=2), k.leg_gap(1)),
    ),
    _c("dim-09", DIM, "staircase. 4 steps. 10cm wide.", one(k.staircase(4), k.dims(2, 4))),
    _c(
        "dim-10",
        DIM,
        "A garden bench: seat 20 cm long, legs 5 cm tall.",
        one(_span(1), k.long(4)),
    ),
    _c("dim-11", DIM, "REQ: blk 0.1 x 0.1 x 0.15 m (LxWxH).", one(k.block(2, 2, 3))),
    _c(
        "dim-12",
        DIM,
        "Let's ask it for a square slab, twenty centimetres on each side and one cube thick.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "dim-13",
        DIM,
        "Wall:\n  length 350 mm\n  height 100 mm\n  along the left side, running front to back",
        one(k.wall(7, 2), k.runs("x"), reg("left")),
    ),
    _c("dim-14", DIM, "pyramid, base 25cm.", one(k.pyramid(), k.base(5, 5))),
    _c(
        "dim-15",
        DIM,
        "A coffee table, 15 cm square on top and 10 cm high, standing on four legs.",
        one(
            k.dims(3, 3),
            k.any_of(k.all_of(_roofed(4, 1), k.height(2)), _roofed(4, 2)),
        ),
    ),
    _c("dim-16", DIM, "REQ: row, 0.4m, cubes only", one(k.row(8), k.only_cubes)),
    _c(
        "dim-17",
        DIM,
        "Who can tell me how tall half a metre is? We'll ask for a tower exactly that tall, "
        "fifty centimetres.",
        one(T(10)),
    ),
    _c(
        "dim-18",
        DIM,
        "Canopy:\n- four legs, 15 cm each\n- roof 20 x 20 cm",
        one(_roofed(4, 3), k.dims(4, 4)),
    ),
    _c(
        "dim-19",
        DIM,
        "L shape. arms 20cm. 1 high.",
        one(k.shape_letter("L"), k.dims(4, 4), k.height(1)),
    ),
    _c(
        "dim-20",
        DIM,
        "A chimney 40 cm tall and as thick as two cubes each way.",
        one(T(8, base=2)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "REQ: bridge, legs 3H. NOTE: do NOT use beam for deck, cubes only.",
        one(_bar_on_posts(3, 3), k.only_cubes),
    ),
    _c(
        "neg-02",
        NEG,
        "Let's see if it listens: a tower of four, but not in the middle. Anywhere else is fine.",
        one(T(4), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-03",
        NEG,
        "Setup:\n- a 3 x 3 frame, one layer\n- no cube in the middle",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-04",
        NEG,
        "tower 6. not on the left.",
        one(T(6), k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-05",
        NEG,
        "A table, but without the top: just four legs two cubes tall, in a square with two "
        "cubes between them.",
        k.all_of(k.each(4, T(2)), _corners(4)),
    ),
    _c(
        "neg-06",
        NEG,
        "REQ: pyramid. LIMIT: max 2 lvls (low ceiling in inspection booth).",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-07",
        NEG,
        "This time, class, we tell it what NOT to do: a staircase of three steps that does not "
        "climb towards the robot.",
        one(k.staircase(3), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-08",
        NEG,
        "Build list:\n- two towers of 3\n- keep them apart: at least 3 cubes between\n- no "
        "bridge joining them",
        k.pair(T(3), T(3), _apart(3)),
    ),
    _c("neg-09", NEG, "row 7. no gaps. no beams.", one(k.row(7), k.only_cubes)),
    _c(
        "neg-10",
        NEG,
        "A doorway with no lintel, just the two door posts, four high and two cubes apart.",
        k.pair(T(4), T(4), k.gap_of(2)),
    ),
    _c(
        "neg-11",
        NEG,
        "REQ: 3x twr 3H in a row, 1 blk spacing. EXCEPT middle twr: omit.",
        k.pair(T(3), T(3), k.gaps(1, 3)),
    ),
    _c(
        "neg-12",
        NEG,
        "Now a wall six long and two high, and let's make sure it doesn't run along the front; "
        "have it go from front to back instead.",
        one(k.wall(6, 2), k.runs("x")),
    ),
    _c(
        "neg-13",
        NEG,
        "Ring:\n- 4 x 4 outside\n- 1 high\n- NOT closed: leave one cube out of the front side",
        one(k.parts(11), k.dims(4, 4), k.height(1), k.not_(k.ring, "closed"), _missing_on(_F)),
    ),
    _c(
        "neg-14",
        NEG,
        "pyramid 3. no top cube.",
        one(_flat_topped_pyramid, k.pyramid(2)),
    ),
    _c(
        "neg-15",
        NEG,
        "A bench with nothing on it: a seat on two legs one cube high, and don't put anything "
        "else on the table.",
        one(_span(1)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr. 4. bakc.", one(T(4), reg("back"))),
    _c("typo-02", TYP, "REQ: brdge, lgs 2H. LOC: centr", one(_span(2), reg("centre"))),
    _c(
        "typo-03",
        TYP,
        "Now watch, we'll ask it for a pyrmid with thre levels.",
        one(k.pyramid(3)),
    ),
    _c("typo-04", TYP, "Todo:\n- wal 5 lnog\n- 2 hihg", one(k.wall(5, 2))),
    _c("typo-05", TYP, "Make somthing like a goal post, postes 4 high.", one(_span(4))),
    _c(
        "typo-06",
        TYP,
        "stiars 5 up lft",
        k.any_of(one(k.staircase(5), k.rises(_L)), one(k.staircase(5), reg("left"))),
    ),
    _c("typo-07", TYP, "REQ: slb 3x4 1 lyr", one(k.block(3, 4, 1))),
    _c(
        "typo-08",
        TYP,
        "Let's see if it can build a tower of fuor, and anotehr of two right beside it.",
        k.any_of(k.pair(T(4), T(2), k.within(0.15)), one(k.cell_heights(4, 2))),
    ),
    _c(
        "typo-09",
        TYP,
        "Items:\n1. towre 3\n2. towre 3\n3. gpa of 2 between",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c("typo-10", TYP, "a tabel with four lges, 2 tall", one(_roofed(4, 2))),
    _c("typo-11", TYP, "rign 5x5 1 hgih", one(_PEN5)),
    _c("typo-12", TYP, "REQ: twr 7 blk, LOC: frnt rght", one(T(7), reg("front right"))),
    _c(
        "typo-13",
        TYP,
        "Now we'll ask it for an arch, sorry, an arhc, with legs three cubs tall.",
        one(_span(3)),
    ),
    _c("typo-14", TYP, "a chimeny, 6 high, at the bcak left", one(_chimney(6), reg("back left"))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "left. tower. 5.", one(T(5), reg("left"))),
    _c(
        "wo-02",
        WO,
        "LOC: back right. QTY: 1. REQ: blk 2x2x2.",
        one(k.block(2, 2, 2), reg("back right")),
    ),
    _c(
        "wo-03",
        WO,
        "Three steps high, climbing towards the back: that's the staircase we'll ask it for now.",
        one(k.staircase(3), k.rises(_B)),
    ),
    _c(
        "wo-04",
        WO,
        "- 2 cubes apart\n- both 4 high\n- two towers\n- side by side, left to right",
        k.in_order("y", T(4), T(4), gaps=(2,)),
    ),
    _c(
        "wo-05",
        WO,
        "Four legs three high and a flat top on them, like a table: that's what I'm after.",
        one(_roofed(4, 3)),
    ),
    _c("wo-06", WO, "middle, bridge, tall", one(_span(lo=_TALL_LEGS), reg("centre"))),
    _c("wo-07", WO, "H 3 blk / L 6 blk / REQ: wall", one(k.wall(6, 3))),
    _c(
        "wo-08",
        WO,
        "On top of a 3 by 3 slab, right in its middle, is where we'll ask it to put a tower of "
        "three.",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
    ),
    _c(
        "wo-09",
        WO,
        "Final positions:\n- front: row of 4\n- back: tower of 6",
        k.structures(k.all_of(k.row(4), reg("front")), k.all_of(T(6), reg("back"))),
    ),
    _c(
        "wo-10",
        WO,
        "2 high. 3 wide. 1 deep. block. right side.",
        one(k.block_xy(1, 3, 2), reg("right")),
    ),
    _c(
        "wo-11",
        WO,
        "A fence, that's what the right side needs, six cubes long and one high.",
        one(k.row(6), reg("right")),
    ),
    _c(
        "wo-12",
        WO,
        "REQ (2 items): twr 4H; in front of it, 1 blk gap, twr 2H.",
        k.pair(T(2), T(4), k.gap_of(1, _F)),
    ),
    _c(
        "wo-13",
        WO,
        "Inside a ring, four by four and one high: a single cube. That's what we'll ask for next.",
        k.any_of(k.around(T(1), _PEN4), one(k.holding(T(1), _PEN4))),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Okay everyone, eyes up here please. Jamie, sit down. Right, now watch: we'll ask it "
        "for a tower of five cubes. Ready? Here goes.",
        one(T(5)),
    ),
    _c(
        "fil-02",
        FIL,
        "WO#6613 | PRI: low | ASSET: demo cell 2 | REQ: wall 4L x 3H | NOTES: per J. Okafor, "
        "for Tuesday tour | SIGN-OFF: pending",
        one(k.wall(4, 3)),
    ),
    _c(
        "fil-03",
        FIL,
        "Morning all,\n\nPer yesterday's stand-up, the plan for the cell is below.\n\n- one "
        "pyramid, three levels\n\nThat's it for now. Shout if anything's unclear.",
        one(k.pyramid(3)),
    ),
    _c("fil-04", FIL, "ugh. ok. bridge. legs 2. go.", one(_span(2))),
    _c(
        "fil-05",
        FIL,
        "You know those little footbridges in Japanese gardens? Not the curve, just the idea: "
        "two posts three cubes tall and something across the top.",
        one(_span(3)),
    ),
    _c(
        "fil-06",
        FIL,
        "Who remembers what we did on Monday with the wooden blocks? That's right, stairs. So "
        "let's see if the robot can do the same: four steps, please.",
        one(k.staircase(4)),
    ),
    _c(
        "fil-07",
        FIL,
        "REF: PM-SCHED-Q3 / CAT: demo build / REQ: blk 3x3x2 / EST: 15 min / TECH: R. Silva",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-08",
        FIL,
        "Hi team, quick note before the freight meeting.\n1. Tower of 4 on the left.\n2. That's "
        "all, the rest waits until Thursday.",
        one(T(4), reg("left")),
    ),
    _c("fil-09", FIL, "no time. row 5. thx.", one(k.row(5))),
    _c(
        "fil-10",
        FIL,
        "My grandmother had a mantel clock shaped like a little temple, funny what you "
        "remember. Anyway: a ring of cubes, four by four, two high, please.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "fil-11",
        FIL,
        "Shh, listen, the robot is thinking! Okay, now let's see if it can put a single cube "
        "on the right side of the table, all by itself.",
        one(T(1), reg("right")),
    ),
    _c(
        "fil-12",
        FIL,
        "REQ: twr 3H. NOTES: prev WO closed as dup, see #6610; parts bin restocked; no further "
        "action on gripper. LOC: front.",
        one(T(3), reg("front")),
    ),
    _c(
        "fil-13",
        FIL,
        "Agenda item 3 (cell):\n• L-shape, arms of 4, one layer\n• owner: me\n• due: today\n"
        "Agenda item 4: canteen rota (not for the robot)",
        one(k.shape_letter("L"), k.dims(4, 4), k.height(1)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "REQ: twr 4H. LOC: back left corner.", one(T(4), reg("back left"))),
    _c(
        "reg-02",
        REG,
        "Now watch, we'll ask it to put a two-level pyramid right at the front, near the robot.",
        one(k.pyramid(2), reg("front")),
    ),
    _c(
        "reg-03",
        REG,
        "Placement:\n- wall, 5 long, 2 high\n- along the back edge\n- running left to right",
        one(k.wall(5, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c("reg-04", REG, "tower 3. far right.", one(T(3), reg("right"), _centre_y_max(0.20))),
    _c(
        "reg-05",
        REG,
        "Put a bench along the left-hand edge of the table, legs one cube tall.",
        one(_span(1), k.centre_y_min(0.40)),
    ),
    _c(
        "reg-06",
        REG,
        "REQ: slab 2x2x1 LOC: X 0.6 / Y 0.2",
        one(k.block(2, 2, 1), k.near(0.60, 0.20, 0.02)),
    ),
    _c(
        "reg-07",
        REG,
        "Let's see if it knows where the middle is: a tower of four right in the centre of the "
        "table.",
        one(T(4), reg("centre")),
    ),
    _c(
        "reg-08",
        REG,
        "Zones:\n- front right: tower of 2\n- back left: tower of 5",
        k.structures(k.all_of(T(2), reg("front right")), k.all_of(T(5), reg("back left"))),
    ),
    _c("reg-09", REG, "staircase 3. back. right side.", one(k.staircase(3), reg("back right"))),
    _c(
        "reg-10",
        REG,
        "A chimney, five cubes tall, over in the far back corner on the right.",
        one(_chimney(5), reg("back right")),
    ),
    _c(
        "reg-11",
        REG,
        "REQ: ring 4x4 1H. LOC: front left. NOTE: keep clear of robot base (min 25 cm out).",
        one(_PEN4, reg("front left"), k.min_x(0.25)),
    ),
    _c(
        "reg-12",
        REG,
        "And now two towers of three: one on the far left of the table and one on the far right.",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "reg-13",
        REG,
        "Location brief:\n- 2 x 3 block, 1 layer\n- centre it at x = 0.5 m, y = 0.3 m",
        one(k.block(2, 3, 1), k.near(0.50, 0.30, 0.02)),
    ),
    _c("reg-14", REG, "bridge. left. legs 2.", one(_span(2), reg("left"))),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Let's see what it does on its own: build anything you like, robot, as long as it's "
        "cubes only.",
        k.all_of(k.anything, k.layout(k.only_cubes)),
    ),
    _c(
        "open-02",
        OPEN,
        "REQ: demo structure, any type. CONSTRAINT: max height 150mm.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-03",
        OPEN,
        "For the open day:\n- something eye-catching\n- your choice of shape\n- must fit in the "
        "back half of the table",
        k.all_of(k.anything, k.layout(k.min_x(0.50))),
    ),
    _c("open-04", OPEN, "something. small. whatever.", k.small),
    _c(
        "open-05",
        OPEN,
        "Make something that looks like a bit of playground equipment, a slide or a climbing "
        "frame, whatever comes to mind.",
        k.all_of(k.anything, k.layout(k.height(lo=2))),
    ),
    _c(
        "open-06",
        OPEN,
        "Here's a fun one for the class: build three different things, robot, you choose what.",
        k.all_of(k.anything, _count(3), _all_differ),
    ),
    _c(
        "open-07",
        OPEN,
        "REQ: any structure using exactly 8 blk. cubes only.",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(8), k.only_cubes))),
    ),
    _c(
        "open-08",
        OPEN,
        "Options (pick one):\na) a bridge\nb) an arch\nc) a gate\nWhichever is easiest.",
        k.all_of(k.anything, one(_ARCH)),
    ),
    _c(
        "open-09",
        OPEN,
        "something tall. anything.",
        k.all_of(k.anything, k.layout(k.height(lo=_TALL_TOWER))),
    ),
    _c(
        "open-10",
        OPEN,
        "Something you could sit on, sized for a doll.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-11",
        OPEN,
        "Let's see if it can make something with a hole you could look through. You decide "
        "what exactly.",
        k.all_of(k.anything, k.layout(k.any_of(_ARCH, k.ring))),
    ),
    _c(
        "open-12",
        OPEN,
        "REQ: something symmetrical for signage photo. LOC: any. SIZE: within 3x3 blk footprint.",
        k.all_of(k.anything, k.layout(k.all_of(_fits(3, 3), _symmetric))),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "WO#5512 REQ: replace worn bearing on conveyor 3 drive motor. LOC: line 2.",
        k.honest(),
    ),
    _c(
        "bad-02",
        BAD,
        "¿Puedes construir una torre de cinco cubos, por favor?",
        k.honest(one(T(5))),
    ),
    _c("bad-03", BAD, "asdf. tower? qwe", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-04",
        BAD,
        "Plan:\n1. Tower of 12.\n2. Done.",  # 12 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-05",
        BAD,
        "Build me a real staircase I can walk up to the mezzanine.",
        k.honest(k.anything),
    ),
    _c(
        "bad-06",
        BAD,
        "REQ: wall 20L x 2H blk. LOC: front.",  # 1 m long: longer than the workspace either way
        k.honest(k.anything),
    ),
    _c(
        "bad-07",
        BAD,
        "Let's try to trick it: a tower that's three cubes tall and also seven cubes tall.",
        k.honest(one(k.any_of(T(3), T(7)))),
    ),
    _c("bad-08", BAD, "🤖🧱❓", k.honest()),
    _c(
        "bad-09",
        BAD,
        "Step 1: build a tower of 4.\nStep 2: put it on top of the tower from step 3.\nStep 3: "
        "build a tower of 2 on top of the tower from step 1.",
        k.honest(k.anything),
    ),
    _c(
        "bad-10",
        BAD,
        "Make it look exactly like the Eiffel Tower, every girder.",
        k.honest(k.anything),
    ),
    _c(
        "bad-11",
        BAD,
        "REQ: ring 3x3 ext, hollow interior 4x4.",  # the inside bigger than the outside
        k.honest(k.anything),
    ),
    _c(
        "bad-12",
        BAD,
        "Now for something silly, class: let's ask for a tower with minus two cubes.",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-13", BAD, "bridge. legs 0.", k.honest(k.anything)),
    _c(
        "bad-14",
        BAD,
        "- pyramid, 3 levels\n- one single structure\n- but every cube separate, none touching "
        "any other",
        k.honest(k.anything),
    ),
    _c(
        "bad-15",
        BAD,
        "Build a chair like the one I'm sitting on, with armrests that fold.",
        k.honest(k.anything),
    ),
    _c(
        "bad-16",
        BAD,
        "REQ: twr 4H. LOC: X 1.2 / Y 0.3.",  # x 1.2 m: far beyond the back of the workspace
        k.honest(one(T(4))),
    ),
    _c(
        "bad-17",
        BAD,
        "Bauen Sie bitte eine Brücke mit Pfeilern aus drei Würfeln.",
        k.honest(one(_span(3))),
    ),
    _c("bad-18", BAD, "same again as the last ticket", k.honest(k.anything)),
    _c(
        "bad-19",
        BAD,
        "Tasks:\n1. Pyramid, base 12 x 12.\n2. Tower on top.",  # 12 wide: past y's 10 cubes
        k.honest(k.anything),
    ),
    _c("bad-20", BAD, "A pool table, full size.", k.honest(k.anything)),
]
