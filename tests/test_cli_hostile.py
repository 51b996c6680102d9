"""Hostile input at the command line: one line naming the path or field and the fix, exit 2,
never a traceback — checked on the reported reproductions (real subprocesses) and by a fuzz
test that drives every subcommand in-process with hostile files and arguments."""

from __future__ import annotations

import json
import math
import os
import sqlite3
import string
import subprocess
import sys
import tempfile
from pathlib import Path
from types import SimpleNamespace

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from sdi import cli
from sdi.orchestrator.bus import MessageBus

SDI = [sys.executable, "-m", "sdi.cli"]
TOWER = {
    "objects": [
        {"id": "c1", "position": [0.4, 0.3, 0.025], "size": [0.05, 0.05, 0.05]},
        {"id": "c2", "position": [0.4, 0.3, 0.075], "size": [0.05, 0.05, 0.05]},
    ]
}


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*SDI, *args], capture_output=True, text=True, timeout=300)


def errors(proc: subprocess.CompletedProcess[str]) -> list[str]:
    """The lines SDI wrote to stderr (without PyBullet's banner)."""
    return [line for line in proc.stderr.splitlines() if not line.startswith("pybullet build")]


def assert_bad_input(proc: subprocess.CompletedProcess[str], *needles: str) -> str:
    """Exit 2, one line on stderr that contains every needle, and no traceback anywhere."""
    assert "Traceback" not in proc.stderr + proc.stdout, proc.stderr
    assert proc.returncode == 2, (proc.returncode, proc.stderr)
    lines = errors(proc)
    assert len(lines) == 1, lines
    for needle in needles:
        assert needle in lines[0], (needle, lines[0])
    return lines[0]


@pytest.fixture
def tower(tmp_path: Path) -> Path:
    path = tmp_path / "tower.json"
    path.write_text(json.dumps(TOWER))
    return path


# -- the reported reproductions, as real subprocesses ------------------------------------------


def test_deeply_nested_layout(tmp_path):
    path = tmp_path / "deep.json"
    path.write_text('{"objects":' * 100_000 + "[]" + "}" * 100_000)
    assert_bad_input(run("verify", str(path)), "nested too deeply")


@pytest.mark.parametrize("kind", ["folder", "missing parent", "unwritable", "under a file"])
def test_plan_out_to_a_place_that_cannot_be_written(tmp_path, kind):
    target = {
        "folder": tmp_path,
        "missing parent": tmp_path / "no" / "plan.json",
        "unwritable": Path("/proc/sdi-plan.json"),
        "under a file": tmp_path / "file.txt" / "plan.json",
    }[kind]
    (tmp_path / "file.txt").write_text("x")
    before = sorted(tmp_path.iterdir())
    line = assert_bad_input(run("plan", "a 3-cube tower", "--out", str(target)), "--out")
    assert str(target.parent if kind != "folder" else target) in line
    assert sorted(tmp_path.iterdir()) == before  # nothing written, no .tmp left behind


@pytest.fixture(scope="module")
def approved_db(tmp_path_factory) -> Path:
    """A run database holding run ``r1``: a 2-cube tower, its record approved and executed."""
    from sdi.orchestrator import Orchestrator

    db = tmp_path_factory.mktemp("approved") / "runs.sqlite"
    orch = Orchestrator(db=db, arms=["irb120"])
    try:
        status = orch.start("a 2-cube tower at x = 0.4", run_id="r1", approve=True)
        assert status.status == "success" and status.state["approved_hash"]
    finally:
        orch.close()
    return db


@pytest.mark.parametrize(
    ("option", "value"),
    [("--rapid", "/proc/sdi-rapid"), ("--python", "{tmp}/no/prog.py"), ("--python", "{tmp}")],
)
def test_export_paths_are_checked_before_anything(tmp_path, approved_db, option, value):
    value = value.format(tmp=tmp_path)
    rapid = tmp_path / "rapid"
    args = ["--rapid", str(rapid)] if option == "--python" else []
    proc = run("export", "--run", "r1", "--db", str(approved_db), *args, option, value)
    assert_bad_input(proc, option)
    assert not rapid.exists()  # no RAPID module written before the Python path failed


def test_execute_report_folder_that_is_a_file(tmp_path, tower):
    assert_bad_input(run("execute", str(tower), "--report", str(tower)), "--report", "is a file")


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        (b"\x00\x01\xff\xfe", "not UTF-8"),
        (None, "is a folder"),
        (b"[workspace]\nx_max = nan\n", "workspace.x_max: must be a finite number, got nan"),
        (b"[workspace]\nx_max = inf\n", "workspace.x_max: must be a finite number, got inf"),
    ],
)
def test_bad_cell_files(tmp_path, tower, content, needle):
    path = tmp_path / "cell.toml"
    if content is None:
        path.mkdir()
    else:
        path.write_bytes(content)
    assert_bad_input(run("verify", str(tower), "--cell", str(path)), needle)


@pytest.mark.parametrize("value", ["nan", "inf", "-1", "0"])
def test_epsilon_must_be_finite_and_positive(tower, value):
    assert_bad_input(run("execute", str(tower), "--epsilon", value), "--epsilon", value)


def test_unknown_arms_are_bad_input(tower):
    line = assert_bad_input(run("run", "--layout", str(tower), "--arms", "irb9000"))
    assert "irb9000" in line and "irb120" in line


def _run_db(path: Path) -> Path:
    bus = MessageBus(path)
    for k in range(200):
        bus.send("r1", "human", "orchestrator", "command", {"command": "x" * 200, "k": k})
    bus.close()
    return path


@pytest.mark.parametrize("kind", ["missing", "folder", "garbage", "truncated", "locked"])
def test_bad_run_databases(tmp_path, kind):
    db = tmp_path / "runs.sqlite"
    lock = None
    if kind == "folder":
        db.mkdir()
    elif kind == "garbage":
        db.write_bytes(b"this is no database\n" * 10)
    elif kind == "truncated":
        data = _run_db(db).read_bytes()
        db.write_bytes(data[: len(data) // 3])
    elif kind == "locked":
        _run_db(db)
        lock = sqlite3.connect(db)
        lock.execute("BEGIN EXCLUSIVE")
    try:
        for proc in (run("log", "r1", "--db", str(db)), run("resume", "r1", "--db", str(db))):
            assert_bad_input(proc, "--db", str(db))
    finally:
        if lock is not None:
            lock.close()
    if kind == "missing":
        assert not db.exists()  # `sdi log` must not create an empty database


def test_log_of_a_good_database_still_works(tmp_path):
    proc = run("log", "r1", "--db", str(_run_db(tmp_path / "runs.sqlite")), "--json")
    assert proc.returncode == 0 and len(json.loads(proc.stdout)["messages"]) == 200


@pytest.mark.parametrize(
    ("content", "needle"),
    [
        (None, "no such file"),
        (b"\xff\xfe[", "not UTF-8"),
        (b"[{", "not valid JSON"),
        # a run's state is MessagePack, which has no integers past 64 bits: found by the fuzz
        (b'[{"op": "translate", "id": "c1", "dx": 1' + b"0" * 40 + b"}]", "edits[0].dx is 1"),
        (b'[{"op": "translate", "id": "c1", "dy": NaN}]', "edits[0].dy is nan"),
    ],
)
def test_resume_edit_files(tmp_path, content, needle):
    edits = tmp_path / "edits.json"
    if content is not None:
        edits.write_bytes(content)
    db = _run_db(tmp_path / "runs.sqlite")
    assert_bad_input(run("resume", "r1", "--db", str(db), "--edit", str(edits)), "edits", needle)


# -- messages -------------------------------------------------------------------------------


def test_markup_in_messages_is_shown_as_written(tmp_path):
    path = tmp_path / "q.json"
    part = {"id": "a", "position": [0.4, 0.3, 0.025], "orientation": [2, 0, 0, 0]}
    path.write_text(json.dumps({"objects": [part]}))
    assert_bad_input(run("verify", str(path)), "quaternion [w, x, y, z] must have norm 1")


def test_a_huge_coordinate_is_bad_input_without_warnings(tmp_path):
    path = tmp_path / "far.json"
    part = {"id": "a", "position": [1e308, 0.3, 0.025]}
    path.write_text(json.dumps({"objects": [part]}))
    line = assert_bad_input(run("verify", str(path)), "objects[0].position", "1e+308")
    assert len(line) < 200 and "Warning" not in line


def test_refused_is_said_once(tmp_path):
    path = tmp_path / "floating.json"
    path.write_text(json.dumps({"objects": [{"id": "a", "position": [0.4, 0.3, 0.3]}]}))
    proc = run("execute", str(path))
    assert proc.returncode == 1 and "Traceback" not in proc.stderr
    assert "refused:" in proc.stderr and "refused: refused" not in proc.stderr


def test_pre_execution_summary_is_words_not_a_dict():
    summary = {
        "steps": 6,
        "steps_per_robot": {"irb120": 3, "irb1600": 3},
        "makespan_s": 53.98,
        "parallel": True,
        "planning_s_per_step": 0.3,
        "notes": [],
    }
    text = cli._describe_planning(summary)
    assert text == "6 pick-and-place steps (irb120 3, irb1600 3), makespan 54.0 s, arms in parallel"
    assert "{" not in cli._describe_failure({"message": "no IK", "part_id": "c3", "step": 2})


def test_interactive_edit_of_a_missing_or_bad_file_asks_again(tmp_path, monkeypatch, capsys):
    good = tmp_path / "good.json"
    good.write_text(json.dumps([{"op": "remove", "id": "c2"}]))
    latin = tmp_path / "latin.json"
    latin.write_bytes(b'[{"op": "remove", "id": "\xe9"}]')
    answers = iter([f"e {tmp_path / 'missing.json'}", f"e {latin}", f"e {good}"])
    monkeypatch.setattr(cli.typer, "prompt", lambda *a, **k: next(answers))
    monkeypatch.setattr(cli.sys.stdin, "isatty", lambda: True, raising=False)
    status = SimpleNamespace(waiting_for={"kind": "failure_report", "failure": None})
    decision = cli._review(status, as_json=False)
    assert decision == {"action": "edit", "edits": [{"op": "remove", "id": "c2"}]}
    said = capsys.readouterr().err
    assert "missing.json" in said and "no such file" in said and "not UTF-8" in said


# -- fuzz: every subcommand, hostile files and arguments, in-process ---------------------------

SUBCOMMANDS = ("plan", "verify", "sequence", "execute", "export", "run", "resume", "log",
               "skills", "bench")  # fmt: skip
NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, -0.0, 1e308, -1e308, 10**400, 0.025, 0.4, True, None, "0.4"]),
)
MARKUP = st.sampled_from(["[w, x, y, z]", "[/bold]", "[red]", "\x00", "é", "  ", "[", "]"])
TEXT = st.one_of(st.text(max_size=40), MARKUP, st.text(string.printable, max_size=40))
JSON = st.recursive(
    st.one_of(st.none(), st.booleans(), NUMBERS.filter(lambda v: not isinstance(v, str)), TEXT),
    lambda inner: st.one_of(st.lists(inner, max_size=4), st.dictionaries(TEXT, inner, max_size=4)),
    max_leaves=12,
)
PART = st.fixed_dictionaries(
    {},
    optional={
        "id": st.one_of(st.sampled_from(["c1", "c2", "[/x]", ""]), TEXT),
        "position": st.one_of(st.lists(NUMBERS, max_size=4), JSON),
        "orientation": st.lists(NUMBERS, max_size=5),
        "size": st.lists(NUMBERS, max_size=4),
        "colour": TEXT,
    },
)
LAYOUT = st.fixed_dictionaries(
    {"objects": st.lists(PART, max_size=4)},
    optional={"sequence": st.one_of(st.lists(TEXT, max_size=3), JSON), "layout": JSON},
)
TOML_KEYS = [
    "workspace.x_max",
    "workspace.x_min",
    "tolerances.contact",
    "limits.max_parts",
    "design.structure_gap",
    "part_types.cube",
    "bogus.key",
    "limits.phase_seconds",
]
TOML_VALUES = st.sampled_from(
    [
        "nan",
        "inf",
        "-inf",
        "-1",
        "0",
        "1e308",
        '"x"',
        "[1, 2]",
        "[0.05, 0.05, -0.05]",
        "0.3",
        "true",
        "{a = 1}",
        "[[]]",
    ]
)


@st.composite
def toml_files(draw: st.DrawFn) -> bytes:
    lines = []
    for key in draw(st.lists(st.sampled_from(TOML_KEYS), max_size=3, unique=True)):
        section, name = key.split(".")
        lines.append(f"[{section}]\n{name} = {draw(TOML_VALUES)}\n")
    if draw(st.booleans()):
        lines.append('[[robots]]\nname = "a"\nmodel = "irb120"\nbase_xy = [0, 0]\n' * 2)
    return "".join(lines).encode()


CONTENT = st.one_of(
    st.binary(max_size=64),
    TEXT.map(lambda t: t.encode("utf-8", "surrogatepass")),
    JSON.map(lambda v: json.dumps(v).encode()),
    LAYOUT.map(lambda v: json.dumps(v).encode()),
    st.integers(1, 50_000).map(lambda n: ("[" * n + "]" * n).encode()),
    st.integers(1, 50_000).map(lambda n: ('{"objects":' * n + "[]" + "}" * n).encode()),
    toml_files(),
    st.just(b"\xff\xfe"),
)
PATH_KINDS = ("file", "file", "file", "folder", "missing", "missing parent", "under a file",
              "proc", "good")  # fmt: skip
GOOD = {
    "layout.json": json.dumps(TOWER).encode(),
    "cell.toml": b"[workspace]\nx_max = 0.75\n",
    "edits.json": json.dumps([{"op": "translate", "id": "c1", "by": [0.0, 0.0, 0.0]}]).encode(),
}


@st.composite
def hostile_path(draw: st.DrawFn, base: Path, name: str) -> str:
    """A path in `base`: a file with hostile (or good) content, a folder, missing, …"""
    kind = draw(st.sampled_from(PATH_KINDS))
    path = base / name
    if kind == "good" and name == "runs.sqlite":
        path.write_bytes(_paused_run_db())
    elif kind == "good" and name in GOOD:
        path.write_bytes(GOOD[name])
    elif kind in ("file", "good"):
        path.write_bytes(draw(CONTENT))
    elif kind == "folder":
        path.mkdir(exist_ok=True)
    elif kind == "missing parent":
        path = base / "no" / name
    elif kind == "under a file":
        (base / "plain.txt").write_text("x")
        path = base / "plain.txt" / name
    elif kind == "proc":
        path = Path("/proc") / name
    return str(path)


EARLY = {
    "execute": [["--fault", "meteor"], ["--arms", "irb9000"], ["--epsilon", "nan"],
                ["--epsilon", "-1"], ["--arms", ","]],
    "run": [["--fault", "meteor"], ["--arms", "irb9000"], ["--method", "bogus"],
            ["--backend", "nope"]],
}  # fmt: skip
"""Arguments that make execute/run stop before any motion is planned or run (export never
plans: it writes an approved record only)."""
COMMANDS = st.one_of(
    TEXT,
    st.sampled_from(
        [
            "a 3-cube tower",
            "a small bridge",
            "a tower at x = 1e308",
            "a tower of 1e400 cubes",
            "a [red] tower [/red]",
            "a row of -3 cubes",
            "a 1000 by 1000 grid",
            "build " * 400,
        ]
    ),
)
_DB: dict[str, bytes] = {}


def _paused_run_db() -> bytes:
    """A run database holding one run ``r1`` paused at its design review (made once)."""
    if "db" not in _DB:
        from sdi.orchestrator import Orchestrator

        with tempfile.TemporaryDirectory() as tmp:
            orch = Orchestrator(db=Path(tmp) / "runs.sqlite")
            status = orch.start("a 2-cube tower at x = 0.4", run_id="r1")
            assert status.status == "paused"
            orch.close()
            _DB["db"] = (Path(tmp) / "runs.sqlite").read_bytes()
    return _DB["db"]


def _would_move(args: list[str]) -> bool:
    """True if execute would plan motion (a layout file that passes the Inspector)."""
    from sdi.inspector.verifier import verify
    from sdi.model.layout import load_layout

    try:
        layout, sequence = load_layout(args[1])
        return verify(layout, sequence=sequence).passed
    except Exception:
        return False


@st.composite
def invocations(draw: st.DrawFn, base: Path) -> list[str]:
    sub = draw(st.sampled_from(SUBCOMMANDS))
    args = [sub]
    if sub in ("plan", "run"):
        args.append(draw(COMMANDS))
    if sub in ("verify", "sequence", "execute", "export"):
        args.append(draw(hostile_path(base, "layout.json")))
    if sub in ("resume", "log"):
        run_ids = st.one_of(TEXT.filter(lambda t: not t.startswith("-")), st.just("r1"))
        args.append(draw(st.one_of(st.just("r1"), run_ids)))
    if sub in ("resume", "log") or (sub == "run" and draw(st.booleans())):
        kind = draw(st.sampled_from(["good", "hostile"]))
        db = base / "runs.sqlite"
        if kind == "good":
            db.write_bytes(_paused_run_db())
        args += ["--db", str(db) if kind == "good" else draw(hostile_path(base, "runs.sqlite"))]
    if sub not in ("skills", "log") and draw(st.booleans()):
        args += ["--cell", draw(hostile_path(base, "cell.toml"))]
    if sub in ("plan", "bench") and draw(st.booleans()):
        args += ["--out", draw(hostile_path(base, "out.json"))]
    if sub == "execute" and draw(st.booleans()):
        args += ["--report", draw(hostile_path(base, "report"))]
    if sub == "export":
        for option, name in (("--rapid", "rapid"), ("--python", "prog.py")):
            if draw(st.booleans()):
                args += [option, draw(hostile_path(base, name))]
    answer = draw(st.sampled_from(["wait", "reject", "edit"]))
    if sub == "resume" and answer == "reject":  # never --approve: that would run the motion
        args.append("--reject")
    elif sub == "resume" and answer == "edit":
        args += ["--edit", draw(hostile_path(base, "edits.json"))]
    moves = sub == "execute" and _would_move(args)
    if moves or (sub == "run" and draw(st.booleans())):
        args += draw(st.sampled_from(EARLY[sub]))  # never plan or run motion in a fuzz example
    if sub == "plan":
        args += draw(st.sampled_from([[], ["--method", "bogus"], ["--backend", "nope"]]))
    if sub != "skills" and draw(st.booleans()):
        args.append("--json")
    if draw(st.integers(0, 9)) == 0:
        args.append(draw(st.sampled_from(["--bogus", "--force", "extra"])))
    return args


FUZZ = {"examples": 0, "crashes": 0}


@settings(
    max_examples=int(os.environ.get("SDI_FUZZ_EXAMPLES", "300")),
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
@given(data=st.data())
def test_fuzz_every_subcommand(data):
    _paused_run_db()  # made here, not inside a strategy (it draws random run ids)
    runner = CliRunner()
    with tempfile.TemporaryDirectory() as tmp:
        base = Path(tmp)
        args = data.draw(invocations(base), label="args")
        env = {"SDI_DB": str(base / "default.sqlite"), "SDI_BENCH_CACHE": str(base / "cache")}
        result = runner.invoke(cli.app, args, env=env)
    FUZZ["examples"] += 1
    text = result.output + (result.stderr or "")
    crashed = result.exception is not None and not isinstance(result.exception, SystemExit)
    FUZZ["crashes"] += crashed
    assert not crashed, (args, repr(result.exception))
    assert result.exit_code in (0, 1, 2), (args, result.exit_code, text)
    assert "Traceback" not in text, (args, text)
    if result.exit_code == 2 and "--json" in args and result.stdout.startswith("{"):
        last = json.loads(result.stdout.splitlines()[-1])
        # a bad input is an error; an edit the run refused leaves it paused, saying why
        refused = last["status"] == "paused" and (last.get("waiting_for") or {}).get("refused")
        assert last["status"] == "error" or refused, last


def test_no_nan_sneaks_through_the_cell_loader(tmp_path):
    """The fuzz's TOML values, one at a time: every accepted cell has only finite numbers."""
    from sdi.errors import InputError
    from sdi.model.cell import CellConfig

    for key in TOML_KEYS:
        for value in ["nan", "inf", "-inf", "1e308"]:
            section, name = key.split(".")
            path = tmp_path / "c.toml"
            path.write_text(f"[{section}]\n{name} = {value}\n")
            try:
                cell = CellConfig.load(path)
            except InputError as exc:
                assert key in str(exc) or "bogus" in key
                continue
            numbers = json.dumps(cell.model_dump())
            assert "NaN" not in numbers and "Infinity" not in numbers
            assert all(math.isfinite(v) for v in cell.workspace.lower + cell.workspace.upper)


def test_edits_nested_a_few_hundred_deep_are_bad_input(tmp_path):
    """300 levels pass the JSON parser and failed in the run's checkpoint writer (a TypeError
    the fuzz found): refused as too deep, the run left as it was."""
    db = tmp_path / "runs.sqlite"
    db.write_bytes(_paused_run_db())
    edits = tmp_path / "edits.json"
    edits.write_text('{"objects":' * 300 + "[]" + "}" * 300)
    result = CliRunner().invoke(cli.app, ["resume", "r1", "--db", str(db), "--edit", str(edits)])
    assert result.exit_code == 2 and isinstance(result.exception, SystemExit)
    assert "nested too deeply to be edits" in result.output
