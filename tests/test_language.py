"""The language front end: relations built as the words say, every word accounted for.

The commands here are this file's own (not in the evaluation sets); each test checks the
layout's geometry or the reading's account, not only the family names.
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from sdi.errors import SpecError
from sdi.language import FAMILIES, check_family, read
from sdi.pipeline import plan
from sdi.spec.structure_spec import (
    BlockSpec,
    Relation,
    Spec,
    StructureDraft,
    TowerSpec,
    structure,
)


def boxes(result):
    assert result.layout is not None, result.error
    lo = np.array([[p.position[d] - p.size[d] / 2 for d in range(3)] for p in result.layout])
    hi = np.array([[p.position[d] + p.size[d] / 2 for d in range(3)] for p in result.layout])
    return lo, hi


# -- relations ----------------------------------------------------------------------------------
def test_a_column_on_top_of_a_base_stands_on_its_top_face():
    r = plan("put a column of 3 cubes on top of a 4 by 4 base layer")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 16 + 3
    upper = lo[:, 2] > 0.01
    assert upper.sum() == 3
    # the column stands on the base's top face, inside its footprint
    assert np.isclose(lo[upper, 2].min(), hi[~upper, 2].max())
    for d in (0, 1):
        assert lo[upper, d].min() >= lo[~upper, d].min() - 1e-9
        assert hi[upper, d].max() <= hi[~upper, d].max() + 1e-9


def test_a_ring_around_a_tower_leaves_the_tower_inside():
    r = plan("a pen of cubes surrounding a 2-cube stack")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    tall = hi[:, 2] > 0.06
    assert tall.sum() == 1  # the stack's upper cube; the ring is one high
    tower_xy = ((lo[tall, 0] + hi[tall, 0]) / 2)[0], ((lo[tall, 1] + hi[tall, 1]) / 2)[0]
    ring = lo[:, 2] < 0.01
    # ring parts on every side of the tower
    assert (hi[ring, 0] < tower_xy[0]).any() and (lo[ring, 0] > tower_xy[0]).any()
    assert (hi[ring, 1] < tower_xy[1]).any() and (lo[ring, 1] > tower_xy[1]).any()


def test_towers_joined_by_a_beam_carry_it():
    r = plan("connect two 3-high columns with a beam across the top")
    assert r.status == "success", r.notes
    beams = [p for p in r.layout if max(p.size) > 0.1]
    assert len(beams) == 1
    assert np.isclose(beams[0].position[2] - beams[0].size[2] / 2, 0.15)  # on 3 levels
    assert len(r.layout) == 3 + 3 + 1


def test_a_structure_to_the_left_of_another_is_at_larger_y():
    r = plan("a 3-cube tower to the left of a wall 4 long and 1 high")
    assert r.status == "success", r.notes
    tower = [p for p in r.layout if p.position[2] > 0.06]
    assert len(tower) == 2
    column = (tower[0].position[0], tower[0].position[1])
    wall = [p for p in r.layout if (p.position[0], p.position[1]) != column]
    assert len(wall) == 4
    assert all(column[1] > p.position[1] for p in wall)


def test_then_add_on_top_of_it_stacks_a_copy():
    r = plan("lay 5 cubes in a row, and then put a second row on top of it")
    assert r.status == "success", r.notes
    lo, _ = boxes(r)
    assert len(lo) == 10
    assert sorted(np.round(lo[:, 2], 3).tolist()).count(0.05) == 5


def test_a_pronoun_inside_a_phrase_points_at_the_other_structure():
    reading = read("a 3-step staircase with a 2-cube tower beside it")
    [rel] = reading.spec.relations
    shapes = [s.shape for s in reading.spec.structures]
    assert shapes[rel.subject] == "tower" and shapes[rel.object] == "staircase"


def test_a_bridge_on_its_own_pillars_is_not_a_relation():
    reading = read("a bridge with two spans on pillars 2 cubes high")
    assert reading.spec.relations == ()
    [bridge] = reading.spec.structures
    assert (bridge.shape, bridge.spans, bridge.height) == ("bridge", 2, 2)


# -- honest status ------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "command, dropped",
    [
        ("a sparkly tower of 3", "sparkly"),
        ("a wobbly wall 4 long", "wobbly"),
        ("a 3-cube tower 6 cubes tall", "3 parts"),
    ],
)
def test_a_reading_that_drops_a_material_word_is_partial(command, dropped):
    r = plan(command)
    assert r.status == "partial"
    assert any(dropped in n for n in r.notes), r.notes
    assert r.error and "not used" in r.error


@pytest.mark.parametrize(
    "command",
    [
        "hi there, could you please build a tower of 3 for the demo? thanks!",
        "ok so, just a row of 4 cubes. The visitors come at 10.",
        "Kindly construct a 2 by 2 grid, nothing fancy",
    ],
)
def test_chatter_and_politeness_do_not_make_a_plan_partial(command):
    assert plan(command).status == "success"


def test_material_means_numbers_negations_and_structure_words():
    from sdi.language.words import is_material

    assert is_material("5", "NUM")
    assert is_material("not", "PART")
    assert is_material("left", "ADJ")
    assert is_material("wobbly", "ADJ")
    assert not is_material("please", "INTJ")
    assert not is_material("the", "DET")
    assert not is_material("build", "VERB")


def test_typos_are_corrected_and_reported():
    reading = read("a smal pyramd on the rigth")
    assert [s.shape for s in reading.spec.structures] == ["pyramid"]
    assert reading.spec.structures[0].region == "right"
    assert sum("corrected" in n for n in reading.notes) == 3


@pytest.mark.parametrize(
    "command, shape, slots, fixed",
    [
        # misspellings the English word list keeps, a hundred times rarer than the word meant
        ("a colum of 4 cubes", "tower", {"height": 4}, "column"),
        ("a wall 5 long, hight 3", "wall", {"length": 5, "height": 3}, "height"),
        # an English word where only a part word fits: after a number
        ("a row of 6 cubs", "row", {"length": 6}, "cubes"),
        # the same letters win a tie ("heigh" is one letter away too)
        ("a wall with 4 in the length and 2 in the heigth", "wall", {"length": 4, "height": 2},
         "height"),
    ],
)  # fmt: skip
def test_misspellings_english_keeps_are_corrected_where_they_stand(command, shape, slots, fixed):
    reading = read(command)
    (s,) = reading.spec.structures
    assert s.shape == shape and {k: getattr(s, k) for k in slots} == slots
    assert any(n.startswith("corrected") and n.endswith(f"'{fixed}'") for n in reading.notes)


@pytest.mark.parametrize("command", ["a lone cube on the left", "the cubs want a tower of 3"])
def test_an_english_word_is_not_corrected_to_a_structure_word(command):
    assert not any(n.startswith("corrected") for n in read(command).notes)


def test_a_derived_word_is_not_a_typo():
    reading = read("a stubbyish tower of 2")
    assert not any("corrected" in n for n in reading.notes)
    assert "stubbyish" in reading.material


@pytest.mark.parametrize(
    "command, check",
    [
        ("five cubes next to each other, do not stack them", lambda s: s.shape == "row"),
        ("a tower which is not on the right", lambda s: s.region != "right"),
        ("a tower, but not too high", lambda s: s.height == 3),
        ("a wall 6 long, no higher than 2 cubes", lambda s: s.height == 2),
    ],
)
def test_negations_with_one_reading_are_applied_and_stated(command, check):
    reading = read(command)
    assert check(reading.spec.structures[0]), reading.spec
    assert reading.complete and reading.notes


def test_every_error_says_what_was_understood():
    for command in ("xyzzy plugh", "construye una torre", "3 4 5"):
        r = plan(command).to_json_dict()
        assert r["status"] == "error" and "understood" in r


def test_the_command_length_limit_is_an_error_not_a_crash():
    r = plan("a tower " * 400)
    assert r.status == "error" and "limit" in (r.error or "")


# -- the family registry ------------------------------------------------------------------------
def test_every_family_has_an_entry_and_a_value_it_cannot_use_is_reported():
    from sdi.design.shapes import FAMILIES as GENERATORS

    assert set(FAMILIES) == set(GENERATORS)
    notes: list[str] = []
    material: list[str] = []
    out = check_family(StructureDraft(shape="tower", height=3, width=4), notes, material)
    assert isinstance(out, TowerSpec) and "width" not in TowerSpec.model_fields
    assert material == ["width=4"]
    assert notes and "ignored width=4" in notes[0]


def test_a_grid_given_a_height_becomes_a_block():
    notes: list[str] = []
    out = check_family(StructureDraft(shape="grid", length=2, width=3, height=2), notes, [])
    assert isinstance(out, BlockSpec)
    assert (out.shape, out.length, out.width, out.height) == ("block", 2, 3, 2)


def test_a_block_of_a_count_with_two_sides_gets_its_height():
    notes: list[str] = []
    spec = StructureDraft(shape="block", count=18, length=3, width=3)
    out = check_family(spec, notes, [])
    assert isinstance(out, BlockSpec) and out.height == 2


def test_a_family_spec_refuses_a_slot_it_cannot_use_naming_it():
    with pytest.raises(ValueError, match=r"a grid has no slot height; its slots are count, length"):
        structure("grid", length=2, height=2)
    with pytest.raises(ValueError, match="has no slot count"):
        Spec.model_validate({"structures": [{"shape": "block", "count": 18}]})
    with pytest.raises(ValueError, match="shape"):
        Spec.model_validate({"structures": [{"shape": "dome", "height": 2}]})
    assert structure("grid", length=2, width=3).describe() == "grid length=2 width=3"


def test_the_registry_slots_are_the_spec_types_fields():
    from sdi.spec.structure_spec import SHAPES, STRUCTURE_TYPES, family_slots

    assert set(FAMILIES) == set(STRUCTURE_TYPES) == set(SHAPES)
    for name, family in FAMILIES.items():
        assert family.spec_type is STRUCTURE_TYPES[name]
        assert family.slots == set(family_slots(family.spec_type))
    assert FAMILIES["castle"].slots >= {"count", "length", "width", "height"}
    assert "height" not in FAMILIES["grid"].slots and "count" not in FAMILIES["block"].slots


def test_the_model_schema_is_one_type_per_family():
    schema = Spec.model_json_schema()
    items = schema["properties"]["structures"]["items"]
    assert set(items["discriminator"]["mapping"]) == set(FAMILIES)
    grid = schema["$defs"]["GridSpec"]
    assert grid["additionalProperties"] is False and "height" not in grid["properties"]
    assert grid["required"] == ["shape"]


# -- relations in the spec ----------------------------------------------------------------------
def test_relations_must_form_a_forest():
    t = structure("tower")
    with pytest.raises(ValueError, match="cycle"):
        Spec(
            structures=(t, t),
            relations=(
                Relation(kind="on_top_of", subject=0, object=1),
                Relation(kind="next_to", subject=1, object=0),
            ),
        )
    with pytest.raises(ValueError, match="two different"):
        Spec(structures=(t,), relations=(Relation(kind="on_top_of", subject=0, object=0),))


# -- compositions rendered to English parse back to the same tree --------------------------------
_RENDER = {
    "tower": (lambda n: f"a tower of {n} cubes", "height"),
    "row": (lambda n: f"a row of {n} cubes", "length"),
    "staircase": (lambda n: f"a staircase with {n} steps", "steps"),
    "wall": (lambda n: f"a wall {n} cubes long", "length"),
    "pyramid": (lambda n: f"a pyramid with a base of {n} cubes", "length"),
}
_RELATIONS = {
    "next_to": ["{a} next to {b}", "{a} beside {b}"],
    "left": ["{a} to the left of {b}"],
    "right": ["{a} to the right of {b}"],
    "on_top_of": ["{a} on top of {b}"],
}


@settings(max_examples=60, deadline=None)
@given(
    first=st.sampled_from(sorted(_RENDER)),
    second=st.sampled_from(sorted(_RENDER)),
    n1=st.integers(2, 4),
    n2=st.integers(2, 4),
    relation=st.sampled_from(sorted(_RELATIONS)),
    form=st.integers(0, 1),
    lead=st.sampled_from(["", "please build ", "put ", "could you make "]),
)
def test_rendered_compositions_parse_back(first, second, n1, n2, relation, form, lead):
    if relation == "on_top_of" and (first, second) != ("tower", "tower"):
        second = "row" if first == "tower" else second
    render_a, slot_a = _RENDER[first]
    render_b, slot_b = _RENDER[second]
    templates = _RELATIONS[relation]
    text = lead + templates[form % len(templates)].format(a=render_a(n1), b=render_b(n2))
    reading = read(text)
    assert reading.complete, (text, reading.material)
    structures = reading.spec.structures
    assert [s.shape for s in structures] == [first, second], text
    assert getattr(structures[0], slot_a) == n1 and getattr(structures[1], slot_b) == n2, text
    [rel] = reading.spec.relations
    kind = "next_to" if relation in ("left", "right") else relation
    side = relation if relation in ("left", "right") else None
    assert (rel.kind, rel.subject, rel.object, rel.side) == (kind, 0, 1, side), text


def test_an_unreadable_command_raises_with_what_was_understood():
    with pytest.raises(SpecError) as info:
        read("the quick brown fox")
    assert info.value.understood is not None


# -- the model cross-check compares slots and relations -----------------------------------------
def test_explicit_numbers_beat_a_models_reading():
    from scripted_model import ScriptedChat
    from sdi.agents.specifier import Specifier

    wrong = {"structures": [{"shape": "tower", "height": 9, "at_x": 0.7}]}
    result = Specifier(ScriptedChat([wrong])).specify("a 3-cube tower at x = 0.4")
    [tower] = result.spec.structures
    assert (tower.height, tower.at_x) == (3, 0.4)
    assert result.source == "rules (llm disagreed)"
    assert "height" in result.notes[0] and "9" in result.notes[0]


def test_a_model_that_agrees_on_every_stated_slot_is_used():
    from scripted_model import ScriptedChat
    from sdi.agents.specifier import Specifier

    right = {
        "structures": [{"shape": "grid", "length": 3, "width": 3}, {"shape": "tower", "height": 2}],
        "relations": [{"kind": "on_top_of", "subject": 1, "object": 0}],
    }
    result = Specifier(ScriptedChat([right])).specify("a 2-high column on top of a 3x3 layer")
    assert result.source == "llm"
    missing = {**right, "relations": []}
    result = Specifier(ScriptedChat([missing])).specify("a 2-high column on top of a 3x3 layer")
    assert result.source == "rules (llm disagreed)"
    assert len(result.spec.relations) == 1


# -- sequences, references and numbers -----------------------------------------------------------
@pytest.mark.parametrize(
    "command, shape, key, value",
    [
        ("put up a column of 3. afterwards add two more cubes on it", "tower", "height", 5),
        ("start a 4-step staircase, then extend it by one more step", "staircase", "steps", 5),
        ("make a pillar of 8 and then halve it", "tower", "height", 4),
        ("a 2 by 4 slab; after that, triple its height", "block", "height", 3),
    ],
)
def test_a_later_clause_changes_the_structure_it_refers_to(command, shape, key, value):
    reading = read(command)
    [s] = reading.spec.structures
    assert (s.shape, getattr(s, key)) == (shape, value), reading.notes
    assert reading.complete


def test_removing_parts_afterwards_is_reported_not_built():
    r = plan("lay a row of 5, then pull the middle one out")
    assert r.status == "partial"
    assert len(r.layout) == 5
    assert any("cannot take parts out" in n for n in r.notes)


def test_between_puts_the_three_in_a_line():
    reading = read("a 2-cube stack between a 3-long wall and a 2x2 pad")
    shapes = [s.shape for s in reading.spec.structures]
    middle, wall = shapes.index("tower"), shapes.index("wall")
    assert (middle, wall) in {(r.subject, r.object) for r in reading.spec.relations}
    r = plan("a 2-cube stack between a wall 3 long and 1 high and a 2x2 pad")
    assert r.status == "success", r.notes
    upper = [p for p in r.layout if p.position[2] > 0.06]
    column = {(p.position[0], p.position[1]) for p in upper}
    assert len(column) == 1  # only the stack has a second level
    ((x, y),) = column
    others = [p for p in r.layout if (p.position[0], p.position[1]) != (x, y)]
    assert min(p.position[0] for p in others) < x < max(p.position[0] for p in others)


def test_ordinal_and_comparative_references_pick_one_structure():
    reading = read("a tower of 2 and a tower of 5. put a ring around the taller one")
    [rel] = reading.spec.relations
    tall = [k for k, s in enumerate(reading.spec.structures) if s.height == 5]
    assert rel.kind == "around" and rel.object == tall[0]


@pytest.mark.parametrize(
    "command, error",
    [("a tower at x = 2e9", "too large"), ("a row of inf cubes", "not a number")],
)
def test_numbers_sdi_cannot_use_are_refused(command, error):
    r = plan(command).to_json_dict()
    assert r["status"] == "error" and error in r["error"] and "understood" in r


def test_number_forms_are_read_and_stated():
    reading = read("a tower at x = 3.5e-1 and y = 0,2")
    [s] = reading.spec.structures
    assert (s.at_x, s.at_y) == (0.35, 0.2)
    assert len([n for n in reading.notes if n.startswith("read")]) == 2


# -- no command crashes the front end -----------------------------------------------------------
_SALAD = sorted(
    {
        *("tower", "towers", "row", "grid", "wall", "bridge", "ring", "pyramid", "staircase"),
        *("castle", "canopy", "arch", "L", "U", "pad", "slab", "base", "layer", "beam", "cube"),
        *("on", "top", "of", "it", "them", "then", "and", "with", "a", "the", "not", "no"),
        *("between", "around", "inside", "next", "to", "beside", "behind", "joined", "by"),
        *("each", "one", "two", "three", "10", "cm", "x", "=", "0.4", "(", ")", ",", ".", ";"),
        *("-", "another", "second", "first", "more", "than", "half", "twice", "make", "put"),
        *("take", "off", "add", "until", "@", "#12", "1e3", "5/6", "2+3", "L=4", "left", "back"),
        *("tall", "wide", "small", "high", "long", "steps", "levels", "don't", "isn't", "\n"),
    }
)


@settings(max_examples=150, deadline=None)
@given(st.lists(st.sampled_from(_SALAD), min_size=1, max_size=18))
def test_no_word_salad_crashes_the_front_end(tokens):
    result = plan(" ".join(tokens))
    data = result.to_json_dict()
    assert data["status"] in ("success", "partial", "failure", "error")
    if data["status"] == "error":
        assert "understood" in data and data["error"]
    if data["status"] == "success":
        assert result.reading is not None and result.reading.complete


# -- constructions that must be read, or refused honestly ------------------------------------
def test_a_negative_count_is_refused_but_a_negative_coordinate_is_not_a_count():
    with pytest.raises(SpecError, match="cannot be negative"):
        read("please make -3 walls")
    assert read("a 2-cube tower at x = -0.1 m").spec.structures[0].at_x == pytest.approx(-0.1)
    bullets = read("- row\n- 4 cubes\n- front side")  # list bullets are not minus signs
    assert bullets.spec.structures[0].length == 4


def test_anywhere_but_a_side_is_the_other_side():
    r = read("anywhere but the left: a row of 3")
    assert r.spec.structures[0].region == "right"


def test_in_after_a_number_before_a_dimension_is_inches():
    r = plan("a row, 8 in long")  # 8 inches = 0.2032 m: four 5 cm cubes
    assert r.status == "success", r.notes
    assert len(r.layout) == 4


def test_an_unread_comparison_is_never_a_silent_success():
    r = plan("two rows, the front one longer than the back one")
    assert r.status == "partial"
    assert any("longer than" in n for n in r.notes)


def test_a_difference_from_the_number_said_before_is_computed():
    r = read("two stacks: one of 4, the other 2 more than that")
    assert sorted(s.height for s in r.spec.structures) == [4, 6]


def test_one_item_per_copy_shares_the_description_out():
    r = read("three rows of 4, one on the left, one in the middle, one on the right")
    assert [s.length for s in r.spec.structures] == [4, 4, 4]
    assert [s.region for s in r.spec.structures] == ["left", "centre", "right"]


def test_a_restated_value_in_a_later_clause_is_kept_and_a_different_one_reported():
    assert read("a wall 3 long. THREE").spec.structures[0].length == 3
    r = plan("a row of 6. 2")
    assert r.status == "partial"


def test_an_english_word_is_not_corrected_into_a_structure_with_another_first_letter():
    with pytest.raises(SpecError):
        read("shut the robot down")


def test_spaced_out_with_several_structures_keeps_each_structure_whole():
    r = read("a 2x2 pad and a row of 4, spaced out")
    assert [s.shape for s in r.spec.structures] == ["grid", "row"]
    assert all(getattr(s, "gap_m", None) is None for s in r.spec.structures)
    one = read("a row of 4, spaced out")  # one structure: its parts apart
    assert one.spec.structures[0].gap_m == pytest.approx(0.05)


def test_separate_cubes_stand_apart():
    r = plan("put three separate cubes in a row")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    xs = sorted(zip(lo[:, 0], hi[:, 0], strict=True))
    ys = sorted(zip(lo[:, 1], hi[:, 1], strict=True))
    assert len(lo) == 3
    apart_x = all(b[0] - a[1] > 0.01 for a, b in itertools.pairwise(xs))
    apart_y = all(b[0] - a[1] > 0.01 for a, b in itertools.pairwise(ys))
    assert apart_x or apart_y


def test_two_sizes_in_metres_go_to_two_sides_or_are_reported():
    s = read("a slab 10 cm wide and 20 cm deep").spec.structures[0]
    # a slab's width slot runs front to back (x), its length left to right (y)
    assert (s.width_m, s.length_m) == (pytest.approx(0.20), pytest.approx(0.10))
    w = read("wall, height 10cm, length 30cm").spec.structures[0]
    assert (w.height_m, w.length_m) == (pytest.approx(0.10), pytest.approx(0.30))


def test_which_side_runs_left_to_right_is_read():
    s = read("a 2 by 4 slab, long side left to right").spec.structures[0]
    assert (s.length, s.width, s.axis) == (4, 2, "y")
    # a gloss that says what width or depth means confirms it; it does not turn the slab
    t = read("a slab 10 cm wide (left to right) and 20 cm deep").spec.structures[0]
    assert (t.width_m, t.length_m) == (pytest.approx(0.20), pytest.approx(0.10))
    g = plan("a grid 2 cubes deep (away from the robot) and 5 cubes wide")
    lo, hi = boxes(g)
    assert g.status == "success" and len(lo) == 10
    assert (hi[:, 0].max() - lo[:, 0].min(), hi[:, 1].max() - lo[:, 1].min()) == (
        pytest.approx(0.10, abs=0.01),
        pytest.approx(0.25, abs=0.01),
    )


def test_a_slab_minus_its_middle_is_a_ring():
    assert read("a 4x4 slab minus its middle").spec.structures[0].shape == "enclosure"


def test_a_pens_floor_is_its_inside():
    r = read("a 2-cube tower inside a pen that has a 2 by 2 floor")
    pen = next(s for s in r.spec.structures if s.shape == "enclosure")
    assert (pen.length, pen.width) == (4, 4)
    assert len(r.spec.structures) == 2


def test_one_behind_the_other_places_the_second_copy():
    r = read("two rows of 3, one in front of the other")
    assert [s.length for s in r.spec.structures] == [3, 3]
    (rel,) = r.spec.relations
    assert (rel.kind, rel.side) == ("next_to", "front")


def test_fractions_of_a_metre_and_a_half_dozen_are_numbers():
    assert read("a tower 2 tenths of a metre tall").spec.structures[0].height_m == pytest.approx(
        0.2
    )
    assert read("a row 1/4 of a meter long").spec.structures[0].length_m == pytest.approx(0.25)
    assert read("a row of a half dozen cubes").spec.structures[0].length == 6


def test_an_intensifier_before_a_place_is_not_a_lost_word():
    r = plan("a row of 3 at the front and a 2-cube tower immediately behind it")
    assert r.status == "success", r.notes
    assert read("a 4-cube tower, dead centre").spec.structures[0].region == "centre"


def test_the_same_again_is_another_one_and_apiece_is_each():
    r = read("a row of 2 on the left. then the same again on the right")
    assert [(s.length, s.region) for s in r.spec.structures] == [(2, "left"), (2, "right")]
    assert [s.height for s in read("three towers, four cubes apiece").spec.structures] == [4] * 3


def test_a_row_that_does_not_run_one_way_runs_the_other():
    assert read("a row of 5 which does not run front to back").spec.structures[0].axis == "y"


def test_a_structure_placed_beside_and_touching_has_no_gap():
    r = plan("a 2-cube tower, and a 3-cube tower to its right, touching it")
    assert r.status == "success" and any("touching" in n for n in r.notes)
    cols = columns(r)
    (y_right, h_right), (y_left, h_left) = sorted((y, h) for (_, y), h in cols.items())
    assert (h_right, h_left) == (3, 2)  # the 3-cube tower on the right (-y)
    assert abs((y_left - y_right) - 0.05) < 0.002  # side by side, faces together


def test_a_beam_over_a_gates_posts_is_the_gates_own():
    # an arch said by its posts and a beam is that post-and-beam: SDI's bridge, said so (SDI's
    # arch steps corbels in under its beam)
    r = read("an arch with two posts 3 high and a beam over them")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 3)]
    assert any("posts and a beam as a bridge" in n for n in r.notes)


def test_a_noun_that_means_tall_is_tall_unless_a_size_is_given():
    assert read("build a spire").spec.structures[0].height == 6
    assert read("a 4-cube obelisk").spec.structures[0].height == 4


def test_a_sentence_marked_unrelated_is_not_read():
    r = plan("Row 2 of the shelf is empty (unrelated). Please make a 3-cube tower.")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.reading.spec.structures] == ["tower"]


def test_a_walls_part_count_gives_its_courses_or_is_reported():
    assert read("a wall of 12 cubes, 4 long").spec.structures[0].height == 3
    assert read("wall: 10 cubes, 5 per course").spec.structures[0].height == 2
    r = plan("a wall of 10 cubes, 4 long")
    assert r.status == "partial"


def test_all_the_way_round_and_bump_it_up_are_read():
    r = read("a 2-cube tower with a ring all the way round it")
    assert [x.kind for x in r.spec.relations] == ["around"]
    w = read("a 4-long wall two courses tall, then bump it up another course")
    assert w.spec.structures[0].height == 3


def test_a_total_in_an_aside_is_checked_against_the_sides():
    b = read("a 2x2 block, two layers (8 cubes)").spec.structures[0]
    assert (b.length, b.width, b.height) == (2, 2, 2)
    assert plan("a 2x2 block, two layers (8 cubes)").status == "success"
    assert plan("a 2x2 block, two layers (10 cubes)").status == "partial"


def test_no_gaps_in_it_is_not_a_relation():
    r = plan("a 4x4 ring with no gaps in it")
    assert r.status == "success", r.notes
    assert not r.reading.spec.relations


def test_a_booth_or_hall_number_is_a_reference_not_a_size():
    r = plan("for the expo (booth 7) an L shape")
    assert r.status == "success", r.notes
    assert r.reading.spec.structures[0].length != 7


def test_a_block_the_same_size_on_every_side_is_a_cube_of_that_size():
    b = read("a solid block 2 cubes on every side").spec.structures[0]
    assert (b.length, b.width, b.height) == (2, 2, 2)
    ring = read("a ring 4 cubes on each side").spec.structures[0]  # a flat family: its sides
    assert (ring.length, ring.width) == (4, 4)


def test_nothing_taller_than_is_the_most_allowed():
    r = read("nothing taller than 3 cubes: a 2 by 2 block")
    assert r.spec.structures[0].height == 3
    assert plan("nothing taller than 3 cubes: a 2 by 2 block").status == "success"


def test_a_staircase_that_does_not_climb_one_way_climbs_the_other():
    s = read("a staircase of 3 that does not go up towards the back").spec.structures[0]
    assert (s.axis, s.yaw_deg) == ("x", 180.0)
    r = plan("a staircase of 3 that does not go up towards the back")
    lo, hi = boxes(r)
    top = int(np.argmax(hi[:, 2]))
    assert lo[top, 0] == pytest.approx(lo[:, 0].min())  # the highest step is at the front


# -- self-corrections, changes by the main size, components, chatter numbers ---------------------
@pytest.mark.parametrize(
    ("command", "key", "value", "said"),
    [
        ("lay out a line of 6 cubes, no wait, 7", "length", 7, "'6' → '7'"),
        ("a 2x4 slab, sorry, not 2x4, 2x3", "width", 3, "'2 x 4' → '2 x 3'"),
        ("a wall 20 cm long, i mean 30 cm", "length", 6, "'20 cm' → '30 cm'"),
    ],
)
def test_a_correction_in_the_command_replaces_the_value_it_corrects(command, key, value, said):
    r = read(command)
    s = r.spec.structures[0]
    got = getattr(s, key, None) or round((getattr(s, f"{key}_m", 0) or 0) / 0.05)
    assert got == value and r.complete
    assert any(said in n for n in r.notes), r.notes


def test_a_corrected_region_moves_the_structure():
    r = plan("a 3-cube stack on the right, actually the left")
    lo, _hi = boxes(r)
    assert r.status == "success" and lo[:, 1].min() > 0.30  # left is +y


@pytest.mark.parametrize(
    ("command", "key", "value"),
    [
        ("a line of 5 cubes. then make it 3", "length", 3),
        ("stack 6 cubes; no wait, make it 2", "height", 2),
        ("a 4-step staircase. make it 2", "steps", 2),
    ],
)
def test_make_it_n_sets_the_size_the_structure_was_given(command, key, value):
    r = read(command)
    assert len(r.spec.structures) == 1 and getattr(r.spec.structures[0], key) == value
    assert r.complete


def test_make_it_n_on_a_structure_with_two_sizes_is_not_guessed():
    r = plan("a 3 by 4 pad. then make it 5")
    assert r.status != "success"  # which side is 5 is not said


def test_a_later_clause_about_pillars_sizes_the_bridge_before():
    r = plan("a bridge please. its pillars 4 high.")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 2 * 4 + 1 and np.isclose(hi[:, 2].max(), 5 * 0.05)


def test_towers_and_a_beam_across_are_one_bridge():
    r = plan("two columns of 2 cubes and one beam across them")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 5 and len(r.spec.structures) == 1
    top = hi[:, 2] > 0.11
    assert top.sum() == 1 and (hi[top, :2] - lo[top, :2]).max() > 0.1  # the beam spans


@pytest.mark.parametrize(
    "command",
    [
        "shift B handover at 6:30 - build a 3-cube tower",
        "Page 12 of the manual says: a tower of 3",
        "the team meeting is at 2pm, meanwhile a 3 cube tower",
    ],
)
def test_times_and_reference_numbers_are_not_sizes(command):
    r = plan(command)
    assert r.status == "success", r.notes
    lo, _hi = boxes(r)
    assert len(lo) == 3 and len(r.spec.structures) == 1


def test_an_offset_from_the_centre_is_a_coordinate():
    r = plan("a 2-cube tower 15 cm to the right of the centre")
    lo, hi = boxes(r)
    assert np.isclose((lo[:, 1].min() + hi[:, 1].max()) / 2, 0.30 - 0.15)
    assert any("y = 0.15" in n for n in r.notes)


def test_wide_is_left_to_right_and_deep_front_to_back():
    for command in ("a pad 2 wide and 4 deep", "a pad 2 across, 4 back", "a 4 deep, 2 wide pad"):
        lo, hi = boxes(plan(command))
        assert np.isclose(hi[:, 0].max() - lo[:, 0].min(), 0.20), command  # 4 deep along x
        assert np.isclose(hi[:, 1].max() - lo[:, 1].min(), 0.10), command  # 2 wide along y


@pytest.mark.parametrize(
    ("command", "height"),
    [("a stack of ten minus 7", 3), ("two rows, one of 6 and one of 3 fewer", None)],
)
def test_spoken_arithmetic_is_computed(command, height):
    r = read(command)
    if height:
        assert r.spec.structures[0].height == height
    else:
        assert sorted(s.length for s in r.spec.structures) == [3, 6]
    assert r.complete


def test_the_same_family_with_the_names_the_one_named_before():
    r = read("an L and a tower next to each other, the L on the right")
    assert [s.shape for s in r.spec.structures].count("l_shape") == 1
    assert next(s for s in r.spec.structures if s.shape == "l_shape").region == "right"


@pytest.mark.parametrize(
    "command",
    [
        "the right tower twice as tall as a 3-cube tower on the left, which is lower",
        "a tower floating above the table",
        "a wall, but turn it",
    ],
)
def test_a_size_or_direction_word_left_unused_is_never_a_silent_success(command):
    r = plan(command)
    assert r.status != "success" or any(
        w in " ".join(r.notes) for w in ("twice", "floating", "turn", "lower")
    )


# -- distributive placement: one copy at each corner or end -------------------------------------
def test_a_copy_on_each_corner_of_the_top_face():
    r = plan("a 3-high stack on each corner of a 5 by 5 pad")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 25 + 4 * 3
    up = lo[:, 2] > 0.01
    pad_lo, pad_hi = lo[~up].min(axis=0), hi[~up].max(axis=0)
    # four columns, each flush with one corner of the pad
    for cx, cy in itertools.product((pad_lo[0], pad_hi[0]), (pad_lo[1], pad_hi[1])):
        at = up & (np.isclose(lo[:, 0], cx) | np.isclose(hi[:, 0], cx))
        at &= np.isclose(lo[:, 1], cy) | np.isclose(hi[:, 1], cy)
        assert at.sum() == 3, (cx, cy)


def test_towers_at_both_ends_stand_against_the_ends():
    r = plan("a wall 4 long and 1 high with a 3-cube tower at each end of it")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 4 + 6
    tall = hi[:, 2] > 0.06
    ys = sorted({round(float(v), 3) for v in (lo[tall, 1] + hi[tall, 1]) / 2})
    assert len(ys) == 2 and np.isclose(ys[1] - ys[0], 5 * 0.05)  # either side of 4 cubes


def test_one_corner_is_a_single_copy_and_an_impossible_spread_is_an_error():
    r = plan("a 3x3 slab with a 2-cube tower standing on one corner of it")
    lo, _hi = boxes(r)
    assert len(lo) == 9 + 2
    r = plan("a 2x2 slab with a 2x2 pad on each corner")
    assert r.status != "success" and r.layout is None


def test_a_relation_at_corners_is_part_of_the_spec_and_refused_for_a_ring():
    Relation(kind="on_top_of", subject=1, object=0, at="corners")
    with pytest.raises(ValueError, match="at:"):
        Relation(kind="around", subject=1, object=0, at="corners")


# -- negated sides, limits, labels, what cannot be built ----------------------------------------
def test_neither_side_of_an_axis_is_its_centre():
    for command in (
        "a 3-cube tower, not on the left or on the right",
        "not front, not back: a tower",
    ):
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        lo, hi = boxes(r)
        centre = ((lo[:, 0].min() + hi[:, 0].max()) / 2, (lo[:, 1].min() + hi[:, 1].max()) / 2)
        assert np.allclose(centre, (0.45, 0.30), atol=0.03), command


def test_a_stated_maximum_is_built_and_said():
    r = read("a bridge please, but do not make it taller than 3")
    assert r.spec.structures[0].height == 3 and any("at most 3" in n for n in r.notes)


def test_floating_or_below_the_table_is_never_a_silent_success():
    for command in ("a 3-cube tower hovering above the table", "a row of 4 sunk into the table"):
        r = plan(command)
        assert r.status == "partial", command
        assert any("stands on the table" in n for n in r.notes)


def test_labelled_sizes_go_to_the_labelled_sides():
    r = read("a block 4 x 2 x 3 (H x W x L)")
    s = r.spec.structures[0]
    assert (s.height, s.width, s.length) == (4, 2, 3)
    r = read("a pad 10 x 20 cm (w x d)")
    lo, hi = boxes(plan("a pad 10 x 20 cm (w x d)"))
    assert np.isclose(hi[:, 0].max() - lo[:, 0].min(), 0.20)  # deep: front to back


def test_a_second_relation_for_one_structure_is_reported_not_raised():
    from sdi.language.reader import _one_each
    from sdi.language.state import ReadState
    from sdi.model.cell import CellConfig

    st_ = ReadState("x", CellConfig())
    rels = [Relation(kind="next_to", subject=1, object=0, side="back"),
            Relation(kind="next_to", subject=1, object=2)]  # fmt: skip
    assert _one_each(rels, st_) == rels[:1]
    assert st_.material == ["relation next_to"] and "already placed" in st_.notes[0]
    r = plan("two rows of 4, one behind the other, and a gap of one cube between them")
    assert r.status == "success" and r.spec.relations[0].gap_m == pytest.approx(0.05)


def test_a_cube_fits_inside_a_ring_of_four():
    r = plan("a single cube inside a 4 by 4 ring")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    inner = (hi[:, 2] < 0.06) & np.isclose(lo[:, 0], 0.425) & np.isclose(lo[:, 1], 0.275)
    assert len(lo) == 12 + 1 and inner.sum() <= 1


# -- coherence: what the sentence structure says and a reading leaves out ------------------------
def _coherence(command, *structures, relations=()):
    from sdi.language import coherence
    from sdi.language.state import ReadState
    from sdi.language.syntax import parse
    from sdi.model.cell import CellConfig

    st_ = ReadState(command, CellConfig())
    spec = Spec(structures=tuple(structures), relations=tuple(relations))
    doc = parse(command)
    coherence.check(doc, spec, st_, set(range(len(doc))))
    return st_.material


def test_a_relation_the_reading_lost_is_material():
    grid, tower = structure("grid", length=3, width=3), structure("tower", height=3)
    assert _coherence("On the base, put a tower of 3.", grid, tower) == ["On the base"]
    related = (Relation(kind="on_top_of", subject=1, object=0),)
    assert _coherence("On the base, put a tower of 3.", grid, tower, relations=related) == []
    # regions and side-by-side words are no relation to lose
    left, right = (
        tower.model_copy(update={"region": "left"}),
        grid.model_copy(update={"region": "right"}),
    )
    assert _coherence("a tower on the left and a row on the right", left, right) == []
    assert _coherence("a tower and a row next to each other", tower, grid) == []


def test_a_count_the_reading_does_not_have_is_material():
    tower = structure("tower", height=4)
    assert "three stacks" in _coherence("three stacks, 4 high", tower, tower)
    assert _coherence("three stacks, 4 high", tower, tower, tower, tower) == ["three stacks"]
    assert _coherence("three stacks, 4 high", tower, tower, tower) == []
    bridge = structure("bridge", height=3)
    assert _coherence("two towers joined by a beam", bridge) == []  # made of the two


# -- shop-floor shorthand ---------------------------------------------------------------------
@pytest.mark.parametrize(
    ("command", "shape", "slots"),
    [
        ("tower 6ht", "tower", {"height": 6}),
        ("wall 5 lng 3 hgt", "wall", {"length": 5, "height": 3}),
        ("pyramid 3 lvls", "pyramid", {"height": 3}),
        ("row of 7 pcs", "row", {"length": 7}),
        ("L w/ arms 5 n 2", "l_shape", {"length": 5, "width": 2}),
        ("bridge pillars 4 high", "bridge", {"height": 4}),
    ],
)
def test_shorthand_is_expanded_and_noted(command, shape, slots):
    r = read(command)
    s = r.spec.structures[0]
    assert len(r.spec.structures) == 1 and s.shape == shape
    assert all(getattr(s, k) == v for k, v in slots.items()), s
    assert r.complete


def test_counts_and_plus_signs_in_a_terse_order():
    r = read("3x stack 2ht + 1x stack 4ht")
    assert sorted(s.height for s in r.spec.structures) == [2, 2, 2, 4]
    assert any("as 'and'" in n for n in r.notes)


def test_a_corner_abbreviation_places_the_structure_there():
    lo, hi = boxes(plan("pad 2x2 front right cnr"))
    assert lo[:, 0].min() < 0.40 and hi[:, 1].max() < 0.25  # front = low x, right = low y


# -- the gap between structures ------------------------------------------------------------------
def _clear_y(lo, hi, a, b):
    """Clear space along y between the parts selected by masks a and b."""
    return max(lo[b, 1].min() - hi[a, 1].max(), lo[a, 1].min() - hi[b, 1].max())


def test_a_stated_gap_is_the_space_beside_the_other_structure():
    r = plan("a 3-cube tower to the right of a 2x2 pad, a two cube gap")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    tall = hi[:, 2] > 0.06
    column = np.isclose(lo[:, 1], lo[tall, 1].min())  # the tower's column of parts
    assert len(lo) == 4 + 3 and np.isclose(_clear_y(lo, hi, column, ~column), 0.10)


def test_a_stated_gap_separates_unrelated_structures():
    r = plan("three stacks of 2, with 1 cube gap")
    lo, _hi = boxes(r)
    ys = sorted({round(float(v), 4) for v in lo[:, 1]})
    assert len(ys) == 3 and np.allclose(np.diff(ys), 0.10)  # 0.05 wide + 0.05 apart


def test_a_distance_to_its_side_is_the_gap_of_that_relation():
    rel = read("a wall 3 long, then an identical wall 15 cm behind it").spec.relations
    assert len(rel) == 1 and rel[0].side == "back" and rel[0].gap_m == pytest.approx(0.15)


def test_a_gap_inside_one_structure_or_under_a_bridge_is_not_between_structures():
    assert read("a row of 4 cubes with a one-cube gap between each cube").spec.gap_m is None
    bridge = read("a bridge over a gap of 2 cubes").spec
    assert bridge.gap_m is None and bridge.structures[0].shape == "bridge"


def test_a_number_that_shows_nowhere_in_the_reading_is_material():
    ring = structure("enclosure", length=4, width=4, height=2)
    assert _coherence("a ring 4x4 2 high, 3 of them", ring) == ["3"]
    assert _coherence("a ring 4x4 2 high, 3 of them", ring, ring, ring) == []
    r = plan("ring 3x3 2 ht, 3 of them")
    assert r.status == "success" and len(r.spec.structures) == 3


@pytest.mark.parametrize(
    "command",
    [
        "pad 150x100 mm",  # millimetres read as parts
        "a tower of 5. Actually no, make it 6.",  # superseded, and said so
        "mic check 1 2 3. a row of 4 cubes",  # counting aloud
        "for my class of 10-year-olds: a staircase with 3 steps",  # an age
        "phase two of the demo: a 3 by 3 pad",  # a name
    ],
)
def test_numbers_shown_converted_superseded_or_not_sizes_are_no_alarm(command):
    r = plan(command)
    assert not any("shows nowhere" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("command", "shapes"),
    [
        ("pad 3x3, 2 of them", ["grid", "grid"]),
        ("a boundary wall around nothing in particular", ["enclosure"]),
        ("two stacks of 3 with something across them", ["bridge"]),
        ("a 4x4 slab, leave out the middle ones", ["enclosure"]),
        ("right from a tower of 2, a wall of 3", ["wall", "tower"]),
    ],
)
def test_ways_of_saying_copies_rings_beams_and_sides(command, shapes):
    r = read(command)
    assert sorted(s.shape for s in r.spec.structures) == sorted(shapes), r.notes
    if "right from" in command:
        assert r.spec.relations[0].side == "right"


def test_a_square_base_said_per_side_is_square():
    lo, hi = boxes(plan("pyramid, the base is 20 cm each side"))
    assert np.isclose(hi[:, 0].max() - lo[:, 0].min(), 0.20)
    assert np.isclose(hi[:, 1].max() - lo[:, 1].min(), 0.20)


@pytest.mark.parametrize(
    ("command", "shape", "slots"),
    [
        ("a 4x4 ring, one high. Then fill it in.", "grid", {"length": 4, "width": 4}),
        ("4 layers of 3x3, then remove the top layer", "block", {"height": 3}),
        ("a balustrade four long and two high", "wall", {"length": 4, "height": 2}),
        ("two pallets of 2x2, 2 high", "block", {"length": 2, "width": 2, "height": 2}),
        ("a slab 25 cm square, 5 cm thick", "grid", {"length": 5, "width": 5}),
    ],
)
def test_fill_in_unload_and_trade_words(command, shape, slots):
    r = plan(command)
    assert r.status == "success", r.notes
    s = r.spec.structures[0]
    assert s.shape == shape and all(getattr(s, k) == v for k, v in slots.items()), s


def test_something_to_pass_under_is_a_bridge_and_an_english_word_is_no_typo():
    r = read("something a toy car could drive under")
    assert r.spec.structures[0].shape == "bridge"
    r = read("a tower, the visitors walk past it")
    assert not any("to 'wall'" in n for n in r.notes)


@pytest.mark.parametrize(
    ("command", "shapes", "slots"),
    [
        ("make a row nine long, no sorry, seven long", ["row"], {"length": 7}),
        ("a tower uh six um no wait five high", ["tower"], {"height": 5}),
        ("a pyramid no not a pyramid a staircase of 4", ["staircase"], {"steps": 4}),
        ("qty: 2\nitem: wall\nheight_cubes: 3", ["wall", "wall"], {"height": 3}),
        ("type: slab\nwidth: 15cm\ndepth: 10cm", ["grid"], {}),
        ("a gate without the beam: just its two pillars of 4", ["tower", "tower"], {"height": 4}),
    ],
)
def test_spoken_corrections_and_pasted_forms(command, shapes, slots):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == shapes
    assert all(getattr(s, k) == v for s in r.spec.structures for k, v in slots.items())


@pytest.mark.parametrize(
    ("command", "shapes", "slots", "said"),
    [
        # a speech recogniser's numbers, each said in a note
        ("a pillar for high and a pillar to high", ["tower", "tower"], None, "'for' as 'four'"),
        ("a row of for please", ["row"], {"length": 4}, "'for' as 'four'"),
        ("a stack of tree", ["tower"], {"height": 3}, "'tree' as 'three'"),
        ("only won cube on the left", ["tower"], {"height": 1}, "'won' as 'one'"),
        # spoken corrections with no commas, a ticket's later line, "not A, B"
        ("a row with uh six cubes no seven cubes", ["row"], {"length": 7}, "'six' → 'seven'"),
        ("a pillar of four um no not four three", ["tower"], {"height": 3}, "'four' → 'three'"),
        ("Wall L=5 H=4. EDIT: H=2, not 4", ["wall"], {"height": 2}, "→ '2 high'"),
        ("2 pyramids, no wait, 3 pyramids", ["pyramid"] * 3, None, "'2 pyramids' → "),
        ("a row not of eight, of six", ["row"], {"length": 6}, "'eight' → 'six'"),
    ],
)
def test_what_a_speech_recogniser_writes(command, shapes, slots, said):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == shapes
    assert all(getattr(s, k) == v for s in r.spec.structures for k, v in (slots or {}).items())
    assert any(said in n for n in r.notes), r.notes


def test_to_and_for_stay_words_where_a_number_cannot_stand():
    r = plan("a row of 3 next to a tower of 2, not too tall, for the demo")
    assert sorted(s.shape for s in r.spec.structures) == ["row", "tower"]
    assert not any(" as 'two'" in n or " as 'four'" in n for n in r.notes), r.notes
    assert plan("a tower of 4 next to the pyramid").spec.structures[0].height == 4


def test_a_number_left_over_is_not_dropped_silently_unless_it_repeats_one_used():
    r = plan("a pillar of 5. SEVEN")
    assert r.status == "partial" and "SEVEN" in (r.error or ""), r.notes
    r = plan("a pillar of 5. not 4, FIVE")  # the number said again: nothing dropped
    assert r.status == "success" and r.spec.structures[0].height == 5, r.notes
    r = plan("Let's count: one, two, three - a row of 3 cubes")  # counting aloud: no size
    assert r.status == "success", r.notes


@pytest.mark.parametrize(
    ("command", "heights", "said"),
    [
        # "floors" of a structure named before are its levels; a floor said alone is a slab
        ("a pyramid of three floors", None, "'three floors' as three levels of the pyramid"),
        ("a tower of 3 floors", [3], "as 3 levels of the tower"),
        # a count said after the plural that names them ("4-high" is no count)
        ("Pillars of five, two of them", [5, 5], "as two pillars"),
        ("4-high stacks, three of them; not one should touch another one", [4, 4, 4], "three"),
        # "another" with its own size is a second structure, not a change of the first
        ("a stack of 2 and another 5 high", [2, 5], None),
        ("a stack of 3 and another with double the height", [3, 6], "as 6 (from the 3"),
        ("the stack of 4 and the other stack, it has double of the height", [4, 8], "as 8"),
    ],
)
def test_levels_counts_and_another_said_the_way_non_native_speakers_say_them(
    command, heights, said
):
    r = plan(command)
    assert r.status == "success", r.notes
    if heights is not None:
        assert sorted(s.height for s in r.spec.structures) == heights
    else:
        assert [(s.shape, s.height) for s in r.spec.structures] == [("pyramid", 3)]
    assert said is None or any(said in n for n in r.notes), r.notes


def test_a_dimension_word_before_its_value_and_a_staircase_climbing_said_last():
    s = plan("a slab, side 20 cm, thick 10 cm").spec.structures[0]
    assert (s.length_m, s.width_m, s.height_m) == (0.2, 0.2, 0.1)  # not side 0.1, 0.2 thick
    s = plan("a wall, long 6, high 3").spec.structures[0]
    assert (s.length, s.height) == (6, 3)
    s = plan("Stairs, five of them, up to the left climbing").spec.structures[0]
    assert (s.shape, s.steps, s.axis, s.region) == ("staircase", 5, "y", None)
    assert plan("a 3 by 3 floor").spec.structures[0].shape == "grid"  # "3 floor" is no level


@pytest.mark.parametrize(
    ("command", "subject", "object_", "side", "gap"),
    [
        # the structure said after "behind it" / "to the left of it" stands there, beside the
        # one said before — in one sentence, after a full stop, with a gap said after it
        ("a ring 4x4 and behind it a row of 3", "row", "enclosure", "back", None),
        ("a block 2x2x2. To the right of it a stack of 5", "tower", "block", "right", None),
        ("a staircase of 3 and right from it one tower of 6", "tower", "staircase", "right", None),
        ("a pad 3x3 and in front of it a stack of 2, at a distance of 2 cubes", "tower", "grid",
         "front", 0.1),
    ],
)  # fmt: skip
def test_a_relation_said_before_its_subject_with_a_pronoun(command, subject, object_, side, gap):
    r = plan(command)
    assert r.status == "success", r.notes
    [rel] = r.spec.relations
    shapes = [s.shape for s in r.spec.structures]
    assert (shapes[rel.subject], shapes[rel.object], rel.side) == (subject, object_, side)
    assert rel.gap_m == gap or (gap is None and r.spec.gap_m is None)


def test_a_little_one_added_is_a_second_structure_of_the_same_kind_but_not_in_apposition():
    r = plan("a stack of 6, and beside it a small one only half as tall")
    assert r.status == "success", r.notes
    assert sorted(s.height for s in r.spec.structures) == [3, 6]
    r = plan("a stack of 4 and then a tiny one of 1")
    assert sorted(s.height for s in r.spec.structures) == [1, 4]
    r = plan("three levels, the pyramid, a big one please")  # the same pyramid
    assert [s.shape for s in r.spec.structures] == ["pyramid"]


@pytest.mark.parametrize(
    "command",
    [
        "two stacks of 4, then put a beam across the two",
        "two stacks of 4, then a beam across both",
        "two stacks of 4 and a long beam across them",
        "two stacks of 4; then a beam from the first across to the other one",
    ],
)
def test_a_beam_across_the_two_rests_on_both(command):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 4)]


def test_a_walls_count_that_cannot_fill_its_levels_is_its_length_and_either_reading_is_said():
    r = plan("a wall of 7 cubes, 3 high")  # 7 cannot fill 3 levels: 7 long (it built 9 parts)
    s = r.spec.structures[0]
    assert (s.length, s.height, len(r.layout)) == (7, 3, 21)
    assert any("7 cannot fill 3 levels" in n for n in r.notes), r.notes
    r = plan("a wall of 8 cubes, 2 high")  # 8 in all, 4 long: the reading is said
    assert (r.spec.structures[0].count, len(r.layout)) == (8, 8)
    assert any("say '8 long'" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("command", "shapes", "region"),
    [
        # a correction that names another structure takes back the one said last
        ("a stack of 4. scratch that, make it a pyramid", ["pyramid"], None),
        ("a stack of 2 on the left, no wait, make it a row of 3", ["row"], "left"),
        ("a ring 4x4, actually a block 2x2 instead", ["block"], None),
        ("a row of 3 and a stack of 5. Change of plan: an arch", ["row", "arch"], None),
        # ... but not a change of its parts, and not one more
        ("a bridge on pillars of 3. actually make the pillars 2", ["bridge"], None),
        ("a stack of 3, and actually a pyramid as well", ["tower", "pyramid"], None),
    ],
)
def test_a_correction_that_names_another_structure_replaces_the_last(command, shapes, region):
    r = plan(command)
    assert [s.shape for s in r.spec.structures] == shapes, r.notes
    assert region is None or r.spec.structures[-1].region == region


def test_structures_in_a_line_front_to_back_stand_one_behind_the_other():
    r = plan("4 stacks of 2 in a row from front to back, 1 cube gaps")
    assert r.status == "success" and r.spec.line == "x", r.notes
    xs = sorted({round(p.position[0], 3) for p in r.layout})
    ys = {round(p.position[1], 3) for p in r.layout}
    assert len(xs) == 4 and len(ys) == 1  # along x (front to back), one y
    assert all(np.isclose(b - a, 0.05 + 0.05) for a, b in itertools.pairwise(xs))  # 1-cube gaps
    r = plan("4 stacks of 2 in a row")  # no direction: side by side along y, as before
    assert r.spec.line is None and len({round(p.position[1], 3) for p in r.layout}) == 4


def test_a_width_said_with_from_left_to_right_runs_left_to_right():
    r = plan("a pad six cubes across from left to right and two deep")
    xs = {round(p.position[0], 3) for p in r.layout}
    ys = {round(p.position[1], 3) for p in r.layout}
    assert (len(xs), len(ys)) == (2, 6)  # six along y (left to right), two along x (deep)


def test_a_second_layer_said_alone_goes_on_top_and_so_does_a_third():
    r = plan("a 3x2 pad. then a second layer, the same. then a third.")
    assert r.status == "success", r.notes
    zs = sorted({round(p.position[2], 3) for p in r.layout})
    assert len(zs) == 3 and len(r.layout) == 18  # one 3x2 block three levels high
    assert len({(round(p.position[0], 3), round(p.position[1], 3)) for p in r.layout}) == 6


@pytest.mark.parametrize(
    ("command", "region"),
    [
        ("a stack of 4, don't use the right half of the table", "left"),  # it was built there
        ("a row of 3 and stay out of the front part", "back"),
        ("a pad 2x2, never touch the back side of the table", "front"),
    ],
)
def test_a_half_of_the_table_to_avoid_puts_the_structure_in_the_other(command, region):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.region for s in r.spec.structures] == [region]


def test_across_the_tops_of_two_stacks_a_beam():
    r = plan("Across the tops of two stacks of 4 cubes, a beam.")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 4)]


def test_gaps_said_in_bricks_and_plurals_and_a_misspelt_apart():
    for command in ("two stacks of 3 with a gap of one brick", "two stacks of 3, 1 cube gaps",
                    "two stacks of 3, one cube appart"):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and r.spec.gap_m == 0.05, (command, r.notes)
        assert [s.shape for s in r.spec.structures] == ["tower", "tower"]


def test_n_on_m_is_a_size_said_the_way_of_other_languages():
    s = plan("a slab four on three").spec.structures[0]
    assert (s.length, s.width) == (4, 3)
    s = plan("a stack of 2 on 3 cubes").spec.structures[0]  # not a size: cubes follow
    assert (s.shape, s.height) == ("tower", 2)


def test_a_work_orders_notation():
    s = plan("pen 6x4 h=1").spec.structures[0]  # "h=" after a size is the height, no word left
    assert (s.shape, s.length, s.width, s.height) == ("enclosure", 6, 4, 1)
    r = plan("3 stacks H=150 mm, clear gap 100 mm")  # a drawing's gap is between faces
    assert r.status == "success" and r.spec.gap_m == 0.1, r.notes
    r = plan("2 stacks of 3, 10 cm clear")
    assert r.status == "success" and r.spec.gap_m == 0.1, r.notes
    r = plan("pen 4x4, 3 high, no infill")  # hollow, as a pen is
    assert r.status == "success" and r.spec.structures[0].height == 3, r.notes
    s = plan("a block W x D x H = 4 x 3 x 2").spec.structures[0]  # the labels, not H=4
    assert (s.length, s.width, s.height) == (4, 3, 2)
    r = plan("qty 3 stacks h=3/h=5/h=1 in one line")  # a value each; the line is no row
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", h) for h in (3, 5, 1)]
    s = plan("wall L 200 mm, H 150 mm").spec.structures[0]  # a drawing's letters
    assert (s.length_m, s.height_m) == (0.2, 0.15)
    s = plan("a wall with length of 0.2 meter and height of 0.15 meter").spec.structures[0]
    assert (s.length_m, s.height_m) == (0.2, 0.15)
    s = plan("an L 4 by 3").spec.structures[0]  # the letter names the shape there
    assert (s.shape, s.length, s.width) == ("l_shape", 4, 3)


def test_coordinates_pasted_as_a_table_place_each_structure():
    r = read("x,y,structure\n0.35,0.20,tower 3\n0.60,0.45,tower 2")
    got = sorted((s.at_x, s.at_y, s.height) for s in r.spec.structures)
    assert got == [(0.35, 0.2, 3), (0.6, 0.45, 2)]


def test_nothing_is_built_on_the_robot():
    r = plan("stack 3 cubes on the robot arm")
    assert r.status == "partial" and any("robot" in n for n in r.notes)


def test_a_family_named_that_the_reading_does_not_build_is_material():
    tower = structure("tower", height=3)
    assert "pyramid" in _coherence("a tower of 3 next to a small pyramid", tower)
    bridge = structure("bridge", height=3)
    assert _coherence("two towers of 3 joined by a beam", bridge) == []  # built as its pillars
    on_left = tower.model_copy(update={"region": "left"})
    assert _coherence("a tower of 3 on the left of the table", on_left) == []  # the work table


# -- loose cubes, negations, middles, order (found on the dev11 set) -----------------------------
def columns(result):
    """(x, y) of each column of parts → its height in parts."""
    lo, hi = boxes(result)
    out: dict[tuple[float, float], int] = {}
    for a, b in zip(lo, hi, strict=True):
        key = (round((a[0] + b[0]) / 2, 3), round((a[1] + b[1]) / 2, 3))
        out[key] = out.get(key, 0) + 1
    return out


def test_each_loose_cube_is_a_structure_of_its_own_where_it_was_put():
    r = plan("a cube at the back left and a cube at the front right")
    assert r.status == "success", r.notes
    (x1, y1), (x2, y2) = sorted(columns(r))  # two single cubes, not one
    assert x2 - x1 > 0.1 and y1 < y2 - 0.1  # the back one is on the left (+y)
    r = plan("put one cube on the left and one on the right")
    assert r.status == "success" and len(columns(r)) == 2
    # a cube as a unit or as an addition stays one
    assert read("a wall 5 long and a cube thick").spec.structures[0].shape == "wall"
    assert len(read("a tower of 3 with a cube on top").spec.structures) == 2


def test_a_structure_or_an_addition_said_not_to_be_built_is_left_out():
    r = plan("don't build a tower, build a row of 3 instead")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["row"]
    assert any("not wanted" in n for n in r.notes)
    r = plan("make two pillars of 4 cubes but don't put anything across them")
    assert r.status == "success" and sorted(columns(r).values()) == [4, 4]
    r = plan("two stacks of 3, and please no beam on top of them")
    assert r.status == "success" and sorted(columns(r).values()) == [3, 3]
    # "don't make the pillars taller than 2" is a limit, not a structure left out
    assert read("a bridge, don't make the pillars taller than 2").spec.structures[0].height == 2


def test_a_negation_the_reading_does_not_honour_is_not_a_success():
    r = plan("a tower on the right but not a wall on the left")
    assert r.status == "partial"
    assert any("what these words exclude" in n for n in r.notes)
    r = plan("put a pyramid down but not near the tower")
    assert r.status == "partial" and any("not near the tower" in n for n in r.notes)
    # politeness, and negations the reading keeps, do not alarm
    for command in ("if it's not too much trouble, a staircase with four steps",
                    "two towers of 3, they should not touch each other",
                    "build a wall, not a tower"):  # fmt: skip
        assert plan(command).status == "success", command


def test_a_place_word_no_structure_stands_at_is_not_a_success():
    # a reading that merged two placed structures into one place loses a place word
    from sdi.language.coherence import check
    from sdi.language.state import ReadState
    from sdi.language.syntax import parse
    from sdi.model.cell import CellConfig

    text = "a tower at the back left and a tower at the front right"
    doc = parse(text)
    one = Spec(structures=(structure(shape="tower", region="front left"),))
    st = ReadState(text, CellConfig())
    check(doc, one, st, set(range(len(doc))))
    assert {"back", "right"} <= set(st.material)
    # directions and "right then" are not places
    for command in ("a row of 5 running left to right across the back",
                    "Right then, a tower of seven please",
                    "a wall 5 long 2 high along the left edge, running front to back"):  # fmt: skip
        assert plan(command).status == "success", command


def test_the_middle_of_a_slab_is_its_top_and_of_a_fence_its_inside():
    r = plan("first build a 3x3 slab, then put a tower of 3 in the middle of it")
    assert r.status == "success", r.notes
    cols = columns(r)
    assert len(cols) == 9
    centre = max(cols, key=lambda c: cols[c])
    xs, ys = sorted({c[0] for c in cols}), sorted({c[1] for c in cols})
    assert centre == (xs[1], ys[1]) and cols[centre] == 4  # slab + 3, in the middle
    r = plan("a 6 by 6 fence with a small 2-level pyramid in the middle")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == ["enclosure", "pyramid"]
    assert r.spec.relations[0].kind == "around"
    lo, hi = boxes(r)
    ring = hi[:, 2] < 0.06
    inner = ~ring | (lo[:, 0] > lo[ring, 0].min() + 0.04) & (hi[:, 0] < hi[ring, 0].max() - 0.04)
    assert inner.sum() >= 5  # the pyramid (4 + 1) inside the ring's outer bounds
    # without "with", "in the middle" is the table's centre
    assert read("a tower in the middle").spec.structures[0].region == "centre"


def test_the_tallest_one_goes_where_it_was_asked():
    r = plan("three towers of 2, 4 and 6 cubes, with the tallest one in the middle")
    assert r.status == "success", r.notes
    heights = [h for _, h in sorted(columns(r).items(), key=lambda kv: kv[0][1])]
    assert heights[1] == 6 and sorted(heights) == [2, 4, 6]
    r = plan("two towers of 3 and 5, the shortest on the left")
    heights = [h for _, h in sorted(columns(r).items(), key=lambda kv: kv[0][1])]
    assert r.status == "success" and heights == [5, 3]  # left is +y


def test_a_pyramids_bottom_count_and_one_foot():
    r = plan("a pyramid of 3 levels with 9 cubes on the bottom")
    assert r.status == "success" and len(r.layout) == 9 + 4 + 1
    assert read("a pyramid with 5 cubes on the bottom").spec.structures[0].length == 5
    assert read("a wall 35 cm long and a foot high").spec.structures[0].height_m == 0.3048
    s = read("a 2x2 block, not taller than 10 cm").spec.structures[0]
    assert s.height == 2  # the whole parts within 10 cm


def test_a_size_compared_with_the_one_said_before():
    r = read("build a tower of 3, and next to it a tower twice as tall")
    assert [s.height for s in r.spec.structures] == [3, 6]
    assert [
        s.height for s in read("a tower with 4 cubes and another one with one less").spec.structures
    ] == [4, 3]
    assert [
        s.height for s in read("a tower of 5 and a second one a cube shorter").spec.structures
    ] == [5, 4]
    assert [
        s.height for s in read("a tower of 6 and next to it a wall half as high").spec.structures
    ] == [6, 3]
    # additions to the structure just built stay additions
    r = plan("stack four cubes and then put two more on top")
    assert r.status == "success" and sorted(columns(r).values()) == [6]


def test_n_more_of_a_structure_adds_copies():
    r = read("a tower of 3 and two more like it")
    assert [s.height for s in r.spec.structures] == [3, 3, 3]
    assert len(read("a tower and 2 more towers").spec.structures) == 3
    assert (
        read("build a staircase of 2 steps, then extend it by two more steps")
        .spec.structures[0]
        .steps
        == 4
    )


def test_a_walls_width_in_metres_is_its_length_and_a_square_pad():
    s = read("build a wall 40 cm wide, 2 cubes high").spec.structures[0]
    assert (s.shape, s.length_m, s.height) == ("wall", 0.4, 2)
    r = plan("a square pad 20 cm on each side")
    assert r.status == "success" and len(r.layout) == 16


def test_relations_chained_with_and():
    r = plan("a 3x3 pad with a 2x2 pad on top of it and a single cube on top of that")
    assert r.status == "success", r.notes
    lo, _ = boxes(r)
    assert sorted(np.round(lo[:, 2] / 0.05).astype(int).tolist()).count(2) == 1  # one on top
    assert len(lo) == 9 + 4 + 1


def test_a_part_taken_out_afterwards_is_read_as_the_result():
    r = plan("make a 4x4 floor. then remove the middle 4 cubes")
    assert r.status == "success" and len(r.layout) == 12  # a 4x4 ring
    assert (
        read("a staircase of 5 steps, then take away the highest step").spec.structures[0].steps
        == 4
    )
    r = plan("build 5 towers of 2 in a line, then take away the middle one")
    assert r.status == "success" and sorted(columns(r).values()) == [2, 2, 2, 2]
    # a change SDI cannot make is still reported, never read as a new structure
    r = plan("a row of 5, then push the last two together")
    assert r.status == "partial"


def test_component_words_name_the_structure_they_belong_to():
    r = plan("build a bridge, then stand one single cube on the middle of the beam")
    assert r.status == "success" and r.spec.relations[0].kind == "on_top_of"
    r = plan("a little table: four legs, each 2 cubes high, and a flat top resting on them")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["canopy"]
    # "on the table" is the work table
    assert plan("put a few towers on the table").status == "success"


def test_one_more_next_to_that_chains_and_a_side_corrected():
    r = read(
        "make a stack of 3 cubes. put another stack of 3 next to it. and one more next to that"
    )
    assert [s.height for s in r.spec.structures] == [3, 3, 3]
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]
    r = read("a stack of 3 to the left of a stack of 5 - no, to the right of it")
    assert [x.side for x in r.spec.relations] == ["right"]
    assert read("a row of 4, no, 5").spec.structures[0].length == 5
    assert read("a 3x3 grid, no beams").spec.structures[0].length == 3  # "no" is not a correction


def test_places_said_as_corners_halfway_and_shorthand():
    r = read("one tower of 2 in each of the four corners of the table")
    assert sorted(s.region or "" for s in r.spec.structures) == [
        "back left", "back right", "front left", "front right"]  # fmt: skip
    assert all(s.height == 2 for s in r.spec.structures)
    s = read("a tower of 6 at y = 0.15, halfway between front and back").spec.structures[0]
    assert (s.at_y, s.region) == (0.15, "centre")
    r = read("a towr of 4 nxt to a towr of 2")
    assert [x.kind for x in r.spec.relations] == ["next_to"]


def test_a_contradiction_or_a_negative_count_is_refused_with_the_words():
    for command, words in (("a row of 5 that is also a tower of 5", "both a row and a tower"),
                           ("build a tower with minus 3 cubes", "cannot be negative")):  # fmt: skip
        with pytest.raises(SpecError, match=words) as exc:
            read(command)
        assert exc.value.understood is not None
        assert plan(command).status == "error"
    assert read("nine minus four cubes in a row").spec.structures[0].length == 5


def test_parts_said_with_no_structure_beside_a_named_one_are_not_a_success():
    r = plan("Five cubes long, three cubes tall - such a wall I need.")
    assert r.status == "partial" and any("row was guessed" in n for n in r.notes)
    assert plan("put one cube on top of a tower of three").status == "success"


def test_typos_that_lost_or_swapped_a_letter_and_joined_words():
    s = read("a wall 5 lnog and 2 tal").spec.structures[0]
    assert (s.shape, s.length, s.height) == ("wall", 5, 2)
    s = read("wll 4 lon 3 hgh").spec.structures[0]
    assert (s.shape, s.length, s.height) == ("wall", 4, 3)
    r = plan("stak thre cubse on top of eachother")
    assert r.status == "success" and len(r.layout) == 3
    assert plan("Baue einen Turm aus drei Würfeln").status != "success"  # not English


def test_corrections_that_name_the_structure_and_lists_said_one_by_one():
    s = read("a 3 by 3 pen, one high - no wait, make the pen 5 by 5").spec.structures
    assert [(x.shape, x.length, x.width) for x in s] == [("enclosure", 5, 5)]
    s = read("make a bridge with pillars of 2. actually make the pillars 4 instead").spec.structures
    assert [(x.shape, x.height) for x in s] == [("bridge", 4)]
    r = read("first a lone cube, then a tower of 2, then one of 3, all in a row with gaps")
    assert [x.height for x in r.spec.structures] == [1, 2, 3]
    r = read("two cubes, one in the back left corner and one in the back right corner")
    assert sorted((x.height, x.region) for x in r.spec.structures) == [
        (1, "back left"), (1, "back right")]  # fmt: skip
    assert (
        read("put a cube down at x 0.3 y 0.3, then stack two more on it").spec.structures[0].height
        == 3
    )
    # four separate structures in a square stand in two rows of two; an arrangement SDI does
    # not make is said, not silently replaced by a structure
    r = plan("four stacks of 2 arranged in a square")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower"] * 4
    assert r.spec.grid == (2, 2)
    r = plan("four stacks of 2 arranged in a circle")
    assert r.status == "partial" and [s.shape for s in r.spec.structures] == ["tower"] * 4
    assert any("fornt" in n and "front" in n for n in read("towr of 5 at the fornt").notes)


def test_different_heights_a_left_to_right_list_and_a_walls_rows():
    r = read("a handful of towers, none of them the same height")
    heights = [s.height for s in r.spec.structures]
    assert len(heights) >= 3 and len(set(heights)) == len(heights)
    r = plan("left to right: a tower of 3, then a 2x2 slab")
    assert r.status == "success"
    cols = columns(r)
    tower = max(cols, key=lambda c: cols[c])
    assert all(tower[1] > y for (_, y), h in cols.items() if h == 1)  # the tower on the left
    s = read("a wall made of 8 cubes, two rows of four").spec.structures
    assert [(x.shape, x.length, x.height) for x in s] == [("wall", 4, 2)]


def test_lists_layers_and_a_height_compared_with_its_neighbour():
    r = read("three towers please: two, four and six high")
    assert [s.height for s in r.spec.structures] == [2, 4, 6]
    s = read("a 6 by 2 slab, double thickness").spec.structures[0]
    assert (s.shape, s.length, s.width, s.height) == ("block", 6, 2, 2)
    assert read("a single-layer pad 0.1 by 0.2 metres").spec.structures[0].shape == "grid"
    r = plan("lay a 3x3 floor and then take the centre cube back out")
    assert r.status == "success" and len(r.layout) == 8
    # a change of the structure just built stays a change
    assert read("a 2x3 grid; after that, double its height").spec.structures[0].height == 2


def test_a_square_fence_with_something_inside_is_a_ring_of_that_size():
    r = read("a 7 by 7 fence with a small plus sign inside it")
    ring = r.spec.structures[0]
    assert (ring.shape, ring.length, ring.width, ring.height) == ("enclosure", 7, 7, None)
    assert r.spec.relations[0].kind == "around"


def test_a_relation_said_before_its_subject_and_a_distance_away():
    r = read("a 3x3 floor, and on it a tower of two")
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("on_top_of", 1, 0)]
    assert [s.shape for s in r.spec.structures] == ["grid", "tower"]
    r = read("a tower of four, and to the right of it, a couple of cubes away, a 2x2 block")
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("right", 0.1)]
    r = read(
        "a stack of two at the front, behind it a stack of four, and behind that one a stack of six"
    )
    assert sorted(s.height for s in r.spec.structures) == [2, 4, 6]


# -- against an edge of the workspace -----------------------------------------------------------
WS = {"back": (0, 0.80), "front": (0, 0.20), "left": (1, 0.55), "right": (1, 0.05)}


@pytest.mark.parametrize(
    "command, side",
    [
        ("a 3 by 2 pad pushed as far forward as it can go", "front"),
        ("stack 5 cubes as far to the right as possible", "right"),
        ("a wall 4 long, flush with the back edge of the table", "back"),
        ("a block 2x2x2 all the way over to the left", "left"),
        ("two cubes in a row, at the front, the furthest they can go", "front"),
        ("a row of six parallel to the right edge", "right"),
    ],
)
def test_a_structure_said_against_an_edge_touches_that_boundary(command, side):
    r = plan(command)
    assert r.status == "success", (r.error, r.notes)
    lo, hi = boxes(r)
    d, bound = WS[side]
    reach = hi[:, d].max() if side in ("back", "left") else lo[:, d].min()
    assert np.isclose(reach, bound, atol=1e-6), (side, reach)
    assert any("edge of the workspace" in n for n in r.notes)


def test_a_distance_from_an_edge_is_not_against_it_and_a_plain_side_is_not_an_edge():
    _, hi = boxes(plan("a tower of 2 set 10 cm from the left edge"))
    assert np.isclose(hi[:, 1].max(), 0.55 - 0.10, atol=0.026)  # 10 cm in, not flush
    _, hi = boxes(plan("a tower of 2 on the left"))
    assert hi[:, 1].max() < 0.55 - 0.04  # the left region, not the boundary


def test_parallel_to_a_side_edge_runs_front_to_back():
    lo, hi = boxes(plan("a row of five parallel to the left edge"))
    assert hi[:, 0].max() - lo[:, 0].min() > 0.2  # five parts along x
    assert np.isclose(hi[:, 1].max(), 0.55)


# -- a bound the structure must stay below ------------------------------------------------------
@pytest.mark.parametrize(
    "command, levels",
    [
        ("a stack that stays below 4 cubes high", 3),
        ("a tower, keep it under seven tall", 6),
        ("a column less than 15 cm tall", 2),  # whole 5 cm parts strictly below 15 cm
        ("a staircase with fewer than five steps", 4),
        ("a pyramid lower than 4 levels", 3),
    ],
)
def test_a_strict_upper_bound_builds_the_most_below_it(command, levels):
    r = plan(command)
    assert r.status == "success", (r.error, r.notes)
    _, hi = boxes(r)
    assert np.isclose(hi[:, 2].max(), 0.05 * levels)
    assert any("the most below" in n for n in r.notes)


def test_a_bound_on_a_gate_bounds_the_whole_gate_not_its_pillars():
    r = plan("a gate for the hallway, but keep it under 5 cubes tall")
    _, hi = boxes(r)
    assert hi[:, 2].max() <= 0.20 + 1e-9  # pillars and the beam on them, below 5 parts
    r = plan("a gate whose pillars are under 5 cubes tall")
    _, hi = boxes(r)
    assert np.isclose(hi[:, 2].max(), 0.25)  # pillars 4, the beam on them


def test_a_bound_nothing_fits_below_is_reported():
    r = plan("a tower under 1 cube tall")
    assert r.status != "success" and any("nothing can be built below" in n for n in r.notes)


# -- claims: what the command says must hold of the whole reading ------------------------------
@pytest.mark.parametrize(
    "command",
    [
        "five cubes in a line, none stacked, each one flat on the table",
        "a 4 by 4 ring, please leave it empty inside",
        "two stacks of 4 but they should never touch each other",
        "a wall 3 long 2 high and nothing else on the table",
        "a 2x2 slab with nothing on top of it",
    ],
)
def test_a_claim_the_reading_keeps_is_noted_and_the_plan_succeeds(command):
    r = plan(command)
    assert r.status == "success", (r.error, r.notes)
    assert any(": holds," in n for n in r.notes)


@pytest.mark.parametrize(
    "command, claim",
    [
        ("a tower of 4 cubes, not stacked", "not stacked"),  # a tower is stacked
        ("a 3x3 pad with a cube on top, and nothing on top of it at all", "nothing on top"),
        ("a tower of 2 and they must not touch", "must not touch"),  # one structure
        ("a 3 by 3 block with nothing inside", "nothing inside"),  # nothing hollow to be empty
    ],
)
def test_a_claim_the_reading_breaks_makes_it_partial_naming_the_words(command, claim):
    r = plan(command)
    assert r.status == "partial", (r.error, r.notes)
    assert any(n.startswith("ignored '") and claim in n for n in r.notes), r.notes


def test_claims_are_cut_from_the_text_and_kept_on_the_reading():
    reading = read("a row of 4, lying flat on the table, nothing else")
    assert "flat" not in reading.text and "else" not in reading.text
    assert not reading.material


# -- non-native forms: "in the length", decimal commas, "the double of", "side of" ---------------
@pytest.mark.parametrize(
    "command, slots",
    [
        ("build a wall with 5 cubes in the length and 2 in the height", {"length": 5, "height": 2}),
        ("a wall, 20 cm in the length, in the height of 10 cm", {"length_m": 0.2, "height_m": 0.1}),
        ("a row 0,25 m long", {"length_m": 0.25}),
        ("a slab of 0,25 x 0,1 m", {"length": 5, "width": 2}),
        ("a tower whose height is the double of 3 cubes", {"height": 6}),
    ],
)
def test_non_native_size_forms_fill_the_slots(command, slots):
    (s,) = read(command).spec.structures
    assert {k: getattr(s, k) for k in slots} == slots


def test_a_list_with_commas_is_not_a_decimal():
    heights = [s.height for s in read("three towers of 2,3 and 4").spec.structures]
    assert heights == [2, 3, 4]


@pytest.mark.parametrize("side", ["left", "right", "front", "back"])
def test_on_the_side_of_a_structure_is_a_relation_not_a_region(side):
    spec = read(f"a 3 by 3 pad and a tower of 2 on the {side} side of the pad").spec
    (r,) = spec.relations
    assert (r.kind, r.side, spec.structures[r.subject].shape) == ("next_to", side, "tower")
    assert spec.structures[r.subject].region is None
    hand = "-hand" if side in ("left", "right") else ""
    spec = read(f"a tower of 2 on the {side}{hand} side of the table").spec
    assert not spec.relations and spec.structures[0].region == side


# -- what a speech recogniser writes for a structure word ---------------------------------------
@pytest.mark.parametrize(
    "command, shape, slots",
    [
        ("um a tour of 4 cubes please", "tower", {"height": 4}),
        ("a pier a mid of two levels", "pyramid", {"height": 2}),
        ("a stair case with five steps", "staircase", {"steps": 5}),
        ("put down a 4 by 2 slap", "grid", {"length": 4, "width": 2}),
        ("a rope of seven cubes", "row", {"length": 7}),
        ("a wall sick long and three high", "wall", {"length": 6, "height": 3}),
    ],
)
def test_a_misheard_structure_word_is_read_where_only_it_fits(command, shape, slots):
    reading = read(command)
    (s,) = reading.spec.structures
    assert s.shape == shape and {k: getattr(s, k) for k in slots} == slots
    assert any(n.startswith("read '") for n in reading.notes)


def test_the_same_words_elsewhere_are_left_alone():
    reading = read("after the tour of the plant, a tower of 2; feeling sick of waiting")
    assert [s.shape for s in reading.spec.structures] == ["tower"]
    assert not any("as 'tower'" in n or "as 'six'" in n for n in reading.notes)


# -- the choice left to SDI -----------------------------------------------------------------------
@pytest.mark.parametrize(
    "command, shape",
    [
        ("build whatever you like", "tower"),
        ("dealer's choice, go", "tower"),
        ("something with a beam on top, sizes up to you", "bridge"),
        ("my nephew is six, surprise him... no wait, surprise me", "tower"),
    ],
)
def test_a_command_that_leaves_the_choice_to_sdi_builds_a_default_and_says_so(command, shape):
    r = plan(command)
    assert r.status == "success", (r.error, r.notes)
    assert [s.shape for s in r.spec.structures] == [shape]
    assert any("the choice left to SDI" in n for n in r.notes)


def test_a_family_with_its_sizes_left_to_sdi_uses_the_defaults_and_says_so():
    r = plan("a pyramid, number of levels your call")
    assert r.status == "success" and r.spec.structures[0].shape == "pyramid"
    assert any("left to SDI" in n for n in r.notes)
    r = plan("you choose the wall length, one wall only")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["wall"]


def test_nothing_to_go_on_is_still_an_error_and_a_word_near_a_shape_is_not_one():
    assert plan("build something").status == "error"
    reading = read("she wants a tower of 2")
    assert not any("corrected" in n for n in reading.notes)  # "she" is no "shed"


# -- a structure described again, flanked, or stood on its corners or centre ---------------------
def test_an_apposition_describes_the_structure_named_before_it():
    (s,) = read("a stack, a tall one").spec.structures
    assert s.shape == "tower" and s.height is not None and s.height >= 5
    spec = read("three stacks, a low one, a medium one and a tall one").spec
    heights = sorted(s.height for s in spec.structures)
    assert len(heights) == 3 and heights[0] < heights[1] < heights[2]
    (s,) = read("a wall around the sheep, a square one, 5 cubes on each side").spec.structures
    assert (s.shape, s.length, s.width) == ("enclosure", 5, 5)  # a closed fence is a ring


def test_a_likeness_after_a_structure_is_a_description_and_a_wish_is_not_a_likeness():
    reading = read("a 2 by 2 block, 3 high, a bit like a chimney")
    assert [s.shape for s in reading.spec.structures] == ["block"] and not reading.material
    assert [s.shape for s in read("we would like a wall 4 long").spec.structures] == ["wall"]


def test_one_on_each_side_flanks_it_left_and_right_with_the_gap_said():
    r = plan("a 2x2 slab with a stack of 3 on each side of it, with a little gap")
    assert r.status == "success", (r.error, r.notes)
    columns: dict[tuple[float, float], int] = {}
    for p in r.layout:
        xy = (round(p.position[0], 3), round(p.position[1], 3))
        columns[xy] = columns.get(xy, 0) + 1
    stacks = sorted(xy for xy, n in columns.items() if n == 3)
    slab = [xy for xy, n in columns.items() if n == 1]
    assert len(stacks) == 2 and len(slab) == 4
    assert stacks[0][0] == stacks[1][0]  # same x: left and right of the slab, not front and back
    slab_y = (min(y for _, y in slab), max(y for _, y in slab))
    # one part of clear space between each stack and the slab (centres 0.05 + 0.05 apart)
    assert np.isclose(slab_y[0] - stacks[0][1], 0.10) and np.isclose(stacks[1][1] - slab_y[1], 0.10)


@pytest.mark.parametrize(
    "command, anchored",
    [
        ("a 4 by 4 pad and a cube on its corners", "corners"),
        ("a 4x4 slab; a stack of 2 at all its four corners", "corners"),
        ("a 3x3 slab with a column of 3 rising from its middle", None),
    ],
)
def test_corners_and_centre_said_without_each_are_relations(command, anchored):
    (r,) = read(command).spec.relations
    assert (r.kind, r.at) == ("on_top_of", anchored)


# -- corrections said in full, and a hedged number ------------------------------------------------
def test_a_correction_said_with_its_reason_replaces_the_number():
    (s,) = read("a wall 4 long. Sorry, no, 6 long, the 4 was a typo.").spec.structures
    assert (s.shape, s.length) == ("wall", 6)


def test_a_corrected_phrase_said_in_full_replaces_the_old_phrase():
    spec = read("two stacks of 5 no actually make that three stacks of 5 one cube apart").spec
    assert [s.height for s in spec.structures] == [5, 5, 5]
    assert spec.gap_m == 0.05


def test_a_hedged_number_is_used_when_it_is_the_only_number():
    (s,) = read("a stack, not too high, perhaps five?").spec.structures
    assert s.height == 5
    (s,) = read("a stack of four, maybe five").spec.structures
    assert s.height == 4  # the first number; the hedge is an alternative


def test_a_negated_beam_does_not_hide_the_gap_between_towers():
    spec = read("three pillars of 2 with no beam on them, standing two cubes apart").spec
    assert len(spec.structures) == 3 and spec.gap_m == 0.10


def test_structures_of_counted_parts_standing_in_a_row_are_side_by_side_not_a_row():
    spec = read("two stacks of three cubes placed in a row, a cube's width between them").spec
    assert [s.shape for s in spec.structures] == ["tower", "tower"] and spec.gap_m == 0.05


def test_a_label_before_a_size_is_dropped_and_the_size_kept():
    (s,) = read("Summary version: 4x2 slab").spec.structures
    assert (s.shape, s.length, s.width) == ("grid", 4, 2)


def test_a_wall_one_deep_and_n_wide_is_n_long_across_the_robot():
    (s,) = read("wall: 2 high, 5 wide, 1 deep").spec.structures
    assert (s.shape, s.length, s.height, s.axis) == ("wall", 5, 2, "y")
    (s,) = read("a wall 3 long and 2 wide").spec.structures
    assert s.shape == "block"  # two parts deep: no wall


def test_one_more_after_a_stacked_copy_goes_on_top_again():
    spec = read("lay a row of 3, then another row of 3 on top, then one more").spec
    assert sorted((r.subject, r.object, r.kind) for r in spec.relations) == [
        (1, 0, "on_top_of"),
        (2, 1, "on_top_of"),
    ]
    spec = read("a row of 3, another row of 3 beside it, and another one").spec
    assert all(r.kind != "on_top_of" for r in spec.relations)  # nothing was stacked


def test_that_one_is_the_structure_referred_to():
    (s,) = read("stack three cubes, then put two more on top of that one").spec.structures
    assert (s.shape, s.height) == ("tower", 5)


# -- the gap between a bridge's own supports ------------------------------------------------------
@pytest.mark.parametrize(
    "command, span",
    [
        ("a gate whose posts stand 10 cm apart", 2),
        ("a bridge, the clearance between the pillars is 50 mm", 1),
        ("two stacks of 3 with a beam across them, 2 cubes apart", 2),
    ],
)
def test_a_gap_between_supports_is_the_span(command, span):
    r = plan(command)
    assert r.status == "success", (r.error, r.notes)
    (s,) = r.spec.structures
    assert (s.shape, s.span) == ("bridge", span)
    ys = sorted({round(p.position[1], 3) for p in r.layout if p.size[1] < 0.1})
    assert np.isclose(ys[-1] - ys[0] - 0.05, 0.05 * span)  # clear space between the pillars


def test_a_gap_between_bridges_is_between_them_and_a_span_too_wide_is_refused():
    assert read("two bridges 10 cm apart").spec.gap_m == 0.10
    r = plan("a bridge with pillars 20 cm apart")
    assert r.status == "failure" and "span" in r.error  # no beam that long


# -- a programmer's notation and texting ---------------------------------------------------------
@pytest.mark.parametrize(
    "command, shape, slots",
    [
        ("wall(length=6, height=2)", "wall", {"length": 6, "height": 2}),
        ("slab(4, 3)", "grid", {"length": 4, "width": 3}),
        ("stairs(steps=4)", "staircase", {"steps": 4}),
        ("tower(h=2*4)", "tower", {"height": 8}),
        ("towr(h=3)", "tower", {"height": 3}),  # a family name misspelt before its brackets
    ],
)
def test_a_call_notation_names_the_family_and_its_sizes(command, shape, slots):
    (s,) = read(command).spec.structures
    assert s.shape == shape and {k: getattr(s, k) for k in slots} == slots


def test_a_call_with_dx_dy_sizes_along_the_axes():
    r = plan("block(dx=2, dy=4, dz=1)")
    lo, hi = boxes(r)
    assert np.allclose(hi.max(axis=0) - lo.min(axis=0), [0.10, 0.20, 0.05])


def test_a_position_with_a_height_above_the_table_is_reported():
    r = plan("tower(h=2) @ (0.45, 0.30, 0.20)")
    assert r.status == "partial" and any("z = 0.20" in n for n in r.notes)
    assert plan("tower(h=2) @ (0.45, 0.30, 0.0)").status == "success"


def test_texting_shorthand():
    (s,) = read("can u do a 4x4 square w a hole in the middle").spec.structures
    assert s.shape == "enclosure"
    assert len(read("2 towers of 3 n put a beam across").spec.structures) == 1  # a bridge
    (s,) = read("a tower idk how tall, u pick").spec.structures
    assert s.shape == "tower"


# -- words the grammar consults: kept, or reported ------------------------------------------------
def test_a_hole_in_the_middle_makes_it_hollow():
    for command in ("a 4x4 pad with an opening in the middle", "a hollow slab 3 by 3"):
        (s,) = read(command).spec.structures
        assert s.shape == "enclosure", command


def test_a_beam_put_across_towers_joins_them():
    (s,) = read("two stacks of 3, then place a plank across them").spec.structures
    assert s.shape == "bridge"


@pytest.mark.parametrize(
    "command, word",
    # ("two towers of 2 and a girder" is a bridge: the girder lies across them)
    [("two towers of 2 and a girder beside them", "girder"), ("a 2x2 block, hollow", "hollow")],
)
def test_a_consulted_word_the_reading_builds_nothing_for_is_reported(command, word):
    r = plan(command)
    assert r.status == "partial", r.notes
    assert any(n.startswith(f"ignored '{word}': the reading builds nothing") for n in r.notes)


def test_texting_and_warehouse_words():
    (s,) = read("pls a lil tower in the left lane").spec.structures
    assert (s.shape, s.region) == ("tower", "left") and s.height is not None and s.height <= 3
    (s,) = read("stack 4 in the front-right bay").spec.structures
    assert s.region == "front right"
    spec = read("a pad 3x3 n stick a tower of 2 behind the middle of it").spec
    (r,) = spec.relations
    assert (r.kind, r.side) == ("next_to", "back")


def test_no_source_file_holds_a_control_character():
    """A pattern written through a non-raw string once put a backspace where its ``\\b`` was, and
    the rule silently never matched."""
    from pathlib import Path

    import sdi

    root = Path(sdi.__file__).parent
    bad = [
        str(p.relative_to(root))
        for p in root.rglob("*.py")
        if any(ord(c) < 32 and c not in "\n\t\r" for c in p.read_text(encoding="utf-8"))
    ]
    assert not bad


def test_one_on_each_of_four_sides_stands_on_every_side():
    r = plan("a 2x2 block 2 high with a stack of 2 on each of its four sides, one cube clear")
    assert r.status == "success", (r.error, r.notes)
    columns: dict[tuple[float, float], int] = {}
    for p in r.layout:
        xy = (round(p.position[0], 3), round(p.position[1], 3))
        columns[xy] = columns.get(xy, 0) + 1
    assert len(columns) == 4 + 4 and all(n == 2 for n in columns.values())
    cx = sum(x for x, _ in columns) / 8
    cy = sum(y for _, y in columns) / 8
    by_distance = sorted(columns, key=lambda xy: (xy[0] - cx) ** 2 + (xy[1] - cy) ** 2)
    block, stacks = by_distance[:4], by_distance[4:]
    lo = (min(x for x, _ in block), min(y for _, y in block))
    hi = (max(x for x, _ in block), max(y for _, y in block))
    # one stack in front, behind, left and right, each one cube clear of the block's face
    sides = sorted(
        ("front" if x < lo[0] else "back" if x > hi[0] else "right" if y < lo[1] else "left")
        for x, y in stacks
    )
    assert sides == ["back", "front", "left", "right"]
    for x, y in stacks:
        clear = max(lo[0] - x, x - hi[0], lo[1] - y, y - hi[1]) - 0.05
        assert np.isclose(clear, 0.05)


def test_more_cubes_stacked_on_the_middle_of_a_floor_are_a_column_on_it():
    spec = read("lay a 3x3 slab, then stack 3 more on the middle one").spec
    assert [s.shape for s in spec.structures] == ["grid", "tower"]
    (r,) = spec.relations
    assert r.kind == "on_top_of" and spec.structures[1].height == 3


def test_the_top_taken_off_a_pyramid_is_a_cut_off_pyramid_not_a_smaller_one():
    r = plan("a pyramid of 4 levels, then take the top level off")
    (s,) = r.spec.structures
    assert r.status == "success" and (s.length, s.height) == (4, 3)
    assert any("3 levels on its base of 4" in n for n in r.notes)


# -- where things may not go ---------------------------------------------------------------------
@pytest.mark.parametrize(
    "command, regions",
    [
        ("put everything on the right side: a tower of 2 and a row of 3", ["right", "right"]),
        ("a stack of 3; never put it anywhere near the back edge", ["front"]),
        ("a stack of 3, on no account to be placed on the right", ["left"]),
        ("a row of 4 that keeps out of the front third of the table", ["back"]),
        ("a 2x2 pad, then keep it in the left part", ["left"]),
    ],
)
def test_where_a_structure_may_not_go_or_must_stay(command, regions):
    assert [s.region for s in read(command).spec.structures] == regions


def test_no_second_layer_is_a_claim_the_reading_keeps_or_breaks():
    assert plan("a 3 by 2 slab, no second layer").status == "success"
    assert plan("a 3 by 2 block 2 high, no second layer").status == "partial"


def test_a_beam_laid_across_two_towers_named_apart_joins_them_with_the_gap_as_span():
    r = plan("a stack of 2, then another stack of 2 two cubes apart, then lay a plank across both")
    assert r.status == "success", (r.error, r.notes)
    (s,) = r.spec.structures
    assert (s.shape, s.height, s.span) == ("bridge", 2, 2)


def test_single_parts_left_out_are_reported_and_a_climb_towards_my_left_turns_the_stairs():
    r = plan("a wall 4 long 3 high, but remove the end cubes of the top course")
    assert r.status == "partial" and r.spec.structures[0].height == 3
    assert len(r.spec.structures) == 1
    (s,) = read("stairs of 4 steps that climb towards my right").spec.structures
    assert s.axis == "y"


def test_the_middle_of_the_bench_is_the_centre_of_the_work_surface():
    (s,) = read("a tower of 3 in the middle of the bench").spec.structures
    assert (s.shape, s.region) == ("tower", "centre")


def test_removing_the_tallest_of_towers_named_apart_leaves_the_others():
    r = plan("a stack of 2, a stack of 5 and a stack of 3, then remove the tallest one")
    assert r.status == "success", (r.error, r.notes)
    assert sorted(s.height for s in r.spec.structures) == [2, 3]
    r = plan("two stacks of 3, then take away the tallest one")
    assert r.status == "partial"  # no single tallest: the command does not say which


@pytest.mark.parametrize(
    "command",
    [
        "one layer of 8 cubes in two rows",
        "two rows of four, 1 layer",
        "2 rows of 4 cubes, one layer",
    ],
)
def test_one_layer_said_of_rows_is_a_floor_not_another_structure(command):
    (s,) = read(command).spec.structures
    assert (s.shape, s.length, s.width) == ("grid", 4, 2)


def test_the_expected_result_said_is_a_description_and_a_bridge_thing_a_beam():
    spec = read("a pad 4 by 2, then a pad 4 by 2 on it; it should come out as a block").spec
    assert [s.shape for s in spec.structures] == ["grid", "grid"]
    (s,) = read("two stacks of 2 and lay a bridge piece across the top").spec.structures
    assert s.shape == "bridge"


def test_a_structure_beside_them_both_stands_beside_the_whole_group():
    r = plan("two stacks of 2, and a row of 5 in front of them both")
    assert r.status == "success", (r.error, r.notes)
    stacks = [p for p in r.layout if p.position[2] > 0.05]  # the stacks' upper cubes
    row = [p for p in r.layout if p.position[0] == min(q.position[0] for q in r.layout)]
    assert len(stacks) == 2 and len(row) == 5
    ys = [p.position[1] for p in stacks]
    lo, hi = min(p.position[1] for p in row), max(p.position[1] for p in row)
    assert lo < min(ys) and max(ys) < hi  # the row runs in front of both stacks


def test_a_second_cube_on_the_middle_one_is_one_cube_there():
    r = plan("a row of 3, then put a second cube on the middle one")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 4
    up = lo[:, 2] > 0.04
    assert up.sum() == 1
    ground = (lo[~up] + hi[~up]) / 2
    top = ((lo[up] + hi[up]) / 2)[0]
    assert np.allclose(top[:2], np.median(ground[:, :2], axis=0), atol=0.005)


def test_a_verb_left_at_the_end_names_no_structure():
    r = plan("cubes six, in one column, please stack")
    lo, _ = boxes(r)
    assert r.status == "success" and len(lo) == 6
    assert np.ptp(lo[:, 0]) < 1e-6 and np.ptp(lo[:, 1]) < 1e-6  # one column of six
    assert len(boxes(plan("a wall of 6, now build"))[0]) == 6


def test_next_to_at_the_start_is_a_relation_and_a_bare_name_later_sizes_it():
    s = read("next to the pyramid a tower of 5 pls, pyramid 3 levels").spec
    assert sorted((x.shape, x.height) for x in s.structures) == [("pyramid", 3), ("tower", 5)]
    assert [r.kind for r in s.relations] == ["next_to"]
    t = read("behind the wall a tower of 3, wall 4 long").spec
    assert [(x.shape, getattr(x, "length", None)) for x in t.structures] == [
        ("tower", None),
        ("wall", 4),
    ]
    (rel,) = t.relations
    assert (t.structures[rel.subject].shape, rel.side) == ("tower", "back")


def test_a_row_on_top_of_a_wall_runs_along_the_wall():
    r = plan("a wall 4 long along x, with a row of 3 on top")
    assert r.status == "success", r.notes
    lo, _ = boxes(r)
    top = lo[:, 2] >= lo[:, 2].max() - 1e-6
    assert top.sum() == 3 and np.ptp(lo[top, 1]) < 1e-6  # along x, on the wall
    # on the wall's own top, not on the taller tower set beside it
    q = plan("a tower of 3 in front of a wall, then a row of 2 on top of the wall")
    assert q.status == "success", q.notes
    (tower,) = [o for o in q.layout.objects if o.position[2] > 0.1 and o.position[0] < 0.45]
    row = [o for o in q.layout.objects if o.position[2] > 0.1 and o.position[0] > 0.45]
    assert len(row) == 2 and {o.position[0] for o in row} != {tower.position[0]}


@pytest.mark.parametrize(
    ("said", "mm"),
    [
        ("a 6 inch stack", "152.4 mm"),
        ("two inches apart", "50.8 mm"),
        ("a foot-long row", "304.8 mm long"),
        ("1 ft 6 in tall", "457.2 mm"),
        ("a foot and a half tall", "457.2 mm"),
        ("1 1/2 inches apart", "38.1 mm"),
        ("a gap of 3/4 of an inch", "19 mm"),
        ("half an inch apart", "12.7 mm"),
        ('a 6" tower', "152.4 mm"),
        ("a 6 by 6 inch pad", "152.4 mm by 152.4 mm"),
        ("tower 10in tall", "254 mm"),
        ("a yard tall", "914.4 mm"),
    ],
)
def test_imperial_lengths_are_read_in_millimetres_and_noted(said, mm):
    from sdi.language.units import to_millimetres

    notes: list[str] = []
    assert mm in to_millimetres(said, notes)
    assert notes and notes[0].startswith("read '")


@pytest.mark.parametrize(
    "said", ["put 2 in each corner", "4 in a row", "3 in the back", "at the foot of the wall"]
)
def test_in_and_foot_that_are_no_length_stay(said):
    from sdi.language.units import to_millimetres

    notes: list[str] = []
    assert to_millimetres(said, notes) == said and notes == []


def test_inches_size_and_space_structures():
    r = plan("Put a 6 inch stack and a 4 inch stack about two inches apart.")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert sorted(np.round(hi[:, 2], 3))[-1] == pytest.approx(0.15)  # 6 in: 3 cubes
    assert len(lo) == 5 and r.spec.gap_m == pytest.approx(0.0508)
    # a yard is beyond the cell: refused, not built smaller
    assert plan("A tower a yard tall.").status != "success"
    # a change in inches counts whole parts
    s = read("Lay a 6 by 6 inch pad, then build it up to 4 inches tall.").spec.structures[0]
    assert (s.length, s.width, s.height) == (3, 3, 2)


def test_an_upper_bound_in_length_builds_the_whole_parts_within_it():
    for said in ("a tower no taller than 18 cm", "a tower at most 18 cm tall",
                 "A tower no taller than 7 inches, but as tall as that allows."):  # fmt: skip
        r = plan(said)
        assert r.status == "success" and len(r.layout.objects) == 3, (said, r.notes)


def test_undo_takes_back_the_step_before_and_says_so():
    r = plan("Row of 4 going left to right. Then a tower of 3 next to it. Undo the last one.")
    assert r.status == "success" and len(r.layout.objects) == 4, r.notes
    assert any("taken back" in n and "tower" in n for n in r.notes)
    s = read("a row of 3. then a tower of 5 behind it. scratch that. a wall 4 long behind it")
    assert [x.shape for x in s.spec.structures] == ["row", "wall"]
    (rel,) = s.spec.relations  # "behind it": behind the row, the tower being gone
    assert (rel.subject, rel.object, rel.side) == (1, 0, "back")
    # a group's last one is one of the group; a step's last one is the step
    t = read("5 towers of 2 in a line, then remove the last one").spec
    assert len(t.structures) == 4
    u = read("a tower of 3, then a tower of 2 next to it, remove the last one").spec
    assert [x.height for x in u.structures] == [3]
    # with nothing before it, there is nothing to take back: not silently dropped
    assert plan("a tower of 3. undo").status != "success"


def test_a_typo_of_a_relation_word_is_corrected():
    r = plan("Please tower of cubes five, in the left sied.")
    assert "corrected 'sied' to 'side'" in r.notes
    assert [s.shape for s in r.spec.structures] == ["tower"]  # not a shed
    assert "corrected 'anothr' to 'another'" in read("row of 4. thn anothr one on top").notes


def test_a_count_before_a_singular_name_with_its_size_after_is_a_count():
    assert [s.height for s in read("I want 3 tower of 3 cube.").spec.structures] == [3, 3, 3]
    assert len(read("make 2 wall, long 4").spec.structures) == 2
    # not the last number of a size group, and not a size with an article
    assert len(read("make a 2x2 block, 2 high, and a 5 cube tower next to it").spec.structures) == 2
    assert [s.height for s in read("a 5 tower").spec.structures] == [5]


def test_a_count_and_an_equal_height_said_of_the_whole_are_checked():
    r = plan("Tower, 5 cube. Also tower, 5 cube. Total 2 tower, same height.")
    assert r.status == "success" and len(r.spec.structures) == 2, r.notes
    assert any("holds" in n and "Total 2 tower" in n for n in r.notes)
    bad = plan("a tower of 3 and a tower of 4, same height")
    assert bad.status == "partial" and "same height" in (bad.error or "")
    assert plan("a tower of 3 and a tower of 2, total 3 tower").status == "partial"
    # "none of them the same height" says the opposite; a count naming them is no claim
    assert len(read("three towers in total, each 2 high").spec.structures) == 3
    assert not any("holds" in n for n in read("a handful of towers, none the same height").notes)


def test_a_bare_singular_name_after_a_relation_word_is_the_one_named():
    r = plan("Wall, long 6, high 2. In front of wall, one tower of 3 cube. Not touch.")
    s = r.spec
    assert [x.shape for x in s.structures] == ["wall", "tower"]
    (rel,) = s.relations
    assert (rel.subject, rel.object, rel.side) == (1, 0, "front")
    lo, hi = boxes(r)
    column = np.ptp(lo[:, 1], axis=0) > 0  # the wall's parts spread along y
    wall_front = lo[:, 0].max()
    tower_back = hi[hi[:, 0] < wall_front, 0].max()
    assert column and wall_front - tower_back > 0.01  # "not touch": apart


def test_a_relation_word_corrected_to_another_side_keeps_the_relation():
    s = read("tower of 3 in the middle. now a tower of 5 behind it. no wait, in front of it.").spec
    (rel,) = s.relations
    assert (rel.kind, rel.subject, rel.side) == ("next_to", 1, "front")
    assert getattr(s.structures[1], "region", None) is None  # not "at the front of the table"


def _columns(r):
    cols: dict[tuple[float, float], int] = {}
    for o in r.layout.objects:
        key = (round(o.position[0], 3), round(o.position[1], 3))
        cols[key] = cols.get(key, 0) + 1
    return cols


def _built_as_said(command, shapes, heights):
    """`plan(command)` succeeds with these families, and (unless None) columns this high."""
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == shapes
    if heights is not None:
        assert sorted(_columns(r).values()) == heights
    return r


def test_the_tallest_goes_where_it_is_said_along_the_line():
    r = plan("three towers of 2, 4 and 6 in a straight line front to back, tallest at the back, "
             "5 cm clear spacing")  # fmt: skip
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items())  # front (small x) to back
    assert len({y for (_, y), _ in cols}) == 1 and cols[-1][1] == 6
    assert r.spec.gap_m == pytest.approx(0.05)
    left = sorted(_columns(plan("three towers of 2, 4 and 6, tallest on the left")).items(),
                  key=lambda kv: kv[0][1])  # fmt: skip
    assert left[-1][1] == 6  # left is +y
    # a line front to back has no left end: said so, not silently ignored
    odd = plan("three towers of 2, 4 and 6 in a line front to back, the tallest on the left")
    assert odd.status == "partial"


def test_levels_labelled_in_order_stand_each_on_the_one_before():
    r = plan("level 1: 4x4 floor. level 2: 3x3 on top. level 3: 2x2. level 4: 1 block. gg")
    assert r.status == "success", r.notes
    levels: dict[float, int] = {}
    for o in r.layout.objects:
        levels[round(o.position[2], 3)] = levels.get(round(o.position[2], 3), 0) + 1
    assert [levels[z] for z in sorted(levels)] == [16, 9, 4, 1]


def test_an_expected_result_is_checked_against_the_reading():
    ok = plan("Step 1: place a 2 x 3 base, one layer. Step 2: add a second identical layer. "
              "Expected result: a 2 x 3 x 2 block.")  # fmt: skip
    assert ok.status == "success" and len(ok.layout.objects) == 12, ok.notes
    assert any("holds" in n and "Expected result" in n for n in ok.notes)
    bad = plan("a 2x3 slab, then add a second identical layer. Expected result: a 2 x 3 x 3 block.")
    assert bad.status == "partial" and "Expected result" in (bad.error or "")


def test_a_change_said_on_its_own_halves_or_doubles_the_size_before():
    assert [s.height for s in read("tower of 8. too much, half of that.").spec.structures] == [4]
    assert [s.height for s in read("a tower of 3. no, double it").spec.structures] == [6]
    # said of another structure, it is a comparison, not a change
    two = read("Two towers, one 3 high and the other one twice that.").spec.structures
    assert 3 in [s.height for s in two]
    # a clause of such words left unused is never chatter
    assert plan("a tower of 3. half as much again, roughly").status == "partial"


def test_rows_counted_per_row_or_by_columns_make_one_floor():
    for said in ("Grid of 4 rows, 3 cubes per row, one layer", "a grid of 4 rows of 3",
                 "a grid with 4 rows and 3 columns"):  # fmt: skip
        (g,) = read(said).spec.structures
        assert (g.shape, g.length, g.width) == ("grid", 3, 4), said
    w = read("a wall of 2 rows with 7 in each").spec.structures
    assert [(s.shape, s.length, s.height) for s in w] == [("wall", 7, 2)]
    (fewer,) = read("Grid of 4 rows, 3 cubes per row. Then remove the last row.").spec.structures
    assert (fewer.length, fewer.width) == (3, 3)
    top = read("spawn a 2x2 block 3 high. then break the top layer lol").spec.structures
    assert [s.height for s in top] == [2]


def test_a_removal_sdi_cannot_make_is_reported_not_read_as_a_pointer():
    r = plan("a 3x3 pyramid. then remove the first one")
    assert r.status == "partial" and "remove the first one" in (r.error or "")


def test_a_staircase_kept_from_one_way_climbs_another():
    s = read("build stairs, 4 steps, but dont make them go towards me, make them go up to the "
             "right").spec.structures[0]  # fmt: skip
    assert (s.axis, s.yaw_deg, s.steps) == ("y", 180.0, 4)  # as "going up to the right"
    assert (s.axis, s.yaw_deg) == tuple(
        getattr(read("a staircase of 4 steps going up to the right").spec.structures[0], k)
        for k in ("axis", "yaw_deg")
    )
    t = read("stairs of 3, not going towards me")
    assert t.spec.structures[0].axis == "x" and any("climbing towards the back" in n
                                                     for n in t.notes)  # fmt: skip


def test_a_place_glossed_in_brackets_is_the_place_meant():
    r = read("make a 5 block tower but don't put it on the spawn point (the middle)")
    assert r.spec.structures[0].region not in (None, "centre")
    assert read("a tower by the loading side (i.e. the front)").spec.structures[0].region == (
        "front"
    )


def test_same_again_but_copies_with_the_change():
    s = read("Put a 2x2 slab, one layer, front left. Same again but back right, and 2 layers.")
    _, b = s.spec.structures
    assert (b.length, b.width, b.height, b.region) == (2, 2, 2, "back right")
    w = read("a wall 4 long and 2 high, then another one but 3 high").spec.structures
    assert [(x.length, x.height) for x in w] == [(4, 2), (4, 3)]
    assert [x.height for x in read("a tower of 3 and another tower of 5").spec.structures] == [
        3,
        5,
    ]


def test_on_top_of_all_and_a_walled_area():
    s = read("a line of 5. then a line of 3 on it. at the end one cube on the top of all.").spec
    assert [(r.subject, r.object) for r in s.relations] == [(1, 0), (2, 1)]
    assert read("a walled area, 5 by 5").spec.structures[0].shape == "enclosure"
    assert read("an arena 6 by 6").spec.structures[0].shape == "enclosure"


def test_a_word_of_a_contraction_is_no_typo():
    r = read("two towers of 2 that aren't touching each other")
    assert not any("arena" in n for n in r.notes) and r.complete


def test_size_words_before_their_numbers_after_a_family_name():
    w = read("Make one wall long 7 and high 2.").spec.structures[0]
    assert (w.shape, w.length, w.height) == ("wall", 7, 2)
    b = read("A block large 3, long 4, high 2.").spec.structures[0]
    assert (b.length, b.width, b.height) == (4, 3, 2)


def test_misspelt_units_and_changes_in_units_or_without_a_noun():
    assert read("make a 6 inhc tower").spec.structures[0].height_m == pytest.approx(0.1524)
    s = read("Stack it up to 10 inches, then pull the top 2 inches off.").spec.structures[0]
    assert (s.height, s.height_m) == (4, None)
    t = read("tower of 6 please. hmm too tall, take off 2. actually take off one more.")
    assert [x.height for x in t.spec.structures] == [3]
    r = read("row of 7. no make it 3 less.").spec.structures[0]
    assert (r.shape, r.length) == ("row", 4)
    # more than a change: reported, not half done
    assert plan("tower of 7, then pull the top 3 cubes off and set them down as a separate "
                "tower next to it").status == "partial"  # fmt: skip


def test_two_rows_next_to_each_other_stand_alongside():
    r = plan("row of 4. and another row like that next to it, touching.")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 8
    assert (hi[:, 0].max() - lo[:, 0].min(), hi[:, 1].max() - lo[:, 1].min()) == (
        pytest.approx(0.10, abs=0.01),
        pytest.approx(0.20, abs=0.01),
    )


def test_tetris_pieces_are_the_families_that_build_them():
    cases = {
        "build a tetris L-piece out of cubes": ("l_shape", 4),
        "make me a tetirs T-peice": ("t_shape", 4),
        "make a tetris piece, any one": ("l_shape", 4),
        "a row of 4 standing on end": ("tower", 4),
    }
    for said, (shape, parts) in cases.items():
        r = plan(said)
        assert r.status == "success" and len(r.layout.objects) == parts, (said, r.notes)
        assert [s.shape for s in r.spec.structures] == [shape], said
    two = read("stand two I-pieces on end, one on top of the other").spec
    assert [s.height for s in two.structures] == [4, 4] and len(two.relations) == 1
    assert plan("an S-piece").status == "error"  # no family builds it: said, not guessed


def test_each_one_the_cells_own_part_size_and_inch_coordinates():
    s = read("Three stacks, each one 4 inches high.").spec.structures
    assert len(s) == 3 and read("Three stacks, each one 4 inches high.").complete
    assert [x.height for x in read("stack half a dozen of the 2-inch blocks").spec.structures] == [
        6
    ]
    t = read("Put a 3-high stack at x = 18 in, y = 12 in.").spec.structures[0]
    assert (t.at_x, t.at_y) == (pytest.approx(0.4572), pytest.approx(0.3048))


def test_a_comparison_with_that_and_one_of_n_after_a_singular():
    assert [s.height for s in read("Two towers, one 3 high and the other one twice that.")
            .spec.structures] == [3, 6]  # fmt: skip
    assert [s.height for s in read("One tower of six cubes and one of four").spec.structures] == [
        6,
        4,
    ]
    # after a plural, "one of 3 and one of 5" names the ones counted
    assert [s.height for s in read("two towers, one of 3 and one of 5").spec.structures] == [3, 5]


def test_a_gap_said_of_two_structures_side_by_side_or_between_them():
    assert read("Two inches between them, the two stacks, each 6 inches.").spec.gap_m == (
        pytest.approx(0.0508)
    )
    r = read("drop an O-piece and an I-piece side by side with a little gap").spec
    assert r.gap_m == pytest.approx(0.05) and all(
        getattr(s, "gap_m", None) is None for s in r.structures
    )


def test_structures_listed_left_to_right_stand_in_that_order():
    r = plan("three towers of 1, 2 and 3, from left to right")
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])  # left (+y) first
    assert [h for _, h in by_y] == [1, 2, 3]
    one = plan("a row of 5 running left to right")  # a single structure runs that way
    assert np.ptp([o.position[0] for o in one.layout.objects]) == 0


def test_another_like_that_copies_the_one_before():
    s = read("A wall 4 long, 2 high. And another like that, behind it, with a cube gap.").spec
    assert [(x.length, x.height) for x in s.structures] == [(4, 2), (4, 2)]
    (rel,) = s.relations
    assert (rel.side, rel.gap_m) == ("back", pytest.approx(0.05))


def test_a_part_count_and_free_standing_said_of_the_whole_are_checked():
    r = plan("The deliverable is 2 walls of 5 x 2 cubes and 1 tower of 5; total part count 25.")
    assert r.status == "success" and len(r.layout.objects) == 25, r.notes
    assert plan("three towers of 2, 7 cubes in total").status == "partial"
    # counted by the generators: a pyramid of 3 tiers is 6 parts here, not the 14 said
    assert plan("replicate: pyramid, 3 tiers, 14 cubes in total").status == "partial"
    # the only size of the structure is no claim
    assert [s.height for s in read("a tower, 6 cubes in total").spec.structures] == [6]
    free = read("two 3-high towers and a 2 x 2 block; all three items free-standing")
    assert len(free.spec.structures) == 3 and any("holds" in n for n in free.notes)


def test_in_cubes_is_a_unit_gloss_and_x3_after_a_name_is_a_count():
    s = read("four towers of heights 1, 2, 3 and 4 (in cubes), free-standing").spec.structures
    assert [x.height for x in s] == [1, 2, 3, 4]
    assert [x.height for x in read("make a tower x3, each one 4 blocks").spec.structures] == [
        4,
        4,
        4,
    ]
    (row,) = read("row x5 along X").spec.structures  # a work order's length
    assert row.length == 5


def test_distances_from_the_robot_and_the_middle_line_are_coordinates():
    t = read("Put a 4 inch tower about 16 inches out from the robot.").spec.structures[0]
    assert t.at_x == pytest.approx(0.4064)
    u = read("Tower of 6 inches, 8 inches left of the middle line.").spec.structures[0]
    assert u.at_y == pytest.approx(0.5032)  # the workspace's middle is y = 0.30; left is +y
    assert read("a tower 10 cm behind the centre").spec.structures[0].at_x == pytest.approx(0.6)


def test_rejection_conditions_are_constraints():
    r = read("Nonconformance if the two towers touch. Build: towers of 5 and 2, 50 mm clear.")
    assert [x.height for x in r.spec.structures] == [5, 2] and r.spec.gap_m == pytest.approx(0.05)
    b = read("Reject if any part is within 10 cm of the front edge. Required: a 2x2 block, 3 high")
    assert [x.region for x in b.spec.structures] == ["back"]
    row = read("A row 8 inches long, sitting right up at the back edge, within an inch of it.")
    assert row.complete and row.spec.structures[0].edge == ("back",)


def test_a_copy_said_with_an_offset_stands_off_the_one_before():
    s = read("1) row x5 along X (front to back). 2) duplicate it 1 cube to the left, parallel").spec
    assert [(x.shape, x.length) for x in s.structures] == [("row", 5), ("row", 5)]
    (rel,) = s.relations
    assert (rel.subject, rel.object, rel.side, rel.gap_m) == (1, 0, "left", pytest.approx(0.05))
    t = read("a wall. then a tower 2 cubes behind").spec
    (r2,) = t.relations
    assert (r2.side, r2.gap_m) == ("back", pytest.approx(0.1))


@pytest.mark.parametrize(
    ("scanned", "read_as"),
    [
        ("Bui1d a tovver of 4", "Build a tower of 4"),
        ("a wa11 2O cm 1ong", "a wall 20 cm long"),
        ("l0 crn apart", "10 cm apart"),
        ("PIace a pyrarnid in the rniddle", "Place a pyramid in the middle"),
        ("tvv0 tovvers 0n t0p", "two towers on top"),
        ("PIease bui1d a tow er of 6 cu bes.", "Please build a tower of 6 cubes."),
        ("N0 tovver ta11er than 4", "No tower taller than 4"),
        ("5tep l: a row", "step 1: a row"),
    ],
)
def test_a_scanners_confusions_are_read_back_and_noted(scanned, read_as):
    from sdi.language.scanned import unscan

    text, notes = unscan(scanned)
    assert text == read_as and notes


@pytest.mark.parametrize(
    "kept", ["t0: row(n=4)", "at A1 and C3", "a 1x1 tower", "rnig 6x6", "put it in to the box"]
)
def test_labels_sizes_and_typos_are_no_scanner_confusion(kept):
    from sdi.language.scanned import unscan

    assert unscan(kept)[0] == kept


def test_stage_directions_are_the_performers():
    r = read("Set a 2 by 2 riser, one cube tall, downstage left.").spec.structures[0]
    assert (r.shape, r.region) == ("grid", "front right")  # stage left: the cell's right
    t = read("Upstage of the 3-high tower, one cube back from it, a 2 by 2 riser.").spec
    (rel,) = t.relations
    assert (rel.side, rel.gap_m) == ("back", pytest.approx(0.05))
    s = read("I need a flight of six treads.").spec.structures[0]
    assert (s.shape, s.steps) == ("staircase", 6)


def test_slavic_and_dutch_speakers_phrasing():
    s = read("Build wall long 5, high 2, and behind of wall put pyramid from 2 levels").spec
    assert [(x.shape, getattr(x, "height", None)) for x in s.structures] == [
        ("wall", 2),
        ("pyramid", 2),
    ]
    assert read("Hoi! a wall of 6 long and 2 high. Dank je!").complete
    assert [x.height for x in read("Build a tower whose height is the square of 3.")
            .spec.structures] == [9]  # fmt: skip


def test_an_array_of_stacks_is_built_as_the_stacks_not_one_slab():
    r = plan("a 2 x 3 array of 2-high stacks, and make sure no two stacks touch")
    assert r.status == "success" and len(r.spec.structures) == 6 and r.spec.grid == (2, 3)
    assert all(s.height == 2 for s in r.spec.structures)


def test_plate_positions_wells_and_likenesses():
    s = read("Put down a 3 x 3 plate, one cube thick, and stand a 2-high stack in its centre well.")
    (rel,) = s.spec.relations
    assert rel.kind == "on_top_of" and s.spec.structures[rel.subject].shape == "tower"
    b2 = read("In position B2 of a 3 x 3 plate, one layer thick, stand a 3-high stack.")
    assert [r.kind for r in b2.spec.relations] == ["on_top_of"] and b2.complete
    assert not read("put a 2-high stack in position A1 of a 3 x 3 plate").complete  # said
    a1 = read("Put a 2-high stack in the back-left corner of the table, like position A1 on a "
              "plate.").spec.structures  # fmt: skip
    assert [(x.shape, x.region) for x in a1] == [("tower", "back left")]


def test_a_wall_not_named_is_the_tables_edge_and_a_progression_of_heights():
    t = read("Make tower from 4 cubes, but not in middle, near to wall on back.").spec
    assert [(x.shape, x.region) for x in t.structures] == [("tower", "back")]
    p = read("Build four towers; first from 1 cube, every next one cube higher.").spec
    assert [x.height for x in p.structures] == [1, 2, 3, 4]
    assert read("Hoi! a wall of 6 long and 2 high. Dank je!").spec.structures[0].shape == "wall"


def test_removals_said_after_a_place_and_a_checkerboard_are_reported():
    r = plan("Make wall from 6 cubes long, 3 high. Then from top row take out two cubes on ends.")
    assert r.status == "partial" and len(r.spec.structures) == 1
    assert plan("Make a checkerboard on a 4 x 4 plate: fill every other position").status != (
        "success"
    )


def test_cuboids_flats_and_a_square_based_pyramid():
    (b,) = read("Build a cube with an edge length of 3.").spec.structures
    assert (b.shape, b.length, b.width, b.height) == ("block", 3, 3, 3)
    r = plan("A square-based pyramid of 3 layers with a total of 14 cubes.")
    assert r.status == "success" and len(r.layout.objects) == 14, r.notes
    (w,) = read("a flat 6 wide and 4 high running across the stage").spec.structures
    assert (w.shape, w.length, w.height) == ("wall", 6, 4)
    (g,) = read("not a tower: a flat 2 by 2 patch").spec.structures  # "flat" the adjective
    assert g.shape == "grid"


def test_non_native_between_each_and_a_wall_that_is():
    s = read("Make 4 towers, in each 3 cubes, in one line, between them one cube.").spec
    assert [x.height for x in s.structures] == [3, 3, 3, 3] and s.gap_m == pytest.approx(0.05)
    t = read("Put tower from 2 cubes near to wall, on front side of it. Wall is long 6 and high 3.")
    assert [(x.shape, getattr(x, "length", None)) for x in t.spec.structures] == [
        ("tower", None),
        ("wall", 6),
    ]
    (rel,) = t.spec.relations
    assert rel.side == "front"
    u = read("Set a flight of 3 treads rising upstage. Actually, give it 4 treads.")
    (st,) = u.spec.structures
    assert (st.steps, st.axis) == (4, "x")


def test_a_gap_said_with_a_tower_and_a_copy_with_a_gap():
    s = read("Put a bridge with pillars of 3 high and next to it on the right side a tower of 4 "
             "high, with one block in between.").spec  # fmt: skip
    assert all(getattr(x, "gap_m", None) is None for x in s.structures)
    c = read("4 cubes stacked = one 200 mm column; make two of those, 150 mm apart").spec
    assert [x.height for x in c.structures] == [4, 4] and c.gap_m == pytest.approx(0.15)


def test_one_of_several_changed_is_reported_and_strike_takes_back():
    r = plan("Build two walls with 5 cubes in the length. The first wall has 2 cubes in the "
             "height, the second one more.")  # fmt: skip
    assert r.status == "partial" and len(r.spec.structures) == 2
    s = read("Build a flat 5 wide and 3 high across the back. Then strike it and put a 4-high "
             "tower there instead.").spec  # fmt: skip
    assert [(x.shape, x.height) for x in s.structures] == [("tower", 4)]
    assert plan("a tower of 3. undo").status == "error"
    ring = read("a ring one cube high, 5 x 5 outside, with a single 3-high tower standing at its "
                "center, not touching the ring.").spec  # fmt: skip
    assert [r.kind for r in ring.relations] == ["around"]


def test_a_structure_named_in_passing_then_described_is_one():
    s = read("I like a tower. Build a tower of 5.").spec
    assert [x.height for x in s.structures] == [5]
    # a place makes the first one of its own; so does "another"
    assert len(read("a tower on the left. a tower of 5").spec.structures) == 2
    assert len(read("I like a tower. Build another tower of 5.").spec.structures) == 2


def test_a_cross_by_its_arms_and_a_top_left_off_is_said():
    (c,) = read("a cross with arms 2 cubes long").spec.structures
    assert (c.shape, c.length) == ("cross", 5)
    r = plan("a pyramid on a 4x4 base, but stop before the single top cube")
    assert r.status == "partial"
    assert plan("ok robot back online after e-stop reset, pls do bridge pillars 2 high").status == (
        "success"
    )


def test_parallel_walls_units_apart():
    r = plan("Build two walls, each 5 long and 2 high, parallel to each other and 3 units apart.")
    assert r.status == "success", r.notes
    xs = sorted({round(o.position[0], 3) for o in r.layout.objects})
    assert len(xs) == 2 and xs[1] - xs[0] == pytest.approx(0.20)  # one behind the other, 3 clear
    assert len({round(o.position[1], 3) for o in r.layout.objects}) == 5


def test_the_work_table_is_no_table_to_span_and_its_front_side():
    r = read("Place three towers of heights 2, 4 and 2 in a straight line, 1 unit apart, symmetric "
             "about the middle of the table.").spec  # fmt: skip
    assert [x.height for x in r.structures] == [2, 4, 2] and r.gap_m == pytest.approx(0.05)
    assert all(x.region is None for x in r.structures)  # a line stands centred anyway
    s = read("Put a tower of five bricks on the table and a 2 by 2 block one brick away from it, "
             "on its front side.").spec  # fmt: skip
    (rel,) = s.relations
    assert (rel.side, rel.gap_m) == ("front", pytest.approx(0.05))


def test_a_change_to_each_or_all_of_them_changes_every_one():
    for said in ("three towers of 2, then add one more cube to each",
                 "Make three towers of 2 and then make all of them one higher."):  # fmt: skip
        assert [x.height for x in read(said).spec.structures] == [3, 3, 3], said
    last = read("three towers of 2, then add one more cube to the last one").spec.structures
    assert [x.height for x in last] == [2, 2, 3]


def test_a_second_of_the_same_size_runs_the_same_way():
    s = read("first a row of 4 going away from the robot, then a second row of 4 alongside it")
    assert [(x.length, x.axis) for x in s.spec.structures] == [(4, "x"), (4, "x")]


@pytest.mark.parametrize(
    ("data", "shapes"),
    [
        ('{"shape": "tower", "count": 3, "height": 4}', [("tower", 4)] * 3),
        ("- type: wall\n  length: 5\n  height: 2\n- type: tower\n  height: 3\n  behind: wall",
         [("wall", 2), ("tower", 3)]),
        ("towers: [2, 3, 4]\nspacing: 1", [("tower", 2), ("tower", 3), ("tower", 4)]),
        ("n_towers=2\nheight=4\ngap_cm=10", [("tower", 4)] * 2),
        ('// owner: @dmitri\n{"shape": "wall", "length": 4, "height": 3}', [("wall", 3)]),
        ("```yaml\n# generated\nshape: staircase\nsteps: 3\n```", [("staircase", None)]),
        ('{"shape": "pyramid", "levels": 3,}', [("pyramid", 3)]),
        ("steps:\n  - build: {shape: tower, height: 3}\n  - add: {cubes: 2, to: tower}",
         [("tower", 5)]),
    ],
)  # fmt: skip
def test_commands_written_as_data_are_read(data, shapes):
    r = read(data)
    got = [(s.shape, getattr(s, "height", None)) for s in r.spec.structures]
    assert got == shapes and any(n.startswith("read the data as") for n in r.notes)


@pytest.mark.parametrize(
    "words",
    ["[ticket #882] [prio: low] Build: cross shape, 5x5. /cc @ops", "Spec: staircase, n=6 steps.",
     "h=4, base 2x2, block", "Note: build a tower of 3"],
)  # fmt: skip
def test_words_with_brackets_or_colons_are_not_data(words):
    from sdi.language.structured import looks_like_data

    assert not looks_like_data(words)


def test_malformed_data_is_refused_with_the_parsers_message():
    r = plan('{"shape": "tower", "height": }')
    assert r.status == "error" and "height" in (r.error or "")
    assert "does not parse" in (plan('{"shape": "tower" "height": 3}').error or "")


def test_words_spelt_as_they_sound_and_a_childs_homophones():
    r = read("a big towr of 6 and a litle won of 2 rite next to it tuching")
    assert [x.height for x in r.spec.structures] == [6, 2]
    (rel,) = r.spec.relations
    assert rel.gap_m == 0.0 and any("sounds like" in n for n in r.notes)
    assert read("a reely big brij with legs of 3").spec.structures[0].shape == "bridge"
    s = read("sum stares of 3 steps that go up to the rite").spec.structures[0]
    assert (s.shape, s.steps) == ("staircase", 3)
    t = read("5 steps my stares shud have, going up to the back").spec.structures[0]
    assert (t.shape, t.steps) == ("staircase", 5)  # "shud" is should, not a shed
    # letters swapped stay a typo, gibberish and other languages sound like nothing
    assert read("a rign 4 by 4").spec.structures[0].shape == "enclosure"
    assert plan("jjjjjjj kkk").status == "error"
    assert plan("haz una torre de cinco cubos por favor").status == "error"


def test_indian_english_focus_words_and_a_command_partly_in_another_language():
    s = read("Make three towers, heights 2, 4 and 6 only, in one line, one cube gap each.").spec
    assert [x.height for x in s.structures] == [2, 4, 6] and s.gap_m == pytest.approx(0.05)
    e = read("Make three towers of height 2. Then put one-one cube on each.").spec
    assert [x.height for x in e.structures] == [3, 3, 3]
    c = plan("Exercise three: lay a 3x3 slab and set one cube on each of its four corners.")
    assert c.status == "success" and len(c.layout.objects) == 9 + 4  # one on each corner
    h = plan("Ek tower banao, chaar cube ka, left side mein.")
    assert h.status == "partial" and "does not know" in " ".join(h.notes)
    assert not any("mini" in n for n in h.notes)  # no size read into a word by its sound


def test_words_that_take_parts_out_or_count_by_the_dozen_are_not_dropped_silently():
    # "skip the four corners" is an exclusion SDI does not build: said, never a silent grid
    r = plan("A 4 by 4 tray of cupcakes, one cube each, but skip the four corners")
    assert r.status == "partial" and any("skip" in n for n in r.notes)
    # "half a dozen" is six: a tower of one is not what was asked
    r = read("Half a dozen pancakes in one stack, one cube each.")
    assert not r.complete and "Half a dozen" in r.material
    # "two dozen cubes" as a 4 by 6 slab: 24 parts, the number shows
    assert plan("two dozen cubes as a 4 by 6 slab").status == "success"


def test_knocking_the_first_structure_down_takes_it_back():
    for command in (
        "bild a wall of 3 and then nock it down and bild a towr of 3 insted",
        "build a row of 4, then demolish it and make a tower of 2 instead",
    ):
        r = read(command)
        assert [s.shape for s in r.spec.structures] == ["tower"], command


def test_places_that_disagree_for_one_structure_are_reported_unless_the_last_one_wins():
    r = read("a tower of 3 on the left, in the middle")
    assert r.spec.structures[0].region == "left" and not r.complete
    assert any("disagree" in n for n in r.notes)
    # a correction: the last place said is the one built
    r = read("build a tower of 4. and put it on the left side. no sorry, the right side.")
    assert r.spec.structures[0].region == "right" and r.complete
    # neither side: the middle
    r = read("Make pyramid of 2 levels, not on the left side, not on the right side, in the middle")
    assert r.spec.structures[0].region == "centre" and r.complete


def test_a_relation_to_a_face_of_a_structure_is_a_relation_cue():
    # "against its tall end", "round the edge of the top": related to a structure's face;
    # built side by side, that is not what was asked
    for command in ("a row of 3 and a tower of 4 against its end",
                    "Two layers of 3 by 3 for the base, then a border of cubes round the edge "
                    "of the top"):  # fmt: skip
        r = read(command)
        assert len(r.spec.structures) == 2 and not r.spec.relations, command
        assert not r.complete, command


def test_an_expected_result_of_several_structures_is_checked_by_its_part_count():
    r = read("two towers of 4 side by side, touching. Expected result: a 1 x 3 x 4 block")
    assert not r.complete and any("that result 12" in n for n in r.notes)
    r = read("two towers of 4 side by side, touching. Expected result: a 1 x 2 x 4 block")
    assert r.complete
    # a description with a size left to its default is not counted ("2 deep and 4 high")
    r = read("two towers of 4, touching - should come out as a block 2 deep and 4 high")
    assert r.complete and any("not checked" in n for n in r.notes)


def test_separate_structures_said_touching_stand_with_no_gap():
    r = plan("two towers of 4 side by side, touching")
    assert r.status == "success"
    ys = sorted({round(o.position[1], 4) for o in r.layout.objects})
    assert len(ys) == 2 and abs((ys[1] - ys[0]) - 0.05) < 1e-6  # one cube apart: faces touch


def test_a_bridge_named_then_described_as_towers_and_a_beam_is_one_bridge():
    r = read("I want a bridge. Two towers of 3 with a beam across them.")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 3)]
    # another one said: two bridges
    r = read("a bridge on the left, and another one: two towers of 3 joined by a beam")
    assert [s.shape for s in r.spec.structures] == ["bridge", "bridge"]


def test_towers_joined_at_the_top_carry_a_beam_not_each_other():
    for command in ("two columns of 4, joined at the top", "two towers of 3 connected at the top",
                    "Build an arch. Two columns of 4, joined at the top."):  # fmt: skip
        r = read(command)
        assert [s.shape for s in r.spec.structures] == ["bridge"], command
        assert not any(rel.kind == "on_top_of" for rel in r.spec.relations), command


def test_a_structure_kept_off_a_side_stands_on_the_other():
    r = read("dont put the pyramid on the left. put it on the right. 2 levels.")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("pyramid", "right")]
    assert r.complete
    r = read("never place the tower on the front side, 4 high")
    assert [(s.region, s.height) for s in r.spec.structures] == [("back", 4)]


@pytest.mark.parametrize(
    ("command", "want"),
    [
        ("a tower of 4 cubes of height", [("tower", 4)]),
        ("Put a pyramid of 2 floors in the right part", [("pyramid", 2)]),
        ("A wall of 3 of length and 2 of height", [("wall", 2)]),
        ("A wall of eight long and half so high, please.", [("wall", 4)]),
        ("tower of 3 - no 6 - at the back", [("tower", 6)]),
        ("A row of 6 along the front. Oh and build it up: make it two layers. No, three.",
         [("wall", 3)]),
    ],
)  # fmt: skip
def test_word_orders_of_other_languages_and_spoken_corrections(command, want):
    r = read(command)
    assert [(s.shape, s.height) for s in r.spec.structures] == want, r.notes
    assert r.complete, r.notes


def test_romance_and_german_places_gaps_and_by():
    r = read("Put a pyramid of 2 floors in the right part")
    assert r.spec.structures[0].region == "right"
    r = read("A platform of 20 per 20 centimetres, one cube thick")
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (4, 4)
    r = read("A 3-high tower, left beside it a row of 4 cubes, one cube gap between, bitte.")
    assert r.complete and [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [
        ("next_to", "left", 0.05)
    ]
    r = read("a tower of 4 and, at its left, a wall 3 long and 2 high, separated by one cube")
    assert r.complete and [(x.side, x.gap_m) for x in r.spec.relations] == [("left", 0.05)]
    # "50 mm clearance between rows": the trailing word is kept for what follows it
    assert read("a tower of 4 and a row of 3, one cube gap between them").complete


def test_a_count_corrected_after_a_plural_is_the_count_of_structures():
    r = read("Four towers of 2, make that five, in a row, a cube apart.")
    assert [s.height for s in r.spec.structures] == [2] * 5
    assert any("'Four' → 'five'" in n for n in r.notes)
    r = read("At the front, a row of 5, make that 6, running left to right.")
    assert [s.length for s in r.spec.structures] == [6] and r.complete


def test_structures_said_to_rise_one_way_stand_getting_taller_that_way():
    r = read("three towers of 5, 2 and 3, getting taller from left to right")
    assert [s.height for s in r.spec.structures] == [5, 3, 2]  # placed from the right
    r = read("three towers of 2, 4 and 6 in one line, ascending from right to left")
    assert [s.height for s in r.spec.structures] == [2, 4, 6]
    r = read("a staircase of 4 steps ascending from right to left")
    assert r.spec.structures[0].axis == "y" and r.complete
    # "then on the right, same.": another one the same there
    r = read("on the left, a tower. 3 high. no, 4 high. then on the right, same.")
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 4), ("right", 4)]


def test_a_coordinate_without_a_unit_is_in_the_unit_that_puts_it_on_the_table():
    r = read("Column of 6 at x 700 y 100.")
    s = r.spec.structures[0]
    assert (s.at_x, s.at_y) == pytest.approx((0.7, 0.1)) and r.complete
    assert any("700 mm" in n for n in r.notes)
    s = read("a tower at x 45 y 30").spec.structures[0]
    assert (s.at_x, s.at_y) == pytest.approx((0.45, 0.3))
    assert plan("At x 550 y 350: pyramid, 2 levels, base 3 x 3.").status == "success"


def test_a_structure_moved_after_it_was_placed_stands_where_it_was_moved():
    s = read("Place a column of 5 at x 350 y 250. Then relocate it 200 mm in +x.").spec.structures
    assert [(x.at_x, x.at_y, x.height) for x in s] == [pytest.approx((0.55, 0.25, 5))]
    s = read("a tower of 3 at x 0.4 y 0.3, then shift it 2 cubes to the left").spec.structures
    assert [(x.at_x, x.at_y) for x in s] == [pytest.approx((0.4, 0.4))]
    r = read("Put a 2x2 block, 2 high, at the back right. Then move it to the front left.")
    assert [x.region for x in r.spec.structures] == ["front left"] and r.complete
    # a copy set off from the first is no move
    r = read("1) row x5 along X (front to back). 2) duplicate it 1 cube to the left, parallel")
    assert len(r.spec.structures) == 2


@pytest.mark.parametrize(
    ("command", "heights"),
    [
        ("build for towers won of each height from won to for", [1, 2, 3, 4]),
        ("three towers going up by won each starting at too", [2, 3, 4]),
        ("Three towers, the first 2 high and each next one 2 higher, bitte in one line.",
         [2, 4, 6]),
        ("uh i want to towers of ate please", [8, 8]),
    ],
)  # fmt: skip
def test_a_series_of_heights_and_numbers_a_recogniser_spells_as_words(command, heights):
    r = read(command)
    assert sorted(s.height for s in r.spec.structures) == heights, r.notes
    assert {s.shape for s in r.spec.structures} == {"tower"} and r.complete


def test_four_towers_from_one_to_six_is_no_series():
    r = read("four towers, one of each height from one to six")
    assert not (r.complete and sorted(s.height for s in r.spec.structures) == [1, 2, 3, 4])


def test_a_warehouse_operators_words():
    r = read("Two pallet stacks, 2 by 2 footprint, three layers each, and leave an aisle two "
             "cubes wide between them.")  # fmt: skip
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 2, 2, 3)
    ] * 2
    assert r.spec.gap_m == pytest.approx(0.1) and r.complete
    r = read("Build a stack 3 pallets high, each pallet a 2 by 2 layer.")
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 2, 2, 3)
    ]
    r = read("couple of 4-stacks, back of the cell, touching")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 4)] * 2
    assert r.spec.gap_m == 0.0
    r = read("Give me 2 stacks of 4, single cubes, with an aisle of one between them.")
    assert [s.height for s in r.spec.structures] == [4, 4] and r.complete
    # "a 3-pillar bridge" is three pillars, not a pillar of three
    r = read("a 3-pillar bridge, pillars 3 cubes")
    assert [(s.shape, s.spans) for s in r.spec.structures] == [("bridge", 2)]
    # "an aisle away from the robot" is no gap
    assert "gap" not in read("Row of cubes 40 cm long, running down the aisle away from the "
                             "robot.").text  # fmt: skip


def test_several_structures_in_one_region_stand_in_a_line_there():
    r = plan("three towers of 2 at the back")
    xs = {round(o.position[0], 3) for o in r.layout.objects}
    ys = {round(o.position[1], 3) for o in r.layout.objects}
    assert r.status == "success" and len(xs) == 1 and len(ys) == 3
    assert min(xs) > 0.5  # all three at the back


def test_the_bigger_one_behind_orders_two_structures_front_to_back():
    r = read("the bigger one behind. two towers, 5 and 2. a cube gap.")
    assert r.spec.line == "x" and [s.height for s in r.spec.structures] == [2, 5]
    r = read("Stack of 4 over on the front left, and a line of 5 behind it with a bit of a gap.")
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("back", 0.05)]
    assert r.spec.structures[1].gap_m is None and r.spec.structures[0].height == 4


def test_a_structure_on_a_named_corner_of_anothers_top():
    r = plan("A 3 by 3 slab, one course, with a 2-storey column standing on its rear left corner.")
    assert r.status == "success"
    top = {(round(o.position[0], 3), round(o.position[1], 3)) for o in r.layout.objects
           if o.position[2] > 0.03}  # fmt: skip
    xs = [o.position[0] for o in r.layout.objects]
    ys = [o.position[1] for o in r.layout.objects]
    assert top == {(round(max(xs), 3), round(max(ys), 3))}  # back (+x), left (+y)
    # "on the back left corner" alone is the table's corner
    r2 = read("a tower on the back left corner")
    assert [s.region for s in r2.spec.structures] == ["back left"] and not r2.spec.relations


def test_taking_back_what_was_named():
    r = read("Put a tower of 4 on the left and a wall of 4 by 2 on the right. Actually forget "
             "the wall.")  # fmt: skip
    assert [(s.shape, s.region) for s in r.spec.structures] == [("tower", "left")] and r.complete
    with pytest.raises(SpecError, match="takes back"):
        read("A tower of 4. No, 6. No wait, scratch all of that, don't build anything.")
    r = read("ok so I said a tower of 3 earlier but scratch that, different thing entirely "
             "today: a pyramid of 2 levels.")  # fmt: skip
    assert [(s.shape, s.height) for s in r.spec.structures] == [("pyramid", 2)]
    # "don't build anything at the back" is a place, not a retraction
    r = read("don't build anything at the back, put a tower of 3 at the front")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("tower", "front")]


def test_taking_down_what_stands_on_the_table_is_not_a_build():
    with pytest.raises(SpecError, match="clear table"):
        read("Take down the castle from last night.")
    r = plan("remove the tower from yesterday and build a wall of 4")
    assert r.status == "partial" and any("clear table" in n for n in r.notes)


@pytest.mark.parametrize(
    ("command", "shape", "size"),
    [
        ("Realize a tower with half a dozen cubes plus one.", "tower", 7),
        ("Please a row of ten cubes, all in one line from left to right.", "row", 10),
        ("ok new batch incoming, ignore the racket from line 3. row of 4 please", "row", 4),
    ],
)
def test_sums_a_redundant_line_and_a_production_lines_name(command, shape, size):
    r = read(command)
    assert [(s.shape, getattr(s, "height", None) or s.length) for s in r.spec.structures] == [
        (shape, size)
    ]


def test_a_stack_touching_a_pallets_edge_and_a_rise_along_an_axis():
    r = read("Drop a single-layer 4 by 2 pallet at the back, and put a 3-high stack in front of "
             "it, touching the pallet's front edge.")  # fmt: skip
    assert len(r.spec.structures) == 2
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("front", 0.0)]
    s = read("Staircase, 3 steps, rising in -y.").spec.structures[0]
    assert (s.axis, s.yaw_deg) == ("y", 180.0)  # climbing towards the right (-y)


@pytest.mark.parametrize(
    ("command", "want"),
    [
        ("two towers, 5 and 3 high", [("tower", 5), ("tower", 3)]),
        ("3 tower, and a row of 2", [("tower", 3), ("row", None)]),
        ("1 tower, 8 cubes", [("tower", 8)]),
        ("3 layres of 2 by 3 on one palett", [("block", 3)]),
        ("Wall: length 350 mm, height 100 mm, thickness 50 mm.", [("wall", None)]),
    ],
)
def test_an_operators_shorthand(command, want):
    r = read(command)
    assert [(s.shape, getattr(s, "height", None)) for s in r.spec.structures] == want, r.notes
    assert r.complete, r.notes


def test_sizes_counted_in_cubes_and_gaps_said_off_or_between_each_one():
    r = read("a hollow rectangle, 6 cubes by 4 cubes on the outside, 2 high")
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("enclosure", 6, 4, 2)
    ]
    r = read("make a row of five but dont let them touch like leave a little gap between each one")
    assert r.complete and [s.gap_m for s in r.spec.structures] == [0.05]
    r = read("3-step staircase in the middle, and a 2 stack each side of it, left and right, "
             "one cube off")  # fmt: skip
    assert [(x.kind, x.at, x.gap_m) for x in r.spec.relations] == [("next_to", "ends", 0.05)]


def test_an_architects_words():
    r = read("A colonnade of five columns, three storeys each, running left to right, one cube "
             "of clear space between neighbouring columns.")  # fmt: skip
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 3)] * 5
    assert r.spec.gap_m == pytest.approx(0.05) and r.complete
    r = read("a bridge on two 3-storey piers")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 3)] and r.complete
    r = read("A ground-floor slab with a 25 by 15 cm footprint, one course thick.")
    assert r.complete


def test_removing_the_only_structure_named_leaves_nothing_to_build():
    with pytest.raises(SpecError, match="takes back everything"):
        read("Build a wall of 5 long, 2 high. Then remove the wall. Then remove the tower.")
    r = read("a wall of 4. remove the wall. a tower of 3")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 3)]


def test_structures_asked_about_then_described_are_built_once():
    r = read("Is it ok to put a small pyramid on top of a block? Maybe a 3 by 3 block two high, "
             "with a pyramid of 2 levels sitting on it?")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["block", "pyramid"]
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("on_top_of", 1, 0)]
    # another one said: both built
    r = read("Can you build a tower? Then another tower of 4 next to it.")
    assert len(r.spec.structures) == 2


def test_what_a_structure_is_for_and_a_size_agreed_are_no_structures():
    r = read("just give me a 2 by 4 slab, one course, as a plinth study.")
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("grid", 2, 4)]
    r = read("Yes, the ring: 4 by 4, one high. Or no, let me think... yes, 4 by 4 is fine.")
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("enclosure", 4, 4)]


def test_the_work_table_a_footprint_tower_and_a_single_cube_marker():
    r = read("Hi Sam - table's clear, I packed the test pieces away. First job: a 2 by 2 block, "
             "3 high, and a 5-tower on its right with a one-cube gap. Cheers, Priya")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["block", "tower"] and r.complete
    r = read("a 2x2 tower of 3 on the left")
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 2, 2, 3)
    ]
    assert [s.shape for s in read("a 1x1 tower of 3").spec.structures] == ["tower"]
    r = read("In the middle bay a 2 by 2 stack 3 high, and on either side of it a single-cube "
             "marker, one cube off.")  # fmt: skip
    assert [(s.shape, getattr(s, "height", None)) for s in r.spec.structures] == [
        ("block", 3),
        ("tower", 1),
    ]
    assert [(x.subject, x.object, x.at) for x in r.spec.relations] == [(1, 0, "ends")]
    # "split it into two stacks" is no reading SDI makes: said, never silent
    assert not read("Build a 5-high stack, then split it into two stacks side by side").complete


def test_a_bare_structure_beside_sized_ones_is_said_not_silently_built():
    # "table's clear" once built a default canopy beside the block; any such bare structure
    # with no size, place or relation among sized ones is reported
    r = read("a tower of 4 on the left, and a plinth")
    assert not r.complete and any("'plinth': a block of its default size" in n for n in r.notes)
    # placed together as said, or with a count, or the sizes left to SDI: no report
    assert read("a T and a cross next to each other, the T on the left").complete
    assert read("a tower of 3 next to a bridge").complete
    assert read("a tower of 3 and a bridge, your call on the sizes").complete


def test_distances_said_centre_to_centre_are_placed_as_clear_gaps():
    r = read("Column of 3 centred on x 400 y 300. Second column of 3, 100 mm to the left of the "
             "first, centre to centre.")  # fmt: skip
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("left", pytest.approx(0.05))]
    r = read("two columns of 4, 150 mm centre to centre, not touching, aligned along x.")
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("back", pytest.approx(0.1))]
    assert r.complete and [s.height for s in r.spec.structures] == [4, 4]
    # between structures wider than a part the pitch is no clear gap SDI can place: said
    assert not read("two 2 by 2 blocks, 300 mm apart centre to centre").complete


def test_a_structure_at_stated_coordinates_stays_there_with_another_beside_it():
    r = plan("Column of 3 centred on x 400 y 300. Second column of 3, 100 mm to the left of the "
             "first, centre to centre.")  # fmt: skip
    cols = sorted({(round(o.position[0], 3), round(o.position[1], 3)) for o in r.layout.objects})
    assert r.status == "success" and cols == [(0.4, 0.3), (0.4, 0.4)]


def test_an_ordinal_names_one_of_the_structures_built_one_by_one():
    r = read("Build a tower of 5, then another one of 5 to the right of it. Hmm, make the second "
             "one 3 instead.")  # fmt: skip
    assert [s.height for s in r.spec.structures] == [5, 3] and r.complete
    r = read("a tower of 3 and a wall of 4. make the first one 5")
    assert r.spec.structures[0].height == 5
    # no third structure: nothing changed, said
    assert not read("a tower of 3 and a tower of 4. make the third one 5").complete


def test_make_them_changes_every_one_and_typos_of_correction_words():
    r = read("two towrs of 4 nex to each other, actualy make them 5")
    assert [s.height for s in r.spec.structures] == [5, 5] and r.complete
    assert [s.height for s in read("three towers of 2. make them 4").spec.structures] == [4] * 3


@pytest.mark.parametrize(
    "command",
    [
        "A column 35 centimetres tall on a single-cube footprint.",
        "A hollow enclosure: outer footprint 6 by 4, walls one cube thick and two courses high.",
        "Four storeys, on a single-cube footprint, in the back right corner: the column.",
    ],
)
def test_what_every_column_or_ring_is_anyway_is_no_unused_size(command):
    assert read(command).complete


def test_a_height_named_first_with_its_level_word():
    r = read("Height 3 courses, length 300 mm, wall, at the front.")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("wall", 3)] and r.complete


def _sorted_columns(r):
    """(x, y) of each column of cubes with its height in parts, sorted."""
    return sorted(_columns(r).items())


@pytest.mark.parametrize(
    "command",
    [
        "Two towers of 4 and between them please a tower of 2 build.",
        "Make two towers of 4 and a tower of 2. Put the tower of 2 between them.",
        "two towers of 4 with a tower of 2 between them",
        "put a tower of 2 between two single towers of 4, one cube gap on each side",
    ],
)
def test_a_structure_said_between_two_stands_between_them(command):
    r = plan(command)
    heights = [h for _, h in _sorted_columns(r)]
    assert r.status == "success" and heights == [4, 2, 4], _sorted_columns(r)


def test_a_gap_said_of_the_outer_two_holds_the_one_between():
    r = plan("two towers of 4, 3 cubes apart, with a tower of 2 in the middle between them")
    (a, _), (m, _), (b, _) = (c for c in _sorted_columns(r))
    assert r.status == "success" and round(b[0] - a[0], 3) == 0.2 and round(m[0] - a[0], 3) == 0.1


def test_a_wall_between_two_towers_has_them_at_its_ends():
    r = plan("Between two towers of 4 put a wall 3 long and 2 high, everything touching.")
    ys = sorted({y for (_, y), _ in _sorted_columns(r)})
    xs = {x for (x, _), _ in _sorted_columns(r)}
    assert r.status == "success" and len(xs) == 1 and len(ys) == 5


def test_one_more_on_a_tower_is_a_cube_and_a_cube_on_a_slab_is_not_a_layer():
    r = plan("Make tower from 3 cubes. Then put on it one more. And one more.")
    assert r.status == "success" and [h for _, h in _sorted_columns(r)] == [5]
    r = plan("a tower of 4. then put one more on top. then one more")
    assert r.status == "success" and [h for _, h in _sorted_columns(r)] == [6]
    r = plan("a 2x2 slab, then put one more cube on it")
    assert sorted(round(o.position[2], 3) for o in r.layout.objects) == [0.025] * 4 + [0.075]
    r = read("a 2 by 2 block 2 high, then add 4 more cubes on top")
    assert r.spec.structures[0].height == 3
    # another structure when one is named or placed beside
    assert len(read("a tower of 3 on the left. and one more on the right").spec.structures) == 2


@pytest.mark.parametrize(
    ("command", "shape", "height"),
    [
        ("bridge with pillars 3 high", "bridge", 3),
        ("brige w 2 towrs of 3", "bridge", 3),
        ("a table with four legs of 3 cubes", "canopy", 3),
        ("an arch with legs of 2", "arch", 2),
    ],
)
def test_a_fragment_with_no_article_and_legs_of_a_height(command, shape, height):
    r = read(command)
    assert [(s.shape, s.height) for s in r.spec.structures] == [(shape, height)] and r.complete


def test_the_tables_centre_is_a_region_not_a_table():
    r = read("place a 2x2 block (2 high) at table centre; a 4-cube tower directly on top of it")
    assert [s.shape for s in r.spec.structures] == ["block", "tower"] and r.complete
    assert r.spec.structures[0].region == "centre"


def test_a_gap_said_after_a_relation_to_a_bridge_is_between_them():
    r = read("bridge with 3-high legs. single cube in front of it, 2 cubes out")
    assert [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [("next_to", "front", 0.1)]


def test_a_thing_to_build_that_is_no_structure_is_material():
    r = read("Can u make a fridge w/ legs of 2")
    assert not r.complete and any("'fridge'" in n for n in r.spec.notes)
    assert read("make a tower of 3").complete


@pytest.mark.parametrize(
    ("word", "meant"),
    [("twr", "tower"), ("twrs", "towers"), ("blk", "block"), ("lyr", "layer"), ("lgs", "legs"),
     ("brdg", "bridge"), ("clmn", "column"), ("pllr", "pillar"), ("btm", "bottom")],
)  # fmt: skip
def test_a_word_written_without_its_vowels_is_the_word_it_abbreviates(word, meant):
    from sdi.language.typos import abbreviated

    assert abbreviated(word) == meant
    assert abbreviated("ctr") in ("centre", "center")  # not a crater: English says it far more


@pytest.mark.parametrize("word", ["mdl", "plc", "qty", "xyz", "tower", "hmm"])
def test_an_abbreviation_that_could_be_two_words_or_is_no_word_of_sdis_is_left(word):
    from sdi.language.typos import abbreviated

    assert abbreviated(word) is None  # "mdl": middle or module; "PLC" is no place


def test_a_work_order_in_abbreviations_is_read_and_each_expansion_noted():
    r = plan("REQ: twr 4H. LOC: back left corner.")
    (s,) = r.spec.structures
    assert r.status == "success" and (s.shape, s.height, s.region) == ("tower", 4, "back left")
    assert "read 'twr' as 'tower' (an abbreviation)" in r.notes


def test_words_left_unused_in_more_about_a_structure_named_before_are_accounted():
    # 'double' was dropped with the phrase that only said more about the tower (success, 3 high)
    r = plan("REQ: twr x1. H: double the std 3-blk twr.")
    assert r.status == "partial" and any("'double'" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("command", "anchor", "kind", "columns"),
    [  # column heights in parts: a 3x3 slab with a 2-tower on each corner; a 5 x 2 wall
        # with a 3-tower beside each end
        ("4 towers of 2, one per corner of a 3x3 slab", "corners", "on_top_of", [1] * 5 + [3] * 4),
        ("a 3x3 slab with four 2-cube towers, one on each corner", "corners", "on_top_of",
         [1] * 5 + [3] * 4),
        ("two towers of 3, one at each end of a wall 5 long", "ends", "next_to", [2] * 5 + [3] * 2),
    ],
)  # fmt: skip
def test_one_per_corner_or_end_is_one_copy_on_each_not_more_structures(
    command, anchor, kind, columns
):
    r = read(command)
    assert len(r.spec.structures) == 2, r.spec.structures
    (rel,) = r.spec.relations
    assert (rel.kind, rel.at) == (kind, anchor)
    assert sorted(_columns(plan(command)).values()) == columns


@pytest.mark.parametrize(
    ("command", "word"),
    [
        # ("fore and aft" is read now: running front to back, noted — see the test of fwd and aft)
        ("Lay out a row of six along the starboard side.", "starboard"),
        ("Six high it must be, the mast, and on the bow end.", "bow"),
    ],
)
def test_a_place_in_words_sdi_does_not_know_is_not_a_silent_success(command, word):
    r = plan(command)
    assert r.status == "partial", r.notes
    assert f"ignored '{word}': says where to build, in words SDI does not know" in r.notes


@pytest.mark.parametrize(
    "command",
    ["Please build a tower of 3 quickly.", "This time, a staircase of three steps.",
     "sorry my english not so good, i want wall, 4 long, 2 high"],
)  # fmt: skip
def test_everyday_words_beside_the_build_verb_are_no_place(command):
    assert plan(command).status == "success"


def test_a_word_that_only_sounds_like_a_structure_is_not_built_beside_one_named():
    r = read("Tsak: a 2x3 slba, 1 layre.")  # 'Tsak' sounds like 'desk': it was a table too
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("grid", 2, 3)]
    assert read("a reely big brij with legs of 3").spec.structures[0].shape == "bridge"


@pytest.mark.parametrize(
    ("command", "height", "length"),
    [
        ("Cell, this is Control. Height tree, length six, wall. Over.", 3, 6),
        ("wall, fower high, fife long", 4, 5),
    ],
)
def test_numbers_in_radio_voice_procedure(command, height, length):
    (s,) = read(command).spec.structures
    assert (s.shape, s.height, s.length) == ("wall", height, length)


def test_a_figure_in_brackets_that_repeats_the_word_is_one_number_and_one_that_disagrees_is_said():
    (s,) = read("a tower of five (5) cubes").spec.structures
    assert s.height == 5
    r = plan("a tower of five (4) cubes")
    assert r.status == "partial" and any("'4'" in n for n in r.notes), r.notes


def test_a_number_said_digit_by_digit():
    (s,) = read("a row of cubes along y, wun-fife-zero millimetres long").spec.structures
    assert (s.shape, s.length_m) == ("row", 0.15)


def test_a_contracts_thereof_and_upon_relate_the_tower_to_the_slab():
    r = read("The Contractor shall lay a slab of three (3) by three (3) cubes, and shall erect "
             "upon the centre thereof a tower of two (2) cubes.")  # fmt: skip
    (rel,) = r.spec.relations
    assert rel.kind == "on_top_of" and r.spec.structures[rel.object].shape == "grid"


def test_a_slab_comprising_cubes_in_rows_is_that_slab_not_a_second_structure():
    (s,) = read("one slab comprising twelve cubes arranged in three rows of four").spec.structures
    assert (s.shape, sorted((s.length, s.width))) == ("grid", [3, 4])


def test_extending_a_row_makes_it_longer_not_taller():
    (s,) = read("a row of 5, then extend it by two more cubes at the same end").spec.structures
    assert (s.shape, s.length) == ("row", 7)


def test_structures_placed_in_the_order_named_from_front_to_back_stand_in_a_line_along_x():
    r = read("a tower of 1, a tower of 2 and a tower of 3 placed in that order from front to back")
    assert r.spec.line == "x" and [s.height for s in r.spec.structures] == [1, 2, 3]
    assert r.complete  # 'order' is used, not an unused material word


def test_a_user_storys_done_when_is_checked_against_the_reading():
    ok = plan("a row of 5, then extend it by two. Done when: one row, seven long.")
    assert ok.status == "success", ok.notes
    bad = plan("a row of 5. Done when: one row, six long.")
    assert bad.status == "partial", bad.notes


@pytest.mark.parametrize(
    "command",
    ["Lay a deck five by five, one thick, but leave the middle open.",
     "a 3x3 slab, keep the centre free"],
)  # fmt: skip
def test_a_slab_with_its_middle_left_open_is_a_ring(command):
    (s,) = read(command).spec.structures
    assert s.shape == "enclosure"


def test_a_clause_placing_a_structure_at_a_side_is_not_chatter():
    r = plan("make a wall of 5 length, 2 height, and keep a tower of 3 on its right side itself")
    assert r.status != "success" or len(r.spec.relations) == 1, r.notes
    assert plan("a tower of 4 but not in the middle, put it somewhere off to the side").status == (
        "success"
    )


def test_several_things_of_sdis_choosing_are_that_many_structures():
    r = plan("build three different things, robot, you choose what.")
    assert r.status == "success" and len({s.shape for s in r.spec.structures}) == 3, r.notes
    guessed = plan("Please build two things, you can choose what, but not too big, under 5 high.")
    assert guessed.status == "partial", guessed.notes  # one wall of the parts said: not two things


def test_sizes_labelled_with_the_cells_axes():
    (s,) = read("Block, 150 x 100 x 100 mm (X x Y x Z).").spec.structures
    # x is depth (away from the robot), y across
    assert (s.shape, s.width_m, s.length_m, s.height_m) == ("block", 0.15, 0.1, 0.1)
    (w,) = read("a block W×D×H = 3×2×2").spec.structures  # the older label form still reads
    assert (w.length, w.width, w.height) == (3, 2, 2)


def test_what_is_said_before_anyway_is_an_aside():
    r = read("My grandmother had a clock shaped like a little temple. Anyway: a ring of cubes, "
             "four by four, two high, please.")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["enclosure"] and r.complete
    kept = read("Build a tower of 3. Anyway, a wall of 4 too.")
    assert [s.shape for s in kept.spec.structures] == ["tower", "wall"]  # a build verb: no aside


def test_no_module_of_the_front_end_binds_a_top_level_name_twice():
    # a second `_AXES_LABEL` in normalise silently replaced the first (a 'W×D×H =' label then
    # stayed in the text): the rule tables of these modules are long, so names must not repeat
    import ast
    import collections
    from pathlib import Path

    import sdi

    root = Path(sdi.__file__).parent
    for path in [*(root / "language").glob("*.py"), *(root / "spec").glob("*.py")]:
        names: collections.Counter[str] = collections.Counter()
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.Assign):
                names.update(t.id for t in node.targets if isinstance(t, ast.Name))
            elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
                names[node.target.id] += 1
            elif isinstance(node, ast.FunctionDef | ast.ClassDef):
                names[node.name] += 1
        assert [n for n, c in names.items() if c > 1] == [], path.name


@pytest.mark.parametrize(
    "command",
    ["make any shape you like, but keep it on the left",
     "Do one thing, make any shape you like, but keep it in the left side only."],
)  # fmt: skip
def test_a_structure_of_sdis_choosing_goes_where_it_is_then_placed(command):
    # "keep it on the left" said after the choice was left to SDI: an error, or a tower mid-table
    (s,) = read(command).spec.structures
    assert (s.shape, s.region) == ("tower", "left")


@pytest.mark.parametrize(
    ("command", "region"),
    [("a wall 6 long, 2 high; it shall not be placed along the front of the table", "back"),
     ("a tower of 3, it must not be built on the left side", "right"),
     ("a tower of 3 at the back, not the front", "back"),
     ("a tower of 3 on the left side, not the right", "left")],
)  # fmt: skip
def test_a_place_said_with_not_is_the_other_one(command, region):
    r = plan(command)
    assert r.status == "success" and r.spec.structures[0].region == region, r.notes


@pytest.mark.parametrize(
    "command",
    ["a tower of 3; it will never stand at the back", "a tower of 3; nothing at the back"],
)
def test_a_place_a_negation_excludes_is_never_built_silently(command):
    # it was read as at the back, with no note
    r = plan(command)
    assert r.status == "partial" and any("exclude" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("command", "shape", "sizes"),
    [  # a fitter's millimetres with no unit: sizes in parts of 50 mm
        ("Wall, 350 long by 150 high.", "wall", {"length_m": 0.35, "height_m": 0.15}),
        ("Block, 100 by 100, 150 high.", "block", {"length": 2, "width": 2, "height_m": 0.15}),
        ("Tower of 150, centre at X 400, Y 200.", "tower", {"height_m": 0.15, "at_x": 0.4}),
        ("Ring, 250 square outside, 100 high.", "enclosure", {"length": 5, "width": 5}),
    ],
)
def test_a_round_size_of_50_or_more_without_a_unit_is_in_millimetres(command, shape, sizes):
    r = read(command)
    (s,) = r.spec.structures
    assert s.shape == shape and all(getattr(s, k) == pytest.approx(v) for k, v in sizes.items())
    assert any("without a unit" in n for n in r.notes)


@pytest.mark.parametrize(
    "command", ["Hi, job 2207: tower of 3", "station 40, a tower of 3", "a row of 5 cubes at 10:30"]
)
def test_a_job_number_or_a_time_is_no_size(command):
    (s,) = read(command).spec.structures
    assert getattr(s, "height", None) == 3 or getattr(s, "length", None) == 5


def test_a_fitters_mil_and_daylight():
    r = read("Two towers, 200 mil high, 50 mil of daylight between them, and a 150 beam across "
             "the top.")  # fmt: skip
    (s,) = r.spec.structures
    assert (s.shape, s.spans, s.height_m) == ("bridge", 1, pytest.approx(0.2)) and r.complete


def test_keep_it_off_an_edge_and_a_coordinate_said_with_not():
    (s,) = read("Block 150 by 150, 100 high, and keep it off the front edge.").spec.structures
    assert s.region == "back"
    assert plan("Column 200 tall, do not place it forward of X500.").status == "partial"


@pytest.mark.parametrize(
    "command",
    ["Build a wall, six long, two high. Scratch that - a row of six instead.",
     "Build a wall, six long, two high. Scratch that, make it a row of six.",
     "Build a wall, six long, two high. Och, scrap that, a row of six instead."],
)  # fmt: skip
def test_scratch_that_with_the_new_structure_in_the_same_sentence_takes_the_old_one_back(command):
    # the wall was built as well, silently
    r = plan(command)
    assert r.status == "success" and [(s.shape, s.length) for s in r.spec.structures] == [
        ("row", 6)
    ], r.notes


def test_max_parts_and_one_more_on_top():
    (s,) = read("a tower, max 6 cubes").spec.structures
    assert s.height == 6
    r = read("3x3 slab center. Then 2x2 on top. Then 1 on top of that")
    assert [x.shape for x in r.spec.structures] == ["grid", "grid", "tower"]
    assert len(r.spec.relations) == 2 and r.complete


@pytest.mark.parametrize(
    ("command", "shape"),
    [("Towel of 5 cubes front right", "tower"), ("a slav 3 by 3", "grid")],
)
def test_a_real_word_one_letter_off_where_a_structure_is_named_and_sized(command, shape):
    r = read(command)
    assert [s.shape for s in r.spec.structures] == [shape] and any(
        "corrected" in n for n in r.notes
    )


def test_an_autocorrected_beam_and_a_structure_named_beside_an_everyday_word():
    (b,) = read("Bridge w/ legs of 2 and a bean across").spec.structures
    assert b.shape == "bridge"
    # a towel beside a tower named is not corrected: the command names its structure
    assert plan("a towel of 3 next to a tower").status != "success"


def test_a_list_of_heights_with_its_dimension_word_after_it():
    r = read("towers of 2, 3 and 4 high")
    assert [s.height for s in r.spec.structures] == [2, 3, 4] and r.complete


def test_a_slab_said_with_its_cubes_and_rows_in_commas_and_a_pyramid_base_in_centimetres():
    (s,) = read("Slab, 12 cubes, 3 rows of 4").spec.structures
    assert sorted((s.length, s.width)) == [3, 4]
    (p,) = read("Pyramid w/ a 15cm base").spec.structures
    assert (p.shape, p.length, p.dims) == ("pyramid", 3, 3)


@pytest.mark.parametrize(("command", "word"), [("Tower of", "of"), ("a row of 5 and", "and")])
def test_a_command_that_stops_mid_phrase_is_not_a_silent_success(command, word):
    r = plan(command)
    assert r.status == "partial" and f"the command stops after '{word}'" in " ".join(r.notes)


def test_changes_said_of_the_structure_by_its_name_and_in_other_verbs():
    (row,) = read("a row of three cubes. Then please extend the row by two cubes at the same "
                  "end, so that it becomes five cubes long.").spec.structures  # fmt: skip
    assert row.length == 5
    (st,) = read("Staircase, four steps, 50 mil rise each. Then lose the top step.").spec.structures
    assert (st.shape, st.steps, st.height_m) == ("staircase", 3, None)
    assert plan("a staircase of 3 steps, 100 mm rise each").status == "partial"  # not one part


def test_scots_on_the_shop_floor():
    r = read("Gie us three towers o' two in a row, a cube apart.")
    assert [s.height for s in r.spec.structures] == [2, 2, 2] and r.complete
    (ring, tower) = read("Gie us a wee ring, five by five, one high, wi' a tower o' two stood in "
                         "the middle of it.").spec.structures  # fmt: skip
    assert (ring.shape, tower.height) == ("enclosure", 2)


@pytest.mark.parametrize(
    ("command", "sizes"),
    [("a wall 0.1m high", {"height_m": 0.1}),
     ("Wall 0.3m long x 0.1m high", {"length_m": 0.3, "height_m": 0.1}),
     ("wall 300 mm long x 150 mm high", {"length_m": 0.3, "height_m": 0.15})],
)  # fmt: skip
def test_a_metric_size_glued_to_its_unit_and_an_x_between_two_sizes(command, sizes):
    # "0.1m" was read back as a scanner's "0.im" (an error), "x 0.1m" as a coordinate
    r = plan(command)
    (s,) = r.spec.structures
    assert r.status == "success" and all(
        getattr(s, k) == pytest.approx(v) for k, v in sizes.items()
    )


@pytest.mark.parametrize(
    ("command", "shapes"),
    [("Two towers of 3. Then put a beam across the tops.", ["bridge"]),
     ("Lay a 3 by 2 slab, one course. Then put a second course on it, same size.", ["block"]),
     ("Shift B, station 4, cycle 118. Block 2x2, 2 high", ["block"]),
     ("On the right-hand side, by the end of the day if you can, a pyramid of three.", ["pyramid"]),
     ("Hi, job 2207 on the screen says: tower of 3. Thx", ["tower"]),
     ("a wall 5 long, square to the front edge", ["wall"]),
     ("Something tall-ish for the lobby photo, as long as it doesn't fall over.", ["tower"])],
)  # fmt: skip
def test_shop_floor_phrases_that_are_no_structure_or_a_change_of_one(command, shapes):
    # each built a second structure, left a word unused, or read 'as long as' as a row's length
    r = plan(command)
    assert r.status == "success" and [s.shape for s in r.spec.structures] == shapes, r.notes


def test_an_ordinal_step_word_begins_a_step_and_is_never_lost():
    # "Secondly, remove the top cube." vanished with no note (a silent success)
    r = plan("a pyramid of 3 levels. Secondly, remove the top cube.")
    assert any("remove the top cube" in n for n in r.notes)
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (3, 2)


def test_a_time_and_a_size_word_of_a_person_are_no_sizes_of_the_structure():
    r = read("So - the big boss is coming round at three and she loves a good staircase. "
             "Four steps, climbing towards the back, if you can.")  # fmt: skip
    (s,) = r.spec.structures  # two staircases were built: one 5 steps 3 wide ("big", "three")
    assert (s.shape, s.steps, s.width) == ("staircase", 4, None)


@pytest.mark.parametrize(
    ("command", "length_m", "height"),
    [("a wall 15 cm high and 25 long", 0.25, {"height_m": 0.15}),
     ("a wall 25 cm long and 10 high", 0.25, {"height_m": 0.1}),
     ("a wall 25 cm long and 2 high", 0.25, {"height": 2})],  # 2 cm is less than a part
)  # fmt: skip
def test_a_bare_size_after_one_in_centimetres_is_in_centimetres(command, length_m, height):
    (s,) = read(command).spec.structures
    assert s.length_m == pytest.approx(length_m)
    assert all(getattr(s, k) == pytest.approx(v) for k, v in height.items())


@pytest.mark.parametrize(
    ("command", "shape", "region"),
    [("Build a flat 5 wide and 3 high across the back. Then strike it and put a 4-high tower "
      "there instead.", "tower", "back"),
     ("a tower of 3 at the back left. Undo that and put a wall of 4 there.", "wall", "back left")],
)  # fmt: skip
def test_there_after_a_take_back_is_where_the_structure_taken_back_stood(command, shape, region):
    r = plan(command)
    (s,) = r.spec.structures  # the old one was kept, or the new one stood mid-table, silently
    assert r.status == "success" and (s.shape, s.region) == (shape, region), r.notes


@pytest.mark.parametrize(
    "command",
    ["two towers 4 high, one on the left and one on the right",
     "two towers, 4 high, one on the left and one on the right",
     "two towers of 4 cubes, one on the left and one on the right",
     "two towers of 4 cubes of height, one on the left and one on the right"],
)  # fmt: skip
def test_two_towers_one_on_each_side_are_two_towers(command):
    # four were built (the cubes read as loose cubes, or 'one … one' as two more), silently
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted((s.region, s.height) for s in r.spec.structures) == [("left", 4), ("right", 4)]


def test_a_single_cube_said_beside_counted_towers_is_no_miscount():
    # the count check reads the command as said: a single cube is a tower of one
    r = plan("a single cube placed between two 4-cube towers")
    assert r.status == "success" and len(r.spec.structures) == 3, r.notes


@pytest.mark.parametrize(
    ("command", "heights"),
    [("three towers next to each other, heights 1 2 3", [1, 2, 3]),
     ("put two cubes on top of each other", [2]),
     ("three cubes one on top of the other", [3])],
)  # fmt: skip
def test_everyday_stacks_and_lists(command, heights):
    # 'heights 1 2 3' built three towers of 1; 'two cubes on top of each other' a row, silently
    r = plan(command)
    assert r.status == "success" and [s.height for s in r.spec.structures] == heights, r.notes


def test_next_to_it_on_the_right_is_that_side():
    r = read("a tower of six cubes, and next to it on the right a tower of two")
    (rel,) = r.spec.relations
    assert (rel.kind, rel.side, r.spec.structures[rel.subject].height) == ("next_to", "right", 2)


@pytest.mark.parametrize(
    ("command", "shape", "sizes"),
    [("an L with 4 cubes in each arm", "l_shape", {"length": 4, "width": 4}),
     ("two 3x3 slabs stacked", "block", {"length": 3, "width": 3, "height": 2}),
     ("two 2 by 2 pads on top of each other", "block", {"length": 2, "width": 2, "height": 2})],
)  # fmt: skip
def test_arms_and_stacked_slabs(command, shape, sizes):
    # the arms were unused (partial); two slabs were built side by side, silently
    r = plan(command)
    (s,) = r.spec.structures
    assert r.status == "success" and s.shape == shape
    assert all(getattr(s, k) == v for k, v in sizes.items())


def test_an_opening_in_a_wall_is_reported():
    # it was built as a ring around a bridge, silently
    r = plan("a wall with a door in the middle")
    assert r.status == "partial" and any("no opening" in n for n in r.notes)
    assert plan("behind the tower of 3, the wall of 4 long 2 high, with a gap of one").status == (
        "success"
    )


@pytest.mark.parametrize(
    ("command", "gap"),
    [
        ("two towers of 3, 2 apart", 0.1),
        ("two towers of 3, 10 apart", 0.1),
        ("two towers 2 apart", 0.1),
    ],
)
def test_a_gap_said_without_a_unit(command, gap):
    # "2 apart" was read as a second tower 2 high (or a gap of 2 cm), silently
    r = read(command)
    assert len(r.spec.structures) == 2 and r.spec.gap_m == pytest.approx(gap)
    assert len({s.height for s in r.spec.structures}) == 1


def test_a_tower_on_each_side_of_a_wall_named_after_it():
    # one tower stood behind the wall's end, the other beside it, silently
    r = plan("a tower of 2 on each side of a wall 4 long")
    cols = _columns(r)
    assert r.status == "success" and len(r.spec.structures) == 2
    assert len({x for x, _ in cols}) == 1 and len(cols) == 6  # one line: a tower at each end


def test_a_corner_not_said_is_an_assumption_said():
    r = plan("stack 4 blocks in the corner")
    assert r.spec.structures[0].region == "back left"
    assert "read 'the corner' as the back left corner (which was not said)" in r.notes


def test_a_staircase_that_goes_up_steps_to_a_side_and_a_third_tower():
    (s,) = read("I need a staircase that goes up 4 steps to the left").spec.structures
    assert (s.shape, s.steps, s.axis, s.region) == ("staircase", 4, "y", None)  # not a place
    r = plan("a tower of 3 cubes, another of 4 and a third of 5")
    assert r.status == "success" and [t.height for t in r.spec.structures] == [3, 4, 5]


def test_several_structures_on_one_top_are_reported_and_two_walls_forming_a_corner_an_l():
    # one of the two towers stood on the table beside the slab, silently
    r = plan("a 4x2 slab with two towers of 2 on it")
    assert r.status == "partial" and any("all but one" in n for n in r.notes)
    (s,) = read("two walls forming a corner").spec.structures  # two walls and an L were built
    assert (s.shape, s.height) == ("l_shape", 2)


def _footprints(layout):
    """Footprint centres (x, y) of the columns of `layout`, rounded to a millimetre."""
    return sorted({(round(p.position[0], 3), round(p.position[1], 3)) for p in layout.objects})


def test_separate_structures_in_rows_and_columns():
    # "in a square", "in a 2x2 grid", "in two rows of three": the structures themselves stand
    # in rows and columns; before, a grid of cubes was added beside them, silently
    r = plan("place 4 towers of 2 in a square")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower"] * 4
    cols = _footprints(r.layout)
    assert len(cols) == 4 and len({x for x, _ in cols}) == 2 and len({y for _, y in cols}) == 2
    r = plan("six towers of 2 in two rows of three")
    assert r.status == "success" and len(r.spec.structures) == 6 and r.spec.grid == (2, 3)
    cols = _footprints(r.layout)
    assert len({x for x, _ in cols}) == 2 and len({y for _, y in cols}) == 3
    r = plan("four towers, three high, in a 2x2 grid")
    assert [s.shape for s in r.spec.structures] == ["tower"] * 4 and r.spec.grid == (2, 2)
    assert r.status == "success" and len(r.layout) == 12
    r = plan("a 2 x 3 array of 2-high stacks")
    assert r.status == "success" and r.spec.grid == (2, 3) and len(r.layout) == 12
    # stated gaps hold between rows and between columns
    r = plan("four towers of 3 in a square, 10 cm apart")
    xs = sorted({x for x, _ in _footprints(r.layout)})
    assert r.spec.grid == (2, 2) and abs((xs[1] - xs[0]) - 0.15) < 1e-6
    # counts no arrangement fits are said; cubes in a square are one grid
    for text in ("five stacks in a grid", "six towers in a square", "three towers in a square"):
        r = plan(text)
        assert r.status == "partial" and r.spec.grid is None, text
    r = plan("nine cubes arranged in a square")
    assert [(s.shape, s.count) for s in r.spec.structures] == [("grid", 9)]
    # three rows stacked on each other are one wall
    s = read("three rows of four cubes stacked on top of each other").spec.structures
    assert [(x.shape, x.length, x.height) for x in s] == [("wall", 4, 3)]


def test_a_grid_arrangement_must_place_every_separate_structure():
    from sdi.spec.structure_spec import Spec, structure

    towers = tuple(structure("tower", height=2) for _ in range(4))
    assert Spec(structures=towers, grid=(2, 2)).grid == (2, 2)
    with pytest.raises(ValueError, match="grid: 2 x 3 places for 4"):
        Spec(structures=towers, grid=(2, 3))


def _heights(layout):
    """Column heights in parts, keyed by footprint centre (x, y) rounded to a millimetre."""
    tops: dict[tuple[float, float], int] = {}
    for p in layout.objects:
        key = (round(p.position[0], 3), round(p.position[1], 3))
        tops[key] = max(tops.get(key, 0), round((p.position[2] + p.size[2] / 2) / 0.05))
    return tops


def test_as_tall_as_a_structure_named_before_is_its_measured_size():
    # "as tall as the staircase" was read as a vague "tall" (6 high), silently
    r = plan("a staircase of 3 steps and a tower as tall as the staircase")
    assert r.status == "success" and [
        s.height for s in r.spec.structures if s.shape == "tower"
    ] == [3]
    r = plan("a tower of 2 and a wall as high as the tower")
    assert r.status == "success" and r.spec.structures[1].height == 2
    r = plan("a wall 6 long and a row as long as the wall")
    assert r.spec.structures[1].length == 6
    r = plan("a pyramid with a 4x4 base and next to it a tower as tall as the pyramid")
    assert r.status == "success" and r.spec.structures[1].height == 4
    r = plan("a tower as tall as the wall")  # nothing named before it to measure
    assert r.status == "partial"


def test_a_pyramid_with_its_top_taken_off_keeps_its_base():
    for text in ("a pyramid of 4 levels, then take the top cube off",
                 "They'd like a pyramid of four levels, but they also said to take the top cube "
                 "off it afterwards."):  # fmt: skip
        r = plan(text)
        (s,) = r.spec.structures
        assert r.status == "success" and (s.shape, s.length, s.height) == ("pyramid", 4, 3), text
    r = plan("a pyramid with a base of 4, 3 levels high")  # two sizes, not a list of values
    assert r.status == "success" and (r.spec.structures[0].length, r.spec.structures[0].height) == (
        4, 3)  # fmt: skip


def test_sides_order_and_gaps_said_in_everyday_ways():
    # "right" as "exactly" is no side; "on the right at the back" is both
    r = plan("They want a wall of 6 by 2 right across the middle of the table, left to right.")
    assert r.status == "success" and r.spec.structures[0].region == "centre"
    assert read("a tower on the right at the back").spec.structures[0].region == "back right"
    r = plan("a tower of 3 and a cube right next to it")
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["next_to"]
    # "not too close to the robot": away from it; "going away from the robot" is a direction
    assert (
        read("a tower of 4, I guess not too close to the robot").spec.structures[0].region == "back"
    )
    assert read("a row of 4 going away from the robot").spec.structures[0].region is None
    # "towers of 3 and 6, 2 cubes apart": the gap between two towers, not a third tower
    r = plan(
        "Client says: towers of 3 and 6, 2 cubes apart, and the shorter one has to be in front."
    )
    assert r.status == "success" and sorted(s.height for s in r.spec.structures) == [3, 6]
    tops = _heights(r.layout)
    x_short = [x for (x, _), h in tops.items() if h == 3]
    x_tall = [x for (x, _), h in tops.items() if h == 6]
    assert max(x_short) < min(x_tall)  # the shorter one in front (smaller x)
    # "lined up with the middle of the row": a structure beside another is centred on it
    r = plan(
        "Row of 5 at the front, then tower of 3 behind it, lined up with the middle of the row"
    )
    assert r.status == "success" and len(r.spec.structures) == 2
    # a work order's list labels and bare nouns: "Row 2:" is a label, "on top of blk" the block
    r = plan("Row 1: Wall, L=5, H=2, Loc front. Row 2: same wall, Loc back.")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("wall", "front"), ("wall", "back")]
    r = plan("REQ: blk 2x2x2, LOC: ctr. Twr 3H on top of blk, centred.")
    assert [s.shape for s in r.spec.structures] == ["block", "tower"]
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]


def test_unused_words_that_change_a_structure_are_material():
    # "(supersedes rev A)": a change SDI did not make is not success ("extend it to 5 steps" is
    # now made, see test_extended_to_a_size_and_a_list_of_heights_with_one_unit)
    assert (
        plan("Job 4 rev A: Tower H 3. Job 4 rev B: Tower H 6 (supersedes rev A)").status
        == "partial"
    )
    # a structure placed where "everything" should not be is said
    r = plan("Keep everything on the right half, the left half is where the forklift goes. "
             "A wall of 5, 2 high.")  # fmt: skip
    assert r.status == "partial"


def test_an_operator_changes_and_takes_from_what_was_named():
    # "changed it to 5", "remove the right one", "take 2 off the left one", "from one end"
    r = plan("The customer ordered a tower of 7, then called back and changed it to 5.")
    assert r.status == "success" and [(s.height, s.region) for s in r.spec.structures] == [
        (5, None)
    ]
    r = plan("Three towers of 2, 3 and 4 in a line. Then remove the right one.")
    assert sorted(s.height for s in r.spec.structures) == [3, 4]  # listed right to left: the 2 goes
    r = plan(
        "tower of 4 on the left, tower of 4 on the right, then, hmm, I guess take 2 off "
        "the left one"
    )
    assert r.status == "success"
    assert sorted((s.region, s.height) for s in r.spec.structures) == [("left", 2), ("right", 4)]
    r = plan("Lay out a row of 8, then remove 3 cubes from one end.")
    assert r.status == "success" and r.spec.structures[0].length == 5
    r = plan("a wall 6 long 2 high, then take 2 cubes off one end")  # one column of two
    assert r.spec.structures[0].length == 5
    assert plan("a wall 6 long 2 high, then take 3 cubes off one end").status == "partial"
    r = plan(
        "They asked for a 3x3 block two high, and then on reflection they'd like one more "
        "layer on it."
    )
    assert r.status == "success" and r.spec.structures[0].height == 3


def test_hesitations_and_a_pronoun_for_the_family_named_before():
    r = plan("row of 5? no wait, 4 I think. yes 4. along the front")
    assert r.status == "success" and [(s.length, s.region) for s in r.spec.structures] == [
        (4, "front")
    ]
    r = plan("a tower of... I guess 7? seven's fine")
    assert r.status == "success" and r.spec.structures[0].height == 7
    r = plan("Next job: 4-high tower, and a 2-high one right next to it on its left.")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4, 2]
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "left")]
    r = plan("a stack double the height of a 3-cube one")  # a measure, not a second stack
    assert [s.height for s in r.spec.structures] == [6]
    # "another one 2 high" after a 3x3 slab: that footprint, its own height
    r = plan("a 3x3 slab 4 high, then another one 2 high next to it")
    assert [(s.length, s.width, s.height) for s in r.spec.structures] == [(3, 3, 4), (3, 3, 2)]
    r = plan("put a tower of 2, and another one three times that height beside it")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 6]
    # a phrasal "back" is no place; articles dropped after a comma
    assert (
        read("a tower of 3, I'll get back to you about the rest").spec.structures[0].region is None
    )
    r = plan("tower of 4 on the left, tower of 4 on the right")
    assert r.status == "success" and [s.region for s in r.spec.structures] == ["left", "right"]


def test_rows_said_apart_and_places_refused_in_other_words():
    r = plan("make two rows of six, parallel, with one cube between them")
    assert (
        r.status == "success"
        and [(s.shape, s.length) for s in r.spec.structures] == [("row", 6)] * 2
    )
    assert [s.shape for s in plan("two rows of four").spec.structures] == ["grid"]
    r = plan("wall 5 by 2 but not along the back, the camera is mounted there")
    assert r.status == "success" and r.spec.structures[0].region == "front"
    r = plan("They'd like a pyramid of 3 levels, and they specifically don't want it on the left.")
    assert r.status == "success" and r.spec.structures[0].region == "right"


def test_a_plan_view_and_everyday_step_and_gap_words():
    # a drawing seen from above, the robot at the bottom: top is the back
    r = plan("On the drawing of the table, the tower (4 high) is top left and the 2x2 square "
             "(one high) is bottom right.")  # fmt: skip
    assert r.status == "success"
    assert [s.region for s in r.spec.structures] == ["back left", "front right"]
    r = plan("a 3x3 slab with a cube on its top left corner")  # its own corner, on top
    assert [(x.kind, x.at) for x in r.spec.relations] == [("on_top_of", "back left corner")]
    # a step's rise said in units is one part; a rise SDI cannot build is said
    r = plan("Staircase with six 5 cm steps.")
    assert r.status == "success" and r.spec.structures[0].steps == 6
    assert plan("Staircase 150 mm high, 50 mm steps.").status == "success"
    assert plan("a staircase with 10 cm steps").status == "partial"
    # a gap with its distance after a fronted structure keeps the side said
    r = plan("a wall 5 long. a 3 high tower 5 cm behind it")
    assert [(x.subject, x.object, x.side) for x in r.spec.relations] == [(1, 0, "back")]
    r = plan("First, build a tower of four at the front right. After that, put a tower of two "
             "directly behind it, a cube apart. Finally, put a tower of three directly to the "
             "left of the first one, also a cube apart.")  # fmt: skip
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4, 2, 3]
    # "a row of three cubes between them" is the row's size, not a gap
    r = plan("two towers of 3, then put a row of three cubes between them")
    assert not any("0.15 m" in n for n in r.notes)


def test_one_more_structure_a_described_bridge_and_a_sized_rectangle():
    r = plan("two towers of three and one tower of five")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 3, 5]
    r = plan("two towers, one of 3 and one of 5")  # each of the two named
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 5]
    r = plan("Hello! Would it be possible to build a little bridge — two towers of two cubes with "
             "one of those long beams laid across the top? Thank you so much.")  # fmt: skip
    assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
        ("bridge", 2)
    ]
    r = plan("Could I please have a dozen cubes laid out as a flat rectangle, two rows of six?")
    assert r.status == "success" and [(s.shape, s.length, s.width) for s in r.spec.structures] == [
        ("grid", 6, 2)]  # fmt: skip
    r = plan(
        "I'd like a tower of three, please — oh, actually, could it be a tower of five instead?"
    )
    assert r.status == "success" and [s.height for s in r.spec.structures] == [5]


def test_distances_from_the_table_edges_and_corners_on_one_side():
    r = plan("15 cm tower, its centre 10 cm from the front edge and 15 cm from the left edge.")
    (s,) = r.spec.structures
    assert r.status == "success" and (s.at_x, s.at_y) == (0.3, 0.4)
    (s,) = plan(
        "From the left edge 10 cm, from the back edge 10 cm: a 10 cm tower."
    ).spec.structures
    assert (s.at_x, s.at_y) == (0.7, 0.45)
    r = plan("First a tower of three in each back corner. After that, a tower of two in each front "
             "corner.")  # fmt: skip
    assert r.status == "success"
    assert sorted((s.region, s.height) for s in r.spec.structures) == [
        ("back left", 3), ("back right", 3), ("front left", 2), ("front right", 2)]  # fmt: skip


def test_people_counted_a_round_likeness_and_sizes_in_units_before_the_noun():
    r = plan("I hope I'm not holding up the queue — my grandson is waiting outside with his two "
             "sisters. Could you make a row of three cubes for him to see?")  # fmt: skip
    assert r.status == "success" and [(s.shape, s.length) for s in r.spec.structures] == [
        ("row", 3)
    ]
    r = plan("Could you build a cone, please, about fifteen centimetres high?")
    assert any("cone" in n and "stepped" in n for n in r.notes)  # said, not silently squared
    r = plan("Two 15 cm towers with a 10 cm gap between them.")
    assert r.status == "success" and len(r.spec.structures) == 2


def test_parts_taken_off_an_end_or_the_top_and_sizes_changed_in_units():
    r = plan("First build a row of six along the front, left to right. After that, take the two "
             "cubes off its left end.")  # fmt: skip
    assert r.status == "success" and r.spec.structures[0].length == 4
    r = plan("Build a tower of seven. Then remove the top two cubes.")
    assert r.status == "success" and r.spec.structures[0].height == 5
    r = plan("Build a 30 cm tower. Then shorten it by 10 cm.")
    assert r.status == "success" and r.spec.structures[0].height == 4
    r = plan("Block 15 x 10 cm, 10 cm high; then add 5 cm to its height.")
    assert r.status == "success" and r.spec.structures[0].height == 3
    # the one on a side, of structures named left to right or placed by SDI (right to left)
    r = plan("Three towers of 2, 3 and 4, left to right. Then take away the one on the right.")
    assert sorted(s.height for s in r.spec.structures) == [2, 3]
    r = plan("Three towers of 2, 3 and 4. Then take away the one on the right.")
    assert sorted(s.height for s in r.spec.structures) == [3, 4]
    # which one is said by height; one SDI cannot pick out is reported, not guessed
    r = plan(
        "a tower of 4 on the left and a tower of 5 on the right, then take 2 off the taller one"
    )
    assert sorted((s.region, s.height) for s in r.spec.structures) == [("left", 4), ("right", 3)]
    assert plan("two towers of 4, then take 2 off the red one").status == "partial"
    r = plan("Build three towers of three in a row, left to right.")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower"] * 3


def test_the_same_again_a_top_step_and_words_that_are_no_structure():
    r = plan("First a tower of two at the front left, after that the same at the back left, and "
             "finally the same at the back right.")  # fmt: skip
    assert r.status == "success"
    assert [(s.region, s.height) for s in r.spec.structures] == [
        ("front left", 2), ("back left", 2), ("back right", 2)]  # fmt: skip
    r = plan("on the left, a tower. 3 high. no, 4 high. then on the right, same.")
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 4), ("right", 4)]
    r = plan(
        "First, build a staircase of four steps. After that, put a single cube on its top step."
    )
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["on_top_of"]
    r = plan("a tower of four cubes, but please not in the middle of the table? It would block my "
             "view of the robot.")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["tower"]  # "block" is a verb here
    r = plan("First, four towers of three, one in each corner of the table. After that, a single "
             "cube in the centre.")  # fmt: skip
    assert r.status == "success" and sorted(str(s.region) for s in r.spec.structures) == [
        "back left", "back right", "centre", "front left", "front right"]  # fmt: skip
    r = plan("two walls facing each other, each four cubes long and two cubes high, with a gap of "
             "two cubes between them")  # fmt: skip
    assert r.status == "success" and len(r.spec.structures) == 2
    (s,) = plan("A solid cube made of cubes, 15 cm each way.").spec.structures
    assert (s.length_m, s.width_m, s.height_m) == (0.15, 0.15, 0.15)


def test_a_number_only_the_structure_count_explains_must_count_something():
    from sdi.language.coherence import _counts_something
    from sdi.language.syntax import parse

    def counts(text: str, word: str) -> bool:
        doc = parse(text)
        return _counts_something(doc, next(t.i for t in doc if t.text == word))

    assert counts("two towers of 3", "two")
    assert counts("two separate 3-cube pillars", "two")
    assert counts("a tower of 3 and 2 more like it", "2")
    assert not counts("a wall and a tower 2 wide", "2")  # a size no slot took: reported


def test_thinking_aloud_is_no_content():
    r = plan(
        "hmm, a ring, maybe 5 by 5, one high, and I guess a tower of 3 standing in the middle of it"
    )
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["around"]
    r = plan("maybe two towers, both 4 high, roughly a cube apart, and a beam across them I guess")
    assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
        ("bridge", 4)
    ]
    r = plan(
        "I think a staircase, 4 steps, and then, not sure, maybe a cube on the top step? "
        "yeah, let's do that"
    )
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["on_top_of"]
    r = plan("roughly a 3 by 3 by 3 block, I mean made out of cubes")
    assert r.status == "success"
    assert [(s.length, s.width, s.height) for s in r.spec.structures] == [(3, 3, 3)]
    r = plan("maybe three towers of 2")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 2, 2]


def test_a_form_of_keyed_fields_is_read_field_by_field():
    from sdi.language.fields import as_words

    r = plan("Tower | H: 4 | X (mm): 500 | Y (mm): 400")
    (s,) = r.spec.structures
    assert r.status == "success" and (s.height, s.at_x, s.at_y) == (4, 0.5, 0.4)
    r = plan("Wall | L (mm): 400 | H (mm): 100")
    assert r.status == "success" and r.layout is not None and len(r.layout) == 16
    r = plan("Qty 2 | Bridge | Post H: 2 | Beam: 1 each")
    assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
        ("bridge", 2), ("bridge", 2)]  # fmt: skip
    r = plan(
        "MES export 14/03 08:00 – Order 77812 – Priority 2 – Item: Tower – Qty: 1 – Height: 6 cubes"
    )
    assert r.status == "success" and [s.height for s in r.spec.structures] == [6]
    r = plan("Loc: front left / Item: row / Qty cubes: 5")
    assert [(s.shape, s.length, s.region) for s in r.spec.structures] == [("row", 5, "front left")]
    r = plan("Item: ring | Size: 4x4 | H: 2 | Contents: 1 cube, centred inside")
    assert [x.kind for x in r.spec.relations] == ["around"]
    # prose with dashes or slashes is no form
    notes: list[str] = []
    assert as_words("a wall - 5 long - and a tower", notes) == "a wall - 5 long - and a tower"
    assert notes == []


def test_a_single_cube_said_inside_a_ring_is_built():
    # "with 1 cube, centred inside" was dropped, silently
    r = plan("a ring 4x4, 2 high, with 1 cube, centred inside")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("enclosure", 2), ("tower", 1)]
    assert [x.kind for x in r.spec.relations] == ["around"]


def test_changes_comparisons_and_directions_said_in_everyday_ways():
    r = plan("Check build: 2x2 block, 3 high. Tower of 5 touching its left side.")
    assert [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [("next_to", "left", 0.0)]
    r = plan("A set of steps, four of them, going up to the left; then cap the top step with one "
             "more cube.")  # fmt: skip
    shapes = [(s.shape, getattr(s, "steps", None) or s.height) for s in r.spec.structures]
    assert shapes == [("staircase", 4), ("tower", 1)]
    r = plan("Gripper changed. Test piece: block 2x2x2. Then build it up to 2x2x4.")
    assert r.status == "success" and r.spec.structures[0].height == 4
    r = plan("A low fence along the back, one cube high and six long, then make it a cube taller.")
    assert r.status == "success" and (r.spec.structures[0].length, r.spec.structures[0].height) == (
        6, 2)  # fmt: skip
    r = plan("Check build: two towers, one of 3 and the other taller by 2, gap 1.")
    assert sorted(s.height for s in r.spec.structures) == [3, 5]
    r = plan("A pair of gateposts, each three cubes tall, a cube apart.")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 3]
    r = plan("A set of steps in the front left corner, three steps, going up towards the back.")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("staircase", "front left")]
    r = plan("four separate cubes in a row, 2 cubes apart")  # parts, not centimetres
    assert r.spec.structures[0].gap_m == 0.1
    r = plan("Task 1: Place four single cubes in a line from front to back, each one cube apart.")
    assert r.status == "success" and r.spec.structures[0].length == 4
    (s,) = plan("A low fence down the left side, 30 cm long and 5 cm high.").spec.structures
    assert s.region == "left"
    r = plan("Put a row of seven cubes and don't make it go front to back.")
    assert r.spec.structures[0].axis == "y"
    both = plan("a staircase of three steps going up to the left and going up to the right")
    assert both.status == "partial"
    assert (
        plan("a staircase going up to the left, no wait, going up to the right").status == "success"
    )


def test_sticky_notes_negated_places_and_the_one_on_a_side():
    r = plan("tower of 4 x2 pls, before 6")  # two of them; "before 6" is a time
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4, 4]
    r = plan("Task: Lay a row of five cubes. It must not be at the front of the table.")
    assert r.status == "success" and r.spec.structures[0].region == "back"
    r = plan("wall 5 long x 2 high, not along the front")
    assert r.status == "success" and r.spec.structures[0].region == "back"
    r = plan(
        "Task: Build two towers of four, one cube apart. Then remove the top cube from the "
        "one on the right."
    )
    assert r.status == "success" and sorted(s.height for s in r.spec.structures) == [3, 4]
    r = plan("Um right let me think ok a block two by two and two high in the centre.")
    assert r.spec.structures[0].region == "centre"  # "right" begins the sentence: no side
    r = plan("sorry for the mess on the bench, will sort tmrw. tower of 5 front right pls")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("tower", "front right")]
    r = plan(
        "Build two towers of three one in the front left corner and one in the back right corner."
    )
    assert sorted(str(s.region) for s in r.spec.structures) == ["back right", "front left"]


def test_both_pronouns_of_a_pair_and_a_tower_at_a_walls_end():
    # "a tower of 3 behind it and a tower of 2 in front of it": both "it"s are the wall
    r = plan("a wall 5 long, a tower of 3 behind it and a tower of 2 in front of it")
    assert r.status == "success"
    assert sorted((x.subject, x.object, x.side) for x in r.spec.relations) == [
        (1, 0, "back"), (2, 0, "front")]  # fmt: skip
    r = plan("make a wall 4 long and 2 high with a tower of 3 at the left end")
    assert [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [("next_to", "left", 0.0)]
    r = plan("a stack of 4 at the left end of the table and another stack of 4 at the right end")
    assert sorted(str(s.region) for s in r.spec.structures) == ["left", "right"]


def test_a_row_of_cubes_across_two_towers_is_a_beam_said_so():
    # "joined by a row of 3 cubes on top" stood the row on the table between them, silently
    r = plan("two towers of 3, a cube apart, joined by a row of 3 cubes on top")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["bridge"]
    assert any("would not hold" in n for n in r.notes)
    r = plan("stack 4 cubes on the left and 2 on the right")
    assert sorted((s.region, s.height) for s in r.spec.structures) == [("left", 4), ("right", 2)]


def test_a_gap_said_once_and_the_sides_of_the_work_table():
    r = plan("three towers of 3 spaced 10 cm apart in the middle")
    assert r.spec.gap_m == 0.1 and not any("0.05 m" in n for n in r.notes)  # one gap, said once
    r = plan("a tower of 3 cubes on the left side of the table, and a tower of 5 cubes on the "
             "right side")  # fmt: skip
    assert r.status == "success"  # the table's side is a place, not a relation to a table
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 3), ("right", 5)]


def test_more_said_beside_is_a_new_stack_and_lengths_listed_for_walls():
    # "then stack 2 more next to it" made the first tower 5 high, silently
    r = plan("stack 3 cubes, then stack 2 more next to it")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 2]
    assert [x.kind for x in r.spec.relations] == ["next_to"]
    r = plan("a tower of 3, then add 2 more cubes on top")  # on top: the same tower, taller
    assert [s.height for s in r.spec.structures] == [5]
    r = plan("two walls side by side, 3 and 5 long")
    assert r.status == "success" and [s.length for s in r.spec.structures] == [3, 5]


def test_a_form_names_its_item_in_the_singular_and_more_set_to_a_side_is_a_new_stack():
    # the form reader shares the data reader's family word: "Towers" is a tower ("towerss"
    # was written, and a typo correction noted for it)
    r = plan("Qty 2 | Towers | H: 3")
    assert [s.height for s in r.spec.structures] == [3, 3]
    assert not any("towerss" in n for n in r.notes)
    r = plan("stack 3 cubes, then stack 2 more to its left")
    assert [s.height for s in r.spec.structures] == [3, 2]
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "left")]


@pytest.mark.parametrize(
    ("command", "regions"),
    [
        ("I'm standing across the table from the robot. Put a tower of 3 on my left.", ["right"]),
        ("as I look at it from the visitor side, a row of 3 on the right", ["left"]),
        ("From where I stand, opposite the robot, a wall of 4 on the far side from me", ["front"]),
        ("I'm opposite the robot: a tower of 2 nearest me", ["back"]),
        ("a tower of 4 on the robot's left; I'm opposite the robot", ["left"]),
        ("a tower of 3 on my right", ["right"]),  # no viewpoint said: the robot's, noted
        ("tower of 3 on the far side of the table", ["back"]),  # a place, not a viewpoint
    ],
)
def test_places_said_from_across_the_table_are_turned_into_the_robots_frame(command, regions):
    # an operator facing the robot said where they stand; "my left" was built on the robot's
    # left, silently
    r = plan(command)
    assert r.status == "success"
    assert [s.region for s in r.spec.structures] == regions
    viewpoint = "opposite" in command or "across" in command or "visitor" in command
    assert any("read the places from where" in n for n in r.notes) == viewpoint
    assert any("as the robot's right" in n for n in r.notes) == ("my right" in command)


def test_a_viewpoint_turns_relations_orders_and_climbs_but_not_the_robots_own_words():
    r = plan("Facing the robot: a staircase of 4 climbing towards me, and a tower of 2 to the "
             "left of it")  # fmt: skip
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "right")]
    tops = {round(o.position[0], 3): o.position[2] for o in r.layout.objects}
    assert max(tops, key=tops.__getitem__) > 0.45  # climbs away from the robot, to +x
    r = plan("I'm on the other side of the table from the robot. A wall of 5 nearest me, with a "
             "tower of 2 in front of it as I see it")  # fmt: skip
    assert r.spec.structures[0].region == "back"
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "back")]
    # "from right to left" is an order (it was read as "to the left": all three at the left)
    for command in ("three towers of 1, 2 and 3 from right to left",
                    "three towers of 1, 2 and 3 from left to right, I'm standing opposite the "
                    "robot"):  # fmt: skip
        r = plan(command)
        tops: dict[float, float] = {}
        for o in r.layout.objects:
            y = round(o.position[1], 3)
            tops[y] = max(tops.get(y, 0.0), o.position[2])
        left_first = [round(tops[y] / 0.05 + 0.5) for y in sorted(tops, reverse=True)]
        assert r.status == "success" and left_first == [3, 2, 1]


def test_supports_named_with_their_gap_corners_by_count_and_things_put_inside_a_ring():
    # "two 3 high towers 10 cm apart joined with a beam" lost its towers with the gap: an error
    r = plan("two 3 high towers 10 cm apart joined with a beam")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["bridge"]
    assert r.spec.structures[0].height == 3 and r.spec.structures[0].span == 2
    # "in the four corners of the table" is one in each (a row of four was built, silently)
    r = plan("put four single cubes in the four corners of the table")
    assert sorted(str(s.region) for s in r.spec.structures) == [
        "back left", "back right", "front left", "front right"]  # fmt: skip
    r = plan("a 4x4 slab with a cube in the four corners")
    assert [(x.kind, x.at) for x in r.spec.relations] == [("on_top_of", "corners")]
    # a cube put "inside" or "in the middle" after a ring stands in it (it stood in the
    # table's centre with the ring moved aside, or anywhere)
    for command in ("make a ring of 4 by 4 and put a cube inside",
                    "make a ring of 4 by 4, then put a cube in the centre",
                    "build a pen 5 by 5, then stack 3 cubes inside"):  # fmt: skip
        r = plan(command)
        assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("around", 0, 1)]
    r = plan("a ring of 4 by 4 on the left and put a tower of 3 in the centre of the table")
    assert not r.spec.relations and r.spec.structures[1].region == "centre"


def test_a_noun_naming_a_structures_use_is_noted_not_material():
    # "a fire ring", "three lookout towers": the noun before the structure names its use
    r = plan("A fire ring five cubes across")
    assert r.status == "success" and any("'fire' names its use" in n for n in r.notes)
    r = plan("Three lookout towers of 3 in a line")  # and the count before it still counts
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 3, 3]
    # what it is made of, a misspelling, or a verb the parser took for a noun stay material
    for command, word in (("a glass tower of 3", "glass"), ("a signall post 3 high", "signall")):
        r = plan(command)
        assert r.status == "partial" and any(f"ignored '{word}'" in n for n in r.notes), r.notes
    # a verb the parser took for a noun: "Disregard pyramid" takes the pyramid back
    r = plan("Tower of 3. Disregard pyramid.")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower"]
    assert any("not wanted: 'Disregard pyramid'" in n for n in r.notes)


def test_parts_counted_for_a_bridge_or_table_and_cubes_by_cubes_and_posts_at_each_end():
    # "a bridge of 6 cubes" was a bridge 6 high (16 parts), silently
    for command in ("a bridge of 6 cubes", "a table, 6 cubes in all"):
        r = plan(command)
        assert r.status == "partial" and any("parts follow from its legs" in n for n in r.notes)
    r = plan("brigde on two 3-cube pilars")  # the pillars' cubes are their height
    assert r.status == "success" and r.spec.structures[0].height == 3
    # "five cubes by five" is a footprint (it was 5 parts: a ring 3 on a side)
    r = plan("a ring, 5 cubes by 5, one high")
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 5)
    # "a post 2 cubes high at each end": 2 high ("2 cube(s) … at each end" was two posts of 1,
    # then 6 high)
    r = plan("a row of 5 with a tower 2 cubes high at each end")
    assert [s.height for s in r.spec.structures if s.shape == "tower"] == [2]
    assert [x.at for x in r.spec.relations] == ["ends"]


def test_the_left_one_and_the_right_one_rows_high_stacked_in_turn_and_as_tall_as_possible():
    # "two towers, the left one 5 high and the right one 2 high": both were 5, both left
    r = plan("make two towers, the left one 5 high and the right one 2 high")
    assert r.status == "success"
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 5), ("right", 2)]
    r = plan("a wall 4 long and 3 rows high")  # rows counted upwards are its courses
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (4, 3)
    # "in the centre" after a bridge's legs is the table's centre (it was an unused relation)
    r = plan("I need a bridge with legs 3 tall in the centre of the table")
    assert r.status == "success" and r.spec.structures[0].region == "centre"
    r = plan("a 3x3 slab with a 2x2 slab on top and a single cube on top of that")
    assert r.status == "success"
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]
    for command in ("a tower as high as possible in the centre", "as tall a tower as possible"):
        r = plan(command)
        assert r.status == "success" and r.spec.structures[0].height == 10


@pytest.mark.parametrize(
    ("command", "heights", "regions"),
    [
        ("twr ht 3 @ L, then same @ R", [3, 3], ["left", "right"]),
        ("stn 2: twr ht 4 @ front L", [4], ["front left"]),
        ("pyramid 3 lvl @ ctr, twr ht 5 R of it", [3, 5], ["centre", None]),
    ],
)
def test_a_surveyors_shorthand_left_right_clear_and_each(command, heights, regions):
    # "@ front L", "R of it", "then same @ R": the sides in capitals (they were ignored words)
    r = plan(command)
    assert r.status == "success"
    assert [getattr(s, "height", None) for s in r.spec.structures] == heights
    assert [s.region for s in r.spec.structures] == regions
    if "R of it" in command:
        assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "right")]


def test_shorthand_sizes_gaps_and_removals_said_in_other_orders():
    r = plan("wall 5L x 2H, 1 blk on ea end")  # "5L x 2H" is 5 long, 2 high; "ea end" each end
    assert r.status == "success" and (r.spec.structures[0].length, r.spec.structures[0].height) \
        == (5, 2)  # fmt: skip
    assert [x.at for x in r.spec.relations] == ["ends"]
    r = plan("qty 2 twrs ht 3, 2 clr between")  # two cubes clear between them
    assert r.status == "success" and r.spec.gap_m == 0.1
    # "take off the top two", "take 5 cm off the top": the verb before what it takes
    r = plan("build a tower of seven then take off the top two thank you")
    assert r.status == "success" and r.spec.structures[0].height == 5
    r = plan("Build a wall 40 cm long and 15 cm high, then take 5 cm off the top.")
    assert r.status == "success" and r.spec.structures[0].height == 2
    r = plan("Stack it up to 10 inches, then pull the top 2 inches off.")  # not "the top 5"
    assert r.spec.structures[0].height == 4
    # "take the first one down": that one gone, its gap with it
    r = plan("Build two towers of four a cube apart. Then take the first one down again.")
    assert r.status == "success" and len(r.spec.structures) == 1
    # the middle one of three taken away: the two left keep their places
    r = plan("three towers of two in a row, a cube apart, then knock the middle one down")
    assert len(r.spec.structures) == 2 and r.spec.gap_m == pytest.approx(0.15)


def test_flagpoles_and_lookouts_not_touching_one_at_each_place_and_as_far_as_the_table_goes():
    # "flagpole", "lookout", "watchtower" are towers (a flagpole four tall was a wall)
    r = plan("The flagpole goes in the very middle of the table: four cubes tall.")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 4)]
    r = plan("A lookout tower of six")  # one tower, not a lookout and a tower
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 6)]
    # "don't let them touch": apart (it was an error for flagpoles, ignored words for towers)
    for command in ("Two flagpoles of four, and don't let them touch.",
                    "Two towers of 150, and don't let them touch."):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and len(r.spec.structures) == 2
        assert any("must not touch': holds" in n for n in r.notes)
    r = plan("two towers of 150 mm, not touching")  # 150 mm is their height, not the gap
    assert r.status == "success" and r.spec.structures[0].height_m == 0.15
    # "1 @ back L, 1 @ back R": one each (both stood at the back left, silently)
    r = plan("2 twrs ht 2: 1 @ back L, 1 @ back R")
    assert sorted(str(s.region) for s in r.spec.structures) == ["back left", "back right"]
    # "not one behind the other": side by side (read as a correction of "one", silently)
    r = plan("two towers of three not touching and not one behind the other")
    assert not any(x.side in ("front", "back") for x in r.spec.relations)
    r = plan("Put a 3 by 3 slab as far from the robot as the table goes.")
    assert r.spec.structures[0].edge == ("back",)
    r = plan("A tower of 3. No, not three, just two.")  # "just" adds nothing to the figure
    assert r.status == "success" and r.spec.structures[0].height == 2


def test_a_correction_of_a_figure_said_twice_is_reported():
    # "Three towers of 3. No, not three, two": which three is not said (the height was
    # changed and three towers built, silently)
    r = plan("Three towers of 3 in a row. No, not three, just two.")
    assert r.status == "partial" and any("says three 2 times" in n for n in r.notes)


def test_one_cube_and_another_either_side_facing_walls_a_missing_middle_and_an_ends_top():
    # "place one cube at …, and another at …": two cubes (the first was dropped, silently)
    r = plan("place one cube at x=0.5, y=0.3 and another at x=0.6, y=0.3")
    assert [(s.at_x, s.at_y) for s in r.spec.structures] == [(0.5, 0.3), (0.6, 0.3)]
    # "two towers of 3 either side of it": one on each side (two on one side, three built)
    r = plan("a tower of 5, and two towers of 3 either side of it")
    assert len(r.layout.objects) == 5 + 3 + 3
    assert [(x.kind, x.at) for x in r.spec.relations] == [("next_to", "ends")]
    r = plan("build two walls of 5 facing each other with a gap of 3 cubes")
    xs = {round(o.position[0], 3) for o in r.layout.objects}
    assert len(xs) == 2 and max(xs) - min(xs) == pytest.approx(0.2)  # parallel, 3 cubes clear
    r = plan("make a 3x3 square with the middle missing")
    assert r.status == "success" and r.spec.structures[0].shape == "enclosure"
    # "on top of the left end": on the wall's top at its left end (it stood on the table)
    r = plan("a wall 4 long with a tower of 2 on top of its left end")
    assert [(x.kind, x.at) for x in r.spec.relations] == [("on_top_of", "left end")]
    top = max(r.layout.objects, key=lambda o: o.position[2])
    assert top.position[1] == max(o.position[1] for o in r.layout.objects)  # the left (+y) end


def test_extended_to_a_size_and_a_list_of_heights_with_one_unit():
    # "then extend it to 5 steps" made a second staircase
    r = plan("Make a staircase of 3 steps, then extend it to 5 steps.")
    assert r.status == "success" and [s.steps for s in r.spec.structures] == [5]
    r = plan("a row of 4, then extend it to 7")  # the row's own size, not a height
    assert [(s.shape, s.length) for s in r.spec.structures] == [("row", 7)]
    # "5, 10 and 15 cm tall": the unit said once is every value's (two were dropped)
    r = plan("Three towers, 5, 10 and 15 cm tall, from left to right")
    assert r.status == "success" and sorted(s.height for s in r.spec.structures) == [1, 2, 3]
    r = plan("three towers, 7, 10 and 15 cm tall")  # 7 cm is no whole cube: not turned
    assert r.status == "partial"


def test_a_row_of_towers_and_heights_from_one_to_five():
    # "a row of 5 towers" built a row beside five towers; "heights 1 to 5" five towers of 1
    r = plan("a row of 5 towers")
    assert [s.shape for s in r.spec.structures] == ["tower"] * 5
    r = plan("a line of 5 towers, heights 1 to 5")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [1, 2, 3, 4, 5]
    r = plan("a line of 4 stacks of 2")  # their size stays theirs
    assert [s.height for s in r.spec.structures] == [2, 2, 2, 2]
    assert plan("a row of 5 cubes").spec.structures[0].shape == "row"


@pytest.mark.parametrize(
    "command",
    [
        "Build two towers of five cubes, one cube apart, and lay a beam across their tops.",
        "two towers of 3, a beam across the tops",  # a tower stood on the other, silently
        "Put two towers of 3 a cube apart. After that, beam on top across both.",
    ],
)
def test_a_beam_across_their_tops_joins_the_towers(command):
    r = plan(command)
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["bridge"]


def test_the_structure_named_then_described_and_touching_allowed():
    # ", pyramid 3 levels" after "the pyramid" describes it (a second pyramid was read)
    r = plan("put a tower of 3 right behind the pyramid, pyramid 3 levels")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower", "pyramid"]
    # "tower can touch the wall, that's fine": touching allowed, not a third structure
    r = plan("put the 2-high tower in front of the wall, wall is 5 long 3 high, tower can touch "
             "the wall that's fine")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["tower", "wall"]
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("front", 0.0)]


@pytest.mark.parametrize(
    ("command", "sizes"),
    [
        # "one higher" was read as the length said before plus one (a wall 6 high)
        ("build a wall 5 long then make it one higher", [("wall", 5, 3)]),
        ("build a wall 3 long then make it one cube taller", [("wall", 3, 3)]),
        # "2 shorter" made a wall 4 high; "one shorter" a row 5 high
        ("build a wall 6 long, then make it 2 shorter", [("wall", 4, None)]),
        ("build a row of 6 then make it one shorter", [("row", 5, None)]),
        ("build a row of 5 then add one more cube to it", [("row", 6, None)]),  # not a 5 x 2 wall
        ("build a 3x3 slab then make it one layer thicker", [("block", 3, 2)]),
        ("build a tower of 3 on the left and a row of 5 on the right, then make the row 2 longer",
         [("tower", None, 3), ("row", 7, None)]),
        ("build two towers of 4, then take one cube off the second one",
         [("tower", None, 4), ("tower", None, 3)]),
        # "remove the second one" was a reference to it, nothing removed, nothing said
        ("build a tower of 4 and a tower of 2, then remove the second one", [("tower", None, 4)]),
        ("place one cube; then stack 4 more on it", [("wall", 1, 5)]),  # on it: upwards
    ],
)
def test_changes_said_as_more_less_or_an_ordinal_change_that_structure(command, sizes):
    r = plan(command)
    assert r.status == "success"
    got = [(s.shape, getattr(s, "length", None), getattr(s, "height", None))
           for s in r.spec.structures]  # fmt: skip
    assert got == sizes


def test_the_same_length_as_the_one_before_and_a_staircase_counted_in_cubes():
    # "a wall of the same length behind it" was a wall of the default length, silently
    r = plan("build a row of 5 and a wall of the same length behind it")
    assert [getattr(s, "length", None) for s in r.spec.structures] == [5, 5]
    r = plan("build a wall 4 long and a row the same length in front of it")
    assert [getattr(s, "length", None) for s in r.spec.structures] == [4, 4]
    # "as tall as the first one" was a tower of 1; "as tall as the tower" measured its own
    for command in ("a tower of 4 and a tower as tall as the first one",
                    "a tower of 4 and beside it a tower as tall as the tower"):  # fmt: skip
        assert [s.height for s in plan(command).spec.structures] == [4, 4]
    r = plan("build a tower of 5 and a row as long as the tower is tall")  # not 1 long
    assert [getattr(s, "length", None) for s in r.spec.structures] == [None, 5]
    r = plan("a handful of towers, none of them the same height")  # not "as tall as the tower"
    assert len({s.height for s in r.spec.structures}) == len(r.spec.structures)
    # "using 6 cubes": the steps that take 6 (a staircase of 6 steps, 21 cubes, was built)
    r = plan("build a staircase using 6 cubes")
    assert r.status == "success" and r.spec.structures[0].steps == 3


@pytest.mark.parametrize(
    ("command", "regions"),
    [
        ("build a tower of 2 in the front and back", ["front", "back"]),  # one tower was built
        ("a tower of 2 on the left and on the right", ["left", "right"]),
        ("build a row of 3 and a tower of 2 in the front and back", [None, "front", "back"]),
    ],
)
def test_one_structure_said_in_two_places_is_one_in_each(command, regions):
    r = plan(command)
    assert r.status == "success" and [s.region for s in r.spec.structures] == regions


def test_a_line_of_separate_structures_too_long_for_the_table_stays_one_line():
    # "5 towers of 2 in a line": four stood in a line and the fifth out of it, silently
    r = plan("build 5 towers of 2 in a line")
    xs = {round(o.position[0], 3) for o in r.layout.objects}
    assert r.status == "success" and len(xs) == 1
    r = plan("three towers of 3 spaced 10 cm apart")  # a gap said is kept as said
    ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
    assert [round(b - a, 3) for a, b in itertools.pairwise(ys)] == [0.15, 0.15]


def test_what_a_structure_is_for_is_not_another_structure():
    # "for our castle" built a castle too; "as a monument" a third structure
    r = plan("A wall for our castle. You decide how long.")
    assert [s.shape for s in r.spec.structures] == ["wall"]
    r = plan("a ring 5 by 5, with a column of three standing in the middle of it as a monument")
    assert [s.shape for s in r.spec.structures] == ["enclosure", "tower"]
    assert plan("build a castle with a wall").spec.structures[0].shape == "castle"


def test_a_size_said_once_for_every_structure_and_one_measured_on_a_named_size():
    # "…, both 3 high" went to the last wall only, silently
    r = plan("build a 4 long wall on the left and a 4 long wall on the right, both 3 high")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 3]
    r = plan("build a 4 long wall on the left and a 4 long wall on the right, same height 3")
    assert [s.height for s in r.spec.structures] == [3, 3]
    r = plan("a tower of 3, both 4 high")  # a size of its own already: which is not said
    assert r.status == "partial" and r.spec.structures[0].height == 3
    # "as long as a row of 6": 6 long (a row of 6 was built as well)
    r = plan("build a wall as long as a row of 6")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("wall", 6)]


@pytest.mark.parametrize(
    ("command", "sizes"),
    [
        # "of six (6) cubes in length": the figure repeated in brackets hid the length (2 long)
        ("A wall of six (6) cubes in length and two (2) in height.", [(6, 2)]),
        # the figure before its dimension's noun: the height was dropped, 2 long
        ("Make a wall of 4 length, 2 height", [(4, 2)]),
        ("a wall 4 length 2 height", [(4, 2)]),
        # a size said first for the structures counted after it: the second tower had none
        ("4 cubes high, two towers, one on the left and one on the right", [(None, 4)] * 2),
        ("Of 4 cubes of height, two towers, one in the left part and one in the right part.",
         [(None, 4)] * 2),
    ],
)  # fmt: skip
def test_sizes_said_with_bracketed_figures_after_the_number_or_before_the_structures(
    command, sizes
):
    r = plan(command)
    got = [(getattr(s, "length", None), s.height) for s in r.spec.structures]
    assert r.status == "success" and got == sizes


def test_a_wall_of_n_cubes_is_never_silently_rounded_to_whole_courses():
    # "a wall of 7 cubes" built 8 (4 long, 2 high) and said nothing
    r = plan("a wall of 7 cubes")
    assert len(r.layout.objects) == 14 and any("7 long" in n for n in r.notes)
    # "a wall of four cubes, two high" was 2 long and 2 high, a block: it is 4 long
    r = plan("a wall of four cubes, two high")
    assert r.spec.structures[0].length == 4 and len(r.layout.objects) == 8
    # all the parts, when that makes a wall: said, with how to say the other reading
    r = plan("a wall of 12 cubes, 3 high")
    assert len(r.layout.objects) == 12 and any("say '12 long'" in n for n in r.notes)
    r = plan("a wall of 6")
    assert len(r.layout.objects) == 6 and any("3 long, 2 high" in n for n in r.notes)


def test_a_sentence_about_a_part_of_a_structure_named_before_is_not_another():
    # the coordinates' sentence built a second tower at the centre, and took y = 0.45 with it:
    # "m." was not the end of a sentence
    r = plan("Place a tower of 3 cubes at x = 0.35 m, y = 0.45 m. The coordinates are the "
             "centre of the tower's footprint.")  # fmt: skip
    s = r.spec.structures
    assert len(s) == 1 and (s[0].at_x, s[0].at_y, s[0].height) == (0.35, 0.45, 3)
    r = plan("a tower of 3 at the back. Make the tower's top flat.")  # was a second tower of 2
    assert [s.height for s in r.spec.structures] == [3]


@pytest.mark.parametrize(
    ("command", "heights"),
    [
        ("a tower of 3. Make its height 5.", [5]),  # partial: "ignored 3 parts"
        ("a tower of 3. Make the tower's height 5.", [5]),  # a second tower of 5
        ("a wall 4 long 2 high. Change its height to 3", [3]),  # ignored
        ("a tower of 3. Then make the tower one shorter.", [2]),  # a tower of 1 beside
        ("a tower of 3 and a wall of 4 long. Make the tower one taller.", [4, None]),  # the wall
    ],
)
def test_a_change_said_of_a_dimension_or_of_a_structure_by_name(command, heights):
    r = plan(command)
    assert r.status == "success" and [s.height for s in r.spec.structures] == heights


def test_more_added_to_a_row_and_a_chain_of_structures_each_beside_the_one_before():
    # "add one more to the end" / "add 2 more to the row" built a second row
    for command, n in (("make a row of 4 cubes then add one more to the end", 5),
                       ("a row of 3 cubes. add 2 more to the row", 5)):  # fmt: skip
        r = plan(command)
        assert [(s.shape, s.length) for s in r.spec.structures] == [("row", n)]
    # "…, and a tower of 1 to the left of that": an error, "the relations form a cycle"
    for command in ("a tower of 3, a tower of 2 to the left of it, and a tower of 1 to the "
                    "left of that",
                    "a tower of 3, and to the left of it a tower of 2, and to the left of that "
                    "a tower of 1"):  # fmt: skip
        r = plan(command)
        assert r.status == "success"
        ys = {round(o.position[1], 3): round(o.position[2] + o.size[2] / 2, 3)
              for o in r.layout.objects}  # fmt: skip
        tops = [ys[y] for y in sorted(ys)]  # from the right (-y) to the left
        assert tops == sorted(tops, reverse=True) and len(tops) == 3
    # "a cube on top of that" after a wall and a tower: on the tower (was a beam on both)
    r = plan("a wall of 4, a tower of 2 behind it, and a cube on top of that")
    assert r.status == "success" and r.spec.relations[-1].kind == "on_top_of"
    # "and a cube in front of it": a cube, not a distance of one cube (it was dropped)
    r = plan("a small wall at the back right and a cube in front of it")
    assert [s.shape for s in r.spec.structures] == ["wall", "tower"]
    # "on top of the cube at the left end" of a row: on it, at that end (was on the table)
    r = plan("a row of four going left to right then a tower of three on top of the cube at "
             "the at the left end")  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of" and r.spec.relations[0].at == "left end"


def test_descriptions_of_the_structures_named_and_sizes_said_for_each_after_their_places():
    # "The tower is 4 high, the wall is 3 long." built four structures
    r = plan("Put the tower next to the wall. The tower is 4 high, the wall is 3 long.")
    got = [(s.shape, s.height if s.shape == "tower" else s.length) for s in r.spec.structures]
    assert r.status == "success" and got == [("tower", 4), ("wall", 3)]
    # "…, 4 cubes each" reached the last tower only
    r = plan("a tower in the back left and another one in the front right, 4 cubes each")
    assert [s.height for s in r.spec.structures] == [4, 4]
    # "both towers 4 high, one on the left, one on the right" built four towers
    for command in ("both towers 4 high, one on the left, one on the right",
                    "two towers, 4 high each, one on the left and one on the right"):  # fmt: skip
        r = plan(command)
        assert [(s.region, s.height) for s in r.spec.structures] == [("left", 4), ("right", 4)]
    # "at the far left" is the left side (it was the back left corner)
    r = plan("two towers of 3, one at the far left, one at the far right")
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    assert plan("a tower in the far left corner").spec.structures[0].region == "back left"


def test_distances_said_in_words_or_from_the_robot_and_a_move_of_a_structure_placed_by_region():
    # "move it 10 cm to the left" of a tower placed by region: the tower was 0.1 m high
    r = plan("a tower of 3 at the back, then move it 10 cm to the left")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.height, s.at_y) == (3, pytest.approx(0.40))
    # "at 40 cm from the robot": a tower 8 high
    s = plan("build a tower of 2 at 40 cm from the robot").spec.structures[0]
    assert (s.height, s.at_x) == (2, 0.4)
    # "twenty centimetres to its right": a tower 4 high beside, with no gap said
    r = plan("a tower of 3, then another tower of 3 twenty centimetres to its right")
    assert [s.height for s in r.spec.structures] == [3, 3] and r.spec.relations[0].gap_m == 0.2
    # "with no gap": the "no" was ignored and SDI's own gap kept
    r = plan("two towers of 2 side by side with no gap")
    ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
    assert r.status == "success" and [round(b - a, 3) for a, b in itertools.pairwise(ys)] == [0.05]
    # a likeness of the figure said is no size of its own (partial, "ignored 'ruler'")
    r = plan("A lookout tower thirty centimetres tall, about as tall as a school ruler.")
    assert r.status == "success" and r.spec.structures[0].height_m == 0.3


@pytest.mark.parametrize(
    ("command", "shape", "said"),
    [
        # a sentence led by "It" gave a second structure when the first had a place
        ("A staircase on the right. It has 5 steps.", "staircase", {"steps": 5}),
        ("A ring at the back. It should be 4 by 4 and 2 high.", "enclosure",
         {"length": 4, "width": 4, "height": 2}),
        ("A block at the front left. It is 2 by 2 by 3.", "block",
         {"length": 2, "width": 2, "height": 3}),
    ],
)  # fmt: skip
def test_a_sentence_led_by_it_describes_the_structure_named_before(command, shape, said):
    r = plan(command)
    (s,) = r.spec.structures
    assert r.status == "success" and s.shape == shape and s.region is not None
    assert {k: getattr(s, k) for k in said} == said


def test_plural_descriptions_distances_from_an_edge_or_in_x_corners_and_climbing_down():
    # "Both walls are 3 long." built two more walls; "Both 5 high." sized the last one
    r = plan("Two walls, one at the front and one at the back. Both walls are 3 long.")
    assert [(s.region, s.length) for s in r.spec.structures] == [("front", 3), ("back", 3)]
    r = plan("Two towers, one at the front and one at the back. Both 5 high.")
    assert [s.height for s in r.spec.structures] == [5, 5]
    # "about 10 cm from the front" / "35 cm in x" were heights
    s = plan("a tower of 3 near the left edge, about 10 cm from the front").spec.structures[0]
    assert (s.height, s.at_x) == (3, 0.3)
    s = plan("a tower of 2 at 35 cm in x and 45 cm in y").spec.structures[0]
    assert (s.height, s.at_x, s.at_y) == (2, pytest.approx(0.35), pytest.approx(0.45))
    # "in a corner": a corner of the table, said which (an L shape was built beside it)
    r = plan("a tower of 2 in a corner")
    assert [s.region for s in r.spec.structures] == ["back left"]
    assert any("was not said" in n for n in r.notes)
    # "climbing towards the robot" climbs to the front; "going down towards the back" too
    for command in ("a staircase of 3 steps climbing towards the robot",
                    "a staircase of 3 steps, going down towards the back"):  # fmt: skip
        r = plan(command)
        top = max(r.layout.objects, key=lambda o: o.position[2])
        assert top.position[0] == min(o.position[0] for o in r.layout.objects)


def test_more_structures_than_the_words_name_is_not_success():
    # two walls built for "the wall" said twice, reported as success
    r = plan("put the wall behind the tower, with the tower 3 high and the wall 5 long")
    walls = [s for s in r.spec.structures if s.shape == "wall"]
    reported = any("2 walls where the command names 1" in n for n in r.notes)
    assert (len(walls) == 1 and r.status == "success") or (r.status == "partial" and reported)
    # counted plainly, and not where the words say several
    for command in ("a tower of 3 on the left and another one on the right",
                    "two tower of 5, and a beam lying across top of them",
                    "a tower of 3 at the back and a tower of 2 at the front",
                    "ring 4x4 3 high, 2 of them",
                    "3x3 slab in the centre. Then 2x2 on top. Then 1 on top of that"):  # fmt: skip
        assert not any("where the command names" in n for n in plan(command).notes), command
    # the description itself, each structure in turn, read as more about them
    r = plan("put a pyramid behind the staircase; the staircase has 3 steps and the pyramid a "
             "base of 3")  # fmt: skip
    assert r.status == "success" and [s.shape for s in r.spec.structures] == [
        "pyramid", "staircase"
    ]


def test_one_more_on_each_the_middle_one_and_the_tall_one():
    # "add one more cube to each of them" after two phrases: only the last one grew, and the
    # note said "each"
    r = plan("a tower of 2 and a tower of 4, then add one more cube to each of them")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 5]
    for command, heights in (
        ("a tower of 2, a tower of 4 and a tower of 6 in a row; put a cube on each of them",
         [3, 5, 7]),
        ("two towers of 3, then add a cube on top of each", [4, 4]),
    ):  # fmt: skip
        r = plan(command)  # a separate cube was built, silently
        assert [s.height for s in r.spec.structures] == heights
    # "a cube on the middle one": on the first one (or read as "on top")
    for command in ("three towers of 2 in a row. Put a cube on the middle one.",
                    "three 2x2 blocks side by side, with a cube on top of the middle one"):
        r = plan(command)
        assert r.status == "success" and r.spec.relations[-1].object == 1
    # "the tall one" was a tower one cube high
    r = plan("a tower of 2, a tower of 3 and a tower of 4; put the tall one at the back")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 3, 4]
    # "close to the back" was built at the front; "go ahead and stack …" named no structure
    assert plan("a wall 4 long close to the back").spec.structures[0].region == "back"
    assert plan("go ahead and stack 5 cubes on the right").spec.structures[0].height == 5


def test_a_cube_added_beside_the_one_on_a_side_and_its_other_side():
    # "and a cube 10 cm to its left": the cube was dropped
    r = plan("a tower of 3 at the centre and a cube 10 cm to its left")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 1]
    assert r.spec.relations[0].gap_m == 0.1
    # "on the left one" of two rows, one on each side: on the row on the left
    r = plan("a row of 3 on the left, a row of 3 on the right; put a tower of 2 on the left one")
    assert r.status == "success" and (r.spec.relations[0].kind, r.spec.relations[0].object) == (
        "on_top_of", 0
    )
    # "with a row on its left and a row on its right": both beside the tower (the second was
    # beside the first row); "…to its left, and … to its left" is a chain
    r = plan("a tower of 5 with a row of 2 on its left and a row of 2 on its right")
    assert [(x.subject, x.object, x.side) for x in r.spec.relations] == [
        (1, 0, "left"), (2, 0, "right")
    ]
    r = plan("a tower of 3, a tower of 2 to its left, and a tower of 1 to its left")
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]


def test_sizes_for_both_in_two_dimensions_a_gap_said_with_between_and_impossible_requests():
    # "both 3 long 2 high" sized the last wall only
    r = plan("make a wall on the left side and a wall on the right side, both 3 long 2 high")
    assert [(s.length, s.height) for s in r.spec.structures] == [(3, 2), (3, 2)]
    # "three 2x2 blocks in a row along the back": a row was built beside them
    r = plan("three 2x2 blocks in a row along the back")
    assert [s.shape for s in r.spec.structures] == ["grid"] * 3
    # "with a tower in front of it and a tower behind it": both beside the block
    r = plan("a 2x3 block with a tower of 2 in front of it and a tower of 3 behind it")
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 0)]
    # "between" left over after the gap made a correct reading partial
    for command in ("two towers with 3 floors, 5 cm between",
                    "a tower of four to the left of a tower of two with a gap in between"):
        assert plan(command).status == "success", command
    # what no layout can be is not a silent success
    for command in ("two towers in the same spot", "put a tower on top of itself",
                    "a tall short tower", "a tower of 3 outside the table to the left"):
        r = plan(command)
        assert r.status == "partial" and any(n.startswith("ignored '") for n in r.notes)


def test_a_hurdle_a_gantry_and_a_crossbar_are_a_bridge():
    # "a hurdle with posts of 2" / "a gantry with legs of 4" built one tower, silently
    for command, high in (("a hurdle with posts of 2", 2), ("a gantry with legs of 4", 4),
                          ("two posts 3 high with a crossbar on top", 3)):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
            ("bridge", high)
        ]


def test_next_to_the_tall_one_is_the_tallest_named():
    # "a cube next to the tall one" stood by the short tower
    r = plan("make two towers, 2 and 5 high, and put a cube next to the tall one")
    assert r.status == "success" and (r.spec.relations[0].subject, r.spec.relations[0].object) == (
        2, 1
    )


def test_a_move_in_harmless_words_cubes_on_the_ends_of_a_row_and_its_end_cubes_taken_off():
    # "Put it on the right." was all harmless words: the tower stayed on the left
    r = plan("a tower of 3 on the left. Actually, put it on the right.")
    assert r.status == "success" and r.spec.structures[0].region == "right"
    # "one more cube on each end of it" made the row one longer
    r = plan("lay a row of 5 cubes and put one more cube on each end of it")
    tops = sorted(round(o.position[2] + o.size[2] / 2, 3) for o in r.layout.objects)
    assert r.status == "success" and len(r.layout.objects) == 7 and tops[-2:] == [0.1, 0.1]
    # "take off both end cubes" of a row was refused; of a wall 2 high it still is (which?)
    r = plan("a row of 6, then take off both end cubes")
    assert r.status == "success" and r.spec.structures[0].length == 4
    assert plan("a wall 6 long 2 high, then remove both end cubes").status == "partial"
    # "stack 2 more layers on it" stays two layers more
    r = plan("put down a 2x3 slab, then stack 2 more layers on it")
    assert r.spec.structures[0].height == 3


def test_a_structure_with_its_own_size_and_another_on_top():
    # "a staircase with 4 steps and … a tower of 2 on top": the steps went to the tower (4 high)
    for command in ("make a staircase with 4 steps and put a tower of 2 on top",
                    "make a staircase with 4 steps going up to the right and put a tower of 2 "
                    "at the top"):  # fmt: skip
        r = plan(command)
        assert r.status == "success"
        assert [(s.shape, getattr(s, "steps", None) or s.height) for s in r.spec.structures] == [
            ("staircase", 4), ("tower", 2)
        ]


def test_the_last_cube_of_a_row_and_the_top_of_a_pyramid_taken_off():
    # both were refused ("SDI builds structures whole")
    r = plan("a row of 5 then remove the last cube")
    assert r.status == "success" and r.spec.structures[0].length == 4
    r = plan("a pyramid of 4 levels, then take off the top")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.length, s.height) == (4, 3)
    # "remove the last one" of three towers still takes the tower away
    r = plan("three towers of 2, then remove the last one")
    assert [s.height for s in r.spec.structures] == [2, 2]


def test_the_tall_one_removed_and_the_last_cube_of_a_wall_reported():
    # "then remove the tall one" pointed at it and removed nothing, silently
    r = plan("build a tall tower and a short tower, then remove the tall one")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2]
    # "the last cube" of a wall 2 high: which one is not said (it was a wall 1 high)
    assert plan("build a wall 5 long, then remove the last cube").status == "partial"


def test_members_by_ordinal_and_one_compared_after_a_relation():
    # "the first 3 high, the second 5 high": both heights were one tower's (a conflict)
    r = plan("two towers: the first 3 high, the second 5 high")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 5]
    r = plan("Two towers, please: the first one eight high, the second half as tall as the first.")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [8, 4]
    # "and next to it one twice as tall": one tower 6 high, the 3 dropped (partial)
    for command, heights in (("a tower of 3, and next to it one twice as tall", [3, 6]),
                             ("a tower of 6 and next to it one half as tall", [6, 3]),
                             ("a tower of 3, and beside it one of 6", [3, 6])):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [s.height for s in r.spec.structures] == heights
        assert [rel.kind for rel in r.spec.relations] == ["next_to"]
    # "twice as long as the wall" is the wall's size, not the number said last
    r = plan("a wall of 4, a tower of 3, and a row twice as long as the wall")
    assert r.status == "success" and r.spec.structures[2].length == 8
    # half of 5 is no whole number of cubes: reported, not rounded
    assert plan("a tower of 5 and a tower half as tall as the tower").status == "partial"


def test_probe_misreadings_of_plain_commands():
    # "infront of" was corrected to "front": one tower at the front, the second lost
    r = plan("a tower of three infront of a tower of three")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 3]
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "front")]
    # cubes given two sides are a slab, "wide" across and "deep" front to back (was swapped)
    r = plan("single layer of cubes 4 wide and 3 deep in the front left")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.shape, s.length, s.width) == ("grid", 4, 3)
    # "one more row on top" of a wall was a row of one cube
    r = plan("a wall of 5 then one more row on top")
    s = r.spec.structures[0]
    assert r.status == "success" and len(r.spec.structures) == 1 and (s.length, s.height) == (5, 3)
    # "put them on top of each other" ignored 'them' and left the slabs apart, as success
    r = plan("make three 3x3 slabs and put them on top of each other")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.shape, s.length, s.width, s.height) == ("block", 3, 3, 3)
    r = plan("two towers of 3 stacked on top of each other")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [6]
    # a U asked for, a ring built: stated and partial, not success
    r = plan("a U shape with a tower of 3 inside")
    assert r.status == "partial" and r.spec.structures[0].shape == "enclosure"
    # "facing each other" unused is material
    assert plan("build 2 staircases of 3 steps, facing each other").status == "partial"
    # "with no towers on the corners": a ring (the note said the towers were left out)
    r = plan("a castle with no towers on the corners")
    assert r.status == "success" and r.spec.structures[0].shape == "enclosure"


def test_the_middle_one_changed_is_reported_and_members_placed_by_coordinates():
    # "make the middle one taller by 2" changed the last tower, silently; of an odd number of
    # towers named together the middle one is the middle of the order they stand in; with two
    # there is none
    r = plan("three towers of 3. make the middle one taller by 2")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 5, 3]
    r = plan("a tower of 2, a tower of 3 and a tower of 4, then make the middle one 6")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 6, 4]
    r = plan("two towers of 3, then make the middle one 5")
    assert r.status == "partial"
    assert all(s.region is None for s in r.spec.structures)  # "middle" was a place
    # "one at y = 0.15 and the other at y = 0.45": the decimal point ended the list
    r = plan("two towers of 3, one at y = 0.15 and the other at y = 0.45")
    assert r.status == "success"
    assert [(s.height, s.at_y) for s in r.spec.structures] == [(3, 0.15), (3, 0.45)]


def test_later_steps_that_set_a_size_move_or_take_a_part_off():
    # "then make it 5 long" / "make the right one 4 tall": the earlier size was reported as
    # a conflict (partial) though the later one is the change asked for
    r = plan("a row of 3, then make it 5 long")
    assert r.status == "success" and r.spec.structures[0].length == 5
    r = plan("put a tower of 2 on the left and a tower of 2 on the right. "
             "then make the right one 4 tall")  # fmt: skip
    assert r.status == "success"
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 2), ("right", 4)]
    r = plan("build three towers of 2, 3 and 4, and then make them all 5 high")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [5, 5, 5]
    # members by ordinal after a semicolon
    r = plan("two towers of 3 cubes; the first one at the back, the second one at the front")
    assert r.status == "success" and [s.region for s in r.spec.structures] == ["back", "front"]
    # "move it 10 cm back" was refused ("builds structures whole")
    r = plan("tower of 6 at x=0.4 y=0.3 then move it 10 cm back")
    assert r.status == "success" and r.spec.structures[0].at_x == pytest.approx(0.5)
    r = plan("a tower of 3, then move it 2 cubes forward")
    assert r.status == "success" and r.spec.structures[0].at_x < 0.45
    # a column off a wall's end, the top row taken off with the particle after it
    r = plan("Build a wall 6 long and 2 high, then remove one column from the end")
    assert r.status == "success" and (r.spec.structures[0].length, r.spec.structures[0].height) == (
        5, 2
    )
    r = plan("a wall 3 long 3 high, then take the top row off")
    assert r.status == "success" and r.spec.structures[0].height == 2
    # "the one in the middle" of three placed left, middle and right
    r = plan("a tower of 3 on the left, a tower of 4 in the middle and a tower of 5 on the right, "
             "then take the one in the middle down")  # fmt: skip
    assert r.status == "success" and [s.height for s in r.spec.structures] == [3, 5]


def test_a_cube_on_each_and_more_than_two_one_behind_the_other():
    # "with a cube on top of each": the cube was dropped, silently
    r = plan("two towers of 3 with a cube on top of each")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4, 4]
    r = plan("two towers of 3 with a cube on top of each, and a row of 4 in front of them")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["tower"] * 2 + ["row"]
    assert [s.height for s in r.spec.structures[:2]] == [4, 4]
    # on each cube of a row: a second course (a loose cube beside it, partial)
    r = plan("Lay a row of 4 cubes, then put a cube on top of each one")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.shape, s.length, s.height) == ("wall", 4, 2)
    # on each of a slab's corners stays on the corners
    r = plan("lay a 3x3 slab and set one cube on each of its four corners")
    assert [x.at for x in r.spec.relations] == ["corners"]
    # three towers "one behind the other": a line front to back (one relation of three)
    r = plan("three towers of 2 one behind the other")
    assert r.status == "success" and {s.axis for s in r.spec.structures} == {"x"}
    # "on top of the middle cube of the row": on the row (a tower at the centre and a cube)
    r = plan("a row of 5 and a tower of 3 on top of the middle cube of the row")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["row", "tower"]
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]


def test_a_tower_beside_a_bridge_and_sizes_listed_for_members():
    # "an arch and a tower of 2 to its right": the tower became the arch's pillars (2 high)
    for command, shapes in (("an arch and a tower of 2 to its right", ["arch", "tower"]),
                            ("a canopy with legs of 3 and a tower of 3 beside it",
                             ["canopy", "tower"]),
                            ("build a castle and a tower of 5 in front of it",
                             ["castle", "tower"])):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [s.shape for s in r.spec.structures] == shapes
        assert [x.kind for x in r.spec.relations] == ["next_to"]
    # a bridge's own pillars are still its own
    r = plan("a bridge with pillars of 3 and a beam on top")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 3)]
    # "two slabs, 2x2 and 3x3": two 3x3 slabs (partial); a size and a place each, in turn
    r = plan("two slabs, 2x2 and 3x3, side by side")
    assert r.status == "success"
    assert [(s.length, s.width) for s in r.spec.structures] == [(2, 2), (3, 3)]
    r = plan("build 2 towers: 4 high on the left, 2 high on the right")
    assert r.status == "success"
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 4), ("right", 2)]
    # one size said for all is not a list
    assert [s.height for s in plan("two towers, 3 high").spec.structures] == [3, 3]


def test_the_other_side_of_a_named_structure_and_words_no_slot_takes():
    # "one in front of the wall, the other behind it": a second default wall was built
    r = plan("build a wall 5 long 2 high and two towers of 3, one in front of the wall, the "
             "other behind it")  # fmt: skip
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["wall", "tower",
                                                                               "tower"]
    assert sorted((x.side, x.object) for x in r.spec.relations) == [("back", 0), ("front", 0)]
    # "wider" of an arch made it taller, silently
    for command in ("build an arch, then make it wider", "a wide arch"):
        r = plan(command)
        assert r.status == "partial" and r.spec.structures[0].height is None
    # a second beam on the first was dropped, silently
    r = plan("build a bridge with pillars 2 high, then add a second beam on top of the first")
    assert r.status == "partial"
    # "two cubes shorter than 6" built a tower of 2
    assert [s.height for s in plan("make a tower two cubes shorter than 6").spec.structures] == [4]


def test_corrections_and_changes_said_in_everyday_words():
    # each was partial with the change unused
    r = plan("make a 3 by 3 slab on the left, actually the other side")
    assert r.status == "success" and r.spec.structures[0].region == "right"
    r = plan("stack 4 cubes, take one off, then add three")
    assert r.status == "success" and r.spec.structures[0].height == 6
    r = plan("build two towers of 3, the left one and the right one, then make the left one 5")
    assert r.status == "success"
    assert [(s.region, s.height) for s in r.spec.structures] == [("left", 5), ("right", 3)]
    r = plan("Build a 4x2 slab. Then make it 3 wide instead of 2.")
    assert r.status == "success" and (r.spec.structures[0].length, r.spec.structures[0].width) == (
        4, 3
    )
    r = plan("two rows of 5 cubes, put the second one on top of the first")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.shape, s.length, s.height) == ("wall", 5, 2)
    r = plan("three slabs 2x2, stacked on top of each other, with a cube on top")
    assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
        ("block", 3), ("tower", 1)
    ]
    r = plan("a row of 3 cubes, never at the back")
    assert r.status == "success" and r.spec.structures[0].region == "front"


def test_a_castles_towers_and_a_bridges_pillars_changed_later():
    # "make the towers taller (4 high)" built a separate tower of 4 beside a default castle;
    # "make the towers 5 high" raised the castle's walls to 5
    r = plan("build a castle and then make the towers taller (4 high)")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["castle"]
    r = plan("a castle with walls 2 high, then make the towers 5 high")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.height, s.count) == (2, 3)  # towers 3 above the walls
    # "make the pillars taller, 3 cubes each": a tower of 6 beside a default bridge
    r = plan("build a bridge, then make the pillars taller, 3 cubes each")
    assert r.status == "success" and [(s.shape, s.height) for s in r.spec.structures] == [
        ("bridge", 3)
    ]


def test_terse_operator_commands_read_as_meant():
    # "going up right" was the right of the table, the stairs climbing left
    r = plan("stairs 4 going up right, back")
    heights = {}
    for o in r.layout.objects:
        key = round(o.position[1], 3)
        heights[key] = max(heights.get(key, 0), round(o.position[2] / 0.05 + 0.5))
    assert r.status == "success" and [heights[y] for y in sorted(heights)] == [4, 3, 2, 1]
    # "centre 0.5, 0.3": the coordinates were dropped
    s = plan("pyramid base 3, centre 0.5, 0.3").spec.structures[0]
    assert (s.at_x, s.at_y) == (0.5, 0.3)
    # "on the left end" of a row was the left of the table, the tower standing apart
    r = plan("row of 5, tower 3 on the left end")
    assert r.status == "success" and [(x.kind, x.at) for x in r.spec.relations] == [
        ("on_top_of", "left end")
    ]
    # "on top left corner" of a block, "on the back left corner": that corner of it
    for command in ("block 3x2x2, tower 2 on top left corner",
                    "a 3x3 slab with a cube on the back left corner"):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [x.at for x in r.spec.relations] == ["back left corner"]
    assert plan("a 3x3 slab with a cube on its left corner").status == "partial"  # which one?
    # "in front, 1 cube gap": the gap was noted and not kept (the row placed by region)
    r = plan("wall 5, then a row of 5 in front, 1 cube gap")
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("front", 0.05)]
    # "make it 4x4" built a second slab; "raise it one layer" was dropped
    r = plan("slab 3x3. make it 4x4")
    assert r.status == "success" and [(s.length, s.width) for s in r.spec.structures] == [(4, 4)]
    r = plan("ring 4x4 then raise it one layer")
    assert r.status == "success" and r.spec.structures[0].height == 2
    # "not going left to right" still turns the row
    assert plan("a row of 6 but not going left to right").spec.structures[0].axis == "x"


def test_shapes_described_by_what_they_look_like():
    # "just as long" was a vague "long" (6); "one step shorter" one step
    r = plan("A row of 5, and beside it a wall just as long but three cubes high.")
    assert r.status == "success" and (r.spec.structures[1].length, r.spec.structures[1].height) == (
        5, 3
    )
    r = plan("A staircase of 4 steps, and a second staircase one step shorter next to it.")
    assert r.status == "success" and len(r.spec.structures) == 2
    assert sorted(max(round(o.position[2] / 0.05 + 0.5) for o in r.layout.objects
                      if abs(o.position[0] - x) < 1e-6)
                  for x in {o.position[0] for o in r.layout.objects}) == [3, 4]  # fmt: skip
    # "on top of its middle": the tower stood on the table at the centre
    r = plan("A wall 6 cubes long and 1 high with a 2-cube tower on top of its middle.")
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["on_top_of"]
    r = plan("First a layer 5 cubes long and 3 wide, then a row of 5 cubes along the middle of it.")
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["on_top_of"]
    # "5 cubes along each edge": a grid of 5 cubes; "4 cubes in each layer": 4 by 4 a layer
    s = plan("A square slab with 5 cubes along each edge.").spec.structures[0]
    assert (s.length, s.width) == (5, 5)
    s = plan("A block 3 layers high with 4 cubes in each layer.").spec.structures[0]
    assert (s.length, s.width, s.height) == (2, 2, 3)


def test_counted_copies_on_top_are_not_stacked_on_each_other():
    # "slab 5x2, 3 towers of 2 on top": the third tower stood on the second, nothing on the slab
    r = plan("slab 5x2, 3 towers of 2 on top")
    assert r.status == "partial"
    assert [(x.kind, x.object) for x in r.spec.relations] == [("on_top_of", 0)]


def test_levels_named_in_words_stand_on_each_other():
    # "Bottom: … Middle: … Top: …" built three pieces apart on the table, as success
    for command in ("Bottom: a 3 by 3 square of cubes. Middle: a 2 by 2 square. Top: one cube.",
                    "first level: a 3 by 3 square, second level: a 2 by 2 square, third level: "
                    "one cube"):  # fmt: skip
        r = plan(command)
        assert r.status == "success"
        assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [
            ("on_top_of", 1, 0), ("on_top_of", 2, 1)
        ]
    # ordinals that are no levels stay apart
    r = plan("first a row of 4 on the right, second a row of 4 on the left")
    assert [s.region for s in r.spec.structures] == ["right", "left"] and not r.spec.relations


def test_a_row_added_to_a_slab_or_a_wall():
    # "add a row along the back" of a slab built a separate default row at the table's back
    r = plan("grid 4x2, add a row along the back")
    assert r.status == "success"
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("grid", 4, 3)]
    r = plan("a 3x3 slab, then add a row on the left")
    assert [(s.length, s.width) for s in r.spec.structures] == [(4, 3)]
    # of a wall, "another row" is a course more
    r = plan("a wall of 5, then add another row")
    assert r.status == "success" and [(s.length, s.height) for s in r.spec.structures] == [(5, 3)]


def test_distances_said_out_from_the_robot_or_off_an_edge():
    # "60 cm out" was the wall's length (12 long across the table)
    r = plan("wall 4 long, 3 high, centred on y=0.3, 60 cm out")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.length, s.height, s.at_x) == (4, 3, 0.6)
    s = plan("enclosure 4x3 at 600mm out").spec.structures[0]
    assert (s.length, s.width, s.at_x) == (4, 3, 0.6)
    s = plan("a tower 10 cm off the back edge").spec.structures[0]
    assert s.at_x == pytest.approx(0.7)


def test_sizes_said_against_a_named_structure_and_a_pyramids_square_base():
    # "a tower on its left that is 1 cube taller than the wall": a default tower and a wall
    # 1 long, 4 high, as success
    r = plan("A wall 3 high and 5 long, and a tower on its left that is 1 cube taller than the "
             "wall.")  # fmt: skip
    assert r.status == "success"
    assert [(s.shape, s.height) for s in r.spec.structures] == [("wall", 3), ("tower", 4)]
    # "with a square base": the square was a second structure (a grid beside the pyramid)
    for command in ("a pyramid with a square base of 3",
                    "A pyramid 15 cm high with a square base 15 cm across."):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [(s.shape, s.length) for s in r.spec.structures] == [
            ("pyramid", 3)
        ]
    # "a stack where every layer is a 2 by 2 square, five layers": a 2x2 slab beside a block
    s = plan("A stack where every layer is a 2 by 2 square, five layers in all.").spec.structures
    assert [(x.shape, x.length, x.width, x.height) for x in s] == [("block", 2, 2, 5)]


def test_a_later_sentence_that_places_two_structures_named_before():
    # "put the row behind the tower" was reported unused (the two built side by side)
    r = plan("a tower of 3 and a row of 3. put the row behind the tower")
    assert r.status == "success"
    assert [(x.subject, x.object, x.side) for x in r.spec.relations] == [(1, 0, "back")]
    r = plan("Make a 2x2 pad and a tower of 5. Set the pad to the left of the tower.")
    assert r.status == "success" and [(x.kind, x.side) for x in r.spec.relations] == [
        ("next_to", "left")
    ]
    # "beside each end" of a wall: one at each end
    r = plan("a wall 4 long and 2 high with a tower of 4 beside each end")
    assert r.status == "success" and [x.at for x in r.spec.relations] == ["ends"]


def test_along_an_edge_is_against_it_and_a_bottom_layer_is_square():
    # "along the left edge" stood 7.5 cm in from it (the left region)
    r = plan("row of 8 along the left edge")
    assert r.status == "success" and max(o.position[1] for o in r.layout.objects) == pytest.approx(
        0.525
    )
    assert {round(o.position[1], 3) for o in r.layout.objects} == {0.525}  # front to back
    r = plan("20 cm wall, 10 cm high, along the back edge and no more than 5 cm from it.")
    assert r.status == "success" and min(o.position[0] for o in r.layout.objects) > 0.75
    # "along the left side" is still that side of the table
    assert plan("a row of 4 along the left side").spec.structures[0].region == "left"
    # "9 cubes in the bottom layer" of a pyramid: a 3 by 3 level (a row of 9 built 45 cubes)
    s = plan("A pyramid with 9 cubes in the bottom layer.").spec.structures[0]
    assert (s.length, s.dims) == (3, 3)
    assert plan("a pyramid with 9 cubes on the bottom row").spec.structures[0].length == 9


def test_the_middle_one_taken_away_leaves_its_space_with_no_gap_said():
    # with no gap said, the two left closed up (0.15 m apart instead of where they stood)
    r = plan("3 towers of 3, then remove the middle one")
    ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
    before = sorted({round(o.position[1], 3) for o in plan("3 towers of 3").layout.objects})
    assert r.status == "success" and ys == [before[0], before[-1]]


def test_a_staircases_low_end_and_sizes_of_two_kinds_shared():
    # "a tower of 2 at its foot": the relation was dropped, silently
    r = plan("a staircase of 4 and a tower of 2 at its foot")
    assert r.status == "success" and [(x.kind, x.side) for x in r.spec.relations] == [
        ("next_to", "right")  # it climbs to the left: its foot is on the right
    ]
    r = plan("stairs 4 going up to the right, and a tower of 2 at the foot of the stairs")
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "left")]
    r = plan("tower 3 next to a 3 step staircase, low end")
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "right")]
    # "two walls, 4 long and 3 high": both that size (a list of members' sizes split them)
    r = plan("two walls, 4 long and 3 high, 15 cm apart")
    assert r.status == "success"
    assert [(s.length, s.height) for s in r.spec.structures] == [(4, 3), (4, 3)]


def test_a_structure_beside_a_ring_that_encloses_another_is_built():
    # the row in front of the ring was in the reading and missing from the layout, as success
    r = plan("build a 5x5 ring with a tower of 4 inside it, and a row of 3 in front of the ring")
    assert r.status == "success" and len(r.layout.objects) == 16 + 4 + 3
    ring_front = min(o.position[0] for o in r.layout.objects if o.position[2] < 0.03
                     and abs(o.position[1] - 0.2) < 1e-6)  # fmt: skip  # the ring's side column
    row = [o for o in r.layout.objects if o.position[0] < ring_front - 1e-6]
    assert len(row) == 3  # all three in front of the ring


def test_a_take_back_and_each_legs_height():
    # "scratch that, just one tower of 6": the three towers of 2 were built as well, silently
    r = plan("3 towers of 2. scratch that, just one tower of 6")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [6]
    # "each leg 2 cubes tall" was dropped (legs 3 high), silently
    r = plan("build a table with 4 legs, each leg 2 cubes tall")
    assert r.status == "success" and r.spec.structures[0].height == 2


def test_a_structure_on_a_ring_that_encloses_another_is_refused_with_the_reason():
    from sdi.design.composer import compose
    from sdi.errors import InfeasibleError

    r = plan("build a 5x5 ring with a tower of 4 inside it, and a row of 3 in front of the ring")
    rels = list(r.spec.relations)
    rels[1] = rels[1].model_copy(update={"kind": "on_top_of", "side": None})
    with pytest.raises(InfeasibleError, match="on top of a ring around another structure"):
        compose(r.spec.model_copy(update={"relations": tuple(rels)}))


def test_a_ring_with_towers_at_its_corners_and_a_tower_on_a_table():
    # "a hollow square … with towers of 4 at the corners": a ring and one tower, as success
    for command in ("a hollow square 4 by 4 with walls 2 high and taller towers of 4 at the "
                    "corners", "a 4 by 4 ring with towers of 4 at the corners"):  # fmt: skip
        r = plan(command)
        assert r.status == "success" and [s.shape for s in r.spec.structures] == ["castle"]
        heights = {}
        for o in r.layout.objects:
            key = (round(o.position[0], 3), round(o.position[1], 3))
            heights[key] = heights.get(key, 0) + 1
        assert sorted(heights.values())[-4:] == [4, 4, 4, 4]  # four corner towers 4 high
    # "table with 4 legs and a tower of 2 on top": the tower became the legs (2 high), as
    # success; now the tower stands on the table (which the design checks then refuse)
    r = plan("table with 4 legs and a tower of 2 on top")
    assert [(s.shape, getattr(s, "height", None)) for s in r.spec.structures] == [
        ("canopy", None), ("tower", 2)
    ]
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("on_top_of", 1, 0)]


def _parts_by_height(r, height):
    """The parts of the layout's columns `height` cubes tall."""
    cols: dict = {}
    for o in r.layout.objects:
        cols.setdefault((round(o.position[0], 3), round(o.position[1], 3)), []).append(o)
    return [o for parts in cols.values() if len(parts) == height for o in parts]


def test_a_counted_group_stands_together_beside_the_other_structure():
    # "a wall and two towers behind it": the second tower stood behind the first, silently; and
    # "two towers of 4 behind a wall": the first stood free beside them
    for command in ("a wall 6 long 2 high, 2 towers of 4 behind it",
                    "two towers of 4 behind a wall 6 long 2 high",
                    "a wall 6 long 2 high and 2 towers of 4 behind it"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", command
        towers, wall = _parts_by_height(r, 4), _parts_by_height(r, 2)
        assert len(towers) == 8 and len(wall) == 12, command
        assert min(o.position[0] for o in towers) > max(o.position[0] for o in wall), command
        assert "side by side" in " ".join(r.notes)
    # two towers with nothing else named stay as they were: one behind the other
    r = plan("two towers of 3, one behind the other")
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "back")]


def test_three_high_and_two_towers_counts_the_towers():
    # "a wall 3 high and two towers of 4": "two" was read as the towers' height (one tower of 2)
    r = plan("a wall 3 long and two towers of 4")
    assert [(s.shape, s.height) for s in r.spec.structures] == [
        ("wall", None), ("tower", 4), ("tower", 4)
    ]
    r = plan("a wall 3 high and two towers of 4")
    assert [s.shape for s in r.spec.structures] == ["wall", "tower", "tower"]


def test_towers_one_behind_the_other_joined_by_a_beam_span_front_to_back():
    # the bridge was built left to right at the front, silently
    for command in ("a tower of 3 in front and a tower of 3 behind it and a beam joining them",
                    "a tower of 3 and another tower of 3 behind it with a beam on top"):
        r = plan(command)
        assert r.status == "success", command
        pillars = _parts_by_height(r, 3)
        assert len({round(o.position[1], 3) for o in pillars}) == 1, command  # one y
        assert len({round(o.position[0], 3) for o in pillars}) == 2, command  # two x


def test_an_arch_high_is_its_overall_height():
    # "an arch 4 cubes tall" built 4-cube legs under two corbel levels and the beam: 7 tall
    for command, legs in (("make an arch 4 cubes tall", 1), ("an arch 5 high", 2),
                          ("an arch 30 cm tall", 3)):  # fmt: skip
        r = plan(command)
        assert r.status == "success", command
        assert r.spec.structures[0].height == legs, command
        top = max(o.position[2] + o.size[2] / 2 for o in r.layout.objects)
        assert round(top / 0.05) == legs + 3, command
    # the legs sized: as before
    assert plan("an arch with legs 3 high").spec.structures[0].height == 3
    # lower than any arch: the legs, said so (it was built 6 high with no note)
    r = plan("uh an arch three cubes high please")
    assert r.spec.structures[0].height == 3 and "at least 4 high" in " ".join(r.notes)
    # no number said: SDI's arch
    assert plan("a tiny archway").status == "success"


def test_a_name_before_a_colon_and_a_bare_adjective_one():
    # "an enclosure: a hollow square …, with walls 2 high": a second structure, a wall, silently
    r = plan("We need an enclosure: a hollow square 5 cubes on each side, with walls 2 cubes high.")
    assert r.status == "success"
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("enclosure", 5, 5, 2)
    ]
    # ", big one," read "one" as the pyramid's size: a single cube
    r = plan("make pyramid, big one, on middle of table")
    assert r.status == "success" and r.spec.structures[0].length >= 3
    r = plan("two towers, big one and small one")
    heights = [s.height for s in r.spec.structures]
    assert len(heights) == 2 and heights[0] > heights[1]


def test_corrections_with_units_and_a_confirmed_restatement():
    # "Wall 300 mm x 100 mm. Correction: 300 mm x 150 mm.": a wall and a slab, silently
    r = plan("Wall 300 mm x 100 mm. Correction: 300 mm x 150 mm.")
    assert r.status == "success"
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", 6, 3)]
    # "… No, a wall of 4. Yes, a wall, 4 long and 2 high.": the yes named a second wall
    r = plan("Build a tower of 4. No, a wall of 4. Yes, a wall, 4 long and 2 high.")
    assert r.status == "success" and len(r.layout.objects) == 8
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", 4, 2)]
    # a "yes" before a structure not named before is no restatement
    r = plan("a wall of 4. Yes, a tower of 2 too")
    assert [s.shape for s in r.spec.structures] == ["wall", "tower"]


def test_forget_the_second_one_and_in_line():
    # "actually forget the second one": both towers were built, with no note
    for command in ("build a tower of four then put a tower of two next to it actually forget "
                    "the second one", "a tower of 4 and a tower of 2. forget the second one"):
        r = plan(command)
        assert r.status == "success", command
        assert [s.height for s in r.spec.structures] == [4] and not r.spec.relations
    # "in line" was a row of its own, and "the last one" then took the row away
    r = plan("please build three tower of two cube in line, then remove the last one")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 2]
    # "in line with the wall": beside it, not a row between them
    r = plan("a tower in line with the wall")
    assert [s.shape for s in r.spec.structures] == ["tower", "wall"]
    assert [x.kind for x in r.spec.relations] == ["next_to"]
    # "two pyramid next each other": one pyramid
    r = plan("two pyramid next each other, both have base of 3 cubes")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("pyramid", 3)] * 2


def test_inside_at_the_end_and_a_gate_beside_a_tower():
    # "ring 5x5, 2 high, tower 3 insdie.": the tower stood beside the ring, silently
    r = plan("ring 5x5, 2 high, tower 3 insdie.")
    assert r.status == "success"
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("around", 0, 1)]
    assert plan("ring 5x5 1 high, dont put anything inside").spec.relations == ()
    # "… with a beam on them, and a tower of 4 to the right": the tower stood on the beam
    r = plan("something like a gate: two pillars 3 high with a beam on them, and a tower of 4 "
             "to the right")  # fmt: skip
    assert r.status == "success"
    assert [s.shape for s in r.spec.structures] == ["bridge", "tower"]
    assert r.spec.relations == ()
    cubes = [o for o in r.layout.objects if max(o.size) < 0.1]
    top = [o for o in cubes if o.position[2] > 0.16]  # the tower's fourth cube
    assert len(top) == 1
    tower_y = top[0].position[1]
    pillars = [o for o in cubes if abs(o.position[1] - tower_y) > 1e-6]
    assert len(pillars) == 6 and tower_y < min(o.position[1] for o in pillars)  # to the right
    # "a bridge, and a tower of 4 to the right": one bridge on pillars of 4, silently
    r = plan("a bridge, and a tower of 4 to the right")
    assert [s.shape for s in r.spec.structures] == ["bridge", "tower"]


def test_lists_likenesses_and_what_it_makes():
    # "two bridges … and a tower of five behind them": the tower was the bridges' pillars
    r = plan("two bridges um side by side and a tower of five behind them")
    assert [s.shape for s in r.spec.structures] == ["bridge", "bridge", "tower"]
    assert ("next_to", 2, "back") in [(x.kind, x.subject, x.side) for x in r.spec.relations]
    # "towers 2 3 4 5": one tower of 2 (the 2 was the count)
    for command in ("towers 2 3 4 5, left to right, 1 cube gaps.", "towers: 2, 3, 4 and 5"):
        r = plan(command)
        assert r.status == "success", command
        assert sorted(s.height for s in r.spec.structures) == [2, 3, 4, 5], command
    # "a flat square like a floor six by six": the size went with the likeness (4 by 4)
    r = plan("okay so i want um a big flat square of cubes like a floor six by six")
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("grid", 6, 6)]
    # "… That's a small wall.": a second wall
    r = plan("Two rows of four cubes, one on top of the other. That's a small wall.")
    assert r.status == "success" and len(r.layout.objects) == 8
    assert len(r.spec.structures) == 1


def test_apart_along_an_axis_a_cube_on_the_beam_a_clipped_wall_and_a_frame():
    # "two slabs, 50 mm apart along x": laid side by side, silently (x runs front to back)
    r = plan("Two 3 x 3 slabs, 50 mm apart along x.")
    assert [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [("next_to", "back", 0.05)]
    # "a bridge with a cube sitting in the middle of the beam": the cube was the pillars' height
    r = plan("a bridge with a cube sitting in the middle of the beam")
    assert [s.shape for s in r.spec.structures] == ["bridge", "tower"]
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    # "wal 6x2 back": a slab at the front
    r = plan("wal 6x2 back, row 6 front.")
    assert [(s.shape, s.region) for s in r.spec.structures] == [("wall", "back"), ("row", "front")]
    # "a frame 5 by 5 with the inside empty": 5 by 5 was read as the inside (a 7 by 7 frame)
    r = plan("a flat frame of cubes, 5 by 5 with the inside empty")
    assert [(s.length, s.width) for s in r.spec.structures] == [(5, 5)]
    r = plan("a ring with a 3 by 3 space inside")
    assert [(s.length, s.width) for s in r.spec.structures] == [(5, 5)]


def test_a_side_and_the_gap_said_again():
    # "4 cubes a side": a 2 by 2 slab, silently
    r = plan("one-layer square, 4 cubes a side, in the centre of the table")
    assert [(s.length, s.width) for s in r.spec.structures] == [(4, 4)]
    # "…, 5 cm apart. Then make the gap 15 cm": the change was dropped with no note
    for command in ("two stacks of 3, 5 cm apart; no, make the gap 15 cm",
                    "two stacks of 3, 5 cm apart. make the gap 15 cm"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", command
        ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
        assert ys[1] - ys[0] == pytest.approx(0.15 + 0.05, abs=0.002), command


def test_changes_that_cannot_be_made_are_reported_not_built_beside():
    # "make the middle tower 5": a fourth tower in the middle, silently (now the middle one of
    # the three as they stand, in the order named)
    r = plan("make 3 towers of 2. make the middle tower 5")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 5, 2]
    # "a tower of 3, then make it 4x4": a 4 by 4 slab beside the tower, silently
    r = plan("a tower of 3, then make it 4x4")
    assert r.status == "partial" and [s.shape for s in r.spec.structures] == ["tower"]
    # a slab can be made 4x4
    r = plan("a 3x3 slab, then make it 4x4")
    assert r.status == "success" and [(s.length, s.width) for s in r.spec.structures] == [(4, 4)]


def test_labelled_levels_with_a_cube_on_top_and_a_distance_beside_a_bridge():
    # "second level a 2x2 patch, and a single cube on top": the 2x2 stood apart on the table
    r = plan("ground level a 3x2 patch, second level a 2x2 patch, and a single cube on top")
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [
        ("on_top_of", 1, 0), ("on_top_of", 2, 1)
    ]
    # "a bridge, and a pyramid 15 cm to its left": the 15 cm became the pyramid's base
    r = plan("a bridge, and a 2 level pyramid 15 cm to its left")
    assert r.status == "success"
    assert [(x.side, x.gap_m) for x in r.spec.relations] == [("left", 0.15)]


def test_the_smaller_one_in_front_and_an_even_t_bar():
    # "one of five and one of two with the small one in front": both in the front region
    r = plan("two stacks of cubes um one of five and one of two with the small one in front")
    assert [s.height for s in r.spec.structures] == [5, 2]
    assert [(x.kind, x.subject, x.object, x.side) for x in r.spec.relations] == [
        ("next_to", 1, 0, "front")
    ]
    # a T's bar said 4 wide is built 5 wide (the stem on its middle cube): said, not silent
    r = plan("a T shape 4 by 3")
    assert r.status == "partial" and "5 long, not 4" in " ".join(r.notes)
    assert plan("a T shape 5 by 3").status == "success"


def test_sizes_said_after_a_bare_structure_are_its_own():
    # "Let's make a block. Two cubes wide, …": a default block and a guessed block beside it
    r = plan("Let's make a block. Two cubes wide, four cubes deep and three cubes tall.")
    assert r.status == "success"
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 2, 4, 3)
    ]
    r = plan("Now we will build a wall. It should be six cubes long and two cubes high.")
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", 6, 2)]
    # "canopy. 4 legs. 2 high.": the legs were a tower of their own
    r = plan("canopy. 4 legs. 2 high.")
    assert r.status == "success"
    assert [(s.shape, s.height) for s in r.spec.structures] == [("canopy", 2)]
    # "bridge. legs 3.": the legs' height was read as an arm's length and dropped
    r = plan("bridge. legs 3.")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("bridge", 3)]
    # sizes somewhere else, or of a structure already sized, stay apart
    r = plan("a tower on the left. 3 cubes on the right")
    assert len(r.spec.structures) == 2 and r.status == "partial"
    r = plan("a wall 4 long. 3 cubes in a row.")
    assert [s.shape for s in r.spec.structures] == ["wall", "row"]


def test_changes_of_mind_said_in_more_ways():
    # "Wait, I meant a staircase": the bridge was built beside the staircase
    r = plan("Build a bridge. Wait, I meant a staircase, 4 steps.")
    assert r.status == "success"
    assert [(s.shape, s.steps) for s in r.spec.structures] == [("staircase", 4)]
    r = plan("a row of 4, I meant a row of 6")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("row", 6)]
    # "shorten to 5", "go with 4", "make it longer, 6": each was dropped as partial
    for command, size in (("row 8. shorten to 5.", ("row", "length", 5)),
                          ("A tower of 6 in the centre. Hmm, 6 is too tall, go with 4.",
                           ("tower", "height", 4)),
                          ("a wall 4 long 3 high, then make it more long, 6",
                           ("wall", "length", 6)),
                          ("a wall 4 long 3 high, make it taller, 5",
                           ("wall", "height", 5))):  # fmt: skip
        r = plan(command)
        shape, key, value = size
        assert r.status == "success", command
        got = [(s.shape, getattr(s, key)) for s in r.spec.structures]
        assert got == [(shape, value)], command
    r = plan("a wall 4 long 3 high, make it taller, 5")
    assert [s.length for s in r.spec.structures] == [4]


def test_one_more_and_one_of_them():
    # "a tower of three then add one more": a second tower of 3, as success
    r = plan("build a tower of three then add one more")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 4)]
    r = plan("build three towers of 2 then add one more")
    assert [s.height for s in r.spec.structures] == [2, 2, 2, 2]
    # "two towers of 4, then remove one of them": both were built (partial)
    r = plan("two towers of 4, then remove one of them")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4]
    # of two that differ, which one is not said
    r = plan("a tower of 2 and a tower of 4, then remove one of them")
    assert r.status == "partial" and [s.height for s in r.spec.structures] == [2, 4]


def test_a_castle_with_its_walls_in_the_centre_and_a_couple_of():
    # "a castle with walls two high … in the centre": the castle stood around a wall of its own
    r = plan("Build a castle with walls two high and corner towers four high, please, in the "
             "centre of the table.")
    assert [s.shape for s in r.spec.structures] == ["castle"] and not r.spec.relations
    r = plan("a ring with a tower in the centre")
    assert [x.kind for x in r.spec.relations] == ["around"]
    # "a couple of towers, …, one at the front and one at the back": four towers
    r = plan("a couple of towers, both 3 high, one at the front and one at the back")
    assert [(s.height, s.region) for s in r.spec.structures] == [(3, "front"), (3, "back")]
    r = plan("a couple of layers of cubes, 3 by 3")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("block", 2)]
    # "a 150 mm cube made of cubes": a row of 3
    r = plan("a 150 mm cube made of cubes")
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 3, 3, 3)
    ]
    assert len(plan("a 5 cm cube").layout.objects) == 1


def test_foreman_codes_stairs_up_and_counts_shared():
    r = plan("T4 back left")
    assert [(s.shape, s.height, s.region) for s in r.spec.structures] == [
        ("tower", 4, "back left")
    ]
    r = plan("2x T3, 10 cm apart, back")
    assert [s.height for s in r.spec.structures] == [3, 3]
    r = plan("W 5x2 front, T4 behind it")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("wall", 2), ("tower", 4)]
    assert r.spec.structures[0].length == 5
    assert [s.shape for s in plan("a T 5x3").spec.structures] == ["t_shape"]
    # "stairs x4, up to the back": climbing to the left, on the back of the table
    r = plan("stairs x4, up to the back")
    assert [(s.steps, s.axis, s.region) for s in r.spec.structures] == [(4, "x", None)]
    r = plan("a staircase, four steps, it should climb up towards the left side")
    assert [(s.steps, s.axis, s.region) for s in r.spec.structures] == [(4, "y", None)]
    # "use 8 cubes for two equal towers": two towers of 8
    for command in ("use 8 cubes for two equal towers, side by side",
                    "make two towers out of 8 cubes"):  # fmt: skip
        assert [s.height for s in plan(command).spec.structures] == [4, 4], command
    # "two towers, one twice as tall as the other": both 4 (twice the count of towers); no
    # height said, SDI's own 3 and twice that, said
    r = plan("two towers, one twice as tall as the other")
    assert [s.height for s in r.spec.structures] == [6, 3] and "6 and 3" in r.notes[0]
    r = plan("two walls 2 high side by side, one 3 long and the other twice as long")
    assert [(s.length, s.height) for s in r.spec.structures] == [(3, 2), (6, 2)]


def test_t_parts_letters_lines_and_positions_of_stacks():
    # "the top bar 5 long and the stem 3": bar 3 and stem 5
    for command in ("a T shape, the top bar 5 long and the stem 3",
                    "a T shape with a bar of 5 and a stem of 3",
                    "a T shape, bar 5, stem 3"):  # fmt: skip
        r = plan(command)
        assert [(s.length, s.width) for s in r.spec.structures] == [(5, 3)], command
    # "make letter T …": 'letter' left unused (partial)
    r = plan("make letter T with cubes, top bar 5 cubes and stem 3 cubes")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["t_shape"]
    # "a U lying flat": a footprint is flat
    assert plan("an L shape lying flat, 4 by 3").status == "success"
    assert plan("an L shape 3 high lying flat").status == "partial"
    # "a tower, a wall and a block in a line from left to right": a row of its own, and the
    # three stood front to back
    r = plan("a tower, a wall and a block in a line from left to right, all 2 high")
    assert [s.shape for s in r.spec.structures] == ["block", "wall", "tower"]
    ys = [o.position[1] for o in r.layout.objects]  # the block's 8, the wall's 8, the tower's 2
    assert max(ys[:8]) < min(ys[8:16]) and max(ys[8:16]) < min(ys[16:])
    # "one cube's width away": a cube was built there
    r = plan("a wall 8 long and a row of 4 cubes in front of it, one cube's width away")
    assert [s.shape for s in r.spec.structures] == ["wall", "row"]
    assert [x.gap_m for x in r.spec.relations] == [0.05]
    # "… Build that in the back left.": the levels stayed in the middle
    r = plan("bottom: 5 by 5; middle: 3 by 3; top: a single cube. Build that in the back left.")
    assert [s.region for s in r.spec.structures] == ["back left", None, None]


def test_places_said_first_and_towers_beside_a_pillared_structure():
    # "a 3 by 3 grid and, 10 cm behind it, a pyramid": side by side (partial)
    r = plan("a 3 by 3 grid and, 10 cm behind it, a pyramid")
    assert [(x.kind, x.side, x.gap_m) for x in r.spec.relations] == [("next_to", "back", 0.1)]
    r = plan("a 3-high wall and, to its left, a tower twice as high")
    assert [(x.side, r.spec.structures[x.subject].height) for x in r.spec.relations] == [
        ("left", 6)
    ]
    # "an arch with a tower in front of it and a tower behind it": the towers were its pillars
    for command in ("an arch with a tower in front of it and a tower behind it",
                    "an arch, a tower in front of it and a tower behind it"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", command
        assert sorted(x.side for x in r.spec.relations) == ["back", "front"], command
    assert [s.shape for s in plan("a bridge, towers 3 high").spec.structures] == ["bridge"]
    # "a wall of the same width 3 high": 3 high read as width 3 ("3 wide high")
    r = plan("a 3x3 grid and a wall of the same width, 3 high")
    wall = r.spec.structures[1]
    assert (wall.shape, wall.length, wall.height) == ("wall", 3, 3)
    # "right behind it": against it
    r = plan("a 3 by 3 grid and, right behind it, a wall 3 long 3 high")
    assert [x.gap_m for x in r.spec.relations] == [0.0]
    assert plan("a tower on the right in front of a wall").spec.relations[0].gap_m is None
    # "a tower of 2 cubes above it": the 2 was dropped with no note
    r = plan("bridge below, tower of 2 cube above on it")
    assert [s.shape for s in r.spec.structures] == ["bridge", "tower"]
    assert r.spec.structures[1].height == 2 and r.spec.relations[0].kind == "on_top_of"
    assert plan("a tower 2 taller").status == "partial"
    # labelled levels said "the same" and "level 1 is …"
    r = plan("layer one 2 by 6, layer two the same, layer three the same")
    assert [(s.length, s.width) for s in r.spec.structures] == [(2, 6)] * 3
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]
    r = plan("level 1 is a 4x2 slab, level 2 is a 4x2 slab, that's it")
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("on_top_of", 1, 0)]


def test_changes_made_by_comparison_and_regrouping():
    # "actually make it one level taller": '4 high' read with no structure (partial)
    r = plan("start with a pyramid of 3 levels; actually make it one level taller")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [4]
    # "Make the first one twice as tall", "make it twice as long": each was dropped
    r = plan("two towers of 3. Make the first one twice as tall.")
    assert [s.height for s in r.spec.structures] == [6, 3]
    r = plan("a block 2x2x2; make it twice as long")
    assert [(s.length, s.width, s.height) for s in r.spec.structures] == [(4, 2, 2)]
    # "Make the smaller one as tall as the other"
    r = plan("a tower of 2 and a tower of 4. Make the smaller one as tall as the other.")
    assert [s.height for s in r.spec.structures] == [4, 4]
    # "no, stack them instead": a row and a default tower beside it
    r = plan("a row of five cubes. no, stack them instead")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 5)]
    r = plan("a tower of 6. actually, line them up")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("row", 6)]
    # "Remove the one on the right" of towers placed left and right: the places were said to
    # disagree
    r = plan("a 3-high tower on the right and a 5-high tower on the left. Remove the one on "
             "the right.")
    assert r.status == "success" and [(s.height, s.region) for s in r.spec.structures] == [
        (5, "left")
    ]
    # "a tower next to it, as tall as it is": as tall as the tower itself (no size: partial)
    r = plan("a wall 5 long 2 high. Then a tower next to it, as tall as it is.")
    assert r.status == "success" and [s.height for s in r.spec.structures] == [2, 2]
    assert [x.kind for x in r.spec.relations] == ["next_to"]


def test_one_way_and_the_other_each_way_and_the_bottom_layer():
    r = plan("an L, 4 one way and 3 the other")
    assert r.status == "success"
    assert sorted(getattr(r.spec.structures[0], k) for k in ("length", "width")) == [3, 4]
    r = plan("a plus sign, 5 cubes across each way")
    assert r.status == "success" and r.spec.structures[0].length == 5
    r = plan("bottom layer 4 by 4, then 3 by 3 on it, then 2 by 2, then one cube on top")
    assert r.status == "success" and len(r.spec.relations) == 3
    r = plan("level 1 a 5x5 square, level 2 a 3x3 square in the middle, level 3 one cube in the "
             "middle")
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]


def test_a_structure_on_either_side_stands_apart():
    # "a bridge with a 4-high tower on either side of it": the towers stood against its ends,
    # one structure with it
    for command in ("a bridge with a 4-high tower on either side of it",
                    "build a staircase of three and two towers of three one on each side of "
                    "it"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", command
        gap = r.spec.relations[0].gap_m
        assert [x.at for x in r.spec.relations] == ["ends"] and gap is not None and gap > 0
    # "at each end" of a row: against its ends, as before
    r = plan("a row of 5 with a cube at each end")
    assert [(x.at, x.gap_m) for x in r.spec.relations] == [("ends", None)]
    ys = sorted(round(o.position[1], 3) for o in r.layout.objects)
    assert len(ys) == 7 and all(round(b - a, 3) == 0.05 for a, b in itertools.pairwise(ys))


def test_more_letter_counts_sides_and_negated_other_side():
    # "two L shapes, 5 cm apart": the gap was an L's parameter, dropped
    r = plan("two L shapes, both 3 by 2, 5 cm apart")
    assert r.status == "success" and r.spec.gap_m == 0.05
    assert [s.shape for s in plan("2 L shapes").spec.structures] == ["l_shape"] * 2
    assert plan("a 5-cube tower between two L shapes").status == "success"
    # "with each side 2 high": 2 was read as the ring's side (a 4 by 4 ring 1 high)
    r = plan("an enclosure 4 by 4 with each side 2 high")
    assert [(s.length, s.width, s.height) for s in r.spec.structures] == [(4, 4, 2)]
    # "a fence round an empty square 5 by 5": a wall beside a 5 by 5 ring
    r = plan("a fence round an empty square 5 by 5, two cubes high")
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("enclosure", 5, 2)]
    # "at the corners of a square": in a line, and a slab
    r = plan("four 3-high towers at the corners of a square")
    assert [s.shape for s in r.spec.structures] == ["tower"] * 4 and r.spec.grid == (2, 2)
    # "a row of three 2-high towers with 5 cm between neighbours": a row of its own
    r = plan("a row of three 2-high towers with 5 cm between neighbours")
    assert [s.shape for s in r.spec.structures] == ["tower"] * 3 and r.spec.gap_m == 0.05
    # "on its right, not on its left": the negation was left unused (partial)
    r = plan("a 2x2x2 block with a 4-high tower on its right, not on its left")
    assert r.status == "success" and [x.side for x in r.spec.relations] == ["right"]
    r = plan("Make pyramid of 2 levels, not on the left side, not on the right side, in the "
             "middle only.")
    assert r.status == "success" and r.layout.objects[0].position[1] == pytest.approx(0.3, abs=0.03)
    # "make it more tall with 2 cube": a wall of guessed parts beside the tower
    r = plan("make tower of 3 cube. after, make it more tall with 2 cube")
    assert [s.height for s in r.spec.structures] == [5]
    # "steps, 1, 2, 3 and 4 cubes high": one step
    r = plan("The result should be steps, 1, 2, 3 and 4 cubes high")
    assert [(s.shape, s.steps) for s in r.spec.structures] == [("staircase", 4)]
    # "…, completely solid": 'solid' a second block beside the box
    r = plan("the finished thing is a box 3 wide, 2 deep, 2 tall, completely solid")
    assert r.status == "success" and len(r.spec.structures) == 1
    # "L 4x2 front left": a 2 by 4 slab
    assert [s.shape for s in plan("L 4x2 front left").spec.structures] == ["l_shape"]


def test_ticket_abbreviations_confirmations_and_described_shapes():
    # "len 6, ht 2, pos front": the length dropped (a wall 3.85 m long refused)
    r = plan("WO-77: wall, len 6, ht 2, runs left-right, pos front")
    assert r.status == "success"
    assert [(s.shape, s.length, s.height, s.region) for s in r.spec.structures] == [
        ("wall", 6, 2, "front")
    ]
    r = plan("qty 1 block, len 3 wid 2 ht 2")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("block", 2)]
    r = plan("ticket: wall A len 6 ht 2, wall B same size")
    assert [(s.length, s.height) for s in r.spec.structures] == [(6, 2), (6, 2)]
    # "wall len 5 ht 3 with a tower of 2 on top": 'wall' the verb (a tower 3 high alone)
    r = plan("wall len 5 ht 3 with a tower of 2 on top")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["wall", "tower"]
    assert plan("qty 4 twrs ht 1 in a square, 1 clr").spec.grid == (2, 2)
    # a number confirmed again was built a second time
    r = plan("a row of, uh, six cubes? no seven. seven cubes")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("row", 7)]
    r = plan("maybe a tower of 4? yeah 4 cubes")
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 4)]
    r = plan("three towers. 3 high.")
    assert [s.height for s in r.spec.structures] == [3, 3, 3]
    # steps listed, a closed square, one leg and the other, the far edge, a 2x2 pillar
    r = plan("steps going up 1, 2, 3, 4 cubes, climbing to the left")
    assert [(s.steps, s.axis) for s in r.spec.structures] == [(4, "y")]
    r = plan("a closed square of cubes, 5 by 5, one cube high")
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("enclosure", 5, 1)]
    r = plan("an L: one leg 4 cubes, the other 3 cubes")
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("l_shape", 4, 3)]
    r = plan("a 5x5 layer of cubes near the far edge")
    assert [s.region for s in r.spec.structures] == ["back"]
    r = plan("a 2x2 pillar 5 blocks tall")
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("block", 2, 2, 5)
    ]
    r = plan("stairs 3 steps up to the right, 3 wide")
    assert [(s.steps, s.axis, s.yaw_deg) for s in r.spec.structures] == [(3, "y", 180.0)]


def test_orders_levels_and_corrections_by_noun():
    # "towers of 2, 4 and 6 … from left to right, shortest on the left": the order was
    # reversed twice (4, 6, 2)
    r = plan("towers of 2, 4 and 6 in a line from left to right, shortest on the left")
    columns: dict = {}
    for o in r.layout.objects:
        columns[round(o.position[1], 3)] = columns.get(round(o.position[1], 3), 0) + 1
    assert [columns[y] for y in sorted(columns, reverse=True)] == [2, 4, 6]  # left (+y) first
    # "bottom level: 3 by 3. level 2: …": the bottom stood apart from levels 2 and 3
    r = plan("bottom level: 3 by 3. level 2: 2 by 2. level 3: 1 cube.")
    assert [(x.subject, x.object) for x in r.spec.relations] == [(1, 0), (2, 1)]
    # "a pyramid with base 4... no, base 3": a platform of 3 beside a pyramid of 4
    r = plan("a pyramid with base 4... no, base 3")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("pyramid", 3)]
    # "now one the same as before on the right": dropped (partial)
    r = plan("put a tower of 4 on the left. now one the same as before on the right")
    assert [(s.height, s.region) for s in r.spec.structures] == [(4, "left"), (4, "right")]
    # "from the front to the back", "on the far side of it"
    r = plan("three single cubes in a line from the front to the back, 10 cm gaps")
    assert r.status == "success" and [s.axis for s in r.spec.structures] == ["x"]
    r = plan("a wall 4 long 2 high and, on the far side of it, a tower of 3")
    assert [x.side for x in r.spec.relations] == ["back"]


def test_layers_listed_ones_named_and_sides_apart():
    # "layers from the bottom: 3x2, 3x2, 3x2": one layer
    r = plan("layers from the bottom: 3x2, 3x2, 3x2")
    assert len(r.spec.structures) == 3 and len(r.spec.relations) == 2
    # "two towers: a big one with five blocks and a small one with two blocks": three towers
    r = plan("Now the robot will build two towers: a big one with five blocks and a small one "
             "with two blocks. The small one goes on the left!")
    assert sorted(s.height for s in r.spec.structures) == [2, 5]
    # "the left one 5 high, the right one 3 high, 15 cm between them": 25 cm apart
    r = plan("two towers: the left one 5 high, the right one 3 high, 15 cm between them")
    ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
    assert r.status == "success" and ys[1] - ys[0] == pytest.approx(0.15 + 0.05, abs=0.002)
    assert max(r.layout.objects, key=lambda o: o.position[2]).position[1] == ys[1]  # 5 left


def test_castle_corner_heights_positions_and_axes_said_in_a_ticket():
    # "towers on the corners 3 high": built, but the 3 reported unused (partial)
    r = plan("castle: 5 by 5, walls 2 high, towers on the corners 3 high")
    assert r.status == "success" and max(o.position[2] for o in r.layout.objects) > 0.1
    # "pos: x 300 mm y 450 mm", "parallel to the y axis": 'pos', 'parallel' left unused
    r = plan("tower, 2 high, pos: x 300 mm y 450 mm")
    assert r.status == "success" and (r.spec.structures[0].at_x, r.spec.structures[0].at_y) == (
        0.3, 0.45
    )
    r = plan("wall 250 mm long, 100 mm high, parallel to the y axis, centred at x 0.6 y 0.3")
    assert r.status == "success" and [s.axis for s in r.spec.structures] == ["y"]


def test_extents_said_with_their_direction():
    # "5 across from left to right": the 5 ran front to back, silently
    r = plan("a block 2 deep, 5 across from left to right, 2 high")
    xs = {round(o.position[0], 3) for o in r.layout.objects}
    ys = {round(o.position[1], 3) for o in r.layout.objects}
    assert (len(xs), len(ys)) == (2, 5)
    # "40 cm along the x axis" of a wall: read as the place x = 0.40 m (a 2-cube column)
    r = plan("the finished wall: 1 cube thick, 40 cm along the x axis, 10 cm high")
    assert r.status == "success" and len({round(o.position[0], 3) for o in r.layout.objects}) == 8
    assert plan("a tower at 40 cm along x").spec.structures[0].at_x == 0.4


def test_a_line_listed_in_order_keeps_its_order_when_one_is_added_to():
    # "towers of 2, 3 and 4 from front to back, then a cube on the first": they stood across
    r = plan("build towers of 2, 3 and 4 from front to back. "
             "then add a cube on top of the first one")
    assert r.status == "success", r.notes
    assert [h for _, h in sorted(_columns(r).items())] == [3, 3, 4]  # front (small x) first
    assert len({y for _, y in _columns(r)}) == 1
    # named left to right: the first is the leftmost (largest y), and it grows
    r = plan("build towers of 2, 3 and 4 from left to right. "
             "then add a cube on top of the first one")
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])
    assert [h for _, h in by_y] == [3, 3, 4] and len({x for x, _ in _columns(r)}) == 1


def test_levels_said_by_size_alone_are_named_by_it():
    # "second layer 3x3 … top a single cube": two structures, the top not a level
    r = plan("description: bottom layer a 4x4 square, second layer 3x3, third layer 2x2, "
             "top a single cube")  # fmt: skip
    assert r.status == "success", r.notes
    assert len(r.layout.objects) == 16 + 9 + 4 + 1 and max(_heights(r.layout).values()) == 4
    # "5 cubes in a line … 3 on top … 1": a row of 5, a row of 3, a cube (no layout)
    r = plan("first layer 5 cubes in a line, second layer 3 on top in the middle, "
             "third layer 1 in the middle")  # fmt: skip
    assert r.status == "success", r.notes
    assert [h for _, h in sorted(_heights(r.layout).items(), key=lambda kv: kv[0][1])] == [
        1, 2, 3, 2, 1
    ]  # fmt: skip
    # "levels: (1) … (2) … (3)": numbered in brackets
    r = plan("levels: (1) a 5x5 slab (2) a 3x3 slab centred (3) one cube centred")
    assert len(r.layout.objects) == 25 + 9 + 1
    # "level 4: 1 cube on one corner" of three 2x2 levels: the corner was the second level's
    r = plan("level 1: 2x2; level 2: 2x2; level 3: 2x2; level 4: 1 cube on one corner")
    assert r.status == "success", r.notes
    assert sorted(_heights(r.layout).values()) == [3, 3, 3, 4]


def test_spoken_numbers_and_homophones_of_a_dictated_command():
    # "x zero point three five, y zero point two": the place (it was x = 0, a failure)
    s = plan("put a stack of two at x zero point three five, y zero point two").spec.structures[0]
    assert (s.at_x, s.at_y, s.height) == (0.35, 0.2, 2)
    # "a slab too by three", "arms too long": two (a 3-cube slab and a 5 by 5 U, silently)
    r = plan("can you make a slab too by three")
    assert r.status == "success" and len(r.layout.objects) == 6
    r = plan("i want a u shape five wide with arms too long")
    assert r.status == "success" and len(r.layout.objects) == 5 + 2
    # "2 high one behind the other": the one starts the placing, not a height of 1
    r = plan("two walls 5 long 2 high one behind the other")
    assert r.status == "success" and len(r.layout.objects) == 20


def test_lines_said_with_each_other_or_all_in_a_straight_line():
    # "towers of 2, 4 and 6 one behind the other": a line front to back (a 2 by 2 grid)
    for said in ("one behind the other", "behind each other"):
        r = plan(f"towers of 2, 4 and 6 {said}")
        cols = sorted(_columns(r).items())
        assert [h for _, h in cols] == [2, 4, 6] and len({y for (_, y), _ in cols}) == 1
    # "…, all three in a straight line": the three placed, not a row of 3 beside them
    r = plan("Place a tower of 2 at the front. Next, a tower of 4 behind it. Then a tower of 6 "
             "behind that one, all three in a straight line.")  # fmt: skip
    assert sorted(_columns(r).values()) == [2, 4, 6]


def test_places_and_directions_said_in_other_words():
    # "stacking four cubes": a tower (a row, silently)
    assert _columns(plan("Would you mind stacking four cubes at the back of the table?")) == {
        (0.65, 0.3): 4
    }  # fmt: skip
    # "nowhere near the robot": at the back (at the front, silently)
    assert plan("a 2 by 2 block 3 high, nowhere near the robot").spec.structures[0].region == "back"
    # "climbing toward the far end": to the back; "the high end on the right": to the right
    cols = sorted(_heights(plan("a staircase of four climbing toward the far end").layout).items())
    assert [h for _, h in cols] == [1, 2, 3, 4]  # taller with x
    heights = _heights(plan("please put stair with 4 step, the high part must stay at right "
                            "side").layout)  # fmt: skip
    assert [h for _, h in sorted(heights.items(), key=lambda kv: kv[0][1])] == [4, 3, 2, 1]
    # "one in each corner of the floor": the table's corners (a 3x3 slab with towers on it)
    r = plan("need four stacks of two, one in each corner of the floor, over")
    assert sorted(_columns(r).values()) == [2, 2, 2, 2]
    # "a plinth surmounted by a column": on it (beside it, silently)
    r = plan("A plinth 2 x 2 x 2 surmounted by a column of three courses.")
    assert len(r.layout.objects) == 8 + 3 and max(_heights(r.layout).values()) == 5


def test_a_row_made_deeper_and_a_slab_made_a_block():
    # "make it two cubes deep": a row of 2 was built beside the row, silently
    for said in ("make it 2 cubes deep", "now make it two rows deep"):
        r = plan(f"a row of 5. {said}")
        assert r.status == "success" and len(_columns(r)) == 10 and len(r.layout.objects) == 10
    # "make it a block by stacking two more layers": a 2x2x2 block was built beside it
    r = plan("slab 3 by 3. okay now make it a block by stacking two more layers")
    assert r.status == "success" and sorted(set(_columns(r).values())) == [3]
    assert len(r.layout.objects) == 27


def test_a_structure_beside_another_lines_up_with_it_not_with_its_group():
    # "a tower in front of the pyramid, a row to the left of the tower": the tower stood off
    # the pyramid's line, centred with the row beside it, silently
    r = plan("a pyramid with a 3 by 3 base at the back right, a tower of 4 in front of it, and a "
             "row of 3 to the left of the tower")  # fmt: skip
    cols = _columns(r)
    (tower,) = [k for k, h in cols.items() if h == 4]
    ys = [o.position[1] for o in r.layout.objects if o.position[0] > tower[0] + 0.1]  # pyramid
    assert tower[1] == pytest.approx((min(ys) + max(ys)) / 2)
    # "a tower to the left of the first one" of two standing one behind the other: beside it
    r = plan("First, build a tower of four at the front right. After that, put a tower of two "
             "directly behind it, a cube apart. Finally, put a tower of three directly to the left "
             "of the first one, also a cube apart.")  # fmt: skip
    cols = _columns(r)
    first = next(k for k, h in cols.items() if h == 4)
    assert next(k for k, h in cols.items() if h == 3)[0] == first[0]
    # "a row in front of them both": centred on the two together
    r = plan("Two towers of three, a little apart, and then a longer row of five cubes in front "
             "of them both.")  # fmt: skip
    towers = [k for k, h in _columns(r).items() if h == 3]
    row = [k for k, h in _columns(r).items() if h == 1]
    assert np.mean([y for _, y in row]) == pytest.approx(np.mean([y for _, y in towers]))
    with pytest.raises(ValueError, match="whole"):
        Relation(kind="on_top_of", subject=1, object=0, whole=True)


def test_radio_procedure_and_warehouse_talk():
    # "how copy, over", "at bay left": the radio words carry nothing, the bay is the side
    r = plan("Base, need one stack of five at bay left, how copy, over")
    assert r.status == "success" and r.spec.structures[0].region == "left", r.notes
    r = plan("bay right, one stack of three; bay left, one stack of six; over")
    assert r.status == "success" and [s.region for s in r.spec.structures] == ["right", "left"]
    # "one cube of air between them": the gap (the two stood a structure gap apart)
    r = plan("need two stacks of four at the near end by the robot, one cube of air between them, "
             "over")  # fmt: skip
    ys = sorted(y for _, y in _columns(r))
    assert r.status == "success" and ys[1] - ys[0] == pytest.approx(0.10)
    # "negative on the stack of six, make it four"; "correction on the pyramid: base four"
    assert plan("negative on the stack of six, make it four, over").spec.structures[0].height == 4
    r = plan("correction on the pyramid: base four, not three. three levels. over and out")
    assert r.status == "success" and r.spec.relations == (), r.notes
    # "three stacks, heights two, three, two … tall one in the middle": 2, 3, 2 (x = 3 m)
    r = plan("copy that. three stacks, heights two, three, two, in a line, tall one in the "
             "middle, out")  # fmt: skip
    assert [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])] == [2, 3, 2]
    r = plan("three stacks of two, three and two")
    assert r.status == "success" and sorted(s.height for s in r.spec.structures) == [2, 2, 3]


def test_legs_corrections_and_fronted_relations_in_plain_words():
    # "every leg is two cubes": legs 2 high (the two was dropped, silently)
    r = plan("I like to have table, four leg, every leg is two cube")
    cubes = [o for o in r.layout.objects if o.size == (0.05, 0.05, 0.05)]
    assert r.status == "success" and len(cubes) == 4 * 2
    # "four by four... he says bigger! Five by five then.": one slab, 5 by 5 (both were built)
    r = plan("A big flat floor, four by four... he says bigger! Five by five then.")
    assert len(r.spec.structures) == 1 and len(r.layout.objects) == 25
    # "and before the wall, a tower" / "and in front of the wall, a tower": in front of it
    for said in ("before the wall", "in front of the wall", "in front of it"):
        r = plan(f"Wall long 5, high 3, and {said}, a tower of two cube")
        assert r.status == "success", (said, r.notes)
        wall_x = max(x for (x, _), h in _columns(r).items() if h == 3)
        assert next(x for (x, _), h in _columns(r).items() if h == 2) < wall_x
    # "… with one cube of air between them" of what was built as one structure: not success
    r = plan("Two 2 by 2 cakes, two layers each, side by side on the cooling rack with one cube "
             "of air between them.")  # fmt: skip
    assert len(r.spec.structures) == 1 and r.status == "partial"


def test_a_group_said_together_beside_a_structure_is_centred_on_it():
    # "three towers in front of the wall": the three together, centred before the wall
    r = plan("make one wall 6 long 2 high and infront of it three tower of 2")
    front = min(x for x, _ in _columns(r))
    towers = [y for (x, y) in _columns(r) if x == front]
    wall = [y for (x, y) in _columns(r) if x != front]
    assert (len(towers), len(wall)) == (3, 6) and np.mean(towers) == pytest.approx(np.mean(wall))


def test_a_drawing_s_sizes_labels_and_pitch():
    # "Plate 200 × 200 × 50": all three millimetres (the 50 was 50 parts high)
    r = plan("Plate 200 × 200 × 50 (single layer).")
    assert r.status == "success" and len(r.layout.objects) == 16
    # "L × W × H = 150 × 100 × 100 mm", "300 L × 50 W × 100 H": each by its label
    r = plan("Solid block, envelope L × W × H = 150 × 100 × 100 mm.")
    assert r.status == "success" and len(r.layout.objects) == 3 * 2 * 2
    r = plan("Wall 300 L × 50 W × 100 H, long axis parallel to Y, centreline at X 650.")
    assert r.status == "success" and r.spec.structures[0].at_x == 0.65
    assert len({round(o.position[1], 3) for o in r.layout.objects}) == 6  # along y
    # "Column Ø50, H 250": one cube across, 250 mm high
    r = plan("Column Ø50, H 250, located at X 400 / Y 300.")
    assert r.status == "success" and _columns(r) == {(0.4, 0.3): 5}
    # "parallel to X", "100 clear between inner faces": along x, 100 mm apart (100 cubes)
    r = plan("Two walls 250 L × 100 H, parallel to X, 100 clear between inner faces.")
    ys = sorted({round(o.position[1], 3) for o in r.layout.objects})
    assert r.status == "success" and ys[1] - ys[0] == pytest.approx(0.15)
    assert len({round(o.position[0], 3) for o in r.layout.objects}) == 5
    # "centres 150 mm apart", "pitch 150 mm": centre to centre (it was the clear gap)
    for said in ("centres 150 mm apart", "pitch 150 mm", "on 150 mm pitch"):
        ys = sorted({y for _, y in _columns(plan(f"two towers of 3, {said}"))})
        assert ys[1] - ys[0] == pytest.approx(0.15), said


def test_a_line_in_a_region_closes_up_to_stay_in_it():
    # "five towers of 3 along the back": the fifth stood out of the back, silently
    r = plan("A colonnade of five columns, each three courses tall, running along the back of "
             "the site.")  # fmt: skip
    cols = _columns(r)
    assert sorted(cols.values()) == [3] * 5 and {x for x, _ in cols} == {0.65}
    # "a stair of five risers": five steps (a block and five slabs, silently)
    r = plan("A monumental stair of five risers, two units wide, rising toward the back.")
    assert r.spec.structures[0].shape == "staircase" and r.spec.structures[0].steps == 5


def test_changes_and_lists_said_with_the_dimension_they_change():
    # "raise it to two high" of an L: its height (its arm became 2 long, silently)
    r = plan("First build an L shape with arms of 4 and 3, one high. Then raise it to two high.")
    assert r.status == "success" and len(r.layout.objects) == 6 * 2, r.notes
    # "stack a second identical layer on it": a layer more (it was dropped)
    r = plan("First, a grid 3 by 4. Next, stack a second identical layer on it.")
    assert r.status == "success" and len(r.layout.objects) == 24
    # "arms of 4 and 3, one high": the one is the height, not a third arm
    r = plan("an L shape with arms of 4 and 3, one high")
    assert r.status == "success" and len(r.layout.objects) == 6
    # "the small one at left": it on the left, the others in line (all stood at the left)
    r = plan("three towers in one line, 1, 2 and 3 high, the small one at left")
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])
    assert by_y[0][1] == 1 and len({x for (x, _), _ in by_y}) == 1


def test_places_said_of_one_structure_of_a_pair_keep_to_it():
    # "a tower in the centre, the same again 10 cm to its left": the first stays in the centre
    r = plan("Build a tower of 5 in the centre. Now build the same tower again, 10 cm to its left.")
    assert sorted(_columns(r)) == [(0.45, 0.3), (0.45, 0.45)]
    # "the bigger one further from the robot": behind (dropped, silently); "closer": in front
    r = plan("two pyramids, one with 3 levels and one with 2, the bigger one further from the "
             "robot")  # fmt: skip
    top = max(r.layout.objects, key=lambda o: o.position[2])  # the 3-level one's top
    assert top.position[0] == max(o.position[0] for o in r.layout.objects)
    cols = _columns(plan("two towers of 2 and 5, the taller one closer to the robot"))
    assert min(cols.items())[1] == 5  # the front (smallest x) one
    # "steps 1, 2, 3 and 4 cubes high, going from left to right": 1 at the left
    heights = _heights(plan("The result should be steps, 1, 2, 3 and 4 cubes high, going from "
                            "left to right").layout)  # fmt: skip
    assert [h for _, h in sorted(heights.items(), key=lambda kv: -kv[0][1])] == [1, 2, 3, 4]
    # "the tall one on the left please: two towers, 2 and 5 high": said before them
    cols = _columns(plan("the tall one on the left please: two towers, 2 and 5 high"))
    assert max(cols.items(), key=lambda kv: kv[0][1])[1] == 5


def test_one_twice_as_tall_as_the_other_and_ordinal_lists():
    # no height said: SDI's own 3 and twice that (two towers of 1 were built)
    r = plan("two towers, one twice as tall as the other")
    assert r.status == "success" and sorted(_columns(r).values()) == [3, 6]
    # "two towers of 2, one twice as tall as the other": 2 and 4 (2 and 1, silently)
    assert sorted(_columns(plan("two towers of 2, one twice as tall as the other")).values()) == [
        2, 4
    ]  # fmt: skip
    r = plan("two towers, one twice as tall as the other, the short one four cubes")
    assert sorted(_columns(r).values()) == [4, 8]
    # "first a wall …, second a tower …, third a tower of 5 to the right of the second"
    r = plan("first a wall 4 long and 2 high, second a tower of 3 to its right, third a tower of 5 "
             "to the right of the second")  # fmt: skip
    assert r.status == "success", r.notes
    # "each step 3 cubes wide": the staircase that wide
    r = plan("a staircase, 3 steps, climbing to the back, each step 3 cubes wide")
    assert r.status == "success" and len(r.layout.objects) == 3 * (1 + 2 + 3)


def test_a_letter_s_height_in_courses_once_both_sides_are_said():
    # "a T shape 5 by 3, 2 high": 2 courses (the 2 was its stem, the 3 ignored)
    r = plan("a T shape 5 by 3, 2 high")
    assert r.status == "success" and len(r.layout.objects) == 7 * 2
    assert plan("a U shape 5 by 3, 2 high").spec.structures[0].height == 2
    assert plan("a U 4 wide and 3 high").spec.structures[0].width == 3  # a letter drawn: its arms
    # a T "5 across the top and 3 down, one high": its bar and stem (the 3 was dropped)
    r = plan("Would you mind building a T shape, 5 across the top and 3 down, one high?")
    s = r.spec.structures[0]
    assert r.status == "success" and (s.length, s.width) == (5, 3)


def test_a_castle_s_corners_raised_and_an_ordinal_course_on_top():
    # "then raise the corners to 4": its corner towers (dropped)
    r = plan("First make a castle 6 by 6 with walls 1 high and corners 3 high. Then raise the "
             "corners to 4.")  # fmt: skip
    assert r.status == "success" and max(_heights(r.layout).values()) == 4
    # "a third row of 5 on top of that": one course more, the ordinal nothing more (unread)
    r = plan("a row of 5, then a second row of 5 on top of it. Finally, a third row of 5 on top "
             "of that.")  # fmt: skip
    assert r.status == "success" and sorted(set(_columns(r).values())) == [3]


def _level_sizes(layout):
    """Each level's (cubes across x, cubes across y), bottom up."""
    levels: dict[int, set[tuple[float, float]]] = {}
    for p in layout.objects:
        levels.setdefault(round(p.position[2] / 0.05 - 0.5), set()).add(
            (round(p.position[0], 3), round(p.position[1], 3))
        )
    return [
        (len({x for x, _ in cells}), len({y for _, y in cells}))
        for _, cells in sorted(levels.items())
    ]


def test_a_structure_with_another_of_its_family_beside_it_is_two():
    # "a tower of 4 with a tower of 2 on its left": one tower, the 2 dropped
    r = plan("a tower of 4 with a tower of 2 on its left")
    cols = _columns(r)
    assert r.status == "success" and sorted(cols.values()) == [2, 4]
    (short_y,) = [y for (_, y), h in cols.items() if h == 2]
    (tall_y,) = [y for (_, y), h in cols.items() if h == 4]
    assert short_y > tall_y  # left is +y
    # "… and one on its right": a third of the same size, on the other side
    r = plan("a tower of 4 with a tower of 2 on its left and one on its right")
    cols = _columns(r)
    assert r.status == "success" and sorted(cols.values()) == [2, 2, 4]
    tall_y = next(y for (_, y), h in cols.items() if h == 4)
    assert sorted(y > tall_y for (_, y), h in cols.items() if h == 2) == [False, True]
    r = plan("a wall of 5 with a tower of 2 in front of it and one behind it")
    assert r.status == "success" and len(r.layout.objects) == 10 + 2 + 2


@pytest.mark.parametrize(
    "command",
    [
        "a pyramid with levels 5x5, 3x3 and 1x1",
        "a stepped pyramid: 5 by 5, then 3 by 3, then 1 by 1",
        "a pyramid: bottom level 5x5, middle 3x3, top 1x1",
        "a pyramid with levels 5x5, 3x3 and a single cube on top",
        "a pyramid, level 1: 5x5, level 2: 3x3, level 3: 1x1",
    ],
)
def test_a_pyramid_listed_by_its_levels_is_those_levels(command):
    # was a single cube ("1x1" its size), three structures, or a pyramid beside the levels
    r = plan(command)
    assert r.status == "success", r.notes
    assert _level_sizes(r.layout) == [(5, 5), (3, 3), (1, 1)]


def test_a_level_list_that_disagrees_with_its_count_is_not_read_as_levels():
    r = plan("a 4-level pyramid 4x4, 2x2, 1x1")
    assert not any("as its levels" in n for n in r.notes)
    r = plan("a 3-level pyramid 4x4, 2x2, 1x1")
    assert r.status == "success" and _level_sizes(r.layout) == [(4, 4), (2, 2), (1, 1)]


@pytest.mark.parametrize(
    "command, heights",
    [
        # the correction named the family in the plural: the old count replaced, not a second
        ("uh, staircase, five steps, no, four steps, going up to the, um, left", [1, 2, 3, 4]),
        # a count corrected with the structure named again: two, not three
        ("um, a tower... no wait, two towers actually, uh, both four high", [4, 4]),
        ("er, so, two walls, um, no, just one wall, eight long, one high, at the back", [1] * 8),
    ],
)
def test_a_hesitant_self_correction_replaces_what_it_corrects(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == heights
    assert any("corrected by the command itself" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, size, wall, corner",
    [
        ("a castle 6x6, walls 2 high, corners 4 high", 6, 2, 4),  # corners were 3, silently
        ("castle 6x6, wall ht 2, corner ht 4", 6, 2, 4),
        ("castle 5x5 walls 2 corners 4", 5, 2, 4),  # was a ring, a wall and a tower
        ("a castle 6 by 6, corners 4 high", 6, 1, 4),  # walls 4, corners 5
    ],
)
def test_a_castle_s_corners_and_walls_said_bare(command, size, wall, corner):
    r = plan(command)
    heights = _heights(r.layout)
    xs = sorted({x for x, _ in heights})
    ys = sorted({y for _, y in heights})
    corners = {(x, y) for x in (xs[0], xs[-1]) for y in (ys[0], ys[-1])}
    assert r.status == "success" and (len(xs), len(ys)) == (size, size)
    assert {heights[c] for c in corners} == {corner}
    assert {h for c, h in heights.items() if c not in corners} == {wall}


def test_a_second_one_twice_as_tall_as_the_first_is_not_a_copy():
    # "… a second tower that is twice as tall as the first": 8 worked out, then copied as 4
    r = plan("Build a tower of 4 cubes, and next to it a second tower that is twice as tall as "
             "the first.")  # fmt: skip
    assert r.status == "success" and sorted(_columns(r).values()) == [4, 8]


def test_places_given_to_the_first_and_second_in_a_sentence_of_their_own():
    r = plan("Build two towers of 3. Put the first one on the left and the second one on the "
             "right.")  # fmt: skip
    ys = sorted(y for (_, y) in _columns(r))
    assert r.status == "success" and len(ys) == 2
    assert ys[0] <= 0.25 and ys[1] >= 0.35  # one each side, not both on the left
    r = plan("two walls 4 long. The first one at the back and the other one at the front.")
    assert r.status == "success" and {s.length for s in r.spec.structures} == {4}


@pytest.mark.parametrize(
    "command",
    [
        "a wall and an arch. Put the wall behind the arch.",
        "Make an arch and a wall; the latter goes behind the former.",
    ],
)
def test_one_of_two_named_together_placed_by_its_name_in_a_later_sentence(command):
    # "Put the wall", "the latter": one of the two named together, by name or by order
    r = plan(command)
    assert r.status == "success", r.notes
    beam_x = next(p.position[0] for p in r.layout.objects if p.id.startswith("b"))
    xs = {round(p.position[0], 3) for p in r.layout.objects}
    assert len(xs) == 2 and max(xs) > beam_x + 0.01  # the wall's line behind the arch's


@pytest.mark.parametrize(
    "command",
    [
        "Build a 5 by 5 slab and a 3 by 3 by 2 block. Put the block on top of the slab, in the "
        "middle.",
        "Build a 5 by 5 slab and a 3 by 3 by 2 block. Put the latter on top of the former, in the "
        "middle.",
    ],
)
def test_a_block_put_on_a_slab_named_with_it_stands_on_it(command):
    r = plan(command)  # was a failure: no room beside the slab
    assert r.status == "success", r.notes
    assert _level_sizes(r.layout) == [(5, 5), (3, 3), (3, 3)]


def test_the_latter_inside_the_former():
    r = plan("Make a ring 5 by 5 and a tower of 3; put the latter inside the former.")
    heights = _heights(r.layout)
    ((tx, ty),) = [c for c, h in heights.items() if h == 3]
    ring = [c for c, h in heights.items() if h == 1]
    assert r.status == "success" and len(ring) == 16
    assert min(x for x, _ in ring) < tx < max(x for x, _ in ring)
    assert min(y for _, y in ring) < ty < max(y for _, y in ring)


@pytest.mark.parametrize(
    "command, length, width, height",
    [
        ("an L shape with legs 5 and 3", 5, 3, 1),  # was a default L and two towers
        ("an L shape, arms 4 and 4, 2 high", 4, 4, 2),  # the 2 was taken for an arm
        ("U shape; base 5; arms 3; 1 high", 5, 3, 1),  # a U and a platform
        ("a U shape, base 5, arms 3, 2 high", 5, 3, 2),  # the arms' 3 was dropped
    ],
)
def test_a_letter_s_arms_and_base_said_as_its_two_sides(command, length, width, height):
    r = plan(command)
    (s,) = r.spec.structures
    assert r.status == "success", r.notes
    assert (s.length, s.width, s.height or 1) == (length, width, height)


def test_a_letter_shaped_wall_s_arms_are_not_its_length_and_height():
    # "4 by 3" of an L-shaped wall is its length and height: its arms are not turned into that
    r = plan("an L-shaped wall, arms 4 and 3 long, 2 high")
    (s,) = r.spec.structures
    assert (s.length, s.width, s.height) == (4, 3, 2)


def test_a_small_pyramid_of_so_many_levels_gets_the_base_they_need():
    # "a little pyramid, three levels" failed: the small base (2) cannot hold 3 levels
    r = plan("Reckon you could knock up a little pyramid, three levels, over on the right?")
    assert r.status == "success"
    assert _level_sizes(r.layout)[0][1] == 3 and len(_level_sizes(r.layout)) == 3
    assert any("a base of 3" in n for n in r.notes)


@pytest.mark.parametrize(
    "command",
    [
        "Right, stick a ring five by five, two high, smack in the middle.",  # stood on the right
        "Pop a tower of 3 in the middle, no worries.",  # 'no' made it partial
    ],
)
def test_colloquial_verbs_and_intensifiers_are_read(command):
    r = plan(command)
    assert r.status == "success", r.notes
    xs = [p.position[1] for p in r.layout.objects]
    assert abs((min(xs) + max(xs)) / 2 - 0.30) < 0.03  # in the middle, left to right


@pytest.mark.parametrize(
    "command, axis, low",
    [
        # the face at the coordinate, the centre half a footprint beyond (was the centre there)
        ("Slab 2 x 2, front edge at X250, centred on Y300.", 0, 0.25),
        ("Slab 6 × 3 cubes, single layer, long side along x, front edge at x = 0.30 m.", 0, 0.30),
        ("a wall 4 long, right side at y = 0.10 m", 1, 0.10),
    ],
)
def test_an_edge_placed_by_a_coordinate_is_that_face_not_the_centre(command, axis, low):
    lo, _ = boxes(plan(command))
    assert abs(lo[:, axis].min() - low) < 1e-6


def test_an_edge_at_a_coordinate_of_the_other_axis_or_several_structures_is_not_silent():
    r = plan("a row of 4 with its left end at y = 0.5")
    _, hi = boxes(r)
    assert r.status == "success" and abs(hi[:, 1].max() - 0.5) < 1e-6
    r = plan("two towers at x = 0.4 and a slab, front edge at x = 0.5")
    assert r.status != "success" and any("front edge at x = 0.5" in n for n in r.notes)


@pytest.mark.parametrize(
    "command", ["a row of 5 at x = 0.5 m, tolerance ±10 mm", "a tower at x = 0.45 m (±5 mm)"]
)
def test_a_tolerance_is_not_a_size(command):
    r = plan(command)  # the 10 mm was a second length (failure: less than one part)
    assert r.status == "success" and any("as a tolerance" in n for n in r.notes)


def test_ticket_directions_and_approx():
    r = plan("qty 3 towers, ht 4, pitch 100mm, in line L-R")
    assert r.status == "success" and len({round(p.position[1], 3) for p in r.layout.objects}) == 3
    r = plan("a bridge, clear span approx. 5 cm")  # "a" of "approx." was read as the span
    assert r.status == "success" and not any(n.startswith("ignored") for n in r.notes)
    assert any("'clear span about 5 cm' as 0.05 m" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, heights",
    [
        # three towers of 2, silently
        ("Three towers, please: start with 2 cubes and add one more cube for every next tower.",
         [2, 3, 4]),
        # "starting at 2" was dropped as a time of day ("meeting at 2"): three towers of 1
        ("three towers, starting at 2 and each one cube taller than the one before", [2, 3, 4]),
        ("four stacks starting from 1, each 2 cubes higher", [1, 3, 5, 7]),
    ],
)  # fmt: skip
def test_a_series_of_towers_from_a_first_height_and_a_step(command, heights):
    r = plan(command)
    assert r.status == "success" and sorted(_columns(r).values()) == heights


@pytest.mark.parametrize(
    "command, heights",
    [
        ("need 2 towers of four rn one left one right", [4, 4]),  # 'rn' read as metres: 80 high
        ("3 towers of 2 in a line w gaps of 1 cube ✌️", [2, 2, 2]),  # a fourth, the gap's cube
        ("tower of 3 n a tower of 6 next to it", [3, 6]),
    ],
)
def test_chat_shorthand_is_read(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == heights


def test_a_ticket_s_short_words():
    r = plan("pyr, 4 lvls, back rt")  # was an error: nothing named
    assert r.status == "success" and r.spec.structures[0].shape == "pyramid"
    assert r.spec.structures[0].region == "back right"


def test_two_structures_at_one_coordinate_keep_the_gap_along_the_other():
    # "both at x = 0.50 m" with a 12 cm gap: the two towers touched, one structure
    r = plan("Two towers, 15 cm tall each, with a 12 cm clear gap between them, both at x = 0.50 "
             "m.")  # fmt: skip
    lo, hi = boxes(r)
    ys = sorted(set(np.round(lo[:, 1], 3)))
    assert r.status == "success" and len(ys) == 2 and ys[1] - ys[0] - 0.05 >= 0.12 - 1e-9
    assert set(np.round((lo[:, 0] + hi[:, 0]) / 2, 3)) == {0.5}


@pytest.mark.parametrize(
    "command",
    [
        # "in the centre of the block's top": was a relation with no subject (partial)
        "A tower of 4 is to be placed on top of a 3 by 3 by 2 block, in the centre of the "
        "block's top.",
        # "with a tower in the middle of its top": the tower stood beside the slab, silently
        "a 3x3 slab with a tower of 4 in the middle of its top",
    ],
)
def test_in_the_middle_of_its_top_is_on_top_centred(command):
    r = plan(command)
    heights = _heights(r.layout)
    assert r.status == "success" and len(heights) == 9
    (top,) = [c for c, h in heights.items() if h == max(heights.values())]
    xs = sorted({x for x, _ in heights})
    ys = sorted({y for _, y in heights})
    assert top == (xs[1], ys[1])  # the middle of the 3 by 3


@pytest.mark.parametrize(
    "command, left_height",
    [
        # failed: "the second one" was read as a base of 1
        ("Make a 3-level pyramid and a 2-level one; the former goes on the left, the latter on "
         "the right.", 3),
        ("a tower of 3 and a tower of 5; the first on the left, the other on the right", 3),
    ],
)  # fmt: skip
def test_the_first_and_the_second_of_two_named_given_their_places(command, left_height):
    r = plan(command)
    heights = _heights(r.layout)
    assert r.status == "success", r.notes
    left = max(y for _, y in heights)
    right = min(y for _, y in heights)
    assert left >= 0.35 and right <= 0.25
    assert max(h for (_, y), h in heights.items() if y > 0.3) == left_height


@pytest.mark.parametrize(
    "command, heights",
    [
        # the verb made a third tower of its default size (partial)
        ("stack six cubes into two towers", [3, 3]),
        # "of equal height" between the towers and the total: towers of 8 each, silently
        ("two towers of equal height using 8 cubes", [4, 4]),
        ("three towers the same height made of 9 cubes", [3, 3, 3]),
    ],
)
def test_a_total_of_parts_split_among_the_structures(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == heights


def test_a_pyramid_of_so_many_levels_and_parts():
    # "a 3-level pyramid using 10 cubes": a base of 4 cut at 3 levels (9 parts), silently
    r = plan("a 3-level pyramid using 10 cubes")
    assert r.status == "partial" and any("10 parts" in n for n in r.notes)
    # two levels of five parts: the whole 3-D pyramid, 2 by 2 and one on top
    r = plan("a pyramid of 2 levels using exactly 5 cubes")
    assert r.status == "success"
    assert sorted(round(p.position[2], 3) for p in r.layout.objects) == [0.025] * 4 + [0.075]


@pytest.mark.parametrize(
    "command, per_level",
    [
        # the base and what stands on it were one structure (partial; "a 4x4x3 block")
        ("a 4x4 base and a tower of 3 on it", [16, 1, 1, 1]),
        ("4x4 base, tower of 3 on it", [16, 1, 1, 1]),
        ("a tower of 3 on a 4x4 base", [16, 1, 1, 1]),
        ("a 3x3 base layer and a 2x2 layer on it", [9, 4]),
        # a size said with its noun left out: the 3x3 was dropped
        ("a 3x3 base with a 2x2 on it", [9, 4]),
        # "then one cube on top" of the stack: read as a beam across both layers (partial)
        ("a 3x3 base, a 2x2 on that, then one cube on top", [9, 4, 1]),
        ("a 3x3 layer, a 2x2 layer on that, then a cube on top", [9, 4, 1]),
    ],
)
def test_a_sized_base_is_a_slab_of_its_own(command, per_level):
    r = plan(command)
    assert r.status == "success", r.notes
    levels = [0] * len(per_level)
    for p in r.layout.objects:
        levels[round((p.position[2] - 0.025) / 0.05)] += 1
    assert levels == per_level


@pytest.mark.parametrize(
    "command", ["a pyramid with a 4x4 base", "a 3-level pyramid on a 4x4 base"]
)
def test_a_pyramid_s_base_stays_the_pyramid_s(command):
    r = plan(command)
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["pyramid"]


@pytest.mark.parametrize(
    "command, ok",
    [
        # "a 3-cube beam" was a row of its own: the beam dropped (partial)
        ("two 3-high towers 10cm apart with a 3-cube beam across the top", True),
        ("two towers of 3 with a beam of 3 cubes on top", True),
        # a beam SDI does not have: said, never silently the 0.15 m one
        ("two towers of 3 with a 20 cm beam on top", False),
        ("two towers of 3 with a beam 4 cubes long on top", False),
    ],
)
def test_a_beam_s_length_is_checked_against_sdi_s_beam(command, ok):
    r = plan(command)
    assert [s.shape for s in r.spec.structures] == ["bridge"]
    assert (r.status == "success") is ok, r.notes
    assert any("SDI's beam" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, height",
    [
        # "leave off the top cube" was ignored as two words of no meaning: 5 high, silently
        ("make a tower of 5 but leave off the top cube", 4),
        ("a tower of 5 without the top cube", 4),
        ("a tower of 5, minus the top cube", 4),
        ("a tower of 5 but leave out the top two cubes", 3),
    ],
)
def test_a_structure_without_its_top_parts(command, height):
    r = plan(command)
    assert r.status == "success", r.notes
    assert list(_columns(r).values()) == [height]


def test_a_gap_left_in_a_wall_for_a_door_is_not_silent():
    # the door was a bridge of its own beside a solid wall, silently
    r = plan("build a wall that is 6 long and 3 tall, leave a gap in the middle for a door")
    assert r.status == "partial" and any("no opening" in n for n in r.notes)


@pytest.mark.parametrize(
    "command",
    [
        # a cube on each cube of a row: one cube on the row, silently
        "a row of 5, and on every cube of it another cube",
        "a row of 5 with a cube on each cube",
        "a row of 5 with another cube on top of each one",
    ],
)
def test_a_cube_on_each_cube_is_another_layer(command):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == [2] * 5


@pytest.mark.parametrize(
    "command, sides",
    [
        # "a 3 long stem": the stem's 3 was refused as a second width (partial)
        ("Make a T with a 5 long top and a 3 long stem", (5, 3)),
        ("an L with a 4 long arm and a 2 long arm", (4, 2)),
        ("an L with an arm of 4 cubes and another arm of 2", (4, 2)),
    ],
)
def test_a_letter_s_parts_said_by_their_length(command, sides):
    r = plan(command)
    assert r.status == "success", r.notes
    (s,) = r.spec.structures
    assert (s.length, s.width) == sides


def test_a_single_layer_of_cubes_is_a_layer():
    # "a single layer of cubes": a row, with a note that no structure was named
    r = plan("fill the front left quarter of the table with a single layer of cubes")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["grid"]
    assert r.spec.structures[0].region == "front left"


@pytest.mark.parametrize(
    "command, heights_left_to_right",
    [
        # "starting at two" was taken for a time of day: three towers of 1, silently
        ("three towers going up by one each starting at two", None),
        ("three towers getting taller from left to right, starting at 1", [1, 2, 3]),
    ],
)
def test_a_series_said_by_its_first_height(command, heights_left_to_right):
    r = plan(command)
    cols = _columns(r)
    assert r.status == "success", r.notes
    if heights_left_to_right is None:
        assert sorted(cols.values()) == [2, 3, 4]
    else:
        assert [h for _, h in sorted(cols.items(), key=lambda kv: -kv[0][1])] == [1, 2, 3]
        assert any("step was not said" in n for n in r.notes)


@pytest.mark.parametrize(
    "command",
    [
        # the sizes given by the side in the next sentence: both towers 5 on the left (partial)
        "Make two towers. The left one should be 5 high, the right one 2 high.",
        "Make two towers. The left one 5 high, the right one 2.",  # the 2 in the 5's unit
        "two towers: left 5 high, right 2 high",
    ],
)
def test_sizes_given_by_side_in_the_next_clause(command):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert [h for _, h in sorted(cols.items(), key=lambda kv: -kv[0][1])] == [5, 2]


@pytest.mark.parametrize(
    "command",
    [
        # two fronted "on top of that" in one clause: a cycle of relations, an error
        "A 3 by 3 square. On top of that a 2 by 2 square, and on top of that a cube.",
        # "a smaller 2 by 2 square": the comparative left unused (partial)
        "First a big flat square of 3 by 3. On top of that a smaller 2 by 2 square, and on top "
        "of that one single cube.",
    ],
)
def test_stacked_in_turn_with_fronted_relations(command):
    r = plan(command)
    assert r.status == "success", r.notes
    levels = [0, 0, 0]
    for p in r.layout.objects:
        levels[round((p.position[2] - 0.025) / 0.05)] += 1
    assert levels == [9, 4, 1]


def test_a_comparative_said_with_its_own_size_is_checked():
    r = plan("a tower of 5 and a smaller tower of 3")
    assert r.status == "success" and sorted(_columns(r).values()) == [3, 5]
    # "a taller tower of 7" was read as 6 and refused as a second height (partial, 5 and 5)
    r = plan("a tower of 5 and a taller tower of 7")
    assert r.status == "success" and sorted(_columns(r).values()) == [5, 7]
    r = plan("a tower of 5 and a taller tower of 3")
    assert r.status == "partial" and any("3 is not taller" in n for n in r.notes)


@pytest.mark.parametrize(
    "command",
    [
        # "at its centre" after "then" was the table's centre: the tower beside the slab
        "a 3x3 slab, then a tower of 3 at its centre",
        "a 3x3 slab, then a tower of 3 in its middle",
        # "couse" was corrected to "goes" by its sound; an engineer's pier was no structure
        "Construct a 3x3 slab, one couse thick, then a 1x1 pier of 3 coures at its centre.",
    ],
)
def test_its_centre_is_the_structure_s_named_before(command):
    r = plan(command)
    assert r.status == "success", r.notes
    heights = _heights(r.layout)
    assert len(heights) == 9 and max(heights.values()) == 4


def test_an_engineer_s_pier_is_a_column():
    r = plan("Erect a single pier, 5 courses high.")  # was an error: nothing named
    assert r.status == "success" and list(_columns(r).values()) == [5]


@pytest.mark.parametrize(
    "command, shape, slots",
    [
        # "3 is enough" was dropped as a size agreed: 4 levels, silently
        ("A pyramid with 4 levels - actually 3 is enough.", "pyramid", {"height": 3}),
        # two staircases (partial)
        ("Staircase, 5 steps. Or... let's do 3 steps instead.", "staircase", {"steps": 3}),
        # "change that, legs 4 high": a bridge and a tower of 4 beside it, silently
        ("Bridge with legs 2 high; change that, legs 4 high.", "bridge", {"height": 4}),
        # both built (partial)
        ("Build an arch. Never mind, a tower of 2 instead.", "tower", {"height": 2}),
        ("Put a tower of 3 in the back right corner. Hmm, no, front left corner.", "tower",
         {"region": "front left"}),
    ],
)  # fmt: skip
def test_a_change_of_mind_replaces_what_it_corrects(command, shape, slots):
    r = plan(command)
    assert r.status == "success", r.notes
    (s,) = r.spec.structures
    assert s.shape == shape and {k: getattr(s, k) for k in slots} == slots


@pytest.mark.parametrize(
    "command, left_to_right",
    [
        # "the 5 on the left" placed both towers on the left, silently
        ("two towers, 3 and 5 high, the 5 on the left", [5, 3]),
        # "one is 4 high and one is 2 high": both 4 (partial)
        ("Two towers make, one is 4 high and one is 2 high", None),
        # "one of height two and one of height six": both of 1 (partial)
        ("two towers um one of height two and one of height six uh with the six on the right",
         [2, 6]),
    ],
)
def test_one_each_said_by_its_size(command, left_to_right):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    heights = [h for _, h in sorted(cols.items(), key=lambda kv: -kv[0][1])]
    if left_to_right is None:
        assert sorted(heights) == [2, 4]
    else:
        assert heights == left_to_right


def test_every_corner_of_the_table_should_have_one():
    # one tower, silently
    r = plan("In the end, every corner of the table should have a tower of 2 cubes.")
    assert r.status == "success" and sorted(_columns(r).values()) == [2, 2, 2, 2]


@pytest.mark.parametrize(
    "command, sides",
    [
        # "on each side" was one at each end: a row beside the slab (partial)
        ("Let's make a square mat that is 20 centimetres on each side", (4, 4, 1)),
        # "a cube": a count of one beside its sides (partial)
        ("build a cube thats 10cm on every side", (2, 2, 2)),
        ("Result: a cube made of cubes, three on each edge.", (3, 3, 3)),
    ],
)
def test_a_size_said_on_each_side(command, sides):
    r = plan(command)
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert tuple(round(float(v) / 0.05) for v in hi.max(0) - lo.min(0)) == sides


def test_a_courtesy_tail_does_not_cut_the_relation():
    # "on top of it, if that's ok": 'it, if that's ok' was no structure; the tower beside
    r = plan("Could you put a 2x2 slab down and then stack a tower of 3 on top of it, if that's "
             "ok?")  # fmt: skip
    assert r.status == "success" and max(_heights(r.layout).values()) == 4


def test_the_one_of_a_size_kept_on_a_side():
    # "and 4 one keep on right side": the 2 on the right, silently
    r = plan("Two towers make, one is 4 high and one is 2 high, and 4 one keep on right side.")
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert [h for _, h in sorted(cols.items(), key=lambda kv: kv[0][1])] == [4, 2]


def test_a_gap_said_with_walls_side_by_side_is_between_them():
    # "side by side with a gap": refused as no wall parameter (partial)
    r = plan("Could you make 2 walls, each 3 long and 3 high, side by side with a gap?")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    ys = sorted(set(np.round((lo[:, 1] + hi[:, 1]) / 2, 3)))
    steps = sorted(np.round(np.diff(ys), 3))  # along the line: 0.05 in a wall, 0.1 at the gap
    assert len(ys) == 6 and steps == [0.05] * 4 + [0.1]


@pytest.mark.parametrize(
    "command, heights",
    [
        # "give each tower three cubes": a sixth tower of 3 beside five default ones (partial)
        ("make five towers and give each tower three cubes", [3, 3, 3, 3, 3]),
        # "over it": the tower beside the plate (partial)
        ("First make one 2 by 3 plate, after that put one tower of 2 cubes over it.", None),
    ],
)
def test_each_and_over_it_in_plain_words(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    if heights:
        assert sorted(_columns(r).values()) == heights
    else:
        assert max(_heights(r.layout).values()) == 3


def test_a_beam_s_length_is_checked_against_the_cell_s_beam():
    from sdi.model.cell import CellConfig

    cell = CellConfig(part_types={"cube": (0.05, 0.05, 0.05), "beam": (0.2, 0.05, 0.05)})
    reading = read("two towers of 3 with a 4-cube beam on top", cell)
    assert any("as SDI's beam (4 cubes, 0.2 m long)" in n for n in reading.notes)
    reading = read("two towers of 3 with a 3-cube beam on top", cell)
    assert any("SDI's beam is 4 cubes (0.2 m) long" in n for n in reading.notes)


@pytest.mark.parametrize(
    "command",
    [
        # the roof's size went with the noun: a default table, silently
        "a pavilion with legs 3 high and a 20 by 20 cm roof",
        "Canopy:\n- four legs, 15 cm each\n- roof 20 x 20 cm",
        # a top sized after the legs was a 4 by 4 block of its own (partial)
        "a table, legs 2 high, 4x4 top",
        "a gazebo with a 4x4 deck",
    ],
)
def test_a_table_s_top_said_with_its_size_sizes_the_table(command):
    r = plan(command)
    assert r.status == "success", r.notes
    assert r.notes[-2] == "a table top 4 parts across: legs 2 apart"  # as "a table, 4x4 top"
    assert r.notes[-1].startswith("the table's top is its beams, 3 parts across")
    lo, hi = boxes(r)  # the legs (cubes: no turn to undo) stand 4 parts across each way
    legs = lo[:, 2] < 1e-6
    span = hi[legs].max(0) - lo[legs].min(0)
    assert tuple(round(float(v) / 0.05) for v in span[:2]) == (4, 4)


@pytest.mark.parametrize(
    "command, parts",
    [
        # a one-cube tower was built beside the ring, silently
        ("Ring 4x4, 1 high, leave out one cube on the left side", 12),
        ("Ring:\n- 4 x 4 outside\n- 1 high\n- NOT closed: leave one cube out of the front side",
         12),
        # the door was read as a bridge beside the wall, the wall built as a ring
        ("a wall of 6 with a doorway in the middle", 6),
        ("a 4x4 ring, leave a gap for a door", 12),
    ],
)
def test_an_opening_asked_is_reported_and_builds_nothing_of_its_own(command, parts):
    r = plan(command)
    assert r.status == "partial"
    assert len(r.layout) == parts
    assert any("with no opening in them" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, along",
    [
        # the wall stood across the middle of the pad, silently
        ("a 3x3 pad and along its back edge a wall 3 long, 2 high, standing on the pad", "back"),
        ("a 4x4 slab with a row of 4 on top along its left edge", "left"),
    ],
)
def test_a_structure_on_a_top_along_its_edge_stands_flush_with_it(command, along):
    r = plan(command)
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    base = lo[:, 2] < 1e-6
    upper = ~base
    axis, far = {"back": (0, True), "left": (1, True), "front": (0, False)}[along]
    edge = hi[base, axis].max() if far else lo[base, axis].min()
    side = hi[upper, axis].max() if far else lo[upper, axis].min()
    assert abs(side - edge) < 1e-6
    other = 1 - axis  # it runs along the edge: as long as the top there
    assert abs((hi[upper, other].max() - lo[upper, other].min())
               - (hi[base, other].max() - lo[base, other].min())) < 1e-6  # fmt: skip
    assert hi[upper, axis].max() - lo[upper, axis].min() < 0.05 + 1e-6


@pytest.mark.parametrize(
    "command, height, across",
    [
        # a 5 by 5 slab was built with a tower on each corner, silently
        ("Four towers of 2, one at each corner of a 5 by 5 square.", 2, 5),
        ("a tower of 3 at each corner of a 4 by 4 square", 3, 4),
        # one 4 by 4 slab, silently
        ("I need to mark the four corners of a 20 cm square with single cubes.", 1, 4),
    ],
)
def test_towers_at_the_corners_of_a_square_outline_it(command, height, across):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert sorted(cols.values()) == [height] * 4
    lo, hi = boxes(r)
    assert tuple(round(float(v) / 0.05) for v in (hi.max(0) - lo.min(0))[:2]) == (across, across)


def test_towers_on_the_corners_of_a_built_square_stand_on_it():
    r = plan("a 4x4 slab with a tower of 3 at each corner")
    assert r.status == "success", r.notes
    assert len(r.layout) == 16 + 4 * 3


@pytest.mark.parametrize(
    "command, height",
    [
        # "And one more layer." was ignored, and the run still said success
        ("Make a 3x3 slab. And one more layer.", 2),
        ("a wall 4 long 2 high. One more course.", 3),
    ],
)
def test_one_more_level_said_without_a_verb_adds_it(command, height):
    r = plan(command)
    assert r.status == "success", r.notes
    assert set(_columns(r).values()) == {height}


def test_a_tower_on_the_wall_s_left_end_stands_there():
    # "on the wall's left end" was read as "on it": the tower stood on the middle, silently
    r = plan("Build a wall 6 long and 2 high along the back. Put a tower of 3 on the wall's left "
             "end.")  # fmt: skip
    assert r.status == "success", r.notes
    cols = _columns(r)
    left = max(y for _, y in cols)
    assert {h for (_, y), h in cols.items() if y == left} == {5}
    assert {h for (_, y), h in cols.items() if y != left} == {2}


@pytest.mark.parametrize(
    "command",
    [
        # built flat, one cube deep, silently
        "a pyramid of 3 levels with a square base",
        "A pyramid, not a flat one: 3 levels with a square base.",
        "a 3-level pyramid, square base",
    ],
)
def test_a_pyramid_on_a_square_base_is_a_square_pyramid(command):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == 9 + 4 + 1


@pytest.mark.parametrize(
    "command, heights",
    [
        # the second "one shorter" counted from the "one" said in the first: a tower of 1
        ("A 4-cube tower. Then another, one shorter, to its right. Then another, one shorter "
         "again, to the right of that.", [4, 3, 2]),
    ],
)
def test_a_comparison_after_a_comparison_starts_from_the_size_it_gave(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values(), reverse=True) == heights


def test_twice_as_tall_again_is_not_the_same_height_again():
    # "then one twice as tall again" was 6 again, silently; 12 does not fit: refused
    r = plan("a tower of 3, then one twice as tall, then one twice as tall again")
    assert r.status != "success"
    assert any("as 12 (from the 6 said before)" in n for n in r.notes)


def test_the_one_in_the_middle_is_not_read_as_a_place():
    # "make the one in the middle 2 cubes taller": every tower placed in the middle and the
    # change read as a tower of 3 ("from the 1 said before"), silently
    r = plan("Make three towers of 2, 4 and 3 cubes in a row. Make the one in the middle 2 cubes "
             "taller.")  # fmt: skip
    assert [s.height for s in r.spec.structures] == [2, 6, 3]  # the middle of the row
    assert all(getattr(s, "region", None) is None for s in r.spec.structures)
    assert any("Make the middle one 2 cubes taller" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, said, value",
    [
        # built as 3 and 4 with no word of it
        ("A few cubes in a row.", "A few", 3),
        ("several towers of 3", "several", 4),
    ],
)
def test_a_vague_count_says_the_number_it_was_read_as(command, said, value):
    r = plan(command)
    assert r.status == "success", r.notes
    assert f"read '{said}' as {value}: the number was not said; say how many if it matters" in (
        r.notes
    )


def test_a_wall_in_a_line_is_one_wall():
    # "in a line" was read as a row of its own beside the wall, silently
    r = plan("A one-high wall of 6 in a line along the left edge of the table.")
    assert r.status == "success", r.notes
    assert len(r.layout) == 6 and set(_columns(r).values()) == {1}


@pytest.mark.parametrize(
    "command, across",
    [
        # "Turn it so …" was left unread: the 4 ran front to back, silently
        ("Build a 2x4 slab. Turn it so the long side runs left to right.", (2, 4)),
        ("a 2 by 4 slab with the long side front to back", (4, 2)),
    ],
)
def test_the_way_a_slab_s_long_side_runs(command, across):
    r = plan(command)
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert tuple(round(float(v) / 0.05) for v in (hi.max(0) - lo.min(0))[:2]) == across


def test_a_size_said_by_the_body_is_reported():
    # "a hand's width high" was read as nothing: a wall of the default height, silently
    r = plan("A wall a hand's width high and 5 cubes long.")
    assert r.status == "partial"
    said = "ignored 'a hand's width': not a size SDI can measure"
    assert any(n.startswith(said) for n in r.notes)


@pytest.mark.parametrize(
    "command",
    [
        # a ring was built around a tower, silently
        "two towers of 3 and a tower of 5 in the middle of them",
        "two towers of 3 and a tower of 5 in between",
        # a ring around a tower; the 5 reported unused
        "My kid wants two towers of 3 with one of 5 in the middle of them.",
        "two towers of 3 with one of 5 between them",
    ],
)
def test_one_in_the_middle_of_two_stands_between_them(command):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: kv[0][1])
    assert [h for _, h in cols] == [3, 5, 3]


def test_a_request_made_for_someone_is_the_operator_s_own():
    # "She wants …": 'she' and 'wants' reported as unused words (partial)
    r = plan("She wants a wall 6 blocks long and 3 high.")
    assert r.status == "success", r.notes


@pytest.mark.parametrize(
    "command, tower, legs, gap",
    [
        # the tower was read into the table's "with …" (its height reported unused, no tower)
        ("a table with legs 2 high and a tower of 3 on its right", 3, 2, None),
        ("a bridge with pillars of 3 high and a tower of 4 on its right", 4, 3, None),
        # the gap's clause made the bridge the one on the right, silently
        ("Put a bridge with pillars of 3 high and next to it on the right side a tower of 4 "
         "high, with one block in between.", 4, 3, 0.10),
    ],
)
def test_a_structure_after_one_said_with_its_legs_stands_on_its_side(command, tower, legs, gap):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    (ty,) = [y for (_, y), h in cols.items() if h == tower]
    others = [y for (_, y), h in cols.items() if h != tower]
    assert legs in cols.values()
    assert ty < min(others)  # the robot's right: smaller y
    if gap is not None:
        pillar = min(y for (_, y), h in cols.items() if h == legs)
        assert pillar - ty == pytest.approx(gap)


@pytest.mark.parametrize(
    "command, length",
    [
        # a 3 by 2 floor and a tower beside it, silently
        ("a tower of 5 standing between two rows of three, not touching either row", 3),
        ("a tower of 5 between two lines of 4 cubes", 4),
    ],
)
def test_a_tower_between_two_rows_has_a_row_on_each_side(command, length):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert sorted(cols.values()) == [1] * 2 * length + [5]
    (tx, ty) = next(k for k, h in cols.items() if h == 5)
    rows = [k for k, h in cols.items() if h == 1]
    # the rows run parallel on either side of the tower, one part thick each
    for axis in (0, 1):
        lines = {round(k[axis], 3) for k in rows}
        if len(lines) == 2:
            a, b = sorted(lines)
            assert a < (tx, ty)[axis] < b
            break
    else:
        raise AssertionError(f"not two parallel rows: {rows}")


@pytest.mark.parametrize(
    "command, tower, end",
    [
        # the end was not read: the tower stood anywhere, silently
        ("a 4-step staircase climbing to the right, with a tower of 5 at its high end", 5,
         "right"),
        ("3 step stairs going up to the left pls, and a tower of 2 touching the low end", 2,
         "right"),
        # "at the bottom of the stairs": the 2 was read as a length a tower has not (partial)
        ("a staircase of 3 steps going up to the right and a tower of 2 at the bottom of the "
         "stairs", 2, "left"),
    ],
)
def test_a_tower_at_an_end_of_a_staircase_stands_beside_that_end(command, tower, end):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: kv[0][1])  # right (small y) to left
    heights = [h for _, h in cols]
    # the tower beside the end, the staircase's steps rising away from or towards it
    assert heights[-1 if end == "left" else 0] == tower
    steps = heights[:-1] if end == "left" else heights[1:]
    assert sorted(steps) == list(range(1, len(steps) + 1))


@pytest.mark.parametrize(
    "command, climbs",
    [
        # the field's side was read as the table's region: it climbed to the back, silently
        ("Staircase spec:\n- steps: 6\n- width: 2 cubes\n- direction: up towards the left", "left"),
        ("stairs | steps: 4 | direction: right", "right"),
    ],
)
def test_a_staircase_s_direction_field_is_the_way_it_climbs(command, climbs):
    r = plan(command)
    assert r.status == "success", r.notes
    tops: dict[float, float] = {}
    for o in r.layout.objects:
        y = round(o.position[1], 3)
        tops[y] = max(tops.get(y, 0.0), o.position[2])
    ys = sorted(tops)
    assert len(ys) > 2  # along y, not front to back
    rising = [tops[y] for y in ys]  # right (small y) to left
    assert rising == sorted(rising, reverse=climbs == "right")


def test_three_sizes_said_with_times_are_a_block_s_sides():
    # "3 times 3" was multiplied: a 9 by 2 floor, silently
    r = plan("Make one block of 3 times 3 times 2 cubes.")
    assert r.status == "success", r.notes
    lo, hi = boxes(r)
    assert len(lo) == 18
    assert sorted(round(float(v) / 0.05) for v in (hi.max(0) - lo.min(0))) == [2, 3, 3]


@pytest.mark.parametrize("command", ["Build a wall of length −3.", "a tower, height: -2 cubes"])
def test_a_size_below_zero_is_an_error(command):
    # the minus was dropped: a wall 3 long, silently
    r = plan(command)
    assert r.status == "error"
    assert "a size below zero cannot be built" in r.error


@pytest.mark.parametrize(
    "command, parts", [("ring 5x5 h2", 32), ("wall 5 long h2", 10), ("twr H4", 4)]
)
def test_a_height_written_against_its_letter(command, parts):
    # "h2" was dropped (a ring 1 high) or read as a length, silently
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    assert max(round(o.position[2] / 0.05 - 0.5) for o in r.layout.objects) + 1 in (2, 4)


def test_a_letter_shaped_wall_with_its_height_said_apart_has_arms_of_the_by_sizes():
    # "4 by 4" was read as 4 long and 4 high, the "2 cubes high" dropped, silently
    r = plan("As a QA-minded PM, I want an L-shaped wall, 4 by 4 cubes, 2 cubes high.")
    assert r.status == "success", r.notes
    assert len(r.layout) == 2 * 7
    assert set(_columns(r).values()) == {2}


def test_towers_evenly_spaced_in_a_row_are_the_row():
    # "in a row" after "evenly spaced" was built as a row of 5 cubes beside the columns
    r = plan("A colonnade of four columns, each three cubes tall, evenly spaced in a row.")
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == [3, 3, 3, 3]


@pytest.mark.parametrize(
    "command, middle, sides",
    [
        # 'flanking' was dropped as a word of no meaning; "towers 4 cubes tall" a third tower
        ("Two towers flanking a central pyramid of 3 levels; towers 4 cubes tall.", 6, 4),
        ("a pyramid of 3 levels flanked by two towers of 4", 6, 4),
        ("a pyramid of 3 levels between two towers. The towers are 4 cubes tall.", 6, 4),
    ],
)
def test_two_towers_flanking_a_structure_stand_either_side_of_it(command, middle, sides):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = _columns(r)
    towers = sorted(k for k, h in cols.items() if h == sides)
    assert len(towers) == 2 and len(r.layout) == middle + 2 * sides
    rest = [k for k, h in cols.items() if h != sides]
    axis = 0 if abs(towers[0][0] - towers[1][0]) > abs(towers[0][1] - towers[1][1]) else 1
    lo, hi = sorted(t[axis] for t in towers)
    assert all(lo < k[axis] < hi for k in rest)


def test_a_check_said_after_the_structure_restates_it():
    # "Acceptance: 5 steps, 1 cube wide" was built as a second staircase, silently
    r = plan("As a user I want a 5-step staircase rising towards the right so that the demo "
             "looks good. Acceptance: 5 steps, 1 cube wide.")  # fmt: skip
    assert r.status == "success", r.notes
    assert len(r.layout) == 15
    r = plan("A 5-step staircase. Acceptance: 6 steps.")
    assert r.status == "partial" and len(r.layout) == 15
    assert any("differs from the staircase described before (steps 6)" in n for n in r.notes)


@pytest.mark.parametrize(
    "command, parts",
    [
        # ", solid," was read as a second block; "!!" ended the sentence (a tower of its own)
        ("Verify: a cube of 3x3x3 cubes, solid, centred on the table.", 27),
        ("He wants a castle!! with towers in the corners", len(plan("a castle").layout)),
    ],
)
def test_words_said_of_the_structure_are_not_a_second_one(command, parts):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts


@pytest.mark.parametrize(
    "command",
    [
        # the gap's width was read as a span of 1 / ignored with the river, silently
        "a bridge with pillars 2 high, the gap is 2 blocks wide",
        "a bridge over a river 2 cubes wide",
    ],
)
def test_the_width_of_what_a_bridge_crosses_is_its_span(command):
    r = plan(command)
    assert r.status == "success", r.notes
    pillars = sorted(k[1] for k, h in _columns(r).items() if h > 1)
    assert len(pillars) == 2 and pillars[1] - pillars[0] == pytest.approx(0.15)


@pytest.mark.parametrize(
    "command, height",
    [
        # each correction was left unread: the first value built (or both, as two towers)
        ("Build me a tower of 6, ah no, of 4 cubes.", 4),
        ("Stack of 6, no, stack of 4, at the back.", 4),
        ("Tower 5 cubes. Correction to previous line: tower 4 cubes.", 4),
    ],
)
def test_a_correction_said_again_with_its_noun_or_a_filler_replaces_the_value(command, height):
    r = plan(command)
    assert r.status == "success", r.notes
    assert list(_columns(r).values()) == [height]
    assert any(n.startswith("corrected by the command itself") for n in r.notes)


def test_a_corrected_length_in_millimetres_replaces_the_one_said():
    # "— correction: height 100 mm" left both heights; the 150 reported unused (partial)
    r = plan("Wall length 250 mm, height 150 mm — correction: height 100 mm.")
    assert r.status == "success", r.notes
    assert set(_columns(r).values()) == {2}


@pytest.mark.parametrize(
    "command, heights",
    [
        # "a taller one on the right" was read as ordering a row (one tower built)
        ("a tower of 2 on the left and a taller one on the right", [2, 3]),
        # "a bigger one of 4": "a one of 4", read as nothing (one tower built)
        ("Put a little tower of 2 on the left and a bigger one of 4 on the right side of the "
         "table.", [2, 4]),
    ],
)
def test_a_comparative_one_is_a_second_structure(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])  # left to right
    assert [h for _, h in cols] == heights


@pytest.mark.parametrize(
    "command",
    [
        # "stack 5 on the right" made the first stack 8 high, silently
        "Stack 3 on the left, stack 5 on the right, stack 4 in between them.",
        # the three were read as the towers of one beam (partial)
        "a tower of 3 on the left, a tower of 5 on the right, a tower of 4 in between them",
    ],
)
def test_a_third_stack_in_between_them_stands_between_the_two(command):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])  # left to right
    assert [h for _, h in cols] == [3, 4, 5]


@pytest.mark.parametrize(
    "command, height",
    [
        # a row of 2 was laid across the tower's one-cube top (failure)
        ("a tower of 3, then put 2 cubes on top", 5),
        # a block of its own beside the tower, "to make it taller" reported (partial)
        ("Build a tower of 4 and then put a block on top of it to make it taller.", 5),
    ],
)
def test_cubes_put_on_top_of_a_tower_make_it_taller(command, height):
    r = plan(command)
    assert r.status == "success", r.notes
    assert list(_columns(r).values()) == [height]


@pytest.mark.parametrize(
    "command, parts, heights",
    [
        # "four blocks on each side" was read as a tower at each end (a 3 by 3 ring)
        ("Please build a ring of blocks with an empty middle, four blocks on each side.", 12, {1}),
        ("Can you lay out a square of nine blocks, three on each side, all flat on the table?",
         9, {1}),
        # the arms' 3 was read as the wall's height, the "2 high" reported unused
        ("An L-shaped corridor wall, arms 5 and 3, 2 high.", 14, {2}),
        # what she likes was built as a second staircase of its own
        ("She likes stairs, can you do stairs with 3 steps going up to the right?", 6, {1, 2, 3}),
        # "a long block across them" was a 3-long block laid on the bridge (failure)
        ("Now make a bridge: two towers of two blocks and lay a long block across them.", 5, None),
        # "single stack" and "each stack three high" were stacks of their own
        ("Stack 'em four high, single stack.", 4, {4}),
        ("Give me a row of three stacks, each stack three high.", 9, {3}),
        # the 3 was dropped: a 3 by 3 L
        ("Make an L with five blocks going one way and three blocks going the other way.", 7,
         {1}),
        # "around a middle block": a ring around a block (failure); "arms 1 block long": a bar
        ("Make a cross with arms of two blocks around a middle block.", 9, {1}),
        ("A cross-shaped plaza, arms 1 block long around a centre block, single layer.", 5, {1}),
    ],
)
def test_words_that_size_the_structure_are_not_structures_of_their_own(command, parts, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    if heights is not None:
        assert set(_columns(r).values()) == heights


@pytest.mark.parametrize(
    "command",
    [
        # its rows, said from the bottom: the three and two reported unused (partial)
        "Build a pyramid: four blocks at the bottom, then three, then two, then one on top.",
        # a default pyramid and four rows beside it
        "a pyramid with rows of 4, 3, 2 and 1",
    ],
)
def test_a_pyramid_s_rows_listed_are_its_levels(command):
    r = plan(command)
    assert r.status == "success", r.notes
    levels: dict[int, int] = {}
    for o in r.layout.objects:
        z = round(o.position[2] / 0.05 - 0.5)
        levels[z] = levels.get(z, 0) + 1
    assert [levels[z] for z in sorted(levels)] == [4, 3, 2, 1]


def test_a_comparison_starts_from_the_parts_of_a_tower_said_in_words():
    # "of four blocks" was taken for a count of structures: "half as tall" unread, a tower of 6
    r = plan("Build a tower of four blocks. Next to it, on its left, build another one that is "
             "half as tall.")  # fmt: skip
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: kv[0][1])  # right to left
    assert [h for _, h in cols] == [4, 2]


@pytest.mark.parametrize(
    "command, parts, heights",
    [
        # the columns stood bare and the lintel was a default bridge beside them (partial)
        ("Two columns of three cubes carrying a lintel.", 7, {3, 1}),
        # four bare columns and a default slab beside them (partial)
        ("A portico: four columns of two cubes supporting a flat roof slab.",
         len(plan("a table with legs 2 high").layout), None),
        # "bridge btw 2 twrs": a default bridge beside two towers (partial)
        ("bridge btw 2 twrs hgt 3", 7, {3, 1}),
    ],
)
def test_columns_carrying_a_top_are_its_supports(command, parts, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    assert any(max(o.size) > 0.06 for o in r.layout.objects)  # a beam or a top across them
    if heights is not None:
        assert set(_columns(r).values()) == heights


@pytest.mark.parametrize(
    "command, heights",
    [
        # both on the left ('opposite' and the right reported unused)
        ("Two spawn towers, 4 tall, on opposite sides of the map — left and right.", [4, 4]),
        # the 5 was dropped: two towers of 3
        ("2 towers h=3,h=5", [3, 5]),
        # a default row beside ten single cubes (partial)
        ("Row of 5 stacks, heights going up 1 2 3 4 5 from right to left.", [1, 2, 3, 4, 5]),
    ],
)
def test_each_structure_of_several_gets_what_was_said_for_it(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    cols = sorted(_columns(r).items(), key=lambda kv: kv[0][1])  # right to left
    assert [h for _, h in cols] == heights
    if len(heights) == 2 and "left" in command:
        assert cols[0][0][1] < 0.25 < cols[1][0][1]  # one each side of the table's middle


@pytest.mark.parametrize(
    "command, height",
    [
        # "±0.01" was read as a count of its own: an error
        ("Cube stack 0.25 m ±0.01 tall at x = 450 mm, y = 300 mm.", 5),
        # "single 50 mm cube footprint" was read as its height: one cube (partial)
        ("Tower, height 150 mm ±5 mm, single 50 mm cube footprint.", 3),
    ],
)
def test_a_tolerance_and_a_one_part_footprint_leave_a_tower_its_height(command, height):
    r = plan(command)
    assert r.status == "success", r.notes
    assert list(_columns(r).values()) == [height]


@pytest.mark.parametrize(
    "command, parts",
    [
        # "Test case 7" was read as the pyramid's base: 7, 6 and 5 (18 parts)
        ("Test case 7: pyramid with 3 levels.", 6),
        # the purpose's words were read as a structure to enclose (partial)
        ("As a user I want an enclosure 5x3 cubes so that a ball can be kept inside.", 12),
        # 'egypt' reported unused (partial)
        ("Can you make a pyramid like the ones in Egypt, with 3 layers?", 6),
    ],
)
def test_a_label_a_purpose_and_a_likeness_are_no_sizes(command, parts):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    assert any(n.startswith("ignored '") for n in r.notes)  # what was set aside is said


@pytest.mark.parametrize(
    "command, heights",
    [
        # a row of 2 beside one tower, 'times' reported unused (partial)
        ("build a tower three cubes high and then build the same thing two more times in a row",
         [3, 3, 3]),
        ("a tower of 3 cubes, then two more of the same in a row", [3, 3, 3]),
        # 'build it one more time' reported unused: one tower (partial)
        ("Build tower 3 cubes. Then build it one more time on the left of it.", [3, 3]),
    ],
)
def test_the_same_again_is_a_copy_of_the_one_before(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == heights


@pytest.mark.parametrize(
    "command, parts, heights",
    [
        # spoken "no make it" with no comma: the four reported unused (partial)
        ("make a flat square um four by four no make it three by three", 9, {1}),
        # 'tall' after three sizes reported unused (partial)
        ("make a block two by two by three tall", 12, {3}),
        # a dictated "new line": the bridge laid across one tower (failure)
        ("build two towers four cubes each new line and a bridge across the top of them", 9,
         {4, 1}),
        # "a gap between the rows" read as rows a beam joins (partial)
        ("Two rows of 4 cubes, one behind the other, with a gap between the rows.", 8, {1}),
        # "step width" reported unused; "+y (left)" read as the table's left region
        ("Spec: staircase, N=4 steps, step width 2 cubes, ascending toward +y (left).", 20,
         {1, 2, 3, 4}),
    ],
)
def test_spoken_and_spec_phrasings_size_the_structure(command, parts, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    assert set(_columns(r).values()) == heights


@pytest.mark.parametrize(
    "command, parts, heights",
    [
        # 'more high than 2' and 'not' reported unused (partial)
        ("Please build a wall of 4 cubes length and not more high than 2.", 8, {2}),
        # "T form … the leg": a table, a T and a tower (partial)
        ("Make T form, the top is 5 cubes, the leg is 3 cubes.", 7, {1}),
        # "4 cubes outside dimensions" read as a gap: a 5 by 5 ring (partial)
        ("An enclosed courtyard, 5 by 4 cubes outside dimensions, walls two courses high.", 28,
         {2}),
        # "four walls in a square": four 4 by 4 blocks and a ring (failure)
        ("Can you make a little house for her teddy? Four walls in a square, 4 blocks each side, "
         "2 high.", 24, {2}),
    ],
)
def test_non_native_and_drawing_phrasings_size_the_structure(command, parts, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert len(r.layout) == parts
    assert set(_columns(r).values()) == heights


def test_rows_of_towers_are_that_many_towers_in_rows():
    # a 2 by 3 floor and a tower of 3 beside it, silently
    r = plan("Three rows of two towers each, every tower three cubes tall.")
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert sorted(cols.values()) == [3] * 6
    assert len({x for x, _ in cols}) == 3 and len({y for _, y in cols}) == 2


def test_a_purpose_that_names_a_size_is_not_set_aside():
    # "so my toy can climb onto a 3-cube-high platform": the platform's 3 is a size
    r = plan("Make a step so my toy can climb onto a 3-cube-high platform.")
    assert not any("what it is for" in n for n in r.notes)


def test_rows_said_after_the_towers_size_arrange_them():
    # "three cubes tall" between the towers and "in 3 rows of 2" hid the towers: a floor of 6
    # was built beside them, silently
    r = plan("six towers, three cubes tall, in 3 rows of 2")
    assert r.status == "success", r.notes
    cols = _columns(r)
    assert sorted(cols.values()) == [3] * 6
    assert len({x for x, _ in cols}) == 3 and len({y for _, y in cols}) == 2


def test_towers_joined_by_a_beam_across_the_top_are_a_bridge():
    # 'a beam across the top' was reported as naming nothing (partial)
    r = plan("two towers of 3 joined by a beam across the top")
    assert r.status == "success", r.notes
    assert len(r.layout) == 7 and set(_columns(r).values()) == {3, 1}


def test_an_arch_lower_overall_than_any_arch_is_not_a_silent_success():
    # "3 cubes tall in total" built an arch 6 high, and the run said success
    r = plan("Please make an arch. It should be 3 cubes tall in total.")
    assert r.status == "partial"
    assert any("read 3 high as its legs, 6 high overall" in n for n in r.notes)


def _profile(r, axis: int) -> list[int]:
    """Column heights along one table axis (0 = x, front to back; 1 = y, right to left)."""
    cols: dict[float, int] = {}
    for o in r.layout.objects:
        key = round(o.position[axis], 3)
        cols[key] = max(cols.get(key, 0), round(o.position[2] / 0.05 + 0.5))
    return [cols[k] for k in sorted(cols)]


@pytest.mark.parametrize(
    "command, profile",
    [
        # each staircase climbed the same way: one of them away from the tower, silently
        ("a 2-step staircase on each side of a 4-high tower", [1, 2, 4, 2, 1]),
        ("Begin with a wall 5 long and 3 tall. Next, put a 2-step staircase against each end.",
         [1, 2, 3, 3, 3, 3, 3, 2, 1]),
        # "leading up to": the staircase climbed away from the tower
        ("a 4-step staircase leading up to a tower of 6", [6, 4, 3, 2, 1]),
    ],
)
def test_a_staircase_beside_a_structure_climbs_towards_it(command, profile):
    r = plan(command)
    assert r.status == "success", r.notes
    assert _profile(r, 1) in (profile, profile[::-1])


def test_a_staircase_whose_way_up_is_said_keeps_it_beside_a_tower():
    r = plan("a 3-step staircase going up to the left, and a tower of 4 on its right")
    assert r.status == "success", r.notes
    assert _profile(r, 1) == [4, 1, 2, 3]


def test_a_move_to_one_side_keeps_the_place_across_it():
    # "put it on the left" after "at the front" dropped the front, silently
    r = plan("put a row of 5 at the front, but don't put it on the right")
    assert r.status == "success", r.notes
    assert r.spec.structures[0].region == "front left"
    assert plan("a tower at the back. Move it to the left.").spec.structures[0].region == (
        "back left"
    )
    assert plan("a tower at the left. Now move it to the centre.").spec.structures[0].region == (
        "centre"
    )


@pytest.mark.parametrize(
    "command, length, height",
    [
        # ", same length" was dropped: a wall of 4, silently
        ("I want a row of 6. Then build a wall behind it, same length, 3 high.", 6, 3),
        # "the same size" of a second wall was left over (partial)
        ("First a wall 4 long, 2 high. After that a second wall the same size behind it.", 4, 2),
        # "5 high, 4 long" after "next to it": the relation was lost (partial)
        ("a tower of 5 and a wall next to it, 5 high, 4 long", 4, 5),
    ],
)
def test_a_size_said_after_the_second_structure_is_its_own(command, length, height):
    r = plan(command)
    assert r.status == "success", r.notes
    second = r.spec.structures[1]
    assert second.shape == "wall" and (second.length, second.height) == (length, height)
    assert len(r.spec.relations) == 1


def test_same_height_said_of_a_count_stays_a_claim():
    r = plan("Tower, 5 cube. Also tower, 5 cube. Total 2 tower, same height.")
    assert r.status == "success", r.notes
    assert [s.height for s in r.spec.structures] == [5, 5]


def test_a_size_measured_from_a_structure_in_millimetres_does_not_crash():
    # "304.8 mm" was cut at its decimal point: a 8 mm row, and the reader raised
    r = plan("Start with a foot-long row running front to back. Then put a second row on top, "
             "same length.")  # fmt: skip
    assert r.status == "success", r.notes
    assert len(r.layout) == 12 and set(_columns(r).values()) == {2}


def test_touching_it_after_a_relation_to_it_is_the_same_relation():
    # "next to it, touching it": the relation's object was 'it, touching it' (partial)
    r = plan("a tower of 5. Then put a wall next to it, touching it.")
    assert r.status == "success", r.notes
    assert len(r.spec.relations) == 1 and r.spec.relations[0].gap_m == 0.0
    # a likeness said last is set aside, not built ("a house" was a ring)
    r = plan("Start with something like a chimney, five cubes tall. Then put a little wall on "
             "either side of it, two cubes long and two high, touching it, like the gable end of "
             "a house.")  # fmt: skip
    assert r.status == "success", r.notes
    assert _profile(r, 1) == [2, 2, 5, 2, 2]


def test_a_table_top_said_as_a_fragment_is_the_tables_own():
    # "Top about 4 by 4 cubes." was a separate 4 by 4 slab, silently
    r = plan("Let's do a table. Legs 3 cubes tall. Top about 4 by 4 cubes.")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == ["canopy"]
    assert r.spec.structures[0].span == 2


@pytest.mark.parametrize(
    "command, sides",
    [
        # the patch and the row were one phrase: the relations formed a cycle (error)
        ("a tower of 5 to the left of a 2x2 patch, and a row of 3 to the right of it",
         {"left", "right"}),
        # "on the left of it and a row of 4 behind it": the row stood behind the tower
        ("Put a 4x2 block, two high, in the middle. Put a tower of 3 on the left of it and a row "
         "of 4 behind it.", {"left", "back"}),
    ],
)
def test_two_structures_related_to_the_one_between_them(command, sides):
    r = plan(command)
    assert r.status == "success", r.notes
    middle = next(i for i, s in enumerate(r.spec.structures) if s.shape in ("grid", "block"))
    assert {rel.object for rel in r.spec.relations} == {middle}
    assert {rel.side for rel in r.spec.relations} == sides


@pytest.mark.parametrize(
    "command, heights",
    [
        # a ring was built around the tower, silently
        ("a cross with a 3-cube tower in the centre", [1, 1, 1, 1, 4]),
        ("a row of 5 with a tower of 3 in the middle", [1, 1, 1, 1, 4]),
    ],
)
def test_a_tower_in_the_middle_of_a_cross_or_row_stands_on_it(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == heights
    assert [rel.kind for rel in r.spec.relations] == ["on_top_of"]


def test_a_wall_said_by_its_sides_with_a_middle_stays_a_ring():
    r = plan("a wall 6 by 6 with a pyramid in the middle")
    assert [s.shape for s in r.spec.structures] == ["enclosure", "pyramid"]


def test_a_structure_outside_another_on_a_side_stands_beside_it():
    # "outside it on the left": the tower went to the table's left, unrelated to the pen
    r = plan("a pen 6x4 and a tower of 3 outside it on the left")
    assert r.status == "success", r.notes
    assert [(rel.kind, rel.side) for rel in r.spec.relations] == [("next_to", "left")]
    assert r.spec.structures[1].region is None


def test_a_place_said_after_a_list_is_the_place_of_all():
    # only the last tower went to the back, silently
    r = plan("a tower of 2, a tower of 4 and a tower of 6, evenly spaced along the back")
    assert r.status == "success", r.notes
    assert [s.region for s in r.spec.structures] == ["back"] * 3
    assert len({round(o.position[0], 3) for o in r.layout.objects}) == 1
    # without the comma, or in a sentence of its own, the place is the last one's
    r = plan("a tower of 2 and a tower of 4 at the back")
    assert [s.region for s in r.spec.structures] == [None, "back"]
    r = plan("A wall of 4. A tower of 2, at the back.")
    assert [s.region for s in r.spec.structures] == [None, "back"]


def test_how_many_structures_said_in_a_sentence_of_its_own_sizes_none():
    # "I need two things." made the pyramid's base 2: failure
    r = plan("I need two things. A pyramid with 3 levels on the left. A staircase of 3 on the "
             "right.")  # fmt: skip
    assert r.status == "success", r.notes
    assert r.spec.structures[0].height == 3 and r.spec.structures[0].length is None
    r = plan("I need three things. A pyramid with 3 levels on the left. A staircase of 3 on the "
             "right.")  # fmt: skip
    assert r.status == "partial" and any("'three things'" in n for n in r.notes)


def test_a_tower_at_the_corner_of_an_l_stands_where_its_arms_meet():
    # the tower went to the table's back left corner, silently
    r = plan("an L shape of 5 by 3 with a tower of 4 at the corner")
    assert r.status == "success", r.notes
    assert [(rel.kind, rel.at) for rel in r.spec.relations] == [("on_top_of", "bend")]
    cols = _columns(r)
    (bend,) = [k for k, h in cols.items() if h > 1]
    assert cols[bend] == 5
    xs, ys = {x for x, _ in cols}, {y for _, y in cols}
    assert bend[0] in (min(xs), max(xs)) and bend[1] in (min(ys), max(ys))
    # its arms meet at that part: a neighbour along x and one along y
    near = [k for k in cols if abs(k[0] - bend[0]) + abs(k[1] - bend[1]) < 0.051 and k != bend]
    assert {k[0] == bend[0] for k in near} == {True, False}


def test_a_bend_is_only_on_a_top_with_one_corner_where_arms_meet():
    from sdi.design.composer import compose
    from sdi.errors import InfeasibleError

    spec = Spec(
        structures=(structure(shape="grid", length=3, width=3), TowerSpec(shape="tower")),
        relations=(Relation(kind="on_top_of", subject=1, object=0, at="bend"),),
    )
    with pytest.raises(InfeasibleError, match="4 corners where two arms meet"):
        compose(spec)
    with pytest.raises(ValueError, match="corner of an L"):
        Relation(kind="next_to", subject=1, object=0, at="bend")


def test_a_word_of_the_structure_said_as_a_sentence_of_its_own():
    # "Flat." named no structure (partial)
    r = plan("Okay. Grid of 2 by 5. Flat. Put it on the right.")
    assert r.status == "success", r.notes
    assert r.spec.structures[0].region == "right" and len(r.layout) == 10


def test_no_cubes_stacked_on_top_holds_for_a_single_layer():
    r = plan("a 3x3 layer, no cubes stacked on top")
    assert r.status == "success", r.notes
    assert len(r.layout) == 9


def test_the_gap_between_a_bridges_pillars_said_in_a_sentence():
    # "The gap between them should be 2 cubes." built a second bridge of 3 pillars (partial)
    r = plan("Make a bridge. The pillars should be 4 cubes high. The gap between them should be "
             "2 cubes.")  # fmt: skip
    assert r.status == "success", r.notes
    (bridge,) = r.spec.structures
    assert (bridge.height, bridge.span) == (4, 2)


def test_a_staircase_against_or_leading_up_to_a_tower_touches_it():
    # "against a tower" was reported as not a relation (partial); "leading up to" stood apart
    for command in ("a 4-step staircase against a tower of 6",
                    "a 4-step staircase leading up to a tower of 6"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [(rel.kind, rel.gap_m) for rel in r.spec.relations] == [("next_to", 0.0)]
        assert _profile(r, 1) in ([6, 4, 3, 2, 1], [1, 2, 3, 4, 6])
        assert len({round(o.position[1], 3) for o in r.layout.objects}) == 5  # no gap column


def test_against_the_wall_with_no_wall_named_is_not_a_relation():
    r = plan("a tower of 3 against the wall")
    assert r.status == "partial"
    r = plan("a wall of 5 and a tower of 3 against the wall")
    assert r.status == "success", r.notes
    assert [(rel.kind, rel.gap_m) for rel in r.spec.relations] == [("next_to", 0.0)]


def test_a_plus_signs_arms_are_counted_from_its_middle():
    # "arms two cubes long" built a cross 3 long (partial)
    r = plan("a plus sign made of cubes, arms two cubes long")
    assert r.status == "success", r.notes
    assert r.spec.structures[0].length == 5 and len(r.layout) == 9


def test_as_tall_as_a_staircases_top_step():
    # read as a vague "tall": a tower of 6, and the relation lost (partial)
    r = plan("Build a staircase of 4. Then put a tower next to it, as tall as its top step.")
    assert r.status == "success", r.notes
    assert r.spec.structures[1].height == 4 and len(r.spec.relations) == 1


def test_a_misspelt_beam_is_corrected():
    # 'beem' was left unused: the two towers were stacked (partial)
    r = plan("two towrs of 4 with a beem across the tops")
    assert r.status == "success", r.notes
    assert "corrected 'beem' to 'beam'" in r.notes
    assert [s.shape for s in r.spec.structures] == ["bridge"]


@pytest.mark.parametrize(
    "command, parts, top, on_top",
    [
        # the second tower stood on the first: failure
        ("lay a 2x6 patch first and after that stand two towers of 3 on its two ends", 18, 4, 2),
        # "four cubes" named no structure the corners could carry (partial)
        ("a 4x4 slab with four cubes on its four corners", 20, 2, 4),
        # a third tower stood apart beside the wall, silently
        ("a wall 5 long with two towers of 2 at both ends", 14, 2, 7),
    ],
)
def test_as_many_as_the_ends_or_corners_are_one_at_each(command, parts, top, on_top):
    r = plan(command)
    assert r.status == "success", r.notes
    levels = [round(o.position[2] / 0.05 + 0.5) for o in r.layout.objects]
    assert len(levels) == parts and max(levels) == top
    assert levels.count(top) == on_top


def test_towers_at_the_four_corners_of_the_table_stay_one_in_each_corner():
    r = plan("four towers of 3 at the four corners of the table")
    assert r.status == "success", r.notes
    assert sorted(s.region for s in r.spec.structures) == [
        "back left", "back right", "front left", "front right"]  # fmt: skip
    # the object said after "the corners of": the copies stand on it
    r = plan("four towers of 2 at the corners of a 4x4 slab")
    assert r.status == "success", r.notes
    assert [(rel.kind, rel.at) for rel in r.spec.relations] == [("on_top_of", "corners")]


@pytest.mark.parametrize(
    "command, shapes, parts, tallest",
    [
        # a default plinth was built beside the slab, and the columns stood on the plinth
        ("Put a plinth down first, a 3 by 3 slab one cube thick, and stand four columns of two "
         "on its corners.", ["grid", "tower"], 17, 3),
        # a default tower beside the one of 3 (partial)
        ("a tower, a tower of 3", ["tower"], 3, 3),
        # a column of 6 was built, silently
        ("I want a wall, a long one of 6 cubes", ["wall"], 12, 2),
    ],
)
def test_a_structure_said_again_with_its_size_is_the_same_one(command, shapes, parts, tallest):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == shapes
    assert len(r.layout) == parts and max(_columns(r).values()) == tallest


def test_a_list_after_a_comma_is_not_one_structure_said_again():
    r = plan("a tower, a tower of 3 and a wall")
    assert [s.shape for s in r.spec.structures] == ["tower", "tower", "wall"]


def test_a_tower_at_the_corner_of_a_slab_stands_on_one_corner_of_it():
    # the tower went to the table's back left corner, apart from the slab, silently
    r = plan("a 3x3 slab with a tower at the corner")
    assert r.status == "success", r.notes
    assert [(rel.kind, rel.at) for rel in r.spec.relations] == [("on_top_of", "corner")]
    assert any("which corner was not said" in n for n in r.notes)
    cols = _columns(r)
    (corner,) = [k for k, h in cols.items() if h > 1]
    assert corner == (min(x for x, _ in cols), min(y for _, y in cols))  # the front right


def test_one_more_block_on_a_wall_is_a_cube_on_it():
    # a 2x2x2 block stood on the wall's ends: failure
    r = plan("a wall 5 long, 2 high. put one more block on top at each end")
    assert r.status == "success", r.notes
    levels = [round(o.position[2] / 0.05 + 0.5) for o in r.layout.objects]
    assert len(levels) == 12 and levels.count(3) == 2
    # a tower named last grows by it
    r = plan("a tower of 3. put one more cube on top")
    assert [s.height for s in r.spec.structures] == [4]


@pytest.mark.parametrize(
    "command, heights",
    [
        # every tower was built 1 high, the comparison reported unused (partial)
        ("three towers in a row, each one block taller than the one before", [1, 2, 3]),
        ("four stacks, each 2 cubes shorter than the previous one, starting at 8", [8, 6, 4, 2]),
        ("three towers, the first 2 high, each one cube taller than the one before", [2, 3, 4]),
        # the heights listed after it
        ("three towers, each one block taller than the one before: one, two, three", [1, 2, 3]),
        # "a row of towers": a row of 5 was built beside them (partial)
        ("a row of towers, 1, 2, 3, 4 cubes high", [1, 2, 3, 4]),
    ],
)
def test_towers_each_taller_than_the_one_before(command, heights):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.height for s in r.spec.structures] == heights


def test_towers_each_shorter_with_no_start_are_not_guessed():
    r = plan("three towers, each one shorter than the last")
    assert r.status == "partial" and "shorter than the last" in (r.error or "")


@pytest.mark.parametrize(
    "command, side, height",
    [
        # a wall 6 long and 6 high, its 3 reported unused (partial)
        ("a 3-high wall all the way around a 6 by 6 area", 8, 3),
        # a wall 7 long and 7 high, silently
        ("a fence around a 5 by 5 space", 7, 1),
        ("walls around a 4 by 4 area, 2 high", 6, 2),
    ],
)
def test_a_wall_around_an_area_is_a_ring_with_that_inside(command, side, height):
    r = plan(command)
    assert r.status == "success", r.notes
    (ring,) = r.spec.structures
    assert ring.shape == "enclosure" and (ring.length, ring.width) == (side, side)
    assert set(_columns(r).values()) == {height} and len(_columns(r)) == 4 * (side - 1)


def test_a_table_top_wider_than_its_beams_says_so():
    # the top built is its beams over the legs' centres: 3 across under a "4 by 4 top", unsaid
    r = plan("a table with legs 3 tall and a 4 by 4 top")
    assert any("the table's top is its beams, 3 parts across" in n for n in r.notes)
    top = [o for o in r.layout.objects if o.position[2] == max(p.position[2] for p in r.layout)]
    across = {round(o.position[1], 3) for o in top}
    assert len(across) == 3  # three beams side by side: the note tells the truth
    assert not any("top is its beams" in n for n in plan("a table with a 3 by 3 top").notes)


@pytest.mark.parametrize(
    "command, shapes, heights",
    [
        # "another one" after "the corner of the table" built a table, silently
        ("build a tower at the back left corner of the table then another one at the front right "
         "corner", ["tower", "tower"], [3, 3]),
        # "scratch that" took back the wall: error
        ("Make a wall 4 long, scratch that, 6 long, 2 high.", ["wall"], [2] * 6),
        # spoken "too high" after a length: 4 high were built for a vague "high"
        ("build a wall six long and too high", ["wall"], [2] * 6),
        # one cube was built
        ("stack one cube on top of another cube", ["tower"], [2]),
    ],
)
def test_spoken_and_revised_commands_are_read_as_meant(command, shapes, heights):
    _built_as_said(command, shapes, heights)


def test_a_per_b_is_a_by_b_and_a_kind_field_qualifies_the_family():
    # "two per two" was a pack of 2, silently
    r = plan("Put a tower of three cubes over the block of two per two.")
    assert r.spec.structures[1].shape == "block"
    assert (r.spec.structures[1].length, r.spec.structures[1].width) == (2, 2)
    # "kind: square" was read as the family: a 2x2x4 block, silently
    r = plan("item: pyramid\nlevels: 4\nkind: square")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == ["pyramid"]
    levels = sorted(round(o.position[2] / 0.05 + 0.5) for o in r.layout.objects)
    assert [levels.count(k) for k in (1, 2, 3, 4)] == [16, 9, 4, 1]


def test_a_staircase_way_up_said_in_the_past_or_corrected():
    # "rose toward the left" was an unknown word: it climbed to the back, silently
    r = plan("a staircase of six steps rose toward the left")
    assert r.spec.structures[0].axis == "y" and not r.spec.structures[0].yaw_deg
    # "going up to the back, no, to the front" went to the table's front, climbing back
    r = plan("Staircase of 4 going up to the back, no, to the front actually.")
    assert r.status == "success", r.notes
    (stairs,) = r.spec.structures
    assert (stairs.axis, stairs.yaw_deg, stairs.region) == ("x", 180.0, None)


@pytest.mark.parametrize(
    "command, shapes, heights",
    [
        # a sentence telling what happened before built the structure it named, as well
        ("Left off before the bridge. Please build a bridge with pillars 2 cubes tall.",
         ["bridge"], [1, 2, 2]),
        ("Hello again! Last time the enclosure was too small. Could you build it 6 by 6 this "
         "time, one cube high? Thanks so much.", ["enclosure"], [1] * 20),
        # a structure taken back by its name was built all the same
        ("Castle. Wait, no castle. Just a tower of 6.", ["tower"], [6]),
        ("Hello, please disregard my earlier message asking for a pyramid. What we actually "
         "need is a tower eight cubes tall.", ["tower"], [8]),
        ("forget the pyramid, build a tower of 8", ["tower"], [8]),
        ("Nothing fancy, no bridges or arches — just two towers of five, side by side.",
         ["tower", "tower"], [5, 5]),
    ],
)
def test_what_is_recounted_or_taken_back_by_name_is_not_built(command, shapes, heights):
    r = _built_as_said(command, shapes, heights)
    assert any("happened before" in n or "taken back" in n or "not wanted" in n for n in r.notes)


def test_a_structure_taken_back_by_name_needs_the_name_of_a_structure():
    # "skip the centre cube": a part, not a structure — still reported, nothing taken back
    r = plan("Build a 3x3x3 block. skip the centre cube of the top layer")
    assert r.status == "partial" and len(r.layout.objects) == 27
    # a sentence in the past with no request after it is what to build (a story)
    r = plan("There was a great pyramid, four levels high.")
    assert [s.shape for s in r.spec.structures] == ["pyramid"]
    # "ignore the wall's colour": the wall's, not the wall
    r = plan("ignore the wall's colour, build it 4 long")
    assert [(s.shape, s.length) for s in r.spec.structures] == [("wall", 4)]


@pytest.mark.parametrize(
    "command, levels",
    [
        ("Pyramid replacement: 4x4 base, go up until it's a single cube on top.",
         [16, 9, 4, 1]),
        ("a pyramid with a 4x4 base, a single cube on top", [16, 9, 4, 1]),
        ("a 4-level pyramid topped with one cube", [4, 3, 2, 1]),
    ],
)
def test_a_pyramid_said_to_end_in_one_cube_is_that_pyramid(command, levels):
    # the single cube was a tower stood on the pyramid (or a 4x4 block on it: failure)
    r = plan(command)
    assert r.status == "success", r.notes
    assert [a * b for a, b in _level_sizes(r.layout)] == levels
    # a cube put on top of it is a cube added
    r = plan("a pyramid, then put one cube on top of it")
    assert [s.shape for s in r.spec.structures] == ["pyramid", "tower"]


@pytest.mark.parametrize(
    "command, shapes, heights",
    [
        # "2nd" was read as the row's length
        ("row of 4 pls, then 2nd row behind it", ["row", "row"], [1] * 8),
        # "three cubes, one on top of another": three towers of one, two stacked (partial)
        ("Shim stack: three cubes, one on top of another, in the front right.", ["tower"], [3]),
        # "a cube alone" between them was read as a one-cube gap
        ("Build a tower of 4 cubes and an other tower of 4 cubes, and between them a cube alone.",
         ["tower", "tower", "tower"], [1, 4, 4]),
        # a 1x6 wall with its height said apart was a column 6 high
        ("Place a 1x6 wall along +y, height 2, centred at x=0.55 y=0.30.", ["wall"], [2] * 6),
        # sizes said after "a small wall" built a second wall beside it
        ("could you please build a small wall for us? Six cubes long and two cubes high would be "
         "ideal.", ["wall"], [2] * 6),
    ],
)
def test_counts_and_sizes_said_in_other_words(command, shapes, heights):
    _built_as_said(command, shapes, heights)


def test_a_tower_over_a_block_stands_on_it_and_a_corner_said_with_a_hyphen():
    # "a tower of three cubes over the block": beside it, silently
    r = plan("Put a tower of three cubes over the block of two per two.")
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [("on_top_of", 0, 1)]
    # "on its back-left corner" was read as "back to left": the table's back left region
    r = plan("a 3 by 4 slab with a tower of 2 on its back-left corner")
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    assert max(o.position[2] for o in r.layout.objects) > 0.1
    # "front-back" still runs from one to the other
    assert plan("a row of 5 running front-back").spec.structures[0].axis == "x"


def test_the_small_one_said_without_one():
    r = plan("Construct two towers, the one of four cubes and the other of two, the small at "
             "the right.")
    assert r.status == "success", r.notes
    cols = _columns(r)
    (small,) = [k for k, v in cols.items() if v == 2]
    (tall,) = [k for k, v in cols.items() if v == 4]
    assert small[1] < tall[1]  # right = smaller y


@pytest.mark.parametrize(
    "command, shapes, heights",
    [
        # "WO-4474" was a tower of 4474 parts: failure
        ("WO-4474 ITEM 1 TOWER 3 CUBES; ITEM 2 TOWER 3 CUBES; ITEM 3 BRIDGE JOINING ITEMS 1 AND "
         "2.", ["bridge"], [1, 3, 3]),
        # "REVISED TO 6 CUBES PER ENG": the 8 kept, the 6 a row beside it
        ("WO-4478 REV B: TOWER 8 CUBES, REVISED TO 6 CUBES PER ENG.", ["tower"], [6]),
        # "QTY 1" of an arch was its legs' height
        ("WO-4482: ARCH, QTY 1, LOC X=0.45 Y=0.30.", ["arch"], None),
        # "BETWEEN ITEMS 1 AND 2": between nothing (partial)
        ("WO-4485 ITEM 1: TOWER 4. ITEM 2: TOWER 4. ITEM 3: TOWER 2 BETWEEN ITEMS 1 AND 2.",
         ["tower", "tower", "tower"], [2, 4, 4]),
    ],
)
def test_a_work_order_numbers_its_items_and_says_its_quantities(command, shapes, heights):
    r = _built_as_said(command, shapes, heights)
    if heights is None:
        assert r.spec.structures[0].height is None  # the arch of its own size


def test_an_item_referred_to_by_its_number_is_that_structure():
    # "ADJACENT TO LEFT END OF ITEM 1": the tower went to the table's left, silently
    r = plan("WO-4481 ITEM 1 WALL LEN 5 HT 3. ITEM 2 TOWER HT 5 ADJACENT TO LEFT END OF ITEM 1.")
    assert r.status == "success", r.notes
    assert [(x.kind, x.subject, x.object, x.side) for x in r.spec.relations] == [
        ("next_to", 1, 0, "left")
    ]


@pytest.mark.parametrize(
    "command, shapes",
    [
        # a likeness said first, then what to build after a colon (partial: 'city', 'skyline')
        ("Like a city skyline: three towers side by side, 2, 5 and 3 tall.",
         ["tower", "tower", "tower"]),
        ("Like a Jenga tower but solid: a 3x3 block, 4 high.", ["block"]),
        ("Like a scoreboard: a wall 6 wide and 3 high at the back of the table.", ["wall"]),
        # a likeness with "the" or a plural after the structure it describes
        ("A big L like the letter magnet on the fridge, five down and three across.",
         ["l_shape"]),
        ("Two towers like twin teddy bears, three blocks each, standing next to each other.",
         ["tower", "tower"]),
    ],
)
def test_a_likeness_is_a_description(command, shapes):
    r = plan(command)
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == shapes
    assert any("as a description, not a structure" in n for n in r.notes)


def test_a_likeness_that_names_the_structure_or_one_named_before_is_read():
    # "a tower like the first one": a tower one cube high, silently
    r = plan("a tower of 3 and a tower like the first one")
    assert [s.height for s in r.spec.structures] == [3, 3]
    # the likeness names what to build when nothing after the colon does
    r = plan("Like a T formation: bar of 3, stem of 3.")
    assert [s.shape for s in r.spec.structures] == ["t_shape"]


def _opening(r):
    """The side of its bounding box a U leaves open: where its arms end."""
    cells = {(round(o.position[0] / 0.05), round(o.position[1] / 0.05)) for o in r.layout}
    xs, ys = sorted({x for x, _ in cells}), sorted({y for _, y in cells})
    full = {"front": all((xs[0], y) in cells for y in ys),
            "back": all((xs[-1], y) in cells for y in ys),
            "right": all((x, ys[0]) in cells for x in xs),
            "left": all((x, ys[-1]) in cells for x in xs)}  # fmt: skip
    (open_side,) = [side for side, closed in full.items() if not closed]  # base and arms: full
    return open_side


@pytest.mark.parametrize(
    "command, side, across",
    [
        # every U opened to the front; "opening at the back" was read as its place
        ("Pilot a U-shape, 4 wide, 4 deep, as a cell layout, opening at the back.", "back", 4),
        ("Opening toward the back, 4 wide, 3 deep: a U.", "back", 4),
        ("a U-shape: base 5, arms 3 including the corner cubes, opening toward the left.",
         "left", 3),
        ("a U, 4 wide and 3 deep, opening to the right", "right", 4),
        ("Like the letter U with its open end facing the front of the table, 3 wide and 3 deep.",
         "front", 3),
    ],
)
def test_a_u_opens_the_way_it_is_said(command, side, across):
    r = plan(command)
    assert r.status == "success", r.notes
    assert _opening(r) == side
    ys = {round(o.position[1], 3) for o in r.layout}
    assert len(ys) == across  # "wide": left to right, whichever way it opens


@pytest.mark.parametrize(
    "command, shapes, heights",
    [
        # "two identical 2x2x2 blocks": one block, 2x2x1, silently
        ("Batch size 2: two identical 2x2x2 blocks, one behind the other.", ["block", "block"],
         [2] * 8),
        # "two 2x2x2 blocks, one behind the other": the last "2 blocks" were the two (2 pads)
        ("two 2x2x2 blocks, one behind the other", ["block", "block"], [2] * 8),
        # "a single cube wide": a one-cube tower beside the staircase
        ("Looks like a ramp built out of stairs, 6 steps, a single cube wide.", ["staircase"],
         [1, 2, 3, 4, 5, 6]),
        # "a piece across the top" was dropped: two pillars, silently
        ("two pillars two high with a piece across the top", ["bridge"], [1, 2, 2]),
        # "the second row … on top of the first" after two rows: a third row
        ("- row of 4\n- row of 4\n- second row directly on top of the first", ["row", "row"],
         [2] * 4),
        # a likeness with a comma before the structure: a bridge (the doorway) and an arch
        ("Make it look like a doorway, an arch.", ["arch"], None),
    ],
)
def test_what_a_list_or_a_likeness_says_of_its_parts(command, shapes, heights):
    _built_as_said(command, shapes, heights)


def test_not_touching_an_edge_keeps_away_from_it_and_instead_of_takes_back():
    # "NOT touching the front edge": the cubes a gap apart, the grid at the front edge
    r = plan("- grid 2 x 5\n- one layer\n- NOT touching the front edge")
    assert r.status == "success", r.notes
    assert r.spec.structures[0].region == "back" and len(r.layout.objects) == 10
    # "base of 5 this time instead of 4": 'instead' was left over (partial)
    r = plan("Kaizen on yesterday's pyramid: base of 5 this time instead of 4.")
    assert r.status == "success" and r.spec.structures[0].length == 5
    assert any("'instead of 4' as the size it replaces" in n for n in r.notes)
    # "a wall instead of a tower": both were built
    r = plan("a wall instead of a tower")
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["wall"]


def test_a_size_in_cubes_by_a_size_in_a_unit():
    # "3 cubes by 20 cm": the unit said last was taken for both (a 1 by 4 grid), silently
    r = plan("Grid 3 cubes by 20 cm, one layer.")
    assert r.status == "success", r.notes
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (3, 4)
    # a unit said last still counts for a number said bare before it
    r = plan("a slab 20 by 30 cm")
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (4, 6)


def test_two_sized_structures_one_each_place():
    # "two 3 by 3 slabs: one on the left, one on the right": three slabs, silently
    r = plan("two 3 by 3 slabs: one on the left, one on the right")
    assert r.status == "success", r.notes
    assert [(s.shape, s.region, s.length, s.width) for s in r.spec.structures] == [
        ("grid", "left", 3, 3), ("grid", "right", 3, 3)
    ]


def test_a_margin_from_the_edges_is_reported_and_paths_lead_up_to():
    # "10 cm away from every table edge": a table was built, and 10 cm the staircase's height
    r = plan("Put a 3-step staircase somewhere, but stay at least 10 cm away from every table "
             "edge.")
    assert r.status == "partial" and [s.shape for s in r.spec.structures] == ["staircase"]
    assert r.spec.structures[0].height_m is None
    assert any("not a margin from its edges" in n for n in r.notes)
    # "running up to a block", "climbed up to a tower": no relation, silently
    for command in ("a row of four cubes running up to a block two by two by two",
                    "A staircase of four steps climbed up to a tower of five cubes."):  # fmt: skip
        r = plan(command)
        assert r.status == "success", r.notes
        assert [x.kind for x in r.spec.relations] == ["next_to"], command
    # "climbing up to the back" stays the way it climbs
    assert plan("a staircase climbing up to the back").spec.structures[0].axis == "x"
    # "a square closed, four on four": a 4 by 4 slab, silently
    r = plan("I need a square closed, four on four, height one cube.")
    assert [(s.shape, s.length, s.width) for s in r.spec.structures] == [("enclosure", 4, 4)]


def test_two_sizes_said_of_the_same_structure_are_reported():
    # "(same tower)": two towers were built, silently (the note on 'case' was all there was)
    r = plan("Case: tower height = 3 cubes AND tower height = 6 cubes (same tower).")
    assert r.status == "partial"
    assert any("'(same tower)'" in n and "say the one size meant" in n for n in r.notes)


def test_each_side_of_it_said_without_on():
    # "a tower of 2 each side of it": the 2 went to the tower's sides (partial), no relation
    r = plan("arch pls. then a tower of 2 each side of it")
    assert r.status == "success", r.notes
    assert [x.kind for x in r.spec.relations] == ["next_to"]
    assert len(r.layout.objects) == len(plan("an arch").layout.objects) + 4  # 2 on each side


def test_a_recounted_sentence_with_no_in_it_is_not_built():
    # "no" is no count: the recounting sentence was kept and the bridge reported as excluded
    r = plan("Last time there was no room for the bridge. Please build a bridge.")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == ["bridge"]
    assert any("what happened before" in n for n in r.notes)


def test_a_correction_that_says_instead_of_the_structure_replaces_it():
    # "Actually, a wall of 4 instead of the tower": the correction and the take-back both acted
    r = plan("a tower of 3. Actually, a wall of 4 instead of the tower")
    assert r.status == "success", r.notes
    assert [(s.shape, s.length) for s in r.spec.structures] == [("wall", 4)]


def _extent_in_parts(r, axis):
    lo = min(o.position[axis] - o.size[axis] / 2 for o in r.layout.objects)
    hi = max(o.position[axis] + o.size[axis] / 2 for o in r.layout.objects)
    return round((hi - lo) / 0.05)


def test_a_bridge_said_long_has_its_pillars_that_far_apart():
    # "a bridge whose deck is 4 cubes long": the 4 was ignored (no such parameter)
    for command, long in (("a bridge 4 cubes long", 4),
                          ("a bridge 3 cubes long, pillars 4 high", 3),
                          ("a bridge 7 long with 2 spans", 7)):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert max(_extent_in_parts(r, 0), _extent_in_parts(r, 1)) == long, command
    # a length no beam can span is an error that says so, not a default bridge
    r = plan("A bridge that is 25 cm long overall.")
    assert r.status == "failure" and "span" in r.error
    # the deck said long is its beams, one length: reported unless it is theirs
    r = plan("a bridge whose deck is 4 cubes long")
    assert r.status == "partial" and any("deck is its beams" in n for n in r.notes)
    assert plan("a bridge with a top 3 long and legs 2 high").status == "success"


def test_a_bridges_legs_said_after_a_dash_are_its_height():
    # "Brdige – legs 3": legs read as an L's arms, a 3-wide bridge
    for command in ("bridge – legs 3", "Job 5 – Brdige – legs 3 – beam acros top"):
        r = plan(command)
        assert r.status == "success", r.notes
        assert [(s.shape, s.height, s.width) for s in r.spec.structures] == [("bridge", 3, None)]


def test_the_middle_one_is_sized_like_the_left_and_right_ones():
    # "the middle one 3 tall": three default towers and three walls were built
    r = plan("three towers in a row: the middle one 3 tall, the left one 2 tall, the right one 1")
    assert r.status == "success", r.notes
    by_y = sorted(_columns(r).items(), key=lambda kv: kv[0][1])  # right (small y) to left
    assert [h for _, h in by_y] == [1, 3, 2]


def test_one_on_each_side_after_a_count_is_that_many_not_one_more():
    # "a wall with two towers, one on each side": a third tower, one cube high, silently
    r = _built_as_said("a wall with two towers of 3, one on each side", ["wall", "tower"], None)
    assert sorted(_columns(r).values()) == [2, 2, 2, 2, 3, 3]
    # "four towers around it (, one on each side)": a ring of 40 parts around the block, or
    # seven towers
    for command in ("a 2x2 block with four 2-cube towers around it, one on each side",
                    "a 2x2 block with four 2-cube towers, one on each side",
                    "four towers of 2 around a 2x2 block"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        cols = _columns(r)
        assert sorted(cols.values()) == [1, 1, 1, 1, 2, 2, 2, 2], command
        block = [xy for xy, h in cols.items() if h == 1]
        cx = sum(x for x, _ in block) / 4
        cy = sum(y for _, y in block) / 4
        sides = {("x+" if x > cx else "x-") if abs(x - cx) > abs(y - cy) else
                 ("y+" if y > cy else "y-") for (x, y), h in cols.items() if h == 2}  # fmt: skip
        assert sides == {"x+", "x-", "y+", "y-"}, command


def test_a_line_too_long_across_the_table_with_its_neighbours_is_turned():
    # "a row of 5 with a tower on each side": 0.55 m along y, a failure
    r = plan("a row of 5 with a tower on each side")
    assert r.status == "success", r.notes
    assert sorted(_columns(r).values()) == [1, 1, 1, 1, 1, 3, 3]
    assert _extent_in_parts(r, 0) > _extent_in_parts(r, 1)  # along x


def test_a_flat_shape_said_to_stand_up_is_a_wall():
    # "a 2 by 3 rectangle … standing up on its edge", "a vertical 3x2 slab": flat, silently
    for command, long, high in (
        ("a 2 by 3 rectangle, one cube thick, standing up on its edge", 3, 2),
        ("a vertical 3x2 slab", 3, 2),
        ("a 3 by 2 panel standing upright", 3, 2),
        ("a 2x4 panel standing on its end", 2, 4),
    ):
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", long, high)]
        assert sorted(set(_columns(r).values())) == [high], command
    # an upright word of another structure stays its own
    r = plan("a 3x3 slab with a vertical tower on it")
    assert [s.shape for s in r.spec.structures] == ["grid", "tower"]


def test_a_value_said_to_be_better_or_enough_corrects_the_one_before():
    for command, shape, key, value in (
        ("a staircase, 5 steps. 3 steps would be better", "staircase", "steps", 3),
        ("a tower of 6. hmm, 4 is enough", "tower", "height", 4),
        ("a tower of 5, 3 would be fine", "tower", "height", 3),
    ):
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [(s.shape, getattr(s, key)) for s in r.spec.structures] == [(shape, value)]
    # the same value agreed to again is no correction
    r = plan("a 4 by 4 slab. yes, 4 by 4 is fine")
    assert [(s.length, s.width) for s in r.spec.structures] == [(4, 4)]


def test_a_heading_that_names_the_thing_is_no_structure_of_its_own():
    # "Goods shed: a 3 by 4 enclosure": the shed was a table beside the enclosure (partial)
    r = plan("Goods shed: a 3 by 4 enclosure, two cubes high.")
    assert r.status == "success", r.notes
    assert [(s.shape, s.length, s.width, s.height) for s in r.spec.structures] == [
        ("enclosure", 3, 4, 2)
    ]
    # "Signal box: …": its name is no material word left unused
    r = plan("Signal box: a 2x2x2 block and, right next to it on its left, a tower of 3.")
    assert r.status == "success", r.notes
    assert [s.shape for s in r.spec.structures] == ["block", "tower"]
    # a heading that is a request, or says something of the shape, stays read
    r = plan("A hollow enclosure: outer footprint 6 by 4, walls one cube thick and two courses "
             "high.")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["enclosure"]
    r = plan("Build me a bridge: two towers with 3 floors, between them 5 cm, and on top a beam "
             "of 15 cm.")  # fmt: skip
    assert r.status == "success" and [s.shape for s in r.spec.structures] == ["bridge"]


def test_numbered_steps_are_steps_and_their_labels_no_numbers():
    # "2." was read as a count, "(2)" as a second size of the first tower, "Step" as a staircase
    r = _built_as_said("1. a row of 3 cubes 2. a row of 2 cubes on top of it 3. one cube on "
                       "top of that", ["row", "row", "tower"], None)  # fmt: skip
    assert _level_sizes(r.layout) in ([(1, 3), (1, 2), (1, 1)], [(3, 1), (2, 1), (1, 1)])
    r = _built_as_said("(1) tower of 4 at x 0.3 y 0.5 (2) tower of 2 at x 0.6 y 0.1",
                       ["tower", "tower"], [2, 4])  # fmt: skip
    assert [(s.at_x, s.at_y) for s in r.spec.structures] == [(0.3, 0.5), (0.6, 0.1)]
    _built_as_said("1 - enclosure 5x4, one high. 2 - tower of 3 inside it.",
                   ["enclosure", "tower"], None)  # fmt: skip
    _built_as_said("Step one, build a 5-step staircase. Step two, put a tower of 2 on the right "
                   "of it.", ["staircase", "tower"], None)  # fmt: skip
    r = _built_as_said("Steps -- 1: tower 3 front left; 2: tower 3 front right; 3: tower 3 back "
                       "left; 4: tower 3 back right.", ["tower"] * 4, [3, 3, 3, 3])  # fmt: skip
    assert [s.region for s in r.spec.structures] == [
        "front left", "front right", "back left", "back right"
    ]
    r = _built_as_said("Steps: a) 3x3 patch in the centre b) one cube on each of its four "
                       "corners", ["grid", "tower"], None)  # fmt: skip
    assert len(r.layout.objects) == 13
    # a sentence that ends in a number is no label
    _built_as_said("1. a tower of 2. then a wall of 4", ["tower", "wall"], None)


def test_a_crosss_arms_said_apart_from_it_are_its_arms():
    # "plus sign? Arms of one cube each": one cube; "arms 2 cubes out from the centre cube": a
    # cross 2 long (partial)
    for command, long in (("Can it do a plus sign? Arms of one cube each.", 3),
                          ("cross shape, arms 2 cubes out from the centre cube", 5)):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [(s.shape, s.length) for s in r.spec.structures] == [("cross", long)]


def test_a_quarter_metre_and_a_total_said_together():
    # "a quarter metre long": 6 cubes; "two equal towers that together use 10 cubes": 10 each
    r = plan("A wall a quarter metre long, 2 high.")
    assert r.status == "success" and r.spec.structures[0].length_m == 0.25
    r = _built_as_said("Two equal towers that together use 10 cubes.", ["tower", "tower"], [5, 5])
    _built_as_said("three towers which together have 12 cubes", ["tower"] * 3, [4, 4, 4])


def test_slang_a_spelling_by_ear_and_arms_in_millimetres():
    # "6 my bad" was no correction; "back rite corner" no place; "fr" a material word
    r = plan("tower of 4 wait no 6 my bad")
    assert r.status == "success" and r.spec.structures[0].height == 6
    r = plan("put a 3 stack in the back rite corner")
    assert r.status == "success" and r.spec.structures[0].region == "back right"
    assert plan("block 2 by 2 by 3 fr fr").status == "success"
    # "arms 100 mm each": a cross of 201 (an error)
    r = plan("Cross: arms 100 mm each from the centre cube, single course.")
    assert r.status == "success", r.notes
    assert [(s.shape, s.length) for s in r.spec.structures] == [("cross", 5)]


def test_loose_words_of_place_and_build():
    # "far apart": "far" was the back of the table and the gap one cube
    r = _built_as_said("two towers of 3 far apart", ["tower", "tower"], [3, 3])
    assert r.spec.gap_m == pytest.approx(0.15) and r.spec.structures[0].region is None
    # "a 3 by 3 footing and a 1-brick pier of 3 courses in the centre of it": a 3x3x3 block
    r = _built_as_said("Lay a 3 by 3 footing and a 1-brick pier of 3 courses in the centre of "
                       "it.", ["grid", "tower"], None)  # fmt: skip
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    assert sorted(_columns(r).values()) == [1] * 8 + [4]
    # "on each of its two short ends": beside the slab, not on it
    r = plan("Sketch: a flat 2x5 slab with a tower of 2 standing on each of its two short ends.")
    assert r.status == "success" and [x.kind for x in r.spec.relations] == ["on_top_of"]
    assert len(r.layout.objects) == 14
    assert max(o.position[2] for o in r.layout.objects) == pytest.approx(0.125)  # on its top


def test_corrections_said_with_a_dash_or_a_new_number():
    # "stacked? no -- two 3x3 layers side by side": a 3x3x2 block and a third layer
    r = _built_as_said("Two 3x3 layers stacked? no -- two 3x3 layers side by side, each one "
                       "cube thick.", ["grid", "grid"], [1] * 18)  # fmt: skip
    # "two 3x3 layers side by side" alone: one 3 by 3 slab
    _built_as_said("two 3x3 layers side by side", ["grid", "grid"], [1] * 18)
    # "…, so let's do seven": ten built, the seven reported unused
    r = plan("Volunteer asked for a tower of ten -- that's too tall for our demo, so let's do "
             "seven.")  # fmt: skip
    assert [(s.shape, s.height) for s in r.spec.structures] == [("tower", 7)]
    # a structure said after "let's do" is one more, not a correction
    r = plan("a tower of 3, let's do a wall next to it")
    assert [s.shape for s in r.spec.structures] == ["tower", "wall"]


def test_a_pyramids_top_said_as_one_cube_is_its_own():
    # "top is a single cube": a loose cube beside the pyramid
    r = _built_as_said("AC: pyramid, 3-D, 3x3 base, top is a single cube.", ["pyramid"], None)
    assert _level_sizes(r.layout) == [(3, 3), (2, 2), (1, 1)]


def test_a_small_wall_said_wide_and_a_pier_said_square():
    # "a little house wall: 5 wide, 3 tall": a 3 by 5 block, 45 parts, silently
    r = plan("Next up, a little house wall: 5 wide, 3 tall, at the back so everyone can see.")
    assert r.status in ("success", "partial")
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", 5, 3)]
    # a long wall said 2 wide stays two parts thick
    r = plan("a long wall 2 wide")
    assert [(s.shape, s.width) for s in r.spec.structures] == [("block", 2)]
    # "a pier 2 bricks square and 3 courses up": a tower of 2 and a 3-high block
    r = _built_as_said("Build a pier 2 bricks square and 3 courses up.", ["block"], [3, 3, 3, 3])


def test_a_corner_cube_a_change_line_and_one_more_cube_beside_it():
    # "on its back-left cube": the table's back left corner, silently
    r = plan("Step 1 block 2x3x1. Step 2 nothing. Step 3 put a tower of 3 on its back-left cube.")
    assert r.status == "success", r.notes
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    # "2. Change: 3 high instead.": no structure named there (partial)
    r = plan("1. Build wall, 6 long, 2 high. 2. Change: 3 high instead.")
    assert r.status == "success", r.notes
    assert [(s.shape, s.length, s.height) for s in r.spec.structures] == [("wall", 6, 3)]
    # "put one more cube beside it on the table": nothing beside the tower (partial)
    r = _built_as_said("Build a tower of three, and put one more cube beside it on the table.",
                       ["tower", "tower"], [1, 3])  # fmt: skip
    assert [x.kind for x in r.spec.relations] == ["next_to"]


def test_a_side_named_by_its_size_runs_the_way_said():
    # "with the 3 running left-right": the block turned so its 2 ran left to right, silently
    r = plan("On the drawing there's a block 3 wide, 2 deep, 2 high, with the 3 running "
             "left-right.")
    assert r.status == "success", r.notes
    assert (_extent_in_parts(r, 0), _extent_in_parts(r, 1), _extent_in_parts(r, 2)) == (2, 3, 2)
    r = plan("a 4 by 2 slab with the 4 running front to back")
    assert r.status == "success", r.notes
    assert (_extent_in_parts(r, 0), _extent_in_parts(r, 1)) == (4, 2)
    # a size the structure has no side of is reported, not taken
    assert plan("a row of 5 with the 3 running left to right").status == "partial"


def test_a_structure_from_a_run_before_moved_or_its_sides_swapped():
    centre_y = plan("a tower of 3").layout.objects[0].position[1]
    # "this time put the same tower at the back": a second tower of 4 there, silently
    r = _built_as_said("Last run you built the tower of 4 at the front; this time put the same "
                       "tower at the back.", ["tower"], [4])  # fmt: skip
    assert r.spec.structures[0].region == "back"
    # "Redo it but on the right": the right was reported, the tower left on the left
    r = _built_as_said("Run 12 log: 'tower 3 @ left'. Redo it but on the right.", ["tower"], [3])
    assert r.layout.objects[0].position[1] < centre_y
    # "Swap sides this time": refused
    r = _built_as_said("Like the last job: a tower of 3 to the left of a wall of 4 by 2. Swap "
                       "sides this time.", ["tower", "wall"], None)  # fmt: skip
    cols = _columns(r)
    tower_y = [y for (_, y), n in cols.items() if n == 3]
    wall_y = [y for (_, y), n in cols.items() if n == 2]
    assert len(tower_y) == 1 and tower_y[0] < min(wall_y)  # the tower on the wall's right now
    r = _built_as_said("a tower at the front and a wall at the back - switch places please",
                       ["tower", "wall"], None)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["back", "front"]
    # "Same as before, …": "before" was reported unused
    r = _built_as_said("Same as before, a 3x3 grid, but move it to the back left.", ["grid"], None)
    assert r.spec.structures[0].region == "back left"


def test_a_recounted_structure_changed_is_that_structure():
    # "Previous bridge had 2-high legs; raise the legs to 3": a bridge and a tower of 2
    r = _built_as_said("Previous bridge had 2-high legs; raise the legs to 3.", ["bridge"], None)
    assert r.spec.structures[0].height == 3
    # "change it to base 3": the base 5 kept, 'change' ignored as no content, silently
    r = _built_as_said("a pyramid with base 5, change it to base 3, 3-D", ["pyramid"], None)
    assert len(r.layout.objects) == 9 + 4 + 1
    r = _built_as_said("The last pyramid had base 5; rebuild it with base 3, 3-D this time.",
                       ["pyramid"], None)  # fmt: skip
    assert len(r.layout.objects) == 9 + 4 + 1


def test_a_bricklayers_course_skin_and_runs_at_right_angles():
    # "Stretcher course of seven": no structure recognised
    r = _built_as_said("Stretcher course of seven, single skin, along the front.", ["row"], None)
    assert len(r.layout.objects) == 7
    r = plan("Lay a course of 4 and then another course of 4 on top, straight up -- no offset.")
    assert r.status == "success", r.notes
    assert _level_sizes(r.layout) in ([(1, 4), (1, 4)], [(4, 1), (4, 1)])
    # "double skin": two bricks thick
    r = _built_as_said("a double skin wall 4 long 3 high", ["block"], None)
    assert sorted(_level_sizes(r.layout)[0]) == [2, 4]
    # "two runs meeting at right angles, 5 and 4 bricks": a row of 2
    r = _built_as_said("Corner: two runs meeting at right angles, 5 and 4 bricks, one course.",
                       ["l_shape"], None)  # fmt: skip
    assert len(r.layout.objects) == 5 + 4 - 1
    r = _built_as_said("two walls at right angles, 4 and 3 long, 2 high", ["l_shape"], None)
    assert len(r.layout.objects) == 2 * (4 + 3 - 1)


def test_a_tickets_key_and_lettered_sizes_are_no_counts():
    # "SDI-101": a tower of 101 levels (failure); "110 Block." a row of 110
    r = _built_as_said("SDI-101 [Story] Build tower. AC: single column, height = 6 cubes.",
                       ["tower"], [6])  # fmt: skip
    r = _built_as_said("SDI-110 Block. Dimensions (cubes): L3 x W2 x H2.", ["block"], None)
    assert sorted(_level_sizes(r.layout)[0]) == [2, 3] and len(_level_sizes(r.layout)) == 2
    # "U-shape: …": the heading's "shape:" was read as "a", and nothing recognised
    r = _built_as_said("SDI-112 U-shape: width 4, arm depth 3, opening faces right.",
                       ["u_shape"], None)  # fmt: skip
    # "4 (x) by 2 (y) by 1 (z)": each value along its axis (a count of 4 was built)
    r = _built_as_said("Assemble a solid cuboid 4 (x) by 2 (y) by 1 (z).", ["grid"], None)
    assert (_extent_in_parts(r, 0), _extent_in_parts(r, 1)) == (4, 2)
    # a structure's name with a number stays the structure
    _built_as_said("TOWER-3 please", ["tower"], [3])


def test_radio_procedure_words_are_no_structure():
    # "Robot, this is Base.": a 3 by 3 platform beside the tower
    _built_as_said("Robot, this is Base. Build tower, height four. Over.", ["tower"], [4])
    # "Negative, height two": a correction; "I say again, …": a repeat (a second tower)
    _built_as_said("Robot, Base. Tower, height six. Negative, height two. Over.", ["tower"], [2])
    r = _built_as_said("Robot from Base: bridge, pillars two high, over. I say again, pillars two "
                       "high. Out.", ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 2
    # "x zero-point-three": x = 0 (failure)
    r = _built_as_said("Robot, Base. Tower height five at position x zero-point-three, y "
                       "zero-point-four-five. Over.", ["tower"], [5])  # fmt: skip
    assert r.layout.objects[0].position[:2] == pytest.approx([0.3, 0.45])
    # "final answer: 5" after a size: that size (the marker's pattern once lost it)
    _built_as_said("a tower 3 high. final answer: 5", ["tower"], [5])
    # "spread out", "take it back out": no radio "out"
    _built_as_said("rows: 3 of them, 5 cubes each, spaced out", ["row", "row", "row"], None)


def test_what_a_carpenter_or_a_palletiser_says_is_read():
    # "a header across the tops of them": one tower 8 high, silently
    r = _built_as_said("Put up two posts four high and lay a header across the tops of them.",
                       ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 4
    # "a panel, flat on the bench": built standing up, silently
    r = _built_as_said("A panel, flat on the bench: two blocks by five.", ["grid"], None)
    assert len(_level_sizes(r.layout)) == 1 and len(r.layout.objects) == 10
    # "flat on the floor": a grid of the floor beside the L, silently
    _built_as_said("Make the letter L with your blocks: 3 down and 3 across, flat on the floor!",
                   ["l_shape"], None)  # fmt: skip
    # "cases": the palletiser's parts (partial); "scratch that, 3 cases": an error
    _built_as_said("Put one row of 5 cases along the front edge of the table.", ["grid"], None)
    _built_as_said("Single stack of 4 cases — scratch that, 3 cases.", ["tower"], [3])
    # "stack a solid lump …": a default tower beside the block
    _built_as_said("Stack a solid lump three by three by two, reckon that'll do.", ["block"],
                   [2] * 9)  # fmt: skip
    # "a couple high": a count of two parts, dropped (height 1)
    _built_as_said("Could you knock up a wee wall, five long and a couple high?", ["wall"],
                   [2] * 5)  # fmt: skip


def test_likenesses_questions_and_apposition_name_one_structure():
    # "one of those Egyptian pyramids, a proper square one, five wide at the base": a slab
    r = _built_as_said("Imagine one of those Egyptian pyramids, a proper square one, five wide at "
                       "the base.", ["pyramid"], None)  # fmt: skip
    assert _level_sizes(r.layout)[0] == (5, 5)
    # "like soldiers standing in a line": a second row, silently
    _built_as_said("A row of five blocks, like soldiers standing in a line across the front.",
                   ["row"], None)  # fmt: skip
    # "Should the wall be 2 high? Yes, …": the question's wall built as well, silently
    _built_as_said("Should the wall be 2 high? Yes, let's do a wall 6 long and 2 high.", ["wall"],
                   [2] * 6)  # fmt: skip
    # "a tall tower … and a short one … — say five and two": 6 and 5, silently
    _built_as_said("A tall tower in the back left corner and a short one in the front right — "
                   "say five and two.", ["tower", "tower"], [2, 5])  # fmt: skip
    # "Fancy a pyramid? Square base of three": a pyramid and a grid
    r = _built_as_said("Fancy a pyramid? Square base of three, properly 3D, none of that flat "
                       "nonsense.", ["pyramid"], None)  # fmt: skip
    assert len(r.layout.objects) == 9 + 4 + 1
    # "Make a small one": a castle one part long (failure)
    _built_as_said("What's a castle look like with these cubes? Make a small one.", ["castle"],
                   None)  # fmt: skip
    # "a plus sign — a cross — 1 block in the middle and 1 on each side": two crosses
    r = _built_as_said("Now a plus sign — a cross — 1 block in the middle and 1 on each side!",
                       ["cross"], None)  # fmt: skip
    assert len(r.layout.objects) == 5
    # a list of the same family stays a list
    _built_as_said("a tower, a tower, and a wall", ["tower", "tower", "wall"], None)
    # "each arm two blocks out from the middle": read as a gap, arms of 1
    r = _built_as_said("A plus sign, like on a Swiss flag, laid flat, each arm two blocks out "
                       "from the middle.", ["cross"], None)  # fmt: skip
    assert len(r.layout.objects) == 9


def test_a_ring_round_a_space_an_empty_middle_and_a_cad_extrusion():
    # "around an empty 3x3 centre": a 3 by 3 ring
    r = _built_as_said("Wrap a ring of cases around an empty 3x3 centre, one tier.",
                       ["enclosure"], None)  # fmt: skip
    assert _level_sizes(r.layout) == [(5, 5)] and len(r.layout.objects) == 16
    # a patch said inside a wall is a patch of its own
    assert [s.shape for s in plan("a cube wall enclosing a 2x2 patch").spec.structures].count(
        "grid"
    ) == 1
    # "hollow in the middle", "empty in the middle": a solid box or slab
    _built_as_said("Frame me a box — four by four outside, one course high, hollow in the "
                   "middle.", ["enclosure"], None)  # fmt: skip
    _built_as_said("a 4x4 square, empty in the middle", ["enclosure"], None)
    # "Materials: 5 cm cubes.": a stray cube; "ring / fence thing": a wall 5 high
    _built_as_said("Materials: 5 cm cubes. Procedure: build a hollow square perimeter, 5 x 5 "
                   "cubes external, height 2.", ["enclosure"], None)  # fmt: skip
    r = _built_as_said("ring / fence thing ⭕ 5x5, 1 high", ["enclosure"], None)
    assert len(r.layout.objects) == 16
    # CAD: "extrude 1", "depth 2 units", "T profile: flange 5, web 3"
    r = _built_as_said("Boss-extrude a solid 2x3 footprint, depth 2 units.", ["block"], None)
    assert len(r.layout.objects) == 12
    r = _built_as_said("T profile: flange 5 cubes, web 3 cubes, extrude 1 unit.", ["t_shape"],
                       None)  # fmt: skip
    assert len(r.layout.objects) in (7, 8)  # a bar of 5 and a stem of 3 (with or without the joint)
    # "on top of its middle cube, a tower of 2": beside the row
    r = _built_as_said("Can you build a row of 5 and, on top of its middle cube, a tower of 2?",
                       ["row", "tower"], None)  # fmt: skip
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    # "3 stacks in a line going front to back": left to right, silently
    r = _built_as_said("Put 3 stacks in a line going front to back, heights 1, 2 and 3 going "
                       "back.", ["tower"] * 3, [1, 2, 3])  # fmt: skip
    assert len({round(o.position[1], 3) for o in r.layout.objects}) == 1


def test_one_of_a_line_picked_by_its_place_or_sized_by_another():
    # "except the third from the left which should be 4": four towers of 2
    r = plan("Four display towers in a line left to right, all 2 high, except the third from the "
             "left which should be 4.")  # fmt: skip
    assert r.status == "success", r.notes
    by_y = [n for _, n in sorted((y, n) for (_, y), n in _columns(r).items())]  # right to left
    assert by_y == [2, 4, 2, 2]  # the third from the left is the second from the right
    # "make the second from the front height four": ignored
    r = plan("Robot, Base. Three towers in a line front to back, all height two. Then make the "
             "second from the front height four. Over.")  # fmt: skip
    assert r.status == "success", r.notes
    assert [n for _, n in sorted((x, n) for (x, _), n in _columns(r).items())] == [2, 4, 2]
    # "the second one should be 4 high": all three 4 high
    _built_as_said("three towers of 2 in a row; the second one should be 4 high",
                   ["tower"] * 3, [2, 2, 4])  # fmt: skip
    # "twice as long as it is high, and 3 high": 4 long (the default)
    _built_as_said("Can you make a wall twice as long as it is high, and 3 high?", ["wall"],
                   [3] * 6)  # fmt: skip
    # "the one on the left twice as tall as the one on the right, which is 3 storeys": two of 3
    r = _built_as_said("Picture two skyscrapers, the one on the left twice as tall as the one on "
                       "the right, which is 3 storeys.", ["tower", "tower"], [3, 6])  # fmt: skip
    left = max(_columns(r).items(), key=lambda kv: kv[0][1])
    assert left[1] == 6
    _built_as_said("Two towers: the second is twice as tall as the first, and the first is 3.",
                   ["tower", "tower"], [3, 6])  # fmt: skip
    # "Graphic wall: 5 long, 4 high, and a plinth …": the heading's wall was dropped
    r = plan("Graphic wall: 5 long, 4 high, and a 2-high plinth 1x1 in front of it.")
    assert [s.shape for s in r.spec.structures] == ["wall", "block"]
    assert sorted(_columns(r).values()) == [2, 4, 4, 4, 4, 4]


def test_a_structure_said_again_is_one_structure():
    # a restatement in a sentence of its own built a second one, silently
    _built_as_said("Make a row of 5. Five cubes side by side in a line, left to right, I mean.",
                   ["row"], None)  # fmt: skip
    r = _built_as_said("Put a tower on the left. On the left side, 3 cubes, a tower of 3 on the "
                       "left.", ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "left"
    _built_as_said("Make a flat square, 3 by 3. A 3x3 layer, one cube thick, flat on the table.",
                   ["grid"], None)  # fmt: skip
    _built_as_said("A tower of 6. No wait, 5. Five. A tower of five cubes.", ["tower"], [5])
    # two said differently stay two
    _built_as_said("A tower of 3. A tower of 4.", ["tower", "tower"], [3, 4])
    _built_as_said("a tower of 3 at the front. a tower of 3 at the back.", ["tower", "tower"],
                   [3, 3])  # fmt: skip
    # "The tower shall stand on the left side.": the place of the tower said before (dropped)
    r = _built_as_said("Please build me a tower from 5 cubes. The tower shall stand on the left "
                       "side.", ["tower"], [5])  # fmt: skip
    assert r.spec.structures[0].region == "left"
    # "make tower A 5 high instead": a second tower
    _built_as_said("Build tower A, 3 high. Now make tower A 5 high instead.", ["tower"], [5])


def test_each_leg_sized_and_a_stacked_footprint():
    # "a table with 4 legs, each 2 cubes tall": a default table, silently
    for command in ("a table with 4 legs, each 2 cubes tall.",
                    "Task 14: Build a table with 4 legs. Each leg is 2 cubes tall."):  # fmt: skip
        r = _built_as_said(command, ["canopy"], None)
        assert r.spec.structures[0].height == 2
    # a size said for each that no structure named can take is reported
    assert plan("a pyramid with base 3, each 2 high").status == "partial"
    # "Stack a 3x3 footprint two high, solid, …": a second block
    r = _built_as_said("Stack a 3x3 footprint two high, solid, in the back right corner.",
                       ["block"], [2] * 9)  # fmt: skip
    # "stack a 2 by 2 tower, 4 levels high": a slab and a tower
    _built_as_said("Can the robot stack a 2 by 2 tower, 4 levels high?", ["block"], [4] * 4)


def test_compass_words_with_north_at_the_back_unless_said():
    # "north-west corner", "the southern edge", "to the north of": ignored (partial)
    r = _built_as_said("Compass convention: north is the far side of the table. Place a 4-cube "
                       "tower in the north-west corner.", ["tower"], [4])  # fmt: skip
    assert r.spec.structures[0].region == "back left"
    r = _built_as_said("With north at the back: build a wall 6 long running east-west, 2 high, on "
                       "the southern edge.", ["wall"], [2] * 6)  # fmt: skip
    assert _extent_in_parts(r, 1) == 6 and r.spec.structures[0].region == "front"
    r = _built_as_said("Far side is north. Tower of 5 to the north of a tower of 2.",
                       ["tower", "tower"], [2, 5])  # fmt: skip
    cols = _columns(r)
    assert max(cols, key=lambda xy: xy[0]) == max(cols, key=lambda xy: cols[xy])  # 5 behind
    # with no convention said, north is the back; said otherwise, the convention goes
    assert plan("a tower in the north east corner").spec.structures[0].region == "back right"
    r = plan("North is the near side. A tower in the north-east corner.")
    assert r.spec.structures[0].region == "front left"


def test_a_beam_said_another_way_and_arms_said_as_legs():
    # "joined at their tops by a beam": the beam left unused (two bare towers)
    r = _built_as_said("two towers of three cubes each, joined at their tops by a beam",
                       ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 3
    _built_as_said("The Structure shall comprise two (2) towers of three (3) cubes each, "
                   "connected at their tops by a spanning member.", ["bridge"], None)  # fmt: skip
    _built_as_said("two posts 2 high and a crossbar on top", ["bridge"], None)
    # "one leg 5 cubes, the other leg 3 cubes": an L and two towers
    r = _built_as_said("Please build an L-form: one leg 5 cubes, the other leg 3 cubes.",
                       ["l_shape"], None)  # fmt: skip
    assert len(r.layout.objects) == 5 + 3 - 1
    # "5 across and 3 down": a T with a stem of 1
    r = _built_as_said("Could it make a T, like the letter, 5 across and 3 down?", ["t_shape"],
                       None)  # fmt: skip
    assert len(r.layout.objects) in (7, 8)


def test_an_hmi_line_of_keyed_fields_is_read_by_its_keys():
    # "BUILD: BRIDGE PILLAR_H=3 SPAN=2": a bridge 4 high with 3 spans, silently
    r = _built_as_said("BUILD: BRIDGE PILLAR_H=3 SPAN=2", ["bridge"], None)
    assert r.spec.structures[0].height == 3
    assert _extent_in_parts(r, 2) == 4  # pillars of 3 and the beam
    # "BUILD: TABLE LEGS=4 LEG_H=2": a default table and a tower of 2
    r = _built_as_said("BUILD: TABLE LEGS=4 LEG_H=2", ["canopy"], None)
    assert r.spec.structures[0].height == 2
    # "T=1" a wall's thickness (a T of one part, a failure); "POS=BACK_LEFT" its place
    r = _built_as_said("BUILD: WALL L=6 H=3 T=1", ["wall"], [3] * 6)
    r = _built_as_said("BUILD: TOWER H=4 POS=BACK_LEFT", ["tower"], [4])
    assert r.spec.structures[0].region == "back left"
    r = _built_as_said("BUILD: ROW N=5 DIR=LEFT_RIGHT", ["row"], [1] * 5)
    assert _extent_in_parts(r, 1) == 5
    # a ticket's title and notes are words to read, not words left over
    _built_as_said("SDI-103 | Type: Task | Title: Flat grid 2x6 | Notes: one layer only",
                   ["grid"], [1] * 12)  # fmt: skip


def test_three_side_by_side_sized_by_their_places_or_listed_each_with_its_unit():
    # "the middle one 3 high" beside "side by side" was read as every tower 2 high
    for command in ("three towers side by side, the left one 2 high, the middle one 3 high, "
                    "the right one 1 high",
                    "three towers side by side from left to right, 2 high, 3 high and 1 high",
                    "middle block 3 high, left block 2 high, right block 1 high"):  # fmt: skip
        r = _built_as_said(command, ["tower"] * 3, [1, 2, 3])
        by_y = [h for (_, _), h in sorted(_columns(r).items(), key=lambda kv: -kv[0][1])]
        assert by_y == [2, 3, 1], command  # left (+y) to right
    # a podium of blocks: no longer three blocks and a default staircase, silently
    r = plan("Make a podium for the winners: middle block 3 high, left block 2 high, right "
             "block 1 high.")  # fmt: skip
    assert r.status != "success" or len(r.spec.structures) == 3, r.notes


def test_a_post_rising_from_a_corner_a_deck_on_supports_and_a_renamed_structure():
    # "a 3-cube post rising from one corner of it": set beside the base, silently
    r = _built_as_said("Build a stand for a phone: a 2x2 base, 1 high, with a 3-cube post "
                       "rising from one corner of it.", ["grid", "tower"], None)  # fmt: skip
    assert sorted(_columns(r).values()) == [1, 1, 1, 4]
    # "two supports, three high, and a deck on top": a 3-high block; "walkway": not read
    r = _built_as_said("two supports, three high, and a deck on top", ["bridge"], None)
    assert r.spec.structures[0].height == 3
    r = _built_as_said("Like a footbridge over a stream — two supports, three high, and a "
                       "walkway on top.", ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 3
    # "— basically a wall": a slab and a second wall; "— a square ring": a wall and a floor
    _built_as_said("Extrude a rectangle 4 long x 1 thick to a height of 3 — basically a wall.",
                   ["wall"], [3] * 4)  # fmt: skip
    r = _built_as_said("Low barrier around a 3x3 floor area — a square ring, 1 high.",
                       ["enclosure"], [1] * 16)  # fmt: skip
    # a list of structures after a dash stays a list
    _built_as_said("a slab of 3x3 — a tower, 4 high", ["grid", "tower"], None)


def test_a_plus_said_cube_by_cube_stairs_to_the_rear_and_a_wall_along_an_edge():
    # "Put one cube in the middle and 1 cube on each side of it." built one cube, silently
    r = _built_as_said("Make a plus sign. Put one cube in the middle and 1 cube on each side "
                       "of it.", ["cross"], [1] * 5)  # fmt: skip
    # "ascend toward the rear": the back (it climbed to the left, silently)
    r = _built_as_said("the staircase shall have four (4) steps and shall ascend toward the "
                       "rear.", ["staircase"], None)  # fmt: skip
    cols = sorted(_columns(r).items())  # front (small x) to back
    assert [h for _, h in cols] == [1, 2, 3, 4]
    # "along left edge" with no article: it ran left to right, silently
    r = _built_as_said("Add wall along left edge. length 5. height 2.", ["wall"], [2] * 5)
    assert _extent_in_parts(r, 0) == 5
    # palletiser's and lab words: "tier" is a layer, "contiguous" touching, "Protocol 2" a name
    _built_as_said("Put a 2-high stack on top of a 2x2 base tier.", ["tower", "grid"], None)
    _built_as_said("Protocol 2. Arrange 8 cubes in a single straight line along the y-axis, "
                   "contiguous.", ["row"], [1] * 8)  # fmt: skip
    _built_as_said("Construct an arch spanning a clear gap of 150 mm.", ["arch"], None)


def test_posts_apart_by_their_centres_when_no_beam_spans_it_clear_and_a_bridge_said_as_a_beam():
    # "about 15 cm apart with a header beam": a 15 cm clear span no beam bridges (a failure)
    r = _built_as_said("Need two posts 3 high about 15 cm apart with a header beam across the "
                       "top of 'em.", ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].span == 2
    assert any("centres" in n for n in r.notes)
    # "two towers 10 cm apart with a beam across": no structure was read at all
    r = _built_as_said("two towers 10 cm apart with a beam across", ["bridge"], None)
    assert r.spec.structures[0].span == 2
    # "one bridge on top connecting both": a beam on the two towers (a bridge on one of them)
    for command in ("Make two towers, each of 3 cubes, and kindly put one bridge on top "
                    "connecting both.",
                    "two towers of 3 and a beam on top connecting them"):  # fmt: skip
        r = _built_as_said(command, ["bridge"], None)
        assert r.spec.structures[0].height == 3, command


def test_a_worksheets_first_and_second_a_cube_sized_three_ways_and_a_table_plate():
    # "Build two towers. The first has 2 cubes, the second has 4 cubes.": a row of 2 beside
    # two default towers
    r = _built_as_said("Build two towers. The first has 2 cubes, the second has 4 cubes. Put "
                       "the taller one on the right.", ["tower", "tower"], [2, 4])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: kv[0][1])
    assert by_y[0][1] == 4  # the taller on the right (smaller y)
    # "a cube that is 2 cubes long, 2 cubes wide and 2 cubes tall": a tower of 2
    r = _built_as_said("Build a cube that is 2 cubes long, 2 cubes wide and 2 cubes tall.",
                       ["block"], [2, 2, 2, 2])  # fmt: skip
    # "which goes from the front to the back": 'goes' was reported as not used
    r = _built_as_said("Please build me a row with 7 cubes, which goes from the front to the "
                       "back.", ["row"], [1] * 7)  # fmt: skip
    assert _extent_in_parts(r, 0) == 7
    # "four legs … and a plate on top": the table's own top, not a relation left unused
    r = _built_as_said("Please build me a table: four legs with height 3 cubes and a plate on "
                       "top.", ["canopy"], None)  # fmt: skip
    assert r.spec.structures[0].height == 3


def test_the_arms_of_a_letter_said_as_ways_and_a_metric_slab_one_cube_thick():
    # "4 going up and 2 going across": the 2 was dropped, silently
    r = _built_as_said("an L: 4 going up and 2 going across", ["l_shape"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (4, 2)
    # "2 more going across": beside the corner cube
    r = _built_as_said("Make the letter L: 4 cubes going up the page and 2 more going across.",
                       ["l_shape"], [1] * 6)  # fmt: skip
    r = _built_as_said("I see a letter L lying on the table, five along the long side and "
                       "three along the short.", ["l_shape"], [1] * 7)  # fmt: skip
    # a T's "3 across and 2 going down": the stem of 2 was dropped
    r = _built_as_said("Make the letter T with cubes: 3 across the top and 2 going down.",
                       ["t_shape"], None)  # fmt: skip
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (3, 2)
    # "30 cm long, 15 cm deep, one cube thick": read as one part long and wide (partial)
    _built_as_said("a slab 30 cm long, 15 cm deep, one cube thick", ["grid"], [1] * 18)
    # a form's fields: a thickness is a wall's only; a title names the structure
    _built_as_said("Slab requirements:\n- length: 30 cm (left to right)\n- depth: 15 cm\n"
                   "- thickness: one cube", ["grid"], [1] * 18)  # fmt: skip
    r = _built_as_said("REQ: slab 2x2x1 LOC: X 0.6 / Y 0.2", ["block"], [1] * 4)
    assert r.spec.structures[0].at_y == pytest.approx(0.2)


def test_layers_said_in_turn_a_tower_on_the_middle_of_a_row_and_towers_of_one_cube():
    # the issue's own example: "then one cube as the third level" was a relation cycle (error)
    r = _built_as_said("first a 3x3 layer, then a 2x2 layer on it, then one cube as the third "
                       "level", ["grid", "grid", "tower"], None)  # fmt: skip
    assert _level_sizes(r.layout) == [(3, 3), (2, 2), (1, 1)]
    # "then a 2 by 2 layer, finish with a single cube on top": the 2x2 beside the 3x3
    r = _built_as_said("Start with a 3 by 3 layer, then a 2 by 2 layer, finish with a single "
                       "cube on top. Centre each layer.", ["grid", "grid", "tower"],
                       None)  # fmt: skip
    assert _level_sizes(r.layout) == [(3, 3), (2, 2), (1, 1)]
    # "on top of the middle of a row of three": set at the table's centre, beside the row
    r = _built_as_said("Tower of two on top of the middle of a row of three.", ["tower", "row"],
                       [1, 1, 3])  # fmt: skip
    # "a 1-cube tower", "four single-cube towers": built 3 high, silently
    _built_as_said("a 1-cube tower", ["tower"], [1])
    _built_as_said("Sentinel posts: four single-cube towers, one at each corner of the table.",
                   ["tower"] * 4, [1] * 4)  # fmt: skip
    # a pier one brick wide is still one part across
    _built_as_said("a 1-brick pier 3 high", ["tower"], [3])


def test_one_in_each_corner_of_a_side_and_both_towers_said_again():
    # "two columns of five, one in each back corner": the second was a single cube
    r = _built_as_said("Two specimen columns of five, one in each back corner.",
                       ["tower", "tower"], [5, 5])  # fmt: skip
    assert {s.region for s in r.spec.structures} == {"back left", "back right"}
    # "Build both towers side by side": two more default towers were built
    _built_as_said("A tower has 3 cubes. A second tower is twice as tall. Build both towers "
                   "side by side.", ["tower", "tower"], [3, 6])  # fmt: skip


def test_a_complaint_about_the_last_run_and_a_texters_abbreviations():
    # "You put the tower on the left again. … Tower of three, right side.": two towers
    r = _built_as_said("You put the tower on the left again. I wanted it on the right. Tower of "
                       "three, right side.", ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "right"
    # "The ring had a cube in the middle. A 4x4 square ring, …": a 3x3 ring, a cube and the ring
    _built_as_said("The ring had a cube in the middle. A 4x4 square ring, 1 high, EMPTY in the "
                   "middle this time.", ["enclosure"], [1] * 12)  # fmt: skip
    # "up twd back" climbed to the left; "bk R" was dropped; "4+3" an L of 7
    r = _built_as_said("stairs x4, up twd back", ["staircase"], None)
    assert [h for _, h in sorted(_columns(r).items())] == [1, 2, 3, 4]
    r = _built_as_said("twr 3 no 4, bk R", ["tower"], [4])
    assert r.spec.structures[0].region == "back right"
    _built_as_said("L shp 4+3 flat", ["l_shape"], [1] * 6)


def test_a_fence_said_as_a_line_a_border_along_an_edge_and_circling_back():
    # "little fence, eight cubes in a line": a default wall beside a row of 8
    r = _built_as_said("Fair dinkum little fence, eight cubes in a line, running front to back "
                       "on the right side.", ["wall"], [1] * 8)  # fmt: skip
    assert _extent_in_parts(r, 0) == 8
    # "a low border … along the right-hand edge": a ring of 16 parts
    r = _built_as_said("I'd like a low border, one cube high, running all along the right-hand "
                       "edge, seven cubes long.", ["wall"], [1] * 7)  # fmt: skip
    assert _extent_in_parts(r, 0) == 7
    # "Circle back to the wall: …": a ring as well as the wall
    _built_as_said("Circle back to the wall: three cubes long, four high, built along the left "
                   "edge.", ["wall"], [4] * 3)  # fmt: skip


def test_a_board_square_a_centre_left_empty_and_a_programmers_calls():
    # "on the back-left square" (of a board): a slab was built under the rook
    r = _built_as_said("Think of the table as a board. Put a rook - a tower of three cubes - on "
                       "the back-left square.", ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "back left"
    # "with the centre square empty, one rank high": a full 3x3 and a row of 8
    _built_as_said("Set up a 3 by 3 square with the centre square empty, one rank high.",
                   ["enclosure"], [1] * 8)  # fmt: skip
    # a call: "tower(4)" at "back_left" (21 parts); "for level in range(3): …" (one layer)
    r = _built_as_said("if table.empty(): build tower(4) at back_left", ["tower"], [4])
    assert r.spec.structures[0].region == "back left"
    _built_as_said("for level in range(3): lay 2x2 square", ["block"], [3] * 4)
    r = _built_as_said("T(bar=5, stem=2), flat", ["t_shape"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 2)
    r = _built_as_said("pyramid(base=4, square=True)", ["pyramid"], None)
    assert _level_sizes(r.layout)[0] == (4, 4)


def test_the_left_tower_has_two_cubes_the_right_has_four():
    # the sizes in a sentence of their own, said with "has": a row of 2 beside default towers
    r = _built_as_said("Two towers stand 15 cm apart (gap between them). The left tower has 2 "
                       "cubes, the right has 4. Build them.", ["tower", "tower"],
                       [2, 4])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: kv[0][1])
    assert [h for _, h in by_y] == [4, 2]  # right (smaller y) 4, left 2
    assert by_y[1][0][1] - by_y[0][0][1] == pytest.approx(0.15 + 0.05)  # 15 cm clear


def test_stick_the_tall_one_on_the_left():
    # "stick the tall one on the left": the order was left to chance ('stick' not used)
    r = _built_as_said("Two towers, one three high and one five high, stick the tall one on the "
                       "left, reckon that'll do.", ["tower", "tower"], [3, 5])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: kv[0][1])
    assert [h for _, h in by_y] == [3, 5]  # the 5 on the left (+y)


def test_columns_at_centres_listed_without_and():
    # "2, 4, 2 high, at 10 cm centres": the 4 and the centres were left unused
    r = _built_as_said("Three columns in line, 2, 4, 2 high, at 10 cm centres, front to back.",
                       ["tower"] * 3, [2, 2, 4])  # fmt: skip
    xs = sorted(x for (x, _) in _columns(r))
    assert [round(b - a, 3) for a, b in itertools.pairwise(xs)] == [0.1, 0.1]  # centre to centre
    by_x = [h for _, h in sorted(_columns(r).items())]
    assert by_x == [2, 4, 2]


def test_a_complaint_that_tells_the_old_numbers_and_a_gap_of_at_least_one():
    # "I asked for a tower ON TOP of the slab, not next to it.": a relation cycle (error)
    r = _built_as_said("I asked for a tower ON TOP of the slab, not next to it. 3x3 slab, tower "
                       "of 2 on top.", ["grid", "tower"], [1] * 8 + [3])  # fmt: skip
    # "… you made had no beam on top … WITH a beam resting on both": one tower on the other
    r = _built_as_said("The bridge you made had no beam on top, just two towers. I want two "
                       "three-high towers WITH a beam resting on both.", ["bridge"],
                       None)  # fmt: skip
    assert r.spec.structures[0].height == 3
    # "a gap of at least one cube": read as 'a gap of a', and 'least' left unused
    r = _built_as_said("Two towers were touching last time, I wanted a gap. Two towers of four, "
                       "with a gap of at least one cube between them.", ["tower", "tower"],
                       [4, 4])  # fmt: skip
    ys = sorted(y for (_, y) in _columns(r))
    assert ys[1] - ys[0] == pytest.approx(0.05 + 0.05)


def test_another_layer_said_with_its_sides_goes_on_the_block():
    # "another two by two layer on top": 'another' took the sizes for a cube of its own (failure)
    _built_as_said("make a block two by two and two high and then put another two by two layer "
                   "on top", ["block", "grid"], [3, 3, 3, 3])  # fmt: skip


def test_two_rows_said_apart_stand_apart_one_behind_the_other():
    # "two rows of three cubes side by side one cube apart": one 3 by 2 floor, the gap ignored
    r = _built_as_said("two rows of three cubes side by side one cube apart", ["row", "row"],
                       [1] * 6)  # fmt: skip
    xs = sorted({x for (x, _) in _columns(r)})
    assert len(xs) == 2 and xs[1] - xs[0] == pytest.approx(0.1)  # one cube clear, parallel
    # "six towers … in two rows of three": the rows place the towers, they are no rows
    _built_as_said("six towers of 2 in two rows of three, a cube apart", ["tower"] * 6, [2] * 6)
    # walls keep a size said after both: "two walls of 4 cubes, 3 high, with a gap of 2 cubes"
    _built_as_said("two walls of 4 cubes, 3 high, with a gap of 2 cubes", ["wall", "wall"],
                   [3] * 8)  # fmt: skip


def test_four_towers_sized_between_commas_one_in_each_corner():
    # "Four towers, two high, one in each corner of the table": one tower of 2, silently
    r = _built_as_said("Four towers, two high, one in each corner of the table? Sorry, is that a "
                       "lot?", ["tower"] * 4, [2] * 4)  # fmt: skip
    assert len({x for (x, _) in _columns(r)}) == 2 and len({y for (_, y) in _columns(r)}) == 2


def test_the_shortest_at_one_end_keeps_the_listed_order():
    # "heights 2, 4 and 6, …, shortest on the left": built 2, 6, 4 from the left, silently
    r = _built_as_said("Three towers in a line, heights 2, 4 and 6, a cube gap between each, "
                       "shortest on the left.", ["tower"] * 3, [2, 4, 6])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])  # left (+y) first
    assert [h for _, h in by_y] == [2, 4, 6]


def test_a_pyramids_top_said_again_is_no_cube_of_its_own():
    # "top level a single cube": a loose cube beside the pyramid, silently
    r = _built_as_said("Sample: pyramid, 3 levels, top level a single cube.", ["pyramid"], None)
    assert r.spec.structures[0].height == 3


def test_more_added_to_the_same_row_lengthen_it():
    # "Add 4 more to the same row. Total 8 in one row.": three rows (4, 4 and 8), silently
    r = _built_as_said("Row of 4 cubes. Add 4 more to the same row. Total 8 in one row.", ["row"],
                       [1] * 8)  # fmt: skip
    assert r.spec.structures[0].length == 8


def test_sized_columns_listed_share_the_noun_said_last():
    # "a 1-cube, a 2-cube and a 3-cube column": one cube (the first two had no noun)
    _built_as_said("a 1-cube, a 2-cube and a 3-cube column, two cubes apart", ["tower"] * 3,
                   [1, 2, 3])  # fmt: skip


def test_an_arch_described_as_posts_and_a_beam_has_posts_that_high():
    # "An arch …: two posts two cubes high, … with a beam across": corbels made them 3 high
    r = _built_as_said("An arch for the entrance: two posts two cubes high, one cube apart, with a "
                       "beam across.", ["bridge"], None)  # fmt: skip
    top = max(o.position[2] + o.size[2] / 2 for o in r.layout.objects)
    assert top == pytest.approx(0.15)  # two cubes and the beam


def test_a_post_against_the_end_of_a_wall_named_after_it():
    # "a post … hard up against the right end of a wall five long": set at its left, silently
    r = _built_as_said("Stand a post four high hard up against the right end of a wall five long, "
                       "two high.", ["tower", "wall"], [2] * 5 + [4])  # fmt: skip
    post = next(k for k, h in _columns(r).items() if h == 4)
    assert all(post[1] < y for (_, y), h in _columns(r).items() if h == 2)  # right is -y


def test_more_added_to_the_middle_column_of_a_line_is_no_new_column():
    # "then add 2 cubes to the middle column only": a fourth column of 2, silently
    r = _built_as_said("three towers of 3 in a line, then add 2 cubes to the middle column only",
                       ["tower"] * 3, [3, 3, 5])  # fmt: skip
    assert [s.height for s in r.spec.structures] == [3, 5, 3]
    # of a tower in the middle of the table and another, which one is meant is not said
    r = plan("a tower of 3 in the middle and a tower of 2 on the left, then add 2 cubes to the "
             "middle tower")  # fmt: skip
    assert r.status != "success" and len(r.spec.structures) == 2


def test_the_back_of_the_room_is_the_back_of_the_table():
    # "at the back of the room": an enclosure (a room) was built beside the tower, silently
    r = _built_as_said("a tower of 3 at the back of the room", ["tower"], [3])
    assert r.spec.structures[0].region == "back"
    # a room built before is that room
    assert [s.shape for s in plan("a 5 by 5 room, then put a tower of 2 at the back of the "
                                  "room").spec.structures] == ["enclosure", "tower"]  # fmt: skip


def test_a_heading_naming_a_family_the_words_after_it_describe_as_another():
    # "The altar: a 2 by 3 block, two cubes high": an altar is a table; a table and a block
    r = _built_as_said("The altar: a 2 by 3 block, two cubes high, against the back of the room.",
                       ["block"], [2] * 6)  # fmt: skip
    assert any("name of the block" in n for n in r.notes)
    # a bridge's heading names what its pillars and beam make
    _built_as_said("a bridge: 2 pillars of 3, a beam across", ["bridge"], None)


def test_like_a_tetris_piece_after_a_shape_is_what_it_looks_like():
    # "An L shape, … - like the tetris piece": a second L (3 by 2), silently
    r = _built_as_said("An L shape, one arm four and the other three, one layer - like the tetris "
                       "piece.", ["l_shape"], None)  # fmt: skip
    assert not any("to 'tetris'" in n for n in r.notes)  # no correction of a word spelt right


def test_make_one_with_sizes_the_structure_named_before():
    # "Kids love a pyramid - make one with four layers": a pyramid one cube wide (failure)
    r = _built_as_said("Kids love a pyramid - make one with four layers.", ["pyramid"], None)
    assert r.spec.structures[0].height == 4


def test_one_cube_between_each_or_between_neighbours_is_the_gap():
    # "one cube between each": read as a size of the towers (partial)
    for said in ("four towers of three in a row, one cube between neighbours",
                 "four towers of three, one cube between each"):  # fmt: skip
        r = _built_as_said(said, ["tower"] * 4, [3] * 4)
        assert r.spec.gap_m == pytest.approx(0.05)


def test_straight_across_from_left_to_right_runs_left_to_right():
    # "straight across from left to right": ran front to back ('across from' as facing)
    r = _built_as_said("A row of seven cubes on the counter, straight across from left to right.",
                       ["row"], [1] * 7)  # fmt: skip
    assert len({x for (x, _) in _columns(r)}) == 1


def test_sizes_said_as_requirements_and_read_out_correct_the_first():
    # "Amendment: height shall be 2" / "my notes say two high actually": ignored (partial)
    for said in ("Assemble a 2x2 block 3 high. Amendment: height shall be 2.",
                 "A 2 by 2 block three high - sorry, my notes say two high actually."):  # fmt: skip
        _built_as_said(said, ["block"], [2] * 4)


def test_sizes_between_dashes_and_a_gap_of_exactly():
    # "Two walls - four long, two high - one behind the other": 'one' read as a height (partial)
    _built_as_said("Two walls - four long, two high - one behind the other with, um, a one cube "
                   "gap?", ["wall", "wall"], [2] * 8)  # fmt: skip
    # "a clear gap of exactly 3 cubes": 3 read as a size of the towers, the gap one cube
    r = _built_as_said("Two towers of 4 each (8 cubes total), separated by a clear gap of exactly "
                       "3 cubes.", ["tower", "tower"], [4, 4])  # fmt: skip
    ys = sorted(y for (_, y) in _columns(r))
    assert ys[1] - ys[0] == pytest.approx(0.15 + 0.05)


def test_the_leftmost_one_gets_more_cubes():
    # "The leftmost one gets 3 more cubes.": a row of 3 beside the towers
    r = _built_as_said("Put three towers of 2 in a row left to right, a cube between each. The "
                       "leftmost one gets 3 more cubes.", ["tower"] * 3, [2, 2, 5])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])  # left (+y) first
    assert [h for _, h in by_y] == [5, 2, 2]


def test_nothing_wanted_on_them_is_no_relation():
    # "no lintel or roof on them": the "on them" stood one column on another
    _built_as_said("A colonnade of four columns, three storeys, no lintel or roof on them, one "
                   "cube between each.", ["tower"] * 4, [3] * 4)  # fmt: skip


def test_actually_just_fewer_recounts_the_structures():
    # "put 5 towers of 1 in a row. actually just 4.": five towers 4 high, silently
    _built_as_said("put 5 towers of 1 in a row. actually just 4. a cube between each.",
                   ["tower"] * 4, [1] * 4)  # fmt: skip


def test_a_label_pointed_at_later_is_not_dropped_silently():
    # "tower B: 3 high, on A's right": A's right read as the table's right, silently
    for gap in ("", "\n• one cube between neighbours"):
        r = plan("Arrangement:\n• tower A: 6 high\n• tower B: 3 high, on A's right\n• tower C: "
                 "3 high, on A's left" + gap)  # fmt: skip
        assert r.status != "success"


def test_the_one_of_its_family_in_the_middle_of_a_line():
    # "…, and another 2 by 2 block, a cube apart, the tower in the middle": a second tower at
    # the table's centre, silently
    r = _built_as_said("a 2 by 2 block, a tower of six, and another 2 by 2 block, a cube apart, "
                       "the tower in the middle.", ["block", "tower", "block"],
                       [1] * 8 + [6])  # fmt: skip
    ys = sorted({y for (_, y) in _columns(r)})
    tower_y = next(y for (_, y), h in _columns(r).items() if h == 6)
    assert ys.index(tower_y) == 2  # two block columns on each side


def test_room_words_that_build_no_room():
    # "wherever there's room on the bench", "for the medieval room": an enclosure beside it
    _built_as_said("Just a pyramid, three levels, wherever there's room on the bench.",
                   ["pyramid"], None)  # fmt: skip
    r = _built_as_said("Build a castle for the medieval room. Then move it to the back right of "
                       "the table.", ["castle"], None)  # fmt: skip
    assert r.spec.structures[0].region == "back right"


def test_a_column_at_the_heart_of_an_enclosure_that_frames_it():
    # "at the heart of a 6 by 6 enclosure - the enclosure frames it": a failure
    r = _built_as_said("Place a column of three at the heart of a 6 by 6 enclosure - the "
                       "enclosure frames it.", ["tower", "enclosure"], None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["around"]


def test_one_at_each_of_the_four_corners_of_the_table():
    # "one at each of the four corners of the table": one column of 3 and nothing at the corners
    r = _built_as_said("Four columns of three, one at each of the four corners of the table.",
                       ["tower"] * 4, [3] * 4)  # fmt: skip
    assert len({x for (x, _) in _columns(r)}) == 2 and len({y for (_, y) in _columns(r)}) == 2


def test_an_exhibit_labels_number_is_no_size():
    # "Exhibit label 12: a stepped pyramid of four tiers.": 12 read as a size (failure)
    r = _built_as_said("Exhibit label 12: a stepped pyramid of four tiers.", ["pyramid"], None)
    assert r.spec.structures[0].height == 4


def test_a_long_wall_counted_in_cubes_takes_its_length_from_them():
    # "a long wall, 10 cubes, two high": 6 long (the vague size of 'long'), silently; 'long'
    # with a count says the count runs its length
    _built_as_said("a long wall, 10 cubes, two high, across the back", ["wall"], [2] * 10)


def test_a_family_said_bare_before_a_place_is_the_one_named():
    # "…, wall on the left": a second wall there, silently
    _built_as_said("make a tower of 4 and a wall 3 long 2 high that don't touch, wall on the left",
                   ["tower", "wall"], [2, 2, 2, 4])  # fmt: skip
    # "The staircase on the left, the tower on the right." said in a sentence of its own, of a
    # "2x2 tower of 3." (a block one high, and a second staircase and block)
    _built_as_said("a 4-step staircase and a 2x2 tower of 3. The staircase on the left, the tower "
                   "on the right.", ["staircase", "block"], None)  # fmt: skip
    _built_as_said("we had a 4-step staircase and a 2x2 tower of 3 side by side all day. Rebuild "
                   "those two, stairs on the left, tower on the right, a couple of cubes between.",
                   ["staircase", "block"], None)  # fmt: skip


def test_one_of_four_in_the_middle_of_the_table_and_one_of_six():
    # "… in the middle of the table and one of 6 at the back": a table 6 high, silently
    _built_as_said("a tower of 2 at the front, one of 4 in the middle of the table and one of 6 at "
                   "the back", ["tower"] * 3, [2, 4, 6])  # fmt: skip


def test_a_question_that_asks_for_nothing_is_refused():
    # "how many cubes are left in the feeder?": a row of 8 ('many'), silently
    with pytest.raises(SpecError, match="a question"):
        read("how many cubes are left in the feeder?")


def test_blocks_of_one_footprint_with_their_heights_listed():
    # "three 2x2 blocks, 1, 2 and 3 high": slabs 3, 2 and 1 long, silently
    r = _built_as_said("three 2x2 blocks, 1, 2 and 3 high, left to right, with gaps between",
                       ["block"] * 3, [1] * 4 + [2] * 4 + [3] * 4)  # fmt: skip
    at_y = {y: h for (_, y), h in _columns(r).items()}
    assert [at_y[y] for y in sorted(at_y, reverse=True)] == [1, 1, 2, 2, 3, 3]  # left (+y) first


def test_three_walls_one_behind_the_other_stand_in_one_line():
    # "three walls …, one behind the other": the second beside them, silently
    r = _built_as_said("three walls 4 long 2 high, one behind the other, 2 cubes apart",
                       ["wall"] * 3, [2] * 12)  # fmt: skip
    xs = sorted({x for (x, _) in _columns(r)})
    assert len({y for (_, y) in _columns(r)}) == 4
    assert [round(b - a, 3) for a, b in itertools.pairwise(xs)] == [0.15, 0.15]


def test_one_tower_of_several_as_tall_as_another():
    # "make the short one as tall as the middle one": nothing changed (and all at the centre)
    r = _built_as_said("towers of 3, 5 and 7 in a row, a cube apart; make the short one as tall as "
                       "the middle one", ["tower"] * 3, [5, 5, 7])  # fmt: skip
    assert all(getattr(s, "region", None) is None for s in r.spec.structures)
    # which one is short is not said when two are: honest
    assert plan("three towers of 2, 2 and 6. make the short one as tall as the tall one").status \
        != "success"  # fmt: skip


def test_cubes_removed_from_a_tower_come_off_its_top():
    # "Step 3: remove 1 cube.": refused ('cannot take parts out')
    _built_as_said("Step 1: build a column of 3. Step 2: add 4 cubes to the column. Step 3: remove "
                   "1 cube.", ["tower"], [6])  # fmt: skip
    _built_as_said("build a tower of 8 and then remove half of it", ["tower"], [4])
    # of a wall, where they come from is not said: honest
    assert plan("a wall 4 long 3 high, then remove 2 cubes").status != "success"


def test_sizes_each_with_its_own_of_and_a_gap_said_between():
    # "Three towers, of two, of three and of four, … with two cubes between": all 4 high
    r = _built_as_said("Three towers, of two, of three and of four, in a line with two cubes "
                       "between, from left to right.", ["tower"] * 3, [2, 3, 4])  # fmt: skip
    by_y = sorted(_columns(r).items(), key=lambda kv: -kv[0][1])
    assert [h for _, h in by_y] == [2, 3, 4]
    assert by_y[0][0][1] - by_y[1][0][1] == pytest.approx(0.1 + 0.05)


def test_plain_ways_to_say_touching_parallel_and_too_tall():
    _built_as_said("two towers of 4 that touch", ["tower", "tower"], [4, 4])
    _built_as_said("tower of 7 please. hmm thats too tall, do 5", ["tower"], [5])
    _built_as_said("two parallel walls 4 long 3 tall with 10 cm between them", ["wall", "wall"],
                   [3] * 8)  # fmt: skip


def test_estate_agents_words_for_a_wall_a_neighbour_and_a_terrace():
    # "Boundary wall, …, running along the left side": a ring 9 on a side
    r = _built_as_said("Boundary wall, nine long and two high, running along the left side of the "
                       "lot.", ["wall"], [2] * 9)  # fmt: skip
    assert r.spec.structures[0].region == "left"
    r = _built_as_said("A pyramid of three levels with a tower of four as its next-door neighbour.",
                       ["pyramid", "tower"], None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["next_to"]
    # "A terrace of four towers": a staircase beside them
    _built_as_said("A terrace of four towers of three in a row, one cube between neighbours.",
                   ["tower"] * 4, [3] * 4)  # fmt: skip


def test_another_a_little_to_its_right():
    # "a tower of 3 a little to its left and another a little to its right": the second tower
    # was not built ('another a little' no structure)
    r = _built_as_said("a pyramid of 3 levels in the middle with a tower of 3 a little to its left "
                       "and another a little to its right", ["pyramid", "tower", "tower"],
                       None)  # fmt: skip
    assert sorted(rel.side for rel in r.spec.relations) == ["left", "right"]


def test_a_copy_of_it_and_the_same_done_elsewhere():
    # "then put a copy of it at the back": ignored; "another one" of a 2x2 block: one cube
    _built_as_said("build a 2x2 block 3 high at the front. then put a copy of it at the back",
                   ["block", "block"], [3] * 8)  # fmt: skip
    _built_as_said("build a 2x2 block 3 high at the front. then put another one at the back",
                   ["block", "block"], [3] * 8)  # fmt: skip
    r = _built_as_said("a tower of 4 in the front left. do the same at the back left and back "
                       "right", ["tower"] * 3, [4] * 3)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["front left", "back left", "back right"]


def test_the_middle_one_of_a_square_of_cubes_is_its_middle_cube():
    # "a 3 by 3 square of cubes, then take out the middle one": refused (which structure?)
    _built_as_said("make a 3 by 3 square of cubes, then take out the middle one", ["enclosure"],
                   [1] * 8)  # fmt: skip


def test_levels_said_with_next_and_finished_with_one_cube():
    # "first a 4x4 slab, next a 3x3 on it, next a 2x2, and finish with one cube": the 2x2 and
    # the cube beside the rest
    r = _built_as_said("first a 4x4 slab, next a 3x3 on it, next a 2x2, and finish with one cube",
                       ["grid", "grid", "grid", "tower"], None)  # fmt: skip
    assert max(o.position[2] + o.size[2] / 2 for o in r.layout.objects) == pytest.approx(0.2)


def test_cubes_taken_off_the_tall_one_of_several():
    # "then take 3 off the tall one": refused ('cannot take parts out')
    _built_as_said("three towers of 2, 4 and 6 in a row, a cube apart, then take 3 off the tall "
                   "one", ["tower"] * 3, [2, 3, 4])  # fmt: skip


def test_a_change_is_kept_when_a_later_sentence_places_the_structure():
    # "a tower of 3, then add 2 more cubes to it. At the back.": the note said 5, the tower
    # was built 3 high (the place read the tower again from its first words)
    r = _built_as_said("a tower of 3, then add 2 more cubes to it. At the back.", ["tower"], [5])
    assert r.spec.structures[0].region == "back"
    r = _built_as_said("three towers of 3 in a row, a cube apart, then add two cubes to the middle "
                       "one. In the middle of the table.", ["tower"] * 3, [3, 3, 5])  # fmt: skip
    assert [s.height for s in r.spec.structures] == [3, 5, 3]


def test_structures_in_a_row_not_touching_build_no_row():
    # "3 pyramids, in a row, not touching": a fourth structure, a default row, silently
    for said in ("3 pyramids, in a row, not touching", "3 pyramids of 2 levels in a row, not "
                 "touching"):  # fmt: skip
        r = _built_as_said(said, ["pyramid"] * 3, None)
        assert r.spec.gap_m == pytest.approx(0.05)


def test_a_total_said_before_the_rows_that_make_it():
    # "six cubes, two rows of 3": a row of 6 and a row of 3 (partial)
    r = _built_as_said("six cubes, two rows of 3, a cube apart", ["row", "row"], [1] * 6)
    assert "'6 cubes in total': holds, 6 parts" in r.notes


def test_a_wall_between_them_sized_after_and_all_touching():
    # "with a wall between them, 4 long 2 high, all touching": the sizes read as the towers',
    # and 'all touching' dropped (gaps between), silently
    r = _built_as_said("two towers of 6 with a wall between them, 4 long 2 high, all touching",
                       ["tower", "tower", "wall"], [2] * 4 + [6, 6])  # fmt: skip
    ys = sorted({y for (_, y) in _columns(r)})
    assert [round(b - a, 3) for a, b in itertools.pairwise(ys)] == [0.05] * 5


def test_line_up_and_a_lone_column():
    # "Line up five towers of two": 'line' unused (partial); "a lone column": 'lone' unused
    _built_as_said("Line up five towers of two, a cube apart, like toy soldiers.", ["tower"] * 5,
                   [2] * 5)  # fmt: skip
    _built_as_said("a lone column, seven cubes tall, toward the back", ["tower"], [7])


def test_a_size_below_zero_said_with_its_dimension_is_refused():
    # "a bridge with pillars -2 high": built 2 high, silently
    for said in ("a bridge with pillars -2 high", "a tower -3 high"):
        with pytest.raises(SpecError, match="below zero"):
            read(said)
    # a dash before a size is no minus
    _built_as_said("The wall - 6 long, 2 high - build it at the front.", ["wall"], [2] * 6)


def test_plain_words_for_an_l_a_bound_a_place_and_pens():
    # "right, er, could I get an L shape, arms four long": on the right, 4 by 2, silently
    r = _built_as_said("right, er, could I get an L shape, arms four long, flat on the table, "
                       "thanks", ["l_shape"], None)  # fmt: skip
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (4, 4)
    assert r.spec.structures[0].region is None
    # "keep it under 10 cubes": a row of 10, silently
    assert len(plan("surprise me, but keep it under 10 cubes").layout.objects) < 10
    # "on the far side of the table from the robot": read as where the speaker stands
    r = _built_as_said("a 3-step staircase on the far side of the table from the robot",
                       ["staircase"], None)  # fmt: skip
    assert r.spec.structures[0].region == "back"
    # "three pens, one high: 3 by 3, 4 by 4 and 3 by 4": three pens 3 by 4
    r = _built_as_said("three pens, one high: 3 by 3, 4 by 4 and 3 by 4", ["enclosure"] * 3, None)
    assert [(s.length, s.width) for s in r.spec.structures] == [(3, 3), (4, 4), (3, 4)]


def test_another_cube_on_it_and_another():
    # "Put another cube on it. And another.": the third cube beside the first two, silently
    r = plan("put a cube in the centre. Put another cube on it. And another.")
    assert r.status == "success" and sorted(_columns(r).values()) == [3]


def test_a_cube_underneath_a_table_a_pillar_in_a_courtyard_and_one_more_than_that():
    # "and, underneath it, a single cube": set on top of the table, silently
    assert plan("a table with legs 2 high and, underneath it, a single cube").status != "success"
    # "a pillar right in the middle of its courtyard": the pillar dropped, silently
    r = _built_as_said("a castle with a 3-high pillar right in the middle of its courtyard",
                       ["castle", "tower"], None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["around"]
    # "one tower of one more than that": a third tower, all 2 high
    _built_as_said("one tower of 2, and one tower of one more than that, not touching",
                   ["tower", "tower"], [2, 3])  # fmt: skip


def test_a_bridge_high_overall_and_a_bench_on_two_legs():
    # "a bridge 4 high overall": posts 4 high, the bridge 5, silently
    r = _built_as_said("a gate 4 high overall with a beam on top", ["bridge"], None)
    top = max(o.position[2] + o.size[2] / 2 for o in r.layout.objects)
    assert top == pytest.approx(0.2)
    # "a bench with legs of two and a beam": a table on four legs with a roof of beams
    r = _built_as_said("Build a bench with legs of two and a beam. Then make the legs 3 tall",
                       ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 3 and "read 'bench' as 'bridge'" in r.notes


def test_one_more_on_top_the_same_on_the_right_a_wide_pillar_and_hang_on():
    # "a stack of five, and then one more on top": 'on' related nothing (partial)
    _built_as_said("a stack of five, and then one more on top", ["tower"], [6])
    # "… on the left. and the same on the right.": nothing on the right (partial)
    r = _built_as_said("a tower of 5 on the left. and the same on the right.", ["tower", "tower"],
                       [5, 5])  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    # "a pillar 2 cubes wide and 2 deep, 3 high": a tower, its width ignored
    _built_as_said("a pillar 2 cubes wide and 2 deep, 3 high", ["block"], [3] * 4)
    # "hang on, make it 6 by 4": 'hang' unused (partial)
    r = _built_as_said("a pen 5 by 4 one cube high - hang on, make it 6 by 4", ["enclosure"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (6, 4)


def _inside_ring(r):
    """The column heights standing strictly inside the layout's outline, and the parts on it."""
    pos = [(round(o.position[0], 3), round(o.position[1], 3)) for o in r.layout.objects]
    x0, x1 = min(x for x, _ in pos), max(x for x, _ in pos)
    y0, y1 = min(y for _, y in pos), max(y for _, y in pos)
    outline = [(x, y) for x, y in pos if x in (x0, x1) or y in (y0, y1)]
    inner: dict[tuple[float, float], int] = {}
    for x, y in pos:
        if x0 < x < x1 and y0 < y < y1:
            inner[(x, y)] = inner.get((x, y), 0) + 1
    return sorted(inner.values()), len(outline)


def test_several_structures_inside_one_ring():
    # "a ring 6 by 6 with two towers of 2 inside it": one inside, the other outside, silently
    for command, heights, ring in (
        ("a ring 6 by 6 with two towers of 2 inside it", [2, 2], 20),
        ("Could you surround a tower of 6 and a tower of 2 with one ring?", [2, 6], None),
        ("Make one ring 7 by 7 and inside put four towers: heights 1, 2, 3 and 4.", [1, 2, 3, 4],
         24),
        ("Ring 7 by 7, one high, and two towers of 3 inside it, not touching anything.", [3, 3],
         24),
    ):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [s.shape for s in r.spec.structures].count("enclosure") == 1
        inner, outline = _inside_ring(r)
        assert inner == heights, command
        assert outline == (ring or len(r.layout.objects) - sum(heights)), command
    # the ring 7 by 7 is 7 by 7 (its inside was read as 7 by 7: a ring 9 by 9)
    r = plan("Make one ring 7 by 7 and inside put four towers: heights 1, 2, 3 and 4.")
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (7, 7)
    # three cubes in a row inside it: a row of 3 (the row after 'inside it' was one of 5)
    r = _built_as_said("Build an enclosure 9 cubes by 5 cubes and put three single cubes inside "
                       "it in a row.", ["enclosure", "row"], None)  # fmt: skip
    assert r.spec.structures[1].length == 3
    r = _built_as_said("enclosure 8x6, one high. inside: row of 4, centred.", ["enclosure", "row"],
                       None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["around"]


def test_walls_with_heights_listed_and_walls_forming_a_corner():
    # "three walls 4 long, heights 1, 2 and 3": walls 1, 2 and 3 long, 2 high, silently
    for command in ("three walls 4 long, heights 1, 2 and 3, one behind another, 1 cube apart, "
                    "the tallest at the back",
                    "three walls, each 4 long, with heights of 1, 2 and 3",
                    "three walls 4 long, 1, 2 and 3 high"):  # fmt: skip
        r = _built_as_said(command, ["wall"] * 3, None)
        assert [(s.length, s.height) for s in r.spec.structures] == [(4, 1), (4, 2), (4, 3)]
    # "two walls forming a corner, each 4 long, 2 high": an L whose arms are 4 long
    r = _built_as_said("two walls forming a corner, each 4 long, 2 high", ["l_shape"], None)
    s = r.spec.structures[0]
    assert (s.length, s.width, s.height) == (4, 4, 2)


def test_a_row_of_cubes_counted_after_and_a_podium_given_a_footprint():
    # "a row of cubes, not a tower, five of them": five rows of 5, silently
    r = _built_as_said("a row of cubes, not a tower, five of them", ["row"], [1] * 5)
    # "a podium 2 by 2, 2 high": a staircase 2 wide
    r = _built_as_said("a podium 2 by 2, 2 high, with a cube on top in the middle",
                       ["block", "tower"], None)  # fmt: skip
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (2, 2)
    assert max(o.position[2] + o.size[2] / 2 for o in r.layout.objects) == pytest.approx(0.15)
    # a podium with nothing said of its footprint stays a stepped one
    assert plan("something like a podium").spec.structures[0].shape == "staircase"


def test_a_relation_said_first_with_its_object_described_or_a_verb():
    # "In front of a 3x3 slab, put a tower of 2": ', put' began a step of its own (partial)
    r = _built_as_said("In front of a 3x3 slab, put a tower of 2.", ["tower", "grid"], None)
    assert [(rel.kind, rel.side) for rel in r.spec.relations] == [("next_to", "front")]
    # "Behind the throne - a 2 by 2 block one high - looms a pillar of seven": the block at the
    # back and the pillar anywhere, silently
    r = _built_as_said("Behind the throne - a 2 by 2 block one high - looms a pillar of seven.",
                       ["tower", "block"], None)  # fmt: skip
    assert [(rel.kind, rel.side) for rel in r.spec.relations] == [("next_to", "back")]
    assert r.spec.structures[0].height == 7
    r = _built_as_said("Behind the wall - four long, two high - a tower of three.",
                       ["tower", "wall"], None)  # fmt: skip
    assert (r.spec.structures[1].length, r.spec.structures[0].height) == (4, 3)


def test_a_second_structure_sized_before_its_noun_in_a_with_phrase():
    # "a 5 high tower with a 2 high one touching it on the right": one tower of 5 (partial)
    for command in ("a 5 high tower with a 2 high one touching it on the right",
                    "a 5 high tower with a 2 high tower on its right"):  # fmt: skip
        r = _built_as_said(command, ["tower", "tower"], [2, 5])
        assert [(rel.kind, rel.side) for rel in r.spec.relations] == [("next_to", "right")]
    # "a pyramid with a 5x5 base and a tower of 3 next to it": a 5x5 block of its own (partial)
    r = _built_as_said("a pyramid with a 5x5 base and a tower of 3 next to it",
                       ["pyramid", "tower"], None)  # fmt: skip
    assert r.spec.structures[0].length == 5 and r.spec.structures[0].dims == 3
    # "a tower of 4 with a smaller one next to it, 2 high": 'smaller' unused (partial); a
    # comparison the sizes contradict stays unread
    r = _built_as_said("a tower of 4 with a smaller one next to it, 2 high", ["tower", "tower"],
                       [2, 4])  # fmt: skip
    assert plan("a tower of 4 with a smaller one next to it, 6 high").status == "partial"


def test_a_layer_sized_after_it_and_a_slab_at_one_end_of_another():
    # "then a second tier, 2 by 2, set right in the centre of it": a second 4x4 layer and the
    # 2x2 on top of that, silently
    r = _built_as_said("first the slab, 4 by 4; then a second tier, 2 by 2, set right in the "
                       "centre of it", ["grid", "grid"], None)  # fmt: skip
    assert sorted(_columns(r).values()) == [1] * 12 + [2] * 4
    # "2 x 4 slab, and on it a 2 x 2 slab at one end": centred (partial)
    r = _built_as_said("2 x 4 slab, and on it a 2 x 2 slab at one end", ["grid", "grid"], None)
    cols = _columns(r)
    high = [k for k, v in cols.items() if v == 2]
    low = [k for k, v in cols.items() if v == 1]
    axis = 0 if len({k[0] for k in cols}) == 4 else 1
    assert max(k[axis] for k in high) < min(k[axis] for k in low) or min(
        k[axis] for k in high
    ) > max(k[axis] for k in low)


def test_a_structure_said_again_and_words_that_strengthen_a_place():
    # "A castle! Nothing fancy, just a castle please": two castles, silently
    _built_as_said("A castle! Nothing fancy, just a castle please :)", ["castle"], None)
    # "right in the very centre": on the right, silently
    r = plan("Just a simple single cube, right in the very centre, nothing else!")
    assert r.status == "success" and r.spec.structures[0].region == "centre"
    # "bar 5 stem 3": 'stem' corrected to 'item' and dropped, silently
    r = _built_as_said("T shape flat, bar 5 stem 3. tower 3 behind it, 1 gap.",
                       ["t_shape", "tower"], None)  # fmt: skip
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 3)
    # "line front→back": left to right at the front, silently
    r = _built_as_said("5 single cubes, line front→back, gap 1 each.", ["row"], None)
    assert r.spec.structures[0].axis == "x"


def test_one_tower_of_a_line_picked_by_its_side_size_or_the_robot():
    # "the one nearest the robot, make it 6" of a line front to back: the back one grew
    for command in ("Three towers of 3 in a line front to back, two-cube gaps. The one nearest "
                    "the robot, make it 6.",
                    "Three towers of 3 in a line front to back, two-cube gaps. Make the front "
                    "one 6."):  # fmt: skip
        r = _built_as_said(command, ["tower"] * 3, [3, 3, 6])
        cols = sorted(_columns(r).items())  # front (small x) first
        assert cols[0][1] == 6
    # of two towers side by side, "the front one" is none of them: said so (the 6 was lost
    # and both stood at the front, silently)
    r = plan("two towers of 3. make the front one 6")
    assert r.status == "partial" and all(s.region is None for s in r.spec.structures)
    # "Take the tallest one down to 3": the tallest taken away, silently
    r = _built_as_said("Three towers in a row, 2, 4 and 6 high, gap of one. Take the tallest one "
                       "down to 3.", ["tower"] * 3, [2, 3, 4])  # fmt: skip
    _built_as_said("three towers of 2, 4 and 6. make the tallest one 3.", ["tower"] * 3, [2, 3, 4])
    # "remove the smaller one": read as a reference to it, nothing removed, silently
    _built_as_said("two towers, of 3 and 5. remove the smaller one.", ["tower"], [5])
    r = plan("stair 3 + stair 5, side by side, gap 1. remove the smaller.")
    assert r.status == "partial" and len(r.spec.structures) == 2


def test_copies_of_a_bridge_said_with_its_posts_and_copies_placed_each_side():
    # "Bridge with posts 2 and a beam, then another one …": another post (a tower), silently
    r = _built_as_said("Bridge with posts 2 and a beam, then another one the same right next to "
                       "it on its right.", ["bridge", "bridge"], None)  # fmt: skip
    assert [s.height for s in r.spec.structures] == [2, 2]
    # "two more exactly like it, one to its left and one to its right": the first 2 taller
    # ('put two more'), or two towers of 1 beside two of 3
    _built_as_said("Make a tower of 3, then put two more exactly like it, one to its left and "
                   "one to its right, with one-cube gaps.", ["tower"] * 3, [3, 3, 3])  # fmt: skip
    r = _built_as_said("a wall of 4 and two more like it, one in front of it and one behind it",
                       ["wall"] * 3, None)  # fmt: skip
    assert [s.length for s in r.spec.structures] == [4, 4, 4]
    # "the exact same arch again in front of it with a little gap": the copy an arch 1 high
    r = _built_as_said("Can I have an arch? And then, just for fun, the exact same arch again in "
                       "front of it with a little gap, like a double tunnel entrance.",
                       ["arch", "arch"], None)  # fmt: skip
    assert r.spec.structures[0] == r.spec.structures[1]


def test_terse_changes_copies_into_corners_and_a_tower_on_every_side_of_a_ring():
    # "2 towers h3, gap 2. right one +3.": both moved to the right, the +3 lost, silently
    _built_as_said("2 towers h3, gap 2. right one +3.", ["tower", "tower"], [3, 6])
    # "The wall on right side, make 4 high.": a fourth wall, 4 high, at the right
    r = _built_as_said("I build three walls in line left to right, each 3 long and 2 high, gap "
                       "one. The wall on right side, make 4 high.", ["wall"] * 3, None)  # fmt: skip
    assert sorted(s.height for s in r.spec.structures) == [2, 2, 4]
    # "… in the back right corner and copy it into the other three corners": one copy, a tower
    # of 3 in the middle, silently
    r = _built_as_said("Put a tower of 5 in the back right corner and copy it into the other "
                       "three corners.", ["tower"] * 4, [5, 5, 5, 5])  # fmt: skip
    assert {s.region for s in r.spec.structures} == {
        "back left", "back right", "front left", "front right"
    }  # fmt: skip
    # "ring 5x5x1. tower 4 outside each side": one tower; a ring has four sides
    for command in ("ring 5x5x1. tower 4 outside each side, gap 1.",
                    "a ring 5x5 with a tower of 4 on each side"):  # fmt: skip
        r = plan(command)
        assert r.status == "success", r.notes
        assert sorted(_columns(r).values()).count(4) == 4


def test_structures_in_a_triangle_or_a_square_of_four():
    # "Three towers of 4 in a triangle.": in a line (partial)
    r = _built_as_said("Three towers of 4 in a triangle.", ["tower"] * 3, [4, 4, 4])
    xs = sorted(x for x, _ in _columns(r))
    assert xs[0] == xs[1] < xs[2]  # two side by side, the third behind them
    front = sorted(y for (x, y) in _columns(r) if x == xs[0])
    back = [y for (x, y) in _columns(r) if x == xs[2]]
    assert back[0] == pytest.approx(sum(front) / 2)  # centred on the pair
    assert plan("four towers in a triangle").status == "partial"
    # "a square of four 2x2 blocks, each 2 high": two blocks of their own, silently
    r = _built_as_said("Make a square of four 2x2 blocks, each 2 high, with a gap of one between "
                       "them.", ["block"] * 4, [2] * 16)  # fmt: skip
    assert len({x for x, _ in _columns(r)}) == 4 and len({y for _, y in _columns(r)}) == 4
    # "6 towers h2, 2 rows of 3": two rows of cubes built besides, silently
    r = _built_as_said("6 towers h2, 2 rows of 3, gap 1.", ["tower"] * 6, [2] * 6)
    assert r.spec.grid == (2, 3)


def test_the_two_in_the_middle_of_a_line_and_one_taken_from_between_others():
    # "make the two in the middle 5 high" of four: a fifth structure or nothing (partial)
    for command in ("four towers of 2 in a row, a cube apart; make the two in the middle 5 high",
                    "Line up four 3-high towers with two-cube gaps and bump the middle pair up "
                    "to 5."):  # fmt: skip
        r = _built_as_said(command, ["tower"] * 4, None)
        heights = [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])]
        assert heights[1:3] == [5, 5] and heights[0] == heights[3] != 5
    r = _built_as_said("Line up four walls, each 3 long and 2 high, one behind the other, a cube "
                       "apart. The two in the middle go up to 4 high.",
                       ["wall"] * 4, None)  # fmt: skip
    assert [s.height for s in r.spec.structures] == [2, 4, 4, 2]
    # "remove the middle two": the two left keep their places
    r = _built_as_said("4 towers of 2 in a row, gap 1. remove middle two.", ["tower"] * 2, [2, 2])
    ys = sorted(y for _, y in _columns(r))
    assert ys[1] - ys[0] == pytest.approx(0.3)  # three gaps and two towers, centre to centre
    # "take away the tallest" standing in the middle of three: the others keep their places
    r = _built_as_said("three towers of 2, 5 and 3 in a row, a cube apart. take away the tallest",
                       ["tower"] * 2, [2, 3])  # fmt: skip
    ys = sorted(y for _, y in _columns(r))
    assert ys[1] - ys[0] == pytest.approx(0.2)


def test_one_of_a_line_counted_from_its_side_and_made_taller():
    # "the second from the right" of a line said no way: every tower 4 high (partial)
    r = _built_as_said("four towers of 2 in a row. make the second from the right 4 high",
                       ["tower"] * 4, None)  # fmt: skip
    heights = [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])]  # from right
    assert heights == [2, 4, 2, 2]
    # "make the second from the left a bit taller": not read (partial)
    r = _built_as_said("Three towers of 2 in a row from left to right. Make the second from the "
                       "left a bit taller.", ["tower"] * 3, [2, 2, 3])  # fmt: skip
    # "a tower of 3, make it taller": nothing changed, silently
    _built_as_said("a tower of 3, make it taller", ["tower"], [4])
    # "the tallest you can manage": 6 high, silently
    _built_as_said("Could I get a really tall tower — the tallest you can manage?", ["tower"],
                   [10])  # fmt: skip


def test_gaps_and_words_said_around_the_structures():
    # "leave a gap of one between a 3-cube tower and a 4-cube tower": the gap unused (partial)
    r = _built_as_said("Can you leave a gap of one between a 3-cube tower and a 4-cube tower?",
                       ["tower", "tower"], [3, 4])  # fmt: skip
    assert r.spec.gap_m == pytest.approx(0.05)
    # "the distance between is 15 cm": unused (partial)
    r = _built_as_said("Tower of 4, and tower of 4, the distance between is 15 cm.",
                       ["tower", "tower"], [4, 4])  # fmt: skip
    assert r.spec.gap_m == pytest.approx(0.15)
    # "a U form, width 5, arm 4": the arm's length dropped (partial)
    r = _built_as_said("a U shape, width 5, arm 4.", ["u_shape"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 4)
    # "a fat little tower — 3 by 3 across and only 2 tall. Doable?": 'fat', 'Doable' unused
    _built_as_said("I'm thinking a fat little tower — 3 by 3 across and only 2 tall. Doable?",
                   ["block"], [2] * 9)  # fmt: skip
    # "tucked into the front-left corner": 'tucked' unused (partial)
    r = _built_as_said("Could you build a little stair case — three steps — tucked into the "
                       "front-left corner?", ["staircase"], None)  # fmt: skip
    assert r.spec.structures[0].region == "front left"


def test_the_middle_one_of_a_line_said_with_its_height():
    # "three towers of 2 in a line, the middle one 5 high": a fourth tower of 5 in the centre
    # (or all three 5 high), silently
    for command in ("three towers of 2 in a line, 2 apart, the middle one 5 high",
                    "Line up three towers of 2 with two-cube gaps, and the one in the middle "
                    "should be 5 tall",
                    "Line up three towers of 2, two cubes apart; the centre one gets 5",
                    ):  # fmt: skip
        r = _built_as_said(command, ["tower"] * 3, [2, 2, 5])
        heights = [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])]
        assert heights == [2, 5, 2]


def test_heights_said_as_articles_copies_mirrored_and_sizes_after_on_it():
    # "Two towers, a 4 and a 7, the 7 behind the 4": two towers of 4 at the back (partial)
    r = _built_as_said("Two towers, a 4 and a 7, the 7 behind the 4.", ["tower", "tower"], [4, 7])
    cols = sorted(_columns(r).items())  # front (small x) first
    assert [h for _, h in cols] == [4, 7]
    # "then make it two times higher": not read (partial)
    _built_as_said("First make tower of 4. Then make it two times higher. Then take away three "
                   "cubes.", ["tower"], [5])  # fmt: skip
    # "then mirror it on the right side": not read (partial)
    r = _built_as_said("Build a staircase of 3 steps on the left side of the table, then mirror "
                       "it on the right side.", ["staircase", "staircase"], None)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    # "a 2x2 block on it, 1 high, in the middle": 'on' related nothing (partial)
    r = _built_as_said("First a 4x4 slab. Then a 2x2 block on it, 1 high, in the middle. Finally "
                       "a single cube on top of that.", ["grid", "block", "tower"],
                       None)  # fmt: skip
    assert max(o.position[2] + o.size[2] / 2 for o in r.layout.objects) == pytest.approx(0.15)
    assert sorted(_columns(r).values()).count(2) == 4  # the block on the slab, not beside it


def test_a_pyramid_counted_by_its_levels_and_cubes_said_in_it():
    # "one cube at the top, four under that and nine at the bottom": a flat pyramid 9 long
    for command in ("make me a pyramid that has one cube at the top, four under that and nine at "
                    "the bottom", "a pyramid with layers of 9, 4 and 1"):  # fmt: skip
        r = _built_as_said(command, ["pyramid"], None)
        top = max(o.position[2] + o.size[2] / 2 for o in r.layout.objects)
        assert len(r.layout.objects) == 14 and top == pytest.approx(0.15)
    # a pyramid with four layers is no count of cubes
    assert plan("Kids love a pyramid - make one with four layers.").spec.structures[0].length != 2
    # "a wall with 10 cubes in it, 5 along the bottom": 'in it' related nothing (partial)
    _built_as_said("a wall with 10 cubes in it, 5 along the bottom", ["wall"], [2] * 5)
    # "a 3 by 3 platform with a little pyramid on it, 2 levels": beside it (partial)
    r = _built_as_said("a 3 by 3 platform with a little pyramid on it, 2 levels",
                       ["grid", "pyramid"], None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["on_top_of"]


def test_walls_facing_each_other_one_more_on_it_and_a_tall_one_and_the_other():
    # "two walls … facing each other across a 3-cube gap": end to end, 'facing' unused (partial)
    r = _built_as_said("two walls, 3 long and 2 high, facing each other across a 3-cube gap",
                       ["wall", "wall"], [2] * 6)  # fmt: skip
    xs = sorted({x for x, _ in _columns(r)})
    assert len(xs) == 2 and xs[1] - xs[0] == pytest.approx(0.2)  # parallel, 3 cubes between
    # "Put two more on it. Then one more.": a second tower (partial)
    _built_as_said("Make a tower of 3. Put two more on it. Then one more.", ["tower"], [6])
    # "two towers, a tall one of 6 and the other one 2": two towers of 1 (partial)
    r = _built_as_said("two towers, a tall one of 6 and the other one 2; put the tall one on the "
                       "left", ["tower", "tower"], [2, 6])  # fmt: skip
    left = max(_columns(r).items(), key=lambda kv: kv[0][1])  # left is +y
    assert left[1] == 6


def test_places_said_by_the_robot_and_edges_and_a_change_with_nothing_before_it():
    # "in the corner closest to the robot on its right": the front left corner, silently
    r = _built_as_said("Put a tower of 3 at the centre, and a tower of 5 in the corner closest "
                       "to the robot on its right.", ["tower", "tower"], [3, 5])  # fmt: skip
    assert r.spec.structures[1].region == "front right"
    # "the high part is at the back": climbing to the left
    r = _built_as_said("Staircase with 3 step, the high part is at the back.", ["staircase"], None)
    cols = sorted(_columns(r).items())  # front (small x) first
    assert [h for _, h in cols] == [1, 2, 3]
    # "long side along the back edge": the long side ran front to back
    r = _built_as_said("Make a slab 2 by 4 in the back, long side along the back edge.", ["grid"],
                       [1] * 8)  # fmt: skip
    assert len({x for x, _ in _columns(r)}) == 2 and len({y for _, y in _columns(r)}) == 4
    # "as far from the robot as it goes": 7.5 cm short of the back edge
    r = _built_as_said("Slab 3 by 3 as far from the robot as it goes.", ["grid"], [1] * 9)
    assert r.spec.structures[0].edge == ("back",)
    # "make the wall longer um by two" with nothing before: a wall 2 long, silently
    with pytest.raises(SpecError, match="none is named before it"):
        read("make the wall longer um by two")
    # "a wall of 4, then make the wall longer by two": its 6 parts, 3 long, silently
    r = _built_as_said("a wall of 4, then make the wall longer by two", ["wall"], [2] * 6)
    assert r.spec.structures[0].length == 6


def test_everyday_words_around_sizes_places_and_pairs():
    # each was 'partial' for a word left unused, or built something else, silently
    for command, shapes, heights in (
        ("A ring of cubes, one layer, outside size 3 by 3.", ["enclosure"], [1] * 8),
        ("build a staircase that goes up 25 cm", ["staircase"], [1, 2, 3, 4, 5]),
        ("Build three towers in a row - 2, 4 and 6 cubes high - with one cube of space between "
         "neighbours", ["tower"] * 3, [2, 4, 6]),
        ("Tower of 3, not in the front and not in the back, in the middle line", ["tower"], [3]),
        ("Build pyramid with 3 level and in the front of it one tower of 2", ["pyramid", "tower"],
         None),
        ("small tower (2) on the left, tall tower (8) on the right", ["tower", "tower"], [2, 8]),
        ("tower 5 cubes and next it a tower 3 cubes, they must touch", ["tower", "tower"], [3, 5]),
    ):  # fmt: skip
        _built_as_said(command, shapes, heights)
    # "a 2x2 block in each of the 4 corners of the table": one block in the middle, silently
    r = _built_as_said("stick a 2x2 block in each of the 4 corners of the table", ["block"] * 4,
                       [1] * 16)  # fmt: skip
    assert {s.region for s in r.spec.structures} == {
        "back left", "back right", "front left", "front right"
    }  # fmt: skip
    # "circling back on the demo layout": the staircase at the back, silently
    r = _built_as_said("Hi all, circling back on the demo layout. Could we get a staircase of 5 "
                       "steps in the centre?", ["staircase"], None)  # fmt: skip
    assert r.spec.structures[0].region == "centre"
    # "Two walls 4 long and 2 high, one at the front and one at the back": four walls, silently
    r = _built_as_said("Two walls 4 long and 2 high, one at the front and one at the back, both "
                       "running left to right.", ["wall", "wall"], None)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["front", "back"]
    # "that does not climb towards the left or the right": to the right, silently
    r = _built_as_said("Make a staircase of 4 steps that does not climb towards the left or the "
                       "right.", ["staircase"], None)  # fmt: skip
    assert r.spec.structures[0].axis == "x"
    # "an L shpae with amrs of 5": 'amrs' unused, an L 3 by 3
    r = _built_as_said("an L shpae with amrs of 5", ["l_shape"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 5)


def test_a_tower_for_each_of_three_walls_in_a_square_and_the_floor_beside_the_table():
    # "a tower for each of my 3 kids": one tower, silently
    _built_as_said("a tower for each of my 3 kids please, all different heights, in a line",
                   ["tower"] * 3, [2, 3, 4])  # fmt: skip
    # "put tower of 4 on the corner of it": at the table's back left corner, silently
    r = _built_as_said("First you build slab 3x3. After, you put tower of 4 on the corner of it.",
                       ["grid", "tower"], None)  # fmt: skip
    assert [rel.kind for rel in r.spec.relations] == ["on_top_of"]
    # "Four walls, 4 long, 2 high, in a square so they box in an empty space": six structures
    r = _built_as_said("Four walls, 4 long, 2 high, in a square so they box in an empty space.",
                       ["enclosure"], [2] * 12)  # fmt: skip
    # "on the floor next to the table": built on the table, silently
    assert plan("put a 3-high tower on the floor next to the table").status == "partial"
    # "the three to stand in one line": a row of 3 besides, silently
    r = plan("A tower of four cubes shall stand between two towers of two cubes each, the three "
             "to stand in one line.")  # fmt: skip
    assert [s.shape for s in r.spec.structures] == ["tower"] * 3


def test_two_changes_in_one_step_a_cube_count_and_a_place_pointed_at():
    # "Take 3 off and move it to the front left": still 6 high, silently
    r = _built_as_said("Tower of 6 at the back right. Take 3 off and move it to the front left.",
                       ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "front left"
    # "Staircase. Cube count: exactly 10.": 10 steps, silently
    _built_as_said("Staircase. Cube count: exactly 10.", ["staircase"], [1, 2, 3, 4])
    # "Let's raise the middle one to 4": nothing raised, silently
    _built_as_said("Three towers in a row, left to right: 4, 2, 4. Let's raise the middle one to "
                   "4.", ["tower"] * 3, [4, 4, 4])  # fmt: skip
    # "put a tower um over there": a tower in the middle, silently
    r = plan("put a tower um over there")
    assert r.status == "partial" and any("cannot see" in n for n in r.notes)


def test_towers_on_top_at_each_end_and_cubes_removed_from_one_named_by_side():
    # "put a tower of 2 at each end on top": refused, the relations read as a cycle
    r = _built_as_said("wall 4 long 2 high then put a tower of 2 at each end on top",
                       ["wall", "tower"], None)  # fmt: skip
    assert sorted(_columns(r).values()) == [2, 2, 4, 4]
    # "remove two cubes from the one on the right": refused as taking parts out (partial)
    r = _built_as_said("First make two towers of 4 side by side, one cube apart. Then remove two "
                       "cubes from the one on the right.", ["tower", "tower"], [2, 4])  # fmt: skip
    right = min(_columns(r).items(), key=lambda kv: kv[0][1])  # right is -y
    assert right[1] == 2
    # "Keep everything on the right-hand side — a 3 by 3 slab over there": the place said
    r = _built_as_said("Keep everything on the right-hand side — a 3 by 3 slab over there, one "
                       "layer.", ["grid"], [1] * 9)  # fmt: skip


def test_a_beam_across_two_towers_named_in_sentences_of_their_own():
    # "Make a tower of 3. … one more tower of 3 at right of it … put a beam across them": the
    # beam was dropped ('them' named only the first tower)
    for last in ("put a beam across them.", "put beam on both."):
        r = _built_as_said("Make a tower of 3. After this, make one more tower of 3 at right of "
                           f"it, with gap 1 cube. After this, {last}", ["bridge"],
                           None)  # fmt: skip
        assert r.spec.structures[0].height == 3


def test_moves_said_with_a_pronoun_or_a_distance_and_places_swapped():
    # "Then you move him to the right side": refused as moving what was built (partial)
    r = _built_as_said("Make a tower of 3 cube on the left side. Then you move him to the right "
                       "side.", ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "right"
    # "shift the whole thing to the back": likewise
    r = _built_as_said("A 2 by 2 block, 2 high, at the front. Add another layer, then shift the "
                       "whole thing to the back.", ["block"], [3] * 4)  # fmt: skip
    assert r.spec.structures[0].region == "back"
    # "slide it left by 2 cubes": likewise
    r = plan("Place a tower, 3 high, at x 50 cm, y 30 cm. Then slide it left by 2 cubes.")
    assert r.spec.structures[0].at_y == pytest.approx(0.4)
    # "Swap their places", "change the place of them": likewise
    r = _built_as_said("Tower of 2 at the back and tower of 6 at the front. Swap their places.",
                       ["tower", "tower"], [2, 6])  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["front", "back"]


def test_a_count_removed_in_a_sentence_of_its_own():
    # "Remove 1." between other changes: refused as taking parts out (partial)
    _built_as_said("a tower of 4. remove 1.", ["tower"], [3])
    r = _built_as_said("row 6. remove 2.", ["row"], [1] * 4)
    # the count of a staircase said on its own: its steps were 10
    _built_as_said("Staircase. Cube count: exactly 10.", ["staircase"], [1, 2, 3, 4])
    # a count said after sized structures stays a claim, checked
    r = plan("a tower of 5 and a wall 4 long, cube count 13")
    assert r.status == "success" and any("holds" in n for n in r.notes)


def test_edges_without_the_a_coordinate_pair_and_revisions_of_a_size():
    # "20 cm from right edge": read as the tower's height (partial)
    r = _built_as_said("Make a tower of 3, 15 cm from the back edge and 20 cm from right edge.",
                       ["tower"], [3])  # fmt: skip
    s = r.spec.structures[0]
    assert (s.at_x, s.at_y) == (pytest.approx(0.65), pytest.approx(0.25))
    # "(x, y) = (45 cm, 30 cm)": the 30 cm read as the height (partial)
    r = _built_as_said("Tower H=5 at (x, y) = (45 cm, 30 cm).", ["tower"], [5])
    assert (r.spec.structures[0].at_x, r.spec.structures[0].at_y) == (0.45, 0.3)
    # "Revision B: length 7", "Is too tall, make 1 layer less": not read (partial)
    r = _built_as_said("Wall length 5, height 2, left-right. Revision B: length 7.", ["wall"], None)
    assert r.spec.structures[0].length == 7
    for command in ("I want wall 5 long, 3 tall. Is too tall, make 1 layer less.",
                    "I want wall 5 long, 3 tall. make it one layer lower"):  # fmt: skip
        # (the second was made 1 high, silently)
        r = _built_as_said(command, ["wall"], [2] * 5)


def test_a_cube_on_each_pillar_and_a_position_said_before_the_item():
    # "Raise the whole thing by adding one cube to each pillar": a loose cube besides, silently
    r = _built_as_said("Bridge: two pillars of 3 with a beam across. Raise the whole thing by "
                       "adding one cube to each pillar.", ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].height == 4
    # "Position: 5 cm from the front edge, … Item: row of 6": the row in the middle, silently
    r = _built_as_said("Position: 5 cm from the front edge, centred left-right. Item: row of 6, "
                       "left-right.", ["row"], [1] * 6)  # fmt: skip
    assert r.spec.structures[0].at_x == pytest.approx(0.25)


def _cube_on_the_beam(r):
    """The beam's part and the cube standing on it, centred over it."""
    beam = next(o for o in r.layout.objects if max(o.size) > 0.06)
    top = max(r.layout.objects, key=lambda o: o.position[2])
    assert top is not beam and top.position[2] > beam.position[2]
    assert top.position[:2] == pytest.approx(beam.position[:2])
    return beam


def test_a_beam_said_across_the_top_of_towers_said_before_it():
    # "then a beam across the top": the beam named nothing and was dropped (partial)
    for command in ("two towers of five with one cube of space between them, then a beam across "
                    "the top", "two towers of 5, beam across", "two columns of 3, beam across "
                    "the top", "2 twrs ht 3, 1 clr, beam across top",
                    "two towers of 4, a beam on top"):  # fmt: skip
        r = _built_as_said(command, ["bridge"], None)
        heights = sorted(_columns(r).values())
        assert heights[-2:] == [heights[-1]] * 2 and heights[-1] in (3, 4, 5)
    # a beam held up by towers, a bridge's own lintel, pillars said in the plural only
    _built_as_said("a beam supported by two 3-cube towers", ["bridge"], [1, 3, 3])
    _built_as_said("a gate made of two 4-cube posts and a lintel", ["bridge"], [1, 4, 4])
    _built_as_said("pillars of 2, beam on top, bridge", ["bridge"], [1, 2, 2])
    _built_as_said("posts 3 high, beam on top", ["bridge"], [1, 3, 3])
    # a slab on a slab is not a beam on it
    r = plan("He'd like a slab 2 by 3 and, on top of it, a smaller slab 1 by 2, like a cake.")
    assert [s.shape for s in r.spec.structures] == ["grid", "grid"]
    assert r.spec.relations and r.spec.relations[0].kind == "on_top_of"


def test_a_cube_on_the_beam_that_joins_two_towers():
    # "… put a beam across them. Finally, put a single cube on the middle of the beam": the
    # cube was read as a third tower joining them (partial) or stood beside them
    for command in ("First build two towers of four a cube apart. After that, put a beam across "
                    "them. Finally, put a single cube on the middle of the beam.",
                    "a beam laid across two towers of 4 with a cube on the middle of the beam",
                    "two towers of 4 with a beam across them and a cube on the middle of the beam",
                    "two towers of 3, a beam across them, a cube on the beam, centred",
                    "two towers of 3 one cube apart with a beam on top, then a cube on the beam",
                    "a beam supported by two 3-cube towers, with one cube sitting on the middle "
                    "of the beam"):  # fmt: skip
        r = _built_as_said(command, ["bridge", "tower"], None)
        _cube_on_the_beam(r)
    # what follows the beam is a structure of its own
    r = _built_as_said("two towers of 4 joined by a beam, a pyramid to the left",
                       ["bridge", "pyramid"], None)  # fmt: skip
    # a trailing word about the beam SDI does not use is reported
    r = plan("two towers of 3, a beam across the top, then a cube on the beam, over the middle "
             "AC: it's all one piece")  # fmt: skip
    assert r.status == "partial" and [s.shape for s in r.spec.structures] == ["bridge", "tower"]


def test_one_structure_named_twice_in_a_phrase_is_one():
    # "Tower, 250 mm tall, single column": two towers were built (partial)
    r = _built_as_said("Tower, 250 mm tall, single column, for the vision calibration rig.",
                       ["tower"], [5])  # fmt: skip
    r = _built_as_said("My daughter is asking for a big wall in the back, 8 long and 4 high, "
                       "it's her castle wall she says.", ["wall"], [4] * 8)  # fmt: skip
    assert any("named twice" in n for n in r.notes)
    # the group counted before, sized again by name: its size (a third wall was built)
    for command in ("A tower of 6 between two walls, each wall 3 long and 3 high.",
                    "a tower of 6 between two walls, the walls 3 long and 3 high"):  # fmt: skip
        r = _built_as_said(command, ["tower", "wall", "wall"], None)
        assert [(s.length, s.height) for s in r.spec.structures[1:]] == [(3, 3), (3, 3)]
    # two said as two stay two
    r = plan("a tower of 5 and a tower")
    assert len(r.spec.structures) == 2
    assert len(plan("tower 3, tower 5").spec.structures) == 2


def test_a_count_before_a_size_word_counts_the_structures():
    # "one tall tower" was a tower 1 high, silently; "two tall towers" one tower 2 high
    for command, n in (("one tall tower", 1), ("one really tall tower", 1), ("one big tower", 1),
                       ("two tall towers", 2), ("2 tall towers", 2),
                       ("My kid just wants one really tall tower, as tall as the robot can do.",
                        1)):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        heights = [s.height for s in r.spec.structures]
        assert len(heights) == n and all(h is not None and h >= 5 for h in heights), command
    # "as tall as the robot can do" after "really tall": the tallest that fits (6 high was built)
    _built_as_said("My kid just wants one really tall tower, as tall as the robot can do.",
                   ["tower"], [10])  # fmt: skip
    r = _built_as_said("one tall tower and one short tower", ["tower", "tower"], None)
    assert r.spec.structures[0].height > r.spec.structures[1].height
    # a number with an article before it is the size: "a 5 tall tower"
    _built_as_said("a 5 tall tower", ["tower"], [5])
    _built_as_said("two tall towers of 5", ["tower", "tower"], [5, 5])


def test_places_one_each_after_a_shared_layer_count_and_sizes_said_with_on_and_and():
    # "Two 3x3 slabs, 1 layer each, one at front-left, one at back-right": both front left
    r = _built_as_said("Two 3x3 slabs, 1 layer each, one at front-left, one at back-right.",
                       ["grid", "grid"], [1] * 18)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["front left", "back right"]
    # "block 2 on 2 on 2": the third side was dropped (one layer, silently)
    r = _built_as_said("Put block 2 on 2 on 2 in middle of table.", ["block"], [2] * 4)
    # "base is four and four": a pyramid with a 4 by 4 base (a one-wide stepped shape)
    r = _built_as_said("Make for me one pyramid, base is four and four.", ["pyramid"], None)
    assert r.spec.structures[0].length == 4
    xs = {round(o.position[0], 3) for o in r.layout.objects if o.position[2] < 0.05}
    ys = {round(o.position[1], 3) for o in r.layout.objects if o.position[2] < 0.05}
    assert (len(xs), len(ys)) == (4, 4)


def test_the_rise_of_each_step_is_not_the_staircase_height():
    # "4 risers of 5 cm each": read as the whole staircase 5 cm high (one cube, silently)
    r = _built_as_said("Staircase: 4 risers of 5 cm each, ascending toward the left.",
                       ["staircase"], [1, 2, 3, 4])  # fmt: skip
    assert r.spec.structures[0].steps == 4
    # a rise SDI's parts cannot make is reported, the steps kept
    r = plan("a staircase, 5 steps of 10 cm each")
    assert r.status == "partial" and r.spec.structures[0].steps == 5


def test_a_structure_then_one_here_and_one_there_is_two():
    # "each want a tower, one on the left and one on the right": a third tower, silently
    r = _built_as_said("Our twins each want a tower, one on the left and one on the right, both "
                       "5 high.", ["tower", "tower"], [5, 5])  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    # "just a cube, one single cube": the cube said again (two were built)
    _built_as_said("ok so nothing fancy just a cube, one single cube, front left, and then "
                   "that's it", ["tower"], [1])  # fmt: skip
    # "in a line 1 gap": the gap's size (a row 1 long was built beside the towers)
    r = _built_as_said("3 twrs of 4 in a line 1 gap", ["tower"] * 3, [4, 4, 4])
    assert r.spec.gap_m == pytest.approx(0.05)


def test_on_the_corner_of_the_structure_before_and_what_the_parts_make():
    # "… and a tower of 3 on its corner": stood apart from the L, silently; "Then add a tower of
    # 3 on the corner" was read as a corner of the table
    for command in ("an L shape 4 by 4, and a tower of 3 on its corner",
                    "L shape 4x4 flat, 1 high. Then add a tower of 3 on the corner"):  # fmt: skip
        r = _built_as_said(command, ["l_shape", "tower"], None)
        assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    r = _built_as_said("put a tower on the corner", ["tower"], None)
    assert r.spec.structures[0].region is not None and not r.spec.relations
    # "… to make a gate": what the towers and beam make, not a second bridge
    r = _built_as_said("two stacks of five cubes one at the front one at the back and then put a "
                       "beam across the tops to make a gate", ["bridge"], None)  # fmt: skip
    assert r.spec.structures[0].axis == "x"
    assert any(n.startswith("'to make a gate': holds") for n in r.notes)
    _built_as_said("a tower of 3, then I want to make a wall next to it", ["tower", "wall"], None)


def test_on_the_beam_said_after_it_and_changes_of_the_towers_said_by_name():
    # "…, and on the beam a stack of three": the stack stood apart, silently
    r = _built_as_said("Two stacks of two, a beam across their tops, and on the beam a stack of "
                       "three.", ["bridge", "tower"], None)  # fmt: skip
    _cube_on_the_beam(r)
    _built_as_said("two columns of two and one beam", ["bridge"], [1, 2, 2])
    # "make the towers 4 high": a third tower was built, silently
    _built_as_said("two towers of 2. make the towers 4 high", ["tower", "tower"], [4, 4])
    _built_as_said("Two posts of two and a beam on them. Now make the posts four high.",
                   ["bridge"], [1, 4, 4])  # fmt: skip


def test_layers_said_by_their_size_in_turn():
    # "A row of 5, then 3 on it, then 1": read as five towers joined by a beam (failure)
    for command, levels in (("A row of 5, then 3 on it, then 1.", [5, 3, 1]),
                            ("a row of four, then three on top, then two, then one", [4, 3, 2, 1]),
                            ("4x4, then 3x3, then 2x2, then one cube", [16, 9, 4, 1])):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        by_level: dict[float, int] = {}
        for o in r.layout.objects:
            by_level[round(o.position[2], 3)] = by_level.get(round(o.position[2], 3), 0) + 1
        assert [n for _, n in sorted(by_level.items())] == levels, command


def test_sizes_said_as_one_and_a_count_heading_its_list():
    # "three towers: a little one, a middle one and a big one": three towers 1 high, silently
    for command in ("My daughter wants three towers: a little one, a middle one and a big one.",
                    "three towers: a small tower, a medium tower and a big tower"):  # fmt: skip
        r = _built_as_said(command, ["tower"] * 3, None)
        heights = [s.height for s in r.spec.structures]
        assert heights == sorted(heights) and heights[0] < heights[-1] and heights[0] >= 2
    r = _built_as_said("a tower of 5 and a small one next to it", ["tower", "tower"], None)
    assert r.spec.structures[1].height < 5
    # a correction of the base: "Correction, base three by three" (a 3x3 slab was added)
    r = _built_as_said("Pyramid, base four by four. Correction, base three by three. Over.",
                       ["pyramid"], None)  # fmt: skip
    assert r.spec.structures[0].length == 3
    # what the structures are said to become is checked, never dropped: a ring that "becomes a
    # solid plate" is not what was built
    r = plan("a square ring, four by four, one cube tall, and then it fills in the middle so it "
             "becomes a solid plate")  # fmt: skip
    assert r.status == "partial" and any("becomes a solid plate" in n for n in r.notes)


def test_an_opening_a_height_after_taller_what_it_is_for_and_an_empty_inside():
    # "Gate, opening two cubes wide": the gap between the posts was dropped, silently
    r = _built_as_said("Gate, opening two cubes wide, posts four high. Over.", ["bridge"], None)
    assert r.spec.structures[0].span == 2
    # "Make the left one taller, five": made 4 high, silently
    r = _built_as_said("Two towers of three, a cube apart. Make the left one taller, five.",
                       ["tower", "tower"], [3, 5])  # fmt: skip
    # "with the taller one standing behind": it stood in front, silently
    r = _built_as_said("Two little towers, one of five and one of two, with the taller one "
                       "standing behind.", ["tower", "tower"], [2, 5])  # fmt: skip
    tall = max(r.layout.objects, key=lambda o: o.position[2])
    short = min(r.layout.objects, key=lambda o: o.position[2] if o.position[:2] != tall.position[:2]
                else 9)  # fmt: skip
    assert tall.position[0] > short.position[0]  # back is +x
    # "for my garden scene": a garden enclosure was built with the wall's sizes, silently
    r = _built_as_said("I'd love a little wall for my garden scene, seven long and two high.",
                       ["wall"], [2] * 7)  # fmt: skip
    # "inside empty": a solid slab was built
    _built_as_said("Square of cubes, inside empty, side is five, one layer.", ["enclosure"],
                   [1] * 16)  # fmt: skip


def test_the_side_of_one_said_beside_the_one_before_picks_it():
    # "a tower of five one cube to its right. Make the right one shorter, three": the left one
    # was changed, silently
    r = _built_as_said("Tower of two, and a tower of five one cube to its right. Make the right "
                       "one shorter, three.", ["tower", "tower"], [2, 3])  # fmt: skip
    by_y = [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])]
    assert by_y == [3, 2]  # right (small y) first: the right one changed
    r = _built_as_said("a tower of 2 and a tower of 5 to its left. make the left one 3",
                       ["tower", "tower"], [2, 3])  # fmt: skip
    by_y = [h for _, h in sorted(_columns(r).items(), key=lambda kv: kv[0][1])]
    assert by_y == [2, 3]
    # not said: the first named is the one on the right, as SDI lines them up
    _built_as_said("two towers of 2 and 5. make the right one 3", ["tower", "tower"], [3, 5])


def test_counts_before_a_singular_noun_and_sizes_by_ordinal():
    # "Two wall, each six long and two high": one wall 2 high, silently
    r = _built_as_said("Two wall, each six long and two high", ["wall", "wall"], None)
    assert [(s.length, s.height) for s in r.spec.structures] == [(6, 2), (6, 2)]
    _built_as_said("two tower, each 3 high", ["tower", "tower"], [3, 3])
    # "two towers, first 3, second 6": both 3 high; "the first one 3 and the second one 6":
    # the second 1 high — silently
    for command in ("two towers, first 3, second 6",
                    "two towers, the first one 3 and the second one 6"):  # fmt: skip
        _built_as_said(command, ["tower", "tower"], [3, 6])
    # "put second behind of first": the relation was dropped
    r = _built_as_said("I want two tower, first is 3, second is 6, put second behind of first.",
                       ["tower", "tower"], [3, 6])  # fmt: skip
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "back")]


def test_touching_denied_in_its_clause_keeps_the_gap():
    # "I don't want them touching": read as no gap between them, silently
    r = _built_as_said("two pyramids of 3 levels, I don't want them touching.",
                       ["pyramid", "pyramid"], None)  # fmt: skip
    assert r.spec.gap_m != 0.0
    xs = sorted({round(o.position[1], 3) for o in r.layout.objects})
    gaps = [b - a for a, b in itertools.pairwise(xs)]
    assert max(gaps) > 0.05 + 1e-6  # an empty column between them
    r = _built_as_said("two towers of 3 side by side, touching", ["tower", "tower"], [3, 3])
    assert r.spec.gap_m == 0.0


def test_a_slab_on_four_legs_is_a_table_and_a_height_after_taller():
    # "A flat three by four slab on four legs of three cubes": a slab and a tower (failure)
    r = _built_as_said("A flat three by four slab on four legs of three cubes.", ["canopy"], None)
    assert r.spec.structures[0].height == 3
    # "make it taller, 5": the height, not the wall's length
    r = _built_as_said("a wall 4 long 3 high, make it taller, 5", ["wall"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (4, 5)
    # "Table for the packing station mock-up: …": what it is for built nothing of its own
    _built_as_said("Table for the packing station mock-up: four legs two high, top on them. Over.",
                   ["canopy"], None)  # fmt: skip


def test_changes_said_plainly_after_the_structure():
    # each was reported as a change SDI cannot make, or dropped
    _built_as_said("Build a tower of six. ... Copy that, now pull two off the top. Over.",
                   ["tower"], [4])  # fmt: skip
    r = _built_as_said("Row of eight. Take off the last three.", ["row"], [1] * 5)
    r = _built_as_said("Tower of four at x 0.40, y 0.30. Move it back by 2.", ["tower"], [4])
    assert (r.spec.structures[0].at_x, r.spec.structures[0].at_y) == (pytest.approx(0.5), 0.3)
    _built_as_said("Make tower of eight. No, too high, make of five.", ["tower"], [5])
    r = _built_as_said("Two towers of four, two cubes apart. Now bring them closer, one cube "
                       "apart.", ["tower", "tower"], [4, 4])  # fmt: skip
    assert r.spec.gap_m == pytest.approx(0.05)


def test_it_ends_a_relation_before_and_a_structure_after_it():
    # "a 2x2 layer in the middle of it, and one cube on top": "it, and a cube" was one phrase
    # (a ring was built around the layer, partial)
    r = _built_as_said("a 4x4 layer, a 2x2 layer in the middle of it, and one cube on top.",
                       ["grid", "grid", "tower"], None)  # fmt: skip
    assert [(x.kind, x.subject, x.object) for x in r.spec.relations] == [
        ("on_top_of", 1, 0), ("on_top_of", 2, 1)]  # fmt: skip


def test_call_signs_and_the_structures_said_again():
    # "Base, this is floor. …": a grid was built for "Base" (partial)
    r = _built_as_said("Base, this is floor. Block two by two by two, stack of three on top, "
                       "centred. Over.", ["block", "tower"], None)  # fmt: skip
    assert [x.kind for x in r.spec.relations] == ["on_top_of"]
    # "…, just the stacks": a third stack was built (partial)
    _built_as_said("Two stacks of five, no beam, just the stacks, two cubes apart. Over.",
                   ["tower", "tower"], [5, 5])  # fmt: skip


def test_corrections_in_a_chain_lists_without_commas_and_arches_of_posts_and_a_beam():
    # "sorry, 3x3, sorry again, 5x5": a 3x3 pyramid and a 5x5 slab, silently
    r = _built_as_said("Pyramid with a 4x4 base, sorry, 3x3, sorry again, 5x5.", ["pyramid"], None)
    assert r.spec.structures[0].length == 5
    # "Tower of 5, no 6, ok 4": 6 built, the 4 reported
    _built_as_said("Tower of 5, no 6, ok 4.", ["tower"], [4])
    _built_as_said("a tower of 3, ok", ["tower"], [3])
    # "three towers um two three and four high": all three 4 high, silently
    _built_as_said("three towers um two three and four high in a row left to right",
                   ["tower"] * 3, [2, 3, 4])  # fmt: skip
    # "a small archway: two pillars of three, a beam across": SDI's corbelled arch, 5 high
    r = _built_as_said("I'd really like a small archway for my diorama: two pillars of three, a "
                       "beam across, and nothing else.", ["bridge"], [1, 3, 3])  # fmt: skip
    assert any("posts and a beam as a bridge" in n for n in r.notes)
    assert [s.shape for s in plan("an arch with legs of 3").spec.structures] == ["arch"]


def test_a_quantity_of_parts_and_a_depth_by_its_letter():
    # "Row, qty 7 cubes": seven rows, silently
    _built_as_said("Row, qty 7 cubes, along Y, front edge.", ["row"], [1] * 7)
    # "shape=slab; w=3; d=5": the depth dropped, silently (3 by 3)
    _built_as_said("shape=slab; w=3; d=5; layers=1", ["grid"], [1] * 15)


def test_the_long_side_said_along_an_axis():
    # "arranged 3 x 4, one layer, long side along x": the 3 was laid along x, silently
    for command, along_x in (("Quantity 12 cubes, arranged 3 x 4, one layer, long side along x.",
                              4), ("a 3x4 slab, short side along x", 3)):  # fmt: skip
        r = _built_as_said(command, ["grid"], [1] * 12)
        assert len({round(o.position[0], 3) for o in r.layout.objects}) == along_x


def test_corners_one_each_hyphenated_corners_arms_along_each_side_and_before_as_in_front():
    # "each one in one corner of the table": the four stood in a line, silently
    r = _built_as_said("Four towers of three, each one in one corner of the table, and in the "
                       "centre a tower of six.", ["tower"] * 5, [3, 3, 3, 3, 6])  # fmt: skip
    assert sorted(s.region or "" for s in r.spec.structures) == [
        "back left", "back right", "centre", "front left", "front right"]  # fmt: skip
    # "move it to the front-left spawn point": moved to the front only, silently
    r = _built_as_said("Spawn a tower of 4 blocks, then move it to the front-left spawn point.",
                       ["tower"], [4])  # fmt: skip
    assert r.spec.structures[0].region == "front left"
    # "three cubes along each side": a 2 by 2 L, silently
    r = _built_as_said("an L shape, like the letter, three cubes along each side, flat on the "
                       "table.", ["l_shape"], [1] * 5)  # fmt: skip
    # "Before the wall of five, …, a tower of four": the tower stood to the wall's side
    r = _built_as_said("Before the wall of five, at distance of one cube, a tower of four.",
                       ["tower", "wall"], None)  # fmt: skip
    assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "front")]


def test_ordinals_in_a_line_said_from_left_toward_right():
    # "Three towers in line, the first of two, …, from left toward right": all 2 high, the
    # right read as a place
    r = _built_as_said("Three towers in line, the first of two, the second of four, the third of "
                       "six, from left toward right.", ["tower"] * 3, [2, 4, 6])  # fmt: skip
    left_to_right = [h for _, h in sorted(_columns(r).items(), key=lambda kv: -kv[0][1])]
    assert left_to_right == [2, 4, 6]


def test_by_said_as_for_and_a_relation_in_a_key_value_line():
    # "On the block of two for two, a small tower of three": a block 2 by 1, silently
    r = _built_as_said("On the block of two for two, a small tower of three you put, in the "
                       "middle.", ["tower", "block"], None)  # fmt: skip
    assert (r.spec.structures[1].length, r.spec.structures[1].width) == (2, 2)
    # "on=block 2x2x2": the tower stood beside the block, silently — now reported
    assert plan("shape=tower; h=2; on=block 2x2x2").status != "success"


def test_who_places_it_said_first_and_an_axis_by_its_key():
    # "Now it will place one cube in each of the four corners": one cube, silently
    r = _built_as_said("Now it will place one cube in each of the four corners of the table.",
                       ["tower"] * 4, [1] * 4)  # fmt: skip
    assert len({s.region for s in r.spec.structures}) == 4
    # "axis=x": dropped as chatter (the row ran left to right, silently)
    r = _built_as_said("shape=row; n=5; axis=x; pos=right", ["row"], [1] * 5)
    assert r.spec.structures[0].axis == "x"


def test_structures_picked_by_the_sizes_said_for_them():
    # "The 2 goes behind the 5": both at the back, side by side (or the 5 behind), silently
    for command, side in (("Two towers: 2 and 5. The 2 goes behind the 5.", "back"),
                          ("Two towers: 2 and 5. The 2 goes behind the 5. No, in front.", "front"),
                          ("Two towers of 2 and 5, the 2 behind the 5", "back")):  # fmt: skip
        r = _built_as_said(command, ["tower", "tower"], [2, 5])
        (rel,) = r.spec.relations
        assert (r.spec.structures[rel.subject].height, rel.side) == (2, side), command
    # named with articles, read by the rule for them: never two more towers
    r = plan("2 towers, a 5 and a 3, the 5 behind the 3, gap of 2 cubes")
    assert len(r.spec.structures) == 2


def test_a_beam_said_last_and_a_copy_on_top_of_towers_a_beam_joins():
    # "… and bridge them with a beam" stays read by its verb (the rule for a beam said last
    # took the beam from it and left no towers to join)
    _built_as_said("two stacks of 3 and bridge them with a beam", ["bridge"], [1, 3, 3])
    # "… then another cube on top" of towers a beam joins: an IndexError (the phrases counted the
    # two towers the bridge replaced)
    r = _built_as_said("two towers of 2 with a beam across them, then another cube on top",
                       ["bridge", "row"], None)  # fmt: skip
    _cube_on_the_beam(r)


def test_a_comparison_then_a_number_stays_a_gap_or_an_unread_change():
    # "a tower one shorter, 2 cubes apart": the gap was read as a height (0.05 m, silently)
    r = _built_as_said("a 3 cube tower and a tower one shorter, 2 cubes apart", ["tower", "tower"],
                       [2, 3])  # fmt: skip
    assert r.spec.gap_m == pytest.approx(0.1)
    # "… you make higher, 6" with nothing made: reported, never a wall 6 long (silently)
    r = plan("Make four tower, all of 3, in one line with space one cube. The first and the "
             "second you make higher, 6.")  # fmt: skip
    assert r.status == "partial"
    # an arch's opening: its corbels narrow it, so the span is not read from it
    assert plan("Build an arch whose opening is two cubes wide.").status != "success"


def test_a_copy_said_after_one_on_a_bridge_made_of_towers_stands_on_it():
    # the towers a beam joins became one bridge, and the phrases kept counting the towers: "and
    # another" after a cube on the bridge stood apart on the table (composition.relate renumbers
    # the phrases it keeps)
    r = _built_as_said("two towers of 3 joined by a beam, then a cube on top of it. And another.",
                       ["bridge", "tower", "tower"], None)  # fmt: skip
    beam = next(o for o in r.layout.objects if max(o.size) > 0.06)
    above = [o for o in r.layout.objects if o.position[2] > beam.position[2]]
    assert len(above) == 2
    assert {tuple(round(v, 3) for v in o.position[:2]) for o in above} == {
        tuple(round(v, 3) for v in beam.position[:2])
    }


def test_a_staircase_step_named_by_its_place_or_its_size():
    # "next to the top step", "near the lowest step": beside that end of the staircase ('step'
    # was reported unused and the tower stood anywhere, or at the front)
    for command, end in (
        ("a staircase of 3 steps and a tower of 5 next to the top step", "high"),
        ("a staircase of 3 steps, then near the highest step a tower of 5", "high"),
        ("a staircase of 3 steps going up to the right and a tower of 2 near the lowest step",
         "low"),
    ):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert any(f"staircase's {end} end" in n for n in r.notes), command
        (rel,) = r.spec.relations
        assert rel.kind == "next_to" and r.spec.structures[rel.object].shape == "staircase"
    # "whose top step is 15 cm up", "each step being 100 mm wide": the staircase's own sizes
    r = _built_as_said("A staircase whose top step is 15 cm above the table, please.",
                       ["staircase"], [1, 2, 3])  # fmt: skip
    r = _built_as_said("A staircase of four steps, each step being 100 mm wide.", ["staircase"],
                       [1, 1, 2, 2, 3, 3, 4, 4])  # fmt: skip
    # "each step 5 cm high": the rise of each step, not the staircase 5 cm high (one cube)
    r = _built_as_said("a staircase of 3, each step 5 cm high", ["staircase"], [1, 2, 3])
    assert plan("a staircase of four steps, every step rising 10 cm").status == "partial"


def test_a_numbered_reference_to_a_line_or_a_step_of_a_procedure_is_no_size():
    # "FYI line 3 is down", "Commissioning step 14 of 22": references, not sizes or words to
    # report ('line' and 'step' made the reading partial; "of 22" a number unused)
    for command, shape in (("FYI line 3 is down, anyway: wall 4 long 3 high, thx", "wall"),
                           ("Commissioning step 14 of 22, ref. CR-0831. Action: build a staircase "
                            "of 3 steps.", "staircase")):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        assert [s.shape for s in r.spec.structures] == [shape]
    assert any("'step 14 of 22': a reference number" in n for n in r.notes)
    # a line or a step with a size is still read: "a line 5 long", "towers in a line 3 apart"
    _built_as_said("a line 5 long", ["row"], [1, 1, 1, 1, 1])
    # numbered steps stay steps in order
    r = _built_as_said("step 1 build a wall 4 long, step 2 put a tower of 2 in front of it",
                       ["wall", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].side == "front"


def test_my_table_is_the_work_table():
    # "on the left side of my table": a table was built beside the pillar, silently
    r = _built_as_said("Four bricks high, a 1x1 pillar, on the left side of my table", ["block"],
                       [4])  # fmt: skip
    assert r.spec.structures[0].region == "left"
    # a table to build is still one
    assert plan("build my table with legs of 2").spec.structures[0].shape == "canopy"


def test_a_refusal_of_parts_on_a_face_is_not_read_as_nothing_on_top():
    # "no cube on the top layer's corners": the rule for "no beam on top" left out "no cube on
    # the top", said it had done so, and built the full block (silently)
    r = plan("A block 3 by 2 by 2 high with no cube on the top layer's corners.")
    assert r.status != "success"
    assert not any(n.startswith("left out what is not wanted") for n in r.notes)
    r = _built_as_said("two towers of 3 but no beam across them", ["tower", "tower"], [3, 3])
    assert any(n.startswith("left out what is not wanted") for n in r.notes)


def test_removing_the_one_on_a_side_said_with_regions():
    # "Finally remove the left one." of towers placed by region: read as a pointer to it and
    # dropped with no note (all three built, silently)
    r = _built_as_said("First a tower of three on the left, then a tower of four in the middle, "
                       "then a tower of five on the right. Finally remove the left one.",
                       ["tower", "tower"], [4, 5])  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["centre", "right"]


def test_corrections_that_replace_a_side_return_to_a_number_or_add_a_move():
    # "at the back instead of the left": the left replaced (it went back left, silently)
    r = _built_as_said("Tower of 3 on the left. Make that 5. And put it at the back instead of "
                       "the left.", ["tower"], [5])  # fmt: skip
    assert r.spec.structures[0].region == "back"
    # "No, back to 3": the number again (read as the back, silently)
    r = _built_as_said("Tower of 3. Make it 5. No, back to 3.", ["tower"], [3])
    assert r.spec.structures[0].region is None
    r = _built_as_said("Pyramid, 3 levels. Make it 4 levels. No, back to 3, but put it at the "
                       "back.", ["pyramid"], None)  # fmt: skip
    assert (r.spec.structures[0].height, r.spec.structures[0].region) == (3, "back")
    # "No, further right too": a move as well, not instead of the front
    r = _built_as_said("Arch in the centre. Move it to the front. No, further right too.",
                       ["arch"], None)  # fmt: skip
    assert r.spec.structures[0].region == "front right"


def test_a_removal_verb_left_unread_is_never_chatter():
    # "take one corner cube away" in a table's row: 'take' was reported as not about the
    # structure, and the slab built whole with status success
    r = plan("task | action\n1 | lay a 3x4 slab\n2 | take one corner cube away")
    assert r.status != "success"
    assert "ignored 'take': not used by the reading" in r.notes


def test_lists_and_speech_repeats_and_words_for_the_top():
    # "3 towers 2/4/6": the 2 was lost (two towers, silently)
    _built_as_said("3 towers 2/4/6 in a line", ["tower"] * 3, [2, 4, 6])
    # "a gap of one one cube": a cube was built from the repeated word
    _built_as_said("um three towers of two uh in a row with a gap of one one cube", ["tower"] * 3,
                   [2, 2, 2])  # fmt: skip
    # "then a single on the peak": dropped as chatter, silently
    r = _built_as_said("Base layer 3x3, second layer 2x2 on top, then a single on the peak.",
                       ["grid", "grid", "tower"], None)  # fmt: skip
    assert len(r.spec.relations) == 2
    # "4 buy 4": by (a 2x2 slab, silently)
    _built_as_said("make a slab 4 buy 4", ["grid"], [1] * 16)


def test_words_around_a_structure_that_name_no_other():
    # "in the very centre of the plinth area": a plinth was built; "An obelisk, a single column
    # of eight": one column, not a tall tower beside it
    r = _built_as_said("An obelisk, a single column of eight, in the very centre of the plinth "
                       "area.", ["tower"], [8])  # fmt: skip
    assert r.spec.structures[0].region == "centre"
    # "loves bridges": a second bridge was built
    _built_as_said("Our little one loves bridges!! Could we have a bridge with two legs, each leg "
                   "three cubes tall?", ["bridge"], None)  # fmt: skip
    # "Tolerance of one cube": no cube to build
    _built_as_said("Procedure 7: erect a column of height 0.35 m at the front-right position. "
                   "Tolerance of one cube is not acceptable.", ["tower"], [7])  # fmt: skip
    # "a 2x2 brick on top of a 2x4 brick": two levels (one 2x4 layer, silently)
    r = _built_as_said("Put a 2x2 brick on top of a 2x4 brick", ["block", "block"], None)
    assert r.spec.relations[0].kind == "on_top_of"


def test_a_structure_sized_by_the_table():
    # "a wall as wide as the table", "across the whole width of the table", "along the whole
    # front edge": as many parts as the table's side takes (the default size, silently)
    for command, shape, n in (("Build a wall as wide as the table.", "wall", 10),
                              ("a wall across the whole width of the table", "wall", 10),
                              ("a row along the whole front edge", "row", 10),
                              ("a row along the whole left edge", "row", 12)):  # fmt: skip
        r = plan(command)
        assert r.status == "success", (command, r.notes)
        (s,) = r.spec.structures
        assert (s.shape, s.length) == (shape, n), command
        assert any(f"as {n} parts long" in note for note in r.notes)


def test_a_list_said_from_one_side_a_key_refused_a_place_and_a_plate_across_towers():
    # "…, from left": the order of the line (all three in the left region, silently)
    r = _built_as_said("Build three tower in line, height of them two, three, four, from left.",
                       ["tower"] * 3, [2, 3, 4])  # fmt: skip
    assert r.spec.structures[0].region is None
    cols = _columns(r)
    assert cols[max(cols, key=lambda c: c[1])] == 2  # the tower of 2 at the left (+y)
    # "region!=centre": anywhere but the centre (built in the centre, silently)
    r = plan("shape=pyramid levels=3 region!=centre")
    assert r.spec.structures[0].region not in (None, "centre")
    # "bridge them with a 1x4 plate": the plate is their beam (laid between them)
    _built_as_said("Make two 1x1 towers of 3 bricks and bridge them with a 1x4 plate", ["bridge"],
                   None)  # fmt: skip
    # "add a cube in the middle of the top": on the bridge (at the table's centre)
    r = _built_as_said("Bridge with posts of 2. Make the posts 3. And add a cube in the middle of "
                       "the top.", ["bridge", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of"


def test_arms_said_longer_and_shorter_a_shared_coordinate_and_a_climb_towards_the_robot():
    # "the longer limb being five cubes and the shorter three": arms 5 and 3 (both 3, silently)
    r = _built_as_said("Construct the letter L in plan, the longer limb being five cubes and the "
                       "shorter three.", ["l_shape"], None)  # fmt: skip
    assert (r.spec.structures[0].length, r.spec.structures[0].width) == (5, 3)
    # "…, both at x = 0.4 m": the x of each (the first stood at the default x, silently)
    r = _built_as_said("Tower of 3 at y = 0.5 m and a tower of 5 at y = 0.1 m, both at x = 0.4 m.",
                       ["tower", "tower"], [3, 5])  # fmt: skip
    assert [s.at_x for s in r.spec.structures] == [0.4, 0.4]
    # "which go up in direction of robot": it climbs towards the front (the default way, silently)
    for command in ("Make the staircase which go up in direction of robot, four step.",
                    "Make the staircase which goes up towards the robot, four steps."):  # fmt: skip
        r = _built_as_said(command, ["staircase"], None)
        s = r.spec.structures[0]
        assert (s.axis, s.yaw_deg) == ("x", 180.0), command


def test_too_that_says_as_well_is_no_word_left_unused():
    # "and one on the right too": as well ('too' was reported unused: partial)
    _built_as_said("a tower on the left, and one on the right too", ["tower", "tower"], None)
    # "too" of a size stays material
    assert plan("a tower of 9, is it too tall").ignored == ("too",)


def test_between_two_placed_in_corners_and_a_cube_put_between_two():
    # "a tower … at the back left, a tower … at the front right, and a wall of three between
    # them": midway, each keeping its corner (all three lined up along the back, silently)
    r = _built_as_said("A tower of six at the back left, a tower of one at the front right, and a "
                       "wall of three between them.", ["tower", "tower", "wall"], None)  # fmt: skip
    assert [s.region for s in r.spec.structures] == ["back left", "front right", "centre"]
    assert not r.spec.relations
    # "and a cube between them", "put a cube between them": a cube (read as a gap, the cube
    # dropped, silently); "with a cube between them" stays a gap
    for command in ("two towers of 3 and a cube between them",
                    "two towers of 3, put a cube between them"):  # fmt: skip
        r = _built_as_said(command, ["tower", "tower", "tower"], [1, 3, 3])
        assert r.spec.gap_m is None
    r = _built_as_said("two towers of 3 with a cube between them", ["tower", "tower"], [3, 3])
    assert r.spec.gap_m == pytest.approx(0.05)


def test_a_structure_behind_them_said_with_stands_behind_the_whole_group():
    # "two towers of 2 with a row of 4 behind them": behind both, side by side (behind the second
    # only, the first set apart, silently); "behind the whole row" of towers in a row: them
    r = _built_as_said("two towers of 2 with a row of 4 behind them", ["tower", "tower", "row"],
                       None)  # fmt: skip
    assert {(rel.subject, rel.side) for rel in r.spec.relations} == {(1, "left"), (2, "back")}
    r = _built_as_said("Three towers, 1, 2 and 3 high, standing in a row from left to right, with "
                       "a wall of five, two high, behind the whole row.",
                       ["tower", "tower", "tower", "wall"], None)  # fmt: skip
    wall = next(rel for rel in r.spec.relations if rel.subject == 3)
    assert wall.side == "back"
    # "height too" in a radio call: the number, never "as well"
    r = plan("Cell, this is Control. Block, too by too, height too, position front. Over.")
    assert "ignored 'too': not used by the reading" in r.notes or r.spec.structures[0].height == 2


def test_the_base_said_again_and_a_beam_from_one_top_to_the_other():
    # "a 3 x 3 single-layer base. … a single cube on the base": on it (side by side, partial)
    r = _built_as_said("Step 1. Build a 3 x 3 single-layer base. Step 2. Place a single cube on "
                       "the base, centred.", ["grid", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of"
    # a pyramid on "the base" with no base named before: its own
    assert plan("a pyramid on the base").status == "success"
    # "a beam resting across from one top to the other": a bridge (the towers were stacked)
    _built_as_said("Two towers of four, and a beam resting across from one top to the other",
                   ["bridge"], None)  # fmt: skip


def test_a_group_said_in_an_order_keeps_it_with_a_structure_behind_them():
    # "in a row from left to right, and a wall of five behind them": 1, 2, 3 from the left (the
    # order was turned round, silently)
    r = _built_as_said("Three towers, 1, 2 and 3 high, in a row from left to right, and a wall of "
                       "five behind them.", ["tower", "tower", "tower", "wall"], None)  # fmt: skip
    towers = {k: h for k, h in _columns(r).items() if k[0] < min(c[0] for c in _columns(r)) + 0.01}
    assert [towers[k] for k in sorted(towers, key=lambda c: -c[1])] == [1, 2, 3]


def test_shapes_named_in_their_parts_and_ends():
    # "don't use any Technic beams": no beams, and never "built of cubes only" beside a beam
    r = plan("Build an arch but don't use any Technic beams, just regular bricks")
    assert r.status == "partial" and not any("built of cubes only" in n for n in r.notes)
    # "in the gap of the U": reported, not stood beside it silently; "in its hollow" of a ring
    r = plan("A U shape with arms of three and a single cube standing in the gap of the U.")
    assert r.status == "partial" and any("inside a U's opening" in n for n in r.notes)
    r = _built_as_said("a ring 5 by 5 with a tower in its hollow", ["enclosure", "tower"], None)
    assert r.spec.relations[0].kind == "around"
    # "Two bridges side by side, left and right": one on each side (both on the left)
    r = _built_as_said("Two bridges side by side, left and right", ["bridge", "bridge"], None)
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    # an L's corner is where its arms meet (another corner, which SDI chose)
    r = _built_as_said("L shape 3x3 then tower 2 on the corner", ["l_shape", "tower"], None)
    assert r.spec.relations[0].at == "bend"
    # "on either end": at each end (one end, which SDI chose)
    r = _built_as_said("Set a single cube on either end of a wall four long and two high",
                       ["tower", "wall"], [2, 2, 3, 3])  # fmt: skip
    # "another slab half as long": the other side kept (a 2-long slab of the default width)
    r = _built_as_said("A slab three by four and next to it another slab half as long.",
                       ["grid", "grid"], None)  # fmt: skip
    assert (r.spec.structures[1].length, r.spec.structures[1].width) == (3, 2)


def test_corrections_of_a_relation_a_bare_size_and_a_tower_made_taller():
    # "in front of a wall of 5. No wait, behind it. And make the tower 4.": behind, 4 high (a
    # second tower was built, the relation kept)
    r = _built_as_said("Put a tower of 2 in front of a wall of 5. No wait, behind it. And make the "
                       "tower 4.", ["tower", "wall"], None)  # fmt: skip
    assert r.spec.structures[0].height == 4 and r.spec.relations[0].side == "back"
    # "Hmm, 3 high." and "Actually high 6.": the size said again (reported unused)
    r = _built_as_said("Wall 5 long, 2 high. Hmm, 3 high. And make it 7 long.", ["wall"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (7, 3)
    _built_as_said("High 4, tower. Actually high 6. Left side.", ["tower"], [6])


def test_a_palletisers_courses_rows_by_columns_and_stacks_in_a_pattern():
    # "one course 8 long" (error: no structure), "Two courses, 6 blocks per course" (a tower of
    # 2), "3 rows by 4 columns, 2 layers" of a pallet (a pallet and three rows)
    r = _built_as_said("Lay one course 8 long along the back edge.", ["row"], [1] * 8)
    assert r.spec.structures[0].region == "back"
    _built_as_said("Two courses, 6 blocks per course, stacked straight.", ["wall"], [2] * 6)
    r = _built_as_said("Pallet build: 3 rows by 4 columns, 2 layers, centre of the table.",
                       ["block"], [2] * 12)  # fmt: skip
    # "one cube clearance between stacks": the gap (a default tower for 'stacks')
    r = _built_as_said("Put three stacks of five in a row down the left side, one cube clearance "
                       "between stacks.", ["tower"] * 3, [5, 5, 5])  # fmt: skip
    assert r.spec.gap_m == pytest.approx(0.05)
    # "stacks of 2 in a 3 by 2 pattern": six of them (one was built)
    _built_as_said("Build stacks of 2 in a 3 by 2 pattern with one-cube aisles.", ["tower"] * 6,
                   [2] * 6)  # fmt: skip


def test_lists_said_by_whose_heights_and_parts_said_by_their_role():
    # "whose heights, respectively, are two, four and six cubes, each separated … by a single
    # cube's width": 2, 4, 6 a cube apart (all 6 high, and a cube built from "cube's width")
    _built_as_said("Construct three towers in a line from left to right, whose heights, "
                   "respectively, are two, four and six cubes, each separated from the next by a "
                   "single cube's width.", ["tower"] * 3, [2, 4, 6])  # fmt: skip
    _built_as_said("three towers of 2, 4 and 6, each separated from the next by a single cube's "
                   "width.", ["tower"] * 3, [2, 4, 6])  # fmt: skip
    # "one have three cube, other have five cube, they stand near": 3 and 5, side by side (both
    # 3; the second put at the front for "near")
    r = _built_as_said("Make two tower, one have three cube, other have five cube, they stand "
                       "near.", ["tower", "tower"], [3, 5])  # fmt: skip
    assert all(s.region is None for s in r.spec.structures)
    # "close together": never the front region
    r = _built_as_said("two towers of 3 and 5, close together", ["tower", "tower"], [3, 5])
    assert all(s.region is None for s in r.spec.structures)
    # "a crossbeam on top": a beam (the posts stood apart)
    _built_as_said("A torii-style gate: two posts of four and a crossbeam on top, at the back.",
                   ["bridge"], None)  # fmt: skip
    # "Layers: 4x4, then 3x3, …": the levels (read as 4 layers 4 cm from the edge: failure)
    _built_as_said("Layers: 4x4, then 3x3, then 2x2, then 1. Keep them centred.",
                   ["grid", "grid", "grid", "tower"], None)  # fmt: skip
    # "with a single cube as the temple on top": the cube on top (a canopy for the temple)
    _built_as_said("A Maya pyramid: base four by four, four levels, with a single cube as the "
                   "temple on top.", ["pyramid"], None)  # fmt: skip


def test_a_clock_face_a_checklists_letters_and_a_shape_said_bare_again():
    # "the robot at six o'clock … at twelve o'clock": at the back (the centre, silently)
    r = _built_as_said("Picture the table as a clock with the robot at six o'clock. Put a tower of "
                       "three at twelve o'clock.", ["tower"], [3])  # fmt: skip
    assert r.spec.structures[0].region == "back"
    r = _built_as_said("Robot at 6 o'clock: a staircase of four that does not climb towards 12.",
                       ["staircase"], None)  # fmt: skip
    assert (r.spec.structures[0].axis, r.spec.structures[0].yaw_deg) == ("x", 180.0)
    # a time of day stays one
    assert plan("meet me at 5 o'clock, a tower of 3").spec.structures[0].region is None
    # "Wall L 6 x ht 3, w 1", "RH of A", "lg ht 2": a checklist's sizes and sides
    _built_as_said("Wall L 6 x ht 3, w 1.", ["wall"], [3] * 6)
    r = _built_as_said("Twr A ht 5. Twr B ht 3, RH of A, 2 clr.", ["tower", "tower"], [3, 5])
    cols = _columns(r)
    assert cols[min(cols, key=lambda c: c[1])] == 3  # B on the right (-y)
    _built_as_said("Tbl, lgs qty 4, lg ht 2, tp: beams.", ["canopy"], None)
    # "on slab" said bare after a slab: on it (a second slab, silently)
    r = _built_as_said("Slab 3x3, qty 1. Twr ht 2 on slab, ctr.", ["grid", "tower"], None)
    assert r.spec.relations[0].kind == "on_top_of"
    # "'Three, the tower, make it!' He means a tower of three.": one tower (two, silently)
    _built_as_said("'Three, the tower, make it!' He means a tower of three.", ["tower"], [3])
    # "a little tower on top of the middle" of a bridge: on it (beside it, silently)
    r = _built_as_said("I want a bridge with pillars 2 high and then a little tower on top of the "
                       "middle!!", ["bridge", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of"
    # "none of them taller than 4": a limit (read as nothing: towers of 3, silently)
    _built_as_said("three towers, none of them taller than 4", ["tower"] * 3, [4, 4, 4])
    # "My son says no bridges and no towers today": left out (a bridge was built)
    _built_as_said("My son says no bridges and no towers today, he wants a plain flat slab, 4 by "
                   "4", ["grid"], [1] * 16)  # fmt: skip
    # "mid table": the centre (a table was built)
    r = _built_as_said("bridge, posts 3 high + beam, mid table", ["bridge"], None)
    assert r.spec.structures[0].region == "centre"


def test_a_question_then_the_request_and_later_steps_said_with_their_particle_last():
    # "Is there room for two walls side by side? I need two walls …": two walls (a room was
    # built, and the asked walls beside the described ones: failure)
    _built_as_said("Is there room for two walls side by side? I need two walls, five long and "
                   "two high, parallel, with a gap of two.", ["wall", "wall"],
                   [2] * 10)  # fmt: skip
    # "How many cubes do you have? …": a question of stock (a row of 8 beside the wall)
    _built_as_said("How many cubes do you have? I want a wall eleven long.", ["wall"], [2] * 11)
    # "take the first one away", "move the tower to the back": applied (refused)
    r = _built_as_said("Build a tower of three, then a tower of five, and then take the first one "
                       "away.", ["tower"], [5])  # fmt: skip
    r = _built_as_said("Put a slab of 2 by 4 on the right, and then a tower of three on the left, "
                       "and then move the tower to the back.", ["grid", "tower"], None)  # fmt: skip
    assert r.spec.structures[1].region.startswith("back")


def test_fore_and_aft_a_checklists_each_and_clear_between_and_an_hour_of_a_structure():
    # "aft end (fwd = robot end)": the back (the front, silently); "fwd of wall": in front of it
    r = _built_as_said("Twr ht 4, LH side, aft end (fwd = robot end).", ["tower"], [4])
    assert r.spec.structures[0].region == "back left"
    r = _built_as_said("Wall L 5 ht 2. Twr ht 3 fwd of wall, not touching (fwd = robot end).",
                       ["wall", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].side == "front"
    r = _built_as_said("a tower, fwd = far end, at the fwd end", ["tower"], [3])
    assert r.spec.structures[0].region == "back"
    r = _built_as_said("Stair, 5 steps, w 2, climbs aft (aft = away from robot).", ["staircase"],
                       None)  # fmt: skip
    assert r.spec.structures[0].axis == "x" and r.spec.structures[0].yaw_deg in (None, 0.0)
    # "ht 2 ea, … 1 cube clr btwn": each 2 high, a cube apart ('ea' read as cubes)
    r = _built_as_said("Twrs qty 3, ht 2 ea, in line, 1 cube clr btwn.", ["tower"] * 3, [2, 2, 2])
    assert r.spec.gap_m == pytest.approx(0.05)
    # "at its three o'clock (robot at six)": to its right; "At two o'clock, robot at six"
    r = _built_as_said("Build a tower of four in the centre, then a tower of two at its three "
                       "o'clock (robot at six).", ["tower", "tower"], [2, 4])  # fmt: skip
    assert r.spec.relations[0].side == "right"
    r = _built_as_said("At two o'clock, robot at six, a tower of four.", ["tower"], [4])
    assert r.spec.structures[0].region == "back right"


def test_a_structure_named_by_its_label():
    # "Column A …, Column B …, 50 mm clear to the right of A": beside the first (the table's
    # right region, 100 mm from it, silently)
    r = _built_as_said("Column A 150 mm high. Column B 250 mm high, offset 50 mm clear to the "
                       "right of A.", ["tower", "tower"], [3, 5])  # fmt: skip
    (rel,) = r.spec.relations
    assert (rel.subject, rel.object, rel.side) == (1, 0, "right")
    assert rel.gap_m == pytest.approx(0.05)
    # "fore and aft": running front to back (read as the back, silently)
    r = _built_as_said("Anyway, lay out a row of five cubes for me, fore and aft.", ["row"],
                       [1] * 5)  # fmt: skip
    assert r.spec.structures[0].axis == "x" and r.spec.structures[0].region is None


def test_between_the_first_two_and_steps_said_one_by_one():
    # "a third tower, of five, between the first two": between them (apart, partial)
    r = _built_as_said("Build two towers of three, three cubes apart, and then a third tower, of "
                       "five, between the first two.", ["tower"] * 3, [3, 3, 5])  # fmt: skip
    assert {rel.object for rel in r.spec.relations} == {0, 2}
    # "the first step one cube high, the second two, …, the fourth four": four steps (two)
    r = _built_as_said("Steps: the first step one cube high, the second two, the third three, the "
                       "fourth four, each step two cubes wide.", ["staircase"], None)  # fmt: skip
    assert (r.spec.structures[0].steps, r.spec.structures[0].width) == (4, 2)


def test_a_table_as_high_in_total():
    # "a table 3 cubes high in total", "no taller than three cubes in total": legs 2 and the top
    # (legs 3, 4 high in all, silently)
    for command in ("a table 3 cubes high in total",
                    "Build a table but no taller than three cubes in total."):  # fmt: skip
        r = _built_as_said(command, ["canopy"], None)
        assert max(o.position[2] + o.size[2] / 2 for o in r.layout.objects) == pytest.approx(0.15)


def test_a_cube_said_with_whose_it_is():
    # "put our class mascot cube right in the middle of it": a cube inside (dropped as chatter)
    r = _built_as_said("Build a ring five by five, one cube high, and put our class mascot cube "
                       "right in the middle of it.", ["enclosure", "tower"], None)  # fmt: skip
    assert r.spec.relations[0].kind == "around"


def test_on_the_other_side_of_the_first():
    # "… a tower of two next to that, and then a tower of six on the other side of the first
    # one": across from the two (dropped, silently)
    r = _built_as_said("Build a tower of four, and then a tower of two next to that, and then a "
                       "tower of six on the other side of the first one.", ["tower"] * 3,
                       [2, 4, 6])  # fmt: skip
    cols = _columns(r)
    order = [cols[k] for k in sorted(cols, key=lambda c: -c[1])]
    assert order.index(4) == 1  # the four in the middle


def test_the_bottom_of_its_own_and_what_is_meant_that_names_nothing():
    # "3 by 3 on the bottom": its own bottom, never a relation to the block named before it
    r = plan("Make a solid block out of 18 cubes, 3 by 3 on the bottom")
    assert r.status == "success" and not r.spec.relations
    # "He means the tallest you can do, so ten": what is meant names no structure: the quote is
    # kept (no structure at all was read)
    _built_as_said("My son says 'a tower as tall as me!' He means the tallest you can do, so ten.",
                   ["tower"], [10])  # fmt: skip


@pytest.mark.parametrize(
    ("command", "left_first"),
    [
        # "I'm across the table" said bare, and a speech recogniser's "im oposite": not read as
        # where the speaker stands (the row's left end was the robot's, silently)
        ("I'm across the table. Build a row of 4 running left to right as I see it, then put a "
         "cube on its left end", [1, 1, 1, 2]),
        # the order from the speaker's left read after their left is turned (a line front to
        # back, all on the left, silently)
        ("Standing opposite the robot: three towers, 1, 2 and 3 high, going from my left to my "
         "right.", [3, 2, 1]),
    ],
)  # fmt: skip
def test_a_speaker_across_the_table_in_more_words(command, left_first):
    r = plan(command)
    assert r.status == "success" and any("from where the speaker stands" in n for n in r.notes)
    cols: dict[float, int] = {}
    for (_, y), h in _columns(r).items():
        cols[y] = max(cols.get(y, 0), h)
    assert [cols[y] for y in sorted(cols, reverse=True)] == left_first


def test_a_speaker_across_the_table_said_after_or_misspelt():
    r = plan("im oposite the robot. staircase 4 steps climbing towards me pls")
    assert r.status == "success" and r.spec.structures[0].axis == "x"
    tops = {round(o.position[0], 3): o.position[2] for o in r.layout.objects}
    assert max(tops, key=tops.__getitem__) == max(tops)  # it climbs away from the robot, to +x
    r = plan("Put a tower of 3 on the robot's left, and a tower of 3 on my left. I'm standing "
             "across from it.")  # fmt: skip
    assert r.status == "success"
    assert [s.region for s in r.spec.structures] == ["left", "right"]


def test_too_where_only_a_number_fits_and_each_after_a_row():
    # "each for long too high": two high (read as 'not about the structure': 4 high, silently)
    r = _built_as_said("i need three walls each for long too high spaced one apart", ["wall"] * 3,
                       None)  # fmt: skip
    assert {(s.length, s.height) for s in r.spec.structures} == {(4, 2)}
    r = _built_as_said("on the right side a wall put it five long too high", ["wall"], None)
    assert (r.spec.structures[0].length, r.spec.structures[0].height) == (5, 2)
    assert "too" in plan("a tower of 5, is that too high?").ignored  # still "too much"
    # "four towers in a row each two high": theirs (a wall 2 high was built beside them)
    _built_as_said("make four towers in a row each two high", ["tower"] * 4, [2, 2, 2, 2])


@pytest.mark.parametrize(
    ("command", "shapes", "heights"),
    [
        ("GIVEN an empty table WHEN the robot builds THEN exactly 2 towers of height 3 exist.",
         ["tower", "tower"], [3, 3]),
        ("GIVEN a tower of 5 WHEN the top 2 cubes are removed THEN a tower of 3 remains.",
         ["tower"], [3]),
        ("GIVEN an empty table WHEN I request a bridge THEN there are 2 pillars of 2 cubes AND "
         "one beam spans them.", ["bridge"], None),
        ("Given a clear table, when I ask for a wall 4 long, then a wall 4 long and 2 high "
         "exists.", ["wall"], [2, 2, 2, 2]),
        ("Precondition: table empty. Action: place a tower of 4.", ["tower"], [4]),
    ],
)  # fmt: skip
def test_acceptance_criteria_build_what_the_then_says(command, shapes, heights):
    # the table of GIVEN an empty table was built as a structure (a table of its default size)
    r = _built_as_said(command, shapes, heights)
    assert "canopy" not in [s.shape for s in r.spec.structures]


def test_a_then_in_capitals_without_a_frame_is_a_sequence():
    # no GIVEN, no WHEN: "THEN" is the next step, and what came before it is built too
    _built_as_said("BUILD A ROW OF 6 THEN A TOWER OF 2 ON TOP", ["row", "tower"], None)


def test_changes_said_with_only_until_and_break():
    # "make it only four" (the change was lost), "until it's 7 high" (one cube was added), "break
    # the top 2 blocks" (a row of 2 was laid beside it)
    _built_as_said("Would you kindly build a tower of six, and then make it only four?", ["tower"],
                   [4])  # fmt: skip
    _built_as_said("Start with a tower of 3. Then add one more cube to it at a time until it's 7 "
                   "high.", ["tower"], [7])  # fmt: skip
    r = plan("build a 1x1 pillar 6 blocks high then break the top 2 blocks")
    assert r.status == "success" and sorted(_columns(r).values()) == [4]


def test_not_joined_and_facing_each_other_are_claims_that_hold():
    # "but NOT joined at the top" was read as joined by a beam
    r = _built_as_said("two towers of 3, not joined at the top", ["tower", "tower"], [3, 3])
    assert any("holds" in n for n in r.notes)
    # "facing each other": two walls the same way ('facing' was left unused: partial)
    r = _built_as_said("Two walls 5 long, 2 high, facing each other, with a 3 cube gap between "
                       "them.", ["wall", "wall"], None)  # fmt: skip
    assert any("'facing each other': holds" in n for n in r.notes)


def test_the_one_behind_the_other_and_structures_named_by_a_vague_size():
    # "the one behind the other" read "one" as a wall one long, silently
    r = _built_as_said("Make please two walls, the one behind the other, each four long and two "
                       "high.", ["wall", "wall"], None)  # fmt: skip
    assert {(s.length, s.height) for s in r.spec.structures} == {(4, 2)}
    r = plan("two walls, the one behind the other")
    assert [s.length for s in r.spec.structures] == [None, None]
    # "the small tower … the big tower" at first mention: two towers (the big one was the small
    # one again); then each one's size said by that word (both 2, silently)
    for command in ("Put the small tower in front of the big tower. The small has two cubes, the "
                    "big has five.",
                    "Put the small tower before the big tower. The small has two cubes, the big "
                    "has five.",
                    "A small tower in front of a big tower: the small one 2 cubes, the big one "
                    "5."):  # fmt: skip
        r = _built_as_said(command, ["tower", "tower"], [2, 5])
        assert [(x.kind, x.side) for x in r.spec.relations] == [("next_to", "front")]
        assert r.spec.structures[r.spec.relations[0].subject].height == 2  # the small in front
    # named both ways in one phrase, "the small one" is one of those two
    r = _built_as_said("a big tower of 6 and a small one of 2, then put a cube on top of the small "
                       "one", ["tower"] * 3, [3, 6])  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of"


def test_walls_round_the_edge_of_a_floor_stand_on_its_rim():
    # "walls around the edge of it": a ring on the floor (a wall beside it); a ring on a 3 by 5
    # slab is that size (a 4 by 4 overhung it: a failure)
    r = _built_as_said("build a 4x4 floor. now build walls around the edge of it 2 high",
                       ["grid", "enclosure"], None)  # fmt: skip
    assert r.spec.relations[0].kind == "on_top_of" and len(r.layout.objects) == 16 + 24
    r = _built_as_said("a 3x5 slab with a wall round the edge of it", ["grid", "enclosure"], None)
    assert len(r.layout.objects) == 15 + 12


@pytest.mark.parametrize(
    "command",
    ["Two towers: the tower of 4 on the right, the tower of 2 on the left, with a 2-cube gap.",
     "Two towers: a 4 on the right, a 2 on the left",
     "I'm across the table. Two towers: the 4 on my left, the 2 on my right, with a 2-cube gap."],
)  # fmt: skip
def test_items_of_a_list_named_by_the_size_and_place(command):
    # "the tower of 4 on the right, the tower of 2 on the left": both 4, on one side, silently
    r = _built_as_said(command, ["tower", "tower"], [2, 4])
    cols = _columns(r)
    assert [cols[k] for k in sorted(cols, key=lambda c: -c[1])] == [2, 4]  # left to right


def test_a_tolerance_round_the_centre_and_a_table_kept_clear():
    # "pyramid centre within 8 cm of the table centre": in the centre (a second pyramid 8 cm
    # long was built)
    r = _built_as_said("Precondition: table empty. Action: place pyramid, 3 levels. "
                       "Postcondition: pyramid centre within 8 cm of the table centre.",
                       ["pyramid"], None)  # fmt: skip
    assert r.spec.structures[0].region == "centre"
    # "keep the front half of the table clear" is no empty table SDI starts from
    r = plan("Put a 3x3 block 2 high in the back right bay, and keep the front half of the table "
             "clear.")  # fmt: skip
    assert r.status != "success" or r.spec.structures[0].region == "back right"


@pytest.mark.parametrize(
    ("command", "length_m", "height_m"),
    [
        ("All dimensions in cm: a wall 20 long, 10 high.", 0.2, 0.1),  # a failure: 20 cubes
        ("Units: inches. A wall 12 long, 4 high.", 0.3048, 0.1016),  # 12 cubes, silently
        ("Inches, all of these: wall, 12 long, 4 high.", 0.3048, 0.1016),
    ],
)
def test_a_unit_said_once_for_every_size(command, length_m, height_m):
    r = _built_as_said(command, ["wall"], None)
    s = r.spec.structures[0]
    assert (s.length_m, s.height_m) == (pytest.approx(length_m), pytest.approx(height_m))
    assert any("the unit of every size said without one" in n for n in r.notes)


def test_a_then_that_says_how_they_stand_a_foot_to_its_right_and_a_vague_size_said_again():
    # "Then the tower does not touch the ring": a claim about those named before, not what to
    # build instead of them
    r = _built_as_said("Given a ring 5x5 outside. When a tower of 3 is placed inside the ring. "
                       "Then the tower does not touch the ring.", ["enclosure", "tower"], None)
    assert r.spec.relations[0].kind == "around"
    # "about a foot to its right": 0.3 m (a foot was not read: 0.1 m, silently)
    r = plan("Put a 3-cube tower in the back left, and a 2x2 block about a foot to its right.")
    assert r.status == "success" and r.spec.relations[0].gap_m == pytest.approx(0.3048)
    # "a tall column … column 4 high": the column named before, 4 high (a second one, silently)
    _built_as_said("a ring, and inside it a tall column. Ring 6x6, 1 high; column 4 high.",
                   ["enclosure", "tower"], None)  # fmt: skip


def test_a_pyramids_bottom_the_tallest_said_of_one_and_finish_it_at():
    # "5x5 at the bottom", "the bottom layer has to be 4 by 4": the base ('bottom' unused)
    s = _built_as_said("I want a low, wide pyramid: 5x5 at the bottom, 3 levels.", ["pyramid"],
                       None).spec.structures[0]  # fmt: skip
    assert (s.length, s.height) == (5, 3)
    s = _built_as_said("A pyramid, you pick the size, but the bottom layer has to be 4 by 4.",
                       ["pyramid"], None).spec.structures[0]  # fmt: skip
    assert s.length == 4
    # "the middle one the tallest": towers one high in the centre, silently
    r = _built_as_said("three towers of 2, 4 and 3, the middle one the tallest", ["tower"] * 3,
                       [2, 3, 4])  # fmt: skip
    cols = _columns(r)
    assert [cols[k] for k in sorted(cols, key=lambda c: -c[1])][1] == 4
    assert plan("can you make 3 towers and the midle one is the bigest!!!").status != "success"
    # "finish it at 6", "take it up to 5 cubes": that high (3, silently)
    _built_as_said("the tower on the left got to 3 cubes before the gripper jammed. Carry on "
                   "with it and finish it at 6.", ["tower"], [6])  # fmt: skip
    _built_as_said("a tower of 3, then take it up to 5 cubes.", ["tower"], [5])
    # "… centred on it so the centre of mass stays over the middle": what it is for
    r = plan("a 4x4 slab, then a 2x2 block two high centred on it so the centre of mass stays "
             "over the middle.")  # fmt: skip
    assert r.status == "success" and r.spec.relations[0].kind == "on_top_of"


def test_numbered_steps_revised_or_left_out():
    # "Step 2 (revised): …": that step said anew, or changed (both were built)
    r = _built_as_said("Step 1: tower of 3 on the left. Step 2: tower of 5 on the right. Step 2 "
                       "(revised): tower of 4 on the right.", ["tower", "tower"], [3, 4])
    assert [s.region for s in r.spec.structures] == ["left", "right"]
    r = _built_as_said("Step 1: ring 5 by 5, one high. Step 2: tower of 3 in its centre. Step 2 "
                       "(revised): a tower of 2 instead.", ["enclosure", "tower"], None)
    assert r.spec.structures[1].height == 2 and r.spec.relations[0].kind == "around"
    # "Ignore step 3.", "Skip step 2 - we don't need it.": that step left out (it was built)
    r = _built_as_said("1. Build a wall 6 long, 2 high. 2. Put a tower of 3 in front of it. 3. Add "
                       "a second layer to the wall. Ignore step 3.", ["wall", "tower"], None)
    assert (r.spec.structures[0].height, r.spec.structures[1].height) == (2, 3)
    _built_as_said("1) Row of 5. 2) A second row of 5 behind it, touching. 3) Skip step 2 - we "
                   "don't need it.", ["row"], [1, 1, 1, 1, 1])  # fmt: skip


@pytest.mark.parametrize(
    ("command", "shapes", "heights"),
    [
        # "as tall as a pint glass": about 15 cm (read as a vague 'tall': 6, silently)
        ("Put a tower as tall as a pint glass in the back left corner.", ["tower"], [3]),
        ("A tower about as tall as a coffee mug.", ["tower"], [2]),
        ("As tall as a milk carton, the tower, please - at the back.", ["tower"], [4]),
        # "the size of a shoebox", "of a paperback book": its sides (a default 2 by 2 by 2)
        ("A block the size of a shoebox.", ["block"], [2] * 24),
        ("A slab about the size of a paperback book, lying flat, in the front right.", ["grid"],
         [1] * 8),
    ],
)  # fmt: skip
def test_a_size_said_by_an_everyday_thing(command, shapes, heights):
    r = _built_as_said(command, shapes, heights)
    assert any("the usual size of" in n for n in r.notes)


def test_no_wait_make_a_number_and_a_structure_taken_off_the_board():
    # "no wait make 5!!!": five ('make 5' was no structure named there)
    r = _built_as_said("make 4 towers of 2. no wait make 5!!!", ["tower"] * 5, [2] * 5)
    # "then take the right one off the board": that tower taken away (refused as parts taken off)
    r = _built_as_said("Tower of 2 on the front-left square of the board and another on the "
                       "front-right square. Then take the right one off the board.", ["tower"],
                       [2])  # fmt: skip
    assert r.spec.structures[0].region == "front left"
    # "take the top one off" is still the top cube of it
    _built_as_said("a tower of 5, take the top one off", ["tower"], [4])


def test_an_everyday_thing_said_with_its_measure_is_a_likeness():
    # the measure said after the thing is the size (the thing's usual size clashed with it)
    r = _built_as_said("A wall as long as your hand, about twenty centimetres, and two cubes high.",
                       ["wall"], None)  # fmt: skip
    assert (r.spec.structures[0].length_m, r.spec.structures[0].height) == (0.2, 2)
    r = _built_as_said("Something about the size of a shoebox: 30 cm long, 15 cm wide and 10 cm "
                       "tall, solid.", ["block"], None)  # fmt: skip
    s = r.spec.structures[0]
    assert (s.length_m, s.width_m, s.height_m) == (0.3, 0.15, 0.1)


def test_a_maths_teachers_numbers_and_an_engineers_piers_and_deck():
    # "half of eight" (8), "twice as many towers as 2" (as many: 8), "one step fewer than 5" (1)
    _built_as_said("a tower of half of eight cubes", ["tower"], [4])
    r = _built_as_said("build twice as many towers as 2, each 3 high", ["tower"] * 4, [3] * 4)
    assert not any("'many'" in n for n in r.notes)
    assert plan("a staircase with one step fewer than 5").spec.structures[0].steps == 4
    assert plan("a pyramid with two more levels than 1").spec.structures[0].height == 3
    # "two piers 4 high … with a deck across": a bridge (the piers unused, the deck a slab)
    r = _built_as_said("two piers 4 high, 3 cubes apart, with a deck across", ["bridge"], None)
    assert r.spec.structures[0].height == 4
    _built_as_said("a deck on two piers of 3, clear span 2", ["bridge"], None)


def test_a_texters_u_a_family_heading_and_a_beam_laid_on_them():
    # "can u build like a tower of 5": you (a U shape like a tower: an error)
    _built_as_said("yo can u build like a tower of 5 rn pls 🙏", ["tower"], [5])
    assert plan("can u make a u shape 5 wide").spec.structures[0].shape == "u_shape"
    # "a garden border: a low edging wall 8 long": the wall the heading names (an enclosure)
    r = _built_as_said("a garden border: a low edging wall 8 long along the front", ["wall"], None)
    assert r.spec.structures[0].length == 8
    _built_as_said("Border: a wall 8 long", ["wall"], None)
    _built_as_said("Enclosure: outer 5x4, wall height 2, open interior.", ["enclosure"], None)
    # "lay a beam on them", "a deck on two piers": the beam across them (the towers stacked)
    for command in ("two pillars of 3, lay a beam on them", "two towers of 2, place a beam on top "
                    "of them", "two piers of 3, lay a deck on them"):  # fmt: skip
        _built_as_said(command, ["bridge"], None)
