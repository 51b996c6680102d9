"""LLM fault suite: `sdi plan`/`sdi run --backend openai` against a real HTTP server on 127.0.0.1
that answers with scripted faults (tests/fault_server.py).

Every fault must end the same way: no crash, the bad reply counted (`malformed`, or `failures`
when nothing usable came back at all), the fallback to the grammar stated in the JSON
(`spec_source`, `notes`) and on stderr, and a sane exit code. Durations are not asserted here
(the machine is shared); the hang case only checks that the call gave up and fell back.
"""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from fault_server import INJECTION, FaultServer
from sdi import deadline
from sdi.cli import app
from sdi.llm import LLMError, OpenAIChat, parse_json

COMMAND = "a 3-cube tower at x = 0.4"
TOWER_SPEC = json.dumps({"structures": [{"shape": "tower", "height": 3, "at_x": 0.4}]})

MALFORMED = ["garbage", "empty_choices", "not_completion", "html", "deep"]
"""Replies that are not chat completions: the client counts them as malformed."""
UNUSABLE_CONTENT = {
    "deep_content": "ok",  # a completion whose content is JSON 90 000 levels deep
    "injection": "ok:" + INJECTION,
    "injection_json": "ok:"
    + json.dumps(
        {
            "structures": [{"shape": "tower", "height": 3, "at_x": 0.4}],
            "run": "__import__('os').system('touch /tmp/pwned')",
        }
    ),
}
"""Completions whose content is not a usable spec: the Specifier counts them as malformed."""


def invoke(*args: str, base_url: str, timeout: float = 5.0) -> tuple[int, str, str]:
    runner = CliRunner()
    result = runner.invoke(
        app,
        [*args, "--backend", "openai", "--llm-timeout", str(timeout)],
        env={"SDI_LLM_BASE_URL": base_url, "SDI_LLM_MODEL": "fault-model"},
        catch_exceptions=False,
    )
    return result.exit_code, result.stdout, result.stderr


def plan_json(base_url: str, timeout: float = 5.0) -> tuple[int, dict]:
    code, stdout, _ = invoke("plan", COMMAND, "--json", base_url=base_url, timeout=timeout)
    lines = [line for line in stdout.splitlines() if line.strip()]
    assert len(lines) == 1, stdout  # exactly one JSON object, whatever the endpoint did
    return code, json.loads(lines[0])


def assert_fell_back(data: dict, reason: str) -> None:
    assert data["status"] == "success"  # the grammar planned the tower
    assert data["spec_source"] == "grammar"
    assert [s["shape"] for s in data["spec"]["structures"]] == ["tower"]
    (note,) = data["notes"]
    assert note.startswith("the model's reply was unusable (") and "used the grammar" in note
    assert reason in note


@pytest.mark.parametrize("fault", MALFORMED)
def test_a_reply_that_is_not_a_completion_is_malformed_retried_then_the_grammar(fault):
    with FaultServer([fault]) as server:
        code, data = plan_json(server.base_url)
    assert code == 0
    assert_fell_back(data, "not a chat completion")
    assert "after 2 tries" in data["notes"][0]
    assert server.requests == 2  # one retry, then the fallback
    assert data["metrics"]["llm_malformed"] == 2 and data["metrics"]["llm_calls"] == 0


@pytest.mark.parametrize("fault", sorted(UNUSABLE_CONTENT))
def test_a_completion_without_a_usable_spec_is_malformed_then_the_grammar(fault):
    with FaultServer([UNUSABLE_CONTENT[fault]]) as server:
        code, data = plan_json(server.base_url)
    assert code == 0
    assert_fell_back(data, "not a")
    assert data["metrics"]["llm_malformed"] == 1 and data["metrics"]["llm_calls"] == 1
    # an injected instruction changes nothing: the tower stands where the command said
    assert {o["position"][0] for o in data["layout"]["objects"]} == {0.4}


def test_http_500_is_retried_then_stated():
    with FaultServer(["http500"]) as server:
        code, data = plan_json(server.base_url)
    assert code == 0
    assert_fell_back(data, "HTTP 500 after 2 tries")
    assert data["metrics"]["llm_failures"] == 1 and server.requests == 2


def test_a_hanging_endpoint_is_given_up_within_the_budget():
    with FaultServer(["hang"]) as server:
        code, data = plan_json(server.base_url, timeout=2.0)
    assert code == 0
    assert_fell_back(data, "no reply within 2 s")
    assert data["metrics"]["llm_failures"] == 1
    assert server.requests == 1  # the budget covers every try: no second wait


def test_an_unreachable_endpoint_is_stated():
    with FaultServer(["ok"]) as server:
        url = server.base_url  # a port that was just closed
    code, data = plan_json(url)
    assert code == 0
    assert_fell_back(data, "cannot connect after 2 tries")


def test_a_transient_fault_is_retried_and_the_model_used():
    with FaultServer(["http500", "ok:" + TOWER_SPEC]) as server:
        code, data = plan_json(server.base_url)
    assert code == 0 and data["status"] == "success"
    assert data["spec_source"] == "model" and data["notes"] == []
    assert data["metrics"]["llm_calls"] == 1 and server.requests == 2


def test_a_model_cannot_override_a_coordinate_the_command_states():
    reply = json.dumps({"structures": [{"shape": "tower", "height": 3, "at_x": 5.0}]})
    with FaultServer(["ok:" + reply]) as server:
        code, data = plan_json(server.base_url)
    assert code == 0 and data["spec_source"] == "grammar"  # the command says x = 0.4
    assert {o["position"][0] for o in data["layout"]["objects"]} == {0.4}
    assert any("at_x" in note and "5.0" in note for note in data["notes"])


def test_a_well_formed_spec_with_injected_coordinates_is_still_inspected():
    reply = json.dumps({"structures": [{"shape": "tower", "height": 3, "at_x": 5.0}]})
    with FaultServer(["ok:" + reply]) as server:
        code, stdout, _ = invoke("plan", "a 3-cube tower", "--json", base_url=server.base_url)
    data = json.loads(stdout)
    assert code == 1 and data["status"] == "failure"  # x = 5 m is outside the workspace
    assert data["spec_source"] == "model"


def test_the_text_view_states_the_fallback_on_stderr():
    with FaultServer(["http500"]) as server:
        code, stdout, stderr = invoke("plan", COMMAND, base_url=server.base_url)
    assert code == 0
    assert "HTTP 500 after 2 tries" in stderr and "used the grammar" in stderr
    assert "Traceback" not in stdout + stderr


def test_a_model_designer_on_garbage_fails_cleanly():
    with FaultServer(["garbage"]) as server:
        code, stdout, _ = invoke(
            "plan", COMMAND, "--json", "--method", "LLM-Direct", base_url=server.base_url
        )
    data = json.loads(stdout)
    assert code == 1 and data["status"] == "failure" and data["layout"] is None
    assert data["metrics"]["llm_malformed"] >= 1


@pytest.mark.parametrize("fault", ["http500", "garbage", "empty_choices", "html", "deep"])
def test_run_survives_every_fault(fault, tmp_path):
    with FaultServer([fault]) as server:
        code, stdout, _ = invoke(
            "run", COMMAND, "--json", "--db", str(tmp_path / "runs.db"), base_url=server.base_url
        )
    data = json.loads(stdout)
    assert code == 0 and data["status"] == "paused"  # at the design review, as without a model
    assert data["spec_source"] == "rules (llm malformed)"
    counted = data["usage"]["failures"] if fault == "http500" else data["usage"]["malformed"]
    assert counted >= 1


@pytest.mark.parametrize("value", ["0", "-3"])
def test_a_non_positive_llm_timeout_is_bad_input(value):
    url = "http://127.0.0.1:9/v1"
    code, stdout, _ = invoke("plan", COMMAND, "--json", base_url=url, timeout=float(value))
    assert code == 2 and "--llm-timeout" in json.loads(stdout)["error"]


def test_a_phase_limit_clips_the_budget_and_ends_the_phase():
    with FaultServer(["hang"]) as server:
        model = OpenAIChat(base_url=server.base_url, model="m", timeout=120.0)
        with deadline.phase_limit("design", 1.0), pytest.raises(deadline.PhaseTimeout):
            model.chat([{"role": "user", "content": "hi"}])
    assert server.requests == 1 and model.usage.failures == 1


def test_the_client_raises_only_llm_errors_with_a_short_reason():
    with FaultServer(["deep"]) as server:
        model = OpenAIChat(base_url=server.base_url, model="m", timeout=5.0, max_retries=0)
        with pytest.raises(LLMError) as info:
            model.chat([{"role": "user", "content": "hi"}])
    assert info.value.malformed
    assert info.value.reason == "not a chat completion: JSON nested too deep"
    assert model.usage.malformed == 1 and model.usage.failures == 1


def test_parse_json_refuses_deep_nesting_as_a_value_error():
    with pytest.raises(ValueError, match="too deep"):
        parse_json("[" * 90_000 + "]" * 90_000)


def test_every_wait_is_announced_with_what_it_waits_for():
    from contextlib import nullcontext

    said: list[str] = []

    def waiting(text: str):
        said.append(text)
        return nullcontext()

    with FaultServer(["http500", "ok:hi"]) as server:
        model = OpenAIChat(base_url=server.base_url, model="m", timeout=5.0, waiting=waiting)
        assert model.chat([{"role": "user", "content": "x"}], role="designer").content == "hi"
    assert len(said) == 2 and all("designer" in t and "127.0.0.1" in t for t in said)
    assert "try 1/2" in said[0] and "try 2/2" in said[1]


def _raw(message: object, **extra: object) -> str:
    return "raw:" + json.dumps({"choices": [{"index": 0, "message": message}], **extra})


@pytest.mark.parametrize(
    ("body", "content", "tools"),
    [
        (
            _raw({"content": [{"type": "text", "text": "a"}, {"type": "text", "text": "b"}]}),
            "ab",
            [],
        ),
        (
            _raw(
                {
                    "content": None,
                    "tool_calls": [{"id": "c1", "function": {"name": "f", "arguments": {"x": 1}}}],
                }
            ),
            None,
            [("c1", "f", '{"x": 1}')],
        ),
        (
            _raw({"content": "hi"}, usage={"prompt_tokens": "many", "completion_tokens": -1}),
            "hi",
            [],
        ),
    ],
)
def test_odd_but_usable_completions_are_read(body, content, tools):
    with FaultServer([body]) as server:
        model = OpenAIChat(base_url=server.base_url, model="m", timeout=5.0)
        reply = model.chat([{"role": "user", "content": "x"}])
    assert reply.content == content
    assert [(c.id, c.name, c.arguments) for c in reply.tool_calls] == tools
    assert reply.prompt_tokens == 0 and model.usage.malformed == 0


@pytest.mark.parametrize(
    "body",
    [
        _raw({"content": None}),
        _raw({"content": {"nested": True}}),
        _raw("a string"),
        "raw:" + json.dumps({"choices": {"0": {}}}),
        "raw:" + json.dumps([1, 2, 3]),
        "raw:null",
    ],
)
def test_replies_shaped_wrong_are_malformed(body):
    with FaultServer([body]) as server:
        model = OpenAIChat(base_url=server.base_url, model="m", timeout=5.0, max_retries=0)
        with pytest.raises(LLMError) as info:
            model.chat([{"role": "user", "content": "x"}])
    assert info.value.malformed and info.value.reason.startswith("not a chat completion")
    assert model.usage.malformed == 1
