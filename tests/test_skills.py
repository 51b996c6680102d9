"""Skill registry (§III-B): schemas, validation-before-dispatch, failures as data."""

from __future__ import annotations

import json

import pytest

from sdi.skills import SkillRegistry, SkillResult, default_registry


@pytest.fixture(scope="module")
def registry() -> SkillRegistry:
    return default_registry()


REQUIRED = [
    "verify", "check_workspace", "check_gravity", "check_gripping", "check_collision",
    "sequence", "flatten", "shift",
]  # fmt: skip
FAMILIES = [
    "tower", "row", "grid", "wall", "block", "pyramid", "staircase", "bridge", "arch",
    "canopy", "enclosure", "l_shape", "u_shape", "t_shape", "castle",
]  # fmt: skip


def test_required_skills_and_generators_are_registered(registry):
    for name in REQUIRED + [f"generate_{f}" for f in FAMILIES]:
        assert name in registry


def test_tools_are_openai_function_schemas(registry):
    tools = registry.tools()
    assert len(tools) == len(registry.names)
    for tool in tools:
        assert tool["type"] == "function"
        fn = tool["function"]
        assert fn["name"] in registry and fn["description"]
        assert fn["parameters"]["type"] == "object"
        json.dumps(tool)  # serialisable


def test_generator_skill_returns_a_verified_layout(registry):
    result = registry.dispatch("generate_staircase", {"steps": 4, "region": "left"})
    assert result.status == "success", result.errors
    assert result.data["passed"] is True
    assert len(result.data["layout"]["objects"]) == 10
    assert len(result.data["sequence"]) == 10


@pytest.mark.parametrize(
    ("name", "arguments", "needle"),
    [
        ("no_such_tool", {}, "unknown tool"),
        ("generate_tower", "{not json", "not valid JSON"),
        ("generate_tower", "[1, 2]", "JSON object"),
        ("generate_tower", {"height": 0}, "height"),
        ("generate_tower", {"hieght": 3}, "hieght"),
        ("verify", {"layout": {"objects": [{"id": "a", "position": [0, 0]}]}}, "position"),
        ("verify", {}, "layout"),
        ("generate_tower", {"height": 40}, "height"),
        ("generate_bridge", {"span": 5}, "span"),
    ],
)
def test_bad_calls_are_failures_not_exceptions(registry, name, arguments, needle):
    result = registry.dispatch(name, arguments)
    assert isinstance(result, SkillResult)
    assert result.status == "failure"
    assert any(needle in e for e in result.errors), result.errors


def test_result_serialises_for_a_tool_message(registry):
    text = registry.dispatch("generate_tower", {"height": 2}).to_json()
    data = json.loads(text)
    assert set(data) == {"status", "data", "errors"}


def _tower(registry, **kw):
    return registry.dispatch("generate_tower", {"height": 4, **kw}).data["layout"]


def test_granular_checks_only_report_their_constraint(registry):
    layout = _tower(registry)
    layout["objects"][3]["position"][0] = 1.2  # top cube out of the workspace, and floating
    ws = registry.dispatch("check_workspace", {"layout": layout})
    col = registry.dispatch("check_collision", {"layout": layout})
    grav = registry.dispatch("check_gravity", {"layout": layout})
    assert ws.status == "failure" and {v["constraint"] for v in ws.data["violations"]} == {
        "workspace"
    }
    assert col.status == "success"
    assert grav.status == "failure"
    assert {v["constraint"] for v in grav.data["violations"]} <= {"contact", "support", "stability"}


def test_sequence_skill_and_reversed_order(registry):
    layout = _tower(registry)
    result = registry.dispatch("sequence", {"layout": layout})
    assert result.status == "success"
    order = result.data["sequence"]
    bad = registry.dispatch("verify", {"layout": layout, "sequence": order[::-1]})
    assert bad.status == "failure"
    assert {v["constraint"] for v in bad.data["violations"]} >= {"sequence"}


def test_recovery_skills(registry):
    layout = _tower(registry, height=6)
    flat = registry.dispatch("flatten", {"layout": layout, "z_max": 0.15})
    assert flat.status == "success", flat.errors
    assert (
        max(o["position"][2] + o["size"][2] / 2 for o in flat.data["layout"]["objects"])
        <= 0.15 + 1e-9
    )
    moved = registry.dispatch("shift", {"layout": layout, "blocked": [{"x_max": 0.5}]})
    assert moved.status == "success", moved.errors
    assert min(o["position"][0] - 0.025 for o in moved.data["layout"]["objects"]) >= 0.5 - 1e-9


def test_subset_registry(registry):
    sass = registry.subset(["verify"])
    assert sass.names == ["verify"]
    with pytest.raises(KeyError):
        registry.subset(["verify", "nope"])
