"""An eighteenth held-out set for the language front end (dev18): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev17` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a theatre / event set designer who thinks in risers, platforms, treads, flats, wings,
  downstage and upstage. The audience sits where the robot stands, so downstage = towards the
  robot = front (small x) and upstage = back (large x). A riser or platform is a solid slab
  ("4 wide and 3 deep": wide runs left to right, along y; deep runs front to back, along x),
  treads are steps, a flat is a wall one cube thick, the wings are the far left and right.
  Stage left and stage right are the performer's, facing the audience: stage left = the
  robot's right (-y), stage right = the robot's left (+y). Where the designer glosses it
  ("the actor's left as they look out at the house") only that reading is accepted; where a
  bare "stage left" is said, a builder at a robot cell with no audience in sight could take
  it either way, so the predicate accepts either side (but not the middle);
* a laboratory technician who thinks in plates, racks, arrays, wells and positions ("a 3 x 4
  array", "A1", "every other position", "a checkerboard"). An array of positions is a regular
  grid of single columns; where no spacing is said, any even spacing is accepted, touching
  (a solid plate) included; where a spacing is said, that clear gap (± 1.5 cm). Positions
  are labelled in any turn or mirror image unless the command says which way the rows run;
* an operator whose first language is Polish, Russian or Dutch — no articles, "tower from 5
  cubes", "put on it one more", "near to wall", "behind of", verb last or second; and three
  commands wholly in Polish, Russian or Dutch (bad input: a refusal or a noted reading);
* text that came from OCR of a handwritten note — letter/number confusions a scanner makes
  ("5" for S, "0" for O, "l" and "1" swapped, "rn" for m, "vv" for w, "8" for B, "q" for g),
  words broken by stray spaces and stray marks ("|", "~"). A size is read as the writer meant
  it ("l0 crn" = 10 cm = 2 cubes); "N cm apart" accepts the clear gap and, where buildable,
  the centre-to-centre reading;
* a mathematics teacher using geometry words: cuboid, prism, square-based pyramid, vertex,
  face, edge, parallel, perpendicular, adjacent, symmetric, right angle, reflect, translate.
  "A 2 by 3 by 4 cuboid" is the same solid whichever side stands up, so any orientation is
  accepted; a unit is a cube; "adjacent" means sharing a face (one structure).

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("on it", "the left one"),
distributive phrases ("on each vertex", "in each wing"), comparisons ("half as high", "the
square of 3"), corrections, removals and unusable input (gibberish, contradictions, sizes
past the cell, other languages, commands that are not about building).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — a bare stage direction
either way, an array touching or spaced, a cuboid on any face, a reflection that moves the
tower or copies it — and nothing else. Geometry comes only from `sdi.bench.boxes`, through
the shared checks in `language_checks` and the local checks below.

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

_SNAP = 0.01  # m: a column centre this close to a lattice point is on it


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev18-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _offset(dx: int, dy: int) -> k.Rel:
    """A's footprint centre lies `dx` cubes along x and `dy` along y from B's (± 1 cm)."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        (ax, ay), (bx0, by0) = bx.centre(a), bx.centre(b)
        if abs(ax - bx0 - dx * bx.CUBE) > _SNAP or abs(ay - by0 - dy * bx.CUBE) > _SNAP:
            return f"A at ({ax - bx0:+.3f}, {ay - by0:+.3f}) from B, want ({dx}, {dy}) cubes"
        return None

    return rel


def _centre_x_min(lo: float) -> k.Check:
    """The footprint centre at x ≥ `lo` (m): far back, near the back edge."""

    def f(bs: k.Boxes) -> k.Reason:
        x = bx.centre(bs)[0]
        return None if x >= lo else f"centre x {x:.3f}, want ≥ {lo}"

    return f


def _forms(rows: tuple[str, ...]) -> list[dict[tuple[int, int], int]]:
    """A plan of column heights (a digit a cell, "." empty) in its eight turns and mirror
    images, each moved to start at (0, 0)."""
    want = {(i, j): int(ch) for i, row in enumerate(rows) for j, ch in enumerate(row) if ch != "."}
    out = []
    for turn in bx.SYMMETRIES:
        moved = {turn(i, j): h for (i, j), h in want.items()}
        mi = min(i for i, _ in moved)
        mj = min(j for _, j in moved)
        out.append({(i - mi, j - mj): h for (i, j), h in moved.items()})
    return out


def _snap(values: list[float], n: int) -> tuple[list[int], float] | None:
    """Indices of `values` on n evenly spaced lattice points from their minimum to their
    maximum, and the pitch (m); None when some value is off the lattice."""
    lo, hi = min(values), max(values)
    if n == 1:
        return ([0] * len(values), 0.0) if hi - lo <= _SNAP else None
    pitch = (hi - lo) / (n - 1)
    if pitch < bx.CUBE - 0.005:
        return None
    idx = [round((v - lo) / pitch) for v in values]
    if any(abs(lo + i * pitch - v) > _SNAP for i, v in zip(idx, values, strict=True)):
        return None
    return idx, pitch


def _positions(*rows: str, gap: int | None = None, min_gap: int = 0) -> k.Check:
    """Positions on a plate or rack: single full columns of cubes standing on the table whose
    heights, position by position, are `rows` (a digit a position, "." an empty one) in any
    turn or mirror image, on an evenly spaced grid. With `gap`, neighbouring positions are
    that many cubes clear (± 1.5 cm; 0 = touching); otherwise any spacing, touching included,
    with at least `min_gap` cubes clear."""
    forms = _forms(rows)

    def pitch_ok(p: float) -> bool:
        if p == 0.0:
            return True
        if gap is not None:
            return abs(p - (gap + 1) * bx.CUBE) <= 0.015
        return p >= (min_gap + 1) * bx.CUBE - 0.015

    def f(bs: k.Boxes) -> k.Reason:
        if not bs:
            return "no parts"
        cols = bx.columns(bs)
        tops: list[tuple[float, float, int]] = []
        for col in cols:
            r = k.tower(len(col))(col) or k.only_cubes(col)
            if r:
                return f"a position is not a single column of cubes: {r}"
            if col[0].lo[2] > bx.TOL:
                return "a column off the table"
            x, y, _ = col[0].centre
            tops.append((x, y, len(col)))
        for form in forms:
            if len(form) != len(tops):
                continue
            ni = max(i for i, _ in form) + 1
            nj = max(j for _, j in form) + 1
            sx = _snap([t[0] for t in tops], ni)
            sy = _snap([t[1] for t in tops], nj)
            if sx is None or sy is None or not (pitch_ok(sx[1]) and pitch_ok(sy[1])):
                continue
            got = {(i, j): t[2] for i, j, t in zip(sx[0], sy[0], tops, strict=True)}
            if got == form:
                return None
        return f"{len(tops)} columns, not the wanted positions {list(rows)}"

    return f


def _plate(*rows: str, gap: int | None = None, min_gap: int = 0) -> k.Pred:
    """The whole layout, inside the workspace, is the positions `rows` (see `_positions`)."""
    return k.all_of(k.anything, k.layout(_positions(*rows, gap=gap, min_gap=min_gap)))


def _any_array(min_n: int) -> k.Pred:
    """The whole layout is a full, evenly spaced r × c array of single cubes, r·c ≥ min_n."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        n = len(bx.boxes(result))
        if n < min_n:
            return f"{n} parts, want an array of ≥ {min_n}"
        shapes = [(r, n // r) for r in range(1, n + 1) if n % r == 0]
        return k.any_of(*[_plate(*["1" * c] * r) for r, c in shapes])(result)

    return f


def _array_and(marker: k.Check, side: str, *rows: str, gap: int | None = None) -> k.Pred:
    """One structure passing `marker` on `side` of all the rest, which are the positions
    `rows` (see `_positions`)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        first: k.Reason = None
        for i, c in enumerate(comps):
            rest = [b for j, g in enumerate(comps) if j != i for b in g]
            if marker(c) is not None or not rest:
                continue
            r = _positions(*rows, gap=gap)(rest)
            if r is None and bx.side_of(c, rest) != side:
                r = f"the marker is {bx.side_of(c, rest)} of the array, want {side}"
            if r is None:
                return None
            first = first or r
        return first or "no marker structure"

    return f


def _cuboid(a: int, b: int, c: int) -> k.Check:
    """A solid a × b × c box of cells standing on any face (any side up)."""

    def f(bs: k.Boxes) -> k.Reason:
        got = sorted((*bx.plan_dims(bs), bx.thickness_cubes(bs)))
        if got != sorted((a, b, c)):
            return f"a {got[0]}×{got[1]}×{got[2]} box, want {a}×{b}×{c} in any orientation"
        return k.full(bs)

    return f


def _right_angle(arm: int, high: int) -> k.Check:
    """Two walls `high` cubes high meeting at a right angle in an L: arms of `arm` cubes that
    share the corner cube (footprint arm × arm) or one butting against the other's end
    (arm × arm+1); every column full."""

    def f(bs: k.Boxes) -> k.Reason:
        r = k.shape_letter("L")(bs)
        if r:
            return r
        if bx.plan_dims(bs) not in ((arm, arm), (arm, arm + 1)):
            return f"L footprint {bx.plan_dims(bs)}, want arms of {arm}"
        if bx.thickness_cubes(bs) != high:
            return f"{bx.thickness_cubes(bs)} high, want {high}"
        vox = bx.voxels(bs)
        return None if len(vox) == len(bx.cells(bs)) * high else "columns not full"

    return f


def _prism(bs: k.Boxes) -> k.Reason:
    """A prism of cubes: the same cross-section all along x, y or z, at least 2 long."""
    vox = bx.voxels(bs)
    if not vox:
        return "no parts"
    for axis in range(3):
        n = max(v[axis] for v in vox) + 1
        if n < 2:
            continue
        slices = [
            {tuple(v[a] for a in range(3) if a != axis) for v in vox if v[axis] == t}
            for t in range(n)
        ]
        if all(s == slices[0] and s for s in slices):
            return None
    return "no constant cross-section along any axis"


def _mirror(bs: k.Boxes, axis: int, at: float) -> bool:
    """Every box has a partner mirrored in the plane `axis` = `at` (± 5 mm)."""

    def image(b: k.Box) -> tuple[tuple[float, ...], tuple[float, ...]]:
        lo, hi = list(b.lo), list(b.hi)
        lo[axis], hi[axis] = 2 * at - b.hi[axis], 2 * at - b.lo[axis]
        return tuple(lo), tuple(hi)

    def same(p: tuple[float, ...], q: tuple[float, ...]) -> bool:
        return all(abs(u - v) <= 0.005 for u, v in zip(p, q, strict=True))

    return all(any(same(image(b)[0], c.lo) and same(image(b)[1], c.hi) for c in bs) for b in bs)


def _symmetric_about_middle(bs: k.Boxes) -> k.Reason:
    """The layout is its own mirror image in the table's left-right middle line (y = 0.30),
    or in a front-back line across its own centre lying near the middle of the table
    (x 0.40–0.55)."""
    if _mirror(bs, 1, 0.30):
        return None
    cx = bx.centre(bs)[0]
    if 0.40 <= cx <= 0.55 and _mirror(bs, 0, cx):
        return None
    return "not symmetric about a middle line of the table"


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
GATE = k.bridge
RING4 = k.all_of(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4))
RING5 = k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5))
# a bare "stage left/right": the performer's side (the robot's other side) or the robot's own
EITHER_SIDE = k.any_of(reg("left"), reg("right"))
MID_LR = k.near(y=0.30, tol=0.05)  # "centre stage" left to right
RISER = k.all_of(k.solid(2, 2), k.low(2))  # a 2 by 2 riser of no stated height: 1 or 2 high


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Two flats, each 4 wide and 3 high, both parallel to the front edge, one downstage of "
        "the other, with a 2-cube crossover between them.",
        k.pair(
            k.all_of(k.wall(4, 3), k.runs("y")),
            k.all_of(k.wall(4, 3), k.runs("y")),
            k.parallel_gap(2),
        ),
    ),
    _c(
        "rel-02",
        REL,
        "Set a 2 by 2 riser, one cube tall, and put a 3-high tower upstage of it, leaving a "
        "one-cube gap.",
        k.pair(T(3), k.block(2, 2, 1), k.gap_of(1, _B)),
    ),
    _c(
        "rel-03",
        REL,
        "Build a proscenium from two 4-high towers with a beam across the top, and set a 2 by "
        "3 platform, one high, upstage of it, not touching.",
        k.pair(k.block(2, 3, 1), GATE(4, pillars=2), k.all_rels(k.on_side(_B), _near)),
    ),
    _c(
        "rel-04",
        REL,
        "Put down a 3 x 3 plate, one cube thick, and stand a 2-high stack in its centre well.",
        k.any_of(  # on the plate's centre position, or down in the well where that cube was
            one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
            one(k.plan_heights("111", "121", "111")),
        ),
    ),
    _c(
        "rel-05",
        REL,
        "Make tower from 5 cubes and near to it, on left side, tower from 2 cubes. They not "
        "touching.",
        k.pair(T(2), T(5), k.all_rels(k.on_side(_L), _near)),
    ),
    _c(
        "rel-06",
        REL,
        "Build wall long 5, high 2, and behind of wall put pyramid from 2 levels, close but not "
        "touching.",
        k.pair(k.pyramid(2), k.wall(5, 2), k.all_rels(k.on_side(_B), _near)),
    ),
    _c(
        "rel-07",
        REL,
        "Put a bridge with pillars of 3 high and next to it on the right side a tower of 4 "
        "high, with one block in between.",
        k.pair(T(4), GATE(3, pillars=2), k.gap_of(1, _R)),
    ),
    _c(
        "rel-08",
        REL,
        "Bui1d a tovver of 4 and a 5econd tovver of 2, l0 crn apart.",
        k.pair(T(4), T(2), k.gaps(1, 2)),  # 10 cm clear = 2 cubes; centre to centre = 1 clear
    ),
    _c(
        "rel-09",
        REL,
        "PIace a pyrarnid of 3 leve1s in the rniddle and a tovver of 3 in fr0nt of it.",
        k.all_of(
            k.pair(T(3), k.pyramid(3), k.all_rels(k.on_side(_F), _near)),
            k.some(k.pyramid(3), reg("centre")),
        ),
    ),
    _c(
        "rel-10",
        REL,
        "Build two walls, each 5 long and 2 high, parallel to each other and 3 units apart.",
        k.pair(  # 3 clear between the faces, or 3 between the walls' centre lines (2 clear)
            k.wall(5, 2), k.wall(5, 2), k.either(k.parallel_gap(3), k.parallel_gap(2))
        ),
    ),
    _c(
        "rel-11",
        REL,
        "Two walls of length 4 and height 2, perpendicular to each other and meeting at a common "
        "vertex, so they form a right angle.",
        one(_right_angle(4, 2)),
    ),
    _c(
        "rel-12",
        REL,
        "A 2 by 2 by 2 cube, and a 1 by 1 by 4 column standing beside it, adjacent to one of its "
        "side faces.",
        one(k.plan_heights("22", "22", "4.")),
    ),
    _c(
        "rel-13",
        REL,
        "Place three towers of heights 2, 4 and 2 in a straight line, 1 unit apart, symmetric "
        "about the middle of the table.",
        k.all_of(k.line(T(2), T(4), T(2), gaps=(1,)), k.some(T(4), reg("centre"))),
    ),
    _c(
        "rel-14",
        REL,
        "Set up a 2 x 3 array of single cubes with a one-cube gap between neighbouring "
        "positions, and a 4-high marker stack off to the right of the whole array.",
        _array_and(T(4), _R, "111", "111", gap=1),
    ),
    _c(
        "rel-15",
        REL,
        "Make a platform of 3 by 5, one layer, and put on each corner a tower of 2 high.",
        one(k.base(3, 5), k.corner_columns(2), k.levels(15, 4, 4)),
    ),
    _c(
        "rel-16",
        REL,
        "Put a 2-high platform, 3 wide and 2 deep, downstage centre, and a 5-high tower in each "
        "wing.",
        k.structures(
            k.all_of(k.block_xy(2, 3, 2), reg("front"), MID_LR),
            k.all_of(T(5), reg("left")),
            k.all_of(T(5), reg("right")),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Put two towers from 4 cubes, distance between them three cubes, and in middle between "
        "them one small tower from 2 cubes.",
        k.line(T(4), T(2), T(4), gaps=(1,)),
    ),
    _c(
        "rel-18",
        REL,
        "a 3x3 b1ock 2 high with a 5ingle cube 0n t0p in the centre",
        one(k.levels(9, 9, 1), k.base(3, 3), k.top_centred()),
    ),
    _c(
        "rel-19",
        REL,
        "On a 3 x 3 grid of positions with no gaps, put a 2-high stack at A1 and another at C3; "
        "leave the rest empty.",
        _plate("2..", "...", "..2", gap=0),  # opposite corners, whichever way A1 is counted
    ),
    _c(
        "rel-20",
        REL,
        "A square-based pyramid of two layers, 3 by 3 and then 1 on top, with a column of "
        "height 3 adjacent to the middle of one edge of its base.",
        one(k.plan_heights("111", "121", "111", ".3.")),
    ),
    _c(
        "rel-21",
        REL,
        "Put a 3-high tower stage left of a 4-wide flat 2 high, not touching it.",
        # a bare "stage left": the performer's left (the robot's right) or the robot's left
        k.pair(T(3), k.wall(4, 2), k.all_rels(k.either(k.on_side(_L), k.on_side(_R)), _near)),
    ),
    _c(
        "rel-22",
        REL,
        "Make two towers next to each other with a gap of one block; the left one is twice as "
        "high as the right one, and the right one is 3 high.",
        k.pair(T(6), T(3), k.gap_of(1, _L)),
    ),
    _c(
        "rel-23",
        REL,
        "Build wall long 5 high 2. On this wall, on its middle, put tower from 2 cubes.",
        one(k.flat, k.profile(2, 2, 4, 2, 2)),
    ),
    _c(
        "rel-24",
        REL,
        "Label the rows A to C from front to back and the columns 1 to 4 from left to right, no "
        "gaps between positions. Put a 3-high stack in A1 and another in C4.",
        k.pair(T(3), T(3), _offset(2, -3)),  # C4 is two rows back and three columns right
    ),
    _c(
        "rel-25",
        REL,
        "Put tower from 2 cubes near to wall, on front side of it. Wall is long 6 and high 3.",
        k.pair(T(2), k.wall(6, 3), k.all_rels(k.on_side(_F), _near)),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "First set a 2 by 2 riser, one high, at centre stage. Then stack a second riser of the "
        "same size on top of it.",
        one(k.block(2, 2, 2), reg("centre")),
    ),
    _c(
        "seq-02",
        SEQ,
        "Build a flat 5 wide and 3 high across the back. Then strike it and put a 4-high tower "
        "there instead.",
        one(T(4), reg("back")),
    ),
    _c(
        "seq-03",
        SEQ,
        "Fill a 3 x 3 plate, one layer. Then empty the four corner positions.",
        one(k.plan_heights(".1.", "111", ".1.")),
    ),
    _c(
        "seq-04",
        SEQ,
        "Start with a row of 6 positions, one cube in each, no gaps. Then empty every other "
        "position, starting from the second.",
        k.in_line(3, T(1), 1),  # positions 1, 3 and 5 stay
    ),
    _c("seq-05", SEQ, "Make tower from 3 cubes. Then put on it one more. And one more.", one(T(5))),
    _c(
        "seq-06",
        SEQ,
        "First build platform 2 on 3, one layer. After this on platform put wall from 3 cubes "
        "long, 2 high, along long side.",
        one(k.plan_heights("333", "111")),
    ),
    _c(
        "seq-07",
        SEQ,
        "Make first a row of 4 blocks from left to right. Put then on the outer two blocks each "
        "another block.",
        one(k.lr_profile(2, 1, 1, 2), k.runs("y")),
    ),
    _c(
        "seq-08",
        SEQ,
        "5tep l: bui1d a wa11 4 1ong 2 high. 5tep 2: add 0ne more 1ayer 0n t0p.",
        one(k.wall(4, 3)),
    ),
    _c("seq-09", SEQ, "rnake a tovver of 6. then rernove the t0p tw0.", one(T(4))),
    _c(
        "seq-10",
        SEQ,
        "Build a 3 by 3 by 1 cuboid in the middle, then translate it 4 units towards the back.",
        # from the middle (x 0.45–0.50) 20 cm back: centre x ≥ 0.57, still central left to right
        one(k.block(3, 3, 1), _centre_x_min(0.57), k.near(y=0.30, tol=0.08)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Build a tower of height 3 whose centre is 10 cm to the left of the middle of the "
        "table. Then reflect it in the line through the middle that runs front to back.",
        k.any_of(  # the tower moved to its image, or the image added to it
            one(T(3), k.near(y=0.20)),
            k.structures(k.all_of(T(3), k.near(y=0.40)), k.all_of(T(3), k.near(y=0.20))),
        ),
    ),
    _c(
        "seq-12",
        SEQ,
        "Set a flight of 3 treads rising upstage. Actually, give it 4 treads.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Make two 2 x 2 plates, one layer each, side by side with a one-cube gap. Then add a "
        "second layer to the left plate only.",
        k.pair(k.block(2, 2, 2), k.block(2, 2, 1), k.gap_of(1, _L)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Build a tower of 7 blocks. No, that is too high, make it 4. And put it at the back.",
        one(T(4), reg("back")),
    ),
    _c(
        "seq-15",
        SEQ,
        "Build three towers from 3 cubes in row from left to right, gap one cube. Then take "
        "away right tower.",
        k.in_order("y", T(3), T(3), gaps=(1,)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Start with a 4 by 4 square of cubes, one layer. On it place a 3 by 3 square, then a 2 "
        "by 2, then a single cube: a square-based pyramid.",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c(
        "seq-17",
        SEQ,
        "bui|d a 4-5tep 5taircase rising to the 1eft, then take off the t0p 5tep.",
        one(  # the whole top step gone (3 steps), or only its top cube
            k.any_of(k.all_of(k.staircase(3), k.rises(_L)), k.lr_profile(3, 3, 2, 1))
        ),
    ),
    _c(
        "seq-18",
        SEQ,
        "Put a 2-high tower downstage left. Sorry, upstage left.",
        one(T(2), reg("back"), EITHER_SIDE),  # a bare "left" from the stage: either side
    ),
    _c(
        "seq-19",
        SEQ,
        "Make wall from 6 cubes long, 3 high. Then from top row take out two cubes on ends.",
        one(k.flat, k.profile(2, 3, 3, 3, 3, 2)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Fill positions 1 to 5 of a single row, one cube each, touching. Then move the cube from "
        "position 5 onto position 1.",
        one(k.flat, k.profile(2, 1, 1, 1)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Build a 2 by 3 by 2 cuboid. Now double its height.",
        one(k.any_of(k.block(2, 3, 4), k.block(2, 2, 6))),  # 2 × 3 base, or stood on its 2 × 2
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "a 3 x 4 array of single cubes", _plate("1111", "1111", "1111")),
    _c(
        "num-02",
        NUM,
        "Twelve positions in a 2 x 6 layout, one cube in each, 1 cube spacing between positions.",
        _plate("111111", "111111", gap=1),
    ),
    _c(
        "num-03",
        NUM,
        "Make a checkerboard on a 4 x 4 plate: fill every other position, one cube each.",
        k.any_of(  # the pattern on the table, or on top of a 4 x 4 plate
            one(k.plan_heights("1.1.", ".1.1", "1.1.", ".1.1")),
            one(k.plan_heights("2121", "1212", "2121", "1212")),
        ),
    ),
    _c(
        "num-04",
        NUM,
        "Make tower from 5 cubes and two towers from 3 cubes.",
        k.structures(T(5), T(3), T(3)),
    ),
    _c(
        "num-05",
        NUM,
        "Build four towers; first from 1 cube, every next one cube higher.",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    _c(
        "num-06",
        NUM,
        "Make three towers of 2 and then make all of them one higher.",
        k.each(3, T(3)),
    ),
    _c("num-07", NUM, "bui1d a tovver 0f l0 cubes", one(T(10))),
    _c("num-08", NUM, "a rovv 0f 7 cu8es", one(k.row(7))),
    _c(
        "num-09",
        NUM,
        "Build a cuboid with a volume of 18 cubes, 2 cubes high, on a square base.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "num-10",
        NUM,
        "Make three towers whose heights are consecutive even numbers, the smallest being 2.",
        k.structures(T(2), T(4), T(6)),
    ),
    _c("num-11", NUM, "Build a tower whose height is the square of 3.", one(T(9))),
    _c("num-12", NUM, "I need a flight of six treads.", one(k.staircase(6))),
    _c(
        "num-13",
        NUM,
        "Give me three 2-high risers, each 2 by 2, spread across downstage.",
        k.each(3, k.block(2, 2, 2), reg("front")),
    ),
    _c(
        "num-14",
        NUM,
        "Fill every other position of a row of 9 positions, starting with position 1, with a "
        "2-high stack.",
        k.in_line(5, T(2), 1),  # positions 1, 3, 5, 7, 9 of a touching row
    ),
    _c(
        "num-15",
        NUM,
        "Make a rack of 4 positions in a line, one cube gap between positions, with stacks 1, "
        "2, 3 and 4 high in that order.",
        k.line(T(1), T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-16",
        NUM,
        "Build a tower of 6 and next to it one that is half as high, with a small gap.",
        k.pair(T(3), T(6), k.within(0.15)),
    ),
    _c(
        "num-17",
        NUM,
        "Make 4 towers, in each 3 cubes, in one line, between them one cube.",
        k.in_line(4, T(3), 1),
    ),
    _c(
        "num-18",
        NUM,
        "A square-based pyramid of 3 layers with a total of 14 cubes.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "num-19",
        NUM,
        "Build from twelve cubes block two by two, high three.",
        one(k.block(2, 2, 3)),
    ),
    _c("num-20", NUM, "tvv0 tovvers: 0ne 0f 3, the 0ther 0f 8", k.structures(T(3), T(8))),
    _c(
        "num-21",
        NUM,
        "Make row of towers: first 2, second 3, third 4 cubes. Between towers one cube.",
        k.line(T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-22",
        NUM,
        "A 4 by 4 square slab, one layer, with a column of 3 cubes standing on each of its four "
        "vertices.",
        one(k.base(4, 4), k.corner_columns(3), k.levels(16, 4, 4, 4)),
    ),
    _c(
        "num-23",
        NUM,
        "Masking: a flat 3 wide and 4 high in each wing, both running up and down stage.",
        k.structures(
            k.all_of(k.wall(3, 4), k.runs("x"), reg("left")),
            k.all_of(k.wall(3, 4), k.runs("x"), reg("right")),
        ),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "a 2 by 3 by 4 cuboid", one(_cuboid(2, 3, 4))),
    _c("dim-02", DIM, "Build a cube with an edge length of 3.", one(k.block(3, 3, 3))),
    _c("dim-03", DIM, "a cuboid 4 long, 2 wide and 1 high", one(k.block(2, 4, 1))),
    _c(
        "dim-04",
        DIM,
        "A triangular prism of cubes, 4 long: its cross-section is 3 cubes along the bottom and "
        "1 on top in the middle.",
        one(k.pyramid_counts(12, 4), k.dims(3, 4), k.centred()),
    ),
    _c("dim-05", DIM, "A platform 4 wide by 3 deep, 2 high.", one(k.block_xy(3, 4, 2))),
    _c(
        "dim-06",
        DIM,
        "a flat 6 wide and 4 high running across the stage",
        one(k.wall(6, 4), k.runs("y")),
    ),
    _c(
        "dim-07",
        DIM,
        "A step unit with 3 treads, each tread 2 cubes wide.",
        one(k.staircase(3), k.dims(2, 3)),
    ),
    _c(
        "dim-08",
        DIM,
        "Lay out a 48-well plate: 6 by 8 positions, one cube in each well, no gaps.",
        one(k.block(6, 8, 1)),
    ),
    _c("dim-09", DIM, "a 2 x 4 plate, 2 cubes thick", one(k.block(2, 4, 2))),
    _c(
        "dim-10",
        DIM,
        "Make wall: length 7 cubes, height 3 cubes, thickness 1.",
        one(k.wall(7, 3)),
    ),
    _c("dim-11", DIM, "Need block: long 5, wide 2, high 3.", one(k.block(2, 5, 3))),
    _c("dim-12", DIM, "Make a tower of 30 centimetres high.", one(T(6))),
    _c("dim-13", DIM, "a wa1l 2O cm 1ong and l5 cm high", one(k.wall(4, 3))),
    _c("dim-14", DIM, "a 5lab 3 x 3, 5 crn thick", one(k.block(3, 3, 1))),
    _c("dim-15", DIM, "tovver 25 crn ta1l", one(T(5))),
    _c(
        "dim-16",
        DIM,
        "A square of side 5 made of cubes, one layer, hollow inside.",
        one(RING5),
    ),
    _c(
        "dim-17",
        DIM,
        "A prism whose cross-section is a right-angled staircase triangle with both legs 3 "
        "cubes, extruded to a length of 4.",
        one(k.staircase(3), k.dims(3, 4)),
    ),
    _c(
        "dim-18",
        DIM,
        "A riser 40 cm wide, 15 cm deep and 10 cm high.",
        one(k.block_xy(3, 8, 2)),
    ),
    _c(
        "dim-19",
        DIM,
        "Make pyramid, base 5 on 5, levels 3.",
        one(k.pyramid(3), k.base(5, 5)),
    ),
    _c(
        "dim-20",
        DIM,
        "A proscenium arch: two legs 6 high, a header beam across them, the opening one cube wide.",
        one(GATE(6, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "dim-21",
        DIM,
        "Build a square of 4 by 4 blocks, only the edge, 2 layers high.",
        one(k.ring_of(high=2, inner=(2, 2)), k.dims(4, 4)),
    ),
    _c(
        "dim-22",
        DIM,
        "A 3 x 3 array of stacks, each stack 3 cubes tall, 2 cubes of spacing between stacks.",
        _plate("333", "333", "333", gap=2),
    ),
    _c(
        "dim-23",
        DIM,
        "A wall 5 long, one cube thick, whose heights go 1, 2, 3, 2, 1, symmetric about its "
        "middle.",
        one(k.flat, k.profile(1, 2, 3, 2, 1)),
    ),
    _c(
        "dim-24",
        DIM,
        "A 3 by 5 slab, one layer, with a row of cubes on top along one of its long edges.",
        one(k.plan_heights("22222", "11111", "11111")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A 3 by 3 platform, one high, but leave the centre out for a trap door.",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c(
        "neg-02",
        NEG,
        "Fill a 4 x 4 plate, one layer, but leave the four middle wells empty.",
        one(RING4),
    ),
    _c(
        "neg-03",
        NEG,
        "A row of 5 positions with no gaps: fill every one except position 3.",
        _plate("11.11", gap=0),
    ),
    _c(
        "neg-04",
        NEG,
        "Make tower from 4 cubes, but not in middle, near to wall on back.",
        one(T(4), _centre_x_min(0.60), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-05",
        NEG,
        "Build two towers from 3 cubes, not touching, but distance not more than one cube.",
        k.pair(T(3), T(3), k.within(bx.CUBE + 0.015)),
    ),
    _c(
        "neg-06",
        NEG,
        "Make a staircase of 4 steps, not going up to the back but up to the left.",
        one(k.staircase(4), k.rises(_L)),
    ),
    _c(
        "neg-07",
        NEG,
        "N0 tovver ta11er than 4. Bui1d three 0f them, a11 diff erent.",
        k.any_of(*[k.structures(*map(T, hs)) for hs in itertools.combinations(range(1, 5), 3)]),
    ),
    _c(
        "neg-08",
        NEG,
        "A 3 by 4 rectangle of cubes, one layer, but with no cubes on its vertices.",
        one(k.plan_heights(".11.", "1111", ".11.")),
    ),
    _c(
        "neg-09",
        NEG,
        "Two walls of length 5 and height 2 that are parallel but not adjacent: leave 2 units "
        "between them.",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.parallel_gap(2)),
    ),
    _c(
        "neg-10",
        NEG,
        "A flat 5 wide and 2 high upstage, not in the wings, keep it centre.",
        one(k.wall(5, 2), k.runs("y"), reg("back"), MID_LR),
    ),
    _c(
        "neg-11",
        NEG,
        "Build a 2 x 3 array of 2-high stacks, and make sure no two stacks touch.",
        _plate("222", "222", min_gap=1),
    ),
    _c(
        "neg-12",
        NEG,
        "Build a 3 by 3 block of 2 layers, but not the middle one in the upper layer.",
        one(k.plan_heights("222", "212", "222")),
    ),
    _c(
        "neg-13",
        NEG,
        "d0nt put the pyrarnid 0n the 1eft. put it 0n the riqht. 2 1evels.",
        one(k.pyramid(2), reg("right")),
    ),
    _c(
        "neg-14",
        NEG,
        "Tower from 6 cubes, but not standing on table: put it on platform 3 on 3 from one layer.",
        one(k.on_top(T(6), k.block(3, 3, 1)), k.levels(9, 1, 1, 1, 1, 1, 1)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "PIease bui1d a tow er of 6 cu bes.", one(T(6))),
    _c(
        "typo-02",
        TYP,
        "a pyrarnid, 3 1eve1s, 1n the rniddle",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "typo-03",
        TYP,
        "tvvo 5tacks 0f 4, 5 crn apart",
        k.pair(T(4), T(4), k.gap_of(1)),  # centre to centre 5 cm would make them touch
    ),
    _c("typo-04", TYP, "a 8ridge: 2 pi11ars 0f 3, a bearn acr0ss", one(GATE(3, pillars=2))),
    _c("typo-05", TYP, "rnake a wa11 5 1ong, 3 high ~ thanks", one(k.wall(5, 3))),
    _c(
        "typo-06",
        TYP,
        "5taircase 0f 5 5teps ris1ng t0 the back",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c("typo-07", TYP, "a 4x4 rinq, 1 hiqh", one(RING4)),
    _c(
        "typo-08",
        TYP,
        "3 x 3 s1ab, 2 1ayers, at the fr0nt 1eft",
        one(k.block(3, 3, 2), reg("front left")),
    ),
    _c("typo-09", TYP, "Make towr from 4 cubs on rigt side.", one(T(4), reg("right"))),
    _c(
        "typo-10",
        TYP,
        "a platfrom 3 wide 2 deep, one hgih, dwonstage",
        one(k.block_xy(2, 3, 1), reg("front")),
    ),
    _c("typo-11", TYP, "fill a 2 x 3 plaet, one layre, no gpas", one(k.block(2, 3, 1))),
    _c("typo-12", TYP, "a cubiod 3 by 2 by 2", one(_cuboid(3, 2, 2))),
    _c(
        "typo-13",
        TYP,
        "tovver of 3 0n t0p 0f a 2x2 p1ate",
        one(k.on_top(T(3), k.block(2, 2, 1))),
    ),
    _c(
        "typo-14",
        TYP,
        "a rovv, l5 crn 1ong, runn1ng 1eft t0 riqht",
        one(k.row(3), k.runs("y")),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Tower from 5 cubes on left side build.", one(T(5), reg("left"))),
    _c(
        "wo-02",
        WO,
        "On back side of table wall put, long 4, high 3.",
        one(k.wall(4, 3), reg("back")),
    ),
    _c(
        "wo-03",
        WO,
        "Next to the tower of 3 must a tower of 5 come, on the right side, with one block between.",
        k.pair(T(5), T(3), k.gap_of(1, _R)),
    ),
    _c(
        "wo-04",
        WO,
        "On the left must a tower of 3 blocks come, and on the right a tower of 5 blocks.",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(5), reg("right"))),
    ),
    _c(
        "wo-05",
        WO,
        "Downstage, a 2-high riser, 2 by 3; that's where the chorus stands.",
        one(k.block(2, 3, 2), reg("front")),
    ),
    _c(
        "wo-06",
        WO,
        "In position B2 of a 3 x 3 plate, one layer thick, stand a 3-high stack.",
        k.any_of(  # on the plate's middle position, or in place of its middle cube
            one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
            one(k.plan_heights("111", "131", "111")),
        ),
    ),
    _c(
        "wo-07",
        WO,
        "Of height 4, a cuboid on a square base with edge 2, build one.",
        one(k.block(2, 2, 4)),
    ),
    _c("wo-08", WO, "3 high | tovver | back riqht", one(T(3), reg("back right"))),
    _c(
        "wo-09",
        WO,
        "Between two towers from 4 cubes put wall from 3 cubes long, high 2, everything touching.",
        one(k.flat, k.profile(4, 2, 2, 2, 4)),
    ),
    _c(
        "wo-10",
        WO,
        "Five cubes in row from left to right on front side lay.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-11",
        WO,
        "Upstage of the 3-high tower, one cube back from it, a 2 by 2 riser.",
        k.pair(RISER, T(3), k.gap_of(1, _B)),
    ),
    _c(
        "wo-12",
        WO,
        "Perpendicular to the front edge, a wall: length 5, height 2.",
        one(k.wall(5, 2), k.runs("x")),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Okay, notes from tech rehearsal: the director hated the old look, so scrap it. All we "
        "need now is one 3 by 3 platform, two cubes high, centre stage. Thanks, team!",
        one(k.block(3, 3, 2), reg("centre")),
    ),
    _c(
        "fil-02",
        FIL,
        "Quick one before the half: a flight of 3 treads going up towards upstage, and that's "
        "it. Break a leg, everyone!",
        one(k.staircase(3), k.rises(_B)),
    ),
    _c(
        "fil-03",
        FIL,
        "Hi, it's Priya from the assay lab. We don't need the usual plate layout today. Could "
        "you just put out a 2 x 2 block of cubes, one layer? Thanks so much, I'll log it in the "
        "notebook.",
        one(k.block(2, 2, 1)),
    ),
    _c(
        "fil-04",
        FIL,
        "Per SOP-114, step 6 (initial the sheet when done): place a single 5-high stack. Gloves "
        "on, as usual.",
        one(T(5)),
    ),
    _c(
        "fil-05",
        FIL,
        "Good day. I am new here, sorry for my English, I learn still. Please make tower from 6 "
        "cubes. Thank you very much.",
        one(T(6)),
    ),
    _c(
        "fil-06",
        FIL,
        "Hello, colleague. Yesterday we have problem with gripper, but now all is working. So: "
        "build please bridge, pillars from 4 cubes. Thank you.",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "fil-07",
        FIL,
        "Hoi! Ok so, my manager says I must test this, so here it goes: a wall of 6 long and 2 "
        "high. Dank je!",
        one(k.wall(6, 2)),
    ),
    _c(
        "fil-08",
        FIL,
        "- - - N0TE (pIease read) - - - Bui1d a 4 high tovver. thx, J.",
        one(T(4)),
    ),
    _c(
        "fil-09",
        FIL,
        "Frorn the desk of Mr. Harris: 0ne pyrarnid, 2 1eve1s. Regards",
        one(k.pyramid(2)),
    ),
    _c(
        "fil-10",
        FIL,
        "Right, class, eyes on the robot. Today's lesson is on 3-D shapes, and our first "
        "example is going to be a cuboid 2 by 2 by 3. Watch closely, everyone.",
        one(_cuboid(2, 2, 3)),
    ),
    _c(
        "fil-11",
        FIL,
        "Now, as I said last week, a staircase is really a prism in disguise, but never mind "
        "that for now: build a 4-step staircase for us.",
        one(k.staircase(4)),
    ),
    _c(
        "fil-12",
        FIL,
        "Heads up from the stage manager: the fly system is down and the actors are on break. "
        "Set a 5-high tower downstage left. Stage left, that's the actor's left as they look "
        "out at the house.",
        one(T(5), reg("front right")),  # glossed: the performer's left, the robot's right
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "Put a 3-high tower downstage centre.",
        one(T(3), reg("front"), MID_LR),
    ),
    _c(
        "reg-02",
        REG,
        "Set a 2 by 2 riser, one cube tall, downstage left.",
        one(k.block(2, 2, 1), reg("front"), EITHER_SIDE),  # bare stage direction: either side
    ),
    _c(
        "reg-03",
        REG,
        "a flat 4 wide and 2 high, upstage centre, along the back edge",
        one(k.wall(4, 2), k.runs("y"), reg("back"), MID_LR),
    ),
    _c(
        "reg-04",
        REG,
        "A 4-high tower in the stage-right wing, stage right meaning the performer's right as "
        "they face the audience.",
        one(T(4), reg("left")),  # the performer faces the robot: their right is +y
    ),
    _c(
        "reg-05",
        REG,
        "Put a 2-high stack in the back-left corner of the table, like position A1 on a plate.",
        one(T(2), reg("back left")),
    ),
    _c(
        "reg-06",
        REG,
        "Place a 2 x 3 plate, one layer, in the front right corner.",
        one(k.block(2, 3, 1), reg("front right")),
    ),
    _c(
        "reg-07",
        REG,
        "Put tower from 3 cubes near to left edge of table.",
        one(T(3), k.centre_y_min(0.45)),
    ),
    _c(
        "reg-08",
        REG,
        "Build pyramid from 2 levels in far right corner, far from me.",
        one(k.pyramid(2), reg("back right")),
    ),
    _c(
        "reg-09",
        REG,
        "Put a wall of 5 long and 2 high along the front edge, close to the robot.",
        one(k.wall(5, 2), k.runs("y"), reg("front")),
    ),
    _c(
        "reg-10",
        REG,
        "p1ace a 3-cube tovver at x = 0.5O, y = 0.2O",
        one(T(3), k.near(0.50, 0.20, 0.011)),
    ),
    _c(
        "reg-11",
        REG,
        "tovver 0f 2 1n the back, rniddle",
        one(T(2), reg("back"), MID_LR),
    ),
    _c(
        "reg-12",
        REG,
        "Place a cube of side 2 with its centre at the point (0.45, 0.30).",
        one(k.block(2, 2, 2), k.near(0.45, 0.30, 0.011)),
    ),
    _c(
        "reg-13",
        REG,
        "Build a 3 by 1 by 1 row on the table's line of symmetry, the one running front to back.",
        one(k.row(3), k.runs("x"), k.near(y=0.30, tol=0.011)),
    ),
    _c(
        "reg-14",
        REG,
        "Put a 4-high stack at coordinates x = 600 mm, y = 400 mm (centre of the stack).",
        one(T(4), k.near(0.60, 0.40, 0.011)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Any set piece you like, but keep it under 3 cubes high.",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c(
        "open-02",
        OPEN,
        "Give me some scenery for the back of the stage, your design.",
        k.all_of(k.anything, k.layout(reg("back"))),
    ),
    _c(
        "open-03",
        OPEN,
        "Lay out any array you like: at least 4 positions, single cubes, evenly spaced.",
        _any_array(4),
    ),
    _c(
        "open-04",
        OPEN,
        "Put something on the table to test the gripper, anything with at least 5 cubes.",
        k.all_of(k.anything, k.layout(k.parts(lo=5))),
    ),
    _c(
        "open-05",
        OPEN,
        "Make what you want, only not high, maximum 2 cubes.",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c("open-06", OPEN, "Build any bridge, size you choose.", k.all_of(k.anything, one(k.arch))),
    _c(
        "open-07",
        OPEN,
        "Make something nice, you decide, but use no more than 10 blocks.",
        k.all_of(k.anything, k.layout(k.parts(hi=10))),
    ),
    _c("open-08", OPEN, "bui1d s0rnething. any th1ng.", k.anything),
    _c(
        "open-09",
        OPEN,
        "Build any prism you like out of cubes.",
        k.all_of(k.anything, one(_prism)),
    ),
    _c(
        "open-10",
        OPEN,
        "Build a shape of your choice that is symmetric about the middle of the table.",
        k.all_of(k.anything, k.layout(_symmetric_about_middle)),
    ),
    _c(
        "open-11",
        OPEN,
        "Some steps for the actors to climb, as many as you like.",
        k.all_of(k.anything, one(k.staircase())),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Zbuduj wieżę z pięciu kostek.", k.honest(one(T(5)))),
    _c(
        "bad-02",
        BAD,
        "Построй башню из четырёх кубиков слева.",
        k.honest(one(T(4), reg("left"))),
    ),
    _c("bad-03", BAD, "Bouw een muur van zes lang en twee hoog.", k.honest(one(k.wall(6, 2)))),
    _c("bad-04", BAD, "~~ ll1l 0O0 rn rn ,,, ##", k.honest()),
    _c("bad-05", BAD, "bui1d a [i11egib1e] 0f [?] cu bes", k.honest(k.anything)),
    _c(
        "bad-06",
        BAD,
        "A flat 20 wide and 3 high across the whole stage.",  # 20 cubes: past the cell
        k.honest(one(k.flat)),
    ),
    _c(
        "bad-07",
        BAD,
        "Fill a whole 96-well plate, 8 by 12, with a 2-high stack in every well, 1 cube "
        "spacing.",  # 15 × 23 cubes: past the cell
        k.honest(k.anything),
    ),
    _c(
        "bad-08",
        BAD,
        "A cube whose edges are 2, 3 and 4 cubes long.",
        k.honest(
            one(k.any_of(_cuboid(2, 3, 4), k.block(2, 2, 2), k.block(3, 3, 3), k.block(4, 4, 4)))
        ),
    ),
    _c(
        "bad-09",
        BAD,
        "Two walls that are both parallel and perpendicular to each other.",
        k.honest(k.anything),
    ),
    _c(
        "bad-10",
        BAD,
        "A tower whose height is 3 squared plus 3.",  # 12: past the 10-level limit
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-11",
        BAD,
        "Make tower from 4 cubes, on left side and on right side, but only one tower.",
        k.honest(one(T(4))),
    ),
    _c("bad-12", BAD, "Put on it one more cube.", k.honest(k.anything)),
    _c("bad-13", BAD, "tovver 0f l5", k.honest(one(T(lo=1, hi=10)))),  # 15 levels
    _c("bad-14", BAD, "Fly in the backdrop and bring up the lights.", k.honest()),
    _c("bad-15", BAD, "Pipette 50 µL into wells A1 to A6.", k.honest()),
    _c(
        "bad-16",
        BAD,
        "Make a tower of 3 high that is higher than the tower of 5 next to it.",
        k.honest(k.anything),
    ),
    _c(
        "bad-17",
        BAD,
        "Put the 2 by 2 platform upstage and downstage at the same time.",
        k.honest(one(k.solid(2, 2))),
    ),
]
