"""The commissioning record: planned once, approved by hash, executed exactly, refused if changed.

Tampering is done to the real SQLite file and the real cell file; execution is the real sim.
"""

from __future__ import annotations

import json
import sqlite3
import subprocess
import sys

import numpy as np
import pytest

from sdi.commission import commission
from sdi.execute.record import CommissioningRecord, RecordError, cell_hash
from sdi.model.cell import CellConfig
from sdi.model.layout import parse_layout
from sdi.orchestrator import Orchestrator

SDI = [sys.executable, "-m", "sdi.cli"]


def sdi(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=600)


@pytest.fixture
def orch(tmp_path):
    o = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    yield o
    o.close()


def at_confirmation(orch: Orchestrator, command: str = "a 2-cube tower at x = 0.4"):
    s = orch.start(command)
    s = orch.resume(s.run_id, {"action": "approve"})
    assert s.status == "paused" and s.waiting_for["kind"] == "pre_execute"
    return s


def types(orch: Orchestrator, run_id: str) -> list[str]:
    return [m.type for m in orch.bus.history(run_id)]


def test_the_record_round_trips_exactly():
    cell = CellConfig()
    layout, _ = parse_layout(
        {"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], "size": [0.05, 0.05, 0.05]},
                     {"id": "b", "position": [0.4, 0.3, 0.075], "size": [0.05, 0.05, 0.05]}]}
    )  # fmt: skip
    planned = commission(layout, cell, arms=["irb120"])
    record = CommissioningRecord.of(planned)
    again = record.commissioning(cell)
    assert CommissioningRecord.of(again).hash == record.hash
    for robot, tr in planned.motion.trajectories.items():
        assert np.array_equal(tr.q, again.motion.trajectories[robot].q)
        assert np.array_equal(tr.t, again.motion.trajectories[robot].t)
    with pytest.raises(RecordError, match="cell configuration changed"):
        record.commissioning(CellConfig.model_validate({"workspace": {"z_max": 0.45}}))
    with pytest.raises(RecordError, match="changed after it was planned"):
        CommissioningRecord.load(record.text.replace('"parallel":false', '"parallel":true'),
                                 record.hash)  # fmt: skip


def test_what_runs_is_what_was_approved(orch):
    s = at_confirmation(orch)
    record = s.waiting_for["record_hash"]
    assert s.waiting_for["planning"]["record_hash"] == record
    assert s.waiting_for["planning"]["steps_per_robot"] == {"irb120": 2}
    s = orch.resume(s.run_id, {"action": "approve", "record_hash": record})
    assert s.status == "success"
    execution = s.state["execution"]
    assert execution["record_hash"] == record == s.state["approved_hash"]
    assert execution["v_traj"] == "pass" and execution["delta_rad"] < 0.05  # Q_exec tracks it
    kinds = types(orch, s.run_id)
    assert kinds.count("record") == 1  # motion planned once: in PRE_EXECUTE, never in EXECUTE


def test_an_approval_naming_another_record_moves_nothing(orch):
    s = at_confirmation(orch)
    s = orch.resume(s.run_id, {"action": "approve", "record_hash": "0" * 64})
    assert s.status == "aborted"
    assert "execution_started" not in types(orch, s.run_id)


def test_a_tampered_record_is_refused(orch):
    s = at_confirmation(orch)
    conn = sqlite3.connect(orch.db)
    conn.execute("UPDATE records SET body = replace(body, '\"rate_hz\":50.0', '\"rate_hz\":5.0')")
    conn.commit()
    conn.close()
    s = orch.resume(s.run_id, {"action": "approve", "record_hash": s.waiting_for["record_hash"]})
    assert s.status == "failure" and s.state["failure"]["error_type"] == "record"
    assert "changed after it was planned" in s.state["failure"]["message"]
    kinds = types(orch, s.run_id)
    assert "refused" in kinds and "execution_started" not in kinds


def test_a_layout_changed_after_approval_is_refused(orch):
    s = at_confirmation(orch)
    record = s.waiting_for["record_hash"]
    layout = dict(s.state["layout"])
    layout["objects"] = [dict(o) for o in layout["objects"]]
    layout["objects"][0]["position"] = [0.41, 0.3, 0.025]
    layout["objects"][1]["position"] = [0.41, 0.3, 0.075]
    config = {"configurable": {"thread_id": s.run_id}}
    orch.graph.update_state(
        config, {"layout": layout, "approved_hash": record, "phase": "execute"}, as_node="confirm"
    )
    s = orch.resume(s.run_id)
    assert s.status == "failure" and "layout changed" in s.state["failure"]["message"]
    assert "execution_started" not in types(orch, s.run_id)


def test_a_cell_changed_after_approval_is_refused(orch):
    s = at_confirmation(orch)
    record = s.waiting_for["record_hash"]
    other = CellConfig.model_validate({"workspace": {"z_max": 0.45}})
    config = {"configurable": {"thread_id": s.run_id}}
    changed = {"cell": other.model_dump(mode="json"), "cell_hash": cell_hash(other)}
    orch.graph.update_state(
        config, {**changed, "approved_hash": record, "phase": "execute"}, as_node="confirm"
    )
    s = orch.resume(s.run_id)
    assert s.status == "failure" and "cell configuration changed" in s.state["failure"]["message"]
    assert "execution_started" not in types(orch, s.run_id)


def test_resume_is_bound_to_the_cell_and_backend_it_started_with(tmp_path):
    db = tmp_path / "runs.sqlite"
    cell = tmp_path / "cell.toml"
    cell.write_text("[workspace]\nz_max = 0.50\n")
    proc = sdi("run", "a 2-cube tower at x = 0.4", "--approve", "--cell", str(cell),
               "--arms", "irb120", "--json", "--db", str(db))  # fmt: skip
    status = json.loads(proc.stdout)
    run_id, started = status["run_id"], status["cell_hash"]
    assert status["waiting_for"]["kind"] == "pre_execute"
    cell.write_text("[workspace]\nz_max = 0.45\n")  # the cell file changes after approval
    now = cell_hash(CellConfig.load(cell))
    refused = sdi("resume", run_id, "--approve", "--cell", str(cell), "--db", str(db))
    message = " ".join(refused.stderr.split())
    assert refused.returncode == 2 and started[:12] in message and now[:12] in message
    other = sdi("resume", run_id, "--approve", "--backend", "openai", "--db", str(db))
    assert other.returncode == 2 and "'rules'" in other.stderr and "'openai'" in other.stderr
    bus_types = json.loads(sdi("log", run_id, "--json", "--db", str(db)).stdout)["messages"]
    assert "execution_started" not in [m["type"] for m in bus_types]
    # without --cell the run continues with its own cell, and executes the approved record
    done = sdi("resume", run_id, "--approve", "--json", "--db", str(db))
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["status"] == "success" and result["cell_hash"] == started
    assert result["execution"]["record_hash"] == status["waiting_for"]["record_hash"]


def test_replan_with_cell_inspects_and_plans_again(tmp_path):
    db = tmp_path / "runs.sqlite"
    cell = tmp_path / "cell.toml"
    cell.write_text("[workspace]\nz_max = 0.50\n")
    status = json.loads(
        sdi("run", "a 2-cube tower at x = 0.4", "--approve", "--cell", str(cell),
            "--arms", "irb120", "--json", "--db", str(db)).stdout
    )  # fmt: skip
    cell.write_text("[workspace]\nz_max = 0.45\n")
    proc = sdi("resume", status["run_id"], "--cell", str(cell), "--replan-with-cell", "--json",
               "--db", str(db))  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    again = json.loads(proc.stdout)
    assert again["cell_hash"] == cell_hash(CellConfig.load(cell)) != status["cell_hash"]
    assert again["waiting_for"]["kind"] == "design_review"  # a new design review, new cell
    kinds = [m["type"] for m in json.loads(
        sdi("log", status["run_id"], "--json", "--db", str(db)).stdout)["messages"]]  # fmt: skip
    assert kinds.count("verification") == 2 and "cell_changed" in kinds


def test_programs_can_be_written_from_the_stored_record(orch):
    from sdi.export import rapid_module

    s = at_confirmation(orch)
    record = orch.record(s.run_id)
    assert record.hash == s.waiting_for["record_hash"]
    texts = []
    for _ in range(2):
        plan = record.commissioning(record.cell())
        texts.append(rapid_module(plan.job, plan.tasks, plan.motion, plan.robots["irb120"]))
    assert texts[0] == texts[1] and "MODULE" in texts[0]  # the same motion, every time


def test_sdi_export_writes_the_approved_record_of_a_run_only(orch, tmp_path):
    from sdi.export import rapid_module

    s = at_confirmation(orch)
    record = orch.record(s.run_id)
    plan = record.commissioning(record.cell())
    expected = rapid_module(plan.job, plan.tasks, plan.motion, plan.robots["irb120"])
    out = tmp_path / "rapid"
    waiting = sdi("export", "--run", s.run_id, "--db", str(orch.db), "--rapid", str(out))
    assert waiting.returncode == 2 and "no approved commissioning record" in waiting.stderr
    assert not out.exists()  # nothing written for a record no one approved
    orch.resume(s.run_id, {"action": "approve", "record_hash": record.hash})
    assert orch.approved_record(s.run_id).hash == record.hash
    proc = sdi("export", "--run", s.run_id, "--db", str(orch.db), "--rapid", str(out))
    assert proc.returncode == 0, proc.stderr
    assert (out / "SDI_IRB120.mod").read_text(encoding="utf-8") == expected
    both = sdi("export", "layout.json", "--run", s.run_id, "--rapid", str(tmp_path / "x"))
    assert both.returncode == 2 and "LAYOUT_FILE cannot be exported" in both.stderr
    missing = sdi("export", "--run", "nope", "--db", str(orch.db), "--rapid", str(tmp_path / "y"))
    assert missing.returncode == 2 and "Traceback" not in missing.stderr
