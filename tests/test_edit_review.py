"""Edits are the operator's intent: an edit the Inspector refuses is shown with its violations
and answered by the operator (repair, undo, replan); the result is re-verified, the diff from
their layout is stated, and no edit spends the replan budget. Order edits and insert with yaw."""

from __future__ import annotations

import itertools
import json

import pytest

from scripted_model import tower
from sdi.design import compose
from sdi.errors import InputError
from sdi.inspector import verify
from sdi.inspector.analysis import Analysis
from sdi.model.cell import CellConfig
from sdi.model.layout import parse_layout
from sdi.orchestrator import Orchestrator
from sdi.orchestrator.edits import edit
from sdi.recovery.repair import nearest_order, repair_edit
from sdi.spec import Spec, structure


@pytest.fixture
def orch(tmp_path):
    o = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    yield o
    o.close()


def build(shape: str, **kw):
    return compose(Spec(structures=(structure(shape, **kw),)))


def positions(layout: dict) -> dict[str, list[float]]:
    return {o["id"]: o["position"] for o in layout["objects"]}


OUTSIDE = [{"op": "move", "id": "c3", "position": [1.0, 0.3, 0.125]}]  # x = 1.0: outside


def test_an_invalid_edit_is_shown_not_discarded(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE})
    w = s.waiting_for
    assert s.status == "paused" and w["kind"] == "edit_review"
    assert positions(w["layout"])["c3"] == [1.0, 0.3, 0.125]  # the operator's layout
    assert "workspace" in {v["constraint"] for v in w["violations"]}
    assert w["repair"] is not None and set(w["choices"]) >= {"repair", "undo", "replan"}
    # the repair keeps c3 as close as it can: back inside the workspace at the edge, on the table
    fixed = positions(w["repair"]["layout"])
    assert fixed["c3"][0] == pytest.approx(0.775) and fixed["c3"][2] == pytest.approx(0.025)
    assert s.state["replans"] == 0 and not s.state.get("tried")


def test_repair_is_reverified_and_the_diff_is_stated(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE})
    s = orch.resume(s.run_id, {"action": "repair"})
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    layout, _ = parse_layout(s.waiting_for["layout"])
    assert verify(layout).passed
    outcome = s.state["edit_outcome"]
    assert outcome["choice"] == "repair" and [c["id"] for c in outcome["changes"]] == ["c3"]
    assert "c3 moved by (-0.225, 0, -0.1) m" in s.state["notes"][-1]
    events = [m.type for m in orch.bus.history(s.run_id)]
    assert "edit_check" in events and "edit_resolved" in events  # the audit trail has both


def test_undo_returns_to_the_layout_before_the_edit(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    before = s.waiting_for["layout"]
    s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE})
    s = orch.resume(s.run_id, {"action": "undo"})
    assert s.waiting_for["kind"] == "design_review" and s.waiting_for["layout"] == before
    assert s.state["edit_outcome"]["choice"] == "undo"
    assert [c["id"] for c in s.state["edit_outcome"]["changes"]] == ["c3"]


def test_replan_redesigns_and_reports_the_diff(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE})
    s = orch.resume(s.run_id, {"action": "replan"})
    assert s.status == "paused" and s.waiting_for["kind"] == "design_review"
    outcome = s.waiting_for["edit_outcome"]
    assert outcome["choice"] == "replan" and any(c["id"] == "c3" for c in outcome["changes"])
    assert s.state["replans"] == 0  # the operator's choice, not a failure


def test_invalid_edits_do_not_spend_the_replan_budget(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    for k in range(5):  # more than the method's 3 replans
        s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE if k == 0 else [
            {"op": "translate", "id": "c2", "by": [0.0, 0.0, 0.2]}]})  # fmt: skip
        assert s.status == "paused" and s.waiting_for["kind"] == "edit_review", k
    assert s.state["replans"] == 0 and s.state.get("failure") is None


def test_approve_does_not_answer_a_refused_edit(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    s = orch.resume(s.run_id, {"action": "edit", "edits": OUTSIDE})
    s = orch.resume(s.run_id, {"action": "approve"}, approve_all=True)
    assert s.status == "paused" and s.waiting_for["kind"] == "edit_review"
    assert "repair" in s.waiting_for["refused"]
    assert "execution" not in [m.type for m in orch.bus.history(s.run_id)]


def test_a_valid_order_edit_is_kept(orch):
    s = orch.start("a row of 3 cubes")
    order = s.waiting_for["sequence"][::-1]  # flat: any order is valid
    s = orch.resume(s.run_id, {"action": "edit", "edits": [{"op": "sequence", "reverse": True}]})
    assert s.waiting_for["kind"] == "design_review" and s.waiting_for["sequence"] == order


def test_a_refused_order_shows_the_nearest_valid_one(orch):
    s = orch.start("a 3-cube tower at x = 0.45")
    s = orch.resume(s.run_id, {"action": "edit", "edits": [{"op": "sequence", "reverse": True}]})
    w = s.waiting_for
    assert w["kind"] == "edit_review" and w["nearest_order"] == ["c1", "c2", "c3"]
    assert {v["constraint"] for v in w["violations"]} & {"gravity", "sequence"}
    s = orch.resume(s.run_id, {"action": "repair"})
    assert s.waiting_for["kind"] == "design_review" and s.waiting_for["sequence"] == w[
        "nearest_order"
    ]  # fmt: skip


def test_nearest_order_moves_only_what_must_come_later():
    layout = build("staircase", steps=3)
    wanted = layout.ids[::-1]
    order = nearest_order(layout, layout_cell(), wanted)
    assert order is not None and verify(layout, sequence=order).passed
    # among the parts on the table, the operator's (reversed) order is kept
    ground = [pid for pid in order if layout.part(pid).bottom < 1e-6]
    assert ground == [pid for pid in wanted if layout.part(pid).bottom < 1e-6]


def test_nearest_order_keeps_the_move_before_pairs_the_supports_allow():
    layout = build("canopy", height=4)  # Table IV's H9: the roof before the pillars
    first = layout.ids[0]  # the first pillar cube of the generator's order
    roof = ("b1", "b2", "b3", "b4", "b5")
    assert len(layout) == 21  # the paper's 21-step canopy: 4 pillars of 4 and a 5-beam roof
    wanted = edit(layout, [{"op": "sequence", "move": b, "before": first}
                           for b in roof], sequence=layout.ids)  # fmt: skip
    assert wanted.asked == tuple((b, first) for b in roof)
    fix = repair_edit(wanted.layout, touched=(), sequence=wanted.sequence, asked=wanted.asked)
    assert fix is not None and verify(layout, sequence=fix.sequence).passed
    at = {pid: k for k, pid in enumerate(fix.sequence)}
    # a beam may come before that cube exactly when the cube does not hold it up
    below = Analysis(layout, layout_cell()).graph.support_edges
    holds: dict[str, set[str]] = {}
    for lo, up in below.tolist():
        holds.setdefault(layout.ids[up], set()).add(layout.ids[lo])

    def under(pid: str) -> set[str]:
        out = set(holds.get(pid, ()))
        for q in list(out):
            out |= under(q)
        return out

    possible = [(b, first) for b, _ in wanted.asked if first not in under(b)]
    assert possible  # some beam stands on pillars that do not include that cube
    assert all(at[b] < at[first] for b, _ in possible)
    assert set(fix.unkept) == set(wanted.asked) - set(possible)
    assert "not kept: " in fix.describe()


def layout_cell():
    from sdi.model.cell import CellConfig

    return CellConfig()


def test_order_edits_move_before_and_errors_name_the_field():
    layout, _ = parse_layout(json.dumps(tower(3)))
    moved = edit(layout, [{"op": "sequence", "move": ["c3"], "before": "c1"}])
    assert moved.sequence == ("c3", "c1", "c2") and moved.layout == layout
    assert edit(layout, [{"op": "sequence", "order": ["c2", "c1", "c3"]}]).sequence == (
        "c2", "c1", "c3",
    )  # fmt: skip
    for bad, where in (
        ({"op": "sequence"}, "edits[0]"),
        ({"op": "sequence", "order": ["c1", "c2"]}, "edits[0].order"),
        ({"op": "sequence", "move": "zz", "before": "c1"}, "edits[0].move"),
        ({"op": "sequence", "move": "c1", "before": "c1"}, "edits[0].before"),
        ({"op": "sequence", "reverse": "yes"}, "edits[0].reverse"),
    ):
        with pytest.raises(InputError) as info:
            edit(layout, [bad])
        assert info.value.field == where


def test_insert_takes_a_yaw():
    layout, _ = parse_layout(json.dumps(tower(1)))
    out = edit(layout, [{"op": "insert", "id": "b", "position": [0.5, 0.3, 0.025],
                         "size": [0.1, 0.05, 0.05], "yaw_deg": 90}])  # fmt: skip
    part = out.layout.part("b")
    assert part.half_extents[0] == pytest.approx(0.025) and part.half_extents[1] == pytest.approx(
        0.05
    )  # fmt: skip
    assert out.touched == ("b",)
    with pytest.raises(InputError, match=r"edits\[0\]\.yaw_deg"):
        edit(layout, [{"op": "insert", "id": "b", "position": [0.5, 0.3, 0.025], "yaw_deg": "x"}])


def test_repair_keeps_what_the_operator_did_when_it_can():
    layout = build("tower", height=5, at_x=0.45, at_y=0.3)
    gone = edit(layout, [{"op": "remove", "id": "c3"}]).layout
    fix = repair_edit(gone, touched=())
    assert fix is not None and "c3" not in fix.layout.ids  # the removal stands
    assert verify(fix.layout).passed and len(fix.layout) == 4
    assert {c.id for c in fix.changes} == {"c4", "c5"}  # only the parts above settled
    assert all(c.by is not None and c.by[2] == pytest.approx(-0.05) for c in fix.changes)


def test_repair_of_a_collision_keeps_the_operators_part_and_moves_the_other_aside():
    layout = build("row", length=6, axis="y")  # Table IV's H4: c2 put where c1 stands
    c1, c2 = layout.part("c1"), layout.part("c2")
    stacked = edit(layout, [{"op": "move", "id": "c2", "position": list(c1.position)}])
    fix = repair_edit(stacked.layout, touched=stacked.touched, original=layout)
    assert fix is not None and verify(fix.layout).passed and fix.kept == ("c2",)
    assert fix.layout.part("c2").position == c1.position  # exactly where the operator put it
    assert fix.layout.part("c1").position == c2.position  # c1 took the place c2 left
    assert [c.id for c in fix.changes] == ["c1"] and "c1 moved by (0, 0.05, 0) m" in fix.describe()


def test_a_part_pushed_aside_takes_what_rests_on_it_and_a_hanging_part_follows():
    layout = build("block", length=3, width=2, height=2)  # Table IV's H5
    shoved = edit(layout, [{"op": "translate", "id": "c1", "by": [-0.025, 0.0, 0.0]}])
    assert not verify(shoved.layout).passed  # c1 overlaps c4, c7 hangs over its edge
    fix = repair_edit(shoved.layout, touched=shoved.touched, original=layout)
    assert fix is not None and verify(fix.layout).passed and fix.kept == ("c1",)
    assert fix.layout.part("c1").position == shoved.layout.part("c1").position
    by = {c.id: c.by for c in fix.changes}
    assert by == {"c4": (-0.025, 0.0, 0.0), "c10": (-0.025, 0.0, 0.0), "c7": (-0.025, 0.0, 0.0)}


def test_with_no_room_to_make_the_operators_part_is_lifted_onto_the_other():
    layout = build("grid", length=3, width=3, at_x=0.45, at_y=0.3)
    centre = min(layout, key=lambda p: abs(p.position[0] - 0.45) + abs(p.position[1] - 0.3))
    corner = layout.objects[0]
    stacked = edit(layout, [{"op": "move", "id": corner.id, "position": list(centre.position)}])
    fix = repair_edit(stacked.layout, touched=stacked.touched)  # no original: no vacated place
    assert fix is not None and verify(fix.layout).passed
    moved = fix.layout.part(corner.id)
    assert moved.position[:2] == centre.position[:2] and moved.bottom == pytest.approx(centre.top)
    assert len(fix.changes) == 1


def test_parts_moved_together_come_back_inside_together():
    layout = build("wall", length=3, height=3, at_x=0.45, at_y=0.3)
    top = [p for p in layout if p.top > 0.15 - 1e-9]
    y0 = min(p.position[1] for p in top)
    moved = edit(layout, [{"op": "translate", "id": p.id, "by": [0.0, 0.01 - y0, 0.0]}
                          for p in top])  # fmt: skip
    fix = repair_edit(moved.layout, touched=moved.touched, original=layout)
    assert fix is not None and verify(fix.layout).passed and len(fix.layout) == 9
    rows = sorted(fix.layout.part(p.id).position[1] for p in top)
    gaps = [b - a for a, b in itertools.pairwise(rows)]
    assert gaps == pytest.approx([0.05, 0.05])  # still a row, as the operator moved it
    assert rows[0] - 0.025 == pytest.approx(CellConfig().workspace.y_min)  # as close as it can
