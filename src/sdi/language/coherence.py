"""Coherence: does the reading show what the command's sentence structure says?

Accounting (`sdi.language.accounting`) makes sure every *word* is used or reported. A reading
can still use every word and miss what the words say together: "On the base, put a tower of
3" read as a base and a tower side by side uses every word. Two checks on the parse find
such readings and make them incomplete (``partial``), with a note naming the words:

- **Relations**: a relation word ("on", "behind", "around", "between", "across" …) whose
  object in the parse is a structure ("the base", "a row of 3") or a pronoun ("it",
  "them"), in a reading with several structures and no relation between any of them.
- **Counts**: a number that counts a structure noun ("two towers", "three stacks") when the
  reading has fewer structures than that and none that is made of several (a bridge of two
  towers, a castle of four, a grid of rows).
- **Numbers**: every number of the command (above 1) shows in the reading — as a size, a
  count of structures or parts, or a length in any unit the cell knows. A number the grammar
  took but that shows nowhere ("ring 4x4 3 high, 2 of them" built as one ring) was attached
  to the wrong thing or dropped.
- **More than named**: more structures of a family than the operator's words name ("put the
  wall behind the tower, with the tower 3 high and the wall 5 long" read as two walls) — the
  reading added one nobody asked for. Counted only where the words count plainly: a number
  before the noun, one for "a wall", none more for a later "the wall"; words of several
  ("each", "both", "another one", "the corners", cubes) leave the family uncounted.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from sdi.errors import SDIError
from sdi.language.nouns import BEAMS, STRUCTURE_PLURALS
from sdi.language.state import ReadState
from sdi.spec import lexicon as lx
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import Spec

if TYPE_CHECKING:
    from spacy.tokens import Doc, Token

_RELATION_WORDS = frozenset(
    {
        "on", "onto", "atop", "above", "over", "behind", "around", "round", "inside", "within",
        "between", "across", "along", "against", "under", "below", "beneath", "underneath",
        "front", "surrounding", "encircling",
    }
)  # fmt: skip
# "next to", "beside", "alongside" without a side are what side by side already is; parts of a
# structure ("on pillars", "on four legs") belong to it.
_COMPONENTS = frozenset(
    {"pillar", "pillars", "leg", "legs", "post", "posts", "support", "supports"}
)
_MORE = frozenset({"another", "more", "second", "third", "also", "plus", "again", "copy", "extra"})
_POINTERS = frozenset({"it", "them", "its", "their", "this", "that", "these", "those", "both"})
# Families made of several structures the command may have counted separately.
_COMPOSITE = frozenset(
    {"bridge", "arch", "canopy", "castle", "grid", "block", "wall", "enclosure", "pack"}
)


_FACES = frozenset({"edge", "edges", "rim", "top", "perimeter", "side", "sides", "border", "end"})


def _structural(tok: Token) -> bool:
    """`tok` (a relation word's object) names a structure or points at one: its head noun,
    not the phrases hanging from it ("on the left and a row …")."""
    w = tok.lower_
    if w in _COMPONENTS or w in lx.STEP_WORDS:
        return False
    return (
        (w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES)
        or w in _POINTERS
        or w in ("base", "foundation", "platform", "slab", "pad")
        or (w == "top" and tok.head.lower_ == "of" and tok.head.head.lower_ in _FACES)
        or (w in _FACES and any(c.dep_ == "poss" and c.lower_ in _POINTERS for c in tok.children))
    )  # "against its tall end"


def _work_table(tok: Token) -> bool:
    """ "on the table": the work table, not a table to build."""
    return tok.lower_ in ("table", "bench", "workspace") and any(
        c.lower_ in ("the", "this", "our", "my", "your", "that", "work") for c in tok.children
    )


def _relation_cues(doc: Doc, spanned: bool) -> list[str]:
    """Words relating structures; with `spanned` (a bridge, arch or table built), not a beam
    laid on its own pillars ("two pillars 3 high with a beam on them")."""
    cues = []
    for tok in doc:
        if tok.lower_ not in _RELATION_WORDS:
            continue
        if spanned and tok.head.lower_ in BEAMS:
            continue
        objects = [c for c in tok.children if c.dep_ in ("pobj", "dobj", "obj")]
        objects = [o for o in objects if not _work_table(o)]
        if tok.lower_ in ("next", "front"):  # "next to X", "in front of X"
            objects = [c for p in tok.children if p.dep_ == "prep" for c in p.children
                       if c.dep_ == "pobj"]  # fmt: skip
        if any(o.lower_ in ("other", "another") for o in objects):
            continue  # "next to each other", "on top of one another": side by side words
        for o in list(objects):  # "round the edge of the top", "along the rim of the base"
            while o.lower_ in _FACES and (of := _of(o)) is not None and not _work_table(of):
                objects.append(of)  # ("the left side of the table" is the work table's)
                o = of
        if any(_structural(o) for o in objects):
            span = doc[tok.i : max(o.i for o in objects) + 1]
            cues.append(span.text)
    return cues


def _of(tok: Token) -> Token | None:
    """The object of `tok`'s "of" ("the edge of the top" → top)."""
    return next(
        (c for p in tok.children if p.lower_ == "of" for c in p.children if c.dep_ == "pobj"),
        None,
    )


def _count_cues(doc: Doc) -> list[tuple[str, str, int]]:
    cues = []
    for tok in doc:
        if tok.dep_ != "nummod" or tok.head.lower_ not in lx.SHAPE_WORDS or tok.i > tok.head.i:
            continue  # "3 towers 2 high": a number after the noun is a size
        noun = tok.head.lower_
        if noun in lx.AMBIGUOUS_SHAPES or noun in lx.STEP_WORDS or not noun.endswith("s"):
            continue
        if doc[tok.i + 1].lower_ in lx.UNITS_M:
            continue  # "two 15 cm towers": a size in units, not how many
        value = words_to_numbers([tok.lower_])[0]
        if value.isdigit() and int(value) >= 2:
            cues.append((f"{tok.text} {tok.head.text}", lx.SHAPE_WORDS[noun], int(value)))
    return cues


def _counts(spec: Spec) -> set[float]:
    """How many structures the reading builds, in all and of each family, and one fewer ("then
    2 more like it")."""
    families: dict[str, int] = {}
    for s in spec.structures:
        families[s.shape] = families.get(s.shape, 0) + 1
    totals = [len(spec.structures), *families.values()]
    return {float(n) for n in totals} | {float(n - 1) for n in totals}


def _shown(spec: Spec, st: ReadState) -> set[float]:
    """Every size, place and part count the reading shows, in the forms a command may have said
    it (how many structures there are is `_counts`)."""
    from sdi.design.composer import part_sizes
    from sdi.design.shapes import generate

    shown: set[float] = set()
    metres: list[float] = [g for g in [spec.gap_m, *(r.gap_m for r in spec.relations)] if g]
    for s in spec.structures:
        for key, value in s.model_dump(exclude_none=True).items():
            if key.endswith("_m") or key in ("at_x", "at_y"):
                metres.append(float(value))
            elif isinstance(value, int | float) and not isinstance(value, bool):
                shown.add(float(value))
                if isinstance(value, int) and key != "yaw_deg":
                    metres.append(value * st.cell.cube[0])  # "20 cm" read as 4 parts
            elif isinstance(value, list | tuple):
                shown.update(float(v) for v in value if isinstance(v, int | float))
        try:
            boxes = generate(s, part_sizes(st.cell, s.part))
        except (SDIError, ValueError):  # one the composer will refuse: no count to show
            continue
        shown.add(float(len(boxes)))
        levels: dict[float, int] = {}
        for b in boxes:
            levels[round(b.z, 4)] = levels.get(round(b.z, 4), 0) + 1
        shown.update(float(n) for n in levels.values())
        shown.add(float(len(levels)))  # how high it stands, in levels
    for note in st.notes:  # a length a note states ("0.0508 m thick is one layer")
        metres.extend(float(v) for v in re.findall(r"(\d+(?:\.\d+)?) m\b", note))
    for m in metres:
        shown.update(round(m / unit, 2) for unit in lx.UNITS_M.values())
        shown.add(round(m / st.cell.cube[0], 2))
    return shown


def _counts_something(doc: Doc, i: int) -> bool:
    """The number at token `i` counts things: a plural noun follows ("two towers", "2 more",
    "three of them", "two identical ones"), or it stands alone as a count ("make it 3")."""
    after = [t for t in doc[i + 1 : i + 7] if not t.is_punct]
    if not after:
        return True
    if after[0].lower_ in ("more", "of", "others", "again", "copies", "times", "each", "apiece"):
        return True
    # a plural structure noun the tagger took for a verb ("2 T shapes")
    return any(t.tag_ in ("NNS", "NNPS") or t.lower_ in _PLURAL_NOUNS for t in after)


_PLURAL_NOUNS = STRUCTURE_PLURALS | {"shapes"}


_NOT_GEOMETRY = frozenset(
    {"year", "years", "yr", "yrs", "old", "minute", "minutes", "min", "mins", "hour", "hours",
     "hrs", "second", "seconds", "sec", "secs", "percent", "%", "people", "students", "kids",
     "visitors", "day", "days", "week", "weeks", "o'clock", "am", "pm", "times"}
)  # fmt: skip


_LABELS = frozenset(
    {"round", "phase", "version", "entry", "item", "page", "number", "no", "run", "trial", "day",
     "week", "lesson", "exercise", "chapter", "section", "step", "stage", "task", "part", "bay",
     "station", "cell", "line", "shift", "job", "order", "team", "group", "room", "table"}
)  # fmt: skip


_PEOPLE = frozenset(
    {"she", "he", "who", "kid", "child", "son", "daughter", "baby", "boy", "girl", "nephew",
     "niece", "grandson", "granddaughter", "brother", "sister", "cousin", "friend"}
)  # fmt: skip


def _numbers(doc: Doc, tokens: set[int], command: str) -> list[tuple[str, float, int]]:
    """The numbers the operator wrote inside the structures' phrases (not ones a rewrite put
    in, not ages, times or percentages), with their token index."""
    said = set(re.findall(r"\d+(?:\.\d+)?|[a-z]+", command.lower()))
    out = []
    for tok in doc:
        if tok.lower_ == "dozen" and tok.i in tokens:  # "half a dozen", "a dozen", "two dozen"
            half = any(t.lower_ == "half" for t in doc[max(0, tok.i - 2) : tok.i])
            times = words_to_numbers([doc[tok.i - 1].lower_])[0] if tok.i else ""
            if times.isdigit():
                out.append((doc[tok.i - 1 : tok.i + 1].text, 12.0 * int(times), tok.i))
                continue
            start = next(t.i for t in doc[max(0, tok.i - 2) : tok.i + 1] if t.lower_ in
                         ("half", "dozen"))  # fmt: skip
            out.append((doc[start : tok.i + 1].text, 6.0 if half else 12.0, tok.i))
            continue
        if not tok.like_num or tok.i not in tokens or tok.lower_ not in said:
            continue
        after = [t.lower_ for t in doc[tok.i + 1 : tok.i + 3] if t.lower_ != "-"]
        if after and after[0] in _NOT_GEOMETRY:
            continue
        if any(doc[j].like_num for j in (tok.i - 1, tok.i + 1) if 0 <= j < len(doc)):
            continue  # "test 1 2 3": counting aloud, not a size
        if tok.i > 0 and doc[tok.i - 1].lower_ in _LABELS:
            continue  # "round two", "phase 3": a name, not a size
        before = [t.lower_ for t in doc[max(0, tok.i - 2) : tok.i]]
        person = len(before) == 2 and (before[0] in _PEOPLE or doc[tok.i - 2].pos_ == "PROPN")
        if person and before[1] in ("is", "'s", "s", "aged", "turns", "turned"):
            continue  # "she's four", "Emma is six": an age
        value = words_to_numbers([tok.lower_])[0]
        try:
            v = float(value)
        except ValueError:
            continue
        if v > 1:
            out.append((tok.text, v, tok.i))
    return out


# A family named in the words may be built as a part of another ("two towers joined by a beam"
# is a bridge; "a wall around it" an enclosure): the families each one can contain.
_CONTAINS: dict[str, frozenset[str]] = {
    "bridge": frozenset({"tower", "grid", "row", "wall"}),
    "arch": frozenset({"tower", "bridge"}),
    "canopy": frozenset({"tower", "grid", "bridge", "block"}),
    "castle": frozenset({"tower", "enclosure", "wall", "row", "grid"}),
    "enclosure": frozenset({"wall", "row", "tower", "grid", "castle"}),
    "u_shape": frozenset({"wall", "row"}),
    "l_shape": frozenset({"wall", "row"}),
    "t_shape": frozenset({"wall", "row"}),
    "cross": frozenset({"wall", "row"}),
    "block": frozenset({"grid", "row", "wall", "tower", "pack"}),
    "pyramid": frozenset({"grid", "block", "staircase"}),
    "staircase": frozenset({"tower", "row", "wall", "pyramid"}),
    "wall": frozenset({"row", "tower", "grid", "block"}),
    "grid": frozenset({"row", "block", "pack", "wall"}),
    "row": frozenset({"tower", "grid"}),
    "tower": frozenset({"row", "block", "grid"}),
    "pack": frozenset({"tower", "block", "grid", "row"}),
}


def _families_named(doc: Doc, tokens: set[int]) -> dict[str, str]:
    """Structure families the phrases name (the word that names each), parts of a structure
    ("its pillars", "on four legs") and words that only describe ("a square base") aside."""
    named: dict[str, str] = {}
    for tok in doc:
        w = tok.lower_
        if tok.i not in tokens or w not in lx.SHAPE_WORDS or w in lx.AMBIGUOUS_SHAPES:
            continue
        if w in _COMPONENTS or tok.pos_ not in ("NOUN", "PROPN") or tok.dep_ == "compound":
            continue
        if w in ("table", "tables", "bench") and tok.i > 0 and doc[tok.i - 1].lower_ in (
            "the", "this", "our", "my", "your", "that", "work", "of", "on"
        ):  # fmt: skip
            continue  # "on the table": the work table, not a table to build
        named.setdefault(lx.SHAPE_WORDS[w], tok.text)
    return named


_COORDINATE = re.compile(r"[xy](?:\d+(?:\.\d+)?)?")  # "x", "X500": a coordinate said
_ONE_PART = frozenset({"cube", "block", "brick", "cubes", "blocks", "bricks"})
_NEGATIONS = frozenset({"not", "n't", "never", "no", "without", "nor", "neither", "nothing"})
_SCOPE_ENDS = frozenset({",", ".", ";", ":", "!", "?", "-", "but", "and", "instead", "then", "so"})
_NEGATED_RELATIONS: dict[str, str] = {
    "on": "on_top_of", "onto": "on_top_of", "top": "on_top_of", "across": "on_top_of",
    "over": "on_top_of", "above": "on_top_of", "atop": "on_top_of", "around": "around",
    "inside": "around", "within": "around", "surround": "around", "next": "next_to",
    "beside": "next_to",
}  # fmt: skip


def _negated_kept(doc: Doc, spec: Spec) -> list[str]:
    """What a negation excludes that the reading still builds: a family ("don't build a tower")
    or a relation ("don't put anything across them") said nowhere else without a negation."""
    built = {s.shape for s in spec.structures}
    related = (
        {r.kind for r in spec.relations}
        | {
            f"at {side}"
            for s in spec.structures
            for side in (getattr(s, "region", None) or "").split()
            if side in _PLACES.values()
        }
        | {
            "at coordinates"
            for s in spec.structures
            if getattr(s, "at_x", None) is not None or getattr(s, "at_y", None) is not None
        }
    )
    scoped: set[int] = set()
    cues: list[tuple[str, set[str], set[str]]] = []
    for tok in doc:
        if tok.lower_ not in _NEGATIONS:
            continue
        scope = []
        for t in doc[tok.i + 1 : tok.i + 8]:
            if t.lower_ in _SCOPE_ENDS:
                break
            scope.append(t)
        scoped.update(t.i for t in scope)
        families = {
            lx.SHAPE_WORDS[w] for w in (t.lower_ for t in scope)
            if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES and w not in _COMPONENTS
        }  # fmt: skip
        kinds = {_NEGATED_RELATIONS[t.lower_] for t in scope if t.lower_ in _NEGATED_RELATIONS}
        # "it will never stand at the back", "nothing at the back": a place excluded
        kinds |= {f"at {_PLACES[t.lower_]}" for t in scope if t.lower_ in _PLACES}
        if any(_COORDINATE.fullmatch(t.lower_) for t in scope):
            kinds.add("at coordinates")  # "do not place it forward of X500"
        if families or kinds:
            cues.append((doc[tok.i : scope[-1].i + 1].text, families, kinds))
    outside = [t for t in doc if t.i not in scoped and t.lower_ not in _NEGATIONS]
    said_families = {lx.SHAPE_WORDS[t.lower_] for t in outside if t.lower_ in lx.SHAPE_WORDS}
    said_kinds = {_NEGATED_RELATIONS[t.lower_] for t in outside if t.lower_ in _NEGATED_RELATIONS}
    said_kinds |= {f"at {_PLACES[t.lower_]}" for t in outside if t.lower_ in _PLACES}
    if any(_COORDINATE.fullmatch(t.lower_) for t in outside):
        said_kinds.add("at coordinates")
    return [
        cue for cue, families, kinds in cues
        if (families & built) - said_families or (kinds & related) - said_kinds
    ]  # fmt: skip


_PLACES = {"left": "left", "right": "right", "front": "front", "back": "back", "rear": "back"}
_BACK_AS_ADVERB = frozenset({"out", "off", "in", "up", "down", "together", "into", "onto"})
_RIGHT_AS_ADVERB = frozenset(
    {"then", "next", "in", "on", "at", "above", "behind", "beside", "away", "now", "up", "-",
     "by", "against", "under", "below", "there", "here", "so", ",", "hand"}
)  # fmt: skip


def _places_lost(doc: Doc, spec: Spec, st: ReadState, tokens: set[int]) -> list[str]:
    """Place words of the structures' phrases ("at the back left") that no structure, relation
    or note shows: merged or dropped with the structure they placed."""
    shown: set[str] = set()
    for s in spec.structures:
        shown.update((s.region or "").split())
        if s.at_x is not None or s.at_y is not None:
            return []  # coordinates: the places are numbers, checked as numbers
    shown.update(r.side or "" for r in spec.relations)
    noted = " ".join(st.notes).lower()
    lost = []
    for tok, place in _place_words(doc, tokens):
        if place not in shown and tok.lower_ not in noted:
            lost.append(tok.text)
    return lost


def _place_words(doc: Doc, tokens: set[int]) -> list[tuple[Token, str]]:
    """The place words of the structures' phrases ("at the back left"), with the side each
    names; not "put it back", "left to right" or "right next to it"."""

    def word(i: int) -> str:
        return doc[i].lower_ if 0 <= i < len(doc) else ""

    out = []
    for tok in doc:
        place = _PLACES.get(tok.lower_)
        if place is None or tok.i not in tokens or tok.pos_ in ("VERB", "AUX"):
            continue
        if tok.lower_ == "back" and (tok.pos_ == "ADV" or word(tok.i + 1) in _BACK_AS_ADVERB):
            continue  # "take it back out", "put it back": not the back of the table
        if (word(tok.i - 1) in ("to", "-") and word(tok.i - 2) in _PLACES) or (
            word(tok.i + 1) in ("to", "-") and word(tok.i + 2) in _PLACES
        ):
            continue  # "left to right", "front-to-back": a direction, not a place
        if (
            tok.lower_ == "right"
            and word(tok.i - 1) != "the"
            and (tok.i == 0 or word(tok.i + 1) in _RIGHT_AS_ADVERB)
        ):
            continue  # "right then, …", "right next to it", "right-hand"
        out.append((tok, place))
    return out


def _places_at_odds(doc: Doc, spec: Spec, tokens: set[int], gone: str) -> str | None:
    """One structure, no relation, and places said for it on both sides of an axis ("on the
    right, on the left"): the reading can stand on one of them only. Places of structures
    taken back or moved (`gone`, their notes) are not its own."""
    if len(spec.structures) != 1 or spec.relations or spec.structures[0].region is None:
        return None
    said = [(t, p) for t, p in _place_words(doc, tokens) if p not in gone]
    said += [(t, "centre") for t in doc if t.i in tokens and t.lower_ in ("middle", "centre",
             "center") and t.head.lower_ in ("in", "at")]  # fmt: skip
    said.sort(key=lambda tp: tp[0].i)
    sides = {p for _, p in said}
    region = spec.structures[0].region or ""
    across = {"left", "right"} <= sides or ("centre" in sides and sides & {"left", "right"})
    if not (across or {"front", "back"} <= sides):
        return None
    if said[-1][1] in region.split() or (said[-1][1] == "centre" and region == "centre"):
        return None  # the last place said wins: a correction ("on the left. no, the right")
    return ", ".join(dict.fromkeys(t.text for t, _ in said))


# Words the grammar consults without marking them used, and what a reading that keeps them
# builds: a beam ("two towers of 3 and put a beam across"), an opening ("a pad 3 by 3, hollow").
_KEPT_BY = (
    (frozenset({"beam", "beams", "plank", "planks", "lintel", "lintels", "girder", "girders"}),
     frozenset({"bridge", "canopy", "arch", "castle"}), "nothing with a beam"),
    (frozenset({"hollow", "hole", "opening"}),
     frozenset({"enclosure", "castle", "u_shape", "bridge", "arch", "canopy"}), "nothing hollow"),
)  # fmt: skip


def _consulted_lost(doc: Doc, spec: Spec) -> list[tuple[str, str]]:
    """Consulted words the reading builds nothing for, with what it lacks ("two towers of 3
    and put a beam across" read as two towers): (word, lack) pairs."""
    lost = []
    shapes = {s.shape for s in spec.structures}
    beams = any(s.part == "beam" for s in spec.structures)
    for words, families, lack in _KEPT_BY:
        if shapes & families or (beams and "beam" in words):
            continue
        for tok in doc:
            if tok.lower_ not in words:
                continue
            before = {t.lower_ for t in doc[max(0, tok.i - 3) : tok.i]}
            after = {t.lower_ for t in doc[tok.i + 1 : tok.i + 3]}
            if not (before | after) & (_NEGATIONS | {"none", "nope", "skip"}):
                lost.append((tok.text, lack))
                break
    return lost


_REFERENCE_DETS = frozenset({"the", "this", "that", "its", "their", "these", "those", "same"})
_SEVERAL = frozenset({
    "each", "every", "per", "both", "corner", "corners", "ends", "sides", "either", "again",
    "copy", "copies", "same", "more", "twice", "pair", "pairs", "couple", "all", "several",
    "some", "few", "times", "many", "lots", "plenty", "repeat", "identical", "matching",
    # "another one", "a little one", "one in the back right": more, said without the noun
    "one", "ones", "another", "other", "others", "second", "third", "fourth", "fifth", "trio",
    "quartet", "qty", "count", "array", "set", "sets", "x2", "x3", "x4", "shape", "them",
    "mirror", "duplicate",
})  # fmt: skip


def _named_at_most(command: str) -> dict[str, int]:
    """How many structures of each family the operator's words name at most, for a family
    named only in the singular: one for each said with "a" (or bare), none for a later "the
    X" that points back at one named before. A family counted ("two towers": the count cues'
    check), said in the plural or with words of several ("each", "both", "the corners") has
    no bound here."""
    words = re.findall(r"[a-z0-9]+(?:\.[0-9]+)?|[.,;:!?]", command.lower())
    bound: dict[str, int] = {}
    open_ended: set[str] = set()
    for i, w in enumerate(words):
        family = lx.SHAPE_WORDS.get(w)
        if family is None or w in lx.AMBIGUOUS_SHAPES or w in _COMPONENTS or w in lx.STEP_WORDS:
            continue
        if w in ("table", "tables", "bench") and i and words[i - 1] in _REFERENCE_DETS | {"on"}:
            continue  # "on the table": the work table
        before = []
        for v in reversed(words[max(0, i - 3) : i]):
            if v in ".,;:!?":
                break
            before.append(v)
        plural = w.endswith("s") and lx.SHAPE_WORDS.get(w[:-1]) == family
        number = next((v for v in before if words_to_numbers([v])[0].isdigit()), None)
        if plural or (number is not None and before and before[0] == number):
            open_ended.add(family)  # "two towers", "two tower of 5": the count's own check
        elif before and before[0] in _REFERENCE_DETS:
            bound.setdefault(family, 1)  # "the tower": the one named before, or the first
        else:
            bound[family] = bound.get(family, 0) + 1
    return {f: n for f, n in bound.items() if f not in open_ended}


_PLACE = r"(?:front|back|rear|left|right|middle|centre|center)"
_TWO_PLACES = re.compile(
    r"\b" + _PLACE + r"\s+and\s+(?:on\s+|in\s+|at\s+)?(?:the\s+)?" + _PLACE + r"\b", re.IGNORECASE
)


_THEN_COUNT = re.compile(
    r"\bthen\s+(?:\d+|one|two|three|four|five|six|seven|eight)\b(?!\s*(?:x|by)\b)", re.IGNORECASE
)


def _more_than_named(spec: Spec, command: str) -> list[str]:
    """ "Put the tower next to the wall. The tower is 4 high." read as four structures: more of
    a family than the words name — the reading added structures nobody asked for."""
    said = set(re.findall(r"[a-z0-9]+", command.lower()))
    if said & _SEVERAL or said & {"cube", "cubes", "block", "blocks", "brick", "bricks"}:
        return []
    if re.search(r"\d\s*(?:,\s*\d+\s*)*(?:and|&)\s*\d|\bx\s*\d|\d\s*x\b(?!\s*\d)", command, re.I):
        return []  # "towers of 2, 4 and 6", "tower x2": counted by the list
    if _TWO_PLACES.search(command):
        return []  # "a tower of 2 in the front and back": one in each
    out = []
    for family, most in _named_at_most(command).items():
        if family in ("grid", "block", "pack", "enclosure"):
            continue  # "then 2x2 on top": a slab said by its size alone
        if family == "row" and _THEN_COUNT.search(command):
            continue  # "a row of 5, then 3 on it, then 1": rows said by their length alone
        got = sum(s.shape == family for s in spec.structures)
        if got > most >= 1:
            out.append(f"{got} {family.replace('_', ' ')}s where the command names {most}")
    return out


def check(doc: Doc, spec: Spec, st: ReadState, tokens: set[int]) -> None:
    """Notes and material for what the sentence structure says and the reading does not."""
    for word, lack in _consulted_lost(doc, spec):
        st.material.append(word)
        st.notes.append(f"ignored '{word}': the reading builds {lack}")
    for cue in _negated_kept(doc, spec):
        st.material.append(cue)
        st.notes.append(f"ignored '{cue}': the reading still builds what these words exclude")
    lost = list(dict.fromkeys(_places_lost(doc, spec, st, tokens)))
    for word in lost:
        st.material.append(word)
        st.notes.append(f"ignored '{word}': no structure of the reading stands there")
    gone = " ".join(  # the places of structures taken back, changed or removed
        n for n in st.notes
        if "taken back" in n or "(was " in n or re.search(r"\d left of the \d", n)
    ).lower()
    odds = None if lost else _places_at_odds(doc, spec, tokens, gone)
    if odds:
        where = spec.structures[0].region
        st.material.append(odds)
        st.notes.append(f"ignored '{odds}': places that disagree for one structure; "
                        f"built on the {where}")  # fmt: skip
    n = len(spec.structures)
    if n >= 2 and not spec.relations:
        spanned = any(s.shape in ("bridge", "arch", "canopy") for s in spec.structures)
        for cue in _relation_cues(doc, spanned):
            if st.flanked and cue.lower().startswith("between"):
                continue  # placed midway between the places of the two (`composition`)
            st.material.append(cue)
            st.notes.append(
                f"ignored '{cue}': the structures are built side by side, not related as "
                "these words say"
            )
    built = {s.shape for s in spec.structures}
    noted = " ".join(st.notes).lower()
    for family, word in _families_named(doc, tokens).items():
        if family in built or any(family in _CONTAINS.get(b, frozenset()) for b in built):
            continue
        if word.lower() in noted:
            continue  # a note already says what became of it ("the ring filled in")
        st.material.append(word)
        st.notes.append(f"ignored '{word}': the reading builds no {family.replace('_', ' ')}")
    told = {
        w for w in words_to_numbers(
            re.findall(r"\d+(?:\.\d+)?|[a-z]+", " ".join([*st.material, *st.notes]).lower())
        )
    }  # fmt: skip
    unexplained = [
        (t, v, i) for t, v, i in _numbers(doc, tokens, st.command) if f"{v:g}" not in told
    ]
    if unexplained:
        sizes, counts = _shown(spec, st), _counts(spec)
        for text, value, i in unexplained:
            v = round(value, 2)
            # a number only the count of structures explains must count something ("a tower
            # of 2 cubes more" beside another: there are 2, but the 2 counts none of them)
            if v not in sizes and (v not in counts or not _counts_something(doc, i)):
                st.material.append(text)
                st.notes.append(f"ignored '{text}': the number shows nowhere in the reading")
    typos = any(n.startswith("corrected '") for n in st.notes)  # the words said are not all
    for extra in [] if typos else _more_than_named(spec, st.command):
        st.material.append(extra)
        st.notes.append(f"the reading builds {extra}; say how many are meant")
    if any(s.shape in _COMPOSITE for s in spec.structures):
        return
    more = bool(_MORE & set(re.findall(r"[a-z]+", st.command.lower())))
    for cue, family, count in _count_cues(doc):
        got = sum(s.shape == family for s in spec.structures)
        # counted in the operator's words: the rewrites add structure words of their own
        # ("one on the left and one on the right" became "another tower")
        said = sum(
            lx.SHAPE_WORDS.get(w) == family or (family == "tower" and w in _ONE_PART)
            for w in re.findall(r"[a-z]+", st.command.lower())
        )  # a single cube is a tower of one
        named = said or sum(lx.SHAPE_WORDS.get(t.lower_) == family for t in doc)
        # more than counted: only when nothing else names one ("a column between two stacks")
        if f"left of the {count}" in noted:
            continue  # "5 towers, then take away the middle one": 4 left, as asked
        if got == count + 1 and "placed between the two" in noted:
            continue  # "two towers of 3 with one of 5 between them": the one between is more
        if got < count and "the step before taken back" in noted:
            continue  # "3 towers of 2. scratch that, one tower of 6": the count taken back
        if got < count or (got > count and not more and named == 1):
            st.material.append(cue)
            st.notes.append(f"ignored '{cue}': the reading has {got} {family}s, not {count}")
