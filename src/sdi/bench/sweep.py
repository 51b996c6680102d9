"""A sweep: suites × methods × seeds, each case under a wall-clock limit, cached and resumable.

Where cases run:

- one at a time in this process (``jobs=1``, the default);
- a local pool of ``jobs`` worker processes (each opens its backend once and keeps it);
- a Ray cluster (``ray_address``; ``"local"`` starts a local instance) — optional extra
  ``ray``; the local pool stays the default.

Each case runs under a per-run time limit: an alarm in the process running it ends the case
as ``timeout``; a worker that does not come back within the limit plus a grace period is
killed (and replaced) and its case is a ``timeout`` too.

Results are cached, one JSON file per case, under a key made of the case's data, its method,
backend, seed, the run configuration (cell, physics, phase limit) and a hash of SDI's own
source: a rerun skips what is done with the same code and configuration and resumes an
interrupted sweep where it stopped. Timeouts and errors are not cached as done.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import multiprocessing as mp
import signal
import threading
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from functools import cache
from multiprocessing.connection import Connection, wait
from pathlib import Path
from typing import Any

from sdi.bench.cases import CaseResult, CaseTimeout, RunConfig, run_case
from sdi.bench.scenarios import Case

GRACE_S = 15.0
"""How long past its limit a worker may take to report a case's own timeout before it is
killed."""


@dataclass(frozen=True)
class Job:
    """One case to run: its suite, case, method (None: the plain pipeline) and seed."""

    suite: str
    case: Case
    method: str | None
    seed: int

    def describe(self) -> str:
        return f"{self.suite} {self.case.id} {self.method or 'pipeline'} seed {self.seed}"


PRESENTATION = ("cli.py", "bench/sweep.py", "bench/report.py", "bench/tables.py", "bench/charts.py")
"""Modules that run, tabulate or draw results but do not make them: not in the code key."""


@cache
def code_key() -> str:
    """A hash of SDI's source and suite files (all but `PRESENTATION`): results of other code
    are not reused."""
    root = Path(__file__).resolve().parents[1]
    h = hashlib.sha256()
    for path in sorted([*root.rglob("*.py"), *root.rglob("*.toml")]):
        if path.relative_to(root).as_posix() in PRESENTATION:
            continue
        h.update(str(path.relative_to(root)).encode())
        h.update(path.read_bytes())
    return h.hexdigest()[:16]


def cache_key(job: Job, config: RunConfig) -> str:
    data = {
        "suite": job.suite,
        "case": job.case.model_dump(mode="json"),
        "method": job.method,
        "seed": job.seed,
        "config": config.model_dump(mode="json"),
        "code": code_key(),
    }
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()[:24]


class ResultCache:
    """Finished cases as JSON files in a folder (created on first write)."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.error: str | None = None
        """Why results could not be stored (the sweep goes on without the cache)."""

    def get(self, key: str) -> CaseResult | None:
        path = self.folder / f"{key}.json"
        try:
            result = CaseResult.model_validate_json(path.read_bytes())
        except (OSError, ValueError):
            return None
        return result if result.outcome in ("done", "n/a") else None

    def put(self, result: CaseResult) -> None:
        if result.outcome not in ("done", "n/a") or self.error is not None:
            return
        tmp = self.folder / f".{result.key}.{time.monotonic_ns()}.tmp"
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            tmp.write_text(result.model_dump_json(), encoding="utf-8")
            tmp.replace(self.folder / f"{result.key}.json")
        except OSError as exc:
            self.error = f"{exc.filename or self.folder}: {exc.strerror or exc}"
            with contextlib.suppress(OSError):
                tmp.unlink()


@contextlib.contextmanager
def time_limit(seconds: float | None) -> Iterator[None]:
    """Raise `CaseTimeout` in this thread after `seconds` (only the main thread can be
    interrupted; elsewhere the caller's hard limit applies)."""
    if seconds is None or threading.current_thread() is not threading.main_thread():
        yield
        return

    def ring(signum: int, frame: Any) -> None:
        raise CaseTimeout(f"ran past {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def run_job(job: Job, config: RunConfig, timeout: float | None) -> CaseResult:
    """Run one job under its time limit (in whatever process calls it)."""
    key = cache_key(job, config)
    start = time.perf_counter()
    try:
        with time_limit(timeout):
            result = run_case(job.suite, job.case, job.method, job.seed, config)
    except CaseTimeout:  # the alarm rang outside the case's own handler
        result = CaseResult(
            suite=job.suite,
            case=job.case.id,
            method=job.method,
            backend=config.backend,
            seed=job.seed,
            outcome="timeout",
            seconds=time.perf_counter() - start,
        )
    return result.model_copy(update={"key": key})


def _timed_out(job: Job, config: RunConfig, seconds: float) -> CaseResult:
    return CaseResult(
        suite=job.suite,
        case=job.case.id,
        method=job.method,
        backend=config.backend,
        seed=job.seed,
        outcome="timeout",
        seconds=seconds,
        error=f"killed after {seconds:.0f} s",
        key=cache_key(job, config),
    )


Progress = Callable[[Job, CaseResult, bool], None]
"""Called after each job with its result and whether it came from the cache."""


def sweep(
    jobs: Sequence[Job],
    config: RunConfig,
    *,
    workers: int = 1,
    timeout: float | None = None,
    cache: ResultCache | None = None,
    fresh: bool = False,
    ray_address: str | None = None,
    progress: Progress | None = None,
) -> list[CaseResult]:
    """Run every job (cached ones are read back unless `fresh`); results in job order."""
    results: dict[int, CaseResult] = {}
    todo: list[int] = []
    for i, job in enumerate(jobs):
        hit = None if (cache is None or fresh) else cache.get(cache_key(job, config))
        if hit is not None:
            results[i] = hit
            if progress is not None:
                progress(job, hit, True)
        else:
            todo.append(i)

    def done(i: int, result: CaseResult) -> None:
        results[i] = result
        if cache is not None:
            cache.put(result)
        if progress is not None:
            progress(jobs[i], result, False)

    if ray_address is not None:
        _on_ray(jobs, todo, config, timeout, ray_address, done)
    elif workers > 1 and len(todo) > 1:
        _on_pool(jobs, todo, config, timeout, workers, done)
    else:
        for i in todo:
            done(i, run_job(jobs[i], config, timeout))
    return [results[i] for i in range(len(jobs))]


# -- the local process pool ------------------------------------------------------------------


def _serve(conn: Connection) -> None:
    """A pool worker: run the jobs it is sent until it is sent None."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent handles Ctrl-C
    while True:
        message = conn.recv()
        if message is None:
            return
        job, config, timeout = message
        conn.send(run_job(job, config, timeout))


class _Worker:
    def __init__(self, ctx: Any) -> None:
        self.conn, child = ctx.Pipe()
        self.process = ctx.Process(target=_serve, args=(child,), daemon=True)
        self.process.start()
        child.close()
        self.job: int | None = None
        self.started = 0.0

    def stop(self, kill: bool = False) -> None:
        if kill:
            self.process.kill()
        else:
            with contextlib.suppress(OSError):
                self.conn.send(None)
        self.process.join(timeout=10)
        if self.process.is_alive():
            self.process.kill()
            self.process.join()
        self.conn.close()


def _on_pool(
    jobs: Sequence[Job],
    todo: list[int],
    config: RunConfig,
    timeout: float | None,
    n: int,
    done: Callable[[int, CaseResult], None],
) -> None:
    ctx = mp.get_context("spawn")  # no fork of a process holding threads, PyBullet or SQLite
    queue = list(todo)
    pool = [_Worker(ctx) for _ in range(min(n, len(todo)))]
    hard = None if timeout is None else timeout + GRACE_S
    try:
        while queue or any(w.job is not None for w in pool):
            for w in pool:
                if w.job is None and queue:
                    w.job, w.started = queue.pop(0), time.monotonic()
                    w.conn.send((jobs[w.job], config, timeout))
            busy = [w for w in pool if w.job is not None]
            ready = wait([w.conn for w in busy], timeout=1.0)
            for w in busy:
                assert w.job is not None
                if w.conn in ready:
                    try:
                        result = w.conn.recv()
                    except (EOFError, OSError):  # the worker died (out of memory, a crash)
                        result = CaseResult(
                            suite=jobs[w.job].suite,
                            case=jobs[w.job].case.id,
                            method=jobs[w.job].method,
                            backend=config.backend,
                            seed=jobs[w.job].seed,
                            outcome="error",
                            error="worker process died",
                            key=cache_key(jobs[w.job], config),
                        )
                        i = w.job
                        w.stop(kill=True)
                        pool[pool.index(w)] = _Worker(ctx)
                        done(i, result)
                        continue
                    i, w.job = w.job, None
                    done(i, result)
                elif hard is not None and time.monotonic() - w.started > hard:
                    i = w.job
                    w.stop(kill=True)
                    pool[pool.index(w)] = _Worker(ctx)
                    done(i, _timed_out(jobs[i], config, time.monotonic() - w.started))
    finally:
        for w in pool:
            w.stop(kill=w.job is not None)


# -- Ray ---------------------------------------------------------------------------------------


def _on_ray(
    jobs: Sequence[Job],
    todo: list[int],
    config: RunConfig,
    timeout: float | None,
    address: str,
    done: Callable[[int, CaseResult], None],
) -> None:
    try:
        import ray
    except ImportError:
        from sdi.errors import InputError

        raise InputError(
            "Ray is not installed; install the optional extra: pip install 'sdi[ray]'",
            field="--ray",
        ) from None
    started_here = not ray.is_initialized()
    if started_here:
        if address == "local":
            ray.init(include_dashboard=False, log_to_driver=False)
        else:
            ray.init(address=address, log_to_driver=False)
    try:
        remote = ray.remote(max_retries=0)(run_job)
        # no more in flight than the cluster has CPUs, so a task starts when it is submitted
        # and its hard limit counts from then
        slots = max(1, int(ray.cluster_resources().get("CPU", 1)))
        queue = list(todo)
        pending: dict[Any, tuple[int, float]] = {}
        hard = None if timeout is None else timeout + GRACE_S
        while pending or queue:
            while queue and len(pending) < slots:
                i = queue.pop(0)
                pending[remote.remote(jobs[i], config, timeout)] = (i, time.monotonic())
            ready, _ = ray.wait(list(pending), num_returns=1, timeout=1.0)
            for ref in ready:
                i, _t0 = pending.pop(ref)
                try:
                    result = ray.get(ref)
                except Exception as exc:  # the task or its worker failed
                    result = CaseResult(
                        suite=jobs[i].suite,
                        case=jobs[i].case.id,
                        method=jobs[i].method,
                        backend=config.backend,
                        seed=jobs[i].seed,
                        outcome="error",
                        error=f"ray: {type(exc).__name__}: {exc}",
                        key=cache_key(jobs[i], config),
                    )
                done(i, result)
            if hard is not None:
                now = time.monotonic()
                for ref, (i, t0) in list(pending.items()):
                    if now - t0 > hard:
                        ray.cancel(ref, force=True)
                        del pending[ref]
                        done(i, _timed_out(jobs[i], config, now - t0))
    finally:
        if started_here:
            ray.shutdown()
