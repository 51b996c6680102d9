"""LLM access behind one protocol: OpenAI-compatible endpoints, a local llama.cpp server, and
the offline `rules` backend (no model: the grammar Specifier and parametric Designer)."""

from sdi.llm.backends import BACKENDS, open_backend
from sdi.llm.chat import ChatModel, ChatReply, Message, ToolCall, Usage
from sdi.llm.local_server import LocalModelUnavailable, LocalServer, find_model_file
from sdi.llm.openai_backend import LLMError, OpenAIChat, parse_json

__all__ = [
    "BACKENDS",
    "ChatModel",
    "ChatReply",
    "LLMError",
    "LocalModelUnavailable",
    "LocalServer",
    "Message",
    "OpenAIChat",
    "ToolCall",
    "Usage",
    "find_model_file",
    "open_backend",
    "parse_json",
]
