"""Operator answers (flags and typed answers) and the audit trail that records them."""

from __future__ import annotations

import json
import os
import pty
import re
import select
import subprocess
import sys
import time

import pytest

from sdi.cli import _answer
from sdi.orchestrator import MessageBus, Orchestrator

SDI = [sys.executable, "-m", "sdi.cli"]


def sdi(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize(
    ("typed", "kind", "action"),
    [
        ("yes", "pre_execute", "approve"), ("Y", "pre_execute", "approve"),
        ("a", "resume_execution", "approve"), ("approve", "design_review", "approve"),
        ("no", "pre_execute", "reject"), ("r", "design_review", "reject"),
        ("retry", "failure_report", "retry"), ("x", "failure_report", "abort"),
        ("e edits.json", "design_review", "edit"), ("x", "design_review", "abort"),
        ("abort", "recovery_review", "abort"), ("r make it 4 high", "design_review", "reject"),
    ],
)  # fmt: skip
def test_typed_answers_mean_what_they_say(typed, kind, action):
    assert _answer(typed, kind)["action"] == action


def test_a_typed_reason_goes_with_the_rejection_of_a_design():
    assert _answer("r make it 4 high", "design_review") == {
        "action": "reject", "reason": "make it 4 high"
    }  # fmt: skip
    assert _answer("r", "design_review") == {"action": "reject"}  # ends the run, as before
    assert _answer("no thanks", "pre_execute") == {"action": "reject"}  # no replan there


def test_reject_with_a_reason_replans_from_the_command_line(tmp_path):
    db = tmp_path / "runs.sqlite"
    status = json.loads(sdi("run", "a row of 3 cubes", "--json", "--db", str(db)).stdout)
    run_id = status["run_id"]
    proc = sdi("resume", run_id, "--reason", "move it to the back", "--db", str(db))
    assert proc.returncode == 2 and "--reason goes with --reject" in proc.stderr
    proc = sdi("resume", run_id, "--reject", "--reason", "move it to the back", "--json",
               "--db", str(db))  # fmt: skip
    after = json.loads(proc.stdout)
    assert after["status"] == "paused" and after["waiting_for"]["kind"] == "design_review"
    assert "replanned after your rejection" in after["waiting_for"]["replanned"]
    xs = [p["position"][0] for p in after["waiting_for"]["layout"]["objects"]]
    assert min(xs) > max(p["position"][0] for p in status["waiting_for"]["layout"]["objects"])
    proc = sdi("resume", run_id, "--reject", "--json", "--db", str(db))
    assert json.loads(proc.stdout)["status"] == "rejected"  # no reason: the run ends


@pytest.mark.parametrize(
    ("typed", "kind"), [("maybe", "pre_execute"), ("e", "design_review"), ("", "pre_execute"),
                        ("e x.json", "pre_execute"), ("yes", "failure_report")]
)  # fmt: skip
def test_anything_else_is_asked_again(typed, kind):
    assert _answer(typed, kind) is None


def test_conflicting_answers_are_refused(tmp_path):
    for flags in (["--approve", "--reject"], ["--approve-all", "--reject"],
                  ["--approve", "--edit", "x.json"]):  # fmt: skip
        proc = sdi("resume", "abc", *flags, "--db", str(tmp_path / "r.sqlite"))
        assert proc.returncode == 2 and "give one answer" in proc.stderr, proc.stderr


def test_approve_answers_only_the_pending_review(tmp_path):
    db = tmp_path / "runs.sqlite"
    status = json.loads(sdi("run", "a 2-cube tower at x = 0.4", "--arms", "irb120", "--json",
                            "--db", str(db)).stdout)  # fmt: skip
    assert status["waiting_for"]["kind"] == "design_review"
    proc = sdi("resume", status["run_id"], "--approve", "--json", "--db", str(db))
    after = json.loads(proc.stdout)
    assert after["status"] == "paused" and after["waiting_for"]["kind"] == "pre_execute"
    assert after.get("execution") is None


def test_a_refused_edit_says_why(tmp_path):
    db = tmp_path / "runs.sqlite"
    status = json.loads(sdi("run", "a 2-cube tower at x = 0.4", "--arms", "irb120", "--json",
                            "--db", str(db)).stdout)  # fmt: skip
    edits = tmp_path / "edits.json"
    edits.write_text(json.dumps([{"op": "move", "id": "nope", "position": [0.4, 0.3, 0.025]}]))
    proc = sdi("resume", status["run_id"], "--edit", str(edits), "--db", str(db))
    assert proc.returncode == 2
    assert "edit refused" in proc.stderr and "nope" in proc.stderr
    again = json.loads(sdi("resume", status["run_id"], "--json", "--db", str(db)).stdout)
    assert again["waiting_for"]["kind"] == "design_review"  # still waiting, layout unchanged
    assert again["waiting_for"]["layout"] == status["waiting_for"]["layout"]


def test_yes_at_the_prompt_executes(tmp_path):
    db = tmp_path / "runs.sqlite"
    master, slave = pty.openpty()
    proc = subprocess.Popen(
        [*SDI, "run", "a 2-cube tower at x = 0.4", "--db", str(db), "--arms", "irb120"],
        stdin=slave, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
    )  # fmt: skip
    os.close(slave)
    seen = b""
    for prompt in (b"Design review", b"Execute this record"):
        limit = time.monotonic() + 300  # a guard against hanging, not a measurement
        while prompt not in seen and time.monotonic() < limit:
            ready, _, _ = select.select([proc.stdout, proc.stderr], [], [], 1.0)
            for stream in ready:
                seen += os.read(stream.fileno(), 65536)
        assert prompt in seen, seen[-2000:]
        os.write(master, b"yes\n")
    proc.communicate(timeout=600)
    os.close(master)
    assert proc.returncode == 0
    run_id = re.search(rb"run ([0-9a-f]{12})", seen).group(1).decode()
    bus = MessageBus(db)
    confirm = [m.payload for m in bus.history(run_id) if m.type == "confirm"]
    bus.close()
    assert confirm[0]["action"] == "approve" and len(confirm[0]["record_hash"]) == 64


def test_identical_events_are_all_kept(tmp_path):
    orch = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    s = orch.start("a 2-cube tower at x = 0.4")
    # an edit that changes nothing: the same layout is verified again, with the same result
    s = orch.resume(s.run_id, {"action": "edit", "edits": [{"op": "translate", "id": "c1",
                                                           "by": [0.0, 0.0, 0.0]}]})  # fmt: skip
    history = orch.bus.history(s.run_id)
    verifications = [m.payload for m in history if m.type == "verification"]
    assert len(verifications) == 2 and verifications[0] == verifications[1]
    assert [m.seq for m in history] == list(range(1, len(history) + 1))
    orch.close()


def test_concurrent_writers_get_contiguous_numbers(tmp_path):
    db = tmp_path / "runs.sqlite"
    MessageBus(db).close()
    code = (
        "import sys; from sdi.orchestrator import MessageBus\n"
        "bus = MessageBus(sys.argv[1])\n"
        "for k in range(150): bus.send('r', sys.argv[2], 'x', 'tick', {'k': k})\n"
    )
    procs = [subprocess.Popen([sys.executable, "-c", code, str(db), f"w{n}"]) for n in range(3)]
    for p in procs:
        assert p.wait(timeout=300) == 0
    bus = MessageBus(db)
    history = bus.history("r")
    bus.close()
    assert [m.seq for m in history] == list(range(1, 451))
    for n in range(3):  # each writer's events, all there, in its own order
        mine = [m.payload["k"] for m in history if m.sender == f"w{n}"]
        assert mine == list(range(150))


def test_the_confirmation_shows_the_record_and_what_is_built(capsys):
    from sdi.cli import _show_record

    _show_record(
        {
            "record_hash": "ab" * 32,
            "planning": {"makespan_s": 12.5, "steps": 3, "parallel": False, "notes": [],
                         "parts_per_robot": {"irb120": ["c1", "c2", "c3"]}},
            "as_built": {"placed": [{"part_id": "c1", "step": 0, "robot": "irb120",
                                     "pose": [0.4, 0.3, 0.025, 1, 0, 0, 0]}]},
        }
    )  # fmt: skip
    text = " ".join(capsys.readouterr().out.split())
    assert "ab" * 32 in text and "makespan 12.5 s" in text and "irb120: 3 steps: c1 c2 c3" in text
    assert (
        "interrupted after 1 of 3 steps" in text
        and "c1 (step 1, irb120) at (0.4, 0.3, 0.025)" in text
    )


def test_a_failure_report_is_not_approved_blindly(tmp_path):
    from scripted_model import ScriptedChat, cube

    model = ScriptedChat(lambda msgs, opt: {"objects": [cube("a", 0.4, 0.3, 0.3)]})  # floats
    db = tmp_path / "runs.sqlite"
    orch = Orchestrator(db=db, model=model)
    s = orch.start("zorblax", method="LGOrch", backend="rules")
    orch.close()
    assert s.waiting_for["kind"] == "failure_report"
    proc = sdi("resume", s.run_id, "--approve", "--db", str(db))
    assert proc.returncode == 2 and "failure report" in proc.stderr
    proc = sdi("resume", s.run_id, "--reject", "--json", "--db", str(db))
    assert json.loads(proc.stdout)["status"] == "failure"  # aborted, by a person's answer


def test_a_failure_report_can_be_retried_from_the_command_line(tmp_path):
    from scripted_model import ScriptedChat, cube

    model = ScriptedChat(lambda msgs, opt: {"objects": [cube("a", 0.4, 0.3, 0.3)]})  # floats
    db = tmp_path / "runs.sqlite"
    orch = Orchestrator(db=db, model=model)
    s = orch.start("zorblax", method="LGOrch", backend="rules")
    orch.close()
    assert s.waiting_for["kind"] == "failure_report"
    proc = sdi("resume", s.run_id, "--approve", "--db", str(db))
    assert proc.returncode == 2 and "--retry" in proc.stderr
    proc = sdi("resume", s.run_id, "--retry", "--json", "--db", str(db))
    assert proc.returncode != 2, proc.stderr
    bus = MessageBus(db)
    answers = [m.payload for m in bus.history(s.run_id) if m.type == "failure_decision"]
    kinds = [m.type for m in bus.history(s.run_id)]
    bus.close()
    assert answers[-1]["action"] == "retry"
    assert kinds[kinds.index("failure_decision") + 1 :].count("error") == 1  # planned again


def test_a_refused_edit_is_answered_with_choose(tmp_path):
    db = tmp_path / "runs.sqlite"
    status = json.loads(sdi("run", "a 3-cube tower at x = 0.45", "--arms", "irb120", "--json",
                            "--db", str(db)).stdout)  # fmt: skip
    edits = tmp_path / "edits.json"
    edits.write_text(json.dumps([{"op": "move", "id": "c3", "position": [1.0, 0.3, 0.125]}]))
    run_id = status["run_id"]
    after = json.loads(
        sdi("resume", run_id, "--edit", str(edits), "--json", "--db", str(db)).stdout
    )
    assert after["waiting_for"]["kind"] == "edit_review" and after["waiting_for"]["repair"]
    proc = sdi("resume", run_id, "--approve", "--db", str(db))
    assert proc.returncode == 2 and "--choose" in proc.stderr  # not approved blindly
    proc = sdi("resume", run_id, "--choose", "repair", "--json", "--db", str(db))
    done = json.loads(proc.stdout)
    assert done["waiting_for"]["kind"] == "design_review"
    assert done["edit_outcome"]["choice"] == "repair" and done["edit_outcome"]["changes"]
    assert any("your edit → repair" in n for n in done["notes"])


@pytest.mark.parametrize(
    ("typed", "action"), [("f", "repair"), ("undo", "undo"), ("p", "replan"), ("r", "reject")]
)
def test_typed_answers_to_a_refused_edit(typed, action):
    assert _answer(typed, "edit_review")["action"] == action
    assert _answer("yes", "edit_review") is None  # an invalid layout is not approved


def test_a_review_says_what_changed():
    from sdi.cli import _review_lines

    lines = _review_lines({
        "kind": "edit_review",
        "violations": [{"constraint": "workspace", "message": "c3 leaves the workspace",
                        "hint": "move c3 to x=0.775"}],
        "repair": {"summary": "c3 moved by (-0.225, 0, -0.1) m to (0.775, 0.3, 0.025)"},
        "nearest_order": ["c1", "c2", "c3"],
    })  # fmt: skip
    text = "\n".join(lines)
    assert "workspace: c3 leaves the workspace — move c3 to x=0.775" in text
    assert "repair: c3 moved by (-0.225, 0, -0.1) m" in text and "c1 → c2 → c3" in text
    shown = _review_lines({"kind": "recovery_review", "recovery": {"summary": "flatten: x → y"}})
    assert shown == ["recovery: flatten: x → y"]


def test_a_failure_report_is_answered_with_a_recovery_skill(tmp_path):
    db = tmp_path / "runs.sqlite"
    status = json.loads(sdi("run", "a tower of 3 cubes", "--fault", "joint_drift", "--approve",
                            "--json", "--db", str(db)).stdout)  # fmt: skip
    run_id = status["run_id"]
    status = json.loads(sdi("resume", run_id, "--approve", "--json", "--db", str(db)).stdout)
    assert status["waiting_for"]["kind"] == "failure_report"  # δ breached ε
    assert [k["name"] for k in status["waiting_for"]["skills"]] == [
        "shift",
        "flatten",
        "spread",
        "modify",
    ]
    proc = sdi("resume", run_id, "--recover", "teleport", "--json", "--db", str(db))
    assert proc.returncode == 2  # not offered: the report waits again, saying why
    assert (
        "choose one of shift, flatten, spread, modify"
        in json.loads(proc.stdout)["waiting_for"]["refused"]
    )
    proc = sdi("resume", run_id, "--recover", "flatten", "--json", "--db", str(db))
    after = json.loads(proc.stdout)
    assert after["waiting_for"]["kind"] == "recovery_review"
    assert after["waiting_for"]["recovery"]["action"] == "flatten"


@pytest.mark.parametrize(
    ("typed", "skill"), [("s flatten", "flatten"), ("recover modify", "modify")]
)
def test_typed_recovery_skills_at_a_failure_report(typed, skill):
    assert _answer(typed, "failure_report") == {"action": "recover", "skill": skill}
    assert _answer("s", "failure_report") is None  # which skill?
