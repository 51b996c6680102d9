"""A recovery's outcome as data: which skill, what it changed (moved by, turned by, flattened
from → to), whether the *shape* changed, and the part-by-part diff from the failed layout.

The orchestrator puts it in the run's notes, its JSON (`recoveries`), the audit trail (a
`recovery` event) and, when the shape changed, in front of the operator for approval.
`recover` runs the skill REPLAN chose (shift, flatten, spread); `rule_replan` is the rule-based
baselines' replan (the paper's MultiAgent-RuleOrch): translate away from a workspace or
collision region, lower under a height limit, nothing else.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from pydantic import BaseModel, ConfigDict

from sdi.errors import InfeasibleError
from sdi.execute.record import layout_hash
from sdi.model.cell import CellConfig
from sdi.model.diff import PartChange, layout_diff
from sdi.model.layout import Layout
from sdi.model.region import Region
from sdi.recovery.flatten import flatten
from sdi.recovery.reshape import reshape
from sdi.recovery.shift import shift_search
from sdi.recovery.spread import spread
from sdi.spec.structure_spec import Spec


class RecoveryOutcome(BaseModel):
    """What a recovery did. Lengths in metres, angles in degrees."""

    model_config = ConfigDict(frozen=True)

    action: str  # shift | flatten | spread | rule-replan
    summary: str  # one line for people
    shape_changed: bool
    moved_by_m: tuple[float, float] | None = None
    turned_deg: float | None = None
    margin_m: float | None = None
    flattened_from: str | None = None
    flattened_to: str | None = None
    survival: float | None = None  # share of the command kept (reshape), 0…1
    gap_m: float | None = None  # the gap opened between neighbouring parts (spread)
    changes: tuple[PartChange, ...] = ()  # part by part, from the failed layout


def height_limit(blocked: tuple[Region, ...], layout: Layout, cell: CellConfig) -> float:
    """The lowest z_min of the blocked regions, else half the structure's height (in levels)."""
    limits = [r.z_min for r in blocked if r.z_min is not None]
    if limits:
        return min(limits)
    h = cell.cube[2]
    tops = layout.centres[:, 2] + layout.half_extents[:, 2]
    return max(1, math.ceil(round(float(tops.max()) / h) / 2)) * h


def recover(
    action: str,
    layout: Layout,
    cell: CellConfig,
    blocked: tuple[Region, ...],
    spec: Spec | None = None,
    *,
    arms: Sequence[str] | None = None,
) -> tuple[Layout, RecoveryOutcome]:
    """Run `shift`, `flatten` (reshape first) or `spread` on the failed layout;
    `InfeasibleError` if the skill cannot clear `blocked`, or if its result would be the failed
    layout unchanged. `arms` are the arms `spread` commissions for (default: the cell's).

    A shift that had to turn a structure off the axis its command named is a changed shape (the
    operator approves it); a plain move, or a turn of a structure without a named axis, is not."""
    if action == "shift":
        shifted = shift_search(layout, cell, blocked=blocked)
        result = shifted.layout
        axis = _turned_axis(spec, shifted.yaw_deg)
        summary = f"shift: {shifted.describe()}"
        if axis is not None:
            summary += f"; it now runs along {axis[1]}, not along {axis[0]} as commanded"
        outcome = RecoveryOutcome(
            action="shift", summary=summary, shape_changed=axis is not None,
            moved_by_m=(shifted.dx, shifted.dy), turned_deg=shifted.yaw_deg,
            margin_m=round(shifted.margin, 6),
        )  # fmt: skip
    elif action == "spread":
        spreaded = spread(layout, cell, blocked=blocked, arms=arms)
        result = spreaded.layout
        moved = spreaded.shifted
        outcome = RecoveryOutcome(
            action="spread", summary=f"spread: {spreaded.describe()}", shape_changed=True,
            moved_by_m=(moved.dx, moved.dy) if moved else None,
            turned_deg=moved.yaw_deg if moved else None,
            margin_m=round(moved.margin, 6) if moved else None, gap_m=spreaded.gap,
        )  # fmt: skip
    elif action == "flatten":
        shaped = reshape(spec, layout, cell, z_max=height_limit(blocked, layout, cell),
                         blocked=blocked)  # fmt: skip
        result = shaped.layout
        outcome = RecoveryOutcome(
            action="flatten", summary=f"flatten: {shaped.describe()}", shape_changed=True,
            flattened_from=shaped.before, flattened_to=shaped.after, survival=shaped.survival,
        )  # fmt: skip
    else:
        raise InfeasibleError(f"action: no recovery skill {action!r}", parameter="action")
    return _stated(layout, result, outcome)


def _turned_axis(spec: Spec | None, yaw_deg: float) -> tuple[str, str] | None:
    """(commanded axis, axis now) if a quarter turn by `yaw_deg` moved a structure off the axis
    its command named ("a row along the y axis"), else None: then the turn is a changed shape."""
    if spec is None or round(yaw_deg) % 180 == 0:
        return None
    for s in spec.structures:
        axis = getattr(s, "axis", None)
        if axis in ("x", "y"):
            return axis, "y" if axis == "x" else "x"
    return None


def rule_replan(
    layout: Layout, cell: CellConfig, blocked: tuple[Region, ...]
) -> tuple[Layout, RecoveryOutcome]:
    """The rule-based replan: under a height limit lower the structure (geometric flatten),
    then translate it (no turning) clear of the other regions."""
    if not blocked:
        raise InfeasibleError("blocked: no region is known to avoid", parameter="blocked")
    result = layout
    words = []
    sideways = ("x_min", "x_max", "y_min", "y_max")
    ceiling = [
        r for r in blocked
        if r.z_min is not None and r.normal is None and all(getattr(r, k) is None for k in sideways)
    ]  # fmt: skip
    if ceiling:
        z_max = min(r.z_min for r in ceiling if r.z_min is not None)
        lowered = flatten(result, cell, z_max=z_max)
        if layout_hash(lowered) != layout_hash(result):
            words.append(f"lowered under {z_max:g} m")
            result = lowered
    rest = tuple(r for r in blocked if r not in ceiling)
    moved: tuple[float, float] | None = None
    if rest:
        try:
            shifted = shift_search(result, cell, blocked=rest, yaws=(0.0,))
            result, moved = shifted.layout, (shifted.dx, shifted.dy)
            words.append(f"moved by ({shifted.dx:.3f}, {shifted.dy:.3f}) m")
        except InfeasibleError as exc:
            if exc.parameter != "layout":  # "already clear" is no failure here
                raise
    outcome = RecoveryOutcome(
        action="rule-replan", summary=f"rule-based replan: {', '.join(words) or 'no change'}",
        shape_changed=bool(ceiling) and "lowered" in " ".join(words), moved_by_m=moved,
    )  # fmt: skip
    return _stated(layout, result, outcome)


def _stated(
    before: Layout, after: Layout, outcome: RecoveryOutcome
) -> tuple[Layout, RecoveryOutcome]:
    if layout_hash(after) == layout_hash(before):
        raise InfeasibleError(
            f"layout: {outcome.action} would run the failed layout again unchanged; not tried",
            parameter="layout",
        )
    changes = tuple(layout_diff(before, after))
    return after, outcome.model_copy(update={"changes": changes})
