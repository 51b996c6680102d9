"""A real twin server on 127.0.0.1 and Debian's headless Chromium driven by Playwright.

`make test` installs Chromium (Debian package) and Playwright (pip); with SDI_REQUIRE_BROWSER
set, a missing browser fails the tests instead of skipping them. WebGL renders in software
there, so tests wait on the page's scene state (`window.sdiTwin`), never on wall-clock budgets.
"""

from __future__ import annotations

import os
import shutil
import socket
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest

CHROMIUM = os.environ.get("SDI_CHROMIUM", "/usr/bin/chromium")
ARGS = [
    "--no-sandbox", "--disable-background-networking", "--disable-component-update",
    "--disable-sync", "--no-first-run", "--disable-quic",
    "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
]  # fmt: skip


def need_browser() -> None:
    have = Path(CHROMIUM).is_file() or shutil.which(CHROMIUM) is not None
    try:
        import playwright  # noqa: F401
    except ImportError:
        have = False
    if not have:
        if os.environ.get("SDI_REQUIRE_BROWSER"):
            pytest.fail(
                f"Chromium ({CHROMIUM}) or Playwright is missing; `make test` installs them"
            )
        pytest.skip("no Chromium/Playwright here (make test installs them)")


@contextmanager
def served(db: Path, token: str | None = None) -> Iterator[tuple[str, Any]]:
    """The twin's app on a free loopback port, in this process; yields (url, Twin)."""
    import uvicorn

    from sdi.twin.server import create_app
    from sdi.twin.service import Twin

    twin = Twin(db)
    app = create_app(twin, token=token)
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    server = uvicorn.Server(uvicorn.Config(app, log_level="warning", ws="websockets-sansio"))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    while not server.started:
        if not thread.is_alive():
            raise RuntimeError("the twin server did not start")
        time.sleep(0.05)
    try:
        yield f"http://127.0.0.1:{sock.getsockname()[1]}/", twin
    finally:
        twin.wait()
        server.should_exit = True
        thread.join(timeout=10)
        twin.close()


@contextmanager
def browser() -> Iterator[Any]:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        try:
            yield b
        finally:
            b.close()


def page_errors(page: Any) -> list[str]:
    """Collects the page's uncaught errors (a test asserts there are none)."""
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    return errors


def state(page: Any, expr: str) -> Any:
    return page.evaluate(f"() => {{ const T = window.sdiTwin; return {expr}; }}")


def wait(page: Any, expr: str, timeout_s: float = 300.0) -> None:
    """Wait until `expr` (over T = window.sdiTwin) is true; generous: software WebGL."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        page.wait_for_function(
            f"() => {{ const T = window.sdiTwin; return !!(T && T.ready && ({expr})); }}",
            timeout=timeout_s * 1000,
        )
    except PlaywrightTimeout:  # say where the page was instead, so a failure explains itself
        seen = page.evaluate(
            "() => { const T = window.sdiTwin || {}; const v = T.view || {};"
            " return { phase: T.phase, error: T.lastError, busy: v.busy, status: v.status,"
            " run_error: v.error, waiting: (v.waiting_for || {}).kind,"
            " parts: v.review ? v.review.parts.length : null, edits: v.review ?"
            " v.review.edits.length : null, editFailed: T.editFailed }; }"
        )
        raise AssertionError(f"the page never showed `{expr}` in {timeout_s:.0f} s; "
                             f"it shows {seen}") from None  # fmt: skip


def top(position: list[float], size: float = 0.05) -> list[float]:
    """The centre of a part's top face (what the camera above sees of it)."""
    return [position[0], position[1], position[2] + size / 2 - 1e-4]


def shot(page: Any, path: Path) -> None:
    """A screenshot once the page has drawn two more frames (what it shows is current)."""
    n = state(page, "T.frames")
    wait(page, f"T.frames >= {n + 2}")
    page.screenshot(path=path)


def drag(page: Any, src: list[float], dst: list[float], *, shift: bool = False) -> None:
    """A real mouse drag of the part whose top face is at `src` to put it under `dst`."""
    a = state(page, f"T.screenOf({top(src)})")
    b = state(page, f"T.screenOf({top(dst)})")
    page.mouse.move(a[0], a[1])
    if shift:
        page.keyboard.down("Shift")
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(a[0] + (b[0] - a[0]) * k / 10, a[1] + (b[1] - a[1]) * k / 10)
    page.mouse.up()
    if shift:
        page.keyboard.up("Shift")
