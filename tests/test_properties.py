"""Property tests: generators, the sequencer and the verifier on random input.

The verifier is checked against a naive all-pairs reference written here from the paper's
definitions (contact predicate eq. 5, collision C3, contact C4), independent of the k-d tree
and the vectorised code in `sdi.inspector`.
"""

from __future__ import annotations

import itertools
import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from sdi.design import compose
from sdi.design.shapes import FAMILIES
from sdi.errors import InfeasibleError, SequencingError
from sdi.inspector import Analysis, Constraint, check_collision, check_contact, sequence, verify
from sdi.model import CellConfig, Layout, ParallelGripper, Part, VacuumGripper, Workspace
from sdi.spec.structure_spec import STRUCTURE_TYPES, Spec, StructureSpec, structure

CELLS = {
    "default": CellConfig(),
    "parallel": CellConfig(grippers=(ParallelGripper(),)),
    "vacuum": CellConfig(grippers=(VacuumGripper(),)),
    "small": CellConfig(workspace=Workspace(x_min=0.3, x_max=0.6, y_min=0.1, y_max=0.4, z_max=0.3)),
}
REGIONS = sorted(CellConfig().design.regions)
ORDER = {Constraint.GRAVITY, Constraint.SEQUENCE, Constraint.GRIPPING}
EPS = CellConfig().tolerances.contact

FAST = settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])


# --------------------------------------------------------------------------------------------
# strategies


def opt(strategy: st.SearchStrategy) -> st.SearchStrategy:
    return st.one_of(st.none(), strategy)


@st.composite
def structure_specs(
    draw, yaw: st.SearchStrategy | None = None, shape: st.SearchStrategy | None = None
) -> StructureSpec:
    """A single structure with random in-range parameters, axis and placement."""
    count = st.integers(1, 12)
    kwargs: dict[str, object] = {
        "shape": draw(shape if shape is not None else st.sampled_from(sorted(FAMILIES))),
        "count": draw(opt(count)),
        "length": draw(opt(count)),
        "width": draw(opt(count)),
        "height": draw(opt(count)),
        "steps": draw(opt(count)),
        "span": draw(opt(st.integers(1, 6))),
        "spans": draw(opt(st.integers(1, 4))),
        "dims": draw(opt(st.sampled_from([2, 3]))),
        "axis": draw(opt(st.sampled_from(["x", "y"]))),
        "gap_m": draw(opt(st.sampled_from([0.0, 0.005, 0.014, 0.02, 0.05]))),
        "yaw_deg": draw(yaw if yaw is not None else st.sampled_from([0.0, 90.0, 180.0, -90.0])),
    }
    where = draw(st.sampled_from(["none", "region", "at"]))
    if where == "region":
        kwargs["region"] = draw(st.sampled_from(REGIONS))
    elif where == "at":
        kwargs["at_x"] = draw(st.floats(0.15, 0.85, allow_nan=False).map(lambda v: round(v, 3)))
        kwargs["at_y"] = draw(st.floats(0.0, 0.6, allow_nan=False).map(lambda v: round(v, 3)))
    # only the family's own slots: a value it cannot use is refused (test_language)
    fields = STRUCTURE_TYPES[str(kwargs["shape"])].model_fields
    return structure(**{k: v for k, v in kwargs.items() if k in fields})


def generate_or_refuse(spec: Spec, cell: CellConfig) -> Layout | None:
    """The generator contract: a layout that verifies, or InfeasibleError naming a parameter."""
    try:
        lay = compose(spec, cell)
    except InfeasibleError as exc:
        assert exc.parameter, f"InfeasibleError without a parameter: {exc}"
        assert exc.parameter in str(exc), exc
        return None
    report = verify(lay, cell, precedence=spec.precedence)
    assert report.passed, (spec.describe(), [v.message for v in report.violations[:5]])
    assert report.sequence is not None and sorted(report.sequence) == sorted(lay.ids)
    return lay


def quaternions() -> st.SearchStrategy:
    def yaw(a: float) -> tuple[float, float, float, float]:
        return (math.cos(a / 2), 0.0, 0.0, math.sin(a / 2))

    def unit(v: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        n = math.sqrt(sum(x * x for x in v))
        return tuple(x / n for x in v)  # type: ignore[return-value]

    comp = st.floats(-1, 1, allow_nan=False)
    return st.one_of(
        st.just((1.0, 0.0, 0.0, 0.0)),
        st.sampled_from([0.5, 1.0, 1.5]).map(lambda k: yaw(k * math.pi)),
        st.floats(-math.pi, math.pi).map(yaw),
        st.tuples(comp, comp, comp, comp).filter(lambda v: sum(x * x for x in v) > 0.01).map(unit),
    )


@st.composite
def random_layouts(draw) -> Layout:
    """Random boxes: on a coarse grid (touching, stacked, overlapping) or anywhere, any size,
    some rotated; inside and outside the workspace, on the table, floating or below it."""
    n = draw(st.integers(0, 24))
    on_grid = draw(st.booleans())
    parts = []
    for i in range(n):
        if on_grid:
            # Grid points with a jitter of a fraction of ε: faces touch, overlap or gap by
            # amounts just inside and just outside the tolerance (never exactly on it).
            jitter = st.sampled_from([0.0, 0.0, 0.0, 0.0004, -0.0004, 0.0013, -0.0013])
            pos = (
                0.30 + 0.025 * draw(st.integers(0, 16)) + draw(jitter),
                0.15 + 0.025 * draw(st.integers(0, 12)) + draw(jitter),
                0.025 * draw(st.integers(0, 8)) + draw(jitter),
            )
            size = tuple(
                draw(st.sampled_from([0.025, 0.05, 0.05, 0.05, 0.1, 0.15])) for _ in range(3)
            )
        else:
            pos = (
                draw(st.floats(-0.2, 1.2, allow_nan=False)),
                draw(st.floats(-0.2, 0.8, allow_nan=False)),
                draw(st.floats(-0.1, 0.7, allow_nan=False)),
            )
            size = tuple(draw(st.floats(0.005, 0.4, allow_nan=False)) for _ in range(3))
        q = draw(st.one_of(st.just((1.0, 0.0, 0.0, 0.0)), quaternions()))
        parts.append(Part(id=f"p{i}", position=pos, size=size, orientation=q))
    return Layout(objects=tuple(parts))


# --------------------------------------------------------------------------------------------
# generators


@FAST
@given(spec=structure_specs(), cell_name=st.sampled_from(["default", "vacuum", "small"]))
def test_every_generator_output_verifies_or_names_a_parameter(spec, cell_name):
    generate_or_refuse(Spec(structures=(spec,)), CELLS[cell_name])


@pytest.mark.parametrize("shape", sorted(FAMILIES))
@settings(max_examples=8, deadline=None)
@given(data=st.data())
def test_each_family_verifies_or_names_a_parameter(shape, data):
    spec = data.draw(structure_specs(shape=st.just(shape)))
    generate_or_refuse(Spec(structures=(spec,)), CELLS["default"])


@settings(max_examples=30, deadline=None)
@given(spec=structure_specs(yaw=st.floats(-360, 360, allow_nan=False)))
def test_generator_output_with_any_in_range_yaw_verifies_or_names_a_parameter(spec):
    generate_or_refuse(Spec(structures=(spec,)), CELLS["default"])


@settings(max_examples=30, deadline=None)
@given(specs=st.lists(structure_specs(), min_size=2, max_size=3))
def test_several_structures_verify_or_name_a_parameter(specs):
    generate_or_refuse(Spec(structures=tuple(specs)), CELLS["default"])


# --------------------------------------------------------------------------------------------
# sequencer


def replays_cleanly(lay: Layout, cell: CellConfig) -> None:
    """A sequence the sequencer returns has no gravity, sequence or gripping violation."""
    try:
        order = sequence(Analysis(lay, cell))
    except SequencingError as exc:
        assert exc.blocked and set(exc.blocked) <= set(lay.ids)
        assert verify(lay, cell).sequence is None
        return
    assert sorted(order) == sorted(lay.ids)
    replay = verify(lay, cell, sequence=order)
    bad = [v.message for v in replay.violations if v.constraint in ORDER]
    assert not bad, bad
    # and it is the order verify itself would choose
    assert verify(lay, cell).sequence == tuple(order)


@FAST
@given(spec=structure_specs(), cell_name=st.sampled_from(["default", "parallel", "vacuum"]))
def test_sequencer_output_replays_on_generated_layouts(spec, cell_name):
    try:
        lay = compose(Spec(structures=(spec,)))
    except InfeasibleError:
        assume(False)
        return
    replays_cleanly(lay, CELLS[cell_name])


@FAST
@given(lay=random_layouts(), cell_name=st.sampled_from(["default", "parallel"]))
def test_sequencer_output_replays_on_random_layouts(lay, cell_name):
    replays_cleanly(lay, CELLS[cell_name])


# --------------------------------------------------------------------------------------------
# verifier on random layouts


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lay=random_layouts(), cell_name=st.sampled_from(["default", "parallel", "small"]))
def test_verify_never_crashes_and_is_consistent(lay, cell_name):
    cell = CELLS[cell_name]
    r = verify(lay, cell)
    assert r.passed == (len(r.violations) == 0)
    ids = set(lay.ids)
    for v in r.violations:
        assert isinstance(v.constraint, Constraint)
        assert v.objects and set(v.objects) <= ids
        assert v.message and v.hint
    if r.passed:
        assert r.sequence is not None
    if r.sequence is not None:
        assert sorted(r.sequence) == sorted(lay.ids)
        again = verify(lay, cell, sequence=list(r.sequence))
        # The same order checked explicitly gives the same geometry verdict and no order error.
        assert not [v for v in again.violations if v.constraint in ORDER]
        assert {(v.constraint, v.objects) for v in again.violations} == {
            (v.constraint, v.objects) for v in r.violations
        }


def reference_half_extents(p: Part) -> list[float]:
    """World AABB half extents from the rotation matrix, written out by hand."""
    w, x, y, z = p.orientation
    rot = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    return [sum(abs(rot[r][c]) * p.size[c] / 2 for c in range(3)) for r in range(3)]


AMBIGUOUS = 1e-9
"""Pairs whose gap is this close to a threshold are left out: float order may differ there."""


def reference(lay: Layout, eps: float) -> tuple[set[frozenset[str]], set[str], set[frozenset[str]]]:
    """Naive O(N²): colliding pairs, parts breaking paper C4, and pairs too close to call."""
    parts = list(lay)
    half = [reference_half_extents(p) for p in parts]
    colliding: set[frozenset[str]] = set()
    touching: set[int] = set()
    unsure: set[frozenset[str]] = set()
    for i, j in itertools.combinations(range(len(parts)), 2):
        gaps = [
            abs(parts[i].position[d] - parts[j].position[d]) - (half[i][d] + half[j][d])
            for d in range(3)
        ]
        pair = frozenset((parts[i].id, parts[j].id))
        if any(abs(g + eps) < AMBIGUOUS or abs(g - eps) < AMBIGUOUS for g in gaps):
            unsure.add(pair)
        if all(g < -eps for g in gaps):
            colliding.add(pair)
        if all(g <= eps for g in gaps):
            touching |= {i, j}
    floating = {
        p.id
        for k, p in enumerate(parts)
        if abs(p.position[2] - half[k][2]) > eps and k not in touching
    }
    return colliding, floating, unsure


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lay=random_layouts())
def test_collisions_and_contact_agree_with_a_naive_reference(lay):
    cell = CELLS["default"]
    a = Analysis(lay, cell)
    colliding, floating, unsure = reference(lay, cell.tolerances.contact)
    assume(not unsure)
    found = [frozenset(v.objects) for v in check_collision(a)]
    assert len(found) == len(set(found)), "a pair is reported twice"
    assert set(found) == colliding
    assert {v.objects[0] for v in check_contact(a)} == floating
    # the composite report says the same
    r = verify(lay, cell)
    assert {
        frozenset(v.objects) for v in r.violations if v.constraint == Constraint.COLLISION
    } == colliding
    assert {v.objects[0] for v in r.violations if v.constraint == Constraint.CONTACT} == floating


@settings(max_examples=40, deadline=None)
@given(
    n=st.integers(2, 30),
    reach=st.floats(0.01, 0.6),
    big=st.floats(0.05, 0.6),
)
def test_reference_agreement_with_one_large_part_among_small_ones(n, reach, big):
    # The candidate search must use the largest part's reach, not a typical one.
    small = [
        Part(
            id=f"s{k}",
            position=(0.2 + (k % 6) * 0.11, 0.1 + (k // 6) * 0.11, 0.025),
            size=(0.02, 0.02, 0.05),
        )
        for k in range(n)
    ]
    plank = Part(id="plank", position=(0.5, 0.3, 0.025 + reach / 10), size=(big, big, 0.05))
    lay = Layout(objects=(*small, plank))
    colliding, floating, unsure = reference(lay, EPS)
    assume(not unsure)
    a = Analysis(lay, CELLS["default"])
    assert {frozenset(v.objects) for v in check_collision(a)} == colliding
    assert {v.objects[0] for v in check_contact(a)} == floating
