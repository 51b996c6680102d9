"""A layout `C`: an ordered collection of parts with unique ids, and its JSON I/O.

`parse_layout` is the one door for layouts from outside (files, the CLI, an LLM): it refuses
malformed JSON, unknown fields, non-finite numbers, bad sizes, unnormalised quaternions,
duplicate ids and more parts than the configured limit, naming the offending field or part.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterable, Iterator
from functools import cached_property
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, ValidationError, model_validator

from sdi.errors import InputError, LimitError
from sdi.model.part import Part

DEFAULT_MAX_PARTS = 10_000


class Layout(BaseModel):
    """An immutable layout. `objects` keeps the order it was given in."""

    model_config = ConfigDict(frozen=True, extra="forbid")

    objects: tuple[Part, ...] = ()

    @model_validator(mode="after")
    def _unique_ids(self) -> Layout:
        seen: set[str] = set()
        for index, part in enumerate(self.objects):
            if part.id in seen:
                raise ValueError(
                    f"duplicate part id {part.id!r} at objects[{index}]; every id must be unique"
                )
            seen.add(part.id)
        return self

    def __len__(self) -> int:
        return len(self.objects)

    def __iter__(self) -> Iterator[Part]:  # type: ignore[override]
        return iter(self.objects)

    @cached_property
    def index(self) -> dict[str, int]:
        """Part id → position in `objects`."""
        return {part.id: i for i, part in enumerate(self.objects)}

    @cached_property
    def ids(self) -> list[str]:
        return [part.id for part in self.objects]

    @cached_property
    def centres(self) -> np.ndarray:
        """Part centres, metres, shape (N, 3)."""
        if not self.objects:
            return np.zeros((0, 3))
        return np.array([part.position for part in self.objects], dtype=float)

    @cached_property
    def half_extents(self) -> np.ndarray:
        """AABB half extents, metres, shape (N, 3)."""
        if not self.objects:
            return np.zeros((0, 3))
        half = 0.5 * np.array([part.size for part in self.objects], dtype=float)
        for i, part in enumerate(self.objects):
            if part.orientation != (1.0, 0.0, 0.0, 0.0):
                half[i] = part.half_extents
        return half

    @cached_property
    def volumes(self) -> np.ndarray:
        """Part volumes, m³, shape (N,); uniform density makes these the masses."""
        if not self.objects:
            return np.zeros(0)
        return np.array([math.prod(part.size) for part in self.objects], dtype=float)

    def part(self, part_id: str) -> Part:
        return self.objects[self.index[part_id]]

    def replaced(self, parts: Iterable[Part]) -> Layout:
        """A new layout holding `parts` (validated again)."""
        return Layout(objects=tuple(parts))

    def to_json_dict(self) -> dict[str, Any]:
        """The JSON contract: ``{objects: [{id, position, orientation, size}]}``, metres."""
        return {
            "objects": [
                {
                    "id": p.id,
                    "position": [round(float(v), 6) for v in p.position],
                    "orientation": [round(float(v), 9) for v in p.orientation],
                    "size": [round(float(v), 6) for v in p.size],
                }
                for p in self.objects
            ]
        }


def _field_path(loc: tuple[int | str, ...]) -> str:
    path = ""
    for item in loc:
        path += f"[{item}]" if isinstance(item, int) else (f".{item}" if path else str(item))
    return path


def _describe(error: ValidationError, data: Any) -> InputError:
    first = error.errors()[0]
    loc = tuple(first["loc"])
    field = _field_path(loc)
    message = first["msg"].removeprefix("Value error, ")
    if first["type"] == "extra_forbidden":
        if len(loc) >= 2 and loc[0] == "objects":
            message = "unknown field; a part has only id, position, orientation, size"
        else:
            message = "unknown field; a layout has only 'objects' (and 'sequence')"
    # Name the part, not only its index, when we can.
    if len(loc) >= 2 and loc[0] == "objects" and isinstance(loc[1], int):
        try:
            part_id = data["objects"][loc[1]].get("id")
        except (KeyError, IndexError, TypeError, AttributeError):
            part_id = None
        if part_id is not None:
            message = f"{message} (part {part_id!r})"
    return InputError(message, field=field or None)


def parse_layout(
    data: str | bytes | dict[str, Any], *, max_parts: int = DEFAULT_MAX_PARTS
) -> tuple[Layout, list[str] | None]:
    """Parse a layout document; return the layout and its ``sequence`` if the document has one.

    Accepts ``{"objects": [...], "sequence": [...]?}`` or a whole `sdi plan --json` result
    (``{"layout": {...}, "sequence": [...], ...}``).
    """
    if isinstance(data, str | bytes):
        try:
            data = json.loads(data, parse_constant=_refuse_constant)
        except json.JSONDecodeError as exc:
            raise InputError(
                f"not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}"
            ) from None
        except RecursionError:
            raise InputError(
                'JSON nested too deeply; a layout is {"objects": [parts]}, a few levels deep'
            ) from None
    if not isinstance(data, dict):
        raise InputError("a layout must be a JSON object with an 'objects' list")
    sequence = data.get("sequence")
    if "layout" in data:
        data = data["layout"]
        if not isinstance(data, dict):
            raise InputError("must be an object with an 'objects' list", field="layout")
    else:
        data = {k: v for k, v in data.items() if k != "sequence"}
    objects = data.get("objects")
    if not isinstance(objects, list):
        raise InputError("missing or not a list; put the parts under 'objects'", field="objects")
    if len(objects) > max_parts:
        raise LimitError(
            f"{len(objects)} parts is more than the limit of {max_parts}; "
            "split the job or raise limits.max_parts in the cell configuration",
            field="objects",
        )
    try:
        layout = Layout.model_validate(data)
    except ValidationError as exc:
        raise _describe(exc, data) from None
    if sequence is not None:
        sequence = _check_sequence(sequence, layout)
    return layout, sequence


def _check_sequence(sequence: Any, layout: Layout) -> list[str]:
    if not isinstance(sequence, list) or not all(isinstance(s, str) for s in sequence):
        raise InputError("must be a list of part ids", field="sequence")
    unknown = [s for s in sequence if s not in layout.index]
    if unknown:
        raise InputError(
            f"unknown part ids {unknown[:5]}; use ids from 'objects'", field="sequence"
        )
    if len(set(sequence)) != len(sequence):
        raise InputError("lists a part more than once; each part is placed once", field="sequence")
    missing = [i for i in layout.ids if i not in set(sequence)]
    if missing:
        raise InputError(
            f"leaves out parts {missing[:5]}; a sequence orders every part", field="sequence"
        )
    return list(sequence)


def _refuse_constant(name: str) -> float:
    raise InputError(f"{name} is not allowed; every number must be finite")


def load_layout(
    path: str | Path, *, max_parts: int = DEFAULT_MAX_PARTS
) -> tuple[Layout, list[str] | None]:
    """Read and parse a layout file (see `parse_layout`)."""
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"no such file: {path}; check the path") from None
    except IsADirectoryError:
        raise InputError(f"{path} is a folder; give a layout JSON file") from None
    except UnicodeDecodeError:
        raise InputError(f"cannot read {path}: not UTF-8 text; give a layout JSON file") from None
    except OSError as exc:
        raise InputError(f"cannot read {path}: {exc.strerror or exc}; check the path") from None
    return parse_layout(text, max_parts=max_parts)
