"""The LLM-critic ablation: how well does an LLM judge feasibility, against the Inspector?

Layouts from the evaluation suite (all feasible) and a corrupted copy of each (one part lifted
off its support, pushed into a neighbour, or moved out of the workspace — all infeasible) are
shown to the critic of the Hybrid-LLMCritic method. Its verdicts are scored against the
symbolic Inspector: accuracy, false accepts (an infeasible layout called feasible — the
dangerous error, which the symbolic gate before PRE_EXECUTE still stops) and false rejects
(wasted replans).

Run: `python benchmarks/critic_ablation.py --backend local` (needs `make local`);
results in benchmarks/results/critic_ablation_<backend>.json.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from contextlib import ExitStack
from pathlib import Path

from sdi.bench.suite import SUITE
from sdi.inspector.verifier import verify
from sdi.llm import open_backend
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout
from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.graph import RunContext, llm_critic
from sdi.orchestrator.methods import METHODS
from sdi.pipeline import plan

RESULTS = Path(__file__).parent / "results"


def corrupt(layout: Layout, kind: str) -> Layout:
    """One infeasible variant: the last part lifted, pushed sideways into overlap, or moved out."""
    last = layout.objects[-1]
    delta = {
        "floating": (0.0, 0.0, 0.08),
        "overlap": (0.5 * last.size[0], 0.0, 0.0),
        "outside": (1.5, 0.0, 0.0),
    }[kind]
    return Layout(objects=(*layout.objects[:-1], last.moved(*delta)))


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--backend", choices=("local", "openai"), default="local")
    ap.add_argument("--per-group", type=int, default=2)
    args = ap.parse_args(argv)
    cell = CellConfig()
    kinds = ("floating", "overlap", "outside")
    cases: list[tuple[str, Layout]] = []
    for g in "ABCDE":
        for k, command in enumerate([c for c in SUITE if c.group == g][: args.per_group]):
            layout = plan(command.text, cell).layout
            if layout is None or len(layout) > 30:  # the critic reads the layout as JSON
                continue
            cases.append((command.id, layout))
            cases.append((f"{command.id}-{kinds[k % 3]}", corrupt(layout, kinds[k % 3])))

    rows = []
    with ExitStack() as stack:
        model = open_backend(args.backend, stack)
        assert model is not None  # the critic needs a model: --backend is local or openai
        tmp = Path(stack.enter_context(tempfile.TemporaryDirectory()))
        bus = MessageBus(tmp / "bus.sqlite")  # the critic sends nothing; the context needs one
        stack.callback(bus.close)
        ctx = RunContext(cell, METHODS["Hybrid-LLMCritic"], model, bus)
        for name, layout in cases:
            truth = verify(layout, cell).passed
            verdict = llm_critic(ctx, layout)
            rows.append({"case": name, "feasible": truth, "critic_passed": verdict["passed"]})
            print(name, truth, verdict["passed"], file=sys.stderr, flush=True)
        usage = model.usage.to_json_dict()

    n = len(rows)
    feasible = [r for r in rows if r["feasible"]]
    infeasible = [r for r in rows if not r["feasible"]]
    summary = {
        "cases": n,
        "accuracy": round(sum(r["feasible"] == r["critic_passed"] for r in rows) / n, 3),
        "false_accepts": sum(r["critic_passed"] for r in infeasible),
        "infeasible": len(infeasible),
        "false_rejects": sum(not r["critic_passed"] for r in feasible),
        "feasible": len(feasible),
        "llm_calls": usage["llm_calls"],
        "malformed": usage["malformed"],
        "inspector_accuracy": 1.0,  # by definition: the Inspector is the ground truth here
    }
    out = RESULTS / f"critic_ablation_{args.backend}.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    data = {"backend": args.backend, "model": getattr(model, "model", None), "summary": summary}
    out.write_text(json.dumps(data | {"rows": rows}, indent=2) + "\n", encoding="utf-8")
    print(json.dumps(summary))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
