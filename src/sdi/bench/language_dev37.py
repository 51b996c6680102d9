"""A thirty-seventh held-out set for the language front end (dev37): five new everyday voices.

Written blind: without looking at the Specifier's grammar, the front end's code or tests, the
frozen test set, the cases of any other set (but dev27, the format example) or any benchmark
result, and worded apart from `language_dev` … `language_dev36` (no command shared with any
set, see tests). Nothing here was run through the system while it was written. The set is
deliberately mainstream: about 85 % of the commands are what an ordinary person at a robot
cell would really type — one or two structures with a size, a place, one relation or a
two-step sequence (build X, then put Y on top / take some off / make it taller), in plain,
varied English (build / make / put / stand / stack / lay / set up / give me / can you; the
place first or the size last; sizes as words or digits, "2 by 3", "2x2", cm, mm and metres;
articles dropped now and then; casual punctuation).

The brief suggested a shop assistant dressing a window, a parent typing for a child, a
logistics dispatcher, a chef, a phone user with autocorrect slips, a German or French
speaker, a museum curator and a gamer. All but the first had been used (parents by dev10 and
dev15; logistics and warehouse people by dev9, dev16, dev20 and dev33; a baker / pastry chef
by dev19; autocorrect by dev22 and dev27; German and French speakers by dev15, dev17, dev21
and dev24; a museum exhibit designer by dev10 and a museum volunteer by dev34; game players
and designers by dev10, dev17 and dev24), so the window dresser is kept and four other
ordinary people, none of them a voice of an earlier set, were chosen. Slips of the keyboard
("stakc", "o'clcok") happen in every voice and are read as meant.

* a shop assistant dressing the shop window with the cell: the table is "the window" (or "the
  window display"); "the glass" / "the front of the window" is the front edge, where
  passers-by look in from the robot's side, so "at / against / along the glass" is the front
  region, "the back of the window" the back region and "down the side of the window" the
  left or the right region; left and right are as a passer-by looking in sees them, which is
  the robot's left and right. A "stand" or "display stand" is a tower (one column); a
  "plinth" is a one-layer slab unless a thickness is given; a "display table" is four
  separate legs under one connected top; a "frame" is a ring (its size the outside). Stock,
  customers, the till, the boss and opening times are filler (a number in them is never a
  size). Steaming the dresses asks for no build (refusal only); a stand taller than the cell
  and cubes the cell does not stock (glass) are bad input;
* an estate agent who writes like a property listing: a "storey" is one cube level ("a
  three-storey tower" is three high); a "bungalow" or anything "single-storey" is one cube
  high; "detached" means a separate structure, not touching anything; a "semi-detached pair"
  (or "a pair of semis") is two equal columns set touching as one structure; "to the rear"
  is behind; "the road" is the front edge, so "fronting the road" is the front region and
  "set back from the road" is outside the front region; "the plot" is the table; a "loft
  conversion" adds one more full storey on the whole footprint; an "extension" is built
  against the side named, touching, as one structure; a "penthouse" stands on the top.
  Listing talk ("stunning opportunity", "no onward chain", references, prices, EPC and
  council-tax bands, viewing times) is filler. Booking a viewing asks for no build (refusal
  only); a house of 2,000 square feet and a negative number of storeys are bad input;
* a farmer who thinks in bales: a "bale" is a cube; a "stack" of N bales is a tower; a "wall
  of bales" is a wall; "a row of bales" is a row; a "pen" is a ring (its size the outside);
  a "gate" or "field gate" is two posts with a bar across the tops (a beam where a beam is
  named, a beam or a bar of cubes where it is not); "the near end" is the front region (the
  robot's side), "the far end" the back region and "the far edge" every part at x ≥ 0.60;
  "fork off" is take off; "a bale apart" / "a bale's width between" is one cube clear.
  Livestock, acres, the vet, the tractor and times are filler. Checking the sheep asks for
  no build (refusal only); a round bale (a cylinder) and a wall longer than the cell are bad
  input;
* a glider pilot from the weekend club who gives places by the clock face, as pilots do:
  looking at the table from the robot's side, 12 o'clock is straight ahead (away from the
  robot, +x), 3 o'clock the robot's right (-y), 6 o'clock the robot's side (-x) and 9 o'clock
  the robot's left (+y), counted round the middle of the table. "At 12 o'clock" / "dead
  ahead" is the back region with the footprint centre within 8 cm of y = 0.30; 1 and 2 o'clock
  are the back-right region; "at 3 o'clock" is the right region with the footprint centre
  within 8 cm of x = 0.45; 4 and 5 o'clock are the front-right region; 6 o'clock is the front
  region within 8 cm of y = 0.30; 7 and 8 o'clock the front-left region; 9 o'clock the left
  region within 8 cm of x = 0.45; 10 and 11 o'clock the back-left region. "Off its 3
  o'clock" / "at its 9 o'clock" is to that side of the structure named (3 right, 9 left, 12
  behind, 6 in front). A clock position is never a size or a time. The weather, flying hours
  and checks are filler. An hour that is not on the clock (14 o'clock), one tower in two
  places at once and one tower of two heights are bad input;
* a Yorkshire operator writing as they speak: "t'" (the), "o'" (of), "wi'" (with), "mek"
  (make), "tek" (take), "tha" (you), "'em" (them), "un" (one: "t'end un"), "nay" (no: a
  correction, "nay, at t'front" replaces the place), "nowt" (nothing), "owt" (anything),
  "summat" (something), "nobbut" (only), "ey up" (hello), "love", "our kid" (a brother),
  "parky" (cold) and "like" at the end of a sentence (filler). "Reet" is "right": "on
  t'reet" / "t'reet-hand side" is the right side, but before a place or a measure it only
  stresses it ("reet at t'front" is at the very front, "reet up to 30 cm" is up to 30 cm);
  "while" means "until" ("stack 'em while it's three high" stops at three). A message
  saying nowt is to be built today asks for no build (refusal only); a build "like" someone
  else's from before (nothing to go on) and a half-typed command are bad input.

About 85 % ordinary and 15 % harder: three to five structures, references ("the right-hand
one", "the middle one", "its 9 o'clock"), distributive phrases ("on each end", "in each
corner", "either side of it"), removals (the middle one of three, cubes off the ends of the
top course), corrections in the same message ("no, make that …", "actually, …") and unusable
input.

Same `Case` type and the same 11 phenomena as the other sets. Each predicate checks parameters
(heights, footprints in cubes, parts per level, number of separate structures, relations,
regions, order) and accepts every reasonable reading of vague wording, and nothing else.
Conventions (mostly dev27's):

* "next to", "beside", "side by side" with nothing said about touching is clear of it and no
  more than 25 cm away, or set against it so that the two are one structure (checked by its
  column heights); "right next to it" is at most 10 cm clear, or touching; "not touching",
  "detached", "apart" and "a gap" mean separate structures;
* "in front of", "behind", "to the rear of", "to the left / right of" and a clock side ("off
  its 3 o'clock") is the dominant direction between footprint centres (back = +x, front =
  -x, left = +y, right = -y), any distance when none is said; where nothing rules touching
  out, a tower so placed may also be set against the other as one structure, the tower's
  column then lying on that side of the rest;
* "N cubes apart" / "a cube's gap" / "a bale apart" / "a cube between 'em" is the clear gap
  (± 1.5 cm); a bare "10 cm apart" accepts the clear gap and the centre-to-centre reading;
  "parallel" is the same long axis, facing each other across the gap; "a row of N … a cube
  apart" / "in a line" is the shared `in_line` or `in_order` (along y for "left to right" and
  "along the front", along x for "front to back");
* "on top of" stands on it, anywhere on it unless "in the middle" / "dead centre" is said
  (then centred over it, ± 2–3 cm); a cube or a tower "on each end" of a row or wall stands
  on its end columns; "a stand of three in front of" a staircase may stand against it;
* a bridge's or gate's top is a beam (the shared `bridge`, overall height one more than the
  posts) where the command names a beam, and a beam or a bar of cubes where it does not;
  "just bales across the top — no beam" is a bar of cubes only; a table is four separate legs
  under one connected top of beams or of cubes (with "15 cm high overall" the top one layer
  on legs of two); "no beams" is cubes only;
* a ring's or pen's stated size is its outside; "in the middle of" a ring is inside its empty
  interior, clear of the ring, with the centres within 3 cm; "inside it, not touching the
  sides" is anywhere in the interior, clear of the ring; a gap "in the side" of a pen leaves
  one or two cubes out of that side only;
* a staircase's width is free unless given, and so is the way it climbs unless said; "take
  the top step off" accepts the top cube off (heights 1, 2, 3, 4, 4) or the whole last step
  off; a pyramid's step is free unless given, so a 3 × 3 base is 9-4-1 or 9-1, and with the
  top cube taken off 9-4 or the bare 3 × 3 layer; "take the top layer off" a wall lowers it
  by one;
* "something tall" is at least four cubes high; "any size", "your choice", "owt'll do" leave
  everything free but what is said; "single storey only" keeps the whole layout one cube
  high; "no more than N" bales counts cubes (beams not counted);
* regions are those of `sdi.bench.boxes.region_problem` on the footprint centre (left y >
  0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre within 8 cm of (0.45, 0.30)),
  with the voices' words above; "in the middle" of the glass (or of any edge) is that region
  with the footprint centre within 8 cm of the centre line (y = 0.30); "up against the left
  edge" is a footprint centre at y ≥ 0.45; "leave the front half empty" puts every part at
  x ≥ 0.50.

Bad input is honest only as an error (or a failure) or as a layout WITH notes naming the
assumption (`k.honest`); a request that is not a build at all, or that was cancelled, admits
only the refusal. Geometry comes only from `sdi.bench.boxes`, through the shared checks in
`language_checks` and the local checks below.

Cell: workspace x 0.20–0.80, y 0.05–0.55, z ≤ 0.50 m (at most 10 cube levels; 12 cubes front
to back, 10 left to right); cube 0.05 m, beam 0.15 × 0.05 × 0.05 m; left = +y, back = +x
(away from the robot at x = 0, y = 0.30); the front is the robot's side (small x).
"""

from __future__ import annotations

from sdi.bench import boxes as bx
from sdi.bench import language_checks as k
from sdi.bench.language_checks import Case

_L, _R, _F, _B = k.SIDES
REL, SEQ, NUM, DIM, NEG, TYP = k.REL, k.SEQ, k.NUM, k.DIM, k.NEG, k.TYP
WO, FIL, REG, OPEN, BAD = k.WO, k.FIL, k.REG, k.OPEN, k.BAD

_TALL = 4  # cubes: "something tall"
_MID = 0.08  # m: "in the middle" of an edge, and a clock hour on an axis


def _c(id_: str, phenomenon: str, text: str, accept: k.Pred) -> Case:
    return Case(id=f"dev37-{id_}", phenomenon=phenomenon, text=text, accept=accept)


# ---------------------------------------------------------------- local checks


def _clock(hour: int) -> k.Check:
    """The pilot's clock position, counted round the middle of the table as seen from the
    robot's side: 12 ahead (back, on the centre line ± 8 cm), 3 right and 9 left (level with
    the table's middle, x = 0.45 ± 8 cm), 6 the robot's side (front, centre line ± 8 cm),
    and the hours between the corners (1–2 back right, 4–5 front right, 7–8 front left,
    10–11 back left)."""
    if hour == 12:
        return k.all_of(k.region("back"), k.near(y=0.30, tol=_MID))
    if hour == 6:
        return k.all_of(k.region("front"), k.near(y=0.30, tol=_MID))
    if hour == 3:
        return k.all_of(k.region("right"), k.near(x=0.45, tol=_MID))
    if hour == 9:
        return k.all_of(k.region("left"), k.near(x=0.45, tol=_MID))
    corner = {1: "back right", 2: "back right", 4: "front right", 5: "front right"}
    corner |= {7: "front left", 8: "front left", 10: "back left", 11: "back left"}
    return k.region(corner[hour])


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
    than the posts; the posts `mouth` cubes apart clear when given."""
    c = k.all_of(k.bridge(posts, pillars=2), k.height(posts + 1))
    return c if mouth is None else k.all_of(c, k.leg_gap(mouth))


def _span(posts: int, mouth: int | None = None) -> k.Check:
    """A gate or bridge with no beam named: two posts `posts` high with a beam or a bar of
    cubes across the tops (`mouth` cubes apart clear when given)."""
    return k.any_of(_beam_bridge(posts, mouth), _bar_on_posts(posts, posts, mouth))


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
    """A table on `legs` legs `leg_h` high: the shared `canopy` one layer above the legs, a
    top of cubes, or the cell's beam roof."""
    return k.any_of(
        k.all_of(k.canopy(legs, leg_h, leg_h), k.height(leg_h + 1)),
        _roof_on(legs, leg_h),
        k.beam_roof(legs, leg_h),
    )


def _col_beside(h: int, rest: k.Check, side: str, col_check: k.Check | None = None) -> k.Check:
    """One structure: a full column of exactly `h` cubes on the table, set against the rest,
    which passes `rest`; the column lies to `side` of the rest (and passes `col_check`)."""

    def f(bs: k.Boxes) -> k.Reason:
        first: k.Reason = None
        for col in bx.columns(bs):
            if len(col) != h or k.tower(h)(col) is not None or col[0].lo[2] > bx.TOL:
                continue
            others = [b for b in bs if all(b is not c for c in col)]
            if not others:
                continue
            r = rest(others) or (col_check(col) if col_check else None)
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


def _missing_on(side: str) -> k.Check:
    """The footprint's border has at least one empty cell, and every empty border cell lies on
    its `side` edge (front = smallest x, back = largest x, right = smallest y, left = largest
    y)."""

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


T = k.tower
one = k.one
reg = k.region
_PEN4 = k.all_of(k.ring_of(1, (2, 2)), k.dims(4, 4))
_PEN5 = k.all_of(k.ring_of(1, (3, 3)), k.dims(5, 5))
_GATE_ANY = k.any_of(k.bridge(), _bar_on_posts())  # posts of any height, a beam or a bar
_MIDDLE_Y = k.near(y=0.30, tol=_MID)


CASES: list[Case] = [
    # ------------------------------------------------------------------ relation
    _c(
        "rel-01",
        REL,
        "For the window: a plinth 3 by 3, one layer, with a display stand of four stood in the "
        "middle of it.",
        one(k.on_top(T(4), k.block(3, 3, 1)), k.top_centred(0.02), k.levels(9, 1, 1, 1, 1)),
    ),
    _c(
        "rel-02",
        REL,
        "Semi-detached pair please: two towers of four storeys, touching.",
        one(k.cell_heights(4, 4)),
    ),
    _c(
        "rel-03",
        REL,
        "Stack five bales at the far end, then put a pen 4 by 4, one bale high, in front of it.",
        k.any_of(
            k.pair(_PEN4, k.all_of(T(5), reg("back")), k.on_side(_F)),
            one(_col_beside(5, _PEN4, _B, reg("back"))),
        ),
    ),
    _c(
        "rel-04",
        REL,
        "Tower of six at 12 o'clock, and a tower of two off its 3 o'clock with a cube's gap.",
        k.pair(T(2), k.all_of(T(6), _clock(12)), k.gap_of(1, _R)),
    ),
    _c(
        "rel-05",
        REL,
        "Ey up. Put a tower o' three on t'left, and another o' five right next to it.",
        k.any_of(
            k.pair(T(5), k.all_of(T(3), reg("left")), k.within(0.10)),
            one(k.cell_heights(3, 5), reg("left")),
        ),
    ),
    _c(
        "rel-06",
        REL,
        "Could you build a display table, four legs two high with a top, and stand a single cube "
        "on it dead centre?",
        one(_topped(_roofed(4, 2)), k.top_centred(0.02)),
    ),
    _c(
        "rel-07",
        REL,
        "Two-storey block, 3 by 2, with a detached tower of four to the rear.",
        k.pair(T(4), k.block(3, 2, 2), k.on_side(_B)),
    ),
    _c("rel-08", REL, "Field gate: two posts three bales high, bar across the top.", one(_span(3))),
    _c(
        "rel-09",
        REL,
        "Wall five long, two high, running across the table at 6 o'clock, and a tower of four "
        "behind it.",
        k.any_of(
            k.pair(T(4), k.all_of(k.wall(5, 2), k.runs("y"), _clock(6)), k.on_side(_B)),
            one(_col_beside(4, k.all_of(k.wall(5, 2), k.runs("y")), _B), reg("front")),
        ),
    ),
    _c(
        "rel-10",
        REL,
        "Lay a row o' four along t'front, wi' a tower o' two on each end of it.",
        one(k.profile(3, 1, 1, 3), k.flat, k.runs("y"), reg("front")),
    ),
    _c(
        "rel-11",
        REL,
        "Frame for the hats, 5 by 5 and one high, with a stand of three right in the middle of it.",
        k.pair(_PEN5, T(3), k.centred_in(0.03)),
    ),
    _c(
        "rel-12",
        REL,
        "A bungalow 3 by 3, and a three-storey tower on its left.",
        k.any_of(
            k.pair(T(3), k.block(3, 3, 1), k.on_side(_L)),
            one(_col_beside(3, k.block(3, 3, 1), _L)),
        ),
    ),
    _c(
        "rel-13",
        REL,
        "Two stacks of four bales with a bale's width between them, at the near end.",
        k.all_of(k.pair(T(4), T(4), k.gap_of(1)), k.layout(reg("front"))),
    ),
    _c(
        "rel-14",
        REL,
        "Pyramid of three levels in the centre, and a tower of five at its 9 o'clock.",
        k.any_of(
            k.pair(T(5), k.all_of(k.pyramid(3), reg("centre")), k.on_side(_L)),
            one(_col_beside(5, k.pyramid(3), _L)),
        ),
    ),
    _c(
        "rel-15",
        REL,
        "Two walls, five long an' three high, both runnin' front to back, a cube apart — "
        "parallel, like.",
        k.pair(
            k.all_of(k.wall(5, 3), k.runs("x")),
            k.all_of(k.wall(5, 3), k.runs("x")),
            k.parallel_gap(1),
        ),
    ),
    _c(
        "rel-16",
        REL,
        "Staircase of four for the handbags, climbing to the left, and a stand of three in "
        "front of it.",
        k.any_of(
            k.pair(T(3), k.all_of(k.staircase(4), k.rises(_L)), k.on_side(_F)),
            one(_col_beside(3, k.all_of(k.staircase(4), k.rises(_L)), _F)),
        ),
    ),
    _c(
        "rel-17",
        REL,
        "Block 3 by 3, two storeys, with a penthouse on top: a tower of two in the middle.",
        one(k.on_top(T(2), k.block(3, 3, 2)), k.levels(9, 9, 1, 1), k.top_centred(0.02)),
    ),
    _c(
        "rel-18",
        REL,
        "Pen, five bales by five, one high, and a stack of two inside it not touching the sides.",
        k.around(T(2), _PEN5),
    ),
    _c(
        "rel-19",
        REL,
        "Two rows of six running front to back, one at 3 o'clock and one at 9 o'clock.",
        k.structures(
            k.all_of(k.row(6), k.runs("x"), _clock(3)),
            k.all_of(k.row(6), k.runs("x"), _clock(9)),
        ),
    ),
    _c(
        "rel-20",
        REL,
        "Stick a 2 by 2 block, two high, in t'middle, an' a tower o' four either side of it, a "
        "cube's gap each side.",
        k.any_of(
            *[
                k.in_order(axis, T(4), k.all_of(k.block(2, 2, 2), reg("centre")), T(4), gaps=(1,))
                for axis in ("x", "y")
            ]
        ),
    ),
    # ------------------------------------------------------------------ sequence
    _c(
        "seq-01",
        SEQ,
        "Put a stand of six at the back of the window. Actually, make it four — six hides the "
        "mannequin.",
        one(T(4), reg("back")),
    ),
    _c(
        "seq-02",
        SEQ,
        "Build a single-storey block, 4 by 2. Then add a loft conversion.",
        one(k.block(4, 2, 2)),
    ),
    _c("seq-03", SEQ, "Stack six bales, then fork two off the top.", one(T(4))),
    _c(
        "seq-04",
        SEQ,
        "Tower of three at 10 o'clock. Then the same again at 2 o'clock.",
        k.structures(k.all_of(T(3), reg("back left")), k.all_of(T(3), reg("back right"))),
    ),
    _c(
        "seq-05",
        SEQ,
        "Mek a wall six long, two high. Then knock one end cube off t'top course.",
        one(k.profile(2, 2, 2, 2, 2, 1), k.flat),
    ),
    _c(
        "seq-06",
        SEQ,
        "Lay a plinth 4 by 3, one layer. Then a smaller plinth, 2 by 2, on top of it, centred.",
        one(k.on_top(k.block(2, 2, 1), k.block(4, 3, 1)), k.centred(), k.levels(12, 4)),
    ),
    _c(
        "seq-07",
        SEQ,
        "Build a three-storey tower. Then a second one just like it, detached, two cubes away.",
        k.pair(T(3), T(3), k.gap_of(2)),
    ),
    _c(
        "seq-08",
        SEQ,
        "Put up a wall of bales five long and three high at the far end, then take the top layer "
        "off.",
        one(k.wall(5, 2), reg("back")),
    ),
    _c(
        "seq-09",
        SEQ,
        "Staircase of five steps at 6 o'clock. Then take the top step off.",
        one(k.any_of(k.staircase(4), k.profile(1, 2, 3, 4, 4)), _clock(6)),
    ),
    _c(
        "seq-10",
        SEQ,
        "Three towers o' three in a row, two cubes apart. Then tek t'middle un away.",
        k.pair(T(3), T(3), k.gap_of(5)),
    ),
    _c(
        "seq-11",
        SEQ,
        "Row of five along the glass, then pop a cube on each end of it.",
        one(k.profile(2, 1, 1, 1, 2), k.flat, k.runs("y"), reg("front")),
    ),
    _c(
        "seq-12",
        SEQ,
        "Block 3 by 3, two storeys. Then a single-storey extension on its left side, also 3 by 3.",
        one(k.plan_heights("222111", "222111", "222111"), k.upper_side(_R, 1)),
    ),
    _c(
        "seq-13",
        SEQ,
        "Two stacks of four bales, two bales apart. Then fork the right-hand one down to two.",
        k.pair(T(2), T(4), k.gap_of(2, _R)),
    ),
    _c(
        "seq-14",
        SEQ,
        "Build a tower of seven at 1 o'clock — no, make that 11 o'clock.",
        one(T(7), reg("back left")),
    ),
    _c(
        "seq-15",
        SEQ,
        "Build a pyramid wi' a base o' three by three. Then tek t'top cube off.",
        one(k.any_of(k.pyramid_counts(9, 4), k.block(3, 3, 1))),
    ),
    _c(
        "seq-16",
        SEQ,
        "Frame 4 by 4, one high, for the scarves. Then build it up to two high.",
        one(k.ring_of(2, (2, 2)), k.dims(4, 4)),
    ),
    _c(
        "seq-17",
        SEQ,
        "Put up a two-storey wall six long across the back, then take the two end cubes off the "
        "top storey.",
        one(k.profile(1, 2, 2, 2, 2, 1), k.flat, k.runs("y"), reg("back")),
    ),
    _c(
        "seq-18",
        SEQ,
        "Two stacks of three, a bale apart. Then lay a bar across the tops to make a gate.",
        one(_span(3, 1)),
    ),
    _c(
        "seq-19",
        SEQ,
        "First a 2x2 block, three high, at 12 o'clock. Then a tower of two at 6 o'clock.",
        k.structures(k.all_of(k.block(2, 2, 3), _clock(12)), k.all_of(T(2), _clock(6))),
    ),
    _c(
        "seq-20",
        SEQ,
        "Build a tower o' four on t'reet. Nay, on t'left, sorry.",
        one(T(4), reg("left")),
    ),
    # ------------------------------------------------------------------ numbers
    _c(
        "num-01",
        NUM,
        "Three display stands in a row, heights 2, 4 and 6, a cube apart.",
        k.line(T(2), T(4), T(6), gaps=(1,)),
    ),
    _c("num-02", NUM, "Four-storey tower. Ref 2291, guide price 250k.", one(T(4))),
    _c(
        "num-03",
        NUM,
        "Forty ewes to see to after this, so quick: a stack of six bales.",
        one(T(6)),
    ),
    _c("num-04", NUM, "At 2 o'clock, a tower of three.", one(T(3), reg("back right"))),
    _c("num-05", NUM, "Nobbut three cubes in it — a row o' three, that's all.", one(k.row(3))),
    _c(
        "num-06",
        NUM,
        "Four single cubes along the front, left to right, a cube apart — the price tags go on "
        "them.",
        k.all_of(k.in_order("y", *[T(1)] * 4, gaps=(1,)), k.layout(reg("front"))),
    ),
    _c("num-07", NUM, "A block 2 by 3, three storeys.", one(k.block(2, 3, 3))),
    _c("num-08", NUM, "Ten bales laid flat, two rows of five.", one(k.block(2, 5, 1))),
    _c(
        "num-09",
        NUM,
        "Two towers of four, one at 3 o'clock and one at 9 o'clock.",
        k.structures(k.all_of(T(4), _clock(3)), k.all_of(T(4), _clock(9))),
    ),
    _c(
        "num-10",
        NUM,
        "A tower o' four an' one twice that, side by side.",
        k.any_of(k.pair(T(8), T(4), k.within(0.25)), one(k.cell_heights(8, 4))),
    ),
    _c("num-11", NUM, "Stack eight cubes into one tall stand.", one(T(8))),
    _c(
        "num-12",
        NUM,
        "Three detached towers: one storey, two storeys and three storeys, left to right.",
        k.in_order("y", T(1), T(2), T(3)),
    ),
    _c(
        "num-13",
        NUM,
        "Five stacks of two bales in a line, a bale's gap between each.",
        k.in_line(5, T(2), 1),
    ),
    _c("num-14", NUM, "Pyramid of four levels at 12 o'clock.", one(k.pyramid(4), _clock(12))),
    _c(
        "num-15",
        NUM,
        "Four towers, heights one to four, nowt touching.",
        k.structures(T(1), T(2), T(3), T(4)),
    ),
    _c("num-16", NUM, "Staircase of six for the shoe display.", one(k.staircase(6))),
    _c(
        "num-17",
        NUM,
        "A ring 6 by 6 outside, one storey, like a courtyard.",
        one(k.ring_of(1, (4, 4)), k.dims(6, 6)),
    ),
    _c(
        "num-18",
        NUM,
        "A couple of bale walls, each four long and two high, a bale apart.",
        k.pair(k.wall(4, 2), k.wall(4, 2), k.gap_of(1)),
    ),
    _c(
        "num-19",
        NUM,
        "Three towers of two: at 10, 12 and 2 o'clock.",
        k.structures(
            k.all_of(T(2), reg("back left")),
            k.all_of(T(2), _clock(12)),
            k.all_of(T(2), reg("back right")),
        ),
    ),
    _c(
        "num-20",
        NUM,
        "Keep stackin' cubes on t'left while it's six high, then stop.",
        one(T(6), reg("left")),
    ),
    # ------------------------------------------------------------------ dimensions
    _c(
        "dim-01",
        DIM,
        "Display stand 35 cm tall, back right of the window.",
        one(T(7), reg("back right")),
    ),
    _c("dim-02", DIM, "A block 150 mm by 100 mm, 15 cm high.", one(k.block(3, 2, 3))),
    _c("dim-03", DIM, "Wall of bales, 40 cm long and 10 cm high.", one(k.wall(8, 2))),
    _c("dim-04", DIM, "Tower 0.2 m tall at 9 o'clock.", one(T(4), _clock(9))),
    _c("dim-05", DIM, "Slab, 25 cm by 20, one layer, if tha can.", one(k.block(5, 4, 1))),
    _c("dim-06", DIM, "A plinth 30 by 20 cm, one cube thick.", one(k.block(6, 4, 1))),
    _c(
        "dim-07",
        DIM,
        "Each storey's 5 cm, so I want a tower 30 cm high.",
        one(T(6)),
    ),
    _c(
        "dim-08",
        DIM,
        "Pen 25 cm square, outside measure, 10 cm high.",
        one(k.ring_of(2, (3, 3)), k.dims(5, 5)),
    ),
    _c(
        "dim-09",
        DIM,
        "Row, 300 mm long, running front to back at 3 o'clock.",
        one(k.row(6), k.runs("x"), _clock(3)),
    ),
    _c(
        "dim-10",
        DIM,
        "A staircase reet up to 25 centimetres, 5 cm a step.",
        one(k.staircase(5)),
    ),
    _c(
        "dim-11",
        DIM,
        "Two stands, 15 cm and 25 cm tall, 10 cm apart.",
        k.pair(T(3), T(5), k.gaps(1, 2)),
    ),
    _c(
        "dim-12",
        DIM,
        "Block half a metre long, 10 cm wide and 5 cm high.",
        one(k.block(10, 2, 1)),
    ),
    _c(
        "dim-13",
        DIM,
        "Gate with posts 15 cm high and a 15 cm beam across them.",
        one(_beam_bridge(3)),
    ),
    _c(
        "dim-14",
        DIM,
        "Block 10 by 10 cm, 20 cm high, at 6 o'clock.",
        one(k.block(2, 2, 4), _clock(6)),
    ),
    _c("dim-15", DIM, "Tower, 45 cm, in t'middle.", one(T(9), reg("centre"))),
    _c(
        "dim-16",
        DIM,
        "Frame 20 cm by 30 cm outside, 5 cm high.",
        one(k.ring_of(1, (2, 4)), k.dims(4, 6)),
    ),
    _c(
        "dim-17",
        DIM,
        "A table 15 cm high overall: legs of 10 cm and a top.",
        one(_roofed(4, 2), k.height(3)),
    ),
    _c(
        "dim-18",
        DIM,
        "Two stacks 20 cm tall, 5 cm of gap between, and a 15 cm beam across them.",
        one(_beam_bridge(4, 1)),
    ),
    _c(
        "dim-19",
        DIM,
        "At 11 o'clock, a wall 25 cm long and 15 cm high.",
        one(k.wall(5, 3), reg("back left")),
    ),
    _c("dim-20", DIM, "A block, 15 by 15 centimetres an' 10 high.", one(k.block(3, 3, 2))),
    # ------------------------------------------------------------------ negation
    _c(
        "neg-01",
        NEG,
        "A stand of five, but not in the middle of the window.",
        one(T(5), k.not_(reg("centre"), "in the centre")),
    ),
    _c(
        "neg-02",
        NEG,
        "Two towers of three storeys, detached — they mustn't touch.",
        k.each(2, T(3)),
    ),
    _c(
        "neg-03",
        NEG,
        "Pen 4 by 4, one high, but leave a gap in the far side for the gate.",
        one(
            k.dims(4, 4),
            k.height(1),
            k.parts(lo=10, hi=11),
            k.not_(k.ring, "closed"),
            _missing_on(_B),
        ),
    ),
    _c(
        "neg-04",
        NEG,
        "Tower of four anywhere but 12 o'clock.",
        one(T(4), k.not_(_clock(12), "at 12 o'clock")),
    ),
    _c(
        "neg-05",
        NEG,
        "A pyramid, three levels, nowt on top of it an' no beams.",
        one(k.pyramid(3), k.only_cubes),
    ),
    _c(
        "neg-06",
        NEG,
        "Row of six, not along the glass — down the side of the window, front to back.",
        one(k.row(6), k.runs("x"), k.any_of(reg("left"), reg("right"))),
    ),
    _c(
        "neg-07",
        NEG,
        "A 2 by 2 block, three storeys, not on the left.",
        one(k.block(2, 2, 3), k.not_(reg("left"), "on the left")),
    ),
    _c(
        "neg-08",
        NEG,
        "Gate with posts of two, just bales across the top — no beam.",
        one(_bar_on_posts(2, 2), k.only_cubes),
    ),
    _c(
        "neg-09",
        NEG,
        "Staircase of four, not climbing towards 6 o'clock.",
        one(k.staircase(4), k.not_(k.rises(_F), "climbs towards the robot")),
    ),
    _c(
        "neg-10",
        NEG,
        "A table, four legs o' two, but nay beams — cubes for t'top.",
        one(_roof_on(4, 2), k.only_cubes),
    ),
    _c(
        "neg-11",
        NEG,
        "Plinth 5 by 3, one layer, with the middle three cubes left out — that's where the vase "
        "goes.",
        one(k.ring_of(1, (1, 3)), k.dims(3, 5), k.parts(12)),
    ),
    _c(
        "neg-12",
        NEG,
        "Single-storey block 4 by 3, and don't put it anywhere near the road.",
        one(k.block(4, 3, 1), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "neg-13",
        NEG,
        "Two stacks of five, not side by side — one at the near end, one at the far end.",
        k.structures(k.all_of(T(5), reg("front")), k.all_of(T(5), reg("back"))),
    ),
    _c(
        "neg-14",
        NEG,
        "Wall five long, two high, at 9 o'clock, not running left to right.",
        one(k.wall(5, 2), k.runs("x"), _clock(9)),
    ),
    _c(
        "neg-15",
        NEG,
        "Tower o' six, an' I don't want it on t'reet.",
        one(T(6), k.not_(reg("right"), "on the right")),
    ),
    # ------------------------------------------------------------------ typo
    _c(
        "typo-01",
        TYP,
        "Dispaly stand of fuor, front left of the widnow.",
        one(T(4), reg("front left")),
    ),
    _c("typo-02", TYP, "A thre-storey towr, detahced.", one(T(3))),
    _c("typo-03", TYP, "Stakc of six baels at the far ned.", one(T(6), reg("back"))),
    _c("typo-04", TYP, "Towre of five at 3 o'clcok.", one(T(5), _clock(3))),
    _c("typo-05", TYP, "Mek a wal six lnog, two hihg.", one(k.wall(6, 2))),
    _c(
        "typo-06",
        TYP,
        "Plinht 4 by 4, one layr, in the centr.",
        one(k.block(4, 4, 1), reg("centre")),
    ),
    _c(
        "typo-07",
        TYP,
        "Bunaglow 3 by 2, one storye, on the lfet.",
        one(k.block(3, 2, 1), reg("left")),
    ),
    _c("typo-08", TYP, "Pne 5 by 5, one bael high.", one(_PEN5)),
    _c("typo-09", TYP, "Pyarmid of three levles at 6 o'clock.", one(k.pyramid(3), _clock(6))),
    _c(
        "typo-10",
        TYP,
        "Staircsae o' four steps, climbin' to t'bakc.",
        one(k.staircase(4), k.rises(_B)),
    ),
    _c("typo-11", TYP, "Two stnads of three, a cueb apart.", k.pair(T(3), T(3), k.gap_of(1))),
    _c(
        "typo-12",
        TYP,
        "Semi-detahced pair of towers, five storeys each.",
        one(k.cell_heights(5, 5)),
    ),
    _c(
        "typo-13",
        TYP,
        "Rwo of five bales alnog the near end.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "typo-14",
        TYP,
        "Blcok 2 by 3, two high, at 10 o'cock.",
        one(k.block(2, 3, 2), reg("back left")),
    ),
    # ------------------------------------------------------------------ word order
    _c("wo-01", WO, "Back left of the window, a stand of three.", one(T(3), reg("back left"))),
    _c(
        "wo-02",
        WO,
        "Three storeys, 2x2, on the right — that's the block.",
        one(k.block(2, 2, 3), reg("right")),
    ),
    _c("wo-03", WO, "Six high, the stack, at the far end.", one(T(6), reg("back"))),
    _c(
        "wo-04",
        WO,
        "At 8 o'clock: row of four, left to right.",
        one(k.row(4), k.runs("y"), reg("front left")),
    ),
    _c(
        "wo-05",
        WO,
        "On t'left, a wall, four long and three high, mek it.",
        one(k.wall(4, 3), reg("left")),
    ),
    _c(
        "wo-06",
        WO,
        "Four steps, climbing to the right — that's the staircase for the boots.",
        one(k.staircase(4), k.rises(_R)),
    ),
    _c(
        "wo-07",
        WO,
        "To the rear of a two-storey block 3 by 2, a detached tower of five.",
        k.pair(T(5), k.block(3, 2, 2), k.on_side(_B)),
    ),
    _c(
        "wo-08",
        WO,
        "Across the tops of two three-bale stacks, a beam.",
        one(_beam_bridge(3)),
    ),
    _c("wo-09", WO, "5 high, 12 o'clock, tower.", one(T(5), _clock(12))),
    _c(
        "wo-10",
        WO,
        "Five long, one high, along t'front — a row, like.",
        one(k.row(5), k.runs("y"), reg("front")),
    ),
    _c(
        "wo-11",
        WO,
        "In the middle of a 5 by 5 frame, one high, a stand of two.",
        k.pair(_PEN5, T(2), k.centred_in(0.03)),
    ),
    _c(
        "wo-12",
        WO,
        "One storey, 4 by 4 outside, hollow in the middle — that's the courtyard I'm after.",
        one(k.ring_of(1, (2, 2)), k.dims(4, 4)),
    ),
    _c("wo-13", WO, "Three levels, the pyramid, near end.", one(k.pyramid(3), reg("front"))),
    _c(
        "wo-14",
        WO,
        "Behind t'tower o' two, a tower o' four, a cube between 'em.",
        k.pair(T(4), T(2), k.gap_of(1, _B)),
    ),
    # ------------------------------------------------------------------ filler
    _c(
        "fil-01",
        FIL,
        "Morning! New season's stock came in and the window looks bare. Can you do a stand of "
        "four in the centre? Thanks!",
        one(T(4), reg("centre")),
    ),
    _c(
        "fil-02",
        FIL,
        "Stunning opportunity, early viewing advised, no onward chain. Two-storey block, 3 by 3.",
        one(k.block(3, 3, 2)),
    ),
    _c(
        "fil-03",
        FIL,
        "Lambing's nearly done and the tractor's playing up again. Anyway — a row of six bales, "
        "please.",
        one(k.row(6)),
    ),
    _c(
        "fil-04",
        FIL,
        "Good soaring weather today, thermals everywhere. Right: staircase of three at 4 o'clock.",
        one(k.staircase(3), reg("front right")),
    ),
    _c(
        "fil-05",
        FIL,
        "Ey up, love, kettle's on and our kid's late again. Mek us a tower o' five, ta.",
        one(T(5)),
    ),
    _c(
        "fil-06",
        FIL,
        "Boss wants the window done before we open at nine, so: a 2 by 2 plinth, two high, front "
        "right.",
        one(k.block(2, 2, 2), reg("front right")),
    ),
    _c(
        "fil-07",
        FIL,
        "Property ref 7781, EPC band C, council tax band D: a three-storey tower at the back.",
        one(T(3), reg("back")),
    ),
    _c(
        "fil-08",
        FIL,
        "Forty acres to cut by Friday, so I'll be brief. Build us a pen, 4 by 4, one bale high.",
        one(_PEN4),
    ),
    _c(
        "fil-09",
        FIL,
        "Tower of six, please. Flew three hours on Sunday, best day of the year so far.",
        one(T(6)),
    ),
    _c(
        "fil-10",
        FIL,
        "Eeh, it's reet parky out this morning. Wall, five long and two high, if tha can.",
        one(k.wall(5, 2)),
    ),
    _c(
        "fil-11",
        FIL,
        "Sorry, had a customer at the till — right, a staircase of five for the window, thanks.",
        one(k.staircase(5)),
    ),
    _c(
        "fil-12",
        FIL,
        "Viewings from 10 am Saturday, offers over 300. A bridge: posts two storeys, beam across.",
        one(_beam_bridge(2)),
    ),
    _c(
        "fil-13",
        FIL,
        "Vet's coming at 2 for the heifers, so quick as you can: two stacks of three bales, a bale "
        "apart.",
        k.pair(T(3), T(3), k.gap_of(1)),
    ),
    _c(
        "fil-14",
        FIL,
        "Pre-flight checks done, canopy closed. Block 3 by 2, one high, at 12 o'clock.",
        one(k.block(3, 2, 1), _clock(12)),
    ),
    # ------------------------------------------------------------------ region
    _c(
        "reg-01",
        REG,
        "A stand of three right up against the glass, in the middle.",
        one(T(3), reg("front"), _MIDDLE_Y),
    ),
    _c(
        "reg-02",
        REG,
        "A bungalow 3 by 3, set back from the road.",
        one(k.block(3, 3, 1), k.not_(reg("front"), "at the front")),
    ),
    _c(
        "reg-03",
        REG,
        "Stack of four at the near end, left-hand side.",
        one(T(4), reg("front left")),
    ),
    _c("reg-04", REG, "Tower of three at 5 o'clock.", one(T(3), reg("front right"))),
    _c(
        "reg-05",
        REG,
        "Slab, 3 by 3, one high, reet at t'back.",
        one(k.block(3, 3, 1), reg("back")),
    ),
    _c(
        "reg-06",
        REG,
        "Plinth 2 by 3, one layer, back right corner of the window.",
        one(k.block(2, 3, 1), reg("back right")),
    ),
    _c(
        "reg-07",
        REG,
        "A two-storey block 2 by 2 fronting the road, on the left.",
        one(k.block(2, 2, 2), reg("front left")),
    ),
    _c(
        "reg-08",
        REG,
        "Row of bales along the far edge, six long.",
        one(k.row(6), k.runs("y"), k.min_x(0.60)),
    ),
    _c("reg-09", REG, "Pyramid of two levels at 7 o'clock.", one(k.pyramid(2), reg("front left"))),
    _c(
        "reg-10",
        REG,
        "Row o' five down t'reet-hand side, front to back.",
        one(k.row(5), k.runs("x"), reg("right")),
    ),
    _c(
        "reg-11",
        REG,
        "Two stands of four, one in each back corner of the window.",
        k.structures(k.all_of(T(4), reg("back left")), k.all_of(T(4), reg("back right"))),
    ),
    _c("reg-12", REG, "Tower of five, centre of the plot.", one(T(5), reg("centre"))),
    _c(
        "reg-13",
        REG,
        "Pen 4 by 4, one high, in the middle of the table.",
        one(_PEN4, reg("centre")),
    ),
    _c(
        "reg-14",
        REG,
        "Row of five, left to right, dead ahead at 12 o'clock.",
        one(k.row(5), k.runs("y"), _clock(12)),
    ),
    _c(
        "reg-15",
        REG,
        "Tower o' three reet up against t'left edge.",
        one(T(3), k.centre_y_min(0.45)),
    ),
    # ------------------------------------------------------------------ open
    _c(
        "open-01",
        OPEN,
        "Something eye-catching for the window, your choice, cubes only.",
        k.all_of(k.anything, k.layout(k.only_cubes)),
    ),
    _c(
        "open-02",
        OPEN,
        "Any property you like, but no more than two storeys.",
        k.all_of(k.anything, k.layout(k.low(2))),
    ),
    _c(
        "open-03",
        OPEN,
        "Stack the bales however you like, just use no more than ten.",
        k.all_of(k.anything, k.layout(_cubes(hi=10))),
    ),
    _c(
        "open-04",
        OPEN,
        "Build anything you like at 12 o'clock.",
        k.all_of(k.anything, k.layout(_clock(12))),
    ),
    _c("open-05", OPEN, "Mek us summat nice, owt'll do.", k.anything),
    _c(
        "open-06",
        OPEN,
        "A little display, whatever you think works, on the left of the window.",
        k.all_of(k.anything, k.layout(reg("left"))),
    ),
    _c(
        "open-07",
        OPEN,
        "Any building you fancy, single storey only.",
        k.all_of(k.anything, k.layout(k.height(1))),
    ),
    _c(
        "open-08",
        OPEN,
        "Build a gate, any size you like.",
        k.all_of(k.anything, k.some(_GATE_ANY)),
    ),
    _c(
        "open-09",
        OPEN,
        "Two things of your choice, one at 3 o'clock and one at 9.",
        k.all_of(k.anything, k.structures(_clock(3), _clock(9))),
    ),
    _c(
        "open-10",
        OPEN,
        "Summat tall, owt tha likes, on t'reet.",
        k.all_of(k.anything, k.layout(k.all_of(reg("right"), k.height(lo=_TALL)))),
    ),
    _c(
        "open-11",
        OPEN,
        "Surprise me with a centrepiece, nothing over 20 cm tall.",
        k.all_of(k.anything, k.layout(k.low(4))),
    ),
    _c(
        "open-12",
        OPEN,
        "Any layout you like, but leave the front half of the plot empty.",
        k.all_of(k.anything, k.layout(k.min_x(0.50))),
    ),
    # ------------------------------------------------------------------ bad input
    _c("bad-01", BAD, "Can you steam the dresses for the window before lunch?", k.honest()),
    _c(
        "bad-02",
        BAD,
        "A display stand two metres tall for the mannequin.",  # 40 cubes: past the cell
        k.honest(one(T(lo=1, hi=10))),
    ),
    _c("bad-03", BAD, "Book a viewing for Tuesday at 4, please.", k.honest()),
    _c(
        "bad-04",
        BAD,
        "A detached house, 2,000 square feet, three storeys.",  # far past the cell
        k.honest(k.anything),
    ),
    _c(
        "bad-05",
        BAD,
        "A round bale, a proper cylinder, 10 cm across.",
        k.honest(k.anything),
    ),
    _c("bad-06", BAD, "Go and check the sheep in the top field.", k.honest()),
    _c("bad-07", BAD, "Tower of four at 14 o'clock.", k.honest(one(T(4)))),
    _c(
        "bad-08",
        BAD,
        "One tower of three, at 3 o'clock and at 9 o'clock both.",
        k.honest(k.anything),
    ),
    _c("bad-09", BAD, "Nowt today, ta. Don't build owt.", k.honest()),
    _c("bad-10", BAD, "Mek it like our kid's one from last week.", k.honest(k.anything)),
    _c("bad-11", BAD, "qwpoeiruty zmxn", k.honest()),
    _c("bad-12", BAD, "A tower of minus two storeys.", k.honest(k.anything)),
    _c(
        "bad-13",
        BAD,
        "A wall of bales twenty long, two high.",  # 20 cubes: past the cell's 12
        k.honest(k.anything),
    ),
    _c(
        "bad-14",
        BAD,
        "A tower at 12 o'clock that is both two and six high.",
        k.honest(one(k.any_of(T(2), T(6)))),
    ),
    _c(
        "bad-15",
        BAD,
        "Use the glass cubes for the stand this time, four of them.",  # not stocked
        k.honest(one(T(4))),
    ),
    _c("bad-16", BAD, "Mek a wall o'", k.honest(k.anything)),
]
