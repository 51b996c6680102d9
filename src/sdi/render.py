"""Rich terminal views of plans: summary, top-down height map, violations, sequence."""

from __future__ import annotations

import numpy as np
from rich.console import Console, Group, RenderableType
from rich.panel import Panel
from rich.table import Table
from rich.text import Text

from sdi.inspector.violation import Violation
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout

LEVEL_STYLES = [
    "green",
    "cyan",
    "blue",
    "magenta",
    "yellow",
    "red",
    "bright_green",
    "bright_cyan",
    "bright_blue",
    "bright_magenta",
]


MAX_CELLS = 120
"""Largest top view drawn, cubes along x or y (a larger workspace is described, not drawn)."""


def top_view(layout: Layout, cell: CellConfig) -> Text:
    """Column heights in parts on the cube grid, seen from above (x down the page, y across)."""
    ws, s = cell.workspace, cell.cube[0]
    nx = round((ws.x_max - ws.x_min) / s)
    ny = round((ws.y_max - ws.y_min) / s)
    if nx > MAX_CELLS or ny > MAX_CELLS:
        return Text(
            f"top view omitted: the workspace is {nx} × {ny} cubes (at most {MAX_CELLS} a side)",
            style="dim",
        )
    levels = np.zeros((nx, ny), dtype=int)
    lo = layout.centres - layout.half_extents
    hi = layout.centres + layout.half_extents
    for k in range(len(layout)):
        # cells whose centre lies inside the part's footprint (half-cell offsets round down)
        i0 = max(0, int(np.floor((lo[k, 0] - ws.x_min) / s + 0.5 + 1e-6)))
        i1 = min(nx, max(i0 + 1, int(np.floor((hi[k, 0] - ws.x_min) / s + 0.5 + 1e-6))))
        j0 = max(0, int(np.floor((lo[k, 1] - ws.y_min) / s + 0.5 + 1e-6)))
        j1 = min(ny, max(j0 + 1, int(np.floor((hi[k, 1] - ws.y_min) / s + 0.5 + 1e-6))))
        level = round(hi[k, 2] / cell.cube[2])
        levels[i0:i1, j0:j1] = np.maximum(levels[i0:i1, j0:j1], level)
    text = Text()
    text.append(
        f"top view: y {ws.y_max:g} m (left) … {ws.y_min:g} m (right), "
        f"x {ws.x_min:g} m (front, top row) … {ws.x_max:g} m\n",
        style="dim",
    )
    for i in range(nx):
        for j in reversed(range(ny)):
            v = levels[i, j]
            if v:
                text.append(f"{v:>2}", style=LEVEL_STYLES[(v - 1) % len(LEVEL_STYLES)])
            else:
                text.append(" ·", style="dim")
        text.append("\n")
    return text


def violations_table(violations: tuple[Violation, ...] | list[Violation], limit: int = 20) -> Table:
    table = Table(title=f"{len(violations)} violation(s)", show_lines=False, title_style="bold red")
    table.add_column("constraint", style="red")
    table.add_column("parts")
    table.add_column("message")
    table.add_column("hint", style="yellow")
    for v in list(violations)[:limit]:
        ids = ", ".join(v.objects[:4]) + (" …" if len(v.objects) > 4 else "")
        # Text, not markup: a message such as "quaternion [w, x, y, z]" is shown as written.
        table.add_row(*(Text(cell) for cell in (v.constraint.value, ids, v.message, v.hint)))
    if len(violations) > limit:
        table.caption = f"(+{len(violations) - limit} more; use --json for all)"
    return table


def plan_panel(result: object, cell: CellConfig) -> Panel:
    from sdi.pipeline import PlanResult

    assert isinstance(result, PlanResult)
    colour = {"success": "green", "partial": "yellow", "failure": "red", "error": "red"}[
        result.status
    ]
    lines: list[RenderableType] = [Text.assemble(("command  ", "bold"), result.command)]
    if result.spec is not None:
        lines.append(Text.assemble(("read as  ", "bold"), result.spec.describe()))
    for note in result.notes or (result.spec.notes if result.spec is not None else ()):
        style = "bold yellow" if note.startswith("ignored") else "yellow"
        lines.append(Text.assemble(("note     ", "bold yellow"), (note, style)))
    if result.layout is not None:
        n = len(result.layout)
        levels = len({round(p.position[2], 3) for p in result.layout})
        lines.append(Text.assemble(("layout   ", "bold"), f"{n} parts, {levels} level(s)"))
        lines.append(top_view(result.layout, cell))
    if result.sequence:
        seq = " → ".join(result.sequence[:30]) + (" …" if len(result.sequence) > 30 else "")
        lines.append(Text.assemble(("sequence ", "bold"), seq))
    if result.violations:
        lines.append(violations_table(result.violations))
    if result.error and not result.violations:
        lines.append(Text.assemble(("error    ", "bold red"), result.error))
    if result.understood:
        lines.append(Text.assemble(("understood ", "bold"), str(result.understood)))
    lines.append(Text(f"{result.seconds * 1000:.1f} ms, {result.llm_calls} LLM calls", style="dim"))
    return Panel(Group(*lines), title=f"[{colour}]{result.status}[/{colour}]", border_style=colour)


def print_plan(console: Console, result: object, cell: CellConfig) -> None:
    console.print(plan_panel(result, cell))
