"""Backend names → chat models: `rules` (no model), `local` (llama.cpp on 127.0.0.1), `openai`."""

from __future__ import annotations

from contextlib import ExitStack

from sdi.errors import InputError
from sdi.llm.chat import ChatModel
from sdi.llm.local_server import LocalModelUnavailable, LocalServer
from sdi.llm.openai_backend import OpenAIChat

BACKENDS = ("rules", "local", "openai")


def open_backend(name: str, stack: ExitStack) -> ChatModel | None:
    """The chat model of backend `name` (None for `rules`); a local server it starts is
    stopped when `stack` closes. Unknown names and a missing local model are `InputError`s."""
    if name == "rules":
        return None
    if name == "openai":
        return OpenAIChat()
    if name == "local":
        try:
            return stack.enter_context(LocalServer()).chat_model()
        except LocalModelUnavailable as exc:
            raise InputError(str(exc), field="--backend") from None
    raise InputError(f"unknown backend {name!r}; use rules, local or openai", field="--backend")
