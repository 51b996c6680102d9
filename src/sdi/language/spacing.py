"""Spacing between structures: "a tower to the left of the pad, one cube gap", "two towers,
10 cm apart", "a second wall 2 cubes in front of it".

When the command names several structures, a gap it states is the clear space between them
— never between the parts inside one of them (a pad with a "one cube gap" is nine loose
cubes). The phrase is taken out of the text with a note; the reading puts the value on the
``next_to`` relations it builds (`Relation.gap_m`), else on the spacing of the separate
structures (`Spec.gap_m`). With one structure the words are left to the phrase grammar ("a row
of 5 with a one-cube gap between the cubes").
"""

from __future__ import annotations

import re

from sdi.language.state import ReadState
from sdi.spec import lexicon as lx
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import Spec, StructureDraft

_N = r"(\d+(?:\.\d+)?|a\s+couple\s+of|a\s+pair\s+of|a|an|one|two|three|four|five|six)"
_UNIT = r"(cubes?|parts?|blocks?|bricks?|pieces?|cm|mm|m)(?:'s|s')?"  # "a cube's space"
_BETWEEN_PLURAL = r"(?:stacks|towers|columns|pillars|rows|walls|posts|structures|pieces)"
"""What a gap is said between, named bare ("one cube clearance between stacks")."""
_GAP = re.compile(
    r",?\s*\b(?:with\s+|leaving\s+|leave\s+|keep\s+|and\s+)?(?:a\s+)?(?:gap\s+(?:of\s+)?"
    + _N + r"(?:[- ]?" + _UNIT + r")?"
    + r"|" + _N + r"[- ]?" + _UNIT + r"\s+(?:gaps?|spaces?|spacing|apart|aisle)\b"
    + r"|" + _N + r"[- ]?" + _UNIT
    + r"\s+(?:away|off|out|clear)(?:\s+from\s+(?:it|them|each\s+other|the\s+\w+))?"
    + r"|" + _N + r"[- ]?" + _UNIT
    + r"\s+(?:of\s+)?(?:gaps?|spaces?|room|clearance|aisle|walkway|path|corridor)"
    r"(?:\s+between(?:\s+(?:them|the\s+two|each|(?:the\s+)?" + _BETWEEN_PLURAL + r"))?)?"
    + r"|" + _N + r"[- ]?" + _UNIT + r"\s+(?:of\s+)?width\s+between(?:\s+(?:them|the\s+two|each))?"
    + r"|" + _N + r"[- ]?" + _UNIT + r"\s+between\s+(?:them|the\s+two|each\s+other|"
    r"(?:each|every)\s+(?:pair|two)|each(?!\s+(?:cube|part|block|brick)s?\b)|"
    r"(?:the\s+|its\s+)?neighbou?rs)\b"
    + r"|(?:at\s+)?(?:a\s+)?distance\s+(?:of\s+)?" + _N + r"(?:[- ]?" + _UNIT + r")?"
    + r"|(?:separated|spaced|parted)\s+by\s+" + _N + r"[- ]?" + _UNIT
    # "in a line with two cubes between, from left to right": between them
    + r"|" + _N + r"[- ]?" + _UNIT + r"\s+between(?=\s*(?:[,.;!?]|$|from\b|and\b|then\b))"
    + r"|(?:at\s+)?" + _N + r"[- ]?" + _UNIT + r"\s+of\s+(?:distance|separation|space))"
    r"(?:\s+between\s+(?:them|the\s+two|the\s+\w+s|" + _BETWEEN_PLURAL + r"\b))?",
    re.IGNORECASE,
)  # fmt: skip
_BETWEEN_EACH = re.compile(
    r"^\s*(?:in\s+)?between\s+(?:each\s+(?:one|other|of\s+them)|them(?:\s+all)?)\b", re.IGNORECASE
)
# "then shift it (by) 2 cubes to the left": a move of the structure, not a distance between two
MOVED = re.compile(r"\b(?:move|shift|slide|relocate|push|nudge)\s+(?:it|them)(?:\s+by)?\s*$", re.I)
# "2 cubes to its right", "10 cm in front of it": a relation with its distance
_OFFSET = re.compile(
    r"(?<!\bof\s)(?<!\bwith\s)(?<!\bby\s)\b"
    + _N
    + r"[- ]?"
    + _UNIT
    + r"\s+(?=(?:to\s+(?:the|its)\s+(?:left|right)|in\s+front\s+of|"
    r"behind|further\s+back)\b)",
    re.IGNORECASE,
)
# "… and a cube in front of it": what comes before a structure added, not a distance
_ADDED = re.compile(
    r"(?:^|[;.:]|\b(?:and|put|place|set|stand|add|then|plus|also|with))\s*$", re.IGNORECASE
)
# "with a bit of space", "a little gap", "slightly apart": a small gap, one part wide
_VAGUE = re.compile(
    r",?\s*\b(?:each\s+)?(?:with\s+|leaving\s+|leave\s+|and\s+)?(?:(?:a|some)\s+)?(?:(?:little|small|"
    r"tiny|bit\s+of|some|narrow)\s+)+(?:gap|space|room|distance)"
    r"(?:\s+between(?:\s+(?:them|the\s+two))?|\s+(?:to|from)\s+(?:it|them|the\s+\w+))?"
    r"|\b(?:a\s+)?(?:little|bit|tad)\s+apart\b|\bslightly\s+apart\b",
    re.IGNORECASE,
)
_INSIDE = re.compile(r"between\s+(?:each|every|the)\s+(?:cube|part|block)s?\b", re.IGNORECASE)
_PLURALS = "|".join(
    sorted((w for w in lx.SHAPE_WORDS if w.endswith("s") and w.isalpha()), key=len, reverse=True)
)
_PLURAL_SHAPES = re.compile(
    r"\b(?:two|three|four|five|\d+|both|pair\s+of|couple\s+of)\s+(?:\w+\s+)?(?:" + _PLURALS
    + r"|shapes)\b"  # "two L shapes"
    r"|\b(?:another|second|identical|copy|same)\b|\bits\b|\bof\s+it\b"
    # "towers of 3 and 6": a size for each of several
    r"|\b(?:" + _PLURALS + r")\s+(?:of\s+)?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
    r"(?:\s*,\s*\w+)*\s+(?:and|&)\s+(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b",
    re.IGNORECASE,
)


_SPANNING = frozenset({"bridge", "arch", "canopy"})


def _spanning_named(said: list[str], beams: bool = False) -> bool:
    """A bridge, arch, table or span (or, with `beams`, a beam) is named and not negated ("two
    columns without any lintel, a cube apart" names none)."""
    negated = {i + d for i, w in enumerate(said) if w in ("no", "without", "not") for d in (1, 2)}
    words = ("bridge", "span", "beam", "beams") if beams else ("bridge", "span")
    return any(
        (lx.SHAPE_WORDS.get(w) in _SPANNING or w in words)
        and i not in negated
        and not (w in ("table", "tables") and i and said[i - 1] in ("the", "of"))  # the work table
        for i, w in enumerate(said)
    )


def _spanning_plural(said: list[str]) -> bool:
    """Several bridges, arches or tables are named ("two bridges")."""
    return any(w.endswith("s") and lx.SHAPE_WORDS.get(w) in _SPANNING for w in said)


_MIDDLE = re.compile(r"\b(?:in\s+(?:the\s+)?middle|between)\b", re.IGNORECASE)
# "a single cube in front of it, 2 cubes out": the gap said right after a relation
_RELATED = re.compile(
    r"\b(?:in\s+front\s+of|behind|to\s+the\s+(?:left|right)\s+of|next\s+to|beside)\s+"
    r"(?:it|them|the\s+\w+)\s*,?\s*$",
    re.IGNORECASE,
)


_COPY_SAID = frozenset({"another", "second", "again", "identical", "copy"})
"""The words of a copy that put a gap between it and the one before, not in it (narrower than
`nouns.COPY_WORDS`: "the same" says nothing of a second structure)."""


def _several(text: str) -> bool:
    """The command names more than one structure (two shape nouns, a counted plural, a copy)
    and none that spans a gap of its own (a bridge's gap is its span)."""
    said = re.findall(r"[a-z]+", text.lower())
    # "an arch, and another one in front of it with a little gap": a copy, the gap between
    copy = bool(_COPY_SAID & set(said)) and any(
        w in lx.SHAPE_WORDS for w in said
    )
    if _spanning_named(said) and not _spanning_plural(said) and not copy:
        return False  # a bridge's gap is its span; "two bridges 10 cm apart" is between them
    return _named_apart(said) or copy or bool(_PLURAL_SHAPES.search(text))


def _named_apart(said: list[str]) -> bool:
    """The words `said` name two structures by their shape nouns (a spanning one among them
    or not)."""
    return sum(w in lx.SHAPE_WORDS and w not in lx.SELDOM_STRUCTURES for w in said) >= 2


def _metres(value: str, unit: str | None, part_m: float) -> float | None:
    said = " ".join(value.lower().split())
    number = "2" if said in ("a couple of", "a pair of") else words_to_numbers([said])[0]
    if number in ("a", "an"):
        number = "1"
    try:
        n = float(number)
    except ValueError:
        return None
    unit = (unit or "cube").lower()
    if unit in lx.UNITS_M:
        return n * lx.UNITS_M[unit]
    return n * part_m  # cubes, parts, blocks


def _measured(m: re.Match[str], part_m: float) -> float | None:
    """The distance a gap pattern matched, m: its alternatives capture (number, unit) pairs, the
    first that matched is the one said; None outside (0, 0.5] m."""
    groups = m.groups()
    pairs = [(groups[i], groups[i + 1]) for i in range(0, len(groups), 2)]
    value, unit = next(((v, u) for v, u in pairs if v is not None), (None, None))
    metres = _metres(value, unit, part_m) if value else None
    return metres if metres is not None and 0 < metres <= 0.5 else None


_SUPPORTS = r"(?:pillars|legs|towers|supports|columns|posts|piers|stacks|uprights)"
_IS = r"(?:is\s+|of\s+|[:=]\s*|(?:should|must|will|shall|has\s+to|needs\s+to)\s+be\s+)?"
"""How a gap's size is said: "the gap between them should be 3 cubes"."""
_SPAN = re.compile(
    r",?\s*\b(?:with\s+)?(?:a\s+|the\s+)?(?:clear\s+|inner\s+)?span(?:\s+between\s+(?:the\s+)?"
    + _SUPPORTS + r")?\s+" + _IS + r"(?:(?:about|around|roughly)\s+)?" + _N
    + r"(?:[- ]?" + _UNIT + r")?"
    + r"|,?\s*\b(?:with\s+)?(?:the\s+|its\s+)?" + _SUPPORTS
    + r"\s+(?:are\s+|standing\s+|set\s+|placed\s+)?" + _N + r"[- ]?" + _UNIT + r"\s+apart"
    + r"|,?\s*\b(?:and\s+)?(?:the\s+)?(?:inner\s+|clear\s+)?(?:distance|gap|space|spacing|"
    r"clearance|opening)\s+(?:of|between)\s+(?:the\s+)?(?:" + _SUPPORTS + r"|them)"
    + r"\s+" + _IS
    + _N + r"[- ]?" + _UNIT
    + r"|,?\s*\bbetween\s+(?:them|the\s+" + _SUPPORTS + r")\s+(?:is\s+|a\s+gap\s+of\s+)?" + _N
    + r"[- ]?" + _UNIT
    + r"|,?\s*\b" + _N + r"[- ]?" + _UNIT
    + r"\s+(?:of\s+)?(?:gap\s+|space\s+|clearance\s+)?between\s+(?:them|the\s+" + _SUPPORTS + r")"
    + r"|\bspanning\s+an?\s+" + _N + r"[- ]?" + _UNIT + r"\s+gap",
    re.IGNORECASE,
)  # fmt: skip
"""A bridge's, arch's or table's own gap: "pillars 10 cm apart", "between them 5 cm", "the
distance of the pillars is 5 cm", "a span of 2"."""


_APART = re.compile(r",?\s*\b" + _N + r"[- ]?" + _UNIT + r"\s+apart\b", re.IGNORECASE)


def take_span(text: str, st: ReadState) -> str:
    """`text` without the gap between a spanning structure's supports; the gap in `st.span_m`."""
    said = re.findall(r"[a-z]+", text.lower())
    if not _spanning_named(said, beams=True):
        return text
    m = _SPAN.search(text)
    if m is None and not _spanning_plural(said):
        m = _APART.search(text)  # "two towers of five three cubes apart and a beam across them"
    span = _measured(m, st.cell.cube[0]) if m is not None else None
    if m is None or span is None:
        return text
    beam = st.cell.part_types.get("beam")
    reach = beam[0] - 2 * st.cell.tolerances.support_overlap if beam else None
    part = st.cell.cube[0]
    if reach and re.search(r"\bapart\b", m.group(0), re.I) and span > reach >= span - part:
        # "two posts 15 cm apart with a beam across": no beam spans 15 cm clear, so the 15 cm
        # is between their centres (the bridge failed)
        st.notes.append(f"read '{m.group(0).strip(' ,')}' as between the supports' centres: "
                        f"{span - part:g} m clear (a beam spans at most {reach:g} m)")  # fmt: skip
        span = round(span - part, 6)
    else:
        st.notes.append(f"read '{m.group(0).strip(' ,')}' as {span:g} m between the supports")
    st.span_m = span
    # "two 3 high towers 10 cm apart": the supports' noun names them, and stays
    named = re.match(r"\s*(" + _SUPPORTS + r")\b", m.group(0), re.IGNORECASE)
    counted = r"\b(?:high|tall|cubes?|levels?|(?<!the\s)(?:two|three|four|five|six|\d+))\s*$"
    if not re.search(counted, text[: m.start()], re.I):  # "two towers 10 cm apart": counted
        named = None  # "leave the two stacks a cube apart": the stacks named before
    return text[: m.start()] + " " + (named.group(1) + " " if named else "") + text[m.end() :]


_CENTRES = re.compile(
    r",?\s*\b(?:measured\s+)?(?:from\s+)?(?:centre|center)s?[\s-]+to[\s-]+(?:centre|center)s?\b|,?\s*\bon\s+"
    r"(?:centres|centers)\b|,?\s*\bc/c\b",
    re.IGNORECASE,
)


_PITCH = re.compile(
    r"\b(?:(?:on|at)\s+(?:an?\s+)?)?(?P<a>\d+(?:\.\d+)?\s*(?:mm|cm|m)\b)\s+pitch\b|\bpitch(?:ed)?\s+(?:of\s+"
    r"|at\s+)?(?P<b>\d+(?:\.\d+)?\s*(?:mm|cm|m)\b)|\b(?:with\s+)?(?:their\s+)?(?:centres|centers)\s+"
    r"(?P<c>\d+(?:\.\d+)?\s*(?:mm|cm|m|cubes?)\b)\s+apart\b|\b(?:at|on)\s+(?P<d>\d+(?:\.\d+)?\s*(?:mm|cm|m)\b)"
    r"\s+(?:centres|centers)\b",
    re.IGNORECASE,
)
"""A pitch ("on 100 mm pitch", "pitch 150 mm", "centres 150 mm apart", "at 10 cm centres"):
centre to centre."""


def take_centres(text: str, st: ReadState) -> str:
    """`text` without "centre to centre": the distances said are between centres, not clear
    gaps (`pitches` turns them into gaps once the structures are known)."""
    text = _PITCH.sub(
        lambda m: f"{next(g for g in m.groups() if g)} apart, centre to centre",
        text,
    )
    m = _CENTRES.search(text)
    if m is None:
        return text
    st.centres = m.group(0).strip(" ,")
    before, after = text[: m.start()], text[m.end() :]
    if re.search(r"\d\s*(?:mm|cm|m|cubes?)\s*$", before) and not re.match(r"\s*apart\b", after):
        before += " apart"  # "two columns, 150 mm centre to centre": 150 mm apart
    return before + after


def pitches(spec: Spec, st: ReadState) -> Spec:
    """Gaps said centre to centre, as clear gaps: between towers one part wide, the pitch less
    one part; between others the command's measure is not a clear gap SDI can place: said."""
    if st.centres is None:
        return spec
    part = st.cell.cube[0]
    narrow = all(s.shape == "tower" and getattr(s, "length", None) in (None, 1)
                 for s in spec.structures)  # fmt: skip
    if not narrow:
        st.material.append(st.centres)
        st.notes.append(f"ignored '{st.centres}': the gaps are placed clear between the "
                        "structures, not between their centres")  # fmt: skip
        return spec

    def clear(g: float | None) -> float | None:
        return None if g is None else round(max(0.0, g - part), 6)

    relations = tuple(r.model_copy(update={"gap_m": clear(r.gap_m)}) for r in spec.relations)
    st.notes.append(f"read '{st.centres}': the gaps said less one part width ({part:g} m), clear")
    return spec.model_copy(update={"gap_m": clear(spec.gap_m), "relations": relations})


_A_CUBE_BETWEEN = re.compile(
    r",?\s*(?:and\s+)?(?:a|one|an?\s+extra|a\s+single|one\s+single)\s+(?:cube|block|brick)\s+between\b",
    re.IGNORECASE,
)
_PLACED_BEFORE = re.compile(
    r"\b(?:put|place|add|stand|set|stack|build|insert|lay|sit|position|drop)\s*$", re.IGNORECASE
)
"""'two towers, and a cube between them', 'put a cube between them': a cube, no gap."""


def take_gap(text: str, st: ReadState) -> str:
    """`text` without the gap phrase between structures; the gap in `st.gap_m`."""
    if _INSIDE.search(text):
        return text
    part_m = st.cell.cube[0]
    m = _GAP.search(text)
    if m is not None and (
        re.search(r"\b(?:of|with)\s*$", text[: m.start()], re.I)
        or (
            re.search(r"\b(?:take|knock|pull|lift)(?:\s+the)?\s*$", text[: m.start()], re.I)
            and re.search(r"\boff\b", m.group(0), re.I)
            and re.match(
                r"\s*(?:its|one|the|either)\s+(?:(?:left|right|front|back)\s+)?end\b"
                r"|\s*(?:the\s+)?(?:top|first|second|third|last|middle|taller|shorter|left|right|"
                r"front|back)\b|\s*(?:it|them|each|both)\b",
                text[m.end() :],
                re.I,
            )
        )
    ):
        m = None  # "a row of three cubes between them", "take the two cubes off": no gap
    elif (
        m is not None
        and _A_CUBE_BETWEEN.match(m.group(0))
        and (
            m.group(0).lstrip(" ,").lower().startswith("and")
            or _PLACED_BEFORE.search(text[: m.start()]) is not None
        )
    ):
        m = None  # "two towers, and a cube between them", "put a cube between them": a cube
    offset_only = (
        m is None
        and _OFFSET.search(text) is not None
        and _named_apart(re.findall(r"[a-z]+", text.lower()))
    )
    if not _several(text) and not (m is not None and _RELATED.search(text[: m.start()])) and not (
        offset_only  # "a bridge, and a pyramid 15 cm to its left": no span, a distance
    ):
        return text  # "a bridge, its pillars 2 cubes apart": the bridge's own span
    if m is not None:
        gap = _measured(m, part_m)
        if gap is not None:
            st.gap_m, st.gap_said = gap, m.group(0).strip(" ,")
            st.gap_first = not _MIDDLE.search(text[: m.start()])
            st.notes.append(f"read '{m.group(0).strip(' ,')}' as {gap:g} m between the structures")
            rest = re.sub(
                r"^\s*(?:each|apiece|between\s+each|(?:in\s+)?between(?:\s+(?:them|the\s+"
                r"two|both)\b|(?=\s*(?:[,.;!?]|$))))",
                "",
                text[m.end() :],
                flags=re.I,
            )
            # "… a cube apart. Finally … also a cube apart": the same gap, said again
            said = re.escape(m.group(0).strip(" ,"))
            again = re.compile(
                r",?\s*\b(?:also|again|too|as\s+well)?\s*"
                + said
                + r"(?:\s+(?:also|again|too|as\s+well))?",
                re.I,
            )
            rest = again.sub(" ", rest)
            return text[: m.start()] + " " + rest  # "one cube gap each": the same gap
    v = _VAGUE.search(text)
    if v is not None:
        st.gap_m = part_m
        st.notes.append(f"read '{v.group(0).strip(' ,')}' as a small gap: one part ({part_m:g} m)")
        rest = _BETWEEN_EACH.sub("", text[v.end() :])
        return text[: v.start()] + " " + rest
    o = _OFFSET.search(text)
    if o is not None and MOVED.search(text[: o.start()]):
        o = None  # "then shift it 2 cubes to the left": a move of the structure, read later
    if (
        o is not None
        and o.group(1).lower() in ("a", "an")
        and _ADDED.search(text[: o.start()])
    ):
        o = None  # "a small wall and a cube in front of it": a cube, not a distance
    if o is not None:
        gap = _metres(o.group(1), o.group(2), part_m)
        if gap is not None and 0 < gap <= 0.5:
            st.gap_m = gap
            st.notes.append(f"read '{o.group(0).strip()}' as {gap:g} m away")
            return text[: o.start()] + text[o.end() :]
    return text


def _space_kept(spec: Spec, st: ReadState, gap_m: float) -> Spec | None:
    """The middle one (or two) of one-part-wide structures `gap_m` apart taken away: the two
    left keep their places, the space between them (None when they are not one part wide)."""
    widths = {getattr(s, "length", None) or 1 for s in spec.structures}
    if len(spec.structures) != 2 or widths != {1}:
        return None
    k = st.taken_inner
    gap = round((k + 1) * gap_m + k * st.cell.cube[1], 6)
    st.notes.append(f"the two left keep their places: {gap:g} m between them")
    return spec.model_copy(update={"gap_m": gap})


def apply_gap(spec: Spec, st: ReadState) -> Spec:
    """The stated gap on the relations beside (else between the separate structures)."""
    inner = st.taken_inner > 0
    if st.gap_m is None:
        # "three towers, then remove the middle one": at the gap SDI leaves between structures
        if inner and not spec.relations:
            return _space_kept(spec, st, st.cell.design.structure_gap) or spec
        return spec
    beside = [
        r for r in spec.relations if r.kind == "next_to" and r.at in (None, "ends", "end", "sides")
    ]
    if beside:
        relations = tuple(
            r.model_copy(update={"gap_m": st.gap_m}) if r in beside else r for r in spec.relations
        )
        return spec.model_copy(update={"relations": relations})
    related = {r.subject for r in spec.relations}
    if len(spec.structures) - len(related) >= 2:
        if inner:
            # "three towers a cube apart, then take the middle one away": at the gap said
            kept = _space_kept(spec, st, st.gap_m)
            if kept is not None:
                return kept
            st.material.append("the space of the one taken away")
            st.notes.append("ignored the space of the one taken away: the others stand "
                            f"{st.gap_m:g} m apart, closed up")  # fmt: skip
        return spec.model_copy(update={"gap_m": st.gap_m})
    if len(spec.structures) < 2 and st.taken:
        # "two towers a cube apart, then take the first one down": the gap went with it
        st.notes.append(f"the gap of {st.gap_m:g} m went with the structure taken away")
        return spec
    st.material.append(f"gap {st.gap_m:g} m")
    st.notes.append(f"ignored the gap of {st.gap_m:g} m: there are no two structures side by side")
    return spec


def apply_span(drafts: list[StructureDraft], st: ReadState) -> list[StructureDraft]:
    """The stated gap between supports as the span (in parts) of the one spanning structure
    (a gap said between two towers that a beam then joins is that bridge's span)."""
    alone = len(drafts) == 1 and drafts[0].shape in _SPANNING
    if st.span_m is None and st.gap_m is not None and alone:
        st.span_m, st.gap_m = st.gap_m, None
    if st.span_m is None:
        return drafts
    spanning = [k for k, d in enumerate(drafts) if d.shape in _SPANNING and d.span is None]
    parts = st.span_m / st.cell.cube[0]
    if not spanning and st.gap_m is None:
        st.gap_m = st.span_m  # "two towers three cubes apart and a beam across them": between
        return drafts  # the towers, as said, for the beam to reach across or not
    if len(spanning) != 1 or abs(parts - round(parts)) > 1e-6 or round(parts) < 1:
        st.material.append(f"span {st.span_m:g} m")
        st.notes.append(
            f"ignored the gap of {st.span_m:g} m between supports: "
            + ("it is no whole number of parts" if len(spanning) == 1 else
               "no single bridge, arch or table to give it to")
        )  # fmt: skip
        return drafts
    k = spanning[0]
    return [*drafts[:k], drafts[k].model_copy(update={"span": round(parts)}), *drafts[k + 1 :]]
