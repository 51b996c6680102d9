"""The Inspector: symbolic verification V(C, K) and assembly sequencing (never an LLM)."""

from sdi.inspector.analysis import Analysis
from sdi.inspector.sequencer import sequence
from sdi.inspector.verifier import (
    Report,
    check_collision,
    check_contact,
    check_gripping_order,
    check_order,
    check_stability,
    check_support,
    check_workspace,
    verify,
)
from sdi.inspector.violation import Constraint, Violation

__all__ = [
    "Analysis",
    "Constraint",
    "Report",
    "Violation",
    "check_collision",
    "check_contact",
    "check_gripping_order",
    "check_order",
    "check_stability",
    "check_support",
    "check_workspace",
    "sequence",
    "verify",
]
