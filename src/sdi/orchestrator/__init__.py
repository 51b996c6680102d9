"""The orchestrator: LangGraph phases, human interrupts, recovery, durable state, event stream."""

from sdi.orchestrator.bus import Message, MessageBus
from sdi.orchestrator.edits import apply_edits
from sdi.orchestrator.graph import RoutingError, build_graph, mermaid
from sdi.orchestrator.lease import RunBusyError, RunLease
from sdi.orchestrator.methods import METHODS, Method
from sdi.orchestrator.runner import Orchestrator, RunInfo, RunStatus, default_db
from sdi.orchestrator.serde import PlainSerializer, UnsafeCheckpointError

__all__ = [
    "METHODS",
    "Message",
    "MessageBus",
    "Method",
    "Orchestrator",
    "PlainSerializer",
    "RoutingError",
    "RunBusyError",
    "RunInfo",
    "RunLease",
    "RunStatus",
    "UnsafeCheckpointError",
    "apply_edits",
    "build_graph",
    "default_db",
    "mermaid",
]
