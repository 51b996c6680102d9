"""Stability the simulation agrees with (issue 12, item 3).

The centre-of-mass test treated everything above a cut as one rigid body, so a 1-high canopy
with a pillar removed passed: the cross beams on the unsupported beam were counted as holding
it up. The equilibrium LP (contacts only push), the placed-alone test and the intermediate
assembly states refuse it; PyBullet (`physics_check.assemble`) is the oracle.
"""

from __future__ import annotations

import numpy as np
import pytest

from conftest import codes, of
from sdi.bench.stability_cases import cases
from sdi.design import compose
from sdi.execute.physics_check import assemble
from sdi.inspector import Analysis, Constraint, verify
from sdi.inspector.equilibrium import alone, robust, solve, solve_many
from sdi.model import CellConfig, Layout, Part
from sdi.pipeline import plan
from sdi.spec.structure_spec import Spec, structure

CASES = {c.name: c for c in cases()}


def _one_pillar_canopy() -> Layout:
    planned = plan("a canopy 1 high")
    assert planned.status == "success" and planned.layout is not None
    return Layout(objects=tuple(p for p in planned.layout.objects if p.id != "c1"))


def test_one_pillar_canopy_is_refused_with_the_missing_pillar_as_hint():
    lay = _one_pillar_canopy()
    r = verify(lay)
    assert not r.passed
    assert codes(r) == {"stability"}
    [v] = of(r, Constraint.STABILITY)
    assert v.objects[0] == "b1"
    assert "cannot hold it up" in v.message
    assert "add a part under b1 at (0.5, 0.25, 0.025)" in v.hint
    # The suggestion is the pillar that was removed: adding it back passes.
    at = v.suggestion["add_part_at"]
    fixed = Layout(objects=(*lay.objects, Part(id="new", position=tuple(at))))
    assert verify(fixed).passed


def test_the_centre_of_mass_test_alone_missed_it():
    from sdi.inspector.stability import find_toppling

    a = Analysis(_one_pillar_canopy(), CellConfig())
    assert find_toppling(a.graph, a.cell.tolerances.stability_margin) == []  # the old check
    assert solve(a.graph, 0.002).unbalanced == [a.layout.index["b1"]]  # the LP
    assert alone(a.graph, 0.002).tolist() == [a.layout.index["b1"]]


@pytest.mark.parametrize("name", sorted(n for n, c in CASES.items() if not c.stands))
def test_layouts_that_fall_are_refused_with_a_stability_hint(name):
    r = verify(CASES[name].layout, sequence=CASES[name].sequence)
    assert not r.passed
    stab = of(r, Constraint.STABILITY)
    assert stab, r.violations
    for v in stab:
        assert v.hint.strip()
        assert any(w in v.hint for w in ("add a part", "move", "place")), v.hint


@pytest.mark.parametrize("name", sorted(n for n, c in CASES.items() if c.stands))
def test_layouts_that_stand_pass(name):
    assert verify(CASES[name].layout, sequence=CASES[name].sequence).passed


@pytest.mark.parametrize(
    "shape", ["tower", "wall", "pyramid", "staircase", "bridge", "arch", "canopy", "castle"]
)
def test_generated_structures_still_pass(shape):
    assert verify(compose(Spec(structures=(structure(shape),)))).passed


def test_counterweight_order_matters():
    case = CASES["counterweight_after_the_load"]
    lay, bad = case.layout, list(case.sequence)
    r = verify(lay, sequence=bad)
    [v] = of(r, Constraint.STABILITY)
    assert "after step 3 (placing tip)" in v.message
    assert v.hint.startswith("place weight earlier (before tip)")
    assert not assemble(lay, bad).stands
    # Left to itself the Inspector puts the counterweight first; that order stands.
    r = verify(lay)
    assert r.passed
    assert r.sequence == ("p", "beam", "weight", "tip")
    assert assemble(lay, r.sequence).stands


def test_friction_only_widens_what_stands_and_groups_are_independent():
    lay = _one_pillar_canopy()
    a = Analysis(lay, CellConfig())
    b1 = a.layout.index["b1"]
    assert solve(a.graph, 0.002, friction=0.5).unbalanced == [b1]  # friction cannot save it
    good = Analysis(CASES["canopy"].layout, CellConfig())
    assert solve(good.graph, 0.002, friction=0.5).stands
    # One LP for several groups gives each group's own answer.
    everything = np.arange(len(lay))
    both = solve_many(a.graph, 0.002, [everything, np.array([0, 1, 2]), np.array([], int)])
    assert [e.stands for e in both] == [False, True, True]


def test_robust_parts():
    a = Analysis(CASES["bridge"].layout, CellConfig())
    assert robust(a.graph).all()  # the beam's two supports span it
    a = Analysis(CASES["cantilever_beam_2cm"].layout, CellConfig())
    assert not robust(a.graph)[a.layout.index["beam"]]


@pytest.mark.parametrize(
    "name",
    [
        "canopy",
        "canopy_one_pillar_removed",
        "cantilever_beam_5cm",
        "bridge",
        "counterweight_after_the_load",
        "counterweight_order_by_the_inspector",
    ],
)
def test_physics_agrees_with_the_inspector(name):
    case = CASES[name]
    r = verify(case.layout, sequence=case.sequence)
    stood = assemble(case.layout, r.sequence or case.layout.ids, seed=1)
    assert stood.stands == case.stands == r.passed, stood.to_json_dict()
