"""The twin without a browser: edit operations, snapping, undo/redo, the run service on a real
run database and orchestrator, the HTTP API and its token gate, and the bind refusal."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from conftest import cube, layout
from sdi.errors import InputError
from sdi.execute.record import layout_hash
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.twin.review import ReviewSession, snap, yaw_deg
from sdi.twin.server import check_bind, create_app, is_loopback
from sdi.twin.service import LockedError, Twin

CELL = CellConfig()


def row3() -> Layout:
    return layout(cube("c1", 0.45, 0.25, 0.025), cube("c2", 0.45, 0.30, 0.025),
                  cube("c3", 0.45, 0.35, 0.025))  # fmt: skip


# -- snapping and edit operations --------------------------------------------------------------
def test_snap_puts_centres_on_the_half_cube_grid_and_resting_levels():
    assert snap([0.4612, 0.2901, 0.031], (0.05, 0.05, 0.05), CELL) == [0.45, 0.3, 0.025]
    assert snap([0.4, 0.3, 0.09], (0.05, 0.05, 0.05), CELL) == [0.4, 0.3, 0.075]
    assert snap([0.4, 0.3, -0.2], (0.15, 0.05, 0.05), CELL) == [0.4, 0.3, 0.025]


def test_a_drag_onto_a_neighbour_is_a_collision_on_both_and_undo_clears_it():
    s = ReviewSession(CELL, row3())
    assert s.report().passed
    s.apply({"op": "move", "id": "c3", "position": [0.452, 0.303, 0.02]})  # snapped onto c2
    view = s.to_json_dict()
    collision = [v for v in view["violations"] if v["constraint"] == "collision"]
    assert collision and set(collision[0]["objects"]) == {"c2", "c3"}
    states = {p["id"]: p["state"] for p in view["parts"]}
    assert states["c2"] == states["c3"] == "violating" and states["c1"] != "violating"
    assert s.undo() and s.report().passed and s.to_json_dict()["can_redo"]
    assert s.redo() and not s.report().passed
    assert s.undo() and not s.undo()  # nothing more to undo


def test_free_move_is_not_snapped():
    s = ReviewSession(CELL, row3())
    s.apply({"op": "move", "id": "c1", "position": [0.4612, 0.2, 0.025], "free": True})
    assert s.layout().objects[0].position == (0.4612, 0.2, 0.025)


def test_a_new_edit_clears_redo_and_each_finished_edit_is_one_step():
    s = ReviewSession(CELL, row3())
    s.apply({"op": "insert", "part": "beam", "position": [0.45, 0.30, 0.08], "yaw_deg": 90})
    assert len(s.steps) == 1 and len(s.edits) == 2  # insert + its turn: one undo step
    beam = s.layout().objects[-1]
    assert beam.size == (0.15, 0.05, 0.05) and round(yaw_deg(beam.orientation)) == 90
    assert beam.position == (0.45, 0.3, 0.075)
    s.undo()
    s.apply({"op": "rotate", "id": "c1", "by_deg": -90})
    assert not s.undone and round(yaw_deg(s.layout().objects[0].orientation)) == -90


def test_hints_apply_the_inspectors_suggestion():
    s = ReviewSession(CELL, row3())
    s.apply({"op": "move", "id": "c3", "position": [0.1, 0.3, 0.025]})
    k = next(i for i, v in enumerate(s.report().violations) if v.constraint == "workspace")
    s.apply({"op": "hint", "index": k})
    assert s.report().passed
    assert s.layout().objects[2].position[0] >= CELL.workspace.x_min + 0.025 - 1e-9
    # a floating part: the hint adds the missing support under it
    s.apply({"op": "move", "id": "c3", "position": [0.6, 0.3, 0.125]})
    k = next(i for i, v in enumerate(s.report().violations) if v.constraint == "contact")
    s.apply({"op": "hint", "index": k})
    assert len(s.layout()) == 4


def test_reorder_sets_the_assembly_order_and_the_inspector_checks_it():
    s = ReviewSession(CELL, layout(cube("a", 0.45, 0.3, 0.025), cube("b", 0.45, 0.3, 0.075)))
    s.apply({"op": "reorder", "id": "b", "before": "a"})  # the top before its support
    assert s.order == ["b", "a"]
    assert any(v.constraint in ("sequence", "gravity") for v in s.report().violations)
    s.undo()
    assert s.report().passed and s.report().sequence == ("a", "b")


@pytest.mark.parametrize(
    ("op", "field"),
    [
        ({"op": "fly", "id": "c1"}, "op"),
        ({"op": "move", "id": "zz", "position": [0.4, 0.3, 0.025]}, "id"),
        ({"op": "move", "id": "c1", "position": [0.4, "a", 0.025]}, "position"),
        ({"op": "move", "id": "c1", "position": [0.4, float("nan"), 0.025]}, "position"),
        ({"op": "move", "id": "c1", "position": [10**400, 0.3, 0.025]}, "position"),
        ({"op": "rotate", "id": "c1", "by_deg": 45}, "by_deg"),
        ({"op": "insert", "part": "brick", "position": [0.4, 0.3, 0.025]}, "part"),
        ({"op": "hint", "index": 0}, "index"),
        ({"op": "reorder", "id": "c1", "before": "nope"}, "before"),
    ],
)
def test_bad_operations_name_their_field_and_change_nothing(op, field):
    s = ReviewSession(CELL, row3())
    with pytest.raises(InputError) as info:
        s.apply(op)
    assert info.value.field == field
    assert s.steps == [] and s.version == 0 and s.layout() == row3()


# -- the service on a real run database --------------------------------------------------------
@pytest.fixture
def twin(tmp_path: Path):
    t = Twin(tmp_path / "runs.sqlite")
    yield t
    t.close()


def _review_run(twin: Twin, command: str = "a row of 3 cubes") -> str:
    run_id = twin.start(command)
    twin.wait()
    assert twin.view(run_id)["waiting_for"]["kind"] == "design_review"
    return run_id


def test_edits_survive_a_restart_of_the_server(tmp_path: Path):
    first = Twin(tmp_path / "runs.sqlite")
    run_id = _review_run(first)
    first.edit(run_id, "tab-a", {"op": "remove", "id": "c3"})
    first.close()
    second = Twin(tmp_path / "runs.sqlite")
    try:
        view = second.view(run_id)
        assert [p["id"] for p in view["review"]["parts"]] == ["c1", "c2"]
        assert view["review"]["can_undo"]
    finally:
        second.close()


def test_one_tab_holds_the_edit_lock(twin: Twin):
    run_id = _review_run(twin)
    twin.edit(run_id, "tab-a", {"op": "remove", "id": "c3"})
    with pytest.raises(LockedError):
        twin.edit(run_id, "tab-b", {"op": "undo"})
    twin.release(run_id, "tab-a")
    twin.edit(run_id, "tab-b", {"op": "undo"})
    assert len(twin.view(run_id)["review"]["parts"]) == 3


def test_accept_executes_exactly_the_edited_layout_and_revise_goes_back(twin: Twin):
    run_id = _review_run(twin)
    twin.edit(run_id, "t", {"op": "move", "id": "c3", "position": [0.55, 0.35, 0.025]})
    session = twin.session(run_id)
    assert session is not None
    seen = layout_hash(session.layout())
    with pytest.raises(InputError, match="changed"):
        twin.accept(run_id, "t", "0" * 64)
    twin.accept(run_id, "t", seen)
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "pre_execute", view
    record = twin._orch.record(run_id)
    assert record.body["layout_hash"] == seen
    timeline = twin.timeline(run_id)
    assert {s["part_id"] for s in timeline["steps"]} == {"c1", "c2", "c3"}
    assert all(s["release"] is not None and s["release"] <= timeline["makespan_s"]
               for s in timeline["steps"])  # fmt: skip
    with pytest.raises(InputError, match="record on screen"):
        twin.confirm(run_id, "t", "approve", "f" * 64)
    twin.confirm(run_id, "t", "revise", None)
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "design_review"
    assert view["record_hash"] is None
    assert layout_hash(Layout.model_validate(twin._orch.status(run_id).waiting_for["layout"])) \
        == seen  # fmt: skip


def test_accept_is_refused_while_violations_remain(twin: Twin):
    run_id = _review_run(twin)
    twin.edit(run_id, "t", {"op": "move", "id": "c3", "position": [0.45, 0.3, 0.025]})
    session = twin.session(run_id)
    assert session is not None
    with pytest.raises(InputError, match="violations"):
        twin.accept(run_id, "t", layout_hash(session.layout()))


# -- the HTTP API ------------------------------------------------------------------------------
def test_api_errors_name_the_field(twin: Twin):
    client = TestClient(create_app(twin))
    r = client.post("/api/runs", json={"command": "   "})
    assert r.status_code == 400 and r.json()["field"] == "command"
    r = client.post("/api/runs", content=b"not json", headers={"content-type": "application/json"})
    assert r.status_code == 400 and r.json()["field"] == "body"
    r = client.get("/api/runs/nope")
    assert r.status_code == 404
    assert client.get("/api/scene").json()["robots"][0]["chain"][0]["type"] == "revolute"


def test_the_token_gate(twin: Twin):
    client = TestClient(create_app(twin, token="s3cret"))
    assert client.get("/api/runs").status_code == 401
    assert client.get("/").status_code == 401
    assert client.get("/api/runs", headers={"authorization": "Bearer wrong"}).status_code == 401
    assert client.get("/api/runs", headers={"authorization": "Bearer s3cret"}).status_code == 200
    page = client.get("/?token=s3cret")  # the URL the CLI prints: sets the cookie
    assert page.status_code == 200 and "sdi_token" in page.cookies
    assert client.get("/api/runs").status_code == 200  # the cookie now carries it
    fresh = TestClient(create_app(twin, token="s3cret"))
    with pytest.raises(Exception), fresh.websocket_connect("/ws/runs/x") as ws:  # noqa: B017
        ws.receive_json()


def test_binding_beyond_loopback_needs_a_token():
    assert is_loopback("127.0.0.1") and is_loopback("::1") and is_loopback("localhost")
    assert not is_loopback("0.0.0.0")
    with pytest.raises(InputError) as info:
        check_bind("0.0.0.0", None)
    assert info.value.field == "--host"
    check_bind("0.0.0.0", "s3cret")
    check_bind("127.0.0.1", None)


def test_cli_refuses_a_public_bind_without_a_token(tmp_path: Path):
    proc = subprocess.run(
        [sys.executable, "-m", "sdi.cli", "twin", "--host", "0.0.0.0", "--db",
         str(tmp_path / "r.sqlite")],
        capture_output=True, text=True, timeout=120, env={"SDI_TWIN_TOKEN": "", "PATH": ""},
    )  # fmt: skip
    lines = [x for x in proc.stderr.splitlines() if not x.startswith("pybullet build")]
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert len(lines) == 1 and "--host" in lines[0] and "--token" in lines[0]
    assert not (tmp_path / "r.sqlite").exists()


def test_an_edit_refused_elsewhere_is_answered_in_the_twin(twin: Twin):
    """The CLI and the twin share the run database: an invalid edit sent from the command
    line pauses the run at `edit_review`, which the twin shows and answers."""
    from sdi.orchestrator import Orchestrator

    run_id = _review_run(twin)
    cli = Orchestrator(db=twin.db)
    try:
        outside = [{"op": "move", "id": "c3", "position": [1.0, 0.3, 0.025]}]
        status = cli.resume(run_id, {"action": "edit", "edits": outside})
    finally:
        cli.close()
    assert status.waiting_for["kind"] == "edit_review"
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "edit_review" and view["review"] is None
    assert {p["id"]: p["position"] for p in view["layout"]}["c3"] == [1.0, 0.3, 0.025]
    assert any(v["constraint"] == "workspace" for v in view["waiting_for"]["violations"])
    with pytest.raises(InputError) as info:
        twin.resolve_edit(run_id, "t", "maybe")
    assert info.value.field == "action"
    twin.resolve_edit(run_id, "t", "undo")
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "design_review"
    assert {p["id"]: p["position"] for p in view["review"]["parts"]}["c3"] == [0.45, 0.35, 0.025]


def test_the_reading_shows_what_the_specifier_left_unused(twin: Twin):
    run_id = twin.start("a tower of 3 cubes with a flag")
    twin.wait()
    reading = twin.view(run_id)["reading"]
    assert reading["ignored"] == ["flag"]
    assert any(s.startswith("tower#1") for s in reading["structures"])


# -- reject with a reason: the orchestrator replans --------------------------------------------
def _positions(view: dict) -> dict[str, list[float]]:
    return {p["id"]: p["position"] for p in view["review"]["parts"]}


def test_a_rejection_with_a_reason_replans_and_the_next_review_says_what_changed(twin: Twin):
    run_id = _review_run(twin)
    before = _positions(twin.view(run_id))
    with pytest.raises(InputError) as info:
        twin.reject(run_id, "t", "   ")
    assert info.value.field == "reason"
    twin.reject(run_id, "t", "move it to the back")
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "design_review", view
    after = _positions(view)
    assert set(after) == set(before)
    assert all(after[i][0] > before[i][0] for i in after)  # the back of the table: larger x
    assert "moved" in view["waiting_for"]["replanned"]
    # a reason the reader cannot use brings the same layout back: the review says so
    twin.reject(run_id, "t", "I do not like it")
    twin.wait()
    view = twin.view(run_id)
    assert _positions(view) == after
    assert "the same layout came back" in view["waiting_for"]["replanned"]
    assert "like" in view["waiting_for"]["replanned"]  # the words it did not use
    twin.abort(run_id, "t")
    twin.wait()
    assert twin.view(run_id)["status"] == "rejected"


def test_rejected_edits_do_not_come_back_with_the_same_layout(twin: Twin):
    run_id = _review_run(twin)
    twin.edit(run_id, "t", {"op": "remove", "id": "c3"})
    twin.reject(run_id, "t", "nothing I can say")
    twin.wait()
    review = twin.view(run_id)["review"]
    assert len(review["parts"]) == 3 and not review["can_undo"]


def test_a_reject_without_a_reason_still_ends_the_run(tmp_path: Path):
    from sdi.orchestrator import Orchestrator

    orch = Orchestrator(db=tmp_path / "r.sqlite")
    try:
        s = orch.start("a row of 3 cubes")
        assert s.waiting_for["choices"] == ["approve", "edit", "reject", "abort"]
        s = orch.resume(s.run_id, {"action": "reject", "reason": "  "})
        assert s.status == "rejected"
    finally:
        orch.close()


# -- touch point 3: the failure report's options, a δ breach -----------------------------------
def _executed(twin: Twin, command: str, faults: list[str]) -> str:
    run_id = twin.start(command, faults)
    twin.wait()
    twin.accept(run_id, "t", twin.view(run_id)["review"]["layout_hash"])
    twin.wait()
    view = twin.view(run_id)
    twin.confirm(run_id, "t", "approve", view["waiting_for"]["record_hash"])
    twin.wait()
    return run_id


def test_a_delta_breach_stops_the_robots_and_raises_the_failure_report(twin: Twin):
    run_id = _executed(twin, "a tower of 3 cubes", ["joint_drift"])
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "failure_report", view
    assert view["failure"]["error_type"] == "deviation"
    assert view["failure"]["scenario"] == "joint_drift"
    execution = view["execution"]
    assert execution["status"] == "paused" and execution["v_traj"] == "fail"
    assert execution["delta_rad"] > execution["epsilon_rad"]
    assert execution["completed_steps"] < 3  # stopped, not finished
    kinds = [e["type"] for e in twin.events(run_id)]
    assert kinds.index("execution") < len(kinds) - 1 - kinds[::-1].index("stopped")
    # the report offers the orchestrator's options: its recovery skills, retry, edit, abort
    waiting = view["waiting_for"]
    assert waiting["choices"] == ["recover", "retry", "edit", "abort"]
    assert [k["name"] for k in waiting["skills"]] == ["shift", "flatten", "spread", "modify"]
    assert view["review"] is not None  # the failed layout, open in the editor


def test_the_operator_picks_a_recovery_skill_at_the_failure_report(twin: Twin):
    run_id = _executed(twin, "a tower of 3 cubes", ["joint_drift"])
    with pytest.raises(InputError) as info:
        twin.failure_decision(run_id, "t", "recover", "teleport")
    assert info.value.field == "skill"
    twin.failure_decision(run_id, "t", "recover", "shift")  # nothing is blocked: refused
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "failure_report"
    assert "shift" in view["waiting_for"]["refused"]
    twin.failure_decision(run_id, "t", "recover", "flatten")  # lowers the tower
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "recovery_review", view
    assert view["waiting_for"]["recovery"]["action"] == "flatten"
    assert max(p["position"][2] for p in view["review"]["parts"]) < 0.125
    answers = [e["payload"] for e in twin.events(run_id) if e["type"] == "failure_decision"]
    assert answers[-1] == {"action": "recover", "skill": "flatten", "by": "twin"}


def test_a_human_edit_of_the_failed_layout_goes_back_to_design_review(twin: Twin):
    run_id = _executed(twin, "a tower of 3 cubes", ["joint_drift"])
    with pytest.raises(InputError, match="edit the failed layout first"):
        twin.accept(run_id, "t", twin.view(run_id)["review"]["layout_hash"])
    twin.edit(run_id, "t", {"op": "remove", "id": "c3"})
    twin.accept(run_id, "t", twin.view(run_id)["review"]["layout_hash"])
    twin.wait()
    view = twin.view(run_id)
    assert view["waiting_for"]["kind"] == "design_review", view
    assert sorted(_positions(view)) == ["c1", "c2"]
    answers = [e["payload"] for e in twin.events(run_id) if e["type"] == "failure_decision"]
    assert answers[-1]["action"] == "edit" and answers[-1]["edits"] == [
        {"op": "remove", "id": "c3"}
    ]


def test_a_worker_that_breaks_says_so_on_the_page_and_frees_the_run(twin: Twin):
    run_id = _executed(twin, "a tower of 3 cubes", ["joint_drift"])

    def broken(_orch: object) -> None:  # a bug in an action, not the operator's mistake
        raise KeyError("layout")

    twin._work(run_id, "edit-failed", broken)
    twin.wait()
    view = twin.view(run_id)
    assert view["busy"] is None and view["waiting_for"]["kind"] == "failure_report"
    assert view["error"].startswith("the edit-failed stopped on an internal error (KeyError")
    kinds = [e["type"] for e in twin.events(run_id)]
    assert kinds[-2:] == ["twin_error", "twin_idle"]


# -- the run's record, and the replay from its events ------------------------------------------
def test_the_record_is_the_one_awaiting_approval_after_a_recovery(tmp_path: Path):
    from sdi.orchestrator import Orchestrator

    orch = Orchestrator(db=tmp_path / "r.sqlite")
    try:
        s = orch.start("a row of 3 cubes", faults=["workspace_boundary"])
        s = orch.resume(s.run_id, {"action": "reject", "reason": "move it to the back"})
        s = orch.resume(s.run_id, {"action": "approve"})  # x = 0.65: beyond the boundary
        first = s.waiting_for["record_hash"]
        assert orch.record(s.run_id).hash == first  # awaiting approval
        s = orch.resume(s.run_id, {"action": "approve", "record_hash": first})
        assert s.state["approved_hash"] == first and s.state["execution"]["status"] == "failure"
        while s.waiting_for["kind"] != "pre_execute":  # the recovery's design, approved
            assert s.waiting_for["kind"] in ("design_review", "recovery_review"), s.waiting_for
            s = orch.resume(s.run_id, {"action": "approve"})
        second = s.waiting_for["record_hash"]
        assert second != first and s.state["approved_hash"] == first
        assert orch.record(s.run_id).hash == second  # not the stale approved one
        s = orch.resume(s.run_id, {"action": "abort"})
        assert s.status == "aborted"
        assert orch.record(s.run_id).hash == first  # nothing pending: the one approved
    finally:
        orch.close()


def test_a_finished_run_replays_from_its_events_alone(twin: Twin):
    from sdi.twin.replay import replay

    run_id = _review_run(twin)
    twin.edit(run_id, "t", {"op": "move", "id": "c3", "position": [0.55, 0.35, 0.025]})
    twin.accept(run_id, "t", twin.view(run_id)["review"]["layout_hash"])
    twin.wait()
    record_hash = twin.view(run_id)["waiting_for"]["record_hash"]
    twin.confirm(run_id, "t", "approve", record_hash)
    twin.wait()
    assert twin.view(run_id)["status"] == "success"
    told = twin.replay(run_id)
    assert told == replay(twin.events(run_id))  # the events, nothing else
    assert told["command"] == "a row of 3 cubes"
    kinds = [s["kind"] for s in told["steps"]]
    assert kinds == ["design", "decision", "design", "decision", "record", "approval",
                     "execution"]  # fmt: skip
    first, edit, second, approve, record, approval, execution = told["steps"]
    c3 = {p["id"]: p["position"] for p in first["parts"]}["c3"]
    assert c3 == [0.45, 0.35, 0.025]
    assert edit["action"] == "edit" and edit["by"] == "twin" and len(edit["edits"]) == 1
    assert {p["id"]: p["position"] for p in second["parts"]}["c3"] == [0.55, 0.35, 0.025]
    assert (first["version"], second["version"]) == (1, 2)
    assert approve["action"] == "approve"
    assert record["record_hash"] == approval["record_hash"] == record_hash
    assert approval["by"] == "twin"
    assert execution["record_hash"] == record_hash
    assert execution["report"]["v_traj"] == "pass"
    assert execution["report"]["delta_rad"] <= execution["report"]["epsilon_rad"]
    placed = [e for e in execution["events"] if e["type"] == "step_done"]
    assert sorted(e["payload"]["part_id"] for e in placed) == ["c1", "c2", "c3"]
    assert any(e["type"] == "samples" for e in execution["events"])
    assert twin.timeline(run_id, record_hash)["record_hash"] == record_hash
    client = TestClient(create_app(twin))
    assert client.get(f"/api/runs/{run_id}/replay").json() == told
    r = client.get(f"/api/runs/{run_id}/timeline", params={"record": "f" * 64})
    assert r.status_code == 400 and r.json()["field"] == "record"


def test_the_answer_handlers_leave_the_event_loop_free(tmp_path: Path):
    """While the run database is busy, a reject, an edit-review answer and a failure answer
    wait in worker threads: the server keeps answering other requests meanwhile."""
    import threading
    import time

    import httpx

    from twin_harness import served

    with served(tmp_path / "runs.sqlite") as (url, twin):
        run_id = _review_run(twin)
        codes: dict[str, int] = {}

        def post(path: str, data: dict) -> None:
            codes[path] = httpx.post(f"{url}api/runs/{run_id}/{path}", json=data,
                                     timeout=60).status_code  # fmt: skip

        answers = {"reject": {"tab": "t", "reason": "move it to the back"},
                   "edit-review": {"tab": "t", "action": "undo"},
                   "failure": {"tab": "t", "action": "retry"}}  # fmt: skip
        threads = [threading.Thread(target=post, args=a) for a in answers.items()]
        with twin._lock:  # the service's reads of the run database wait for this
            for t in threads:
                t.start()
            time.sleep(1.0)  # the three requests reach the server and wait
            assert httpx.get(f"{url}api/scene", timeout=10).status_code == 200
            assert all(t.is_alive() for t in threads)  # still waiting, yet the loop answered
        for t in threads:
            t.join(timeout=60)
        assert codes == {"reject": 200, "edit-review": 400, "failure": 400}
