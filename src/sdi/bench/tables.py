"""The paper's tables from a sweep's results: a JSON summary and Markdown per suite.

- ``commands`` (Tables II/III): per method, success % per group and overall, seconds and LLM
  messages per command;
- ``human-mods`` (Table IV): per modification and method, detected / corrected / edit kept;
- ``failures`` (Table V): per scenario and method, recovered / shape kept;
- ``motion`` (Table VI): per command, and per category as in the paper.

With the physics column, every table also says how many successful layouts stand. A method
that needs a model shows ``n/a`` on the ``rules`` backend. Over several seeds a cell shows ✓
(every seed), ✗ (none) or k/n.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from sdi.bench.cases import CaseResult
from sdi.bench.scenarios import FailureCase, HumanMod, load
from sdi.bench.suite import GROUPS

SHORT = {"MultiAgent-RuleOrch": "Rule", "PGEOrch": "PGE", "LGOrch": "LG", "Hybrid": "Hyb"}
"""The paper's column names for the methods of Tables IV and V."""


def label(method: str | None) -> str:
    return method or "pipeline"


def _methods(results: Sequence[CaseResult]) -> list[str | None]:
    seen: list[str | None] = []
    for r in results:
        if r.method not in seen:
            seen.append(r.method)
    return seen


def _frac(k: int, n: int) -> str:
    return f"{k}/{n}"


def _mark(values: Sequence[bool]) -> str:
    if not values:
        return "–"
    k = sum(values)
    return "✓" if k == len(values) else "✗" if k == 0 else _frac(k, len(values))


def _done(rs: Sequence[CaseResult]) -> list[CaseResult]:
    return [r for r in rs if r.outcome != "n/a"]


def _ok(r: CaseResult, name: str) -> bool:
    return r.outcome == "done" and bool(r.fields.get(name))


def _physics(rs: Sequence[CaseResult]) -> dict[str, int] | None:
    checked = [r.physics for r in rs if r.physics is not None]
    if not any(r.physics is not None for r in rs):
        return None
    return {"assembled": len(checked), "stand": sum(bool(p["stands"]) for p in checked)}


def _stands_cell(p: dict[str, int] | None) -> str:
    return "–" if p is None else _frac(p["stand"], p["assembled"])


def _problems(rs: Sequence[CaseResult]) -> dict[str, int]:
    return {
        o: sum(r.outcome == o for r in rs)
        for o in ("timeout", "error")
        if any(r.outcome == o for r in rs)
    }


def summarise(suite: str, results: Sequence[CaseResult]) -> dict[str, Any]:
    """The suite's table as JSON: one entry per method, and per-case rows where the paper
    has them."""
    return {
        "commands": _commands,
        "human-mods": _human_mods,
        "failures": _failures,
        "motion": _motion,
    }[suite](results)


def markdown(suite: str, summary: dict[str, Any]) -> str:
    return {
        "commands": _commands_md,
        "human-mods": _human_mods_md,
        "failures": _failures_md,
        "motion": _motion_md,
    }[suite](summary)


# -- Tables II/III -----------------------------------------------------------------------------


def _seconds(r: CaseResult) -> float:
    """The run's own time: planning for the pipeline, the orchestrator's run for a method (not
    the one-time loading of the language pipeline or a model)."""
    value = r.fields.get("seconds")
    return float(value) if isinstance(value, int | float) else r.seconds


def _group_stats(rs: Sequence[CaseResult]) -> dict[str, Any]:
    n = len(rs)
    if not n:
        return {"count": 0}
    return {
        "count": n,
        "successes": sum(_ok(r, "success") for r in rs),
        "success_rate": round(sum(_ok(r, "success") for r in rs) / n, 4),
        "seconds_per_command": round(sum(_seconds(r) for r in rs) / n, 4),
        "llm_calls_per_command": round(sum(r.llm_calls for r in rs) / n, 3),
    }


def _commands(results: Sequence[CaseResult]) -> dict[str, Any]:
    group_of = {c.id: getattr(c, "group", "") for c in load("commands")}
    out: dict[str, Any] = {}
    for m in _methods(results):
        rs = [r for r in results if r.method == m]
        done = _done(rs)
        if not done:
            out[label(m)] = {"n/a": True}
            continue
        groups = [g for g in GROUPS if any(group_of[r.case] == g for r in done)]
        out[label(m)] = {
            "overall": _group_stats(done),
            "groups": {g: _group_stats([r for r in done if group_of[r.case] == g]) for g in groups},
            "physics": _physics(done),
            "problems": _problems(done),
        }
    return {"methods": out}


def _commands_md(summary: dict[str, Any]) -> str:
    methods = summary["methods"]
    groups = sorted({g for s in methods.values() for g in s.get("groups", {})}, key=GROUPS.index)
    physics = any(s.get("physics") for s in methods.values())
    head = [
        "Method",
        *(f"{g} %" for g in groups),
        "Overall %",
        "s / command",
        "LLM messages / command",
    ] + (["stands (physics)"] if physics else [])
    lines = ["| " + " | ".join(head) + " |", "|---|" + "---:|" * (len(head) - 1)]
    for name, s in methods.items():
        if s.get("n/a"):
            lines.append(f"| {name} | " + " | ".join(["n/a"] * (len(head) - 1)) + " |")
            continue
        cells = [
            f"{100 * s['groups'][g]['success_rate']:.1f}" if g in s["groups"] else "–"
            for g in groups
        ]
        o = s["overall"]
        row = [
            name,
            *cells,
            f"{100 * o['success_rate']:.1f}",
            f"{o['seconds_per_command']:.3f}",
            f"{o['llm_calls_per_command']:.2f}",
        ]
        if physics:
            row.append(_stands_cell(s.get("physics")))
        lines.append("| " + " | ".join(row) + " |")
    return "\n".join(lines)


# -- Table IV ----------------------------------------------------------------------------------

_IV_KEYS = ("detected", "corrected", "edit_kept", "edit_as_close", "shape_kept")


def _human_mods(results: Sequence[CaseResult]) -> dict[str, Any]:
    methods = _methods(results)
    rows = []
    for case in load("human-mods"):
        assert isinstance(case, HumanMod)
        rs = [r for r in results if r.case == case.id]
        if not rs:
            continue
        steps = sorted({int(r.fields.get("steps", 0)) for r in rs if r.outcome == "done"})
        row: dict[str, Any] = {
            "id": case.id,
            "name": case.label,
            "type": case.type,
            "paper_steps": case.paper_steps,
            "steps": steps,
            "steps_note": case.steps_note,
            "methods": {},
        }
        for m in methods:
            mine = [r for r in rs if r.method == m]
            done = _done(mine)
            if not done:
                row["methods"][label(m)] = "n/a"
                continue
            cell: dict[str, Any] = {
                k: _mark([_ok(r, k) for r in done]) for k in (*_IV_KEYS, "entered")
            }
            refused = {str(r.fields.get("refused")) for r in done if r.fields.get("refused")}
            cell["refused"] = sorted(refused)
            cell["notes"] = sorted({n for r in done for n in r.fields.get("notes", [])})[:5]
            cell["problems"] = _problems(done)
            row["methods"][label(m)] = cell
        rows.append(row)
    totals: dict[str, Any] = {}
    for m in methods:
        done = _done([r for r in results if r.method == m])
        if not done:
            totals[label(m)] = "n/a"
            continue
        corrected = [r for r in done if _ok(r, "corrected")]
        totals[label(m)] = {
            "runs": len(done),
            **{k: sum(_ok(r, k) for r in done) for k in (*_IV_KEYS, "entered")},
            "stated": sum(bool(r.fields.get("notes")) for r in corrected),
            "physics": _physics(done),
        }
    return {"rows": rows, "totals": totals}


def _head(names: Sequence[str]) -> list[str]:
    return [SHORT.get(n, n) for n in names]


def _human_mods_md(summary: dict[str, Any]) -> str:
    names = list(summary["totals"])
    head = ["Human modification", "Type", "Steps (paper / built)", *_head(names)]
    lines = [
        "Each cell: detected / corrected / operator's edit kept / kept as close as possible "
        "(where the edit cannot be kept, e.g. a part put outside the workspace: no feasible pose "
        "is nearer the operator's target than the repaired one by more than a 5 mm grid step).",
        "",
        "| " + " | ".join(head) + " |",
        "|---|---|---:|" + ":---:|" * len(names),
    ]
    notes = sorted({row["steps_note"] for row in summary["rows"] if row["steps_note"]})
    marks = "¹²³⁴⁵⁶⁷⁸⁹"
    for row in summary["rows"]:
        built = "/".join(str(s) for s in row["steps"]) or "–"
        note = f" {marks[notes.index(row['steps_note'])]}" if row["steps_note"] else ""
        steps = f"{row['paper_steps']} / {built}{note}"
        cells = []
        for n in names:
            c = row["methods"][n]
            cells.append(
                "n/a"
                if c == "n/a"
                else f"{c['detected']} / {c['corrected']} / {c['edit_kept']} / "
                f"{c.get('edit_as_close', '–')}"
            )
        lines.append(f"| {row['name']} | {row['type']} | {steps} | " + " | ".join(cells) + " |")
    for key, title in (
        ("detected", "Detected"),
        ("corrected", "Corrected"),
        ("edit_kept", "Edit kept"),
        ("edit_as_close", "Edit kept as close as possible"),
        ("stated", "Correction stated in notes"),
    ):
        cells = []
        for n in names:
            t = summary["totals"][n]
            if t == "n/a":
                cells.append("n/a")
            else:
                of = t["corrected"] if key == "stated" else t["runs"]
                cells.append(_frac(t[key], of))
        lines.append(f"| **{title}** | | | " + " | ".join(cells) + " |")
    if any(t != "n/a" and t.get("physics") for t in summary["totals"].values()):
        cells = [
            "n/a" if t == "n/a" else _stands_cell(t.get("physics"))
            for t in summary["totals"].values()
        ]
        lines.append(
            "| **Corrected layouts that stand (physics)** | | | " + " | ".join(cells) + " |"
        )
    for k, note in enumerate(notes):
        lines.append("")
        lines.append(f"{marks[k]} {note}.")
    return "\n".join(lines)


# -- Table V -----------------------------------------------------------------------------------

_V_KEYS = ("hit", "recovered", "shape_kept", "changed")


def _failures(results: Sequence[CaseResult]) -> dict[str, Any]:
    methods = _methods(results)
    rows = []
    for case in load("failures"):
        assert isinstance(case, FailureCase)
        rs = [r for r in results if r.case == case.id]
        if not rs:
            continue
        row: dict[str, Any] = {
            "id": case.id,
            "name": case.label,
            "error": case.error,
            "command": case.command,
            "keepable": _keepable(rs),
            "keepable_reason": next(
                (str(r.fields["keepable_reason"]) for r in rs if r.fields.get("keepable_reason")),
                None,
            ),
            "methods": {},
        }
        for m in methods:
            done = _done([r for r in rs if r.method == m])
            if not done:
                row["methods"][label(m)] = "n/a"
                continue
            cell: dict[str, Any] = {k: _mark([_ok(r, k) for r in done]) for k in _V_KEYS}
            cell["tried"] = [r.fields.get("tried") for r in done]
            cell["notes"] = sorted({n for r in done for n in r.fields.get("notes", [])})[:5]
            cell["problems"] = _problems(done)
            row["methods"][label(m)] = cell
        rows.append(row)
    totals: dict[str, Any] = {}
    for m in methods:
        done = _done([r for r in results if r.method == m])
        if not done:
            totals[label(m)] = "n/a"
            continue
        changed = [r for r in done if _ok(r, "recovered") and _ok(r, "changed")]
        can = [r for r in done if r.fields.get("keepable")]
        totals[label(m)] = {
            "runs": len(done),
            **{k: sum(_ok(r, k) for r in done) for k in _V_KEYS},
            "keepable": len(can),
            "kept_where_keepable": sum(_ok(r, "shape_kept") for r in can),
            "changed_and_recovered": len(changed),
            "stated": sum(bool(r.fields.get("notes")) for r in changed),
            "physics": _physics(done),
        }
    return {"rows": rows, "totals": totals}


def _keepable(rs: Sequence[CaseResult]) -> bool | None:
    """The case's computed answer (the same for every method), or None if not recorded."""
    values = {bool(r.fields["keepable"]) for r in rs if "keepable" in r.fields}
    return values.pop() if len(values) == 1 else None


def _failures_md(summary: dict[str, Any]) -> str:
    names = list(summary["totals"])
    head = ["Scenario", "Error type", "Shape can be kept (computed)", *_head(names)]
    lines = [
        "Each cell: recovered / commanded shape kept. *Shape can be kept* is computed "
        "(`sdi.bench.keepable`): some quarter turn and placement on a 5 mm grid of the planned "
        "structure (packed, or with the gaps the `spread` recovery opens) keeps the shape "
        "signature, lies in the workspace, stays the recovery's margin clear of every blocked "
        "region, and can be commissioned by the arms.",
        "",
        "| " + " | ".join(head) + " |",
        "|---|---|:---:|" + ":---:|" * len(names),
    ]
    reasons: list[str] = []
    for row in summary["rows"]:
        cells = []
        for n in names:
            c = row["methods"][n]
            cells.append("n/a" if c == "n/a" else f"{c['recovered']} / {c['shape_kept']}")
        can = row.get("keepable")
        mark = "–" if can is None else "✓" if can else "✗"
        if can is False and row.get("keepable_reason"):
            reasons.append(f"{row['name']}: {row['keepable_reason']}")
            mark += f" {_SUP[len(reasons)]}" if len(reasons) < len(_SUP) else ""
        lines.append(f"| {row['name']} | {row['error']} | {mark} | " + " | ".join(cells) + " |")

    def total(key: str, of: str = "runs") -> list[str]:
        return ["n/a" if t == "n/a" else _frac(t[key], t[of]) for t in summary["totals"].values()]

    lines.append("| **Recovered** | | | " + " | ".join(total("recovered")) + " |")
    lines.append("| **Shape kept** | | | " + " | ".join(total("shape_kept")) + " |")
    if any(t != "n/a" and "keepable" in t for t in summary["totals"].values()):
        lines.append(
            "| **Shape kept where it can be kept** | | | "
            + " | ".join(total("kept_where_keepable", "keepable"))
            + " |"
        )
    lines.append(
        "| **Change stated in notes** (of recovered with a changed layout) | | | "
        + " | ".join(total("stated", "changed_and_recovered"))
        + " |"
    )
    lines.append(
        "| Failure injected (the command hit its region) | | | " + " | ".join(total("hit")) + " |"
    )
    if any(t != "n/a" and t.get("physics") for t in summary["totals"].values()):
        cells = [
            "n/a" if t == "n/a" else _stands_cell(t.get("physics"))
            for t in summary["totals"].values()
        ]
        lines.append(
            "| **Recovered layouts that stand (physics)** | | | " + " | ".join(cells) + " |"
        )
    for k, reason in enumerate(reasons[: len(_SUP) - 1], start=1):
        lines += ["", f"{_SUP[k]} {reason}."]
    return "\n".join(lines)


_SUP = " ¹²³⁴⁵⁶⁷⁸⁹"
"""Footnote marks (index 1…9)."""


# -- Table VI ----------------------------------------------------------------------------------


def _motion(results: Sequence[CaseResult]) -> dict[str, Any]:
    rows = []
    for case in load("motion"):
        for r in (r for r in results if r.case == case.id):
            rows.append(
                {
                    "id": case.id,
                    "seed": r.seed,
                    "outcome": r.outcome,
                    **r.fields,
                    "physics": r.physics,
                    "error": r.error or r.fields.get("error"),
                }
            )
    categories: dict[str, Any] = {}
    for row in rows:
        if row.get("extra"):
            continue
        c = categories.setdefault(
            row.get("category") or "?", {"commands": 0, "passed": 0, "parts": [], "speedups": []}
        )
        c["commands"] += 1
        c["passed"] += bool(row.get("passed"))
        if row.get("parts"):
            c["parts"].append(row["parts"])
        if row.get("speedup"):
            c["speedups"].append(row["speedup"])
    return {"rows": rows, "categories": categories, "physics": _physics(list(results))}


def _rng(values: Sequence[float], fmt: str = "{:g}") -> str:
    if not values:
        return "–"
    lo, hi = min(values), max(values)
    return fmt.format(lo) if lo == hi else f"{fmt.format(lo)}–{fmt.format(hi)}"


def _motion_md(summary: dict[str, Any]) -> str:
    lines = ["| Category (commands) | Cubes | Speed-up (two arms) | Pass |", "|---|---:|---:|---:|"]
    total_n = total_pass = 0
    for name, c in summary["categories"].items():
        total_n += c["commands"]
        total_pass += c["passed"]
        lines.append(
            f"| {name} ({c['commands']}) | {_rng(c['parts'])} | "
            f"{_rng(c['speedups'], '{:.2f}×')} | {_frac(c['passed'], c['commands'])} |"
        )
    lines.append(f"| **Total** | | | **{_frac(total_pass, total_n)}** |")
    physics = summary.get("physics")
    lines += [
        "",
        "| command | parts | one arm | makespan one arm s | makespan two arms s | "
        "speed-up | planning s/step | executed | V_traj | worst part mm |"
        + (" stands |" if physics else ""),
        "|---|---:|---|---:|---:|---:|---:|---|---|---:|" + ("---|" if physics else ""),
    ]
    for r in summary["rows"]:
        if r.get("outcome") != "done" or r.get("error"):
            lines.append(
                f"| {r.get('command', r['id'])} | {r.get('outcome')}: {r.get('error') or ''} |"
            )
            continue

        def v(key: str, r: dict[str, Any] = r) -> str:
            value = r.get(key)
            return "—" if value is None else str(value)

        row = [
            v("command") + (" (extra)" if r.get("extra") else ""),
            v("parts"),
            v("single_arm"),
            v("makespan_one_arm_s"),
            v("makespan_two_arms_s"),
            v("speedup"),
            v("planning_s_per_step"),
            v("executed"),
            v("v_traj"),
            v("max_placement_error_mm"),
        ]
        if physics:
            p = r.get("physics")
            row.append("–" if p is None else ("yes" if p["stands"] else "**no**"))
        lines.append("| " + " | ".join(row) + " |")
    if physics:
        lines += ["", f"Passed layouts that stand in physics: {_stands_cell(physics)}."]
    return "\n".join(lines)
