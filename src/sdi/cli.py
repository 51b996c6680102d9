"""The `sdi` command line. Thin: it parses, calls the library, prints.

Exit codes: 0 success, 1 planning or verification failure, 2 bad input (the message names the
field or part and the fix; no stack trace). One boundary (`_Boundary`) turns every `SDIError`
and every OS or SQLite error on a path the user gave into that one line and exit 2. Every file
is written through `sdi.outputs` (checked first, whole or not at all, no overwriting of files
SDI did not write unless --force).
"""

from __future__ import annotations

import json
import math
import sqlite3
import sys
import time
from contextlib import ExitStack
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.console import Console
from rich.markup import escape
from rich.text import Text
from typer.core import TyperGroup

from sdi.errors import InputError, SDIError, SequencingError
from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence as run_sequence
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig
from sdi.model.layout import load_layout
from sdi.outputs import Outputs
from sdi.pipeline import plan as run_plan
from sdi.render import print_plan, violations_table


class _Boundary(TyperGroup):
    """The one error path of the CLI: a user's mistake is one line and exit 2, never a trace.

    `SDIError`s that no command handled, and OS or SQLite errors on a path the user gave,
    become ``error: <what>: <why>; <fix>`` on stderr (or one JSON object with ``--json``).
    Anything else is a bug in SDI and keeps its traceback.
    """

    def parse_args(self, ctx: Any, args: list[str]) -> list[str]:
        _invocation.clear()
        _invocation["json"] = "--json" in args
        return super().parse_args(ctx, args)

    def invoke(self, ctx: Any) -> Any:
        as_json = bool(_invocation.get("json"))
        try:
            return super().invoke(ctx)
        except SDIError as exc:
            _fail(str(exc), as_json)
        except sqlite3.Error as exc:
            db = _invocation.get("db", "the run database")
            _fail(f"--db: {db}: {_sqlite_reason(exc)}", as_json)
        except OSError as exc:
            if exc.filename is None:
                raise
            _fail(f"{exc.filename}: {exc.strerror or exc}; check the path", as_json)


_invocation: dict[str, object] = {}
"""What the boundary needs to know about the command being run: ``json``, ``db``."""


app = typer.Typer(
    cls=_Boundary,
    add_completion=False,
    no_args_is_help=True,
    help="SDI: plain-language commands → verified, sequenced robot assembly plans.",
    pretty_exceptions_enable=False,
)
out = Console()
err = Console(stderr=True)

CellOption = Annotated[
    Path | None,
    typer.Option("--cell", help="cell configuration TOML (default: built-in; $SDI_CELL)"),
]
JsonOption = Annotated[bool, typer.Option("--json", help="print one JSON object")]
LlmTimeoutOption = Annotated[
    float | None,
    typer.Option(
        "--llm-timeout",
        metavar="SECONDS",
        help="wall-clock budget of one model call, retries included (default 120)",
    ),
]


def _emit(data: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(data, indent=None) + "\n")


def _line(console: Console, label: str, style: str, message: object) -> None:
    """Print ``label message`` as one line; `message` is shown as is (never read as markup)."""
    console.print(Text.assemble((label, style), " ", str(message)), soft_wrap=True)


def _fail(message: str, as_json: bool) -> NoReturn:
    if as_json:
        _emit({"status": "error", "error": message})
    else:
        _line(err, "error:", "bold red", message)
    raise typer.Exit(2)


def _bad_input(exc: SDIError, as_json: bool) -> NoReturn:
    _fail(str(exc), as_json)


def _sqlite_reason(exc: sqlite3.Error) -> str:
    text = str(exc)
    if "locked" in text or "busy" in text:
        return "the database is locked by another process; wait for it or use another --db"
    if "not a database" in text or "malformed" in text:
        return "not an SDI run database (damaged or another kind of file); give another --db"
    if "unable to open" in text:
        return "cannot open it (a folder, a missing folder or no permission); give a file path"
    return f"{text}; give another --db"


def _database(path: Path | None, *, run_id: str | None = None) -> Path:
    """The run database (`path`, $SDI_DB or the user data dir), checked before SDI opens it:
    not a folder, SDI's SQLite file if it exists. Given the `run_id` it must hold, a missing
    database is refused (never created empty)."""
    from sdi.orchestrator import default_db

    db = path or default_db()
    _invocation["db"] = str(db)
    if db.is_dir():
        raise InputError(f"{db} is a folder; give a database file", field="--db")
    if not db.exists():
        if run_id is not None:
            raise InputError(
                f"no run database at {db}, so no run {run_id!r}; "
                "give the --db of the `sdi run` that printed it",
                field="--db",
            )
        if path is not None and not db.parent.is_dir():
            raise InputError(f"folder {db.parent} does not exist; create it first", field="--db")
        return db
    try:
        conn = sqlite3.connect(f"file:{db}?mode=ro", uri=True, timeout=2.0)
        try:
            tables = {row[0] for row in conn.execute("SELECT name FROM sqlite_master")}
        finally:
            conn.close()
    except sqlite3.Error as exc:
        raise InputError(f"{db}: {_sqlite_reason(exc)}", field="--db") from None
    if tables and not tables & {"events", "messages", "checkpoints", "leases", "records"}:
        raise InputError(
            f"{db} is another program's SQLite database, not SDI's; give another --db",
            field="--db",
        )
    return db


def _arms(arms: str | None, cell: CellConfig, as_json: bool) -> list[str] | None:
    """The robots named by ``--arms`` (None: all); unknown names are bad input."""
    if arms is None:
        return None
    names = [a.strip() for a in arms.split(",") if a.strip()]
    known = [r.name for r in cell.robots]
    unknown = [a for a in names if a not in known]
    if unknown or not names:
        message = f"unknown robots {unknown}" if unknown else "names no robot"
        _fail(f"--arms: {message}; the cell has {', '.join(known)}", as_json)
    return names


_EDITS_DEPTH = 16
"""Edits are a list of flat objects with short lists in them: deeper JSON is no edits."""


def _plain_numbers(value: Any, where: str, path: Path, depth: int = 0) -> None:
    """Every number in an edits file is finite and fits 64 bits (a run's state is stored as
    MessagePack, which has no larger integers), and the file is no deeper than edits are (a few
    hundred levels pass the parser and fail in the run's checkpoint writer): else bad input
    naming where it is."""
    if isinstance(value, dict | list) and depth >= _EDITS_DEPTH:
        raise InputError(f"{path} is nested too deeply to be edits", field="edits")
    if isinstance(value, bool):
        return
    if isinstance(value, int) and not -(2**63) <= value < 2**64:
        raise InputError(
            f"{path}: {where or 'the value'} is {str(value)[:12]}…, far beyond any size or "
            "position in the cell; give metres (e.g. 0.4)",
            field="edits",
        )
    if isinstance(value, float) and not math.isfinite(value):
        raise InputError(
            f"{path}: {where or 'the value'} is {value}; give a finite number", field="edits"
        )
    if isinstance(value, dict):
        for key, item in value.items():
            _plain_numbers(item, f"{where}.{key}" if where else str(key), path, depth + 1)
    elif isinstance(value, list):
        for k, item in enumerate(value):
            _plain_numbers(item, f"{where}[{k}]" if where else f"edits[{k}]", path, depth + 1)


def _read_edits(path: Path) -> Any:
    """The edits JSON of ``--edit`` or the interactive ``e FILE``; bad files are bad input."""
    try:
        edits = json.loads(path.read_text(encoding="utf-8"))
    except FileNotFoundError:
        raise InputError(f"no such file: {path}; check the path", field="edits") from None
    except IsADirectoryError:
        raise InputError(f"{path} is a folder; give an edits JSON file", field="edits") from None
    except UnicodeDecodeError:
        raise InputError(
            f"{path} is not UTF-8 text; give an edits JSON file", field="edits"
        ) from None
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror or exc}", field="edits") from None
    except json.JSONDecodeError as exc:
        raise InputError(
            f"{path} is not valid JSON: {exc.msg} at line {exc.lineno}; "
            'give a list of edits, e.g. [{"op": "translate", …}]',
            field="edits",
        ) from None
    except RecursionError:
        raise InputError(f"{path} is nested too deeply to be edits", field="edits") from None
    _plain_numbers(edits, "", path)
    return edits


ForceOption = Annotated[
    bool, typer.Option("--force", help="replace output files that SDI did not write")
]


def _cell(path: Path | None, as_json: bool) -> CellConfig:
    try:
        return CellConfig.load(path)
    except InputError as exc:
        _bad_input(exc, as_json)


@app.command()
def plan(
    command: Annotated[str, typer.Argument(help="what to build, in plain language")],
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    out_file: Annotated[
        Path | None, typer.Option("--out", help="also write the JSON result here")
    ] = None,
    backend: Annotated[
        str, typer.Option("--backend", help="rules (offline, default) | local (llama.cpp) | openai")
    ] = "rules",
    method: Annotated[
        str, typer.Option("--method", help="a method of the paper's Table II")
    ] = "Hybrid",
    force: ForceOption = False,
    llm_timeout: LlmTimeoutOption = None,
) -> None:
    """Plan a command end to end: spec → layout → verification → assembly sequence."""
    cell = _cell(cell_path, json_out)
    outputs = Outputs(force=force)
    if out_file is not None:
        outputs.file(out_file, "--out")
    if backend == "rules" and method == "Hybrid":
        result = run_plan(command, cell)
    else:
        from sdi.pipeline import plan_with

        with ExitStack() as stack:
            model = _model(backend, json_out, stack, llm_timeout)
            try:
                result = plan_with(command, method, model, cell)
            except InputError as exc:
                _bad_input(exc, json_out)
    data = result.to_json_dict()
    if out_file is not None and result.status == "success":
        outputs.commit({out_file: json.dumps(data, indent=2) + "\n"})
    if json_out:
        _emit(data)
    else:
        print_plan(out, result, cell)
        for note in result.notes:
            err.print(note, style="yellow", markup=False, highlight=False)
    raise typer.Exit({"success": 0, "partial": 1, "failure": 1, "error": 2}[result.status])


def _load(path: Path, cell: CellConfig, as_json: bool) -> tuple[Any, list[str] | None]:
    try:
        return load_layout(path, max_parts=cell.limits.max_parts)
    except InputError as exc:
        _bad_input(exc, as_json)


@app.command("verify")
def verify_cmd(
    layout_file: Annotated[
        Path, typer.Argument(help="layout JSON ({objects: […]} or a plan result)")
    ],
    json_out: JsonOption = False,
    cell_path: CellOption = None,
) -> None:
    """Verify a layout (and its sequence, if the file has one) against every constraint."""
    cell = _cell(cell_path, json_out)
    layout, sequence = _load(layout_file, cell, json_out)
    report = verify(layout, cell, sequence=sequence)
    if json_out:
        _emit({"status": "success" if report.passed else "failure", **report.to_json_dict()})
    elif report.passed:
        out.print(f"[green]passed[/green]: {len(layout)} parts satisfy every constraint")
    else:
        out.print(violations_table(report.violations))
    raise typer.Exit(0 if report.passed else 1)


@app.command("sequence")
def sequence_cmd(
    layout_file: Annotated[Path, typer.Argument(help="layout JSON")],
    json_out: JsonOption = False,
    cell_path: CellOption = None,
) -> None:
    """Compute the assembly order (Alg. 4) for a layout."""
    cell = _cell(cell_path, json_out)
    layout, _ = _load(layout_file, cell, json_out)
    try:
        order = run_sequence(Analysis(layout, cell))
    except SequencingError as exc:
        if json_out:
            _emit(
                {"status": "failure", "sequence": None, "error": str(exc), "blocked": exc.blocked}
            )
        else:
            _line(err, "no sequence:", "bold red", exc)
        raise typer.Exit(1) from None
    if json_out:
        _emit({"status": "success", "sequence": order})
    else:
        out.print(Text(" → ".join(order)), soft_wrap=True)


@app.command()
def bench(
    out_file: Annotated[
        Path | None, typer.Option("--out", help="write the results JSON here (one suite)")
    ] = None,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    force: ForceOption = False,
    suite: Annotated[
        str,
        typer.Option(
            "--suite", help="commands | human-mods | failures | motion | all (default: commands)"
        ),
    ] = "commands",
    method: Annotated[
        list[str] | None,
        typer.Option(
            "--method",
            help="a method to run (repeatable; 'pipeline' = no orchestrator; 'paper' = Rule, "
            "PGE, LG, Hybrid; 'all'); default: the pipeline on commands, the paper's four on "
            "human-mods and failures",
        ),
    ] = None,
    backend: Annotated[
        str, typer.Option("--backend", help="rules (default; no model), local or openai")
    ] = "rules",
    jobs: Annotated[int, typer.Option("--jobs", help="local worker processes")] = 1,
    ray: Annotated[
        str | None,
        typer.Option(
            "--ray", metavar="ADDRESS", help="run on a Ray cluster ('local': a local instance)"
        ),
    ] = None,
    seeds: Annotated[int, typer.Option("--seeds", help="seeds per case (0, 1, …)")] = 1,
    timeout: Annotated[
        float, typer.Option("--timeout", metavar="SECONDS", help="wall-clock limit per run")
    ] = 600.0,
    phase_seconds: Annotated[
        float | None,
        typer.Option("--phase-seconds", help="the orchestrator's per-phase limit, s"),
    ] = None,
    physics: Annotated[
        bool,
        typer.Option(
            "--physics", help="assemble every successful layout in PyBullet: does it stand?"
        ),
    ] = False,
    only: Annotated[
        str | None, typer.Option("--only", help="comma-separated case ids (e.g. A01,H3)")
    ] = None,
    report_dir: Annotated[
        Path | None,
        typer.Option("--report", help="write <suite>.json, .md and .png into this folder"),
    ] = None,
    cache_dir: Annotated[
        Path | None,
        typer.Option(
            "--cache",
            help="cached results (default: $SDI_BENCH_CACHE or the user cache folder)",
        ),
    ] = None,
    fresh: Annotated[
        bool, typer.Option("--fresh", help="run every case again, ignoring cached results")
    ] = False,
) -> None:
    """Run evaluation suites (the paper's Tables II–VI) and print their tables."""
    import os

    from platformdirs import user_cache_dir
    from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

    from sdi.bench.cases import RunConfig
    from sdi.bench.charts import chart
    from sdi.bench.report import (
        plan_jobs,
        resolve_methods,
        resolve_suites,
        suite_json,
        suite_markdown,
    )
    from sdi.bench.sweep import ResultCache, sweep
    from sdi.llm.backends import BACKENDS

    def bad(message: str, option: str) -> NoReturn:
        _bad_input(InputError(message, field=option), json_out)

    try:
        suites = resolve_suites(suite)
    except ValueError as exc:
        bad(str(exc), "--suite")
    try:
        methods = resolve_methods(method)
    except ValueError as exc:
        bad(str(exc), "--method")
    if backend not in BACKENDS:
        bad(f"unknown backend {backend!r}; choose from {sorted(BACKENDS)}", "--backend")
    if jobs < 1:
        bad(f"must be ≥ 1, got {jobs}", "--jobs")
    if seeds < 1:
        bad(f"must be ≥ 1, got {seeds}", "--seeds")
    if not (math.isfinite(timeout) and timeout > 0):
        bad(f"must be a number of seconds > 0, got {timeout:g}", "--timeout")
    if phase_seconds is not None and not (math.isfinite(phase_seconds) and phase_seconds > 0):
        bad(f"must be a number of seconds > 0, got {phase_seconds:g}", "--phase-seconds")
    if ray is not None and not ray.strip():
        bad("needs an address (host:port, ray://host:port or 'local')", "--ray")
    if ray is not None and jobs > 1:
        bad("runs on the Ray cluster's workers; drop --jobs (the local pool) or --ray", "--jobs")
    if out_file is not None and len(suites) > 1:
        bad("writes one suite's JSON; with --suite all use --report DIR", "--out")
    wanted = [c.strip() for c in only.split(",") if c.strip()] if only else None
    cell = _cell(cell_path, json_out)
    outputs = Outputs(force=force)
    if out_file is not None:
        outputs.file(out_file, "--out")
    if report_dir is not None:
        outputs.folder(
            report_dir,
            "--report",
            patterns=tuple(f"{s}.{ext}" for s in suites for ext in ("json", "md", "png")),
        )
    all_jobs = plan_jobs(suites, methods, seeds, wanted)
    if not all_jobs:
        bad(f"no case of {suites} has an id in {wanted}", "--only")
    folder = cache_dir or Path(
        os.environ.get("SDI_BENCH_CACHE") or Path(user_cache_dir("sdi")) / "bench"
    )
    config = RunConfig(backend=backend, physics=physics, phase_seconds=phase_seconds, cell=cell)
    columns = (TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
               TimeElapsedColumn())  # fmt: skip
    cached = {"n": 0}
    with Progress(*columns, console=err, transient=True) as progress:
        task = progress.add_task("bench", total=len(all_jobs))

        def tick(job: Any, result: Any, from_cache: bool) -> None:
            cached["n"] += from_cache
            progress.update(task, advance=1, description=f"{job.describe()}: {result.outcome}")

        store = ResultCache(folder)
        results = sweep(all_jobs, config, workers=jobs, timeout=timeout,
                        cache=store, fresh=fresh, ray_address=ray,
                        progress=tick)  # fmt: skip
    reports: dict[str, dict[str, Any]] = {}
    files: dict[Path, bytes | str] = {}
    for name in suites:
        mine = [r for r in results if r.suite == name]
        data = suite_json(name, mine, config, seeds)
        reports[name] = data
        if report_dir is not None:
            files[report_dir / f"{name}.json"] = json.dumps(data, indent=2) + "\n"
            files[report_dir / f"{name}.md"] = suite_markdown(name, data) + "\n"
            files[report_dir / f"{name}.png"] = chart(name, data["summary"])
        if out_file is not None:
            files[out_file] = json.dumps(data, indent=2) + "\n"
    if files:
        outputs.commit(files)
    if json_out:
        _emit(reports[suites[0]] if len(suites) == 1 else {"suites": reports})
        return
    for name, data in reports.items():
        out.print(Text(f"{name} ({data['backend']}, {seeds} seed(s))", style="bold"))
        out.print(Text(suite_markdown(name, data)), soft_wrap=True)
        for r in data["results"]:
            f = r["fields"]
            if name == "commands" and r["outcome"] == "done" and not f.get("success"):
                who = f" [{r['method']}]" if r["method"] else ""
                _line(out, "✗", "red", f"{r['case']}{who} {f.get('text')!r}: {f.get('reason')}")
            elif r["outcome"] in ("timeout", "error"):
                _line(
                    out, r["outcome"], "red", f"{r['case']} {r['method'] or ''} {r['error'] or ''}"
                )
    if store.error:
        _line(err, "warning:", "yellow", f"--cache: results not stored ({store.error})")
    if cached["n"]:
        _line(err, "cached:", "dim", f"{cached['n']} of {len(all_jobs)} runs read from {folder}")


FaultOption = Annotated[
    list[str] | None, typer.Option("--fault", help="inject a failure scenario (repeatable)")
]


def _check_faults(names: list[str] | None, as_json: bool) -> None:
    from sdi.execute.faults import FAULTS

    unknown = [f for f in names or [] if f not in FAULTS]
    if unknown:
        message = f"unknown scenario {unknown}; choose from {sorted(FAULTS)}"
        _bad_input(InputError(message, field="--fault"), as_json)


ArmsOption = Annotated[
    str | None,
    typer.Option("--arms", help="comma-separated robots to use (default: every robot of the cell)"),
]


def _commission(
    layout_file: Path,
    cell_path: Path | None,
    arms: str | None,
    as_json: bool,
) -> Any:
    """Check the cell, the arms and the layout (cheap, before anything heavy is imported),
    then plan the job for the cell."""
    from sdi.errors import MotionPlanningError, UnverifiedPlanError

    cell = _cell(cell_path, as_json)
    robots = _arms(arms, cell, as_json)
    layout, sequence = _load(layout_file, cell, as_json)
    from sdi.commission import commission
    from sdi.execute.job import VerifiedJob

    try:
        job = VerifiedJob.inspect(layout, cell, sequence)  # the one verification
        return commission(job, arms=robots)
    except UnverifiedPlanError as exc:
        if as_json:
            _emit({"status": "refused", "error": str(exc), "violations": exc.violations_json()})
        else:
            _line(err, "refused:", "bold red", str(exc).removeprefix("refused: "))
            if exc.violations:
                err.print(violations_table(exc.violations))
        raise typer.Exit(1) from None
    except InputError as exc:
        _bad_input(exc, as_json)
    except MotionPlanningError as exc:
        event = getattr(exc.event, "to_json_dict", lambda: None)()
        if as_json:
            _emit({"status": "failure", "error": str(exc), "event": event})
        else:
            _line(err, "motion planning failed:", "bold red", exc)
        raise typer.Exit(1) from None


@app.command("execute")
def execute_cmd(
    layout_file: Annotated[Path, typer.Argument(help="layout JSON or a saved plan result")],
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
    epsilon: Annotated[float, typer.Option(help="V_traj threshold on δ, rad")] = 0.05,
    fault: FaultOption = None,
    report_dir: Annotated[
        Path | None, typer.Option("--report", help="write report.json and deviation.png here")
    ] = None,
    force: ForceOption = False,
) -> None:
    """Plan motion for a verified layout, execute it in simulation, monitor and report."""
    from sdi.execute.faults import FAULTS

    _check_faults(fault, json_out)
    if not (math.isfinite(epsilon) and epsilon > 0):
        _fail(f"--epsilon: must be a finite number > 0 rad, got {epsilon}", json_out)
    outputs = Outputs(force=force)
    if report_dir is not None:
        outputs.folder(report_dir, "--report", patterns=("report.json", "deviation.png"))
    plan = _commission(layout_file, cell_path, arms, json_out)
    from sdi.commission import execute
    from sdi.monitor.report import deviation_png

    result, report = execute(plan, epsilon=epsilon, faults=tuple(FAULTS[f] for f in fault or []))
    report = {"planning": plan.summary(), **report}
    if report_dir is not None:
        files: dict[Path, bytes | str] = {
            report_dir / "report.json": json.dumps(report, indent=2) + "\n"
        }
        if result.executed and set(result.executed) == set(plan.motion.trajectories):
            from sdi.monitor import deviation

            files[report_dir / "deviation.png"] = deviation_png(
                deviation(plan.motion.trajectories, result.executed), epsilon
            )
        outputs.commit(files)
    if json_out:
        _emit(report)
    else:
        out.print_json(data=report)
    raise typer.Exit(0 if report["status"] == "success" and report["v_traj"] == "pass" else 1)


@app.command("export")
def export_cmd(
    layout_file: Annotated[
        Path | None,
        typer.Argument(help="not exported directly: run it with `sdi run --layout` first"),
    ] = None,
    rapid: Annotated[
        Path | None, typer.Option("--rapid", help="directory for one RAPID module per robot")
    ] = None,
    python: Annotated[
        Path | None, typer.Option("--python", help="file for the Python program")
    ] = None,
    force: ForceOption = False,
    run_id: Annotated[
        str | None,
        typer.Option("--run", help="the run whose approved commissioning record to export"),
    ] = None,
    db: Annotated[
        Path | None, typer.Option("--db", help="run database (with --run; default: $SDI_DB)")
    ] = None,
) -> None:
    """Export robot programs (ABB RAPID, abb-motion-program-exec Python) from the commissioning
    record the operator approved (`--run`): exactly the motion approved, never a new plan."""
    if layout_file is not None and run_id is not None:
        _fail("give --run RUN_ID only (a LAYOUT_FILE cannot be exported directly)", False)
    if layout_file is not None:
        _fail(f"{layout_file}: programs are written only from an approved commissioning record; "
              f"run it with `sdi run --layout {layout_file}`, approve the design and the record, "
              "then `sdi export --run RUN_ID`", False)  # fmt: skip
    if run_id is None:
        _fail("give --run RUN_ID: the run whose approved commissioning record to export", False)
    if rapid is None and python is None:
        _fail("give --rapid DIR and/or --python FILE", False)
    outputs = Outputs(force=force)
    if rapid is not None:
        outputs.folder(rapid, "--rapid", patterns=("SDI_*.mod",))
    if python is not None:
        outputs.file(python, "--python")
    from sdi.orchestrator import Orchestrator

    orch = Orchestrator(db=_database(db, run_id=run_id), create=False)
    try:
        record = orch.approved_record(run_id)  # the cell and the arms are the record's
        plan = record.commissioning(record.cell())
    finally:
        orch.close()
    from sdi.export import interlock_plan, python_program, rapid_module

    interlocks = interlock_plan(
        plan.tasks, plan.robots, parallel=plan.parallel, signals=plan.job.cell.interlocks
    )
    files: dict[Path, bytes | str] = {}
    if rapid is not None:
        for name in plan.tasks.robots:
            if plan.tasks.for_robot(name):
                files[rapid / f"SDI_{name.upper()}.mod"] = rapid_module(
                    plan.job, plan.tasks, plan.motion, plan.robots[name], interlocks=interlocks
                )
    if python is not None:
        files[python] = python_program(
            plan.job,
            plan.tasks,
            plan.motion,
            plan.robots,
            command=f"run {run_id}",
            filename=python.name,
            interlocks=interlocks,
        )
    for path in outputs.commit(files):
        _line(out, "wrote", "", path)


BackendOption = Annotated[
    str, typer.Option("--backend", help="rules (offline, default) | local (llama.cpp) | openai")
]
MethodOption = Annotated[str, typer.Option("--method", help="a method of the paper's Table II")]
DbOption = Annotated[
    Path | None, typer.Option("--db", help="run database (default: user data dir; $SDI_DB)")
]


def _model(backend: str, as_json: bool, stack: ExitStack, timeout: float | None = None) -> Any:
    """The chat model for a backend (None: rules); a local server stops when `stack` closes.
    While it waits for the model, a spinner on stderr says what for (only on a terminal)."""
    from sdi.llm import open_backend

    waiting = (lambda text: err.status(text, spinner="dots")) if err.is_terminal else None
    try:
        return open_backend(backend, stack, timeout=timeout, waiting=waiting)
    except InputError as exc:
        _bad_input(exc, as_json)


APPROVE_WORDS = ("a", "approve", "y", "yes", "ok")
EDITABLE = ("design_review", "recovery_review", "edit_review", "failure_report")
"""The reviews an edits file may answer."""
REJECT_WORDS = ("r", "reject", "n", "no")


def _answer(text: str, kind: str) -> dict[str, Any] | None:
    """An operator's typed answer at a review, or None if it is not one (ask again)."""
    words = text.strip().split(maxsplit=1)
    word = words[0].lower() if words else ""
    if word in ("e", "edit") and kind in EDITABLE:
        if len(words) < 2:
            return None
        return {"action": "edit", "file": words[1]}
    if kind == "edit_review":
        choice = {
            "f": "repair",
            "fix": "repair",
            "repair": "repair",
            "u": "undo",
            "undo": "undo",
            "p": "replan",
            "replan": "replan",
            "r": "reject",
            "reject": "reject",
        }.get(word)
        return {"action": choice} if choice else None  # fmt: skip
    if kind == "failure_report":
        if word in ("r", "retry"):
            return {"action": "retry"}
        if word in ("s", "skill", "recover"):
            return {"action": "recover", "skill": words[1].strip()} if len(words) > 1 else None
        if word in ("x", "abort", "n", "no"):
            return {"action": "abort"}
        return None
    if word in APPROVE_WORDS:
        return {"action": "approve"}
    if word in ("x", "abort"):
        return {"action": "abort"}
    if word in REJECT_WORDS:
        if len(words) > 1 and kind in ("design_review", "recovery_review"):
            return {"action": "reject", "reason": words[1]}  # replan with the reason
        return {"action": "reject"}
    return None


def _show_record(waiting: dict[str, Any]) -> None:
    planning = waiting.get("planning") or {}
    out.print(
        f"commissioning record [bold]{waiting.get('record_hash')}[/bold]\n"
        f"  makespan {planning.get('makespan_s')} s, {planning.get('steps')} steps, "
        f"{'two arms in parallel' if planning.get('parallel') else 'one arm at a time'}"
    )
    for robot, parts in (planning.get("parts_per_robot") or {}).items():
        out.print(f"  {robot}: {len(parts)} steps: {' '.join(parts)}", markup=False)
    for note in planning.get("notes") or []:
        out.print(f"  note: {note}", markup=False)
    built = waiting.get("as_built")
    if built:
        placed = built.get("placed") or []
        out.print(
            f"[yellow]an earlier execution of this record was interrupted[/yellow] after "
            f"{len(placed)} of {planning.get('steps')} steps; already built:"
        )
        for p in placed:
            x, y, z = (round(v, 4) for v in p["pose"][:3])
            out.print(f"  {p['part_id']} (step {p['step'] + 1}, {p['robot']}) at ({x}, {y}, {z})")
        out.print("Continuing sets the arms to the start of the first step not done.")


def _edits_file(path: str | Path) -> Any:
    return _read_edits(Path(str(path).strip()))


def _edits_or_exit(path: str | Path, as_json: bool) -> Any:
    try:
        return _edits_file(path)
    except InputError as exc:
        _bad_input(exc, as_json)


def _review(status: Any, as_json: bool) -> dict[str, Any] | None:
    """Ask the operator at an interrupt; None when nobody can answer (non-interactive)."""
    waiting = status.waiting_for or {}
    if as_json or not sys.stdin.isatty():
        return None
    kind = str(waiting.get("kind"))
    if waiting.get("refused"):
        err.print(f"[bold red]edit refused:[/bold red] {waiting['refused']}", markup=True)
    if kind in ("design_review", "recovery_review", "edit_review"):
        from sdi.model.layout import parse_layout
        from sdi.render import top_view

        layout, _ = parse_layout(waiting.get("layout") or {"objects": []})
        out.print(top_view(layout, CellConfig()))
        if waiting.get("sequence"):
            out.print(f"sequence: {' → '.join(waiting.get('sequence') or [])}", markup=False)
        for line in _review_lines(waiting):
            out.print(line, markup=False)
        question, default = {
            "design_review": (
                "Design review: [a]pprove, [e]dit FILE.json, [r]eject REASON (replan), [x] abort",
                "a",
            ),
            "recovery_review": (
                "The recovery changed the shape: [a]pprove, [e]dit FILE.json, [r]eject REASON "
                "(replan), [x] abort",
                "x",
            ),
            "edit_review": (
                "Your edit breaks constraints: [f]ix (the repair), [u]ndo, re[p]lan, "
                "[e]dit FILE.json, [r]eject",
                "f" if waiting.get("repair") else "u",
            ),
        }[kind]
    elif kind in ("pre_execute", "resume_execution"):
        _show_record(waiting)
        question, default = "Execute this record on the robots (sim)? [a]pprove / [r]eject", "r"
    else:
        _line(out, "failure:", "red", _describe_failure(waiting.get("failure")))
        for v in waiting.get("violations") or []:
            _line(out, "  -", "", v)
        for k in waiting.get("skills") or []:
            _line(out, f"  skill {k.get('name')}:", "", k.get("does"))
        question = "Failure report: [s]kill NAME, [r]etry, [e]dit FILE.json, [x] abort"
        default = "x"
    while True:
        decision = _answer(typer.prompt(question, default=default), kind)
        if decision is None:
            err.print("please answer with one of the choices shown")
            continue
        if decision["action"] != "edit":
            break
        try:
            return {"action": "edit", "edits": _edits_file(decision["file"])}
        except InputError as exc:  # a typo in a file name: say so and ask again
            _line(err, "error:", "bold red", exc)
    if decision["action"] == "approve" and waiting.get("record_hash"):
        decision["record_hash"] = waiting["record_hash"]
    return decision


def _review_lines(waiting: dict[str, Any]) -> list[str]:
    """What a review must say besides the layout: a recovery's change, an edit's violations,
    its repair and the nearest valid order, what became of the operator's last edit."""
    lines = []
    recovery = waiting.get("recovery")
    if isinstance(recovery, dict):
        lines.append(f"recovery: {recovery.get('summary')}")
    if waiting.get("replanned"):
        lines.append(str(waiting["replanned"]))
    for v in (waiting.get("violations") or [])[:10]:
        if isinstance(v, dict):
            lines.append(f"  ✗ {v.get('constraint')}: {v.get('message')} — {v.get('hint')}")
    repair = waiting.get("repair")
    if waiting.get("kind") == "edit_review":
        lines.append(f"repair: {repair.get('summary')}" if isinstance(repair, dict)
                     else "repair: none keeps this edit valid")  # fmt: skip
    if waiting.get("nearest_order"):
        lines.append(f"nearest valid order: {' → '.join(waiting['nearest_order'])}")
    outcome = waiting.get("edit_outcome")
    if isinstance(outcome, dict) and outcome.get("choice") not in (None, "kept"):
        count = len(outcome.get("changes") or [])
        lines.append(f"your edit → {outcome['choice']}: {count} part(s) differ from your layout")
    return lines


def _describe_planning(summary: Any) -> str:
    """The pre-execution summary in words: steps per robot, makespan, parallel, notes."""
    if not isinstance(summary, dict):
        return str(summary)
    per_robot = summary.get("steps_per_robot") or {}
    robots = ", ".join(f"{name} {n}" for name, n in per_robot.items())
    text = f"{summary.get('steps', '?')} pick-and-place steps" + (f" ({robots})" if robots else "")
    if isinstance(summary.get("makespan_s"), int | float):
        text += f", makespan {summary['makespan_s']:.1f} s"
    text += ", arms in parallel" if summary.get("parallel") else ", one arm at a time"
    notes = summary.get("notes") or []
    return text + (f"; {'; '.join(str(n) for n in notes)}" if notes else "")


def _describe_failure(failure: Any) -> str:
    """A failure event in words: its message, kind, part and step when known."""
    if not isinstance(failure, dict):
        return "the design did not pass the Inspector" if failure is None else str(failure)
    head = failure.get("message") or failure.get("error") or failure.get("type") or "failed"
    details = [
        f"{key} {failure[key]}"
        for key in ("error_type", "robot", "part_id", "step", "scenario")
        if failure.get(key) is not None
    ]
    return f"{head}" + (f" ({', '.join(details)})" if details else "")


def _drive(orch: Any, status: Any, as_json: bool) -> Any:
    while status.status == "paused":
        decision = _review(status, as_json)
        if decision is None:
            break
        status = orch.resume(status.run_id, decision)
    return status


def _finish(status: Any, as_json: bool) -> None:
    data = status.to_json_dict()
    if as_json:
        _emit(data)
    else:
        out.print_json(data=data)
        waiting = status.waiting_for or {}
        if waiting.get("refused"):
            err.print(f"[bold red]edit refused:[/bold red] {waiting['refused']}")
        if status.status == "paused":
            kind = waiting.get("kind")
            what = f" record {waiting['record_hash'][:12]}" if waiting.get("record_hash") else ""
            how = {
                "failure_report": "--retry (or --recover SKILL, --edit FILE, --reject)",
                "edit_review": "--choose repair|undo|replan (or --edit FILE, --reject)",
            }.get(str(kind), "--approve (or --reject, --edit FILE; --approve-all for every "
                             "later review too)")  # fmt: skip
            for line in _review_lines(waiting):
                err.print(line, markup=False)
            err.print(
                f"[yellow]paused at {kind}{what}[/yellow]: nothing moves without a human OK. "
                f"Continue with `sdi resume {status.run_id} {how}`"
            )
    if status.status == "paused" and (status.waiting_for or {}).get("refused"):
        raise typer.Exit(2)
    codes = {"success": 0, "paused": 0}
    raise typer.Exit(codes.get(status.status, 1))


PHASES = {
    "spec": "specified", "layout": "designed", "verification": "inspected",
    "review": "design review answered", "record": "motion planned: record",
    "confirm": "execution confirmed", "execution_started": "executing",
    "motion_started": "robots moving", "step_done": "part set down",
    "execution": "execution finished", "route": "replanning",
    "execution_interrupted": "found an interrupted execution", "refused": "refused",
    "edit_refused": "edit refused", "failure": "failure", "recovery": "recovered",
    "edit_check": "your edit breaks constraints", "edit_resolved": "your edit",
}  # fmt: skip


def _progress(orch: Any, as_json: bool) -> None:
    """Show the run's progress by phase on stderr as its events are stored (not for --json)."""
    if as_json:
        return
    start = time.monotonic()

    def show(m: Any) -> None:
        what = PHASES.get(m.type)
        if what is None:
            return
        p = m.payload
        detail = {
            "verification": lambda: (
                "passed" if p.get("passed") else f"{len(p.get('violations', []))} violation(s)"
            ),
            "record": lambda: f"{str(p.get('record_hash'))[:12]}, makespan {p.get('makespan_s')} s",
            "step_done": lambda: (
                f"{p.get('part_id')} by {p.get('robot')} ({p.get('completed')} done)"
            ),
            "route": lambda: str(p.get("action")),
            "execution": lambda: f"{p.get('status')}, V_traj {p.get('v_traj')}",
            "refused": lambda: str(p.get("error")),
            "edit_refused": lambda: str(p.get("error")),
            "recovery": lambda: str(p.get("summary")),
            "edit_check": lambda: (
                f"{len(p.get('violations') or [])} violation(s); repair: "
                f"{(p.get('repair') or {}).get('summary', 'none')}"
            ),
            "edit_resolved": lambda: str(p.get("choice")),
        }.get(m.type, lambda: "")()
        line = f"[dim]{time.monotonic() - start:7.1f} s[/dim]  {what}"
        err.print(f"{line}  {escape(detail)}" if detail else line)

    orch.bus.listeners.append(show)


def _busy(exc: Exception, as_json: bool) -> NoReturn:
    if as_json:
        _emit({"status": "busy", "error": str(exc)})
    else:
        err.print(f"[bold red]busy:[/bold red] {exc}")
    raise typer.Exit(1)


@app.command("run")
def run_cmd(
    command: Annotated[
        str | None, typer.Argument(help="what to build, in plain language (or use --layout)")
    ] = None,
    layout_file: Annotated[
        Path | None,
        typer.Option(
            "--layout",
            help="run a layout file (JSON, or a saved plan result) instead of a command: the "
            "Inspector, the reviews and the record's approval as for a command",
        ),
    ] = None,
    approve: Annotated[
        bool, typer.Option("--approve", help="approve the design review (execution still asks)")
    ] = False,
    approve_all: Annotated[
        bool,
        typer.Option("--approve-all", help="approve every review, execution included (unattended)"),
    ] = False,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
    backend: BackendOption = "rules",
    method: MethodOption = "Hybrid",
    fault: FaultOption = None,
    db: DbOption = None,
    llm_timeout: LlmTimeoutOption = None,
) -> None:
    """Run the whole orchestrator graph: plan, design, inspect, review, confirm, execute (sim)."""
    from sdi.orchestrator import Orchestrator, RunBusyError

    if (command is None) == (layout_file is None):
        _fail("give a COMMAND or --layout FILE (one of them)", json_out)
    _check_faults(fault, json_out)
    cell = _cell(cell_path, json_out)
    robots = _arms(arms, cell, json_out)
    given, sequence = _load(layout_file, cell, json_out) if layout_file else (None, None)
    if layout_file is not None:
        if not given:
            _fail(f"--layout: {layout_file} has no parts: nothing to build", json_out)
        command = f"layout file {layout_file.name}"
    assert command is not None
    db = _database(db)
    with ExitStack() as stack:
        model = _model(backend, json_out, stack, llm_timeout)
        try:
            orch = Orchestrator(db=db, cell=cell, model=model, arms=robots)
            stack.callback(orch.close)
            _progress(orch, json_out)
            run_id = orch.new_run_id()
            if not json_out:
                err.print(f"run {run_id}")
            with orch.owning(run_id):  # one process at a time, prompts included
                status = orch.start(
                    command, method=method, backend=backend, faults=list(fault or []),
                    approve=approve_all, run_id=run_id, layout=given, sequence=sequence,
                )  # fmt: skip
                waiting = status.waiting_for or {}
                if approve and status.status == "paused" and waiting.get("kind") == "design_review":
                    status = orch.resume(run_id, {"action": "approve", "by": "--approve"})
                status = _drive(orch, status, json_out)
        except InputError as exc:
            _bad_input(exc, json_out)
        except RunBusyError as exc:
            _busy(exc, json_out)
    _finish(status, json_out)


@app.command("resume")
def resume_cmd(
    run_id: Annotated[str, typer.Argument(help="the run to continue")],
    approve: Annotated[
        bool, typer.Option("--approve", help="answer the pending review (only that one): approve")
    ] = False,
    approve_all: Annotated[
        bool, typer.Option("--approve-all", help="approve the pending review and every later one")
    ] = False,
    reject: Annotated[
        bool,
        typer.Option(
            "--reject",
            help="answer the pending review: reject; the run ends (at a design review, add "
            "--reason to replan instead)",
        ),
    ] = False,
    reason: Annotated[
        str | None,
        typer.Option(
            "--reason",
            help="with --reject at a design review: why; the orchestrator replans, reading it "
            "after the command as a change (e.g. 'make it 4 high')",
        ),
    ] = None,
    retry: Annotated[
        bool, typer.Option("--retry", help="answer a failure report: plan the command again")
    ] = False,
    recover: Annotated[
        str | None,
        typer.Option(
            "--recover",
            help="answer a failure report: run one of the recovery skills it offers "
            "(shift, flatten, spread, modify)",
        ),
    ] = None,
    choose: Annotated[
        str | None,
        typer.Option(
            "--choose", help="answer an edit the Inspector refused: repair, undo or replan"
        ),
    ] = None,
    edit: Annotated[
        Path | None, typer.Option("--edit", help="answer with edits from a JSON file")
    ] = None,
    replan_with_cell: Annotated[
        bool,
        typer.Option(
            "--replan-with-cell", help="continue with the --cell given now: inspect and plan again"
        ),
    ] = False,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
    backend: Annotated[
        str | None, typer.Option("--backend", help="must match the run's backend (default: it)")
    ] = None,
    db: DbOption = None,
    llm_timeout: LlmTimeoutOption = None,
) -> None:
    """Continue a paused or interrupted run (after a review prompt, a crash or a kill), with the
    method, backend, arms, faults and cell it was started with."""
    from sdi.orchestrator import Orchestrator, RunBusyError

    flags = {"--approve": approve, "--approve-all": approve_all, "--reject": reject,
             "--edit": edit is not None, "--retry": retry, "--recover": recover is not None,
             "--choose": choose is not None}  # fmt: skip
    answers = [name for name, given in flags.items() if given]
    if len(answers) > 1:
        _bad_input(InputError(f"give one answer, not {' and '.join(answers)}"), json_out)
    if reason is not None and not reject:
        _bad_input(InputError("--reason goes with --reject", field="--reason"), json_out)
    decision: dict[str, Any] | None = None
    if edit is not None:
        decision = {"action": "edit", "edits": _edits_or_exit(edit, json_out)}
    elif reject:
        decision = {"action": "reject"}
        if reason is not None and reason.strip():
            decision["reason"] = reason.strip()
    elif retry:
        decision = {"action": "retry"}
    elif recover is not None:
        decision = {"action": "recover", "skill": recover}
    elif choose is not None:
        if choose not in ("repair", "undo", "replan"):
            _bad_input(InputError(f"{choose!r}: choose repair, undo or replan",
                                  field="--choose"), json_out)  # fmt: skip
        decision = {"action": choose}
    cell = _cell(cell_path, json_out) if cell_path is not None else None
    db = _database(db, run_id=run_id)
    with ExitStack() as stack:
        try:
            orch = Orchestrator(db=db, cell=cell, create=False)
            stack.callback(orch.close)
            info = orch.info(run_id)
            if backend is not None and backend != info.backend:
                raise InputError(
                    f"run {run_id} was started with backend {info.backend!r}, not {backend!r}; "
                    "a run continues with what it was started with (omit --backend)",
                    field="--backend",
                )
            wanted = arms.split(",") if arms else None
            if wanted is not None and wanted != info.arms:
                raise InputError(
                    f"run {run_id} was started with arms {info.arms or 'all'}, not {wanted}",
                    field="--arms",
                )
            orch.model = _model(info.backend, json_out, stack, llm_timeout)
            _progress(orch, json_out)
            with orch.owning(run_id):  # one process at a time, prompts included
                kind = (orch.status(run_id).waiting_for or {}).get("kind")
                if reason is not None and kind not in ("design_review", "recovery_review"):
                    raise InputError(
                        f"run {run_id} waits on {kind or 'nothing'}; a reason replans only "
                        "at a design review (--reject alone ends the run)",
                        field="--reason",
                    )
                if ((retry or recover is not None) and kind != "failure_report") or (
                    choose and kind != "edit_review"
                ):
                    raise InputError(
                        f"run {run_id} waits on {kind or 'nothing'}, which {answers[0]} does "
                        "not answer",
                        field=answers[0],
                    )
                if approve or approve_all:
                    pending = orch.status(run_id)
                    if kind == "failure_report":
                        raise InputError(
                            f"run {run_id} waits on a failure report, which is not approved: "
                            "answer it with --retry (plan the command again), --recover SKILL, "
                            "--edit FILE, --reject (abort), or interactively",
                            field=answers[0],
                        )
                    if kind == "edit_review":
                        raise InputError(
                            f"run {run_id} waits on your edit, which the Inspector refused: "
                            "answer it with --choose repair|undo|replan, --edit FILE or --reject",
                            field=answers[0],
                        )
                    decision = {"action": "approve", "by": answers[0]}
                    record_hash = (pending.waiting_for or {}).get("record_hash")
                    if record_hash:
                        decision["record_hash"] = record_hash
                status = orch.resume(
                    run_id, decision, approve_all=approve_all, replan_with_cell=replan_with_cell
                )
                if decision is None:
                    status = _drive(orch, status, json_out)
        except InputError as exc:
            if "no run database" in str(exc):
                exc = InputError(f"no run {run_id!r}: {exc}")
            _bad_input(exc, json_out)
        except RunBusyError as exc:
            _busy(exc, json_out)
    _finish(status, json_out)


@app.command("log")
def log_cmd(
    run_id: Annotated[str, typer.Argument(help="the run whose event stream to show")],
    json_out: JsonOption = False,
    follow: Annotated[
        bool, typer.Option("--follow", "-f", help="keep printing events until the run stops")
    ] = False,
    after: Annotated[int, typer.Option("--after", help="only events after this number")] = 0,
    db: DbOption = None,
) -> None:
    """The run's event stream (audit trail): who told whom what, in order, one number each."""
    from sdi.orchestrator import MessageBus
    from sdi.orchestrator.lease import RunLease

    path = _database(db, run_id=run_id)
    try:
        bus = MessageBus(path, create=False)
    except InputError as exc:
        _bad_input(InputError(f"no run {run_id!r}: {exc}"), json_out)
    if not bus.history(run_id) and not follow:
        _bad_input(InputError(f"no run {run_id!r} in {path}", field="RUN_ID"), json_out)
    lease = RunLease(path, run_id)

    def quiet(new: list[Any]) -> bool:
        return not follow or (not new and lease.holder() is None)

    if json_out and not follow:
        history = bus.history(run_id, after=after)
        _emit({"run_id": run_id, "messages": [m.to_json_dict() for m in history]})
        return
    try:
        for m in bus.follow(run_id, after=after, done=quiet):
            if json_out:
                _emit(m.to_json_dict())
            else:
                body = json.dumps(m.payload, default=str)
                out.print(
                    f"{m.seq:>5}  {m.sender} → {m.receiver}  {m.type}  {body[:160]}",
                    markup=False,
                    soft_wrap=True,
                )
    except KeyboardInterrupt:
        pass
    finally:
        bus.close()


@app.command("twin")
def twin_cmd(
    host: Annotated[str, typer.Option("--host", help="address to listen on")] = "127.0.0.1",
    port: Annotated[int, typer.Option("--port", help="TCP port (0: any free one)")] = 8765,
    token: Annotated[
        str | None,
        typer.Option(
            "--token",
            envvar="SDI_TWIN_TOKEN",
            help="secret every client must present (required beyond loopback)",
        ),
    ] = None,
    plan_command: Annotated[
        str | None,
        typer.Option("--plan", help="start a run with this command first; the page opens on it"),
    ] = None,
    cell_path: CellOption = None,
    db: DbOption = None,
) -> None:
    """Serve the digital twin: review, edit, approve, preview and watch runs in a browser."""
    import socket

    from sdi.twin.server import check_assets, check_bind, create_app
    from sdi.twin.service import Twin

    try:
        check_bind(host, token)
        check_assets()
        if not 0 <= port <= 65535:
            raise InputError(f"{port} is not a TCP port; give 0…65535", field="--port")
        cell = _cell(cell_path, False)
        db = _database(db)
        sock = socket.socket(socket.AF_INET6 if ":" in host else socket.AF_INET)
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind((host, port))
        except OSError as exc:
            raise InputError(
                f"cannot listen on {host}:{port} ({exc.strerror}); choose another --port",
                field="--port",
            ) from None
        twin = Twin(db, cell)
    except InputError as exc:
        _bad_input(exc, False)
    run_id = None
    if plan_command is not None:
        try:
            run_id = twin.start(plan_command)
        except InputError as exc:
            _bad_input(exc, False)
        err.print(f"planning run {run_id}: {plan_command}")
        twin.wait()
    import uvicorn

    app_ = create_app(twin, token=token)
    shown = "127.0.0.1" if host in ("0.0.0.0", "::") else host
    url = f"http://{shown}:{sock.getsockname()[1]}/"
    if token:
        url += f"?token={token}"
    if run_id:
        url += f"#{run_id}"
    out.print(f"SDI twin: {url}", markup=False, soft_wrap=True)
    err.print(f"run database {db}; Ctrl-C stops the server (runs stay in the database)")
    config = uvicorn.Config(app_, log_level="warning", ws="websockets-sansio")
    try:
        uvicorn.Server(config).run(sockets=[sock])
    finally:
        twin.close()


@app.command("graph")
def graph_cmd() -> None:
    """Print the orchestrator's graph as LangGraph draws it (Mermaid)."""
    from sdi.orchestrator.graph import mermaid

    sys.stdout.write(mermaid() + "\n")


@app.command()
def skills() -> None:
    """Print the skill registry as OpenAI function-calling tool schemas (JSON)."""
    from sdi.skills import default_registry

    _emit({"tools": default_registry().tools()})


def main() -> None:
    app()


if __name__ == "__main__":
    main()
