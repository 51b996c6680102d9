"""Backend names → chat models: `rules` (no model), `local` (llama.cpp on 127.0.0.1), `openai`."""

from __future__ import annotations

from contextlib import ExitStack

from sdi.errors import InputError
from sdi.llm.chat import ChatModel
from sdi.llm.local_server import LocalModelUnavailable, LocalServer
from sdi.llm.openai_backend import OpenAIChat, Waiting

BACKENDS = ("rules", "local", "openai")
DEFAULT_TIMEOUT_S = 120.0
"""Wall-clock budget of one model call, all retries included, seconds."""


def open_backend(
    name: str, stack: ExitStack, *, timeout: float | None = None, waiting: Waiting | None = None
) -> ChatModel | None:
    """The chat model of backend `name` (None for `rules`); a local server it starts is
    stopped when `stack` closes. `timeout` is one call's budget in seconds, retries included
    (default 120 s); `waiting` is entered around every wait for the model (a spinner). Unknown
    names, a missing local model and a timeout ≤ 0 are `InputError`s."""
    if timeout is not None and not timeout > 0:
        raise InputError(f"must be > 0 seconds, got {timeout:g}", field="--llm-timeout")
    budget = DEFAULT_TIMEOUT_S if timeout is None else timeout
    if name == "rules":
        return None
    if name == "openai":
        return OpenAIChat(timeout=budget, waiting=waiting)
    if name == "local":
        try:
            server = stack.enter_context(LocalServer())
        except LocalModelUnavailable as exc:
            raise InputError(str(exc), field="--backend") from None
        return server.chat_model(timeout=budget, waiting=waiting)
    raise InputError(f"unknown backend {name!r}; use rules, local or openai", field="--backend")
