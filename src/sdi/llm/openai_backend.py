"""Any OpenAI-compatible endpoint through the official `openai` SDK.

OpenAI, Azure, Ollama, vLLM, LM Studio and llama.cpp's server all speak this protocol. Structured
output asks for `response_format={"type": "json_schema", ...}` first; servers that refuse that
type (llama.cpp accepts `{"type": "json_object", "schema": ...}` instead) get the fallback, and
the client remembers which one worked. Timeouts and bounded retries with exponential backoff
come from the SDK; every call is counted in `usage`.
"""

from __future__ import annotations

import html
import json
import os
from typing import Any

from sdi import deadline
from sdi.errors import SDIError
from sdi.llm.chat import ChatReply, Message, ToolCall, Usage


class LLMError(SDIError):
    """The model endpoint failed (unreachable, refused, timed out after retries)."""


class OpenAIChat:
    def __init__(
        self,
        *,
        model: str | None = None,
        base_url: str | None = None,
        api_key: str | None = None,
        timeout: float = 120.0,
        max_retries: int = 2,
        name: str = "openai",
    ) -> None:
        import openai

        self.name = name
        self.model = model or os.environ.get("SDI_LLM_MODEL") or "gpt-4o-mini"
        self.usage = Usage()
        self._schema_mode = "json_schema"
        self._timeout = timeout
        self._client = openai.OpenAI(
            base_url=base_url
            or os.environ.get("SDI_LLM_BASE_URL")
            or os.environ.get("OPENAI_BASE_URL"),
            api_key=api_key or os.environ.get("OPENAI_API_KEY") or "not-needed",
            timeout=timeout,
            max_retries=max_retries,
        )

    def _format(self, schema: dict[str, Any]) -> dict[str, Any]:
        if self._schema_mode == "json_schema":
            return {"type": "json_schema", "json_schema": {"name": "output", "schema": schema}}
        return {"type": "json_object", "schema": schema}

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
    ) -> ChatReply:
        import openai

        kwargs: dict[str, Any] = {
            "model": self.model,
            "messages": messages,
            "max_tokens": max_tokens,
            "temperature": temperature,
        }
        if tools:
            kwargs["tools"] = tools
            if tool_choice is not None:
                kwargs["tool_choice"] = tool_choice
        for _ in range(2):
            if json_schema is not None:
                kwargs["response_format"] = self._format(json_schema)
            deadline.check()
            left = deadline.remaining()
            if left is not None:  # never wait past the phase's wall-clock limit
                kwargs["timeout"] = max(1.0, min(self._timeout, left))
            try:
                response = self._client.chat.completions.create(**kwargs)
                break
            except (openai.BadRequestError, openai.InternalServerError) as exc:
                # llama.cpp's server refuses the json_schema type (with a 400 or a 500)
                refused = "json_schema" in str(exc) or isinstance(exc, openai.BadRequestError)
                if json_schema is not None and self._schema_mode == "json_schema" and refused:
                    self._schema_mode = "json_object"
                    continue
                self.usage.failures += 1
                raise LLMError(f"{self.name}: the endpoint refused the request: {exc}") from None
            except openai.OpenAIError as exc:
                self.usage.failures += 1
                raise LLMError(f"{self.name}: {type(exc).__name__}: {exc}") from None
        else:  # pragma: no cover - both formats refused
            raise LLMError(f"{self.name}: no structured-output format accepted")
        choice = response.choices[0].message
        calls = tuple(
            ToolCall(c.id or f"call_{k}", c.function.name, c.function.arguments or "{}")
            for k, c in enumerate(choice.tool_calls or [])
            if getattr(c, "function", None) is not None
        )
        usage = response.usage
        reply = ChatReply(
            content=choice.content,
            tool_calls=calls,
            prompt_tokens=getattr(usage, "prompt_tokens", 0) or 0,
            completion_tokens=getattr(usage, "completion_tokens", 0) or 0,
        )
        self.usage.add(reply, role)
        return reply


def parse_json(text: str | None, *, limit: int = 200_000) -> Any:
    """The first JSON value in a model's text (fenced code blocks allowed); ValueError if none."""
    if not text:
        raise ValueError("empty reply")
    if len(text) > limit:
        raise ValueError(f"reply of {len(text)} characters exceeds {limit}")
    cleaned = text.strip()
    if "&#34;" in cleaned or "&quot;" in cleaned:  # some chat templates HTML-escape quotes
        cleaned = html.unescape(cleaned)
    if "```" in cleaned:
        parts = cleaned.split("```")
        cleaned = max(parts[1::2], key=len) if len(parts) > 2 else cleaned
        cleaned = cleaned.removeprefix("json").strip()
    start = min((i for i in (cleaned.find("{"), cleaned.find("[")) if i >= 0), default=-1)
    if start < 0:
        raise ValueError("no JSON object in the reply")
    value, _ = json.JSONDecoder().raw_decode(cleaned[start:])
    return value
