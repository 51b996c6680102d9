"""Spec → layout: the parametric structure families and the Designer that places them."""

from sdi.design.composer import compose, design
from sdi.design.shapes import FAMILIES

__all__ = ["FAMILIES", "compose", "design"]
