"""Everyday phrasings: how operators say sizes, places, picks and changes in their own words.

Read first in the phrasing table (`sdi.language.normalise`), each a rewrite into the words the
later stages read, with the misreading it replaced: *"two walls forming a corner, each 4 long"*,
*"the one nearest the robot, make it 6"*, *"a tower for each of my 3 kids"*, *"Take 3 off and move
it to the front left"*, *"Position: … Item: …"*. Written from commands no set holds (the
language probes); each has a test in `tests/test_language.py`.
"""

from __future__ import annotations

import re
from collections.abc import Callable

from sdi.language.nouns import families_said, l_named_last, nouns_said, shape_alternation
from sdi.spec import lexicon as lx
from sdi.spec.numbers import ORDINAL_STEPS, words_to_numbers

_Repl = str | Callable[[re.Match[str]], str]
_NUM = r"(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten)"
_FAMILY_SAID = shape_alternation(min_len=3)
_CHANGE_LED = re.compile(r"\b(?:make|set|raise|lower|change|turn|bring)\s+$", re.IGNORECASE)
_COUNTED_PLURAL = re.compile(
    r"\b(?:two|three|four|2|3|4)\s+(?:\w+\s+)?(?:" + _FAMILY_SAID + r")s\b", re.IGNORECASE
)


_THEN_SIZE = re.compile(
    r"\s*[,;.]?\s*(?:and\s+)?then\s+(?:put\s+|add\s+|lay\s+)?(?:an?\s+)?(" + _NUM
    + r")(?:\s*(?:x|by)\s*(" + _NUM + r"))?(?:\s+(?:cubes?|blocks?|layer|course|row))?"
    r"(?:\s+(?:on\s+(?:it|top(?:\s+of\s+(?:it|that))?|that)|above(?:\s+it)?|over\s+it))?"
    r"(?=\s*(?:[,;.]|$|and\b|then\b))",
    re.IGNORECASE,
)


def _layers_in_turn(m: re.Match[str]) -> str:
    """ "A row of 5, then 3 on it, then 1", "4x4, then 3x3, then 2x2, then one cube": each
    number a layer of the first one's kind on top of the one before (the numbers named nothing,
    or the rows were read as the pillars of a bridge)."""
    row = m.group("n") is not None
    sentence = re.split(r"[.;!?]", m.string[: m.start()])[-1]
    if not row and families_said(sentence):
        return m.group(0)  # "a stepped pyramid: 5 by 5, then 3 by 3, …": its own levels
    out = [m.group("head")]
    for later in _THEN_SIZE.finditer(m.group("rest")):
        a, b = later.group(1), later.group(2)
        one = words_to_numbers([a.lower()])[0] == "1" and (b is None or b in ("1", "one"))
        if one:
            out.append("then a cube on top")
        elif row:
            out.append(f"then a row of {a} on top")
        else:
            out.append(f"then a {a} by {b or a} layer on top")
    return ", ".join(out) + " "


def _sized_one(m: re.Match[str]) -> str:
    """ "three towers: a small one, a medium one and a big one": one of the family said before,
    that size ("one" was read as 1 high, silently); "middle" is the medium size."""
    said = nouns_said(m.string[: m.start()])
    if not said:
        return m.group(0)
    plural = lx.SHAPE_WORDS.get(said[-1][:-1]) is not None
    if not plural and re.search(r"[a-z]\s*[,—–-]\s*$", m.string[: m.start()]):
        return m.group(0)  # "a stack, a tall one": the stack described again (`rewrites`)
    size = re.sub(r"\b(?:middle|mid)(?:[\s-]*sized)?\b", "medium", m.group(2), flags=re.I)
    if plural:  # "three towers: a small one, …": one of those counted
        return f"one {size}"
    return f"{m.group(1)} {size} {said[-1]}"


def _listed_after_count(m: re.Match[str]) -> str:
    """ "three towers: a small tower, a medium tower and a big tower": the count heads the list
    of the ones it counts (five towers were built, silently)."""
    n = words_to_numbers([m.group(1).lower()])[0]
    family = m.group(3)
    rest = re.split(r"[.;!?]", m.string[m.end() :])[0]
    items = re.findall(rf"\b(?:an?|one)\s+(?:[\w-]+\s+){{0,3}}?{family}\b", rest, re.I)
    return "" if n.isdigit() and int(n) == len(items) else m.group(0)


def _by_their_sizes(m: re.Match[str]) -> str:
    """ "Two towers: 2 and 5. The 2 goes behind the 5": the ones of those sizes, by name (the
    5 was put behind the 2, or both at the back, silently)."""
    before = m.string[: m.start()]
    said = nouns_said(before)
    numbers = words_to_numbers(re.findall(r"\d+|[a-z]+", before.lower()))
    a, b = (words_to_numbers([m.group(k).lower()])[0] for k in (1, 3))
    if not said or a == b or a not in numbers or b not in numbers:
        return m.group(0)
    if re.search(rf"\ban?\s+(?:{m.group(1)}|{a})\b", before, re.IGNORECASE):
        return m.group(0)  # "2 towers, a 5 and a 3, the 5 behind the 3": named so (`rewrites`)
    family = said[-1][:-1] if lx.SHAPE_WORDS.get(said[-1][:-1]) else said[-1]
    return f"put the {family} of {a} {m.group(2)} the {family} of {b}"


def _with_sized_one(m: re.Match[str]) -> str:
    """ "… with a 2 high one": another of the family said before, its height after it ("one"
    with no family before stays as it was)."""
    family = m.group(3).lower()
    if family == "one":
        said = nouns_said(m.string[: m.start()])
        if not said:
            return m.group(0)
        family = said[-1]
    return f"with a {family} {m.group(1)} {m.group(2)}"


def _pyramid_base(m: re.Match[str]) -> str:
    """ "a pyramid with a 5x5 base": a pyramid 5 x 5; "with a base of 5" stays as said unless
    another structure follows ("… and a tower of 3 next to it"): then "a pyramid 5 wide"."""
    if m.group(2):
        return f"{m.group(1)} {m.group(2)} x {m.group(3)}"
    if m.group(5):
        return f"{m.group(1)} {m.group(4)} x {m.group(5)}"
    if re.match(r"\s*,?\s*and\s+(?:an?|one|two|three|four|\d+)\s", m.string[m.end() :], re.I):
        return f"{m.group(1)} {m.group(4)} wide"
    return m.group(0)


def _heights_as_articles(m: re.Match[str]) -> str:
    """ "two towers, a 4 and a 7, the 7 behind the 4": a tower of each height (as many as
    counted), and "the 7" after it the one of 7; as it was when the count differs."""
    heights = [*re.findall(r"\d+", m.group(3)), m.group(4)]
    if words_to_numbers([m.group(1).lower()])[0] != str(len(heights)):
        return m.group(0)
    noun = m.group(2).lower()[:-1]
    return " and ".join(f"a {noun} of {h}" for h in heights)


def _named_by_height(m: re.Match[str]) -> str:
    """ "…, the 7 behind the 4": the one of 7 behind the one of 4, when a structure of 7 was
    named before; as it was otherwise."""
    if not re.search(rf"\bof\s+{m.group(1)}\b|\ban?\s+{m.group(1)}\b", m.string[: m.start()]):
        return m.group(0)
    other = f" the {m.group(3)} one" if m.group(3) else ""
    return f"the {m.group(1)} one {m.group(2)}{other}"


def _middle_one_said(m: re.Match[str]) -> str:
    """ "three towers of 2 in a line, the middle one 5 high": a change of the middle one of an odd
    number of towers counted before; as it was when the others are sized by their places too
    ("the middle one 3 tall, the left one 2 tall, …")."""
    sentence = re.split(r"[.;!?]", m.string[: m.start()])[-1] + m.string[m.end() :].split(".")[0]
    counted = re.search(r"\b(?:three|five|seven|[357])\s+(?:[\w-]+\s+)?(?:towers|stacks|columns|"
                        r"pillars)\b", m.string[: m.start()], re.I)  # fmt: skip
    if not counted or re.search(r"\b(?:left|right|front|back|outer|outside|end)\s+(?:one|ones|"
                                r"tower|towers|block)\b", sentence, re.I):  # fmt: skip
        return m.group(0)
    return f". make the middle one {m.group(1)} high"


def _pyramid_counted(m: re.Match[str]) -> str:
    """ "a pyramid …, one cube at the top, four under that and nine at the bottom": levels of 1,
    4 and 9 cubes (three levels or more) make a square pyramid 3 x 3, the places said kept; any
    other numbers stay."""
    said = [int(n) for n in words_to_numbers(re.findall(r"[a-z]+|\d+", m.group(2).lower()))
            if n.isdigit()]  # fmt: skip
    side = round(max(said) ** 0.5) if said else 0
    if side < 3 or sorted(said) != [k * k for k in range(1, side + 1)]:
        return m.group(0)
    places = re.findall(r"\b(?:on|at|in)\s+the\s+(?:back|front|left|right|middle|centre|center)"
                        r"(?:\s+(?:left|right))?(?:\s+corner)?\b", m.group(2), re.I)  # fmt: skip
    return f"{m.group(1)} {side} x {side}" + "".join(f" {p}" for p in places)


def _walls_in_square(m: re.Match[str]) -> str:
    """ "four walls, 4 long, 2 high, in a square": a ring 4 by 4, 2 high."""
    long = re.search(r"(\d+|two|three|four|five|six)\s+(?:cubes?\s+)?long", m.group(1), re.I)
    high = re.search(r"(\d+|two|three|four|five|six)\s+(?:cubes?\s+)?(?:high|tall)", m.group(1),
                     re.I)
    side = f" {long.group(1)} by {long.group(1)}" if long else ""
    return f"a ring{side}" + (f", {high.group(1)} high" if high else "")


_LABELLED = re.compile(r"\b(?:column|tower|wall|row|block|slab|stack|pillar|post|pyramid|staircase|"
                       r"ring|bridge|twr)\s+([A-D])\b(?!['’])", re.IGNORECASE)
_ORDINALS = tuple(ORDINAL_STEPS)[:4]  # "first" … "fourth"


def _label_named(m: re.Match[str]) -> str:
    """ "Column A …, Column B …, 50 mm clear to the right of A": of the one labelled A, the first
    named (read as the table's right, silently); the label only, when none is named so."""
    labels = list(dict.fromkeys(x.group(1).upper() for x in _LABELLED.finditer(m.string)))
    said = m.group(2).upper()  # the labels in the order the structures are named
    if said not in labels or len(labels) < 2 or labels.index(said) > 3:
        return m.group(0)
    return f"{m.group(1)} the {_ORDINALS[labels.index(said)]} one"


def _steps_counted(m: re.Match[str]) -> str:
    """Steps said one by one, each one higher: that many steps; else the words as they were."""
    said = re.findall(r"\b(second|third|fourth|fifth|sixth|seventh|eighth)\s+(?:step\s+|stair\s+|"
                      r"one\s+)?(?:is\s+)?(\d|two|three|four|five|six|seven|eight)\b", m.group(0),
                      re.I)  # fmt: skip
    values = [int(words_to_numbers([v.lower()])[0]) for _, v in said]
    order = [ORDINAL_STEPS[o.lower()] for o, _ in said]
    if order != list(range(2, len(said) + 2)) or values != order:
        return m.group(0)
    return f"{len(said) + 1} steps"


_SIDE_SAID = re.compile(
    r"\b(?:to\s+(?:its|the)\s+(left|right)|(left|right)\s+of|on\s+its\s+(left|right)|(in\s+front\s+of|behind)|"
    r"(next\s+to|beside|alongside))\b",
    re.IGNORECASE,
)


def _other_side(m: re.Match[str]) -> str:
    """ "a tower of four, a tower of two next to that, and a tower of six on the other side of
    the first one": the side across from the one said before (or from SDI's own, the left, for
    "next to"); the relation was dropped, silently."""
    said = list(_SIDE_SAID.finditer(m.string[: m.start()]))
    if not said:
        return m.group(0)
    last = said[-1]
    side = (last.group(1) or last.group(2) or last.group(3) or "").lower()
    obj = m.group(1)
    if obj.lower() in ("it", "that", "this"):
        if len(families_said(m.string[: m.start()])) != 2 or not (last.group(1) or last.group(3)):
            return m.group(0)
        obj = "the first one"  # "a tower, a tower to its right, and one on the other side of it"
    if last.group(4):
        return f"{'behind' if last.group(4).lower().startswith('in') else 'in front of'} {obj}"
    opposite = {"left": "right", "right": "left"}.get(side, "right")  # "next to": on the left
    return f"to the {opposite} of {obj}"


EVERYDAY: list[tuple[re.Pattern[str], _Repl]] = [
    # "right in the very centre": the centre ("very" kept "right" from reading as an intensifier)
    (re.compile(r"\bthe\s+very\s+(?=(?:centre|center|middle|front|back|top|bottom|end|edge|corner|"
                r"left|right)\b)", re.I), "the "),
    # "surround a tower of 6 and a tower of 2 with one ring": a ring ("one ring" was read as a
    # reference to the towers: a tower was made the ring)
    (re.compile(r"\b((?:surround|enclose|encircle|fence\s+in|box\s+in)\b[^.;?!]*?\bwith\s+)"
                r"(?:just\s+)?(?:one|a\s+single)\s+(?=(?:ring|enclosure|fence|wall|border|frame|"
                r"square)\b)", re.I),
     r"\1a "),
    # "Take the tallest one down to 3", "knock it down to 2 high": that height (the tallest was
    # taken away, silently)
    (re.compile(r"\b(?:take|bring|knock|cut|chop|lower)\s+(the\s+(?:[\w-]+\s+){0,2}?(?:one|tower|"
                r"stack|column|pillar|post|wall)|it|that(?:\s+one)?|them)\s+down\s+to\s+(" + _NUM
                + r")\b", re.I),
     r"make \1 \2"),
    # "one ring 7 by 7 and inside put four towers": what stands inside it (read as the ring's
    # inside, 7 by 7, and the towers stood outside, silently)
    (re.compile(r"(\b(?:ring|enclosure|fence|pen|frame|border|courtyard)\b[^.;]*?\d+\s*(?:x|by)\s*\d+"
                r"[^.;]*?)\s*,?\s*\band\s+inside(?:\s+(?:it|of\s+it))?\s*,?\s*(?=(?:put|place|build|"
                r"stand|set|add|make)\b|(?:an?|one|two|three|four|five|six|\d+)\s)", re.I),
     r"\1. inside it, "),
    # "three single cubes inside it in a row": the row's words together, before the relation
    # (the row after "inside it" was one of its own, 5 long)
    (re.compile(r"\b(inside|within)\s+(it|them|the\s+(?:ring|enclosure|pen|fence|frame|square))\s*,?\s+"
                r"(in\s+an?\s+(?:row|line|straight\s+line))\b", re.I), r"\3 \1 \2"),
    # "two towers of 3 inside it, not touching anything": apart, said before the relation (the
    # words after "inside it" were read as a structure of their own)
    (re.compile(r"\b(inside|within)\s+(it|them|the\s+(?:ring|enclosure|pen|fence|frame|square))\s*,\s*"
                r"(not\s+touching|(?:with\s+)?(?:gaps|space)\s+between\s+them)(?:\s+(?:each\s+other|one\s+"
                r"another|anything|the\s+(?:ring|walls?|sides?)|(?:each\s+other\s+)?or\s+the\s+(?:ring|"
                r"walls?|sides?)))?(?=\s*(?:[.;!?]|$))", re.I), r"\3 \1 \2"),
    # "enclosure 8x6, one high. inside: row of 4": inside it
    (re.compile(r"(?:^|(?<=[.;]\s))\s*(inside|within)\s*:\s*", re.I), r"\1 it, "),
    # "tower 4 outside each side": beside each side
    (re.compile(r"\b(?:(tower|stack|column|pillar)s?\s+(\d+)\s+)?outside\s+(each|every|all\s+four|"
                r"all)\s+(?:of\s+its\s+)?sides?\b(?:\s+of\s+(?:it|the\s+\w+))?", re.I),
     lambda m: (f"{m.group(1)} of {m.group(2)} " if m.group(1) else "")
     + f"on {m.group(3)} side of it"),
    # "The wall on right side, make 4 high": that one changed (the wall was a fourth, at the right)
    (re.compile(r"(?:^|(?<=[.;!?]\s))\s*the\s+(" + _FAMILY_SAID + r"|one)\s+(?:on|at)\s+(?:the\s+)?"
                r"(left|right|front|back)(?:[\s-]+(?:hand\s+)?(?:side|end))?\s*,\s*(make|raise|lower)\s+"
                r"(?:it\s+)?", re.I),
     r"\3 the \2 \1 "),
    # "right one +3", "the tall one -2": that one, cubes added or taken off
    (re.compile(r"\b(?:the\s+)?(left|right|front|back|first|second|last|middle|tall|short|taller|shorter|"
                r"tallest|shortest)\s+(one|tower|stack|column|wall)\s*([+-])\s*(\d+)\b", re.I),
     lambda m: f"add {m.group(4)} to the {m.group(1)} {m.group(2)}" if m.group(3) == "+"
     else f"take {m.group(4)} off the {m.group(1)} {m.group(2)}"),
    # "a tower of 5 in the back right corner and copy it into the other three corners": one in
    # each corner (one copy in the middle, silently)
    (re.compile(r"\s+in\s+the\s+(?:back|front)\s+(?:left|right)\s+corner\s*,?\s*(?:and\s+)?"
                r"(?:then\s+)?(?:copy|repeat|duplicate|put\s+(?:the\s+same|one|copies))\s+(?:it\s+|that\s+)?"
                r"(?:in|into|at|to)\s+(?:the\s+|all\s+the\s+)?(?:other|remaining)\s+(?:three|3)"
                r"(?:\s+corners)?\b", re.I),
     " in each corner"),
    # "6 towers h2, 2 rows of 3": in those rows (two rows of cubes were built besides)
    (re.compile(r"(\b(?:\d+|four|six|eight|nine)\s+(?:towers|stacks|columns|pillars|pyramids|blocks|"
                r"piles)\b[^.;]*?),\s*(?=(?:two|three|four|[2-4])\s+rows\s+of\s+(?:two|three|four|[2-4])\b)",
                re.I),
     r"\1, in "),
    # "a square of four 2x2 blocks, each 2 high": the four in a square (two blocks were built)
    (re.compile(r"\ba\s+(square|grid)\s+of\s+(four|nine|six|[469])\s+([^,.;]+?)(?=\s*(?:[,.;]|$|\bwith\b))",
                re.I), r"\2 \3 in a \1"),
    # "a tower of 2 a bit off to each side of it": to each side ("bit" and "off" were unused)
    (re.compile(r"\b(?:a\s+(?:little\s+)?bit|slightly)\s+(?:off|out|away)\s+(?=to\b|from\b)", re.I),
     ""),
    # "tucked into the front-left corner", "squeezed into the corner": in it
    (re.compile(r"\b(?:tucked|squeezed|nestled|pushed|snug)\s+(?:up\s+)?(?:into|in)\s+(?=the\b)",
                re.I),
     "in "),
    # "leave a gap of one between a 3-cube tower and a 4-cube tower": the two, that gap apart
    (re.compile(r"\b(?:leave|put|keep|make)\s+(a\s+gap\s+of\s+(?:\d+|one|two|three)(?:\s+cubes?)?)\s+"
                r"between\s+(an?\s+[^,.;?!]+?\s+and\s+an?\s+[^,.;?!]+?)(?=\s*(?:[,.;?!]|$))", re.I),
     r"\2, with \1"),
    # "the distance between is 15 cm", "the gap between them should be 2 cubes": that far apart
    (re.compile(r"\bthe\s+(?:distance|gap|space|spacing)\s+between(?:\s+(?:them|the\s+two|each))?\s+"
                r"(?:is|should\s+be|must\s+be|will\s+be|of)\s+((?:\d+(?:\.\d+)?|one|two|three|four)\s*"
                r"(?:cm|mm|m|cubes?)\b)", re.I), r"\1 apart"),
    # "a U form, width 5, arm 4": its arms 4 long
    (re.compile(r"\b(arms?)\s+(\d+)\b(?!\.\d|\d)(?!\s*(?:(?:cubes?|blocks?|parts?|bricks?)\s+)?(?:long|high|"
                r"tall|wide|x|by|and|n|&|cm|mm|m)\b)", re.I),
     r"arms \2 long"),
    # "Doable?", "Is that possible?", "I'm thinking a …": no content
    (re.compile(r"(?:^|(?<=[.!?;,]\s)|(?<=[\u2014\u2013-]\s))\s*(?:is\s+(?:that|this|it)\s+)?"
                r"(?:doable|possible|feasible|ok(?:ay)?|alright)\s*\?", re.I), " "),
    (re.compile(r"\bi'?m\s+thinking(?:\s+of)?\s+(?=an?\s)", re.I), ""),
    # "a fat little tower — 3 by 3 across": its footprint said ("fat" was unused)
    (re.compile(r"\b(?:fat|chunky|stout|thick)\s+(?=(?:little\s+|short\s+|low\s+)?(?:tower|column|pillar|"
                r"stack|block)\b[^.;]*?\b\d+\s*(?:x|by)\s*\d+)", re.I), ""),
    # "the tallest you can manage": the tallest that fits
    (re.compile(r"\bthe\s+tallest(?:\s+one)?\s+(?:you|it|the\s+robot)\s+can\s+(?:manage|make|build|do|"
                r"go|get)\b", re.I), "as tall as possible"),
    # "a really tall tower, as tall as possible": the tallest ("tall" made it 6)
    (re.compile(r"\b(?:really\s+|very\s+|super\s+)?tall\s+(?=(?:tower|column|stack|pillar)\b[^.;?]*\bas\s+"
                r"(?:tall|high)\s+as\s+(?:possible|you\s+can|it\s+can))", re.I), ""),
    # "make the second one a bit taller": taller (the change was not read)
    (re.compile(r"\b(?:a\s+(?:little\s+)?bit|a\s+little|slightly|somewhat|a\s+touch)\s+(?=(?:taller|higher|"
                r"shorter|lower|longer|wider|bigger|smaller)\b)", re.I), ""),
    # "three towers of 2 in a line, the middle one 5 high", "… and the one in the middle should be
    # 5 tall": a change of the middle one (a fourth tower, or all three 5 high)
    (re.compile(r"\s*,?\s*(?:and\s+|with\s+|but\s+)?the\s+(?:one\s+(?:smack\s+|right\s+)?in\s+the\s+"
                r"(?:middle|centre|center)|(?:middle|centre|center)\s+one)\s+(?:(?:is|should\s+be|must\s+"
                r"be|being|needs\s+to\s+be|gets)\s+)?(" + _NUM
                + r")(?:\s+(?:cubes?\s+)?(?:high|tall)\b|"
                r"\s*(?=[.;,!?]|$|\s+and\b))", re.I),
     _middle_one_said),
    # "…, the 7 behind the 4": the one of 7 behind the one of 4
    (re.compile(r"\bthe\s+(\d+)\s+(behind|in\s+front\s+of|(?:to\s+the\s+)?(?:left|right)\s+of|next\s+"
                r"to|beside|on\s+the\s+(?:left|right))(?:\s+(?:the\s+)?(\d+))?\b(?!\s*(?:cubes?|cm|mm|m|"
                r"high|tall|long)\b)", re.I),
     _named_by_height),
    # "Two towers, a 4 and a 7, the 7 behind the 4": a tower of each height, and each named by
    # its height after (the 7 was lost, both stood at the back)
    (re.compile(r"\b(two|three)\s+(towers|stacks|columns|pillars)\s*[,:]\s*((?:(?:an?|one)\s+\d+\s*,?"
                r"\s*)+)(?:and|&)\s+(?:an?|one)\s+(\d+)\b(?!\s*(?:cubes?\s+)?(?:high|tall|long|wide|x|by)\b)",
                re.I),
     _heights_as_articles),
    # "then make it two times higher": twice as tall
    (re.compile(r"\b(two|three|four|2|3|4)\s+times\s+(?:higher|taller|as\s+(?:high|tall))\b", re.I),
     lambda m: "twice as tall" if m.group(1).lower() in ("two", "2")
     else f"{m.group(1)} times as tall"),
    # "then mirror it on the right side": another one there
    (re.compile(r"\b(?:mirror|copy|repeat|duplicate)\s+(?:it|that|this)\s+(?=(?:on|to|at)\s+the\s+(?:left|"
                r"right|front|back|other)\b)", re.I), "another one "),
    # "a pyramid with one cube at the top, four under that and nine at the bottom": its levels
    # counted, a square pyramid 3 x 3 (read as a flat one 9 long)
    (re.compile(r"\b(pyramid)\b([^.;]*)", re.I), _pyramid_counted),
    # "a wall with 10 cubes in it, 5 along the bottom": of 10 cubes ("in it" related nothing)
    (re.compile(r"\bwith\s+(\d+|" + _NUM + r")\s+(cubes|blocks|bricks)\s+in\s+(?:it|total|all)\b",
                re.I), r"of \1 \2"),
    # "two walls, 3 long and 2 high, facing each other across a 3-cube gap": one behind the
    # other, that gap between ('facing' was unused)
    (re.compile(r"\b((?:two|2)\s+(?:walls|fences|rows|barriers)\b[^.;]*?)\s*,?\s*\bfacing\s+(?:each\s+"
                r"other|one\s+another)\s+across\s+(?=an?\s|\d|one|two|three)", re.I),
     r"\1, one behind the other, with "),
    # "Put two more on it. Then one more.": one more on it (another tower was built)
    (re.compile(r"(\b(?:put|add|stack|place)\s+(?:\d+|two|three|four|five|another|one)\s+more(?:\s+"
                r"cubes?)?\s+on\s+(?:it|top)\b[^.;]*[.;]\s*(?:and\s+)?then\s+)(one|two|three|\d+)\s+more\s*"
                r"(?=[.;!]|$)", re.I),
     r"\1put \2 more on it"),
    # "two towers, a tall one of 6 and the other one 2": a tower of each
    (re.compile(r"\b(?:two|2)\s+(towers|stacks|columns|pillars)\s*,\s*(?:an?|one)\s+(?:tall|high|big|short|"
                r"small|low)\s+one\s+(?:of\s+)?(\d+)\s+and\s+(?:the\s+other(?:\s+one)?|a\s+(?:short|small|low|"
                r"tall|big)\s+one)\s+(?:of\s+)?(\d+)\b", re.I),
     lambda m: f"a {m.group(1)[:-1]} of {m.group(2)} and a {m.group(1)[:-1]} of {m.group(3)}"),
    # "a tower of 5 in the corner closest to the robot on its right": the front right corner
    (re.compile(r"\bthe\s+corner\s+(?:that'?s\s+|which\s+is\s+)?(?:(closest|nearest)\s+(?:to\s+)?|(?:furthest|"
                r"farthest)\s+(?:away\s+)?from\s+)(?:the\s+)?robot\s*,?\s*(?:on\s+(?:its|the)\s+|to\s+the\s+)"
                r"(left|right)\b", re.I),
     lambda m: f"the {'front' if m.group(1) else 'back'} {m.group(2).lower()} corner"),
    # "Staircase with 3 step, the high part is at the back": climbing to the back
    (re.compile(r"\s*,?\s*(?:with\s+)?the\s+(?:high|higher|tall|taller|top)\s+(?:part|end|side|step)\s+(?:is\s+|"
                r"being\s+|should\s+be\s+|goes\s+)?(?:at|on|to|towards)\s+the\s+(back|front|left|right)\b",
                re.I), r" going up to the \1"),
    # "long side along the back edge": running left to right, against it
    (re.compile(r"\blong(?:er)?\s+side\s+(?:along|against|on|at)\s+the\s+(back|front)(\s+edge)?\b",
                re.I), r"long side running left to right, along the \1 edge"),
    # "outside size 3 by 3", "size 4 by 4": the size ('size' was unused)
    (re.compile(r"\b(?:(outside|outer|inside|inner)\s+)?size\s*(?:of\s+|is\s+|:\s*)?"
                r"(?=\d+\s*(?:x|by)\s*\d)", re.I),
     lambda m: f"{m.group(1)} " if m.group(1) else ""),
    # "a staircase that goes up 25 cm": that high
    (re.compile(r"\b(?:that|which)\s+(?:goes|rises|climbs|reaches)\s+(?:up\s+)?(?:to\s+)?(?=(?:\d+(?:\.\d+)?\s*"
                r"(?:cm|mm|m)|\d+\s+cubes?)\b)", re.I), ""),
    # "one cube of space between neighbours": between them
    (re.compile(r"\bbetween\s+(?:the\s+)?(?:neighbou?rs|each\s+neighbou?r|neighbou?ring\s+ones)\b",
                re.I),
     "between them"),
    # "in the middle line": in the middle
    (re.compile(r"\bin\s+the\s+(?:middle|centre|center)\s+line\b", re.I), "in the middle"),
    # "a ring 5 x 5 of one height": one high
    (re.compile(r"\bof\s+(one|two|three|\d)\s+height\b", re.I), r"\1 high"),
    # "in the front of it": in front of it
    (re.compile(r"\bin\s+the\s+front\s+of\s+(?=it\b|them\b|the\b)", re.I), "in front of "),
    # "small tower (2) on the left": a tower of 2
    (re.compile(r"\b(tower|stack|column|pillar|wall|row)\s*\(\s*(\d+)\s*\)", re.I), r"\1 of \2"),
    # "stick a 2x2 block in each of the 4 corners of the table": in each corner
    (re.compile(r"\bin\s+each\s+of\s+the\s+(?:4|four)\s+corners\b", re.I), "in each corner"),
    # "they must touch", "they should be touching": touching
    (re.compile(r"\s*,?\s*(?:and\s+)?they\s+(?:must|should|have\s+to|need\s+to)\s+(?:be\s+)?touch(?:ing)?"
                r"(?:\s+each\s+other)?\b", re.I), ", touching"),
    # "small tower of 2 on the left, tall tower of 8 on the right": each its article (the
    # second was read as the first's relation)
    (re.compile(r"(?:^|(?<=[,;.]\s)|(?<=\band\s))\s*(?=(?:small|tall|big|little|short|low|wide|long|high)\s+"
                r"(?:tower|stack|column|pillar|wall|row|slab|block|pyramid|staircase)\b)", re.I),
     " a "),
    # "a staircase that does not climb towards the left or the right": to the back (read as
    # climbing to the right)
    (re.compile(r"\b(?:that\s+|which\s+)?(?:does\s+not|doesn'?t|should\s+not|shouldn'?t|not|never)\s+(?:climb|go|"
                r"rise|run)(?:s|ing)?\s+(?:up\s+)?(?:towards|to)\s+(?:the\s+)?(?:left\s+or\s+(?:the\s+)?right|right\s+"
                r"or\s+(?:the\s+)?left|front\s+or\s+(?:the\s+)?back|back\s+or\s+(?:the\s+)?front)\b",
                re.I),
     lambda m: "going up to the back" if re.search(r"left|right", m.group(0), re.I)
     else "going up to the left"),
    # "…, the three to stand in one line": in a line (a row of 3 was built besides, silently)
    (re.compile(r"\bthe\s+(?:two|three|four|five|both|lot)\s+(?:of\s+them\s+)?(?:(?:to\s+|should\s+|must\s+|shall\s+)?"
                r"(?:stand|be|sit|go)\s+|standing\s+|are\s+|being\s+)?(?=in\s+(?:one|a)\s+(?:straight\s+)?(?:line|row)"
                r"\b)", re.I), ""),
    # "a tower for each of my 3 kids": three towers
    (re.compile(r"\ban?\s+(tower|stack|column|pillar|pyramid|wall|row|staircase)\s+for\s+each\s+of\s+(?:my|the|our|"
                r"his|her|their)\s+(\d+|two|three|four|five|six)\s+[a-z]+\b", re.I), r"\2 \1s"),
    # "put tower of 4 on the corner of it": on one corner of its top (the table's corner)
    (re.compile(r"\bon\s+the\s+corner\s+of\s+(it|that|the\s+(?:slab|block|platform|square|base|pad))\b",
                re.I),
     r"on one corner of \1"),
    # "4 walls in a square and a tower in the middle", "Four walls, 4 long, 2 high, in a square":
    # a ring (walls apart, or one square slab)
    (re.compile(r"\b(?:four|4)\s+walls\b((?:\s*,?\s*(?:each\s+)?(?:\d+|two|three|four|five|six)\s+(?:cubes?\s+)?"
                r"(?:long|high|tall))*)\s*,?\s*(?:in|forming|making|as)\s+a\s+square\b", re.I),
     _walls_in_square),
    # "in a square so they box in an empty space": what for (a box was built of 'box')
    (re.compile(r"\s*,?\s*\bso\s+(?:that\s+)?(?:they|it)\s+(?:box|fence|close|wall|shut|enclose)s?\s+(?:in\s+)?"
                r"(?:an?\s+)?(?:empty\s+|open\s+)?(?:space|area|yard|square|court)\b", re.I), ""),
    # "Take 3 off and move it to the front left": two changes (the first was dropped, silently)
    (re.compile(r"\b((?:take|knock|remove)\s+\w+\s+(?:cubes?\s+)?off(?:\s+(?:it|the\s+top))?)\s+and\s+(?:then\s+)?"
                r"(?=(?:move|shift|slide|put|place)\s+it\b)", re.I), r"\1. then "),
    # "Staircase. Cube count: exactly 10.": built of 10 cubes (10 steps were built)
    (re.compile(r"\s*[.;,]?\s*(?<!total\s)\b(?:cube|block)\s+count\s*(?::|is|of)?\s*(?:exactly\s+|precisely\s+|"
                r"just\s+)?(\d+)\b", re.I),
     lambda m: m.group(0) if re.search(r"\d|\b(?:one|two|three|four|five|six)\b",
                                       m.string[: m.start()], re.I)
     else f" using {m.group(1)} cubes"),  # sized before: the count is a claim (`claims`)
    # "put a tower of 2 at each end on top": on top at each end (read as relations in a cycle)
    (re.compile(r"\b(?:at|on)\s+(each|both|either)\s+(ends?)\s+on\s+top\b(?!\s+of)", re.I),
     r"on top at \1 \2"),
    # "remove two cubes from the one on the right": that one, two cubes lower
    (re.compile(r"\b(?:remove|take\s+away)\s+(\d+|one|two|three|four|five)\s+(?:cubes?|blocks?)\s+(?:from|off)\s+(the\s+"
                r"(?:(?:left|right|front|back|first|second|last|middle|tall|taller|tallest|short|shorter|shortest)\s+"
                r"(?:one|tower|stack|column)|(?:one|tower|stack|column)\s+on\s+the\s+(?:left|right|front|back)))\b",
                re.I), r"take \1 off \2"),
    # "Then you move him to the right side", "shift the whole thing to the back": move it
    (re.compile(r"\b(?:(?:you|we|i'?ll|i\s+will|then)\s+)?(?:move|shift|slide|push|put)\s+(?:him|her|the\s+whole\s+"
                r"(?:thing|lot|structure)|everything|all\s+of\s+it)\s+(?=to\s+(?:the\s+)?(?:left|right|front|back|"
                r"middle|centre|center)\b)", re.I), "move it "),
    # "slide it left by 2 cubes", "Move it back by 2": 2 cubes to the left, to the back
    (re.compile(r"\b(move|shift|slide|push)\s+(it|them)\s+(left|right|back|forward|backward|forwards|backwards)\s+"
                r"by\s+((?:\d+|one|two|three|four|five)(?:\s+(?:cubes?|cm|mm|parts?)|(?!\s*(?:m|blocks?)\b)))\b",
                re.I),
     lambda m: f"{m.group(1)} {m.group(2)} {m.group(4)}"
     + ("" if len(m.group(4).split()) > 1 else " cubes") + " to the "
     + {"forward": "front", "forwards": "front", "backward": "back", "backwards": "back"}.get(
         m.group(3).lower(), m.group(3).lower())),
    # "Build tower height 4. Add 3. Remove 1.": one cube off (refused as taking parts out)
    (re.compile(r"(?:^|(?<=[.;!?]\s))\s*(?:then\s+|now\s+)?(?:remove|take\s+away|subtract)\s+(\d+|one|two|three|"
                r"four|five)(?:\s+(?:cubes?|blocks?))?\s*(?=[.;!?]|$)", re.I),
     r"then take \1 off it"),
    # "15 cm from the back edge and 20 cm from right edge": from the right edge (the 20 cm was
    # read as the tower's height)
    (re.compile(r"\bfrom\s+(left|right|front|back)\s+(edge|side)\b", re.I), r"from the \1 \2"),
    # "at (x, y) = (45 cm, 30 cm)": x 45 cm, y 30 cm (the 30 cm was read as the height)
    (re.compile(r"\(\s*x\s*,\s*y\s*\)\s*=?\s*\(\s*(\d+(?:\.\d+)?)\s*(cm|mm|m)?\s*,\s*(\d+(?:\.\d+)?)\s*"
                r"(cm|mm|m)?\s*\)", re.I),
     lambda m: f"x = {m.group(1)} {m.group(2) or m.group(4) or ''}, y = {m.group(3)} "
     f"{m.group(4) or m.group(2) or ''}"),
    # "Revision B: length 7", "Change: height 3": that size now
    (re.compile(r"\b(?:revision|rev\.?|change|update|amendment|amend|correction|edit)\s*[A-Z0-9]?\s*:\s*"
                r"(length|height|width|steps)\s*(?:=|:|is|of)?\s*(\d+)\b(?!\s*(?:mm|cm|m|in|inch)\b)",
                re.I),
     lambda m: f"make it {m.group(2)} " + {"length": "long", "height": "high", "width": "wide",
                                            "steps": "steps"}[m.group(1).lower()]),
    # "make a slab 4 buy 4": by (the second 4 was dropped: a 2x2 slab, silently)
    (re.compile(r"(?<=\d)\s+(?:buy|bye|bu|bt)\s+(?=\d)", re.I), " by "),
    # "our little one loves bridges": what someone likes is no structure to build (a second
    # bridge was built, silently)
    (re.compile(r"\b(loves?|adores?|enjoys?|(?:is|are|s)\s+(?:really\s+|so\s+)?(?:into|crazy\s+"
                r"about|mad\s+about|obsessed\s+with|fond\s+of))\s+(?:all\s+)?(" + _FAMILY_SAID
                + r")s\b", re.I),
     lambda m: f"{m.group(1)} them"
     if re.search(rf"\b(?:an?|one|the)\s+(?:\w+\s+){{0,3}}?{m.group(2)}\b", m.string[m.end() :],
                  re.I)
     else m.group(0)),
    # "Tolerance of one cube is NOT acceptable": a tolerance, no cube to build
    (re.compile(r"\btolerances?\s+(?:of\s+|is\s+|=\s*)?(?:\+/-|±|plus\s+or\s+minus)?\s*"
                r"(?:\d+(?:\.\d+)?|one|half\s+a|a)\s*(?:cubes?|parts?|blocks?)\b", re.I),
     "tolerance"),
    # "three tower in line, height of them two, three, four, from left": in that order from the
    # left (all three were put in the left region, silently)
    (re.compile(r"(?:\s*,\s*|\s+)(?:starting\s+|counting\s+|going\s+|reading\s+)?from\s+(?:the\s+)?"
                r"(left|right)(?:\s+side)?\s*(?=[.;!]|$)", re.I),
     lambda m: m.group(0)
     if re.search(r"(?:\d|\b(?:cubes?|blocks?|parts?|units?|cm|mm|m|inch(?:es)?|away|apart|far|"
                  r"distance|offset|steps?|edge))\s*$", m.string[: m.start()], re.I)
     else f", {m.group(1)} to {'right' if m.group(1).lower() == 'left' else 'left'}"),
    # "three towers standing in a row …, a wall behind the whole row": behind them all (a row
    # was built for "the whole row", silently)
    (re.compile(r"\b(?:the\s+)?(?:whole|entire|full)\s+(?:row|line|group|set|lot)\b(?!\s+of\b)",
                re.I),
     lambda m: "them" if re.search(r"\bin\s+(?:a\s+)?(?:row|line)\b|\bside\s+by\s+side\b",
                                   m.string[: m.start()], re.I) else m.group(0)),
    # "a beam resting across from one top to the other": across them (the towers were stacked)
    (re.compile(r"\b(?:(?:resting|laid|lying|running|going|spanning|placed|set)\s+)?(?:across\s+)?"
                r"from\s+(?:the\s+)?(?:one|first)\s+(?:top|tower|post|pillar|column|stack|leg)?\s*to"
                r"\s+the\s+(?:other|second)(?:\s+(?:one|top|tower|post|pillar|column|stack|leg))?\b",
                re.I),
     " across them "),
    # "don't use any Technic beams": no beams (the word before the beams hid the refusal)
    (re.compile(r"\b(?:do\s+not|don'?t|never|please\s+don'?t)\s+use\s+(?:any\s+)?(?:[a-z]+\s+)?(beams?|planks?|"
                r"lintels?)\b", re.I), r"no \1"),
    # "a tower of 2 … And make the tower 4.": 4 high (a second tower was built)
    (re.compile(r"\b((?:make|set|change|turn|bring)\s+(?:the|that|this)\s+(?:tower|column|stack|pillar|post|"
                r"mast|obelisk)\s+(?:to\s+|into\s+)?)(\d+|one|two|three|four|five|six|seven|eight|nine|ten)\b"
                r"(?!\s*(?:high|tall|cubes?|blocks?|long|wide|x|by|levels?|layers?|steps?|cm|mm|m|more|less|"
                r"fewer|times|taller|shorter|higher|lower|bigger|smaller|longer|wider|narrower|up|down)\b)",
                re.I), r"\1\2 high"),
    # "Actually high 6", "Hmm, 3 high": a size said again corrects the one before
    (re.compile(r"\b(actually|no|sorry|wait|rather|hmm+)\s*,?\s*(high|tall|long|wide|deep)\s+(\d+|one|two|three|"
                r"four|five|six|seven|eight|nine|ten)\b", re.I), r"\1, \3 \2"),
    # a palletiser's words: "one course 8 long" is a row (error: no structure); "Two courses, 6
    # blocks per course" a wall 6 long, 2 high (a tower of 2); "Pallet: 3 rows by 4 columns, 2
    # layers" a 3 by 4 block 2 high (three rows and a pallet)
    (re.compile(r"\b(a|one|single|1)\s+course\b(?=\s+(?:of\s+)?" + _NUM + r"\b|\s+\w+\s+long\b)",
                re.I), r"\1 row"),
    (re.compile(r"\b(" + _NUM + r")\s+(?:courses|layers|levels|tiers)\s*,?\s*(" + _NUM
                + r")\s+(?:blocks?|bricks?|cubes?)\s+(?:per|in\s+each|each)\s+(?:course|layer|"
                r"level|tier)\b", re.I),
     r"a wall \2 long and \1 high"),
    (re.compile(r"\b(" + _NUM + r")\s+rows?\s+(?:by|x)\s+(" + _NUM + r")\s+columns?\s*,?\s*(" + _NUM
                + r")\s+(?:layers|levels|courses|tiers)\b", re.I),
     lambda m: (f"{m.group(1)} by {m.group(2)}, {m.group(3)} layers"
                if re.search(r"\b(?:pallet|slab|grid|block|base|platform|floor|pad|array)\b",
                             m.string[: m.start()], re.I)
                else f"a block {m.group(1)} by {m.group(2)}, {m.group(3)} high")),
    # "stacks of 2 in a 3 by 2 pattern": six of them (one stack was built)
    (re.compile(r"(?<![\w-])(?<!\d\s)((?:stacks|towers|columns|pillars|piles|posts)\s+of\s+" + _NUM
                + r"\s+(?:cubes?\s+)?in\s+an?\s+)(\d)\s*(?:x|by)\s*(\d)(?=\s+(?:grid|array|pattern|"
                r"matrix|layout|formation|arrangement)\b)", re.I),
     lambda m: (m.group(0)
                if re.search(r"\b(?:\d+|one|two|three|four|five|six|seven|eight|nine|ten|twelve|"
                             r"several|some|a\s+few)\s+(?:\w+\s+)?$", m.string[: m.start()], re.I)
                else f"{int(m.group(2)) * int(m.group(3))} {m.group(1)}{m.group(2)} by "
                f"{m.group(3)}")),
    # "a crossbeam on top", "a cross-beam", "a crosspiece": a beam (ignored: the posts stood
    # apart)
    (re.compile(r"\bcross[\s-]?(beam|piece|member)(s?)\b", re.I), r"beam\2"),
    # "Layers: 4x4, then 3x3, …": the heading names what the sizes are (read as 4 layers)
    (re.compile(r"\b(?:layers|levels|tiers|courses)\s*:\s*(?=\d+\s*(?:x|by)\s*\d+)", re.I), ""),
    # "with a single cube as the temple on top": the cube; its role names no structure (a
    # canopy was built for the temple)
    (re.compile(r"\b(cubes?|blocks?|bricks?|towers?(?:\s+of\s+\d+)?|rows?|slabs?)\s+as\s+(?:the|a|an|its)\s+"
                r"(?!(?:base|top|bottom|first|second|third|last|middle|centre|center|floor|roof|deck)\b)"
                r"[a-z]+\b(?=\s*(?:on|at|in|atop|beside|next|behind|,|\.|;|$))", re.I), r"\1"),
    # "three towers …, whose heights, respectively, are two, four and six cubes": of two, four
    # and six (all 6 high, silently)
    (re.compile(r"\s*,?\s*\b(?:whose|their)\s+heights?\s*,?\s*(?:respectively\s*,?\s*)?(?:are|being|of|"
                r"=|:)\s*(?:respectively\s*,?\s*)?(?=" + _NUM + r"\s*,)", re.I), " of "),
    # "separated from the next by a single cube's width": one cube (a cube was built, silently)
    (re.compile(r"\b(?:a|one)\s+(?:single\s+)?(cube|block|brick|part)'?s\s+(?:width|length|breadth)\b",
                re.I), r"one \1"),
    # "Make two tower, one have three cube, other have five cube": the other of five (3 and 3)
    (re.compile(r"(?<=,)\s*other\s+(?=(?:of|has|have|having|with|is|be)\b)", re.I), " the other "),
    (re.compile(r"\b(one|the\s+other|the\s+first|the\s+second)\s+(?:has|have|having|with|is\s+of)\s+("
                + _NUM + r")\s+(?:cubes?|blocks?|bricks?)\b", re.I), r"\1 of \2 cubes"),
    # "close together", "near each other", "they stand near": side by side (read as the front,
    # near the robot, silently)
    (re.compile(r"\b(?:(?:stand(?:ing)?|placed|set|put|built)\s+)?(?:close|near)\s+(?:together|to\s+each\s+other|"
                r"to\s+one\s+another|each\s+other|one\s+another)\b", re.I), "side by side"),
    (re.compile(r"\b(?:they|both|the\s+two)\s+(?:stand|are|go|should\s+be|standing)\s+(?:near|close)\b"
                r"(?=\s*(?:[,.;!]|$))", re.I), "side by side"),
    # "bridge, posts 3 high + beam, mid table": in the centre (a table was built)
    (re.compile(r"\b(?:at\s+|in\s+)?mid[\s-]+(?:table|bench|workspace|cell)\b", re.I),
     "in the centre"),
    # a checklist's "RH of A", "LH side": right-hand and left-hand (B stood on the left of A,
    # 'RH' reported unused, silently)
    (re.compile(r"\b(RH|LH)\s+(?:of|from)\b"),
     lambda m: f"to the {'right' if m.group(1) == 'RH' else 'left'} of"),
    (re.compile(r"\b(RH|LH)(?:\s+(side|end|corner))?\b"),
     lambda m: ("right" if m.group(1) == "RH" else "left")
     + (f" {m.group(2)}" if m.group(2) else "")),
    # "'Three, the tower, make it!' He means a tower of three.": what is meant, said again (both
    # were built)
    (re.compile(r"^.*?[\"'“‘][^\"'”’]+[\"'”’][\s.!?,]*(?:he|she|they|my\s+\w+|the\s+\w+)\s+(?:means?|meant)\s+",
                re.I | re.S),
     lambda m: "" if families_said(m.string[m.end() :]) else m.group(0)),  # what is meant, named
    # "a little tower on top of the middle": on top of it, centred (beside the bridge, silently)
    (re.compile(r"\bon\s+top\s+of\s+the\s+(?:very\s+)?(?:middle|centre|center)\b"
                r"(?=\s*(?:[,.;!?]|$|and\b|then\b|please\b))", re.I),
     lambda m: ("on top of it" if families_said(m.string[: m.start()]) else m.group(0))),
    # "none of them taller than 2": no taller than 2, a limit (a tower of 3, silently)
    (re.compile(r"\bnone\s+(?:of\s+them\s+)?(?:is\s+|are\s+|being\s+)?(taller|higher|longer|wider|bigger)\s+than\b",
                re.I), r"no \1 than"),
    # "none on the right side": not there (a tower was built on the right, silently)
    (re.compile(r"\bnone\s+(?:of\s+them\s+)?((?:on|at|in)\s+the\s+(?:left|right|front|back)"
                r"(?:\s+(?:side|half|edge))?)\b", re.I), r"not \1"),
    # "Is there room for two walls side by side?": a question of space (a room was built); "How
    # many cubes do you have?": of stock (a row of 8)
    (re.compile(r"\b(?:is\s+there|there'?s|have\s+you\s+got|do\s+you\s+have|got)\s+(?:enough\s+)?(?:room|space)\s+"
                r"(?:for|to\s+(?:build|fit|put|place))\b", re.I), "can you fit"),
    (re.compile(r"\bhow\s+many\s+(?:cubes|blocks|bricks|parts|pieces)\s+(?:do|have|are|can|did)\b[^.?!]*\?\s*",
                re.I), " "),
    # "take the first one away", "knock the end column off": the verb's particle said last (the
    # removal was refused)
    (re.compile(r"\b(take|knock|pull|lift)\s+((?:the|one|an?)\s+(?:(?:first|second|third|last|middle|left|right|"
                r"front|back|top|end|\w+est)\s+)?(?:one|tower|stack|column|pillar|row|wall|cube|block|layer|"
                r"level))\s+(away|off|out)\b", re.I),
     lambda m: (f"{m.group(1)} away {m.group(2)}"  # "take the right one off (the board)": gone
                if m.group(3).lower() == "off" and re.search(
                    r"\b(?:first|second|third|middle|left|right|front|back)\s+(?:one|tower|stack|"
                    r"column|pillar|row|wall|block)$", m.group(2), re.I)
                else f"{m.group(1)} {m.group(3)} {m.group(2)}")),
    # "… then a tower of three on the left, and then move the tower to the back": it, the one
    # named last (the move was refused)
    (re.compile(r"\b(move|shift|slide|put)\s+the\s+(" + _FAMILY_SAID
                + r")\s+(?=(?:to|over\s+to|into)\s+the\b)", re.I),
     lambda m: (f"{m.group(1)} it " if families_said(m.string[: m.start()])[-1:]
                == families_said(m.group(2)) else m.group(0))),
    # "to the right of A" of structures labelled A and B: of the first one
    (re.compile(r"\b(of|from|beside|behind|on|onto|next\s+to|than)\s+([A-D])\b(?!['’])(?![-.]?\w)"),
     _label_named),
    # "a third tower, of five, between the first two": between them (placed apart, silently)
    (re.compile(r"\bbetween\s+the\s+(?:first\s+two|two\s+first|other\s+two|two\s+others|two\s+of\s+them)\b"
                r"(?:\s+(?:" + _FAMILY_SAID + r"))?", re.I), "between them"),
    # "the first step one cube high, the second two, the third three, the fourth four": four
    # steps, each one higher (a 2-step staircase, read from the numbers)
    (re.compile(r"\b(?:the\s+)?first\s+(?:step|stair|level)\s+(?:is\s+)?(?:one|1)\s+(?:cubes?\s+)?(?:high|tall|up)?"
                r"(?:\s*,?\s*(?:and\s+|then\s+)?the\s+(?:second|third|fourth|fifth|sixth|seventh|eighth)\s+(?:step\s+|"
                r"stair\s+|one\s+)?(?:is\s+)?(?:\d|two|three|four|five|six|seven|eight)(?:\s+(?:cubes?\s+)?(?:high|tall|up))?)+",
                re.I), _steps_counted),
    # "put our class mascot cube right in the middle of it": a cube (the words were read as
    # chatter and the cube dropped)
    (re.compile(r"\b(?:our|my|your|his|her|their)\s+(?:[a-z]+\s+){0,2}?(cube|block|brick)\b(?=\s+(?:right\s+|just\s+)?"
                r"(?:in|on|at|inside|beside|next|behind|into|onto|between)\b)", re.I), r"a \1"),
    # "… a tower of two next to that, and then a tower of six on the other side of the first
    # one": across from it (dropped, silently)
    (re.compile(r"\b(?:on|at)\s+the\s+other\s+side\s+of\s+(it|that|this|the\s+first(?:\s+one)?|the\s+(?:"
                + _FAMILY_SAID + r"))\b", re.I), _other_side),
    # "go up in direction of robot": towards it (the staircase climbed the default way)
    (re.compile(r"\bin\s+(?:the\s+)?direction\s+(?:of|to|towards?)\s+(?:the\s+)?(robot|front|back|rear|left|"
                r"right)\b", re.I), r"towards the \1"),
    # "the longer limb being five cubes and the shorter three": an L's arms (both 3, silently)
    (re.compile(r"\b(?:the\s+|its\s+|with\s+the\s+)?(?:longer|long|longest|bigger|larger)\s+(?:arm|"
                r"limb|leg|side|branch|wing)\s+(?:being\s+|is\s+|of\s+|=\s*|:\s*)?(" + _NUM
                + r")(?:\s+cubes?)?(?:\s+long)?\s*,?\s*(?:and\s+)?(?:the\s+|its\s+)?(?:shorter|"
                r"short|shortest|smaller)(?:\s+(?:arm|limb|leg|side|branch|wing|one))?\s+(?:being\s+|is\s+|"
                r"of\s+|=\s*|:\s*)?(" + _NUM + r")\b(?:\s+cubes?)?(?:\s+long)?", re.I),
     r"arms \1 and \2"),
    # "region!=centre", "position=not left": anywhere but there (read as there, silently)
    (re.compile(r"\b(?:region|position|location|loc|place|where|side|area)\s*(?:!=|<>|≠|=\s*not\s+|"
                r":\s*not\s+)\s*(?:the\s+)?((?:front|back|rear)?[\s_-]*(?:left|right|centre|center|middle|"
                r"front|back|rear))\b", re.I),
     lambda m: f" not in the {m.group(1).replace('_', ' ').replace('-', ' ').strip()} "),
    # "And add a cube in the middle of the top": on top of it, centred (it stood in the table's
    # centre, silently)
    (re.compile(r"\b(?:in|on|at)\s+the\s+(?:very\s+)?(?:middle|centre|center)\s+of\s+(?:the|its)\s+top\b"
                r"(?!\s+of\b)", re.I), "on top of it"),
    # "bridge them with a 1x4 plate": the plate across them is their beam (it was laid between
    # them on the table, silently)
    (re.compile(r"\b((?:bridge|join|span|connect|link|cap|top)\s+(?:them|the\s+two|both)(?:\s+\w+)?\s+with\s+"
                r"(?:a|one|an)\s+)(?:\d+\s*x\s*\d+\s+|long\s+|flat\s+)?(?:plate|plank|board|tile|slab)\b",
                re.I), r"\1beam"),
    # "then a single on the peak": a single cube on top (dropped as chatter, silently)
    (re.compile(r"\b(a|one)\s+single\s+(?=(?:on|at|atop|onto|in|to|beside|next|behind)\b)", re.I),
     r"\1 single cube "),
    (re.compile(r"\b(on|at|to|onto)\s+(?:the|its)\s+(?:very\s+)?(?:peak|apex|summit|tip|pinnacle)\b"
                r"(?!\s+of\b)", re.I), r"\1 top"),
    # "with a gap of one one cube": a number said twice in speech is said once
    (re.compile(r"\b(one|two|three|four|five|six|seven|eight|nine|ten)\s+\1\b(?=\s+(?:cubes?|blocks?|"
                r"bricks?|high|tall|long|wide|levels?|layers?|steps?)\b)", re.I), r"\1"),
    # "Move it to the front. No, further right too": a move as well as the one before, not
    # instead of it (the front was lost, silently)
    (re.compile(r"\bno\b\s*[,.!]?\s*(?:(?:move\s+it\s+|put\s+it\s+)?(?:further|farther|more|a\s+bit|"
                r"a\s+little)\s+)?(?:to\s+(?:the\s+)?)?(left|right|front|back)\s*,?\s*(?:too|as\s+well|also)\b",
                re.I), r"and move it to the \1"),
    # "Make it 4 levels. No, back to 3": that number again (read as the back, silently)
    (re.compile(r"\b(no|nope|actually|wait|sorry|hmm)\b\s*[,.!]?\s*(?:go\s+|change\s+it\s+|make\s+it\s+|"
                r"put\s+it\s+|set\s+it\s+)?back\s+to\s+(\d+|one|two|three|four|five|six|seven|eight|nine|"
                r"ten)\b(?!\s*(?:mm|cm|m|in|inch|inches)\b)", re.I), r"\1, \2"),
    # "Is too tall, make 1 layer less": one layer lower
    (re.compile(r"\b(?:it\s+)?is\s+too\s+(?:tall|high|big),?\s*(?:so\s+)?(?:make|do)\s+(?:it\s+)?(\d+|one|two|"
                r"three)\s+(?:layers?|levels?|rows?|courses?|cubes?)\s+less\b", re.I),
     r"make it \1 lower"),
    # "add one cube to each pillar": to each of them (a 1-cube tower was built besides, silently)
    (re.compile(r"\b(?:(?:raise|lift|heighten)\s+(?:the\s+whole\s+thing|it|the\s+\w+)\s+)?(?:by\s+)?(?:add(?:ing)?|"
                r"put(?:ting)?|stack(?:ing)?|plac(?:e|ing))\s+(a|one|an\s+extra|1|two|2)\s+(?:more\s+)?(cubes?|blocks?)\s+"
                r"(?:to|on(?:to)?)\s+(?:the\s+top\s+of\s+)?each\s+(?:pillar|post|leg|column|support|tower|stack)\b",
                re.I), r"add \1 \2 to each of them"),
    # "Position: 5 cm from the front edge. Item: row of 6": the item, then where it goes
    (re.compile(r"\b(?:position|place|location|where)\s*:\s*([^.;]+)[.;]\s*(?:item|build|part|structure|what)\s*:\s*"
                r"([^.;]+)", re.I), r"\2, \1"),
    # "T shape flat, bar 5 stem 3": terse parts and sizes, one after another without commas
    (re.compile(r"\b(bar|stem|arms?|base|legs?|posts?|pillars?|beam|top)\s+(\d+)\s+(?=(?:bar|stem|arms?|"
                r"legs?|posts?|pillars?|beam|height|length|width|gap)\s+\d)", re.I), r"\1 \2, "),
    # "A castle! Nothing fancy, just a castle please": the one named, said again (two were built)
    (re.compile(r"(?<=[.!?,;]\s)\s*(?:(?:nothing\s+(?:fancy|special|else)|keep\s+it\s+simple)\s*,?"
                r"\s*)?just\s+(?:an?|one)\s+(" + _FAMILY_SAID
                + r")\s*(?:,?\s*please)?\s*(?=[.!?;:)(]|$)", re.I),
     lambda m: " " if m.group(1).lower() in re.findall(r"[a-z]+", m.string[: m.start()].lower())
     else m.group(0)),
    # "a 5 high tower with a 2 high one touching it on the right": a second structure (the two
    # were read as one, its height twice)
    (re.compile(r"\bwith\s+(?:an?|one)\s+(" + _NUM + r")[\s-]+(?:cubes?[\s-]+)?(high|tall)\s+("
                + _FAMILY_SAID + r"|one)\b", re.I),
     _with_sized_one),
    # "2 x 4 slab, and on it a 2 x 2 slab at one end": the one on it, at that end of its top (two
    # relations in one clause left the end unplaced)
    (re.compile(r"\s*,?\s*\band\s+on\s+(?:it|that|this|top)\s*,?\s+(an?\s+[^,.;]+?)\s+(?:at|on)\s+"
                r"(one|either|the\s+(?:left|right|front|back|far|near))\s+end\b", re.I),
     r", with \1 on \2 end"),
    # "a pyramid with a 5x5 base and a tower of 3 next to it": the pyramid's size (the base was
    # read as a block of its own when a relation followed)
    (re.compile(r"\b(pyramids?)\s+(?:with|having|on)\s+(?:an?\s+|its\s+)?(?:(\d+)\s*(?:x|by)\s*(\d+)"
                r"\s+(?:square\s+)?(?:base|bottom(?:\s+layer)?|footprint)|(?:square\s+)?(?:base|bottom"
                r"(?:\s+layer)?|footprint)\s+(?:of\s+)?(\d+)(?:\s*(?:x|by|on|times)\s*(\d+))?)"
                r"(?:\s+cubes?)?(?:\s+(?:wide|across|(?:on\s+)?(?:a|each)\s+side))?\b"
                r"(?!\s*(?:x|by|on|cm|mm|m)\b)", re.I),
     _pyramid_base),
    # "just a cube, one single cube, front left": the cube said again, one (two were built)
    (re.compile(r"\b(an?\s+(?:single\s+)?([a-z]+))\s*,\s*(?:just\s+|only\s+)?(?:one|a)\s+(?:single|"
                r"lone|solitary|only)\s+\2\b", re.I), r"\1"),
    # "each want a tower, one on the left and one on the right": two of them, one each (a third
    # tower was built)
    (re.compile(r"\b(?:an?|one)\s+(" + _FAMILY_SAID + r")\s*,\s*(?=one\s+(?:on|at|in|to)\b"
                r"[^.;]*?\band\s+(?:one|the\s+other)\s+(?:on|at|in|to)\b)", re.I),
     lambda m: (f"two {m.group(1)}s, " if f"{m.group(1).lower()}s" in lx.SHAPE_WORDS
                else m.group(0))),
    # "an L shape 4 by 4, then a tower of 3 on the corner", "… on its corner": on a corner of the
    # structure before (stood apart from it, silently, or in a corner of the table)
    (re.compile(r"\bon\s+(?:its|the)\s+corner\b(?!\s*(?:of|closest|nearest|next|by|cubes?|blocks?|"
                r"parts?|ones?|pieces?)\b)", re.I),
     lambda m: (m.group(0) if l_named_last(m.string[: m.start()])  # the L's own corner: its bend
                else "on one corner of it" if m.group(0).lower().split()[1] == "its"
                or len(families_said(m.string[: m.start()])) >= 2 else m.group(0))),
    # "two towers of 2. make the towers 4 high", "… now make the posts four high": all of them
    # (a third tower was built, or one of them changed)
    (re.compile(r"\b(make|set|raise|lower|build|bring|take|turn)\s+(?:all\s+|both\s+)?(?:of\s+)?"
                r"the\s+(?:two\s+|three\s+|four\s+)?(" + _FAMILY_SAID
                + r")s\b(?=\s+(?:to\s+|up\s+to\s+|down\s+to\s+)?(?:\d|one|two|three|four|five|"
                r"six|seven|eight|nine|ten|taller|higher|shorter|lower|longer)\b)", re.I),
     lambda m: (f"{m.group(1)} them" if {lx.SHAPE_WORDS.get(m.group(2).lower())}
                == set(families_said(m.string[: m.start()])) else m.group(0))),
    # "A row of 5, then 3 on it, then 1.", "4x4, then 3x3, then 2x2, then one cube": layers in turn
    (re.compile(r"\b(?P<head>(?:an?\s+)?(?:row|line|course)\s+of\s+(?P<n>" + _NUM
                + r")(?:\s+cubes?)?|(?:an?\s+)?" + _NUM + r"\s*(?:x|by)\s*" + _NUM
                + r"(?:\s+(?:layer|slab|square|base|floor))?)(?P<rest>(?:" + _THEN_SIZE.pattern
                + r"){2,})", re.I),
     _layers_in_turn),
    # "three towers: a small tower, a medium tower and a big tower": the count heads its list
    (re.compile(r"\b(two|three|four|five|six|[2-6])\s+((" + _FAMILY_SAID + r")s)\s*:\s*", re.I),
     _listed_after_count),
    # "three towers: a small one, a medium one and a big one"
    (re.compile(r"(?<!not\s)(?<!no\s)\b(an?)\s+((?:(?:really|very|bit)\s+)?(?:middle|mid|"
                + "|".join(sorted(lx.SIZE_WORDS))
                + r")(?:[\s-]*sized)?)\s+one\b(?![\s-]*(?:cubes?|blocks?|parts?|high|tall|long|"
                r"wide|deep|layers?|levels?|of)\b)", re.I),
     _sized_one),
    # "Gate, opening two cubes wide, posts four high": the gap between its posts (dropped)
    (re.compile(r"\b(?:an?\s+|the\s+)?(?:clear\s+)?opening\s+(?:of\s+|is\s+)?(" + _NUM
                + r")\s+(?:cubes?\s+|blocks?\s+)?(?:wide|across)\b|\b(?:an?\s+)?(" + _NUM
                + r")[\s-]+(?:cubes?[\s-]+|blocks?[\s-]+)?(?:wide\s+)?opening\b", re.I),
     lambda m: (m.group(0) if re.search(r"\barch", m.string, re.I)  # its corbels narrow it
                else f"span {m.group(1) or m.group(2)}")),
    # "Make the left one taller, five": the height said after the comparison (made 1 taller)
    (re.compile(r"\b(taller|higher|shorter|lower|longer)\s*[,:—–-]\s*(?:to\s+|say\s+)?(" + _NUM
                + r")\b(?=\s*(?:[.;,!]|$|and\b|then\b))", re.I),
     lambda m: (m.group(0) if re.search(r"\bmake\s*$", m.string[: m.start()], re.I)  # no object
                else f"{m.group(2)} {'long' if m.group(1).lower() == 'longer' else 'high'}")),
    # "with the taller one standing behind": the taller one behind (it stood in front, silently)
    (re.compile(r"\b(?:with\s+)?(the\s+(?:taller|shorter|bigger|smaller|higher|lower|tallest|"
                r"shortest|biggest|smallest|longer|shorter)(?:\s+one)?)\s+(?:is\s+)?(?:standing|placed|"
                r"set|sitting|going|positioned|located)\s+(?=behind|in\s+front|at\s+the|on\s+the|"
                r"to\s+the)", re.I), r"\1 "),
    # "Square of cubes, inside empty": empty inside, a ring (a solid slab was built)
    (re.compile(r"\b(?:the\s+)?inside\s+(?:is\s+|left\s+)?(empty|hollow|open)\b", re.I),
     r"\1 inside"),
    # "Two wall, each six long": a count before a singular noun, as non-native speakers say it
    # (read as one wall 2 high, silently)
    (re.compile(r"(?<!\ba\s)(?<!\ban\s)(?<!\bthe\s)(?<!\bof\s)\b(two|three|four|five|six|seven|eight|"
                r"nine|ten)\s+(" + _FAMILY_SAID + r")\b(?=\s*(?:[,:;]|each|every|and\b|with\b|$))",
                re.I),
     lambda m: (f"{m.group(1)} {m.group(2)}s" if f"{m.group(2).lower()}s" in lx.SHAPE_WORDS
                else m.group(0))),
    # "two towers, first is 3, second is 6", "the first one 3 and the second one 6": each one's
    # size in turn (both were built 3 high, or the second 1 high, silently)
    (re.compile(r"\b(?:the\s+)?(first|second|third|fourth|last)(?:\s+one\b)?+\s*(?:is\s+|=\s*|"
                r":\s*)?(" + _NUM + r")\b(?!\s*(?:x|by|cm|mm|m|cubes?\s+(?:apart|away|gap|from)|"
                r"apart|away|gap|from|of|high|tall|long|wide|deep|levels?|layers?|steps?)\b)",
                re.I),
     lambda m: (f"the {m.group(1)} one of {m.group(2)}"
                if _COUNTED_PLURAL.search(m.string[: m.start()])
                and not _CHANGE_LED.search(m.string[: m.start()]) else m.group(0))),
    # "put second behind of first": the ordinals as the ones named (the relation was dropped)
    (re.compile(r"\b(put|place|set|stand)\s+(?:the\s+)?(first|second|third|last)(?:\s+one)?\s+(behind|"
                r"in\s+front\s+of|next\s+to|beside|on\s+top\s+of|on|(?:to\s+the\s+)?(?:left|right)\s+"
                r"of)(?:\s+of)?\s+(?:the\s+)?(first|second|third|last)(?:\s+one)?\b", re.I),
     r"\1 the \2 one \3 the \4 one"),
    # "A flat three by four slab on four legs of three cubes": a table, that top (a slab with a
    # tower beside it was built)
    (re.compile(r"\b(?:an?\s+)?(?:flat\s+)?(" + _NUM + r"\s*(?:x|by)\s*" + _NUM
                + r")\s+(?:flat\s+)?(?:slab|top|platform|plate|board|deck|tabletop)\s+(?:on|"
                r"resting\s+on|supported\s+by|"
                r"standing\s+on|sitting\s+on|set\s+on|on\s+top\s+of)\s+(four|4)\s+(legs|posts|pillars|"
                r"columns|supports)\b", re.I),
     r"a table \1 with \2 \3"),
    # changes said plainly, into the words the changes read: "pull two off the top", "Take off
    # the last three", "Move it back by 2", "make of five", "bring them closer, one cube apart"
    # (each was reported as a change SDI cannot make, or dropped)
    (re.compile(r"\b(?:pull|knock|lift|pop|pluck|remove)\s+(" + _NUM
                + r")\s+(?:cubes?\s+|blocks?\s+)?(?:off|from)\s+(?:the\s+)?(top|end)\b", re.I),
     r"take \1 off the \2"),
    (re.compile(r"\b(?:take\s+off|take\s+away|remove|drop)\s+the\s+last\s+(?!one\b)(" + _NUM
                + r")\b"
                r"(?!\s*(?:towers?|stacks?|walls?|rows?))", re.I), r"take \1 off"),
    (re.compile(r"\bmake\s+(?:of|with)\s+(?=" + _NUM + r"\b)", re.I), "make it "),
    (re.compile(r"\b(?:now\s+|then\s+)?(?:bring|move|put|push)\s+them\s+(?:closer(?:\s+together)?|"
                r"further\s+apart|farther\s+apart|apart)\s*,?\s*(?:to\s+)?(" + _NUM
                + r")\s*(cubes?|blocks?|mm|cm)?\s*(?:apart|gap)\b", re.I),
     lambda m: f"make the gap {m.group(1)} {m.group(2) or 'cubes'}"),
    # "Base, this is floor. Block two by two by two, …": a radio call's call signs (a grid was
    # built for "Base")
    (re.compile(r"^\s*\w+(?:\s+\w+)?\s*,\s*this\s+is\s+\w+(?:\s+\w+)?\s*[.,;:]\s*", re.I), ""),
    # "two stacks of five, just the stacks": the stacks said again (a third one was built)
    (re.compile(r"\s*,?\s*\b(?:just|only)\s+the\s+(" + _FAMILY_SAID + r")s\b(?=\s*(?:[,.;]|$))",
                re.I),
     lambda m: "" if lx.SHAPE_WORDS.get(m.group(1).lower()) in families_said(m.string[: m.start()])
     else m.group(0)),
    # "three towers um two three and four high": a list said without commas (all were built 4 high)
    (re.compile(r"(?<![\d.]\s)(?<!x\s)(?<!by\s)\b(" + _NUM + r")((?:\s+" + _NUM
                + r")+)\s+(and|&)\s+(" + _NUM + r")\b(?!\s*(?:x|by|cm|mm|m)\b)", re.I),
     lambda m: (", " if re.search(r"[a-z]s(?:\s+(?:um+|uh+|er+|erm+))?\s*$", m.string[: m.start()])
                else "")
     + ", ".join([m.group(1), *m.group(2).split()]) + f" {m.group(3)} {m.group(4)}"),
    # "Row, qty 7 cubes", "Qty 4 columns": a quantity (seven rows were built); "Block 150 x 100
    # mm, qty 2": that many of the structure named first (one was built)
    (re.compile(r"\b(?:qty|quantity)\.?\s*[:=]?\s*(" + _NUM + r")\s+(?=[a-z])", re.I), r"\1 "),
    (re.compile(r"^(\W*)(?:an?\s+)?(" + _FAMILY_SAID + r")\b([^.;]*?),\s*(?:qty|quantity)\.?\s*"
                r"[:=]?\s*(" + _NUM + r")\b", re.I),
     lambda m: (f"{m.group(1)}{m.group(4)} {m.group(2)}s{m.group(3)}"
                if f"{m.group(2).lower()}s" in lx.SHAPE_WORDS else m.group(0))),
    # "move it to the front-left spawn point": the corner said with a hyphen (read as the front)
    (re.compile(r"\b(front|back|rear)-(left|right)\b", re.I), r"\1 \2"),
    # "Four towers of three, each one in one corner of the table": one in each corner (the four
    # were lined up in the middle, silently)
    (re.compile(r"\beach(?:\s+one)?\s+(?:in|at|on)\s+(?:one|a|its\s+own)\s+corner\b", re.I),
     "one in each corner"),
    # "an L shape, three cubes along each side": its arms (read as an axis; a 2 by 2 L, silently)
    (re.compile(r"\balong\s+(each|every|both)\s+(sides?|arms?|legs?|edges?)\b", re.I), r"on \1 \2"),
    # "Before the wall of five, at distance of one cube, a tower of four": in front of it, as
    # non-native speakers say it (no verb: a place, not an order of work)
    (re.compile(r"(^|[.;:]\s*)before\s+(?=(?:the|a|an|it)\b(?![^.;]*\b(?:build|put|place|make|stack|"
                r"lay|add|start|begin|do|you|we|i)\b))", re.I), r"\1in front of "),
    # "from left toward right": from left to right (read as a place on the right)
    (re.compile(r"\bfrom\s+(?:the\s+)?(left|right|front|back)\s+towards?\s+(?:the\s+)?(left|right|front|"
                r"back)\b", re.I), r"from \1 to \2"),
    # "the block of two for two", "a ring of five for five": by, as non-native speakers say it
    (re.compile(r"(?<=\s)(" + _NUM + r")\s+for\s+(" + _NUM + r")\b", re.I), r"\1 by \2"),
    # "shape=tower; h=2; on=block 2x2x2": on a block (stood beside it, silently)
    (re.compile(r"[;,]\s*(on|under|inside|around|beside|behind)\s*=\s*(?=[a-z])", re.I), r" \1 a "),
    # "shape=row; n=5; axis=x": along x (dropped as chatter, silently)
    (re.compile(r"\b(?:axis|dir|direction|orientation)\s*[:=]\s*([xy])\b", re.I), r"along \1"),
    # "Two towers: 2 and 5. The 2 goes behind the 5": the ones of those sizes
    (re.compile(r"\bthe\s+(" + _NUM + r")(?:\s+one)?\s+(?:(?:goes|is|stands|sits|should\s+(?:go|be|"
                r"stand)|must\s+(?:go|be)|will\s+(?:go|be))\s+)?(behind|in\s+front\s+of|to\s+the\s+"
                r"(?:left|right)\s+of|left\s+of|right\s+of|next\s+to|beside|on\s+top\s+of|on)\s+the\s+("
                + _NUM + r")(?:\s+one)?\b", re.I),
     _by_their_sizes),
    # "3 towers of 4, 1 gap", "in a line 1 gap": the gap's size (read as a height in a list, or
    # as a row 1 long beside the towers, silently)
    (re.compile(r"(?<!by\s)(?<![x×]\s)(?<![x×])\b(\d+|one|two|three)\s+(gap|space)\b"
                r"(?!\s*(?:of|between|to|from|inside|within|in\s+the)\b)", re.I),
     r"\2 \1"),
]
"""The everyday phrasings, in the order they are tried (earlier rewrites feed later ones)."""
