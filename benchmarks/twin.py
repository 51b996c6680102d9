"""The digital twin's responsiveness: edit → violations, frames per second, websocket traffic.

Everything runs against the real server (uvicorn on 127.0.0.1, a real run database) and, for
the frame rate, Debian's headless Chromium (software WebGL: a floor, not a GPU figure).

* **edit → violations shown** (ms): a finished drag that makes a collision, posted to the
  server, which applies it (C ⊕ I_h), runs the Inspector and answers with the violations —
  measured in the page from the drop to the violations being drawn (`performance.now()`),
  for layouts of 25 and 200 parts. Median and worst of N drags, with the server-side
  Inspector time alone as the reference in the same run.
* **frames per second** with 500 parts in the scene (one instanced mesh), against the same
  page with the scene alone (no parts) in the same browser — median of 3 five-second windows.
* **websocket bytes per second** while a job executes (Q_exec samples at 10 Hz per arm, step
  and δ events): bytes received by one client over the execution, divided by its duration.

Run: `python benchmarks/twin.py` (part of `make bench`); writes `benchmarks/results/twin.json`.
"""

from __future__ import annotations

import argparse
import asyncio
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).parents[1] / "tests"))

from sdi.inspector.verifier import verify
from twin_harness import browser, served, state, wait

OUT = Path(__file__).parent / "results" / "twin.json"
SIZES = {25: "a 5 by 5 grid", 200: "a 10 by 10 block 2 high"}
BIG = "a 10 by 10 block 5 high"  # 500 parts
JOB = "build a 3-cube tower at x = 0.4 m and a 4-step staircase on the left"


def edit_latency(page: Any, twin: Any, n: int) -> dict[str, Any]:
    """N drags of the first part onto the second, each undone; page-side ms per drag."""
    run_id = state(page, "T.runId")
    session = twin.session(run_id)
    first, second = session.layout().objects[:2]
    page_ms, server_ms = [], []
    for _ in range(n):
        t = page.evaluate(
            """async ([id, to]) => {
                const T = window.sdiTwin, t0 = performance.now();
                await T.edit({ op: "move", id, position: to });
                await new Promise(requestAnimationFrame);
                const ok = T.view.review.violations.some(v => v.constraint === "collision");
                return ok ? performance.now() - t0 : -1;
            }""",
            [first.id, list(second.position)],
        )
        assert t >= 0, f"the collision was not shown: {state(page, 'T.lastError')}"
        page_ms.append(t)
        t0 = time.perf_counter()
        verify(session.layout(), session.cell)
        server_ms.append((time.perf_counter() - t0) * 1000)
        page.evaluate("() => window.sdiTwin.edit({ op: 'undo' })")
        wait(page, "T.view.review.violations.length === 0")
    return {
        "parts": len(session.layout()),
        "drags": n,
        "page_ms_median": round(statistics.median(page_ms), 1),
        "page_ms_best": round(min(page_ms), 1),
        "page_ms_worst": round(max(page_ms), 1),
        "inspector_ms_median": round(statistics.median(server_ms), 1),
    }


def fps(page: Any, seconds: float = 5.0, windows: int = 3) -> float:
    rates = []
    for _ in range(windows):
        f0 = state(page, "T.frames")
        time.sleep(seconds)
        rates.append((state(page, "T.frames") - f0) / seconds)
    return round(statistics.median(rates), 1)


async def _count_ws(url: str, run_id: str, stop: asyncio.Event, seen: dict[str, int]) -> None:
    import websockets

    ws_url = url.replace("http://", "ws://") + f"ws/runs/{run_id}?tab=bench"
    async with websockets.connect(ws_url, max_size=None) as ws:
        while not stop.is_set():
            try:
                msg = await asyncio.wait_for(ws.recv(), timeout=0.5)
            except TimeoutError:
                continue
            seen["bytes"] += len(msg)
            seen["messages"] += 1


def websocket_rate(url: str, twin: Any) -> dict[str, Any]:
    run_id = twin.start(JOB)
    twin.wait()
    session = twin.session(run_id)
    from sdi.execute.record import layout_hash

    twin.accept(run_id, "bench", layout_hash(session.layout()))
    twin.wait()
    record = twin.view(run_id)["waiting_for"]["record_hash"]

    async def main() -> tuple[int, int, float]:
        stop, seen = asyncio.Event(), {"bytes": 0, "messages": 0}
        counter = asyncio.create_task(_count_ws(url, run_id, stop, seen))
        await asyncio.sleep(1.0)  # the backlog of the run so far is sent first: not counted
        before = dict(seen)
        t0 = time.perf_counter()
        twin.confirm(run_id, "bench", "approve", record)
        await asyncio.to_thread(twin.wait)
        seconds = time.perf_counter() - t0
        await asyncio.sleep(0.5)
        stop.set()
        await counter
        return seen["bytes"] - before["bytes"], seen["messages"] - before["messages"], seconds

    total, messages, seconds = asyncio.run(main())
    view = twin.view(run_id)
    return {
        "command": JOB,
        "status": view["status"],
        "bytes_total": total,
        "messages": messages,
        "execution_wall_s": round(seconds, 2),
        "bytes_per_s": round(total / seconds),
    }


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--drags", type=int, default=15)
    parser.add_argument("--out", type=Path, default=OUT)
    args = parser.parse_args()
    result: dict[str, Any] = {"how": __doc__.split("\n\n", 1)[1].strip()}
    with tempfile.TemporaryDirectory() as tmp, served(Path(tmp) / "runs.sqlite") as (url, twin):
        with browser() as b:
            page = b.new_page(viewport={"width": 1280, "height": 800})
            page.goto(url)
            wait(page, "T.scene && T.robots")
            result["fps_scene_only"] = fps(page)
            result["edit"] = []
            for size, command in SIZES.items():
                run_id = twin.start(command)
                twin.wait()
                page.goto(f"{url}#{run_id}")
                wait(page, f"T.phase === 'design_review' && T.partIds.length === {size}")
                result["edit"].append({"command": command, **edit_latency(page, twin, args.drags)})
            run_id = twin.start(BIG)
            twin.wait()
            page.goto(f"{url}#{run_id}")
            wait(page, "T.phase === 'design_review' && T.partIds.length === 500")
            result["fps_500_parts"] = fps(page)
        result["websocket"] = websocket_rate(url, twin)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(json.dumps({k: v for k, v in result.items() if k != "how"}, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
