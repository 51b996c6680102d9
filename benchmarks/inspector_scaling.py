"""Verifier and sequencer time from 10 to 10 000 parts, against a naive all-pairs reference.

The layouts are dense fields of 4-level columns (a realistic worst case: every part touches its
neighbours, so contact, support, stability and gripping all have work to do), in a workspace
enlarged to hold them. The reference computes the same pairwise contact and collision relations
over all N² pairs (numpy, chunked), the way a verifier without a spatial index would; the ratio
reference / ours is measured in the same run, so machine noise cancels.

Run: `python benchmarks/inspector_scaling.py` (part of `make bench`).
"""

from __future__ import annotations

import json
import math
import platform
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig, Limits, Workspace
from sdi.model.layout import Layout
from sdi.model.part import Part

SIZES = (10, 100, 1_000, 10_000)
LEVELS = 4
REPEATS = 3
OUT = Path(__file__).parent / "results" / "inspector_scaling.json"


def field_of_columns(n: int) -> Layout:
    columns = math.ceil(n / LEVELS)
    nx = math.ceil(math.sqrt(columns))
    parts = []
    for k in range(n):
        col, level = divmod(k, LEVELS)
        i, j = divmod(col, nx)
        parts.append(
            Part(id=f"c{k}", position=(0.1 + 0.05 * i, 0.1 + 0.05 * j, 0.025 + 0.05 * level))
        )
    return Layout(objects=tuple(parts))


def naive_pairs(layout: Layout, eps: float, chunk: int = 512) -> tuple[int, int]:
    """All N² pairs: how many touch (paper contact) and how many collide."""
    c, h = layout.centres, layout.half_extents
    contacts = collisions = 0
    for start in range(0, len(layout), chunk):
        ci, hi = c[start : start + chunk, None, :], h[start : start + chunk, None, :]
        gap = np.abs(ci - c[None, :, :]) - (hi + h[None, :, :])
        touch = np.all(gap <= eps, axis=2)
        collide = np.all(gap < -eps, axis=2)
        idx = np.arange(start, min(start + chunk, len(layout)))[:, None]
        upper = np.arange(len(layout))[None, :] > idx
        contacts += int(np.sum(touch & upper))
        collisions += int(np.sum(collide & upper))
    return contacts, collisions


def best(fn, repeats: int = REPEATS) -> float:
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return min(times)


def main() -> int:
    cell = CellConfig(
        workspace=Workspace(x_min=0.0, x_max=10.0, y_min=0.0, y_max=10.0, z_max=1.0),
        limits=Limits(max_parts=20_000),
    )
    eps = cell.tolerances.contact
    rows = []
    for n in SIZES:
        layout = field_of_columns(n)
        report = verify(layout, cell)
        assert report.passed, report.violations[:3]
        graph = Analysis(layout, cell).graph
        ours_pairs = (int(graph.in_contact.sum()), int(graph.colliding.sum()))
        assert ours_pairs == naive_pairs(layout, eps), "spatial index disagrees with all pairs"
        t_verify = best(lambda lay=layout: verify(lay, cell))
        t_sequence = best(lambda lay=layout: sequence(Analysis(lay, cell)))
        t_pairs = best(lambda lay=layout: Analysis(lay, cell).graph.colliding)
        repeats = 1 if n >= 10_000 else REPEATS
        t_naive = best(lambda lay=layout: naive_pairs(lay, eps), repeats=repeats)
        rows.append(
            {
                "parts": n,
                "verify_s": round(t_verify, 5),
                "sequence_s": round(t_sequence, 5),
                "pairs_ours_s": round(t_pairs, 5),
                "pairs_naive_s": round(t_naive, 5),
                "naive_over_ours_pairs": round(t_naive / t_pairs, 2),
            }
        )
        print(
            f"{n:>6} parts  verify {t_verify:8.4f} s  sequence {t_sequence:8.4f} s  "
            f"pairs {t_pairs:8.4f} s vs all-pairs {t_naive:8.4f} s ({t_naive / t_pairs:6.1f}×)"
        )
    growth = [
        math.log(rows[k + 1]["verify_s"] / rows[k]["verify_s"]) / math.log(SIZES[k + 1] / SIZES[k])
        for k in range(1, len(rows) - 1)
    ]
    result = {
        "benchmark": "inspector_scaling",
        "python": sys.version.split()[0],
        "machine": platform.machine(),
        "layout": f"field of {LEVELS}-level columns of 0.05 m cubes",
        "rows": rows,
        "verify_growth_exponent": round(statistics.mean(growth), 3),
        "targets": {"verify_10k_s": 0.5, "sequence_10k_s": 1.0},
    }
    print(f"verify time grows as N^{result['verify_growth_exponent']} from 100 to 10 000 parts")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
