"""The evaluation suite: its shape, its geometry-only signatures, its predicates, its score."""

from __future__ import annotations

import ast
import math
import re
from collections import Counter
from pathlib import Path

import pytest

from sdi.bench import shape_checks
from sdi.bench import signatures as sg
from sdi.bench import suite as suite_module
from sdi.bench.runner import SuiteResult, run_suite
from sdi.bench.suite import GROUPS, SUITE, by_id
from sdi.model import Layout, Part, quat_from_yaw

S = 0.05  # cube edge, m
X0, Y0 = 0.40, 0.30  # where hand-made layouts start, m


def cube(i: float, j: float, k: float, x0: float = X0, y0: float = Y0):
    """A cube whose lattice cell is (i, j, k) counted from (x0, y0) on the table (fractions ok)."""
    return (x0 + (i + 0.5) * S, y0 + (j + 0.5) * S, (k + 0.5) * S)


def lay(*cells, x0: float = X0, y0: float = Y0) -> Layout:
    """A layout of cubes at the given (i, j, k) cells."""
    return Layout(
        objects=tuple(
            Part(id=f"c{n}", position=cube(*c, x0=x0, y0=y0)) for n, c in enumerate(cells)
        )
    )


def with_beams(layout: Layout, *beams: tuple[float, float, float, str]) -> Layout:
    """Add 0.15 m beams centred on cell coordinates (i, j, k), long along 'x' or 'y'."""
    extra = [
        Part(
            id=f"b{n}",
            position=cube(i, j, k),
            orientation=quat_from_yaw(0.0 if along == "x" else 1.5707963267948966),
            size=(0.15, 0.05, 0.05),
        )
        for n, (i, j, k, along) in enumerate(beams)
    ]
    return Layout(objects=(*layout.objects, *extra))


def stack(i: int, j: int, h: int, base: int = 0) -> list[tuple[int, int, int]]:
    return [(i, j, k) for k in range(base, base + h)]


def ring(nx: int, ny: int, k: int = 0) -> list[tuple[int, int, int]]:
    return [(i, j, k) for i in range(nx) for j in range(ny) if i in (0, nx - 1) or j in (0, ny - 1)]


def box(nx: int, ny: int, nz: int) -> list[tuple[int, int, int]]:
    return [(i, j, k) for i in range(nx) for j in range(ny) for k in range(nz)]


# Hand-made reference layouts ------------------------------------------------------------------

TOWER3 = lay(*stack(0, 0, 3))
ROW3 = lay((0, 0, 0), (1, 0, 0), (2, 0, 0))
GRID33 = lay(*box(3, 3, 1))
GRID33_HOLE = lay(*[c for c in box(3, 3, 1) if c != (1, 1, 0)])
WALL42_CELLS = [(0, j, k) for j in range(4) for k in range(2)]
WALL42 = lay(*WALL42_CELLS)
BLOCK222 = lay(*box(2, 2, 2))
RING33 = lay(*ring(3, 3))
STAIRS3 = lay(*stack(0, 0, 1), *stack(1, 0, 2), *stack(2, 0, 3))
# 2-D pyramid 3-2-1, upper courses offset by half a cube as real courses are.
PYRAMID_CELLS_2D = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0.5, 0, 1), (1.5, 0, 1), (1, 0, 2)]
PYRAMID2D = lay(*PYRAMID_CELLS_2D)
PYRAMID3D = lay(
    *box(3, 3, 1),
    *[(i + 0.5, j + 0.5, 1) for i in range(2) for j in range(2)],
    (1, 1, 2),
)
# Two pillars two high with a beam on top (gap of one cube): a bridge.
BRIDGE = with_beams(lay(*stack(0, 0, 2), *stack(2, 0, 2)), (1, 0, 2, "x"))
# A table: four legs two high, two beams along x, two beams across them.
TABLE = with_beams(
    lay(*stack(0, 0, 2), *stack(2, 0, 2), *stack(0, 2, 2), *stack(2, 2, 2)),
    (1, 0, 2, "x"),
    (1, 2, 2, "x"),
    (0, 1, 3, "y"),
    (2, 1, 3, "y"),
)


# (a) the suite ------------------------------------------------------------------------------


def test_suite_has_seventy_commands_in_the_papers_groups():
    assert len(SUITE) == 70
    sizes = Counter(c.group for c in SUITE)
    assert sizes == {"A": 13, "B": 15, "C": 12, "D": 18, "E": 12}
    assert tuple(sorted(sizes)) == GROUPS


def test_suite_ids_and_texts_are_unique_and_well_formed():
    ids = [c.id for c in SUITE]
    assert len(set(ids)) == len(ids)
    assert len({c.text.lower() for c in SUITE}) == len(SUITE)
    for c in SUITE:
        assert re.fullmatch(r"[A-E]\d\d", c.id) and c.id[0] == c.group
        assert callable(c.accept) and c.text.strip()
    assert by_id("C05").text == next(c.text for c in SUITE if c.id == "C05")
    with pytest.raises(KeyError):
        by_id("Z99")


# (b) signatures on hand-made layouts ----------------------------------------------------------


# What the judging modules may take from the judged code: the Layout and Part classes as
# containers of raw poses, nothing else (no geometry helpers, no cell tables, no Designer or
# Inspector). Their cached geometry attributes must not be read either.
_JUDGES = (sg, suite_module, shape_checks)
_FORBIDDEN_MODULES = ("sdi.design", "sdi.inspector", "sdi.model.cell")
_CONTAINERS = {
    "sdi.model": {"Layout", "Part"},
    "sdi.model.layout": {"Layout"},
    "sdi.model.part": {"Part"},
}
_GEOMETRY_ATTRIBUTES = {"half_extents", "centres", "volumes", "bottom", "top"}


def _sdi_imports(tree: ast.AST) -> list[tuple[str, str | None]]:
    """(module, imported name or None for a plain ``import``) for every import of sdi code."""
    out: list[tuple[str, str | None]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            out += [(a.name, None) for a in node.names if a.name.split(".")[0] == "sdi"]
        elif isinstance(node, ast.ImportFrom) and (node.module or "").split(".")[0] == "sdi":
            assert node.level == 0 and node.module
            out += [(node.module, a.name) for a in node.names]
    return out


@pytest.mark.parametrize("module", _JUDGES, ids=lambda m: m.__name__)
def test_the_judges_import_no_geometry_or_regions_from_the_judged_code(module):
    tree = ast.parse(Path(module.__file__).read_text(encoding="utf-8"))
    imports = _sdi_imports(tree)
    assert imports, "the parser found no sdi imports at all"
    for mod, name in imports:
        full = f"{mod}.{name}" if name else mod
        assert not full.startswith(_FORBIDDEN_MODULES), full
        if mod in _CONTAINERS:
            assert name in _CONTAINERS[mod], f"{full}: only the data classes may be imported"
        elif mod == "sdi":
            assert name not in {"design", "inspector", "model"}, full
        else:
            assert mod.startswith("sdi.bench") and name is not None, full
    used = {n.attr for n in ast.walk(tree) if isinstance(n, ast.Attribute)}
    assert not used & _GEOMETRY_ATTRIBUTES, sorted(used & _GEOMETRY_ATTRIBUTES)
    names = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)}
    assert not names & {"CellConfig", "rotation_matrix", "quat_from_yaw"}


def test_the_suite_uses_only_judging_modules_of_the_bench():
    tree = ast.parse(Path(suite_module.__file__).read_text(encoding="utf-8"))
    bench = {(m, n) for m, n in _sdi_imports(tree) if m.startswith("sdi.bench")}
    assert bench == {("sdi.bench", "signatures")}


def _part(yaw_deg: float, size=(0.15, 0.05, 0.05)) -> Part:
    half = math.radians(yaw_deg) / 2  # the quaternion written out, not the model's helper
    return Part(
        id="p",
        position=(0.45, 0.30, 0.025),
        orientation=(math.cos(half), 0.0, 0.0, math.sin(half)),
        size=size,
    )


def test_raw_pose_box_turned_90_degrees_swaps_x_and_y():
    assert sg.world_half_extents((1.0, 0.0, 0.0, 0.0), (0.15, 0.05, 0.05)) == pytest.approx(
        (0.075, 0.025, 0.025)
    )
    for yaw in (90.0, -90.0, 270.0):
        c, h = sg.world_boxes(Layout(objects=(_part(yaw),)))
        assert h[0] == pytest.approx((0.025, 0.075, 0.025), abs=1e-12)
        assert c[0] == pytest.approx((0.45, 0.30, 0.025))
    assert sg.footprint_size(Layout(objects=(_part(90.0),))) == pytest.approx((0.05, 0.15))
    assert sg.footprint_size(Layout(objects=(_part(180.0),))) == pytest.approx((0.15, 0.05))
    # a quarter turn about x instead stands the beam's y edge up: y and z swap
    q = (math.cos(math.pi / 4), math.sin(math.pi / 4), 0.0, 0.0)
    assert sg.world_half_extents(q, (0.15, 0.05, 0.10)) == pytest.approx((0.075, 0.05, 0.025))


def test_raw_pose_box_turned_45_degrees_has_the_larger_footprint():
    r = math.sqrt(0.5)
    cube = _part(45.0, size=(0.05, 0.05, 0.05))
    _, h = sg.world_boxes(Layout(objects=(cube,)))
    assert h[0] == pytest.approx((0.05 * r, 0.05 * r, 0.025))  # the diagonal, 0.0707 m across
    beam = _part(45.0)
    _, h = sg.world_boxes(Layout(objects=(beam,)))
    side = (0.075 + 0.025) * r  # (long + short half-edge) · cos 45°
    assert h[0] == pytest.approx((side, side, 0.025))
    assert sg.footprint_size(Layout(objects=(beam,))) == pytest.approx((2 * side, 2 * side))
    # 0.141 m each way: more than the beam's width on both axes, so a larger footprint
    # (0.020 m² against 0.15 × 0.05 = 0.0075 m² unturned)
    assert 2 * side > 0.05 and (2 * side) ** 2 > 0.15 * 0.05
    assert sg.footprint_size(Layout(objects=(cube,))) == pytest.approx((0.1 * r, 0.1 * r))
    assert 0.1 * r > 0.05  # a cube turned 45° is wider than its edge
    # a not-quite-unit quaternion is normalised by the judge itself
    q = tuple(1.0005 * v for v in beam.orientation)
    assert sg.world_half_extents(q, beam.size) == pytest.approx((side, side, 0.025))


def test_lattice_counts_levels_columns_and_beams():
    assert sg.levels(TOWER3) == 3
    assert sg.columns(TOWER3) == {(0, 0): 3}
    assert sg.levels(GRID33) == 1
    assert sg.columns(STAIRS3) == {(0, 0): 1, (1, 0): 2, (2, 0): 3}
    # the beam fills three cells on level 2, over both pillars and the gap
    lat = sg.lattice(BRIDGE)
    assert lat.level(2) == {(0, 0), (1, 0), (2, 0)}
    assert sg.column_tops(BRIDGE)[(1, 0)] == 3 and sg.columns(BRIDGE)[(1, 0)] == 1
    assert sg.is_long(BRIDGE.part("b0")) and not sg.is_long(BRIDGE.part("c0"))
    assert sg.bbox_cells(WALL42) == (1, 4, 2)
    assert sg.footprint_dims(WALL42) == (1, 4)
    assert sg.main_axis(WALL42) == "y" and sg.main_axis(ROW3) == "x"
    assert sg.main_axis(GRID33) is None
    assert sg.levels(Layout()) == 0


def test_tower():
    assert sg.is_tower(TOWER3)
    assert not sg.is_tower(ROW3)  # a row is not a tower
    assert not sg.is_tower(lay(*stack(0, 0, 2), *stack(3, 0, 2)))  # two stacks
    assert not sg.is_tower(lay((0, 0, 0), (0, 0, 2)))  # floating top
    assert not sg.is_tower(lay((0, 0, 0)))  # one cube is no tower by default
    assert sg.is_tower(lay((0, 0, 0)), min_height=1)
    assert not sg.is_tower(lay(*stack(0, 0, 3), *stack(1, 0, 2)))  # uneven


def test_row():
    assert sg.is_row(ROW3)
    assert sg.is_row(lay((0, 0, 0), (1.4, 0, 0), (2.8, 0, 0)))  # gaps allowed…
    assert not sg.is_row(lay((0, 0, 0), (1.4, 0, 0), (2.8, 0, 0)), contiguous=True)  # …unless not
    assert not sg.is_row(TOWER3)
    assert not sg.is_row(lay((0, 0, 0), (1, 0, 0), (1, 1, 0)))  # bent
    assert not sg.is_row(lay((0, 0, 0), (1, 0, 0), (1, 0, 1)))  # two levels
    assert not sg.is_row(GRID33)


def test_grid():
    assert sg.is_grid(GRID33)
    assert not sg.is_grid(GRID33_HOLE)  # a grid with a hole is not a grid
    assert not sg.is_grid(ROW3)  # too thin
    assert not sg.is_grid(BLOCK222)  # two levels
    assert not sg.is_grid(lay(*box(3, 3, 1), (0, 0, 1)))


def test_wall_and_block():
    assert sg.is_wall(WALL42)
    assert not sg.is_wall(ROW3)  # one level
    assert sg.is_wall(ROW3, min_height=1)
    assert not sg.is_wall(BLOCK222)  # two thick
    assert not sg.is_wall(lay(*[c for c in WALL42_CELLS if c != (0, 1, 1)]))  # missing part
    assert sg.is_block(BLOCK222)
    assert sg.is_full_box(BLOCK222)
    assert not sg.is_block(GRID33)  # one level
    assert sg.is_block(GRID33, min_height=1)
    assert not sg.is_block(lay(*box(2, 2, 2)[:-1]))  # a corner missing
    assert not sg.is_block(WALL42)


def test_pyramid():
    assert sg.pyramid_dims(PYRAMID2D) == 2
    assert sg.pyramid_dims(PYRAMID3D) == 3
    assert sg.is_pyramid(PYRAMID3D, dims=3) and not sg.is_pyramid(PYRAMID2D, dims=3)
    # courses inset by a whole cube each side also make a (step) pyramid
    assert sg.is_pyramid(lay(*[(i, 0, 0) for i in range(5)], (1, 0, 1), (2, 0, 1), (3, 0, 1)))
    assert not sg.is_pyramid(STAIRS3)  # flush at one end: a staircase
    assert not sg.is_pyramid(TOWER3)  # not shrinking
    assert not sg.is_pyramid(lay((0, 0, 0), (1, 0, 0), (-0.5, 0, 1)))  # overhangs
    assert not sg.is_pyramid(lay((0.5, 0, 0), (0, 0, 1), (1, 0, 1)))  # upside down
    assert not sg.is_pyramid(GRID33)  # one level
    assert not sg.is_pyramid(lay((0, 0, 0), (2, 0, 0), (1, 0, 1)))  # hole in the base


def test_staircase():
    assert sg.staircase_steps(STAIRS3) == 3
    wide = lay(*[c for j in range(2) for i in range(3) for c in stack(i, j, i + 1)])
    assert sg.staircase_steps(wide) == 3
    descending = lay(*stack(0, 0, 2), *stack(1, 0, 1))
    assert sg.staircase_steps(descending) == 2
    assert not sg.is_staircase(lay(*stack(0, 0, 1), *stack(1, 0, 3)))  # steps by two
    assert not sg.is_staircase(lay((0, 0, 0), (1, 0, 0), (1, 0, 2)))  # hollow column
    assert not sg.is_staircase(PYRAMID2D)
    assert not sg.is_staircase(TOWER3) and not sg.is_staircase(ROW3)


def test_podium():
    assert sg.is_podium(lay(*stack(0, 0, 2), *stack(1, 0, 3), *stack(2, 0, 1)))
    assert not sg.is_podium(STAIRS3)
    assert not sg.is_podium(ROW3)


def test_span():
    assert sg.has_span(BRIDGE)
    ((part_id, gap),) = sg.span_parts(BRIDGE)
    assert part_id == "b0" and gap == pytest.approx(S)
    # a beam on a solid wall has nothing empty beneath it
    assert not sg.has_span(with_beams(lay(*box(3, 1, 2)), (1, 0, 2, "x")))
    # something standing in the opening, even lower down, closes the gap
    blocked = with_beams(lay(*stack(0, 0, 2), *stack(2, 0, 2), (1, 0, 0)), (1, 0, 2, "x"))
    assert not sg.has_span(blocked)
    # a beam on one pillar only is a cantilever, not a span
    assert not sg.has_span(with_beams(lay(*stack(0, 0, 2)), (1, 0, 2, "x")))
    assert not sg.has_span(TOWER3) and not sg.has_span(Layout())
    assert len(sg.ground_supports(BRIDGE)) == 2
    assert len(sg.ground_supports(TABLE)) == 4


def test_table():
    assert sg.is_table(TABLE)
    assert not sg.is_table(BRIDGE)  # two feet
    assert not sg.is_table(lay(*stack(0, 0, 2), *stack(2, 0, 2), *stack(0, 2, 2), *stack(2, 2, 2)))


def test_enclosure():
    assert sg.is_enclosure(RING33)
    assert sg.enclosed_cells(RING33, 0) == {(1, 1)}
    assert sg.enclosed_cells(lay(*ring(4, 5)), 0) == {(i, j) for i in (1, 2) for j in (1, 2, 3)}
    assert not sg.is_enclosure(GRID33)  # an enclosure needs a hollow
    assert not sg.is_enclosure(lay(*[c for c in ring(3, 3) if c != (1, 2, 0)]))  # open side
    corners_missing = lay(*[c for c in ring(3, 3) if c[:2] not in ((0, 0), (2, 2))])
    assert not sg.is_enclosure(corners_missing)  # walls meeting only at an edge leak
    two_high = lay(*ring(3, 3), *ring(3, 3, k=1))
    assert sg.enclosure_levels(two_high) == 2
    assert sg.enclosure_levels(lay(*ring(3, 3), (1, 1, 1))) == 1  # level 1 is no ring


def test_letter_shapes():
    l_shape = lay((0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (0, 2, 0))
    u_shape = lay((0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (0, 2, 0), (2, 1, 0), (2, 2, 0))
    t_shape = lay((0, 2, 0), (1, 2, 0), (2, 2, 0), (1, 1, 0), (1, 0, 0))
    plus = lay((1, 0, 0), (1, 1, 0), (1, 2, 0), (0, 1, 0), (2, 1, 0))
    assert sg.is_l(l_shape) and not sg.is_l(u_shape) and not sg.is_l(ROW3)
    assert sg.is_u(u_shape) and not sg.is_u(l_shape) and not sg.is_u(RING33)
    assert not sg.is_enclosure(u_shape)
    assert sg.is_t(t_shape) and not sg.is_t(plus) and not sg.is_t(l_shape)
    assert sg.is_cross(plus) and not sg.is_cross(t_shape) and not sg.is_cross(GRID33)
    off_centre = lay(*[(0, j, 0) for j in range(-1, 4)], (-1, 0, 0), (1, 0, 0))
    assert not sg.is_cross(off_centre)
    # letters are judged in any orientation and as upright prisms
    rotated_l = lay((0, 0, 0), (0, 1, 0), (0, 2, 0), (-1, 2, 0), (-2, 2, 0))
    assert sg.is_l(rotated_l)
    assert sg.is_l(
        lay(*[(i, j, k) for i, j, _ in [(0, 0, 0), (1, 0, 0), (0, 1, 0)] for k in (0, 1)])
    )
    assert not sg.is_l(lay((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 1, 1)))  # uneven heights


def test_castle():
    castle = lay(*ring(4, 4), *[(i, j, 1) for i in (0, 3) for j in (0, 3)])
    assert sg.is_castle(castle)
    assert not sg.is_castle(lay(*ring(4, 4)))  # no taller corners
    assert not sg.is_castle(lay(*ring(4, 4), (0, 0, 1), (3, 3, 1)))  # only two corners
    assert not sg.is_castle(lay(*box(4, 4, 1), *[(i, j, 1) for i in (0, 3) for j in (0, 3)]))


def test_separate_structures():
    two = lay(*stack(0, 0, 3), *stack(4, 0, 2))
    comps = sg.separate_structures(two)
    assert [len(c) for c in comps] == [3, 2]
    assert all(sg.is_tower(c) for c in comps)
    assert len(sg.separate_structures(lay(*stack(0, 0, 3), *stack(1, 0, 2)))) == 1
    assert len(sg.separate_structures(lay((0, 0, 0), (1, 1, 0)))) == 2  # only an edge touches
    assert len(sg.separate_structures(BRIDGE)) == 1
    assert len(sg.separate_structures(TABLE)) == 1
    assert sg.separate_structures(Layout()) == []
    assert sg.gap_between(comps[0], comps[1]) == pytest.approx(3 * S)


def test_positions_and_regions():
    assert sg.footprint_centre(GRID33) == pytest.approx((X0 + 1.5 * S, Y0 + 1.5 * S))
    assert sg.footprint_size(ROW3) == pytest.approx((3 * S, S))
    with pytest.raises(ValueError):
        sg.footprint_centre(Layout())
    assert sg.in_region(TOWER3, (0.40, 0.45), (0.30, 0.35))
    assert not sg.in_region(TOWER3, (0.45, 0.50), (0.30, 0.35))
    back_left = lay(*stack(0, 0, 2), x0=0.625, y0=0.425)  # centre (0.65, 0.45)
    front_right = lay(*stack(0, 0, 2), x0=0.275, y0=0.125)  # centre (0.30, 0.15)
    middle = lay(*stack(0, 0, 2), x0=0.425, y0=0.275)  # centre (0.45, 0.30)
    assert sg.in_named_region(back_left, "back left")
    assert sg.in_named_region(back_left, "back") and sg.in_named_region(back_left, "left")
    assert not sg.in_named_region(back_left, "front") and not sg.in_named_region(back_left, "right")
    assert sg.in_named_region(front_right, "front right")
    assert not sg.in_named_region(front_right, "back left")
    assert sg.in_named_region(middle, "centre") and not sg.in_named_region(back_left, "centre")
    assert sg.in_named_region(back_left, "back-left corner")
    assert sg.in_named_region(middle, "center") and sg.in_named_region(middle, "middle")
    with pytest.raises(ValueError):
        sg.in_named_region(middle, "upstairs")
    assert sg.region_problem(Layout(), "left") == "no parts"


@pytest.mark.parametrize(
    ("name", "inside", "outside"),
    [
        ("left", (0.45, 0.34), (0.45, 0.32)),
        ("right", (0.45, 0.26), (0.45, 0.28)),
        ("front", (0.41, 0.30), (0.43, 0.30)),
        ("back", (0.49, 0.30), (0.47, 0.30)),
        ("centre", (0.52, 0.37), (0.54, 0.30)),
        ("centre", (0.38, 0.23), (0.45, 0.39)),
        ("back left", (0.49, 0.34), (0.49, 0.32)),
        ("back left", (0.49, 0.34), (0.47, 0.34)),
        ("front right", (0.30, 0.15), (0.30, 0.45)),
    ],
)
def test_named_regions_are_the_judges_own_numbers(name, inside, outside):
    # left y > 0.33, right y < 0.27, front x < 0.42, back x > 0.48, centre ±0.08 of (0.45, 0.30)
    assert sg.in_named_region(at_centre(stack(0, 0, 2), *inside), name)
    assert not sg.in_named_region(at_centre(stack(0, 0, 2), *outside), name)


def test_compactness():
    assert sg.compactness(BLOCK222) == 1.0
    assert sg.compactness(RING33) == pytest.approx(8 / 9)
    assert sg.compactness(lay((0, 0, 0), (2, 2, 0))) == pytest.approx(2 / 9)
    assert sg.compactness(Layout()) == 0.0


# (c) predicates reject wrong layouts ----------------------------------------------------------


def at_centre(cells, x: float, y: float) -> Layout:
    """Cubes at `cells`, shifted so the footprint centre is (x, y)."""
    layout = lay(*cells)
    cx, cy = sg.footprint_centre(layout)
    return lay(*cells, x0=X0 + x - cx, y0=Y0 + y - cy)


@pytest.mark.parametrize(
    ("cid", "good", "bads"),
    [
        # a tower at x = 0.4: not elsewhere, not a row, not taller
        (
            "A01",
            at_centre(stack(0, 0, 3), 0.40, 0.30),
            [
                at_centre(stack(0, 0, 3), 0.50, 0.30),
                at_centre([(0, 0, 0), (1, 0, 0), (2, 0, 0)], 0.40, 0.30),
                at_centre(stack(0, 0, 4), 0.40, 0.30),
            ],
        ),
        ("A04", GRID33, [GRID33_HOLE, lay(*box(3, 3, 2)), lay(*box(4, 3, 1))]),
        ("A05", WALL42, [lay(*[(0, j, 0) for j in range(8)]), lay(*box(2, 2, 2)), TOWER3]),
        ("A06", lay(*[c for i in range(4) for c in stack(i, 0, i + 1)]), [PYRAMID2D, STAIRS3]),
        ("A12", BRIDGE, [lay(*stack(0, 0, 2), *stack(2, 0, 2)), lay(*box(3, 1, 2), (1, 0, 2))]),
        ("B02", ROW3, [TOWER3, GRID33, lay((0, 0, 0), (1, 0, 0), (1, 1, 0))]),
        ("B03", lay(*stack(0, 0, 6)), [TOWER3, lay(*[(i, 0, 0) for i in range(6)])]),
        ("B13", lay(*box(3, 2, 1)), [lay(*[(i, 0, 0) for i in range(6)]), TOWER3]),
        ("C01", lay(*ring(4, 4)), [lay(*box(4, 4, 1)), RING33, lay(*ring(4, 4)[:-1])]),
        ("C06", lay(*ring(3, 3), *[(i, j, 1) for i in (0, 2) for j in (0, 2)]), [RING33, GRID33]),
        ("C08", lay(*ring(3, 3), *ring(3, 3, k=1)), [RING33, lay(*box(3, 3, 2))]),
        ("D01", PYRAMID3D, [PYRAMID2D, lay(*box(3, 3, 1))]),
        ("D04", TABLE, [BRIDGE, lay(*box(3, 3, 2))]),
        (
            "D06",
            BRIDGE,
            [lay(*stack(0, 0, 2), *stack(2, 0, 2)), lay(*stack(0, 0, 2), *stack(4, 0, 2))],
        ),
        (
            "D08",
            lay(*stack(0, 0, 2), *stack(3, 0, 3), *stack(6, 0, 4)),
            [lay(*stack(0, 0, 3), *stack(3, 0, 3), *stack(6, 0, 3)), lay(*stack(0, 0, 9))],
        ),
        (
            "D10",
            at_centre([c for i in range(3) for c in stack(i, 0, i + 1)], 0.65, 0.45),
            [
                at_centre([c for i in range(3) for c in stack(i, 0, i + 1)], 0.30, 0.15),
                at_centre(PYRAMID_CELLS_2D, 0.65, 0.45),
            ],
        ),
        (
            "E10",
            with_beams(
                lay(*[c for i in (0, 3, 6, 9) for c in stack(i, 0, 3)]),
                (1.5, 0, 3, "x"),
                (4.5, 0, 3, "x"),
                (7.5, 0, 3, "x"),
            ),
            [with_beams(lay(*stack(0, 0, 3), *stack(2, 0, 3)), (1, 0, 3, "x"))],
        ),
    ],
)
def test_predicates_accept_the_right_shape_and_reject_wrong_ones(cid, good, bads):
    command = by_id(cid)
    assert command.accept(good) is None, command.accept(good)
    for bad in bads:
        reason = command.accept(bad)
        assert isinstance(reason, str) and reason, f"{cid} accepted a wrong layout"


def test_compound_predicate_checks_each_structure_and_region():
    command = by_id("D11")  # a 2 by 2 grid on the right and a 3-cube tower on the left
    grid_right = [(i, j, 0) for i in range(2) for j in range(2)]
    good = Layout(
        objects=(
            *at_centre(grid_right, 0.45, 0.15).objects,
            *(
                p.model_copy(update={"id": f"t{n}"})
                for n, p in enumerate(at_centre(stack(0, 0, 3), 0.45, 0.45).objects)
            ),
        )
    )
    assert command.accept(good) is None
    swapped = Layout(
        objects=(
            *at_centre(grid_right, 0.45, 0.45).objects,
            *(
                p.model_copy(update={"id": f"t{n}"})
                for n, p in enumerate(at_centre(stack(0, 0, 3), 0.45, 0.15).objects)
            ),
        )
    )
    assert "region" in (command.accept(swapped) or "")
    assert command.accept(at_centre(grid_right, 0.45, 0.15)) is not None  # the tower is missing


# (d) the whole suite through the pipeline -----------------------------------------------------


@pytest.fixture(scope="module")
def suite_result() -> SuiteResult:
    return run_suite()


def test_runner_reports_every_command(suite_result: SuiteResult):
    assert len(suite_result.records) == 70
    assert [r.id for r in suite_result.records] == [c.id for c in SUITE]
    for r in suite_result.records:
        assert r.seconds >= 0 and r.parts >= 0
        assert r.success == (r.status == "success" and r.accepted)
        assert r.accepted == (r.reason is None)
    data = suite_result.to_json_dict()
    assert set(data["groups"]) == set(GROUPS)
    assert data["overall"]["count"] == 70
    assert len(data["commands"]) == 70
    table = suite_result.markdown_table()
    rows = [line for line in table.splitlines() if line.startswith("| ") and "---" not in line]
    assert [row.split("|")[1].strip() for row in rows[1:]] == [*GROUPS, "Overall"]


def test_runner_on_a_subset_calls_progress():
    seen = []
    result = run_suite(commands=SUITE[:3], progress=seen.append)
    assert [r.id for r in seen] == ["A01", "A02", "A03"]
    assert result.overall.count == 3


def test_suite_meets_the_acceptance_target(suite_result: SuiteResult):
    failing = "\n".join(
        f"  {r.id} {r.text!r}: status={r.status} spec=[{r.spec}] reason={r.reason}"
        for r in suite_result.failures
    )
    rates = {g: s.rate for g, s in suite_result.groups.items()}
    assert suite_result.overall.rate >= 0.98, f"overall {suite_result.overall.rate:.1%}\n{failing}"
    assert all(rate >= 0.95 for rate in rates.values()), f"per group {rates}\n{failing}"
