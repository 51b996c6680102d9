"""The commissioning records of runs, stored once each in the run database under their hash."""

from __future__ import annotations

import threading
import time
from pathlib import Path

from sdi.execute.record import CommissioningRecord, RecordError
from sdi.orchestrator.rundb import connect, prepare

SCHEMA = """
CREATE TABLE IF NOT EXISTS records (
    run_id TEXT NOT NULL, hash TEXT NOT NULL, created REAL NOT NULL, body TEXT NOT NULL,
    PRIMARY KEY (run_id, hash)
);
"""


class RecordStore:
    def __init__(self, path: Path) -> None:
        self._db = connect(prepare(path))
        self._db.isolation_level = None
        self._db.executescript(SCHEMA)
        self._lock = threading.Lock()

    def put(self, run_id: str, record: CommissioningRecord) -> None:
        with self._lock:
            self._db.execute(
                "INSERT OR IGNORE INTO records VALUES (?, ?, ?, ?)",
                (run_id, record.hash, time.time(), record.text),
            )

    def get(self, run_id: str, record_hash: str) -> CommissioningRecord:
        """The stored record; `RecordError` if it is missing or no longer matches its hash."""
        with self._lock:
            row = self._db.execute(
                "SELECT body FROM records WHERE run_id = ? AND hash = ?", (run_id, record_hash)
            ).fetchone()
        if row is None:
            raise RecordError(f"run {run_id} has no commissioning record {record_hash[:12]}")
        return CommissioningRecord.load(str(row[0]), record_hash)

    def close(self) -> None:
        self._db.close()
