"""ξ_flatten and ξ_shift: deterministic geometric recovery whose output re-verifies."""

from __future__ import annotations

import numpy as np
import pytest

from sdi.design import compose
from sdi.errors import InfeasibleError
from sdi.inspector import verify
from sdi.model.cell import CellConfig
from sdi.model.region import Region
from sdi.recovery import flatten, shift
from sdi.spec import Spec, structure


def build(shape: str, **kw):
    return compose(Spec(structures=(structure(shape, **kw),)))


@pytest.mark.parametrize(
    ("shape", "kw", "z_max"),
    [
        ("tower", {"height": 6}, 0.15),
        ("staircase", {"steps": 5}, 0.10),
        ("wall", {"length": 4, "height": 4}, 0.1),
    ],
)
def test_flatten_lowers_keeps_parts_and_verifies(shape, kw, z_max):
    layout = build(shape, **kw)
    flat = flatten(layout, z_max=z_max)
    assert sorted(flat.ids) == sorted(layout.ids)
    assert max(p.top for p in flat) <= z_max + 1e-9
    assert verify(flat).passed, verify(flat).violations[:3]


def test_flatten_avoids_blocked_regions():
    layout = build("tower", height=6, at_x=0.5, at_y=0.3)
    blocked = (Region(y_max=0.3),)  # nothing may go to y < 0.3 … except what is already there
    flat = flatten(layout, z_max=0.1, blocked=blocked)
    moved = [p for p in flat if p.position != layout.part(p.id).position]
    assert moved and all(p.position[1] - 0.025 >= 0.3 - 1e-9 for p in moved)


def test_flatten_refuses_below_one_part():
    with pytest.raises(InfeasibleError) as info:
        flatten(build("tower"), z_max=0.01)
    assert info.value.parameter == "z_max"


@pytest.mark.parametrize(
    "region",
    [
        Region(x_min=0.6),
        Region(y_min=0.4),
        Region(normal=(1.0, 1.0, 0.0), offset=0.7),
        Region(x_min=0.4, x_max=0.6, y_min=0.2, y_max=0.4),
    ],
)
def test_shift_clears_blocked_region(region):
    layout = build("grid", length=3, width=3, at_x=0.6, at_y=0.35)
    lo = layout.centres - layout.half_extents
    hi = layout.centres + layout.half_extents
    assert region.blocks(lo, hi).any()  # the scenario really is blocked
    moved = shift(layout, blocked=(region,))
    lo = moved.centres - moved.half_extents
    hi = moved.centres + moved.half_extents
    assert not region.blocks(lo, hi).any()
    assert verify(moved).passed


def test_shift_reports_impossible():
    layout = build("tower")
    with pytest.raises(InfeasibleError) as info:
        shift(layout, blocked=(Region(x_min=0.0),))
    assert info.value.parameter == "blocked"


def test_region_half_space_and_box():
    import numpy as np

    r = Region(normal=(1.0, 1.0, 0.0), offset=0.7)
    assert r.blocks(np.array([[0.3, 0.3, 0.0]]), np.array([[0.35, 0.35, 0.05]])).tolist() == [False]
    assert r.blocks(np.array([[0.36, 0.33, 0.0]]), np.array([[0.41, 0.38, 0.05]])).tolist() == [
        True
    ]
    with pytest.raises(ValueError):
        Region(normal=(1.0, 0.0, 0.0))


# -- the smallest change, with a margin, stated --------------------------------------------------
def boxes(layout):
    return layout.centres - layout.half_extents, layout.centres + layout.half_extents


def test_shift_keeps_a_margin_from_the_blocked_region():
    from sdi.execute.faults import SCENARIOS
    from sdi.recovery.shift import default_margin, shift_search

    layout = build("grid", length=2, width=2, at_x=0.45, at_y=0.3)  # the 2×2 grid of Table V
    region = SCENARIOS["singular_centre"].regions
    out = shift_search(layout, blocked=region)
    lo, hi = boxes(out.layout)
    pad = default_margin(CellConfig())
    assert pad >= 0.0008 + CellConfig().tolerances.contact  # placement gap + tolerance
    grown = np.array([pad, pad, 0.0]) - 1e-6
    assert not any(r.blocks(lo - grown, hi + grown).any() for r in region)
    assert (out.dx, out.dy) != (0.0, 0.0) and "mm clear" in out.describe()


def test_shift_never_reruns_a_clear_layout():
    from sdi.recovery.shift import shift_search

    layout = build("tower", height=2, at_x=0.3, at_y=0.3)
    with pytest.raises(InfeasibleError) as info:
        shift_search(layout, blocked=(Region(x_min=0.7),))
    assert info.value.parameter == "layout"


def test_shift_turns_when_only_a_turn_fits():
    from sdi.recovery.shift import shift_search

    row = build("row", length=3, axis="y", at_x=0.5, at_y=0.3)  # 0.15 m along y
    band = (Region(y_max=0.23), Region(y_min=0.37))  # only 0.14 m of y is free
    out = shift_search(row, blocked=band)
    assert out.yaw_deg in (90.0, 270.0) and "turned by" in out.describe()
    lo, hi = boxes(out.layout)
    assert lo[:, 1].min() > 0.23 and hi[:, 1].max() < 0.37
    assert verify(out.layout).passed


def test_shift_moves_before_it_turns_a_row_off_its_axis():
    from sdi.recovery.outcome import recover

    spec = Spec(structures=(structure("row", length=6, axis="y"),))  # Table V's F04
    row = compose(spec)
    hi = (row.centres + row.half_extents)[:, 1].max()
    region = (Region(y_min=0.4),)
    assert hi > 0.4  # the row reaches into the region
    out, outcome = recover("shift", row, CellConfig(), region, spec)
    assert outcome.turned_deg == 0.0 and outcome.moved_by_m is not None
    assert outcome.moved_by_m[1] < -0.05  # a longer move than a turn, but the row still runs
    assert np.ptp(out.centres[:, 0]) == 0.0 and not outcome.shape_changed  # along y
    assert (out.centres + out.half_extents)[:, 1].max() < 0.4 and verify(out).passed


def test_a_turn_off_the_commanded_axis_is_a_changed_shape_and_says_so():
    from sdi.recovery.outcome import recover

    spec = Spec(structures=(structure("row", length=5, axis="y"),))  # a 0.25 m row
    band = (Region(y_max=0.23), Region(y_min=0.37))  # in a 0.14 m band: only a turn fits
    out, outcome = recover("shift", compose(spec), CellConfig(), band, spec)
    assert outcome.turned_deg in (90.0, 270.0) and outcome.shape_changed
    assert "runs along x, not along y as commanded" in outcome.summary
    assert np.ptp(out.centres[:, 1]) == 0.0 and verify(out).passed


def test_spread_opens_the_same_gap_between_every_pair_of_neighbours():
    from sdi.recovery.spread import spread_apart

    layout = build("block", length=2, width=2, height=2, at_x=0.45, at_y=0.3)
    out = spread_apart(layout, 0.03)
    assert [p.position[2] for p in out] == [p.position[2] for p in layout]  # heights kept
    xs = sorted({p.position[0] for p in out})
    ys = sorted({p.position[1] for p in out})
    assert np.diff(xs) == pytest.approx([0.08]) and np.diff(ys) == pytest.approx([0.08])

    def middle(lay):
        lo, hi = boxes(lay)
        return (lo.min(axis=0) + hi.max(axis=0))[:2] / 2

    assert middle(out) == pytest.approx(middle(layout))  # spread about the footprint centre
    assert verify(out).passed  # each column still stands on its own


def test_spread_lets_the_arms_build_a_grid_in_the_corner_pocket():
    from sdi.commission import commission
    from sdi.errors import SDIError
    from sdi.execute.faults import SCENARIOS
    from sdi.recovery.outcome import recover
    from sdi.recovery.shift import shift_search

    pocket = SCENARIOS["corner_pocket"].regions  # Table V's F10
    grid = shift_search(build("grid", length=2, width=2), blocked=pocket).layout
    with pytest.raises(SDIError, match="vacuum"):  # the last cube: only the vacuum, out of reach
        commission(grid, CellConfig())
    out, outcome = recover("spread", grid, CellConfig(), pocket)
    assert outcome.action == "spread" and outcome.shape_changed and outcome.gap_m
    assert "opened gaps of" in outcome.summary and len(outcome.changes) == 4
    lo, hi = boxes(out)
    assert lo[:, 0].min() > 0.55 and hi[:, 0].max() < 0.75
    assert lo[:, 1].min() > 0.35 and hi[:, 1].max() < 0.55
    assert verify(out).passed and commission(out, CellConfig()) is not None


def test_rules_spread_only_after_a_grip_or_reach_failure_that_moving_did_not_fix():
    from sdi.orchestrator.graph import rule_route
    from sdi.orchestrator.methods import METHODS

    hybrid = METHODS["Hybrid"]
    ik = {"failure": {"error_type": "ik", "scenario": None}}
    assert rule_route({**ik, "tried": ["shift", "shift", "flatten"]}, hybrid) == "spread"
    assert rule_route({**ik, "tried": ["shift", "shift", "flatten", "spread"]}, hybrid) == "modify"
    region = {"failure": {"error_type": "collision", "scenario": "env_collision"}}
    assert rule_route({**region, "tried": ["shift", "flatten"]}, hybrid) == "modify"


def test_flatten_keeps_the_command_structure_first():
    from sdi.recovery import reshape

    spec = Spec(structures=(structure("tower", height=4, at_x=0.45, at_y=0.3),))
    out = reshape(spec, compose(spec), z_max=0.15, blocked=(Region(z_min=0.15),))
    assert len(out.layout) == 4  # every commanded part is still there
    assert "→ 2 towers of 2+2 levels" in out.describe() and out.before == "tower (height 4)"
    assert max(p.top for p in out.layout) <= 0.15 + 1e-9 and verify(out.layout).passed


def test_flatten_that_changes_nothing_is_not_tried():
    from sdi.recovery import reshape

    spec = Spec(structures=(structure("tower", height=2),))
    with pytest.raises(InfeasibleError) as info:
        reshape(spec, compose(spec), z_max=0.15)
    assert info.value.parameter == "z_max" and "same layout" in str(info.value)


def test_rule_replan_moves_away_from_a_collision_region():
    from sdi.recovery.outcome import rule_replan

    layout = build("tower", height=3, at_x=0.5, at_y=0.45)
    out, outcome = rule_replan(layout, CellConfig(), (Region(y_min=0.4),))
    _, hi = boxes(out)
    assert hi[:, 1].max() < 0.4 and verify(out).passed
    assert outcome.moved_by_m is not None and outcome.moved_by_m[0] == 0.0  # no turn, no x
    assert not outcome.shape_changed and len(outcome.changes) == 3


def test_recovery_states_what_changed_and_a_new_shape_waits(tmp_path):
    from sdi.orchestrator import Orchestrator

    orch = Orchestrator(db=tmp_path / "r.sqlite")
    s = orch.start("a 4-cube tower at x = 0.45", faults=["height_limit"], approve=True)
    assert s.status == "paused" and s.waiting_for["kind"] == "recovery_review"
    recovery = s.state["recoveries"][-1]
    assert recovery["flattened_from"] == "tower (height 4)" and recovery["shape_changed"]
    assert any(m.type == "recovery" for m in orch.bus.history(s.run_id))
    assert s.to_json_dict()["recoveries"][-1]["summary"].startswith("flatten: flattened from")
    orch.close()


@pytest.mark.parametrize("method", ["MultiAgent-RuleOrch", "PGEOrch", "LGOrch"])
def test_rule_based_baselines_replan_away_from_the_region(tmp_path, method):
    from sdi.orchestrator import Orchestrator

    orch = Orchestrator(db=tmp_path / "b.sqlite")
    s = orch.start("a 3-cube tower at x = 0.5, y = 0.45", method=method,
                   faults=["env_collision"], approve=True)  # fmt: skip
    assert s.status == "success", s.state.get("notes")
    assert s.state["recoveries"][0]["action"] == "rule-replan"
    orch.close()
