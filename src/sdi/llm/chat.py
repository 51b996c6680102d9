"""The one small protocol every LLM backend implements, and its accounting.

Messages are OpenAI chat messages (dicts with role/content, tool_calls, tool_call_id). A reply
is text, tool calls, or both. Every backend counts calls and tokens in `Usage`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

Message = dict[str, Any]


@dataclass(frozen=True)
class ToolCall:
    id: str
    name: str
    arguments: str  # JSON text, as the model wrote it (may be malformed)


@dataclass(frozen=True)
class ChatReply:
    content: str | None
    tool_calls: tuple[ToolCall, ...] = ()
    prompt_tokens: int = 0
    completion_tokens: int = 0

    def as_message(self) -> Message:
        """The assistant message to append to the conversation."""
        message: Message = {"role": "assistant", "content": self.content or ""}
        if self.tool_calls:
            message["tool_calls"] = [
                {
                    "id": c.id,
                    "type": "function",
                    "function": {"name": c.name, "arguments": c.arguments},
                }
                for c in self.tool_calls
            ]
        return message


@dataclass
class Usage:
    calls: int = 0
    prompt_tokens: int = 0
    completion_tokens: int = 0
    failures: int = 0
    malformed: int = 0
    by_role: dict[str, int] = field(default_factory=dict)

    def add(self, reply: ChatReply, role: str) -> None:
        self.calls += 1
        self.prompt_tokens += reply.prompt_tokens
        self.completion_tokens += reply.completion_tokens
        self.by_role[role] = self.by_role.get(role, 0) + 1

    def to_json_dict(self) -> dict[str, Any]:
        return {
            "llm_calls": self.calls,
            "prompt_tokens": self.prompt_tokens,
            "completion_tokens": self.completion_tokens,
            "failures": self.failures,
            "malformed": self.malformed,
            "by_role": dict(self.by_role),
        }


@runtime_checkable
class ChatModel(Protocol):
    """A chat-completion backend (OpenAI-compatible server, local llama.cpp, test double)."""

    name: str
    usage: Usage

    def chat(
        self,
        messages: list[Message],
        *,
        tools: list[dict[str, Any]] | None = None,
        json_schema: dict[str, Any] | None = None,
        max_tokens: int = 1024,
        temperature: float = 0.3,
        role: str = "llm",
        tool_choice: str | dict[str, Any] | None = None,
    ) -> ChatReply: ...
