"""A twenty-fourth held-out set for the language front end (dev24): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev22` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a quality inspector who states tolerances and checks: "must be exactly 4 high, no more",
  "verify the gap is one cube", "reject anything else", "tolerance zero". A stated figure is
  exact; the checks the inspector names (a gap, a count, cubes only, a position) are what the
  predicate checks, and a "first-article" or "batch record" preamble is filler. "Dead centre"
  and "centre line" are the centre region and y = 0.30 (± 3 cm);
* a non-technical visitor trying the cell for the first time, polite and unsure, who says
  "blocks" for cubes, "a little staircase thing", "a little table", "a doorway", "can the
  robot make". A "little" structure has the size the visitor gives, and any size when none is
  given; "next to it" is clear of it and no more than five cubes away, or set against it as
  one structure; a doorway or "something you can look through" is anything spanning a gap;
* a game / level designer who thinks in tiles, levels and a map: a tile is one cube cell, "N
  levels" or "N-level" is N cubes high, a "tile floor" or "platform" is a one-level slab, a
  "crate" is a single cube, a "pillar" is a tower, a "room" is a hollow enclosure (its stated
  size read as the outside or as the floor inside), "1 tile gap" is one cube clear. North,
  south, east and west are defined in the command itself. Tile coordinates counted from the
  robot are met to 3 cm (tile corner, tile centre, from 0 or from 1). "Raise to level 3"
  accepts three high and, counting the ground as level 0, four high;
* an operator dictating through speech recognition: "um", "uh", "like", "so basically",
  restarts ("uh no", "scratch that", "not three by three, two by four") where the last word
  wins, numbers as words and mis-transcribed homophones read as the operator meant them ("for"
  is four, "to"/"too" two, "tree" three, "queues" cubes, "stare case" staircase). A number the
  recogniser lost ("[inaudible]") is bad input;
* a French- or Italian-speaking operator with small slips of English: "a tower of 4 floors"
  (4 high), "at the right of" / "at the left" (on that side), "in front to" / "behind to"
  (in front of, behind), "distant of 2 cubes" (2 cubes clear), "the half" (half of it), "the
  double", "marches" (steps), "long 30 cm and high 15 cm", "large" (wide), "a tour" (a
  tower), "without nothing" (with nothing), "one next to the other" (side by side). "The half
  of the wall" accepts either half (the top course off, or one end off). Three commands are
  wholly in French or Italian (bad input: a refusal or a noted reading).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the middle one",
"the first one"), distributive phrases ("a tower on each corner", "a cube on each side"),
comparisons ("double the first", "one course higher", "the half"), corrections ("uh no
wait"), removals and unusable input (gibberish, other languages, contradictions, sizes past
the cell, requests the cell cannot serve, references to nothing built).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a bridge's top a beam or a
bar of cubes, a roof of beams or of cubes, a tower "next to" another structure set against it
or clear of it, stairs "up to" a tower touching it or not — and nothing else. Geometry comes
only from `sdi.bench.boxes`, through the shared checks in `language_checks` and the local
checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30); the front is the
robot's side (small x).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

_TILE = 0.03  # m: a tile coordinate, met whichever way the tiles are counted


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev24-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _apart(n: int) -> k.Rel:
    """A and B are at least `n` cubes apart, clear (− 1.5 cm)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        gap = bx.separation(a, b)
        return None if gap >= n * bx.CUBE - 0.015 else f"{gap:.3f} m apart, want ≥ {n} cube(s)"

    return rel


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


def _bar_on_posts(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """Two separate posts, full columns `posts` cubes high (any height when None), `mouth`
    cubes apart clear (± 1.5 cm) when given, and as the topmost level one connected bar
    resting on both — a beam or a row of cubes (with a row of cubes the shared `bridge` does
    not see the span, since the bar's middle cubes rest on nothing)."""

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
            r = k.tower(posts)(g) or k.on_table(g)
            if r:
                return f"post: {r}"
            if not any(bx.rests_on(p, q) for p in bar for q in g):
                return "the bar does not rest on both posts"
        gap = bx.separation(legs[0], legs[1])
        if mouth is not None and abs(gap - mouth * bx.CUBE) > 0.015:
            return f"posts {gap:.3f} m apart, want {mouth} cube(s)"
        return None

    return f


def _span(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """A bridge or doorway: two posts `posts` high with a top across them, a beam (the shared
    `bridge`) or a bar of cubes; the posts `mouth` cubes apart clear when given."""
    beam = k.bridge(posts, pillars=2)
    if posts is not None:  # the shared check also finds short legs under a top of leg cubes
        beam = k.all_of(beam, k.height(posts + 1))
    if mouth is not None:
        beam = k.all_of(beam, k.leg_gap(mouth))
    return k.any_of(beam, _bar_on_posts(posts, mouth))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected roof that is the topmost level and rests on every leg (a roof of cubes too,
    whose middle cubes rest on nothing)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        z = max(round(b.lo[2], 3) for b in bs)
        roof = [b for b in bs if round(b.lo[2], 3) == z]
        below = [b for b in bs if round(b.lo[2], 3) != z]
        found = bx.components(below) if below else []
        if len(found) != legs or len(bx.components(roof)) != 1:
            return f"{len(found)} legs under the top level, want {legs} under one roof"
        for g in found:
            r = k.on_table(g) or k.full(g) or k.height(leg_h)(g)
            if r:
                return f"leg: {r}"
            if not any(bx.rests_on(p, q) for p in roof for q in g):
                return "the roof does not rest on every leg"
        return None

    return f


def _roofed(legs: int, leg_h: int) -> k.Check:
    """A table or canopy on `legs` legs `leg_h` high: the shared `canopy`, or a cube roof."""
    shared = k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1))
    # the cell's beam roof (two crossing layers of beams) added after the first measurement
    return k.any_of(shared, _roof_on(legs, leg_h), k.beam_roof(legs, leg_h))


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


def _split_columns(bs: k.Boxes, h: int) -> list[tuple[list[k.Box], list[k.Box]]]:
    """Each (column, rest) split of `bs` where the column is a full tower of exactly `h`
    cubes standing on the table and something else remains."""
    out = []
    for col in bx.columns(bs):
        if len(col) != h or k.tower(h)(col) is not None or col[0].lo[2] > bx.TOL:
            continue
        rest = [b for b in bs if all(b is not c for c in col)]
        if rest:
            out.append((col, rest))
    return out


def _against(h: int, rest: k.Check, side: str | None = None, middle: bool = False) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table set against the rest,
    which passes `rest`; the column on `side` of the rest when given, and with `middle`
    facing the middle of that side (± 3 cm)."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col, others in _split_columns(bs, h):
            r = rest(others)
            got = bx.side_of(col, others)
            if r is None and side is not None and got != side:
                r = f"the {h}-column is {got} of the rest, want {side}"
            if r is None and middle:
                (cx, cy), (ox, oy) = bx.centre(col), bx.centre(others)
                off = abs(cy - oy) if got in (_F, _B) else abs(cx - ox)
                if off > 0.03:
                    r = f"the {h}-column is {off:.3f} m off the middle"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the rest"

    return f


def _stairs_to(h: int, steps: int, toward: str | None = None) -> k.Check:
    """One structure: a staircase of `steps` with a full `h`-cube column set against its high
    end (the stairs lead up to the column); the stairs climb `toward` when given."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col, others in _split_columns(bs, h):
            r = k.staircase(steps)(others)
            up = bx.rises_towards(others)
            if r is None and bx.side_of(col, others) != up:
                r = f"the column is {bx.side_of(col, others)} of the stairs, which climb {up}"
            if r is None and toward is not None and up != toward:
                r = f"the stairs climb {up}, want {toward}"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the stairs"

    return f


def _climbs_to(toward: str | None = None, max_gap: float = 0.15) -> k.Rel:
    """A (a staircase) climbs towards B, which stands clear of it no more than `max_gap` m
    away off its high end; A climbs `toward` when given."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        up = bx.rises_towards(a)
        if up is None:
            return "not a staircase"
        if bx.side_of(b, a) != up:
            return f"the tower is {bx.side_of(b, a)} of the stairs, which climb {up}"
        if toward is not None and up != toward:
            return f"the stairs climb {up}, want {toward}"
        gap = bx.separation(a, b)
        return None if 0 < gap <= max_gap else f"{gap:.3f} m apart, want 0–{max_gap} m"

    return rel


def _inside_box(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A's footprint centre lies within B's bounding footprint (a crate in the corner of an
    L, clear of its arms)."""
    (x, y), ((x0, y0, _), (x1, y1, _)) = bx.centre(a), bx.bounds(b)
    return None if x0 < x < x1 and y0 < y < y1 else "not within the other's footprint"


def _not_in_line(result: Mapping[str, Any]) -> k.Reason:
    """The separate structures' footprint centres do not all lie on one straight line (some
    centre at least 2 cm off the line through the two furthest apart)."""
    comps = k.separate_structures(result)
    if isinstance(comps, str):
        return comps
    pts = [bx.centre(g) for g in comps]
    if len(pts) < 3:
        return "fewer than three structures"
    a, b = max(
        ((p, q) for i, p in enumerate(pts) for q in pts[i + 1 :]),
        key=lambda pq: math.dist(pq[0], pq[1]),
    )
    n = math.dist(a, b)
    if n == 0:
        return "all in one place"
    off = max(abs((p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0])) / n for p in pts)
    return None if off >= 0.02 else "all in one straight line"


def _max_x(x: float) -> k.Check:
    """Every part lies at x ≤ `x` (m): in front of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[0] for b in bs)
        return None if hi <= x + bx.TOL else f"a part reaches x {hi:.3f}, want ≤ {x}"

    return f


def _max_y(y: float) -> k.Check:
    """Every part lies at y ≤ `y` (m): on the right of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[1] for b in bs)
        return None if hi <= y + bx.TOL else f"a part reaches y {hi:.3f}, want ≤ {y}"

    return f


def _min_y(y: float) -> k.Check:
    """Every part lies at y ≥ `y` (m): on the left of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _fits(a: int, b: int) -> k.Check:
    """A footprint no bigger than a × b cubes (either way round)."""

    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        want = (min(a, b), max(a, b))
        ok = got[0] <= want[0] and got[1] <= want[1]
        return None if ok else f"footprint {got}, want within {want}"

    return f


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_L_WALL = k.plan_heights("222", "2..", "2..", "2..")  # arms of 4 and 3 tiles, 2 levels


def _next_to(h: int, other: k.Check, side: str | None = None) -> k.Pred:
    """A tower of `h` next to `other`: clear of it (≤ 5 cubes, on `side` when given) or set
    against it as one structure."""
    rel = _near if side is None else k.all_rels(k.on_side(side), _near)
    return k.any_of(k.pair(T(h), other, rel), one(_against(h, other, side)))


def _up_to(h: int, steps: int, toward: str | None = None) -> k.Pred:
    """A staircase of `steps` leading up to a tower of `h`: clear of it or set against it."""
    return k.any_of(
        k.pair(k.staircase(steps), T(h), _climbs_to(toward)),
        one(_stairs_to(h, steps, toward)),
    )


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Tower of 4 and a tower of 2, the short one directly left of the tall one. Verify the "
        "gap between them is exactly one cube, reject anything else.",
        k.pair(T(2), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "rel-02",
        REL,
        "Hello, um, could the robot put down a little block of cubes, 2 by 2, and a tower of "
        "three behind it? If that's not too much trouble.",
        _next_to(3, k.solid(2, 2), _B),
    ),
    _c(
        "rel-03",
        REL,
        "Place a 3x3 tile floor and put a single 2-level pillar on the centre tile of it.",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "so basically a wall um five long two high and uh a tower of three in front of it, "
        "like touching the middle of it",
        one(_against(3, k.wall(5, 2), _F, middle=True)),
    ),
    _c(
        "rel-05",
        REL,
        "I want a pyramid of 3 floors and at the right of it a tower of 5, distant of 2 cubes.",
        k.pair(T(5), k.pyramid(3), k.gap_of(2, _R)),
    ),
    _c(
        "rel-06",
        REL,
        "Ring, 5 by 5 outside, one high. One tower of 3 inside it, standing free in the exact "
        "centre — it must not touch the ring walls.",
        k.pair(k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5)), T(3), k.centred_in()),
    ),
    _c(
        "rel-07",
        REL,
        "Would it be possible for the robot to make a little staircase thing, three steps, "
        "going up towards a tower of four? I'd like the stairs to lead up to it.",
        _up_to(4, 3),
    ),
    _c(
        "rel-08",
        REL,
        "Two 1x4 walls, 2 levels tall, parallel, with a 2-tile corridor between them.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-09",
        REL,
        "put a bridge uh with legs three high and then like a tower of two on each side of the "
        "bridge, not touching it",
        k.between_(_span(3), T(2)),
    ),
    _c(
        "rel-10",
        REL,
        "Make a tower of 6 floors and put a wall of 4 of length in front to it, one cube of "
        "space between.",
        k.pair(k.any_of(k.wall(4), k.row(4)), T(6), k.gap_of(1, _F)),
    ),
    _c(
        "rel-11",
        REL,
        "Three towers in a line left to right: 2, 5, 2. Middle one must be the tallest. Gaps "
        "one cube each side — check both.",
        k.in_order("y", T(2), T(5), T(2), gaps=(1,)),
    ),
    _c(
        "rel-12",
        REL,
        "Can the robot make a tower of three blocks and then put one more block next to it, on "
        "the table, on its left? Sorry if I'm saying it wrong.",
        _next_to(1, T(3), _L),
    ),
    _c(
        "rel-13",
        REL,
        "Level layout: an L-shaped wall, arms 4 and 3 tiles, 2 levels high, and a single crate "
        "tucked into the inside corner of the L.",
        k.any_of(
            one(k.plan_heights("222", "21.", "2..", "2..")),
            k.pair(T(1), _L_WALL, _inside_box),
        ),
    ),
    _c(
        "rel-14",
        REL,
        "a pyramid of tree levels and to the left of it a tower of for",
        _next_to(4, k.pyramid(3), _L),
    ),
    _c(
        "rel-15",
        REL,
        "I would like two towers of 4 floors, one next to the other, with the space of one cube "
        "between them, and a beam over them like a bridge.",
        one(_span(4, 1)),
    ),
    _c(
        "rel-16",
        REL,
        "Tower of 3, with one single cube touching each of its four sides — front, back, left, "
        "right. Inspect: every one of those cubes flat on the table.",
        one(k.plan_heights(".1.", "131", ".1.")),
    ),
    _c(
        "rel-17",
        REL,
        "Put a 2x2 block, 1 level, between two 3-level pillars, all on one row, 1 tile gap on "
        "both sides.",
        k.line(T(3), k.block(2, 2, 1), T(3), gaps=(1,)),
    ),
    _c(
        "rel-18",
        REL,
        "Could you do a little wall, four blocks long and two high, with a small tower sitting "
        "on top of it at one end? Two blocks for the tower.",
        one(k.plan_heights("4222")),
    ),
    _c(
        "rel-19",
        REL,
        "okay so um three towers, uh, one, two and three high, and the middle one's the, uh, "
        "the two, and they're like all touching",
        one(k.dims(1, 3), k.profile(1, 2, 3)),
    ),
    _c(
        "rel-20",
        REL,
        "A staircase of 4 marches, and behind to the staircase a wall of 5, high of 3, distant "
        "one cube.",
        k.pair(k.wall(5, 3), k.staircase(4), k.gap_of(1, _B)),
    ),
    _c(
        "rel-21",
        REL,
        "Slab 4x2, one layer. A tower of 2 sitting on each of the four corners of the slab. "
        "Verify corner placement.",
        one(k.base(4, 2), k.corner_columns(2), k.levels(8, 4, 4)),
    ),
    _c(
        "rel-22",
        REL,
        "Three 2-level pillars in a row along the front, 2 tiles apart. Put a crate on top of "
        "the middle one.",
        k.all_of(
            k.in_order("y", T(2), T(3), T(2), gaps=(2,)),
            k.layout(reg("front")),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "build a tower of six uh no wait five, five cubes", one(T(5))),
    _c(
        "seq-02",
        SEQ,
        "Step 1: 3x3 slab, one layer. Step 2: a second layer, 2x2, in one corner of it. Hold "
        "for inspection after step 2.",
        one(k.plan_heights("221", "221", "111")),
    ),
    _c(
        "seq-03",
        SEQ,
        "First could the robot make a tower of five blocks? And then, um, maybe take the top "
        "two off again? Thank you!",
        one(T(3)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Build order: first a 4x1 row of tiles, then raise the two end tiles to level 3.",
        one(k.any_of(k.plan_heights("3113"), k.plan_heights("4114"))),
    ),
    _c(
        "seq-05",
        SEQ,
        "Before, you make a wall of 6 of length and 2 of height. After, you remove the half of "
        "the wall.",
        one(k.any_of(k.row(6), k.wall(3, 2))),
    ),
    _c(
        "seq-06",
        SEQ,
        "stack for cubes, sorry, stack four cubes, and then put two more on top",
        one(T(6)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Build two towers of 3, two cubes apart. Then make the left one 5 high. Final check: "
        "left 5, right 3, gap still two cubes.",
        k.pair(T(5), T(3), k.gap_of(2, _L)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Oh, could it make a little bridge? And afterwards put one block right on the middle "
        "of the top?",
        one(_topped(_span()), k.top_centred()),
    ),
    _c(
        "seq-09",
        SEQ,
        "First pass: a ring of tiles, 4x4, one level. Second pass: raise the whole ring to 2 "
        "levels.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-10",
        SEQ,
        "okay a pyramid, base uh four by four and um like three levels, no actually make it "
        "just two levels",
        one(k.pyramid(2), k.base(4, 4)),
    ),
    _c(
        "seq-11",
        SEQ,
        "First make a tower of 3 floors. Then at the left of it make another equal, and then "
        "a third equal at the left of the second.",
        k.any_of(
            k.in_order("y", T(3), T(3), T(3), max_gap=0.25),
            one(k.wall(3, 3), k.runs("y")),
        ),
    ),
    _c(
        "seq-12",
        SEQ,
        "Build a 2x3 block, 2 layers. Then remove exactly one layer. Result must be 2x3x1 and "
        "nothing else on the table.",
        one(k.block(2, 3, 1)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Can you first put a row of five blocks along the front, and then a tower of three "
        "blocks standing on the right-hand end of that row?",
        one(k.plan_heights("41111"), k.upper_side(_R, 1), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-14",
        SEQ,
        "Spawn three 2-level pillars in a row along the back, 1 tile apart. Then delete the "
        "middle one.",
        k.pair(k.all_of(T(2), reg("back")), k.all_of(T(2), reg("back")), k.gap_of(3)),
    ),
    _c(
        "seq-15",
        SEQ,
        "so basically uh put a wall there, like, uh, no scratch that, put a staircase, three "
        "steps, that's it",
        one(k.staircase(3)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Make a tower of 8 floors. Then take the 3 cubes of the top and make with them a "
        "second tower at the right of the first, one cube of distance.",
        k.pair(T(3), T(5), k.gap_of(1, _R)),
    ),
    _c(
        "seq-17",
        SEQ,
        "First lay a 5-long row of cubes running front to back. Then add a second course on "
        "the same footprint. Verify: 5 by 1 by 2, no voids.",
        one(k.wall(5, 2), k.runs("x")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Could you make two little towers, three blocks each? And, um, then join them at the "
        "top somehow, like a doorway?",
        one(_span(3)),
    ),
    _c(
        "seq-19",
        SEQ,
        "Step one, 3x3 platform, 1 level. Step two, another 3x3 platform on top of it. Step "
        "three, a 1x1 pillar of 2 levels in the middle of that.",
        one(k.on_top(T(2), k.block(3, 3, 2)), k.top_centred(), k.levels(9, 9, 1, 1)),
    ),
    _c(
        "seq-20",
        SEQ,
        "three towers uh two three and four high in a row, one cube apart, and then um take "
        "the middle one away",
        k.pair(T(2), T(4), k.gap_of(3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "build uh seven cubes in a stack please, just the one stack", one(T(7))),
    _c(
        "num-02",
        NUM,
        "Two towers, heights 3 and 6 — the second exactly double the first, tolerance zero.",
        k.structures(T(3), T(6)),
    ),
    _c(
        "num-03",
        NUM,
        "Could it make a dozen blocks into a little flat square-ish thing? Whatever shape works, "
        "as long as it's flat.",
        one(k.any_of(k.block(3, 4, 1), k.block(2, 6, 1)), k.only_cubes),
    ),
    _c(
        "num-04",
        NUM,
        "I need a 4x4 tile floor with a 2x2 block, 2 levels high, sitting centred on it.",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.centred(), k.levels(16, 4, 4)),
    ),
    _c("num-05", NUM, "um a row of for cubes, for, f o u r", one(k.row(4))),
    _c(
        "num-06",
        NUM,
        "A pyramid with 3 floors: 9 cubes in the first floor, 4 in the second and 1 in the third.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-07",
        NUM,
        "Build three towers: the first 2 high, each following one exactly one cube taller. No "
        "more than 4 on the tallest. One cube gap between neighbours.",
        k.line(T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-08",
        NUM,
        "Could the robot stack a couple of blocks, and then a few more next to them? Like two "
        "and then three?",
        k.any_of(k.pair(T(2), T(3), _near), one(k.cell_heights(2, 3))),
    ),
    _c(
        "num-09",
        NUM,
        "Place 6 single-tile crates in a 2 by 3 formation, 1 tile apart each way.",
        k.all_of(k.each(6, T(1)), k.layout(k.dims(3, 5)), _nn_gap(1)),
    ),
    _c(
        "num-10",
        NUM,
        "a wall, twelve, I mean, like, uh, twelve cubes total, six long two high",
        one(k.wall(6, 2), k.parts(12)),
    ),
    _c(
        "num-11",
        NUM,
        "I want two towers, one of 6 floors and the other the half.",
        k.structures(T(6), T(3)),
    ),
    _c(
        "num-12",
        NUM,
        "Grid of 2 by 2 towers, each exactly 3 high, each one cube clear of its neighbours.",
        k.all_of(k.each(4, T(3)), k.layout(k.dims(3, 3)), _nn_gap(1)),
    ),
    _c(
        "num-13",
        NUM,
        "How about a pyramid with, um, maybe three or four layers? Whichever the robot likes.",
        one(k.pyramid(lo=3, hi=4)),
    ),
    _c(
        "num-14",
        NUM,
        "Four pillars of 1, 2, 3 and 4 levels, lined up tallest to shortest from left to right, "
        "1 tile gaps.",
        k.in_order("y", T(4), T(3), T(2), T(1), gaps=(1,)),
    ),
    _c(
        "num-15",
        NUM,
        "three towers of um two and uh one more tower of like five",
        k.structures(T(2), T(2), T(2), T(5)),
    ),
    _c(
        "num-16",
        NUM,
        "Make 5 towers, every one of 2 floors, in line, distant one cube each from the other.",
        k.in_line(5, T(2), 1),
    ),
    _c(
        "num-17",
        NUM,
        "Wall A: 5 long, 2 high. Wall B: same length, one course higher. Parallel, 2 cubes apart.",
        k.pair(k.wall(5, 2), k.wall(5, 3), k.parallel_gap(2)),
    ),
    _c(
        "num-18",
        NUM,
        "Could the robot put three separate blocks on the table, just one block each, spread "
        "out a bit?",
        k.each(3, T(1)),
    ),
    _c("num-19", NUM, "Staircase with 5 steps, 2 tiles wide.", one(k.staircase(5), k.dims(2, 5))),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Tower, 20 cm, tolerance zero — that is four cubes exactly, no more.",
        one(T(4)),
    ),
    _c(
        "dim-02",
        DIM,
        "Could the robot make a wall about as long as my hand, say 20 centimetres, and not "
        "very tall, 10 centimetres?",
        one(k.wall(4, 2)),
    ),
    _c(
        "dim-03",
        DIM,
        "A 5x3 tile room, walls 2 levels, hollow.",
        one(
            k.any_of(
                k.all_of(k.ring_of(2, (3, 1)), k.dims(3, 5)),
                k.all_of(k.ring_of(2, (5, 3)), k.dims(5, 7)),
            )
        ),
    ),
    _c(
        "dim-04",
        DIM,
        "a tower, uh, thirty five centimetres tall, three five",
        one(T(7)),
    ),
    _c("dim-05", DIM, "A wall long 30 cm and high 15 cm.", one(k.wall(6, 3))),
    _c(
        "dim-06",
        DIM,
        "Slab, 150 by 200 mm, 50 mm thick. To measure: three by four cubes, single layer.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "dim-07",
        DIM,
        "Is it possible to make a block shape about 10 cm each way? Like one big cube made of "
        "the little ones.",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "dim-08",
        DIM,
        "Platform 6 tiles wide by 2 deep, 1 level, wide side facing the robot.",
        one(k.block_xy(2, 6, 1)),
    ),
    _c(
        "dim-09",
        DIM,
        "the bridge, uh, legs are like fifteen centimetres tall and um the gap under it ten "
        "centimetres",
        one(_span(3, 2)),
    ),
    _c(
        "dim-10",
        DIM,
        "A staircase of 4 steps, each step high 5 cm and deep 5 cm, large 15 cm.",
        one(k.staircase(4), k.dims(3, 4)),
    ),
    _c("dim-11", DIM, "Column, 0.45 m. That is nine cubes; ten is a reject.", one(T(9))),
    _c(
        "dim-12",
        DIM,
        "Could it build something like a little table? Four legs maybe 10 centimetres tall and "
        "a flat top.",
        one(_roofed(4, 2)),
    ),
    _c(
        "dim-13",
        DIM,
        "Pyramid, base footprint 5x5 tiles, 3 levels.",
        one(k.pyramid(3), k.base(5, 5)),
    ),
    _c(
        "dim-14",
        DIM,
        "a wall uh point two five metres long and uh point one high",
        one(k.wall(5, 2)),
    ),
    _c(
        "dim-15",
        DIM,
        "A platform of 20 cm on 20 cm, thick 5 cm, in the middle of the table.",
        one(k.block(4, 4, 1), reg("centre")),
    ),
    _c(
        "dim-16",
        DIM,
        "Ring 300 by 300 mm outside, 50 mm walls, 100 mm high. Check the inside clearance is "
        "200 by 200.",
        one(k.ring_of(2, (4, 4)), k.dims(6, 6)),
    ),
    _c("dim-17", DIM, "A 2x2 pillar, 6 levels tall.", one(k.block(2, 2, 6))),
    _c(
        "dim-18",
        DIM,
        "Could I get a row of blocks about half a metre long?",
        one(k.row(lo=9, hi=11)),
    ),
    _c(
        "dim-19",
        DIM,
        "a block uh fifteen by fifteen by, uh, five centimetres",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "dim-20",
        DIM,
        "A tower of 4 floors with the base large 10 cm.",
        one(k.block(2, 2, 4)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Wall, 5 by 2, cubes only. A beam anywhere in it is a reject.",
        one(k.wall(5, 2), k.only_cubes),
    ),
    _c(
        "neg-02",
        NEG,
        "Could it make a bridge, but not too tall please, nothing higher than three blocks "
        "altogether?",
        one(_span(), k.low(3)),
    ),
    _c(
        "neg-03",
        NEG,
        "4x4 tile floor, 1 level, but leave the four corner tiles out.",
        one(k.plan_heights(".11.", "1111", "1111", ".11.")),
    ),
    _c(
        "neg-04",
        NEG,
        "not a tower, uh, a wall, a wall of four long and um three high",
        one(k.wall(4, 3)),
    ),
    _c(
        "neg-05",
        NEG,
        "A tower of 5 floors, but not in the middle, and not at the left.",
        one(T(5), k.not_(reg("centre"), "in the middle"), k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-06",
        NEG,
        "Two towers of 4. They must not touch; minimum clearance two cubes.",
        k.pair(T(4), T(4), _apart(2)),
    ),
    _c(
        "neg-07",
        NEG,
        "Could it make a little staircase thing with three steps, but not going up to the "
        "left? Going up to the right, if that makes sense.",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "neg-08",
        NEG,
        "A 2-level wall 6 tiles long — no door, no gaps, solid all the way.",
        one(k.wall(6, 2)),
    ),
    _c(
        "neg-09",
        NEG,
        "put a pyramid um not the big one just two levels",
        one(k.pyramid(2)),
    ),
    _c(
        "neg-10",
        NEG,
        "Make a ring of 4 by 4 with 1 floor, without nothing inside.",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "neg-11",
        NEG,
        "Row of 7 cubes, except position 4: leave it empty. Verify a three-cube run each side "
        "of the gap.",
        k.all_of(k.each(2, k.row(3)), k.layout(k.dims(1, 7))),
    ),
    _c(
        "neg-12",
        NEG,
        "Could it make three little towers of two blocks each, but please not all in a "
        "straight line?",
        k.all_of(k.each(3, T(2)), _not_in_line),
    ),
    _c(
        "neg-13",
        NEG,
        "Pillar, 5 levels, anywhere except the back half of the map.",
        one(T(5), _max_x(0.50)),
    ),
    _c(
        "neg-14",
        NEG,
        "a slab uh three by three, no no, not three by three, two by four, one layer",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "neg-15",
        NEG,
        "A bridge with pillars of 2 floors, but without the beam: make the top with cubes.",
        one(_bar_on_posts(2), k.only_cubes),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "Can the robbot make a towr of 4 bloks?", one(T(4))),
    _c("typo-02", TYP, "build a stare case with for steps", one(k.staircase(4))),
    _c("typo-03", TYP, "3x3 tlie floor, 1 levle", one(k.block(3, 3, 1))),
    _c("typo-04", TYP, "Wal 6 long, 2 hgih, verfiy faces flat.", one(k.wall(6, 2))),
    _c("typo-05", TYP, "A piramid of 3 floors, please.", one(k.pyramid(3))),
    _c("typo-06", TYP, "a bridge with legs of tree", one(_span(3))),
    _c("typo-07", TYP, "could you pleese make a litle bridge thing", one(_span())),
    _c("typo-08", TYP, "two pilars, 4 lvls, 2 tile gap", k.pair(T(4), T(4), k.gap_of(2))),
    _c("typo-09", TYP, "a tower of five queues", one(T(5))),
    _c("typo-10", TYP, "A tour of 6 floors at the rigth.", one(T(6), reg("right"))),
    _c("typo-11", TYP, "Slab 2x5 singel layer, chek corners square.", one(k.block(2, 5, 1))),
    _c(
        "typo-12",
        TYP,
        "a ring of blocs, 5 by 5, one hihg",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5)),
    ),
    _c("typo-13", TYP, "a wall of six by to", one(k.wall(6, 2))),
    _c("typo-14", TYP, "Make a castel with 4 towers at the corners.", one(k.castle)),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "At the left, put me a tower of 3 floors.", one(T(3), reg("left"))),
    _c(
        "wo-02",
        WO,
        "four high, the tower, make it four high, at the back",
        one(T(4), reg("back")),
    ),
    _c(
        "wo-03",
        WO,
        "Gap one cube, two towers, each three high — in that order of priority.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "wo-04",
        WO,
        "At map centre: pyramid, 2 levels, base 3x3.",
        one(k.pyramid(2), k.base(3, 3), reg("centre")),
    ),
    _c(
        "wo-05",
        WO,
        "Stairs, could it do? Little ones, three steps maybe?",
        one(k.staircase(3)),
    ),
    _c(
        "wo-06",
        WO,
        "Of 5 cubes long and of 2 high, a wall I want, in front.",
        one(k.wall(5, 2), reg("front")),
    ),
    _c(
        "wo-07",
        WO,
        "on top of the slab uh the tower, and the slab is three by three, tower's two",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.levels(9, 1, 1)),
    ),
    _c(
        "wo-08",
        WO,
        "To be built: block, 2 by 2 by 3. Location: back left.",
        one(k.block(2, 2, 3), reg("back left")),
    ),
    _c(
        "wo-09",
        WO,
        "Corridor walls — two of them, 5 tiles, 2 levels, a 1 tile corridor in between.",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.parallel_gap(1)),
    ),
    _c(
        "wo-10",
        WO,
        "Behind the little tower, the bigger one, please: the little one two blocks, the "
        "bigger one four.",
        _next_to(4, T(2), _B),
    ),
    _c(
        "wo-11",
        WO,
        "The ring I want of 5 by 5 and high 2.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "wo-12",
        WO,
        "the right side, uh, that's where the wall goes, three long two high",
        one(k.wall(3, 2), reg("right")),
    ),
    _c(
        "wo-13",
        WO,
        "Left of the pillar: the staircase. Pillar 4 levels, staircase 3 steps going up to it.",
        _up_to(4, 3, _R),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "um so basically like, uh, we need a tower, yeah, uh, a tower of three, that's it, thanks",
        one(T(3)),
    ),
    _c(
        "fil-02",
        FIL,
        "Oh wow, this is my first time seeing one of these up close! My grandson would love "
        "it. Could it make a little pyramid, two layers?",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Note for the batch record: shift B, calibration checked at 07:40, no deviations "
        "open. Build: wall 4 long by 3 high.",
        one(k.wall(4, 3)),
    ),
    _c(
        "fil-04",
        FIL,
        "Okay, blocking out the first room of the dungeon, this is just greybox so don't sweat "
        "the details: 4x4 tile floor, 1 level.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "fil-05",
        FIL,
        "Good morning, excuse me for my English, it is not very good. I would like a staircase "
        "of 5 steps, please.",
        one(k.staircase(5)),
    ),
    _c(
        "fil-06",
        FIL,
        "right so, uh, hang on, the the uh, yeah, bridge, bridge with uh pillars of two, okay",
        one(_span(2)),
    ),
    _c(
        "fil-07",
        FIL,
        "I'm sorry, I really don't know anything about robots, my daughter works here. Could "
        "it maybe make a row of six blocks?",
        one(k.row(6)),
    ),
    _c(
        "fil-08",
        FIL,
        "Per work instruction WI-204 section 3, and after the usual sign-off: block 3 by 2, "
        "two layers, on the centre line.",
        one(k.block(3, 2, 2), k.near(y=0.30)),
    ),
    _c(
        "fil-09",
        FIL,
        "lol my playtesters keep falling off the edge of the map. anyway: a wall 5 tiles long, "
        "3 levels.",
        one(k.wall(5, 3)),
    ),
    _c(
        "fil-10",
        FIL,
        "so uh like I was saying to Dave, um, we'll do the slab, two by two, uh, two high, yeah",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "fil-11",
        FIL,
        "Ciao! Sorry, I come from the other plant, is my first day here. Make me please a "
        "tower of 7 floors.",
        one(T(7)),
    ),
    _c(
        "fil-12",
        FIL,
        "What a clever machine. Now, I don't want to be a bother, but could it make an arch, "
        "like a little doorway? Any size is fine.",
        one(_ARCH),
    ),
    _c(
        "fil-13",
        FIL,
        "Before anything else, I'm logging this as a first-article check. Ring, 4 by 4, one "
        "high, cubes only.",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4), k.only_cubes),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Tower of 3, back right corner. Verify it is not sitting in the middle.",
        one(T(3), reg("back right")),
    ),
    _c(
        "reg-02",
        REG,
        "Could the robot put a little tower of two blocks over on the left side, please?",
        one(T(2), reg("left")),
    ),
    _c(
        "reg-03",
        REG,
        "Map is the table, origin at the robot, 1 tile = 5 cm, x away from the robot, y to its "
        "left. Put a 1x1 pillar of 3 levels on tile x=10, y=6.",
        one(T(3), k.near(0.50, 0.30, _TILE)),
    ),
    _c(
        "reg-04",
        REG,
        "put the uh the wall at the front, like right at the front, four long two high",
        one(k.wall(4, 2), reg("front")),
    ),
    _c(
        "reg-05",
        REG,
        "A pyramid of 2 floors at the bottom of the table, I mean far from the robot, on the left.",
        one(k.pyramid(2), reg("back left")),
    ),
    _c(
        "reg-06",
        REG,
        "Place the 2x2 block, one layer, in the centre of the cell, square to the robot.",
        one(k.block(2, 2, 1), reg("centre")),
    ),
    _c(
        "reg-07",
        REG,
        "Spawn a 3-level pillar in the north-east corner. North is away from the robot, east "
        "is its right.",
        one(T(3), reg("back right")),
    ),
    _c(
        "reg-08",
        REG,
        "the staircase, uh, over on the right, the robot's right, three steps",
        one(k.staircase(3), reg("right")),
    ),
    _c(
        "reg-09",
        REG,
        "Could it make a little wall at the back, far away from the robot? Three blocks long "
        "and two high.",
        one(k.wall(3, 2), reg("back")),
    ),
    _c(
        "reg-10",
        REG,
        "A tower of 4 floors in front to the robot, at the right.",
        one(T(4), reg("front right")),
    ),
    _c(
        "reg-11",
        REG,
        "Row of 5 along the left edge of the workspace, running front to back. No part to the "
        "right of y = 0.45.",
        one(k.row(5), k.runs("x"), _min_y(0.45)),
    ),
    _c(
        "reg-12",
        REG,
        "Place the 2x3 slab, 1 level, in the south-west corner (south = robot side, west = the "
        "robot's left).",
        one(k.block(2, 3, 1), reg("front left")),
    ),
    _c(
        "reg-13",
        REG,
        "so um the pyramid goes like in the middle, uh, dead middle, two levels",
        one(k.pyramid(2), reg("centre")),
    ),
    _c(
        "reg-14",
        REG,
        "A wall of 4 long and 2 high on the left side, and a tower of 3 on the right side.",
        k.structures(k.all_of(k.wall(4, 2), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "I've no idea what it can do — could it just make something nice for me to take a "
        "photo of?",
        k.anything,
    ),
    _c(
        "open-02",
        OPEN,
        "Greybox me some cover for the arena: a few low blocks, none above 2 levels, at least "
        "three pieces.",
        k.all_of(k.anything, _count(3, 99), k.layout(k.low(2))),
    ),
    _c(
        "open-03",
        OPEN,
        "Build any test artefact you like, but it must use exactly 8 cubes and nothing else.",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(8), k.only_cubes))),
    ),
    _c(
        "open-04",
        OPEN,
        "um just like, uh, make whatever, something tall I guess, yeah",
        k.all_of(k.anything, k.layout(k.height(lo=4))),
    ),
    _c(
        "open-05",
        OPEN,
        "Make something like a little house, as you want.",
        k.all_of(k.anything, k.layout(k.height(lo=2))),
    ),
    _c(
        "open-06",
        OPEN,
        "Could the robot make some steps for a little doll? Any number of steps.",
        k.all_of(k.anything, one(k.staircase())),
    ),
    _c(
        "open-07",
        OPEN,
        "Need a landmark for the level, readable from far away: one structure only, as tall as "
        "you can safely make it, but at least 6 levels.",
        k.all_of(k.anything, one(k.height(lo=6))),
    ),
    _c(
        "open-08",
        OPEN,
        "Any structure, footprint inside 3 by 3 cubes, not over 3 high. Your design.",
        k.all_of(k.anything, k.layout(k.all_of(_fits(3, 3), k.low(3)))),
    ),
    _c(
        "open-09",
        OPEN,
        "uh, a couple of things, two things, doesn't matter what, like side by side",
        k.all_of(k.anything, k.pair(_any, _any, _near)),
    ),
    _c(
        "open-10",
        OPEN,
        "Surprise me with a construction, but only on the right half of the table.",
        k.all_of(k.anything, k.layout(_max_y(0.30))),
    ),
    _c(
        "open-11",
        OPEN,
        "Could it make something with a hole in it that you could look through?",
        k.all_of(k.anything, one(_ARCH)),
    ),
    _c(
        "open-12",
        OPEN,
        "Block out an enclosure, any size, any height, with something inside it.",
        k.all_of(k.anything, k.any_of(k.around(_any), one(k.holding(_any, k.ring)))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "uh uh the the mm hmm okay yeah no", k.honest()),
    _c(
        "bad-02",
        BAD,
        "Construis une tour de quatre cubes à gauche, s'il te plaît.",
        k.honest(one(T(4), reg("left"))),
    ),
    _c(
        "bad-03",
        BAD,
        "Costruisci un muro lungo cinque cubi e alto due.",
        k.honest(one(k.wall(5, 2))),
    ),
    _c(
        "bad-04",
        BAD,
        "Tower, 60 cm. Tolerance zero, no substitutes.",  # 12 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-05", BAD, "Can the robot make me a cup of tea?", k.honest()),
    _c(
        "bad-06",
        BAD,
        "Spawn an enemy patrol that walks back and forth between the two pillars.",
        k.honest(k.anything),
    ),
    _c(
        "bad-07",
        BAD,
        "Wall 4 long, exactly 3 high and exactly 2 high.",
        k.honest(one(k.any_of(k.wall(4, 3), k.wall(4, 2)))),
    ),
    _c(
        "bad-08",
        BAD,
        "build a tower of, uh, [inaudible] cubes",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-09", BAD, "A slab of 2 metres on 1 metre.", k.honest(k.anything)),
    _c(
        "bad-10",
        BAD,
        "Fai una piramide di tre piani, per favore.",
        k.honest(one(k.pyramid(3))),
    ),
    _c(
        "bad-11",
        BAD,
        "Generate a procedurally random dungeon with 40 rooms.",
        k.honest(k.anything),
    ),
    _c(
        "bad-12",
        BAD,
        "Could you put the blocks back the way they were when I came in?",
        k.honest(k.anything),
    ),
    _c(
        "bad-13",
        BAD,
        "Two towers of 3, touching each other, with a one-cube gap between them.",
        k.honest(k.anything),
    ),
    _c("bad-14", BAD, "bill the tar of fork cubs on the lift", k.honest(k.anything)),
    _c("bad-15", BAD, "uhhh... hmm. ...", k.honest()),
    _c(
        "bad-16",
        BAD,
        "Put a 3-level pillar on tile x=20, y=3, 1 tile = 5 cm from the robot.",  # x 1.0 m
        k.honest(one(T(3))),
    ),
    _c(
        "bad-17",
        BAD,
        "Can it build a tower that reaches all the way up to the ceiling?",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-18", BAD, "A tower of minus 2 floors.", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-19",
        BAD,
        "Staircase of 4 steps that climbs to the left and to the right at the same time, with "
        "no peak in the middle.",
        k.honest(k.anything),
    ),
    _c("bad-20", BAD, "make a pyramid with zero levels", k.honest()),
]
