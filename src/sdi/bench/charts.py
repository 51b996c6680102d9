"""PNG charts of a suite's summary (`sdi.bench.tables.summarise`), as bytes.

commands: success % per group and method; human-mods: detected / corrected / edit kept per
method; failures: recovered / shape kept per method; motion: makespan on one arm and on two
per command. Methods that are ``n/a`` are left out of the charts (the tables say so).
"""

from __future__ import annotations

import io
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from sdi.bench.tables import SHORT


def _bars(
    title: str, categories: list[str], series: dict[str, list[float]], ylabel: str, top: float
) -> bytes:
    width_in = min(10.0, max(5.0, 0.3 * len(categories) * max(1, len(series)) + 2.5))
    fig, ax = plt.subplots(figsize=(width_in, 3.4))
    width = 0.8 / max(1, len(series))
    for k, (name, values) in enumerate(series.items()):
        xs = [i + (k - (len(series) - 1) / 2) * width for i in range(len(categories))]
        ax.bar(xs, values, width, label=name)
    ax.set_xticks(range(len(categories)))
    ax.set_xticklabels(categories)
    ax.set_ylim(0, top)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    if len(series) > 1:
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=110, metadata={"Software": None})
    plt.close(fig)
    return buf.getvalue()


def chart(suite: str, summary: dict[str, Any]) -> bytes:
    if suite == "commands":
        methods = {m: s for m, s in summary["methods"].items() if not s.get("n/a")}
        groups = sorted({g for s in methods.values() for g in s["groups"]})
        series = {
            m: [100 * s["groups"].get(g, {}).get("success_rate", 0.0) for g in groups]
            + [100 * s["overall"]["success_rate"]]
            for m, s in methods.items()
        }
        return _bars(
            "Evaluation suite: success per group", [*groups, "all"], series, "success %", 105
        )
    if suite in ("human-mods", "failures"):
        totals = {m: t for m, t in summary["totals"].items() if t != "n/a"}
        keys = (
            [("detected", "detected"), ("corrected", "corrected"), ("edit_kept", "edit kept"),
             ("edit_as_close", "kept as close as possible")]
            if suite == "human-mods"
            else [("recovered", "recovered"), ("shape_kept", "shape kept"),
                  ("keepable", "shape can be kept")]
        )  # fmt: skip
        series = {name: [t.get(k, 0) for t in totals.values()] for k, name in keys}
        top = max([t["runs"] for t in totals.values()] or [1]) + 0.5
        title = (
            "Table IV: invalid human modifications"
            if suite == "human-mods"
            else "Table V: injected failures"
        )
        return _bars(title, [SHORT.get(m, m) for m in totals], series, "cases", top)
    rows = [r for r in summary["rows"] if r.get("outcome") == "done" and not r.get("error")]
    labels = [r["id"] for r in rows]
    series = {
        "one arm": [float(r.get("makespan_one_arm_s") or 0.0) for r in rows],
        "two arms": [float(r.get("makespan_two_arms_s") or 0.0) for r in rows],
    }
    top = max([*series["one arm"], *series["two arms"], 1.0]) * 1.1
    return _bars("Table VI: makespan per command", labels, series, "makespan, s", top)
