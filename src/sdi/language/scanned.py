"""Text read by a scanner from a handwritten note: the letters and digits OCR confuses ("tovver"
for tower, "bui1d", "5tep", "0f", "rnake", "riqht", "l0 crn" for 10 cm, "tow er" broken in two).

A word that no word list knows is read as the known word it makes when its confusable
characters are read the other way (0 o, 1 l i, 5 s, 8 b, | l, I l, rn m, vv w, q g); a number
with letters in it ("l0", "2O") as the number; two halves of a word the lexicon knows, split
by a stray space, as that word. Every change is reported."""

from __future__ import annotations

import itertools
import re

from sdi.language import words
from sdi.language.typos import english_frequency, known_word

_SWAPS = {"rn": ("m",), "vv": ("w",), "0": ("o",), "1": ("l", "i"), "5": ("s",), "8": ("b",),
          "|": ("l",), "q": ("g",), "I": ("l",)}  # fmt: skip
"""What a scanner's character (or pair) may stand for."""
_CONFUSABLE = re.compile("|".join(re.escape(c) for c in sorted(_SWAPS, key=len, reverse=True)))
_LABEL = re.compile(r"[A-Za-z][0-9]")
_SIZE = re.compile(r"[0-9lI]+[xX][0-9lI]+")
_TOKEN = re.compile(r"[A-Za-z0-9|]+")
_NUMBERISH = re.compile(r"[0-9lIoO|]+")
_MEASURE = re.compile(r"\d+(?:mm|cm|m|in|ft|x|s|st|nd|rd|th|h|H|L|W)", re.IGNORECASE)


_CONTRACTED = frozenset({"dont", "doesnt", "didnt", "cant", "wont", "isnt", "arent", "shouldnt",
                         "mustnt", "neednt"})  # fmt: skip
"""Contractions written without the apostrophe, which the normaliser reads."""

_SHORT = frozenset({"no", "on", "of", "in", "to", "is", "it", "so", "or"})
"""Two-letter words a letter and a digit may stand for ("N0 tower", "0n top")."""


def _known(word: str) -> bool:
    return known_word(word) or word.lower() in _CONTRACTED


def _readings(token: str) -> list[str]:
    """Every way of reading `token`'s confusable characters (at most 256)."""
    parts: list[tuple[str, ...]] = []
    k = 0
    for m in _CONFUSABLE.finditer(token):
        parts.append((token[k : m.start()],))
        parts.append((m.group(0), *_SWAPS[m.group(0)]))
        k = m.end()
    parts.append((token[k:],))
    out = ["".join(p) for p in itertools.islice(itertools.product(*parts), 256)]
    return [o for o in out if o != token]


def _word(token: str, after: str = "") -> str | None:
    """The known word a scanned `token` stands for, or None. A digit or a bar in a word is a
    scanner's sure sign; with letters only ("rnake", "tovver") the word read must be one SDI
    knows ("rnig" is a typo of ring, not "mig")."""
    if _known(token) or token.isdigit() or not _CONFUSABLE.search(token):
        return None
    if _MEASURE.fullmatch(token):
        return None  # "0.1m", "25cm", "6in": a number with its unit, as written
    if _LABEL.fullmatch(token) and re.match(r" [A-Za-z]", after):
        short = [r for r in _readings(token) if r.lower() in _SHORT]
        return short[0] if short else None  # "N0 tower": no; "t0: row", "A1": labels
    if not re.search(r"[A-Za-z]", token) or _LABEL.fullmatch(token) or _SIZE.fullmatch(token):
        return None  # "t0", "A1": a label; "1x1": a size
    sure = bool(re.search(r"[0-9|]|[a-z]I|I[a-z]{2}", token))
    letters = [
        r for r in _readings(token)
        if r.isalpha() and (_known(r) if sure else r.lower() in words.VOCABULARY)
    ]  # fmt: skip
    if not letters:
        return None
    freq = english_frequency()
    return max(letters, key=lambda r: (r.lower() in words.VOCABULARY, freq.get(r.lower(), 0)))


def _number(token: str) -> str | None:
    """ "l0", "l5", "2O", "1O0": a number with letters a scanner put in it."""
    if not _NUMBERISH.fullmatch(token) or not re.search(r"\d", token) or token.isdigit():
        return None
    return re.sub(r"[lI|]", "1", re.sub(r"[oO]", "0", token))


def unscan(text: str) -> tuple[str, list[str]]:
    """`text` with scanner confusions read back, and a note for each."""
    notes: list[str] = []

    def fix(m: re.Match[str]) -> str:
        token = m.group(0)
        read = _number(token) or _word(token, m.string[m.end() : m.end() + 2])
        if read is None:
            return token
        notes.append(f"read '{token}' as '{read}' (a scanner's confusion)")
        return read

    text = _TOKEN.sub(fix, text)

    text = _LABEL_ONE.sub(r"\1 1", text)  # "5tep l:": step 1
    pieces = re.split(r"(\s+)", text)
    k = 0
    while k + 2 < len(pieces):
        a, space, b = pieces[k], pieces[k + 1], pieces[k + 2]
        if space == " " and _broken(a, b):
            notes.append(f"read '{a} {b.rstrip('.,;:!?')}' as '{a + b.rstrip('.,;:!?')}' "
                         "(a word broken in two)")  # fmt: skip
            pieces[k : k + 3] = [a + b]
            continue
        k += 2
    return "".join(pieces), notes


_LABEL_ONE = re.compile(
    r"\b(step|level|layer|item|part|position|stage|phase)\s+[lI|](?=\W|$)", re.I
)


def _broken(a: str, b: str) -> bool:
    """ "tow er", "cu bes", "diff erent": two halves of one word, split by a stray space."""
    b = b.rstrip(".,;:!?")
    if not (a.isalpha() and b.isalpha() and len(a) >= 2 and 2 <= len(b) <= 6):
        return False
    whole = (a + b).lower()
    if whole in ("into", "onto"):
        return False
    lexicon = whole in words.CORRECTABLE and not (_known(a) and _known(b) and len(b) > 3)
    return lexicon or (_known(whole) and not (_known(a) and _known(b)))
