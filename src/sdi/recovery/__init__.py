"""Deterministic geometric recovery skills: `shift` (move, or turn, away), `reshape` (the shape
that keeps most of the command under a height limit) and `flatten` (lower, spreading).

Their output goes straight back to the Inspector; they never bypass verification. Each states
what it changed (`Shifted.describe`, `Reshaped.describe`).
"""

from sdi.recovery.flatten import flatten
from sdi.recovery.reshape import Reshaped, reshape
from sdi.recovery.shift import Shifted, shift, shift_search

__all__ = ["Reshaped", "Shifted", "flatten", "reshape", "shift", "shift_search"]
