"""A thirty-fifth held-out set for the language front end (dev35): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set (but dev27, the format example) or any benchmark
result, and worded apart from `language_dev` … `language_dev33` (no command shared with any
set, see tests). Nothing here was run through the system while it was written. The set is
deliberately mainstream: about 80 % of the commands are ordinary — one or two structures with
a size, a place, one relation or a two-step sequence, in plain but varied English, as real
operators type them — and they come from five kinds of people, none of them used by an
earlier set. Three of the five voices first asked for had been used already and were swapped
for fresh ones, and one was narrowed to its new part:

* a newcomer on their first day who does not know the names of the shapes and describes each
  by what it looks like: "like a letter L", "like a capital T", "like the number 7 lying
  down", "a plus sign", "like an equals sign", "like the letter n", "like a picture frame",
  "stairs like in a stadium", "like a domino standing on its end". (dev26 already had a
  first-day hire hedging over the names; only the new part — shapes named by the letter,
  digit, sign or familiar thing they look like — is kept.) A letter or a sign "lying flat" or
  "on the table" is its footprint, one cube high: an L (either hand, so a 7 lying down is an
  L), a T, a U, a plus sign (the shared `shape_letter`, or the exact plan for a plus "N across
  each way", its arms meeting in the middle), an H (two parallel bars joined at their middles);
  an L "standing up" is one cube thick in a vertical plane, a full column at one end of a
  one-high row; a T's stem "N below" the bar is counted beyond the bar, or with the bar's cell
  where the wording allows both; the letter n, an upside-down U or a football goal is two
  posts with something across the tops; a picture frame, a doughnut or "a square with a hole"
  is a ring; a minus sign is a row; an equals sign is two parallel rows with a clear gap;
  stadium steps are a staircase; a chimney is a tower; a domino standing on its end is a wall
  one cube thick. A ball, a true circle, a shape with no name at all and a half-typed command
  are bad input;
* a landscape gardener who talks garden words (in place of the project manager writing
  acceptance criteria: "Given … when … then" stories and acceptance bullets were dev25's
  product owner's and dev17's quality engineer's). A raised bed is a ring (its size the
  outside, one cube high unless said); edging is a row, one cube high; a path is a row one
  cube wide; a retaining wall is a wall; a patio is a one-layer slab; stepping stones are
  single cubes standing apart; a post, an obelisk or a marker post is a tower; a planter "a
  single cube" is one cube; a pergola is four separate posts under one connected top of beams
  or of cubes ("beams laid across the top" is the cell's beam roof, the shared `beam_roof`;
  "cubes only for the top" a top of cubes). "The far end away from the robot" is the back.
  Planting and watering are not builds (refusal only); digging a pond and a bed past the
  cell are bad input;
* an operator who states the goal in one sentence and the constraint in the next ("Build a
  tower of five. Don't put it on the right side.", "Two towers side by side. Make the left one
  the taller of the two."). The second sentence adds to the first or changes it; "no taller
  than 15 cm" is at most three cubes; "the taller of the two" is at least one cube taller; a
  constraint that contradicts the goal (a tower of eight kept under 20 cm, a pyramid whose top
  is bigger than its bottom), a length past the cell and a cancelled request are bad input
  (the last admits only the refusal);
* an operator from Singapore or Malaysia writing Singapore / Malaysian English (in place of
  the French / Italian / Portuguese speaker: French and Italian patterns were dev17's and
  dev24's, Portuguese dev21's): "one" as the article ("build one tower four cube"), plural -s
  dropped ("two tower", "three level"), "can?" / "can build or not?" (a request), "also can"
  (either is fine), "don't want" (not), "take out" (remove), "already" (done: "after finish
  already"), "the short one" (a reference), "in the right part of the table" (the right
  region), "near the robot side" (the front), "lah", "ah", "aiyo", "wah" (particles, filler).
  "Aiyo, forget it" cancels the request and a question about the gripper asks for no build
  (both refusal only); "same like last time" and half cubes are bad input;
* a graphic / UI designer laying out the table like a page (in place of the quality engineer
  asking for test builds with tolerances: the quality inspector with tolerances was dev9's,
  dev17's and dev24's). A "gutter" is the clear gap between neighbours; a "margin" is the clear
  distance from the workspace's edge to the nearest part (± 2 cm); "centre-align" lines the
  footprint centres up (± 3 cm); "right-aligned" rows have their right-hand ends in line
  (± 1.5 cm), "on the same baseline" their front faces; "horizontal" is left to right;
  "width" runs left to right (y) and "depth" front to back (x); "distributed" / "evenly
  spaced" with a gutter given is that clear gap between every pair of neighbours; "mirrored
  left and right of the centre line" / "symmetric about the centre line" is a layout that is
  its own mirror image across y = 0.30 (± 1.5 cm), and "mirror it to the back right" puts the
  copy at the mirror position (± 2 cm); "hugging" an edge is along it; "the centre point of the
  table" is the centre region's (0.45, 0.30) or the workspace's middle (0.50, 0.30), ± 2 cm.
  A position off the table, "make it pop" and exporting a PDF (not a build: refusal only) are
  bad input.

About 80 % ordinary and 20 % harder: three or more structures (up to a 3 × 3 grid),
references ("the tall one", "the short one", "the second one from the left"), distributive
phrases ("a post at each end", "a cube at every corner", "both arms four", "one cube of space
between each"), removals ("take the tall one away", "take out the middle one", "take the top
step away"), corrections in the same message ("Oh wait, I think four", "Wait ah sorry, put on
the right side instead") and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by its
  columns); "right next to it" is at most 10 cm clear, or touching; "not touching", "don't
  want touching", "apart", "a gap" mean separate structures; "must touch" makes them one;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none is
  said, the two kept separate; "directly in front of its middle" may also stand against it,
  and lines the centres up (± 3 cm); "a post at each end" of a row stands on the end cubes,
  makes the end columns that high, or stands just past each end, touching or clear (at most
  25 cm) and in line with the row;
* "N cubes apart" / "a cube's gap" / "one cube space" / "an N cm gutter" / "the space between
  them N cm" is the clear gap (± 1.5 cm); "N cm apart centre to centre" is between footprint
  centres; "parallel" is the same long axis, facing each other across the gap;
* a bridge's top is a beam (the shared `bridge`, overall height one more than the posts) where
  the command names a beam, and a beam or a bar of cubes where it does not; "no beam — just
  cubes across the top" is a bar of cubes only;
* a ring's stated size is its outside; "in the middle of" / "in the hole in the middle" of a
  ring is inside its empty interior, clear of the ring, with the centres within 3 cm;
* a staircase's width is free unless given, and so is the way it climbs unless said; "the
  high side don't want near the robot" is any staircase not climbing towards the front;
  "take the top step away" from five steps accepts four steps or the top cube off (heights 1,
  2, 3, 4, 4); a pyramid's step is free unless the base and levels fix it;
* "a tower of three on the corner where the arms meet" of a flat L makes that corner column
  four high (standing on it) or three high; "a planter in one corner" of a slab stands on a
  corner cell; "a tower standing in the very middle" of a flat plus sign makes the middle
  column five high or four;
* "any size", "whatever you like" leave everything but what is said free; "something with an
  opening underneath" is anything spanning a gap; "something that looks like steps" is a
  staircase or a pyramid; "anything that looks like a table" is four separate legs under one
  connected top; "no more than ten cube" counts cubes (beams not counted);
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the back edge" is every part at x ≥ 0.60, "the back half" every part at x ≥ 0.50,
  "the left half" every part at y ≥ 0.30, "against the right-hand edge" / "hugging the right
  edge" a footprint centre at y ≤ 0.15 and "hugging the left edge" one at y ≥ 0.45, "the centre
  line" y = 0.30 ± 3 cm; a stated coordinate is the footprint centre ± 2 cm.

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

_CENTRE_Y = 0.30  # m: the centre line of the table, running front to back
_EDGE = {_F: (0, 0.20), _B: (0, 0.80), _R: (1, 0.05), _L: (1, 0.55)}  # axis, workspace edge


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev35-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _free(bs: k.Boxes) -> k.Reason:
    """Any structure at all ("an object of your choice")."""
    return None if bs else "no parts"


def _any_rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """No relation asked for between A and B."""
    return None


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


def _span(posts: int, mouth: int | None = None) -> k.Check:
    """A bridge with no beam named: two posts `posts` high with a beam (one layer above the
    posts) or a bar of cubes across the tops; `mouth` cubes apart clear when given."""
    return k.any_of(_beam_bridge(posts, mouth), _bar_on_posts(posts, posts, mouth))


def _roof_on(legs: int, leg_h: int | None) -> k.Check:
    """`legs` separate legs, each a full column on the table `leg_h` cubes high (any height
    when None), under one connected top that is the topmost level and rests on every leg (a
    top of beams or of cubes, whose middle cubes rest on nothing)."""

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
            r = k.on_table(g) or k.full(g) or (k.height(leg_h)(g) if leg_h else None)
            if r:
                return f"leg: {r}"
            if not any(bx.rests_on(p, q) for p in roof for q in g):
                return "the top does not rest on every leg"
        return None

    return f


def _roofed(legs: int, leg_h: int) -> k.Check:
    """A pergola or table on `legs` legs `leg_h` high: the shared `canopy` one layer above the
    legs, a top of cubes, or the cell's beam roof."""
    return k.any_of(
        k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1)),
        _roof_on(legs, leg_h),
        k.beam_roof(legs, leg_h),
    )


def _col_beside(h: int, rest: k.Check, side: str, mid: float | None = None) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table, set against the rest,
    which passes `rest`; the column lies to `side` of the rest and, with `mid`, its centre is
    within `mid` m of the rest's centre across that direction."""

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
            if r is None and mid is not None:
                axis = 1 if side in (_F, _B) else 0
                off = abs(bx.centre(col)[axis] - bx.centre(others)[axis])
                r = None if off <= mid else f"the column is {off:.3f} m off the middle"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column against the rest"

    return f


def _facing_mid(tol: float = 0.03) -> k.Rel:
    """A stands square in front of (or behind, or beside) the middle of B: their centres line
    up across the direction from B to A, ± tol."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (ax, ay), (bx0, by0) = bx.centre(a), bx.centre(b)
        off = abs(ay - by0) if bx.side_of(a, b) in (_F, _B) else abs(ax - bx0)
        return None if off <= tol else f"{off:.3f} m off the middle"

    return rel


def _taller(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A is at least one cube taller than B."""
    ha, hb = bx.thickness_cubes(a), bx.thickness_cubes(b)
    return None if ha > hb else f"{ha} cubes high, not taller than {hb}"


def _two_cols(a: k.Check, b: k.Check, rel: k.Rel) -> k.Check:
    """One structure of exactly two columns set against each other, each standing on the
    table; one passes `a`, the other `b`, and rel(A, B) holds (two towers touching)."""

    def f(bs: k.Boxes) -> k.Reason:
        cols = bx.columns(bs)
        if len(cols) != 2:
            return f"{len(cols)} columns, want 2"
        first: k.Reason = None
        for p, q in ((cols[0], cols[1]), (cols[1], cols[0])):
            r = k.on_table(p) or k.on_table(q) or a(p) or b(q) or rel(p, q)
            if r is None:
                return None
            first = first or r
        return first

    return f


def _flush(side: str, tol: float = 0.015) -> k.Rel:
    """A's and B's `side` faces are in line (± tol): "right-aligned" rows end at the same
    right-hand y, things "on the same baseline" have their front faces at the same x."""
    axis = 0 if side in (_F, _B) else 1
    hi = side in (_B, _L)

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        ea = bx.bounds(a)[1 if hi else 0][axis]
        eb = bx.bounds(b)[1 if hi else 0][axis]
        return None if abs(ea - eb) <= tol else f"{side} faces {abs(ea - eb):.3f} m out of line"

    return rel


def _mirror(y0: float | None = _CENTRE_Y, tol: float = 0.015) -> k.Check:
    """The boxes are their own mirror image left to right — part for part (± tol), or cube
    cell for cube cell — about their own middle, which lies on y = `y0` (± tol) unless `y0`
    is None."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        (_, ylo, _), (_, yhi, _) = bx.bounds(bs)
        mid = (ylo + yhi) / 2
        if y0 is not None and abs(mid - y0) > tol:
            return f"mirror line at y {mid:.3f}, want {y0} ± {tol}"
        corners = [(*b.lo, *b.hi) for b in bs]

        def image(b: bx.Box) -> tuple[float, ...]:
            return (b.lo[0], 2 * mid - b.hi[1], b.lo[2], b.hi[0], 2 * mid - b.lo[1], b.hi[2])

        def has(p: tuple[float, ...]) -> bool:
            return any(all(abs(u - v) <= tol for u, v in zip(p, c, strict=True)) for c in corners)

        if all(has(image(b)) for b in bs):
            return None
        vox = bx.voxels(bs)
        fy = bx.footprint_cubes(bs)[1]
        if {(i, fy - 1 - j, z) for i, j, z in vox} == vox:
            return None
        return "not a mirror image of itself left to right"

    return f


def _lines(values: list[float], tol: float = 0.01) -> list[float]:
    """The distinct values (those within `tol` of the one before merged), ascending."""
    groups: list[list[float]] = []
    for v in sorted(values):
        if groups and v - groups[-1][-1] <= tol:
            groups[-1].append(v)
        else:
            groups.append([v])
    return [sum(g) / len(g) for g in groups]


def _nearest(values: list[float], v: float) -> int:
    return min(range(len(values)), key=lambda n: abs(values[n] - v))


def _grid(a: int, b: int, check: k.Check, gap: int) -> k.Pred:
    """a × b separate structures (either way round), each passing `check`, their footprint
    centres on a full rectangular grid, every pair of grid neighbours `gap` cubes apart clear
    (± 1.5 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != a * b:
            return f"{len(comps)} separate structures, want {a * b}"
        for g in comps:
            r = check(g)
            if r:
                return r
        centres = [bx.centre(g) for g in comps]
        xs = _lines([c[0] for c in centres])
        ys = _lines([c[1] for c in centres])
        if sorted((len(xs), len(ys))) != sorted((a, b)):
            return f"not a {a} × {b} grid: {len(xs)} lines by {len(ys)}"
        at = {
            (_nearest(xs, cx), _nearest(ys, cy)): g
            for g, (cx, cy) in zip(comps, centres, strict=True)
        }
        if len(at) != a * b:
            return "two structures on one grid point"
        for (i, j), g in at.items():
            for nb in ((i + 1, j), (i, j + 1)):
                h = at.get(nb)
                if h is None:
                    continue
                gap_m = bx.separation(g, h)
                if abs(gap_m - gap * bx.CUBE) > 0.015:
                    return f"grid neighbours {gap_m:.3f} m apart, want {gap} cube(s)"
        return None

    return f


def _margin(edge: str, d: float, tol: float = 0.02) -> k.Check:
    """The nearest face is `d` m (± tol) in from the workspace's `edge`."""
    axis, e = _EDGE[edge]

    def f(bs: k.Boxes) -> k.Reason:
        lo, hi = bx.bounds(bs)
        gap = lo[axis] - e if edge in (_F, _R) else e - hi[axis]
        return None if abs(gap - d) <= tol else f"{gap:.3f} m from the {edge} edge, want {d}"

    return f


def _y_range(lo: float | None = None, hi: float | None = None) -> k.Check:
    """Every part between y = lo and y = hi (m): "the left half" is lo = 0.30."""

    def f(bs: k.Boxes) -> k.Reason:
        (_, ylo, _), (_, yhi, _) = bx.bounds(bs)
        if lo is not None and ylo < lo - bx.TOL:
            return f"a part reaches y {ylo:.3f}, want ≥ {lo}"
        if hi is not None and yhi > hi + bx.TOL:
            return f"a part reaches y {yhi:.3f}, want ≤ {hi}"
        return None

    return f


def _centre_y_max(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m): over to the right."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


def _in_a_row(axis: str, tol: float = 0.03) -> k.Pred:
    """Every separate structure's footprint centre on one straight line along `axis` ("y":
    left to right), the other coordinate within `tol` of each other."""
    other = 1 if axis == "x" else 0

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        vals = [bx.centre(g)[other] for g in comps]
        spread = max(vals) - min(vals)
        return None if spread <= tol else f"centres {spread:.3f} m out of one straight line"

    return f


def _near_any(xs: tuple[float, ...], ys: tuple[float, ...], tol: float = 0.02) -> k.Check:
    """The footprint centre within `tol` of one of the x values and one of the y values (an
    empty tuple leaves that axis free)."""

    def f(bs: k.Boxes) -> k.Reason:
        cx, cy = bx.centre(bs)
        if xs and all(abs(cx - x) > tol for x in xs):
            return f"centre x {cx:.3f}, want one of {xs} ± {tol}"
        if ys and all(abs(cy - y) > tol for y in ys):
            return f"centre y {cy:.3f}, want one of {ys} ± {tol}"
        return None

    return f


def _frame_gap(side: str) -> k.Check:
    """A one-cell-wide frame — every occupied cell on the footprint's border — with exactly one
    border cell left empty, on its `side` edge (front = smallest x, left = largest y)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        cs = bx.cells(bs)
        fx, fy = bx.footprint_cubes(bs)
        border = {
            (i, j) for i in range(fx) for j in range(fy) if i in (0, fx - 1) or j in (0, fy - 1)
        }
        if cs - border:
            return "cells filled inside the frame"
        missing = border - cs
        if len(missing) != 1:
            return f"{len(missing)} border cells empty, want 1"
        ((i, j),) = missing
        on = {_F: i == 0, _B: i == fx - 1, _R: j == 0, _L: j == fy - 1}[side]
        return None if on else f"the gap is not in the {side} side"

    return f


def _full_edge(side: str, n: int) -> k.Check:
    """The footprint's `side` edge line holds `n` occupied cells (a T's bar at the front)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        fx, fy = bx.footprint_cubes(bs)
        want = {_F: (0, 0), _B: (0, fx - 1), _R: (1, 0), _L: (1, fy - 1)}[side]
        got = sum(1 for c in bx.cells(bs) if c[want[0]] == want[1])
        return None if got == n else f"{got} cells along the {side} edge, want {n}"

    return f


def _l_upright(bs: k.Boxes) -> k.Reason:
    """An L standing up in a vertical plane: one cube thick, a full column at one end of a
    one-high row (slice heights h, 1, …, 1 with h ≥ 2, either way round)."""
    if not bs:
        return "no parts"
    fx, fy = bx.footprint_cubes(bs)
    if min(fx, fy) != 1 or max(fx, fy) < 2:
        return f"footprint {fx}×{fy}, not one cube thick and two or more long"
    prof = bx.step_profile(bs, 0 if fx > fy else 1)
    if prof[-1] > prof[0]:
        prof = prof[::-1]
    if prof[0] < 2 or any(p != 1 for p in prof[1:]):
        return f"slice heights {prof}, not an L standing up"
    return None if len(bx.voxels(bs)) == sum(prof) else "columns not full"


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


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_TABLE = k.any_of(k.canopy(4), _roof_on(4, None))  # four legs under one top, any size
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_PLUS3 = k.plan_heights(".1.", "111", ".1.")
_PLUS5 = k.plan_heights("..1..", "..1..", "11111", "..1..", "..1..")
_CORNERS = ("back left", "back right", "front left", "front right")


def _flat_letter(kind: str, *sizes: tuple[int, int]) -> k.Check:
    """A letter lying flat: its footprint the letter `kind`, one cube high, the footprint one
    of `sizes` (any size when none)."""
    size = k.any_of(*[k.dims(a, b) for a, b in sizes]) if sizes else _free
    return k.all_of(k.shape_letter(kind), k.height(1), size)


def _row_y(n: int) -> k.Check:
    return k.all_of(k.row(n), k.runs("y"))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Build a tower of five. Put a tower of two right next to it, on its left.",
        k.any_of(
            k.pair(T(2), T(5), k.all_rels(k.within(0.10), k.on_side(_L))),
            one(_col_beside(2, T(5), _L)),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "I need a pyramid with three levels in the centre. A tower of four goes in front of it, "
        "not touching.",
        k.pair(T(4), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_F)),
    ),
    _c(
        "rel-03",
        REL,
        "Make a wall six long and two high across the back. Add a tower of three directly in "
        "front of its middle.",
        k.any_of(
            k.pair(
                T(3),
                k.all_of(k.wall(6, 2), k.runs("y"), reg("back")),
                k.all_rels(k.on_side(_F), _facing_mid()),
            ),
            one(_col_beside(3, k.all_of(k.wall(6, 2), k.runs("y"), reg("back")), _F, mid=0.03)),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "Two towers side by side. Make the left one the taller of the two.",
        k.any_of(
            k.pair(T(lo=1), T(lo=1), k.all_rels(k.on_side(_L), _taller, k.within(0.25))),
            one(_two_cols(T(lo=1), T(lo=1), k.all_rels(k.on_side(_L), _taller))),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "I'd like something that looks like the letter n — two towers of three with a beam laid "
        "across the top of them.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-06",
        REL,
        "Make a square like a picture frame, four by four, one high, and put a tower of three "
        "just to the right of it, not touching.",
        k.pair(T(3), _PEN4, k.all_rels(k.on_side(_R), k.within(0.25))),
    ),
    _c(
        "rel-07",
        REL,
        "A plus sign lying flat, five cubes across each way, with a tower of four standing in "
        "the very middle of it.",
        one(
            k.any_of(
                k.plan_heights("..1..", "..1..", "11511", "..1..", "..1.."),
                k.plan_heights("..1..", "..1..", "11411", "..1..", "..1.."),
            )
        ),
    ),
    _c(
        "rel-08",
        REL,
        "Make two rows of five lying side by side like an equals sign, with one cube of space "
        "between them.",
        k.pair(k.row(5), k.row(5), k.parallel_gap(1)),
    ),
    _c(
        "rel-09",
        REL,
        "Build a raised bed, five by five and one high, with a tower of three in the middle of it "
        "as an obelisk.",
        k.pair(_PEN5, T(3), k.centred_in(0.03)),
    ),
    _c(
        "rel-10",
        REL,
        "A pergola, please: four posts, each two cubes high, with beams laid across the top.",
        one(k.beam_roof(4, 2)),
    ),
    _c(
        "rel-11",
        REL,
        "Lay an edging row of five across the front, with a post two cubes high at each end.",
        k.any_of(
            one(
                k.flat,
                k.runs("y"),
                reg("front"),
                k.any_of(
                    k.profile(3, 1, 1, 1, 3),
                    k.profile(2, 1, 1, 1, 2),
                    k.profile(2, 1, 1, 1, 1, 1, 2),
                ),
            ),
            k.all_of(
                k.in_order("y", T(2), _row_y(5), T(2), max_gap=0.25),
                _in_a_row("y"),
                k.layout(reg("front")),
            ),
        ),
    ),
    _c(
        "rel-12",
        REL,
        "Put a retaining wall five long and three high along the back, and a row of five cubes as "
        "edging in front of it, a cube's gap between.",
        k.pair(
            k.row(5),
            k.all_of(k.wall(5, 3), k.runs("y"), reg("back")),
            k.all_rels(k.parallel_gap(1), k.on_side(_F)),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Build one wall five long three high, then put one tower of four behind the wall. Don't "
        "want touching ah.",
        k.pair(T(4), k.wall(5, 3), k.on_side(_B)),
    ),
    _c(
        "rel-14",
        REL,
        "Make one slab 3 by 3 at the right side, then put one cube on top, must be centre, can?",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1), reg("right")),
    ),
    _c(
        "rel-15",
        REL,
        "Two tower five cube high, put side by side, in between leave one cube space lah.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "rel-16",
        REL,
        "Make one bridge for me — the leg two cube high, on top use the long beam, between the "
        "legs one cube space.",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "rel-17",
        REL,
        "Two towers of four, mirrored left and right of the centre line, with a 10 cm gutter "
        "between them.",
        k.all_of(k.pair(T(4), T(4), k.gap_of(2)), k.layout(_mirror())),
    ),
    _c(
        "rel-18",
        REL,
        "Centre-align a tower of five behind a row of six that runs left to right, 5 cm gap "
        "between them.",
        k.pair(T(5), _row_y(6), k.all_rels(k.gap_of(1, _B), _facing_mid())),
    ),
    _c(
        "rel-19",
        REL,
        "Three towers — heights three, two, three — distributed left to right with 5 cm gutters, "
        "the short one in the middle.",
        k.in_order("y", T(3), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "rel-20",
        REL,
        "Two rows running left to right, six cubes in front and four cubes behind, right-aligned, "
        "with one cube of space between them.",
        k.pair(
            _row_y(4),
            _row_y(6),
            k.all_rels(k.parallel_gap(1), k.on_side(_B), _flush(_R)),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Build a tower of six at the back left. Then make it two cubes shorter.",
        one(T(4), reg("back left")),
    ),
    _c(
        "seq-02",
        SEQ,
        "Build a wall five long and two high. After that, add a third layer on top of it.",
        one(k.wall(5, 3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Start with a 3 by 3 slab in the middle. Next, a 2 by 2 layer on it, and finally one cube "
        "on the very top.",
        one(k.pyramid_counts(9, 4, 1), reg("centre")),
    ),
    _c(
        "seq-04",
        SEQ,
        "Build two towers, one of five and one of two, with a cube's gap. Take the tall one away "
        "afterwards.",
        one(T(2)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Make an L shape flat on the table, both arms four cubes long. Then stand a tower of "
        "three on the corner where the arms meet.",
        one(
            k.any_of(
                k.plan_heights("4111", "1...", "1...", "1..."),
                k.plan_heights("3111", "1...", "1...", "1..."),
            )
        ),
    ),
    _c(
        "seq-06",
        SEQ,
        "First a row of five, flat like a minus sign, running left to right. Then add two cubes "
        "going back from the middle cube, so it looks like a T.",
        one(_flat_letter("T", (5, 3)), _full_edge(_F, 5)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Build stairs like the ones in a stadium, five steps. Then take the top step away.",
        one(k.any_of(k.staircase(4), k.profile(1, 2, 3, 4, 4))),
    ),
    _c(
        "seq-08",
        SEQ,
        "Make a tall thin tower like a chimney, six cubes. Oh wait, I think four would look "
        "better.",
        one(T(4)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Lay a patio slab four by three, one layer. Then put a planter on it — a single cube — "
        "in one corner.",
        one(k.plan_heights("2111", "1111", "1111")),
    ),
    _c(
        "seq-10",
        SEQ,
        "Put in a row of edging six cubes long across the front. Then take the two cubes off the "
        "left end.",
        one(_row_y(4), reg("front")),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build the raised bed four by four, one high. Now make it one cube taller all round.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Make three stepping stones in a line left to right, a cube apart. Then take out the "
        "middle one.",
        k.pair(T(1), T(1), k.gap_of(3)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Build one tower six cube first, after that take out two from the top.",
        one(T(4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Make one row of four going left to right. After finish already, put one more row of "
        "four behind it, must touch.",
        one(k.block_xy(2, 4, 1)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Build one pyramid three level on the left. Wait ah sorry, put on the right side instead.",
        one(k.pyramid(3), reg("right")),
    ),
    _c(
        "seq-16",
        SEQ,
        "First build two tower, one three cube one five cube, one cube apart. Then the short one "
        "add two more cube on top.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Place a row of five along the front, centred on the centre line. Then duplicate it "
        "directly behind with a 5 cm gutter.",
        k.all_of(
            k.pair(_row_y(5), _row_y(5), k.all_rels(k.parallel_gap(1), _facing_mid())),
            k.some(k.row(5), reg("front")),
            k.layout(k.near(y=_CENTRE_Y, tol=0.03)),
        ),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build a tower of three at the back left. Then mirror it to the back right.",
        k.all_of(
            k.structures(k.all_of(T(3), reg("back left")), k.all_of(T(3), reg("back right"))),
            k.layout(_mirror(tol=0.02)),
        ),
    ),
    _c(
        "seq-19",
        SEQ,
        "Lay out a 2 by 4 slab, one layer. Then increase its height to three layers.",
        one(k.block(2, 4, 3)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Three towers of two in a row left to right, 5 cm gutters. Then make the second one from "
        "the left four high.",
        k.in_order("y", T(2), T(4), T(2), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Build three towers. Each one should be four cubes tall.",
        k.each(3, T(4)),
    ),
    _c("num-02", NUM, "Make a staircase. It needs seven steps.", one(k.staircase(7))),
    _c(
        "num-03",
        NUM,
        "Build a pyramid with a 4 by 4 base. Give it four levels.",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "num-04",
        NUM,
        "Put up two walls. Both should be four long and three high, and they must not touch.",
        k.each(2, k.wall(4, 3)),
    ),
    _c(
        "num-05",
        NUM,
        "Could you make something like a capital L lying flat on the table, with both arms four "
        "cubes long?",
        one(_flat_letter("L", (4, 4))),
    ),
    _c(
        "num-06",
        NUM,
        "Could you build a plus sign out of five cubes, lying flat?",
        one(_PLUS3),
    ),
    _c(
        "num-07",
        NUM,
        "I want stairs like at a stadium, three steps, and each step three cubes wide.",
        one(k.staircase(3), k.dims(3, 3)),
    ),
    _c(
        "num-08",
        NUM,
        "Make a shape like the letter H lying flat: two rows of three with one cube joining them "
        "in the middle.",
        one(k.plan_heights("111", ".1.", "111")),
    ),
    _c(
        "num-09",
        NUM,
        "Six stepping stones in a line from front to back, one cube of space between each.",
        k.in_order("x", *[T(1)] * 6, gaps=(1,)),
    ),
    _c(
        "num-10",
        NUM,
        "Build two raised beds, each four by four and one high, with a cube's gap between them.",
        k.pair(_PEN4, _PEN4, k.gap_of(1)),
    ),
    _c(
        "num-11",
        NUM,
        "I want a row of edging eight cubes long down the left side, front to back.",
        one(k.row(8), k.runs("x"), reg("left")),
    ),
    _c(
        "num-12",
        NUM,
        "A pergola on four posts, each post three cubes high.",
        one(_roofed(4, 3)),
    ),
    _c(
        "num-13",
        NUM,
        "Build three tower — one cube, two cube, three cube — in one line from left to right, "
        "each one leave one cube space.",
        k.in_order("y", T(1), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "num-14",
        NUM,
        "I want one block two by two, stack until four layer.",
        one(k.block(2, 2, 4)),
    ),
    _c(
        "num-15",
        NUM,
        "Make two pyramid, both also three level, don't want them touching.",
        k.each(2, k.pyramid(3)),
    ),
    _c(
        "num-16",
        NUM,
        "Put one cube at every corner of the table, so total four cube lah.",
        k.structures(*[k.all_of(T(1), reg(r)) for r in _CORNERS]),
    ),
    _c(
        "num-17",
        NUM,
        "A 3 by 3 grid of single cubes, 5 cm gutters between them.",
        _grid(3, 3, T(1), 1),
    ),
    _c(
        "num-18",
        NUM,
        "Three towers of two, evenly spaced along the back, 10 cm gutters.",
        k.all_of(k.in_order("y", T(2), T(2), T(2), gaps=(2,)), k.layout(reg("back"))),
    ),
    _c(
        "num-19",
        NUM,
        "Two identical towers of six, symmetric about the centre line, 20 cm apart centre to "
        "centre.",
        k.all_of(k.pair(T(6), T(6), k.gap_of(3)), k.layout(_mirror())),
    ),
    _c(
        "num-20",
        NUM,
        "Build a row of cubes. It should be exactly nine long.",
        one(k.row(9)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Build a tower. It should be 35 cm tall.", one(T(7))),
    _c(
        "dim-02",
        DIM,
        "Lay a slab 20 cm by 15 cm. Keep it to one layer.",
        one(k.block(4, 3, 1)),
    ),
    _c("dim-03", DIM, "Build a wall 30 cm long. Make it 10 cm high.", one(k.wall(6, 2))),
    _c(
        "dim-04",
        DIM,
        "Put a staircase on the left. Its top step should be 25 cm up.",
        one(k.staircase(5), reg("left")),
    ),
    _c(
        "dim-05",
        DIM,
        "Can you make an L lying flat, each arm about 15 cm?",
        one(_flat_letter("L", (3, 3))),
    ),
    _c(
        "dim-06",
        DIM,
        "Could I have stairs like in a stadium, 20 centimetres high at the top?",
        one(k.staircase(4)),
    ),
    _c(
        "dim-07",
        DIM,
        "Something like a domino standing on its end: 10 cm wide, 20 cm tall and one cube thick.",
        one(k.wall(2, 4)),
    ),
    _c(
        "dim-08",
        DIM,
        "Make a shape like a capital T lying flat, the top bar 25 cm across and the stem 15 cm "
        "long below it.",
        one(_flat_letter("T", (5, 4), (5, 3))),
    ),
    _c(
        "dim-09",
        DIM,
        "Build a raised bed 25 cm square on the outside and 10 cm high.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-10",
        DIM,
        "A retaining wall 40 cm long and 15 cm high, please.",
        one(k.wall(8, 3)),
    ),
    _c(
        "dim-11",
        DIM,
        "Put in a garden path 5 cm wide and 45 cm long, running away from the robot.",
        one(k.row(9), k.runs("x")),
    ),
    _c(
        "dim-12",
        DIM,
        "A pergola with posts 15 cm high and a top about 15 by 15 cm.",
        one(_roofed(4, 3), k.dims(3, 3)),
    ),
    _c(
        "dim-13",
        DIM,
        "Build one tower 0.3 metre high, put at the centre there.",
        one(T(6), reg("centre")),
    ),
    _c(
        "dim-14",
        DIM,
        "I want one wall, the length 25 cm, the height 15 cm, can?",
        one(k.wall(5, 3)),
    ),
    _c(
        "dim-15",
        DIM,
        "Make one slab 10 cm by 30 cm, one layer enough already.",
        one(k.block(2, 6, 1)),
    ),
    _c(
        "dim-16",
        DIM,
        "Build two tower 20 cm high, the space between them 10 cm.",
        k.pair(T(4), T(4), k.gap_of(2)),
    ),
    _c(
        "dim-17",
        DIM,
        "A tower 250 mm tall with a 50 mm margin from the back edge.",
        one(T(5), _margin(_B, 0.05)),
    ),
    _c(
        "dim-18",
        DIM,
        "Block, 150 mm wide by 100 mm deep by 100 mm high.",
        one(k.block_xy(2, 3, 2)),
    ),
    _c(
        "dim-19",
        DIM,
        "Two towers 15 cm tall, 15 cm gutter between them, side by side left to right.",
        k.pair(T(3), T(3), k.gap_of(3, _L)),
    ),
    _c(
        "dim-20",
        DIM,
        "Build a bridge. The legs should be 15 cm tall and the opening between them 5 cm.",
        one(_span(3, 1)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Build a tower of five. Don't put it on the right side.",
        one(T(5), k.not_(reg("right"), "on the right")),
    ),
    _c(
        "neg-02",
        NEG,
        "Build a wall six long. It must be no taller than 15 cm.",
        one(k.wall(6), k.low(3)),
    ),
    _c(
        "neg-03",
        NEG,
        "Build a staircase of four steps. It must not go up towards the left.",
        one(k.staircase(4), k.not_(k.rises(_L), "climbs to the left")),
    ),
    _c(
        "neg-04",
        NEG,
        "Make a square with a hole in it, like a picture frame, four by four — but not closed all "
        "the way round: leave one cube out of the left side.",
        one(k.dims(4, 4), k.height(1), k.not_(k.ring, "closed"), _frame_gap(_L)),
    ),
    _c(
        "neg-05",
        NEG,
        "I'd like a bridge like the letter n, legs of two, but no beam — just cubes across the "
        "top.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-06",
        NEG,
        "Build a plus sign of cubes lying flat, three across, and please don't stack anything on "
        "it.",
        one(_PLUS3),
    ),
    _c(
        "neg-07",
        NEG,
        "A retaining wall six long and two high, but not along the front — I need the front clear.",
        one(k.wall(6, 2), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-08",
        NEG,
        "Build a pergola with four posts two cubes high, no beams, cubes only for the top.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "Two raised beds four by four, one high, not touching each other.",
        k.each(2, _PEN4),
    ),
    _c(
        "neg-10",
        NEG,
        "Build one tower four cube, don't want at the front, put at the back.",
        one(T(4), reg("back")),
    ),
    _c(
        "neg-11",
        NEG,
        "Two wall four long two high, don't want touching, also don't want same direction.",
        k.pair(
            k.all_of(k.wall(4, 2), k.runs("x")),
            k.all_of(k.wall(4, 2), k.runs("y")),
            _any_rel,
        ),
    ),
    _c(
        "neg-12",
        NEG,
        "Make one staircase five step, but the high side don't want near the robot.",
        one(k.staircase(5), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-13",
        NEG,
        "A row of eight — not horizontal; run it front to back.",
        one(k.row(8), k.runs("x")),
    ),
    _c(
        "neg-14",
        NEG,
        "Two towers of three, no overlap and no touching, 15 cm apart centre to centre.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "neg-15",
        NEG,
        "Build two towers of three. They shouldn't be next to each other — put them at opposite "
        "ends of the table.",
        k.pair(T(3), T(3), _opposite_ends),
    ),
    # ------------------------------------------------------------------ typo
    _c(
        "typo-01",
        TYP,
        "Biuld a towre of six. Keep it in the midle of the table.",
        one(T(6), reg("centre")),
    ),
    _c("typo-02", TYP, "Make a wlal four long. It shuold be three hihg.", one(k.wall(4, 3))),
    _c(
        "typo-03",
        TYP,
        "Two piramids of two levles. Keep them apart.",
        k.each(2, k.pyramid(2)),
    ),
    _c(
        "typo-04",
        TYP,
        "Can you make a shpae like a leter T lying flat, the top five acorss and the stem two "
        "below?",
        one(_flat_letter("T", (5, 3), (5, 2))),
    ),
    _c("typo-05", TYP, "Stiars like in a stadum, four stpes please.", one(k.staircase(4))),
    _c("typo-06", TYP, "A pluss sign lyign flat, five acros each way.", one(_PLUS5)),
    _c("typo-07", TYP, "Buld a raised bed five by fiev, one hgih.", one(_PEN5)),
    _c("typo-08", TYP, "Pergloa with four psots three high pls.", one(_roofed(4, 3))),
    _c(
        "typo-09",
        TYP,
        "Stepping stoens: four in a line left to rihgt, one cueb apart.",
        k.in_order("y", *[T(1)] * 4, gaps=(1,)),
    ),
    _c(
        "typo-10",
        TYP,
        "Can help me bulid one towr five cube at the back rigth?",
        one(T(5), reg("back right")),
    ),
    _c(
        "typo-11",
        TYP,
        "Make one wal six long two high on the lfet side lah.",
        one(k.wall(6, 2), reg("left")),
    ),
    _c(
        "typo-12",
        TYP,
        "Two tower thre cube, one cube spcae in between.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "typo-13",
        TYP,
        "Tower of fuor, centred on the cnetre line at the bakc.",
        one(T(4), reg("back"), k.near(y=_CENTRE_Y, tol=0.03)),
    ),
    _c(
        "typo-14",
        TYP,
        "Two rows of five, paralel, 5 cm guttre betwen them.",
        k.pair(k.row(5), k.row(5), k.parallel_gap(1)),
    ),
    # ------------------------------------------------------------------ word order
    _c(
        "wo-01",
        WO,
        "At the back right. That's where the tower of three goes.",
        one(T(3), reg("back right")),
    ),
    _c(
        "wo-02",
        WO,
        "Three levels high — that's the pyramid I need. It goes on the left.",
        one(k.pyramid(3), reg("left")),
    ),
    _c(
        "wo-03",
        WO,
        "Four steps. Make a staircase with that many, and it should climb to the right.",
        one(k.staircase(4), k.rises(_R)),
    ),
    _c(
        "wo-04",
        WO,
        "Flat on the table, like the number 7 lying down — that's the shape, four cubes along the "
        "top and four down the side.",
        one(_flat_letter("L", (4, 4))),
    ),
    _c(
        "wo-05",
        WO,
        "Like a football goal, that's the look — two posts five cubes tall with a beam across the "
        "top.",
        one(_beam_bridge(5)),
    ),
    _c(
        "wo-06",
        WO,
        "Along the back, five long and two high, a retaining wall.",
        one(k.wall(5, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "wo-07",
        WO,
        "In the middle of a raised bed five by five, one high — a tower of four, as a centrepiece.",
        k.pair(_PEN5, T(4), k.centred_in(0.03)),
    ),
    _c(
        "wo-08",
        WO,
        "From front to back, a path of seven cubes; put it on the right.",
        one(k.row(7), k.runs("x"), reg("right")),
    ),
    _c(
        "wo-09",
        WO,
        "Tower four cube, the left side there, can build or not?",
        one(T(4), reg("left")),
    ),
    _c(
        "wo-10",
        WO,
        "Behind the slab 2 by 3, one tower of five put there, leave one cube space.",
        k.pair(T(5), k.block(2, 3, 1), k.gap_of(1, _B)),
    ),
    _c(
        "wo-11",
        WO,
        "Three level pyramid, middle of the table, build for me.",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "wo-12",
        WO,
        "Left to right, 10 cm gutters: towers of one, two and three.",
        k.in_order("y", T(1), T(2), T(3), gaps=(2,)),
    ),
    _c(
        "wo-13",
        WO,
        "On the centre line, at the front, a row of five running left to right — centred, please.",
        one(_row_y(5), reg("front"), k.near(y=_CENTRE_Y, tol=0.03)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning! Hope the weekend was good. Build a tower of four. Keep it at the front left.",
        one(T(4), reg("front left")),
    ),
    _c(
        "fil-02",
        FIL,
        "Quick one before the 10:30 meeting. Build a 2 by 2 block. Make it three high.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-03",
        FIL,
        "Hi, sorry, it's my first day and I don't know the proper names yet. Can you make the "
        "shape that looks like stairs, three steps?",
        one(k.staircase(3)),
    ),
    _c(
        "fil-04",
        FIL,
        "Um, okay, my supervisor said to try something simple first. A shape like a letter U "
        "lying flat, five across and three deep?",
        one(_flat_letter("U", (5, 3))),
    ),
    _c(
        "fil-05",
        FIL,
        "Sorry if this is a silly question. Could you make a ring like a doughnut, four by four, "
        "one cube high?",
        one(_PEN4),
    ),
    _c(
        "fil-06",
        FIL,
        "Lovely weather for it — the roses are finally out. Anyway, a raised bed four by four, "
        "two high, on the left please.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4), reg("left")),
    ),
    _c(
        "fil-07",
        FIL,
        "I've been landscaping for twenty years and I still love a neat edge. Edging row of six "
        "along the front, please.",
        one(_row_y(6), reg("front")),
    ),
    _c(
        "fil-08",
        FIL,
        "The client's coming at three to look at the plans. Put a pergola up: four posts, two "
        "high.",
        one(_roofed(4, 2)),
    ),
    _c(
        "fil-09",
        FIL,
        "Wah, today very busy ah. Build one pyramid four level for me lah, thank you.",
        one(k.pyramid(4)),
    ),
    _c(
        "fil-10",
        FIL,
        "Boss say must finish before 5 o'clock. Make one wall seven long three high, can?",
        one(k.wall(7, 3)),
    ),
    _c(
        "fil-11",
        FIL,
        "Sorry ah, just now the system hang. Build one tower three cube at the front right, "
        "thanks.",
        one(T(3), reg("front right")),
    ),
    _c(
        "fil-12",
        FIL,
        "Working on the spring catalogue, 12 pages still to go. For the photo: two towers of "
        "five, 10 cm gutter.",
        k.pair(T(5), T(5), k.gap_of(2)),
    ),
    _c(
        "fil-13",
        FIL,
        "Not a fan of clutter — less is more, as we say in the studio. Just one tower of three, "
        "dead centre.",
        one(T(3), reg("centre")),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Build a tower of five. Put it in the back left corner.",
        one(T(5), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "Lay a row of six. It has to run along the back edge.",
        one(_row_y(6), k.min_x(0.60)),
    ),
    _c(
        "reg-03",
        REG,
        "Make a 2 by 2 block, two high. Its centre should be at x 0.55, y 0.20.",
        one(k.block(2, 2, 2), k.near(0.55, 0.20, 0.02)),
    ),
    _c(
        "reg-04",
        REG,
        "Can you make a letter L lying flat, arms of three, in the front right corner?",
        one(_flat_letter("L", (3, 3)), reg("front right")),
    ),
    _c(
        "reg-05",
        REG,
        "Put stairs like the stadium kind, three steps, on the left half of the table, please.",
        one(k.staircase(3), _y_range(lo=_CENTRE_Y)),
    ),
    _c(
        "reg-06",
        REG,
        "Make a plus sign, three cubes each way, lying flat in the middle of the table.",
        one(_PLUS3, reg("centre")),
    ),
    _c(
        "reg-07",
        REG,
        "Raised bed four by four, one high, at the far end of the table away from the robot.",
        one(_PEN4, reg("back")),
    ),
    _c(
        "reg-08",
        REG,
        "A retaining wall five long, two high, against the right-hand edge, running front to back.",
        one(k.wall(5, 2), k.runs("x"), _centre_y_max(0.15)),
    ),
    _c(
        "reg-09",
        REG,
        "Stepping stones, three of them, in a line across the back half, a cube apart.",
        k.all_of(k.in_order("y", T(1), T(1), T(1), gaps=(1,)), k.layout(k.min_x(0.50))),
    ),
    _c(
        "reg-10",
        REG,
        "Put one tower six cube at the front left corner there.",
        one(T(6), reg("front left")),
    ),
    _c(
        "reg-11",
        REG,
        "Build one slab 3 by 3 in the right part of the table, near the robot side.",
        one(k.block(3, 3, 1), reg("front right")),
    ),
    _c(
        "reg-12",
        REG,
        "A tower of four with a 10 cm margin from the left edge and a 10 cm margin from the back "
        "edge.",
        one(T(4), _margin(_L, 0.10), _margin(_B, 0.10)),
    ),
    _c(
        "reg-13",
        REG,
        "Centre a 3 by 3 slab on the table, one layer, exactly on the centre point.",
        one(k.block(3, 3, 1), _near_any((0.45, 0.50), (_CENTRE_Y,))),
    ),
    _c(
        "reg-14",
        REG,
        "Two towers of three, one hugging the left edge and one hugging the right edge, mirrored.",
        k.all_of(
            k.structures(k.all_of(T(3), k.centre_y_min(0.45)), k.all_of(T(3), _centre_y_max(0.15))),
            k.layout(_mirror(tol=0.02)),
        ),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Build anything you like. It must not be taller than 15 cm.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-02",
        OPEN,
        "Make something with an opening underneath it. Any size is fine.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-03",
        OPEN,
        "Build whatever you think looks good. Use cubes only, though.",
        k.all_of(k.anything, k.layout(k.only_cubes)),
    ),
    _c(
        "open-04",
        OPEN,
        "Can you build something that looks like a letter L? Any size, lying down or standing up.",
        k.all_of(k.anything, one(k.any_of(k.shape_letter("L"), _l_upright))),
    ),
    _c(
        "open-05",
        OPEN,
        "I'm not sure what to ask for… something that looks like steps, maybe? Any size.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-06",
        OPEN,
        "Anything that looks like a table, any size you want.",
        k.all_of(k.anything, one(_TABLE)),
    ),
    _c(
        "open-07",
        OPEN,
        "Put something nice in the garden bed area — anything, as long as it stays in the back "
        "half.",
        k.all_of(k.anything, k.layout(k.min_x(0.50))),
    ),
    _c(
        "open-08",
        OPEN,
        "Design me a little garden feature, your choice, no taller than 20 cm.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-09",
        OPEN,
        "Anything also can, just put on the left side.",
        k.all_of(k.anything, k.layout(reg("left"))),
    ),
    _c(
        "open-10",
        OPEN,
        "You choose what to build lah, but don't want more than ten cube.",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-11",
        OPEN,
        "Any composition you like, as long as it's symmetric about the centre line.",
        k.all_of(k.anything, k.layout(_mirror())),
    ),
    _c(
        "open-12",
        OPEN,
        "Two objects of your choice, on the same baseline left to right, with a 10 cm gutter.",
        k.all_of(
            k.anything,
            k.pair(_free, _free, k.all_rels(k.gap_of(2), k.on_side(_L), _flush(_F))),
        ),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "Build a tower of eight. It must stay under 20 cm tall.",  # eight cubes is 40 cm
        k.honest(one(T(lo=1, hi=8))),
    ),
    _c(
        "bad-02",
        BAD,
        "Build a wall. Make it 90 cm long.",  # 18 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-03",
        BAD,
        "Build a pyramid. The top level must be bigger than the bottom one.",
        k.honest(k.anything),
    ),
    _c(
        "bad-04",
        BAD,
        "Build a tower of three. Actually, cancel that — nothing today.",
        k.honest(),
    ),
    _c(
        "bad-05",
        BAD,
        "Make me a shape like a ball, about 10 cm round.",
        k.honest(k.anything),
    ),
    _c(
        "bad-06",
        BAD,
        "Could you make the thing that looks like, um… the thing? You know the one.",
        k.honest(k.anything),
    ),
    _c(
        "bad-07",
        BAD,
        "Make something shaped like a circle lying flat, 20 cm across.",  # cubes make no circle
        k.honest(k.anything),
    ),
    _c("bad-08", BAD, "Can you make a shape like the letter", k.honest(k.anything)),
    _c("bad-09", BAD, "Plant a row of tulips along the front edge.", k.honest()),
    _c(
        "bad-10",
        BAD,
        "Dig a pond in the middle, 10 cm deep.",  # the cell cannot dig into the table
        k.honest(k.anything),
    ),
    _c(
        "bad-11",
        BAD,
        "A raised bed 80 cm by 80 cm, one high.",  # 16 cubes a side: past the cell
        k.honest(k.anything),
    ),
    _c("bad-12", BAD, "Can you water the beds at the back before you go?", k.honest()),
    _c(
        "bad-13",
        BAD,
        "Same like last time, build the one the boss like.",
        k.honest(k.anything),
    ),
    _c(
        "bad-14",
        BAD,
        "Build one tower three and a half cube high, can?",
        k.honest(one(k.any_of(T(3), T(4)))),
    ),
    _c(
        "bad-15",
        BAD,
        "Aiyo, forget it lah, don't need to build anything already.",
        k.honest(),
    ),
    _c(
        "bad-16",
        BAD,
        "Can help me check why the gripper keep dropping the cube or not?",
        k.honest(),
    ),
    _c("bad-17", BAD, "Make the whole layout pop a bit more.", k.honest(k.anything)),
    _c(
        "bad-18",
        BAD,
        "Place a tower of four centred at x 1.2 m, y 0.3 m.",  # x 1.2 is off the table
        k.honest(one(T(4))),
    ),
    _c("bad-19", BAD, "Export the current layout as a PDF and email it to me.", k.honest()),
]
