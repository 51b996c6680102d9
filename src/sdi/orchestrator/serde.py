"""The checkpoint serializer: plain data in, plain data out; nothing in a run database runs.

LangGraph's `JsonPlusSerializer` revives any `module.name(*args)` written into a checkpoint
unless it is told otherwise, so a crafted run database can make `sdi resume` call `os.system`.
SDI's state is plain JSON (`sdi.jsonable.plain`); the only objects LangGraph itself writes into
our checkpoints are its `Interrupt` (a pending review) and, in pending writes, `Command` and
`Send`. `PlainSerializer` revives exactly those three, refuses everything else — other
constructors, method calls, numpy buffers, legacy JSON constructors, pickle — with
`UnsafeCheckpointError` naming the type, and never imports a module named by the data.
"""

from __future__ import annotations

from typing import Any

import ormsgpack
from langgraph.checkpoint.serde.jsonplus import (
    EXT_CONSTRUCTOR_KW_ARGS,
    EXT_CONSTRUCTOR_POS_ARGS,
    EXT_CONSTRUCTOR_SINGLE_ARG,
    EXT_PYDANTIC_V2,
    JsonPlusSerializer,
)
from langgraph.types import Command, Interrupt, Send

from sdi.errors import SDIError

ALLOWED: dict[tuple[str, str], type] = {
    ("langgraph.types", "Interrupt"): Interrupt,
    ("langgraph.types", "Command"): Command,
    ("langgraph.types", "Send"): Send,
}
"""(module, name) → class: the only objects a checkpoint may hold besides plain data."""


class UnsafeCheckpointError(SDIError):
    """A checkpoint holds something other than plain data (a constructor, pickle, …)."""


def _ext_hook(code: int, data: bytes) -> Any:
    if code not in (EXT_CONSTRUCTOR_SINGLE_ARG, EXT_CONSTRUCTOR_POS_ARGS, EXT_CONSTRUCTOR_KW_ARGS,
                    EXT_PYDANTIC_V2):  # fmt: skip
        raise UnsafeCheckpointError(f"refused a msgpack extension of type {code}")
    tup = ormsgpack.unpackb(data, ext_hook=_ext_hook, option=ormsgpack.OPT_NON_STR_KEYS)
    if not (isinstance(tup, list | tuple) and len(tup) >= 3):
        raise UnsafeCheckpointError("refused a malformed msgpack extension")
    key = (str(tup[0]), str(tup[1]))
    cls = ALLOWED.get(key)
    if cls is None:
        raise UnsafeCheckpointError(f"refused to construct {key[0]}.{key[1]}")
    args = tup[2]
    try:
        if code == EXT_CONSTRUCTOR_SINGLE_ARG:
            return cls(args)
        if code == EXT_CONSTRUCTOR_POS_ARGS and isinstance(args, list | tuple):
            return cls(*args)
        if isinstance(args, dict):
            return cls(**args)
    except (TypeError, ValueError) as exc:
        raise UnsafeCheckpointError(f"malformed {key[0]}.{key[1]}: {exc}") from None
    raise UnsafeCheckpointError(f"malformed arguments for {key[0]}.{key[1]}")


class PlainSerializer(JsonPlusSerializer):
    """`JsonPlusSerializer` for writing; on reading, plain msgpack data and `ALLOWED` only."""

    def __init__(self) -> None:
        super().__init__(allowed_msgpack_modules=None, __unpack_ext_hook__=_ext_hook)

    def loads_typed(self, data: tuple[str, bytes]) -> Any:
        type_, payload = data
        if type_ in ("null", "bytes", "bytearray"):
            return super().loads_typed(data)
        if type_ != "msgpack":
            raise UnsafeCheckpointError(f"refused a checkpoint value of type {type_!r}")
        refused: list[UnsafeCheckpointError] = []

        def hook(code: int, data: bytes) -> Any:
            try:
                return _ext_hook(code, data)
            except UnsafeCheckpointError as exc:  # ormsgpack replaces it with its own error
                refused.append(exc)
                raise

        try:
            return ormsgpack.unpackb(payload, ext_hook=hook, option=ormsgpack.OPT_NON_STR_KEYS)
        except (ormsgpack.MsgpackDecodeError, TypeError, ValueError) as exc:
            if refused:
                raise refused[0] from None
            raise UnsafeCheckpointError(f"unreadable checkpoint value: {exc}") from None
