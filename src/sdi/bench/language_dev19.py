"""A nineteenth held-out set for the language front end (dev19): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev18` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a baker / pastry chef who thinks in tiers and layers: "like a wedding cake", "a tier smaller
  each time", "stack them like pancakes", "a crust round the edge like a pie". A tier is a
  full rectangle of cubes, one or more layers thick, standing inside the tier below it; a
  pancake is one flat layer; a sheet cake or tray is a one-layer slab; a crust is a border one
  cube higher than the filling. Where a tier's thickness is not said, one layer or several are
  both accepted; a tier need not be centred unless the baker says so;
* a PE teacher or sports coach: podiums (first place in the middle and highest, second on its
  left, third on its right; left is the robot's left, +y, as everywhere at this cell), goals
  (two posts with a crossbar across the top), hurdles (a low gate), a starting line (a row of
  cubes), cones (single cubes), "a relay of stacks". A podium is accepted as one stepped block
  (each place one or two cubes wide) or, unless the coach says the blocks touch, as separate
  blocks in a line left to right, no more than two cubes apart. A crossbar may be a beam or a
  row of cubes. "A hurdle two cubes high" may be read as legs of two, or as legs of one under
  a bar whose top is two cubes up;
* a software developer writing JSON, YAML or key=value config instead of prose, sometimes with
  a comment line, a trailing comma or misspelt keys. A list of heights is that many towers in
  any arrangement, unless the config asks for a row; "width" runs left to right (y) and
  "depth" front to back (x); `gap_cm=10` accepts the clear gap and, where buildable, the
  centre-to-centre reading; JSON that cannot be read (a missing value, NaN, a negative count)
  is bad input;
* a child of about eight writing phonetically and excitedly ("a reely tall towr!!", "a brij",
  "sum stares", "ate blox", "to towrs of for"). Number words are read as the child meant them;
  "really tall" is five cubes or more; a made-up or impossible wish is bad input;
* an operator using Indian or Nigerian English idiom: "kindly do the needful", "prepone",
  "same to same" (exactly the same), "one-one cube on each" (one cube on each), "in the
  centre itself" (right in the centre), "revert back" (undo), "do one thing" (here is what to
  do), "only" as emphasis, "abeg", "no vex", "put am". Three commands are wholly or mostly in
  Hindi, Bengali or Hinglish (bad input: a refusal or a noted reading).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the middle one"),
distributive phrases ("one-one cube on each", "a stack on each side"), comparisons ("twice
as tall as the one before"), corrections ("revert back", a config diff), removals and unusable
input (gibberish, contradictions, sizes past the cell, unreadable JSON, other languages).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a podium touching or in
separate blocks, a hurdle's height as legs or overall, tiers one layer or several thick, a
gap clear or centre to centre — and nothing else. Geometry comes only from `sdi.bench.boxes`,
through the shared checks in `language_checks` and the local checks below.

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

_EDGE = 0.005  # m: two tier outlines this close are the same outline


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev19-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


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


def _line_any(*checks: k.Check, gaps: tuple[int, ...] = ()) -> k.Pred:
    """The structures in a line along x or y, in any order."""
    return k.any_of(
        *[
            k.in_order(axis, *cs, gaps=gaps)
            for axis in ("x", "y")
            for cs in itertools.permutations(checks)
        ]
    )


def _nearest_within(hi: float) -> k.Pred:
    """Every separate structure has a neighbour no more than `hi` m away, clear."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < 2:
            return "fewer than two structures"
        for i, g in enumerate(comps):
            gap = min(bx.separation(g, h) for j, h in enumerate(comps) if j != i)
            if gap > hi:
                return f"a structure {gap:.3f} m from its nearest neighbour, want ≤ {hi}"
        return None

    return f


def _centre_x_max(hi: float) -> k.Check:
    """The footprint centre at x ≤ `hi` (m): right up at the front edge."""

    def f(bs: k.Boxes) -> k.Reason:
        x = bx.centre(bs)[0]
        return None if x <= hi else f"centre x {x:.3f}, want ≤ {hi}"

    return f


def _tier_stack(bs: k.Boxes) -> list[tuple[int, int, int]] | str:
    """The tiers of a cake, bottom first, as (short side, long side, layers) in cubes; or why
    `bs` is not one. Every level is one part thick, a full rectangle without overlaps, standing
    on the level below; consecutive levels with the same outline form one tier; each tier lies
    inside the one below it and is strictly smaller."""
    if not bs:
        return "no parts"
    if k.on_table(bs):
        return "not on the table"
    by: dict[float, list[k.Box]] = {}
    for b in bs:
        by.setdefault(round(b.lo[2], 3), []).append(b)
    zs = sorted(by)
    outlines: list[tuple[float, float, float, float]] = []
    for z in zs:
        lv = by[z]
        if any(abs(b.size[2] - bx.CUBE) > bx.TOL for b in lv):
            return "a part more than one layer thick"
        for p, q in itertools.combinations(lv, 2):
            if all(min(p.hi[i], q.hi[i]) - max(p.lo[i], q.lo[i]) > bx.TOL for i in (0, 1)):
                return "overlapping parts"
        (x0, y0, _), (x1, y1, _) = bx.bounds(lv)
        area = sum(b.size[0] * b.size[1] for b in lv)
        if abs(area - (x1 - x0) * (y1 - y0)) > 0.2 * bx.CUBE * bx.CUBE:
            return "a layer that is not a full rectangle"
        outlines.append((x0, y0, x1, y1))
    for lower, upper in itertools.pairwise(zs):
        if abs(upper - lower - bx.CUBE) > bx.TOL or not bx.stands_on(by[upper], by[lower]):
            return "a layer not resting on the one below"
    tiers: list[list[float]] = []  # outline + layer count
    for o in outlines:
        if tiers and all(abs(u - v) <= _EDGE for u, v in zip(tiers[-1][:4], o, strict=True)):
            tiers[-1][4] += 1
            continue
        if tiers:
            prev = tiers[-1]
            inside = o[0] >= prev[0] - _EDGE and o[1] >= prev[1] - _EDGE
            inside = inside and o[2] <= prev[2] + _EDGE and o[3] <= prev[3] + _EDGE
            if not inside:
                return "a tier not inside the one below"
        tiers.append([*o, 1])
    out = []
    for x0, y0, x1, y1, n in tiers:
        sx, sy = bx.cubes(x1 - x0), bx.cubes(y1 - y0)
        out.append((min(sx, sy), max(sx, sy), round(n)))
    return out


def _tiers(*specs: tuple[int, int, int]) -> k.Check:
    """A cake of exactly these tiers, bottom first: (side, side, layers) each, either way
    round."""
    want = [(min(a, b), max(a, b), n) for a, b, n in specs]

    def f(bs: k.Boxes) -> k.Reason:
        got = _tier_stack(bs)
        if isinstance(got, str):
            return got
        return None if got == want else f"tiers {got}, want {want}"

    return f


def _tiered(n: int | None = None) -> k.Check:
    """A cake of ≥ 2 tiers (exactly `n` when given), each a full rectangle of any thickness."""

    def f(bs: k.Boxes) -> k.Reason:
        got = _tier_stack(bs)
        if isinstance(got, str):
            return got
        if len(got) < 2:
            return "one tier only"
        return None if n is None or len(got) == n else f"{len(got)} tiers, want {n}"

    return f


def _cake(n: int | None = None) -> k.Check:
    """A tiered cake of `n` tiers however thick: a pyramid of single layers, or tiers."""
    return k.any_of(k.pyramid(n), _tiered(n))


def _lr_heights(*hs: int) -> k.Check:
    """One stepped block on the table whose heights from left (+y) to right (-y) are `hs`,
    each place one or two cubes wide, any depth, every column full."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.on_table(bs)
        if r:
            return r
        got = bx.step_profile(bs, 1)[::-1]
        depth = bx.footprint_cubes(bs)[0]
        for w in (1, 2):
            want = [h for h in hs for _ in range(w)]
            if got == want:
                n = len(bx.voxels(bs))
                return None if n == sum(want) * depth else "columns not full"
        return f"left-to-right heights {got}, want {list(hs)}"

    return f


def _col(h: int) -> k.Check:
    """A solid block `h` cubes high on the table, any footprint (a podium place)."""
    return k.all_of(k.full, k.height(h), k.on_table)


def _podium(*hs: int) -> k.Pred:
    """A podium whose places, left to right, are `hs` high: one stepped block, or separate
    blocks in a line left to right no more than two cubes apart."""
    return k.any_of(
        k.one(_lr_heights(*hs)),
        k.in_order("y", *[_col(h) for h in hs], max_gap=2 * bx.CUBE + 0.015),
    )


def _bar_on_posts(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """Two separate posts `posts` cubes high (any height when None), `mouth` cubes apart
    (± 1.5 cm) when given, and as the topmost level one connected bar resting on both, whether
    the bar is a beam or a row of cubes (the shared `bridge` measures a cube-row bar's legs one
    short, since its middle cubes rest on nothing)."""

    def f(bs: k.Boxes) -> k.Reason:
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


def _goal(posts: int | None = None) -> k.Check:
    """A goal, gate or hurdle: two posts `posts` high with a crossbar (a beam or cubes)."""
    return k.any_of(k.bridge(posts, pillars=2), _bar_on_posts(posts))


def _hurdle(h: int) -> k.Check:
    """A hurdle "h cubes high": legs of h under a bar, or legs of h - 1 with the bar's top at
    h."""
    if h < 2:
        return _goal(h)
    return k.any_of(_goal(h), k.all_of(_goal(h - 1), k.height(h)))


def _tall_side(side: str) -> k.Check:
    """The tallest column(s) of one structure lie on `side` of the rest of it."""

    def f(bs: k.Boxes) -> k.Reason:
        cols = bx.columns(bs)
        top = max(bx.top(c) for c in cols)
        tall = [b for c in cols if bx.top(c) >= top - bx.TOL for b in c]
        rest = [b for c in cols if bx.top(c) < top - bx.TOL for b in c]
        if not rest:
            return "no lower part"
        got = bx.side_of(tall, rest)
        return None if got == side else f"the tall part is {got} of the rest, want {side}"

    return f


def _bare_middle(legs: int) -> k.Pred:
    """Two hurdles with legs `legs` high and, between them, two bare posts of that height."""
    hurdle = _goal(legs)
    post = k.tower(legs)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = k.structures(hurdle, hurdle, post, post)(result)
        if r:
            return r
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        hs = [g for g in comps if hurdle(g) is None]
        posts = [b for g in comps if hurdle(g) is not None for b in g]
        if len(hs) != 2:
            return "not two hurdles"
        return None if bx.between(posts, hs[0], hs[1]) else "the bare posts are not in between"

    return f


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
        "Put a 3-pancake stack to the left of a 2 by 2 sheet cake, one layer thick, leaving one "
        "cube of space between them.",
        k.pair(T(3), k.block(2, 2, 1), k.gap_of(1, _L)),
    ),
    _c(
        "rel-02",
        REL,
        "Two 2 by 2 cakes, two layers each, side by side on the cooling rack with one cube of "
        "air between them.",
        k.pair(k.block(2, 2, 2), k.block(2, 2, 2), k.gap_of(1)),
    ),
    _c(
        "rel-03",
        REL,
        "Set a 3 by 3 cake, two layers deep, at the back of the table, and a single-cube "
        "cupcake just in front of it, not touching.",
        k.all_of(
            k.pair(T(1), k.block(3, 3, 2), k.all_rels(k.on_side(_F), _near)),
            k.some(k.block(3, 3, 2), reg("back")),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "Podium time: the winner's block 3 high in the middle, second place 2 high on its left, "
        "third place 1 high on its right.",
        _podium(2, 3, 1),
    ),
    _c(
        "rel-05",
        REL,
        "Goalposts: two posts 3 high with a crossbar on top, and a one-cube ball in front of the "
        "goal, two cubes away from it.",
        k.pair(T(1), _goal(3), k.gap_of(2, _F)),
    ),
    _c(
        "rel-06",
        REL,
        "Set up two hurdles in a row going away from me, each two cubes high, with a 3-cube "
        "run-up between them.",
        k.in_order("x", _hurdle(2), _hurdle(2), gaps=(3,)),
    ),
    _c(
        "rel-07",
        REL,
        '{"items": [{"type": "tower", "height": 4}, {"type": "tower", "height": 2, "left_of": 0}]}',
        k.pair(T(2), T(4), k.on_side(_L)),
    ),
    _c(
        "rel-08",
        REL,
        "- type: wall\n  length: 5\n  height: 2\n- type: tower\n  height: 3\n  behind: wall\n"
        "  gap: 1",
        k.pair(T(3), k.wall(5, 2), k.gap_of(1, _B)),
    ),
    _c(
        "rel-09",
        REL,
        "tower.height=5\npyramid.levels=2\npyramid.position=right_of(tower)\ngap_cm=5",
        k.pair(k.pyramid(2), T(5), k.gap_of(1, _R)),
    ),
    _c(
        "rel-10",
        REL,
        "a big towr of 6 and a litle won of 2 rite next to it tuching",
        one(k.cell_heights(6, 2)),
    ),
    _c(
        "rel-11",
        REL,
        "mak a towr of 5 and a smol towr of 2 on the left of it",
        k.any_of(  # apart, or built against its left side
            k.pair(T(2), T(5), k.all_rels(k.on_side(_L), _near)),
            one(k.cell_heights(5, 2), _tall_side(_R)),
        ),
    ),
    _c(
        "rel-12",
        REL,
        "Kindly build one tower of 4 cubes and, just behind it, one more tower of same to same "
        "height, gap of one cube only.",
        k.pair(T(4), T(4), k.gap_of(1, _B)),
    ),
    _c(
        "rel-13",
        REL,
        "Do one thing: make a wall of 5 length, 2 height, and keep a tower of 3 on its right "
        "side itself, touching it.",
        one(k.cell_heights(2, 2, 2, 2, 2, 3), _tall_side(_R)),
    ),
    _c(
        "rel-14",
        REL,
        "Abeg, put one pyramid of 2 levels for the middle, then one tower of 3 for each side of "
        "am, left and right.",
        k.all_of(
            k.in_order("y", T(3), k.pyramid(2), T(3)),
            k.some(k.pyramid(2), reg("centre")),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "A relay of stacks: four stacks in a line from left to right, 1, 2, 3 and 4 high, each "
        "one cube clear of the next.",
        k.in_order("y", T(1), T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "rel-16",
        REL,
        "A 2 by 2 cake, two layers, with a cherry on top: one cube sitting on one of its corners.",
        one(k.plan_heights("32", "22")),
    ),
    _c(
        "rel-17",
        REL,
        '{"base": {"shape": "slab", "size": [3, 3]}, "on_top": {"shape": "tower", "height": 2, '
        '"at": "center"}}',
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "rel-18",
        REL,
        "put the smol towr betwen the too big towrs. big ones are 4. smol is 2",
        k.any_of(k.between_(T(2), T(4)), one(k.flat, k.profile(4, 2, 4))),
    ),
    _c(
        "rel-19",
        REL,
        "Tower of 5 in back side and tower of 2 in front side of it, both in same line only, "
        "gap 2 cubes.",
        k.pair(T(2), T(5), k.gap_of(2, _F)),
    ),
    _c(
        "rel-20",
        REL,
        "Goal at the back: two posts 2 high, crossbar on top. Penalty spot: one cube, straight "
        "out in front of the goal.",
        k.all_of(
            k.pair(T(1), _goal(2), k.on_side(_F)),
            k.some(_goal(2), reg("back")),
        ),
    ),
    _c(
        "rel-21",
        REL,
        "A 3-cube stack of pancakes on each side of a 2 by 3 sheet cake, one on the left and one "
        "on the right, each one cube away from the cake.",
        k.in_order("y", T(3), k.block(2, 3, 1), T(3), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Bake the bottom tier first: 3 by 3, two layers. Then a 1 by 1 tier, two layers, on the "
        "middle of it.",
        one(_tiers((3, 3, 2), (1, 1, 2)), k.top_centred()),
    ),
    _c(
        "seq-02",
        SEQ,
        "Stack four 2 by 2 pancakes, then eat the top one.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Make a 3-tier cake, a tier smaller each time, then lift off the top tier for the freezer.",
        one(_cake(2)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Set out three cones in a line left to right, one cube each, 2 cubes apart. Then stack "
        "a second cube on the middle cone.",
        k.in_order("y", T(1), T(2), T(1), gaps=(2,)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Build the podium: middle block 3 high. Then the block for second place, 2 high, "
        "touching it on the left. Finally third place, 1 high, touching it on the right.",
        one(_lr_heights(2, 3, 1)),
    ),
    _c(
        "seq-06",
        SEQ,
        "Put up goalposts with posts 2 high and a crossbar. Then add a second, identical goal at "
        "the other end of the table.",
        k.any_of(
            k.structures(
                k.all_of(_goal(2), reg("front")),
                k.all_of(_goal(2), reg("back")),
            ),
            k.structures(
                k.all_of(_goal(2), reg("left")),
                k.all_of(_goal(2), reg("right")),
            ),
        ),
    ),
    _c(
        "seq-07",
        SEQ,
        "steps:\n  - build: {shape: tower, height: 3}\n  - add: {cubes: 2, to: tower}",
        one(T(5)),
    ),
    _c(
        "seq-08",
        SEQ,
        '[{"op": "build", "shape": "wall", "length": 6, "height": 2}, {"op": "remove", '
        '"target": "top_row"}]',
        one(k.row(6)),
    ),
    _c("seq-09", SEQ, "- tower.height = 3\n+ tower.height = 5", one(T(5))),
    _c(
        "seq-10",
        SEQ,
        "frist make a towr of 4. then put won more on top. then won more!!!",
        one(T(6)),
    ),
    _c("seq-11", SEQ, "make sum stares with 3 steps. no wait i want 5 steps", one(k.staircase(5))),
    _c(
        "seq-12",
        SEQ,
        "Build a tower of 6. Then remove 2 cubes from the top. Then revert back, I want the 6 "
        "only.",
        one(T(6)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Make a wall of 4 length, 2 height, then a tower of 3. Sorry, prepone the tower: build "
        "the tower first, then the wall on the right side of the tower, not touching.",
        k.pair(k.wall(4, 2), T(3), k.all_rels(k.on_side(_R), _near)),
    ),
    _c(
        "seq-14",
        SEQ,
        "First make a pyramid of 3 levels. Then do one thing, remove the top cube itself.",
        one(k.pyramid(2)),
    ),
    _c(
        "seq-15",
        SEQ,
        "Two layers of 3 by 3 for the base, then a border of cubes round the edge of the top "
        "like a pie crust.",
        one(k.plan_heights("333", "323", "333")),
    ),
    _c(
        "seq-16",
        SEQ,
        "Build a 5-high stack, then split it into two stacks side by side, as even as you can.",
        k.any_of(
            k.pair(T(3), T(2), k.near_rel(0.10)),
            one(k.cell_heights(3, 2)),
        ),
    ),
    _c(
        "seq-17",
        SEQ,
        "tower: {height: 4}\n---\n# revision 2\ntower: {height: 4, position: back-left}",
        one(T(4), reg("back left")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Roll out a 2 by 4 sheet, one layer. Cut it in half across the middle and set the "
        "halves one cube apart.",
        k.pair(k.block(2, 2, 1), k.block(2, 2, 1), k.gap_of(1)),
    ),
    _c(
        "seq-19",
        SEQ,
        "bild a wall of 3 and then nock it down and bild a towr of 3 insted",
        one(T(3)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Make three towers of height 2. Then put one-one cube on each.",
        k.each(3, T(3)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "A five-tier wedding cake, one layer per tier, a tier smaller each time.",
        one(k.pyramid(5)),
    ),
    _c("num-02", NUM, "Half a dozen pancakes in one stack, one cube each.", one(T(6))),
    _c(
        "num-03",
        NUM,
        "Two dozen cupcakes on a tray: 4 rows of 6, one cube each, no gaps.",
        one(k.block(4, 6, 1)),
    ),
    _c(
        "num-04",
        NUM,
        "Podium: gold 4 high, silver 3, bronze 2; gold in the middle, silver to its left, bronze "
        "to its right, all touching.",
        one(_lr_heights(3, 4, 2)),
    ),
    _c(
        "num-05",
        NUM,
        "Set out four low hurdles in a line, legs one cube high, gaps of one cube between hurdles.",
        k.line(*[_goal(1)] * 4, gaps=(1,)),
    ),
    _c("num-06", NUM, '{"towers": [3, 5, 2]}', k.structures(T(3), T(5), T(2))),
    _c("num-07", NUM, "towers: [2, 2, 2, 2]\nspacing: 1", k.in_line(4, T(2), 1)),
    _c(
        "num-08",
        NUM,
        '{"shape": "tower", "count": 3, "height": 4}',
        k.each(3, T(4)),
    ),
    _c(
        "num-09",
        NUM,
        "i want fore towrs!! wun of 1 and wun of 2 and wun of 3 and wun of 4",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    _c("num-10", NUM, "ate blox in a rowe", one(k.row(8))),
    _c("num-11", NUM, "a towr as tall as SEVIN blox", one(T(7))),
    _c(
        "num-12",
        NUM,
        "Make three towers, heights 2, 4 and 6 only, in one line, one cube gap each.",
        k.line(T(2), T(4), T(6), gaps=(1,)),
    ),
    _c(
        "num-13",
        NUM,
        "Make two-two towers on left and right: two towers of 3 on the left side and two towers "
        "of 3 on the right side.",
        k.structures(
            k.all_of(T(3), reg("left")),
            k.all_of(T(3), reg("left")),
            k.all_of(T(3), reg("right")),
            k.all_of(T(3), reg("right")),
        ),
    ),
    _c(
        "num-14",
        NUM,
        "A 4-tier cake with 30 cubes in it altogether, square tiers, one layer each.",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "num-15",
        NUM,
        "A relay of three stacks, each twice as tall as the one before, starting at 1.",
        k.structures(T(1), T(2), T(4)),
    ),
    _c(
        "num-16",
        NUM,
        "Four cones across the starting line, single cubes, spaced 2 cubes apart.",
        k.in_line(4, T(1), 2),
    ),
    _c(
        "num-17",
        NUM,
        "n_towers=3\nheight=4\ngap_cm=10",
        k.in_line(3, T(4), 1, 2),  # 10 cm clear = 2 cubes; centre to centre = 1 clear
    ),
    _c(
        "num-18",
        NUM,
        "Make one pyramid of 2 levels using exactly 5 cubes only.",
        one(k.pyramid_counts(4, 1)),
    ),
    _c("num-19", NUM, "make 10 towrs of 1", k.each(10, T(1))),
    _c(
        "num-20",
        NUM,
        "Three layer cakes, all 2 by 2: a one-layer, a two-layer and a three-layer, in a row "
        "with a cube gap between each.",
        _line_any(k.block(2, 2, 1), k.block(2, 2, 2), k.block(2, 2, 3), gaps=(1,)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Three tiers, each two layers thick: 4 by 4 at the bottom, then 3 by 3, then 2 by 2.",
        one(_tiers((4, 4, 2), (3, 3, 2), (2, 2, 2))),
    ),
    _c(
        "dim-02",
        DIM,
        "A square cake tin 15 cm across, filled 10 cm deep.",
        one(k.block(3, 3, 2)),
    ),
    _c("dim-03", DIM, "A sheet cake 20 cm by 10 cm, one layer.", one(k.block(2, 4, 1))),
    _c("dim-04", DIM, "A loaf, 4 cubes long, 2 wide and 2 tall.", one(k.block(2, 4, 2))),
    _c(
        "dim-05",
        DIM,
        "A 5 by 5 pie: a base layer with a crust round the edge, one cube higher than the filling.",
        one(k.plan_heights("22222", "21112", "21112", "21112", "22222")),
    ),
    _c(
        "dim-06",
        DIM,
        "A goal 2 cubes wide between the posts, posts 3 high, crossbar across the top.",
        one(k.any_of(k.all_of(k.bridge(3, pillars=2), k.leg_gap(2)), _bar_on_posts(3, 2))),
    ),
    _c(
        "dim-07",
        DIM,
        "Starting line: a single row of cubes 40 cm long, left to right across the front.",
        one(k.row(8), k.runs("y"), reg("front")),
    ),
    _c(
        "dim-08",
        DIM,
        "A long-jump sand pit: a rectangle outline 4 by 6 cubes, one cube high, empty inside.",
        one(k.ring_of(high=1, inner=(2, 4)), k.dims(4, 6)),
    ),
    _c(
        "dim-09",
        DIM,
        '{"shape": "block", "width": 3, "depth": 2, "height": 2}',
        one(k.block_xy(2, 3, 2)),  # width left to right (y), depth front to back (x)
    ),
    _c("dim-10", DIM, "size: [2, 3, 4]  # x, y, z in cubes", one(k.block_xy(2, 3, 4))),
    _c("dim-11", DIM, 'dims_cm = {"l": 20, "w": 10, "h": 15}', one(k.block(2, 4, 3))),
    _c(
        "dim-12",
        DIM,
        "shape: pyramid\nbase: 3x3\nlevels: 2",
        one(k.pyramid(2), k.base(3, 3)),
    ),
    _c("dim-13", DIM, "a towr 20 sentameters tall", one(T(4))),
    _c("dim-14", DIM, "a wall thats 6 long and 3 tal", one(k.wall(6, 3))),
    _c(
        "dim-15",
        DIM,
        "Make a wall of length 30 cm and height 10 cm, thickness one cube only.",
        one(k.wall(6, 2)),
    ),
    _c("dim-16", DIM, "Block of 3 by 3, height 15 centimetres.", one(k.block(3, 3, 3))),
    _c(
        "dim-17",
        DIM,
        "A wedding cake 4 tiers high, each tier one layer, the bottom tier 7 by 7.",
        one(k.pyramid(4), k.base(7, 7)),
    ),
    _c(
        "dim-18",
        DIM,
        "Hurdle: legs 1 cube high, and a bar 3 cubes long resting across them.",
        one(
            k.any_of(k.all_of(k.bridge(1, pillars=2), k.leg_gap(1)), _bar_on_posts(1, 1)),
            k.dims(1, 3),
        ),
    ),
    _c(
        "dim-19",
        DIM,
        "A take-off board for the long jump: a flat slab one cube thick, 2 deep and 5 wide, "
        "at the front.",
        one(k.block_xy(2, 5, 1), reg("front")),
    ),
    _c("dim-20", DIM, "a big squer 4 by 4 and 2 hi", one(k.block(4, 4, 2))),
    _c(
        "dim-21",
        DIM,
        "Make a staircase of 4 steps, each step 2 cubes wide itself.",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A 3 by 3 cake, two layers, but leave the middle of the top layer empty for the filling.",
        one(k.plan_heights("222", "212", "222")),
    ),
    _c(
        "neg-02",
        NEG,
        "A 4 by 4 tray of cupcakes, one cube each, but skip the four corners, they always burn.",
        one(k.plan_heights(".11.", "1111", "1111", ".11.")),
    ),
    _c(
        "neg-03",
        NEG,
        "Two goals, posts 2 high with a crossbar each, but don't put them closer than 3 cubes "
        "to each other.",
        k.pair(_goal(2), _goal(2), _apart(3)),
    ),
    _c(
        "neg-04",
        NEG,
        "A podium without the bronze step: just gold, 3 high, and silver, 2 high, on its left, "
        "touching.",
        one(_lr_heights(2, 3)),
    ),
    _c(
        "neg-05",
        NEG,
        '{"shape": "tower", "height": 4, "count": 2, "touching": false}',
        k.each(2, T(4)),
    ),
    _c(
        "neg-06",
        NEG,
        "wall:\n  length: 5\n  height: 2\n  use_beams: false",
        one(k.wall(5, 2), k.only_cubes),
    ),
    _c("neg-07", NEG, "a towr of 5 but NOT blue", one(T(5))),
    _c(
        "neg-08",
        NEG,
        "dont make it wobly!! a towr of 6 thats not wobly",
        one(k.any_of(T(6), T(6, base=2))),  # a plain column, or a wider, steadier one
    ),
    _c(
        "neg-09",
        NEG,
        "Make a tower of 5, but don't put it in the centre itself; put it in the front right "
        "corner.",
        one(T(5), reg("front right")),
    ),
    _c(
        "neg-10",
        NEG,
        "Build 3 towers of 2, no touching each other, but not more than one cube gap.",
        k.all_of(k.each(3, T(2)), _nearest_within(bx.CUBE + 0.015)),
    ),
    _c(
        "neg-11",
        NEG,
        "Three hurdles in a row, posts 2 high, but leave the bar off the middle one.",
        _bare_middle(2),
    ),
    _c(
        "neg-12",
        NEG,
        "tower.height=3\ntower.region=left  # NOT right, the right side is taped off",
        one(T(3), reg("left")),
    ),
    _c(
        "neg-13",
        NEG,
        "Make pyramid of 2 levels, not on the left side, not on the right side, in the middle "
        "only.",
        one(k.pyramid(2), reg("centre")),
    ),
    _c(
        "neg-14",
        NEG,
        "sum stares of 3 steps that go up to the rite not to the left",
        one(k.staircase(3), k.rises(_R)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a reely big brij with legs of 3", one(_goal(3))),
    _c("typo-02", TYP, "a piramid with 3 layrs", one(k.pyramid(3))),
    _c("typo-03", TYP, "to towrs of for", k.each(2, T(4))),
    _c("typo-04", TYP, "sum stares with 4 steps", one(k.staircase(4))),
    _c("typo-05", TYP, "a wal 5 long and 2 hie", one(k.wall(5, 2))),
    _c("typo-06", TYP, '{"shape": "pyramid", "levels": 3,}', one(k.pyramid(3))),
    _c("typo-07", TYP, '{"shpae": "tower", "hieght": 6}', one(T(6))),
    _c("typo-08", TYP, "shape=wal length=4 height=3", one(k.wall(4, 3))),
    _c("typo-09", TYP, "a weding cake with 3 teirs, each one smaler", one(_cake(3))),
    _c("typo-10", TYP, "stack 4 pancaeks, 2 by 2 ech", one(k.block(2, 2, 4))),
    _c(
        "typo-11",
        TYP,
        "Kindly make one towr of 5 cubes in the lft side.",
        one(T(5), reg("left")),
    ),
    _c("typo-12", TYP, "Pls bild a wall of lenght 6 and hight 2.", one(k.wall(6, 2))),
    _c("typo-13", TYP, "podim: midle 3, left 2, rite 1", _podium(2, 3, 1)),
    _c("typo-14", TYP, "goalpots 2 high with a crosbar", one(_goal(2))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Tower of 4 cubes, on the left side, you make.", one(T(4), reg("left"))),
    _c(
        "wo-02",
        WO,
        "In the back side only, one wall you build, length 5, height 2.",
        one(k.wall(5, 2), reg("back")),
    ),
    _c(
        "wo-03",
        WO,
        '{"position": "front-left", "height": 3, "shape": "tower"}',
        one(T(3), reg("front left")),
    ),
    _c("wo-04", WO, "height: 2\nlength: 6\ntype: wall", one(k.wall(6, 2))),
    _c(
        "wo-05",
        WO,
        "Three high, in the middle: that's first place. Second, two high, to its left. Third, "
        "one high, to its right. No gaps.",
        one(_lr_heights(2, 3, 1)),
    ),
    _c(
        "wo-06",
        WO,
        "Over two 3-high posts, a crossbar; that's the goal.",
        one(_goal(3)),
    ),
    _c(
        "wo-07",
        WO,
        "On top of a 3 by 3 layer, a 2 by 2 layer, and on top of that, one cube: that's my cake.",
        one(_tiers((3, 3, 1), (2, 2, 1), (1, 1, 1))),
    ),
    _c(
        "wo-08",
        WO,
        "To the right of the big cake goes the little one: big is 3 by 3, two layers; little is "
        "2 by 2, one layer; a cube of space between.",
        k.pair(k.block(2, 2, 1), k.block(3, 3, 2), k.gap_of(1, _R)),
    ),
    _c(
        "wo-09",
        WO,
        "on the rite put a towr of 3 and on the left a towr of 6",
        k.structures(k.all_of(T(3), reg("right")), k.all_of(T(6), reg("left"))),
    ),
    _c(
        "wo-10",
        WO,
        "5 steps my stares shud have, going up to the back",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c(
        "wo-11",
        WO,
        "Pyramid of 3 levels, in the front side itself, make it.",
        one(k.pyramid(3), reg("front")),
    ),
    _c(
        "wo-12",
        WO,
        "Four high, two by two, right in the middle of the table: my layer cake.",
        one(k.block(2, 2, 4), reg("centre")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning! Ovens are on and the croissants are proving, so while I wait: a 3 by 3 cake, "
        "two layers, please. Ta, love.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-02",
        FIL,
        "Right, chef here, bit frazzled, big wedding order for four o'clock. For now just give "
        "me a tower of 5 cubes, I'll sort the tiers out later.",
        one(T(5)),
    ),
    _c(
        "fil-03",
        FIL,
        "Okay team, whistle's gone, water bottles down! Today we're doing goalposts: posts of "
        "4, crossbar on top. Hustle!",
        one(_goal(4)),
    ),
    _c(
        "fil-04",
        FIL,
        "Listen up, Year 5, eyes on the robot's table please: a row of 6 cubes for our starting "
        "line. No messing about.",
        one(k.row(6)),
    ),
    _c(
        "fil-05",
        FIL,
        '// TODO: move this to the config service\n// owner: @dmitri\n{"shape": "wall", '
        '"length": 4, "height": 3}',
        one(k.wall(4, 3)),
    ),
    _c(
        "fil-06",
        FIL,
        "```yaml\n# generated by layout-bot v0.3.1, do not edit\nshape: staircase\nsteps: 3\n```",
        one(k.staircase(3)),
    ),
    _c(
        "fil-07",
        FIL,
        "hi robot!!! my name is maya and i am 8 and i LOVE dogs. can you make a towr of 4 "
        "pleeeease",
        one(T(4)),
    ),
    _c(
        "fil-08",
        FIL,
        "omg omg ok so. a piramid. with 2 levels. thats it bye!!!",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-09",
        FIL,
        "Good morning sir, hope you are doing well. Kindly do the needful and make one wall of "
        "length 5 and height 3. Thanks and regards.",
        one(k.wall(5, 3)),
    ),
    _c(
        "fil-10",
        FIL,
        "Sir, I have one small doubt but I will ask it later. For now, please build tower of 6 "
        "cubes only.",
        one(T(6)),
    ),
    _c(
        "fil-11",
        FIL,
        "Abeg, no vex for the delay o. Just help me build one staircase of 4 steps, God bless you.",
        one(k.staircase(4)),
    ),
    _c(
        "fil-12",
        FIL,
        "Right, it's chucking it down so we're in the sports hall today. Set up a podium for me: "
        "first in the middle 3 high, second on the left 2 high, third on the right 1 high.",
        _podium(2, 3, 1),
    ),
    _c(
        "fil-13",
        FIL,
        "Between you and me the last cake I made collapsed, so let's keep it simple this time: "
        "two tiers, 3 by 3 then 1 by 1, one layer each.",
        one(k.pyramid_counts(9, 1)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Put a 2 by 2 cake, one layer, in the back left corner, out of the way of the mixer.",
        one(k.block(2, 2, 1), reg("back left")),
    ),
    _c(
        "reg-02",
        REG,
        "Set the wedding cake, three tiers of 3 by 3, 2 by 2 and a single cube, in the centre "
        "of the table.",
        one(_tiers((3, 3, 1), (2, 2, 1), (1, 1, 1)), reg("centre")),
    ),
    _c(
        "reg-03",
        REG,
        "Put the starting line, a row of 5 cubes, right along the front edge, left to right.",
        one(k.row(5), k.runs("y"), _centre_x_max(0.30)),
    ),
    _c(
        "reg-04",
        REG,
        "Goal at the far end of the table: posts of 3 and a crossbar.",
        one(_goal(3), reg("back")),
    ),
    _c(
        "reg-05",
        REG,
        "Put a single 3-high stack for first place in the front left corner.",
        one(T(3), reg("front left")),
    ),
    _c(
        "reg-06",
        REG,
        '{"shape": "tower", "height": 2, "x": 0.6, "y": 0.15}',
        one(T(2), k.near(0.60, 0.15, 0.011)),
    ),
    _c(
        "reg-07",
        REG,
        "pos_mm=(350, 450)\nshape=pyramid\nlevels=2",
        one(k.pyramid(2), k.near(0.35, 0.45, 0.011)),
    ),
    _c(
        "reg-08",
        REG,
        "region: back-right\nshape: wall\nlength: 4\nheight: 2",
        one(k.wall(4, 2), reg("back right")),
    ),
    _c("reg-09", REG, "put a towr of 3 in the midel of the tabel", one(T(3), reg("centre"))),
    _c("reg-10", REG, "a brij all the way at the back", one(_ARCH, reg("back"))),
    _c(
        "reg-11",
        REG,
        "Make tower of 4 in left side corner, back side.",
        one(T(4), reg("back left")),
    ),
    _c(
        "reg-12",
        REG,
        "Keep one 2 by 2 block, 2 high, in the centre itself.",
        one(k.block(2, 2, 2), reg("centre")),
    ),
    _c(
        "reg-13",
        REG,
        "Put am for the right side, near the front: one tower of 3.",
        one(T(3), reg("front right")),
    ),
    _c(
        "reg-14",
        REG,
        "Pipe a row of 4 cupcakes along the left edge, running front to back.",
        one(k.row(4), k.runs("x"), k.centre_y_min(0.45)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "a reely tall towr!!",
        one(k.any_of(T(lo=5, hi=10), T(lo=5, hi=10, base=2))),
    ),
    _c(
        "open-02",
        OPEN,
        "make sumthing that gos up up up!!",
        k.all_of(k.anything, k.layout(k.height(lo=3))),
    ),
    _c("open-03", OPEN, "a brij pleese", k.all_of(k.anything, one(_ARCH))),
    _c("open-04", OPEN, "i want sum stares", k.all_of(k.anything, one(k.staircase()))),
    _c(
        "open-05",
        OPEN,
        "Surprise me: any cake you like, as long as it has tiers.",
        k.all_of(k.anything, one(_cake())),
    ),
    _c(
        "open-06",
        OPEN,
        "Something small for a christening table, no more than 6 cubes in all.",
        k.all_of(k.anything, k.layout(k.parts(hi=6))),
    ),
    _c(
        "open-07",
        OPEN,
        "Set up any obstacle course you like, at least three separate pieces.",
        k.all_of(k.anything, _count(3, 99)),
    ),
    _c(
        "open-08",
        OPEN,
        "Any sort of hurdle, your call on the height.",
        k.all_of(k.anything, one(_goal())),
    ),
    _c(
        "open-09",
        OPEN,
        '{"shape": "any", "max_height": 3}',
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c(
        "open-10",
        OPEN,
        "# anything goes\nshape=*\ncount=2",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-11",
        OPEN,
        "Do one thing, make any shape you like, but keep it in the left side only.",
        k.all_of(k.anything, k.layout(reg("left"))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, '{"shape": "tower", "height": }', k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-02",
        BAD,
        '{"shape": "tower", "height": 40}',  # 40 levels: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-03",
        BAD,
        '{"shape": "tower", "height": 3, "height": 6}',
        k.honest(one(k.any_of(T(3), T(6)))),
    ),
    _c("bad-04", BAD, "{{{{]]]: :: ,,,}", k.honest()),
    _c("bad-05", BAD, '{"shape": "tower", "height": "NaN"}', k.honest(one(T(lo=1, hi=10)))),
    _c("bad-06", BAD, "asdfjkl;;; hahahahaha poop", k.honest()),
    _c("bad-07", BAD, "a towr all the way to the moon!!!!", k.honest(one(T(lo=1, hi=10)))),
    _c("bad-08", BAD, "make me a reel unicorn", k.honest(k.anything)),
    _c(
        "bad-09",
        BAD,
        "A wedding cake of 12 tiers, a tier smaller each time.",  # 12 levels: past the cell
        k.honest(one(_cake())),
    ),
    _c(
        "bad-10",
        BAD,
        "A baker's dozen of cupcakes in a single straight row, one cube each, touching.",
        k.honest(one(k.row())),  # 13 cubes: longer than the table either way
    ),
    _c(
        "bad-11",
        BAD,
        "Podium: first place 2 high in the middle, second place 4 high on its left, and first "
        "must be the tallest.",
        k.honest(k.anything),
    ),
    _c("bad-12", BAD, "Goalposts 3 high with a crossbar, but no posts.", k.honest(k.anything)),
    _c("bad-13", BAD, "पाँच क्यूब का एक टावर बनाइए।", k.honest(one(T(5)))),
    _c("bad-14", BAD, "চারটি কিউব দিয়ে একটি টাওয়ার বানাও।", k.honest(one(T(4)))),
    _c(
        "bad-15",
        BAD,
        "Ek tower banao, chaar cube ka, left side mein.",
        k.honest(one(T(4), reg("left"))),
    ),
    _c(
        "bad-16",
        BAD,
        "Build one tower of height 5 only, and make it 3 high.",
        k.honest(one(k.any_of(T(5), T(3)))),
    ),
    _c("bad-17", BAD, "Revert back.", k.honest(k.anything)),
    _c("bad-18", BAD, '{"shape": "pyramid", "levels": -2}', k.honest(one(k.pyramid()))),
    _c("bad-19", BAD, "Mark out a full-size football pitch.", k.honest(k.anything)),
    _c("bad-20", BAD, "Bake at 180 for 40 minutes, then leave to cool.", k.honest()),
]
