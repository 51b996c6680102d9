"""The verifier V(C, K): every constraint on hand-made layouts (pass and fail), the violation
data it returns, and the paper's Table IV human modifications on generated structures."""

from __future__ import annotations

import json
import math

import pytest

from conftest import S, box, codes, cube, layout, of, tower
from sdi.design import compose
from sdi.errors import InputError
from sdi.inspector import Analysis, Constraint, Report, Violation, sequence, verify
from sdi.model import CellConfig, Layout, Part, Workspace, quat_from_yaw
from sdi.spec.structure_spec import Spec, structure

ORDER = {Constraint.GRAVITY, Constraint.SEQUENCE, Constraint.GRIPPING}


# --------------------------------------------------------------------------------------------
# helpers


def well_formed(report: Report, lay: Layout) -> Report:
    """Check the report's invariants and every violation's data; return the report."""
    assert report.passed == (len(report.violations) == 0)
    assert set(report.checked) == {c.value for c in Constraint}
    for v in report.violations:
        assert isinstance(v.constraint, Constraint)
        assert v.objects, v
        assert set(v.objects) <= set(lay.ids), v
        assert v.message.strip() and v.hint.strip(), v
    if report.sequence is not None:
        assert sorted(report.sequence) == sorted(lay.ids)
    json.dumps(report.to_json_dict())  # the whole report is plain JSON
    return report


def check(lay: Layout, cell: CellConfig | None = None, **kwargs) -> Report:
    return well_formed(verify(lay, cell, **kwargs), lay)


def apply_suggestion(lay: Layout, suggestion: dict) -> Layout:
    """Apply a violation's machine-readable fix the way a Designer or the twin would."""
    parts = list(lay.objects)
    if set(suggestion) == {"id", "position"}:
        pid, pos = suggestion["id"], suggestion["position"]
        assert pid in lay.ids
        parts = [
            Part(id=p.id, position=tuple(pos), orientation=p.orientation, size=p.size)
            if p.id == pid
            else p
            for p in parts
        ]
    elif set(suggestion) == {"add_part_at"}:
        parts.append(Part(id="added_part", position=tuple(suggestion["add_part_at"])))
    elif set(suggestion) == {"ids", "translate"}:
        dx, dy = suggestion["translate"]
        ids = set(suggestion["ids"])
        assert ids <= set(lay.ids)
        parts = [p.moved(dx, dy) if p.id in ids else p for p in parts]
    else:  # pragma: no cover - a new suggestion format must be added here
        raise AssertionError(f"unknown suggestion format {suggestion}")
    return Layout(objects=tuple(parts))


def same(v: Violation, w: Violation) -> bool:
    return v.constraint == w.constraint and set(v.objects) == set(w.objects)


def assert_suggestion_fixes(lay: Layout, v: Violation, cell: CellConfig | None = None) -> Report:
    """Applying `v.suggestion` removes `v` (same constraint on the same parts)."""
    assert v.suggestion is not None, v
    fixed = apply_suggestion(lay, v.suggestion)
    after = check(fixed, cell)
    left = [w for w in after.violations if same(v, w)]
    assert not left, f"suggestion {v.suggestion} did not fix {v.message!r}: still {left}"
    return after


# --------------------------------------------------------------------------------------------
# C2 workspace


class TestWorkspace:
    def test_parts_inside_pass(self):
        r = check(layout(tower(3), cube("x", 0.3, 0.1, 0.025)))
        assert r.passed

    @pytest.mark.parametrize(
        "pos",
        [(0.775, 0.3, 0.025), (0.225, 0.3, 0.025), (0.45, 0.075, 0.025), (0.45, 0.525, 0.025)],
    )
    def test_box_flush_with_the_boundary_passes(self, pos):
        assert check(layout(cube("a", *pos))).passed

    def test_protrusion_within_eps_passes(self):
        assert check(layout(cube("a", 0.7755, 0.3, 0.025))).passed

    @pytest.mark.parametrize(
        ("pos", "axis"),
        [
            ((0.777, 0.3, 0.025), "x"),  # centre inside, box 2 mm out
            ((0.15, 0.3, 0.025), "x"),
            ((1.0, 0.3, 0.025), "x"),
            ((0.45, 0.01, 0.025), "y"),
            ((0.45, 0.58, 0.025), "y"),
            ((0.45, 0.3, 0.015), "z"),  # pushed 1 cm into the table
        ],
    )
    def test_part_outside_is_reported_and_suggestion_moves_it_in(self, pos, axis):
        lay = layout(
            cube("in", 0.45, 0.3, 0.025) if pos[:2] != (0.45, 0.3) else [], cube("a", *pos)
        )
        r = check(lay)
        ws = of(r, Constraint.WORKSPACE)
        assert len(ws) == 1
        v = ws[0]
        assert v.objects == ("a",)
        assert "a" in v.message and f"{axis} ∈" in v.message
        assert v.hint.startswith("move a to") and f"{axis}=" in v.hint
        after = assert_suggestion_fixes(lay, v)
        assert not of(after, Constraint.WORKSPACE)

    def test_part_above_the_workspace(self):
        lay = layout(tower(11))  # 0.55 m tall, workspace is 0.50 m
        ws = of(check(lay), Constraint.WORKSPACE)
        assert [v.objects for v in ws] == [("t11",)]

    def test_part_larger_than_the_workspace_has_no_position_suggestion(self):
        lay = layout(box("pole", 0.45, 0.3, 0.3, 0.05, 0.05, 0.6))
        [v] = of(check(lay), Constraint.WORKSPACE)
        assert v.suggestion is None
        assert "larger than the workspace along z" in v.hint

    def test_rotated_part_uses_its_bounding_box(self):
        # A 0.15 m beam centred 0.06 m from the wall fits along y but not when turned 45°.
        beam = dict(id="b", position=(0.74, 0.3, 0.025), size=(0.15, 0.05, 0.05))
        assert check(layout(Part(**beam, orientation=quat_from_yaw(math.pi / 2)))).passed
        r = check(layout(Part(**beam, orientation=quat_from_yaw(math.pi / 4))))
        assert codes(r) == {"workspace"}

    def test_workspace_comes_from_the_cell(self):
        lay = layout(cube("a", 0.65, 0.3, 0.025))
        assert check(lay).passed
        small = CellConfig(workspace=Workspace(x_max=0.6))
        [v] = of(check(lay, small), Constraint.WORKSPACE)
        assert v.suggestion == {"id": "a", "position": [0.575, 0.3, 0.025]}


# --------------------------------------------------------------------------------------------
# C3 collision


class TestCollision:
    def test_touching_faces_are_allowed(self):
        lay = layout(
            tower(2, 0.40, 0.30, "a"), tower(2, 0.45, 0.30, "b"), tower(2, 0.40, 0.35, "c")
        )
        r = check(lay)
        assert Constraint.COLLISION not in {v.constraint for v in r.violations}
        assert r.passed

    def test_overlap_within_eps_is_allowed(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.4491, 0.3, 0.025))
        assert not of(check(lay), Constraint.COLLISION)

    def test_overlap_is_reported_with_a_hint_that_moves_a_part(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.448, 0.3, 0.025))
        r = check(lay)
        [v] = of(r, Constraint.COLLISION)
        assert set(v.objects) == {"a", "b"}
        assert "0.002" in v.message and "along x" in v.message
        assert v.hint == "move b to x=0.45"
        assert v.suggestion == {"id": "b", "position": [0.45, 0.3, 0.025]}
        after = assert_suggestion_fixes(lay, v)
        assert after.passed

    def test_overlap_on_two_axes_only_is_not_a_collision(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.42, 0.3, 0.085))  # 1 cm above a
        r = check(lay)
        assert not of(r, Constraint.COLLISION)
        assert of(r, Constraint.CONTACT)  # but b floats

    def test_same_position_is_fixed_by_stacking(self):
        lay = layout(cube("a", 0.4, 0.3, 0.025), cube("b", 0.4, 0.3, 0.025))
        [v] = of(check(lay), Constraint.COLLISION)
        assert "along z" in v.message
        assert v.suggestion == {"id": "b", "position": [0.4, 0.3, 0.075]}
        assert assert_suggestion_fixes(lay, v).passed

    def test_quarter_turned_beam_touching_a_cube_does_not_collide(self):
        beam = Part(
            id="b", position=(0.4, 0.3, 0.025), size=(0.15, 0.05, 0.05),
            orientation=quat_from_yaw(math.pi / 2),
        )  # fmt: skip
        lay = layout(beam, cube("c", 0.45, 0.3, 0.025), cube("d", 0.4, 0.4, 0.025))
        r = check(lay)
        assert not of(r, Constraint.COLLISION)
        assert r.passed

    def test_45_degree_cube_next_to_a_cube_collides_by_its_bounding_box(self):
        turned = Part(id="t", position=(0.45, 0.3, 0.025), orientation=quat_from_yaw(math.pi / 4))
        lay = layout(cube("a", 0.40, 0.3, 0.025), turned)
        [v] = of(check(lay), Constraint.COLLISION)
        assert set(v.objects) == {"a", "t"}

    def test_only_the_overlapping_pair_is_named(self):
        block = [
            cube(f"c{i}{j}", 0.4 + i * S, 0.2 + j * S, 0.025) for i in range(4) for j in range(3)
        ]
        intruder = cube("x", 0.4 + 1.5 * S + 0.003, 0.2 + 2 * S + 0.04, 0.025)  # hits c12, c22
        r = check(layout(block, intruder))
        pairs = {frozenset(v.objects) for v in of(r, Constraint.COLLISION)}
        assert pairs == {frozenset({"x", "c12"}), frozenset({"x", "c22"})}


# --------------------------------------------------------------------------------------------
# C4 contact (paper) and the stricter support check


class TestContact:
    def test_floating_part_is_reported(self):
        lay = layout(cube("a", 0.4, 0.3, 0.025), cube("f", 0.6, 0.3, 0.125))
        r = check(lay)
        [v] = of(r, Constraint.CONTACT)
        assert v.objects == ("f",)
        assert "floats" in v.message
        assert not of(r, Constraint.SUPPORT)  # a part touching nothing is contact's job
        assert_suggestion_fixes(lay, v)

    def test_suggestion_for_one_level_up_completes_the_layout(self):
        lay = layout(cube("f", 0.6, 0.3, 0.075))
        [v] = of(check(lay), Constraint.CONTACT)
        assert assert_suggestion_fixes(lay, v).passed

    def test_on_the_table_and_stacked_parts_pass(self):
        assert not codes(check(layout(tower(4))))

    def test_table_contact_within_eps(self):
        assert check(layout(cube("a", 0.4, 0.3, 0.0255))).passed
        [v] = of(check(layout(cube("a", 0.4, 0.3, 0.027))), Constraint.CONTACT)
        assert v.objects == ("a",)

    def test_gap_above_another_part_is_no_contact(self):
        lay = layout(cube("a", 0.4, 0.3, 0.025), cube("b", 0.4, 0.3, 0.077))  # 2 mm gap
        [v] = of(check(lay), Constraint.CONTACT)
        assert v.objects == ("b",)
        near = layout(cube("a", 0.4, 0.3, 0.025), cube("b", 0.4, 0.3, 0.0755))  # 0.5 mm gap
        assert check(near).passed

    def test_contact_holds_through_a_chain_of_floating_parts(self):
        # Paper C4 only asks for *some* contact: two touching floating cubes satisfy it,
        # the stricter support check does not.
        lay = layout(cube("a", 0.4, 0.3, 0.125), cube("b", 0.4, 0.3, 0.175))
        r = check(lay)
        assert not of(r, Constraint.CONTACT)
        assert {v.objects[0] for v in of(r, Constraint.SUPPORT)} == {"a"}


class TestSupport:
    def test_side_only_contact_fails_support_but_passes_paper_contact(self):
        lay = layout(tower(2, 0.40), cube("s", 0.45, 0.30, 0.09))  # touches t2's side only
        r = check(lay)
        assert not of(r, Constraint.CONTACT)
        [v] = of(r, Constraint.SUPPORT)
        assert v.objects[0] == "s"
        assert "t2" in v.objects
        assert "side" in v.message
        assert_suggestion_fixes(lay, v)

    def test_edge_contact_fails_support_and_is_fixed_by_moving_onto_the_part(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.45, 0.3, 0.075))
        r = check(lay)
        [v] = of(r, Constraint.SUPPORT)
        assert v.objects == ("b", "a")
        assert v.hint.startswith("move b onto a")
        assert assert_suggestion_fixes(lay, v).passed

    def test_support_suggestion_does_not_move_a_part_into_another(self):
        # s leans on the side of a 2-cube tower. Moving s "onto t1" puts it where t2 is.
        lay = layout(tower(2, 0.40), cube("s", 0.45, 0.30, 0.075))
        [v] = of(check(lay), Constraint.SUPPORT)
        after = check(apply_suggestion(lay, v.suggestion))
        assert not of(after, Constraint.COLLISION), (v.suggestion, after.violations)

    def test_too_small_footprint_overlap_is_not_support(self):
        # 3 mm of overlap is less than tolerances.support_overlap (5 mm).
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.447, 0.3, 0.075))
        assert [v.objects[0] for v in of(check(lay), Constraint.SUPPORT)] == ["b"]
        # 1 cm of overlap is support (the part then topples, which stability reports).
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.44, 0.3, 0.075))
        r = check(lay)
        assert not of(r, Constraint.SUPPORT)
        assert of(r, Constraint.STABILITY)

    def test_resting_within_eps_is_support(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.40, 0.3, 0.0758))
        assert check(lay).passed

    def test_middle_of_a_tower_removed(self):
        parts = tower(5)
        lay = layout(parts[:2], parts[3:])  # t3 gone: t4 and t5 touch only each other
        r = check(lay)
        assert not of(r, Constraint.CONTACT)  # the paper's predicate misses it …
        assert [v.objects[0] for v in of(r, Constraint.SUPPORT)] == ["t4"]  # … we do not
        assert not r.passed


# --------------------------------------------------------------------------------------------
# stability (beyond the paper)


class TestStability:
    def test_overhanging_cube_fails(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.43, 0.3, 0.075))
        r = check(lay)
        [v] = of(r, Constraint.STABILITY)
        assert v.objects == ("b",)
        assert "centre of mass" in v.message
        assert codes(r) == {"stability"}
        assert assert_suggestion_fixes(lay, v).passed

    def test_small_offset_is_stable(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.41, 0.3, 0.075))
        assert check(lay).passed

    def test_cantilever_beam_fails(self):
        beam = box("beam", 0.45, 0.3, 0.125, 0.15, 0.05, 0.05)  # centre 5 cm past the tower
        lay = layout(tower(2, 0.40), beam)
        r = check(lay)
        groups = {frozenset(v.objects) for v in of(r, Constraint.STABILITY)}
        assert frozenset({"beam"}) in groups
        assert codes(r) == {"stability"}

    def test_cantilever_suggestions_fix_their_violation(self):
        beam = box("beam", 0.45, 0.3, 0.125, 0.15, 0.05, 0.05)
        lay = layout(tower(2, 0.40), beam)
        failures = []
        for v in of(check(lay), Constraint.STABILITY):
            fixed = check(apply_suggestion(lay, v.suggestion))
            if any(same(v, w) for w in fixed.violations):
                failures.append((sorted(v.objects), v.suggestion))
        assert not failures, f"suggestions that do not fix their own violation: {failures}"

    def test_sub_structure_topples_although_each_part_rests_on_its_support(self):
        # b sits 2 cm off a's centre (stable alone); a beam on b carries c at its far end.
        # Each part's own centre of mass is over its support; {b, beam, c} together is not.
        lay = layout(
            cube("a", 0.40, 0.3, 0.025),
            cube("b", 0.42, 0.3, 0.075),
            box("beam", 0.42, 0.3, 0.125, 0.15, 0.05, 0.05),
            cube("c", 0.48, 0.3, 0.175),
        )
        groups = {frozenset(v.objects) for v in of(check(lay), Constraint.STABILITY)}
        assert frozenset({"b", "beam", "c"}) in groups
        assert frozenset({"c"}) not in groups
        assert frozenset({"beam", "c"}) not in groups

    def test_pyramid_straddle_passes(self):
        lay = layout(
            cube("a", 0.40, 0.3, 0.025), cube("b", 0.45, 0.3, 0.025), cube("c", 0.425, 0.3, 0.075)
        )
        assert check(lay).passed

    def test_straddle_shifted_off_one_base_still_stands_on_the_other(self):
        # c rests on a and b, but its centre of mass is beyond b's far edge: topples.
        lay = layout(
            cube("a", 0.40, 0.3, 0.025), cube("b", 0.45, 0.3, 0.025), cube("c", 0.478, 0.3, 0.075)
        )
        assert [v.objects for v in of(check(lay), Constraint.STABILITY)] == [("c",)]

    def test_bridge_beam_on_two_pillars_passes(self):
        lay = layout(
            tower(2, 0.40),
            tower(2, 0.50, prefix="u"),
            box("beam", 0.45, 0.3, 0.125, 0.15, 0.05, 0.05),
        )
        assert check(lay).passed

    def test_generated_pyramid_and_bridge_pass(self):
        for shape in ("pyramid", "bridge", "arch", "canopy"):
            lay = compose(Spec(structures=(structure(shape),)))
            assert check(lay).passed, shape


# --------------------------------------------------------------------------------------------
# C1 gravity and C6 sequence with a given order


class TestOrder:
    def test_bottom_up_tower_order_passes(self):
        lay = layout(tower(3))
        r = check(lay, sequence=["t1", "t2", "t3"])
        assert r.passed
        assert r.sequence == ("t1", "t2", "t3")

    def test_reversed_tower_order_gives_sequence_violations(self):
        lay = layout(tower(3))
        r = check(lay, sequence=["t3", "t2", "t1"])
        seq = of(r, Constraint.SEQUENCE)
        assert {v.objects for v in seq} == {("t1", "t2"), ("t2", "t3")}
        for v in seq:
            assert "rests on" in v.message
            assert v.hint.startswith(f"place {v.objects[0]} before {v.objects[1]}")
        assert not of(r, Constraint.GRAVITY)
        assert r.sequence == ("t3", "t2", "t1")

    def test_gravity_for_contact_that_is_not_support(self):
        # b is a taller box beside a: they touch side to side and b's centre is higher, so the
        # paper's C1 wants a first. Nothing rests on anything, so it is gravity, not sequence.
        lay = layout(cube("a", 0.40, 0.3, 0.025), box("b", 0.45, 0.3, 0.03, 0.05, 0.05, 0.06))
        assert check(lay, sequence=["a", "b"]).passed
        r = check(lay, sequence=["b", "a"])
        [v] = r.violations
        assert v.constraint == Constraint.GRAVITY
        assert v.objects == ("a", "b")
        assert "place a before b" in v.hint

    def test_stated_precedence(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.60, 0.3, 0.025))
        assert check(lay, sequence=["b", "a"]).passed
        r = check(lay, sequence=["b", "a"], precedence=(("a", "b"),))
        [v] = r.violations
        assert v.constraint == Constraint.SEQUENCE
        assert v.objects == ("a", "b")
        assert "precedence" in v.message

    def test_precedence_is_honoured_without_a_sequence(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.60, 0.3, 0.025))
        r = check(lay, precedence=(("b", "a"),))
        assert r.passed
        assert r.sequence == ("b", "a")

    def test_precedence_cycle_is_a_sequence_violation(self):
        lay = layout(cube("a", 0.40, 0.3, 0.025), cube("b", 0.60, 0.3, 0.025))
        r = check(lay, precedence=(("a", "b"), ("b", "a")))
        [v] = r.violations
        assert v.constraint == Constraint.SEQUENCE
        assert set(v.objects) == {"a", "b"}
        assert "cycle" in v.message
        assert r.sequence is None

    def test_unknown_precedence_id(self):
        with pytest.raises(InputError):
            verify(layout(tower(2)), precedence=(("t1", "nope"),))

    @pytest.mark.parametrize("seq", [["t1"], ["t1", "t2", "t2"], ["t1", "t2", "zz"], []])
    def test_sequence_must_order_every_part_once(self, seq):
        with pytest.raises(InputError) as info:
            verify(layout(tower(2)), sequence=seq)
        assert info.value.field == "sequence"


# --------------------------------------------------------------------------------------------
# C5 gripping


def layer(n: int, x0: float = 0.40, y0: float = 0.20) -> list[Part]:
    return [cube(f"c{i}{j}", x0 + i * S, y0 + j * S, 0.025) for i in range(n) for j in range(n)]


class TestGripping:
    def test_dense_layer_is_not_grippable_with_a_parallel_gripper_only(self, parallel_cell):
        lay = layout(layer(3))
        r = check(lay, parallel_cell)
        grip = of(r, Constraint.GRIPPING)
        assert {v.objects[0] for v in grip} == set(lay.ids)
        centre = next(v for v in grip if v.objects[0] == "c11")
        assert set(centre.objects[1:]) == {"c01", "c10", "c12", "c21"}
        assert r.sequence is None
        assert not r.passed

    def test_dense_layer_with_a_given_order_blames_the_late_parts(self, parallel_cell):
        lay = layout(layer(3))
        r = check(lay, parallel_cell, sequence=lay.ids)
        blocked = {v.objects[0] for v in of(r, Constraint.GRIPPING)}
        assert "c00" not in blocked  # the first part has nothing around it
        assert "c11" in blocked and "c22" in blocked

    def test_dense_layer_is_grippable_with_the_vacuum(self, vacuum_cell, cell):
        lay = layout(layer(3))
        assert check(lay, vacuum_cell).passed
        assert check(lay, cell).passed

    def test_cube_between_two_placed_neighbours_along_x_is_grippable_along_y(self, parallel_cell):
        lay = layout(
            cube("a", 0.40, 0.3, 0.025), cube("m", 0.45, 0.3, 0.025), cube("b", 0.50, 0.3, 0.025)
        )
        r = check(lay, parallel_cell, sequence=["a", "b", "m"])
        assert r.passed

    def test_neighbours_on_both_axes_block_the_fingers(self, parallel_cell):
        lay = layout(
            cube("a", 0.40, 0.3, 0.025), cube("m", 0.45, 0.3, 0.025), cube("b", 0.50, 0.3, 0.025),
            cube("n", 0.45, 0.35, 0.025),
        )  # fmt: skip
        r = check(lay, parallel_cell, sequence=["a", "b", "n", "m"])
        [v] = r.violations
        assert v.constraint == Constraint.GRIPPING
        assert v.objects[0] == "m"
        assert set(v.objects[1:]) == {"a", "b", "n"}
        assert "place m before" in v.hint
        # Placing m before n leaves the y axis free when m goes in.
        assert check(lay, parallel_cell, sequence=["a", "b", "m", "n"]).passed

    def test_finger_clearance_gap_makes_room(self, parallel_cell):
        gap = 0.015  # > clearance + finger thickness = 0.014 m
        row = [cube(f"r{i}", 0.40 + i * (S + gap), 0.3, 0.025) for i in range(3)]
        col = [cube(f"k{j}", 0.40 + (S + gap), 0.3 + (j + 1) * (S + gap), 0.025) for j in range(2)]
        assert check(layout(row, col), parallel_cell).passed

    def test_part_too_wide_for_the_fingers(self, parallel_cell, vacuum_cell):
        lay = layout(box("plate", 0.45, 0.3, 0.025, 0.2, 0.2, 0.05))
        [v] = check(lay, parallel_cell).violations
        assert v.constraint == Constraint.GRIPPING
        assert "no gripper fits" in v.message
        assert check(lay, vacuum_cell).passed

    def test_face_too_small_for_the_vacuum(self, vacuum_cell, parallel_cell):
        lay = layout(cube("small", 0.45, 0.3, 0.015, size=0.03))
        [v] = check(lay, vacuum_cell).violations
        assert v.constraint == Constraint.GRIPPING
        assert "no gripper fits" in v.message
        assert check(lay, parallel_cell).passed


# --------------------------------------------------------------------------------------------
# report


class TestReport:
    def test_empty_and_single_part_layouts(self):
        r = check(Layout())
        assert r.passed and r.sequence == ()
        r = check(layout(cube("a", 0.4, 0.3, 0.025)))
        assert r.passed and r.sequence == ("a",)

    def test_by_constraint_counts(self):
        lay = layout(
            cube("a", 1.0, 0.3, 0.025),
            cube("b", 0.4, 0.3, 0.025), cube("c", 0.4, 0.3, 0.025),
            cube("f", 0.6, 0.3, 0.3),
        )  # fmt: skip
        r = check(lay)
        counts = r.by_constraint()
        assert counts["workspace"] == 1
        assert counts["collision"] == 1
        assert counts["contact"] == 1
        assert sum(counts.values()) == len(r.violations)

    def test_json_form(self):
        lay = layout(cube("a", 1.0, 0.3, 0.025))
        data = json.loads(json.dumps(check(lay).to_json_dict()))
        assert data["passed"] is False
        [v] = data["violations"]
        assert v["constraint"] == "workspace"
        assert v["objects"] == ["a"]
        assert v["suggestion"] == {"id": "a", "position": [0.775, 0.3, 0.025]}


# --------------------------------------------------------------------------------------------
# Paper Table IV: invalid human modifications on generated structures


def gen(shape: str, **kw: object) -> Layout:
    lay = compose(Spec(structures=(structure(shape, **kw),)))
    r = check(lay)
    assert r.passed, (shape, r.violations)
    return lay


def edit(lay: Layout, moves: dict[str, tuple[float | None, float | None, float | None]]) -> Layout:
    """Set coordinates of some parts (None keeps a coordinate)."""
    parts = []
    for p in lay:
        if p.id in moves:
            pos = tuple(
                old if new is None else new
                for old, new in zip(p.position, moves[p.id], strict=True)
            )
            p = Part(id=p.id, position=pos, orientation=p.orientation, size=p.size)
        parts.append(p)
    return Layout(objects=tuple(parts))


def without(lay: Layout, ids: set[str]) -> Layout:
    return Layout(objects=tuple(p for p in lay if p.id not in ids))


def column(lay: Layout, pid: str) -> list[str]:
    """Ids of the cubes stacked in the same (x, y) column as `pid`."""
    x, y, _ = lay.part(pid).position
    return [
        p.id for p in lay
        if p.size == (S, S, S) and abs(p.position[0] - x) < 1e-9 and abs(p.position[1] - y) < 1e-9
    ]  # fmt: skip


class TestTableIV:
    def test_move_cube_to_x_1_in_tower(self):
        lay = gen("tower", height=3)
        bad = edit(lay, {"c2": (1.0, None, None)})
        r = check(bad)
        assert [v.objects for v in of(r, Constraint.WORKSPACE)] == [("c2",)]

    def test_move_row_to_y_0_01_in_wall(self):
        lay = gen("wall", length=3, height=3, axis="x")  # 9 steps
        top = [p.id for p in lay if p.position[2] > 0.1]
        assert len(top) == 3
        bad = edit(lay, dict.fromkeys(top, (None, 0.01, None)))
        r = check(bad)
        assert {v.objects[0] for v in of(r, Constraint.WORKSPACE)} == set(top)

    def test_move_pillar_to_x_0_85_in_canopy(self):
        lay = gen("canopy")
        pillar = column(lay, "c1")
        assert len(pillar) >= 3
        bad = edit(lay, dict.fromkeys(pillar, (0.85, None, None)))
        r = check(bad)
        assert {v.objects[0] for v in of(r, Constraint.WORKSPACE)} == set(pillar)

    def test_stack_two_cubes_at_the_same_position(self):
        lay = gen("pyramid", length=3)  # 6 steps
        bad = edit(lay, {"c2": lay.part("c1").position})
        r = check(bad)
        assert frozenset({"c1", "c2"}) in {
            frozenset(v.objects) for v in of(r, Constraint.COLLISION)
        }

    def test_overlap_cubes_in_dense_block(self):
        lay = gen("block", length=3, width=2, height=2)  # 12 steps
        assert len(lay) == 12
        a = lay.part("c1")
        neighbour = next(
            p for p in lay
            if p.id != "c1" and abs(p.position[2] - a.position[2]) < 1e-9
            and math.dist(p.position, a.position) == pytest.approx(S)
        )  # fmt: skip
        # push c1 2 cm into its neighbour
        shift = [0.4 * (n - o) for n, o in zip(neighbour.position, a.position, strict=True)]
        bad = edit(lay, {"c1": tuple(o + d for o, d in zip(a.position, shift, strict=True))})
        r = check(bad)
        pairs = {frozenset(v.objects) for v in of(r, Constraint.COLLISION)}
        assert frozenset({"c1", neighbour.id}) in pairs
        v = next(v for v in of(r, Constraint.COLLISION) if set(v.objects) == {"c1", neighbour.id})
        assert_suggestion_fixes(bad, v)

    def test_remove_middle_cube_from_tower(self):
        lay = gen("tower", height=5)
        r = check(without(lay, {"c3"}))
        broken = {v.objects[0] for v in of(r, Constraint.SUPPORT) + of(r, Constraint.CONTACT)}
        assert "c4" in broken
        assert not r.passed

    def test_remove_pillar_from_bridge(self):
        lay = gen("bridge")
        beam = next(p.id for p in lay if p.id.startswith("b"))
        pillar = column(lay, "c1")
        r = check(without(lay, set(pillar)))
        assert codes(r) & {"support", "stability"}
        assert any(
            beam in v.objects for v in of(r, Constraint.STABILITY) + of(r, Constraint.SUPPORT)
        )

    def test_reverse_staircase_assembly_order(self):
        lay = gen("staircase", steps=3)
        good = check(lay).sequence
        assert good is not None
        r = check(lay, sequence=list(reversed(good)))
        assert of(r, Constraint.SEQUENCE)
        assert not r.passed

    def test_roof_before_pillars_in_canopy(self):
        lay = gen("canopy")
        good = list(check(lay).sequence or ())
        roof = [pid for pid in good if pid.startswith("b")]
        assert len(roof) == 5  # two beams on the pillars, three side by side closing the top
        r = check(lay, sequence=roof + [pid for pid in good if pid not in roof])
        seq = of(r, Constraint.SEQUENCE)
        assert seq
        assert {v.objects[1] for v in seq} <= set(roof)  # the roof beams are placed too early
        assert not r.passed


def test_sequence_found_by_verify_is_the_sequencer_order():
    lay = gen("castle")
    assert check(lay).sequence == tuple(sequence(Analysis(lay)))


def test_violations_serialise_to_plain_json_for_checkpoints_and_the_bus():
    # checkpoints (msgpack) and the message bus (JSON) refuse numpy scalars
    import json

    from sdi.inspector.verifier import verify
    from sdi.model.layout import parse_layout

    bad = {"objects": [
        {"id": "float", "position": [0.4, 0.3, 0.3]},
        {"id": "a", "position": [0.5, 0.3, 0.025]}, {"id": "b", "position": [0.52, 0.3, 0.025]},
        {"id": "out", "position": [2.0, 0.3, 0.025]},
        {"id": "big", "position": [0.3, 0.1, 0.05], "size": [0.05, 0.05, 0.1]},
        {"id": "top", "position": [0.33, 0.1, 0.125]},
    ]}  # fmt: skip
    layout, _ = parse_layout(json.dumps(bad))
    report = verify(layout)
    assert len({v.constraint for v in report.violations}) >= 3
    for v in report.violations:
        text = json.dumps(v.to_json_dict())  # no default=: plain types only
        assert json.loads(text)["constraint"] == v.constraint.value


def test_plain_turns_numpy_values_into_json_values():
    import json

    import numpy as np

    from sdi.jsonable import plain

    value = {"a": np.float64(0.5), "b": (np.int64(2), np.array([1.0, 2.0])), 3: [np.bool_(True)]}
    assert json.loads(json.dumps(plain(value))) == {"a": 0.5, "b": [2, [1.0, 2.0]], "3": [True]}


def test_the_canopy_roof_is_closed_and_the_paper_s_21_steps():
    # the roof was two beams on the pillars and two across them, a cube-wide gap down the
    # middle of its top (20 parts at height 4; the paper counts 21)
    lay = gen("canopy", height=4)
    assert len(lay) == 21
    c, h = lay.centres, lay.half_extents
    top = c[:, 2] == c[:, 2].max()
    lo, hi = (c[top] - h[top])[:, :2], (c[top] + h[top])[:, :2]
    covered = float(((hi - lo)[:, 0] * (hi - lo)[:, 1]).sum())
    span = hi.max(0) - lo.min(0)
    assert covered == pytest.approx(float(span[0] * span[1]))  # side by side, no gap, no overlap
