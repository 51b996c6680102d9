"""A sixteenth held-out set for the language front end (dev16): five new voices at the cell.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set or any benchmark result, and worded apart from `language_dev` …
`language_dev15` (no command shared with any set, see tests). Nothing here was run through
the system while it was written. The commands come from five kinds of people:

* a warehouse / logistics lead who thinks in pallets, stacks, lanes, bays and aisles ("stack
  4 high in the left lane", "two pallets with an aisle between");
* a teenager texting from a phone — lowercase, no punctuation, slang and abbreviations ("u",
  "n", "w", "lil", "idc", "thx");
* a retired mechanical engineer writing long, formal, precise sentences with millimetres and
  careful qualifications ("a column of three further cubes upon its central cube");
* a robotics researcher in coordinates, vectors and terse math-like notation ("tower(h=5) @
  (0.45, 0.30)", "grid 3x5, one layer", "A.h += 2");
* a safety officer or shift supervisor who adds limits and prohibitions ("do not stack above
  3", "keep it clear of the front edge", "nothing within 10 cm of the robot-side edge").

About 70 % ordinary (one or two structures with a size, a place, one relation or a two-step
sequence) and 30 % harder: three or more structures, references ("it", "them", "the tall
one", "A" and "B"), distributive phrases ("each", "on each of its sides", "between each"),
comparisons ("twice as tall", "half that size", "2 less than 10"), corrections ("actually nvm
make it 3"), removals and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording — one merged structure where a
tower could be set down touching another, both clear and centre-to-centre readings of an
unqualified spacing where both are buildable, any small size for "a lil tower" — and nothing
else. Geometry comes only from `sdi.bench.boxes`, through the shared checks in
`language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels); cube 0.05 m,
beam 0.15 m; left = +y, back = +x (away from the robot at x = 0, y = 0.30).
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


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev16-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _apart(lo: float, hi: float | None = None) -> k.Rel:
    """A and B are at least `lo` m (and at most `hi` m, when given) apart, clear."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        gap = bx.separation(a, b)
        if gap < lo or (hi is not None and gap > hi):
            return f"{gap:.3f} m apart, want {lo}–{hi if hi is not None else ''} m"
        return None

    return rel


def _either_way(*checks: k.Check, max_gap: float | None = None) -> k.Pred:
    """The structures in a line along x or y, in this order or the reverse."""
    rev = checks[::-1]
    return k.any_of(
        k.in_order("x", *checks, max_gap=max_gap),
        k.in_order("x", *rev, max_gap=max_gap),
        k.in_order("y", *checks, max_gap=max_gap),
        k.in_order("y", *rev, max_gap=max_gap),
    )


def _gap_between(check: k.Check, n: int, axis: str | None = None) -> k.Pred:
    """Exactly two structures pass `check`; they are `n` cubes apart (clear, ± 1.5 cm), side
    by side along `axis` ("x" front–back, "y" left–right) when given."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        two = [g for g in comps if check(g) is None]
        if len(two) != 2:
            return f"{len(two)} structures of that kind, want 2"
        r = k.gap_of(n)(two[0], two[1])
        if r:
            return r
        if axis is not None:
            line = {"x": (_F, _B), "y": (_L, _R)}[axis]
            if bx.side_of(two[0], two[1]) not in line:
                return f"not side by side along {axis}"
        return None

    return f


def _lanes(n_lanes: int, per_lane: int) -> k.Pred:
    """The structures stand in `n_lanes` straight lanes (along x or along y) of `per_lane`
    each: their centres share one of `n_lanes` coordinates across the lanes (± 2 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        for axis in (0, 1):
            groups: list[list[float]] = []
            for v in sorted(bx.centre(g)[axis] for g in comps):
                if groups and v - groups[-1][0] <= 0.02:
                    groups[-1].append(v)
                else:
                    groups.append([v])
            if len(groups) == n_lanes and all(len(g) == per_lane for g in groups):
                return None
        return f"not {n_lanes} lanes of {per_lane}"

    return f


def _collinear(result: Mapping[str, Any]) -> k.Reason:
    """Every structure's centre on one line along x or along y (± 2 cm)."""
    comps = k.separate_structures(result)
    if isinstance(comps, str):
        return comps
    for axis in (0, 1):
        vs = [bx.centre(g)[axis] for g in comps]
        if max(vs) - min(vs) <= 0.02:
            return None
    return "not in one straight line"


def _ring_clear(n: int) -> k.Rel:
    """A (a ring) surrounds B, centred on it, with exactly `n` cubes of free floor between B's
    footprint and the ring on every side."""

    def rel(a: k.Boxes, b: k.Boxes) -> k.Reason:
        r = k.centred_in()(a, b)
        if r:
            return r
        fx, fy = bx.footprint_cubes(b)
        cells = round(bx.interior_area(a) / (bx.CUBE * bx.CUBE))
        want = (fx + 2 * n) * (fy + 2 * n)
        return None if cells == want else f"ring interior {cells} cells, want {want}"

    return rel


def _at_high_end(a: k.Boxes, b: k.Boxes) -> k.Reason:
    """A stands beyond the end B (a staircase) climbs towards, clear of it by 1 cube or more
    and no more than 25 cm."""
    up = bx.rises_towards(b)
    if up is None:
        return "B is not a staircase"
    if bx.side_of(a, b) != up:
        return f"A is {bx.side_of(a, b)} of the stairs, which climb towards {up}"
    return _apart(0.035, 0.25)(a, b)


def _min_y(y: float) -> k.Check:
    """Every part lies at y ≥ `y` (m), i.e. on that side of y or further left."""

    def f(bs: k.Boxes) -> k.Reason:
        lo = min(b.lo[1] for b in bs)
        return None if lo >= y - bx.TOL else f"a part reaches y {lo:.3f}, want ≥ {y}"

    return f


def _centre_x(lo: float) -> k.Check:
    """The footprint centre at x ≥ `lo` (m)."""

    def f(bs: k.Boxes) -> k.Reason:
        x = bx.centre(bs)[0]
        return None if x >= lo else f"centre x {x:.3f}, want ≥ {lo}"

    return f


def _centre_y(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m)."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


T = k.tower
one = k.one
reg = k.region
_near = k.near_rel()
GATE = k.bridge
RING5 = k.all_of(k.ring_of(high=1, inner=(3, 3)), k.dims(5, 5))
RING4 = k.all_of(k.ring_of(high=1, inner=(2, 2)), k.dims(4, 4))
PALLET22 = k.block(2, 2, 1)
WALL_X = k.all_of(k.wall(5, 2), k.runs("x"))


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "Two stacks in the same lane, one 4 high and one 2 high, with a cube's width of "
        "clearance between them.",
        k.pair(T(4), T(2), k.gap_of(1)),
    ),
    _c(
        "rel-02",
        REL,
        "yo can u put a tower of 3 on top of a 2 by 2 block thx",
        one(k.on_top(T(3), k.solid(2, 2))),
    ),
    _c(
        "rel-03",
        REL,
        "I should be obliged if you would erect a wall running left to right, six cubes long "
        "and two high, and stand a column of four cubes 50 mm beyond its left-hand end.",
        k.pair(T(4), k.all_of(k.wall(6, 2), k.runs("y")), k.gap_of(1, _L)),
    ),
    _c(
        "rel-04",
        REL,
        "tower(h=5) @ (0.45, 0.30); tower(h=2) at +0.10 in y from it",
        k.structures(
            k.all_of(T(5), k.near(0.45, 0.30, 0.02)), k.all_of(T(2), k.near(0.45, 0.40, 0.02))
        ),
    ),
    _c(
        "rel-05",
        REL,
        "Build a three-step staircase with a tower of 3 at its top end. Leave at least one "
        "cube of clearance between the two, no contact.",
        k.pair(T(3), k.staircase(3), _at_high_end),
    ),
    _c(
        "rel-06",
        REL,
        "make 2 stacks of 4 n put a bridge thing across the top",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "rel-07",
        REL,
        "Fence off a bay 5 cubes by 5, one high, and put a stack of 3 right in the middle of it.",
        k.pair(RING5, T(3), k.centred_in()),
    ),
    _c(
        "rel-08",
        REL,
        "pyramid(levels=3) centred at (0.50, 0.30); ring(h=1) around it with 1-cube clearance "
        "on all sides",
        k.pair(k.ring_of(high=1), k.all_of(k.pyramid(3), k.near(0.50, 0.30)), _ring_clear(1)),
    ),
    _c(
        "rel-09",
        REL,
        "Two towers of 4 with a beam across them. The beam must bear on both towers, no "
        "overhanging off one side.",
        one(GATE(4, pillars=2)),
    ),
    _c(
        "rel-10",
        REL,
        "Kindly lay a slab 150 mm square and one cube in thickness, and erect upon its central "
        "cube a column of three further cubes.",
        one(k.on_top(T(3), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "cn u make a lil wall 3 long 2 high n stick a tower of 4 right behind the middle of it "
        "touching",
        one(k.plan_heights("222", ".4."), k.upper_side(_B, 2)),
    ),
    _c(
        "rel-12",
        REL,
        "Two 2 by 2 pallets, one high, left and right of each other with a 15 cm aisle between, "
        "and a stack of 5 in the middle of the aisle.",
        k.all_of(k.between_(T(5), PALLET22), _gap_between(PALLET22, 3, "y")),
    ),
    _c(
        "rel-13",
        REL,
        "wall(len=5, h=2) along y; tower(h=4) at both ends, flush",
        one(
            k.any_of(
                k.all_of(
                    k.flat,
                    k.runs("y"),
                    k.any_of(k.profile(4, 2, 2, 2, 2, 2, 4), k.profile(4, 2, 2, 2, 4)),
                ),
                k.plan_heights("22222", "4...4"),
            )
        ),
    ),
    _c(
        "rel-14",
        REL,
        "Inside a 5 by 5 fence one cube high, put a stack of 2. The stack is not to touch the "
        "fence at any point.",
        k.around(T(2), RING5),
    ),
    _c(
        "rel-15",
        REL,
        "3 towers in a row middle one tallest like 6 n the outside ones 3 lil gaps",
        _either_way(T(3), T(6), T(3), max_gap=0.15),
    ),
    _c(
        "rel-16",
        REL,
        "Please construct two columns of five cubes each, their centres 100 mm apart, and "
        "bridge them at the top with a single beam.",
        one(GATE(5, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "rel-17",
        REL,
        "Stack 3 high in the left lane and 3 high in the right lane, and put a 2 by 2 pallet, "
        "one high, dead centre between them.",
        k.all_of(
            k.between_(PALLET22, T(3)),
            k.some(T(3), reg("left")),
            k.some(T(3), reg("right")),
        ),
    ),
    _c(
        "rel-18",
        REL,
        "block(2,2,2) at workspace centre; tower(h=3) on each of its 4 sides, clearance 1 cube",
        k.on_every_side(k.all_of(k.block(2, 2, 2), reg("centre")), T(3), 1),
    ),
    _c(
        "rel-19",
        REL,
        "Keep the pyramid, three levels, at least 10 cm away from the 4-high tower. The gripper "
        "needs that clearance.",
        k.pair(k.pyramid(3), T(4), _apart(0.085)),
    ),
    _c(
        "rel-20",
        REL,
        "build a castle n put a lil tower in front of it not touching",
        k.pair(T(lo=1, hi=5), k.castle, k.all_rels(k.on_side(_F), _near)),
    ),
    _c(
        "rel-21",
        REL,
        "I require two walls, each 250 mm long and 100 mm high, parallel to one another and "
        "100 mm apart, so as to form a corridor leading away from me.",
        k.pair(WALL_X, WALL_X, k.either(k.parallel_gap(2), k.parallel_gap(1))),
    ),
    _c(
        "rel-22",
        REL,
        "Three-step staircase, and a stack of 4 on the floor against its top end, touching, "
        "like a ramp up to the stack.",
        one(k.any_of(k.profile(1, 2, 3, 4), k.plan_heights("1234", "123."))),
    ),
    _c(
        "rel-23",
        REL,
        "Four stacks of 3 in a line, one cube's gap between each stack.",
        k.in_line(4, T(3), 1),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Stack 3 high, then a second stack of 3 with a one-cube gap, then lay a beam across the "
        "two.",
        one(GATE(3, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "seq-02",
        SEQ,
        "ok first a 3x3 square flat on the table then stack 2 more on the middle one",
        one(k.on_top(T(2), k.block(3, 3, 1)), k.centred(), k.levels(9, 1, 1)),
    ),
    _c(
        "seq-03",
        SEQ,
        "First, lay a row of five cubes running from left to right. Having done so, place a "
        "second course of three cubes upon it, centred, and finally a single cube atop that.",
        one(k.pyramid_counts(5, 3, 1), k.flat, k.runs("y")),
    ),
    _c(
        "seq-04",
        SEQ,
        "step 1: tower(h=6) @ (0.50, 0.30). step 2: remove top 2 cubes.",
        one(T(4), k.near(0.50, 0.30)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Build a wall 6 long and 4 high, then take the top course off. We don't go above 15 cm "
        "on this bench.",
        one(k.wall(6, 3)),
    ),
    _c(
        "seq-06",
        SEQ,
        "Lay down a 4 by 3 pallet, one layer, then put a second layer the same size straight on "
        "top.",
        one(k.block(4, 3, 2)),
    ),
    _c("seq-07", SEQ, "make a tower of 5 actually nvm make it 3", one(T(3))),
    _c(
        "seq-08",
        SEQ,
        "Begin with two columns of three cubes side by side, left and right, 100 mm apart "
        "centre to centre. Once they are complete, raise the left-hand column by a further two "
        "cubes.",
        k.pair(T(5), T(3), k.gap_of(1, _L)),
    ),
    _c(
        "seq-09",
        SEQ,
        "1) grid 3x5, one layer  2) remove the 4 corner cubes",
        one(k.plan_heights(".111.", "11111", ".111.")),
    ),
    _c(
        "seq-10",
        SEQ,
        "Put up the two towers, 4 and 4, one cube apart. Then the beam across. Then stop: "
        "nothing goes on top of the beam.",
        one(k.bare_bridge, GATE(4, pillars=2), k.leg_gap(1)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Three stacks of 2 in a row left to right, gaps between. Then move the middle stack "
        "onto the right-hand one.",
        k.pair(T(2), T(4), k.all_rels(k.on_side(_L), k.near_rel(0.30))),
    ),
    _c(
        "seq-12",
        SEQ,
        "do a pyramid 3 levels then take the top cube off lol",
        one(k.pyramid(2), k.long(lo=3)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Lay a square ring of cubes, five to a side on the outside and one course high; then "
        "build up the four corners only, to three cubes each.",
        one(k.ring, k.dims(5, 5), k.corner_columns(2), k.levels(16, 4, 4)),
    ),
    _c(
        "seq-14",
        SEQ,
        "t0: row(n=4) along x at y=0.20. t1: copy it to y=0.40.",
        k.structures(
            k.all_of(k.row(4), k.runs("x"), k.near(y=0.20, tol=0.02)),
            k.all_of(k.row(4), k.runs("x"), k.near(y=0.40, tol=0.02)),
        ),
    ),
    _c(
        "seq-15",
        SEQ,
        "Start a tower of 7. Correction from the supervisor: max 5 on this shift. Build it to 5.",
        one(T(5)),
    ),
    _c(
        "seq-16",
        SEQ,
        "Lay a 2 by 2 pallet one high, put another 2 by 2 on top of it, and finish with one "
        "cube on the very top.",
        one(k.on_top(T(1), k.block(2, 2, 2))),
    ),
    _c(
        "seq-17",
        SEQ,
        "put down 2 rows of 5 next to each other then another row of 5 on top in the middle",
        one(k.on_top(k.row(5), k.block(2, 5, 1))),
    ),
    _c(
        "seq-18",
        SEQ,
        "Erect a staircase of four steps rising away from me. When that is finished, remove "
        "the lowest step entirely.",
        one(k.xprofile(2, 3, 4)),
    ),
    _c(
        "seq-19",
        SEQ,
        "A = tower(h=3) @ (0.35, 0.20); B = tower(h=3) @ (0.35, 0.40); then A.h += 2",
        k.structures(
            k.all_of(T(5), k.near(0.35, 0.20, 0.02)), k.all_of(T(3), k.near(0.35, 0.40, 0.02))
        ),
    ),
    _c(
        "seq-20",
        SEQ,
        "make 2 towers of 2 then put 1 on top of the other so its just 1 tower",
        one(T(4)),
    ),
    _c(
        "seq-21",
        SEQ,
        "Two stacks, 2 high and 6 high. Then take 2 off the tall one and put them on the short "
        "one.",
        k.each(2, T(4)),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "Single stack, eight high, nothing fancy.", one(T(8))),
    _c("num-02", NUM, "make like 3 towers of 4 plz", k.each(3, T(4))),
    _c("num-03", NUM, "A column of precisely nine cubes, if you would be so kind.", one(T(9))),
    _c("num-04", NUM, "tower(h=2*3)", one(T(6))),
    _c(
        "num-05",
        NUM,
        "Two towers, one of 5 and one of 3. Five is the most we allow on this bench.",
        k.structures(T(5), T(3)),
    ),
    _c(
        "num-06",
        NUM,
        "One pallet of 12 cubes laid 4 by 3, one high, and next to it a second pallet half "
        "that size.",
        k.any_of(
            k.pair(k.block(4, 3, 1), k.block(2, 3, 1), _near),
            one(k.parts(18), k.height(1), k.on_table),
        ),
    ),
    _c("num-07", NUM, "tower thats 2 less than 10", one(T(8))),
    _c(
        "num-08",
        NUM,
        "Four columns, of heights two, four, six and eight cubes respectively, standing in a "
        "line from left to right.",
        k.any_of(k.in_order("y", T(2), T(4), T(6), T(8)), one(k.lr_profile(2, 4, 6, 8))),
    ),
    _c("num-09", NUM, "n_towers=5, h=2 each, spacing 0.10 m c-c", k.in_line(5, T(2), 1)),
    _c(
        "num-10",
        NUM,
        "Three stacks of 4 and not one more. Three is the limit for this area.",
        k.each(3, T(4)),
    ),
    _c("num-11", NUM, "Give me a staircase, 7 steps.", one(k.staircase(7))),
    _c("num-12", NUM, "pyramid w like 4 levels", one(k.pyramid(4))),
    _c(
        "num-13",
        NUM,
        "A wall whose length is one and a half times its height, the height being four cubes.",
        one(k.wall(6, 4)),
    ),
    _c(
        "num-14",
        NUM,
        "towers h ∈ {1, 2, 3, 4}, separate, collinear",
        k.all_of(k.structures(T(1), T(2), T(3), T(4)), _collinear),
    ),
    _c(
        "num-15",
        NUM,
        "No more than a dozen cubes in total for this one: a 3 by 4 slab, single layer.",
        one(k.block(3, 4, 1)),
    ),
    _c(
        "num-16",
        NUM,
        "Two lanes of stacks, 3 stacks per lane, every stack 2 high.",
        k.all_of(k.each(6, T(2)), _lanes(2, 3)),
    ),
    _c(
        "num-17",
        NUM,
        "ok so 4 towers going 1 then 2 then 3 then 4 high like stairs but not touching",
        _either_way(T(1), T(2), T(3), T(4)),
    ),
    _c(
        "num-18",
        NUM,
        "Three columns: the first of three cubes, the second twice as tall as the first, and "
        "the third one cube shorter than the second.",
        k.structures(T(3), T(6), T(5)),
    ),
    _c(
        "num-19",
        NUM,
        "block(3,3,3) minus centre column",
        one(k.ring_of(high=3, inner=(1, 1)), k.dims(3, 3)),
    ),
    _c("num-20", NUM, "I need ten cubes in one straight line on the table.", one(k.row(10))),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "A wall 300 mm long and 150 mm high, please, a single cube in thickness.",
        one(k.wall(6, 3)),
    ),
    _c("dim-02", DIM, "slab 0.25 × 0.10 m, single layer", one(k.block(5, 2, 1))),
    _c("dim-03", DIM, "Pallet 4 cubes deep and 5 wide, two layers.", one(k.block_xy(4, 5, 2))),
    _c("dim-04", DIM, "can u make a block 3 wide 3 long n 2 tall", one(k.block(3, 3, 2))),
    _c("dim-05", DIM, "A tower 25 cm tall. Not a centimetre higher.", one(T(5))),
    _c(
        "dim-06",
        DIM,
        "A cuboid measuring 100 by 150 mm in plan and 100 mm in height.",
        one(k.block(2, 3, 2)),
    ),
    _c("dim-07", DIM, "box(dx=3, dy=2, dz=4) in cube units", one(k.block_xy(3, 2, 4))),
    _c(
        "dim-08",
        DIM,
        "Fence in a bay 6 cubes by 4 on the outside, walls 2 high.",
        one(k.ring_of(high=2, inner=(4, 2)), k.dims(4, 6)),
    ),
    _c("dim-09", DIM, "a bridge w legs like 10cm tall", one(GATE(2, pillars=2))),
    _c(
        "dim-10",
        DIM,
        "A staircase of four steps, each step being 100 mm wide.",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c(
        "dim-11",
        DIM,
        "L-shape, arms 0.25 m and 0.15 m, h=1",
        one(k.shape_letter("L"), k.dims(3, 5), k.height(1)),
    ),
    _c(
        "dim-12",
        DIM,
        "Pad size 20 by 20 cm, one layer, and that is the maximum footprint allowed here.",
        one(k.block(4, 4, 1)),
    ),
    _c(
        "dim-13",
        DIM,
        "Row of cubes 40 cm long, running down the aisle away from the robot.",
        one(k.row(8), k.runs("x")),
    ),
    _c(
        "dim-14",
        DIM,
        "A table, if you please: four legs each 150 mm high supporting a top.",
        one(k.canopy(4, 3, 3)),
    ),
    _c(
        "dim-15",
        DIM,
        "ring(outer=5x5, h=2)",
        one(k.ring_of(high=2, inner=(3, 3)), k.dims(5, 5)),
    ),
    _c("dim-16", DIM, "make a wall thats 8 long n like 3 high", one(k.wall(8, 3))),
    _c(
        "dim-17",
        DIM,
        "The block is to be 3 by 2 by 2 cubes, and nothing bigger than that in any direction.",
        one(k.any_of(k.block(3, 2, 2), k.block(2, 2, 3))),
    ),
    _c(
        "dim-18",
        DIM,
        "A pyramid whose base is 250 mm square.",
        one(k.pyramid(), k.base(5, 5)),
    ),
    _c(
        "dim-19",
        DIM,
        "wall: L=0.30, H=0.20, along x",
        one(k.wall(6, 4), k.runs("x")),
    ),
    _c(
        "dim-20",
        DIM,
        "Two pallets, 3 by 3, one layer each, 10 cm apart.",
        k.pair(k.block(3, 3, 1), k.block(3, 3, 1), k.gap_of(2)),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "Tower of 4. Do not put it anywhere near the front edge; keep it in the back half.",
        one(T(4), reg("back")),
    ),
    _c(
        "neg-02",
        NEG,
        "A wall 5 long, and do not stack above 3.",
        one(k.any_of(k.wall(5, 2), k.wall(5, 3))),
    ),
    _c("neg-03", NEG, "make a 3x3 thing but no 2nd layer just flat", one(k.block(3, 3, 1))),
    _c(
        "neg-04",
        NEG,
        "Two columns of three cubes, not joined at the top in any way, 100 mm apart.",
        k.pair(T(3), T(3), k.gaps(1, 2)),
    ),
    _c(
        "neg-05",
        NEG,
        "grid 4x4, h=1, no corners",
        one(k.plan_heights(".11.", "1111", "1111", ".11.")),
    ),
    _c("neg-06", NEG, "Stack 5 high, not on the right side. Left lane.", one(T(5), reg("left"))),
    _c(
        "neg-07",
        NEG,
        "A ring 4 by 4, one high. Nothing inside it and nothing outside it either.",
        one(RING4),
    ),
    _c("neg-08", NEG, "make a tower of 4 n dont put anything on top of it", one(T(4))),
    _c(
        "neg-09",
        NEG,
        "A staircase of five steps, though not rising towards the robot; I want it to climb "
        "towards my left.",
        one(k.staircase(5), k.rises(_L)),
    ),
    _c(
        "neg-10",
        NEG,
        "tower(h=5) @ (0.50, 0.30), no other objects in the cell",
        one(T(5), k.near(0.50, 0.30)),
    ),
    _c(
        "neg-11",
        NEG,
        "Two towers of 3. They must not touch each other and must not be more than 15 cm apart.",
        k.pair(T(3), T(3), k.near_rel(0.165)),
    ),
    _c(
        "neg-12",
        NEG,
        "Lay a 4 by 2 pallet, no second layer, and keep it out of the middle of the table.",
        one(k.block(4, 2, 1), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-13",
        NEG,
        "wall 5 long 2 high but leave out the middle cube on the top row",
        one(k.profile(2, 2, 1, 2, 2), k.flat),
    ),
    _c(
        "neg-14",
        NEG,
        "A column of six cubes, on no account to be placed on the left half of the table.",
        one(T(6), _centre_y(0.305)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "cna u biuld a towr of 5", one(T(5))),
    _c("typo-02", TYP, "Stakc 3 hihg in the rigth lane", one(T(3), reg("right"))),
    _c(
        "typo-03",
        TYP,
        "A wall of sevn cubes in lenght and two in heigth, if you wuold.",
        one(k.wall(7, 2)),
    ),
    _c("typo-04", TYP, "pyarmid(levels=3)", one(k.pyramid(3))),
    _c(
        "typo-05",
        TYP,
        "Tower of 4, keep it clera of the frnot edge.",
        one(T(4), k.min_x(0.245)),
    ),
    _c(
        "typo-06",
        TYP,
        "Two palets 2 by 2 wiht an isle between",
        k.pair(k.solid(2, 2), k.solid(2, 2), _near),
    ),
    _c("typo-07", TYP, "brige w 2 towrs of 3", one(GATE(3, pillars=2))),
    _c(
        "typo-08",
        TYP,
        "A staricase of five setps rising away from me.",
        one(k.staircase(5), k.rises(_B)),
    ),
    _c("typo-09", TYP, "twoer(h=7) @ (0.40, 0.30)", one(T(7), k.near(0.40, 0.30))),
    _c(
        "typo-10",
        TYP,
        "Build a 3x3 slab, one layer, and dont go ovr 1 cube hight.",
        one(k.block(3, 3, 1)),
    ),
    _c("typo-11", TYP, "Put a 5 by 5 fense one high aroudn a stak of 2.", k.around(T(2), RING5)),
    _c("typo-12", TYP, "plz make a cassle", one(k.castle)),
    _c(
        "typo-13",
        TYP,
        "A colum of four cubes with a second colum of four behind it, 50 mm betwen them.",
        k.pair(T(4), T(4), k.gap_of(1, _B)),
    ),
    _c("typo-14", TYP, "wal(len=4, h=3)", one(k.wall(4, 3))),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "High as 6, that stack, and in the back lane.", one(T(6), reg("back"))),
    _c(
        "wo-02",
        WO,
        "on top of the block put a tower of 2 the block is 2x2",
        one(k.on_top(T(2), k.solid(2, 2))),
    ),
    _c(
        "wo-03",
        WO,
        "Of cubes, five; of layers, one; in a line running left to right: that is the row I "
        "require.",
        one(k.row(5), k.runs("y")),
    ),
    _c("wo-04", WO, "@ (0.60, 0.20): tower, h=3", one(T(3), k.near(0.60, 0.20))),
    _c("wo-05", WO, "Three high, no more, the tower by the right edge.", one(T(3), reg("right"))),
    _c(
        "wo-06",
        WO,
        "To the left of the 3 by 3 pallet, a stack of 4, one cube gap.",
        k.pair(T(4), k.block(3, 3, 1), k.gap_of(1, _L)),
    ),
    _c("wo-07", WO, "3 steps the stairs should have ok", one(k.staircase(3))),
    _c(
        "wo-08",
        WO,
        "Behind the wall, which is to be four cubes long and two high, a column of three "
        "cubes, standing 50 mm clear of it.",
        k.pair(T(3), k.wall(4, 2), k.gap_of(1, _B)),
    ),
    _c("wo-09", WO, "h=4, base 2x2, block", one(k.block(2, 2, 4))),
    _c(
        "wo-10",
        WO,
        "A bridge, two pillars of 3, beam on top, the whole thing in the middle of the bench.",
        one(GATE(3, pillars=2), reg("centre")),
    ),
    _c("wo-11", WO, "Five long, three high, that's the wall.", one(k.wall(5, 3))),
    _c(
        "wo-12",
        WO,
        "next to the pyramid a tower of 5 pls, pyramid 3 levels",
        k.any_of(
            k.pair(T(5), k.pyramid(3), _near),
            one(k.with_column(5, k.pyramid(3))),
        ),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Alright, morning all. Before the forklift lads get back I just need one stack of 4 on "
        "the table, that's it, cheers.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "omg ok so like my teacher said i should try this lol can u make a wall 4 long 2 high thx",
        one(k.wall(4, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Good afternoon. I trust this finds the cell in good order. I should be grateful if you "
        "would construct a pyramid of three levels. With thanks in advance, R. Hargreaves "
        "(retd.)",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-04",
        FIL,
        "quick sanity check before the real run: tower(h=3), default pose, nothing else. ty",
        one(T(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Reminder to all staff: hard hats in the cell area. Today's build: a 2 by 4 slab, one "
        "layer. Thank you for working safely.",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "fil-06",
        FIL,
        "Okay team, we're a bit behind so let's keep it simple, a row of 6 cubes, that's the "
        "whole order.",
        one(k.row(6)),
    ),
    _c("fil-07", FIL, "heyyy so im bored lol make a bridge idc how big", one(k.bridge())),
    _c(
        "fil-08",
        FIL,
        "If it is not too much trouble, and with the understanding that I am rather new to "
        "these machines, a staircase of three steps would suit me admirably.",
        one(k.staircase(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "fyi the camera is recalibrated now so we should be good. anyway: ring 4x4 h=1 please",
        one(RING4),
    ),
    _c(
        "fil-10",
        FIL,
        "Per the site induction, all builds stay under half a metre. For today: one tower, six "
        "cubes.",
        one(T(6)),
    ),
    _c(
        "fil-11",
        FIL,
        "Right, listen up, this one's for the trade show display: two stacks of 5 with a beam "
        "across the top, and make it look tidy.",
        one(GATE(5, pillars=2)),
    ),
    _c(
        "fil-12",
        FIL,
        "brb dinner but can u do a 3x3 square w a hole in the middle ty",
        one(k.ring_of(high=1, inner=(1, 1)), k.dims(3, 3)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "Stack of 3 in the back-left bay.", one(T(3), reg("back left"))),
    _c("reg-02", REG, "tower(h=4) @ (0.30, 0.45)", one(T(4), k.near(0.30, 0.45))),
    _c(
        "reg-03",
        REG,
        "A 2 by 2 slab, one layer, at the front right.",
        one(k.block(2, 2, 1), reg("front right")),
    ),
    _c(
        "reg-04",
        REG,
        "put a tower of 5 in the back corner on the right",
        one(T(5), reg("back right")),
    ),
    _c(
        "reg-05",
        REG,
        "A wall four cubes long and two high, positioned centrally on the work surface.",
        one(k.wall(4, 2), reg("centre")),
    ),
    _c(
        "reg-06",
        REG,
        "Row of 5, front lane, running left to right.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "reg-07", REG, "pyramid(3) centred at x=0.55, y=0.25", one(k.pyramid(3), k.near(0.55, 0.25))
    ),
    _c(
        "reg-08",
        REG,
        "Keep everything in the left half of the table: a tower of 4 and a tower of 2, not "
        "touching.",
        k.structures(k.all_of(T(4), _min_y(0.295)), k.all_of(T(2), _min_y(0.295))),
    ),
    _c("reg-09", REG, "tower of 3 all the way at the back", one(T(3), _centre_x(0.60))),
    _c(
        "reg-10",
        REG,
        "A slab of three by three cubes, one thick, its centre 350 mm out from the robot and "
        "100 mm to the right of the centre line.",
        one(k.block(3, 3, 1), k.near(0.35, 0.20)),
    ),
    _c(
        "reg-11",
        REG,
        "Pallet 3 by 2, one high, far right of the table, front half.",
        one(k.block(3, 2, 1), reg("front right")),
    ),
    _c(
        "reg-12",
        REG,
        "row(n=5) along x, at y=0.10",
        one(k.row(5), k.runs("x"), k.near(y=0.10)),
    ),
    _c(
        "reg-13",
        REG,
        "Tower of 6 dead centre, and nothing within 10 cm of the robot-side edge.",
        one(T(6), reg("centre"), k.min_x(0.295)),
    ),
    _c(
        "reg-14",
        REG,
        "can u put a lil pyramid on the left side",
        one(k.pyramid(lo=2, hi=4), reg("left")),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Build whatever you can get the most cubes into without going over 3 high.",
        k.all_of(k.anything, k.layout(k.low(3))),
    ),
    _c("open-02", OPEN, "make something cool idc what", k.anything),
    _c(
        "open-03",
        OPEN,
        "I leave the design entirely to you, save that it should include at least one span "
        "resting on two supports.",
        k.all_of(k.anything, k.layout(k.arch)),
    ),
    _c(
        "open-04",
        OPEN,
        "random structure, ≤ 10 parts, h ≤ 3",
        k.all_of(k.anything, k.layout(k.all_of(k.parts(hi=10), k.low(3)))),
    ),
    _c(
        "open-05",
        OPEN,
        "Any structure you like, provided it is no taller than 20 cm and stays out of the front "
        "quarter of the table.",
        k.all_of(k.anything, k.layout(k.all_of(k.low(4), k.min_x(0.345)))),
    ),
    _c(
        "open-06",
        OPEN,
        "Put together a couple of stacks, whatever heights you think.",
        k.few(2, 3, T(lo=1, hi=10)),
    ),
    _c("open-07", OPEN, "build a tower idk how tall u pick", one(T(lo=2, hi=10))),
    _c("open-08", OPEN, "any enclosure, any size, h=1", one(k.ring, k.height(1))),
    _c(
        "open-09",
        OPEN,
        "Something simple for the visitors, your choice, but one structure only and under 4 "
        "cubes high.",
        k.structures(k.all_of(k.on_table, k.low(3))),
    ),
    _c(
        "open-10",
        OPEN,
        "A staircase, of whatever number of steps you consider sensible.",
        one(k.staircase(lo=2, hi=10)),
    ),
    _c(
        "open-11",
        OPEN,
        "make me smth w a bridge in it",
        k.all_of(k.anything, k.layout(k.arch)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "asdfgh lol", k.honest()),
    _c("bad-02", BAD, "Stack 14 high.", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-03",
        BAD,
        "Tower of 5, but nothing on this bench is to be taller than 3.",
        k.honest(one(k.any_of(T(5), T(lo=1, hi=3)))),
    ),
    _c(
        "bad-04",
        BAD,
        "Je voudrais une tour de quatre cubes, s'il vous plaît.",
        k.honest(one(T(4))),
    ),
    _c("bad-05", BAD, "tower(h=-3)", k.honest()),
    _c(
        "bad-06",
        BAD,
        "Build a wall 3 metres long.",
        k.honest(one(k.any_of(k.wall(lo=2, hi=12), k.row(lo=2, hi=12)))),
    ),
    _c("bad-07", BAD, "ok now make it way bigger lol", k.honest(k.anything)),
    _c("bad-08", BAD, "Same as yesterday.", k.honest()),
    _c(
        "bad-09",
        BAD,
        "A pyramid of three levels whose top level is larger than its base.",
        k.honest(one(k.pyramid(3))),
    ),
    _c("bad-10", BAD, "ring(outer=3x3, inner=4x4)", k.honest(one(k.ring))),
    _c("bad-11", BAD, "Place a tower of 4 at x = 1.2 m.", k.honest(one(T(4)))),
    _c("bad-12", BAD, "💀💀💀 bruh", k.honest()),
    _c(
        "bad-13",
        BAD,
        "Construct, if you would, a solid cube one metre on a side.",
        k.honest(one(k.full)),
    ),
    _c("bad-14", BAD, "Stack 4 high on the mezzanine.", k.honest(one(T(4)))),
    _c("bad-15", BAD, "tower(h=3) @ (0.50, 0.30, 0.70)", k.honest(one(T(3)))),
]
