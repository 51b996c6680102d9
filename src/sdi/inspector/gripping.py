"""Gripping feasibility (paper C5) for the cell's tools.

Each tool gives a part one or more grip *options*: the vacuum gripper one (from the top), the
parallel gripper two (fingers closing along x or along y). An option is a set of keep-out boxes
that the tool sweeps when it comes down from above and grips: for the fingers, a slab beside each
side face from `grip_depth` below the top upwards; for a body, its footprint from just above the
top upwards. A part already in place that reaches into a keep-out box blocks that option; a part
is grippable when some option is unblocked and the tool fits it (opening, face size).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from sdi.inspector.box_index import overlapping
from sdi.model.cell import ParallelGripper, VacuumGripper
from sdi.model.layout import Layout

INF = np.inf


@dataclass(frozen=True)
class GripOption:
    """One way to grip: a tool and, for fingers, the closing axis β."""

    tool: str
    kind: str
    axis: str | None

    @property
    def label(self) -> str:
        return f"{self.tool} {self.kind}" + (
            f" along {self.axis}" if self.axis else " from the top"
        )


def _keep_out(
    layout: Layout, gripper: VacuumGripper | ParallelGripper, axis: int | None, eps: float
) -> tuple[np.ndarray, np.ndarray]:
    """Keep-out boxes (N, B, 6) as [x_lo, x_hi, y_lo, y_hi, z_lo, z_hi] and fit mask (N,)."""
    c, h = layout.centres, layout.half_extents
    n = len(layout)
    top = c[:, 2] + h[:, 2]
    if isinstance(gripper, VacuumGripper):
        face = np.stack(
            [c[:, 0] - h[:, 0] + eps, c[:, 0] + h[:, 0] - eps,
             c[:, 1] - h[:, 1] + eps, c[:, 1] + h[:, 1] - eps,
             top + eps, np.full(n, INF)], axis=1)  # fmt: skip
        bx, by = gripper.body_half_extents
        body = np.stack(
            [c[:, 0] - bx, c[:, 0] + bx, c[:, 1] - by, c[:, 1] + by,
             top + gripper.body_clearance, np.full(n, INF)], axis=1)  # fmt: skip
        fits = 2 * np.minimum(h[:, 0], h[:, 1]) >= gripper.min_face - 1e-9
        return np.stack([face, body], axis=1), fits
    assert axis is not None
    across = 1 - axis
    depth = np.minimum(gripper.grip_depth, h[:, 2])
    tip = top - depth
    reach = gripper.clearance + gripper.finger_thickness
    half_width = 0.5 * gripper.finger_width + gripper.clearance
    boxes = []
    for side in (-1.0, 1.0):
        face = c[:, axis] + side * h[:, axis]
        lo = np.minimum(face, face + side * reach)
        hi = np.maximum(face, face + side * reach)
        box = np.empty((n, 6))
        box[:, 2 * axis], box[:, 2 * axis + 1] = lo, hi
        box[:, 2 * across] = c[:, across] - half_width
        box[:, 2 * across + 1] = c[:, across] + half_width
        box[:, 4], box[:, 5] = tip, INF
        boxes.append(box)
    b_along, b_across = gripper.body_half_extents
    body = np.empty((n, 6))
    body[:, 2 * axis], body[:, 2 * axis + 1] = c[:, axis] - b_along, c[:, axis] + b_along
    body[:, 2 * across], body[:, 2 * across + 1] = c[:, across] - b_across, c[:, across] + b_across
    body[:, 4], body[:, 5] = tip + gripper.finger_length, INF
    boxes.append(body)
    fits = 2 * h[:, axis] + 2 * gripper.clearance <= gripper.max_opening + 1e-9
    return np.stack(boxes, axis=1), fits


@dataclass(frozen=True)
class GripModel:
    """Grip options of every part and which other parts block which option.

    `fits[i, o]`: the tool of option o can hold part i at all. `blocks` rows are
    ``(i, o, j)``, sorted: part j, when present, blocks option o of part i.
    """

    layout: Layout
    grippers: tuple[VacuumGripper | ParallelGripper, ...]
    eps: float

    @cached_property
    def _built(self) -> tuple[list[GripOption], np.ndarray, np.ndarray]:
        options: list[GripOption] = []
        boxes: list[np.ndarray] = []
        fits: list[np.ndarray] = []
        for gripper in self.grippers:
            axes: tuple[int | None, ...] = (None,) if isinstance(gripper, VacuumGripper) else (0, 1)
            for axis in axes:
                b, f = _keep_out(self.layout, gripper, axis, self.eps)
                options.append(
                    GripOption(gripper.name, gripper.kind, None if axis is None else "xy"[axis])
                )
                boxes.append(b)
                fits.append(f)
        n = len(self.layout)
        fit = np.stack(fits, axis=1) if fits else np.zeros((n, 0), dtype=bool)
        return options, fit, self._blocks(boxes)

    def _blocks(self, boxes: list[np.ndarray]) -> np.ndarray:
        """Rows (i, o, j), sorted, for every part j whose box reaches more than ε into a
        keep-out box of option o of part i (j ≠ i). A grid hash finds the overlaps, so the
        cost is near-linear in the parts and the rows, however dense the layout."""
        layout = self.layout
        n = len(layout)
        if n < 2 or not boxes:
            return np.zeros((0, 3), dtype=np.intp)
        c, h = layout.centres, layout.half_extents
        top = c[:, 2] + h[:, 2]
        # implied by the overlap in exact arithmetic; kept so rounding decides as it always has
        floor = np.min([b[:, :, 4].min(axis=1) for b in boxes], axis=0)
        n_opt = len(boxes)
        keys = []
        for o, b in enumerate(boxes):
            flat = b.reshape(-1, 6)
            q, j = overlapping(flat[:, 0::2], flat[:, 1::2], c - h, c + h, self.eps)
            i = q // b.shape[1]
            ok = (i != j) & (top[j] > floor[i] + self.eps)
            keys.append((i[ok].astype(np.int64) * n_opt + o) * n + j[ok])
        key = np.sort(np.concatenate(keys))  # one sorted row per (part, option, blocker)
        key = key[np.concatenate([key[:1] == key[:1], key[1:] != key[:-1]])]
        part_option, blocker = np.divmod(key, n)
        part, option = np.divmod(part_option, n_opt)
        return np.stack([part, option, blocker], axis=1).astype(np.intp)

    @cached_property
    def _by_part(self) -> np.ndarray:
        """`blocks[ptr[i]:ptr[i + 1]]` are the rows of part i (blocks are sorted by part)."""
        return np.searchsorted(self.blocks[:, 0], np.arange(len(self.layout) + 1))

    def rows_of(self, part: int) -> np.ndarray:
        """The `blocks` rows (part, o, j) of one part, in O(its rows)."""
        ptr = self._by_part
        return self.blocks[ptr[part] : ptr[part + 1]]

    @property
    def options(self) -> list[GripOption]:
        return self._built[0]

    @property
    def fits(self) -> np.ndarray:
        return self._built[1]

    @property
    def blocks(self) -> np.ndarray:
        return self._built[2]

    def grippable_given(self, rank: np.ndarray) -> np.ndarray:
        """Per part: some option fits and no part placed earlier (lower `rank`) blocks it."""
        blocked = np.zeros_like(self.fits)
        b = self.blocks
        earlier = rank[b[:, 2]] < rank[b[:, 0]]
        blocked[b[earlier, 0], b[earlier, 1]] = True
        return np.any(self.fits & ~blocked, axis=1)

    def blockers_given(self, part: int, rank: np.ndarray) -> list[int]:
        """Parts placed before `part` that block any of its fitting options."""
        b = self.rows_of(part)
        rows = b[(rank[b[:, 2]] < rank[part]) & self.fits[part, b[:, 1]]]
        return sorted(set(rows[:, 2].tolist()))
