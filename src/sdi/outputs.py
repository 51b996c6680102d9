"""Output files: checked before anything is written, written whole or not at all.

Every file SDI writes (plans, results, reports, plots, robot programs) goes through an
`Outputs`: the caller names each output path first (`file`, `folder`), which checks it at once
— nothing is computed for a path that cannot be written — and then hands over the contents in
one `commit`. A commit writes each file to a temporary file in the same folder and renames it
into place, so a reader sees the old file or the new one, never half of one, and a failure
leaves no temporary file behind. All files of a commit are written before the first is
renamed, so an export that cannot write its Python program writes no RAPID module either.

**Which files did SDI write?** Each folder SDI writes into gets a small manifest,
``.sdi-outputs.json``: file name → SHA-256 of the bytes SDI wrote. A file may be replaced
without ``--force`` only if the manifest lists it and its content is still what SDI wrote;
a file SDI did not write, or one edited since, is refused unless ``force``. In an output
folder (``--rapid DIR``, ``--report DIR``), SDI's files from an earlier write that this write
does not produce again (the module of an arm no longer used, the plot of an earlier run) are
removed, so the folder never mixes two runs; other files in the folder are left alone.
"""

from __future__ import annotations

import contextlib
import errno
import fnmatch
import hashlib
import json
import os
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from sdi.errors import InputError

MANIFEST = ".sdi-outputs.json"
"""Name of the per-folder manifest of files SDI wrote."""


class OutputError(InputError):
    """An output path cannot be written (a folder, a missing parent, no permission, a file
    SDI did not write). `field` is the command-line option that named the path."""


def _digest(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _read_manifest(folder: Path) -> dict[str, str]:
    try:
        data = json.loads((folder / MANIFEST).read_text(encoding="utf-8"))
        files = data.get("files", {}) if isinstance(data, dict) else {}
        return {str(k): str(v) for k, v in files.items()} if isinstance(files, dict) else {}
    except (OSError, ValueError, RecursionError):
        return {}  # no manifest (or a broken one): SDI vouches for no file here


def written_by_sdi(path: Path) -> bool:
    """True if `path` is a file SDI wrote and nobody changed since (see the module doc)."""
    expected = _read_manifest(path.parent).get(path.name)
    if expected is None or not path.is_file():
        return False
    try:
        return _digest(path.read_bytes()) == expected
    except OSError:
        return False


def _reason(exc: OSError) -> str:
    fixes = {
        errno.EACCES: "permission denied; choose a folder you can write to",
        errno.EPERM: "not permitted; choose a folder you can write to",
        errno.EROFS: "read-only file system; choose another place",
        errno.ENOSPC: "no space left on the device; free some space or choose another place",
        errno.ENOENT: "no such folder; create it first or choose another place",
        errno.ENOTDIR: "a part of the path is a file, not a folder; choose another place",
        errno.EISDIR: "is a folder; give a file name",
    }
    return fixes.get(exc.errno or 0, f"{exc.strerror or exc}; choose another place")


@dataclass
class _Folder:
    path: Path
    option: str
    patterns: tuple[str, ...]
    create: bool

    def holds(self, name: str) -> bool:
        return any(fnmatch.fnmatch(name, p) for p in self.patterns)


@dataclass
class Outputs:
    """The output paths of one command, checked up front and written in one `commit`.

    `force` allows replacing files SDI did not write (see the module doc).
    """

    force: bool = False
    _files: dict[Path, str] = field(default_factory=dict)
    _folders: dict[Path, _Folder] = field(default_factory=dict)

    def file(self, path: Path | str, option: str) -> Path:
        """Register an output file named by command-line `option`; raise `OutputError` now if
        it cannot be written. Its folder must exist (SDI does not create chains of folders)."""
        path = Path(path)
        if path.name in ("", ".", "..") or path.is_dir():
            raise OutputError(f"{path} is a folder; give a file name", field=option)
        if path.name == MANIFEST:
            raise OutputError(f"{MANIFEST} is SDI's manifest; choose another name", field=option)
        pending = self._folders.get(path.parent)
        if pending is None or not pending.create:  # else: a folder this commit creates
            self._check_folder(path.parent, option)
        if path.exists() or path.is_symlink():
            self._check_replace(path, option)
        self._files[path] = option
        return path

    def folder(self, path: Path | str, option: str, *, patterns: tuple[str, ...]) -> Path:
        """Register an output folder for files named like `patterns` (globs: ``SDI_*.mod``).

        The folder is created at commit if missing (its parent must exist). Files matching
        a pattern that SDI did not write are refused unless `force` (which replaces them).
        """
        path = Path(path)
        folder = _Folder(path, option, patterns, create=not path.exists())
        if path.exists() and not path.is_dir():
            raise OutputError(f"{path} is a file; give a folder", field=option)
        if folder.create:
            self._check_folder(path.parent, option)
        else:
            self._check_folder(path, option)
            if not self.force:
                foreign = [
                    p.name
                    for p in sorted(path.iterdir())
                    if folder.holds(p.name) and p.is_file() and not written_by_sdi(p)
                ]
                if foreign:
                    raise OutputError(
                        f"{path} holds {', '.join(foreign[:5])}, which SDI did not write; "
                        "choose another folder or add --force to replace them",
                        field=option,
                    )
        self._folders[path] = folder
        return path

    def _check_folder(self, folder: Path, option: str) -> None:
        folder = folder if str(folder) else Path(".")
        if not folder.exists():
            raise OutputError(
                f"folder {folder} does not exist; create it first or choose another place",
                field=option,
            )
        if not folder.is_dir():
            raise OutputError(f"{folder} is not a folder; choose another place", field=option)
        if not os.access(folder, os.W_OK | os.X_OK):
            raise OutputError(
                f"cannot write in {folder}: permission denied; choose another place", field=option
            )

    def _check_replace(self, path: Path, option: str) -> None:
        if not path.is_file():
            raise OutputError(f"{path} exists and is not a regular file", field=option)
        if not self.force and not written_by_sdi(path):
            raise OutputError(
                f"{path} exists and SDI did not write it; add --force to replace it",
                field=option,
            )

    def commit(self, contents: dict[Path, bytes | str]) -> list[Path]:
        """Write `contents` (path → bytes or UTF-8 text) atomically; return the paths written.

        Every path must be a registered file or lie directly in a registered folder. Nothing
        is renamed into place until every file has been written in full.
        """
        data = {
            Path(p): c.encode("utf-8") if isinstance(c, str) else bytes(c)
            for p, c in contents.items()
        }
        for path in data:
            folder = self._folders.get(path.parent)
            if path not in self._files and folder is None:
                raise ValueError(f"{path} was not registered as an output")  # a bug, not input
            option = self._files.get(path) or (folder.option if folder else "")
            if folder is not None and path.exists():
                self._check_replace(path, option)
        created: list[Path] = []
        temps: dict[Path, str] = {}
        current = next(iter(data), Path("."))
        try:
            for folder in self._folders.values():
                if folder.create and not folder.path.exists():
                    current = folder.path
                    folder.path.mkdir()
                    created.append(folder.path)
            for path, blob in data.items():
                current = path
                temps[path] = _write_temp(path, blob)
            for path, temp in temps.items():
                current = path
                os.replace(temp, path)
        except OSError as exc:
            for temp in temps.values():
                with contextlib.suppress(OSError):
                    os.unlink(temp)
            for folder_path in reversed(created):
                with contextlib.suppress(OSError):
                    folder_path.rmdir()
            folder_of = self._folders.get(current) or self._folders.get(current.parent)
            option = self._files.get(current) or (folder_of.option if folder_of else "")
            raise OutputError(f"cannot write {current}: {_reason(exc)}", field=option) from None
        removed = self._remove_stale(set(data))
        self._update_manifests(data, removed)
        return list(data)

    def _remove_stale(self, written: set[Path]) -> set[Path]:
        removed = set()
        for folder in self._folders.values():
            for path in sorted(folder.path.iterdir()):
                if (
                    path not in written
                    and folder.holds(path.name)
                    and path.is_file()
                    and (self.force or written_by_sdi(path))
                ):
                    with contextlib.suppress(OSError):
                        path.unlink()
                        removed.add(path)
        return removed

    def _update_manifests(self, written: dict[Path, bytes], removed: set[Path]) -> None:
        folders = {p.parent for p in written} | {p.parent for p in removed}
        for folder in folders:
            entries = _read_manifest(folder)
            for path in removed:
                if path.parent == folder:
                    entries.pop(path.name, None)
            for path, blob in written.items():
                if path.parent == folder:
                    entries[path.name] = _digest(blob)
            entries = {k: v for k, v in entries.items() if (folder / k).is_file()}
            text = json.dumps({"written_by": "sdi", "files": entries}, indent=1, sort_keys=True)
            with contextlib.suppress(OSError):  # the outputs are written; the manifest is a help
                os.replace(_write_temp(folder / MANIFEST, text.encode() + b"\n"), folder / MANIFEST)


def write_atomic(path: Path | str, data: bytes | str) -> Path:
    """Write one file whole or not at all (temporary file beside it, then rename); no checks,
    no manifest — for library callers. The CLI uses `Outputs`."""
    path = Path(path)
    blob = data.encode("utf-8") if isinstance(data, str) else data
    os.replace(_write_temp(path, blob), path)
    return path


def _write_temp(path: Path, data: bytes) -> str:
    """Write `data` to a new temporary file beside `path`; return its name."""
    fd, temp = tempfile.mkstemp(dir=path.parent or ".", prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(temp, 0o644)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise
    return temp
