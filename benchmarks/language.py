"""The language front end on the unseen evaluation sets (dev, dev2 … dev39 and frozen test).

Every case is planned in-process with `sdi.pipeline.plan` and scored:

* correct           — status ``success`` and the case's predicate holds (for ``bad_input``: the
                      expected honest outcome — an error, or a layout *with* notes naming the
                      assumption — never a silent success);
* honest miss       — not correct, but the status is not ``success``;
* silent misreading — status ``success`` but the predicate fails (the worst outcome).

Writes `benchmarks/results/language_<set>.json` for every set of
`sdi.bench.language_checks.SETS` (dev, dev2 … dev39 and test).

Run: `python benchmarks/language.py [--set dev|dev2|…|dev39|test|both|all]` (`both` = dev and
test, `all` = every set).
"""

from __future__ import annotations

import argparse
import importlib
import json
import statistics
import time
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from sdi.bench.language_checks import OUTCOMES, PHENOMENA, SETS, Case, score
from sdi.pipeline import plan

RESULTS = Path(__file__).parent / "results"


def run_case(case: Case) -> dict[str, Any]:
    start = time.perf_counter()
    try:
        result: Mapping[str, Any] = plan(case.text).to_json_dict()
    except Exception as exc:  # a crash is an unusable answer, scored like any other
        result = {"status": "crash", "error": f"{type(exc).__name__}: {exc}", "layout": None}
    ms = (time.perf_counter() - start) * 1000
    outcome, reason = score(case, result)
    return {
        "id": case.id,
        "phenomenon": case.phenomenon,
        "text": case.text if len(case.text) <= 300 else case.text[:300] + "…",
        "status": result.get("status"),
        "outcome": outcome,
        "reason": reason,
        "notes": list(result.get("notes") or []),
        "error": result.get("error"),
        "ms": round(ms, 2),
    }


def summarise(rows: Sequence[dict[str, Any]]) -> dict[str, Any]:
    n = len(rows)
    counts = {o: sum(r["outcome"] == o for r in rows) for o in OUTCOMES}
    return {
        "cases": n,
        "correct_pct": round(100 * counts["correct"] / n, 1) if n else 0.0,
        "honest_miss_pct": round(100 * counts["honest_miss"] / n, 1) if n else 0.0,
        "silent_misreadings": counts["silent_misreading"],
        "median_ms": round(statistics.median(r["ms"] for r in rows), 2) if n else 0.0,
    }


def run_set(name: str, cases: Sequence[Case]) -> dict[str, Any]:
    plan("warm up the imports")
    rows = [run_case(c) for c in cases]
    per = {p: summarise([r for r in rows if r["phenomenon"] == p]) for p in PHENOMENA}
    return {
        "benchmark": f"language_{name}",
        "overall": summarise(rows),
        "per_phenomenon": per,
        "cases": rows,
    }


def table(name: str, res: dict[str, Any]) -> str:
    lines = [
        f"language {name}",
        f"{'phenomenon':<12} {'cases':>5} {'correct':>8} {'honest':>7} {'silent':>6} {'ms':>6}",
    ]
    for p, s in [*res["per_phenomenon"].items(), ("overall", res["overall"])]:
        lines.append(
            f"{p:<12} {s['cases']:>5} {s['correct_pct']:>7.1f}% {s['honest_miss_pct']:>6.1f}% "
            f"{s['silent_misreadings']:>6} {s['median_ms']:>6.1f}"
        )
    return "\n".join(lines)


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--set", choices=(*SETS, "both", "all"), default="both")
    args = ap.parse_args(argv)
    chosen = {"both": ("dev", "test"), "all": SETS}.get(args.set, (args.set,))
    sets: list[tuple[str, Sequence[Case]]] = [
        (name, importlib.import_module(f"sdi.bench.language_{name}").CASES) for name in chosen
    ]
    RESULTS.mkdir(parents=True, exist_ok=True)
    for name, cases in sets:
        res = run_set(name, cases)
        out = RESULTS / f"language_{name}.json"
        out.write_text(json.dumps(res, indent=2, ensure_ascii=False) + "\n", encoding="utf-8")
        print(table(name, res))
        print(f"→ {out}\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
