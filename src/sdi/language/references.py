"""References to structures named before: pronouns and definite nouns ("it", "them", "the
base"), picks ("the first one", "the smaller tower"), copies ("another tower", "a second row")
and later clauses that say more about an earlier structure ("the staircase has 3 steps")."""

from __future__ import annotations

import re

from sdi.language.nouns import (
    BASES,
    COPY_WORDS,
    GENERIC,
    LEAD_VERBS,
    PRONOUNS,
    beam_only,
    shape_alternation,
)
from sdi.language.state import Phrase, PhraseRelation, ReadState
from sdi.spec import lexicon as lx
from sdi.spec.structure_spec import SpecDraft, StructureDraft

_SIZES = ("count", "length", "width", "height", "steps", "span", "spans", "dims",
          "length_m", "width_m", "height_m", "gap_m", "part")  # fmt: skip


def _sized(s: StructureDraft) -> dict[str, object]:
    """The sizes a structure was given (its part kind aside)."""
    return s.model_dump(include=set(_SIZES) - {"part"}, exclude_defaults=True)


def copies(
    spec: SpecDraft, text: str, st: ReadState, earlier: list[StructureDraft] | None = None
) -> SpecDraft:
    """ "another tower", "a second row": the sizes of the one named before (in this phrase,
    or the last of that family named earlier)."""
    if not set(re.findall(r"[a-z]+", text.lower())) & COPY_WORDS:
        return spec
    out = list(spec.structures)
    for k, s in enumerate(out):
        said = s.model_dump(include=set(_SIZES), exclude_defaults=True)
        spacing = {k: v for k, v in said.items() if k == "gap_m"}  # how far apart: no size
        said = {k: v for k, v in said.items() if k != "gap_m"}
        pool = [*(earlier or []), *out[:k]]
        first = next((o for o in reversed(pool) if o.shape == s.shape), None)
        if first is None:
            continue
        if said and set(said) <= {"height", "height_m"}:
            # "a 3x3 slab 4 high, then another one 2 high": its footprint, a height of its own
            footprint = first.model_dump(include={"length", "width", "dims", "length_m", "width_m"},
                                         exclude_defaults=True)  # fmt: skip
            if footprint:
                out[k] = s.model_copy(update=footprint)
                st.notes.append(f"another {s.shape}: the same footprint as the first, "
                                + ", ".join(f"{key} {v}" for key, v in said.items()))  # fmt: skip
                continue
        if said and not _BUT.search(text):
            same = all(getattr(first, key) == v for key, v in said.items())
            if same and s.axis is None and first.axis:  # "a second row of 4": the same way
                out[k] = s.model_copy(update={"axis": first.axis})
            continue
        # "same again but back right, and 2 layers": the first's sizes, what is said instead
        turned = {"axis": first.axis} if s.axis is None and first.axis else {}  # the same way
        out[k] = s.model_copy(
            update={**first.model_dump(include=set(_SIZES)), **said, **spacing, **turned}
        )
        if said:
            changed = ", ".join(f"{key} {v}" for key, v in said.items())
            st.notes.append(f"another {s.shape}: the same size as the first but {changed}")
        else:
            st.notes.append(f"another {s.shape}: the same size as the first")
    return spec.model_copy(update={"structures": tuple(out)})


_BUT = re.compile(r"\b(?:but|except|only|instead)\b", re.IGNORECASE)
"""'another one but 2 high': a copy with a size changed (without it, a size said is the copy's
own: 'another tower of 5')."""


def _of_family(family: str, before: list[Phrase], structures: list[StructureDraft]) -> list[int]:
    """The structures of `family` the phrases before built."""
    return [
        i for q in before if q.count and q.spec is not None
        for i in range(q.first, q.first + q.count) if structures[i].shape == family
    ]  # fmt: skip


def definite(
    p: Phrase, spec: SpecDraft, before: list[Phrase], structures: list[StructureDraft]
) -> int | None:
    """ "the staircase has 3 steps" after a staircase was named: the index of that one."""
    m = re.match(
        r"^\W*(?:(?:put|place|set|move|stand)\s+)?(?:the|that|this)\s+(\w+)(?:\s+(\w+))?",
        p.text,
        re.IGNORECASE,
    )
    if not m or len(spec.structures) != 1:
        return None
    family = lx.SHAPE_WORDS.get(m.group(1).lower()) or lx.SHAPE_WORDS.get(
        (m.group(2) or "").lower()
    )
    if family is None or family != spec.structures[0].shape:
        return None
    matches = _of_family(family, before, structures)
    said = spec.structures[0].model_dump(exclude_defaults=True, exclude={"shape"})
    if len(matches) > 1 and said:
        # "two towers of 4 and a tower of 2. Put the tower of 2 between them": the one that size
        matches = [
            i for i in matches
            if all(structures[i].model_dump(exclude_defaults=True).get(k) == v
                   for k, v in said.items())
        ]  # fmt: skip
    if len(matches) != 1:
        return None
    known = structures[matches[0]].model_dump(exclude_defaults=True, exclude={"shape"})
    words_ = set(re.findall(r"[a-z]+", p.text[: m.end()].lower()))  # "the T on the left": it
    if any(known.get(k) not in (None, v) for k, v in said.items()) or words_ & (
        set(lx.REGION_WORDS) | COPY_WORDS | {"other", "first", "second", "third", "last"}
    ):
        return None  # "then the right tower of 2": another tower
    return matches[0]


def possessive(
    p: Phrase, spec: SpecDraft, before: list[Phrase], structures: list[StructureDraft]
) -> int | None:
    """ "Place a tower at … The coordinates are the centre of the tower's footprint", "Make
    the tower's top flat": a phrase about a part of the one structure of that family named
    before is about that one, never a new one."""
    m = re.search(r"\b(?:the|that|this)\s+(\w+)'s?\b", p.text, re.IGNORECASE)
    if not m or "'" not in m.group(0) or len(spec.structures) != 1:
        return None
    family = lx.SHAPE_WORDS.get(m.group(1).lower())
    if family is None or family != spec.structures[0].shape:
        return None
    matches = _of_family(family, before, structures)
    return matches[0] if len(matches) == 1 else None


def described(
    p: Phrase, spec: SpecDraft, before: list[Phrase], structures: list[StructureDraft]
) -> int | None:
    """ "A staircase on the right. It has 5 steps.", "A ring at the back. It should be 4 by
    4.": a sentence led by a pronoun that gives sizes describes the structure named last before
    it — it was a second one, of the family the sizes suggest."""
    if not _PRONOUN_SAYS.match(p.text) or len(spec.structures) != 1:
        return None
    if re.search(r"\b(?:not|never|no|nor)\b|n't", p.text, re.IGNORECASE):
        return None  # "It should not be more than 3 high": a bound, read elsewhere
    if not _sized(spec.structures[0]):
        return None
    built = [q for q in before if q.spec is not None and q.count and not q.undone]
    if not built or built[-1].clause == p.clause:
        return None
    idx = built[-1].first + built[-1].count - 1
    named = {
        lx.SHAPE_WORDS[w] for w in re.findall(r"[a-z]+", p.text.lower())
        if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES
    }  # fmt: skip
    if named - {structures[idx].shape}:
        return None  # "It has a tower beside it": another structure, named
    said, own = spec.structures[0].shape, structures[idx].shape
    footprint = said in ("grid", "block") and own in ("enclosure", "castle", "grid", "block")
    return idx if said == own or footprint else None  # "a ring … It should be 4 by 4"


_PRONOUN_SAYS = re.compile(
    r"^\W*(?:and\s+)?(?:it|this|that)\s*(?:'s|has|is|should|must|needs|will|shall|would|can|"
    r"ought)\b",
    re.IGNORECASE,
)


def named_ahead(
    p: Phrase, spec: SpecDraft, before: list[Phrase], structures: list[StructureDraft]
) -> int | None:
    """ "next to the pyramid a tower of 5, pyramid 3 levels": a bare family name with sizes,
    after a structure of that family was only pointed at ("the pyramid"), gives that one's
    sizes; it is not a second one."""
    m = re.match(r"^\W*(\w+)", p.text)
    if not m or len(spec.structures) != 1:
        return None
    family = lx.SHAPE_WORDS.get(m.group(1).lower())
    said = _sized(spec.structures[0])
    if family is None or family != spec.structures[0].shape or not said:
        return None
    pointed = [
        i for q in before if q.count and q.spec is not None
        and (m2 := re.match(r"^\W*(?:(?:the|that|this)\s+)?(\w+)(?:\W|$)", q.text, re.IGNORECASE))
        and lx.SHAPE_WORDS.get(m2.group(1).lower()) == family
        for i in range(q.first, q.first + q.count)
        if structures[i].shape == family
        and not _sized(structures[i])
    ]  # fmt: skip
    same = [i for i, s in enumerate(structures) if s.shape == family]
    return pointed[0] if len(pointed) == 1 and same == pointed else None


def named_again(
    p: Phrase, spec: SpecDraft, before: list[Phrase], structures: list[StructureDraft]
) -> int | None:
    """ "The kids want to see a bridge … could you do one with pillars about three cubes
    tall": a structure named in passing (no size, no place) and then described in a later
    clause is one structure, not two — unless the later words make it another ("another",
    "second", a count)."""
    # a count word before a part noun ("four steps", "two levels") is a size, not a count
    counted = re.sub(r"\b(?:two|three|four)\s+(?=(?:steps?|levels?|layers?|tiers?|cubes?|"
                     r"blocks?|storeys?|floors?|courses?|high|tall|long|wide)\b)", "",
                     p.text.lower())  # fmt: skip
    if len(spec.structures) != 1 or set(re.findall(r"[a-z]+", counted)) & (
        COPY_WORDS | {"two", "three", "four", "more", "also", "other", "both", "each"}
    ):
        return None
    said = spec.structures[0]
    if not _sized(said):
        return None
    same = [i for i, s in enumerate(structures) if s.shape == said.shape]
    if len(same) != 1:
        return None
    first = structures[same[0]]
    owner = next((q for q in before if q.count and q.first <= same[0] < q.first + q.count), None)
    # "… a tall column. … column 4 high": a size said only by a word is no size of its own (said
    # again as "a column …", it is a new mention)
    vague = (
        owner is not None
        and not re.match(r"\W*(?:an?|one)\b", p.text, re.I)
        and not re.search(r"\d|\b(?:one|two|three|four|five|six|seven|eight|nine|ten)\b",
                          owner.text, re.I)
    )  # fmt: skip
    bare = (vague or not _sized(first)) and not first.model_dump(
        include={"region", "at_x", "at_y"}, exclude_defaults=True
    )
    if owner is None or owner.clause == p.clause or owner.count != 1 or not bare:
        return None
    return same[0]


_SECOND = re.compile(
    r"\b(?:and|plus|also|then|with|&)\s+(?:then\s+)?(?:a|an|one|some)\b|\b(?:another|second|"
    r"both|each|pair|couple|several|more|twins?|others?|extra|again|too|as\s+well)\b",
    re.IGNORECASE,
)
"""Words that make a second noun of one family a second structure ("a wall and a wall")."""
_PLACES = ("region", "at_x", "at_y", "axis")
_THE_GROUP = re.compile(
    r",\s*(?:and\s+)?(?:(?:the|each|both|all|every)(?:\s+of\s+the)?\s+)+(?:two\s+|three\s+)?"
    r"([a-z]+)\b",
    re.IGNORECASE,
)
"""', the walls …', ', each wall …': the structures counted before, named again."""


def named_twice(spec: SpecDraft, text: str, st: ReadState) -> SpecDraft:
    """ "Tower, 250 mm tall, single column", "a big wall at the back, 8 long and 4 high, it's
    her castle wall": one structure sized and named again in the same phrase, with no word that
    makes it a second one (two towers and two walls were built); "two walls, each wall 3 long":
    the group's size. (A name set off by a dash or said as a shape is taken out of the words
    before they are read: `normalise._named_twice`.)"""
    if len({s.shape for s in spec.structures}) != 1:
        return spec
    *group, last = spec.structures
    again = _THE_GROUP.search(text)
    if (
        len(group) >= 2
        and again
        and lx.SHAPE_WORDS.get(again.group(1).lower()) == last.shape
        and _sized(last)
        and not any(_sized(s) for s in group)
    ):
        # "two walls, the walls 3 long and 3 high", "…, each wall 3 long": the group's size
        sizes = last.model_dump(include={*_SIZES, *_PLACES}, exclude_defaults=True)
        st.notes.append(f"read '{text[again.start():].strip(' ,')}' as the size of each "
                        f"{last.shape} named before it")  # fmt: skip
        return spec.model_copy(
            update={"structures": tuple(s.model_copy(update=sizes) for s in group)}
        )
    if len(spec.structures) != 2:
        return spec
    said = re.findall(r"[a-z]+", text.lower())
    plural = [w for w in said if w.endswith("s") and lx.SHAPE_WORDS.get(w[:-1])]
    if plural or _SECOND.search(text) or set(said) & COPY_WORDS or said.count("a") > 1:
        return spec  # "a tower, a tower of 5": listed, two
    a, b = spec.structures
    if not (_sized(a) or _sized(b)) or set(_sized(a)) & set(_sized(b)):
        return spec  # "tower 3, tower 5": a size each, two
    if a.model_dump(include=set(_PLACES), exclude_defaults=True) and b.model_dump(
        include=set(_PLACES), exclude_defaults=True
    ):
        return spec  # each placed: two, somewhere each
    more = b.model_dump(include={*_SIZES, *_PLACES}, exclude_defaults=True)
    st.notes.append(f"read the {a.shape} named twice in '{text.strip()}' as one")
    return spec.model_copy(update={"structures": (a.model_copy(update=more),)})


def same_as_before(p: Phrase, spec: SpecDraft, before: list[Phrase]) -> str | None:
    """ "Steps: 5. Shape: staircase.": a bare family name in a later clause names the one
    structure described before, not a second one."""
    if len(spec.structures) != 1 or _sized(spec.structures[0]):
        return None
    said = set(re.findall(r"[a-z]+", p.text.lower()))
    if said & (COPY_WORDS | {"and", "also", "more", "two", "three", "other", "plus", "then"}):
        return None
    built = [q for q in before if q.spec is not None and q.count]
    if not built or built[-1].clause == p.clause or built[-1].count != 1:
        return None
    prev = built[-1].spec
    assert prev is not None
    shape = spec.structures[0].shape
    described = _sized(prev.structures[-1])
    return shape if prev.structures[-1].shape == shape and described else None


_SPANNING_PARTS = frozenset(
    {"beam", "beams", "lintel", "roof", "top", "deck", "span", "plank", "tabletop", "slab"}
)
"""Parts of a bridge, an arch or a table that a later clause may name for the whole."""


_THE_BEAM = re.compile(
    r"\W*(?:on\s+)?(?:the|that|this|its)\s+(?:(?:middle|centre|center|top|midpoint)\s+of\s+"
    r"(?:the\s+)?)?(?:beam|lintel|plank|girder|crossbar|deck)\b\W*?(?:,(?P<rest>.*))?$",
    re.IGNORECASE,
)
"""'the beam', 'the middle of the lintel': the top of what a beam said before made."""
_MIDDLE = re.compile(
    r"(?:(?:over|in|at|on)\s+)?(?:the\s+)?(?:middle|centre|center|mid-?span|midpoint)|centred|"
    r"centered",
    re.IGNORECASE,
)
"""Where on a beam a structure said on it stands: its middle, where SDI stands it."""


def the_beam(
    text: str, earlier: list[Phrase], structures: list[StructureDraft], rels: list[PhraseRelation]
) -> tuple[int, str] | None:
    """ "… a beam across them, then a cube on the middle of the beam": the phrase whose
    structure "the beam" of `text` names — the towers the last beam said before it lies on (they
    become a bridge), else the last bridge, arch or canopy built — and any words said after it
    that are not where on the beam (they are reported)."""
    said = _THE_BEAM.match(text)
    if said is None:
        return None
    rest = (said.group("rest") or "").strip()
    rest = "" if _MIDDLE.fullmatch(rest) else rest
    owner = _beam_owner(earlier, structures, rels)
    return None if owner is None else (owner, rest)


def _beam_owner(
    earlier: list[Phrase], structures: list[StructureDraft], rels: list[PhraseRelation]
) -> int | None:
    k = len(earlier)
    laid: list[tuple[int, int | None]] = [
        (r.object, r.subject) for r in rels if r.kind == "joined" and r.object is not None
    ]
    laid += [(r.subject, r.object) for r in rels if r.kind == "on" and r.subject < k
             and beam_only(earlier[r.subject].text)]  # fmt: skip
    laid = [(beam, on) for beam, on in laid if beam < k]
    if laid:
        beam, on = max(laid, key=lambda said: said[0])
        if on is None:  # "…, a beam on top": on the structures said before it
            on = next((j for j in range(beam - 1, -1, -1) if earlier[j].count), None)
        return None if on is None else resolve(earlier, on)
    spans = ("bridge", "arch", "canopy")
    return next((j for j in range(k - 1, -1, -1) if earlier[j].count and any(
        structures[i].shape in spans for i in range(earlier[j].first, earlier[j].first
                                                     + earlier[j].count))), None)  # fmt: skip


def refers_to(p: Phrase, before: list[Phrase], partner: int | None = None) -> int | None:
    """A phrase that only points at an earlier one ("it", "them", "the base"). `partner`: the
    phrase this one is related to ("put a tower in the middle of it"): "it" is another one."""
    said = p.text.lower().replace(",", " ").split()
    led = False
    while said and said[0] in LEAD_VERBS:
        said, led = said[1:], True  # "put the cube": the cube named before
    rest = " ".join(said)
    words_ = [w for w in said if w not in ("the", "of")]
    if not words_ or len(words_) > 6:
        return None
    built = [
        j
        for j, q in enumerate(before)
        if (q.spec is not None or q.ref is not None) and not q.undone
    ]
    others = [j for j in built if partner is None or resolve(before, j) != partner]
    built = others or built
    if words_[0] == "that":  # "… next to it, and another one next to that": the one just named
        named = [j for j in built if before[j].spec is not None]
        built = named or built
    if not built:
        return None
    sides = [w for w in words_[1:] if w in ("left", "right", "front", "back")]
    trailing = all(
        w in lx.REGION_WORDS or w in ("on", "to", "at", "in", "its", "side", "hand", "of")
        for w in words_[1:]
    )
    if words_[0] in PRONOUNS and (len(words_) <= 2 or trailing) and len(words_) <= 6 and not led:
        p.side = sides[0] if sides else None
        if words_[0] in ("them", "these", "those"):
            many = [j for j in built if before[j].count > 1]
            return resolve(before, many[-1] if many else built[-1])
        return resolve(before, built[-1])
    if len(words_) <= 3 and words_[-1] in _SPANNING_PARTS and rest.startswith(("the", "its")):
        # "on the middle of the beam", "the roof": the part of a bridge, arch or table named
        for j in reversed(built):
            spec = before[resolve(before, j)].spec
            if spec is not None and any(s.shape in ("bridge", "arch", "canopy")
                                        for s in spec.structures):  # fmt: skip
                return resolve(before, j)
    bare = (  # "on slab", "on slab, ctr": the slab named before
        said[0] in lx.SHAPE_WORDS and not said[0].endswith("s")
        and all(w in lx.REGION_WORDS for w in said[1:])
    )  # fmt: skip
    if bare:
        words_ = said[:1]  # "slab, center": on the slab, at its centre
    if (
        len(words_) <= 2
        and words_[-1] in GENERIC | BASES | set(lx.SHAPE_WORDS) | {"cube", "block", "brick"}
        and (rest.startswith(("the", "its")) or bare)  # "in front of wall": the wall named
    ):
        noun = words_[-1]
        if noun in ("base", "foundation", "bottom", "first", "platform", "plinth"):
            return resolve(before, built[0])
        if noun in ("cube", "block", "brick", "part"):
            # "the cube": the structure of one part named before
            for j in reversed(built):
                spec = before[resolve(before, j)].spec
                if spec is not None and any(one_cube(s) for s in spec.structures):
                    return resolve(before, j)
            return None
        family = lx.SHAPE_WORDS.get(noun)
        for j in reversed(built):
            spec = before[resolve(before, j)].spec
            if spec is not None and any(s.shape == family for s in spec.structures):
                if sized_otherwise(rest, before[resolve(before, j)].text):
                    continue  # "the small tower in front of the big tower": another one
                return resolve(before, j)
        if family is None:
            return resolve(before, built[-1])  # "the structure", "the other one"
        return None  # "the tower" named for the first time: a structure of its own
    return None


_LARGE = frozenset({"big", "bigger", "large", "larger", "tall", "taller", "high", "higher", "long"})
_SMALL = frozenset({"small", "smaller", "little", "short", "shorter", "low", "lower", "tiny"})


def sized_otherwise(said: str, earlier: str) -> bool:
    """`said` ("the big tower") gives a size word the opposite of the one the `earlier` phrase
    was named with ("the small tower"), or another height: it is another structure."""
    words_, named = (set(re.findall(r"[a-z]+", t.lower())) for t in (said, earlier))
    high, was = (set(re.findall(r"\b(\d+)-high\b", t)) for t in (said, earlier))
    large, small = _LARGE & words_, _SMALL & words_  # (named both ways: one of those)
    return bool(
        (large and _SMALL & named and not large & named)
        or (small and _LARGE & named and not small & named)
        or (high and was and not high & was)  # "the 2-high tower in front of the 5-high tower"
    )


_PICK = re.compile(
    r"^(?:\w+\s+)?the\s+(first|second|third|fourth|last|smaller|smallest|larger|largest|bigger|"
    r"biggest|taller|tallest|shorter|shortest|lower|higher|middle|centre|center|left|right|front|"
    r"back|tall|big|large|short|small|little|high|low)(?:[\s-]?hand(?:ed)?)?(?:\s+(?:one|"
    + shape_alternation()
    + r"))?$",
    re.IGNORECASE,
)


def one_cube(s: StructureDraft) -> bool:
    """A structure of one part: a tower one high or a row one long."""
    return (s.shape == "tower" and s.height == 1) or (s.shape == "row" and s.length == 1)


def pick_structure(text: str, structures: list[StructureDraft], among: list[int]) -> int | None:
    """ "the first one", "the smaller one", "the taller tower": one of the structures named
    in earlier clauses (`among`; all so far when empty)."""
    m = _PICK.match(text.strip())
    if not m or not structures:
        return None
    among = among or list(range(len(structures)))
    word = m.group(1).lower()
    positive = {"tall": "tallest", "high": "tallest", "big": "biggest", "large": "biggest",
                "short": "shortest", "low": "shortest", "small": "smallest", "little": "smallest"}
    if word in positive:  # "the tall one" of those named: the tallest ("the tall" is no pick)
        if not m.group(0).lower().rstrip().endswith(("one", *lx.SHAPE_WORDS)):
            return None
        word = positive[word]
    order = {"first": 0, "second": 1, "third": 2, "fourth": 3}
    if word in order:
        return among[order[word]] if order[word] < len(among) else None
    if word == "last":
        return among[-1]
    if word in ("left", "right", "front", "back"):
        # "a row on the left, a row on the right; a tower of 2 on the left one": the one
        # placed on that side ("not the left. the back." is a place)
        if m.end(1) == len(text.strip()) or m.group(0).lower().startswith("not"):
            return None
        sided = [i for i in among if word in (structures[i].region or "").split()]
        return sided[0] if len(sided) == 1 else None
    if word in ("middle", "centre", "center"):
        # "three blocks side by side, with a cube on the middle one": the middle of an odd
        # number alike (the cube named with them is not one of them)
        runs: list[list[int]] = []
        for i in among:  # runs of structures alike, one after the other
            if runs and structures[runs[-1][-1]] == structures[i] and runs[-1][-1] == i - 1:
                runs[-1].append(i)
            else:
                runs.append([i])
        odd = [r for r in runs if len(r) >= 3 and len(r) % 2]
        return odd[-1][len(odd[-1]) // 2] if odd else None

    def size(s: StructureDraft) -> float:
        tall = s.height or s.steps or (s.height_m or 0) / 0.05 or 1
        wide = (s.length or 1) * (s.width or 1)
        return float(tall if word in ("taller", "tallest", "shorter", "shortest", "lower",
                                      "higher") else tall * wide)  # fmt: skip

    sizes = [size(structures[i]) for i in among]
    big = word in ("larger", "largest", "bigger", "biggest", "taller", "tallest", "higher")
    target = max(sizes) if big else min(sizes)
    if sizes.count(target) != 1:
        return None
    return among[sizes.index(target)]


def resolve(phrases: list[Phrase], j: int) -> int:
    while phrases[j].ref is not None:
        j = phrases[j].ref  # type: ignore[assignment]
    return j
