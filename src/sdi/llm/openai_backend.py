"""Any OpenAI-compatible endpoint through the official `openai` SDK.

OpenAI, Azure, Ollama, vLLM, LM Studio and llama.cpp's server all speak this protocol. Structured
output asks for `response_format={"type": "json_schema", ...}` first; servers that refuse that
type (llama.cpp accepts `{"type": "json_object", "schema": ...}` instead) get the fallback, and
the client remembers which one worked.

Faults are handled here, never passed on as crashes. One call has **one wall-clock budget**
(`timeout`, seconds) that covers every try, clipped further to the orchestrator phase's limit
(`sdi.deadline`); the SDK's own retries are off and each try runs in a worker thread that is
abandoned when the budget runs out, so a hanging endpoint costs at most the budget. Transient
faults (no connection, a timeout, HTTP 408/409/429/5xx, a reply that is not a chat completion)
are retried (`max_retries` more tries) with a short backoff; then `LLMError` says what
happened (its `reason` is short enough for a note: "HTTP 500 after 2 tries"). The raw body is
parsed here, so an HTML proxy page, garbage bytes, `{"choices": []}`, JSON that is not a
completion or JSON nested 90 000 levels deep are each counted in `usage.malformed`.
"""

from __future__ import annotations

import html
import json
import os
import threading
import time
from collections.abc import Callable
from contextlib import AbstractContextManager, nullcontext
from typing import Any
from urllib.parse import urlsplit

from sdi import deadline
from sdi.errors import SDIError
from sdi.llm.chat import ChatReply, Message, ToolCall, Usage

Waiting = Callable[[str], AbstractContextManager[object]]
"""Called with a sentence saying what a call waits for; the context spans the wait (a spinner)."""

RETRY_STATUS = frozenset({408, 409, 429, 500, 502, 503, 504})
BACKOFF_S = 0.5
"""Pause before the second try, seconds; doubled for each further try, clipped to the budget."""


class LLMError(SDIError):
    """The model endpoint gave no usable reply (unreachable, refused, timed out, malformed).

    `reason` is a short phrase for notes ("HTTP 500 after 2 tries", "no reply within 2 s");
    `malformed` is True when the endpoint answered, but not with a chat completion.
    """

    def __init__(self, message: str, *, reason: str | None = None, malformed: bool = False) -> None:
        self.reason = reason or message
        self.malformed = malformed
        super().__init__(message)


class _Malformed(Exception):
    """The endpoint answered with something that is not a chat completion (internal)."""


class _Fault(Exception):
    """One try failed; `retry` says whether another try may help (internal)."""

    def __init__(
        self, reason: str, *, retry: bool, malformed: bool = False, schema_refused: bool = False
    ) -> None:
        self.reason = reason
        self.retry = retry
        self.malformed = malformed
        self.schema_refused = schema_refused
        super().__init__(reason)


class OpenAIChat:
    """A `ChatModel` for an OpenAI-compatible endpoint.

    `timeout` is the wall-clock budget of one `chat` call in seconds, all tries included;
    `max_retries` bounds the tries after the first (0 = no retry); `waiting` (optional) is
    entered around every wait for the endpoint, e.g. a spinner.
    """

    def __init__(
        self,
        *,
        model: str | None = None,
        base_url: str | None = None,
        api_key: str | None = None,
        timeout: float = 120.0,
        max_retries: int = 1,
        name: str = "openai",
        waiting: Waiting | None = None,
    ) -> None:
        import openai

        if not timeout > 0:
            raise ValueError(f"timeout must be > 0 s, got {timeout}")
        self.name = name
        self.model = model or os.environ.get("SDI_LLM_MODEL") or "gpt-4o-mini"
        self.usage = Usage()
        self.timeout = float(timeout)
        self.max_tries = 1 + max(0, int(max_retries))
        self._waiting = waiting
        self._schema_mode = "json_schema"
        self._client = openai.OpenAI(
            base_url=base_url
            or os.environ.get("SDI_LLM_BASE_URL")
            or os.environ.get("OPENAI_BASE_URL"),
            api_key=api_key or os.environ.get("OPENAI_API_KEY") or "not-needed",
            timeout=self.timeout,
            max_retries=0,  # retries are ours, inside one budget
        )
        self.base_url = str(self._client.base_url)

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
        end = time.monotonic() + self.timeout
        tries = 0
        last: _Fault | None = None
        while True:
            if tries == 0:
                deadline.check()  # no call is started after the phase's limit
            left = end - time.monotonic()
            phase_left = deadline.remaining()
            if phase_left is not None:  # never wait past the phase's wall-clock limit
                left = min(left, phase_left)
            if left <= 0 or tries >= self.max_tries:
                break
            if json_schema is not None:
                kwargs["response_format"] = self._format(json_schema)
            tries += 1
            try:
                body = self._attempt(kwargs, left, role, tries)
                reply = _reply_from(body)
            except _Malformed as exc:
                self.usage.malformed += 1
                last = _Fault(f"not a chat completion: {exc}", retry=True, malformed=True)
            except _Fault as exc:
                negotiable = json_schema is not None and self._schema_mode == "json_schema"
                if exc.schema_refused and negotiable:
                    self._schema_mode = "json_object"
                    tries -= 1  # a format negotiation, not a failed try
                    continue
                self.usage.malformed += int(exc.malformed)
                last = exc
            else:
                self.usage.add(reply, role)
                return reply
            if not last.retry or tries >= self.max_tries:
                break
            pause = BACKOFF_S * 2 ** (tries - 1)
            phase_left = deadline.remaining()
            if time.monotonic() + pause >= end or (phase_left is not None and pause >= phase_left):
                break
            time.sleep(pause)
        self.usage.failures += 1
        deadline.check()
        if last is None or last.reason == "timeout":
            reason = f"no reply within {self.timeout:g} s"
            if phase_left is not None and phase_left < self.timeout:
                reason = "no reply before the phase's time limit"
        else:
            reason = last.reason + (f" after {tries} tries" if tries > 1 else "")
        raise LLMError(
            f"{self.name} ({self.base_url}): {reason}",
            reason=reason,
            malformed=last is not None and last.malformed,
        )

    def _attempt(self, kwargs: dict[str, Any], left: float, role: str, k: int) -> bytes:
        """One HTTP request in a worker thread, abandoned after `left` seconds; the raw body."""
        box: dict[str, Any] = {}
        done = threading.Event()

        def run() -> None:
            try:
                raw = self._client.chat.completions.with_raw_response.create(
                    **kwargs, timeout=max(left, 0.01)
                )
                box["body"] = raw.http_response.content
                box["type"] = raw.http_response.headers.get("content-type", "")
            except BaseException as exc:  # handed to the caller's thread
                box["error"] = exc
            finally:
                done.set()

        worker = threading.Thread(target=run, name=f"sdi-llm-{role}", daemon=True)
        host = urlsplit(self.base_url).netloc or self.base_url
        tries = f"try {k}/{self.max_tries}"
        text = f"waiting for {self.model} at {host} ({role}, {tries}, ≤ {left:.0f} s)"
        with self._waiting(text) if self._waiting else nullcontext():
            worker.start()
            finished = done.wait(left)
        if not finished:
            raise _Fault("timeout", retry=False)
        if "error" in box:
            raise _classify(box["error"]) from None
        if "html" in str(box.get("type", "")).lower():
            raise _Malformed("an HTML page")
        return bytes(box["body"])


def _classify(exc: BaseException) -> _Fault:
    """An SDK exception as a try's fault: what to say and whether to try again."""
    import openai

    if isinstance(exc, openai.APITimeoutError):
        return _Fault("timeout", retry=False)
    if isinstance(exc, openai.APIConnectionError):
        return _Fault("cannot connect", retry=True)
    if isinstance(exc, openai.APIStatusError):
        code = exc.status_code
        # llama.cpp's server refuses the json_schema type (with a 400 or a 500)
        refused = "json_schema" in str(exc) or isinstance(exc, openai.BadRequestError)
        return _Fault(f"HTTP {code}", retry=code in RETRY_STATUS, schema_refused=refused)
    if isinstance(exc, (ValueError, RecursionError)):
        return _Fault(f"not a chat completion: {type(exc).__name__}", retry=True, malformed=True)
    return _Fault(f"{type(exc).__name__}: {exc}"[:200], retry=False)


def _reply_from(body: bytes) -> ChatReply:
    """A chat completion body as a reply; `_Malformed` says why it is not one."""
    head = body[:512].lstrip().lower()
    if head.startswith((b"<!doctype", b"<html")):
        raise _Malformed("an HTML page")
    try:
        data = json.loads(body)
    except RecursionError:
        raise _Malformed("JSON nested too deep") from None
    except ValueError:
        raise _Malformed("not JSON") from None
    if not isinstance(data, dict) or "choices" not in data:
        raise _Malformed("JSON without 'choices'")
    choices = data["choices"]
    if not isinstance(choices, list) or not choices:
        raise _Malformed("no choices")
    message = choices[0].get("message") if isinstance(choices[0], dict) else None
    if not isinstance(message, dict):
        raise _Malformed("a choice without a message")
    content = message.get("content")
    if isinstance(content, list):  # content parts, as some servers send: their text joined
        texts = [
            p["text"] for p in content if isinstance(p, dict) and isinstance(p.get("text"), str)
        ]
        content = "".join(texts) if texts else None
    if content is not None and not isinstance(content, str):
        raise _Malformed("message content that is not text")
    calls = []
    raw_calls = message.get("tool_calls") or []
    if not isinstance(raw_calls, list):
        raise _Malformed("tool_calls that is not a list")
    for k, call in enumerate(raw_calls):
        function = call.get("function") if isinstance(call, dict) else None
        if not isinstance(function, dict) or not isinstance(function.get("name"), str):
            continue
        arguments = function.get("arguments")
        if not isinstance(arguments, str):
            arguments = json.dumps(arguments) if arguments is not None else "{}"
        calls.append(ToolCall(str(call.get("id") or f"call_{k}"), function["name"], arguments))
    if content is None and not calls:
        raise _Malformed("a message with neither content nor tool calls")
    usage = data.get("usage")
    if not isinstance(usage, dict):
        usage = {}
    return ChatReply(
        content=content,
        tool_calls=tuple(calls),
        prompt_tokens=_count(usage.get("prompt_tokens")),
        completion_tokens=_count(usage.get("completion_tokens")),
    )


def _count(value: object) -> int:
    return value if isinstance(value, int) and not isinstance(value, bool) and value >= 0 else 0


def parse_json(text: str | None, *, limit: int = 200_000) -> Any:
    """The first JSON value in a model's text (fenced code blocks allowed); ValueError if none
    (also for JSON nested too deep to parse)."""
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
    try:
        value, _ = json.JSONDecoder().raw_decode(cleaned[start:])
    except RecursionError:
        raise ValueError("JSON nested too deep") from None
    return value
