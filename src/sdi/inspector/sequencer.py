"""Symbolic assembly sequencing (paper Alg. 4).

Build the precedence DAG (the paper's ≺: contact and a lower centre, plus stated precedence),
then disassemble: repeatedly remove a sink — a part nothing remaining depends on — that some
tool can grip with every other remaining part still present; reverse the removals. Removing a
part only frees space, so a part that becomes removable stays removable and the greedy choice
never blocks a later one: if no removable part is left, no valid order exists. Ties go to the
part assembled last by preference (highest bottom, then x, y, id), so the reversed order builds
bottom-up. O((N + E + B) log N) for E precedence edges and B grip-blocking relations.
"""

from __future__ import annotations

import heapq
from dataclasses import dataclass

import numpy as np

from sdi.errors import SequencingError
from sdi.inspector.analysis import Analysis


@dataclass(frozen=True)
class Stuck:
    """Why disassembly stopped: parts no order can place, with what stands in their way."""

    ungrippable: dict[int, list[int]]
    """sink part → remaining parts blocking every tool option (empty: no tool fits it)."""
    waiting: list[int]
    """remaining parts that wait on others (a precedence cycle when there are no sinks)."""


def disassemble(analysis: Analysis) -> tuple[list[int], Stuck | None]:
    """Assembly order as indices, or the partial order and why it is stuck."""
    n = len(analysis.layout)
    edges = np.concatenate([analysis.graph.gravity_edges, analysis.precedence_edges])
    grip = analysis.grip
    fits, blocks = grip.fits, grip.blocks
    n_opt = fits.shape[1]

    out_degree = np.bincount(edges[:, 0], minlength=n).tolist()
    by_upper = edges[np.argsort(edges[:, 1], kind="stable")]
    pred_ptr = np.searchsorted(by_upper[:, 1], np.arange(n + 1)).tolist()
    preds = by_upper[:, 0].tolist()

    fitting = blocks[fits[blocks[:, 0], blocks[:, 1]]]  # sorted by part, like `blocks`
    count = np.zeros((n, n_opt), dtype=np.int64)
    np.add.at(count, (fitting[:, 0], fitting[:, 1]), 1)
    count[~fits] = -1  # an option whose tool does not fit never opens
    by_blocker = fitting[np.argsort(fitting[:, 2], kind="stable")]
    blk_ptr = np.searchsorted(by_blocker[:, 2], np.arange(n + 1)).tolist()
    blk_part = by_blocker[:, 0].tolist()
    blk_opt = by_blocker[:, 1].tolist()
    open_opts = (count == 0).sum(axis=1).tolist()
    count_l = count.tolist()

    rank = analysis.preference.tolist()
    removed = [False] * n
    heap = [-rank[i] for i in range(n) if out_degree[i] == 0 and open_opts[i] > 0]
    heapq.heapify(heap)
    by_rank = [0] * n
    for i, r in enumerate(rank):
        by_rank[r] = i
    queued = [False] * n
    for r in heap:
        queued[by_rank[-r]] = True
    removal: list[int] = []
    while heap:
        i = by_rank[-heapq.heappop(heap)]
        removed[i] = True
        removal.append(i)
        touched: list[int] = []
        for k in range(pred_ptr[i], pred_ptr[i + 1]):
            p = preds[k]
            out_degree[p] -= 1
            touched.append(p)
        for k in range(blk_ptr[i], blk_ptr[i + 1]):
            p, o = blk_part[k], blk_opt[k]
            count_l[p][o] -= 1
            if count_l[p][o] == 0:
                open_opts[p] += 1
                touched.append(p)
        for p in touched:
            if not queued[p] and not removed[p] and out_degree[p] == 0 and open_opts[p] > 0:
                queued[p] = True
                heapq.heappush(heap, -rank[p])
    order = removal[::-1]
    if len(order) == n:
        return order, None
    part_ptr = np.searchsorted(fitting[:, 0], np.arange(n + 1)).tolist()
    fitting_blocker = fitting[:, 2].tolist()
    ungrippable: dict[int, list[int]] = {}
    waiting: list[int] = []
    for i in range(n):
        if removed[i]:
            continue
        if out_degree[i] == 0:
            blockers = fitting_blocker[part_ptr[i] : part_ptr[i + 1]]
            ungrippable[i] = sorted({j for j in blockers if not removed[j]})
        else:
            waiting.append(i)
    return order, Stuck(ungrippable, waiting)


def sequence(analysis: Analysis) -> list[str]:
    """The assembly order σ* as part ids; `SequencingError` names the blocked parts."""
    order, stuck = disassemble(analysis)
    ids = analysis.layout.ids
    if stuck is None:
        return [ids[i] for i in order]
    if stuck.ungrippable:
        names = [ids[i] for i in sorted(stuck.ungrippable)]
        raise SequencingError(
            f"no assembly order: no tool can grip {', '.join(names[:8])}"
            + (f" (+{len(names) - 8} more)" if len(names) > 8 else "")
            + " with the parts around it in place",
            blocked=names,
        )
    names = [ids[i] for i in stuck.waiting]
    raise SequencingError(
        f"no assembly order: the stated precedence has a cycle through {', '.join(names[:8])}",
        blocked=names,
    )
