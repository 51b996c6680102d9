"""The safety gate: nothing unverified reaches tasks, motion, a driver or an exporter."""

from __future__ import annotations

import dataclasses

import pytest

from sdi.commission import commission
from sdi.errors import UnverifiedPlanError
from sdi.execute import VerifiedJob
from sdi.inspector import Violation
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
    error = info.value
    assert error.violations and all(isinstance(v, Violation) for v in error.violations)
    assert error.report is not None and error.violations == error.report.violations
    for v, d in zip(error.violations, error.violations_json(), strict=True):
        assert d["objects"] == list(v.objects) and d["hint"] == v.hint and v.objects


def forged(job: VerifiedJob, **changes: object) -> VerifiedJob:
    """A job assembled by hand: the fields of `job`, some replaced, never through `inspect`."""
    bad = object.__new__(VerifiedJob)
    for f in dataclasses.fields(VerifiedJob):
        object.__setattr__(bad, f.name, changes.get(f.name, getattr(job, f.name)))
    return bad


@pytest.mark.parametrize("name", sorted(ADVERSARIAL))
def test_task_generation_and_commissioning_refuse(name):
    with pytest.raises(UnverifiedPlanError):
        commission(ADVERSARIAL[name])
    # the stages take a job; a forged one holding an unverified layout is refused by all
    genuine = VerifiedJob.inspect(Layout(objects=(cube("a", 0.4, 0.3, 0.025),)))
    bad = forged(genuine, layout=ADVERSARIAL[name], sequence=ADVERSARIAL[name].ids)
    with pytest.raises(UnverifiedPlanError):
        TaskGenerator(arms=["irb120"]).generate(bad)
    with pytest.raises(UnverifiedPlanError):
        commission(bad, arms=["irb120"])


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
    job.check()  # the genuine job passes the identity check
    # replacing the layout after inspection is caught by the identity check every stage runs
    bad = forged(job, layout=ADVERSARIAL["floating"], sequence=("a",))
    with pytest.raises(UnverifiedPlanError):
        bad.check()
    # so is a forged hash claiming content the Inspector never passed
    bad = forged(job, layout=ADVERSARIAL["floating"], sequence=("a",), hash=bad.content_hash())
    with pytest.raises(UnverifiedPlanError):
        bad.check()
    # and altering a genuine job in place
    altered = forged(job)
    object.__setattr__(altered, "layout", ADVERSARIAL["outside"])
    with pytest.raises(UnverifiedPlanError):
        altered.check()


def test_drivers_and_exporters_refuse_a_forged_job():
    """Nothing moves or is exported unless the job came from `VerifiedJob.inspect`."""
    from sdi.execute import SimDriver
    from sdi.export import python_program, rapid_module

    plan = commission(Layout(objects=(cube("c0", 0.4, 0.3, 0.025),)), arms=["irb120"])
    bad = forged(plan.job, layout=ADVERSARIAL["under the table"], sequence=("a",))
    robot = plan.robots["irb120"]
    with pytest.raises(UnverifiedPlanError):
        SimDriver(plan.robots).execute(bad, plan.tasks, plan.motion)
    with pytest.raises(UnverifiedPlanError):
        rapid_module(bad, plan.tasks, plan.motion, robot)
    with pytest.raises(UnverifiedPlanError):
        python_program(bad, plan.tasks, plan.motion, plan.robots)
    # the genuine job with a task plan that is not its own is refused too
    other = commission(
        Layout(objects=(cube("x", 0.4, 0.3, 0.025), cube("y", 0.4, 0.3, 0.075))), arms=["irb120"]
    )
    with pytest.raises(UnverifiedPlanError):
        rapid_module(plan.job, other.tasks, other.motion, robot)
    with pytest.raises(UnverifiedPlanError):
        SimDriver(plan.robots).execute(plan.job, other.tasks, other.motion)
