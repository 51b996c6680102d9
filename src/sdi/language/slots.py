"""Stage 6: slot filling. Each noun phrase is read by the phrase grammar (`sdi.spec.grammar`)
into structures with their slots filled; references, modifications and continuations are
resolved on the way, and the words the grammar did not use go to the account."""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from sdi.errors import SpecError
from sdi.language import words
from sdi.language.accounting import account, is_chatter
from sdi.language.modify import DROP_VERBS, MODIFY, REMOVAL, continues, modify
from sdi.language.nouns import BEAMS, beam_only
from sdi.language.references import (
    copies,
    definite,
    described,
    named_again,
    named_ahead,
    named_twice,
    pick_structure,
    possessive,
    refers_to,
    same_as_before,
    sized_otherwise,
    the_beam,
)
from sdi.language.state import Phrase, PhraseRelation, ReadState
from sdi.spec import lexicon as lx
from sdi.spec.grammar import parse_phrase
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import SpecDraft, StructureDraft

if TYPE_CHECKING:
    from spacy.tokens import Doc

    from sdi.model.cell import CellConfig


_MAKE_IT = re.compile(
    r"^\W*(?:then\s+|and\s+|now\s+|actually\s+)*make\s+(?:it|them|that|this)\s+"
    r"(?:\d+|one|two|three|four|five|six)\s*(?:x|by)\s*(?:\d+|one|two|three|four|five|six)\b",
    re.I,
)
_COUNT_ONLY = re.compile(
    r"^\W*(?:\d+|[a-z]+)\s+(?:cubes?|parts?|blocks?)(?:\s+(?:tall|high|long))?\W*$", re.I
)


_DROPS = re.compile(
    r"^\W*(?:then\s+|and\s+|now\s+|actually\s+|oh\s+|finally\s+|lastly\s+)?(?:" + DROP_VERBS
    + r"\s+the\s+(?:\w+est|last|first|second|middle|taller|higher|bigger|larger|shorter|lower|"
    r"smaller|left|right|front|back)\b|undo\b|scratch\s+that\b|"
    r"(?:cancel|forget|scrap|"
    r"delete|take\s+back|get\s+rid\s+of)\s+(?:the\s+)?(?:last|latest|previous|that|it)\b)",
    re.IGNORECASE,
)


_SIZES = ("length", "width", "height", "count", "steps", "spans", "dims", "length_m", "width_m",
          "height_m")  # fmt: skip


def _said_again(p: Phrase, spec: SpecDraft, before: list[Phrase],
                structures: list[StructureDraft], doc: Doc) -> int | None:  # fmt: skip
    """The structure named in the sentence before, said again in a sentence of its own with
    nothing that contradicts it and no word of another ("Put a tower on the left. On the left
    side, a tower of 3."): its index; two were built, silently."""
    if len(spec.structures) != 1 or not p.tokens:
        return None
    built = [q for q in before if q.spec is not None and q.count]
    if not built or built[-1].count != 1 or not built[-1].tokens:
        return None
    sentence, earlier = doc[p.tokens[0]].sent, doc[built[-1].tokens[0]].sent
    if sentence.start == earlier.start or _ANOTHER.search(sentence.text):
        return None
    if any(q.spec is None and q.tokens and doc[q.tokens[0]].sent.start == sentence.start
           and q is not p for q in before):  # fmt: skip
        return None  # a sentence with more in it than the structure
    index = built[-1].first
    prev, new = structures[index], spec.structures[0]
    if prev.shape != new.shape:
        return None
    said_as = [re.sub(r"\W+", " ", q.text.lower()).strip() for q in (p, built[-1])]
    if said_as[0] == said_as[1]:
        return None  # "ITEM 1: TOWER 4. ITEM 2: TOWER 4.": a list of two alike
    for key in _SIZES:
        a, b = getattr(prev, key), getattr(new, key)
        if a is not None and b is not None and a != b:
            return None  # "a tower of 3. A tower of 4.": two
    if any(getattr(prev, key) != getattr(new, key) for key in ("region", "at_x", "at_y")):
        return None  # "a tower on the left. a tower of 5": a place makes the first its own
    said = [k for k in _SIZES if getattr(new, k) is not None]
    if not said and not [k for k in _SIZES if getattr(prev, k) is not None]:
        return None  # nothing sized: `same_as_before`
    return index


def _more_about(
    index: int,
    shape: str,
    p: Phrase,
    spec: SpecDraft,
    structures: list[StructureDraft],
    st: ReadState,
    how: str = "more about the {shape} named before",
) -> None:
    """The sizes a phrase says, given to the structure named before that it describes; the
    phrase builds none of its own."""
    said = spec.structures[0].model_dump(exclude_defaults=True, exclude={"shape"})
    structures[index] = structures[index].model_copy(update=said)
    st.notes.append(f"'{p.text}': " + how.format(shape=shape))
    p.count = 0


def _continued(
    p: Phrase, before: list[Phrase], structures: list[StructureDraft], st: ReadState,
    joiner: str = " , ",
) -> SpecDraft | None:
    """The phrase read as more of the structure before it (`continues`): its structures read
    again, keeping a size a change made to them since ("… then add two cubes to the middle one
    … in the middle of the table": the change was lost)."""
    said = {id(q): list(q.spec.structures) for q in before if q.spec is not None}
    grown = continues(p, before, st.cell, joiner)
    if grown is None:
        return None
    count, prev = grown
    assert prev.spec is not None
    now = list(prev.spec.structures)
    held = structures[prev.first : prev.first + count]
    restated = set(words_to_numbers(re.findall(r"\d+|[a-z]+", p.text.lower())))
    for i, (was, built, again) in enumerate(zip(said[id(prev)], held, now, strict=False)):
        # ("… Then revert back, I want the 6 only.": a size said again is the size)
        changed = {key: getattr(built, key) for key in _CHANGEABLE
                   if getattr(built, key, None) != getattr(was, key, None)
                   and str(getattr(again, key, None)) not in restated}  # fmt: skip
        if changed and again.shape == built.shape:
            now[i] = again.model_copy(update=changed)
    structures[prev.first : prev.first + count] = now
    _carry_notes(prev.spec.notes, st)
    return prev.spec


_CHANGEABLE = ("height", "length", "width", "steps")
"""The sizes a later change sets on a structure already read (`modify`)."""


def _holding(phrases: list[Phrase], i: int) -> int | None:
    """The phrase that built structure `i`."""
    return next((j for j, q in enumerate(phrases) if q.count and q.first <= i < q.first + q.count),
                None)  # fmt: skip


def _content(text: str) -> list[str]:
    """The words of `text` that say something (structure nouns always do)."""
    return [w for w in re.findall(r"[a-z0-9.]+", text.lower())
            if w not in words.HARMLESS or w in lx.SHAPE_WORDS]  # fmt: skip


def _beam_words(content: list[str]) -> bool:
    """Nothing said but a beam (or a bridge's top), its parts and "top"."""
    return all(w in BEAMS or w in lx.PART_WORDS or w == "top" for w in content)


def _beam_said(text: str) -> bool:
    """A beam before a comma and chatter only ("a beam, if it's no bother")."""
    head, comma, rest = text.partition(",")
    content = _content(head)
    return bool(comma and rest.strip() and content) and _beam_words(content) and is_chatter(rest)


_THE_FAMILY = re.compile(
    r"\W*(?:(?:put|place|set|move|stand|position)\s+)?(?:the|that)\s+(\w+)(?:\W*$|(?=\s*,))"
)
"""'the wall', 'put the block', 'the slab, in the middle': one family named, pointed at."""


def fill_slots(
    phrases: list[Phrase], rels: list[PhraseRelation], st: ReadState, doc: Doc
) -> list[StructureDraft]:
    structures: list[StructureDraft] = []
    pending: list[str] = []
    joiners = {r.object for r in rels if r.kind == "joined"} | {
        r.subject for r in rels if r.kind == "on" and (beam_only(phrases[r.subject].text)
                                                      or _beam_said(phrases[r.subject].text))
    }
    for r in rels:
        if r.kind == "next" and r.side and (r.object is None or r.object < r.subject):
            phrases[r.subject].beside = r.side  # "… and a tower of 5 to its right"
    for k, p in enumerate(phrases):
        content = _content(p.text)
        earlier = [
            i
            for q in phrases[:k]
            if q.clause < p.clause and q.count
            for i in range(q.first, q.first + q.count)
        ]
        beam = the_beam(p.text, phrases[:k], structures, rels)
        if beam is not None:  # "… a beam across them, then a cube on the middle of the beam"
            spanned, rest = beam
            p.ref, p.structure = spanned, phrases[spanned].first
            if rest and not is_chatter(rest):
                st.material.append(rest)
                st.notes.append(f"ignored '{rest}': said of the beam, read as where the "
                                "structure stands")  # fmt: skip
            continue
        dropping = _DROPS.search(p.text)
        if dropping and modify(p, phrases[:k], structures, st):
            continue  # "then remove the tallest one": a change, not a reference to it
        # a removal SDI could not make is reported below, never read as a pointer to one
        pick = None if dropping else pick_structure(p.text, structures, earlier)
        if pick is not None and structures:
            p.structure = pick
            p.ref = _holding(phrases[:k], pick)
            if p.ref is not None and sized_otherwise(p.text, phrases[p.ref].text):
                p.ref = None  # "the small tower in front of the big tower": another one
            if p.ref is not None:
                continue
            p.structure = None
        partner = next((r.object if r.subject == k else r.subject for r in rels
                        if k in (r.subject, r.object) and r.object is not None), None)  # fmt: skip
        ref = refers_to(p, phrases[:k], partner)
        if ref is not None:
            p.ref = ref
            the = _THE_FAMILY.match(p.text.lower())  # "the wall", "put the block"
            family = lx.SHAPE_WORDS.get(the.group(1)) if the else None
            q = phrases[ref]
            if family and q.count > 1:  # "the wall" of "a wall, a tower of 3": that one
                span = range(q.first, q.first + q.count)
                mine = [i for i in span if structures[i].shape == family]
                if len(mine) == 1:
                    p.structure = mine[0]
            continue
        moves = any(op in _CHANGE_OPS and pattern.search(p.text) for pattern, op in MODIFY)
        if not content and not moves:
            continue  # ("put it on the right" is all harmless words, and a move)
        if k in joiners and (_beam_said(p.text) or _beam_words(content)):
            continue  # "a beam", "a bridge on top" as what joins the towers: no own structure
        if modify(p, phrases[:k], structures, st):
            continue
        if _MAKE_IT.match(p.text) and [q for q in phrases[:k] if q.spec is not None]:
            # "a tower of 3, then make it 4x4": a change SDI could not make to it, never a new
            # structure read from its words (a 4 by 4 slab was built beside the tower)
            st.material.append(p.text.strip())
            st.notes.append(f"ignored '{p.text.strip()}': SDI cannot make that change to the "
                            f"{structures[-1].shape if structures else 'structure'}; say the "
                            "size it should have in the first place")  # fmt: skip
            continue
        if _COUNT_ONLY.match(p.text) and [q for q in phrases[:k] if q.spec is not None]:
            grown = _continued(p, phrases[:k], structures, st)  # "make a tower? 4 cubes?"
            if grown is not None:
                continue
        if _COMPONENT.search(p.text) and _pillared(phrases[:k]):
            # "A bridge. Pillars of 3."
            grown = _continued(p, phrases[:k], structures, st, " with ")
            if grown is not None:
                st.notes.append(f"read '{p.text}' as the {grown.structures[0].shape}'s own")
                continue
        said_shapes = [w for w in re.findall(r"[a-z]+", p.text.lower()) if w in lx.SHAPE_WORDS]
        alone = not [q for q in phrases[:k] if q.spec is not None] and len(said_shapes) == 1
        down = _TAKE_DOWN.match(p.text)
        if down and not alone and not [q for q in phrases[:k] if q.spec is not None]:
            said = p.text[: down.end()].strip() + " " + said_shapes[0]
            st.material.append(said)
            st.notes.append(f"ignored '{said}': SDI builds on a clear table and cannot take down "
                            "what already stands there")  # fmt: skip
        if down and alone:
            # "Take down the castle from last night.": nothing named before to take down
            st.material.append(p.text)
            st.notes.append(f"ignored '{p.text.strip()}': SDI builds on a clear table and cannot "
                            "take down what already stands there; clear it, then say what to "
                            "build")  # fmt: skip
            continue
        moved = any(  # "move it to the left": a change MODIFY makes
            op in _CHANGE_OPS and pattern.search(p.text) for pattern, op in MODIFY
        )
        counted = _REMOVED_COUNT.match(p.text)
        prior = [q for q in phrases[:k] if q.spec is not None and q.count]
        if counted and prior and structures[prior[-1].first + prior[-1].count - 1].shape == "tower":
            # "Step 3: remove 1 cube." of a tower: a cube can only come off its top
            said, p.text = p.text, f"take {counted.group(1)} off"
            if modify(p, phrases[:k], structures, st):
                st.notes[-1] = st.notes[-1].replace(f"'{p.text}'", f"'{said.strip(' .')}'")
                continue
            p.text = said
        if REMOVAL.match(p.text) and not moved and [q for q in phrases[:k] if q.spec is not None]:
            # "then pull out the middle cube", "push them together": a change SDI cannot
            # make to a structure it built; never a new structure read from those words
            st.material.append(p.text)
            st.notes.append(
                f"ignored '{p.text}': SDI builds structures whole and cannot take parts out, "
                "move or merge them afterwards; describe the result instead"
            )
            continue
        change = next((m for pattern, _ in MODIFY if (m := pattern.search(p.text))), None)
        tail: Phrase | None = None
        if change is not None and change.start() > 0:
            # "begin with a 2-step staircase and keep adding steps until it has 4"
            tail = Phrase(tokens=[], clause=p.clause, text=p.text[change.start() :])
            p.text = re.sub(r"(?:,|\band\b|\bthen\b|\s)+$", "", p.text[: change.start()])
        if pending and not [q for q in phrases[:k] if q.spec is not None]:
            p.text = " , ".join([*pending, p.text])  # "High: 3. Long: 5. Wall."
            pending.clear()
        try:
            spec, unused = _parse_or_base(p, st)
            spec = named_twice(copies(spec, p.text, st, structures), p.text, st)
        except SpecError:
            grown = _continued(p, phrases[:k], structures, st)
            if grown is not None:
                continue
            if not [q for q in phrases[:k] if q.spec is not None] and not is_chatter(p.text):
                pending.append(p.text)
                continue
            if is_chatter(p.text):
                st.ignored.append(p.text)
                st.notes.append(f"ignored '{p.text}': no structure, size or place in it")
                continue
            if _repeats(p.text, structures):  # "tower of 5. not 4, FIVE"
                st.ignored.append(p.text)
                st.notes.append(f"ignored '{p.text}': repeats a number already used")
                continue
            st.material.append(p.text)
            st.notes.append(f"ignored '{p.text}': no structure named there")
            continue
        legs = bool(_COMPONENT.search(p.text)) and _pillared(phrases[:k])  # "canopy. 4 legs."
        if (not said_shapes or legs) and _sizes_of_named(p, spec, phrases[:k], structures, st):
            continue
        if _sizes_of_plural(p, spec, structures, st):
            continue  # "two towers and a pyramid; towers 4 cubes tall"
        if _restated(p, spec, phrases[:k], structures, st):
            continue  # "… a 5-step staircase. Acceptance: 5 steps, 1 cube wide."
        told = described(p, spec, phrases[:k], structures)
        if told is not None:
            # "A staircase on the right. It has 5 steps.": more about it, not a second one
            _more_about(told, structures[told].shape, p, spec, structures, st)
            _account(p, spec, unused, doc, st)
            continue
        owner = possessive(p, spec, phrases[:k], structures)
        if owner is not None and not re.search(r"\d|\b(?:height|length|width|high|tall|long|"
                                               r"wide)\b", p.text, re.IGNORECASE):
            # "The tower's top must be flat": about it, and no size of it
            shape = structures[owner].shape
            st.notes.append(f"'{p.text}' is about the {shape} described before, not another")
            _account(p, spec, unused, doc, st)
            continue
        related = any(k in (r.subject, r.object) for r in rels)
        again = None if related else _said_again(p, spec, phrases[:k], structures, doc)
        if again is not None:
            # "Make a row of 5. Five cubes side by side in a line, I mean.": one row, said twice
            _more_about(again, structures[again].shape, p, spec, structures, st,
                        how="the {shape} named before, said again")  # fmt: skip
            _account(p, spec, unused, doc, st)
            at = _holding(phrases[:k], again)
            if at is not None and phrases[at].count == 1:  # read on with what it said
                phrases[at].text = f"{phrases[at].text} , {p.text}"
                p.ref = at
            continue
        same = same_as_before(p, spec, phrases[:k])
        if same is not None and any(getattr(spec.structures[0], key) is not None
                                    for key in ("region", "at_x", "at_y", "axis")):  # fmt: skip
            # "… a tower from 5 cubes. The tower shall stand on the left side.": its place
            last = [q for q in phrases[:k] if q.spec is not None and q.count][-1]
            _more_about(last.first + last.count - 1, same, p, spec, structures, st)
            _account(p, spec, unused, doc, st)
            continue
        if same is not None:
            st.notes.append(f"'{p.text}' names the {same} described before")
            _account(p, spec, unused, doc, st)
            continue
        named = definite(p, spec, phrases[:k], structures)
        if named is None:
            named = named_ahead(p, spec, phrases[:k], structures)
        if named is None:
            named = named_again(p, spec, phrases[:k], structures)
        if named is not None:
            # "…; the staircase has 3 steps": more about the staircase named before
            _more_about(named, spec.structures[0].shape, p, spec, structures, st)
            _account(p, spec, unused, doc, st)
            at = _holding(phrases[:k], named)
            if at is not None and phrases[at].count == 1:  # "staircase. 4 steps. 10cm wide.":
                phrases[at].text = f"{phrases[at].text} , {p.text}"  # kept when read on, and
                p.ref = at  # "… a block two high, with a pyramid on it": it is that one
            elif at is not None:  # "a slab and a block. Put the block on it": one of those
                p.ref, p.structure = at, named  # named together
            continue
        ordinal = _ORDINAL_OF.match(p.text)
        family = lx.SHAPE_WORDS.get(ordinal.group(1).lower()) if ordinal else None
        if family and sum(s.shape == family for s in structures) >= 2:
            # "Two walls … The first wall has 2 cubes in the height": one of several named
            # together, changed — SDI does not change one of them; never a new one
            st.material.append(p.text)
            st.notes.append(f"ignored '{p.text}': SDI cannot change one of several "
                            f"{family}s named together; give each its own size")  # fmt: skip
            continue
        p.spec = spec
        p.first = len(structures)
        p.count = len(spec.structures)
        structures.extend(spec.structures)
        if tail is not None:
            modify(tail, [p], structures, st)
        st.notes.extend(spec.notes)
        _account(p, spec, unused, doc, st)
    for text in pending:
        st.material.append(text)
        st.notes.append(f"ignored '{text}': no structure named there")
    return structures


_PLACE_SLOTS = {"region", "at_x", "at_y", "axis", "count"}


def _sizes_of_named(
    p: Phrase,
    spec: SpecDraft,
    before: list[Phrase],
    structures: list[StructureDraft],
    st: ReadState,
) -> bool:
    """ "Let's make a block. Two cubes wide, four cubes deep and three cubes tall.": sizes said
    with no structure, after a structure named with none, are that structure's (a row guessed
    from them was built beside it)."""
    built = [q for q in before if q.spec is not None and q.count and not q.undone]
    if len(spec.structures) != 1 or not built or built[-1].clause == p.clause:
        return False
    prev = built[-1]
    own = structures[prev.first : prev.first + prev.count]
    guessed = spec.structures[0]
    said = own[0].model_dump(exclude_defaults=True).keys() - {"shape", "part"} if own else set()
    if said and not _NUMBER.search(prev.text) and not said & _PLACE_SLOTS:
        said = set()  # "a small wall. Six cubes long …": the vague size gives way to the figures
    if len(own) != 1 or said:
        return False  # the structure named before has sizes, a place or a way of its own
    if guessed.region or guessed.at_x is not None or guessed.at_y is not None:
        return False  # "a tower on the left. 3 cubes on the right": somewhere else
    if _ANOTHER.search(p.text):
        return False  # "… and another 4 cubes"
    if not _NUMBER.search(p.text):
        return False  # "Medium height.": a vague size, read with the structure elsewhere
    if re.search(r"\b(?:not|never|no|nor|than)\b|n't", p.text, re.IGNORECASE):
        return False  # "Not more than 3 high": a bound, read elsewhere
    try:
        grown, _ = parse_phrase(prev.text + " , " + p.text, st.cell)
    except SpecError:
        return False
    if len(grown.structures) != 1 or grown.structures[0].shape != own[0].shape:
        return False  # it read as another family, or more: not sizes of this one
    prev.text = prev.text + " , " + p.text
    prev.spec = grown
    p.count = 0
    structures[prev.first] = grown.structures[0]
    _carry_notes(grown.notes, st)
    st.notes.append(f"read '{p.text}' as the size of the {own[0].shape} named before")
    return True


_PLURAL_SIZED = re.compile(
    r"^\W*(?:and\s+)?(?:(?:the|both|all|all\s+the|both\s+the|each\s+of\s+the)\s+)?([a-z]+s)\b"
    r"(?:\s+(?:are|should\s+be|must\s+be|will\s+be|each|both|all|of))*\s+(?=\d|(?:one|two|three|"
    r"four|five|six|seven|eight|nine|ten)\b)",
    re.IGNORECASE,
)


def _sizes_of_plural(
    p: Phrase, spec: SpecDraft, structures: list[StructureDraft], st: ReadState
) -> bool:
    """ "two towers flanking a pyramid; towers 4 cubes tall", "… The towers are 4 high.": the
    size of every structure of that family named before with none (a third tower was built)."""
    m = _PLURAL_SIZED.match(p.text)
    word = m.group(1).lower() if m else ""
    family = lx.SHAPE_WORDS.get(word)
    if family is None or word in lx.AMBIGUOUS_SHAPES or _ANOTHER.search(p.text):
        return False
    if not spec.structures or any(s.shape != family for s in spec.structures):
        return False
    sizes = spec.structures[0].model_dump(exclude_defaults=True, exclude={"shape", "part"})
    if not sizes or sizes.keys() & {"region", "at_x", "at_y", "edge", "yaw_deg"}:
        return False  # "towers at the back": a place, read elsewhere
    if any(s.model_dump(exclude_defaults=True, exclude={"shape", "part"}) != sizes
           for s in spec.structures):  # fmt: skip
        return False
    mine = [n for n, s in enumerate(structures) if s.shape == family]
    if len(mine) < 2 or any(
        structures[n].model_dump(exclude_defaults=True).keys() & sizes.keys() for n in mine
    ):
        return False  # one named before, or their sizes said already: not theirs
    for n in mine:
        structures[n] = structures[n].model_copy(update=sizes)
    _carry_notes(spec.notes, st)
    st.notes.append(f"read '{p.text}' as the size of the {len(mine)} {family}s named before")
    p.count = 0
    return True


_CHECK_LABEL = re.compile(
    r"^\W*(?:acceptance(?:\s+criteria)?|ac|expected(?:\s+result)?|check|verify|"
    r"definition\s+of\s+done|dod|then)\s*[:=-]", re.IGNORECASE
)


def _restated(
    p: Phrase,
    spec: SpecDraft,
    before: list[Phrase],
    structures: list[StructureDraft],
    st: ReadState,
) -> bool:
    """ "As a user I want a 5-step staircase … Acceptance: 5 steps, 1 cube wide.": a check
    said after the structure restates it — its sizes are that structure's, not a second one's
    (a second staircase was built, silently); a size the check gives differently is reported."""
    if not _CHECK_LABEL.match(p.text) or len(spec.structures) != 1:
        return False
    built = [q for q in before if q.spec is not None and q.count and not q.undone]
    if not built or built[-1].clause == p.clause or built[-1].count != 1:
        return False
    idx = built[-1].first
    own, said = structures[idx], spec.structures[0]
    if said.shape != own.shape:
        return False
    sizes = said.model_dump(exclude_defaults=True, exclude={"shape", "part"})
    mine = own.model_dump(exclude_defaults=True)
    differ = {k: v for k, v in sizes.items() if k in mine and mine[k] != v}
    structures[idx] = own.model_copy(update={k: v for k, v in sizes.items() if k not in mine})
    _carry_notes(spec.notes, st)
    p.count = 0
    if differ:
        st.material.append(p.text)
        st.notes.append(f"ignored '{p.text}' where it differs from the {own.shape} described "
                        f"before ({', '.join(f'{k} {v}' for k, v in differ.items())}); "
                        "built the one described")  # fmt: skip
    else:
        st.notes.append(f"read '{p.text}' as a check of the {own.shape} described before")
    return True


_ANOTHER = re.compile(r"\b(?:another|second|more|also|too|as\s+well|again|other)\b", re.I)
_NUMBER = re.compile(r"\d|\b(?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\b",
                     re.IGNORECASE)


def _account(p: Phrase, spec: SpecDraft, unused: list[str], doc: Doc, st: ReadState) -> None:
    """The words of `p` its reading left unused, and what it ignored, go to the account — also
    of a phrase that only says more about a structure named before ("H: double the std
    3-block tower": 'double' is not used)."""
    st.material.extend(n for n in spec.notes if n.startswith("ignored"))
    free = list(p.tokens)
    for w in unused:
        tok = next((doc[i] for i in free if doc[i].lower_.replace("'", "") == w), None)
        if tok is not None:
            free.remove(tok.i)
        account(w, tok, st)


_CHANGE_OPS = frozenset({"region", "offset"})
_REMOVED_COUNT = re.compile(
    r"^\W*(?:(?:and|then|now)\s+)*(?:please\s+)?(?:remove|take\s+away|lose|drop)\s+(\d+|one|two|three|"
    r"four|five|six|a|an)\s+(?:cubes?|blocks?)\W*$",
    re.IGNORECASE,
)
_TAKE_DOWN = re.compile(
    r"^\W*(?:please\s+)?(?:take|tear|knock|pull)\s+down\b|^\W*(?:please\s+)?(?:demolish|dismantle|"
    r"clear\s+away|remove|destroy)\s+the\b",
    re.IGNORECASE,
)


_ORDINAL_OF = re.compile(
    r"^\W*the\s+(?:first|second|third|fourth|last|other|left|right|front|back)\s+(\w+)", re.I
)


_COMPONENT = re.compile(r"\b(?:pillars?|legs?|posts?|supports?|uprights?|piers?)\b", re.I)
_PILLARED = frozenset({"bridge", "arch", "canopy", "table"})


def _pillared(before: list[Phrase]) -> bool:
    """The last structure named stands on pillars or legs (a bridge, an arch, a table)."""
    built = [q for q in before if q.spec is not None and q.count]
    return bool(built) and built[-1].spec.structures[-1].shape in _PILLARED  # type: ignore[union-attr]


def _carry_notes(notes: tuple[str, ...], st: ReadState) -> None:
    """The grammar's notes on a phrase read again with a later clause ("Tower of 5. 4."):
    a value it could not use is as material as in the first reading."""
    for n in notes:
        if n not in st.notes:
            st.notes.append(n)
            if n.startswith("ignored"):
                st.material.append(n)


_ONE_CUBE = re.compile(
    r"^(?:\w+\s+)?(?:a|an|one|single|a\s+single|another|1)\s+(?:more\s+)?(?:cube|block|brick|part)"
    r"(?:\s+\w+)?$",
    re.IGNORECASE,
)


def _parse_or_base(p: Phrase, st: ReadState) -> tuple[SpecDraft, list[str]]:
    """The phrase grammar's reading; "a sturdy base" with nothing else named is a platform,
    "a cube" on its own one part."""
    named = _named_first(p.text, st.cell)
    if named is not None:
        # "We need an enclosure: a hollow square 5 on each side, with walls 2 high": the name,
        # then the structure it names described (read as two, the walls a third)
        head, p.text, described = named
        st.notes.append(f"read '{head}' as the name of what follows the colon")
        return described
    try:
        return parse_phrase(p.text, st.cell)
    except SpecError:
        if _ONE_CUBE.match(p.text.strip()):
            return parse_phrase("a single cube", st.cell)[0], []
        lone = re.sub(
            r"^(\W*(?:\w+\s+)?)(?:a|an|one|a\s+single|single)\s+(?:cube|block|brick)\b",
            r"\1a 1-cube tower",
            p.text,
            flags=re.IGNORECASE,
        )
        if lone != p.text:  # "a cube in the front left corner"
            spec, unused = parse_phrase(lone, st.cell)
            p.text = lone
            return spec, unused
        base = re.search(r"\b(base|foundation|footing|plinth)\b", p.text, re.IGNORECASE)
        if not base:
            raise
        text = p.text[: base.start()] + "platform" + p.text[base.end() :]
        spec, unused = parse_phrase(text, st.cell)
        st.notes.append(f"read '{base.group(0)}' as a platform (one layer)")
        p.text = text
        return spec, unused


def _named_first(
    text: str, cell: CellConfig
) -> tuple[str, str, tuple[SpecDraft, list[str]]] | None:
    """`text` is "<a family, no size>: <that family described>": the name, the description
    and its reading; else None."""
    head, colon, tail = text.partition(":")
    if not colon or not tail.strip() or not re.search(r"\b(?:an?|one)\s+\w+\s*$", head):
        return None
    tail = tail.strip()
    try:
        (name,) = parse_phrase(head, cell)[0].structures
        described = parse_phrase(tail, cell)
    except (SpecError, ValueError):
        return None
    sized = name.model_dump(exclude_none=True, exclude_defaults=True).keys() - {"shape"}
    shapes = [s.shape for s in described[0].structures]
    if sized or not shapes or shapes[0] != name.shape:
        return None
    return head.strip(), tail, described


def _repeats(text: str, structures: list[StructureDraft]) -> bool:
    """`text` is only numbers, each already a value of a structure read."""
    said = words_to_numbers(re.findall(r"[a-z]+|\d+", text.lower()))
    if not said or not all(w.isdigit() for w in said):
        return False
    used = {v for s in structures for v in s.model_dump().values() if isinstance(v, int)}
    return {int(w) for w in said} <= used
