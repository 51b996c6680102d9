"""Stage 1: normalise a command's text — symbols, contractions, lists, homophones and number
forms — before anything reads it. Numbers SDI cannot use (not finite, past 10⁶) are refused."""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable, Sequence

from rapidfuzz.distance import DamerauLevenshtein

from sdi.errors import SpecError
from sdi.language.everyday import EVERYDAY
from sdi.language.nouns import families_said, shape_alternation
from sdi.language.spacing import MOVED
from sdi.language.units import declared, things, to_millimetres
from sdi.language.words import CORRECTABLE, NEGATIONS, SIGNIFICANT
from sdi.spec import lexicon as lx
from sdi.spec.numbers import FACTORS, UNITS, words_to_numbers

_SYMBOLS = {"×": " x ", "–": "-", "—": "-", "’": "'", "″": '"', "\u00a0": " "}


_DIMS = re.compile(r"(?<=\d)\s*[x*]\s*(?=\d)", re.IGNORECASE)


SPACES = re.compile(r"\s+")


_CONTRACTIONS = [
    (re.compile(r"\b(can)'?t\b", re.IGNORECASE), r"\1 not"),
    (re.compile(r"\bwon'?t\b", re.IGNORECASE), "will not"),
    (re.compile(r"\b(is|are|was|were|do|does|did|should|must|could|would)n'?t\b", re.I), r"\1 not"),
]


_SCIENTIFIC = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?|\.\d+)[eE]([+-]?\d+)\b")


_NOT_A_NUMBER = re.compile(r"(?<![\w])(nan|inf|infinity)(?![\w])", re.IGNORECASE)


_DECIMAL_COMMA = re.compile(r"(?<=[=:])\s*(-?\d+),(\d+)\b(?!\s*(?:,|and)\s*\d)")
# "0,3 m", "0,2 x 0,15 m", "1,5 metres": a decimal comma before a unit or a size's "x"/"by"
# (a list "3,4 and 5 towers" has no unit after it)
_DECIMAL_COMMA_UNIT = re.compile(
    r"(?<![\d,])(0|[1-9]\d?),(\d{1,3})(?=\s*(?:mm|cm|m|met(?:re|er)s?|x|by)\b)"
    r"|(?<![\d,])(0),(\d{1,3})\b(?!,\d)",
    re.IGNORECASE,
)


_REFERENCE_NO = re.compile(
    r"(?:#|\bno\.\s*|\bnumber\s+)\d+\b|\b(?:order|ticket|job|ref|request|id|station|cell|booth|"
    r"hall|aisle|lab|desk|batch|lot|week|version|rev|entry|sheet|page|room|bay|figure|fig|stn|"
    r"run|trial|session|group|team|building|shift|day|item|tab|slide|chapter|section|cycle|"
    r"serial|pallet\s+id|work\s+order|wo|po|part\s+no|label|exhibit|plot|model|drawing|dwg|kit|display|"
    r"exercise|lesson|experiment|protocol|procedure|sample|bench|rig|line(?:\s+no)?|step|task|assignment|question|(?:test\s+)?case|test|scenario|round|mission|quest|spec)\s*"
    r"(?:[:#]|-(?=\d))?\s*[A-Za-z]*\d[\w-]*(?:\s+of\s+\d+\b)?|\b\d{3,}-\d+\b"
    r"|(?-i:\b[A-Z][A-Z0-9]{1,9}-\d+\b)"  # a ticket's key: "SDI-101", "WO-3321"
    r"|\b\d{1,2}(?:[:.]\d{2})?\s*(?:am|pm|a\.m\.|p\.m\.)(?!\w)|\b\d{1,2}:\d{2}\b",
    re.IGNORECASE,
)


# a name of a place glossed in brackets with a place the cell knows: "the spawn point (the
# middle)", "the loading side (i.e. the front)"
_PLACE_GLOSS = re.compile(
    r"\bthe\s+(?:[a-z-]+\s+){1,3}?\(\s*(?:i\.?e\.?,?\s+|aka\s+|=\s*)?"
    r"(the\s+(?:middle|centre|center|left|right|front|back)(?:\s+(?:left|right))?"
    r"(?:\s+(?:side|edge|corner|half))?)\s*\)",
    re.IGNORECASE,
)


_FAMILY_SAID = shape_alternation(min_len=3)
_ONE_NEW = r"(?:and\s+)?(?:then\s+)?(?:put\s+|place\s+)?(?:an?|one|another)\s+"
_RELATION_SAID = (
    r"(?:in\s+front\s+of|behind|to\s+the\s+(?:left|right)\s+of|next\s+to|beside|on\s+top\s+of|on|"
    r"against|in\s+the\s+middle\s+of)"
)
_TABLE_ENDS = re.compile(r"\bends?\s+of\s+the\s+(?:table|workspace|bench|cell)\b", re.IGNORECASE)
_BOTH_IT = re.compile(
    r"\b(?P<prev>" + _FAMILY_SAID + r")\b(?P<head>[^.;]*?,\s*" + _ONE_NEW
    + r"(?P<fam1>" + _FAMILY_SAID + r")\b[^.;,]*?\b" + _RELATION_SAID + r"\s+it)"
    + r"(?P<mid>\s*,?\s+" + _ONE_NEW + r"(?P<fam2>" + _FAMILY_SAID + r")\b[^.;,]*?\b"
    + _RELATION_SAID + r"\s+)it\b",
    re.IGNORECASE,
)
"""'a wall, a tower of 3 behind it and a tower of 2 in front of it': both "it"s name the wall."""
_ONE_OF_EACH = re.compile(r"\bone\s+(?:of|with|tower|stack|wall|row)\b(?![^.;]*[.;])", re.I)
"""'two towers, one of 3 and one of 5': the first of a list naming each one."""
_CORNERS_OF = {
    "back": ("back left", "back right"), "front": ("front left", "front right"),
    "left": ("front left", "back left"), "right": ("front right", "back right"),
    "rear": ("back left", "back right"), "far": ("back left", "back right"),
    "near": ("front left", "front right"),
}  # fmt: skip
"""The two corners on one side of the table: "in each back corner"."""
_SHAPE_NOUNS = frozenset(w for w in lx.SHAPE_WORDS if w not in lx.AMBIGUOUS_SHAPES and len(w) > 2)


# "a tower x3", "pyramid ×2": that many of it (not a coordinate: "x 3" and "x=3" have a space
# or a sign; "x3" straight after the family name is a count)
_TIMES_N = re.compile(
    r"\b(?:a\s+|an\s+|one\s+)?(" + _FAMILY_SAID + r")"
    r"(\s+of\s+\d+(?:\s+(?:high|tall|long|cubes?))?(?=\s+[x×]))?"
    r"\s*[x×](\d+)\b(?![.,]\d|\s*(?:x|by|cm|mm|m)\b)",
    re.IGNORECASE,
)


# a stage's directions, said from the performer facing the audience (at the front): downstage
# is the front, upstage the back, stage left the cell's right and stage right its left
_STAGE = re.compile(
    r"\b(?:(down|up)[\s-]?stage|centre[\s-]stage|center[\s-]stage)(?:\s+(left|right|centre|center))?\b"
    r"|\bstage\s+(left|right)\b",
    re.IGNORECASE,
)


_STAGE_OF = re.compile(r"\b(down|up)[\s-]?stage\s+(?:of|from)\b", re.IGNORECASE)


def _stage(text: str, notes: list[str]) -> str:
    # "upstage of the tower": behind it (a relation, not a place on the table)
    text = _STAGE_OF.sub(
        lambda m: " in front of " if m.group(1).lower() == "down" else " behind ", text
    )

    def place(m: re.Match[str]) -> str:
        depth = {"down": "front", "up": "back"}.get((m.group(1) or "").lower(), "")
        side = (m.group(2) or m.group(3) or "").lower()
        side = {"left": "right", "right": "left"}.get(side, "")  # the performer's left
        said = " ".join(w for w in (depth, side) if w) or "centre"
        notes.append(f"read '{m.group(0)}' as {'the ' + said} (stage directions are the "
                     "performer's, facing the front)")  # fmt: skip
        before = m.string[: m.start()]
        if re.search(r"\b(?:ris\w*|climb\w*|ascend\w*|up)\s*$", before, re.I):
            return f" towards the {said} "  # "treads rising upstage"
        towards = re.search(r"\b(?:towards?|toward|to|at|in|on)\s*$", before, re.I)
        return f" the {said} " if towards else f" at the {said} "

    return _STAGE.sub(place, text)


def _sized_cube(m: re.Match[str]) -> str:
    """ "a 150 mm cube": a block 150 mm each way; a cube one part wide stays one part."""
    size = float(m.group(1)) * lx.UNITS_M[m.group(2).lower()]
    if size < 0.075:
        return m.group(0)
    side = f"{m.group(1)} {m.group(2)}"
    return f"a {side} by {side} by {side} block"


def _plus(m: re.Match[str]) -> str:
    """ "half a dozen cubes plus one": the sum."""
    said = m.group(1).lower()
    first = 6 if said.startswith("half") else 12 if "dozen" in said else int(
        words_to_numbers([said])[0])  # fmt: skip
    return f"{first + int(words_to_numbers([m.group(3).lower()])[0])} {m.group(2) or ''}"


_APART_SAID = re.compile(
    r"\b(?:apart|gap|between|clear|centre\s+to\s+centre|center\s+to\s+center)\b", re.I
)
_BRIDGE = re.compile(r"\b(?:bridge|arch)\b", re.IGNORECASE)
_DIGITS = {w: n for w, n in UNITS.items() if n <= 12 and w not in ("no", "single")} | {
    "wun": 1, "fower": 4, "fife": 5, "niner": 9, "tree": 3,
}  # fmt: skip
_DIGIT_WORD = "zero|one|two|three|four|five|six|seven|eight|nine|wun|fower|fife|niner|tree"
_EACH_AT = {"at": "at", "in": "in"}  # "one per corner" stands on each; "one at each end" at it
_PER_ANCHOR = {"corner": 4, "end": 2, "side": 2}


_EACH_SIDE_NAMED = re.compile(
    r"[\s,]*(?:it\b|them\b|that\b|this\b)?[\s,]*one\s+(?:in\s+front|behind|on\s+the|to\s+the|at\s+the|"
    r"left|right|front|back)\b",
    re.IGNORECASE,
)
"""'…, one in front, one behind, one left, one right': each of the four named after it."""


def _one_per_anchor(m: re.Match[str]) -> str:
    """ "4 towers of 2, on each corner": a tower of 2 on each corner, when the count is the
    number of corners or ends; "two towers, one on each side" of a structure named before it
    or after it: one on either side, "four towers …, one on each side": one on all four."""
    count = words_to_numbers([m.group(1).lower()])[0]
    anchor = (m.group(5) or m.group(6)).lower()
    if anchor == "side":
        of = re.match(r"\s+of\s+(?:the\s+)?(\w+)", m.string[m.end() :], re.I)
        if of and of.group(1).lower() in ("table", "workspace", "cell", "bench", "area"):
            return m.group(0)
        sentence = re.split(r"[.;!?]\s", m.string[: m.start()])[-1]
        if not of and not re.search(rf"\b(?:{_FAMILY_SAID})\b", sentence, re.I):
            return m.group(0)  # "Two towers at the front, one on each side": the table's
        if count == "4":  # "four towers around the slab, one on each side": on all four
            said, *around = re.split(r"\s*,?\s*\b(?:a?round|surrounding)\s+", m.group(3),
                                     maxsplit=1, flags=re.I)  # fmt: skip
            whose = " of " + around[0].strip(" ,") if around else ""
            return f"a {m.group(2)}{said} on all four sides{whose}"
    if count != str(_PER_ANCHOR[anchor]):
        return m.group(0)
    said = m.group(4) if m.group(5) else "on each side"
    sized = re.sub(r"\s*,\s*", " ", m.group(3)).rstrip()  # "four towers, two high, one in each …"
    return f"a {m.group(2)}{sized} {said}"


def _product(m: re.Match[str]) -> bool:
    """The count said (group 2) is the rows (3) times the parts per row (4)."""
    n, rows, each = words_to_numbers([m.group(2).lower(), m.group(3).lower(), m.group(4).lower()])
    return (n + rows + each).isdigit() and int(n) == int(rows) * int(each)


_DECK = re.compile(
    r"\b(?:lay|put|place|set)\s+(?:the|a)\s+deck\b|\bdeck\s+(?:across|over|on|spanning)\b"
    r"|\bwith\s+a\s+deck\s+across\b",
    re.IGNORECASE,
)
_BOTH_SIDES = (
    r"\s*,?\s*(?:left\s+and\s+right|right\s+and\s+left|front\s+and\s+back|back\s+and\s+front)\b"
)

_DIMENSION_ADJ = {
    "height": "high", "high": "high", "length": "long", "long": "long", "width": "wide",
    "wide": "wide", "depth": "deep", "thickness": "thick", "large": "long",
}  # fmt: skip

_FOREIGN_COURTESY = re.compile(
    r"\b(?:hoi|doei|dank\s+(?:je|u)(?:\s+wel)?|bedankt|dzi(?:ę|e)kuj(?:ę|e)|spasibo|"
    r"danke(?:\s+sch(?:ö|oe)n)?|gracias|merci(?:\s+beaucoup)?|grazie|privet|cze(?:ść|sc)|bitte(?:\s+sch(?:ö|oe)n)?|"
    r"guten\s+(?:morgen|tag|abend)|hallo|tsch(?:ü|ue)ss|por\s+favor|obrigad[oa]|muito\s+obrigad[oa]|"
    r"hola|buenos\s+d[ií]as|bom\s+dia|ol[aá]|ciao|buongiorno|prego|bonjour|s'il\s+vous\s+pla[iî]t|"
    r"ja|jawohl|genau|fertig|kisses|besos|beijos)\b[!.,]?",
    re.IGNORECASE,
)
_CHAT_COURTESY = re.compile(
    r"\b(?:rn|tysm|thx|thnx|tx|ty|lol|lmao|asap)\b|,?\s*\bif\s+(?:that'?s|that\s+is|it'?s|it\s+is)\s+"
    r"(?:ok|okay|alright|all\s+right|fine|possible|not\s+too\s+much\s+trouble)\b|,?\s*\bif\s+you\s+"
    r"(?:can|could|don'?t\s+mind|do\s+not\s+mind)\b|,?\s*\bif\s+possible\b",
    re.IGNORECASE,
)
"""A chat's "right now", "thank you so much", "thanks", "lol" (its full stop kept)."""


def courtesy(text: str) -> str:
    """`text` without greetings and thanks in other languages ("Hoi!", "Dank je!"), read before
    typo correction (which would make "Dank" a rank)."""
    return _CHAT_COURTESY.sub(" ", _FOREIGN_COURTESY.sub(" ", text))


_IDIOMS = re.compile(
    r"\b(?:break\s+a\s+leg|good\s+luck|(?:a\s+)?quick\s+one(?:\s+before\s+the\s+(?:half|break|show|"
    r"break|end\s+of\s+(?:the\s+)?shift))?|fingers\s+crossed|knock\s+yourself\s+out|"
    r"no\s+(?:worries|dramas|rush|hurry|stress)(?:\s+mate)?)\b[!.,:]?",
    re.IGNORECASE,
)
_SQUARED = re.compile(r"\bthe\s+square\s+of\s+(\d+)\b|\b(\d+)\s+squared\b", re.IGNORECASE)


_SAME_AS = re.compile(
    r"(?:\b(?:of\s+|with\s+)?the\s+|(?<=,)\s*)same\s+(length|height|width)(?:\s+as\s+(?:it|that(?:\s+one)?|the\s+(?:first|"
    r"other|last)\s+one))?(?!\s+as\s+the\s+(?!first\b|other\b|last\b)\w+)"
    r"|\bas\s+(long|tall|high)\s+as\s+(?:it|that(?:\s+one)?|the\s+(?:first|other)\s+one)\b",
    re.IGNORECASE,
)


_SUPERLATIVE = {"tall": "tallest", "high": "tallest", "big": "biggest", "large": "biggest",
                "long": "longest", "short": "shortest", "low": "shortest", "small": "smallest",
                "little": "smallest"}  # fmt: skip
_FAMILY_BEFORE = re.compile(r"\b(?:" + _FAMILY_SAID + r")\b", re.IGNORECASE)
_SYMBOL = {1.0: "m", 0.01: "cm", 0.001: "mm"}  # the symbol of a unit said in full (lx.UNITS_M)


def _words_figure(said: str) -> str | None:
    """ "one hundred and fifty ": 150; None when the words are no single figure."""
    words = [w for w in re.split(r"[\s-]+", said.strip().lower()) if w]
    while words and words[0] == "and":
        words = words[1:]
    if not words or words[-1] == "and":
        return None
    got = words_to_numbers(words)
    return got[0] if len(got) == 1 and got[0].isdigit() else None


# "…, the wall is 3 long": where the next description of a structure named begins
_EACH_DESCRIBED = re.compile(
    r",?\s+(?:and\s+)?(?=the\s+(?:" + _FAMILY_SAID + r")\s+(?:is|are|should|must|has|needs|will|"
    r"to\s+be|\d|one|two|three|four|five|six|an?)\b)",
    re.IGNORECASE,
)
_LIKENED = re.compile(
    r"\s*[,—-]*\s*\b(?:about\s+|roughly\s+|around\s+|nearly\s+|so\s+|almost\s+)?as\s+(?:tall|high|long|"
    r"wide|big)\s+as\s+(?:an?|my|your|our|the)\s+([a-z][a-z' ]{1,30}?)(?=\s*(?:$|[.;!,]))",
    re.IGNORECASE,
)
_FIGURE_SAID = re.compile(r"\d\s*(?:mm|cm|m)\b[^.;!]*$", re.IGNORECASE)


def _likened(text: str, notes: list[str]) -> str:
    """ "a tower 30 cm tall — about as tall as a school ruler": a likeness that glosses a figure
    said before it, not a size of its own."""

    def gloss(m: re.Match[str]) -> str:
        words = m.group(1).lower().split()
        if not _FIGURE_SAID.search(m.string[: m.start()]) or any(
            w in lx.SHAPE_WORDS or w in ("one", "it", "that", "first", "second", "other", "row")
            for w in words
        ):
            return m.group(0)
        notes.append(f"read '{m.group(0).strip(' ,—-')}' as a likeness of the size said")
        return ""

    return _LIKENED.sub(gloss, text)


_BY_IT = re.compile(
    r"\b(?:next\s+to|beside|behind|in\s+front\s+of|on\s+top\s+of|left\s+of|right\s+of)\s+it\b"
    r"[^.;]*$",
    re.IGNORECASE,
)


def _same_as(m: re.Match[str]) -> str:
    """ "a wall of the same length behind it", "a tower as tall as the first one": as long (tall)
    as the structure named just before, by its name (it was dropped, or a tower of 1 built)."""
    before = m.string[: m.start()].lower()
    prev = re.findall(r"[a-z]+", before)[-1:]
    bare = not re.match(r"(?:of|with|as|same)\b", m.group(0).strip(), re.I)
    if re.search(r"\bmake\s+(?:it|them|the\s+\w+(?:\s+one)?)\s*$", before) or (
        bare and not (prev and (prev[0] == "one" or prev[0] in lx.SHAPE_WORDS))
    ):
        return m.group(0)  # "make the first one the same height", "none of them the same height"
    # the phrase the size is said in (", same length": the one before the comma)
    own = re.split(r"\band\b|,|;|\bthen\b", before.rstrip(" ,"))[-1]
    counted = re.findall(
        r"\b(?:\d+|two|three|four|five|six|seven|eight|nine|ten|both|all|each)\s+([a-z]+)", own
    )
    own_nouns = [w for w in re.findall(r"[a-z]+", own) if w in lx.SHAPE_WORDS]
    before_own = before.rstrip(" ,")[: len(before.rstrip(" ,")) - len(own)]
    said_before = [w for w in re.findall(r"[a-z]+", before_own) if w in lx.SHAPE_WORDS]
    if m.group(0).strip().lower().startswith("same") and (
        any(w in lx.SHAPE_WORDS or w.rstrip("s") in lx.SHAPE_WORDS for w in counted)
        or (
            own_nouns
            and said_before
            and lx.SHAPE_WORDS[own_nouns[-1]] == lx.SHAPE_WORDS[said_before[-1]]
            and not re.search(r"\b(?:second|another|other|next|new|more)\b", own)
        )
    ):
        # "Total 2 tower, same height", "a tower of 3 and a tower of 4, same height": a claim
        # of their own, checked later
        return m.group(0)
    earlier = before_own if own_nouns else before
    named = [
        w for w in re.findall(r"[a-z]+", earlier)
        if w in lx.SHAPE_WORDS and w not in lx.AMBIGUOUS_SHAPES
    ]
    if not named:
        return m.group(0)  # "two towers of the same height": a claim of their own, checked later
    last = named[-1]
    if (
        re.search(r"\bas\s+\w+\s+as\s+it\b", m.group(0), re.I)
        and _BY_IT.search(before)
        and len(named) >= 2
    ):
        last = named[-2]  # "then a tower next to it, as tall as it is": the one it stands by
    noun = last[:-1] if last.endswith("s") and last[:-1] in lx.SHAPE_WORDS else last
    said = (m.group(1) or m.group(2)).lower()
    word = {"length": "long", "long": "long", "width": "wide"}.get(said, "tall")
    return f" as {word} as the {noun} "


def _height_run(m: re.Match[str]) -> str:
    """ "heights 1 to 5": "heights 1, 2, 3, 4 and 5" (at most ten, rising)."""
    low, high = int(m.group(2)), int(m.group(3))
    if not 1 <= low < high <= 10:
        return m.group(0)
    run = [str(v) for v in range(low, high + 1)]
    return f"{m.group(1)}{', '.join(run[:-1])} and {run[-1]}"


_NUM = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
_A_PLACE = r"(?:(?:back|front|rear)(?:[\s-](?:left|right))?|left|right|middle|centre|center)"
_PROGRESSION = re.compile(
    r"\b(" + _NUM + r")\s+(towers|stacks|columns|pillars|posts)\b([^.;:]*?)\s*,?\s*(?:with\s+)?each"
    r"(?:\s+one)?\s+(?:(" + _NUM + r"|a)\s+)?(?:(?:cubes?|blocks?|levels?)\s+)?"
    r"(taller|higher|shorter|lower)\s+"
    r"than\s+the\s+(?:one\s+(?:before(?:\s+it)?|to\s+its\s+(?:left|right)|on\s+its\s+(?:left|right))|"
    r"last(?:\s+one)?|previous(?:\s+one)?)"
    r"(?:\s*,?\s*(?:starting|beginning)\s+(?:at|with|from)\s+(" + _NUM + r")"
    r"(?:\s+(?:cubes?|high|tall))?)?",
    re.IGNORECASE,
)
"""'three towers in a row, each one cube taller than the one before': heights that rise by a
step (every tower was built 1 high, the comparison reported unused)."""


_WAY_UP_CORRECTED = re.compile(
    r"(\b(?:going|climbing|rising|goes|climbs|rises)\s+up\s+(?:to(?:wards?)?|toward)\s+the\s+)"
    r"(left|right|back|front)\s*,?\s*(?:no|sorry|wait|i\s+mean|rather)\s*,?\s*(?:to(?:wards?)?|toward)\s+"
    r"the\s+(left|right|back|front)\b(?:\s*,?\s*actually\b)?",
    re.IGNORECASE,
)
"""A staircase's way up corrected ("going up to the back, no, to the front actually"): the
correction was read as a place on the table."""
_TOO_HIGH = re.compile(
    r"(\b" + _NUM + r"\s+(?:cubes?\s+)?(?:long|wide|deep)\s+"
    r"and\s+)too\s+(high|tall|long|wide|deep)\b",
    re.IGNORECASE,
)
"""'a wall six long and too high' (spoken): two high, a size beside a size (4 high were built
for a vague "high")."""


def _progression(m: re.Match[str], notes: list[str]) -> str:
    said = [words_to_numbers([g.lower()])[0] if g else "" for g in m.groups()]
    count, step, start = int(said[0]), int(said[3]) if said[3].isdigit() else 1, said[5]
    own = re.search(r"\b(?:of|(?:starting|beginning)\s+(?:at|with|from))\s+(" + _NUM + r")\b|\b("
                    + _NUM + r")\s+(?:cubes?\s+)?(?:high|tall)\b", m.group(3), re.IGNORECASE)
    if own and not start.isdigit():  # "three towers, the first of 2, each one taller …"
        start = words_to_numbers([(own.group(1) or own.group(2)).lower()])[0]
    listed = re.match(r"\s*[:,-]?\s*" + _NUM + r"\s*,", m.string[m.end() :], re.IGNORECASE)
    if listed:  # "… taller than the one before: one, two, three": the heights are listed
        return f"{m.group(1)} {m.group(2)}{m.group(3)}"
    rising = m.group(5).lower() in ("taller", "higher")
    rest = m.string[: m.start()] + " " + m.string[m.end() :]
    if not start.isdigit() and (
        not rising or re.search(r"\b" + _NUM + r"\b", rest, re.IGNORECASE)
    ):
        # "each one shorter than the last": from what height is not said; a number said
        # elsewhere may say it ("… the smallest 2 high"), so nothing is guessed
        return m.group(0)
    first = int(start) if start.isdigit() else 1
    heights = [first + (k if rising else -k) * step for k in range(count)]
    if not 2 <= count <= 10 or min(heights) < 1 or max(heights) > 20:
        return m.group(0)
    run = [str(h) for h in heights]
    notes.append(f"read '{m.group(0).strip()}' as heights {', '.join(run)}"
                 + ("" if start.isdigit() else " (the first 1 high: where it starts was not said)"))
    return f"{m.group(1)} {m.group(2)}{m.group(3)}, heights {', '.join(run[:-1])} and {run[-1]}"


def _list_in_cubes(m: re.Match[str]) -> str:
    """ "5, 10 and 15 cm": "1, 2 and 3 cubes" when every value is a whole number of 5 cm cubes
    (the unit said once was read for the last value only)."""
    values = [float(v) for v in re.findall(r"\d+(?:\.\d+)?", m.group(1))]
    mm = [v * (10.0 if m.group(2).lower() == "cm" else 1.0) for v in values]
    if any(v <= 0 or abs(v / 50.0 - round(v / 50.0)) > 1e-9 for v in mm):
        return m.group(0)
    cubes = [str(round(v / 50.0)) for v in mm]
    return f"{', '.join(cubes[:-1])} and {cubes[-1]} cubes"


# phrasings of operators whose English is not (only) British or American — a Slavic or Dutch
# speaker's prepositions ("tower from 5 cubes", "behind of wall", "near to wall"), Indian
# English focus words — and of other trades and notes, each read as the plain words it means
def _than(m: re.Match[str]) -> str:
    """ "two cubes shorter than 6": 4 high; "2 longer than 4": 6 long."""
    by, than = (int(words_to_numbers([m.group(k).lower()])[0]) for k in (1, 3))
    less = m.group(2).lower() in ("shorter", "lower")
    value = than - by if less else than + by
    if value < 1:
        return m.group(0)
    return f" {value} {'long' if m.group(2).lower() == 'longer' else 'high'} "


def _other_side(m: re.Match[str]) -> str:
    """ "on the left, actually the other side": moved to the side opposite the one said last."""
    said = re.findall(r"\b(left|right|front|back)\b", m.string[: m.start()].lower())
    return f", then move it to the {lx.OPPOSITE_SIDE[said[-1]]} " if said else m.group(0)


_PUT_THE = re.compile(
    r"(?:(?<=[.;!])|,\s*(?:and\s+)?then|\bthen|^)\s*(?:please\s+)?(?:put|place|move|set|stand)\s+the\s+([a-z]+)\s+"
    r"((?:right\s+|just\s+|directly\s+)?(?:behind|in\s+front\s+of|next\s+to|beside|to\s+the\s+(?:left|right)\s+of|"
    r"on\s+top\s+of)\s+the\s+([a-z]+))\s*[.!]?\s*$",
    re.IGNORECASE,
)


def _put_the(text: str) -> str:
    """ "a tower of 3 and a row of 3. put the row behind the tower": the row, said first, is
    set that way (the last sentence places two structures named before it)."""
    m = _PUT_THE.search(text)
    if not m or not all(w.lower() in lx.SHAPE_WORDS for w in (m.group(1), m.group(3))):
        return text
    before = text[: m.start()]
    named = re.compile(r"\b(?:an?|one)\s+(?:[\w-]+\s+){0,3}?" + re.escape(m.group(1))
                       + r"\b[^,.;]*?(?=\s*(?:,|\.|;|\band\b|$))", re.IGNORECASE)  # fmt: skip
    first = named.search(before)
    other = re.search(rf"\b{re.escape(m.group(3))}\b", before, re.I)
    if first is None or other is None or other.start() > first.start():
        return text  # the other named after it: the sentence as it is reads it
    return f"{before[: first.end()]} {m.group(2)}{before[first.end() :]}".rstrip(" .,;") + "."


def _square_of(m: re.Match[str]) -> str:
    """ "with 4 cubes in each layer": the square of that many (2 by 2; only squares match)."""
    side = round(int(words_to_numbers([m.group(1).lower()])[0]) ** 0.5)
    return f"{side} by {side}"


def _named_last(text: str) -> str | None:
    """The family of the structure named last in `text` (unambiguous family nouns only)."""
    said = families_said(re.sub(r"\b(?:in|into)\s+(?:a|one)\s+(?:row|line)\b", " ", text.lower()))
    return said[-1] if said else None  # ("in a row", "in a line": how they stand, no row)


_ENCLOSING = re.compile(
    r"\b(?:rings?|enclosures?|fences?|pens?|castles?|frames?|corrals?|courtyards?|hollow)\b", re.I
)
_EMPTY_INSIDE = re.compile(
    r"\b(?:hollow|empty|open|anything|nothing|something|no)\s+(?:\w+\s+)?$", re.I
)
_PLACED_AT = re.compile(
    r"\b(?:at|to|from|position(?:ed)?|placed|centred|centered|centre|center)\s*$", re.I
)
_NOT_THE_TABLE = r"(?!\s+(?:the\s+)?(?:table|workspace|cell|bench|work\s+area|tabletop)\b)"
_Repl = str | Callable[[re.Match[str]], str]
"""What a phrasing becomes: a template, or what a function of the match gives."""
_OTHER_SIDE = {"left": "right", "right": "left", "front": "back", "back": "front"}


def _pyramid_rows(m: re.Match[str]) -> str:
    """ "a pyramid with rows of 4, 3, 2 and 1": its base and levels, when the rows count down
    one at a time; else the words as they were."""
    if not re.search(r"\bpyramid", _sentence_before(m.string, m.start()), re.I):
        return m.group(0)
    rows = [int(v) for v in words_to_numbers(re.findall(_NUM, m.group(1), re.I)) if v.isdigit()]
    if len(rows) < 2 or any(a - b != 1 for a, b in itertools.pairwise(rows)):
        return m.group(0)
    return f" with a base of {rows[0]} , {len(rows)} levels "


def _listed_figures(said: str) -> str:
    """ "two, three, two" → "2, 3 and 2": a list of numbers in figures, the last after 'and'."""
    figures = words_to_numbers([w for w in re.findall(r"\w+", said.lower()) if w != "and"])
    return ", ".join(figures[:-1]) + " and " + figures[-1]


_RADIO = re.compile(
    r"(?:^|(?<=[.,;:!?]))\s*(?:(?:copy(?:\s+that)?|roger(?:\s+that)?|ten[\s-]four|10-4|wilco|radio\s+"
    r"check(?:\.{2,}|\s)*(?:ok(?:ay)?\s+cell)?|how\s+copy|over\s+and\s+out|over|out)\s*(?=[.,;:!?]|$))+",
    re.I,
)
"""Radio procedure words ("copy that.", ", how copy, over", "over and out"): no content."""
_LETTER_BEFORE = re.compile(
    r"\b(?:[LUTJ][\s-]*(?:shaped?|block)?|letter\s+[LUTJ])\b(?![\s-]*(?:shaped?\s+)?(?:wall|fence))"
    r"[^.\n]*$"
)
"""A letter shape named earlier in the sentence ("an L shape with …", "U-shape, …"); not a
letter-shaped wall, whose "4 by 3" would be its length and height."""


_LETTER_SAID = re.compile(r"\b(?:(?-i:[LT])|[lt][\s-]?shaped?)\b", re.I)
"""An L or a T named earlier in the sentence ("the letter L", "T-shaped"): its arms said as ways
or as "4+3" belong to it."""
_WAY = (
    r"(?:(?:going|running|that\s+go(?:es)?|goes|runs|heading)\s+)?(?:along\s+the\s+(?:front|back|left|"
    r"right)(?:\s+(?:side|edge))?|along\s+the\s+(?:long|short)(?:\s+"
    r"(?:side|arm|leg|edge))?|the\s+(?:long|short)\s+(?:side|arm|leg)|up(?:wards?)?|down(?:wards?)?|"
    r"across|along|back(?:wards)?|forwards?|north|south|east|west|sideways|to\s+the\s+(?:left|right))"
)
_ARMS_SAID = re.compile(
    rf"\b(?P<a>{_NUM})\s+(?:cubes?\s+|blocks?\s+)?(?P<wa>{_WAY})\b(?:\s+(?:the|a|this)\s+"
    r"(?:page|sheet|table|top))?\s*,?\s*(?:and|then|,)\s+(?:then\s+)?(?:another\s+)?"
    rf"(?P<b>{_NUM})\s+(?P<more>more\s+)?(?:cubes?\s+|blocks?\s+)?(?P<wb>{_WAY})\b"
    r"(?:\s+(?:the|a|this)\s+(?:page|sheet|table|top))?(?:\s+(?:one|ones|side|arm|leg|edge))?",
    re.I,
)


def _arms_said(m: re.Match[str]) -> str:
    """ "the letter L: 4 cubes going up the page and 2 more going across": an L of arms 4
    and 3 (the 2 was dropped, silently); "a T … 3 across and 2 going down": its bar and stem."""
    letter = _LETTER_SAID.search(_sentence_before(m.string, m.start()))
    ways = r"going|running|goes|runs|heading|go|more|long|short|page|sheet|north|south|east|west"
    plain = not re.search(rf"\b(?:{ways}|back\w*|forwards?|sideways|to)\b", m.group(0), re.I)
    if letter is None or plain or m.group("wa").lower().strip() == m.group("wb").lower().strip():
        return m.group(0)  # "five down and three across": read as it is
    a, b = words_to_numbers([m.group("a").lower(), m.group("b").lower()])
    if letter.group(0).lower().startswith("t"):
        return f"the top bar {a} long and the stem {b}"
    more = 1 if m.group("more") else 0  # "2 more going across": beside the corner cube
    return f"arms of {a} and {int(b) + more}"


def _called(m: re.Match[str]) -> str:
    """ "tower(4)": a tower of 4; "T(bar=5, stem=2)": a T shape, bar 5, stem 2;
    "pyramid(base=4, square=True)": a pyramid, base 4, square (a flag set is its word)."""
    name = f"{m.group(1)} shape" if m.group(1) in ("T", "L", "U") else m.group(1)
    args = [a.strip() for a in m.group(2).split(",") if a.strip()]
    if len(args) == 1 and args[0].isdigit():
        return f"{name} of {args[0]}"
    flags, said = [], []
    keyed = {"base": "base {} wide", "height": "{} high", "h": "{} high", "width": "{} wide",
             "w": "{} wide", "length": "{} long", "l": "{} long",
             "levels": "{} levels"}  # fmt: skip
    for arg in args:
        key, _, value = (w.strip() for w in arg.partition("="))
        if value.lower() in ("true", "yes"):
            flags.append(key)  # "square=True": a square one
        elif value.lower() not in ("false", "no", "none"):
            said.append(keyed.get(key.lower(), key + " {}").format(value) if value else key)
    return ", ".join([" ".join([*flags, name]), *said])


def _sentence_before(text: str, at: int) -> str:
    """The words of the sentence `text` is in at `at`, up to there."""
    return re.split(r"[.;]", text[:at])[-1]


_SIDE_ONE = (
    r"(?:the\s+)?(left|right|front|back|(?:middle|centre|center)(?=\s+(?:one|tower|stack|column|"
    r"wall|row)\b))(?:[\s-]?(?:hand|most))?"
    r"(?:\s+(?:one|tower|stack|column|"
    r"wall|row))?\s+(?:(?:is|should\s+be|must\s+be|will\s+be|needs\s+to\s+be|has\s+to\s+be|"
    r"is\s+to\s+be|has|gets|should\s+have|with)\s+)?"
)
"""'the left one should be', 'right': one of several, named by its side."""
_SIDE_SIZE = rf"{_NUM}\s+(?:cubes?\s+)?(?:high|tall|long|wide|levels?|cubes?)"


_COUNTED_THEN = (
    r"\b((?:two|three|four|[2-4])\s+(?:towers|stacks|columns|pillars|walls|rows|pyramids|blocks)\b"
    r"[^.;]*?)\s*\.\s+"
)
"""Structures counted, then the end of their sentence: "Make two towers." before one that sizes
them one by one (the two sentences are read as one)."""
_SIDE_ITEM = (
    r"(?:the\s+)?(left|middle|centre|center|right)(?:[\s-]?(?:hand|most))?\s+(one|tower|stack|column|"
    r"block|pillar|post)\s+(?:(?:is|should\s+be|must\s+be)\s+)?(" + _SIDE_SIZE + ")"
)
_THREE_SIDES = re.compile(_SIDE_ITEM + r"(?:\s*[,;]?\s*(?:and\s+)?" + _SIDE_ITEM + "){2}", re.I)


def _three_sides(m: re.Match[str]) -> str:
    """ "three towers side by side: the left one 2 high, the middle one 3 high, the right one 1
    high", "middle block 3 high, left block 2 high, right block 1 high": the three from left to
    right (the middle one was the table's middle, or left as said)."""
    items = re.findall(_SIDE_ITEM, m.group(0), re.I)
    side = {w.lower().replace("centre", "middle").replace("center", "middle"): size
            for w, _, size in items}  # fmt: skip
    if sorted(side) != ["left", "middle", "right"]:
        return m.group(0)
    named = {noun.lower() for _, noun, _ in items} - {"one"}
    counted = "three towers " if named else ""  # "middle block 3 high, …": three of them
    return f"{counted}from left to right, {side['left']}, {side['middle']} and {side['right']}"


def _side_one(m: re.Match[str], size: str | None) -> str:
    """ "the left one 5 high": one 5 high on the left (a size with no unit: left as said)."""
    if size is None:
        return m.group(0)
    side = m.group(1).lower()
    if side in ("middle", "centre", "center"):
        if re.search(r"\b(?:next\s+to\s+each\s+other|side\s+by\s+side|touching|together)\b",
                     m.string, re.IGNORECASE):
            return m.group(0)  # the table's middle is not the middle of a group set together
        return f"one {size} in the middle"
    where = "on the " if side in ("left", "right") else "at the "
    of = "of " if re.search(r"\bcubes?$", size, re.I) else ""  # "has 2 cubes": one of 2 cubes
    return f"one {of}{size} {where}{side}"


def _blocks_listed(m: re.Match[str]) -> str:
    """ "three 2x2 blocks, 1, 2 and 3 high": a block of each height, as many as counted."""
    heights = [h for h in m.group(4, 5, 6, 7) if h]
    if words_to_numbers([m.group(1).lower()])[0] != str(len(heights)):
        return m.group(0)
    blocks = [f"a {m.group(2)} by {m.group(3)} block {h} high" for h in heights]
    return ", ".join(blocks[:-1]) + " and " + blocks[-1]


def _walls_listed(m: re.Match[str]) -> str:
    """ "three walls 4 long, heights 1, 2 and 3": a wall of each height, as many as counted, each
    as long as said; as it was when neither 'heights' nor 'high' says what the numbers are."""
    heights = _listed_figures(m.group(5)).replace(" and ", ", ").split(", ")
    if not (m.group(4) or m.group(6)) or words_to_numbers([m.group(1).lower()])[0] != str(
        len(heights)
    ):
        return m.group(0)
    length = re.sub(r"^[\s,]*(?:each\s+)?", " ", m.group(3)) if m.group(3).strip() else ""
    walls = [f"a {m.group(2).lower()[:-1]}{length} {h} high" for h in heights]
    return ", ".join(walls[:-1]) + " and " + walls[-1]


def _object_between_dashes(m: re.Match[str]) -> str:
    """ "Behind the wall - four long, two high - …": the relation, its object described (the
    sizes one list), and a comma before the subject."""
    said = m.group(3)
    if re.match(r"(?:an?|one)\s", said, re.I):
        return f"{m.group(1)}{said}, "
    sizes = re.sub(r"\s*,\s*", " and ", said)
    return f"{m.group(1)}a {m.group(2)} {sizes}, "


def _total_first(m: re.Match[str]) -> str:
    """ "six cubes, two rows of 3": the rows, and the total said after them as a claim (when
    the rows times their length make it); otherwise as it was."""
    total, groups, each = words_to_numbers([m.group(k).lower() for k in (1, 3, 4)])
    if not (total + groups + each).isdigit() or int(total) != int(groups) * int(each):
        return m.group(0)
    return f"{m.group(2)}, {total} cubes in total"


def _more_than_that(m: re.Match[str]) -> str:
    """ "one tower of 2, and one tower of one more than that": the size said before, plus (or
    less) that many; as it was when no size was said before."""
    said = re.findall(r"\bof\s+(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b",
                      m.string[: m.start()], re.I)  # fmt: skip
    if not said:
        return m.group(0)
    values = words_to_numbers([said[-1].lower(), m.group(1).lower()])
    if not all(v.isdigit() for v in values):
        return m.group(0)
    was, by = (int(v) for v in values)
    now = was + by if m.group(2).lower() == "more" else was - by
    return f"of {now}" if now >= 1 else m.group(0)


def _rows_apart(m: re.Match[str]) -> str:
    """ "two rows of six, parallel, …", "two rows of three 10 cm apart": the rows one by one;
    two rows (not walls) said apart stand one behind the other, as rows do."""
    noun = m.group(2)[:-1].lower().replace("line", "row")
    rest = m.string[m.end() :].split(".")[0]
    if noun == "wall" and not re.search(r"\b(?:parallel|between\s+them)\b", rest, re.I):
        return m.group(0)  # "two walls of 4 cubes, 3 high, with a gap of 2": both 3 high
    more = 2 if m.group(1).lower() in ("three", "3") else 1
    said = ", ".join([f"a {noun} of {m.group(3)}"] + [f"another {noun} of {m.group(3)}"] * more)
    in_line = re.search(r"\b(?:parallel|in\s+(?:a\s+)?line|end\s+to\s+end)\b", rest, re.I)
    if more == 1 and noun == "row" and not in_line:
        said += " one behind the other"
    return said


def _sizes_listed(m: re.Match[str]) -> str:
    """ "three towers side by side, 2 high, 3 high and 1 high": one list of sizes, "2, 3 and 1
    high", when structures were counted before it in the sentence (the first size was read as
    every tower's, the others dropped)."""
    counted = re.search(r"\b(?:two|three|four|five|six|[2-9])\s+(?:[a-z-]+\s+){0,2}?(?:"
                        + _FAMILY_SAID + r")s\b", _sentence_before(m.string, m.start()), re.I)
    if counted is None:
        return m.group(0)
    said = re.findall(_NUM, m.group(0), re.I)
    return f"{', '.join(said[:-1])} and {said[-1]} {m.group(2)}"


def _with_unit_before(m: re.Match[str]) -> str | None:
    """ "the left one 5 high, the right one 2": the bare 2 in the unit of the one before."""
    said = re.findall(
        rf"\b{_NUM}\s+((?:cubes?\s+)?(?:high|tall|long|wide|levels?)|cubes?)\b",
        _sentence_before(m.string, m.start()),
        re.I,
    )
    return f"{m.group('bare')} {said[-1]}" if said else None


# "three towers going up by one each starting at two": a series' first height, not a time
_SERIES_BEFORE = re.compile(
    r"\b(?:towers|stacks|columns|pillars|heights|going\s+up|rising|climbing|increasing|growing|"
    r"getting|ascending)\b",
    re.I,
)


# "4 levels - actually 3 is enough": a correction's new value, not a size agreed
_CORRECTING = re.compile(r"\b(?:actually|no|wait|sorry|rather|instead|or)\s*[,.…-]*\s*$", re.I)


def _another_value(m: re.Match[str]) -> bool:
    """The number agreed to ("4 is enough") is none said before it, which one was."""
    said = re.findall(rf"\d+|\b(?:{_NUM})\b", m.group(0), re.I)
    before = re.findall(rf"\d+|\b(?:{_NUM})\b", m.string[: m.start()], re.I)
    values = set(words_to_numbers([w.lower() for w in before]))
    return bool(values) and not set(words_to_numbers([w.lower() for w in said])) <= values


_THE_N_PLACED = re.compile(
    rf"\s*,?\s*(?:with\s+|and\s+)?(?:the\s+({_NUM})(?:[\s-]high|[\s-]tall)?(?:\s+one)?|({_NUM})\s+one)\s+"
    r"(?:is\s+|goes\s+|should\s+be\s+|stands\s+|keep\s+|put\s+|place\s+|set\s+)?((?:on|at|in|to)\s+"
    r"the\s+(?:far\s+)?(?:left|right|front|back)(?:[\s-]hand)?(?:\s+side)?)\b",
    re.IGNORECASE,
)
_UNIT = r"(?:cubes?\s+)?(?:high|tall|long)"


def _placed_by_size(text: str) -> str:
    """ "two towers, 3 and 5 high, the 5 on the left", "one of height two and one of height six,
    with the six in the back": the one of that size placed there (the place went to both,
    silently)."""
    m = _THE_N_PLACED.search(text)
    if m is None:
        return text
    n, where = (m.group(1) or m.group(2)).lower(), m.group(3)
    before, after = _sentence_before(text, m.start()), text[m.end() :]
    sentence = m.start() - len(before)
    ones = [o for o in re.finditer(rf"\bone\s+({_NUM})\s+{_UNIT}", before, re.I)
            if o.group(1).lower() == n]  # fmt: skip
    if len(ones) == 1:
        at = ones[0].end()
        return f"{text[:sentence]}{before[:at]} {where}{before[at:]}{after}"
    pair = re.search(rf"\b(?:of\s+)?({_NUM})\s+and\s+({_NUM})(\s+{_UNIT})?\s*$", before, re.I)
    if pair is None or n not in (pair.group(1).lower(), pair.group(2).lower()):
        return text
    a, b = pair.group(1), pair.group(2)
    unit = pair.group(3)
    one_a, one_b = (f"one {a}{unit}", f"one {b}{unit}") if unit else (f"one of {a}", f"one of {b}")
    said = f"{one_a} {where} and {one_b}" if a.lower() == n else f"{one_a} and {one_b} {where}"
    lead = before[: pair.start()].rstrip()
    return f"{text[:sentence]}{lead}, {said}{after}"


def _of_it(m: re.Match[str]) -> str:
    """ "a 3x3 slab, then a tower at its centre": the slab's middle ("of it"), where nothing
    in the sentence before ("with", "on top of") already relates the two."""
    sentence = _sentence_before(m.string, m.start())
    related = re.search(r"\b(?:with|on\s+top\s+of|around|inside)\b", sentence, re.I)
    return "" if related else "of it "


def _each_side(m: re.Match[str]) -> str:
    """ "20 cm on each side": 20 cm by 20 cm; of a cube or a box, by 20 cm a third time."""
    said = m.group(1) or m.group(2)
    solid = re.search(r"\b(?:cube|box|block)\b[^.;]*$", m.string[: m.start()], re.I)
    return f"{said} by {said} by {said}" if solid else f"{said} by {said}"


def _series_start(m: re.Match[str]) -> bool:
    """ "three towers going up by one each starting at two": not a time of day."""
    started = m.group(1).lower().startswith(("start", "begin"))
    return started and bool(_SERIES_BEFORE.search(_sentence_before(m.string, m.start())))


_PHRASINGS: list[tuple[re.Pattern[str], _Repl]] = [
    *EVERYDAY,  # `everyday`: read first
    # "put one more cube beside it on the table": a cube of its own beside it (the cube was
    # one more level of it, and "it on the table" no structure)
    (re.compile(r"\b(?:one\s+more|an\s+extra|another)\s+(?:single\s+)?(?:cube|block|brick)\b(?=\s+(?:"
                r"beside|next\s+to|by|near|alongside|in\s+front\s+of|behind|to\s+the\s+(?:left|right)\s+"
                r"of)\b)", re.I), "a single cube"),
    (re.compile(r"\b((?:beside|next\s+to|by|near|alongside)\s+(?:it|them))\s+on\s+the\s+(?:table|floor|"
                r"ground|bench)\b", re.I), r"\1"),
    # "a pier 2 bricks square and 3 courses up": 2 by 2, 3 high
    (re.compile(r"\b(\d+|two|three|four|five|six)\s+(?:bricks?|cubes?|blocks?|parts?)\s+square\b",
                re.I), r"\1 by \1"),
    (re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight)\s+(?:courses|layers|levels|tiers)\s+"
                r"(?:up|tall)\b", re.I), r"\1 high"),
    # "two 3x3 layers side by side": two slabs (one 3 by 3 slab was built)
    (re.compile(r"\b((?:two|three|four|[2-4])\s+\d+\s*(?:x|by)\s*\d+\s+)(?:layer|level|tier|course)s\b"
                r"(?=[^.;]*\b(?:side\s+by\s+side|next\s+to\s+each\s+other|beside\s+each\s+other|apart|"
                r"in\s+a\s+(?:row|line))\b)", re.I), r"\1slabs"),
    # "a 1-brick pier": one part across, as a pier is; "four single-cube towers": towers of one
    # cube (built 3 high, silently)
    (re.compile(r"\b(?:1|one|single)[\s-](?:brick|cube|block)[\s-](?:(?:wide|thick)\s+(?=(?:pier|"
                r"column|pillar|post|tower|chimney|stack|wall)s?\b)|(?=(?:pier|chimney|wall)s?\b))",
                re.I), ""),
    (re.compile(r"\b(?:1|one|single)[\s-](?:brick|cube|block)[\s-]((?:column|pillar|post|tower|"
                r"stack)s?)\b", re.I), r"\1 of 1"),
    # warehouse talk: "one stack of five at bay left", "bay right, one stack of three": that
    # side of the table
    (re.compile(r"\b(?:(at|on|in|along)\s+)?bay\s+(left|right)\b", re.I),
     lambda m: f"{m.group(1) or 'on'} the {m.group(2)}"),
    # "one cube of air between them": the gap between them
    (re.compile(r"\b(" + _NUM + r"\s+(?:cubes?|blocks?))\s+of\s+(?:air|daylight|clearance)\b",
                re.I), r"\1 of space"),
    # "correction on the pyramid: base four, not three": the structure and what it should be
    # (the 'on' was a relation to nothing)
    (re.compile(r"^\W*(?:correction|change|update|amendment)\s+(?:on|to|for)\s+(?:the\s+)?(\w+)\s*:",
                re.I), r"a \1:"),
    # "three stacks of two, three and two": the list in figures (it was read as three of 2)
    (re.compile(r"\bof\s+((?:one|two|three|four|five|six|seven|eight|nine)(?:\s*,\s*(?:one|two|three|"
                r"four|five|six|seven|eight|nine))+\s*,?\s*and\s+(?:one|two|three|four|five|six|seven|"
                r"eight|nine))\b(?!\s*(?:x|by)\b)", re.I),
     lambda m: "of " + _listed_figures(m.group(1))),
    # "four by four... he says bigger! Five by five then.": a correction (both were built)
    (re.compile(r"(?:\b(?:he|she|they|the\s+(?:boss|customer|client))\s+(?:says?|wants?)\s+(?:it\s+)?)?"
                r"\b(?:bigger|smaller|taller|shorter|longer|wider|higher|lower)\s*[!.]+\s*(" + _NUM
                + r"(?:\s*(?:x|by)\s*" + _NUM + r")?)\s+then\b", re.I), r"no, \1"),
    # "a wall, and before the wall, a tower of two": in front of it (it stood behind, silently)
    (re.compile(r"\bbefore\s+(?=(?:the\s+(?:wall|tower|row|block|slab|pyramid|staircase|stairs|bridge|"
                r"arch|castle|ring|fence|stack|column)|it)\s*,?\s*(?:an?|one|two|three|put|place|"
                r"build|set|stack)\b)", re.I), "in front of "),
    # "an L shape with arms of 4 and 3, one high": the height is not a third arm (the list took
    # it, and the 3 was dropped)
    (re.compile(r"\b((?:arms?|legs?|sides?|wings?)\s+(?:of\s+)?" + _NUM + r"\s+and\s+" + _NUM
                + r")\s*,\s*(?=" + _NUM + r"\s+(?:cubes?\s+|blocks?\s+|levels?\s+|layers?\s+)?"
                r"(?:high|tall)\b)", re.I), r"\1; "),
    # "the small one at left": on the left (every structure stood at the left, silently)
    (re.compile(r"\b(at|on)\s+(left|right)(?=\s*(?:[,.;!?]|$|side\b))", re.I),
     lambda m: f"on the {m.group(2)}"),
    # "the one nearest the robot, make it 6": the front one (the robot works from the front)
    (re.compile(r"\bthe\s+(one|tower|stack|column|pillar|wall|row)\s+(?:that'?s\s+|which\s+is\s+)?"
                r"(?:(nearest|closest)\s+(?:to\s+)?|(?:furthest|farthest)\s+(?:away\s+)?from\s+)"
                r"(?:the\s+)?robot\b", re.I),
     lambda m: f"the {'front' if m.group(2) else 'back'} {m.group(1)}"),
    # "the bigger one further from the robot": behind the other (it was dropped, silently);
    # "the taller one closer to the robot": in front
    (re.compile(r"\b(the\s+\w+\s+one)\s+(?:(?:is|should\s+be|stands?|goes)\s+)?(?:(further|farther)"
                r"\s+(?:away\s+)?from|(?:closer|nearer)\s+to)\s+(?:the\s+)?robot\b(?!\s+than\b)",
                re.I),
     lambda m: f"{m.group(1)} {'behind' if m.group(2) else 'in front'}"),
    # "steps, 1, 2, 3 and 4 cubes high, going from left to right": they go up that way (they
    # climbed to the left, silently)
    (re.compile(r"\b(going|running|rising)\s+(?=from\s+(?:the\s+)?(?:left|right|front|back)\s+to\s+)",
                re.I),
     lambda m: "going up " if re.search(r"\b(?:stair|step)", m.string[: m.start()], re.I)
     else m.group(0)),
    # "the tall one on the left please: two towers, 2 and 5 high": said after them (the tall
    # one stood on the right, silently)
    (re.compile(r"^\W*(the\s+\w+\s+one\s+(?:on|at|to|in)\s+(?:the\s+)?(?:left|right|front|back))"
                r"(?:\s+please)?\s*:\s*(.+?)\s*$", re.I | re.S), r"\2, \1"),
    # "first a wall …, second a tower …, third a tower of 5 to the right of the second": the
    # order the structures are said in (the 'third' was left unread)
    (re.compile(r"(?:(?<=[,;.:])|(?<=\band))\s*(second|third|fourth|fifth)\s*[,:]?\s+(?=(?:an?|one)\s)",
                re.I), " then "),
    # "a staircase, 3 steps, each step 3 cubes wide": the staircase that wide (the step unread)
    (re.compile(r"\b(?:each|every)\s+(?:step|stair|tread)\s+(?:is\s+|being\s+)?(?=(?:\d+"
                r"(?:\.\d+)?\s*(?:mm|cm|m)|" + _NUM
                + r"(?:\s+(?:cubes?|blocks?))?)\s+(?:wide|across)\b)", re.I),
     ""),
    # "a staircase whose top step is 15 cm up": the staircase that high (the step unread)
    (re.compile(r"\b(?:whose|with\s+(?:its|the|a))\s+(?:top|highest|last|upper)\s+(?:step|stair|"
                r"tread)\s+(?:is\s+|sits\s+|stands\s+)?(?:at\s+)?(?=\d+(?:\.\d+)?\s*(?:mm|cm|m)\s+(?:up|"
                r"high|above|off|from|tall)\b)", re.I), ""),
    # a T "5 across the top and 3 down (the stem)": its bar and stem (the 3 was dropped)
    (re.compile(r"\b(" + _NUM + r")\s+(?:cubes?\s+)?across\s+the\s+top\s*(,|and)?\s*(" + _NUM
                + r")\s+(?:cubes?\s+)?down(?:\s+the\s+(?:stem|middle|centre|center))?\b", re.I),
     lambda m: m.group(0) if not re.search(r"\bT\b|\bt[\s-]shape", m.string, re.I)
     else f"the top bar {m.group(1)} long and the stem {m.group(3)}"),
    # "a stair of five risers": five steps (the risers were read as five slabs, silently)
    (re.compile(r"\b(" + _NUM + r")\s+(?:risers|treads)\b", re.I), r"\1 steps"),
    # "a wall 5 long, and in front of the wall, a tower of 2": the relation said first starts a
    # sentence of its own (the wall was read as a second wall, or as the tower's subject)
    (re.compile(r"[,;]\s*and\s+(?=(?:in\s+front\s+of|behind|to\s+the\s+(?:left|right)\s+of|next\s+to|"
                r"beside|on\s+top\s+of|on\s+(?:either|each)\s+side\s+of)\s+(?:the\s+\w+|it|that(?:\s+one)?)"
                r"\s*,)", re.I), ". "),
    # "negative on the stack of six, make it four": the change, on the structure said before
    (re.compile(r"^\W*negative\s+on\s+(?:the\s+)?([^,.;]+?)\s*,\s*(?=make\s+it\b)", re.I),
     r"a \1. no, "),
    # "three walls 4 long, heights 1, 2 and 3", "… 4 long, 1, 2 and 3 high": a wall of each
    # height, all that long (the heights were read as their lengths, the length dropped, silently)
    (re.compile(r"\b(two|three|four|[2-4])\s+(walls|fences|barriers)\b((?:\s*,?\s*(?:each\s+)?"
                + _NUM + r"\s+(?:cubes?\s+)?long)?)\s*[,:]?\s*(?:(?:with\s+|of\s+)?(heights?)\s*"
                r"(?:of\s+|:\s*)?)?("
                + _NUM + r"(?:\s*,\s*" + _NUM + r")*\s*(?:,\s*|,?\s*and\s+)" + _NUM
                + r")\b(\s+(?:cubes?\s+)?(?:high|tall))?(?!\s*(?:x|by|cm|mm|m|long|wide)\b)", re.I),
     _walls_listed),
    # "three stacks, heights two, three, two": one of each height (3 was read as x = 3 m)
    (re.compile(r"(?<=[a-z]s)\s*,?\s*(?:with\s+)?heights?\s*:?\s+(" + _NUM + r"(?:\s*,\s*" + _NUM
                + r")*\s*(?:,\s*|,?\s*and\s+)" + _NUM + r")\b(?!\s*(?:x|by|cm|mm|m)\b)", re.I),
     lambda m: " of " + _listed_figures(m.group(1))),
    # "a table, four legs, every leg is two cubes": each leg that high (the two was dropped,
    # silently)
    (re.compile(r"\b(?:each|every)\s+(leg|pillar|post|support|column)\s+(?:is\s+|of\s+)?(?=(?:\d+|"
                r"one|two|three|four|five|six)\s+(?:cubes?|blocks?|bricks?)\b(?!\s+(?:high|tall)))",
                re.I),
     r"each \1 has "),
    # "a block, nowhere near the robot": far from it (it stood at the front, silently)
    (re.compile(r"\b(?:nowhere\s+near)\s+"
                r"(?=(?:the\s+)?robot\b)", re.I), "far from "),
    # "climbing toward the far end": the back (it climbed to the left, silently); "ascend
    # toward the rear": the back (read as the table's back region, silently)
    (re.compile(r"\b((?:climb|ris|ascend)\w*|going\s+up|goes\s+up|up)\s+(?:to(?:wards?)?|toward)\s+the\s+"
                r"(?:far\s+(?:end|side|edge)|rear)\b", re.I), r"\1 towards the back"),
    # "a staircase of 4, the high end on the right": it climbs towards the right (it climbed
    # to the left, silently); "the low end on the left": the same way
    (re.compile(r"\b(?:with\s+)?(?:the|its)\s+(high|higher|highest|tall|taller|tallest|top|low|lower|"
                r"lowest|bottom)\s+(?:end|part|side|step)\s+(?:(?:must|should|will|has\s+to)\s+)?"
                r"(?:(?:be|stay|go|sit|stand)\s+)?(?:on|at|to(?:wards?)?)\s+(?:the\s+)?(left|right|back|"
                r"front)(?:\s+side)?\b", re.I),
     lambda m: m.group(0) if not re.search(r"\b(?:stair|step)", m.string[: m.start()], re.I)
     else "going up to the " + (m.group(2) if m.group(1).lower()[:2] in ("hi", "ta", "to")
                                else _OTHER_SIDE[m.group(2).lower()])),
    # a staircase's "direction: up towards the left" (a field): the way it climbs (read as the
    # table's left region, silently)
    (re.compile(r"\b(?:direction\s*[:=]?|(?:climb(?:ing)?|rises?|rising)\s*[:=])\s*(?:(?:going\s+)?up\s+)?(?:(?:to(?:wards?)?|"
                r"toward)\s+)?(?:the\s+)?(left|right|back|front)\b", re.I),
     lambda m: m.group(0) if not re.search(r"\b(?:stair|step)", m.string, re.I)
     else f"going up to the {m.group(1)}"),
    # "a 2x2 base with a 3-cube post rising from one corner of it": standing on that corner
    # (set beside the base, silently)
    (re.compile(r"\b(?:ris(?:es|ing)|grow(?:s|ing)|com(?:es|ing)\s+up|stick(?:s|ing)\s+up|going\s+up)"
                r"\s+(?:from|out\s+of|off)\s+(?=(?:one|a|each|every|all)\s+(?:of\s+(?:its|the)\s+)?"
                r"(?:four\s+)?corners?\b(?!\s+of\s+the\s+(?:table|bench|floor)))", re.I), "on "),
    # "one in each corner of the floor": the table's corners, when no floor was named
    (re.compile(r"\b(each|every|all\s+four|the\s+four)\s+(corners?)\s+of\s+the\s+(?:floor|cell|workspace|"
                r"work\s+area|area)\b", re.I),
     lambda m: m.group(0) if re.search(r"\bfloor", m.string[: m.start()], re.I)
     else f"{m.group(1)} {m.group(2)} of the table"),
    # "a plinth surmounted by a column", "crowned with a cube": topped by it
    (re.compile(r"\b(?:surmounted|crowned|capped)\s+(by|with)\b", re.I), r"topped \1"),
    # "would you mind stacking four cubes at the back": stack them (a row was laid, silently)
    (re.compile(r"(?:^\W*|\b(?:mind|try|start|begin|about)\s+)(stack|pil)ing\s+(?=(?:\d+|a|an|one|"
                r"two|three|four|five|six|seven|eight|nine|ten|some)\b)", re.I),
     lambda m: f"{m.group(1)}{'e' if m.group(1).lower() == 'pil' else ''} "),
    # "two walls 5 long 2 high one behind the other": the one starts the placing (it was read as
    # 'high one', a height of 1)
    (re.compile(r"(?<=\b(?:high|tall|long|wide|deep))\s+(?=one\s+(?:in\s+front\s+of|behind|beside|"
                r"next\s+to|on\s+top\s+of|above|to\s+the\s+(?:left|right)\s+of|after)\s+the\s+"
                r"other\b)", re.I), ", "),
    # "slab 3 by 3. now make it a block by stacking two more layers": the change says how (a
    # 2x2x2 block was built beside the slab)
    (re.compile(r"\b(?:make|turn)\s+(it|them)\s+(?:into\s+)?an?\s+(?:solid\s+)?(?:block|wall|slab|"
                r"platform)\s+by\s+(add|stack|put|pil)(?:ing)\b(?=(?:\s+\w+){1,3}?\s+(?:layers?|levels?|"
                r"rows?|courses?|tiers?)\b)", re.I),
     lambda m: f"{m.group(2)}{'e' if m.group(2).lower() == 'pil' else ''}"),
    # "three towers of two in line": in a line (the line was read as a row of its own)
    (re.compile(r"\bin\s+(?:one\s+|single\s+)?line\b(?!\s+with\b)", re.I), "in a line"),
    # "a bridge with a cube sitting in the middle of the beam": on top of it (the cube was the
    # pillars' height)
    (re.compile(r"\b(?:(?:sitting|standing|resting|placed|set)\s+)?(?:in|on|at)\s+the\s+"
                r"(?:middle|centre|center)\s+of\s+(?:the|its)\s+(?:beam|lintel|deck|roof|span)\b",
                re.I), "on top in the middle"),
    # "two slabs, 50 mm apart along x": x runs away from the robot, one behind the other (the
    # slabs were laid side by side, their own long sides along x)
    (re.compile(r"\bapart\s+(?:along|in|on)\s+(?:the\s+)?([xy])(?:[\s-]*(?:axis|direction))?\b",
                re.I),
     lambda m: "apart, one behind the other" if m.group(1).lower() == "x"
     else "apart, side by side"),
    # "towers 2 3 4 5", "towers: 2, 3, 4 and 5": one of each (the first was the count)
    (re.compile(r"\b(towers|stacks|columns|pillars|piles)\s*:?\s+"
                r"((?:\d+\s*(?:,\s*|\s+and\s+|\s+)){2,}\d+)\b"
                r"(?!\s*(?:x|by|cm|mm|m|cubes?|high|tall|long|wide|levels?|apart|stacked)\b)",
                re.I),
     lambda m: f"{m.group(1)} of " + ", ".join(re.findall(r"\d+", m.group(2)))),
    # "ring 5x5, 2 high, tower 3 inside.": inside the ring named before (it stood beside it)
    (re.compile(r"\b(inside|within)(?=\s*(?:[.;!?]|$))", re.I),
     lambda m: f"{m.group(1)} it" if _ENCLOSING.search(m.string[: m.start()])
     and not _EMPTY_INSIDE.search(m.string[: m.start()]) else m.group(0)),
    # "3 towers of 2. make the middle tower 5": the middle one (a fourth tower in the middle)
    (re.compile(r"\b(make|raise|lower|change)\s+the\s+(middle|centre|center)\s+"
                r"(?:tower|stack|column|pillar|pile)\b", re.I), r"\1 the \2 one"),
    # "… one of five and one of two with the small one in front": in front of the other (both
    # stood in the front region)
    (re.compile(r"\b(?:with\s+)?the\s+((?:small|big|short|tall|low|high|large|little)(?:er)?)\s+one\s+"
                r"(in\s+front|behind|(?:on|to)\s+the\s+(?:left|right))(?=\s*(?:[.,;!?]|$))", re.I),
     lambda m: f"the {m.group(1)} one {m.group(2)}"
     + (" the other" if m.group(2).lower() == "behind" else " of the other")),
    # "a tower in line with the wall": beside it (the line was a row of its own, silently)
    # (not "in a line with two cubes between")
    (re.compile(r"\bin\s+(?:a\s+)?line\s+with\b(?!\s+(?:an?\s+|" + _NUM + r"[\s-]+)(?:cubes?|cm|mm|"
                r"gaps?|spaces?)\b)", re.I), "next to"),
    # a contract's "four (4)": the figure repeats the word (first, so every
    # rule sees one number); one that disagrees is kept
    (re.compile(r"\b([a-z]+)\s*\(\s*(\d+)\s*\)", re.I),
     lambda m: m.group(1) if _DIGITS.get(m.group(1).lower(), -1) == int(m.group(2))
     else m.group(0)),
    # "make its height 5", "set the tower's height to 6": a change of that dimension of it
    (re.compile(r"\b(make|set|change|bring)\s+(?:its|their|the\s+[a-z]+'s)\s+(height|length)\s+"
                r"(?:to\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b(?!\s*(?:mm|cm|m)\b)",
                re.I),
     lambda m: f"make it {m.group(3)} {'high' if m.group(2).lower() == 'height' else 'long'}"),
    # "a tower of 3, a tower of 2 left of it, and a tower of 1 left of that": a chain, each
    # one beside the one before — a clause each
    (re.compile(r",\s*and\s+(?=[^.;]*?\b(?:of|beside|behind|on|against)\s+(?:that|this)(?:\s+one)?\b)",
                re.I),
     lambda m: "; and " if re.search(r"\b(?:of|beside|behind|on|against)\s+it\b[^.;]*$",
                                     m.string[: m.start()], re.I) else m.group(0)),
    # "Put the tower next to the wall. The tower is 4 high, the wall is 3 long.": a sentence
    # about each of the structures named, one by one
    (re.compile(r"(^|[.;!?]\s*)(the\s+(?:" + _FAMILY_SAID + r")\s+(?:is|are|should|must|has|needs|"
                r"wants|will|to\s+be)\b[^.;!?]*)", re.I),
     lambda m: m.group(1) + _EACH_DESCRIBED.sub(". ", m.group(2))),
    # "twenty centimetres to its right", "one hundred and fifty millimetres": the figure
    (re.compile(r"\b((?:(?:twenty|thirty|forty|fifty|sixty|seventy|eighty|ninety|hundred|eleven|twelve|"
                r"thirteen|fourteen|fifteen|sixteen|seventeen|eighteen|nineteen|ten|one|two|three|four|"
                r"five|six|seven|eight|nine|and)[\s-]+)+)(centimet(?:re|er)s?|millimet(?:re|er)s?|"
                r"met(?:re|er)s?)\b", re.I),
     lambda m: (f"{n} {_SYMBOL[lx.UNITS_M[m.group(2).lower()]]}" if (n := _words_figure(m.group(1)))
                else m.group(0))),
    # "with no gap between them", "side by side with no space": touching (the "no" was
    # ignored and SDI's own gap set)
    (re.compile(r",?\s*\b(?:with\s+|and\s+|leaving\s+)?(?:no|without\s+(?:a|any))\s+(?:gap|space)s?\s+"
                r"(?:in\s+)?between(?:\s+(?:them|the\s+two|each\s+other|the\s+\w+s))?\b", re.I),
     ", touching"),
    (re.compile(r"\b(side\s+by\s+side|next\s+to\s+each\s+other)\s*,?\s*(?:with\s+)?(?:no|without\s+(?:a|any))"
                r"\s+(?:gap|space)s?\b", re.I), r"\1, touching"),
    # "a wall, 40 cm along the x axis": that long along x (it was read as the place x = 0.40 m)
    (re.compile(r"\b(\d+(?:\.\d+)?\s*(?:mm|cm|m)|\d+\s+cubes?)\s+(?:long\s+)?along\s+(?:the\s+)?([xy])"
                r"(?:[\s-]*axis)?\b(?!\s*=|\s+from\b|\s+(?:and|,)\s+\d)", re.I),
     lambda m: m.group(0) if _PLACED_AT.search(m.string[: m.start()])
     or not re.search(r"\b(?:wall|walls|row|rows|line|fence|bar)\b", m.string, re.I)
     else f"{m.group(1)} long along {m.group(2)}"),
    # "at 35 cm in x and 45 cm in y": the coordinates (the figures were a height)
    (re.compile(r"\b(\d+(?:\.\d+)?)\s*(mm|cm|m)\s+(?:in|along|on)\s+(?:the\s+)?([xy])"
                r"(?:[\s-]+axis)?\b(?!\s*=)", re.I),
     lambda m: m.group(0) if MOVED.search(m.string[: m.start()])
     else f"{m.group(3)} = {m.group(1)} {m.group(2)}"),
    # "a tower in a corner": a corner of the table (an L shape was built beside it)
    (re.compile(r"\b(in|into)\s+(?:a|any|one)\s+(?=(?:(?:far|back|front|near|rear)\s+)?corner\b"
                r"(?!\s+of\b))", re.I), r"\1 the "),
    # "climbing towards the robot": to the front; "going down towards the back": it climbs to
    # the front (it was moved to the back, climbing there)
    (re.compile(r"\b(climb\w*|ris(?:e|es|ing)|ascend\w*|(?:going|goes|go|stepping|steps)\s+up)\s+"
                r"(towards?|to)\s+(?:the\s+)?robot\b", re.I), r"\1 \2 the front"),
    (re.compile(r"\b(?:(?:going|goes|stepping|steps|running|runs|sloping|slopes)\s+down|"
                r"descend(?:s|ing)?|fall(?:s|ing))\s+(?:towards?|to)\s+(?:the\s+)?(front|back|rear|left|"
                r"right|robot)\b", re.I),
     lambda m: "climbing towards the " + {"front": "back", "robot": "back", "back": "front",
                                          "rear": "front", "left": "right",
                                          "right": "left"}[m.group(1).lower()]),
    # "put the tall one at the back", "the big one on the right": the tallest (or the
    # taller) of those named, not a structure one cube high
    # ("the small at the right": the noun left unsaid)
    (re.compile(r"\bthe\s+(tall|high|big|large|long|short|low|small|little)\s+(?:(one|tower|stack|column)\b|"
                r"(?=(?:at|on|in)\s+the\s+(?:left|right|front|back)\b))"
                r"(?=\s*(?:,\s*)?(?:goes\s+|is\s+|stands\s+|should\s+(?:be|go|stand)\s+|must\s+(?:be|go)\s+)?"
                r"(?:(?:in|on|at|to)\s+the|behind)\b)", re.I),
     lambda m: "the " + _SUPERLATIVE[m.group(1).lower()] + " " + (m.group(2) or "one ")
     if _FAMILY_BEFORE.search(m.string[: m.start()]) else m.group(0)),
    # "then remove the tall one": the tallest named (it was read as a pointer, nothing removed)
    (re.compile(r"\b(remove|take\s+(?:away|out|down)|knock\s+(?:down|over)|get\s+rid\s+of|drop|"
                r"delete)\s+the\s+(tall|high|big|large|short|low|small|little)\s+(one|tower|stack|"
                r"column)\b", re.I),
     lambda m: f"{m.group(1)} the " + _SUPERLATIVE[m.group(2).lower()] + f" {m.group(3)}"),
    # "go ahead and stack 5 cubes": the build
    (re.compile(r"(^\s*|[.;:!]\s*)(?:go\s+ahead\s+and|just\s+go\s+and)\s+", re.I), r"\1"),
    # "a gap in between", "gap of 2 between each", "5 cm between": the gap said, and "between"
    # with it (it was left over, and the reading partial)
    (re.compile(r"(?<!\bof\s)\b(gaps?|space|spacing)((?:\s+of\s+\S+(?:\s+(?:cubes?|cm|mm|m))?)?)\s+"
                r"(?:in\s+)?between"
                r"(?:\s+(?:each(?:\s+(?:one|other|of\s+them))?|them(?:\s+all)?|the\s+two|both|positions))?"
                r"(?=\s*(?:$|[,.;!]))", re.I), r"\1\2"),
    (re.compile(r"\b(\d+(?:\.\d+)?\s*(?:mm|cm|m|cubes?))\s+(?:in\s+)?between(?:\s+(?:each(?:\s+(?:one|"
                r"other|of\s+them))?|them(?:\s+all)?|the\s+two|both))?(?=\s*(?:$|[,.;!]))", re.I),
     r"\1 apart"),
    # a bricklayer's words: "a stretcher course of seven" is a row of 7, "single skin" one
    # brick thick ("course" alone stays a level: "3 courses high")
    (re.compile(r"\b(?:(?:stretcher|header|brick|soldier)\s+)?course\s+of\s+(?=(?:\d+|one|two|three|four|"
                r"five|six|seven|eight|nine|ten|eleven|twelve)\b)", re.I), "row of "),
    (re.compile(r"\b(?:double|two)[- ]skin\b(?![^.;]*\b(?:\d+|one|two|three)\s+(?:thick|deep|wide"
                r")\b)",
                re.I), "two thick"),
    (re.compile(r"\b(?:single|double|two)[- ]skin\b", re.I), " "),  # one brick thick, as built
    # "… on top, straight up -- no offset": stacked square, as SDI stacks
    (re.compile(r"\s*[,;]?\s*(?:[-\u2013\u2014]+\s*)?(?:with\s+)?(?:no|zero|without(?:\s+any)?)\s+"
                r"(?:offset|overhang|stagger)\b", re.I), " "),
    # "a lintel across the tops of them": across them
    (re.compile(r"\b(across|over|spanning)\s+(?:the\s+tops(?:\s+of\s+(?:them|both|the\s+two(?:\s+\w+)?|"
                r"the\s+(?:posts|towers|pillars|columns|legs|stacks)))?|the\s+top\s+of\s+(?:them|both|"
                r"the\s+two(?:\s+\w+)?)|their\s+tops|both\s+tops)\b", re.I), r"\1 them"),
    # "a panel, flat on the bench: two by five": a panel said flat lies on the table (it stood up)
    (re.compile(r"\b(?:panel|board|sheet)(s?)\b(?=[^.;:]*?(?::[^.;]*)?\b(?:flat|lying\s+down|"
                r"laid\s+down)\b(?!\s+(?:roof|top)))|\b(?<=flat\s)(?:panel|board|sheet)(s?)\b",
                re.I),
     r"slab\1\2"),
    # "flat on the floor", "on the ground", "on the bench": on the table (the floor was a grid)
    (re.compile(r"\b(on|onto)\s+the\s+(?:floor|ground|bench|workbench|mat|carpet|work\s+surface|counter|worktop|countertop)\b"
                r"(?!\s+(?:of|plan|(?:next\s+to|beside|by|near|in\s+front\s+of|behind)\s+the\s+(?:table|bench)))",
                re.I), r"\1 the table"),
    # "one of those Egyptian pyramids": one pyramid (a pyramid of 1 was built, and a grid)
    (re.compile(r"\bone\s+of\s+(?:those|these)\s+((?:[a-z-]+\s+){0,2}?)([a-z]+s)\b", re.I),
     lambda m: next((f"a {m.group(1)}{w}" for w in (m.group(2)[:-1], m.group(2)[:-2])
                     if w.lower() in lx.SHAPE_WORDS), m.group(0))),
    # "a pyramid, a proper square one, five wide": the same pyramid, square (a grid was built)
    (re.compile(r"\b(an?\s+)((?:[a-z-]+\s+){0,2}?)([a-z]+)\s*,\s*an?\s+(?:(?:proper|real|nice|good|"
                r"classic|true|properly)\s+)?(square|solid|hollow|3-?d|2-?d|flat)\s+one\s*(?=,)",
                re.I),
     lambda m: f"{m.group(1)}{m.group(2)}{m.group(4)} {m.group(3)}"
     if m.group(3).lower() in lx.SHAPE_WORDS else m.group(0)),
    # "a row of five, like soldiers standing in a line": a likeness of the row, not a second one
    (re.compile(r"\s*,?\s*\b(?:just\s+)?like\s+(?:\w+\s+){0,2}?\w+s\s+(?:standing|lined\s+up|waiting|"
                r"marching|sitting|all)\s+in\s+an?\s+(?:straight\s+)?(?:line|row|queue)\b", re.I),
     " "),
    # "3 stacks in a line going front to back": the line's way
    (re.compile(r"\b(in\s+an?\s+(?:straight\s+)?(?:line|row))\s+(?:going|running|heading|laid\s+out)\s+"
                r"(?=(?:from\s+)?(?:the\s+)?(?:front|back|left|right)\s+to\b)", re.I), r"\1 "),
    # "five long and a couple high": two high (read as a count of two parts, dropped)
    (re.compile(r"\ba\s+couple\s+(?:of\s+)?(?=(?:cubes?\s+|blocks?\s+|bricks?\s+)?(?:high|tall|long|wide|"
                r"deep)\b)", re.I), "2 "),
    # "a square, 3 blocks on each side": 3 by 3 (walls were put on its sides)
    (re.compile(r"\b(square|ring|enclosure|fence|pen|frame|border)\s*,?\s*(?:with\s+)?("
                + _NUM + r")\s+"
                r"(?:cubes?\s+|blocks?\s+|bricks?\s+|parts?\s+)?(?:on|along|per|to|for)\s+(?:each|every|a)\s+"
                r"side\b", re.I), r"\1 \2 by \2"),
    # "a ring around an empty 3x3 centre": the ring round that space, 5 by 5 (a space not said
    # empty may be the ring's own size: left as it was)
    (re.compile(r"\b(ring|fence|wall|border|barrier|enclosure)\b((?:\s+of\s+\w+)?)\s+(?:(?:all\s+)?"
                r"(?:a)?round|surrounding|enclosing)\s+an?\s+(?:empty|open|clear|free)\s+(\d+)\s*(?:x|by)\s*"
                r"(\d+)\s+(?:(?:floor|empty|open)\s+)?(?:centre|center|space|area|hole|middle|gap|"
                r"courtyard)\b", re.I),
     lambda m: f"{m.group(1)}{m.group(2)} {int(m.group(3)) + 2} by {int(m.group(4)) + 2}"),
    # "Materials: 5 cm cubes.": the parts SDI has
    (re.compile(r"(^|[.;!?\n]\s*)(?:materials?|parts?|using|stock)\s*:\s*(?:5\s*cm|50\s*mm)\s+"
                r"(?:cubes?|blocks?)\s*(?:[.;!?]|$)\s*", re.I), r"\1"),
    # "ring / fence thing": two words for one structure, the first named
    (re.compile(r"\b([a-z]+)\s*/\s*([a-z]+)\b(?:\s+(?:thing|thingy|type|kind|sort))?", re.I),
     lambda m: m.group(1) if (m.group(1).lower() in lx.SHAPE_WORDS
                              and m.group(2).lower() in lx.SHAPE_WORDS
                              and m.group(1).lower() not in lx.AMBIGUOUS_SHAPES) else m.group(0)),
    # "each arm two blocks out from the middle", "arm length 2 from the centre cube": arms of 2
    # (the 2 was read as a gap)
    (re.compile(r"\b(?:(?:each|every)\s+arm\s+(?:is\s+)?|arms?\s+length\s+(?:of\s+)?)("
                + _NUM + r")"
                r"(?:\s+(?:cubes?|blocks?|bricks?))?(?:\s+long)?(?:\s+out)?\s+(?:from|off)\s+the\s+"
                r"(?:centre|center|middle)(?:\s+(?:cube|block|one))?\b", re.I), r"arms of \1"),
    # "a plus sign — a cross — 1 block in the middle and 1 on each side": arms of 1; "Put one
    # cube in the middle and 1 cube on each side of it." (a cross one cube long, silently)
    (re.compile(r"\b(?:(?:put|place|add|lay|set)\s+)?(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+)?"
                r"in\s+the\s+(?:middle|centre|center)\s*,?\s*"
                r"(?:and|with|plus)\s+(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+)?(?:on|to|off)\s+"
                r"(?:each|every|all\s+four|all)\s+sides?\b(?:\s+of\s+(?:it|that|the\s+middle(?:\s+"
                r"(?:one|cube|block))?))?", re.I),
     lambda m: f"arms of {m.group(2)}"
     if re.search(r"\b(?:cross|plus)\b", m.string[: m.start()], re.I)
     and m.group(1).lower() in ("1", "one") else m.group(0)),
    # a CAD user's height: "extrude 1", "4 units in +Z", "boss-extrude a 2x3 footprint, depth 2"
    (re.compile(r"\bextrude[sd]?\s+(?:it\s+|by\s+)?(" + _NUM + r")(?:\s+(?:units?|cubes?|blocks?|"
                r"layers?))?(?:\s+(?:in|along)\s+\+?z)?\b", re.I), r"\1 high"),
    (re.compile(r"\b(" + _NUM + r")\s+(?:units?|cubes?|blocks?|levels?)\s+(?:in|along|up\s+in)\s+"
                r"(?:the\s+)?\+?z(?:[\s-]+(?:axis|direction))?\b", re.I), r"\1 high"),
    (re.compile(r"(\bextrude[^.;]*?)\b(?:depth|distance)\s+(?:of\s+)?(" + _NUM + r")(?:\s+units?)"
                                                                                 r"?\b",
                re.I), r"\1 \2 high"),
    # "T profile: flange 5 cubes, web 3 cubes": a T, its bar and its stem
    (re.compile(r"\b([ltu])[\s-]+(?:profile|section|beam)\b", re.I), r"\1 shape"),
    (re.compile(r"\b(t[\s-]+shape\b[^.;]*?)\bflange\s+(?:of\s+)?(?=" + _NUM + r"\b)", re.I),
     r"\1bar of "),
    (re.compile(r"\b(t[\s-]+shape\b[^.;]*?)\bweb\s+(?:of\s+)?(?=" + _NUM + r"\b)", re.I),
     r"\1stem of "),
    # "Fancy a pyramid? Square base of three": an offer, then what it is (two were built)
    (re.compile(r"\b((?:fancy|how\s+about|what\s+about|ready\s+for|up\s+for|shall\s+we\s+(?:do|build|"
                r"make|try))\s+(?:a|an|some|one)\s+(?:[a-z-]+\s+){0,2}?[a-z]+)\s*\?\s*(?=[A-Za-z0-9])",
                re.I), r"\1, "),
    # "I want a castle. Make a small one.": that one, small (the "one" was its size)
    (re.compile(r"\s*[.!?]\s*(?:now\s+|please\s+|just\s+)?(?:make|build|do|give\s+me|let'?s\s+(?:make|"
                r"build|do)|i'?d\s+like)\s+(?:me\s+|us\s+)?an?\s+((?:small|little|big|large|tall|short|low|"
                r"wide|long|tiny|huge|bigger|smaller|taller|shorter)\s+)one\b", re.I),
     r", a \1one"),
    # "a pyramid — 3 at the bottom, then 2, then 1, in a single line": a flat pyramid
    (re.compile(r"(\bpyramid\b[^.;?]*?)\s*,?\s*\bin\s+an?\s+(?:single|flat|straight)\s+(?:line|row)\b",
                re.I), r"\1, flat"),
    # "a table — four legs, each 2 high, and a top": the table's own legs
    (re.compile(r"\b(table|canopy|pavilion|shelter|gazebo)\s*(?:[\u2014\u2013]|\s-+)\s*(?=(?:four|4|"
                r"three|3|two|2|six|6)\s+legs\b)", re.I), r"\1 with "),
    # "a 3x3 footprint two high, solid, in the corner": solid, as built (a second block)
    (re.compile(r"(\b(?:footprint|block|slab|layer|lump|cuboid|box|grid|square)\b[^.;!?]*?)\s*,\s*(?:and\s+)?"
                r"(?:completely\s+|fully\s+|all\s+)?solid\s*(?=[,.;!?]|$)", re.I), r"\1 "),
    # "stack a 2 by 2 tower, 4 levels high": the tower, stacked (a slab and a tower were built)
    (re.compile(r"\bstack\s+(?=(?:a|an|one)\s+\d+\s*(?:x|by)\s*\d+(?:\s*(?:x|by)\s*\d+)?\s+(?:tower|column|stack|"
                r"pillar|block)\b)", re.I), "build "),
    # "Frame me a box", "knock me up a wall": a way to say build
    (re.compile(r"\b(?:frame|knock|rustle|whip|throw|fix)\s+(?:me|us)\s+(?:up\s+)?(?=an?\s)", re.I),
     "build me "),
    # "joined at their tops by a beam": joined by it (the beam was left unused)
    (re.compile(r"\b(joined|connected|linked|bridged|spanned)\s+(?:at|across)\s+(?:their|the)\s+tops?\s+"
                r"(by|with)\b", re.I), r"\1 \2"),
    # "a crossbar on top", "a spanning member", "one long piece across the top": a beam
    (re.compile(r"\b(?:cross[\s-]?bar|(?:long|horizontal|spanning|flat)\s+(?:piece|member|part|bar)|spanning\s+"
                r"(?:beam|element))(s?)\b(?=[^.;]*\b(?:across|over|on\s+top|atop|between|connect|join|from))",
                re.I), r"beam\1"),
    (re.compile(r"\b((?:by|with)\s+(?:a|one|an)\s+)(?:cross[\s-]?bar|(?:long|horizontal|spanning|flat)\s+(?:piece|"
                r"member|part|bar)|spanning\s+(?:beam|element))\b", re.I), r"\1beam"),
    # "an L-form: one leg 5 cubes, the other leg 3 cubes": arms of 5 and 3 (two towers)
    (re.compile(r"\bone\s+(?:leg|arm|side)\s+(?:of\s+|is\s+)?(" + _NUM
                + r")(?:\s+(?:cubes?|blocks?))?"
                r"(?:\s+long)?\s*,?\s*(?:and\s+)?the\s+other\s+(?:leg|arm|side)?\s*(?:of\s+|is\s+)?("
                + _NUM + r")(?:\s+(?:cubes?|blocks?))?(?:\s+long)?", re.I),
     lambda m: f"arms of {m.group(1)} and {m.group(2)}"
     if re.search(r"\bl\b|l[\s-]shape|l[\s-]form", m.string[: m.start()], re.I) else m.group(0)),
    # "a T, like the letter, 5 across and 3 down": its bar and its stem
    (re.compile(r"(\bt\b[^.;]*?)\b(" + _NUM + r")\s+(?:cubes?\s+)?across\s*,?\s*(?:and\s+)?("
                + _NUM + r")\s+(?:cubes?\s+)?down\b", re.I), r"\1bar of \2 and a stem of \3"),
    # a carpenter's "header" laid across posts is a lintel
    (re.compile(r"\bheader(s?)(?=\s+(?:beam\s+|board\s+)?(?:across|over|on\s+top|atop|spanning|between|"
                r"from)\b)", re.I), r"lintel\1"),
    # radio procedure: "Robot, this is Base.", "Base to Robot.", "… Over.", "Break.", "I say
    # again": who calls whom and when the message ends ("Base" was a platform)
    (re.compile(r"(^|[.;!?\n]\s*)(?:(?:robot|sdi|cell)\s*,\s*(?:this\s+is\s+)?base|base\s+(?:to|calling)\s+"
                r"(?:robot|sdi|cell)|(?:robot|sdi|cell)\s+(?:from|this\s+is)\s+base|this\s+is\s+base)\s*"
                r"[.,:;!]+\s*", re.I), r"\1"),
    (re.compile(r"(?:[.;!]|(?<=[a-z]),)\s*(?:over(?:\s+and\s+out)?|out|roger)\s*[.!]?\s*$", re.I),
     "."),
    (re.compile(r"(^|[.;!?]\s*)break\s*[.,:;!]+\s*", re.I), r"\1"),
    (re.compile(r"(^|[.;!?]\s*)i\s+say\s+again\s*[.,:;!]+[^.;!?]*[.;!?]?\s*", re.I),
     r"\1"),  # a repeat
    (re.compile(r"\s*,\s*over\s*[.,]\s*(?=\w)", re.I), ". "),
    # "Goal: a wall …", "Exercise 15 — …", "this time": a label or a framing, not the build
    (re.compile(r"(^|[.;!?\n]\s*)(?:goal|objective|aim|task|deliverable)\s*:\s*", re.I), r"\1"),
    (re.compile(r"(^|[.;!?\n]\s*)(?:(?:the\s+)?same\s+as\s+(?:before|last\s+time|yesterday|the\s+last\s+"
                r"(?:one|run|job|time))|as\s+before)\s*[,:;\-\u2013\u2014]+\s*", re.I), r"\1"),
    # "Previous bridge had 2-high legs; raise the legs to 3": that bridge, then changed
    (re.compile(r"(^|[.;!?\n]\s*)(?:the\s+)?(?:previous|last|earlier|old)\s+(tower|stack|column|row|wall|block|"
                r"slab|grid|layer|pyramid|staircase|bridge|arch|ring|enclosure|table|castle|cross)\s+(?:had|has|"
                r"used)\s+(?=\w)", re.I), r"\1a \2 with "),
    # "last run … at the front; this time put the same tower at the back": that one, moved
    (re.compile(r"\bthis\s+time\s*,?\s*((?:just\s+)?(?:move|put|place|build|set|make)\s+)the\s+same\s+"
                r"(?:one|tower|stack|column|pillar|row|wall|block|slab|grid|layer|pyramid|staircase|bridge|"
                r"arch|ring|enclosure|table|castle|cross)\b(?=\s*,?\s*(?:but\s+)?(?:to|towards|at|on|in)\s)",
                re.I), r"\1it"),
    (re.compile(r"\bthis\s+time\b", re.I), " "),
    (re.compile(r"(\d\s*(?:mm|cm|m)?)\s+in\s+plan\b", re.I), r"\1"),
    # "a gate made of two 4-cube posts and a lintel": the posts are its own
    (re.compile(r"\b(?:made|built|consisting|formed)\s+(?:up\s+)?(?:of|from)\s+(?=(?:two|2|four|4)\s+(?:\S+\s+)?"
                r"(?:posts|pillars|legs|columns|uprights|supports)\b)", re.I), "with "),
    # "put one more cube on each end of it": a cube on each end, not a longer row
    (re.compile(r"\b(?:one|a)\s+more\s+(cube|block|brick)\s+(?=on\s+(?:each|both|either)\s+ends?\b)",
                re.I), r"a \1 "),
    # a stutter of small words ("on top of the cube at the at the left end"): said once
    (re.compile(r"\b((?:(?:at|on|in|of|the|a|an|to|and|with|by|from)\s+){1,3})\1", re.I), r"\1"),
    # "a wall 4 length, 2 height": the figure before its dimension's noun
    (re.compile(r"(?<!\bover\s)(?<!\bthan\s)\b(\d+(?:\.\d+)?(?:\s*(?:mm|cm|m))?|one|two|three|four|"
                r"five|six|seven|eight|nine|ten)\s+(length|height|width|depth)\b(?!\s+of\b)"
                r"(?!\s+(?:\d|one|two|three|four|five|six|seven|eight|nine|ten)\b)", re.I),
     r"\2 \1"),
    # "4 cubes high, two towers, one on the left and one on the right": a size said first, for
    # the structures counted after it
    (re.compile(r"(^|[.;:]\s*)(?:of\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+"
                r"(?:cubes?\s+|blocks?\s+)?(?:of\s+|in\s+)?(high|tall|height|long|length)\s*,\s*"
                r"((?:\d+|two|three|four|five|six|both)\s+(?:the\s+)?(?!(?:cube|block|brick|part|piece|"
                r"level|layer|step|course)s\b)[a-z]+s)\b", re.I),
     lambda m: f"{m.group(1)}{m.group(4)} {m.group(2)} "
     f"{'high' if m.group(3).lower() in ('high', 'tall', 'height') else 'long'}"),
    # "make a ring of 4 by 4 and put a cube inside" / "… in the middle": inside the ring (the
    # middle of the table, or nothing, was read, with the ring moved aside)
    (re.compile(r"\b((?:ring|enclosure|pen|corral|fence|square\s+frame|hollow\s+square|courtyard)"
                r"\b[^.;]*?(?:,\s*|\band\s+|\bthen\s+)(?:then\s+)?(?:put|place|stand|set|add|stack)"
                r"\s+[^.;,]*?)\s+(?:(?:right\s+)?inside|in\s+the\s+(?:middle|centre|center))\b"
                r"(?!\s+(?:of|it|them|the)\b)", re.I),
     r"\1 in the middle of it"),
    # "a ring five cubes by five", "5 cubes by 3": a footprint, not a count of cubes
    (re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?|blocks?|"
                r"bricks?)\s+(by|x)\s+(?=\d|one\b|two\b|three\b|four\b|five\b|six\b|seven\b|"
                r"eight\b|nine\b|ten\b)", re.I),
     lambda m: m.group(0) if re.search(r"\b(?:wall|walls|bay|fence)\W+(?:\w+\W+){0,2}$",
                                       m.string[: m.start()], re.I)
     or re.match(r"\d+(?:\.\d+)?\s*(?:mm|cm|m|millimet|centimet|met|inch)", m.string[m.end() :],
                 re.I)
     else f"{m.group(1)} {m.group(2)} "),  # a wall's "A by B" is its length by height; "3 cubes
    # by 20 cm" says which is in parts
    # "place one cube at x=0.5, … and another at …": a cube, a structure of its own (it was
    # read as the part count of the one after it, and its place dropped)
    (re.compile(r"(^|\b(?:place|put|set|stand|add|and|then|with)\s+)one\s+"
                r"(?=(?:single\s+)?(?:cube|block|brick)\b(?!\s+(?:high|tall|long|wide|thick|deep|"
                r"apart|gap|away|from|of|each))(?=[^;]*\banother\b))", re.I), r"\1a "),
    # "two towers of 3 either side of it": one on each side
    (re.compile(r"(?<!\bon\s)(?<!\bat\s)(?<!\bto\s)\beither\s+side\s+of\b", re.I),
     "on either side of"),
    # "tower can touch the wall, that's fine": touching allowed (a third structure was read)
    (re.compile(r"\s*,?\s*\b(?:the\s+)?(?:tower|it|they|stack|column|row|wall)\s+(?:can|may|is\s+allowed\s+to|"
                r"are\s+allowed\s+to)\s+touch\s+(?:the\s+\w+|it|each\s+other|them)"
                r"(?:[,\s]+(?:that'?s|that\s+is|is)\s+(?:fine|ok|okay|alright|allowed))?", re.I),
     " , touching is fine "),
    # "a tower of 3 behind the pyramid, pyramid 3 levels": the pyramid named, described
    (re.compile(r"(\bthe\s+(" + shape_alternation() + r")\b[^.;]*?,\s*)(\2)\s+(?=(?:is\s+|at\s+)?"
                r"(?:\d|one\b|two\b|three\b|four\b|five\b|six\b|seven\b|eight\b|nine\b|ten\b))",
                re.I), r"\1the \3 "),
    # "lay a beam across their tops", "beam on top across both": across them
    (re.compile(r"\bacross\s+(?:their\s+tops?|the\s+tops)\b(?!\s+of\b)", re.I), "across them"),
    (re.compile(r"\bon\s+top\s+(?=across\s+(?:both|them|the\s+two)\b)", re.I), ""),
    (re.compile(r"\s*,\s*(?=(?:a|one)\s+(?:beam|plank|lintel)\s+(?:across|over)\s+(?:them|both|the\s+two)\b)",
                re.I), " and "),
    # "a column … as a monument", "a wall for our castle": what it is for, not another structure
    (re.compile(r"\s*,?\s*\bas\s+an?\s+(?:little\s+|small\s+)?(?:monument|landmark|memorial|marker|"
                r"centrepiece|centerpiece|feature|decoration|ornament|statue)\b", re.I), " "),
    (re.compile(r"(\b(?:tower|wall|row|stack|column|fence|gate|bridge|slab)s?\b[^.;]*?)\s+for\s+"
                r"(?:our|my|your|his|her|their|the)\s+(?:\w+\s+)?(?:castle|fort|house|town|village|"
                r"railway|train\s+set|model)\b", re.I), r"\1"),
    # "a tower of 2 in the front and back", "… on the left and on the right": one in each
    (re.compile(r"\b((?:an?|one)\s+(?:[\w-]+\s+){0,3}?(?:tower|stack|column|pillar|wall|row|block|slab|"
                r"pyramid|staircase|cube)(?:\s+of\s+(?:\d+|one|two|three|four|five|six)(?:\s+cubes?)?)?"
                r"(?:\s+(?:\d+|one|two|three|four|five|six)\s+(?:cubes?\s+)?(?:high|tall|long))?)"
                r"\s+(?:in|at|on)\s+the\s+(front|back|left|right)\s+and\s+(?:(?:in|at|on)\s+)?(?:the\s+)?"
                r"(front|back|left|right)\b(?!\s+(?:corner|of|side\s+of|end|edge|half|left|right)\b)",
                re.I),
     r"\1 at the \2 and \1 at the \3"),
    # "a wall as long as a row of 6": 6 long (a row of 6 was built too)
    (re.compile(r"\bas\s+(long|tall|high)\s+as\s+an?\s+(?:row|tower|stack|column|line|wall)\s+of\s+"
                r"(\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?:\s+cubes?)?\b", re.I),
     lambda m: f" {m.group(2)} {'long' if m.group(1).lower() == 'long' else 'high'} "),
    # "a tower next to it, as tall as its top step": as tall as the staircase (read as a vague
    # "tall": 6 high)
    (re.compile(r"\bas\s+(tall|high)\s+as\s+(?:its|the(?:\s+(?:staircase|stairs?)(?:'s|')?)?)\s+(?:very\s+)?"
                r"(?:top|highest|last|upper(?:most)?)\s+(?:step|stair|level)\b", re.I),
     lambda m: m.group(0) if not re.search(r"\bstair|\bsteps?\b", m.string[: m.start()], re.I)
     else f"as {m.group(1)} as the staircase"),
    # "a wall of the same length behind it", "a tower as tall as the first one", "then a wall
    # behind it, same length, 3 high" (dropped, silently)
    (_SAME_AS, _same_as),
    # "a second wall the same size behind it": a copy of the first, which is what a second of
    # the same family is ('size' was left over: partial)
    (re.compile(r"\b((?:a\s+second|another|one\s+more|an\s+other)\s+(" + _FAMILY_SAID
                + r"|one))\s*,?\s+(?:of\s+|in\s+)?(?:exactly\s+)?the\s+same\s+(?:size|dimensions)"
                r"(?:\s+as\s+(?:it|that(?:\s+one)?|the\s+(?:first|other)(?:\s+one)?|the\s+\2))?\b",
                re.I), r"\1"),
    # "a row of 5 towers", "a line of 4 stacks of 2": that many in a row (a row was built too)
    (re.compile(r"\ban?\s+(?:row|line)\s+of\s+(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+"
                r"(towers|stacks|columns|pillars|posts|pyramids|walls|staircases|arches|bridges)\b"
                r"((?:\s+(?:of\s+)?(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
                r"(?:\s+(?:cubes?|high|tall|levels?|steps?))?)?)", re.I), r"\1 \2\3 in a row"),
    # "a row of towers, 1, 2, 3, 4 cubes high": towers in a row (a row of 5 was built too)
    (re.compile(r"\ban?\s+(?:row|line)\s+of\s+(towers|stacks|columns|pillars|posts)\b"
                r"(?!\s+(?:of\s+)?(?:\d|one|two|three|four|five|six|seven|eight|nine|ten)\b)",
                re.I),
     r"\1 in a row"),
    # "5 towers, heights 1 to 5": one of each height (five of height 1 were built)
    (re.compile(r"\b(heights?\s+(?:of\s+)?)(?:from\s+)?(\d)\s*(?:to|through|-|–)\s*(\d+)\b", re.I),
     _height_run),
    # "three towers, 5, 10 and 15 cm tall": each in cubes when every one is whole cubes
    (re.compile(r"\b(\d+(?:\.\d+)?(?:\s*,\s*\d+(?:\.\d+)?)*\s*,?\s*(?:and|&)\s*\d+(?:\.\d+)?)\s*"
                r"(mm|cm)\b(?=\s+(?:tall|high|long|in\s+height))", re.I), _list_in_cubes),
    # "two towers of 3 on either side of it": one on each side (two on each were built)
    (re.compile(r"\b(?:two|2)\s+(tower|stack|column|pillar|post|cube|block|row|wall)s"
                r"((?:\s+of\s+(?:\d+|one|two|three|four|five|six|seven|eight)(?:\s+(?:cubes?|high|tall))?)?"
                r"(?:\s+(?:\d+|one|two|three|four|five|six)\s+(?:cubes?\s+)?(?:high|tall|long))?)"
                r"\s*,?\s+(on\s+(?:either|each|both)\s+sides?\s+of)\b", re.I),
     r"a \1\2 \3"),
    # "stand two towers of 3 on its two ends", "four cubes on its four corners": one at each (the
    # second stood on the first: failure)
    (re.compile(r"\b(two|2|four|4)\s+(tower|stack|column|pillar|post|cube|block|pyramid)s"
                r"((?:\s+of\s+(?:\d+|one|two|three|four|five|six|seven|eight)(?:\s+(?:cubes?|high|tall))?)?"
                r"(?:\s+(?:\d+|one|two|three|four|five|six)\s+(?:cubes?\s+)?(?:high|tall|long))?)"
                r"\s*,?\s+(?:one\s+)?(on|at)\s+(?:its|the|both|all|each\s+of\s+its)\s+(?:(?:two|2|four|4)\s+)?"
                r"(ends|corners)\b(?!\s+of\s+the\s+(?:table|workspace|cell|bench|floor|area|work))(\s+of\b)?",
                re.I),  # the table's four corners are its corner regions, one each
     lambda m: m.group(0) if (m.group(1).lower() in ("two", "2")) != (m.group(5).lower() == "ends")
     else f"a {m.group(2)}{m.group(3)} {m.group(4)} each {m.group(5)[:-1]} of"
     + ("" if m.group(6) else " it")),
    # "a 3x3 square with the middle missing": hollow
    (re.compile(r"\bwith\s+(?:the|its)\s+(?:middle|centre|center)(?:\s+(?:cube|one|bit))?\s+"
                r"(?:missing|empty|left\s+out|left\s+empty|removed|open|taken\s+out)\b", re.I),
     "hollow"),
    # "No, not three, just two": the corrected figure ("just" adds nothing to it)
    (re.compile(r"(\bnot\s+(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*,\s*)"
                r"(?:just|only|but)\s+(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)",
                re.I), r"\1"),
    # "don't let them touch": they must not touch (a claim, checked on the reading)
    (re.compile(r"\b(?:do\s+not|don'?t|never)\s+let\s+(?:them|the\s+two|the\s+\w+)\s+touch"
                r"(?:\s+each\s+other)?\b(?![^.;]*\b(?:gaps?|space|apart)\b)", re.I),
     " they must not touch "),
    # "1 @ back L, 1 @ back R": one in each place
    (re.compile(r"(?:(?<=[:,;]\s)|(?<=[:,;])|(?<=\band\s))1\s+(?=(?:at|@|on|in)\b)", re.I), "one "),
    # "not one behind the other": side by side; "not side by side": one behind the other
    (re.compile(r"\b(?:and\s+)?not\s+one\s+behind\s+(?:the\s+other|another)\b", re.I),
     " side by side "),
    (re.compile(r"\b(?:and\s+)?not\s+side\s+by\s+side\b", re.I), " one behind the other "),
    # "a tower at the back left corner of the table then another one …": the table's corner
    # (the table was the last noun: "another one" built a table, silently)
    (re.compile(r"\b(the\s+(?:back|front|rear|far|near)[\s-](?:left|right)\s+corner)\s+of\s+the\s+"
                r"(?:work\s*)?(?:table|bench|workspace|cell)(?:\s*top)?\b", re.I), r"\1"),
    # "a wall 4 long, scratch that, 6 long": the value taken back, not the wall ("takes back
    # everything it names": error)
    (re.compile(r"(\b" + _NUM + r"\s+(?:cubes?\s+)?(?:long|high|tall|wide|deep|steps?|levels?)\s*),"
                r"\s*(?:scratch|strike|cross\s+out)\s+that\s*,\s*(?=" + _NUM + r"\b)", re.I),
     r"\1, no, "),
    # "the block of two per two": two by two (a pack of 2 was built, silently)
    (re.compile(r"\b(" + _NUM + r")\s+per\s+(" + _NUM + r")\b(?!\s*(?:row|level|layer)s?\b)", re.I),
     r"\1 by \2"),
    # "stack one cube on top of another cube": a tower of two (one cube was built)
    (re.compile(r"\b(?:stack|put|place|set)\s+(?:one|a|a\s+single)\s+(?:cube|block)\s+(?:on\s+top\s+of|"
                r"onto|on)\s+(?:another|a\s+second|one\s+more)(?:\s+(?:cube|block|one))?\b", re.I),
     "stack a tower of 2"),
    # "a 1x6 wall along +y, height 2": its footprint, one cube thick and six long (a wall 1
    # long and 6 high was built, a column)
    (re.compile(r"\b(?:1\s*[x×]\s*(\d+)|(\d+)\s*[x×]\s*1(?=\s+\w+\b[^.;]*\b(?:height|high|tall)\b))"
                r"\s+(wall|row)\b(?!\s*[x×])", re.I),
     lambda m: f"{m.group(3)} {m.group(1) or m.group(2)} long"),
    # a work order's "TOWER, QTY 3": three towers; "QTY CUBES 5": five cubes ("QTY 1" of an
    # arch was its height); "… PER ENG": who asked for it
    (re.compile(r"\b(" + _FAMILY_SAID + r")\s*,?\s*(?:qty|quantity)\s*[:=]?\s*(\d+)\b",
                re.I),
     lambda m: f"{m.group(2)} {m.group(1)}"
     + ("" if m.group(2) == "1" or m.group(1).lower().endswith("s") else "s")),
    (re.compile(r"\b(?:qty|quantity)\s*(?:of\s+)?(cubes|blocks|parts)\s*[:=]?\s*(\d+)\b", re.I),
     r"\2 \1"),
    (re.compile(r"\s*\bper\s+(?:the\s+)?(?:eng|engineering|engineer|customer|client|spec|drawing|"
                r"request|qa|manager|management|supervisor|instructions?)\b\.?", re.I), " "),
    # a work order's "BETWEEN ITEMS 1 AND 2", "JOINING ITEMS 1 AND 2": the two named
    (re.compile(r"\b(?:items|parts|structures|nos?\.?)\s+\d+\s+(?:and|&)\s+\d+\b", re.I), "them"),
    # "arms 3 including the corner cubes": as SDI counts them (read as the table's corner)
    (re.compile(r"\s*,?\s*\b(?:including|incl\.?|counting)\s+the\s+corners?(?:\s+(?:cubes?|blocks?|"
                r"ones?|pieces?))?\b", re.I), " "),
    # "a tower adjacent to the left end of the wall": at that end, beside it (the tower went
    # to the table's left)
    (re.compile(r"\b(?:adjacent\s+to|next\s+to|beside|touching|against|right\s+by)\s+"
                r"(?:(the|its)\s+)?(?=(?:left|right|front|back)\s+end\b)", re.I),
     lambda m: f"at {m.group(1) or 'the'} "),
    # "two pillars with a piece across the top", "a crossbar over the top": a beam on them (the
    # piece was dropped, silently)
    (re.compile(r"\b(?:an?|one)\s+(?:(?:long|flat|single)\s+)?(?:piece|cross[\s-]?bar|"
                r"cross[\s-]?piece|cross[\s-]?beam|bar|rod|stick|board|slat)\s+(?:(?:laid|placed|set|"
                r"going|running|lying|resting)\s+)?(?:across|over)\s+(?=the\s+tops?\b|them\b|both\b|"
                r"the\s+two\b)", re.I), "a beam across "),
    # "a bridge over a river", "each step one cube higher than the last": a likeness, what a
    # staircase is
    (re.compile(r"\s+over\s+(?:a|the)\s+(?:river|stream|road|canal|ditch|valley|moat|creek|brook)\b"
                r"(?!\s+(?:that\s+is\s+|which\s+is\s+|of\s+|about\s+)?(?:\d|one|two|three|four|five|six))",
                re.I), " "),
    (re.compile(r"\s*,?\s*\b(?:with\s+)?each\s+step\s+(?:one|1)\s+(?:cube|block)\s+(?:higher|taller)\s+"
                r"than\s+the\s+(?:last|previous|one\s+before)(?:\s+one)?\b", re.I), " "),
    # "three cubes, one on top of another": a tower of three (three towers of one, two stacked)
    (re.compile(r"(?<!\bof\s)\b(" + _NUM + r")\s+(?:cubes|blocks)\s*,?\s*(?:stacked\s+|piled\s+)?"
                r"(?:one\s+on\s+top\s+of|one\s+on|one\s+above)\s+(?:another|the\s+other|each\s+other|"
                r"the\s+next|the\s+last)\b", re.I),
     r"a tower of \1"),
    # "a 3-high wall all the way around a 6 by 6 area": a ring with that inside (a wall 6 long
    # and 6 high was built)
    (re.compile(r"\b(?:walls?|fences?|fencing|borders?|barriers?|rings?)\b([^.;]*?)\s+"
                r"(?:all\s+the\s+way\s+)?(?:around|round|surrounding|enclosing)\s+(?:a|an|the)\s+"
                r"(\d+\s*(?:by|x)\s*\d+)\s+(?:square\s+)?(?:area|space|region|zone|yard|plot|field)\b",
                re.I),  # not a patch or a square: a structure of its own, enclosed
     r"ring\1 around a \2 space"),
    # "a pen and a tower outside it on the left": beside it, on that side (the tower went to
    # the table's left; "outside it" alone named nothing)
    (re.compile(r"\boutside\s+(?:of\s+)?(it|them|the\s+(?!table\b|workspace\b|cell\b|bench\b)"
                r"[a-z]+)(?:\s*,?\s*(?:on|to|at)\s+(?:the|its)\s+(left|right|back|front)"
                r"(?:\s+side)?\b)?", re.I),
     lambda m: m.group(0) if re.search(r"\b(?:nothing|anything|no\s+\w+)\s+(?:else\s+)?$",
                                       m.string[: m.start()], re.I)  # "nothing outside it"
     else f"to the {m.group(2)} of {m.group(1)}" if m.group(2) else f"next to {m.group(1)}"),
    # "as far from the robot as the table goes": flush with the back edge
    (re.compile(r"\bas\s+far\s+(?:away\s+)?from\s+the\s+robot\s+as\s+(?:the\s+(?:table|cell|"
                r"workspace)\s+(?:goes|allows|lets\s+it)|it\s+(?:can|will)\s+go|it\s+goes|possible|you\s+"
                r"can)\b",
                re.I), " as far back as it can go "),
    # "Behind the throne - a 2 by 2 block one high - looms a pillar of seven", "Behind the wall
    # - four long, two high - a tower of three": the fronted relation's object described between
    # dashes (the dash ended the clause: the block stood at the back, the pillar free, silently)
    (re.compile(r"(?:^|(?<=[.;!?]\s))(\s*(?:behind|in\s+front\s+of|next\s+to|beside|(?:to\s+the\s+)?"
                r"(?:left|right)\s+of|on\s+top\s+of|on|around)\s+)the\s+([a-z]+)\s+[-–(]\s*"
                r"([^-–()]+?)\s*[-–)]\s*,?\s*", re.I),
     _object_between_dashes),
    # "On top of that a 2 by 2 square, and on top of that a cube": each fronted relation a
    # sentence of its own (two in one clause related the pronouns to the wrong phrases)
    (re.compile(r"(\bon\s+top\s+of\s+(?:that|it|this)\b[^.;]*?)\s*,?\s+and\s+(?:then\s+)?"
                r"(on\s+top\s+of\s+(?:that|it|this)|on\s+(?:that|it|this)|above\s+(?:that|it|this))\s+"
                r"(?=(?:a|an|one|another|\d+)\b)", re.I), r"\1. \2 "),
    # "two towers flanking a central pyramid", "a pyramid flanked by two towers": the one
    # between the two ('flanking' was dropped as a word of no meaning, silently)
    (re.compile(r"\b((?:two|2|a\s+pair\s+of)\s+[^,.;]*?)\s+flanking\s+(?:a|an|the)\s+(?:central\s+|middle\s+)?"
                r"([^,.;]+?)(?=\s*(?:[,.;]|\band\b|\bthen\b|$))", re.I),
     r"a \2 between \1"),
    (re.compile(r"\bflanked\s+(?:on\s+(?:both|either|each)\s+sides?\s+)?(?:by|with)\s+", re.I),
     lambda m: "between " if re.match(r"(?:two|2|a\s+pair|both)\b", m.string[m.end() :], re.I)
     else "between two "),
    # "a pyramid between two towers, towers 4 cubes tall": the size of those named before, in
    # a sentence of its own (a third tower was built, silently)
    (re.compile(r"\s*[,;]\s*(?:and\s+)?((?:both|all|the)\s+)?(towers|walls|rows|stacks|columns|pillars|"
                r"pyramids|staircases)(\s+(?:are\s+|each\s+|both\s+)?(?:(?:\d+|one|two|three|four|five|six|"
                r"seven|eight|nine|ten)\s+(?:cubes?\s+|blocks?\s+)?(?:high|tall|long|levels?|steps?)))\b"
                r"(?=\s*(?:[.;]|$))", re.I),
     lambda m: m.group(0) if not re.search(
         r"\b(?:two|three|four|both|2|3|4)\s+(?:\w+\s+)?" + m.group(2) + r"\b",
         _sentence_before(m.string, m.start()), re.I)
     else f". The {m.group(2)}{m.group(3)}"),
    # "a tower of 3, then put 2 cubes on top", "put a block on top of it to make it taller":
    # the tower that much taller (a row of 2 was laid across its top; a block beside it)
    (re.compile(r"\b(add|put|stack|place|set)\s+(\d+|a|an|one|two|three|four|five)\s+(cubes?|blocks?)\s+"
                r"(?=on(?:to)?\s+(?:the\s+)?top\b(?:\s+of\s+(?:it|that|the\s+(?:tower|stack|column)))?"
                r"(?!\s+of\b))", re.I),
     lambda m: m.group(0) if (lambda named: not named or named[-1].lower() not in (
         "tower", "towers", "stack", "column", "pillar"))(
         re.findall(r"\b(" + "|".join(lx.SHAPE_WORDS) + r")\b", m.string[: m.start()], re.I))
     else f"{m.group(1)} {'one' if m.group(2).lower() in ('a', 'an') else m.group(2)} more "
          f"{m.group(3)} "),
    # "put a block on top of it to make it taller": what the addition is for (read as a
    # phrase of its own)
    (re.compile(r"\s*,?\s*(?:in\s+order\s+|so\s+as\s+)?to\s+make\s+(?:it|them)\s+(?:a\s+(?:bit|little)\s+|"
                r"one\s+)?(?:taller|higher|bigger|longer|wider)\b", re.I),
     lambda m: " "
     if re.search(r"\b(?:more|on\s+top|onto)\b", _sentence_before(m.string, m.start()), re.I)
     else m.group(0)),
    # "a row of three stacks, each stack three high": each that high (a fourth stack was built)
    (re.compile(r"\b(each|every)\s+(?:stack|tower|column|pillar|pile|post)\s+(?:is\s+|being\s+)?(?=(?:\d+|one|"
                r"two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?\s+|blocks?\s+)?(?:high|tall)\b)",
                re.I), r"\1 "),
    # "two towers of two blocks and lay a long block across them": a beam (a 3-long block was
    # laid on a bridge, and failed)
    (re.compile(r"\b(?:a|one)\s+long\s+(?:block|brick|piece|cube|bar)\s+(?=(?:across|over|on\s+top\s+of|onto|on)\s+"
                r"(?:them|the\s+two|both|the\s+(?:towers|stacks|columns|pillars|posts)))", re.I),
     "a beam "),
    # "Stack 'em four high, single stack.": one stack (a second one was built)
    (re.compile(r"(?<=\w)\s+'em\b", re.I), " them"),
    (re.compile(r"\s*,\s*(?:just\s+|only\s+)?(?:a\s+|one\s+)?single\s+(?:stack|tower|column|pile)\s*(?=[.;!]|$)",
                re.I),
     lambda m: " " if re.search(r"\bstack", _sentence_before(m.string, m.start()), re.I)
     else m.group(0)),
    # "She likes stairs, can you do stairs with 3 steps": what someone likes, not a structure
    (re.compile(r"\b(?:she|he|they|my\s+\w+|the\s+kids?|the\s+children|our\s+\w+)\s+(?:really\s+)?(?:likes?|"
                r"loves?|adores?|is\s+into|are\s+into|enjoys?|is\s+crazy\s+about)\s+(?:\w+\s+)?(stairs|"
                r"staircases|towers|bridges|castles|pyramids|arches|walls)\s*[,.;!]\s*", re.I),
     lambda m: m.group(0) if not re.search(rf"\b{m.group(1)[:5]}", m.string[m.end() :], re.I)
     else ""),
    # "a pyramid: four blocks at the bottom, then three, then two, then one on top": its rows,
    # said from the bottom (the three and two were reported unused)
    (re.compile(r"\b(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+)?(?:at|on|in|along)\s+the\s+bottom"
                r"(?:\s+row)?((?:\s*,?\s*(?:and\s+)?then\s+" + _NUM
                + r"(?:\s+(?:cubes?|blocks?))?)+)(?:\s+(?:on\s+top|at\s+the\s+top))?", re.I),
     lambda m: m.group(0) if not re.search(r"\bpyramid", m.string, re.I)
     else "rows of " + ", ".join([m.group(1), *re.findall(_NUM, m.group(2), re.I)])),
    # "a pyramid with rows of 4, 3, 2 and 1": a base of 4, one fewer each level up (a pyramid
    # and four rows beside it were built); rows to a flat top say its levels
    (re.compile(r"\b(?:with\s+|of\s+|in\s+)?(?:rows|levels|layers|tiers|courses)\s+of\s+(" + _NUM
                + r"(?:\s*,\s*" + _NUM + r")*(?:\s*,?\s*(?:and\s+)?" + _NUM + r"))"
                r"(?:\s+(?:cubes|blocks))?(?:\s+(?:each|respectively))?", re.I),
     lambda m: _pyramid_rows(m)),
    # "an L with five blocks going one way and three going the other way": its arms (the 3
    # was dropped)
    (re.compile(r"\b(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+)?(?:going\s+|running\s+|in\s+)?one\s+"
                r"(?:way|direction)\s*,?\s+and\s+(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+)?"
                r"(?:going\s+|running\s+|in\s+)?the\s+other(?:\s+(?:way|direction|one))?\b", re.I),
     r"arms \1 and \2"),
    # "a cross with arms of two around a middle block": its own centre (read as a ring around a
    # block)
    (re.compile(r"\s+(?:around|round|from)\s+(?:a|the|one)\s+(?:middle|centre|center|central|"
                r"single)\s+(?:block|cube|square)\b", re.I),
     lambda m: " "
     if re.search(r"\b(?:cross|plus|arms?)\b", _sentence_before(m.string, m.start()), re.I)
     else m.group(0)),
    # "a ring around a 3x3 floor area": the area (a floor was built beside it)
    (re.compile(r"\b((?:around|round|enclosing|surrounding)\s+(?:an?\s+)?(?:empty\s+)?\d+\s*(?:x|by)\s*\d+"
                r")\s+floor\s+(?:area|space|patch)\b", re.I), r"\1 space"),
    # "a cube that is 2 cubes long, 2 cubes wide and 2 cubes tall": a block that size (a tower
    # of 2)
    (re.compile(r"\b((?:a|one)\s+(?:(?:big|large|solid|small|single)\s+)?)cube\b(?=(?:\s*,|\s+(?:that|"
                r"which)\s+(?:is|measures))?\s+(?:\d|one|two|three|four|five)[^.;]*?\blong\b[^.;]*?\bwide\b[^.;]*?"
                r"\b(?:tall|high|deep)\b)",
                re.I), r"\1block"),
    # "a row with 7 cubes, which goes from the front to the back": the way it runs ("goes" was
    # reported as not used)
    (re.compile(r"\b(?:(?:which|that)\s+)?(?:goes|runs|extends|stretches|reaches|going|running|"
                r"extending|stretching)\s+(?=from\s+(?:the\s+)?(?:front|back|left|right|near|far)\b[^.;]{0,25}"
                r"\bto\b)", re.I), ""),
    # "a tower of two on top of the middle of a row of three": on its middle (set at the
    # table's centre, beside the row, silently)
    (re.compile(r"\bon\s+top\s+of\s+the\s+(middle|centre|center)\s+of\b", re.I), r"on the \1 of"),
    # "A tower has 3 cubes. A second tower is twice as tall. Build both towers side by side.":
    # the two said (two more towers were built)
    (re.compile(r"\bboth\s+(?:of\s+)?(?:the\s+|these\s+|those\s+)?(" + _FAMILY_SAID + r")s\b",
                re.I),
     lambda m: f"the two {m.group(1)}s"
     if families_said(m.string[: m.start()]).count(lx.SHAPE_WORDS.get(m.group(1).lower(), "")) >= 2
     else m.group(0)),
    # "…, finish with a single cube on top", "and end with": then (the cube's relation was lost)
    (re.compile(r",\s*(?:and\s+)?(?:finish(?:ing)?|end(?:ing)?|round(?:ing)?\s+it\s+off|top(?:ping)?\s+it\s+"
                r"off)\s+(?:off\s+|up\s+)?with\s+(?=(?:an?|one|a\s+single)\s)", re.I), ", then "),
    # "Start with a 3 by 3 layer, then a 2 by 2 layer, finish with a single cube on top": a
    # layer after a layer is laid on it (it was set beside it, silently)
    (re.compile(r"\b((?:layer|level|course)\b\s*,?\s*(?:and\s+)?then\s+(?:an?|one)\s+(?:\d+\s*(?:x|by)\s*\d+"
                r"\s+)?(?:layer|level|course))\b(?!\s*(?:on|onto|beside|next|to|at|in|behind|under|below|"
                r"above|over|of|,\s*(?:on|beside|next|to|at|in|behind)\b))", re.I), r"\1 on it"),
    # "first a 3x3 layer, then a 2x2 layer on it, then one cube as the third level": a cube on
    # top (a relation cycle, an error)
    (re.compile(r"\b(then|and\s+then|finally|lastly)\s+one\s+(?:single\s+)?(cube|block|brick)\b(?=\s+(?:on|as|at|"
                r"to\s+top|for)\b)", re.I), r"\1 a \2"),
    # "little fence, eight cubes in a line": the fence is the line (a default wall and a row)
    (re.compile(r"\b(fence|wall|border|barrier|kerb|curb|edging|hedge|row|line)\s*,\s*(" + _NUM
                + r")\s+(?:cubes?|blocks?|bricks?)\s+(?:long\s+)?in\s+an?\s+(?:straight\s+)?"
                r"(?:line|row)\b", re.I), r"\1, \2 cubes long"),
    # "a low border … running all along the right-hand edge": a wall along it (a ring)
    (re.compile(r"\bborder\b(?=[^.;]*\b(?:along|down)\s+(?:the\s+)?(?:\w+[\s-]+){0,2}(?:edge|side)\b)"
                r"(?![^.;]*\b(?:around|round|enclos\w*|surround\w*)\b)", re.I), "wall"),
    # "Circle back to the wall: …": return to it (a ring was built); "Hi all, circling back on
    # the demo layout": the whole aside (read as the back)
    (re.compile(r"\bcircl(?:e|ing)\s+back\s+(?:(?:to|round\s+to|around\s+to)\b|on\b[^.,;!?]*|"
                r"(?=[.,;!?]))", re.I), ""),
    # "a 3 by 3 square with the centre square empty": its middle empty (a second, a row of 8)
    (re.compile(r"\bwith\s+(?:the\s+)?(centre|center|middle)\s+(?:square|cube|spot|cell|block|one|"
                r"position)\s+(?:left\s+)?(empty|open|free|missing|out|removed)\b", re.I),
     " hollow"),
    # "a rook on the back-left square" (of a board): that corner of the table (a slab was
    # built under it)
    (re.compile(r"\b(?:on|at|in)\s+the\s+((?:back|front|far|near)[\s-]+(?:left|right))\s+(?:square|cell)\b"
                r"(?!\s+of\s+(?!the\s+(?:table|board)\b))(?:\s+of\s+the\s+(?:table|board))?", re.I),
     r"in the \1 corner"),
    # a programmer's call: "tower(4)", "T(bar=5, stem=2)", "pyramid(base=4, square=True)":
    # the structure and its sizes; "if table.empty():" a condition; "back_left" a place;
    # "for level in range(3): lay 2x2 square" that many levels
    (re.compile(r"\bif\s+[\w.]+\(\)\s*:\s*", re.I), ""),
    (re.compile(r"\b(back|front)_(left|right)\b", re.I), r"\1 \2"),
    (re.compile(r"\bfor\s+(?:level|layer|tier|course|z)\s+in\s+range\(\s*(\d+)\s*\)\s*:\s*([^.;\n]+)",
                re.I), r"\2, \1 layers"),
    (re.compile(r"\b(" + _FAMILY_SAID + r"|(?-i:[TLU]))\(([^()]*)\)", re.I), _called),
    # "one rank high" (a chess player's row): one high (a row of 8 was built)
    (re.compile(r"\b(" + _NUM + r")\s+ranks?\s+(high|tall)\b", re.I), r"\1 \2"),
    # "three towers … of two, of three and of four": a list of their sizes
    # (a comma before the first "of" too: "Three towers, of two, of three and of four")
    (re.compile(r"(?:\s*,)?\s*\bof\s+(" + _NUM + r")\s*,\s*of\s+(" + _NUM + r")\s*,?\s*(?:and\s+)?"
                r"of\s+(" + _NUM + r")\b", re.I),
     lambda m: " of {}, {} and {}".format(*words_to_numbers([n.lower() for n in m.groups()]))),
    # "Two towers stand 15 cm apart": the towers, 15 cm apart ("stand" split them from their
    # sizes said after)
    (re.compile(r"\b((?:two|three|four|[2-9])\s+(?:" + _FAMILY_SAID + r")s)\s+(?:stand|standing|"
                r"sit|sitting)\s+(?=\d|one|two|three|four|five|six)", re.I), r"\1 "),
    # "15 cm apart (gap between them)": a clear gap, as "apart" is read
    (re.compile(r"\bapart\s*\(\s*(?:a\s+|the\s+)?(?:clear\s+)?(?:gap|space|distance)\s+between\s+(?:them|the\s+"
                r"\w+)\s*\)", re.I), "apart"),
    # "stick the tall one on the left", "bung it at the back": put
    (re.compile(r"\b(?:stick|bung|chuck)\b(?=\s+(?:the|it|them|a|an|one|that|those|this)\b)", re.I),
     "put"),
    # "a gap of at least one cube": one cube, the least asked (the "a" of "at" was read)
    (re.compile(r"\b(?:at\s+least|no\s+less\s+than|a\s+minimum\s+of|minimum)\s+(?=(?:\d|one|two|three|"
                r"four|five)\b[^.;,]{0,12}?\b(?:cubes?|blocks?|cm|mm|m)\b)", re.I), ""),
    # "3 & 5, 5 on R": the one of 5 on the right
    (re.compile(r"(?<=\bon\s)(?-i:R)\b"), "the right"),
    (re.compile(r"(?<=\bon\s)(?-i:L)\b"), "the left"),
    # "8 cubes in a line, contiguous": touching (reported as not used)
    (re.compile(r"\bcontiguous(?:ly)?\b", re.I), "touching"),
    # "an arch spanning a clear gap of 150 mm": its span ("spanning" reported as not used)
    (re.compile(r"\b(arch|bridge)\s+spanning\s+(?:an?\s+)?(?:clear\s+|free\s+)?(?:gap|opening|span|"
                r"distance)\s+of\b", re.I), r"\1 with a span of"),
    # "a 2x2 base tier", "1 tier": a layer (a palletiser's word; "tier" was not used)
    (re.compile(r"\btier\b", re.I), "layer"),
    # "two towers … and put one bridge on top connecting both": a beam joining them (a bridge
    # beside the towers, on one of them)
    (re.compile(r"\b(a|one|the)\s+bridge\s+(?=(?:on\s+top|across(?:\s+the\s+tops?)?|over)\b[^.;]{0,30}?"
                r"\b(?:connecting|joining|linking|between|spanning)\b)", re.I),
     lambda m: f"{m.group(1)} beam "
     if re.search(r"\b(?:towers|pillars|columns|stacks|posts)\b",
                  _sentence_before(m.string, m.start()), re.I)
     else m.group(0)),
    # a bridge's "walkway", "footway", "roadway": its deck
    (re.compile(r"\b(?:walk|foot|road)[\s-]?way\b(?!\s+between\b)", re.I), "deck"),  # not a gap
    # "two supports, three high, and a walkway on top": pillars (nothing was built, or a block)
    (re.compile(r"\b(two|2|both|pair\s+of)\s+supports\b(?=[^.;]*\b(?:beam|plank|lintel|girder|"
                r"deck)\b)", re.I),
     lambda m: m.group(0)
     if re.search(r"\b(?:foot)?bridge", _sentence_before(m.string, m.start()), re.I)
     else f"{m.group(1)} pillars"),
    # "two columns of three cubes carrying a lintel", "supporting a flat roof slab": the beam
    # on top of them (the columns stood bare, the lintel a default bridge beside them)
    (re.compile(r"\b(?:carrying|supporting|holding\s+up|bearing|that\s+carry|that\s+support|which\s+carry|"
                r"which\s+support)\s+(?:a|an|one|the)\s+(?:flat\s+|long\s+|single\s+)?(lintel|beam|plank|"
                r"girder|slab|roof(?:\s+slab)?|deck|top)\b", re.I),
     lambda m: m.group(0)
     if not re.search(
         r"\b(?:two|2|both|pair\s+of)\s+(?:\w+\s+)?(?:columns|towers|pillars|posts|stacks)\b",
         _sentence_before(m.string, m.start()), re.I)
     else (" with a beam on top" if m.group(1).lower() in ("lintel", "beam", "plank", "girder")
           else f" with a {m.group(1)} on top")),
    # "a portico: four columns of two cubes supporting a flat roof slab": a table on those legs
    (re.compile(r"\b(?:four|4)\s+(?:columns|pillars|posts|legs|piers)\s+(?:of\s+)?(" + _NUM
                + r")\s+"
                r"(?:cubes?\s+|blocks?\s+)?(?:high\s+|tall\s+)?(?:each\s+)?,?\s*(?:carrying|supporting|holding\s+up|"
                r"bearing|under)\s+(?:a|an|one|the)\s+(?:flat\s+)?(?:roof(?:\s+slab)?|slab|top|deck|table\s?top)\b",
                re.I),
     r"a table with legs \1 high"),
    # "Tower, height 150 mm, single 50 mm cube footprint": one part across, what a tower is
    # (the 50 mm was read as its height)
    (re.compile(r"\s*,?\s*(?:on\s+)?(?:a\s+)?(?:single|one)[\s-]+(?:\d+\s*(?:mm|cm)\s+)?"
                r"(?:cube|block|part)s?\s+(?:footprint|base|wide)\b", re.I),
     lambda m: " " if re.search(r"\b(?:tower|stack|column|pillar|post)", m.string, re.I)
     else m.group(0)),
    # "then build the same thing two more times", "two more of the same", "build it one more
    # time": copies of the one before (a row of 2 was built, silently)
    (re.compile(
        r"\b(?:(?:build|make|do|add|put|stack|take)\s+)?(?:the\s+same(?:\s+(?:thing|one|again))?|"
        r"it\s+again|that\s+again)\s+(" + _NUM + r")\s+more\s+times?\b", re.I), r"\1 more like it"),
    (re.compile(r"\b(" + _NUM + r")\s+more\s+of\s+the\s+same\b", re.I), r"\1 more like it"),
    (re.compile(
        r"\b(?:build|make|do|stack|take)\s+(?:it|that|this|the\s+same(?:\s+thing)?)\s+(?:one\s+more\s+time|"
        r"once\s+more|(?:all\s+over\s+)?again)\b(?:\s+and\s+put\s+it)?", re.I), "one more like it"),
    # "a block two by two by three tall": its three sides, the last its height ('tall' was
    # reported unused)
    (re.compile(
        r"\b(" + _NUM + r"\s*(?:by|x)\s*" + _NUM + r"\s*(?:by|x)\s*" + _NUM + r")\s+(?:cubes?\s+)?"
        r"(?:tall|high)\b", re.I), r"\1"),
    # "… four cubes each new line and a bridge …": a dictated line break
    (re.compile(
        r"(?<!\ba\s)(?<!\bthe\s)\s*\bnew\s+(?:line|paragraph)\b(?!\s+of\b)\s*", re.I), ". "),
    # "with a gap between the rows": the gap between them (read as rows a beam joins)
    (re.compile(
        r"\b(gap|space)\s+between\s+the\s+(?:rows|towers|walls|stacks|columns|lines|two)\b", re.I),
     r"\1 between them"),
    # "step width 2 cubes": the staircase's width
    (re.compile(r"\bstep\s+(width|depth)\b", re.I), r"\1"),
    # "ascending toward +y (left)": the side that axis points to
    (re.compile(
        r"\b(to(?:wards?)?|toward)\s+([+-])\s*([xy])\b(?:\s*\(\s*(?:left|right|back|front)\s*\))?",
        re.I),
     lambda m: f"{m.group(1)} the "
     + {("+", "y"): "left", ("-", "y"): "right", ("+", "x"): "back", ("-", "x"): "front"}[
         (m.group(2), m.group(3).lower())]),
    # "Make T form": the letter's shape
    (re.compile(r"\b([LTU])[\s-]*form\b", re.I), r"\1 shape"),
    # "a T shape, the top is 5 cubes, the leg is 3 cubes": the T's stem (a tower)
    (re.compile(
        r"\b(the\s+|its\s+)?leg\b(?=\s+(?:is\s+)?(?:\d|one|two|three|four|five|six)\b)", re.I),
     lambda m: f"{m.group(1) or ''}stem"
     if re.search(r"\bT\s+shape|\bT-shape", _sentence_before(m.string, m.start()))
     else m.group(0)),
    # "a wall … not more high than 2": no higher than that
    (re.compile(r"\bnot\s+more\s+(high|tall|long|wide)\s+than\b", re.I),
     lambda m: "no " + {"high": "higher", "tall": "taller", "long": "longer", "wide": "wider"}[
         m.group(1).lower()] + " than"),
    # "a courtyard, 5 by 4 cubes outside dimensions": its size over all ('4 cubes out' was read
    # as a gap)
    (re.compile(r"((?:by|x)\s*\d+\s*(?:cubes?|blocks?|cm|mm)?)\s+(?:outside|outer|external|overall|exterior)"
                r"(?:\s+(?:dimensions?|size|measurements?))?\b|(\d\s*(?:cubes?|blocks?|cm|mm)?)\s+(?:outside|"
                r"outer|external|overall|exterior)\s+(?:dimensions?|size|measurements?)\b", re.I),
     lambda m: m.group(1) or m.group(2)),
    (re.compile(r"\benclosed\s+(?=(?:courtyard|yard|court|garden|pen|area|space)\b)", re.I), ""),
    # "four walls in a square, 4 blocks each side": a square ring (four blocks side by side)
    (re.compile(r"\b(?:four|4)\s+walls\s+(?:in|forming|making|as)\s+a\s+square\b", re.I),
     "a square ring"),
    # "three rows of two towers each": six towers, three rows of two (a 2 by 3 floor was built)
    (re.compile(r"\b(" + _NUM + r")\s+rows\s+of\s+(" + _NUM
                + r")\s+(towers|stacks|columns|pillars|piles)(?:\s+each)?\b", re.I),
     lambda m: (lambda n: m.group(0) if not all(v.isdigit() for v in n)
                else f"{int(n[0]) * int(n[1])} {m.group(3)} in {n[0]} rows of {n[1]}")(
         words_to_numbers([m.group(1).lower(), m.group(2).lower()]))),
    # "two towers of 3 joined by a beam across the top": the beam that joins them ('a beam across
    # the top' was reported as naming nothing)
    (re.compile(r"\b((?:joined|connected|linked|bridged|spanned)\s+(?:by|with)\s+(?:a|one|the)\s+(?:beam|lintel|"
                r"plank|girder))\s+(?:(?:laid|lying|running)\s+)?(?:across|over|on)\s+(?:the\s+)?(?:tops?|top\s+of\s+"
                r"them|them)\b", re.I), r"\1"),
    # "Row of 5 stacks": five stacks in a row (a row of its own was built beside them)
    (re.compile(r"\b(?:a\s+)?(?:row|line)\s+of\s+(" + _NUM
                + r")\s+(stacks|towers|columns|pillars|piles|posts)\b", re.I), r"\1 \2 in a row"),
    # "heights going up 1 2 3 4 5": a list said without commas
    (re.compile(
        r"\b(heights?(?:\s+(?:going\s+up|rising|of))?)\s+(\d+)((?:\s+\d+){2,})\b(?!\s*(?:mm|cm|m)\b)",
        re.I),
     lambda m: f"{m.group(1)} {_listed_figures(m.group(2) + m.group(3))}"),
    # "two towers, 4 tall, on opposite sides — left and right": one on each side said
    (re.compile(r"\s*,?\s*(?:on|at)\s+(?:the\s+)?opposite\s+(?:sides|ends)(?:\s+of\s+the\s+\w+)?\s*[,:—–-]*\s*"
                r"(?:the\s+)?(left|front)\s+and\s+(?:the\s+)?(right|back)\b", re.I),
     r", one on the \1 and one on the \2"),
    # "2 towers h=3,h=5": one height each (the 5 was dropped)
    (re.compile(r"\bh\s*=\s*(\d+)\s*,\s*h\s*=\s*(\d+)(?:\s*,\s*h\s*=\s*(\d+))?", re.I),
     lambda m: (f"{m.group(1)}, {m.group(2)} and {m.group(3)}" if m.group(3)
                else f"{m.group(1)} and {m.group(2)}") + " high"),
    # "a block of 3 times 3 times 2 cubes": three sizes, not a product (read as 9 by 2)
    (re.compile(r"\b(" + _NUM + r")\s+times\s+(" + _NUM + r")\s+times\s+(" + _NUM + r")\b", re.I),
     r"\1 by \2 by \3"),
    # "an L-shaped corridor wall, arms 5 and 3, 2 high": its arms said, the letter's (its arms'
    # second value was read as the wall's height)
    (re.compile(r"\b([LUT])[\s-]*shaped?\s+(?:\w+\s+)?(?:wall|fence)\b(?=[^.;]*\barms?\b)", re.I),
     r"\1 shape"),
    # "an L-shaped wall, 4 by 4 cubes, 2 cubes high": with its height said apart, the "4 by 4"
    # is the letter's arms (read as 4 long and 4 high, the 2 dropped, silently)
    (re.compile(r"\b([LUT])[\s-]*shaped?\s+(?:wall|fence)(\s*,?\s*(?:of\s+)?" + _NUM
                + r"\s*(?:by|x)\s*" + _NUM + r"(?:\s+(?:cubes?|blocks?))?)(?=\s*,?\s*(?:and\s+)?"
                + _NUM + r"\s+(?:cubes?\s+|blocks?\s+|courses?\s+)?(?:high|tall)\b)", re.I),
     r"\1 shape\2"),
    # "Two towers make, one 4 high …": the verb after its object
    (re.compile(r"\b((?:two|three|four|five|[2-9])\s+(?:towers|walls|rows|stacks|columns|blocks|pyramids))"
                r"\s+(make|build)\b", re.I), r"\2 \1"),
    # "two towers one two high and one six high": one each, said without a comma
    (re.compile(r"\b((?:two|three|four|five|[2-9])\s+(?:towers|walls|rows|stacks|columns|pillars))\s+"
                r"(?=(?:(?:um+|uh+|er+|erm)\s+)*one\s+(?:is\s+|being\s+|of\s+(?:a\s+)?height\s+(?:of\s+)?)?"
                r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b)", re.I), r"\1, "),
    # "make five towers and give each tower three cubes": each that high
    (re.compile(r"\s*,?\s*\b(?:and\s+)?(?:give|make)\s+(?:each|every)\s+(?:one|tower|stack|column|"
                r"pillar)\s+(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:cubes|blocks)\b",
                re.I),
     r", each \1 cubes high"),
    # "put one tower of 2 cubes over it": on top of it
    (re.compile(r"\b((?:tower|stack|column|cube|block|row|layer|slab|pyramid|wall)s?(?:\s+of\s+\S+"
                r"(?:\s+cubes?)?)?)\s+over\s+(it|that|this)\b", re.I), r"\1 on top of \2"),
    # "one is 4 high and one is 2 high", "one of height two and one of height six": one each
    (re.compile(r"\b(one|another|the\s+other)\s+(?:is\s+|being\s+|of\s+|with\s+)(?:a\s+)?height\s+"
                r"(?:of\s+)?(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b(?!\s*(?:cm|mm|m)\b)",
                re.I), r"\1 \2 high"),
    (re.compile(r"\b(one|another|the\s+other)\s+(?:is|being)\s+(\d+|one|two|three|four|five|six|seven|"
                r"eight|nine|ten)\s+((?:cubes?\s+)?(?:high|tall|long|wide))\b", re.I), r"\1 \2 \3"),
    # "every corner of the table should have a tower of 2": one in each corner
    (re.compile(r"\b(?:each|every|all(?:\s+four)?(?:\s+the)?)\s+corners?\s+of\s+the\s+(table|workspace|"
                r"cell)\s+(?:should|must|shall|will|is\s+to|has\s+to|needs\s+to)?\s*(?:have|get|gets|has|"
                r"hold|holds|needs)\s+(an?\s+[^.,;]+)", re.I), r"\2 in each corner of the \1"),
    # "a tile 20 cm on each side", "a cube 10cm on every side", "three on each edge": its sides
    (re.compile(r"\b(?:(\d+(?:\.\d+)?\s*(?:cm|mm|m|cubes?|(?:centi|milli)?met(?:re|er)s))\s+(?:on|per|along|"
                r"for)\s+(?:each|every|a|one)\s+(?:side|edge)|(\d+|two|three|four|five|six)\s+(?:cubes?\s+)?"
                r"(?:on|per|along)\s+(?:each|every|an?)\s+edge)\b(?!\s+of\b)", re.I),
     _each_side),
    # "a 3x3 slab with a 2x2 slab on top and a cube on top of that": stacked in turn
    (re.compile(r"(\bon\s+(?:top|it)(?:\s+of\s+it)?\s*,?\s*)and\s+(?=(?:then\s+)?(?:an?|one|"
                r"a\s+single|single)\s+[^,.;]{0,40}?\bon\s+(?:top\s+of\s+)?(?:that|this|the\s+\w+)\b)",
                re.I), r"\1, then "),
    # "a wall of 6 cubes, 2 rows high": rows counted upwards are courses (its height)
    (re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s+(?:rows|courses|tiers)"
                r"\s+(high|tall)\b", re.I), r"\1 \2"),
    # "three towers side by side: the left one 2 high, the middle one 3 high, …" (`_three_sides`);
    # "2 high, 3 high and 1 high", "2, 4, 2 high": one list of sizes (`_sizes_listed`)
    (_THREE_SIDES, _three_sides),
    (re.compile(rf"\b({_NUM})\s+(high|tall|levels|storeys|stories)(?:\s*,\s*{_NUM}\s+\2)*\s*,?\s*"
                rf"(?:and\s+)?{_NUM}\s+\2\b", re.I), _sizes_listed),
    (re.compile(rf"\b({_NUM})\s*,\s*{_NUM}\s*,\s*{_NUM}\s+(high|tall)\b", re.I), _sizes_listed),
    # "two towers, the left one 5 high and the right one 2 high": one each, in those places;
    # "Make two towers. The left one should be 5 high, the right one 2.", "two towers: left 5
    # high, right 2 high" (a bare number after the first takes its unit)
    (re.compile(rf"(?<=[,:;.]\s){_SIDE_ONE}({_SIDE_SIZE})(?=\s*(?:,|;|\.|\band\b|$))", re.I),
     lambda m: _side_one(m, m.group(2))),
    (re.compile(rf"(?:(?<=[,;]\s)|(?<=\band\s)){_SIDE_ONE}(?:(?P<sized>{_SIDE_SIZE})|(?P<bare>{_NUM}))"
                r"(?=\s*(?:,|;|\.|$))", re.I),
     lambda m: _side_one(m, m.group("sized") or _with_unit_before(m))),
    # "Make two towers. One 5 high on the left, one 2 high on the right.": one sentence
    (re.compile(_COUNTED_THEN + r"(?=one\s[^.;]*?\b(?:on|at)\s+the\s+(?:left|right|front|back)\b"
                r"[^.;]*?,?\s*(?:and\s+)?(?:one|the\s+other)\s)", re.I), r"\1, "),
    # "Build two towers. The first has 2 cubes, the second has 4 cubes.": one sentence (the
    # sizes were read as a row of their own)
    (re.compile(_COUNTED_THEN + r"(?=the\s+(?:first|left|right|front|back)\s+(?:one\s+|tower\s+|"
                r"stack\s+|column\s+)?(?:has|is|of|should|with|will|gets|needs|\d)\b[^.;]*?\bthe\s+"
                r"(?:second|other|last)\b)", re.I), r"\1, "),
    # "four cubes in the four corners of the table": one in each corner
    (re.compile(r"\b(in|on|at|into)\s+(?:all\s+)?the\s+(?:four|4)\s+corners\b", re.I),
     r"\1 each corner"),
    (re.compile(r"\b(" + _FAMILY_SAID + r")\s+from\s+(?=\d|(?:one|two|three|four|five|six|"
                r"seven|eight|nine|ten)\b)", re.IGNORECASE), r"\1 of "),
    (re.compile(r"\b(behind|beside|left|right)\s+of\s+(?=(?:" + _FAMILY_SAID + r")\b)",
                re.IGNORECASE), r"\1 of the "),
    (re.compile(r"\bbehind\s+of\b", re.IGNORECASE), "behind"),
    (re.compile(r"\bnear\s+to\b", re.IGNORECASE), "near"),
    # "in each 3 cubes", "between them one cube": the number after its preposition
    (re.compile(r"\bin\s+each\s+(?=\d|(?:one|two|three|four|five|six)\b)", re.I), "each "),
    (re.compile(r"\bbetween\s+(them|each|the\s+towers?|the\s+stacks?)\s+(one|a|\d+|two|three)\s+"
                r"(cubes?|blocks?|parts?)\b", re.I), r"\2 \3 between \1"),
    (re.compile(r"\bwith\s+(one|a|\d+|two|three)\s+(cubes?|blocks?|parts?)\s+(?:in\s+)?between\b",
                re.I), r"with \1 \2 gap"),
    # Romance and German word order: "4 cubes of height", "3 of length and 2 of height", "5 of
    # thickness", "a height of 4" stays; "20 per 20" is 20 by 20; "in the right part" is on the
    # right; "half so high" is half as high; "the double of" is twice
    (re.compile(r"\b(\d+(?:\.\d+)?|one|two|three|four|five|six|seven|eight|nine|ten)\s+"
                r"((?:cubes?|blocks?|parts?|floors?|levels?|storeys?|cm|mm|centimet(?:re|er)s?)\s+)?"
                r"(?:of\s+(height|length|width|depth|thickness|high|long|wide|large)|"
                r"in\s+(height|length|width|depth|thickness))\b", re.I),  # "8 in long": inches
     lambda m: m.group(1) + " " + (m.group(2) or "")
     + _DIMENSION_ADJ[(m.group(3) or m.group(4)).lower()]),
    (re.compile(r"(?<=\d)\s*(cm|mm|m)?\s+per\s+(?=\d)", re.I), r" \1 by "),
    (re.compile(r"\b(?:in|on|at)\s+the\s+(left|right|front|back|rear)(?:\s+(?:hand|most))?\s+"
                r"(?:part|zone|portion|sector)\b(?!\s+of\b)", re.I), r"on the \1"),
    (re.compile(r"\bhalf\s+so\s+(high|tall|long|wide|big)\b", re.I), r"half as \1"),
    (re.compile(r"\b(?:the\s+)?double\s+of\s+(?:the\s+)?(?:cubes?|height|size|it|that)\b", re.I),
     "twice as high"),
    (re.compile(r"\b(" + _FAMILY_SAID + r")\s+of\s+(?=(?:\d+|one|two|three|four|five|six|seven|"
                r"eight|nine|ten)\s+(?:cubes?\s+)?(?:long|high|tall|wide|deep)\b)", re.I), r"\1 "),
    (re.compile(r"\bat\s+its\s+(left|right)(?:\s+side)?\b", re.I), r"to the \1 of it"),
    # "a cube left beside it": to its left ("right next to it" is "immediately next to it")
    (re.compile(r"\b(left|(?<=\bthe\s)right)\s+(?:beside|next\s+to)\s+(it|them)\b", re.I),
     r"to the \1 of \2"),
    # "at 1 cube of distance to the back, other equal" (a Romance speaker): 1 cube behind it,
    # another the same; "After," is then
    (re.compile(r"\bat\s+(\d+|one|two|three|a)\s+(cubes?|cm|mm)\s+of\s+distance\s+(?:to|at|on)\s+the\s+"
                r"(back|left|right|front)\b", re.I),
     lambda m: f"{m.group(1)} {m.group(2)} " + {"back": "behind it", "front": "in front of it"}.get(
         m.group(3).lower(), f"to the {m.group(3).lower()} of it")),
    (re.compile(r"\b(?:an?\s+)?other\s+(?:one\s+)?(?:equal|identical|the\s+same|same)\b", re.I),
     "another one the same"),
    (re.compile(r"(^|[.;!]\s*)(?:and\s+)?after\s*,", re.I), r"\1then"),
    # "then on the right, same.": another one the same there
    (re.compile(r"\b(on|at|in)\s+the\s+(left|right|front|back)\s*,?\s+(?:the\s+)?same(?:\s+(?:again|"
                r"thing|one))?\s*(?=[.;!]|$)", re.I), r"another one the same \1 the \2"),
    # "then shift it 2 cubes to the left": a move by that much, never a relation to itself
    (re.compile(r"\b(move|shift|slide|relocate|push|nudge)\s+(it|them)\s+(?:by\s+)?(\d+(?:\.\d+)?|one|two|"
                r"three|four|five|a)\s*(mm|cm|m|cubes?)\s+(?:to\s+the|towards\s+the|to\s+its)\s+"
                r"(left|right)\b", re.I),
     lambda m: f"{m.group(1)} {m.group(2)} {m.group(3)} {m.group(4)} in "
     + ("+y" if m.group(5).lower() == "left" else "-y")),
    # a warehouse's words: "pallet stacks" are blocks, "3 pallets high" three layers, an aisle
    # is the gap between; "4 singles" four single cubes; "over on the left" is on the left;
    # "a 5-tower", "4-stacks" are towers of that height
    (re.compile(r"\bpallet[\s-]+(stacks?|loads?)\b", re.I),
     lambda m: "stacks" if m.group(0).lower().endswith("s") else "block"),
    (re.compile(r"(?<=\d)\s+pallets\s+(high|tall)\b", re.I), r" layers \1"),
    (re.compile(r"\b(?:an?\s+)?aisles?\s+(?:of\s+)?(\d+|one|two|three|a)\b\s*(cubes?|cm|mm)?(?:\s+wide)?",
                re.I),
     lambda m: f"a gap of {m.group(1)} {m.group(2) or 'cube'}"),
    (re.compile(r"\b(\d+|one|two|three|a)[- ](cubes?|cm|mm)\s+aisles?\b", re.I), r"\1 \2 gap"),
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)\s+singles\b", re.I),
     r"\1 single cubes"),
    # "two 2 by 2 blocks": structures of that footprint (a "block" counted is a part)
    (re.compile(r"\b(\d+|two|three|four|five|six)\s+((?:identical|matching|equal|similar)\s+)?"
                r"(\d+\s*(?:x|by)\s*\d+(?:\s*(?:x|by)\s*\d+)?)\s+blocks\b", re.I), r"\1 \2\3 pads"),
    # "a row of 4, a row of 4, the second row on top of the first": the two named, one put on
    # the other (a third row was built on the first)
    (re.compile(r"(?:[,;]\s*|\band\s+|^\s*-\s*|\n\s*-?\s*)(?:the\s+)?second\s+(" + _FAMILY_SAID
                + r")\s+(?:goes\s+|is\s+|sits\s+)?(?:(?:placed|set|stacked|laid|put)\s+)?"
                r"(?:directly\s+|right\s+|straight\s+)?(on\s+top\s+of|on|atop|above|behind|"
                r"in\s+front\s+of|next\s+to)"
                r"\s+the\s+first\b", re.I | re.M),
     lambda m: (f". then put the second {m.group(1)} {m.group(2)} the first"
                if len(re.findall(rf"\b{m.group(1)}s?\b", m.string[: m.start()], re.I)) >= 2
                else m.group(0))),
    # "a tower of 2 each side of it": on each side (the sizes went to the tower: partial)
    (re.compile(r"(?<![a-z])(?=(?:each|either)\s+side\s+of\s+(?:it|them|the\s+[a-z]+)\b)", re.I),
     lambda m: "on " if re.search(r"\b(?:\d+|" + _FAMILY_SAID + r")s?\s+$", m.string[: m.start()],
                                  re.I) else ""),
    # "NOT touching the front edge": away from it (read as the cubes not touching each other,
    # and the grid put at the front)
    (re.compile(r"\b(?:not|never|(?:do|does|must|should)\s*n[o']?t)\s+(?:be\s+)?(?:touching|touch|against|at|on)"
                r"\s+the\s+(front|back|left|right)\s+edge(?:\s+of\s+the\s+table)?\b", re.I),
     r"not at the \1"),
    # "6 steps, a single cube wide": one cube wide (a one-cube tower was built beside it)
    (re.compile(r"\b(?:a\s+)?single\s+(cube|block)\s+(wide|deep|thick|high|tall|long)\b", re.I),
     r"1 \1 \2"),
    # "2 stacks of 4, single cubes,": what they are made of, as every stack is
    (re.compile(r"(\b(?:stacks?|towers?|columns?|rows?|lines?)\s+of\s+(?:\d+|one|two|three|four|five|six|"
                r"seven|eight|nine|ten))\s*,\s*(?:all\s+)?single\s+cubes\b", re.I), r"\1"),
    # "a 150 mm cube made of cubes": a block that size each way (a row of 3 was built)
    (re.compile(r"\ban?\s+(\d+(?:\.\d+)?)\s*(mm|cm|m)\s+cube\b(?:\s+(?:made\s+)?(?:of|from|out\s+of)\s+"
                r"(?:small(?:er)?\s+)?cubes)?", re.I), _sized_cube),
    # "an enclosure 4 by 4 with each side 2 high": its walls 2 high (2 was read as a side)
    (re.compile(r"\b(?:each|every|all)\s+(?:of\s+its\s+|the\s+)?(?:sides?|walls?)\s+(?:is\s+|are\s+|being\s+)?"
                r"(\d+|one|two|three|four|five|six)\s+(?:cubes?\s+)?(high|tall)\b", re.I),
     r"\1 \2"),
    # "a fence round an empty square 5 by 5": a hollow square that size (the fence was a wall
    # of its own beside a slab)
    (re.compile(r"\b(?:an?\s+)?(?:fence|wall|walls|ring|border)\s+(?:all\s+)?(?:a?round|enclosing)\s+an?\s+"
                r"(?:empty|open|hollow|clear)\s+(?:square|rectangle|area|space|yard)\b", re.I),
     "a hollow square"),
    # "four towers at the corners of a square": in a square
    (re.compile(r"\b(?:at|on)\s+the\s+(?:four\s+)?corners\s+of\s+(?:a|an\s+imaginary)\s+square\b",
                re.I), "in a square"),
    # "a row of three 2-high towers": three towers in a row ("between neighbours": apart)
    (re.compile(r"\ba\s+(?:row|line)\s+of\s+(two|three|four|five|six|\d+)\s+((?:[\w-]+\s+)?(?:towers|"
                r"stacks|columns|pillars|pyramids|walls|blocks|arches|bridges))\b", re.I),
     r"\1 \2 in a row"),
    (re.compile(r"\b(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+(?:between|from)\s+(?:neighbours|neighbors|"
                r"neighbouring\s+ones|one\s+to\s+the\s+next)\b", re.I), r"\1 apart"),
    # "steps, 1, 2, 3 and 4 cubes high", "steps going up 1, 2, 3, 4 cubes": 4 steps
    (re.compile(r"\b(steps|stairs|staircase)((?:\s+(?:going|climbing|rising|that\s+go|up))*)\s*,?\s*1\s*,\s*2"
                r"\s*(?:,\s*3\s*)?(?:,\s*4\s*)?(?:,\s*5\s*)?(?:,\s*6\s*)?(?:,?\s*and|,)\s*([3-7])"
                r"(?:\s+cubes?)?(?:\s+(?:high|tall))?\b", re.I),
     lambda m: f"{m.group(1)} of {m.group(3)} steps{m.group(2)}"),
    # "a closed square of cubes, 5 by 5": a ring
    (re.compile(r"\b(?:closed|fenced|walled)\s+(square|rectangle)\b", re.I), r"hollow \1"),
    (re.compile(r"\b(square|rectangle)\s+closed\b", re.I), r"hollow \1"),  # "a square closed"
    # "a row of four cubes running up to a block", "a staircase climbed up to a tower": leading
    # up to it (no relation was read)
    (re.compile(r"\b(?:running|runs|ran|going|goes|went|climbing|climbs|climbed|rising|rises|rose|"
                r"stepping|steps|led|leads)\s+up\s+to\s+(?=(?:a|an|the)\s+(?!(?:back|front|left|right|"
                r"top|middle|centre|center|far|rear|height|level|total|max|maximum|size|number|few|"
                r"couple|dozen)\b))", re.I), "leading up to "),
    # "an L: one leg 4 cubes, the other 3 cubes": 4 by 3
    (re.compile(r"\bone\s+(?:leg|arm|side)\s+(?:is\s+|of\s+)?(\d+|two|three|four|five|six|seven)\s*(?:cubes?\s*)?"
                r"(?:long\s*)?,?\s*(?:and\s+)?the\s+other(?:\s+one)?\s+(?:is\s+|of\s+)?(\d+|two|three|four|five|"
                r"six|seven)(?:\s+cubes?)?(?:\s+long)?\b", re.I), r"\1 by \2"),
    # "two pyramids, a big one with a base of 5 and a small one with a base of 3": each named
    (re.compile(r"\b(?:two|2|both)\s+(" + _FAMILY_SAID + r")s\s*[:,]\s*(an?\s+[a-z]+\s+)one\b"
                r"([^.;!?]*?\band\s+)(an?\s+[a-z]+\s+)one\b", re.I),
     lambda m: f"{m.group(2)}{m.group(1)}{m.group(3)}{m.group(4)}{m.group(1)}"),
    # "layers from the bottom: 3x2, 3x2, 3x2": each layer on the one before
    (re.compile(r"\b(?:levels|layers|tiers)\s+(?:from\s+(?:the\s+)?bottom(?:\s+up)?|bottom\s+(?:to|up)(?:\s+(?:to\s+)?top)?)"
                r"\s*:\s*((?:\d+\s*(?:x|by)\s*\d+|(?:one|a\s+single|1)\s+cube)(?:\s*(?:,|and|,\s*and|then)\s*(?:\d+\s*(?:x|by)\s*\d+|"
                r"(?:one|a\s+single|1)\s+cube))+)", re.I),
     lambda m: " ".join(f"level {k + 1}: {size.strip()}." for k, size in enumerate(
         re.split(r"\s*(?:,\s*and|,|\band\b|\bthen\b)\s*", m.group(1))))),
    # "a wall, 1 cube thick, …": what every wall is (the 1 was read as its length)
    (re.compile(r"\s*,?\s*\b(?:one|1|a\s+single)\s+(?:cube|block|part)s?\s+(?:thick|deep)\b",
                re.I),
     lambda m: " " if re.search(r"\b(?:wall|walls|fence|row|line)\b", m.string, re.I)
     else m.group(0)),
    # "5 across from left to right", "2 deep from front to back": the side already says which
    # way (the direction turned the block: 5 ran front to back)
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes?\s+)?(across|wide)\s+"
                r"(?:from\s+)?(?:the\s+)?(?:left\s+to\s+(?:the\s+)?right|right\s+to\s+(?:the\s+)?left)\b",
                re.I), r"\1 \2"),
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes?\s+)?(deep)\s+"
                r"(?:from\s+)?(?:the\s+)?(?:front\s+to\s+(?:the\s+)?back|back\s+to\s+(?:the\s+)?front)\b",
                re.I), r"\1 \2"),
    # "from the front to the back": from front to back ('back' was left unused)
    (re.compile(r"\bfrom\s+the\s+(front|back|left|right)\s+to\s+the\s+(front|back|left|right)\b",
                re.I), r"from \1 to \2"),
    # "on the far side of it": behind it; "on the near side of it": in front of it
    (re.compile(r"\bon\s+the\s+far\s+side\s+of\b" + _NOT_THE_TABLE, re.I), "behind"),
    (re.compile(r"\bon\s+the\s+near\s+side\s+of\b" + _NOT_THE_TABLE, re.I), "in front of"),
    # "near the far edge": at the back (near was read as the near edge)
    (re.compile(r"\bnear\s+(?:to\s+)?the\s+far\s+(edge|side|end)\b", re.I), r"at the far \1"),
    # "a 2x2 pillar 5 blocks tall": a block that size (a slab beside a pillar)
    (re.compile(r"\b(?:an?\s+)?(\d+)\s*(?:x|by)\s*(\d+)\s+(?:pillar|column|tower|stack|post)\s+(?:of\s+)?(\d+)\s+"
                r"(?:cubes?\s+|blocks?\s+)?(?:tall|high)\b", re.I), r"a \1 by \2 by \3 block"),
    # "a box 3 wide, 2 deep, 2 tall, completely solid": what a block is ('solid' was a second)
    (re.compile(r"\s*,?\s*(?:and\s+)?(?:completely|totally|fully|entirely|all|100%)\s+(?:solid|filled(?:\s+in)?)\b",
                re.I),
     lambda m: " " if re.search(r"\b(?:box|block|brick|cuboid|slab|grid|pad|platform)\b",
                                m.string[: m.start()], re.I) else m.group(0)),
    # "a bridge over the river …, the river is 3 blocks wide", "the gap is 3 blocks wide": the
    # span under it (ignored as a word of no meaning, or read as a span of 1, silently)
    (re.compile(r"\b(?:the|a|an)\s+(?:gap|river|stream|road|canal|channel|ravine|moat|ditch|valley|"
                r"opening|space)\s+(?:(?:between\s+(?:them|the\s+\w+)|under\s+(?:it|the\s+\w+))\s+)?"
                r"(?:is\s+|being\s+|of\s+)?(" + _NUM + r")\s+(?:cubes?\s+|blocks?\s+|parts?\s+)?"
                r"(?:wide|across)\b", re.I),
     lambda m: m.group(0)
     if not re.search(r"\b(?:bridges?|arch(?:es)?|viaducts?|spans?)\b", m.string, re.I)
     else f"over a {m.group(1)}-block gap"),
    # "a castle!! with towers in the corners": an exclamation mid-sentence, not its end (the
    # towers were read as a structure of their own)
    (re.compile(r"(?<=\w)\s*!+(?=\s+[a-z])"), ""),
    # "a cube of 3x3x3 cubes, solid, centred": said of the block (read as a second block)
    (re.compile(r"\s*,\s*(?:and\s+)?(?:solid|filled(?:\s+in)?)\s*(?=[,.;]|$)", re.I),
     lambda m: " " if re.search(r"\b(?:box|block|brick|cuboid|slab|grid|pad|platform|cube|layer)\b",
                                m.string[: m.start()], re.I) else m.group(0)),
    # "a tower on its right, not on its left": the side said, the other ruled out
    (re.compile(r"(?<!\bnot\s)\b((?:on|to)\s+(?:its|the)\s+(left|right|front|back)(?:\s+side)?)\s*,?\s*"
                r"(?:and\s+|but\s+)?"
                r"not\s+(?:on\s+|to\s+)?(?:its|the)\s+(left|right|front|back)(?:\s+side)?\b", re.I),
     lambda m: m.group(1) if m.group(2).lower() != m.group(3).lower() else m.group(0)),
    # "L 4x2 front left": an L shape that size ("L" alone is left elsewhere)
    (re.compile(r"(?:^|(?<=[.;,]\s))L\s+(?=\d+\s*(?:x|by)\s*\d)"), "an L shape "),
    # "2 L shapes", "two T shapes": that many letter shapes (the capital read as 'long')
    (re.compile(r"\b([2-6])\s+(?=[LTU][\s-]+shape[sd]?\b)"),
     lambda m: ("two", "three", "four", "five", "six")[int(m.group(1)) - 2] + " "),
    # "an L shape with legs 5 and 3", "L, arms 4 & 4": its two arms, 5 by 3 (one read as a
    # length, the other as a tower); "a U, base 5, arms 3": 5 by 3
    (re.compile(r"\b(?:with\s+)?(?:a\s+|the\s+|its\s+)?base\s+(?:of\s+)?(\d+|two|three|four|five|six|"
                r"seven|eight)(?:\s+cubes?)?(?:\s+long)?\s*(?:,|;|and|&)\s*(?:(?:with\s+)?(?:its\s+|the\s+)?)"
                r"arms\s+(?:of\s+)?(\d+|two|three|four|five|six|seven|eight)\b(?:\s+cubes?)?(?:\s+long)?",
                re.I),
     lambda m: f"{m.group(1)} by {m.group(2)}" if _LETTER_BEFORE.search(m.string[: m.start()])
     else m.group(0)),
    (re.compile(r"\b(?:with\s+)?(?:(?:its|the)\s+)?(?:arms|legs|sides|wings)\s+(?:of\s+|are\s+)?"
                r"(\d+|two|three|four|five|six|seven|eight)\s*(?:cubes?\s+)?(?:long\s+)?(?:and|&|,)\s*"
                r"(\d+|two|three|four|five|six|seven|eight)\b(?!\s*(?:cubes?\s+)?(?:high|tall|deep|wide|"
                r"thick)\b)(?:\s+cubes?)?(?:\s+long)?", re.I),
     lambda m: f"{m.group(1)} by {m.group(2)}" if _LETTER_BEFORE.search(m.string[: m.start()])
     else m.group(0)),
    # "an L, 4 one way and 3 the other": 4 by 3; "a plus, 5 cubes across each way": 5 by 5
    (re.compile(r"\b(\d+|one|two|three|four|five|six|seven|eight)\s+(?:cubes?\s+)?(?:long\s+)?"
                r"(?:one\s+way|in\s+one\s+direction)\s*,?\s*(?:and\s+)?(\d+|one|two|three|four|five|six|"
                r"seven|eight)\s+(?:cubes?\s+)?(?:long\s+)?(?:the\s+other(?:\s+way)?|in\s+the\s+other"
                r"(?:\s+direction)?)\b", re.I), r"\1 by \2"),
    (re.compile(r"\b(\d+|three|four|five|six|seven|eight|nine)\s+(?:cubes?\s+)?(?:across\s+|long\s+|wide\s+)?"
                r"(?:each|both|either|every)\s+ways?\b", re.I), r"\1 by \1"),
    # a pyramid's "5x5 at the bottom", "the bottom layer has to be 4 by 4": its base ('bottom'
    # was left unused)
    (re.compile(r"(?<=\d)\s+(?:at|on)\s+the\s+bottom\b(?!\s+of)|\bthe\s+bottom(?:\s+(?:layer|level|"
                r"tier|row|course))?(?=\s+(?:has\s+to\s+be|must\s+be|should\s+be|is|of)\s+(?:\d|a\s+\d))",
                re.I),
     lambda m: ((" at the base" if m.group(0).lower().startswith(" ") else "the base")
                if re.search(r"\b(?:pyramid|ziggurat)s?\b", m.string, re.I)
                and not re.search(r"\b(?:top|middle|second|upper|next)\s+(?:layer|level|tier|"
                                  r"row)\b", m.string, re.I) else m.group(0))),
    # "bottom layer 4 by 4, then 3 by 3 on it": the first layer ('bottom' was left unused)
    (re.compile(r"^(\W*)(?:the\s+)?bottom\s+(layer|level|tier|course|row)\b(?!\s*[:=-])"
                r"(?!.*\b(?:top|middle|second|upper|next)\s+(?:(?:layer|level|tier|course|row)\b|"
                r"\d+\s*(?:x|by)\s*\d))",
                re.I),
     r"\1\2"),
    # "a 3 by 3 grid and, 10 cm behind it, a pyramid": the place said first, between commas
    (re.compile(r"\band\s*,\s*([^,.;]{2,40}?\b(?:it|them|its\s+(?:left|right)|their\s+(?:left|right)))"
                r"\s*,\s*(?=(?:an?|one|two|three|four|another|\d+)\b)", re.I), r"and \1 "),
    # "an arch with a tower in front of it": a tower of its own there (not the arch's pillar)
    (re.compile(r"\bwith\s+(?=(?:an?|one|two|three|four|\d+)\s+(?:(?!and\b|then\b)[\w-]+\s+){0,4}?"
                r"(?:in\s+front\s+of|"
                r"behind|beside|next\s+to|to\s+the\s+(?:left|right)\s+of|to\s+its\s+(?:left|right)|"
                r"on\s+its\s+(?:left|right))\s+it\b)", re.I), "and "),
    # "in front of it, one cube's width away": a cube apart (a cube was built there)
    (re.compile(r"\b(one|a|two|three|\d+)\s+(cube|block)s?['’]?s?\s+(?:width|widths|length)\s+"
                r"(?=away|apart|off|from|between)", re.I),
     lambda m: f"{m.group(1)} {m.group(2)}"
     + ("" if m.group(1).lower() in ("one", "a", "1") else "s") + " "),
    # "wall len 5 ht 3 with …" at a clause's start: the noun, not the verb "to wall"
    (re.compile(r"(^|[.;:]\s*)(wall|fence|ring|block|bridge)(?=\s+(?:len|lgth|ht|hgt|wid|dp)\b)",
                re.I), r"\1a \2"),
    # "a couple of layers of cubes, 3 by 3": two layers (one was built)
    (re.compile(r"\ba\s+couple\s+of\s+(?=(?:layers|levels|tiers|courses|storeys|steps|cubes|blocks)\b)",
                re.I), "two "),
    # "half a dozen cubes plus one": seven; "a row of ten cubes, all in one line": a row is one
    # line; "the racket from line 3": a production line's name; "the pallet's front edge": it
    (re.compile(r"\b(half\s+a\s+dozen|a\s+dozen|\d+|two|three|four|five|six|seven|eight|nine|ten)\s+"
                r"(cubes?\s+|blocks?\s+)?plus\s+(\d+|one|two|three|four|five)\b(?:\s+(?:more|extra))?",
                re.I), _plus),
    (re.compile(r"(\b(?:row|line|wall)\s+of\s+[^.;]*?)\s*,?\s*(?:all\s+)?in\s+(?:a|one)\s+(?:single\s+|straight\s+)?"
                r"line\b", re.I), r"\1"),
    (re.compile(r"\b(?:from|on|at|in)\s+(?:production\s+)?line\s+\d+\b", re.I), " "),
    # "and a tower of 5 in the middle of them": between them (built as a ring around a tower)
    (re.compile(r"\bin\s+the\s+(?:middle|centre|center)\s+of\s+(?:them|those|both(?:\s+of\s+them)?|"
                r"the\s+two(?:\s+\w+)?)\b", re.I), "between them"),
    (re.compile(r"\bin\s+between\b(?!\s+(?:them|the|those|these|both|two|it)\b)", re.I),
     "between them"),
    # "two towers of 3 with one of 5 between them": and one of 5 between them (a size of theirs)
    (re.compile(r"(\b(?:two|2)\s+(towers|stacks|columns|pillars)\b[^.;]*?)\s+with\s+(?:one|another)"
                r"(?:\s+(?:tower|stack|column|pillar))?(\s+(?:of\s+)?\w+(?:\s+(?:cubes?|high|tall))?\s+"
                r"between\s+them)\b", re.I),
     lambda m: f"{m.group(1)} and a {m.group(2)[:-1]}{m.group(3)}"),
    # "my son wants a tower", "the client would like …": a request made for someone, as one's own
    (re.compile(r"\b(?:my|our|the|his|her|their)\s+(?:little\s+|young\s+|eldest\s+|youngest\s+)?"
                r"(?:sons?|daughters?|kids?|child(?:ren)?|boys?|girls?|grandson|granddaughter|"
                r"grandkids|nephew|niece|little\s+one|boss|client|customer|supervisor|manager|"
                r"foreman|teacher|students)\s+(?:wants?|would\s+(?:like|love)|asked\s+for|needs?)\b",
                re.I), "I want"),
    (re.compile(r"(?:^|(?<=[.!?]\s))(?:she|he|they)\s+(?:wants?|would\s+like|needs?)\b", re.I),
     "I want"),
    # "make the one in the middle 2 taller": the middle one (its words were read as a place)
    (re.compile(r"\bthe\s+(one|tower|stack|column|pillar)\s+in\s+the\s+(middle|centre|center)\b"
                r"(?!\s+of\b)", re.I), r"the \2 \1"),
    # "on the wall's left end": on its end ("on it" placed the tower in the middle, silently)
    (re.compile(r"\bthe\s+(?:" + _FAMILY_SAID + r")'s\s+(left|right|front|back|rear)"
                r"(?:[\s-]+hand)?\s+end\b", re.I), r"its \1 end"),
    (re.compile(r"\bthe\s+(" + _FAMILY_SAID + r")'s\s+(?:front|back|rear|left|right|near|far)?\s*"
                r"(?:edge|side|face|end)\b", re.I), "it"),
    # "rising in -y", "do not rise toward +y": the side of the table that axis points to
    (re.compile(r"\b(climbing|climbs?|rising|rises?|ascending|ascends?|going\s+up|goes\s+up)\s+(?:in|along|"
                r"towards?|to)\s+(?:the\s+)?([+-])\s*([xy])\b", re.I),
     lambda m: f"{m.group(1)} to the " + {"+x": "back", "-x": "front", "+y": "left", "-y": "right"}[
         m.group(2) + m.group(3).lower()]),
    # "…, don't build anything": everything before taken back
    (re.compile(r"\b(?:(?:do\s+not|don'?t)\s+build\s+anything(?:\s+at\s+all)?|build\s+nothing)\b"
                r"(?!\s*(?:at|on|in|near|behind|to|there|here|left|right|front|back|beside|next|within|"
                r"inside|outside|around|between|under|over)\b)", re.I), "scratch all of that"),
    # "6 cubes by 4 cubes": 6 by 4; "a 2 stack", "the 4 stack", "3 tower": a stack of 2 …;
    # "none touching", "none in the front"; "on one pallet" (the structure is the pallet);
    # "two towers, 5 and 3 high": towers of 5 and 3
    (re.compile(r"\b(\d+)\s+cubes?\s+(by|x)\s+(\d+)\s+cubes?\b", re.I), r"\1 \2 \3"),
    (re.compile(r"(^|[.;:,]\s*|\b(?:a|an|the|one|each|every)\s+)([2-9]|10|two|three|four|five|six|seven|eight|"
                r"nine|ten)\s+(stack|tower|column)\b(?!\s*(?:of|with|s\b))", re.I), r"\1\3 of \2"),
    (re.compile(r"\bnone\s+(?:of\s+them\s+)?touching\b", re.I), "not touching"),
    (re.compile(r",\s*none\s+(?:of\s+them\s+)?(?=(?:in|at|on)\s+the\s+(?:front|back|left|right)\b)",
                re.I), ", not "),
    (re.compile(r"\s+(?:on|onto)\s+(?:one|a|the|a\s+single)\s+pallet\b(?!\s+of)", re.I), ""),
    (re.compile(r"\b(\d+|two|three|four|five|six)\s+(towers|stacks|columns|pillars),?\s+((?:\d+\s*,\s*)*\d+"
                r"\s*,?\s*and\s+\d+)\s+(?:cubes?\s+)?(?:high|tall)\b", re.I), r"\1 \2 of \3"),
    # "a little gap between each one": gaps; "each side of it, left and right": each side
    (re.compile(r"\b(gaps?|space|spacing)\s+between\s+(?:each\s+(?:one|cube|block|part|of\s+them)|them\s+all|"
                r"the\s+cubes)\b", re.I), r"\1"),
    (re.compile(r"(?<!\bon\s)\b(each|either|both)\s+(sides?)\s+of\s+(it|them)" + _BOTH_SIDES, re.I),
     r"on \1 \2 of \3"),
    (re.compile(r"(?<=\bon\s)(each|either|both)\s+(sides?)\s+of\s+(it|them)" + _BOTH_SIDES, re.I),
     r"\1 \2 of \3"),
    # "placed in that order from front to back": the order is the one they are named in
    (re.compile(r"\b(?:in\s+(?:that|this|the\s+same|the\s+given|the\s+listed)\s+order)\s*,?\s*"
                r"(?=(?:going\s+|running\s+)?(?:from\s+)?(?:the\s+)?(?:left|right|front|back)\s+to\b)",
                re.I), ""),
    # "Och, scrap that", "Oh, scratch that": the interjection does not hide the take-back
    (re.compile(r"\b(?:och|oh|ah|aw|ach|argh|ugh|hmm|um|er|right|ok|okay|naw|no)\s*[,!.-]?\s*"
                r"(?=(?:scrap|scratch|forget|cancel|strike|bin)\s+(?:that|it|this)\b)", re.I), ""),
    # "Scratch that - a row of six instead", "scrap that, make it a row": the take-back is a
    # clause of its own, so that it takes the step before back
    (re.compile(r"\b(scratch|scrap|cancel|bin|ditch)\s+(that|it|this)\s*(?:[-,:;—–]+|\s-\s)\s*"
                r"(?:just|only|instead|rather)?\s*(?=(?:an?|one|two|three|\d+)\s)", re.I),
     r"\1 \2. "),
    # "each leg 2 cubes tall": the legs that high
    (re.compile(r"\s*,?\s*\beach\s+(?:leg|post|pillar)\s+(?:is\s+|being\s+)?(\d+|one|two|three|four|five)\s+"
                r"(?:cubes?\s+)?(?:tall|high)\b", re.I), r" with legs \1 high"),
    # "then break the top 2 blocks", "break off the top cube": take them off (a row of 2 was laid
    # beside it)
    (re.compile(r"\bbreak\s+(?:off\s+)?(?=the\s+(?:top|upper)\s+(?:" + _NUM + r"\s+)?(?:cubes?|"
                r"blocks?|bricks?|levels?|layers?)\b)", re.I), "take off "),
    # "and then make it only four", "make it just 3": the size it becomes (the change was lost)
    (re.compile(r"\b(make|have)\s+(it|that|them)\s+(?:only|just|simply)\s+(?=" + _NUM + r"\b)",
                re.I), r"\1 \2 "),
    # "add one more cube to it at a time until it's 7 high": that high in the end (one was added)
    (re.compile(r"\b(?:keep\s+)?add(?:ing)?\s+(?:one\s+more\s+cube|one|a\s+cube|cubes|more\s+"
                r"cubes)(?:\s+(?:to|on(?:to)?)\s+(?:it|the\s+top))?(?:\s+(?:one\s+)?at\s+a\s+time)?\s+"
                r"until\s+it(?:'s|\s+is|\s+stands)\s+(" + _NUM
                + r")\s+(?:cubes?\s+)?(?:high|tall)\b", re.I),
     r"make it \1 high"),
    # "Carry on with it and finish it at 6", "take it up to 5 cubes": that high in the end (the
    # size was lost)
    (re.compile(r"\b(?:finish|complete|top\s+out|take|bring|grow)\s+(it|the\s+tower|that\s+one)\s+"
                r"(?:off\s+)?(?:up\s+)?(?:at|to)\s+(" + _NUM + r")(?:\s+(?:cubes?|blocks?))?"
                r"(?:\s+(?:high|tall))?(?=\s*(?:[.,;!]|$|and\b|then\b))", re.I),
     r"make \1 \2 high"),
    # "lose the top step", "knock off the top level": take it away
    (re.compile(r"\b(?:lose|ditch|drop|knock\s+off|take\s+off|get\s+rid\s+of)\s+(?=the\s+(?:top|last|highest|"
                r"upper)\s+(?:step|level|layer|tier|cube|course|row)\b)", re.I), "remove "),
    # "Wall 0.3m long x 0.1m high": the x between two sizes is "and", not a coordinate
    (re.compile(r"\b(long|high|tall|wide|deep|thick)\s+[x×]\s+(?=\d)", re.I), r"\1 and "),
    # "Two towers of 3. Then put a beam across the tops.": the towers carry the beam
    (re.compile(r"[.;]\s*(?:and\s+)?(?:then|next|after\s+that|finally),?\s+"
                r"(?=(?:put|lay|run|place|set|add|stick)\s+(?:a|the|one)\s+(?:\w+\s+)?beam\s+"
                r"(?:across|over|on))", re.I), ", then "),
    (re.compile(r"(?<=beam)\s+(?:across|over)\s+(?:the\s+)?tops(?:\s+of\s+them)?\b", re.I),
     " across them"),
    # "put a second course on it": a layer more
    (re.compile(r"\b(?:put|lay|place|stack|add)\s+(?:a|one|another)\s+(second|third|further|new|"
                r"extra|more)?\s*(?:course|layer|level|tier)\s+(?:on\s+top\s+of\s+it|on\s+it|"
                r"on\s+top)\b", re.I),
     r"add a \1 layer"),
    # "by the end of the day", "this afternoon": when, not what
    (re.compile(r",?\s*\b(?:by\s+(?:the\s+)?end\s+of\s+(?:the\s+)?(?:day|shift|week)|"
                r"(?:by|before|after)\s+(?:lunch|break|tonight|tomorrow)|"
                r"this\s+(?:morning|afternoon|evening))\b", re.I), " "),
    # "as long as it doesn't fall over": provided that (no length in it)
    (re.compile(r"\bas\s+long\s+as\s+(?=(?:it|they|there|nothing|it's)\s+(?:does|do|is|are|stays?|stands?|won't|doesn't|isn't|"
                r"can|will|holds?|fits?)\b)",
                re.I), "provided that "),
    # "the boss is coming round at three": a time, not a size
    (re.compile(r"\b((?:com(?:e|es|ing)|arriv(?:e|es|ing)|back|round|over|here|start(?:s|ing)?|"
                r"meeting|visit(?:s|ing)?|due|lunch|break|finish(?:es|ing)?|leav(?:e|es|ing))\s+)"
                r"at\s+(?:one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve|\d{1,2})\b"
                r"(?!\s*(?:cubes?|blocks?|high|tall|long|wide|levels?|steps?|mm|cm|m\b|x\b|by\b|[.,]\d))"
                r"(?![^.;]*\b(?:taller|higher|more|bigger)\b)",  # "starting at 2, each one taller"
                re.I), lambda m: m.group(0) if _series_start(m) else m.group(1)),
    # "the big boss", "a big day", "a little while": a size word of a person or a time
    (re.compile(r"\b(?:big|large|little|small|tall|huge|tiny|short)\s+(?=(?:boss|bosses|day|deal|guy|"
                r"girl|boy|man|woman|kid|kids|brother|sister|crowd|fan|thanks|question|favou?r|"
                r"problem|news|moment|event|show|hurry|rush|while|bit\s+of\s+(?:time|a\s+rush)|"
                r"meeting|visit|customer|client|audience)\b)", re.I), ""),
    # "right across the middle", "right in the centre": "right" as "exactly", not a side
    (re.compile(r"(?<!\bthe\s)(?<!\bits\s)(?<!\bthe\sfar\s)\bright\s+(?=(?:across|through|along|over)\s+the\s+(?:middle|centre|center|table)\b|"
                r"in\s+the\s+(?:middle|centre|center)\b|at\s+the\s+(?:very\s+)?(?:front|back|middle|"
                r"centre|center)\b|next\s+to\b|beside\b|behind\b|in\s+front\s+of\b|"
                r"against\b)", re.I), ""),
    # "blk 2x2x2. Twr 3H on top of blk": the block named before (a work order drops "the")
    (re.compile(r"\b(on\s+top\s+of|onto|atop|beside|next\s+to|behind|in\s+front\s+of)\s+(?=(?:"
                + _FAMILY_SAID + r")\b(?!\s*(?:of|\d)))", re.I),
     lambda m: m.group(0) + ("the " if re.search(
         r"\b" + re.escape(m.string[m.end():].split()[0].rstrip(",.;:").lower()) + r"\b",
         m.string[: m.start()], re.I) else "")),
    # "towers of 2, 4 and 6 behind each other": one behind the other (they stood across at the
    # back, silently)
    (re.compile(r"\b(?:placed\s+|standing\s+|set\s+)?behind\s+(?:each\s+other|one\s+another)\b",
                re.I), ", one behind the other"),
    # "a 4x4 floor. now build walls around the edge of it 2 high": a ring standing on its rim
    # (a wall was built beside it)
    (re.compile(r"\b(?:an?\s+)?(?:walls?|low\s+walls?|rim|border|edging)\s+(?:all\s+)?(?:a)?round\s+"
                r"the\s+(?:outer\s+)?(?:edges?|rim|border|outside)\s+of\s+(it|that|the\s+(?:floor|slab|"
                r"base|platform|grid|plate|block))\b", re.I), r"a ring on top of \1"),
    # "pyramid centre within 8 cm of the table centre": in the centre (a second pyramid 8 cm
    # long was built)
    (re.compile(r"\b(?:(?:its|the)\s+)?(?:centre|center|middle)\s+(?:is\s+|lies\s+|sits\s+)?within\s+"
                r"\d+(?:\.\d+)?\s*(?:cm|mm|m)\s+of\s+the\s+(?:table(?:'s)?\s+|workspace(?:'s)?\s+)?"
                r"(?:centre|center|middle)\b", re.I), "in the centre"),
    # "three towers, the middle one the tallest", "and the midle one is the bigest": with the
    # tallest one in the middle (read as towers one high in the centre, silently)
    (re.compile(r"(?:,\s*|\s+and\s+)(?:with\s+)?the\s+(middle|centre|center|left|right|front|back)"
                r"(?:[\s-]?hand)?(?:\s+one)?\s+(?:is\s+|being\s+|should\s+be\s+|must\s+be\s+)?the\s+"
                r"(tallest|highest|biggest|largest|shortest|smallest|lowest)\b(?:\s+one)?", re.I),
     lambda m: (f" with the {m.group(2)} one "
                + ("in the middle" if m.group(1).lower() in ("middle", "centre", "center")
                   else f"on the {m.group(1).lower()}"))),
    # "Put the small tower before the big tower": in front of it, as "vor" says (dropped)
    (re.compile(r"\b((?:put|place|set|stand|position)\b[^.;,:]*?)\bbefore\s+(?=(?:the|a|an|it|"
                r"them)\b(?![^.;,:]*\b(?:is|are|gets|goes|has\s+been)\b))", re.I),
     r"\1in front of "),
    # "two walls, the one behind the other": one of them behind the other (read as a wall one
    # long, silently)
    (re.compile(r"\bthe\s+one\s+(?=(?:behind|in\s+front\s+of|on\s+top\s+of|next\s+to|beside|"
                r"on|above)\s+the\s+other\b)", re.I), "one "),
    # "towers of 2, 4 and 6 one behind the other": a list of three or more, in a line front to
    # back (they stood on a 2 by 2 grid, silently)
    (re.compile(r"\b((?:towers|stacks|columns|pillars|piles)\s+of\s+(?:\d+\s*,\s*)+\d+\s*,?\s*and\s+"
                r"\d+(?:\s+(?:cubes|high|tall))?)\s*,?\s*\bone\s+behind\s+(?:the\s+other|another)\b",
                re.I),
     r"\1 in a line front to back"),
    # "three walls, each 3 long, one behind the other": more than two in a line front to back
    # (towers and blocks; rows and walls so placed stand side to side, not end to end)
    (re.compile(r"(?<!\bof\s)(?<!\bx\s)(?<!\bby\s)\b((?:three|four|five|six|[3-6])\s+"
                r"(?:\d+\s*(?:x|by)\s*\d+\s+|[a-wyz-]+\s+)?(?:towers|stacks|columns|pillars|"
                r"blocks|pyramids|cubes)\b[^.;]{0,40}?),?\s*\bone\s+behind\s+(?:the\s+other|another)\b",
                re.I), r"\1 in a line front to back"),
    # "a second row of 5 on top of it": the ordinal is the order said, nothing more (unread)
    (re.compile(r"\b(an?)\s+(?:second|third|fourth|fifth)\s+(?=(?:row|course|layer)\s+of\s+\d+\s+on\s+"
                r"top\b)", re.I), "a "),
    # "two towers of 3 with a cube on top of each", "three towers, each with a cube on top"
    (re.compile(r"\s*,?\s*\b(?:(?:each|all)\s+with\s+(?:a|one)\s+(?:single\s+|more\s+|extra\s+)?"
                r"(?:cube|block)\s+on\s+(?:top|it)\b|with\s+(?:a|one)\s+(?:single\s+|more\s+|extra\s+)?"
                r"(?:cube|block)\s+on\s+(?:top\s+of\s+)?(?:each|every|both|all)"
                r"(?:\s+(?:one|of\s+them|tower|stack))?\b)", re.I),
     lambda m: (", then put a cube on top of each ; "
                if _named_last(m.string[: m.start()]) == "tower" else m.group(0))),
    # "lay a row of 4 cubes, then put a cube on top of each one": a second course
    (re.compile(r"\b(?:put|place|stack|set|add)\s+(?:a|one)\s+(?:more\s+|extra\s+)?(?:cube|block)\s+on\s+"
                r"(?:top\s+of\s+)?(?:each|every)(?:\s+(?:one|cube|block|of\s+them))?\b"
                r"(?![^.;,]*\b(?:ends?|sides?|corners?|edges?)\b)", re.I),
     lambda m: "add one more layer" if _named_last(m.string[: m.start()]) in ("row", "grid", "wall")
     else m.group(0)),
    # "a row of 5 and, on top of its middle cube, a tower of 2": the tower, then where it stands
    (re.compile(r"\b(and|then)\s*,?\s*((?:up)?on\s+(?:(?:the\s+)?top\s+of\s+)?(?:it|its\s+(?:\w+[\s-]+)?"
                r"(?:cube|block|end|middle|centre|center|corner))|on\s+top)\s*,\s*(an?\s+[^.;?,]+)",
                re.I),
     r"\1 \3 \2"),
    # "a tower of 3 on top of the middle cube of the row": on the middle of the row
    (re.compile(r"\bon\s+(?:top\s+of\s+)?the\s+(?:middle|centre|center)\s+(?:cube|one|block|brick|part)\s+"
                r"of\s+(?:the|that|this)\s+(row|wall|line|slab|platform)\b", re.I),
     r"on the middle of the \1"),
    # "an arch and a tower of 2 to its right": a structure of its own, not the arch's pillar
    (re.compile(r"\b((?:(?:an?|the)\s+)?(?:[\w-]+\s+){0,3}?(?:bridge|arch|archway|table|canopy|gate|pavilion|"
                r"shelter|castle|fort)(?:e?s)?\b[^.;]*?)\s+and\s+((?:then\s+)?(?:(?:put|place|set|add|build|stack)\s+)?(?:an?|one)\s+"
                r"(?:tower|stack|column|pillar|cube)\b[^.;]{0,30}?\b(?:next\s+to\s+(?:it|them)|"
                r"beside\s+(?:it|them)|behind\s+(?:it|them)|in\s+front\s+of\s+(?:it|them)|"
                r"to\s+(?:the\s+)?(?:left|right)\s+of\s+(?:it|them)|to\s+(?:its|their)\s+(?:left|right)|"
                r"on\s+(?:top\s+of\s+)?it|onto\s+it|near\s+(?:it|them)|on\s+top(?=\s*(?:$|[.,;!]))|"
                r"(?:to|on)\s+the\s+(?:left|right)(?:\s+side)?(?=\s*(?:$|[.,;!]))))\b",
                re.I), r"\1; and \2"),
    # "a tower two cubes shorter than 6": the size it comes to
    (re.compile(r"\b(\d+|one|two|three|four|five)\s+(?:cubes?\s+|levels?\s+|parts?\s+)?(shorter|lower|taller|"
                r"higher|longer)\s+than\s+(\d+|two|three|four|five|six|seven|eight|nine|ten)\b"
                r"(?!\s*(?:cm|mm|m|x|by)\b|\s+(?:cubes?\s+)?(?:high|tall|long)\b)", re.I),
     _than),
    # "make a 3 by 3 slab on the left, actually the other side": moved to the opposite side
    (re.compile(r"\s*,?\s*\b(?:actually|no|sorry|wait|or\s+rather)\b\s*,?\s*(?:(?:put\s+it|make\s+it|"
                r"build\s+it)\s+)?(?:on|at|to)?\s*the\s+other\s+(?:side|end)\b", re.I),
     _other_side),
    # "two towers of 3, the left one and the right one": one on each side
    (re.compile(r"\b(two|2)\s+([a-z]+s(?:\s+of\s+\d+)?)\s*,\s*the\s+(left|front)(?:[\s-]hand)?\s+one\s+and\s+"
                r"the\s+(right|back)(?:[\s-]hand)?\s+one\b", re.I),
     r"\1 \2, one on the \3 and one on the \4"),
    # "two rows of 5 cubes, put the second one on top of the first": stacked
    (re.compile(r"\s*,?\s*(?:and\s+)?(?:then\s+)?(?:put|stack|place|set)\s+the\s+second(?:\s+one)?\s+on\s+"
                r"(?:top\s+of\s+)?the\s+first(?:\s+one)?\b", re.I), " stacked"),
    # "three slabs 2x2, stacked": the size after the noun
    (re.compile(r"\b(two|three|four|five|[2-5])\s+(slabs|layers|grids|pads|plates|platforms|squares)\s+"
                r"(\d+\s*(?:x|by)\s*\d+)\s*,?\s*(?=stacked\b|on\s+top\s+of\s+each\s+other\b)",
                re.I),
     r"\1 \3 \2 "),
    # "make the pillars taller, 3 cubes each": the pillars that high
    (re.compile(r"\b(make\s+(?:the|its|both)\s+(?:corner\s+)?(?:pillars|legs|posts|towers|turrets))\s+"
                r"(?:taller|higher)\s*[,:(-]?\s*(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes?\s+)?"
                r"(?:each|high|tall)\b\)?", re.I), r"\1 \2 high"),
    # "stairs 4 going up right": the way they climb, not the right of the table
    (re.compile(r"\b(?:(?:going|goes|climbing|climbs|rising|rises|ascending|stepping)\s+up|climbing|climbs|"
                r"rising|rises|ascending)\s+(left|right)\b(?!\s+(?:to|of|corner|side|end|half|edge|hand)\b)",
                re.I), r"going up to the \1"),
    # "pyramid base 3, centre 0.5, 0.3": centred there
    (re.compile(r"\b(?:centred|centered|centre|center)\s+(?:at\s+|on\s+)?\(?\s*(\d*\.\d+|\d+(?:\.\d+)?)\s*(mm|cm|m)?"
                r"\s*,\s*(\d*\.\d+|\d+(?:\.\d+)?)\s*(mm|cm|m)?\s*\)?", re.I),
     lambda m: f" at x = {m.group(1)}{m.group(2) or ''}, y = {m.group(3)}{m.group(4) or ''} "),
    # "row of 5, tower 3 on the left end": on its end, not the left of the table
    (re.compile(r"\bon\s+(?:top\s+of\s+)?the\s+(left|right|front|back|far|near)\s+end\b"
                r"(?:\s+of\s+(?:it|the\s+(?:row|wall|line|slab)))?", re.I), r"on its \1 end"),
    # "then a row of 5 in front, 1 cube gap": in front of it, that far
    (re.compile(r"\b(in\s+front|behind|to\s+the\s+(?:left|right))(?=\s*,?\s*(?:with\s+)?(?:an?\s+)?(?:\d+|one|two|"
                r"three|a)\s*(?:cubes?|cm|mm)\s+(?:gap|apart|away)\b)", re.I), r"\1 of it"),
    # "a 2-cube tower on top of its middle", "a row along the middle of it": on it, centred
    (re.compile(r"\b(?:on\s+top\s+of\s+its|on\s+its|along\s+(?:the\s+)?(?:middle|centre|center)\s+of)\s+"
                r"(?:(?:middle|centre|center)\b(?!\s+(?:cube|one|block|brick|part|column|row|step))|(?=it\b))"
                r"(?:\s*it\b)?", re.I), "on the middle of it"),
    # "a square slab with 5 cubes along each edge": that many on each side
    (re.compile(r"\b((?:slab|grid|layer|square|platform|pad)\s+)with\s+(\d+|two|three|four|five|six|seven|"
                r"eight)\s+(?:cubes?\s+)?along\s+(?:each|every)\s+(?:edge|side)\b", re.I),
     r"\1with \2 on each side"),
    # "a block 3 layers high with 4 cubes in each layer": a square of that many
    (re.compile(r"\bwith\s+(4|9|16|four|nine|sixteen)\s+(?:cubes?\s+)?(?:in|per|on)\s+(?:each|every)\s+"
                r"(?:layer|level)\b", re.I),
     _square_of),
    # "60 cm out", "600mm out": that far out from the robot
    (re.compile(r"\b(?:at\s+)?(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+out\b(?!\s+(?:of|from)\b)", re.I),
     r" \1 from the robot "),
    # "5 cm off the front edge", "10 cm in from the left edge": from it
    (re.compile(r"\b(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+(?:off|in\s+from|in\s+off|inside|away\s+from)\s+the\s+"
                r"(front|back|left|right)\s+edge\b", re.I), r"\1 from the \2 edge"),
    # "a pyramid with a square base 15 cm across": its base (a square is no second structure),
    # and the pyramid a square one (it was built flat, one cube deep)
    (re.compile(r"\b(pyramid|ziggurat)(\b[^.;]{0,30}?\bwith\s+(?:a|its)\s+)square\s+(base|bottom|"
                r"footprint)\s+of\s+(\d+)(?!\s*(?:cubes?|parts?|blocks?)?\s+in\b)", re.I),
     r"\1\2\4 by \4 \3"),  # "with a square base of 4": 4 on a side
    (re.compile(r"(?<!square\s)\b(pyramid|ziggurat)(\b[^.;]{0,30}?\bwith\s+(?:a|its)\s+)square\s+"
                r"(base|bottom|footprint)\b", re.I), r"square \1\2\3"),
    # "a stack where every layer is a 2 by 2 square, five layers in all": that footprint
    (re.compile(r"\s*,?\s*\b(?:where|in\s+which|with)\s+(?:every|each)\s+(?:layer|level)\s+(?:is|being)\s+"
                r"(?:an?\s+)?(\d+\s*(?:x|by)\s*\d+)(?:\s+(?:square|slab|grid|layer))?", re.I),
     r" \1"),
    # "with a base 15 cm across": a square base that wide
    (re.compile(r"\b(base|bottom)\s+(\d+(?:\.\d+)?\s*(?:cm|mm|m))\s+(?:across|wide|square)\b",
                re.I), r"\1 of \2"),
    # "a wall with a tower of 4 beside each end": one at each end
    (re.compile(r"\b(?:beside|next\s+to|by|against)\s+(each|both|either)\s+(end|ends)\b", re.I),
     r"at \1 end"),
    # "a hollow square 4 by 4 with walls 2 high and towers of 4 at the corners": a castle
    (re.compile(r"\b(?:ring|enclosure|pen|hollow\s+square|square\s+ring)\b([^.;]*?)\bwith\s+"
                r"((?:[^.;]*?\s+and\s+)?)(?:taller\s+|tall\s+)?towers\s+(?:of\s+(\d+)|(\d+)\s+(?:cubes?\s+)?"
                r"(?:high|tall))\s+(?:at|on|in)\s+(?:the|its|all\s+(?:four|4)|each\s+of\s+the|every|"
                r"all\s+the)\s+(?:four\s+)?corners?\b", re.I),
     lambda m: f"castle{m.group(1)} with {m.group(2)}corner towers {m.group(3) or m.group(4)} "
               "high"),
    # "a castle 6x6, walls 2 high, corners 4 high", "castle 5x5 walls 2 corners 4": its corner
    # towers and its walls (the corners were dropped, a bare "walls 2" read as a second thing)
    (re.compile(r"\b(castles?|forts?|fortress)\b([^.;]*?)\bcorners?\s+(?:(?:are|is|of|at|ht|height)\s+)?"
                r"(\d+|two|three|four|five|six|seven|eight)(?:\s+cubes?)?(?:\s+(?:high|tall))?\b"
                r"(?!\s*(?:x|by|cm|mm|m)\b)", re.I),
     r"\1\2corner towers \3 high"),
    (re.compile(r"\b(castles?|forts?|fortress)\b([^.;]*?)\bwalls?\s+(?:(?:are|is|of|ht|height)\s+)?"
                r"(\d+|one|two|three|four|five|six)(?:\s+cubes?)?\b(?!\s*(?:x|by|long|wide|across|"
                r"deep|thick|cm|mm|m|cubes?\s+(?:long|wide))\b)(?:\s+(?:high|tall)\b)?", re.I),
     r"\1\2walls \3 high"),
    # "take the top row off": the particle before what is taken
    (re.compile(r"\b(take|knock|pull|lift)\s+(the\s+(?:\w+\s+){0,2}?(?:row|layer|course|level|cube|cubes|"
                r"step|top))\s+(off|away|out)\b(?=\s*(?:$|[.,;!]|\band\b|\bthen\b))", re.I),
     r"\1 \3 \2"),
    # "make three 3x3 slabs and put them on top of each other": stacked
    (re.compile(r"\s*,?\s*\b(?:and\s+|then\s+)*(?:put|stack|place|set|pile|lay)\s+them\s+(?:all\s+)?"
                r"(on\s+top\s+of\s+(?:each\s+other|one\s+another))", re.I), r" stacked \1"),
    # "a wall of 5, then one more row on top": a course more of the wall, not a row of one
    (re.compile(r"\b(?:(?:put|lay|place|stack|add)\s+)?(?:one\s+more|another|an\s+extra)\s+(?:row|course)"
                r"\s+(?:on\s+top(?:\s+of\s+(?:it|that))?|on\s+it)(?=\s*(?:[.;,!]|$|\band\b|\bthen\b))",
                re.I),
     lambda m: " add one more layer " if _named_last(m.string[: m.start()]) in ("wall", "row")
     else m.group(0)),
    # "Row 1: Wall, L=5 … Row 2: same wall", "Line 3: Tower": a line of a list, not a row
    (re.compile(r"(?:^|(?<=[.;|\n]))\s*(?:row|line|item|entry|pos(?:ition)?|no\.?|#)\s*\d{1,2}\s*[:)]\s+",
                re.I), " "),
    # "a 4-high tower and a 2-high one": one of the family named before, that size
    (re.compile(r"(?<!\bof\s)(?<!\bthan\s)(?<!\bas\s)\b(an?|another|one\s+more)\s+((?:\d+|two|three|four|"
                r"five|six|seven|eight|nine|ten)[- ](?:high|tall|long|wide|cubes?|blocks?|steps?|"
                r"levels?|"
                r"layers?|stor(?:e?y|eys|ies)))\s+"
                r"one\b(?!\s+(?:of|cube|block)\b)", re.I),
     lambda m: (lambda fam: f"{m.group(1)} {m.group(2)} {fam}" if fam else m.group(0))(
         next((w for w in reversed(re.findall(r"[a-z]+", m.string[: m.start()].lower()))
               if w in _SHAPE_NOUNS), None))),
    # "called back and changed it", "I'll get back to you", "come back later": no place
    (re.compile(r"\b((?:call|called|calling|ring|rang|phone|phoned|text|texted|e-?mail|e-?mailed|write|wrote|"
                r"get|gets|got|getting|come|comes|came|coming|go|goes|went|going|report|reported|hear|heard|"
                r"be|been|check|checking|hold|held|step|stepped)\s+)back\b(?=\s*(?:$|[,.;!?]|to\b|later\b|"
                r"soon\b|in\s+a\b|with\b|after\b|and\b|tomorrow\b|then\b))", re.I), r"\1"),
    # "4 I think. yes 4.", "I guess 7? seven's fine": a number said again to confirm it
    (re.compile(r"(?<=[.?!])\s*(?:yes|yeah|yep|ok|okay|right)\s*,?\s*(?:\d+|one|two|three|four|five|six|"
                r"seven|eight|nine|ten)\s*(?=[.!]|$)", re.I), " "),
    (re.compile(r"(?<=[.?!,])\s*(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?:'s|\s+is)\s+"
                r"(?:fine|good|ok|okay|right|it)\b\s*(?=[.!,]|$)", re.I), " "),
    # "then they'd like one more layer on it": add one
    (re.compile(r"\b(?:(?:i|we|they|he|she|you|customer|client)\s*(?:'d|would)\s+(?:also\s+)?like|"
                r"(?:i|we|they)\s+(?:also\s+)?(?:want|need)|(?:he|she|it)\s+(?:also\s+)?(?:wants|needs))\s+"
                r"(?=(?:one\s+more|another|an\s+extra|(?:\d+|two|three)\s+more)\s+(?:layer|level|course|tier|"
                r"cube|block|step|row)s?\b)", re.I), "add "),
    # "a tower between two rows of three": two rows, one on each side (not a 3 by 2 floor)
    (re.compile(r"\b(between\s+)(?:two|2)\s+(?:row|line)s\s+of\s+(\d+|two|three|four|five|six|seven|"
                r"eight|nine|ten)(?:\s+(?:cubes|blocks|bricks))?(?:\s+each)?\b", re.I),
     r"\1a row of \2 and another row of \2"),
    # "six cubes, two rows of 3, a cube apart": the total said first, then how (the 6 went to a
    # row)
    (re.compile(r"\b(\d+|four|six|eight|nine|ten|twelve)\s+(?:cubes|blocks|bricks)\s*[,:]\s*((two|three|four|"
                r"[2-4])\s+(?:rows|lines|towers|stacks|columns|piles)\s+of\s+(\d+|two|three|four|five|six))\b",
                re.I), _total_first),
    # "two rows of six, parallel, with one cube between them", "two rows of three side by side
    # one cube apart": separate rows, not one floor
    (re.compile(r"(?<!\bin\s)(?<!\binto\s)(?<!\bas\s)"  # not "six towers in two rows of three"
                r"\b(two|three|2|3)\s+(rows|lines|walls)\s+of\s+(\d+|two|three|four|five|six|seven|eight|nine|"
                r"ten)(?:\s+(?:cubes|blocks|bricks))?(?:\s+each)?(?=(?:(?!\b(?:and|then|tower|stack|column|pyramid|stair|bridge|arch|slab|ring|block|"
                r"castle)\b)[^.;])*\b(?:apart|gap|spaced|separated)\b|"
                r"(?![^.;]*\bside\s+by\s+side\b)[^.;]*\b(?:parallel|between\s+them)\b)"
                r"(?![^.;]*\b(?:one\s+behind|in\s+front|end\s+to\s+end)\b)", re.I),
     _rows_apart),
    # "two towers of three and one tower of five", "two of 3 and one of 5": one more structure
    # (not "two towers, one of 3 and one of 5", which names each of them)
    (re.compile(r"(?<=\d|[a-z])(\s*,?\s+and\s+)one\s+(?=(?:tower|stack|column|pillar|wall|row|pyramid|"
                r"staircase|bridge|arch|slab|ring|castle)s?\b)", re.I),
     lambda m: m.group(0) if _ONE_OF_EACH.search(m.string[: m.start()]) else f"{m.group(1)}a "),
    (re.compile(r"(?<=\d|[a-z])(\s*,?\s+and\s+)one\s+(?=(?:of|with)\s+(?:\d|one|two|three|four|five|six|"
                r"seven|eight|nine|ten)\b)", re.I),
     lambda m: m.group(0) if _ONE_OF_EACH.search(m.string[: m.start()])
     else f"{m.group(1)}another "),
    # "a pyramid, 3 levels, top level a single cube": the pyramid's own top, said again (not a
    # cube of its own beside it)
    (re.compile(r"(\bpyramid\b[^.;?!]*?)\s*,?\s*(?:with\s+|and\s+)?(?:the\s+|its\s+|a\s+)?(?:top|peak|apex|"
                r"summit)(?:\s+(?:level|layer|row|tier|course))?\s*(?:is\s+|of\s+|being\s+|=\s*|:\s*)?"
                r"(?:just\s+|only\s+)?(?:a\s+single|one\s+single|a|one|1)\s+(?:single\s+)?(?:cube|block|brick)\b"
                r"(?!\s+(?:on|above|high|tall|tower|stack|column))", re.I), r"\1"),
    # "Row of 4 cubes. Add 4 more to the same row.": that row (not a second one the same)
    (re.compile(r"\b((?:add|put|stack|place|pile)\b[^.;]*?\b(?:to|onto|on|into)\s+the)\s+same\s+"
                r"(?=(?:row|tower|stack|column|pile|wall|line)\b)", re.I), r"\1 "),
    # "a 1-cube, a 2-cube and a 3-cube column": the noun said last is every one's
    (re.compile(r"\b(an?\s+[\w]+-(?:cubes?|high|tall|levels?|storeys?))\s*,\s*(?:(an?\s+[\w]+-(?:cubes?|high|tall|"
                r"levels?|storeys?))\s*,?\s+)?(?:and\s+)?(an?\s+[\w]+-(?:cubes?|high|tall|levels?|storeys?))\s+"
                r"(tower|column|stack|pillar|post|plinth)s?\b", re.I),
     lambda m: ", ".join(f"{a} {m.group(4)}" for a in m.group(1, 2) if a)
     + f" and {m.group(3)} {m.group(4)}"),
    # "a block against the back of the room": the room the cell stands in, its back the table's
    # (not a room built around it), unless a room was built before ("a 5 by 5 room, then a
    # tower at the back of the room")
    (re.compile(r"\b((?:at|in|on|to|against|toward|towards|along)\s+the\s+(?:back|front|rear|far|near|left|"
                r"right|middle|centre|center)(?:[\s-](?:left|right))?(?:\s+(?:side|end|corner|edge))?)\s+of\s+"
                r"the\s+(room|chamber|hall|lab|workshop|shop|studio|gallery|lot|plot|site|yard)\b",
                re.I),
     lambda m: m.group(0) if re.search(rf"\b{m.group(2)}\b", m.string[: m.start()], re.I)
     else m.group(1)),
    # "Kids love a pyramid - make one with four layers": the one named, sized (not a pyramid
    # one cube wide)
    (re.compile(r"\b((?:make|build|do|give\s+me|stack|put\s+up)\s+)one(?=\s+with\b)", re.I),
     lambda m: f"{m.group(1)}it" if families_said(m.string[: m.start()]) else m.group(0)),
    # "a row of seven, straight across from left to right": along the way said (across from was
    # read as facing: front to back)
    (re.compile(r"\b(?:straight\s+)?across\s+(?=from\s+(?:the\s+)?(?:left|right)\b)", re.I), ""),
    # "Amendment: height shall be 2": the size as a requirement states it
    (re.compile(r"\b((?:the\s+|its\s+)?(?:height|length|width|depth)\s+)(?:shall|should|must|will|needs\s+to|"
                r"has\s+to)\s+be\s+(?=(?:\d|one|two|three|four|five|six|seven|eight|nine|ten)\b)",
                re.I),
     r"\1is "),
    # "Two walls - four long, two high - one behind the other": the sizes set off by dashes
    # are the structures' own (as with commas)
    (re.compile(r"\b([a-z]+s(?:\s+in\s+a\s+(?:row|line))?)\s+[-—–]+\s+((?:[^-—–.;?!]{0,40}?\b)?(?:\d+|one|two|"
                r"three|four|five|six|seven|eight|nine|ten)\s+(?:cubes?\s+)?(?:high|tall|long|wide|deep)\b"
                r"[^-—–.;?!]{0,30}?)\s+[-—–]+\s+", re.I), r"\1, \2, "),
    # "sorry, my notes say two high actually": what the speaker reads out is the size
    (re.compile(r"\b(?:my|the|our)\s+(?:notes|sheet|drawing|spec|plan|list|paper)\s+(?:says?|said)\s+",
                re.I),
     ""),
    # "separated by a clear gap of exactly 3 cubes": the gap, exactly as said
    (re.compile(r"\b((?:gap|space|distance|spacing|clearance)\s+of\s+)(?:exactly|precisely|just)\s+",
                re.I),
     r"\1"),
    # "The leftmost one gets 3 more cubes.": more added to the one on the left
    (re.compile(r"\b(left|right|front|back)[\s-]?most\b", re.I), r"\1"),
    (re.compile(r"\b(the\s+[a-z]+\s+(?:one|tower|stack|column|pillar|post))\s+(?:gets|receives)\s+((?:\d+|one|two|"
                r"three|four|five|six|a|an)\s+(?:more|extra|additional)\s+(?:cubes?|blocks?|levels?|layers?))\b",
                re.I), r"add \2 to \1"),
    # "wherever there's room on the bench": anywhere (no room to build)
    (re.compile(r",?\s*\b(?:wherever|anywhere|where(?:ver)?\s+you\s+like)\s+there(?:'s|\s+is)\s+(?:enough\s+|some\s+)?"
                r"(?:room|space)(?:\s+(?:on|at)\s+the\s+\w+)?", re.I), " "),
    # "a castle for the medieval room": what it is for (no room built beside it)
    (re.compile(r"\s+for\s+(?:the|a|our|my)\s+(?:[a-z]+\s+)?(?:room|hall|gallery|display)\b", re.I),
     " "),
    # "at the heart of a 6 by 6 enclosure": in its middle
    (re.compile(r"\b(?:at|in)\s+the\s+(?:heart|very\s+centre|very\s+center|dead\s+centre|dead\s+center)\s+of\b",
                re.I), "in the middle of"),
    # "one at each of the four corners of the table": one in each corner
    (re.compile(r"\b(?:at|in|on)\s+each\s+of\s+the\s+(?:four\s+|4\s+)?corners\s+of\s+the\s+(table|workspace|cell)\b",
                re.I), r"in each corner of the \1"),
    # "a column in the middle of a 6 by 6 enclosure - the enclosure frames it": said again
    (re.compile(r"\s*[-—–,;]\s*the\s+([a-z]+)\s+(?:frames|surrounds|encloses|encircles|rings|holds|contains)\s+"
                r"(?:it|them)\b", re.I),
     lambda m: " " if re.search(rf"\b{m.group(1)}\b", m.string[: m.start()], re.I)
     and re.search(r"\b(?:inside|middle|centre|center|around|surround(?:ed|ing)?)\b",
                   m.string[: m.start()], re.I)
     else m.group(0)),
    # "a tower of four as its next-door neighbour": next to it
    (re.compile(r"\b(?:as\s+)?(?:its|their|the)\s+next[\s-]door\s+neighbou?r\b", re.I),
     "next to it"),
    # "A terrace of four towers": four towers in a row (not a staircase)
    (re.compile(r"\b(?:an?\s+)?terrace\s+of\s+(?=(?:\d+|two|three|four|five|six)\s+(?:towers|stacks|columns|"
                r"blocks|houses)\b)", re.I), ""),
    # "Boundary wall, nine long …, running along the left side": a wall along that side
    (re.compile(r"\b(?:boundary|perimeter)\s+(?=(?:wall|fence)\b[^.;]*\b(?:along|running|runs)\b)",
                re.I), ""),
    # "a wall … parked straight behind it": set there
    (re.compile(r"\bparked\b(?=\s+(?:straight\s+|right\s+|just\s+)?(?:behind|in\s+front|next|beside|on|at|to)\b)",
                re.I), "placed"),
    # "a tower of 4 and a wall 3 long …, wall on the left": the wall named (a second wall was
    # built there)
    (re.compile(r"(?<=[,;]\s)(tower|wall|row|slab|block|pyramid|staircase|stairs|column|bridge|ring|"
                r"arch)\s+(?=(?:on|at|to|in)\s+the\s+(?:left|right|front|back|middle|centre|center)\b)",
                re.I),
     lambda m: f"the {m.group(1)} " if set(families_said(m.group(1)))
     <= set(families_said(m.string[: m.start()])) else m.group(0)),
    # "three 2x2 blocks, 1, 2 and 3 high": one block of each height (the heights were read
    # as their lengths, silently)
    (re.compile(r"\b(two|three|four|[2-4])\s+(\d+)\s*(?:x|by)\s*(\d+)\s+(?:blocks|slabs|squares|pads)\s*,?\s+"
                r"(?:(?:of\s+|with\s+)?heights?\s+)?(\d+)(?:\s*,\s*(\d+))?(?:\s*,\s*(\d+))?\s*,?\s+and\s+(\d+)"
                r"(?:\s+(?:cubes?\s+)?(?:high|tall|layers?|levels?))?\b", re.I),
     _blocks_listed),
    # "three walls 4 long 2 high, one behind the other": all in one line front to back (only the
    # third was set behind the first)
    # (walls and rows parallel, one behind another: claimed and kept as `parallel`)
    (re.compile(r"(?<!\bx\s)(?<!\bby\s)(?<![x×*])(\b(?:three|four|five|six|[3-6])\s+(?:[a-z]+\s+)?("
                + _FAMILY_SAID
                + r")s\b[^.;]*?)\s*,?\s*\bone\s+behind\s+(?:the\s+other|another)\b", re.I),
     lambda m: m.group(1) + (", one behind another" if m.group(2).lower() in ("wall", "row", "line")
                             else ", in a line front to back")),
    # "two towers of 4 that touch": touching
    (re.compile(r"\b(?:that|which)\s+(?:touch|are\s+touching|touch\s+each\s+other)\b", re.I),
     "touching"),
    # "a 5 high tower with a 2 high one touching it": a second one of that family, that high
    (re.compile(r"\b(with|and)\s+an?\s+((?:\d+|two|three|four|five|six|seven|eight|nine|ten)[\s-](?:high|tall))"
                r"\s+one\b", re.I),
     lambda m: f"{m.group(1)} a {fams[-1]} {m.group(2)}"
     if (fams := [f for f in families_said(m.string[: m.start()])
                  if f in ("tower", "wall", "pyramid")])
     else m.group(0)),
    # "tower of 7 please. hmm thats too tall, do 5": make it 5
    (re.compile(r"\bthats\b", re.I), "that's"),
    (re.compile(r"(\btoo\s+(?:tall|high|big|long|short|small|low|much|many)\s*[,.!]?\s*)do\s+(?=\d|one\b|two\b|"
                r"three\b|four\b|five\b|six\b|seven\b|eight\b|nine\b|ten\b)", re.I), r"\1make it "),
    # "two parallel walls 4 long": two walls, parallel (one wall was built)
    (re.compile(r"\b(two|three|2|3)\s+parallel\s+(walls|rows|lines)\b", re.I), r"\1 \2, parallel,"),
    # "then remove half of it": halve it
    (re.compile(r"\b(?:remove|take\s+(?:away|off))\s+half\s+of\s+(it|them)\b|\btake\s+half\s+of\s+(it|them)\s+"
                r"(?:away|off)\b", re.I), lambda m: f"halve {m.group(1) or m.group(2)}"),
    # "with a 2 high one touching it on the right": on its right, against it
    (re.compile(r"\btouching\s+(it|them)\s+(?:on|at|to)\s+(?:the|its|their)\s+(left|right|front|back)"
                r"(?:[\s-]hand)?(?:\s+side)?\b", re.I),
     lambda m: {"front": f"in front of {m.group(1)}", "back": f"behind {m.group(1)}"}.get(
         m.group(2).lower(), f"to the {m.group(2).lower()} of {m.group(1)}") + ", touching"),
    # "a 4-step staircase and a tower of 3. The staircase on the left, the tower on the right.":
    # the places of the ones named, said in a sentence of their own (two more were built)
    # ("Rebuild those two, stairs on the left, tower on the right, …" likewise)
    (re.compile(r"[.;]\s+(?:(?:re)?(?:build|make|do)\s+(?:those|these|them|both)(?:\s+(?:two|three))?"
                r"\s*,\s*)?(?=(?:the\s+)?(?:" + _FAMILY_SAID + r")s?\s+(?:on|at|to|in)\s+the\s+\w+"
                r"(?:[\s-]\w+)?"
                r"(?:\s*,\s*(?:and\s+)?(?:the\s+)?(?:" + _FAMILY_SAID + r")s?\s+(?:on|at|to|in)\s+"
                r"the\s+\w+"
                r"(?:[\s-]\w+)?)+\s*(?:[.!,]|$))", re.I), ", "),
    # "and a little way from the slab a wall", "a tower a little to its left": near it, on
    # that side (a failure; "another a little" read as a structure)
    (re.compile(r"\ba\s+(?:little|short|small)\s+way\s+(?:away\s+)?from\s+", re.I), "near "),
    (re.compile(r"\ba\s+(?:little|bit|tad)\s+(?=to\s+(?:its|the)\s+(?:left|right)\b|in\s+front\b|behind\b)",
                re.I), ""),
    # "then put a copy of it at the back", "do the same at the back left and back right":
    # another one there (ignored: no structure named)
    (re.compile(r"\b(put|place|make|build|add)\s+(?:a|an)\s+(?:copy|duplicate|replica|twin)\s+of\s+(?:it|that)\b",
                re.I), r"\1 another one"),
    (re.compile(r"\bdo\s+(?:the\s+)?same(?:\s+thing)?\s+((?:at|on|in)\s+the\s+" + _A_PLACE + r")"
                r"(?:\s*,?\s+and\s+(?:(?:at|on|in)\s+)?(?:the\s+)?(" + _A_PLACE + r"))?", re.I),
     lambda m: f"another one {m.group(1)}"
     + (f" and another one at the {m.group(2)}" if m.group(2) else "")),
    # "first a 4x4 slab, next a 3x3 on it, next a 2x2": then (said in turn)
    (re.compile(r"(?<=[,;]\s)next\s+(?=(?:an?|one|\d+)\s)", re.I), "then "),
    # "first a 4x4 slab, next a 3x3 on it, next a 2x2, and finish with one cube": the last of
    # the levels stacked in turn goes on top too (the cube was left out)
    (re.compile(r"\b(then\s+(?:an?|one)\s+(?:single\s+)?(?:cube|block|brick))\b(?=\s*(?:[.;!]|$))",
                re.I),
     lambda m: f"{m.group(1)} on top"
     if re.search(r"\bon\s+(?:it|top)\b", m.string[: m.start()], re.I) else m.group(0)),
    # "take 2 off the tall one and put them on the short one": two changes (the second was
    # dropped, silently)
    (re.compile(r"\b((?:take|knock|lift|remove)\s+(\d+|one|two|three|four|five)\s+(?:cubes?\s+)?(?:off|from)\s+"
                r"the\s+\w+\s+(?:one|tower|stack|column))\s*,?\s+and\s+(?:then\s+)?(?:put|stack|place|add|set)\s+"
                r"(?:them|those)\s+(?:on(?:to)?|to)\s+(?:the\s+top\s+of\s+)?(the\s+\w+\s+(?:one|tower|stack|"
                r"column))\b", re.I), r"\1. then add \2 cubes to \3"),
    # "3 pyramids of 2 levels in a row": the levels theirs, the row how they stand (a default
    # row was built)
    (re.compile(r"\b(\d+|one|two|three|four|five|six)\s+(levels?|layers?|steps?|tiers?|storeys?)\s+(?=in\s+a\s+"
                r"(?:row|line)\b)", re.I), r"\1 \2, "),
    # "a lone column, seven cubes tall": one column ('lone' was left unused)
    (re.compile(r"\b(an?|one)\s+(?:lone|solitary|lonely)\s+(?=(?:column|tower|pillar|post|stack|wall|pyramid)\b)",
                re.I), r"\1 "),
    # "Line up five towers of two, a cube apart": five towers in a line
    # "Line up four 3-high towers with two-cube gaps and bump …": the towers' words, then the line
    (re.compile(r"\bline\s+up\s+((?:\d+|two|three|four|five|six|seven|eight)\s+(?:[\w-]+\s+){0,2}?[a-z]+s\b"
                r"[^,.;]*?)(?=\s*(?:[,.;]|$|\s(?:and|then)\s+(?!a\b)))", re.I), r"\1 in a line"),
    # "two towers of 6 with a wall between them, 4 long 2 high": the sizes the wall's (they
    # were read as the towers')
    (re.compile(r"\b(an?\s+(?:wall|row|block|slab|pyramid|staircase))\s+(between\s+them)\s*,\s*((?:\d+|two|three|"
                r"four|five|six)\s+(?:long|high|tall|wide|deep)(?:\s*,?\s*(?:and\s+)?(?:\d+|two|three|four|five|"
                r"six)\s+(?:long|high|tall|wide|deep)){0,2})", re.I), r"\1 \3 \2"),
    # "and an identical bridge 2 cubes to the right of it": another bridge the same
    (re.compile(r"\b(?:an?\s+)(?:identical|matching)\s+(?=(?:bridge|tower|wall|row|block|slab|pyramid|staircase|"
                r"arch|ring|castle)\b)", re.I), "another "),
    # "…, all touching": touching (it was dropped, silently)
    # (not "4 rows of 4 cubes, all touching": one floor)
    (re.compile(r"\b(?:all|both|each)\s+(?:of\s+them\s+)?(?=touching\b)", re.I),
     lambda m: m.group(0)
     if re.search(r"\b(?:rows|lines)\s+of\b|\bcubes\b", m.string[: m.start()], re.I) else ""),
    # "an L shape, arms four long": both arms that long (the other was 2)
    (re.compile(r"(?<!\bboth\s)(?<!\beach\s)(?<!\btwo\s)\barms\s+(?=(?:\d+|one|two|three|four|five|six|seven|"
                r"eight)\s+(?:cubes?\s+)?long\b)", re.I),
     lambda m: "both arms " if re.search(r"(?-i:\bL\b)|\bl[\s-]shape", m.string[: m.start()], re.I)
     else m.group(0)),
    # "right, er, could I get an L shape …": a word to start with, not the right-hand side
    (re.compile(r"^\s*right\s*[,!]\s*(?:(?:er|erm|um|uh|so|then)\s*,?\s*)?(?=\S)", re.I), ""),
    # "three pens, one high: 3 by 3, 4 by 4 and 3 by 4": the shared size after the list (all
    # three were built 3 by 4)
    (re.compile(r"\b((?:two|three|four|[2-4])\s+[a-z]+s)\s*,\s*((?:\d+|one|two|three|four|five)\s+(?:cubes?\s+)?"
                r"(?:high|tall))\s*:\s*([^.;:]+?)(?=\s*(?:[.;]|$))", re.I), r"\1: \3, all \2"),
    # "on the far side of the table from the robot": at the back (read as where the speaker
    # stands, across from the robot)
    (re.compile(r"\b(?:on|at|to)\s+the\s+(far|near)\s+side\s+of\s+the\s+(?:table|workspace|cell|bench)\s+from\s+"
                r"the\s+robot\b", re.I),
     lambda m: m.group(0)  # "I'm on the far side of the table from the robot": the speaker
     if re.search(r"\b(?:i'?m|i\s+am|we'?re|we\s+are|stand(?:s|ing)?|sit(?:s|ting)?|am|is|are)\s*$",
                  m.string[: m.start()], re.I)
     else "at the back" if m.group(1).lower() == "far" else "at the front"),
    # "a table with legs 2 high and, underneath it, a single cube": the cube under it (it was
    # set on top, silently)
    (re.compile(r"\b(and\s*,?\s*)(underneath|beneath|under|below)\s+(it|them|the\s+\w+)\s*,?\s*((?:an?|one)\s+"
                r"(?:single\s+)?[\w-]+(?:\s+[\w-]+)?)(?=\s*(?:[.;,]|$))", re.I), r"\1\4 \2 \3"),
    # "a castle with a pillar right in the middle of its courtyard": in its middle (the pillar
    # was dropped, silently)
    (re.compile(r"\b(?:right\s+)?in\s+the\s+(?:middle|centre|center)\s+of\s+(?:its|the)\s+(?:courtyard|yard|court|"
                r"inside|interior|inner\s+space)\b", re.I), "in the middle"),
    # "one tower of 2, and one tower of one more than that": of 3 (a third tower was built)
    (re.compile(r"\bof\s+(one|two|three|four|\d+)\s+(more|fewer|less)\s+than\s+(?:that|the\s+first(?:\s+one)?)\b",
                re.I), _more_than_that),
    # "make the middle one 6 and the two outside ones 2": two changes, each its own
    (re.compile(r"\b(make\s+the\s+[a-z]+\s+(?:one|ones|tower|towers)\s+(?:\d+|[a-z]+)(?:\s+(?:high|tall))?)\s*,?\s+"
                r"and\s+(?=the\s+)", re.I), r"\1. then make "),
    # "a stack of five, and then one more on top": one more cube on it
    (re.compile(r",?\s*\b(?:and\s+)?then\s+one\s+more\s+on\s+top\b(?!\s+of\b)", re.I),
     lambda m: ", then add one more cube on top"
     if (families_said(m.string[: m.start()]) or ["row"])[-1] == "tower" else m.group(0)),
    # "a tower of 5 on the left. and the same on the right.": another one there
    (re.compile(r"(?<!\bone\s)\b(?:and\s+)?the\s+same\s+(?:one\s+|again\s+)?((?:on|at|in)\s+the\s+"
                + _A_PLACE + r")\b", re.I),
     lambda m: f"another one {m.group(1)}" if families_said(m.string[: m.start()])
     else m.group(0)),
    # "a pillar 2 cubes wide and 2 deep, 3 high": a block that wide and deep (a tower one
    # cube across, the width ignored)
    (re.compile(r"\b(?:an?\s+)?(?:pillar|column|tower|post|stack)\s+(\d+|two|three|four)\s+"
                r"(?:cubes?\s+)?wide\s*(?:,|and|by|x)?\s*(\d+|two|three|four)\s+(?:cubes?\s+)?deep\b",
                re.I),
     r"a \1 by \2 block"),
    # "hang on, make it 6 by 4": a correction said as a pause
    (re.compile(r"\bhang\s+on\b", re.I), "wait"),
    # "one of those long beams laid across the top": a beam across the top
    (re.compile(r"\bone\s+of\s+(?:those|these|the|your|them)\s+(?:(?:long|big|heavy|large)\s+)?"
                r"(beam|plank|bar)s\b", re.I), r"a \1"),
    (re.compile(r"\b(?:long|big|heavy|large)\s+(?=(?:beam|plank)s?\b)", re.I), ""),
    (re.compile(r"\b(?:laid|placed|set|sitting|resting|lying|going|running|laying)\s+(?=(?:across|over)\s+"
                r"(?:the\s+)?(?:top|tops|them|both|it)\b(?!\s+of\b))", re.I), ""),
    # "a little bridge — two towers of two with a beam across the top": the bridge, described
    (re.compile(r"\b(?:an?\s+)?(?:(?:little|small|simple|basic|nice|big)\s+)?(?:bridge|gate|gateway|arch)\s*"
                r"(?:[—–(]|\s-)\s*(?=(?:two|2)\s+(?:towers|stacks)\b[^.?!]*\b(?:beams?|bar|lintel)\s+"
                r"(?:\w+\s+)?(?:across|over)\b)", re.I), ""),
    # "An arch for the entrance: two posts two cubes high, … with a beam across": posts and a
    # beam on them, as said (an arch's corbels made the posts a level higher, silently)
    (re.compile(r"^\s*(?:an?\s+)?(?:(?:little|small|simple|basic|nice|big)\s+)?(?:gate|gateway|arch)"
                r"(?:\s+for\s+(?:the\s+|an?\s+)?[a-z]+)?\s*(?:[—–(:]|\s-)\s*(?=(?:two|2)\s+(?:towers|stacks|"
                r"posts|pillars|columns|uprights)\b[^.?!]*\bwith\s+(?:an?\s+|one\s+)?(?:beams?|bar|lintel)\s+"
                r"(?:\w+\s+)?(?:across|over)\b)", re.I), ""),
    # "a flat rectangle, two rows of six": the rectangle's own size, said after it
    (re.compile(r"\b(rectangle|square|slab|grid|floor|pad|platform|plate|mat|patch|block)\s*[,:—–-]\s*"
                r"(?:in\s+)?(two|three|four|five|six|[2-6])\s+rows\s+of\s+(two|three|four|five|six|seven|"
                r"eight|nine|ten|\d+)\b(?!\s+(?:cubes?\s+)?(?:each\s+)?(?:high|tall|layers?|levels?))",
                re.I),
     r"\1 of \2 rows of \3"),
    # "my grandson and his two sisters", "the 3 visitors": people counted, not parts
    (re.compile(r"\b(?:\d+|two|three|four|five|six|seven|eight|nine|ten|twelve|twenty)\s+(?=(?:sisters|brothers|"
                r"kids|children|grandchildren|grandsons|granddaughters|sons|daughters|friends|colleagues|guests|"
                r"visitors|people|persons|customers|clients|students|pupils|operators|engineers|managers|"
                r"girls|boys|men|women|adults|parents|families|apprentices|trainees|staff)\b)",
                re.I), ""),
    # "a tower of three in each back corner": the back left and the back right corner
    (re.compile(r"\b((?:an?|one)\s+[^,.;]{1,40}?)\s+(?:in|at|on)\s+(?:each|both|either)\s+(?:of\s+the\s+)?"
                r"(back|front|left|right)(?:[\s-]hand)?\s+corners?\b(?!\s+of\s+(?:it|the\s+(?!table)))",
                re.I),
     lambda m: " and ".join(f"{m.group(1)} in the {c} corner"
                            for c in _CORNERS_OF[m.group(2).lower()])),
    # "after that the same at the back left": another one there
    (re.compile(r"(?<=\b(?:then|that|next|also)\s)(?<!\bone\s)the\s+same(?:\s+(?:thing|one|again))?\s+"
                r"(?=(?:at|on|in)\s+the\s+(?:(?:far|back|front)\s+)?(?:front|back|left|right)\b)"
                r"|(?<=\bfinally\s)the\s+same\s+(?=(?:at|on|in)\s+the\s+(?:front|back|left|right)\b)"
                r"|(?<=\bthen\s)same\s+(?=(?:at|on|in)\s+(?:the\s+)?(?:front|back|left|right|[LR])\b)",
                re.I), "another one "),
    # "a single cube on its top step": on its top (a staircase's top is its top step)
    (re.compile(r"\bon\s+(?:its|the|their)\s+(?:top|highest|last|uppermost)\s+(?:step|stair|tread)\b",
                re.I), "on top of it"),
    # "a tower of 2 cubes more": of 2 cubes ("more" after a size said with "of")
    (re.compile(r"\b(of\s+(?:\d+|two|three|four|five|six)\s+(?:cubes?|blocks?|bricks?))\s+more\b",
                re.I), r"\1"),
    # "it would block my view": no block
    (re.compile(r"\b(would|will|could|might|may|to|'d|'ll|it)\s+block\s+(?=(?:my|the|our|his|her|their|your)\s+"
                r"(?:view|line|way|access|path|sight|reach)\b)", re.I), r"\1 obstruct "),
    # "four towers of three, one in each corner of the table": a tower of three in each corner
    (re.compile(r"\b(?:four|4)\s+(towers|stacks|columns|pillars|cubes|blocks)(\s+(?:of\s+)?[\w-]+(?:\s+(?:high|tall|"
                r"cubes?))?)?\s*,?\s*(?:with\s+)?one\s+(?:in|at|on)\s+each\s+corner\s+of\s+the\s+"
                r"(table|workspace|cell)\b", re.I),
     lambda m: f"a {m.group(1)[:-1]}{m.group(2) or ''} in each corner of the {m.group(3)}"),
    # "two columns of five, one in each back corner": one in the back left and one in the back
    # right corner (the second was a single cube, silently)
    (re.compile(r"\b(?:two|2|both)\s+(?P<adj>[a-z]+\s+)??(towers|stacks|columns|pillars|posts|cubes|blocks|"
                r"pyramids)(\s+(?:of\s+)?"
                r"[\w-]+(?:\s+(?:high|tall|cubes?))?)?\s*,?\s*(?:with\s+)?one\s+(?:in|at|on)\s+(?:each|either|"
                r"both)\s+(?:of\s+the\s+)?(back|front|rear|far|near|left|right)(?:[\s-]+hand)?\s+corners?\b"
                r"(?:\s+of\s+the\s+(?:table|workspace|cell))?", re.I),
     lambda m: " and ".join(
         f"a {m.group('adj') or ''}{m.group(2)[:-1]}{m.group(3) or ''} in the {corner} corner"
         for corner in _CORNERS_OF[m.group(4).lower()])),
    # "two walls facing each other": parallel, one behind the other
    (re.compile(r"\b(walls|rows|lines)((?:\s+(?:of\s+)?(?:\d+|two|three|four|five|six|seven|eight)"
                r"(?:\s+(?:cubes?|long|high))?)?)\s+facing\s+each\s+other\b", re.I),
     r"\1\2 parallel to each other"),
    # "a solid cube of cubes, 15 cm each way": that size along every side
    (re.compile(r"\b(\d+(?:\.\d+)?\s*(?:cm|mm|m)|(?:\d+|two|three|four|five)\s+cubes?)\s+(?:each\s+way|every\s+way|"
                r"in\s+(?:each|every)\s+direction|all\s+(?:round|around|ways))\b", re.I),
     r"\1 long, \1 wide and \1 high"),
    # "two towers, both 4 high": the size of each ("both" is no count of parts); "four towers in
    # a row each two high": theirs, not the row's (a wall 2 high was built beside them)
    (re.compile(r"(?:(?<=\brow\s)|(?<=\bline\s)|(?<=\bside\s)|(?<=\bapart\s)|(?<=\bother\s))"
                r"(?:both|all|each)(?:\s+one)?\s+(?=(?:\d+|one|two|three|"
                r"four|five|six|seven|eight|nine|ten)\s*(?:cubes?\s+)?(?:high|tall|long|wide|deep|"
                r"levels?|layers?|steps?)\b)", re.I), ", "),
    (re.compile(r"\b(?:both|all|each)\s+(?=(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)\s*"
                r"(?:cubes?\s+)?(?:high|tall|long|wide|deep|levels?|layers?|steps?)\b)", re.I), ""),
    # "a ring 4x4, 2 high, with 1 cube, centred inside": a column of cubes in its middle
    (re.compile(r"\b((?:ring|enclosure|pen|frame|fence|square\s+ring|hollow\s+square)\b[^.;]*?),?\s*with\s+"
                r"(one|a|a\s+single|single|1)\s+cube\s*,?\s*(?:centred|centered|placed|standing|"
                r"sitting)?\s*(?:right\s+)?(?:inside(?:\s+it)?|in\s+(?:the\s+)?(?:middle|centre|center)(?:\s+of\s+it)?)"
                r"\b", re.I),
     lambda m: f"{m.group(1)} and a tower of 1 in the middle of it"),
    # "a wall, a tower of 3 behind it and a tower of 2 in front of it": both "it"s the wall
    (_BOTH_IT, lambda m: m.group(0) if m.group("prev").lower() in (
        m.group("fam1").lower(), m.group("fam2").lower())
     else f"{m.group('prev')}{m.group('head')}{m.group('mid')}the {m.group('prev')}"),
    # "a wall 4 long with a tower of 3 at the left end": against its left end
    (re.compile(r"(?<!\btower\s)(?<!\bone\s)(?<!\bstack\s)(?<!\bcube\s)"
                r"\b(?:at|against)\s+(?:the|its)\s+(left|right)(?:[\s-]+hand)?\s+end\b"
                r"(?!\s+of\s+the\s+(?:table|workspace|bench|cell|row\s+of\s+(?:towers|stacks)))"
                r"(?:\s+of\s+(?:it|the\s+(?:wall|row|line|fence|slab)))?", re.I),
     lambda m: m.group(0) if _TABLE_ENDS.search(m.string)
     # "… against the right end of a wall five long": of the wall named next
     else f"right against the {m.group(1).lower()}"
     if re.match(r"\s+of\s+(?:an?|one)\b", m.string[m.end() :], re.I)
     else f"to the {m.group(1).lower()} of it, touching"),
    # "stack 4 cubes on the left and 2 on the right": a stack on each side
    (re.compile(r"\b(?:stack|pile|put)\s+(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes|blocks|bricks)\s+"
                r"((?:on|at|in)\s+the\s+(?:left|right|front|back|middle|centre|center)(?:\s+(?:left|right))?)"
                r"\s*,?\s+and\s+(\d+|two|three|four|five|six|seven|eight)\s+"
                r"((?:on|at|in)\s+the\s+(?:left|right|front|back|middle|centre|center)(?:\s+(?:left|right))?)\b",
                re.I), r"a tower of \1 \2 and a tower of \3 \4"),
    # "stack 3 cubes, then stack 2 more next to it": a stack of 2 beside it
    (re.compile(r"\b(stack|put|place|add|set)\s+(\d+|two|three|four|five|six)\s+more(?:\s+(?:cubes|blocks))?\s*,?\s+"
                r"(?=(?:right\s+)?(?:next\s+to|beside|behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|"
                r"alongside|(?:to|on)\s+its\s+(?:left|right))\b)", re.I), r"\1 a stack of \2 "),
    # "a tower of 5 touching its left side": against it on that side
    (re.compile(r"\btouching\s+its\s+(left|right|front|back)(?:[\s-]+hand)?(?:\s+(?:side|end|face))?\b",
                re.I),
     lambda m: {"front": "in front of it, touching", "back": "behind it, touching"}.get(
         m.group(1).lower(), f"to the {m.group(1).lower()} of it, touching")),
    # "cap the top step with one more cube": a cube on top of it
    (re.compile(r"\bcap\s+(?:the\s+top(?:\s+(?:step|level|one))?|it|the\s+\w+)\s+(?:off\s+)?with\s+(?:one\s+more|"
                r"a|one|another|a\s+single|an\s+extra)\s+cube\b", re.I), "put a cube on top of it"),
    # "build it up to 2x2x4": to that height
    (re.compile(r"\b((?:build|make|raise|grow|stack)\s+it\s+up\s+to)\s+\d+\s*[x×]\s*\d+\s*[x×]\s*(\d+)\b",
                re.I), r"\1 \2 high"),
    # "the other taller by 2": two taller
    (re.compile(r"\b(taller|higher|shorter|lower|longer|wider)\s+by\s+(\d+|one|two|three|four|five|a)"
                r"(?:\s+(?:cubes?|levels?|blocks?))?\b", re.I), r"\2 cubes \1"),
    # "don't make it go front to back", "don't run it left to right": not that way
    (re.compile(r"\b(?:do\s+not|don'?t|never)\s+(?:make\s+it\s+|have\s+it\s+|let\s+it\s+)?(?:go|run|point|"
                r"extend|stretch|lay\s+it|build\s+it|put\s+it)\s+(?:it\s+)?(?:from\s+)?(?:the\s+)?(front|back|left|"
                r"right)\s+to\s+(?:the\s+)?(front|back|left|right)\b", re.I), r"not \1 to \2"),
    # "a low fence down the left side": along it
    (re.compile(r"\b(?:down|up)\s+(?=the\s+(?:left|right|front|back)(?:[\s-]+hand)?\s+(?:side|edge)\b)",
                re.I), "along "),
    # "a set of steps", "a flight of stairs": a staircase
    (re.compile(r"\b(?:set|flight)\s+of\s+(?:steps|stairs)\b", re.I), "staircase"),
    # "a pair of gateposts": posts
    (re.compile(r"\bgate[\s-]?posts\b", re.I), "posts"),
    (re.compile(r"\bgate[\s-]?post\b", re.I), "post"),
    # thinking aloud: "I guess", "I suppose", "not sure", "yeah, let's do that"
    (re.compile(r",?\s*\b(?:i\s+(?:guess|suppose|reckon|believe)|(?:i'?m\s+)?not\s+(?:really\s+)?sure"
                r"(?:\s+but)?|i\s+think(?=\s+(?:a|an|the|two|three|four|five|\d|it|we|maybe)\b)|"
                r"(?:yeah|yes|ok|okay)\s*,?\s*let'?s\s+(?:do|go\s+with)\s+(?:that|it|this))\b\s*,?",
                re.I), " "),
    # "a 3 by 3 by 3 block, I mean made out of cubes": what it is made of, said again
    (re.compile(r",?\s*\b(?:i\s+mean\s+)?(?:made|built)\s+(?:up\s+)?(?:out\s+)?of\s+(?:single\s+|the\s+|"
                r"small\s+)?(?:cubes|blocks|bricks)\b(?=\s*(?:$|[,.;!?]))", re.I), " "),
    # "Loc: back left", "Loc back left": a location field
    (re.compile(r"\bloc(?:ation)?\s*[:=]?\s+(?=(?:the\s+)?(?:front|back|left|right|centre|center|"
                r"middle)\b)", re.I), "at the "),
    # "um right let me think", "right, so": "right" as a word to begin, no side
    (re.compile(r"(?:^|(?<=[.!?]\s))\W*(?:(?:um+|uh+|er+|ok(?:ay)?|so|yeah)\W+)*right\b\s*,?\s*"
                r"(?=(?:so|then|let|ok(?:ay)?|now|um+|uh+|here|listen|well|guys|team|folks|stick|pop|put|"
                r"place|build|make|chuck|whack|bung|knock|give|can|could|we|i|you)\b)",
                re.I), " "),
    # "the mess on the bench", "in the middle of the bench": the workbench is the table
    (re.compile(r"\b(on|at|off|across|along|of|from|clear)\s+the\s+(?:(?:work\s*)?bench|(?:building\s+)?site)"
                r"\b(?!\s+(?:with|of)\b)", re.I), r"\1 the table"),
    # "two towers of three one in the front left corner and one in the back right corner"
    (re.compile(r"\b(of\s+(?:\d+|two|three|four|five|six))\s+(one\s+(?:in|at|on)\s+the\b)", re.I),
     r"\1, \2"),
    # "pls build it before 6", "until 3 pm": a time of day
    (re.compile(r"\b(?:before|after|until|till|til)\s+(?:\d{1,2}(?:[:.]\d{2})?|one|two|three|four|five|"
                r"six|seven|eight|nine|ten|eleven|twelve|noon|lunch)(?:\s*(?:am|pm|o'?clock))?\b"
                r"(?=\s*(?:$|[,.;!?→]|(?:today|tonight|tomorrow|pls|please|thx|thanks|if)\b))",
                re.I), " "),
    # "tall-ish", "smallish": the size word itself
    (re.compile(r"\b(tall|high|long|wide|low|short|big|small|flat)-?ish\b", re.I), r"\1"),
    # "job 2207 on the screen says:", "on the HMI": where the job was read, not a structure
    (re.compile(r"\b(?:on|from)\s+(?:the|my|our|this)\s+(?:screen|display|hmi|monitor|tablet)"
                r"(?:\s+(?:says|shows|reads))?\b|\b(?:the\s+)?(?:screen|display|hmi)\s+(?:says|shows|reads)\b",
                re.I), " "),
    # "a wall 5 long, square to the front edge": set square, as SDI sets every structure
    (re.compile(r",?\s*\b(?:set\s+)?square\s+(?:to|with)\s+the\s+(?:front|back|left|right|table)"
                r"(?:\s+(?:edge|side))?\b", re.I), " "),
    # "Undo that and put a wall there": the take-back, then the new step
    (re.compile(r"\b(undo|scratch|scrap|cancel|bin|ditch)\s+(that|it|this)\s+and\s+(?:then\s+)?"
                r"(?=(?:put|place|build|make|set|add|stack|lay|do)\b)", re.I), r"\1 \2. then "),
    # "heights 1 2 3": a list said without commas
    (re.compile(r"\b(heights?|lengths?|sizes?)\s+(?:of\s+)?(\d+(?:\s+\d+){1,5})\b(?!\s*(?:x|by|mm|cm|m)\b)",
                re.I), lambda m: f"{m.group(1)} {', '.join(m.group(2).split())}"),
    # "three rows of four cubes stacked on top of each other": a wall four long, three high
    (re.compile(r"\b(two|three|four|five|six|[2-6])\s+(?:rows|lines|courses)\s+of\s+(\d+|two|three|four|five|"
                r"six|seven|eight|nine|ten)(?:\s+(?:cubes|blocks|bricks))?,?\s+(?:stacked(?:\s+up)?"
                r"(?:\s+on\s+top\s+of\s+(?:each\s+other|one\s+another))?|on\s+top\s+of\s+(?:each\s+other|"
                r"one\s+another)|one\s+on\s+top\s+of\s+the\s+other)\b", re.I),
     r"a wall \2 long and \1 high"),
    # "two towers of 3 stacked on top of each other": one tower, all their cubes high
    (re.compile(r"\b(two|three|four|[2-4])\s+(?:towers|stacks|columns|pillars)\s+of\s+(\d+|two|three|four|"
                r"five)(?:\s+(?:cubes|blocks|bricks))?,?\s+(?:stacked(?:\s+up)?(?:\s+on\s+top\s+of\s+(?:each\s+"
                r"other|one\s+another))?|on\s+top\s+of\s+(?:each\s+other|one\s+another)|one\s+on\s+top\s+of\s+"
                r"the\s+other)\b", re.I),
     lambda m: "a tower of " + str(int(words_to_numbers([m.group(1).lower()])[0])
                                  * int(words_to_numbers([m.group(2).lower()])[0]))),
    # "put two cubes on top of each other", "three cubes one on top of the other": a tower
    (re.compile(r"\b(two|three|four|five|six|seven|eight|nine|ten|\d+)\s+(?:cubes|blocks|bricks)\s+"
                r"(?:stacked\s+)?(?:(?:on\s+top\s+of|onto|on)\s+(?:each\s+other|one\s+another)|"
                r"one\s+on\s+top\s+of\s+(?:the\s+)?(?:other|another|next))\b", re.I),
     r"a tower of \1"),
    # "next to it on the right", "beside the wall, on its left side": that side of it
    (re.compile(r"\b(?:next\s+to|beside|by)\s+(it|them|the\s+\w+)\s*,?\s+(?:on|to)\s+"
                r"(?:the|its|their)\s+(left|right|front|back)(?:[\s-]+(?:hand\s+)?side)?\b"
                r"(?!\s+(?:of|edge|corner)\b)", re.I),
     lambda m: {"front": f"in front of {m.group(1)}", "back": f"behind {m.group(1)}"}.get(
         m.group(2).lower(), f"to the {m.group(2)} of {m.group(1)}")),
    # "an L with 4 cubes in each arm": arms of 4
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight)\s+(?:cubes?|blocks?|bricks?)\s+"
                r"(?:in|on|per|for)\s+(?:each|every|both|either)\s+(?:of\s+its\s+)?arms?\b", re.I),
     r"arms of \1"),
    # "two 3x3 slabs stacked": one block that many layers high
    (re.compile(r"\b(two|three|four|five|[2-5])\s+(\d+\s*(?:x|by)\s*\d+)\s+(?:slabs|layers|grids|pads|plates|"
                r"platforms|squares)\s+(?:stacked(?:\s+up)?(?:\s+on\s+top\s+of\s+each\s+other)?|on\s+top\s+of\s+"
                r"each\s+other|one\s+on\s+top\s+of\s+the\s+other)\b", re.I), r"a \2 block \1 high"),
    # "a tower of 2 on each side of a wall 4 long": the wall, and a tower on each side of it
    (re.compile(r"^(?P<x>\W*(?:an?|one)\s+[\w\s-]+?)\s+(?P<on>on|at)\s+(?P<q>each|either|both)\s+"
                r"(?P<n>sides?)\s+of\s+(?P<y>an?\s+[^,.;]+?)\s*(?=$|[.;])", re.I),
     lambda m: f"{m.group('y')} and {m.group('x')} {m.group('on')} {m.group('q')} "
     f"{m.group('n')} of it"),
    # "a staircase that goes up 4 steps to the left": of 4 steps, going up to the left
    (re.compile(r"\b(?:that|which)\s+(?:goes|go|climbs|rises)\s+up\s+(\d+|two|three|four|five|six|seven|"
                r"eight)\s+steps\s+(to(?:wards)?\s+the\s+(?:left|right|back|front))\b", re.I),
     r"of \1 steps going up \2"),
    (re.compile(r"\b(?:that|which)\s+(?:goes|go|climbs|climb|rises|rise)\s+(?=up\s+(?:to(?:wards)?\s+the\s+)?"
                r"(?:left|right|back|front)\b)", re.I), "going "),
    # "a tower of 3, another of 4 and a third of 5": another one
    (re.compile(r"\ba\s+(?:third|fourth|fifth|sixth)\s+(?:one\s+)?(?=(?:of|with)\s+(?:\d|one|two|three|four|"
                r"five|six|seven|eight|nine|ten)\b)", re.I), "another "),
    # "two walls forming a corner", "two rows making an L": one L shape
    # "two runs meeting at right angles, 5 and 4 bricks": its arms
    (re.compile(r"\btwo\s+(walls|rows|runs|lines|lengths|courses)\s+(?:(?:forming|making|that\s+form|that\s+"
                r"make|meeting\s+(?:at|in)|that\s+meet\s+(?:at|in)|joined\s+at|joining\s+at|at)\s+"
                r"(?:a\s+)?(?:corner|an?\s+l(?:[\s-]shape)?|right\s+angles?|90(?:\s*degrees|\s*°)?)"
                r"(?:\s+to\s+each\s+other)?)\b", re.I),
     lambda m: "an L shape 2 high" if m.group(1).lower() == "walls" and not re.search(
         r"\b(?:high|tall|courses|layers|levels)\b", m.string[m.end():].split(".")[0], re.I)
     else "an L shape"),
    # "an L shape, 4 and 3 long, 2 high": its arms, then its height
    (re.compile(r"(\b(?:l[\s-]shape[d]?|an\s+l)\b[^.;\d]{0,30}?)\b(" + _NUM + r"\s+and\s+" + _NUM
                + r")\s+"
                r"(?:cubes?\s+|bricks?\s+|parts?\s+)?long\s*,\s*(?=" + _NUM + r"\s+(?:cubes?\s+)?"
                                                                              r"(?:high|tall)\b)",
                re.I),
     lambda m: m.group(1).rstrip(" ,") + " " + re.sub(r"(?i)\s+and\s+", " by ", m.group(2)) + ", "),
    # "Then 1 on top of that": one cube on top
    (re.compile(r"\b(then|and|plus)\s+(?:1|one)\s+(?=(?:on\s+top|on\s+it|up\s+top|atop)\b)", re.I),
     r"\1 a cube "),
    # "max 6 cubes", "maximum of 6": the most allowed
    (re.compile(r"\b(?:max|maximum|max\.)\s*(?:of\s+)?(?=\d+\s*(?:cubes?|blocks?|parts?|pieces?|bricks?)\b)",
                re.I), "no more than "),
    # a contract's pronominal adverbs: "upon the centre thereof" is on the centre of it
    (re.compile(r"\bthereof\b", re.I), "of it"),
    (re.compile(r"\b(?:thereon|thereupon|thereonto)\b", re.I), "on it"),
    (re.compile(r"\btherein\b", re.I), "in it"),
    (re.compile(r"\bthereto\b", re.I), "to it"),
    (re.compile(r"\b(?<!depending\s)(?<!depends\s)upon\s+", re.I), "on "),
    (re.compile(r"\b(?:the\s+)?said\s+(?=(?:tower|wall|row|slab|block|bridge|staircase|pyramid|"
                r"structure|grid|ring|arch|canopy)s?\b)", re.I), "the "),
    # a number said digit by digit ("one-five-zero millimetres", "wun-fife-zero"): 150
    (re.compile(r"\b(?:" + _DIGIT_WORD + r")(?:-(?:" + _DIGIT_WORD + r")){1,3}\b", re.I),
     lambda m: "".join(str(_DIGITS[w.lower()]) for w in m.group(0).split("-"))
     if len(m.group(0).split("-")) >= 3 or "zero" in m.group(0).lower() else m.group(0)),
    # "a slab comprising twelve cubes arranged in three rows of four": the slab's own rows
    (re.compile(r"\b((?:slab|grid|block|platform|layer|pad|floor|plate|deck|patch|mat)s?\b[^.;]{0,30}?)"
                r"\s*,?\s*\b(?:(?:comprising|consisting\s+of|made\s+(?:up\s+)?of|of|with)\s+)?(\w+)\s+"
                r"(?:cubes?|blocks?|parts?|pieces?)\s*,?\s*(?:arranged\s+|laid\s+(?:out\s+)?|set\s+"
                r"(?:out\s+)?|placed\s+)?(?:(?:in|as)\s+)?(\w+)\s+rows\s+of\s+(\w+)(?:\s+(?:cubes?|each))?",
                re.I),
     lambda m: f"{m.group(1)} {m.group(4)} by {m.group(3)}" if _product(m) else m.group(0)),
    # "one per corner of a slab", "one at each end of the wall": one on (at) each of them
    (re.compile(r"(?<!\bof\s)\b(?:one|1|a\s+single\s+one)\s+(per|for\s+each|at\s+each|at\s+every|"
                r"on\s+every|in\s+each|on\s+each|on\s+(?:all\s+)?(?:four|4|two|2|both))\s+"
                r"(corner|end)s?\b", re.I),
     lambda m: f"{_EACH_AT.get(m.group(1).split()[0].lower(), 'on')} each {m.group(2)}"),
    # "4 towers of 2, on each corner of it": one tower on each of its four corners; "two
    # towers, one on each side" (the "one" was a third tower, one high): one on either side,
    # "four towers, one on each side": one on each of its four sides
    (re.compile(r"\b(four|4|two|2)\s+(?!(?:cube|block|brick|part|level|layer|course)s?\b)"
                r"((?:\d+[- ]cubes?[- ]|\w+[- ])?[a-z]+?)s\b([^.;:]{0,40}?)"
                r"\s*,?\s*\b((?:on|at|in)\s+each\s+(corner|end)|(?:one|1)\s+(?:on|at|to)\s+"
                r"(?:each|either)\s+(side))\b", re.I),
     _one_per_anchor),
    # "four towers of 2 around it (, one on each side)": one on each of its four sides (a ring
    # was built around it); "four cubes around the tower": the same
    (re.compile(r"\b(?:four|4)\s+((?:\d+[- ]cubes?[- ]|\w+[- ])?(?:tower|stack|column|pillar|post|"
                r"cube|block))s((?:\s+of\s+(?:\d+|one|two|three|four|five|six)(?:\s+cubes?)?)?"
                r"(?:\s+(?:\d+|one|two|three|four|five|six)\s+(?:cubes?\s+)?(?:high|tall))?)\s+"
                r"(?:(?:placed|standing|set|arranged|spaced(?:\s+evenly)?)\s+)?(?:a?round|surrounding)\s+"
                r"(?:(it|them|that|this)\b(?:\s*,?\s*(?:with\s+)?one\s+(?:on|at|to)\s+each\s+side\b)?)?",
                re.I),
     lambda m: m.group(0) if _EACH_SIDE_NAMED.match(m.string, m.end())  # read as said
     else f"a {m.group(1)}{m.group(2)} on all four sides of {m.group(3) or ''}"),
    # an architect's words: "a colonnade of five columns" is five columns, piers are pillars,
    # "between neighbouring columns" is between them, a "ground-floor slab" a slab
    (re.compile(r"\b(?:an?\s+)?colonnade\s+(?:of|with)\s+(?=\d|two|three|four|five|six|seven|eight)",
                re.I), ""),
    # a bridge's piers are its pillars (a deck on them)
    (re.compile(r"\bpier(s?)\b(?!\s+a\s*mid)", re.I),
     lambda m: ("pillar" + m.group(1)) if _BRIDGE.search(m.string) or _DECK.search(m.string)
     else m.group(0) if re.search(r"\b(?:lintels?|beams?|girders?|spans?|across)\b", m.string, re.I)
     else ("column" + m.group(1))),  # an engineer's standing alone are columns
    # "two pillars of 3, lay a beam on them": put it across them (the towers were stacked)
    (re.compile(r"\b(?:lay|put|place|set)\s+((?:a|the|one)\s+(?:beam|lintel|plank|girder|deck))\s+(?:on|"
                r"across|over|onto)\s+(?:top\s+of\s+)?(them|both|the\s+two|the\s+(?:towers|pillars|piers|"
                r"posts|columns))\b", re.I), r"then put \1 across \2"),
    # "two piers 4 high … with a deck across", "a deck on two piers of 3": the beam they carry
    # (a slab was built, the piers reported unused)
    (re.compile(r"\b(a|the)\s+deck\b", re.I),
     lambda m: f"{m.group(1)} beam" if re.search(r"\b(?:piers?|pillars?)\b", m.string, re.I)
     and re.search(r"\bdeck\s+(?:across|over|on|spanning|between)\b|\bacross\b", m.string, re.I)
     else m.group(0)),
    (re.compile(r"\bbetween\s+(?:neighbouring|neighboring|adjacent)\s+(?:columns|towers|stacks|pillars)\b",
                re.I), "between them"),
    (re.compile(r"\bground[\s-]+floor\s+(?=slab|plate|pad|platform|layer)", re.I), ""),
    # "…, one course, as a plinth study": what it is for; "yes, 4 by 4 is fine": a size agreed
    (re.compile(r",?\s*\bas\s+an?\s+(?:\w+\s+)?(?:study|test|demo|mock-?up|example|sample|trial|"
                r"placeholder|stand-?in|dummy)\b", re.I), ""),
    (re.compile(r"\b(?:(?:yes|yeah|ok|okay)\s*,?\s*)?(?:\d+\s*(?:x|by)\s*\d+|\d+|one|two|three|four|five|six)"
                r"\s+(?:is|'s)\s+(?:fine|ok|okay|good|right|correct|perfect|enough)\b", re.I),
     lambda m: m.group(0) if _CORRECTING.search(m.string[: m.start()]) or _another_value(m)
     else ""),  # "actually 3 is"; "a tower of 6. hmm, 4 is enough": a correction
    # "table's clear", "the table is empty": the work table; "I packed the test pieces away":
    # what was done before; "a 2x2 tower of 3": a 2 by 2 block 3 high
    (re.compile(r"\b(?:the\s+)?(?:work\s*)?table(?:'s|\s+is)\s+(?:now\s+)?(?:clear|empty|free|ready|clean)"
                r"(?:ed)?\b", re.I), ""),
    (re.compile(r"\b(?:i|we)\s+(?:packed|put|cleared|tidied|took)\s+(?:the\s+)?(?:\w+\s+)?(?:pieces|cubes|parts|"
                r"blocks|bricks)\s+away\b", re.I), ""),
    (re.compile(r"\b(\d+)\s*(?:x|by)\s*(\d+)\s+(?:towers?|columns?|stacks?|pillars?)\s+(?:of\s+)?(\d+)(?![/\d]|\.\d)"
                r"(?:\s+(?:cubes?|high|tall|levels?|layers?))?\b", re.I),
     lambda m: f"tower of {m.group(3)}" if m.group(1) == m.group(2) == "1"
     else f"{m.group(1)} by {m.group(2)} block {m.group(3)} high"),
    # "… a 2x2 tower of 3, the staircase on the left, the tower on the right": that block (a
    # second tower was built)
    (re.compile(r"\bthe\s+(?:tower|column|stack|pillar)\b", re.I),
     lambda m: "the block"
     if re.search(r"\d\s+by\s+\d+\s+block\s+\d+\s+high\b", m.string[: m.start()])
     and not re.search(r"\b(?:towers?|columns?|stacks?|pillars?)\b", m.string[: m.start()], re.I)
     else m.group(0)),
    # "a single-cube marker", "a one-cube spacer": one cube standing alone
    (re.compile(r"\b(an?|one|each|two|three|four)\s+(?:single|one)[- ]cube\s+(?:markers?|posts?|"
                r"pieces?|spacers?|stops?|pins?|pegs?|cones?|targets?|blocks?)\b", re.I),
     r"\1 1-cube tower"),
    # "two columns of three, left and right": one on the left, one on the right
    (re.compile(r"(\b(?:two|2|both)\s+(?:\w+\s+){0,5}?(?:towers|columns|stacks|pillars|walls|rows|"
                r"bridges|arches|pyramids|staircases|slabs|blocks|rings|tables)\b[^.;]*?)"
                r",\s*(left|front)\s+and\s+(right|back)\b(?!\s+(?:of|side))", re.I),
     lambda m: m.group(1) + ("" if _APART_SAID.search(m.string)  # side by side, that far apart
                             else f", one on the {m.group(2)} and one on the {m.group(3)}")),
    # "a column … on a single-cube footprint": as every column is; "walls one cube thick": as a
    # ring's walls are
    (re.compile(r",?\s*\b(?:on|with|of)\s+(?:a\s+)?(?:single|one|1)[- ]cube\s+footprint\b", re.I),
     ""),
    (re.compile(r",?\s*\b(?:(?:the|its|with)\s+)?(?:walls?|sides?)\s+(?:are\s+|is\s+)?"
                r"(?:one|1|a\s+single)\s+(?:cube|part|block)\s+thick\b", re.I), ""),
    # "aligned along x": one behind the other; "aligned along y": side by side
    (re.compile(r"\b(?:aligned|lined\s+up)\s+(?:along|on|with)\s+(?:the\s+)?x(?:[\s-]+axis)?\b",
                re.I),
     "one behind the other"),
    (re.compile(r"\b(?:aligned|lined\s+up)\s+(?:along|on|with)\s+(?:the\s+)?y(?:[\s-]+axis)?\b",
                re.I),
     "side by side"),
    (re.compile(r"\bover\s+(?=(?:on|at|in|by)\s+the\b)", re.I), ""),
    (re.compile(r"\b(\d+|two|three|four|five|six|seven|eight|nine|ten)-(stack|tower|column)(s?)\b"
                r"(?!\s+(?:" + _FAMILY_SAID + r")\b)", re.I), r"\2\3 of \1"),
    # "a stack 3 pallets high, each pallet a 2 by 2 layer": the stack's footprint
    (re.compile(r",?\s*each\s+(?:pallet|layer|level|course|tier)\s+(?:is\s+)?(?:a\s+)?(\d+\s*(?:x|by)\s*\d+)"
                r"(?:\s+(?:layer|pallet|level|course|tier))?", re.I), r", \1"),
    # "Wall is long 6 and high 3": the sizes of the one named
    (re.compile(r"\b(" + _FAMILY_SAID + r")\s+(?:is|are)\s+(?=(?:long|high|tall|wide|deep)\s+\d)",
                re.I), r"\1 "),
    # "a square-based pyramid": a square pyramid
    (re.compile(r"\bsquare[\s-]+based\b", re.I), "square"),
    # "a cube with an edge length of 3": a block 3 on every side
    (re.compile(r"\b(?:a\s+)?(?:big\s+|large\s+|solid\s+)?cube\s+(?:with\s+(?:an?\s+)?(?:edge|side)s?"
                r"(?:\s+length)?\s+(?:of\s+)?|of\s+(?:edge|side)\s+(?:length\s+)?)(\d+)\b", re.I),
     r"a \1 by \1 by \1 block"),
    # "one that is half as high": one half as high
    (re.compile(r"\b(one|another)\s+(?:that|which)\s+(?:is|are)\s+(?=(?:twice|half|double|\d+\s+times|"
                r"one|two|a)\b)", re.I), r"\1 "),
    # "a flat 6 wide and 4 high" (a stage's flat): a wall
    (re.compile(r"\b(a|an|one|two|three|four|each|the|both)\s+flat(s?)\b(?=\s*(?:\d+\s*(?:cubes?\s+)?"
                r"(?:wide|high|tall)\b|,|each\b|(?<=s)\s))", re.I), r"\1 wall\2"),
    # "the table's line of symmetry", "the centre line": the middle across the table
    (re.compile(r"\b(?:on|along|at)\s+(?:the\s+)?(?:table'?s\s+)?(?:line\s+of\s+symmetry|centre\s*line|"
                r"center\s*line|middle\s+line)\b(?:\s*,\s*(?:the\s+one\s+)?(running\s+front\s+to\s+back))?",
                re.I), r" in the centre \1 "),
    # "From the desk of Mr. Harris:": a letterhead
    (re.compile(r"\bfrom\s+the\s+desk\s+of\s+[^:]{1,40}:", re.I), " "),
    # "a ring …, with a tower standing at its center": in its middle (not the table's)
    (re.compile(r"\b(?:standing\s+|placed\s+|set\s+)?(?:at|in)\s+its\s+(?:very\s+)?(?:centre|center|"
                r"middle)\b", re.I), lambda m: " in the middle " + _of_it(m)),
    # "with a tower in the middle, not touching the ring": inside it, clear of it anyway
    (re.compile(r"\b(in\s+the\s+middle)\s*,?\s*(?:but\s+)?not\s+touching\s+(?:it|them|the\s+\w+)\b",
                re.I), r"\1"),
    # "then strike it and put a tower there instead": the one before taken back, then the new
    (re.compile(r"\b(?:strike|remove|take\s+down|scrap|dismantle|clear\s+away|get\s+rid\s+of|"
                r"demolish|destroy)\s+(?:it|that|this)\s+and\s+(?:then\s+)?"
                r"(?=(?:put|build|place|make|set|stand)\b)", re.I), "undo that. then "),
    # "knock it down and build a tower instead", "tear that down, then make …"
    (re.compile(r"\b(?:k?nock|tear|pull|take|break)\s+(?:it|that|this)\s+(?:down|over|apart)\s*"
                r"(?:,\s*)?(?:and\s+)?(?:then\s+)?(?=(?:put|build|place|make|set|stand)\b)", re.I),
     "undo that. then "),
    # "3 units apart", "leave 2 units between them": a unit of the cube world is a cube
    (re.compile(r"\b(\d+|one|two|three|four|five|six)\s+units?\b(?!\s+of\s+(?:measure|length))",
                re.I), r"\1 cubes"),
    # Indian English: "one-one cube on each" (one each), "heights 2, 4 and 6 only", "in the
    # left side only" (a focus word, no limit of its own)
    (re.compile(r"\b(one|two|three)-\1\b", re.I), r"\1"),
    (re.compile(r"(?<=\d)\s+only\b|\s+only\b(?=\s*(?:[,.;!]|$))", re.I), ""),
    # "one cube back from it": that far behind it
    (re.compile(r"\b(\d+|a|one|two|three|four)\s+(cubes?|parts?|blocks?|mm|cm)\s+(?:back|away|out)\s+"
                r"from\s+(it|them|that)\b", re.IGNORECASE), r"\1 \2 away from \3"),
]  # fmt: skip


# "near to wall, on front side of it", "… one brick away from it, on its front side": the side
# said after what it is beside
_SIDE_OF = re.compile(
    r"\b(?:(?:near|next\s+to|beside|by|close\s+to)\s+(?:the\s+)?(\w+)\s*,\s*on\s+(?:the\s+)?"
    r"(front|back|left|right)\s+side\s+of\s+it|(?:on|at)\s+its\s+(front|back)\s+side)\b",
    re.IGNORECASE,
)


def _side_of(m: re.Match[str]) -> str:
    if m.group(3):
        return f"{lx.BESIDE_PHRASE[m.group(3).lower()]} it"
    return f"{lx.BESIDE_PHRASE[m.group(2).lower()]} the {m.group(1)}"


# "a row of 5. then another row 1 cube to the left": to the left of the one before, that far
_OFFSET_FROM_LAST = re.compile(
    r"\b(\d+(?:\.\d+)?|a|one|two|three|four|five)\s+(cubes?|parts?|blocks?|mm|cm)\s+(?:to\s+the\s+"
    r"(left|right)|(behind|in\s+front))\b(?!\s+(?:of|side|edge|half|corner|end|it|them|that|this|the)\b)",
    re.IGNORECASE,
)


def _from_last(m: re.Match[str]) -> str:
    """The offset said of a structure after another: from the one before (the first
    structure named has nothing to be beside: left as said)."""
    before = m.string[: m.start()].lower()
    said = re.findall(r"[a-z]+", before)
    if len(re.split(r"[.;]|\bthen\b", before)) < 2 or not any(w in lx.SHAPE_WORDS for w in said):
        return m.group(0)
    if m.group(3):
        return f"{m.group(1)} {m.group(2)} to its {m.group(3)}"
    side = "back" if m.group(4).lower() == "behind" else "front"
    return f"{m.group(1)} {m.group(2)} {lx.BESIDE_PHRASE[side]} it"


_METRE_WORDS = [
    (re.compile(r"\b(?:half\s+a|a\s+half)\s+(metre|meter)\b", re.I), "0.5 m"),
    # "a quarter of a metre", "a quarter metre"
    (re.compile(r"\b(?:a\s+)?quarter\s+(?:of\s+)?(?:a\s+)?(metre|meter)\b", re.I), "0.25 m"),
    (re.compile(r"\ba\s+(metre|meter)\b", re.I), "1 m"),
]


# "a third of a metre", "3/10 of a metre", "two fifths of a meter"
_FRACTION_TOP = {"a": "1", "an": "1", "one": "1", "two": "2", "three": "3", "four": "4"}
_FRACTION_BOTTOM = {"half": "2", "halve": "2", "third": "3", "quarter": "4", "fourth": "4",
                    "fifth": "5", "tenth": "10"}  # fmt: skip
_FRACTION_OF_METRE = re.compile(
    r"\b(\d+|an?|one|two|three|four)\s*(?:/\s*|\s)(\d+|halves|half|thirds?|quarters?|fourths?|"
    r"fifths?|tenths?)\s+of\s+a\s+(?:metre|meter)\b",
    re.IGNORECASE,
)


_UNRELATED = re.compile(
    r"[^.;!?\n]*\(\s*(?:unrelated|not\s+related|off[- ]topic|fyi|ignore(?:\s+this)?)\s*\)"
    r"[^.;!?\n]*[.;!?\n]?",
    re.IGNORECASE,
)


_LIST_ITEM = re.compile(
    r"(?:^|\n|(?<=[.;]))\s*\d+\)\s+(?=[A-Za-z])|(?:^|\n)\s*\d+\.\s+(?=[A-Za-z])"
)


_BULLET = re.compile(r"(?:^|\n)\s*[-*•]\s+(?=[A-Za-z0-9])")
_STEP_WORDS = ("one", "two", "three", "four", "five", "six", "seven", "eight", "nine")
_STEPS_HEAD = re.compile(
    r"^\s*(?:(?:steps?|plan|sequence|order|instructions?)\s*(?::|--|-|—|–)\s*)?", re.IGNORECASE
)
_TAKES_NUMBER = re.compile(
    r"(?:\b(?:of|by|x|at|is|are|be|to|with|about|height|width|length|and|or|than|from|=)|[\d=])\s*$",
    re.IGNORECASE,
)


def _step_label(n: int) -> re.Pattern[str]:
    """The n-th label of a numbered list: "1.", "(1)", "1)", "1:", "1 -", "Step 1:", "Step one,",
    "a)", "(a)"."""
    letter = "abcdefghi"[n - 1]
    return re.compile(
        rf"(?:(?<=^)|(?<=[\s.;,:(]))(?:\(\s*(?:{n}|{letter})\s*\)|{n}\s*[.):](?=\s)|{letter}\)|{n}\s+[-–—]"
        rf"(?=\s)|(?:step|stage)\s+(?:{n}|{_STEP_WORDS[n - 1]})\b\s*[.,:)–—-]?)\s*",
        re.IGNORECASE,
    )


_STEP_LABELS = tuple(_step_label(n) for n in range(1, 10))
"""The labels of the first nine steps, in order (compiled once: every command is tried)."""


def _numbered_steps(text: str, notes: list[str]) -> str:
    """ "1. a row of 3 cubes 2. a row of 2 on top of it 3. …", "Step 1: … Step 2: …", "(1) …
    (2) …", "a) … b) …": each step after the first is a step of its own, and its label no
    number of the structure ("2." was read as a count, "Step" as a staircase)."""
    start = _STEPS_HEAD.match(text)
    head = start.end() if start else 0
    first = _STEP_LABELS[0].match(text, head)
    if first is None:
        return text
    text, revised = _revised_steps(text, first.end())
    dropped = {int(m.group(1)): m.group(0).strip(" .;") for m in _DROP_STEP.finditer(text)}
    text = _DROP_STEP.sub(" ", text)
    labels = [first]
    pos = first.end()
    for label in _STEP_LABELS[1:]:
        found = next((m for m in label.finditer(text, pos)
                      if m.group(0).startswith("(") or m.group(0)[:1].isalpha()
                      or not _TAKES_NUMBER.search(text[: m.start()])), None)  # fmt: skip
        if found is None:
            break
        labels.append(found)
        pos = found.end()
    if len(labels) < 2 and not revised:
        return text
    notes.append(f"read the {len(labels)} numbered steps as steps in that order")
    steps = [
        text[m.end() : labels[k + 1].start() if k + 1 < len(labels) else len(text)]
        for k, m in enumerate(labels)
    ]
    for n, said in revised.items():
        if n <= len(steps):
            notes.append(f"read step {n} as revised: '{said.strip(' .;')}'")
            whole = re.match(r"\W*(?:an?\s+|the\s+)?(?:\w+\s+)?(?:" + _FAMILY_SAID + r")\b", said,
                             re.I)  # fmt: skip
            if whole and not re.search(r"\binstead\b", said, re.I):
                steps[n - 1] = said  # a step said anew
            else:  # "a tower of 2 instead": a change of the step
                steps[n - 1] = steps[n - 1].rstrip(" .;,") + ". Actually, " + said
    for n, said in dropped.items():
        if n <= len(steps):
            notes.append(f"left out step {n}, as said ('{said}')")
            steps[n - 1] = ""
    kept = [step.strip(" ,;") for step in steps if step.strip(" ,;.")]
    return ". then ".join(kept)


_REVISED = re.compile(
    r"(?:(?<=^)|(?<=[\s.;,]))(?:step\s+)?([1-9])\s*\(\s*(?:revised|updated|amended|corrected|changed|"
    r"new)\s*\)\s*[:.)\-–—]?\s*",
    re.IGNORECASE,
)
_ANY_STEP = re.compile(r"(?:(?<=^)|(?<=[\s.;,]))(?:step\s+[1-9]\b|[1-9]\s*[.):](?=\s))", re.I)
_DROP_STEP = re.compile(
    r"\b(?:please\s+)?(?:ignore|skip|forget|drop|cancel|delete|scrap|leave\s+out)\s+(?:the\s+)?"
    r"step\s+([1-9])\b(?:\s*[-–—,:]\s*[^.;]*)?[.;]?",
    re.IGNORECASE,
)
"""'Ignore step 3.', 'Skip step 2 - we don't need it.': that step left out."""


def _revised_steps(text: str, after: int) -> tuple[str, dict[int, str]]:
    """ "Step 2: a tower of 5. Step 2 (revised): make that one 4 instead": the revised words of
    each step, taken out of `text` (both were read: the revision as a change of step 2)."""
    revised: dict[int, str] = {}
    for m in reversed(list(_REVISED.finditer(text, after))):
        nxt = _ANY_STEP.search(text, m.end())
        end = nxt.start() if nxt else len(text)
        revised[int(m.group(1))] = text[m.end() : end]
        text = text[: m.start()] + " " + text[end:]
    return text, revised


_ROBOT_NAME = re.compile(r"\b(?:the\s+)?(?:abb\s+)?irb\s*-?\s*(?:120|1600)\b", re.IGNORECASE)
_OWN_TABLE = re.compile(
    r"\b(of|on|at|across|along|in|to|near|from|onto|off)\s+(?:my|our|your)\s+"
    r"(?=(?:work\s*)?(?:table|bench|workbench)\b)",
    re.IGNORECASE,
)
"""'on the left side of my table': the work table (a table was built, silently)."""


_PAIR_UNIT = re.compile(
    r"\(\s*(-?\d+(?:\.\d+)?)\s*,\s*(-?\d+(?:\.\d+)?)\s*\)\s*(mm|cm|m)\b", re.IGNORECASE
)


_SLASH_XY = re.compile(
    r"\b(\d+(?:\.\d+)?)\s*/\s*(\d+(?:\.\d+)?)\s*(mm|cm|m)\b(?:\s*\(\s*x\s*/\s*y\s*\))?",
    re.IGNORECASE,
)


_COUNTED = r"(?:towers|stacks|rows|walls|cubes|blocks|pillars|columns|more|steps|levels|layers)"


_CHAT: list[tuple[re.Pattern[str], _Repl]] = [
    # texting: "2 stacks of 4 n put a bridge", "a 3x3 square w a hole", "in a line w gaps of 1"
    # (read before the phrasings, which know "with" and "and")
    (re.compile(r"(?<=[a-z0-9])\s+n\s+(?=(?:a\b|[a-z]{2,}))", re.I), " and "),
    (re.compile(r"(?<=[a-z0-9])\s+w\s+(?=(?:a|an|the|one|two|\d|legs?|gaps?|arms?|sides?|walls?|"
                r"corners?|pillars?|posts?|steps?|levels?|space)\b)", re.I), " with "),
]
_TOLERANCE = re.compile(
    r"\s*,?\s*\(?\s*(?:(?:with\s+)?(?:a\s+)?tolerance(?:\s+of)?\s*:?\s*)?(?:±|\+\s*/\s*-|\+-|plus\s+or\s+"
    r"minus)\s*(\d+(?:\.\d+)?\s*(?:mm|cm|m))\b\s*\)?",
    re.IGNORECASE,
)
"""A measurement's tolerance: "(±5 mm)", "± 1 cm", "tolerance ±10 mm" (its number was read as a
size)."""


def _tolerance(m: re.Match[str], notes: list[str] | None) -> str:
    if notes is not None:
        notes.append(f"read '±{m.group(1)}' as a tolerance: the parts stand at the value said")
    return " "


_BUILD_SLANG = re.compile(
    r"\b(?:knock\s+(?:up|together)|whack|bung|chuck|stick|pop)(?:\s+(?:us|me))?\s+(?:up\s+|down\s+)?"
    r"(?=(?:an?|one|two|three|four|five|six|some|a\s+couple|\d)\b)",
    re.IGNORECASE,
)
"""'pop a bridge on the right', 'chuck us two walls', 'knock up an arch': build (the verb was
read as nothing, 'knock' as knocking down)."""
_SMACK = re.compile(
    r"\b(?:smack(?:\s+bang)?|slap(?:\s+bang)?|bang|plumb|bang\s+on)\s+(?=(?:in|on|at)\s+the\s+"
    r"(?:middle|centre|center)\b)",
    re.IGNORECASE,
)
"""'smack in the middle': in the middle."""


# Shorthand from phones and shop-floor notes: (pattern, expansion). Each expansion is noted.
_TICKET_DIM = {"len": "long", "lgth": "long", "ht": "high", "hgt": "high", "hght": "high",
               "wid": "wide", "wdth": "wide", "dp": "deep", "dpth": "deep",
               "l": "long", "w": "wide", "h": "high", "d": "deep"}  # fmt: skip
_FAR_FWD = re.compile(
    r"\b(?:fwd|forward)\s*(?:=|is|means)\s*(?:the\s+)?(?:far|back|away)|\baft\s*(?:=|is|means)\s*"
    r"(?:the\s+)?(?:robot|near|front)",
    re.IGNORECASE,
)


def _fore_aft(m: re.Match[str]) -> str:
    """ "fwd", "aft": the front (the robot's end) and the back, unless the command says fwd is
    the far end; "fwd of the wall": in front of it."""
    fwd = m.group(1).lower() == "fwd"
    front = fwd != bool(_FAR_FWD.search(m.string))
    if m.group(2):
        return "in front of the" if front else "behind the"
    return "front" if front else "back"
_SHORTHAND: list[tuple[re.Pattern[str], _Repl]] = [
    # "two towers, one twice as tall as the other, the short one three cubes": that one 3
    (re.compile(r"\b(two\s+(?:towers|stacks|columns|pillars))\s*,?\s*(?:with\s+)?one\s+(?:of\s+them\s+)?"
                r"twice\s+as\s+(?:tall|high)\s+as\s+the\s+other\s*,?\s*(?:and\s+)?the\s+(?:short|shorter|"
                r"small|smaller|low|lower|other)\s+one\s+(?:is\s+)?(\d+|one|two|three|four|five)(?:\s+(?:cubes?|"
                r"blocks?))?(?:\s+(?:high|tall))?\b", re.I),
     r"\1, one \2 high and one twice as tall"),
    # "two towers, one twice as tall as the other", no height said: SDI's own 3 and twice that
    # (two towers of 1 were built)
    (re.compile(r"\b(two\s+(?:towers|stacks|columns|pillars))\s*,?\s*(?:with\s+)?one\s+(?:of\s+them\s+)?"
                r"twice\s+as\s+(?:tall|high)\s+as\s+the\s+other\b(?![^.;]*(?:\d|\b(?:one|two|three|four|"
                r"five|six|seven|eight|nine|ten)\b))", re.I),
     r"\1 of 6 and 3"),
    # "two towers of 2, one twice as tall as the other": the other 2 high (they were 2 and 1)
    (re.compile(r"\btwo\s+(towers|stacks|columns|pillars)\s+of\s+(\d+)\s*,?\s*(?:with\s+)?one\s+"
                r"(?:of\s+them\s+)?twice\s+as\s+(tall|high)\s+as\s+the\s+other\b", re.I),
     r"two \1, one \2 high and one twice as tall"),
    # a work ticket's abbreviations: "len 6, ht 2, wid 2", "pos front", "qty 1 block"
    (re.compile(r"\b(len|lgth|ht|hgt|hght|wid|wdth|dp|dpth)\.?\s*[:=]?\s*(\d+(?:\.\d+)?(?:\s*(?:mm|cm|m)\b)?)"
                r"(?:\s*cubes?\b)?", re.I),
     lambda m: f"{m.group(2)} {_TICKET_DIM[m.group(1).lower()]}"),
    # "approx." (its full stop ended the sentence)
    (re.compile(r"\b(?:approx\.?|approximately|ca\.|circa)(?=\s)", re.I), "about"),
    # "in line L-R", "both run F-B": left to right, front to back
    (re.compile(r"\b(?:L\s*[-–/>→]+\s*R|R\s*[-–/>→]+\s*L|F\s*[-–/>→]+\s*B|B\s*[-–/>→]+\s*F)\b"),
     lambda m: {"L": "left to right", "R": "right to left", "F": "front to back",
                "B": "back to front"}[m.group(0)[0]]),
    # "line front→back", "left -> right": from one side to the other
    (re.compile(r"\b(front|back|left|right)\s*(?:→|->|-->|=>|⇒)\s*(front|back|left|right)\b", re.I),
     r"from \1 to \2"),
    # "pos: x 300 mm y 450 mm": at that place; "parallel to the y axis": along y
    (re.compile(r"\b(?:pos|posn|loc)\.?\s*[:=]?\s*(?=x\s*[:=]?\s*\d|\(\s*\d)", re.I), "at "),
    # "parallel to X", "long axis parallel to Y" (a drawing's axes)
    (re.compile(r"\b(?:(?:its\s+)?long\s+(?:axis|side|edge)\s+)?parallel\s+(?:to|with)\s+(?:the\s+([xy])"
                r"[\s-]*axis|([xy])(?![\s-]*(?:=|\d)))\b", re.I),
     lambda m: f"along {m.group(1) or m.group(2)}"),
    (re.compile(r"\b(?:pos|posn|loc)\.?\s*[:=]?\s*((?:front|back|rear|left|right|centre|center|middle)"
                r"(?:[\s-]+(?:left|right|corner))?)\b", re.I), r"at the \1"),
    (re.compile(r"\b(?:qty|qnty)\.?\s*[:=]?\s*(\d+)\s+(?=[a-z])", re.I), r"\1 "),
    # a ticket's one-letter sizes after a structure named: "Wall L 6 x ht 3, w 1" (the L and w
    # reported unused); "lg ht 2" of legs: their height
    (re.compile(r"(?<![\w'-])(L|W|H|D|w|h|d)\s*[:=]?\s*(\d+(?:\.\d+)?)\b(\s*x(?=\s*\d+\s+(?:high|tall|"
                r"long|wide|deep)\b))?(?(3)|(?!\s*(?:x\s*\d|by|-?shaped?|\d)))"),
     lambda m: m.group(0)
     if not [f for f in families_said(m.string[: m.start()]) if f != "l_shape"]
     else f"{m.group(2)} {_TICKET_DIM[m.group(1).lower()]}" + (" and" if m.group(3) else "")),
    (re.compile(r"\b(?:lg|leg)\s+(?=\d+\s+high\b)", re.I), "legs "),
    # "wall A …, wall B same size": a label, not a size or a letter shape
    # (kept where a later word points at one by its label: "on A's right")
    (re.compile(r"\b(wall|tower|row|block|slab|stack|column|pyramid)\s+[A-D](?=\s*(?:[,:]|\d|$|same\b|"
                r"\d+\s|len\b|ht\b|is\b))"),
     lambda m: m.group(0) if re.search(r"\b[A-D]['’]s\s|\bof\s+[A-D]\b", m.string) else m.group(1)),
    # Scots on the shop floor: "a tower o' five", "wi' a gap", "tae the right", "twa high"
    (re.compile(r"\bo['’](?=\s)(?!\s*clock)", re.I), "of"),
    (re.compile(r"\bwi['’](?=\s)", re.I), "with"),
    (re.compile(r"\btae\b", re.I), "to"),
    (re.compile(r"\btwa\b", re.I), "two"),
    (re.compile(r"\bgie\b", re.I), "give"),
    (re.compile(r"\baff\b", re.I), "off"),
    (re.compile(r"\b(?:nae|naw)\b", re.I), "no"),
    (re.compile(r"\byin\b", re.I), "one"),
    (re.compile(r"\bwee\b", re.I), "little"),
    (re.compile(r"\baboot\b", re.I), "about"),
    (re.compile(r"\bdoon\b", re.I), "down"),
    # a fitter's "mil" is a millimetre; "50 mil of daylight between them" the clear gap
    (
        re.compile(
            r"(?:(?<=\d)\s*|(?<=\d\s))mils?\b(?!\s+(?:cubes?|blocks?|bricks?|parts?)\b)", re.I
        ),
        " mm",
    ),
    (
        re.compile(
            r"\b(\d+(?:\.\d+)?\s*(?:mm|cm|m)?)\s+(?:of\s+)?(?:clear\s+)?daylight"
            r"(?:\s+between(?:\s+(?:them|each|the\s+\w+))?)?",
            re.I,
        ),
        r"\1 apart",
    ),
    (
        re.compile(r"(?<=\d)\s*(?:ht|hgt|hght|hgh|hi|h)\b(?!\s*x)|\b(?:ht|hgt|hght|hgh)\b", re.I),
        " high",
    ),
    (re.compile(r"(?<=[a-z0-9])\s+\+\s+(?=[a-z0-9])", re.I), " and "),
    (re.compile(r"(?<=\d)\s*(?:lng|lg)\b|\b(?:lng)\b", re.I), " long"),
    (re.compile(r"(?<=\d)\s*(?:wd)\b", re.I), " wide"),
    (re.compile(r"(?<=\d)\s*(?:dp)\b", re.I), " deep"),
    (re.compile(r"\blvls\b", re.I), "levels"),
    (re.compile(r"\blvl\b", re.I), "level"),
    (re.compile(r"\bea\b(?=\s+(?:end|side|corner|one|of|tower|stack|column|post|row|wall)s?\b)",
                re.I), "each"),  # "1 blk on ea end": on each end
    (re.compile(r"\b(high|tall|long|wide|deep)\s+ea\b", re.I), r"\1 each"),  # "ht 2 ea": each
    (re.compile(r"\b(?:pcs|pc|ea)\b(?=\W|$)", re.I), "cubes"),
    (re.compile(r"\b(on|of|onto|across)\s+(?:the\s+)?tp\b", re.I), r"\1 top"),  # "1 blk on tp"
    # a ship's or a cell's ends: "fwd" the front (the robot's end), "aft" the back, unless the
    # command defines them the other way ("(fwd = far end)")
    (re.compile(r"\bfore[\s-]+(?:and|&|n)[\s-]+aft\b", re.I), "running front to back"),  # a ship's
    (re.compile(r"\b(fwd|aft)(\s+of)?\b", re.I), _fore_aft),
    (re.compile(r"\s*\(?\s*\b(?:front\s*(?:=|is|means)\s*(?:the\s+)?(?:robot(?:'s)?|near|front)|back\s*(?:=|is|"
                r"means)\s*(?:the\s+)?(?:far|back|away\s+from\s+(?:the\s+)?robot))(?:\s+(?:end|side))?\s*\)?",
                re.I), " "),  # the definition said, once read (SDI's own: the front is the robot's)
    (re.compile(r"\b(climb(?:s|ing)?|ris(?:es|ing)|going\s+up|goes\s+up)\s+(back|front|left|right)\b"
                r"(?!\s+(?:of|edge|side|corner|end|half)\b)", re.I), r"\1 towards the \2"),
    (re.compile(r"\bLH\s*[-–/>→]+\s*RH\b"), "left to right"),
    (re.compile(r"\bRH\s*[-–/>→]+\s*LH\b"), "right to left"),
    # a surveyor's shorthand: "@ front L", "R of it", "5L x 2H", "1 clr", "rmv"
    (re.compile(r"(?<=\d)\s*L\s*x\s*(\d+)\s*(?:H\b|high\b)"), r" long and \1 high"),  # "5L x 2H"
    (re.compile(r"(?<=\d)\s*L\b(?!')"), " long"),
    (re.compile(r"\b(at|front|back|rear)\s+L\b(?![-'])"), r"\1 left"),
    (re.compile(r"\b(at|front|back|rear)\s+R\b(?![-'])"), r"\1 right"),
    (re.compile(r"(?:(?<=^)|(?<=[\s,;:]))L(?=\s+of\s+(?:it|them|the|that)\b)"), "left"),
    (re.compile(r"(?:(?<=^)|(?<=[\s,;:]))R(?=\s+of\s+(?:it|them|the|that)\b)"), "right"),
    (re.compile(r"\b(\d+|one|two|three)\s*(?:cubes?\s+|blocks?\s+)?(?:clr|clear)\b(?:\s+(?:between|btwn)"
                r"(?:\s+(?:them|each|(?:the\s+)?"
                r"inner\s+faces))?)?", re.I),
     lambda m: f"{m.group(1)} {'mm' if _drawn_mm(m.group(1)) else 'cubes'} apart"),
    (re.compile(r"\brmv\b|\brmve\b", re.I), "remove"),
    # "make letter T with cubes", "build the letter U 5 wide": that shape
    (re.compile(r"\b(?:(?:an?|the)\s+)?(?:big\s+|capital\s+)?letter\s+([TLUtlu])\b(?![-'])(?!\s+shape)"),
     r"a \1 shape"),
    (_ARMS_SAID, _arms_said),
    # a foreman's codes: "T4 back left", "2x T3", "W 5x2 front" (capital letter, a number)
    (re.compile(r"\b([2-9])\s*x\s*T(\d{1,2})(?![\w.-])(?!\s*(?:x|by|shape)\b)"),
     r"\1 towers of \2"),
    (re.compile(r"(?<![\w-])T(\d{1,2})(?![\w.-])(?!\s*(?:x|by|shape)\b)"), r"a tower of \1"),
    (re.compile(r"(?<![\w-])W\s*(\d{1,2})\s*x\s*(\d{1,2})(?![\w.-])(?!\s*(?:x|by)\b)"),
     r"a wall \1 long and \2 high"),
    (re.compile(r"\b(?:cnr|crnr)\b", re.I), "corner"),
    (re.compile(r"\b(?:cnrs|crnrs)\b", re.I), "corners"),
    (re.compile(r"\beachother\b", re.I), "each other"),
    (re.compile(r"\bontop\b", re.I), "on top"),
    (re.compile(r"\bnextto\b", re.I), "next to"),
    (re.compile(r"\binfront\b", re.I), "in front"),
    (re.compile(r"\bnxt\b", re.I), "next"),
    # "bridge btw 2 twrs" (not "by the way")
    (re.compile(r"\bbtw(?=\s+(?:\d|two\b|them\b|both\b))", re.I), "between"),
    (re.compile(r"\b(?:bhnd|bhd)\b", re.I), "behind"),
    (re.compile(r"\bfrnt\b", re.I), "front"),
    (re.compile(r"\blft\b", re.I), "left"),
    (re.compile(r"\b(?:rght|rgt)\b", re.I), "right"),
    (re.compile(r"\b(?:btwn|betw)\b", re.I), "between"),
    (re.compile(r"\babv\b", re.I), "above"),
    (re.compile(r"\bw/o\b", re.I), "without"),
    (re.compile(r"\bw/(?=\s|\w)", re.I), "with "),
    (re.compile(r"(?<=\d)\s+n\s+(?=\d)", re.I), " and "),
    # "on top of a block, in the centre of the block's top": centred on it (the top was read
    # as nothing, the middle as a relation with no subject)
    (re.compile(r",?\s*(?:right\s+|exactly\s+)?(?:in|at|on)\s+the\s+(?:centre|center|middle)\s+of\s+"
                r"(?:the\s+[a-z]+['’]s\s+top|its\s+top|the\s+top(?:\s+(?:face|surface))?\s+of\s+(?:the\s+"
                r"[a-z]+|it))(?:\s+(?:face|surface))?\b", re.I),
     lambda m: ", centred" if re.search(r"\bon(?:\s+top\s+of|to)?\b", re.split(r"[.;!?]", m.string[
         : m.start()])[-1], re.I) else " on top, centred"),
    # "2 towers of four one left one right": one on each side
    (re.compile(r"\bone\s+(left|right)\s*,?\s*(?:and\s+)?(?:one|the\s+other)\s+(left|right)\b",
                re.I),
     lambda m: ("" if m.string[: m.start()].rstrip().endswith(",") else ", ")
     + f"one on the {m.group(1)} and one on the {m.group(2)}"
     if m.group(1).lower() != m.group(2).lower() else m.group(0)),
    # a ticket's short words: "pyr, 4 lvls, back rt", "ascend twd robot"
    (re.compile(r"\bpyr\b\.?", re.I), "pyramid"),
    (re.compile(r"\blvls?\b\.?", re.I), "levels"),
    (re.compile(r"\b(?:twd|twds|twrds)\b\.?", re.I), "towards"),
    # "stairs x4, up twd back": climbing towards the back (read as the table's back region)
    (re.compile(r"\b(up|climb\w*|ris(?:e|es|ing)|going\s+up)\s+(towards?|toward)\s+(back|front|left|right)\b",
                re.I), r"\1 \2 the \3"),
    # "bk R", "bk rt": a texter's back right
    (re.compile(r"\b(?:bk|bck)\b\.?(?=\s*(?:R|L|rt|lt|right|left|corner|side|edge|$|[,.;]))", re.I),
     "back"),
    (re.compile(r"(?<=\bback\s)(?-i:R)\b|(?<=\bfront\s)(?-i:R)\b"), "right"),
    (re.compile(r"(?<=\bback\s)(?-i:L)\b|(?<=\bfront\s)(?-i:L)\b"), "left"),
    (re.compile(r"\b(back|front|rear)\s+rt\b\.?|\brt\b(?=\s+(?:side|corner|of)\b)", re.I),
     lambda m: f"{m.group(1) or ''} right".strip()),
    (re.compile(r"\b(back|front|rear)\s+lt\b\.?|\blt\b(?=\s+(?:side|corner|of)\b)", re.I),
     lambda m: f"{m.group(1) or ''} left".strip()),
    (re.compile(r"\bascend(?:s|ing)?\b", re.I), "climbing"),
    # a warehouse's places: "the back-left bay", "the left lane", "front lane"
    (
        re.compile(
            r"\b((?:front|back|rear|left|right|middle|centre|center)(?:[- ](?:left|right))?)"
            r"\s+(?:lane|bay|zone|section|quadrant|strip)\b",
            re.I,
        ),
        r"\1",
    ),
    # a texter's "can u build like a tower of 5": you (read as a U shape like a tower: an error)
    (re.compile(r"\b(can|could|would|will|do|did|if|when|are|thank)\s+u\b(?![\s-]*(?:shape|shaped)\b)",
                re.I), r"\1 you"),
    (re.compile(r"\bidk\b", re.I), "I do not know"),
    (re.compile(r"\bidc\b", re.I), "I do not care"),
    (re.compile(r"\bdunno\b", re.I), "I do not know"),
    (re.compile(r"\blil\b", re.I), "little"),
    (re.compile(r"\bsmth\b|\bsth\b", re.I), "something"),
    (re.compile(r"\bshud\b", re.I), "should"),
    (re.compile(r"\bwud\b", re.I), "would"),
    (re.compile(r"\bcud\b", re.I), "could"),
    (re.compile(r"\bcn\s+u\b", re.I), "can you"),
    (re.compile(r"\b(?:u|ya)\s+(?=pick|choose|decide)", re.I), "you "),
    (re.compile(r"\b(\d+)\s*x\s+(?=[a-z]{3,})(?!by\b|cubes?\b)", re.I), r"\1 "),
]


# a programmer's notation: "tower(h=5)", "wall(len=5, h=2)", "block(2,2,2)", "box(dx=3, dy=2,
# dz=4)", "row(n=4)", "ring(outer=5x5, h=2)", "tower(h=2*3)": the family with its sizes in words
_CALL = re.compile(r"\b([a-z_]+)\(\s*([^()]*?)\s*\)", re.IGNORECASE)
_ARG_WORD = {
    "h": "high", "height": "high", "dz": "high", "z": "high", "levels": "levels", "lvls": "levels",
    "len": "long", "length": "long", "l": "long", "dx": "deep", "w": "wide", "width": "wide",
    "dy": "wide", "d": "deep", "depth": "deep", "steps": "steps", "legs": "legs", "n": "count",
    "count": "count", "num": "count", "outer": "", "size": "",
}  # fmt: skip


def _arg_value(value: str) -> str | None:
    product = re.fullmatch(r"(\d+)\s*\*\s*(\d+)", value)
    if product:
        return str(int(product.group(1)) * int(product.group(2)))
    plain = re.fullmatch(r"\d+(?:\.\d+)?(?:\s*(?:mm|cm|m))?|\d+x\d+(?:x\d+)?", value)
    return value if plain else None


def _call(m: re.Match[str], notes: list[str]) -> str:
    name, args = m.group(1).lower(), [a.strip() for a in m.group(2).split(",") if a.strip()]
    if name not in lx.SHAPE_WORDS and len(name) >= 3:
        # "wal(len=4)": what stands before the brackets can only be a family name
        near = [w for w in lx.SHAPE_WORDS if DamerauLevenshtein.distance(name, w) == 1]
        if len(near) == 1:
            notes.append(f"corrected '{m.group(1)}' to '{near[0]}'")
            name = near[0]
    if name not in lx.SHAPE_WORDS or not args:
        return m.group(0)
    plain = [_arg_value(a) for a in args]
    if all(plain):  # "block(2,2,2)": sizes in order
        return f" {name} {' x '.join(p for p in plain if p)} "
    words = []
    for arg in args:
        key, _, value = arg.partition("=")
        key, value = key.strip().lower(), _arg_value(value.strip())
        if key not in _ARG_WORD or value is None:
            return m.group(0)
        word = _ARG_WORD[key]
        words.append(f"of {value}" if word == "count" else f"{value} {word}".strip())
    out = f" {name} {' , '.join(words)} "
    notes.append(f"read '{m.group(0)}' as '{out.strip()}'")
    return out


_OPPOSITES = re.compile(
    r"\b(?:(front|back)\s*[-–/]\s*(back|front)|(left|right)\s*[-–/]\s*(right|left))\b", re.I
)  # "front-back", "left/right": from one to the other; "back-left" is a corner
_FILLER_WORD = r"(?:u+h+|u+m+|e+r+m*|h+m+)"
"""'uh', 'um', 'er', 'hmm': a sound, nothing to read."""
_FILLERS = re.compile(
    r"\b" + _FILLER_WORD + r"\b,?|[\u2600-\u27bf\U0001f300-\U0001faff\u2b50\u2b55\u274c\u2705"
    r"\ufe0f\u200d]"
)
_DANGLING = re.compile(
    r"\b(the|a|an|to|of|on|in|at|by|with|is|are|its|their|some)\s*,\s*(?:" + _FILLER_WORD
    + r"|like|you\s+know)\s*,\s*|(?<=,)\s*(?:like|you\s+know)\s*,",
    re.IGNORECASE,
)
"""A filler between commas after an article or preposition ("up to the, um, left"), and its
commas; ", like," alone."""
# "0.30,0.45,tower 2": a spreadsheet row of x, y and what stands there
_CSV_AT = re.compile(
    r"(?:\bx\s*,\s*y\s*,\s*(?:structure|shape|item|what)\b\s*[/\n]?\s*)?"
    r"\b(0?\.\d+|\d(?:\.\d+)?)\s*,\s*(0?\.\d+|\d(?:\.\d+)?)\s*,\s*"
    r"([a-z][\w -]*?)(?=\s*(?:/|\n|$|;))",
    re.IGNORECASE,
)


def _csv_at(m: re.Match[str]) -> str:
    return f" ; {m.group(3)} at x = {m.group(1)} m, y = {m.group(2)} m ; "


# "qty: 3 / item: tower": how many of the structure the line describes
_QUANTITY = re.compile(
    r"\b(?:qty|quantity|count|no\.\s*of\s+units)\s*[:=]\s*(\d+)\b\s*[/,;]?", re.I
)


def _quantity(m: re.Match[str], notes: list[str] | None, found: list[int]) -> str:
    n = int(m.group(1))
    if n > 1:
        found.append(n)
    return " "


# a word that starts a noun phrase: "of to" before it is a preposition ("next to the wall")
_NOT_A_NOUN_NEXT = (
    r"(?!\s+(?:the|a|an|it|its|them|this|that|these|those|each|every|my|our|your|me|us|him|"
    r"her|one|both|either|left|right|front|back)\b)"
)

_TREE = re.compile(
    r"\btree\s+(?=" + _COUNTED + r"\b|floors\b|tiers\b|high\b|tall\b|long\b|wide\b)"
    r"|(?<=\bof\s)tree\b" + _NOT_A_NOUN_NEXT,
    re.I,
)
_WON = re.compile(
    r"\bwon\s+(?=(?:cube|block|tower|stack|row|wall|pillar|column|beam|step|level|layer|more)\b)",
    re.I,
)

_SAID_NUMBER = _NUM + r"\b"
# what a speech recogniser writes for a structure word, where only that word fits: "a tour of
# five cubes", "two tours of 3", "a peer amid", "a stare case", "a 3 by 3 slap", "a rope of 6"
_SHAPE_HEARD = [
    (re.compile(r"\b(?:peer|pier|pair|pierre)\s+a\s*mid(s?)\b", re.I), r"pyramid\1"),
    (re.compile(r"\b(?:stare|stair)[\s-]+case(s?)\b", re.I), r"staircase\1"),
    (re.compile(r"\btour(s?)\b(?=\s+(?:of\s+)?" + _SAID_NUMBER + r")", re.I), r"tower\1"),
    (re.compile(r"(?:(?<=\d\s)|(?<=\btwo\s)|(?<=\bthree\s)|(?<=\bfour\s)|(?<=\bfive\s))"
                r"tour(s?)\b", re.I), r"tower\1"),
    (re.compile(r"\bslap(s?)\b(?=\s+(?:of\s+)?" + _SAID_NUMBER + r")|(?<=\d\s)slap(s?)\b", re.I),
     r"slab\1\2"),
    (re.compile(r"\brope(s?)\b(?=\s+of\s+" + _SAID_NUMBER + r")", re.I), r"row\1"),
]  # fmt: skip

_SAID_DIGIT = {w: str(n) for w, n in _DIGITS.items() if n <= 9} | dict.fromkeys(
    ("nought", "oh", "o"), "0"
)
_DIGITS_SAID = r"(?:zero|nought|oh|o|one|two|three|four|five|six|seven|eight|nine|\d)"
_SPOKEN_DECIMAL = re.compile(
    rf"(?:(?<=\bx\s)|(?<=\by\s)|(?<=\bat\s)|(?<=[=:]\s)|(?<=\bis\s)|\b(?=zero\b|nought\b))"
    rf"(?:(zero|nought|oh|\d)[\s-]+)?point[\s-]+({_DIGITS_SAID}(?:[\s-]+{_DIGITS_SAID})?)\b",
    re.I,
)
"""A decimal said as a speech recogniser writes it: "x zero point three five", "y point two"."""


def _spoken_decimal(m: re.Match[str]) -> str:
    digits = "".join(_SAID_DIGIT.get(w.lower(), w) for w in re.split(r"[\s-]+", m.group(2)))
    whole = _SAID_DIGIT.get((m.group(1) or "0").lower(), m.group(1) or "0")
    return f"{whole}.{digits}"


_HOMOPHONES: list[tuple[re.Pattern[str], _Repl]] = [
    (_SPOKEN_DECIMAL, _spoken_decimal),
    (re.compile(r"\b(?:to|too)\s+(?=" + _COUNTED + r"\b|by\s+(?:to|too|two|\d|one|three|tree|four|"
                r"for|five|six|seven|eight|nine|ten)\b)", re.I), "two "),
    # "a u shape five wide with arms too long": only a number fits there
    (re.compile(r"\b(arms|legs|sides|pillars|posts|wings)\s+(?:to|too)\s+(?=(?:long|high|tall|"
                r"wide|deep)\b)", re.I), lambda m: f"{m.group(1)} two "),
    (re.compile(r"(?<=\bby\s)(?:to|too)\b", re.I), "two"),
    # "Wall, length six, height too. Break.": a size key then its value, spoken
    (re.compile(r"\b(height|length|width|depth|levels|steps|layers)\s*(?:=|:|is|of)?\s+(?:to|too)\b"
                r"(?=\s*(?:[,.;!]|$|and\b|then\b|over\b))", re.I), lambda m: f"{m.group(1)} two"),
    (re.compile(r"\bfor\s+(?=" + _COUNTED + r"\b|high\b|tall\b|long\b|wide\b)", re.I), "four "),
    (re.compile(r"(?<=\bof\s)for\s*$", re.I), "four"),
    (re.compile(r"\bate\s+(?=" + _COUNTED + r"\b)", re.I), "eight "),
    # a child's spelling by ear: "a litle won", "fore towrs", "on the rite", "sum stares"
    (
        re.compile(
            r"(?<!\bi\s)(?<!\bwe\s)(?<!\bhas\s)(?<!\bhave\s)(?<!\bhad\s)\bwon\b"
            r"(?=\s+(?:of|more|cube|block|on|next|rite|right|left)\b|\s*[!.,]|\s*$)",
            re.I,
        ),
        "one",
    ),
    (re.compile(r"\bfore\s+(?=" + _COUNTED + r"\b)", re.I), "four "),
    (
        re.compile(
            r"\bsum\b(?=\s+(?:stairs|stares|steps|cubes|blocks|towers?|things?|bricks)\b)", re.I
        ),
        "some",
    ),
    (re.compile(r"(?<=\bthe\s)rite\b|\brite\b(?=\s+(?:next|side|of|hand|corner|end|edge)\b)|"
                r"(?<=\bback\s)rite\b|(?<=\bfront\s)rite\b", re.I), "right"),
    (re.compile(r"(?<=\bto\s)rite\b|(?<=\bon\s)rite\b", re.I), "right"),
    (
        re.compile(
            r"(?:(?<=\bsum\s)|(?<=\bsome\s)|(?<=\bthe\s)|(?<=\bmy\s)|(?<=\bof\s))stares\b", re.I
        ),
        "stairs",
    ),
    (re.compile(r"\bstares\b(?=\s+(?:of|with|that|go|going)\b)", re.I), "stairs"),
    (re.compile(r"\bsick\s+(?=" + _COUNTED + r"\b|high\b|tall\b|long\b|wide\b)", re.I), "six "),
    # a speech recogniser's numbers: "a wall for long to high", "a tower of to in front of
    # it", "tree levels", "just won cube" (a number word where only a number fits)
    (re.compile(r"\bto\s+(?=(?:high|tall|long|wide|deep)\b)", re.I), "two "),  # not "too tall"
    # "three walls each for long too high", "each one too high": a size where only a number fits
    # (the height was lost: 'too' read as not about the structure)
    (re.compile(r"(?:(?<=\blong\s)|(?<=\bhigh\s)|(?<=\btall\s)|(?<=\bwide\s)|(?<=\beach\s)"
                r"|(?<=\beach\sone\s))too\s+(?=(?:high|tall|long|wide|deep)\b)", re.I), "two "),
    (re.compile(r"(?<=\bof\s)(?:to|too)\b" + _NOT_A_NOUN_NEXT, re.I), "two"),
    (re.compile(r"(?<=\bof\s)for\b" + _NOT_A_NOUN_NEXT, re.I), "four"),
    (_TREE, "three "),
    (_WON, "one "),
    # "of each height from won to for", "going up by won each starting at too", "ate long",
    # "towers of ate", "for by tree"
    (re.compile(r"(?<=\bfrom\s)won\b|(?<=\bby\s)won\b", re.I), "one"),
    (re.compile(r"(?<=\bto\s)for\b(?=\s*(?:[,.;!]|$|and\b|then\b))", re.I), "four"),
    (re.compile(r"(?<=\bat\s)too\b(?=\s*(?:[,.;!]|$|from\b|and\b|on\b|in\b))", re.I), "two"),
    (
        re.compile(
            r"\bate\s+(?=(?:long|high|tall|wide|deep|by)\b)|(?<=\bof\s)ate\b|(?<=\bby\s)ate\b", re.I
        ),
        "eight ",
    ),
    (
        re.compile(r"\bfor\s+(?=by\s+(?:\d|tree|three|too|two|to|for|four|five|six)\b)", re.I),
        "four ",
    ),
    (re.compile(r"(?<=\bby\s)tree\b", re.I), "three"),
    (re.compile(r"(?<=\d)\s+bye\s+(?=\d)", re.I), " by "),
    # radio voice procedure (ICAO): "fower", "fife", "niner", "wun"; "height tree"
    (re.compile(r"\bfower\b", re.I), "four"),
    (re.compile(r"\bfife\b", re.I), "five"),
    (re.compile(r"\bniner\b", re.I), "nine"),
    (re.compile(r"\bwun\b", re.I), "one"),
    (
        re.compile(
            "|".join(
                rf"(?<=\b{w}\s)tree\b"
                for w in (
                    "height",
                    "length",
                    "width",
                    "depth",
                    "quantity",
                    "count",
                    "levels",
                    "steps",
                )
            ),
            re.I,
        ),
        "three",
    ),
    (re.compile(r"\b(?:el|ell)\s+(?=shape|shaped)", re.I), "L "),
    (re.compile(r"\btee\s+(?=shape|shaped)", re.I), "T "),
]


_UNIT_SAID = r"(?:mm|cm|m|millimet(?:re|er)s?|centimet(?:re|er)s?|met(?:re|er)s?|cubes?)"
_MEASURE = rf"(\d+(?:\.\d+)?\s*{_UNIT_SAID}?)(?!\w|\.\d)"
_DIM_WORD = {"length": "long", "height": "high", "width": "wide", "depth": "deep",
             "thickness": "thick", "l": "long", "h": "high", "w": "wide", "d": "deep"}  # fmt: skip
# "with length of 0.3 meter and height of 0.1 meter": the value with its dimension word
_HIGH_LEVELS = re.compile(
    r"\b(\d+)\s+high\s+(?:courses|layers|levels|storeys|stories|floors|tiers|cubes)\b", re.I
)
_NAMED_DIM = re.compile(
    r"\b(?:with\s+)?(?:a\s+)?(length|height|width|depth|thickness)\s+(?:of\s+|is\s+|[:=]\s*)?"
    + _MEASURE
    + r"(?!\s*(?:high|tall|long|wide|deep|thick)\b)",  # "the same width, 3 high": a height
    re.IGNORECASE,
)
# "4 cubes in the length and 3 in the height", "in the height of 20 cm": a value with its
# dimension, said the way many non-native speakers say it
_IN_THE_DIM = re.compile(
    _MEASURE + r"\s+in\s+(?:the\s+)?(length|height|width|depth|thickness)\b", re.IGNORECASE
)
_IN_THE_DIM_OF = re.compile(
    r"\bin\s+(?:the\s+)?(length|height|width|depth|thickness)\s+of\s+" + _MEASURE, re.IGNORECASE
)
# "the height is the double of 4 cubes": that value, doubled
_DOUBLE_OF = re.compile(
    r"\b(?:the\s+)?(double|twice|triple|thrice)\s+(?:of\s+)?(?:the\s+)?(\d+)(?=\s*(?:cubes?|"
    r"parts?|blocks?|bricks?|levels?|layers?|floors?|high|tall|long|wide)\b)",
    re.IGNORECASE,
)
# a drawing's "L 250 mm, H 100 mm" (capitals: "a h 3" is no height)
_LETTER_DIM = re.compile(
    r"(?<![\w=])(?<!\ban\s)(?<!\ba\s)([LHWD])\s*:?\s+" + _MEASURE + r"(?!\s*(?:by|x)\b)"
)


# "3 towers h=2/h=4/h=6", "h=2/4/6": a value per structure, said as a list
_LETTER_LIST = re.compile(
    r"\b([LHW])\s*=\s*(\d+)((?:\s*/\s*(?:[LHW]\s*=\s*)?\d+)+)(?!\s*(?:mm|cm|m)\b)", re.I
)


# "h=2", "L=5 cubes" (read before the "4 h" shorthand would take the h; not "W x D x H =")
_LETTER_EQ = re.compile(
    r"(?<!\bx\s)(?<!\bx)\b([LHWD])\s*=\s*(\d+(?:\.\d+)?)\s*(mm|cm|m|cubes?)?", re.IGNORECASE
)


# "ring 5x5 h2", "twr H4": a height written against its letter (the 2 was dropped, silently)
_H_JOINED = re.compile(r"(?<![\w.-])h(\d{1,2})\b(?!\s*(?:mm|cm|m)\b)", re.IGNORECASE)


def _letter_eq(m: re.Match[str]) -> str:
    return f" {m.group(2)} {m.group(3) or ''} {_DIM_WORD[m.group(1).lower()]} "


def _letter_list(m: re.Match[str]) -> str:
    values = [m.group(2), *re.findall(r"\d+", m.group(3))]
    return f" , {', '.join(values[:-1])} and {values[-1]} {_DIM_WORD[m.group(1).lower()]} "


def _dimensioned(m: re.Match[str]) -> str:
    """ "height of 20 cm" and "20 cm in the height" alike: the value, then its word."""
    first, second = m.group(1), m.group(2)
    dim, value = (first, second) if first.lower() in _DIM_WORD else (second, first)
    return f" {value.strip()} {_DIM_WORD[dim.lower()]} "


_SAID_LOOSELY = [
    # "a bench with legs of two and a beam": two legs and a beam across them, a bridge (a table
    # has four legs and a roof of beams)
    (re.compile(r"\b(bench|seat)\b(?=[^.;]*\blegs?\b[^.;]*\b(?:a|one|the)\s+(?:single\s+)?(?:beam|plank)\b)"
                r"(?![^.;]*\b(?:four|4)\s+legs\b)", re.I), "bridge"),
    # "two towers of 3 far apart": "far" was the back of the table and the gap one cube
    (re.compile(r"\b(?:far|wide|well|a\s+(?:good|long)\s+way)\s+apart\b", re.I),
     "3 cubes apart"),
    # "on each of its two short ends": its two ends
    (re.compile(r"\b(its|the|two|2|both)\s+(?:short|narrow|outer)\s+(ends)\b", re.I), r"\1 \2"),
    # "Lay a 3 by 3 footing and a pier …": the base a slab of its own (the pier took its size)
    (re.compile(r"(?:^|(?<=[.;:!?]\s)|(?<=\bbuild\s)|(?<=\blay\s)|(?<=\bput\s)|(?<=\bmake\s)|"
                r"(?<=\bplace\s))(?:down\s+)?(an?|one)\s+(\d+\s*(?:x|by)\s*\d+)\s+(?:\w+\s+)?"
                r"(?:base|foundation|footing)\b(?=\s*(?:,|and\b|then\b|;|\.|with\b))", re.I),
     r"\1 \2 slab"),
]
"""Readings of loose words, each said in a note."""


def _expand_noted(
    pairs: Sequence[tuple[re.Pattern[str], _Repl]], text: str, notes: list[str]
) -> str:
    """Each pattern replaced by its template (or what its function gives), each noted."""
    for pattern, repl in pairs:

        def expand(m: re.Match[str], repl: _Repl = repl) -> str:
            out = repl(m) if callable(repl) else m.expand(repl)
            if out != m.group(0):  # a function may leave what it matched as it was
                notes.append(f"read '{m.group(0).strip()}' as '{out.strip()}'")
            return out

        text = pattern.sub(expand, text)
    return text


# "side 20 cm, thick 10 cm", "high 3": the dimension word said before its value, as a list item
# "wall, long 6, high 2", "a wall long 7 and high 2", "a block large 3": the size word first
_DIM_FIRST = re.compile(
    r"(^|[,;:]\s*|\band\s+|\b(?:" + _FAMILY_SAID + r")\s+)(thick|high|tall|long|wide|deep|large|"
    r"broad)\s+(\d+(?:\.\d+)?\s*" + _UNIT_SAID + r"?)(?=\s*(?:$|[,;.]|\band\b))",
    re.IGNORECASE,
)

_LARGE = {"large": "wide", "broad": "wide"}  # "a block large 3": as wide

_NUM_WORD = r"(?:\d+|two|three|four|five|six|seven|eight|nine|ten)"
_N_ON_M = re.compile(
    rf"\b({_NUM_WORD})\s+on\s+({_NUM_WORD})(?:\s+on\s+({_NUM_WORD}))?\b(?!\s*(?:cubes?|blocks?|"
    r"parts?|towers?|levels?|layers?|of\b|the\b))",
    re.IGNORECASE,
)
_BASE_AND = re.compile(
    rf"\b(base|footprint|bottom|size)(\s+(?:is|of|=|:)\s*|\s+)({_NUM_WORD})\s+and\s+({_NUM_WORD})\b"
    r"(?!\s*(?:high|tall|levels?|layers?|cubes?\s+high))",
    re.IGNORECASE,
)
"""'base is four and four': its two sides (the base was read as 4, the second 4 dropped)."""


def _n_by_m(m: re.Match[str]) -> str:
    third = f" by {m.group(3)}" if m.group(3) else ""  # "block 2 on 2 on 2"
    return f"{m.group(1)} by {m.group(2)}{third}"


# a drawing's words for a gap between faces (SDI's gaps are between faces): "clear gap 300 mm",
# "50 mm clear", "clearance 2 cubes"; and "no infill" of what is hollow anyway
_CLEAR = [
    (re.compile(r"\bclear\s+(?=(?:gap|space|distance|spacing)\b)", re.I), ""),
    (
        re.compile(
            r"((?:\d+(?:\.\d+)?|a|one|two|three|four)\s*(?:mm|cm|m|cubes?|parts?))\s+"
            r"clear(?:ance)?\b",
            re.I,
        ),
        r"\1 gap",
    ),
    (re.compile(r"\bclearance\b", re.I), "gap"),
    (re.compile(r"\b(?:no|without)\s+(?:infill|fill|filling)\b|\bunfilled\b", re.I), "hollow"),
]

_AXES_LABEL = re.compile(
    r"\(\s*(?:length|width|height|depth|[lwdh])(?:\s*[x×*,/]\s*(?:length|width|height|depth|"
    r"[lwdh]))+\s*\)|\b[lwdh]\s*[x×*]\s*[lwdh](?:\s*[x×*]\s*[lwdh])?\s*[=:]",
    re.IGNORECASE,
)


_VALUE = r"\d+(?:\.\d+)?\s*(?:mm|cm|m)?"
_LABEL = r"(?:length|width|height|depth|[lwdh])"
_LABELLED = re.compile(
    rf"(?P<values>{_VALUE}(?:\s*[x×*]\s*{_VALUE}){{1,2}})\s*\(?\s*"
    rf"(?P<labels>{_LABEL}(?:\s*[x×*]\s*{_LABEL}){{1,2}})\s*\)?(?!\w)",
    re.IGNORECASE,
)
_LETTERED_ONE = r"([LWHD])\s*[=:]?\s*(\d+(?:\.\d+)?(?:\s*(?:mm|cm|m)\b)?)"
_LETTERED = re.compile(
    rf"(?-i:\b{_LETTERED_ONE}(?:\s*[x×*,]\s*|\s+){_LETTERED_ONE}(?:(?:\s*[x×*,]\s*|\s+){_LETTERED_ONE})?)"
    r"(?!\w)"
)
"""'L3 x W2 x H2': each value after the letter of its dimension (the 110 of a ticket key was
taken as the row's length, the sizes lost)."""
_AXIS_EACH_ONE = r"(\d+(?:\.\d+)?(?:\s*(?:mm|cm|m)\b)?)\s*\(\s*([xyz])\s*\)"
_AXIS_EACH = re.compile(
    rf"\b{_AXIS_EACH_ONE}\s*(?:by|x|×|\*)\s*{_AXIS_EACH_ONE}(?:\s*(?:by|x|×|\*)\s*{_AXIS_EACH_ONE})?",
    re.IGNORECASE,
)
"""'4 (x) by 2 (y) by 1 (z)': each value the size along the cell's axis after it (x away from the
robot, y across, z up); it was read as a count of 4."""
_XYZ_LABEL = re.compile(r"\(\s*x\s*[x×*]\s*y(\s*[x×*]\s*z)?\s*\)", re.IGNORECASE)
_DIMENSION_OF = {"l": "long", "w": "wide", "h": "high", "d": "deep"}
_AXIS_LABEL = {"x": "d", "y": "w", "z": "h"}  # x away from the robot, y across, z up


_SUM = re.compile(r"\b(\d+)\s*\+\s*(\d+)\b")


_SLASHES = re.compile(r"\b\d+(?:/\d+)+\b(?!\s*(?:mm|cm|m|of|metres?|meters?|inch(?:es)?)\b)")


_STRUCTURE_NOUNS = "|".join(
    sorted((w for w in {*lx.SHAPE_WORDS, *lx.PART_WORDS} if w.isalpha()), key=len, reverse=True)
)
# "build -2 towers": a count below zero (a coordinate "x = -0.2" is not a count)
_NEGATIVE_COUNT = re.compile(
    r"(?:^|(?<=[\s,;:(]))[-−](\d+)\s+(?:[a-z]+[- ])?(?:" + _STRUCTURE_NOUNS + r")s?\b",
    re.IGNORECASE,
)


# The largest number a command may carry; beyond it nothing SDI builds is meant.
_LARGEST = 1e6


_ANYWAY = re.compile(
    r"^(?P<aside>[^:]*?[.!?;]\s*)(?:so\s+|but\s+|ok(?:ay)?\s*,?\s*)?(?:anyway|anyhow|long\s+story\s+"
    r"short|enough\s+of\s+that|back\s+to\s+(?:work|business|the\s+job))\s*[:,.!-]\s*",
    re.IGNORECASE,
)
_BUILD_WORDS = re.compile(
    r"\b(?:build|make|put|place|stack|add|set|lay|give|want|need|\d+|one|two|three|four|five|six|"
    r"seven|eight|nine|ten)\b",
    re.IGNORECASE,
)


def _aside(text: str, notes: list[str]) -> str:
    """ "My grandmother had a clock shaped like a little temple. Anyway: a ring of cubes …":
    what is said before "anyway" is an aside — if it asks for nothing (no build verb, no number)
    and a structure is named after it."""
    m = _ANYWAY.match(text)
    if m is None or _BUILD_WORDS.search(m.group("aside")):
        return text
    rest = text[m.end() :]
    if not any(w in lx.SHAPE_WORDS for w in re.findall(r"[a-z]+", rest.lower())):
        return text
    marker = m.group(0)[m.end("aside") :].strip(" :,.!-")
    notes.append(f"ignored '{m.group('aside').strip()}': an aside before '{marker}'")
    return rest


_BARE_SIZE = re.compile(
    r"(?<![\w.,=#@:/-])(?P<n>\d{2,4})(?![\w.,]\d)(?!\s*(?:mm|cm|m\b|millimet|centimet|met|inch|in\b"
    r"|ft\b|feet|cubes?|blocks?|bricks?|parts?|pieces?|pcs|%|:|th\b|st\b|nd\b|rd\b|am\b|pm\b|"
    r"o'?clock|minutes?|mins?|hours?|seconds?|degrees?|deg\b|people|visitors|kids|children))"
    r"(?=\s*(?:long|high|tall|wide|deep|thick|square|across|apart|by\b|x\b|×|in\s+from|"
    r"out\s+from|off\s+the|centre|center|,?\s*(?:one|1)\s+course))",
    re.IGNORECASE,
)
_BARE_OF = re.compile(
    r"(?P<said>\b(?:tower|column|stack|wall|row|pillar|post|leg)s?\s+(?:of|o')\s+)(?P<n>\d{2,4})\b"
    r"(?!\s*(?:mm|cm|m\b|cubes?|blocks?|parts?))",
    re.IGNORECASE,
)
_BEAM_150 = re.compile(r"\b150\s*(?:mm\s+|mil\s+)?(?=beams?\b)", re.IGNORECASE)
_BARE_PAIR = re.compile(
    r"(?<![\w.,=#@:/-])(\d{2,4})\s*(by|x|×)\s*(\d{2,4})(?![\w.,]\d)(?!\s*(?:mm|cm|m\b|millimet|"
    r"centimet|met|inch|in\b|ft\b|feet|cubes?|blocks?|bricks?|parts?|%))",
    re.IGNORECASE,
)
_BARE_TRIPLE = re.compile(
    r"(?<![\w.,=#@:/-])(\d{2,4})\s*(by|x|×)\s*(\d{2,4})\s*(by|x|×)\s*(\d{2,4})(?![\w.,]\d)"
    r"(?:\s*(mm|cm|millimet(?:er|re)s?|centimet(?:er|re)s?)\b)?",
    re.IGNORECASE,
)
"""A drawing's size triple, "200 × 200 × 50", "150 x 100 x 100 mm": one unit for all three."""
_LABELLED_TRIPLE = re.compile(
    r"\b([LWH])\s*[x×*]\s*([LWH])\s*[x×*]\s*([LWH])\s*[=:]?\s*(\d{1,4})\s*[x×*]\s*(\d{1,4})\s*[x×*]"
    r"\s*(\d{1,4})(?:\s*(mm|cm)\b)?",
    re.IGNORECASE,
)
"""A drawing's "L × W × H = 150 × 100 × 100 mm": each size by its label (mm unless said)."""
_TRIPLE_LABELLED = re.compile(
    r"\b(\d{2,4})\s*([LWH])\s*[x×*]\s*(\d{2,4})\s*([LWH])\s*[x×*]\s*(\d{2,4})\s*([LWH])\b"
    r"(?:\s*(mm|cm)\b)?"
)
"""A drawing's "300 L × 50 W × 100 H": each size followed by its label."""
_DIAMETER = re.compile(r"[Øø⌀]\s*(\d{2,4})\b(?:\s*mm\b)?")
_DRAWING_LABEL = re.compile(r"\b([HLW])\s*=?\s*(\d{2,4})\b(?!\s*(?:mm|cm|m\b|x\b|×|by\b))")
"""A drawing's labelled size, "Column H 250": that many millimetres high (long, wide)."""
_DRAWN = {"H": "high", "L": "long", "W": "wide"}


def _drawn_mm(said: str) -> bool:
    """A bare number that can only be millimetres: a round 50 or more (no count of parts)."""
    return said.isdigit() and int(said) >= 50 and int(said) % 10 == 0
_SAME_UNIT = re.compile(
    r"(?P<said>\b\d+(?:\.\d+)?\s*(?:cm|centimet(?:er|re)s?)\s+(?:long|high|tall|wide|deep)\s*"
    r"(?:,|and|,\s*and|by|x)\s*)(?P<v>\d+)\s+(?P<dim>long|high|tall|wide|deep)\b",
    re.IGNORECASE,
)
_BARE_APART = re.compile(
    r"(?P<lead>(?:^|[,;:]|\band)\s*|(?<=[a-z])\s+)(?P<n>\d{1,2}|one|two|three|four|five)\s+apart\b",
    re.IGNORECASE,
)
_NOT_A_SIZE_BEFORE = re.compile(
    r"\b(?:job|station|cycle|shift|wo|no|number|line|cell|bay|order|ticket|room|batch|sheet|"
    r"exercise|entry|step|x|y|at|ref|part|sku|item)\s*[#:.]?\s*$",
    re.IGNORECASE,
)


def _drawing_sizes(text: str, notes: list[str]) -> str:
    """A drawing's sizes: "L × W × H = 150 × 100 × 100 mm" each by its label, "Column Ø50"
    one cube across (read before the letters are read as words)."""

    def labelled_triple(m: re.Match[str]) -> str:
        unit = (m.group(7) or "mm").lower()
        said = [f"{m.group(4 + k)} {unit} {_DRAWN[m.group(1 + k).upper()]}" for k in range(3)]
        notes.append(f"read '{m.group(0).strip()}' as {', '.join(said)}")
        return ", ".join(said)

    def diameter(m: re.Match[str]) -> str:
        n = int(m.group(1))
        notes.append(f"read '{m.group(0).strip()}' as {n} mm across")
        return "" if n == 50 else f"{n} mm wide"

    def triple_labelled(m: re.Match[str]) -> str:
        unit = (m.group(7) or "mm").lower()
        said = [f"{m.group(1 + 2 * k)} {unit} {_DRAWN[m.group(2 + 2 * k)]}" for k in range(3)]
        notes.append(f"read '{m.group(0).strip()}' as {', '.join(said)}")
        return ", ".join(said)

    text = _LABELLED_TRIPLE.sub(labelled_triple, text)
    text = _TRIPLE_LABELLED.sub(triple_labelled, text)
    text = re.sub(r"\bcent(?:re|er)[\s-]?line\s+(?=at\b)", "centred ", text, flags=re.I)
    return _DIAMETER.sub(diameter, text)


def _bare_millimetres(text: str, notes: list[str]) -> str:
    """ "Wall, 350 long by 150 high", "a tower of 150", "Block, 100 by 100": a size of 50 or
    more without a unit, a round number, is in millimetres — no structure of the cell is 50
    parts along anything (a count of parts, a coordinate, a job number is left alone)."""

    def labelled(m: re.Match[str]) -> bool:  # "job 2207", "x 450": no size
        return bool(_NOT_A_SIZE_BEFORE.search(m.string[max(0, m.start() - 12) : m.start()]))

    def mm(m: re.Match[str]) -> str:
        n = int(m.group("n"))
        if not _drawn_mm(m.group("n")) or labelled(m):
            return m.group(0)
        notes.append(f"read {n} without a unit as {n} mm")
        return f"{m.groupdict().get('said') or ''}{n} mm"

    def beam(m: re.Match[str]) -> str:
        notes.append(f"read '{m.group(0).strip()} beam' as a beam (the cell's beams are 150 mm)")
        return ""

    text = _BEAM_150.sub(beam, text)

    def pair(m: re.Match[str]) -> str:  # "Block, 100 by 100": both in millimetres
        if not all(_drawn_mm(v) for v in (m.group(1), m.group(3))) or labelled(m):
            return m.group(0)
        notes.append(f"read {m.group(1)} and {m.group(3)} without a unit as millimetres")
        return f"{m.group(1)} mm {m.group(2)} {m.group(3)} mm"

    def triple(m: re.Match[str]) -> str:  # "Plate 200 × 200 × 50": all three in millimetres
        values = (m.group(1), m.group(3), m.group(5))
        unit = (m.group(6) or "").lower()
        if unit.startswith(("cm", "centi")):
            return f"{values[0]} cm {m.group(2)} {values[1]} cm {m.group(4)} {values[2]} cm"
        if not unit and (not all(_drawn_mm(v) for v in values) or labelled(m)):
            return m.group(0)
        if not unit:
            notes.append(f"read {' × '.join(values)} without a unit as millimetres")
        return f"{values[0]} mm {m.group(2)} {values[1]} mm {m.group(4)} {values[2]} mm"

    text = _BARE_TRIPLE.sub(triple, text)

    def drawing(m: re.Match[str]) -> str:  # "Column H 250": 250 mm high
        n = int(m.group(2))
        if not _drawn_mm(m.group(2)):
            return m.group(0)
        notes.append(f"read '{m.group(0)}' as {n} mm {_DRAWN[m.group(1)]}")
        return f"{n} mm {_DRAWN[m.group(1)]}"

    text = _DRAWING_LABEL.sub(drawing, text)
    text = _BARE_PAIR.sub(pair, text)

    def same_unit(m: re.Match[str]) -> str:  # "15 cm high and 25 long": 25 cm too
        v = float(m.group("v"))
        if v < 10 or v % 5:
            return m.group(0)
        notes.append(f"read {m.group('v')} as {m.group('v')} cm, the unit said before it")
        return f"{m.group('said')}{m.group('v')} cm {m.group('dim')}"

    text = _SAME_UNIT.sub(same_unit, text)

    def apart(m: re.Match[str]) -> str:  # "two towers of 3, 2 apart": a gap said in parts
        n = int(words_to_numbers([m.group("n").lower()])[0])
        unit = "cubes" if n <= 5 else "cm" if n % 5 == 0 and n < 50 else None
        if unit is None:
            return m.group(0)
        notes.append(f"read '{m.group(0).strip()}' as {n} {unit} apart")
        return f"{m.group('lead')}{n} {unit} apart"

    text = _BARE_APART.sub(apart, text)

    return _BARE_OF.sub(mm, _BARE_SIZE.sub(mm, text))


_TAKEN_BACK_THERE = re.compile(
    r"\b(?:strike|undo|scratch|scrap|remove|cancel|take\s+(?:it|that)\s+(?:away|down))\b"
    r"(?:\s+(?:it|that|this))?(?P<mid>[^.;]{0,60}?)\bthere\b",
    re.IGNORECASE,
)
_PLACE_SAID = re.compile(
    r"\b(?:at|on|in|across|along|to)\s+the\s+(?:far\s+)?(?:front|back|rear|left|right|middle|centre|"
    r"center)(?:[\s-]+(?:left|right))?(?:\s+(?:edge|side|corner|half|end))?\b",
    re.IGNORECASE,
)


def _there(text: str, notes: list[str]) -> str:
    """ "a wall across the back. Then strike it and put a tower there instead": there is where
    the structure taken back was said to stand."""
    m = _TAKEN_BACK_THERE.search(text)
    if m is None:
        return text
    places = list(_PLACE_SAID.finditer(text[: m.start()]))
    if not places:
        return text
    place = places[-1].group(0)
    notes.append(f"read 'there' as '{place}', where the structure taken back stood")
    return text[: m.end() - len("there")] + place + text[m.end() :]


_ALONE = re.compile(
    r"\b(?:a|one)\s+(cube|block|brick)\s+(?:alone|on\s+its\s+own|by\s+itself|all\s+alone)\b", re.I
)
_ORDINAL_WORD = {"1": "first", "2": "second", "3": "third", "4": "fourth", "5": "fifth",
                 "6": "sixth", "7": "seventh", "8": "eighth", "9": "ninth",
                 "10": "tenth"}  # fmt: skip
_ORDINAL_FIGURE = re.compile(r"\b(10|[1-9])(?:st|nd|rd|th)\b(?=\s+[a-z])", re.IGNORECASE)


_ITEM_LABEL = re.compile(
    r"\bitem\s*(\d+)\s*[:.)-]?\s*(?:\d+x\s+)?(" + _FAMILY_SAID + r")\b", re.I
)
_ITEM_REF = re.compile(
    r"\b(of|to|on|beside|from|behind|with)\s+item\s*(\d+)\b(?!\s*[:.)-]?\s*[a-z])", re.I
)


def _items_named(text: str) -> str:
    """A work order's "ITEM 2 TOWER … ADJACENT TO LEFT END OF ITEM 1": the structure labelled
    item 1 (the label was read as a reference number, and "of item 1" as nothing)."""
    named = {m.group(1): m.group(2).lower() for m in _ITEM_LABEL.finditer(text)}
    return _ITEM_REF.sub(
        lambda m: f"{m.group(1)} the {named[m.group(2)]}" if m.group(2) in named else m.group(0),
        text,
    )


_NOT_A_NAME = frozenset({
    "me", "us", "you", "i", "we", "it", "please", "pls", "build", "make", "put", "stack", "lay",
    "set", "place", "create", "give", "want", "need", "do", "let's", "lets", "now", "next",
    "then", "first", "here", "so", "ok", "okay", "can", "could", "would", "will", "is", "are",
    "of", "for", "with", "on", "in", "at", "to", "my", "our", "your", "some", "new", "another",
    "a", "an", "the", "up", "instantiate", "generate", "produce", "construct", "assemble",
    "hollow", "solid", "flat", "open", "closed", "filled", "empty", "square", "round", "double",
    "single", "triple", "stepped", "upright", "standing", "lying", "free", "freestanding",
})  # fmt: skip
"""Words that make a heading a request or a sentence, or say something of the structure's
shape: not the name of a thing."""
_HEADING = re.compile(
    r"^[ \t]*((?:[a-z'-]+[ \t]+){0,3}?)([a-z]+)[ \t]*(?::|--|—|–|[ \t]-[ \t])[ \t]*(?=\S)", re.I
)


_ANSWERED = re.compile(
    r"(?:^|(?<=[.!?])\s)(?P<question>[^.!?]*\?)\s*(?P<yes>(?:yes|yeah|yep|yup|ok(?:ay)?|sure|right)\b\s*[,.!:;-]*\s*)",
    re.IGNORECASE,
)
"""'Should the wall be 2 high? Yes, let's do a wall 6 long and 2 high.': a question the command
answers itself (the question's wall was built as well)."""


def _answered(text: str, notes: list[str]) -> str:
    """A question answered "yes, …" by a sentence that names a structure itself: the answer is
    the build, the question goes (an answer that only refers back keeps it)."""
    m = _ANSWERED.search(text)
    if m is None:
        return text
    answer = re.split(r"[.!?](?:\s|$)", text[m.end() :])[0]
    asked = families_said(m.group("question"))
    if not asked or not families_said(answer):
        return text
    notes.append(f"read '{m.group('question').strip()}' as a question the words after it answer")
    return text[: m.start()] + " " + text[m.end("yes") :]


_VAGUE_THEN_SAID = re.compile(
    rf"\s*(?:[—–-]+|,|;|\.)\s*(?:say|let'?s\s+say|call\s+it|so)\s+({_NUM})\s+and\s+({_NUM})"
    r"(?:\s+(?:cubes?|blocks?|high|tall))?\s*(?=[.!]|$)",
    re.IGNORECASE,
)
"""'a tall tower … and a short one … — say five and two': the numbers for the vague sizes, in
order (the tall one was 6, the short one 5)."""


_VAGUE = r"(tall|short|high|low|taller|shorter|big|small|little|large|bigger|smaller)"
_VAGUE_ITEM = (
    r"the\s+" + _VAGUE + r"(?:\s+(?:one|tower|stack|column|pillar|post))?\s*,?\s*(?:is|has|gets|"
    r"should\s+be|must\s+be|:|=|of|with)?\s*(" + _NUM + r")(?:\s+(?:cubes?|blocks?|bricks?))?"
    r"(?:\s+(?:high|tall))?"
)
_VAGUE_EACH_SAID = re.compile(
    r"\s*(?:[—–-]+|,|;|:|\.)\s*" + _VAGUE_ITEM + r"\s*(?:,|;|\.)?\s*(?:and\s+)?" + _VAGUE_ITEM
    + r"\s*(?=[.!]|$)",
    re.IGNORECASE,
)
"""'a small tower in front of a big tower. The small has two cubes, the big has five': each
one's size said by the word it was named with (both were 2, or the big one lost)."""


def _vague_each_said(text: str, notes: list[str]) -> str:
    """Two structures named by a vague size ("the small tower … the big tower"), then each
    one's number said by that word ("the small one 2 cubes, the big one 5")."""
    m = _VAGUE_EACH_SAID.search(text)
    if m is None:
        return text
    said = {m.group(1).lower(): m.group(2), m.group(3).lower(): m.group(4)}
    before = text[: m.start()]
    vague = list(re.finditer(r"\b" + _VAGUE + r"\s+(?=(?:tower|stack|column|pillar|post|one)\b)",
                             before, re.I))  # fmt: skip
    if len(said) != 2 or sorted(v.group(1).lower() for v in vague) != sorted(said):
        return text
    out, at = [], 0
    for v in vague:
        value = words_to_numbers([said[v.group(1).lower()]])[0]
        out += [before[at : v.start()], f"{value}-high "]
        at = v.end()
    notes.append(f"read '{m.group(0).strip(' ,;:.—–-')}' as the sizes of the "
                 f"{' and the '.join(v.group(1).lower() for v in vague)} one")  # fmt: skip
    return "".join(out) + before[at:] + text[m.end() :]


def _vague_then_said(text: str, notes: list[str]) -> str:
    """Two sizes said vaguely ("a tall tower … a short one"), then two numbers for them."""
    m = _VAGUE_THEN_SAID.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    vague = list(re.finditer(r"\b(tall|short|high|low|taller|shorter|big|small|little)\s+(?=(?:to"
                             r"wer|stack|"
                             r"column|pillar|post|one)\b)", before, re.I))  # fmt: skip
    if len(vague) != 2:
        return text
    values = words_to_numbers([m.group(1).lower(), m.group(2).lower()])
    out, at = [], 0
    for v, value in zip(vague, values, strict=True):
        out += [before[at : v.start()], f"{value}-high "]
        at = v.end()
    first, second = (v.group(1).lower() for v in vague)
    notes.append(f"read '{m.group(0).strip(' ,;.—–-')}' as the sizes of the {first} and the "
                 f"{second} one")  # fmt: skip
    return "".join(out) + before[at:] + text[m.end() :]


_TWICE_NAMED = re.compile(
    r"\b(?:an?|the)\s+((?:[a-z]+[\s-]){0,2}?[a-z]+)\s*(?:,|\u2014|\u2013|\s-+\s)\s*(?:an?|the)\s+"
    r"((?:[a-z]+[\s-]){0,2}?[a-z]+)\s*(?=,|\u2014|\u2013|\s-+\s)",
    re.IGNORECASE,
)
"""'a plus sign — a cross — …', 'a cross-lap shape, a plus sign, …': one structure named twice."""


def _named_twice(text: str, notes: list[str]) -> str:
    """One structure named again in apposition: the second name goes (two were built)."""

    def family(words: str) -> list[str]:
        return families_said(re.sub(r"\bplus(?:\s+sign)?\b", "cross", words, flags=re.I))

    def once(m: re.Match[str]) -> str:
        first, second = family(m.group(1)), family(m.group(2))
        listed = re.match(r"\s*,\s*(?:and|or|plus|then)\b", m.string[m.end() :], re.I)
        if len(first) != 1 or first != second or listed:
            return m.group(0)  # "a tower, a stack, and a wall": a list
        if m.group(1).lower().split()[-1] == m.group(2).lower().split()[-1]:
            return m.group(0)  # "a tower, a tower, …": two of them
        dashed = not re.search(r",", m.group(0)) and not re.match(r"\s*,", m.string[m.end() :])
        named_as = re.search(r"\b(?:sign|shape|shaped|thing|profile|form)\b", m.group(0), re.I)
        if not (dashed or named_as):
            return m.group(0)  # "a wall, a low one, …" may be a list: only a dash or a name
        notes.append(f"read '{m.group(0).strip()}' as one {first[0]} named twice")
        return m.group(0)[: m.end(1) - m.start()]

    return _TWICE_NAMED.sub(once, text)


_LABELLED_ONE = re.compile(
    r"\b(wall|tower|row|block|slab|stack|column|pyramid|staircase|bridge|arch|ring|grid)\s+(?-i:([A-Z]))\b"
    r"(?!\s*(?:x|by|cm|mm|m|cubes?|blocks?|high|tall|long|wide|levels?|steps?)\b)",
    re.IGNORECASE,
)


def _labelled_again(text: str, notes: list[str]) -> str:
    """ "Build tower A, 3 high. Now make tower A 5 high instead.": a structure named by its
    label again is the one named before ("the tower"), not a second one."""
    seen: set[tuple[str, str]] = set()

    def again(m: re.Match[str]) -> str:
        key = (m.group(1).lower(), m.group(2))
        if key not in seen:
            seen.add(key)
            return m.group(0)
        if len({label for family, label in seen if family == key[0]}) > 1:
            return m.group(0)  # "tower A … tower B … tower A": which one stays the label's
        notes.append(f"read '{m.group(0)}' as the {m.group(1).lower()} named before")
        article = "" if re.search(r"\b(?:the|a|an)\s*$", m.string[: m.start()], re.I) else "the "
        return f"{article}{m.group(1)}"

    return _LABELLED_ONE.sub(again, text)


_COMPASS_SAID = re.compile(
    r"(?:^|(?<=[.;:!?])\s*)\s*(?:compass\s+convention\s*:\s*|grid\s+reference\s+style\s*,?\s*)?(?:with\s+|taking\s+|"
    r"treat(?:ing)?\s+|assume\s+|assuming\s+)?(?:(?P<north>north)\s+(?:is|=|at|as|being)\s+(?:the\s+)?(?P<side>"
    r"far\s+(?:side|edge|end)|back(?:\s+(?:edge|side))?|rear|away\s+from\s+the\s+robot|top|front|near\s+"
    r"(?:side|edge)|robot'?s?\s+side)(?:\s+of\s+the\s+(?:table|bench))?|(?:the\s+)?(?:far|back)\s+"
    r"(?:side|edge)\s+is\s+north)\s*[.:,;]?\s*",
    re.IGNORECASE,
)
_COMPASS = (
    (r"(?:to\s+the\s+|due\s+)?north\s+of", "behind"),
    (r"(?:to\s+the\s+|due\s+)?south\s+of", "in front of"),
    (r"(?:to\s+the\s+|due\s+)?east\s+of", "to the right of"),
    (r"(?:to\s+the\s+|due\s+)?west\s+of", "to the left of"),
    (r"north[\s-]*west(?:ern)?", "back left"), (r"north[\s-]*east(?:ern)?", "back right"),
    (r"south[\s-]*west(?:ern)?", "front left"), (r"south[\s-]*east(?:ern)?", "front right"),
    (r"north[\s-]+(?:to[\s-]+)?south", "back to front"),
    (r"south[\s-]+(?:to[\s-]+)?north", "front to back"),
    (r"east[\s-]+(?:to[\s-]+)?west", "right to left"),
    (r"west[\s-]+(?:to[\s-]+)?east", "left to right"),
    (r"northwards?|northward", "towards the back"), (r"southwards?|southward", "towards the front"),
    (r"eastwards?|eastward", "to the right"), (r"westwards?|westward", "to the left"),
    (r"north(?:ern)?", "back"), (r"south(?:ern)?", "front"), (r"east(?:ern)?", "right"),
    (r"west(?:ern)?", "left"),
)  # fmt: skip
_COMPASS_WORDS = tuple((re.compile(rf"\b{said}\b", re.I), place) for said, place in _COMPASS)
_FLIPPED = {"back": "front", "front": "back", "left": "right", "right": "left"}


def _compass(text: str, notes: list[str]) -> str:
    """North, south, east and west: north is the back (away from the robot) unless the command
    says otherwise ("North is the near side"); the convention said goes."""
    if not re.search(r"\b(?:north|south|east|west)", text, re.I):
        return text
    said = _COMPASS_SAID.search(text)
    side = said.group("side") if said else None
    near = bool(side and re.match(r"front|near|robot", side, re.I))
    if said:
        text = text[: said.start()] + " " + text[said.end() :]
    notes.append("read north as the front (the robot's side), east as the robot's left" if near
                 else "read north as the back (away from the robot), east as the robot's right")
    for pattern, place in _COMPASS_WORDS:
        if near:
            place = {"behind": "in front of", "in front of": "behind"}.get(place, " ".join(
                _FLIPPED.get(w, w) for w in place.split()))  # fmt: skip
        text = pattern.sub(place, text)
    return text


_HOURS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
          "nine": 9, "ten": 10, "eleven": 11, "twelve": 12}  # fmt: skip
_HOUR = r"(\d{1,2}|one|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)"
_ROBOT_AT = re.compile(
    r"(?:[^.;:]*?(?<!o')(?<!o’)\bclock\b[^.;:]*?)?\b(?:the\s+)?robot\s+(?:is\s+|stands\s+|sits\s+)?at\s+"
    + _HOUR
    + r"(?:\s*o['’]?\s*clock\b)?(?!\s*(?:cm|mm|m|cubes?)\b)\s*[.;:,]?\s*",
    re.IGNORECASE,
)
_AT_HOUR = re.compile(
    r"\b(?:at|to(?:wards?)?|on)\s+(?:the\s+|its\s+)?" + _HOUR + r"(?:\s*o['’]?\s*clock|\s+position|"
    r"(?P<bare>(?=\s*(?:[.;,!]|$))))",
    re.IGNORECASE,
)
_HOUR_PLACE = ("back", "back right", "back right", "right", "front right", "front right", "front",
               "front left", "front left", "left", "back left", "back left")  # fmt: skip
"""The place of each hour (12, 1, …, 11) with the robot at six o'clock: twelve is the far side."""


def _clock(text: str, notes: list[str]) -> str:
    """ "Picture the table as a clock with the robot at six o'clock. Put a tower of three at
    twelve o'clock": at the back (the hour was dropped, the tower put in the centre). The robot
    is at six unless the command says another hour."""
    hours = list(_AT_HOUR.finditer(text))
    if not hours:
        return text
    said = _ROBOT_AT.search(text)
    robot = 6
    if said:
        robot = _HOURS.get(said.group(1).lower()) or int(said.group(1))
        text = text[: said.start()] + " " + text[said.end() :]
        hours = list(_AT_HOUR.finditer(text))
    framed = said is not None or re.search(
        r"(?<!o')(?<!o’)(?<!o\s)(?<!\bo)\bclock\b|o['’]?\s*clock\s+position", text, re.I
    )
    out, end = [], 0
    for m in hours:
        near = re.findall(r"[a-z]+", text[: m.start()].lower())[-6:]
        if not framed and (m.group("bare") is not None or not families_said(" ".join(near))):
            continue  # "meet me at 5 o'clock": a time of day; "towards 12": a clock said first
        hour = _HOURS.get(m.group(1).lower()) or int(m.group(1))
        if not 1 <= hour <= 12 or not 1 <= robot <= 12:
            return text
        place = _HOUR_PLACE[(hour - robot + 6) % 12]
        notes.append(f"read '{m.group(0).strip()}' as the {place} (the robot at {robot} o'clock)")
        toward = m.group(0).lower().startswith("to")  # "climb towards 12": that way
        at = f" towards the {place} " if toward else f" at the {place} "
        if re.search(r"\bits\s", m.group(0), re.I):  # "at its three o'clock": beside it
            at = {"back": " behind it ", "front": " in front of it ", "left": " to its left ",
                  "right": " to its right "}.get(place, at)  # fmt: skip
        out.append(text[end : m.start()] + at)
        end = m.end()
    return "".join(out) + text[end:]


_AS_IT_IS = re.compile(
    r"\b(twice|double|three\s+times|thrice|half|just|exactly)\s+as\s+(long|wide)\s+as\s+it\s+is\s+"
    r"(?:high|tall)\b",
    re.IGNORECASE,
)
_HEIGHT_SAID = re.compile(
    rf"\b({_NUM})\s+(?:cubes?\s+|blocks?\s+|bricks?\s+|levels?\s+)?(?:high|tall)\b", re.I
)
_TIMES = FACTORS | {"three": 3.0}  # "three times as long"


def _as_it_is_high(text: str, notes: list[str]) -> str:
    """ "a wall twice as long as it is high, and 3 high": 6 long (the length was the default)."""
    m = _AS_IT_IS.search(text)
    if m is None:
        return text
    start = max(text.rfind(".", 0, m.start()), text.rfind(";", 0, m.start())) + 1
    ends = [i for i in (text.find(".", m.end()), text.find(";", m.end())) if i >= 0]
    heights = [h for h in _HEIGHT_SAID.finditer(text, start, min(ends, default=len(text)))
               if not m.start() <= h.start() < m.end()]  # fmt: skip
    if len(heights) != 1:
        return text
    high = int(words_to_numbers([heights[0].group(1).lower()])[0])
    value = high * _TIMES[m.group(1).lower().split()[0]]
    if value < 1 or value % 1:
        return text
    notes.append(f"read '{m.group(0)}' as {int(value)} {m.group(2).lower()} (it is {high} high)")
    return text[: m.start()] + f"{int(value)} {m.group(2).lower()}" + text[m.end() :]


_WHICH_ONE = (
    r"(?:the\s+)?(?:one\s+on\s+the\s+(?:left|right)|(?:left|right)(?:\s+one)?|first(?:\s+one)?|"
    r"second(?:\s+one)?|other(?:\s+one)?)"
)
_TIMES_THE_OTHER = re.compile(
    r"\b(two|2)\s+(towers|stacks|columns|pillars|posts|skyscrapers|piles)\s*[:,;-]*\s*"
    r"(?P<a>" + _WHICH_ONE + r")\s+(?:is\s+|being\s+)?(?P<times>twice|double|three\s+times|half)\s+"
    r"as\s+(?:tall|high)\s+as\s+(?P<b>" + _WHICH_ONE + r")\s*,?\s*(?:which|and\s+(?:the\s+\w+"
    r"(?:\s+one)?|that\s+one|it)|that)\s+(?:is|being|has)\s+(?P<n>" + _NUM + r")(?:\s+(?:cubes?|"
    r"blocks?|storeys?|stories|levels?|floors?))?(?:\s+(?:high|tall))?",
    re.IGNORECASE,
)
"""'two skyscrapers, the one on the left twice as tall as the one on the right, which is 3
storeys', 'two towers: the second is twice as tall as the first, and the first is 3'."""


def _times_the_other(text: str, notes: list[str]) -> str:
    """Two towers, one a multiple of the other, the other's size said after: both sized."""
    m = _TIMES_THE_OTHER.search(text)
    if m is None:
        return text

    def which(said: str) -> str:  # "the one on the left": left; "the first one": first
        return re.sub(r"^(?:the\s+)?(?:one\s+on\s+the\s+)?|\s+one$", "", said.lower())

    a, b = which(m.group("a")), which(m.group("b"))
    n = int(words_to_numbers([m.group("n").lower()])[0])
    factor = _TIMES[m.group("times").lower().split()[0]]
    if (n * factor) % 1 or a == b:
        return text
    sizes = {b: n, a: int(n * factor)}
    noun = "tower" if m.group(2).lower() == "skyscrapers" else m.group(2).lower().rstrip("s")
    if set(sizes) == {"left", "right"}:
        said = (f"a {noun} of {sizes['left']} on the left and a {noun} of {sizes['right']} on "
                "the right")  # fmt: skip
    elif set(sizes) <= {"first", "second", "other"}:
        first = sizes.get("first", sizes.get("other"))
        second = sizes.get("second", sizes.get("other"))
        said = f"a {noun} of {first} and a {noun} of {second}"
    else:
        return text
    notes.append(f"read '{m.group(0)}' as {said}")
    return text[: m.start()] + said + text[m.end() :]


_ORDINAL_AT = {w: int(n) for n, w in _ORDINAL_WORD.items()}
_FROM_SIDE = re.compile(
    r"\bthe\s+(first|second|third|fourth|fifth|last)(?:\s+(?:one|tower|stack|column|pillar|post))?\s+"
    r"from\s+the\s+(left|right|front|back)\b",
    re.IGNORECASE,
)
_SAID_CHANGED = (
    # "…, all 2 high, except the third which should be 4": a change of that one
    (re.compile(r"\s*,?\s*\bexcept\s+(?:for\s+)?the\s+(first|second|third|fourth|fifth|last)(?:\s+one)?\s*,?\s*"
                r"(?:which|that|who)\s+(?:should\s+be|is|must\s+be|will\s+be|has\s+to\s+be)\s+(?:height\s+)?(?="
                + _NUM + r"\b)", re.I), r". make the \1 one "),
    # "the second one should be 4 high", "make the second height four"
    (re.compile(r"(?:^|(?<=[.;,]\s)|(?<=[.;,]))\s*(?:and\s+|but\s+|then\s+)?the\s+(first|second|third|fourth|fifth|last)"
                r"\s+(?:one|tower|stack|column|pillar)\s+(?:should|must|has\s+to|needs\s+to)\s+be\s+(?:height\s+)?(?="
                + _NUM + r"\b)", re.I), r" make the \1 one "),
    (re.compile(r"\bmake\s+the\s+(first|second|third|fourth|fifth|last)(?:\s+one)?\s+(?:height|high)\s+(?:of\s+)?(?="
                + _NUM + r"\b)", re.I), r"make the \1 one "),
)


def _ordinal_from_side(text: str, notes: list[str]) -> str:
    """ "four towers in a line left to right, … the third from the left": the third in the
    order they were said (from the other end, counted back); only when the line's way was
    said (which one stands where is otherwise the composer's)."""
    text = _from_side(text, notes)
    for pattern, repl in _SAID_CHANGED:
        text = pattern.sub(repl, text)
    return text


def _from_side(text: str, notes: list[str]) -> str:
    m = _FROM_SIDE.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    way = re.search(r"\b(left|right|front|back)\s+to\s+(?:the\s+)?(left|right|front|back)\b",
                    before, re.I)  # fmt: skip
    count = re.search(rf"\b({_NUM})\s+(?:[a-z]+\s+)?(?:towers|stacks|columns|pillars|posts)\b",
                      before, re.I)  # fmt: skip
    if count is None or (way is None and re.search(
        r"\b(?:front|back|behind|on\s+the\s+(?:left|right)|at\s+the|corner|centre|center|middle)\b",
        before, re.I,
    )):  # fmt: skip
        return text
    # a line said no way: SDI stands them from right to left, in the order said
    first, last = (way.group(1).lower(), way.group(2).lower()) if way else ("right", "left")
    said = way.group(0) if way else "right to left, as SDI places a line said no way"
    n = int(words_to_numbers([count.group(1).lower()])[0])
    which, side = m.group(1).lower(), m.group(2).lower()
    at = n if which == "last" else _ORDINAL_AT[which]
    if side == last:
        at = n + 1 - at
    elif side != first:
        return text
    if not 1 <= at <= min(n, 10):
        return text
    notes.append(f"read '{m.group(0)}' as the {_ORDINAL_WORD[str(at)]} of the {n} said {said}")
    return text[: m.start()] + f"the {_ORDINAL_WORD[str(at)]} one" + text[m.end() :]


_SWAP = re.compile(
    r"(?:^|(?<=[.;!?,:\-\u2013\u2014])|\b(?:and|but|then)\b)\s*(?:(?:but|and|then|just|please|now)\s+)*"
    r"(?P<said>(?:swap|switch|flip|reverse|mirror|exchange|change)\s+(?:(?:the\s+)?sides|them(?:\s+round|\s+"
    r"around|\s+over)?|(?:the\s+|their\s+)?(?:left\s+and\s+right|places|positions)|the\s+places?\s+of\s+them|"
    r"it(?:\s+round|\s+around)))"
    r"(?:\s+(?:this\s+time|round|around|over))?(?:\s*,?\s*please)?\s*(?=$|[.;!?,])",
    re.IGNORECASE,
)
"""'a tower of 3 to the left of a wall. Swap sides this time.': the sides said before, the other
way round (it was refused: SDI cannot move what it built)."""


def _swapped(text: str, notes: list[str]) -> str:
    """The sides said before "swap sides", the other way round: left and right when a side was
    said that way, else front and back. Only when sides were said, and only once."""
    m = _SWAP.search(text)
    if m is None:
        return text
    before = text[: m.start()]
    said = re.findall(r"\b(left|right)\b", before, re.I) or re.findall(r"\b(front|back)\b",
                                                                        before, re.I)  # fmt: skip
    if not said:
        return text
    pair = ("left", "right") if said[0].lower() in ("left", "right") else ("front", "back")

    def other(w: re.Match[str]) -> str:
        flipped = _OTHER_SIDE[w.group(0).lower()]
        return flipped.capitalize() if w.group(0)[0].isupper() else flipped

    swapped = re.sub(rf"\b(?:{pair[0]}|{pair[1]})\b", other, before, flags=re.IGNORECASE)
    notes.append(f"read '{m.group('said')}' as {pair[0]} and {pair[1]} the other way round")
    return swapped + text[m.end() :]


_SIZE_SAID = rf"{_NUM}\s+(?:cubes?\s+|blocks?\s+)?(?:high|tall|long|wide|deep|layers?|levels?)"
_BASICALLY = re.compile(
    r"\s*(?P<sep>—|–|\s-+|,|;)\s*(?:(?:so|which\s+is|it'?s|that'?s|it\s+is|that\s+is)\s+)?(?P<said>"
    r"basically|essentially|effectively|in\s+effect|in\s+other\s+words|i\.\s?e\.)?\s*,?\s*(?:just\s+)?"
    r"an?\s+(?:(?:square|low|small|little|simple|flat|plain)\s+)?(?P<named>[a-z]+)"
    rf"(?P<rest>(?:\s*(?:,|and)\s*{_SIZE_SAID})*)\s*[.!]?\s*$",
    re.IGNORECASE,
)
# A family another name of which may be said after a dash: a barrier around a space is a ring
_KIN = {("wall", "enclosure"), ("bridge", "arch"), ("arch", "bridge"), ("row", "wall"),
        ("grid", "block")}  # fmt: skip


def _basically(text: str, notes: list[str]) -> str:
    """ "Extrude a rectangle 4 long x 1 thick to a height of 3 — basically a wall": the one
    structure said is the family named last (a slab and a second structure were built); after
    a bare dash only a kindred family ("Low barrier around a 3x3 floor area — a square ring,
    1 high")."""
    m = _BASICALLY.search(text)
    family = lx.SHAPE_WORDS.get(m.group("named").lower()) if m else None
    enclosing = r"\b(?:around|round|enclosing|surrounding)\b.*"  # what it encloses is not it
    named = families_said(re.sub(enclosing, "", text[: m.start()], flags=re.I)) if m else []
    if m is None or family is None or len(named) != 1:
        return text
    if not m.group("said") and (m.group("sep") in (",", ";") or (named[0], family) not in _KIN):
        return text  # "a slab of 3x3 — a tower, 4 high": a second structure
    said = [w for w in re.finditer(r"[a-z]+", text[: m.start()], re.I)
            if lx.SHAPE_WORDS.get(w.group(0).lower()) == named[0]]  # fmt: skip
    one = r"(?:^|\b(?:an?|one|the)\s)\s*(?:[\w-]+\s+){0,3}$"
    w = said[-1] if said else None
    if w is None or not re.search(one, text[: w.start()], re.I) or (
        w.group(0).lower().endswith("s") and w.group(0).lower()[:-1] in lx.SHAPE_WORDS
    ):
        return text  # "two rows of 3, basically a grid": which one is not a renaming
    notes.append(f"read '{m.group(0).strip(' —–-,;.!')}' as what the {w.group(0)} is: "
                 f"a {m.group('named')}")  # fmt: skip
    return (text[: w.start()] + m.group("named") + text[w.end() : m.start()] + m.group("rest")
            + text[m.end() :])


def _described(text: str) -> list[str]:
    """The families `text` names, a block ("a 2 by 3 block") among them."""
    block = ["block"] if re.search(r"\bblocks?\b", text, re.I) else []
    return [*families_said(text), *block]


def _named_heading(text: str, notes: list[str]) -> str:
    """ "Goods shed: a 3 by 4 enclosure, two high", "Tunnel portal -- an arch": a heading
    that names the thing (a word of its own before a structure noun) and the structure the
    words after it describe; the heading's noun is no second structure."""
    m = _HEADING.match(text)
    described = _described(text[m.end() :]) if m else []
    if m is None or not families_said(m.group(2)) or not described:
        return text
    first = re.split(r"\band\b|[.;]|,\s*(?:an?|one|two|three|four)\s", text[m.end() :],
                     maxsplit=1)[0]  # fmt: skip
    if not _described(first):
        return text  # "Graphic wall: 5 long, 4 high, and a plinth …": the wall's own sizes first
    said = [w.lower() for w in m.group(1).split()]
    listed = set(families_said(m.group(0))) <= set(described)
    if said[:1] in (["a"], ["an"], ["the"]):
        said = said[1:]
    told = set(_described(first))
    # "a garden border: a low wall …": a family of its own, then another one named (not
    # "Enclosure: outer 5x4, wall height 2", its walls)
    own = families_said(m.group(2)) and re.match(r"\s*(?:an?|one)\s", first, re.I)
    named = (not said and not families_said(m.group(2))) or own
    if named and len(told) == 1 and not told & {"tower", *families_said(m.group(2))}:
        # "The altar: a 2 by 3 block, two high": the heading's noun names what the words after
        # it describe as another structure (an altar is also a table; not "a bridge: 2 pillars
        # of 3, a beam across", which names its parts)
        notes.append(f"read '{m.group(0).strip(' :-—–')}' as the name of the {told.pop()} the "
                     "words after it describe")  # fmt: skip
        return text[m.end() :]
    if not said or any(
        w in lx.SIZE_WORDS or w in SIGNIFICANT or w in CORRECTABLE or w in NEGATIONS
        or w in _NOT_A_NAME or w in lx.REGION_WORDS or w in lx.DIMENSION_WORDS
        or w in lx.LEVEL_WORDS or w in lx.STEP_WORDS or w in lx.PART_WORDS
        or (w in ("and", "or") and not listed)
        for w in said
    ):  # fmt: skip
        return text  # "Small tower: …", "A hollow enclosure: …", "Build me a bridge: …"
    notes.append(f"read '{m.group(0).strip(' :-—–')}' as the name of what the words after it "
                 "describe")  # fmt: skip
    return text[m.end() :]


_HALF_OF = re.compile(r"\bhalf\s+of\s+(" + _NUM + r"|1[02468])\b", re.IGNORECASE)
_AS_MANY = re.compile(
    r"\b(twice|double|three\s+times|four\s+times)\s+as\s+many\s+((?:[a-z]+\s+)?)as\s+(" + _NUM
    + r")\b",
    re.IGNORECASE,
)
def _arithmetic(text: str, notes: list[str]) -> str:
    """A maths teacher's numbers: "half of eight", "twice as many towers as 2" — the number they
    come to, noted (read as 8 and as "many"; "one step fewer than 5" is `handlers._arith`'s)."""

    def n(said: str) -> int:
        return int(words_to_numbers([said.lower()])[0])

    def said_as(m: re.Match[str], value: int, rest: str = "") -> str:
        notes.append(f"read '{m.group(0).strip()}' as {value}{' ' + rest.strip() if rest else ''}")
        return f"{value} {rest}".rstrip() + " "

    def half(m: re.Match[str]) -> str:
        return said_as(m, n(m.group(1)) // 2) if n(m.group(1)) % 2 == 0 else m.group(0)

    def as_many(m: re.Match[str]) -> str:
        factor = {"twice": 2, "double": 2, "three": 3, "four": 4}[m.group(1).lower().split()[0]]
        return said_as(m, factor * n(m.group(3)), m.group(2))

    text = _HALF_OF.sub(half, text)
    return _AS_MANY.sub(as_many, text)


def normalise(command: str, notes: list[str] | None = None) -> str:
    """Symbols, contractions, number forms. Numbers SDI cannot use are refused here."""
    notes = notes if notes is not None else []
    text = command
    for a, b in _SYMBOLS.items():
        text = text.replace(a, b)
    text = text.replace("@", " at ")
    text = re.sub(r"\bontop\b", "on top", text, flags=re.IGNORECASE)
    text = _numbered_steps(text, notes)  # "1. a row of 3 2. a row of 2 on top of it"
    text = _items_named(text)  # "… END OF ITEM 1": the structure item 1 is
    text = _named_heading(text, notes)  # "Goods shed: a 3 by 4 enclosure": the enclosure
    text = _compass(text, notes)  # "North = back. A tower in the north-west corner."
    text = _clock(text, notes)  # "the robot at six o'clock … a tower at twelve o'clock"
    text = _swapped(text, notes)  # "a tower left of a wall. Swap sides.": right of it
    text = _answered(text, notes)  # "Should the wall be 2 high? Yes, a wall 6 long …"
    text = _named_twice(text, notes)  # "a plus sign — a cross — 1 in the middle …"
    text = _basically(text, notes)  # "a rectangle 4 long, 1 thick, 3 high — basically a wall"
    text = _ordinal_from_side(text, notes)  # "… left to right, the third from the left …"
    text = _vague_then_said(text, notes)  # "a tall tower and a short one — say five and two"
    text = _vague_each_said(text, notes)  # "… a big tower. The small has 2 cubes, the big 5."
    text = _as_it_is_high(text, notes)  # "a wall twice as long as it is high, and 3 high"
    text = _labelled_again(text, notes)  # "Build tower A, 3 high. Now make tower A 5 high."
    text = _times_the_other(text, notes)  # "… the second twice as tall as the first, … 3"
    text = _arithmetic(text, notes)  # "half of eight", "twice as many towers as 2"
    text = _ORDINAL_FIGURE.sub(lambda m: _ORDINAL_WORD[m.group(1)], text)  # "a 2nd row"
    text = _ALONE.sub(r"a single \1", text)  # "between them a cube alone": a cube, not a gap

    # "Line 3 down for maintenance (unrelated).": a sentence its writer marks as unrelated
    def unrelated(m: re.Match[str]) -> str:
        notes.append(f"ignored '{m.group(0).strip()}': marked as unrelated")
        return " "

    text = _expand_noted(_CHAT, text, notes)
    text = _UNRELATED.sub(unrelated, text)
    text = _aside(text, notes)
    text = _there(text, notes)
    text = _put_the(text)
    text = _CALL.sub(lambda m: _call(m, notes), text)

    def labelled(m: re.Match[str]) -> str:
        values = [v.strip() for v in re.split(r"\s*[x×*]\s*", m.group("values"))]
        unit = re.search(r"[a-z]+$", values[-1], re.IGNORECASE)
        if unit:  # "20 x 10 cm": the unit said last is every value's
            values = [
                v if re.search(r"[a-z]$", v, re.I) else f"{v} {unit.group(0)}" for v in values
            ]
        labels = [lb.strip().lower()[:1] for lb in re.split(r"\s*[x×*]\s*", m.group("labels"))]
        if len(values) != len(labels) or len(set(labels)) != len(labels):
            return m.group(0)
        said = " and ".join(
            f"{v} {_DIMENSION_OF[lb]}" for v, lb in zip(values, labels, strict=True)
        )
        if notes is not None:
            notes.append(f"read '{m.group(0).strip()}' as {said}")
        return f" {said} "

    # "(X x Y x Z)": the cell's axes, x away from the robot (depth), y across, z up
    text = _XYZ_LABEL.sub(lambda m: "(D x W x H)" if m.group(1) else "(D x W)", text)
    text = _LABELLED.sub(labelled, text)  # "250mm x 100mm (L x H)": the label says which

    def lettered(m: re.Match[str]) -> str:
        pairs = [(m.group(i).lower(), m.group(i + 1)) for i in (1, 3, 5) if m.group(i)]
        if len({lb for lb, _ in pairs}) != len(pairs):
            return m.group(0)
        said = " and ".join(f"{v} {_DIMENSION_OF[lb]}" for lb, v in pairs)
        notes.append(f"read '{m.group(0).strip()}' as {said}")
        return f" {said} "

    text = _LETTERED.sub(lettered, text)  # "L3 x W2 x H2"

    def along_axes(m: re.Match[str]) -> str:
        pairs = [(m.group(i + 1).lower(), m.group(i)) for i in (1, 3, 5) if m.group(i)]
        if len({axis for axis, _ in pairs}) != len(pairs):
            return m.group(0)
        said = " and ".join(f"{v} {_DIMENSION_OF[_AXIS_LABEL[axis]]}" for axis, v in pairs)
        notes.append(f"read '{m.group(0).strip()}' as {said}")
        return f" {said} "

    text = _AXIS_EACH.sub(along_axes, text)  # "4 (x) by 2 (y) by 1 (z)"

    def glossed(m: re.Match[str]) -> str:
        notes.append(f"read '{m.group(0).strip()}' as {m.group(1)}")
        return f" {m.group(1)} "

    text = _PLACE_GLOSS.sub(glossed, text)  # "the spawn point (the middle)": the place meant

    def many(m: re.Match[str]) -> str:
        noun, size, n = m.group(1).lower(), m.group(2) or "", m.group(3)
        if noun in ("row", "line", "rows", "lines", "stairs", "steps") and not size:
            # "row x5": five along; "stairs x4": four steps (not four staircases)
            notes.append(f"read '{m.group(0).strip()}' as a {noun} of {n}")
            return f" a {noun} of {n} "
        plural = noun + ("es" if noun.endswith(("ch", "sh", "x")) else "s")
        notes.append(f"read '{m.group(0).strip()}' as {n} {plural}{size}")  # "tower of 4 x2"
        return f" {n} {plural}{size} "

    text = _TIMES_N.sub(many, text)  # "make a tower x3": three of them
    text = _stage(text, notes)  # "downstage left": the front, on the performer's left
    text = _IDIOMS.sub(" ", text)  # "Break a leg, everyone!", "quick one before the half"

    def squared(m: re.Match[str]) -> str:
        n = int(m.group(1) or m.group(2))
        notes.append(f"read '{m.group(0).strip()}' as {n * n}")
        return f" {n * n} "

    text = _SQUARED.sub(squared, text)  # "the square of 3", "3 squared"
    text = _PROGRESSION.sub(lambda m: _progression(m, notes), text)  # "each one taller"

    def too(m: re.Match[str]) -> str:
        notes.append(f"read 'too {m.group(2)}' as 'two {m.group(2)}' (a size beside a size)")
        return f"{m.group(1)}two {m.group(2)}"

    text = _TOO_HIGH.sub(too, text)

    def way_up(m: re.Match[str]) -> str:
        notes.append(f"corrected by the command itself: up to the {m.group(2).lower()} → up to "
                     f"the {m.group(3).lower()}")  # fmt: skip
        return f"{m.group(1)}{m.group(3)}"

    text = _WAY_UP_CORRECTED.sub(way_up, text)  # "going up to the back, no, to the front"
    # "towers 2/4/6": a list of sizes, read as one before the phrasings read lists
    text = _SLASHES.sub(lambda m: ", ".join(m.group(0).split("/")[:-1]) + " and " +
                        m.group(0).split("/")[-1], text)  # fmt: skip
    for pattern, repl in _PHRASINGS:
        text = pattern.sub(repl, text)  # "tower from 5 cubes", "behind of wall", "near to"
    text = _placed_by_size(text)  # "3 and 5 high, the 5 on the left": the one of 5 there
    text = _SIDE_OF.sub(_side_of, text)  # "near to wall, on front side of it"
    text = _OFFSET_FROM_LAST.sub(_from_last, text)  # "then another row 1 cube to the left"
    # an aside in parentheses belongs to the noun before it: "the wall (3 long, 2 high)"
    # "three layers (27 cubes)": a total in an aside is its own item, not a size of the word before
    text = re.sub(
        r"\(\s*(\d+\s+(?:cubes?|parts?|blocks?|bricks?)(?:\s+(?:in\s+)?(?:all|total))?)\s*\)",
        r" , \1 in total ",
        text,
        flags=re.IGNORECASE,
    )
    text = re.sub(
        r"\(([^()]*[A-Za-z][^()]*)\)",
        lambda m: " " + m.group(1).replace(",", " and ") + " ",
        text,
    )
    for pattern, repl in _CONTRACTIONS:
        text = pattern.sub(repl, text)
    bad = _NOT_A_NUMBER.search(text)
    if bad:
        raise SpecError(
            f"'{bad.group(0)}' is not a number SDI can use; give a finite value (e.g. 'x = 0.4')",
            understood={},
        )
    text = _likened(text, notes)

    def scientific(m: re.Match[str]) -> str:
        value = float(m.group(0))
        if abs(value) > _LARGEST:
            raise SpecError(
                f"{m.group(0)} is too large for any count or position in the cell; "
                f"numbers above {_LARGEST:g} are refused",
                understood={"numbers": [m.group(0)]},
            )
        plain = f"{value:.6f}".rstrip("0").rstrip(".")
        notes.append(f"read {m.group(0)} as {plain}")
        return plain

    text = _SCIENTIFIC.sub(scientific, text)

    def comma(m: re.Match[str]) -> str:
        notes.append(f"read '{m.group(1)},{m.group(2)}' as {m.group(1)}.{m.group(2)}")
        return f" {m.group(1)}.{m.group(2)}"

    text = _DECIMAL_COMMA.sub(comma, text)

    def unit_comma(m: re.Match[str]) -> str:
        whole, part = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        notes.append(f"read '{whole},{part}' as {whole}.{part}")
        return f"{whole}.{part}"

    text = _DECIMAL_COMMA_UNIT.sub(unit_comma, text)

    def reference(m: re.Match[str]) -> str:
        label = re.match(r"(line|step)\s", m.group(0), re.I)
        if label and (
            re.search(r"\b(?:a|an|in|one|each|every|the|this|that|its|top|first|last)\s+$",
                      m.string[: m.start()], re.I)
            or re.match(r"\s*(?:x|by|apart|away|[a-z]+\s+(?:apart|away|long|high|wide)|cubes?|"
                        r"blocks?|high|tall|long|wide|deep|mm|cm|m)\b", m.string[m.end() :], re.I)
        ):
            return m.group(0)  # "a line 3 long", "in line 3 apart", "step 2 of 3": no label
        if re.fullmatch(r"[A-Za-z]+-\d+", m.group(0)) and m.group(0).split("-")[0].lower() in (
            lx.SHAPE_WORDS
        ):
            return m.group(0)  # "TOWER-3": a structure, sized
        if re.fullmatch(r"[A-Z][A-Z0-9]{1,9}-\d+", m.group(0)):  # "SDI-110 Block.": a ticket
            notes.append(f"ignored '{m.group(0)}': a reference number, not a size")
            return " "
        sized = re.search(  # "Next job: 4-high tower"
            r"\d-(?:high|tall|long|wide|deep|cubes?|blocks?|levels?|layers?|steps?|tier)$",
            m.group(0),
            re.I,
        )
        if (
            sized
            or re.search(r"\d\s*x\s*\d", m.group(0), re.I)
            or re.match(
                r"\s*-?\s*(?:x|by|cubes?|blocks?|bricks?|parts?|high|tall|long|wide|levels?|layers?|steps?|"
                r"stor(?:ey|y|eys|ies)|mm|cm|m|millimet\w*|centimet\w*|inch(?:es)?)\b",
                m.string[m.end() :],
                re.I,
            )
        ):
            # "short version: 3x3 slab", "item: 4 cubes": the label goes, the size stays
            label = re.match(r"[a-z]+", m.group(0).lower())
            if label and label.group(0) in lx.SHAPE_WORDS:
                return m.group(0)  # "a bench 15 cm long": the structure, sized
            number = re.search(r"\d", m.group(0))
            return " " + m.group(0)[number.start() :] if number else m.group(0)
        time = re.search(r"\d[:.]\d\d$|[ap]\.?m\.?$", m.group(0).lower())
        what = "a time of day" if time else "a reference number"
        notes.append(f"ignored '{m.group(0)}': {what}, not a size")
        return " "

    text = _REFERENCE_NO.sub(reference, text)

    def fraction(m: re.Match[str]) -> str:
        top, bottom = m.group(1).lower(), m.group(2).lower()
        num = float(_FRACTION_TOP.get(top, top))
        den = float(_FRACTION_BOTTOM.get(bottom.rstrip("s"), bottom))
        if den == 0:
            return m.group(0)
        metres = round(num / den, 4)
        notes.append(f"read '{m.group(0).strip()}' as {metres:g} m")
        return f" {metres:g} m "

    text = _FRACTION_OF_METRE.sub(fraction, text)
    text = to_millimetres(declared(things(text, notes), notes), notes)  # "Units: inches", "a 6
    # inch stack", "as tall as a coffee mug"
    for pattern, repl in _METRE_WORDS:
        text = pattern.sub(repl, text)
    for m in re.finditer(r"\d+(?:\.\d+)?", text):
        if float(m.group(0)) > _LARGEST:
            raise SpecError(
                f"{m.group(0)} is too large for any count or position in the cell; "
                f"numbers above {_LARGEST:g} are refused",
                understood={"numbers": [m.group(0)]},
            )
    neg = _NEGATIVE_COUNT.search(text)
    if neg:
        raise SpecError(
            f"'{neg.group(0).strip()}': a count cannot be negative; say how many to build "
            "(e.g. '2 towers')",
            understood={"numbers": [neg.group(1)]},
        )
    text = _drawing_sizes(text, notes)
    text = _LIST_ITEM.sub(" then ", text)  # "1) a tower\n2) another one …"
    text = _BULLET.sub(" , ", text)  # "- tower / - 4 cubes / - left side": one thing's details
    text = _ROBOT_NAME.sub(" the robot ", text)
    text = _OWN_TABLE.sub(r"\1 the ", text)
    text = _PAIR_UNIT.sub(lambda m: f"({m.group(1)} {m.group(3)}, {m.group(2)} {m.group(3)})", text)
    text = _SLASH_XY.sub(
        lambda m: f"x = {m.group(1)} {m.group(3)}, y = {m.group(2)} {m.group(3)}", text
    )
    text = _expand_noted(_SHAPE_HEARD, text, notes)
    text = _expand_noted(_SAID_LOOSELY, text, notes)
    for pattern, repl in _HOMOPHONES:

        def heard(m: re.Match[str], repl: _Repl = repl) -> str:
            said = repl if isinstance(repl, str) else repl(m)
            if m.group(0).strip().lower() != said.strip().lower() and notes is not None:
                notes.append(f"read '{m.group(0).strip()}' as '{said.strip()}'")
            return said

        text = pattern.sub(heard, text)
    text = _DANGLING.sub(lambda m: f"{m.group(1) or ''} ", text)
    text = _TOLERANCE.sub(lambda m: _tolerance(m, notes), text)
    text = _SMACK.sub("", _BUILD_SLANG.sub("build ", text))
    text = _FILLERS.sub(" ", text)  # "uh", "um", emoji: nothing to read
    text = _RADIO.sub(" ", text)  # "copy that.", ", over": radio procedure
    text = _OPPOSITES.sub(lambda m: " to ".join(g for g in m.groups() if g), text)
    text = re.sub(r"\b(left|right)[- ]?hand(?=\s+side\b)", r"\1", text, flags=re.I)
    text = _CSV_AT.sub(_csv_at, text)
    quantities: list[int] = []
    text = _QUANTITY.sub(lambda m: _quantity(m, notes, quantities), text)
    if quantities:  # "qty: 3 / item: tower …": the line's structure, that many times
        text = f"{text.rstrip(' ./;,')} , {quantities[0]} of them"
    text = _LETTER_LIST.sub(_letter_list, text)  # "h=2/h=4/h=6": one value each
    text = _LETTER_EQ.sub(_letter_eq, text)
    text = _H_JOINED.sub(r" \1 high ", text)  # "ring 5x5 h2"
    text = _expand_noted(_SHORTHAND, text, notes)
    text = _bare_millimetres(text, notes)
    text = _N_ON_M.sub(_n_by_m, text)  # "a block two on two", "base three on three"
    text = _BASE_AND.sub(r"\1\2\3 by \4", text)
    for pattern, repl in _CLEAR:
        text = pattern.sub(repl, text)
    text = _IN_THE_DIM.sub(_dimensioned, text)
    text = _IN_THE_DIM_OF.sub(_dimensioned, text)

    def times(m: re.Match[str]) -> str:
        factor = 3 if m.group(1).lower() in ("triple", "thrice") else 2
        notes.append(f"read '{m.group(0).strip()}' as {factor * int(m.group(2))}")
        return f" {factor * int(m.group(2))}"

    text = _DOUBLE_OF.sub(times, text)
    text = _NAMED_DIM.sub(_dimensioned, text)
    text = _HIGH_LEVELS.sub(r"\1 high", text)  # "Height 3 courses" read as "3 high courses"
    text = _LETTER_DIM.sub(_dimensioned, text)
    text = _DIM_FIRST.sub(
        lambda m: f"{m.group(1)}{m.group(3).strip()} {_LARGE.get(m.group(2).lower(), m.group(2))} ",
        text,
    )
    text = _AXES_LABEL.sub(" ", text)  # "W×D×H = 3×2×2", "(length x height)"

    def plus(m: re.Match[str]) -> str:
        said = _LETTER_SAID.finditer(_sentence_before(m.string, m.start()))
        if any(letter.group(0)[0] in "Ll" for letter in said):
            notes.append(f"read '{m.group(0)}' as the L's two arms")
            return f" {m.group(1)} by {m.group(2)} "  # "L shp 4+3": arms, not an L of 7
        total = int(m.group(1)) + int(m.group(2))
        notes.append(f"read '{m.group(0)}' as {total}")
        return str(total)

    text = _SUM.sub(plus, text)
    text = _DIMS.sub(" x ", text)
    return SPACES.sub(" ", text).strip()
