"""The Inspector on layouts that fail everywhere: grip blockers from the grid hash agree with a
brute-force all-pairs reference, the stuck sequencer names every part with its blockers, and a
report's JSON lists at most 50 violations per constraint plus one summary.

The reference is written here from the definition (a part j blocks option o of part i when j's
box reaches more than ε into a keep-out box of o, on every axis), over all N² pairs.
"""

from __future__ import annotations

import itertools
import json
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from sdi.errors import SequencingError
from sdi.inspector import Analysis, Constraint, sequence, verify
from sdi.inspector.box_index import overlapping
from sdi.inspector.gripping import GripModel, _keep_out
from sdi.inspector.sequencer import disassemble
from sdi.inspector.verifier import MAX_PER_CONSTRAINT, cap_violations
from sdi.model import CellConfig, Layout, ParallelGripper, Part, VacuumGripper, Workspace
from sdi.model.cell import Limits

EPS = CellConfig().tolerances.contact
BIG = CellConfig(
    workspace=Workspace(x_min=0.0, x_max=10.0, y_min=0.0, y_max=10.0, z_max=1.0),
    limits=Limits(max_parts=20_000),
)
CELLS = {
    "default": CellConfig(),
    "parallel": CellConfig(grippers=(ParallelGripper(),)),
    "vacuum": CellConfig(grippers=(VacuumGripper(),)),
}


def reference_blocks(lay: Layout, cell: CellConfig) -> set[tuple[int, int, int]]:
    """All (i, o, j) over all pairs, from the keep-out boxes and the overlap definition."""
    c, h = lay.centres, lay.half_extents
    options = [
        (g, axis)
        for g in cell.grippers
        for axis in ((None,) if isinstance(g, VacuumGripper) else (0, 1))
    ]
    boxes = [_keep_out(lay, g, axis, EPS)[0] for g, axis in options]
    floor = np.min([b[:, :, 4].min(axis=1) for b in boxes], axis=0)
    out = set()
    for i, j in itertools.permutations(range(len(lay)), 2):
        if not c[j, 2] + h[j, 2] > floor[i] + EPS:
            continue
        for o, b in enumerate(boxes):
            for box in b[i]:
                if all(
                    min(box[2 * d + 1], c[j, d] + h[j, d]) - max(box[2 * d], c[j, d] - h[j, d])
                    > EPS
                    for d in range(3)
                ):
                    out.add((i, o, j))
    return out


@st.composite
def packed_layouts(draw) -> Layout:
    """Up to 14 boxes on a coarse grid (so faces touch, tops line up, parts overlap), of sizes
    from too small for the vacuum to too wide for the fingers."""
    n = draw(st.integers(1, 14))
    step = draw(st.sampled_from([0.005, 0.01, 0.025]))
    sizes = st.sampled_from([0.01, 0.02, 0.03, 0.05, 0.08, 0.15])
    parts = []
    for k in range(n):
        size = (draw(sizes), draw(sizes), draw(sizes))
        x, y, z = (draw(st.integers(0, 12)) * step for _ in range(3))
        parts.append(Part(id=f"p{k}", position=(0.3 + x, 0.2 + y, size[2] / 2 + z), size=size))
    return Layout(objects=tuple(parts))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(lay=packed_layouts(), cell_name=st.sampled_from(sorted(CELLS)))
def test_blockers_agree_with_the_all_pairs_reference(lay, cell_name):
    cell = CELLS[cell_name]
    grip = GripModel(lay, cell.grippers, EPS)
    rows = [tuple(r) for r in grip.blocks.tolist()]
    assert rows == sorted(set(rows)), "rows are unique and sorted by (part, option, blocker)"
    assert set(rows) == reference_blocks(lay, cell)
    for i in range(len(lay)):  # the per-part index is the same relation
        assert grip.rows_of(i).tolist() == [list(r) for r in rows if r[0] == i]


@settings(max_examples=150, deadline=None)
@given(
    boxes=st.lists(
        st.tuples(
            st.tuples(*[st.integers(0, 20)] * 3),
            st.tuples(*[st.integers(1, 8)] * 3),
            st.booleans(),
        ),
        min_size=1,
        max_size=25,
    ),
    items=st.lists(
        st.tuples(st.tuples(*[st.integers(0, 20)] * 3), st.tuples(*[st.integers(1, 6)] * 3)),
        min_size=1,
        max_size=25,
    ),
)
def test_box_overlaps_agree_with_all_pairs(boxes, items):
    unit = 0.005  # on a grid, so many boxes touch exactly or overlap by exactly ε
    q_lo = np.array([lo for lo, _, _ in boxes], dtype=float) * unit
    q_hi = q_lo + np.array([size for _, size, _ in boxes], dtype=float) * unit
    q_hi[:, 2] = np.where([up for _, _, up in boxes], math.inf, q_hi[:, 2])
    i_lo = np.array([lo for lo, _ in items], dtype=float) * unit
    i_hi = i_lo + np.array([size for _, size in items], dtype=float) * unit
    eps = unit / 5
    q, k = overlapping(q_lo, q_hi, i_lo, i_hi, eps)
    found = list(zip(q.tolist(), k.tolist(), strict=True))
    assert len(found) == len(set(found)), "a pair is reported twice"
    expected = {
        (a, b)
        for a in range(len(q_lo))
        for b in range(len(i_lo))
        if np.all(np.minimum(q_hi[a], i_hi[b]) - np.maximum(q_lo[a], i_lo[b]) > eps)
    }
    assert set(found) == expected


def ungrippable_field(n: int, edge: float = 0.01) -> Layout:
    """`n` cubes too small for the vacuum, packed edge to edge so the fingers cannot go in."""
    nx = math.ceil(math.sqrt(n))
    return Layout(
        objects=tuple(
            Part(
                id=f"u{k}",
                position=(0.1 + edge * (k // nx), 0.1 + edge * (k % nx), edge / 2),
                size=(edge, edge, edge),
            )
            for k in range(n)
        )
    )


@pytest.mark.parametrize("edge", [0.01, 0.03])
def test_a_dense_ungrippable_field_names_every_part_and_caps_its_json(edge):
    n = 400
    lay = ungrippable_field(n, edge)
    report = verify(lay, BIG)
    assert not report.passed and report.sequence is None
    assert report.by_constraint() == {"gripping": n}  # the report keeps every violation
    data = report.to_json_dict()
    json.dumps(data)
    listed = data["violations"]
    assert len(listed) == MAX_PER_CONSTRAINT + 1 and data["omitted"] == {"gripping": n - 50}
    summary = listed[-1]
    assert summary["constraint"] == "gripping" and "350 more gripping" in summary["message"]
    assert summary["objects"] and set(summary["objects"]) <= set(lay.ids)
    with pytest.raises(SequencingError) as info:
        sequence(Analysis(lay, BIG))
    assert sorted(info.value.blocked) == sorted(lay.ids)


def test_the_stuck_sequencer_lists_each_parts_blockers_like_a_scan():
    lay = ungrippable_field(144)
    a = Analysis(lay, BIG)
    order, stuck = disassemble(a)
    assert order == [] and stuck is not None and not stuck.waiting
    b, fits = a.grip.blocks, a.grip.fits
    for i, blockers in stuck.ungrippable.items():
        rows = b[(b[:, 0] == i) & fits[i, b[:, 1]]]
        assert blockers == sorted(set(rows[:, 2].tolist())) and blockers


def test_cap_keeps_short_lists_whole_and_summarises_long_ones():
    report = verify(ungrippable_field(60), BIG)
    whole, omitted = cap_violations(report.violations, None)
    assert len(whole) == 60 and omitted == {}
    capped, omitted = cap_violations(report.violations, 10)
    assert omitted == {"gripping": 50} and len(capped) == 11
    assert capped[:10] == list(report.violations[:10])
    assert capped[-1].constraint == Constraint.GRIPPING and len(capped[-1].objects) <= 10
    assert report.to_json_dict(limit=None)["violations"] == [
        v.to_json_dict() for v in report.violations
    ]
