"""Stage 4: cut a parsed command into clauses at sentence punctuation and sequence words
("then", "after that", "finally"), and say which clauses a sequence word introduced."""

from __future__ import annotations

from typing import TYPE_CHECKING

from sdi.spec import lexicon as lx

if TYPE_CHECKING:
    from spacy.tokens import Doc, Token


# Sequence words that start a new clause.
_SEQUENCE = {"then", "afterwards", "finally", "lastly", "next", "after", "secondly", "thirdly",
             "fourthly"}  # fmt: skip


_LEADS = {"first", "firstly", "and", ",", "after", "that", "then", "next", "finally", "also",
          "please"}  # fmt: skip


def _ends_sentence(doc: Doc, tok: Token) -> bool:
    """ "… y = 0.45 m. The numbers are …": a word the tokeniser kept with its full stop (a
    unit, an abbreviation) ends the sentence when a capital follows."""
    nxt = tok.i + 1
    return (
        len(tok.text) > 1
        and tok.text.endswith(".")
        and not tok.like_num
        and nxt < len(doc)
        and doc[nxt].text[:1].isupper()
    )


def split_clauses(doc: Doc) -> list[tuple[list[int], bool]]:
    """The command's clauses (token indices), each with whether a sequence word ("then",
    "finally", a step label) introduced it."""
    # Clauses end at sentence punctuation, not at the parser's sentence guesses (it splits
    # "a tower at x = 450 mm" at "=").
    clauses: list[list[int]] = []
    current: list[int] = []
    for tok in doc:
        w = tok.lower_
        spaced_dash = (
            w in ("-", "--") and tok.i > 0 and doc[tok.i - 1].whitespace_ and tok.whitespace_
        )
        if spaced_dash and any(doc[i].lower_ in lx.SHAPE_WORDS for i in current):
            spaced_dash = False  # "a table - four legs and a flat top": the same structure
        if (
            (w in (";", ".", "!", "?") or spaced_dash)
            and tok.i != len(doc) - 1
            and not tok.like_num
        ):
            if current:
                clauses.append(current)
                current = []
            continue
        if (
            _verb_after_comma(doc, tok)
            and any(doc[i].lower_ in lx.SHAPE_WORDS for i in current)
            and not _fronted(doc, current)
        ):
            # "a tower of 3, add one more cube on top": a step of its own
            clauses.append(current)
            current = []
            continue
        if w in _SEQUENCE and _starts_clause(doc, tok) and current:
            clauses.append(current)
            current = []
        current.append(tok.i)
        if _ends_sentence(doc, tok):
            clauses.append(current)
            current = []
    if current:
        clauses.append(current)
    # strip leading sequence words and trailing punctuation
    out: list[tuple[list[int], bool]] = []
    for c in clauses:
        sequenced = bool(c) and doc[c[0]].lower_ in _SEQUENCE | {"then", "finally", "lastly"}
        while c and doc[c[0]].lower_ in _LEADS | _SEQUENCE and not _next_to(doc, c[0]):
            c = c[1:]
        while c and doc[c[-1]].is_punct:
            c = c[:-1]
        if c:
            out.append((c, sequenced))
    return out


_STEP_VERBS = {"add", "put", "stack", "place", "lay", "raise", "extend", "remove", "take"}


def _verb_after_comma(doc: Doc, tok: Token) -> bool:
    """`tok` is a comma that a step's verb follows ("…, add one more cube on top")."""
    nxt = doc[tok.i + 1] if tok.i + 1 < len(doc) else None
    return tok.lower_ == "," and nxt is not None and nxt.lower_ in _STEP_VERBS


_RELATION_LEADS = {"behind", "beside", "next", "in", "to", "left", "right", "on", "above",
                   "opposite", "near", "around", "inside", "alongside", "atop"}  # fmt: skip


def _fronted(doc: Doc, current: list[int]) -> bool:
    """The clause so far is a relation said first, with no comma yet ("In front of a 3x3 slab,
    put a tower of 2": the verb after the comma places the subject, no new step)."""
    said = [i for i in current if doc[i].lower_ not in _LEADS]
    return (
        bool(said)
        and doc[said[0]].lower_ in _RELATION_LEADS
        and not any(doc[i].lower_ in (",", "and") for i in current)
    )


def _next_to(doc: Doc, i: int) -> bool:
    """ "Next to the pyramid a tower of 5": "next" begins a relation, not a step."""
    return doc[i].lower_ == "next" and i + 1 < len(doc) and doc[i + 1].lower_ == "to"


def _starts_clause(doc: Doc, tok: Token) -> bool:
    """`tok` ("then", "next", "after") begins a new step of the description."""
    w = tok.lower_
    if w == "next":
        nxt = doc[tok.i + 1].lower_ if tok.i + 1 < len(doc) else ""
        return nxt in (",", "add", "put", "place", "build", "stack", "make", "lay")
    if w == "after":
        nxt = doc[tok.i + 1].lower_ if tok.i + 1 < len(doc) else ""
        return nxt in ("that", "this")
    return True
