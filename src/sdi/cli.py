"""The `sdi` command line. Thin: it parses, calls the library, prints.

Exit codes: 0 success, 1 planning or verification failure, 2 bad input (the message names the
field or part and the fix; no stack trace).
"""

from __future__ import annotations

import json
import sys
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
) -> None:
    """Plan a command end to end: spec → layout → verification → assembly sequence."""
    cell = _cell(cell_path, json_out)
    result = run_plan(command, cell)
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
    fault: Annotated[
        list[str] | None, typer.Option("--fault", help="inject a failure scenario (repeatable)")
    ] = None,
    report_dir: Annotated[
        Path | None, typer.Option("--report", help="write report.json and deviation.png here")
    ] = None,
) -> None:
    """Plan motion for a verified layout, execute it in simulation, monitor and report."""
    from sdi.commission import execute
    from sdi.execute.faults import SCENARIOS
    from sdi.monitor import plot_deviation

    unknown = [f for f in fault or [] if f not in SCENARIOS]
    if unknown:
        _bad_input(
            InputError(
                f"unknown scenario {unknown}; choose from {sorted(SCENARIOS)}", field="--fault"
            ),
            json_out,
        )
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


def _human_ok(question: str, approve: bool, as_json: bool) -> None:
    """Nothing moves without a person's OK: a prompt, or --approve for unattended runs."""
    if approve:
        return
    if not sys.stdin.isatty():
        message = f"{question} needs a human OK: run interactively or pass --approve"
        if as_json:
            _emit({"status": "refused", "error": message})
        else:
            err.print(f"[bold red]refused:[/bold red] {message}")
        raise typer.Exit(1)
    if not typer.confirm(question, default=False):
        err.print("[yellow]stopped by the operator; nothing moved[/yellow]")
        raise typer.Exit(1)


@app.command("run")
def run_cmd(
    command: Annotated[str, typer.Argument(help="what to build, in plain language")],
    approve: Annotated[
        bool, typer.Option("--approve", help="approve the design and the execution (unattended)")
    ] = False,
    json_out: JsonOption = False,
    cell_path: CellOption = None,
    arms: ArmsOption = None,
    epsilon: Annotated[float, typer.Option(help="V_traj threshold on δ, rad")] = 0.05,
    report_dir: Annotated[
        Path | None, typer.Option("--report", help="write plan.json, report.json, deviation.png")
    ] = None,
) -> None:
    """Plan, review, commission, confirm, execute in simulation and monitor one command."""
    from sdi.commission import commission, execute
    from sdi.errors import MotionPlanningError
    from sdi.monitor import deviation, plot_deviation

    cell = _cell(cell_path, json_out)
    result = run_plan(command, cell)
    if not json_out:
        print_plan(out, result, cell)
    if result.status != "success" or result.layout is None:
        if json_out:
            _emit({"design": result.to_json_dict()})
        raise typer.Exit({"failure": 1, "error": 2}.get(result.status, 1))
    _human_ok("Approve this design for the robots?", approve, json_out)
    try:
        plan = commission(
            result.layout, cell, sequence=result.sequence, arms=arms.split(",") if arms else None
        )
    except InputError as exc:
        _bad_input(exc, json_out)
    except MotionPlanningError as exc:
        event = getattr(exc.event, "to_json_dict", lambda: None)()
        if json_out:
            _emit(
                {
                    "design": result.to_json_dict(),
                    "status": "failure",
                    "error": str(exc),
                    "event": event,
                }
            )
        else:
            err.print(f"[bold red]motion planning failed:[/bold red] {exc}")
        raise typer.Exit(1) from None
    summary = plan.summary()
    if not json_out:
        out.print(f"[bold]commissioning[/bold]: {summary}")
    _human_ok(
        f"Execute {summary['steps']} steps (makespan {summary['makespan_s']} s)?", approve, json_out
    )
    executed, report = execute(plan, epsilon=epsilon)
    report = {"design": result.to_json_dict(), "planning": summary, **report}
    if report_dir is not None:
        report_dir.mkdir(parents=True, exist_ok=True)
        (report_dir / "report.json").write_text(
            json.dumps(report, indent=2) + "\n", encoding="utf-8"
        )
        if executed.executed and set(executed.executed) == set(plan.motion.trajectories):
            plot_deviation(
                deviation(plan.motion.trajectories, executed.executed),
                epsilon,
                report_dir / "deviation.png",
            )
    if json_out:
        _emit(report)
    else:
        out.print_json(data={k: v for k, v in report.items() if k != "design"})
    raise typer.Exit(0 if report["status"] == "success" and report["v_traj"] == "pass" else 1)


@app.command()
def skills() -> None:
    """Print the skill registry as OpenAI function-calling tool schemas (JSON)."""
    from sdi.skills import default_registry

    _emit({"tools": default_registry().tools()})


def main() -> None:
    app()


if __name__ == "__main__":
    main()
