"""The message bus: typed messages m = (sender, receiver, type, payload, id), persisted in SQLite.

Every message of a run is stored, so `sdi log RUN_ID` shows the audit trail. Ids are content
hashes: a graph node that re-runs after a crash or a resume sends the same message again, and
the bus keeps one copy.
"""

from __future__ import annotations

import hashlib
import json
import sqlite3
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sdi.jsonable import plain

SCHEMA = """
CREATE TABLE IF NOT EXISTS messages (
    id TEXT PRIMARY KEY, run_id TEXT NOT NULL, seq INTEGER NOT NULL, ts REAL NOT NULL,
    sender TEXT NOT NULL, receiver TEXT NOT NULL, type TEXT NOT NULL, payload TEXT NOT NULL
);
CREATE INDEX IF NOT EXISTS messages_run ON messages (run_id, seq);
"""


@dataclass(frozen=True)
class Message:
    id: str
    run_id: str
    seq: int
    ts: float
    sender: str
    receiver: str
    type: str
    payload: dict[str, Any]


class MessageBus:
    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._db = sqlite3.connect(self.path, check_same_thread=False)
        self._db.executescript(SCHEMA)
        self._db.commit()

    def send(
        self,
        run_id: str,
        sender: str,
        receiver: str,
        type: str,
        payload: dict[str, Any],
        *,
        key: str = "",
    ) -> str:
        body = json.dumps(plain(payload), sort_keys=True, default=str)
        mid = hashlib.sha1(
            f"{run_id}|{sender}|{receiver}|{type}|{key}|{body}".encode()
        ).hexdigest()[:16]
        seq = self._db.execute(
            "SELECT COALESCE(MAX(seq), 0) + 1 FROM messages WHERE run_id = ?", (run_id,)
        ).fetchone()[0]
        self._db.execute(
            "INSERT OR IGNORE INTO messages VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
            (mid, run_id, seq, time.time(), sender, receiver, type, body),
        )
        self._db.commit()
        return mid

    def history(self, run_id: str) -> list[Message]:
        rows = self._db.execute(
            "SELECT id, run_id, seq, ts, sender, receiver, type, payload FROM messages "
            "WHERE run_id = ? ORDER BY seq",
            (run_id,),
        ).fetchall()
        return [Message(r[0], r[1], r[2], r[3], r[4], r[5], r[6], json.loads(r[7])) for r in rows]

    def runs(self) -> list[str]:
        return [
            r[0] for r in self._db.execute("SELECT DISTINCT run_id FROM messages ORDER BY rowid")
        ]

    def close(self) -> None:
        self._db.close()
