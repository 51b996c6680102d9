"""A fourteenth held-out set for the language front end (dev14): five more voices at the cell.

Written without looking at the Specifier's grammar, its tests, the front end's code, the frozen
test set or any benchmark result, and worded apart from `language_dev` … `language_dev13` (no
command shared with any set, see tests). Nothing here was run through the system while it was
written. The commands come from five kinds of people who give orders to a robot cell:

* a maintenance technician testing the cell after a repair — short, practical, "just stack
  three for a test", "the usual pyramid";
* a shift supervisor over a radio or chat — brief, informal, abbreviations ("pls", "thx",
  "w/", "lvls", "over");
* a university student following a lab exercise sheet ("Exercise 4: … Then …"), with the
  sheet's asides left in;
* a product manager in a chat message describing a customer demo — wordy, hedged, vague;
* a hobbyist used to toy-block words ("bricks", "a long brick" for a beam, "a gate", "a
  little house shape"; "studs" is no unit here).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three structures, references ("it", "them", "the first one"),
distributive phrases ("each", "between each"), comparisons ("twice as tall", "one shorter"),
corrections ("actually, make that four"), removals and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — including one merged
structure where a tower could be set down touching another, and both clear and
centre-to-centre readings of an unqualified spacing — and nothing else. Geometry comes only
from `sdi.bench.boxes` through the shared checks in `language_checks` and the local checks
below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30).
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


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev14-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _sorted_comps(result: Mapping[str, Any], n: int, axis: str) -> list[k.Boxes] | str:
    bs = bx.boxes(result)
    if not bs:
        return "no layout"
    if not bx.in_workspace(bs):
        return "a part outside the workspace"
    comps = bx.components(bs)
    if len(comps) != n:
        return f"{len(comps)} separate structures, want {n}"
    if axis == "x":
        return sorted(comps, key=lambda g: bx.centre(g)[0])
    return sorted(comps, key=lambda g: -bx.centre(g)[1])


def _in_order(axis: str, *checks: k.Check, gap: int | None = None) -> k.Pred:
    """Exactly len(checks) separate structures in the workspace, ordered front to back (axis
    "x") or left to right (axis "y"); the i-th passes checks[i]; neighbours `gap` cubes apart
    (clear, ± 1.5 cm) when given, and always in one line along `axis`."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = _sorted_comps(result, len(checks), axis)
        if isinstance(comps, str):
            return comps
        for i, (g, c) in enumerate(zip(comps, checks, strict=True)):
            r = c(g)
            if r:
                return f"structure {i + 1} in order: {r}"
        want = {"x": (_F, _B), "y": (_L, _R)}[axis]
        for a, b in itertools.pairwise(comps):
            if bx.side_of(a, b) not in want:
                return "not in one line"
            if gap is not None:
                r = k.gap_of(gap)(a, b)
                if r:
                    return r
        return None

    return f


def _line_of(n: int, check: k.Check, gap: int) -> k.Pred:
    """n structures passing `check` in a line (front to back or left to right), `gap` apart."""
    return k.any_of(_in_order("x", *[check] * n, gap=gap), _in_order("y", *[check] * n, gap=gap))


def _between_gaps(mid: k.Check, end: k.Check, gap: int) -> k.Pred:
    """Three structures: `mid` between two `end`s, `gap` cubes (clear) from each of them."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.between_(mid, end)(result)
        if r:
            return r
        comps = bx.components(bx.boxes(result))
        first: k.Reason = None
        for i, j, l_ in itertools.permutations(range(3)):
            a, b, c = comps[i], comps[j], comps[l_]
            why = mid(a) or end(b) or end(c)
            if why is None and not bx.between(a, b, c):
                why = "not between"
            why = why or k.gap_of(gap)(a, b) or k.gap_of(gap)(a, c)
            if why is None:
                return None
            first = first or why
        return first

    return f


def _second_centred(tol: float = 0.03) -> k.Check:
    """The parts of the second level (from the bottom) are centred (± tol) over the bottom
    level — whatever stands higher up."""

    def f(bs: k.Boxes) -> k.Reason:
        zs = sorted({round(b.lo[2], 3) for b in bs})
        if len(zs) < 2:
            return "one level only"
        bottom = [b for b in bs if round(b.lo[2], 3) == zs[0]]
        second = [b for b in bs if round(b.lo[2], 3) == zs[1]]
        (sx, sy), (bx0, by0) = bx.centre(second), bx.centre(bottom)
        if abs(sx - bx0) > tol or abs(sy - by0) > tol:
            return f"second level at ({sx:.3f}, {sy:.3f}), bottom at ({bx0:.3f}, {by0:.3f})"
        return None

    return f


def _all_right_of_centre(bs: k.Boxes) -> k.Reason:
    """Nothing in the left half of the table (every part at y ≤ 0.30)."""
    _, (_, y1, _) = bx.bounds(bs)
    return None if y1 <= 0.30 + bx.TOL else f"a part reaches y {y1:.3f}, in the left half"


def _skyline(lo: int, hi: int) -> k.Pred:
    """lo–hi separate single-column towers in the workspace, no two of the same height."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.few(lo, hi, k.tower(lo=1))(result)
        if r:
            return r
        hs = [bx.thickness_cubes(g) for g in bx.components(bx.boxes(result))]
        return None if len(set(hs)) == len(hs) else f"tower heights {sorted(hs)} repeat"

    return f


def _before_both(front: k.Check, back: k.Check, side: str = _F) -> k.Pred:
    """Three structures: two passing `back` and one passing `front`, which stands on `side`
    of each of the other two and within 0.25 m of both."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.structures(front, back, back)(result)
        if r:
            return r
        comps = bx.components(bx.boxes(result))
        first: k.Reason = None
        for i in range(3):
            rest = [g for j, g in enumerate(comps) if j != i]
            why = front(comps[i]) or back(rest[0]) or back(rest[1])
            for g in rest:
                why = why or k.on_side(side)(comps[i], g) or _near(comps[i], g)
            if why is None:
                return None
            first = first or why
        return first

    return f


def _small(result: Mapping[str, Any]) -> k.Reason:
    """Some layout, at most 4 cubes high and 5 cubes long overall."""
    return k.anything(result) or k.layout(k.all_of(k.low(4), k.long(hi=5)))(result)


def _low_demo(result: Mapping[str, Any]) -> k.Reason:
    """Some layout, at most 3 cubes high."""
    return k.anything(result) or k.layout(k.low(3))(result)


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
RING5 = k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5))
GATE = k.bridge


CASES: tuple[Case, ...] = (
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Test run: stack a tower of four, then a tower of two with a one-cube gap to its left.",
        k.pair(T(2), T(4), k.gap_of(1, _L)),
    ),
    _c(
        "rel-02",
        REL,
        "base, need 2 towers of 3, 1 cube gap between, beam across the top. over",
        one(GATE(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "rel-03",
        REL,
        "Exercise 3: Build a wall 4 cubes long and 2 cubes high. Then place a tower of 3 cubes "
        "in front of the wall, leaving a gap of one cube.",
        k.pair(T(3), k.wall(4, 2), k.gap_of(1, _F)),
    ),
    _c(
        "rel-04",
        REL,
        "For the customer demo I'm picturing a nice chunky pyramid, three levels, and on its "
        "right a tall skinny tower of six, with a bit of space between them, so people see "
        "the contrast.",
        k.pair(T(6), k.pyramid(3), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "rel-05",
        REL,
        "Make a gate: two pillars of four bricks with a long brick across the top of them.",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "rel-06",
        REL,
        "after the repair: 3x3 base plate one layer, one cube on top dead centre",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.levels(9, 1), k.centred()),
    ),
    _c(
        "rel-07",
        REL,
        "2 towers, a 5 and a 3, the 5 behind the 3, gap of 2 cubes",
        k.pair(T(5), T(3), k.gap_of(2, _B)),
    ),
    _c(
        "rel-08",
        REL,
        "Exercise 5: Build a square ring of cubes, 5 by 5 and one cube high. Put a tower of 2 "
        "cubes inside it, exactly in the centre.",
        k.pair(RING5, T(2), k.centred_in()),
    ),
    _c(
        "rel-09",
        REL,
        "Build a little tower of three bricks and a row of four bricks lying flat behind it, "
        "not touching.",
        k.pair(k.row(4), T(3), k.all_rels(k.on_side(_B), _near)),
    ),
    _c(
        "rel-10",
        REL,
        "Could we have three towers side by side, getting taller from left to right — two, "
        "four and six cubes — with a cube's gap between each?",
        _in_order("y", T(2), T(4), T(6), gap=1),
    ),
    _c(
        "rel-11",
        REL,
        "put a 2x2 block 2 high between two single towers of 4, one cube gap on each side",
        _between_gaps(k.block(2, 2, 2), T(4), 1),
    ),
    _c(
        "rel-12",
        REL,
        "pyramid 3 lvls, tower of 2 to the right of it, keep a gap",
        k.pair(T(2), k.pyramid(3), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "rel-13",
        REL,
        "Exercise 7: Build two parallel rows of 6 cubes each, running left to right, with "
        "exactly one cube of space between them.",
        k.pair(k.all_of(k.row(6), k.runs("y")), k.all_of(k.row(6), k.runs("y")), k.parallel_gap(1)),
    ),
    _c(
        "rel-14",
        REL,
        "Put a tower of five bricks on the table and a 2 by 2 block one brick away from it, "
        "on its front side.",
        k.pair(k.solid(2, 2), T(5), k.gap_of(1, _F)),
    ),
    _c(
        "rel-15",
        REL,
        "Picture this: a bridge with pillars three cubes tall, and a single cube sitting on the "
        "middle of the beam like a little flag.",
        one(k.on_top(T(1), k.all_of(k.bare_bridge, GATE(3, pillars=2))), k.height(5)),
    ),
    _c(
        "rel-16",
        REL,
        "stack four, then stack another four right behind it, touching - should come out as a "
        "block 2 deep and 4 high",
        one(k.block_xy(2, 1, 4)),
    ),
    _c(
        "rel-17",
        REL,
        "need 3 towers of 3 in a line front to back, 2 cube gaps",
        _in_order("x", T(3), T(3), T(3), gap=2),
    ),
    _c(
        "rel-18",
        REL,
        "Two towers of 4 bricks with a gap of one brick, bridged with a long brick. Then build "
        "the same gate again to the left of the first one, two bricks away from it.",
        k.pair(
            k.all_of(GATE(4, pillars=2), k.leg_gap(1)),
            k.all_of(GATE(4, pillars=2), k.leg_gap(1)),
            k.gap_of(2, _L),
        ),
    ),
    _c(
        "rel-19",
        REL,
        "Two towers of three, a little apart, and then a longer row of five cubes in front of "
        "them both.",
        _before_both(k.row(5), T(3)),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "Stack three for a test. Then add two more on top.", one(T(5))),
    _c(
        "seq-02",
        SEQ,
        "Exercise 2: Build a wall 4 cubes long and 2 cubes high. Then add a third layer to it.",
        one(k.wall(4, 3)),
    ),
    _c("seq-03", SEQ, "lay a row of 5, then take both end cubes off. copy?", one(k.row(3))),
    _c(
        "seq-04",
        SEQ,
        "Let's start with a tower of six — actually, make that four, six feels too tall for "
        "the video.",
        one(T(4)),
    ),
    _c(
        "seq-05",
        SEQ,
        "First put down a base plate of 3 by 3 bricks, then stack a 2 by 2 on it, then one "
        "brick on the very top.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "seq-06",
        SEQ,
        "run the usual pyramid, 3 high. then remove the top cube",
        one(k.pyramid(2)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Exercise 4: (a) Build two towers of 3 cubes, 2 cubes apart. (b) Place a beam across "
        "their tops.",
        one(GATE(3, pillars=2), k.leg_gap(1, 2)),
    ),
    _c(
        "seq-08",
        SEQ,
        "build 3 towers of 2 in a row w/ gaps. then knock the middle one down",
        k.each(2, T(2)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Make a row of six bricks, then on top of it a row of four in the middle, then two on "
        "top of that.",
        one(k.pyramid_counts(6, 4, 2), k.flat, _second_centred()),
    ),
    _c(
        "seq-10",
        SEQ,
        "So first the robot builds a square ring, four by four, one cube tall, and then — this "
        "is the wow moment — it fills in the middle so it becomes a solid plate.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "seq-11",
        SEQ,
        "tower of 7, then pull the top 3 cubes off and set them down as a separate tower next "
        "to it",
        k.any_of(k.pair(T(4), T(3), _near), one(k.cell_heights(4, 3))),
    ),
    _c(
        "seq-12",
        SEQ,
        "Exercise 6: Build a staircase of 3 steps. Then extend it by one more step at the high "
        "end.",
        one(k.staircase(4)),
    ),
    _c("seq-13", SEQ, "wall 5 long 3 high pls. then take the top row back off", one(k.wall(5, 2))),
    _c(
        "seq-14",
        SEQ,
        "Build two towers of five bricks a brick apart. Put a long brick on them like a gate. "
        "Then take the long brick away again.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "seq-15",
        SEQ,
        "First, a small tower of three. Then, beside it with a little space, a second one "
        "that's twice as tall as the first.",
        k.pair(T(6), T(3), _near),
    ),
    _c(
        "seq-16",
        SEQ,
        "slab 2x3 one layer. then a second layer same size. then a third.",
        one(k.block(2, 3, 3)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Exercise 9: Build three towers of 2, 3 and 4 cubes in a line from front to back, one "
        "cube apart. Then remove the tallest one.",
        k.pair(T(3), T(2), k.gap_of(1, _B)),
    ),
    _c("seq-18", SEQ, "tower of 3. scratch that, make it a wall 3 long 3 high", one(k.wall(3, 3))),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "just stack three for a test", one(T(3))),
    _c("num-02", NUM, "2x towers of 6, 2 cubes gap", k.pair(T(6), T(6), k.gap_of(2))),
    _c("num-03", NUM, "Exercise 1: Build a tower of seven cubes.", one(T(7))),
    _c("num-04", NUM, "half a dozen cubes lined up in a neat row, please", one(k.row(6))),
    _c(
        "num-05",
        NUM,
        "Build a pair of towers, each three bricks tall, with a gap of one brick",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "num-06",
        NUM,
        "three towers of two, single cube gap between each",
        _line_of(3, T(2), 1),
    ),
    _c(
        "num-07",
        NUM,
        "tower of 4 + one double that, side by side w/ a gap",
        k.pair(T(8), T(4), _near),
    ),
    _c(
        "num-08",
        NUM,
        "Exercise 3: Build a square block of cubes, 3 by 3 at the base and 3 layers high. How "
        "many cubes did you use?",
        one(k.block(3, 3, 3)),
    ),
    _c(
        "num-09",
        NUM,
        "We'd like a couple of towers, four cubes each, not touching, nothing more.",
        k.each(2, T(4)),
    ),
    _c("num-10", NUM, "Make a tower out of ten bricks", one(T(10))),
    _c(
        "num-11",
        NUM,
        "stack of 5, and a second stack one shorter beside it, 1 cube gap",
        k.pair(T(4), T(5), k.gap_of(1)),
    ),
    _c("num-12", NUM, "four single cubes, spread out, none touching", k.each(4, T(1))),
    _c(
        "num-13",
        NUM,
        "Exercise 8: Build a flat pyramid, one cube thick, with rows of 4, 3, 2 and 1 cubes.",
        one(k.pyramid_counts(4, 3, 2, 1), k.flat),
    ),
    _c(
        "num-14",
        NUM,
        "Three towers in a row: the two outer ones three cubes tall, and the middle one twice "
        "as tall as them.",
        k.between_(T(6), T(3)),
    ),
    _c("num-15", NUM, "A wall made of 2 rows of 5 bricks, one on the other", one(k.wall(5, 2))),
    _c(
        "num-16",
        NUM,
        "tower, 3 cubes. second tower, 3 + 2 cubes. 2 cube gap",
        k.pair(T(5), T(3), k.gap_of(2)),
    ),
    _c("num-17", NUM, "half dozen towers of 1, all apart", k.each(6, T(1))),
    _c(
        "num-18",
        NUM,
        "Exercise 10: Build a wall 6 cubes long and half as many cubes high.",
        one(k.wall(6, 3)),
    ),
    _c(
        "num-19",
        NUM,
        "two stacks, one of 6 and one a third of that, 1 cube gap",
        k.pair(T(2), T(6), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "lay a 2x4 plate, one layer, for the test", one(k.block(2, 4, 1))),
    _c(
        "dim-02",
        DIM,
        "Exercise 1: a wall 5 cubes long, 3 cubes high and 1 cube thick.",
        one(k.wall(5, 3)),
    ),
    _c("dim-03", DIM, "block 3 wide 2 deep 2 tall", one(k.block_xy(2, 3, 2))),
    _c(
        "dim-04",
        DIM,
        "a low, wide platform — five cubes across from left to right and three deep, just one "
        "layer",
        one(k.block_xy(3, 5, 1)),
    ),
    _c("dim-05", DIM, "Build a 4 by 4 square of bricks, two bricks thick", one(k.block(4, 4, 2))),
    _c("dim-06", DIM, "test tower 250 mm tall", one(T(5))),
    _c(
        "dim-07",
        DIM,
        "Exercise 4: Build a ring whose outside measures 4 by 5 cubes, 2 cubes high.",
        one(k.ring_of(high=2, inner=(2, 3)), k.dims(4, 5)),
    ),
    _c("dim-08", DIM, "wall 30cm long, 10cm high", one(k.wall(6, 2))),
    _c("dim-09", DIM, "Make a brick tower as tall as 8 bricks", one(T(8))),
    _c("dim-10", DIM, "a solid cube made of cubes, three on each edge", one(k.block(3, 3, 3))),
    _c("dim-11", DIM, "block 2 deep, 2 wide, 4 high", one(k.block(2, 2, 4))),
    _c(
        "dim-12",
        DIM,
        "Exercise 5: A staircase 4 steps high and 1 cube wide.",
        one(k.staircase(4), k.flat),
    ),
    _c(
        "dim-13",
        DIM,
        "row 8 long, running front to back",
        one(k.row(8), k.runs("x")),
    ),
    _c(
        "dim-14",
        DIM,
        "A gate with posts five bricks tall and a gap of one brick between the posts",
        one(GATE(5, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "dim-15",
        DIM,
        "a wall about the length of a ruler, say 30 centimetres, and 15 centimetres tall",
        one(k.wall(6, 3)),
    ),
    _c("dim-16", DIM, "2x2 column, 5 high", one(T(5, base=2))),
    _c(
        "dim-17",
        DIM,
        "Exercise 6: Build a rectangle of cubes that is 2 cubes from front to back and 6 cubes "
        "from left to right, one layer.",
        one(k.block_xy(2, 6, 1)),
    ),
    # ------------------------------------------------------------------ negation
    _c("neg-01", NEG, "tower of 4, no beams", one(T(4), k.only_cubes)),
    _c(
        "neg-02",
        NEG,
        "row of 5 but NOT front to back, left to right pls",
        one(k.row(5), k.runs("y")),
    ),
    _c(
        "neg-03",
        NEG,
        "Exercise 3b: Build two towers of 3 that do not touch each other.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-04",
        NEG,
        "Please don't make it taller than three cubes — a 3 by 3 block would be nice.",
        one(k.solid(3, 3), k.low(3)),
    ),
    _c(
        "neg-05",
        NEG,
        "Build a gate but not a tall one, posts of just two bricks",
        one(GATE(2, pillars=2)),
    ),
    _c(
        "neg-06",
        NEG,
        "pyramid 3 levels, don't use the left half of the table",
        one(k.pyramid(3), _all_right_of_centre),
    ),
    _c("neg-07", NEG, "wall 4 long, not 2 high, 3 high", one(k.wall(4, 3))),
    _c(
        "neg-08",
        NEG,
        "Exercise 7: Build a staircase of four steps without using any beams.",
        one(k.staircase(4), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "Nothing fancy, no bridges or arches — just two towers of five, side by side with a gap.",
        k.each(2, T(5)),
    ),
    _c("neg-10", NEG, "A row of 6 bricks, not stacked, all on the table", one(k.row(6))),
    _c(
        "neg-11",
        NEG,
        "don't build anything at the back, put a tower of 3 at the front",
        one(T(3), reg("front")),
    ),
    _c("neg-12", NEG, "tower of 6 — not 5, 6", one(T(6))),
    _c(
        "neg-13",
        NEG,
        "Exercise 11: Build a 2 by 2 block that is no taller than 2 cubes and not a single layer.",
        one(k.block(2, 2, 2)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typ-01", TYP, "stakc three cubes for a tset", one(T(3))),
    _c(
        "typ-02",
        TYP,
        "2 towrs of 4, gap 1 cube, breidge on top",
        one(GATE(4, pillars=2), k.leg_gap(1)),
    ),
    _c("typ-03", TYP, "Excercise 2: build a wal 5 cubes long and 2 cubs high", one(k.wall(5, 2))),
    _c("typ-04", TYP, "a pyramd with three levles for the demo pls", one(k.pyramid(3))),
    _c("typ-05", TYP, "make a litle tower of fuor bricks", one(T(4))),
    _c("typ-06", TYP, "lay a 3x3 plat, one layr", one(k.block(3, 3, 1))),
    _c("typ-07", TYP, "row of 6 cubs left to rigth", one(k.row(6), k.runs("y"))),
    _c(
        "typ-08",
        TYP,
        "Exersice 5: two towres of 3 cubes, one cube appart",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c("typ-09", TYP, "a staricase with 4 stpes", one(k.staircase(4))),
    _c("typ-10", TYP, "a gate with two pilars of 3 briks", one(GATE(3, pillars=2))),
    _c("typ-11", TYP, "towr of 5 in the bakc left corner", one(T(5), reg("back left"))),
    _c("typ-12", TYP, "blok 2x2, 3 hihg", one(k.block(2, 2, 3))),
    _c("typ-13", TYP, "Exercize 9: a ring 5 by 5, 1 cube hihg", one(RING5)),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "three high, one wide, a tower — for the test", one(T(3))),
    _c(
        "wo-02",
        WO,
        "of 4 a tower, on its left one of 2, gap 1",
        k.pair(T(2), T(4), k.gap_of(1, _L)),
    ),
    _c("wo-03", WO, "Exercise 3: 2 cubes high and 6 cubes long, a wall build.", one(k.wall(6, 2))),
    _c(
        "wo-04",
        WO,
        "On the right side of the table, that's where I'd like a pyramid, three levels.",
        one(k.pyramid(3), reg("right")),
    ),
    _c("wo-05", WO, "Bricks, five of them, in a row put", one(k.row(5))),
    _c(
        "wo-06",
        WO,
        "on top of a 3x3 slab, centred, a 1x1 tower of 3",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.levels(9, 1, 1, 1), k.centred()),
    ),
    _c(
        "wo-07",
        WO,
        "behind the tower of 5 — gap of 2 — a tower of 3",
        k.pair(T(3), T(5), k.gap_of(2, _B)),
    ),
    _c(
        "wo-08",
        WO,
        "Exercise 4: Across the tops of two towers of 3 cubes, a beam, with one cube of space "
        "between the towers.",
        one(GATE(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "wo-09",
        WO,
        "Four steps high is what the staircase should be, I think.",
        one(k.staircase(4)),
    ),
    _c(
        "wo-10",
        WO,
        "Two bricks wide and four bricks long, one layer, a flat plate make",
        one(k.block(2, 4, 1)),
    ),
    _c("wo-11", WO, "in the front right, a tower of 2", one(T(2), reg("front right"))),
    _c("wo-12", WO, "3 high 5 long the wall", one(k.wall(5, 3))),
    _c(
        "wo-13",
        WO,
        "Exercise 12: Inside a ring of 5 by 5 cubes, one high, a single cube in the centre.",
        k.pair(RING5, T(1), k.centred_in()),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "ok so after the gripper swap, just to check everything's fine, go ahead and stack "
        "three cubes, that's all",
        one(T(3)),
    ),
    _c(
        "fil-02",
        FIL,
        "hey, copy that, uh, when you got a sec, tower of five please, thx, over",
        one(T(5)),
    ),
    _c(
        "fil-03",
        FIL,
        "Exercise 1 (warm-up, 5 minutes, no marks): Build a row of 4 cubes. Make sure the robot "
        "is homed before starting.",
        one(k.row(4)),
    ),
    _c(
        "fil-04",
        FIL,
        "Hi team! Super excited about Thursday — for the customer demo, could the robot build "
        "something simple but elegant, like a 3-level pyramid? Thanks so much!!",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Okay, this brings back memories of my old toy box! Let's do a simple gate, two posts "
        "of three bricks and a long one across the top.",
        one(GATE(3, pillars=2)),
    ),
    _c(
        "fil-06",
        FIL,
        "right, the encoder's been replaced, so let's see — a 2 by 2 block, two high, nothing "
        "else, cheers",
        one(k.block(2, 2, 2)),
    ),
    _c("fil-07", FIL, "FYI line 3 is down, anyway: wall 4 long 3 high, thx", one(k.wall(4, 3))),
    _c(
        "fil-08",
        FIL,
        "Exercise 6 (read carefully!): Build a staircase of 3 steps. Note: the lab closes at 6 pm.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Just brainstorming here, nothing final, but I think two towers of four with a little "
        "gap would look great on the slide.",
        k.each(2, T(4)),
    ),
    _c(
        "fil-10",
        FIL,
        "My kid loves this bit: a tall tower, seven bricks, no more no less.",
        one(T(7)),
    ),
    _c(
        "fil-11",
        FIL,
        "standard post-maintenance check, as per the checklist: row of 5 left to right",
        one(k.row(5), k.runs("y")),
    ),
    _c("fil-12", FIL, "k, go: tower 4, front left, done", one(T(4), reg("front left"))),
    _c(
        "fil-13",
        FIL,
        "Exercise 8 (from the 2nd edition of the sheet): build a 3 by 3 slab, one layer thick. "
        "You may discuss with your partner.",
        one(k.block(3, 3, 1)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower of 3 at the back right, test", one(T(3), reg("back right"))),
    _c("reg-02", REG, "pyramid 2 lvls, center of table", one(k.pyramid(2), reg("centre"))),
    _c(
        "reg-03",
        REG,
        "Exercise 5: Build a tower of 4 cubes at x = 0.6, y = 0.2.",
        one(T(4), k.near(0.6, 0.2)),
    ),
    _c(
        "reg-04",
        REG,
        "Put the wall toward the left so the camera on the right has a clear view — four long, "
        "two high.",
        one(k.wall(4, 2), reg("left")),
    ),
    _c(
        "reg-05",
        REG,
        "Put a little tower of two bricks in the front left corner, and another one in the "
        "back right corner.",
        k.structures(k.all_of(T(2), reg("front left")), k.all_of(T(2), reg("back right"))),
    ),
    _c(
        "reg-06",
        REG,
        "row of 4 near the robot, along the front edge",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "reg-07",
        REG,
        "tower 6 far back, middle left-right",
        one(T(6), reg("back"), k.near(y=0.30, tol=0.05)),
    ),
    _c(
        "reg-08",
        REG,
        "Exercise 9: Build a 2 by 2 block, 2 high, centred at x = 0.5, y = 0.3.",
        one(k.block(2, 2, 2), k.near(0.5, 0.3)),
    ),
    _c(
        "reg-09",
        REG,
        "Keep everything on the right-hand side — a 3 by 3 slab over there, one layer.",
        one(k.block(3, 3, 1), reg("right"), _all_right_of_centre),
    ),
    _c(
        "reg-10",
        REG,
        "A tower of 5 bricks in the back left corner of the table",
        one(T(5), reg("back left")),
    ),
    _c(
        "reg-11",
        REG,
        "two towers of 3, one at the front left, one at the front right",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("front right"))),
    ),
    _c(
        "reg-12",
        REG,
        "staircase 3 steps, far left side",
        one(k.staircase(3), reg("left")),
    ),
    _c(
        "reg-13",
        REG,
        "Exercise 10: Place a single cube at x = 0.35, y = 0.45, and another at x = 0.55, "
        "y = 0.15.",
        k.structures(k.all_of(T(1), k.near(0.35, 0.45)), k.all_of(T(1), k.near(0.55, 0.15))),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "build something small to check the gripper, anything", _small),
    _c("open-02", OPEN, "smth nice for the visitors, keep it low", _low_demo),
    _c(
        "open-03",
        OPEN,
        "Exercise 12 (free design): build any structure that contains at least one arch.",
        k.all_of(k.anything, k.layout(k.arch)),
    ),
    _c(
        "open-04",
        OPEN,
        "Something that looks like a little city skyline — a few towers of different heights.",
        _skyline(3, 6),
    ),
    _c(
        "open-05",
        OPEN,
        "A little house shape, walls and a roof, whatever size you think",
        k.all_of(k.anything, one(k.height(lo=2))),
    ),
    _c("open-06", OPEN, "the usual calibration stack, whatever you normally do", k.anything),
    _c(
        "open-07",
        OPEN,
        "pick a tower height, ur choice, just one tower",
        one(T(lo=2, hi=10)),
    ),
    _c(
        "open-08",
        OPEN,
        "Exercise 13 (creative): design a bridge of your own choice.",
        one(GATE()),
    ),
    _c(
        "open-09",
        OPEN,
        "Make it look impressive but safe — maybe something symmetrical?",
        k.anything,
    ),
    _c("open-10", OPEN, "Build me a gate of any size you like", one(GATE())),
    _c(
        "open-11",
        OPEN,
        "some test pattern of single cubes on the table, a handful, not touching",
        k.few(3, 10, T(1)),
    ),
    _c(
        "open-12",
        OPEN,
        "A wall of some kind as a backdrop, at the back of the table",
        one(k.wall(), reg("back")),
    ),
    _c(
        "open-13",
        OPEN,
        "Build a little castle gate, your own design, but keep it under six bricks tall",
        k.all_of(k.anything, k.layout(k.all_of(k.arch, k.low(5)))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "stack 15 for the stress test", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-02", BAD, "kshh... tower... kshh... over", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-03",
        BAD,
        "Exercise 14: Build a wall 4 cubes long and 3 cubes high that is also only 1 cube high.",
        k.honest(one(k.any_of(k.wall(4, 3), k.row(4)))),
    ),
    _c("bad-04", BAD, "Can the robot make it pop? You know what I mean.", k.honest()),
    _c("bad-05", BAD, "Build a tower 20 studs tall", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-06", BAD, "row of 14 along left-right", k.honest(one(k.row(lo=2, hi=12)))),
    _c("bad-07", BAD, "same as yesterday", k.honest()),
    _c("bad-08", BAD, "Exercise 15: Build a staircase with minus two steps.", k.honest()),
    _c("bad-09", BAD, "lorem ipsum dolor, demo v3 FINAL final", k.honest()),
    _c(
        "bad-10",
        BAD,
        "A tower of 4 bricks floating in the air above the table",
        k.honest(one(T(4))),
    ),
    _c("bad-11", BAD, "tower of 3 at x = 1.2", k.honest(one(T(3)))),
    _c(
        "bad-12",
        BAD,
        "2 towers of 5, 0 cm apart but not touching",
        k.honest(k.any_of(k.each(2, T(5)), one(k.wall(2, 5)))),
    ),
    _c(
        "bad-13",
        BAD,
        "Exercise 16: Build a pyramid with 12 levels.",
        k.honest(one(k.pyramid(lo=2, hi=10))),
    ),
)
