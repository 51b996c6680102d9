"""Run leases: one process at a time owns (advances, executes) a run.

A lease is a row ``(run_id, token, pid, host, acquired, heartbeat)`` in the run database, taken
in one ``BEGIN IMMEDIATE`` transaction, so of two processes that try at once exactly one gets
it. The owner refreshes the heartbeat while it holds the lease and deletes the row when it is
done. A lease is stale — and may be taken over — when its heartbeat is older than
`stale_after_s`, or at once when its owner is a process on this host that no longer exists
(killed with -9, say). Anyone else gets `RunBusyError` naming the owner's pid and host.
"""

from __future__ import annotations

import os
import socket
import sqlite3
import threading
import time
import uuid
from dataclasses import dataclass
from pathlib import Path
from types import TracebackType

from sdi.errors import SDIError
from sdi.orchestrator.rundb import BUSY_TIMEOUT_S

SCHEMA = """
CREATE TABLE IF NOT EXISTS leases (
    run_id TEXT PRIMARY KEY, token TEXT NOT NULL, pid INTEGER NOT NULL, host TEXT NOT NULL,
    acquired REAL NOT NULL, heartbeat REAL NOT NULL
);
"""

STALE_AFTER_S = 60.0
"""A lease whose heartbeat is older than this (s) is stale."""


class RunBusyError(SDIError):
    """Another live process owns the run."""

    def __init__(self, run_id: str, pid: int, host: str, age_s: float) -> None:
        self.run_id, self.pid, self.host = run_id, pid, host
        super().__init__(
            f"run {run_id} is being executed by pid {pid} on {host} (last heartbeat "
            f"{age_s:.0f} s ago); wait for it to finish, or, if that process is gone, for its "
            f"lease to go stale ({STALE_AFTER_S:.0f} s after the last heartbeat)"
        )


@dataclass(frozen=True)
class Holder:
    pid: int
    host: str
    heartbeat: float


def _alive(pid: int) -> bool:
    """Whether a process with this pid exists on this host (a zombie counts as gone)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
        return stat.rsplit(")", 1)[1].split()[0] != "Z"
    except (OSError, IndexError):
        return True


class RunLease:
    """The lease on one run; a context manager (`with RunLease(db, run_id): ...`)."""

    def __init__(self, db: Path, run_id: str, *, stale_after_s: float = STALE_AFTER_S) -> None:
        self.db = db
        self.run_id = run_id
        self.stale_after_s = stale_after_s
        self.token = uuid.uuid4().hex
        self.pid = os.getpid()
        self.host = socket.gethostname()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def _connect(self) -> sqlite3.Connection:
        conn = sqlite3.connect(self.db, timeout=BUSY_TIMEOUT_S, isolation_level=None)
        conn.executescript(SCHEMA)
        return conn

    def holder(self) -> Holder | None:
        """The live owner of the run, if any (None when free or stale)."""
        conn = self._connect()
        try:
            return self._live(conn)
        finally:
            conn.close()

    def _live(self, conn: sqlite3.Connection) -> Holder | None:
        row = conn.execute(
            "SELECT token, pid, host, heartbeat FROM leases WHERE run_id = ?", (self.run_id,)
        ).fetchone()
        if row is None or row[0] == self.token:
            return None
        holder = Holder(int(row[1]), str(row[2]), float(row[3]))
        if time.time() - holder.heartbeat > self.stale_after_s:
            return None
        if holder.host == self.host and not _alive(holder.pid):
            return None
        return holder

    def acquire(self) -> None:
        conn = self._connect()
        try:
            conn.execute("BEGIN IMMEDIATE")
            holder = self._live(conn)
            if holder is not None:
                conn.execute("ROLLBACK")
                raise RunBusyError(
                    self.run_id, holder.pid, holder.host, time.time() - holder.heartbeat
                )
            now = time.time()
            conn.execute(
                "INSERT OR REPLACE INTO leases VALUES (?, ?, ?, ?, ?, ?)",
                (self.run_id, self.token, self.pid, self.host, now, now),
            )
            conn.execute("COMMIT")
        finally:
            conn.close()
        self._stop.clear()
        self._thread = threading.Thread(target=self._beat, name="sdi-lease", daemon=True)
        self._thread.start()

    def _beat(self) -> None:
        conn = self._connect()
        try:
            while not self._stop.wait(self.stale_after_s / 4):
                conn.execute(
                    "UPDATE leases SET heartbeat = ? WHERE run_id = ? AND token = ?",
                    (time.time(), self.run_id, self.token),
                )
        finally:
            conn.close()

    def release(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join()
            self._thread = None
        conn = self._connect()
        try:
            conn.execute(
                "DELETE FROM leases WHERE run_id = ? AND token = ?", (self.run_id, self.token)
            )
        finally:
            conn.close()

    def __enter__(self) -> RunLease:
        self.acquire()
        return self

    def __exit__(
        self,
        exc_type: type[BaseException] | None,
        exc: BaseException | None,
        tb: TracebackType | None,
    ) -> None:
        self.release()
