"""Stage 5: relation markers. Each clause is cut into noun phrases at markers ("on top of",
"around", "next to", "joined by", "surround … with") and each marker becomes a relation
between the phrase before it and the one after — when its object names a structure."""

from __future__ import annotations

from typing import TYPE_CHECKING

from sdi.language import words
from sdi.language.clauses import split_clauses
from sdi.language.nouns import (
    SPACE_WORDS,
    beam_only,
    is_component,
    names_structure,
    object_head,
)
from sdi.language.state import Phrase, PhraseRelation
from sdi.spec import lexicon as lx

if TYPE_CHECKING:
    from spacy.tokens import Doc


_SIDE_WORDS = (("left", "left"), ("right", "right"), ("front", "front"), ("back", "back"),
               ("rear", "back"))  # fmt: skip

# Relation markers: words → (kind, side). Kinds: on (subject on object), around (subject
# encloses object), inside (object encloses subject), next (beside, `side`), join (subject
# joins the object's pillars), joined (the object joins the subject's pillars).
_MARKERS: list[tuple[tuple[str, ...], str, str | None]] = [
    (("on", "the", "middle", "of"), "on", None),
    (("on", "the", "centre", "of"), "on", None),
    (("on", "the", "center", "of"), "on", None),
    (("across", "the", "top", "of"), "on", None),
    (("across", "the", "tops", "of"), "on", None),
    (("across",), "on", None),
    (("on", "top", "of"), "on", None),
    (("on", "the", "top", "of"), "on", None),
    (("on", "top"), "on", None),
    (("onto",), "on", None),
    (("atop",), "on", None),
    (("upon",), "on", None),
    (("above",), "on", None),
    (("over",), "on", None),
    (("on",), "on", None),
    (("underneath",), "under", None),
    (("beneath",), "under", None),
    (("below",), "under", None),
    (("under",), "under", None),
    (("around",), "around", None),
    (("round",), "around", None),
    (("surrounding",), "around", None),
    (("enclosing",), "around", None),
    (("encircling",), "around", None),
    (("in",), "inside_ref", None),
    (("into",), "inside_ref", None),
    (("inside", "of"), "inside", None),
    (("inside",), "inside", None),
    (("within",), "inside", None),
    (("in", "the", "middle", "of"), "middle", None),
    (("in", "the", "centre", "of"), "middle", None),
    (("in", "the", "center", "of"), "middle", None),
    (("right", "in", "the", "middle"), "middle_with", None),
    (("in", "the", "very", "middle"), "middle_with", None),
    (("in", "the", "middle"), "middle_with", None),
    (("in", "the", "centre"), "middle_with", None),
    (("in", "the", "center"), "middle_with", None),
    (("at", "the", "centre"), "middle_with", None),
    (("at", "the", "center"), "middle_with", None),
    (("in", "its", "middle"), "middle_with", None),
    (("in", "its", "centre"), "middle_with", None),
    (("in", "its", "center"), "middle_with", None),
    (("surrounded", "by"), "inside", None),
    (("enclosed", "by"), "inside", None),
    (("enclosed", "in"), "inside", None),
    (("encircled", "by"), "inside", None),
    (("ringed", "by"), "inside", None),
    (("next", "to"), "next", None),
    (("beside",), "next", None),
    (("besides",), "next", None),
    (("alongside", "it"), "next_implicit", None),
    (("alongside",), "next", None),
    (("adjacent", "to"), "next", None),
    (("close", "to"), "next", None),
    (("near", "to"), "next", None),
    (("leading", "up", "to"), "next", None),
    (("leading", "to"), "next", None),
    (("up", "against"), "next", None),
    (("right", "against"), "next", None),
    (("against",), "next", None),
    (("near",), "next", None),
    (("to", "its", "left"), "next_implicit", "left"),
    (("to", "its", "right"), "next_implicit", "right"),
    (("on", "its", "left"), "next_implicit", "left"),
    (("on", "its", "right"), "next_implicit", "right"),
    (("in", "front", "of", "it"), "next_implicit", "front"),
    (("behind", "it"), "next_implicit", "back"),
    (("to", "the", "left", "of"), "next", "left"),
    *(
        ((prep, "the", side, "side", "of"), "next", where)
        for prep in ("on", "to", "at", "by")
        for side, where in _SIDE_WORDS
    ),
    (("at", "the", "front", "of"), "next", "front"),
    (("left", "from"), "next", "left"),
    (("right", "from"), "next", "right"),
    (("left", "of"), "next", "left"),
    (("right", "of"), "next", "right"),
    (("on", "the", "left", "of"), "next", "left"),
    (("left", "of"), "next", "left"),
    (("to", "the", "right", "of"), "next", "right"),
    (("on", "the", "right", "of"), "next", "right"),
    (("right", "of"), "next", "right"),
    (("in", "front", "of"), "next", "front"),
    (("behind",), "next", "back"),
    (("at", "the", "back", "of"), "next", "back"),
    (("joined", "at", "the", "top", "by"), "joined", None),
    (("connected", "at", "the", "top", "by"), "joined", None),
    (("joined", "on", "top", "by"), "joined", None),
    (("joined", "on", "top", "with"), "joined", None),
    (("joined", "at", "the", "top", "with"), "joined", None),
    (("connected", "on", "top", "with"), "joined", None),
    (("connected", "on", "top", "by"), "joined", None),
    (("joined", "together", "by"), "joined", None),
    (("joined", "by"), "joined", None),
    (("connected", "by"), "joined", None),
    (("linked", "by"), "joined", None),
    (("bridged", "by"), "joined", None),
    (("spanned", "by"), "joined", None),
    (("joined", "with"), "joined", None),
    (("connected", "with"), "joined", None),
    (("topped", "by"), "topped", None),
    (("topped", "with"), "topped", None),
    (("capped", "by"), "topped", None),
    (("capped", "with"), "topped", None),
    (("joining",), "join", None),
    (("connecting",), "join", None),
    (("linking",), "join", None),
    (("bridging",), "join", None),
    (("spanning",), "join", None),
    (("between",), "join", None),
]


_MARKERS.sort(key=lambda m: -len(m[0]))


_VERB_AROUND = {"surround", "encircle", "enclose", "ring", "circle", "fence", "wall"}


_VERB_JOIN = {"join", "connect", "link", "bridge", "span"}


_VERB_TOP = {"top", "cap", "crown"}


_FRONTED_VERBS = {"goes", "go", "stands", "sits", "comes", "is", "are", "put", "place", "build",
                  "add", "stack", "lies", "rests", "belongs", "should", "will", "must"}  # fmt: skip


# what a structure's own size and direction are said in after "with" ("a staircase with 4 steps
# going up to the right and …")
_OWN_SIZE_WORDS = frozenset({
    "high", "tall", "long", "wide", "deep", "of", "each", "along", "x", "y", "rotated", "degrees",
    "by", "going", "up", "towards", "toward", "to", "the", "left", "right", "back", "front",
    "climbing", "rising",
})  # fmt: skip


# a structure's own supports, sized after "with" ("a table with legs 2 high and …")
_OWN_PARTS = frozenset({"legs", "pillars", "posts", "supports", "feet"})


def _own_then_and(doc: Doc, toks: list[int]) -> int | None:
    """Where "and" starts a structure of its own after the own sizes said with "with" ("a
    staircase with 4 steps and a tower of 2"): its position in toks, or None."""
    withs = [n for n, i in enumerate(toks) if doc[i].lower_ == "with"]
    if not withs:
        return None
    ands = [n for n in range(withs[-1] + 1, len(toks)) if doc[toks[n]].lower_ == "and"]
    own = bool(ands) and all(
        doc[i].like_num
        or doc[i].lower_ in lx.STEP_WORDS | lx.LEVEL_WORDS | lx.PART_WORDS
        or doc[i].lower_ in _OWN_SIZE_WORDS | _OWN_PARTS
        for i in toks[withs[-1] + 1 : ands[0]]
    )
    if own and names_structure(doc, toks[ands[0] + 1 :]):
        return ands[0]
    return None


_BESIDE_OR_ON = frozenset({"next", "on", "next_implicit"})


def _listed_pair(doc: Doc, seg: list[int]) -> int | None:
    """Where "and" joins two structures named in `seg` ("a 3x2 patch, and a row of 3"), else
    None."""
    for n, i in enumerate(seg[1:-1], start=1):
        follows = doc[seg[n + 1]]
        if (
            doc[i].lower_ == "and"
            and (follows.lower_ in ("a", "an") or follows.like_num)
            and (
                names_structure(doc, seg[:n])
                or [doc[k].lower_ for k in seg[:n] if doc[k].lower_ != ","] in (["it"], ["them"])
            )
            and names_structure(doc, seg[n + 1 :])
        ):
            return n
    return None


def find_phrases(doc: Doc) -> tuple[list[Phrase], list[PhraseRelation]]:
    phrases: list[Phrase] = []
    rels: list[PhraseRelation] = []
    stacking = False
    for ci, (clause, sequenced) in enumerate(split_clauses(doc)):
        first_phrase, first_rel = len(phrases), len(rels)
        _clause_phrases(doc, clause, ci, phrases, rels)
        new = rels[first_rel:]
        if not new and stacking and sequenced and len(phrases) == first_phrase + 1:
            # "… a 4x1 row on it. Then 3x1. Then 2x1.": a step in a stack goes on top
            rels.append(PhraseRelation("on", first_phrase, None))
            continue
        # "… with a beam on them. Then a tower of 4": a bridge's own beam starts no stack
        stacking = any(
            r.kind == "on" and not beam_only(_text(doc, phrases[r.subject].tokens)) for r in new
        )
    for p in phrases:
        p.text = _text(doc, p.tokens).strip()
    return phrases, rels


def _text(doc: Doc, tokens: list[int]) -> str:
    return "".join(doc[k].text_with_ws for k in tokens)


def _clause_phrases(
    doc: Doc, clause: list[int], ci: int, phrases: list[Phrase], rels: list[PhraseRelation]
) -> None:
    end = clause[-1] + 1
    lower = [t.lower_ for t in doc]
    markers: list[tuple[int, int, str, str | None]] = []  # (start, end, kind, side)
    k = clause[0]
    # verbs: "surround X with Y", "join X and Y with Z", "top it with a beam"
    verb: tuple[int, str] | None = None
    for i in clause:
        lemma = doc[i].lemma_.lower()
        if doc[i].tag_ in ("VB", "VBP") or (i == clause[0] and doc[i].tag_ != "VBN"):
            if lemma in _VERB_AROUND or lower[i] in _VERB_AROUND:
                verb = (i, "v_around")
            elif lemma in _VERB_JOIN or lower[i] in _VERB_JOIN:
                verb = (i, "v_join")
            elif lemma in _VERB_TOP and lower[i] in _VERB_TOP:
                verb = (i, "v_top")
            if verb:
                break
    if verb is not None:
        v, kind = verb
        prep = next(
            (i for i in clause if i > v and lower[i] in ("with", "by", "using", "in")), None
        )
        if prep is not None and object_head(doc, prep + 1, end)[1]:
            markers.append((v, v + 1, kind + "_verb", None))
            markers.append((prep, prep + 1, kind, None))
    while k < end:
        if markers and any(s <= k < e for s, e, _, _ in markers):
            k += 1
            continue
        found = None
        for words_, kind, side in _MARKERS:
            n = len(words_)
            if tuple(lower[k : k + n]) == words_ and k + n <= end:
                found = (words_, kind, side)
                break
        if found is None:
            k += 1
            continue
        words_, kind, side = found
        n = len(words_)
        if (
            words_[-1] == "against"
            and lower[k + n : k + n + 1] == ["the"]
            and lower[k + n + 1 : k + n + 2]
            and lower[k + n + 1] not in lower[:k]
        ):
            k += n  # "a tower against the wall", no wall named: which is not said
            continue
        strong = words_ in (("on", "top", "of"), ("on", "the", "top", "of"), ("atop",))
        head, is_structure = object_head(doc, k + n, end, strong)
        if (
            is_structure
            and head is not None
            and kind == "on"
            and is_component(doc, clause, k, head)
        ):
            k += n
            continue  # "a bridge on pillars 3 high": the bridge's own pillars
        numeric_before = k > clause[0] and (
            doc[k - 1].like_num
            or (lower[k - 1] in lx.PART_WORDS and k - 2 >= 0 and doc[k - 2].like_num)
        )
        if kind == "middle_with":
            # "a 3x3 slab with a tower in the middle": the middle of the structure before
            # "with" (not the table's centre, which has no "with" before it)
            withs = [i for i in clause if i < k and lower[i] == "with"]
            nouns = [i for i in range(withs[-1] + 1, k) if doc[i].lower_ in lx.SHAPE_WORDS] if (
                withs
            ) else []  # fmt: skip
            if (
                head is not None
                or not withs
                or not names_structure(doc, list(range(withs[-1] + 1, k)))
                or (nouns and is_component(doc, clause, withs[-1], nouns[0]))
            ):
                k += n  # "a castle with walls 2 high in the centre": its own walls, placed
                continue
        implicit = (
            (kind == "on" and words_[-1] == "top" and (head is None or not is_structure))
            or (kind in ("inside", "middle") and head is None)
            or kind in ("next_implicit", "middle_with")
        )
        if kind == "next" and head is None and words_[0] in ("alongside", "beside", "besides"):
            kind, implicit = "next_implicit", True  # "… then a second row alongside"
        said_of = k - (1 if doc[k - 1].like_num else 2) - 1  # "a tower of three cubes over":
        if (  # the tower's own size, and then where it stands
            numeric_before
            and kind == "on"
            and words_[0] in ("above", "over")
            and not (said_of >= clause[0] and lower[said_of] == "of" and is_structure)
        ):
            k += n
            continue
        if kind == "inside_ref":
            if head is None or doc[head].lower_ not in ("it", "them"):
                k += n
                continue
            kind = "inside"
        overlaps = any(a < k + n and k < b for a, b, _, _ in markers)
        if (is_structure or implicit) and not overlaps:
            markers.append((k, k + n, kind, side))
        k += n
    if not markers:
        phrases.append(Phrase(tokens=list(clause), clause=ci))
        return
    markers.sort()
    # cut the clause into segments between markers
    segments: list[list[int]] = []
    cur: list[int] = []
    bounds = iter(markers)
    m = next(bounds, None)
    for i in clause:
        while m is not None and i >= m[1]:
            m = next(bounds, None)
        if m is not None and m[0] <= i < m[1]:
            if i == m[0]:
                segments.append(cur)
                cur = []
            continue
        cur.append(i)
    segments.append(cur)
    lead = [i for i in segments[0] if doc[i].lower_ not in words.HARMLESS and not doc[i].is_space]
    trailing: list[int] = []  # a phrase of its own after the fronted relation's subject
    first = segments[0]
    if (
        len(markers) == 1
        and lead
        and first
        and doc[first[-1]].lower_ in ("and", ",")
        and names_structure(doc, first)
    ):
        # "Build a wall 5 long, and behind the wall put a pyramid": a relation said first in
        # a clause of its own after the structure before; the verb ends its object
        last = segments[-1]
        verbs = [n for n, i in enumerate(last) if doc[i].lower_ in _FRONTED_VERBS and n]
        if verbs and names_structure(doc, last[verbs[0] + 1 :]):
            phrases.append(Phrase(tokens=first, clause=ci))
            segments[0], segments[-1] = last[verbs[0] + 1 :], last[: verbs[0]]
            lead = []
    if markers and not lead:
        # "On top of two 2-cube towers, a beam.": the subject follows the object, after the
        # first comma of the last segment (or the verb: "To the right of a tower goes a row")
        last = segments[-1]
        commas = [n for n, i in enumerate(last) if doc[i].lower_ == ","]
        verbs = [n for n, i in enumerate(last) if doc[i].lower_ in _FRONTED_VERBS and n]
        cut = commas[0] if commas else (verbs[0] if verbs and len(markers) == 1 else None)
        pronoun_first = bool(last) and doc[last[0]].lower_ in ("it", "them", "that", "this")
        if cut is None and pronoun_first:
            cut = 0  # "on it a tower of 3": the pronoun is the object
        # "behind the wall 3 long and 2 high a 3-cube tower": a second noun phrase (before a
        # comma: "next to the pyramid a tower of 5, pyramid 3 levels")
        named_after = bool(commas) and names_structure(doc, last[commas[0] + 1 :])
        articles = [
            n
            for n, i in enumerate(last)
            if n > 0
            and doc[i].lower_ in ("a", "an")
            and (not named_after or n < commas[0])
            and names_structure(doc, last[n : n + 5])
            and names_structure(doc, last[:n])
        ]
        if cut is None or (articles and not pronoun_first):
            cut = articles[0] - 1 if articles else None
            if cut is not None:
                segments[0] = last[cut + 1 : commas[0] if named_after else None]
                segments[-1] = last[: cut + 1]
                trailing = last[commas[0] + 1 :] if named_after else []
                cut = None
        if cut is not None and names_structure(doc, last[cut + 1 :]):
            segments[0] = last[cut + 1 :]
            # "To the left of it a tower": the pronoun stays, naming the one said before
            # (only when something was said before it for it to name)
            segments[-1] = last[:cut] or (
                last[:1] if pronoun_first and cut == 0 and phrases else []
            )
    for j in range(len(markers)):
        tail = segments[j + 1]
        commas = [n for n, i in enumerate(tail) if doc[i].lower_ == ","]
        if (
            (not commas or commas[0] > 2)  # "…, at a distance of one cube" may follow
            and len(tail) > 1
            and doc[tail[0]].lower_ in ("it", "them", "that", "this")
            and (doc[tail[1]].lower_ in ("a", "an", "another") or doc[tail[1]].like_num)
            and names_structure(doc, tail[1 : commas[0] if commas else None])
            and not markers[j][2].endswith("_verb")
            and markers[j][2] in ("on", "next", "inside", "around", "middle")
        ):
            # "a slab, and on it a tower of 2": the subject follows the pronoun
            if names_structure(doc, segments[j]):
                phrases.append(Phrase(tokens=segments[j], clause=ci))
            segments[j], segments[j + 1] = tail[1:], tail[:1]
            continue
        if (
            commas
            and commas[0] <= 2
            and doc[tail[0]].lower_ in ("it", "them", "this", "that")
            and names_structure(doc, tail[commas[0] + 1 :])
            and not markers[j][2].endswith("_verb")
            and commas[0] + 1 < len(tail)
            and doc[tail[commas[0] + 1]].lower_ not in ("and", "then", "plus", "also")
        ):
            # "a T shape and, left of it, an L shape": the subject follows the pronoun; what
            # stood before the marker is a phrase of its own
            if names_structure(doc, segments[j]):
                phrases.append(Phrase(tokens=segments[j], clause=ci))
            segments[j] = tail[commas[0] + 1 :]
            segments[j + 1] = tail[: commas[0]]
    first_of: list[int] = []  # the phrase each segment starts with, and the one it ends with
    last_of: list[int] = []
    for j, seg in enumerate(segments):
        first_of.append(len(phrases))
        cut = _listed_pair(doc, seg) if 0 < j < len(markers) else None
        # "a 2x2 layer in the middle of it, and one cube on top": "it" ends the first relation
        said = [doc[k].lower_ for k in seg[:cut] if doc[k].lower_ != ","] if cut is not None else []
        pointed = said in (["it"], ["them"])
        if cut is not None and ({markers[j - 1][2], markers[j][2]} <= _BESIDE_OR_ON or pointed):
            # "a tower to the left of a 3x2 patch, and a row to the right of it": the patch is
            # the first relation's object, the row the second's subject (the row stood left of
            # the tower and right of it: a cycle)
            phrases.append(Phrase(tokens=[i for i in seg[:cut] if doc[i].lower_ != ","], clause=ci))
            seg = seg[cut + 1 :]
        last_of.append(len(phrases))
        phrases.append(Phrase(tokens=seg, clause=ci))
    if trailing:
        phrases.append(Phrase(tokens=trailing, clause=ci))
    # relate the segments: marker j sits between segment j and j + 1
    for j, (start, _, kind, side) in enumerate(markers):
        before, after = last_of[j], first_of[j + 1]
        if kind.endswith("_verb"):
            continue
        if kind == "inside" and any(doc[i].lower_ in SPACE_WORDS for i in phrases[before].tokens):
            continue  # "an enclosure with a 2 by 2 space inside it": its own inside
        after_toks = phrases[after].tokens
        named = bool(after_toks) and object_head(doc, after_toks[0], after_toks[-1] + 1)[1]
        pronoun = bool(after_toks) and all(
            doc[i].lower_ in ("it", "them", "its", "top", "of", "the", "middle", "centre", "and")
            or doc[i].is_punct
            for i in after_toks
        )
        if (
            kind in ("on", "inside", "next", "middle", "middle_with")
            and (not named or pronoun)
            and (kind != "next" or pronoun)
        ):
            # "a block with a single cube on top", "an enclosure with a pyramid inside":
            # the structure after "with" is the subject, the one before it the object
            toks = phrases[before].tokens
            withs = [n for n, i in enumerate(toks) if doc[i].lower_ == "with"]
            if withs and names_structure(doc, toks[withs[-1] + 1 :]):
                # "a staircase with 4 steps and a tower of 2 on top": the steps are the
                # staircase's own; what stands on it comes after the "and"
                cut = _own_then_and(doc, toks)
                if cut is None:
                    cut = withs[-1]
                phrases[before].tokens = toks[:cut]
                phrases[after].tokens = toks[cut + 1 :] + phrases[after].tokens
                if pronoun:
                    phrases[after].tokens = toks[cut + 1 :]  # the pronoun names the first
                if kind == "on":
                    rels.append(PhraseRelation("on", after, before))
                elif kind == "next":
                    them = pronoun and any(doc[i].lower_ == "them" for i in after_toks)
                    rels.append(PhraseRelation("next", after, before, side, plural=them))
                elif kind in ("middle", "middle_with"):
                    rels.append(PhraseRelation("middle", before, after))
                else:
                    rels.append(PhraseRelation("around", before, after))
                continue
            if kind in ("inside", "middle", "middle_with") and not named:
                continue  # "with a 2 by 2 space inside": the ring's own inside
        if kind == "v_around":
            rels.append(PhraseRelation("around", after, before))
        elif kind == "v_join":
            rels.append(PhraseRelation("joined", before, after))
        elif kind == "v_top":
            rels.append(PhraseRelation("on", after, before))
        elif kind == "on":
            implicit = (
                not phrases[after].tokens
                or not object_head(doc, phrases[after].tokens[0], phrases[after].tokens[-1] + 1)[1]
            )
            rels.append(PhraseRelation("on", before, None if implicit else after))
        elif kind == "under":
            rels.append(PhraseRelation("on", after, before))
        elif kind == "around":
            rels.append(PhraseRelation("around", before, after))
        elif kind == "inside":
            rels.append(PhraseRelation("around", after, before))
        elif kind == "middle":
            rels.append(PhraseRelation("middle", after, before))
        elif kind == "next":
            rels.append(PhraseRelation("next", before, after, side))
        elif kind == "next_implicit" and named and names_structure(doc, phrases[before].tokens):
            # "a wall and behind it a tower": the one after, beside the one before
            rels.append(PhraseRelation("next", after, before, side))
        elif kind == "next_implicit" and (cut := _own_then_and(doc, phrases[before].tokens)) and (
            not [i for i in after_toks if doc[i].lower_ not in words.HARMLESS | {","}]
        ):
            # "a table with legs 2 high and a tower of 3 on its right": the legs are the
            # table's own; what stands to its right comes after the "and"
            toks = phrases[before].tokens
            phrases[before].tokens, phrases[after].tokens = toks[:cut], toks[cut + 1 :]
            rels.append(PhraseRelation("next", after, before, side))
        elif kind == "next_implicit":
            rels.append(
                PhraseRelation("next", before, None, side)
            )  # "to its right": the one before
        elif kind == "joined":
            rels.append(PhraseRelation("joined", before, after))
        elif kind == "join":
            between = doc[start].lower_ == "between"
            rels.append(PhraseRelation("between" if between else "joined", after, before))
        elif kind == "topped":
            rels.append(PhraseRelation("on", after, before))
