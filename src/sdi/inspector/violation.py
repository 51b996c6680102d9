"""Violations are data: a constraint code, the parts involved, a message and a concrete hint.

The same object feeds the Designer's retry prompt, the digital twin's highlighting and the CLI.
"""

from __future__ import annotations

from enum import StrEnum

from pydantic import BaseModel, ConfigDict, Field

from sdi.jsonable import plain


class Constraint(StrEnum):
    """The constraint set K: the paper's six (§II) plus our stricter physical checks."""

    GRAVITY = "gravity"
    """C1: parts in contact, the lower one placed first (contact pairs that are not support)."""
    WORKSPACE = "workspace"
    """C2 reachability: every part's box inside the workspace cuboid W."""
    COLLISION = "collision"
    """C3: bounding boxes of distinct parts do not overlap (touching within ε is allowed)."""
    CONTACT = "contact"
    """C4: a part not on the table touches some other part."""
    GRIPPING = "gripping"
    """C5: when a part is placed, some tool can grip it around the parts already placed."""
    SEQUENCE = "sequence"
    """C6: supporting parts and stated predecessors come first."""
    SUPPORT = "support"
    """Stricter C4: a part off the table rests on a top face with positive footprint overlap."""
    STABILITY = "stability"
    """Beyond the paper: the layout and each state of its assembly stand (centre of mass over
    the support polygon, each part balanced when placed, static equilibrium by LP)."""


PAPER_CONSTRAINTS = (
    Constraint.GRAVITY,
    Constraint.WORKSPACE,
    Constraint.COLLISION,
    Constraint.CONTACT,
    Constraint.GRIPPING,
    Constraint.SEQUENCE,
)


class Violation(BaseModel):
    """One broken constraint. `hint` says where to move what; `suggestion` is the same as data."""

    model_config = ConfigDict(frozen=True)

    constraint: Constraint
    objects: tuple[str, ...]
    message: str
    hint: str
    suggestion: dict[str, object] | None = Field(
        default=None,
        description="machine-readable fix, e.g. {'id': 'c4', 'position': [x, y, z]} (metres)",
    )

    def to_json_dict(self) -> dict[str, object]:
        out: dict[str, object] = {
            "constraint": self.constraint.value,
            "objects": list(self.objects),
            "message": self.message,
            "hint": self.hint,
        }
        if self.suggestion is not None:
            out["suggestion"] = plain(self.suggestion)
        return out


def fmt(value: float) -> str:
    """Metres for messages: millimetre precision, no trailing zeros."""
    text = f"{value:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def fmt_point(point: tuple[float, ...] | list[float]) -> str:
    return "(" + ", ".join(fmt(v) for v in point) + ")"
