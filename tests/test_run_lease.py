"""One process at a time per run: leases in the real SQLite file, contested by real processes.

No test waits on the clock: a process is held inside EXECUTE by a gate file
(`SDI_HOLD_AT=execute`, `SDI_HOLD_FILE`) and released when the test has seen what it needs.
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
from pathlib import Path

import pytest

from sdi.orchestrator import MessageBus, Orchestrator, RunBusyError, RunLease

SDI = [sys.executable, "-m", "sdi.cli"]


def wait_for(path: Path, proc: subprocess.Popen[str]) -> None:
    """Until `path` exists (the held process reached its gate) — or the process died."""
    import time

    while not path.exists():
        if proc.poll() is not None:
            raise AssertionError(f"process ended early: {proc.communicate()}")
        time.sleep(0.05)


def paused_at_confirmation(db: Path) -> str:
    orch = Orchestrator(db=db, arms=["irb120"])
    try:
        s = orch.start("a 2-cube tower at x = 0.4")
        s = orch.resume(s.run_id, {"action": "approve"})
    finally:
        orch.close()
    assert s.status == "paused" and s.waiting_for["kind"] == "pre_execute"
    return s.run_id


def test_a_lease_is_taken_once(tmp_path):
    db = tmp_path / "runs.sqlite"
    Orchestrator(db=db).close()
    first = RunLease(db, "r1")
    first.acquire()
    try:
        second = RunLease(db, "r1")
        with pytest.raises(RunBusyError, match=rf"pid {os.getpid()} on {socket.gethostname()}"):
            second.acquire()
        RunLease(db, "r2").acquire()  # other runs are free
    finally:
        first.release()
    with RunLease(db, "r1"):  # released on exit: free again
        pass


def test_a_dead_owner_or_an_old_heartbeat_frees_the_lease(tmp_path):
    db = tmp_path / "runs.sqlite"
    Orchestrator(db=db).close()
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    lease = RunLease(db, "r1")
    lease.acquire()
    lease._stop.set()  # no more heartbeats, and the row claims the dead process
    import sqlite3

    conn = sqlite3.connect(db)
    conn.execute("UPDATE leases SET pid = ?", (dead.pid,))
    conn.commit()
    with RunLease(db, "r1"):  # the owner is gone: taken over at once
        pass
    other = RunLease(db, "r1")
    other.acquire()
    other._stop.set()
    conn.execute("UPDATE leases SET host = 'elsewhere', heartbeat = heartbeat - 3600")
    conn.commit()
    with RunLease(db, "r1"):  # another host, silent for an hour: stale
        pass
    conn.execute("INSERT INTO leases VALUES ('r1', 't', 1, 'elsewhere', 0, 1e12)")
    conn.commit()
    with pytest.raises(RunBusyError, match="pid 1 on elsewhere"):
        RunLease(db, "r1").acquire()  # another host, heartbeat fresh: busy
    conn.close()


def test_two_concurrent_resumes_execute_once(tmp_path):
    db = tmp_path / "runs.sqlite"
    run_id = paused_at_confirmation(db)
    gate = tmp_path / "gate"
    env = {**os.environ, "SDI_HOLD_AT": "execute", "SDI_HOLD_FILE": str(gate)}
    first = subprocess.Popen(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )  # fmt: skip
    wait_for(Path(f"{gate}.ready"), first)  # the first is inside EXECUTE, holding the run
    second = subprocess.run(
        [*SDI, "resume", run_id, "--approve", "--db", str(db)],
        capture_output=True, text=True, timeout=300, env=env,
    )  # fmt: skip
    assert second.returncode == 1, second.stderr
    message = " ".join(second.stderr.split())
    assert f"run {run_id} is being executed by pid {first.pid} on {socket.gethostname()}" in message
    gate.touch()
    out, err = first.communicate(timeout=600)
    assert first.returncode == 0, err
    assert json.loads(out)["status"] == "success"
    bus = MessageBus(db)
    types = [m.type for m in bus.history(run_id)]
    bus.close()
    assert types.count("execution_started") == 1 and types.count("execution") == 1


def test_an_operator_at_a_prompt_owns_the_run(tmp_path):
    import pty
    import select
    import time

    db = tmp_path / "runs.sqlite"
    master, slave = pty.openpty()
    proc = subprocess.Popen(
        [*SDI, "run", "a 2-cube tower at x = 0.4", "--db", str(db), "--arms", "irb120"],
        stdin=slave, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )  # fmt: skip
    os.close(slave)
    seen = b""
    limit = time.monotonic() + 300  # a guard against hanging, not a measurement
    while b"Design review" not in seen and time.monotonic() < limit:
        ready, _, _ = select.select([proc.stdout, proc.stderr], [], [], 1.0)
        for stream in ready:
            seen += os.read(stream.fileno(), 65536)
    assert b"Design review" in seen, seen[-2000:]
    import re

    run_id = re.search(rb"run ([0-9a-f]{12})", seen).group(1).decode()
    other = subprocess.run(
        [*SDI, "resume", run_id, "--approve-all", "--db", str(db)],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert other.returncode == 1 and f"pid {proc.pid}" in " ".join(other.stderr.split())
    proc.send_signal(signal.SIGKILL)
    proc.wait(timeout=30)
    proc.stdout.close()
    proc.stderr.close()
    os.close(master)
    # its owner is dead: the run is free at once, and nothing had moved
    done = subprocess.run(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout)["waiting_for"]["kind"] == "pre_execute"


def test_log_follow_streams_a_run_live_until_it_stops(tmp_path):
    db = tmp_path / "runs.sqlite"
    run_id = paused_at_confirmation(db)
    gate = tmp_path / "gate"
    env = {**os.environ, "SDI_HOLD_AT": "execute", "SDI_HOLD_FILE": str(gate)}
    runner = subprocess.Popen(
        [*SDI, "resume", run_id, "--approve", "--db", str(db), "--json"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
    )  # fmt: skip
    wait_for(Path(f"{gate}.ready"), runner)
    follower = subprocess.Popen(
        [*SDI, "log", run_id, "--follow", "--json", "--db", str(db)],
        stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
    )  # fmt: skip
    first = json.loads(follower.stdout.readline())  # the stream is already flowing
    assert first["seq"] == 1 and first["type"] == "command"
    gate.touch()  # let execution go on while the follower watches
    runner.communicate(timeout=600)
    rest = follower.stdout.read()  # to its end: the follower stops by itself with the run
    follower.stdout.close()
    assert follower.wait(timeout=120) == 0
    events = [first, *(json.loads(line) for line in rest.splitlines())]
    assert [e["seq"] for e in events] == list(range(1, len(events) + 1))
    kinds = [e["type"] for e in events]
    assert kinds[-1] == "stopped" and events[-1]["payload"]["status"] == "success"
    assert kinds.count("step_done") == 2 and "execution" in kinds
    samples = [e["payload"] for e in events if e["type"] == "samples"]  # Q_exec and δ, live
    assert samples and all(s["delta_max_rad"] < 0.05 for s in samples)
    assert len(samples[0]["q"]["irb120"][0]) == 1 + 6  # t and six joints
