"""Deterministic geometric recovery skills: `flatten` (lower, spreading) and `shift` (move away).

Their output goes straight back to the Inspector; they never bypass verification.
"""

from sdi.recovery.flatten import flatten
from sdi.recovery.shift import shift

__all__ = ["flatten", "shift"]
