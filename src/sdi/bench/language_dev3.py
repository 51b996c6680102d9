"""A third, independent development set for the language front end (dev3).

Written without looking at the Specifier's grammar, its tests or the frozen test set, and worded
apart from `language_dev` and `language_dev2` (no command shared with any set, see tests). The
commands are written as different people would type or say them:

* a terse maintenance technician ("row 4, back edge"), a chatty project manager, a student;
* a non-native speaker (articles missing, odd order: "make tower 4 cube high");
* someone dictating by voice (no punctuation, "um", homophones: "to towers of for");
* text pasted from a work order or a ticket, bullet and numbered lists, markdown;
* someone describing the end state ("I need to end up with…", "the final thing should…");
* questions ("can you stack 3 cubes?");
* mixed units (mm, cm, dm, m, inches, "half a metre").

Relations come in many forms (atop, onto, above, below, under, surrounding, enclosing, inside,
within, in the middle of, between, flanked by, next to, beside, left/right of, in front of,
behind, bridged by, spanning, resting on, supported by) and with references ("it", "them",
"the first one", "the second", "the base", "the taller one", "that").

Same `Case` type and phenomena as the other sets, weighted towards the hard phenomena. Each
predicate checks parameters (parts per level, footprints in cubes, heights, number of separate
structures, relations, regions), accepting every reasonable reading of vague wording and
nothing else. The local checks below compose the shared ones in `language_checks` and read
geometry only from `sdi.bench.boxes`.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the IRB120 at x = 0).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Mapping
from typing import Any

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev3-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks (on boxes)


def _top_centred(bs: k.Boxes) -> k.Reason:
    """The parts of the highest level sit over the middle of the structure's footprint
    (within 13 mm, a quarter cube)."""
    if not bs:
        return "no parts"
    z = max(round(b.lo[2], 3) for b in bs)
    top = [b for b in bs if round(b.lo[2], 3) == z]
    (tx, ty), (cx, cy) = bx.centre(top), bx.centre(bs)
    if abs(tx - cx) > 0.013 or abs(ty - cy) > 0.013:
        return f"top level centred at ({tx:.3f}, {ty:.3f}), footprint centre ({cx:.3f}, {cy:.3f})"
    return None


def _max_side(n: int) -> k.Check:
    """No footprint side longer than n cubes."""

    def f(bs: k.Boxes) -> k.Reason:
        a, b = bx.plan_dims(bs)
        return None if b <= n else f"footprint {a}×{b}, want at most {n}×{n}"

    return f


def _against(edge: str, within: float = 0.05) -> k.Check:
    """The footprint reaches to within `within` m of the workspace's `edge` (back/front/left/
    right) — "right up against the back edge", "hugging the right boundary"."""
    (x0, x1), (y0, y1), _ = bx.WORKSPACE

    def f(bs: k.Boxes) -> k.Reason:
        lo, hi = bx.bounds(bs)
        gap = {
            _B: x1 - hi[0],
            _F: lo[0] - x0,
            _L: y1 - hi[1],
            _R: lo[1] - y0,
        }[edge]
        return None if gap <= within + 1e-6 else f"{gap:.3f} m from the {edge} edge"

    return f


def _row_across(lo: int, hi: int) -> k.Check:
    """A row of lo–hi cubes running left–right (along y)."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.row(lo=lo, hi=hi)(bs)
        if r:
            return r
        fx, fy = bx.footprint_cubes(bs)
        return None if fy > fx else "the row runs front–back, not left–right"

    return f


def _squat(bs: k.Boxes) -> k.Reason:
    """A solid block at least 2 × 2 in plan and lower than its narrower plan side."""
    a, b = bx.plan_dims(bs)
    h = bx.thickness_cubes(bs)
    if a < 2 or h >= a:
        return f"not squat: {a}×{b}×{h}"
    return k.full(bs)


def _roomy_ring(bs: k.Boxes) -> k.Reason:
    """An enclosure with room inside for at least a 2 × 2 patch (≥ 4 empty cells)."""
    r = k.ring(bs)
    if r:
        return r
    cells = round(bx.interior_area(bs) / (bx.CUBE * bx.CUBE))
    return None if cells >= 4 else f"only {cells} empty cells inside"


def _long_flat(bs: k.Boxes) -> k.Reason:
    """One layer, at least 4 cubes long and at least twice as long as wide."""
    a, b = bx.plan_dims(bs)
    h = bx.thickness_cubes(bs)
    if h != 1 or b < 4 or b < 2 * a:
        return f"not long and flat: {a}×{b}×{h}"
    return None


def _pile(n: int) -> k.Check:
    """A solid, tidy pile of exactly n cubes: no side (plan or height) over 3 cubes."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.parts(n)(bs) or k.only_cubes(bs) or k.full(bs)
        if r:
            return r
        sides = (*bx.footprint_cubes(bs), bx.thickness_cubes(bs))
        return None if max(sides) <= 3 else f"not a tidy pile: {sides[0]}×{sides[1]}×{sides[2]}"

    return f


def _fat_tower(bs: k.Boxes) -> k.Reason:
    """A short, fat tower: a 2 × 2 column 2–4 high, or a 3 × 3 column 3–4 high."""
    return k.any_of(k.tower(lo=2, hi=4, base=2), k.tower(lo=3, hi=4, base=3))(bs)


def _tiny_arch(bs: k.Boxes) -> k.Reason:
    """Something spanning a gap, from at most 8 parts and at most 4 cubes high."""
    r = k.arch(bs)
    if r:
        return r
    if len(bs) > 8 or bx.thickness_cubes(bs) > 4:
        return f"not tiny: {len(bs)} parts, {bx.thickness_cubes(bs)} high"
    return None


# ---------------------------------------------------------------- local predicates (on results)


def _comps(result: Mapping[str, Any]) -> list[list[bx.Box]]:
    return bx.components(bx.boxes(result))


def _has(check: k.Check) -> k.Pred:
    """Some separate structure of the layout passes `check` (used with a relation that has
    already counted the structures: "the pad at the back, the tower in front of it")."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = _comps(result)
        if not comps:
            return "no layout"
        reasons = [check(g) for g in comps]
        if any(r is None for r in reasons):
            return None
        return "no structure fits: " + str(reasons[0])

    return f


def _spread(n: int, check: k.Check, min_gap: float) -> k.Pred:
    """n separate structures, each passing `check`, every two at least `min_gap` m apart."""
    base = k.each(n, check)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = base(result)
        if r:
            return r
        comps = _comps(result)
        gap = min(bx.separation(a, b) for a, b in itertools.combinations(comps, 2))
        return None if gap >= min_gap - 1e-6 else f"only {gap:.3f} m apart, want ≥ {min_gap}"

    return f


def _in_line(n: int, check: k.Check) -> k.Pred:
    """n separate structures, each passing `check`, their footprint centres on one straight
    line (within 13 mm)."""
    base = k.each(n, check)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = base(result)
        if r:
            return r
        pts = [bx.centre(g) for g in _comps(result)]
        a, b = max(itertools.combinations(pts, 2), key=lambda p: math.dist(*p))
        length = math.dist(a, b)
        if length == 0:
            return "all at one point"
        for p in pts:
            off = abs((p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0])) / length
            if off > 0.013:
                return f"not in a line: a centre {off:.3f} m off it"
        return None

    return f


T = k.tower
one = k.one
not_ = k.not_
reg = k.region
L_SHAPE, U_SHAPE, T_SHAPE, CROSS = (k.shape_letter(s) for s in ("L", "U", "T", "cross"))

CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "a 2x2 pad with a 3-cube tower atop it",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    _c(
        "rel-02",
        REL,
        "stack a 2-high column onto a 3 by 2 slab",
        one(k.on_top(T(2), k.block(3, 2, 1))),
    ),
    _c("rel-03", REL, "a single cube on a row of three", one(k.on_top(T(1), k.row(3)))),
    _c(
        "rel-04",
        REL,
        "a 2x2 block two layers high sitting above a 4x4 grid",
        one(k.on_top(k.block(2, 2, 2), k.block(4, 4, 1))),
    ),
    _c(
        "rel-05",
        REL,
        "a 5-cube row below a 3-cube row",
        one(k.on_top(k.row(3), k.row(5))),
    ),
    _c("rel-06", REL, "a ring surrounding a three-step staircase", k.around(k.staircase(3))),
    _c("rel-07", REL, "a cube wall enclosing a 2x2 patch", k.around(k.block(2, 2, 1))),
    _c(
        "rel-08",
        REL,
        "a 3-cube tower inside a 5x5 pen",
        k.around(T(3), k.all_of(k.ring_of(inner=(3, 3)), k.dims(5, 5))),
    ),
    _c("rel-09", REL, "a castle with a 4-high tower in the middle of it", k.around(T(4), k.castle)),
    _c(
        "rel-10",
        REL,
        "a single cube within a square ring that is 2 cubes high",
        k.around(T(1), k.ring_of(high=2)),
    ),
    _c(
        "rel-11",
        REL,
        "a 2x2 block between a wall and a tower of 3",
        k.between_(k.solid(2, 2), k.wall(), T(3)),
    ),
    _c("rel-12", REL, "a 5-high tower next to a T shape", k.beside(T(5), T_SHAPE)),
    _c("rel-13", REL, "a row of 4 beside a U shape", k.beside(k.row(4), U_SHAPE)),
    _c(
        "rel-14",
        REL,
        "an L to the left of a 2x2x2 block",
        k.beside(L_SHAPE, k.block(2, 2, 2), _L),
    ),
    _c("rel-15", REL, "a cross right of a castle", k.beside(CROSS, k.castle, _R)),
    _c(
        "rel-16",
        REL,
        "a 2-cube tower in front of a bridge",
        k.beside(T(2), k.bridge(), _F),
    ),
    _c(
        "rel-17",
        REL,
        "build a 3x3 grid and put a tower of 4 behind it",
        k.beside(T(4), k.block(3, 3, 1), _B),
    ),
    _c("rel-18", REL, "two posts of 4 cubes bridged by a beam", one(k.bridge(4, pillars=2))),
    _c("rel-19", REL, "a beam spanning a pair of single cubes", one(k.bridge(1, pillars=2))),
    _c(
        "rel-20",
        REL,
        "a deck resting on three pillars, each 2 cubes",
        one(k.legs_roof(legs=3, leg_lo=2, leg_hi=2)),
    ),
    _c(
        "rel-21",
        REL,
        "a beam supported by two 3-cube towers, with one cube sitting on the middle of the beam",
        one(k.bridge(3, pillars=2), k.parts(8), k.levels(2, 2, 2, 1, 1), _top_centred),
    ),
    _c(
        "rel-22",
        REL,
        "Build a tower of 2 and a tower of 6. Put the taller one behind the other.",
        k.beside(T(6), T(2), _B, max_gap=0.5),
    ),
    _c(
        "rel-23",
        REL,
        "Lay a 4x4 base. On top of the base, along its outer edge, a ring one cube high.",
        one(k.on_top(k.ring_of(high=1, inner=(2, 2)), k.block(4, 4, 1))),
    ),
    _c(
        "rel-24",
        REL,
        "Make two towers of 3 and a single cube. Put the cube between them.",
        k.between_(T(1), T(3)),
    ),
    _c(
        "rel-25",
        REL,
        "a row of 3 and a tower of 4 - put the first one in front of the second",
        k.beside(k.row(3), T(4), _F),
    ),
    _c("rel-26", REL, "four single cubes under a flat roof", one(k.canopy(4, 1, 1))),
    _c(
        "rel-27",
        REL,
        "a 2-cube tower flanked by two 2x2 pads",
        k.between_(T(2), k.block(2, 2, 1)),
    ),
    _c(
        "rel-28",
        REL,
        "please you build bridge: two tower of three cube, joined on top with beam",
        one(k.bridge(3, pillars=2)),
    ),
    _c(
        "rel-29",
        REL,
        "put pyramid in left side of table, and near to it on right one tower 3 cube",
        k.all_of(
            k.beside(T(3), k.pyramid(lo=2), _R),
            _has(k.all_of(k.pyramid(lo=2), reg(_L))),
        ),
    ),
    _c(
        "rel-30",
        REL,
        "the final layout should have a 3x3 pad with a 2x2 pad on it and nothing else",
        one(k.on_top(k.block(2, 2, 1), k.block(3, 3, 1))),
    ),
    _c(
        "rel-31",
        REL,
        "a 3x3 pad and a 2x2 pad; put a 2-cube tower on the smaller one",
        k.structures(k.block(3, 3, 1), k.on_top(T(2), k.block(2, 2, 1))),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Step one: put down a 2 by 3 base. Step two: add another layer just like it. "
        "Step three: cap it with a third identical layer.",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "seq-02",
        SEQ,
        "1) a 4-cube tower\n2) another one next to it, leaving a one-cube gap\n"
        "3) a beam across both",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "make three separate single cubes in a line, then stack a second cube on the middle one",
        k.between_(T(2), T(1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "start with a 5 by 5 ring of cubes; raise it to 3 layers; finally drop a single cube "
        "in the middle",
        k.around(T(1), k.all_of(k.ring_of(high=3, inner=(3, 3)), k.dims(5, 5))),
    ),
    _c("seq-05", SEQ, "lay a row of 6, then take off both end cubes", one(k.row(4))),
    _c(
        "seq-06",
        SEQ,
        "build a wall 5 long and 2 high, then pull out the middle cube of the top layer",
        one(k.profile(2, 2, 1, 2, 2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Make me a pyramid, 3 levels. After that, put a ring around it.",
        k.around(k.pyramid(3)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Stack 8 cubes into a tower. Oops, too tall - take 3 back off.",
        one(T(5)),
    ),
    _c(
        "seq-09",
        SEQ,
        "build a 2x2x2 block, then a 2-cube tower on top of it, then another cube on top of that",
        one(k.on_top(T(3), k.block(2, 2, 2))),
    ),
    _c(
        "seq-10",
        SEQ,
        "lay out a plus sign 3 across, then put one cube on its centre",
        one(k.on_top(T(1), k.all_of(CROSS, k.dims(3, 3))), _top_centred),
    ),
    _c(
        "seq-11",
        SEQ,
        "Make a staircase with 2 steps. Now make it 5 steps.",
        one(k.staircase(5)),
    ),
    _c(
        "seq-12",
        SEQ,
        "Lay a row of 3, then another row of 3 right behind it, then a third behind that",
        k.any_of(one(k.block(3, 3, 1)), k.each(3, k.row(3))),
    ),
    _c(
        "seq-13",
        SEQ,
        "build a tower of 6 and then cut it in half",
        # the half that is left, or both halves standing separately
        k.any_of(one(T(3)), k.each(2, T(3))),
    ),
    _c(
        "seq-14",
        SEQ,
        "put a 3 cube tower in the middle; then surround it with a ring; then make the ring 2 high",
        k.all_of(k.around(T(3), k.ring_of(high=2)), _has(k.all_of(T(3), reg("centre")))),
    ),
    _c(
        "seq-15",
        SEQ,
        "one: a 5x1 row. two: a 4x1 row on it. three: 3x1 on that. four: 2x1. "
        "five: a single cube on top.",
        one(k.flat, k.pyramid_counts(5, 4, 3, 2, 1)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Build 4 towers, 1, 2, 3 and 4 cubes tall. Then push them together into one piece.",
        one(k.parts(10), k.levels(4, 3, 2, 1), k.any_of(k.dims(1, 4), k.dims(2, 2))),
    ),
    _c(
        "seq-17",
        SEQ,
        "Make a gate from two 3-high posts and a lintel. Afterwards add a second lintel on top "
        "of the first.",
        one(k.bridge(3, pillars=2), k.parts(8), k.levels(2, 2, 2, 1, 1)),
    ),
    _c(
        "seq-18",
        SEQ,
        "first a 3 by 3 pad at the back, then a tower of 4 in front of it",
        k.all_of(
            k.beside(T(4), k.block(3, 3, 1), _F),
            _has(k.all_of(k.block(3, 3, 1), reg(_B))),
        ),
    ),
    _c(
        "seq-19",
        SEQ,
        "build a tower of 5. then a tower of 2 to its right. then make the second one the same "
        "height as the first",
        k.any_of(k.beside(T(5), T(5), _L, max_gap=0.5), one(k.block(1, 2, 5))),
    ),
    _c(
        "seq-20",
        SEQ,
        "Put down a 3x3 square. Add a 3x3 square on top. Then take away the centre cube of the "
        "top one.",
        one(k.on_top(k.ring_of(high=1, inner=(1, 1)), k.block(3, 3, 1)), k.parts(17)),
    ),
    _c(
        "seq-21",
        SEQ,
        "first build a bridge on two 2-cube pillars. then add a third pillar and another beam "
        "so it has two spans",
        one(k.bridge(2, pillars=3)),
    ),
    _c(
        "seq-22",
        SEQ,
        "start with an L, 3 by 3. Then build every cube of it up to 2 high.",
        one(L_SHAPE, k.dims(3, 3), k.height(2), k.parts(10)),
    ),
    _c("seq-23", SEQ, "twr 3. +2 on top. -1.", one(T(4))),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "twelve cubes in three equal stacks",
        k.any_of(k.each(3, T(4)), one(k.wall(3, 4))),
    ),
    _c("num-02", NUM, "a stack of 2+3 cubes", one(T(5))),
    _c("num-03", NUM, "a triple-decker 2x2 block", one(k.block(2, 2, 3))),
    _c("num-04", NUM, "fifteen cubes laid flat as a 3 by 5 pad", one(k.block(3, 5, 1))),
    _c("num-05", NUM, "eleven cubes in a straight line", one(k.row(11))),
    _c("num-06", NUM, "a pyramid of 14 cubes", one(k.pyramid(lo=2), k.parts(14))),
    _c(
        "num-07",
        NUM,
        "a tower of nine and a second one a third as tall",
        k.structures(T(9), T(3)),
    ),
    _c("num-08", NUM, "3 towers with heights 2/4/6", k.structures(T(2), T(4), T(6))),
    _c("num-09", NUM, "four single cubes, spread out", k.each(4, T(1))),
    _c(
        "num-10",
        NUM,
        "ten cubes: a 2x2x2 block plus a 2-cube tower beside it",
        k.beside(k.block(2, 2, 2), T(2)),
    ),
    _c("num-11", NUM, "a 3-pillar bridge, pillars 3 cubes", one(k.bridge(3, pillars=3))),
    _c("num-12", NUM, "a staircase with six treads", one(k.staircase(6))),
    _c("num-13", NUM, "a wall of 16 cubes in 2 courses", one(k.wall(8, 2))),
    _c("num-14", NUM, "half as many cubes as eight, in a column", one(T(4))),
    _c("num-15", NUM, "a grid of 20 cubes, 4 deep", one(k.block(4, 5, 1))),
    _c("num-16", NUM, "twin 5-cube towers", k.each(2, T(5))),
    _c("num-17", NUM, "a trio of 2-high towers", k.each(3, T(2))),
    _c("num-18", NUM, "a 3-tier pyramid", one(k.pyramid(3))),
    _c("num-19", NUM, "a double-height 3x3 block", one(k.block(3, 3, 2))),
    _c(
        "num-20",
        NUM,
        "seven cubes: five in a row and the other two stacked on its ends",
        one(k.profile(2, 1, 1, 1, 2)),
    ),
    _c(
        "num-21",
        NUM,
        "8 cubes as two towers of equal height",
        k.any_of(k.each(2, T(4)), one(k.block(1, 2, 4))),
    ),
    _c("num-22", NUM, "a single layer of 6 cubes in 2 rows", one(k.block(2, 3, 1))),
    _c(
        "num-23",
        NUM,
        "could you make me twenty cubes as 4 towers?",
        k.any_of(k.each(4, T(5)), one(k.wall(4, 5))),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a pad measuring 20 x 10 cm", one(k.block(4, 2, 1))),
    _c("dim-02", DIM, "a tower half a metre tall", one(T(10))),
    _c("dim-03", DIM, "a wall 40cm x 15cm (length x height)", one(k.wall(8, 3))),
    _c("dim-04", DIM, "a block W×D×H = 3×2×2", one(k.block(3, 2, 2))),
    _c("dim-05", DIM, "a platform 1 dm by 3 dm", one(k.block(2, 6, 1))),
    _c("dim-06", DIM, "a tower about 8 inches tall", one(T(4))),
    _c("dim-07", DIM, "a staircase whose top step is 15 cm up", one(k.staircase(3))),
    _c("dim-08", DIM, "a pillar 0.45 m high", one(T(9))),
    _c("dim-09", DIM, "a 25 cm × 5 cm × 5 cm bar", one(k.row(5))),
    _c(
        "dim-10",
        DIM,
        "a U 5 wide with arms 3 long",
        # the arms counted with or without the corner cube
        one(U_SHAPE, k.any_of(k.dims(3, 5), k.dims(4, 5))),
    ),
    _c("dim-11", DIM, "a cross with arms 2 cubes long", one(CROSS, k.dims(5, 5))),
    _c(
        "dim-12",
        DIM,
        "a flat pyramid 7 cubes wide at the bottom",
        one(k.pyramid(lo=2), k.flat, k.base(1, 7)),
    ),
    _c(
        "dim-13",
        DIM,
        "a table top 15 by 15 cm on legs 10 cm tall",
        one(k.canopy(lo=2, hi=2), k.dims(3, 3)),
    ),
    _c(
        "dim-14",
        DIM,
        "a staircase 3 wide, 3 steps, rising away from the robot",
        one(k.staircase(3), k.rises(_B), k.dims(3, 3)),
    ),
    _c("dim-15", DIM, "a slab 0.25 m x 150 mm, 2 layers", one(k.block(5, 3, 2))),
    _c("dim-16", DIM, "a column 35 centimetres high", one(T(7))),
    _c(
        "dim-17",
        DIM,
        "a square pen, 30 cm across the outside, one cube high",
        one(k.ring_of(high=1, inner=(4, 4)), k.dims(6, 6)),
    ),
    _c(
        "dim-18",
        DIM,
        "a bridge with its deck 25 cm above the table",
        # the deck's underside or its top at 25 cm
        one(k.bridge(lo=4, hi=5)),
    ),
    _c(
        "dim-19",
        DIM,
        "an enclosure with a 2 by 2 space inside it",
        one(k.ring_of(inner=(2, 2)), k.any_of(k.dims(4, 4), k.dims(6, 6))),
    ),
    _c(
        "dim-20",
        DIM,
        "a row spanning the whole width of the workspace, left to right",
        one(_row_across(9, 10)),
    ),
    _c("dim-21", DIM, "how about a 15 x 10 x 5 cm block?", one(k.block(3, 2, 1))),
    _c("dim-22", DIM, "a wall 0.2 m long and 150 mm high", one(k.wall(4, 3))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "a tower of 4 anywhere but near the robot",
        one(T(4), not_(reg(_F), "near the robot")),
    ),
    _c(
        "neg-02",
        NEG,
        "a row of 5; avoid the left side",
        one(k.row(5), not_(reg(_L), "on the left")),
    ),
    _c(
        "neg-03",
        NEG,
        "keep the middle of the table clear: one 3-cube tower on the left, one on the right",
        k.structures(
            k.all_of(T(3), reg(_L), not_(reg("centre"), "in the middle")),
            k.all_of(T(3), reg(_R), not_(reg("centre"), "in the middle")),
        ),
    ),
    _c(
        "neg-04",
        NEG,
        "a 2x2x2 block minus one of the top cubes",
        one(k.levels(4, 3), k.dims(2, 2), k.parts(7)),
    ),
    _c(
        "neg-05",
        NEG,
        "a 4x4 patch but skip the middle four",
        one(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4), k.parts(12)),
    ),
    _c("neg-06", NEG, "a tower that doesn't go higher than 15 cm", one(T(lo=2, hi=3))),
    _c("neg-07", NEG, "not one but two 2x2 pads", k.each(2, k.block(2, 2, 1))),
    _c(
        "neg-08",
        NEG,
        "stairs that do not climb to the left",
        one(k.staircase(), not_(k.rises(_L), "climbs to the left")),
    ),
    _c("neg-09", NEG, "an arch, but no beams - cubes only", one(k.arch, k.only_cubes)),
    _c("neg-10", NEG, "an L no bigger than 3 by 3", one(L_SHAPE, _max_side(3))),
    _c(
        "neg-11",
        NEG,
        "two towers of 3, not next to each other - far apart",
        _spread(2, T(3), 0.15),
    ),
    _c(
        "neg-12",
        NEG,
        "a rectangular enclosure, not a square one: 4 by 6",
        one(k.ring, k.dims(4, 6)),
    ),
    _c("neg-13", NEG, "no pyramid this time, just a 3x3 block 2 high", one(k.block(3, 3, 2))),
    _c(
        "neg-14",
        NEG,
        "a staircase of four steps, none of them wider than one cube",
        one(k.staircase(4), k.dims(1, 4)),
    ),
    _c("neg-15", NEG, "a tower, definitely not 3 cubes, make it 6", one(T(6))),
    _c(
        "neg-16",
        NEG,
        "a 3-level pyramid without its top cube",
        # the two lower levels of a 3-level pyramid, 3-D or flat, steps of one or two cubes
        one(
            k.any_of(
                k.pyramid_counts(9, 4),
                k.pyramid_counts(25, 9),
                k.all_of(k.flat, k.pyramid_counts(3, 2)),
                k.all_of(k.flat, k.pyramid_counts(5, 3)),
            )
        ),
    ),
    _c(
        "neg-17",
        NEG,
        "a castle whose corner towers are no taller than 3 cubes",
        one(k.castle, k.height(lo=2, hi=3)),
    ),
    _c(
        "neg-18",
        NEG,
        "three cubes in a line, but not touching each other",
        _in_line(3, T(1)),
    ),
    _c(
        "neg-19",
        NEG,
        "a wall 6 long, not more than 2 high and not less than 2 high",
        one(k.wall(6, 2)),
    ),
    _c(
        "neg-20",
        NEG,
        "a tower anywhere except the left or the back",
        one(T(lo=2), not_(reg(_L), "on the left"), not_(reg(_B), "at the back")),
    ),
    _c(
        "neg-21",
        NEG,
        "- wall 4 long\n- 2 high\n- no beams\n- not on the right",
        one(k.wall(4, 2), k.only_cubes, not_(reg(_R), "on the right")),
    ),
    # ------------------------------------------------------------------ typo (and dictation)
    _c("typo-01", TYP, "a tpwer of 4", one(T(4))),
    _c("typo-02", TYP, "stak 5 cubse", one(T(5))),
    _c("typo-03", TYP, "buld a bridg on 2 cube piilars", one(k.bridge(2, pillars=2))),
    _c("typo-04", TYP, "to towers of for", k.each(2, T(4))),
    _c("typo-05", TYP, "a row of ate cubes", one(k.row(8))),
    _c("typo-06", TYP, "atowerof6", one(T(6))),
    _c("typo-07", TYP, "BUIDL A WALL 5 LONG 2 HIHG", one(k.wall(5, 2))),
    _c("typo-08", TYP, "a staricase of 3", one(k.staircase(3))),
    _c("typo-09", TYP, "an encloser round a 3 tall tower", k.around(T(3))),
    _c("typo-10", TYP, "a 2 bye 3 grid", one(k.block(2, 3, 1))),
    _c("typo-11", TYP, "a collumn of 7", one(T(7))),
    _c(
        "typo-12",
        TYP,
        "a pyrmaid with a 3x3 bottom",
        one(k.pyramid(lo=2), k.base(3, 3)),
    ),
    _c("typo-13", TYP, "a cassle at the bakc", one(k.castle, reg(_B))),
    _c(
        "typo-14",
        TYP,
        "first make a tower of three then put to more cubes on it",
        one(T(5)),
    ),
    _c("typo-15", TYP, "an el shape three by three", one(L_SHAPE, k.dims(3, 3))),
    _c(
        "typo-16",
        TYP,
        "put a tower of three on top of the to by to pad",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Tower. Five high. Left side.", one(T(5), reg(_L))),
    _c("wo-02", WO, "What I want at the back is a row of 6.", one(k.row(6), reg(_B))),
    _c(
        "wo-03",
        WO,
        "3 steps it must have, the staircase on the right",
        one(k.staircase(3), reg(_R)),
    ),
    _c("wo-04", WO, "make tower 4 cube high", one(T(4))),
    _c("wo-05", WO, "On the table put you a pyramid of 3 levels.", one(k.pyramid(3))),
    _c("wo-06", WO, "Of cubes 3 by 4 make a grid.", one(k.block(3, 4, 1))),
    _c(
        "wo-07",
        WO,
        "The wall - 6 long, 2 high - build it at the front.",
        one(k.wall(6, 2), reg(_F)),
    ),
    _c("wo-08", WO, "Height 4, width 2, depth 2: that's the block.", one(k.block(2, 2, 4))),
    _c("wo-09", WO, "Between two 4-cube towers goes a row of 3.", k.between_(k.row(3), T(4))),
    _c("wo-10", WO, "Under a beam, two 2-cube towers.", one(k.bridge(2, pillars=2))),
    _c("wo-11", WO, "Around the 2x2 pad, build a ring.", k.around(k.block(2, 2, 1))),
    _c(
        "wo-12",
        WO,
        "To the left of it a row of 3 - it being a tower of 4.",
        k.beside(k.row(3), T(4), _L),
    ),
    _c("wo-13", WO, "Last, a cube on top; first, a tower of 3.", one(T(4))),
    _c(
        "wo-14",
        WO,
        "Rising to the back, four steps of stairs.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c("wo-15", WO, "Two levels, the pyramid, flat.", one(k.pyramid(2), k.flat)),
    _c(
        "wo-16",
        WO,
        "On the right the taller tower (6), on the left the shorter (2).",
        k.beside(T(6), T(2), _R, max_gap=0.5),
    ),
    _c("wo-17", WO, "Five cubes long, three cubes tall - such a wall I need.", one(k.wall(5, 3))),
    _c(
        "wo-18",
        WO,
        "tower 3 high, centre at 350/200 mm (x/y)",
        one(T(3), k.near(0.35, 0.20)),
    ),
    _c(
        "wo-19",
        WO,
        "A beam on top - the posts, 2 of them, 4 high.",
        one(k.bridge(4, pillars=2)),
    ),
    _c(
        "wo-20",
        WO,
        "In the back right a castle, and in the front left a tower of 3.",
        k.structures(k.all_of(k.castle, reg("back right")), k.all_of(T(3), reg("front left"))),
    ),
    _c(
        "wo-21",
        WO,
        "The base is 3 by 3, the top is a single cube, and in between a 2 by 2: pyramid.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c("wo-22", WO, "I want wall, long 7 cube, high 2 cube.", one(k.wall(7, 2))),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Hi all, quick sync from my side: the client loved last week's demo, so for round two "
        "could we get the robot to put together a pyramid - the proper 3-D kind, three levels, "
        "3x3 at the bottom - ideally before Friday? Thanks so much, really appreciate "
        "everyone's effort!",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "fil-02",
        FIL,
        "WORK ORDER 2024-117\nCell: IRB120 / Station B\nTask: assemble wall, L = 6 cubes, "
        "H = 2 cubes\nPriority: normal\nRequested by: QA",
        one(k.wall(6, 2)),
    ),
    _c("fil-03", FIL, "- tower\n- 4 cubes\n- left side", one(T(4), reg(_L))),
    _c(
        "fil-04",
        FIL,
        "okay um so build a a staircase with uh four steps period thanks",
        one(k.staircase(4)),
    ),
    _c(
        "fil-05",
        FIL,
        "for my robotics assignment i need the robot to make a bridge (two pillars 2 cubes tall "
        "+ a beam). is that ok?? thank u",
        one(k.bridge(2, pillars=2)),
    ),
    _c("fil-06", FIL, "can you stack 3 cubes?", one(T(3))),
    _c(
        "fil-07",
        FIL,
        "is it possible to get a 2x4 block two layers high?",
        one(k.block(2, 4, 2)),
    ),
    _c("fil-08", FIL, "\U0001f680 tower of 5 pls \U0001f64f", one(T(5))),
    _c(
        "fil-09",
        FIL,
        "[ticket #882] [prio: low] Build: cross shape, 5x5. /cc @ops",
        one(CROSS, k.dims(5, 5)),
    ),
    _c(
        "fil-10",
        FIL,
        "Hello, I am new here. I want the robot build a row of 7 cubes please. Thank you very "
        "much for help.",
        one(k.row(7)),
    ),
    _c(
        "fil-11",
        FIL,
        "So yeah, long story short, after the whole thing with the gripper yesterday we just "
        "need something basic to check it works - like two towers of two, side by side, "
        "nothing fancy",
        k.any_of(k.each(2, T(2)), one(k.block(1, 2, 2))),
    ),
    _c(
        "fil-12",
        FIL,
        "### Request\n**Structure:** staircase\n**Steps:** 3\n**Direction:** climbing to the right",
        one(k.staircase(3), k.rises(_R)),
    ),
    _c(
        "fil-13",
        FIL,
        "I need to end up with a ring of cubes, 2 high, and honestly that's it, nothing else on "
        "the table",
        one(k.ring_of(high=2)),
    ),
    _c(
        "fil-14",
        FIL,
        "the final thing should look like a T, roughly 3 wide and 3 long (seen from above, I mean)",
        one(T_SHAPE, k.dims(3, 3)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "a 2x2 pad in the corner nearest the robot on the left",
        one(k.block(2, 2, 1), reg("front left")),
    ),
    _c("reg-02", REG, "tower of 3 on the far side of the table", one(T(3), reg(_B))),
    _c(
        "reg-03",
        REG,
        "row 4, right up against the back edge",
        one(k.row(4), reg(_B), _against(_B)),
    ),
    _c(
        "reg-04",
        REG,
        "a pyramid centred at (550, 250) mm",
        one(k.pyramid(lo=2), k.near(0.55, 0.25)),
    ),
    _c(
        "reg-05",
        REG,
        "a 4-long wall hugging the right boundary",
        one(k.wall(4), reg(_R), _against(_R)),
    ),
    _c(
        "reg-06",
        REG,
        "3-step stairs in the far left corner",
        one(k.staircase(3), reg("back left")),
    ),
    _c(
        "reg-07",
        REG,
        "one tower of 4 on each side, left and right",
        k.structures(k.all_of(T(4), reg(_L)), k.all_of(T(4), reg(_R))),
    ),
    _c("reg-08", REG, "a ring on the left half of the table", one(k.ring, reg(_L))),
    _c(
        "reg-09",
        REG,
        "bridge close to the IRB120, on the right",
        one(k.bridge(), reg("front right")),
    ),
    _c("reg-10", REG, "a tower of 3 at y = 0.1 m, x = 0.7 m", one(T(3), k.near(0.7, 0.1))),
    _c(
        "reg-11",
        REG,
        "put a tower 10 cm from the left edge",
        # 10 cm to its centre or to its side: centre y 0.45 or 0.425
        one(T(lo=2), k.near(y=0.44, tol=0.03)),
    ),
    _c(
        "reg-12",
        REG,
        "a row of 3 across the front, 5 cm in from the front edge",
        one(_row_across(3, 3), reg(_F), k.near(x=0.26, tol=0.03)),
    ),
    _c(
        "reg-13",
        REG,
        "a pyramid at the back, centred left to right",
        one(k.pyramid(lo=2), reg(_B), k.near(y=0.30)),
    ),
    _c(
        "reg-14",
        REG,
        "a 2x2x2 block at the centre point of the work area",
        one(k.block(2, 2, 2), reg("centre")),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "a modest tower", one(T(lo=2, hi=5))),
    _c("open-02", OPEN, "a towering column", one(T(lo=6, hi=10))),
    _c("open-03", OPEN, "a squat block", one(_squat)),
    _c("open-04", OPEN, "a narrow wall", one(k.wall())),
    _c("open-05", OPEN, "a grand staircase", one(k.staircase(lo=4))),
    _c("open-06", OPEN, "a low footbridge", one(k.bridge(lo=1, hi=2))),
    _c("open-07", OPEN, "a roomy pen", one(_roomy_ring)),
    _c("open-08", OPEN, "something long and flat", one(_long_flat)),
    _c(
        "open-09",
        OPEN,
        "a carport for a toy car",
        one(k.any_of(k.canopy(), k.bridge(), k.arch)),
    ),
    _c("open-10", OPEN, "a few separate single cubes", k.few(2, 6, T(1))),
    _c("open-11", OPEN, "a minimal bridge", one(k.bridge(1, pillars=2))),
    _c(
        "open-12",
        OPEN,
        "a compact cube of cubes",
        one(k.any_of(k.block(2, 2, 2), k.block(3, 3, 3))),
    ),
    _c("open-13", OPEN, "a big U", one(U_SHAPE, k.long(lo=4))),
    _c("open-14", OPEN, "a short, fat tower", one(_fat_tower)),
    _c("open-15", OPEN, "a tidy pile of 6 cubes", one(_pile(6))),
    _c("open-16", OPEN, "a tiny archway", one(_tiny_arch)),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Construye una torre de cinco cubos", k.honest(one(T(5)))),
    _c("bad-02", BAD, "Zbuduj wieżę z trzech kostek", k.honest(one(T(3)))),
    _c("bad-03", BAD, "a tower one metre tall", k.honest(one(T(lo=2, hi=10)))),
    _c(
        "bad-04",
        BAD,
        "a 4-cube tower made of 6 cubes",
        k.honest(k.any_of(one(T(4)), one(T(6)))),
    ),
    _c("bad-05", BAD, "put a row of 5 at x = -0.3", k.honest(one(k.row(5)))),
    _c("bad-06", BAD, "...", k.refused),
    _c("bad-07", BAD, "undo that", k.honest()),
    _c("bad-08", BAD, "build the same as yesterday", k.honest()),
    _c("bad-09", BAD, "a pyramid with 0 levels", k.honest()),
    _c("bad-10", BAD, "a sphere of cubes 20 cm across", k.honest(k.layout(k.parts(lo=1)))),
    _c("bad-11", BAD, "$(reboot)", k.refused),
    _c("bad-12", BAD, "a tower 11 cubes high", k.honest(one(T(lo=2, hi=10)))),
    _c(
        "bad-13",
        BAD,
        "a row of 3 cubes, each 10 cm long",
        k.honest(k.any_of(one(k.row(3)), one(k.row(6)))),
    ),
    _c("bad-14", BAD, "uh hmm yeah no", k.refused),
    _c("bad-15", BAD, "a 12 cm tower", k.honest(one(T(lo=2, hi=3)))),
    _c(
        "bad-16",
        BAD,
        "a ring with a tower inside that is wider than the ring",
        k.honest(k.any_of(one(k.ring), k.around(T(lo=1)))),
    ),
)
