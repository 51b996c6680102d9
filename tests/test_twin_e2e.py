"""The digital twin end to end: a real server, real headless Chromium, a real run.

Type a command → the parts appear; drag one into another → a collision on both; undo → it
clears; drag one out of the workspace and apply the hint; accept; the record's preview plays
and the slider scrubs; approve; execution finishes with V_traj = pass and every part green;
reload → the run is still there and replays from its events: the design versions, the edit,
the approval (record hash, who), the execution with δ. A rejection with a reason replans. A
δ breach stops execution and raises the failure report with the orchestrator's options (a
recovery skill, retry, a human edit of the failed layout, abort). A screenshot of each step is
saved under the test's output folder ($SDI_TWIN_SCREENSHOTS, else pytest's tmp_path).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from twin_harness import browser, drag, need_browser, page_errors, served, shot, state, top, wait

pytestmark = pytest.mark.slow


@pytest.fixture
def shots(tmp_path: Path) -> Path:
    folder = Path(os.environ.get("SDI_TWIN_SCREENSHOTS") or tmp_path / "screens")
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def test_command_review_preview_execute_replay(tmp_path: Path, shots: Path) -> None:
    need_browser()
    with served(tmp_path / "runs.sqlite") as (url, twin), browser() as b:
        page = b.new_page(viewport={"width": 1280, "height": 800})
        errors = page_errors(page)
        page.goto(url)
        wait(page, "T.scene && T.robots")

        # command intake → the parts appear at design review, with the reading
        page.fill("#command", "a row of 3 cubes")
        page.click("#plan")
        wait(page, "T.phase === 'design_review' && T.partIds.length === 3")
        reading = page.inner_text("#reading")
        assert "row" in reading
        shot(page, shots / "1-review.png")
        parts = state(page, "T.view.review.parts")
        pos = {p["id"]: p["position"] for p in parts}
        assert state(page, "T.view.review.passed") is True

        # drag the end cube onto the middle one: a collision on both
        drag(page, pos["c3"], pos["c2"])
        wait(page, "T.view.review.violations.some(v => v.constraint === 'collision')")
        v = state(page, "T.view.review.violations.find(v => v.constraint === 'collision')")
        assert sorted(v["objects"]) == ["c2", "c3"]
        assert state(page, "T.partStates.c2") == "violating"
        assert state(page, "T.partStates.c3") == "violating"
        assert "collision" in state(page, "T.labels.c2") and "collision" in state(
            page, "T.labels.c3"
        )
        assert state(page, "T.labels.c1") is None  # no label on a part that breaks nothing
        assert page.is_disabled("#accept")
        shot(page, shots / "2-collision.png")

        # undo → clears, the cube is back where the Designer put it
        page.click("#undo")
        wait(page, "T.view.review.violations.length === 0")
        assert state(page, "T.view.review.parts.find(p => p.id === 'c3').position") == pos["c3"]

        # drag it out of the workspace; the violation's hint moves it back inside
        outside = [0.1, pos["c3"][1], pos["c3"][2]]
        drag(page, pos["c3"], outside)
        wait(page, "T.view.review.violations.some(v => v.constraint === 'workspace')")
        shot(page, shots / "3-workspace.png")
        page.click("#violations button.hint")
        wait(page, "T.view.review.violations.length === 0 && T.view.review.edits.length === 2")
        moved = state(page, "T.view.review.parts.find(p => p.id === 'c3').position")
        assert moved[0] >= 0.2 + 0.025 - 1e-9  # inside W (x ≥ 0.20) with its half width
        edited = state(page, "T.view.review.layout_hash")

        # accept → the run applies the same edits, plans motion, waits at touch point 2
        page.click("#accept")
        wait(page, "T.phase === 'pre_execute' && T.timeline")
        assert state(page, "T.view.review") is None
        steps = state(page, "T.timeline.steps.length")
        assert steps == 3
        # what is previewed is the layout the operator accepted
        record = twin._orch.record(state(page, "T.runId"))
        from sdi.execute.record import layout_hash
        from sdi.model.layout import Layout

        assert layout_hash(Layout.model_validate(record.body["layout"])) == edited

        # the preview plays, and the slider scrubs: parts appear as they are released
        page.click("#play")
        wait(page, "T.clock > 1.0")
        page.click("#play")  # pause
        first_release = state(page, "Math.min(...T.timeline.steps.map(s => s.release))")
        page.locator("#slider").fill(str(first_release - 0.5))
        wait(page, "Object.values(T.partStates).filter(s => s === 'hidden').length === 3")
        page.locator("#slider").fill(str(first_release + 0.5))
        wait(page, "Object.values(T.partStates).filter(s => s === 'hidden').length === 2")
        shot(page, shots / "4-preview.png")

        # approve (naming the record's hash) → execution, watched live
        record_hash = state(page, "T.view.waiting_for.record_hash")
        page.click("#approve")
        wait(page, "T.vTraj === 'pass' && Object.keys(T.placed).length === 3", 600)
        assert set(state(page, "Object.values(T.placed)")) == {"placed"}
        assert state(page, "T.view.status") == "success"
        assert state(page, "T.deltaPoints.length") > 0
        shot(page, shots / "5-executed.png")

        # reload → the run is still there, finished, and replays from its event stream
        run_id = state(page, "T.runId")
        page.reload()
        wait(page, f"T.runId === '{run_id}' && T.view.status === 'success'")
        assert run_id in page.inner_text("#runs")
        page.click("#replay")
        wait(page, "T.replay && T.replay.k === 0")
        kinds = state(page, "T.replay.steps.map(s => s.kind)")
        assert kinds == ["design", "decision", "design", "decision", "record", "approval",
                         "execution"]  # fmt: skip
        # the Designer's layout as the review showed it, then the operator's edit, then theirs
        assert state(page, "T.partIds.length") == 3
        assert state(page, "T.replay.layout.find(p => p.id === 'c3').position") == pos["c3"]
        shot(page, shots / "6-replay-design.png")
        page.click("#replay-next")
        wait(page, "T.replay.k === 1")
        assert "edit" in page.inner_text("#replay-step") and "by twin" in page.inner_text(
            "#replay-step"
        )
        page.click("#replay-next")
        wait(page, "T.replay.k === 2")
        assert state(page, "T.replay.layout.find(p => p.id === 'c3').position") == moved
        for k in (3, 4, 5):
            page.click("#replay-next")
            wait(page, f"T.replay.k === {k}")
        approval = page.inner_text("#replay-step")
        assert f"approved record {record_hash[:12]} by twin" in approval
        # the execution: parts come back as the replay's clock reaches them, with δ
        page.click("#replay-next")
        wait(page, "T.replay.k === 6 && T.placedAtReplayStart !== undefined")
        assert state(page, "T.placedAtReplayStart") == 0
        wait(page, "Object.keys(T.placed).length === 3 && T.deltaPoints.length > 0")
        assert set(state(page, "Object.values(T.placed)")) == {"placed"}
        assert "V_traj pass" in page.inner_text("#replay-step")
        shot(page, shots / "6-replay.png")
        assert errors == []


def test_reject_with_a_reason_replans(tmp_path: Path, shots: Path) -> None:
    need_browser()
    with served(tmp_path / "runs.sqlite") as (url, twin), browser() as b:
        run_id = twin.start("a row of 3 cubes")
        twin.wait()
        page = b.new_page(viewport={"width": 1280, "height": 800})
        errors = page_errors(page)
        page.goto(f"{url}#{run_id}")
        wait(page, "T.phase === 'design_review' && T.partIds.length === 3")
        xs = state(page, "T.view.review.parts.map(p => p.position[0])")
        page.click("#reject")  # no reason: refused, nothing changes
        wait(page, "T.lastError && T.lastError.startsWith('reason')")
        page.fill("#reason", "move it to the back")
        page.click("#reject")
        wait(page, "T.phase === 'design_review' && T.view.waiting_for.replanned")
        after = state(page, "T.view.review.parts.map(p => p.position[0])")
        assert min(after) > max(xs)  # the back of the table
        assert page.is_visible("#replanned") and "moved" in page.inner_text("#replanned")
        notes = page.locator("#reading li.note").all_inner_texts()
        assert notes and len(notes) == len(set(notes))  # each note once, not reading + run
        shot(page, shots / "7-replanned.png")
        page.click("#review-abort")
        wait(page, "T.phase === 'rejected'")
        assert errors == []


def test_a_delta_breach_raises_the_failure_report_with_its_options(
    tmp_path: Path, shots: Path
) -> None:
    need_browser()
    with served(tmp_path / "runs.sqlite") as (url, twin), browser() as b:
        # an injected drift: joint 1 leaves the plan 3 s into the motion
        run_id = twin.start("a tower of 3 cubes", ["joint_drift"])
        twin.wait()
        page = b.new_page(viewport={"width": 1280, "height": 800})
        errors = page_errors(page)
        page.goto(f"{url}#{run_id}")
        wait(page, "T.phase === 'design_review' && T.partIds.length === 3")
        page.click("#accept")
        wait(page, "T.phase === 'pre_execute' && T.timeline && "
                   "T.timeline.record_hash === T.view.waiting_for.record_hash")  # fmt: skip
        page.click("#approve")
        wait(page, "T.phase === 'failure_report'", 600)
        assert page.is_visible("#failure-panel")
        assert "deviation" in page.inner_text("#failure")
        assert state(page, "T.view.execution.status") == "paused"
        # δ crossed ε on the plot before the robots stopped
        wait(page, "T.deltaPoints.some(p => p[1] > T.scene.epsilon_rad)")
        skills = state(page, "[...document.querySelectorAll('#skills button')]"
                       ".map(b => b.textContent)")  # fmt: skip
        assert skills == ["shift", "flatten", "spread", "modify"]
        for button in ("#retry", "#edit-failed", "#fail-abort"):
            assert page.is_visible(button)
        shot(page, shots / "8-delta-breach.png")
        # a skill that cannot help says why; the report stays open
        page.click("#skill-shift")
        wait(page, "T.phase === 'failure_report' && !!T.view.waiting_for.refused")
        assert "shift" in page.inner_text("#failure-refused")
        # the human edit: the failed layout opens in the editor, the edit goes to the run
        page.click("#edit-failed")
        wait(page, "T.view.review && !document.getElementById('review-panel').hidden")
        assert page.is_hidden("#failure-panel") and page.is_disabled("#accept")
        c3 = state(page, "T.view.review.parts.find(p => p.id === 'c3').position")
        at = state(page, f"T.screenOf({top(c3)})")
        page.mouse.click(at[0], at[1])
        wait(page, "T.selected === 'c3'")
        page.click("#delete")
        wait(page, "T.view.review.parts.length === 2")
        shot(page, shots / "9-edit-failed.png")
        page.click("#accept")
        wait(page, "T.phase === 'design_review' && T.partIds.length === 2")
        assert errors == []


def test_second_tab_sees_the_run_but_cannot_edit_while_the_first_holds_the_lock(
    tmp_path: Path,
) -> None:
    need_browser()
    with served(tmp_path / "runs.sqlite") as (url, twin), browser() as b:
        run_id = twin.start("a tower of 2 cubes")
        twin.wait()
        one, two = b.new_page(), b.new_page()
        for page in (one, two):
            page.goto(f"{url}#{run_id}")
            wait(page, "T.phase === 'design_review' && T.partIds.length === 2")
        one.click("#insert-cube")
        wait(one, "T.view.review.parts.length === 3")
        # the other tab is told of the edit and shows it, but its own edit is refused
        wait(two, "T.view.review.parts.length === 3")
        two.click("#undo")
        wait(two, "T.lastError && T.lastError.includes('another tab')")
        assert state(one, "T.view.review.parts.length") == 3


def test_a_failure_the_recovery_cannot_fix_raises_the_failure_report(
    tmp_path: Path, shots: Path
) -> None:
    need_browser()
    with served(tmp_path / "runs.sqlite") as (url, twin), browser() as b:
        # a row across two blocked regions: every recovery the budget allows fails too
        run_id = twin.start("a row of 8 cubes", ["workspace_boundary", "env_collision"])
        twin.wait()
        page = b.new_page(viewport={"width": 1280, "height": 800})
        errors = page_errors(page)
        page.goto(f"{url}#{run_id}")
        wait(page, "T.phase === 'design_review' && T.partIds.length === 8")
        # the operator accepts each design and record the recovery proposes, until it gives up
        for _ in range(8):
            wait(page, "['design_review', 'recovery_review', 'pre_execute', 'failure_report']"
                       ".includes(T.phase)", 600)  # fmt: skip
            phase = state(page, "T.phase")
            if phase == "failure_report":
                break
            if phase in ("design_review", "recovery_review"):
                page.click("#accept")
            else:
                wait(
                    page, "T.timeline && T.timeline.record_hash === T.view.waiting_for.record_hash"
                )
                page.click("#approve")
            wait(page, f"T.phase !== '{phase}'")
        assert state(page, "T.phase") == "failure_report"
        assert page.is_visible("#failure-panel")
        assert "blocked region" in page.inner_text("#failure")
        assert page.is_visible("#skills button")  # the recovery skills are offered
        shot(page, shots / "7-failure-report.png")
        page.click("#fail-abort")
        wait(page, "T.phase === 'failure'")
        assert errors == []
