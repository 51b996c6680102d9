"""The twin's web server: one page, a JSON API and a websocket per run, on 127.0.0.1.

FastAPI + three.js rather than viser: the twin must refuse clients without the token when it
listens beyond loopback (viser's server has no authentication hook), keep its state in the run
database that the CLI shares, and be driven by end-to-end tests through the page itself.

- ``GET /`` the page; ``/static`` its script and style; ``/vendor/three`` three.js (from npm).
- ``GET /api/scene`` the fixed scene; ``GET/POST /api/runs`` list runs / start one.
- ``GET /api/runs/{id}`` the run's view; ``/timeline?record=HASH`` its commissioning record
  for the preview (default: the current one); ``/events?after=N`` its event stream;
  ``/replay`` the run told again from its events (`sdi.twin.replay`).
- ``POST /api/runs/{id}/lock|edit|accept|reject|abort|confirm|edit-review|failure`` the touch
  points.

Every handler that reads or writes the run database does it in a worker thread, never on the
event loop.
- ``WS /ws/runs/{id}`` new events as they are stored (samples of Q_exec at 10 Hz, never whole
  trajectories); the page answers with heartbeats that keep its edit lock.

A user mistake is a 400 (409: another tab holds the lock) with ``{"error", "field"}``.
"""

from __future__ import annotations

import asyncio
import ipaddress
import secrets
from pathlib import Path
from typing import Any

from fastapi import FastAPI, Request, WebSocket, WebSocketDisconnect
from fastapi.responses import FileResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from starlette.middleware.base import BaseHTTPMiddleware, RequestResponseEndpoint

from sdi.errors import InputError
from sdi.model.cell import CellConfig
from sdi.twin.scene import scene
from sdi.twin.service import LockedError, Twin

WEB = Path(__file__).parent / "web"
THREE = WEB / "node_modules" / "three"
POLL_S = 0.1
"""How often a websocket looks for new events in the run database, s."""


def is_loopback(host: str) -> bool:
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def check_bind(host: str, token: str | None) -> None:
    """Listening beyond loopback needs a token every client must present."""
    if not is_loopback(host) and not token:
        raise InputError(
            f"listening on {host} would let anyone on the network steer the robots; give "
            "--token SECRET (every client must present it) or keep the default 127.0.0.1",
            field="--host",
        )


def check_assets() -> None:
    if not (THREE / "build" / "three.module.js").is_file():
        raise InputError(
            f"the twin's browser library three.js is missing under {WEB}; run `make twin-assets` "
            "(npm install there)",
            field="twin",
        )


class _TokenGate(BaseHTTPMiddleware):
    def __init__(self, app: Any, token: str) -> None:
        super().__init__(app)
        self.token = token

    async def dispatch(self, request: Request, call_next: RequestResponseEndpoint) -> Response:
        if not presented(self.token, request.query_params.get("token"),
                         request.headers.get("authorization"),
                         request.cookies.get("sdi_token")):  # fmt: skip
            return JSONResponse({"error": "this twin needs its token", "field": "token"}, 401)
        response = await call_next(request)
        if request.query_params.get("token"):
            response.set_cookie("sdi_token", self.token, httponly=True, samesite="strict")
        return response


def presented(token: str, query: str | None, header: str | None, cookie: str | None) -> bool:
    given = [query, cookie]
    if header and header.lower().startswith("bearer "):
        given.append(header[7:])
    return any(g and secrets.compare_digest(g, token) for g in given)


def _error(exc: InputError) -> JSONResponse:
    status = 409 if isinstance(exc, LockedError) else 400
    if exc.field == "RUN_ID":
        status = 404
    return JSONResponse({"error": str(exc), "field": exc.field}, status)


def create_app(twin: Twin, *, token: str | None = None) -> FastAPI:
    app = FastAPI(title="SDI twin", docs_url=None, redoc_url=None, openapi_url=None)
    if token:
        app.add_middleware(_TokenGate, token=token)
    check_assets()
    app.mount("/static", StaticFiles(directory=WEB / "static"), name="static")
    app.mount("/vendor/three", StaticFiles(directory=THREE), name="three")
    cell = twin.cell or CellConfig()
    fixed = scene(cell)

    @app.exception_handler(InputError)
    async def _input_error(request: Request, exc: InputError) -> JSONResponse:
        return _error(exc)

    async def body(request: Request) -> dict[str, Any]:
        try:
            data = await request.json()
        except ValueError:
            raise InputError("the request body must be a JSON object", field="body") from None
        if not isinstance(data, dict):
            raise InputError("the request body must be a JSON object", field="body")
        return data

    def text(data: dict[str, Any], key: str) -> str:
        value = data.get(key, "")
        if not isinstance(value, str):
            raise InputError("must be text", field=key)
        return value

    @app.get("/")
    async def page() -> FileResponse:
        return FileResponse(WEB / "index.html")

    @app.get("/api/scene")
    async def get_scene() -> dict[str, Any]:
        return fixed

    @app.get("/api/runs")
    async def list_runs() -> list[dict[str, Any]]:
        return await asyncio.to_thread(twin.runs)

    @app.post("/api/runs")
    async def start_run(request: Request) -> dict[str, Any]:
        data = await body(request)
        faults = data.get("faults") or []
        if not (isinstance(faults, list) and all(isinstance(f, str) for f in faults)):
            raise InputError("must be a list of fault scenario names", field="faults")
        return {"run_id": await asyncio.to_thread(twin.start, text(data, "command"), faults)}

    @app.get("/api/runs/{run_id}")
    async def get_run(run_id: str) -> dict[str, Any]:
        return await asyncio.to_thread(twin.view, run_id)

    @app.get("/api/runs/{run_id}/timeline")
    async def get_timeline(run_id: str, record: str | None = None) -> dict[str, Any]:
        return await asyncio.to_thread(twin.timeline, run_id, record)

    @app.get("/api/runs/{run_id}/replay")
    async def get_replay(run_id: str) -> dict[str, Any]:
        return await asyncio.to_thread(twin.replay, run_id)

    @app.get("/api/runs/{run_id}/events")
    async def get_events(run_id: str, after: int = 0) -> list[dict[str, Any]]:
        return await asyncio.to_thread(twin.events, run_id, after)

    @app.post("/api/runs/{run_id}/lock")
    async def take_lock(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        if data.get("release"):
            twin.release(run_id, text(data, "tab"))
            return {"lock": twin.holder(run_id)}
        return {"lock": twin.lock(run_id, text(data, "tab")).tab}

    @app.post("/api/runs/{run_id}/edit")
    async def edit(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        op = data.get("op")
        if not isinstance(op, dict):
            raise InputError("needs an operation object", field="op")
        return await asyncio.to_thread(twin.edit, run_id, text(data, "tab"), op)

    @app.post("/api/runs/{run_id}/accept")
    async def accept(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        await asyncio.to_thread(twin.accept, run_id, text(data, "tab"), text(data, "layout_hash"))
        return {"ok": True}

    @app.post("/api/runs/{run_id}/reject")
    async def reject(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        await asyncio.to_thread(twin.reject, run_id, text(data, "tab"), text(data, "reason"))
        return {"ok": True}

    @app.post("/api/runs/{run_id}/abort")
    async def abort(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        await asyncio.to_thread(twin.abort, run_id, text(data, "tab"))
        return {"ok": True}

    @app.post("/api/runs/{run_id}/confirm")
    async def confirm(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        record = data.get("record_hash")
        await asyncio.to_thread(
            twin.confirm, run_id, text(data, "tab"), text(data, "action"),
            record if isinstance(record, str) else None,
        )  # fmt: skip
        return {"ok": True}

    @app.post("/api/runs/{run_id}/edit-review")
    async def edit_review(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        await asyncio.to_thread(twin.resolve_edit, run_id, text(data, "tab"), text(data, "action"))
        return {"ok": True}

    @app.post("/api/runs/{run_id}/failure")
    async def failure(run_id: str, request: Request) -> dict[str, Any]:
        data = await body(request)
        skill = data.get("skill")
        await asyncio.to_thread(
            twin.failure_decision, run_id, text(data, "tab"), text(data, "action"),
            skill if isinstance(skill, str) else None,
        )  # fmt: skip
        return {"ok": True}

    @app.websocket("/ws/runs/{run_id}")
    async def stream(ws: WebSocket, run_id: str) -> None:
        if token and not presented(token, ws.query_params.get("token"), None,
                                   ws.cookies.get("sdi_token")):  # fmt: skip
            await ws.close(code=4401)
            return
        await ws.accept()
        tab = ws.query_params.get("tab", "")
        after = int(ws.query_params.get("after", "0") or 0)

        async def heartbeats() -> None:
            while True:
                await ws.receive_text()
                twin.seen(run_id, tab)

        listener = asyncio.create_task(heartbeats())
        try:
            while not listener.done():
                new = await asyncio.to_thread(twin.events, run_id, after)
                if new:
                    after = new[-1]["seq"]
                    await ws.send_json({"type": "events", "events": new})
                await asyncio.sleep(POLL_S)
        except (WebSocketDisconnect, RuntimeError):
            pass
        finally:
            listener.cancel()

    return app


def serve(
    twin: Twin, *, host: str = "127.0.0.1", port: int = 8765, token: str | None = None
) -> None:
    """Serve until interrupted (the CLI's `sdi twin`)."""
    import uvicorn

    check_bind(host, token)
    app = create_app(twin, token=token)
    uvicorn.run(app, host=host, port=port, log_level="warning", ws="websockets-sansio")
