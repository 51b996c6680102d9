"""Stage 7: composition. Relations between phrases become `Relation`s between structures:
pronouns resolve to the structures they name, a ring "around" something becomes an
enclosure, towers "joined by" a beam become a bridge standing on them, and a structure
"between" two others stands in a row with them."""

from __future__ import annotations

import math
import re

from sdi.language.nouns import COPY_WORDS, beam_only, families_said
from sdi.language.references import resolve
from sdi.language.state import Phrase, PhraseRelation, ReadState
from sdi.spec import lexicon as lx
from sdi.spec.structure_spec import (
    Relation,
    RelationKind,
    RowSpec,
    StructureDraft,
    StructureSpec,
    TowerSpec,
)

_KINDS: dict[str, RelationKind] = {"on": "on_top_of", "around": "around", "next": "next_to"}


def relate(
    phrases: list[Phrase],
    rels: list[PhraseRelation],
    structures: list[StructureDraft],
    st: ReadState,
) -> tuple[list[Relation], list[StructureDraft]]:
    relations: list[Relation] = []
    drop: set[int] = set()
    replace: dict[int, StructureDraft] = {}

    def built(j: int | None, fallback: int) -> int | None:
        if j is None:
            # "on top" with no object: the phrase before the subject — or the one a pronoun
            # just before it names ("a tower on the left of it and a row behind it": it)
            cands = [
                q
                for q in range(fallback)
                if (phrases[q].count and phrases[q].spec)
                or (
                    phrases[q].ref is not None
                    and q == fallback - 1
                    and phrases[q].clause == phrases[fallback].clause
                )
            ]
            return resolve(phrases, cands[-1]) if cands else None
        j = resolve(phrases, j)
        return j if phrases[j].count and phrases[j].spec is not None else None

    joiners = {r.object for r in rels if r.kind in ("joined", "between")}
    # what "its" named in the relation before (said without an object), and on which side
    its: tuple[int, str, int] | None = None
    for n_rel, r in enumerate(rels):
        if r.kind == "between":
            flanked = _flanked(phrases, r, structures, relations)
            if flanked:
                relations.extend(flanked)
                st.flanked = True
                st.notes.append("placed between the two, side by side")
                continue
            if flanked is not None:  # midway between the places of the two
                st.flanked = True
                st.notes.append("placed midway between the places of the two")
                continue
            r = PhraseRelation("joined", r.subject, r.object, r.side)
        subj = r.subject
        if phrases[subj].modified or (r.object is not None and phrases[r.object].modified):
            continue  # "add a third layer on it": already a change of that structure
        if r.kind == "on" and subj in joiners:
            continue  # "joined by a bridge on top": the joining beam lies on top anyway
        obj = built(r.object, r.subject)
        if r.kind == "joined":
            pillars = built(r.subject, r.subject)
            if not phrases[r.subject].text.strip() and phrases[r.subject].ref is None:
                pillars = built(None, r.subject)  # "… behind it with a beam on top": "it" taken
            pillars = (
                resolve(phrases, r.subject) if phrases[r.subject].ref is not None else (pillars)
            )
            between = _between(phrases, pillars, r.object, structures)
            if between:
                relations.extend(between)
                st.notes.append("placed between the two, side by side")
                continue
            _join(phrases, pillars, r.object, structures, replace, drop, st, relations)
            continue
        s_ref = phrases[subj].ref is not None
        subj = resolve(phrases, subj)
        if phrases[subj].undone or (
            r.object is not None and phrases[resolve(phrases, r.object)].undone
        ):
            continue  # "… next to it. Undo the last one.": taken back with its structure
        if not phrases[subj].count or phrases[subj].spec is None:
            if phrases[subj].tokens and r.kind == "on" and obj is not None:
                # "a beam on top of the two towers": the beam joins them
                _join(phrases, obj, subj, structures, replace, drop, st, relations)
                continue
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored a relation '{r.kind}': its subject is not a structure")
            continue
        s_first, s_last = phrases[subj].first, phrases[subj].first + phrases[subj].count - 1
        o_ref = r.object is not None and phrases[r.object].ref is not None
        if r.object is None:
            # "X with Y on top", "on top" alone: the structure before the subject
            s_idx = s_last
            o_idx = (
                s_last - 1
                if phrases[subj].count > 1
                else (phrases[obj].first + phrases[obj].count - 1 if obj is not None else -1)
            )
            if (
                its is not None
                and r.kind == "next"
                and r.side is not None
                and its[1] == lx.OPPOSITE_SIDE.get(r.side)
                and its[2] == n_rel - 1
            ):
                # "a tower with a row on its left and a row on its right": its other side ("…
                # to its left, and a tower of 1 to its left" is the one before)
                o_idx = its[0]
            its = (o_idx, r.side, n_rel) if r.kind == "next" and r.side else None
        elif obj is None:
            o_idx = -1
            s_idx = s_last
        elif obj == subj:
            # "a staircase with a tower next to it", "a ring with a tower inside it": the
            # pronoun's side takes the first structure of the phrase, the other the last
            s_idx = s_first if s_ref else s_last
            o_idx = s_first if o_ref or not s_ref else s_last
            if phrases[subj].count == 1:
                o_idx = s_first - 1
        else:
            s_idx = s_last
            o_idx = phrases[obj].first + phrases[obj].count - 1
        copies = _counted_copies(phrases[subj], structures) if not s_ref else []
        members: list[int] = []
        if (
            r.kind == "next"
            and copies
            and s_idx == copies[-1]
            and phrases[r.subject].structure is None
            and (r.object is None or obj != subj)
            and not st.anchors
        ):
            # "a wall and two towers behind it", "two towers of 4 behind a wall": the copies side
            # by side as one unit beside the other (the last stood beside the one before it,
            # or beside the wall with the first left free)
            before = o_idx
            if r.object is None:
                o_idx = copies[0] - 1 if copies[0] > s_first else -1
                if o_idx < 0 and obj is not None and obj != subj:
                    o_idx = phrases[obj].first + phrases[obj].count - 1
            if o_idx >= 0:
                s_idx, members = copies[0], copies[1:]
            else:
                o_idx = before  # "two towers, one behind": nothing else to stand beside
        if r.kind == "on" and r.object is None and s_idx in copies[1:] and not st.anchors:
            # "slab 5x2, 3 towers of 2 on top": the copies stood on each other, silently; "it"
            # is the slab, and SDI stands one of them on it
            o_idx = copies[0] - 1 if copies[0] > s_first else -1
            said = _counted_said(phrases[subj])
            st.material.append(said)
            st.notes.append(
                f"ignored '{said}' on it for all but one: SDI stands one structure on "
                "another's top (say 'one on each corner' to spread them)"
            )
        elif (
            r.kind == "on"
            and r.object is not None
            and obj != subj
            and phrases[subj].count > 1
            and phrases[r.subject].structure is None
            and not st.anchors
        ):
            # "a 4x2 slab with two towers of 2 on it": only one of them stands on it
            said = phrases[subj].text.strip(" ,")
            st.material.append(said)
            st.notes.append(
                f"ignored '{said}' on it for all but one: SDI stands one structure on "
                "another's top (say 'one on each corner' to spread them)"
            )
        if phrases[r.subject].structure is not None:
            s_idx = phrases[r.subject].structure  # type: ignore[assignment]
        if r.object is not None and phrases[r.object].structure is not None:
            o_idx = phrases[r.object].structure  # type: ignore[assignment]
        own = o_idx in (s_idx, -1) and structures[s_idx].shape in ("bridge", "arch", "canopy")
        if own and set(phrases[subj].text.lower().split()) & _OWN_TOPS:
            # "a table: four legs … and a flat top resting on them": its own top
            st.notes.append(f"read '{r.kind}' as the {structures[s_idx].shape}'s own top")
            continue
        sited = structures[s_idx].region or structures[s_idx].at_x is not None
        if (o_idx < 0 or o_idx == s_idx) and r.kind == "middle" and not sited:
            # "a bridge with legs 3 tall in the centre": nothing else named, the table's centre
            structures[s_idx] = structures[s_idx].model_copy(update={"region": "centre"})
            st.notes.append("read 'in the middle' with no other structure as the table's centre")
            continue
        if o_idx < 0 or o_idx == s_idx:
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored '{r.kind}': no structure to relate '{phrases[subj].text}' to")
            continue
        if obj is None:
            obj = subj
        picked = r.object is not None and phrases[r.object].structure is not None
        first = phrases[obj].first
        shapes = {structures[i].shape for i in range(first, first + phrases[obj].count)}
        if (
            r.object is not None
            and phrases[r.object].text.strip(" ,").lower() in ("it", "that", "this", "that one")
            and len(shapes) > 1
        ):
            picked = True  # "a wall, a tower behind it, and a cube on top of that": the last one
        members_of = range(first, first + phrases[obj].count)
        if any(
            rel.kind == "on_top_of" and rel.subject in members_of and rel.object in members_of
            for rel in relations
        ):
            picked = True  # "a 3x3 layer and a 2x2 layer on that, then a cube on top": the stack's
        joined = replace.get(first) is not None and replace[first].shape == "bridge"
        if joined and o_idx in drop:
            o_idx = first  # "two towers joined by a beam, then a cube on top": on the bridge
        elif r.kind == "on" and phrases[obj].count > 1 and phrases[subj].count == 1 and not picked:
            _join(phrases, obj, subj, structures, replace, drop, st, relations)
            continue
        subject = replace.get(s_idx, structures[s_idx])
        obj_spec = replace.get(o_idx, structures[o_idx])
        subject = _copy_if_asked(phrases[subj], subject, obj_spec, st)
        if r.kind == "middle":
            # "a 3x3 slab with a tower in the middle": on the slab, centred; "a 6 by 6 fence with
            # a pyramid in the middle": inside it. The subject is the one with a middle.
            if subject.shape in _TOPPED or (subject.shape == "row" and (subject.width or 1) == 1):
                # "a cross with a tower in the centre", "a row of 5 with a tower in the middle"
                # (a wall's middle stays inside it: "a wall 6 by 6 with a pyramid in the middle")
                st.notes.append(f"read 'in the middle' of the {subject.shape} as on top of it, "
                                "centred")  # fmt: skip
                subject, obj_spec, s_idx, o_idx = obj_spec, subject, o_idx, s_idx
                r = PhraseRelation("on", r.subject, r.object, r.side)
            else:
                subject = _enclosing(subject, st)
                r = PhraseRelation("around", r.subject, r.object, r.side)
        if r.kind == "around" and obj_spec.shape in ("enclosure", "castle"):
            subject, obj_spec = obj_spec, subject
            s_idx, o_idx = o_idx, s_idx
        if r.kind == "around" and subject.shape not in ("enclosure", "castle"):
            ring = _enclosing(subject, st)  # "a 7 by 7 fence with … inside it": 7 by 7 around
            if ring is subject:
                st.notes.append(f"a {subject.shape} around another structure: built as a ring")
                if subject.shape in ("l_shape", "t_shape", "u_shape"):
                    # "a U shape with a tower inside": the letter asked for is not a ring
                    st.material.append(f"{subject.shape} as a ring")
                ring = StructureDraft(shape="enclosure", height=subject.height, part=subject.part)
            subject = ring
        replace[s_idx] = subject
        if any(rel.subject == s_idx for rel in relations):
            st.material.append(f"relation {r.kind}")
            st.notes.append(f"ignored a second relation of '{phrases[subj].text}'")
            continue
        kind: RelationKind = _KINDS[r.kind]
        edge = subject.edge[0] if kind == "on_top_of" and len(subject.edge) == 1 else None
        if edge is not None:
            # "a wall standing on the pad, along its back edge": the edge of the top it stands
            # on, not of the table (the unit was pulled to the table's back edge)
            subject = subject.model_copy(
                update={"edge": (), "region": None if subject.region == edge else subject.region}
            )
            st.notes.append(f"read the {edge} edge as the {obj_spec.shape}'s: the "
                            f"{subject.shape} stands on it along that edge")  # fmt: skip
        placed = {"at_x": subject.at_x, "at_y": subject.at_y, "region": subject.region}
        if kind != "around" and any(v is not None for v in placed.values()):
            # the unit stands where the object stands: a position said of the subject moves
            # to the object when the object has none
            if obj_spec.at_x is None and obj_spec.at_y is None and obj_spec.region is None:
                replace[o_idx] = obj_spec.model_copy(update=placed)
            else:
                st.notes.append(
                    f"the position of the {subject.shape} follows the {obj_spec.shape} it is "
                    f"{kind.replace('_', ' ')}"
                )
            replace[s_idx] = subject.model_copy(update=dict.fromkeys(placed))
        if (
            kind == "on_top_of"
            and subject.shape == "enclosure"
            and subject.length is None
            and subject.width is None
            and obj_spec.shape in ("grid", "block")
            and obj_spec.length
            and obj_spec.width
            and min(obj_spec.length, obj_spec.width) >= 3
        ):  # "a 3x5 slab with a wall round its edge": the ring on its rim (a 4 by 4 overhung)
            subject = subject.model_copy(
                update={"length": obj_spec.length, "width": obj_spec.width}
            )
            replace[s_idx] = subject
            st.notes.append(f"the ring as long and wide as the {obj_spec.shape} it stands on: "
                            f"{obj_spec.length} by {obj_spec.width}")  # fmt: skip
        side = r.side or (phrases[r.object].side if r.object is not None else None)
        if kind == "on_top_of":
            side = edge  # on a top: only an edge said places it off the top's centre
        if kind == "next_to" and st.stair_end and obj_spec.shape == "staircase":
            # "a tower at its low end": the side the staircase climbs from (or to)
            side = _stair_foot(obj_spec)
            side = lx.OPPOSITE_SIDE[side] if st.stair_end == "high" else side
            st.stair_end = None
        at = next((a for a in st.anchors if a[0] == kind), None)
        if at is not None and _covers(subject, obj_spec) and any(
            later.kind == r.kind for later in rels[n_rel + 1 :]
        ):  # "a 2x2 slab on a 2x2 slab, then a cube on one corner": the corner is the cube's
            at = None
        if at is not None:
            st.anchors.remove(at)
            side = None
        group = _group(phrases, r, obj, s_idx, relations) if kind == "next_to" else []
        inside = _inside(phrases, r.object, obj, (s_idx, o_idx, subj), structures, relations) if (
            kind == "around"
        ) else []
        if inside:
            # "a ring 6 by 6 with two towers of 2 inside it", "two towers with a ring around
            # them": all inside, side by side (the ring enclosed one and the others stood
            # outside, silently)
            o_idx = inside[0]
            along = "back" if st.line == "x" else "left"
            gap = st.gap_m if st.gap_m is not None else st.cell.cube[0]
            across = math.ceil(math.sqrt(len(inside))) if len(inside) > 3 else len(inside)
            for k, m in enumerate(inside[1:], start=1):
                # in rows of `across`: four in a square, each row behind the one before
                first = k % across == 0
                side = ("left" if along == "back" else "back") if first else along
                beside = inside[k - across if first else k - 1]
                relations.append(
                    Relation(kind="next_to", subject=m, object=beside, side=side, gap_m=gap)
                )
            laid = "side by side" if across == len(inside) else f"in rows of {across}"
            apart = ", a part apart" if st.gap_m is None else ""
            st.notes.append(f"placed the {len(inside)} structures {laid} inside the ring{apart}")
        if group and at is None:
            # "a row in front of them both": the group side by side as one unit, and the
            # subject beside the whole of it
            o_idx = group[0]
            along = "back" if st.line == "x" else "left"
            # "… from left to right": each after the first on that side of it (the order was
            # turned round, silently)
            along = _LISTED_SIDE.get(st.listing or "", along)
            relations.extend(
                Relation(kind="next_to", subject=m, object=group[0], side=along, whole=True)
                for m in group[1:]
            )
            said = phrases[r.object].text if r.object is not None and not r.plural else "them"
            st.notes.append(f"read '{said}' as the {len(group)} together")
        # a copy on every side of a ring stands a part away (the gap between structures made
        # "a ring 5x5 with a tower on each side" wider than the table)
        near = st.cell.cube[0] if at and at[1] == "sides" and st.gap_m is None else None
        relations.append(
            Relation(kind=kind, subject=s_idx, object=o_idx, side=side, at=at[1] if at else None,
                     gap_m=near)
        )  # fmt: skip
        if members:
            along = "back" if side in ("left", "right") else "left"
            relations.extend(
                Relation(kind="next_to", subject=m, object=s_idx, side=along, whole=True)
                for m in members
            )
            where = lx.BESIDE_PHRASE.get(side or "", "beside")
            st.notes.append(
                f"placed the {len(members) + 1} {subject.shape}s side by side, together {where} "
                f"the {obj_spec.shape}"
            )
    for _, anchor in st.anchors:  # "on each corner" with nothing it could stand on
        where = f"at each {anchor.rstrip('s')}" if anchor.endswith("s") else f"at one {anchor}"
        st.material.append(where)
        st.notes.append(f"ignored '{where}': no structure to stand it on or beside")
    st.anchors.clear()
    for k, s in replace.items():
        structures[k] = s
    _to_base(relations, structures)
    if drop:
        keep = [k for k in range(len(structures)) if k not in drop]
        index = {old: new for new, old in enumerate(keep)}
        relations = [
            r.model_copy(update={"subject": index[r.subject], "object": index[r.object]})
            for r in relations
            if r.subject in index and r.object in index
        ]
        structures = [structures[k] for k in keep]
        for p in phrases:  # the phrases name the structures that remain (towers a beam joins:
            # the bridge built on them)
            if p.count:
                kept = [index[k] for k in range(p.first, p.first + p.count) if k in index]
                p.first, p.count = (kept[0], len(kept)) if kept else (p.first, 0)
            if p.structure is not None:
                p.structure = index.get(p.structure)
    return relations, structures


_LISTED_SIDE = {"left to right": "right", "right to left": "left", "front to back": "back",
                "back to front": "front"}  # fmt: skip
"""The side of the first structure the others of a group said in that order stand on."""

_OWN_TOPS = frozenset({"top", "roof", "beam", "beams", "lintel", "deck", "tabletop", "slab",
                       "plate", "board", "plank", "walkway"})
_TOPPED = ("grid", "block", "pack", "cross")
"""Families whose middle is a top face another structure stands on."""


def _covers(subject: StructureDraft, obj: StructureDraft) -> bool:
    """A level as large as the one it stands on: it cannot stand on one of its corners."""
    if subject.shape not in ("grid", "block") or obj.shape not in ("grid", "block"):
        return False
    sides = sorted((subject.length or 0, subject.width or 0))
    under = sorted((obj.length or 0, obj.width or 0))
    return sides[0] >= under[0] > 0 and sides[1] >= under[1]


def _to_base(relations: list[Relation], structures: list[StructureDraft]) -> None:
    """A position moved to the structure something stands on goes on down to the one at the
    bottom ("bottom: 5 by 5; middle: 3 by 3; top: a cube. Build that in the back left.": it
    stopped at the middle level, which stands where the bottom does)."""
    keys = ("at_x", "at_y", "region")
    for _ in range(len(relations)):
        moved = False
        for r in relations:
            upper, lower = structures[r.subject], structures[r.object]
            placed = {k: getattr(upper, k) for k in keys}
            if (r.kind == "on_top_of" and any(v is not None for v in placed.values())
                    and all(getattr(lower, k) is None for k in keys)):  # fmt: skip
                structures[r.object] = lower.model_copy(update=placed)
                structures[r.subject] = upper.model_copy(update=dict.fromkeys(keys))
                moved = True
        if not moved:
            return


def _enclosing(host: StructureDraft, st: ReadState) -> StructureDraft:
    """A wall or fence with something in its middle: a ring; "6 by 6" is then its two sides."""
    if host.shape in ("wall", "row") and host.length and host.height == host.length:
        st.notes.append(f"read the {host.shape} {host.length} by {host.length} with something in "
                        f"its middle as a ring {host.length} by {host.length}")  # fmt: skip
        return StructureDraft(shape="enclosure", length=host.length, width=host.length,
                              part=host.part, region=host.region, at_x=host.at_x,
                              at_y=host.at_y)  # fmt: skip
    return host


def _inside(
    phrases: list[Phrase],
    ref: int | None,
    obj: int | None,
    pair: tuple[int, int, int],
    structures: list[StructureDraft],
    relations: list[Relation],
) -> list[int]:
    """The structures a ring encloses together: the counted copies its object is one of ("with
    two towers inside it"), or all a plural reference names ("a ring around them"), when they
    stand free; else []."""
    if obj is None:
        return []
    p = phrases[obj]
    named = range(p.first, p.first + p.count)
    plural = ref is not None and bool(_GROUP_WORDS.match(phrases[ref].text.strip(" ,.")))
    ring, o_idx, subj = pair
    # "surround a tower of 6 and a tower of 2 with a ring": every one the other phrase names,
    # each by its own noun
    listed = len(families_said(p.text)) == p.count and not re.search(r"\bthe\b", p.text, re.I)
    plural = plural or (obj != subj and listed and (ref is None or phrases[ref].ref is None))
    group = [k for k in named if k != ring] if plural else _counted_copies(p, structures)
    family = structures[o_idx].shape
    if not group and any(lx.SHAPE_WORDS.get(w[:-1]) == family
                         for w in re.findall(r"[a-z]+s\b", p.text.lower())):  # fmt: skip
        # "a ring with towers of 1, 2, 3 and 4 inside it": every one of the family listed
        group = [o_idx]
        while group[0] - 1 in named and group[0] - 1 != ring and (
            structures[group[0] - 1].shape == family
        ):
            group.insert(0, group[0] - 1)
    related = {r.subject for r in relations} | {r.object for r in relations}
    if len(group) < 2 or o_idx not in group or ring in group or related & set(group):
        return []
    return group


_GROUP_WORDS = re.compile(
    r"^(?:them(?:\s+both|\s+all)?|both(?:\s+of\s+them)?|all\s+of\s+them|the\s+(?:two|three|four)"
    r"(?:\s+of\s+them)?|all\s+(?:three|four))$",
    re.IGNORECASE,
)


def _group(
    phrases: list[Phrase], r: PhraseRelation, obj: int, subject: int, relations: list[Relation]
) -> list[int]:
    """The structures a plural reference ("them both", "the two", "… with a row behind them")
    names as a relation's object, when they stand free (no relation of their own yet): else
    []."""
    ref = r.object
    if ref is None or not (r.plural or _GROUP_WORDS.match(phrases[ref].text.strip(" ,."))):
        return []
    p = phrases[obj]
    # "two towers of 2 and a row of 4 behind them": the ones named before the subject
    group = [k for k in range(p.first, p.first + p.count) if k < subject or subject < p.first]
    related = {r.subject for r in relations} | {r.object for r in relations}
    if len(group) < 2 or related & set(group):
        return []
    return group


_COUNTED = re.compile(r"\b(?:two|three|four|five|six|[2-6])\s+(?:[\w-]+\s+){0,2}?([a-z]+)s\b", re.I)


def _counted_copies(p: Phrase, structures: list[StructureDraft]) -> list[int]:
    """The structures of a counted plural that ends the phrase ("…, two towers of 4"): the run
    of identical copies at its end, when the phrase counts that family; else []."""
    if p.count < 2 or p.spec is None:
        return []
    last = p.first + p.count - 1
    counted = [m.group(1).lower() for m in _COUNTED.finditer(p.text)]
    if not counted or lx.SHAPE_WORDS.get(counted[-1]) != structures[last].shape:
        return []
    run = [last]
    while run[0] - 1 >= p.first and structures[run[0] - 1] == structures[last]:
        run.insert(0, run[0] - 1)
    return run if len(run) >= 2 else []


def _counted_said(p: Phrase) -> str:
    """The words of the counted plural in the phrase ("two towers of 4")."""
    found = list(_COUNTED.finditer(p.text))
    return p.text[found[-1].start() :].strip(" ,") if found else p.text.strip(" ,")


def _stair_foot(stairs: StructureDraft) -> str:
    """The side of its low end: a staircase climbs +y (left) unless its axis is x (back) or it
    is turned half round (right, front)."""
    turned = round((stairs.yaw_deg or 0.0) % 360) == 180
    if stairs.axis == "x":
        climbs = "front" if turned else "back"
    else:
        climbs = "right" if turned else "left"
    return lx.OPPOSITE_SIDE[climbs]


def _copy_if_asked(
    p: Phrase, subject: StructureDraft, other: StructureDraft, st: ReadState
) -> StructureDraft:
    """ "a second row", "another one like it": the same parameters as the structure referred to."""
    said = set(p.text.lower().split())
    explicit = subject.model_dump(exclude_defaults=True, exclude={"shape"})
    if said & COPY_WORDS and not explicit and subject.shape == other.shape:
        st.notes.append(f"'{p.text}': the same {other.shape} as the one it stands on or beside")
        return other.model_copy(update={"at_x": None, "at_y": None, "region": None})
    return subject


def _flanked(
    phrases: list[Phrase],
    r: PhraseRelation,
    structures: list[StructureDraft],
    relations: list[Relation],
) -> list[Relation] | None:
    """ "a tower of 2 between them", "between them a tower of 2", "two towers and a cube; put
    the cube between them": the structure said between stands in a row with the two it is
    between, in the middle. Two placed in opposite corners ("at the back left … at the front
    right, and a wall between them"): it stands midway between their places and they keep
    theirs — no relations, [] (it was lined up with them along the back, silently). None when
    it is a beam or a spanning structure that joins them, or when the two are not clear."""
    own = phrases[r.subject]  # after "between": the two, or "them" with the middle after it
    said = own.text.strip(" ,.").lower().split()
    middle: list[int] = []
    if own.ref is not None:
        pair = _structures_of(phrases[resolve(phrases, r.subject)])
        if len(pair) < 2 and said[:1] == ["them"] and r.object is not None:
            # "stack 3 on the left, stack 5 on the right, stack 4 in between them": "them"
            # are the two named, one a clause, before the one between
            named = [k for q in phrases[: r.object] for k in _structures_of(q)]
            pair = named[-2:]
    elif said[:1] == ["them"] and own.count:
        # "between them please a tower of 2": the middle is named after the pronoun
        earlier = [q for q in phrases[: r.subject] if q.count and q.spec is not None]
        pair = _structures_of(earlier[-1]) if earlier else []
        middle = _structures_of(own)
    else:
        pair = _structures_of(own)
    if not middle:
        before = phrases[resolve(phrases, r.object)] if r.object is not None else None
        if before is None:
            return None
        if phrases[r.object].structure is not None:  # type: ignore[index]
            middle = [phrases[r.object].structure]  # type: ignore[index, list-item]
        else:
            middle = [k for k in _structures_of(before) if k not in pair]
    if len(pair) > 2:
        pair, extra = _alike_pair(pair, structures)
        middle = middle or extra
    if len(pair) == 3 and not middle:
        # "a tower of 3, a tower of 5 and a tower of 4 between them": the one said with
        # "between", last, stands between the two named before it
        pair, middle = pair[:2], pair[2:]
    if len(pair) != 2 or len(middle) != 1 or middle[0] in pair:
        return None
    x = middle[0]
    if structures[x].shape in ("bridge", "arch", "canopy") or structures[x].part == "beam":
        return None
    related = {rel.subject for rel in relations}
    if x in related or pair[1] in related:
        return None
    a, b = pair
    # a wall or row between two: at its ends, along its length (left to right); two said on
    # either side ("3 on the left, 5 on the right"): from the one to the other
    along = "left" if structures[x].shape in ("wall", "row") else "back"
    side_a, side_b = structures[a].region, structures[b].region
    if side_a in lx.OPPOSITE_SIDE and lx.OPPOSITE_SIDE[side_a] == side_b:
        along = side_b
    elif side_a and side_b and len(side_a.split()) + len(side_b.split()) > 2:
        mid = _midway(side_a, side_b)
        placed = structures[x].region or structures[x].at_x is not None
        if mid is not None and not placed:
            structures[x] = structures[x].model_copy(update={"region": mid})
            return []
    return [
        Relation(kind="next_to", subject=x, object=a, side=along),
        Relation(kind="next_to", subject=b, object=x, side=along),
    ]


def _midway(a: str, b: str) -> str | None:
    """The region halfway between two regions ("back left" and "front right": the centre;
    "back left" and "back right": the back), or None when they share no line."""
    parts = []
    for axis in (("back", "front"), ("left", "right")):
        said_a = next((w for w in a.split() if w in axis), None)
        said_b = next((w for w in b.split() if w in axis), None)
        if said_a == said_b and said_a is not None:
            parts.append(said_a)
        elif said_a is None or said_b is None:
            return None  # "back left" and "left": not two ends of one line
    return " ".join(parts) or "centre"


def _structures_of(p: Phrase) -> list[int]:
    return list(range(p.first, p.first + p.count)) if p.spec is not None else []


def _alike_pair(idx: list[int], structures: list[StructureDraft]) -> tuple[list[int], list[int]]:
    """Of three structures, the two alike ("two towers of 3 and a single cube") and the other."""
    if len(idx) != 3:
        return idx, []
    keys = [structures[k].model_dump(exclude={"region", "at_x", "at_y"}) for k in idx]
    for odd in range(3):
        rest = [k for n, k in enumerate(idx) if n != odd]
        a, b = (keys[n] for n in range(3) if n != odd)
        if a == b and keys[odd] != a:
            return rest, [idx[odd]]
    return idx, []


def _between(
    phrases: list[Phrase], pillars: int | None, middle: int | None, structures: list[StructureDraft]
) -> list[Relation]:
    """ "a 2x2 block between a wall and a tower": the three in a row, the middle one between
    (empty when the middle one is a beam or bridge that joins them instead)."""
    if pillars is None or middle is None or phrases[pillars].count != 2:
        return []
    m = phrases[middle]
    target = resolve(phrases, middle)
    spec = phrases[target].spec
    if spec is None or beam_only(m.text):
        return []
    if m.structure is not None:
        x = m.structure
    else:
        x = phrases[target].first + phrases[target].count - 1
    if structures[x].shape in ("bridge", "arch"):
        return []
    a, b = phrases[pillars].first, phrases[pillars].first + 1
    if x in (a, b):
        return []
    return [
        Relation(kind="next_to", subject=x, object=a, side="back"),
        Relation(kind="next_to", subject=b, object=x, side="back"),
    ]


def _join(
    phrases: list[Phrase],
    pillars: int | None,
    joiner: int | None,
    structures: list[StructureDraft],
    replace: dict[int, StructureDraft],
    drop: set[int],
    st: ReadState,
    relations: list[Relation],
) -> None:
    """Towers "joined by" a beam or bridge: a bridge standing on them as its pillars, spanning
    the way they were set beside each other ("a tower in front and a tower behind it")."""
    if pillars is None or not phrases[pillars].count:
        st.material.append("relation joined")
        st.notes.append("ignored 'joined by': no towers to join")
        return
    p = phrases[pillars]
    idx = list(range(p.first, p.first + p.count))
    towers = [replace.get(k, structures[k]) for k in idx]
    if len(towers) == 1 and towers[0].shape in ("bridge", "arch", "canopy"):
        return  # "a bridge: two pillars … with a beam across the top": the bridge's own beam
    if len(towers) == 1 and towers[0].shape == "row" and (towers[0].length or 0) >= 2:
        # "a beam spanning a pair of single cubes": each cube is a pillar one part high
        n = towers[0].length or 2
        towers = [towers[0].model_copy(update={"shape": "tower", "height": 1, "length": None,
                                               "gap_m": None})] * n  # fmt: skip
    if len(towers) == 1 and towers[0].shape == "tower" and _PAIR.match(p.text):
        # "pillars of 2, beam on top": the plural names the beam's two pillars (one was built)
        towers = [towers[0]] * 2
        st.notes.append(f"read '{p.text.strip(' ,')}' under one beam as two")
    if len(towers) == 1 and towers[0].shape == "tower":
        # "stack 3 high, then a second stack of 3, then lay a beam across the two": the tower
        # named just before it is the other pillar
        def single_towers(said: list[Phrase]) -> list[int]:
            return [q.first for q in said if q.count == 1 and q.spec is not None
                    and q.first not in drop
                    and replace.get(q.first, structures[q.first]).shape == "tower"]  # fmt: skip

        before = single_towers(phrases[:pillars])
        # "a tower of 3. then one more … . then put a beam across them": the last two
        singles = single_towers(phrases[: joiner if joiner is not None else len(phrases)])
        if not before and len(singles) >= 2 and singles[-2] == idx[0]:
            idx = singles[-2:]
            towers = [replace.get(k, structures[k]) for k in idx]
            st.notes.append("read the beam's towers as the last two named")
        elif before:
            idx = [before[-1], *idx]
            towers = [replace.get(k, structures[k]) for k in idx]
            st.notes.append("read the beam's towers as the last two named")
    if len(towers) < 2 or any(t.shape != "tower" for t in towers):
        shapes = ", ".join(t.shape for t in towers)
        st.material.append("relation joined")
        st.notes.append(
            f"ignored 'joined by': only two or more towers can carry a beam (got {shapes})"
        )
        return
    heights = {t.height or (3 if t.height_m is None else None) for t in towers}
    metres = {t.height_m for t in towers if t.height_m is not None}
    if len(heights) > 1 or len(metres) > 1:
        st.material.append("relation joined")
        st.notes.append("ignored 'joined by': towers of different heights cannot carry one beam")
        return
    first = towers[0]
    sides = {r.side for r in relations if r.kind == "next_to" and {r.subject, r.object} <= set(idx)}
    axis = first.axis
    if sides and sides <= {"front", "back"}:
        axis = "x"
    elif sides and sides <= {"left", "right"}:
        axis = "y"
    region = first.region
    ends = {t.region or "" for t in towers}
    if len(towers) == 2 and ends in ({"front", "back"}, {"left", "right"}):
        # "two stacks, one at the front, one at the back, and a beam across the tops": its ends
        axis, region = ("x" if "front" in ends else "y"), None
        st.notes.append(f"read the towers at the {' and '.join(sorted(ends))} as the pillars at "
                        "the bridge's two ends")  # fmt: skip
    bridge = StructureDraft(
        shape="bridge",
        height=first.height,
        height_m=first.height_m,
        spans=len(towers) - 1,
        at_x=first.at_x,
        at_y=first.at_y,
        region=region,
        axis=axis,
    )
    if joiner is not None and phrases[joiner].spec is not None:
        j = phrases[joiner]
        own = [x.shape for x in j.spec.structures] if j.spec else []
        if any(shape not in ("bridge", "arch") for shape in own):
            st.material.append("relation between")
            st.notes.append(
                f"ignored 'between': only a beam or bridge can join towers, not a "
                f"{own[0]}; built them side by side"
            )
            return
        extra = j.spec.structures[0] if j.spec else None
        if extra is not None and extra.shape == "bridge" and extra.span is not None:
            bridge = bridge.model_copy(update={"span": extra.span})
        drop.update(range(j.first, j.first + j.count))
    st.notes.append(
        f"{len(towers)} towers joined by a beam: a bridge with {len(towers) - 1} span(s) on them"
    )
    replace[idx[0]] = bridge
    drop.update(idx[1:])
    named = [
        q for q in phrases[: min(p for p in (pillars, joiner) if p is not None)]
        if q.count == 1 and q.spec is not None and q.first not in drop and q.ref is None
        and replace.get(q.first, structures[q.first]).shape in ("bridge", "arch")
        and not _NUMBER.search(q.text)  # nothing sized: a name of what follows
    ] + [  # "pillars of 2, beam on top, bridge": the name said last
        q for q in phrases[max(p for p in (pillars, joiner) if p is not None) + 1 :][-1:]
        if q.count == 1 and q.spec is not None and q.ref is None and _NAME_LAST.match(q.text)
        and re.search(r"\b" + re.escape(q.text.split()[-1]) + r"\W*$", st.command)
        and replace.get(q.first, structures[q.first]).shape in ("bridge", "arch")
    ]  # fmt: skip
    if named and not _MORE_WORDS.search(st.command):
        # "I want a bridge. Two towers of 3 with a beam across them.": the bridge described
        drop.add(named[-1].first)
        st.notes.append(f"read '{named[-1].text.strip()}' as the bridge the towers and beam make "
                        "(their pillars and beam)")  # fmt: skip


_NAME_LAST = re.compile(
    r"\W*(?:(?:that|this|it)\s*(?:is|'s|makes?|=)\s*)?(?:(?:the|a|an|one|my|our)\s+)?"
    r"(?:bridge|gate|arch|archway|doorway|goal|goalpost|portal|gateway)(?:\s+(?:make|please|done))?"
    r"\W*$",
    re.IGNORECASE,
)
"""', bridge', 'that is the gate': a name said after the towers and beam it names."""
_PAIR = re.compile(
    r"\W*(?:(?:the|its|their|with)\s+)?(?:towers|pillars|posts|columns|stacks|legs|piers|supports|"
    r"uprights)\b(?![^,;.]*\b(?:each|all)\b)",
    re.IGNORECASE,
)
"""'pillars of 2', 'the posts 3 high': towers said in the plural, with no count of them."""
_NUMBER = re.compile(r"\d|\b(?:one|two|three|four|five|six|seven|eight|nine|ten)\b", re.I)
_MORE_WORDS = re.compile(r"\b(?:another|second|more|two\s+bridges|both)\b", re.IGNORECASE)


def unstack(s: StructureSpec, st: ReadState) -> StructureSpec:
    """ "side by side, don't stack them": a tower's parts laid in a row."""
    if isinstance(s, TowerSpec):
        return RowSpec(shape="row", length=s.height or 3, at_x=s.at_x, at_y=s.at_y, region=s.region)
    return s
