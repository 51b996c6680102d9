"""The rule-based Specifier: phrasings map to the right structure and parameters."""

from __future__ import annotations

import pytest

from sdi.errors import LimitError, SpecError
from sdi.model.cell import CellConfig, Limits
from sdi.spec import parse_command


def one(command: str):
    spec = parse_command(command)
    assert len(spec.structures) == 1, spec.describe()
    return spec.structures[0]


@pytest.mark.parametrize(
    ("command", "shape", "params"),
    [
        ("build a 3-cube tower at x=0.4", "tower", {"height": 3, "at_x": 0.4}),
        ("Stack five cubes", "tower", {"height": 5}),
        ("pile up 4 blocks please", "tower", {"height": 4}),
        ("a column of three", "tower", {"height": 3}),
        ("a pillar made of seven bricks", "tower", {"height": 7}),
        ("a tower twenty centimetres tall", "tower", {"height_m": 0.2}),
        ("a 5-step staircase", "staircase", {"steps": 5}),
        ("a podium with four steps", "staircase", {"steps": 4}),
        ("stairs, 3 steps, two cubes wide", "staircase", {"steps": 3, "width": 2}),
        ("a wall 4 long and 2 high", "wall", {"length": 4, "height": 2}),
        ("a fence six cubes long", "wall", {"length": 6}),
        ("a wall of 0.3 m length", "wall", {"length_m": 0.3}),
        ("a 3 by 4 grid", "grid", {"length": 3, "width": 4}),
        ("a 3x3 floor of cubes", "grid", {"length": 3, "width": 3}),
        ("a 2x2x2 block", "block", {"length": 2, "width": 2, "height": 2}),
        ("a solid cube made of 27 cubes", "pack", {"count": 27}),
        ("a pyramid with a base of 4", "pyramid", {"length": 4}),
        ("a square pyramid with a 3x3 base", "pyramid", {"length": 3, "dims": 3}),
        ("a ziggurat", "pyramid", {"dims": 3}),
        ("a gate", "bridge", {}),
        ("a bridge with a span of 2 and pillars 4 high", "bridge", {"span": 2, "height": 4}),
        ("an arch spanning 3 cubes", "arch", {"span": 3}),
        ("a table with legs three cubes high", "canopy", {"height": 3}),
        ("a hollow square of side 5", "enclosure", {"length": 5, "width": 5}),
        ("a ring of cubes 4 by 3", "enclosure", {"length": 4, "width": 3}),
        ("an L-shape with arms of 3", "l_shape", {"length": 3, "width": 3}),
        ("a U shaped wall", "u_shape", {}),
        ("a plus sign", "cross", {}),
        ("a castle with four corner towers 3 high", "castle", {"count": 2}),
        ("line up seven cubes", "row", {"length": 7}),
        ("a row of 5 cubes along the x axis", "row", {"length": 5, "axis": "x"}),
        ("a line of cubes spaced 2 cm apart", "row", {"gap_m": 0.02}),
        ("pack a dozen cubes as tightly as you can", "pack", {"count": 12}),
    ],
)
def test_phrasings(command, shape, params):
    s = one(command)
    assert s.shape == shape, s.describe()
    for key, value in params.items():
        got = getattr(s, key)
        assert got == pytest.approx(value), f"{key}: {got} != {value} in {s.describe()}"


@pytest.mark.parametrize(
    ("command", "key", "value"),
    [
        ("build a tower at x = 0.45 m, y = 0.30 m", "at_y", 0.30),
        ("a tower at (0.5, 0.2)", "at_x", 0.5),
        ("a tower at x=45 cm", "at_x", 0.45),
        ("a tower at x = 450 mm", "at_x", 0.45),
        ("a tower on the left", "region", "left"),
        ("a grid in the back right corner", "region", "back right"),
        ("a small wall near the robot", "region", "front"),
        ("a row far from the robot", "region", "back"),
        ("a tower in the middle", "region", "centre"),
        ("a wall rotated 90 degrees", "yaw_deg", 90.0),
    ],
)
def test_positions_regions_rotation(command, key, value):
    assert getattr(one(command), key) == pytest.approx(value)


def test_number_words_and_digits_agree():
    assert one("a tower of twelve").height == one("a tower of 12").height == 12
    assert one("a row of twenty-five cubes").length == 25
    assert one("a row of half a dozen cubes").length == 6


def parts(command: str) -> int:
    from sdi.design import compose

    return len(compose(parse_command(command)))


def test_vague_sizes_order_structures():
    assert parts("a small tower") < parts("a tower") < parts("a tall tower")
    assert parts("a little bridge") < parts("a big bridge")
    assert one("a low wall").height < one("a tall wall").height
    assert one("a short row").length < one("a long row").length
    assert one("a few cubes in a row").length == 3
    assert parts("a tiny pyramid") < parts("a huge pyramid")


def test_multiplicity_and_compounds():
    spec = parse_command("three towers")
    assert [s.shape for s in spec.structures] == ["tower"] * 3
    spec = parse_command("twin towers of 6 cubes")
    assert [(s.shape, s.height) for s in spec.structures] == [("tower", 6), ("tower", 6)]
    joined = one("two towers of 3 cubes joined by a bridge")
    assert joined.shape == "bridge" and joined.height == 3
    spec = parse_command("a tower of 4 cubes on the left and a staircase with 3 steps on the right")
    assert [(s.shape, s.region) for s in spec.structures] == [
        ("tower", "left"),
        ("staircase", "right"),
    ]
    assert spec.structures[0].height == 4 and spec.structures[1].steps == 3
    spec = parse_command("a tower next to a wall")
    assert [s.shape for s in spec.structures] == ["tower", "wall"]


def test_material_words_are_not_structures():
    assert [s.shape for s in parse_command("a brick wall").structures] == ["wall"]
    assert [s.shape for s in parse_command("a tower of blocks").structures] == ["tower"]
    assert [s.shape for s in parse_command("a 4 by 5 grid in the back left corner").structures] == [
        "grid"
    ]


@pytest.mark.parametrize("command", ["", "   ", "hello there", "asdfgh qwerty", "build something"])
def test_unintelligible_commands_fail_clearly(command):
    with pytest.raises(SpecError) as info:
        parse_command(command)
    assert "tower" in str(info.value) or "empty" in str(info.value)


def test_parts_without_a_shape_fall_back_to_a_row_with_a_note():
    spec = parse_command("something with 4 cubes on the left, please")
    (s,) = spec.structures
    assert (s.shape, s.length, s.region) == ("row", 4, "left")
    assert any("row" in note for note in spec.notes)


def test_failure_says_what_was_understood():
    with pytest.raises(SpecError) as info:
        parse_command("do the thing at x = 0.4 on the left")
    assert info.value.understood.get("coordinates") == {"x": 0.4}
    assert info.value.understood.get("regions") == ["left"]


def test_zero_and_limits():
    with pytest.raises(SpecError, match="whole numbers"):
        parse_command("a tower of 0 cubes")
    cell = CellConfig(limits=Limits(max_command_chars=20))
    with pytest.raises(LimitError, match="max_command_chars"):
        parse_command("a tower of three cubes on the left side", cell)


@pytest.mark.parametrize(
    "phrase",
    ["two towers of 3 close together", "two towers of 3 near each other",
     "two towers close to one another"],
)  # fmt: skip
def test_close_together_says_how_far_apart_not_where(phrase):
    # "close" and "near" of each other are not the front of the table (near the robot)
    from sdi.model.cell import CellConfig
    from sdi.spec.grammar import parse_phrase

    draft, _ = parse_phrase(phrase, CellConfig())
    assert [s.region for s in draft.structures] == [None, None]
