"""The paper's compared methods (Table II) on the evaluation suite, per backend.

For every method: success per group, LLM calls, tokens and seconds per command, running the
whole orchestrator up to the verified design. Backends:

- `rules` (default): no model; every method's neural parts are their rule-based counterparts,
  so the methods differ only in orchestration. All 70 commands.
- `local`: SmolLM2-135M-Instruct served by llama.cpp on 127.0.0.1 (needs `make local`). A
  135M model is slow on 2 cores and weak, so by default only the first commands of groups A–B
  (`--per-group`), with a lower phase limit (`--phase-seconds`).
- `openai`: the endpoint in SDI_LLM_BASE_URL / OPENAI_BASE_URL with SDI_LLM_MODEL.

Run: `python benchmarks/methods.py --backend rules` and
`python benchmarks/methods.py --backend local` (both in `make bench`); results in
benchmarks/results/methods_<backend>.json.
"""

from __future__ import annotations

import argparse
import json
import sys
from contextlib import ExitStack
from pathlib import Path

from sdi.bench.methods import markdown_table, records_json, run_method, summarise
from sdi.bench.suite import SUITE
from sdi.llm import open_backend
from sdi.model.cell import CellConfig, Limits
from sdi.orchestrator.methods import METHODS

RESULTS = Path(__file__).parent / "results"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--backend", choices=("rules", "local", "openai"), default="rules")
    ap.add_argument("--methods", nargs="*", default=list(METHODS), choices=list(METHODS))
    ap.add_argument(
        "--groups", default=None, help="groups to run, e.g. AB (default: all; AB local)"
    )
    ap.add_argument("--per-group", type=int, default=None, help="first N commands of each group")
    ap.add_argument("--phase-seconds", type=float, default=None, help="per-phase time limit, s")
    ap.add_argument("--out", type=Path, default=None)
    args = ap.parse_args(argv)

    small = args.backend == "local"
    groups = args.groups or ("AB" if small else "ABCDE")
    per_group = args.per_group or (3 if small else None)
    commands = []
    for g in groups:
        in_group = [c for c in SUITE if c.group == g]
        commands += in_group[:per_group] if per_group else in_group
    phase_seconds = args.phase_seconds or (120.0 if small else 300.0)
    cell = CellConfig(limits=Limits(phase_seconds=phase_seconds))

    with ExitStack() as stack:
        model = open_backend(args.backend, stack)
        records = []
        for method in args.methods:
            records += run_method(
                method,
                commands,
                model,
                cell,
                progress=lambda r: print(
                    f"{r.method:20s} {r.id} {'ok ' if r.success else 'NO '} "
                    f"calls={r.llm_calls} tokens={r.prompt_tokens + r.completion_tokens} "
                    f"{r.seconds:.2f}s {r.reason or ''}",
                    file=sys.stderr,
                    flush=True,
                ),
            )
        model_name = getattr(model, "model", None) if model is not None else None

    summary = summarise(records)
    out = args.out or RESULTS / f"methods_{args.backend}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    data = {
        "backend": args.backend,
        "model": model_name,
        "commands": [c.id for c in commands],
        "phase_seconds": phase_seconds,
        "summary": summary,
        "records": records_json(records),
    }
    out.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
    print(markdown_table(summary))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
