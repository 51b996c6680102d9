"""Computed rewrites: replacements that need arithmetic or context ("twelve cubes in three
equal stacks" → three stacks of four) or that set a flag on the reading ("don't stack them",
"no beams"). The rewrite table (`sdi.language.rewrites`) names each by its key in `HANDLERS`."""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable

from sdi.errors import InfeasibleError, SpecError
from sdi.language.nouns import L_NAMED, STRUCTURE_PLURALS, families_said, l_named_last
from sdi.language.state import ReadState
from sdi.spec import lexicon as lx
from sdi.spec.numbers import FACTORS, NUMBER_WORDS, words_to_numbers


def _split(m: re.Match[str], st: ReadState) -> str:
    """ "twelve cubes in three equal stacks": three stacks of four."""
    said = [words_to_numbers([m.group(g).lower()])[0] for g in ("total", "count")]
    if not all(v.isdigit() for v in said):
        return m.group(0)
    total, count = int(said[0]), int(said[1])
    noun = m.group("noun").lower()
    if count < 1 or total % count:
        st.material.append(m.group(0))
        st.notes.append(f"ignored '{m.group(0)}': {total} parts do not split into {count} equal")
        return f" {count} {noun} "
    st.notes.append(f"{total} parts as {count} {noun}: {total // count} each")
    return f" {count} {noun} of {total // count} cubes "


Handler = Callable[[re.Match[str], ReadState, str], str]


def _said(m: re.Match[str]) -> tuple[str, list[str]]:
    return m.group(0).strip(" ,"), [g.lower() if g else "" for g in m.groups()]


def _no_stack(m: re.Match[str], st: ReadState, note: str) -> str:
    st.no_stack = True
    st.notes.append(note.format(_said(m)[0]))
    return " "


def _no_beams(m: re.Match[str], st: ReadState, note: str) -> str:
    st.no_beams = True
    st.notes.append(note.format(_said(m)[0]))
    return " "


def _placement(m: re.Match[str], st: ReadState, note: str) -> str:
    if re.search(r"\b(?:castle|fort|fortress|citadel)s?\b", m.string, re.IGNORECASE):
        return m.group(0)  # "a castle with a tower at each corner": the family's own
    sided = re.search(r"\b(?:each|every|all)\s+(?:\w+\s+)?sides?\b", m.group(0), re.IGNORECASE)
    if (
        sided
        and not m.group(1)
        and re.search(
            r"(?<!\bof\s)(?<![\w.])(?:\d+(?:\.\d+)?|two|three|four|five|six|seven|eight|nine|ten)\s*"
            r"(?:cubes?|parts?|blocks?|cm|mm|m|in|inch(?:es)?|ft|feet|foot)?\s*(?:long\s*)?$",
            m.string[: m.start()],
            re.IGNORECASE,
        )
    ):
        return m.group(0)  # "a courtyard 5 cubes on each side": a size
    said = re.sub(r"\s+of\s+an?$", "", _said(m)[0])
    at = "corners" if "corner" in said.lower() else "ends" if " end" in said.lower() else None
    if at and re.search(r"\bone\b", said, re.IGNORECASE):
        at = at[:-1]  # "on one corner": a single copy ("on either end": each end, as people say)
    all_four = re.search(r"\b(?:four|4|all)\b", said, re.IGNORECASE)
    flanking = at is None and (
        re.search(r"\b(?:either|both|each)\b", said, re.IGNORECASE) or all_four
    )
    if flanking and not all_four and re.search(r"\bbetween\b", m.string[: m.start()], re.I):
        # "a block between two towers, one cube gap on each side": the two gaps of "between"
        st.notes.append(f"read '{said}' as the gaps on both sides of the one between")
        return " "
    named = families_said(m.string[: m.start()])  # the object: the one before the subject
    square = len(named) > 1 and named[-2] == "enclosure" and bool(sided)
    if flanking and (all_four or square):
        # "a tower on each of its 4 sides", "a ring 5x5, a tower on each side": every side
        at = "sides"
    elif flanking:  # "a tower on each side of it", "on either side": one at each of its ends
        at = "ends"
    elif at is None:  # "on one side": which side is not said
        st.material.append(said)
        st.notes.append(f"ignored '{said}': which side of the structure is not clear")
        return " "
    on = re.match(r"\s*,?\s*(?:stacked|resting|standing|sitting)?\s*on\b", m.group(0), re.I)
    on_top = re.search(r"\bon\s+top\s*,?\s*$", m.string[: m.start()], re.IGNORECASE)
    kind = "on_top_of" if (on or on_top or at == "corners") and not flanking else "next_to"
    st.anchors.append((kind, at))
    st.flanking = st.flanking or bool(flanking and kind == "next_to")
    if at.endswith("s"):
        st.notes.append(
            f"read '{said}' as one at each of its {at}"
            + (" (one on each side, along its length)" if flanking and at == "ends" else "")
        )
    else:  # "on one end": which end is not said
        st.notes.append(f"'{said}': which {at} was not said; SDI took one")
    if on_top and not m.group(1):
        return " "  # "a wall with a cube on top at each end"
    obj = m.group(1)
    if kind == "on_top_of":
        return f" on top of {obj} " if obj else " on top "
    return f" next to {obj or 'it'} "



def _bend(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "an L shape of 5 by 3 with a tower of 4 at the corner": on top of the L where its arms
    meet; "a 3x3 slab with a tower at the corner": on one corner of its top (both went to the
    table's back left corner)."""
    sentence = re.split(r"[.;!?]", m.string[: m.start()])[-1]
    withs = list(re.finditer(r"\bwith\b", sentence, re.IGNORECASE))
    l_last = l_named_last(m.string[: m.start()])  # "an L shape 3x3 then a tower on the corner"
    if not withs and not l_last:
        return m.group(0)
    named = [
        lx.SHAPE_WORDS[w]
        for w in re.findall(r"[a-z]+", sentence[: withs[-1].start() if withs else None].lower())
        if w in lx.SHAPE_WORDS
    ]
    if L_NAMED.search(sentence) or l_last:
        st.anchors.append(("on_top_of", "bend"))
        st.notes.append(f"read '{_said(m)[0]}' as on top of the L's corner, where its arms meet")
    elif named and named[-1] in ("grid", "block", "pack"):
        st.anchors.append(("on_top_of", "corner"))
        st.notes.append(f"read '{_said(m)[0]}' as on one corner of its top (which corner was not "
                        "said: the front right)")  # fmt: skip
    else:
        return m.group(0)
    return " on top "


def _extra_cube(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "… put one more block on top at each end" after a wall: a single cube; after a tower it
    makes the tower taller (a change, read later)."""
    named = [
        lx.SHAPE_WORDS[w] for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())
        if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES
    ]  # fmt: skip
    if not named or named[-1] == "tower":
        return m.group(0)
    return " a 1-cube tower "


def _arith(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "3 more than 4", "one step fewer than 5": the number worked out, with what it counts."""
    said, (a, noun, op, noun_after, b) = _said(m)
    a_, b_ = (words_to_numbers([g])[0] for g in (a, b))
    if b in ("that", "this", "it", "those", "them"):
        # "one of 2, the other 3 more than that": the number said last before it
        before = re.findall(r"[a-z]+|\d+", m.string[: m.start()].lower())
        said_before = [w for w in words_to_numbers(before) if w.isdigit()]
        b_ = said_before[-1] if said_before else b_
    if not (a_.isdigit() and b_.isdigit()):
        return m.group(0)
    value = int(b_) + (int(a_) if op == "more" else -int(a_))
    counted = noun or noun_after
    if counted and value < 1:
        return m.group(0)
    if counted and value > 1 and not counted.endswith("s"):
        counted += "s"  # "one step fewer than 5": 4 steps
    st.notes.append(f"read '{said}' as {value}" + (f" {counted}" if counted else ""))
    return f" {value} {counted} "


def _from_centre(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "10 cm to the left of the centre": a coordinate, the workspace centre moved."""
    said, groups = _said(m)
    metres = float(groups[0]) * lx.UNITS_M[groups[1]]
    side = groups[2].split()[-1]
    cx, cy = st.cell.design.regions.get("centre", st.cell.design.anchor)
    centre = {"x": cx, "y": cy}
    axis, sign = {"left": ("y", 1), "right": ("y", -1), "back": ("x", 1), "behind": ("x", 1),
                  "front": ("x", -1), "forward": ("x", 1)}[side]  # fmt: skip
    value = round(centre[axis] + sign * metres, 4)
    st.notes.append(f"read '{said}' as {axis} = {value:g} m")
    return f" at {axis} = {value:g} m "


def _square_base(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a pyramid with a 35 cm base side": the base is that long on every side."""
    side = re.sub(r"[- ]cubes?$", "", (m.group(1) or m.group(2)).strip())
    st.notes.append(f"read '{m.group(0).strip()}' as a square base {side} by {side}")
    return f" {side} by {side} base "


def _bottom_count(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a pyramid of 3 levels with 9 cubes on the bottom": a count of parts in the bottom level.
    A square number k² with k levels (or "square") is a k by k base; otherwise a row's length."""
    said = words_to_numbers([m.group(1).lower()])[0]
    if not said.isdigit():
        return m.group(0)
    count, text = int(said), m.string
    side = round(count**0.5)
    levels = re.search(r"\b(\d+)[- ](?:levels?|layers?|tiers?|high|tall)\b|\b(?:levels?|layers?|"
                       r"tiers?)\s*(?:of|:|=)?\s*(\d+)\b", text, re.IGNORECASE)  # fmt: skip
    high = int(levels.group(1) or levels.group(2)) if levels else None
    # "9 cubes in the bottom layer": a layer is a square level (a row is a row)
    square = re.search(r"\bsquare\b", text, re.IGNORECASE) or re.search(
        r"\b(?:layer|level|tier)\b", m.group(0), re.IGNORECASE
    )
    too_long = count > 10 and high is None  # no row of so many: a square of them
    if side >= 2 and side * side == count and (high == side or (square or too_long)):
        st.notes.append(f"read '{m.group(0).strip()}' as a {side} by {side} bottom level")
        return f" with a {side} by {side} base "
    return f" with a base of {count} "


def _base_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "pyramid. 4 levels. base 4 by 4.": a base said on its own, right after a pyramid was
    named, is that pyramid's base (not a platform of its own)."""
    said = re.findall(r"[a-z]+", m.string[: m.start()].lower())
    shapes = [w for w in said if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]
    if not shapes or lx.SHAPE_WORDS[shapes[-1]] != "pyramid":
        return m.group(0)
    return f"{m.group(1)} the pyramid , {m.group(2)}"


def _pyramid_base(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "pyramid, base 25cm": the side of its square base; "base 9 pcs", "4 levels. base 16":
    the count of its bottom level (`_bottom_count`). Only for a pyramid."""
    if not re.search(r"\bpyramids?\b", m.string, re.IGNORECASE):
        return m.group(0)
    unit = (m.group(2) or "").lower()
    if unit in lx.UNITS_M:
        side = f"{m.group(1)} {unit}"
        st.notes.append(f"read '{m.group(0).strip()}' as a square base {side} by {side}")
        return f" with a {side} by {side} base "
    if "." in m.group(1):
        return m.group(0)
    return _bottom_count(m, st, note)


def _compared_one(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower of 4 with a smaller one next to it, 2 high": a comparison the heights said make
    true is said by them (the word was left unused); one they contradict stays unread."""
    before = re.findall(r"\b(?:of|tower|stack|column|pillar)\s+(\d+)\b|\b(\d+)\s+(?:cubes?\s+)?"
                        r"(?:high|tall)\b", m.string[: m.start()], re.IGNORECASE)  # fmt: skip
    if not before:
        return m.group(0)
    other = int(next(a or b for a, b in reversed(before)))
    own = int(m.group(3))
    lower = m.group(1).lower() in ("smaller", "shorter", "lower", "littler", "little", "small")
    if (own < other) != lower or own == other:
        return m.group(0)
    st.notes.append(f"'{m.group(1)}': {own} high, {'below' if lower else 'above'} the {other} "
                    "said before")  # fmt: skip
    return f"another {m.group(2)}"


def _extreme_at(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "with the tallest one in the middle": where the biggest (or smallest) of several
    structures stands; the reader orders them (`st.order`)."""
    said = m.group(0).strip(" ,")
    small = ("shortest", "lowest", "smallest", "shorter", "lower", "smaller")
    most = "min" if m.group(1).lower() in small else "max"
    where = (m.group(2) or "").lower() or {"behind": "back"}.get((m.group(3) or "").lower(), "")
    where = where or ("front" if m.group(3) else "middle")
    if where in ("front", "back") and st.line is None:
        st.line = "x"  # "the bigger one behind": one behind the other
    st.order = (said, most, where)
    return " "


def _named_in_middle(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "…, a tower of six, and another 2 by 2 block, the tower in the middle": the one structure
    of that family, named once among three or more, stands in the middle of their line."""
    said = m.string[: m.start()]
    before = families_said(said) + ["block"] * len(re.findall(r"\bblocks?\b", said, re.I))
    shape = lx.SHAPE_WORDS.get((m.group("a") or m.group("b")).lower())
    if shape is None or before.count(shape) != 1 or len(before) < 3 or st.order is not None:
        return m.group(0)
    st.order = (m.group(0).strip(" ,"), f"shape:{shape}", "middle")
    return " "


def _halfway(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "halfway between front and back": centred front to back (or left to right)."""
    said, groups = _said(m)
    axis = "front to back" if groups[0] in ("front", "back") else "left-right"
    st.notes.append(f"read '{said}' as centred {axis}")
    return " centred front to back " if axis == "front to back" else " centred left-right "


def _negative(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower with minus 3 cubes": a count below zero is refused, not read as 3."""
    raise SpecError(
        f"'{m.group(0).strip()}': a count cannot be negative; say how many to build "
        "(e.g. 'a tower of 3 cubes')",
        understood={},
    )


def _also_a(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a row of 5 that is also a tower of 5": one structure cannot be two families."""
    said, groups = _said(m)
    first, second = lx.SHAPE_WORDS.get(groups[0]), lx.SHAPE_WORDS.get(groups[1])
    if first is None or second is None or first == second:
        return m.group(0)
    raise SpecError(
        f"'{said}': one structure cannot be both a {first} and a {second}; say which to build, "
        f"or ask for two structures ('a {first} and a {second}')",
        understood={"structures": [first, second]},
    )


def _all_different(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a handful of towers, none of them the same height": the reader gives them different
    heights (`st.distinct`)."""
    st.distinct = m.group(0).strip(" ,")
    return " "


def _listing_said(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "three towers of 1, 2 and 3 from left to right": the order they are named in, if
    there are several; the words stay for a structure that runs that way."""
    if st.listing is None:
        st.listing = f"{m.group(1).lower()} to {m.group(2).lower()}"
    return m.group(0)


def _listing(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "three things, left to right: …": the structures named from left to right."""
    st.listing = f"{m.group(1).lower()} to {m.group(2).lower()}"
    return " : "


# how separate structures stand in their row ("standing", "evenly spaced", "set out")
_HOW_THEY_STAND = frozenset({
    "standing", "placed", "arranged", "set", "lined", "up", "spaced", "evenly", "equally",
    "regularly", "out",
})  # fmt: skip


def _in_a_row(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "three towers of 3 in a row with gaps": separate structures stand side by side anyway;
    "in a line front to back": one behind the other; "cubes in a row" is a row (left to the
    grammar)."""
    before = re.findall(r"[a-z]+", m.string[: m.start()].lower())
    while before and before[-1] in _HOW_THEY_STAND:
        before.pop()  # "three columns of four cubes standing in a row": how they stand
    noun = before[-1] if before else ""
    plural = [w for w in before[-5:] if w.endswith("s") and w in lx.SHAPE_WORDS
              and (w not in lx.AMBIGUOUS_SHAPES or (w == "pads" and "x" in before[-4:]))
              and w not in ("rows", "lines")]  # fmt: skip
    counted_parts = any(w in ("of", "each") for w in before[-3:-1])  # "of four cubes"
    if not plural or (noun in ("cubes", "blocks", "bricks", "parts") and not counted_parts):
        return m.group(0)
    then = m.string[m.end() :].lower()
    if re.match(
        r"\s*,?\s*(?:from\s+)?(?:the\s+)?(?:front|back)\s+to\s+(?:the\s+)?(?:front|back)", then
    ):
        st.line = "x"
        st.notes.append(f"read '{m.group(0).strip()} front to back' as one behind the other")
    else:
        st.notes.append(f"read '{m.group(0).strip()}' as the structures side by side")
    return " "


def _height_list(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "three towers: two, four and six high": the heights as a list of numbers."""
    values = words_to_numbers([g.lower() for g in m.groups()])
    return f" {values[0]}, {values[1]} and {values[2]} "


def _layers_word(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "double thickness": two layers."""
    n = {"double": 2, "triple": 3}[m.group(1).lower()]
    st.notes.append(f"read '{m.group(0).strip()}' as {n} layers")
    return f" {n} high "


def _arrangement(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "arranged in a square", "in a grid": separate structures stand in rows and columns
    where their count makes the shape (four or nine in a square, six in a grid); said in
    a circle, a triangle or a count that does not fit, it is reported (`reader`)."""
    said, groups = _said(m)
    if not _structures_before(m):
        return m.group(0)  # "nine cubes in a square": one grid (left to the grammar)
    if groups[0] in ("square", "grid", "block", "array", "pattern", "matrix"):
        st.grid = (0, 1 if groups[0] == "square" else 0, said)
        return " "
    if groups[0] == "triangle":  # two side by side, the third behind them, centred (`reader`)
        st.triangle = said
        return " "
    st.material.append(said)
    st.notes.append(f"ignored '{said}': separate structures are placed side by side in a line")
    return " "


_PLURAL_STRUCTURE = re.compile(
    r"\b(towers|stacks|columns|pillars|posts|piles|pyramids|staircases|stairs|walls|rows|blocks|"
    r"slabs|bridges|arches|cubes|things|ones)\b",
    re.IGNORECASE,
)


def _grid_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "four towers of 2 in a 2 x 2 grid", "six stacks in two rows of three": the structures
    in rows (front to back) by columns. Only after separate structures named in the plural;
    cubes in a grid are one grid (left to the grammar)."""
    said, groups = _said(m)
    if not _structures_before(m):
        return m.group(0)
    a, b = (int(v) for v in words_to_numbers([groups[0] or groups[2], groups[1] or groups[3]]))
    st.grid = (a, b, said)
    return " "


def _measure_named(before: str, family: str | None, measure: str, st: ReadState) -> int | None:
    """The size (in parts, as built) of the `family` structure named last in `before`: its
    height for "tall"/"high", else its length; None when none can be measured. The phrase the
    size is said in is not searched: its own structure is not the one named."""
    from sdi.design.composer import part_sizes
    from sdi.design.shapes import generate
    from sdi.language.families import check_family
    from sdi.spec.grammar import parse_phrase

    clauses = [c for c in re.split(r"[.;](?!\d)|,|\band\b", before) if c.strip()]
    if len(clauses) > 1:
        clauses = clauses[:-1]
    for clause in reversed(clauses):
        if family is None:
            break
        try:
            draft, _ = parse_phrase(clause, st.cell)
            found = [s for s in draft.structures if s.shape == family]
            if not found:
                continue
            spec = check_family(found[-1], [], [], part_m=st.cell.cube[0])
            sizes = part_sizes(st.cell, spec.part)
            boxes = generate(spec, sizes)
        except (SpecError, ValueError, InfeasibleError):
            continue  # "a 3 mm row": no size in parts to take
        if measure in ("tall", "high"):
            return round(max(b.z for b in boxes) / sizes.h + 0.5)
        us, vs = [b.u for b in boxes], [b.v for b in boxes]
        return round(max(max(us) - min(us), max(vs) - min(vs)) / sizes.s) + 1
    return None


def _as_big_as(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a staircase of 3 steps and a tower as tall as the staircase": the size of the
    structure named before, measured in parts as it is built (a staircase of 3 steps is 3
    high, a pyramid of base 4 is 4 high). When it cannot be measured the words are reported,
    not read as a vague "tall"."""
    said, (factor, *groups) = _said(m)
    word, family = groups[0], lx.SHAPE_WORDS.get(groups[1])
    times = FACTORS.get(factor, 1.0)
    # "as long as the tower is tall": the wall's length, the tower's height
    measure = (groups[2] if len(groups) > 2 and groups[2] else word).lower()
    n = _measure_named(m.string[: m.start()], family, measure, st)
    if n is not None:
        dimension = "high" if word in ("tall", "high") else "long"
        if (n * times) % 1 or n * times < 1:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': {factor} {n} is no whole number of parts")
            return " "
        n = int(n * times)
        st.notes.append(f"read '{said}' as {n} {dimension} (the {family} named before)")
        return f" {n} {dimension} "
    st.material.append(said)
    st.notes.append(f"ignored '{said}': no {groups[1]} with a size was named before it")
    return " "


def _than_named(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower that is 1 cube taller than the wall": the wall's height, changed."""
    said, (by, word, noun) = _said(m)
    family = lx.SHAPE_WORDS.get(noun)
    n = _measure_named(m.string[: m.start()], family, "tall" if word in _HEIGHT_WORDS else "long",
                       st)  # fmt: skip
    step = 1 if by in ("", "a") else int(words_to_numbers([by])[0])
    if n is None:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': no {noun} with a size was named before it")
        return " "
    value = n + step if word in ("taller", "higher", "longer") else n - step
    if value < 1:
        return m.group(0)
    dimension = "high" if word in _HEIGHT_WORDS else "long"
    st.notes.append(f"read '{said}' as {value} {dimension} (the {family} named before is {n})")
    return f" {value} {dimension} "


def _from_edge(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "its centre 10 cm from the front edge", "15 cm in from the left edge": the footprint
    centre that far from that edge of the workspace (the edges of the table SDI knows)."""
    said, groups = _said(m)
    if groups[0]:
        value, unit, edge = groups[0], groups[1], groups[2]
    else:
        value, unit, edge = groups[4], groups[5], groups[3]
    metres = float(value) * {"mm": 0.001, "cm": 0.01, "m": 1.0}[unit]
    ws = st.cell.workspace
    axis, line, sign = {
        "front": ("x", ws.x_min, 1), "back": ("x", ws.x_max, -1),
        "right": ("y", ws.y_min, 1), "left": ("y", ws.y_max, -1),
    }[edge]  # fmt: skip
    at = line + sign * metres
    if not (ws.x_min <= at <= ws.x_max if axis == "x" else ws.y_min <= at <= ws.y_max):
        return m.group(0)  # past the other edge: left to the rest (and reported)
    st.notes.append(f"read '{said}' as its centre at {axis} = {at:.3f} m (the {edge} edge of the "
                    f"workspace is at {axis} = {line:g} m)")  # fmt: skip
    return f" , at {axis} = {round(at, 4)} m , "


def _cube_bar(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "two towers joined by a row of 3 cubes on top": a beam across them, said — a row of
    loose cubes would not hold across the gap. Only over two supports named before."""
    before = m.string[: m.start()]
    if not re.search(r"\b(?:towers|pillars|posts|stacks|columns|legs)\b", before, re.I):
        return m.group(0)  # "a wall with a row on top": a row standing on it
    st.notes.append(f"read '{_said(m)[0]}' as a beam across the tops: a row of loose cubes "
                    "would not hold across the gap")  # fmt: skip
    return " with a beam across the top "


def _top_left(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "top left of the drawing", "in the bottom right corner": a plan seen from above with the
    robot at the bottom — top is the back, bottom the front."""
    said, groups = _said(m)
    side = "back" if groups[0] in ("top", "upper") else "front"
    st.notes.append(f"read '{said}' as the {side} {groups[1]} (seen from above, the robot at "
                    "the bottom)")  # fmt: skip
    before = m.string[: m.start()]
    placed = re.search(r"\b(?:the|at|in|on|its|their|each|every)\s*$", before, re.I)
    lead = "" if placed else " at the"
    return f"{lead} {side} {groups[1]}{groups[2]} "


def _centred_beside(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower behind it, lined up with the middle of the row": a structure set beside
    another stands centred on it already; with no such relation the words stay (and are
    reported if unused)."""
    clause = re.split(r"[.;]", m.string[: m.start()])[-1]
    if not re.search(
        r"\b(?:behind|in\s+front\s+of|beside|next\s+to|(?:left|right)\s+of)\b", clause, re.I
    ):
        return m.group(0)
    st.notes.append(f"read '{_said(m)[0]}' as centred on it (a structure beside another stands "
                    "centred on it)")  # fmt: skip
    return " "


_PARTS_SIZE = re.compile(
    r"\b(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes|blocks)\s+(?:high|tall|"
    r"long|wide|each|apiece)\b",
    re.IGNORECASE,
)
"""A size said in parts ("three cubes tall"): not the structures named."""


def _structures_before(m: re.Match[str]) -> bool:
    """The clause before `m` names separate structures in the plural ("four towers of 2"),
    not parts ("nine cubes")."""
    clause = re.split(r"[.;]|\bthen\b", m.string[: m.start()])[-1]
    if re.search(r"\b\d+\s*(?:x|by)\s*\d+\s+(?:blocks|slabs|pads)\b", clause, re.I):
        return True  # "four 2x2 blocks in a square": blocks of their own, not cubes
    clause = _PARTS_SIZE.sub(" ", clause)  # "six towers, three cubes tall, in 3 rows of 2"
    nouns = _PLURAL_STRUCTURE.findall(clause)
    return bool(nouns) and nouns[-1].lower() not in ("cubes", "blocks", "things", "ones", "rows")


def _array_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a 2 x 3 array of 2-high stacks": six stacks, in 2 rows of 3."""
    said, groups = _said(m)
    n = int(groups[0]) * int(groups[1])
    st.grid = (int(groups[0]), int(groups[1]), said)
    high = f" of {groups[2]}" if groups[2] else ""
    return f" {n} {groups[3]}{high} "


def _top_end(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a wall with a tower of 2 on top of its left end": on top of it, at that end of its top
    (it stood in the table's left region, beside the wall, silently)."""
    said, groups = _said(m)
    side = "back" if groups[0] == "rear" else groups[0]
    st.anchors.append(("on_top_of", f"{side} end"))
    st.notes.append(f"read '{said}' as on top of it, at its {side} end")
    return " on top "


def _top_corner(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a column standing on its rear left corner": on top of the structure, at that corner
    of its top face; "on the back left corner" alone is the table's."""
    said, groups = _said(m)
    if "its" not in said.lower().split() and " of " not in said.lower():
        return m.group(0)
    corner = f"{'back' if groups[0] in ('back', 'rear') else 'front'} {groups[1]} corner"
    st.anchors.append(("on_top_of", corner))
    st.notes.append(f"read '{said}' as on top of it, at its {corner}")
    return " on top "


def _not_touching(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "not touching", "spaced out": a part's width apart — unless a gap is already said
    ("150 mm apart, not touching"), which keeps them apart as it is."""
    said = _said(m)[0]
    if st.gap_m is not None or st.span_m is not None:
        st.notes.append(f"'{said}': holds, the gap said keeps them apart")
        return " "
    st.notes.append(note.format(said))
    if re.search(r"\bin\s+a\s+(?:row|line)\s*,?\s*$", m.string[: m.start()], re.I):
        return " , spaced 5 cm apart "  # "3 pyramids, in a row, not touching": no row of its own
    return " spaced 5 cm apart "


def _corners(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a cube in each corner of the table": one copy in each corner region. Without "of
    the table" only when no other structure is named (then the corners may be its own)."""
    what = m.group(1).strip()
    rest = (m.string[: m.start()] + " " + m.string[m.end() :]).lower()
    head = re.sub(  # "tower of 2", "tower of three": its size aside
        r"\s+(?:of\s+)?(?:\d+|two|three|four|five|six|seven|eight|nine|ten)(?:\s+\w+)?$", "", what
    )
    if re.search(r"\b(?:with|and|on|of)\b", head, re.IGNORECASE) or (
        not m.group(2) and any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", rest))
    ):
        return m.group(0)  # "a slab with a cube on every corner": the slab's corners
    what = re.sub(r"^(?:an?|one)\s+", "", what, flags=re.IGNORECASE)
    if re.fullmatch(r"(?:single\s+)?(?:cube|block|brick|part)s?", what, re.IGNORECASE):
        what = "1-cube tower"  # one part, not a default structure
    corners = ("back left", "back right", "front left", "front right")
    st.notes.append(f"read '{m.group(0).strip()}' as one in each corner of the table")
    return " " + " and ".join(f"a {what} in the {c} corner" for c in corners) + " "


def _neither_side(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "not left, not right": centred on that axis; "not at the back or the front": the same
    front to back. Two sides of different axes ("not left or back") have no one reading."""
    said, groups = _said(m)
    pair = {groups[0], groups[1]}
    if pair not in ({"left", "right"}, {"front", "back"}):
        return m.group(0)
    axis = "across the table (y)" if "left" in pair else "front to back (x)"
    st.notes.append(f"read '{said}' as centred {axis}")
    placed = re.search(r"\b(?:centre|center|middle|left|right|front|back)\b", m.string[m.end() :])
    return " " if placed else " in the centre "


def _neg_place(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "do not put the pyramid on the left": the pyramid on the other side."""
    said, groups = _said(m)
    side = lx.OPPOSITE_SIDE[groups[2]]
    st.notes.append(f"read '{said}' as on the {side}")
    return f" {groups[0]} {groups[1]} on the {side} "


def _at_most(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "don't make the pillars taller than 2": the most allowed is what is built."""
    said, groups = _said(m)
    st.notes.append(f"read '{said}' as at most {groups[1]}: built {groups[1]} high")
    return f" , {groups[1]} high "


def _below(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "keep it under six bricks tall", "fewer than 5 steps": the most below the bound."""
    said, groups = _said(m)
    bound = words_to_numbers([groups[0]])[0]
    unit, what = groups[1].strip(), groups[2].strip()
    limit = f"{bound} {unit}" if unit in _MM else bound
    if not bound.isdigit():
        return m.group(0)
    most = int(bound) - 1
    if unit in _MM:
        most = -(-int(bound) * _MM[unit] // 50) - 1  # whole 5 cm parts strictly below
        unit = "cubes"
    return _bounded(m, st, said, most, unit, what, f"the most below {limit}")


def _within(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "no taller than 177.8 mm", "at most 18 cm high": the whole parts within the bound."""
    said, groups = _said(m)
    value, unit = (groups[0], groups[1]) if groups[0] else (groups[2], groups[3])
    most = int(float(value) * _MM[unit] / 50 + 1e-9)  # whole 5 cm parts, not above it
    return _bounded(m, st, said, most, "cubes", "high", f"the most within {value} {unit}")


def _bounded(
    m: re.Match[str], st: ReadState, said: str, most: int, unit: str, what: str, why: str
) -> str:
    """The most a bound allows, as the size to build (or said to be nothing buildable)."""
    what = "high" if what in ("tall", "in height") else what
    if not what.endswith("s") and what != "high":
        what += "s"
    if most < 1:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': nothing can be built below that")
        return " "
    roofed = [
        w for w in re.findall(r"[a-z]+", m.string.lower())
        if lx.SHAPE_WORDS.get(w) in ("bridge", "canopy")
    ]  # fmt: skip
    pillars = re.search(r"\b(?:pillars?|legs?|posts?)\b", m.string, re.I)
    if what == "high" and roofed and not pillars:
        # the whole gate stays below the bound: its pillars one part lower, under the beam
        if most < 2:
            return m.group(0)
        st.notes.append(
            f"read '{said}' as the whole {roofed[0]} at most {most} high: pillars {most - 1} high"
        )
        return f" , {most - 1} high "
    size = f"{most} {what}" if what != "high" else f"{most} {unit + ' ' if unit else ''}high"
    st.notes.append(f"read '{said}' as {size} ({why})")
    return f" , {size} "


_MM = {"cm": 10, "mm": 1, "centimetres": 10, "centimeters": 10, "m": 1000}


def _cannot(m: re.Match[str], st: ReadState, why: str) -> str:
    """Words asking for what SDI cannot build: material, with why, and cut from the text."""
    said = _said(m)[0]
    st.material.append(said)
    st.notes.append(f"ignored '{said}': {why}")
    return " "


def _unsupported(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "floating above the table", "down into the table": nothing SDI builds can do that."""
    return _cannot(
        m, st, "every structure stands on the table, resting on it or on parts below it; "
        "nothing can float, go below the table or stand on the robot or a person",
    )  # fmt: skip


def _pointed(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "put a tower um over there": a place pointed at, which SDI cannot see."""
    if re.search(r"\b(?:left|right|front|back|centre|center|middle|corner|x\s*=?\s*\d)", st.command,
                 re.IGNORECASE):  # fmt: skip
        st.notes.append(f"read '{_said(m)[0]}' as the place said")  # "… on the right, over there"
        return " "
    why = "a place pointed at, which SDI cannot see; say where (e.g. 'on the left', 'at x 40 cm')"
    return _cannot(m, st, why)


def _impossible(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "two towers in the same spot", "on top of itself", "a tall short tower": what no
    layout can be, material with why."""
    said = _said(m)[0].lower()
    if "same" in said:
        why = "two structures cannot stand in the same place; say where each goes"
    elif "itself" in said:
        why = "a structure cannot stand on, in or around itself; name the other structure"
    else:
        why = "the sizes contradict each other; say one size"
    return _cannot(m, st, why)


def _corner_named(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower of 2 on the top left corner" of a block: on a corner; which one SDI cannot
    choose, so the side named is reported."""
    said, groups = _said(m)
    named = [w for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())
             if w in lx.SHAPE_WORDS or w in lx.PART_WORDS]  # fmt: skip
    if len(named) < 2:
        return m.group(0)  # "a tower on the back left corner": the table's corner
    side = re.sub(r"[\s-]+", " ", groups[0]).replace("rear", "back").split()
    if len(side) == 2 and side[1] in ("left", "right"):
        return f" on its {side[0]} {side[1]} corner "  # "on the back left corner": that one
    st.material.append(f"the {groups[0]} corner")
    st.notes.append(f"ignored '{groups[0]}' of '{said}': SDI stands it on one corner, not a "
                    "corner it can choose; say 'on one corner' if any will do")  # fmt: skip
    return " on one corner of it "


def _stair_end(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower of 3 at its low end", "at the foot of the stairs", "touching its high end":
    beside that end of the staircase (which end follows the way it climbs)."""
    said = _said(m)[0]
    if not re.search(r"\b(?:stair|stairs|staircase|steps?)\b", m.string, re.IGNORECASE):
        return m.group(0)  # "at the top end of the wall": no staircase named
    touches = said.lower().startswith(("against", "touching"))
    if touches and re.match(r"\s*,?\s*(?:a|an|one|two|three|the)\s", m.string[m.end() :], re.I):
        return m.group(0)  # "against its tall end a tower of five": said before what it places
    high = re.search(r"\b(?:(?:high|higher|highest|upper|tall|taller)\s+end|(?:top|highest|upper|"
                     r"tallest)\s+(?:step|stair|tread))\b", said, re.I)
    st.stair_end = "high" if high else "low"
    st.notes.append(f"read '{said}' as beside the staircase's {st.stair_end} end")
    if m.group(0).lstrip().startswith(","):
        return " "  # "tower 3 next to a 3 step staircase, low end": the relation is said
    of = re.search(r"\bof\s+(the\s+\w+)\s*$", said, re.IGNORECASE)
    touching = " touching " if touches else " "
    return f" next to {of.group(1) if of else 'it'}{touching}"


def _in_the_u(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a single cube standing in the gap of the U": SDI has no place inside a U's opening (the
    cube stood beside it, silently); "a ring with a tower in its hollow": inside it; with
    neither named, the words are left as they were."""
    if not re.search(r"\bu\b(?:[\s-]*shaped?)?|\bhorseshoe\b", m.string, re.IGNORECASE):
        ring = re.search(r"\b(?:ring|enclosure|fence|pen|frame|corral|castle)\b", m.string, re.I)
        return " inside it " if ring else m.group(0)  # "a ring with a tower in its hollow"
    return _cannot(m, st, "SDI cannot stand a structure inside a U's opening; it stands "
                          "beside the U")  # fmt: skip


def _beam_on_beam(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "then add a second beam on top of the first": a bridge carries one beam a span."""
    return _cannot(m, st, "a bridge or arch carries one beam on each span; SDI lays no beam on "
                          "another")  # fmt: skip


_KEYED = {"length": "long", "len": "long", "width": "wide", "depth": "deep", "height": "high",
          "thickness": "thick"}  # fmt: skip


def _keyed_size(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "depth: 15cm": the size with the dimension word the key names."""
    return f" {m.group(2)} {_KEYED[m.group(1).lower()]} , "


def _relative(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "one of 7 and one of 2 fewer": the number said last before it, changed."""
    said, groups = _said(m)
    base = _said_last(m)
    n = words_to_numbers([groups[0]])[0]
    if base is None or not n.isdigit():
        return m.group(0)
    value = base + (int(n) if groups[1] == "more" else -int(n))
    if value < 1:
        return m.group(0)
    st.notes.append(f"read '{said}' as {value} ({base} {groups[1]} {n})")
    return f" {value} "


COUNTED = re.compile(
    r"(?<!\bof\s)\b(?:\d+|two|three|four|five|six|seven|eight|nine|ten)\s+(?=(?:[a-z]+\s+)?(?:"
    + "|".join(sorted(STRUCTURE_PLURALS, key=len, reverse=True))
    + r")\b)",
    re.IGNORECASE,
)
"""A number that counts structures ("two towers"), not a size a comparison starts from ("a
tower of four blocks": its parts)."""


def _said_last(m: re.Match[str]) -> int | None:
    """The last number said before the match (the size a comparison starts from); for a
    height ("a cube taller") or a length, the last number said as one, when one was."""
    for compared, said_as in (("taller|higher|shorter|lower|tall|high", "high|tall"),
                              ("longer|long", "long")):  # fmt: skip
        if re.search(rf"\b(?:{compared})\b", m.group(0), re.I):
            sizes = re.findall(
                r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?\s+)?"
                rf"(?:{said_as})\b",
                m.string[: m.start()],
                re.I,
            )
            if sizes:
                return int(words_to_numbers([sizes[-1].lower()])[0])
    told = COUNTED.sub(" ", m.string[: m.start()])  # "two towers, one twice as tall": no size
    before = re.findall(r"[a-z]+|\d+", told.lower())
    if before and before[-1] in ("one", "a"):
        before = before[:-1]  # "beside it one half its height": the one being compared
    said = [w for w in words_to_numbers(before) if w.isdigit()]
    return int(said[-1]) if said else None


def _compared(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower of 3, and next to it one twice as tall", "another with one less", "a second
    one a cube taller": the number said last before it, changed."""
    said, groups = _said(m)
    base = _said_last(m)
    number = r"(?:\d+|" + "|".join(NUMBER_WORDS) + r")"
    read = [(at, v) for w, v in st.compared if (at := m.string.rfind(w, 0, m.start())) >= 0]
    at, gave = max(read, default=(-1, None))
    if gave is not None and not re.search(rf"\b{number}\b", m.string[at + 1 : m.start()], re.I):
        # "another, one shorter, … then another, one shorter again": from the size the
        # comparison before gave, no number said since (its own words were the base)
        base = gave
    if base is None:
        return m.group(0)
    sizes = re.findall(rf"\bof\s+{number}\b|\b{number}\s+(?:cubes?\s+)?(?:high|tall|long|wide)\b",
                       m.string[: m.start()], re.I)  # fmt: skip
    if re.match(r"\s+as\s+the\s+first\b", m.string[m.end() :], re.I) and len(sizes) != 1:
        return m.group(0)  # "… as the first": the size said last is the first's only alone
    if re.search(r"\bmake\s+(?:it|them|the\s+\w+(?:\s+one)?)\s*$", m.string[: m.start()], re.I):
        return m.group(0)  # "then make it one higher": a change of that structure (`modify`)
    if groups[1] == "height":  # "one half its height": a new structure, not "double its height"
        before = m.string[: m.start()].lower()
        prev = re.findall(r"[a-z]+", before)[-1:]
        other = re.search(r"\b(?:another|other|second|one\s+more)\b[^,.;]*(?:,\s*it)?[^,.;]*$",
                          before)  # fmt: skip  # "the other tower, it has double of the height"
        if not other and (not prev or (prev[0] not in ("one", "a") and
                                       prev[0] not in lx.SHAPE_WORDS)):  # fmt: skip
            return m.group(0)
    if len(groups) == 4 and groups[3]:  # the second form: "a cube taller"
        groups = groups[2:]
    word = groups[0] or "1"  # "a cube taller"
    factor = FACTORS.get(word)
    times = re.fullmatch(r"(\w+)\s+times", word)
    if times and words_to_numbers([times.group(1)])[0].isdigit():
        factor = float(words_to_numbers([times.group(1)])[0])
    if factor is not None:
        value = base * factor
    else:
        n = words_to_numbers([word])[0]
        if not n.isdigit():
            return m.group(0)
        sign = 1 if groups[1] in ("more", "taller", "higher", "longer", "bigger") else -1
        value = base + sign * int(n)
    if value < 1 or value % 1:
        return m.group(0)
    st.notes.append(f"read '{said}' as {int(value)} (from the {base} said before)")
    st.compared.append((m.group(0), int(value)))
    if groups[1] in _HEIGHT_WORDS:
        return f" {int(value)} high "
    if groups[1] in ("long", "longer", "wide", "wider"):  # "the other twice as long": 6 long
        dims = list(re.finditer(rf"\b({number})\s*(?:by|x)\s*({number})\b", m.string[: m.start()],
                                re.I))  # fmt: skip
        copy = re.search(r"\b(?:another|a\s+second|the\s+other|one\s+more)\s+\w+\s*,?\s*$",
                         m.string[: m.start()], re.I)  # fmt: skip
        if dims and copy:
            # "a slab three by four and another slab half as long": 3 by 2 (the 3 was lost)
            a, b = (int(v) for v in words_to_numbers([dims[-1].group(1), dims[-1].group(2)]))
            if base == b:
                return f" {a} by {int(value)} "
        return f" {int(value)} {groups[1].removesuffix('er')} "
    return f" of {int(value)} "


_HEIGHT_WORDS = ("tall", "high", "taller", "higher", "shorter", "lower", "height")


def _operation(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "nine minus four", "3 times 2": the number it comes to."""
    said, groups = _said(m)
    a, b = (words_to_numbers([g])[0] for g in (groups[0], groups[2]))
    if not (a.isdigit() and b.isdigit()):
        return m.group(0)
    op = groups[1].split()[0]
    value = {"plus": int(a) + int(b), "minus": int(a) - int(b), "times": int(a) * int(b),
             "multiplied": int(a) * int(b)}[op]  # fmt: skip
    if value < 1:
        return m.group(0)
    st.notes.append(f"read '{said}' as {value}")
    return f" {value} "


def _not_axis(m: re.Match[str], st: ReadState, note: str) -> str:
    said, groups = _said(m)
    other = "front to back" if groups[0].split()[0] in ("left", "side") else "left to right"
    st.notes.append(f"read '{said}' as running {other}")
    return f" running {other} "


def _one_layer(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "two rows of four, 1 layer": what a floor is anyway; said of a wall or a block, its
    height."""
    before = [lx.SHAPE_WORDS.get(w) for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())]
    stacked = [f for f in before if f in ("wall", "block", "tower", "enclosure", "castle")]
    if stacked:
        return " , 1 high "
    st.notes.append(f"'{_said(m)[0]}': one layer, as built")
    return " "


def _parts_out(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "leave out the middle cube on the top row": single parts SDI cannot leave out."""
    return _cannot(
        m, st, "SDI builds each structure whole and cannot leave single parts out; describe "
        "the shape that remains instead",
    )  # fmt: skip


def _region_all(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "keep everything in the left half": a region for every structure that has none."""
    said, groups = _said(m)
    st.region_all = groups[0]
    st.notes.append(f"read '{said}' as every structure on the {groups[0]}")
    return " , "


def _keep_off(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "Reject if any part is within 10 cm of the front edge": every structure on the other
    side of the table."""
    said, groups = _said(m)
    side = lx.OPPOSITE_SIDE[groups[0]]
    st.region_all = st.region_all or side
    st.notes.append(f"read '{said}' as every structure on the {side}")
    return " , "


def _xyz(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "at (0.50, 0.30, 0.70)": x and y place it; a z above the table cannot be built."""
    x, y, z = m.group(1), m.group(2), m.group(3)
    if abs(float(z)) > 1e-9:
        said = m.group(0).strip()
        st.material.append(said)
        st.notes.append(
            f"ignored z = {z} in '{said}': every structure stands on the table (z = 0); "
            "say where it stands on the table, or stack it on another structure"
        )
    return f" ( {x} , {y} ) "


_COUNTED_NOUN = re.compile(
    r"\s*(?:[a-z]+\s+)?(?:towers|stacks|walls|rows|columns|pillars|pyramids|blocks|slabs|staircases|"
    r"bridges|rings|things|ones|cubes|steps|levels|layers)\b",
    re.IGNORECASE,
)


def _maybe(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "three, maybe four": the first number; "not too tall, maybe four?": the only one."""
    said, groups = _said(m)
    value = words_to_numbers([groups[0]])[0]
    before = m.string[: m.start()]
    if not value.isdigit():
        return m.group(0)
    after = m.string[m.end() : m.end() + 12]
    number = r"\d|\b(?:" + "|".join(NUMBER_WORDS) + r")\b"
    if re.search(number, before, re.I) or re.match(r"\s*(?:or|to|-)\s*(?:" + number + ")", after):
        st.notes.append(note.format(said))
        return " "
    if _COUNTED_NOUN.match(m.string[m.end() : m.end() + 30]):
        return f" {value} "  # "maybe two towers": a count said with a hedge
    st.notes.append(f"read '{said}' as {value}, the only number said")
    return f" , {value} "


def _edge(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "as far forward as it can go": against that edge of the workspace."""
    said, groups = _said(m)
    side = {"forward": "front", "forwards": "front", "backward": "back", "backwards": "back"}
    st.notes.append(f"read '{said}' as against that edge of the workspace")
    return f" at the {side.get(groups[0], groups[0])} edge "


def _delegated(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "whatever size works", "your call on sizes": SDI chooses, with its defaults."""
    said = _said(m)[0]
    st.delegated = said
    st.notes.append(f"'{said}': left to SDI, which uses its default sizes")
    return " , "


def _every_side(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a solid block 100 mm on every side": a block's sides all that size (a flat family's
    "5 on each side" is read by the grammar)."""
    said_words = re.findall(r"[a-z]+", m.string.lower())
    if not any(lx.SHAPE_WORDS.get(w) == "block" for w in said_words):
        return m.group(0)
    v = m.group(1).strip()
    st.notes.append(f"read '{m.group(0).strip()}' as {v} long, wide and high")
    return f" {v} long , {v} wide and {v} high "


_NEXT_ONE = re.compile(
    r"(?:\s*,\s*(?:and\s+)?|\s+and\s+)(?:one|(?:the\s+other|another|the\s+(?:second|third|"
    r"fourth|last))(?:\s+one(?=\s+(?:at|on|in|to|behind|beside|next|near|by)\b))?)\b"
    # "one at the front one at the back": the next item said with no comma
    r"|(?:(?<=front)|(?<=back)|(?<=left)|(?<=right)|(?<=rear)|(?<=middle)|(?<=centre)|(?<=corner))"
    r"\s+one(?=\s+(?:at|on|in)\s+the\s+(?:front|back|left|right|far|near|rear|middle|centre)\b)",
    re.IGNORECASE,
)


_SIZE_LEAD = re.compile(
    r"(?:\d+|two|three|four|five|six|seven|eight)\s*(?:(x|by)\s*\d+|(?:cubes?\s+)?(high|tall|long))\b",
    re.IGNORECASE,
)
"""A list item that starts with a size ("2x2", "4 high on the left")."""


def _size_kind(item: str) -> str:
    """Which size a list item gives: "by" (2x2), "high" (4 high, 4 tall) or "long"."""
    m = _SIZE_LEAD.match(item)
    if m is None:
        return ""
    return "by" if m.group(1) else "high" if m.group(2).lower() in ("high", "tall") else "long"


_ONE_THE_OTHER = re.compile(
    r"((?:\w+\s+)?(?:behind|in\s+front\s+of|next\s+to|beside|on\s+top\s+of|on|atop|"
    r"(?:to\s+the\s+)?(?:left|right)\s+of))\s+the\s+other(?:\s+one)?(.*)",
    re.IGNORECASE,
)


_COUNTED_SIZE = re.compile(
    r"\b(?:two|three|four|five|six|\d+)\s+(?:(?:identical|matching|equal|similar)\s+)?"
    r"(?:\d+\s*(?:x|by|×)\s*)+$",
    re.IGNORECASE,
)


def _distribute(m: re.Match[str], st: ReadState, note: str) -> str:
    """One item per copy ("two towers of 3, one at the far left, one at the far right"), each
    with the shared description; left as it is when the items do not match the count."""
    if _COUNTED_SIZE.search(m.string[: m.start()]):
        return m.group(0)  # "two 2 x 2 x 2 blocks, one behind the other": the last size, no count
    said, groups = _said(m)
    two = groups[0].lower() == "both" or groups[0].lower().startswith("a ")  # a couple of
    n_ = "2" if two else words_to_numbers([groups[0]])[0]
    size = re.sub(r"^\s*,\s*|\s+(?:each|apiece)\s*$", " ", (m.group(4) or "").rstrip())
    noun = f"{m.group(2) or ''}{m.group(3)}{size.rstrip()}"
    # "two towers: the tower of 4 on the right, the 2 on the left": one of each size
    listing = re.sub(r"(^|,\s*(?:and\s+)?|\band\s+)(?:the|an?)\s+(?:" + re.escape(m.group(3))
                     + r"\s+of\s+)?(?=(?:\d+|two|three|four|five|six|seven|eight)\s+(?:on|at|in|"
                     r"to)\s)", r"\1one of ", m.group("items"), flags=re.IGNORECASE)  # fmt: skip
    first = re.match(r"one|the\s+first(?:\s+one)?", listing, re.IGNORECASE)
    if first is None:
        # "two slabs, 2x2 and 3x3, side by side", "2 towers: 4 high on the left, 2 high on
        # the right": a size each, in turn; the words after them are about all of them
        listed = re.split(r"\s*,\s*(?:and\s+)?|\s+and\s+", listing)
        sized = list(itertools.takewhile(lambda i: bool(_SIZE_LEAD.match(i)), listed))
        tail = ", ".join(listed[len(sized) :])
        kinds = {_size_kind(i) for i in sized}
        if not n_.isdigit() or int(n_) != len(sized) or size.strip() or len(kinds) > 1:
            return m.group(0)  # "two walls, 4 long and 3 high": both, each that long and high
        st.notes.append(f"read '{said}' as {n_} {m.group(3)}s, one each")
        return " " + " and ".join(f"a {noun} {i}" for i in sized) + (f", {tail} " if tail else " ")
    items = [i.strip(" ,") for i in _NEXT_ONE.split(listing[first.end() :])]
    pair = _ONE_THE_OTHER.fullmatch(items[0]) if len(items) == 1 else None
    if pair and n_ == "2":
        # "two towers of 3, one behind the other": the second placed by the first
        st.notes.append(f"read '{said}' as two {m.group(3)}s, the second {pair.group(1)} the first")
        return f" a {noun} and a {noun} {pair.group(1)} it {pair.group(2)} "
    if not n_.isdigit() or int(n_) != len(items) or not all(items):
        return m.group(0)
    st.notes.append(f"read '{said}' as {n_} {m.group(3)}s, one each")
    together = m.group("together") or ""  # "two walls side by side, one 3 long and …"
    return " " + " and ".join(f"a {noun} {item}" for item in items) + f"{together} "


def _more_like(m: re.Match[str], st: ReadState, note: str) -> str:
    shapes = [w for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())
              if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]  # fmt: skip
    if not shapes:
        return m.group(0)
    noun = shapes[-1] if shapes[-1].endswith("s") else shapes[-1] + "s"
    return f" {_said(m)[1][0]} identical {noun} "


def _copies_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "ring 4x4 3 high, 2 of them": the structure described, that many times."""
    said, groups = _said(m)
    n = words_to_numbers([groups[0]])[0]
    if not n.isdigit() or int(n) < 2:
        return m.group(0)
    shapes = [w for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())
              if w in lx.SHAPE_WORDS and w not in lx.SELDOM_STRUCTURES]  # fmt: skip
    if not shapes or shapes[-1].endswith("s"):
        return m.group(0)  # "4-high pillars, two of them": two pillars, not two bridges
    st.notes.append(f"read '{said}' as {n} of the structure described")
    noun = shapes[-1] if shapes[-1] not in lx.AMBIGUOUS_SHAPES else lx.SHAPE_WORDS[shapes[-1]]
    return "".join(f" and another {noun}" for _ in range(int(n) - 1)) + " "


def _more_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a tower of 3 and 2 more towers", "… and three more like it": copies added to the one
    described (2 more towers after a tower are three towers)."""
    said, groups = _said(m)
    n = words_to_numbers([groups[0]])[0]
    noun = groups[1] if len(groups) > 1 else ""
    family = lx.SHAPE_WORDS.get(noun) if noun else None
    shapes = families_said(m.string[: m.start()])
    if not n.isdigit() or not 1 <= int(n) <= 20 or not shapes:
        return m.group(0)
    family = family or shapes[-1]
    if family != shapes[-1]:
        return m.group(0)  # "a wall and 2 more towers": towers of their own
    st.notes.append(f"read '{said.split(',')[0]}' as {n} more {family}s like the one before")
    places = [g for g in m.groups()[2:4] if g] if len(m.groups()) >= 4 else []
    if len(places) == 2 and n == "2":  # "two more like it, one to its left and one to its right"
        return f" and another {family} {places[0]} and another {family} {places[1]} "
    return "".join(f" and another {family}" for _ in range(int(n))) + " "


def _times(m: re.Match[str], st: ReadState, note: str) -> str:
    said, groups = _said(m)
    factor = {"twice": 2, "double": 2, "three times": 3, "thrice": 3, "half": 0.5}
    base_n = words_to_numbers([groups[2]])[0]
    times = re.fullmatch(r"(\w+)\s+times", groups[0])
    k_: float = factor.get(re.sub(r"\s+", " ", groups[0]), 0)
    if times and words_to_numbers([times.group(1)])[0].isdigit():
        k_ = int(words_to_numbers([times.group(1)])[0])
    if not base_n.isdigit() or not k_ or (int(base_n) * k_) % 1:
        return m.group(0)
    value = int(int(base_n) * k_)
    st.notes.append(f"read '{said}' as {value} {groups[1]}")
    return f" {value} {groups[1]} "


def _layer_on_top(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "then a second layer" (a layer goes on top), and "then a third" after layers."""
    if m.group(1):
        said = m.group(1)
    elif re.search(r"\b(?:layer|level|tier|course)\b", m.string[: m.start()], re.IGNORECASE):
        said = "another layer"
    else:
        return m.group(0)
    st.notes.append(f"read '{m.group(0).strip(' ,')}' as a layer on top of the one before")
    size = m.group(2) if m.lastindex and m.lastindex >= 2 and m.group(2) else None
    return f"{said} {size} on top" if size else f"{said} on top"  # "a second tier, 2 by 2, …"


def _across_them(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "across the two", "from one tower across to the other one": across them."""
    return f" {m.group(1) or 'across'} them "


def _rise_order(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "ascending from right to left": a staircase climbs that way; several structures stand
    in a line getting taller that way."""
    said, groups = _said(m)
    if {groups[0], groups[1]} not in ({"left", "right"}, {"front", "back"}):
        return m.group(0)
    if re.search(r"\b(?:stair\w*|steps?|flight)\b", m.string, re.IGNORECASE):
        return f" climbing to the {groups[1]} "
    st.order = (said, "rise", groups[1])
    return " "


_ALONG = {"back": "along x", "left": "along y", "front": "along x rotated 180 degrees",
          "right": "along y rotated 180 degrees"}  # fmt: skip
"""A staircase climbs towards +x along x and +y along y (left = +y, back = +x)."""


def _climb(m: re.Match[str], st: ReadState, note: str) -> str:
    side = next(side for side in _said(m)[1] if side)  # "climbing to the back", "up to the back …"
    return f" {_ALONG[side.lower()]} "


def _stairs_up(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "stairs x4, up to the back": the staircase as said, climbing that way."""
    return f"{m.group(1)} {_ALONG[m.group(2).lower()]} "


def _rows(m: re.Match[str], st: ReadState, note: str) -> str:
    said_n = [words_to_numbers([g])[0] for g in _said(m)[1][:2]]
    if all(v.isdigit() for v in said_n) and int(said_n[0]) % int(said_n[1]) == 0:
        return f" {int(said_n[0]) // int(said_n[1])} by {said_n[1]} "
    return m.group(0)


def _rows_of(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "2 rows with 7 in each", "4 rows, 3 cubes per row", "4 rows and 3 columns": 4 rows of
    3 (a wall's rows are its courses)."""
    groups = [g for g in _said(m)[1] if g]
    walls = re.search(r"\b(?:wall|walls|fence)\b", m.string[: m.start()], re.IGNORECASE)
    said = f" {groups[0]} {'levels' if walls else 'rows'} of {groups[1]} "
    if not re.search(r"\b(?:in\s+each|each|apiece)\s*$", m.group(0), re.IGNORECASE):
        st.notes.append(f"read '{m.group(0).strip()}' as{said.rstrip()}")
    return said


def _layers(m: re.Match[str], st: ReadState, note: str) -> str:
    said, groups = _said(m)
    st.notes.append(note.format(said))
    layers = {"double": 2, "triple": 3, "quadruple": 4}[groups[0]]
    return f"{layers}-layer"


def _not_climb(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "stairs that do not go up towards the back": they climb the other way; "don't make
    them go towards me, make them go up to the right": the way said after it."""
    said, groups = _said(m)
    side = groups[0] or "front"  # "towards me", "to the robot": the robot's side
    later = re.search(
        r"\b(?:(?:go(?:es|ing)?\s+)?up|climb\w*|ris\w*|ascend\w*)\s+(?:to(?:wards?)?|toward)\s+"
        r"(?:the\s+)?(left|right|front|back)\b",
        m.string[m.end() :],
        re.IGNORECASE,
    )
    if later and later.group(1).lower() != side:
        st.notes.append(f"'{said}': holds, it climbs towards the {later.group(1).lower()}")
        return " , "
    opposite = lx.OPPOSITE_SIDE[side]
    st.notes.append(f"read '{said}' as climbing towards the {opposite}")
    return f" climbing towards the {opposite} "


def _offset(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "16 inches out from the robot": x from the robot's base; "8 inches left of the middle
    line", "10 cm behind the centre": from the middle of the workspace."""
    said, groups = _said(m)
    metres = float(groups[0]) * _MM[groups[1]] / 1000
    ws = st.cell.workspace
    if groups[2]:
        y = (ws.y_min + ws.y_max) / 2 + (metres if groups[2] == "left" else -metres)
        where = f"y = {y:.4g} m"
    elif groups[3]:
        x = (ws.x_min + ws.x_max) / 2 + (-metres if groups[3].startswith("in") else metres)
        where = f"x = {x:.4g} m"
    else:
        where = f"x = {metres:.4g} m"  # the robot stands at x = 0
    st.notes.append(f"read '{said}' as at {where}")
    return f" at {where} "


def _plate_position(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "in position B2 of a 3 x 3 plate": on top of the plate; a structure on another stands
    centred on it, so only the centre position is kept, any other is reported."""
    said, groups = _said(m)
    row, col = ord(groups[0].upper()) - ord("A"), int(groups[1]) - 1
    rows, cols = (int(groups[3]), int(groups[4])) if groups[3] else (0, 0)
    if rows and 2 * row + 1 == rows and 2 * col + 1 == cols:
        st.notes.append(f"read '{said.strip()}' as on top of it, at its centre")
    else:
        st.material.append(f"position {groups[0].upper()}{groups[1]}")
        st.notes.append(f"ignored position {groups[0].upper()}{groups[1]}: a structure set on "
                        "another stands centred on it")  # fmt: skip
    return f" on top of {groups[2]} "


def _unmade(m: re.Match[str], st: ReadState, note: str) -> str:
    """A part left off that the families cannot leave off ("stop before the top cube"): said."""
    said = m.group(0).strip(" ,")
    st.material.append(said)
    st.notes.append(f"ignored '{said}': SDI builds the structure whole; say its size instead")
    return " "


def _cross_arms(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "a cross with arms 2 cubes long": arms from the middle cube, so each bar is 5."""
    said, groups = _said(m)
    arm = int(words_to_numbers([groups[0]])[0])
    if groups[1]:  # "arms 100 mm each from the centre cube": in parts
        metres = arm * lx.UNITS_M[groups[1]]
        parts = metres / st.cell.cube[0]
        if abs(parts - round(parts)) > 0.05 or round(parts) < 1:
            return m.group(0)
        arm = round(parts)
    st.notes.append(f"read '{said}' as arms of {arm} from the middle cube: bars of {2 * arm + 1}")
    return f"cross {2 * arm + 1} wide "


def _wall_edge(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "near to wall on back" with no wall named before: the table's back edge."""
    said, groups = _said(m)
    if re.search(r"\bwalls?\b", m.string[: m.start()], re.IGNORECASE):
        return m.group(0)  # a wall named before: that one
    side = groups[0] or groups[1]
    st.notes.append(f"read '{said}' as at the {side} (no wall is named: the table's edge)")
    return f" at the {side} "


def _progression(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "four towers; first from 1 cube, every next one cube higher": 1, 2, 3 and 4."""
    said, groups = _said(m)
    said_step = "1" if groups[3] == "a" else groups[3]
    n, first, step = (int(words_to_numbers([g])[0]) for g in (groups[0], groups[2], said_step))
    heights = [first + k * step for k in range(n)]
    listed = ", ".join(str(h) for h in heights[:-1]) + f" and {heights[-1]}"
    st.notes.append(f"read '{said}' as {groups[1]} of {listed}")
    return f" {n} {groups[1]} of {listed}"


def _series(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "four towers, one of each height from one to four", "three towers going up by one each
    starting at two": the heights of the series, one after another."""
    g = {k: words_to_numbers([v.lower()])[0] for k, v in m.groupdict().items() if v}
    n, first = int(g["n"]), int(g["first"])
    step = 1 if g.get("step", "1") == "a" else int(g.get("step", "1"))
    if "last" in g and int(g["last"]) - first + 1 != n:
        return m.group(0)  # "four towers from one to six": no series of one step
    heights = [first + k * step for k in range(n)]
    listed = ", ".join(str(h) for h in heights[:-1]) + f" and {heights[-1]}"
    kind = m.group("kind")
    unsaid = " (one cube more each: the step was not said)" if "step" in m.re.groupindex and (
        "step" not in g and "last" not in g
    ) else ""  # fmt: skip
    st.notes.append(f"read '{m.group(0).strip()}' as {kind} of {listed}{unsaid}")
    where = m.groupdict().get("dir") or ""
    return f" {n} {kind} of {listed}" + (f", {where.strip()}" if where else "")


def _part_size(m: re.Match[str], st: ReadState, note: str) -> str:
    """ "stack half a dozen of the 2-inch blocks": a part size said is the cell's own part
    when it is within 15 % of it (else left for the reading to report)."""
    said, groups = _said(m)
    mm = float(groups[0]) * _MM[groups[1]]
    cube = st.cell.cube[0] * 1000
    if abs(mm - cube) > 0.15 * cube:
        return m.group(0)
    st.notes.append(f"read '{said}' as the cell's {cube:g} mm {groups[2]}")
    return f" of {groups[2]} "


# Rewrites whose replacement is computed: the `_REWRITES` entry names one of these.
HANDLERS: dict[str, Handler] = {
    "{pointed}": _pointed,
    "{compared_one}": _compared_one,
    "{split}": lambda m, st, note: _split(m, st),
    "{no_stack}": _no_stack,
    "{no_beams}": _no_beams,
    "{placement}": _placement,
    "{bend}": _bend,
    "{extra_cube}": _extra_cube,
    "{arith}": _arith,
    "{from_centre}": _from_centre,
    "{relative}": _relative,
    "{keyed_size}": _keyed_size,
    "{copies_of}": _copies_of,
    "{neither_side}": _neither_side,
    "{neg_place}": _neg_place,
    "{rise_order}": _rise_order,
    "{series}": _series,
    "{top_corner}": _top_corner,
    "{top_end}": _top_end,
    "{not_touching}": _not_touching,
    "{unsupported}": _unsupported,
    "{impossible}": _impossible,
    "{beam_on_beam}": _beam_on_beam,
    "{in_the_u}": _in_the_u,
    "{stair_end}": _stair_end,
    "{corner_named}": _corner_named,
    "{at_most}": _at_most,
    "{corners}": _corners,
    "{square_base}": _square_base,
    "{bottom_count}": _bottom_count,
    "{pyramid_base}": _pyramid_base,
    "{base_of}": _base_of,
    "{extreme_at}": _extreme_at,
    "{named_in_middle}": _named_in_middle,
    "{compared}": _compared,
    "{more_of}": _more_of,
    "{halfway}": _halfway,
    "{also_a}": _also_a,
    "{negative}": _negative,
    "{arrangement}": _arrangement,
    "{array_of}": _array_of,
    "{grid_of}": _grid_of,
    "{centred_beside}": _centred_beside,
    "{top_left}": _top_left,
    "{cube_bar}": _cube_bar,
    "{from_edge}": _from_edge,
    "{as_big_as}": _as_big_as,
    "{than_named}": _than_named,
    "{all_different}": _all_different,
    "{listing}": _listing,
    "{listing_said}": _listing_said,
    "{in_a_row}": _in_a_row,
    "{layers_word}": _layers_word,
    "{height_list}": _height_list,
    "{operation}": _operation,
    "{more_like}": _more_like,
    "{distribute}": _distribute,
    "{not_axis}": _not_axis,
    "{edge}": _edge,
    "{maybe}": _maybe,
    "{xyz}": _xyz,
    "{region_all}": _region_all,
    "{parts_out}": _parts_out,
    "{one_layer}": _one_layer,
    "{delegated}": _delegated,
    "{below}": _below,
    "{within}": _within,
    "{part_size}": _part_size,
    "{offset}": _offset,
    "{wall_edge}": _wall_edge,
    "{cross_arms}": _cross_arms,
    "{unmade}": _unmade,
    "{plate_position}": _plate_position,
    "{progression}": _progression,
    "{keep_off}": _keep_off,
    "{not_climb}": _not_climb,
    "{every_side}": _every_side,
    "{times}": _times,
    "{climb}": _climb,
    "{stairs_up}": _stairs_up,
    "{across_them}": _across_them,
    "{layer_on_top}": _layer_on_top,
    "{rows}": _rows,
    "{rows_of}": _rows_of,
    "{layers}": _layers,
}
