"""A run of a layout the operator gives as a file (`sdi run --layout`): the same Inspector, reviews
and approval by hash as a command's run, and the only way a hand-made layout reaches a program."""

from __future__ import annotations

import json

import pytest

from sdi.errors import InputError
from sdi.model.layout import Layout, parse_layout
from sdi.orchestrator import Orchestrator


def layout_of(*cubes: tuple[float, float, float]) -> Layout:
    objects = [{"id": f"c{k}", "position": list(p)} for k, p in enumerate(cubes)]
    layout, _ = parse_layout({"objects": objects})
    return layout


TOWER = layout_of((0.4, 0.3, 0.025), (0.4, 0.3, 0.075))


@pytest.fixture
def orch(tmp_path):
    o = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    yield o
    o.close()


def test_a_valid_layout_file_is_reviewed_as_it_is(orch):
    s = orch.start("layout file tower.json", layout=TOWER)
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    assert s.waiting_for["layout"] == TOWER.to_json_dict()  # neither read nor redesigned
    assert s.state["spec_source"] == "layout file" and s.state.get("spec") is None
    assert s.state.get("execution") is None  # nothing moved
    s = orch.resume(s.run_id, {"action": "approve"})
    assert s.waiting_for["kind"] == "pre_execute"  # the record is approved on its own
    with pytest.raises(InputError, match="no approved commissioning record"):
        orch.approved_record(s.run_id)


def test_the_operators_order_is_kept_or_refused_with_the_nearest_valid_one(orch):
    s = orch.start("layout file tower.json", layout=TOWER, sequence=["c0", "c1"])
    assert s.waiting_for["kind"] == "design_review" and s.waiting_for["sequence"] == ["c0", "c1"]
    s = orch.start("layout file tower.json", layout=TOWER, sequence=["c1", "c0"])
    assert s.waiting_for["kind"] == "edit_review"
    assert "sequence" in {v["constraint"] for v in s.waiting_for["violations"]}
    assert s.waiting_for["nearest_order"] == ["c0", "c1"]


def test_an_invalid_layout_file_goes_back_to_the_operator_with_a_repair(orch):
    bad = layout_of((0.95, 0.3, 0.025), (0.4, 0.3, 0.175))  # outside W; floating
    s = orch.start("layout file bad.json", layout=bad)
    w = s.waiting_for
    assert s.status == "paused" and w["kind"] == "edit_review"
    assert {"workspace", "contact"} <= {v["constraint"] for v in w["violations"]}
    assert w["choices"] == ["repair", "edit", "reject"]  # nothing to undo, no command to replan
    assert s.state["tried"] == []  # no recovery ran on the operator's layout behind their back
    repaired, _ = parse_layout(w["repair"]["layout"])
    s = orch.resume(s.run_id, {"action": "undo"})  # not a choice here: asked again
    assert s.waiting_for["kind"] == "edit_review" and "answer one of" in s.waiting_for["refused"]
    s = orch.resume(s.run_id, {"action": "repair"})
    assert s.waiting_for["kind"] == "design_review"
    assert s.waiting_for["layout"] == repaired.to_json_dict()
    assert any(n.startswith("your edit → repair: ") for n in s.state["notes"])


def test_a_reason_cannot_change_a_layout_file_and_says_so(orch):
    s = orch.start("layout file tower.json", layout=TOWER)
    s = orch.resume(s.run_id, {"action": "reject", "reason": "make it 4 high"})
    assert s.waiting_for["kind"] == "design_review"
    assert s.waiting_for["layout"] == TOWER.to_json_dict()
    assert any("'make it 4 high' was not applied" in n for n in s.state["notes"])


def test_an_empty_layout_is_refused(orch):
    with pytest.raises(InputError, match="no parts"):
        orch.start("layout file empty.json", layout=layout_of())


def test_the_command_message_names_the_given_layout(orch):
    s = orch.start("layout file tower.json", layout=TOWER)
    first = orch.bus.history(s.run_id)[0]
    assert first.type == "command" and first.payload["given_parts"] == 2
    assert json.dumps(first.payload)  # plain JSON on the audit trail
