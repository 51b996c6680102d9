"""The 70-command evaluation suite, groups A–E as in the paper's experimental setup.

A (13) explicit structures with dimensions, 3–15 parts; B (15) vague or under-specified
requests; C (12) enclosed and dense structures; D (18) 3-D packing and open-ended requests,
compounds, positions and regions; E (12) scale stress, 13–25 parts each.

Commands are written the way an operator would type them. Each carries an acceptance predicate
built from `sdi.bench.signatures` — part count, levels, the shape's signature, and the position
or region when the command states one — that returns None for an acceptable layout or a short
reason. Predicates accept every reasonable reading of a vague command and nothing else.

The judge is independent of the system it judges: `sdi.bench.signatures` computes every part's
world box from the raw pose itself, and named regions ("back left", "centre") are fixed numbers
written there (see its module docstring), not the composer's or the cell's region table. A
`Layout` is only read for its parts' raw poses.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable
from dataclasses import dataclass

from sdi.bench import signatures as sg
from sdi.model.layout import Layout

Accept = Callable[[Layout], str | None]
"""An acceptance predicate: None when the layout does what the command asked, else why not."""

GROUPS: tuple[str, ...] = ("A", "B", "C", "D", "E")


@dataclass(frozen=True)
class BenchCommand:
    """One evaluation command: its id, difficulty group, text and acceptance predicate."""

    id: str
    group: str
    text: str
    accept: Accept


# ---------------------------------------------------------------------------------------------
# Predicate building blocks


def _range(lo: int, hi: int | None) -> str:
    if hi is None:
        return f"≥ {lo}"
    return str(lo) if lo == hi else f"{lo}–{hi}"


def all_of(*checks: Accept) -> Accept:
    """Every check must pass; the first failure's reason is reported."""

    def run(layout: Layout) -> str | None:
        for check in checks:
            reason = check(layout)
            if reason is not None:
                return reason
        return None

    return run


def any_of(*checks: Accept) -> Accept:
    """At least one check must pass (alternative readings of a vague command)."""

    def run(layout: Layout) -> str | None:
        reasons = []
        for check in checks:
            reason = check(layout)
            if reason is None:
                return None
            reasons.append(reason)
        return " / ".join(reasons)

    return run


def parts(lo: int, hi: int | None = -1) -> Accept:
    """Part count in [lo, hi]; ``hi=-1`` (default) means exactly `lo`, None means no upper end."""
    top = lo if hi == -1 else hi

    def run(layout: Layout) -> str | None:
        n = len(layout)
        if n < lo or (top is not None and n > top):
            return f"{n} parts, expected {_range(lo, top)}"
        return None

    return run


def parts_in(*allowed: int) -> Accept:
    """Part count is one of `allowed`."""

    def run(layout: Layout) -> str | None:
        if len(layout) not in allowed:
            return f"{len(layout)} parts, expected one of {sorted(allowed)}"
        return None

    return run


def n_levels(lo: int, hi: int | None = -1) -> Accept:
    """Number of occupied levels in [lo, hi] (same conventions as `parts`)."""
    top = lo if hi == -1 else hi

    def run(layout: Layout) -> str | None:
        n = sg.levels(layout)
        if n < lo or (top is not None and n > top):
            return f"{n} levels, expected {_range(lo, top)}"
        return None

    return run


def shape(name: str, test: Callable[[Layout], bool]) -> Accept:
    """The layout has the signature `test`; `name` says what was expected."""

    def run(layout: Layout) -> str | None:
        return None if test(layout) else f"not {name}"

    return run


def footprint(short: int, long: int | None = None) -> Accept:
    """Footprint bounding box of `short` × `long` cells, either way round."""
    want = (short, short if long is None else long)
    want = (min(want), max(want))

    def run(layout: Layout) -> str | None:
        got = sg.footprint_dims(layout)
        if got == want:
            return None
        return f"footprint {got[0]}×{got[1]} cells, expected {want[0]}×{want[1]}"

    return run


def axis(name: str) -> Accept:
    """The footprint's long side runs along world `name` (``x`` or ``y``)."""

    def run(layout: Layout) -> str | None:
        got = sg.main_axis(layout)
        return None if got == name else f"long side along {got or 'neither axis'}, expected {name}"

    return run


def steps(lo: int, hi: int | None = -1) -> Accept:
    """A staircase with a step count in [lo, hi]."""
    top = lo if hi == -1 else hi

    def run(layout: Layout) -> str | None:
        n = sg.staircase_steps(layout)
        if n is None:
            return "not a staircase"
        if n < lo or (top is not None and n > top):
            return f"{n} steps, expected {_range(lo, top)}"
        return None

    return run


def tower(lo: int, hi: int | None = -1) -> Accept:
    """A tower whose height in levels is in [lo, hi]."""
    return all_of(shape("a tower", lambda lay: sg.is_tower(lay, min_height=1)), n_levels(lo, hi))


def at(x: float | None = None, y: float | None = None, tol: float = 0.03) -> Accept:
    """Footprint centre within `tol` m of the stated x and/or y, m."""

    def run(layout: Layout) -> str | None:
        cx, cy = sg.footprint_centre(layout)
        if x is not None and abs(cx - x) > tol:
            return f"centre x = {cx:.3f} m, asked for {x:g} m"
        if y is not None and abs(cy - y) > tol:
            return f"centre y = {cy:.3f} m, asked for {y:g} m"
        return None

    return run


def region(name: str) -> Accept:
    """Footprint centre inside the named region, judged on the fixed numbers of
    `signatures.REGION_TESTS` (left y > 0.33, right y < 0.27, front x < 0.42, back x > 0.48,
    centre within 0.08 m of (0.45, 0.30); several words must all hold)."""
    sg.region_words(name)  # an unknown region word is a mistake in the suite: fail at import

    def run(layout: Layout) -> str | None:
        reason = sg.region_problem(layout, name)
        return None if reason is None else f"{name} region: {reason}"

    return run


def single() -> Accept:
    """One connected structure."""

    def run(layout: Layout) -> str | None:
        n = len(sg.separate_structures(layout))
        return None if n == 1 else f"{n} separate structures, expected 1"

    return run


def structures(*each: Accept, max_gap: float | None = None) -> Accept:
    """Exactly ``len(each)`` separate structures, matched one-to-one to the checks.

    With `max_gap`, every structure must stand within `max_gap` m of another one ("next to").
    """

    def run(layout: Layout) -> str | None:
        comps = sg.separate_structures(layout)
        if len(comps) != len(each):
            return f"{len(comps)} separate structures, expected {len(each)}"
        if max_gap is not None and len(comps) > 1:
            for a, comp in enumerate(comps):
                near = min(sg.gap_between(comp, o) for b, o in enumerate(comps) if b != a)
                if near > max_gap + 1e-9:
                    return f"structures {near:.3f} m apart, expected next to each other"
        first: str | None = None
        for order in itertools.permutations(comps):
            reasons = [check(comp) for check, comp in zip(each, order, strict=True)]
            if all(r is None for r in reasons):
                return None
            if first is None:
                first = next(r for r in reasons if r is not None)
        return f"structures do not match ({first})"

    return run


def wallish(min_length: int = 2, min_height: int = 2) -> Accept:
    return shape("a wall", lambda lay: sg.is_wall(lay, min_length, min_height))


def spans(lo: int = 1) -> Accept:
    """At least `lo` parts bridging a gap with supports on both sides."""

    def run(layout: Layout) -> str | None:
        n = len(sg.span_parts(layout))
        return None if n >= lo else f"{n} spanning parts, expected ≥ {lo}"

    return run


def feet(lo: int, hi: int | None = -1) -> Accept:
    """Number of separate footings on the table in [lo, hi]."""
    top = lo if hi == -1 else hi

    def run(layout: Layout) -> str | None:
        n = len(sg.ground_supports(layout))
        if n < lo or (top is not None and n > top):
            return f"{n} separate footings on the table, expected {_range(lo, top)}"
        return None

    return run


def compact(min_fill: float, max_side: int | None = None) -> Accept:
    """Tightly packed: fills ≥ `min_fill` of its bounding box, no side over `max_side` cells,
    and not a flat line."""

    def run(layout: Layout) -> str | None:
        fill = sg.compactness(layout)
        if fill < min_fill:
            return f"fills {fill:.0%} of its bounding box, expected ≥ {min_fill:.0%}"
        dims = sg.bbox_cells(layout)
        if max_side is not None and max(dims) > max_side:
            return f"bounding box {dims} cells, expected no side over {max_side}"
        if sorted(dims)[1] < 2:
            return "a line, not a packed cluster"
        return None

    return run


def hollow(cells: int | None = None, level: int = 0) -> Accept:
    """The given level closes a ring around empty cells (exactly `cells` of them if given)."""

    def run(layout: Layout) -> str | None:
        inside = sg.enclosed_cells(layout, level)
        if not inside:
            return f"level {level} encloses no empty cell"
        if cells is not None and len(inside) != cells:
            return f"encloses {len(inside)} empty cells, expected {cells}"
        return None

    return run


def every_level_hollow() -> Accept:
    def run(layout: Layout) -> str | None:
        n, closed = sg.levels(layout), sg.enclosure_levels(layout)
        return None if n == closed else f"only {closed} of {n} levels are closed rings"

    return run


def corners_taller_by(extra: int) -> Accept:
    """Castle corners rise exactly `extra` levels above the highest other wall column."""

    def run(layout: Layout) -> str | None:
        tops = sg.column_tops(layout)
        i0, i1 = min(i for i, _ in tops), max(i for i, _ in tops)
        j0, j1 = min(j for _, j in tops), max(j for _, j in tops)
        corners = {(i0, j0), (i0, j1), (i1, j0), (i1, j1)}
        rest = [h for c, h in tops.items() if c not in corners]
        got = {tops.get(c, 0) for c in corners}
        want = max(rest, default=0) + extra
        return None if got == {want} else f"corner heights {sorted(got)}, expected {want}"

    return run


def pyramid(dims: int | None = None) -> Accept:
    label = {None: "a pyramid", 2: "a flat (2-D) pyramid", 3: "a square-based (3-D) pyramid"}
    return shape(label[dims], lambda lay: sg.is_pyramid(lay, dims=dims))


def grid() -> Accept:
    return shape("a filled one-level grid", sg.is_grid)


def block() -> Accept:
    return shape("a solid block", sg.is_block)


def enclosure() -> Accept:
    return shape("an enclosure", sg.is_enclosure)


def tower_heights(*heights: int) -> Accept:
    """Separate towers with exactly these heights (any order)."""
    return structures(*(tower(h) for h in heights))


# ---------------------------------------------------------------------------------------------
# The commands

_A: list[tuple[str, Accept]] = [
    ("Build a 3-cube tower at x = 0.4 m.", all_of(tower(3), parts(3), at(x=0.40))),
    ("Stack five cubes on top of each other.", all_of(tower(5), parts(5))),
    (
        "Place a row of 6 cubes along the x axis.",
        all_of(shape("a row", sg.is_row), parts(6), axis("x")),
    ),
    ("Make a 3 by 3 grid of cubes.", all_of(grid(), footprint(3), parts(9))),
    (
        "Build a wall 4 cubes long and 2 cubes high.",
        all_of(wallish(), footprint(1, 4), n_levels(2), parts(8)),
    ),
    ("Build a staircase with 4 steps.", all_of(steps(4), parts(10, 20))),
    ("Construct a 2x2x2 block of cubes.", all_of(block(), footprint(2), n_levels(2), parts(8))),
    (
        "Build a pyramid with a base of 3 cubes.",
        all_of(pyramid(), any_of(footprint(1, 3), footprint(3)), parts(4, 14)),
    ),
    ("Put a column of 4 cubes at x = 0.5 m, y = 0.2 m.", all_of(tower(4), at(0.50, 0.20))),
    (
        "Build a wall 30 cm long and 10 cm high.",
        all_of(wallish(), footprint(1, 6), n_levels(2), parts(12)),
    ),
    ("Build a tower 15 cm tall.", all_of(tower(3), parts(3))),
    (
        "Build a bridge: two pillars, each two cubes high, with a beam across the top.",
        all_of(single(), spans(1), feet(2), n_levels(3), parts(5)),
    ),
    (
        "Create an L shape with both arms 3 cubes long.",
        all_of(shape("an L", sg.is_l), footprint(3), parts(5)),
    ),
]

_B: list[tuple[str, Accept]] = [
    ("a small bridge", all_of(single(), spans(1), feet(2), parts(3, 12))),
    ("a few cubes in a row", all_of(shape("a row", sg.is_row), parts(3, 6))),
    ("a tall tower", all_of(tower(5, 10))),
    (
        "something like a podium",
        all_of(
            single(),
            n_levels(2, None),
            parts(3, 20),
            any_of(
                shape("a staircase", sg.is_staircase),
                shape("a winners' podium", sg.is_podium),
                shape("a pyramid", sg.is_pyramid),
                shape("a raised block", lambda lay: sg.is_block(lay, min_side=1)),
            ),
        ),
    ),
    ("a short wall", all_of(wallish(2, 1), n_levels(1, 2), parts(3, 12))),
    ("a big pyramid", all_of(pyramid(), n_levels(3, None))),
    ("stack some blocks", all_of(tower(2, 8))),
    ("a little staircase", all_of(steps(2, 4), parts(3, 12))),
    (
        "a long wall",
        all_of(
            wallish(5, 1),
            shape(
                "longer than high", lambda lay: max(sg.bbox_cells(lay)[:2]) > sg.bbox_cells(lay)[2]
            ),
        ),
    ),
    (
        "a medium-sized platform",
        all_of(
            any_of(grid(), shape("a low slab", lambda lay: sg.is_block(lay, min_height=1))),
            n_levels(1, 2),
            parts(4, 25),
        ),
    ),
    (
        "put a couple of towers side by side",
        structures(tower(2, 8), tower(2, 8), max_gap=0.15),
    ),
    ("a small arch", all_of(single(), spans(1), feet(2), parts(3, 12))),
    (
        "a handful of cubes packed tightly together",
        all_of(single(), compact(0.75), parts(4, 10)),
    ),
    ("a tower of medium height", all_of(tower(3, 5))),
    (
        "a low, wide block",
        all_of(
            shape("a solid block", lambda lay: sg.is_block(lay, min_side=2, min_height=1)),
            n_levels(1, 2),
            shape("wider than high", lambda lay: sg.footprint_dims(lay)[1] >= 3),
            parts(4, 18),
        ),
    ),
]

_C: list[tuple[str, Accept]] = [
    (
        "Build an enclosure of 4 by 4 cubes.",
        all_of(enclosure(), hollow(4), footprint(4), n_levels(1), parts(12)),
    ),
    (
        "Make a ring of cubes around an empty square.",
        all_of(single(), enclosure(), every_level_hollow(), parts(8, 24)),
    ),
    (
        "Build a courtyard 5 cubes on each side.",
        all_of(enclosure(), every_level_hollow(), footprint(5), parts_in(16, 32, 48)),
    ),
    (
        "Build a U shape 3 cubes wide with arms 3 cubes long.",
        all_of(
            shape("a U", sg.is_u),
            any_of(footprint(3), footprint(3, 4)),
            n_levels(1),
            parts_in(7, 9),
        ),
    ),
    (
        "Pack 12 cubes as tightly as possible.",
        all_of(single(), compact(0.85, max_side=3), parts(12)),
    ),
    ("Build a small castle.", all_of(shape("a castle", sg.is_castle), parts(8, 24))),
    (
        "Build a solid block 3 cubes long, 2 wide and 2 high.",
        all_of(block(), footprint(2, 3), n_levels(2), parts(12)),
    ),
    (
        "Build a square pen, 3 cubes per side and 2 cubes high.",
        all_of(enclosure(), every_level_hollow(), footprint(3), n_levels(2), parts(16)),
    ),
    (
        "Make a hollow square of cubes with a 2 by 2 space inside.",
        all_of(enclosure(), hollow(4), footprint(4), parts(12)),
    ),
    (
        "Build a rectangular enclosure, 5 cubes long and 3 wide.",
        all_of(enclosure(), hollow(3), footprint(3, 5), n_levels(1), parts(12)),
    ),
    (
        "Build a castle: a 4 by 4 ring of walls with a tower at each corner rising one cube "
        "above the walls.",
        all_of(shape("a castle", sg.is_castle), footprint(4), corners_taller_by(1)),
    ),
    (
        "Fill a 20 cm by 15 cm area densely with cubes.",
        all_of(grid(), footprint(3, 4), parts(12)),
    ),
]

_D: list[tuple[str, Accept]] = [
    (
        "Build a 3D pyramid with a 3 by 3 base.",
        all_of(pyramid(3), footprint(3), parts_in(10, 14)),
    ),
    ("Build a ziggurat.", all_of(pyramid(3), parts(5, 30))),
    ("Pack 8 cubes into a compact cube.", all_of(block(), footprint(2), n_levels(2), parts(8))),
    (
        "Build a table.",
        all_of(single(), shape("a table (legs under a top)", sg.is_table), parts(5, 20)),
    ),
    ("Build a gate.", all_of(single(), spans(1), feet(2), n_levels(2, None), parts(3, 20))),
    (
        "Build two towers joined by a bridge.",
        all_of(single(), spans(1), feet(2), n_levels(3, None), parts(5, 20)),
    ),
    (
        "Build a tower next to a wall.",
        structures(tower(2, 10), any_of(wallish(2, 2), wallish(3, 1)), max_gap=0.15),
    ),
    ("Build three separate towers of 2, 3 and 4 cubes.", tower_heights(2, 3, 4)),
    (
        "Build a tower of 4 cubes at x = 0.45 m, y = 0.30 m.",
        all_of(tower(4), at(0.45, 0.30)),
    ),
    (
        "Build a staircase with 3 steps in the back left corner.",
        all_of(steps(3), parts(6, 12), region("back left")),
    ),
    (
        "Put a 2 by 2 grid on the right and a 3-cube tower on the left.",
        structures(
            all_of(grid(), footprint(2), parts(4), region("right")),
            all_of(tower(3), region("left")),
        ),
    ),
    (
        "Build a two-tier ziggurat on a 3 by 3 base.",
        all_of(pyramid(3), footprint(3), n_levels(2), parts_in(10, 13)),
    ),
    (
        "Make a compact cluster of 10 cubes.",
        all_of(single(), compact(0.75, max_side=4), parts(10)),
    ),
    (
        "Build an archway two cubes high.",
        all_of(single(), spans(1), feet(2), n_levels(2, 5), parts(3, 20)),
    ),
    (
        "Build a shelter with four legs and a roof.",
        all_of(single(), shape("legs under a roof", sg.is_table), feet(4), parts(5, 20)),
    ),
    (
        "Put a row of 4 cubes at the front and a wall 3 cubes long and 2 high at the back.",
        structures(
            all_of(shape("a row", sg.is_row), parts(4), region("front")),
            all_of(wallish(), footprint(1, 3), n_levels(2), parts(6), region("back")),
        ),
    ),
    (
        "Build a 3-step staircase with a 3-cube tower next to it.",
        structures(all_of(steps(3), parts(6)), tower(3), max_gap=0.15),
    ),
    (
        "Build a block of 3 by 2 by 2 cubes in the centre of the table.",
        all_of(block(), footprint(2, 3), n_levels(2), parts(12), region("centre")),
    ),
]

_E: list[tuple[str, Accept]] = [
    (
        "Build a wall 6 cubes long and 3 cubes high.",
        all_of(wallish(), footprint(1, 6), n_levels(3), parts(18)),
    ),
    (
        "Lay out a 5 by 4 grid of cubes centred at x = 50 cm, y = 30 cm.",
        all_of(grid(), footprint(4, 5), parts(20), at(0.50, 0.30)),
    ),
    ("Build a staircase of six steps.", all_of(steps(6), parts(21, 42))),
    (
        "Build a three-dimensional pyramid, three levels high.",
        all_of(pyramid(3), n_levels(3), parts(14, 35)),
    ),
    (
        "Build a courtyard enclosure 6 by 5 cubes.",
        all_of(enclosure(), hollow(12), footprint(5, 6), n_levels(1), parts(18)),
    ),
    (
        "Build a castle 5 cubes per side with corner towers two cubes taller than the walls.",
        all_of(shape("a castle", sg.is_castle), footprint(5), corners_taller_by(2), parts(24, 40)),
    ),
    ("Pack 24 cubes into a dense block.", all_of(single(), compact(0.85, max_side=4), parts(24))),
    (
        "Build a solid block 4 long, 3 wide and 2 high.",
        all_of(block(), footprint(3, 4), n_levels(2), parts(24)),
    ),
    ("Build three towers, each 7 cubes tall.", tower_heights(7, 7, 7)),
    (
        "Build a bridge with three spans on pillars 3 cubes high.",
        all_of(single(), spans(3), feet(4), n_levels(4), parts(15)),
    ),
    (
        "Build a staircase 4 steps high and 2 cubes wide.",
        all_of(steps(4), footprint(2, 4), parts(20)),
    ),
    (
        "Build a fence 45 cm long and 10 cm high.",
        all_of(wallish(), footprint(1, 9), n_levels(2), parts(18)),
    ),
]


def _build() -> tuple[BenchCommand, ...]:
    out = []
    for group, rows in zip(GROUPS, (_A, _B, _C, _D, _E), strict=True):
        for n, (text, accept) in enumerate(rows, start=1):
            out.append(BenchCommand(id=f"{group}{n:02d}", group=group, text=text, accept=accept))
    return tuple(out)


SUITE: tuple[BenchCommand, ...] = _build()
"""The 70 evaluation commands, in group order A01…E12."""

GROUP_SIZES: dict[str, int] = {g: sum(1 for c in SUITE if c.group == g) for g in GROUPS}


def by_id(command_id: str) -> BenchCommand:
    """The suite command with id `command_id` (e.g. ``"C05"``)."""
    for command in SUITE:
        if command.id == command_id:
            return command
    raise KeyError(f"no suite command {command_id!r}")
