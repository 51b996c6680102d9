"""A thirtieth set for the language front end (dev30): five new everyday voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev29` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is deliberately mainstream: about
80 % of the commands are what a person at a robot cell would really type — one or two
structures with a size, a place, one relation or a two-step sequence, in plain, varied
English (build / put / place / stack / lay / set up / make / give me / I need / could you /
I'd like; the place first or the size last; sizes as words, digits, "3x2", cm, mm and metres;
articles dropped now and then; casual punctuation) — and they come from five kinds of
people, none of them used by an earlier set:

* an experienced operator who is terse but writes whole, grammatical sentences: "Build a
  tower of six at the back right.", "Stand a tower of three on each end of a row of five."
  No chatter, no slang, every sentence finished with a full stop;
* someone copying a layout from a paper sketch and describing it in plan view ("seen from
  above", "on the drawing", "on the sketch"). The page lies on the table as seen from the
  robot: the TOP of the page is the BACK of the table (+x, away from the robot), the BOTTOM
  of the page is the FRONT (the robot's side, small x), the left of the page is the left
  (+y) and the right of the page the right (-y); "across the page" runs left to right
  (along y), "up / down the page" runs front to back (along x); "one above the other" on the
  page is one behind the other. A square on the sketch is one cube; a number written in a
  square is the height of that column in cubes (an unmarked square is one cube high); a
  square "crossed out" is taken away. A stated scale ("drawn at 1:5") turns paper lengths
  into table lengths (1 cm at 1:5 is one cube). Where the sketch is said to show the table,
  "top left of the drawing" is the back-left region and so on. A sketch that is only
  "attached", a square marked with a negative number and one tower drawn in two places are
  bad input;
* a shift supervisor giving two or three jobs in one message, in order: "First …, after
  that …, finally …". Every job stays on the table unless a later job takes it away; "that's
  it" / "nothing else" means exactly the structures named; "cancel everything and build
  nothing" admits only the refusal; a job that sits on something that is not there ("the
  blue box") is bad input;
* a technician who gives every size in metric units (cm, mm, m) and positions as distances
  from the table's edges, taken as the workspace's edges (front edge x = 0.20, back edge
  x = 0.80, left edge y = 0.55, right edge y = 0.05). "Its centre N from the … edge" is the
  footprint centre (± 2 cm); a bare "N from" / "N in from" an edge accepts the footprint
  centre or the nearest face at that distance (± 2 cm); "no more than N from" / "within N
  of" an edge puts the nearest face within N; "at least N away from" an edge puts every part
  at least that far; "x = 0.6 m, y = 0.2 m" is the footprint centre (± 2 cm); a "5 cm cube"
  is one cube; sizes between whole cubes (12.5 cm), a zero size, positions off the table and
  shapes the cell cannot make (a sphere) are bad input;
* a polite, slightly wordy office worker trying the cell at an open day: "Hello!", "would it
  be possible", "if it's not too much trouble", "thank you so much", remarks about the day,
  the family, the coffee. The courtesy and the chat are filler (a number in them is not a
  size); a question that asks for no build ("where is the coffee machine?") admits only a
  refusal; a request in French is bad input (a refusal, or the reading with a note).

About 80 % ordinary and 20 % harder: three or more structures, references ("the first one",
"on it", "on the middle of the beam"), distributive phrases ("on each end", "in each back
corner", "on each of its four corners"), comparisons ("twice as tall", "half its height"),
removals ("take away the middle two columns", "remove the lowest step", "crossed out"),
corrections in the same message ("No, two high.", "Correction: two levels.") and unusable
input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) through the shared checks and accepts every reasonable reading of vague
wording, and nothing else. Conventions (mostly dev27's):

* "next to" / "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by column heights); a
  tower "to the left / right of" or "in front of" another with nothing said about touching
  may also stand against it (its column then lies on that side of the rest); "a gap",
  "apart", "not touching", "separate" mean separate structures; "N cubes apart", "a cube
  apart", "a N cm gap", "N cm clear" are the clear gap (± 1.5 cm); "N cm between centres" /
  "centre to centre" is measured between footprint centres;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none is
  said; "directly behind" / "directly to the left of" also lines the centres up (± 3 cm);
  "above the middle square" on a sketch is behind the middle of it, centres lined up;
  "between" is the shared `between_` on three separate structures (or, where the command
  allows touching, the three set against one another in one line);
* a bridge's top is a beam (two posts under the beam, the overall height one more than the
  posts) where the command names a beam, and a beam or a bar of cubes where it does not;
  "ordinary cubes across instead" of the beam is a bar of cubes only; a table is four
  separate legs under one connected top of beams or of cubes;
* a ring's stated size is its outside; "in the middle of" / "in the hole in the middle of" a
  ring is inside its empty interior, clear of the ring, with the centres within 3 cm; a
  tower "inside" a ring is anywhere in the interior, clear of the ring or standing against
  its wall (then one structure);
* a "slab" or a "rectangle" with no height is one layer; a "2x2 block" with no height is
  any number of layers; a staircase's width is free unless given, and so is the way it
  climbs unless said; "remove the lowest step" of a four-step staircase leaves columns 2-3-4
  (or a rebuilt three-step staircase); a pyramid's step is free unless the levels fix it;
  "a tower of three on each end of a row" stands on the end cubes (end columns four high);
  "a tower of two on each of its four corners" of a 3 × 3 slab makes the corner columns
  three high; "a cube on top, anywhere" is one part on the topmost level resting on the rest;
* "tall" with no figure is at least five cubes high; "nothing taller than 15 cm" is at most
  three cubes; "no more than N cubes" counts cubes (beams not counted); "something with
  stairs in it" is a staircase or a pyramid; "some sort of enclosure" is a ring; "about
  30 cm" is the nearest whole number of cubes (six);
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the left edge" is a footprint centre at y ≥ 0.45; "the back half" is every part at
  x ≥ 0.50 and "anywhere except the top half of the page" every part at x ≤ 0.50; "centred
  left to right" / "on the centre line" is y = 0.30 ± 3 cm; "the far end of the table, the
  side furthest from the robot" is the back region; "across the bottom of the page" is the
  front region.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`): gibberish, another language, contradictions, sizes past the cell,
positions off the table, sizes between whole cubes, shapes the cell cannot make, references
to things not on the table. A message that asks for no build at all, or calls the build
off, admits only the refusal (or a failure). Geometry comes only from `sdi.bench.boxes`,
through the shared checks in `language_checks` and the local checks below.

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

_TALL = 5  # cubes: "tall" with no figure
_EDGES = {_F: (0, 0.20, 1.0), _B: (0, 0.80, -1.0), _R: (1, 0.05, 1.0), _L: (1, 0.55, -1.0)}
"""Each table edge: (axis, coordinate, sign pointing into the table)."""


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev30-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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
    """Two separate full posts lo–hi cubes high on the table (any height when None) and, as
    the topmost level, one connected bar resting on both — a beam or a row of cubes (whose
    middle cubes rest on nothing, so the shared `bridge` does not see it)."""

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        z = max(round(b.lo[2], 3) for b in bs)
        bar = [b for b in bs if round(b.lo[2], 3) == z]
        below = [b for b in bs if round(b.lo[2], 3) != z]
        posts = bx.components(below) if below else []
        if len(posts) != 2 or len(bx.components(bar)) != 1:
            return "not one bar on two separate posts"
        for g in posts:
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
    """A bridge with no beam named: a beam bridge, or a bar of cubes across two posts."""
    return k.any_of(_beam_bridge(posts), _bar_on_posts(posts, posts))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate full legs `leg_h` high on the table under one connected top that is
    the topmost level and rests on every leg (beams or cubes)."""

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
    """A table: the shared `canopy` one layer above the legs, a top of cubes, or the beam
    roof."""
    return k.any_of(
        k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1)),
        _roof_on(legs, leg_h),
        k.beam_roof(legs, leg_h),
    )


def _col_beside(h: int, rest: k.Check, side: str) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table set against the rest,
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
    """A stands square to the middle of B: their centres line up across the direction from B
    to A, ± tol."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (ax, ay), (bx0, by0) = bx.centre(a), bx.centre(b)
        off = abs(ay - by0) if bx.side_of(a, b) in (_F, _B) else abs(ax - bx0)
        return None if off <= tol else f"{off:.3f} m off the middle"

    return rel


def _end_to_end(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A and B run along the same axis and lie one after the other along it."""
    (ax, ay), (bx_, by) = bx.footprint_cubes(a), bx.footprint_cubes(b)
    if (ax > ay) != (bx_ > by):
        return "not running the same way"
    along = (_F, _B) if ax > ay else (_L, _R)
    return None if bx.side_of(a, b) in along else "side by side, not end to end"


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


def _fits(a: int, b: int) -> k.Check:
    """A footprint no bigger than a × b cubes (either way round)."""

    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        want = (min(a, b), max(a, b))
        ok = got[0] <= want[0] and got[1] <= want[1]
        return None if ok else f"footprint {got}, want within {want}"

    return f


def _max_x(x: float) -> k.Check:
    """Every part lies at x ≤ `x` (m): no further back than that."""

    def f(bs: k.Boxes) -> k.Reason:
        hi = max(b.hi[0] for b in bs)
        return None if hi <= x + bx.TOL else f"a part reaches x {hi:.3f}, want ≤ {x}"

    return f


def _off_edge(edge: str, d: float, centre_only: bool = False, tol: float = 0.02) -> k.Check:
    """The footprint centre `d` m in from the table's `edge` (± tol), or — unless
    `centre_only` — the nearest face `d` m in from it."""
    axis, at, sign = _EDGES[edge]

    def f(bs: k.Boxes) -> k.Reason:
        lo, hi = bx.bounds(bs)
        dc = (bx.centre(bs)[axis] - at) * sign
        df = ((lo if sign > 0 else hi)[axis] - at) * sign
        if abs(dc - d) <= tol or (not centre_only and abs(df - d) <= tol):
            return None
        return f"centre {dc:.3f} m, nearest face {df:.3f} m from the {edge} edge, want {d}"

    return f


def _hugs(edge: str, d: float) -> k.Check:
    """The nearest face no more than `d` m (+ 5 mm) in from the table's `edge`."""
    axis, at, sign = _EDGES[edge]

    def f(bs: k.Boxes) -> k.Reason:
        lo, hi = bx.bounds(bs)
        df = ((lo if sign > 0 else hi)[axis] - at) * sign
        return None if df <= d + 0.005 else f"{df:.3f} m from the {edge} edge, want ≤ {d}"

    return f


def _steps(*hs: int) -> k.Check:
    """On the table, slice heights `hs` along x or y (either direction), every column full,
    whatever the width."""
    want = list(hs)

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        r = k.on_table(bs)
        if r:
            return r
        n = len(bx.voxels(bs))
        fx, fy = bx.footprint_cubes(bs)
        for axis, width in ((0, fy), (1, fx)):
            got = bx.step_profile(bs, axis)
            if got in (want, want[::-1]) and n == sum(hs) * width:
                return None
        px, py = bx.step_profile(bs, 0), bx.step_profile(bs, 1)
        return f"slice heights {px} / {py}, want {want}"

    return f


def _anchored(anchor: k.Check, *others: tuple[k.Check, k.Rel]) -> k.Pred:
    """Exactly 1 + len(others) separate structures: one passing `anchor` and, for each
    (check, rel) in `others`, another passing check with rel(it, anchor)."""
    n = 1 + len(others)

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != n:
            return f"{len(comps)} separate structures, want {n}"
        first: k.Reason = None
        for perm in itertools.permutations(range(n)):
            a = comps[perm[0]]
            r = anchor(a)
            for (check, rel), i in zip(others, perm[1:], strict=True):
                r = r or check(comps[i]) or rel(comps[i], a)
            if r is None:
                return None
            first = first or r
        return first

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
        "Build a tower of four cubes and put a tower of two cubes to its left.",
        k.any_of(k.pair(T(2), T(4), k.on_side(_L)), one(_col_beside(2, T(4), _L))),
    ),
    _c(
        "rel-02",
        REL,
        "From my sketch, seen from above: five squares in a row across the page, and above the "
        "middle one, with one empty square between, a square marked 3.",
        k.pair(
            T(3),
            k.all_of(k.row(5), k.runs("y")),
            k.all_rels(k.gap_of(1, _B), _facing_mid()),
        ),
    ),
    _c(
        "rel-03",
        REL,
        "First, build a 3x3 slab in the middle of the table. After that, put a tower of three "
        "on the middle of it.",
        one(
            k.on_top(T(3), k.block(3, 3, 1)),
            k.centred(),
            k.levels(9, 1, 1, 1),
            reg("centre"),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "Two 15 cm towers with a 10 cm gap between them.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "rel-05",
        REL,
        "Hello! Would it be possible to build a little bridge — two towers of two cubes with one "
        "of those long beams laid across the top? Thank you so much.",
        one(_beam_bridge(2)),
    ),
    _c(
        "rel-06",
        REL,
        "Put a 2x2 block, two high, behind a left-to-right row of four cubes, leaving a gap.",
        k.pair(k.block(2, 2, 2), k.all_of(k.row(4), k.runs("y")), k.on_side(_B)),
    ),
    _c(
        "rel-07",
        REL,
        "On the drawing there is a square ring five squares on each side, one high, and in the "
        "hole in the middle of it a square with a 2 written in it.",
        k.pair(_PEN5, T(2), k.centred_in(0.03)),
    ),
    _c(
        "rel-08",
        REL,
        "First, a wall six long and three high across the back. After that, a tower of five in "
        "front of it.",
        k.any_of(
            k.pair(T(5), k.all_of(k.wall(6, 3), k.runs("y"), reg("back")), k.on_side(_F)),
            one(_col_beside(5, k.all_of(k.wall(6, 3), k.runs("y")), _F), reg("back")),
        ),
    ),
    _c(
        "rel-09",
        REL,
        "Place a 10 cm tower on top of a 10 x 10 cm block that is 5 cm high.",
        one(k.on_top(T(2), k.block(2, 2, 1)), k.levels(4, 1, 1)),
    ),
    _c(
        "rel-10",
        REL,
        "I'd love to see a pyramid with three levels and, next to it, if it's not too much "
        "trouble, a small tower of three cubes.",
        k.any_of(
            k.pair(T(3), k.pyramid(3), k.within(0.25)),
            one(k.with_column(3, k.pyramid(3))),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "Build two towers of five cubes, one cube apart, and lay a beam across their tops.",
        one(_beam_bridge(5, 1)),
    ),
    _c(
        "rel-12",
        REL,
        "First, put a tower of three on the left and another on the right. After that, put a "
        "row of three cubes between them, with a gap on each side.",
        k.between_(k.row(3), k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "rel-13",
        REL,
        "Put a single 5 cm cube 10 cm clear to the right of a 20 cm tower.",
        k.pair(T(1), T(4), k.gap_of(2, _R)),
    ),
    _c(
        "rel-14",
        REL,
        "Could you please put a tower of two cubes inside a ring? The ring could be five cubes "
        "on each side and one cube high — I think that would look lovely.",
        k.any_of(k.around(T(2), _PEN5), one(k.holding(T(2), _PEN5))),
    ),
    _c(
        "rel-15",
        REL,
        "Stand a tower of three on each end of a row of five.",
        one(k.profile(4, 1, 1, 1, 4)),
    ),
    _c(
        "rel-16",
        REL,
        "Seen from above: two rows of four squares across the page, one above the other, with a "
        "one-square gap between them.",
        k.pair(
            k.all_of(k.row(4), k.runs("y")),
            k.all_of(k.row(4), k.runs("y")),
            k.parallel_gap(1),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "First, build a staircase of four steps. After that, put a single cube on its top step.",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "rel-18",
        REL,
        "Wall 25 cm long, 10 cm high; 15 cm tower 5 cm behind it.",
        k.pair(T(3), k.wall(5, 2), k.gap_of(1, _B)),
    ),
    _c(
        "rel-19",
        REL,
        "Hi there, I was wondering if you could build two walls facing each other, each four "
        "cubes long and two cubes high, with a gap of two cubes between them?",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-20",
        REL,
        "Put a pyramid of two levels to the right of a 3x3 slab, one cube away from it.",
        k.pair(k.pyramid(2), k.block(3, 3, 1), k.gap_of(1, _R)),
    ),
    _c(
        "rel-21",
        REL,
        "Three things on the sketch, left to right across the page: a square marked 1, a square "
        "marked 3 and a square marked 5, each with one empty square between.",
        k.in_order("y", T(1), T(3), T(5), gaps=(1,)),
    ),
    _c(
        "rel-22",
        REL,
        "First, build a tower of four at the front right. After that, put a tower of two "
        "directly behind it, a cube apart. Finally, put a tower of three directly to the left "
        "of the first one, also a cube apart.",
        _anchored(
            k.all_of(T(4), reg("front right")),
            (T(2), k.all_rels(k.gap_of(1, _B), _facing_mid())),
            (T(3), k.all_rels(k.gap_of(1, _L), _facing_mid())),
        ),
    ),
    _c(
        "rel-23",
        REL,
        "Block 10 x 10 cm, 15 cm high, 5 cm to the left of a 15 cm tower.",
        k.pair(k.block(2, 2, 3), T(3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-24",
        REL,
        "If it's no bother, I'd like a staircase of three steps with a single cube just in "
        "front of it, on the side nearest the robot.",
        k.any_of(
            k.pair(T(1), k.staircase(3), k.all_rels(k.on_side(_F), k.within(0.25))),
            one(_col_beside(1, k.staircase(3), _F)),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "First, a tower of three at the back left. After that, a tower of three at the back right.",
        k.structures(k.all_of(T(3), reg("back left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "seq-02",
        SEQ,
        "First build a row of six along the front, left to right. After that, take the two "
        "cubes off its left end.",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c("seq-03", SEQ, "Build a tower of seven. Then remove the top two cubes.", one(T(5))),
    _c(
        "seq-04",
        SEQ,
        "First, lay a 2x4 slab. After that, put a second layer of the same size on it. Finally, "
        "put a single cube on top, anywhere.",
        one(_topped(k.block(2, 4, 2))),
    ),
    _c("seq-05", SEQ, "Build a 30 cm tower. Then shorten it by 10 cm.", one(T(4))),
    _c(
        "seq-06",
        SEQ,
        "Could you first build a wall five cubes long and two high, and then, when that's "
        "done, a second wall just the same behind it with a small gap?",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.all_rels(k.on_side(_B), k.within(0.25))),
    ),
    _c(
        "seq-07",
        SEQ,
        "The sketch comes on two sheets. Sheet one, the bottom layer: a 3x3 square. Sheet two, "
        "the layer above: only the middle square.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "seq-08",
        SEQ,
        "First, a pyramid of three levels on the left. Correction: two levels.",
        one(k.pyramid(2), reg("left")),
    ),
    _c(
        "seq-09",
        SEQ,
        "Build a wall eight long and two high. Then take away the middle two columns.",
        k.pair(k.wall(3, 2), k.wall(3, 2), k.all_rels(k.gap_of(2), _end_to_end)),
    ),
    _c(
        "seq-10",
        SEQ,
        "First a tower of two at the front left, after that the same at the back left, and "
        "finally the same at the back right.",
        k.structures(
            k.all_of(T(2), reg("front left")),
            k.all_of(T(2), reg("back left")),
            k.all_of(T(2), reg("back right")),
        ),
    ),
    _c("seq-11", SEQ, "Lay a row 30 cm long, then extend it by 10 cm.", one(k.row(8))),
    _c(
        "seq-12",
        SEQ,
        "Please could you start with a tower of six cubes and then, once that's done, take the "
        "top cube off? Thanks ever so much.",
        one(T(5)),
    ),
    _c(
        "seq-13",
        SEQ,
        "First build two towers of four a cube apart. After that, put a beam across them. "
        "Finally, put a single cube on the middle of the beam.",
        one(_topped(_beam_bridge(4, 1)), k.top_centred()),
    ),
    _c("seq-14", SEQ, "Build a 2x3 block, three high. No, two high.", one(k.block(2, 3, 2))),
    _c(
        "seq-15",
        SEQ,
        "On the first drawing there's a row of four squares across the page; on the second "
        "drawing it's the same row with the right-hand square crossed out.",
        one(k.row(3), k.runs("y")),
    ),
    _c(
        "seq-16",
        SEQ,
        "First, a 4x4 ring, one high, in the middle. After that, a tower of three in the back "
        "right corner. Finally, a tower of three in the front left corner.",
        k.structures(
            k.all_of(_PEN4, reg("centre")),
            k.all_of(T(3), reg("back right")),
            k.all_of(T(3), reg("front left")),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "Build a 20 cm staircase with 5 cm steps, then remove the lowest step.",
        one(k.any_of(_steps(2, 3, 4), k.staircase(3))),
    ),
    _c(
        "seq-18",
        SEQ,
        "I'd like a tower of three, please — oh, actually, could it be a tower of five instead? "
        "Sorry!",
        one(T(5)),
    ),
    _c(
        "seq-19",
        SEQ,
        "First build a 3x3 slab at the back. After that, put a tower of two on each of its four "
        "corners.",
        one(k.plan_heights("313", "111", "313"), reg("back")),
    ),
    _c(
        "seq-20",
        SEQ,
        "Build three towers of three in a row, left to right, a cube apart. Then take away the "
        "one on the right.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Block 15 x 10 cm, 10 cm high; then add 5 cm to its height.",
        one(k.block(3, 2, 3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Build three towers of two cubes in a line, one cube apart.",
        k.in_line(3, T(2), 1),
    ),
    _c(
        "num-02",
        NUM,
        "Sketch: a row of squares marked 1, 2, 3, 4 from left to right across the page, all "
        "touching.",
        one(k.lr_profile(1, 2, 3, 4)),
    ),
    _c(
        "num-03",
        NUM,
        "First, two towers of six. After that, one tower of three between them.",
        k.any_of(k.between_(T(3), T(6)), one(k.plan_heights("636"))),
    ),
    _c("num-04", NUM, "Stack nine cubes into a single tower.", one(T(9))),
    _c(
        "num-05",
        NUM,
        "Would you be able to make a pyramid with four levels? That would be wonderful.",
        one(k.pyramid(4)),
    ),
    _c("num-06", NUM, "Build a 4 by 3 slab, one layer.", one(k.block(4, 3, 1))),
    _c(
        "num-07",
        NUM,
        "Build two towers of three and one tower of five, all apart from each other.",
        k.structures(T(3), T(3), T(5)),
    ),
    _c(
        "num-08",
        NUM,
        "The drawing is a square of squares, 3 by 3, every square marked 2.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "num-09",
        NUM,
        "First build four towers of two in a line from front to back, a cube apart. After that, "
        "nothing else.",
        k.in_order("x", *[T(2)] * 4, gaps=(1,)),
    ),
    _c("num-10", NUM, "Staircase with six 5 cm steps.", one(k.staircase(6))),
    _c(
        "num-11",
        NUM,
        "My daughter is eight and she'd love a tower with as many cubes as her age, if that's "
        "possible!",
        one(T(8)),
    ),
    _c(
        "num-12",
        NUM,
        "Build a tower of three and, beside it, a tower twice as tall.",
        k.any_of(k.pair(T(6), T(3), k.within(0.25)), one(k.cell_heights(6, 3))),
    ),
    _c(
        "num-13",
        NUM,
        "On the sketch: a row of seven squares, the two end ones marked 5 and the five between "
        "them unmarked.",
        one(k.profile(5, 1, 1, 1, 1, 1, 5)),
    ),
    _c(
        "num-14",
        NUM,
        "First, a 2x2 block four high. After that, a second one, exactly half its height, next "
        "to it with a gap.",
        k.pair(k.block(2, 2, 2), k.block(2, 2, 4), k.within(0.25)),
    ),
    _c(
        "num-15",
        NUM,
        "Three towers, 5, 10 and 15 cm tall, from left to right, with 5 cm gaps.",
        k.in_order("y", T(1), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "num-16",
        NUM,
        "Could I please have a dozen cubes laid out as a flat rectangle, two rows of six?",
        one(k.block(2, 6, 1)),
    ),
    _c("num-17", NUM, "Build a wall seven cubes long and four cubes high.", one(k.wall(7, 4))),
    _c(
        "num-18",
        NUM,
        "First, four towers of three, one in each corner of the table. After that, a single "
        "cube in the centre.",
        k.structures(
            *[k.all_of(T(3), reg(r)) for r in _CORNERS],
            k.all_of(T(1), reg("centre")),
        ),
    ),
    _c(
        "num-19",
        NUM,
        "Seen from above it's a plus sign: a middle square with an arm two squares long on each "
        "of its four sides, all one high.",
        one(k.shape_letter("cross"), k.dims(5, 5), k.height(1)),
    ),
    _c(
        "num-20",
        NUM,
        "I'd like a couple of small towers, three cubes each, please, not touching.",
        k.each(2, T(3)),
    ),
    _c(
        "num-21",
        NUM,
        "Build a pyramid of five levels on a five-by-five base.",
        one(k.pyramid(5), k.base(5, 5)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Build a tower 25 cm tall.", one(T(5))),
    _c("dim-02", DIM, "I need a wall 40 cm long and 15 cm high.", one(k.wall(8, 3))),
    _c("dim-03", DIM, "Slab 200 mm by 150 mm, one layer.", one(k.block(4, 3, 1))),
    _c("dim-04", DIM, "Tower, 0.35 m.", one(T(7))),
    _c(
        "dim-05",
        DIM,
        "Build a block 10 cm wide, 20 cm long and 10 cm high.",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "My sketch is drawn at 1:5. The rectangle on it measures 4 cm by 2 cm; build it two "
        "layers high.",
        one(k.block(4, 2, 2)),
    ),
    _c(
        "dim-07",
        DIM,
        "Ring 25 cm square on the outside, 5 cm high.",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5)),
    ),
    _c("dim-08", DIM, "Staircase 150 mm high, 50 mm steps.", one(k.staircase(3))),
    _c(
        "dim-09",
        DIM,
        "I'd like a tower about thirty centimetres tall, if you please.",
        one(T(6)),
    ),
    _c(
        "dim-10",
        DIM,
        "Two 15 cm towers, 15 cm between centres.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "dim-11",
        DIM,
        "Bridge: two 10 cm pillars 5 cm apart, 15 cm beam across.",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "dim-12",
        DIM,
        "Build a pyramid whose base is 20 cm square.",
        one(k.pyramid(), k.base(4, 4)),
    ),
    _c("dim-13", DIM, "Block 0.1 m x 0.1 m, 0.25 m high.", one(k.block(2, 2, 5))),
    _c(
        "dim-14",
        DIM,
        "First, a wall 30 cm long and 10 cm high. After that, a 20 cm tower 10 cm clear to its "
        "left.",
        k.pair(T(4), k.wall(6, 2), k.gap_of(2, _L)),
    ),
    _c(
        "dim-15",
        DIM,
        "Could you build a little wall, maybe 20 centimetres long and 10 centimetres tall?",
        one(k.wall(4, 2)),
    ),
    _c("dim-16", DIM, "5 cm high slab, 25 by 25 cm.", one(k.block(5, 5, 1))),
    _c(
        "dim-17",
        DIM,
        "Table: four legs 100 mm high, top 150 x 150 mm.",
        one(_roofed(4, 2), k.dims(3, 3)),
    ),
    _c(
        "dim-18",
        DIM,
        "At 1:10, the row on my sketch is 3 cm long and runs across the page.",
        one(k.row(6), k.runs("y")),
    ),
    _c("dim-19", DIM, "400 mm row, running front to back.", one(k.row(8), k.runs("x"))),
    _c("dim-20", DIM, "Build a wall 0.5 m long and 0.15 m high.", one(k.wall(10, 3))),
    _c(
        "dim-21",
        DIM,
        "A solid cube made of cubes, 15 cm each way.",
        one(k.block(3, 3, 3)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Build a tower of five, but not at the front.",
        one(T(5), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-02",
        NEG,
        "Slab 20 cm x 20 cm, no beams.",
        one(k.block(4, 4, 1), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "Would you mind building a tower of four cubes, but please not in the middle of the "
        "table? It would block my view of the robot.",
        one(T(4), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-04",
        NEG,
        "My drawing is a 3x3 square of squares, one high, with the bottom middle square left "
        "empty.",
        one(k.dims(3, 3), k.height(1), k.parts(8), _missing_on(_F)),
    ),
    _c(
        "neg-05",
        NEG,
        "First, a row of five across the back. After that, a tower of three in front of it, "
        "but not touching the row.",
        k.pair(T(3), k.all_of(k.row(5), k.runs("y"), reg("back")), k.on_side(_F)),
    ),
    _c(
        "neg-06",
        NEG,
        "15 cm tower, at least 20 cm away from the front edge.",
        one(T(3), k.min_x(0.40)),
    ),
    _c(
        "neg-07",
        NEG,
        "Build a staircase of four steps that does not climb towards the robot.",
        one(k.staircase(4), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-08",
        NEG,
        "Could you make a little pyramid of three levels, and please don't use the long beams, "
        "just the cubes?",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c("neg-09", NEG, "Build two towers of four that do not touch.", k.each(2, T(4))),
    _c(
        "neg-10",
        NEG,
        "Row 25 cm long, not running left to right.",
        one(k.row(5), k.runs("x")),
    ),
    _c(
        "neg-11",
        NEG,
        "On the sketch a 2x2 square, one high, sits anywhere except the top half of the page.",
        one(k.block(2, 2, 1), _max_x(0.50)),
    ),
    _c(
        "neg-12",
        NEG,
        "First, a wall five long and two high at the front. After that, a tower of six — not "
        "next to the wall, put it at the back.",
        k.structures(
            k.all_of(k.wall(5, 2), reg("front")),
            k.all_of(T(6), reg("back")),
        ),
    ),
    _c(
        "neg-13",
        NEG,
        "I'd like a bridge, please, but without the long beam on top — could you use ordinary "
        "cubes across instead? Legs of two cubes would be fine.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-14",
        NEG,
        "Build a 3 by 3 square, one high, without its middle cube.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "Build a towr of six at the bakc right.", one(T(6), reg("back right"))),
    _c("typo-02", TYP, "Wal 35 cm long, 10 cm tal.", one(k.wall(7, 2))),
    _c(
        "typo-03",
        TYP,
        "Hello, could you pleese build a pyrmaid of four levles?",
        one(k.pyramid(4)),
    ),
    _c(
        "typo-04",
        TYP,
        "Frist, a 2x2 blcok in the centre. Aftre that, a tower of three to its rigth.",
        k.any_of(
            k.pair(T(3), k.all_of(k.solid(2, 2), reg("centre")), k.on_side(_R)),
            one(_col_beside(3, k.solid(2, 2), _R), reg("centre")),
        ),
    ),
    _c(
        "typo-05",
        TYP,
        "On the skecth, a row of fuor squares down the left side of the page.",
        one(k.row(4), k.runs("x"), reg("left")),
    ),
    _c("typo-06", TYP, "Build a staricase of five steps.", one(k.staircase(5))),
    _c(
        "typo-07",
        TYP,
        "Slab 15 x 15 cm, one layr, in the centr.",
        one(k.block(3, 3, 1), reg("centre")),
    ),
    _c(
        "typo-08",
        TYP,
        "Woudl it be posible to have two towers of thre cubes, with a gap betwen them?",
        k.each(2, T(3)),
    ),
    _c(
        "typo-09",
        TYP,
        "Build a brdige with pillars of three and a beam on top.",
        one(_beam_bridge(3)),
    ),
    _c(
        "typo-10",
        TYP,
        "First a tower of for on the left, after taht a tower of two on the rihgt.",
        k.structures(k.all_of(T(4), reg("left")), k.all_of(T(2), reg("right"))),
    ),
    _c(
        "typo-11",
        TYP,
        "Tower 20 cm hihg, its centre 10 cm from the rigth edge.",
        one(T(4), _off_edge(_R, 0.10, centre_only=True)),
    ),
    _c("typo-12", TYP, "Seen from abvoe: a ring of squres, 5 by 5, one high.", one(_PEN5)),
    _c(
        "typo-13",
        TYP,
        "Could you make a litle table with four legs, each two cubse high?",
        one(_roofed(4, 2)),
    ),
    _c("typo-14", TYP, "Put a singel cube on top of a tower of fuor.", one(T(5))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "At the back left, build a tower of three.", one(T(3), reg("back left"))),
    _c(
        "wo-02",
        WO,
        "30 cm long, 15 cm high, one cube thick: that wall.",
        one(k.wall(6, 3)),
    ),
    _c(
        "wo-03",
        WO,
        "Top right of the drawing: a pyramid, two levels.",
        one(k.pyramid(2), reg("back right")),
    ),
    _c(
        "wo-04",
        WO,
        "In the middle of the table, if I may, I'd like a ring of cubes, four by four and one "
        "high.",
        one(_PEN4, reg("centre")),
    ),
    _c(
        "wo-05",
        WO,
        "A tower of five at the back — do that first; after that, in front of it, a 2x2 block "
        "one high.",
        k.any_of(
            k.pair(k.block(2, 2, 1), k.all_of(T(5), reg("back")), k.on_side(_F)),
            one(_col_beside(5, k.block(2, 2, 1), _B)),
        ),
    ),
    _c(
        "wo-06",
        WO,
        "Five cubes high, one cube wide: a tower, in the centre.",
        one(T(5), reg("centre")),
    ),
    _c(
        "wo-07",
        WO,
        "From the left edge 10 cm, from the back edge 10 cm: a 10 cm tower.",
        one(T(2), _off_edge(_L, 0.10), _off_edge(_B, 0.10)),
    ),
    _c(
        "wo-08",
        WO,
        "Finally, put a cube on top; but first, build a 2x2 block two high in the centre.",
        one(_topped(k.block(2, 2, 2)), reg("centre")),
    ),
    _c(
        "wo-09",
        WO,
        "Three cubes long, two cubes wide and two cubes high — could you build me a block like "
        "that, please?",
        one(k.block(3, 2, 2)),
    ),
    _c(
        "wo-10",
        WO,
        "Across the bottom of the page, six squares in a row.",
        one(k.row(6), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-11",
        WO,
        "To the right of the pyramid, a tower of four. The pyramid has three levels.",
        k.any_of(
            k.pair(T(4), k.pyramid(3), k.on_side(_R)),
            one(_col_beside(4, k.pyramid(3), _R)),
        ),
    ),
    _c("wo-12", WO, "Two layers, 20 by 10 cm: the block I need.", one(k.block(4, 2, 2))),
    _c(
        "wo-13",
        WO,
        "A staircase, please, with four steps — going up away from the robot, if that's all right.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "wo-14",
        WO,
        "The bridge after the wall, please: first a wall four long and two high on the right, "
        "then a bridge with legs of two on the left.",
        k.structures(
            k.all_of(k.wall(4, 2), reg("right")),
            k.all_of(_span(2), reg("left")),
        ),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Good morning! I work in accounts upstairs and this is my very first open day. I'd be "
        "delighted if the robot could build a tower of four cubes.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "Morning, team. Two jobs this shift. First, a row of five at the front. After that, a "
        "tower of three at the back. Thanks.",
        k.structures(k.all_of(k.row(5), reg("front")), k.all_of(T(3), reg("back"))),
    ),
    _c(
        "fil-03",
        FIL,
        "The last batch went well. Build a 3x3 slab, one layer, at the front right.",
        one(k.block(3, 3, 1), reg("front right")),
    ),
    _c(
        "fil-04",
        FIL,
        "I found this sketch in the drawer from last week's trial; it's a bit smudged but "
        "readable. It shows a staircase of three steps climbing towards the top of the page.",
        one(k.staircase(3), k.rises(_B)),
    ),
    _c(
        "fil-05",
        FIL,
        "Calibration checked at 08:15, all tolerances within 0.5 mm. Build a 20 cm tower.",
        one(T(4)),
    ),
    _c(
        "fil-06",
        FIL,
        "Oh, this is so exciting — I've seen videos of robots like this but never one in real "
        "life! Might I ask for a little wall, four cubes long and two high?",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-07",
        FIL,
        "Quick note from the supervisor's desk: forty parts still to ship today. First a "
        "pyramid of two levels on the left; after that, nothing more.",
        one(k.pyramid(2), reg("left")),
    ),
    _c(
        "fil-08",
        FIL,
        "The night shift left the table clear. Build a bridge with two legs of four and a beam.",
        one(_beam_bridge(4)),
    ),
    _c(
        "fil-09",
        FIL,
        "My colleague drew this on a napkin at lunch, so excuse the coffee stain. Seen from "
        "above: two squares side by side, touching, each marked 3.",
        one(k.block(1, 2, 3)),
    ),
    _c(
        "fil-10",
        FIL,
        "Room temperature 21 °C, humidity 40 %. Block 10 x 10 cm, 20 cm tall.",
        one(k.block(2, 2, 4)),
    ),
    _c(
        "fil-11",
        FIL,
        "I hope I'm not holding up the queue — my grandson is waiting outside with his two "
        "sisters. Could you make a row of three cubes for him to see?",
        one(k.row(3)),
    ),
    _c(
        "fil-12",
        FIL,
        "Safety walk at 2 pm, so keep the cell tidy. First a tower of five in the centre, and "
        "after that we're done.",
        one(T(5), reg("centre")),
    ),
    _c(
        "fil-13",
        FIL,
        "The gripper was replaced yesterday and it works fine. Build a ring five by five, two "
        "high.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "fil-14",
        FIL,
        "Measured the table again this morning: 60 cm x 50 cm, as expected. 25 cm row, left to "
        "right.",
        one(k.row(5), k.runs("y")),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Build a tower of four in the front left corner.",
        one(T(4), reg("front left")),
    ),
    _c(
        "reg-02",
        REG,
        "On the drawing of the table, the tower (4 high) is top left and the 2x2 square (one "
        "high) is bottom right.",
        k.structures(
            k.all_of(T(4), reg("back left")),
            k.all_of(k.block(2, 2, 1), reg("front right")),
        ),
    ),
    _c(
        "reg-03",
        REG,
        "15 cm tower, its centre 10 cm from the front edge and 15 cm from the left edge.",
        one(T(3), _off_edge(_F, 0.10, centre_only=True), _off_edge(_L, 0.15, centre_only=True)),
    ),
    _c(
        "reg-04",
        REG,
        "Would it be possible to put a little pyramid of two levels right in the middle of the "
        "table?",
        one(k.pyramid(2), reg("centre")),
    ),
    _c(
        "reg-05",
        REG,
        "First, a row of four at the back right. After that, a row of four at the back left.",
        k.structures(k.all_of(k.row(4), reg("back right")), k.all_of(k.row(4), reg("back left"))),
    ),
    _c(
        "reg-06",
        REG,
        "20 cm wall, 10 cm high, along the back edge and no more than 5 cm from it.",
        one(k.wall(4, 2), k.runs("y"), _hugs(_B, 0.05)),
    ),
    _c(
        "reg-07",
        REG,
        "On the sketch of the table the row runs down the right-hand side of the page, five "
        "squares long.",
        one(k.row(5), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-08",
        REG,
        "Build a 2x2 block, three high, at the back, centred left to right.",
        one(k.block(2, 2, 3), reg("back"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-09",
        REG,
        "20 cm tower, 10 cm in from the right edge and 20 cm in from the front edge.",
        one(T(4), _off_edge(_R, 0.10), _off_edge(_F, 0.20)),
    ),
    _c(
        "reg-10",
        REG,
        "Could you possibly build a staircase of three steps over on the right-hand side, near "
        "the robot?",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "reg-11",
        REG,
        "First a tower of three in each back corner. After that, a tower of two in each front "
        "corner.",
        k.structures(
            k.all_of(T(3), reg("back left")),
            k.all_of(T(3), reg("back right")),
            k.all_of(T(2), reg("front left")),
            k.all_of(T(2), reg("front right")),
        ),
    ),
    _c(
        "reg-12",
        REG,
        "Dead centre of the page, which is the table: a single square marked 6.",
        one(T(6), reg("centre")),
    ),
    _c(
        "reg-13",
        REG,
        "Build a row of six along the left edge, running front to back.",
        one(k.row(6), k.runs("x"), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-14",
        REG,
        "3 x 3 slab, 5 cm thick, centre at x = 0.6 m, y = 0.2 m.",
        one(k.block(3, 3, 1), k.near(0.60, 0.20, 0.02)),
    ),
    _c(
        "reg-15",
        REG,
        "I'd like a tower of three at the far end of the table, the side furthest from the "
        "robot, please.",
        one(T(3), reg("back")),
    ),
    _c(
        "reg-16",
        REG,
        "Build a tower of five in the back half of the table, on the right.",
        one(T(5), k.min_x(0.50), reg("right")),
    ),
    _c(
        "reg-17",
        REG,
        "Bottom left of the drawing of the table: a ring four squares by four, one high.",
        one(_PEN4, reg("front left")),
    ),
    _c(
        "reg-18",
        REG,
        "10 cm tower on the centre line, 40 cm from the front edge to its centre.",
        one(T(2), _off_edge(_F, 0.40, centre_only=True), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-19",
        REG,
        "Block 10 x 10 cm, 10 cm high, touching the right edge, 15 cm from the front edge.",
        one(k.block(2, 2, 2), _hugs(_R, 0.0), _off_edge(_F, 0.15)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "I don't mind what it is at all — could the robot just build something nice for the "
        "visitors?",
        k.anything,
    ),
    _c(
        "open-02",
        OPEN,
        "Build anything you like with no more than eight cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=8))),
    ),
    _c(
        "open-03",
        OPEN,
        "Any structure, nothing taller than 15 cm.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-04",
        OPEN,
        "The sketch of the table only shows a shaded patch in the top right corner with "
        "'anything' written in it.",
        k.all_of(k.anything, k.layout(reg("back right"))),
    ),
    _c(
        "open-05",
        OPEN,
        "First, something of your choice at the front. After that, a tower of three at the back.",
        k.all_of(k.anything, k.structures(reg("front"), k.all_of(T(3), reg("back")))),
    ),
    _c(
        "open-06",
        OPEN,
        "Build any shape with a gap underneath it.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-07",
        OPEN,
        "Could you build something with stairs in it? Whatever you think looks best.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-08",
        OPEN,
        "Anything, footprint no bigger than 15 x 15 cm.",
        k.all_of(k.anything, k.layout(_fits(3, 3))),
    ),
    _c(
        "open-09",
        OPEN,
        "First, build three separate things of your choice. After that, nothing else.",
        k.all_of(k.anything, _count(3)),
    ),
    _c(
        "open-10",
        OPEN,
        "The sketch is a blank page with 'your choice' written across it.",
        k.anything,
    ),
    _c(
        "open-11",
        OPEN,
        "Build something tall in the centre.",
        k.all_of(k.anything, k.layout(k.all_of(reg("centre"), k.height(lo=_TALL)))),
    ),
    _c(
        "open-12",
        OPEN,
        "Would the robot be able to build some sort of enclosure, any size, just so I can see "
        "how it works?",
        k.all_of(k.anything, k.some(k.ring)),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "Build a tower of fifteen cubes.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-02", BAD, "My sketch is attached.", k.honest(k.anything)),
    _c(
        "bad-03",
        BAD,
        "First, build a wall one metre long. After that, a tower of two next to it.",  # 20 cubes
        k.honest(k.anything),
    ),
    _c("bad-04", BAD, "Sphere, 15 cm diameter.", k.honest(k.anything)),
    _c("bad-05", BAD, "Excuse me, where is the coffee machine?", k.honest()),
    _c(
        "bad-06",
        BAD,
        "Build a tower of three cubes that is exactly 40 cm tall.",  # 3 cubes are 15 cm
        k.honest(one(k.any_of(T(3), T(8)))),
    ),
    _c(
        "bad-07",
        BAD,
        "20 cm tower, its centre 80 cm from the front edge.",  # x = 1.0: off the table
        k.honest(k.anything),
    ),
    _c(
        "bad-08",
        BAD,
        "On the drawing of the table the one tower is both in the top left and in the bottom "
        "right corner.",
        k.honest(k.anything),
    ),
    _c(
        "bad-09",
        BAD,
        "First, a pyramid of three levels. After that, cancel everything and build nothing.",
        k.honest(),
    ),
    _c(
        "bad-10",
        BAD,
        "Bonjour, pourriez-vous construire une tour de trois cubes, s'il vous plaît ?",
        k.honest(one(T(3))),
    ),
    _c("bad-11", BAD, "Qwpoeiruty zxmcnv.", k.honest()),
    _c(
        "bad-12",
        BAD,
        "Tower 12.5 cm tall.",  # two and a half cubes
        k.honest(one(k.any_of(T(2), T(3)))),
    ),
    _c(
        "bad-13",
        BAD,
        "20 cm tower, centre 5 cm behind the back edge.",
        k.honest(k.anything),
    ),
    _c(
        "bad-14",
        BAD,
        "Could you build a cone, please, about fifteen centimetres high?",
        k.honest(k.anything),
    ),
    _c(
        "bad-15",
        BAD,
        "First, put a tower of four on top of the blue box. After that, a row of three.",
        k.honest(k.anything),
    ),
    _c(
        "bad-16",
        BAD,
        "Build a ring eleven cubes by eleven, one high.",  # 11 across: past the cell's 10
        k.honest(k.anything),
    ),
    _c("bad-17", BAD, "The sketch shows one square marked -2.", k.honest(k.anything)),
    _c("bad-18", BAD, "Wall 30 cm long, 0 cm high.", k.honest(k.anything)),
]
