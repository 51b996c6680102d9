"""Part / Layout validation and the JSON door (`parse_layout`, `load_layout`)."""

from __future__ import annotations

import json
import math

import pytest
from pydantic import ValidationError

from conftest import cube, layout, tower
from sdi.errors import InputError, LimitError
from sdi.model import Layout, Part, load_layout, parse_layout, quat_from_yaw


def doc(*parts: dict, **extra: object) -> dict:
    return {"objects": list(parts), **extra}


def pd(pid: str = "a", position=(0.4, 0.3, 0.025), **fields: object) -> dict:
    return {"id": pid, "position": list(position), **fields}


# --------------------------------------------------------------------------------------------
# Part


class TestPart:
    def test_defaults_are_the_default_cube_upright(self):
        p = Part(id="c1", position=(0.4, 0.3, 0.025))
        assert p.size == (0.05, 0.05, 0.05)
        assert p.orientation == (1.0, 0.0, 0.0, 0.0)
        assert p.bottom == pytest.approx(0.0)
        assert p.top == pytest.approx(0.05)

    @pytest.mark.parametrize(
        "kwargs",
        [
            {"position": (math.nan, 0.3, 0.025)},
            {"position": (0.4, math.inf, 0.025)},
            {"position": (0.4, 0.3, -math.inf)},
            {"position": (0.4, 0.3, 0.025), "size": (0.05, math.nan, 0.05)},
            {"position": (0.4, 0.3, 0.025), "orientation": (math.nan, 0.0, 0.0, 0.0)},
            {"position": (0.4, 0.3, 0.025), "size": (0.0, 0.05, 0.05)},
            {"position": (0.4, 0.3, 0.025), "size": (0.05, -0.05, 0.05)},
            {"position": (0.4, 0.3, 0.025), "size": (20.0, 0.05, 0.05)},
            {"position": (0.4, 0.3, 0.025), "orientation": (1.0, 0.0, 0.0, 0.1)},
            {"position": (0.4, 0.3, 0.025), "orientation": (0.0, 0.0, 0.0, 0.0)},
            {"position": (0.4, 0.3, 0.025), "colour": "red"},
        ],
    )
    def test_constructor_refuses_bad_values(self, kwargs):
        with pytest.raises(ValidationError):
            Part(id="c1", **kwargs)

    @pytest.mark.parametrize("bad_id", ["", "a b", "c/1", "x" * 65])
    def test_constructor_refuses_bad_ids(self, bad_id):
        with pytest.raises(ValidationError):
            Part(id=bad_id, position=(0.4, 0.3, 0.025))

    def test_quaternion_within_tolerance_is_accepted_without_renormalising(self):
        q = (1.0004, 0.0, 0.0, 0.0)
        assert Part(id="c", position=(0.4, 0.3, 0.025), orientation=q).orientation == q
        with pytest.raises(ValidationError):
            Part(id="c", position=(0.4, 0.3, 0.025), orientation=(1.002, 0.0, 0.0, 0.0))

    def test_is_immutable_and_moved_returns_a_copy(self):
        p = Part(id="c1", position=(0.4, 0.3, 0.025), size=(0.15, 0.05, 0.05))
        with pytest.raises(ValidationError):
            p.position = (0.0, 0.0, 0.0)  # type: ignore[misc]
        q = p.moved(dx=0.01, dz=0.05)
        assert p.position == (0.4, 0.3, 0.025)
        assert q.position == pytest.approx((0.41, 0.3, 0.075))
        assert (q.id, q.size, q.orientation) == (p.id, p.size, p.orientation)


class TestRotatedBoundingBox:
    BEAM = (0.15, 0.05, 0.05)

    def test_identity_keeps_half_sizes(self):
        p = Part(id="b", position=(0.4, 0.3, 0.025), size=self.BEAM)
        assert p.half_extents == pytest.approx([0.075, 0.025, 0.025])

    @pytest.mark.parametrize("yaw_deg", [90, -90, 270])
    def test_quarter_turn_yaw_swaps_x_and_y(self, yaw_deg):
        q = quat_from_yaw(math.radians(yaw_deg))
        p = Part(id="b", position=(0.4, 0.3, 0.025), size=self.BEAM, orientation=q)
        assert p.half_extents == pytest.approx([0.025, 0.075, 0.025], abs=1e-12)

    def test_half_turn_yaw_keeps_extents(self):
        p = Part(
            id="b", position=(0.4, 0.3, 0.025), size=self.BEAM, orientation=quat_from_yaw(math.pi)
        )
        assert p.orientation == (0.0, 0.0, 0.0, 1.0)  # snapped, exact
        assert p.half_extents == pytest.approx([0.075, 0.025, 0.025], abs=1e-12)

    def test_45_degree_yaw_grows_the_box(self):
        p = Part(id="c", position=(0.4, 0.3, 0.025), orientation=quat_from_yaw(math.pi / 4))
        r = 0.025 * math.sqrt(2)
        assert p.half_extents == pytest.approx([r, r, 0.025])
        beam = Part(
            id="b",
            position=(0.4, 0.3, 0.025),
            size=self.BEAM,
            orientation=quat_from_yaw(math.pi / 4),
        )
        expected = (0.075 + 0.025) / math.sqrt(2)
        assert beam.half_extents == pytest.approx([expected, expected, 0.025])

    def test_roll_about_x_swaps_y_and_z(self):
        half = math.sqrt(0.5)
        p = Part(
            id="b",
            position=(0.4, 0.3, 0.075),
            size=(0.05, 0.15, 0.05),
            orientation=(half, half, 0, 0),
        )
        assert p.half_extents == pytest.approx([0.025, 0.025, 0.075], abs=1e-12)
        assert p.bottom == pytest.approx(0.0)
        assert p.top == pytest.approx(0.15)

    def test_layout_arrays_use_world_aabb(self):
        beam = Part(
            id="b",
            position=(0.4, 0.3, 0.025),
            size=self.BEAM,
            orientation=quat_from_yaw(math.pi / 2),
        )
        lay = layout(cube("c", 0.5, 0.3, 0.025), beam)
        assert lay.half_extents[1] == pytest.approx([0.025, 0.075, 0.025], abs=1e-12)
        assert lay.centres[1] == pytest.approx([0.4, 0.3, 0.025])
        assert lay.volumes == pytest.approx([0.05**3, 0.15 * 0.05 * 0.05])


# --------------------------------------------------------------------------------------------
# Layout


class TestLayout:
    def test_keeps_order_and_indexes_ids(self):
        lay = layout(tower(3), cube("z", 0.6, 0.3, 0.025))
        assert lay.ids == ["t1", "t2", "t3", "z"]
        assert lay.index["z"] == 3
        assert lay.part("t2").position == pytest.approx((0.45, 0.3, 0.075))
        assert len(lay) == 4
        assert [p.id for p in lay] == lay.ids

    def test_duplicate_ids_are_refused(self):
        with pytest.raises(ValidationError, match="duplicate part id 't1'"):
            layout(tower(2), cube("t1", 0.6, 0.3, 0.025))

    def test_empty_layout_is_valid(self):
        lay = Layout()
        assert len(lay) == 0
        assert lay.centres.shape == (0, 3)
        assert lay.to_json_dict() == {"objects": []}


# --------------------------------------------------------------------------------------------
# parse_layout / load_layout: bad input is an InputError naming what is wrong


def parse_error(data, **kwargs) -> InputError:
    with pytest.raises(InputError) as info:
        parse_layout(data, **kwargs)
    return info.value


class TestParseBadInput:
    @pytest.mark.parametrize("text", ['{"objects": [', "", "not json", '{"objects": [1,]}'])
    def test_malformed_json(self, text):
        err = parse_error(text)
        assert "not valid JSON" in str(err)

    @pytest.mark.parametrize("const", ["NaN", "Infinity", "-Infinity"])
    def test_nan_and_infinity_literals(self, const):
        text = '{"objects": [{"id": "a", "position": [0.4, CONST, 0.025]}]}'
        err = parse_error(text.replace("CONST", const))
        assert const in str(err)
        assert "finite" in str(err)

    def test_overflowing_number_is_refused_as_non_finite(self):
        err = parse_error('{"objects": [{"id": "a", "position": [0.4, 1e400, 0.025]}]}')
        assert err.field == "objects[0].position"
        assert "'a'" in str(err)

    @pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf])
    def test_non_finite_floats_in_a_dict(self, value):
        err = parse_error(doc(pd("a"), pd("b", position=(0.5, 0.3, value))))
        assert err.field == "objects[1].position"
        assert "'b'" in str(err)
        assert "finite" in str(err)

    @pytest.mark.parametrize("size", [[0, 0.05, 0.05], [0.05, -0.05, 0.05], [0.05, 0.05, 0.0]])
    def test_zero_or_negative_size(self, size):
        err = parse_error(doc(pd("a"), pd("cube7", position=(0.5, 0.3, 0.025), size=size)))
        assert err.field == "objects[1].size"
        assert "'cube7'" in str(err)
        assert "> 0" in str(err)

    def test_duplicate_ids_name_the_id_and_index(self):
        err = parse_error(doc(pd("a"), pd("b", position=(0.5, 0.3, 0.025)), pd("a")))
        assert "'a'" in str(err)
        assert "objects[2]" in str(err)
        assert "duplicate" in str(err)

    def test_unknown_part_field(self):
        err = parse_error(doc(pd("a"), pd("b", position=(0.5, 0.3, 0.025), colour="red")))
        assert err.field == "objects[1].colour"
        assert "'b'" in str(err)
        assert "unknown field" in str(err)

    def test_unknown_top_level_field(self):
        err = parse_error(doc(pd("a"), extra_stuff=1))
        assert err.field == "extra_stuff"

    def test_unknown_top_level_field_is_not_described_as_a_part_field(self):
        # The field sits next to 'objects', not inside a part: telling the author which keys
        # a *part* has sends them looking in the wrong place.
        err = parse_error(doc(pd("a"), extra_stuff=1))
        assert "a part has only" not in str(err)

    @pytest.mark.parametrize("quat", [[1, 0, 0, 0.1], [0.5, 0.5, 0.5, 0.4], [0, 0, 0, 0]])
    def test_unnormalised_quaternion(self, quat):
        err = parse_error(doc(pd("a", orientation=quat)))
        assert err.field == "objects[0].orientation"
        assert "'a'" in str(err)
        assert "norm" in str(err)

    def test_wrong_vector_length_and_types(self):
        err = parse_error(doc(pd("a", position=(0.4, 0.3))))
        assert err.field is not None and err.field.startswith("objects[0].position")
        err = parse_error(doc(pd("a", position=("x", 0.3, 0.025))))
        assert err.field is not None and err.field.startswith("objects[0].position")

    def test_numeric_string_coordinate_is_refused(self):
        err = parse_error(doc(pd("a", position=("0.4", 0.3, 0.025))))
        assert err.field == "objects[0].position[0]"

    def test_integers_are_numbers(self):
        text = '{"objects": [{"id": "a", "position": [1, 0, 0], "orientation": [1, 0, 0, 0]}]}'
        lay, _ = parse_layout(text)
        assert lay.part("a").position == (1.0, 0.0, 0.0)

    def test_boolean_coordinate_is_refused(self):
        # JSON `true` is not a length; silently reading it as 1.0 m moves the part off the table.
        err = parse_error('{"objects": [{"id": "a", "position": [true, 0.3, 0.025]}]}')
        assert err.field is not None and err.field.startswith("objects[0].position")

    @pytest.mark.parametrize("bad_id", ["", "a b", "ü"])
    def test_bad_part_id(self, bad_id):
        err = parse_error(doc(pd(bad_id)))
        assert err.field == "objects[0].id"

    def test_missing_id(self):
        err = parse_error(doc({"position": [0.4, 0.3, 0.025]}))
        assert err.field == "objects[0].id"

    @pytest.mark.parametrize("data", [[1, 2], "[]", "42", '"objects"'])
    def test_document_must_be_an_object(self, data):
        err = parse_error(data)
        assert "objects" in str(err)

    @pytest.mark.parametrize("data", [{"parts": []}, {"objects": {}}, {"objects": "a"}])
    def test_objects_must_be_a_list(self, data):
        assert parse_error(data).field == "objects"

    def test_plan_result_layout_must_be_an_object(self):
        assert parse_error({"layout": 5}).field == "layout"

    def test_a_part_must_be_an_object(self):
        assert parse_error(doc(5)).field == "objects[0]"

    def test_more_parts_than_the_limit(self):
        parts = [pd(f"c{i}", position=(0.4, 0.3, 0.025 + 0.05 * i)) for i in range(5)]
        with pytest.raises(LimitError) as info:
            parse_layout(doc(*parts), max_parts=4)
        assert info.value.field == "objects"
        assert "5" in str(info.value) and "4" in str(info.value)
        assert isinstance(info.value, InputError)
        lay, _ = parse_layout(doc(*parts[:4]), max_parts=4)  # exactly at the limit is fine
        assert len(lay) == 4

    def test_limit_is_checked_before_validating_parts(self):
        # Even junk parts do not get validated one by one when there are too many of them.
        with pytest.raises(LimitError):
            parse_layout({"objects": [{}] * 3}, max_parts=2)


class TestParseSequence:
    TWO = (pd("a"), pd("b", position=(0.4, 0.3, 0.075)))

    def test_valid_sequence_is_returned(self):
        lay, seq = parse_layout(doc(*self.TWO, sequence=["a", "b"]))
        assert seq == ["a", "b"]
        assert lay.ids == ["a", "b"]

    def test_no_sequence_gives_none(self):
        assert parse_layout(doc(*self.TWO))[1] is None

    @pytest.mark.parametrize(
        ("sequence", "words"),
        [
            (["a", "zz", "b"], ["unknown", "zz"]),
            (["a", "b", "a"], ["more than once"]),
            (["a"], ["leaves out", "b"]),
            ([], ["leaves out", "a"]),
            ("ab", ["list"]),
            (["a", 2], ["list"]),
            ({"a": 1}, ["list"]),
        ],
    )
    def test_wrong_sequence_lists(self, sequence, words):
        err = parse_error(doc(*self.TWO, sequence=sequence))
        assert err.field == "sequence"
        for w in words:
            assert w in str(err)

    def test_plan_json_result_is_accepted(self):
        text = json.dumps(
            {
                "status": "success",
                "command": "two cubes",
                "layout": doc(*self.TWO),
                "sequence": ["a", "b"],
                "violations": [],
            }
        )
        lay, seq = parse_layout(text)
        assert lay.ids == ["a", "b"]
        assert seq == ["a", "b"]

    def test_plan_json_result_sequence_is_checked(self):
        err = parse_error({"layout": doc(*self.TWO), "sequence": ["b"]})
        assert err.field == "sequence"


class TestRoundTrip:
    def test_to_json_dict_round_trips(self):
        beam = Part(
            id="beam_1",
            position=(0.45, 0.3, 0.125),
            size=(0.15, 0.05, 0.05),
            orientation=quat_from_yaw(math.pi / 2),
        )
        lay = layout(tower(2, 0.45, 0.25, "l"), tower(2, 0.45, 0.35, "r"), beam)
        data = lay.to_json_dict()
        assert set(data) == {"objects"}
        assert set(data["objects"][0]) == {"id", "position", "orientation", "size"}
        again, seq = parse_layout(json.dumps(data))
        assert seq is None
        assert again.ids == lay.ids
        for p, q in zip(lay, again, strict=True):
            assert q.position == pytest.approx(p.position, abs=1e-6)
            assert q.size == pytest.approx(p.size, abs=1e-6)
            assert q.orientation == pytest.approx(p.orientation, abs=1e-9)
        # A second trip is exact: the JSON form is a fixed point.
        assert parse_layout(again.to_json_dict())[0] == again

    def test_round_trip_of_exact_values_is_equal(self):
        # Values with at most 6 decimals survive the 6-decimal JSON form exactly.
        lay = layout(
            cube("a", 0.45, 0.3, 0.025), cube("b", 0.45, 0.3, 0.075), cube("x", 0.6, 0.2, 0.025)
        )
        assert parse_layout(lay.to_json_dict())[0] == lay

    def test_bytes_input(self):
        lay, _ = parse_layout(json.dumps(doc(pd("a"))).encode())
        assert lay.ids == ["a"]


class TestLoadLayout:
    def test_reads_a_file(self, tmp_path):
        path = tmp_path / "layout.json"
        path.write_text(
            json.dumps(doc(pd("a"), pd("b", position=(0.4, 0.3, 0.075)), sequence=["a", "b"]))
        )
        lay, seq = load_layout(path)
        assert lay.ids == ["a", "b"]
        assert seq == ["a", "b"]
        lay2, _ = load_layout(str(path))
        assert lay2 == lay

    def test_missing_file(self, tmp_path):
        with pytest.raises(InputError, match="no such file"):
            load_layout(tmp_path / "nope.json")

    def test_not_utf8(self, tmp_path):
        path = tmp_path / "bad.json"
        path.write_bytes(b'{"objects": [{"id": "\xff"}]}')
        with pytest.raises(InputError, match="cannot read"):
            load_layout(path)

    def test_a_directory(self, tmp_path):
        with pytest.raises(InputError):
            load_layout(tmp_path)

    def test_malformed_file_content(self, tmp_path):
        path = tmp_path / "layout.json"
        path.write_text('{"objects": [{"id": "a", "position": [NaN, 0, 0]}]}')
        with pytest.raises(InputError, match="NaN"):
            load_layout(path)

    def test_limit_applies_to_files(self, tmp_path):
        path = tmp_path / "layout.json"
        path.write_text(json.dumps(doc(pd("a"), pd("b", position=(0.5, 0.3, 0.025)))))
        with pytest.raises(LimitError):
            load_layout(path, max_parts=1)
