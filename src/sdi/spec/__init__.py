"""Command → structured specification (the Specifier ξ_spec)."""

from sdi.spec.grammar import parse_command
from sdi.spec.structure_spec import SHAPES, Spec, StructureSpec

__all__ = ["SHAPES", "Spec", "StructureSpec", "parse_command"]
