"""Self-corrections: "a row of 3, no wait, 4", "a 3x5 pad — sorry, not 3x5, 3x4", "on the left,
actually the right". An operator who corrects a value mid-sentence means the later value in
place of the earlier one of the same kind (a size group, a length with a unit, a count, a
region). The correction replaces it in the text before anything else reads it, with a note;
a correction that names a structure again ("no wait, make it a wall") or changes it ("make it
4") is left to the later stages as a clause of its own."""

from __future__ import annotations

import re

from sdi.spec import lexicon as lx
from sdi.spec.numbers import COUNT_WORDS, words_to_numbers

MARKER = re.compile(
    r"\s*[,.!?;…—–-]+\s*(?:(?:ah|oh|uh|um|erm|er|hmm)\s*,?\s*)?no\s*(?:[,!]\s*|[-—–]+\s*|(?=\d|(?:one|two|three|four|five|six|seven|eight|nine|"
    r"ten)\b))|"  # "a stack of 3 to the left of it - no, to the right", "3 - no 6 -", ". No, 3"
    r"\s*[,.;:!?…—–-]*\s*\b(?:no\s*,?\s*wait|wait\s*,?\s*no|no\s*,?\s*sorry|sorry\s*,?\s*no|"
    r"scratch\s+that|or\s+rather|i\s+meant?|make\s+that|actually\s*,?\s*no|"
    r"correction(?:\s+to\s+(?:the\s+)?(?:previous|last|above|first)\s+(?:line|sentence|one|item))?|"
    r"no\s*,?\s*actually(?:\s*,?\s*make\s+(?:that|it))?|actually\s*,?\s*make\s+(?:that|it)|"
    r"on\s+second\s+thoughts?|change\s+of\s+plan|change\s+that|never\s*mind|nvm|"
    r"actually|sorry(?:\s+again)?|oops|wait|(?:revised|changed|updated|amended|corrected)\s+to)\b"
    r"\s*[,:;—–-]?\s*|"
    # "Tower of 5, no 6, ok 4": the number settled on
    r"\s*[,.;]+\s*(?:ok(?:ay)?|fine|alright|right|hmm+|um+|erm)\s*,?\s*(?=(?:\d+|one|two|three|four|five|"
    r"six|seven|"
    r"eight|nine|ten)\b(?!\s*(?:more|less|fewer|extra|others?)\b))|"
    r"\s*[,.;!—–-]*\s*\b(?:edit|revision|update|amendment|change)\s*:\s*|"  # a ticket's later line
    # on the radio: "Tower, height six. Negative, height two."
    r"\s*[,.;!—–-]+\s*negative\s*[,:;]\s*|"
    # "no wait 4, no wait 6 final answer 6": the number said last
    r"\s*[,.;:!?…—–-]*\s*\b(?:so\s+)?final\s+(?:answer|call|decision|number|offer)\s*(?:is\s*)?[,:;=—–-]*\s*"
    r"(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)|"
    # "a tower of ten -- that's too tall, so let's do seven": the number said again
    r"\s*[,.;:!?…—–-]*\s*\b(?:so\s+)?let'?s\s+(?:do|go\s+(?:with|for)|say)\s+(?=(?:\d+|one|two|"
    r"three|four|five|six|seven|eight|nine|ten)\b\s*(?:[.!,;]|$|cubes?\b|high\b|tall\b|long\b|wide\b|"
    r"steps?\b|levels?\b))|"
    r"\s*[,.;!—–-]*\s*\bor\s*(?:\.{2,}|…)\s*|"  # "Staircase, 5 steps. Or... let's do 3 steps"
    # "a pyramid with base 5, change it to base 3": its value said again
    r"\s*[,.;!—–-]+\s*(?:then\s+|now\s+|but\s+|so\s+|please\s+)?(?:change|rebuild|redo|remake)\s+(?:it|that)"
    r"\s+(?:to|with)\s+(?=(?:an?\s+)?(?:base|height|length|width)\b|(?:\d+|one|two|three|four|five|six|"
    r"seven|eight|nine|ten)\b)|"
    # "… 5 cm apart. Then make the gap 15 cm": the gap said again, changed
    r"\s*[,.;!—–-]+\s*(?:then\s+|now\s+)?(?:make|change|set|widen|narrow)\s+the\s+"
    r"(?:gap|spacing|space|distance)(?:\s+between\s+them)?(?:\s+to)?\s+(?=\d|(?:one|two|three|four|"
    r"five|six|seven|eight|nine|ten)\b)",
    re.IGNORECASE,
)

_WORDS = sorted(COUNT_WORDS, key=len, reverse=True)
_NUMBER = r"(?:\d+(?:\.\d+)?|" + "|".join(_WORDS) + r")"
_UNIT = r"(?:" + "|".join(sorted(map(re.escape, lx.UNITS_M), key=len, reverse=True)) + r")"
_REGION = r"(?:" + "|".join(sorted(map(re.escape, lx.REGION_WORDS), key=len, reverse=True)) + r")"

# The kinds of value a correction can replace, most specific first: (kind, pattern).
_KINDS: tuple[tuple[str, re.Pattern[str]], ...] = (
    ("size", re.compile(rf"\b{_NUMBER}(?:\s*{_UNIT})?(?:\s*(?:x|by)\s*{_NUMBER}(?:\s*{_UNIT})?)+\b",
                        re.I)),
    ("length", re.compile(rf"\b{_NUMBER}\s*{_UNIT}\b", re.I)),
    ("count", re.compile(rf"\b{_NUMBER}\b", re.I)),
    ("region", re.compile(rf"\b(?:{_REGION})(?:\s+(?:{_REGION}))?\b", re.I)),
)

# spoken, with no commas: "five steps no six steps", "of five no not five six"
_SPOKEN_NO = re.compile(
    rf"(\b{_NUMBER}\b(?:\s+[a-z]+){{0,2}}?)\s+no\s+(?=(?:not\s+{_NUMBER}\s+|make\s+(?:it|that)\s+)?"
    rf"{_NUMBER}\b)",
    re.I,
)  # "five steps no six steps", "four by four no make it three by three"
# "a wall not of seven, of five": the number taken back, and the one meant
_NOT_A_BUT_B = re.compile(
    rf"(?<=[a-z]\s)not\s+(of\s+)?({_NUMBER})\s*,\s*(?:but\s+)?(of\s+)?({_NUMBER})\b", re.I
)
_NOT_OLD_SPOKEN = re.compile(rf"^not\s+{_NUMBER}\s+(?={_NUMBER}\b)", re.I)  # "not five six"
_AND_NOT_OLD = re.compile(rf"\s*,?\s*(?:and\s+)?not\s+{_NUMBER}(?:\s+[a-z]+)?$", re.I)

_NOT_OLD = re.compile(r"^(?:no\s*,?\s*)?not\s+[^,;.]+?\s*[,;]\s*|^no\s*,\s*", re.IGNORECASE)
_FILLER = re.compile(
    r"^(?:(?:it\s+should\s+be|it'?s|i\s+meant|i\s+want|we\s+need|make\s+it|make\s+that|"
    r"(?:make|set)\s+the\s+(?:gap|space|spacing|distance)(?:\s+(?:to|of))?|"
    r"(?:could|can|would)\s+(?:it|that|we|you)\s+(?:be|make\s+it|do|have)|how\s+about|let'?s\s+(?:do|make)|"
    r"the|a|just|only|(?:base|footprint|size)(?:\s+(?:is|of))?\s*[:=]?|"  # "no wait, base 3 by 3"
    r"(?:make|do|build)(?=\s+(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)|"
    r"an|to|on|at|in|of|with)\s+)+",
    re.I,
)


_HEDGE = re.compile(
    r"\s*,?\s*\b(?:i\s+think|i\s+guess|i\s+reckon|i\s+suppose|i'?d\s+say|probably|maybe|perhaps|my\s+bad|"
    r"sorry|oops|lol|"
    r"or\s+so|instead|(?:is|will|would|should)\s+(?:be\s+)?(?:enough|plenty|fine|ok|okay|good|"
    r"better|sufficient|do))\s*$",
    re.IGNORECASE,
)

_OF_IT = re.compile(
    r"(?:\s+(?:hand\s+)?side)?\s+of\s+(?:it|that|them|this|those|the\s+\w+(?:\s+\w+)?)$", re.I
)
_PARTS = re.compile(r"\s+(?:cubes?|blocks?|parts?|pieces?|bricks?)$", re.IGNORECASE)


def _value(said: str) -> str | None:
    """The kind of a value said on its own ("five", "6 cubes", "3 by 4", "the left")."""
    value = _PARTS.sub("", _FILLER.sub("", said.strip()).strip(" ,.;!?"))
    return _kind(value) if value and not _names_structure(value) else None


def _kind(value: str) -> str | None:
    for kind, pattern in _KINDS:
        m = pattern.fullmatch(value.strip())
        if m:
            return kind
    return None


def _names_structure(text: str) -> bool:
    """`text` names a structure: a family noun, or a plural one counted ("two 3x3 layers")."""
    said = text.lower()
    return any(
        w in lx.SHAPE_WORDS
        or (w[-1:] == "s" and w[:-1] in lx.SHAPE_WORDS
            and re.search(rf"\b(?:{_NUMBER})\s+(?:\S+\s+){{0,3}}{w}\b", said) is not None)
        for w in re.findall(r"[a-z]+", said)
    )  # fmt: skip


_NOT_THAT = re.compile(
    r"\b(?:an?\s+)?(\w+)\s*[,.]?\s*(?:no|nope)\s*[,.]?\s*not\s+(?:an?\s+)?(\1)\b\s*[,.;:—–-]*\s*",
    re.IGNORECASE,
)
_DIM_WORDS = r"(?:long|high|tall|wide|deep|thick)"
_WITH_DIM = re.compile(
    rf"^({_NUMBER}(?:\s*{_UNIT})?)\s+((?:cubes?\s+|parts?\s+)?{_DIM_WORDS})\b(.*)$",
    re.IGNORECASE | re.DOTALL,
)


def _names_again(text: str, notes: list[str]) -> str:
    """ "a wall no not a wall a row of six": the structure named first is taken back."""
    m = _NOT_THAT.search(text)
    if m is None or m.group(1).lower() not in lx.SHAPE_WORDS:
        return text
    notes.append(f"corrected by the command itself: not a {m.group(1)}")
    return text[: m.start()] + text[m.end() :]


def _with_dimension(before: str, value: str, rest: str, notes: list[str]) -> str | None:
    """ "six long no sorry five long three high": the corrected size is the one said with
    the same dimension word; what follows it stays."""
    m = _WITH_DIM.match(value)
    if m is None:
        return None
    dim = m.group(2).split()[-1]
    olds = list(re.finditer(rf"\b({_NUMBER}(?:\s*{_UNIT})?)\s+(?:cubes?\s+|parts?\s+)?{dim}\b",
                            before, re.I))  # fmt: skip
    if not olds:  # "a tower six, no wait, five high": the count said last, now with its word
        counts = _bare_counts(before)
        if not counts:
            return None
        old = counts[-1]
        notes.append(f"corrected by the command itself: '{old.group(0)}' → '{m.group(1)} {dim}'")
        fixed = before[: old.start()] + f"{m.group(1)} {dim}" + before[old.end() :]
        return f"{fixed} {m.group(3).strip()}{rest}"
    old = olds[-1]
    notes.append(f"corrected by the command itself: '{old.group(0)}' → '{m.group(1)} {dim}'")
    fixed = before[: old.start(1)] + m.group(1) + before[old.end(1) :]
    return f"{fixed} {m.group(3).strip()}{rest}"


_CLAUSE_CUT = re.compile(r"[.;:!?]\s*|,\s*(?:and\s+|then\s+)?|\s+(?:and|then)\s+", re.IGNORECASE)
_MAKE_IT = re.compile(
    r"^(?:(?:make|change|turn)\s+(?:it|that|this)\s+(?:into\s+|to\s+)?|"
    r"(?:it\s+should\s+be|let'?s\s+(?:do|have|make|build)|i\s+want|we\s+need|build|have|"
    r"(?:what\s+)?i\s+meant(?:\s+was)?|"
    r"(?:could|can|would)\s+(?:it|that|we|you)\s+(?:be|make\s+it|do|have)|how\s+about)\s+)",
    re.IGNORECASE,
)
_ADDED = re.compile(r"\b(?:too|as\s+well|also|another|more|plus)\b", re.IGNORECASE)
_PLACE = re.compile(
    rf"\b(?:at|on|in)\s+the\s+(?:{_REGION})(?:\s+(?:{_REGION}))?(?:\s+(?:corner|side|edge))?\b",
    re.IGNORECASE,
)


def _another_structure(before: str, after: str, notes: list[str]) -> str | None:
    """ "a tower of 3 at the back, no wait, make it a wall": the structure said last is taken
    back and the new one stands in its place (where the old one stood, unless it says where)."""
    if _ADDED.search(after):
        return None  # "…, actually a pyramid too": one more, not a correction
    cuts = [m.end() for m in _CLAUSE_CUT.finditer(before.rstrip(" ,;:—–-"))]
    for start in [*reversed(cuts), 0][:3]:  # "Build a wall, six long, two high.": all of it
        taken_back = before[start:].strip(" ,;:—–-")
        taken_back = re.sub(r"\s+(?:but|and|or)$", "", taken_back, flags=re.I)  # "… earlier but"
        if _names_structure(taken_back):
            break
    else:
        return None
    new = re.sub(r"\s*\b(?:instead|actually)\b", "", _MAKE_IT.sub("", after.strip()),
                 flags=re.I).strip(" ,")  # fmt: skip
    new = _regrouped(taken_back, new)  # "a row of five cubes. no, stack them": a tower of five
    lead = re.search(r"(?:^|[:;,—–-]\s*)((?:an?|one)\s.*)$", new, re.IGNORECASE | re.DOTALL)
    if lead and not _names_structure(new[: lead.start(1)]):
        new = lead.group(1)  # "scratch that, different thing entirely today: a pyramid of 2"
    if not re.match(rf"(?:an?|one|{_NUMBER})\s", new, re.IGNORECASE):
        return None  # "actually make the pillars 4": a change of the structure, not another
    place = _PLACE.search(taken_back)
    if place and not _PLACE.search(new):
        new = f"{new.rstrip(' .!')} {place.group(0)}"
    notes.append(f"corrected by the command itself: '{taken_back}' → '{new.strip(' .!')}'")
    return before[:start] + new


_REGROUP = re.compile(
    r"^(?:(stack|pile)|(line|lay|set|put))\s+(?:them|those|these|the\s+cubes|it)\s*(?:(up)|(out|"
    r"down|in\s+a\s+(?:row|line)))?\s*[.!]?$",
    re.IGNORECASE,
)


def _regrouped(taken_back: str, new: str) -> str:
    """ "a row of five cubes. no, stack them instead": the same cubes as a tower (a row, for
    "line them up"); other words as they are."""
    m = _REGROUP.match(new)
    said = re.search(rf"\b(?:of\s+)?({_NUMBER})\s+(?:cubes|blocks|parts)\b|\bof\s+({_NUMBER})\b",
                     taken_back, re.I)  # fmt: skip
    if m is None or said is None:
        return new
    n = said.group(1) or said.group(2)
    if m.group(1) and not m.group(4):
        return f"a tower of {n}"
    if m.group(2) and (m.group(3) or m.group(4)):
        return f"a row of {n}"
    return new


def _noun_first(before: str, value: str, rest: str, notes: list[str]) -> str | None:
    """ "a pyramid with base 4... no, base 3": the number said after the same noun, replaced
    (the noun alone was read as another structure, a platform)."""
    m = _NOUN_VALUE.fullmatch(value)  # "legs 2 high; change that, legs 4 high"
    if m is None:
        return None
    olds = list(re.finditer(rf"\b{re.escape(m.group(1))}\s+(?:of\s+|is\s+)?({_NUMBER})\b"
                            rf"(\s*{_UNIT}\b)?", before, re.IGNORECASE))  # fmt: skip
    if not olds:
        return None
    old = olds[-1]
    notes.append(f"corrected by the command itself: '{old.group(0)}' → '{value}'")
    end = old.end(2) if m.group(3) and old.group(2) else old.end(1)  # "height 150 mm … 100 mm"
    return before[: old.start(1)] + m.group(2) + (m.group(3) or "") + before[end:] + rest


_NOUN_VALUE = re.compile(
    rf"(?!(?:not|no|and|but|or|then|of|to|make)\b)([a-z]+)\s+(?:of\s+|is\s+)?({_NUMBER})(\s*{_UNIT})?(?:\s+(?:cubes?\s+)?{_DIM_WORDS})?",
    re.IGNORECASE,
)


def _with_noun(before: str, value: str, rest: str, notes: list[str]) -> str | None:
    """ "five steps, no, six steps": the number said last with the same noun, replaced; "three
    towers of three, no, make that four towers of three a cube apart": the whole phrase."""
    m = re.match(rf"({_NUMBER})\s+([a-z]+?)s?\b", value, re.IGNORECASE)
    if m is None or (
        m.end() < len(value)
        and not {m.group(2).lower(), m.group(0).split()[-1].lower()} & set(lx.SHAPE_WORDS)
    ):  # "five steps, no, four steps, going up": the plural names the family
        return None
    olds = list(re.finditer(rf"\b({_NUMBER})\s+{m.group(2)}s?\b", before, re.IGNORECASE))
    if not olds:
        return None
    old = olds[-1]
    if m.end() < len(value):  # the phrase said again, in full: it replaces the old one
        notes.append(f"corrected by the command itself: '{before[old.start():].strip()}' → "
                     f"'{value}'")  # fmt: skip
        return before[: old.start()] + value + rest
    notes.append(f"corrected by the command itself: '{old.group(0)}' → '{value}'")
    return before[: old.start(1)] + m.group(1) + before[old.end(1) :] + rest


def _not_a_but_b(text: str, notes: list[str]) -> str:
    m = _NOT_A_BUT_B.search(text)
    if m is None:
        return text
    new = f"{m.group(3) or m.group(1) or ''}{m.group(4)}"
    notes.append(f"corrected by the command itself: '{m.group(2)}' → '{m.group(4)}'")
    return text[: m.start()] + new + text[m.end() :]


# "…, the 5 was wrong": the retraction a correction ends with, said of the number it replaces
_WAS_WRONG = re.compile(
    rf"\s*,?\s*\b(?:the\s+)?{_NUMBER}\s+(?:was|is)\s+(?:wrong|a\s+mistake|a\s+typo|incorrect|"
    r"not\s+right)\b",
    re.IGNORECASE,
)


_CONFIRMED = re.compile(
    r"(?:(?<=[.;!?])|^)(\s*)(?:yes|yeah|yep|right|exactly|correct|that'?s\s+(?:it|right))\b"
    r"\s*[,!.:;—–-]*\s*(?:an?|one)\s+([a-z]+)\b",
    re.IGNORECASE,
)


def _confirmed(m: re.Match[str], notes: list[str]) -> str:
    """ "…, no, a wall of 4. Yes, a wall, 4 long and 2 high": the wall named before, said
    again with more about it (it was a second wall)."""
    family = lx.SHAPE_WORDS.get(m.group(2).lower())
    before = [lx.SHAPE_WORDS.get(w) for w in re.findall(r"[a-z]+", m.string[: m.start()].lower())]
    if family is None or family not in before:
        return m.group(0)
    notes.append(f"read '{m.group(0).strip()}' as the {m.group(2)} named before, said again")
    return f"{m.group(1)}the {m.group(2)}"


_RESTATED = re.compile(
    rf"(?<=[.?!;])(\s*)(?:(?:yes|yeah|yep|yup|ok|okay|right|so|that'?s|i\s+said)\s*,?\s*)?({_NUMBER})"
    r"(?:\s+(?:cubes?|blocks?|of\s+them))?\s*(?:[.!?]+\s*|$)",
    re.IGNORECASE,
)


def _restated(text: str, notes: list[str]) -> str:
    """ "maybe a tower of 4? yeah 4 cubes", "six cubes? no seven. seven cubes": a sentence
    that only says again the number said last before it (it was built a second time)."""

    def drop(m: re.Match[str]) -> str:
        said = re.findall(rf"\b{_NUMBER}\b", m.string[: m.start()], re.IGNORECASE)
        if not said or words_to_numbers([said[-1].lower()]) != words_to_numbers(
            [m.group(2).lower()]
        ):
            return m.group(0)
        notes.append(f"read '{m.group(0).strip()}' as the {m.group(2)} said before, confirmed")
        return m.group(1)

    return _RESTATED.sub(drop, text)


def correct(text: str, notes: list[str], material: list[str] | None = None) -> str:
    """`text` with every "old …, no wait, new" replaced by the corrected wording, and a number
    only confirmed again dropped; a correction whose old value the command says more than once
    is also in `material`."""
    return _restated(_corrected(text, notes, material), notes)


_INSTEAD = re.compile(
    rf"\s*,?\s*\b(?:instead\s+of|rather\s+than|in\s+place\s+of)\s+(?:the\s+)?(?:old\s+)?{_NUMBER}"
    r"(?:\s+(?:cubes?|levels?|steps?|layers?|high|long|wide))?\b(?!\s*(?:x|by)\b)",
    re.IGNORECASE,
)
"""'a base of 5 this time instead of 4': the size it replaces, not one of its own."""


def _instead(m: re.Match[str], notes: list[str]) -> str:
    clause = re.split(r"[.;!?]", m.string[: m.start()])[-1]
    if re.search(r"\b(?:make|change|set|turn|widen|narrow|extend|shorten|raise|lower)\b", clause,
                 re.I):
        return m.group(0)  # "then make it 3 wide instead of 2": which side changes, for modify
    notes.append(f"read '{m.group(0).strip(' ,')}' as the size it replaces")
    return " "


_BETTER = re.compile(
    rf"(?<=[.;,!?])\s*(?:(?:hmm+|um+|well|maybe|actually|i\s+think)\s*,?\s*)?({_NUMBER}(?:\s+[a-z]+)?)"
    r"\s+(?:would\s+be|'d\s+be|is|are|will\s+be|might\s+be|sounds|looks)\s+(?:a\s+lot\s+|much\s+)?"
    r"(?:better|enough|plenty|nicer|best|more\s+like\s+it|right|fine|ok|okay|good|perfect)\b",
    re.IGNORECASE,
)
"""'a staircase, 5 steps. 3 steps would be better': the value said again, as its correction."""


def _better(m: re.Match[str]) -> str:
    if not re.search(rf"\b{_NUMBER}\b", m.string[: m.start()], re.IGNORECASE):
        return m.group(0)  # "a staircase, 3 steps is enough": the only value said
    return f" make that {m.group(1)}"


_FINAL_AGAIN = re.compile(
    rf"\b({_NUMBER})\s*[,.;:!?…—–-]*\s*(?:so\s+)?final\s+(?:answer|call|decision|number|offer)\s*(?:is\s*)?"
    r"[,:;=—–-]*\s*\1\b",
    re.IGNORECASE,
)
"""'no wait 6, final answer 6': the number said last, confirmed."""


_RELATION = (
    r"(?:behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|(?:left|right)\s+of|next\s+to|beside|"
    r"on\s+top\s+of|under(?:neath)?|below)"
)
_RELATION_AGAIN = re.compile(
    r"\s*[,.;:!?…—–-]+\s*(?:no\s*,?\s*wait|wait\s*,?\s*no|no\s*,?\s*sorry|sorry|actually|no|wait|"
    r"i\s+meant?|make\s+that|or\s+rather)\s*[,:;—–-]?\s*(?:put\s+it\s+|it\s+goes\s+)?"
    rf"(?P<new>{_RELATION})\s+(?:it|them|that|the\s+\w+)\s*(?=[.;!?]|$|,\s*(?:and|then)\b)",
    re.IGNORECASE,
)
"""'a tower of 2 in front of a wall of 5. No wait, behind it.': the relation said again."""


def _relation_again(text: str, notes: list[str]) -> str:
    """The relation said before a correction that names another one, replaced by it (the
    correction was read as nothing, and a second tower built, silently)."""
    m = _RELATION_AGAIN.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    olds = list(re.finditer(rf"\b{_RELATION}\b", before, re.IGNORECASE))
    if not olds:
        return text
    old = olds[-1]
    notes.append(f"corrected by the command itself: '{old.group(0)}' → '{m.group('new')}'")
    return before[: old.start()] + m.group("new") + before[old.end() :] + text[m.end() :]


def _corrected(text: str, notes: list[str], material: list[str] | None = None) -> str:
    text = _relation_again(text, notes)
    text = _FINAL_AGAIN.sub(r"\1", text)
    text = _BETTER.sub(_better, text)
    text = _INSTEAD.sub(lambda m: _instead(m, notes), text)
    if MARKER.search(text):
        text = _WAS_WRONG.sub(" ", text)
    text = _CONFIRMED.sub(lambda m: _confirmed(m, notes), text)
    text = _names_again(text, notes)
    text = _not_a_but_b(text, notes)
    text = _SPOKEN_NO.sub(r"\1, no, ", text)
    for _ in range(4):  # a command rarely corrects itself more than once or twice
        m = MARKER.search(text)
        if m is None or m.start() == 0:
            return text
        before, after = text[: m.start()], text[m.end() :]
        value_next = re.match(r"\s*[.;]\s*([^.;!?]+)", after)
        if (
            re.search(r"scratch|forget|cancel", m.group(0), re.I)
            and value_next
            and re.match(rf"\s*{_NUMBER}\b", value_next.group(1), re.I)
            and not _names_structure(value_next.group(1))
        ):
            after = " " + after[value_next.start(1) :]  # "… 4 cases. scratch that. 3 cases."
        head = re.split(r"(?<=[.;!?])\s|,\s*(?=and\b|then\b)", after, maxsplit=1)
        said, rest = head[0], after[len(head[0]) :]
        stop = re.search(r"[.;!?]+\s*$", said)
        if stop:  # "no, 4 high. then on the right": the sentence ends where it ended
            said, rest = said[: stop.start()], stop.group(0) + rest
        first = re.match(r"[^,;—–-]+", said)
        if (
            first
            and first.end() < len(said.rstrip(" .!?"))
            and (_value(first.group(0)) is not None or _NOUN_VALUE.fullmatch(first.group(0)))
        ):
            # "four towers of 2, make that five, in a row": the value, then the command goes on
            said, rest = first.group(0), after[first.end() :]
        value = _FILLER.sub("", _NOT_OLD.sub("", said.strip())).strip(" ,.;!?")
        value = _AND_NOT_OLD.sub("", _NOT_OLD_SPOKEN.sub("", value))  # "h=6, not 8"
        value = _PARTS.sub("", _HEDGE.sub("", value))  # "no wait, 4 I think"
        side = _OF_IT.sub("", value)  # "to the right of it": the side of the same relation
        if side != value and _kind(side) == "region":
            value = side
        place = re.sub(r"\s+(?:hand\s+)?(?:corner|side|edge)$", "", value, flags=re.I)
        if place != value and _kind(place) == "region":
            value = place  # "in the back right corner. Hmm, no, front left corner."
        kind = _kind(value) if value and not _names_structure(value) else None
        renamed = _noun_first(before, value, rest, notes)  # "with base 4... no, base 3"
        if renamed is not None:
            text = renamed
            continue
        recounted = _with_noun(before, value, rest, notes)  # "3 towers, no wait, 4 towers"
        if recounted is not None:
            text = recounted
            continue
        if kind is None and not _names_structure(value):
            dimensioned = _with_dimension(before, value, rest, notes)
            if dimensioned is not None:
                text = dimensioned
                continue
        if kind is None and _names_structure(value):  # "a tower. scratch that, a wall 3 long"
            replaced = _another_structure(before, after, notes)
            if replaced is not None:
                text = replaced
                continue
        if not value and re.search(r"scratch|forget|cancel", m.group(0), re.I):
            # "a tower of 5 behind it. scratch that. a wall …": the step before, taken back
            text = before.rstrip(" ,;:—–-") + ". then undo that. " + rest.lstrip(" .,;")
            continue
        if kind is None:  # a correction in words of its own: a clause the later stages read
            change = re.search(r"\bmake\s+(?:that|it)\s*$", m.group(0).strip(" ,:;—–-"), re.I)
            said_after = f"make it {after}" if change else after  # "actually make it one taller"
            text = before.rstrip(" ,;:—–-") + ". then " + said_after
            continue
        olds = (
            _bare_counts(before)
            if kind == "count"
            else list(_KINDS[[k for k, _ in _KINDS].index(kind)][1].finditer(before))
        )
        if not olds:
            return text
        old = olds[-1]
        counted = _COUNTED.search(before) if kind == "count" else None
        fewer = re.match(r"\s*(?:just|only)\b", said) or re.search(r"\b(?:just|only)\s*$",
                                                                   m.group(0))
        if counted and (counted.end() >= len(before.rstrip(" ,;:—–-")) or fewer):
            # "four towers of 2, make that five": the count of the structures is what was counted;
            # "5 towers of 1 in a row. actually just 4.": the structures, fewer
            old = next((o for o in olds if o.start() == counted.start(1)), old)
        negated = re.match(r"(?:no\s*,?\s*)?not\s+(\w+)\s*[,;]", said.strip(), re.IGNORECASE)
        if negated and kind == "count":
            number = words_to_numbers([negated.group(1).lower()])[0]
            same = [o for o in olds if words_to_numbers([o.group(0).lower()])[0] == number]
            if len(same) > 1:
                # "Three towers of 3. No, not three, two": which three is not said
                if material is not None:
                    material.append(f"not {negated.group(1)}")
                notes.append(f"ignored 'not {negated.group(1)}': the command says "
                             f"{negated.group(1)} {len(same)} times; changed the last")  # fmt: skip
        notes.append(f"corrected by the command itself: '{old.group(0)}' → '{value}'")
        if kind == "region" and old.group(0).lower() == "behind" and value.lower() in _SIDES:
            value = lx.BESIDE_PHRASE[value.lower()]  # "behind it. no wait, in front of it"
        text = before[: old.start()] + value + before[old.end() :] + rest
    return text


_SIDES = ("front", "left", "right")
"""The other sides a correction of "behind" (a relation word) may name."""


_COUNTED = re.compile(rf"\b({_NUMBER})\s+(?:[a-z]+\s+)?[a-z]+s\s+(?:of|with)\s+{_NUMBER}\b", re.I)


def _bare_counts(text: str) -> list[re.Match[str]]:
    """The bare numbers in `text`: not one of a size group ("3 x 5") or a length ("30 cm")."""
    return [o for o in _KINDS[2][1].finditer(text) if _kind(_widest(text, o)) == "count"]


def _widest(text: str, m: re.Match[str]) -> str:
    """The number `m` together with a unit or size group it belongs to."""
    for _, pattern in _KINDS[:2]:
        for g in pattern.finditer(text):
            if g.start() <= m.start() and m.end() <= g.end():
                return g.group(0)
    return m.group(0)
