"""A twenty-sixth held-out set for the language front end (dev26): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set or any benchmark result, and worded apart from
`language_dev` … `language_dev25` (no command shared with any set, see tests). Nothing here
was run through the system while it was written. The set is meant to measure the everyday
case, so about 75 % of the commands are ordinary — one or two structures with a size, a place,
one relation or a two-step sequence, in plain but varied English — and they come from five
kinds of people, none of them used by an earlier set:

* a night-shift operator near the end of a long shift: tired, lowercase, terse but not
  cryptic ("tower of 3 front left. then the same again front right."), the odd grumble about
  the coffee machine or the last batch (filler), small slips, "no, 4 — my mistake" as a
  correction, "same as last night" (nothing to go on: bad input);
* a new hire on their first day who is unsure of the words: polite questions ("Could you …?",
  "Is that OK?"), hedges about the names ("the long piece, the beam I think", "a flat square
  of cubes — a slab?", "I'm not sure ring is the right word"). A question that names a
  structure is a request for it; a part named by description ("the long bars", "the long
  piece") is the beam; "a little space" or "a bit of space" between two things is clear of
  it and no more than 25 cm away; "not too close to the robot" is outside the front region;
  "the corner nearest me, beside the robot on its right" is the front right;
* an engineer dictating to a colleague who types it for them ("Typing this for Marco:", "He
  says", "she wants", "her words, I'm just typing"). Only what the engineer asks for is
  checked; the typist's asides are filler; "wait, he says 2 levels" replaces what was said
  before. A message where the engineer walked off, or where the typist
  could not tell which of two figures was meant, is bad input;
* a sales engineer at a trade-fair booth setting up demos between groups of visitors:
  upbeat, quick, "for the next group", "so the crowd can see", "a quick pyramid". The crowd
  talk is filler; "exactly as tall as the pyramid" is a comparison (the pyramid's height in
  cubes); real bricks and a wall two metres long for the banner are bad input;
* a supervisor sending a short instruction by e-mail: a subject line, a greeting, one or two
  lines and a sign-off ("Thanks, Karen", "Sent from my phone"). Subject lines, greetings,
  "Re: Re:", signatures and job titles are filler (a number in them is not a size); "not 3 as
  I wrote yesterday" replaces yesterday's figure; an e-mail that only points at an
  attachment is bad input.

About 75 % ordinary and 25 % harder: three or more structures, references ("on it", "the
middle one", "the right end of the wall"), distributive phrases ("a cube on each corner of
the top", "a single cube on each side", "between each"), comparisons ("half as tall", "twice
as high", "one cube shorter", "exactly as tall as the pyramid"), corrections ("no, 4", "wait,
he says 2 levels", "actually … make it 3 high"), removals ("take the top two off", "take the
middle one away", "without the cube on the very top") and unusable input (sizes and
positions past the cell, negative sizes, contradictions, figures that disagree, requests the
cell cannot serve, references to nothing built, keyboard mash).

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions) and accepts every reasonable reading of vague wording, and nothing else:

* "next to" / "beside" with nothing said about touching is clear of it and no more than 25 cm
  away, or set against it so that the two are one structure (checked by its column
  heights); "not touching", "a gap", "apart" and "leave a gap" mean two separate structures;
  "touching" means one;
* "in front of", "behind", "to the left / right of" is the dominant direction between
  footprint centres (back = +x, front = -x, left = +y, right = -y); "in front of it, on the
  robot side" is the front; "behind it, touching" is a column set against the back; with no
  distance said any distance will do, and a tower "behind" a block may stand against it;
* a bridge's top is a beam (the shared `bridge`, its overall height one more than the
  pillars) where the command names a beam or "the long piece", and a beam or a bar of cubes
  where it does not; "no beam, cubes across the top" is a bar of cubes only; a table or
  canopy is four separate legs under one connected top of beams or of cubes;
* a staircase's width is free unless given, and so is the way it climbs; "a cube on the top
  step" stands on the top step only; "stairs leading up to a tower, touching it" put the
  tower against the top step, in the direction the stairs climb;
* "a cube on each corner of the top" of a 3 × 3 block puts a cube on its four corner cells
  and nothing else; "without the cube on the very top" of a three-level pyramid leaves its
  two lower levels; "leave out one cube on the side nearest the robot, like a door" is a 4 ×
  4 ring less one cube of its front side; "a square … no cube in the middle" is the 3 × 3
  ring of eight;
* "an L shape with both arms 20 cm" is an L whose footprint is 4 × 4; "a pyramid on a base of
  25 by 25 cm, coming to a point" accepts the 25-9-1 and the 25-16-9-4-1 pyramid; "10 cm of
  space between them" is the clear gap;
* "something small" is at most 4 cubes high and 5 long overall; "towers of different heights"
  are two or more separate one- or two-cube-wide columns, no two of the same height;
  "symmetrical, left and right match" is a mirror image of itself across the y axis;
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30));
  "all the way at the back" is every part at x ≥ 0.60, "as close to the robot as you can"
  every part at x ≤ 0.35, "the left half" every part at y ≥ 0.30, "the centre line" y = 0.30
  ± 3 cm, "right at the front, in the middle" the front region on the centre line; a stated
  coordinate is the footprint centre ± 2 cm.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`); a request that is not a build at all admits only the refusal.
Geometry comes only from `sdi.bench.boxes`, through the shared checks in `language_checks`
and the local checks below.

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

_NEAR = 0.25  # m: "next to", "beside", "a little space between" when clear of it


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev26-{id_}", phenomenon=phenomenon, text=text, accept=accept)


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


def _next_to(a: k.Check, b: k.Check, joined: k.Check) -> k.Pred:
    """ "Next to" / "beside" where touching is not said: A and B separate and no more than
    25 cm apart, or one structure passing `joined` (the two set against each other)."""
    return k.any_of(k.pair(a, b, k.within(_NEAR)), k.one(joined))


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


def _span(posts: int | None = None, mouth: int | None = None) -> k.Check:
    """A bridge whose top is not named: two posts `posts` high (any height when None) with a
    beam (the shared `bridge`) or a bar of cubes across the tops; posts `mouth` cubes apart
    clear when given."""
    beam = k.all_of(k.bridge(posts, pillars=2), k.height(None if posts is None else posts + 1))
    if mouth is not None:
        beam = k.all_of(beam, k.leg_gap(mouth))
    return k.any_of(beam, _bar_on_posts(posts, posts, mouth))


def _roof_on(legs: int, leg_h: int) -> k.Check:
    """`legs` separate legs, each a full column `leg_h` cubes high on the table, under one
    connected top that is the topmost level and rests on every leg (a top of beams or of
    cubes, whose middle cubes rest on nothing)."""

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
    """A table or canopy on `legs` legs `leg_h` high: the shared `canopy` one layer above the
    legs, a top of cubes, or the cell's beam roof."""
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


def _stairs_to(h: int, steps: int) -> k.Check:
    """One structure: a staircase of `steps` steps and a full column of exactly `h` cubes on
    the table touching it at its top end (the column lies in the direction the stairs
    climb)."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col in bx.columns(bs):
            if len(col) != h or k.tower(h)(col) is not None or col[0].lo[2] > bx.TOL:
                continue
            rest = [b for b in bs if all(b is not c for c in col)]
            if not rest:
                continue
            r = k.staircase(steps)(rest)
            if r is None:
                up, side = bx.rises_towards(rest), bx.side_of(col, rest)
                if side != up:
                    r = f"the {h}-column is {side} of the stairs, which climb {up}"
            if r is None and not any(bx.touching(p, q) for p in col for q in rest):
                r = "the column does not touch the stairs"
            if r is None:
                return None
            first = first or r
        return first or f"no {h}-cube column at the top of the stairs"

    return f


def _on_top_step(extra: int, steps: int) -> k.Check:
    """A staircase of `steps` steps (climbing any way) with a tower of `extra` cubes standing
    on its top step, and nothing else above the top step's height."""

    def f(bs: k.Boxes) -> k.Reason:
        top = steps * bx.CUBE - bx.TOL
        upper = [b for b in bs if b.lo[2] >= top]
        lower = [b for b in bs if b.lo[2] < top]
        if not upper or not lower:
            return "nothing standing on the top step"
        r = k.staircase(steps)(lower) or k.tower(extra)(upper)
        if r:
            return r
        return None if bx.stands_on(upper, lower) else "the cube does not stand on the stairs"

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


def _nn_gap(n: int) -> k.Pred:
    """Every separate structure's nearest neighbour is `n` cubes away, clear (± 1.5 cm)."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < 2:
            return "fewer than two structures"
        for i, g in enumerate(comps):
            gap = min(bx.separation(g, h) for j, h in enumerate(comps) if j != i)
            if abs(gap - n * bx.CUBE) > 0.015:
                return f"a structure {gap:.3f} m from its nearest neighbour, want {n} cube(s)"
        return None

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
    """A pyramid whose top level is more than one part (its top cube left off)."""
    p = bx.pyramid_levels(bs)
    if p is None:
        return "not a pyramid"
    return None if p[-1] > 1 else "a single cube on top"


def _cubes(lo: int | None = None, hi: int | None = None) -> k.Check:
    """Between `lo` and `hi` cubes among the parts (beams not counted)."""

    def f(bs: k.Boxes) -> k.Reason:
        n = sum(k.only_cubes([b]) is None for b in bs)
        if (lo is not None and n < lo) or (hi is not None and n > hi):
            return f"{n} cubes, want {lo if lo is not None else ''}–{hi if hi is not None else ''}"
        return None

    return f


def _max_x(hi: float) -> k.Check:
    """Every part lies at x ≤ `hi` (m): that close to the robot or closer."""

    def f(bs: k.Boxes) -> k.Reason:
        top = max(b.hi[0] for b in bs)
        return None if top <= hi + bx.TOL else f"a part reaches x {top:.3f}, want ≤ {hi}"

    return f


def _min_y(lo: float) -> k.Check:
    """Every part lies at y ≥ `lo` (m): on the left of that line."""

    def f(bs: k.Boxes) -> k.Reason:
        low = min(b.lo[1] for b in bs)
        return None if low >= lo - bx.TOL else f"a part reaches y {low:.3f}, want ≥ {lo}"

    return f


def _mirror_lr(bs: k.Boxes) -> k.Reason:
    """The occupied cells are their own mirror image left to right (across the y axis)."""
    vox = bx.voxels(bs)
    if not vox:
        return "no parts"
    mj = max(j for _, j, _ in vox)
    return None if {(i, mj - j, z) for i, j, z in vox} == vox else "left and right differ"


def _distinct_towers(lo: int = 2) -> k.Pred:
    """At least `lo` separate structures, each a full column one or two cubes across on the
    table, no two of the same height."""

    def f(result: Mapping[str, Any]) -> k.Reason:
        comps = k.separate_structures(result)
        if isinstance(comps, str):
            return comps
        if len(comps) < lo:
            return f"{len(comps)} separate structures, want ≥ {lo}"
        hs = []
        for g in comps:
            r = k.on_table(g) or k.any_of(k.tower(), k.tower(base=2))(g)
            if r:
                return f"not a tower: {r}"
            hs.append(bx.thickness_cubes(g))
        return None if len(set(hs)) == len(hs) else f"heights {sorted(hs)} repeat"

    return f


T = k.tower
one = k.one
reg = k.region
_ARCH = k.any_of(k.arch, _bar_on_posts())  # anything spanning a gap, cube-row bars too
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_CENTRE_LINE = k.near(y=0.30, tol=0.03)


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "ok. tower of 4, and a tower of 2 right next to it on its left side. not touching.",
        k.pair(T(2), T(4), k.all_rels(k.on_side(_L), k.within(_NEAR))),
    ),
    _c(
        "rel-02",
        REL,
        "Hi, first day here. Could you lay a flat square of cubes, 3 by 3, and then stand one "
        "cube in the middle of it? I think the flat part is called a slab?",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "rel-03",
        REL,
        "Typing this for Marco: he wants a wall 4 long and 2 high, and a tower of 5 in front of "
        "it, on the robot side, with a one-cube gap between them.",
        k.pair(T(5), k.wall(4, 2), k.gap_of(1, _F)),
    ),
    _c(
        "rel-04",
        REL,
        "Next group's coming over. Put a 2-level pyramid in the middle of the table and a "
        "3-cube tower behind it, with a two-cube gap, so both are in view.",
        k.pair(T(3), k.all_of(k.pyramid(2), reg("centre")), k.gap_of(2, _B)),
    ),
    _c(
        "rel-05",
        REL,
        "Subject: bridge for Thursday\n\nHi,\n\nPlease build a bridge with two pillars 3 cubes "
        "high and a beam across the top.\n\nThanks,\nKaren",
        one(_beam_bridge(3)),
    ),
    _c(
        "rel-06",
        REL,
        "two towers of 3, one cube apart, and a beam on top joining them. that's all.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "rel-07",
        REL,
        "Can the robot make a ring of cubes, 5 by 5, one cube high, with a tower of 3 inside "
        "it? Sorry, I'm not sure ring is the right word.",
        k.any_of(k.around(T(3), _PEN5), one(k.holding(T(3), _PEN5))),
    ),
    _c(
        "rel-08",
        REL,
        "Lena says: a tower of 6 on the right side of the table, and a row of 4 somewhere to "
        "the left of it, not touching. Her words, I'm just typing.",
        k.pair(k.row(4), k.all_of(T(6), reg("right")), k.on_side(_L)),
    ),
    _c(
        "rel-09",
        REL,
        "For the demo: a tower of 5, and right behind it, touching it, a tower of 3. From the "
        "front it looks like two steps.",
        one(_col_beside(3, T(5), _B)),
    ),
    _c(
        "rel-10",
        REL,
        "Hi team,\n\nCan we get a 2x2 block, 2 layers high, with a single cube sitting on top "
        "of it? Nothing else needed.\n\nThanks,\nDev",
        one(k.on_top(T(1), k.block(2, 2, 2)), k.levels(4, 4, 1)),
    ),
    _c(
        "rel-11",
        REL,
        "pyramid, 3 levels, back right. tower of 2 in front of it, leave a gap.",
        k.pair(T(2), k.all_of(k.pyramid(3), reg("back right")), k.on_side(_F)),
    ),
    _c(
        "rel-12",
        REL,
        "I need the long piece, the beam I think, laid across two stacks of two cubes. Is that "
        "called a bridge? Anyway, that please.",
        one(_beam_bridge(2)),
    ),
    _c(
        "rel-13",
        REL,
        "From Sam, word for word: a 3x3 slab, one layer, at the front, and a tower of 4 "
        "standing on the middle of it.",
        one(
            k.on_top(T(4), k.block(3, 3, 1)),
            k.centred(),
            k.levels(9, 1, 1, 1, 1),
            reg("front"),
        ),
    ),
    _c(
        "rel-14",
        REL,
        "Let's do the classic one: a staircase of 3 steps leading up to a tower of 5, with the "
        "top step touching the tower.",
        one(_stairs_to(5, 3)),
    ),
    _c(
        "rel-15",
        REL,
        "Subject: layout for the audit\n\nPlease put one row of 5 along the back and another "
        "row of 5 along the front, both running left to right.\n\nRegards,\nTom",
        k.structures(
            k.all_of(k.row(5), k.runs("y"), reg("back")),
            k.all_of(k.row(5), k.runs("y"), reg("front")),
        ),
    ),
    _c(
        "rel-16",
        REL,
        "tower of 5 in the middle, then one single cube on each side of it, left and right, "
        "touching it.",
        one(k.lr_profile(1, 5, 1), reg("centre")),
    ),
    _c(
        "rel-17",
        REL,
        "Sorry, I'm new. Can I get two towers of 4 with one of those long bars across the top "
        "connecting them, and then one cube on the bar, right in the middle?",
        one(_topped(_beam_bridge(4)), k.top_centred()),
    ),
    _c(
        "rel-18",
        REL,
        "Typing for Ahmed. He wants three towers in a line going left to right, heights 2, 4 "
        "and 2, the tall one in the middle, one cube gap between each.",
        k.in_order("y", T(2), T(4), T(2), gaps=(1,)),
    ),
    _c(
        "rel-19",
        REL,
        "A 3x3 block two layers high, and then a cube on each corner of the top. Looks like a "
        "little fort.",
        one(k.plan_heights("323", "222", "323")),
    ),
    _c(
        "rel-20",
        REL,
        "Hi,\n\nPlease set up two walls, each 5 long and 2 high, side by side and parallel with "
        "a two-cube gap, for the gripper test.\n\nThanks,\nOlga",
        k.pair(k.wall(5, 2), k.wall(5, 2), k.parallel_gap(2)),
    ),
    _c(
        "rel-21",
        REL,
        "A pyramid with 3 levels and, two cubes to the right of it, a tower exactly as tall as "
        "the pyramid.",
        k.pair(T(3), k.pyramid(3), k.gap_of(2, _R)),
    ),
    # ------------------------------------------------------------------ sequence
    _c("seq-01", SEQ, "tower of 6. no, 4 — my mistake, 4.", one(T(4))),
    _c(
        "seq-02",
        SEQ,
        "First could you lay a row of 4 cubes, and then a second row of 4 right on top of it? "
        "I think that makes a wall?",
        one(k.wall(4, 2)),
    ),
    _c(
        "seq-03",
        SEQ,
        "Kim says: build a tower of 5 in the back left. Then a second tower of 5 next to it, "
        "one cube apart.",
        k.pair(k.all_of(T(5), reg("back left")), T(5), k.gap_of(1)),
    ),
    _c(
        "seq-04",
        SEQ,
        "Start with a 3x3 slab, one layer. Then a 2x2 layer on top, then one cube on top of "
        "that. A quick pyramid for the crowd.",
        one(k.pyramid_counts(9, 4, 1)),
    ),
    _c(
        "seq-05",
        SEQ,
        "Subject: wall height\n\nPlease build a wall 6 long and 3 high, then take the top layer "
        "off again; we only need it 2 high for now.\n\nThanks",
        one(k.wall(6, 2)),
    ),
    _c(
        "seq-06",
        SEQ,
        "row of 3. then add 2 more on the end so it's one row of 5.",
        one(k.row(5)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Can you build a tower of 3, and then another one the same next to it? With a little "
        "space between them, I mean.",
        k.pair(T(3), T(3), k.within(_NEAR)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Okay, he's dictating now. First a 2 by 3 slab, one cube thick. Then a tower of 3 on "
        "one corner of the slab. That's it.",
        one(k.plan_heights("411", "111")),
    ),
    _c(
        "seq-09",
        SEQ,
        "Build a tower of 7. Hmm, that's too tall for the photo, take the top two off.",
        one(T(5)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Hi,\n\nFirst build two towers of 2, one cube apart. Then lay a beam across the top of "
        "them.\n\nThanks,\nBen",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "seq-11",
        SEQ,
        "tower of 3 front left. then the same again front right.",
        k.structures(k.all_of(T(3), reg("front left")), k.all_of(T(3), reg("front right"))),
    ),
    _c(
        "seq-12",
        SEQ,
        "Step one, a staircase with 3 steps. Step two, a cube on the top step. Is that the "
        "right way to say it?",
        one(_on_top_step(1, 3)),
    ),
    _c(
        "seq-13",
        SEQ,
        "A pyramid of 3 levels — wait, he says 2 levels. Two. Sorry.",
        one(k.pyramid(2)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Put a row of 6 along the front, left to right, then a second row of 6 directly behind "
        "it, touching, so it's two deep.",
        one(k.block(2, 6, 1), k.runs("y"), reg("front")),
    ),
    _c(
        "seq-15",
        SEQ,
        "Subject: correction to yesterday's request\n\nPlease build the tower in the back right "
        "5 high, not 3 as I wrote yesterday.\n\nBest,\nAnna",
        one(T(5), reg("back right")),
    ),
    _c(
        "seq-16",
        SEQ,
        "3 towers of 2 in a line, a cube apart. then take the middle one away.",
        k.pair(T(2), T(2), k.gap_of(3)),
    ),
    _c(
        "seq-17",
        SEQ,
        "I'd like a ring, 4 by 4, one cube high. Then could you make the whole ring 2 high "
        "instead?",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-18",
        SEQ,
        "He says: a wall 5 long and 2 high, running left to right. Then a tower of 3 on top of "
        "the right end of the wall.",
        one(k.lr_profile(2, 2, 2, 2, 5)),
    ),
    _c(
        "seq-19",
        SEQ,
        "Build a 2x2 block 4 high. Actually that's a bit much for the table, make it 3 high.",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "seq-20",
        SEQ,
        "Hi all,\n\nStep 1: a 3x3 block, 2 layers, in the centre.\nStep 2: remove the top "
        "layer.\nStep 3: put a single cube on the middle.\n\nCheers,\nPaul",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1), reg("centre")),
    ),
    _c(
        "seq-21",
        SEQ,
        "tower of 5 in the centre. ok now move it to the back. still just the one tower.",
        one(T(5), reg("back")),
    ),
    # ------------------------------------------------------------------ numbers
    _c("num-01", NUM, "two towers, 3 cubes each, not touching each other.", k.each(2, T(3))),
    _c(
        "num-02",
        NUM,
        "Could I have four cubes in a line, just on the table, touching each other?",
        one(k.row(4)),
    ),
    _c("num-03", NUM, "Jo wants eight cubes stacked up into a single tower.", one(T(8))),
    _c(
        "num-04",
        NUM,
        "Three towers for the booth, 1, 2 and 3 high from left to right, a cube apart.",
        k.in_order("y", T(1), T(2), T(3), gaps=(1,)),
    ),
    _c(
        "num-05",
        NUM,
        "Hi,\n\nPlease build a slab of 12 cubes, 3 by 4, one layer.\n\nThanks",
        one(k.block(3, 4, 1)),
    ),
    _c("num-06", NUM, "pyramid, base 3 by 3, 3 levels.", one(k.pyramid_counts(9, 4, 1))),
    _c("num-07", NUM, "Can you make a tower out of ten cubes? Or is ten too many?", one(T(10))),
    _c(
        "num-08",
        NUM,
        "She wants two walls, each 3 long and 2 high, and they shouldn't touch.",
        k.each(2, k.wall(3, 2)),
    ),
    _c(
        "num-09",
        NUM,
        "A tower of 6, and another one half as tall beside it.",
        _next_to(T(3), T(6), k.cell_heights(3, 6)),
    ),
    _c(
        "num-10",
        NUM,
        "Subject: pillars\n\nWe need 4 pillars, each 3 cubes high, in one line, a cube apart."
        "\n\nThanks,\nRaj",
        k.in_line(4, T(3), 1),
    ),
    _c(
        "num-11",
        NUM,
        "3 rows of 3 cubes, touching, one layer. a square basically.",
        one(k.block(3, 3, 1)),
    ),
    _c(
        "num-12",
        NUM,
        "I was told to ask for a staircase with 5 steps. Is that OK?",
        one(k.staircase(5)),
    ),
    _c(
        "num-13",
        NUM,
        "He says one tower of 4 and a second tower one cube shorter, with a one-cube gap.",
        k.pair(T(3), T(4), k.gap_of(1)),
    ),
    _c(
        "num-14",
        NUM,
        "Five single cubes in a row across the front, a cube apart, like dots on a domino.",
        k.all_of(k.in_order("y", T(1), T(1), T(1), T(1), T(1), gaps=(1,)), k.layout(reg("front"))),
    ),
    _c(
        "num-15",
        NUM,
        "Hi,\n\nCould you build a pyramid with a 4x4 base, 4 levels?\n\nThanks,\nLisa",
        one(k.pyramid_counts(16, 9, 4, 1)),
    ),
    _c("num-16", NUM, "tower of 9 please. yes, 9.", one(T(9))),
    _c(
        "num-17",
        NUM,
        "Two towers please, one of 2 cubes and one twice as high, with a bit of space between "
        "them.",
        k.pair(T(2), T(4), k.within(_NEAR)),
    ),
    _c(
        "num-18",
        NUM,
        "Typing for Greta: three towers, 3, 4 and 5 high, from front to back, with a one-cube "
        "gap between each.",
        k.in_order("x", T(3), T(4), T(5), gaps=(1,)),
    ),
    _c(
        "num-19",
        NUM,
        "A 2 by 2 block, three layers. That's twelve cubes, right?",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "num-20",
        NUM,
        "Subject: test pattern\n\nPlease place four single cubes in a square, with two cubes "
        "of space between neighbours.\n\nBest,\nH.",
        k.all_of(k.each(4, T(1)), k.layout(k.dims(4, 4)), _nn_gap(2)),
    ),
    # ------------------------------------------------------------------ dimensions
    _c("dim-01", DIM, "tower, 20 cm tall, back right.", one(T(4), reg("back right"))),
    _c(
        "dim-02",
        DIM,
        "Could you build a wall that's 25 centimetres long and 10 centimetres high?",
        one(k.wall(5, 2)),
    ),
    _c(
        "dim-03",
        DIM,
        "He says a row 30 cm long, going left to right.",
        one(k.row(6), k.runs("y")),
    ),
    _c(
        "dim-04",
        DIM,
        "Build a tower 40 cm high so people at the back of the crowd can see it.",
        one(T(8)),
    ),
    _c(
        "dim-05",
        DIM,
        "Hi,\n\nPlease build a solid block 10 cm by 10 cm and 15 cm high.\n\nThanks,\nSue",
        one(k.block(2, 2, 3)),
    ),
    _c("dim-06", DIM, "slab 15 x 20 cm, one cube thick.", one(k.block(3, 4, 1))),
    _c(
        "dim-07",
        DIM,
        "The cubes are 5 cm, I think? Then I need a tower 35 cm tall, please.",
        one(T(7)),
    ),
    _c(
        "dim-08",
        DIM,
        "Pillars 10 cm high, 5 cm apart, with the beam on top. That's what Nina wants.",
        one(_beam_bridge(2, 1)),
    ),
    _c(
        "dim-09",
        DIM,
        "Thirty-five centimetres of wall, 10 cm tall, at the back of the table, running left "
        "to right.",
        one(k.wall(7, 2), k.runs("y"), reg("back")),
    ),
    _c(
        "dim-10",
        DIM,
        "Subject: staircase\n\nPlease build a staircase 15 cm high, 5 cm per step.\n\nThanks",
        one(k.staircase(3)),
    ),
    _c("dim-11", DIM, "ring, 20 x 20 cm, 5 cm high.", one(_PEN4)),
    _c(
        "dim-12",
        DIM,
        "How about a bridge? Legs 15 cm high and 5 cm of gap between them. I'm not sure what "
        "goes across the top, whatever you normally use.",
        one(_span(3, 1)),
    ),
    _c(
        "dim-13",
        DIM,
        "Two towers, 15 cm and 25 cm tall, with 10 cm of space between them. He was very specific.",
        k.pair(T(3), T(5), k.gap_of(2)),
    ),
    _c(
        "dim-14",
        DIM,
        "A pyramid on a base of 25 by 25 cm, as many levels as it takes to come to a point.",
        one(k.any_of(k.pyramid_counts(25, 9, 1), k.pyramid_counts(25, 16, 9, 4, 1))),
    ),
    _c(
        "dim-15",
        DIM,
        "Hi,\n\nWe need a platform 20 cm wide (left to right) and 10 cm deep (front to back), "
        "one cube thick, at the front.\n\nThanks,\nMo",
        one(k.block_xy(2, 4, 1), reg("front")),
    ),
    _c(
        "dim-16",
        DIM,
        "flat L shape on the table, both arms 20 cm.",
        one(k.shape_letter("L"), k.dims(4, 4), k.height(1)),
    ),
    _c(
        "dim-17",
        DIM,
        "Could you make a table? Four legs about 10 cm tall and a top on them. Sorry, I don't "
        "know the proper name for it.",
        one(_roofed(4, 2)),
    ),
    _c(
        "dim-18",
        DIM,
        "He'd like a staircase 2 cubes wide and 20 cm high.",
        one(k.staircase(4), k.dims(2, 4)),
    ),
    _c(
        "dim-19",
        DIM,
        "Let's do a wall 30 cm long and 20 cm tall, with a 10 cm tower 5 cm in front of it.",
        k.pair(T(2), k.wall(6, 4), k.gap_of(1, _F)),
    ),
    _c(
        "dim-20",
        DIM,
        "Subject: block\n\nA block 0.1 m x 0.15 m, 0.1 m high, please, in the back left.\n\n"
        "Regards,\nJan",
        one(k.block(2, 3, 2), reg("back left")),
    ),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "tower of 4. not in the middle this time.",
        one(T(4), k.not_(reg("centre"), "in the middle")),
    ),
    _c(
        "neg-02",
        NEG,
        "Can I get a wall 5 long and 2 high, but without the long pieces? Only cubes.",
        one(k.wall(5, 2), k.only_cubes),
    ),
    _c(
        "neg-03",
        NEG,
        "A row of 6, he says, but not left to right. Front to back.",
        one(k.row(6), k.runs("x")),
    ),
    _c(
        "neg-04",
        NEG,
        "A 3-level pyramid, but not at the back; people can't see it there.",
        one(k.pyramid(3), k.not_(reg("back"), "at the back")),
    ),
    _c(
        "neg-05",
        NEG,
        "Hi,\n\nPlease build two towers of 3. They must not touch each other.\n\nThanks",
        k.each(2, T(3)),
    ),
    _c(
        "neg-06",
        NEG,
        "3x3 square, one high, no cube in the middle.",
        one(k.ring_of(1, (1, 1)), k.dims(3, 3), k.parts(8)),
    ),
    _c(
        "neg-07",
        NEG,
        "I'd like a tower of 5, but not too close to the robot please, it makes me a bit nervous.",
        one(T(5), k.not_(reg("front"), "close to the robot")),
    ),
    _c(
        "neg-08",
        NEG,
        "Bridge with legs of 2. No beam, he says. Cubes across the top instead.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "A staircase of 4, and don't have it climbing towards the robot; it should climb away "
        "from it.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c(
        "neg-10",
        NEG,
        "Hi,\n\nA wall 6 long and 2 high, please. Not along the front this time.\n\nThanks",
        one(k.wall(6, 2), k.not_(reg("front"), "along the front")),
    ),
    _c(
        "neg-11",
        NEG,
        "tower of 3, anywhere except the left side.",
        one(T(3), k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-12",
        NEG,
        "A 4 by 4 ring, one high, but leave out one cube on the side nearest the robot, like a "
        "door. Is that possible?",
        one(
            k.dims(4, 4),
            k.height(1),
            k.parts(11),
            k.not_(k.ring, "closed"),
            _missing_on(_F),
        ),
    ),
    _c(
        "neg-13",
        NEG,
        "He wants a pyramid, 3 levels, but without the cube on the very top.",
        one(_flat_topped_pyramid, k.pyramid(2)),
    ),
    _c(
        "neg-14",
        NEG,
        "A 2x2 block, 2 high, no beams and nothing on top. Just the block.",
        one(k.block(2, 2, 2), k.only_cubes),
    ),
    _c(
        "neg-15",
        NEG,
        "Subject: tower\n\nOne tower of 6 in the centre, please, and don't build anything else "
        "this time.\n\nThanks,\nMark",
        one(T(6), reg("centre")),
    ),
    # ------------------------------------------------------------------ typo
    _c("typo-01", TYP, "towr of 5 in the bakc left pls", one(T(5), reg("back left"))),
    _c(
        "typo-02",
        TYP,
        "Could you biuld a wall 4 long and 3 hgih? Sorry, typing too fast.",
        one(k.wall(4, 3)),
    ),
    _c("typo-03", TYP, "He syas a pyramd with 3 levles.", one(k.pyramid(3))),
    _c(
        "typo-04",
        TYP,
        "Quick, a staircse of 4 stpes in the midlde!",
        one(k.staircase(4), reg("centre")),
    ),
    _c(
        "typo-05",
        TYP,
        "Hi,\n\nPlease bulid two towrs of 4, one cube aprt.\n\nThanks",
        k.pair(T(4), T(4), k.gap_of(1)),
    ),
    _c(
        "typo-06",
        TYP,
        "rwo of 6 along the frnot, left to rigth",
        one(k.row(6), k.runs("y"), reg("front")),
    ),
    _c(
        "typo-07",
        TYP,
        "Can I have a brdige with legs of 3 and the long peice on top?",
        one(_beam_bridge(3)),
    ),
    _c("typo-08", TYP, "She wnats a 2x3 slab, one layr.", one(k.block(2, 3, 1))),
    _c(
        "typo-09",
        TYP,
        "tower of 3 with a cueb on top, so 4 tall in totl, fornt right",
        one(T(4), reg("front right")),
    ),
    _c("typo-10", TYP, "Hi,\n\nCoudl you build a rign 5x5, one high?\n\nThansk", one(_PEN5)),
    _c(
        "typo-11",
        TYP,
        "tower of 2 nxet to a tower of 6",
        _next_to(T(2), T(6), k.cell_heights(2, 6)),
    ),
    _c(
        "typo-12",
        TYP,
        "A caonpy with 4 legs 2 cubes tall, please? I saw one yestreday.",
        one(_roofed(4, 2)),
    ),
    _c("typo-13", TYP, "Blcok 3 by 3, two layrs, at the bcak.", one(k.block(3, 3, 2), reg("back"))),
    _c(
        "typo-14",
        TYP,
        "Two wlls, 4 long and 2 hihg, parralel, a cube apart.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.parallel_gap(1)),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "back left, tower of 3.", one(T(3), reg("back left"))),
    _c(
        "wo-02",
        WO,
        "On the right side, could you put a row of 5? Going front to back, I mean.",
        one(k.row(5), k.runs("x"), reg("right")),
    ),
    _c(
        "wo-03",
        WO,
        "Five high, the tower, and in the centre. That's the order he said it in.",
        one(T(5), reg("centre")),
    ),
    _c(
        "wo-04",
        WO,
        "In the front, a 2 by 2 block, two layers; behind it, a tower of 6.",
        k.any_of(
            k.pair(T(6), k.all_of(k.block(2, 2, 2), reg("front")), k.on_side(_B)),
            one(_col_beside(6, k.all_of(k.block(2, 2, 2), reg("front")), _B)),
        ),
    ),
    _c(
        "wo-05",
        WO,
        "Hi,\n\nIn the back right corner, a pyramid of two levels, please.\n\nThanks",
        one(k.pyramid(2), reg("back right")),
    ),
    _c(
        "wo-06",
        WO,
        "on top of a 3x3 slab, one cube. in the centre of it.",
        one(k.on_top(T(1), k.block(3, 3, 1)), k.centred(), k.levels(9, 1)),
    ),
    _c(
        "wo-07",
        WO,
        "The steps, 3 of them, a staircase, on the left please?",
        one(k.staircase(3), reg("left")),
    ),
    _c(
        "wo-08",
        WO,
        "Between two towers of 4, a tower of 2. He described the middle one first. One cube "
        "apart each.",
        k.line(T(4), T(2), T(4), gaps=(1,)),
    ),
    _c("wo-09", WO, "Three high and six long, the wall for the photo.", one(k.wall(6, 3))),
    _c(
        "wo-10",
        WO,
        "Subject: request\n\nTo the left of a tower of 5, a tower of 3, please. Not touching."
        "\n\nThanks",
        k.pair(T(3), T(5), k.on_side(_L)),
    ),
    _c(
        "wo-11",
        WO,
        "legs 3 high, beam across, one cube gap. a bridge.",
        one(_beam_bridge(3, 1)),
    ),
    _c(
        "wo-12",
        WO,
        "Four by two, one layer, that's the flat thing I need. A slab?",
        one(k.block(2, 4, 1)),
    ),
    _c(
        "wo-13",
        WO,
        "Right at the front, in the middle, a tower of, let's say, 4.",
        one(T(4), reg("front"), _CENTRE_LINE),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "long night. coffee machine's broken again. anyway, tower of 4 please.",
        one(T(4)),
    ),
    _c(
        "fil-02",
        FIL,
        "Hello! It's my first day and everyone's been really nice. My trainer said to start "
        "with something easy, so could you build a row of 3?",
        one(k.row(3)),
    ),
    _c(
        "fil-03",
        FIL,
        "Okay, I'm typing for Piotr because he's got gloves on and can't use the keyboard. He "
        "says, um, a wall, 5 long, 3 high. That's it.",
        one(k.wall(5, 3)),
    ),
    _c(
        "fil-04",
        FIL,
        "Wow, busy day at the booth, about two hundred people through already! Right, for the "
        "next group: a pyramid with 3 levels.",
        one(k.pyramid(3)),
    ),
    _c(
        "fil-05",
        FIL,
        "Subject: Re: Re: cell schedule\n\nHi all,\n\nHope you had a good weekend. As "
        "discussed in Monday's meeting, please build a 2x2 block, 3 layers high.\n\nKind "
        "regards,\nSandra\nProduction Supervisor, Line 2",
        one(k.block(2, 2, 3)),
    ),
    _c(
        "fil-06",
        FIL,
        "3am, nobody else here. just need a staircase with 4 steps for the morning check.",
        one(k.staircase(4)),
    ),
    _c(
        "fil-07",
        FIL,
        "My manager is watching so I really hope this works, haha. A tower of 6, please!",
        one(T(6)),
    ),
    _c(
        "fil-08",
        FIL,
        "He's on the phone with a supplier at the same time, so bear with us. He says: a ring, "
        "4 by 4, two cubes high.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "fil-09",
        FIL,
        "Okay everyone, watch the arm, it's accurate to a fraction of a millimetre. Robot, "
        "build a bridge with legs 2 high.",
        one(_span(2)),
    ),
    _c(
        "fil-10",
        FIL,
        "Hi team,\n\nQuick one before I go on leave for 2 weeks: please build a row of 7 along "
        "the left side.\n\nThanks,\nGeorge\n\nSent from my phone",
        one(k.row(7), reg("left")),
    ),
    _c(
        "fil-11",
        FIL,
        "ugh, last batch failed, whatever. clear it and give me a slab 2 by 5, one layer.",
        one(k.block(2, 5, 1)),
    ),
    _c(
        "fil-12",
        FIL,
        "Sorry, quick question first: do I just type what I want? I'll try. A tower of 2 in "
        "the front left, please.",
        one(T(2), reg("front left")),
    ),
    _c(
        "fil-13",
        FIL,
        "Ladies and gentlemen, this robot has never seen this request before! Build a tower of "
        "5 and a tower of 3, a cube apart.",
        k.pair(T(3), T(5), k.gap_of(1)),
    ),
    # ------------------------------------------------------------------ region
    _c("reg-01", REG, "tower of 3 at x 0.4, y 0.2.", one(T(3), k.near(0.40, 0.20, 0.02))),
    _c(
        "reg-02",
        REG,
        "Could you put a 2x2 block, one layer, in the corner nearest me? I'm standing beside "
        "the robot, on its right.",
        one(k.block(2, 2, 1), reg("front right")),
    ),
    _c(
        "reg-03",
        REG,
        "He wants a wall 5 long and 2 high all the way at the back, running left to right.",
        one(k.wall(5, 2), k.runs("y"), k.min_x(0.60)),
    ),
    _c(
        "reg-04",
        REG,
        "Put the tower of 5 right in the middle of the table so everybody can see it.",
        one(T(5), reg("centre")),
    ),
    _c(
        "reg-05",
        REG,
        "Hi,\n\nPlease place a pyramid of 2 levels in the front left corner.\n\nThanks",
        one(k.pyramid(2), reg("front left")),
    ),
    _c(
        "reg-06",
        REG,
        "row of 4 down the right side, front to back.",
        one(k.row(4), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-07",
        REG,
        "The far side, away from the robot, is that the back? A tower of 4 there, please.",
        one(T(4), reg("back")),
    ),
    _c(
        "reg-08",
        REG,
        "Tower of 2 at x equals 0.55, y equals 0.40. In metres, he says.",
        one(T(2), k.near(0.55, 0.40, 0.02)),
    ),
    _c(
        "reg-09",
        REG,
        "Put the staircase, 3 steps, at the front right, where the crowd is standing.",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "reg-10",
        REG,
        "Subject: placement\n\nThe 3x3 slab, one layer, should go in the back right corner.\n\n"
        "Thanks,\nElif",
        one(k.block(3, 3, 1), reg("back right")),
    ),
    _c(
        "reg-11",
        REG,
        "tower of 4 in the front left corner and another tower of 4 in the back right corner.",
        k.structures(k.all_of(T(4), reg("front left")), k.all_of(T(4), reg("back right"))),
    ),
    _c(
        "reg-12",
        REG,
        "I'm told the robot is at the front. Could you make a row of 5 as close to it as you "
        "can, running left to right?",
        one(k.row(5), k.runs("y"), _max_x(0.35)),
    ),
    _c(
        "reg-13",
        REG,
        "Karl says: pyramid, 3 levels, on the left half of the table.",
        one(k.pyramid(3), _min_y(0.30)),
    ),
    _c(
        "reg-14",
        REG,
        "A 2x2 block, 3 high, at the back on the centre line, where the camera points.",
        one(k.block(2, 2, 3), reg("back"), _CENTRE_LINE),
    ),
    # ------------------------------------------------------------------ open
    _c("open-01", OPEN, "anything. just something small to test the gripper.", k.small),
    _c(
        "open-02",
        OPEN,
        "I don't know what to ask for yet. Could you build something simple so I can see how "
        "it works?",
        k.anything,
    ),
    _c(
        "open-03",
        OPEN,
        "He says build whatever you like, but use no more than 6 cubes.",
        k.all_of(k.anything, k.layout(_cubes(hi=6))),
    ),
    _c(
        "open-04",
        OPEN,
        "Surprise the crowd: build something at least 30 cm tall, any shape.",
        k.all_of(k.anything, k.layout(k.height(lo=6))),
    ),
    _c(
        "open-05",
        OPEN,
        "Hi,\n\nPlease build any structure you like on the right side of the table, for a "
        "camera test.\n\nThanks",
        k.all_of(k.anything, k.layout(reg("right"))),
    ),
    _c(
        "open-06",
        OPEN,
        "two things, any shape, not touching.",
        k.all_of(k.anything, _count(2)),
    ),
    _c(
        "open-07",
        OPEN,
        "Could you build something with a gap underneath that you could see through? Like an "
        "arch, maybe?",
        k.all_of(k.anything, k.layout(_ARCH)),
    ),
    _c(
        "open-08",
        OPEN,
        "Fatima says: any kind of staircase, whatever size you think is best.",
        one(k.staircase()),
    ),
    _c(
        "open-09",
        OPEN,
        "Build some towers of different heights for the kids to count. How many and how tall "
        "is up to you.",
        k.all_of(k.anything, _distinct_towers(2)),
    ),
    _c(
        "open-10",
        OPEN,
        "Hi,\n\nBuild whatever you think shows the cell off best, but keep it no taller than "
        "20 cm.\n\nThanks",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-11",
        OPEN,
        "some kind of wall, any size. back of the table.",
        one(k.wall(), reg("back")),
    ),
    _c(
        "open-12",
        OPEN,
        "Show them something symmetrical: any shape, as long as the left and the right match.",
        k.all_of(k.anything, k.layout(_mirror_lr)),
    ),
    # ------------------------------------------------------------------ bad input
    _c(
        "bad-01",
        BAD,
        "tower of 15 cubes. tall one tonight.",  # past the cell's 10 levels
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-02",
        BAD,
        "Could you build a tower of... sorry, I forgot the number. I'll go and ask my trainer.",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-03", BAD, "He says, um, hang on, he's walked off. Never mind.", k.honest()),
    _c(
        "bad-04",
        BAD,
        "Build a tower of 5 at x = 1.5 m so the people at the back can see it.",  # past x 0.80
        k.honest(one(T(5))),
    ),
    _c(
        "bad-05", BAD, "Subject: FW: cell\n\nSee the attached drawing.\n\nThanks,\nKate", k.honest()
    ),
    _c("bad-06", BAD, "same as last night, you know the one.", k.honest(k.anything)),
    _c(
        "bad-07",
        BAD,
        "Can the robot make me a coffee? Everyone told me to ask it.",
        k.honest(),
    ),
    _c(
        "bad-08",
        BAD,
        "He wants a wall 5 long and 3 high that's also only 1 high. I'm typing exactly what he "
        "said.",
        k.honest(one(k.any_of(k.wall(5, 3), k.row(5)))),
    ),
    _c(
        "bad-09",
        BAD,
        "Build a tower taller than the one next to it.",  # nothing next to it
        k.honest(k.anything),
    ),
    _c(
        "bad-10",
        BAD,
        "Hi,\n\nPlease build a pyramid with a base of 15 by 15 cubes.\n\nThanks",  # past 10
        k.honest(one(k.pyramid())),
    ),
    _c("bad-11", BAD, "tower of minus 3", k.honest(one(T(lo=1, hi=10)))),
    _c(
        "bad-12",
        BAD,
        "Can you build a circle? A properly round one, not a square.",
        k.honest(one(k.ring)),
    ),
    _c(
        "bad-13",
        BAD,
        "A tower of five, he says. No, he's holding up four fingers. I don't know, ask him.",
        k.honest(one(k.any_of(T(4), T(5)))),
    ),
    _c(
        "bad-14",
        BAD,
        "Build a wall 2 metres long across the front for the banner.",  # 40 cubes: past y's 10
        k.honest(one(k.any_of(k.wall(), k.row()))),
    ),
    _c(
        "bad-15",
        BAD,
        "Hi,\n\nPlease build the tower 3 high, 5 high.\n\nThanks",
        k.honest(one(k.any_of(T(3), T(5)))),
    ),
    _c("bad-16", BAD, "sdfghjkl", k.honest()),
    _c(
        "bad-17",
        BAD,
        "Could you please stack the cubes into a tower that reaches the ceiling?",
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c(
        "bad-18",
        BAD,
        "Build a 3 by 3 block out of real bricks, the big ones, for the display wall.",
        k.honest(k.anything),
    ),
]
