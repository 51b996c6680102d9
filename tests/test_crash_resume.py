"""Crash and resume with the real CLI, SQLite checkpoints and processes that really die."""

from __future__ import annotations

import json
import os
import pty
import re
import select
import signal
import subprocess
import sys
import time

import pytest

from sdi.orchestrator import MessageBus

pytestmark = pytest.mark.slow
SDI = [sys.executable, "-m", "sdi.cli"]


def history(db, run_id: str) -> list[str]:
    bus = MessageBus(db)
    try:
        return [m.type for m in bus.history(run_id)]
    finally:
        bus.close()


def test_kill_during_human_review_then_resume(tmp_path):
    db = tmp_path / "runs.sqlite"
    master, slave = pty.openpty()  # stdin is a terminal: the CLI asks and waits
    proc = subprocess.Popen(
        [*SDI, "run", "a 2-cube tower at x = 0.4", "--db", str(db), "--arms", "irb120"],
        stdin=slave, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )  # fmt: skip
    os.close(slave)
    seen = b""
    deadline = time.monotonic() + 120
    while b"Design review" not in seen and time.monotonic() < deadline:
        ready, _, _ = select.select([proc.stdout, proc.stderr], [], [], 1.0)
        for stream in ready:
            seen += os.read(stream.fileno(), 65536)
    assert b"Design review" in seen, seen[-2000:]
    run_id = re.search(rb"run ([0-9a-f]{12})", seen).group(1).decode()
    proc.send_signal(signal.SIGKILL)  # the operator's terminal dies mid-review
    proc.wait(timeout=30)
    proc.stdout.close()
    proc.stderr.close()
    os.close(master)
    before = history(db, run_id)
    assert "verification" in before and "execution" not in before
    done = subprocess.run(
        [*SDI, "resume", run_id, "--approve-all", "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["status"] == "success" and result["execution"]["v_traj"] == "pass"
    after = history(db, run_id)
    assert after[: len(before)] == before  # nothing from before the kill was lost


def test_crash_during_replan_then_resume(tmp_path):
    db = tmp_path / "runs.sqlite"
    env = {**os.environ, "SDI_CRASH_AT": "replan"}
    crashed = subprocess.run(
        [*SDI, "run", "a 3-cube tower at x = 0.4", "--fault", "low_ceiling", "--approve-all",
         "--db", str(db), "--arms", "irb120", "--json"],
        capture_output=True, text=True, timeout=600, env=env,
    )  # fmt: skip
    assert crashed.returncode == 137  # died inside REPLAN
    bus = MessageBus(db)
    (run_id,) = bus.runs()
    failures = [m for m in bus.history(run_id) if m.type == "execution"]
    bus.close()
    assert failures and failures[0].payload["status"] == "failure"
    resumed = subprocess.run(
        [*SDI, "resume", run_id, "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert resumed.returncode == 0, resumed.stderr
    result = json.loads(resumed.stdout)
    # flattening changed the shape: a person approves it, even in an --approve-all run
    assert result["status"] == "paused" and result["waiting_for"]["kind"] == "recovery_review"
    approved = subprocess.run(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert approved.returncode == 0, approved.stderr
    result = json.loads(approved.stdout)
    assert result["status"] == "success" and result["tried"][0] == "flatten"
    log = subprocess.run(
        [*SDI, "log", run_id, "--db", str(db), "--json"], capture_output=True, text=True
    )
    messages = json.loads(log.stdout)["messages"]
    types = [m["type"] for m in messages]
    # one failed execution before the crash, one after the repair: EXECUTE did not run again
    # on resume (checkpoints are written before the next node starts), and nothing is merged
    assert types.count("execution_started") == 2 and types.count("execution") == 2
    assert "route" in types
    assert [m["seq"] for m in messages] == list(range(1, len(messages) + 1))


def test_resume_unknown_run_is_bad_input(tmp_path):
    proc = subprocess.run(
        [*SDI, "resume", "deadbeef0000", "--db", str(tmp_path / "x.sqlite")],
        capture_output=True, text=True, timeout=120,
    )  # fmt: skip
    assert proc.returncode == 2 and "deadbeef0000" in proc.stderr


def test_kill_during_execution_resumes_from_what_is_built(tmp_path):
    db = tmp_path / "runs.sqlite"
    env = {**os.environ, "SDI_CRASH_AFTER_STEPS": "1"}  # dies right after the first part is set
    crashed = subprocess.run(
        [*SDI, "run", "a 3-cube tower at x = 0.4", "--approve-all", "--db", str(db),
         "--arms", "irb120", "--json"],
        capture_output=True, text=True, timeout=600, env=env,
    )  # fmt: skip
    assert crashed.returncode == 137
    bus = MessageBus(db)
    (run_id,) = bus.runs()
    bus.close()
    before = history(db, run_id)
    assert before.count("step_done") == 1 and "execution" not in before
    # resume (no answer): it must not move; it shows what is built and asks again
    asked = subprocess.run(
        [*SDI, "resume", run_id, "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert asked.returncode == 0, asked.stderr
    waiting = json.loads(asked.stdout)["waiting_for"]
    assert waiting["kind"] == "resume_execution"
    built = waiting["as_built"]
    assert [p["part_id"] for p in built["placed"]] == ["c1"] and built["steps_completed"] == 1
    assert built["record_hash"] == waiting["record_hash"]
    assert "execution_interrupted" in history(db, run_id)
    assert history(db, run_id).count("execution_started") == 1  # nothing moved yet
    done = subprocess.run(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["status"] == "success" and result["execution"]["v_traj"] == "pass"
    assert result["execution"]["completed_steps"] == 3
    assert result["execution"]["record_hash"] == waiting["record_hash"] == result["approved_hash"]
    log = subprocess.run(
        [*SDI, "log", run_id, "--db", str(db), "--json"], capture_output=True, text=True
    )
    messages = json.loads(log.stdout)["messages"]
    types = [m["type"] for m in messages]
    assert types.count("record") == 1  # motion was planned once, before the first approval
    assert types.count("step_done") == 3  # c1 before the kill, c2 and c3 after: none twice
    parts = [m["payload"]["part_id"] for m in messages if m["type"] == "step_done"]
    assert sorted(parts) == ["c1", "c2", "c3"]
    assert [m["seq"] for m in messages] == list(range(1, len(messages) + 1))
    assert before == types[: len(before)]  # nothing from before the kill was lost


def test_kill_9_from_outside_during_execution_loses_and_repeats_nothing(tmp_path):
    db = tmp_path / "runs.sqlite"
    proc = subprocess.Popen(
        [*SDI, "run", "a 4-cube tower at x = 0.4", "--approve-all", "--db", str(db),
         "--arms", "irb120", "--json"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
    )  # fmt: skip
    run_id = None
    while proc.poll() is None:  # watch the real event stream; kill once a part is down
        if db.exists():
            bus = MessageBus(db)
            runs = bus.runs()
            if runs and "step_done" in [m.type for m in bus.history(runs[0])]:
                run_id = runs[0]
                proc.send_signal(signal.SIGKILL)
            bus.close()
        time.sleep(0.02)
    proc.wait()
    assert proc.returncode == -signal.SIGKILL and run_id is not None
    before = history(db, run_id)
    built = before.count("step_done")
    assert 1 <= built < 4 and "execution" not in before
    asked = subprocess.run(
        [*SDI, "resume", run_id, "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    waiting = json.loads(asked.stdout)["waiting_for"]
    assert waiting["kind"] == "resume_execution" and len(waiting["as_built"]["placed"]) == built
    done = subprocess.run(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    result = json.loads(done.stdout)
    assert result["status"] == "success" and result["execution"]["completed_steps"] == 4
    assert result["execution"]["record_hash"] == waiting["record_hash"]
    bus = MessageBus(db)
    messages = bus.history(run_id)
    bus.close()
    parts = [m.payload["part_id"] for m in messages if m.type == "step_done"]
    assert sorted(parts) == ["c1", "c2", "c3", "c4"]  # every part set down exactly once
    assert [m.type for m in messages].count("record") == 1  # planned once
    assert [m.seq for m in messages] == list(range(1, len(messages) + 1))
