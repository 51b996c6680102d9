"""The digital twin end to end: a real server, real headless Chromium, a real run.

Type a command → the parts appear; drag one into another → a collision on both; undo → it
clears; drag one out of the workspace and apply the hint; accept; the record's preview plays
and the slider scrubs; approve; execution finishes with V_traj = pass and every part green;
reload → the run is still there and replays. A screenshot of each step is saved under the
test's output folder ($SDI_TWIN_SCREENSHOTS, else pytest's tmp_path).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from twin_harness import browser, drag, need_browser, page_errors, served, shot, state, wait

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
        wait(page, "T.placedAtReplayStart !== undefined")
        assert state(page, "T.placedAtReplayStart") == 0  # parts come back as the replay runs
        wait(page, "Object.keys(T.placed).length === 3 && T.deltaPoints.length > 0")
        shot(page, shots / "6-replay.png")
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
        shot(page, shots / "7-failure-report.png")
        page.click("#fail-abort")
        wait(page, "T.phase === 'failure'")
        assert errors == []
