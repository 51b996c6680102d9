"""ξ_flatten and ξ_shift: deterministic geometric recovery whose output re-verifies."""

from __future__ import annotations

import pytest

from sdi.design import compose
from sdi.errors import InfeasibleError
from sdi.inspector import verify
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
