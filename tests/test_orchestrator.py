"""The LangGraph orchestrator: phases, interrupts, routing, recovery, relaxation, budgets."""

from __future__ import annotations

import json

import pytest

from scripted_model import ScriptedChat, cube, tower
from sdi.errors import InputError
from sdi.model.layout import parse_layout
from sdi.orchestrator import METHODS, Orchestrator, apply_edits


@pytest.fixture
def orch(tmp_path):
    o = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    yield o
    o.close()


def test_three_touch_points_pause_and_resume(orch):
    s = orch.start("a 2-cube tower at x = 0.4")
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    assert len(s.waiting_for["layout"]["objects"]) == 2
    s = orch.resume(s.run_id, {"action": "approve"})
    assert s.status == "paused" and s.waiting_for["kind"] == "pre_execute"
    s = orch.resume(s.run_id, {"action": "approve"})
    assert s.status == "success"
    assert s.state["execution"]["v_traj"] == "pass"
    kinds = [m.type for m in orch.bus.history(s.run_id)]
    assert kinds[:4] == ["command", "spec", "layout", "verification"] and "execution" in kinds


def test_a_run_whose_command_was_not_all_read_ends_partial_and_says_why(orch):
    s = orch.start("a 2-cube tower at x = 0.4, hovering over the table")
    assert s.status == "paused" and any("hovering" in n for n in s.state["notes"])
    assert s.to_json_dict()["unread"] == ["hovering over the table"]
    s = orch.resume(s.run_id, {"action": "approve"})
    s = orch.resume(s.run_id, {"action": "approve"})
    assert s.state["execution"]["v_traj"] == "pass" and s.status == "partial"
    done = orch.start("a 2-cube tower at x = 0.4", approve=True)
    assert done.status == "success" and done.to_json_dict()["unread"] == []


def test_rejecting_the_design_moves_nothing(orch):
    s = orch.start("a 2-cube tower at x = 0.4")
    s = orch.resume(s.run_id, {"action": "reject"})
    assert s.status == "rejected"
    assert "execution" not in [m.type for m in orch.bus.history(s.run_id)]


def test_human_edits_are_reverified(orch):
    s = orch.start("a 2-cube tower at x = 0.4")
    # move the top cube into the air: the Inspector must catch it, and the operator decides
    edited = [{"op": "move", "id": "c2", "position": [0.4, 0.3, 0.3]}]
    s = orch.resume(s.run_id, {"action": "edit", "edits": edited})
    msgs = [m for m in orch.bus.history(s.run_id) if m.type == "verification"]
    assert msgs[0].payload["passed"] and not msgs[1].payload["passed"]
    assert s.status == "paused" and s.waiting_for["kind"] == "edit_review"
    assert s.waiting_for["layout"]["objects"][1]["position"] == [0.4, 0.3, 0.3]  # theirs, shown
    s = orch.resume(s.run_id, {"action": "repair"})
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    layout, _ = parse_layout(s.waiting_for["layout"])
    from sdi.inspector import verify

    assert verify(layout).passed  # only a verified layout comes back for review


def test_bad_edit_is_refused_and_nothing_changes(orch):
    s = orch.start("a 2-cube tower at x = 0.4")
    before = s.waiting_for["layout"]
    s = orch.resume(
        s.run_id, {"action": "edit", "edits": [{"op": "move", "id": "nope", "position": [0, 0, 0]}]}
    )
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    assert s.waiting_for["layout"] == before
    assert any("edit refused" in n for n in s.state["notes"])


@pytest.mark.parametrize(
    ("fault", "recovery"), [("low_ceiling", "flatten"), ("singular_centre", "shift")]
)
def test_execution_failure_is_recovered_by_a_skill(orch, fault, recovery):
    command = (
        "a 3-cube tower at x = 0.4" if fault == "low_ceiling" else "a 2-cube tower at x = 0.45"
    )
    s = orch.start(command, faults=[fault], approve=True)
    if recovery == "flatten":  # a changed shape is the operator's to approve, even unattended
        assert s.status == "paused" and s.waiting_for["kind"] == "recovery_review"
        assert s.waiting_for["recovery"]["shape_changed"] is True
        s = orch.resume(s.run_id, {"action": "approve"}, approve_all=True)
    assert s.status == "success", s.state.get("notes")
    assert s.state["tried"][0] == recovery
    assert s.state["notes"][-1].startswith(f"recovery: {recovery}: ")  # what changed, stated
    routes = [m.payload["action"] for m in orch.bus.history(s.run_id) if m.type == "route"]
    assert routes[0] == recovery


def script(answer, designed):
    def reply(msgs, opt):
        role = opt.get("role")
        if role == "router":
            return answer
        if role == "specifier":
            return "not json"  # the grammar reads the command instead
        return designed

    return reply


def test_llm_router_choice_is_honoured_within_the_budget(tmp_path):
    # low ceiling: the rules would flatten first; the model insists on shift, which cannot
    # clear a height limit, so the run uses its replans and stops (bounded), as a failure
    model = ScriptedChat(script({"action": "shift"}, tower(3)))
    o = Orchestrator(db=tmp_path / "a.sqlite", model=model, arms=["irb120"])
    s = o.start("a 3-cube tower at x = 0.4", method="Hybrid", faults=["low_ceiling"], approve=True)
    assert s.state["tried"][0] == "shift"
    assert s.status == "failure"
    assert s.state["replans"] <= METHODS["Hybrid"].replans + 1
    assert model.usage.by_role["router"] >= 2


def test_invalid_router_answer_falls_back_to_rules(tmp_path):
    model = ScriptedChat(script("launch the rockets", tower(2, x=0.45)))
    o = Orchestrator(db=tmp_path / "b.sqlite", model=model, arms=["irb120"])
    s = o.start(
        "a 2-cube tower at x = 0.45", method="Hybrid", faults=["singular_centre"], approve=True
    )
    assert s.status == "success" and s.state["tried"][0] == "shift"
    assert model.usage.malformed >= 1


def test_budget_bounds_replans_and_escalates(tmp_path):
    # a model whose designs always float: the loop must stop and hand over to a human
    model = ScriptedChat(lambda msgs, opt: {"objects": [cube("a", 0.4, 0.3, 0.3)]})
    o = Orchestrator(db=tmp_path / "c.sqlite", model=model)
    s = o.start("zorblax", method="LGOrch")
    assert s.status == "paused" and s.waiting_for["kind"] == "failure_report"
    assert s.state["replans"] <= METHODS["LGOrch"].replans + 1
    s = o.resume(s.run_id, {"action": "abort"})
    assert s.status == "failure"


def test_specifier_relaxation_after_repeated_failures(tmp_path):
    calls = {"designer": 0}

    def script(msgs, opt):
        role = opt.get("role")
        if role == "specifier":  # a spec the generators refuse: the model must design
            return {"structures": [{"shape": "tower", "height": 40}]}
        if role == "designer":
            calls["designer"] += 1
            # fails under the expanded spec, succeeds once the raw command is passed on
            relaxed = "Specification:" not in msgs[-1]["content"] and len(msgs) <= 4
            return (
                tower(2)
                if relaxed and calls["designer"] > 3
                else {"objects": [cube("a", 0.4, 0.3, 0.3)]}
            )
        return "{}"

    model = ScriptedChat(script)
    o = Orchestrator(db=tmp_path / "d.sqlite", model=model)
    s = o.start("zorblax tower thing", method="Hybrid")
    assert "relax" in s.state["tried"]
    assert s.state["relaxed"] is True


def test_hybrid_spends_no_design_call_when_the_generators_build_the_spec(tmp_path):
    model = ScriptedChat(
        lambda msgs, opt: (
            {"structures": [{"shape": "tower", "height": 3}]}
            if opt.get("role") == "specifier"
            else {"objects": [cube("a", 0.4, 0.3, 0.3)]}
        )  # would float, if it were asked
    )
    o = Orchestrator(db=tmp_path / "h.sqlite", model=model)
    s = o.start("a tower of three cubes", method="Hybrid")
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    assert len(s.state["layout"]["objects"]) == 3
    assert model.usage.calls == 1 and model.usage.by_role == {"specifier": 1}
    o.close()


def test_hybrid_hands_a_spec_the_generators_refuse_to_the_model(tmp_path):
    model = ScriptedChat(
        lambda msgs, opt: (
            {"structures": [{"shape": "tower", "height": 40}]}
            if opt.get("role") == "specifier"
            else tower(3)
        )
    )
    o = Orchestrator(db=tmp_path / "g.sqlite", model=model)
    s = o.start("a very tall tower", method="Hybrid")
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    assert model.usage.by_role["designer"] == 1
    o.close()


def test_unknown_method_is_bad_input(orch):
    with pytest.raises(InputError, match="Hybrid"):
        orch.start("a tower", method="Magic")


def test_edits_all_or_nothing():
    layout, _ = parse_layout(json.dumps(tower(2)))
    edited = apply_edits(
        layout,
        [{"op": "remove", "id": "c2"}, {"op": "insert", "id": "n1", "position": [0.5, 0.3, 0.025]}],
    )
    assert edited.ids == ["c1", "n1"]
    with pytest.raises(InputError, match=r"edits\[1\]"):
        apply_edits(layout, [{"op": "remove", "id": "c2"}, {"op": "teleport", "id": "c1"}])
    assert layout.ids == ["c1", "c2"]
    for bad in (10**400, float("nan"), True):  # past any float, not finite, not a number
        with pytest.raises(InputError, match=r"edits\[0\]\.position"):
            apply_edits(layout, [{"op": "insert", "id": "n1", "position": [bad, 0.3, 0.025]}])


def test_a_phase_past_its_wall_clock_limit_goes_to_the_failure_report(tmp_path):
    import time

    from sdi.model.cell import CellConfig, Limits

    def slow(msgs, opt):  # every reply takes longer than the phase may
        time.sleep(0.15)
        return {"objects": [cube("a", 0.4, 0.3, 0.3)]}  # floating: the loop would retry

    model = ScriptedChat(slow)
    cell = CellConfig(limits=Limits(phase_seconds=0.1))
    o = Orchestrator(db=tmp_path / "t.sqlite", model=model, cell=cell)
    s = o.start("a tower of 3 cubes", method="LGOrch")
    assert s.status == "paused" and s.waiting_for["kind"] == "failure_report"
    failure = s.state["failure"]
    assert failure["error_type"] == "timeout" and failure["phase"] == "design"
    assert "phase_seconds" in failure["message"]
    # stopped at the first clean point: no second Designer call after the limit
    assert model.usage.by_role["designer"] == 1
    assert any(m.type == "failure" for m in o.bus.history(s.run_id))
    o.close()


def test_a_rejection_reason_is_the_model_designers_feedback(tmp_path):
    model = ScriptedChat(lambda msgs, opt: tower(2))
    o = Orchestrator(db=tmp_path / "runs.sqlite", model=model, arms=["irb120"])
    try:
        s = o.start("a 2-cube tower", method="LGOrch")
        assert s.waiting_for["kind"] == "design_review"
        told = [m["content"] for m in model.calls[-1][0] if m["role"] == "user"]
        assert "rejected" not in told[-1]
        s = o.resume(s.run_id, {"action": "reject", "reason": "make it taller"})
        told = [m["content"] for m in model.calls[-1][0] if m["role"] == "user"]
        assert told[-1].startswith("a 2-cube tower")
        assert "The operator rejected a design: make it taller" in told[-1]
        # the scripted model gives the same tower again: the review says so
        assert "the same layout came back" in s.waiting_for["replanned"]
    finally:
        o.close()
