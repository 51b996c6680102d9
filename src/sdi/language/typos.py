"""Typo correction: an unknown word close to a word the Specifier knows is read as that word.

A word is a candidate only if it is unknown both to the lexicon and to a list of English words,
has at least four letters, and lies within a Damerau–Levenshtein distance of 1 (words of up
to five letters) or 2 (longer words) of exactly one best lexicon word; on a tie, the word with
the same letters wins ("heigth" is "height", not "heigh"). An English word is corrected only
where nothing else fits (after a number, one letter from a part word: "4 cubs") or when it is
a hundred times rarer than the lexicon word one letter away ("hight"). Every
correction is reported ("corrected 'brige' to 'bridge'").
"""

from __future__ import annotations

import re
from functools import cache
from importlib import resources

import jellyfish
from rapidfuzz import fuzz, process
from rapidfuzz.distance import DamerauLevenshtein

from sdi.language import words
from sdi.spec import lexicon as lx
from sdi.spec.numbers import NUMBER_WORDS

_WORD = re.compile(r"[A-Za-z]+")
_SHAPES = frozenset(w for w in lx.SHAPE_WORDS if w not in lx.AMBIGUOUS_SHAPES)
_SUFFIXES = {"y", "ed", "ing", "er", "est", "ly", "ish", "ie", "ies"}


_KNOWN = frozenset(words.VOCABULARY)
# Words that carry a relation, a place or a step, which a typo may stand for ("the left sied",
# "thn anothr one") though they are not content of their own (left unused, they are no loss).
_FUNCTION = {"side", "sides", "then", "another", "other", "each", "every", "edge", "edges", "top",
             "bottom", "middle", "centre", "center", "after", "first", "second", "third", "last",
             "across", "along", "same", "space", "gap", "level", "layer", "inch", "inches",
             "foot", "feet", "wait", "sorry", "tetris", "piece", "downstage",
             "upstage", "actually", "instead", "height", "beam", "beams"}  # fmt: skip
_TARGETS = words.CORRECTABLE | _FUNCTION  # what a word may be corrected to
_CHOICES = sorted(_TARGETS)


_CUT_SHORT = ("tall", "long", "high", "wide", "deep", "next")  # "tal", "nex": a letter lost


@cache
def english_frequency() -> dict[str, int]:
    """How often each of the 82 765 most frequent English words occurs (SymSpell's list, from
    Google Books n-grams intersected with SCOWL). spaCy's string store is no word list: it holds
    every token its model saw, "litle" and "heigth" among them."""
    text = (resources.files("symspellpy") / "frequency_dictionary_en_82_765.txt").read_text()
    return {w: int(f) for w, f in (line.split(" ", 1) for line in text.splitlines() if line)}


def known_word(word: str) -> bool:
    """`word` is English (the frequency list) or one of SDI's own words."""
    w = word.lower()
    return w in _KNOWN or w in english_frequency()


def _vocab_has(word: str) -> bool:
    return word in english_frequency()


_RARER = 100
"""A listed word this many times rarer than a lexicon word one letter away is a misspelling
of it that the list keeps ("hight" for height, "colum" for column; "lone" is 49× rarer than
"long" and stays)."""


def _misspelt(w: str) -> bool:
    """`w` is on the list but every lexicon word one letter away is a hundred times more
    frequent: a misspelling the list keeps."""
    freq = english_frequency()
    found = process.extract(w, _CHOICES, scorer=DamerauLevenshtein.distance, score_cutoff=1)
    return bool(found) and all(freq.get(c, 0) >= _RARER * freq[w] for c, _, _ in found)


_PARTS = sorted(w for w in lx.PART_WORDS if w.isalpha() and len(w) > 3)
_NUMBER = re.compile(r"(?:\d+|" + "|".join(NUMBER_WORDS) + r")\s+$", re.IGNORECASE)


def _slot_word(w: str, m: re.Match[str]) -> str | None:
    """The part word an English word after a number stands for, by one letter ("4 cubs",
    "2 cubse apart"); None elsewhere ("the cubs at the zoo")."""
    if not _NUMBER.search(m.string[max(0, m.start() - 12) : m.start()]):
        return None
    hits = [c for c in _PARTS if DamerauLevenshtein.distance(w, c) == 1]
    plural = [c for c in hits if c.endswith("s") == w.endswith("s")]
    return hits[0] if len(hits) == 1 else plural[0] if len(plural) == 1 else None


@cache
def _by_sound() -> dict[str, list[str]]:
    """The words a misspelling may stand for, by their Metaphone key (jellyfish)."""
    out: dict[str, list[str]] = {}
    nouns = (_TARGETS - set(lx.SIZE_WORDS)) | _SPOKEN  # never a size by ear ("mein" is no mini)
    for word in sorted(nouns):
        if word.isalpha() and len(word) >= 3:
            out.setdefault(jellyfish.metaphone(word), []).append(word)
    return out


_TEXTED = frozenset({"shud", "wud", "cud", "smth", "pls", "plz", "thx", "lil", "dunno"})
"""Words of a text message the normaliser expands ("shud" is should, not a shed)."""

_GLUED = {"infront": "in front", "ontop": "on top", "nextto": "next to", "inbetween": "in between"}
"""Two words a hurried writer runs together."""

_SPOKEN = frozenset({"really", "something", "please", "small", "touching", "instead", "knock",
                     "should", "goes", "podium", "crossbar", "goalposts", "blocks", "stairs",
                     "smaller", "wedding", "pancakes", "tiers", "each", "make"})  # fmt: skip
"""Everyday words a child or a hurried writer spells by ear, beside the lexicon's own."""


def _sounds_like(w: str) -> str | None:
    """The one known word that sounds like `w` (Metaphone), if there is exactly one — of a
    word with a vowel ("jjjjjjj" sounds like nothing)."""
    if len(w) < 4 or not re.search(r"[aeiouy]", w) or re.search(r"(.)\1\1", w):
        return None
    same = _by_sound().get(jellyfish.metaphone(w), [])
    return same[0] if len(same) == 1 else None


_VOWELS = re.compile(r"[aeiou]")
_ACRONYMS = frozenset({"plc", "hmi", "cnc", "tcp", "rpm", "std", "qty", "sku", "mph", "kph",
                       "ppm", "pcs", "thx", "pls", "plz", "smth", "lvl", "lvls", "hrs", "mins",
                       "pcb", "xyz", "tbd", "wrt", "bldg", "frm", "nds", "cmms", "hgt", "hght",
                       "lng", "cnr", "crnr", "frnt", "lft", "rght", "rgt", "nxt",
                       "bhnd", "stn", "clr", "rmv"})  # fmt: skip
"""Vowel-less words of a shop floor that are no abbreviation of SDI's words ("PLC" is no
place), or that the normaliser expands itself."""


def skeleton(word: str) -> str:
    """`word` as a writer short of time abbreviates it: its first letter, then its consonants
    (y counts as one), "ck" as "k", a doubled letter once ("tower" → "twr", "block" → "blk",
    "pillar" → "plr")."""
    w = word.lower().replace("ck", "k")
    w = w[:1] + _VOWELS.sub("", w[1:])
    return re.sub(r"(.)\1+", r"\1", w)


@cache
def _abbreviations() -> dict[str, list[tuple[int, str]]]:
    """Each abbreviation SDI's words can be written as, with the words and how close: 0 the
    skeleton itself ("twr"), 1 the skeleton less a silent "gh" or one inner consonant ("hgt",
    "ctr", "cnr"), 2 its first four or more letters ("pyrm")."""
    out: dict[str, list[tuple[int, str]]] = {}

    def add(key: str, rank: int, word: str) -> None:
        if len(key) >= 3 and key != word:
            out.setdefault(key, []).append((rank, word))

    for word in sorted(_TARGETS):
        if not word.isalpha() or len(word) < 3:
            continue
        s = skeleton(word)
        add(s, 0, word)
        for short in {s.replace("gh", ""), s.replace("gh", "g")} - {s}:
            add(short, 1, word)
        for i in range(1, len(s) - 1):
            if len(s) >= 4 and s[i] in "nrh":  # a weak consonant: "ctr", "cnr", "lgth"
                add(s[:i] + s[i + 1 :], 1, word)
        for n in range(4, len(s)):
            add(s[:n], 2, word)
    return out


def abbreviated(word: str) -> str | None:
    """The one word of SDI's that `word`, a word with no vowel after its first letter, is an
    abbreviation of ("twr" tower, "blk" block, "lyr" layer, "lgs" legs, "ctr" centre, "brdg"
    bridge, "clmn" column); None if it is none or could be two ("mdl": middle or module).
    Of two, the one English uses at least twice as often ("blk" is a block, not bulk; "ctr"
    a centre, not a crater); centre and center are one."""
    w = word.lower()
    if len(w) < 3 or _VOWELS.search(w[1:]) or w in _ACRONYMS or not w.isalpha():
        return None
    found = _abbreviations().get(skeleton(w), [])
    if not found:
        return None
    best = min(r for r, _ in found)
    one: dict[tuple[str, str], str] = {}
    for t in sorted({t for r, t in found if r == best}):
        one.setdefault((skeleton(t), t[:4]), t)  # "cntr": centre or center, the same word
    top = list(one.values())
    if len(top) > 1:  # "twrs" is towers, "twr" tower
        top = [t for t in top if t.endswith("s") == w.endswith("s")] or top
    freq = english_frequency()
    top.sort(key=lambda t: -freq.get(t, 0))
    if len(top) > 1 and freq.get(top[0], 0) < 2 * freq.get(top[1], 0):
        return None
    return top[0]


_SIZED_AFTER = re.compile(
    r"\s+(?:(?:of|if|o'?)\s+)?(?:\d|one\b|two\b|three\b|four\b|five\b|six\b)", re.IGNORECASE
)
_ACROSS_AFTER = re.compile(r"\s+(?:across|over|on\s+top)\b", re.IGNORECASE)


def _structure_slot(w: str, m: re.Match[str]) -> str | None:
    """The structure word an English word stands for where a structure is named and sized, one
    letter off, in a command that names no structure ("Towel of 5 cubes", "a slav 3 by 3"), or
    the beam laid across ("and a bean across"); None elsewhere."""
    after = m.string[m.end() :]
    before = m.string[: m.start()]
    if _ACROSS_AFTER.match(after) and DamerauLevenshtein.distance(w, "beam") == 1:
        return "beam"
    if len(w) < 4 or not _SIZED_AFTER.match(after) or _names_a_structure(m):
        return None
    if not re.search(r"(?:^|[.:;!?]|\b(?:an?|the|one)\s)\s*$", before, re.IGNORECASE):
        return None
    hits = sorted({c for c in _WHOLE if DamerauLevenshtein.distance(w, c) == 1})
    return hits[0] if len(hits) == 1 else None


def _names_a_structure(m: re.Match[str]) -> bool:
    """The text around `m` names a structure in a word of its own, or one a near typo is —
    not a support or a level of one ("a brij with legs of 3" names only the bridge)."""
    for other in _WORD.finditer(m.string):
        w = other.group(0).lower()
        if other.start() != m.start() and (
            w in _WHOLE or (len(w) > 3 and not known_word(w) and process.extractOne(
                w, _WHOLE, scorer=DamerauLevenshtein.distance, score_cutoff=1) is not None)
        ):  # fmt: skip
            return True
    return False


_WHOLE = sorted(
    _SHAPES - lx.LEVEL_WORDS - {"leg", "legs", "pillar", "pillars", "post", "posts", "pier",
                                "piers", "upright", "uprights", "support", "supports"}
)  # fmt: skip


def _one_letter_dropped(w: str, word: str) -> bool:
    """`w` is `word` with one letter left out ("couse", "coures" of course)."""
    return len(word) == len(w) + 1 and any(word[:i] + word[i + 1 :] == w for i in range(len(word)))


def correct(text: str, *, aggressive: bool = False) -> tuple[str, list[str]]:
    """`text` with typos replaced, and a note per correction. `aggressive` also corrects
    words the English vocabulary knows ("wal"), for a command nothing else could read."""
    notes: list[str] = []

    def fix(m: re.Match[str]) -> str:
        raw = m.group(0)
        w = raw.lower()
        if w in _GLUED:
            return _GLUED[w]  # "infront of": two words run together, not a misspelt one
        if (
            len(w) < 3
            or w in _KNOWN
            or w in _TEXTED
            or m.string[m.end() : m.end() + 1] in ("'", "’")
        ):
            return raw  # "aren't", "couldn't": a word of a contraction, not a typo
        glued = (
            m.string[max(0, m.start() - 1) : m.start()].isdigit()
            or m.string[m.end() : m.end() + 1].isdigit()
        )  # "4H", "1st", "X250": a unit or a label, not an abbreviation
        short = None if glued else abbreviated(w)
        if short:
            notes.append(f"read '{raw}' as '{short}' (an abbreviation)")
            return short
        if len(w) == 3:  # three letters: only a swap of two neighbours ("teh")
            swaps = {w[:i] + w[i + 1] + w[i] + w[i + 2 :] for i in range(2)}
            hit = sorted(swaps & _TARGETS)
            cut = [d for d in _CUT_SHORT if d.startswith(w)]  # "tal", "lon": a letter lost
            if not hit and len(cut) == 1:
                notes.append(f"corrected '{raw}' to '{cut[0]}'")
                return cut[0]
            if len(hit) == 1:
                notes.append(f"corrected '{raw}' to '{hit[0]}'")
                return hit[0]
            ended = [c for c in _WHOLE if len(c) == 4 and c.startswith(w)]
            if len(ended) == 1 and _SIZED_AFTER.match(m.string[m.end() :]):
                notes.append(f"corrected '{raw}' to '{ended[0]}'")  # "wal 6x2": its last letter
                return ended[0]
            if not aggressive:
                return raw
            choices_here = [c for c in _CHOICES if c in _SHAPES and len(c) > len(w)]
        else:
            choices_here = _CHOICES
        if _vocab_has(w) and not _misspelt(w) and (not aggressive or len(w) > 3):
            slot = _slot_word(w, m) or _structure_slot(w, m)
            if slot:  # "4 cubs", "Towel of 5 cubes": the only word that fits where it stands
                notes.append(f"corrected '{raw}' to '{slot}'")
                return slot
            return raw  # an English word ("walk", "tour") is not a typo, even for a last try
        limit = 1 if len(w) <= 5 else 2
        found = process.extract(
            w, choices_here, scorer=DamerauLevenshtein.distance, score_cutoff=limit, limit=3
        )
        if not found:
            heard = None if _vocab_has(w) else _sounds_like(w)
            if heard in _SHAPES and _names_a_structure(m):
                return raw  # "Tsak: a 2x3 slab" is no desk beside the slab: a guess too far
            if heard:  # "brij", "blox", "sumthing": spelt as it sounds
                notes.append(f"corrected '{raw}' to '{heard}' (it sounds like it)")
                return heard
            return raw
        if any(c == w for c, _, _ in found):
            return raw  # "tetris": a word SDI knows, spelt right
        if any(w.startswith(c) and w[len(c) :] in _SUFFIXES for c, _, _ in found):
            return raw  # "chunky", "stacked": a derived form of a word, not a typo
        if aggressive and _vocab_has(w):
            # a word English knows ("shut") is read as a structure only if it starts the same
            found = [f for f in found if f[0][0] == w[0]]
            if not found:
                return raw
        best = min(d for _, d, _ in found)
        top = [c for c, d, _ in found if d == best]
        swapped = [c for c in top if sorted(c) == sorted(w)]
        if len(top) > 1 and swapped:
            top = swapped  # "fornt": two letters of a place word swapped, not "fort"
        if len(top) > 1:
            same_start = [c for c in top if c[0] == w[0]] or top
            # a tie: the candidate sharing most letters in order ("thre" → "three", not "the")
            ranked = sorted(same_start, key=lambda c: -fuzz.ratio(w, c))
            if len(ranked) > 1 and fuzz.ratio(w, ranked[0]) == fuzz.ratio(w, ranked[1]):
                return raw
            top = ranked[:1]
        heard = None if _vocab_has(w) else _sounds_like(w)
        if (
            heard
            and heard != top[0]
            and not _one_letter_dropped(w, top[0])  # "couse" is no "goes" but a course
            and sorted(top[0]) != sorted(w)  # "rign": letters swapped, not a sound
            and jellyfish.metaphone(top[0]) != jellyfish.metaphone(w)
        ):
            top = [heard]  # "blox" sounds like blocks, not box
        if (
            aggressive
            and _vocab_has(w)
            and english_frequency().get(top[0], 0) < english_frequency()[w]
        ):
            return raw  # "she" is no "shed": a word more common than the one it is near
        notes.append(f"corrected '{raw}' to '{top[0]}'")
        return top[0]

    return _WORD.sub(fix, text), notes
