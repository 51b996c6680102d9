"""The safety gate: nothing unverified reaches tasks, motion, a driver or an exporter."""

from __future__ import annotations

import dataclasses

import pytest

from sdi.commission import commission
from sdi.errors import UnverifiedPlanError
from sdi.execute import VerifiedJob
from sdi.model.layout import Layout
from sdi.model.part import Part
from sdi.tasks import TaskGenerator


def cube(pid: str, x: float, y: float, z: float) -> Part:
    return Part(id=pid, position=(x, y, z))


ADVERSARIAL = {
    "floating": Layout(objects=(cube("a", 0.4, 0.3, 0.2),)),
    "colliding": Layout(objects=(cube("a", 0.4, 0.3, 0.025), cube("b", 0.41, 0.3, 0.025))),
    "outside": Layout(objects=(cube("a", 1.2, 0.3, 0.025),)),
    "overhang": Layout(objects=(cube("a", 0.4, 0.3, 0.025), cube("b", 0.44, 0.3, 0.075))),
    "under the table": Layout(objects=(cube("a", 0.4, 0.3, -0.01),)),
}


@pytest.mark.parametrize("name", sorted(ADVERSARIAL))
def test_inspect_refuses(name):
    with pytest.raises(UnverifiedPlanError) as info:
        VerifiedJob.inspect(ADVERSARIAL[name])
    assert info.value.violations


@pytest.mark.parametrize("name", sorted(ADVERSARIAL))
def test_task_generation_and_commissioning_refuse(name):
    with pytest.raises(UnverifiedPlanError):
        TaskGenerator().generate(ADVERSARIAL[name])
    with pytest.raises(UnverifiedPlanError):
        commission(ADVERSARIAL[name])


def test_wrong_sequence_is_refused():
    tower = Layout(objects=tuple(cube(f"c{k}", 0.4, 0.3, 0.025 + 0.05 * k) for k in range(3)))
    VerifiedJob.inspect(tower)  # fine bottom-up
    with pytest.raises(UnverifiedPlanError):
        VerifiedJob.inspect(tower, sequence=["c2", "c1", "c0"])


def test_a_job_cannot_be_forged_or_altered():
    tower = Layout(objects=(cube("c0", 0.4, 0.3, 0.025),))
    job = VerifiedJob.inspect(tower)
    with pytest.raises(UnverifiedPlanError):
        VerifiedJob(job.layout, job.sequence, job.cell, job.report)
    # replacing the layout after inspection is caught by the re-check drivers run
    bad = object.__new__(VerifiedJob)
    for f in dataclasses.fields(VerifiedJob):
        object.__setattr__(bad, f.name, getattr(job, f.name))
    object.__setattr__(bad, "layout", ADVERSARIAL["floating"])
    object.__setattr__(bad, "sequence", ("a",))
    with pytest.raises(UnverifiedPlanError):
        bad.recheck()
