"""A thirty-fourth held-out set for the language front end (dev34): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set (but dev27, the format example) or any benchmark
result, and worded apart from `language_dev` … `language_dev33` (no command shared with any
set, see tests). Nothing here was run through the system while it was written. The set is
deliberately mainstream: about 80 % of the commands are ordinary — one or two structures with
a size, a place, one relation or a two-step sequence, in plain but varied English — and they
come from five kinds of people, none of them used by an earlier set.

The brief for this set asked for a maintenance technician's work order, a primary-school
teacher, a voice-assistant transcript, an operator who refers to earlier builds and to the
robot, and an engineer who gives every measure in mm or cm. Four of those had been used
already (the work order by dev13 and dev23, with maintenance technicians in dev3, dev8 and
dev14; teachers by dev5, dev9, dev13 and dev23; voice transcripts by dev9, dev13, dev15,
dev20, dev24 and dev32; engineers in mm by dev13, dev16, dev20, dev27 and dev30), so each is
replaced by a fresh voice that keeps what it was meant to test — shorthand, picture words,
unpunctuated lower case with restarts, and mixed metric units. The fourth voice is kept: no
earlier set had it as a voice (single phrases such as dev14's "the usual pyramid", dev17's
"same again" and dev20's "the one from last night" belonged to other voices).

* a land surveyor who writes the job as field-book shorthand (in place of the work order):
  "ht" (height, in cubes unless a unit is given), "qty N" (N separate structures), "L" / "R"
  (left / right), "@" (at), "w/" (with), "approx" (the figure stands), "o/a" (overall),
  "c/l" (the centre line, y = 0.30 ± 3 cm), "c/c" (centre to centre), "clr" (clear gap, in
  cubes unless a unit is given), "blk" (cube), "lyr" / "lvl" (layer / level), "ea" (each),
  "ctr" (centre), "twr" (tower), "stair" (staircase), "twd" (towards), "rmv" (remove),
  "cnr" (corner), "NL x MH" (N long, M high), "row xN" (a row N cubes long), "amend:"
  (replaces what it amends); numbered steps "1) … 2) …" are done in order. Station, point,
  page and drawing numbers, the weather and the crew count are filler. A field-book line
  that is no build (re-checking the instrument) admits only the refusal;
* a scout leader showing a troop round the cell (in place of the primary-school teacher),
  in camp words: a lookout, lookout tower, flagpole or totem pole is a tower (one column); a
  camp gateway is two posts with a crossbar across the tops (a beam where a beam is named, a
  beam or a bar of cubes where it is not); a bench is two legs with a seat across them, in
  the same way; a fire ring is a ring, of any height unless one is said; a log is a row one
  cube high and a log wall a wall; stepping stones are separate single cubes in one line,
  any spacing unless one is said; a tent pitch is a one-layer slab; "steps to climb" are a
  staircase. The Cubs, Beavers, patrols and troops are people (a number of them is never a
  size). A real campfire, a canvas tent and a tower as tall as a tree are bad input;
* a museum volunteer in their seventies who types with one finger (in place of the
  voice-assistant transcript): all lower case, no punctuation, numbers as words, a phrase
  typed twice when they lose their place ("at the at the back", read once), letters
  doubled, dropped or swapped ("towwer", "wal", "tow high"), "no wait" replacing what it
  corrects, and courtesy to the robot (filler). A phrase that stops short, a row of one
  key, two heights for one tower and a request to build nothing today are bad input (the
  last admits only the refusal);
* an operator who refers to earlier builds and to the robot: "the usual", "same as
  always", "like last time", "from this morning", "the one we always do" add nothing when
  the command itself gives every figure that is checked; a reference inside the message
  ("the first one", "that one", "another like it", "the one in the middle") is to a
  structure the same message names. "Close in", "near the robot" and "where the robot can
  reach it easily" are the front region; "right in front of the robot" is the front region
  on the centre line (y = 0.30 ± 3 cm); "the robot's left / right" are the left / right
  regions; "well away from the robot" is outside the front region; "as far from the robot as
  the table goes" puts every part at x ≥ 0.60; "the far side of it, away from the robot" is
  behind it (+x); "the side facing the robot" is its front side. Where the meaning hangs on
  an earlier build the message does not describe ("same as before but 5 high", "the usual",
  an "it" that names nothing, a tower on "the one from this morning"), the command is bad
  input;
* an interior designer who gives every measure in millimetres or centimetres, sometimes both
  in one breath (in place of the engineer): "a wall 200 mm long, 10 cm high" is 4 long and
  2 high; a column is a tower one cube across unless a plan size is given ("10 by 10 cm in
  plan" is 2 × 2); "N thick" for a slab is its layers; "at 400, 200 mm" is the footprint
  centre in the cell frame (x away from the robot, y to its left), held to 2 cm; "its
  centre N from the back edge" is the footprint centre that far from the workspace's edge
  (± 2 cm). "N apart" between two structures accepts the clear gap and, where buildable as
  separate structures, the centre-to-centre reading; "N clear" and "N between them" are the
  clear gap only; "centre to centre" is that only. A size that is not a whole number of
  cubes, a wall longer than the cell and a cylinder are bad input.

About 80 % ordinary and 20 % harder: three structures, references ("the first one", "that
beam", "the one in the middle", "the left end"), distributive phrases ("one on each end",
"a cube's gap between each"), comparisons ("half as tall as that one", "three shorter", "one
taller than the one before"), removals ("take the first one down", "rmv 1 blk ea end",
"take away the middle one"), corrections in the same message and unusable input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else:

* "next to", "beside" with nothing said about touching is clear of it and no more than 25 cm
  away; "right next to it" is at most 10 cm clear, or set against it so that the two are
  one structure (checked by its column heights); "not touching", "a gap", "a bit of space",
  "apart" mean separate structures;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y), any distance when none
  is said, the two kept separate; where nothing rules touching out, a tower to one side of
  another tower, or behind a slab, may also be set against it as one structure (checked by
  the column and the side it stands on); "not one behind the other" is side by side (left
  or right);
* "on top of the middle one" of a row stands on its middle cube; "a cube on each end" of a
  wall stands on its end columns; a column "on each end" of a row stands on its end cubes;
  "on top of" a slab "centred" is centred over it (± 3 cm); a cube "on that beam, in the
  middle" is centred over the bridge (± 3 cm);
* a bridge's or gateway's top is a beam (the shared `bridge`, overall height one more than
  the posts) where the command names a beam, and a beam or a bar of cubes where it does not;
  "just cubes across the top" is a bar of cubes only;
* a ring's stated size is its outside; "in the middle of" a ring is inside its empty
  interior, clear of the ring, with the centres within 3 cm;
* a staircase's width is free unless given, and so is the way it climbs unless said; a
  staircase "N cm high" has one step per cube of height; a pyramid's step is free unless
  given, so "three levels, then take the top cube off" is any two-level pyramid with more
  than one part on top; "a pyramid on a 250 mm square base, 15 cm tall" is three levels on
  a full 5 × 5 base;
* a slab is a full block of the stated footprint, one layer unless a thickness is given;
  "the stepping stones, then take away the middle one" leaves the outer stones evenly spaced
  and the middle gap one stone and two gaps wide; "qty 4 twrs ht 1 in a square, 1 clr" is
  four single cubes on the corners of a square whose sides run along x and y, one cube clear;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "along the right-hand edge" is a footprint centre at y ≤ 0.15; "no part closer than 40 cm
  to the robot" measures, in plan, from the robot's base at (0, 0.30) to the nearest point
  of every part; a stated coordinate is the footprint centre ± 2 cm.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`); a request that is not a build at all, or that asks for nothing to be
built, admits only the refusal. Geometry comes only from `sdi.bench.boxes`, through the
shared checks in `language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 × 0.05 × 0.05 m; left = +y, back = +x
(away from the robot at x = 0, y = 0.30); the front is the robot's side (small x).
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

_ROBOT = (0.0, 0.30)  # the robot's base in plan, m


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev34-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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
    """A gateway or bench with no beam named: two posts `posts` high with a beam (one layer
    above the posts) or a bar of cubes across the tops."""
    return k.any_of(_beam_bridge(posts), _bar_on_posts(posts, posts))


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


def _flat_topped_pyramid(bs: k.Boxes) -> k.Reason:
    """A pyramid whose top level is more than one part (its top cube taken off)."""
    p = bx.pyramid_levels(bs)
    if p is None:
        return "not a pyramid"
    return None if p[-1] > 1 else "a single cube on top"


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


def _stones(n: int) -> k.Pred:
    """Stepping stones: exactly n separate single cubes in one line along x or y, any
    spacing."""
    return k.any_of(*[k.in_order(axis, *[k.tower(1)] * n) for axis in ("x", "y")])


def _stones_less_middle(n: int) -> k.Pred:
    """What is left of n + 1 evenly spaced stepping stones in a line left to right when the
    middle one is taken away (n even): n separate single cubes in a line along y, the outer
    gaps all equal (± 1.5 cm) and the middle gap one cube plus two of them (± 1.5 cm)."""
    line = k.in_order("y", *[k.tower(1)] * n)

    def f(result: Mapping[str, Any]) -> k.Reason:
        r = line(result)
        if r:
            return r
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        comps = sorted(comps, key=lambda g: -bx.centre(g)[1])
        gaps = [bx.separation(a, b) for a, b in itertools.pairwise(comps)]
        mid = len(gaps) // 2
        outer = gaps[:mid] + gaps[mid + 1 :]
        if max(outer) - min(outer) > 0.015:
            return "the stones left are not evenly spaced"
        want = 2 * outer[0] + bx.CUBE
        if abs(gaps[mid] - want) > 0.015:
            return f"middle gap {gaps[mid]:.3f} m, want {want:.3f} (a stone taken out)"
        return None

    return f


def _square_of_singles(gap: int) -> k.Pred:
    """Four separate single cubes on the corners of a square whose sides run along x and y,
    neighbours `gap` cubes clear (± 1.5 cm)."""
    side = (gap + 1) * bx.CUBE

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) != 4:
            return f"{len(comps)} separate structures, want 4"
        for g in comps:
            r = k.tower(1)(g)
            if r:
                return r
        pts = sorted(bx.centre(g) for g in comps)
        near_, far_ = sorted(pts[:2], key=lambda p: p[1]), sorted(pts[2:], key=lambda p: p[1])
        ok = (
            abs(near_[0][0] - near_[1][0]) <= 0.01
            and abs(far_[0][0] - far_[1][0]) <= 0.01
            and abs(near_[0][1] - far_[0][1]) <= 0.01
            and abs(near_[1][1] - far_[1][1]) <= 0.01
            and abs(far_[0][0] - near_[0][0] - side) <= 0.015
            and abs(near_[1][1] - near_[0][1] - side) <= 0.015
        )
        return None if ok else f"not on the corners of a square {gap} cube(s) clear"

    return f


def _far_from_robot(d: float) -> k.Check:
    """No part's nearest point (in plan) closer than `d` m to the robot's base."""

    def f(bs: k.Boxes) -> k.Reason:
        for b in bs:
            dx = max(b.lo[0] - _ROBOT[0], _ROBOT[0] - b.hi[0], 0.0)
            dy = max(b.lo[1] - _ROBOT[1], _ROBOT[1] - b.hi[1], 0.0)
            dist = math.hypot(dx, dy)
            if dist < d - bx.TOL:
                return f"a part {dist:.3f} m from the robot, want ≥ {d}"
        return None

    return f


def _centre_y_max(hi: float) -> k.Check:
    """The footprint centre at y ≤ `hi` (m): over to the right."""

    def f(bs: k.Boxes) -> k.Reason:
        y = bx.centre(bs)[1]
        return None if y <= hi else f"centre y {y:.3f}, want ≤ {hi}"

    return f


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_FIRE5 = k.all_of(k.ring_of(None, (3, 3)), k.dims(5, 5))  # a fire ring: any height
_ANY_TOWER = T(lo=1, hi=10)


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "stn 2: twr ht 4 @ front L, 2nd twr ht 2 beside it, 1 clr",
        k.pair(k.all_of(T(4), reg("front left")), T(2), k.gap_of(1)),
    ),
    _c(
        "rel-02",
        REL,
        "Can the robot make us a camp gateway? Two posts, three cubes tall, and a crossbar on "
        "top for the Cubs to walk under.",
        one(_span(3)),
    ),
    _c(
        "rel-03",
        REL,
        "a row of five cubes and a tower of three on top of the middle one please",
        one(k.profile(1, 1, 4, 1, 1)),
    ),
    _c(
        "rel-04",
        REL,
        "Tower of four at the front left. Then the same again straight behind it, two cubes apart.",
        k.pair(T(4), k.all_of(T(4), reg("front left")), k.gap_of(2, _B)),
    ),
    _c(
        "rel-05",
        REL,
        "A wall 250 mm long and 10 cm high, with a 15 cm column in front of it, 50 mm clear.",
        k.pair(T(3), k.wall(5, 2), k.gap_of(1, _F)),
    ),
    _c(
        "rel-06",
        REL,
        "A fire ring five cubes across, with a flagpole two cubes high standing in the middle "
        "of it.",
        k.pair(_FIRE5, T(2), k.centred_in(0.03)),
    ),
    _c("rel-07", REL, "req: 2 twrs ht 3, 1 clr, beam across top", one(_beam_bridge(3, 1))),
    _c(
        "rel-08",
        REL,
        "please put a tower of four to the left of a tower of two with a gap in between",
        k.pair(T(4), T(2), k.on_side(_L)),
    ),
    _c(
        "rel-09",
        REL,
        "Put a 3x3 slab close in to the robot, and a tower of 5 on the far side of it, away "
        "from the robot.",
        k.any_of(
            k.pair(T(5), k.all_of(k.block(3, 3, 1), reg("front")), k.on_side(_B)),
            one(_col_beside(5, k.all_of(k.block(3, 3, 1), reg("front")), _B)),
        ),
    ),
    _c(
        "rel-10",
        REL,
        "Two walls, each 300 mm long and 100 mm high, parallel, with 10 cm between them.",
        k.pair(k.wall(6, 2), k.wall(6, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-11",
        REL,
        "Build a bench for round the campfire: two legs one cube high and a beam on top for "
        "the seat.",
        one(_beam_bridge(1)),
    ),
    _c(
        "rel-12",
        REL,
        "a ring five by five one high and a tower of three in the middle of it",
        k.pair(_PEN5, T(3), k.centred_in(0.03)),
    ),
    _c(
        "rel-13",
        REL,
        "pyramid 3 lvl @ ctr, twr ht 5 R of it",
        k.pair(T(5), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_R)),
    ),
    _c(
        "rel-14",
        REL,
        "Build a tower of six, then a tower half as tall as that one right next to it.",
        k.any_of(k.pair(T(3), T(6), k.within(0.10)), one(k.cell_heights(6, 3))),
    ),
    _c(
        "rel-15",
        REL,
        "Place a column 100 x 100 mm in plan and 20 cm high on top of a 20 x 20 cm slab one "
        "cube thick, centred.",
        one(
            k.on_top(T(4, base=2), k.block(4, 4, 1)),
            k.centred(),
            k.levels(16, 4, 4, 4, 4),
        ),
    ),
    _c(
        "rel-16",
        REL,
        "Three lookout towers in a line — four, six and four cubes tall, the tall one in the "
        "middle — with a cube's gap between each.",
        k.line(T(4), T(6), T(4), gaps=(1,)),
    ),
    _c("rel-17", REL, "wall 5L x 2H, 1 blk on ea end", one(k.profile(3, 2, 2, 2, 3))),
    _c(
        "rel-18",
        REL,
        "Two towers of three a cube apart with a beam across them — then put a single cube on "
        "that beam, in the middle.",
        one(_topped(_beam_bridge(3, 1)), k.top_centred()),
    ),
    _c(
        "rel-19",
        REL,
        "please build a wall six long and three high and a row of six in front of it not touching",
        k.pair(k.row(6), k.wall(6, 3), k.on_side(_F)),
    ),
    _c(
        "rel-20",
        REL,
        "Two 200 mm towers, 300 mm apart centre to centre, and a 10 cm tower halfway between them.",
        k.line(T(4), T(2), T(4), gaps=(2,)),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "twr ht 6 @ back R. amend: ht 4", one(T(4), reg("back right"))),
    _c(
        "seq-02",
        SEQ,
        "First lay a log four cubes long, then lay a second log right on top of it.",
        one(k.wall(4, 2)),
    ),
    _c("seq-03", SEQ, "build a tower of seven then take off the top two thank you", one(T(5))),
    _c(
        "seq-04",
        SEQ,
        "Build the staircase we always do — three steps — then add a fourth step at the top end.",
        one(k.staircase(4)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Lay a 150 by 150 mm slab one cube thick, then a second layer, 10 by 10 cm, on top of "
        "it in one corner.",
        one(k.plan_heights("221", "221", "111")),
    ),
    _c(
        "seq-06",
        SEQ,
        "1) row x6 along front 2) rmv 1 blk ea end",
        one(k.row(4), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-07",
        SEQ,
        "Let's build a lookout tower of three — and then the scouts want it two cubes taller.",
        one(T(5)),
    ),
    _c(
        "seq-08",
        SEQ,
        "make a block two by two and two high and then put another two by two layer on top",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "seq-09",
        SEQ,
        "Build two towers of four a cube apart. Then take the first one down again.",
        one(T(4)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Build a wall 40 cm long and 15 cm high, then take 5 cm off the top.",
        one(k.wall(8, 2)),
    ),
    _c(
        "seq-11",
        SEQ,
        "twr ht 3 @ L, then same @ R",
        k.structures(k.all_of(T(3), reg("left")), k.all_of(T(3), reg("right"))),
    ),
    _c(
        "seq-12",
        SEQ,
        "First a fire ring, five cubes by five and one high; then build it up one more layer "
        "all the way round.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "seq-13",
        SEQ,
        "a row of four going left to right then a tower of three on top of the cube at the at "
        "the left end",
        one(k.lr_profile(4, 1, 1, 1)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Put up the pyramid from this morning again — three levels — then take the top cube off.",
        one(k.pyramid(2), _flat_topped_pyramid),
    ),
    _c(
        "seq-15",
        SEQ,
        "Put a 20 cm column at 400, 200 mm, then move it 100 mm to the left.",
        one(T(4), k.near(0.40, 0.30, 0.02)),
    ),
    _c(
        "seq-16",
        SEQ,
        "block 3x2 1 lyr @ ctr, then 2nd lyr same size on top",
        one(k.block(3, 2, 2), reg("centre")),
    ),
    _c(
        "seq-17",
        SEQ,
        "Make stepping stones across the front — five single cubes, evenly spaced with gaps "
        "between — then take away the middle one.",
        k.all_of(_stones_less_middle(4), k.layout(reg("front"))),
    ),
    _c(
        "seq-18",
        SEQ,
        "build a wall five long and two high no wait three high",
        one(k.wall(5, 3)),
    ),
    _c(
        "seq-19",
        SEQ,
        "Build a tower of five in the middle and another like it on the robot's right, then "
        "remove the one in the middle.",
        one(T(5), reg("right")),
    ),
    _c(
        "seq-20",
        SEQ,
        "Lay a 250 mm row, then stand a 15 cm column on each end of it.",
        one(k.profile(4, 1, 1, 1, 4)),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "qty 2 twrs ht 3, 2 clr between",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c("num-02", NUM, "A totem pole nine cubes tall, please.", one(T(9))),
    _c(
        "num-03",
        NUM,
        "three towers of two in a row with one cube between each",
        k.in_line(3, T(2), 1),
    ),
    _c(
        "num-04",
        NUM,
        "Four towers in a line, a cube apart: the first one a single cube, and each one after "
        "it one taller than the one before.",
        k.line(T(1), T(2), T(3), T(4), gaps=(1,)),
    ),
    _c(
        "num-05",
        NUM,
        "Four 100 mm columns in a row along the back, 50 mm apart.",
        k.all_of(k.in_order("y", *[T(2)] * 4, gaps=(1,)), k.layout(reg("back"))),
    ),
    _c("num-06", NUM, "slab 4x3 1 lyr", one(k.block(4, 3, 1))),
    _c(
        "num-07",
        NUM,
        "A flat patch of a dozen cubes for the tent pitch — three rows of four.",
        one(k.block(3, 4, 1)),
    ),
    _c("num-08", NUM, "could you make me a tower of ten cubes", one(T(10))),
    _c(
        "num-09",
        NUM,
        "The usual pair of towers: four high, three cubes between them.",
        k.pair(T(4), T(4), k.gap_of(3)),
    ),
    _c(
        "num-10",
        NUM,
        "Three columns, 50, 100 and 150 mm high, front to back, 100 mm between each.",
        k.in_order("x", T(1), T(2), T(3), gaps=(2,)),
    ),
    _c("num-11", NUM, "qty 4 twrs ht 1 in a square, 1 clr", _square_of_singles(1)),
    _c(
        "num-12",
        NUM,
        "Two flagpoles, one seven cubes tall and the other three shorter, with a bit of space "
        "between.",
        k.pair(T(7), T(4), k.within(0.25)),
    ),
    _c(
        "num-13",
        NUM,
        "a pyramid with a bottom of three by three and two levels",
        one(k.pyramid(2), k.base(3, 3)),
    ),
    _c(
        "num-14",
        NUM,
        "A staircase with one more step than the three-step one you usually do.",
        one(k.staircase(4)),
    ),
    _c(
        "num-15",
        NUM,
        "Two slabs, each 100 by 150 mm and one cube thick, 100 mm apart.",
        k.pair(k.block(2, 3, 1), k.block(2, 3, 1), k.gap_of(2)),
    ),
    _c("num-16", NUM, "wall 7L x 3H", one(k.wall(7, 3))),
    _c(
        "num-17",
        NUM,
        "A lookout as tall as the number of scouts in a patrol — that's six.",
        one(T(6)),
    ),
    _c(
        "num-18",
        NUM,
        "two rows of three cubes side by side one cube apart",
        k.pair(k.row(3), k.row(3), k.parallel_gap(1)),
    ),
    _c(
        "num-19",
        NUM,
        "Build three towers of two, three and four in a line, a cube apart; then make the "
        "shortest one as tall as the tallest.",
        k.any_of(
            k.line(T(4), T(3), T(4), gaps=(1,)),
            k.line(T(4), T(4), T(3), gaps=(1,)),
        ),
    ),
    _c(
        "num-20",
        NUM,
        "A ring 300 mm square on the outside and 5 cm high.",
        one(k.ring_of(1, (4, 4)), k.dims(6, 6)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "Wall 200 mm long, 15 cm high.", one(k.wall(4, 3))),
    _c(
        "dim-02",
        DIM,
        "Column 0.35 m tall at the back right.",
        one(T(7), reg("back right")),
    ),
    _c("dim-03", DIM, "twr ht 250mm @ front R", one(T(5), reg("front right"))),
    _c("dim-04", DIM, "slab 20x15cm 1 lyr", one(k.block(4, 3, 1))),
    _c(
        "dim-05",
        DIM,
        "A lookout tower thirty centimetres tall — about as tall as a school ruler.",
        one(T(6)),
    ),
    _c(
        "dim-06",
        DIM,
        "A camp gateway with posts 20 cm high and a beam across the top.",
        one(_beam_bridge(4)),
    ),
    _c(
        "dim-07",
        DIM,
        "a wall half a metre long ten centimetres tall thank you",
        one(k.wall(10, 2)),
    ),
    _c(
        "dim-08",
        DIM,
        "a tower twenty centimetres high at the at the back please",
        one(T(4), reg("back")),
    ),
    _c(
        "dim-09",
        DIM,
        "The staircase you always make for demos, but this time 20 cm high.",
        one(k.staircase(4)),
    ),
    _c(
        "dim-10",
        DIM,
        "A tower 15 cm tall, close in where the robot can reach it easily.",
        one(T(3), reg("front")),
    ),
    _c("dim-11", DIM, "Block 100 mm by 150 mm, 10 cm high.", one(k.block(2, 3, 2))),
    _c("dim-12", DIM, "A 25 cm by 10 cm slab, 50 mm thick.", one(k.block(5, 2, 1))),
    _c("dim-13", DIM, "row approx 30cm o/a @ front", one(k.row(6), reg("front"))),
    _c(
        "dim-14",
        DIM,
        "2 twrs ht 200mm, 100mm c/c",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "dim-15",
        DIM,
        "Steps for the scouts to climb, 15 centimetres high at the top.",
        one(k.staircase(3)),
    ),
    _c(
        "dim-16",
        DIM,
        "a ring twenty five centimetres across and five centimetres high",
        one(k.ring_of(1, (3, 3)), k.dims(5, 5)),
    ),
    _c("dim-17", DIM, "A column 400 mm tall and 10 by 10 cm in plan.", one(T(8, base=2))),
    _c(
        "dim-18",
        DIM,
        "A pyramid on a 250 mm square base, 15 cm tall.",
        one(k.pyramid(3), k.base(5, 5)),
    ),
    _c(
        "dim-19",
        DIM,
        "A bridge like the one from the last demo: legs 10 cm tall, 5 cm apart, beam on top.",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "dim-20",
        DIM,
        "A log fifty centimetres long along the back of the table.",
        one(k.row(10), k.runs("y"), reg("back")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "twr ht 5, NOT @ ctr",
        one(T(5), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-02",
        NEG,
        "A fire ring five by five, one high — and don't put anything inside it, that's where "
        "the fire goes.",
        one(_PEN5),
    ),
    _c(
        "neg-03",
        NEG,
        "a tower of four but not on the right side please",
        one(T(4), k.not_(reg("right"), "on the right")),
    ),
    _c(
        "neg-04",
        NEG,
        "Tower of six, and this time keep it well away from the robot.",
        one(T(6), k.not_(reg("front"), "near the robot")),
    ),
    _c(
        "neg-05",
        NEG,
        "A 200 mm wall, 100 mm high, not running left to right.",
        one(k.wall(4, 2), k.runs("x")),
    ),
    _c("neg-06", NEG, "pyramid 3 lvl, no beams", one(k.pyramid(3), k.only_cubes)),
    _c("neg-07", NEG, "Two flagpoles of four, and don't let them touch.", k.each(2, T(4))),
    _c(
        "neg-08",
        NEG,
        "a bridge with legs of two but no beam just cubes across the top",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "A tower of three, but not where we usually put it — anywhere except the front left.",
        one(T(3), k.not_(reg("front left"), "at the front left")),
    ),
    _c(
        "neg-10",
        NEG,
        "A 150 x 150 mm slab, one cube thick, nowhere near the front edge.",
        one(k.block(3, 3, 1), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-11",
        NEG,
        "stair 4 steps, NOT rising twd robot",
        one(k.staircase(4), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-12",
        NEG,
        "A log six cubes long that does not point towards the robot.",
        one(k.row(6), k.runs("y")),
    ),
    _c(
        "neg-13",
        NEG,
        "two towers of three not touching and not one behind the other",
        k.pair(T(3), T(3), k.on_side(_L)),
    ),
    _c(
        "neg-14",
        NEG,
        "Build the ring again, five by five and one high, but leave a one-cube gap in the side "
        "facing the robot.",
        one(
            k.dims(5, 5),
            k.height(1),
            k.parts(15),
            k.not_(k.ring, "closed"),
            _missing_on(_F),
        ),
    ),
    _c(
        "neg-15",
        NEG,
        "A 300 mm row, no part of it closer than 40 cm to the robot.",
        one(k.row(6), _far_from_robot(0.40)),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "a towwer of fiev cubes", one(T(5))),
    _c("typo-02", TYP, "a wal six long and tow high", one(k.wall(6, 2))),
    _c("typo-03", TYP, "twr ht 4 @ bck L", one(T(4), reg("back left"))),
    _c("typo-04", TYP, "pyrmd 3 lvl @ ctr", one(k.pyramid(3), reg("centre"))),
    _c("typo-05", TYP, "A lookuot tower of six for the Cubs, plaese.", one(T(6))),
    _c(
        "typo-06",
        TYP,
        "Make a camp gatway: two posts of two and a baem across the top.",
        one(_beam_bridge(2)),
    ),
    _c(
        "typo-07",
        TYP,
        "The usaul staircase, four stesp, climbing away from the robot.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "typo-08",
        TYP,
        "Same block as alwyas — 2 by 2, thre high — in the midle.",
        one(k.block(2, 2, 3), reg("centre")),
    ),
    _c(
        "typo-09",
        TYP,
        "Wal 250 mm long, 10 cm hihg, at the bakc.",
        one(k.wall(5, 2), reg("back")),
    ),
    _c("typo-10", TYP, "Slab 150 x 200 mm, one cueb thick", one(k.block(3, 4, 1))),
    _c(
        "typo-11",
        TYP,
        "two towres of three with a gpa of one cube",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c("typo-12", TYP, "a rnig four by four one high", one(_PEN4)),
    _c(
        "typo-13",
        TYP,
        "row x5 alnog frnt edge",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c("typo-14", TYP, "Stepping stoens: four singel cubes in a line with gaps.", _stones(4)),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "@ back R: twr, ht 3", one(T(3), reg("back right"))),
    _c("wo-02", WO, "150 mm high and 300 mm long, that's the wall.", one(k.wall(6, 3))),
    _c(
        "wo-03",
        WO,
        "Over by the left, for the scouts, a lookout of four.",
        one(T(4), reg("left")),
    ),
    _c(
        "wo-04",
        WO,
        "five cubes high a tower in the middle please",
        one(T(5), reg("centre")),
    ),
    _c(
        "wo-05",
        WO,
        "Where the robot can reach it easily, nice and close, put a 2 by 2 block two high.",
        one(k.block(2, 2, 2), reg("front")),
    ),
    _c(
        "wo-06",
        WO,
        "on top of slab 3x3: 1 blk, ctr",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "wo-07",
        WO,
        "At 500, 200 mm, a column 20 cm tall.",
        one(T(4), k.near(0.50, 0.20, 0.02)),
    ),
    _c(
        "wo-08",
        WO,
        "Four cubes long and two high, the log wall for the camp, along the back.",
        one(k.wall(4, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "wo-09",
        WO,
        "to the right of a tower of five a tower of two",
        k.any_of(k.pair(T(2), T(5), k.on_side(_R)), one(_col_beside(2, T(5), _R))),
    ),
    _c(
        "wo-10",
        WO,
        "Three high, the same tower as yesterday, at the front right.",
        one(T(3), reg("front right")),
    ),
    _c("wo-11", WO, "4 steps, rising L, stair", one(k.staircase(4), k.rises(_L))),
    _c(
        "wo-12",
        WO,
        "With 10 cm clear between them, two 250 mm towers.",
        k.pair(T(5), T(5), k.gap_of(2)),
    ),
    _c(
        "wo-13",
        WO,
        "In the middle of a fire ring of five by five, a flagpole of four, please.",
        k.pair(_FIRE5, T(4), k.centred_in(0.03)),
    ),
    # ------------------------------------------------------------------ filler
    _c("fil-01", FIL, "stn 14, pt ref 220: twr ht 3", one(T(3))),
    _c(
        "fil-02",
        FIL,
        "Right, Beavers, sit down please, the robot is going to build us something. Robot: a "
        "tower of four cubes.",
        one(T(4)),
    ),
    _c(
        "fil-03",
        FIL,
        "hello robot i hope you are well my grandson showed me how to type this a row of four "
        "cubes please thank you",
        one(k.row(4)),
    ),
    _c(
        "fil-04",
        FIL,
        "Morning. Like we did on Friday, but I've written it all out this time: a pyramid of "
        "three levels in the centre.",
        one(k.pyramid(3), reg("centre")),
    ),
    _c(
        "fil-05",
        FIL,
        "Client meeting at 10:30, so quickly: a slab 200 x 100 mm, one layer, on the left.",
        one(k.block(4, 2, 1), reg("left")),
    ),
    _c(
        "fil-06",
        FIL,
        "weather fine, 3 on site, level checked. req: wall 6L x 2H",
        one(k.wall(6, 2)),
    ),
    _c(
        "fil-07",
        FIL,
        "We've got twelve Cubs and two leaders here today, and they'd love to see a bridge — "
        "legs of two with a beam on top.",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-08",
        FIL,
        "i am not very good with computers so please be patient with me a staircase of three steps",
        one(k.staircase(3)),
    ),
    _c(
        "fil-09",
        FIL,
        "Robot's been good as gold all week. Usual drill: two towers of five, a cube apart.",
        k.pair(T(5), T(5), k.gap_of(1)),
    ),
    _c(
        "fil-10",
        FIL,
        "The showroom is 6 by 4 metres, but never mind that — a column 150 mm tall at the back.",
        one(T(3), reg("back")),
    ),
    _c(
        "fil-11",
        FIL,
        "ref dwg 7 rev C, sheet 2 of 3. block 2x2 ht 2 @ front L",
        one(k.block(2, 2, 2), reg("front left")),
    ),
    _c(
        "fil-12",
        FIL,
        "Our troop has been camping for ten years now! For the badge: a fire ring, four by "
        "four, one high.",
        one(_PEN4),
    ),
    _c(
        "fil-13",
        FIL,
        "my husband worked in a factory like this for forty years a tower of six please",
        one(T(6)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "twr ht 4 @ front L cnr", one(T(4), reg("front left"))),
    _c(
        "reg-02",
        REG,
        "A 10 cm column centred at 600, 400 mm.",
        one(T(2), k.near(0.60, 0.40, 0.02)),
    ),
    _c(
        "reg-03",
        REG,
        "A tower of three right in front of the robot, close in.",
        one(T(3), reg("front"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-04",
        REG,
        "Put a 3 by 3 slab as far from the robot as the table goes.",
        one(k.block(3, 3, 1), k.min_x(0.60)),
    ),
    _c(
        "reg-05",
        REG,
        "Build the lookout tower of five on the left-hand side, where the scouts are sitting.",
        one(T(5), reg("left")),
    ),
    _c(
        "reg-06",
        REG,
        "a block two by three one high in the back right corner please",
        one(k.block(2, 3, 1), reg("back right")),
    ),
    _c(
        "reg-07",
        REG,
        "row x4 on c/l, front to back",
        one(k.row(4), k.runs("x"), k.near(y=0.30, tol=0.03)),
    ),
    _c(
        "reg-08",
        REG,
        "A 200 mm row along the right-hand edge, running front to back.",
        one(k.row(4), k.runs("x"), _centre_y_max(0.15)),
    ),
    _c(
        "reg-09",
        REG,
        "Put the stepping stones — three single cubes with gaps — across the front of the table.",
        k.all_of(k.in_order("y", *[T(1)] * 3), k.layout(reg("front"))),
    ),
    _c(
        "reg-10",
        REG,
        "a pyramid of two levels in the front right corner",
        one(k.pyramid(2), reg("front right")),
    ),
    _c(
        "reg-11",
        REG,
        "On the robot's left, a wall five long and two high.",
        one(k.wall(5, 2), reg("left")),
    ),
    _c(
        "reg-12",
        REG,
        "2 twrs ht 2: 1 @ back L, 1 @ back R",
        k.structures(k.all_of(T(2), reg("back left")), k.all_of(T(2), reg("back right"))),
    ),
    _c(
        "reg-13",
        REG,
        "A 15 cm tower, its centre 150 mm in from the back edge and on the centre line.",
        one(T(3), k.near(0.65, 0.30, 0.02)),
    ),
    _c(
        "reg-14",
        REG,
        "The flagpole goes in the very middle of the table: four cubes tall.",
        one(T(4), reg("centre")),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "any struct, max ht 3", k.all_of(k.anything, k.layout(k.low(3)))),
    _c("open-02", OPEN, "Build something you'd find at a scout camp — your choice.", k.anything),
    _c("open-03", OPEN, "just build something nice please anything you like", k.anything),
    _c(
        "open-04",
        OPEN,
        "Whatever you built last time is fine, or anything else — just something on the table.",
        k.anything,
    ),
    _c(
        "open-05",
        OPEN,
        "Anything you like, as long as it fits within 150 by 150 mm.",
        k.all_of(k.anything, k.layout(_fits(3, 3))),
    ),
    _c(
        "open-06",
        OPEN,
        "qty 2 structs, any type, not touching",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-07",
        OPEN,
        "Build something the Cubs could walk under, like a gateway or a bridge.",
        k.all_of(k.anything, k.some(_ARCH)),
    ),
    _c(
        "open-08",
        OPEN,
        "something with steps in it please any size you like",
        k.all_of(k.anything, k.some(k.any_of(k.staircase(), k.pyramid()))),
    ),
    _c(
        "open-09",
        OPEN,
        "Surprise me, but keep it close in to the robot.",
        k.all_of(k.anything, k.layout(reg("front"))),
    ),
    _c(
        "open-10",
        OPEN,
        "Any design you like, nothing taller than 100 mm.",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c(
        "open-11",
        OPEN,
        "any struct, cubes only, max 8 blk",
        k.all_of(k.anything, k.layout(k.all_of(k.only_cubes, _cubes(hi=8)))),
    ),
    _c(
        "open-12",
        OPEN,
        "Some kind of fence round an empty patch of ground — any size.",
        k.all_of(k.anything, one(k.ring)),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Same as before but 5 high.", k.honest(k.anything)),
    _c("bad-02", BAD, "The usual, please.", k.honest(k.anything)),
    _c("bad-03", BAD, "Put it where the robot can reach it easily.", k.honest(k.anything)),
    _c("bad-04", BAD, "Build it again, but on the other side this time.", k.honest(k.anything)),
    _c("bad-05", BAD, "twr ht", k.honest(one(_ANY_TOWER))),
    _c(
        "bad-06",
        BAD,
        "wall 16L x 2H @ back",  # 16 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c("bad-07", BAD, "stn 9: recheck instrument height before next setup", k.honest()),
    _c(
        "bad-08",
        BAD,
        "Build a real campfire in the middle of the fire ring, with flames.",
        k.honest(k.anything),
    ),
    _c("bad-09", BAD, "A lookout tower as tall as a real tree.", k.honest(one(_ANY_TOWER))),
    _c("bad-10", BAD, "A tent made out of canvas and poles, please.", k.honest(k.anything)),
    _c("bad-11", BAD, "a tower of of", k.honest(one(_ANY_TOWER))),
    _c("bad-12", BAD, "jjjjjjjjkkkkkk", k.honest()),
    _c(
        "bad-13",
        BAD,
        "a tower of three cubes and also of six cubes",
        k.honest(k.any_of(one(k.any_of(T(3), T(6))), k.structures(T(3), T(6)))),
    ),
    _c(
        "bad-14",
        BAD,
        "A tower 30 mm tall.",  # not a whole cube
        k.honest(one(T(1))),
    ),
    _c(
        "bad-15",
        BAD,
        "A wall 1.2 m long and 10 cm high.",  # 24 cubes: past the cell
        k.honest(k.anything),
    ),
    _c("bad-16", BAD, "A cylinder 100 mm across and 200 mm tall.", k.honest(k.anything)),
    _c(
        "bad-17",
        BAD,
        "A slab 175 by 100 mm, one layer.",  # 3.5 cubes
        k.honest(one(k.any_of(k.block(3, 2, 1), k.block(4, 2, 1)))),
    ),
    _c("bad-18", BAD, "please dont build anything today the robot needs a rest", k.honest()),
    _c(
        "bad-19",
        BAD,
        "Put a tower of three on top of the one from this morning.",  # nothing on the table
        k.honest(k.anything),
    ),
]
