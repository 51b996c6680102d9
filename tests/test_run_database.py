"""The run database as a file someone else may have written: plain data only, private, checked.

Crafted files are real SQLite files that a real `sdi resume` process opens; the proof that
nothing ran is a marker file the payload would have created.
"""

from __future__ import annotations

import pickle
import sqlite3
import stat
import subprocess
import sys
from pathlib import Path

import ormsgpack
import pytest

from sdi.orchestrator import Orchestrator, PlainSerializer, UnsafeCheckpointError

SDI = [sys.executable, "-m", "sdi.cli"]


def sdi(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=300)


def paused_run(db: Path) -> str:
    orch = Orchestrator(db=db, arms=["irb120"])
    try:
        status = orch.start("a 2-cube tower at x = 0.4")
    finally:
        orch.close()
    assert status.status == "paused"
    return status.run_id


def constructor(marker: Path) -> ormsgpack.Ext:
    """What LangGraph's default serializer revives as `os.system("touch MARKER")`."""
    return ormsgpack.Ext(1, ormsgpack.packb(["os", "system", [f"touch {marker}"]]))


def craft_checkpoints(db: Path, marker: Path) -> None:
    conn = sqlite3.connect(db)
    rows = conn.execute("SELECT rowid, checkpoint FROM checkpoints").fetchall()
    for rowid, blob in rows:
        value = ormsgpack.unpackb(blob, option=ormsgpack.OPT_NON_STR_KEYS)
        value["channel_values"]["command"] = constructor(marker)
        conn.execute(
            "UPDATE checkpoints SET checkpoint = ? WHERE rowid = ?",
            (ormsgpack.packb(value), rowid),
        )
    conn.commit()
    conn.close()


def test_a_crafted_checkpoint_runs_nothing_and_names_the_file(tmp_path):
    db = tmp_path / "crafted.db"
    marker = tmp_path / "pwned"
    run_id = paused_run(db)
    craft_checkpoints(db, marker)
    for args in (["resume", run_id, "--approve"], ["resume", run_id]):
        proc = sdi(*args, "--db", str(db))
        assert proc.returncode == 2, proc.stderr
        assert str(db) in proc.stderr and "os.system" in proc.stderr
        assert "Traceback" not in proc.stderr
        assert not marker.exists()
    # the control: LangGraph's default serializer does run it (so the file is a real attack)
    from langgraph.checkpoint.serde.jsonplus import JsonPlusSerializer

    (blob,) = sqlite3.connect(db).execute("SELECT checkpoint FROM checkpoints LIMIT 1").fetchone()
    JsonPlusSerializer().loads_typed(("msgpack", blob))
    assert marker.exists()


def test_a_crafted_pending_write_runs_nothing(tmp_path):
    db = tmp_path / "crafted.db"
    marker = tmp_path / "pwned"
    run_id = paused_run(db)
    conn = sqlite3.connect(db)
    n = conn.execute(
        "UPDATE writes SET type = 'msgpack', value = ?",
        (ormsgpack.packb({"value": constructor(marker)}),),
    ).rowcount
    conn.commit()
    conn.close()
    assert n > 0  # the pending design review is a write
    proc = sdi("resume", run_id, "--approve", "--db", str(db))
    assert proc.returncode == 2 and str(db) in proc.stderr, proc.stderr
    assert not marker.exists()


@pytest.mark.parametrize(
    "value",
    [
        ("pickle", pickle.dumps(print)),
        ("json", b'{"lc": 2, "type": "constructor", "id": ["os", "system"], "args": ["true"]}'),
        ("msgpack", ormsgpack.packb(ormsgpack.Ext(3, ormsgpack.packb(["os", "x", "y", "z"])))),
        ("msgpack", ormsgpack.packb(ormsgpack.Ext(6, b"\x00"))),  # a numpy buffer
        ("msgpack", b"\xc1"),
    ],
)
def test_the_serializer_reads_plain_data_only(value):
    with pytest.raises(UnsafeCheckpointError):
        PlainSerializer().loads_typed(value)


def test_the_serializer_round_trips_what_a_run_writes():
    from langgraph.types import Interrupt

    serde = PlainSerializer()
    value = {"a": [1, 2.5, "x", None, {"b": True}], "i": Interrupt(value={"kind": "design_review"})}
    assert serde.loads_typed(serde.dumps_typed(value)) == value


def test_the_database_is_private(tmp_path):
    db = tmp_path / "new" / "deeper" / "runs.sqlite"
    paused_run(db)
    assert stat.S_IMODE(db.stat().st_mode) == 0o600
    assert stat.S_IMODE(db.parent.stat().st_mode) == 0o700
    assert stat.S_IMODE((tmp_path / "new").stat().st_mode) == 0o700
    for extra in db.parent.glob("runs.sqlite-*"):  # WAL and shared-memory files
        assert not stat.S_IMODE(extra.stat().st_mode) & 0o077, extra


def test_not_a_database_is_bad_input(tmp_path):
    junk = tmp_path / "junk.db"
    junk.write_bytes(b"this is not sqlite" * 100)
    for args in (["resume", "abc"], ["log", "abc"], ["run", "a 2-cube tower at x = 0.4"]):
        proc = sdi(*args, "--db", str(junk))
        assert proc.returncode == 2, (args, proc.stderr)
        assert str(junk) in proc.stderr and "Traceback" not in proc.stderr


def test_log_and_resume_do_not_create_a_database(tmp_path):
    missing = tmp_path / "none.sqlite"
    for args in (["log", "abc"], ["resume", "abc"]):
        proc = sdi(*args, "--db", str(missing))
        assert proc.returncode == 2 and "abc" in proc.stderr, proc.stderr
    assert not missing.exists()


@pytest.mark.parametrize(
    ("values", "said"),
    [
        ({"faults": ["meteor"]}, "fault"),
        ({"method": "Magic"}, "method"),
        ({"cell": {"workspace": {"x_min": "far"}}}, "cell"),
        ({"cell_hash": "0" * 64}, "hash"),
        ({"arms": "irb120"}, "arms"),
    ],
)
def test_plain_but_wrong_state_is_refused_naming_the_file(tmp_path, values, said):
    db = tmp_path / "crafted.db"
    run_id = paused_run(db)
    orch = Orchestrator(db=db)
    orch.graph.update_state({"configurable": {"thread_id": run_id}}, values)
    orch.close()
    proc = sdi("resume", run_id, "--approve", "--db", str(db))
    assert proc.returncode == 2 and str(db) in proc.stderr and said in proc.stderr, proc.stderr
    assert "Traceback" not in proc.stderr
