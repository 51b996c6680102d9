"""Pairwise geometry of a layout in near-linear time.

Candidate pairs come from a k-d tree over part centres (Chebyshev radius = the largest possible
reach of two boxes), so a layout of N parts costs O(N log N) plus the number of neighbours, not
N² pairs. Everything after that is vectorised over the candidate pairs.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.spatial import cKDTree

from sdi.model.layout import Layout


@dataclass(frozen=True)
class ContactGraph:
    """Contact, collision and support relations of one layout.

    Pairs are index arrays into ``layout.objects``. `gaps[k, d]` is the free distance between
    the boxes of pair k along axis d (negative = they overlap by that much).
    """

    layout: Layout
    eps: float
    support_overlap: float

    @cached_property
    def pairs(self) -> np.ndarray:
        """Candidate pairs (i < j) whose boxes could touch, shape (M, 2)."""
        n = len(self.layout)
        if n < 2:
            return np.zeros((0, 2), dtype=np.intp)
        reach = 2.0 * float(self.layout.half_extents.max()) + self.eps
        tree = cKDTree(self.layout.centres)
        pairs = tree.query_pairs(reach, p=np.inf, output_type="ndarray")
        return pairs.astype(np.intp, copy=False).reshape(-1, 2)

    @cached_property
    def gaps(self) -> np.ndarray:
        c, h = self.layout.centres, self.layout.half_extents
        i, j = self.pairs[:, 0], self.pairs[:, 1]
        return np.abs(c[i] - c[j]) - (h[i] + h[j])

    @cached_property
    def in_contact(self) -> np.ndarray:
        """The paper's contact predicate (eq. 5) per pair: boxes meet on all axes within ε."""
        return np.all(self.gaps <= self.eps, axis=1)

    @cached_property
    def colliding(self) -> np.ndarray:
        """Boxes overlap by more than ε on every axis."""
        return np.all(self.gaps < -self.eps, axis=1)

    @cached_property
    def on_table(self) -> np.ndarray:
        """Parts whose box bottom is at the table top z = 0 (within ε), shape (N,) bool."""
        bottoms = self.layout.centres[:, 2] - self.layout.half_extents[:, 2]
        return np.abs(bottoms) <= self.eps

    @cached_property
    def gravity_edges(self) -> np.ndarray:
        """Paper ≺ (eq. 5/C1): (lower, upper) for contact pairs with a strictly lower centre."""
        pairs = self.pairs[self.in_contact]
        z = self.layout.centres[:, 2]
        dz = z[pairs[:, 1]] - z[pairs[:, 0]]
        lower_first = pairs[dz > 1e-9]
        upper_first = pairs[dz < -1e-9][:, ::-1]
        return np.concatenate([lower_first, upper_first]).reshape(-1, 2)

    @cached_property
    def support(self) -> tuple[np.ndarray, np.ndarray]:
        """Strict support edges (lower, upper) and their contact patches.

        Support means the lower box's top face meets the upper box's bottom face within ε and
        their footprints overlap by at least `support_overlap` on both x and y. Patches are
        rectangles ``[x_lo, x_hi, y_lo, y_hi]`` in metres, shape (E, 4).
        """
        c, h = self.layout.centres, self.layout.half_extents
        edges = self.gravity_edges
        lo, up = edges[:, 0], edges[:, 1]
        face_gap = (c[up, 2] - h[up, 2]) - (c[lo, 2] + h[lo, 2])
        x_lo = np.maximum(c[lo, 0] - h[lo, 0], c[up, 0] - h[up, 0])
        x_hi = np.minimum(c[lo, 0] + h[lo, 0], c[up, 0] + h[up, 0])
        y_lo = np.maximum(c[lo, 1] - h[lo, 1], c[up, 1] - h[up, 1])
        y_hi = np.minimum(c[lo, 1] + h[lo, 1], c[up, 1] + h[up, 1])
        ok = (
            (np.abs(face_gap) <= self.eps)
            & (x_hi - x_lo >= self.support_overlap)
            & (y_hi - y_lo >= self.support_overlap)
        )
        patches = np.stack([x_lo, x_hi, y_lo, y_hi], axis=1)[ok]
        return edges[ok].reshape(-1, 2), patches.reshape(-1, 4)

    @property
    def support_edges(self) -> np.ndarray:
        return self.support[0]

    @property
    def support_patches(self) -> np.ndarray:
        return self.support[1]
