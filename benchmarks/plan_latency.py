"""`sdi plan` time per command, excluding interpreter start-up (target: median ≤ 50 ms).

Plans every command of the evaluation suite in one process, REPEATS times, and reports the
median, 90th percentile and maximum of the per-command best time. A reference workload in the
same run — verifying a fixed 3-cube tower — gives the ratio plan / reference, which stays
comparable across machines and load. The language front end (spaCy parse, relations,
accounting) is timed beside the phrase grammar alone on the whole command (the token scanner
that was the whole Specifier before the front end), so its cost is measured in the same run.

Run: `python benchmarks/plan_latency.py` (part of `make bench`).
"""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path

from sdi.bench.suite import SUITE
from sdi.inspector.verifier import verify
from sdi.language import read
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.model.part import Part
from sdi.pipeline import plan
from sdi.spec.grammar import parse_phrase

REPEATS = 3
OUT = Path(__file__).parent / "results" / "plan_latency.json"


def timed(fn) -> float:
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def main() -> int:
    cell = CellConfig()
    plan("warm up the imports", cell)
    tower = Layout(
        objects=tuple(Part(id=f"c{k}", position=(0.4, 0.3, 0.025 + 0.05 * k)) for k in range(3))
    )
    reference = min(timed(lambda: verify(tower, cell)) for _ in range(20))
    per_command = []
    for command in SUITE:
        best = min(timed(lambda c=command: plan(c.text, cell)) for _ in range(REPEATS))
        per_command.append({"id": command.id, "group": command.group, "seconds": round(best, 5)})
    front, scanner = [], []
    for command in SUITE:
        front.append(min(timed(lambda c=command: read(c.text, cell)) for _ in range(REPEATS)))
        scanner.append(
            min(timed(lambda c=command: parse_phrase(c.text, cell)) for _ in range(REPEATS))
        )
    seconds = sorted(r["seconds"] for r in per_command)
    result = {
        "benchmark": "plan_latency",
        "commands": len(seconds),
        "median_s": round(statistics.median(seconds), 5),
        "p90_s": round(seconds[int(0.9 * (len(seconds) - 1))], 5),
        "max_s": round(seconds[-1], 5),
        "reference_verify_tower_s": round(reference, 6),
        "median_over_reference": round(statistics.median(seconds) / reference, 1),
        "target_median_s": 0.05,
        "front_end_median_s": round(statistics.median(front), 5),
        "front_end_max_s": round(max(front), 5),
        "phrase_grammar_alone_median_s": round(statistics.median(scanner), 5),
        "phrase_grammar_alone_max_s": round(max(scanner), 5),
        "per_command": per_command,
    }
    print(
        f"plan: median {result['median_s'] * 1000:.1f} ms, p90 {result['p90_s'] * 1000:.1f} ms, "
        f"max {result['max_s'] * 1000:.1f} ms over {len(seconds)} commands "
        f"({result['median_over_reference']}× a 3-cube verify); reading: front end median "
        f"{result['front_end_median_s'] * 1000:.1f} ms vs phrase grammar alone "
        f"{result['phrase_grammar_alone_median_s'] * 1000:.1f} ms"
    )
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
