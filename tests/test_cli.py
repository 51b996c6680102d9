"""The `sdi` command line, run as a real subprocess: JSON contract, exit codes, bad input."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

SDI = [sys.executable, "-m", "sdi.cli"]


def run(*args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*SDI, *args],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, **(env or {})},
    )


def plan_json(command: str) -> tuple[int, dict]:
    proc = run("plan", command, "--json")
    lines = [line for line in proc.stdout.splitlines() if line.strip()]
    assert len(lines) == 1, proc.stdout  # exactly one JSON object
    return proc.returncode, json.loads(lines[0])


def test_plan_json_contract_on_success():
    code, data = plan_json("build a 3-cube tower at x = 0.4")
    assert code == 0
    assert set(data) >= {"status", "command", "spec", "layout", "sequence", "violations", "metrics"}
    assert data["status"] == "success" and data["violations"] == []
    objects = data["layout"]["objects"]
    assert len(objects) == 3
    for o in objects:
        assert set(o) == {"id", "position", "orientation", "size"}
        assert o["position"][0] == pytest.approx(0.4)
    assert sorted(data["sequence"]) == sorted(o["id"] for o in objects)
    zs = {o["id"]: o["position"][2] for o in objects}
    assert [zs[i] for i in data["sequence"]] == sorted(zs.values())
    assert set(data["metrics"]) >= {"seconds", "llm_calls"} and data["metrics"]["llm_calls"] == 0


def test_plan_infeasible_is_exit_1_with_parameter():
    code, data = plan_json("a tower of 30 cubes")
    assert code == 1 and data["status"] == "failure"
    assert data["error"].startswith("height")


@pytest.mark.parametrize("command", ["", "blah blah", "please do it"])
def test_plan_unintelligible_is_exit_2(command):
    code, data = plan_json(command)
    assert code == 2 and data["status"] == "error" and data["error"]


def test_plan_rich_output_and_out_file(tmp_path: Path):
    out = tmp_path / "plan.json"
    proc = run("plan", "a small bridge", "--out", str(out))
    assert proc.returncode == 0
    assert "success" in proc.stdout and "sequence" in proc.stdout
    saved = json.loads(out.read_text())
    assert saved["status"] == "success"
    # verify the saved plan (layout + sequence) round-trips
    check = run("verify", str(out), "--json")
    assert check.returncode == 0 and json.loads(check.stdout)["passed"] is True


def test_failed_plan_writes_nothing(tmp_path: Path):
    out = tmp_path / "plan.json"
    proc = run("plan", "a tower of 30 cubes", "--out", str(out))
    assert proc.returncode == 1 and not out.exists()


def write(tmp_path: Path, text: str) -> str:
    path = tmp_path / "layout.json"
    path.write_text(text)
    return str(path)


GOOD = {"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], "size": [0.05, 0.05, 0.05]}]}


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        ("{not json", "not valid JSON"),
        ('{"objects": [{"id": "a", "position": [NaN, 0.3, 0.025]}]}', "NaN"),
        ('{"objects": [{"id": "a", "position": [0.4, 0.3, Infinity]}]}', "Infinity"),
        (
            '{"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], "size": [0, 0.05, 0.05]}]}',
            "objects[0].size",
        ),
        (
            '{"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], "size": [-1, 0.05, 0.05]}]}',
            "> 0",
        ),
        (
            '{"objects": [{"id": "a", "position": [0.4, 0.3, 0.025]}, '
            '{"id": "a", "position": [0.5, 0.3, 0.025]}]}',
            "duplicate part id 'a'",
        ),
        (
            '{"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], "colour": "red"}]}',
            "objects[0].colour",
        ),
        (
            '{"objects": [{"id": "a", "position": [0.4, 0.3, 0.025], '
            '"orientation": [1, 1, 0, 0]}]}',
            "norm",
        ),
        ('{"objects": {}}', "objects"),
        ("[1, 2, 3]", "JSON object"),
    ],
)
@pytest.mark.parametrize("subcommand", ["verify", "sequence"])
def test_bad_layout_files_exit_2_naming_the_field(tmp_path, subcommand, text, needle):
    proc = run(subcommand, write(tmp_path, text))
    assert proc.returncode == 2
    assert needle in proc.stderr
    assert "Traceback" not in proc.stderr


def test_bad_input_json_mode_is_one_object(tmp_path):
    proc = run("verify", write(tmp_path, "{oops"), "--json")
    assert proc.returncode == 2
    assert json.loads(proc.stdout)["status"] == "error"


def test_part_limit_is_enforced(tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text("[limits]\nmax_parts = 2\n")
    objects = [{"id": f"c{k}", "position": [0.4, 0.3, 0.025 + 0.05 * k]} for k in range(3)]
    proc = run("verify", write(tmp_path, json.dumps({"objects": objects})), "--cell", str(cell))
    assert proc.returncode == 2 and "max_parts" in proc.stderr


def test_bad_cell_file_names_the_field(tmp_path):
    cell = tmp_path / "cell.toml"
    cell.write_text("[workspace]\nx_min = 0.9\nx_max = 0.1\n")
    proc = run("plan", "a tower", "--cell", str(cell))
    assert proc.returncode == 2 and "x_min" in proc.stderr and "Traceback" not in proc.stderr


def test_verify_reports_violations_with_exit_1(tmp_path):
    objects = [
        {"id": "a", "position": [0.4, 0.3, 0.025]},
        {"id": "b", "position": [0.4, 0.3, 0.025]},
        {"id": "c", "position": [1.0, 0.3, 0.025]},
    ]
    proc = run("verify", write(tmp_path, json.dumps({"objects": objects})), "--json")
    assert proc.returncode == 1
    found = {v["constraint"] for v in json.loads(proc.stdout)["violations"]}
    assert {"collision", "workspace"} <= found


def test_sequence_command(tmp_path):
    objects = [{"id": f"c{k}", "position": [0.4, 0.3, 0.025 + 0.05 * k]} for k in (2, 0, 1)]
    proc = run("sequence", write(tmp_path, json.dumps({"objects": objects})), "--json")
    assert proc.returncode == 0
    assert json.loads(proc.stdout)["sequence"] == ["c0", "c1", "c2"]


def test_skills_command_lists_tools():
    proc = run("skills")
    tools = json.loads(proc.stdout)["tools"]
    assert {t["function"]["name"] for t in tools} >= {"verify", "sequence", "flatten", "shift"}
