"""Which words name a structure: word classes (pronouns, bases, beams, generic nouns, copy
words) and the tests that decide whether a noun phrase, or the object of a relation marker,
names a structure rather than a place, a space or one of a structure's own components."""

from __future__ import annotations

import re
from collections.abc import Collection
from typing import TYPE_CHECKING

from sdi.language import words
from sdi.spec import lexicon as lx

if TYPE_CHECKING:
    from spacy.tokens import Doc


PRONOUNS = {"it", "them", "this", "that", "these", "those", "one", "both"}


# Nouns that name a structure in a relation but not a family of their own.
GENERIC = {"platform", "slab", "plinth", "pedestal", "layer", "floor", "level", "tier",
            "structure", "thing", "one", "first", "last", "other"}  # fmt: skip


# "a ziggurat on a 3 by 3 base" is the ziggurat's own base; "on top of the base" is another
# structure (and so is "a base layer"): these nouns name a structure only after "on top of".
BASES = {"base", "foundation", "bottom", "footing", "footprint"}


BEAMS = {"beam", "beams", "plank", "planks", "lintel", "lintels", "girder", "girders", "bar",
         "crossbar", "crossbars", "slab", "bridge", "bridges", "arch", "roof", "deck",
         "span"}  # fmt: skip


LEAD_VERBS = {"put", "place", "set", "add", "make", "build", "stack", "lay", "position", "move"}


_ORDINALS = {"first", "second", "third", "fourth", "last", "other"}


_QUANTITY_NOUNS = {"pair", "couple", "set", "group", "bunch", "handful", "trio"}


_EMPTY = {"empty", "hollow", "open", "free", "blank"}


COPY_WORDS = {"second", "another", "same", "identical", "matching", "similar", "twin", "copy"}


_ONE = {"a", "an", "one", "single", "lone"}


SPACE_WORDS = {"space", "hole", "gap", "room", "opening", "void", "cavity", "interior", "area"}


def names_structure(doc: Doc, tokens: list[int]) -> bool:
    """The tokens name a structure (not a space: "a 2 by 2 space inside")."""
    if any(doc[i].lower_ in SPACE_WORDS | _EMPTY for i in tokens):
        return False
    return any(_is_structure_noun(doc, i) for i in tokens)


def _is_structure_noun(doc: Doc, k: int) -> bool:
    w = doc[k].lower_
    if w in ("cube", "block", "brick", "box") and doc[k - 1].lower_ in _ONE and k > 0:
        return True  # "around a single cube": one part is a structure too
    if (
        w in ("block", "brick", "box")
        and k >= 3
        and doc[k - 1].like_num
        and doc[k - 2].lower_ in ("x", "by")
        and doc[k - 3].like_num
    ):
        return True  # "on top of a 2x4 brick": a part that size is a structure
    if w in ("cubes", "blocks", "bricks") and any(
        doc[j].lower_ in ("pair", "couple", "both", "single", "separate", "individual", "loose")
        for j in range(max(0, k - 4), k)
    ):
        return True  # "a beam across a pair of single cubes": the cubes stand as pillars
    if w in lx.PART_WORDS and w not in ("block", "blocks"):
        return False
    if w in ("shape", "shaped") and k > 0 and doc[k - 1].lower_ in ("l", "u", "t", "plus", "cross"):
        return True  # "a U shape"
    if w in lx.LETTER_SHAPES and k + 1 < len(doc) and doc[k + 1].lower_ in lx.LETTER_SHAPE_TAILS:
        return True
    return w in lx.SHAPE_WORDS or w in GENERIC or w in BEAMS


def object_head(doc: Doc, start: int, end: int, strong: bool = True) -> tuple[int | None, bool]:
    """The noun a relation marker points at, and whether it names a structure (`strong`:
    the marker is "on top of", after which "the base" is a structure too)."""
    k = start
    empty = False
    while k < end:
        tok = doc[k]
        w = tok.lower_
        if w in _EMPTY:
            empty = True
        if (w in PRONOUNS or w in _ORDINALS) and (
            k + 1 >= end or doc[k + 1].pos_ not in ("NOUN", "PROPN", "NUM", "ADJ")
        ):
            break  # "on the smaller one", "in front of the second"
        if w in (",", ";", ":"):
            break  # "a ring 20 cm across, one cube high": no object after a comma
        if tok.pos_ in ("DET", "NUM", "ADJ", "ADV", "PUNCT", "SYM") or w in ("x", "by", "-"):
            k += 1
            continue
        if w in lx.SIZE_WORDS or (w in lx.REGION_WORDS and doc[k].dep_ in ("amod", "compound")):
            k += 1
            continue
        if w in _QUANTITY_NOUNS and k + 1 < end and doc[k + 1].lower_ == "of":
            k += 2  # "a pair of stacks", "a couple of towers"
            continue
        if (
            tok.dep_ == "compound"
            and k + 1 < end
            and doc[k + 1].pos_ in ("NOUN", "PROPN")
            and w not in lx.REGION_WORDS
        ):
            k += 1
            continue
        break
    if k >= end:
        return None, False
    w = doc[k].lower_
    if w in lx.REGION_WORDS or w in ("corner", "corners", "table", "edge", "side", "robot"):
        return k, False
    if w in ("each", "top") or (w == "other" and k > 0 and doc[k - 1].lower_ == "each"):
        return k, False  # "on top of each other"
    if empty:
        return k, False
    if w in PRONOUNS and (doc[k].pos_ in ("PRON", "DET", "NUM", "NOUN") or doc[k].dep_ == "pobj"):
        return k, True
    if w in _ORDINALS:
        return k, True
    if w in BASES:  # "a 3x3 base. … a cube on the base": the one said before
        named = any(t.lower_ in BASES or lx.SHAPE_WORDS.get(t.lower_) in ("grid", "block")
                    for t in doc[: max(0, k - 2)])  # fmt: skip
        named = named and w in ("base", "foundation", "footing")  # ("3 by 3 on the bottom")
        return k, strong or (named and doc[k - 1].lower_ in ("the", "that", "this"))
    return k, _is_structure_noun(doc, k)


STRUCTURE_PLURALS = frozenset(
    w for w in lx.SHAPE_WORDS if w.endswith("s") and w.isalpha() and w not in ("steps", "stairs")
)
"""Plural structure nouns that count structures ("two towers"; a staircase's "steps" size it)."""


_COMPONENTS = {
    "castle": {"enclosure", "wall", "tower", "row"},
    "canopy": {"tower", "canopy", "grid"},
    "bridge": {"tower"},
    "arch": {"tower"},
    "enclosure": {"wall"},
}


def is_component(doc: Doc, clause: list[int], marker: int, head: int) -> bool:
    """The object noun names a part of the structure before the marker ("on pillars")."""
    before = [lx.SHAPE_WORDS[doc[i].lower_] for i in clause if i < marker and
              doc[i].lower_ in lx.SHAPE_WORDS]  # fmt: skip
    family = lx.SHAPE_WORDS.get(doc[head].lower_)
    if not before or family is None:
        return False
    return family in _COMPONENTS.get(before[-1], set()) and doc[head].lower_.endswith("s")


_PURE_BEAMS = BEAMS - {"slab", "bridge", "bridges", "arch", "roof", "deck"}


def beam_only(text: str) -> bool:
    said = [w for w in re.findall(r"[a-z]+", text.lower()) if w not in words.HARMLESS]
    if re.search(r"\b(?:another|second|same|identical|copy)\b", text, re.IGNORECASE) and not (
        set(said) & _PURE_BEAMS
    ):
        return False  # "put another slab on top of it": a copy of the slab, not a beam
    return (
        bool(said)
        and all(w in BEAMS or w in lx.PART_WORDS for w in said)
        and any(w in BEAMS for w in said)
    )


def shape_alternation(*, exclude: Collection[str] = (), min_len: int = 1) -> str:
    """The structure words as a regex alternation, longest first (so "towers" is tried before
    "tower"): one-word names only, without `exclude`, at least `min_len` letters."""
    said = (w for w in lx.SHAPE_WORDS if w.isalpha() and len(w) >= min_len and w not in exclude)
    return "|".join(sorted(said, key=len, reverse=True))


def nouns_said(text: str) -> list[str]:
    """The unambiguous structure nouns of `text`, in the order said."""
    return [w for w in re.findall(r"[a-z]+", text.lower())
            if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES]  # fmt: skip


L_NAMED = re.compile(r"\b(?:l[\s-]?shaped?|an?\s+l|l[\s-]?form)\b", re.IGNORECASE)
"""An L shape named ("L shape", "an L", "L-form")."""


def l_named_last(text: str) -> bool:
    """An L is the structure named last in `text`, before the one said now ("an L shape 3x3 then
    a tower of 2 on the corner": the tower is the only structure named after it)."""
    said = list(L_NAMED.finditer(text))
    return bool(said) and len(families_said(text[said[-1].end() :])) <= 1


def families_said(text: str) -> list[str]:
    """The families the unambiguous structure nouns of `text` name, in the order said."""
    return [lx.SHAPE_WORDS[w] for w in nouns_said(text)]
