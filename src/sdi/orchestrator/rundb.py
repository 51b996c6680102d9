"""The run database file: created private, checked to be SQLite before anything reads it.

One SQLite file holds a run's checkpoints, its event stream, its lease and its commissioning
records. It holds commands and layouts, so SDI creates it readable by its owner only (0600)
and any directory it creates for it 0700. An existing file is used as it is (its mode is the
owner's choice), but it must be a SQLite database: a directory, a garbage or truncated file is
refused with an `InputError` that names the path.
"""

from __future__ import annotations

import os
import sqlite3
from pathlib import Path

from sdi.errors import InputError

BUSY_TIMEOUT_S = 30.0
"""How long a connection waits for another process's write lock, s."""


def default_db() -> Path:
    """`$SDI_DB`, or ``runs.sqlite`` in the user's data directory."""
    env = os.environ.get("SDI_DB")
    if env:
        return Path(env)
    from platformdirs import user_data_dir

    return Path(user_data_dir("sdi")) / "runs.sqlite"


def _make_private_dirs(directory: Path) -> None:
    missing = []
    d = directory
    while not d.exists():
        missing.append(d)
        if d.parent == d:
            break
        d = d.parent
    for d in reversed(missing):
        try:
            d.mkdir(mode=0o700)
        except FileExistsError:
            continue
        os.chmod(d, 0o700)  # mkdir's mode is filtered by the umask


def prepare(path: Path, *, create: bool = True) -> Path:
    """Make sure `path` is a usable run database file; create it (0600) if `create`."""
    if path.is_dir():
        raise InputError(f"{path} is a directory; give the database file", field="--db")
    if not path.exists():
        if not create:
            raise InputError(f"no run database at {path}", field="--db")
        try:
            _make_private_dirs(path.parent)
            fd = os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o600)
            os.close(fd)
        except FileExistsError:
            pass  # another process made it first
        except OSError as exc:
            raise InputError(f"cannot create {path}: {exc.strerror}", field="--db") from None
    return path


def connect(path: Path) -> sqlite3.Connection:
    """A connection to a prepared run database; refuses a file that is not SQLite."""
    try:
        conn = sqlite3.connect(path, check_same_thread=False, timeout=BUSY_TIMEOUT_S)
        conn.execute("PRAGMA schema_version").fetchone()
    except sqlite3.DatabaseError as exc:
        raise InputError(f"{path} is not a usable run database ({exc})", field="--db") from None
    return conn
