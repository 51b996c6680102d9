"""Phase wall-clock limits: cooperative checks, clipped LLM timeouts, nothing outside a phase."""

from __future__ import annotations

import time

import pytest

from sdi import deadline


def test_no_limit_outside_a_phase():
    assert deadline.remaining() is None
    deadline.check()  # never raises


def test_limit_is_enforced_and_restored():
    with deadline.phase_limit("design", 0.05):
        left = deadline.remaining()
        assert left is not None and 0 < left <= 0.05
        deadline.check()
        time.sleep(0.06)
        with pytest.raises(deadline.PhaseTimeout, match=r"design.*0.05 s"):
            deadline.check()
    assert deadline.remaining() is None


def test_nested_phase_uses_the_inner_limit_then_the_outer():
    with deadline.phase_limit("execute", 100.0):
        with deadline.phase_limit("design", 1.0):
            assert deadline.remaining() <= 1.0
        assert deadline.remaining() > 1.0


def test_an_llm_call_is_not_started_after_the_limit():
    from sdi.llm import OpenAIChat

    model = OpenAIChat(base_url="http://127.0.0.1:9/v1", model="m", max_retries=0)
    with deadline.phase_limit("design", 0.01):
        time.sleep(0.02)
        with pytest.raises(deadline.PhaseTimeout):
            model.chat([{"role": "user", "content": "hi"}])
    assert model.usage.calls == 0


def test_execution_is_allowed_its_plan_duration_on_top_of_the_phase_limit():
    from sdi.model.cell import CellConfig, Limits
    from sdi.orchestrator.graph import phase_seconds

    cell = CellConfig(limits=Limits(phase_seconds=300))
    planned = {"planning": {"makespan_s": 600.0}}
    assert phase_seconds("design", planned, cell) == 300
    assert phase_seconds("execute", planned, cell) == 300 + 2 * 600
    assert phase_seconds("execute", {}, cell) == 300  # nothing planned yet
