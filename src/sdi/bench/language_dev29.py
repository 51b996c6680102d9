"""A twenty-ninth held-out set for the language front end (dev29): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev28` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is deliberately mainstream: about
80 % of the commands are what a person at a robot cell would really type — one or two
structures with a size, a place, one relation or a two-step sequence, in plain but varied
English (build / make / put / place / stack / set up / lay out / give me / I need / could you;
the place first or the size last; sizes as words, digits, "2 by 4", cm, mm, metres, a foot and
inches; articles dropped now and then; casual punctuation) — and they come from five kinds of
people, none of them used by an earlier set:

* a lab manager writing short requests in the team's shared chat: "@Sam", "+1", "re Priya's
  question — yes", "Edit: 3 not 5" (the edit replaces the figure), "pls", "thx", an emoji.
  A reply to a colleague's question is a request like any other; a chat message that asks
  for something other than a build (the gripper's calibration) is bad input;
* someone who asks rather than orders: "Can it do a …?", "Could you …?", "How about a …?",
  "Would a … work at the back?", "Is that doable?". Each of these means "build this"; a
  question that is not a request for a build ("what can you build?", "how tall can a tower
  get before it falls?") is bad input and admits only a refusal (or a failure);
* an operator who describes the wanted result as it should look when finished: "When done
  there should be …", "End state: …", "Final layout: …", "I want to see …", "once it's
  finished …". The finished state is what counts, so "then take two off" or "the two middle
  cubes should be gone" describe what is left; "nothing else on the table" means exactly the
  structures named;
* an Irish or North-American operator with everyday regional phrasing: "grand" (fine, good),
  "yous" / "ya" (you), "us" (me), "gonna", "kinda", "yeah?", "eh", "like" at the end of a
  sentence (emphasis), "sure look", "howya", "good man", "the other fella's build" (somebody
  else's, here not on the table), "throw up" / "stick" (build, put). "A couple" is exactly
  two, "a few" is three or four, "a bunch" of towers is three to eight, "a good five
  levels" is five;
* a demo presenter narrating to an audience as they type: "Now watch — I'll ask it for …",
  "For this next one …", "Step one … Step two …", "oh wait, folks, I meant …" (the last
  word wins). The narration is filler, and "typing live" or "sloppy" excuses the typos.

About 80 % ordinary and 20 % harder: three structures, references ("on top of that", "the
taller one", "its left"), distributive phrases ("a cube on each corner", "a tower of two in
front of each end", "a cube's gap between each"), comparisons ("three times as tall", "half
their height"), removals ("knock the top row off", "the two middle cubes should be gone"),
corrections in the same message and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "next to" / "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by its column heights);
  "right next to" is at most 10 cm clear, or touching; "touching" is one structure; "not
  touching", "don't let 'em touch", "none touching" mean separate structures;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none is
  said; a tower "in front of" or "behind" a wall or a row may stand against it as one
  structure (the tower's column then lies on that side of the rest); "in front of each end"
  of a row puts a tower square to each end cube (centres lined up ± 3 cm), clear of the row
  or against it;
* "N cubes apart" / "a cube's gap" / "a cube between them" is the clear gap (± 1.5 cm); a bare
  "10 cm apart" accepts the clear gap and the centre-to-centre reading;
* a bridge's or goalpost's top is a beam where the command names one (two posts under the
  beam, the overall height one more than the posts), a beam or a bar of cubes where it does
  not, and a bar of cubes only with "cubes only across the top"; a table is four separate
  legs under one connected top of beams or of cubes;
* a ring's stated size is its outside; "in the middle of" a ring is inside its empty
  interior with the centres within 3 cm; a tower "inside" a ring is anywhere in the interior,
  clear of the ring or standing against its wall (then one structure);
* a staircase's width is free unless given, and so is the way it climbs unless said; "a
  staircase 20 cm tall" has four one-cube steps; a pyramid's step is free unless the levels
  fix it ("base 4 by 4, four levels" is 16-9-4-1); "a cube on top of a 2x2 block" leaves the
  block's height free;
* "a foot" is six cubes (30.5 cm) and "four inches" two (10.2 cm); "under"/"no taller than
  20 cm" is at most four cubes; "something tall" is at least four cubes high; "kinda small"
  is `language_checks.small`; "something with steps in it" is a staircase or a pyramid;
  "some kind of enclosure" is a ring;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "near the robot" is the front; "along the back edge" is every part at x ≥ 0.60, "as far
  from the robot as it'll go" the same; "nothing in the front half" is every part at x ≥
  0.50 and "not in the back half" every part at x ≤ 0.50; "along the left edge" is a
  footprint centre at y ≥ 0.45; "centred" at the front is on the centre line y = 0.30 ± 3 cm;
  a stated coordinate ("x=0.6, y=0.2", "x equals 0.4") is the footprint centre ± 2 cm.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`): gibberish, another language, contradictions, sizes past the cell,
shapes the cell cannot make (a sphere, a cone), a made-up word, a reference to something
that is not on the table. A message that asks for no build at all, or calls the build off,
admits only the refusal (or a failure). Geometry comes only from `sdi.bench.boxes`, through
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
    return Case(id=f"dev29-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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
    than the posts; the posts `mouth` cubes apart clear (± 1.5 cm) when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _span(posts: int) -> k.Check:
    """A bridge with no beam named: two posts `posts` high with a beam (one layer above the
    posts) or a bar of cubes across the tops."""
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


def _next_to(a: k.Check, b: k.Check, tower_h: int, max_gap: float = 0.25) -> k.Pred:
    """A (a tower `tower_h` high) next to B: two structures no more than `max_gap` clear, or
    the tower set against B as one structure."""
    return k.any_of(k.pair(a, b, k.within(max_gap)), k.one(k.with_column(tower_h, b)))


def _behind_or_against(h: int, other: k.Check, side: str) -> k.Pred:
    """A tower `h` high on `side` of `other`: separate (any distance), or set against it."""
    return k.any_of(
        k.pair(k.tower(h), other, k.on_side(side)),
        k.one(_col_beside(h, other, side)),
    )


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


def _hub(hub: k.Check, *arms: tuple[k.Check, k.Rel]) -> k.Pred:
    """Exactly 1 + len(arms) separate structures: one passing `hub`, and for each arm
    (check, rel) another structure passing the check with rel(arm, hub) — "a tower of 5, a
    tower of 3 to its left and a row in front of the taller one"."""
    n = 1 + len(arms)

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != n:
            return f"{len(comps)} separate structures, want {n}"
        first: k.Reason = None
        for order in itertools.permutations(range(n)):
            h = comps[order[0]]
            r = hub(h)
            if r is None:
                for (check, rel), i in zip(arms, order[1:], strict=True):
                    r = check(comps[i]) or rel(comps[i], h)
                    if r:
                        break
            if r is None:
                return None
            first = first or r
        return first

    return f


def _wholly_on(side: str) -> k.Rel:
    """A lies wholly on `side` of B: beyond B's face on that side (touching allowed)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (alo, ahi), (blo, bhi) = bx.bounds(a), bx.bounds(b)
        ok = {
            _F: ahi[0] <= blo[0] + bx.TOL,
            _B: alo[0] >= bhi[0] - bx.TOL,
            _R: ahi[1] <= blo[1] + bx.TOL,
            _L: alo[1] >= bhi[1] - bx.TOL,
        }[side]
        return None if ok else f"not wholly {side} of the other"

    return rel


def _at_each_end(row: k.Check, arm: k.Check, side: str, tol: float = 0.03) -> k.Pred:
    """Three separate structures: one passing `row` and two passing `arm`, each arm wholly on
    `side` of the row and square to a different end cube of it (centres lined up ± tol along
    the row)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != 3:
            return f"{len(comps)} separate structures, want 3"
        first: k.Reason = None
        for i, rw in enumerate(comps):
            r = row(rw)
            arms = comps[:i] + comps[i + 1 :]
            if r is None:
                fx, fy = bx.footprint_cubes(rw)
                axis = 1 if fy > fx else 0
                lo, hi = bx.bounds(rw)
                ends = (lo[axis] + bx.CUBE / 2, hi[axis] - bx.CUBE / 2)
                hit: set[int] = set()
                for a in arms:
                    r = arm(a) or _wholly_on(side)(a, rw)
                    if r is None:
                        c = bx.centre(a)[axis]
                        near = [e for e in (0, 1) if abs(c - ends[e]) <= tol]
                        if not near:
                            r = "an arm is not at an end of the row"
                        else:
                            hit.add(near[0])
                    if r:
                        break
                if r is None and len(hit) != 2:
                    r = "both arms at one end"
            if r is None:
                return None
            first = first or r
        return first

    return f


def _towers_in_line(lo: int, hi: int) -> k.Pred:
    """Between `lo` and `hi` single-column towers of any heights, in one line along x or y."""
    any_tower = k.tower(lo=1, hi=10)
    return k.any_of(
        *[k.in_order(axis, *[any_tower] * n) for n in range(lo, hi + 1) for axis in ("x", "y")]
    )


def _max_x(x: float) -> k.Check:
    """Every part lies at x ≤ `x` (m): no further from the robot than that."""

    def f(bs: k.Boxes) -> k.Reason:
        top = max(b.hi[0] for b in bs)
        return None if top <= x + bx.TOL else f"a part reaches x {top:.3f}, want ≤ {x}"

    return f


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


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_ANY_TOWER = T(lo=1, hi=10)
_RING4 = k.all_of(k.ring_of(inner=(2, 2)), k.dims(4, 4))  # a 4 × 4 ring of any height


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "@Sam yes, a tower of 4 with a tower of 2 beside it. Both on the left pls",
        k.any_of(
            k.pair(
                k.all_of(T(4), reg("left")),
                k.all_of(T(2), reg("left")),
                k.within(0.25),
            ),
            one(k.cell_heights(4, 2), reg("left")),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "Can it put a single cube on top of a 2x2 block?",
        one(_topped(k.solid(2, 2))),
    ),
    _c(
        "rel-03",
        REL,
        "End state: a wall 5 long and 2 high across the back, with a tower of 3 in front of "
        "it, not touching.",
        k.pair(T(3), k.all_of(k.wall(5, 2), k.runs("y"), reg("back")), k.on_side(_F)),
    ),
    _c(
        "rel-04",
        REL,
        "Could yous put a tower of three behind a row of four? Grand.",
        _behind_or_against(3, k.row(4), _B),
    ),
    _c(
        "rel-05",
        REL,
        "Now watch — I'll ask it for a ring, 5 by 5, one high, with a single cube right in the "
        "middle of it.",
        k.pair(_PEN5, T(1), k.centred_in(0.03)),
    ),
    _c(
        "rel-06",
        REL,
        "Re Priya's question — yes, the bridge. Two posts of 3, beam across.",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-07",
        REL,
        "Would a tower of five work to the left of a 3-step staircase?",
        k.pair(T(5), k.staircase(3), k.on_side(_L)),
    ),
    _c(
        "rel-08",
        REL,
        "I want to see a 3x3 slab with a tower of 2 standing on its centre cube.",
        one(k.plan_heights("111", "131", "111")),
    ),
    _c(
        "rel-09",
        REL,
        "Gonna need two towers of 4 with a beam on top, kinda like a goalpost, the towers a "
        "cube apart.",
        one(_beam_bridge(4, 1)),
    ),
    _c(
        "rel-10",
        REL,
        "For this next one I'm typing: pyramid of three levels, and a tower of six behind it.",
        k.pair(T(6), k.pyramid(3), k.on_side(_B)),
    ),
    _c(
        "rel-11",
        REL,
        "pls do a 2x2 block 2 high between two towers of 5, all in a line",
        k.between_(k.block(2, 2, 2), T(5)),
    ),
    _c(
        "rel-12",
        REL,
        "How about a wall, six long and three high, with a cube sitting on each end?",
        one(k.profile(4, 3, 3, 3, 3, 4)),
    ),
    _c(
        "rel-13",
        REL,
        "When it's done there should be a 4-step staircase and a single cube on its top step.",
        one(_topped(k.staircase(4))),
    ),
    _c(
        "rel-14",
        REL,
        "Put a tower of 2 inside a ring of 4 by 4 for us, would yous?",
        k.any_of(k.around(T(2), _RING4), one(k.holding(T(2), _RING4))),
    ),
    _c(
        "rel-15",
        REL,
        "Here's a classic: a table — four legs, three high — and then a tower of two standing "
        "on top of that.",
        one(k.on_top(T(2), _roofed(4, 3))),
    ),
    _c(
        "rel-16",
        REL,
        "ok so: row of 6 across the back, then a tower of 2 in front of each end of it",
        k.any_of(
            _at_each_end(k.all_of(k.row(6), k.runs("y"), reg("back")), T(2), _F),
            one(k.plan_heights("111111", "2....2"), k.upper_side(_F, 1), reg("back")),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Can you stack a 2 by 2 block, 2 high, on top of a 4 by 4 slab?",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)), k.levels(16, 4, 4)),
    ),
    _c(
        "rel-18",
        REL,
        "Final layout: two walls, each 4 long and 2 high, running front to back and parallel, "
        "3 cubes apart.",
        k.pair(
            k.all_of(k.wall(4, 2), k.runs("x")),
            k.all_of(k.wall(4, 2), k.runs("x")),
            k.parallel_gap(3),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "Stick a 3x3 block up, 2 high, with a tower of 6 right next to it.",
        _next_to(T(6), k.block(3, 3, 2), 6, max_gap=0.10),
    ),
    _c(
        "rel-20",
        REL,
        "I'll ask for three things: a tower of 5, a tower of 3 to its left, and a row of 4 in "
        "front of the taller one.",
        _hub(T(5), (T(3), k.on_side(_L)), (k.row(4), k.on_side(_F))),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "Tower of 5, back right. Edit: 3 not 5", one(T(3), reg("back right"))),
    _c(
        "seq-02",
        SEQ,
        "Could it build a row of four and then put a second row on top of it?",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "First a 3x3 slab, then a 2x2 layer on that, then one cube on top — so at the end it's "
        "a little pyramid.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Build a tower of 7, then take a couple cubes off the top.",
        one(T(5)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Step one, I'll get it to build a wall 4 long, 2 high. Step two, a tower of 3 in front "
        "of it.",
        _behind_or_against(3, k.wall(4, 2), _F),
    ),
    _c(
        "seq-06",
        SEQ,
        "lay out a slab 2 by 4 first, then stack another layer the same on it",
        one(k.block(2, 4, 2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Can you build two towers of four, then knock one of them down to two?",
        k.structures(T(4), T(2)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Start with a row of 6 across the front; when finished, the two middle cubes should be "
        "gone.",
        k.all_of(
            k.pair(
                k.all_of(k.row(2), k.runs("y")),
                k.all_of(k.row(2), k.runs("y")),
                k.all_rels(k.gap_of(2), k.either(k.on_side(_L), k.on_side(_R))),
            ),
            k.layout(reg("front")),
        ),
    ),
    _c(
        "seq-09",
        SEQ,
        "Make a staircase of 3 steps and then a tower of 4 to the right of it, grand job.",
        k.pair(T(4), k.staircase(3), k.on_side(_R)),
    ),
    _c(
        "seq-10",
        SEQ,
        "First, a tower of six in the centre. Now — I'm changing my mind live — make it four.",
        one(T(4), reg("centre")),
    ),
    _c(
        "seq-11",
        SEQ,
        "Put up the 5x5 ring, 1 high, then drop a 2-tower in the middle",
        k.pair(_PEN5, T(2), k.centred_in(0.03)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Could you make a 2x2 block three high and then take the top layer off?",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "seq-13",
        SEQ,
        "After both steps I want: a bridge with legs of 2 on the left and, once it's up, a "
        "tower of 3 on the right.",
        k.structures(k.all_of(_span(2), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "seq-14",
        SEQ,
        "Put a row of 3 down, then add a bunch more on the same line so it's 7 long.",
        one(k.row(7)),
    ),
    _c(
        "seq-15",
        SEQ,
        "First the pyramid — base 4 by 4, four levels. Then, to finish it off, I'll have it "
        "remove the top cube.",
        one(k.pyramid_counts(16, 9, 4)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Tower of 4 front left, then same again back left",
        k.structures(k.all_of(T(4), reg("front left")), k.all_of(T(4), reg("back left"))),
    ),
    _c(
        "seq-17",
        SEQ,
        "Can it build a wall three high and five long, then knock the top row off?",
        one(k.wall(5, 2)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Build three towers of 3 in a row a cube apart, then add two cubes to the middle one — "
        "I want the middle standing at 5 when it's done.",
        k.line(T(3), T(5), T(3), gaps=(1,)),
    ),
    _c(
        "seq-19",
        SEQ,
        "Do a tower of 2, then another tower of 2 on top of it — so one tower of 4, yeah?",
        one(T(4)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Okay, a 3 by 3 slab on the left — oh wait, folks, I meant the right.",
        one(k.block(3, 3, 1), reg("right")),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "need 3 towers of 4, spaced a cube apart, in a line", k.in_line(3, T(4), 1)),
    _c("num-02", NUM, "Can it do a tower of nine?", one(T(9))),
    _c(
        "num-03",
        NUM,
        "When done there should be a couple of rows of five, one behind the other with a cube "
        "between them.",
        k.pair(
            k.row(5),
            k.row(5),
            k.all_rels(k.parallel_gap(1), k.on_side(_B)),
        ),
    ),
    _c(
        "num-04",
        NUM,
        "Gimme a few towers of 2, yous can space 'em however.",
        k.few(3, 4, T(2)),
    ),
    _c(
        "num-05",
        NUM,
        "And now eight cubes in a single row, front to back.",
        one(k.row(8), k.runs("x")),
    ),
    _c(
        "num-06",
        NUM,
        "Block 3 by 4, 2 layers, centre of the table",
        one(k.block(3, 4, 2), reg("centre")),
    ),
    _c("num-07", NUM, "How about two towers, one of 3 and one of 6?", k.structures(T(3), T(6))),
    _c(
        "num-08",
        NUM,
        "I want to see four single cubes in a row across the front, a cube's gap between each.",
        k.all_of(k.in_order("y", *[T(1)] * 4, gaps=(1,)), k.layout(reg("front"))),
    ),
    _c("num-09", NUM, "Make a pyramid, a good four levels on it.", one(k.pyramid(4))),
    _c(
        "num-10",
        NUM,
        "Watch this — a tower of two, and next to it one that's three times as tall.",
        k.any_of(k.pair(T(6), T(2), k.within(0.25)), one(k.cell_heights(6, 2))),
    ),
    _c("num-11", NUM, "2 staircases, 3 steps each, not touching", k.each(2, k.staircase(3))),
    _c(
        "num-12",
        NUM,
        "Could it do four towers going up from 1 to 4 cubes, left to right?",
        k.in_order("y", T(1), T(2), T(3), T(4)),
    ),
    _c(
        "num-13",
        NUM,
        "Once it's finished: a 4-level pyramid in the middle, nothing else on the table.",
        one(k.pyramid(4), reg("centre")),
    ),
    _c("num-14", NUM, "Throw up a wall, eh, 6 long and a couple high.", one(k.wall(6, 2))),
    _c(
        "num-15",
        NUM,
        "Let's try numbers: five towers, heights five, four, three, two, one, from front to back.",
        k.in_order("x", T(5), T(4), T(3), T(2), T(1)),
    ),
    _c("num-16", NUM, "tower of seven pls, we need it for the camera check", one(T(7))),
    _c(
        "num-17",
        NUM,
        "Can it put a cube on each corner of a 4 by 4 slab?",
        one(k.plan_heights("2112", "1111", "1111", "2112")),
    ),
    _c(
        "num-18",
        NUM,
        "End state: 3 towers, heights 2, 4 and 6, any order, none touching.",
        k.structures(T(2), T(4), T(6)),
    ),
    _c("num-19", NUM, "Could ya make a staircase with, like, five steps?", one(k.staircase(5))),
    _c(
        "num-20",
        NUM,
        "Two towers of four, and a third tower in between them that's half their height.",
        k.any_of(k.between_(T(2), T(4)), one(k.profile(4, 2, 4))),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Tower 25cm, front right", one(T(5), reg("front right"))),
    _c("dim-02", DIM, "Can it make a wall 30 cm long and 10 cm high?", one(k.wall(6, 2))),
    _c(
        "dim-03",
        DIM,
        "At the end there should be a slab 15 cm by 20 cm, one cube thick.",
        one(k.block(3, 4, 1)),
    ),
    _c("dim-04", DIM, "Build a tower about a foot tall, would ya.", one(T(6))),
    _c(
        "dim-05",
        DIM,
        "Next I'll ask for a block 100 mm by 150 mm, 100 mm high.",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "dim-06",
        DIM,
        "row 0.4 m long across the back",
        one(k.row(8), k.runs("y"), reg("back")),
    ),
    _c("dim-07", DIM, "How about a staircase 20 cm tall?", one(k.staircase(4))),
    _c(
        "dim-08",
        DIM,
        "I want to see a ring 25 cm across on the outside, 5 cm tall.",
        one(_PEN5),
    ),
    _c(
        "dim-09",
        DIM,
        "Could yous do a pyramid with a base about 25 centimetres square?",
        one(k.pyramid(), k.base(5, 5)),
    ),
    _c(
        "dim-10",
        DIM,
        "Now a bridge — pillars 15 centimetres high, and a beam across the top of them.",
        one(_beam_bridge(3)),
    ),
    _c("dim-11", DIM, "Wall 20 cm x 15 cm pls (long x high)", one(k.wall(4, 3))),
    _c("dim-12", DIM, "Would a tower 35 cm high fit at the back?", one(T(7), reg("back"))),
    _c(
        "dim-13",
        DIM,
        "When it's done I want two towers 15 cm tall, 10 cm apart.",
        k.pair(T(3), T(3), k.gaps(1, 2)),
    ),
    _c(
        "dim-14",
        DIM,
        "Lay down a 20 by 30 centimetre slab, one layer, on the left there.",
        one(k.block(4, 6, 1), reg("left")),
    ),
    _c(
        "dim-15",
        DIM,
        "I'll ask for a wall 250 millimetres long and 150 millimetres high, running front to back.",
        one(k.wall(5, 3), k.runs("x")),
    ),
    _c("dim-16", DIM, "2x2 block, 20cm tall", one(k.block(2, 2, 4))),
    _c("dim-17", DIM, "Can it do a row that's 35 centimetres long?", one(k.row(7))),
    _c(
        "dim-18",
        DIM,
        "Final result: a table with legs 10 cm tall and a top 15 cm square.",
        one(_roofed(4, 2), k.dims(3, 3)),
    ),
    _c(
        "dim-19",
        DIM,
        "Gonna need a wall a foot long and four inches high, eh.",
        one(k.wall(6, 2)),
    ),
    _c(
        "dim-20",
        DIM,
        "Let's do millimetres: a tower 300 mm tall, dead centre.",
        one(T(6), reg("centre")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Tower of 4 but not on the right side pls",
        one(T(4), k.not_(reg("right"), "on the right")),
    ),
    _c(
        "neg-02",
        NEG,
        "Can you do a pyramid of 3 levels without any beams?",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "At the end there shouldn't be anything in the front half — just a 2x3 block, two "
        "high, at the back.",
        one(k.block(2, 3, 2), k.min_x(0.50)),
    ),
    _c("neg-04", NEG, "Two towers of 5, and don't let 'em touch, yeah?", k.each(2, T(5))),
    _c(
        "neg-05",
        NEG,
        "Notice I'm saying no beams — a bridge, legs of two, cubes only across the top.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c("neg-06", NEG, "ring 4x4, 2 high, no gaps", one(k.ring_of(2, (2, 2)), k.dims(4, 4))),
    _c(
        "neg-07",
        NEG,
        "Would it be able to make a row of 6 that doesn't go left to right?",
        one(k.row(6), k.runs("x")),
    ),
    _c(
        "neg-08",
        NEG,
        "I want to see a 3x3 square of cubes with the middle one missing.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-09",
        NEG,
        "A staircase of 4, not going up towards the robot now.",
        one(k.staircase(4), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-10",
        NEG,
        "Here's a tricky one: a tower of five that is NOT in the back half.",
        one(T(5), _max_x(0.50)),
    ),
    _c(
        "neg-11",
        NEG,
        "Block 2x2, 3 high, not in the middle of the table",
        one(k.block(2, 2, 3), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-12",
        NEG,
        "Can it build two towers of 3 that aren't touching but are close, like under 10 cm?",
        k.pair(T(3), T(3), k.within(0.10)),
    ),
    _c(
        "neg-13",
        NEG,
        "Done state: an L shape, arms of 4, one high, and no other cubes anywhere.",
        one(k.shape_letter("L"), k.dims(4, 4), k.height(1)),
    ),
    _c(
        "neg-14",
        NEG,
        "Don't be putting it near the robot — a tower of 6 at the back there.",
        one(T(6), reg("back")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr of 4 at the bakc left pls", one(T(4), reg("back left"))),
    _c("typo-02", TYP, "Can it build a staircse of four setps?", one(k.staircase(4))),
    _c(
        "typo-03",
        TYP,
        "When finsihed there shoud be a wall, 5 lnog and 3 high.",
        one(k.wall(5, 3)),
    ),
    _c("typo-04", TYP, "Mkae us a pyrmaid of 3 levles there, grand.", one(k.pyramid(3))),
    _c(
        "typo-05",
        TYP,
        "Now I'll type fast and sloppy: brigde with posts of 3 and a beam acros the top",
        one(_beam_bridge(3)),
    ),
    _c("typo-06", TYP, "2x3 blcok, 2 hihg, front rigth", one(k.block(2, 3, 2), reg("front right"))),
    _c("typo-07", TYP, "Could yuo put a cube on tpo of a towre of 3?", one(T(4))),
    _c(
        "typo-08",
        TYP,
        "End sate: two towrs of 5, a cueb apart.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c("typo-09", TYP, "Gonna need a rign 5 by 5, one hihg, yeah?", one(_PEN5)),
    _c(
        "typo-10",
        TYP,
        "and a row of fvie acorss the front — sorry, typing live!",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c("typo-11", TYP, "slab 4x4 one layr in teh centre", one(k.block(4, 4, 1), reg("centre"))),
    _c("typo-12", TYP, "How abuot a tabel with four legs, two high?", one(_roofed(4, 2))),
    _c(
        "typo-13",
        TYP,
        "I wnat to see a tower of 3 on the lfet and a towre of 6 on the rigth.",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(6), reg("right"))),
    ),
    _c(
        "typo-14",
        TYP,
        "Cud ya do a wal 4 long, 2 hgih, along the bak?",
        one(k.wall(4, 2), k.runs("y"), reg("back")),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "back right: tower of 3. thx", one(T(3), reg("back right"))),
    _c(
        "wo-02",
        WO,
        "On the left, could it build a staircase of four steps?",
        one(k.staircase(4), reg("left")),
    ),
    _c(
        "wo-03",
        WO,
        "Two cubes high and six long — that's how the wall should look when it's done.",
        one(k.wall(6, 2)),
    ),
    _c(
        "wo-04",
        WO,
        "Three high, two by two, a block in the middle there, if yous would.",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    _c(
        "wo-05",
        WO,
        "At the front, centred, a row of five — that's what I'm typing in now.",
        one(k.row(5), reg("front"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "wo-06",
        WO,
        "on top of the 3x3 slab, a tower of 2, centred",
        one(k.plan_heights("111", "131", "111")),
    ),
    _c(
        "wo-07",
        WO,
        "Behind the wall, could there be a tower of 4? Wall's 5 long, 2 high.",
        _behind_or_against(4, k.wall(5, 2), _B),
    ),
    _c("wo-08", WO, "Of 7 cubes, one single tower — that's the end state.", one(T(7))),
    _c(
        "wo-09",
        WO,
        "Four by four, a ring, one high, put it over on the right, would ya.",
        one(_PEN4, reg("right")),
    ),
    _c(
        "wo-10",
        WO,
        "To the right of a tower of five, I'm asking for a tower of two.",
        k.pair(T(2), T(5), k.on_side(_R)),
    ),
    _c(
        "wo-11",
        WO,
        "6 long 3 high wall, front-to-back, left side",
        one(k.wall(6, 3), k.runs("x"), reg("left")),
    ),
    _c(
        "wo-12",
        WO,
        "A 4-step staircase, climbing towards the back — is that doable?",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "wo-13",
        WO,
        "In the front left corner a 2x2 block, one high, and in the back right corner a tower "
        "of 5 — that's how I want it to end up.",
        k.structures(
            k.all_of(k.block(2, 2, 1), reg("front left")),
            k.all_of(T(5), reg("back right")),
        ),
    ),
    _c(
        "wo-14",
        WO,
        "Right beside each other, two towers of 3, touching like.",
        one(k.cell_heights(3, 3)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning team! Hope everyone had a good weekend. For the 10:00 check, tower of 5 please.",
        one(T(5)),
    ),
    _c(
        "fil-02",
        FIL,
        "Hey, quick question, I'm new to this thing and not sure what it can handle — can it do "
        "a staircase of three steps?",
        one(k.staircase(3)),
    ),
    _c(
        "fil-03",
        FIL,
        "OK so for the photo on Friday the client wants it tidy. When done there should be one "
        "wall, 4 long and 2 high, along the back.",
        one(k.wall(4, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "fil-04",
        FIL,
        "Ah sure look, it's been a long week. Build us a 2x2 block, three high, and we'll call "
        "it a day.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Good afternoon everyone, thanks for coming. My name's Dana and I run this cell. Let's "
        "start simple — a tower of four.",
        one(T(4)),
    ),
    _c(
        "fil-06",
        FIL,
        "+1 to what Jo said. Also can we get a row of 6 on the left side, thx 🙏",
        one(k.row(6), reg("left")),
    ),
    _c(
        "fil-07",
        FIL,
        "Sorry if this is a dumb question, but would it be able to build a ring, 5 by 5, one high?",
        one(_PEN5),
    ),
    _c(
        "fil-08",
        FIL,
        "Long story short, the 3 o'clock group cancelled, so I just want to see a pyramid of "
        "three levels in the middle when it's finished.",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-09",
        FIL,
        "Ya know, the coffee machine's busted again, eh. Anyways, could ya build two towers of "
        "3 a cube apart?",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-10",
        FIL,
        "While the robot warms up, a quick word about safety — the light curtain stops it if "
        "you reach in. Right: a bridge with posts of two and a beam on top.",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-11",
        FIL,
        "Lunch is in the break room btw. Slab 3x5, one layer, front of the table.",
        one(k.block(3, 5, 1), reg("front")),
    ),
    _c(
        "fil-12",
        FIL,
        "Just wondering, since we've got the 2 visitors from head office, would a tower of six "
        "on the right look OK?",
        one(T(6), reg("right")),
    ),
    _c(
        "fil-13",
        FIL,
        "No rush on this, honestly, whenever the cell's free. Final state: a wall 3 long, 3 "
        "high, front left.",
        one(k.wall(3, 3), reg("front left")),
    ),
    _c(
        "fil-14",
        FIL,
        "Howya lads, grand day for it. Put up a staircase of 5 for us there, good man.",
        one(k.staircase(5)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "tower of 3 at x=0.6, y=0.2 pls",
        one(T(3), k.near(0.60, 0.20, 0.02)),
    ),
    _c(
        "reg-02",
        REG,
        "Can it put a block, 2 by 2 and 2 high, in the back left corner?",
        one(k.block(2, 2, 2), reg("back left")),
    ),
    _c(
        "reg-03",
        REG,
        "When done I want to see a row of 4 running front to back down the right side.",
        one(k.row(4), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-04",
        REG,
        "Stick a pyramid of 2 levels over in the front right corner there.",
        one(k.pyramid(2), reg("front right")),
    ),
    _c(
        "reg-05",
        REG,
        "Now I'll ask for a tower of four at x equals 0.4 — that's 40 cm out from the robot.",
        one(T(4), k.near(x=0.40, tol=0.02)),
    ),
    _c(
        "reg-06",
        REG,
        "Wall 8x2 along the back edge",
        one(k.wall(8, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-07",
        REG,
        "Could you put a 3-step staircase near the robot?",
        one(k.staircase(3), reg("front")),
    ),
    _c(
        "reg-08",
        REG,
        "End state: a tower of 5 right in the middle of the table, nothing else.",
        one(T(5), reg("centre")),
    ),
    _c(
        "reg-09",
        REG,
        "Gonna want a ring, 4 by 4, one high, up the back there.",
        one(_PEN4, reg("back")),
    ),
    _c(
        "reg-10",
        REG,
        "Let's use the far side of the table: a 2x3 slab, one layer, as far from the robot as "
        "it'll go.",
        one(k.block(2, 3, 1), k.min_x(0.60)),
    ),
    _c(
        "reg-11",
        REG,
        "2 towers of 4 — one back left, one back right",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "Would a wall 6 long, 2 high, work along the left edge?",
        one(k.wall(6, 2), k.runs("x"), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-13",
        REG,
        "I want the finished tower — 3 high — sitting at y = 0.45, x = 0.5.",
        one(T(3), k.near(0.50, 0.45, 0.02)),
    ),
    _c(
        "reg-14",
        REG,
        "Put a slab, 3 by 3, one layer, on the left-hand side, kinda towards the front.",
        one(k.block(3, 3, 1), reg("front left")),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "anything you like for the demo, max 8 cubes",
        k.all_of(k.anything, k.layout(_cubes(hi=8))),
    ),
    _c(
        "open-02",
        OPEN,
        "What would you build with up to ten cubes? Go on, build it.",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-03",
        OPEN,
        "When done there should be something tall on the right — your pick what.",
        k.all_of(k.anything, k.layout(k.all_of(reg("right"), k.height(lo=_TALL)))),
    ),
    _c(
        "open-04",
        OPEN,
        "Build whatever ya like, just keep it kinda small.",
        k.small,
    ),
    _c(
        "open-05",
        OPEN,
        "Let's see what it comes up with — I'm just typing: surprise us, build anything.",
        k.anything,
    ),
    _c(
        "open-06",
        OPEN,
        "something with an arch in it pls, any size",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-07",
        OPEN,
        "Could it build two things of its own choosing, not touching?",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-08",
        OPEN,
        "I just want to see something with steps in it when it's done.",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-09",
        OPEN,
        "Make a bunch of towers, any heights, in a row.",
        k.all_of(k.anything, _towers_in_line(3, 8)),
    ),
    _c(
        "open-10",
        OPEN,
        "For the finale I'll let it decide: any structure at all, so long as it's no taller "
        "than 20 cm.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-11",
        OPEN,
        "any shape, cubes only, inside a 3x3 footprint",
        k.all_of(k.anything, k.layout(k.all_of(k.only_cubes, _fits(3, 3)))),
    ),
    _c(
        "open-12",
        OPEN,
        "Can you build me some kind of enclosure? Any size.",
        k.all_of(k.anything, one(k.ring)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "see above", k.honest(k.anything)),
    _c("bad-02", BAD, "What can you build?", k.honest()),
    _c(
        "bad-03",
        BAD,
        "When done I want a tower 80 cm tall.",  # 16 cubes: past the cell's 10 levels
        k.honest(one(_ANY_TOWER)),
    ),
    _c("bad-04", BAD, "Build us a sphere there, about 10 cm across.", k.honest(k.anything)),
    _c(
        "bad-05",
        BAD,
        "And now, for something impossible: a wall two metres long.",  # 40 cubes
        k.honest(k.anything),
    ),
    _c("bad-06", BAD, "zxcvbnm qwerty", k.honest()),
    _c(
        "bad-07",
        BAD,
        "¿Puedes construir una torre de cuatro cubos?",
        k.honest(one(T(4))),
    ),
    _c(
        "bad-08",
        BAD,
        "End state: one tower, 3 high and 6 high at the same time.",
        k.honest(one(k.any_of(T(3), T(6)))),
    ),
    _c(
        "bad-09",
        BAD,
        "Any chance yous could make a cone, like a traffic cone?",
        k.honest(k.anything),
    ),
    _c("bad-10", BAD, "I'll now ask it to build a tower of zero cubes.", k.honest(k.anything)),
    _c(
        "bad-11",
        BAD,
        "Can someone check if the gripper's been calibrated since Monday?",
        k.honest(),
    ),
    _c("bad-12", BAD, "How tall can a tower get before it falls over?", k.honest()),
    _c(
        "bad-13",
        BAD,
        "When finished there should be a ring 20 by 20 cubes.",  # past the cell's 10 × 12
        k.honest(k.anything),
    ),
    _c("bad-14", BAD, "Ah forget it, don't build anything today, we're grand.", k.honest()),
    _c("bad-15", BAD, "Let's try a made-up word: build a florbnax.", k.honest()),
    _c("bad-16", BAD, "Tower of -2 pls", k.honest(k.anything)),
    _c(
        "bad-17",
        BAD,
        "Can it build a staircase that goes up and down at the same time, but stays flat?",
        k.honest(k.anything),
    ),
    _c(
        "bad-18",
        BAD,
        "Final state: two towers of 4, 90 cm apart.",  # past the cell's diagonal
        k.honest(k.anything),
    ),
    _c(
        "bad-19",
        BAD,
        "Gonna need a tower of 4 on top of the other fella's build.",  # nothing on the table
        k.honest(k.anything),
    ),
    _c(
        "bad-20",
        BAD,
        "Now a 3-step staircase with four steps, please.",
        k.honest(one(k.any_of(k.staircase(3), k.staircase(4)))),
    ),
]
