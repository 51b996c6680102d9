"""The scenario suites as data (Tables IV, V, VI), the sweep that runs them (cache, time
limits, workers, Ray), the paper-shaped tables and the physics column."""

from __future__ import annotations

import json
import time
from collections import Counter

import numpy as np
import pytest
from typer.testing import CliRunner

from sdi import cli
from sdi.bench import shape_checks, sweep
from sdi.bench.cases import (
    CaseResult,
    RunConfig,
    _as_close,
    _kept,
    needs_model,
    run_case,
    stands,
)
from sdi.bench.charts import chart
from sdi.bench.report import plan_jobs, resolve_methods, resolve_suites, suite_json
from sdi.bench.scenarios import FailureCase, HumanMod, MotionCase, load
from sdi.bench.sweep import Job, ResultCache, cache_key
from sdi.bench.tables import markdown, summarise
from sdi.execute.faults import SCENARIOS
from sdi.model import Layout, Part
from sdi.model.cell import CellConfig
from sdi.model.region import Region
from sdi.orchestrator.methods import METHODS
from sdi.pipeline import plan

RULES = RunConfig()


def _plan(command: str) -> Layout:
    result = plan(command)
    assert result.status == "success" and result.layout is not None, (command, result.error)
    return result.layout


# -- the data ----------------------------------------------------------------------------------


def test_table_iv_has_the_papers_nine_modifications_on_the_papers_structures():
    mods = load("human-mods")
    assert len(mods) == 9 and all(isinstance(m, HumanMod) for m in mods)
    assert Counter(m.type for m in mods) == {"WS": 3, "Col": 2, "Grav": 2, "Seq": 2}
    assert [m.paper_steps for m in mods] == [3, 9, 21, 6, 12, 5, 5, 8, 21]


@pytest.mark.parametrize("mod", load("human-mods"), ids=lambda m: m.id)
def test_each_modification_edits_parts_of_its_planned_structure(mod):
    layout = _plan(mod.command)
    assert shape_checks.signature(mod.shape)(layout) is None  # the signature fits the plan
    ids = set(layout.ids)
    for edit in mod.edits:
        named = [edit[k] for k in ("id", "move", "before") if k in edit]
        assert edit.get("op") == "sequence" or named, edit
        assert set(named) <= ids, (edit, sorted(ids))
    # the paper's step count, or a note saying why the generator cannot make it
    assert len(layout) == mod.paper_steps or mod.steps_note, (len(layout), mod.paper_steps)
    if mod.steps_note:
        assert len(layout) != mod.paper_steps


def test_table_v_has_one_case_per_failure_scenario():
    failures = load("failures")
    assert len(failures) == 10 and all(isinstance(f, FailureCase) for f in failures)
    assert sorted(f.scenario for f in failures) == sorted(SCENARIOS)


def _boxes(layout: Layout) -> tuple[np.ndarray, np.ndarray]:
    from sdi.bench.signatures import world_boxes

    centres, half = world_boxes(layout)  # the judge's own geometry, from the raw poses
    return centres - half, centres + half


@pytest.mark.parametrize("case", load("failures"), ids=lambda c: c.id)
def test_each_failure_command_really_reaches_into_its_blocked_region(case):
    layout = _plan(case.command)
    lo, hi = _boxes(layout)
    blocked = np.zeros(len(layout), dtype=bool)
    for region in SCENARIOS[case.scenario].regions:
        blocked |= region.blocks(lo, hi)
    assert blocked.any(), f"{case.command!r} stays clear of {case.scenario}"
    assert shape_checks.signature(case.shape)(layout) is None


# -- can the commanded shape be kept at all? (computed) ------------------------------------------


@pytest.mark.parametrize("case", load("failures"), ids=lambda c: c.id)
def test_a_keepable_placement_keeps_the_signature_and_the_margin(case):
    from sdi.bench.keepable import keepable
    from sdi.recovery.shift import default_margin, translated, turned

    layout = _plan(case.command)
    regions = SCENARIOS[case.scenario].regions
    k = keepable(layout, case.shape, regions, reach=False)
    if not k.geometric:
        assert not k.possible and "no placement" in k.reason and k.candidates == 0
        return
    assert k.moved_by_m is not None and k.yaw_deg is not None and k.candidates > 0
    assert k.gap_m == 0.0  # the packed structure is tried first
    placed = translated(turned(layout, k.yaw_deg), *k.moved_by_m)
    assert shape_checks.signature(case.shape)(placed) is None
    pad = np.array([1.0, 1.0, 0.0]) * (default_margin(CellConfig()) - 1e-6)
    lo, hi = placed.centres - placed.half_extents, placed.centres + placed.half_extents
    assert not any(r.blocks(lo - pad, hi + pad).any() for r in regions)


def test_a_tower_above_a_height_limit_or_a_row_longer_than_its_band_cannot_be_kept():
    from sdi.bench.keepable import keepable

    tower = _plan("Build a 4-cube tower at x = 0.4 m.")  # reaches 0.20 m wherever it stands
    k = keepable(tower, [["tower", 4], ["parts", 4]], (Region(z_min=0.15),), reach=False)
    assert not k.possible and not k.geometric
    row = _plan("Place a row of 4 cubes along the x axis.")  # 0.20 m long, 0.10 m of x free
    corridor = (Region(x_max=0.3), Region(x_min=0.4))
    k = keepable(row, [["row"], ["parts", 4], ["axis", "x"]], corridor, reach=False)
    assert not k.geometric and "turning breaks it: 90°: long side along y, expected x" in k.reason
    k = keepable(row, [["row"], ["parts", 4]], corridor, reach=False)  # no axis named: a turn
    assert k.geometric and k.yaw_deg in (90.0, 270.0)


@pytest.mark.slow
def test_the_packed_corner_pocket_grid_cannot_be_built_there_but_a_spread_one_can():
    from sdi.bench.keepable import case_keepable, keepable
    from sdi.recovery.shift import translated
    from sdi.recovery.spread import spread_apart

    case = next(c for c in load("failures") if c.scenario == "corner_pocket")
    layout, pocket = _plan(case.command), SCENARIOS[case.scenario].regions
    packed = keepable(layout, case.shape, pocket, gaps=())
    assert packed.geometric and not packed.possible
    assert packed.commissioned == packed.candidates > 0  # every clear placement was tried
    assert "open grip options: vacuum" in packed.reason  # the last cube can only be sucked …
    near = case_keepable(case.command, case.shape, "workspace_boundary")
    assert near.possible and near.gap_m == 0.0  # … which the arms can do elsewhere
    k = case_keepable(case.command, case.shape, case.scenario)
    assert k.possible and k.gap_m and k.moved_by_m is not None and k.yaw_deg == 0.0
    spread = translated(spread_apart(layout, k.gap_m), *k.moved_by_m)
    assert shape_checks.signature(case.shape)(spread) is None  # the grid check allows the gap
    assert f"with gaps of {k.gap_m * 1000:.0f} mm" in k.reason


def test_shape_kept_is_judged_without_position_and_rejects_a_flattened_tower():
    tower = load("failures")[6]  # low ceiling: a 3-cube tower
    sig = shape_checks.signature(tower.shape)
    moved = _plan("Build a 3-cube tower at x = 0.3 m, y = 0.2 m.")
    assert sig(moved) is None  # moved elsewhere: still the commanded shape
    assert sig(_plan("Place a row of 3 cubes along the x axis.")) is not None  # flattened


def test_table_vi_has_twelve_commands_in_the_papers_categories_and_one_extra_job():
    motion = load("motion")
    assert all(isinstance(m, MotionCase) for m in motion)
    paper = [m for m in motion if not m.extra]
    assert Counter(m.category for m in paper) == {
        "simple single-arm": 6, "complex single-arm": 3, "dual-arm": 3,
    }  # fmt: skip
    assert all(m.mode == "dual" for m in paper if m.category == "dual-arm")


def test_a_signature_with_an_unknown_check_or_bad_arguments_is_refused():
    with pytest.raises(ValueError, match="unknown check 'spire'"):
        shape_checks.signature([["spire", 3]])
    with pytest.raises(ValueError, match="takes no arguments"):
        shape_checks.signature([["row", 3]])
    with pytest.raises(ValueError, match="check 'parts'"):
        shape_checks.signature([["parts", 1, 2, 3, 4]])
    with pytest.raises(ValueError, match="unknown scenario"):
        FailureCase(id="x", command="a tower", scenario="meteor", name="x", error="x",
                    shape=(("tower", 3),))  # fmt: skip


# -- scoring -----------------------------------------------------------------------------------


def _cube(pid: str, x: float, y: float, z: float) -> Part:
    return Part(id=pid, position=(x, y, z))


def test_edit_kept_means_the_touched_parts_are_where_the_operator_put_them():
    before = Layout(objects=(_cube("a", 0.4, 0.3, 0.025), _cube("b", 0.4, 0.3, 0.075)))
    moved = [{"op": "move", "id": "b", "position": [0.5, 0.3, 0.025]}]
    kept = Layout(objects=(_cube("a", 0.4, 0.3, 0.025), _cube("b", 0.5, 0.3, 0.025)))
    assert _kept(before, kept, ["a", "b"], ["a", "b"], moved)
    assert not _kept(before, before, ["a", "b"], ["a", "b"], moved)  # reverted
    removed = [{"op": "remove", "id": "b"}]
    assert _kept(before, Layout(objects=(before.objects[0],)), [], [], removed)
    assert not _kept(before, before, [], [], removed)  # the removed part came back
    order = [{"op": "sequence", "move": "b", "before": "a"}]
    assert _kept(before, before, ["a", "b"], ["b", "a"], order)
    assert not _kept(before, before, ["a", "b"], ["a", "b"], order)


def test_as_close_accepts_the_nearest_feasible_pose_and_nothing_farther():
    before = _plan("Build a 3-cube tower at x = 0.4 m.")  # Table IV's H1: c3 to x = 1.0
    outside = [{"op": "move", "id": "c3", "position": [1.0, 0.3, 0.125]}]
    cell = CellConfig()

    def with_c3(x: float, y: float, z: float) -> Layout:
        return before.replaced(_cube("c3", x, y, z) if p.id == "c3" else p for p in before)

    edge = with_c3(0.775, 0.3, 0.025)  # at the workspace's edge, on the table
    assert not _kept(before, edge, [], [], outside)  # x = 1.0 cannot be kept …
    assert _as_close(before, edge, [], outside, cell)  # … and nothing feasible is nearer
    assert not _as_close(before, with_c3(0.7, 0.3, 0.025), [], outside, cell)  # 7.5 cm short
    assert not _as_close(before, before, [], outside, cell)  # undone: back on the tower


def test_as_close_keeps_every_move_before_pair_the_supports_allow():
    before = _plan("Build a 3-cube tower at x = 0.4 m.")
    cell = CellConfig()
    impossible = [{"op": "sequence", "move": "c3", "before": "c1"}]  # c1 holds c3 up
    assert _as_close(before, before, ["c1", "c2", "c3"], impossible, cell)
    assert not _kept(before, before, ["c1", "c2", "c3"], ["c1", "c2", "c3"], impossible)
    row = _plan("Place a row of 3 cubes along the x axis.")
    possible = [{"op": "sequence", "move": "c3", "before": "c1"}]  # nothing holds c3 up
    assert not _as_close(row, row, ["c1", "c2", "c3"], possible, cell)
    assert _as_close(row, row, ["c3", "c1", "c2"], possible, cell)


def test_methods_that_need_a_model_are_not_applicable_on_rules():
    assert {m for m in METHODS if needs_model(m)} == {
        "LLM-Direct", "LLM-FullPrompt", "LLM-FixedLoop", "LLM-AdaptLoop", "SASS", "SAMS",
        "LGOrch", "Hybrid-LLMCritic",
    }  # fmt: skip
    case = load("failures")[0]
    start = time.perf_counter()
    result = run_case("failures", case, "LGOrch", 0, RULES)
    assert result.outcome == "n/a" and not result.fields
    assert time.perf_counter() - start < 0.5  # nothing was run


def test_a_human_modification_is_entered_detected_and_scored_consistently():
    mod = load("human-mods")[5]  # remove the middle cube of a 5-cube tower
    r = run_case("human-mods", mod, "Hybrid", 0, RunConfig(physics=True))
    f = r.fields
    assert r.outcome == "done" and f["planned"] and f["steps"] == 5
    assert f["entered"] and f["detected"]  # a floating cube: the Inspector must see it
    assert not f["edit_kept"] or f["corrected"]
    assert (r.physics is not None) == f["corrected"]
    if r.physics is not None:
        assert r.physics["stands"]


def test_an_edit_that_cannot_be_entered_is_neither_detected_nor_corrected():
    mod = HumanMod(id="X", name="bad", type="Seq", paper_steps=3, command="a 3-cube tower",
                   edits=({"op": "teleport", "id": "c1"},), shape=(("tower", 3),))  # fmt: skip
    f = run_case("human-mods", mod, "Hybrid", 0, RULES).fields
    assert not f["entered"] and f["refused"]
    assert not f["detected"] and not f["corrected"] and not f["edit_kept"]


@pytest.mark.slow
def test_an_injected_failure_is_hit_and_scored():
    case = next(c for c in load("failures") if c.scenario == "low_ceiling")
    r = run_case("failures", case, "Hybrid", 0, RunConfig(physics=True))
    f = r.fields
    assert r.outcome == "done" and f["hit"] and f["executions"] >= 1
    assert f["recovered"] == (f["status"] == "success")
    assert not f["shape_kept"] or f["recovered"]
    assert f["stated"] == (not f["changed"] or bool(f["notes"]))


# -- the physics column ------------------------------------------------------------------------


def test_physics_column_tells_a_standing_layout_from_a_falling_one():
    tower = Layout(objects=(_cube("a", 0.4, 0.3, 0.025), _cube("b", 0.4, 0.3, 0.075)))
    assert stands(tower, ["a", "b"], seed=0)["stands"]
    overhang = Layout(objects=(_cube("a", 0.4, 0.3, 0.025), _cube("b", 0.44, 0.3, 0.075)))
    fell = stands(overhang, ["a", "b"], seed=0)
    assert not fell["stands"] and fell["worst_offset_mm"] > 5


def test_a_successful_command_is_assembled_and_a_failed_one_is_not():
    command = load("commands")[0]
    r = run_case("commands", command, None, 0, RunConfig(physics=True))
    assert r.fields["success"] and r.physics is not None and r.physics["stands"]
    r = run_case("commands", command, None, 0, RULES)
    assert r.physics is None  # not asked for


# -- the sweep ---------------------------------------------------------------------------------


def _cheap_jobs(n: int = 2) -> list[Job]:
    return [Job("commands", c, None, 0) for c in load("commands")[:n]]


def test_a_rerun_reads_finished_cases_from_the_cache_and_runs_nothing(tmp_path, monkeypatch):
    cache = ResultCache(tmp_path / "cache")
    first = sweep.sweep(_cheap_jobs(), RULES, cache=cache)
    assert all(r.outcome == "done" and r.key for r in first)
    assert len(list((tmp_path / "cache").glob("*.json"))) == 2

    def boom(*args, **kwargs):
        raise AssertionError("a cached case was run again")

    monkeypatch.setattr(sweep, "run_case", boom)
    seen = []
    again = sweep.sweep(_cheap_jobs(), RULES, cache=cache, progress=lambda j, r, c: seen.append(c))
    assert seen == [True, True] and again == first
    # another configuration is another key: it runs (and here, fails loudly)
    with pytest.raises(AssertionError, match="run again"):
        sweep.sweep(_cheap_jobs(1), RunConfig(physics=True), cache=cache)
    job = _cheap_jobs(1)[0]
    assert cache_key(job, RULES) != cache_key(job, RunConfig(physics=True))
    assert cache_key(job, RULES) != cache_key(Job(job.suite, job.case, None, 1), RULES)


def test_a_case_past_its_time_limit_is_a_timeout_and_is_not_cached(tmp_path, monkeypatch):
    def slow(suite, case, method, seed, config):
        time.sleep(5)
        raise AssertionError("not stopped")

    monkeypatch.setattr(sweep, "run_case", slow)
    cache = ResultCache(tmp_path)
    start = time.perf_counter()
    (r,) = sweep.sweep(_cheap_jobs(1), RULES, timeout=0.3, cache=cache)
    assert r.outcome == "timeout" and time.perf_counter() - start < 2
    assert cache.get(r.key) is None and not list(tmp_path.glob("*.json"))


@pytest.mark.slow
def test_a_local_pool_gives_the_same_scores_as_one_process():
    jobs = _cheap_jobs(3)
    here = sweep.sweep(jobs, RULES)
    pooled = sweep.sweep(jobs, RULES, workers=2, timeout=120)
    assert [r.fields["success"] for r in pooled] == [r.fields["success"] for r in here]
    assert [r.case for r in pooled] == [j.case.id for j in jobs]


@pytest.mark.slow
def test_a_sweep_fans_out_on_a_local_ray_instance():
    pytest.importorskip("ray", reason="the optional extra `ray` is not installed")
    jobs = [*_cheap_jobs(2), Job("failures", load("failures")[0], "LGOrch", 0)]
    results = sweep.sweep(jobs, RULES, ray_address="local", timeout=120)
    assert [r.outcome for r in results] == ["done", "done", "n/a"]
    assert all(r.fields["success"] for r in results[:2])


# -- tables, charts, the command line ----------------------------------------------------------


def _result(suite, case, method, **fields) -> CaseResult:
    return CaseResult(suite=suite, case=case, method=method, backend="rules", seed=0,
                      outcome="n/a" if method == "LGOrch" else "done", fields=fields)  # fmt: skip


def test_table_iv_counts_detected_corrected_and_kept_per_method_with_na():
    results = []
    for k, mod in enumerate(load("human-mods")):
        for m in ("Hybrid", "LGOrch"):
            notes = ["moved back"] if k < 2 else []
            results.append(_result("human-mods", mod.id, m, steps=mod.paper_steps,
                                   detected=True, corrected=k < 7, edit_kept=k < 3,
                                   edit_as_close=k < 5, entered=True, notes=notes))  # fmt: skip
    summary = summarise("human-mods", results)
    assert summary["totals"]["Hybrid"] | {"physics": None} == {
        "runs": 9, "detected": 9, "corrected": 7, "edit_kept": 3, "edit_as_close": 5,
        "shape_kept": 0, "entered": 9, "stated": 2, "physics": None,
    }  # fmt: skip
    assert summary["totals"]["LGOrch"] == "n/a"
    table = markdown("human-mods", summary)
    assert "| Human modification | Type | Steps (paper / built) | Hyb | LG |" in table
    assert "| **Corrected** | | | 7/9 | n/a |" in table
    assert "| **Edit kept as close as possible** | | | 5/9 | n/a |" in table
    assert table.count("✓ / ✓ / ✓ / ✓") == 3 and table.count("✓ / ✓ / ✗ / ✓") == 2
    assert "21 / 21 ¹" not in table
    assert chart("human-mods", summary).startswith(b"\x89PNG")


def test_table_v_reports_recovered_and_shape_kept():
    results = [
        _result("failures", c.id, "Hybrid", hit=True, recovered=True, shape_kept=k % 2 == 0,
                changed=True, notes=["shifted by (0.1, 0)"] if k < 4 else [],
                keepable=k < 6, keepable_reason=None if k < 6 else f"region {k} too small")
        for k, c in enumerate(load("failures"))
    ]  # fmt: skip
    summary = summarise("failures", results)
    t = summary["totals"]["Hybrid"]
    assert (t["recovered"], t["shape_kept"], t["stated"], t["changed_and_recovered"]) == (
        10, 5, 4, 10,
    )  # fmt: skip
    assert (t["keepable"], t["kept_where_keepable"]) == (6, 3)  # cases 0, 2, 4 of 0…5
    table = markdown("failures", summary)
    assert "| **Recovered** | | | 10/10 |" in table and "| **Shape kept** | | | 5/10 |" in table
    assert "| **Shape kept where it can be kept** | | | 3/6 |" in table
    assert "Shape can be kept (computed)" in table
    first, last = load("failures")[0], load("failures")[9]
    assert f"| {first.label} | {first.error} | ✓ |" in table
    assert f"| {last.label} | {last.error} | ✗ ⁴ |" in table and "⁴ " + last.label in table
    assert chart("failures", summary).startswith(b"\x89PNG")


def test_commands_json_keeps_the_suite_runners_keys():
    jobs = plan_jobs(["commands"], None, 1, ["A01", "B01"])
    results = sweep.sweep(jobs, RULES)
    data = suite_json("commands", results, RULES, 1)
    assert data["overall"]["count"] == 2 and set(data["groups"]) == {"A", "B"}
    assert [c["id"] for c in data["commands"]] == ["A01", "B01"]
    assert "| pipeline | 100.0 | 100.0 | 100.0 |" in markdown("commands", data["summary"])
    assert chart("commands", data["summary"]).startswith(b"\x89PNG")


def test_default_methods_per_suite_and_flag_values():
    assert resolve_suites("all") == ["commands", "human-mods", "failures", "motion"]
    assert resolve_methods(["paper"]) == ["MultiAgent-RuleOrch", "PGEOrch", "LGOrch", "Hybrid"]
    assert resolve_methods(["all"]) == list(METHODS)
    jobs = plan_jobs(["commands", "failures", "motion"], None, 2, ["A01", "F01", "M01"])
    assert [(j.case.id, j.method, j.seed) for j in jobs] == [
        ("A01", None, 0), ("A01", None, 1),
        *[("F01", m, s) for m in ("MultiAgent-RuleOrch", "PGEOrch", "LGOrch", "Hybrid")
          for s in (0, 1)],
        ("M01", None, 0), ("M01", None, 1),
    ]  # fmt: skip


@pytest.mark.parametrize(
    ("args", "field"),
    [
        (["--suite", "towers"], "--suite"),
        (["--method", "Magic"], "--method"),
        (["--backend", "gpt9"], "--backend"),
        (["--jobs", "0"], "--jobs"),
        (["--seeds", "0"], "--seeds"),
        (["--timeout", "0"], "--timeout"),
        (["--timeout", "nan"], "--timeout"),
        (["--suite", "all", "--out", "x.json"], "--out"),
        (["--only", "Z99"], "--only"),
        (["--ray", " "], "--ray"),
        (["--ray", "local", "--jobs", "2"], "--jobs"),
    ],
)
def test_bad_bench_flags_are_one_line_and_exit_2(args, field, tmp_path):
    result = CliRunner().invoke(cli.app, ["bench", *args, "--cache", str(tmp_path)])
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    assert len(lines) == 1 and field in lines[0] and "Traceback" not in result.output


def test_bench_writes_the_report_and_a_rerun_is_served_from_the_cache(tmp_path):
    report, cache = tmp_path / "report", tmp_path / "cache"
    args = ["bench", "--suite", "human-mods", "--only", "H6", "--method", "Hybrid",
            "--report", str(report), "--cache", str(cache)]  # fmt: skip
    first = CliRunner().invoke(cli.app, args)
    assert first.exit_code == 0, first.output
    assert sorted(p.name for p in report.iterdir() if not p.name.startswith(".")) == [
        "human-mods.json", "human-mods.md", "human-mods.png",
    ]  # fmt: skip
    data = json.loads((report / "human-mods.json").read_text())
    assert [r["case"] for r in data["results"]] == ["H6"]
    assert "Remove middle cube from tower" in (report / "human-mods.md").read_text()
    again = CliRunner().invoke(cli.app, args)
    assert again.exit_code == 0 and "cached: 1 of 1 runs" in again.output


def test_a_cache_that_cannot_be_written_does_not_stop_the_sweep(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    cache = ResultCache(blocker / "cache")
    (r,) = sweep.sweep(_cheap_jobs(1), RULES, cache=cache)
    assert r.outcome == "done" and r.fields["success"]
    assert cache.error and "file" in cache.error


def test_ray_without_the_extra_is_a_one_line_error(tmp_path, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "ray", None)  # as if the extra were not installed
    args = ["bench", "--only", "A01", "--ray", "local", "--cache", str(tmp_path)]
    result = CliRunner().invoke(cli.app, args)
    assert result.exit_code == 2, result.output
    assert "--ray" in result.output and "sdi[ray]" in result.output
    assert "Traceback" not in result.output
