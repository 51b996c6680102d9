"""The `sdi` command line. Thin: it parses, calls the library, prints.

Exit codes: 0 success, 1 planning or verification failure, 2 bad input (the message names the
field or part and the fix; no stack trace).
"""

from __future__ import annotations

import json
import sys
from contextlib import ExitStack
from pathlib import Path
from typing import Annotated, Any, NoReturn

import typer
from rich.console import Console

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
    llm_timeout: LlmTimeoutOption = None,
) -> None:
    """Plan a command end to end: spec → layout → verification → assembly sequence."""
    cell = _cell(cell_path, json_out)
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
        tmp = out_file.with_suffix(out_file.suffix + ".tmp")
        tmp.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        tmp.replace(out_file)
    if json_out:
        _emit(data)
    else:
        print_plan(out, result, cell)
        for note in result.notes:
            err.print(f"[yellow]{note}[/yellow]")
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


def _model(backend: str, as_json: bool, stack: ExitStack, timeout: float | None = None) -> Any:
    """The chat model for a backend (None: rules); a local server stops when `stack` closes.
    While it waits for the model, a spinner on stderr says what for (only on a terminal)."""
    from sdi.llm import open_backend

    waiting = (lambda text: err.status(text, spinner="dots")) if err.is_terminal else None
    try:
        return open_backend(backend, stack, timeout=timeout, waiting=waiting)
    except InputError as exc:
        _bad_input(exc, as_json)


def _review(status: Any, as_json: bool) -> dict[str, Any] | None:
    """Ask the operator at an interrupt; None when nobody can answer (non-interactive)."""
    waiting = status.waiting_for or {}
    if as_json or not sys.stdin.isatty():
        return None
    kind = waiting.get("kind")
    if kind == "design_review":
        from sdi.model.layout import parse_layout
        from sdi.render import top_view

        layout, _ = parse_layout(waiting.get("layout") or {"objects": []})
        out.print(top_view(layout, CellConfig()))
        out.print(f"sequence: {' → '.join(waiting.get('sequence') or [])}")
        answer = typer.prompt("Design review: [a]pprove, [e]dit FILE.json, [r]eject", default="a")
    elif kind == "pre_execute":
        out.print(f"planned: {waiting.get('planning')}")
        answer = typer.prompt("Execute on the robots (sim)? [a]pprove / [r]eject", default="r")
    else:
        out.print(f"[red]failure[/red]: {waiting.get('failure')} {waiting.get('violations')}")
        answer = typer.prompt("Failure report: [r]etry, [e]dit FILE.json, [x] abort", default="x")
    if answer.startswith("e"):
        path = answer.split(maxsplit=1)[1] if " " in answer else typer.prompt("edits file")
        return {"action": "edit", "edits": json.loads(Path(path).read_text(encoding="utf-8"))}
    if kind == "failure_report":
        return {"action": "retry" if answer.startswith("r") else "abort"}
    return {"action": "approve" if answer.startswith("a") else "reject"}


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
        if status.status == "paused":
            kind = (status.waiting_for or {}).get("kind")
            err.print(
                f"[yellow]paused at {kind}[/yellow]: nothing moves without a human OK. "
                f"Continue with `sdi resume {status.run_id} --approve` (or --reject, --edit FILE)"
            )
    codes = {"success": 0, "paused": 0}
    raise typer.Exit(codes.get(status.status, 1))


@app.command("run")
def run_cmd(
    command: Annotated[str, typer.Argument(help="what to build, in plain language")],
    approve: Annotated[
        bool, typer.Option("--approve", help="approve design and execution (unattended runs)")
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
    from sdi.orchestrator import Orchestrator

    _check_faults(fault, json_out)
    cell = _cell(cell_path, json_out)
    with ExitStack() as stack:
        model = _model(backend, json_out, stack, llm_timeout)
        orch = Orchestrator(db=db, cell=cell, model=model, arms=arms.split(",") if arms else None)
        try:
            status = orch.start(
                command, method=method, backend=backend, faults=list(fault or []), approve=approve
            )
        except InputError as exc:
            _bad_input(exc, json_out)
        if not json_out:
            err.print(f"run {status.run_id}")
        status = _drive(orch, status, json_out)
    _finish(status, json_out)


@app.command("resume")
def resume_cmd(
    run_id: Annotated[str, typer.Argument(help="the run to continue")],
    approve: Annotated[
        bool, typer.Option("--approve", help="answer the pending review: approve")
    ] = False,
    reject: Annotated[
        bool, typer.Option("--reject", help="answer the pending review: reject")
    ] = False,
    edit: Annotated[
        Path | None, typer.Option("--edit", help="answer with edits from a JSON file")
    ] = None,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
    backend: BackendOption = "rules",
    db: DbOption = None,
    llm_timeout: LlmTimeoutOption = None,
) -> None:
    """Continue a paused or interrupted run (after a review prompt, a crash or a kill)."""
    from sdi.orchestrator import Orchestrator

    decision: dict[str, Any] | None = None
    if edit is not None:
        try:
            edits = json.loads(edit.read_text(encoding="utf-8"))
        except (OSError, json.JSONDecodeError) as exc:
            _bad_input(InputError(f"cannot read edits: {exc}", field="--edit"), json_out)
        decision = {"action": "edit", "edits": edits}
    elif approve:
        decision = {"action": "approve"}
    elif reject:
        decision = {"action": "reject"}
    cell = _cell(cell_path, json_out)
    with ExitStack() as stack:
        model = _model(backend, json_out, stack, llm_timeout)
        orch = Orchestrator(db=db, cell=cell, model=model, arms=arms.split(",") if arms else None)
        try:
            status = orch.resume(run_id, decision)
        except InputError as exc:
            _bad_input(exc, json_out)
        if decision is None:
            status = _drive(orch, status, json_out)
        elif approve:
            while (
                status.status == "paused"
                and (status.waiting_for or {}).get("kind") != "failure_report"
            ):
                status = orch.resume(run_id, {"action": "approve"})
    _finish(status, json_out)


@app.command("log")
def log_cmd(
    run_id: Annotated[str, typer.Argument(help="the run whose audit trail to show")],
    json_out: JsonOption = False,
    db: DbOption = None,
) -> None:
    """The message-bus audit trail of a run: who told whom what, in order."""
    from sdi.orchestrator import MessageBus, default_db

    bus = MessageBus(db or default_db())
    history = bus.history(run_id)
    if not history:
        _bad_input(InputError(f"no run {run_id!r}", field="RUN_ID"), json_out)
    if json_out:
        _emit({"run_id": run_id, "messages": [m.__dict__ for m in history]})
        return
    from rich.table import Table

    table = Table(title=f"run {run_id}")
    for col in ("#", "sender", "receiver", "type", "payload"):
        table.add_column(col)
    for m in history:
        table.add_row(
            str(m.seq), m.sender, m.receiver, m.type, json.dumps(m.payload, default=str)[:120]
        )
    out.print(table)


@app.command()
def skills() -> None:
    """Print the skill registry as OpenAI function-calling tool schemas (JSON)."""
    from sdi.skills import default_registry

    _emit({"tools": default_registry().tools()})


def main() -> None:
    app()


if __name__ == "__main__":
    main()
