"""`sdi execute`, `sdi export` and `sdi run` as real subprocesses (sim, no robot)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from rapid_replay import rapidchecker_errors

pytestmark = pytest.mark.slow
SDI = [sys.executable, "-m", "sdi.cli"]


def run(*args: str, stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=600, input=stdin)


@pytest.fixture(scope="module")
def tower_file(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("cli") / "tower.json"
    proc = run("plan", "a 2-cube tower at x = 0.4", "--out", str(path))
    assert proc.returncode == 0, proc.stderr
    return path


def test_execute_reports_and_plots(tower_file, tmp_path):
    proc = run("execute", str(tower_file), "--arms", "irb120", "--json", "--report", str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["status"] == "success" and report["v_traj"] == "pass"
    assert report["max_placement_error_m"] <= 0.002
    assert report["planning"]["steps"] == 2
    assert json.loads((tmp_path / "report.json").read_text())["v_traj"] == "pass"
    assert (tmp_path / "deviation.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_execute_refuses_an_unverified_layout(tmp_path):
    path = tmp_path / "floating.json"
    path.write_text(json.dumps({"objects": [{"id": "a", "position": [0.4, 0.3, 0.3]}]}))
    proc = run("execute", str(path), "--json")
    assert proc.returncode == 1
    out = json.loads(proc.stdout)
    assert out["status"] == "refused"
    # the Inspector's violations as objects: constraint, the parts, message, hint
    contact = [v for v in out["violations"] if v["constraint"] == "contact"]
    assert contact and contact[0]["objects"] == ["a"] and contact[0]["hint"]
    proc = run("execute", str(path))  # the table: the part and the hint
    assert proc.returncode == 1 and "contact" in proc.stderr and "a" in proc.stderr


def test_execute_unknown_fault_is_bad_input(tower_file):
    proc = run("execute", str(tower_file), "--fault", "meteor")
    assert proc.returncode == 2 and "low_ceiling" in proc.stderr


def approved_run(layout: Path, db: Path, *args: str) -> str:
    """Run a layout file through the orchestrator, every review approved (the design and the
    commissioning record); the run's id."""
    proc = run("run", "--layout", str(layout), "--approve-all", "--json", "--db", str(db), *args)
    assert proc.returncode == 0, proc.stderr
    status = json.loads(proc.stdout)
    assert status["status"] == "success" and status["approved_hash"] == status["record_hash"]
    return str(status["run_id"])


def test_export_of_a_layout_file_needs_an_approved_record(tower_file, tmp_path):
    proc = run("export", str(tower_file), "--rapid", str(tmp_path / "rapid"))
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    assert "approved commissioning record" in proc.stderr and "sdi run --layout" in proc.stderr
    assert not (tmp_path / "rapid").exists()  # nothing written
    proc = run("export", "--rapid", str(tmp_path / "rapid"))
    assert proc.returncode == 2 and "--run" in proc.stderr and not (tmp_path / "rapid").exists()


def test_export_writes_rapid_and_python(tower_file, tmp_path):
    run_id = approved_run(tower_file, tmp_path / "runs.sqlite", "--arms", "irb120")
    db, rapid, prog = tmp_path / "runs.sqlite", tmp_path / "rapid", tmp_path / "prog.py"
    proc = run(
        "export", "--run", run_id, "--db", str(db), "--rapid", str(rapid), "--python", str(prog)
    )
    assert proc.returncode == 0, proc.stderr
    module = (tmp_path / "rapid" / "SDI_IRB120.mod").read_text()
    assert module.startswith("MODULE SDI_IRB120") and module.count("MoveL") == 8
    check = subprocess.run(
        [sys.executable, str(tmp_path / "prog.py"), "--dry-run"], capture_output=True, text=True
    )
    assert check.returncode == 0, check.stderr
    assert "MoveL" in check.stdout


def test_export_interlocks_a_dual_arm_job(tmp_path):
    layout = tmp_path / "bridge.json"
    proc = run("plan", "a bridge at x = 0.35", "--out", str(layout))
    assert proc.returncode == 0, proc.stderr
    run_id = approved_run(layout, tmp_path / "runs.sqlite")
    db, rapid, prog = tmp_path / "runs.sqlite", tmp_path / "rapid", tmp_path / "prog.py"
    proc = run(
        "export", "--run", run_id, "--db", str(db), "--rapid", str(rapid), "--python", str(prog)
    )
    assert proc.returncode == 0, proc.stderr
    modules = {p.stem: p.read_text() for p in (tmp_path / "rapid").glob("SDI_*.mod")}
    assert sorted(modules) == ["SDI_IRB120", "SDI_IRB1600"]
    for text in modules.values():
        assert "WaitDI diSDI_" in text and "SetDO doSDI_" in text and "PROC sdi_reset()" in text
        assert rapidchecker_errors(text) == []
    source = (tmp_path / "prog.py").read_text()
    assert "def run(clients" in source and "'after': [['irb" in source
    check = subprocess.run(
        [sys.executable, str(tmp_path / "prog.py"), "--dry-run"], capture_output=True, text=True
    )
    assert check.returncode == 0, check.stderr


def test_run_waits_for_a_human_ok(tmp_path):
    db = tmp_path / "runs.sqlite"
    proc = run("run", "a 2-cube tower at x = 0.4", "--json", "--db", str(db))  # no terminal
    assert proc.returncode == 0, proc.stderr
    status = json.loads(proc.stdout)
    assert status["status"] == "paused" and status["waiting_for"]["kind"] == "design_review"
    assert status.get("execution") is None  # nothing moved


def test_run_approve_answers_only_the_design_review(tmp_path):
    db = tmp_path / "runs.sqlite"
    proc = run("run", "a 2-cube tower at x = 0.4", "--approve", "--arms", "irb120", "--json",
               "--db", str(db))  # fmt: skip
    assert proc.returncode == 0, proc.stderr
    status = json.loads(proc.stdout)
    waiting = status["waiting_for"]
    assert status["status"] == "paused" and waiting["kind"] == "pre_execute"
    assert status.get("execution") is None  # nothing moved
    record = waiting["record_hash"]
    assert len(record) == 64 and waiting["planning"]["record_hash"] == record
    proc = run("resume", status["run_id"], "--approve", "--json", "--db", str(db))
    assert proc.returncode == 0, proc.stderr
    done = json.loads(proc.stdout)
    assert done["status"] == "success" and done["approved_hash"] == record
    assert done["execution"]["record_hash"] == record  # what ran is what was approved


def test_run_with_approval_executes(tmp_path):
    db = tmp_path / "runs.sqlite"
    proc = run(
        "run",
        "a 2-cube tower at x = 0.4",
        "--approve-all",
        "--arms",
        "irb120",
        "--json",
        "--db",
        str(db),
    )
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout)
    assert report["status"] == "success" and report["execution"]["v_traj"] == "pass"
    assert report["usage"]["llm_calls"] == 0  # the rules backend: no model at all


def test_unreachable_supply_area_is_bad_input(tower_file, tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text(
        '[[supply_areas]]\nname = "far"\nrobot = "irb120"\nx_range = [0.60, 0.70]\n'
        'y_range = [0.0, 0.1]\n\n[[supply_areas]]\nname = "b"\nrobot = "irb1600"\n'
        "x_range = [0.95, 1.10]\ny_range = [0.72, 0.87]\n"
    )
    proc = run("execute", str(tower_file), "--cell", str(cell))
    assert proc.returncode == 2
    assert "supply_areas.far" in proc.stderr and "Traceback" not in proc.stderr
