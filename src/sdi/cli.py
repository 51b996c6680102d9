"""The `sdi` command line. Thin: it parses, calls the library, prints.

Exit codes: 0 success, 1 planning or verification failure, 2 bad input (the message names the
field or part and the fix; no stack trace).
"""

from __future__ import annotations

import json
import sys
import time
from contextlib import ExitStack
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.console import Console
from rich.markup import escape

from sdi.errors import InputError, SDIError, SequencingError
from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence as run_sequence
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig
from sdi.model.layout import load_layout
from sdi.pipeline import plan as run_plan
from sdi.render import print_plan, violations_table

app = typer.Typer(
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


def _emit(data: dict[str, Any]) -> None:
    sys.stdout.write(json.dumps(data, indent=None) + "\n")


def _bad_input(exc: SDIError, as_json: bool) -> NoReturn:
    if as_json:
        _emit({"status": "error", "error": str(exc)})
    else:
        err.print(f"[bold red]error:[/bold red] {exc}")
    raise typer.Exit(2)


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
) -> None:
    """Plan a command end to end: spec → layout → verification → assembly sequence."""
    cell = _cell(cell_path, json_out)
    if backend == "rules" and method == "Hybrid":
        result = run_plan(command, cell)
    else:
        from sdi.pipeline import plan_with

        with ExitStack() as stack:
            model = _model(backend, json_out, stack)
            try:
                result = plan_with(command, method, model, cell)
            except InputError as exc:
                _bad_input(exc, json_out)
    data = result.to_json_dict()
    if out_file is not None and result.status == "success":
        tmp = out_file.with_suffix(out_file.suffix + ".tmp")
        tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        tmp.replace(out_file)
    if json_out:
        _emit(data)
    else:
        print_plan(out, result, cell)
    raise typer.Exit({"success": 0, "failure": 1, "error": 2}[result.status])


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
            err.print(f"[bold red]no sequence:[/bold red] {exc}")
        raise typer.Exit(1) from None
    if json_out:
        _emit({"status": "success", "sequence": order})
    else:
        out.print(" → ".join(order))


@app.command()
def bench(
    out_file: Annotated[
        Path | None, typer.Option("--out", help="write the results JSON here")
    ] = None,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
) -> None:
    """Run the 70-command evaluation suite on the offline front end."""
    from rich.progress import Progress

    from sdi.bench.runner import run_suite
    from sdi.bench.suite import SUITE

    cell = _cell(cell_path, json_out)
    with Progress(console=err, transient=True) as progress:
        task = progress.add_task("commands", total=len(SUITE))
        result = run_suite(cell, progress=lambda *_: progress.advance(task))
    data = result.to_json_dict()
    if out_file is not None:
        out_file.parent.mkdir(parents=True, exist_ok=True)
        out_file.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    if json_out:
        _emit(data)
    else:
        out.print(result.markdown_table())
        for record in data["commands"]:
            if not record["accepted"]:
                out.print(f"[red]✗[/red] {record['id']} {record['text']!r}: {record['reason']}")


FaultOption = Annotated[
    list[str] | None, typer.Option("--fault", help="inject a failure scenario (repeatable)")
]


def _check_faults(names: list[str] | None, as_json: bool) -> None:
    from sdi.execute.faults import SCENARIOS

    unknown = [f for f in names or [] if f not in SCENARIOS]
    if unknown:
        message = f"unknown scenario {unknown}; choose from {sorted(SCENARIOS)}"
        _bad_input(InputError(message, field="--fault"), as_json)


ArmsOption = Annotated[
    str | None,
    typer.Option("--arms", help="comma-separated robots to use (default: every robot of the cell)"),
]


def _commission(layout_file: Path, cell_path: Path | None, arms: str | None, as_json: bool) -> Any:
    from sdi.commission import commission
    from sdi.errors import MotionPlanningError, UnverifiedPlanError

    cell = _cell(cell_path, as_json)
    layout, sequence = _load(layout_file, cell, as_json)
    try:
        return commission(layout, cell, sequence=sequence, arms=arms.split(",") if arms else None)
    except UnverifiedPlanError as exc:
        if as_json:
            _emit({"status": "refused", "error": str(exc), "violations": exc.violations})
        else:
            err.print(f"[bold red]refused:[/bold red] {exc}")
            for v in exc.violations:
                err.print(f"  - {v}")
        raise typer.Exit(1) from None
    except InputError as exc:
        _bad_input(exc, as_json)
    except MotionPlanningError as exc:
        event = getattr(exc.event, "to_json_dict", lambda: None)()
        if as_json:
            _emit({"status": "failure", "error": str(exc), "event": event})
        else:
            err.print(f"[bold red]motion planning failed:[/bold red] {exc}")
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
) -> None:
    """Plan motion for a verified layout, execute it in simulation, monitor and report."""
    from sdi.commission import execute
    from sdi.execute.faults import SCENARIOS
    from sdi.monitor import plot_deviation

    _check_faults(fault, json_out)
    if epsilon <= 0:
        _bad_input(InputError("must be > 0 rad", field="--epsilon"), json_out)
    plan = _commission(layout_file, cell_path, arms, json_out)
    result, report = execute(plan, epsilon=epsilon, faults=tuple(SCENARIOS[f] for f in fault or []))
    report = {"planning": plan.summary(), **report}
    if report_dir is not None:
        report_dir.mkdir(parents=True, exist_ok=True)
        (report_dir / "report.json").write_text(
            json.dumps(report, indent=2) + "\n", encoding="utf-8"
        )
        if result.executed and set(result.executed) == set(plan.motion.trajectories):
            from sdi.monitor import deviation

            plot_deviation(
                deviation(plan.motion.trajectories, result.executed),
                epsilon,
                report_dir / "deviation.png",
            )
    if json_out:
        _emit(report)
    else:
        out.print_json(data=report)
    raise typer.Exit(0 if report["status"] == "success" and report["v_traj"] == "pass" else 1)


@app.command("export")
def export_cmd(
    layout_file: Annotated[Path, typer.Argument(help="layout JSON or a saved plan result")],
    rapid: Annotated[
        Path | None, typer.Option("--rapid", help="directory for one RAPID module per robot")
    ] = None,
    python: Annotated[
        Path | None, typer.Option("--python", help="file for the Python program")
    ] = None,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
) -> None:
    """Export robot programs (ABB RAPID, abb-motion-program-exec Python) for a verified layout."""
    from sdi.export import python_program, rapid_module

    if rapid is None and python is None:
        _bad_input(InputError("give --rapid DIR and/or --python FILE"), False)
    plan = _commission(layout_file, cell_path, arms, False)
    written = []
    if rapid is not None:
        rapid.mkdir(parents=True, exist_ok=True)
        for name in plan.tasks.robots:
            if plan.tasks.for_robot(name):
                path = rapid / f"SDI_{name.upper()}.mod"
                path.write_text(
                    rapid_module(plan.job, plan.tasks, plan.motion, plan.robots[name]),
                    encoding="utf-8",
                )
                written.append(path)
    if python is not None:
        python.parent.mkdir(parents=True, exist_ok=True)
        python.write_text(
            python_program(
                plan.job,
                plan.tasks,
                plan.motion,
                plan.robots,
                command=str(layout_file),
                filename=python.name,
            ),
            encoding="utf-8",
        )
        written.append(python)
    for path in written:
        out.print(f"wrote {path}")


BackendOption = Annotated[
    str, typer.Option("--backend", help="rules (offline, default) | local (llama.cpp) | openai")
]
MethodOption = Annotated[str, typer.Option("--method", help="a method of the paper's Table II")]
DbOption = Annotated[
    Path | None, typer.Option("--db", help="run database (default: user data dir; $SDI_DB)")
]


def _model(backend: str, as_json: bool, stack: ExitStack) -> Any:
    """The chat model for a backend (None: rules); a local server stops when `stack` closes."""
    from sdi.llm import open_backend

    try:
        return open_backend(backend, stack)
    except InputError as exc:
        _bad_input(exc, as_json)


APPROVE_WORDS = ("a", "approve", "y", "yes", "ok")
REJECT_WORDS = ("r", "reject", "n", "no")


def _answer(text: str, kind: str) -> dict[str, Any] | None:
    """An operator's typed answer at a review, or None if it is not one (ask again)."""
    words = text.strip().split(maxsplit=1)
    word = words[0].lower() if words else ""
    if word in ("e", "edit") and kind in ("design_review", "failure_report"):
        if len(words) < 2:
            return None
        return {"action": "edit", "file": words[1]}
    if kind == "failure_report":
        if word in ("r", "retry"):
            return {"action": "retry"}
        if word in ("x", "abort", "n", "no"):
            return {"action": "abort"}
        return None
    if word in APPROVE_WORDS:
        return {"action": "approve"}
    if word in REJECT_WORDS:
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


def _edits_file(path: str) -> Any:
    try:
        return json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError, RecursionError) as exc:
        raise InputError(f"cannot read edits from {path}: {exc}", field="--edit") from None


def _read_edits(path: str, as_json: bool) -> Any:
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
    if kind == "design_review":
        from sdi.model.layout import parse_layout
        from sdi.render import top_view

        layout, _ = parse_layout(waiting.get("layout") or {"objects": []})
        out.print(top_view(layout, CellConfig()))
        out.print(f"sequence: {' → '.join(waiting.get('sequence') or [])}", markup=False)
        question, default = "Design review: [a]pprove, [e]dit FILE.json, [r]eject", "a"
    elif kind in ("pre_execute", "resume_execution"):
        _show_record(waiting)
        question, default = "Execute this record on the robots (sim)? [a]pprove / [r]eject", "r"
    else:
        out.print(f"failure: {waiting.get('failure')} {waiting.get('violations')}", markup=False)
        question, default = "Failure report: [r]etry, [e]dit FILE.json, [x] abort", "x"
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
            err.print(f"[bold red]error:[/bold red] {escape(str(exc))}")
    if decision["action"] == "approve" and waiting.get("record_hash"):
        decision["record_hash"] = waiting["record_hash"]
    return decision


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
            err.print(
                f"[yellow]paused at {kind}{what}[/yellow]: nothing moves without a human OK. "
                f"Continue with `sdi resume {status.run_id} --approve` (or --reject, --edit "
                "FILE; --approve-all for every later review too)"
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
    "edit_refused": "edit refused", "failure": "failure",
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
    command: Annotated[str, typer.Argument(help="what to build, in plain language")],
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
) -> None:
    """Run the whole orchestrator graph: plan, design, inspect, review, confirm, execute (sim)."""
    from sdi.orchestrator import Orchestrator, RunBusyError

    _check_faults(fault, json_out)
    cell = _cell(cell_path, json_out)
    with ExitStack() as stack:
        model = _model(backend, json_out, stack)
        try:
            orch = Orchestrator(
                db=db, cell=cell, model=model, arms=arms.split(",") if arms else None
            )
            stack.callback(orch.close)
            _progress(orch, json_out)
            run_id = orch.new_run_id()
            if not json_out:
                err.print(f"run {run_id}")
            with orch.owning(run_id):  # one process at a time, prompts included
                status = orch.start(
                    command, method=method, backend=backend, faults=list(fault or []),
                    approve=approve_all, run_id=run_id,
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
        bool, typer.Option("--reject", help="answer the pending review: reject")
    ] = False,
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
) -> None:
    """Continue a paused or interrupted run (after a review prompt, a crash or a kill), with the
    method, backend, arms, faults and cell it was started with."""
    from sdi.orchestrator import Orchestrator, RunBusyError

    flags = {"--approve": approve, "--approve-all": approve_all, "--reject": reject,
             "--edit": edit is not None}  # fmt: skip
    answers = [name for name, given in flags.items() if given]
    if len(answers) > 1:
        _bad_input(InputError(f"give one answer, not {' and '.join(answers)}"), json_out)
    decision: dict[str, Any] | None = None
    if edit is not None:
        decision = {"action": "edit", "edits": _read_edits(str(edit), json_out)}
    elif reject:
        decision = {"action": "reject"}
    cell = _cell(cell_path, json_out) if cell_path is not None else None
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
            orch.model = _model(info.backend, json_out, stack)
            _progress(orch, json_out)
            with orch.owning(run_id):  # one process at a time, prompts included
                if approve or approve_all:
                    pending = orch.status(run_id)
                    if (pending.waiting_for or {}).get("kind") == "failure_report":
                        raise InputError(
                            f"run {run_id} waits on a failure report, which is not approved: "
                            "answer it with --edit FILE, --reject (abort), or interactively "
                            "(retry / edit / abort)",
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
    from sdi.orchestrator import MessageBus, default_db
    from sdi.orchestrator.lease import RunLease

    path = db or default_db()
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
