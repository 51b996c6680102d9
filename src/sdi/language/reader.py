"""The offline Specifier: a command → a `Reading` (structures, relations, notes).

`read` ties the stages together, each in its own module:

1. **Normalise** (`sdi.language.normalise`): symbols, ``3x3`` → ``3 x 3``, contractions,
   number forms; numbers SDI cannot use are refused. Before it, what is said about the
   conversation rather than the structure (`sdi.language.background`): a sentence recounting
   what happened before, a structure taken back by name ("no castle", "forget the pyramid").
2. **Correct and rewrite**: unknown words close to a known word are corrected
   (`sdi.language.typos`); negations, hedges and idioms with one clear reading are rewritten
   by a table (`sdi.language.rewrites`, computed replacements in `sdi.language.handlers`)
   — "not too tall" → medium, "not on the left" → on the right, "don't stack them" → side
   by side — each with a note.
3. **Parse** with spaCy's dependency parser (`sdi.language.syntax`).
4. **Clauses** (`sdi.language.clauses`): sentences, ``;`` and sequence words ("then", "after
   that") separate clauses.
5. **Relation markers** (`sdi.language.markers`, with the word classes of
   `sdi.language.nouns`): "on top of", "around", "surround … with", "next to", "to the left
   of", "joined by", "connecting" relate the noun phrase before them to the one after (or,
   for verbs, the verb's object to the phrase after "with"). A marker is a relation only if
   its object is a structure, a pronoun ("it", "them") or a definite reference to an earlier
   structure ("the base"); "on the left" stays a region.
6. **Slot filling** (`sdi.language.slots`): each phrase is read by the phrase grammar
   (`sdi.spec.grammar`), which fills the family's slots. A phrase that points at an earlier
   structure ("it", "the base", "the smaller one", "a second row") is resolved by
   `sdi.language.references`; one that changes it ("then add two more cubes to it", "make it
   5 high") by `sdi.language.modify`.
7. **Composition** (`sdi.language.composition`): relations between phrases become relations
   between structures; two towers "joined by" a beam become a bridge on them.
8. **Family check** (`sdi.language.families`): every value goes where its family uses it,
   or is reported.
9. **Accounting** (`sdi.language.accounting`, as each phrase is filled): every word is used
   or reported; unused material words make the reading incomplete (`Reading.complete` is
   False, the plan is ``partial``).

The reading in progress — its phrases, the relations between them and the notes — is a
`sdi.language.state.ReadState`.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from sdi.errors import LimitError, SpecError
from sdi.language import (
    acceptance,
    background,
    claims,
    coherence,
    corrections,
    fields,
    scanned,
    spacing,
    structured,
    typos,
    viewpoint,
)
from sdi.language.accounting import no_structure, understood_summary
from sdi.language.composition import relate, unstack
from sdi.language.families import check_family
from sdi.language.markers import find_phrases
from sdi.language.normalise import courtesy, normalise
from sdi.language.nouns import STRUCTURE_PLURALS, shape_alternation
from sdi.language.reading import Reading
from sdi.language.references import one_cube
from sdi.language.rewrites import outline_corners, rewrite
from sdi.language.slots import fill_slots
from sdi.language.state import Phrase, ReadState
from sdi.language.syntax import parse
from sdi.model.cell import CellConfig
from sdi.spec import lexicon as lx
from sdi.spec.numbers import QUANTITY_WORDS, words_to_numbers
from sdi.spec.structure_spec import Relation, Spec, StructureDraft, StructureSpec

if TYPE_CHECKING:
    from spacy.tokens import Doc


_FACE_AT = re.compile(
    r"\b(?:with\s+)?(?:its|the)?\s*(front|near|back|rear|far|left|right)(?:[\s-]*hand)?\s+(?:edge|face|"
    r"side|end)\s+(?:is\s+|sits\s+|lies\s+|placed\s+|set\s+)?(?:at|on)\s+(?=([xy])\s*(?:[=:]\s*)?\d)",
    re.IGNORECASE,
)
_FACE_SIDE = {"near": "front", "rear": "back", "far": "back"}
_FACE_VALUE = re.compile(r"[xy]\s*[=:]?\s*\d+(?:\.\d+)?\s*(?:mm|cm|m\b)?", re.IGNORECASE)


def _faces_at(text: str, st: ReadState) -> str:
    """ "front edge at x = 0.30 m", "left side at y=450": the coordinate places that face of
    the footprint, not its centre (front and back faces on x, left and right on y)."""

    def face(m: re.Match[str]) -> str:
        side = _FACE_SIDE.get(m.group(1).lower(), m.group(1).lower())
        if (side in ("front", "back")) != (m.group(2).lower() == "x"):
            return m.group(0)  # "front edge at y = …": not a face that coordinate places
        value = _FACE_VALUE.match(m.string[m.end() :])
        st.faces.append((side, f"{m.group(0).strip()} {value.group(0).strip() if value else ''}"))
        return " at "

    return _FACE_AT.sub(face, text)


def _placed_by_face(specs: list[StructureSpec], st: ReadState) -> list[StructureSpec]:
    """The faces said go to the one structure placed by that coordinate."""
    for side, said in st.faces:
        axis = "at_x" if side in ("front", "back") else "at_y"
        placed = [k for k, s in enumerate(specs) if getattr(s, axis) is not None]
        if len(placed) != 1:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': not one structure placed by that coordinate; "
                            "the coordinate is taken as a centre")  # fmt: skip
            continue
        k = placed[0]
        specs[k] = specs[k].model_copy(update={"at_face": (*specs[k].at_face, side)})
        st.notes.append(f"read '{said}' as the {specs[k].shape}'s {side} face there, not its "
                        "centre")  # fmt: skip
    return specs


# "a wall of length −3", "height: -2 cubes": a size below zero (read as 3, silently); not a
# coordinate ("y = -0.1"), a range ("3-4") or a dash ("tower - 3 high")
_NEGATIVE_SIZE = re.compile(
    # "a bridge with pillars -2 high": a size below zero said with its dimension
    # (not a dash before a size: "The wall - 6 long", "- 2 high" in a list)
    r"(?<![\w.])[−-]\d+(?:\.\d+)?\s*(?:cubes?\s+)?(?:high|tall|long|wide|deep|levels?|layers?|steps?)\b|"
    r"\b(?:(?:length|height|width|depth|size|levels?|steps?|count)\s*(?:of|is|=|:)?|of|"
    r"(?:high|long|wide|tall)\s*[:=])\s*[−-]\s?\d+(?:\.\d+)?(?=\s*(?:cubes?|blocks?|parts?|mm|cm|m|"
    r"high|long|wide|tall|levels?|steps?)?\s*(?:[.,;!?]|$))",
    re.IGNORECASE,
)


_ONLY_A_QUESTION = re.compile(
    r"^\s*(?:how\s+(?:many|much|long|tall|high)|what(?:'s|\s+is)|where(?:'s|\s+is|\s+are)|why|when)\b"
    r"(?![^?]*\b(?:build|make|stack|put|place|lay|give\s+me)\b)[^.!?]*\?\s*$",
    re.IGNORECASE,
)
"""A command that is one question and asks for nothing ("how many cubes are left in the
feeder?"): an 8-cube row was built for its 'many'."""


_ONLY_A_CHANGE = re.compile(
    r"^\W*(?:(?:um+|uh+|er+|ok(?:ay)?|so|now|and|then|please|just|right)\W+)*(?:(?:can|could|would)\s+"
    r"you\s+)?(?:please\s+)?(?:make|extend|lengthen|shorten|raise|lower|widen|grow)\s+(?:the\s+\w+|it|"
    r"that|this|them)\s+(?:(?:um+|uh+|er+)\s+)?(?:a\s+(?:bit|little)\s+)?(?:longer|taller|shorter|"
    r"higher|wider|bigger|smaller|lower)\b[^.;!?]*[.!?]?\s*$",
    re.IGNORECASE,
)
"""A command that only changes a structure, none named before ("make the wall longer by two"):
a wall 2 long was built."""


def read(command: str, cell: CellConfig | None = None) -> Reading:
    """Read `command`; `SpecError` (with `understood`) when it names nothing buildable."""
    cell = cell or CellConfig()
    if not isinstance(command, str):
        raise SpecError("the command must be text", understood={})
    if len(command) > cell.limits.max_command_chars:
        raise LimitError(
            f"the command has {len(command)} characters; the limit is "
            f"{cell.limits.max_command_chars} (limits.max_command_chars)",
            field="command",
        )
    if not command.strip():
        raise SpecError(
            "the command is empty; say what to build, e.g. 'a 3-cube tower'", understood={}
        )
    negative = _NEGATIVE_SIZE.search(command)
    if negative:
        raise SpecError(
            f"'{negative.group(0).strip()}': a size below zero cannot be built; sizes count parts "
            "(whole numbers ≥ 1) or measure lengths",
            understood={},
        )
    if _ONLY_A_QUESTION.match(command):
        raise SpecError(
            f"'{command.strip()}' is a question, not something to build; SDI builds what a "
            "command names (e.g. 'a tower of 4 cubes')",
            understood={},
        )
    if _ONLY_A_CHANGE.match(command):
        raise SpecError(
            f"'{command.strip()}' changes a structure, but none is named before it; say what to "
            "build first (e.g. 'a wall of 4, then make it longer by two')",
            understood={},
        )
    st = ReadState(command, cell)
    text = structured.as_words(command, st.notes)  # '{"shape": "tower", "height": 4}'
    text, unscanned = scanned.unscan(courtesy(text))  # "bui1d a tovver 0f": a scanner's
    text, corrected = typos.correct(text)
    corrected[:0] = unscanned
    text = fields.as_words(text, st.notes)  # "Tower | H: 4 | X (mm): 500 | Y (mm): 400"
    text = background.taken_back(background.recounted(text, st.notes), st.notes)
    text = _shared_size(_shared_coordinate(text, st), st)  # "…, both 3 high": every one's
    text = viewpoint.take(text, st.notes)  # "I'm opposite the robot … on my left": its right
    text = acceptance.take(text, st.notes)  # "GIVEN an empty table … THEN 2 towers of 3 exist"
    text = normalise(text, st.notes)
    st.notes[:0] = corrected
    text = corrections.correct(text, st.notes, st.material)
    text = _opening(text, st)
    _vague_counts(text, st)
    text = _same_one(_margins(_table_sized(_body_measures(text, st), st), st), st)
    text = _take_long_side(text, st)
    text = _take_u_opening(text, st)
    text = outline_corners(text, st)  # before the gaps are taken: it says one
    text = _step_rise(text, st)
    text = spacing.take_centres(text, st)
    text = spacing.take_span(text, st)
    text = spacing.take_gap(text, st)
    text = claims.take(text, st)
    text = _faces_at(text, st)
    text = rewrite(text, st)
    text = text.strip()
    doc = parse(text)
    phrases, rels = find_phrases(doc)
    said = list(st.notes)
    structures = fill_slots(phrases, rels, st, doc)
    structures = _asked_then_described(phrases, structures, st, doc)
    structures = _apply_shared(structures, st)
    structures = _u_opening(_long_side(structures, st), st)
    if not structures and any(p.undone for p in phrases):
        raise SpecError(
            f"'{command.strip()[:60]}' takes back everything it names: nothing is left to "
            "build; say what to build instead",
            understood={},
        )
    if not structures:
        # nothing recognised: correct harder (words the English vocabulary knows too, "wal"),
        # then read a structure-less description ("something small") as a tower
        retry, fixed = typos.correct(text, aggressive=True)
        if not fixed:
            retry, fixed = _open(text, st.delegated)
        if fixed:
            st = ReadState(command, cell, notes=said + fixed)  # not the failed reading's
            text = retry
            doc = parse(text)
            phrases, rels = find_phrases(doc)
            structures = fill_slots(phrases, rels, st, doc)
    if not structures:
        down = next((n for n in st.notes if "cannot take down" in n), None)
        if down is not None:
            raise SpecError(down.removeprefix("ignored "), understood=understood_summary(doc))
        no_structure(st, doc, command)
    relations, drafts = relate(phrases, rels, structures, st)
    relations = _stacking_on(relations, drafts, phrases, st)
    drafts = _apart(drafts, st)
    relations, drafts = _gap_of_relation(relations, drafts, st)
    _gap_around_middle(drafts, st)
    touch = _touching(text) or _RIGHT_BY.search(command)  # "right behind it": against it
    if touch and any(r.kind == "next_to" and r.gap_m is None for r in relations):
        # "directly to its left, touching it": no gap between the two
        relations = [
            r.model_copy(update={"gap_m": 0.0}) if r.kind == "next_to" and r.gap_m is None else r
            for r in relations
        ]
        st.notes.append(f"read '{touch.group(0)}' as no gap between the structures beside")
    elif touch and not relations and st.gap_m is None and len(drafts) >= 2:
        # "two towers of 4 side by side, touching": the separate structures stand touching
        st.gap_m = 0.0
        said = touch.group(0).lower().split()
        st.material = [w for w in st.material if w.lower() not in said]
        st.notes = [n for n in st.notes if not any(n.startswith(f"ignored '{w}'") for w in said)]
        st.notes.append(f"read '{touch.group(0)}' as no gap between the structures")
    if st.flanking:  # "a tower on either side of it": apart from it, as separate structures
        relations = [
            r.model_copy(update={"gap_m": cell.design.structure_gap})
            if r.at in ("ends", "sides") and r.kind == "next_to" and r.gap_m is None
            else r
            for r in relations
        ]
    drafts = spacing.apply_span(drafts, st)
    specs = [check_family(s, st.notes, st.material, part_m=cell.cube[0]) for s in drafts]
    specs = [_arch_overall(s, command, cell.cube[2], st) for s in specs]
    specs = [_overall_with_top(s, command, st) for s in specs]
    specs = _placed_by_face(specs, st)
    for s in specs:
        if s.shape in ("t_shape", "cross") and s.length and s.length % 2 == 0:
            # "a T, the top four cubes wide": the generator centres the stem on an odd bar
            what = "T's bar is" if s.shape == "t_shape" else "cross is"
            st.material.append(f"{s.shape.replace('_', ' ')} {s.length} long")
            st.notes.append(f"a {what} built an odd number of cubes long, so that a cube is its "
                            f"middle: {s.length + 1} long, not {s.length}")  # fmt: skip
    if st.no_stack:
        specs = [unstack(s, st) for s in specs]
    taken_back = re.search(
        r"\b(?:no|wait|actually|sorry|instead|rather|i\s+mean|make\s+that|scratch|not)\b",
        command,
        re.I,
    )  # "going up to the left, no wait, to the right": one way, corrected
    climbs = {m.group(1).lower() for m in _CLIMBS.finditer(command)} if not taken_back else set()
    stairs = [s for s in specs if s.shape == "staircase"]
    if len(climbs) > 1 and len(stairs) == 1:
        # "a staircase going up to the left and going up to the right": which way is not clear
        st.material.append("directions " + " and ".join(sorted(climbs)))
        st.notes.append(f"the staircase is said to climb towards {' and '.join(sorted(climbs))}; "
                        "a staircase climbs one way — say which")  # fmt: skip
    for word in dict.fromkeys(re.findall(r"[a-z]+", command.lower())):
        family = _ROUND_LIKENESS.get(word)
        if family and any(s.shape == family for s in specs):
            # "a cone about 15 cm high": cubes cannot make it round; the nearest is stepped
            st.notes.append(f"read '{word}' as a {family}: cubes cannot make a round {word}, "
                            f"so it is stepped")  # fmt: skip
    if st.region_all:
        related = {r.subject for r in relations}
        opposite = lx.OPPOSITE_SIDE.get(st.region_all.split()[-1])
        for s in specs:
            if opposite and s.region and opposite in s.region.split():
                # "keep everything on the right half, the left half is where the forklift
                # goes. A wall of 5": a structure placed where everything should not be
                st.material.append(f"{s.shape} on the {s.region}")
                st.notes.append(
                    f"the {s.shape} is read on the {s.region}, but everything should stay on "
                    f"the {st.region_all}; say where it goes"
                )
        specs = [
            s
            if s.region or s.at_x is not None or s.at_y is not None or k in related
            else s.model_copy(update={"region": st.region_all})
            for k, s in enumerate(specs)
        ]
    specs = _place_for_all(text, specs, relations, st)
    if st.no_beams:
        for s in specs:
            if s.shape in ("bridge", "arch", "canopy") or s.part == "beam":
                st.material.append("no beams")
                st.notes = [n for n in st.notes if not n.endswith("': built of cubes only")]
                a = "an" if s.shape[0] in "aeiou" else "a"
                st.notes.append(f"ignored 'no beams': {a} {s.shape} here is built with beams")
    if len(specs) > 50:
        raise SpecError(
            f"{len(specs)} structures is more than 50", understood=understood_summary(doc)
        )
    relations = _one_each(relations, st)
    relations = _triangle(relations, len(specs), st)
    relations, specs = _sides_apart(relations, specs, st)
    specs, relations = _listed(specs, relations, st)  # named left to right: placed right to left
    specs = _different(_ordered(specs, relations, st), st)
    rows_named = re.search(r"\b(?:rows?|lines?|in\s+a\s+row)\b", text, re.IGNORECASE)
    guessed = [
        s for s in specs if s.shape in ("row", "wall") and (getattr(s, "length", None) or 2) > 1
    ]
    things = _THINGS.search(text) or _THINGS.search(command)  # "I need two things." went
    count_word = (things.group(1) or things.group(2)).lower() if things else "0"
    asked = int(words_to_numbers([count_word])[0])
    if things and asked != len(specs):
        # "two things, under 5 cubes high": one structure built of the sizes said, not two
        st.material.append(things.group(0))
        st.notes.append(
            f"ignored '{things.group(0)}': {len(specs)} structure(s) built; name each of them, "
            "or leave SDI the choice without sizes"
        )
    apart = next((n for n in st.notes if n.endswith(_APART_ANYWAY)), None)
    if apart is not None and len(specs) < 2 and getattr(specs[0], "gap_m", None) is None:
        # "two 2 by 2 cakes … with one cube of air between them": one structure was built, so
        # there is nothing to stand apart — what was asked was more than one
        between = apart.removeprefix("read '").removesuffix(f"' as {_APART_ANYWAY}")
        st.material.append(between)
        st.notes.remove(apart)
        st.notes.append(f"ignored '{between}': one structure was built, with nothing to stand "
                        "apart from; name each structure")  # fmt: skip
    if len(specs) > 1 and _GUESSED_ROW in st.notes and guessed and not rows_named:
        # "five cubes long, three tall - such a wall": parts said apart from the structure they
        # size, built as a row of their own beside it: a guess that is not what was asked
        st.material.append("parts with no structure named")
        st.notes.append("a row was guessed for parts said with no structure, beside the "
                        "structures named; say which structure they belong to")  # fmt: skip
    try:
        spec = Spec(
            structures=tuple(specs),
            relations=tuple(relations),
            line=st.line if st.line and len(specs) > 1 else None,
            grid=_grid(st, len(specs) - len({r.subject for r in relations})),
            notes=tuple(dict.fromkeys(st.notes)),
        )
    except ValueError as exc:  # one line, without the validator's framing
        errors = getattr(exc, "errors", None)
        why = errors()[0]["msg"].removeprefix("Value error, ") if errors else str(exc)
        raise SpecError(
            f"the structures cannot be related: {why}", understood=understood_summary(doc)
        ) from None
    spec = spacing.pitches(spacing.apply_gap(spec, st), st)
    cut = _CUT_OFF.search(command)
    if cut:  # "Tower of": the command stops mid-phrase, its size unsaid
        st.material.append(cut.group(1))
        st.notes.append(f"the command stops after '{cut.group(1)}': what follows it is missing")
    said_words = re.findall(r"[A-Za-z]{2,}", text)
    unknown = list(dict.fromkeys(w for w in said_words if not typos.known_word(w)))
    if len(unknown) >= 3 and len(unknown) >= 0.25 * len(said_words):
        # "Ek tower banao, chaar cube ka": a command partly in another language
        st.material.append("words SDI does not know")
        st.notes.append(f"ignored {', '.join(repr(w) for w in unknown[:6])}: words SDI does "
                        "not know (another language?); say it in English")  # fmt: skip
    coherence.check(doc, spec, st, {k for p in phrases for k in p.tokens})
    claims.check(spec, st)
    _bare_among_sized(spec, phrases, st)
    return Reading(
        command=command,
        text=text.strip(),
        spec=spec,
        phrases=tuple(p.text for p in phrases if p.text and p.ref is None),
        notes=tuple(dict.fromkeys(st.notes)),
        ignored=tuple(dict.fromkeys(st.ignored)),
        material=tuple(dict.fromkeys(st.material)),
    )


def _asked_then_described(
    phrases: list[Phrase], structures: list[StructureDraft], st: ReadState, doc: Doc
) -> list[StructureDraft]:
    """ "Is it ok to put a small pyramid on top of a block? Maybe a 3 by 3 block two high, with
    a pyramid of 2 levels sitting on it?": structures asked about with no size, then described
    with sizes in a later sentence, are the ones described (built once)."""
    asked = [
        q for q in phrases
        if q.count and q.spec is not None and q.tokens
        and doc[q.tokens[0]].sent.text.rstrip().endswith("?")
    ]  # fmt: skip  # ("Could a ring fit around a 2x2 block? Try a ring six by six around a 2x2
    # block": sized, and said again after it)
    if asked:  # the first question only: a later one may be the description
        first = doc[asked[0].tokens[0]].sent.start
        asked = [q for q in asked if doc[q.tokens[0]].sent.start == first]
    if not asked or _ANOTHER.search(st.command):
        return structures
    first_sent = doc[asked[0].tokens[0]].sent.start
    if any(doc[q.tokens[0]].sent.start != first_sent for q in asked):
        return structures  # one question only
    later = [q for q in phrases if q.count and q.spec is not None and q.tokens
             and doc[q.tokens[0]].sent.start > first_sent]  # fmt: skip
    said = [structures[q.first + k].shape for q in asked for k in range(q.count)]
    after = [structures[q.first + k].shape for q in later for k in range(q.count)]
    if not later or any(said.count(f) > after.count(f) for f in set(said)):
        return structures
    out = list(structures)
    for q in sorted(asked, key=lambda q: q.first, reverse=True):
        del out[q.first : q.first + q.count]
        for r in phrases:
            if r.count and r.first > q.first:
                r.first -= q.count
        q.count, q.undone = 0, True
    st.notes.append(f"read the question '{doc[asked[0].tokens[0]].sent.text.strip()}' as asking "
                    "for the structures described after it")  # fmt: skip
    return out


def _bare_among_sized(spec: Spec, phrases: list[Phrase], st: ReadState) -> None:
    """A structure named with no size or place, unrelated to the others, beside structures the
    command sizes ("Hi Sam - table's clear …: a 2 by 2 block, 3 high"): a default one built
    from a word that may not ask for one; said, never a silent success."""
    if len(spec.structures) < 2 or st.delegated or _TOGETHER.search(st.command):
        return  # "a T and a cross next to each other": placed together, as said
    related = {k for r in spec.relations for k in (r.subject, r.object)}
    sized = [k for k, s in enumerate(spec.structures) if s.model_fields_set - _NO_SIZE]
    if not sized:
        return
    for k, s in enumerate(spec.structures):
        if k in related or s.model_fields_set - _NO_SIZE:
            continue
        own = next((p for p in phrases if p.count and p.first <= k < p.first + p.count), None)
        if own is not None and own.count == 1:
            said = own.text.strip()
        else:  # the word of the command that named it ("plinth"), else its family
            words = re.findall(r"[a-z]+", (own.text if own is not None else "").lower())
            said = next((w for w in words if lx.SHAPE_WORDS.get(w) == s.shape), s.shape)
        if own is not None and own.count == 1 and _SIZED.search(said):
            continue  # "two of them, and a row": a count said with it
        st.material.append(said)
        st.notes.append(f"'{said}': a {s.shape.replace('_', ' ')} of its default size, with no "
                        "size or place of its own beside the structures sized; say its size "
                        "if it is meant")  # fmt: skip


_TOGETHER = re.compile(
    r"\b(?:next\s+to|beside)\s+(?:each\s+other|one\s+another)|\bside\s+by\s+side\b", re.IGNORECASE
)
_NO_SIZE = frozenset({"shape", "part", "yaw_deg", "edge", "axis"})
_SIZED = re.compile(r"\d|\b(?:one|two|three|four|five|six|seven|eight|nine|ten)\b", re.IGNORECASE)
_ANOTHER = re.compile(r"\b(?:another|second|more|also|too|as\s+well|again)\b", re.IGNORECASE)


def _sides_apart(
    relations: list[Relation], specs: list[StructureSpec], st: ReadState
) -> tuple[list[Relation], list[StructureSpec]]:
    """ "the left one 5 high, the right one 3 high, 15 cm between them": two structures said
    on opposite sides with the space between them said stand beside each other that far apart
    (each went to its side of the table, the space between them not kept)."""
    if st.gap_m is None or len(specs) != 2 or relations:
        return relations, specs
    first, second = (s.region for s in specs)
    if first is None or second != lx.OPPOSITE_SIDE.get(first) or any(
        s.at_x is not None or s.at_y is not None for s in specs
    ):
        return relations, specs
    st.notes.append(f"read the {first} and the {second} one, {st.gap_m:g} m apart, as side by side")
    beside = Relation(kind="next_to", subject=1, object=0, side=second)
    return [beside], [s.model_copy(update={"region": None}) for s in specs]


def _triangle(relations: list[Relation], n: int, st: ReadState) -> list[Relation]:
    """ "three towers in a triangle": two side by side, the third behind them, centred on the
    pair; of any other count, or structures already related, the words are reported (they
    stood in a line)."""
    if st.triangle is None:
        return relations
    if n != 3 or relations:
        st.material.append(st.triangle)
        st.notes.append(f"ignored '{st.triangle}': only three separate structures make a "
                        "triangle; they are placed side by side in a line")  # fmt: skip
        return relations
    st.notes.append(f"read '{st.triangle}' as two side by side and the third behind them, "
                    "centred")  # fmt: skip
    return [
        Relation(kind="next_to", subject=1, object=0, side="left", whole=True),
        Relation(kind="next_to", subject=2, object=0, side="back"),
    ]


def _one_each(relations: list[Relation], st: ReadState) -> list[Relation]:
    """A structure is placed by one relation: a second one for the same structure ("one behind
    the other, … between them") is reported, not built."""
    kept: list[Relation] = []
    for r in relations:
        if any(k.subject == r.subject for k in kept):
            st.material.append(f"relation {r.kind}")
            st.notes.append(
                f"ignored '{r.kind.replace('_', ' ')}': structure {r.subject + 1} is already "
                "placed by another relation"
            )
            continue
        kept.append(r)
    return kept


_RIGHT_BY = re.compile(
    r"(?<!\bthe\s)(?<!\bits\s)\b(?:right|immediately)\s+(?:behind|in\s+front\s+of|against)\b",
    re.I,
)
_TOUCHING = re.compile(
    r"(?<!\ball\s)\b(?:touching|flush\s+(?:with|against)|butting\s+(?:up\s+)?against|"
    r"pressed\s+against|up\s+against|against(?=\s+(?:a|an|the|it|them|one|each)\b)|"
    r"leading\s+up\s+to(?=\s+(?:a|an|the|it)\b))\b",
    re.IGNORECASE,
)
"""Structures side by side with no gap: "touching", "against a tower", a staircase "leading up
to" it (its top step reaches it)."""
_DENIED = re.compile(
    r"\b(?:not|never|no|without|avoid|don'?t|doesn'?t|mustn'?t|shouldn'?t|isn'?t|aren'?t)\b",
    re.IGNORECASE,
)


def _touching(text: str) -> re.Match[str] | None:
    """The first "touching" said for the structures, not denied in its clause ("I don't want
    them touching" was read as no gap, silently)."""
    for m in _TOUCHING.finditer(text):
        if not _DENIED.search(re.split(r"[.;,!?]", text[: m.start()])[-1]):
            return m
    return None


_GUESSED_ROW = "no structure named: placed the parts in a row"


_SHARED = re.compile(
    r"\s*,\s*(?:and\s+)?(?:both|each(?:\s+one)?|all(?:\s+of\s+them)?|(?:all\s+)?(?:the\s+)?same\s+"
    r"height(?:\s+of)?)\s+(?:(?:are|is|being)\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|"
    r"ten)\s*(?:cubes?\s+)?(high|tall|long)?\s*(?=$|[.;!])",
    re.IGNORECASE,
)


# "a tower at the back left and another at the front right, 4 cubes each"
_SHARED_AFTER = re.compile(
    r"(?<!\btaller)(?<!\bhigher)\s*,\s*(?:and\s+)?(?:with\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*"
    r"(?:cubes?\s*|(high|tall|long)\s+)(?:each|apiece|both|for\s+(?:each|both))\s*(?=$|[.;!])",
    re.IGNORECASE,
)


# "Two walls, one at the front and one at the back. Both walls are 3 long.": a sentence of
# its own that sizes every structure named
_SHARED_SENTENCE = re.compile(
    r"(?:^|(?<=[.;!?]))\s*(?:and\s+)?(?:both|all|they(?:\s+all)?|each|(?:all|both|each)\s+of\s+them|"
    r"the\s+(?:two|three|four))(?:\s+(?:" + shape_alternation() + r"))?\s+"
    r"(?:are\s+|is\s+|should\s+be\s+|must\s+be\s+|will\s+be\s+|need\s+to\s+be\s+|stand\s+)?"
    r"(\d+|one|two|three|four|five|six|seven|"
    r"eight|nine|ten)\s*(?:cubes?\s+)?(high|tall|long)\s*(?:each)?\s*(?:[.!;]|$)",
    re.IGNORECASE,
)


_N_WORD = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
# "both 3 long 2 high": one size said for every structure per dimension
_SHARED_TWO = re.compile(
    r"\b(both|each|all)\s+(" + _N_WORD + r")\s+(?:cubes?\s+)?(long|high|tall)\s*"
    r"(?:,\s*|and\s+|by\s+)?(" + _N_WORD + r")\s+(?:cubes?\s+)?(long|high|tall)\b",
    re.IGNORECASE,
)


_PLACE_FOR_ALL = re.compile(
    r",\s*(?:and\s+)?(?:(?:all|both|each)\s+)?(?:(?:evenly|equally)\s+spaced(?:\s+out)?\s+|spaced\s+out\s+|"
    r"(?:side\s+by\s+side|in\s+a\s+(?:row|line))\s+)?(?:along|at|on|in|across|to)\s+the\s+(?:[a-z]+\s+){0,2}?"
    r"(?:back|front|left|right|middle|centre|center)(?:\s+(?:left|right|edge|side|half|corner))?"
    r"\s*(?:[.!]\s*)?$",
    re.IGNORECASE,
)
"""'a tower of 2, a tower of 4 and a tower of 6, evenly spaced along the back': a place said
once after a list, with a comma, for all of it."""


def _place_for_all(
    text: str, specs: list[StructureSpec], relations: list[Relation], st: ReadState
) -> list[StructureSpec]:
    """The place said after a list of structures, with a comma, is every one's (it went to the
    last only, silently), when nothing else places them."""
    m = _PLACE_FOR_ALL.search(text)
    last = specs[-1] if specs else None
    if m is None or relations or len(specs) < 2 or last is None or last.region is None:
        return specs
    if any(s.region or s.at_x is not None or s.at_y is not None for s in specs[:-1]):
        return specs
    sentence = re.split(r"[.;!?:\n]", text[: m.start()])[-1].lower()
    if sum(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", sentence)) < len(specs):
        return specs  # "A wall of 4. A tower of 2, at the back.": the one in its sentence
    st.notes.append(f"read '{m.group(0).strip(' ,.!')}' as the place of all {len(specs)}")
    return [s.model_copy(update={"region": last.region}) for s in specs]


_SHARED_AT = re.compile(
    r"\s*,?\s*(?:and\s+)?(?:both|all(?:\s+of\s+them)?|each(?:\s+one)?)\s+(?:(?:are|is|standing)\s+)?"
    r"(?:at\s+)?([xy])\s*=\s*(-?\d+(?:\.\d+)?\s*(?:mm|cm|m)?)\b",
    re.IGNORECASE,
)


def _shared_coordinate(text: str, st: ReadState) -> str:
    """ "a tower at y = 0.5 m and a tower at y = 0.1 m, both at x = 0.4 m": the coordinate said
    once for every structure placed by the other one (it went to the last one only,
    silently)."""
    m = _SHARED_AT.search(text)
    if m is None:
        return text
    axis, value = m.group(1).lower(), m.group(2).strip()
    other = "y" if axis == "x" else "x"
    rest = text[: m.start()] + text[m.end() :]
    at = rf"\bat\s+{other}\s*=\s*-?\d+(?:\.\d+)?\s*(?:mm|cm|m)?\b"
    placed = list(re.finditer(at, rest, re.I))
    if len(placed) < 2 or re.search(rf"\b{axis}\s*=", rest, re.I):
        return text
    for p in reversed(placed):
        rest = rest[: p.end()] + f", {axis} = {value}" + rest[p.end() :]
    st.notes.append(f"read '{m.group(0).strip(' ,')}' as the {axis} of each of the "
                    f"{len(placed)}")  # fmt: skip
    return rest


def _shared_size(text: str, st: ReadState) -> str:
    """ "two walls 4 long, one on the left and one on the right, both 3 high": a size said once
    at the end for every structure named (it went to the last one only, silently)."""
    text = _SHARED_TWO.sub(r"\1 \2 \3, \1 \4 \5", text)
    for _ in range(2):
        shared = _one_shared(text, st)
        if shared == text:
            break
        text = shared
    return text


def _one_shared(text: str, st: ReadState) -> str:
    m = _SHARED.search(text) or _SHARED_AFTER.search(text) or _SHARED_SENTENCE.search(text)
    cubes = m is not None and m.group(2) is None and "cube" in m.group(0).lower()
    if m is None or (m.group(2) is None and "same" not in m.group(0).lower() and not cubes):
        return text
    value = words_to_numbers([m.group(1).lower()])[0]
    if not value.isdigit() or (cubes and value == "1"):
        return text  # "half a dozen pancakes in one stack, one cube each": what each one is
    key = "length" if (m.group(2) or "").lower() == "long" else "cubes" if cubes else "height"
    st.shared.append((key, int(value), m.group(0).strip(" ,")))
    return text[: m.start()] + text[m.end() :]


def _apply_shared(structures: list[StructureDraft], st: ReadState) -> list[StructureDraft]:
    """The size said for every structure, on each that has no such size of its own."""
    for shared in st.shared if structures else []:
        structures = _apply_one(structures, shared, st)
    return structures


def _apply_one(
    structures: list[StructureDraft], shared: tuple[str, int, str], st: ReadState
) -> list[StructureDraft]:
    key, value, said = shared
    fits = {"height": ("tower", "wall", "block", "grid", "row", "castle", "enclosure", "canopy",
                       "bridge"),  # a table's or a bridge's height is its legs'
            "length": ("wall", "row", "grid", "block"), "cubes": ("tower",)}[key]  # fmt: skip
    key = "height" if key == "cubes" else key  # "…, 4 cubes each": towers' height
    out, other, taken = [], [], False
    for s in structures:
        own = getattr(s, key)
        if key == "length" and s.shape == "l_shape" and own is None and s.width is None:
            # "two walls forming a corner, each 4 long": each wall an arm of the L
            out.append(s.model_copy(update={"length": value, "width": value}))
            st.notes.append(f"read '{said}' as each arm of the L: {value} long")
            return out + structures[len(out) :]
        if s.shape in fits and own is None and getattr(s, f"{key}_m") is None:
            s = s.model_copy(update={key: value})
            taken = True
        elif own is not None and own != value:
            other.append(f"{s.shape} {key} {own}")
        elif own == value:
            taken = True
        out.append(s)
    if other:  # "two towers of 3, both 4 high": which is meant is not said
        st.material.append(said)
        st.notes.append(f"ignored '{said}' for the {', '.join(other)} said before")
    elif not taken:  # "a pyramid, each 2 high": no structure it can size
        st.material.append(said)
        st.notes.append(f"ignored '{said}': no structure named has that size")
    else:
        st.notes.append(f"read '{said}' as every structure's {key}: {value}")
    return out


_APART_ANYWAY = "standing apart (separate structures always do)"
"""The end of the note on "space between them" (rewrites): what separate structures do anyway."""


def _listed(
    specs: list[StructureSpec], relations: list[Relation], st: ReadState
) -> tuple[list[StructureSpec], list[Relation]]:
    """ "left to right: a tower, then a block, then a pyramid": separate structures stand from
    right to left in the order named, so a list given from the left is placed reversed. A cube
    said on top of one of them keeps the line ("towers of 2, 3 and 4 from front to back, then add
    a cube on top of the first one")."""
    stacked = {r.subject for r in relations}
    if (
        st.listing is None
        or len(specs) - len(stacked) < 2
        or any(r.kind != "on_top_of" or r.at is not None for r in relations)
    ):
        return specs, relations
    if st.listing in ("front to back", "back to front") and st.line is None:
        st.line = "x"  # "four towers … placed in that order from front to back": one behind another
    elif st.line is None:
        st.line = "y"  # "a tower, a wall and a block from left to right": across, even if tight
    if st.listing in ("left to right", "back to front"):
        st.notes.append(f"the structures named {st.listing}, placed in that order")
        last = len(specs) - 1
        turned = [
            r.model_copy(update={"subject": last - r.subject, "object": last - r.object})
            for r in relations
        ]
        return specs[::-1], turned
    return specs, relations


def _different(specs: list[StructureSpec], st: ReadState) -> list[StructureSpec]:
    """ "a handful of towers, none of them the same height": heights one apart."""
    if st.distinct is None:
        return specs
    same = [k for k, s in enumerate(specs) if s.shape == specs[0].shape]
    heights = [getattr(specs[k], "height", None) for k in same]
    if len(same) < 2 or len(set(heights)) == len(heights) or not hasattr(specs[0], "height"):
        return specs
    start = 2 if len(same) <= 9 else 1
    out = list(specs)
    for n, k in enumerate(same):
        out[k] = out[k].model_copy(update={"height": min(start + n, 10), "height_m": None})
    st.notes.append(f"read '{st.distinct}' as heights "
                    f"{', '.join(str(min(start + n, 10)) for n in range(len(same)))}")  # fmt: skip
    return out


_AT = {"front": "at the ", "back": "at the "}


def _ordered(
    specs: list[StructureSpec], relations: list[Relation], st: ReadState
) -> list[StructureSpec]:
    """ "three towers of 2, 4 and 6, the tallest one in the middle": separate structures stand
    side by side from right to left in the order named; the biggest (or smallest) goes where
    it was asked to."""
    if st.order is None:
        return specs
    said, most, where = st.order
    if most.startswith("shape:"):  # "…, the tower in the middle": the one of that family
        named = [k for k, s in enumerate(specs) if s.shape == most[6:]]
        if len(specs) < 3 or relations or len(named) != 1:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': no line of structures to put it in the middle of")
            return specs
        rest = [s for k, s in enumerate(specs) if k != named[0]]
        st.notes.append(f"'{said}': the {most[6:]} stands in the middle of the line")
        return [*rest[: len(specs) // 2], specs[named[0]], *rest[len(specs) // 2 :]]
    sizes = [getattr(s, "height", None) or getattr(s, "length", None) or 0 for s in specs]
    if len(specs) < 2 or relations or len({s.shape for s in specs}) > 1 or len(set(sizes)) < 2:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': no row of like structures of different sizes to order")
        return specs
    if most == "rise":  # taller towards `where`: the list stands from the right (or front)
        if (where in ("front", "back")) != (st.line == "x"):
            st.material.append(said)
            st.notes.append(f"ignored '{said}': the structures do not stand in a line that way")
            return specs
        up = sorted(range(len(specs)), key=lambda k: sizes[k], reverse=where in ("right", "front"))
        st.notes.append(f"'{said}': the structures stand getting taller to the {where}")
        return [specs[k] for k in up]
    pick = sizes.index(max(sizes) if most == "max" else min(sizes))
    rest = [s for k, s in enumerate(specs) if k != pick]
    if (where in ("front", "back") and st.line != "x") or (where in ("left", "right") and
                                                           st.line == "x"):  # fmt: skip
        st.material.append(said)
        st.notes.append(f"ignored '{said}': the structures do not stand in a line that way")
        return specs
    at = {"middle": len(specs) // 2, "right": 0, "left": len(specs) - 1, "front": 0,
          "back": len(specs) - 1}[where]  # fmt: skip
    place = "in the middle" if where == "middle" else _AT.get(where, "on the ") + where
    st.notes.append(f"'{said}': the {'biggest' if most == 'max' else 'smallest'} one {place}")
    if where != "middle" and pick in (0, len(specs) - 1):
        # "heights 2, 4 and 6, the shortest on the left": the list read from that end
        return specs if pick == at else specs[::-1]
    return [*rest[:at], specs[pick], *rest[at:]]


_ONE_MORE = re.compile(
    r"^[\s,]*(?:and\s+)*(?:then\s+)?(?:one\s+more|another|a\s+third|one\s+again)(?:\s+1-cube)?(?:\s+[a-z]+)?"
    r"(?:\s+(?:time|too|again))?[\s.!,]*$",
    re.IGNORECASE,
)


def _stacking_on(
    relations: list[Relation], drafts: list[StructureDraft], phrases: list[Phrase], st: ReadState
) -> list[Relation]:
    """ "a row of four, then another row on top, and then one more": a copy said with no place
    of its own right after one stacked on the one before it goes on top again."""
    subject_of = {r.subject: r for r in relations}
    out = list(relations)
    for p in phrases:
        k = p.first
        if p.count != 1 or k in subject_of or k < 2 or not _ONE_MORE.match(p.text.strip()):
            continue
        below = subject_of.get(k - 1)
        same = drafts[k].shape == drafts[k - 1].shape or all(
            one_cube(d) for d in drafts[k - 1 : k + 1]
        )  # "Put another cube on it. And another.": a cube like the one before
        if below is None or below.kind != "on_top_of" or below.at is not None or not same:
            continue
        rel = Relation(kind="on_top_of", subject=k, object=k - 1)
        out.append(rel)
        subject_of[k] = rel
        st.notes.append(
            f"read '{p.text.strip(' ,')}' as another {drafts[k].shape} on top, like the one before"
        )
    return out


_SPACED = ("row", "grid")  # the families whose parts can stand apart (a gap of their own)


def _apart(drafts: list[StructureDraft], st: ReadState) -> list[StructureDraft]:
    """ "Three rows, spaced out", "a 2x2 pad and a 3x3 pad, not touching": with several
    structures a vague "apart" is about the structures (which stand apart anyway), not the
    parts inside each one."""
    spaced = any(n.endswith("as a part's width apart") for n in st.notes)
    between = _SIDE_BY_SIDE_GAP.search(st.command)  # "… side by side with a little gap"
    towers = any(d.shape not in _SPACED and d.gap_m is not None for d in drafts)
    if len(drafts) < 2 or not (spaced or between or towers):
        return drafts
    out = []
    for d in drafts:
        if d.shape not in _SPACED and d.gap_m is not None and (
            d.shape == "tower" or st.gap_m in (None, d.gap_m)  # a copy's, said once for both
        ):
            # "a tower of 4, with one block in between", "2 walls side by side with a gap": a
            # tower or a wall has no gaps of its own
            if st.gap_m is None:  # a gap said for the structures already holds ("10 cm apart")
                st.gap_m = d.gap_m
                st.notes.append(f"read the gap said with the {d.shape} as {d.gap_m:g} m between "
                                "them")  # fmt: skip
            out.append(d.model_copy(update={"gap_m": None}))
            continue
        if d.shape in ("row", "grid") and d.gap_m is not None:
            if between and st.gap_m is None:
                st.gap_m = d.gap_m
                st.notes.append(f"read '{between.group(0)}' as {d.gap_m:g} m between them")
            d = d.model_copy(update={"gap_m": None})
            note = "several structures spaced out: the structures stand apart, each one whole"
            if note not in st.notes:
                st.notes.append(note)
        out.append(d)
    return out


def _gap_of_relation(
    relations: list[Relation], drafts: list[StructureDraft], st: ReadState
) -> tuple[list[Relation], list[StructureDraft]]:
    """ "a line of 5 behind it with a bit of a gap": one gap, between the line and the one it
    stands beside, not between the line's own parts."""
    if not _ONE_GAP.search(st.command):
        return relations, drafts
    out = []
    for r in relations:
        d = drafts[r.subject]
        if r.kind == "next_to" and r.gap_m is None and d.shape in ("row", "grid") and d.gap_m:
            st.notes.append(f"read the gap said with the {d.shape} as {d.gap_m:g} m between it "
                            "and the structure beside it")  # fmt: skip
            drafts[r.subject] = d.model_copy(update={"gap_m": None})
            r = r.model_copy(update={"gap_m": d.gap_m})
        out.append(r)
    return out, drafts


def _gap_around_middle(drafts: list[StructureDraft], st: ReadState) -> None:
    """ "two towers, 3 cubes between them, and a tower of 2 in the middle between them": the
    gap said of the two outer ones holds the middle one; the gaps beside it are what is left."""
    said = st.gap_said or ""
    if not st.flanked or st.gap_m is None or not st.gap_first or not _PAIR_GAP.search(said):
        return  # said after the middle one was placed: its own gaps
    middle = [d for d in drafts if d.shape == "tower"]
    part = st.cell.cube[0]
    side = (st.gap_m - part) / 2
    if not middle or side < 0:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': the one between does not fit in it")
        return
    st.notes.append(f"read '{said}' as the gap between the outer two: {side:g} m on each side of "
                    "the one between")  # fmt: skip
    st.gap_m = round(side, 4)


_PAIR_GAP = re.compile(r"\bbetween\s+(?:them|the\s+two)\b|\bapart\b|\bof\s+each\s+other\b", re.I)


_ONE_GAP = re.compile(
    r"\bwith\s+(?:a|one)\s+(?:bit\s+of\s+a\s+|small\s+|little\s+|tiny\s+|slight\s+)?gap\b(?!s)",
    re.I,
)


_SIDE_BY_SIDE_GAP = re.compile(
    r"\bside\s+by\s+side\s*,?\s*(?:with|leaving)\s+(?:a\s+)?(?:\w+\s+){0,2}?(?:gap|space)\b", re.I
)


_GENERIC_NOUNS = re.compile(
    r"\b(something|structure|thing|shape|object|construction|sculpture|build|piece|model)\b",
    re.IGNORECASE,
)


_SPANNED = re.compile(r"\b(?:beams?|lintels?|spans?|symmetr\w*|either\s+side|both\s+sides)\b", re.I)


_THINGS = re.compile(
    r"\b(two|three|four|five|[2-5])\s+(?:different\s+|separate\s+|small\s+|little\s+)?"
    r"(?:things|structures|items|objects|shapes|builds|models)\b|\bquantity\s+(two|three|four|five|[2-5])\b",
    re.IGNORECASE,
)
_CLIMBS = re.compile(
    r"\b(?:going|goes|climbing|climbs|rising|rises|ascending|stepping|leading)\s+up\s+(?:to(?:wards?)?\s+|"
    r"toward\s+)?(?:the\s+)?(left|right|front|back)\b",
    re.IGNORECASE,
)
_ROUND_LIKENESS = {"cone": "pyramid", "cones": "pyramid"}
"""Round things the lexicon reads as a family of cubes: said, not silently squared."""

_LEG_WORDS = re.compile(
    r"\b(?:legs?|pillars?|posts?|columns?|feet|foot|supports?|piers?|sides?|uprights?|jambs?)\b",
    re.IGNORECASE,
)


_OVERALL = re.compile(
    r"\b(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes?\s+(?:high\s+|tall\s+)?|(?:high|tall)\s+)"
    r"(?:overall|in\s+total|altogether|all\s+told|including\s+the\s+(?:beam|top))\b",
    re.IGNORECASE,
)


def _overall_with_top(s: StructureSpec, command: str, st: ReadState) -> StructureSpec:
    """A bridge "4 high overall" is 4 high with its beam: posts one lower (they were 4 high,
    the bridge 5, silently); a table "no taller than three cubes in total" the same, less its
    top of two layers: legs 1 (they were 3, the table 5, silently)."""
    m = _OVERALL.search(command)
    if s.shape not in ("bridge", "canopy") or m is None or _LEG_WORDS.search(
        command[: m.start()][-40:]
    ):
        return s
    said = int(words_to_numbers([m.group(1).lower()])[0])
    if s.height != said:
        return s
    bridge = s.shape == "bridge"
    what, legs, top = ("bridge", "posts", "beam") if bridge else ("table", "legs", "top")
    above = 1 if bridge else 2  # a table's top is two layers of beams
    if said <= above:
        st.material.append(m.group(0))
        st.notes.append(f"ignored '{m.group(0)}': a {what} is at least {above + 1} high ({legs} "
                        f"and the {top})")  # fmt: skip
        return s
    st.notes.append(f"read '{m.group(0)}' as the whole {what}: {legs} {said - above} high and "
                    f"the {top}")  # fmt: skip
    return s.model_copy(update={"height": said - above})


def _arch_overall(s: StructureSpec, command: str, level_m: float, st: ReadState) -> StructureSpec:
    """An arch "3 high" is 3 high overall (its height slot counts the legs under the two
    corbel levels and the beam, 6 overall), unless the legs are the ones sized."""
    if s.shape != "arch" or _LEG_WORDS.search(command):
        return s
    said, words = s.height, f"{s.height} high"
    if said is None and s.height_m is not None:
        said = round(s.height_m / level_m)
        words = f"{s.height_m * 100:g} cm ({said} levels) high"
    numbers = words_to_numbers(re.findall(r"\d+(?:\.\d+)?|[a-z]+", command.lower()))
    if said is None or (s.height is not None and str(said) not in numbers):
        return s  # not said: "a tiny arch" is SDI's small arch
    above = min(2, s.span or 2) + 1  # the corbel levels and the beam
    if said - above < 1:
        # "an archway two cubes high": lower than any arch; its legs, said so
        st.notes.append(f"an arch is at least {above + 1} high (1-cube legs, {above - 1} corbel "
                        f"levels and the beam): read {words} as its legs, {said + above} "
                        "high overall")  # fmt: skip
        if re.search(r"\b(?:in\s+total|overall|altogether|all\s+together|total)\b", command, re.I):
            st.material.append(f"{words} overall")  # said of the whole arch: not what is built
        return s
    st.notes.append(f"read the arch's {words} as its overall height: legs {said - above} "
                    f"high, {above - 1} corbel levels and the beam")  # fmt: skip
    return s.model_copy(update={"height": said - above, "height_m": None})


_RISE = re.compile(
    r",?\s*\b(\d+(?:\.\d+)?)\s*(mm|cm)\s+(?:rise|risers?|step\s+height|(?=steps\b))"
    r"(?:\s+(?:each|per\s+step))?\b",
    re.IGNORECASE,
)


_RISE_OF_EACH = re.compile(
    r"\b(\d+|two|three|four|five|six|seven|eight)\s+(?:risers?|steps?|stairs?)\s+(?:of\s+|at\s+)?"
    r"(\d+(?:\.\d+)?)\s*(mm|cm)\s+(?:high\s+|tall\s+)?(?:each|apiece|per\s+step)\b",
    re.IGNORECASE,
)
"""'4 risers of 5 cm each': how much each step rises (read as the staircase 5 cm high: one
part, silently), said as the rise `_RISE` reads."""
_EACH_RISES = re.compile(
    r"\b(?:each|every)\s+(?:step|stair|riser)\s+(?:(?:is|being)\s+)?(?:(?:rising|rises)\s+"
    r"(\d+(?:\.\d+)?)\s*(mm|cm)\b|(\d+(?:\.\d+)?)\s*(mm|cm)\s+(?:high|tall|up|higher)\b)",
    re.IGNORECASE,
)
"""'each step 5 cm high', 'every step rising 50 mm': the rise of each step (read as the
staircase that high: one part)."""


def _step_rise(text: str, st: ReadState) -> str:
    """ "a staircase, four steps, 50 mm rise each": every step rises one part — said, and
    kept only when the rise is the part's height (a step is one part high)."""
    text = _RISE_OF_EACH.sub(r"\1 steps, \2 \3 rise each", text)  # "4 risers of 5 cm each"
    text = _EACH_RISES.sub(lambda e: f"{e.group(1) or e.group(3)} {e.group(2) or e.group(4)} rise "
                           "each", text)  # fmt: skip
    m = _RISE.search(text)
    if m is None or not re.search(r"\b(?:stair|staircase|steps?)\b", text, re.IGNORECASE):
        return text
    metres = float(m.group(1)) * (0.001 if m.group(2).lower() == "mm" else 0.01)
    said = m.group(0).strip(" ,")
    if abs(metres - st.cell.cube[2]) > 1e-6:  # "100 mm rise each": SDI's steps are one part
        st.material.append(said)
        st.notes.append(f"ignored '{said}': each step rises one part ({st.cell.cube[2]:g} m)")
    else:
        st.notes.append(f"read '{said}' as each step one part high")
    return text[: m.start()] + " " + text[m.end() :]


_SOLID = r"\b(?:walls?|slabs?|blocks?|rows?|rings?|enclosures?|fences?|pens?)\b"
_OPENING = re.compile(
    rf"{_SOLID}[^.;\n]{{0,40}}?(?:,\s*|\s+(?:and|but)\s+|\s+)?\b("
    r"(?:with|leave|leaving|cut|having)\s+(?:an?\s+|one\s+)?(?:(?:small\s+|little\s+)?"
    r"(?:doorway|door|opening|hole|window|archway|entrance)\b(?:\s+(?:in|through)\s+(?:the\s+)?"
    r"(?:middle|centre|center|it))?|gap\s+(?:(?:in|through)\s+(?:the\s+)?(?:middle|centre|center|"
    r"it)|for\s+(?:an?\s+)?(?:door|doorway|window|entrance))(?:\s+for\s+(?:an?\s+)?(?:door|"
    r"doorway|window|entrance))?)|"
    # "leave out one cube on the left side", "leave one cube out of the front side"
    r"(?:leave|leaving|miss|missing|skip|skipping|omit|omitting|take|taking)\s+(?:out\s+)?"
    r"(?:one|1|a|a\s+single)\s+(?:cube|block|brick|part)\s+(?:out\s+)?(?:of|from|on|in)\s+"
    r"(?:the\s+|its\s+)?(?:[a-z-]+\s+){0,2}?(?:side|wall|edge|middle|centre|center)\b)",
    re.IGNORECASE,
)
"""An opening asked in a wall, slab or ring ("a wall with a door in the middle", "leave out one
cube on the left side"): SDI builds them solid."""


_VAGUE = re.compile(
    r"\b(a\s+few|several|a\s+handful\s+of|some|many|lots\s+of|a\s+bunch\s+of)\s+(?:(?:small|little|"
    r"big|tall|short|single|separate|loose)\s+)?(cubes|blocks|bricks|parts|"
    + "|".join(sorted(STRUCTURE_PLURALS, key=len, reverse=True)) + r")\b",
    re.IGNORECASE,
)
"""'a few cubes in a row', 'several towers': a count not said exactly."""


def _vague_counts(command: str, st: ReadState) -> None:
    """A count said vaguely is read as SDI's number for the word; the note says which."""
    for m in _VAGUE.finditer(command):
        said = [w for w in m.group(1).lower().split() if w in QUANTITY_WORDS]
        if said:
            value = QUANTITY_WORDS[said[-1]]
            st.notes.append(f"read '{m.group(1)}' as {value}: the number was not said; say how "
                            "many if it matters")  # fmt: skip


_LONG_SIDE = re.compile(
    r"(?:\s*[,;]?\s*(?:and\s+|then\s+)?(?:turn|rotate|orient|set|lay|place)\s+(?:it|them|the\s+\w+)\s+"
    r"(?:so\s+(?:that\s+)?)?|\s*,?\s*(?:with\s+)?)(?:the|its)\s+(long(?:er)?|short(?:er)?)\s+(?:sides?|"
    r"edges?|way|dimension)\s+(?:(?:runs?|running|goes|going|is|lies|lying|pointing)\s+)?(?:from\s+)?"
    r"(left\s+to\s+right|right\s+to\s+left|side\s+to\s+side|front\s+to\s+back|back\s+to\s+front)\b",
    re.IGNORECASE,
)
"""'Turn it so the long side runs left to right': which way a slab's long side runs."""

_SIDE_BY_SIZE = re.compile(
    r"\s*,?\s*(?:with\s+)?the\s+(\d+|two|three|four|five|six|seven|eight|nine|ten)"
    r"(?:[- ](?:cubes?|parts?|blocks?|bricks?))?(?:\s+(?:sides?|edges?|way|dimension|direction))?"
    r"\s+(?:runs?|running|goes|going|lies|lying|pointing)\s+(?:from\s+)?"
    r"(left\s+to\s+right|right\s+to\s+left|side\s+to\s+side|front\s+to\s+back|back\s+to\s+front)\b",
    re.IGNORECASE,
)
"""'a block 3 wide, 2 deep, with the 3 running left to right': the side of that size runs that way
(the block was turned the other way, silently)."""


def _take_long_side(text: str, st: ReadState) -> str:
    """The way a structure's long (or short) side is said to run, taken from the words."""
    m = _LONG_SIDE.search(text) or _SIDE_BY_SIZE.search(text)
    if m is None:
        return text
    across = m.group(2).lower() in ("left to right", "right to left", "side to side")
    st.long_side = (m.group(1).lower().removesuffix("er"), "y" if across else "x",
                    m.group(0).strip(" ,;"))  # fmt: skip
    return text[: m.start()] + text[m.end() :]


_U_NAMED = re.compile(r"\bu\b(?:[\s-]*shaped?)?", re.IGNORECASE)
_U_OPENS = re.compile(
    r"\s*,?\s*\b(?:with\s+)?(?:(?:its|the)\s+)?(?:open(?:ing|s)?|mouth)(?:\s+(?:end|side))?\s+"
    r"(?:is\s+|should\s+be\s+)?(?:fac(?:es|ing)\s+|point(?:s|ing)\s+)?(?:(?:to(?:wards?)?|toward|at|on)\s+)?"
    r"(?:the\s+)?(front|back|rear|left|right)\b(?:\s+(?:side|edge))?(?:\s+of\s+the\s+table)?",
    re.IGNORECASE,
)
"""'a U, 4 wide, opening toward the back', 'with its open end facing the front': where its
arms point (it was read as the U's place, its opening always at the front)."""


def _take_u_opening(text: str, st: ReadState) -> str:
    """The way a U is said to open, taken from the words (only when a U is named)."""
    m = _U_OPENS.search(text)
    if m is None or not _U_NAMED.search(text):
        return text
    side = m.group(1).lower().replace("rear", "back")
    st.u_opening = (side, m.group(0).strip(" ,"))
    return text[: m.start()] + text[m.end() :]


def _u_opening(structures: list[StructureDraft], st: ReadState) -> list[StructureDraft]:
    """The U named opens the way it was said: its base across that way, arms pointing there
    (a U is built with its arms towards the front, along y)."""
    if st.u_opening is None:
        return structures
    side, said = st.u_opening
    k = next((i for i, s in enumerate(structures) if s.shape == "u_shape"), None)
    if k is None:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': no U to open that way")
        return structures
    axis, yaw = {"front": ("y", 0.0), "back": ("y", 180.0), "left": ("x", 0.0),
                 "right": ("x", 180.0)}[side]  # fmt: skip
    s = structures[k]
    update: dict[str, object] = {"axis": axis, "yaw_deg": yaw}
    if axis == "x" and re.search(r"\b(?:wide|deep|across)\b", st.command, re.I) and not re.search(
        r"\b(?:base|arms?|legs?|sides?)\b", st.command, re.I
    ):  # "4 wide, 3 deep, opening to the left": the base runs front to back, 3 long
        update |= {"length": s.width, "width": s.length}
    st.notes.append(f"read '{said}' as the U's arms pointing to the {side}")
    out = list(structures)
    out[k] = s.model_copy(update=update)
    return out


def _long_side(structures: list[StructureDraft], st: ReadState) -> list[StructureDraft]:
    """The structure named last with two sides runs its long side the way it was said: its
    axis that way, its length the longer side (a 2 by 4 slab 'turned so the long side runs left
    to right' kept its 4 front to back, silently)."""
    if st.long_side is None:
        return structures
    which, along, said = st.long_side
    k = next((i for i in range(len(structures) - 1, -1, -1)
              if structures[i].shape in ("grid", "block", "wall", "row")), None)  # fmt: skip
    if k is None:
        st.material.append(said)
        st.notes.append(f"ignored '{said}': no slab, block or wall to turn")
        return structures
    s = structures[k]
    sides = [v for v in (s.length, s.width) if v is not None]
    if which not in ("long", "short"):  # "the 3 running left to right": the side that long
        size = int(words_to_numbers([which])[0])
        if len(sides) == 2 and sides == [size, size]:
            st.notes.append(f"'{said}': both sides of the {s.shape} are {size}, as built")
            return structures
        if size not in sides:
            st.material.append(said)
            st.notes.append(f"ignored '{said}': the {s.shape} has no side of {size} to turn")
            return structures
        which = "long" if size == max(sides) else "short"
    if which == "short":
        along = "x" if along == "y" else "y"
    update: dict[str, object] = {"axis": along}
    if s.shape in ("grid", "block") and len(sides) == 2:
        update |= {"length": max(sides), "width": min(sides)}
    st.notes.append(f"read '{said}' as the {s.shape}'s long side along {along}")
    out = list(structures)
    out[k] = s.model_copy(update=update)
    return out


_BODY_MEASURE = re.compile(
    r"\b(?:an?\s+|one\s+)?(?:(?:hand|finger|thumb|palm|arm|foot)(?:'s|s)?\s+(?:width|breadth|length|"
    r"span)|hand\s*span)\b|\b(?:knee|waist|shoulder|ankle|chest|hip)[\s-]+(?:high|height|tall)\b",
    re.IGNORECASE,
)
"""'a hand's width high', 'knee-high': a size measured by the body, not one SDI can take."""


_MARGIN = re.compile(
    r"\s*,?\s*\b(?:but\s+|and\s+)?(?P<said>(?:(?:stay|keep(?:\s+it)?|staying|keeping\s+it|"
    r"remaining|be)\s+)?(?:at\s+least\s+)?\d+(?:\.\d+)?\s*(?:mm|cm|m|millimet\w*|centimet\w*)\s+"
    r"(?:away\s+)?(?:from|off|clear\s+of)\s+(?:every|each|all|any|the)\s+(?:of\s+the\s+)?"
    r"(?:table\s+|workspace\s+)?edges?(?:\s+of\s+the\s+(?:table|workspace))?)\b",
    re.IGNORECASE,
)
"""'stay at least 10 cm away from every table edge': a margin SDI does not keep (the table was
built as a canopy, and the 10 cm read as the staircase's height)."""


_SAME_ONE = re.compile(
    r"\(\s*(?:it'?s\s+|it\s+is\s+)?(?:the\s+)?same\s+(?:one|structure|" + shape_alternation()
    + r")\s*\)",
    re.IGNORECASE,
)
"""'tower height = 3 AND tower height = 6 (same tower)': two sizes said of one structure."""


def _same_one(text: str, st: ReadState) -> str:
    """ "(same tower)" after sizes said twice: a contradiction SDI does not choose for (two
    towers were built, silently)."""
    for m in _SAME_ONE.finditer(st.command):  # the brackets are gone from `text`
        said = m.group(0).strip("() ")
        st.material.append(m.group(0))
        st.notes.append(f"ignored '{m.group(0)}': each size said is built as its own structure; "
                        "say the one size meant")  # fmt: skip
        text = re.sub(rf"\(?\s*{re.escape(said)}\s*\)?", " ", text, count=1, flags=re.I)
    return text


def _margins(text: str, st: ReadState) -> str:
    """A margin from the table's edges is reported and left out: SDI places structures inside
    the workspace, not a given distance from its edges."""
    for m in _MARGIN.finditer(text):
        said = m.group("said")
        st.material.append(said)
        st.notes.append(f"ignored '{said}': SDI keeps every part inside the workspace, not "
                        "a margin from its edges; give a place or coordinates")  # fmt: skip
    return _MARGIN.sub(" ", text)


def _body_measures(text: str, st: ReadState) -> str:
    """A size said by a body measure is reported and left out (it was read as nothing, the
    structure built to its default size, silently)."""
    for m in _BODY_MEASURE.finditer(text):
        st.material.append(m.group(0).strip())
        st.notes.append(f"ignored '{m.group(0).strip()}': not a size SDI can measure; say it in "
                        "cubes, cm or mm")  # fmt: skip
    return _BODY_MEASURE.sub(" ", text)


_TABLE_SIZED = re.compile(
    r"\b(?:(?:as|so)\s+(?P<as>wide|long)\s+as|(?:across\s+|along\s+|over\s+)?the\s+(?:whole|full|"
    r"entire)\s+(?P<of>width|length)\s+of)\s+the\s+(?:work\s*)?(?:table|bench|workspace|work\s+area)\b"
    r"|\b(?P<along>along|across|on)\s+the\s+(?:whole|full|entire)\s+(?:length\s+of\s+the\s+)?"
    r"(?P<edge>front|back|rear|left|right)\s+(?:edge|side)\b",
    re.IGNORECASE,
)
"""'a wall as wide as the table', 'a row along the whole front edge': as many parts as the
table's side takes (a wall of the default size was built, silently)."""


def _table_sized(text: str, st: ReadState) -> str:
    """A structure said as long as a side of the table: that many parts, running along it."""
    space, part = st.cell.workspace, st.cell.cube[0]

    def sized(m: re.Match[str]) -> str:
        word = (m.group("as") or m.group("of") or "").lower()
        edge = (m.group("edge") or "").lower()
        across = word in ("wide", "width") or edge in ("front", "back", "rear")
        extent = (space.y_max - space.y_min) if across else (space.x_max - space.x_min)
        n = int(extent / part + 1e-6)
        run = "left to right" if across else "front to back"
        st.notes.append(f"read '{m.group(0).strip()}' as {n} parts long, running {run} (the "
                        f"table is {extent:g} m that way)")  # fmt: skip
        if edge:
            return f" {n} long {m.group('along')} the {edge} edge "
        return f" {n} long running {run} "

    return _TABLE_SIZED.sub(sized, text)


def _opening(text: str, st: ReadState) -> str:
    """The opening asked taken out of the words read, and said not built (it was read as a
    bridge or a one-cube tower beside the structure)."""
    m = _OPENING.search(text)
    if m is None:
        return text
    said = m.group(1)
    st.material.append(said)
    st.notes.append(f"ignored '{said}': SDI builds walls, rings and slabs solid, with no "
                    "opening in them")  # fmt: skip
    cut = m.start(1)
    while cut > 0 and text[cut - 1] in " ,:":
        cut -= 1
    before = re.sub(r"(?:,|\band|\bbut|\bnot\s+closed:?)\s*$", "", text[:cut], flags=re.I)
    return before.rstrip(" ,") + text[m.end(1) :]


_CUT_OFF = re.compile(
    r"\b(of|with|and|by|at|from|the|an?|than|into|onto)\s*[,;:-]*\s*$",
    re.IGNORECASE,
)
_PLACED_IT = re.compile(
    r"\b(?:keep|put|place|set|move|stand|have)\s+(?:it|them)\s+(?:on|in|at|to|towards|near)\b", re.I
)
_CHOSEN = (
    "tower of 3",
    "row of 3",
    "pyramid of 2 levels",
    "2 by 2 slab",
    "bridge with pillars of 2",
)
"""What SDI builds when asked for several things of its own choosing: one of each, in turn."""


def _open(text: str, delegated: str | None) -> tuple[str, list[str]]:
    """An open description with no family named: the family its size words suggest; when the
    choice was left to SDI ("build whatever you like"), a small bridge if a beam or a
    symmetry is asked for, else a tower of 3."""
    m = _GENERIC_NOUNS.search(text)
    said = set(re.findall(r"[a-z]+", text.lower()))
    if delegated and not (m and said & set(lx.SIZE_WORDS)):
        many = _THINGS.search(text)
        n = int(words_to_numbers([(many.group(1) or many.group(2)).lower()])[0]) if many else 1
        if 2 <= n <= len(_CHOSEN):  # "build three different things, you choose what"
            chosen = _CHOSEN[:n]
            note = (f"no structure named and the choice left to SDI: built {n} of its choosing, "
                    f"{', '.join(chosen)}")  # fmt: skip
            return f"{text} , " + " and ".join(f"a {c}" for c in chosen), [note]
        family = "bridge with pillars of 2" if _SPANNED.search(text) else "tower of 3"
        note = f"no structure named and the choice left to SDI: built a {family}"
        if _PLACED_IT.search(text):  # "…, but keep it on the left": it is the one SDI builds
            return f"a {family} . {text}", [note]
        return f"{text} , a {family}", [note]
    if not m or not said & set(lx.SIZE_WORDS):
        return text, []  # "build something": nothing to go on
    if said & {"wide", "flat", "low", "broad", "long", "spread"}:
        family = "platform" if not said & {"long"} else "row"
    else:
        family = "tower"
    note = f"no structure named: read '{m.group(0)}' as a {family}"
    return text[: m.start()] + family + text[m.end() :], [note]


def _grid(st: ReadState, free: int) -> tuple[int, int] | None:
    """Rows by columns for the `free` separate structures said to stand in a square or grid
    ("four towers in a square": 2 x 2; "six stacks in a grid": 2 x 3); a count the words
    cannot arrange is reported, and the structures stand in a line."""
    if st.grid is None:
        return None
    rows, cols, said = st.grid
    if rows == 0:  # only the shape was said: the most nearly square arrangement
        rows = max((r for r in range(1, int(free**0.5) + 1) if free % r == 0), default=1)
        cols = free // rows
        if rows == 1 or (said.endswith("square") and rows != cols):
            rows = cols = 0  # five in a grid, six in a square: no such arrangement
    if free < 2 or rows * cols != free:
        st.material.append(said)
        st.notes.append(
            f"ignored '{said}': {free} separate structure(s) cannot stand in "
            + (f"{rows} rows of {cols}" if rows else "that arrangement")
            + "; they are placed side by side in a line"
        )
        return None
    st.notes.append(f"read '{said}' as {rows} rows of {cols}, one behind the other")
    return rows, cols
