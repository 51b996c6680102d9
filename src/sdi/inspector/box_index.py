"""Which axis-aligned boxes overlap which, in time near-linear in the boxes and the answer.

A uniform grid hash over the *items* (the parts): every item is entered in each grid cell its
box touches, every query box (a gripper keep-out volume) looks up the cells it touches, and a
pair met in several cells is kept only in the cell holding the lower corner of the two boxes'
intersection, so each overlapping pair is produced once without a set. Boxes are hashed shrunk
by ε/2, so parts that merely touch (the usual case in a packed layout) share no cell. The cell
edge along each axis is the median item extent, so a part meets a bounded number of cells and
a cell holds a bounded number of parts unless parts overlap heavily. Query boxes may be
unbounded upwards (keep-out volumes reach to infinity); they are clipped to the items' bounding
box first, so a keep-out volume above every part costs nothing. All of it is numpy over
arrays, no Python loop per box.
"""

from __future__ import annotations

import numpy as np


def _expand(lo: np.ndarray, hi: np.ndarray, strides: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every cell of the integer ranges [lo, hi] (K, 3) as (owner index, cell key)."""
    span = hi - lo + 1
    count = span.prod(axis=1)
    base = lo @ strides
    if bool(np.all(count == 1)):
        return np.arange(len(lo)), base
    owner = np.repeat(np.arange(len(lo)), count)
    offset = np.arange(int(count.sum())) - np.repeat(np.cumsum(count) - count, count)
    dx, rest = np.divmod(offset, (span[:, 1] * span[:, 2])[owner])
    dy, dz = np.divmod(rest, span[owner, 2])
    return owner, base[owner] + dx * strides[0] + dy * strides[1] + dz


def overlapping(
    query_lo: np.ndarray,
    query_hi: np.ndarray,
    item_lo: np.ndarray,
    item_hi: np.ndarray,
    eps: float,
) -> tuple[np.ndarray, np.ndarray]:
    """All (query q, item k) whose boxes overlap by more than `eps` along every axis.

    Boxes are given by their lower and upper corners, shapes (Q, 3) and (K, 3), metres; query
    corners may be ±inf. Returns two index arrays of equal length, each pair once, in no
    particular order.
    """
    empty = (np.zeros(0, dtype=np.intp), np.zeros(0, dtype=np.intp))
    if len(query_lo) == 0 or len(item_lo) == 0:
        return empty
    origin = item_lo.min(axis=0)
    top = item_hi.max(axis=0)
    extent = np.median(item_hi - item_lo, axis=0)
    edge = np.where(extent > 0, extent, np.maximum(top - origin, 1.0))
    n_cells = np.floor((top - origin) / edge).astype(np.int64) + 1

    def cell(v: np.ndarray) -> np.ndarray:
        return np.clip(np.floor((v - origin) / edge), 0, n_cells - 1).astype(np.int64)

    strides = np.array([n_cells[1] * n_cells[2], n_cells[2], 1], dtype=np.int64)

    # Boxes overlap by more than ε iff, shrunk by ε/2 on every side, they overlap at all: hashed
    # shrunk, parts that only touch do not share cells.
    half = 0.5 * eps * (1.0 - 1e-6)  # a hair less, so rounding never loses a pair
    i_lo, i_hi = item_lo + half, item_hi - half
    q_lo = np.maximum(query_lo + half, origin)
    q_hi = np.minimum(query_hi - half, top)
    live = np.nonzero(np.all(q_hi > q_lo, axis=1))[0]  # clipped away: nothing to meet
    if live.size == 0:
        return empty

    i_cell_lo, i_cell_hi = cell(i_lo), cell(i_hi)
    item_owner, item_key = _expand(i_cell_lo, i_cell_hi, strides)
    order = np.argsort(item_key, kind="stable")
    item_key, item_owner = item_key[order], item_owner[order]

    q_owner, q_key = _expand(cell(q_lo[live]), cell(q_hi[live]), strides)
    q_owner = live[q_owner]
    start = np.searchsorted(item_key, q_key, side="left")
    stop = np.searchsorted(item_key, q_key, side="right")
    hits = stop - start
    q = np.repeat(q_owner, hits)
    slot = np.repeat(start - np.cumsum(hits) + hits, hits) + np.arange(int(hits.sum()))
    k = item_owner[slot]

    overlap = np.minimum(query_hi[q], item_hi[k]) - np.maximum(query_lo[q], item_lo[k])
    keep = np.all(overlap > eps, axis=1)
    spread = np.any(i_cell_hi != i_cell_lo, axis=1)  # items in several cells: met repeatedly
    if spread.any():
        at = np.repeat(q_key, hits)
        again = np.nonzero(keep & spread[k])[0]
        corner = np.maximum(q_lo[q[again]], i_lo[k[again]])  # of the (shrunk) intersection
        keep[again] = cell(corner) @ strides == at[again]
    return q[keep].astype(np.intp, copy=False), k[keep].astype(np.intp, copy=False)
