"""A twenty-second held-out set for the language front end (dev22): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev21` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a plant manager who gives a goal for a visit or a demo and leaves the details open ("we
  need something like a gate for the demo, two posts and a top, nothing fancy"). What the
  manager leaves open is not checked: a gate is two posts of any height with a beam or a bar
  of cubes across the tops, "close" is clear of it and no more than three cubes away, "off to
  one side" is the left or the right region, and a stated number is still exact;
* an operator texting from a phone: lowercase, "pls", "thx", "w/", "approx", "2x" (two of),
  "1x", emojis and missing punctuation, and autocorrect slips read as the operator meant them
  ("fridge" for bridge, "kept" for left, "towes" for towers). "approx 30cm" is still 6 cubes;
  "like 4 or 5" accepts either;
* a CNC machinist who thinks in machine terms. X, Y and Z are the cell's own axes (X away from
  the robot, Y to its left, Z up), positions are mm from the robot base, so "X450 Y300" is a
  footprint centre at x 0.45, y 0.30 (± 1.1 cm); "to Z 200" puts the top 200 mm up; "pitch
  100" is centre to centre (single cubes one cube clear); "qty" or "off" is a count; "L250
  H150 T50" is length, height and thickness; "150 apart" between parallel walls accepts the
  clear gap and the centre-to-centre reading; a "250 mm square" of columns accepts 250 outside
  or 250 between column centres; with a datum at a corner, "100 in" accepts the part's centre
  or its edge there; "+Y face" / "-Y corners" are the left and right side of the part;
* a model-railway hobbyist using scenery words. A platform is a row (or a one-layer slab when
  a depth is given); a signal post is a tower; a bridge over the line is two piers with a
  deck across the tops (a beam or a bar of cubes); a gantry is the same with a wider mouth; a
  goods shed or station building is a full block unless the command says it has legs and a
  roof (then separate legs under one connected roof) or is hollow (then an enclosure);
  barrier posts of a level crossing are towers; "the line" and "the track" are the empty
  floor between. Working barriers, metres of track and scale models are bad input (a refusal
  or a noted partial reading);
* a Swedish, Finnish or Norwegian operator whose English has small slips: "a tower with 4
  cubes high" (4 high), "a wall on 5 cubes long" (5 long), "in the back" (the back region),
  "an own tower" (a separate one), "become" (get), "I wrote wrong" (a correction). Three
  commands are wholly in Swedish, Finnish or Norwegian (bad input: a refusal or a noted
  reading).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the middle one",
"the smaller one"), distributive phrases ("on the left of every tower"), comparisons ("the
double", "half as tall"), corrections ("no wait", "sry"), removals and unusable input
(gibberish, emoji only, other languages, contradictions, sizes past the cell, raw G-code,
references to nothing built).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a deck as a beam or a bar of
cubes, a tower set against another structure or clear of it when "next to" does not say, a
gap clear or centre to centre where the machinist's wording allows both — and nothing else.
Geometry comes only from `sdi.bench.boxes`, through the shared checks in `language_checks` and
the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30); the front is the
robot's side (small x).
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

_XY = 0.011  # m: a machinist's coordinate, met to about a centimetre


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev22-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _any(bs: k.Boxes) -> k.Reason:
    """Any structure at all."""
    return None if bs else "no parts"


def _apart(n: int) -> k.Rel:
    """A and B are at least `n` cubes apart, clear (− 1.5 cm)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        gap = bx.separation(a, b)
        return None if gap >= n * bx.CUBE - 0.015 else f"{gap:.3f} m apart, want ≥ {n} cube(s)"

    return rel


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


def _bar_on_posts(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """Two separate posts `posts` cubes high (any height when None), `mouth` cubes apart clear
    (± 1.5 cm) when given, and as the topmost level one connected bar resting on both — a beam
    or a row of cubes (with a row of cubes the shared `bridge` finds legs one cube short,
    since the bar's middle cubes rest on nothing)."""

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
            r = k.tower(posts)(g)
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
    """A bridge, gate or gantry: two posts `posts` high with a deck across the tops, a beam
    (the shared `bridge`) or a bar of cubes; posts `mouth` cubes apart clear when given."""
    beam = k.bridge(posts, pillars=2)
    if mouth is not None:
        beam = k.all_of(beam, k.leg_gap(mouth))
    return k.any_of(beam, _bar_on_posts(posts, mouth))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected roof that is the topmost level and rests on every leg (a roof of beams or of
    cubes, whose middle cubes rest on nothing)."""

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
    """A shed or canopy on `legs` legs `leg_h` high: the shared `canopy`, or a cube roof."""
    return k.any_of(k.canopy(legs, leg_h, leg_h), _roof_on(legs, leg_h))


def _off_ends(mid: k.Check, *caps: k.Check, max_gap: float = 0.15) -> k.Pred:
    """1 + len(caps) separate structures: one passing `mid` (longer one way than the other)
    and the rest passing `caps`, each standing clear off a different end of it — in line with
    its long axis, no more than `max_gap` m away."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != 1 + len(caps):
            return f"{len(comps)} separate structures, want {1 + len(caps)}"
        first: k.Reason = None
        for i, m in enumerate(comps):
            r = mid(m)
            fx, fy = bx.footprint_cubes(m)
            if r is None and fx == fy:
                r = "the middle piece has no long axis"
            if r is not None:
                first = first or r
                continue
            along_y = fy > fx
            ends = (_L, _R) if along_y else (_F, _B)
            (lo, hi) = bx.bounds(m)
            others = comps[:i] + comps[i + 1 :]
            for perm in itertools.permutations(others):
                got: list[str] = []
                why: k.Reason = None
                for cap, o in zip(caps, perm, strict=True):
                    side = bx.side_of(o, m)
                    cx, cy = bx.centre(o)
                    across = cx if along_y else cy
                    a0, a1 = (lo[0], hi[0]) if along_y else (lo[1], hi[1])
                    gap = bx.separation(o, m)
                    why = cap(o)
                    if why is None and side not in ends:
                        why = f"a piece {side} of the middle one, not off an end"
                    if why is None and not a0 - bx.TOL <= across <= a1 + bx.TOL:
                        why = "a piece off the end but not in line with it"
                    if why is None and not 0 < gap <= max_gap:
                        why = f"a piece {gap:.3f} m off the end, want 0–{max_gap} m"
                    if why is not None:
                        break
                    got.append(side)
                if why is None and len(set(got)) == len(got):
                    return None
                first = first or why or "two pieces off the same end"
        return first

    return f


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


def _heavier(side: str) -> k.Check:
    """The parts' mean centre lies to `side` of the footprint centre (more material there)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        mx = sum(b.centre[0] for b in bs) / len(bs)
        my = sum(b.centre[1] for b in bs) / len(bs)
        cx, cy = bx.centre(bs)
        d = {_L: my - cy, _R: cy - my, _B: mx - cx, _F: cx - mx}[side]
        return None if d > 0.003 else f"no more material on the {side} side"

    return f


def _max_y(y: float) -> k.Check:
    """Every part lies at y ≤ `y` (m): on the right of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[1] for b in bs)
        return None if hi <= y + bx.TOL else f"a part reaches y {hi:.3f}, want ≤ {y}"

    return f


def _front_edge(x: float, tol: float = 0.011) -> k.Check:
    """The front face (smallest x) at `x` (m), ± tol."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[0] for b in bs)
        return None if abs(lo - x) <= tol else f"front edge at x {lo:.3f}, want {x}"

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


def _facing_mid(tol: float = 0.03) -> k.Rel:
    """A stands square in front of (or behind, or beside) the middle of B: their centres line
    up across the direction from B to A, ± tol."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (ax, ay), (bx0, by0) = bx.centre(a), bx.centre(b)
        off = abs(ay - by0) if bx.side_of(a, b) in (_F, _B) else abs(ax - bx0)
        return None if off <= tol else f"{off:.3f} m off the middle"

    return rel


def _side_rows(n: int, length: int, gap: int) -> k.Pred:
    """`n` rows of `length`, all running the same way, side by side (in a line across their
    length), `gap` cubes apart."""
    along_y = k.all_of(k.row(length), k.runs("y"))
    along_x = k.all_of(k.row(length), k.runs("x"))
    return k.any_of(
        k.in_order("x", *[along_y] * n, gaps=(gap,)),
        k.in_order("y", *[along_x] * n, gaps=(gap,)),
    )


def _deck_off_front(result: Mapping[str, Any]) -> k.Reason:
    """seq-14: a whole bridge (piers 2) at the back and, 2 cubes in front of it, the two bare
    piers of the first bridge."""
    bridge = _span(2)
    r = k.structures(bridge, k.tower(2), k.tower(2))(result)
    if r:
        return r
    comps = k.separate_structures(result)
    if isinstance(comps, str):
        return comps
    whole = [g for g in comps if bridge(g) is None]
    if len(whole) != 1:
        return "not one whole bridge"
    piers = [b for g in comps if bridge(g) is not None for b in g]
    if bx.side_of(whole[0], piers) != _B:
        return f"the whole bridge is {bx.side_of(whole[0], piers)} of the bare piers, want back"
    return k.gap_of(2)(whole[0], piers)


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "For the visitors on Thursday I'd like a tower of five with a little 2 by 2 block, one "
        "layer, just to the right of it. Close, but not touching.",
        k.pair(k.block(2, 2, 1), T(5), k.all_rels(k.on_side(_R), k.within(0.15))),
    ),
    _c(
        "rel-02",
        REL,
        "pls put a tower of 3 behind the wall, wall is 4 long 2 high, 1 cube gap thx",
        k.pair(T(3), k.wall(4, 2), k.gap_of(1, _B)),
    ),
    _c(
        "rel-03",
        REL,
        "Two columns, 200 mm tall each, 100 mm clear between them along Y.",
        k.pair(T(4), T(4), k.gap_of(2, _L)),
    ),
    _c(
        "rel-04",
        REL,
        "Signal post at the end of the platform, please. Platform's a row of 6 cubes, the post "
        "is 4 tall and stands just past the end of it, not touching.",
        _off_ends(k.row(6), T(4), max_gap=0.10),
    ),
    _c(
        "rel-05",
        REL,
        "Can you build a tower with 4 cubes high, and one more tower with 2 cubes high in "
        "front of it? Not so far away, one cube between.",
        k.pair(T(2), T(4), k.gap_of(1, _F)),
    ),
    _c(
        "rel-06",
        REL,
        "Stick a small pyramid, two levels, between two towers of four. Evenly spaced, that's "
        "all I care about.",
        k.line(T(4), k.pyramid(2), T(4), gaps=(1, 2, 3, 4)),
    ),
    _c(
        "rel-07",
        REL,
        "stack of 2 on top of a 3x3 slab pls, in the middle 🙏",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "rel-08",
        REL,
        "Block 100 x 100 x 50 mm, with a 150 mm column standing against its +Y face.",
        one(_col_beside(3, k.block(2, 2, 1), _L)),
    ),
    _c(
        "rel-09",
        REL,
        "Goods shed behind the platform: four legs 2 high with a roof on. Platform is a row of "
        "5 in front of it, one cube apart.",
        k.pair(_roofed(4, 2), k.row(5), k.gap_of(1, _B)),
    ),
    _c(
        "rel-10",
        REL,
        "Put the staircase of 3 steps on the right side of the tower, the tower is 5 high. The "
        "stairs should go up towards the tower.",
        k.any_of(
            k.pair(k.all_of(k.staircase(3), k.rises(_L)), T(5), k.all_rels(k.on_side(_R), _near)),
            one(_col_beside(5, k.all_of(k.staircase(3), k.rises(_L)), _L)),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "build a bridge w/ legs 2 high then put a single cube on it right in the middle",
        one(_topped(_span(2)), k.top_centred()),
    ),
    _c(
        "rel-12",
        REL,
        "Qty 3 columns, 150 tall, pitch 100 along X, centred on X450 Y300.",
        k.all_of(
            k.in_order("x", T(3), T(3), T(3), gaps=(1,)),
            k.layout(k.near(0.45, 0.30, _XY)),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Two platforms either side of the line: rows of 5, parallel, with 2 cubes of track "
        "between them.",
        k.pair(k.row(5), k.row(5), k.parallel_gap(2)),
    ),
    _c(
        "rel-14",
        REL,
        "Build one wall, 5 long and 2 high, and put a tower of 3 at each end of it, not "
        "touching the wall.",
        _off_ends(k.wall(5, 2), T(3), T(3)),
    ),
    _c(
        "rel-15",
        REL,
        "Three towers in a row, the middle one taller than its neighbours — say 2, 4, 2 — with "
        "a cube of room between each.",
        k.line(T(2), T(4), T(2), gaps=(1,)),
    ),
    _c(
        "rel-16",
        REL,
        "can u put the pyramid (3 lvls) in front of the L shape? like 2 cubes in front",
        k.pair(k.pyramid(3), k.shape_letter("L"), k.gap_of(2, _F)),
    ),
    _c(
        "rel-17",
        REL,
        "I would like a ring of cubes, 4 times 4, and inside of it a tower with 3 cubes.",
        k.any_of(
            k.around(T(3), k.all_of(k.ring_of(inner=(2, 2)), k.dims(4, 4))),
            one(k.holding(T(3), k.all_of(k.ring_of(inner=(2, 2)), k.dims(4, 4)))),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "Wall 250 long by 100 high, one cube thick, running along X. Second wall, same spec, "
        "parallel to it, 100 mm clear on its +Y side.",
        k.pair(
            k.all_of(k.wall(5, 2), k.runs("x")),
            k.all_of(k.wall(5, 2), k.runs("x")),
            k.all_rels(k.parallel_gap(2), k.on_side(_L)),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "Bridge over the line with piers 2 high, and a signal post of 5 on either side of the "
        "bridge, a cube clear of it.",
        k.line(T(5), _span(2), T(5), gaps=(1,)),
    ),
    _c(
        "rel-20",
        REL,
        "tower of 6 pls and a 2x2 block 1 high right behind it touching",
        one(_col_beside(6, k.block(2, 2, 1), _F)),
    ),
    _c(
        "rel-21",
        REL,
        "3 step stairs going up to the left pls, and a tower of 2 touching the low end",
        one(_col_beside(2, k.all_of(k.staircase(3), k.rises(_L)), _R)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Start with a wall, six long and two high. Once that's up, put a tower of 3 in front of "
        "the middle of it, a cube away.",
        k.pair(T(3), k.wall(6, 2), k.all_rels(k.gap_of(1, _F), _facing_mid())),
    ),
    _c("seq-02", SEQ, "tower of 5 pls… actually no make it 3", one(T(3))),
    _c(
        "seq-03",
        SEQ,
        "Op 10: lay a 3 x 3 base, one layer. Op 20: single column on the centre cell, up to Z 200.",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "First the two piers, 3 cubes each, two cubes apart. Then lay the deck across them.",
        one(_span(3, 2)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Build a tower with 6 cubes. After that take away the two top ones and put them as an "
        "own tower beside it.",
        k.any_of(k.pair(T(4), T(2), k.within(0.15)), one(k.cell_heights(4, 2))),
    ),
    _c(
        "seq-06",
        SEQ,
        "Let's do a staircase of four steps — no, scratch that, five, the VP likes big numbers.",
        one(k.staircase(5)),
    ),
    _c("seq-07", SEQ, "build 2x towers of 2. then add 1 to each one thx", k.each(2, T(3))),
    _c(
        "seq-08",
        SEQ,
        "Stack a 2 x 4 block, 3 layers. Then remove the top layer.",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Lay the platform first: 6 cubes in a row across the front. Then the station building "
        "behind it, a 2 by 3 block two high, a cube away.",
        k.pair(
            k.block(2, 3, 2),
            k.all_of(k.row(6), k.runs("y"), reg("front")),
            k.gap_of(1, _B),
        ),
    ),
    _c(
        "seq-10",
        SEQ,
        "Please make a pyramid of 3 levels. Sorry, I wrote wrong, it should be 2 levels.",
        one(k.pyramid(2)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build two towers of 4 a few cubes apart, then join them across the top so it looks "
        "like a gate.",
        one(_span(4)),
    ),
    _c("seq-12", SEQ, "make a row of 5 then take away the 2 on the ends", one(k.row(3))),
    _c(
        "seq-13",
        SEQ,
        "Program: 1) column 100 tall at X300 Y200. 2) column 250 tall at X300 Y400. 3) end.",
        k.structures(
            k.all_of(T(2), k.near(0.30, 0.20, _XY)),
            k.all_of(T(5), k.near(0.30, 0.40, _XY)),
        ),
    ),
    _c(
        "seq-14",
        SEQ,
        "Build a bridge, piers 2 high. Then a second one the same, straight behind it, 2 cubes "
        "back. Then take the deck off the first one.",
        _deck_off_front,
    ),
    _c(
        "seq-15",
        SEQ,
        "First you can make a wall on 4 cubes long and 3 high. Then you take away one cube from "
        "the top at both ends.",
        one(k.flat, k.profile(2, 3, 3, 2)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Put a tower of 3 on the left and a tower of 3 on the right. Then, in between, a taller "
        "one — five.",
        k.all_of(
            k.structures(k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right")), T(5)),
            k.in_order("y", T(3), T(5), T(3)),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "pyramid 3 levels at the back... wait no put it front left sry",
        one(k.pyramid(3), reg("front left")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build a 4 x 4 slab, 1 layer. Then a 2 x 2 x 2 block on top, centred. Then remove the "
        "four corner cubes of the slab.",
        one(k.plan_heights(".11.", "1331", "1331", ".11.")),
    ),
    _c(
        "seq-19",
        SEQ,
        "Put up the signal post, 3 cubes. Now extend it by two more.",
        one(T(5)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Make three towers, 2, 3 and 4 high. After that, make the smallest one as high as the "
        "biggest.",
        k.structures(T(4), T(3), T(4)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "We need half a dozen single cubes out in a line, a cube apart, for the conveyor demo.",
        k.in_line(6, T(1), 1),
    ),
    _c("num-02", NUM, "2x towers of 3 + 1x tower of 5 pls", k.structures(T(3), T(3), T(5))),
    _c(
        "num-03",
        NUM,
        "Qty 4 columns, 100 mm tall, one at each corner of a 250 mm square.",
        k.all_of(k.each(4, T(2)), _corners(5, 6)),
    ),
    _c(
        "num-04",
        NUM,
        "Station with three platforms, each a row of 4, side by side, one cube between them.",
        _side_rows(3, 4, 1),
    ),
    _c(
        "num-05",
        NUM,
        "I want 7 cubes in a row please, along the front side.",
        one(k.row(7), k.runs("y"), reg("front")),
    ),
    _c(
        "num-06",
        NUM,
        "A dozen cubes stacked three high in one solid block. You pick the footprint.",
        one(k.any_of(k.block(2, 2, 3), k.block(1, 4, 3))),
    ),
    _c(
        "num-07",
        NUM,
        "pls 3 towers 1 2 3 tall like steps but not touching, gap 1",
        k.line(T(1), T(2), T(3), gaps=(1,)),
    ),
    _c("num-08", NUM, "Pyramid, 3 tiers, base 9 pcs.", one(k.pyramid_counts(9, 4, 1))),
    _c(
        "num-09",
        NUM,
        "A short goods train: three wagons, 1 by 2 blocks coupled one behind the other, a cube "
        "gap between each.",
        k.any_of(  # wagons end to end: their long sides along the line
            k.in_order("x", *[k.all_of(k.solid(1, 2), k.runs("x"))] * 3, gaps=(1,)),
            k.in_order("y", *[k.all_of(k.solid(1, 2), k.runs("y"))] * 3, gaps=(1,)),
        ),
    ),
    _c(
        "num-10",
        NUM,
        "Make two towers, one with 3 cubes and one with the double.",
        k.structures(T(3), T(6)),
    ),
    _c(
        "num-11",
        NUM,
        "Two towers, please: the first one eight high, the second half as tall as the first.",
        k.structures(T(8), T(4)),
    ),
    _c("num-12", NUM, "tower of like 4 or 5 idc", one(T(lo=4, hi=5))),
    _c(
        "num-13",
        NUM,
        "Qty 2 walls, 5 x 2 each, 150 apart.",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.either(k.gap_of(3), k.parallel_gap(2))),
    ),
    _c(
        "num-14",
        NUM,
        "Ten signal posts? No, just a pair, 3 high each, a cube apart.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "num-15",
        NUM,
        "Build 3 small towers with 2 cubes each, and on the left of every tower one single "
        "cube, touching.",
        k.each(3, _col_beside(1, T(2), _L)),
    ),
    _c(
        "num-16",
        NUM,
        "Give me four towers, each one cube taller than the last, starting from two.",
        k.structures(T(2), T(3), T(4), T(5)),
    ),
    _c(
        "num-17",
        NUM,
        "a 3x3 grid of single cubes w/ 1 cube gaps between",
        k.all_of(k.each(9, T(1)), k.layout(k.dims(5, 5)), _nn_gap(1)),
    ),
    _c("num-18", NUM, "1 pc on 1 pc on 1 pc… 7 total, single column.", one(T(7))),
    _c(
        "num-19",
        NUM,
        "A level crossing: four barrier posts, 2 cubes high, with 3 cubes of road between them "
        "each way.",
        k.all_of(k.each(4, T(2)), _corners(5)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Block, 150 x 100 x 100 mm (X x Y x Z).", one(k.block_xy(3, 2, 2))),
    _c("dim-02", DIM, "Column, 0.3 m, Z up.", one(T(6))),
    _c("dim-03", DIM, "wall approx 30cm long 10cm tall", one(k.wall(6, 2))),
    _c(
        "dim-04",
        DIM,
        "A platform 40 cm long and 10 cm deep, one cube high, along the front.",
        one(k.block(2, 8, 1), k.runs("y"), reg("front")),
    ),
    _c(
        "dim-05",
        DIM,
        "A wall with 25 centimetre long and 15 centimetre high, please.",
        one(k.wall(5, 3)),
    ),
    _c("dim-06", DIM, "Just a flat slab, about a foot square, one layer.", one(k.block(6, 6, 1))),
    _c(
        "dim-07",
        DIM,
        "Staircase, 4 steps, rise 50, run 50, width 100.",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c(
        "dim-08",
        DIM,
        "A bridge over the line: piers 10 cm high and 10 cm of clearance between them.",
        one(_span(2, 2)),
    ),
    _c("dim-09", DIM, "A tower with 35 cm high.", one(T(7))),
    _c("dim-10", DIM, "slab 4x6 1 layer thx", one(k.block(4, 6, 1))),
    _c(
        "dim-11",
        DIM,
        "Hollow rectangle, outside 250 x 200, wall one cube thick, 100 high.",
        one(k.ring_of(2, (3, 2)), k.dims(4, 5)),
    ),
    _c(
        "dim-12",
        DIM,
        "Goods shed, 4 cubes long and 3 wide, walls 2 high, hollow inside.",
        one(k.ring_of(2, (2, 1)), k.dims(3, 4)),
    ),
    _c(
        "dim-13",
        DIM,
        "Make a pyramid where the bottom is 4 times 4 cubes.",
        one(k.pyramid(), k.base(4, 4)),
    ),
    _c(
        "dim-14",
        DIM,
        "Something like a gate for the entrance display, two posts and a top, about 20 cm tall "
        "overall.",
        one(_span(), k.height(4)),
    ),
    _c("dim-15", DIM, "Wall, L250 H150 T50, axis along Y.", one(k.wall(5, 3), k.runs("y"))),
    _c("dim-16", DIM, "tower 0.25m pls", one(T(5))),
    _c(
        "dim-17",
        DIM,
        "A signal gantry over three tracks: two posts 4 high, 6 cubes apart, and a bar across "
        "the top.",
        one(_span(4, 6)),
    ),
    _c(
        "dim-18",
        DIM,
        "A block that is 3 cubes in width, 2 cubes in depth and 2 in height.",
        one(k.block_xy(2, 3, 2)),
    ),
    _c(
        "dim-19",
        DIM,
        "Slab 200 x 200 x 50 at X500 Y300.",
        one(k.block(4, 4, 1), k.near(0.50, 0.30, _XY)),
    ),
    _c("dim-20", DIM, "row 35cm plz", one(k.row(7))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A tower of 5, but not in the middle of the table, people will be walking round it. Put "
        "it off to one side.",
        one(T(5), k.any_of(reg("left"), reg("right"))),
    ),
    _c(
        "neg-02",
        NEG,
        "wall 5 long 2 high NO beams pls only cubes",
        one(k.wall(5, 2), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "3 x 3 x 1 plate, no material at the centre cell.",
        one(k.plan_heights("111", "1.1", "111")),
    ),
    _c(
        "neg-04",
        NEG,
        "A bridge without a deck, just the two piers, 3 high, two cubes apart.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "neg-05",
        NEG,
        "Build two towers of 4, but they must not stand together, at least 2 cubes between.",
        k.pair(T(4), T(4), _apart(2)),
    ),
    _c(
        "neg-06",
        NEG,
        "A pyramid, but don't go over 3 levels, the ceiling's low in the photo studio.",
        one(k.pyramid(lo=2, hi=3)),
    ),
    _c(
        "neg-07",
        NEG,
        "staircase 4 steps not going up to the back, up to the left instead",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "neg-08",
        NEG,
        "Column 200 tall, do not place it forward of X500.",
        one(T(4), k.min_x(0.50)),
    ),
    _c(
        "neg-09",
        NEG,
        "A platform of 6 cubes in a row, but leave a one-cube gap in the middle for the footpath.",
        k.all_of(k.each(2, k.row(3)), k.layout(k.dims(1, 7))),
    ),
    _c(
        "neg-10",
        NEG,
        "A wall 4 long, 2 high, but not with beams, only with cubes, and not on the right side.",
        one(k.wall(4, 2), k.only_cubes, k.not_(reg("right"), "on the right")),
    ),
    _c(
        "neg-11",
        NEG,
        "Three 2 by 2 blocks in a row, two high, except the middle one, that one only one high.",
        k.any_of(
            k.line(k.block(2, 2, 2), k.block(2, 2, 1), k.block(2, 2, 2)),
            one(k.profile(2, 2, 1, 1, 2, 2)),
        ),
    ),
    _c("neg-12", NEG, "ring 5x5 no roof 1 high", one(k.ring_of(1, (3, 3)), k.dims(5, 5))),
    _c(
        "neg-13",
        NEG,
        "Plate 4 x 4, one layer, omit the two cells at the -Y corners.",
        one(k.plan_heights(".11.", "1111", "1111", "1111"), _heavier(_L)),
    ),
    _c(
        "neg-14",
        NEG,
        "Goods shed without a roof, just the walls: a 4 by 4 square, 2 high.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "buikd a tiwer of 4 pls", one(T(4))),
    _c("typo-02", TYP, "can u make a fridge w/ legs of 2", one(_span(2))),
    _c("typo-03", TYP, "stsircase 3 steos", one(k.staircase(3))),
    _c("typo-04", TYP, "A pyramide with 3 levels.", one(k.pyramid(3))),
    _c("typo-05", TYP, "Bild a tower off 5 kubes.", one(T(5))),
    _c("typo-06", TYP, "colum 150 tal at X400 Y250", one(T(3), k.near(0.40, 0.25, _XY))),
    _c(
        "typo-07",
        TYP,
        "a signall post 3 hgih next to a platfrom of 4",
        k.any_of(k.pair(T(3), k.row(4), k.within(0.15)), one(k.with_column(3, k.row(4)))),
    ),
    _c("typo-08", TYP, "wall 6 lomg 2 hihg", one(k.wall(6, 2))),
    _c("typo-09", TYP, "A brdige, nothing fancy, pillars of 3.", one(_span(3))),
    _c("typo-10", TYP, "Make a walll of 5 cubes long and 3 cubes hight.", one(k.wall(5, 3))),
    _c("typo-11", TYP, "tower of 3 on the kept side", one(T(3), reg("left"))),
    _c("typo-12", TYP, "pyrmaid 2 tiers base 3x3", one(k.pyramid(2), k.base(3, 3))),
    _c("typo-13", TYP, "a brigde over the lne, peirs 2 high", one(_span(2))),
    _c("typo-14", TYP, "2 towes of 5 w/ a cube gap", k.pair(T(5), T(5), k.gap_of(1))),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "On the left side shall the tower stand, 4 cubes high.",
        one(T(4), reg("left")),
    ),
    _c("wo-02", WO, "Z 150, column, at X600 Y400.", one(T(3), k.near(0.60, 0.40, _XY))),
    _c(
        "wo-03",
        WO,
        "3 high 2x2 back right corner block pls",
        one(k.block(2, 2, 3), reg("back right")),
    ),
    _c("wo-04", WO, "Over the line goes the bridge, piers 3 high.", one(_span(3))),
    _c(
        "wo-05",
        WO,
        "Five steps, climbing towards the back — that's the staircase I want.",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c(
        "wo-06",
        WO,
        "Today only the tower you build, with 6 cubes; the wall comes tomorrow.",
        one(T(6)),
    ),
    _c(
        "wo-07",
        WO,
        "Along Y, 4 off, single cubes, 100 pitch.",
        k.in_order("y", T(1), T(1), T(1), T(1), gaps=(1,)),
    ),
    _c(
        "wo-08",
        WO,
        "in front of the tower 5 high put a 2 high one thx",
        k.any_of(
            k.pair(T(2), T(5), k.all_rels(k.on_side(_F), k.within(0.15))),
            one(_col_beside(2, T(5), _F)),
        ),
    ),
    _c(
        "wo-09",
        WO,
        "Behind the platform, the goods shed. Platform: 5 in a row. Shed: 2 by 3, two high.",
        k.pair(k.block(2, 3, 2), k.row(5), k.all_rels(k.on_side(_B), k.within(0.15))),
    ),
    _c(
        "wo-10",
        WO,
        "Three levels should the pyramid have, and stand in the middle.",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "wo-11",
        WO,
        "Left, a tower of 3. Right, a tower of 3. Middle, nothing.",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "wo-12",
        WO,
        "At X350 Y450 place: slab, 3 x 3, 1 layer.",
        one(k.block(3, 3, 1), k.near(0.35, 0.45, _XY)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Okay so the board's coming through at ten and honestly they just want to see the arm "
        "move. Can we do a tower of six? That'll do.",
        one(T(6)),
    ),
    _c(
        "fil-02",
        FIL,
        "hey 👋 sorry typing w/ one hand lol. wall 4 long 2 high pls 🙏 thx!!",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Morning. Coffee machine's broken again. Anyway: block, 2 x 3, two layers, no rush.",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "fil-04",
        FIL,
        "Ah, this takes me back to my dad's layout up in the loft, he had a lovely old Hornby "
        "set. Anyway, a signal post 5 cubes tall, please.",
        one(T(5)),
    ),
    _c(
        "fil-05",
        FIL,
        "Hello! Nice weather today, finally some sun after the long winter. Could you please "
        "make a pyramid with 2 levels?",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-06",
        FIL,
        "Look, I'm not an engineer, I just sign the cheques, but I'm told it can do stairs. Four "
        "steps, let's see it.",
        one(k.staircase(4)),
    ),
    _c("fil-07", FIL, "omw to lunch 🍕 bridge legs 3 pls ty", one(_span(3))),
    _c(
        "fil-08",
        FIL,
        "Per the traveller, rev C, which nobody has signed off yet: column, 250 tall. That's "
        "the whole job.",
        one(T(5)),
    ),
    _c(
        "fil-09",
        FIL,
        "Right, the 4.15 from Crewe is running late again, so while we wait: a platform, a row "
        "of 5 cubes, please.",
        one(k.row(5)),
    ),
    _c(
        "fil-10",
        FIL,
        "Sorry for my bad English, I am still learning. Can you build a tower with 3 cubes in "
        "the back?",
        one(T(3), reg("back")),
    ),
    _c(
        "fil-11",
        FIL,
        "Quick one before my next meeting: two towers of four, side by side with a gap, "
        "whatever gap looks right. Cheers.",
        k.pair(T(4), T(4), k.within(0.20)),
    ),
    _c("fil-12", FIL, "ok ok ok. so. 3x3 slab. thats it. ty ❤️", one(k.block(3, 3, 1))),
    _c(
        "fil-13",
        FIL,
        "Spindle's still warming up, so: wall, L200 H100, cubes only, no beams.",
        one(k.wall(4, 2), k.only_cubes),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Put a tower of 4 at the back where the cameras can see it.",
        one(T(4), reg("back")),
    ),
    _c("reg-02", REG, "tower 3 front right corner pls", one(T(3), reg("front right"))),
    _c("reg-03", REG, "Column 100 tall at X700 Y100.", one(T(2), k.near(0.70, 0.10, _XY))),
    _c(
        "reg-04",
        REG,
        "A platform, a row of 6, right along the back edge of the baseboard.",
        one(k.row(6), k.runs("y"), k.min_x(0.65)),
    ),
    _c(
        "reg-05",
        REG,
        "Put it on the left side of the table please, a wall with 4 cubes long and 2 high.",
        one(k.wall(4, 2), reg("left")),
    ),
    _c(
        "reg-06",
        REG,
        "Datum is the front left corner of the work area. Column, 150 tall, 100 in from both "
        "edges.",
        one(T(3), k.near(0.3125, 0.4375, 0.02)),  # 100 in to the centre or to the edge
    ),
    _c("reg-07", REG, "pyramid 2 lvls dead centre pls", one(k.pyramid(2), reg("centre"))),
    _c(
        "reg-08",
        REG,
        "Goods shed in the back left corner: a 2 by 2 block, 2 high.",
        one(k.block(2, 2, 2), reg("back left")),
    ),
    _c(
        "reg-09",
        REG,
        "A staircase with 3 steps in the right front corner.",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "reg-10",
        REG,
        "Keep everything on the right half, the left half is where the forklift goes. A wall "
        "of 5, 2 high.",
        one(k.wall(5, 2), _max_y(0.30)),
    ),
    _c("reg-11", REG, "tower 5 at the far back left pls", one(T(5), reg("back left"))),
    _c(
        "reg-12",
        REG,
        "Slab 2 x 2, front edge at X250, centred on Y300.",
        one(k.block(2, 2, 1), _front_edge(0.25), k.near(y=0.30, tol=_XY)),
    ),
    _c(
        "reg-13",
        REG,
        "Signal post 4 high right at the front, on the right where the line comes in.",
        one(T(4), reg("front right")),
    ),
    _c(
        "reg-14",
        REG,
        "Put the pyramid with 2 levels in the middle of the back side.",
        one(k.pyramid(2), reg("back"), k.near(y=0.30, tol=0.05)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "We need something like a gate for the demo, two posts and a top, nothing fancy.",
        k.all_of(k.anything, one(_span())),
    ),
    _c(
        "open-02",
        OPEN,
        "Build something that shows off what it can do. Your call, but keep it under 30 cm tall.",
        k.all_of(k.anything, k.layout(k.low(6))),
    ),
    _c("open-03", OPEN, "idk something cool? surprise me 😎", k.anything),
    _c(
        "open-04",
        OPEN,
        "A little station scene for the layout, whatever you think fits, at least two pieces.",
        k.all_of(k.anything, _count(2, 99)),
    ),
    _c(
        "open-05",
        OPEN,
        "Can you make some kind of building? I don't mind which one.",
        k.all_of(k.anything, k.layout(k.height(lo=2))),
    ),
    _c(
        "open-06",
        OPEN,
        "Any fixture you like, footprint no bigger than 100 x 100.",
        k.all_of(k.anything, k.layout(_fits(2, 2))),
    ),
    _c(
        "open-07",
        OPEN,
        "Something tall-ish for the lobby photo, as long as it doesn't fall over.",
        k.all_of(k.anything, k.layout(k.height(lo=4))),
    ),
    _c(
        "open-08",
        OPEN,
        "make smth w/ exactly 10 cubes any shape",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(10), k.only_cubes))),
    ),
    _c(
        "open-09",
        OPEN,
        "A bridge of some sort for the branch line, any size.",
        k.all_of(k.anything, one(_ARCH)),
    ),
    _c(
        "open-10",
        OPEN,
        "Please build two things, you can choose what, but not too big, under 5 cubes high.",
        k.all_of(k.anything, _count(2), k.layout(k.low(4))),
    ),
    _c(
        "open-11",
        OPEN,
        "Qty 3, any part, your choice, spaced out along X.",
        k.all_of(k.anything, k.in_order("x", _any, _any, _any)),
    ),
    _c(
        "open-12",
        OPEN,
        "Something symmetrical for the brochure cover, doesn't matter what.",
        k.all_of(k.anything, k.layout(_symmetric)),
    ),
    _c(
        "open-13",
        OPEN,
        "Something for the end of the siding, a buffer stop or whatever you can manage, no more "
        "than 2 high.",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "😂😂😂👍", k.honest()),
    _c("bad-02", BAD, "ok so jdjdjsksks hfhfh", k.honest()),
    _c("bad-03", BAD, "Bygg ett torn med fyra kuber, tack.", k.honest(one(T(4)))),
    _c(
        "bad-04",
        BAD,
        "Rakenna kolmen kuution torni vasemmalle puolelle.",
        k.honest(one(T(3), reg("left"))),
    ),
    _c(
        "bad-05",
        BAD,
        "Kan du lage en mur som er fem lang og to høy?",
        k.honest(one(k.wall(5, 2))),
    ),
    _c(
        "bad-06",
        BAD,
        "Column, 750 mm tall.",  # 15 cube levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-07",
        BAD,
        "Slab 1000 x 200 x 50.",  # 20 cubes long: longer than the workspace either way
        k.honest(k.anything),
    ),
    _c(
        "bad-08",
        BAD,
        "Lay three metres of track round the loft with a tunnel at each end.",
        k.honest(k.anything),
    ),
    _c(
        "bad-09",
        BAD,
        "A level crossing with working barriers that lift when the train comes through.",
        k.honest(k.anything),
    ),
    _c(
        "bad-10",
        BAD,
        "Make it tall but keep it flat: one layer only, and at least six high.",
        k.honest(k.anything),
    ),
    _c(
        "bad-11",
        BAD,
        "2 towers of 3 but it has to be 1 single structure and they cant touch",
        k.honest(k.anything),
    ),
    _c(
        "bad-12",
        BAD,
        "Build a tower with 4 cubes high and at the same time 7 cubes high.",
        k.honest(one(k.any_of(T(4), T(7)))),
    ),
    _c(
        "bad-13",
        BAD,
        "Column at X900 Y300, 100 tall.",  # x 0.90: beyond the back of the workspace
        k.honest(one(T(2))),
    ),
    _c("bad-14", BAD, "Build the whole production line for the demo.", k.honest(k.anything)),
    _c("bad-15", BAD, "??", k.honest()),
    _c("bad-16", BAD, "G01 X100 Y50 F300", k.honest()),
    _c("bad-17", BAD, "A model of the Forth Bridge, to scale.", k.honest(k.anything)),
    _c(
        "bad-18",
        BAD,
        "Please build a tower with 12 cubes high.",  # 12 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-19", BAD, "tower of -3 pls", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-20",
        BAD,
        "Make the same tower as we did yesterday again.",
        k.honest(k.anything),
    ),
]
