"""Accounting (during slot filling). Every word of a command is used or reported: words the
reading left unused go to `ReadState.ignored`, and material ones (`sdi.language.words`) to
`ReadState.material`, which makes the reading incomplete. When nothing buildable is found,
the error says what was understood."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from sdi.errors import SpecError
from sdi.language import words
from sdi.language.nouns import BEAMS
from sdi.language.state import ReadState
from sdi.language.typos import english_frequency
from sdi.spec import lexicon as lx
from sdi.spec.grammar import parse_phrase
from sdi.spec.numbers import NUMBER_WORDS

if TYPE_CHECKING:
    from spacy.tokens import Doc, Token


# Words that make a clause more than chatter (ambiguous shape nouns like "well" do not).
_USABLE = (
    set(lx.SHAPE_WORDS) | set(lx.SIZE_WORDS) | set(lx.DIMENSION_WORDS) | set(lx.REGION_WORDS)
    | lx.LEVEL_WORDS | lx.STEP_WORDS | lx.PART_WORDS | set(lx.UNITS_M) | BEAMS
    | words.SIGNIFICANT  # "too much, half of that": a change of a size, never chatter
    | {"side", "sides", "corner", "corners", "edge", "edges"}  # "keep it on the starboard side"
    | {"peak", "apex", "summit"}  # "then a cube on the peak": on top
) - lx.AMBIGUOUS_SHAPES - {"well", "item", "items", "object", "objects", "unit"}  # fmt: skip


def is_chatter(text: str) -> bool:
    """A clause with nothing the Specifier could use ("The visitors arrive at 10")."""
    # "off to the side" is anywhere but the middle, no side in particular
    said = re.findall(r"[a-z]+|\d+", re.sub(r"\b(?:off\s+)?to\s+the\s+side\b", "", text.lower()))
    # "of five" left over is a number not used; "one, two, three, four" is counting aloud
    worded = any(w in NUMBER_WORDS for w in said) and not re.search(r"\bone\W+two\b", text, re.I)
    if (worded or any(w.isdigit() for w in said)) and not any(w in lx.PART_WORDS for w in said):
        return bool(
            re.search(r"\b(?:item|order|ticket|job|room|at|by|until|before|after)\b", text, re.I)
        )
    return not any(w in _USABLE for w in said)


def _attached(tok: Token) -> bool:
    """`tok` modifies a structure (or a part) in the parse, not the chatter around it."""
    seen = 0
    t = tok
    while seen < 8:
        if t.lower_ in lx.SHAPE_WORDS or t.lower_ in lx.PART_WORDS:
            return t.i != tok.i or tok.pos_ != "NOUN"
        if t.lower_ in ("for",) and t.dep_ == "prep":
            return False  # "for the demo", "for a teddy bear": a purpose
        if t.head.i == t.i:
            return False
        if t.dep_ in ("advcl", "intj", "parataxis", "discourse", "ccomp", "mark"):
            return False
        if t.dep_ == "relcl" and any(
            c.lower_ in ("could", "can", "would", "might") for c in t.children
        ):
            return False  # "a gateway a cube could pass under"
        t = t.head
        seen += 1
    return False


_BUILD_VERBS = frozenset({"make", "build", "construct", "create", "assemble", "stack", "erect"})
_GENERIC = frozenset({
    "something", "thing", "things", "structure", "shape", "object", "one", "construction",
    "build", "model", "copy", "version", "sculpture", "piece", "it", "them", "that", "this",
    "test", "demo", "try", "start", "go",
})  # fmt: skip


def _built_unknown(tok: Token, word: str) -> bool:
    """`tok` is the thing a build verb asks for ("make a fridge") and no structure or part."""
    return (
        tok.dep_ == "dobj"
        and tok.pos_ == "NOUN"
        and tok.head.lemma_.lower() in _BUILD_VERBS
        and word not in lx.SHAPE_WORDS
        and word not in lx.PART_WORDS
        and word not in BEAMS
        and word not in _GENERIC
        and word not in words.HARMLESS
        and not any(c.lower_ in lx.SHAPE_WORDS for c in tok.subtree if c.i != tok.i)
    )


_RARE = 10_000_000
"""A word English uses less often than this (of SymSpell's counts) is no everyday word: "aft",
"amidships", "bow" are; "time", "bit", "children" are not."""
_PLACE_NOUNS = frozenset({"side", "end", "corner", "edge", "half", "part", "quarter", "area",
                          "zone", "spot", "position", "place"})  # fmt: skip


def _where_to_build(tok: Token, word: str) -> bool:
    """`tok` tells where a structure goes in words SDI does not know: a noun used as an adverb of
    the verb that builds it ("put a mast right amidships", "lay a row fore and aft"), or a word
    that picks a place noun ("on the starboard side", "on the bow end")."""
    if word in words.HARMLESS or word in words.CONSULTED or word in lx.FILLER or tok.is_stop:
        return False
    if tok.dep_ in ("compound", "amod") and tok.head.lower_ in _PLACE_NOUNS:
        return tok.head.dep_ == "pobj" and tok.head.head.lower_ in ("on", "at", "to", "in", "along")
    adverbial = tok.dep_ == "npadvmod" or (tok.dep_ == "conj" and tok.head.dep_ == "npadvmod")
    verb = tok.head if tok.dep_ == "npadvmod" else tok.head.head
    return (
        adverbial
        and tok.pos_ in ("NOUN", "ADV")
        and english_frequency().get(word, 0) < _RARE  # not "this time", "children", "a bit"
        and verb.pos_ == "VERB"
        and tok.ent_type_ not in ("DATE", "TIME")
        and any(c.lower_ in lx.SHAPE_WORDS or c.lower_ in lx.PART_WORDS for c in verb.children)
    )


def _takes_away(tok: Token) -> bool:
    """`tok` is a verb that takes parts away ("take one corner cube away", "remove the top"):
    a change of what is built, never chatter."""
    lemma = tok.lemma_.lower()
    if tok.pos_ != "VERB":
        return False
    if lemma in ("remove", "delete", "subtract"):
        return True
    return lemma in ("take", "knock", "pull", "lift") and any(
        t.lower_ in ("away", "off", "out") for t in tok.doc[tok.i + 1 : tok.i + 6]
    )


_STUFF = frozenset({
    "glass", "stone", "wood", "metal", "steel", "iron", "plastic", "concrete", "gold", "silver",
    "paper", "card", "cardboard", "lego", "foam", "rubber", "ice", "sand", "clay", "marble",
    "copper", "brass", "aluminium", "aluminum", "timber", "crystal", "colour", "color",
})  # fmt: skip
"""What a structure is made of, or its colour: SDI builds in its own parts; said, it is material."""


def _names_its_use(tok: Token, word: str) -> bool:
    """`tok` is a noun naming what the structure it modifies is for ("fire ring", "lookout
    tower", "garden wall"): not a place ("corner tower"), a stuff ("glass tower") or a word SDI
    reads."""
    return (
        tok.pos_ in ("NOUN", "PROPN")
        and tok.dep_ == "compound"
        and tok.head.lower_ in lx.SHAPE_WORDS
        and tok.i + 1 == tok.head.i
        and tok.i > 0  # "Disregard pyramid": a verb the parser took for a noun
        and tok.doc[tok.i - 1].pos_ in ("DET", "NUM", "ADJ", "PRON")
        and word.isalpha()
        and english_frequency().get(word, 0) > 0  # an English word, not "signall"
        and word not in _PLACE_NOUNS
        and word not in _STUFF
        and word not in lx.SHAPE_WORDS
        and word not in lx.PART_WORDS
        and word not in lx.REGION_WORDS
    )


def _in_heading(tok: Token) -> bool:
    """`tok` is in a short heading that names what the words after its colon describe ("Signal
    box: a 2x2x2 block …", "Goods shed: a 3 by 4 enclosure …")."""
    doc = tok.doc
    colon = next((t.i for t in doc[:7] if t.text in (":", "—", "–", "--")), None)
    return (
        colon is not None
        and 0 < colon <= 4
        and tok.i < colon
        and tok.pos_ in ("NOUN", "PROPN", "ADJ")  # "Stepping stones: …"
        and not any(t.like_num for t in doc[:colon])
        and any(t.lower_ in lx.SHAPE_WORDS or t.lower_ in lx.PART_WORDS for t in doc[colon + 1 :])
    )  # ("Stepping stones: four single cubes in a line": the cubes are what it names)


def _also(tok: Token) -> bool:
    """`tok` ("too", "also") ends its clause and says "as well" ("and one on the right too"), not
    "too much" ("too tall", "not too many")."""
    doc = tok.doc
    after = doc[tok.i + 1] if tok.i + 1 < len(doc) else None
    last = after is None or after.is_punct or after.lower_ in ("and", "then")
    before = doc[tok.i - 1] if tok.i > 0 else None
    sized = before is not None and (  # "height too": the number two, misheard
        before.lower_ in lx.DIMENSION_WORDS
        or before.lower_ in lx.LEVEL_WORDS
        or before.lower_ in lx.STEP_WORDS
        or before.lower_ in ("height", "length", "width", "depth", "by", "x", "of", "is", "=")
    )
    return last and not sized and tok.head.pos_ not in ("ADJ", "ADV") and not (
        before is not None and before.pos_ in ("ADJ", "ADV") and before.lower_ != "right"
    )


def account(word: str, tok: Token | None, st: ReadState) -> None:
    if word in (",", ":", ";", "(", ")", "=", "+", "&", "*"):
        return
    pos = tok.pos_ if tok is not None else None
    numeric = word[:1].isdigit()
    if tok is None and not numeric and word not in words.CORRECTABLE | words.NEGATIONS:
        return  # a piece of a contraction ("we've" → "weve") or a symbol
    known = (
        (word in words.CORRECTABLE or word in words.NEGATIONS or numeric)
        and word not in words.HARMLESS
    ) or word in words.SIGNIFICANT
    if tok is not None and word in ("too", "also") and _also(tok):
        return  # "and one on the right too": as well, no size
    if tok is not None and _built_unknown(tok, word):
        # "can you make a fridge with legs of 2": what to build is a thing SDI does not know
        st.material.append(word)
        st.ignored.append(word)
        st.notes.append(f"ignored '{word}': what is asked for is not a structure SDI knows")
        return
    if tok is not None and not known and _where_to_build(tok, word):
        # "right amidships", "on the starboard side", "on the bow end": a place in words SDI
        # does not know — which place is not understood
        st.material.append(word)
        st.ignored.append(word)
        st.notes.append(f"ignored '{word}': says where to build, in words SDI does not know")
        return
    if tok is not None and not known and not _attached(tok) and not _takes_away(tok):
        if word not in words.HARMLESS and word not in words.CONSULTED:
            st.ignored.append(word)
            st.notes.append(f"ignored '{word}': not about the structure")
        return
    if tok is not None and word in words.NEGATIONS and not _attached(tok):
        st.ignored.append(word)
        return
    if (
        tok is not None
        and (not known or (word in lx.PART_WORDS and word not in lx.SHAPE_WORDS))
        and word.isalpha()
        and _in_heading(tok)
    ):  # ("Stepping stones: four single cubes …": the stones are the heading's)
        st.ignored.append(word)
        st.notes.append(f"read '{word}' as part of the heading that names what follows it")
        return
    if tok is not None and not known and _names_its_use(tok, word):
        # "a fire ring", "three lookout towers", "a camp gateway": a noun naming the
        # structure's use says nothing of its size, shape or place
        st.ignored.append(word)
        named = f"{word} {tok.head.text}"
        st.notes.append(f"read '{named}' as a {tok.head.lemma_.lower()}: '{word}' names its use, "
                        "with no size, shape or place in it")  # fmt: skip
        return
    if words.is_material(word, pos):
        st.material.append(word)
        st.ignored.append(word)
        st.notes.append(f"ignored '{word}': not used by the reading")
    elif word not in words.HARMLESS and word not in words.CONSULTED and word not in lx.FILLER:
        st.ignored.append(word)


def understood_summary(doc: Doc) -> dict[str, object]:
    out: dict[str, object] = {}
    shapes = [lx.SHAPE_WORDS[t.lower_] for t in doc if t.lower_ in lx.SHAPE_WORDS]
    if shapes:
        out["structures"] = shapes
    nums = [t.text for t in doc if t.like_num]
    if nums:
        out["numbers"] = nums
    parts = [t.lower_ for t in doc if t.lower_ in lx.PART_WORDS]
    if parts:
        out["parts"] = parts
    regions = [lx.REGION_WORDS[t.lower_] for t in doc if t.lower_ in lx.REGION_WORDS]
    if regions:
        out["regions"] = regions
    unknown = [
        t.text for t in doc if t.is_alpha and t.lower_ not in words.VOCABULARY and not t.is_stop
    ]
    if unknown:
        out["unknown_words"] = unknown[:20]
    return out


def no_structure(st: ReadState, doc: Doc, command: str) -> None:
    known = ", ".join(sorted(set(lx.SHAPE_WORDS.values())))
    understood = understood_summary(doc)
    try:
        parse_phrase(doc.text, st.cell)
    except SpecError as exc:
        if exc.understood and "not a usable count" not in str(exc):
            understood = {**understood, **exc.understood}
        elif "not a usable count" in str(exc):
            raise SpecError(str(exc), understood=understood) from None
    raise SpecError(
        "no structure recognised in the command; name one of: "
        + known
        + " (e.g. 'a tower of 4 cubes', 'a 3 by 3 grid on the left')",
        understood=understood,
    )
