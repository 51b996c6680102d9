"""A scripted chat model for control-flow tests (a test double: lives only in tests/)."""

from __future__ import annotations

import json
from collections.abc import Callable
from typing import Any

from sdi.llm.chat import ChatReply, Message, ToolCall, Usage

Script = Callable[[list[Message], dict[str, Any]], ChatReply | str | dict[str, Any]]


class ScriptedChat:
    """Replies from a list (one per call) or a function of (messages, options)."""

    name = "scripted"

    def __init__(self, replies: list[Any] | Script) -> None:
        self.replies = replies
        self.usage = Usage()
        self.calls: list[tuple[list[Message], dict[str, Any]]] = []

    def chat(self, messages: list[Message], **options: Any) -> ChatReply:
        self.calls.append(([dict(m) for m in messages], options))
        if callable(self.replies):
            reply = self.replies(messages, options)
        else:
            reply = self.replies[min(len(self.calls) - 1, len(self.replies) - 1)]
        if isinstance(reply, dict):
            reply = ChatReply(json.dumps(reply))
        elif isinstance(reply, str):
            reply = ChatReply(reply)
        self.usage.add(reply, options.get("role", "llm"))
        return reply


def tool_call(name: str, arguments: dict[str, Any] | str, call_id: str = "call_1") -> ChatReply:
    args = arguments if isinstance(arguments, str) else json.dumps(arguments)
    return ChatReply(None, (ToolCall(call_id, name, args),))


def cube(pid: str, x: float, y: float, z: float) -> dict[str, Any]:
    return {"id": pid, "position": [x, y, z], "size": [0.05, 0.05, 0.05]}


def tower(n: int, x: float = 0.4, y: float = 0.3) -> dict[str, Any]:
    return {"objects": [cube(f"c{k + 1}", x, y, 0.025 + 0.05 * k) for k in range(n)]}
