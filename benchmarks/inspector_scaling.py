"""Verifier and sequencer time from 10 to 10 000 parts, against a naive all-pairs reference.

Best case (layouts that pass): dense fields of 4-level columns of 5 cm cubes (every part touches
its neighbours, so contact, support, stability and gripping all have work to do), in a
workspace enlarged to hold them. The reference computes the same pairwise contact and collision
relations over all N² pairs (numpy, chunked), the way a verifier without a spatial index would;
the ratio reference / ours is measured in the same run, so machine noise cancels.

Worst case (layouts that fail everywhere): a dense field of 1 cm cubes packed edge to edge on
the table. The vacuum cup pattern needs a 4 cm face and every finger keep-out volume holds
about a dozen neighbours, so no tool can take any part: every part is a gripping violation,
disassembly is stuck at once, and every part's blockers are listed. `verify` reports the first
50 and one summary; `sequence` fails naming every part.

Times are the best of 3 runs in one process. Growth exponents are given per decade of N
(log10 of the time ratio from N to 10 N), not averaged, so a super-linear tail shows.

Run: `python benchmarks/inspector_scaling.py` (part of `make bench`).
"""

from __future__ import annotations

import itertools
import json
import math
import platform
import sys
import time
from pathlib import Path

import numpy as np

from sdi.errors import SequencingError
from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence
from sdi.inspector.verifier import verify
from sdi.model.cell import CellConfig, Limits, Workspace
from sdi.model.layout import Layout
from sdi.model.part import Part

SIZES = (10, 100, 1_000, 10_000)
LEVELS = 4
SMALL = 0.01
"""Edge of the worst case's cubes, m: too small for the vacuum, too tightly packed for fingers."""
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


def ungrippable_field(n: int) -> Layout:
    """`n` cubes of edge `SMALL` packed edge to edge in one layer (a near-square field)."""
    nx = math.ceil(math.sqrt(n))
    parts = []
    for k in range(n):
        i, j = divmod(k, nx)
        position = (0.1 + SMALL * i, 0.1 + SMALL * j, SMALL / 2)
        parts.append(Part(id=f"u{k}", position=position, size=(SMALL, SMALL, SMALL)))
    return Layout(objects=tuple(parts))


def failing_sequence(layout: Layout, cell: CellConfig) -> None:
    try:
        sequence(Analysis(layout, cell))
    except SequencingError:
        return
    raise AssertionError("the ungrippable field has an assembly order")


def per_decade(rows: list[dict], key: str) -> dict[str, float]:
    """log10(t(10 N) / t(N)) for each decade of N."""
    return {
        f"{a['parts']}→{b['parts']}": round(math.log10(b[key] / a[key]), 3)
        for a, b in itertools.pairwise(rows)
    }


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
    worst = []
    for n in SIZES:
        layout = ungrippable_field(n)
        report = verify(layout, cell)
        counts = report.by_constraint()
        assert counts == {"gripping": n}, counts  # every part, and nothing else
        listed = report.to_json_dict()["violations"]
        assert len(listed) == min(n, 50) + (n > 50), len(listed)  # capped, plus one summary
        t_verify = best(lambda lay=layout: verify(lay, cell))
        t_json = best(lambda lay=layout: json.dumps(verify(lay, cell).to_json_dict()))
        t_sequence = best(lambda lay=layout: failing_sequence(lay, cell))
        worst.append(
            {
                "parts": n,
                "verify_s": round(t_verify, 5),
                "verify_and_json_s": round(t_json, 5),
                "sequence_s": round(t_sequence, 5),
                "violations": n,
                "listed_in_json": len(listed),
            }
        )
        print(
            f"{n:>6} ungrippable  verify {t_verify:8.4f} s  (+ JSON {t_json:8.4f} s)  "
            f"sequence {t_sequence:8.4f} s"
        )
    result = {
        "benchmark": "inspector_scaling",
        "python": sys.version.split()[0],
        "machine": platform.machine(),
        "timing": f"best of {REPEATS} runs per size in one process (perf_counter)",
        "layout": f"field of {LEVELS}-level columns of 0.05 m cubes",
        "rows": rows,
        "verify_growth_per_decade": per_decade(rows, "verify_s"),
        "sequence_growth_per_decade": per_decade(rows, "sequence_s"),
        "worst_case": {
            "layout": f"one layer of {SMALL} m cubes packed edge to edge: every part ungrippable",
            "rows": worst,
            "verify_growth_per_decade": per_decade(worst, "verify_s"),
            "sequence_growth_per_decade": per_decade(worst, "sequence_s"),
        },
        "targets": {"verify_10k_s": 0.5, "sequence_10k_s": 1.0, "worst_verify_10k_s": 1.0},
    }
    for name, data in (("best", result), ("worst", result["worst_case"])):
        print(f"{name} case: verify growth exponent per decade {data['verify_growth_per_decade']}")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(result, indent=2) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
