"""The verifier V(C, K): every constraint as its own check, and the composite `verify`.

Each check takes an `Analysis` (a layout seen through the cell) and returns violations with a
message and a concrete hint. Checks that need an order (gravity, sequence, gripping) use the
given sequence, or the sequencer's order when none is given. A report keeps every violation;
its JSON lists at most `MAX_PER_CONSTRAINT` of each constraint and sums up the rest in one
violation, so a layout where every one of 10 000 parts breaks a rule still gets a short answer.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
from pydantic import BaseModel, ConfigDict
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

from sdi.errors import InputError
from sdi.inspector.analysis import Analysis, Precedence
from sdi.inspector.equilibrium import alone, robust, solve, solve_many, upward_closure
from sdi.inspector.sequencer import disassemble
from sdi.inspector.stability import find_toppling
from sdi.inspector.violation import Constraint, Violation, fmt, fmt_point
from sdi.model.cell import CellConfig
from sdi.model.layout import Layout

AXES = "xyz"
MAX_PER_CONSTRAINT = 50
"""Violations listed per constraint in JSON; the rest are counted in one summary violation."""


def _names(ids: Sequence[str], limit: int = 5) -> str:
    shown = ", ".join(ids[:limit])
    return shown + (f" (+{len(ids) - limit} more)" if len(ids) > limit else "")


def check_workspace(a: Analysis) -> list[Violation]:
    """C2: every part's box lies inside the workspace cuboid W (within ε)."""
    ws, eps = a.cell.workspace, a.cell.tolerances.contact
    c, h = a.layout.centres, a.layout.half_extents
    lo, hi = np.array(ws.lower), np.array(ws.upper)
    bad = np.nonzero(np.any((c - h < lo - eps) | (c + h > hi + eps), axis=1))[0]
    out = []
    for i in bad.tolist():
        part = a.layout.objects[i]
        target = np.clip(c[i], lo + h[i], hi - h[i])
        broken = [
            f"{AXES[d]} ∈ [{fmt(c[i, d] - h[i, d])}, {fmt(c[i, d] + h[i, d])}] "
            f"(workspace {fmt(lo[d])}…{fmt(hi[d])})"
            for d in range(3)
            if c[i, d] - h[i, d] < lo[d] - eps or c[i, d] + h[i, d] > hi[d] + eps
        ]
        too_big = [AXES[d] for d in range(3) if 2 * h[i, d] > hi[d] - lo[d]]
        moves = [f"{AXES[d]}={fmt(target[d])}" for d in range(3) if abs(target[d] - c[i, d]) > 1e-9]
        hint = (
            f"{part.id} is larger than the workspace along {', '.join(too_big)}; use a smaller part"
            if too_big
            else f"move {part.id} to {', '.join(moves)}"
        )
        out.append(
            Violation(
                constraint=Constraint.WORKSPACE,
                objects=(part.id,),
                message=f"{part.id} leaves the workspace: box {'; '.join(broken)}",
                hint=hint,
                suggestion=None
                if too_big
                else {"id": part.id, "position": [round(v, 6) for v in target]},
            )
        )
    return out


def check_collision(a: Analysis) -> list[Violation]:
    """C3: no two boxes overlap by more than ε."""
    g = a.graph
    pairs, gaps = g.pairs[g.colliding], g.gaps[g.colliding]
    c, ids = a.layout.centres, a.layout.ids
    out = []
    for (i, j), gap in zip(pairs.tolist(), gaps, strict=True):
        depth = -gap
        # Separate along the axis of least penetration; prefer lifting on ties (stacking).
        d = min((2, 0, 1), key=lambda k: (round(float(depth[k]), 9), k != 2))
        mover, other = (j, i) if (c[j, 2], j) >= (c[i, 2], i) else (i, j)
        sign = 1.0 if c[mover, d] >= c[other, d] else -1.0
        target = c[mover].copy()
        target[d] += sign * float(depth[d])
        out.append(
            Violation(
                constraint=Constraint.COLLISION,
                objects=(ids[i], ids[j]),
                message=f"{ids[i]} overlaps {ids[j]} by {fmt(float(depth[d]))} m along {AXES[d]}",
                hint=f"move {ids[mover]} to {AXES[d]}={fmt(target[d])}",
                suggestion={"id": ids[mover], "position": [round(float(v), 6) for v in target]},
            )
        )
    return out


def check_contact(a: Analysis) -> list[Violation]:
    """C4 (paper): a part not resting on the table is in contact with some other part."""
    g = a.graph
    n = len(a.layout)
    touching = np.bincount(g.pairs[g.in_contact].ravel(), minlength=n) > 0
    out = []
    for i in np.nonzero(~g.on_table & ~touching)[0].tolist():
        part = a.layout.objects[i]
        if part.bottom < 0:  # below the table top, not above it: nothing to add underneath
            x, y, z = part.position
            rest = (x, y, z - part.bottom)
            out.append(
                Violation(
                    constraint=Constraint.CONTACT,
                    objects=(part.id,),
                    message=f"{part.id} is sunk {fmt(-part.bottom)} m into the table (its bottom "
                    f"is at z = {fmt(part.bottom)} m) and it touches no other part",
                    hint=f"raise {part.id} to z={fmt(rest[2])} so it rests on the table",
                    suggestion={"id": part.id, "position": [round(v, 6) for v in rest]},
                )
            )
            continue
        below = (part.position[0], part.position[1], part.bottom - a.cell.cube[2] / 2)
        out.append(
            Violation(
                constraint=Constraint.CONTACT,
                objects=(part.id,),
                message=f"{part.id} floats: its bottom is {fmt(part.bottom)} m above the table "
                "and it touches no other part",
                hint=f"lower {part.id} onto the part or table below it, or add a part at "
                f"{fmt_point(below)}",
                suggestion={"add_part_at": [round(v, 6) for v in below]},
            )
        )
    return out


def check_support(a: Analysis) -> list[Violation]:
    """Stricter C4: a part off the table rests on a top face with footprint overlap.

    Parts that touch nothing at all are left to `check_contact`.
    """
    g = a.graph
    n = len(a.layout)
    c, h, ids = a.layout.centres, a.layout.half_extents, a.layout.ids
    supported = np.zeros(n, dtype=bool)
    supported[g.support_edges[:, 1]] = True
    contact_pairs = g.pairs[g.in_contact]
    touching = np.bincount(contact_pairs.ravel(), minlength=n) > 0
    out = []
    for i in np.nonzero(~g.on_table & ~supported & touching)[0].tolist():
        neighbours = contact_pairs[(contact_pairs == i).any(axis=1)].ravel()
        neighbours = [k for k in neighbours.tolist() if k != i]
        lower = [k for k in neighbours if c[k, 2] + h[k, 2] <= c[i, 2] - h[i, 2] + 0.5 * h[i, 2]]
        lower.sort(key=lambda k: float(np.hypot(*(c[k, :2] - c[i, :2]))))
        pid = ids[i]
        # Move it onto a lower neighbour whose top is free; else add a part under it.
        onto = [(k, np.array([c[k, 0], c[k, 1], c[k, 2] + h[k, 2] + h[i, 2]])) for k in lower]
        spot = next(((k, t) for k, t in onto if _free(a, t, h[i], skip=i)), None)
        below = np.array([c[i, 0], c[i, 1], c[i, 2] - h[i, 2] - a.cell.cube[2] / 2])
        suggestion: dict[str, object] | None
        if spot is not None:
            k, target = spot
            hint = f"move {pid} onto {ids[k]} at {fmt_point(tuple(target))}"
            suggestion = {"id": pid, "position": [round(float(v), 6) for v in target]}
        elif below[2] > 0 and _free(a, below, np.array(a.cell.cube) / 2, skip=i):
            hint = f"add a part under {pid} at {fmt_point(tuple(below))}"
            suggestion = {"add_part_at": [round(float(v), 6) for v in below]}
        else:
            hint = f"remove {pid} or place it on a free top face"
            suggestion = None
        out.append(
            Violation(
                constraint=Constraint.SUPPORT,
                objects=(pid, *[ids[k] for k in neighbours[:4]]),
                message=f"{pid} is off the table but rests on no top face: it touches "
                f"{_names([ids[k] for k in neighbours])} only at a side or an edge",
                hint=hint,
                suggestion=suggestion,
            )
        )
    return out


def _free(a: Analysis, centre: np.ndarray, half: np.ndarray, *, skip: int) -> bool:
    """No part except `skip` overlaps the box (centre, half extents) by more than ε."""
    eps = a.cell.tolerances.contact
    gap = np.abs(a.layout.centres - centre) - (a.layout.half_extents + half)
    hit = np.all(gap < -eps, axis=1)
    hit[skip] = False
    return not bool(hit.any())


def check_stability(a: Analysis) -> list[Violation]:
    """Beyond the paper: the layout stands.

    Three tests, each part reported once: every sub-structure's centre of mass is over its
    support polygon (with a fix that moves it there); every part stands on its own supports
    when it is placed (nothing rests on it yet); and static equilibrium of the whole layout by
    LP (`equilibrium.solve`): contacts only push, so parts on top cannot hold up the part
    they rest on."""
    ids = a.layout.ids
    margin = a.cell.tolerances.stability_margin
    out = []
    covered: set[int] = set()
    for t in find_toppling(a.graph, margin):
        covered.update(t.parts)
        names = [ids[i] for i in t.parts]
        movers = [ids[i] for i in t.movers]
        suggestion: dict[str, object] | None = None
        if any(t.towards):
            hint = (
                f"move {_names(movers, 3)} by {fmt_point(t.towards)} m, or add a support under "
                f"{fmt_point(t.com)}"
            )
            suggestion = {"ids": movers, "translate": [round(v, 6) for v in t.towards]}
        else:
            hint = f"add a support under {fmt_point(t.com)} or shorten the overhang"
        out.append(
            Violation(
                constraint=Constraint.STABILITY,
                objects=tuple(names),
                message=f"the {len(names)}-part sub-structure {_names(names)} above "
                f"z={fmt(t.plane_z)} has its centre of mass at {fmt_point(t.com)}, "
                f"{fmt(t.outside_by)} m outside its support polygon",
                hint=hint,
                suggestion=suggestion,
            )
        )
    lonely = [i for i in alone(a.graph, margin).tolist() if i not in covered]
    for i in lonely:
        out.append(_unbalanced(a, i, placed=True))
    covered.update(lonely)
    # The LP only when the cheaper tests found nothing (the layout is refused anyway), and
    # only over the parts that could tip: those not `robust` and everything resting on them.
    # A robust part balances any load on its top, so the rest needs no forces solved.
    weak = np.nonzero(~robust(a.graph))[0]
    if not out and weak.size:
        members = upward_closure(a.graph, weak)
        for i in solve(a.graph, margin, members=members, friction=STABILITY_FRICTION).unbalanced:
            if i not in covered:
                out.append(_unbalanced(a, i, placed=False))
    return out


STABILITY_FRICTION = 0.0
"""Friction coefficient the equilibrium LP may rely on. Zero: loads are gravity only and
contacts horizontal, so a layout that stands needs no friction, and friction in a rigid-body
LP also admits self-stressed force states a real (or simulated) stack does not reach."""

PREFIX_LP_BUDGET = 20_000
"""Intermediate assembly states are solved (in one LP) until their groups hold this many
parts in all; later states of a layout that needs more go unchecked."""


def _supports_of(a: Analysis, i: int) -> list[int]:
    edges = a.graph.support_edges
    return edges[edges[:, 1] == i, 0].tolist()


def _support_spot(a: Analysis, i: int) -> np.ndarray:
    """Where a part under `i` would hold it: the cube-sized cell of its footprint farthest
    from its present supports, one cube below its bottom."""
    c, h = a.layout.centres, a.layout.half_extents
    cube = np.array(a.cell.cube) / 2
    patches = a.graph.support_patches[a.graph.support_edges[:, 1] == i]
    anchor = np.array([patches[:, :2].mean(), patches[:, 2:].mean()]) if len(patches) else c[i, :2]
    reach = np.maximum(h[i, :2] - cube[:2], 0.0)
    best = c[i, :2]
    for sx in (-1.0, 0.0, 1.0):
        for sy in (-1.0, 0.0, 1.0):
            p = c[i, :2] + np.array([sx, sy]) * reach
            if np.linalg.norm(p - anchor) > np.linalg.norm(best - anchor) + 1e-9:
                best = p
    return np.array([best[0], best[1], c[i, 2] - h[i, 2] - cube[2]])


def _unbalanced(
    a: Analysis, i: int, *, placed: bool, when: str = "", first: Sequence[str] = ()
) -> Violation:
    """Part `i` cannot be held still: alone on its supports (`placed`), or under its load."""
    ids = a.layout.ids
    pid = ids[i]
    supports = [ids[k] for k in _supports_of(a, i)]
    on = _names(supports) if supports else "the table"
    edges = a.graph.support_edges
    above = [ids[k] for k in edges[edges[:, 0] == i, 1].tolist()]
    com = (float(a.layout.centres[i, 0]), float(a.layout.centres[i, 1]))
    if placed:
        message = (
            f"{pid} cannot stand on {on}: its centre of mass {fmt_point(com)} is not over "
            f"its support ({fmt(a.cell.tolerances.stability_margin)} m margin)"
        )
        if above:
            message += f"; {_names(above)} on top of it press it down but cannot hold it up"
    else:
        message = (
            f"no contact forces hold {pid} still{when}: resting on {on}, it cannot carry "
            f"{'the parts on it (' + _names(above) + ')' if above else 'its own weight'} "
            "without tipping"
        )
    spot = _support_spot(a, i)
    suggestion: dict[str, object] | None = None
    if spot[2] > 0 and _free(a, spot, np.array(a.cell.cube) / 2, skip=i):
        hint = f"add a part under {pid} at {fmt_point(tuple(spot))}, or shorten the overhang"
        suggestion = {"add_part_at": [round(float(v), 6) for v in spot]}
    else:
        hint = f"move {pid} back over {on}, or shorten the overhang"
    if first:  # an intermediate state: a part put on later holds it
        hint = (
            f"place {_names(list(first), 3)} earlier (before {when.split('placing ')[-1][:-1]}); "
            + hint
        )
    objects = (pid, *[s for s in supports if s != pid][:4])
    return Violation(
        constraint=Constraint.STABILITY,
        objects=objects,
        message=message,
        hint=hint,
        suggestion=suggestion,
    )


def check_assembly_states(a: Analysis, sequence: Sequence[str]) -> list[Violation]:
    """Stability of the intermediate states: after each step, the parts placed so far stand
    (see `_falling_state`)."""
    fall = _falling_state(a, sequence)
    if fall is None:
        return []
    step, i, tipping, later = fall
    ids = a.layout.ids
    when = f" after step {step} (placing {ids[i]})"
    first = [ids[k] for k in later]
    return [_unbalanced(a, k, placed=False, when=when, first=first) for k in tipping]


MAX_REORDERS = 8
"""Counterweights moved earlier, at most this many times, when the Inspector picks the order."""


def stable_order(a: Analysis, sequence: Sequence[str]) -> list[str] | None:
    """`sequence` with counterweights moved earlier until every assembly state stands, or None.

    When a state falls, the parts that rest on the tipping part and come later (its
    counterweights) move to just before the part whose placement tipped it; the new order must
    still satisfy gravity, sequence and gripping."""
    order = list(sequence)
    ids = a.layout.ids
    for _ in range(MAX_REORDERS):
        fall = _falling_state(a, order)
        if fall is None:
            return order
        _, i, _, later = fall
        if not later:
            return None
        moved = [ids[k] for k in later]
        rest = [p for p in order if p not in set(moved)]
        at = rest.index(ids[i])
        order = rest[:at] + moved + rest[at:]
        if check_order(a, order) or check_gripping_order(a, order):
            return None
    return None


def _falling_state(
    a: Analysis, sequence: Sequence[str]
) -> tuple[int, int, list[int], list[int]] | None:
    """The first assembly state that falls: (step, the part placed then, the parts that tip,
    the parts resting on those that come later), or None.

    A part that could tip only carries its own weight and what rests on it; a state can fall
    only when some placed part is not `robust` (its supports do not span its footprint) and
    a later part was its counterweight. Only the steps that load such a part are solved, each
    over the group the new part joins, all in one block-diagonal LP, up to `PREFIX_LP_BUDGET`
    parts in all (the first states along the sequence; later ones go unchecked)."""
    margin = a.cell.tolerances.stability_margin
    index = a.layout.index
    order = [index[pid] for pid in sequence]
    weak = ~robust(a.graph)
    if not weak.any():
        return None
    closure = upward_closure(a.graph, np.nonzero(weak)[0])
    edges = a.graph.support_edges
    n = len(a.layout)
    # Only the new part's group can change: the weak parts and what rests on them, joined by
    # support edges (parts outside the group hold it as fixed ground).
    inside = np.zeros(n, dtype=bool)
    inside[closure] = True
    e = edges[inside[edges[:, 0]] & inside[edges[:, 1]]]
    joined = coo_matrix((np.ones(len(e)), (e[:, 0], e[:, 1])), shape=(n, n))
    _, label = connected_components(joined, directed=False)
    ptr_sorted = edges[np.argsort(edges[:, 1], kind="stable")]
    ptr = np.searchsorted(ptr_sorted[:, 1], np.arange(n + 1))
    risky = np.zeros(n, dtype=bool)  # rests, at some depth, on a weak part
    placed = np.zeros(n, dtype=bool)
    states: list[tuple[int, int, np.ndarray]] = []  # (step, new part, the group to solve)
    budget = PREFIX_LP_BUDGET
    for step, i in enumerate(order[:-1], start=1):
        below = ptr_sorted[ptr[i] : ptr[i + 1], 0]
        risky[i] = bool(np.any(weak[below] | risky[below]))
        placed[i] = True
        if risky[i]:
            group = np.nonzero(placed & (label == label[i]))[0]
            budget -= group.size
            if budget < 0:
                break
            states.append((step, i, group))
    if not states:
        return None
    answers = solve_many(a.graph, margin, [g for _, _, g in states], friction=STABILITY_FRICTION)
    for (step, i, _), eq in zip(states, answers, strict=True):
        if not eq.stands:
            rank = _rank(a, sequence)
            tipping = [k for k in eq.unbalanced if weak[k]] or eq.unbalanced
            on_them = edges[np.isin(edges[:, 0], tipping), 1]
            later = sorted({k for k in on_them.tolist() if rank[k] >= step}, key=lambda k: rank[k])
            return step, i, tipping, later
    return None


def _rank(a: Analysis, sequence: Sequence[str]) -> np.ndarray:
    index = a.layout.index
    rank = np.empty(len(a.layout), dtype=np.intp)
    for k, pid in enumerate(sequence):
        rank[index[pid]] = k
    return rank


def check_order(a: Analysis, sequence: Sequence[str]) -> list[Violation]:
    """C1 gravity and C6 sequence for a given order.

    A support edge placed in the wrong order is a `sequence` violation, so is a stated
    precedence; other contact pairs with the lower part placed later are `gravity` violations.
    """
    rank = _rank(a, sequence)
    ids = a.layout.ids
    support = {tuple(e) for e in a.graph.support_edges.tolist()}
    out = []

    def hint(lo: int, up: int) -> str:
        return (
            f"place {ids[lo]} before {ids[up]} (now step {rank[lo] + 1} after step {rank[up] + 1})"
        )

    for lo, up in a.graph.gravity_edges.tolist():
        if rank[lo] < rank[up]:
            continue
        if (lo, up) in support:
            code, message = Constraint.SEQUENCE, f"{ids[up]} rests on {ids[lo]} but is placed first"
        else:
            code = Constraint.GRAVITY
            message = f"{ids[lo]} touches {ids[up]} lower down but is placed after it"
        out.append(
            Violation(
                constraint=code, objects=(ids[lo], ids[up]), message=message, hint=hint(lo, up)
            )
        )
    for lo, up in a.precedence_edges.tolist():
        if rank[lo] > rank[up]:
            message = f"the stated precedence puts {ids[lo]} before {ids[up]}"
            out.append(
                Violation(
                    constraint=Constraint.SEQUENCE,
                    objects=(ids[lo], ids[up]),
                    message=message,
                    hint=hint(lo, up),
                )
            )
    return out


def check_gripping_order(a: Analysis, sequence: Sequence[str]) -> list[Violation]:
    """C5 for a given order: each part is grippable around the parts placed before it."""
    rank = _rank(a, sequence)
    ok = a.grip.grippable_given(rank)
    ids = a.layout.ids
    out = []
    for i in np.nonzero(~ok)[0].tolist():
        blockers = [ids[j] for j in a.grip.blockers_given(i, rank)]
        out.append(_grip_violation(a, i, blockers, placed=True))
    return out


def _grip_violation(a: Analysis, i: int, blockers: list[str], *, placed: bool) -> Violation:
    pid = a.layout.ids[i]
    if not a.grip.fits[i].any():
        tools = ", ".join(o.label for o in a.grip.options)
        return Violation(
            constraint=Constraint.GRIPPING,
            objects=(pid,),
            message=f"no gripper fits {pid} (size {fmt_point(a.layout.objects[i].size)} m; "
            f"options: {tools})",
            hint=f"use a part size the grippers can hold, e.g. {fmt_point(a.cell.cube)} m",
        )
    when = "when it is placed" if placed else "in any order"
    return Violation(
        constraint=Constraint.GRIPPING,
        objects=(pid, *blockers),
        message=f"no tool can grip {pid} {when}: {_names(blockers)} "
        f"{'placed before it ' if placed else ''}block every grip option",
        hint=f"place {pid} before {_names(blockers, 3)}, or leave a gap of at least "
        f"{fmt(_finger_gap(a.cell))} m beside {pid} along x or y, or keep its top free",
    )


def _finger_gap(cell: CellConfig) -> float:
    gaps = [g.clearance + g.finger_thickness for g in cell.grippers if g.kind == "parallel"]
    return max(gaps, default=0.0)


class Report(BaseModel):
    """The verifier's answer: pass/fail, the violations, and the order that was checked."""

    model_config = ConfigDict(frozen=True)

    passed: bool
    violations: tuple[Violation, ...]
    sequence: tuple[str, ...] | None
    checked: tuple[str, ...]

    def by_constraint(self) -> dict[str, int]:
        counts: dict[str, int] = {}
        for v in self.violations:
            counts[v.constraint.value] = counts.get(v.constraint.value, 0) + 1
        return counts

    def to_json_dict(self, *, limit: int | None = MAX_PER_CONSTRAINT) -> dict[str, object]:
        """The report as JSON, with at most `limit` violations per constraint (None: all);
        `omitted` counts the rest by constraint, when there are any."""
        listed, omitted = cap_violations(self.violations, limit)
        out: dict[str, object] = {
            "passed": self.passed,
            "violations": [v.to_json_dict() for v in listed],
            "sequence": list(self.sequence) if self.sequence is not None else None,
            "checked": list(self.checked),
        }
        if omitted:
            out["omitted"] = omitted
        return out


def cap_violations(
    violations: Sequence[Violation], limit: int | None = MAX_PER_CONSTRAINT
) -> tuple[list[Violation], dict[str, int]]:
    """The first `limit` violations of each constraint, then one summary violation for each
    constraint with more (naming up to `limit` of the parts involved in the rest), and the
    count of the violations left out, by constraint. `limit` None keeps everything."""
    if limit is None:
        return list(violations), {}
    listed: list[Violation] = []
    rest: dict[str, list[tuple[str, ...]]] = {}
    count: dict[str, int] = {}
    for v in violations:
        code = v.constraint.value
        count[code] = count.get(code, 0) + 1
        if count[code] <= limit:
            listed.append(v)
        else:
            rest.setdefault(code, []).append(v.objects)
    for code, groups in rest.items():
        firsts = (group[0] for group in groups if group)  # each violation's own part first
        parts = list(dict.fromkeys([*firsts, *(name for group in groups for name in group)]))
        listed.append(
            Violation(
                constraint=Constraint(code),
                objects=tuple(parts[:limit]),
                message=f"{len(groups)} more {code} violation(s) not listed (at most {limit} "
                f"are), involving {_names(parts)}",
                hint=f"fix the {code} violations listed and verify again",
            )
        )
    return listed, {code: len(groups) for code, groups in rest.items()}


GEOMETRY_CHECKS: dict[Constraint, Callable[[Analysis], list[Violation]]] = {
    Constraint.WORKSPACE: check_workspace,
    Constraint.COLLISION: check_collision,
    Constraint.CONTACT: check_contact,
    Constraint.SUPPORT: check_support,
    Constraint.STABILITY: check_stability,
}


def order_violations(
    a: Analysis, sequence: Sequence[str] | None
) -> tuple[list[Violation], list[str] | None]:
    """Gravity, sequence and gripping: check `sequence`, or find one and report why none exists."""
    if sequence is not None:
        if sorted(sequence) != sorted(a.layout.ids):
            raise InputError("must order every part of the layout exactly once", field="sequence")
        return check_order(a, sequence) + check_gripping_order(a, sequence), list(sequence)
    order, stuck = disassemble(a)
    ids = a.layout.ids
    if stuck is None:
        return [], [ids[i] for i in order]
    out = [
        _grip_violation(a, i, [ids[j] for j in blockers], placed=False)
        for i, blockers in sorted(stuck.ungrippable.items())
    ]
    if not stuck.ungrippable:
        names = [ids[i] for i in stuck.waiting]
        out.append(
            Violation(
                constraint=Constraint.SEQUENCE,
                objects=tuple(names),
                message=f"the stated precedence has a cycle through {_names(names)}",
                hint="remove one of the precedence pairs between these parts",
            )
        )
    return out, None


def verify(
    layout: Layout,
    cell: CellConfig | None = None,
    *,
    sequence: Sequence[str] | None = None,
    precedence: Precedence = (),
) -> Report:
    """V(C, K): run every check; pass only when no constraint is violated."""
    a = Analysis(layout, cell or CellConfig(), tuple(precedence))
    violations: list[Violation] = []
    for check in GEOMETRY_CHECKS.values():
        violations.extend(check(a))
    order_v, order = order_violations(a, sequence)
    violations.extend(order_v)
    if (
        order is not None
        and not order_v
        and not any(v.constraint == Constraint.STABILITY for v in violations)
    ):
        states = check_assembly_states(a, order)
        better = stable_order(a, order) if states and sequence is None else None
        if better is not None:  # the Inspector chose the order: put counterweights first
            order, states = better, []
        violations.extend(states)
    return Report(
        passed=not violations,
        violations=tuple(violations),
        sequence=tuple(order) if order is not None else None,
        checked=tuple(c.value for c in Constraint),
    )
