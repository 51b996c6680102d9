"""One layout seen through the cell: the shared, lazily built geometry every check reads."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from sdi.errors import InputError
from sdi.inspector.contacts import ContactGraph
from sdi.inspector.gripping import GripModel
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout

Precedence = tuple[tuple[str, str], ...]
"""Stated precedence pairs (before, after) by part id, e.g. from the spec or a human."""


def natural_key(text: str) -> tuple[object, ...]:
    """Sort key that orders ``c2`` before ``c10``."""
    return tuple(int(t) if t.isdigit() else t for t in re.split(r"(\d+)", text))


@dataclass(frozen=True)
class Analysis:
    layout: Layout
    cell: CellConfig = field(default_factory=CellConfig)
    precedence: Precedence = ()

    @cached_property
    def graph(self) -> ContactGraph:
        tol = self.cell.tolerances
        return ContactGraph(self.layout, tol.contact, tol.support_overlap)

    @cached_property
    def grip(self) -> GripModel:
        return GripModel(self.layout, self.cell.grippers, self.cell.tolerances.contact)

    @cached_property
    def precedence_edges(self) -> np.ndarray:
        index = self.layout.index
        rows = []
        for before, after in self.precedence:
            for name in (before, after):
                if name not in index:
                    raise InputError(f"unknown part id {name!r}", field="precedence")
            rows.append((index[before], index[after]))
        return np.array(rows, dtype=np.intp).reshape(-1, 2)

    @cached_property
    def preference(self) -> np.ndarray:
        """Assembly preference rank per part: lower bottom first, then x, y, then id."""
        layout = self.layout
        n = len(layout)
        c = np.round(layout.centres, 4)
        bottom = np.round(layout.centres[:, 2] - layout.half_extents[:, 2], 4)
        order = np.lexsort((c[:, 1], c[:, 0], bottom))
        key = np.stack([bottom[order], c[order, 0], c[order, 1]], axis=1)
        tied = np.nonzero(np.all(key[1:] == key[:-1], axis=1))[0]
        if tied.size:  # parts at the same place (only in colliding layouts): order by id
            order = np.array(
                sorted(
                    range(n),
                    key=lambda i: (bottom[i], c[i, 0], c[i, 1], natural_key(layout.objects[i].id)),
                ),
                dtype=np.intp,
            )
        rank = np.empty(n, dtype=np.intp)
        rank[order] = np.arange(n)
        return rank
