"""Lengths said in inches, feet and yards ("a 6 inch stack", "two inches apart", "a
foot-long row", "3/4 of an inch", "1 ft 6 in", "6 by 6 inch"), turned into millimetres, which
the rest of the front end reads, each with a note. pint's unit registry knows the units and
converts them; this module only finds where an operator said one."""

from __future__ import annotations

import re
from fractions import Fraction
from functools import cache
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import pint

_WORDS = {"a": 1, "an": 1, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6,
          "seven": 7, "eight": 8, "nine": 9, "ten": 10, "eleven": 11, "twelve": 12}  # fmt: skip

_PART = {"half": Fraction(1, 2), "quarter": Fraction(1, 4), "third": Fraction(1, 3)}

_N = (
    r"(?:\d+/\d+\s+of\s+an?|\d+(?:\.\d+)?(?:\s+\d+/\d+|-\d+/\d+)?|\d+/\d+|"
    r"(?:(?:a|one|three)\s+)?(?:half|quarter|third)s?(?:\s+of)?\s+an?|"
    + "|".join(sorted(_WORDS, key=len, reverse=True))
    + r")"
)

# what may follow a length: a dimension, a spacing, a size pair, or the structure it sizes
_AFTER = (
    r"(?=[\s-]*(?:tall|high|wide|long|deep|across|thick|apart|away|gap|spacing|space|clear|between|"
    r"in\s+(?:height|length|width|depth|diameter)|from|off|out|to\s+the|left|right|behind|"
    r"in\s+front|of\s+(?:it|the|space|clearance|room)|to\s+(?:its|their|it)|x\b|by\b|×|square|on\s+"
    r"(?:a|each)\s+side|each|per|tower|stack|column|pillar|wall|row|line|pad|slab|block|cubes?|"
    r"blocks?|bricks?|platform|base|floor|layer|step|stairs?|staircase|pyramid|bridge|beam|gate|"
    r"arch|ring|fence|square|grid|high)\b|\s*[,.;:)!?]|\s*$)"
)

# a bare "in" is inches only before a dimension, a size pair or what it sizes ("6 in tall", "a
# 6 in tower"; not "2 in each corner", "3 in the back", "4 in a row")
_AFTER_IN = (
    r"(?=[\s-]*(?:tall|high|wide|long|deep|across|thick|apart|gap|clear|x\b|by\b|×|square|"
    r"tower|stack|column|pillar|wall|row|pad|slab|platform|base|step|staircase|pyramid|bridge|"
    r"beam)\b)"
)

_UNIT = r"(inch(?:es)?|\"|foot|feet|ft\b\.?|yards?|yds?\b\.?)"
_IN = r"(in\b\.?)"

_PINT_UNIT = {"in": "inch", '"': "inch", "ft": "foot", "yd": "yard", "yds": "yard"}

_COMPOUND = re.compile(
    r"\b(" + _N + r")\s*(?:foot|feet|ft\.?|')\s*(?:and\s+)?(" + _N + r")\s*"
    r"(?:inch(?:es)?|in\b\.?|\")" + _AFTER,
    re.IGNORECASE,
)
_AND_A_HALF = re.compile(
    r"\b(" + _N + r")\s+and\s+a\s+half\s+" + _UNIT + _AFTER
    + r"|\b(an?|one)\s+" + _UNIT + r"\s+and\s+a\s+half\b" + _AFTER,
    re.IGNORECASE,
)  # fmt: skip
_PAIR = re.compile(
    r"\b("
    + _N
    + r")\s*(?:x|by|×)\s*("
    + _N
    + r")(?:\s*(?:x|by|×)\s*("
    + _N
    + r"))?[\s-]*"
    + r"(inch(?:es)?|\"|foot|feet|ft\b\.?|yards?|yds?\b\.?|in\b\.?)"
    + _AFTER,
    re.IGNORECASE,
)
# a coordinate in inches: "x = 18 in, y = 12 in"
_COORD = re.compile(
    r"([=:]\s*)(" + _N + r")\s*" + _IN + r"(?=\s*(?:[,;)]|\.(?!\d)|$|and\b))", re.IGNORECASE
)
_SINGLE = re.compile(
    r"\b(" + _N + r")[\s-]*" + _UNIT + _AFTER + r"|\b(" + _N + r")[\s-]*" + _IN + _AFTER_IN,
    re.IGNORECASE,
)


@cache
def _registry() -> pint.UnitRegistry:
    import pint  # its registry takes a quarter of a second to build: only when it is needed

    return pint.UnitRegistry()


def _value(said: str) -> Fraction | None:
    """ "6", "1.5", "3/4", "1 1/2", "1-1/2", "two", "half an", "three quarters of an"."""
    s = re.sub(r"\s+", " ", said.strip().lower())
    words = s.split(" ")
    if words[-1] in ("a", "an") and len(words) > 1:  # "half an", "a quarter of an", "3/4 of an"
        words = [w for w in words[:-1] if w != "of"]
        if len(words) == 1 and "/" in words[0]:
            return _value(words[0])
        share = _PART.get(words[-1].rstrip("s"))
        count = _WORDS.get(words[0], 1) if len(words) > 1 else 1
        return None if share is None else count * share
    if s in _WORDS:
        return Fraction(_WORDS[s])
    m = re.fullmatch(r"(\d+)(?:[\s-](\d+)/(\d+))?|(\d+)/(\d+)|(\d+\.\d+)", s)
    if not m:
        return None
    if m.group(6):
        return Fraction(m.group(6))
    if m.group(4):
        return Fraction(int(m.group(4)), int(m.group(5))) if int(m.group(5)) else None
    whole = Fraction(int(m.group(1)))
    if m.group(2):
        return whole + Fraction(int(m.group(2)), int(m.group(3))) if int(m.group(3)) else None
    return whole


def _mm(value: Fraction, unit: str) -> float:
    name = unit.lower().rstrip(".")
    name = _PINT_UNIT.get(name, name)
    q = _registry().Quantity(float(value), name).to("millimeter")
    return round(float(q.magnitude), 1)


def _article(said: str) -> str:
    """ "a foot long" → "a 304.8 mm long": the article stays when it was the number."""
    return "a " if said.strip().lower() in ("a", "an") else ""


def to_millimetres(text: str, notes: list[str]) -> str:
    """`text` with every imperial length it says in millimetres, each conversion noted."""
    if not re.search(r"inch|in\b|\"|\bf(?:oo|ee)?t\b|\byards?\b|\byds?\b|'", text, re.I):
        return text

    def said_as(m: re.Match[str], mm: str, article: str = "") -> str:
        notes.append(f"read '{m.group(0).strip()}' as {mm}")
        return f" {article}{mm} "

    def compound(m: re.Match[str]) -> str:
        feet, inches = _value(m.group(1)), _value(m.group(2))
        if feet is None or inches is None:
            return m.group(0)
        return said_as(m, f"{_mm(feet, 'foot') + _mm(inches, 'inch'):g} mm")

    def and_a_half(m: re.Match[str]) -> str:
        n, unit = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        v = _value(n)
        if v is None:
            return m.group(0)
        half = _mm(v + Fraction(1, 2), unit)
        return said_as(m, f"{half:g} mm", "" if m.group(1) else _article(n))

    def pair(m: re.Match[str]) -> str:
        vs = [_value(g) for g in m.groups()[:3] if g]
        if any(v is None for v in vs):
            return m.group(0)
        return said_as(m, " by ".join(f"{_mm(v, m.group(4)):g} mm" for v in vs if v is not None))

    def single(m: re.Match[str]) -> str:
        n, unit = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
        v = _value(n)
        if v is None:
            return m.group(0)
        return said_as(m, f"{_mm(v, unit):g} mm", _article(n))

    text = _COMPOUND.sub(compound, text)
    text = _AND_A_HALF.sub(and_a_half, text)
    text = _PAIR.sub(pair, text)

    def coord(m: re.Match[str]) -> str:
        v = _value(m.group(2))
        if v is None:
            return m.group(0)
        notes.append(f"read '{m.group(2)} {m.group(3)}' as {_mm(v, 'inch'):g} mm")
        return f"{m.group(1)}{_mm(v, 'inch'):g} mm"

    text = _COORD.sub(coord, text)
    text = _SINGLE.sub(single, text)
    return re.sub(r"(\d mm)\s*-(?=[a-z])", r"\1 ", text)  # "a foot-long row"


_DECLARED_UNIT = (
    r"(mm|millimet(?:er|re)s|cm|centimet(?:er|re)s|met(?:er|re)s|inch(?:es)?|feet|foot|ft)"
)
# the unit said once for every size ("All dimensions in cm:", "Units: inches.", "(mm)",
# "Inches, all of these:")
_DECLARED = re.compile(
    r"(?:^|(?<=[.;:!?(]))\s*(?:"
    r"(?:all\s+)?(?:dimensions|dims|sizes|measurements|lengths|figures|numbers|values)\s+"
    r"(?:are\s+|given\s+|shown\s+|stated\s+)?(?:all\s+)?in\s+" + _DECLARED_UNIT
    + r"|units?\s*(?:[:=]|are|is)\s*" + _DECLARED_UNIT
    + r"|(?:all\s+)?in\s+" + _DECLARED_UNIT + r"(?=\s*[:,])"
    + r"|" + _DECLARED_UNIT + r"\s*,\s*all\s+of\s+(?:these|them|it)"
    + r")\s*[:,.;]?",
    re.IGNORECASE,
)
_DECLARED_END = re.compile(r"\(\s*(?:all\s+)?(?:in\s+)?" + _DECLARED_UNIT + r"\s*\)", re.I)
# a bare size: "12 long", "length 12", "20 x 10" (a count, "a tower of 5", is no length)
_BARE_SIZE = re.compile(
    r"\b(\d+(?:\.\d+)?)(?=\s*(?:long|high|tall|wide|deep|thick|apart)\b)"
    r"|(\b(?:length|height|width|depth)\s*(?:[:=]|of|is)?\s*)(\d+(?:\.\d+)?)"
    r"(?!\s*(?:mm|cm|m|in|inch|inches|ft|feet|foot|cubes?|blocks?|parts?)\b)"
    r"|\b(\d+(?:\.\d+)?)(\s*(?:x|by|×)\s*)(\d+(?:\.\d+)?)(?:(\s*(?:x|by|×)\s*)(\d+(?:\.\d+)?))?"
    r"(?!\s*(?:mm|cm|m|in|inch|inches|ft|feet|foot|cubes?|blocks?)\b)",
    re.IGNORECASE,
)


def declared(text: str, notes: list[str]) -> str:
    """`text` with the unit said once for every size ("All dimensions in cm: a wall 20 long,
    10 high") written after each bare size, so a size is never read as a count of parts (a
    wall 20 cubes long failed; "Units: inches … 12 long" was 12 cubes, silently)."""
    m = _DECLARED.search(text) or _DECLARED_END.search(text)
    if m is None:
        return text
    unit = next(g for g in m.groups() if g).lower()
    unit = {"ft": "feet", "foot": "feet", "inch": "inches"}.get(unit, unit)
    rest = text[: m.start()] + " " + text[m.end() :]

    def sized(s: re.Match[str]) -> str:
        if s.group(1):
            return f"{s.group(1)} {unit}"
        if s.group(3):
            return f"{s.group(2)}{s.group(3)} {unit}"
        out = f"{s.group(4)} {unit}{s.group(5)}{s.group(6)} {unit}"
        return out + (f"{s.group(7)}{s.group(8)} {unit}" if s.group(8) else "")

    out = _BARE_SIZE.sub(sized, rest)
    if out == rest:
        return text  # no bare size to give it: the words are left to be reported
    notes.append(f"read '{m.group(0).strip(' :,.;')}' as the unit of every size said without one")
    return out


# everyday things an operator sizes by, in mm: (long, wide, high) as they usually stand
_THINGS: dict[str, tuple[float, float, float]] = {
    "coffee mug": (120, 85, 95), "mug": (120, 85, 95), "cup": (90, 90, 90),
    "pint glass": (85, 85, 150), "wine glass": (80, 80, 180), "glass": (75, 75, 120),
    "can of soda": (66, 66, 122), "soda can": (66, 66, 122), "drink can": (66, 66, 122),
    "can of coke": (66, 66, 122), "milk carton": (70, 70, 195), "wine bottle": (75, 75, 300),
    "bottle": (75, 75, 250), "shoebox": (300, 180, 110), "shoe box": (300, 180, 110),
    "shoebox lid": (300, 180, 20), "house brick": (215, 102, 65),
    "paperback book": (178, 110, 25), "paperback": (178, 110, 25), "book": (240, 170, 30),
    "computer keyboard": (440, 130, 30), "keyboard": (440, 130, 30), "tea tray": (400, 300, 20),
    "loaf of bread": (250, 120, 120), "domino": (50, 25, 10), "credit card": (86, 54, 1),
    "smartphone": (150, 72, 8), "phone": (150, 72, 8), "ruler": (300, 30, 3),
    "pencil": (180, 7, 7), "hand": (190, 90, 90), "hand's width": (100, 100, 100),
}  # fmt: skip
_THING = r"(?:" + "|".join(sorted(map(re.escape, _THINGS), key=len, reverse=True)) + r")"
_LIKE_THING = re.compile(
    r"\b(?:(?:about|roughly|around|approximately|nearly)\s+)?(?:"
    r"as\s+(?P<dim>tall|high|long|wide|big|large)\s+as|the\s+(?P<key>size|length|height|width)\s+of)"
    r"\s+(?:a|an|one|the|my|your)\s+(?P<thing>" + _THING + r")(?:\s+standing\s+up)?\b",
    re.IGNORECASE,
)


_MEASURED = re.compile(
    r"\d\s*(?:mm|cm|m|in|inch|inches|ft|feet)\b|\b(?:ten|fifteen|twenty|thirty|forty|fifty)\s+"
    r"(?:centimet|millimet|cm\b|mm\b|inch)",
    re.IGNORECASE,
)


def things(text: str, notes: list[str]) -> str:
    """ "a tower as tall as a coffee mug", "a block the size of a shoebox": the size of the
    thing, in millimetres, with a note (read as a vague 'tall', a tower of 6, silently)."""

    def size(m: re.Match[str]) -> str:
        after = re.split(r"[.;!?]", m.string[m.end() :], maxsplit=1)[0]
        if _MEASURED.search(after):  # "as long as your hand, about twenty centimetres"
            notes.append(f"read '{m.group(0).strip()}' as a likeness: the size said after it "
                         "is used")  # fmt: skip
            return " "
        long, wide, high = _THINGS[m.group("thing").lower()]
        said = (m.group("dim") or m.group("key") or "").lower()
        if m.group(0).lower().endswith("standing up"):
            long, high = high, long
        sized = {"tall": f"{high:g} mm tall", "high": f"{high:g} mm high",
                 "height": f"{high:g} mm high", "long": f"{long:g} mm long",
                 "length": f"{long:g} mm long", "wide": f"{wide:g} mm wide",
                 "width": f"{wide:g} mm wide"}.get(said)  # fmt: skip
        flat = re.search(r"\b(?:slab|plate|floor|pad|platform|tile|grid)s?\b", m.string, re.I)
        if sized is None:  # "the size of", "as big as": its footprint, and its height if solid
            sized = f"{long:g} mm by {wide:g} mm" + ("" if flat else f" by {high:g} mm")
        notes.append(f"read '{m.group(0).strip()}' as {sized} (the usual size of a "
                     f"{m.group('thing').lower()})")  # fmt: skip
        return f" {sized} "

    return _LIKE_THING.sub(size, text)
