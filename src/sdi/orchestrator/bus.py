"""The message bus: one ordered event stream per run, m = (sender, receiver, type, payload, seq).

Every message is an event in the run database with its own sequence number: 1, 2, 3, … per
run, contiguous, assigned in the same statement that stores it (so two writers cannot take the
same number). Nothing is merged: two identical messages are two events. `sdi log RUN_ID` shows
the stream; `follow` yields it live.
"""

from __future__ import annotations

import json
import threading
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sdi.jsonable import plain
from sdi.orchestrator.rundb import connect, prepare

SCHEMA = """
CREATE TABLE IF NOT EXISTS events (
    run_id TEXT NOT NULL, seq INTEGER NOT NULL, ts REAL NOT NULL, sender TEXT NOT NULL,
    receiver TEXT NOT NULL, type TEXT NOT NULL, payload TEXT NOT NULL,
    PRIMARY KEY (run_id, seq)
);
"""


@dataclass(frozen=True)
class Message:
    run_id: str
    seq: int
    ts: float  # s since the epoch
    sender: str
    receiver: str
    type: str
    payload: dict[str, Any]

    @property
    def id(self) -> str:
        return f"{self.run_id}:{self.seq}"

    def to_json_dict(self) -> dict[str, Any]:
        return {"id": self.id, **self.__dict__}


class MessageBus:
    """The event stream of every run in one run database."""

    def __init__(self, path: str | Path, *, create: bool = True) -> None:
        self.path = prepare(Path(path), create=create)
        self._db = connect(self.path)
        self._db.isolation_level = None  # autocommit: every send is its own transaction
        self._db.executescript(SCHEMA)
        self._lock = threading.Lock()
        self.listeners: list[Callable[[Message], None]] = []
        """Called with every event this process sends, after it is stored (progress display)."""

    def send(
        self, run_id: str, sender: str, receiver: str, type: str, payload: dict[str, Any]
    ) -> int:
        """Store one event; returns its sequence number."""
        body = json.dumps(plain(payload), sort_keys=True, default=str)
        now = time.time()
        with self._lock:
            row = self._db.execute(
                "INSERT INTO events SELECT ?, COALESCE(MAX(seq), 0) + 1, ?, ?, ?, ?, ? "
                "FROM events WHERE run_id = ? RETURNING seq",
                (run_id, now, sender, receiver, type, body, run_id),
            ).fetchone()
        if self.listeners:
            message = Message(run_id, int(row[0]), now, sender, receiver, type, json.loads(body))
            for listener in self.listeners:
                listener(message)
        return int(row[0])

    def history(self, run_id: str, *, after: int = 0) -> list[Message]:
        """The run's events with a sequence number above `after`, in order."""
        with self._lock:
            rows = self._db.execute(
                "SELECT run_id, seq, ts, sender, receiver, type, payload FROM events "
                "WHERE run_id = ? AND seq > ? ORDER BY seq",
                (run_id, after),
            ).fetchall()
        return [Message(r[0], r[1], r[2], r[3], r[4], r[5], json.loads(r[6])) for r in rows]

    def follow(
        self,
        run_id: str,
        *,
        after: int = 0,
        done: Callable[[list[Message]], bool],
        poll_s: float = 0.2,
    ) -> Iterator[Message]:
        """Yield events as they arrive until `done(new_events)` says the run is quiet."""
        while True:
            new = self.history(run_id, after=after)
            yield from new
            if new:
                after = new[-1].seq
            if done(new):
                return
            time.sleep(poll_s)

    def runs(self) -> list[str]:
        with self._lock:
            rows = self._db.execute(
                "SELECT run_id FROM events GROUP BY run_id ORDER BY MIN(rowid)"
            ).fetchall()
        return [r[0] for r in rows]

    def close(self) -> None:
        self._db.close()
