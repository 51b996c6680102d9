"""`sdi plan --method/--backend`: every method runs offline; bad choices are bad input."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

from sdi.orchestrator import METHODS
from sdi.pipeline import plan_with

SDI = [sys.executable, "-m", "sdi.cli"]


@pytest.mark.parametrize("method", sorted(METHODS))
def test_every_method_plans_offline_with_the_rules_backend(method):
    result = plan_with("a 3-cube tower at x = 0.4", method, None)
    assert result.status == "success" and result.llm_calls == 0
    assert len(result.layout) == 3


def test_cli_method_and_backend_choices():
    ok = subprocess.run(
        [*SDI, "plan", "a small bridge", "--method", "SAMS", "--json"],
        capture_output=True,
        text=True,
    )
    assert ok.returncode == 0 and json.loads(ok.stdout)["metrics"]["llm_calls"] == 0
    bad = subprocess.run(
        [*SDI, "plan", "a tower", "--method", "Magic"], capture_output=True, text=True
    )
    assert bad.returncode == 2 and "Hybrid" in bad.stderr
    bad = subprocess.run(
        [*SDI, "plan", "a tower", "--backend", "gpt9"], capture_output=True, text=True
    )
    assert bad.returncode == 2 and "rules, local or openai" in bad.stderr


def test_unreachable_endpoint_is_a_clear_failure_not_a_crash():
    env = {**os.environ, "SDI_LLM_BASE_URL": "http://127.0.0.1:9/v1", "OPENAI_API_KEY": "x"}
    proc = subprocess.run(
        [*SDI, "plan", "a 3-cube tower", "--backend", "openai", "--method", "LLM-AdaptLoop",
         "--json"],
        capture_output=True, text=True, env=env, timeout=300,
    )  # fmt: skip
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    data = json.loads(proc.stdout)
    assert data["status"] == "failure" and "openai" in data["error"]
