"""Clauses that change a structure already read: "then add two more cubes to it", "make it 5
high", "move it to the left", or words that continue the phrase before ("Make a tower. 4
cubes."); and changes SDI cannot make (taking parts out), which are reported."""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping

from sdi.errors import SpecError
from sdi.language.nouns import shape_alternation
from sdi.language.state import Phrase, ReadState
from sdi.model.cell import CellConfig
from sdi.spec import lexicon as lx
from sdi.spec.grammar import PRIMARY, parse_phrase
from sdi.spec.numbers import words_to_numbers
from sdi.spec.structure_spec import StructureDraft

_N = r"(\d+(?:\.\d+)?|a|an|one|two|three|four|five|six|seven|eight|nine|ten|another|one\s+more)"


_UNIT = (
    r"(?:\s+(?:more|extra|additional|further))?"
    r"(?:\s+(?:cubes?|levels?|layers?|parts?|blocks?|steps?|storeys?|tiers?))?"
)


_REF = (  # not a place: "stack 5 on the right" is a stack of its own there
    r"(?:it|them|the\s+(?!(?:left|right|front|back|middle|centre|center|table)\b(?!\s+(?:one|tower|"
    r"stack|column|pillar|wall|row|block)\b))\w+(?:\s+one)?|"
    r"each(?:\s+of\s+them|\s+one)?|all\s+of\s+them|them\s+all|both)"
)


_WHICH = (
    r"short|shorter|shortest|small|smaller|smallest|low|lower|lowest|tall|taller|tallest|big|bigger|"
    r"biggest|high|higher|highest|middle|first|second|third|last"
)
"""The words that pick one of several towers (`_which_tower`)."""


# a change said on its own ("too much, half of that", "no, double it"), not a comparison that
# sizes another structure ("and the other one twice that", "one double that height")
_CHANGE_LEAD = (
    r"(?:^\W*|\btoo\s+(?:much|many|tall|high|big|small|short|low|little)\W+|"
    r"\bmake\s+(?:it|them)\s+|^\W*no\W+)"
)
_NO_NOUN = r"(?!\s+(?:height|size|length|width|tall|high|long|wide|big|many|much))"


def _op(pattern: str, op: str) -> tuple[re.Pattern[str], str]:
    return re.compile(pattern, re.IGNORECASE), op


DROP_VERBS = (
    r"(?:take\s+(?:out|away|down)|remove|leave\s+out|drop|skip|lose|ditch|forget(?:\s+about)?|"
    r"scrap|cancel|delete|get\s+rid\s+of)"
)
"""The verbs that take one of several structures named away ("forget the second one")."""

_TWO_MIDDLE = (
    r"(?:two\s+(?:in\s+the\s+(?:middle|centre|center)|middle\s+ones?|inner\s+ones?)|middle\s+(?:two|"
    r"pair)(?:\s+of\s+them)?|two\s+(?:middle|inner)\s+(?:ones|towers|stacks|columns|pillars))"
)
"""The two in the middle of a line of four (or six), after "the"."""
_MIDDLE_TWO = r"the\s+" + _TWO_MIDDLE

# (pattern, operation on the height of the structure referred to)
MODIFY = [
    # "4 towers of 2 in a row. remove the middle two": those two taken away
    _op(r"\b" + DROP_VERBS + r"\s+(?:the\s+)?" + _TWO_MIDDLE + r"\b", "drop2"),
    # "four towers of 2 in a row; make the two in the middle 5 high", "bump the middle pair up
    # to 6", "the two in the middle go up to 4 high": those two, that high
    _op(
        r"\b(?:(?:make|raise|bump|bring|take|lower|set|put)\s+" + _MIDDLE_TWO
        + r"\s+(?:up\s+|down\s+)?(?:to\s+)?|" + _MIDDLE_TWO
        + r"\s+(?:should\s+)?(?:go|goes|come|be|are)\s+(?:up\s+|down\s+)?"
        r"(?:to\s+)?)(\d+|one|two|three|four|five|six|seven|eight|nine|ten)(?:\s+(?:cubes?\s+)?"
        r"(?:high|tall))?\b(?!\s*(?:more|less|fewer)\b)",
        "middle2",
    ),
    # "build a castle, then make the towers taller (4 high)": its corner towers
    _op(
        r"\bmake\s+(?:the|its|all\s+the)\s+(?:corner\s+)?(?:towers|turrets)\s+(?:(?:taller|higher)\s*"
        r"[,(]?\s*)?" + _N
        + r"(?:\s+(?:cubes?\s+)?(?:high|tall|each))?\)?(?:\s+(?:each|instead))?\s*$",
        "=turrets",
    ),
    # "then raise the corners to 4": a castle's corner towers
    _op(
        r"\b(?:raise|heighten|lift|extend|make)\s+(?:the|its|all\s+the)\s+(?:corners|corner\s+towers|turrets)\s+"
        r"(?:up\s+)?to\s+" + _N + r"(?:\s+(?:cubes?\s+)?(?:high|tall))?\s*[.!]?\s*$",
        "=turrets",
    ),
    _op(r"\b(?:add|put|stack|place|pile)\s+" + _N + r"\s+(?:more|extra|additional)" + _UNIT, "+"),
    _op(r"\b(?:add|put|stack|place)\s+" + _N + _UNIT + r"\s+(?:to|on|onto)\s+" + _REF + r"\b", "+"),
    # "put a cube on top of each of them": one more on each
    _op(
        r"\b(?:add|put|stack|place|set)\s+(?:a|one|an)\s+(?:more\s+|extra\s+|single\s+)?(?:cube|block|"
        r"1-cube\s+tower)\s+"
        r"on(?:to)?\s+(?:(?:the\s+)?top\s+of\s+)?(?:each|every|all|both)(?:\s+of\s+them|\s+one|"
        r"\s+tower|\s+stack)?\b",
        "+1",
    ),
    _op(
        r"\b(?:add|stack|put|place|lay)\s+(?:a|one|another)\s+(?:second|third|fourth|fifth|new|further|"
        r"extra|more)?\s*(?:(?:identical|same|matching|similar|equal)\s+)?(?:layer|level|tier|storey|"
        r"course)\b(?!\s+of\b)",
        "+1",
    ),
    _op(
        r"\bmake\s+" + _REF + r"\s+" + _N + r"\s+(?:more\s+)?(?:cubes?\s+|levels?\s+|layers?\s+)?"
        r"(?:taller|higher)\b",
        "+",
    ),
    # "a tower of 3, make it taller": one more (nothing changed, silently)
    _op(r"\bmake\s+(?:it|that|this)\s+(?:one\s+)?(?:taller|higher)\s*(?:please\s*)?[.!]?\s*$",
        "+1"),
    # "then make it one layer thicker": one layer more; "make the row 2 longer": its length
    _op(
        r"\bmake\s+" + _REF + r"\s+" + _N + r"\s+(?:more\s+)?(?:levels?\s+|layers?\s+|courses?\s+)"
        r"(?:thicker|deeper|taller|higher)\b",
        "+",
    ),
    _op(
        r"\bmake\s+" + _REF + r"\s+" + _N + r"\s+(?:more\s+)?(?:cubes?\s+|parts?\s+)?"
        r"(?:longer|bigger|larger)\b",
        "+main",
    ),
    _op(
        r"\b(?:raise|extend|grow|lengthen)\s+(?:it|them|the\s+(?:row|wall|tower|stack|column))\s+"
        r"(?:by\s+" + _N + _UNIT + r"|" + _N
        + r"\s+(?:more\s+)?(?:layers?|levels?|courses?|storeys?)\b)",
        "+",
    ),
    _op(
        r"\b(?:keep\s+adding|add)\s+(?:steps|levels|layers|cubes)\s+until\s+(?:it|there)\s+"
        r"(?:has|is|are)\s+" + _N,
        "=",
    ),
    _op(r"\b(?:build|raise|stack|grow)\s+(?:it|them)\s+up\s+to\s+" + _N, "="),
    # "a staircase of 3 steps, then extend it to 5 steps", "then raise it to 6"
    _op(
        r"\b(?:extend|raise|grow|increase|lengthen|heighten|bring|take|top\s+up)\s+"
        r"(?:it|them|the\s+(?:tower|stack|row|wall|staircase|stairs|pyramid|column)|the\s+(?:middle|centre|"
        r"center|first|second|third|last|left|right|front|back)\s+(?:one|tower|stack|column))\s+(?:up\s+)?"
        r"to\s+" + _N + r"(?:\s+(?:steps|cubes?|levels?|layers?|storeys?))?"
        r"(?:\s+(?:high|tall|long))?(?!\s*(?:cm|mm|m|x|by)\b)",
        "=main",
    ),
    _op(r"\bmake\s+(?:it|them)\s+" + _N + r"\s*(?:instead)?\s*$", "=main"),
    # "row 8. shorten to 5.", "6 is too tall, go with 4", "make it longer, 6": the new size
    _op(
        r"\b(?:(?:shorten|trim|cut|reduce|lower|lengthen|extend|raise|heighten)(?:\s+(?:it|them|"
        r"the\s+(?:tower|stack|row|wall|staircase|stairs|pyramid|column)))?(?:\s+(?:down|back|up))?"
        r"\s+to|go\s+(?:with|for)|settle\s+(?:on|for)|"
        r"make\s+(?:it|them)\s+(?:a\s+bit\s+|a\s+little\s+)?(?:longer|more\s+long|taller|higher|"
        r"shorter|lower|smaller|bigger)\s*[,:(]?\s*(?:to\s+|like\s+|say\s+)?)\s+" + _N
        + r"(?:\s+(?:steps|cubes?|levels?|layers?))?(?:\s+(?:high|tall|long))?"
        r"\s*(?:instead)?\s*[.!)]?\s*$",
        "=main",
    ),
    # "a 4x2 slab, then make it 3 wide instead of 2": that side (the one that was 2)
    _op(
        r"\bmake\s+(?:it|them|the\s+(?:slab|grid|block|platform|pad|layer))\s+" + _N
        + r"\s+(?:cubes?\s+|rows?\s+)?(?:wide|deep|across|thick)\b"
        r"(?:\s+instead\s+of\s+(\d+|one|two|three|four|five|six|seven|eight))?",
        "=side",
    ),
    # "a 4x2 slab, then add a row along the back": the slab one row deeper (wider at a side)
    _op(
        r"\badd\s+(?:a|one|another)\s+(?:more\s+|extra\s+)?row\b(?:\s+of\s+cubes)?(?:\s+(?:along|at|on|to)"
        r"\s+(?:the\s+|its\s+)?(back|front|left|right)(?:\s+(?:side|edge|end))?)?(?=\s*(?:$|[.,;!]|and\b))",
        "+row",
    ),
    # "stack 4 cubes, take one off, then add three": three more
    _op(
        r"\b(?:then\s+)?add\s+" + _N
        + r"(?:\s+(?:cubes?|blocks?))?(?:\s+(?:back|again))?\s*[.!]?\s*$",
        "+",
    ),
    # "a row of 3, then make it 5 long", "then make the right one 4 tall": that size set
    _op(
        r"\bmake\s+" + _REF + r"\s+(?:all\s+)?" + _N
        + r"\s+(?:cubes?\s+|levels?\s+)?(?:high|tall)\b(?!\s+(?:and|but|by|x)\b)",
        "=",
    ),
    _op(
        r"\bmake\s+" + _REF + r"\s+(?:all\s+)?" + _N + r"\s+(?:cubes?\s+)?long\b"
        r"(?!\s+(?:and|but|by|x)\b)",
        "=length",
    ),
    # "make its height 5", "set the tower's height to 6", "change the wall's length to 8"
    _op(
        r"\b(?:make|set|change|changed|bring|increase|reduce|raise|lower)\s+(?:its|their|the\s+\w+'s|the)"
        r"\s+height\s+(?:up\s+|down\s+)?(?:to\s+|into\s+)?" + _N
        + r"(?:\s+(?:cubes?|levels?|layers?))?\s*(?:instead)?\s*[.!]?\s*$",
        "=",
    ),
    _op(
        r"\b(?:make|set|change|changed|bring|increase|reduce|extend)\s+(?:its|their|the\s+\w+'s|the)"
        r"\s+length\s+(?:up\s+|down\s+)?(?:to\s+|into\s+)?" + _N
        + r"(?:\s+(?:cubes?|steps?))?\s*(?:instead)?\s*[.!]?\s*$",
        "=main",
    ),
    # "then called back and changed it to 5", "change that to 4 high"
    _op(
        r"\b(?:change|changed|changes|changing|bump|bumped|drop|dropped|cut|reduce|reduced|increase|"
        r"increased|up|upped)\s+(?:it|that|them|this|the\s+(?:number|height|size|count))\s+"
        r"(?:up\s+|down\s+)?(?:to|into)\s+" + _N + r"(?:\s+(?:cubes?|high|tall|long|levels?|steps?|"
        r"layers?))?\s*(?:instead)?\s*[.!]?\s*$",
        "=main",
    ),
    # "Build a tower of 5, then another one of 5 to the right of it. Make the second one 3."
    _op(
        r"\b(?:make|change)\s+the\s+(?:first|second|third|fourth|last|middle|left|right|front|back|"
        r"taller|tallest|higher|highest|bigger|biggest|larger|largest|shorter|shortest|lower|lowest|"
        r"smaller|smallest|tall|short|big|small)(?:[\s-]hand)?\s+"
        r"(?:one|tower|stack|column|pillar|row|wall)\s+(?:to\s+|into\s+)?" + _N
        + r"(?:\s+(?:cubes?|high|tall|long|levels?))?"
        r"\s*(?:instead)?\s*$",
        "=main",
    ),
    _op(
        r"\bgive\s+(?:it|them)\s+" + _N + r"\s+(?:steps|treads|stairs|levels|layers|tiers|cubes)\b",
        "=main",
    ),
    _op(
        r"\b(?:move|shift|put|place|slide|keep|relocate|build|make|set)\s+(?:it|them|that|this|"
        r"(?:it|them)\s+all|all\s+of\s+(?:it|them)|everything)\s+(?:over\s+)?(?:to|towards|into|"
        r"at|on|in)\s+(?:the\s+)?"
        r"(left|right|front|back|middle|centre|center)(?:\s+(left|right))?\b",
        "region",
    ),
    _op(  # "redo it but on the right", "do it again on the left"
        r"\b(?:redo|rebuild|repeat|do)\s+(?:it|that|them)(?:\s+again)?\s*,?\s*(?:but\s+|only\s+)?"
        r"(?:to|towards|at|on|in)\s+(?:the\s+)?(left|right|front|back|middle|centre|center)(?:\s+(left|right))?\b",
        "region",
    ),
    _op(  # "relocate it 200 mm in +x", "shift it 2 cubes to the left"
        r"\b(?:move|shift|slide|relocate|push|nudge)\s+(?:it|them)\s+(?:by\s+)?(\d+(?:\.\d+)?|one|two|three|"
        r"four|five|a)\s*(mm|cm|m|cubes?)\s+(?:(?:in|along|towards?|to(?:\s+the)?)\s+(?:the\s+)?|further\s+)?"
        r"([+-]?\s*[xy]|left|right|front|back|forwards?|backwards?|away\s+from\s+the\s+robot|"
        r"(?:closer\s+to|towards?)\s+the\s+robot)\b",
        "offset",
    ),
    _op(
        r"\bfill\s+(?:it\s+|them\s+)?in(?:\s+the\s+(?:middle|centre|center|inside|hole|gap))?\b|"
        r"\bfill\s+(?:up\s+)?(?:the|its)\s+(?:middle|centre|center|inside|hole)\b",
        "fill",
    ),
    _op(
        r"\buntil\s+(?:it|they)\s+(?:is|are|stands?)\s+"
        + _N
        + r"\s+(?:cubes?\s+|levels?\s+|layers?\s+)?(?:high|tall)\b",
        "=",
    ),
    _op(r"\b(?:make\s+(?:it|them)\s+)?" + _N + r"\s+times\s+as\s+(?:tall|high)\b", "*"),
    # "make it more tall with 2 cube", "make it taller by 2": that many more
    _op(r"\bmake\s+" + _REF + r"\s+(?:more\s+(?:tall|high)|taller|higher)\s+(?:with|by)\s+" + _N
        + r"(?:\s+(?:more\s+)?(?:cubes?|levels?|layers?))?\b", "+"),
    _op(r"\bmake\s+" + _REF + r"\s+(?:more\s+long|longer)\s+(?:with|by)\s+" + _N
        + r"(?:\s+(?:more\s+)?cubes?)?\b", "+length"),
    # "a tower of 2 and a tower of 4. Make the smaller one as tall as the other."
    _op(
        r"\bmake\s+the\s+(smaller|shorter|lower|taller|bigger|higher|larger)\s+(?:one|tower|stack|"
        r"column)\s+(?:as\s+(?:tall|high)\s+as|the\s+same\s+height\s+as)\s+the\s+other(?:\s+one)?\b",
        "=other",
    ),
    # "towers of 3, 5 and 7 …; make the short one as tall as the middle one": one of several
    _op(
        r"\bmake\s+the\s+(" + _WHICH + r")\s+(?:one|tower|stack|column)\s+"
        r"(?:as\s+(?:tall|high)\s+as|the\s+same\s+height\s+as)\s+the\s+(" + _WHICH
        + r")(?:\s+(?:one|tower|stack|column))?\b",
        "=as",
    ),
    # "three towers of 2, 4 and 6, then take 3 off the tall one", "add 2 to the first one"
    _op(
        r"\b(?:take|knock|lift|remove)\s+" + _N + r"\s+(?:cubes?\s+|levels?\s+)?(?:off|from)\s+"
        r"(?:the\s+top\s+of\s+)?the\s+(" + _WHICH + r")\s+(?:one|tower|stack|column)\b",
        "-one",
    ),
    _op(
        r"\b(?:add|put|stack|place)\s+" + _N + r"\s+(?:more\s+)?(?:cubes?\s+|levels?\s+)?"
        r"(?:to|on|onto)\s+"
        r"(?:the\s+top\s+of\s+)?the\s+(" + _WHICH + r")\s+(?:one|tower|stack|column)\b",
        "+one",
    ),
    # "make the first one twice as tall", "make it twice as long": that size, doubled
    _op(r"\bmake\s+" + _REF + r"\s+(twice|double|triple)\s+as\s+(?:tall|high)\b", "*"),
    _op(r"\bmake\s+" + _REF + r"\s+(twice|double|triple)\s+as\s+long\b", "*length"),
    _op(r"\b(double|triple)\s+(?:its|their|the)\s+height\b", "*"),
    _op(r"\b(double|triple)\s+(?:it|them)\s+in\s+height\b", "*"),
    _op(
        r"\b(?:take|knock|lift|pull)\s+(?:away|off)\s+"
        + _N
        + r"(?:\s+(?:more\s+)?(?:cubes?|levels?|layers?)\b|(?:\s+more)?(?=\s*(?:[,.;!?]|$)))",
        "-",
    ),
    # "then remove the last cube" of a row or a tower; "take off the top" of a pyramid: one less
    _op(
        r"\b(?:remove|drop|(?:take|knock|pull)\s+(?:off|away))\s+the\s+(?:last|final)\s+(?:cube|block)\b"
        r"|\b(?:take|knock|lift|cut)\s+off\s+(?:its|the)\s+top\b(?!\s+(?:of|two|three|four|\d|row|level|"
        r"layer|course|tier|cube|block))",
        "-1",
    ),
    # "then take off both end cubes": a row two shorter
    _op(
        r"\b(?:(?:take|knock|pull|lift)\s+(?:off|away)|remove|drop)\s+(both|the\s+two|two)\s+end\s+"
        r"(?:cubes?|blocks?|ones?)\b",
        "-",
    ),
    # "row of 7. no make it 3 less", "make it two shorter": that many fewer
    _op(
        r"\bmake\s+" + _REF + r"\s+" + _N
        + r"\s+(?:cubes?\s+|levels?\s+|layers?\s+|courses?\s+|rows?\s+)?"
        r"(?:less|fewer|shorter|lower|smaller)\b",
        "-main",
    ),
    _op(
        r"\b(?:take|knock|lift)\s+off\s+(?:its|the)\s+top\s+(?:row|level|layer|course|tier)\b", "-1"
    ),
    _op(r"\b(?:cut|chop)\s+(?:it|them)\s+in\s+(half)\b|\bhalve\s+(?:it|them)\b", "/"),
    # "tower of 8. too much, half of that.": the size said before, halved or doubled
    _op(
        _CHANGE_LEAD
        + r"(?:(half)\s+(?:of\s+)?(?:that|it|this)|halve\s+(?:that|this))\b"
        + _NO_NOUN,
        "/",
    ),
    _op(_CHANGE_LEAD + r"(double|twice)\s+(?:that|it|this)\b" + _NO_NOUN, "*"),
    _op(
        r"\bmake\s+(?:it|them|the\s+\w+|all\s+of\s+them|them\s+all|each(?:\s+of\s+them)?|both)\s+"
        + _N
        + r"\s+(?:steps|cubes?\s+(?:high|tall)|levels?|layers?|high|tall|storeys?)\b"
        r"(?!\s+(?:less|fewer|shorter|lower|smaller|more|taller|higher|thicker|deeper)\b)",
        "=",
    ),
    _op(
        r"\b(?:take|knock|lift|remove)\s+"
        + _N
        + r"\s+(?:cubes?\s+|levels?\s+|(?:mm|cm|m)\s+)?(?:back\s+)?(?:off|away|from\s+the\s+top)\b",
        "-",
    ),
    # "a row of 8, then remove 3 cubes from one end", "take the two cubes off its left end"
    _op(
        r"\b(?:take|knock|remove|drop|pull|lose)\s+(?:the\s+)?"
        + _N
        + r"\s+(?:cubes?\s+|blocks?\s+|parts?\s+)?(?:off\s+|from\s+|away\s+from\s+)"
        r"(?:one|the|an|either|its)\s+(?:(?:left|right|front|back|far|near)\s+)?(?:end|side)\b",
        "-",
    ),
    # "then remove the top two cubes": a lower tower
    _op(
        r"\b(?:take|knock|lift|remove|pull)\s+(?:off\s+)?the\s+top\s+"
        + _N
        + r"(?:\s+(?:cubes?|blocks?|levels?|layers?)\b(?:\s+off)?"
        r"|(?![\d.])(?=\s*(?:[,;!?]|\.(?!\d)|$|\s+(?:please|thanks|thank\s+you|pls)\b)))",
        "-",
    ),
    # "then add 5 cm to its height"
    _op(
        r"\badd\s+(?:another\s+)?"
        + _N
        + r"(?:\s*(?:mm|cm|m)\b)?"
        + _UNIT
        + r"\s+to\s+(?:its|the|their)\s+height\b",
        "+",
    ),
    # "then shorten it by 10 cm", "lower it by two cubes"
    _op(
        r"\b(?:shorten|lower|reduce|cut|trim)\s+(?:it|them|the\s+(?:row|wall|tower|stack|column))\s+"
        r"(?:down\s+)?by\s+" + _N + _UNIT,
        "-",
    ),
    _op(
        r"\b(?:take|knock|lift|pull)\s+(?:off\s+)?(?:the\s+)?top\s+"
        + _N
        + r"?\s*(?:cubes?\s+|levels?\s+|(?:mm|cm|m)\s+)?off\b",
        "-",
    ),
    _op(
        r"\b(?:take|knock|lift|remove|unload|strip)\s+(?:off\s+)?the\s+top\s+(cube|one|level|layer)\b"
        r"(?:\s+off)?",
        "-1",
    ),
    _op(
        r"\b(?:take\s+away|take\s+off|remove|knock\s+off|leave\s+off|drop|break(?:\s+off)?|"
        r"knock\s+down|smash|destroy|delete|pull\s+off|mine)\s+the\s+(?:very\s+)?"
        r"(?:highest|top|topmost|uppermost|last)\s+(?:step|stair|level|layer|course|tier|row)\b",
        "-1",
    ),
    # "no wait, make the pen 5 by 5": the size of the structure named before, changed
    _op(
        r"\bmake\s+(?:the\s+\w+|that(?:\s+\w+)?|it)\s+(\d+\s*(?:x|by)\s*\d+)\b(?:\s+instead)?",
        "dims",
    ),
    # "actually make the pillars 4 instead": a bridge's or a table's own height
    _op(
        r"\b(?:make\s+(?:the|its|both)\s+(?:pillars|legs|posts|supports|columns)\s+(?:(?:taller|higher)\s*"
        r"[,(]?\s*)?|(?:raise|lower|bring|set|change)\s+(?:the|its|both)\s+(?:pillars|legs|posts|supports|"
        r"columns)\s+(?:(?:up|down)\s+)?to\s+)" + _N
        + r"(?:\s+(?:cubes?\s+)?(?:high|tall|each))?\)?(?:\s+(?:each|instead))?\s*$",
        "=pillars",
    ),
    # "then remove the middle 4 cubes": a solid floor with its middle taken out is a ring
    _op(
        r"\b(?:take\s+(?:out|away)|remove|pull\s+out|leave\s+out|lift\s+out|hollow\s+out|"
        r"take(?=\s+the\s+(?:middle|centre|center)\s+(?:cube|part)\s+(?:back\s+)?out))\s+"
        r"(?:all\s+)?(?:of\s+)?the\s+(?:middle|centre|center|inner|inside)\b(?:\s+(?:\d+|one|two|three|"
        r"four|nine)\s+)?(?:\s*(?:cubes?|parts?|ones|bit|square))?(?!\s+one\b)",
        "hollow",
    ),
    # "a wall 6 long 2 high, then remove one column from the end": one shorter
    _op(
        r"\b(?:remove|take\s+(?:off|away|out)|knock\s+(?:off|down)|drop|lose)\s+(?:the\s+)?(?:last|end|final|"
        r"a|one|an)\s+(?:end\s+)?column\b(?:\s+(?:from|at|on|off)\s+(?:the|one|its)\s+(?:end|side))?",
        "-1length",
    ),
    # "5 towers of 2 in a line, then take away the middle one": one structure fewer
    _op(
        r"\b" + DROP_VERBS + r"\s+the\s+(middle|first|second|last|tallest|highest|biggest|"
        r"shortest|lowest|smallest|left|right|front|back)"
        r"(?:[\s-]*hand)?\s+"
        r"(?:one|tower|stack|column|pillar|row|wall)\b"
        # "stair 3 + stair 5. remove the smaller.": of two, the one that size
        r"|\b" + DROP_VERBS + r"\s+the\s+(tallest|highest|biggest|largest|shortest|lowest|smallest|"
        r"taller|higher|bigger|larger|shorter|lower|smaller)(?:\s+(?:one|tower|stack|column|pillar|"
        r"staircase|stairs|pyramid|wall|row|block)\b|(?=\s*(?:[.,;!?]|$)))"
        r"|\b(?:take|knock|pull)\s+the\s+(middle|first|last|second|tallest|highest|biggest|shortest|"
        r"lowest|smallest|left|right|front|back)(?:[\s-]*hand)?\s+(?:one|tower|stack|column|pillar|"
        r"row|wall)\s+(?:down)\b"
        # "then take the one in the middle down", "remove the one in the middle"
        r"|\b(?:take\s+(?:out|away|down)|remove|leave\s+out|drop|lose|ditch)\s+the\s+(?:one|tower|stack|"
        r"column|pillar)\s+in\s+the\s+(middle)\b|\b(?:take|knock|pull)\s+the\s+(?:one|tower|stack|"
        r"column|pillar)\s+in\s+the\s+(middle)\s+(?:down|away|out|off)\b",
        "drop",
    ),
    # "two towers of 4, then remove one of them": one of several alike, left out
    _op(r"\b" + DROP_VERBS + r"\s+(?:just\s+)?(?:one|1)\s+of\s+(?:them|those|the\s+\w+s)\b",
        "drop_one"),
    # "then take away the one on the right": the one on that side
    _op(
        r"\b(?:take\s+(?:out|away|down)|remove|leave\s+out|drop|skip|lose|ditch|get\s+rid\s+of)\s+"
        r"the\s+(?:one|tower|stack|column|pillar|row|wall)\s+(?:on|at|to)\s+the\s+(left|right|front|back)"
        r"(?:[\s-]*hand)?(?:\s+(?:side|end))?\b",
        "drop",
    ),
    # "a tower on the left and a wall on the right. Actually forget the wall.": that one, gone
    _op(
        r"\b(?:forget|remove|drop|scrap|cancel|skip|lose|ditch|delete|get\s+rid\s+of|take\s+away|"
        r"leave\s+out|quit)\s+(?:about\s+)?the\s+("
        + shape_alternation(exclude=lx.AMBIGUOUS_SHAPES)
        + r")\b(?!\s*(?:'s|of)\b)",
        "drop_family",
    ),
    # "A tower of 4. No wait, scratch all of that": everything named before, gone
    _op(
        r"\b(?:scratch|cancel|forget|scrap|undo|drop|delete|clear)\s+(?:all\s+(?:of\s+)?(?:that|it|this|"
        r"the\s+above|them)|everything|the\s+whole\s+(?:thing|lot))\b",
        "undo_all",
    ),
    # "… Then a tower of 3 next to it. Undo the last one.", "scratch that": the step before, gone
    _op(
        r"\b(?:undo|scratch|cancel|forget|scrap|take\s+back|delete|remove|get\s+rid\s+of)\s+"
        r"(?:the\s+)?(?:last|latest|previous)\s+(?:one|step|thing|bit|structure|addition|"
        r"command|change|instruction)\b|\b(?:undo|scratch|scrap|bin|ditch|cancel|take\s+back)\s+"
        r"(?:that|it|this)"
        r"\b|^\W*(?:and\s+)?undo\W*$",
        "undo",
    ),
]


_SPANNING = ("bridge", "arch", "canopy")

REMOVAL = re.compile(
    r"^(?:\w+\s+){0,4}?(?:take|takes|pull|pulls|remove|removes|push|pushes|move|moves|shift|"
    r"leave\s+out|leave\s+off|omit|skip|drop|"
    r"slide|swap|delete|knock|cut|subtract|shove|merge|join\s+up)\b"
    r"(?!.*\b(?:tower|wall|row|pyramid|staircase|bridge|grid|block|ring|castle|arch)s?\b.*\b"
    r"(?:of|with)\s+\d)",
    re.IGNORECASE,
)


def modify(
    p: Phrase, before: list[Phrase], structures: list[StructureDraft], st: ReadState
) -> bool:
    """ "then add two more cubes to it", "make it two taller": change an earlier structure."""
    built = [q for q in before if q.spec is not None and q.count]
    if not built:
        return False
    for pattern, op in MODIFY:
        m = pattern.search(p.text)
        if not m:
            continue
        m = _in_parts(pattern, m, st)
        if op in ("+", "+1") and _set_beside(p, st.command):
            return False  # "then stack 2 more next to it": a new stack beside, not a taller one
        if re.search(r"\b(?:end|last|final)\s+(?:cubes?|blocks?)\b", m.group(0), re.I) and (
            structures[_last_index(built)].shape not in ("row", "tower")
        ):
            return False  # "both end cubes" / "the last cube" of a wall 2 high: which ones?
        if (
            op in ("+", "+1")
            and re.search(r"\b(?:cube|block|brick)\b", p.text, re.I)
            and not _LAYER_WORDS.search(p.text)
            and _set_on_top(p, st.command)
            and not _tower_last(built, structures)
        ):
            return False  # "a row of 5, then put one more cube on each end of it": on top of it
        rest = re.sub(  # "add 2 more to the row": the row named before, nothing more
            r"^\s*(?:(?:more|extra)\s+)?(?:cubes?\s+)?(?:to|on|onto|at)\s+(?:the\s+(?:other\s+)?end\s+of\s+)?"
            r"(?:the|its|that)\s+\w+\b", "", p.text[m.end() :], flags=re.IGNORECASE,
        )  # fmt: skip
        if m.group(0).lower().endswith(("middle", "centre", "center")):
            rest = re.sub(r"^\s*(?:tower|column|stack|pillar|post)\b", "", rest, flags=re.I)
        if _NAMES_MORE.search(rest):
            return False  # "pull the top 3 off and set them down as a tower": more than a change
        change = _CHANGES.get(op)
        for i, s in enumerate(structures):  # each its own object ("3 towers" are one three
            structures[i] = s.model_copy()  # times), to tell which ones a change takes away
        line = [structures[i] for i in _built_indices(built)]
        if op == "offset":
            note = _offset(m, built, structures, st.cell)
        elif change is not None:
            note = change(m, op, p, before, built, structures)
        else:
            note = _resize(m, op, p, before, built, structures, st.cell.cube[2])
        middle = r"\bthe\s+(?:middle|centre|center)\s+(?:one|tower|column|stack|pillar|post)\b"
        alone = [structures[i] for i in _built_indices(built)]
        if note is None and len(alone) == 1 and alone[0].shape == "grid" and re.search(
            r"\bmiddle\s+one\b", p.text, re.I
        ):
            # "a 3 by 3 square of cubes, then take out the middle one": its middle cube
            p.text = re.sub(r"\bmiddle\s+one\b", "middle cube", p.text, flags=re.I)
            return modify(p, before, structures, st)
        if note is None and re.search(middle, p.text, re.I):
            note = _middle_of_line(m, op, built, structures)
        sided = re.search(r"\bthe\s+(left|right|front|back)(?:[\s-]*hand)?\s+(?:one|tower|stack|"
                          r"column|pillar|post|row|wall)\b", p.text, re.I)  # fmt: skip
        unpicked = None
        if note is None and re.search(middle, p.text, re.I):
            # "three towers, then make the middle one 5": the middle one is not picked out
            unpicked = ("SDI cannot tell which structure will stand in the middle; say it by its "
                        "size or side")
        elif note is None and op == "drop" and len(alone) > 1:
            # "a staircase of 3 and one of 5. remove the smaller one": which one is not known
            # here (the words were dropped, silently)
            unpicked = "SDI cannot tell which structure that is; say it by its side or order"
        elif note is None and sided and len(alone) > 1:
            # "two towers of 3. make the front one 6": none of them is picked out by that side
            # (the side placed them all, and the 6 was lost, silently)
            unpicked = (f"no single structure stands on the {sided.group(1).lower()}; say which "
                        "one by its size or order")  # fmt: skip
        if unpicked is not None:
            st.material.append(m.group(0).strip())
            st.notes.append(f"ignored '{m.group(0).strip()}': {unpicked}")
            p.count = 0
            p.modified = True
            return True
        if note is None:
            return False
        st.notes.append(f"'{m.group(0).strip()}': {note}")
        if len(structures) < len(line):  # some were taken away: which places they left
            kept = {id(s) for s in structures}
            gone = [k for k, s in enumerate(line) if id(s) not in kept]
            st.taken += len(gone)
            st.taken_inner += sum(0 < k < len(line) - 1 for k in gone)
        p.count = 0
        p.modified = True  # the phrase is a change of that structure, not one of its own
        return True
    return False


_BESIDE = re.compile(
    r"\b(?:next\s+to|beside|behind|in\s+front\s+of|to\s+the\s+(?:left|right)\s+of|alongside|"
    r"on\s+its\s+(?:left|right))\b",
    re.IGNORECASE,
)

def _after(p: Phrase, command: str) -> str:
    """The words that follow the phrase in the command (30 characters of them, lower case)."""
    said = command.lower()
    at = said.find(p.text.lower())
    return said[at + len(p.text) : at + len(p.text) + 30] if at >= 0 else ""


def _set_beside(p: Phrase, command: str) -> bool:
    """The phrase sets what it names beside another ("stack 2 more next to it"): in its own
    words, or in the words that follow it in the command."""
    return bool(_BESIDE.search(p.text) or _BESIDE.match(_after(p, command).lstrip(" ,")))


def _set_on_top(p: Phrase, command: str) -> bool:
    """The words after the phrase stand what it adds on the structure ("… one more cube on top",
    "… on each end of it"), where a row or a slab does not grow longer."""
    return bool(_ON_TOP.match(_after(p, command)))


_ON_TOP = re.compile(r"\s*,?\s*on\s+(?:(?:the\s+)?top\b|(?:each|both|either)\s+end|(?:it|them)\b)")


def _tower_last(built: list[Phrase], structures: list[StructureDraft]) -> bool:
    return structures[_last_index(built)].shape in ("tower", "staircase", "pyramid", "castle")


_NAMES_MORE = re.compile(
    r"\b(?:" + shape_alternation(exclude=lx.AMBIGUOUS_SHAPES | {"table", "tables"}) + r")\b",
    re.IGNORECASE,
)


def _in_parts(pattern: re.Pattern[str], m: re.Match[str], st: ReadState) -> re.Match[str]:
    """ "build it up to 101.6 mm": a length where a change counts parts, as whole parts."""
    if not m.lastindex or not m.group(1):
        return m
    unit = re.match(r"\s*(mm|cm|m)\b", m.string[m.end(1) :])
    try:
        metres = float(m.group(1)) * lx.UNITS_M[unit.group(1)] if unit else None
    except ValueError:
        return m
    if unit is None or metres is None:
        return m
    part = st.cell.cube[2]
    parts = max(1, round(metres / part))
    st.notes.append(f"read '{m.group(1)} {unit.group(1)}' as {parts} parts ({parts * part:g} m)")
    text = m.string[: m.start(1)] + str(parts) + m.string[m.end(1) + unit.end() :]
    return pattern.search(text) or m


Change = Callable[
    [re.Match[str], str, Phrase, list[Phrase], list[Phrase], list[StructureDraft]], str | None
]
"""One kind of change: it edits `structures` in place and says what changed, or None when it
does not apply to the structures named (the phrase is then read as it stands)."""


def _last_index(built: list[Phrase]) -> int:
    """The index of the structure named last."""
    return built[-1].first + built[-1].count - 1


def _reshaped(s: StructureDraft, shape: str, height: int | None) -> StructureDraft:
    """`s` as another family of the same footprint and place (a ring filled in, a floor with
    its middle taken out)."""
    return StructureDraft(
        shape=shape, length=s.length, width=s.width or s.length, height=height,
        length_m=s.length_m, width_m=s.width_m, at_x=s.at_x, at_y=s.at_y, region=s.region,
        part=s.part,
    )  # fmt: skip


def _fill(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
          structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "then fill in the middle": a ring becomes solid."""
    index = _last_index(built)
    ring = structures[index]
    if ring.shape != "enclosure":
        return None
    solid = "block" if (ring.height or 1) > 1 else "grid"
    structures[index] = _reshaped(ring, solid, ring.height if solid == "block" else None)
    return f"the ring filled in, a solid {solid}"


def _region(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
            structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "move it to the left": the structure named last goes there — on that side only: "at
    the front … put it on the left" is the front left."""
    place = " ".join(g.lower() for g in m.groups() if g)
    place = {"middle": "centre", "center": "centre"}.get(place, place)
    index = _last_index(built)
    was = structures[index].region
    kept = [w for w in (was or "").split() if w in _ACROSS.get(place, ())]
    instead = re.match(r"\s*,?\s*(?:instead\s+of|rather\s+than|and\s+not|not)\s+(?:on\s+|at\s+|"
                       r"in\s+)?(?:the\s+)?(left|right|front|back)\b", p.text[m.end() :], re.I)
    if instead:  # "put it at the back instead of the left": the side said before, replaced
        kept = [w for w in kept if w != instead.group(1).lower()]
    if kept:
        place = f"{place} {kept[0]}" if place in ("front", "back") else f"{kept[0]} {place}"
    structures[index] = structures[index].model_copy(
        update={"region": place, "at_x": None, "at_y": None}
    )
    return f"the {structures[index].shape} goes {place}" + (f" (was {was})" if was else "")


_ACROSS = {"left": ("front", "back"), "right": ("front", "back"), "front": ("left", "right"),
           "back": ("left", "right")}  # fmt: skip
"""The words of a region a move to one side keeps (a move left keeps the front)."""

_DIRECTIONS = {
    "x": ("at_x", 1),  # "move it 10 cm in x": along it, the positive way
    "y": ("at_y", 1),
    "+x": ("at_x", 1),
    "back": ("at_x", 1),
    "-x": ("at_x", -1),
    "front": ("at_x", -1),
    "+y": ("at_y", 1),
    "left": ("at_y", 1),
    "-y": ("at_y", -1),
    "right": ("at_y", -1),
    "forward": ("at_x", -1),  # "move it 10 cm forward", towards the robot
    "forwards": ("at_x", -1),
    "backward": ("at_x", 1),
    "backwards": ("at_x", 1),
    "awayfromtherobot": ("at_x", 1),
    "closertotherobot": ("at_x", -1),
    "towardstherobot": ("at_x", -1),
    "towardtherobot": ("at_x", -1),
}


def _offset(m: re.Match[str], built: list[Phrase], structures: list[StructureDraft],
            cell: CellConfig) -> str | None:  # fmt: skip
    """ "relocate it 200 mm in +x": the structure named last moves that far, from where it was
    said to stand — its coordinates, or the centre of its region (of the table, when it is the
    only structure and was not placed); one placed by a relation has no position to move from."""
    part_m = cell.cube[0]
    index = _last_index(built)
    s = structures[index]
    key, sign = _DIRECTIONS[re.sub(r"\s+", "", m.group(3).lower())]
    regions = cell.design.regions
    placed = s.at_x is not None or s.at_y is not None
    if not placed and (s.region in regions or (s.region is None and len(structures) == 1)):
        x, y = regions.get(s.region or "centre", cell.design.anchor)
        s = s.model_copy(update={"at_x": x, "at_y": y, "region": None})
    if getattr(s, key) is None:
        return None
    amount = float({"a": "1"}.get(m.group(1).lower()) or words_to_numbers([m.group(1).lower()])[0])
    unit = m.group(2).lower()
    metres = amount * (part_m if unit.startswith("cube") else lx.UNITS_M[unit])
    structures[index] = s.model_copy(update={key: round(getattr(s, key) + sign * metres, 6)})
    return f"the {s.shape} moves {metres:g} m to {key[-1]} = {getattr(structures[index], key):g} m"


_TWO_SIDED = frozenset({"grid", "block", "enclosure", "castle", "l_shape", "t_shape", "u_shape"})


def _dims(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
          structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "make the pen 5 by 5": the last structure named that way."""
    a, b = (int(v) for v in re.split(r"\s*(?:x|by)\s*", m.group(1).lower()))
    noun = re.search(r"make\s+(?:the|that)\s+(\w+)", m.group(0), re.I)
    family = lx.SHAPE_WORDS.get(noun.group(1).lower()) if noun else None
    found = [i for i, x in enumerate(structures) if x.shape == family]
    if noun is None:  # "make it 4x4": the structure named last, if it has two sides
        last_index = _last_index(built)
        found = [last_index] if structures[last_index].shape in _TWO_SIDED else []
    if not found:
        return None
    last = structures[found[-1]]
    sized = {"length": a, "width": b, "length_m": None, "width_m": None}
    structures[found[-1]] = last.model_copy(update=sized)
    was = f"{last.length} by {last.width}" if last.length else "its size"
    return f"the {last.shape} is now {a} by {b} (was {was})"


def _pillars(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
             structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "actually make the pillars 4 instead": a bridge's or a table's own height."""
    spanning = [i for i, x in enumerate(structures) if x.shape in _SPANNING]
    value = words_to_numbers([m.group(1).lower()])[0]
    if not spanning or not value.isdigit() or int(value) < 1:
        return None
    last = structures[spanning[-1]]
    structures[spanning[-1]] = last.model_copy(update={"height": int(value), "height_m": None})
    return f"the {last.shape}'s pillars are now {value} high"


def _turrets(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
             structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "then make the towers 4 high": a castle's corner towers, that high overall."""
    castles = [i for i, x in enumerate(structures) if x.shape == "castle"]
    value = words_to_numbers([m.group(1).lower()])[0]
    if not castles or not value.isdigit():
        return None
    last = structures[castles[-1]]
    walls = last.height or 1
    if int(value) <= walls:
        return None  # towers no higher than the walls: no towers
    structures[castles[-1]] = last.model_copy(update={"count": int(value) - walls})
    return f"the castle's corner towers are now {value} high"


def _hollow(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
            structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "then remove the middle 4 cubes": a solid floor or block 3 across or more without its
    middle is a ring."""
    index = _last_index(built)
    floor = structures[index]
    if (
        floor.shape not in ("grid", "block")
        or min(floor.length or 3, floor.width or floor.length or 3) < 3
    ):
        return None
    height = floor.height if floor.shape == "block" else None
    structures[index] = _reshaped(floor, "enclosure", height)
    return f"the {floor.shape} without its middle, a ring"


def _drop(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
          structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "5 towers, then take away the middle one": one of several named together left out;
    "three towers of 2, 3 and 4, then remove the tallest one": the one of a kind by height."""
    which = next(g for g in m.groups() if g).lower()
    target = built[-1]
    if which == "last" and target.count == 1:
        return _undo(m, op, p, before, built, structures)  # "remove the last one": the last step
    every = _built_indices(built)
    if which in ("first", "second") and target.count < 2 and len(every) > 1:
        # "a tower of 4 and a tower of 2, then remove the second one": counted over all built
        index = every[0 if which == "first" else 1]
    elif which in ("first", "second", "last", "middle"):
        if target.count < 2 or (which == "middle" and target.count % 2 == 0):
            return None  # one structure, or no single middle one
        at = {"first": 0, "second": 1, "last": target.count - 1, "middle": target.count // 2}[which]
        index = target.first + at
    elif which in ("left", "right", "front", "back"):
        found_at = _by_side(which, built, structures, before)
        if found_at is None:
            return None
        index = found_at
    else:
        towers = _tower_heights(built, structures)
        if None in towers.values() or (which.endswith("er") and len(towers) != 2):
            return None  # "the smaller" of more than two: which is not said
        found_at = _which_tower(which, towers)
        if found_at is None:
            return None  # no single one: the command does not say which
        index = found_at
    every = _built_indices(built)
    inner = which not in ("middle", "second") and 0 < every.index(index) < len(every) - 1
    gone = _take_out(index, before, built, structures)
    left = sum(q.count for q in built)
    # "take away the tallest" of three, standing in the middle: the others keep their places
    # (`spacing`)
    size = f" (the {gone.shape} {gone.height} high taken away{_INNER if inner else ''})" if (
        gone.height
    ) else ""
    side = f", the one on the {which}" if which in ("left", "right", "front", "back") else ""
    return f"{left} left of the {left + 1}{size}{side}"


_INNER = ", from the middle of the line"
"""Said of a structure taken away from between others (`spacing` keeps their places)."""


def _take_out(index: int, before: list[Phrase], built: list[Phrase],
              structures: list[StructureDraft]) -> StructureDraft:  # fmt: skip
    """Structure `index` taken out of the reading; a phrase left with none is undone (its
    relations go with it)."""
    gone = structures.pop(index)
    owner = next(q for q in built if q.first <= index < q.first + q.count)
    for q in before:
        if q.count and q.first > index:
            q.first -= 1
    owner.count -= 1
    if owner.count == 0:
        owner.undone = True
    return gone


def _built_indices(built: list[Phrase]) -> list[int]:
    """The index of every structure built so far, in the order named."""
    return [q.first + k for q in built for k in range(q.count)]


def _tower_heights(built: list[Phrase], structures: list[StructureDraft]) -> dict[int, int | None]:
    """The towers built so far, by index, with their heights (None: not said)."""
    every = _built_indices(built)
    return {i: structures[i].height for i in every if structures[i].shape == "tower"}


def _extreme_tower(heights: Mapping[int, int | None], low: bool) -> int | None:
    """The one tower of `heights` (two or more, all said) that is the tallest, or with `low`
    the shortest; None when there are fewer than two or no single one."""
    said = {i: h for i, h in heights.items() if h is not None}
    if len(said) < 2 or len(said) != len(heights):
        return None
    best = (min if low else max)(said.values())
    found = [i for i, h in said.items() if h == best]
    return found[0] if len(found) == 1 else None


def _by_side(
    side: str, built: list[Phrase], structures: list[StructureDraft], before: list[Phrase]
) -> int | None:
    """The one structure built so far that stands on `side`: the only one placed in a region
    with that side, or, of structures placed by SDI side by side (listed from right to left,
    or from left to right when the command says so), the one at that end. None when no single
    one is meant."""
    every = _built_indices(built)
    placed = [i for i in every if side in (structures[i].region or "").split()]
    if len(placed) == 1:
        return placed[0]
    free = all(
        structures[i].region is None and structures[i].at_x is None and structures[i].at_y is None
        for i in every
    )
    if placed or not free or len(every) < 2:
        return None
    said = " ".join(q.text for q in before)
    if side in ("front", "back"):
        # "three towers in a line front to back": the first named stands in front (the last, of
        # a line said back to front)
        if not re.search(r"\b(?:front\s+to\s+(?:the\s+)?back|back\s+to\s+(?:the\s+)?front|one\s+"
                         r"behind\s+(?:the\s+other|another)|behind\s+each\s+other)\b", said, re.I):
            return None
        if re.search(r"\bback\s+to\s+(?:the\s+)?front\b", said, re.I):
            every = every[::-1]
        return every[0] if side == "front" else every[-1]
    if re.search(r"\bleft\s+to\s+(?:the\s+)?right\b", said, re.I):
        every = every[::-1]  # "three towers, left to right": the first named is the left one
    on = next((q.beside for q in built if q.count and q.first <= every[-1] < q.first + q.count),
              None)  # fmt: skip
    if on in ("left", "right") and len(every) == 2:
        # "a tower of 2, and a tower of 5 one cube to its right": the second stands on that side
        # (the first was taken for the right one, silently)
        return every[-1] if side == on else every[0]
    return every[0] if side == "right" else every[-1]


def _drop_family(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
                 structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "… and a wall on the right. Actually forget the wall.": the one structure of that family
    named before, taken back (of several, the command does not say which: not changed)."""
    family = lx.SHAPE_WORDS.get(m.group(1).lower())
    indices = _built_indices(built)
    found = [i for i in indices if structures[i].shape == family]
    if len(found) != 1:
        return None
    index = found[0]
    gone = _take_out(index, before, built, structures)
    said = ", ".join(f"{k} {v:g}" for k, v in _sizes(gone).items())
    where = f", on the {gone.region}" if gone.region else ""
    return f"the {gone.shape} taken back ({said or 'its default size'}{where})"


def _sizes(s: StructureDraft) -> dict[str, float]:
    """The sizes a structure was given (to say what was taken back)."""
    keys = {"length", "width", "height", "steps", "count", "length_m", "width_m", "height_m"}
    return {k: v for k, v in s.model_dump(include=keys).items() if isinstance(v, int | float)}


def _drop_one(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
              structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "two towers of 4, then remove one of them": one fewer of structures named together
    alike (which one does not matter); of structures that differ, which is not said."""
    target = built[-1]
    alike = structures[target.first : target.first + target.count]
    if target.count < 2 or any(s != alike[0] for s in alike):
        return None
    _take_out(target.first + target.count - 1, before, built, structures)
    return f"{target.count} left of the {target.count + 1}"


def _as_the_other(m: re.Match[str], op: str, p: Phrase, before: list[Phrase],
                  built: list[Phrase], structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "Make the smaller one as tall as the other": of two towers, one as high as the other."""
    towers = _tower_heights(built, structures)
    low = m.group(1).lower() in ("smaller", "shorter", "lower")
    found_at = _extreme_tower(towers, low) if len(towers) == 2 else None
    if found_at is None:
        return None
    other = next(i for i in towers if i != found_at)
    was, now = structures[found_at].height, structures[other].height
    structures[found_at] = structures[found_at].model_copy(update={"height": now})
    return f"the {m.group(1).lower()} tower now has height {now} (was {was}), as the other"


def _as_one(m: re.Match[str], op: str, p: Phrase, before: list[Phrase],
            built: list[Phrase], structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "towers of 3, 5 and 7; make the short one as tall as the middle one": one tower of
    several (picked by its size, or by the order they were named in) as high as another."""
    towers = _tower_heights(built, structures)
    pick, like = (_which_tower(m.group(k).lower(), towers) for k in (1, 2))
    if pick is None or like is None or pick == like or structures[like].height is None:
        return None
    was, now = structures[pick].height, structures[like].height
    structures[pick] = structures[pick].model_copy(update={"height": now})
    return f"the {m.group(1).lower()} tower now has height {now} (was {was})"


_APPLY: dict[str, Callable[[int, int], int]] = {
    "+": lambda v, n: v + n, "-": lambda v, n: v - n, "=": lambda v, n: n,
    "*": lambda v, n: v * n, "/": lambda v, n: v // n,
}  # fmt: skip
"""A size `v` changed by a number `n`: more, fewer, set to it, times, divided."""


def _on_one(m: re.Match[str], op: str, p: Phrase, before: list[Phrase],
            built: list[Phrase], structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "three towers of 2, 4 and 6, then take 3 off the tall one": that one tower changed."""
    towers = _tower_heights(built, structures)
    pick = _which_tower(m.group(2).lower(), towers)
    n = words_to_numbers([m.group(1).lower()])[0]
    if pick is None or not n.isdigit() or structures[pick].height is None:
        return None
    was = structures[pick].height or 0
    now = _APPLY["-" if op == "-one" else "+"](was, int(n))
    if now < 1:
        return None
    structures[pick] = structures[pick].model_copy(update={"height": now})
    return f"the {m.group(2).lower()} tower now has height {now} (was {was})"


def _unsaid(shape: str, key: str) -> int:
    """A size the command did not say: the generators' own (`sdi.design.shapes`), a wall 2 high
    and 4 long, a slab 1 high, anything else 3."""
    return {"grid": 1, "row": 1, "enclosure": 1, "wall": 2 if key == "height" else 4}.get(shape, 3)


def _middle_two(m: re.Match[str], op: str, p: Phrase, before: list[Phrase],
                built: list[Phrase], structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "four towers of 2 in a row, then make the two in the middle 5 high" (or "remove the
    middle two"): of an even number (four or more) of towers or walls named in one line with no
    place of their own, the two in the middle of the order they stand in, that high (or gone)."""
    every = _built_indices(built)
    shapes = {structures[i].shape for i in every}
    n = words_to_numbers([m.group(1).lower()])[0] if op == "middle2" else "1"
    if (
        len(every) < 4
        or len(every) % 2
        or len(shapes) != 1
        or not shapes <= {"tower", "wall"}
        or any(structures[i].region for i in every)
        or not n.isdigit()
        or int(n) < 1
    ):
        return None
    pair = every[len(every) // 2 - 1 : len(every) // 2 + 1]
    if op == "drop2":  # "remove the middle two"
        for i in reversed(pair):
            _take_out(i, before, built, structures)
        return f"{len(every) - 2} left of the {len(every)} (the two in the middle taken away)"
    were = [structures[i].height or _unsaid(structures[i].shape, "height") for i in pair]
    for i in pair:
        structures[i] = structures[i].model_copy(update={"height": int(n)})
    return (f"the two middle {structures[pair[0]].shape}s of the line now have height {n} (were "
            f"{', '.join(str(h) for h in were)})")  # fmt: skip


def _middle_of_line(m: re.Match[str], op: str, built: list[Phrase],
                    structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "3 columns of height 3 in a line, then add 2 cubes to the middle column": of an odd
    number of towers (and nothing else) named in one line with no place of their own, the one
    in the middle of the order they stand in (the order named) grows or shrinks."""
    every = _built_indices(built)
    towers = _tower_heights(built, structures)
    if len(towers) != len(every) or any(structures[i].region for i in towers):
        return None
    pick = _which_tower("middle", towers)
    said = m.group(1) if m.groups() and m.group(1) else "1"
    said = "1" if said.lower() in ("a", "an", "another", "one more") else said
    n = 1 if op in ("+1", "-1") else words_to_numbers([said.lower()])[0]
    if pick is None or op not in ("+", "-", "+1", "-1", "=", "=main") or not str(n).isdigit():
        return None
    was = structures[pick].height
    if was is None:
        return None
    now = _APPLY[{"+1": "+", "-1": "-", "=main": "="}.get(op, op)](was, int(n))
    if now < 1:
        return None
    structures[pick] = structures[pick].model_copy(update={"height": now})
    return f"the middle tower of the line now has height {now} (was {was})"


def _which_tower(word: str, towers: Mapping[int, int | None]) -> int | None:
    """The one tower of several `word` picks: by size ("the short one"), by the order named
    ("the first one", "the last one"), or the middle one of an odd number named together."""
    stem = re.sub(r"(?:er|est)$", "", word)
    if stem in ("short", "small", "low"):
        return _extreme_tower(towers, low=True)
    if stem in ("tall", "big", "bigg", "high", "larg"):
        return _extreme_tower(towers, low=False)
    order = sorted(towers)
    if word == "middle":
        return order[len(order) // 2] if len(order) % 2 and len(order) > 1 else None
    at = {"first": 0, "second": 1, "third": 2, "last": -1}[word]
    return order[at] if -len(order) <= at < len(order) else None


def _undo(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
          structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "Then a wall behind them. Undo the last one.": the structures of the step before are
    taken back (if nothing is named after, nothing is left to build: the reader refuses)."""
    target = built[-1]
    gone = structures[target.first : target.first + target.count]
    del structures[target.first : target.first + target.count]
    for q in before:
        if q.count and q.first > target.first:
            q.first -= target.count
    target.count, target.undone = 0, True
    said = [f"the {s.shape}" + "".join(f" {k} {v:g}" for k, v in _sizes(s).items()) for s in gone]
    return f"the step before taken back: {' and '.join(said)} not built"


def _undo_all(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
              structures: list[StructureDraft]) -> str | None:  # fmt: skip
    """ "scratch all of that": every structure named before is taken back (with nothing named
    after, nothing is left to build: the reader refuses)."""
    said = [f"the {s.shape}" + "".join(f" {k} {v:g}" for k, v in _sizes(s).items())
            for s in structures]  # fmt: skip
    structures.clear()
    for q in built:
        q.count, q.undone = 0, True
    return f"everything before taken back: {' and '.join(said)} not built"


def _family_named(text: str) -> str | None:
    """The family a change names its structure by ("make the tower one taller")."""
    m = re.search(r"\b(?:make|raise|lower|extend|shorten|lengthen|grow|heighten)\s+the\s+(\w+)\b",
                  text, re.IGNORECASE)  # fmt: skip
    return lx.SHAPE_WORDS.get(m.group(1).lower()) if m else None


def _resize(m: re.Match[str], op: str, p: Phrase, before: list[Phrase], built: list[Phrase],
            structures: list[StructureDraft], part_m: float) -> str | None:  # fmt: skip
    """ "add two more cubes", "make it 4", "halve it": a size of a structure named before
    (the last, or the one an ordinal picks); a size said in metres counts in parts of
    `part_m`."""
    key = None
    main = op.endswith("main")  # "make it 4", "make it 3 less": the size it was given, or its main
    if main:
        op = op[0]
        said = re.search(r"\b(high|tall|long)\s*[.!)]?\s*$", m.group(0), re.I)
        if said:  # "raise it to two high": its height, whatever its main size is
            key = "length" if said.group(1).lower() == "long" else "height"
    elif op.endswith("length"):  # "make it 5 long", "remove one column from the end"
        op, key = op.removesuffix("length"), "length"
    elif op == "+row":  # "add a row along the back": a slab's rows, not a course on top
        op, last_ = "+1", structures[_last_index(built)]
        if last_.shape in ("wall", "row") and not m.group(1):
            key = "height"  # "a wall of 5, then add another row": a course on it
        elif last_.shape != "grid" or last_.length is None or last_.width is None:
            return None
        side = (m.group(1) or "back").lower()
        key = key or ("length" if side in ("left", "right") else "width")
    elif op == "=side":  # "make it 3 wide (instead of 2)": the side it was, else across
        op, last_ = "=", structures[_last_index(built)]
        deep = re.search(r"\b(?:deep|thick)\b", m.group(0), re.I)
        if last_.shape in ("row", "wall") and deep and not m.group(2):
            key = "width"  # "a row of 5, now make it two rows deep": a 5 by 2 slab
        elif last_.shape not in ("grid", "block"):
            return None
        was = m.group(2) and int(words_to_numbers([m.group(2).lower()])[0])
        sides = {k: getattr(last_, k) for k in ("length", "width")}
        if was:
            matching = [k for k, v in sides.items() if v == was]
            if len(matching) != 1:
                return None
            key = matching[0]
        elif last_.shape in ("grid", "block"):
            key = "width" if deep else "length"
    if op in ("+1", "-1"):
        n, op = 1, op[0]
    else:
        word = re.sub(r"\s+", " ", (m.group(1) or ("2" if op == "/" else "1")).lower())
        word = {"another": "1", "one more": "1", "a": "1", "an": "1", "double": "2", "both": "2",
                "the two": "2",
                "triple": "3", "half": "2", "twice": "2"}.get(word, word)  # fmt: skip
        value = words_to_numbers([word])[0]
        if not value.isdigit():
            return None
        n = int(value)
    target = built[-1]
    index = _last_index(built)
    ordinal = re.search(r"\bthe\s+(first|second|third|fourth|last)\b", p.text, re.I)
    sided = re.search(
        r"\bthe\s+(?:(left|right|front|back)(?:[\s-]*hand)?\s+(?:one|tower|stack|column|pillar|row|wall)|"
        r"(?:one|tower|stack|column|pillar|row|wall)\s+(?:on|at|to)\s+the\s+(left|right|front|back))\b",
        p.text,
        re.I,
    )
    side = (sided.group(1) or sided.group(2)).lower() if sided else None
    on_side = _by_side(side, built, structures, before) if side else None
    if sided and on_side is None:
        return None  # "take 2 off the left one" with no single one on the left: said, unused
    extreme = re.search(
        r"\bthe\s+(taller|tallest|higher|highest|bigger|biggest|larger|largest|shorter|shortest|lower|"
        r"lowest|smaller|smallest)\s+(?:one|tower|stack|column|pillar)\b",
        p.text,
        re.I,
    ) or re.search(  # "make the tall one 3": said in the change itself
        r"\bthe\s+(tall|short|big|small)\s+(?:one|tower|stack|column|pillar)\b", m.group(0), re.I
    )
    named = re.search(
        r"\b(?:off|from|to|on)\s+the\s+(\w+)\s+(?:one|tower|stack|column|pillar)\b", p.text, re.I
    )
    if re.search(r"\bthe\s+(?:middle|centre|center)\s+(?:one|tower|stack|column|pillar|row|wall)\b",
                 p.text, re.I):  # fmt: skip
        return None  # "make the middle one taller": which stands in the middle is not known here
    if on_side is not None:
        index = on_side
    elif extreme:
        sized = {i: h for i, h in _tower_heights(built, structures).items() if h}
        low = extreme.group(1).lower().startswith(("short", "low", "small"))
        found_at = _extreme_tower(sized, low)
        if found_at is None:
            return None  # "the taller one" of towers alike: which is not said
        index = found_at
    elif not ordinal and (
        (named and named.group(1).lower() not in ("same", "other", "new", "top"))
        or re.search(
            r"\b(?:off|from)\s+(?:of\s+)?the\s+(?!(?:top|end|ends|side|far|near|left|right|front|back)\b)"
            r"(?!(?:\w+\s+)?(?:end|side)\b)\w+",
            p.text,
            re.I,
        )
    ):
        return None  # "take 2 cubes off the red one", "off the one on my left": not picked out
    elif ordinal and target.count > 1:
        pick = {"first": 0, "second": 1, "third": 2, "fourth": 3, "last": target.count - 1}
        if pick[ordinal.group(1).lower()] >= target.count:
            return None  # "the third one" of two: no such structure
        index = target.first + pick[ordinal.group(1).lower()]
    elif ordinal:  # one structure per phrase: the ordinal counts every structure built
        every = _built_indices(built)
        pick = {"first": 0, "second": 1, "third": 2, "fourth": 3, "last": len(every) - 1}
        at = pick[ordinal.group(1).lower()]
        if at >= len(every):
            return None
        index = every[at]
    family = _family_named(p.text)
    if family and on_side is None and not extreme and not ordinal:
        # "a tower of 3 and a wall of 4. Make the tower one taller": the tower, not the last one
        of_family = [i for i in _built_indices(built) if structures[i].shape == family]
        if structures[index].shape != family and of_family:
            if len(of_family) > 1:
                return None  # which of several is not said
            index = of_family[0]
    last = structures[index]
    if main:
        key = key or _main_slot(last) or _slot_said(m.group(0), last)
        if key is None:
            return None
    lengthwise = re.search(r"\b(?:longer|lengthen|extend|shorter|shorten)\b", m.group(0), re.I)
    if (
        lengthwise
        and last.shape in ("wall", "row")
        and last.count
        and last.length is None
        and (last.shape == "row" or (last.count <= 4 and last.height is None))
    ):
        # "a wall of 4, then make the wall longer by two": 4 long, 6 long now (its 4 were read as
        # all its parts: 3 long, 2 high)
        last = last.model_copy(update={"length": last.count, "count": None})
        structures[index] = last
        key = "length"
    if op in ("-", "-1") and last.shape == "pyramid" and re.search(r"\btop\b", p.text, re.I):
        # its top taken off a pyramid is a cut-off pyramid on the same base, not a smaller one
        base = last.length or last.width or last.height
        levels = last.height or base
        if base is None or levels is None or last.length_m or last.height_m or levels - n < 1:
            return None
        structures[index] = last.model_copy(update={"length": base, "height": levels - n})
        return f"the pyramid now has {levels - n} levels on its base of {base} (was {levels})"
    if (
        op == "+"
        and last.shape in ("grid", "row", "enclosure", "wall", "block")
        and re.search(
            r"\bon\s+(?:the\s+)?(?:middle|centre|center|one|a|each|the\s+\w+\s+end)\b", p.text, re.I
        )
    ):
        return None  # "stack 2 more on the middle one": a column on it, not a layer more
    top_parts = (last.length or 1) * (last.width or 1) if last.shape in ("grid", "block") else 1
    if (
        op == "+"
        and top_parts > 1
        and re.search(r"\b(?:cubes?|blocks?|bricks?|parts?)\b", p.text, re.I)
        and not _LAYER_WORDS.search(p.text)
    ):
        if n % top_parts:
            return None  # "a 2x2 slab, then one more cube on it": a cube on it, not a layer
        n //= top_parts  # "a 2x2 block, add 4 more cubes on top": one layer more
    if last.shape == "grid" and op == "-" and re.search(r"\brow\b", m.group(0), re.I):
        key = "width"  # "4 rows of 3. Then remove the last row.": one row fewer
    vertical = re.search(
        r"\b(?:on\s+top|higher|taller|lower|up|layers?|levels?|high|tall|courses?|stack\w*|pile\w*|"
        r"on\s+(?:it|them)|onto|atop)\b",
        p.text,
        re.I,
    )
    if (
        key is None
        and last.shape in ("row", "wall")
        and op in ("+", "-")
        and (
            re.search(r"\b(?:extend|lengthen|longer|shorten|shorter|ends?)\b", p.text, re.I)
            or last.shape == "row"  # "add one more cube to it": a row one longer, not a wall
        )
        and not vertical
    ):
        key = "length"  # "a row of 5, then extend it by two more cubes at the same end"
        high = last.height or 1
        in_cubes = re.search(r"\b(?:cubes?|blocks?|parts?)\b", p.text)
        if last.shape == "wall" and high > 1 and in_cubes:
            if n % high:
                return None  # "take 3 cubes off one end" of a wall 2 high: no whole columns
            n //= high  # cubes off an end of a wall 2 high: whole columns
    key = key or ("steps" if last.shape == "staircase" else "height")
    metres = getattr(last, f"{key}_m", None)  # "stack it up to 10 inches": in whole parts
    said = getattr(last, key) or (round(metres / part_m) if metres else None)
    now = said or _unsaid(last.shape, key)
    if op == "/" and now % n:
        return None
    new = _APPLY[op](now, n)
    if new < 1:
        return None
    shape = last.shape
    if key == "height" and new > 1 and shape in ("grid", "row"):
        shape = "block" if shape == "grid" else "wall"
    update: dict[str, object] = {key: new, "shape": shape}
    if metres:
        update[f"{key}_m"] = None
    structures[index] = last.model_copy(update=update)
    in_m = f", {metres:g} m, {metres * 100:g} cm" if metres else ""  # "30 cm tower": said in cm
    was = f" (was {now}{in_m})" if said else ""
    alike = [i for i in _built_indices(built) if structures[i].shape == last.shape]
    if _EVERY.search(p.text) and len(alike) > 1 and index == _last_index(built):
        # "three towers of 2, then add one more cube to each": all of them, each from its own
        # size ("a tower of 2 and a tower of 4, … to each of them": 3 and 5)
        were: list[int] = [
            (getattr(structures[i], key) if i != index else now) or _unsaid(last.shape, key)
            for i in alike
        ]
        got = [_APPLY[op](v, n) for v in were]
        if min(got) < 1 or (op == "/" and any(v % n for v in were)):
            structures[index] = last
            return None
        for i, grown in zip(alike, got, strict=True):
            structures[i] = structures[i].model_copy(update={**update, key: grown})
        if len(set(got)) == 1:
            if len(set(were)) > 1:  # "three towers of 2, 3 and 4, then make them all 5 high"
                return (f"each {last.shape} now has {key} {new} (were "
                        f"{', '.join(map(str, were))})")  # fmt: skip
            return f"each {last.shape} now has {key} {new}{was}"
        return (f"the {last.shape}s now have {key} {', '.join(map(str, got))} (were "
                f"{', '.join(map(str, were))})")  # fmt: skip
    prep = "at" if side in ("front", "back") else "on"
    which = f" {prep} the {side}" if on_side is not None else ""
    return f"the {last.shape}{which} now has {key} {new}{was}"


_LAYER_WORDS = re.compile(
    r"\b(?:layers?|levels?|courses?|tiers?|rows?|high|tall|taller|higher|storeys?|stories|"
    r"floors?)\b",
    re.IGNORECASE,
)


_EVERY = re.compile(
    r"\b(?:to\s+each|each\s+of\s+them|all\s+of\s+them|them\s+all|every\s+one|each\s+one|"
    r"both(?:\s+of\s+them)?|on\s+each|of\s+each\b|all\s+\w+s\b|"
    r"(?:make|raise|lower|extend|change|give)\s+them\b)",
    re.IGNORECASE,
)


_CHANGES: dict[str, Change] = {
    "fill": _fill, "region": _region, "dims": _dims, "=pillars": _pillars, "=turrets": _turrets,
    "hollow": _hollow, "drop": _drop, "drop_one": _drop_one, "drop_family": _drop_family,
    "=other": _as_the_other,
    "=as": _as_one,
    "-one": _on_one,
    "+one": _on_one,
    "undo": _undo,
    "undo_all": _undo_all,
    "middle2": _middle_two,
    "drop2": _middle_two,
}  # fmt: skip
"""The changes that are not a size of the last structure (`_resize` does those)."""


def _main_slot(s: StructureDraft) -> str | None:
    """The one size slot the command gave `s`, else its family's main one; None if unclear."""
    given = [k for k in ("length", "width", "height", "steps", "count") if getattr(s, k)]
    if len(given) == 1:
        return given[0]
    return PRIMARY.get(s.shape) if not given else None


def _slot_said(change: str, s: StructureDraft) -> str | None:
    """ "make it longer, 6" of a wall 4 long and 3 high: the size the change's word names."""
    if re.search(r"\b(?:longer|long|lengthen|shorten|shorter)\b", change, re.I) and s.length:
        return "length"
    if re.search(r"\b(?:taller|higher|raise|heighten|lower)\b", change, re.I) and s.height:
        return "height"
    return None


def continues(
    p: Phrase, before: list[Phrase], cell: CellConfig, joiner: str = " , "
) -> tuple[int, Phrase] | None:
    """A phrase with no structure that modifies the one before ("Make it 5 cubes tall"):
    the earlier phrase read again with it, and how many structures it had."""
    built = [q for q in before if q.spec is not None]
    if not built or p.ref is not None:
        return None
    prev = built[-1]
    try:
        spec, _ = parse_phrase(prev.text + joiner + p.text, cell)
    except SpecError:
        return None
    if prev.spec is not None and spec.structures == prev.spec.structures:
        return None
    count = prev.count
    if len(spec.structures) != count:
        return None  # the later words named a structure after all: not a continuation
    prev.text = prev.text + joiner + p.text
    prev.spec = spec
    p.count = 0
    return count, prev
