"""A twentieth held-out set for the language front end (dev20): five voices from the shop floor.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev19` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a production-line operator at the start of a shift, terse and practical ("4 stack front
  left", "row of 5 behind it", "singles across the front"). An "N stack" or "N tower" is one
  column of N cubes; "singles" are single cubes; "a couple" is two; "2x2 of 3 high" is a full
  2 × 2 block three cubes high. Corners and sides are the named regions below;
* a commissioning engineer at the cell writing precise instructions with millimetres,
  coordinates and tolerances. A coordinate ("x 450 y 200", "x = 0.45") is the centre of the
  structure's footprint in the cell frame (x away from the robot, y to its left), held to
  ± 5 mm or, where the engineer states one, to that tolerance plus 1 mm. "Clear" distances
  are face to face, "centre to centre" ones between footprint centres. A "course" is one
  layer of cubes. A robot-frame coordinate is used only with the frame offset stated;
* a shift supervisor's hand-over note to the next operator, with greetings, context and
  instructions mixed. The table is empty when the note is read: "put back", "rebuild", "the
  one from last night" mean build it afresh, and what a note says was removed is not built.
  A note that names nothing buildable (whatever someone asked for on Tuesday) is bad input;
* a warehouse / logistics worker who thinks in pallets, layers, rows and bays. A pallet or a
  pallet load is a full rectangle of cubes; a layer is one level of cubes; "N pallets high" of
  single-layer pallets is N layers; "per row" counts the cubes along a row; each bay holds a
  separate structure; an aisle is a clear gap between two structures, as wide as said (at
  least one cube when no width is given); "keep the aisle clear" means the structures do not
  touch;
* a voice-assistant transcript: speech to text with no punctuation, homophones ("for" / "fore"
  = four, "to" / "too" = two, "tree" = three, "won" = one, "ate" = eight, "hi" = high, "rite"
  = right), filler ("um", "uh", "like", "you know") and self-corrections, where the last word
  wins ("six no sorry seven" is seven). A garbled transcript with nothing usable is bad input.

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("the middle one", "where it
was", "the top step"), distributive phrases ("one on each side", "a second cube on every other
one"), comparisons ("twice as tall", "half that height", "one taller each"), corrections ("no,
make it 5"), removals ("take the top layer back off") and unusable input (gibberish, other
languages, contradictions, sizes past the cell, a request for nothing).

Each predicate checks parameters (heights, footprints in cubes, parts per level, number of
separate structures, relations, regions) and accepts every reasonable reading of vague wording,
and nothing else:

* "behind", "in front of", "to the left / right of" is the dominant direction between the
  footprint centres (back = +x, front = -x, left = +y, right = -y); with no gap stated any gap
  will do, but the two stay separate unless the command says they touch — where touching is a
  fair reading too ("a tower in front of the wall"), the single touching structure is accepted;
* "next to" is at most 25 cm apart; "one on each side" is a line along x or y; "evenly spaced"
  is equal clear gaps (± 1 cm);
* a bridge's top is a beam or a row of cubes unless the command names one; "a bridge N high"
  has legs of N, or legs of N - 1 under a bar whose top is N cubes up;
* "a wall A by B" is A long and B high, or the other way round; a T's stem is counted with or
  without the cell it shares with the bar; a pyramid's base and step are free unless given;
* the named regions are those of `sdi.bench.boxes.region_problem` on the footprint centre
  (left y > 0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of
  (0.45, 0.30)); "the very back" is a centre at x ≥ 0.60, "the right edge" one at y ≤ 0.15,
  "the left half" every part at y ≥ 0.30, "nothing in front of x 0.35" every part at x ≥ 0.35.

Same `Case` type and the same 11 phenomena as the other sets. Bad input is honest only as an
error (or a failure) or as a layout WITH notes naming the assumption (`k.honest`).

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 m; left = +y, back = +x (away from the
robot at x = 0, y = 0.30); the front is the robot's side (small x).
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

_MM5 = 0.006  # m: an engineer's coordinate, ± 5 mm (+ 1 mm)


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev20-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _lined_up(axis: str, tol: float = 0.011) -> k.Rel:
    """A's footprint centre matches B's along `axis` ("x" or "y") within `tol` m."""
    i = 0 if axis == "x" else 1

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        d = abs(bx.centre(a)[i] - bx.centre(b)[i])
        return None if d <= tol else f"centres {d:.3f} m apart along {axis}, want ≤ {tol}"

    return rel


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


def _all_apart(n: int) -> k.Pred:
    """At least two separate structures, every two of them at least `n` cubes apart, clear."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < 2:
            return "fewer than two structures"
        for a, b in itertools.combinations(comps, 2):
            r = _apart(n)(a, b)
            if r:
                return r
        return None

    return f


def _bar_on_posts(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """Two separate single columns on the table (`posts` cubes high when given) and, as the
    topmost level, one connected bar — a beam or a row of cubes — resting on both; the posts
    `mouth` cubes apart, clear (± 1.5 cm), when given."""

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
            r = k.tower(posts)(g) if posts is not None else k.tower(lo=1, hi=10)(g)
            r = r or k.on_table(g)
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
    """A bridge: two supports `posts` high with a beam or a bar of cubes across the top, the
    supports `mouth` cubes apart, clear, when given."""
    beam = k.bridge(posts, pillars=2)
    if mouth is not None:
        beam = k.all_of(beam, k.leg_gap(mouth))
    return k.any_of(beam, _bar_on_posts(posts, mouth))


def _past_top(n: int) -> k.Rel:
    """A stands `n` cubes clear (± 1.5 cm) of staircase B, on the side B climbs towards."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        up = bx.rises_towards(b)
        if up is None:
            return "B is not a staircase"
        return k.gap_of(n, up)(a, b)

    return rel


def _min_y(y: float) -> k.Check:
    """Every part lies at y ≥ `y` (m): on the left of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _centre_x_min(x: float) -> k.Check:
    """The footprint centre at x ≥ `x` (m): right at the back."""

    def f(bs: k.Boxes) -> k.Reason:
        cx = bx.centre(bs)[0]
        return None if cx >= x else f"centre x {cx:.3f}, want ≥ {x}"

    return f


def _centre_y_max(y: float) -> k.Check:
    """The footprint centre at y ≤ `y` (m): along the right edge."""

    def f(bs: k.Boxes) -> k.Reason:
        cy = bx.centre(bs)[1]
        return None if cy <= y else f"centre y {cy:.3f}, want ≤ {y}"

    return f


def _inside(x0: float, x1: float, y0: float, y1: float) -> k.Check:
    """Every part inside the rectangle x0–x1, y0–y1 (m)."""

    def f(bs: k.Boxes) -> k.Reason:
        (lx, ly, _), (hx, hy, _) = bx.bounds(bs)
        ok = lx >= x0 - bx.TOL and hx <= x1 + bx.TOL and ly >= y0 - bx.TOL and hy <= y1 + bx.TOL
        if ok:
            return None
        return f"spans x {lx:.3f}–{hx:.3f}, y {ly:.3f}–{hy:.3f}; want x {x0}–{x1}, y {y0}–{y1}"

    return f


def _has_beam(bs: k.Boxes) -> k.Reason:
    """At least one part is a beam (an edge of 15 cm)."""
    return None if any(max(b.size) >= 0.14 for b in bs) else "no beam"


def _fits(a: int, b: int) -> k.Check:
    """A footprint no bigger than a × b cubes (either orientation)."""
    want = tuple(sorted((a, b)))

    def f(bs: k.Boxes) -> k.Reason:
        got = bx.plan_dims(bs)
        ok = got[0] <= want[0] and got[1] <= want[1]
        return None if ok else f"footprint {got}, want within {want[0]}×{want[1]}"

    return f


def _evenly(axis: str, *checks: k.Check, tol: float = 0.01) -> k.Pred:
    """The structures in a line along `axis` in this order (front to back, or left to right),
    each pair of neighbours the same clear gap apart (± `tol`), none touching."""
    in_line = k.in_order(axis, *checks)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = in_line(result)
        if r:
            return r
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        i = 0 if axis == "x" else 1
        comps = sorted(comps, key=lambda g: bx.centre(g)[i])
        gaps = [bx.separation(a, b) for a, b in itertools.pairwise(comps)]
        if max(gaps) - min(gaps) > tol:
            return f"gaps {[round(g, 3) for g in gaps]} not even"
        return None

    return f


def _either_axis(*checks: k.Check, gaps: tuple[int, ...] = ()) -> k.Pred:
    """The structures in this order along x (front to back) or y (left to right)."""
    return k.any_of(k.in_order("x", *checks, gaps=gaps), k.in_order("y", *checks, gaps=gaps))


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
        "Stack of 4 over on the front left, and a line of 5 behind it with a bit of a gap.",
        k.all_of(
            k.pair(k.row(5), T(4), k.all_rels(k.on_side(_B), _near)),
            k.some(T(4), reg("front left")),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "Column of 3 centred on x 400 y 300. Second column of 3, 100 mm to the left of the "
        "first, centre to centre.",
        k.structures(
            k.all_of(T(3), k.near(0.40, 0.30, _MM5)),
            k.all_of(T(3), k.near(0.40, 0.40, _MM5)),
        ),
    ),
    _c(
        "rel-03",
        REL,
        "Hi Sam - table's clear, I packed the test pieces away. First job: a 2 by 2 block, 3 "
        "high, and a 5-tower on its right with a one-cube gap. Cheers, Priya",
        k.pair(T(5), k.block(2, 2, 3), k.gap_of(1, _R)),
    ),
    _c(
        "rel-04",
        REL,
        "Two pallet stacks, 2 by 2 footprint, three layers each, and leave an aisle two cubes "
        "wide between them.",
        k.pair(k.block(2, 2, 3), k.block(2, 2, 3), k.gap_of(2)),
    ),
    _c(
        "rel-05",
        REL,
        "um put a tower of for on the left and uh a tower of too on the right of it",
        k.pair(T(2), T(4), k.on_side(_R)),
    ),
    _c(
        "rel-06",
        REL,
        "bridge with 3-high legs. single cube in front of it, 2 cubes out",
        k.pair(T(1), _span(3), k.gap_of(2, _F)),
    ),
    _c(
        "rel-07",
        REL,
        "Wall 6 long, 2 high, running along y, centre line at x = 600. Put a 4-cube column in "
        "front of the wall's midpoint, 50 mm clear of its face.",
        k.all_of(
            k.pair(T(4), k.wall(6, 2), k.all_rels(k.gap_of(1, _F), _lined_up("y"))),
            k.some(k.wall(6, 2), k.runs("y"), k.near(x=0.60, tol=_MM5)),
        ),
    ),
    _c(
        "rel-08",
        REL,
        "For tomorrow's demo we need a 3-step staircase climbing towards the back, with a "
        "6-tower just past its top step, one cube clear.",
        k.pair(T(6), k.all_of(k.staircase(3), k.rises(_B)), k.gap_of(1, _B)),
    ),
    _c(
        "rel-09",
        REL,
        "Bay one on the left: a 3 by 2 pallet load, two layers. Bay two on the right: same "
        "again. Keep the aisle between the bays clear.",
        k.pair(k.block(2, 3, 2), k.block(2, 3, 2), k.all_rels(k.on_side(_L), _apart(1))),
    ),
    _c(
        "rel-10",
        REL,
        "okay so build a wall um five long two high and then a tower of tree in front of it "
        "like right in the middle",
        k.any_of(  # standing apart in front of the middle, or against the wall's front face
            k.pair(T(3), k.wall(5, 2), k.all_rels(k.on_side(_F), _lined_up("y"))),
            one(k.plan_heights("22222", "..3.."), k.upper_side(_F, 2)),
        ),
    ),
    _c(
        "rel-11",
        REL,
        "5 tower between two 2 towers, front to back, one cube apart each",
        k.in_order("x", T(2), T(5), T(2), gaps=(1,)),
    ),
    _c(
        "rel-12",
        REL,
        "Hollow square enclosure, outer dimensions 250 x 250 mm, one course high. Single "
        "column of 3 at its centre, +/-5 mm.",
        k.pair(
            k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)),
            T(3),
            k.centred_in(_MM5),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Left the base plate job unfinished, sorry. Please do it: a 3 by 3 slab, one layer, "
        "with a 4-tower standing on its back left corner.",
        one(k.plan_heights("511", "111", "111"), k.upper_side(_B, 1), k.upper_side(_L, 1)),
    ),
    _c(
        "rel-14",
        REL,
        "Drop a single-layer 4 by 2 pallet at the back, and put a 3-high stack in front of it, "
        "touching the pallet's front edge.",
        one(
            k.any_of(
                k.plan_heights("1111", "1111", "3..."),
                k.plan_heights("1111", "1111", ".3.."),
                k.plan_heights("3.", "11", "11", "11", "11"),
            ),
            k.upper_side(_F, 1),
            reg("back"),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "can you put a pyramid like three levels in the middle and then uh two single cubes one "
        "on each side of it a little way off",
        k.all_of(k.between_(k.pyramid(3), T(1)), k.some(k.pyramid(3), reg("centre"))),
    ),
    _c(
        "rel-16",
        REL,
        "Two rows of 4, parallel, both running along x, 100 mm clear between them.",
        k.pair(
            k.all_of(k.row(4), k.runs("x")),
            k.all_of(k.row(4), k.runs("x")),
            k.parallel_gap(2),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Note for nights: we had a 4-step staircase and a 2x2 tower of 3 side by side all day. "
        "Rebuild those two, stairs on the left, tower on the right, a couple of cubes between.",
        k.pair(k.staircase(4), k.block(2, 2, 3), k.gap_of(2, _L)),
    ),
    _c(
        "rel-18",
        REL,
        "Three pallet stacks in a row along the back wall, each 2 by 2 by 2, one-cube aisles "
        "between.",
        k.in_order("y", *[k.all_of(k.block(2, 2, 2), reg("back"))] * 3, gaps=(1,)),
    ),
    _c(
        "rel-19",
        REL,
        "build a staircase with for steps and then a tower the same height as the top step one "
        "cube past the top end",
        k.pair(T(4), k.staircase(4), _past_top(1)),
    ),
    _c(
        "rel-20",
        REL,
        "2 towers of 6, back corners, one left one right",
        k.structures(k.all_of(T(6), reg("back left")), k.all_of(T(6), reg("back right"))),
    ),
    _c(
        "rel-21",
        REL,
        "3-step staircase in the middle, and a 2 stack each side of it, left and right, one "
        "cube off",
        k.all_of(
            k.in_order("y", T(2), k.staircase(3), T(2), gaps=(1,)),
            k.some(k.staircase(3), reg("centre")),
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "three 2-stacks in a line left to right, one cube apart. then the middle one gets 3 "
        "more on it",
        k.in_order("y", T(2), T(5), T(2), gaps=(1,)),
    ),
    _c(
        "seq-02",
        SEQ,
        "Step 1: row of 6 along y at x = 500. Step 2: second course of 6 on top of it. Step 3: "
        "remove the two end cubes of the top course.",
        one(k.profile(1, 2, 2, 2, 2, 1), k.runs("y"), k.near(x=0.50, tol=_MM5)),
    ),
    _c(
        "seq-03",
        SEQ,
        "The tower of 7 on the right from the morning shift: take three off the top and set "
        "them up as their own stack on the left.",
        k.all_of(k.pair(T(3), T(4), k.on_side(_L)), k.some(T(4), reg("right"))),
    ),
    _c(
        "seq-04",
        SEQ,
        "First lay a 3 by 3 pallet, one layer. Then load two more layers on it, same size. Then "
        "take the top layer back off.",
        one(k.block(3, 3, 2)),
    ),
    _c("seq-05", SEQ, "make a row of six no sorry seven cubes", one(k.row(7))),
    _c(
        "seq-06",
        SEQ,
        "build a tower of five and then um put a tower of tree next to it and then actually no "
        "take the second one away",
        one(T(5)),
    ),
    _c(
        "seq-07",
        SEQ,
        "pyramid 3 levels, then knock the top off and put a 2 stack where it was",
        one(k.on_top(T(2), k.pyramid(2)), k.top_centred()),
    ),
    _c(
        "seq-08",
        SEQ,
        "Build a 4 x 4 slab, one layer, centred at x 500 y 300. Then a 2 x 2 x 2 block centred "
        "on the slab.",
        one(
            k.on_top(k.block(2, 2, 2), k.block(4, 4, 1)),
            k.centred(_MM5),
            k.near(0.50, 0.30, _MM5),
        ),
    ),
    _c(
        "seq-09",
        SEQ,
        "Whoever was on before you started a wall 5 long, 2 high and didn't finish it - add a "
        "third course and then it's done.",
        one(k.wall(5, 3)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Stack the first bay 2 by 3, two layers. Then move the top layer into the next bay over "
        "on its right, one-cube aisle between.",
        k.pair(k.block(2, 3, 1), k.block(2, 3, 1), k.gap_of(1, _R)),
    ),
    _c(
        "seq-11",
        SEQ,
        "put down a row of for and uh then on top of that another row of for and then one more "
        "on top so its like a wall",
        one(k.wall(4, 3)),
    ),
    _c("seq-12", SEQ, "tower of 8. no, make it 5. back right", one(T(5), reg("back right"))),
    _c(
        "seq-13",
        SEQ,
        "Sequence: (a) bridge, two 2-high pillars, beam across; (b) single cube on the beam at "
        "midspan; (c) nothing else.",
        one(k.bridge(2, pillars=2), k.top_centred(0.011), k.parts(6), k.height(4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Please put the 3-level pyramid (3x3, 2x2, 1) back up - it got knocked over at 2 am - "
        "and then a 2 tower to its left.",
        k.pair(T(2), k.pyramid_counts(9, 4, 1), k.on_side(_L)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Build a row of 5 single cubes along the front, then stack a second cube on every other "
        "one, starting at the left end.",
        one(k.lr_profile(2, 1, 2, 1, 2), reg("front")),
    ),
    _c(
        "seq-16",
        SEQ,
        "ok first a slab three by three then a tower of for on top in the middle wait no make "
        "the tower too",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(0.011)),
    ),
    _c(
        "seq-17",
        SEQ,
        "2x2 block 3 high. then lift the back half off and set it down as its own block behind, "
        "one gap",
        k.pair(k.block(1, 2, 3), k.block(1, 2, 3), k.gap_of(1, _B)),
    ),
    _c(
        "seq-18",
        SEQ,
        "Place a column of 5 at x 350 y 250. Then relocate it 200 mm in +x.",
        one(T(5), k.near(0.55, 0.25, _MM5)),
    ),
    _c(
        "seq-19",
        SEQ,
        "Heads up, the staircase we left up climbs the wrong way. Tear it down and rebuild it "
        "with 4 steps climbing to the left this time.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Last night's list, in order: (1) tower of 4 in the back left, (2) the same in the back "
        "right, (3) a row of 3 between them. Please do all three.",
        k.between_(k.row(3), k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "4 singles across the front, even spacing",
        _evenly("y", *[k.all_of(T(1), reg("front"))] * 4),
    ),
    _c(
        "num-02",
        NUM,
        "Two columns, 250 mm and 150 mm tall, 100 mm apart clear.",
        k.pair(T(5), T(3), k.gap_of(2)),
    ),
    _c("num-03", NUM, "i need um tree towers of too", k.each(3, T(2))),
    _c(
        "num-04",
        NUM,
        "build for towers won of each height from won to for",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    _c(
        "num-05",
        NUM,
        "A dozen cubes on one pallet: two layers, two rows of three per layer.",
        one(k.block(2, 3, 2)),
    ),
    _c(
        "num-06",
        NUM,
        "3 tower, and one twice as tall beside it, gap of 1",
        k.pair(T(6), T(3), k.gap_of(1)),
    ),
    _c(
        "num-07",
        NUM,
        "Use up exactly 20 cubes in one block: 5 long, 2 wide, 2 high.",
        one(k.block(2, 5, 2)),
    ),
    _c(
        "num-08",
        NUM,
        "Row of 8 cubes along y at x = 0.45, centred on y = 0.30.",
        one(k.row(8), k.runs("y"), k.near(0.45, 0.30, _MM5)),
    ),
    _c(
        "num-09",
        NUM,
        "Three bays, left to right: stacks of 2, 4 and 6 layers, single-cube footprint each, "
        "one-cube aisles.",
        k.in_order("y", T(2), T(4), T(6), gaps=(1,)),
    ),
    _c("num-10", NUM, "a pyramid with uh fore levels", one(k.pyramid(4))),
    _c(
        "num-11",
        NUM,
        "couple of 4-stacks, back of the cell, touching",
        one(k.block(1, 2, 4), reg("back")),
    ),
    _c(
        "num-12",
        NUM,
        "Yesterday's tower was 10 high, which was too tall for the camera. Build it three cubes "
        "shorter.",
        one(T(7)),
    ),
    _c(
        "num-13",
        NUM,
        "Staircase, 5 steps, step rise 50 mm, step run 50 mm.",
        one(k.staircase(5), k.long(5)),
    ),
    _c(
        "num-14",
        NUM,
        "Build a stack 3 pallets high, each pallet a 2 by 2 layer.",
        one(k.block(2, 2, 3)),
    ),
    _c("num-15", NUM, "make like a wall thats um ate long and too tall", one(k.wall(8, 2))),
    _c(
        "num-16",
        NUM,
        "3 towers: 2, 3, 4. tallest on the left. line them up, 1 apart",
        k.any_of(
            k.in_order("y", T(4), T(3), T(2), gaps=(1,)),
            k.in_order("y", T(4), T(2), T(3), gaps=(1,)),
        ),
    ),
    _c(
        "num-17",
        NUM,
        "Quantity 12 cubes, arranged 3 x 4, one layer, long side along x.",
        one(k.block_xy(4, 3, 1)),
    ),
    _c(
        "num-18",
        NUM,
        "Use all 9 cubes in the tray for a square slab, single layer, in the middle of the table.",
        one(k.block(3, 3, 1), reg("centre")),
    ),
    _c("num-19", NUM, "uh i want to towers of ate please", k.each(2, T(8))),
    _c(
        "num-20",
        NUM,
        "Five rows of two on one pallet, single layer.",
        one(k.block(2, 5, 1)),
    ),
    _c(
        "num-21",
        NUM,
        "three towers going up by won each starting at too from left to right",
        k.in_order("y", T(2), T(3), T(4)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Column, height 200 mm, at x 500 y 400.",
        one(T(4), k.near(0.50, 0.40, _MM5)),
    ),
    _c(
        "dim-02",
        DIM,
        "Wall: length 350 mm, height 100 mm, thickness 50 mm.",
        one(k.wall(7, 2)),
    ),
    _c(
        "dim-03",
        DIM,
        "Slab 150 x 200 mm, 50 mm thick, with the 200 mm side along x.",
        one(k.block_xy(4, 3, 1)),
    ),
    _c(
        "dim-04",
        DIM,
        "A pallet 20 cm by 10 cm, stacked 15 cm high.",
        one(k.block(2, 4, 3)),
    ),
    _c(
        "dim-05",
        DIM,
        "row 25 cm long, along the front",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c("dim-06", DIM, "a tower um forty centimetres tall", one(T(8))),
    _c(
        "dim-07",
        DIM,
        "a square block like ten centimetres on each side",
        one(k.block(2, 2, 2)),
    ),
    _c(
        "dim-08",
        DIM,
        "The fixture check needs a hollow rectangle, 6 cubes by 4 cubes on the outside, 2 high.",
        one(k.ring_of(high=2, inner=(2, 4)), k.dims(4, 6)),
    ),
    _c(
        "dim-09",
        DIM,
        "Bridge: pillar height 150 mm, clear span 100 mm between pillars, beam on top.",
        one(k.any_of(k.all_of(k.bridge(3, pillars=2), k.leg_gap(2)), _bar_on_posts(3, 2))),
    ),
    _c(
        "dim-10",
        DIM,
        "Build a block three layers high, four cubes along the aisle and two deep.",
        one(k.block(2, 4, 3)),
    ),
    _c("dim-11", DIM, "stairs, 4 steps, 2 wide", one(k.staircase(4), k.dims(2, 4))),
    _c("dim-12", DIM, "pyramid with a base of five by five", one(k.pyramid(), k.base(5, 5))),
    _c(
        "dim-13",
        DIM,
        "Build the calibration target: a 2 x 2 column of cubes 30 cm tall, where the old one "
        "stood - front right.",
        one(k.block(2, 2, 6), reg("front right")),
    ),
    _c(
        "dim-14",
        DIM,
        "L-shape, one course, legs 200 mm and 150 mm measured along the outside.",
        one(k.shape_letter("L"), k.dims(3, 4), k.height(1)),
    ),
    _c(
        "dim-15",
        DIM,
        "Pallet footprint 3 by 4, loaded 2 layers, with a single-cube marker on top at one corner.",
        one(k.plan_heights("3222", "2222", "2222")),
    ),
    _c(
        "dim-16",
        DIM,
        "um a t shape with the top bar five long and the stem tree long",
        one(k.shape_letter("T"), k.any_of(k.dims(4, 5), k.dims(3, 5))),
    ),
    _c(
        "dim-17",
        DIM,
        "Cross: arms 100 mm each from the centre cube, single course.",
        one(k.plan_heights("..1..", "..1..", "11111", "..1..", "..1..")),
    ),
    _c("dim-18", DIM, "wall 40 cm x 15 cm high, back edge", one(k.wall(8, 3), reg("back"))),
    _c(
        "dim-19",
        DIM,
        "For the vision test we need one tower exactly 0.35 m tall, nothing else on the table.",
        one(T(7)),
    ),
    _c(
        "dim-20",
        DIM,
        "A 3 by 3 pallet loaded 4 layers, then a second one half that height next to it, "
        "one-cube gap.",
        k.pair(k.block(3, 3, 2), k.block(3, 3, 4), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "tower of 5, not in the middle, put it back left",
        one(T(5), reg("back left")),
    ),
    _c("neg-02", NEG, "Wall 5 x 2, cubes only, no beams.", one(k.wall(5, 2), k.only_cubes)),
    _c(
        "neg-03",
        NEG,
        "Don't use the right half of the table tonight, the sensor there is being recalibrated. "
        "Build a 2-level pyramid on a 3 by 3 base on the left.",
        one(k.pyramid(2), k.base(3, 3), _min_y(0.30), reg("left")),
    ),
    _c(
        "neg-04",
        NEG,
        "Stack three pallets of 2 by 2, one layer each, on top of each other, but leave the "
        "front aisle clear - nothing in front of x 0.35.",
        one(k.block(2, 2, 3), k.min_x(0.35)),
    ),
    _c("neg-05", NEG, "build a tower of six no not six five", one(T(5))),
    _c(
        "neg-06",
        NEG,
        "3 towers of 3, none touching, none in the front",
        k.each(3, T(3), k.not_(reg("front"), "in the front")),
    ),
    _c(
        "neg-07",
        NEG,
        "Staircase, 3 steps, rising in -y. Do not rise toward +y.",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "neg-08",
        NEG,
        "Build a ring 4 by 4, one high - don't put anything inside it, the camera needs to see "
        "the floor through it.",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "neg-09",
        NEG,
        "A 2 by 4 pallet, two layers, but no cubes on the top layer's four corners.",
        one(k.plan_heights("1221", "1221")),
    ),
    _c(
        "neg-10",
        NEG,
        "make a row of five but dont let them touch like leave a little gap between each one",
        k.any_of(
            k.in_order("x", *[T(1)] * 5, max_gap=0.115),
            k.in_order("y", *[T(1)] * 5, max_gap=0.115),
        ),
    ),
    _c(
        "neg-11",
        NEG,
        "bridge 2 high, no beam, cubes for the top",
        one(
            k.any_of(_bar_on_posts(2), k.all_of(_bar_on_posts(1), k.height(2))),
            k.only_cubes,
        ),
    ),
    _c(
        "neg-12",
        NEG,
        "Two columns of 4, 150 mm centre to centre, not touching, aligned along x.",
        k.in_order("x", T(4), T(4), gaps=(2,)),
    ),
    _c(
        "neg-13",
        NEG,
        "No pyramids today whatever the sheet says - just a plain 3 by 3 block, 2 high.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "neg-14",
        NEG,
        "Fill a 3 by 3 bay one layer deep, except leave the middle spot empty for the forklift "
        "tine.",
        one(k.plan_heights("111", "1.1", "111")),
    ),
    _c(
        "neg-15",
        NEG,
        "a wall of for by tree but um without the beams just cubes",
        one(k.any_of(k.wall(4, 3), k.wall(3, 4)), k.only_cubes),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "twoer of 5 frnot rigth", one(T(5), reg("front right"))),
    _c("typo-02", TYP, "staris 4 setps", one(k.staircase(4))),
    _c(
        "typo-03",
        TYP,
        "Colum at x 450 y 250, hieght 150 mm.",
        one(T(3), k.near(0.45, 0.25, _MM5)),
    ),
    _c("typo-04", TYP, "Plaese rebuild the brdige, pilars 2 hihg, beam acros.", one(_span(2))),
    _c("typo-05", TYP, "3 layres of 2 by 3 on one palett", one(k.block(2, 3, 3))),
    _c("typo-06", TYP, "build a tower for cubes hi", one(T(4))),
    _c("typo-07", TYP, "make a pyramid tree levels tall", one(k.pyramid(3))),
    _c(
        "typo-08",
        TYP,
        "put won cube on the left and won on the rite",
        k.structures(k.all_of(T(1), reg("left")), k.all_of(T(1), reg("right"))),
    ),
    _c("typo-09", TYP, "wal 6 lnog 3 hgih", one(k.wall(6, 3))),
    _c(
        "typo-10",
        TYP,
        "Ring, outsdie 5x5, 1 corse, emtpy inside.",
        one(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c("typo-11", TYP, "Nedd a 2x2 blcok 4 tal at the bcak.", one(k.block(2, 2, 4), reg("back"))),
    _c(
        "typo-12",
        TYP,
        "row of 6 along teh back wal, sinlge layer",
        one(k.row(6), k.runs("y"), reg("back")),
    ),
    _c(
        "typo-13",
        TYP,
        "a staircase with to steps going up to the left",
        one(k.staircase(2), k.rises(_L)),
    ),
    _c("typo-14", TYP, "L shpae, arms of 3", one(k.shape_letter("L"), k.dims(3, 3))),
    _c(
        "typo-15",
        TYP,
        "build too walls each for long and to hi won behind the other",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.on_side(_B)),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "front left, 3 stack", one(T(3), reg("front left"))),
    _c(
        "wo-02",
        WO,
        "behind the 4 stack, a row of 3. 4 stack goes centre",
        k.all_of(k.pair(k.row(3), T(4), k.on_side(_B)), k.some(T(4), reg("centre"))),
    ),
    _c(
        "wo-03",
        WO,
        "At x 550 y 350: pyramid, 2 levels, base 3 x 3.",
        one(k.pyramid(2), k.base(3, 3), k.near(0.55, 0.35, _MM5)),
    ),
    _c(
        "wo-04",
        WO,
        "On the left, once you've had your coffee, a 4-step staircase please.",
        one(k.staircase(4), reg("left")),
    ),
    _c(
        "wo-05",
        WO,
        "Four layers high, three by two, that pallet goes in the back right bay.",
        one(k.block(2, 3, 4), reg("back right")),
    ),
    _c(
        "wo-06", WO, "five high is what i want the tower to be and on the right", one(T(5), reg(_R))
    ),
    _c(
        "wo-07",
        WO,
        "Beam across the top, two pillars under it, each 100 mm tall - that is the bridge.",
        one(k.bridge(2, pillars=2)),
    ),
    _c("wo-08", WO, "5 long 2 high wall. along the back.", one(k.wall(5, 2), reg("back"))),
    _c(
        "wo-09",
        WO,
        "To the right of the staircase (3 steps), a tower of 3; gap of 2 between them.",
        k.pair(T(3), k.staircase(3), k.gap_of(2, _R)),
    ),
    _c(
        "wo-10",
        WO,
        "In the middle bay a 2 by 2 stack 3 high, and on either side of it a single-cube "
        "marker, one cube off.",
        k.all_of(
            _either_axis(T(1), k.block(2, 2, 3), T(1), gaps=(1,)),
            k.some(k.block(2, 2, 3), reg("centre")),
        ),
    ),
    _c(
        "wo-11",
        WO,
        "on top of a three by three slab um put a tower of too",
        one(k.on_top(T(2), k.block(3, 3, 1))),
    ),
    _c(
        "wo-12",
        WO,
        "row of 4, single cubes, back to front, right side",
        one(k.row(4), k.runs("x"), reg("right")),
    ),
    _c(
        "wo-13",
        WO,
        "Height 3 courses, length 300 mm, wall, at the front.",
        one(k.wall(6, 3), reg("front")),
    ),
    _c(
        "wo-14",
        WO,
        "the left side is where the pyramid goes with tree levels",
        one(k.pyramid(3), reg("left")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "morning. coffee machine's broken again. anyway - 3 stack, centre, cheers",
        one(T(3), reg("centre")),
    ),
    _c(
        "fil-02",
        FIL,
        "Hi Jo, hope the weekend was good. Quick one before I head off: can you get the cell to "
        "build a wall 6 long, 3 high? The line lead wants photos for the audit. Thanks! - Mark",
        one(k.wall(6, 3)),
    ),
    _c(
        "fil-03",
        FIL,
        "um so like uh can you like build a pyramid with um two levels",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-04",
        FIL,
        "Right, lorry's late again so we've got time. Load a 3 by 3 pallet, two layers, and "
        "that's us done till it turns up.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-05",
        FIL,
        "Commissioning step 14 of 22, ref. CR-0831. Operator: J. Okafor. Action: build a "
        "staircase of 3 steps. Expected result: stairs present, no collisions.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-06",
        FIL,
        "hey robot uh hi um so yeah i was thinking maybe a tower of uh seven",
        one(T(7)),
    ),
    _c(
        "fil-07",
        FIL,
        "ok new batch incoming, ignore the racket from line 3. row of 4 please",
        one(k.row(4)),
    ),
    _c(
        "fil-08",
        FIL,
        "FYI the gripper was swapped this afternoon and it's fine now, I tested it on a few "
        "picks. Next thing is a bridge with 3-high legs - build it and leave it up for the "
        "morning.",
        one(_span(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Don't mind the beeping, that's the reach truck reversing. Give me 2 stacks of 4, single "
        "cubes, with an aisle of one between them.",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "fil-10",
        FIL,
        "Note: ambient 21 °C, humidity nominal, e-stop tested OK at 09:40. Build: 2 x 2 x 2 "
        "block centred at x 450 y 300.",
        one(k.block(2, 2, 2), k.near(0.45, 0.30, _MM5)),
    ),
    _c(
        "fil-11",
        FIL,
        "okay okay um so basically what i need is uh like an l shape you know with arms of four",
        one(k.shape_letter("L"), k.dims(4, 4)),
    ),
    _c("fil-12", FIL, "sorry was on the phone. right. 5 tower left side", one(T(5), reg("left"))),
    _c(
        "fil-13",
        FIL,
        "The night crew asked for something easy to check by eye, so nothing fancy: a single "
        "row of 5 cubes running front to back.",
        one(k.row(5), k.runs("x")),
    ),
    _c(
        "fil-14",
        FIL,
        "Stocktake's tomorrow so keep it tidy - one 2 by 4 pallet, one layer, back of the bay.",
        one(k.block(2, 4, 1), reg("back")),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "3 stack back left, 3 stack front right",
        k.structures(k.all_of(T(3), reg("back left")), k.all_of(T(3), reg("front right"))),
    ),
    _c("reg-02", REG, "Column of 6 at x 700 y 100.", one(T(6), k.near(0.70, 0.10, _MM5))),
    _c(
        "reg-03",
        REG,
        "Robot frame: column of 2 at x 450, y -100. The robot base sits at y 300 in cell "
        "coordinates, axes parallel.",
        one(T(2), k.near(0.45, 0.20, _MM5)),
    ),
    _c(
        "reg-04",
        REG,
        "Put the pyramid (2 levels, 3x3 base) at the front in the centre, where the camera can "
        "see it.",
        one(k.pyramid(2), k.base(3, 3), reg("front"), k.near(y=0.30, tol=0.05)),
    ),
    _c(
        "reg-05",
        REG,
        "Stack a 2 by 2, three high, in the bay at the back right.",
        one(k.block(2, 2, 3), reg("back right")),
    ),
    _c(
        "reg-06",
        REG,
        "put a wall of um four by too at the very back",
        one(k.any_of(k.wall(4, 2), k.wall(2, 4)), _centre_x_min(0.60)),
    ),
    _c(
        "reg-07",
        REG,
        "row of 6 down the right edge, front to back",
        one(k.row(6), k.runs("x"), _centre_y_max(0.15)),
    ),
    _c(
        "reg-08",
        REG,
        "Staircase, 3 steps, footprint entirely within x 0.55-0.80, y 0.05-0.25.",
        one(k.staircase(3), _inside(0.55, 0.80, 0.05, 0.25)),
    ),
    _c(
        "reg-09",
        REG,
        "Keep everything on the left half today - two towers of 4, anywhere on that side, not "
        "touching.",
        k.each(2, T(4), _min_y(0.30)),
    ),
    _c(
        "reg-10",
        REG,
        "Block in bay 1 - front left - 3 by 2, two layers. Block in bay 4 - back right - same "
        "size.",
        k.structures(
            k.all_of(k.block(2, 3, 2), reg("front left")),
            k.all_of(k.block(2, 3, 2), reg("back right")),
        ),
    ),
    _c(
        "reg-11",
        REG,
        "um put a tower of five in the uh in the middle of the table",
        one(T(5), reg("centre")),
    ),
    _c("reg-12", REG, "bridge, back right corner, legs 2", one(_span(2), reg("back right"))),
    _c(
        "reg-13",
        REG,
        "Ring, outside 4 x 4, one course, centred on the workspace centre (x 500, y 300).",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4), k.near(0.50, 0.30, _MM5)),
    ),
    _c(
        "reg-14",
        REG,
        "can you do a row of tree in the front right corner",
        one(k.row(3), reg("front right")),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "something tall, whatever's quick",
        k.all_of(k.anything, k.layout(k.height(lo=4))),
    ),
    _c(
        "open-02",
        OPEN,
        "Any structure you like for a reach test, but it must stay below 150 mm and inside x "
        "0.40-0.60.",
        k.all_of(k.anything, k.layout(k.all_of(k.low(3), _inside(0.40, 0.60, 0.05, 0.55)))),
    ),
    _c(
        "open-03",
        OPEN,
        "Surprise the morning shift with something - anything you like, as long as it uses beams.",
        k.all_of(k.anything, k.layout(_has_beam)),
    ),
    _c(
        "open-04",
        OPEN,
        "Stack up whatever you reckon fits on one 3 by 3 pallet.",
        k.all_of(k.anything, one(_fits(3, 3))),
    ),
    _c("open-05", OPEN, "um just build something cool i guess", k.anything),
    _c(
        "open-06",
        OPEN,
        "two of anything, spread out",
        k.all_of(k.anything, _count(2), _all_apart(1)),
    ),
    _c(
        "open-07",
        OPEN,
        "Free choice of shape. Constraint: exactly 10 cubes, no beams.",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(10), k.only_cubes))),
    ),
    _c(
        "open-08",
        OPEN,
        "If you get a minute, put up any kind of bridge for the new starter to look at.",
        k.all_of(k.anything, one(_ARCH)),
    ),
    _c(
        "open-09",
        OPEN,
        "Make any kind of stack, max four layers, and keep it in the back half.",
        k.all_of(k.anything, k.layout(k.all_of(k.low(4), reg("back")))),
    ),
    _c("open-10", OPEN, "make me some stairs any size", k.all_of(k.anything, one(k.staircase()))),
    _c(
        "open-11",
        OPEN,
        "something with at least 3 bits, not touching each other",
        k.all_of(k.anything, _count(3, 99)),
    ),
    _c(
        "open-12",
        OPEN,
        "Any enclosure, any size, one course high.",
        k.all_of(k.anything, one(k.ring, k.height(1))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "uh the um you know the thing the the", k.honest()),
    _c("bad-02", BAD, "tower 14 high front left", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-03",
        BAD,
        "Column of 4 at x 950 y 300.",  # x 0.95: past the back of the workspace
        k.honest(one(T(4))),
    ),
    _c("bad-04", BAD, "Build whatever Dave asked for on Tuesday.", k.honest(k.anything)),
    _c(
        "bad-05",
        BAD,
        "Row of 15 single cubes along the back wall, touching.",  # 15 > 12 cubes either way
        k.honest(one(k.row())),
    ),
    _c("bad-06", BAD, "mmm hmm yeah no totally ok bye", k.honest()),
    _c("bad-07", BAD, "Column of 3 with a footprint of 0 x 0 mm.", k.honest(one(T(3)))),
    _c(
        "bad-08",
        BAD,
        "Bitte einen Turm aus vier Würfeln bauen, links.",
        k.honest(one(T(4), reg("left"))),
    ),
    _c(
        "bad-09",
        BAD,
        "Pon una fila de cinco cubos al fondo.",
        k.honest(one(k.row(5), reg("back"))),
    ),
    _c("bad-10", BAD, "zzzkkrr tower krrk four kkhh", k.honest(one(T(4)))),
    _c(
        "bad-11",
        BAD,
        "3 towers of 3, all touching each other, with 2 cube gaps between them",
        k.honest(k.anything),
    ),
    _c(
        "bad-12",
        BAD,
        "Wall, 5 long, 2 high, centred at x 450 y 300, and a column of 4 centred at the same "
        "point.",
        k.honest(k.anything),
    ),
    _c("bad-13", BAD, "Take down the castle from last night.", k.honest()),
    _c(
        "bad-14",
        BAD,
        "Ten layers of 3 by 3, then two more layers on top of that.",  # 12 layers: past the cell
        k.honest(one(k.solid(3, 3))),
    ),
    _c("bad-15", BAD, "delete everything and then uh build nothing", k.honest()),
    _c(
        "bad-16",
        BAD,
        "Column, height -150 mm, at x 450 y 300.",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-17",
        BAD,
        "a floating row of 4, 10 cm off the table, nothing under it",
        k.honest(one(k.row(4))),
    ),
    _c(
        "bad-18",
        BAD,
        "Merci de construire un mur de six cubes de long et deux de haut.",
        k.honest(one(k.wall(6, 2))),
    ),
]
