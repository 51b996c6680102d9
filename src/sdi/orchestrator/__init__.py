"""The orchestrator: LangGraph phases, human interrupts, recovery, durable state, message bus."""

from sdi.orchestrator.bus import MessageBus
from sdi.orchestrator.edits import apply_edits
from sdi.orchestrator.methods import METHODS, Method
from sdi.orchestrator.runner import Orchestrator, RunStatus, default_db

__all__ = [
    "METHODS",
    "MessageBus",
    "Method",
    "Orchestrator",
    "RunStatus",
    "apply_edits",
    "default_db",
]
