"""Structure signatures written as data: ``[["tower", 3], ["parts", 3]]`` → an acceptance
predicate built from the suite's own building blocks (`sdi.bench.suite`).

A check is a list: its name, then its positional arguments. Only geometry-only checks are
offered (no position or region), so a signature says *what* was built, not *where*: a
recovery that moved the structure keeps its shape, one that flattened a tower does not.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from sdi.bench import signatures as sg
from sdi.bench import suite as su
from sdi.bench.suite import Accept

_SHAPES: dict[str, tuple[str, Callable[..., bool]]] = {
    "row": ("a row", sg.is_row),
    "l": ("an L", sg.is_l),
    "u": ("a U", sg.is_u),
    "table": ("legs under a top", sg.is_table),
    "castle": ("a castle", sg.is_castle),
    "staircase": ("a staircase", sg.is_staircase),
}

_BUILDERS: dict[str, Callable[..., Accept]] = {
    "parts": su.parts,
    "parts_in": su.parts_in,
    "levels": su.n_levels,
    "footprint": su.footprint,
    "axis": su.axis,
    "steps": su.steps,
    "tower": su.tower,
    "tower_heights": su.tower_heights,
    "single": su.single,
    "wall": su.wallish,
    "spans": su.spans,
    "feet": su.feet,
    "compact": su.compact,
    "hollow": su.hollow,
    "every_level_hollow": su.every_level_hollow,
    "pyramid": su.pyramid,
    "grid": su.grid,
    "block": su.block,
    "enclosure": su.enclosure,
}

NAMES: tuple[str, ...] = tuple(sorted([*_BUILDERS, *_SHAPES]))
"""Every check name a signature may use."""


def check(spec: Sequence[Any]) -> Accept:
    """One check from ``[name, *args]``; ValueError naming the check if it is not one."""
    if not spec or not isinstance(spec[0], str):
        raise ValueError(f"a check is [name, *args], got {list(spec)!r}")
    name, args = spec[0], list(spec[1:])
    if name in _SHAPES:
        label, test = _SHAPES[name]
        if args:
            raise ValueError(f"check {name!r} takes no arguments, got {args!r}")
        return su.shape(label, test)
    if name not in _BUILDERS:
        raise ValueError(f"unknown check {name!r}; choose from {list(NAMES)}")
    try:
        return _BUILDERS[name](*args)
    except (TypeError, KeyError) as exc:
        raise ValueError(f"check {name!r} with {args!r}: {exc}") from None


def signature(specs: Sequence[Sequence[Any]]) -> Accept:
    """All checks of a signature (the first failing one's reason is reported)."""
    if not specs:
        raise ValueError("a signature needs at least one check")
    return su.all_of(*(check(s) for s in specs))
