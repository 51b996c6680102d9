"""The gate as a type: one run verifies each layout once, then the `VerifiedJob` flows on.

Task generation, motion planning, the commissioning record, the driver and the exporters take
the job and trust it (an identity check, never a second run of the verifier). Counted here by
wrapping the verifier everywhere it was imported.
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path

import pytest

import sdi.inspector.verifier as verifier
from sdi.orchestrator import Orchestrator


@pytest.fixture
def calls(monkeypatch):
    # every stage imported before counting
    import sdi.commission
    import sdi.execute.sim
    import sdi.export  # noqa: F401

    original = verifier.verify
    counted: Counter[str] = Counter()

    def counting(*args, **kwargs):
        frame = sys._getframe(1)
        counted[f"{Path(frame.f_code.co_filename).stem}.{frame.f_code.co_name}"] += 1
        return original(*args, **kwargs)

    for module in list(sys.modules.values()):
        if getattr(module, "verify", None) is original:
            monkeypatch.setattr(module, "verify", counting)
    return counted


def test_one_run_verifies_the_layout_once(tmp_path, calls):
    """`sdi run "a 3-cube tower at x = 0.4" --approve-all` (sim driver, both arms): one
    verification, in `VerifiedJob.inspect` (the Designer's gate; INSPECT, PRE_EXECUTE and
    EXECUTE take that job). Before the job flowed it was six: the Designer, INSPECT,
    `commission`, task generation, the record's rebuild and the driver's re-check."""
    import json

    from typer.testing import CliRunner

    from sdi.cli import app

    db = tmp_path / "runs.sqlite"
    command = ["run", "a 3-cube tower at x = 0.4", "--approve-all", "--db", str(db), "--json"]
    result = CliRunner().invoke(app, command)
    assert result.exit_code == 0, result.output
    out = json.loads(result.output[result.output.index("{") :])
    assert out["status"] == "success" and out["execution"]["v_traj"] == "pass"
    assert dict(calls) == {"job.inspect": 1}


def test_a_human_edit_is_verified_once_more(tmp_path, calls):
    """Each human edit is a new layout: one more verification (INSPECT), no more."""
    orch = Orchestrator(db=tmp_path / "runs.sqlite", arms=["irb120"])
    try:
        s = orch.start("a 2-cube tower at x = 0.4")
        edit = {"op": "move", "id": "c2", "position": [0.405, 0.3, 0.075]}
        s = orch.resume(s.run_id, {"action": "edit", "edits": [edit]})
        assert s.waiting_for["kind"] == "design_review"
        assert dict(calls) == {"job.inspect": 2}
        s = orch.resume(s.run_id, {"action": "approve"})
        approval = {"action": "approve", "record_hash": s.waiting_for["record_hash"]}
        s = orch.resume(s.run_id, approval)
    finally:
        orch.close()
    assert s.status == "success"
    assert dict(calls) == {"job.inspect": 2}
