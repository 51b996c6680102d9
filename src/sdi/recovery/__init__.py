"""Deterministic geometric recovery skills: `shift` (move, or turn, away), `reshape` (the shape
that keeps most of the command under a height limit), `flatten` (lower, spreading) and `spread`
(open gaps between parts so a parallel gripper reaches each one).

Their output goes straight back to the Inspector; they never bypass verification. Each states
what it changed (`Shifted.describe`, `Reshaped.describe`).
"""

from sdi.recovery.flatten import flatten
from sdi.recovery.reshape import Reshaped, reshape
from sdi.recovery.shift import Shifted, shift, shift_search
from sdi.recovery.spread import Spread, spread

__all__ = ["Reshaped", "Shifted", "Spread", "flatten", "reshape", "shift", "shift_search", "spread"]
